"""The seventh seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-28 (session 12), once, without running the diagnosis on it; run once,
sealed, at the end of session 13's work on the code of d12174d: 176 cases, top-1 25.0 % (44;
24.7 % of the detectable), mean |shrink error| 0.405, wrong names on 20 (11.4 %). Seen
since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen6` before it (figures in
``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen6`,
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
acceleration       ``motor_attraction``: an iron-core linear motor's magnets pull the
                   carriage onto its guides, and the armature current adds to that pull
                   as its square (Gieras and Piech 2000): the current of the thrust
                   m a + F raises the guides' levels above what the friction current
                   alone draws: up when accelerating, hardly (or down) when braking
load               ``plastic_junctions``: the real contact area grows plastically with
                   the load at once (Bowden and Tabor 1950) but recovers only
                   elastically when it falls, so the junctions keep the largest load
                   until sliding renews them (over a tenth of the record's travel): the
                   levels follow the load up at once and down with the travel
asymmetry          ``tilted_pad``: a fixed-incline slider pad (Reynolds 1886): sliding
                   into the converging gap (v > 0) drags oil into a load-carrying wedge,
                   the film thickens as sqrt(|v|) and the asperities are unloaded; the
                   other way the gap diverges and nothing lifts: the positive
                   direction's levels and viscous drag fall with the speed
stribeck_shape     ``rubber_hysteresis``: an elastomer seal's hysteresis friction
                   (Grosch 1963): the asperities excite the rubber at v / lambda and it
                   dissipates by its loss peak (broadened as Cole and Cole 1941): a hump
                   of the curve in the middle of the log-speed range, nothing at rest
position           ``end_cushion``: a hydraulic cylinder's end-position cushioning: past
                   the cushion's entry the outflow is throttled through a tapering gap
                   (an orifice, force ~ v^2 / area^2) while moving into the end, and
                   bypassed by a check valve coming out: a drag in one zone of the
                   stroke and one direction
inertia            ``rattling_mass``: a loose part in a pocket with rubber bumpers (an
                   impact damper, Masri and Caughey 1966): pressed against a bumper it
                   is a missed mass, it floats across the clearance when the
                   acceleration changes sign and lands on the other bumper
delay              ``pressure_line``: the force read as a pressure at the closed end of a
                   sensing line (Nichols 1962): the wave arrives after the line's
                   transit time and echoes between the transducer and the chamber,
                   attenuated by half per round trip: a transport delay with ringing
drift              ``tribo_oxide``: oxidational wear (Quinn 1962): an oxide film grows
                   on the contact plateaus parabolically in time and lowers the levels,
                   then spalls off at its critical thickness (twice in the record) and
                   the metal's levels return at once
backlash           ``biased_play``: a play whose contact is biased by a constant force
                   (a weight, a return spring) smaller than its friction: across the
                   play the contact holds the bias, so after both reversals the force
                   waits at the same level, the bias's, for the flank
gms                ``tomlinson_asperities``: an ensemble of asperity contacts pinned in
                   a corrugated potential (Prandtl 1928, Tomlinson 1929; Caroli and
                   Nozieres 1998) beside the LuGre bristle: each loads elastically on
                   its branch, snaps to the next at an elastic instability and drops
                   force; at ``s`` = 0 the base itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``rubber_hysteresis``
needs a Stribeck curve (not the isolator's mre_lugre), ``end_cushion`` a record that
revisits its positions (not the press), ``plastic_junctions`` a load that changes,
``biased_play`` and ``tomlinson_asperities`` a classic LuGre base (valve, damping rig,
XML-350); each raises a ``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.shapes import SHAPES, stribeck_g

from ..effects_backlash import PLANT_GAP_SHARE
from .kinematics import PlantKinematics
from .truths import (FIT_FRACTION, GAP_BIAS, MAX_DELAY_SAMPLES, _base_parts, _bump_centre,
                     _contact_constants, _driven_contact, _level, _lugre_params, _motion_time,
                     _presliding_path, _span, level_inside, on_fine_grid)

__all__ = ["FORMS", "motor_attraction_truth", "plastic_junctions_truth", "tilted_pad_truth",
           "rubber_hysteresis_truth", "end_cushion_truth", "rattling_mass_truth",
           "pressure_line_truth", "tribo_oxide_truth", "biased_play_truth",
           "tomlinson_asperities_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "motor_attraction", "load": "plastic_junctions",
         "asymmetry": "tilted_pad", "stribeck_shape": "rubber_hysteresis",
         "position": "end_cushion", "inertia": "rattling_mass", "delay": "pressure_line",
         "drift": "tribo_oxide", "backlash": "biased_play", "gms": "tomlinson_asperities"}


# -- acceleration ---------------------------------------------------------------------------
#: inertial thrust of ``motor_attraction``'s moving mass at the top acceleration, x the
#: 99th percentile of |friction| [-], and the attraction's share of the levels [-]
THRUST_MASS, ATTRACTION = 2.0, 0.1


@on_fine_grid
def motor_attraction_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """An iron-core linear motor's normal attraction loading the guides: the motor's
    current follows its thrust T = m a + F_f (the moving mass m, m a99 =
    :data:`THRUST_MASS` F99, F99 the 99th percentile of the base's |friction| F_f), up to
    the amplifier's current limit (a thrust of (:data:`THRUST_MASS` + 1) F99), and adds to
    the magnets' pull as its square; the base law, identified at steady speed, carries the
    pull of the friction current F_f alone. The Coulomb and Stribeck levels are the base's
    times 1 + ``s`` :data:`ATTRACTION` (T^2 - F_f^2) / F99^2 (floored at 0.05), inside the
    bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the levels' rise per unit of the relative squared thrust,
        / :data:`ATTRACTION`.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Normal (attraction) force of iron-core permanent-magnet linear synchronous motors,
    growing with the armature current (Gieras and Piech 2000, Linear Synchronous Motors);
    rolling-guide friction proportional to the normal load. The candidate is an odd,
    lagged function of a fading with |v|; the open forms lag the velocity or a state,
    heat the contact, skid rolling elements, move load between ball rows or press a seal
    with a lagged |a| (even in a). Here the pull goes with the square of the whole
    thrust: the acceleration's current adds to the friction's when accelerating
    (a v > 0) and takes from it when braking, so the levels rise far more in acceleration
    than in braking, instantly.
    """
    F, Ff = _base_parts(kin)
    F99 = max(float(np.percentile(np.abs(Ff), 99)), 1e-300)
    m = THRUST_MASS * F99 / max(kin.scales["a99"], 1e-12)
    # the amplifier's current limit: a speed step (the press's) asks for more than it gives
    lim = (THRUST_MASS + 1.0) * F99
    T = np.clip(m * np.asarray(kin.a, float) + Ff, -lim, lim)
    lev = np.clip(1.0 + s * ATTRACTION * (T * T - Ff * Ff) / (F99 * F99), 0.05, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- load -------------------------------------------------------------------------------------
#: travel over which ``plastic_junctions``' junctions are renewed, x the record's travel [-]
JUNCTION_RUN = 0.1


@njit(cache=True)
def _junction_load(x, L, run):
    """The load [N] the real contact area of plastic junctions corresponds to along the
    positions ``x`` [m] under the load ``L`` [N]: it rises with the load at once (plastic
    growth) and falls towards it only as the sliding renews the junctions, exponentially
    over the travel ``run`` [m]; starts at the first load."""
    n = x.size
    a = np.empty(n)
    c = L[0]
    for k in range(n):
        if k > 0:
            c = L[k] + (c - L[k]) * math.exp(-abs(x[k] - x[k - 1]) / run)
        if L[k] > c:
            c = L[k]
        a[k] = c
    return a


@on_fine_grid
def plastic_junctions_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Plastic junctions: the real contact area is the load over the hardness while the
    load rises (the area grows plastically at once), but an unloaded junction recovers only
    elastically and keeps its area until sliding replaces it; the area's load L_a follows L
    up at once and down exponentially over the travel :data:`JUNCTION_RUN` x the record's
    travel. The Coulomb and Stribeck levels are the base's times 1 + ``s`` 0.6 (L_a - mean
    L) / mean |L| (floored at 0.05), inside the bristle dynamics; the viscous term is the
    base's. ValueError if the load does not change.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], load [N]) and its base law.
    s : float
        Amplitude factor [-]: the levels' slope in the area's relative load, / 0.6.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Bowden and Tabor 1950 (real area of contact = load / hardness, plastic); elastic
    unloading of plastically formed contacts (Johnson 1985, Contact Mechanics); junctions
    renewed over a slip distance (Rabinowicz 1951). The candidate and the open forms are
    laws of the load (affine, a power, one direction, the Stribeck velocity, a threshold),
    of its rate, of a creep towards it in time or of a symmetric play; here the contact
    remembers the largest load until it has slid far enough: a one-sided memory erased by
    the travel, not by the clock.
    """
    L = np.ascontiguousarray(kin.load, dtype=float)
    L0 = max(float(np.mean(np.abs(L))), 1e-12)
    # a change below 1e-6 of the mean load over the record is round-off, not a change
    if float(np.ptp(L)) <= 1e-6 * L0:
        raise ValueError(f"load (plastic_junctions): the {kin.plant} record's load does "
                         f"not change")
    x = np.ascontiguousarray(kin.x, dtype=float)
    travel = max(float(np.sum(np.abs(np.diff(x)))), 1e-300)
    La = _junction_load(x, L, JUNCTION_RUN * travel)
    lev = np.clip(1.0 + s * 0.6 * (La - float(np.mean(L))) / L0, 0.05, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: speed at which ``tilted_pad``'s wedge, at strength 1, carries as much load as the
#: asperities, x v99 [-]
LIFT_SPEED = 0.3


@on_fine_grid
def tilted_pad_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A fixed-incline slider pad: sliding towards the converging gap (v > 0) the pad drags
    oil into a wedge that carries load, the film's thickness grows as h / h0 = sqrt(1 +
    q), q = ``s`` n(v) |v| / (:data:`LIFT_SPEED` v99), n(v) a smooth indicator of v > 0
    (over 2 % of v99); the other way the gap diverges, the film cavitates and nothing
    lifts. The asperities' share of the load falls as (h0 / h)^2: the Coulomb and Stribeck
    levels are the base's times 1 / (1 + q); the film's shear as h0 / h: the viscous term
    the base's times 1 / sqrt(1 + q); inside the bristle dynamics.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the wedge's load capacity relative to its value at strength
        1 (the pad's tilt).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Reynolds 1886 (the inclined slider: load capacity only for a converging film);
    Hamrock, Schmid and Jacobson 2004 (Fundamentals of Fluid Film Lubrication: film
    thickness of a slider ~ sqrt(eta U / W)). The candidate shifts a direction's levels
    and viscous slope (and an offset); the open forms keep a direction's share at all
    speeds, move its Stribeck velocity or viscous slope, add a low-speed tail, follow a
    lip, a thrust, a film laid by the outstroke, a texture fading with the speed or a
    spring along the stroke; here one direction's levels fall as a film lifts the pad,
    more the faster it slides, and its viscous drag falls with them.
    """
    v99 = max(kin.scales["v99"], 1e-12)
    v = np.asarray(kin.v, float)
    pos = 0.5 * (1.0 + np.tanh(v / (0.02 * v99)))
    q = max(float(s), 0.0) * pos * np.abs(v) / (LIFT_SPEED * v99)
    return level_inside(kin, 1.0 / (1.0 + q), 1.0 / np.sqrt(1.0 + q))


# -- stribeck_shape --------------------------------------------------------------------------
#: speed of ``rubber_hysteresis``' loss peak, x v99 [-], and the breadth of the rubber's
#: relaxation spectrum (Cole-Cole exponent, 1: one relaxation time) [-]
LOSS_PEAK_SPEED, LOSS_BREADTH = 0.1, 0.7


@on_fine_grid
def rubber_hysteresis_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Hysteresis friction of an elastomer (a seal or wiper on the rail): its asperities
    excite the rubber at the frequency |v| / lambda, and the rubber dissipates by its loss
    peak at v_p = :data:`LOSS_PEAK_SPEED` v99, broadened by a spectrum of relaxation times
    (u = |v| / v_p, Cole-Cole exponent beta = :data:`LOSS_BREADTH`): the curve gains ``s``
    x 0.4 Fc 2 u^beta / (1 + u^(2 beta)), 0 at rest and at the highest speeds, most at
    v_p, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (a Stribeck curve).
    s : float
        Amplitude factor [-]: the hump's height at v_p, x 0.4 Fc.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Grosch 1963 (rubber friction: a maximum over log speed that follows the rubber's loss
    modulus, shifted by Williams-Landel-Ferry); Persson 2001 (hysteretic friction of rubber
    on rough surfaces); Cole and Cole 1941 (a broadened relaxation peak). The candidate
    bends the base's drop (an exponent, the Lorentzian, a log-speed map); the open forms
    add tails, drops, a spike, a lift-off, a second drop, a logarithmic weakening, an
    Eyring strengthening or a rise at the top speed; this one is a hump in the middle of
    the speed range, with nothing at rest and a fall beyond it.
    """
    if kin.base.name == "mre_lugre":
        raise ValueError("stribeck_shape (rubber_hysteresis): the mre_lugre base has no "
                         "Stribeck curve")
    p = kin.base.params
    v = np.asarray(kin.v, float)
    ub = (np.abs(v) / (LOSS_PEAK_SPEED * max(kin.scales["v99"], 1e-12))) ** LOSS_BREADTH
    extra = 0.4 * float(p.Fc) * 2.0 * ub / (1.0 + ub * ub)
    return level_inside(kin, 1.0 + s * extra / kin.base.g(v), np.ones_like(v))


# -- position --------------------------------------------------------------------------------
#: where ``end_cushion``'s spear enters: this percentile of the held-out positions the fit
#: part also visits [%]; its throttle's area closes by this share at the stroke's end [-];
#: the drag at v99 at the entry, x the friction level [-]
CUSHION_ENTRY, CUSHION_TAPER, CUSHION_FORCE = 75.0, 0.8, 0.5


@on_fine_grid
def end_cushion_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Hydraulic end-position cushioning at the upper end of the stroke: from the entry
    x_c (the :data:`CUSHION_ENTRY` th percentile of the held-out positions the fit part
    also visits, so both see it) to the stroke's end x_e, the outflow passes a throttle
    whose area tapers to 1 - :data:`CUSHION_TAPER` of its entry value (u = (x - x_c) /
    (x_e - x_c)); moving into the end (v > 0) the orifice's pressure drop adds ``s`` x
    :data:`CUSHION_FORCE` x the friction level x (v / v99)^2 / (1 - :data:`CUSHION_TAPER`
    u)^2 to the force (the spear's chamfer rounds the entry over 2 % of the stroke, the
    direction over 2 % of v99); moving out a check valve bypasses the throttle.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the cushion's drag relative to :data:`CUSHION_FORCE` x the
        level at v99 at the entry.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    End-position cushioning of hydraulic cylinders (a cushion spear entering a bore,
    progressive throttling, a check valve for the return stroke: ISO 6020/6022 cylinder
    designs; orifice flow, Merritt 1967, Hydraulic Control Systems). The candidate scales
    the friction along the stroke (a map, a waviness, a defect) and adds a periodic force
    of x; the open forms are level maps (a defect, waviness, a worn section, runout, a bow,
    a transfer film, a taper, a port's wake) or a detent force; here a fluid drag acts in
    one zone of the stroke and one direction, quadratic in the speed and steeper towards
    the end.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (end_cushion): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    x = np.asarray(kin.x, float)
    m = int(round(FIT_FRACTION * x.size))
    xf, xh = x[:m], x[m:]
    inside = xh[(xh >= xf.min()) & (xh <= xf.max())]
    xc = float(np.percentile(inside, CUSHION_ENTRY))
    xe = max(float(np.max(x)), xc + 1e-3 * _span(kin))
    span = _span(kin)
    v99 = max(kin.scales["v99"], 1e-12)
    v = np.asarray(kin.v, float)
    u = np.clip((x - xc) / (xe - xc), 0.0, 1.0)
    entry = 0.5 * (1.0 + np.tanh((x - xc) / (0.02 * span)))
    into = 0.5 * (1.0 + np.tanh(v / (0.02 * v99)))
    drag = entry * into * (v / v99) ** 2 / (1.0 - CUSHION_TAPER * u) ** 2
    F, _ = _base_parts(kin)
    return F + s * CUSHION_FORCE * _level(kin) * drag


# -- inertia ---------------------------------------------------------------------------------
#: ``rattling_mass``'s clearance (half-width), x the stroke [-]; its bumpers' natural
#: frequency with the part, x 1 / the motion's time scale [-], and their damping ratio [-]
CLEARANCE, BUMPER_FREQ, BUMPER_DAMPING = 0.01, 10.0, 0.5


@njit(cache=True)
def _rattle(t, x, v, half, w, zeta, n_sub):
    """Force per unit mass [m/s^2] the carriage (positions ``x`` [m], velocities ``v``
    [m/s] at the times ``t`` [s]) exerts on a loose part in a pocket of half-clearance
    ``half`` [m] lined with bumpers (spring-dampers of natural frequency ``w`` [rad/s] and
    damping ratio ``zeta`` with the part, compressive only): semi-implicit Euler on
    ``n_sub`` sub-steps per step, the carriage's motion linear between the points. Starts
    centred, moving with the carriage."""
    n = t.size
    f = np.empty(n)
    y = x[0]
    u = v[0]
    k = w * w
    c = 2.0 * zeta * w
    f[0] = 0.0
    for j in range(1, n):
        h = (t[j] - t[j - 1]) / n_sub
        acc = 0.0
        for i in range(1, n_sub + 1):
            r = i / n_sub
            xc = x[j - 1] + r * (x[j] - x[j - 1])
            vc = v[j - 1] + r * (v[j] - v[j - 1])
            e = y - xc
            ed = u - vc
            acc = 0.0
            if e > half:
                acc = -k * (e - half) - c * ed
                if acc > 0.0:
                    acc = 0.0
            elif e < -half:
                acc = k * (-e - half) - c * ed
                if acc < 0.0:
                    acc = 0.0
            u += h * acc
            y += h * u
        f[j] = acc
    return f


@on_fine_grid
def rattling_mass_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A loose part in a pocket of the carriage (an impact damper): its clearance is +-
    :data:`CLEARANCE` x the stroke, its bumpers rubber (natural frequency
    :data:`BUMPER_FREQ` / the motion's time scale with the part, damping ratio
    :data:`BUMPER_DAMPING`, compressive only). Pressed against a bumper the part is a mass
    the inverse dynamics misses; when the acceleration changes sign it floats across the
    clearance (no force) and lands on the other bumper (a damped impact). The measured
    force is the base's plus the force on the part, m = ``s`` x 0.3 x the friction level /
    a99 [kg]. At ``s`` = 0 the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the part's mass relative to 0.3 x level / a99.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Impact dampers (Masri and Caughey 1966, a mass in a container with clearance);
    loose parts and tools rattling in pockets of fast axes. The candidate and the open
    forms are masses (constant, filtered, along the stroke, through a ratio or a lossy
    gear, in time, behind a spring, in a fluid) or a payload held by friction; here the
    part is held by nothing: it is missed in full while it leans on a bumper, not at all
    while it crosses the clearance, and its landing is an impact.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    m = s * 0.3 * _level(kin) / max(kin.scales["a99"], 1e-12)
    w = BUMPER_FREQ / _motion_time(kin)
    # sub-steps resolve the bumpers' contact (at most a tenth of a radian a step)
    n_sub = int(min(max(math.ceil(w * kin.dt / 0.1), 1), 400))
    f = _rattle(np.ascontiguousarray(kin.t, dtype=float),
                np.ascontiguousarray(kin.x, dtype=float),
                np.ascontiguousarray(kin.v, dtype=float),
                CLEARANCE * _span(kin), w, BUMPER_DAMPING, n_sub)
    return F + m * f


# -- delay -----------------------------------------------------------------------------------
#: the echoes' amplitude ratio per round trip of ``pressure_line`` [-] and the echoes kept
LINE_REFLECTION, LINE_ECHOES = 0.5, 24


@on_fine_grid
def pressure_line_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force read as a pressure at the closed end of a sensing line: the wave arrives
    after the line's transit time T and reflects between the transducer (closed: +1) and
    the chamber (a large volume: -1), attenuated by :data:`LINE_REFLECTION` = r per round
    trip: y(t) = sum_k w_k F(t - (2k + 1) T), w_k ~ (-r)^k normalised to a static gain of
    1 (:data:`LINE_ECHOES` echoes kept), whose low-frequency delay is T (1 - r) / (1 + r)
    = ``s`` data samples (at most :data:`.truths.MAX_DELAY_SAMPLES`); cubic-spline shifts.
    At ``s`` = 0 the force itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the low-frequency delay [data samples].

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Dynamics of fluid transmission lines (Nichols 1962; Stecki and Davis 1986): a
    transport delay at the speed of sound and standing waves between the line's ends,
    whose friction damps them (lumped here in r). The open forms delay by one amount (a
    shift, held samples), filter (a lag, Bessel, a moving average, a converter's FIR), let
    the delay drift, wander or grow with the rate, or shift the motion; here the force
    comes late and echoes: a comb of delayed copies of alternating sign.
    """
    from scipy.interpolate import CubicSpline
    F, _ = _base_parts(kin)
    d = min(max(float(s), 0.0), MAX_DELAY_SAMPLES)
    if d <= 0.0:
        return F
    r = LINE_REFLECTION
    T = d * (1.0 + r) / (1.0 - r) * kin.sample_dt
    w = (-r) ** np.arange(LINE_ECHOES + 1)
    w = w / w.sum()
    t = np.asarray(kin.t, float)
    spline = CubicSpline(t, F)
    return sum(wk * spline(np.clip(t - (2 * k + 1) * T, t[0], None))
               for k, wk in enumerate(w))


# -- drift -----------------------------------------------------------------------------------
#: ``tribo_oxide``'s spalling period, x the record [-], and the time its spalling is
#: rounded over, x the record [-]
SPALL_PERIOD, SPALL_ROUNDING = 0.45, 0.003


@on_fine_grid
def tribo_oxide_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Oxidational wear: an oxide film grows on the contact plateaus parabolically in time,
    thickness xi / xi_c = sqrt(tau / P) (tau the time since the last spall, P =
    :data:`SPALL_PERIOD` x the record T), and lowers the levels; at its critical thickness
    xi_c it spalls off, twice in the record, and the metal's levels return at once
    (rounded over :data:`SPALL_ROUNDING` T). The Coulomb and Stribeck levels are the base's
    times 1 - ``s`` 0.4 xi / xi_c (floored at 0.05), inside the bristle dynamics; the
    viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the relative level drop at the critical thickness, / 0.4.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Quinn 1962, 1983 (oxidational wear: parabolic oxide growth on the plateaus and
    breakaway at a critical thickness of a few micrometres); oxide films lowering
    metal-metal friction (Bowden and Tabor 1964). The candidate is a trend, a saturating
    change and a step; the open forms warm up, wear in linearly or with the load and
    travel, step, heat with the friction power, cycle with the humidity, rise and fall
    with debris, drop with grease shots or relax in log time; here the levels fall as the
    square root of the time, then jump back, twice.
    """
    from scipy.ndimage import gaussian_filter1d
    t = np.asarray(kin.t, float)
    T = float(t[-1] - t[0]) or 1.0
    phase = (t - t[0]) / (SPALL_PERIOD * T)
    xi = np.sqrt(phase - np.floor(phase))
    # a spall in one fine step would be a jump no sampled record resolves: rounded over
    # SPALL_ROUNDING x the record (the record's ends mirrored)
    xi = gaussian_filter1d(xi, SPALL_ROUNDING * (t.size - 1), mode="mirror")
    lev = np.clip(1.0 - s * 0.4 * xi, 0.05, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: the play of ``biased_play`` at strength 1, as a share of the stroke [-] (the open
#: backlash forms'), and the bias force on the contact, x its Coulomb level, towards -x [-]
GAP_SHARE, BIAS = PLANT_GAP_SHARE, 0.5


def _biased_contact(h, xd, half, bias, m, kh, ch, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a contact of mass ``m`` [kg] on which a constant force ``bias``
    [N] acts, driven by the drive positions ``xd`` [m] (grid step ``h`` [s]) across a play
    of half-width ``half`` [m], the flanks a spring ``kh`` [N/m] and damper ``ch`` [N s/m]
    (compressive only); nothing else bridges the play: the open forms' driven contact
    (:func:`.truths._driven_contact`, ``GAP_BIAS``). Starts centred in the play, at rest,
    its bristle unloaded (the bias then loads it, or the flanks where there is no play)."""
    return _driven_contact(h, xd, half, GAP_BIAS, bias, 0.0, m, kh, ch, s0, s1, s2, Fc, Fs,
                           vs, alpha, shape)


@on_fine_grid
def biased_play_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A play of width ``s``^2 x :data:`GAP_SHARE` x the stroke between the drive (the
    record's motion) and a light contact with the base's LuGre friction (its inertial force
    at the top acceleration 1 % of the Coulomb level, :func:`.truths._contact_constants`),
    on which a constant bias acts: :data:`BIAS` Fc towards -x (a weight on an inclined
    axis, a return spring), less than the contact's friction, so it cannot move the
    contact. Across the play the contact stands still holding the bias; the flanks a
    coupling 100 x stiffer than the bristle, damping ratio 0.5. The measured force is the
    contact's friction. At ``s`` = 0 the contact follows the drive (the base, up to the
    stiff coupling).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the square root of the play's width relative to
        :data:`GAP_SHARE` x the stroke (the contact waits across the play for a time that
        grows as the play's square root at a smooth reversal, so a size growing about
        linearly with the width would follow ``s`` too weakly to be calibrated on the
        XML-350's many small reversals).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Backlash under a bias torque or force (gravity-loaded and spring-preloaded drives:
    Nordin and Gutman 2002, controlling mechanical systems with backlash - a survey): a
    bias larger than the friction keeps one flank engaged, a smaller one only sets what
    the contact holds across the play. The candidate holds or frees the force across the
    play; the open forms couple it rigidly, compliantly, by impacts, a spring, an oil
    film, an idler's drag, with a play varying with the position or growing with the
    travel: each plateau or ramp follows the direction of the drive. Here both reversals
    wait at the same level, the bias's: after a reversal to -x the force falls only part
    of the way, after one to +x it rises only part of the way.
    """
    p = _lugre_params(kin, "backlash (biased_play)")
    half = 0.5 * GAP_SHARE * max(float(s), 0.0) ** 2 * float(np.ptp(kin.x))
    m, kh, ch = _contact_constants(kin, p)
    rate = max(math.sqrt(kh / m), (float(p.sigma1) + float(p.sigma2) + ch) / m)
    n_sub = int(min(max(math.ceil(rate * kin.dt / 0.3), 4), 400))
    t2 = kin.t[0] + (kin.dt / n_sub) * np.arange((kin.t.size - 1) * n_sub + 1)
    xd = np.interp(t2, kin.t, kin.x)
    F = _biased_contact(kin.dt / n_sub, xd, half, -BIAS * float(p.Fc), m, kh, ch,
                        float(p.sigma0), float(p.sigma1), float(p.sigma2), float(p.Fc),
                        float(p.Fs), float(p.vs), float(p.alpha), SHAPES[p.shape])
    return F[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: period of ``tomlinson_asperities``' corrugation at strength 1 beyond the base bristle's
#: path, as a share of the stroke / 3 [-]; the asperities' share of the friction at
#: strength 1 [-]; their count [-]; the Tomlinson parameter eta = 2 pi F0 / (k lambda),
#: > 1 for elastic instabilities [-]
PRESLIDING_SHARE, PT_SHARE, PT_CONTACTS, PT_ETA = 0.02, 0.5, 256, 3.0
#: slip over which the contacts' strength follows the Stribeck level, x the period [-]
PT_STRENGTH_RUN = 0.1


#: points of the table of a Prandtl-Tomlinson branch's force [-]
PT_TABLE = 20001


def _tomlinson_branch(eta: float, n: int = PT_TABLE):
    """A stable Prandtl-Tomlinson branch tabulated evenly in q = u + eta sin u on (-q_max,
    q_max), its ends where 1 + eta cos u = 0: (q_max [-], sin u at the points [-])."""
    us = math.acos(-1.0 / eta)
    qmax = us + eta * math.sin(us)
    u = np.linspace(-us, us, 40 * n)
    q = u + eta * np.sin(u)
    return qmax, np.interp(np.linspace(-qmax, qmax, n), q, np.sin(u))


@njit(cache=True)
def _tomlinson(x, lam, phases, qmax, table):
    """Mean relative force [-] (sin u, F0 = 1) of Prandtl-Tomlinson contacts along the
    drive positions ``x`` [m]: each a tip on a spring in the potential of period ``lam``
    [m] shifted by its phase (``phases`` [m]), quasi-static (overdamped, slow drive): it
    stays on its stable branch, 2 pi (x - phase) / lam - 2 pi n = q = u + eta sin u with
    1 + eta cos u > 0 (|q| < ``qmax``; sin u of q tabulated evenly in ``table``), and
    snaps to the neighbouring branch where its branch ends (an elastic instability).
    Starts each on the branch nearest to its unloaded position."""
    n = x.size
    nc = phases.size
    m = table.size - 1
    scale = m / (2.0 * qmax)
    out = np.zeros(n)
    br = np.empty(nc, dtype=np.int64)
    for i in range(nc):
        br[i] = int(round((x[0] - phases[i]) / lam))
    two_pi = 2.0 * math.pi
    for k in range(n):
        acc = 0.0
        for i in range(nc):
            q = two_pi * ((x[k] - phases[i]) / lam - br[i])
            while q > qmax:
                br[i] += 1
                q -= two_pi
            while q < -qmax:
                br[i] -= 1
                q += two_pi
            r = (q + qmax) * scale
            j = min(int(r), m - 1)
            acc += table[j] + (r - j) * (table[j + 1] - table[j])
        out[k] = acc / nc
    return out


@njit(cache=True)
def _strength(x, g, run):
    """A strength [N] that follows the levels ``g`` [N] over the slip ``run`` [m] along the
    positions ``x`` [m] (exact for a level held over each step; it does not move while the
    contact stands still); starts at the first level."""
    n = x.size
    out = np.empty(n)
    c = g[0]
    for k in range(n):
        if k > 0:
            c = g[k] + (c - g[k]) * math.exp(-abs(x[k] - x[k - 1]) / run)
        out[k] = c
    return out


def _tomlinson_sliding_mean(eta: float) -> float:
    """Mean relative force [-] of the Prandtl-Tomlinson contacts while sliding steadily one
    way (phases uniform): (1 / 2 pi) [-cos u + eta sin(u)^2 / 2] from the landing point
    after a snap to the branch's end."""
    from scipy.optimize import brentq
    us = math.acos(-1.0 / eta)
    qmax = us + eta * math.sin(us)
    ua = brentq(lambda u: u + eta * math.sin(u) - (qmax - 2.0 * math.pi), -us, us)

    def prim(u):
        return -math.cos(u) + 0.5 * eta * math.sin(u) ** 2
    return (prim(us) - prim(ua)) / (2.0 * math.pi)


@on_fine_grid
def tomlinson_asperities_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Presliding by elastic instabilities of pinned asperities beside the bristle: a share
    w = min(:data:`PT_SHARE` ``s``, 1) of the friction is carried by
    :data:`PT_CONTACTS` Prandtl-Tomlinson contacts (each a spring and a tip in a
    corrugated potential of period lambda = the base bristle's path Fs / sigma0 plus ``s``
    x :data:`PRESLIDING_SHARE` x the stroke / 3, phases spread evenly over it, eta =
    :data:`PT_ETA`): each loads elastically along its stable branch and snaps to the next
    where the branch ends, dropping force. Their mean force f, divided by its value in
    steady sliding, is scaled by their strength G, which follows the base's Stribeck level
    g(v) over a slip of :data:`PT_STRENGTH_RUN` lambda (as a bristle's deflection does: a
    reversal, where g(v) jumps to the static level, moves nothing), plus the viscous term;
    the rest by the base's LuGre: F = (1 - w) F_lugre + w (G f + sigma2 v). At ``s`` = 0
    the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the contacts' share (all of the friction from ``s`` = 1 /
        :data:`PT_SHARE` on) and the corrugation's period.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Prandtl 1928, Tomlinson 1929 (a tip on a spring in a periodic potential: friction by
    elastic instabilities); Caroli and Nozieres 1998 (macroscopic dry friction and its
    hysteresis from multistable micro-asperities). Maxwell-slip (the candidate,
    ``maxwell4``, ``maxwell10``) and the Mindlin contacts are elasto-plastic elements that
    slip holding their force (Masing's rule), Dahl, Bouc-Wen and Bliman-Sorine smooth
    path laws, elasto-plastic an elastic range, the Zener junction and the rate-and-state
    interface rate-dependent creep; here each element is multistable: it has several
    elastic states at one position, loads non-linearly and loses force when it snaps.
    """
    p = _lugre_params(kin, "gms (tomlinson_asperities)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, PRESLIDING_SHARE)
    lam = e0 + extra
    w = min(PT_SHARE * float(s), 1.0)
    v = np.ascontiguousarray(kin.v, dtype=float)
    phases = lam * (np.arange(PT_CONTACTS) + 0.5) / PT_CONTACTS
    qmax, table = _tomlinson_branch(PT_ETA)
    f = _tomlinson(np.ascontiguousarray(kin.x, dtype=float), lam, phases, qmax, table)
    f = f / _tomlinson_sliding_mean(PT_ETA)
    G = _strength(np.ascontiguousarray(kin.x, dtype=float), kin.base.g(v),
                  PT_STRENGTH_RUN * lam)
    return (1.0 - w) * F + w * (G * f + float(p.sigma2) * v)
