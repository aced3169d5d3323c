"""The ninth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-29 (session 14) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 15's work on the code of ef5b06a: 176 cases, top-1
33.0 % (58; 33.3 % of the detectable), mean |shrink error| 0.386, wrong names on 36 (20.5 %).
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen8` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen8`,
:mod:`diagnosis.effects_backlash`, :mod:`diagnosis.effects_gms`) and than the candidate's
formula (:mod:`diagnosis.candidates`), taken from the friction literature or from real
machines, integrated along the plant's continuous motion on the grid :data:`.kinematics.FINE`
x finer than the data (:func:`.truths.on_fine_grid`); level changes act inside the bristle
dynamics of a LuGre base (:func:`.truths.level_inside`). ``s`` scales each effect's
amplitude monotonically from the base law at ``s`` = 0 (its calibration,
:func:`.cases._calibrate`, sets the requested size).

=================  =====================================================================
effect             form
=================  =====================================================================
acceleration       ``weight_transfer``: the acceleration's pitching moment moves normal
                   load from the front support to the rear one (longitudinal load
                   transfer, Gillespie 1992), and the two have different friction
                   coefficients (a hybrid guideway: a rolling block and a sliding pad):
                   the levels rise with the signed acceleration along the axis,
                   whichever way the carriage moves, until a support lifts off
load               ``squeeze_cavitation``: the lubricant film between the surfaces
                   resists being squeezed (Reynolds' squeeze term) but cavitates when
                   they separate (the half-Sommerfeld film): the asperities take a
                   rising load only as the film is squeezed out, a falling one they
                   give up at once: the levels follow the load down at once and up
                   with a lag in time
asymmetry          ``meter_out_throttle``: a cylinder's speed set by a one-way flow
                   control valve (a throttle with a check valve, meter-out): moving
                   out, the exhaust passes the orifice and its back-pressure (~ v^2,
                   Merritt 1967) resists; moving in, the check valve bypasses it: a
                   quadratic drag in one direction only
stribeck_shape     ``dither_averaging``: a tangential dither (a valve's PWM or dither
                   signal, an ultrasonic vibration) far faster than the motion: the
                   contact's friction is its Stribeck curve averaged over the dither
                   cycle (Littmann, Storck and Wallaschek 2001): below the dither's
                   velocity amplitude the curve falls to nothing at rest, as
                   (2 / pi) arcsin(v / v_d) for a Coulomb level: no stiction
position           ``air_spring``: a closed chamber of a cylinder (a trapped-air
                   counterbalance) compressed polytropically by the stroke (p V^n =
                   const): its gas force, added whatever the direction of motion,
                   hardens hyperbolically towards the stroke's upper end, and the
                   pressure-energised piston seal's friction rises with it
inertia            ``pick_and_place``: a gripper picks a part near the lower end of the
                   stroke and places it near the upper end (a handling axis): the
                   part's mass is missed only while it is carried, and picking it,
                   the carriage brings it up to its own speed (a variable-mass system,
                   Meshchersky): legs with and without the payload
delay              ``deadband_reporting``: the force is reported send-on-delta (an
                   event-based sensor's attribute reporting, Miskowicz 2006): a new value
                   when it differs from the last reported one by the reportable change,
                   or after the maximum reporting interval; the logger holds it: a
                   delay that grows as the force changes more slowly, the opposite of a
                   slew limit
drift              ``coating_wear_through``: a bonded solid-lubricant coating (MoS2,
                   PTFE) wears with the sliding distance and wears through in spots
                   whose share follows its endurance life's Weibull distribution: the
                   levels stay, then rise along an S-curve of the travel towards the
                   bare substrate's
backlash           ``magnetic_coupling``: drive and contact joined by a magnetic
                   coupling (a magnetically coupled rodless cylinder, a magnetic
                   feedthrough): no play, but a pull F_max sin(2 pi u / p) of their
                   offset u that softens towards its peak: the contact waits after a
                   reversal until the coupling has turned over to the other side
gms                ``gouge_fabric``: a granular third body (wear debris) between the
                   surfaces carries part of the friction: its force chains align with
                   the shear; after a reversal they collapse and the layer is weak
                   until a new fabric has formed over a path of shear (Oda 1972;
                   Toiya, Stambaugh and Losert 2004): an S-shaped presliding curve,
                   soft at first; at ``s`` = 0 the base itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``dither_averaging``
needs a Stribeck curve (not the isolator's mre_lugre), ``air_spring`` a record that revisits
its positions (not the press), ``squeeze_cavitation`` a load that changes,
``magnetic_coupling`` and ``gouge_fabric`` a classic LuGre base (valve, damping rig,
XML-350); each raises a ``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.lugre import bristle_update
from friction.shapes import SHAPES, stribeck_g

from ..effects_backlash import PLANT_GAP_SHARE
from .kinematics import PlantKinematics
from .seen7 import _strength
from .truths import (_base_parts, _bump_centre, _contact_constants, _lag, _level,
                     _lugre_params, _motion_time, _presliding_path, _span, level_inside,
                     on_fine_grid)

__all__ = ["FORMS", "weight_transfer_truth", "squeeze_cavitation_truth",
           "meter_out_throttle_truth", "dither_averaging_truth", "air_spring_truth",
           "pick_and_place_truth", "deadband_reporting_truth", "coating_wear_through_truth",
           "magnetic_coupling_truth", "gouge_fabric_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "weight_transfer", "load": "squeeze_cavitation",
         "asymmetry": "meter_out_throttle", "stribeck_shape": "dither_averaging",
         "position": "air_spring", "inertia": "pick_and_place",
         "delay": "deadband_reporting", "drift": "coating_wear_through",
         "backlash": "magnetic_coupling", "gms": "gouge_fabric"}


# -- acceleration ---------------------------------------------------------------------------
#: ``weight_transfer``'s contrast of the supports' friction coefficients, (mu_pad -
#: mu_roll) / (mu_pad + mu_roll) [-] (0.6: the pad's four times the rolling block's); the
#: acceleration at which, at strength 1, the unloaded support lifts off, x a99 [-]
PAD_CONTRAST, LIFT_OFF = 0.6, 2.0


@on_fine_grid
def weight_transfer_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Longitudinal load transfer between two supports of unequal friction: the carriage's
    centre of mass lies above its drive line, so the inertial force of an acceleration a
    pitches it and moves normal load dN = m a h / L from the front support to the rear one
    (rigid body, quasi-static; each carries N / 2 at rest), dN / (N / 2) = ``s`` a /
    (:data:`LIFT_OFF` a99), until one of them lifts off (|dN| = N / 2; beyond it the
    transfer stays). The rear support is a sliding pad, the front a rolling block (a hybrid
    guideway), so the friction changes by (mu_pad - mu_roll) dN: the Coulomb and Stribeck
    levels are the base's times 1 + :data:`PAD_CONTRAST` clip(``s`` a / (:data:`LIFT_OFF`
    a99), -1, 1), inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the transfer's lever h / L (the centre of mass' height over
        the drive line, over the supports' spacing) relative to its value at strength 1,
        where the front support lifts off at :data:`LIFT_OFF` a99.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Longitudinal load transfer under acceleration (dN = m a h / L, the braking car's:
    Gillespie 1992, Fundamentals of Vehicle Dynamics); hybrid guideways combining rolling
    and sliding (hydrodynamic or polymer-lined) elements (Weck and Brecher 2006,
    Werkzeugmaschinen 2). The candidate adds a force odd in a (fading with |v|) and raises
    the levels with |a|; the open forms lag the velocity or a state, heat the contact,
    skid rolling elements, move load between ball rows, press a seal with a lagged |a|,
    pull the carriage with the thrust or relieve it by a squeeze film: each raises the
    friction by |a|, by accelerating against braking or by the thrust. Here the levels
    follow the signed acceleration along the axis: up when a > 0 and down when a < 0,
    whichever way the carriage moves (so up while braking a backward motion), between
    the pad's and the rolling block's levels.
    """
    a = np.asarray(kin.a, float) / (LIFT_OFF * max(kin.scales["a99"], 1e-12))
    lev = 1.0 + PAD_CONTRAST * np.clip(max(float(s), 0.0) * a, -1.0, 1.0)
    return level_inside(kin, lev, np.ones_like(lev))


# -- load -------------------------------------------------------------------------------------
#: the squeeze film's time constant (linearised about the mean load), x the record [-];
#: the levels' slope in the asperities' load, relative to the mean load, at strength 1 [-]
SQUEEZE_TIME, SQUEEZE_SLOPE = 0.1, 0.6


@njit(cache=True)
def _squeezed_load(t, L, tau):
    """The load [N] the asperities carry under the loads ``L`` [N] at the times ``t`` [s]
    through a cavitating squeeze film: a rise of the load reaches them as the film is
    squeezed out, a first-order lag of time constant ``tau`` [s] (exact for a load held
    over each step); a fall at once (the film cannot pull). Starts at the first load."""
    n = L.size
    a = np.empty(n)
    c = L[0]
    a[0] = c
    for k in range(1, n):
        if L[k] > c:
            c = L[k] + (c - L[k]) * math.exp(-(t[k] - t[k - 1]) / tau)
        else:
            c = L[k]
        a[k] = c
    return a


@on_fine_grid
def squeeze_cavitation_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A lubricated contact whose film resists being squeezed but not being pulled apart:
    when the load L rises, the film between the surfaces carries the increase by its
    squeeze pressure and hands it to the asperities only as it is squeezed out (a
    first-order lag of :data:`SQUEEZE_TIME` x the record, the squeeze time linearised about
    the mean load); when it falls, the film cavitates and the asperities give up the load
    at once (:func:`_squeezed_load`). The Coulomb and Stribeck levels are the base's times
    1 + ``s`` :data:`SQUEEZE_SLOPE` (L_a - mean L) / mean |L|, L_a the asperities' load
    (floored at 0.05), inside the bristle dynamics; the viscous term (the film's shear) is
    the base's. ValueError if the load does not change.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], load [N]) and its base law.
    s : float
        Amplitude factor [-]: the levels' slope in the asperities' relative load, /
        :data:`SQUEEZE_SLOPE`.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Reynolds 1886 (the squeeze term: a closing film carries load ~ eta dh/dt / h^3);
    squeeze films cavitate on separation and carry no tension (the half-Sommerfeld or
    pi-film condition of squeeze-film dampers: San Andres 1996; Hamrock, Schmid and
    Jacobson 2004); load sharing between film and asperities (Johnson, Greenwood and Poon
    1972). The candidate and the open forms are laws of the load (affine, a power, one
    direction, the Stribeck velocity, a step, a hinge), of its rate, of a creep towards it
    in log time, of a play, or a memory of its largest value erased by the travel (up at
    once, down slowly); here the load reaches the friction late while it rises and at once
    while it falls, by the clock.
    """
    L = np.ascontiguousarray(kin.load, dtype=float)
    L0 = max(float(np.mean(np.abs(L))), 1e-12)
    # a change below 1e-6 of the mean load over the record is round-off, not a change
    if float(np.ptp(L)) <= 1e-6 * L0:
        raise ValueError(f"load (squeeze_cavitation): the {kin.plant} record's load does "
                         f"not change")
    t = np.ascontiguousarray(kin.t, dtype=float)
    La = _squeezed_load(t, L, SQUEEZE_TIME * (float(t[-1] - t[0]) or 1.0))
    lev = np.clip(1.0 + s * SQUEEZE_SLOPE * (La - float(np.mean(L))) / L0, 0.05, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``meter_out_throttle``'s drag at v99 at strength 1, x the friction level [-]
THROTTLE_FORCE = 0.5


@on_fine_grid
def meter_out_throttle_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A cylinder's speed set by a one-way flow control valve in its exhaust (meter-out):
    moving out (v > 0) the displaced oil or air leaves through the valve's orifice, whose
    pressure drop grows as the flow squared, Delta p ~ (A v / (C_d A_o))^2, and acts on the
    piston against the motion; moving in (v < 0) the valve's check bypasses the orifice.
    The measured force is the base's plus ``s`` :data:`THROTTLE_FORCE` x the friction level
    x (v / v99)^2 where v > 0 (the check's opening rounded over 2 % of v99).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the throttle's drag at v99 relative to
        :data:`THROTTLE_FORCE` x the level (the orifice's area to the power -2).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Orifice flow, Q = C_d A_o sqrt(2 Delta p / rho) (Merritt 1967, Hydraulic Control
    Systems); meter-out speed control with one-way flow control (throttle check) valves
    (Beater 2007, Pneumatic Drives). The candidate shifts a direction's levels and viscous
    slope (and an offset); the open forms keep a direction's share at all speeds, move its
    Stribeck velocity, viscous slope or low-speed tail, follow a lip, a thrust, a film, a
    texture fading with the speed, a spring, a lifting wedge film or a self-energising
    strut; here a drag grows as the square of the speed in one direction and is absent in
    the other: nothing at low speed, most at the top speed.
    """
    v99 = max(kin.scales["v99"], 1e-12)
    v = np.asarray(kin.v, float)
    out = 0.5 * (1.0 + np.tanh(v / (0.02 * v99)))
    F, _ = _base_parts(kin)
    return F + s * THROTTLE_FORCE * _level(kin) * out * (v / v99) ** 2


# -- stribeck_shape --------------------------------------------------------------------------
#: ``dither_averaging``'s dither velocity amplitude at strength 1, x v99 [-]; the phases
#: of its cycle averaged over [-]; the points of the averaged curve's table over |v| [-]
DITHER_SPEED, DITHER_PHASES, DITHER_TABLE = 0.0225, 256, 4097


def _dithered_curve(g, u, vd: float, phases: int = DITHER_PHASES) -> np.ndarray:
    """The Stribeck curve ``g`` (a callable of the velocity [m/s], even) averaged over a
    sinusoidal dither of velocity amplitude ``vd`` [m/s] at the speeds ``u`` >= 0 [m/s]:
    the mean over the cycle of g(w) sgn(w), w = u + vd sin(theta) [N] (the midpoint rule
    over ``phases`` evenly spaced phases)."""
    theta = 2.0 * np.pi * (np.arange(phases) + 0.5) / phases
    w = np.asarray(u, float)[:, None] + vd * np.sin(theta)[None, :]
    return np.mean(g(w) * np.sign(w), axis=1)


@on_fine_grid
def dither_averaging_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A tangential dither far faster than the motion (a proportional valve's dither or
    PWM, a piezo or ultrasonic vibration): the sliding velocity is v + v_d sin(omega t),
    v_d = ``s`` :data:`DITHER_SPEED` v99, and over each dither cycle the contact slides
    both ways while |v| < v_d; its mean friction is its Stribeck curve averaged over the
    cycle, g_d(v) = mean of g(w) sgn(w), w = v + v_d sin(theta) (:func:`_dithered_curve`,
    tabulated over |v|): for a Coulomb level, (2 / pi) arcsin(|v| / v_d) of it below v_d,
    all of it above. The Stribeck curve is the base's times g_d / g (floored at 0.05),
    inside the bristle dynamics; the viscous term, linear, averages to the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (a Stribeck curve).
    s : float
        Amplitude factor [-]: the dither's velocity amplitude, / (:data:`DITHER_SPEED`
        v99).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Littmann, Storck and Wallaschek 2001 (sliding friction in the presence of ultrasonic
    oscillations: the mean friction (2 / pi) arcsin(v / v_d) below the vibration's velocity
    amplitude); dither against stiction in hydraulic valves and servo drives
    (Armstrong-Helouvry, Dupont and Canudas de Wit 1994). The candidate bends the base's
    drop (an exponent, the Lorentzian, a log-speed map); the open forms add tails, drops,
    a spike, a lift-off, a second drop, a logarithmic weakening, an Eyring strengthening,
    a rise at the top speed, a hump of rubber hysteresis or a notch of a normal
    resonance; here the curve loses its stiction: it rises from nothing at rest, steeply
    (with the arcsine's infinite slope) up to the dither's velocity amplitude, where it
    rejoins the base's.
    """
    if kin.base.name == "mre_lugre":
        raise ValueError("stribeck_shape (dither_averaging): the mre_lugre base has no "
                         "Stribeck curve")
    v = np.asarray(kin.v, float)
    vd = max(float(s), 0.0) * DITHER_SPEED * max(kin.scales["v99"], 1e-12)
    if vd <= 0.0:
        return level_inside(kin, np.ones_like(v), np.ones_like(v))
    u = np.linspace(0.0, max(float(np.max(np.abs(v))), vd), DITHER_TABLE)
    gd = _dithered_curve(kin.base.g, u, vd)
    lev = np.clip(np.interp(np.abs(v), u, gd) / kin.base.g(v), 0.05, None)
    return level_inside(kin, lev, np.ones_like(v))


# -- position --------------------------------------------------------------------------------
#: ``air_spring``'s dead length of the chamber at the stroke's upper end, x the stroke
#: [-]; the polytropic exponent [-]; the gas force's rise over the stroke at strength 1,
#: x the friction level [-]; the seal's level rise over the stroke at strength 1 [-]
AIR_DEAD, AIR_POLYTROPE, AIR_FORCE, AIR_SEAL = 0.5, 1.2, 0.5, 0.2


@on_fine_grid
def air_spring_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A closed chamber of a cylinder (trapped air: a pneumatic counterbalance, a blocked
    port) compressed by the stroke: the gas column's length is l(x) = l_d + x_hi - x (l_d
    = :data:`AIR_DEAD` x the stroke the record visits, x_hi its upper end), the pressure
    polytropic, p / p_0 = (l(x_lo) / l(x))^n (n = :data:`AIR_POLYTROPE`, p_0 at the lower
    end). Its force (p - p_0) A resists the motion towards the upper end and pushes back
    away from it, whatever the direction of motion: the measured force is the base's plus
    ``s`` :data:`AIR_FORCE` x the friction level x r(x), r = (p - p_0) / (p_hi - p_0) (1 at
    the upper end); and the chamber's piston seal, pressure-energised, presses harder: the
    Coulomb and Stribeck levels are the base's times 1 + ``s`` :data:`AIR_SEAL` r(x), inside
    the bristle dynamics.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the chamber's precharge x area, relative to its value at
        strength 1 (the gas force and the seal's rise scale with it).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Polytropic compression of a trapped gas, p V^n = const (n between 1, isothermal, and
    1.4, adiabatic; Beater 2007, Pneumatic Drives); pressure-energised seals, whose contact
    force grows with the pressure they seal (Mueller and Nau 1998, Fluid Sealing
    Technology). The candidate scales the friction along the stroke (a map, a waviness, a
    defect) and adds a periodic force of x; the open forms are level maps (a defect,
    waviness, a worn section, runout, a bow, a transfer film, a taper, a port's wake), a
    periodic detent force, a cushion's drag in one zone and direction or a cover's
    staircase; here a conservative force of the position alone, the same in both
    directions, hardens hyperbolically towards one end, and the levels rise with it.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (air_spring): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    span = _span(kin)
    x = np.asarray(kin.x, float)
    x_lo, x_hi = kin.scales["x_lo"], kin.scales["x_hi"]
    dead = AIR_DEAD * span
    p = ((dead + x_hi - x_lo) / (dead + x_hi - x)) ** AIR_POLYTROPE
    r = (p - 1.0) / (((dead + x_hi - x_lo) / dead) ** AIR_POLYTROPE - 1.0)
    s = max(float(s), 0.0)
    lev = 1.0 + s * AIR_SEAL * r
    return level_inside(kin, lev, np.ones_like(lev)) + s * AIR_FORCE * _level(kin) * r


# -- inertia ---------------------------------------------------------------------------------
#: ``pick_and_place``'s pick and place zones: below this percentile of the positions and
#: above 100 - it [%]; the part's mass at strength 1, x the friction level / a99 [kg per
#: N s^2/m]; the gripper's closing (and opening) time, x the motion's time scale [-]
PICK_ZONE, PAYLOAD, GRIP_TIME = 10.0, 0.3, 0.05


@njit(cache=True)
def _carrying(x, x_pick, x_place):
    """Whether a part is carried [0 or 1] along the positions ``x`` [m]: picked where the
    carriage enters the pick zone (x <= ``x_pick`` [m]), placed where it enters the place
    zone (x >= ``x_place`` [m]), carried in between. Starts empty (picked at once if it
    starts in the pick zone)."""
    n = x.size
    out = np.empty(n)
    c = 0.0
    for k in range(n):
        if x[k] <= x_pick:
            c = 1.0
        elif x[k] >= x_place:
            c = 0.0
        out[k] = c
    return out


@on_fine_grid
def pick_and_place_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A handling axis: a gripper on the carriage picks a part (mass m = ``s``
    :data:`PAYLOAD` x the friction level / a99) where the carriage enters the pick zone (the
    lowest :data:`PICK_ZONE` % of the record's positions) and places it where it enters the
    place zone (the highest :data:`PICK_ZONE` %) (:func:`_carrying`); the gripper closes
    and opens over :data:`GRIP_TIME` x the motion's time scale (a first-order lag), so the
    carried mass is m c(t), c from 0 to 1. The inverse dynamics misses the part: the
    measured force is the base's plus d(m c v)/dt where the part is taken up, m c a +
    m max(dc/dt, 0) v (a part picked at rest is brought up to the carriage's speed; a
    placed part leaves at it and costs the carriage nothing). At ``s`` = 0 the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m], v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the part's mass relative to :data:`PAYLOAD` x level / a99.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Variable-mass systems: the force to take up mass at rest, v dm/dt, beside m a
    (Meshchersky 1897; Cveticanin 1998, Dynamics of Machines with Variable Mass);
    pick-and-place handling axes carrying a payload one way and returning empty, a mass
    the drive's model does not know (payload identification of robots: Swevers et al.
    2007). The candidate and the open forms are masses (constant, filtered, along the
    stroke, through a ratio or a lossy gear, in time, behind a spring, in a fluid), a
    payload held by friction, a part rattling in a pocket or a flywheel through a
    freewheel: each there, or there as a function of the motion, all the record; here the
    mass is there on the legs from one end of the stroke to the other and not on the way
    back, set by where the carriage last turned, and taking it up costs an impulse.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    x = np.ascontiguousarray(kin.x, dtype=float)
    t = np.asarray(kin.t, float)
    c = _carrying(x, float(np.percentile(x, PICK_ZONE)),
                  float(np.percentile(x, 100.0 - PICK_ZONE)))
    c = _lag(t, c, GRIP_TIME * _motion_time(kin))
    m = s * PAYLOAD * _level(kin) / max(kin.scales["a99"], 1e-12)
    pick = np.clip(np.gradient(c, t), 0.0, None)
    return F + m * (c * np.asarray(kin.a, float) + pick * np.asarray(kin.v, float))


# -- delay -----------------------------------------------------------------------------------
#: ``deadband_reporting``'s maximum reporting interval (its heartbeat) [data samples]
REPORT_INTERVAL = 64


@njit(cache=True)
def _send_on_delta(F, delta, most):
    """The values [N] a send-on-delta channel delivers from the signal ``F`` [N]: the first
    value, then each value that differs from the last delivered one by ``delta`` [N] or
    more, or that comes ``most`` points after it (a heartbeat; ``most`` >= 1), held in
    between."""
    n = F.size
    y = np.empty(n)
    c = F[0]
    last = 0
    for k in range(n):
        if abs(F[k] - c) >= delta or k - last >= most:
            c = F[k]
            last = k
        y[k] = c
    return y


@on_fine_grid
def deadband_reporting_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force reported send-on-delta: the transmitter (an event-based sensor reporting
    an attribute on its change, as Zigbee's attribute reporting or an OPC UA absolute
    deadband) checks the force continuously (on the fine grid) and sends a value when it
    differs from the last one sent by the reportable change Delta = ``s`` x R99 x the
    data's sample interval (R99 the 99th percentile of the base force's |dF/dt|), and at
    the latest :data:`REPORT_INTERVAL` data samples after it (the maximum reporting
    interval); the logger holds the last value received (:func:`_send_on_delta`). On a
    ramp of rate R the force comes Delta / (2 R) late on average: ``s`` / 2 samples at R99,
    the longer the slower it changes, up to the heartbeat; a slow drift is held up to Delta
    off until the heartbeat. At ``s`` = 0 the force itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the reportable change, in data samples of the force's
        99th-percentile rate (twice the mean delay at that rate [samples]).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Send-on-delta (level-crossing) reporting (Miskowicz 2006, Send-on-delta concept: an
    event-based data reporting strategy, Sensors 6); attribute reporting with a reportable
    change and a maximum reporting interval (Zigbee Cluster Library, Configure Reporting);
    the absolute deadband of OPC UA's data change filter (IEC 62541-4). The open forms
    delay by one amount (a shift, held samples), filter linearly (a lag, Bessel, a moving
    average, a converter's FIR, a line's echoes) or by rank (a running median), let the
    delay drift, wander or grow with the rate (a slew limit), or shift the motion; here the
    delay is set by the force's own change: short where it changes fast (the reversals),
    long where it creeps, and a steady force is held off by up to the deadband.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    rate = np.abs(np.diff(F)) / kin.dt
    delta = s * float(np.percentile(rate, 99)) * kin.sample_dt
    return _send_on_delta(np.ascontiguousarray(F, dtype=float), delta,
                          max(int(REPORT_INTERVAL * kin.step), 1))


# -- drift -----------------------------------------------------------------------------------
#: ``coating_wear_through``'s characteristic life (63 % of the coating worn through), x the
#: record's travel [-]; the Weibull modulus of its wear-through [-]; the levels' rise when
#: it is all worn through, at strength 1 [-]
COATING_LIFE, COATING_MODULUS, COATING_RISE = 0.6, 3.0, 0.4


@on_fine_grid
def coating_wear_through_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A bonded solid-lubricant coating (MoS2, PTFE) wearing through: it wears with the
    sliding distance D (the travel since the record's start) and fails in spots whose share
    follows its endurance life's Weibull distribution, q = 1 - exp(-(D /
    (:data:`COATING_LIFE` D_end))^:data:`COATING_MODULUS`) (D_end the record's travel);
    where it is worn through the bare substrate rubs. The Coulomb and Stribeck levels are
    the base's times 1 + ``s`` :data:`COATING_RISE` q, inside the bristle dynamics; the
    viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the levels' relative rise on the bare substrate, /
        :data:`COATING_RISE`.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Endurance (wear) life of bonded solid-lubricant films, which ends when the friction
    rises to the substrate's (ASTM D2981; Sliney 1982, Solid lubricant materials for high
    temperatures; Lancaster 1990); Weibull-distributed coating lives (Weibull 1951). The
    candidate is a trend, a saturating change and a step in time; the open forms warm up,
    wear in (in time, with the load and travel, falling), step, heat, cycle, rise and fall
    with debris, drop with grease shots, relax in log time, grow an oxide and spall or
    oxidise after an induction; here the levels stay, then rise along an S-curve of the
    sliding distance (not the clock) to a new plateau.
    """
    x = np.asarray(kin.x, float)
    D = np.concatenate(([0.0], np.cumsum(np.abs(np.diff(x)))))
    life = COATING_LIFE * max(float(D[-1]), 1e-300)
    q = -np.expm1(-(D / life) ** COATING_MODULUS)
    lev = 1.0 + max(float(s), 0.0) * COATING_RISE * q
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: the lost motion of ``magnetic_coupling`` at strength 1 (a reversal between the Coulomb
#: levels), as a share of the stroke [-] (the open backlash forms' play); the coupling's
#: peak pull, x the 99th percentile of the base's |friction| (at least its static level
#: Fs) [-]; its eddy-current damping ratio with the contact at small offsets [-]
GAP_SHARE, COUPLING_PULL, COUPLING_DAMPING = PLANT_GAP_SHARE, 1.5, 0.5


@njit(cache=True)
def _coupled_contact(h, xd, pitch, Fmax, c, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a contact of mass ``m`` [kg] pulled by the drive positions
    ``xd`` [m] (grid step ``h`` [s]) through a magnetic coupling of pole pitch ``pitch``
    [m]: its pull Fmax sin(2 pi u / pitch) of the offset u = drive - contact (``Fmax``
    [N]) and an eddy-current damping ``c`` [N s/m] on the offset's rate. Semi-implicit
    Euler of the mass, the bristle advanced exactly at the contact's velocity
    (:func:`friction.lugre.bristle_update`). Starts aligned, at rest, its bristle
    unloaded."""
    n = xd.size
    F = np.empty(n)
    x = xd[0]
    v = 0.0
    z = 0.0
    k = 2.0 * math.pi / pitch
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        fc = Fmax * math.sin(k * (xd[j] - x)) + c * (vd - v)
        g = stribeck_g(v, Fc, Fs, vs, alpha, shape)
        zd = v - s0 * abs(v) * z / g
        ff = s0 * z + s1 * zd + s2 * v
        F[j] = ff
        v = v + h * (fc - ff) / m
        z = bristle_update(z, v, s0 * abs(v) / stribeck_g(v, Fc, Fs, vs, alpha, shape), h, 0)
        x = x + h * v
    return F


@on_fine_grid
def magnetic_coupling_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact joined by a magnetic coupling (the magnets of a magnetically
    coupled rodless cylinder's piston and carriage, a magnetic linear feedthrough): no
    play, but a pull F_max sin(2 pi u / p) of their offset u (F_max = :data:`COUPLING_PULL`
    x the 99th percentile of the base's |friction|, at least Fs: more than the contact's
    friction, so it does not slip a pole), damped by eddy currents
    (damping ratio :data:`COUPLING_DAMPING` with the contact at small offsets). A reversal
    between the Coulomb levels turns the offset over by (p / pi) arcsin(Fc / F_max), the
    lost motion, = ``s``^2 :data:`GAP_SHARE` x the stroke (its pole pitch p follows), in
    series with the stiff coupling of the other forms, 100 x stiffer than the bristle
    (:func:`.truths._contact_constants`; its compliance lumped into the pitch, exact to
    first order in the offset). The contact is light, with the base's LuGre
    friction (:func:`_coupled_contact`); the measured force is its friction. At ``s`` = 0
    the stiff coupling (the base, up to it).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the square root of the lost motion relative to
        :data:`GAP_SHARE` x the stroke (as the open plays': a size growing about linearly
        with the lost motion follows ``s`` too weakly to be calibrated on the XML-350's
        many small reversals).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Magnetic couplings' pull, sinusoidal in the offset to its peak (the pull-out force)
    and pole slip beyond (Furlani 2001, Permanent Magnet and Electromechanical Devices);
    magnetically coupled rodless cylinders, whose carriage lags the piston and decouples
    when overloaded (Beater 2007, Pneumatic Drives). The candidate holds or frees the
    force across the play; the open forms couple it rigidly, compliantly, by impacts, a
    linear spring, an oil film, an idler's drag, a bias or slack chain strands that harden
    as they straighten, with a play varying with the position or growing with the travel;
    here there is no play at all: a soft coupling that softens as the offset grows (the
    sine's flattening towards its peak), so the contact waits longest, after a reversal,
    just before it follows.
    """
    p = _lugre_params(kin, "backlash (magnetic_coupling)")
    m, kh, _ = _contact_constants(kin, p)
    _, Ff = _base_parts(kin)
    Fmax = COUPLING_PULL * max(float(np.percentile(np.abs(Ff), 99)), float(p.Fs))
    lost = max(float(s), 0.0) ** 2 * GAP_SHARE * float(np.ptp(kin.x))
    # the stiff coupling of the other forms in series (to first order, its compliance
    # lumped into the pitch): at s = 0 the contact follows through it alone
    pitch = math.pi * lost / math.asin(min(float(p.Fc) / Fmax, 1.0)) \
        + 2.0 * math.pi * Fmax / kh
    k0 = 2.0 * math.pi * Fmax / pitch
    c = 2.0 * COUPLING_DAMPING * math.sqrt(k0 * m)
    rate = max(math.sqrt((k0 + float(p.sigma0)) / m),
               (float(p.sigma1) + float(p.sigma2) + c) / m)
    n_sub = int(min(max(math.ceil(rate * kin.dt / 0.3), 4), 400))
    t2 = kin.t[0] + (kin.dt / n_sub) * np.arange((kin.t.size - 1) * n_sub + 1)
    xd = np.interp(t2, kin.t, kin.x)
    F = _coupled_contact(kin.dt / n_sub, xd, pitch, Fmax, c, m, float(p.sigma0),
                         float(p.sigma1), float(p.sigma2), float(p.Fc), float(p.Fs),
                         float(p.vs), float(p.alpha), SHAPES[p.shape])
    return F[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: the path of shear over which ``gouge_fabric``'s force chains re-form at strength 1,
#: beyond the base bristle's path, as a share of the stroke / 3 [-]; the layer's share of
#: the friction at strength 1 [-]; its strength against its fabric, x the sliding
#: strength [-]; the slip over which its strength follows the Stribeck level, x the
#: fabric's path [-]
PRESLIDING_SHARE, GOUGE_SHARE, FABRIC_FLOOR, GOUGE_STRENGTH_RUN = 0.03, 0.5, 0.2, 0.1


@njit(cache=True)
def _gouge(x, G, k, path, floor):
    """Force [N] of a granular layer sheared along the positions ``x`` [m]: elastic
    (stiffness ``k`` [N/m]) up to its strength, then slipping at it; its fabric phi in
    [-1, 1] (the force chains' alignment with +x) relaxes towards the direction of its
    slip over the slip ``path`` [m], and its strength in each direction is G (``floor`` +
    (1 - ``floor``) ((1 +- phi) / 2)^2) (``G`` [N] the sliding strength at each point).
    Starts unloaded, its fabric isotropic (phi = 0)."""
    n = x.size
    out = np.zeros(n)
    f = 0.0
    phi = 0.0
    for j in range(1, n):
        ft = f + k * (x[j] - x[j - 1])
        sp = G[j] * (floor + (1.0 - floor) * (0.5 * (1.0 + phi)) ** 2)
        sn = G[j] * (floor + (1.0 - floor) * (0.5 * (1.0 - phi)) ** 2)
        slip = 0.0
        if ft > sp:
            slip = (ft - sp) / k
            ft = sp
        elif ft < -sn:
            slip = (ft + sn) / k
            ft = -sn
        if slip != 0.0:
            d = 1.0 if slip > 0.0 else -1.0
            phi = d + (phi - d) * math.exp(-abs(slip) / path)
        f = ft
        out[j] = f
    return out


@on_fine_grid
def gouge_fabric_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Presliding through a granular third body beside the bristle: a share w =
    min(:data:`GOUGE_SHARE` ``s``, 1) of the friction is carried by a layer of wear debris,
    elastic with the bristle's stiffness sigma0 up to its strength and sliding at it. The
    strength depends on the layer's fabric phi (its force chains' alignment with the
    shear, in [-1, 1]): in the direction the chains are built for it is the full sliding
    strength G, against them :data:`FABRIC_FLOOR` G, G (:data:`FABRIC_FLOOR` + (1 -
    :data:`FABRIC_FLOOR`) ((1 +- phi) / 2)^2) between; the fabric turns towards the
    direction of the layer's slip over a path lambda = the base bristle's path Fs / sigma0
    plus ``s`` x :data:`PRESLIDING_SHARE` x the stroke / 3 (:func:`_gouge`). G follows the
    base's Stribeck level g(v) over a slip of :data:`GOUGE_STRENGTH_RUN` lambda (a
    reversal, where g(v) jumps to the static level, moves nothing). After a reversal the
    layer unloads elastically, yields at once at the weak floor and then strengthens along
    an S-curve as the new chains form. F = (1 - w) F_lugre + w (f + sigma2 v). At ``s`` = 0
    the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the layer's share (all of the friction from ``s`` = 1 /
        :data:`GOUGE_SHARE` on) and the fabric's path.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Fabric (force-chain) anisotropy of sheared granular media (Oda 1972; Radjai et al.
    1998); the transient after a shear reversal, weak while the old chains collapse and
    the layer compacts, recovering over a strain of a few grains (Toiya, Stambaugh and
    Losert 2004, PRL 93); wear debris as a third body (Godet 1984). Maxwell-slip (the
    candidate, ``maxwell4``, ``maxwell10``) and the Mindlin contacts are elements that
    slip holding their force (Masing's rule), Dahl, Bouc-Wen and Bliman-Sorine path laws
    (concave from the reversal, or overshooting), elasto-plastic an elastic range, the
    Zener junction and the rate-and-state interface rate-dependent creep, the Tomlinson
    contacts multistable tips and the bonds elements born and broken; here the element's
    strength itself is turned over by the reversal: it yields early, at a fraction of its
    strength, and hardens again along an S-curve (convex, then concave) of the path.
    """
    p = _lugre_params(kin, "gms (gouge_fabric)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, PRESLIDING_SHARE)
    lam = e0 + extra
    w = min(GOUGE_SHARE * float(s), 1.0)
    x = np.ascontiguousarray(kin.x, dtype=float)
    v = np.ascontiguousarray(kin.v, dtype=float)
    G = _strength(x, kin.base.g(v), GOUGE_STRENGTH_RUN * lam)
    f = _gouge(x, G, float(p.sigma0), lam, FABRIC_FLOOR)
    return (1.0 - w) * F + w * (f + float(p.sigma2) * v)
