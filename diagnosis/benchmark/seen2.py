"""The second seen family: one more mechanism per effect, now part of the open grid.

Written 2026-11-24 (session 8) as the sealed family, without running the diagnosis on it;
run once at the end of session 8 (170 cases, top-1 41.2 % on 1bba29f; the figures are in
``benchmarks/bench_diagnosis_forms.py``) and moved into the open grid in session 9 (each
effect record's ``truths``, after its other open forms; the new sealed family is
:mod:`.sealed`, the first seen one :mod:`.seen`). Each form is a mechanism of other physics
than the other open forms of its effect and than the candidate's formula
(:mod:`diagnosis.candidates`), integrated along the plant's continuous motion on the grid
:data:`.kinematics.FINE` x finer than the data (:func:`.truths.on_fine_grid`); level changes
act inside the bristle dynamics of a LuGre base (:func:`.truths.level_inside`). ``s`` scales
each effect's amplitude monotonically (its calibration, :func:`.cases._calibrate`, sets the
requested size).

=================  =====================================================================
effect             form (was sealed)
=================  =====================================================================
acceleration       ``contact_aging``: rate-and-state friction with Dieterich's *aging*
                   law: the contact's state grows with the time it is held (healing at
                   rest) and is renewed over a slip distance; the level follows
                   (theta / theta_ss)^s (the open ``slip_memory`` is Ruina's slip law,
                   which does not heal at rest)
load               ``load_stribeck``: the Stribeck velocity proportional to the load to
                   the power ``s`` (a curve of the Hersey number eta v / p: a heavier
                   load thins the film, mixed lubrication lasts to higher speeds); the
                   levels themselves do not depend on the load
asymmetry          ``lip_roll``: a seal lip (an O-ring) that rolls over in its groove
                   after each reversal: a direction state follows the direction of travel
                   over a roll distance of a tenth of the stroke, and the lip drags more
                   (its Coulomb and Stribeck levels, not the viscous term) when rolled
                   for negative travel
stribeck_shape     ``film_liftoff``: mixed lubrication whose asperity load share falls as
                   the film thickness (~ |v|^0.7, elastohydrodynamic) nears the asperity
                   heights and vanishes at a finite lift-off speed (compact asperity
                   heights, share (1 - h/h_max)^2.5): a cusp at rest and a kink at the
                   curve's minimum (the Hersey-number minimum)
position           ``bent_rail``: a guide rail bowed over the stroke (parabolic
                   interference of the preloaded carriage, Hertzian load ~ interference
                   ^1.5) with a scratch across it (a raised-cosine groove 2 % of the
                   stroke wide); the contact load changes, not the viscous drag
inertia            ``geared_inertia``: the drive's rotating inertia reflected through a
                   pinion whose ratio has a once-per-revolution error (5 %, a quarter of
                   the stroke per revolution): J k(x)^2 a + J k(x) k'(x) v^2 (Lagrange
                   with a position-dependent ratio)
delay              ``sigma_delta``: the force channel through a sigma-delta converter's
                   linear-phase decimation FIR (Kaiser-windowed sinc, cut-off 0.45 x the
                   data rate) whose length sets a group delay of ``s`` samples
drift              ``archard_wear``: running-in with the wear volume (Archard: load x
                   sliding distance): the boundary levels fall by ``s`` x (1 - exp(-3 W /
                   W_end)) / (1 - exp(-3)) of the wear W, so the drift follows the travel
                   and the load, not the clock
backlash           ``spring_loaded``: a play bridged by a soft anti-backlash spring (its
                   force at the flank half the Coulomb level) between the drive and a
                   light contact, the flanks a stiff damped coupling: while the drive
                   crosses the play the contact's force ramps with the spring instead of
                   being held (the candidate's ``hold``) or dropping (``free``)
gms                ``bliman_sorine``: the second-order Bliman-Sorine model with the
                   base's Stribeck level: two states relax to their sliding deflection
                   over path lengths 1 : 4, the fast with weight 1 + b, the slow with
                   -b (b up to 0.3): a virgin curve that overshoots the sliding level
                   in the path domain (up to about 15 %) after each reversal, with
                   local memory only (Maxwell-slip blocks rise monotonically, with
                   nonlocal memory); at ``s`` = 0 the base bristle itself
=================  =====================================================================

Where a form applies: as its effect's record (:data:`diagnosis.effects.EFFECTS`,
``truth_applies``); ``film_liftoff`` needs a Stribeck curve (not the isolator's mre_lugre),
``bent_rail`` a record that revisits its positions (not the press), ``spring_loaded`` and
``bliman_sorine`` a classic LuGre base (valve, damping rig, XML-350); each raises a
``ValueError`` elsewhere.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.lugre import bristle_update

from ..effects_backlash import PLANT_GAP_SHARE
from ..effects_gms import PLANT_PRESLIDING_SHARE
from .kinematics import PlantKinematics
from .truths import (GAP_SPRING, MAX_DELAY_SAMPLES, _base_parts, _bump_centre,
                     _contact_constants, _level, _lugre_params, _motion_time, _presliding_path,
                     _run_driven_contact, _span, level_inside, on_fine_grid)

__all__ = ["contact_aging_truth", "load_stribeck_truth", "lip_roll_truth",
           "film_liftoff_truth", "bent_rail_truth", "geared_inertia_truth",
           "sigma_delta_truth", "archard_wear_truth", "spring_loaded_truth",
           "bliman_sorine_truth"]


# -- acceleration ---------------------------------------------------------------------------
@njit(cache=True)
def _aging_state(v, h, Dc, v0):
    """ln(theta / theta_ss) of Dieterich's aging law dtheta/dt = 1 - (|v| + v0) theta / Dc
    (exact for each step's mean speed), theta_ss = Dc / (|v| + v0); starts steady."""
    n = v.size
    r = np.empty(n)
    th = Dc / (abs(v[0]) + v0)
    r[0] = 0.0
    for k in range(1, n):
        w = 0.5 * (abs(v[k]) + abs(v[k - 1])) + v0
        ss = Dc / w
        th = ss + (th - ss) * math.exp(-w * h / Dc)
        r[k] = math.log(th * (abs(v[k]) + v0) / Dc)
    return r


@on_fine_grid
def contact_aging_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Rate-and-state friction with Dieterich's aging law: the contact state theta [s]
    grows with the time the contact is held and is renewed over a slip distance Dc;
    the friction levels are the base's times (theta / theta_ss)^``s``, inside the bristle
    dynamics (above the steady curve after a dwell and while speeding up, below it while
    slowing down).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the exponent b / mu0 of the state's effect on the level.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Dc = 0.05 v99^2 / a99 [m]; the state saturates at rest at Dc / v0 with v0 = 0.05 v99
    [m/s] (the contact's creep limit), so the level stays finite.
    """
    v99 = kin.scales["v99"]
    Dc = 0.05 * v99 * _motion_time(kin)
    r = _aging_state(np.ascontiguousarray(kin.v, dtype=float), kin.dt, Dc, 0.05 * v99)
    return level_inside(kin, np.exp(s * r))


# -- load -------------------------------------------------------------------------------------
@on_fine_grid
def load_stribeck_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The Stribeck velocity proportional to (L / mean L)^``s``: a curve of the Hersey
    number, so a heavier load (a thinner film) keeps the contact in mixed lubrication to
    higher speeds; Coulomb and static levels and the viscous term do not change.
    Isolator (no Stribeck curve): its friction part gains a low-speed excess of half its
    level whose speed scale (a tenth of the top speed at the mean load) follows the load
    the same way.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], load [N]) and its base law.
    s : float
        Amplitude factor [-]: the exponent of the load in the Stribeck velocity.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.
    """
    L = np.clip(kin.load, 0.0, None)
    rel = np.clip(L / max(float(np.mean(L)), 1e-12), 0.05, None)
    q = rel ** s
    v = kin.v
    if kin.base.name == "mre_lugre":
        vs0 = 0.1 * kin.scales["v99"]
        lev = (1.0 + 0.5 * np.exp(-(v / (q * vs0)) ** 2)) / (1.0 + 0.5 * np.exp(-(v / vs0) ** 2))
        return level_inside(kin, lev)
    g = kin.base.g
    return level_inside(kin, g(v / q) / g(v), np.ones_like(v))


# -- asymmetry -------------------------------------------------------------------------------
@njit(cache=True)
def _roll_state(v, h, d, q0):
    """Direction state q in [-1, 1] of a seal lip rolling over a travel ``d`` [m]:
    dq = (sgn v - q) |dx| / d (exact for each step), starting at ``q0``."""
    n = v.size
    q = np.empty(n)
    c = q0
    q[0] = q0
    for k in range(1, n):
        vm = 0.5 * (v[k] + v[k - 1])
        if vm != 0.0:
            sg = 1.0 if vm > 0.0 else -1.0
            c = sg + (c - sg) * math.exp(-abs(vm) * h / d)
        q[k] = c
    return q


@on_fine_grid
def lip_roll_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A seal lip (O-ring) rolling over in its groove after each reversal: a direction
    state q follows the direction of travel over a roll distance of a tenth of the
    stroke (starting rolled for the record's first direction), and the Coulomb and
    Stribeck levels are 1 + ``s`` (1 - q) / 2 times the base's (the lip drags more when
    rolled for negative travel), inside the bristle dynamics; the viscous term is the
    base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], x [m]) and its base law.
    s : float
        Amplitude factor [-]: the relative extra drag of the lip rolled for negative travel.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.
    """
    v = np.ascontiguousarray(kin.v, dtype=float)
    moving = np.flatnonzero(np.abs(v) > 0.02 * kin.scales["v99"])
    q0 = float(np.sign(v[moving[0]])) if moving.size else 0.0   # rolled for the first travel
    q = _roll_state(v, kin.dt, 0.1 * _span(kin), q0)
    return level_inside(kin, 1.0 + s * 0.5 * (1.0 - q), np.ones_like(q))


# -- stribeck_shape --------------------------------------------------------------------------
@on_fine_grid
def film_liftoff_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Mixed lubrication with a finite lift-off speed: the film thickness grows as
    |v|^0.7 (elastohydrodynamic), the asperities' share of the load as (1 - u)^2.5 with
    u = (|v| / v_lo)^0.7 until it vanishes at v_lo (asperity heights of compact support),
    so the curve is Fc + (Fs - Fc) (1 - u)_+^2.5: a cusp at rest and a kink at its
    minimum; v_lo = 3 v_s but at least 10 % of the top speed. The ratio of that curve to
    the base's is raised to the power ``s``, inside the bristle dynamics.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (a Stribeck curve).
    s : float
        Amplitude factor [-]: the power of the curves' ratio.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.
    """
    if kin.base.name == "mre_lugre":
        raise ValueError("stribeck_shape (film_liftoff): the mre_lugre base has no Stribeck "
                         "curve")
    p = kin.base.params
    v = kin.v
    v_lo = max(3.0 * p.vs, 0.1 * kin.scales["v99"])
    u = (np.abs(v) / v_lo) ** 0.7
    curve = p.Fc + (p.Fs - p.Fc) * np.clip(1.0 - u, 0.0, None) ** 2.5
    return level_inside(kin, (curve / kin.base.g(v)) ** s, np.ones_like(v))


# -- position --------------------------------------------------------------------------------
@on_fine_grid
def bent_rail_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A guide rail bowed over the stroke with a scratch across it: the carriage's
    preload interference is 1 + ``s`` (4 u (1 - u) - 2/3) of its nominal (u the position
    along the visited stroke, a parabolic bow of mean zero), the contact load its power
    1.5 (Hertz), and a scratch where fit and held-out parts both pass raises it by
    ``s`` / 2 over a raised-cosine groove 2 % of the stroke wide; the Coulomb and
    Stribeck levels follow the load inside the bristle dynamics, the viscous term not.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the bow's interference relative to the nominal preload's.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.
    """
    xc = _bump_centre(kin)
    if xc is None:
        raise ValueError(f"position (bent_rail): the held-out part of the {kin.plant} record "
                         f"never revisits the positions of its fit part")
    span = _span(kin)
    u = (kin.x - kin.scales["x_lo"]) / span
    bow = np.clip(1.0 + s * (4.0 * u * (1.0 - u) - 2.0 / 3.0), 0.0, None) ** 1.5
    w = 0.02 * span
    d = np.clip(np.abs(kin.x - xc) / w, 0.0, 1.0)
    scratch = 0.5 * (1.0 + np.cos(np.pi * d))
    lev = np.clip(bow * (1.0 + 0.5 * s * scratch), 0.05, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- inertia ---------------------------------------------------------------------------------
#: ratio error of the ``geared_inertia`` pinion (once per revolution) [-]
GEAR_RATIO_ERROR = 0.05
#: travel per pinion revolution of ``geared_inertia``, as a share of the stroke [-]
GEAR_REVOLUTION_SHARE = 0.25


@on_fine_grid
def geared_inertia_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The drive's rotating inertia J reflected through a pinion whose ratio k(x) = k0
    (1 + e sin(2 pi x / p)) [rad/m] has a once-per-revolution error e (5 %, travel p a
    quarter of the stroke per revolution): from T = J k(x)^2 v^2 / 2 the inverse dynamics
    misses J k^2 a + J k k' v^2; J k0^2 = ``s`` x the friction level / a99 [kg].

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the reflected inertia relative to level / a99.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.
    """
    F, _ = _base_parts(kin)
    sc = kin.scales
    J = s * _level(kin) / max(sc["a99"], 1e-12)       # J k0^2 [kg]
    kw = 2.0 * np.pi / (GEAR_REVOLUTION_SHARE * _span(kin))
    ph = kw * (kin.x - sc["x_lo"])
    k = 1.0 + GEAR_RATIO_ERROR * np.sin(ph)                # k / k0 [-]
    dk = GEAR_RATIO_ERROR * kw * np.cos(ph)                # k' / k0 [1/m]
    return F + J * (k * k * kin.a + k * dk * kin.v * kin.v)


# -- delay -----------------------------------------------------------------------------------
@on_fine_grid
def sigma_delta_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force channel through a sigma-delta converter's decimation filter: a
    linear-phase FIR, a sinc of cut-off 0.45 x the data rate under a Kaiser window
    (beta 6) centred ``s`` data samples back (at most :data:`.truths.MAX_DELAY_SAMPLES`),
    unit DC gain, run causally on the fine grid from a settled start; its group delay is
    ``s`` samples, its step response rings before and after the edge.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid and its base law.
    s : float
        Amplitude factor [-]: the group delay [data samples].

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.
    """
    F, _ = _base_parts(kin)
    D = min(max(float(s), 0.0), MAX_DELAY_SAMPLES) * kin.step   # [fine steps]
    W = D + 1.0                                                  # window half-width
    j = np.arange(int(np.floor(2.0 * D)) + 2, dtype=float)
    fc = 0.45 / kin.step                                         # [cycles per fine step]
    win = np.i0(6.0 * np.sqrt(np.clip(1.0 - ((j - D) / W) ** 2, 0.0, None))) / np.i0(6.0)
    taps = 2.0 * fc * np.sinc(2.0 * fc * (j - D)) * win
    taps /= taps.sum()
    pad = np.concatenate((np.full(taps.size - 1, F[0]), F))
    return np.convolve(pad, taps, mode="valid")


# -- drift -----------------------------------------------------------------------------------
@on_fine_grid
def archard_wear_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Running-in with the wear volume: by Archard's law the volume worn grows as load x
    sliding distance, W(t) = int L |v| dt, and the boundary levels (Coulomb and Stribeck,
    inside the bristle dynamics; the viscous film's not) fall by ``s`` (1 - exp(-3 W /
    W_end)) / (1 - exp(-3)) as the asperities flatten: the drift follows the travel and
    the load, standing still while the contact does.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s], load [N]) and its base law.
    s : float
        Amplitude factor [-]: the relative fall of the levels over the record.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.
    """
    rate = np.clip(kin.load, 0.0, None) * np.abs(kin.v)
    W = np.concatenate(([0.0], np.cumsum(0.5 * (rate[1:] + rate[:-1]) * np.diff(kin.t))))
    if not W[-1] > 0:
        raise ValueError(f"drift (archard_wear): the {kin.plant} record does no sliding under "
                         f"load")
    wear = (1.0 - np.exp(-3.0 * W / W[-1])) / (1.0 - np.exp(-3.0))
    lev = np.clip(1.0 - s * wear, 0.05, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: lost motion of ``spring_loaded`` at strength 1, as a share of the stroke [-] (the open
#: backlash forms')
GAP_SHARE = PLANT_GAP_SHARE


@on_fine_grid
def spring_loaded_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A play of width ``s`` x :data:`GAP_SHARE` x the stroke bridged by a soft
    anti-backlash spring whose force at the flank is half the Coulomb level, between the
    drive (the record's motion) and a light contact with the base's LuGre friction (its
    inertial force at the top acceleration 1 % of the Coulomb level); the flanks a
    coupling 100 x stiffer than the bristle, damping ratio 0.5. The measured force is the
    contact's friction: while the drive crosses the play it ramps with the spring. At
    ``s`` = 0 the contact follows the drive through the stiff coupling (the base).

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
    """
    p = _lugre_params(kin, "backlash (spring_loaded)")
    half = 0.5 * GAP_SHARE * max(float(s), 0.0) * float(np.ptp(kin.x))
    m, kh, ch = _contact_constants(kin, p)
    ks = kh if half <= 0.0 else min(0.5 * float(p.Fc) / half, kh)
    return _run_driven_contact(kin, p, half, GAP_SPRING, ks, 0.0, m, kh, ch)


# -- gms -------------------------------------------------------------------------------------
#: presliding path ``bliman_sorine`` adds at strength 1, as a share of the stroke [-]: the
#: fast state's path constant grows by a third of it (the open gms forms' presliding
#: distance)
PRESLIDING_SHARE = PLANT_PRESLIDING_SHARE
#: largest weight b of the slow state of ``bliman_sorine`` [-] and its path constant over
#: the fast state's [-]
BS_WEIGHT, BS_RATIO = 0.3, 4.0


@njit(cache=True)
def _two_bristles(t, v, g, g_mid, k1, k2):
    """Deflections y1, y2 [m] and their rates [m/s] of two bristles of stiffness ``k1``,
    ``k2`` [N/m] under the Stribeck level ``g`` [N] (at the grid points, ``g_mid`` at the
    step midpoints): dy_i/dt = v - k_i |v| y_i / g, advanced as the benchmark's LuGre
    kernel advances its bristle (:func:`friction.lugre.bristle_update`); start unloaded."""
    n = t.size
    y = np.zeros((4, n))
    a = 0.0
    b = 0.0
    for k in range(n):
        y[0, k] = a
        y[1, k] = b
        y[2, k] = v[k] - k1 * abs(v[k]) * a / g[k]
        y[3, k] = v[k] - k2 * abs(v[k]) * b / g[k]
        if k + 1 < n:
            vm = 0.5 * (v[k] + v[k + 1])
            h = t[k + 1] - t[k]
            a = bristle_update(a, vm, k1 * abs(vm) / g_mid[k], h, 0)
            b = bristle_update(b, vm, k2 * abs(vm) / g_mid[k], h, 0)
    return y


@on_fine_grid
def bliman_sorine_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The second-order Bliman-Sorine presliding model with the base's Stribeck level:
    two states relax to their sliding deflection over path lengths e1 and
    :data:`BS_RATIO` e1 (bristles of stiffness k1 = Fs / e1 and k1 / :data:`BS_RATIO`
    under the level g(v)), the fast one with weight 1 + b, the slow one with -b:
    F = k1 ((1 + b) y1 - b y2 / R) + sigma1 d/dt[...] / (sigma0 / k1) + sigma2 v, the
    steady force the base's g(v) + sigma2 v; after a reversal the force overshoots its
    sliding level in the path domain (by up to about 15 %), then settles, with local
    memory only. e1 = Fs / sigma0 (the base bristle's) + ``s`` x
    :data:`PRESLIDING_SHARE` x the stroke / 3 and b = :data:`BS_WEIGHT` x the share of e1
    beyond the bristle's: at ``s`` = 0 the model is the base LuGre.

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
    """
    p = _lugre_params(kin, "gms (bliman_sorine)")
    s0 = float(p.sigma0)
    e0, extra = _presliding_path(kin, s, PRESLIDING_SHARE)
    e1 = e0 + extra
    b = BS_WEIGHT * extra / e1
    k1 = float(p.Fs) / e1
    v = np.ascontiguousarray(kin.v, dtype=float)
    g = kin.base.g
    y = _two_bristles(kin.t, v, g(v), g(0.5 * (v[1:] + v[:-1])), k1, k1 / BS_RATIO)
    zeq = (1.0 + b) * y[0] - b * y[1] / BS_RATIO
    zeq_rate = (1.0 + b) * y[2] - b * y[3] / BS_RATIO
    return k1 * zeq + float(p.sigma1) * (k1 / s0) * zeq_rate + float(p.sigma2) * v
