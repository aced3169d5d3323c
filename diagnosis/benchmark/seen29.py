"""The twenty-ninth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-12-01 (session 33) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 34 (2026-12-01) on the code of f2c371c:
176 cases, 0 skipped, 403 s wall on 2 workers. Top-1 62.5 % (110;
63.5 % of the 170 detectable; the 6 undetectable are all delays below their practical size
(2 of them named delay, 2 unexplained, 2 none)); mean |shrink error| 0.269 (0.216 over the
right ones); wrong names on 23 (13.1 %): acceleration -> asymmetry 6, delay -> acceleration
4, gms -> delay 4, drift -> load 3, load -> delay 2, asymmetry -> load 2, backlash -> gms 1,
inertia -> position 1. By form: position/ferrous_insert 16/16, load/clamping_cylinder 18/20
(delay 2), drift/lining_glazing 16/20 (load 3, none 1), inertia/friction_pendulum 14/20
(unexplained 4, none 1, position 1), asymmetry/gecko_wedges 12/20 (unexplained 4, none 2,
load 2), delay/fixed_point_filter 11/20 (acceleration 4, unexplained 3, none 2),
gms/hysteresis_brake 6/12 (delay 4, unexplained 2), stribeck_shape/flash_weakening 7/16
(none 6, unexplained 3), acceleration/elastic_counterweight 8/20 (unexplained 6,
asymmetry 6), backlash/detent_ball 2/12 (unexplained 9, gms 1). By plant: valve 70.0 %,
isolator 67.9 %, XML-350 67.5 %, damping rig 60.0 %, forging press 42.9 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen28` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen28`,
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
acceleration       ``elastic_counterweight``: the axis is counterbalanced by a weight on a
                   rope over a sheave; the rope's tension, and with it the sheave
                   bearing's load and friction, falls as the carriage accelerates the
                   weight and rises as it brakes it, the weight bouncing on the rope's
                   elasticity
load               ``clamping_cylinder``: the normal load is set by a clamping cylinder
                   whose piston seal has friction: the force the contact receives
                   follows the measured load through a play of twice the seal's
                   friction, held while the load turns back
asymmetry          ``gecko_wedges``: the carriage's pads carry angled microwedges (a
                   gecko-like dry adhesive): pulled along the wedges they adhere and add
                   an adhesion-controlled friction, which needs time to attach and so
                   fades with the speed; pushed against them they slide on their tips
stribeck_shape     ``flash_weakening``: above a weakening speed the asperity contacts
                   heat to their weakening temperature within their lifetimes (flash
                   heating): the friction falls as the weakening speed over the speed
                   towards a weakened level; below it the base's
position           ``ferrous_insert``: the carriage's preload magnet runs over a steel
                   insert set in the bed along part of the stroke: the attraction, and
                   the friction with it, rise over the insert, and the magnet is drawn
                   into it at its edges (a reluctance force)
inertia            ``friction_pendulum``: a payload stands on a curved sliding isolator
                   (a friction pendulum bearing) on the carriage: it rides along until
                   its inertial force overcomes the slider's friction, then slides on
                   the dish, pulled back by gravity on its curvature
delay              ``fixed_point_filter``: the force is smoothed by a recursive first-order
                   filter in integer arithmetic: each update adds the floor of the gain
                   times the difference, in counts, so the reading lags and stops short
                   of a slowly changing force (a rounding dead band)
drift              ``lining_glazing``: the contact's pads are a resin-bonded lining whose
                   surface glazes with the friction work it dissipates: the levels fall
                   as the work accumulates, saturating, and hold in dwells
backlash           ``detent_ball``: a spring-loaded ball in the drive rides in a V-notch of
                   the contact's link in the play's middle: crossing the play, the drive
                   pulls the contact towards itself while the ball is in the notch and
                   nothing bridges the play beyond it, up to the flank
gms                ``hysteresis_brake``: part of the friction is a magnetic hysteresis
                   brake (a magnetised rotor or strip dragged past a pole structure): its
                   force, speed-independent in sliding, reverses over a path along the
                   magnetisation's Rayleigh branches at each reversal; at ``s`` = 0 the
                   base
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``flash_weakening``
needs a Stribeck curve (not the isolator's mre_lugre), ``ferrous_insert`` a record that
revisits its positions (not the press), ``clamping_cylinder`` a load that changes,
``detent_ball`` and ``hysteresis_brake`` a classic LuGre base (valve, damping rig,
XML-350); each raises a ``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.shapes import SHAPES

from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _level,
                     _light_contact_step, _lugre_params, _motion_time, _presliding_path,
                     _substeps, has_stribeck_curve, level_inside, lugre_with_curve,
                     on_fine_grid)

__all__ = ["FORMS", "elastic_counterweight_truth", "clamping_cylinder_truth",
           "gecko_wedges_truth", "flash_weakening_truth", "ferrous_insert_truth",
           "friction_pendulum_truth", "fixed_point_filter_truth", "lining_glazing_truth",
           "detent_ball_truth", "hysteresis_brake_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "elastic_counterweight", "load": "clamping_cylinder",
         "asymmetry": "gecko_wedges", "stribeck_shape": "flash_weakening",
         "position": "ferrous_insert", "inertia": "friction_pendulum",
         "delay": "fixed_point_filter", "drift": "lining_glazing",
         "backlash": "detent_ball", "gms": "hysteresis_brake"}


# -- acceleration ----------------------------------------------------------------------------
#: ``elastic_counterweight``'s fall of the levels per unit of the weight's acceleration over
#: its 99th percentile along the record, at strength 1 [-]; the weight's bounce on the rope, its period x
#: the motion's time scale [-]; its damping ratio [-]
CW_DROP, CW_PERIOD, CW_DAMPING = 0.3, 4.0, 0.3


@njit(cache=True)
def _rope_bounce(t, a, omega, zeta):
    """The acceleration [m/s^2] of a weight hung on an elastic rope whose other end
    accelerates by ``a`` [m/s^2] at the times ``t`` [s] (uniform), from rest: the rope's
    stretch y follows y'' = -``a`` - omega^2 y - 2 ``zeta`` omega y' (the weight's mass
    over the rope's stiffness 1 / omega^2), and the weight's acceleration is ``a`` + y'';
    semi-implicit Euler on sub-steps of at most 0.02 / omega, the end's acceleration held
    over each."""
    n = t.size
    out = np.empty(n)
    dt = t[1] - t[0] if n > 1 else 0.0
    n_sub = max(1, int(math.ceil(omega * dt / 0.02)))
    h = dt / n_sub
    y = 0.0
    w = 0.0
    for k in range(n):
        out[k] = -omega * omega * y - 2.0 * zeta * omega * w
        if k + 1 < n:
            am = 0.5 * (a[k] + a[k + 1])
            for _ in range(n_sub):
                w = w + h * (-am - omega * omega * y - 2.0 * zeta * omega * w)
                y = y + h * w
    return out


@on_fine_grid
def elastic_counterweight_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The axis is counterbalanced (as vertical axes, lifts and the rams of presses are) by
    a weight on a steel rope over a sheave; the sheave's bearing and the rope's bending
    over it carry the friction the base law sees. The rope's tension is the weight's
    gravity less its inertial force: the weight moves against the carriage, so the
    tension, the sheave's load and its bearing's friction fall as the carriage speeds up
    and rise as it slows. The rope is elastic: the weight bounces on it
    (:func:`_rope_bounce`, a period of :data:`CW_PERIOD` x the motion's time scale, damped
    at :data:`CW_DAMPING`), so its acceleration is the carriage's through a lightly
    damped resonance. The Coulomb and Stribeck levels are the base's times 1 - ``s``
    :data:`CW_DROP` x the weight's acceleration over its 99th percentile along the record
    (at least 0.05: the rope slackens), inside the bristle dynamics; the viscous term is
    the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the weight's inertial share of the rope's tension at the top
        acceleration, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Counterweighted hoisting ropes and their dynamic tension (Feyrer 2015, Wire Ropes:
    Tension, Endurance, Reliability, ch. on rope drives and sheaves; Strakosch 1998, The
    Vertical Transportation Handbook, ch. on counterweights and roping) and the load
    dependence of a bearing's friction moment (Harris and Kotzalas 2007, Rolling Bearing
    Analysis, ch. on friction in rolling bearings). The candidate raises the levels with
    |a|, lagged, tilts them with a and adds a force odd in a; the open forms lag, age,
    heat, skid, load, press, attract, squeeze, transfer weight, slosh, dilate, wedge,
    spring a gib, soften rubber, swing arms, unload by the jerk, tilt pads, push ball
    trains, ripple the current, slide rack flanks, set a shoe by a ball in a cone, shut a
    damper's bypass, creep a belt, rack a gantry, tighten a band, surge a feed line, load
    a traction drive's cam or heat a motor's winding. Here a counterweight's inertia
    unloads the rope, and the sheave's friction with it, through the rope's elasticity.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    omega = 2.0 * math.pi / (CW_PERIOD * max(_motion_time(kin), 1e-12))
    aw = _rope_bounce(np.asarray(kin.t, float), np.asarray(kin.a, float), omega,
                      CW_DAMPING)
    aw = aw / max(float(np.percentile(np.abs(aw), 99)), 1e-12)
    lev = np.maximum(1.0 - float(s) * CW_DROP * aw, 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- load ------------------------------------------------------------------------------------
#: ``clamping_cylinder``'s rise of the levels per unit of the clamping force's change over
#: the mean load, at strength 1 [-]; the piston seal's friction, x the load's range [-]
CLAMP_RISE, CLAMP_SEAL = 0.8, 0.12


@njit(cache=True)
def _seal_play(q, r):
    """The force [-] a clamping cylinder's piston passes on at the commanded forces ``q``
    [-] when its seal holds the friction ``r`` [-]: the piston moves only when the
    command leaves the seal's band, N = q - r rising and q + r falling, and holds
    otherwise (a play operator of half-width ``r``, from N = q)."""
    n = q.size
    out = np.empty(n)
    y = q[0] if n > 0 else 0.0
    for k in range(n):
        if q[k] - y > r:
            y = q[k] - r
        elif y - q[k] > r:
            y = q[k] + r
        out[k] = y
    return out


@on_fine_grid
def clamping_cylinder_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The normal load is applied by a clamping cylinder (a pneumatic or hydraulic clamp, a
    brake's caliper piston, a press's pad cushion) and read from its pressure. The piston's
    seal has friction: rising, the piston passes the pressure's force less the seal's;
    falling, more; turning back, it sticks and holds the force until the pressure has
    changed by twice the seal's friction (:func:`_seal_play`, the seal's friction
    :data:`CLAMP_SEAL` x the load's range). The contact's friction follows the force
    the contact receives, not the one read: the Coulomb and Stribeck levels are the base's
    times 1 + ``s`` :data:`CLAMP_RISE` x that force's change from the mean load, over the
    mean load, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], load [N]) and its base law.
    s : float
        Amplitude factor [-]: the share of the contact's friction the clamping force
        carries, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Seal friction in pneumatic and hydraulic cylinders and its hysteresis in the force
    they pass on (Beater 2007, Pneumatic Drives, ch. on friction in cylinders; Belforte,
    Mattiazzo, Mauro and Tokashiki 2003, Measurement of friction force in pneumatic
    cylinders, Tribotest 10) and the play operator of hysteresis (Krasnosel'skii and
    Pokrovskii 1989, Systems with Hysteresis, ch. on the play). The candidate makes the
    levels affine in the load, with a memory over the travel; the open forms scale the
    friction with a Hertz contact's area, a seal's, a film's, a junction's, a pivot's, an
    adhesive contact's or a pin's arc, break, squeeze or desorb films, plough, creep,
    vibrate, overload or feed a constant flow to a pad, heal scuffs, relieve a preload,
    roll on a lossy track, slip differentially, spin balls, press a disc spring, skid
    lightly loaded rollers, bed a rail, heat a liner by PV or shear a soft film under
    pressure. Here the load's own actuator passes it on through its seal's friction: the
    contact's load lags the reading by a play.
    """
    L = np.asarray(kin.load, float)
    Lm = float(np.mean(np.abs(L))) or 1.0
    if not np.ptp(L) > 1e-9 * Lm:
        raise ValueError(f"load (clamping_cylinder): the {kin.plant} record's load does "
                         f"not change")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    N = _seal_play(L, CLAMP_SEAL * float(np.ptp(L)))
    lev = np.maximum(1.0 + float(s) * CLAMP_RISE * (N - Lm) / Lm, 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``gecko_wedges``' rise of the levels at rest along the wedges, at strength 1 [-]; the
#: speed at which the wedges attach over half their contact, x the top speed [-]; the
#: rounding of the direction, x the top speed [-]
GECKO_RISE, GECKO_SPEED, GECKO_ROUND = 0.4, 0.5, 0.05


def _wedge_adhesion(direction, u):
    """The share of the wedges' adhesion [-] along the motion's ``direction`` [-] (+-1,
    rounded) at the speeds ``u`` [-] (over the speed at which half attach): pulled along
    the wedges (+x) they attach over their contact time, 1 / (1 + |u|); pushed against
    them (-x) none."""
    d = np.asarray(direction, float)
    return 0.5 * (1.0 + d) / (1.0 + np.abs(np.asarray(u, float)))


@on_fine_grid
def gecko_wedges_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage's pads carry a gecko-like dry adhesive: a field of angled polymer
    microwedges (as on climbing robots', grippers' and space mechanisms' pads). Sheared
    along their lean (+x), the wedges lay their sides on the counterface and adhere by
    van der Waals forces; the adhesion presses the pad on and adds to the friction
    (frictional adhesion). Sheared against it (-x), they stand on their tips and do not
    adhere. The wedges take time to lay down and attach, so the adhesion's share is 1 /
    (1 + |v| / v_a) (:func:`_wedge_adhesion`; v_a :data:`GECKO_SPEED` x the top speed).
    The Coulomb and Stribeck levels are the base's times 1 + ``s`` :data:`GECKO_RISE` x
    that share, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the wedges' share of the pads, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Frictional adhesion of gecko setae and of angled synthetic microwedges (Autumn,
    Dittmore, Santos, Spenko and Cutkosky 2006, Frictional adhesion: a new angle on gecko
    attachment, J. Exp. Biol. 209; Parness, Soto, Esparza, Wangsuwan and Cutkosky 2009, A
    microfabricated wedge-shaped adhesive array displaying gecko-like dynamic adhesion,
    directionality and long lifetime, J. R. Soc. Interface 6). The candidate gives each
    direction its levels and an offset; the open forms twin the levels, the curves or the
    viscous term, bend a curve, roll a lip, load a thrust bearing, film a rod seal,
    texture a ratchet, return a spring, tilt a pad, strut a sprag, throttle a meter-out,
    differ a cylinder's areas, groove chevrons, buckle a helix, scrape chips, commutate,
    idle a belt, free a roller, wick a felt, run a belt, lean a brush, band a seal,
    counterbalance a valve, vibrate elliptically, diode a flow, pitch pads, skew rollers,
    lift through a screw, turn the frame or angle a pull. Here the pads' surface adheres
    one way only, and the adhesion needs time to form.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    v = np.asarray(kin.v, float)
    d = np.tanh(v / (GECKO_ROUND * v99))
    lev = 1.0 + float(s) * GECKO_RISE * _wedge_adhesion(d, v / (GECKO_SPEED * v99))
    return level_inside(kin, lev, np.ones_like(lev))


# -- stribeck_shape --------------------------------------------------------------------------
#: ``flash_weakening``'s fall of the curve far above the weakening speed, at strength 1 (at
#: most 0.9) [-]; the weakening speed, x the top speed [-]
FLASH_DROP, FLASH_SPEED = 0.5, 0.2


def _flash_factor(u, drop):
    """The asperities' friction [-] (1 below weakening) at the speeds ``u`` [-] (over the
    weakening speed): 1 - ``drop`` (1 - 1 / |u|) above it (Rice's flash heating: the
    asperity lives past its weakening time for the share 1 / |u| of its life)."""
    r = np.abs(np.asarray(u, float))
    return 1.0 - drop * (1.0 - 1.0 / np.maximum(r, 1.0))


@on_fine_grid
def flash_weakening_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The contact's asperities heat in flashes while they live (Rice's flash heating):
    an asperity of size D sliding at v lives D / v and its temperature rises as the
    square root of its time; above a weakening speed v_w its contact reaches the
    weakening temperature within its life, and for the rest of it carries a weakened
    friction. The friction is the base's below v_w and falls as v_w / |v| towards the
    weakened level above it (:func:`_flash_factor`; v_w :data:`FLASH_SPEED` x the top
    speed, the weakened level 1 - ``s`` :data:`FLASH_DROP`): the truth's Stribeck curve
    is the base's times that factor, inside the bristle dynamics; a kink at v_w, no
    smooth transition.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (with a Stribeck curve).
    s : float
        Amplitude factor [-]: the weakening's depth, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Flash heating and weakening of frictional contacts (Rice 2006, Heating and weakening
    of faults during earthquake slip, J. Geophys. Res. 111; Beeler, Tullis and Goldsby
    2008, Constitutive relationships and physical basis of fault strength due to flash
    heating, J. Geophys. Res. 113; Archard 1959, The temperature of rubbing surfaces, Wear
    2). The candidate's curve is Gaussian, Lorentzian or an exponential tail; the open
    forms add tails, rationals, films that lift, spikes, bimodal roughness, logs, Eyring,
    starvation, rubber hysteresis, resonances, dither, melting, grains, readsorption,
    thermoviscous, turbulent and thixotropic films, churning, core losses, breathing
    bellows, eddy brakes, shear thinning, flying pads, wiping menisci, journals, wall
    slip, a closing clearance, a dwell's squeeze, a pocket's suction or condensing
    menisci. Here the asperities' own flash temperature weakens them, above a speed set
    by their size and the heat's diffusion.
    """
    law = kin.base
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (flash_weakening): the mre_lugre base has no "
                         "Stribeck curve")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    vw = FLASH_SPEED * max(kin.scales["v99"], 1e-12)
    k = min(float(s) * FLASH_DROP, 0.9)
    return lugre_with_curve(kin, lambda vv: law.g(vv) * _flash_factor(vv / vw, k))


# -- position --------------------------------------------------------------------------------
#: ``ferrous_insert``'s rise of the levels over the insert, at strength 1 [-]; the
#: reluctance force's peak at the insert's edges, x the friction level, at strength 1 [-];
#: the insert's length and its edges' fringing width, x the visited stroke [-]
FERRO_RISE, FERRO_PULL, FERRO_WIDTH, FERRO_FRINGE = 0.4, 0.1, 0.3, 0.03


def _insert_field(xr, centre, width, fringe):
    """(the magnet's attraction [-], 1 over the insert, 0 far from it; its slope times
    the fringing width [-]) at the positions ``xr`` [-] (over the visited stroke), the
    insert ``width`` long around ``centre``, its edges fringing over ``fringe``."""
    u1 = (np.asarray(xr, float) - (centre - 0.5 * width)) / fringe
    u2 = (np.asarray(xr, float) - (centre + 0.5 * width)) / fringe
    w = 0.5 * (np.tanh(u1) - np.tanh(u2))
    dw = 0.5 * (1.0 / np.cosh(u1) ** 2 - 1.0 / np.cosh(u2) ** 2)
    return w, dw


@on_fine_grid
def ferrous_insert_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage is preloaded onto its ways by a permanent magnet (as magnetically
    preloaded air bearings and some linear guides are) and runs over a bed of a
    non-magnetic material with a steel insert set in it along part of the stroke (a
    clamping strip, a repaired section, a reinforcement; :data:`FERRO_WIDTH` x the
    visited stroke around the middle of what the record's two parts both visit). Over
    the insert the magnet's circuit closes through steel: its attraction, the bearings'
    load and the friction rise (the Coulomb and Stribeck levels the base's times 1 +
    ``s`` :data:`FERRO_RISE` x the attraction's share, :func:`_insert_field`, inside the
    bristle dynamics). At the insert's edges the magnet is drawn into the steel, a
    reluctance force along the stroke, the energy's slope (peak ``s``
    :data:`FERRO_PULL` x the friction level), which the drive carries.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the magnet's strength over the insert, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The reluctance (Maxwell stress) force of a permanent magnet near a ferromagnetic
    part, normal and along the edge (Furlani 2001, Permanent Magnet and Electromechanical
    Devices, ch. on magnetic forces; Slocum 1992, Precision Machine Design, ch. on
    magnetically preloaded bearings). The candidate scales the friction along the stroke
    and adds a force of the position; the open forms put defects, waviness, wear, runout,
    bends, films, cogging, tapers, pockets, cushions, covers, springs, holes, plungers,
    sags, festoons, curves, chains, cams, heat, dents, joints, misalignment, flow forces,
    cranks, overhangs, a track's end, a reel, a way's flatness, conductive strips or a
    guide's ball passage on the stroke. Here a steel part in the bed closes a magnet's
    circuit: a static attraction over it and a pull at its edges.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (ferrous_insert): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    span = max(sc["x_hi"] - sc["x_lo"], 1e-12)
    xr = (np.asarray(kin.x, float) - sc["x_lo"]) / span
    c = (_bump_centre(kin) - sc["x_lo"]) / span
    w, dw = _insert_field(xr, c, FERRO_WIDTH, FERRO_FRINGE)
    lev = 1.0 + float(s) * FERRO_RISE * w
    # the magnet drawn towards the steel: the drive holds it back (force against dw)
    return level_inside(kin, lev, np.ones_like(lev)) - float(s) * FERRO_PULL * _level(kin) * dw


# -- inertia ---------------------------------------------------------------------------------
#: ``friction_pendulum``'s payload mass at strength 1, x the friction level / a99 [kg per
#: N s^2/m]; the slider's friction, its acceleration x the top acceleration [-]; the dish's
#: pendulum period, x the motion's time scale [-]
FP_MASS, FP_FRICTION, FP_PERIOD = 0.5, 0.3, 2.0


@njit(cache=True)
def _pendulum_slider(t, a, omega, mu_g):
    """The acceleration [m/s^2] of a payload on a friction pendulum bearing (a slider in a
    spherical dish of radius g / omega^2) whose base accelerates by ``a`` [m/s^2] at the
    times ``t`` [s] (uniform), from rest in the dish's middle: stuck while the base's
    acceleration and the dish's pull |a + omega^2 u| stay within the slider's friction
    ``mu_g`` [m/s^2], else sliding, u'' = -a - omega^2 u - ``mu_g`` sign(u'); semi-implicit
    Euler on sub-steps of at most 0.02 / omega, sticking where the slide's speed changes
    sign and the friction can hold it."""
    n = t.size
    out = np.empty(n)
    dt = t[1] - t[0] if n > 1 else 0.0
    n_sub = max(1, int(math.ceil(omega * dt / 0.02)))
    h = dt / n_sub
    u = 0.0
    w = 0.0
    for k in range(n):
        drive = a[k] + omega * omega * u
        if w == 0.0 and abs(drive) <= mu_g:
            out[k] = a[k]
        else:
            sg = math.copysign(1.0, w) if w != 0.0 else -math.copysign(1.0, drive)
            out[k] = -omega * omega * u - mu_g * sg
        if k + 1 < n:
            am = 0.5 * (a[k] + a[k + 1])
            for _ in range(n_sub):
                drive = am + omega * omega * u
                if w == 0.0:
                    if abs(drive) <= mu_g:
                        continue
                    w = -h * (drive - math.copysign(mu_g, drive))
                else:
                    wn = w - h * (drive + math.copysign(mu_g, w))
                    if wn * w <= 0.0:
                        wn = 0.0
                    w = wn
                u = u + h * w
    return out


@on_fine_grid
def friction_pendulum_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A payload stands on the carriage on a friction pendulum bearing (a seismic isolator
    of a sensitive instrument or a cabinet: an articulated slider in a spherical
    stainless dish, lined with PTFE), which the inverse dynamics misses. It rides with the
    carriage while its inertial force and the dish's gravity pull stay within the slider's
    friction (:data:`FP_FRICTION` x the top acceleration); beyond, it slides in the dish,
    pulled back by gravity on its curvature (a pendulum of :data:`FP_PERIOD` x the motion's
    time scale) and held back by the slider's friction, and sticks again where its slide
    stops (:func:`_pendulum_slider`). It pushes on the carriage with its own acceleration:
    the truth adds its mass (``s`` :data:`FP_MASS` x the friction level / a99) times that
    acceleration to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the payload's mass, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The friction pendulum system and sliding isolators (Zayas, Low and Mahin 1990, A
    simple pendulum technique for achieving seismic isolation, Earthquake Spectra 6;
    Mokha, Constantinou and Reinhorn 1990, Teflon bearings in base isolation, J. Struct.
    Eng. 116; Naeim and Kelly 1999, Design of Seismic Isolated Structures, ch. on sliding
    systems). The candidate misses a constant mass; the open forms filter it, reflect it
    through gearing, a chain, a pinion or a screw, hang it on a spring, a cable, a fluid,
    a clutch, a coupling, a flyweight, a friction-damped, quasi-zero-stiffness, hose's or
    elastomer mount, surge a spring, add a fluid's mass, pick, drop, empty, slide, rattle,
    telescope, roll or rock it, recoil a frame, saturate a motor, lead a feedforward,
    pitch a scale, radiate waves or swing it on a rod. Here a slider in a dish holds it
    by friction and returns it by gravity: stuck, then a pendulum that sticks again.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    m = float(s) * FP_MASS * _level(kin) / a99
    omega = 2.0 * math.pi / (FP_PERIOD * max(_motion_time(kin), 1e-12))
    acc = _pendulum_slider(np.asarray(kin.t, float), np.asarray(kin.a, float), omega,
                           FP_FRICTION * a99)
    return F + m * acc


# -- delay -----------------------------------------------------------------------------------
#: ``fixed_point_filter``'s time constant at strength 1 [data samples]; its arithmetic's
#: count (one least significant bit), x the force's range [-]
FIX_SAMPLES, FIX_COUNT = 2.0, 2.0 ** -12


@njit(cache=True)
def _integer_lowpass(u, gain, count):
    """The output [N] of a first-order recursive filter y += ``count`` floor(``gain`` (u -
    y) / ``count``) of the input ``u`` [N] in integer arithmetic (an arithmetic right
    shift floors), from the first input rounded to a count: it lags and, where the
    change per step is under a count, stops (at most ``count`` / ``gain`` below a rising
    input, a count above a falling one)."""
    n = u.size
    y = np.empty(n)
    yy = count * math.floor(u[0] / count) if n > 0 else 0.0
    for k in range(n):
        y[k] = yy
        if k + 1 < n:
            yy = yy + count * math.floor(gain * (u[k + 1] - yy) / count)
    return y


@on_fine_grid
def fixed_point_filter_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is smoothed by the load cell's microcontroller with a first-order
    recursive filter in integer arithmetic (an exponential moving average computed with
    a shift, as in many indicators and embedded data loggers), updated at the converter's
    rate (the fine grid's): y += floor(k (u - y)) in counts (:func:`_integer_lowpass`; k
    sets the time constant, ``s`` :data:`FIX_SAMPLES` data samples, one count
    :data:`FIX_COUNT` x the force's range). The reading lags the force, and the floor of
    each update leaves it short of a slowly rising force by up to a count over k (a
    dead band of the rounding, many counts wide) and a count above a falling one. The
    motion channels are on time.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the filter's time constant, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Quantisation in recursive digital filters: the rounding's dead band and limit cycles
    (Jackson 1970, An analysis of limit cycles due to multiplication rounding in recursive
    digital (sub)filters, Proc. 7th Allerton Conf.; Oppenheim and Schafer 2010,
    Discrete-Time Signal Processing, ch. on the effects of finite register length). The
    candidate shifts the force in time or lags it through a first-order filter; the open
    forms delay, filter, average, stamp, decimate, hold, skew, jitter, limit the slew,
    pipe, take medians, report on a dead band, sample positions, run a belt, aerate, drop
    telegrams, leak, creep, notch, track, snub, time a waveguide's pulse, diffuse eddy
    currents, count a resonator, sweep a grating, restore a force by a servo, interleave
    converters, balance a pneumatic cell, count out a dual slope or adapt a filter's time
    constant. Here the filter's own arithmetic rounds: a lag with a dead band that
    grows with it.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    tau = float(s) * FIX_SAMPLES * kin.sample_dt
    gain = -math.expm1(-float(t[1] - t[0]) / tau)
    count = FIX_COUNT * max(float(np.ptp(F)), 1e-12)
    return _integer_lowpass(np.asarray(F, float), gain, count)


# -- drift -----------------------------------------------------------------------------------
#: ``lining_glazing``'s fall of the levels with the lining glazed, at strength 1 [-]; the
#: friction work that glazes it by 1 - 1/e, x the record's [-]
GLAZE_DROP, GLAZE_WORK = 0.3, 0.5


def _glaze(work, scale):
    """The glazed share of the lining [-] after the friction ``work`` [-] (cumulative,
    over the record's), each unit of work glazing the share 1 / ``scale`` of what is not
    yet glazed: 1 - exp(-work / ``scale``)."""
    return -np.expm1(-np.asarray(work, float) / scale)


@on_fine_grid
def lining_glazing_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The contact's pads are a resin-bonded friction lining (a brake or clutch lining, a
    phenolic or composite way liner). Its surface glazes as it dissipates friction work:
    the heat brings the binder to the surface, where it carbonises into a smooth, hard
    glaze that carries a lower friction. The glazed share grows with the work dissipated
    so far, as 1 - exp(-W / W_g) (:func:`_glaze`; W_g :data:`GLAZE_WORK` x the record's
    friction work, the base's |friction x speed| integrated): it does not change in dwells
    and changes fastest where the friction power is largest. The Coulomb and Stribeck
    levels are the base's times 1 - ``s`` :data:`GLAZE_DROP` x the glazed share, inside
    the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the glaze's fall of the friction, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Glazing of friction linings and its dependence on the energy dissipated (Eriksson,
    Bergman and Jacobson 2002, On the nature of tribological contact in automotive brakes,
    Wear 252; Chan and Stachowiak 2004, Review of automotive brake friction materials,
    Proc. IMechE D 218; Limpert 2011, Brake Design and Safety, ch. on lining fade). The
    candidate is a trend, a saturating change, a step, a cycle, a resetting change or the
    friction power's heat; the open forms warm up, wear in, change, heat, wear, follow the
    humidity, grind, relubricate, relax, oxidise, deplete, wear through, swell, build
    films, take in particles, expand, shear down, heat magnets, charge, creep, loosen,
    dewet, channel, drain, spall, evaporate, pump down, settle an additive, crystallise
    wax, bleed a grease's oil or cycle a thermostat. Here the lining's surface changes
    with the work it has dissipated, for good: a glaze, not a temperature.
    """
    F, Ff = _base_parts(kin)
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    p = np.abs(np.asarray(Ff, float) * np.asarray(kin.v, float))
    work = np.concatenate(([0.0], np.cumsum(0.5 * (p[1:] + p[:-1]) * np.diff(t))))
    work = work / max(float(work[-1]), 1e-300)
    lev = np.maximum(1.0 - float(s) * GLAZE_DROP * _glaze(work, GLAZE_WORK), 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: ``detent_ball``'s play at strength 1, as a share of the stroke (its full width) [-]; the
#: detent's hold at strength 1 (at most 0.9), x the Coulomb level [-]; the notch's half-width, x the play's half-width
#: [-]; the rounding of its bottom, x the notch's half-width [-]
DET_CLEAR, DET_HOLD, DET_NOTCH, DET_ROUND = 0.005, 0.8, 0.3, 0.1


@njit(cache=True)
def _detent_force(e, hold, notch, rnd):
    """The detent's force [N] on the contact at the drive's offset ``e`` [m] from the
    play's middle: a spring-loaded ball on the flanks of a V-notch of half-width ``notch``
    [m] pulls the contact towards the drive with ``hold`` [N] (rounded over ``rnd`` x the
    notch at its bottom, and at its edges as exp(-(e / notch)^4)); out of the notch,
    nothing."""
    q = e / notch
    return hold * math.tanh(q / rnd) * math.exp(-q ** 4)


@njit(cache=True)
def _detent_contact(h, xd, half, hold, notch, rnd, kh, ch, m, s0, s1, s2, Fc, Fs, vs,
                    alpha, shape):
    """LuGre friction [N] of a light contact of mass ``m`` [kg] driven by the drive positions
    ``xd`` [m] (steps ``h`` [s]) through a play of half-width ``half`` [m] closed at the
    flanks by a spring ``kh`` [N/m] and damper ``ch`` [N s/m] (compressive only) with the
    detent of :func:`_detent_force` in its middle; from rest, the drive in the play's
    middle. Semi-implicit Euler of the contact, its bristle exact."""
    nn = xd.size
    F = np.empty(nn)
    x = xd[0]
    v = 0.0
    z = 0.0
    for j in range(nn):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        e = xd[j] - x
        ed = vd - v
        fc = _detent_force(e, hold, notch, rnd)
        if e > half:
            f2 = kh * (e - half) + ch * ed
            if f2 > 0.0:
                fc += f2
        elif e < -half:
            f2 = kh * (e + half) + ch * ed
            if f2 < 0.0:
                fc += f2
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha,
                                         shape)
        x = x + h * v
    return F


@on_fine_grid
def detent_ball_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact are joined through a play of ``s``^2 :data:`DET_CLEAR` x the
    stroke with a ball detent in its middle (an indexing or a safety detent: a
    spring-loaded ball in the drive's pin, a V-notch in the contact's link). Crossing the
    play after a reversal, the drive's ball drops into the notch and climbs out of it: while
    it is on the notch's flanks it pulls the contact towards the drive with the detent's
    hold (``s`` :data:`DET_HOLD` x the Coulomb level, at most 0.9 of it: less than the
    friction, so the contact does not follow; :func:`_detent_force`, the notch :data:`DET_NOTCH` x the half-play
    wide), out of it nothing bridges the play until the flank takes the drive up
    (:func:`_detent_contact`). The contact is light (its inertial force at the top
    acceleration 1 % of the Coulomb level) with the base's LuGre friction.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the square root of the play's width (as the open plays') and
        the detent's hold, / their values at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Ball detents and their holding force on a V-notch (Oberg, Jones, Horton and Ryffel
    2016, Machinery's Handbook, ch. on detents and torque limiters; Slocum 1992, Precision
    Machine Design, ch. on kinematic couplings and detents) and lost motion in mechanisms
    (Nordin and Gutman 2002, Controlling mechanical systems with backlash - a survey,
    Automatica 38). The candidate holds or frees the contact across a rigid play; the open
    forms take it up rigidly, compliantly, by impact, against a spring, eccentrically,
    through oil, worn, with a dragging idler, biased, slack, magnetic, preloaded, through a
    flexspline, a rope, a spider, a fluid link, a cable, a clutch, a varying mesh, a
    polymer gear, grease, a wedge, an overlapped spool, a side loaded pin, a toggle
    spring, graded pins, an adhesive flank, packed powder, a floating part between two
    plays or trapped air. Here a notch in the play's middle pulls the contact as the drive
    passes it: a tug at mid-play, none beyond.
    """
    p = _lugre_params(kin, "backlash (detent_ball)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    half = 0.5 * float(s) ** 2 * DET_CLEAR * float(np.ptp(kin.x))
    m, kh, ch = _contact_constants(kin, p)
    rate = max(math.sqrt(kh / m), (float(p.sigma1) + float(p.sigma2) + ch) / m)
    h, xd, n_sub = _substeps(kin, rate)
    hold = min(float(s) * DET_HOLD, 0.9) * float(p.Fc)
    Fr = _detent_contact(h, xd, half, hold, DET_NOTCH * half, DET_ROUND,
                         kh, ch, m, float(p.sigma0), float(p.sigma1), float(p.sigma2),
                         float(p.Fc), float(p.Fs), float(p.vs), float(p.alpha),
                         SHAPES[p.shape])
    return Fr[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: ``hysteresis_brake``'s share of the friction the brake carries, at strength 1 (at most
#: 0.95) [-]; its reversal's path beyond the base bristle's Fs / sigma0, at strength 1, x
#: the stroke / 3 [-]
BRAKE_SHARE, BRAKE_PATH = 0.4, 0.1


@njit(cache=True)
def _rayleigh_loop(x, path):
    """The brake's magnetisation [-] (+-1 saturated) along the positions ``x`` [m], from
    the demagnetised state: after each reversal (at m_r, moving d = +-1) it follows a
    Rayleigh parabola, m = m_r + d (1 - d m_r) (1 - (1 - D / D_s)^2), D the travel since
    the reversal, saturating at D_s = ``path`` (1 - d m_r) [m]: the same initial slope 2 /
    ``path`` on every branch, 2 ``path`` from one saturation to the other."""
    n = x.size
    out = np.empty(n)
    m = 0.0
    mr = 0.0
    xr = x[0] if n > 0 else 0.0
    d = 0.0
    for k in range(n):
        if k > 0:
            dx = x[k] - x[k - 1]
            if dx != 0.0:
                sg = 1.0 if dx > 0.0 else -1.0
                if sg != d:
                    xr = x[k - 1]
                    mr = m
                    d = sg
                ds = path * (1.0 - d * mr)
                if ds > 0.0:
                    q = min(d * (x[k] - xr) / ds, 1.0)
                    m = mr + d * (1.0 - d * mr) * (1.0 - (1.0 - q) ** 2)
        out[k] = m
    return out


@on_fine_grid
def hysteresis_brake_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Part of the contact's friction is a magnetic hysteresis brake (a semi-hard magnetic
    strip or rotor dragged past a pole structure, as in hysteresis brakes, tensioners and
    dynamometers): its force is the hysteresis loss per unit of travel, independent of the
    speed, and after a reversal the strip's magnetisation turns over along the material's
    Rayleigh branches, a parabola of the travel with the same initial slope on every
    branch, over a path (the base bristle's Fs / sigma0 plus ``s`` :data:`BRAKE_PATH` x the
    stroke / 3; :func:`_rayleigh_loop`). The brake carries the share w = ``s``
    :data:`BRAKE_SHARE` of the Coulomb level, w Fc m; the contact the rest, the base's
    LuGre with its curve less w Fc (its viscous term whole). Sliding, the sum is the
    base's; after a reversal the brake's force turns over along the parabola, rate
    independent. At ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the brake's share of the friction (up to ``s`` = 0.95 /
        :data:`BRAKE_SHARE`) and its reversal's path (as the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Hysteresis brakes and couplings (Nagrial 1979, Design of hysteresis machines, IEE Proc.
    126; Bertotti 1998, Hysteresis in Magnetism, ch. on the Rayleigh law; Jiles 2015,
    Introduction to Magnetism and Magnetic Materials, ch. on hysteresis and the Rayleigh
    region). The candidate's presliding is a generalized Maxwell-slip (GMS) element set;
    the open forms are Maxwell-slip sets, Dahl, elasto-plastic, Bliman-Sorine, Bouc-Wen,
    Zener junctions, Mindlin contacts, rate-and-state, Tomlinson asperities, bond rupture,
    gouge, kinematic hardening, interlocking, capillary bridges, cyclic hardening,
    peeling, unloading microslip, a power-law joint, junction growth, avalanches, slip
    weakening, a microslip bar, contact renewal, grease's yield, a superelastic flexure,
    an Eyring film, a viscoplastic layer, a poroelastic one or a confined film that melts,
    each beside the contact, or a stiffening wire mesh in series with it. Here no contact
    makes the hysteresis: a magnet's domains turn over beside it.
    """
    _lugre_params(kin, "gms (hysteresis_brake)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    law = kin.base
    w = min(float(s) * BRAKE_SHARE, 0.95)
    wf = w * _level(kin)
    e0, extra = _presliding_path(kin, s, BRAKE_PATH)
    m = _rayleigh_loop(np.asarray(kin.x, float), e0 + extra)
    rest = lugre_with_curve(kin, lambda vv: law.g(vv) - wf)
    return rest + wf * m
