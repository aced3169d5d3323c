"""The twenty-second seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-30 (session 26) by another hand, once, without running the diagnosis on it;
run once, sealed, at the start of session 27 on the code of 72892bf:
176 cases, 0 skipped, 645 s wall on 2 workers. Top-1 48.9 % (86;
51.2 % of the 168 detectable; the other 8: 6 delays below a sample, 2 Stribeck-shape cases an
oracle cannot tell from the base); mean |shrink error| 0.305; wrong names on 15 (8.5 %):
position -> asymmetry 4, gms -> delay 3, backlash -> gms 2, acceleration -> position 2,
acceleration -> drift 2, asymmetry -> backlash 1, drift -> load 1. By form: load/ball_spin
19/20, inertia/rolling_payload 15/20, acceleration/inertia_valve_damper 14/20,
drift/spall_growth 14/20, delay/quartz_counter 11/20, gms/grease_yield 5/12,
position/crank_transmission 4/16, asymmetry/elliptic_vibration 2/20, backlash/side_loaded_pin
2/12, stribeck_shape/wiping_meniscus 0/16. By plant: valve 67.5 %, isolator 50.0 %, damping
rig 42.5 %, XML-350 42.5 %, press 39.3 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen21` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen21`,
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
acceleration       ``inertia_valve_damper``: a damper on the carriage whose bypass is
                   closed by an inertia valve (a spring-centred poppet that moves once
                   the acceleration, either way, passes its springs' preload): the
                   damper's drag, saturated by its blow-off valve, acts only while the
                   poppet is deflected, and the poppet follows the acceleration with its
                   own second-order dynamics
load               ``ball_spin``: the rolling elements of the guide run in angular
                   contact and spin (pivot) in their contact ellipses: the spin moment
                   ~ mu Q a, a ~ Q^(1/3), and the spin-to-roll ratio grows as the contact
                   angle opens with the load: a drag growing faster than the load
asymmetry          ``elliptic_vibration``: the way vibrates in an ellipse (an unbalance
                   drive beside it, a vibratory feeder's trough): below the way's
                   vibration speed the friction turns within each cycle, and with the
                   normal force's phase lead the mean friction is lower one way than the
                   other and pushes the carriage at rest (vibratory conveying); above
                   it, none
stribeck_shape     ``wiping_meniscus``: a wiper lip drawn over the wetted way drags a
                   liquid meniscus whose film thickness and dissipation follow the
                   capillary number (Landau-Levich-Derjaguin, Bretherton): a drag ~
                   |v|^(2/3), steep at low speed and bending over above it
position           ``crank_transmission``: the carriage is driven by a slider-crank; the
                   crank bearings' dry friction torque reaches the carriage through the
                   crank's transmission ratio, which falls towards the dead centres: a
                   friction that rises towards both ends of the stroke, unevenly (the
                   connecting rod's obliquity)
inertia            ``rolling_payload``: a cylindrical payload rests in a cradle on the
                   carriage and rolls in it without slipping: the whole mass at low
                   frequencies, a third of it (the rolling constraint) above the
                   cradle's rocking frequency, with the rocking mode between
delay              ``quartz_counter``: the force is read by a quartz resonator whose
                   frequency grows as the square root of 1 + F / F_b, counted over a gate
                   time and converted back at the gate's end: the reading is the force
                   whose frequency is the mean over the gate (a lag of half the gate, and
                   the conversion's curvature)
drift              ``spall_growth``: rolling-contact fatigue: a spall in a raceway grows
                   with each overrolling at a rate that grows with its size (Paris-law
                   growth), and the levels rise with the damaged area: a drift counted in
                   overrollings that accelerates, not one that saturates
backlash           ``side_loaded_pin``: drive and contact are joined by a pin in a
                   clearance hole under a transverse load (its weight): after a reversal
                   the pin rolls round its hole, the axial force it carries W tan(theta)
                   growing without bound as it reaches the far side: a take-up of the
                   play whose stiffness grows continuously up to the flank
gms                ``grease_yield``: presliding of a grease layer, an elasto-viscoplastic
                   material (Saramito): an elastic gel below its yield stress, which
                   neither creeps nor relaxes, and a Herschel-Bulkley flow above it: the
                   force after a reversal unloads elastically to the other yield, then
                   grows with the speed as a power below one; at ``s`` = 0 the base
                   itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``wiping_meniscus`` needs a
Stribeck curve (not the isolator's mre_lugre), ``crank_transmission`` a record that revisits
its positions (not the press), ``ball_spin`` a load that changes, ``side_loaded_pin`` and
``grease_yield`` a classic LuGre base (valve, damping rig, XML-350); each raises a
``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.shapes import SHAPES

from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _level,
                     _light_contact_step, _lugre_params, _motion_time, _presliding_path,
                     _substeps, has_stribeck_curve, level_inside, on_fine_grid)

__all__ = ["FORMS", "inertia_valve_damper_truth", "ball_spin_truth", "elliptic_vibration_truth",
           "wiping_meniscus_truth", "crank_transmission_truth", "rolling_payload_truth",
           "quartz_counter_truth", "spall_growth_truth", "side_loaded_pin_truth",
           "grease_yield_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "inertia_valve_damper", "load": "ball_spin",
         "asymmetry": "elliptic_vibration", "stribeck_shape": "wiping_meniscus",
         "position": "crank_transmission", "inertia": "rolling_payload",
         "delay": "quartz_counter", "drift": "spall_growth",
         "backlash": "side_loaded_pin", "gms": "grease_yield"}


# -- acceleration ----------------------------------------------------------------------------
#: ``inertia_valve_damper``'s damper drag with the bypass shut, x the friction level, at
#: strength 1 [-]; the poppet springs' preload, x the top acceleration [-]; the poppet's
#: natural period, x the motion's time scale [-], and its damping ratio [-]; the speed the
#: blow-off valve opens at, x the top speed [-]
IV_DRAG, IV_PRELOAD, IV_PERIOD, IV_DAMPING, IV_BLOWOFF = 0.8, 0.35, 0.08, 0.7, 0.1


@njit(cache=True)
def _poppet(a, h, preload, w, zeta):
    """The deflection y of a spring-centred poppet along the carriage's accelerations
    ``a`` [m/s^2] (steps ``h`` [s]), returned as w^2 y [m/s^2] (its static value is the
    acceleration beyond the preload): its inertial load is the acceleration beyond the
    springs' ``preload`` [m/s^2] (a dead zone), its natural frequency ``w`` [rad/s], its
    damping ratio ``zeta``. Semi-implicit Euler on sub-steps of at most 0.05 / ``w``
    (the acceleration interpolated), from rest."""
    n = a.size
    out = np.empty(n)
    m = max(1, int(math.ceil(w * h / 0.05)))
    hs = h / m
    y = 0.0
    yd = 0.0
    out[0] = 0.0
    for k in range(1, n):
        for i in range(m):
            u = a[k - 1] + (a[k] - a[k - 1]) * (i + 1.0) / m
            d = u - preload if u > preload else (u + preload if u < -preload else 0.0)
            ydd = d - w * w * y - 2.0 * zeta * w * yd
            yd += hs * ydd
            y += hs * yd
        out[k] = w * w * y
    return out


@on_fine_grid
def inertia_valve_damper_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A hydraulic damper rides between the carriage and the frame, its oil normally free
    to pass a bypass. The bypass is closed by an inertia valve: a poppet centred by two
    preloaded springs that moves, either way, once the inertial force of the carriage's
    acceleration passes the springs' preload (:data:`IV_PRELOAD` x the top acceleration),
    with its own natural period (:data:`IV_PERIOD` x the motion's time scale) and damping
    (:func:`_poppet`). The poppet's deflection shuts the bypass in proportion (fully at the
    top acceleration), and the damper's drag, saturated above :data:`IV_BLOWOFF` x the top
    speed by its blow-off valve, is ``s`` :data:`IV_DRAG` x the friction level x that
    closure x tanh(v / v_blow-off), added to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the damper's blow-off force, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Inertia-valve (acceleration-sensitive) dampers (Fox 2003, Inertia valve shock absorber,
    US patent 6,581,948; Dixon 2007, The Shock Absorber Handbook, ch. 8 on
    acceleration-sensitive valving and blow-off valves). The candidate raises the levels
    with |a|, lagged, tilts them with a and adds a force odd in a; the open forms lag, age,
    heat, skid, load, press, attract, squeeze, transfer weight, slosh, dilate, wedge,
    spring a gib, soften rubber, swing arms, unload by the jerk, tilt pads, push ball
    trains, ripple the current, slide rack flanks or set a shoe by a ball in a cone. Here
    a viscous-then-saturated drag of the speed is switched by a resonant valve of the
    acceleration.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    v99 = max(kin.scales["v99"], 1e-12)
    w = 2.0 * math.pi / (IV_PERIOD * max(_motion_time(kin), 1e-12))
    a = np.ascontiguousarray(kin.a, dtype=float)
    y = _poppet(a, float(kin.dt), IV_PRELOAD * a99, w, IV_DAMPING)
    shut = np.minimum(np.abs(y) / ((1.0 - IV_PRELOAD) * a99), 1.0)
    drag = np.tanh(np.asarray(kin.v, float) / (IV_BLOWOFF * v99))
    return F + float(s) * IV_DRAG * _level(kin) * shut * drag


# -- load ------------------------------------------------------------------------------------
#: ``ball_spin``'s rise of the levels at the record's top load, at strength 1 [-]; the
#: contact angle unloaded and its opening at the top load [deg]
SPIN_SHARE, SPIN_ANGLE, SPIN_OPENING = 0.5, 15.0, 25.0


def _spin_drag(load, top):
    """The balls' spin drag at the loads ``load`` [N] over its value at the load ``top``
    [N] [-]: the spin moment mu Q a (3/8) E(k), a ~ Q^(1/3) (Hertz), times the spin-to-roll
    ratio ~ sin(alpha), the contact angle alpha opening from :data:`SPIN_ANGLE` by
    :data:`SPIN_OPENING` x (Q / Q_top)^(2/3) (the contact's approach)."""
    q = np.abs(np.asarray(load, float)) / top
    alpha = np.radians(SPIN_ANGLE + SPIN_OPENING * q ** (2.0 / 3.0))
    return q ** (4.0 / 3.0) * np.sin(alpha) / math.sin(math.radians(SPIN_ANGLE + SPIN_OPENING))


@on_fine_grid
def ball_spin_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The guide's balls run in angular contact with their raceways and, besides rolling,
    spin (pivot) about the normal of each contact. The spin's micro-slip across the
    contact ellipse dissipates a moment ~ mu Q a, the ellipse's half-width a ~ Q^(1/3)
    (Hertz), and the spin-to-roll ratio grows with the contact angle, which opens as the
    load presses the balls into their grooves (:func:`_spin_drag`). The Coulomb and
    Stribeck levels are the base's times 1 + ``s`` :data:`SPIN_SHARE` x that drag over
    its value at the record's top load (its 99th percentile), inside the bristle dynamics;
    the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (load [N]) and its base law.
    s : float
        Amplitude factor [-]: the spin's friction coefficient times the balls' share of the
        contact, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Spin (pivoting) friction of balls in angular contact (Jones 1959, Ball motion and
    sliding friction in ball bearings, J. Basic Eng. 81; Harris and Kotzalas 2007, Rolling
    Bearing Analysis, ch. on ball spin and the spinning moment). The candidate makes the
    levels affine in the load, with a memory over the travel; the open forms scale the
    friction with a Hertz contact's area, a seal's, a film's, a junction's, a pivot's, an
    adhesive contact's or a pin's arc, break, squeeze or desorb films, plough, creep, vibrate,
    overload a pad, heal scuffs, relieve a preload, roll on a lossy track or slip
    differentially in conforming grooves. Here the contact twists: a drag ~ Q^(4/3),
    steepened by the opening contact angle.
    """
    L = np.asarray(kin.load, float)
    Lm = float(np.mean(np.abs(L))) or 1.0
    if not np.ptp(L) > 1e-9 * Lm:
        raise ValueError(f"load (ball_spin): the {kin.plant} record's load does not change")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    top = max(float(np.percentile(np.abs(L), 99)), 1e-12 * Lm)
    lev = 1.0 + float(s) * SPIN_SHARE * _spin_drag(L, top)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``elliptic_vibration``'s tangential vibration speed at strength 1, x the top speed [-];
#: the normal force's swing at strength 1, x its mean [-], and its largest (below 1: the
#: carriage never lifts off); the normal motion's phase lead on the tangential [deg]; the
#: speed the base's direction is rounded over, x the top speed [-]
VIB_SPEED, VIB_SWING, VIB_MAX_SWING, VIB_LEAD, VIB_ROUND = 0.03, 0.1, 0.95, 60.0, 2e-3


def _vibrated_friction(u, swing, lead, n_phase=720):
    """The mean dry friction [-] (1: the plain contact's, sliding +x) of a contact whose
    way vibrates in an ellipse, at the sliding speeds ``u`` [-] over the way's tangential
    speed amplitude: the way's tangential speed cos(phi), the normal force 1 + ``swing``
    sin(phi + ``lead``) [deg] (the normal motion's acceleration), the friction mu N
    sign(u - cos(phi)) averaged over the phase phi (a table of ``n_phase`` phases); +-1
    where |u| > 1."""
    phi = (np.arange(n_phase) + 0.5) * (2.0 * math.pi / n_phase)
    N = np.maximum(1.0 + swing * np.sin(phi + math.radians(lead)), 0.0)
    N = N / N.mean()
    grid = np.linspace(-1.0, 1.0, 2001)
    table = np.mean(N * np.sign(grid[:, None] - np.cos(phi)), axis=1)
    u = np.asarray(u, float)
    return np.where(np.abs(u) >= 1.0, np.sign(u), np.interp(u, grid, table))


@on_fine_grid
def elliptic_vibration_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The way the carriage slides on vibrates, driven by an unbalance motor or a vibratory drive
    beside it (a vibratory feeder's trough, a shaker's table), in an ellipse: tangentially
    at the speed amplitude V = ``s`` :data:`VIB_SPEED` x the top speed, and normally, the
    normal motion's acceleration swinging the contact force by ``s`` :data:`VIB_SWING` of
    its mean (at most :data:`VIB_MAX_SWING`: no lift-off) with a phase lead of
    :data:`VIB_LEAD` degrees on the tangential speed. While the carriage slides slower than
    V the contact's friction turns within each cycle and its mean is the mean of mu N sign(v -
    V cos(phi)) (:func:`_vibrated_friction`): the way drives the carriage one way (the
    feeder's conveying), so the mean friction is lower, and even reversed, sliding one way
    than the other, and it pushes the carriage at rest. The truth replaces the base's
    direction, tanh(v / :data:`VIB_ROUND` x the top speed), of the friction level by that
    mean, added to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the vibration's amplitude (its tangential speed and its
        normal acceleration), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Vibratory conveying by an elliptical (two-axis, phase-shifted) vibration of the track
    (Redford and Boothroyd 1967, Vibratory feeding, Proc. Inst. Mech. Eng. 182; Boothroyd
    2005, Assembly Automation and Product Design, ch. 3) and friction under tangential
    and normal vibration of the contact (Wallaschek 1998, Contact mechanics of
    piezoelectric ultrasonic motors, Smart Mater. Struct. 7; Littmann, Storck and
    Wallaschek 2001, Sliding friction in the presence of ultrasonic oscillations, Arch.
    Appl. Mech. 71). The candidate frees the levels (and the Stribeck velocity and viscous
    term) of each direction and an offset; the open forms twin levels, curves or viscous
    terms, roll lips, load thrust bearings, pump films, ratchet, spring back, tilt pads,
    strut, throttle, differ in areas, pump along grooves, buckle, scrape chips, commutate,
    tension idlers, free-wheel, wick felts, run belts, lean brushes, pull sealing bands or
    hold by a counterbalance valve. Here the asymmetry lives at low speed only: below the
    way's vibration speed, where the normal force's phase makes one direction slide
    easier, and none above it.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v = np.asarray(kin.v, float)
    v99 = max(kin.scales["v99"], 1e-12)
    V = float(s) * VIB_SPEED * v99
    swing = min(float(s) * VIB_SWING, VIB_MAX_SWING)
    mean = _vibrated_friction(v / V, swing, VIB_LEAD)
    return F + _level(kin) * (mean - np.tanh(v / (VIB_ROUND * v99)))


# -- stribeck_shape --------------------------------------------------------------------------
#: ``wiping_meniscus``'s drag at the top speed, x the friction level, at strength 1 [-]; the
#: speed below which the meniscus' drag is viscous, x the top speed [-]
MENISCUS_DRAG, MENISCUS_ROUND = 0.5, 1e-3


def _meniscus_drag(u, eps):
    """The wiping meniscus' drag [-] (1 at u = 1) at the speeds ``u`` [-] (over the top
    speed): sign(u) |u|^(2/3) (the capillary number's 2/3 power), viscous below ``eps``:
    sign(u) ((u^2 + eps^2)^(1/3) - eps^(2/3)) / ((1 + eps^2)^(1/3) - eps^(2/3))."""
    u = np.asarray(u, float)
    e23 = eps ** (2.0 / 3.0)
    return np.sign(u) * ((u * u + eps * eps) ** (1.0 / 3.0) - e23) \
        / ((1.0 + eps * eps) ** (1.0 / 3.0) - e23)


@on_fine_grid
def wiping_meniscus_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A wiper lip (a way wiper, a scraper seal) is drawn over the way, which is wetted by
    the lubricant or coolant. The liquid's meniscus at the lip is deformed by the motion:
    the film it leaves behind thickens as Ca^(2/3) (the capillary number Ca = eta v /
    gamma; Landau-Levich-Derjaguin) and the meniscus' dissipation, like Bretherton's
    pressure drop, grows as Ca^(2/3): a drag steep at low speed that bends over above it
    (:func:`_meniscus_drag`, viscous below :data:`MENISCUS_ROUND` x the top speed). The
    truth adds ``s`` :data:`MENISCUS_DRAG` x the friction level x that drag to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (with a Stribeck curve).
    s : float
        Amplitude factor [-]: the lip's wetted length times the surface tension, / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Dip coating and the drag-out film (Landau and Levich 1942, Dragging of a liquid by a
    moving plate, Acta Physicochim. URSS 17; Derjaguin 1943) and the motion of long
    bubbles and menisci (Bretherton 1961, The motion of long bubbles in tubes, J. Fluid
    Mech. 10: the pressure drop ~ Ca^(2/3)); wiper lips and wetted seals (Persson 2006,
    Sliding Friction, on wiper blades). The candidate reshapes the Stribeck curve; the open
    forms add a tail, a rational drop, a hydrodynamic rise, a spike, a lift-off, two
    roughness scales, a logarithmic or Eyring law, starve a film, add rubber hysteresis,
    resonate, dither, melt, flow grains, readsorb, heat the film, make it turbulent,
    thixotropic, churned or shear-thinning, add core losses, breathe a bellows, brake by
    eddy currents or fly a pad. Here a power law of the speed below one: a capillary drag.
    """
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (wiping_meniscus): the mre_lugre base has no "
                         "Stribeck curve")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    d = _meniscus_drag(np.asarray(kin.v, float) / v99, MENISCUS_ROUND)
    return F + float(s) * MENISCUS_DRAG * _level(kin) * d


# -- position --------------------------------------------------------------------------------
#: ``crank_transmission``'s friction at mid-stroke, x the friction level, at strength 1 [-];
#: the crank's radius, x the larger reach of the visited stroke from its centre [-]; the
#: crank's radius over the connecting rod's length [-]; the speed the friction turns over,
#: x the top speed [-]
CRANK_TORQUE, CRANK_REACH, CRANK_RATIO, CRANK_ROUND = 0.4, 1.25, 0.3, 2e-3


def _crank_lever(x, r, lam):
    """The slider's travel per crank angle over the crank radius, |dx / dtheta| / r [-], at
    the slider positions ``x`` [m] (from the centre of the crank's stroke) of a
    slider-crank of radius ``r`` [m] and ratio ``lam`` = r / l: the slider at r cos(theta)
    + l sqrt(1 - lam^2 sin^2 theta), theta in (0, pi) found on a fine table, travels
    sin(theta) (1 + lam cos(theta) / sqrt(1 - lam^2 sin^2 theta)) per unit angle and
    radius."""
    th = np.linspace(1e-4, math.pi - 1e-4, 20001)
    root = np.sqrt(1.0 - lam * lam * np.sin(th) ** 2)
    pos = r * (np.cos(th) + root / lam)
    pos = pos - 0.5 * (pos[0] + pos[-1])          # the stroke's centre at 0
    lever = np.sin(th) * (1.0 + lam * np.cos(th) / root)
    # pos falls with theta: interpolate on the reversed table
    return np.interp(np.asarray(x, float), pos[::-1], lever[::-1])


@on_fine_grid
def crank_transmission_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage is driven by a slider-crank (a crank and connecting rod), its
    stroke's centre where fit and held-out parts both pass, its radius
    :data:`CRANK_REACH` x the larger reach of the visited stroke from there (the dead
    centres lie outside the visited stroke) and its rod :data:`CRANK_RATIO` times longer.
    The crank's bearings carry a dry friction torque; at the carriage it is that torque
    over the slider's travel per crank angle, r sin(theta) (1 + lambda cos(theta) /
    sqrt(1 - lambda^2 sin^2 theta)) (:func:`_crank_lever`): least near mid-stroke, rising
    towards both dead centres and unevenly (the rod's obliquity). The truth adds ``s``
    :data:`CRANK_TORQUE` x the friction level x the lever at mid-stroke over the lever
    here, against the velocity, to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the crank bearings' friction torque, / its value at strength
        1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Slider-crank kinematics and the friction circle of its joints (Shigley and Uicker 1980,
    Theory of Machines and Mechanisms, ch. 3 and 13; Ham, Crane and Rogers 1958, Mechanics
    of Machinery, on friction in mechanisms and the transmission angle). The candidate
    scales the friction along the stroke and adds a force of the position; the open forms
    put a defect, a waviness, a worn section, runout, a bent rail, a transfer film,
    cogging, a taper, a pocket, a cushion, a cover, an air spring, bolt holes, a plunger, a
    sag, a festoon, a curve, a chain, a cam, a heated zone, brinelled dents, a rail joint,
    misaligned rails or a spool's flow force on the stroke. Here the drive's own geometry:
    a friction referred through a ratio that changes along the stroke.
    """
    x0 = _bump_centre(kin)
    if x0 is None:
        raise ValueError(f"position (crank_transmission): the held-out part of the "
                         f"{kin.plant} record never revisits the positions of its fit part")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    reach = max(sc["x_hi"] - x0, x0 - sc["x_lo"], 1e-12)
    r = CRANK_REACH * reach
    lever = _crank_lever(np.asarray(kin.x, float) - x0, r, CRANK_RATIO)
    mid = float(_crank_lever(np.array([0.0]), r, CRANK_RATIO)[0])
    v99 = max(sc["v99"], 1e-12)
    turn = np.tanh(np.asarray(kin.v, float) / (CRANK_ROUND * v99))
    return F + float(s) * CRANK_TORQUE * _level(kin) * (mid / np.maximum(lever, 1e-3)) * turn


# -- inertia ---------------------------------------------------------------------------------
#: ``rolling_payload``'s mass at strength 1, x the friction level / a99 [kg per N s^2/m]; the
#: cradle's rocking period, x the motion's time scale [-]; the rocking's damping ratio
#: (rolling resistance) [-]
ROLL_MASS, ROLL_PERIOD, ROLL_DAMPING = 0.4, 1.0, 0.15


@njit(cache=True)
def _rolling_force(a, h, w, zeta):
    """The force [N per kg] a solid cylinder rolling without slip in a cradle exerts on the
    carriage under the accelerations ``a`` [m/s^2] (steps ``h`` [s]): its position u in the
    cradle, (3/2) u'' = -(3/2) w^2 u - a - 3 zeta w u' (the rolling constraint's 3/2, the
    cradle's restoring and the rolling resistance), and the force a + u''. Semi-implicit
    Euler on sub-steps of at most 0.05 / ``w`` (the acceleration interpolated), from
    rest."""
    n = a.size
    out = np.empty(n)
    m = max(1, int(math.ceil(w * h / 0.05)))
    hs = h / m
    u = 0.0
    ud = 0.0
    out[0] = a[0] - (2.0 / 3.0) * a[0]
    for k in range(1, n):
        for i in range(m):
            ak = a[k - 1] + (a[k] - a[k - 1]) * (i + 1.0) / m
            udd = -w * w * u - (2.0 / 3.0) * ak - 2.0 * zeta * w * ud
            ud += hs * udd
            u += hs * ud
        out[k] = a[k] + udd
    return out


@on_fine_grid
def rolling_payload_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A cylindrical payload (a roll of material, a drum) rests in a cradle on the carriage
    and rolls in it without slipping. The inverse dynamics misses it. Slowly accelerated
    it rocks to where the cradle's slope balances its inertial force and moves with the
    carriage: its whole mass; accelerated faster than the cradle's rocking frequency
    (period :data:`ROLL_PERIOD` x the motion's time scale), it rolls back on the cradle and
    the carriage carries only the force that spins it up, a third of its mass (the solid
    cylinder's I / (I + m r^2)); the rocking mode, damped by the rolling resistance
    (:data:`ROLL_DAMPING`), lies between (:func:`_rolling_force`). The truth adds ``s``
    :data:`ROLL_MASS` x the friction level / a99 x that force per unit mass to the base.

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
    Rolling without slipping on an accelerated support and the rolling constraint's
    effective mass (Routh 1905, Dynamics of a System of Rigid Bodies, on a cylinder rolling
    inside a cylinder; the ball- and cylinder-in-a-bowl rolling pendulum of rolling
    isolators: Zayas, Low and Mahin 1990, A simple pendulum technique for achieving seismic
    isolation, Earthquake Spectra 6). The candidate misses a constant mass; the open forms
    filter it, reflect it through gearing, a chain's polygon or a pinion, hang it on a
    spring, a cable, a fluid, a clutch, a coupling, a flyweight, a screw, a friction-damped
    mount or a surging spring, add a fluid's mass and its history, pick it up, drop it,
    empty it, slide it, rattle it, telescope it, recoil the frame, saturate the motor,
    lead it by the feedforward or pitch the scale head. Here the missed mass rolls: whole
    below the rocking frequency, a third above.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    w = 2.0 * math.pi / (ROLL_PERIOD * max(_motion_time(kin), 1e-12))
    f = _rolling_force(np.ascontiguousarray(kin.a, dtype=float), float(kin.dt), w,
                       ROLL_DAMPING)
    return F + float(s) * ROLL_MASS * _level(kin) / a99 * f


# -- delay -----------------------------------------------------------------------------------
#: ``quartz_counter``'s gate time at strength 1 [data samples]; the resonator's force scale
#: F_b, x the largest |force| of the record [-]
QUARTZ_SAMPLES, QUARTZ_SCALE = 4.0, 2.0


def _gate_mean(t, u, gate):
    """The mean [-] of ``u`` over the gate [t - ``gate``, t] at each of the times ``t`` [s]
    (the record's start bounds the first gates), from the trapezoidal running integral."""
    c = np.concatenate(([0.0], np.cumsum(0.5 * (u[1:] + u[:-1]) * np.diff(t))))
    start = np.maximum(t - gate, t[0])
    span = t - start
    out = u.copy()
    ok = span > 0.0
    out[ok] = (c[ok] - np.interp(start[ok], t, c)) / span[ok]
    return out


@on_fine_grid
def quartz_counter_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is read by a quartz resonator force sensor (a double-ended tuning fork in
    tension or compression): its frequency is f0 sqrt(1 + F / F_b) (F_b
    :data:`QUARTZ_SCALE` x the record's largest |force|). A counter counts its cycles over
    a gate of ``s`` :data:`QUARTZ_SAMPLES` data samples, which gives the mean frequency over
    the gate, and the reading, reported at the gate's end, is the force of that frequency:
    F_b ((mean f / f0)^2 - 1) (:func:`_gate_mean`): a lag of about half the gate, and the
    square root's curvature averaged in. The motion channels are on time.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the gate time, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Quartz resonator force and pressure sensors read by frequency counting (EerNisse, Ward
    and Wiggins 1988, Survey of quartz bulk resonator sensor technologies, IEEE Trans. UFFC
    35; Albert 1982, Vibrating quartz crystal beam accelerometer, ISA; the gated and
    reciprocal counters of Hewlett-Packard Application Note 200, Fundamentals of electronic
    frequency counters). The candidate shifts the force by a constant time, low-passes it,
    reads it through a transducer's resonance and leaks it; the open forms sample, filter,
    average, hold, skew, jitter, rate-limit, transmit, median, report by deadband, trigger
    on positions, run a belt, aerate, drop telegrams, leak, creep, notch, track, snub, time
    a waveguide's pulse or diffuse eddy currents. Here the force is counted as a frequency:
    averaged over a gate as the square root of itself and reported at the gate's end.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    fb = QUARTZ_SCALE * max(float(np.max(np.abs(F))), 1e-12)
    f = np.sqrt(1.0 + F / fb)
    m = _gate_mean(t, f, float(s) * QUARTZ_SAMPLES * kin.sample_dt)
    return fb * (m * m - 1.0)


# -- drift -----------------------------------------------------------------------------------
#: ``spall_growth``'s rise of the levels at the record's end, at strength 1 [-]; the spall's
#: area at the record's end over its area at the start [-]
SPALL_RISE, SPALL_GROWTH = 0.5, 6.0


def _spall_area(n, growth):
    """The spall's area over its initial area [-] after the share ``n`` [-] (0 to 1) of the
    record's overrollings, growing as dA / dN = C A^2 (a Paris-law growth whose rate goes
    as the square of the spall's size): 1 / (1 - k n), k = 1 - 1 / ``growth`` (``growth``
    at n = 1)."""
    k = 1.0 - 1.0 / growth
    return 1.0 / (1.0 - k * np.asarray(n, float))


@on_fine_grid
def spall_growth_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Rolling-contact fatigue: a spall (a pit) in a raceway of the guide grows with each
    overrolling, the cracks at its trailing edge advancing at a rate that grows with its
    size: dA / dN = C A^2 (:func:`_spall_area`; :data:`SPALL_GROWTH` times its initial
    area by the record's end). The overrollings are counted by the travel (each ball
    passes the spall once per ball spacing), so the damage grows with the travel, not the
    time, and faster and faster. The Coulomb and Stribeck levels are the base's times 1 +
    ``s`` :data:`SPALL_RISE` x (A / A0 - 1) / (``SPALL_GROWTH`` - 1), inside the bristle
    dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the friction added per unit damaged area, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Fatigue crack growth (Paris and Erdogan 1963, A critical analysis of crack propagation
    laws, J. Basic Eng. 85) and the propagation of spalls in rolling bearings (Hoeprich
    1992, Rolling element bearing fatigue damage propagation, J. Tribol. 114; Rosado,
    Forster, Thompson and Cooke 2010, Rolling contact fatigue life and spall propagation of
    AISI M50, M50NiL and AISI 52100, Tribol. Trans. 53). The candidate is a trend, a
    saturating change, a step, a cycle, a resetting change or the friction power's heat;
    the open forms warm up, wear in, change the lubricant, heat, wear, follow the humidity,
    grind a third body, relubricate, relax a seal, oxidise, deplete, wear through, swell,
    build a tribofilm, take in particles, expand, shear down, heat magnets, charge, creep a
    cage, loosen a screw, dewet a film, channel grease or drain a receiver. Here the change
    accelerates with the travel: slow at first, ever faster.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    speed = np.abs(np.asarray(kin.v, float))
    path = np.concatenate(([0.0], np.cumsum(0.5 * (speed[1:] + speed[:-1]) * np.diff(t))))
    n = path / (path[-1] or 1.0)
    lev = 1.0 + float(s) * SPALL_RISE * (_spall_area(n, SPALL_GROWTH) - 1.0) \
        / (SPALL_GROWTH - 1.0)
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: ``side_loaded_pin``'s clearance at strength 1, as a share of the stroke (its full width,
#: both sides) [-]; the pin's transverse load, x the Coulomb level [-]; the angle short of
#: the far side at which the pin meets its flank, as a share of the clearance [-]
PIN_CLEAR, PIN_WEIGHT, PIN_EDGE = 0.008, 0.2, 0.02


@njit(cache=True)
def _pin_contact(h, xd, half, w, edge, m, kh, ch, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a light contact of mass ``m`` [kg] driven by the drive
    positions ``xd`` [m] (steps ``h`` [s]) through a pin in a hole of radial clearance
    ``half`` [m] under the transverse load ``w`` [N]: at an axial offset e the pin has
    rolled round its hole to sin(theta) = e / ``half`` and carries w tan(theta) = w e /
    sqrt(half^2 - e^2) (the root at least ``edge`` x half); past the clearance the flank,
    a spring ``kh`` [N/m] and damper ``ch`` [N s/m], compressive only."""
    n = xd.size
    F = np.empty(n)
    x = xd[0]
    v = 0.0
    z = 0.0
    floor = (edge * half) ** 2
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        e = xd[j] - x
        ed = vd - v
        ec = min(max(e, -half), half)
        fc = w * ec / math.sqrt(max(half * half - ec * ec, floor))
        if e > half:
            f2 = kh * (e - half) + ch * ed
            if f2 > 0.0:
                fc += f2
        elif e < -half:
            f2 = kh * (-e - half) - ch * ed
            if f2 > 0.0:
                fc -= f2
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha,
                                         shape)
        x = x + h * v
    return F


@on_fine_grid
def side_loaded_pin_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact are joined by a pin in a clearance hole (a clevis, a link's
    pivot) that also carries a transverse load, its weight (:data:`PIN_WEIGHT` x the
    Coulomb level), which sets it at the bottom of its hole. An axial force F rolls the
    pin round the hole to the angle theta with tan(theta) = F / W, its axial offset
    half x sin(theta): after a reversal the drive crosses the clearance (radius ``s``^2
    :data:`PIN_CLEAR` / 2 x the stroke) while the force it passes on, W e / sqrt(half^2 -
    e^2), grows without bound as the pin reaches the far side (:func:`_pin_contact`; the
    flank met :data:`PIN_EDGE` short of it): the contact is taken up by a coupling whose
    stiffness grows continuously, held still until the pin has rolled far enough to pass
    its break-away force. The contact is light (its inertial force at the top acceleration
    1 % of the Coulomb level) with the base's LuGre friction.

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
    Clearance joints whose journal moves round its bearing under a steady side load
    (Flores and Ambrosio 2004, Revolute joints with clearance in multibody systems,
    Computers and Structures 82; Dubowsky and Freudenstein 1971, Dynamic analysis of
    mechanical systems with clearances, J. Eng. Ind. 93). The candidate holds or frees the
    contact across a rigid play; the open forms take it up rigidly, compliantly, by impact,
    against a spring, eccentrically, through oil, worn, with a dragging idler, biased,
    slack, magnetic, preloaded, through a flexspline, a rope, a spider, a fluid link, a
    cable, a clutch, a varying mesh, a polymer gear, grease, a wedge or an overlapped
    spool. Here the play's take-up is a rolling pin's: geometric, its stiffness set by the
    side load and growing to the flank.
    """
    p = _lugre_params(kin, "backlash (side_loaded_pin)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    half = 0.5 * float(s) ** 2 * PIN_CLEAR * float(np.ptp(kin.x))
    w = PIN_WEIGHT * float(p.Fc)
    m, kh, ch = _contact_constants(kin, p)
    k_pin = w / (PIN_EDGE ** 3 * max(half, 1e-15))
    rate = max(math.sqrt(max(kh, k_pin) / m), (float(p.sigma1) + float(p.sigma2) + ch) / m)
    h, xd, n_sub = _substeps(kin, rate)
    Fr = _pin_contact(h, xd, half, w, PIN_EDGE, m, kh, ch, float(p.sigma0), float(p.sigma1),
                      float(p.sigma2), float(p.Fc), float(p.Fs), float(p.vs),
                      float(p.alpha), SHAPES[p.shape])
    return Fr[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: the grease layer's elastic path to its yield at strength 1, beyond the base bristle's
#: path, as a share of the stroke / 3 [-]; its share of the friction at strength 1 [-]; its
#: yield stress, x its stress sliding at the top speed [-]; its flow index n [-]
EVP_PATH, EVP_SHARE, EVP_YIELD, EVP_INDEX = 0.1, 0.6, 0.7, 0.5


@njit(cache=True)
def _grease_layer(t, v, path, v_top, yield_, index):
    """The grease layer's stress u [-] (1 when sliding steadily at ``v_top`` [m/s]) along
    the times ``t`` [s] and velocities ``v`` [m/s] (Saramito's elasto-viscoplastic
    solid): du/dt = (v - v_p) / ``path`` (an elastic gel of path ``path`` [m] to the
    stress 1), the plastic rate v_p = 0 below the yield stress ``yield_`` [-] and, above
    it, v_top ((|u| - yield) / (1 - yield))^(1 / ``index``) sign(u) (Herschel-Bulkley
    flow); implicit Euler, Newton on each step (bisection-safe); starts unstressed."""
    n = t.size
    out = np.zeros(n)
    u = 0.0
    k = 1.0 / index
    for j in range(1, n):
        h = t[j] - t[j - 1]
        c = h / path
        # the new stress solves x - u - c (v - vp(x)) = 0, increasing in x: bisection
        lo = min(u + c * v[j], u) - 2.0
        hi = max(u + c * v[j], u) + 2.0
        for _ in range(200):
            x = 0.5 * (lo + hi)
            ex = abs(x) - yield_
            vp = 0.0
            if ex > 0.0:
                vp = v_top * (ex / (1.0 - yield_)) ** k
                if x < 0.0:
                    vp = -vp
            g = x - u - c * (v[j] - vp)
            if g > 0.0:
                hi = x
            else:
                lo = x
            if hi - lo < 1e-12:
                break
        u = 0.5 * (lo + hi)
        out[j] = u
    return out


@on_fine_grid
def grease_yield_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Part of the friction is carried by a grease layer in the contact, an elasto-viscoplastic
    material: below its yield stress it is an elastic gel (its path to the yield, the base
    bristle's Fs / sigma0 plus ``s`` :data:`EVP_PATH` x the stroke / 3, over
    :data:`EVP_YIELD`), and below it neither creeps nor relaxes; above it flows, its plastic
    shear rate a Herschel-Bulkley power (:data:`EVP_INDEX`) of the stress beyond the yield
    (:func:`_grease_layer`). After a reversal the layer unloads elastically through zero to
    the yield on the other side, then flows; sliding, its stress rises from the yield with
    the speed as (v / v99)^n; at rest the stress above the yield flows off, down to the
    yield, and what is below it is held (no creep). Its share w = ``s`` :data:`EVP_SHARE`
    (up to ``s`` = 1) of the friction is its stress times the Stribeck level, the viscous
    term the base's: F = (1 - w) F_lugre + w (g(v) u + sigma2 v). At ``s`` = 0 the base
    itself.

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
    Elasto-viscoplastic fluids (Saramito 2007, A new constitutive equation for
    elastoviscoplastic fluid flows, J. Non-Newtonian Fluid Mech. 145; Herschel and Bulkley
    1926, Konsistenzmessungen von Gummi-Benzolloesungen, Kolloid-Z. 39) and the yield and
    flow of lubricating greases (Lugt 2013, Grease Lubrication in Rolling Bearings, ch. 4
    on grease rheology). The candidate's presliding is a generalized Maxwell-slip (GMS)
    element set; the open forms are Maxwell-slip sets, Dahl, elasto-plastic,
    Bliman-Sorine, Bouc-Wen, Zener junctions, Mindlin contacts, rate-and-state, Tomlinson
    asperities, bond rupture, gouge, kinematic hardening, interlocking, capillary bridges,
    cyclic hardening, peeling, unloading microslip, a power-law joint, junction growth,
    avalanches, slip weakening, a microslip bar and contact renewal. Here the presliding
    is a gel's: elastic below a yield that never creeps, and a power-law flow above it.
    """
    p = _lugre_params(kin, "gms (grease_yield)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, EVP_PATH)
    w = EVP_SHARE * min(float(s), 1.0)
    v = np.ascontiguousarray(kin.v, dtype=float)
    v99 = max(kin.scales["v99"], 1e-12)
    u = _grease_layer(np.ascontiguousarray(kin.t, dtype=float), v,
                      (e0 + extra) / EVP_YIELD, v99, EVP_YIELD, EVP_INDEX)
    return (1.0 - w) * F + w * (kin.base.g(v) * u + float(p.sigma2) * v)
