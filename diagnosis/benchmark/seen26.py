"""The twenty-sixth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-12-01 (session 30) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 31 (2026-12-01) on the code of 00dfbb5:
176 cases, 0 skipped, 505 s wall on 2 workers. Top-1 55.1 % (97;
56.9 % of the 167 detectable; of the 9 undetectable, 2 are asymmetry cases (verdict none),
6 delays (2 of them named delay, 3 unexplained, 1 none), 1 a stribeck_shape case (none));
mean |shrink error| 0.312 (0.231 over the right ones); wrong names on 16 (9.1 %):
acceleration -> asymmetry 5, gms -> delay 3, backlash -> gms 2, delay -> gms 1,
stribeck_shape -> drift 1, stribeck_shape -> acceleration 1, load -> delay 1, asymmetry ->
load 1, drift -> load 1. By form: drift/wax_crystallisation 18/20, load/bedded_rail 17/20,
asymmetry/lifting_screw 13/20, inertia/elastomer_mount 13/20, delay/pneumatic_balance
13/20, acceleration/feed_line_surge 8/20 (asymmetry 5, unexplained 7),
gms/poroelastic_layer 5/12 (delay 3), stribeck_shape/dwell_squeeze 4/16 (none 7),
position/air_film_flatness 4/16 (unexplained 12), backlash/powder_packed_gap 2/12
(unexplained 8, gms 2). By plant: isolator 64.3 %, valve 62.5 %, damping rig 57.5 %,
XML-350 50.0 %, forging press 39.3 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen25` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen25`,
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
acceleration       ``feed_line_surge``: the carriage's hydrostatic pads are fed through a
                   long supply line along the axis; the oil in the line is accelerated
                   with the carriage, its inertia (rho L a) takes from or adds to the
                   pads' supply pressure, and with the pads' lift the solid share of the
                   load: levels that follow the signed acceleration, lagged by the line
load               ``bedded_rail``: the carriage rolls on a rail bedded on a damped
                   elastic foundation; the rail sinks under the load and the carriage
                   keeps climbing out of its own bowl, made asymmetric by the bed's
                   damping: a resistance ~ the load's square, peaking at the bed's
                   relaxation speed
asymmetry          ``lifting_screw``: the axis is driven by a lead screw lifting a
                   weight up a slope; the thread's friction is the weight's times
                   mu sec^2(lambda) / (1 -+ mu tan(lambda)): more raising than lowering,
                   the levels differ by direction through the thread's helix
stribeck_shape     ``dwell_squeeze``: a soft pad runs over a wet track; in the time a
                   point of the track spends under it the film is squeezed out to the
                   roughness only over the pad's rear part (Reynolds squeeze, as in a
                   tyre's hydroplaning): a dry share falling straight with the speed to
                   nothing at the squeeze-out speed, a knee, not a smooth tail
position           ``air_film_flatness``: the carriage rides on air bearings over a
                   granite way whose flatness error changes the film's gap along the
                   stroke: the film's shear drag ~ v / h(x), a viscous drag that varies
                   with the position
inertia            ``elastomer_mount``: a payload on an elastomer mount, a standard
                   linear solid (a spring beside a Maxwell arm): its stiffness and loss
                   change with the frequency, the mount carries the payload whole in
                   slow motions and lags, stiffening, in quick ones
delay              ``pneumatic_balance``: the force is read by a pneumatic force-balance
                   cell (nozzle-flapper): the chamber's pressure that balances it fills
                   through the supply orifice and vents through the exhaust, each flow
                   ~ the square root of its pressure drop: a lag that differs rising and
                   falling and with the level
drift              ``wax_crystallisation``: the lubricant cools through its cloud point
                   and its paraffin crystallises (Avrami kinetics): after an incubation
                   the levels and the viscous term rise along a sigmoid
backlash           ``powder_packed_gap``: the play is packed with powder (wear debris,
                   dry lubricant, dust): the drive crossing it compacts the powder ahead
                   of it, the resistance rising exponentially with the density
                   (plastically: none moving back), until the flank is reached
gms                ``poroelastic_layer``: part of the contact is carried through a
                   fluid-saturated (poroelastic) layer: its drained skeleton is elastic
                   up to the sliding level, and its interstitial fluid's pressure adds a
                   stiffness that relaxes by drainage: a stiff start after each reversal
                   that softens, and in steady sliding a rate-dependent extra stress
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``dwell_squeeze`` needs a
Stribeck curve (not the isolator's mre_lugre), ``air_film_flatness`` a record that revisits
its positions (not the press), ``bedded_rail`` a load that changes, ``powder_packed_gap``
and ``poroelastic_layer`` a classic LuGre base (valve, damping rig, XML-350); each raises a
``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.shapes import SHAPES

from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _lag, _level,
                     _light_contact_step, _lugre_params, _motion_time, _presliding_path,
                     _smooth_max0, _substeps, has_stribeck_curve, level_inside,
                     lugre_with_curve, on_fine_grid)

__all__ = ["FORMS", "feed_line_surge_truth", "bedded_rail_truth", "lifting_screw_truth",
           "dwell_squeeze_truth", "air_film_flatness_truth", "elastomer_mount_truth",
           "pneumatic_balance_truth", "wax_crystallisation_truth", "powder_packed_gap_truth",
           "poroelastic_layer_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "feed_line_surge", "load": "bedded_rail",
         "asymmetry": "lifting_screw", "stribeck_shape": "dwell_squeeze",
         "position": "air_film_flatness", "inertia": "elastomer_mount",
         "delay": "pneumatic_balance", "drift": "wax_crystallisation",
         "backlash": "powder_packed_gap", "gms": "poroelastic_layer"}


# -- acceleration ----------------------------------------------------------------------------
#: ``feed_line_surge``'s change of the levels per unit of the line's inertial pressure (at
#: the top acceleration), at strength 1 [-]; the line's lag (its resistance times its
#: compliance), x the motion's time scale [-]; the lowest level the pads' touch-down
#: leaves [-]
SURGE_RISE, SURGE_LAG, SURGE_FLOOR = 0.4, 0.2, 0.05


def _surge_pressure(t, a, lag):
    """The line's inertial pressure at the pads [-] (1 at the top acceleration, the
    carriage accelerating towards +x) along the accelerations ``a`` [-] (over the top
    acceleration) at the times ``t`` [s]: rho L a, through the line's first-order lag
    ``lag`` [s] (its flow resistance into the pads' compliance)."""
    return _lag(np.asarray(t, float), -np.asarray(a, float), lag)


@on_fine_grid
def feed_line_surge_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage rides on hydrostatic pads fed from a pump through a long supply line
    that runs along the axis (a hose from the bed's end, a drilled gallery in the
    carriage). When the carriage accelerates towards +x, the oil column in the line,
    carried along, needs a pressure rho L a to follow it: the pads' supply pressure falls
    by that much (rises, decelerating), their lift with it, and the share of the load the
    lands' solid contact carries rises (falls). The pressure reaches the pads through the
    line's resistance and the pads' compliance (a first-order lag of :data:`SURGE_LAG` x
    the motion's time scale; :func:`_surge_pressure`). The Coulomb and Stribeck levels are
    the base's times 1 + ``s`` :data:`SURGE_RISE` x the lagged inertial pressure (over its
    value at the top acceleration; never below :data:`SURGE_FLOOR`), inside the bristle
    dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the line's length times the oil's density over the pads'
        supply pressure, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The pressure a fluid column's acceleration takes in a line (Merritt 1967, Hydraulic
    Control Systems, ch. on fluid lines; White 2011, Fluid Mechanics, ch. on unsteady
    flow in pipes) and the solid share of a hydrostatic pad's load as its supply pressure
    falls (Rowe 1983, Hydrostatic and Hybrid Bearing Design, ch. on restrictors and pad
    lift; Stansfield 1970, Hydrostatic Bearings for Machine Tools). The candidate adds a
    term in the acceleration (or its lag); the open forms lag, remember, age, heat flash
    temperatures, skid, tilt, squeeze, slosh, transfer weight, load moments, press
    cylinders, attract motors, dilate, harden, spring a gib, soften, swing, unload by the
    jerk, tilt an air bearing, drive a ball train, ripple a current, slide a rack's
    flanks, set a sensor brake, shut a damper, creep a belt, rack a gantry or tighten a
    band. Here the acceleration acts on the lubricant's supply, not on the contact: a
    signed change, larger one way than the other only through the sign of a.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    lag = SURGE_LAG * max(_motion_time(kin), 1e-12)
    p = _surge_pressure(kin.t, np.asarray(kin.a, float) / a99, lag)
    lev = np.maximum(1.0 + float(s) * SURGE_RISE * p, SURGE_FLOOR)
    return level_inside(kin, lev, np.ones_like(lev))


# -- load ------------------------------------------------------------------------------------
#: ``bedded_rail``'s resistance at the bed's relaxation speed and the record's largest
#: change of the load's square (its 99th percentile), x the friction level, at strength 1
#: [-]; the bed's relaxation speed, x the top speed [-]
BED_DRAG, BED_SPEED = 1.0, 0.3


def _bed_resistance(u):
    """The bowl's resistance factor [-] (1 at its peak, odd in the speed) at the speeds
    ``u`` [-] (over the bed's relaxation speed): a standard-linear-solid bed's loss, 2 u /
    (1 + u^2), which the carriage climbs against."""
    u = np.asarray(u, float)
    return 2.0 * u / (1.0 + u * u)


@on_fine_grid
def bedded_rail_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage's rollers run on a rail bedded on a damped elastic foundation (a
    polymer-grouted or rubber-padded rail, a rail on a concrete bed): under the load W the
    rail sinks into a bowl of depth ~ W / k that travels with the carriage, and the bed's
    damping makes the bowl deeper behind the load than ahead of it, so the carriage keeps
    climbing out of its own bowl: a resistance W x the bowl's slope at the load ~ W^2,
    growing with the speed at first and falling past the bed's relaxation speed
    (:func:`_bed_resistance`, its peak at :data:`BED_SPEED` x the top speed). The base law,
    identified at the mean load, carries the resistance there; the truth adds ``s``
    :data:`BED_DRAG` x the friction level x the resistance factor x the change of (W /
    W_mean)^2 from 1 (over its 99th percentile along the record) to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], load [N]) and its base law.
    s : float
        Amplitude factor [-]: the bed's damping over its stiffness squared, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Beams on elastic foundations and moving loads on damped beds (Hetenyi 1946, Beams on
    Elastic Foundation; Fryba 1999, Vibration of Solids and Structures under Moving Loads,
    ch. on beams on a viscoelastic foundation; Kerr 1964, Elastic and viscoelastic
    foundation models, J. Appl. Mech. 31). The candidate makes the levels affine in the
    load, with a memory over the travel; the open forms scale the friction with a Hertz
    contact's area, a seal's, a film's, a junction's, a pivot's, an adhesive contact's or
    a pin's arc, break, squeeze or desorb films, plough, creep, vibrate, overload or feed
    a constant flow to a pad, heal scuffs, relieve a preload, roll on a lossy track, slip
    differentially, spin balls, press a disc spring or skid lightly loaded rollers. Here
    the loss is in the rail's bed, not in the contact: the load digs the bowl it then
    climbs, so the drag grows as its square.
    """
    L = np.asarray(kin.load, float)
    Lm = float(np.mean(np.abs(L))) or 1.0
    if not np.ptp(L) > 1e-9 * Lm:
        raise ValueError(f"load (bedded_rail): the {kin.plant} record's load does not "
                         f"change")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    d = (L / Lm) ** 2 - 1.0
    d = d / max(float(np.percentile(np.abs(d), 99)), 1e-12)
    r = _bed_resistance(np.asarray(kin.v, float) / (BED_SPEED * v99))
    return F + float(s) * BED_DRAG * _level(kin) * r * d


# -- asymmetry -------------------------------------------------------------------------------
#: ``lifting_screw``'s mu tan(lambda) of the thread at strength 1 [-]; its largest value
#: (near self-locking) [-]; the direction's rounding, x the top speed [-]
SCREW_Q, SCREW_QMAX, SCREW_ROUND = 0.25, 0.8, 0.02


def _thread_levels(direction, q):
    """The thread friction's factor [-] (1 for a flat thread) along the motion's
    ``direction`` [-] (+-1, rounded; +1 raising) for mu tan(lambda) = ``q`` [-]: the
    power screw's friction, raising W mu sec^2(lambda) / (1 - q), lowering / (1 + q),
    over its value at q = 0 (sec^2 lambda taken up by the base)."""
    d = np.asarray(direction, float)
    return 0.5 * (1.0 + d) / (1.0 - q) + 0.5 * (1.0 - d) / (1.0 + q)


@on_fine_grid
def lifting_screw_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The axis is driven by a lead screw (an Acme or trapezoidal thread) that lifts a
    weight up an incline (a Z axis, a tilted slide, a jack) as it moves towards +x. The
    thread's flank slides under the weight's axial force; resolving the forces on the
    helix of lead angle lambda, the thread's friction is W mu sec^2(lambda) / (1 - mu
    tan(lambda)) raising and W mu sec^2(lambda) / (1 + mu tan(lambda)) lowering
    (:func:`_thread_levels`): the helix wedges the flank harder raising than lowering.
    The Coulomb and Stribeck levels are the base's times that factor, with mu tan(lambda)
    = ``s`` :data:`SCREW_Q` (at most :data:`SCREW_QMAX`), the direction rounded over
    :data:`SCREW_ROUND` x the top speed, inside the bristle dynamics; the viscous term is
    the base's. The weight's own force, the same both ways, is the drive's and not in the
    force.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the thread's mu tan(lambda), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Power screws' raising and lowering torques (Shigley, Mischke and Budynas 2004,
    Mechanical Engineering Design, ch. on power screws; Juvinall and Marshek 2011,
    Fundamentals of Machine Component Design, ch. on screws; the self-locking condition
    mu > tan(lambda)). The candidate gives each direction its levels and an offset; the
    open forms twin the levels, the curves or the viscous term, bend a curve, roll a lip,
    load a thrust bearing, film a rod seal, texture a ratchet, return a spring, tilt a pad,
    strut a sprag, throttle a meter-out, differ a cylinder's areas, groove chevrons, buckle
    a helix, scrape chips, commutate, idle a belt, free a roller, wick a felt, run a belt,
    lean a brush, band a seal, counterbalance a valve, vibrate elliptically, diode a flow,
    pitch pads or skew rollers. Here a helix turns a weight into a wedge whose grip
    depends on which way it is driven.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    q = min(float(s) * SCREW_Q, SCREW_QMAX)
    d = np.tanh(np.asarray(kin.v, float) / (SCREW_ROUND * v99))
    lev = _thread_levels(d, q)
    return level_inside(kin, lev, np.ones_like(lev))


# -- stribeck_shape --------------------------------------------------------------------------
#: ``dwell_squeeze``'s dry share's friction at rest, x the Coulomb level, at strength 1 [-];
#: the squeeze-out speed (the pad's length over the film's squeeze-out time), x the top
#: speed [-]; the knee's rounding, x that speed [-]
DWELL_RISE, DWELL_SPEED, DWELL_ROUND = 0.5, 0.3, 0.05


def _dry_share(u, rounding):
    """The pad's dry share [-] (1 at rest) at the speeds ``u`` [-] (over the squeeze-out
    speed): the film under a point of the track is squeezed to the roughness after the
    time t_c, so only the part of the pad behind v t_c is dry: 1 - |u|, none beyond
    |u| = 1 (the knee rounded over ``rounding``)."""
    return _smooth_max0(1.0 - np.abs(np.asarray(u, float)), rounding)


@on_fine_grid
def dwell_squeeze_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A soft pad (an elastomer wiper, a polymer slide shoe, a tyre-like roller) runs over
    a track wetted by a thin liquid film. A point of the track under the pad's leading
    edge starts under a full film, which the pad's pressure squeezes out (Reynolds squeeze
    of a flat pad: h ~ h0 / sqrt(1 + t / tau)); the film reaches the roughness, and the
    surfaces touch, after the time t_c, that is behind the pad's first v t_c of length.
    The pad's dry share is therefore 1 - v / v_c, falling straight with the speed to none
    at the squeeze-out speed v_c = L / t_c (:data:`DWELL_SPEED` x the top speed;
    :func:`_dry_share`), where the pad hydroplanes. The truth's Stribeck curve is the
    base's plus ``s`` :data:`DWELL_RISE` x the Coulomb level x the dry share, inside the
    bristle dynamics.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (with a Stribeck curve).
    s : float
        Amplitude factor [-]: the dry contact's friction over the wet one's, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The squeeze-out of a liquid film under a tyre or a soft pad and hydroplaning (Moore
    1975, The Friction of Pneumatic Tyres, ch. on wet friction; Horne and Dreher 1963,
    Phenomena of pneumatic tire hydroplaning, NASA TN D-2056; Persson, Tartaglino, Albohr
    and Tosatti 2005, Rubber friction on wet and dry road surfaces: the sealing effect,
    Phys. Rev. B 71). The candidate's curve is Gaussian, Lorentzian or an exponential
    tail; the open forms add tails, rationals, films that lift, spikes, bimodal roughness,
    logs, Eyring, starvation, rubber hysteresis, resonances, dither, melting, grains,
    readsorption, thermoviscous, turbulent and thixotropic films, churning, core losses,
    breathing bellows, eddy brakes, shear thinning, flying pads, wiping menisci, journals,
    wall slip or a closing clearance. Here the fall is set by a dwell time, not a film's
    lift: straight in the speed down to a knee.
    """
    law = kin.base
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (dwell_squeeze): the mre_lugre base has no "
                         "Stribeck curve")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    vc = DWELL_SPEED * max(kin.scales["v99"], 1e-12)
    norm = float(_dry_share(0.0, DWELL_ROUND))
    extra = float(s) * DWELL_RISE * float(law.params.Fc) / norm
    return lugre_with_curve(kin, lambda vv: law.g(vv) + extra * _dry_share(vv / vc,
                                                                          DWELL_ROUND))


# -- position --------------------------------------------------------------------------------
#: ``air_film_flatness``'s change of the film's drag at the top speed where the gap is
#: narrowest, x the friction level, at strength 1 [-]; the flatness error's depth, x the
#: nominal gap [-]
FLAT_DRAG, FLAT_DEPTH = 0.6, 0.5


def _flatness(xr):
    """The way's flatness error [-] (within -1 .. 1; positive: the gap narrower) at the
    positions ``xr`` [-] (over the visited stroke, from its low end): a lapped granite's
    long-wave profile, a bow and a twist's trace."""
    xr = np.asarray(xr, float)
    return 0.6 * np.sin(2.0 * math.pi * 0.9 * xr + 0.4) + 0.4 * np.sin(
        2.0 * math.pi * 2.3 * xr + 1.3)


@on_fine_grid
def air_film_flatness_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage rides on aerostatic pads over a granite way whose flatness error (a
    bow and a twist, a fraction of the film's gap) changes the gap along the stroke:
    where the way rises the gap narrows, h = h0 (1 - :data:`FLAT_DEPTH` e(x))
    (:func:`_flatness`), and the film's Couette drag eta A v / h grows. The base law,
    with the nominal gap's drag, carries the drag of h0; the truth adds ``s``
    :data:`FLAT_DRAG` x the friction level x v / v99 x (h0 / h - 1), over its largest
    value, to the base: a viscous drag that changes with the position, none in the
    Coulomb level.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the air's viscosity times the pads' area over the nominal
        gap, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Air bearings' shear drag and the flatness of their guideways (Powell 1970, Design of
    Aerostatic Bearings, ch. on friction; Slocum 1992, Precision Machine Design, ch. on
    aerostatic bearings and granite structures; Stout 1985, Design of aerostatic flat pad
    bearings using pressure sources, Tribol. Int. 18). The candidate scales the friction
    along the stroke and adds a force of the position; the open forms put defects,
    waviness, wear, runout, bends, films, cogging, tapers, pockets, cushions, covers,
    springs, holes, plungers, sags, festoons, curves, chains, cams, heat, dents, joints,
    misalignment, flow forces, cranks, overhangs, a track's end or a reel on the stroke.
    Here nothing touches: the position changes a film's gap, and so a drag that is
    proportional to the speed.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (air_film_flatness): the held-out part of the "
                         f"{kin.plant} record never revisits the positions of its fit part")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    span = max(sc["x_hi"] - sc["x_lo"], 1e-12)
    xr = (np.asarray(kin.x, float) - sc["x_lo"]) / span
    g = 1.0 / (1.0 - FLAT_DEPTH * _flatness(xr)) - 1.0
    top = 1.0 / (1.0 - FLAT_DEPTH) - 1.0
    v99 = max(sc["v99"], 1e-12)
    return F + float(s) * FLAT_DRAG * _level(kin) * np.asarray(kin.v, float) / v99 * g / top


# -- inertia ---------------------------------------------------------------------------------
#: ``elastomer_mount``'s payload mass at strength 1, x the friction level / a99 [kg per
#: N s^2/m]; the mount's static mode's period, x the motion's time scale [-]; its Maxwell
#: arm's stiffness, x the static spring's [-]; the arm's relaxation time, x the static
#: mode's period [-]
MOUNT_MASS, MOUNT_PERIOD, MOUNT_ARM, MOUNT_RELAX = 0.5, 0.4, 2.0, 0.1


@njit(cache=True)
def _mount_force(a, h, w1, w2, tau):
    """The force [N per kg] the payload on a standard-linear-solid mount exerts on the
    carriage under its accelerations ``a`` [m/s^2] (steps ``h`` [s]): the payload's
    displacement y from the carriage obeys y'' = -a - w1^2 y - f, the Maxwell arm's force
    per kg f' = w2^2 y' - f / ``tau`` (springs ``w1``, ``w2`` [rad/s]); the force is a +
    y'' = -(w1^2 y + f). Semi-implicit Euler on sub-steps of at most 0.05 / sqrt(w1^2 +
    w2^2), the arm relaxed implicitly, the acceleration interpolated, from rest."""
    n = a.size
    out = np.empty(n)
    wm = math.sqrt(w1 * w1 + w2 * w2)
    m = max(1, int(math.ceil(wm * h / 0.05)))
    hs = h / m
    y = 0.0
    yd = 0.0
    f = 0.0
    out[0] = 0.0
    for k in range(1, n):
        for i in range(m):
            u = a[k - 1] + (a[k] - a[k - 1]) * (i + 1.0) / m
            yd += hs * (-u - w1 * w1 * y - f)
            y += hs * yd
            f = (f + hs * w2 * w2 * yd) / (1.0 + hs / tau)
        out[k] = -(w1 * w1 * y + f)
    return out


@on_fine_grid
def elastomer_mount_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage carries a payload (an instrument, a motor, a tool) on an elastomer
    mount, which the inverse dynamics misses. The elastomer is a standard linear solid:
    a spring (the static mode of period :data:`MOUNT_PERIOD` x the motion's time scale)
    beside a Maxwell arm :data:`MOUNT_ARM` x stiffer that relaxes over
    :data:`MOUNT_RELAX` x that period (:func:`_mount_force`): slow motions carry the
    payload on the static spring, quick ones on both springs, stiffer, with the arm's
    loss between. The truth adds ``s`` :data:`MOUNT_MASS` x the friction level / a99 x the
    payload's force per unit mass to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the payload's mass, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Elastomer mounts and the standard linear solid (Zener 1948, Elasticity and Anelasticity
    of Metals; Harris and Piersol 2002, Harris' Shock and Vibration Handbook, ch. on
    elastomeric isolators; Rivin 2003, Passive Vibration Isolation, ch. on elastomers).
    The candidate misses a constant mass; the open forms filter it, reflect it through
    gearing, a chain, a pinion or a screw, hang it on a spring, a cable, a fluid, a
    clutch, a coupling, a flyweight, a friction-damped, quasi-zero-stiffness or hose's
    column, surge a spring, add a fluid's mass, pick, drop, empty, slide, rattle,
    telescope, roll or rock it, recoil a frame, saturate a motor, lead a feedforward or
    pitch a scale. Here the mass hangs on a material whose stiffness and loss depend on
    the frequency.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    T = MOUNT_PERIOD * max(_motion_time(kin), 1e-12)
    w1 = 2.0 * math.pi / T
    w2 = math.sqrt(MOUNT_ARM) * w1
    f = _mount_force(np.ascontiguousarray(kin.a, dtype=float), float(kin.dt), w1, w2,
                     MOUNT_RELAX * T)
    return F + float(s) * MOUNT_MASS * _level(kin) / a99 * f


# -- delay -----------------------------------------------------------------------------------
#: ``pneumatic_balance``'s chamber time constant at mid-range at strength 1 [data samples];
#: the chamber's pressure range the force spans, from vent (0) to supply (1) [-]
PNEU_SAMPLES, PNEU_LO, PNEU_HI = 2.0, 0.15, 0.85


@njit(cache=True)
def _balance_pressure(t, target, tau):
    """The chamber's pressure [-] (0 vent, 1 supply) along the times ``t`` [s] towards the
    pressures ``target`` [-] that balance the force: it fills through the supply orifice,
    at a rate ~ sqrt(1 - p), and vents through the exhaust, ~ sqrt(p), each
    (target - p) / ``tau`` at mid-range (``tau`` [s]); each step exact for its rate, from
    the first target."""
    n = t.size
    out = np.empty(n)
    p = target[0]
    out[0] = p
    for k in range(1, n):
        h = t[k] - t[k - 1]
        d = target[k] - p
        if d > 0.0:
            g = math.sqrt(max(1.0 - p, 0.0) / 0.5)
        else:
            g = math.sqrt(max(p, 0.0) / 0.5)
        p = p + d * (1.0 - math.exp(-h * g / tau))
        out[k] = p
    return out


@on_fine_grid
def pneumatic_balance_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is read by a pneumatic force-balance cell (a nozzle-flapper transmitter,
    as in process weighing and older test rigs): the force tilts a flapper over a nozzle,
    and a relay sets the pressure in a balancing bellows until its force balances the
    measured one; the reading is that pressure. The bellows' chamber fills through the
    supply orifice, its flow ~ sqrt(p_supply - p), and vents through the exhaust, ~ sqrt(p
    - p_atm) (:func:`_balance_pressure`; the force's range spans :data:`PNEU_LO` to
    :data:`PNEU_HI` of the pressure's, its time constant ``s`` :data:`PNEU_SAMPLES` data
    samples at mid-range): a rising force near the top of the range is followed more
    slowly than a falling one, and the lag changes with the level. The motion channels are
    on time.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the chamber's volume over its orifices' conductance, / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Pneumatic force-balance transmitters and orifice flows (Andersen 1967, The Analysis and
    Design of Pneumatic Systems; Considine 1985, Process Instruments and Controls Handbook,
    ch. on pneumatic transmitters; Doebelin 2004, Measurement Systems, ch. on force
    measurement). The candidate shifts the force by a constant time, low-passes it, reads
    it through a transducer's resonance and leaks it; the open forms sample, filter,
    average, hold, skew, jitter, rate-limit, transmit, median, report by deadband, trigger
    on positions, run a belt, aerate, drop telegrams, leak, creep, notch, track, snub,
    time a waveguide's pulse, diffuse eddy currents, count a resonator, sweep a grating,
    restore a force by a servo or interleave converters. Here the balance is an air
    volume filled and emptied through orifices: the lag depends on the direction and on
    the level.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    lo, hi = float(np.min(F)), float(np.max(F))
    span = max(hi - lo, 1e-12)
    target = PNEU_LO + (PNEU_HI - PNEU_LO) * (F - lo) / span
    tau = float(s) * PNEU_SAMPLES * kin.sample_dt
    p = _balance_pressure(np.ascontiguousarray(kin.t, dtype=float),
                          np.ascontiguousarray(target), tau)
    return lo + (p - PNEU_LO) / (PNEU_HI - PNEU_LO) * span


# -- drift -----------------------------------------------------------------------------------
#: ``wax_crystallisation``'s rise of the levels by the record's end, at strength 1 [-]; the
#: time the oil passes its cloud point, x the record's length [-]; the crystallisation's
#: Avrami time, x the record's length [-]; Avrami's exponent [-]
WAX_RISE, WAX_ONSET, WAX_TIME, WAX_EXPONENT = 0.4, 0.2, 0.45, 3.0


def _crystallised(tau, onset, time, expo):
    """The crystallised share of the wax [-] at the times ``tau`` [-] (over the record's
    length): none before the cloud point's ``onset``, then Avrami's 1 - exp(-((tau -
    onset) / ``time``)^``expo``)."""
    u = np.maximum(np.asarray(tau, float) - onset, 0.0) / time
    return 1.0 - np.exp(-u ** expo)


@on_fine_grid
def wax_crystallisation_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The machine runs in a cold place (a cold store, an outdoor machine in winter), its
    lubricant cooling through its cloud point while it runs: its dissolved paraffin
    crystallises, nucleating and growing as Avrami's kinetics (:func:`_crystallised`; the
    cloud point passed at :data:`WAX_ONSET` x the record's length, Avrami time
    :data:`WAX_TIME` x it, exponent :data:`WAX_EXPONENT`: three-dimensional growth), and
    the crystals' network thickens the film and roughens the boundary layer. The Coulomb
    and Stribeck levels and the viscous term are the base's times 1 + ``s``
    :data:`WAX_RISE` x the crystallised share over its value at the record's end, inside
    the bristle dynamics: nothing at first, then a sigmoid rise.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the crystallised oil's friction over the clear one's, / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Crystallisation kinetics (Avrami 1939, Kinetics of phase change I, J. Chem. Phys. 7;
    Avrami 1940, ibid. 8) and the wax in lubricating oils below their cloud point
    (Srivastava, Handoo, Agrawal and Joshi 1993, Phase-transition studies in n-alkanes and
    petroleum-related waxes, J. Phys. Chem. Solids 54; Mortier, Fox and Orszulik 2010,
    Chemistry and Technology of Lubricants, ch. on pour point depressants). The candidate
    is a trend, a saturating change, a step, a cycle, a resetting change or the friction
    power's heat; the open forms warm up, wear in, change, heat, wear, follow the
    humidity, grind, relubricate, relax, oxidise, deplete, wear through, swell, build
    films, take in particles, expand, shear down, heat magnets, charge, creep, loosen,
    dewet, channel, drain, spall, evaporate, pump down or settle an additive. Here the oil
    changes phase: nothing until the cloud point, then nucleation and growth.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    tau = (t - t[0]) / max(t[-1] - t[0], 1e-12)
    X = _crystallised(tau, WAX_ONSET, WAX_TIME, WAX_EXPONENT)
    lev = 1.0 + float(s) * WAX_RISE * X / max(float(X[-1]), 1e-12)
    return level_inside(kin, lev, lev)


# -- backlash --------------------------------------------------------------------------------
#: ``powder_packed_gap``'s play at strength 1, as a share of the stroke (its full width,
#: both sides) [-]; the packed powder's resistance at the flank, x the Coulomb level [-];
#: the compaction law's exponent [-]; the rounding of the compaction's direction, x the
#: top speed [-]
POWDER_CLEAR, POWDER_PACK, POWDER_EXPONENT, POWDER_ROUND = 0.01, 0.5, 4.0, 0.02


@njit(cache=True)
def _powder_force(e, ed, half, kh, ch, pack, expo, vround):
    """The force [N] across a powder-packed play of half-width ``half`` [m] at the offset
    ``e`` [m] (drive minus contact) and its rate ``ed`` [m/s]: beyond the play the flank,
    a spring ``kh`` [N/m] and damper ``ch`` [N s/m] (compressive only); within it the
    powder ahead of the drive, compacted plastically: a resistance along the rate (rounded
    over ``vround`` [m/s]) of ``pack`` [N] x (e^(k xi) - 1) / (e^k - 1), xi the share of
    the play closed in that direction, k = ``expo``."""
    if e > half:
        f = kh * (e - half) + ch * ed
        return f if f > 0.0 else 0.0
    if e < -half:
        f = kh * (e + half) + ch * ed
        return f if f < 0.0 else 0.0
    d = math.tanh(ed / vround)
    xi_p = (e + half) / (2.0 * half)
    xi_m = (half - e) / (2.0 * half)
    c = math.exp(expo) - 1.0
    fp = (math.exp(expo * xi_p) - 1.0) / c
    fm = (math.exp(expo * xi_m) - 1.0) / c
    return pack * (0.5 * (1.0 + d) * fp * d + 0.5 * (1.0 - d) * fm * d)


@njit(cache=True)
def _powder_contact(h, xd, half, kh, ch, pack, expo, vround, m, s0, s1, s2, Fc, Fs, vs,
                    alpha, shape):
    """LuGre friction [N] of a light contact of mass ``m`` [kg] driven by the drive
    positions ``xd`` [m] (steps ``h`` [s]) across the powder-packed play of
    :func:`_powder_force`, starting at rest against the +x flank."""
    n = xd.size
    F = np.empty(n)
    x = xd[0] - half
    v = 0.0
    z = 0.0
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        fc = _powder_force(xd[j] - x, vd - v, half, kh, ch, pack, expo, vround)
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha,
                                         shape)
        x = x + h * v
    return F


@on_fine_grid
def powder_packed_gap_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact are joined across a play (``s``^2 :data:`POWDER_CLEAR` x the
    stroke wide) that is packed with powder: wear debris in a gear's or a spline's
    clearance, a dry lubricant (graphite, MoS2) or dust in an open drive. After a reversal
    the drive crossing the play pushes the powder ahead of it against the other flank,
    compacting it: the powder's resistance grows exponentially with its density (the
    share of the play closed; :data:`POWDER_EXPONENT`) up to :data:`POWDER_PACK` x the
    Coulomb level at the flank, and, the compaction being plastic, it does not push back
    when the drive retreats (:func:`_powder_force`). The contact is light (its inertial
    force at the top acceleration 1 % of the Coulomb level) with the base's LuGre friction
    (:func:`_powder_contact`); the flanks as the open plays'.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the square root of the clearance, / its value at strength 1
        (as the open plays').

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Powder compaction's exponential pressure-density law (Kawakita and Luedde 1971, Some
    considerations on powder compression equations, Powder Technol. 4; Heckel 1961,
    Density-pressure relationships in powder compaction, Trans. Metall. Soc. AIME 221) and
    debris in gear and spline clearances (Ku and Valtierra 1975, Spline wear - effects of
    design and lubrication, J. Eng. Ind. 97; Godet 1984, The third-body approach, Wear
    100). The candidate holds or frees the contact across a rigid play; the open forms
    take it up rigidly, compliantly, by impact, against a spring, eccentrically, through
    oil, worn, with a dragging idler, biased, slack, magnetic, preloaded, through a
    flexspline, a rope, a spider, a fluid link, a cable, a clutch, a varying mesh, a
    polymer gear, grease, a wedge, an overlapped spool, a side loaded pin, a toggle
    spring, graded pins or an adhesive flank. Here the gap is full of a solid that yields
    only one way: it resists being crushed and never pushes back.
    """
    p = _lugre_params(kin, "backlash (powder_packed_gap)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    half = 0.5 * float(s) ** 2 * POWDER_CLEAR * float(np.ptp(kin.x))
    m, kh, ch = _contact_constants(kin, p)
    pack = POWDER_PACK * float(p.Fc)
    vround = POWDER_ROUND * max(kin.scales["v99"], 1e-12)
    rate = max(math.sqrt(kh / m), (float(p.sigma1) + float(p.sigma2) + ch) / m,
               pack / (vround * m))
    h, xd, n_sub = _substeps(kin, rate)
    Fr = _powder_contact(h, xd, half, kh, ch, pack, POWDER_EXPONENT, vround, m,
                         float(p.sigma0), float(p.sigma1), float(p.sigma2), float(p.Fc),
                         float(p.Fs), float(p.vs), float(p.alpha), SHAPES[p.shape])
    return Fr[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: the layer's drained elastic path to the sliding level at strength 1, beyond the base
#: bristle's path, as a share of the stroke / 3 [-]; its share of the friction at strength
#: 1 [-]; the fluid pressure's stress in steady sliding at the top speed, x the sliding
#: level [-]; the drainage time, x the motion's time scale [-]
PORO_PATH, PORO_SHARE, PORO_FLUID, PORO_DRAIN = 0.1, 0.6, 0.3, 0.3


@njit(cache=True)
def _poro_layer(t, v, path, fluid_gain, drain):
    """(skeleton stress, fluid stress) [-] (the skeleton's 1 at its sliding level) along
    the velocities ``v`` [m/s] at the times ``t`` [s]: the drained skeleton elastic over
    ``path`` [m] and perfectly plastic at +-1; the interstitial fluid's stress q' =
    ``fluid_gain`` v - q / ``drain`` (its pressure relaxing by drainage over ``drain``
    [s]), exact on each step; from no stress."""
    n = t.size
    u = np.zeros(n)
    q = np.zeros(n)
    ue = 0.0
    qf = 0.0
    for k in range(1, n):
        h = t[k] - t[k - 1]
        ue = ue + h * v[k] / path
        if ue > 1.0:
            ue = 1.0
        elif ue < -1.0:
            ue = -1.0
        e = math.exp(-h / drain)
        qf = qf * e + fluid_gain * v[k] * drain * (1.0 - e)
        u[k] = ue
        q[k] = qf
    return u, q


@on_fine_grid
def poroelastic_layer_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Part of the contact is carried through a fluid-saturated porous layer (a
    sintered, oil-impregnated bronze liner's skin, a hydrogel or a wet polymer coating):
    in shear its drained skeleton is elastic up to the sliding level and then slides
    (its elastic path the base bristle's Fs / sigma0 plus ``s`` :data:`PORO_PATH` x the
    stroke / 3), and its interstitial fluid, pressurised by the layer's deformation, adds
    a stress that relaxes as the fluid drains through the pores (drainage time
    :data:`PORO_DRAIN` x the motion's time scale; :func:`_poro_layer`): after each
    reversal the layer is stiffer than its skeleton, softening as it drains, and in steady
    sliding the fluid carries a stress ~ the speed (:data:`PORO_FLUID` x the sliding
    level at the top speed). Its share w = ``s`` :data:`PORO_SHARE` (up to ``s`` = 1) of
    the friction is its stress times the Stribeck level, the viscous term the base's: F =
    (1 - w) F_lugre + w (g(v) (u + q) / (1 + PORO_FLUID) + sigma2 v). At ``s`` = 0 the
    base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the layer's share (up to ``s`` = 1) and its elastic path (as
        the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Poroelasticity and the interstitial fluid's load support in friction (Biot 1941,
    General theory of three-dimensional consolidation, J. Appl. Phys. 12; Mow, Kuei,
    Lai and Armstrong 1980, Biphasic creep and stress relaxation of articular cartilage,
    J. Biomech. Eng. 102; Ateshian 2009, The role of interstitial fluid pressurization in
    articular cartilage lubrication, J. Biomech. 42). The candidate's presliding is a
    generalized Maxwell-slip (GMS) element set; the open forms are Maxwell-slip sets,
    Dahl, elasto-plastic, Bliman-Sorine, Bouc-Wen, Zener junctions, Mindlin contacts,
    rate-and-state, Tomlinson asperities, bond rupture, gouge, kinematic hardening,
    interlocking, capillary bridges, cyclic hardening, peeling, unloading microslip, a
    power-law joint, junction growth, avalanches, slip weakening, a microslip bar, contact
    renewal, grease's yield, a superelastic flexure, an Eyring film or a viscoplastic
    layer. Here a second phase, the fluid in the pores, carries part of the stress for as
    long as it takes to drain.
    """
    p = _lugre_params(kin, "gms (poroelastic_layer)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    z_path, extra = _presliding_path(kin, s, PORO_PATH)
    v = np.asarray(kin.v, float)
    v99 = max(kin.scales["v99"], 1e-12)
    drain = PORO_DRAIN * max(_motion_time(kin), 1e-12)
    gain = PORO_FLUID / (v99 * drain)
    u, q = _poro_layer(np.ascontiguousarray(kin.t, dtype=float), np.ascontiguousarray(v),
                       z_path + extra, gain, drain)
    w = min(float(s) * PORO_SHARE, 1.0)
    return (1.0 - w) * F + w * (kin.base.g(v) * (u + q) / (1.0 + PORO_FLUID)
                                + float(p.sigma2) * v)
