"""The fifth seen family: one more mechanism per effect, now part of the open grid.

Written 2026-11-24 (session 10, end) as the sealed family, without running the diagnosis on
it; sealed until session 11, run once there on the code of a99721e: 26.1 % top-1 (46/176;
26.7 % of the detectable), mean |shrink error| 0.414, 15 wrong names (8.5 %: acceleration
-> position 4, gms -> acceleration 4, load -> asymmetry 2, asymmetry -> load 2, inertia ->
delay 1, position -> drift 1, inertia -> drift 1), 0 skipped; by form moment_load 0/20,
normal_vibration 2/20, ratchet_texture 10/20, eyring_boundary 1/16, preload_taper 14/16,
dispensing_mass 6/20, timing_jitter 8/20, interval_lubrication 0/20, worn_gap 3/12,
mindlin_contacts 2/12; seen, now open (``benchmarks/bench_diagnosis_forms.py``). Moved
into the open grid at the end of session 11 (each effect record's ``truths``, after its
other open forms; the new sealed family is :mod:`.sealed`, the earlier seen ones
:mod:`.seen`, :mod:`.seen2`, :mod:`.seen3` and :mod:`.seen4`). Each form is a mechanism of
other physics than the other open forms of its effect (:mod:`.truths`, :mod:`.forms`,
:mod:`.seen`, :mod:`.seen2`, :mod:`.seen3`, :mod:`.seen4`, :mod:`diagnosis.effects_backlash`,
:mod:`diagnosis.effects_gms`) and than the candidate's formula (:mod:`diagnosis.candidates`),
taken from the friction literature or from real machines, integrated along the plant's
continuous motion on the grid :data:`.kinematics.FINE` x finer than the data
(:func:`.truths.on_fine_grid`); level changes act inside the bristle dynamics of a LuGre base
(:func:`.truths.level_inside`). ``s`` scales each effect's amplitude monotonically from the
base law at ``s`` = 0 (its calibration, :func:`.cases._calibrate`, sets the requested size).

=================  =====================================================================
effect             form (was sealed)
=================  =====================================================================
acceleration       ``moment_load``: a carriage on a preloaded linear guide whose load
                   sits above the rail: the acceleration's pitching moment moves load
                   from one ball row to the other (Hertz rows, rolling loss ~ Q^(4/3),
                   Tabor); the levels rise with |a|, more steeply once a row unloads
load               ``normal_vibration``: friction falls while the normal load changes
                   (Tolstoi 1967; Littmann et al. 2001): the levels drop with the rate
                   |dL/dt|, not with the load itself
asymmetry          ``ratchet_texture``: a directional (saw-tooth) surface texture: against
                   the grain (v < 0) the slider climbs the teeth and the levels rise; at
                   speed it flies over them, so the rise fades as 1 / (1 + (v / v_t)^2)
stribeck_shape     ``eyring_boundary``: a boundary film whose shear strength rises as the
                   Eyring law asinh(v / v0) (Briscoe and Evans 1982): a strengthening
                   that is steep at low speed and logarithmic above
position           ``preload_taper``: a linear-guide rail ground with a height taper: the
                   preload, and with it the Hertzian rows' friction (~ preload^1.5),
                   changes monotonically along the stroke
inertia            ``dispensing_mass``: the carriage carries a tank that empties over the
                   record (a dispensing axis): the mass missed by the inverse dynamics
                   falls linearly in time to 20 %
delay              ``timing_jitter``: a non-real-time logger timestamps the force with a
                   wandering latency: the force's delay is ``s`` (1 + 0.6 u(t)) samples,
                   u a fixed band-limited random signal in [-1, 1]
drift              ``interval_lubrication``: a central lubrication system injects grease
                   at 15, 50 and 85 % of the record: each shot drops the levels, which
                   creep back as the grease is spread and consumed (a sawtooth in time)
backlash           ``worn_gap``: a gear play that grows with the distance travelled (flank
                   wear, Flodin and Andersson 2000): from 40 % to 100 % of its width over
                   the record; across the play the contact stands still
gms                ``mindlin_contacts``: Hertzian contacts in partial slip (Cattaneo 1938,
                   Mindlin 1949) in parallel with the LuGre bristle: presliding force
                   1 - (1 - d / 2 d*)^1.5 from the last reversal (Masing's rule, doubled
                   path), capped by the Stribeck level; at ``s`` = 0 the base itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``eyring_boundary`` needs
a Stribeck curve (not the isolator's mre_lugre), ``preload_taper`` a record that revisits
its positions (not the press), ``normal_vibration`` a load that changes, ``worn_gap`` and
``mindlin_contacts`` a classic LuGre base (valve, damping rig, XML-350); each raises a
``ValueError`` elsewhere.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..effects_backlash import PLANT_GAP_SHARE
from .kinematics import PlantKinematics
from .truths import (MAX_DELAY_SAMPLES, _base_parts, _bump_centre, _lag, _level,
                     _lugre_params, _motion_time, _presliding_path, _smooth_max0, _span,
                     level_inside, on_fine_grid)

__all__ = ["moment_load_truth", "normal_vibration_truth", "ratchet_texture_truth",
           "eyring_boundary_truth", "preload_taper_truth", "dispensing_mass_truth",
           "timing_jitter_truth", "interval_lubrication_truth", "worn_gap_truth",
           "mindlin_contacts_truth"]


# -- acceleration ---------------------------------------------------------------------------
#: acceleration at which one ball row of ``moment_load`` loses its preload, x a99 [-]
ROW_UNLOAD = 0.5


def _rows(q, eps):
    """Rolling loss of two preloaded Hertzian rows [-] whose loads are 1 +- q (smoothly
    cut at 0), each ~ load^(4/3); 1 at q = 0 up to the rounding."""
    return 0.5 * (_smooth_max0(1.0 + q, eps) ** (4.0 / 3.0)
                  + _smooth_max0(1.0 - q, eps) ** (4.0 / 3.0))


@on_fine_grid
def moment_load_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Moment load on a preloaded linear guide: the carriage's load sits above the rail, so
    the acceleration's pitching moment moves load between the front and rear ball rows,
    loads 1 +- q with q = a / (:data:`ROW_UNLOAD` a99); each row's rolling loss goes as
    its load^(4/3) (a row that loses its preload carries nothing). The Coulomb and Stribeck
    levels are the base's times 1 + ``s`` 0.5 (phi(q) - phi(0)) / (phi(2) - phi(0)), phi
    the rows' loss, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the relative rise of the levels at the top acceleration,
        / 0.5.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Linear-guide catalogues (THK, HIWIN: friction under moment load); Tabor's rolling loss
    ~ Q^(4/3). Even in a and instantaneous like ``rolling_skid`` but from the load path,
    not a skidding share: a convex rise from a = 0 with a kink where a row unloads.
    """
    q = np.asarray(kin.a, float) / (ROW_UNLOAD * max(kin.scales["a99"], 1e-12))
    eps = 0.02
    phi0 = float(_rows(np.zeros(1), eps)[0])
    top = float(_rows(np.full(1, 1.0 / ROW_UNLOAD), eps)[0])
    lev = 1.0 + s * 0.5 * (_rows(q, eps) - phi0) / (top - phi0)
    return level_inside(kin, lev, np.ones_like(lev))


# -- load -------------------------------------------------------------------------------------
@on_fine_grid
def normal_vibration_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Friction reduced by a changing normal load: while the load changes the contact
    partly unloads and re-sticks, so the levels fall with the load's rate r = |dL/dt|
    (lagged over 2 % of the motion's time scale): 1 - ``s`` 0.4 (1 - exp(-r / r99)) / (1 -
    exp(-1)), r99 the rate's 99th percentile, inside the bristle dynamics; the viscous term
    is the base's. ValueError if the load does not change.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], load [N]) and its base law.
    s : float
        Amplitude factor [-]: the relative level drop at the rate r99, / 0.4.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Tolstoi 1967 (normal vibrations lower friction); Littmann, Storck and Wallaschek 2001
    (friction reduction by vibration). The candidate and the open forms are laws of the
    load (affine, a power, one direction, the Stribeck velocity, a threshold) or of its
    history (creep); this one is a law of its rate.
    """
    L = np.asarray(kin.load, float)
    r = _lag(kin.t, np.abs(np.gradient(L, kin.t)), max(0.02 * _motion_time(kin), kin.dt))
    r99 = float(np.percentile(r, 99))
    T = float(kin.t[-1] - kin.t[0]) or 1.0
    # a change below 1e-6 of the mean load over the record is round-off, not a change
    if not np.isfinite(r99) or r99 * T <= 1e-6 * max(float(np.mean(np.abs(L))), 1e-12):
        raise ValueError(f"load (normal_vibration): the {kin.plant} record's load does not "
                         f"change")
    drop = (1.0 - np.exp(-r / r99)) / (1.0 - math.exp(-1.0))
    lev = np.clip(1.0 - s * 0.4 * drop, 0.05, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: speed above which ``ratchet_texture``'s slider flies over the teeth, x v99 [-]
TAKE_OFF = 0.3


@on_fine_grid
def ratchet_texture_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A saw-tooth (directional) surface texture: against the grain (v < 0) the slider
    climbs the teeth's steep flanks and the Coulomb and Stribeck levels are the base's
    times 1 + ``s`` 0.5 n(v) / (1 + (v / v_t)^2), v_t = :data:`TAKE_OFF` v99 (faster, it
    flies over the teeth), n(v) a smooth indicator of v < 0 (over 2 % of v99), inside the
    bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the negative direction's relative level rise at rest, / 0.5.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Directional friction of anisotropic (saw-tooth, scale-like) surfaces (Filippov and
    Gorb 2013; laser-textured surfaces). The open forms keep a direction's share at all
    speeds, move its Stribeck velocity or viscous slope, or follow a lip, a thrust or a
    film; here the asymmetry is geometric and fades with the speed.
    """
    v99 = max(kin.scales["v99"], 1e-12)
    v = np.asarray(kin.v, float)
    neg = 0.5 * (1.0 - np.tanh(v / (0.02 * v99)))
    lev = 1.0 + s * 0.5 * neg / (1.0 + (v / (TAKE_OFF * v99)) ** 2)
    return level_inside(kin, lev, np.ones_like(lev))


# -- stribeck_shape --------------------------------------------------------------------------
#: Eyring speed of ``eyring_boundary``, x v99 [-]
EYRING_SPEED = 0.01


@on_fine_grid
def eyring_boundary_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A boundary film sheared by thermal activation: its shear strength rises as the
    Eyring law, the curve gains ``s`` x 0.4 Fc asinh(|v| / v0) / asinh(v99 / v0), v0 =
    :data:`EYRING_SPEED` v99: steep near rest, logarithmic above, inside the bristle
    dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (a Stribeck curve).
    s : float
        Amplitude factor [-]: the strengthening at the top speed, x 0.4 Fc.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Eyring 1936; Briscoe and Evans 1982 (shear strength of boundary films rising with the
    logarithm of the sliding speed). The candidate bends the base's drop; the open forms
    add tails, drops, a spike, a lift-off, a second drop or a logarithmic *weakening*;
    this one strengthens.
    """
    if kin.base.name == "mre_lugre":
        raise ValueError("stribeck_shape (eyring_boundary): the mre_lugre base has no "
                         "Stribeck curve")
    p = kin.base.params
    v99 = max(kin.scales["v99"], 1e-12)
    v0 = EYRING_SPEED * v99
    v = kin.v
    extra = 0.4 * float(p.Fc) * np.arcsinh(np.abs(v) / v0) / math.asinh(v99 / v0)
    return level_inside(kin, 1.0 + s * extra / kin.base.g(v), np.ones_like(v))


# -- position --------------------------------------------------------------------------------
@on_fine_grid
def preload_taper_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A rail ground with a height taper: the guide's preload changes linearly along the
    stroke, 1 + ``s`` 0.6 (u - 0.5) (u = (x - x_lo) / stroke, floored at 0.1), and the
    Hertzian rows' friction with the preload^1.5: the Coulomb and Stribeck levels are the
    base's times that, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the preload's change over the stroke, / 0.6.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Rail height and parallelism tolerances of linear guides (THK, HIWIN catalogues); a
    Hertz contact's force ~ its approach^1.5. The open forms are local (a defect, a worn
    section, a transfer film), periodic (waviness, runout, cogging) or a bow; this one is
    a monotone, slightly convex change over the whole stroke.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (preload_taper): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    u = (np.asarray(kin.x, float) - kin.scales["x_lo"]) / _span(kin)
    lev = np.clip(1.0 + s * 0.6 * (u - 0.5), 0.1, None) ** 1.5
    return level_inside(kin, lev, np.ones_like(lev))


# -- inertia ---------------------------------------------------------------------------------
@on_fine_grid
def dispensing_mass_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A dispensing axis: the carriage carries a tank that empties at a steady rate over the
    record, so the mass missed by the inverse dynamics is m(t) = m0 (1 - 0.8 (t - t0) /
    T), m0 = ``s`` x 0.3 x the friction level / a99 [kg] (the material leaves at the
    carriage's speed: no thrust).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the starting mass relative to 0.3 x level / a99.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Variable-mass systems (Meshchersky's equation, with the material leaving at the
    body's speed). The candidate and the open forms are constant masses (or vary with
    the position or a gear ratio); here the mass falls with the time.
    """
    F, _ = _base_parts(kin)
    t = np.asarray(kin.t, float)
    T = float(t[-1] - t[0]) or 1.0
    m0 = s * 0.3 * _level(kin) / max(kin.scales["a99"], 1e-12)
    return F + m0 * (1.0 - 0.8 * (t - t[0]) / T) * np.asarray(kin.a, float)


# -- delay -----------------------------------------------------------------------------------
#: seed of ``timing_jitter``'s latency signal (fixed: every case sees the same)
JITTER_SEED = 20261124


@on_fine_grid
def timing_jitter_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A logger on a non-real-time system: the force's timestamps carry a wandering
    latency, so the force is late by d(t) = ``s`` (1 + 0.6 u(t)) data samples (cut at
    :data:`.truths.MAX_DELAY_SAMPLES`), u a band-limited random signal (white noise of a
    fixed seed, lagged over 20 data samples, scaled to unit standard deviation and clipped
    to [-1, 1]); a cubic-spline shift.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the mean delay [data samples].

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Scheduling latency of software-timed acquisition (what hardware timestamping and IEEE
    1588 avoid). The open forms delay or filter by the same amount all along the record,
    or by a delay growing linearly (clock skew); here it wanders.
    """
    from scipy.interpolate import CubicSpline
    F, _ = _base_parts(kin)
    t = np.asarray(kin.t, float)
    w = np.random.default_rng(JITTER_SEED).standard_normal(t.size)
    u = _lag(t, w, 20.0 * kin.sample_dt)
    u = np.clip((u - u.mean()) / max(float(np.std(u)), 1e-300), -1.0, 1.0)
    sm = min(max(float(s), 0.0), MAX_DELAY_SAMPLES)
    d = np.minimum(sm * (1.0 + 0.6 * u), MAX_DELAY_SAMPLES) * kin.sample_dt
    return CubicSpline(t, F)(np.clip(t - d, t[0], None))


# -- drift -----------------------------------------------------------------------------------
#: times of ``interval_lubrication``'s shots, x the record [-], and the time over which a
#: shot's effect fades, x the record [-]
SHOTS, SHOT_FADE = (0.15, 0.5, 0.85), 0.1


@on_fine_grid
def interval_lubrication_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Interval lubrication: a central lubrication system shoots grease into the contact at
    :data:`SHOTS` x the record; each shot lowers the Coulomb and Stribeck levels, which
    creep back as the grease is spread and consumed (exponentially over :data:`SHOT_FADE`
    x the record): the levels are the base's times 1 - ``s`` 0.4 sum_k H_k(t) exp(-(t -
    t_k) / tau) (H_k a step at t_k rounded over 0.5 % of the record), inside the bristle
    dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the relative level drop of a shot, / 0.4.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Central (progressive, interval) lubrication of machine-tool axes (SKF, Lincoln
    systems). The open forms change monotonically (a warm-up, a wear-in, a step, heating,
    wear), cycle smoothly with the ambient or rise and fall once; this one drops sharply
    and recovers, three times.
    """
    t = np.asarray(kin.t, float)
    T = float(t[-1] - t[0]) or 1.0
    u = (t - t[0]) / T
    drop = np.zeros_like(u)
    for tk in SHOTS:
        du = u - tk
        drop += 0.5 * (1.0 + np.tanh(du / 0.005)) * np.exp(-np.maximum(du, 0.0) / SHOT_FADE)
    lev = np.clip(1.0 - s * 0.4 * drop, 0.05, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: lost motion of ``worn_gap`` at the record's end at strength 1, as a share of the stroke
#: [-] (the open backlash forms'), and its share at the start [-]
GAP_SHARE, GAP_START = PLANT_GAP_SHARE, 0.4


@njit(cache=True)
def _worn_play(xd, half):
    """Whether the contact is driven [bool] behind a rigid play of half-width ``half[k]``
    [m] (the drive positions ``xd`` [m]); starts centred in the play."""
    n = xd.size
    eng = np.empty(n, dtype=np.bool_)
    xc = xd[0]
    for k in range(n):
        if xd[k] - xc >= half[k]:
            xc = xd[k] - half[k]
            eng[k] = True
        elif xc - xd[k] >= half[k]:
            xc = xd[k] + half[k]
            eng[k] = True
        else:
            eng[k] = False
    return eng


@on_fine_grid
def worn_gap_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A gear play that wears open: its half-width is ``s`` x :data:`GAP_SHARE` x the
    stroke / 2 x (:data:`GAP_START` + (1 - :data:`GAP_START`) D / D_total), D the distance
    the drive has travelled; across the play the contact stands still, engaged it moves
    with the drive; the measured force is the contact's LuGre friction. At ``s`` = 0 the
    contact is always engaged (the base).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m], v [m/s]) and its base law (a classic
        LuGre).
    s : float
        Amplitude factor [-]: the play's final width relative to :data:`GAP_SHARE` x the
        stroke.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Flank wear enlarging a gear's backlash (Flodin and Andersson 2000, gear wear
    simulation by Archard's law). The candidate and the open forms have a constant play
    (rigid, compliant, impact, spring- or oil-bridged) or one varying with the position
    (eccentric gear); this one grows with the travel.
    """
    _lugre_params(kin, "backlash (worn_gap)")
    x = np.ascontiguousarray(kin.x, dtype=float)
    D = np.concatenate(([0.0], np.cumsum(np.abs(np.diff(x)))))
    Dt = max(float(D[-1]), 1e-300)
    half = (0.5 * GAP_SHARE * max(float(s), 0.0) * float(np.ptp(x))
            * (GAP_START + (1.0 - GAP_START) * D / Dt))
    eng = _worn_play(x, half)
    vc = np.where(eng, np.asarray(kin.v, float), 0.0)
    return kin.base.simulate(kin.t, vc)


# -- gms -------------------------------------------------------------------------------------
#: presliding path of ``mindlin_contacts`` at strength 1, as a share of the stroke / 3 [-],
#: and the Hertzian contacts' share of the friction at strength 1 [-]
PRESLIDING_SHARE, MINDLIN_SHARE = 0.02, 0.5


@njit(cache=True)
def _mindlin(x, g, s2v, d_star):
    """Force [N] of Hertzian contacts in partial slip along the positions ``x`` [m]: from
    the last reversal (x_r, u_r) the force follows Masing's doubled Cattaneo-Mindlin curve
    u_r + sgn 2 L (1 - (1 - |x - x_r| / (2 d*))^1.5), L = ``g`` [N] the Stribeck level,
    capped at +- L (sliding); plus the viscous term ``s2v`` [N]. Starts unloaded (the first
    loading too follows the doubled curve, capped)."""
    n = x.size
    F = np.empty(n)
    u = 0.0
    ur = 0.0
    xr = x[0]
    sgn = 0.0
    for k in range(n):
        if k > 0:
            dx = x[k] - x[k - 1]
            if dx != 0.0:
                sk = 1.0 if dx > 0.0 else -1.0
                if sk != sgn:
                    sgn = sk
                    xr = x[k - 1]
                    ur = u
                d = min(abs(x[k] - xr) / (2.0 * d_star), 1.0)
                L = g[k]
                u = ur + sgn * 2.0 * L * (1.0 - (1.0 - d) ** 1.5)
                u = min(max(u, -L), L)
        F[k] = u + s2v[k]
    return F


@on_fine_grid
def mindlin_contacts_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Hertzian contacts in partial slip beside the bristle: a share w = :data:`MINDLIN_SHARE`
    min(``s``, 1) of the friction is carried by ball-like contacts whose presliding follows
    Cattaneo-Mindlin, 1 - (1 - d / d*)^1.5 of the Stribeck level, with Masing's rule from
    the last reversal (the curve doubled), d* the base bristle's path Fs / sigma0 plus
    ``s`` x :data:`PRESLIDING_SHARE` x the stroke / 3; the rest by the base's LuGre: F = (1
    - w) F_lugre + w F_mindlin. At ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the contacts' share (up to ``s`` = 1) and presliding path.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Cattaneo 1938, Mindlin 1949, Mindlin and Deresiewicz 1953 (partial slip of elastic
    spheres). Maxwell-slip (the candidate, ``maxwell4``, ``maxwell10``) is a set of
    elasto-plastic blocks, Dahl a rate-independent exponent law with symmetric stiffness,
    elasto-plastic an elastic range, Bliman-Sorine two path-relaxing states, Bouc-Wen an
    endochronic law, the Zener junction a relaxation in time; this one is the closed-form
    contact-mechanics curve with exponent 1.5 and a reversal memory.
    """
    p = _lugre_params(kin, "gms (mindlin_contacts)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, PRESLIDING_SHARE)
    w = MINDLIN_SHARE * min(float(s), 1.0)
    v = np.ascontiguousarray(kin.v, dtype=float)
    Fm = _mindlin(np.ascontiguousarray(kin.x, dtype=float), kin.base.g(v),
                  float(p.sigma2) * v, e0 + extra)
    return (1.0 - w) * F + w * Fm
