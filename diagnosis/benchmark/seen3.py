"""The third seen family: one more mechanism per effect, now part of the open grid.

Written 2026-11-24 (session 9) as the sealed family, without running the diagnosis on it;
sealed in session 9, run once on 656e3a8: 39.8 % top-1 (70/176), seen; now open (the
figures are in ``benchmarks/bench_diagnosis_forms.py``). Moved into the open grid in session
10 (each effect record's ``truths``, after its other open forms; the new sealed family is
:mod:`.sealed`, the earlier seen ones :mod:`.seen` and :mod:`.seen2`). Each form is a
mechanism of other physics than the other open forms of its effect (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen`, :mod:`.seen2`, :mod:`diagnosis.effects_backlash`,
:mod:`diagnosis.effects_gms`) and than the candidate's formula (:mod:`diagnosis.candidates`),
integrated along the plant's continuous motion on the grid :data:`.kinematics.FINE` x finer
than the data (:func:`.truths.on_fine_grid`); level changes act inside the bristle dynamics
of a LuGre base (:func:`.truths.level_inside`). ``s`` scales each effect's amplitude
monotonically (its calibration, :func:`.cases._calibrate`, sets the requested size).

=================  =====================================================================
effect             form (was sealed)
=================  =====================================================================
acceleration       ``flash_temperature``: the contact's flash temperature, heated by the
                   friction power |F v| and cooled by conduction into a semi-infinite
                   body (a 1 / sqrt(t) memory kernel, Jaeger/Blok), softens the boundary
                   levels; the steady flash temperature is in the base's own curve, the
                   lag of the transient is the effect (higher friction while the power
                   rises, lower while it falls)
load               ``film_breakdown``: the adsorbed boundary film breaks down above a
                   critical contact pressure (a logistic share of metal contact around the
                   60th percentile of the load, 5 % of the mean load wide): the boundary
                   levels step up with the load, not as a power or affine law
asymmetry          ``thrust_bearing``: a helical or worm stage whose axial thrust follows
                   the *transmitted force* (friction plus the inertial force of the moving
                   mass) and is taken by a rolling bearing one way and a plain thrust
                   washer the other: the levels rise while the drive force is negative,
                   which decelerations and reversals separate from the sign of v
stribeck_shape     ``bimodal_roughness``: a stratified (plateau-honed) surface with two
                   asperity populations: the fine plateau roughness lifts off at the base's
                   Stribeck velocity, the coarse peaks at a higher speed and abruptly (a
                   super-Gaussian drop, exponent 4): a shoulder and a second drop on the
                   curve
position           ``transfer_film``: a solid-lubricant transfer film laid down along the
                   track by the sliding itself: the levels fall with the number of passes
                   over each position (this record's so far and an identical run before
                   it), so rarely travelled parts of the stroke keep the bare level
inertia            ``lossy_gearing``: the drive's inertia reflected through a gear stage
                   of efficiency 0.6: the inverse dynamics misses J a / eta while the
                   drive accelerates the inertia (power flows in) and J a eta while the
                   inertia drives back (braking): a mass error that differs between
                   acceleration and deceleration
delay              ``fieldbus_hold``: the force sampled by a fieldbus slave at its own,
                   slower clock (hold period ``s`` data samples, asynchronous to the
                   logger's), sent with a transport delay of half that and held by the
                   master until the next telegram: a staircase whose mean delay is ``s``
                   samples
drift              ``humidity_cycle``: capillary adhesion of the adsorbed water raises the
                   boundary levels with the ambient humidity, which an on/off
                   dehumidifier drives around a hysteresis band (exponential rises and
                   falls, a period of about 0.56 x the record): a drift that comes and goes
backlash           ``eccentric_gear``: a gear pair with runout: the centre distance, and
                   with it the play, varies once per revolution (half the stroke) between
                   0.2 and 1.8 x its mean, so the lost motion at a reversal depends on
                   where along the stroke it happens
gms                ``bouc_wen``: an endochronic (Bouc-Wen / Valanis) presliding
                   hysteresis with the base's Stribeck level: the loading curve's
                   exponent grows from 1 to 2 and the unloading stiffness falls below
                   the LuGre bristle's as the presliding path grows: local memory, loops
                   that are not Masing's; at ``s`` = 0 the base bristle itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``bimodal_roughness``
needs a Stribeck curve (not the isolator's mre_lugre), ``transfer_film`` a record that
revisits its positions (not the press), ``eccentric_gear`` and ``bouc_wen`` a classic LuGre
base (valve, damping rig, XML-350); each raises a ``ValueError`` elsewhere.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit
from scipy.signal import fftconvolve
from scipy.special import erf

from friction.shapes import SHAPES, stribeck_g

from ..effects_backlash import PLANT_GAP_SHARE
from ..effects_gms import PLANT_PRESLIDING_SHARE
from .kinematics import PlantKinematics
from .truths import (MAX_DELAY_SAMPLES, _base_parts, _bump_centre, _level, _lugre_params,
                     _motion_time, _presliding_path, _smooth_max0, _span, level_inside,
                     on_fine_grid)

__all__ = ["flash_temperature_truth", "film_breakdown_truth", "thrust_bearing_truth",
           "bimodal_roughness_truth", "transfer_film_truth", "lossy_gearing_truth",
           "fieldbus_hold_truth", "humidity_cycle_truth", "eccentric_gear_truth",
           "bouc_wen_truth"]


# -- acceleration ---------------------------------------------------------------------------
def _conduction_kernel(h: float, tau: float, n_max: int) -> np.ndarray:
    """Weights of the semi-infinite body's temperature response to a heat flux, 1 /
    sqrt(pi u) cut off by exp(-u / tau) (heat leaving the contact spot into the bulk),
    integrated over each grid step ``h`` [s] (exactly: the kernel is singular at u = 0) and
    normalised to a unit sum (a steady flux gives its steady temperature)."""
    m = int(min(max(math.ceil(8.0 * tau / h), 2), n_max))
    edges = h * np.arange(m + 1)
    cum = erf(np.sqrt(edges / tau))       # int_0^u exp(-w/tau) / sqrt(pi w tau) dw
    k = np.diff(cum)
    return k / k.sum()


@on_fine_grid
def flash_temperature_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Thermal softening by the contact's flash temperature: the friction power P = |Ff v|
    heats the contact spot, which cools by conduction into a semi-infinite body (memory
    kernel 1 / sqrt(t), cut off after the motion's time scale); the boundary levels and the
    viscous term are the base's times exp(-``s`` (theta - P) / P99), theta the flash
    temperature in units of the power that holds it steady. The steady flash temperature
    belongs to the base's own curve (identified at steady sliding); its lag behind the
    power is the effect: friction above the steady curve while the power rises (speeding
    up), below it while it falls.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the softening per top friction power of temperature lag.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Unlike the open forms it is neither a lagged velocity in the Stribeck curve
    (``frictional_memory``, ``film_dynamics``) nor a state renewed over a slip distance
    (``slip_memory``, ``contact_aging``): its memory is the half-order one of heat
    diffusion, driven by the power, and it acts where the curve is flat too.
    """
    _, Ff = _base_parts(kin)
    P = np.abs(Ff * kin.v)
    P99 = max(float(np.percentile(P, 99)), 1e-300)
    k = _conduction_kernel(kin.dt, _motion_time(kin), P.size)
    # causal, from a settled start (the contact at the first sample's steady temperature)
    theta = fftconvolve(np.concatenate((np.full(k.size - 1, P[0]), P)), k, mode="valid")
    return level_inside(kin, np.exp(-s * (theta - P) / P99))


# -- load -------------------------------------------------------------------------------------
@on_fine_grid
def film_breakdown_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Boundary-film breakdown: the adsorbed lubricant film fails above a critical contact
    pressure, so the share of bare metal contact is a logistic function of the load (centre
    the load's 60th percentile, width 5 % of the mean load); the Coulomb and Stribeck
    levels are the base's times 1 + ``s`` (share - mean share), inside the bristle
    dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (load [N]) and its base law.
    s : float
        Amplitude factor [-]: the relative rise of the levels from film to metal contact.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The open forms are smooth laws of the load (affine, L^(2/3), proportional with a
    sqrt(L) viscous term, one direction only, the Stribeck velocity); this one is a
    threshold (scuffing onset of an extreme-pressure boundary film).
    """
    L = np.clip(kin.load, 0.0, None)
    L0 = max(float(np.mean(L)), 1e-12)
    Lc = float(np.percentile(L, 60))
    share = 0.5 * (1.0 + np.tanh((L - Lc) / (2.0 * 0.05 * L0)))   # logistic, scale 5 % L0
    lev = np.clip(1.0 + s * (share - float(np.mean(share))), 0.05, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
@on_fine_grid
def thrust_bearing_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A helical (or worm) stage whose axial thrust is proportional to the transmitted
    force, taken by a rolling bearing when the drive force is positive and by a plain
    thrust washer when it is negative: the Coulomb and Stribeck levels are the base's
    times 1 + ``s`` max(-Fd, 0) / level (rounded over 5 % of the level), inside the
    bristle dynamics, with Fd the drive force, the base's force plus the inertial force of
    a moving mass m = level / a99; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the washer's friction per unit of drive force.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The open forms key on the direction of *motion* (twins, a Stribeck velocity or tail
    per direction, a seal lip rolled by the travel); here the direction of the
    *transmitted force* decides, which differs from it while the mass decelerates.
    """
    F, _ = _base_parts(kin)
    lvl = _level(kin)
    m = lvl / max(kin.scales["a99"], 1e-12)
    Fd = F + m * kin.a
    lev = 1.0 + s * _smooth_max0(-Fd, 0.05 * lvl) / lvl
    return level_inside(kin, lev, np.ones_like(lev))


# -- stribeck_shape --------------------------------------------------------------------------
@on_fine_grid
def bimodal_roughness_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A stratified (plateau-honed) surface with two asperity populations: the fine
    plateau roughness lifts off as the base's curve does, the coarse peaks at a speed v2 =
    5 v_s (between 15 % and 50 % of the top speed) and abruptly, as the film reaches their
    narrow height band: the curve gains ``s`` x 0.6 (Fs - Fc) exp(-(|v| / v2)^4), a shoulder
    and a second, steep drop, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (a Stribeck curve).
    s : float
        Amplitude factor [-]: the coarse population's share of the static excess.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    One drop of any exponent or a Lorentzian (the candidate), an extra tail, a rational
    drop, a sqrt viscous term, a narrow spike and a compact lift-off (the open forms) all
    bend the curve once; this one has two drops at speeds far apart.
    """
    if kin.base.name == "mre_lugre":
        raise ValueError("stribeck_shape (bimodal_roughness): the mre_lugre base has no "
                         "Stribeck curve")
    p = kin.base.params
    v99 = kin.scales["v99"]
    v2 = min(max(5.0 * float(p.vs), 0.15 * v99), 0.5 * v99)
    v = kin.v
    # a base without a Stribeck excess still has a Coulomb level to carry the shoulder
    excess = max(float(p.Fs) - float(p.Fc), 0.2 * float(p.Fc))
    extra = 0.6 * excess * np.exp(-(np.abs(v) / v2) ** 4)
    return level_inside(kin, 1.0 + s * extra / kin.base.g(v), np.ones_like(v))


# -- position --------------------------------------------------------------------------------
#: bins of the ``transfer_film`` track along the stroke [-]
FILM_BINS = 400


@njit(cache=True)
def _passes(x, lo, w, nb):
    """Passes [-] over each position: the sliding distance travelled over its bin of width
    ``w`` [m] so far, per bin width, at each grid point (and the totals at the end)."""
    n = x.size
    dist = np.zeros(nb)
    out = np.empty(n)
    for k in range(n):
        if k > 0:
            xm = 0.5 * (x[k] + x[k - 1])
            b = min(max(int((xm - lo) / w), 0), nb - 1)
            dist[b] += abs(x[k] - x[k - 1]) / w
        b = min(max(int((x[k] - lo) / w), 0), nb - 1)
        out[k] = dist[b]
    return out, dist


@on_fine_grid
def transfer_film_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A solid-lubricant transfer film (a PTFE-filled slider on a steel guide) laid down by
    the sliding itself: the film over a position grows with the passes over it, n(x, t),
    those of this record so far plus those of an identical run before it; the boundary
    levels are the base's times 1 - ``s`` 0.4 (1 - exp(-n / n0)) (n0 the median passes of
    one run over the positions it visits), inside the bristle dynamics; the viscous term
    is the base's. The stroke's rarely travelled parts keep the bare level.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the film's relative reduction of the levels at saturation.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The open forms are fixed maps of the guide (a bump, waviness, a step, runout, a bow
    and a scratch); this map is made by the motion, in the pattern of its coverage.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (transfer_film): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    x = np.ascontiguousarray(kin.x, dtype=float)
    lo = kin.scales["x_lo"]
    w = _span(kin) / FILM_BINS * (1.0 + 1e-9)
    n_now, total = _passes(x, lo, w, FILM_BINS)
    bins = np.clip(((x - lo) / w).astype(int), 0, FILM_BINS - 1)
    n = total[bins] + n_now                     # the run before this one, then this one
    visited = total[total > 0]
    n0 = max(float(np.median(visited)) if visited.size else 1.0, 1e-12)
    lev = np.clip(1.0 - s * 0.4 * (1.0 - np.exp(-n / n0)), 0.05, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- inertia ---------------------------------------------------------------------------------
#: efficiency of the ``lossy_gearing`` stage [-] (a worm or a high-ratio helical stage)
GEAR_EFFICIENCY = 0.6


@on_fine_grid
def lossy_gearing_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The drive's inertia reflected through a gear stage of efficiency eta
    (:data:`GEAR_EFFICIENCY`): accelerating the inertia the drive supplies J a / eta, when
    the inertia drives back through the stage (power a v < 0) it recovers only J a eta;
    the direction of the power flow is rounded over 5 % of a99 v99. J = ``s`` x the
    friction level / a99 [kg].

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the reflected inertia relative to level / a99.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The open forms are one mass (filtered or raw acceleration), a mass on a spring, a mass
    growing along the stroke and a position-dependent ratio; here the mass seen depends on
    the direction of the power flow through the stage's losses.
    """
    F, _ = _base_parts(kin)
    sc = kin.scales
    J = s * _level(kin) / max(sc["a99"], 1e-12)
    flow = np.tanh(kin.a * kin.v / max(0.05 * sc["a99"] * sc["v99"], 1e-300))
    return F + J * kin.a * GEAR_EFFICIENCY ** (-flow)


# -- delay -----------------------------------------------------------------------------------
#: the fieldbus clock's rate over its nominal (asynchronous to the logger's) [-], and the
#: phase of its first tick [hold periods]
BUS_CLOCK_RATIO, BUS_PHASE = 1.0123, 0.37


@on_fine_grid
def fieldbus_hold_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force channel over a fieldbus: a slave samples the force every ``s`` data
    samples by its own clock (:data:`BUS_CLOCK_RATIO` off the logger's, first tick at
    :data:`BUS_PHASE` of a period), the telegram arrives ``s`` / 2 samples later, and the
    master holds the last value received (zero-order hold): the logged force is a
    staircase whose mean delay is ``s`` samples (at most :data:`.truths.MAX_DELAY_SAMPLES`).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid and its base law.
    s : float
        Amplitude factor [-]: the hold period [data samples], twice the transport delay.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The open forms are continuous filters or shifts of the force (spline shift and lag,
    Bessel, moving average, FIR) or of the motion; this one samples and holds at a slower,
    drifting clock: steps, and a delay that varies between ``s`` / 2 and 3 ``s`` / 2.
    """
    F, _ = _base_parts(kin)
    D = min(max(float(s), 0.0), MAX_DELAY_SAMPLES) * kin.sample_dt
    period = max(D / BUS_CLOCK_RATIO, kin.dt)
    transport = 0.5 * D
    t = kin.t
    # the latest telegram that has arrived by t: sent at the last tick <= t - transport
    k = np.floor((t - transport - t[0]) / period - BUS_PHASE)
    sent = t[0] + (k + BUS_PHASE) * period
    held = np.interp(sent, t, F)
    return np.where(sent >= t[0], held, F[0])


# -- drift -----------------------------------------------------------------------------------
@njit(cache=True)
def _humidity(t, tau_up, tau_down, lo, hi):
    """Relative humidity [-] under an on/off dehumidifier: towards 1 with ``tau_up`` [s]
    while off, towards 0 with ``tau_down`` [s] while on; it switches on at ``hi`` and off at
    ``lo`` (exact for each step); starts at mid-band, off."""
    n = t.size
    r = np.empty(n)
    c = 0.5 * (lo + hi)
    on = False
    r[0] = c
    for k in range(1, n):
        h = t[k] - t[k - 1]
        if on:
            c = c * math.exp(-h / tau_down)
            if c <= lo:
                on = False
        else:
            c = 1.0 + (c - 1.0) * math.exp(-h / tau_up)
            if c >= hi:
                on = True
        r[k] = c
    return r


@on_fine_grid
def humidity_cycle_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Capillary adhesion of the adsorbed water: the ambient humidity, under an on/off
    dehumidifier with a band of 35-65 % (rising with a time constant of 0.6 x the record,
    falling with 0.3 x), cycles with a period of about 0.56 x the record; the Coulomb and
    Stribeck levels are the base's times 1 + ``s`` 0.3 (RH - 0.5) / 0.15, inside the
    bristle dynamics; the viscous film's term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the relative level change from mid-band to the band's edge,
        / 0.3.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The open forms change once (a warm-up, a linear wear-in, a step, heating by the
    friction power, wear with the travel); this one comes and goes with the ambient.
    """
    T = float(kin.t[-1] - kin.t[0]) or 1.0
    rh = _humidity(np.ascontiguousarray(kin.t, dtype=float), 0.6 * T, 0.3 * T, 0.35, 0.65)
    lev = np.clip(1.0 + s * 0.3 * (rh - 0.5) / 0.15, 0.05, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: mean lost motion of ``eccentric_gear`` at strength 1, as a share of the stroke [-] (as the
#: open backlash forms), its relative variation per revolution [-] and the travel of one
#: revolution as a share of the stroke [-]
GAP_SHARE, GAP_RUNOUT, REVOLUTION_SHARE = PLANT_GAP_SHARE, 0.8, 0.5


@njit(cache=True)
def _varying_play(xd, half):
    """Contact positions [m] behind a kinematic play whose half-width ``half`` [m] varies
    along the drive's positions ``xd`` [m] (sharp flanks), starting centred."""
    xc = np.empty(xd.size)
    c = xd[0]
    for k in range(xd.size):
        if xd[k] - c > half[k]:
            c = xd[k] - half[k]
        elif c - xd[k] > half[k]:
            c = xd[k] + half[k]
        xc[k] = c
    return xc


@njit(cache=True)
def _contact_friction(h, vc, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a contact moving with the per-step velocities ``vc`` [m/s]
    (step ``h`` [s], n + 1 points) on the base's Stribeck curve (its ``shape`` code): the
    bristle exact for each step's velocity, the force at a point with the velocity of the
    step that ends there."""
    n = vc.size
    F = np.empty(n + 1)
    z = 0.0
    for k in range(n):
        w = vc[k]
        zd = 0.0
        if w != 0.0:
            g = stribeck_g(w, Fc, Fs, vs, alpha, shape)
            zss = math.copysign(g / s0, w)
            z = zss + (z - zss) * math.exp(-h * s0 * abs(w) / g)
            zd = w - s0 * abs(w) * z / g
        F[k + 1] = s0 * z + s1 * zd + s2 * w
    F[0] = F[1]
    return F


@on_fine_grid
def eccentric_gear_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A gear pair with runout: the centre distance varies once per revolution of the
    gear (travel :data:`REVOLUTION_SHARE` x the stroke), and with it the play, between
    1 -+ :data:`GAP_RUNOUT` times its mean ``s`` x :data:`GAP_SHARE` x the stroke; the
    contact, with the base's LuGre friction, follows the drive (the record's motion) once
    a flank is reached. The measured force is the contact's friction.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the mean play relative to :data:`GAP_SHARE` x the stroke.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The open forms and the candidate have one play width; here the lost motion at a
    reversal depends on where along the stroke it happens.
    """
    p = _lugre_params(kin, "backlash (eccentric_gear)")
    xd = np.ascontiguousarray(kin.x, dtype=float)
    phase = 2.0 * np.pi * (xd - kin.scales["x_lo"]) / (REVOLUTION_SHARE * _span(kin))
    mean_half = 0.5 * GAP_SHARE * max(float(s), 0.0) * float(np.ptp(xd))
    half = mean_half * (1.0 + GAP_RUNOUT * np.sin(phase + 0.6))
    xc = _varying_play(xd, half)
    h = kin.dt
    return _contact_friction(h, np.diff(xc) / h, float(p.sigma0), float(p.sigma1),
                             float(p.sigma2), float(p.Fc), float(p.Fs), float(p.vs),
                             float(p.alpha), SHAPES[p.shape])


# -- gms -------------------------------------------------------------------------------------
#: presliding path ``bouc_wen`` adds at strength 1, as a share of the stroke [-] (a third of
#: the open gms forms' presliding distance, as ``bliman_sorine``)
PRESLIDING_SHARE = PLANT_PRESLIDING_SHARE
#: largest share of the loading term in the unloading stiffness's reduction [-]
BW_GAMMA = 0.4


@njit(cache=True)
def _bouc_wen(t, v, g, g_mid, k, n_exp, gam, s0, s1, s2):
    """Force [N] of a Bouc-Wen presliding hysteresis in force units, du/dt = k (v - (1 -
    gam) |v| |w|^(n-1) w - gam v |w|^n) with w = u / g (``g`` [N] the Stribeck level at the
    grid points, ``g_mid`` at the step midpoints; ``k`` [N/m] the stiffness, ``n_exp`` =
    n), F = u + s1 du/dt / s0 + s2 v; explicit sub-steps keep each step's change of w
    below 2 % (of its local slope); starts unloaded. With n = 1, gam = 0, k = s0 it is
    the LuGre bristle (s0 z = u)."""
    n = t.size
    F = np.empty(n)
    u = 0.0
    for j in range(n):
        vj = v[j]
        w = u / g[j]
        aw = abs(w)
        ud = k * (vj - (1.0 - gam) * abs(vj) * aw ** (n_exp - 1.0) * w
                  - gam * vj * aw ** n_exp)
        F[j] = u + s1 * ud / s0 + s2 * vj
        if j + 1 < n:
            h = t[j + 1] - t[j]
            vm = 0.5 * (vj + v[j + 1])
            gm = g_mid[j]
            slope = n_exp * max(1.0, abs(u) / gm) ** (n_exp - 1.0) + 1.0
            m = int(min(math.ceil(k * abs(vm * h) * slope / (0.02 * gm)), 20000)) + 1
            hh = h / m
            for _ in range(m):
                w = u / gm
                aw = abs(w)
                u += hh * k * (vm - (1.0 - gam) * abs(vm) * aw ** (n_exp - 1.0) * w
                               - gam * vm * aw ** n_exp)
    return F


@on_fine_grid
def bouc_wen_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """An endochronic presliding hysteresis (Bouc-Wen, Valanis) with the base's Stribeck
    level g(v): the friction state u [N] follows du/dx = k (1 - (beta sgn(v w) + gamma)
    |w|^n), w = u / g(v) (beta + gamma = 1: it slides at u = g), and F = u + sigma1
    du/dt / sigma0 + sigma2 v. The presliding path e = Fs / k is the base bristle's
    (e0 = Fs / sigma0) + ``s`` x :data:`PRESLIDING_SHARE` x the stroke / 3; with r =
    (e - e0) / e the exponent n = 1 + r (a stiffer start, a sharper transition to sliding)
    and gamma = :data:`BW_GAMMA` r (the unloading stiffness k (1 + (1 - 2 gamma) |w|^n),
    below the bristle's k (1 + |w|)): at ``s`` = 0 the base LuGre bristle.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m], v [m/s]) and its base law (a classic
        LuGre: its bristle, damping, curve and viscous term).
    s : float
        Amplitude factor [-]: the presliding path added, relative to
        :data:`PRESLIDING_SHARE` x the stroke.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Local memory and a loop shape set by its exponent and its loading/unloading asymmetry:
    neither the blocks of Maxwell-slip (nonlocal memory, Masing's rule), nor Dahl's
    rate-independent exponent 1.5 with symmetric stiffness, nor an elastic range with a
    half-sine transition (elasto-plastic), nor two relaxing states (Bliman-Sorine).
    """
    p = _lugre_params(kin, "gms (bouc_wen)")
    s0 = float(p.sigma0)
    e0, extra = _presliding_path(kin, s, PRESLIDING_SHARE)
    e = e0 + extra
    r = extra / e
    v = np.ascontiguousarray(kin.v, dtype=float)
    g = kin.base.g
    return _bouc_wen(np.ascontiguousarray(kin.t, dtype=float), v, g(v),
                     g(0.5 * (v[1:] + v[:-1])), float(p.Fs) / e, 1.0 + r, BW_GAMMA * r, s0,
                     float(p.sigma1), float(p.sigma2))
