"""The tenth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-29 (session 15) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 16's work on the code of 5aa9452:
176 cases, 0 skipped, 861 s wall beside the open grid. Top-1 40.3 % (71; 42.3 % of the 168
detectable, 40.8 % counting the 6 delay cases below a sample as detectable); mean |shrink
error| 0.346; wrong names on 27 (15.3 %): backlash -> asymmetry 6, delay -> backlash 3,
delay -> acceleration 3, inertia -> asymmetry 3, drift -> load 3. By form:
load/piezoviscous_film 20/20, drift/polymer_swelling 16/20, asymmetry/differential_cylinder
12/20, stribeck_shape/melt_lubrication 9/16, position/bolt_holes 8/16,
gms/kinematic_hardening 5/12, inertia/eddy_coupling 1/20, acceleration/oil_slosh 0/20,
delay/spatial_sampling 0/20, backlash/preloaded_nut 0/12. By plant: press 46.4 %, isolator
42.9 %, valve 40.0 %, XML-350 40.0 %, damping rig 35.0 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen9` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen9`,
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
acceleration       ``oil_slosh``: the contact is fed from an oil bath the carriage
                   carries; the acceleration excites the bath's first sloshing mode
                   (Housner's equivalent oscillator, lightly damped), and when the free
                   surface falls away from the contact's feed the contact runs starved:
                   the levels rise with the sloshing wave's height beyond a margin, late
                   and ringing after each change of the acceleration, one way only
load               ``piezoviscous_film``: the film's viscosity grows exponentially with
                   the contact pressure (Barus 1893), the Hertzian pressure as the load
                   to the power 1/3: the viscous term, not the boundary levels, follows
                   exp(alpha p) of the load
asymmetry          ``differential_cylinder``: a cylinder of unequal areas run by a
                   symmetric valve: the flows through its two metering edges set the
                   rod-side pressure, 1 / (area ratio)^2 higher extending than
                   retracting, and the pressure-energised rod seal follows it; after a
                   reversal the pressure moves to its new level through the oil's
                   compressibility (a lag in time)
stribeck_shape     ``melt_lubrication``: above a speed where the frictional heat melts
                   (or softens) the surface, the contact rides a melt film whose
                   thickness grows with the speed (Bowden and Hughes 1939; Evans, Nye and
                   Cheeseman 1976): the levels fall as 1 / sqrt(v) beyond it, with no
                   floor
position           ``bolt_holes``: the rail's mounting-bolt holes under the carriage's
                   two end seals: each seal lip drops into a hole and climbs out of it at
                   its far edge in the direction of travel: narrow drag spikes at the
                   holes' pitch, in pairs (one per seal), whose positions shift with the
                   direction of motion
inertia            ``eddy_coupling``: a rotating part (a roll, a drum) driven from the
                   axis through an eddy-current coupling whose force follows the slip
                   speed with a peak at a critical slip (Kloss's curve): a lagged mass
                   while the slip is small, which lets go of the part when the
                   acceleration asks more than its pull-out force
delay              ``spatial_sampling``: the force is captured on the encoder's position
                   triggers (averaged over the last few fixed travels) and held by the
                   time-based logger: the delay is the time to travel that distance,
                   short at speed and long near the reversals, where the force's turn is
                   held until the carriage has moved on
drift              ``polymer_swelling``: a polymer (polyamide) liner takes up water by
                   Fickian diffusion and swells, closing its running clearance: the
                   contact pressure, and the levels, rise as the square root of the
                   time (Crank 1975)
backlash           ``preloaded_nut``: a double nut preloaded by a spring (constant-
                   pressure preload): stiff both ways up to the preload, but once the
                   force pulling one way exceeds it the spring half carries the load
                   and yields: no play, a lost motion through a soft spring on one side
                   of the force only
gms                ``kinematic_hardening``: the asperity junctions beside the bristle
                   yield with nonlinear kinematic hardening (Armstrong and Frederick
                   1966; friction by Mroz and Stupkiewicz 1994): an elastic range of
                   fixed width carried by a back-stress, so after a reversal the layer
                   yields before its force has even changed sign (the Bauschinger
                   effect) and hardens exponentially; at ``s`` = 0 the base itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``melt_lubrication``
needs a Stribeck curve (not the isolator's mre_lugre), ``bolt_holes`` a record that
revisits its positions (not the press), ``piezoviscous_film`` a load that changes,
``preloaded_nut`` and ``kinematic_hardening`` a classic LuGre base (valve, damping rig,
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
                     _lugre_params, _motion_time, _presliding_path, _smooth_max0, _span,
                     level_inside, on_fine_grid)

__all__ = ["FORMS", "oil_slosh_truth", "piezoviscous_film_truth",
           "differential_cylinder_truth", "melt_lubrication_truth", "bolt_holes_truth",
           "eddy_coupling_truth", "spatial_sampling_truth", "polymer_swelling_truth",
           "preloaded_nut_truth", "kinematic_hardening_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "oil_slosh", "load": "piezoviscous_film",
         "asymmetry": "differential_cylinder", "stribeck_shape": "melt_lubrication",
         "position": "bolt_holes", "inertia": "eddy_coupling",
         "delay": "spatial_sampling", "drift": "polymer_swelling",
         "backlash": "preloaded_nut", "gms": "kinematic_hardening"}


# -- acceleration ---------------------------------------------------------------------------
#: ``oil_slosh``'s sloshing frequency x the motion's time scale [-]; its damping ratio [-];
#: the wave height (relative to its static value at a99) below which the feed stays wetted
#: [-], and the width it is rounded over [-]; the levels' rise per unit of relative wave
#: height beyond that margin at strength 1 [-]
SLOSH_FREQUENCY, SLOSH_DAMPING, SLOSH_MARGIN, SLOSH_ROUNDING, SLOSH_RISE = \
    0.5, 0.1, 0.3, 0.05, 1.0


@njit(cache=True)
def _slosh(h, u, w, zeta):
    """The sloshing wave's height [-] of a tank whose first mode (natural frequency ``w``
    [rad/s], damping ratio ``zeta``) is driven by the relative acceleration ``u`` [-] on
    the grid of step ``h`` [s]: eta'' + 2 zeta w eta' + w^2 eta = w^2 u (static gain 1),
    semi-implicit Euler. Starts at rest, flat."""
    n = u.size
    out = np.empty(n)
    e = 0.0
    d = 0.0
    for k in range(n):
        out[k] = e
        d += h * (w * w * (u[k] - e) - 2.0 * zeta * w * d)
        e += h * d
    return out


@on_fine_grid
def oil_slosh_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A contact fed from an oil bath carried by the carriage (a splash- or bath-lubricated
    drive): the acceleration a tilts the bath's free surface, which the bath's first
    sloshing mode follows as a lightly damped oscillator (Housner's equivalent
    spring-mass): the wave height eta at the bath's front wall, relative to its static
    value at a99, obeys eta'' + 2 zeta w eta' + w^2 eta = w^2 a / a99 (w =
    :data:`SLOSH_FREQUENCY` / the motion's time scale, zeta = :data:`SLOSH_DAMPING`,
    :func:`_slosh`; accelerating forwards piles the oil up at the rear). The contact's feed
    sits at the front: where the surface there falls by more than :data:`SLOSH_MARGIN`,
    the contact runs starved, and the Coulomb and Stribeck levels are the base's times 1 +
    ``s`` :data:`SLOSH_RISE` max(eta - :data:`SLOSH_MARGIN`, 0) (rounded over
    :data:`SLOSH_ROUNDING`), inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the levels' rise per unit of relative wave height beyond the
        margin, / :data:`SLOSH_RISE`.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Liquid sloshing in moving containers and its equivalent mechanical model (Housner 1963,
    The dynamic behavior of water tanks; Abramson 1966, NASA SP-106; Ibrahim 2005, Liquid
    Sloshing Dynamics); starvation of a contact whose inlet is not flooded (Wedeven, Evans
    and Cameron 1971), here set by the bath's level at the feed. The candidate adds a force
    odd in a and raises the levels with |a|, lagged; the open forms lag the velocity or a
    state, heat the contact, skid rolling elements, move load between ball rows or
    supports, press a seal with a lagged |a|, pull the carriage with the thrust or relieve
    it by a squeeze film. Here the levels follow a resonant response to the signed
    acceleration, one-sided: they rise late after the accelerations that empty the feed,
    ring on at the bath's own frequency after the acceleration has ended, and do not fall
    below the base's.
    """
    a99 = max(kin.scales["a99"], 1e-12)
    w = SLOSH_FREQUENCY / max(_motion_time(kin), 1e-12)
    eta = _slosh(kin.dt, np.ascontiguousarray(kin.a, dtype=float) / a99, w, SLOSH_DAMPING)
    lev = 1.0 + max(float(s), 0.0) * SLOSH_RISE * _smooth_max0(eta - SLOSH_MARGIN,
                                                               SLOSH_ROUNDING)
    return level_inside(kin, lev, np.ones_like(lev))


# -- load -------------------------------------------------------------------------------------
#: ``piezoviscous_film``'s pressure-viscosity exponent alpha x the mean Hertzian pressure at
#: strength 1 [-]; the largest exponent the viscosity reaches (a cap against overflow) [-]
BARUS_EXPONENT, BARUS_CAP = 4.0, 30.0


@on_fine_grid
def piezoviscous_film_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A lubricated contact whose film viscosity grows exponentially with the pressure
    (Barus): eta = eta_0 exp(alpha (p - p_mean)), the contact's Hertzian pressure p =
    p_mean (L / mean L)^(1/3) of the normal load L. The film's shear, the viscous term, is
    the base's times exp(``s`` :data:`BARUS_EXPONENT` ((L / mean L)^(1/3) - 1)) (the
    exponent capped at :data:`BARUS_CAP`), inside the bristle dynamics (the isolator: its
    damper c0 v); the boundary levels are the base's. ValueError if the load does not
    change.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], load [N]) and its base law.
    s : float
        Amplitude factor [-]: alpha p_mean, / :data:`BARUS_EXPONENT`.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Barus 1893 (the isothermal pressure-viscosity law of oils); its role in
    elastohydrodynamic films (Hamrock, Schmid and Jacobson 2004, Fundamentals of Machine
    Elements; Bair 2007, High Pressure Rheology for Quantitative Elastohydrodynamics); the
    Hertzian pressure of a point contact, p ~ L^(1/3) (Johnson 1985). The candidate and
    the open forms are laws of the load on the levels (affine, a power, one direction, the
    Stribeck velocity, a step, a hinge), of its rate, a creep towards it, a play, a memory
    over the travel or a lag while it rises; the viscous term follows the load linearly
    (the candidate's k_v) or as its square root (``squeeze_film``). Here only the film's
    viscous drag follows the load, exponentially in its pressure: nothing at rest, convex
    in the load, most at speed under the largest loads.
    """
    L = np.asarray(kin.load, float)
    L0 = max(float(np.mean(np.abs(L))), 1e-12)
    # a change below 1e-6 of the mean load over the record is round-off, not a change
    if float(np.ptp(L)) <= 1e-6 * L0:
        raise ValueError(f"load (piezoviscous_film): the {kin.plant} record's load does "
                         f"not change")
    p = np.cbrt(np.clip(L, 0.0, None) / L0)
    vis = np.exp(np.minimum(max(float(s), 0.0) * BARUS_EXPONENT * (p - 1.0), BARUS_CAP))
    if kin.base.name == "mre_lugre":
        F, _ = _base_parts(kin)
        return F + float(kin.base.params.c0) * np.asarray(kin.v, float) * (vis - 1.0)
    return level_inside(kin, np.ones_like(vis), vis)


# -- asymmetry -------------------------------------------------------------------------------
#: ``differential_cylinder``'s area ratio, annulus / piston [-]; the oil's compressibility
#: lag of the chamber pressures, x the motion's time scale [-]; the rod seal's share of the
#: levels at strength 1, between its two steady pressures [-]
AREA_RATIO, PRESSURE_LAG, ROD_SEAL = 0.5, 0.3, 0.4


@on_fine_grid
def differential_cylinder_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A differential (single-rod) cylinder, annulus / piston area a = :data:`AREA_RATIO`,
    driven by a symmetric valve from a constant supply: the flows through the two
    metering edges (Q ~ sqrt(Delta p)) and the piston's continuity (Q_A a = Q_B) set, in
    steady motion, the rod-side pressure p_B = p_s / (a (1 + a)) extending (v > 0) and p_s
    a / (1 + a) retracting: 1 / a^2 times higher out than in. The rod seal is
    pressure-energised, its friction ~ p_B. After a reversal the pressures move to their
    new levels through the oil's compressibility: P, p_B relative to its extending value
    (a^2 retracting; the direction rounded over 2 % of v99), follows with a first-order lag
    of :data:`PRESSURE_LAG` x the motion's time scale. The Coulomb and Stribeck levels are
    the base's times 1 + ``s`` :data:`ROD_SEAL` (2 P - 1 - a^2) / (1 - a^2) (the base's
    levels at the mean of the two pressures), inside the bristle dynamics; the viscous term
    is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the rod seal's share of the levels, / :data:`ROD_SEAL`.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Steady chamber pressures of a valve-controlled differential cylinder (Merritt 1967,
    Hydraulic Control Systems; Jelali and Kroll 2003, Hydraulic Servo-systems);
    pressure-energised rod seals whose friction follows the sealed pressure (Mueller and
    Nau 1998, Fluid Sealing Technology). The candidate shifts a direction's levels and
    viscous slope (and an offset); the open forms keep a direction's share, move its
    Stribeck velocity, viscous slope or tail, follow a lip, a thrust, a film, a texture, a
    return spring, a wedge film, a strut or a throttle's v^2. Here the direction's levels
    are set by the pressures one valve gives an unequal-area piston, the same at every
    speed, and cross over, after each reversal, in time: the force of the new direction
    starts at the old direction's seal load.
    """
    a2 = AREA_RATIO ** 2
    v = np.asarray(kin.v, float)
    out = 0.5 * (1.0 + np.tanh(v / (0.02 * max(kin.scales["v99"], 1e-12))))
    P = _lag(kin.t, a2 + (1.0 - a2) * out, PRESSURE_LAG * _motion_time(kin))
    lev = 1.0 + max(float(s), 0.0) * ROD_SEAL * (2.0 * P - 1.0 - a2) / (1.0 - a2)
    return level_inside(kin, np.clip(lev, 0.05, None), np.ones_like(lev))


# -- stribeck_shape --------------------------------------------------------------------------
#: ``melt_lubrication``'s melting speed at strength 1, x v99 [-]
MELT_SPEED = 0.3


@on_fine_grid
def melt_lubrication_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Melt (or softening) lubrication at speed: the frictional heat melts a film of the
    softer surface (a polymer slider, ice) once the speed passes v_m, and the film thickens
    as the speed grows, its shear falling as sqrt(v_m / |v|): the Stribeck curve is the
    base's times (1 + (v / v_m)^2)^(-1/4) (1 at rest and below v_m, 1 / sqrt(|v| / v_m)
    well above), v_m = :data:`MELT_SPEED` v99 / ``s``^2 (more heat, an earlier melt),
    inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (a Stribeck curve).
    s : float
        Amplitude factor [-]: the square root of :data:`MELT_SPEED` v99 / v_m (the
        frictional heating against the heat the solids conduct away).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Frictional melting and the fall of friction with speed (Bowden and Hughes 1939, the
    mechanism of sliding on ice and snow; Evans, Nye and Cheeseman 1976, the kinetic
    friction of ice: mu ~ v^(-1/2) at speed; the surface melting of polymers sliding
    beyond their PV limit). The candidate bends the base's drop (an exponent, the
    Lorentzian, a log-speed map over 2.5 decades); the open forms add tails, drops, a
    spike, a lift-off, a second drop, a logarithmic weakening, an Eyring strengthening, a
    rise at the top speed, a hump of rubber hysteresis, a resonance's notch or a dither's
    loss of stiction. Here the
    level weakens at speed as a power law, -1/2, with no floor: nothing at low speed, the
    curve still falling at the top speed.
    """
    if kin.base.name == "mre_lugre":
        raise ValueError("stribeck_shape (melt_lubrication): the mre_lugre base has no "
                         "Stribeck curve")
    v = np.asarray(kin.v, float)
    s = max(float(s), 0.0)
    u = s * s * v / (MELT_SPEED * max(kin.scales["v99"], 1e-12))
    lev = (1.0 + u * u) ** -0.25
    return level_inside(kin, lev, np.ones_like(v))


# -- position --------------------------------------------------------------------------------
#: ``bolt_holes``' pitch of the rail's bolt holes, x the stroke the record visits [-]; the
#: holes' diameter, x the pitch [-]; the distance between the carriage's two end seals, x
#: the pitch [-]; the travel over which a seal lip climbs out of a hole, x the pitch [-];
#: the drag of a lip climbing out at strength 1, x the levels [-]
HOLE_PITCH, HOLE_SIZE, SEAL_SPACING, CLIMB, CLIMB_DRAG = 0.3, 0.4, 1.37, 0.06, 1.0


def _edge_drag(xs, centres, edge, width):
    """Sum over the holes at ``centres`` [m] of a Gaussian of the seal positions ``xs`` [m]
    about each hole's edge at ``centres`` + ``edge`` [m], of standard deviation ``width``
    [m] [-]."""
    d = (xs[:, None] - (centres[None, :] + edge)) / width
    return np.exp(-0.5 * d * d).sum(axis=1)


@on_fine_grid
def bolt_holes_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The bolt holes of a linear-guide rail under the carriage's two end seals: holes of
    diameter :data:`HOLE_SIZE` p every p = :data:`HOLE_PITCH` x the stroke the record
    visits (from a quarter pitch inside its lower end), the seals :data:`SEAL_SPACING` p
    apart about the carriage's position. A seal's lip drops into a hole freely and drags
    while it climbs out over the hole's far edge in the direction of travel (the upper
    edge when v > 0, the lower when v < 0; the direction rounded over 2 % of v99), over a
    travel of :data:`CLIMB` p (:func:`_edge_drag`). The Coulomb and Stribeck levels are the
    base's times 1 + ``s`` :data:`CLIMB_DRAG` x the sum of both seals' climbs, inside the
    bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: a lip's climbing drag relative to :data:`CLIMB_DRAG` x the
        levels.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Rail mounting-bolt holes and their caps under the end seals of profiled linear guides
    (the manufacturers' mounting instructions: caps flush with the rail, or the seals
    wear and drag); a lip climbing a step (seal lips over grooves and ports: Mueller and
    Nau 1998). The candidate scales the friction along the stroke (a map, a waviness of
    two harmonics, a defect) and adds a periodic force of x; the open forms are level maps
    (a defect, waviness, a worn section, runout, a bow, a transfer film, a taper, a port's
    wake), a periodic detent force, a cushion's drag in one zone and direction, a cover's
    staircase or a trapped gas spring. Here narrow spikes at the holes' pitch, doubled by
    the two seals, sit at a hole's upper edge moving up and its lower edge moving down.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (bolt_holes): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    pitch = HOLE_PITCH * _span(kin)
    x = np.asarray(kin.x, float)
    x_lo, x_hi = kin.scales["x_lo"], kin.scales["x_hi"]
    # every hole either seal can reach, with a pitch to spare
    reach = 0.5 * SEAL_SPACING * pitch + pitch
    k = np.arange(math.floor(-reach / pitch) - 1, math.ceil((x_hi - x_lo + reach) / pitch) + 2)
    centres = x_lo + (k + 0.25) * pitch
    up = 0.5 * (1.0 + np.tanh(np.asarray(kin.v, float)
                              / (0.02 * max(kin.scales["v99"], 1e-12))))
    half, width = 0.5 * HOLE_SIZE * pitch, CLIMB * pitch
    drag = np.zeros_like(x)
    for off in (-0.5 * SEAL_SPACING * pitch, 0.5 * SEAL_SPACING * pitch):
        xs = x + off
        drag += up * _edge_drag(xs, centres, half, width) \
            + (1.0 - up) * _edge_drag(xs, centres, -half, width)
    lev = 1.0 + max(float(s), 0.0) * CLIMB_DRAG * drag
    return level_inside(kin, lev, np.ones_like(lev))


# -- inertia ---------------------------------------------------------------------------------
#: ``eddy_coupling``'s part mass at strength 1, x the friction level / a99 [kg per N s^2/m];
#: its pull-out force, x the part's mass x a99 [-]; the critical slip speed (the pull-out
#: force's), x v99 [-]
COUPLED_MASS, PULL_OUT, CRITICAL_SLIP = 0.3, 0.6, 0.1


@njit(cache=True)
def _eddy_drive(h, v, f_max, u_c, n_sub):
    """Force [N / kg] an eddy-current coupling transmits to a part of unit mass driven by
    the velocities ``v`` [m/s] (grid step ``h`` [s]): 2 ``f_max`` (u / ``u_c``) / (1 + (u /
    ``u_c``)^2) of the slip u = v - v_p (Kloss's curve; ``f_max`` [m/s^2] its pull-out,
    ``u_c`` [m/s] the critical slip), the part following dv_p / dt = that force;
    semi-implicit Euler on ``n_sub`` sub-steps of each grid step (the drive's velocity
    linear between the grid points). Starts with the part moving with the drive."""
    n = v.size
    out = np.empty(n)
    vp = v[0]
    hs = h / n_sub
    for k in range(n):
        u = (v[k] - vp) / u_c
        out[k] = 2.0 * f_max * u / (1.0 + u * u)
        if k + 1 < n:
            for j in range(n_sub):
                vd = v[k] + (v[k + 1] - v[k]) * (j + 1.0) / n_sub
                u = (vd - vp) / u_c
                # linearised about the slip: implicit in the part's velocity
                g = 2.0 * f_max * (1.0 - u * u) / (1.0 + u * u) ** 2 / u_c
                f = 2.0 * f_max * u / (1.0 + u * u)
                vp += hs * f / (1.0 + hs * max(g, 0.0))
    return out


@on_fine_grid
def eddy_coupling_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A rotating part (a roll, a cable drum, a fan) driven from the axis through an
    eddy-current (induction) coupling, of reflected mass m = ``s`` :data:`COUPLED_MASS` x
    the friction level / a99. The coupling's force follows the slip speed u = v - v_p
    between the axis and the part as Kloss's curve, 2 F_po (u / u_c) / (1 + (u / u_c)^2)
    (pull-out force F_po = :data:`PULL_OUT` m a99 at the critical slip u_c =
    :data:`CRITICAL_SLIP` v99), and drives the part, m dv_p / dt = that force
    (:func:`_eddy_drive`). The inverse dynamics misses it: the measured force is the
    base's plus the coupling's force. While the slip stays below u_c the part is a mass
    seen through a lag of about u_c / (2 F_po / m); where the axis accelerates harder than
    F_po / m the slip runs past u_c, the force falls, and the part is let go until the
    axis slows to it.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the part's mass relative to :data:`COUPLED_MASS` x level /
        a99 (the coupling sized with it).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Eddy-current couplings and brakes, whose torque-slip curve peaks at a critical slip
    (Wouterse 1991, Critical torque and speed of eddy current brake with widely separated
    soft iron poles, IEE Proc. B 138; Kloss's formula of the induction machine). The
    candidate and the open forms are masses (constant, filtered, along the stroke, through
    a ratio or a lossy gear, in time, behind a spring, in a fluid), a payload held by
    Coulomb friction, a part rattling in a pocket, a flywheel through a freewheel or a part
    carried one way; here a mass seen through a slip-speed coupling: lagged, and let go
    (its force falling, not held) beyond the coupling's pull-out.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    m = s * COUPLED_MASS * _level(kin) / a99
    f_max = PULL_OUT * a99
    u_c = CRITICAL_SLIP * max(kin.scales["v99"], 1e-12)
    # sub-steps resolving the coupling's fastest response, 2 f_max / u_c
    n_sub = int(min(max(math.ceil(2.0 * f_max / u_c * kin.dt / 0.2), 1), 200))
    return F + m * _eddy_drive(kin.dt, np.ascontiguousarray(kin.v, dtype=float), f_max,
                               u_c, n_sub)


# -- delay -----------------------------------------------------------------------------------
#: ``spatial_sampling``'s travel increments each value averages over [-]
CAPTURE_INCREMENTS = 4


@njit(cache=True)
def _position_capture(F, x, t, step, m_avg):
    """The values [N] a position-triggered averaging capture delivers from the force ``F``
    [N] along the positions ``x`` [m] at the times ``t`` [s]: a capture each time the
    travel (the sum of |dx|) since the last one reaches ``step`` [m] > 0 (located between
    the grid points by linear interpolation), its value the force's time average over the
    last ``m_avg`` increments (trapezoidal; since the start until there are as many), held
    in between. Starts holding the first force."""
    n = F.size
    y = np.empty(n)
    c = F[0]
    y[0] = c
    d = 0.0                        # travel since the last capture [m]
    area = 0.0                     # the force's time integral since the start [N s]
    ring_a = np.zeros(m_avg)       # the integral and time at the last m_avg captures
    ring_t = np.full(m_avg, t[0])
    i = 0
    for k in range(1, n):
        dx = abs(x[k] - x[k - 1])
        h = t[k] - t[k - 1]
        if d + dx >= step:
            # the crossings within this step (only the last m_avg + 1 can count)
            m = int(math.floor((d + dx) / step))
            for q in range(max(1, m - m_avg), m + 1):
                r = (q * step - d) / dx
                Fr = F[k - 1] + r * (F[k] - F[k - 1])
                a_r = area + 0.5 * (F[k - 1] + Fr) * r * h
                t_r = t[k - 1] + r * h
                c = (a_r - ring_a[i]) / (t_r - ring_t[i]) if t_r > ring_t[i] else Fr
                ring_a[i] = a_r
                ring_t[i] = t_r
                i = (i + 1) % m_avg
            d = d + dx - m * step
        else:
            d += dx
        area += 0.5 * (F[k - 1] + F[k]) * h
        y[k] = c
    return y


@on_fine_grid
def spatial_sampling_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force captured on position triggers: an encoder-gated converter averages the
    force over the travel of the last :data:`CAPTURE_INCREMENTS` increments of Delta =
    ``s``^2 x v99 x the data's sample interval each (whichever way) and delivers the mean
    at the end of each increment, and the time-based logger holds the last value
    (:func:`_position_capture`). At the speed v the force comes (:data:`CAPTURE_INCREMENTS`
    + 1) Delta / (2 |v|) late on average: (:data:`CAPTURE_INCREMENTS` + 1) ``s``^2 / 2
    samples at v99, the longer the slower it moves; through a reversal the values average
    over the turn and none comes until the carriage has moved Delta again. At ``s`` = 0
    the force itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the square root of the increment, in samples of travel at
        the top speed (the square, as the open
        plays' lost motion: a size growing about as the square root of the distance, held
        through the XML-350's many small reversals, follows ``s`` too weakly to be
        calibrated).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Sampling on an encoder's pulses, equidistant in the travel rather than in time (the
    angle-domain sampling of order tracking: Potter 1990, A new order tracking method for
    rotating machinery, Sound and Vibration 24; Fyfe and Munck 1997, Analysis of computed
    order tracking, MSSP 11), here gating an averaging converter whose values a
    time-based logger holds. The open forms delay by one amount (a shift, held
    samples), filter linearly (a lag, Bessel, a moving average, a converter's FIR, a
    line's echoes) or by rank (a running median), let the delay drift, wander or grow
    with the force's rate (a slew limit) or its slowness (send-on-delta), or shift the
    motion; here the delay is set by the motion's speed: short where it moves fast, long
    near the reversals and unbounded at rest.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    step = s * s * max(kin.scales["v99"], 1e-12) * kin.sample_dt
    return _position_capture(np.ascontiguousarray(F, dtype=float),
                             np.ascontiguousarray(kin.x, dtype=float),
                             np.ascontiguousarray(kin.t, dtype=float), step,
                             CAPTURE_INCREMENTS)


# -- drift -----------------------------------------------------------------------------------
#: ``polymer_swelling``'s diffusion time l^2 / D of the liner, x the record [-]; the levels'
#: rise per unit of the uptake's saturated value at strength 1 [-]
DIFFUSION_TIME, SWELL_RISE = 10.0, 1.0


def _fickian_uptake(tau):
    """The share [-] of its saturated uptake a plane sheet exposed on both faces has taken
    up at the dimensionless times ``tau`` = D t / l^2 >= 0 [-] (l its thickness): 4
    sqrt(tau / pi) while tau <= 0.01 (the short-time series' first term; the next, 8
    sqrt(tau) ierfc(1 / (2 sqrt(tau))), is below 1e-12 there), and the long-time series
    beyond (Crank 1975, Eq. 4.18, twenty terms)."""
    tau = np.clip(np.asarray(tau, float), 0.0, None)
    short = 4.0 * np.sqrt(tau / np.pi)
    n = 2.0 * np.arange(20) + 1.0
    long_ = 1.0 - (8.0 / (n * n * np.pi ** 2)
                   * np.exp(-np.multiply.outer(tau, n * n * np.pi ** 2))).sum(axis=-1)
    return np.where(tau <= 0.01, short, long_)


@on_fine_grid
def polymer_swelling_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A polymer (polyamide) bearing liner taking up water by Fickian diffusion from the
    record's start: its uptake M(t) / M_sat (:func:`_fickian_uptake`, the liner's diffusion
    time l^2 / D = :data:`DIFFUSION_TIME` x the record, so the uptake is in its sqrt(t)
    stage) swells it, closes its running clearance and raises the contact pressure: the
    Coulomb and Stribeck levels are the base's times 1 + ``s`` :data:`SWELL_RISE`
    M(t) / M_sat, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the levels' rise at the saturated uptake, / :data:`SWELL_RISE`.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Diffusion into a plane sheet (Crank 1975, The Mathematics of Diffusion: the uptake
    grows as sqrt(t) until about half its saturation); water absorption and swelling of
    polyamides, which close plain bearings' clearances (Kohan 1995, Nylon Plastics
    Handbook; Lancaster 1990, A review of the influence of environmental humidity and
    water on friction, lubrication and wear, Tribology International 23).
    The candidate is a trend, a saturating change, a step and a cycle in time; the open
    forms warm up, wear in (in time, with the load and travel), step, heat, cycle, rise
    and fall with debris, drop with grease shots, relax in log time, grow an oxide and
    spall, oxidise after an induction or wear a coating through along the travel. Here the
    levels rise as the square root of the time since the start: steepest at once,
    without a time constant.
    """
    t = np.asarray(kin.t, float)
    T = float(t[-1] - t[0]) or 1.0
    M = _fickian_uptake((t - t[0]) / (DIFFUSION_TIME * T))
    lev = 1.0 + max(float(s), 0.0) * SWELL_RISE * M
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: the lost motion of ``preloaded_nut`` at strength 1 (a reversal between the Coulomb
#: levels, beyond the stiff coupling's), as a share of the stroke [-] (the open backlash
#: forms' play); the preload, x the base's Coulomb level [-]
GAP_SHARE, PRELOAD = PLANT_GAP_SHARE, 0.3


@njit(cache=True)
def _preloaded_contact(h, xd, P, kh, ch, ks, cs, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a contact of mass ``m`` [kg] pulled by the drive positions
    ``xd`` [m] (grid step ``h`` [s]) through a spring-preloaded double nut: for a pull
    above -``P`` [N] the stiff coupling ``kh`` [N/m], ``ch`` [N s/m] of the deflection e =
    drive - contact; below it the preload spring's half carries the load, -P + ``ks`` (e +
    P / kh) with damping ``cs`` [N s/m]. Semi-implicit Euler of the mass, the bristle
    advanced exactly at the contact's velocity (:func:`friction.lugre.bristle_update`).
    Starts at rest, undeflected, its bristle unloaded."""
    n = xd.size
    F = np.empty(n)
    x = xd[0]
    v = 0.0
    z = 0.0
    e_p = -P / kh
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        e = xd[j] - x
        if e >= e_p:
            fc = kh * e + ch * (vd - v)
        else:
            fc = -P + ks * (e - e_p) + cs * (vd - v)
        g = stribeck_g(v, Fc, Fs, vs, alpha, shape)
        zd = v - s0 * abs(v) * z / g
        ff = s0 * z + s1 * zd + s2 * v
        F[j] = ff
        v = v + h * (fc - ff) / m
        z = bristle_update(z, v, s0 * abs(v) / stribeck_g(v, Fc, Fs, vs, alpha, shape), h, 0)
        x = x + h * v
    return F


@on_fine_grid
def preloaded_nut_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact joined by a double nut preloaded by a spring (constant-pressure
    preload, P = :data:`PRELOAD` Fc): while the force pulling the contact backwards stays
    below the preload both halves bear and the coupling is the stiff one of the other
    forms (100 x the bristle's stiffness, :func:`.truths._contact_constants`); beyond it
    the rigid half lifts off its flanks and the spring's half carries the load through
    the preload spring, k_s in series with the stiff coupling (:func:`_preloaded_contact`).
    A reversal between the Coulomb levels then loses (Fc - P) / k_s more travel than the
    stiff coupling's, = ``s``^2 :data:`GAP_SHARE` x the stroke (k_s follows). The contact
    is light, with the base's LuGre friction; the measured force is its friction. At ``s``
    = 0 the stiff coupling (the base, up to it).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the square root of the lost motion relative to
        :data:`GAP_SHARE` x the stroke (as the open plays').

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Constant-pressure (spring) preload of ball-screw double nuts against fixed-position
    preload: the preload stays under wear and heat, but the axial stiffness in the
    spring's direction falls to the spring's once the load exceeds about the preload
    (the ball-screw makers' technical notes; Harris and Kotzalas 2006 on preloaded
    pairs). The candidate holds or frees the force across a play; the open forms couple
    it rigidly, compliantly, by impacts, a linear spring, an oil film, an idler's drag, a
    bias, slack chain strands or a magnetic pull, with a play varying with the position
    or growing with the travel; here there is no play: the coupling is stiff for one sign
    of the force and for the other up to the preload, soft beyond it, so after either
    reversal the force moves quickly over one part of its swing and slowly over the
    negative part beyond -P.
    """
    p = _lugre_params(kin, "backlash (preloaded_nut)")
    m, kh, ch = _contact_constants(kin, p)
    P = PRELOAD * float(p.Fc)
    lost = max(float(s), 0.0) ** 2 * GAP_SHARE * float(np.ptp(kin.x))
    ks = 1.0 / (1.0 / kh + lost / max(float(p.Fc) - P, 1e-300))
    cs = ch * math.sqrt(ks / kh)
    rate = max(math.sqrt((kh + float(p.sigma0)) / m),
               (float(p.sigma1) + float(p.sigma2) + ch) / m)
    n_sub = int(min(max(math.ceil(rate * kin.dt / 0.3), 4), 400))
    t2 = kin.t[0] + (kin.dt / n_sub) * np.arange((kin.t.size - 1) * n_sub + 1)
    xd = np.interp(t2, kin.t, kin.x)
    F = _preloaded_contact(kin.dt / n_sub, xd, P, kh, ch, ks, cs, m, float(p.sigma0),
                           float(p.sigma1), float(p.sigma2), float(p.Fc), float(p.Fs),
                           float(p.vs), float(p.alpha), SHAPES[p.shape])
    return F[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: the hardening path of ``kinematic_hardening``'s layer at strength 1, beyond the base
#: bristle's path, as a share of the stroke / 3 [-]; the layer's share of the friction at
#: strength 1 [-]; its elastic range's half-width, x its sliding strength [-]; the slip
#: over which its strength follows the Stribeck level, x the hardening path [-]
PRESLIDING_SHARE, LAYER_SHARE, ELASTIC_RANGE, LAYER_STRENGTH_RUN = 0.03, 0.5, 0.25, 0.1


@njit(cache=True)
def _hardening(x, G, k, path, r_share):
    """Force [N] of an elastic-plastic layer with nonlinear kinematic hardening sheared
    along the positions ``x`` [m]: elastic (stiffness ``k`` [N/m]) while |f - b| <= r,
    slipping beyond, with the back-stress b following the slip p as db = H dp - (H / b_s)
    b |dp| (Armstrong-Frederick; r = ``r_share`` G, b_s = (1 - ``r_share``) G, H = b_s /
    ``path``, ``G`` [N] the sliding strength at each point, ``path`` [m] the hardening
    path); each step's slip from the linearised consistency condition. Starts unloaded."""
    n = x.size
    out = np.zeros(n)
    f = 0.0
    b = 0.0
    for j in range(1, n):
        r = r_share * G[j]
        bs = max((1.0 - r_share) * G[j], 1e-300)
        H = bs / path
        ft = f + k * (x[j] - x[j - 1])
        over = ft - b
        if abs(over) > r:
            d = 1.0 if over > 0.0 else -1.0
            Ht = max(H * (1.0 - d * b / bs), 0.0)
            dp = (over - d * r) / (k + Ht)
            ft -= k * dp
            b += H * dp - H / bs * b * abs(dp)
        f = ft
        out[j] = f
    return out


@on_fine_grid
def kinematic_hardening_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Presliding through a layer of asperity junctions that yield with nonlinear kinematic
    hardening, beside the bristle: a share w = min(:data:`LAYER_SHARE` ``s``, 1) of the
    friction is carried by a layer elastic with the bristle's stiffness sigma0 inside an
    elastic range of half-width r = :data:`ELASTIC_RANGE` G about its back-stress b, which
    grows with the slip towards +-(1 - :data:`ELASTIC_RANGE`) G over the hardening path
    lambda = the base bristle's path Fs / sigma0 plus ``s`` :data:`PRESLIDING_SHARE` x the
    stroke / 3 (Armstrong-Frederick, :func:`_hardening`); sliding, its force is the
    strength G, which follows the base's Stribeck level over a slip of
    :data:`LAYER_STRENGTH_RUN` lambda. After a reversal from sliding the layer unloads
    elastically over 2 r only, so it yields again while its force still has the old sign,
    and then hardens along exp(-p / lambda) to the other side. F = (1 - w) F_lugre + w (f
    + sigma2 v). At ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the layer's share (all of the friction from ``s`` = 1 /
        :data:`LAYER_SHARE` on) and its hardening path.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Nonlinear kinematic hardening (Armstrong and Frederick 1966, CEGB report RD/B/N731;
    Chaboche 1989) and the Bauschinger effect; frictional slip as plasticity with a
    hardening slip surface (Mroz and Stupkiewicz 1994, An anisotropic friction and wear
    model, IJSS 31; Mroz 2002). Maxwell-slip (the candidate, ``maxwell4``,
    ``maxwell10``) and the Mindlin contacts follow Masing's rule, Dahl, Bouc-Wen and
    Bliman-Sorine path laws (concave from the reversal, or overshooting), elasto-plastic
    an elastic range from the reversal to beyond zero, the Zener junction and the
    rate-and-state interface rate-dependent creep, the Tomlinson contacts multistable
    tips, the bonds elements born and broken and the gouge a fabric turned over; here the
    elastic range is carried by a back-stress: after a reversal it spans 2 r only, so
    the layer slips again before its force has changed sign, and the reversal's branch
    is the virgin curve's hardening doubled in force but not in path (not Masing's).
    """
    p = _lugre_params(kin, "gms (kinematic_hardening)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, PRESLIDING_SHARE)
    lam = e0 + extra
    w = min(LAYER_SHARE * float(s), 1.0)
    x = np.ascontiguousarray(kin.x, dtype=float)
    v = np.ascontiguousarray(kin.v, dtype=float)
    G = _strength(x, kin.base.g(v), LAYER_STRENGTH_RUN * lam)
    f = _hardening(x, G, float(p.sigma0), lam, ELASTIC_RANGE)
    return (1.0 - w) * F + w * (f + float(p.sigma2) * v)
