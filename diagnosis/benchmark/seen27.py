"""The twenty-seventh seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-12-01 (session 31) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 32 (2026-12-01) on the code of 5972ebe:
176 cases, 0 skipped, 862 s wall on 2 workers. Top-1 52.8 % (93;
55.7 % of the 167 detectable; of the 9 undetectable, 6 are delays (5 of them unexplained,
1 none), 2 stribeck_shape cases (none), 1 a gms case (none));
mean |shrink error| 0.277 (0.208 over the right ones); wrong names on 18 (10.2 %):
acceleration -> inertia 8, asymmetry -> load 4, drift -> load 3, backlash -> gms 1,
inertia -> acceleration 1, stribeck_shape -> asymmetry 1. By form: load/pv_heated_liner
18/20, inertia/wave_radiation 17/20 (none 2, acceleration 1), position/conductive_strips
16/16, asymmetry/coriolis_slide 15/20 (load 4), delay/dual_slope_adc 11/20 (unexplained 8),
drift/grease_oil_bleed 8/20 (unexplained 8, load 3), acceleration/self_loading_drive 3/20
(inertia 8, unexplained 8), stribeck_shape/suction_pocket 3/16 (none 8, unexplained 4),
backlash/floating_coupling 1/12 (unexplained 10, gms 1), gms/wire_mesh_backing 1/12
(unexplained 8, none 3). By plant: isolator 67.9 %, forging press 57.1 %, valve 50.0 %,
damping rig 47.5 %, XML-350 47.5 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen26` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen26`,
:mod:`diagnosis.effects_backlash`, :mod:`diagnosis.effects_gms`) and than the candidate's
formula (:mod:`diagnosis.candidates`, ``diagnosis.effects_<name>``), taken from the friction
literature or from real machines, integrated along the plant's continuous motion on the grid
:data:`.kinematics.FINE` x finer than the data (:func:`.truths.on_fine_grid`); level changes
act inside the bristle dynamics of a LuGre base (:func:`.truths.level_inside`). ``s`` scales
each effect's amplitude monotonically from the base law at ``s`` = 0 (its calibration,
:func:`.cases._calibrate`, sets the requested size).

=================  =====================================================================
effect             form
=================  =====================================================================
acceleration       ``self_loading_drive``: the carriage is pushed by a friction (traction)
                   roller drive whose loading cam presses the roller onto its bar in
                   proportion to the force it transmits, the carriage's inertial force
                   with the friction: the drive's rolling losses rise when the motion
                   speeds up and fall when it slows
load               ``pv_heated_liner``: the carriage slides on thermoplastic liners heated
                   by their pressure times speed (PV): the liners' temperature follows the
                   load's friction power over their thermal time and softens them, their
                   friction rising with it
asymmetry          ``coriolis_slide``: the slide runs radially on a rotating head; the
                   Coriolis force 2 m Omega v presses it on one guide face moving out and
                   on the other moving in, and the faces' friction differs: levels that
                   differ by direction, the more the faster it moves
stribeck_shape     ``suction_pocket``: the carriage's flat underside has a pocket open at
                   its trailing edge; the air the bed drags through it leaves it below
                   ambient (a reversed Rayleigh step), a suction growing with the speed
                   to its cavitation limit that presses the carriage on its contacts
position           ``conductive_strips``: the carriage's magnets pass over a bed with
                   conductive strips set in it along the stroke: an eddy-current drag,
                   peaking at the strips' critical speed, where the strips are
inertia            ``wave_radiation``: the carriage carries a blade through a free liquid
                   surface; it drags an added mass and radiates waves (Cummins' equation):
                   a retardation memory of the velocity that carries no force in steady
                   motion
delay              ``dual_slope_adc``: the force is digitised by a dual-slope integrating
                   converter: each reading is the force's mean over the run-up, released
                   after a run-down whose length grows with the reading, and held until
                   the next
drift              ``grease_oil_bleed``: a fresh grease fill bleeds its base oil from the
                   thickener to the contact (Higuchi's square-root release): the levels
                   fall and the viscous term rises, fast at first and ever more slowly
backlash           ``floating_coupling``: drive and contact are joined by a floating
                   intermediate part (an Oldham disc, a floating sleeve) with a play on
                   each side: after a reversal the drive throws the part across its
                   plays, and it rattles between them before the contact is taken up
gms                ``wire_mesh_backing``: the contact's shoe is carried on a knitted wire-
                   mesh pad in series with it, whose wires close up as it deflects: a
                   stiffening, damped compliance in series with the contact, so the
                   presliding is longer, soft at first and stiffer as the wires close
                   up; at ``s`` = 0 the base
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``suction_pocket`` needs
a Stribeck curve (not the isolator's mre_lugre), ``conductive_strips`` a record that revisits
its positions (not the press), ``pv_heated_liner`` a load that changes,
``floating_coupling`` and ``wire_mesh_backing`` a classic LuGre base (valve, damping rig,
XML-350); each raises a ``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.shapes import SHAPES

from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _lag, _level,
                     _light_contact_step, _lugre_params, _motion_time, _smooth_max0,
                     _substeps, has_stribeck_curve, level_inside, lugre_with_curve,
                     on_fine_grid)

__all__ = ["FORMS", "self_loading_drive_truth", "pv_heated_liner_truth",
           "coriolis_slide_truth", "suction_pocket_truth", "conductive_strips_truth",
           "wave_radiation_truth", "dual_slope_adc_truth", "grease_oil_bleed_truth",
           "floating_coupling_truth", "wire_mesh_backing_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "self_loading_drive", "load": "pv_heated_liner",
         "asymmetry": "coriolis_slide", "stribeck_shape": "suction_pocket",
         "position": "conductive_strips", "inertia": "wave_radiation",
         "delay": "dual_slope_adc", "drift": "grease_oil_bleed",
         "backlash": "floating_coupling", "gms": "wire_mesh_backing"}


# -- acceleration ----------------------------------------------------------------------------
#: ``self_loading_drive``'s rise of the levels per unit of the cam's extra normal load (the
#: transmitted force's change, in the friction level), at strength 1 [-]; the carriage's
#: inertial force at the top acceleration, x the friction level [-]; the rounding of the
#: transmitted force's magnitude and of the direction, in those units and x the top speed [-]
CAM_RISE, CAM_INERTIA, CAM_ROUND = 0.4, 1.0, 0.05


def _cam_load(a, direction, inertia, rounding):
    """The loading cam's normal load [-] (1 in steady motion) at the accelerations ``a``
    [-] (over the top acceleration) along the motion's ``direction`` [-] (+-1, rounded):
    the magnitude of the force the drive transmits, the friction (1 along the motion) plus
    the carriage's inertial force ``inertia`` a (rounded over ``rounding``)."""
    q = np.asarray(direction, float) + inertia * np.asarray(a, float)
    return np.sqrt(q * q + rounding * rounding)


@on_fine_grid
def self_loading_drive_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage is pushed by a friction (traction) drive, a driven roller pressed onto
    a bar fixed to the carriage (as in precision stages' capstan and friction-bar drives
    and in traction drives), whose normal load is set by a self-loading cam (a ball ramp):
    the cam presses the roller in proportion to the tangential force it transmits, so
    that it never slips. That force is the carriage's friction plus its inertial force
    (:func:`_cam_load`; the inertial force at the top acceleration :data:`CAM_INERTIA`
    x the friction level): accelerating along the motion the cam presses harder,
    decelerating it relaxes. The drive's rolling and spin losses, felt as friction by the
    axis, follow the normal load: the Coulomb and Stribeck levels are the base's (at the
    steady load) times 1 + ``s`` :data:`CAM_RISE` x the load's change from the steady
    one, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the drive's loss per unit of its normal load times the
        cam's gain, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Traction drives and their self-loading cams (Heilich and Shube 1983, Traction Drives:
    Selection and Application; Loewenthal, Anderson and Rohn 1981, Evaluation of a high
    performance fixed-ratio traction drive, J. Mech. Des. 103) and the rolling contact's
    creep and spin losses (Johnson 1985, Contact Mechanics, ch. on rolling contacts). The
    candidate raises the levels with |a|, lagged, tilts them with a and adds a force odd
    in a; the open forms lag, age, heat, skid, load, press, attract, squeeze, transfer
    weight, slosh, dilate, wedge, spring a gib, soften rubber, swing arms, unload by the
    jerk, tilt pads, push ball trains, ripple the current, slide rack flanks, set a shoe by
    a ball in a cone, shut a damper's bypass, creep a belt, rack a gantry, tighten a band
    or surge a feed line. Here the drive's own normal load follows the force it transmits:
    up when speeding up, down when slowing, whatever the direction.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    v99 = max(kin.scales["v99"], 1e-12)
    direction = np.tanh(np.asarray(kin.v, float) / (CAM_ROUND * v99))
    N = _cam_load(np.asarray(kin.a, float) / a99, direction, CAM_INERTIA, CAM_ROUND)
    N0 = float(_cam_load(0.0, 1.0, CAM_INERTIA, CAM_ROUND))    # steady motion
    lev = np.maximum(1.0 + float(s) * CAM_RISE * (N - N0), 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- load ------------------------------------------------------------------------------------
#: ``pv_heated_liner``'s change of the levels at the record's largest change of the liners'
#: temperature from the mean load's (its 99th percentile), at strength 1 [-]; the liners'
#: thermal time, x the record's length [-]
LINER_RISE, LINER_TIME = 0.5, 0.03


def _liner_heat(t, q, u, time):
    """The liners' temperature rise over the mean load's [-] along the loads ``q`` [-]
    (over the mean |load|) and speeds ``u`` [-] (over the top speed) at the times ``t``
    [s]: the friction power's excess (|q| - 1) |u| (PV at the load, over PV at the mean
    load) through the liner's first-order thermal lag ``time`` [s]."""
    return _lag(np.asarray(t, float),
                (np.abs(np.asarray(q, float)) - 1.0) * np.abs(np.asarray(u, float)), time)


@on_fine_grid
def pv_heated_liner_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage slides on thermoplastic liners (acetal, a filled PTFE or a polyamide
    slideway lining, as on many machine-tool ways and linear plain bearings). Their
    friction heats them by the pressure times the speed, PV, and they cool over their
    thermal time (:data:`LINER_TIME` x the record's length): their temperature follows the
    friction power, and the polymer softens as it warms, its real contact area and its
    friction growing with it. The base law, identified at the mean load, carries the
    heating there; the truth's Coulomb and Stribeck levels are the base's times 1 + ``s``
    :data:`LINER_RISE` x the temperature's excess over the mean load's
    (:func:`_liner_heat`, over its 99th percentile along the record), inside the bristle
    dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s], load [N]) and its base law.
    s : float
        Amplitude factor [-]: the liner's friction change per degree times its thermal
        resistance, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Polymers' PV limits and frictional heating (Lancaster 1972, Estimation of the limiting
    PV relationships for thermoplastic bearing materials, Tribology 4; Archard 1959, The
    temperature of rubbing surfaces, Wear 2; Unal, Mimaroglu, Kadioglu and Ekiz 2004,
    Sliding friction and wear behaviour of polytetrafluoroethylene and its composites under
    dry conditions, Mater. Des. 25). The candidate makes the levels affine in the load,
    with a memory over the travel; the open forms scale the friction with a Hertz
    contact's area, a seal's, a film's, a junction's, a pivot's, an adhesive contact's or
    a pin's arc, break, squeeze or desorb films, plough, creep, vibrate, overload or feed
    a constant flow to a pad, heal scuffs, relieve a preload, roll on a lossy track, slip
    differentially, spin balls, press a disc spring, skid lightly loaded rollers or bed a
    rail. Here the load acts through the heat it makes with the speed, and with the
    liner's thermal lag.
    """
    L = np.asarray(kin.load, float)
    Lm = float(np.mean(np.abs(L))) or 1.0
    if not np.ptp(L) > 1e-9 * Lm:
        raise ValueError(f"load (pv_heated_liner): the {kin.plant} record's load does not "
                         f"change")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    v99 = max(kin.scales["v99"], 1e-12)
    time = LINER_TIME * max(float(t[-1] - t[0]), 1e-12)
    T = _liner_heat(t, L / Lm, np.asarray(kin.v, float) / v99, time)
    T = T / max(float(np.percentile(np.abs(T), 99)), 1e-12)
    lev = np.maximum(1.0 + float(s) * LINER_RISE * T, 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``coriolis_slide``'s Coriolis force at the top speed, x the guides' preload, at strength
#: 1 [-]; the difference of the two faces' friction coefficients over their sum [-]; the
#: rounding of a face's unloading, x the preload [-]
CORIOLIS_Q, CORIOLIS_FACES, CORIOLIS_ROUND = 0.5, 0.5, 0.05


def _face_levels(u, q, faces, rounding):
    """The guides' friction factor [-] (1 at rest) at the speeds ``u`` [-] (over the top
    speed) for the Coriolis force ``q`` u (x the preload): the outer face (its friction
    coefficient 1 + ``faces``) pressed by 1 + q u, the inner (1 - ``faces``) by 1 - q u,
    neither below 0 (rounded over ``rounding``)."""
    w = q * np.asarray(u, float)
    return 0.5 * ((1.0 + faces) * _smooth_max0(1.0 + w, rounding)
                  + (1.0 - faces) * _smooth_max0(1.0 - w, rounding)) / float(
        _smooth_max0(1.0, rounding))


@on_fine_grid
def coriolis_slide_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The axis is a slide running radially on a rotating head (a facing head's U-axis, a
    radial slide on a turntable or a centrifuge's arm), the head turning at a steady rate
    Omega. In the head's frame the moving slide feels the Coriolis force 2 m Omega v,
    across its guides: moving out it presses the slide on one guide face, moving in on the
    other, against the guides' preload. The faces differ (a hardened steel strip on one
    side, a bronze or polymer gib on the other: friction coefficients (1 +- :data:`
    CORIOLIS_FACES`) x their mean), so the guides' friction (:func:`_face_levels`) is
    larger one way than the other, the more the faster the slide moves; the centrifugal
    force, along the slide, is the drive's. The Coulomb and Stribeck levels are the
    base's times that factor, the Coriolis force at the top speed ``s``
    :data:`CORIOLIS_Q` x the preload, inside the bristle dynamics; the viscous term is the
    base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the head's rate times the slide's mass over the preload, /
        its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The Coriolis force on a body moving in a rotating frame (Goldstein, Poole and Safko
    2002, Classical Mechanics, ch. on rigid body motion in rotating frames; Meriam and
    Kraige 2012, Engineering Mechanics: Dynamics, ch. on relative motion in rotating axes)
    and on radial slides and facing heads (Slocum 1992, Precision Machine Design, ch. on
    rotary axes). The candidate gives each direction its levels and an offset; the open
    forms twin the levels, the curves or the viscous term, bend a curve, roll a lip, load
    a thrust bearing, film a rod seal, texture a ratchet, return a spring, tilt a pad,
    strut a sprag, throttle a meter-out, differ a cylinder's areas, groove chevrons,
    buckle a helix, scrape chips, commutate, idle a belt, free a roller, wick a felt, run a
    belt, lean a brush, band a seal, counterbalance a valve, vibrate elliptically, diode a
    flow, pitch pads, skew rollers or lift through a screw. Here the frame turns: the
    velocity itself loads the guides sideways, one face going out, the other coming in.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    lev = _face_levels(np.asarray(kin.v, float) / v99, float(s) * CORIOLIS_Q,
                       CORIOLIS_FACES, CORIOLIS_ROUND)
    return level_inside(kin, lev, np.ones_like(lev))


# -- stribeck_shape --------------------------------------------------------------------------
#: ``suction_pocket``'s suction at its cavitation limit, x the bearing contacts' load share
#: of the Coulomb level, at strength 1 [-]; the speed at which the suction is half its
#: limit, x the top speed [-]
POCKET_RISE, POCKET_SPEED = 0.6, 0.3


def _suction(u):
    """The pocket's suction [-] (1 at its cavitation limit) at the speeds ``u`` [-] (over
    the speed of half the limit): the Couette-driven sub-ambient pressure ~ |u|, bounded
    by the vacuum the film cavitates at: |u| / (1 + |u|)."""
    r = np.abs(np.asarray(u, float))
    return r / (1.0 + r)


@on_fine_grid
def suction_pocket_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage's underside is a flat plate close over a flat bed (a linear motor's
    forcer, a wafer stage's base, a flat carriage on a lapped way) with a recessed pocket
    open at its trailing edge. The air (or oil mist) the moving bed drags into the pocket
    expands over its step: a diverging (reversed Rayleigh) step sets a pressure below
    ambient, proportional to the speed until the film cavitates (:func:`_suction`, half
    its limit at :data:`POCKET_SPEED` x the top speed), and the suction presses the
    carriage onto its bearing contacts. The truth's Stribeck curve is the base's times 1 +
    ``s`` :data:`POCKET_RISE` x the suction, inside the bristle dynamics: a friction that
    rises with the speed, steeply at first, to a plateau.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (with a Stribeck curve).
    s : float
        Amplitude factor [-]: the pocket's area over the contacts' load, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Sub-ambient-pressure (negative pressure) air bearing sliders and the Rayleigh step
    (White 1983, Flying characteristics of the zero-load slider bearing, J. Lubr. Technol.
    105; Hamrock, Schmid and Jacobson 2004, Fundamentals of Fluid Film Lubrication, ch. on
    the Rayleigh step bearing and on gas bearings; Gross 1962, Gas Film Lubrication). The
    candidate's curve is Gaussian, Lorentzian or an exponential tail; the open forms add
    tails, rationals, films that lift, spikes, bimodal roughness, logs, Eyring, starvation,
    rubber hysteresis, resonances, dither, melting, grains, readsorption, thermoviscous,
    turbulent and thixotropic films, churning, core losses, breathing bellows, eddy
    brakes, shear thinning, flying pads, wiping menisci, journals, wall slip, a closing
    clearance or a dwell's squeeze. Here a film pulls instead of lifting: the speed loads
    the contact.
    """
    law = kin.base
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (suction_pocket): the mre_lugre base has no "
                         "Stribeck curve")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    vc = POCKET_SPEED * max(kin.scales["v99"], 1e-12)
    k = float(s) * POCKET_RISE
    return lugre_with_curve(kin, lambda vv: law.g(vv) * (1.0 + k * _suction(vv / vc)))


# -- position --------------------------------------------------------------------------------
#: ``conductive_strips``' drag at the strips' critical speed over a strip's middle, x the
#: friction level, at strength 1 [-]; the critical speed, x the top speed [-]; the strips'
#: pitch, x the visited stroke [-]; a strip's width, x the pitch [-]; the rounding of a
#: strip's edges (the field's fringe), x the pitch [-]
STRIP_DRAG, STRIP_SPEED, STRIP_PITCH, STRIP_WIDTH, STRIP_EDGE = 0.6, 0.5, 0.37, 0.45, 0.06


def _strip_cover(xr, pitch, width, edge):
    """The share of the magnets' field over conductive strip [-] (0 to 1) at the positions
    ``xr`` [-] (over the visited stroke, from its low end): strips of ``width`` x
    ``pitch`` every ``pitch``, the first centred 0.2 pitch in, their edges rounded over
    ``edge`` x ``pitch`` (the field's fringe)."""
    ph = (np.asarray(xr, float) / pitch - 0.2) % 1.0
    d = np.minimum(ph, 1.0 - ph)                       # distance to a strip's centre
    return 0.5 * (1.0 + np.tanh((0.5 * width - d) / edge))


def _eddy_drag(u):
    """The eddy-current drag factor [-] (1 at its peak, odd in the speed) at the speeds
    ``u`` [-] (over the critical speed): a thin plate's 2 u / (1 + u^2), rising as the
    induced currents grow, falling as their own field pushes the magnets' out (skin
    effect)."""
    u = np.asarray(u, float)
    return 2.0 * u / (1.0 + u * u)


@on_fine_grid
def conductive_strips_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage carries permanent magnets (a magnetic preload, a linear motor's mover,
    a magnetic scale's reader) close over a bed in which conductive strips are set along
    the stroke (aluminium or copper filler strips between steel segments, cooling tubes,
    earthing bars), :data:`STRIP_PITCH` x the visited stroke apart
    (:func:`_strip_cover`). Where the magnets pass over a strip their moving field induces
    eddy currents in it, and a drag ~ the strip's conductance x the thin plate's 2 u / (1
    + u^2) (:func:`_eddy_drag`; u the speed over the critical speed, :data:`STRIP_SPEED`
    x the top speed); over the steel nothing. The truth adds ``s`` :data:`STRIP_DRAG` x
    the friction level x that drag to the base: a speed-shaped drag that is there only
    over the strips.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the strips' conductance times the magnets' field squared,
        / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Eddy-current forces on magnets moving over conducting plates (Reitz 1970, Forces on
    moving magnets due to eddy currents, J. Appl. Phys. 41; Thompson 2000, Electrodynamic
    magnetic suspension - models, scaling laws and experimental results, IEEE Trans. Educ.
    43; Sodano and Bae 2004, Eddy current damping in structures, Shock Vib. Dig. 36). The
    candidate scales the friction along the stroke and adds a force of the position; the
    open forms put defects, waviness, wear, runout, bends, films, cogging, tapers, pockets,
    cushions, covers, springs, holes, plungers, sags, festoons, curves, chains, cams,
    heat, dents, joints, misalignment, flow forces, cranks, overhangs, a track's end, a
    reel or a way's flatness on the stroke. Here the bed's material changes along it: an
    induced drag, rising and then falling with the speed, switched on and off by the
    position.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (conductive_strips): the held-out part of the "
                         f"{kin.plant} record never revisits the positions of its fit part")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    span = max(sc["x_hi"] - sc["x_lo"], 1e-12)
    xr = (np.asarray(kin.x, float) - sc["x_lo"]) / span
    c = _strip_cover(xr, STRIP_PITCH, STRIP_WIDTH, STRIP_EDGE)
    u = np.asarray(kin.v, float) / (STRIP_SPEED * max(sc["v99"], 1e-12))
    return F + float(s) * STRIP_DRAG * _level(kin) * c * _eddy_drag(u)


# -- inertia ---------------------------------------------------------------------------------
#: ``wave_radiation``'s added mass at infinite frequency at strength 1, x the friction level
#: / a99 [kg per N s^2/m]; the radiation's damping rate at its peak, x the added mass and
#: its frequency [-]; the period of the waves it radiates most, x the motion's time scale
#: [-]; the retardation's decay time, x that period [-]
WAVE_MASS, WAVE_DAMP, WAVE_PERIOD, WAVE_DECAY = 0.5, 0.5, 0.6, 0.3


def _retardation(t, v, omega, tau):
    """Cummins' memory integral [m] along the velocities ``v`` [m/s] at the times ``t``
    [s]: int K(t - t') v(t') dt' with the retardation kernel K(t) = e^(-t / ``tau``)
    (cos(``omega`` t) - sin(``omega`` t) / (``omega`` ``tau``)), whose integral is 0 (no
    radiation at zero frequency: none in steady motion); exact for a velocity constant over
    each step, from rest."""
    from scipy.signal import lfilter
    h = float(t[1] - t[0])
    lam = complex(-1.0 / tau, omega)
    e = np.exp(lam * h)
    I = lfilter([(e - 1.0) / lam], [1.0, -e], np.asarray(v, float).astype(complex))
    return np.real((1.0 + 1j / (omega * tau)) * I)


@on_fine_grid
def wave_radiation_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage carries a blade, a paddle or a probe through the free surface of a
    liquid (a towing or wave tank's carriage, a coating or cleaning machine's wiper, a
    mixer's stage), which the inverse dynamics misses. The blade drags the liquid's added
    mass (its value at infinite frequency, ``s`` :data:`WAVE_MASS` x the friction level /
    a99) and radiates surface waves, whose force is a memory of the velocity (Cummins'
    equation): the retardation kernel of :func:`_retardation`, ringing at the period of
    the waves it radiates most (:data:`WAVE_PERIOD` x the motion's time scale) and decaying
    over :data:`WAVE_DECAY` x that period, its damping rate :data:`WAVE_DAMP` x the added
    mass and that frequency. Its integral is nothing: steady motion radiates no force. The
    truth adds the added mass's inertial force and the radiation's to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the blade's immersed area, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The impulse response of floating and immersed bodies' radiation (Cummins 1962, The
    impulse response function and ship motions, Schiffstechnik 9; Ogilvie 1964, Recent
    progress toward the understanding and prediction of ship motions, 5th Symp. Naval
    Hydrodyn.; Falnes 2002, Ocean Waves and Oscillating Systems, ch. on radiation). The
    candidate misses a constant mass; the open forms filter it, reflect it through
    gearing, a chain, a pinion or a screw, hang it on a spring, a cable, a fluid, a
    clutch, a coupling, a flyweight, a friction-damped, quasi-zero-stiffness, hose's or
    elastomer mount, surge a spring, add a fluid's mass, pick, drop, empty, slide, rattle,
    telescope, roll or rock it, recoil a frame, saturate a motor, lead a feedforward or
    pitch a scale. Here the mass radiates its momentum away as waves: a memory with no
    stiffness and no steady drag.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    m = float(s) * WAVE_MASS * _level(kin) / a99
    T = WAVE_PERIOD * max(_motion_time(kin), 1e-12)
    omega = 2.0 * math.pi / T
    rad = _retardation(np.asarray(kin.t, float), np.asarray(kin.v, float), omega,
                       WAVE_DECAY * T)
    return F + m * (np.asarray(kin.a, float) + WAVE_DAMP * omega * omega * rad)


# -- delay -----------------------------------------------------------------------------------
#: ``dual_slope_adc``'s run-up (integration) time at strength 1 [data samples]; the
#: run-down's length at full scale, x the run-up [-]; the auto-zero phase, x the run-up [-]
DUAL_SAMPLES, DUAL_RUNDOWN, DUAL_ZERO = 1.5, 1.0, 0.5


@njit(cache=True)
def _conversions(t, C, mid, full, runup, rundown, zero):
    """(release times [s], readings [N]) of a dual-slope converter along the times ``t``
    [s] of the force's running integral ``C`` [N s] (linear between the grid's points):
    each conversion integrates the force over ``runup`` [s] (its mean the reading), runs
    down for ``rundown`` x the run-up x |mean - ``mid``| / ``full`` [s], releases the
    reading and auto-zeroes for ``zero`` x the run-up before the next."""
    n = t.size
    cap = int((t[-1] - t[0]) / (runup * (1.0 + zero))) + 2
    rel = np.empty(cap)
    val = np.empty(cap)
    m = 0
    start = t[0]
    j = 0
    c0 = C[0]
    while m < cap:
        end = start + runup
        if end > t[-1]:
            break
        while j + 1 < n - 1 and t[j + 1] < end:
            j += 1
        w = (end - t[j]) / (t[j + 1] - t[j])
        c1 = C[j] + w * (C[j + 1] - C[j])
        reading = (c1 - c0) / runup
        release = end + rundown * runup * min(abs(reading - mid) / full, 1.0)
        rel[m] = release
        val[m] = reading
        m += 1
        start = release + zero * runup
        if start > t[-1]:
            break
        while j + 1 < n - 1 and t[j + 1] < start:
            j += 1
        w = (start - t[j]) / (t[j + 1] - t[j])
        c0 = C[j] + w * (C[j + 1] - C[j])
    return rel[:m], val[:m]


def _dual_slope(t, f, mid, full, runup, rundown, zero):
    """The readings [N] of a dual-slope converter (:func:`_conversions`) of the force ``f``
    [N] along the times ``t`` [s], each held until the next is released (the first force
    until the first), seen through each grid step's mean (a release inside a step counts
    for its share of it)."""
    t = np.asarray(t, float)
    f = np.asarray(f, float)
    C = np.concatenate(([0.0], np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(t))))
    rel, val = _conversions(t, C, mid, full, runup, rundown, zero)
    if rel.size == 0:
        return f.copy()
    # the held reading H(t) and its running integral G(t) at the releases and the grid
    r = np.concatenate(([t[0]], rel))
    y = np.concatenate(([f[0]], val))
    Gr = np.concatenate(([0.0], np.cumsum(y[:-1] * np.diff(r))))
    i = np.searchsorted(r, t, side="right") - 1
    G = Gr[i] + y[i] * (t - r[i])
    out = np.empty_like(f)
    out[0] = f[0]
    out[1:] = np.diff(G) / np.diff(t)
    return out


@on_fine_grid
def dual_slope_adc_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is digitised by a dual-slope integrating converter (a bench multimeter's,
    a panel meter's or a weighing indicator's: ICL7106-type converters): each conversion
    integrates the force over a run-up of ``s`` :data:`DUAL_SAMPLES` data samples, then
    runs the integrator down at a fixed reference rate, counting until it crosses zero,
    which takes :data:`DUAL_RUNDOWN` x the run-up at full scale, and releases the count
    (the run-up's mean); an auto-zero phase (:data:`DUAL_ZERO` x the run-up) follows
    before the next conversion (:func:`_conversions`, :func:`_dual_slope`; the force's
    range its full scale each way from its middle). The reading is held until the next:
    a mean over a window that is released the later the larger the reading, and the
    conversion rate itself follows the force's size. The motion channels are on time.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the converter's run-up time, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Dual-slope integrating converters (Sheingold 1986, Analog-Digital Conversion Handbook,
    ch. on integrating converters; Kester 2005, Data Conversion Handbook, ch. on
    integrating ADCs; the Intersil ICL7106/ICL7107 data sheet). The candidate shifts the
    force by a constant time, low-passes it, reads it through a transducer's resonance and
    leaks it; the open forms sample, filter, average, hold, skew, jitter, rate-limit,
    transmit, median, report by deadband, trigger on positions, run a belt, aerate, drop
    telegrams, leak, creep, notch, track, snub, time a waveguide's pulse, diffuse eddy
    currents, count a resonator, sweep a grating, restore a force by a servo, interleave
    converters or balance a pneumatic cell. Here the latency is counted out: it grows with
    the reading, and so does the time between readings.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    lo, hi = float(np.min(F)), float(np.max(F))
    mid, full = 0.5 * (lo + hi), max(0.5 * (hi - lo), 1e-12)
    runup = float(s) * DUAL_SAMPLES * kin.sample_dt
    return _dual_slope(kin.t, F, mid, full, runup, DUAL_RUNDOWN, DUAL_ZERO)


# -- drift -----------------------------------------------------------------------------------
#: ``grease_oil_bleed``'s fall of the levels by the record's end, at strength 1 [-]; the
#: viscous term's rise by then [-]; the bleed's time scale (Higuchi's, the oil in the fill's
#: contact zone released), x the record's length [-]
BLEED_FALL, BLEED_VISC, BLEED_TIME = 0.3, 0.4, 2.0


def _bled(tau, time):
    """The share of the fill's releasable oil bled [-] at the times ``tau`` [-] (over the
    record's length): Higuchi's sqrt(tau / ``time``), up to all of it."""
    return np.minimum(np.sqrt(np.maximum(np.asarray(tau, float), 0.0) / time), 1.0)


@on_fine_grid
def grease_oil_bleed_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The way (or the guide's bearings) has just been filled with a fresh grease: its base
    oil is held in the thickener's fibre network and bleeds out of it to the contact,
    diffusing through the depleting matrix: Higuchi's release, ~ the square root of the
    time (:func:`_bled`, time scale :data:`BLEED_TIME` x the record's length). The bled oil
    floods the boundary contact, lowering its friction, and thickens the film the contact
    shears. The Coulomb and Stribeck levels are the base's times 1 - ``s``
    :data:`BLEED_FALL` x the bled share over its value at the record's end, the viscous
    term the base's times 1 + ``s`` :data:`BLEED_VISC` x it, inside the bristle dynamics:
    a change fastest at the start and ever slower, the levels and the viscous term going
    opposite ways.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the grease's oil content that bleeds, / its value at strength
        1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Grease's oil bleeding and its lubrication of rolling and sliding contacts (Lugt 2009, A
    review on grease lubrication in rolling bearings, Tribol. Trans. 52; Lugt 2013, Grease
    Lubrication in Rolling Bearings, ch. on oil bleeding) and the square-root-of-time
    release from a matrix (Higuchi 1961, Rate of release of medicaments from ointment
    bases containing drugs in suspension, J. Pharm. Sci. 50). The candidate is a trend, a
    saturating change, a step, a cycle, a resetting change or the friction power's heat;
    the open forms warm up, wear in, change, heat, wear, follow the humidity, grind,
    relubricate, relax, oxidise, deplete, wear through, swell, build films, take in
    particles, expand, shear down, heat magnets, charge, creep, loosen, dewet, channel,
    drain, spall, evaporate, pump down, settle an additive or crystallise wax. Here oil
    diffuses out of a matrix: a square root of the time, the boundary and the film going
    opposite ways.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    tau = (t - t[0]) / max(t[-1] - t[0], 1e-12)
    B = _bled(tau, BLEED_TIME)
    B = B / max(float(B[-1]), 1e-12)
    lev = np.maximum(1.0 - float(s) * BLEED_FALL * B, 0.05)
    return level_inside(kin, lev, 1.0 + float(s) * BLEED_VISC * B)


# -- backlash --------------------------------------------------------------------------------
#: ``floating_coupling``'s two plays together at strength 1, as a share of the stroke (their
#: full widths) [-]; the floating part's mass, x the contact's [-]; its drag in the
#: coupling's oil, x the flanks' damping [-]
FLOAT_CLEAR, FLOAT_MASS, FLOAT_DRAG = 0.01, 0.25, 0.05


@njit(cache=True)
def _flank(e, ed, half, kh, ch):
    """The force [N] across a play of half-width ``half`` [m] at the offset ``e`` [m] and
    its rate ``ed`` [m/s]: nothing inside it, beyond it a spring ``kh`` [N/m] and damper
    ``ch`` [N s/m], compressive only."""
    if e > half:
        f = kh * (e - half) + ch * ed
        return f if f > 0.0 else 0.0
    if e < -half:
        f = kh * (e + half) + ch * ed
        return f if f < 0.0 else 0.0
    return 0.0


@njit(cache=True)
def _floating_contact(h, xd, half, mf, cf, kh, ch, m, s0, s1, s2, Fc, Fs, vs, alpha,
                      shape):
    """LuGre friction [N] of a light contact of mass ``m`` [kg] driven by the drive
    positions ``xd`` [m] (steps ``h`` [s]) through a floating part of mass ``mf`` [kg],
    with a play of half-width ``half`` [m] between the drive and the part and another
    between the part and the contact (the flanks of :func:`_flank`), the part dragged
    towards the contact's speed by ``cf`` [N s/m]; starting at rest, both plays closed
    towards -x. Semi-implicit Euler of both masses, the contact's bristle exact."""
    n = xd.size
    F = np.empty(n)
    xf = xd[0] - half
    x = xf - half
    vf = 0.0
    v = 0.0
    z = 0.0
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        f1 = _flank(xd[j] - xf, vd - vf, half, kh, ch)
        f2 = _flank(xf - x, vf - v, half, kh, ch) + cf * (vf - v)
        F[j], v, z = _light_contact_step(v, z, f2, h, m, s0, s1, s2, Fc, Fs, vs, alpha,
                                         shape)
        vf = vf + h * (f1 - f2) / mf
        xf = xf + h * vf
        x = x + h * v
    return F


@on_fine_grid
def floating_coupling_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact are joined by a floating intermediate part (an Oldham coupling's
    centre disc, a gear coupling's floating sleeve, a spline's loose intermediate shaft)
    with a play on each side: two plays in series, each half of ``s``^2
    :data:`FLOAT_CLEAR` x the stroke wide. After a reversal the drive crosses its play and
    strikes the part, which flies across the second play and strikes the contact's flank,
    bounces and rattles between the flanks until the drive's push settles it: the contact
    is taken up in steps of impacts rather than once (:func:`_floating_contact`; the part
    :data:`FLOAT_MASS` x the contact's mass, dragged by the coupling's oil, the flanks as
    the open plays'). The contact is light (its inertial force at the top acceleration
    1 % of the Coulomb level) with the base's LuGre friction.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the square root of the plays' width, / its value at strength
        1 (as the open plays').

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Couplings with floating members and the rattle of free masses between clearances
    (Piotrowski 2006, Shaft Alignment Handbook, ch. on flexible couplings; Mann 2005,
    Flexible couplings, in Machinery's Handbook; Karagiannis and Pfeiffer 1991,
    Theoretical and experimental investigations of gear-rattling, Nonlinear Dyn. 2). The
    candidate holds or frees the contact across a rigid play; the open forms take it up
    rigidly, compliantly, by impact, against a spring, eccentrically, through oil, worn,
    with a dragging idler, biased, slack, magnetic, preloaded, through a flexspline, a
    rope, a spider, a fluid link, a cable, a clutch, a varying mesh, a polymer gear,
    grease, a wedge, an overlapped spool, a side loaded pin, a toggle spring, graded pins,
    an adhesive flank or packed powder. Here a free body sits between two plays: the
    take-up is a chain of impacts through it.
    """
    p = _lugre_params(kin, "backlash (floating_coupling)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    half = 0.25 * float(s) ** 2 * FLOAT_CLEAR * float(np.ptp(kin.x))
    m, kh, ch = _contact_constants(kin, p)
    kh, ch = 2.0 * kh, math.sqrt(2.0) * ch           # two flanks in series: the open plays'
    mf = FLOAT_MASS * m
    cf = FLOAT_DRAG * ch
    rate = max(math.sqrt(kh / mf), (ch + cf) / mf,
               (float(p.sigma1) + float(p.sigma2) + ch + cf) / m)
    h, xd, n_sub = _substeps(kin, rate)
    Fr = _floating_contact(h, xd, half, mf, cf, kh, ch, m, float(p.sigma0),
                           float(p.sigma1), float(p.sigma2), float(p.Fc), float(p.Fs),
                           float(p.vs), float(p.alpha), SHAPES[p.shape])
    return Fr[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: the pad's deflection at the sliding level at strength 1, x the base bristle's path at
#: the Coulomb level (Fc / sigma0) [-]; its damping ratio with the contact's mass [-]
MESH_PATH, MESH_DAMPING = 3.0, 0.7


@njit(cache=True)
def _mesh_force(e, ed, k1, e0, c):
    """The wire-mesh pad's force [N] at its deflection ``e`` [m] and rate ``ed`` [m/s]: a
    stiffening spring k1 e (1 + (e / e0)^2) (``k1`` [N/m], ``e0`` [m]: the wires closing
    up) and the wires' rubbing as a damper ``c`` [N s/m]."""
    r = e / e0
    return k1 * e * (1.0 + r * r) + c * ed


@njit(cache=True)
def _mesh_contact(h, xd, k1, e0, c, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a light shoe of mass ``m`` [kg] carried by the drive positions
    ``xd`` [m] (steps ``h`` [s]) through the pad of :func:`_mesh_force`, from rest."""
    n = xd.size
    F = np.empty(n)
    x = xd[0]
    v = 0.0
    z = 0.0
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        fc = _mesh_force(xd[j] - x, vd - v, k1, e0, c)
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha,
                                         shape)
        x = x + h * v
    return F


@on_fine_grid
def wire_mesh_backing_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Part of the contact's compliance is a pad in series with it: the shoe is carried on
    a knitted wire-mesh (metal rubber) pad, as in dampers and seals for hot or oily
    places. In shear the pad stiffens as it deflects, its wires closing up (k1 e (1 + (e
    / e0)^2), its deflection at the static level e0 = ``s`` :data:`MESH_PATH` x the base
    bristle's path at the Coulomb level, Fc / sigma0), its wires' rubbing a damper
    (damping ratio :data:`MESH_DAMPING` with the shoe; :func:`_mesh_force`). The shoe
    (light: its inertial force at the top acceleration 1 % of the Coulomb level) slides
    with the base's LuGre friction (:func:`_mesh_contact`): after each reversal the drive
    first deflects the pad, softly and then stiffer, while the contact's bristle takes up
    its own path, so the presliding is longer than the base's, soft at first and stiffer
    as the wires close up. The force is the shoe's friction; at ``s`` = 0 the base
    itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the pad's compliance, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Metal-mesh dampers and their stiffening, deflection-dependent stiffness (Al-Khateeb and
    Vance 2001, Experimental evaluation of a metal mesh bearing damper, J. Eng. Gas
    Turbines Power 123; Ertas 2009, Compliant hybrid journal bearings using integral wire
    mesh dampers, J. Eng. Gas Turbines Power 131) and series compliance in presliding
    (Al-Bender, Lampaert and Swevers 2005, The generalized Maxwell-slip model, IEEE Trans.
    Autom. Control 50). The candidate's presliding is a generalized Maxwell-slip (GMS)
    element set; the open forms are Maxwell-slip sets, Dahl, elasto-plastic,
    Bliman-Sorine, Bouc-Wen, Zener junctions, Mindlin contacts, rate-and-state, Tomlinson
    asperities, bond rupture, gouge, kinematic hardening, interlocking, capillary bridges,
    cyclic hardening, peeling, unloading microslip, a power-law joint, junction growth,
    avalanches, slip weakening, a microslip bar, contact renewal, grease's yield, a
    superelastic flexure, an Eyring film, a viscoplastic layer or a poroelastic one, each
    beside the contact. Here the compliance is in series with the whole contact, and it
    stiffens instead of yielding.
    """
    p = _lugre_params(kin, "gms (wire_mesh_backing)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    e_s = max(float(s) * MESH_PATH * float(p.Fc) / float(p.sigma0), 1e-15)
    k1 = 0.5 * float(p.Fs) / e_s                      # k1 e_s (1 + 1) = Fs
    m = _contact_constants(kin, p)[0]
    kmax = k1 * (1.0 + 3.0 * 4.0)                     # its stiffness at twice e_s
    c = 2.0 * MESH_DAMPING * math.sqrt(k1 * m)
    rate = max(math.sqrt(kmax / m), (float(p.sigma1) + float(p.sigma2) + c) / m,
               math.sqrt(float(p.sigma0) / m))
    h, xd, n_sub = _substeps(kin, rate)
    Fr = _mesh_contact(h, xd, k1, e_s, c, m, float(p.sigma0), float(p.sigma1),
                       float(p.sigma2), float(p.Fc), float(p.Fs), float(p.vs),
                       float(p.alpha), SHAPES[p.shape])
    return Fr[::n_sub]
