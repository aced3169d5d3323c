"""The sixth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-28 (session 11, end), once, without running the diagnosis on it; run once,
sealed, at the end of session 12's work on the code of 9155e51: 176 cases, top-1 46.6 % (82;
47.1 % of the detectable), mean |shrink error| 0.332, wrong names on 29 (16.5 %). Seen
since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen5` before it (figures in
``benchmarks/bench_diagnosis_forms.py``). Each form is a mechanism of other physics than
every open form of its effect before it (:mod:`.truths`, :mod:`.forms`, :mod:`.seen` to
:mod:`.seen5`,
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
acceleration       ``cylinder_pressure``: a hydraulic cylinder's seals: the chamber
                   pressure that accelerates the load builds up through the oil's
                   compressibility (a lag) and presses the pressurised side's seal
                   harder (Yanada and Sekikawa 2008): the levels rise with the lagged
                   |a|, linearly, in acceleration and braking alike
load               ``pivot_lever``: the normal load reaches the contact through a lever
                   with its own compliance and Coulomb friction in its pivot (a Jenkin
                   element): the contact's load is a play (hysteresis) operator of the
                   applied load, 15 % of its range wide; the levels are affine in it
asymmetry          ``spring_return``: a single-acting cylinder with a preloaded return
                   spring: extending (v > 0) the chamber pressure holds the spring and
                   presses the seal, retracting the spring drives and the chamber is
                   vented: the positive direction's levels rise, more as the spring is
                   compressed along the stroke
stribeck_shape     ``starved_film``: inlet starvation at speed (Wedeven, Evans and Cameron
                   1971; Chevalier et al. 1998): above 40 % of the top speed the track is
                   not replenished, the film thins and the asperities carry load again:
                   the boundary level rises again, quadratically, at high speed
position           ``oil_pocket``: a lubrication port in the rail: the slider picks up oil
                   where it crosses the port and loses it over 15 % of the stroke it then
                   travels, so the levels are lowest just past the port, in the direction
                   of travel (a wake, not a function of x alone)
inertia            ``sliding_payload``: a loose part on the carriage (a workpiece on a
                   pallet): it moves with the carriage (a missed mass) while |a| stays
                   below what its friction holds (0.5 a99), slides beyond, and the
                   carriage then feels only that friction (block on a cart, Coulomb)
delay              ``slew_limit``: the force amplifier's finite slew rate with its
                   single-pole bandwidth (operational amplifiers: slew rate and
                   gain-bandwidth): slow changes lag a little, fast ones (the reversals)
                   are followed at the slew rate: a delay that grows with |dF/dt|
drift              ``seal_relaxation``: the elastomer seal's contact force relaxes after
                   fitting (physical stress relaxation of rubber, linear in log time,
                   Gent 1962): the levels fall as log(1 + t / tau0), tau0 1 % of the
                   record: fast at first, still falling at the end
backlash           ``drag_idler``: a play bridged by a friction-loaded idler (a slip-clutch
                   anti-backlash gear, Michalec 1966): across the play the drive drags
                   the contact with a Coulomb force of half its Coulomb level, so the
                   force holds a plateau there instead of holding, dropping, ramping or
                   following the closing speed
gms                ``rate_state_presliding``: an elastic asperity layer in series with a
                   rate-and-state interface (Dieterich 1979, Ruina 1983, regularised as
                   Rice et al. 2001, aging law) beside the LuGre bristle: presliding as
                   thermally activated creep, so the yield grows with the log of the rate
                   and with the time held; at ``s`` = 0 the base itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``starved_film`` needs a
Stribeck curve (not the isolator's mre_lugre), ``oil_pocket`` a record that revisits its
positions (not the press), ``pivot_lever`` a load that changes, ``drag_idler`` and
``rate_state_presliding`` a classic LuGre base (valve, damping rig, XML-350); each raises a
``ValueError`` elsewhere.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..effects_backlash import PLANT_GAP_SHARE, _play
from .kinematics import PlantKinematics
from .truths import (GAP_DRAG, MAX_DELAY_SAMPLES, _base_parts, _bump_centre,
                     _contact_constants, _lag, _level, _lugre_params, _motion_time,
                     _presliding_path, _run_driven_contact, _smooth_max0, _span,
                     level_inside, on_fine_grid)

__all__ = ["cylinder_pressure_truth", "pivot_lever_truth", "spring_return_truth",
           "starved_film_truth", "oil_pocket_truth", "sliding_payload_truth",
           "slew_limit_truth", "seal_relaxation_truth", "drag_idler_truth",
           "rate_state_presliding_truth"]


# -- acceleration ---------------------------------------------------------------------------
#: time constant of ``cylinder_pressure``'s pressure build-up, x the motion's time scale [-]
PRESSURE_LAG = 0.05


@on_fine_grid
def cylinder_pressure_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A hydraulic cylinder's seals loaded by the pressure that accelerates the load: the
    chamber pressure difference p follows the force demand m a through the oil's
    compressibility (a first-order lag over :data:`PRESSURE_LAG` x the motion's time
    scale), and the pressurised side's seal presses harder by it: the Coulomb and Stribeck
    levels are the base's times 1 + ``s`` 0.5 |p| / a99 (|p| rounded over 2 % of a99),
    inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the relative level rise at the top acceleration, / 0.5.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Seal friction of hydraulic cylinders rising with the chamber pressure (Yanada and
    Sekikawa 2008; Bonchis, Corke and Rye 2002). The open forms lag the velocity or a
    state over a slip distance, age the contact, heat it, skid rolling elements or move
    load between ball rows (instantaneous); here a fluid pressure, linear in |a| and
    lagged by the oil's compliance, loads a seal.
    """
    a99 = max(kin.scales["a99"], 1e-12)
    p = _lag(kin.t, np.asarray(kin.a, float), PRESSURE_LAG * _motion_time(kin))
    # |p| rounded over eps, 0 at p = 0 (measured signals never switch in one sample)
    eps = 0.02 * a99
    lev = 1.0 + s * 0.5 * (_smooth_max0(p, eps) + _smooth_max0(-p, eps) - eps) / a99
    return level_inside(kin, lev, np.ones_like(lev))


# -- load -------------------------------------------------------------------------------------
#: width of ``pivot_lever``'s play on the load, x the load's range [-]
LEVER_PLAY = 0.15


@on_fine_grid
def pivot_lever_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The normal load applied through a lever with its own compliance and Coulomb friction
    in its pivot (a Jenkin element): the lever does not move until the load change
    overcomes the pivot's friction, so the contact's load L_c is a play operator of the
    applied load L (half-width :data:`LEVER_PLAY` / 2 x the load's range, centred at the
    start); the Coulomb and Stribeck levels are the base's times 1 + ``s`` 0.6 (L_c - mean
    L) / mean L, inside the bristle dynamics; the viscous term is the base's. ValueError if
    the load does not change.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (load [N]) and its base law.
    s : float
        Amplitude factor [-]: the levels' slope in the contact's relative load, / 0.6.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    A spring in series with a Coulomb slider transmits a play (backlash) operator of its
    input (Krasnosel'skii and Pokrovskii 1989); brake and clamp levers with pivot friction.
    The open forms are laws of the load (affine, a power, one direction, the Stribeck
    velocity, a threshold), of its rate or a creep towards it; here the load seen by the
    contact has a hysteresis (it depends on whether the load last rose or fell).
    """
    L = np.ascontiguousarray(kin.load, dtype=float)
    L0 = max(float(np.mean(np.abs(L))), 1e-12)
    # a change below 1e-6 of the mean load over the record is round-off, not a change
    if float(np.ptp(L)) <= 1e-6 * L0:
        raise ValueError(f"load (pivot_lever): the {kin.plant} record's load does not "
                         f"change")
    Lc = _play(L, 0.5 * LEVER_PLAY * float(np.ptp(L)))
    lev = np.clip(1.0 + s * 0.6 * (Lc - float(np.mean(L))) / L0, 0.05, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: share of ``spring_return``'s spring force at the stroke's start (its preload) [-]
SPRING_PRELOAD = 0.5


@on_fine_grid
def spring_return_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A single-acting cylinder with a preloaded return spring: extending (v > 0) the
    chamber pressure holds the spring, :data:`SPRING_PRELOAD` + (1 - :data:`SPRING_PRELOAD`)
    u of its force at the stroke's end (u = (x - x_lo) / stroke in [0, 1]), and presses
    the seal; retracting, the spring drives and the chamber is vented. The Coulomb and
    Stribeck levels are the base's times 1 + ``s`` 0.5 n(v) (that spring share), n(v) a
    smooth indicator of v > 0 (over 2 % of v99), inside the bristle dynamics; the viscous
    term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the positive direction's relative level rise at the stroke's
        end, / 0.5.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Spring-return pneumatic and hydraulic cylinders and valve actuators; seal friction
    rising with the pressure (Belforte, Mattiazzo, Mauro and Tokashiki 2003). The open
    forms keep a direction's share at all positions, move its Stribeck velocity or viscous
    slope, follow a lip, a thrust, a film or a texture fading with the speed; here the
    loaded direction's rise grows along the stroke.
    """
    v99 = max(kin.scales["v99"], 1e-12)
    pos = 0.5 * (1.0 + np.tanh(np.asarray(kin.v, float) / (0.02 * v99)))
    u = np.clip((np.asarray(kin.x, float) - kin.scales["x_lo"]) / _span(kin), 0.0, 1.0)
    lev = 1.0 + s * 0.5 * pos * (SPRING_PRELOAD + (1.0 - SPRING_PRELOAD) * u)
    return level_inside(kin, lev, np.ones_like(lev))


# -- stribeck_shape --------------------------------------------------------------------------
#: speed above which ``starved_film``'s track starves, x v99 [-]
STARVATION_SPEED = 0.4


@on_fine_grid
def starved_film_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Inlet starvation at speed: above v_st = :data:`STARVATION_SPEED` v99 the lubricant
    pushed aside is not replenished before the contact returns, the film thins and the
    asperities carry load again: the curve gains ``s`` x 0.4 Fc ((|v| - v_st) / (v99 -
    v_st))^2 above v_st (rounded over 2 % of that range), inside the bristle dynamics; the
    viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (a Stribeck curve).
    s : float
        Amplitude factor [-]: the rise at the top speed, x 0.4 Fc.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Wedeven, Evans and Cameron 1971 (starvation of elastohydrodynamic contacts); Chevalier,
    Lubrecht, Cann, Colin and Dalmaz 1998 (film decay under starvation). The candidate
    bends the base's drop; the open forms add tails, drops, a spike, a lift-off, a second
    drop, a logarithmic weakening or an Eyring strengthening from rest; this one leaves
    the low speeds alone and turns the curve up again at the top of the speed range.
    """
    if kin.base.name == "mre_lugre":
        raise ValueError("stribeck_shape (starved_film): the mre_lugre base has no "
                         "Stribeck curve")
    p = kin.base.params
    v99 = max(kin.scales["v99"], 1e-12)
    vst = STARVATION_SPEED * v99
    v = kin.v
    q = (np.abs(v) - vst) / (v99 - vst)
    # the square of a rounded ramp: smooth through v_st, 1 (up to the rounding) at v99
    extra = 0.4 * float(p.Fc) * _smooth_max0(q, 0.02) ** 2
    return level_inside(kin, 1.0 + s * extra / kin.base.g(v), np.ones_like(v))


# -- position --------------------------------------------------------------------------------
#: ``oil_pocket``'s port half-width, the distance its oil is lost over and the distance a
#: crossing refills it over, x the stroke [-]
PORT_HALF, OIL_RUN, OIL_FILL = 0.02, 0.15, 0.005


@njit(cache=True)
def _carried_oil(x, xc, half, run, fill):
    """Share of a full film [-] the slider carries along the positions ``x`` [m]: it fills
    towards 1 over the travel ``fill`` [m] while within ``half`` [m] of the port ``xc``
    [m], and is lost over the travel ``run`` [m] elsewhere; starts dry."""
    n = x.size
    h = np.empty(n)
    c = 0.0
    for k in range(n):
        if k > 0:
            d = abs(x[k] - x[k - 1])
            if abs(x[k] - xc) < half:
                c = 1.0 - (1.0 - c) * math.exp(-d / fill)
            else:
                c = c * math.exp(-d / run)
        h[k] = c
    return h


@on_fine_grid
def oil_pocket_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A lubrication port in the rail, where the fit and held-out parts both pass: crossing
    it the slider picks up a full film (over :data:`OIL_FILL` x the stroke of travel
    within :data:`PORT_HALF` x the stroke of it), then loses it over :data:`OIL_RUN` x the
    stroke it travels; the Coulomb and Stribeck levels are the base's times 1 - ``s`` 0.4
    h (h the film carried), inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the relative level drop with a full film, / 0.4.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Rail lubrication ports of linear guides (THK, HIWIN catalogues); a film carried from
    its supply and depleted with the distance run (Chevalier et al. 1998). The open forms
    are functions of the position (a defect, waviness, a worn section, runout, a bow,
    cogging, a taper) or of the passes over it (a transfer film); here the level follows
    the travel since the port was crossed: a wake on the side the slider went.
    """
    xc = _bump_centre(kin)
    if xc is None:
        raise ValueError(f"position (oil_pocket): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    span = _span(kin)
    h = _carried_oil(np.ascontiguousarray(kin.x, dtype=float), xc, PORT_HALF * span,
                     OIL_RUN * span, OIL_FILL * span)
    lev = np.clip(1.0 - s * 0.4 * h, 0.05, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- inertia ---------------------------------------------------------------------------------
#: acceleration a loose payload's friction holds it up to, x a99 [-]
PAYLOAD_GRIP = 0.5


@njit(cache=True)
def _payload_force(t, v, a, grip):
    """Force per unit payload mass [m/s^2] the carriage exerts on a loose payload: its own
    acceleration ``a`` while the payload sticks (|a| <= ``grip``), +- ``grip`` while it
    slides (towards the carriage's velocity ``v``); it sticks again when its velocity
    meets the carriage's. Starts stuck."""
    n = t.size
    f = np.empty(n)
    u = v[0]
    stuck = True
    sg = 0.0
    for k in range(n):
        if k > 0 and not stuck:
            u += (t[k] - t[k - 1]) * sg * grip
            if (v[k] - u) * sg <= 0.0:
                stuck = True
        if stuck:
            if abs(a[k]) <= grip:
                u = v[k]
                f[k] = a[k]
                continue
            stuck = False
            sg = 1.0 if a[k] > 0.0 else -1.0
            u = v[k]
        f[k] = sg * grip
    return f


@on_fine_grid
def sliding_payload_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A loose payload on the carriage (a part on a pallet), held by its Coulomb friction
    up to the acceleration g_p = :data:`PAYLOAD_GRIP` a99: while it sticks the inverse
    dynamics misses m a, while it slides only the friction force m g_p that drags it (until
    its velocity meets the carriage's again); m = ``s`` x 0.3 x the friction level / a99
    [kg].

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the payload's mass relative to 0.3 x level / a99.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    A block on an accelerating cart (Coulomb friction: stick while |a| < mu g); parts
    slipping on pallets and grippers of fast handling axes. The candidate and the open
    forms are masses (constant, along the stroke, through a ratio, in time, behind a
    spring, in a fluid) whose force is linear in the acceleration; here the force
    saturates where the payload slips, and its slip has a memory.
    """
    F, _ = _base_parts(kin)
    m = s * 0.3 * _level(kin) / max(kin.scales["a99"], 1e-12)
    grip = PAYLOAD_GRIP * max(kin.scales["a99"], 1e-12)
    f = _payload_force(np.ascontiguousarray(kin.t, dtype=float),
                       np.ascontiguousarray(kin.v, dtype=float),
                       np.ascontiguousarray(kin.a, dtype=float), grip)
    return F + m * f


# -- delay -----------------------------------------------------------------------------------
#: data samples the amplifier takes to slew over the base force's range at strength 1 [-],
#: and its time constant at strength 1, x the data's sample time [-]
SLEW_SAMPLES, AMP_LAG = 5.0, 0.25


@njit(cache=True)
def _slewed(t, F, tau, rate):
    """The output [N] of an amplifier of time constant ``tau`` [s] (0: none) whose output
    moves at most at ``rate`` [N/s], driven by ``F`` [N] (exact lag step for a held input,
    then the slew limit)."""
    n = t.size
    y = np.empty(n)
    y[0] = F[0]
    for k in range(1, n):
        h = t[k] - t[k - 1]
        gain = 1.0 if tau <= 0.0 else 1.0 - math.exp(-h / tau)
        dy = (F[k] - y[k - 1]) * gain
        y[k] = y[k - 1] + min(max(dy, -rate * h), rate * h)
    return y


@on_fine_grid
def slew_limit_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force channel through an amplifier of finite slew rate: a single pole of time
    constant ``s`` :data:`AMP_LAG` data samples (at most :data:`.truths.MAX_DELAY_SAMPLES`),
    its output moving at most over the base force's range in ``s`` :data:`SLEW_SAMPLES`
    data samples (a slew rate fixed against the amplifier's full scale): slow changes lag a
    little, fast ones (the reversals) are followed at the slew rate, so the delay grows
    with the force's rate. At ``s`` = 0 the force itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the pole's time constant [/ 0.5 data samples] and the slew
        rate's reduction.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Slew-rate limiting of operational and charge amplifiers (datasheets: slew rate and
    gain-bandwidth of one pole). The open forms are linear (a transport delay, filters, a
    converter's FIR, held samples, a clock's drift or jitter) or shift the motion; this one
    is nonlinear: its delay depends on the signal's rate.
    """
    F, _ = _base_parts(kin)
    t = np.ascontiguousarray(kin.t, dtype=float)
    if s <= 0.0:
        return F
    rate = max(float(np.ptp(F)), 1e-300) / (float(s) * SLEW_SAMPLES * kin.sample_dt)
    # the pole's lag is cut where the other delay forms' is
    tau = min(float(s) * AMP_LAG, MAX_DELAY_SAMPLES) * kin.sample_dt
    return _slewed(t, np.ascontiguousarray(F, dtype=float), tau, rate)


# -- drift -----------------------------------------------------------------------------------
#: time scale of ``seal_relaxation``'s logarithmic relaxation, x the record [-]
RELAX_TIME = 0.01


@on_fine_grid
def seal_relaxation_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """An elastomer seal (or polymer slide) fitted just before the record: its contact
    force relaxes linearly in log time, and the Coulomb and Stribeck levels with it: the
    base's times 1 - ``s`` 0.3 ln(1 + (t - t0) / tau0) / ln(1 + T / tau0), tau0 =
    :data:`RELAX_TIME` x the record T, inside the bristle dynamics; the viscous term is the
    base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the relative level drop over the record, / 0.3.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Physical stress relaxation of rubber, linear in log time (Gent 1962; ISO 3384 for
    seals). The open forms warm up over the record's time scale, fall linearly, step, heat
    with the friction power, wear with the load and travel, cycle with the humidity, rise
    and fall with debris or with lubrication shots; here the fall is logarithmic: most of
    it in the first percent of the record, still going at its end.
    """
    t = np.asarray(kin.t, float)
    T = float(t[-1] - t[0]) or 1.0
    rel = np.log1p((t - t[0]) / (RELAX_TIME * T)) / math.log1p(1.0 / RELAX_TIME)
    lev = np.clip(1.0 - s * 0.3 * rel, 0.05, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: the play of ``drag_idler`` at strength 1, as a share of the stroke [-] (the open backlash
#: forms'), the idler's drag, x the Coulomb level [-], and the slip speed it is rounded
#: over, x v99 [-]
GAP_SHARE, IDLER_DRAG, IDLER_SLIP = PLANT_GAP_SHARE, 0.5, 0.05


@on_fine_grid
def drag_idler_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A play of width ``s`` x :data:`GAP_SHARE` x the stroke between the drive (the
    record's motion) and a light contact with the base's LuGre friction (its inertial force
    at the top acceleration 1 % of the Coulomb level), bridged by a friction-loaded idler:
    it drags the contact with :data:`IDLER_DRAG` Fc tanh((vd - v) / (:data:`IDLER_SLIP`
    v99)); the flanks a coupling 100 x stiffer than the bristle, damping ratio 0.5. The
    measured force is the contact's friction. At ``s`` = 0 the contact follows the drive
    (the base, up to the stiff coupling).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the play's width relative to :data:`GAP_SHARE` x the stroke.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Friction (slip-clutch) anti-backlash gears (Michalec 1966, Precision Gearing). The
    candidate holds or frees the force across the play; the open forms couple it rigidly,
    compliantly, by impacts, a spring, an oil film, with a play varying with the position
    or growing with the travel; here the coupling across the play is a Coulomb drag below
    the contact's breakaway: the force crosses to a plateau of the drag's level and waits
    there for the flank.
    """
    p = _lugre_params(kin, "backlash (drag_idler)")
    half = 0.5 * GAP_SHARE * max(float(s), 0.0) * float(np.ptp(kin.x))
    m, kh, ch = _contact_constants(kin, p)
    drag = IDLER_DRAG * float(p.Fc)
    slip = IDLER_SLIP * max(kin.scales["v99"], 1e-12)
    return _run_driven_contact(kin, p, half, GAP_DRAG, drag, slip, m, kh, ch,
                               c_gap=drag / slip)


# -- gms -------------------------------------------------------------------------------------
#: presliding path of ``rate_state_presliding`` at strength 1, as a share of the stroke / 3
#: [-], and the rate-and-state element's share of the friction at strength 1 [-]
PRESLIDING_SHARE, RS_SHARE = 0.02, 0.5
#: the interface's direct and evolution effects a and b [-] (relative to its level 1), its
#: reference slip rate, x v99 [-], and its state length, x the presliding path [-]
RS_A, RS_B, RS_V0, RS_DC = 0.03, 0.02, 0.1, 0.5


@njit(cache=True)
def _rs_slip_rate(f, psi, a, v0):
    """Slip rate [m/s] of a regularised rate-and-state interface (Rice et al. 2001) at the
    relative stress ``f`` [-] and state term ``psi`` [-], and its derivative in ``f``."""
    ep = math.exp(min((f - psi) / a, 700.0))
    em = math.exp(min((-f - psi) / a, 700.0))
    return v0 * (ep - em), v0 * (ep + em) / a


@njit(cache=True)
def _rs_element(t, x, k, a, b, v0, dc):
    """Relative force [-] of an elastic layer of stiffness ``k`` [1/m] in series with a
    rate-and-state interface (direct effect ``a``, evolution ``b``, reference rate ``v0``
    [m/s], state length ``dc`` [m], aging law) along the positions ``x`` [m]: implicit
    Euler of the slip (a safeguarded Newton on the force), the state's exact aging step at
    the step's slip rate. Starts unloaded, in steady state at ``v0``."""
    n = t.size
    out = np.empty(n)
    d = x[0]
    th = dc / v0
    out[0] = 0.0
    for j in range(1, n):
        h = t[j] - t[j - 1]
        psi = 1.0 + b * math.log(max(th * v0 / dc, 1e-300))
        ft = k * (x[j] - d)  # the elastic predictor: no slip in the step
        lo, hi = min(ft, 0.0), max(ft, 0.0)
        f = ft
        for _ in range(60):
            V, dV = _rs_slip_rate(f, psi, a, v0)
            r = f - ft + k * h * V
            if r > 0.0:
                hi = f
            else:
                lo = f
            step = r / (1.0 + k * h * dV)
            fn = f - step
            if not (lo < fn < hi):
                fn = 0.5 * (lo + hi)
            if abs(fn - f) < 1e-12:
                f = fn
                break
            f = fn
        dn = x[j] - f / k
        V = abs(dn - d) / h
        d = dn
        if V > 1e-300:
            tss = dc / V
            th = tss + (th - tss) * math.exp(-V * h / dc)
        else:
            th += h
        out[j] = f
    return out


@on_fine_grid
def rate_state_presliding_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Presliding as creep of a rate-and-state interface beside the bristle: a share w =
    :data:`RS_SHARE` min(``s``, 1) of the friction is carried by an elastic asperity layer
    (its path to the level d* = the base bristle's Fs / sigma0 plus ``s`` x
    :data:`PRESLIDING_SHARE` x the stroke / 3) in series with a regularised rate-and-state
    interface (relative level 1, a = :data:`RS_A`, b = :data:`RS_B`, reference rate
    :data:`RS_V0` v99, state length :data:`RS_DC` d*, aging law), its relative force f
    scaled by the base's Stribeck level g(v), plus the viscous term; the rest by the base's
    LuGre: F = (1 - w) F_lugre + w (g(v) f + sigma2 v). At ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m], v [m/s]) and its base law (a classic
        LuGre).
    s : float
        Amplitude factor [-]: the element's share (up to ``s`` = 1) and presliding path.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Dieterich 1979, Ruina 1983 (rate-and-state friction), Rice, Lapusta and Ranjith 2001
    (its regularisation through zero slip rate); presliding as thermally activated creep
    (Baumberger and Caroli 2006). Maxwell-slip (the candidate, ``maxwell4``,
    ``maxwell10``) is a set of elasto-plastic blocks, Dahl a rate-independent exponent law,
    elasto-plastic an elastic range, Bliman-Sorine two path-relaxing states, Bouc-Wen an
    endochronic law, the Zener junction a linear relaxation in time, the Mindlin contacts
    Masing's partial slip; here the yield is an exponential creep law: it grows with the
    log of the rate and, through the aging state, with the time held.
    """
    p = _lugre_params(kin, "gms (rate_state_presliding)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, PRESLIDING_SHARE)
    dstar = e0 + extra
    w = RS_SHARE * min(float(s), 1.0)
    v = np.ascontiguousarray(kin.v, dtype=float)
    f = _rs_element(np.ascontiguousarray(kin.t, dtype=float),
                    np.ascontiguousarray(kin.x, dtype=float), 1.0 / dstar, RS_A, RS_B,
                    RS_V0 * max(kin.scales["v99"], 1e-12), RS_DC * dstar)
    return (1.0 - w) * F + w * (kin.base.g(v) * f + float(p.sigma2) * v)
