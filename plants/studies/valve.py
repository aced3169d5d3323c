"""Seed 000 studies on the voice-coil valve: the friction loops of Figs. 5-7, the
steady-state tests of Fig. 9 and the explicit-Euler observer of Fig. 10, with their
figures (the valve part of the ``plants`` demo stage).

* :func:`loops_at`, :func:`loop_features` - friction-velocity loops recovered as the paper
  does (:func:`plants.valve.recover_friction`) and their double-hysteresis features;
* :func:`stribeck_points` - friction at constant speeds (Fig. 9);
* :func:`euler_observer` - the observer's stability (Eqs. 27-30);
* :func:`demo_figures` - the loops and the Euler observer figures.

Explicit-Euler observer (Eqs. 27-30, :func:`euler_observer`): the classic LuGre state
update ``z += h (v - sigma0 |v| z / g)`` has the factor ``1 - h sigma0 |v| / g`` which turns
negative above ``v_cr = g / (sigma0 h)`` (an observer error then flips sign every sample:
oscillation) and exceeds 1 in magnitude above ``2 v_cr`` (divergence). The default friction
has ``Fc / sigma0 = 6 N / 4.86e5 N/m = 1.235e-5 m``, so ``v_cr = 0.247 m/s`` at h = 50 us, the
value the paper reports for its 10 Hz / 8 mm run. Note the honest limit of this mechanism:
in steady sliding ``z = g / sigma0`` is an exact fixed point of the Euler update whatever
``h``, so the oscillation shows as the sign-alternating response to an observer error (a
measurement glitch, a wrong initial state); it is the observer error, not the undisturbed
trajectory, that oscillates and, above ``2 v_cr``, grows.
"""
from __future__ import annotations

import math

import numpy as np

from friction.base import FrictionModel

from ..valve import (FREQUENCIES, SAMPLE_RATE, ValveActuator, classic_lugre_twin,
                     recover_friction, sine_reference)

from ._figures import folder, pyplot, save

__all__ = ["stribeck_points", "euler_observer", "loop_features", "loops_at", "demo_figures"]


def stribeck_points(speeds, *, plant: ValveActuator | None = None, travel: float = 2e-3,
                    progress=None) -> np.ndarray:
    """Seed 000's steady-state tests (Fig. 9): friction at constant speeds by Eq. (1).

    Each speed runs a stroke under velocity control; the recovered friction is averaged
    over the constant-speed part after the first quarter of the travel.

    Parameters
    ----------
    speeds : array_like
        Speeds [m/s] (signed, nonzero; the paper used 48 in +-0.02 m/s).
    plant : ValveActuator, optional
    travel : float
        Lift travelled at constant speed [m] (within the 8 mm stroke).

    Returns
    -------
    ndarray, shape (n, 2)
        Mean velocity [m/s] and mean recovered friction [N] per speed.
    """
    plant = plant or ValveActuator()
    out = []
    for sp in np.asarray(speeds, float):
        if sp == 0 or not np.isfinite(sp):
            raise ValueError(f"speed {sp!r} m/s: steady-state tests need a nonzero speed")
        ta = float(plant.opts["t_acc"])
        T = ta + travel / abs(sp)
        res = plant.simulate(T, speed=float(sp), progress=progress)
        rec = recover_friction(res, plant, cutoff=min(1000.0, 0.45 * SAMPLE_RATE))
        m = rec["t"] > ta + 0.25 * (T - ta)
        m &= rec["t"] < T - 0.05 * (T - ta)   # filtfilt edge
        out.append((float(np.mean(rec["v"][m])), float(np.mean(rec["F"][m]))))
    return np.array(out)


def euler_observer(law: FrictionModel, t, v, *, a=None, h_inject: float | None = None,
                   rel: float = 0.05):
    """Explicit-Euler observer of ``law`` along (t, v) and its response to an observer error.

    Parameters
    ----------
    law : FrictionModel
        Classic or modified LuGre (state ``z`` first).
    t, v : array_like
        Time [s] (uniform, h = sample interval) and velocity [m/s] fed to the observer.
    a : array_like, optional
        Acceleration [m/s^2] for acceleration-dependent laws.
    h_inject : float, optional
        Time [s] at which an observer error ``rel * |z|`` is injected (default: the first
        sample where ``h sigma0 |v| / g(v) > 1``, or the speed peak if never).
    rel : float
        Relative size of the injected error.

    Returns
    -------
    dict
        ``z`` (Euler state), ``factor`` = 1 - h sigma0 |v| / g(v) per sample (the homogeneous
        factor of Eq. 29 for the classic law), ``onset_time``/``onset_speed`` of factor < 0
        (``nan`` if never), ``error`` (propagated observer error from the injection on),
        ``k0`` (injection index).
    """
    t = np.asarray(t, float)
    v = np.asarray(v, float)
    h = float(np.mean(np.diff(t)))
    kw = {} if a is None else {"a": np.asarray(a, float)}
    F, S = law.simulate(t, v, method="euler", return_state=True, **kw)
    z = S[:, 0]
    p = law.params
    g = _g_of(law, v)
    factor = 1.0 - h * p.sigma0 * np.abs(v) / g
    neg = np.flatnonzero(factor < 0)
    onset_t = float(t[neg[0]]) if neg.size else math.nan
    onset_v = float(abs(v[neg[0]])) if neg.size else math.nan
    if h_inject is None:
        k0 = int(neg[0]) if neg.size else int(np.argmax(np.abs(v)))
    else:
        k0 = int(np.searchsorted(t, h_inject))
    s0 = S[k0].copy()
    s0[0] += rel * max(abs(s0[0]), 1e-30)
    kw2 = {} if a is None else {"a": kw["a"][k0:]}
    _, S2 = law.simulate(t[k0:], v[k0:], method="euler", return_state=True, state0=s0, **kw2)
    err = S2[:, 0] - z[k0:]
    return {"t": t, "z": z, "F": F, "factor": factor, "onset_time": onset_t,
            "onset_speed": onset_v, "error": err, "k0": k0}


def _g_of(law, v):
    if hasattr(law, "g"):
        return np.asarray(law.g(v), float)
    p = law.params
    from friction.shapes import stribeck_g_np
    return stribeck_g_np(v, p.Fc, p.Fs, p.vs, p.alpha, p.shape)


def loop_features(v, F, *, band: tuple[float, float] = (0.3, 0.8), acc=None):
    """Double-hysteresis features of a friction-velocity loop (seed 000 Figs. 5-7).

    Parameters
    ----------
    v, F : array_like
        Velocity [m/s] and friction [N] over whole cycles.
    band : (float, float)
        Speed band, as fractions of max |v|, where the vertical loop is measured.
    acc : array_like, optional
        Acceleration [m/s^2] (default: gradient of v).

    Returns
    -------
    dict
        ``vertical``: mean of F(accelerating) - F(decelerating) over the band, both
        directions, sign-corrected so that > 0 means the paper's clockwise vertical loop
        (more friction while accelerating) [N];
        ``horizontal``: v(F = 0 on the rising crossing) - v(F = 0 on the falling one) [m/s],
        > 0 for the counter-clockwise pre-sliding loop (force lags the velocity reversal).
    """
    v = np.asarray(v, float)
    F = np.asarray(F, float)
    acc = np.gradient(v) if acc is None else np.asarray(acc, float)
    vmax = np.max(np.abs(v))
    lo, hi = band[0] * vmax, band[1] * vmax
    diffs = []
    for sgn in (1.0, -1.0):
        m = (sgn * v > lo) & (sgn * v < hi)
        up = m & (sgn * acc > 0)
        dn = m & (sgn * acc < 0)
        if up.sum() < 3 or dn.sum() < 3:
            continue
        grid = np.linspace(lo, hi, 20)
        fu = np.interp(grid, sgn * v[up][np.argsort(sgn * v[up])],
                       sgn * F[up][np.argsort(sgn * v[up])])
        fd = np.interp(grid, sgn * v[dn][np.argsort(sgn * v[dn])],
                       sgn * F[dn][np.argsort(sgn * v[dn])])
        diffs.append(np.mean(fu - fd))
    vertical = float(np.mean(diffs)) if diffs else math.nan
    # zero crossings of F: velocity there, split by direction of the force change
    s = np.sign(F)
    idx = np.flatnonzero(s[:-1] * s[1:] < 0)
    rising = [v[k] for k in idx if F[k + 1] > F[k]]
    falling = [v[k] for k in idx if F[k + 1] < F[k]]
    horizontal = (float(np.median(rising) - np.median(falling))
                  if rising and falling else math.nan)
    return {"vertical": vertical, "horizontal": horizontal}


def loops_at(freqs=FREQUENCIES, magnitude=8e-3, cycles: float = 2.0, plant=None,
             progress=None):
    """Simulate the sinusoid grid and recover friction loops (last cycle of each run)."""
    plant = plant or ValveActuator()
    out = {}
    for f in freqs:
        stop = cycles / f
        res = plant.simulate(stop, freq=f, magnitude=magnitude, progress=progress)
        rec = recover_friction(res, plant)
        n = int(round(SAMPLE_RATE / f))
        sl = slice(rec["t"].size - n - 1, rec["t"].size - 1)
        out[f] = {"res": res, "rec": {k: val[sl] for k, val in rec.items()},
                  "true_F": np.asarray(res["F"])[sl]}
    return out


def demo_figures(out, summary: dict, quick: bool = True):
    """Valve figures: friction-velocity loops (Figs. 5-7) and the Euler observer (Fig. 10)."""
    plt = pyplot()
    out = folder(out)
    plant = ValveActuator()
    freqs = (5.0, 10.0) if quick else FREQUENCIES
    loops = loops_at(freqs, cycles=1.5 if quick else 2.0, plant=plant)
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    feats = {}
    for f, d in loops.items():
        r = d["rec"]
        ax[0].plot(r["v"], r["F"], lw=0.8, label=f"{f:g} Hz")
        ax[1].plot(r["x"] * 1e3, r["F"], lw=0.8, label=f"{f:g} Hz")
        fe = loop_features(r["v"], r["F"], acc=r["a"])
        feats[f"{f:g}Hz"] = {k: round(val, 4) for k, val in fe.items()}
    ax[0].set(xlabel="v [m/s]", ylabel="recovered friction [N]",
              title="friction-velocity loops, 8 mm (seed 000 Fig. 6)")
    ax[1].set(xlabel="S [mm]", ylabel="recovered friction [N]", title="friction-displacement")
    ax[0].legend()
    p1 = save(fig, out / "valve_loops.png")

    law = plant.friction
    classic = classic_lugre_twin(law)
    fig, ax = plt.subplots(1, 3, figsize=(15, 4))
    obs = {}
    t = np.arange(0.0, 0.1, 1.0 / SAMPLE_RATE)
    for f in (5.0, 10.0, 20.0):
        _, vr, ar = sine_reference(t, f, 8e-3)
        c = euler_observer(classic, t, vr)
        ax[2].plot(t * 1e3, c["factor"], label=f"{f:g} Hz")
        obs[f"{f:g}Hz"] = {k: (None if math.isnan(c[k]) else round(c[k], 5))
                           for k in ("onset_time", "onset_speed")}
        akw = {"a": ar} if "a" in law.extra_inputs else {}
        if f == 10.0:   # oscillation: error injected at the onset flips sign every sample
            e = c["error"][:12] / c["error"][0]
            k = np.arange(e.size)
            ax[1].semilogy(k, np.abs(e), "k-", lw=0.5)
            ax[1].semilogy(k[e > 0], e[e > 0], "o", label="classic, error > 0")
            ax[1].semilogy(k[e < 0], -e[e < 0], "s", label="classic, error < 0")
            m = euler_observer(law, t, vr, h_inject=t[c["k0"]], **akw)
            ax[1].semilogy(k, np.abs(m["error"][:12] / m["error"][0]), "^-",
                           label=f"{law.name}")
        if f == 20.0:   # divergence: above 2 v_cr the injected error grows while it flips
            kg = int(np.argmax(c["factor"] < -1.0))
            g = euler_observer(classic, t, vr, h_inject=t[kg])
            m = euler_observer(law, t, vr, h_inject=t[kg], **akw)
            n = 90
            ax[0].plot(np.arange(n), g["error"][:n] / g["error"][0], ".-", label="classic LuGre")
            ax[0].plot(np.arange(n), m["error"][:n] / m["error"][0], ".-", label=law.name)
    ax[0].set(xlabel="samples after injection", ylabel="error / injected error",
              title="20 Hz / 8 mm: Euler observer error (h = 50 us)")
    ax[1].set(xlabel="samples after injection", ylabel="|error| / injected error",
              title="10 Hz / 8 mm: sign flips from the onset (0.0225 s)")
    ax[2].axhline(0, color="k", lw=0.5)
    ax[2].axhline(-1, color="k", lw=0.5, ls="--")
    ax[2].set(xlabel="t [ms]", ylabel="1 - h sigma0 |v| / g", title="Euler factor (Eq. 29)")
    for a_ in ax:
        a_.legend(fontsize=7)
    p2 = save(fig, out / "valve_euler_observer.png")
    summary.setdefault("figures", []).extend([str(p1), str(p2)])
    summary["valve"] = {"loops": feats, "euler_onset": obs,
                        "v_cr": float(law.params.Fc / (law.params.sigma0 / SAMPLE_RATE))}
    return [p1, p2]
