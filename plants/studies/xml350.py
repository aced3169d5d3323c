"""Seed 003 studies on the XML-350 stage: the paper's compensation results and the loop's
stability, and their figures (the XML-350 part of the ``plants`` demo stage).

* :data:`PAPER_REDUCTIONS`, :data:`MOVES` - Table II and the paper's S-curve moves;
* :func:`compensation_reduction`, :func:`tracking_metrics` - the tracking-error reduction by
  the LuGre feedforward on one move; :func:`mismatch_table` - how it falls when the
  compensator's parameters are off;
* :func:`run_assembled` - the loop assembled from the separate steppers of
  :func:`plants.xml350.loop_parts` with a Gauss-Seidel master (reproduces
  :class:`plants.xml350.XML350` to round-off with the law inside the mechanics);
* :func:`loop_spectral_radius` - stability of the linearised sampled position loop (why
  :class:`plants.xml350.XML350` uses the SD-PID with the 400 Hz current loop);
* :func:`demo_figures` - compensation, mismatch and identification-protocol figures.
"""
from __future__ import annotations

import json
import math
import os

import numpy as np

from friction.base import FrictionModel

from ..xml350 import XML350, XML350Params, loop_parts, xml350_friction

from ._figures import pyplot, save

__all__ = ["PAPER_REDUCTIONS", "MOVES", "run_assembled", "tracking_metrics",
           "compensation_reduction", "mismatch_table", "loop_spectral_radius",
           "plot_compensation", "plot_mismatch", "demo_figures"]

#: seed 003 Table II: fractional tracking-error reductions by the LuGre feedforward
PAPER_REDUCTIONS = {"100um": {"rms_reduction": 0.923, "peak_reduction": 0.939},
                    "1um": {"rms_reduction": 0.873, "peak_reduction": 0.884}}
#: the paper's point-to-point moves [m]
MOVES = {"100um": 1e-4, "1um": 1e-6}


def run_assembled(stop_time: float = 0.06, *, separate_friction: bool = False,
                  exchanges: int = 1, **part_options) -> np.ndarray:
    """The XML-350 loop assembled from the separate steppers of :func:`loop_parts`.

    Gauss-Seidel order at each 10 kHz control instant: trajectory -> feedforward (fed
    ``x_ff, v_ff, a_ff``) -> controller (fed the mechanics' encoder output and ``u_ff``; the
    trajectory's ``a_ff`` is its ``a_d``) -> current command ``i_cmd = M_ctrl u / Kf``. The
    mechanics then advance over the control period in ``exchanges`` communication steps;
    with a separate friction component, friction and mechanics exchange ``v`` and
    ``F_friction`` at each of them (force held over a step). With the law inside the
    mechanics this reproduces :class:`XML350` to round-off.

    Parameters
    ----------
    stop_time : float
        End time [s].
    separate_friction : bool
        Friction as its own component (the friction FMU) instead of inside the mechanics.
    exchanges : int
        Communication steps per control period between friction and mechanics (the
        coupling's zero-order hold error falls with their number).
    **part_options
        Passed to :func:`loop_parts` (distance, compensation, friction, compensator, ...).

    Returns
    -------
    ndarray
        Structured array ``time, x, x_d, e, i_cmd`` at the control rate.
    """
    parts = loop_parts(separate_friction=separate_friction, **part_options)
    p = parts["params"]
    Ts = p.Ts
    hc = Ts / int(exchanges)
    traj, pid, mech = parts["trajectory"], parts["controller"], parts["mechanics"]
    ff, fric = parts.get("feedforward"), parts.get("friction")
    n = int(round(stop_time / Ts))
    rows = np.empty((n + 1, 5))

    def couple():
        if fric is not None:
            fric.set_inputs({"v": mech.outputs()["v"]})
            mech.set_inputs({"F_friction": fric.outputs()["F"]})

    for k in range(n + 1):
        t = k * Ts
        ref = traj.outputs()
        u_ff = 0.0
        if ff is not None:
            ff.set_inputs({"x_d": ref["x_ff"], "v_d": ref["v_ff"], "a_d": ref["a_ff"]})
            u_ff = ff.outputs()["u_ff"]
        couple()
        mo = mech.outputs()
        pid.set_inputs({"x_d": ref["x_d"], "v_d": ref["v_d"], "a_d": ref["a_ff"],
                        "x_f": ref["x_f"], "x": mo["x_meas"], "u_ff": u_ff})
        i_cmd = p.M_ctrl * pid.outputs()["u"] / p.Kf
        mech.set_inputs({"i_cmd": i_cmd})
        rows[k] = (t, mo["x"], ref["x_d"], ref["x_d"] - mo["x"], i_cmd)
        if k == n:
            break
        for c in (traj, ff, pid):
            if c is not None:
                c.do_step(t, Ts)
        for j in range(int(exchanges)):
            if j > 0:
                couple()
            tj = t + j * hc
            if fric is not None:
                fric.do_step(tj, hc)
            mech.do_step(tj, hc)
    names = ("time", "x", "x_d", "e", "i_cmd")
    out = np.empty(n + 1, dtype=[(nm, "f8") for nm in names])
    for j, nm in enumerate(names):
        out[nm] = rows[:, j]
    return out


def tracking_metrics(result: np.ndarray, window: tuple[float, float] | None = None
                     ) -> dict[str, float]:
    """RMS and peak of the tracking error ``e = x_d - x`` [m] over ``window`` [s]."""
    t = result["time"]
    sel = np.ones(t.size, bool) if window is None else (t >= window[0]) & (t <= window[1])
    e = result["e"][sel]
    return {"rms": float(np.sqrt(np.mean(e ** 2))), "peak": float(np.max(np.abs(e)))}


def compensation_reduction(distance: float = 1e-4, *, compensator: FrictionModel | None = None,
                           plant: XML350 | None = None, stop_time: float | None = None,
                           method: str = "fast", baseline: np.ndarray | None = None,
                           return_results: bool = False, **options) -> dict:
    """Tracking-error reduction by the LuGre feedforward on one S-curve move.

    Parameters
    ----------
    distance : float
        Move length [m].
    compensator : FrictionModel, optional
        Feedforward law (default: the plant's own law, a perfect model).
    plant : XML350, optional
        Stage (default: seed 003 numbers and friction).
    stop_time : float, optional
        End of the run [s] (default experiment's stop). Errors are measured from the move
        start to ``stop_time`` (move plus settling).
    baseline : structured array, optional
        An uncompensated run to reuse (saves one simulation in sweeps).
    **options
        Further XML-350 experiment options.

    Returns
    -------
    dict
        ``rms_reduction``, ``peak_reduction`` (1 - compensated / uncompensated), and the
        ``rms``/``peak`` errors [m] of both runs (``*_off``, ``*_on``).
    """
    plant = plant or XML350()
    kw = dict(distance=distance, **options)
    off = baseline if baseline is not None else plant.simulate(stop_time, method=method,
                                                               compensation=False, **kw)
    on = plant.simulate(stop_time, method=method, compensation=True, compensator=compensator,
                        **kw)
    window = (plant.with_options(**kw).move_window()[0], float(on["time"][-1]))
    m_off, m_on = tracking_metrics(off, window), tracking_metrics(on, window)
    out = {"rms_reduction": 1.0 - m_on["rms"] / m_off["rms"],
           "peak_reduction": 1.0 - m_on["peak"] / m_off["peak"],
           "rms_off": m_off["rms"], "rms_on": m_on["rms"],
           "peak_off": m_off["peak"], "peak_on": m_on["peak"]}
    if return_results:
        out["results"] = (off, on)
    return out


def mismatch_table(levels=(0.1, 0.2, 0.3), names=("Fc", "Fs", "sigma0", "sigma1", "sigma2",
                                                   "vs", "all"),
                   moves=None, signs=(1, -1), plant: XML350 | None = None,
                   progress=None) -> list[dict]:
    """How the feedforward's benefit falls when the compensator's parameters are off.

    For each move, parameter (``"all"``: every listed parameter at once), level and sign,
    the compensator is the plant's law with that parameter scaled by ``1 + sign * level``.

    Returns
    -------
    list of dict
        Rows ``{"move", "param", "error", "rms_reduction", "peak_reduction"}`` where
        ``error`` is the signed relative parameter error (e.g. -0.2); the first rows per
        move are the exact compensator (``param="exact"``, ``error=0``).
    """
    plant = plant or XML350()
    law = plant.friction
    moves = moves or MOVES
    singles = [n for n in names if n != "all"]
    rows = []
    total = len(moves) * (1 + len(names) * len(levels) * len(signs))
    done = 0
    for label, dist in moves.items():
        off = plant.simulate(compensation=False, distance=dist)
        r = compensation_reduction(dist, plant=plant, baseline=off)
        rows.append({"move": label, "param": "exact", "error": 0.0,
                     "rms_reduction": r["rms_reduction"],
                     "peak_reduction": r["peak_reduction"]})
        done += 1
        for name in names:
            for level in levels:
                for sg in signs:
                    f = 1.0 + sg * level
                    keys = singles if name == "all" else [name]
                    comp = law.with_values(**{k: getattr(law.params, k) * f for k in keys})
                    r = compensation_reduction(dist, plant=plant, baseline=off,
                                               compensator=comp)
                    rows.append({"move": label, "param": name, "error": sg * level,
                                 "rms_reduction": r["rms_reduction"],
                                 "peak_reduction": r["peak_reduction"]})
                    done += 1
                    if progress is not None:
                        progress(1, f"{label} {name} {sg * level:+.0%}")
    del total, done
    return rows


def loop_spectral_radius(params: XML350Params | None = None, *, controller: str = "pid",
                         distance_to_target: float = math.inf,
                         friction: FrictionModel | None = None,
                         presliding: bool = False) -> float:
    """Spectral radius of the linearised sampled position loop (< 1: stable).

    The stage ``M x'' = K_f i - c v - k x`` (sliding: ``c = sigma2``, ``k = 0``;
    pre-sliding: ``c = sigma1``, ``k = sigma0`` of the law), the first-order current loop,
    the ZOH at ``Ts`` and the discrete (SD-)PID with frozen gains at the given distance to
    the target (Eq. 15), the velocity error by backward difference as in
    :class:`plants.controllers.PID`.

    Parameters
    ----------
    params : XML350Params, optional
    controller : {"pid", "sdpid"}
    distance_to_target : float
        ``|x_f - x|`` [m] at which the SD-PID gains are frozen (``inf``: nominal gains).
    friction : FrictionModel, optional
        LuGre-type law for the linearisation (default: the stage's).
    presliding : bool
        Linearise in pre-sliding (bristle spring) instead of sliding.
    """
    from scipy.linalg import expm  # analysis helper, not used by the simulation

    p = params or XML350Params()
    law = friction or xml350_friction()
    pid = p.pid(state_dependent=controller == "sdpid")
    d = distance_to_target
    kp, ki, kd = pid.gains(0.0, d) if math.isfinite(d) else (p.Kp, p.Ki, p.Kd)
    lp = law.params
    k_f, c_f = (lp.sigma0, lp.sigma1 + lp.sigma2) if presliding else (0.0, lp.sigma2)
    wc = 2 * math.pi * p.f_current
    A = np.array([[0.0, 1.0, 0.0], [-k_f / p.M, -c_f / p.M, p.Kf / p.M], [0.0, 0.0, -wc]])
    B = np.array([0.0, 0.0, wc])
    Ts = p.Ts
    # ZOH discretisation through the augmented matrix exponential
    E = expm(np.block([[A, B[:, None]], [np.zeros((1, 4))]]) * Ts)
    Ad, Bd = E[:3, :3], E[:3, 3]
    # state [x, v, i, I, e_prev]; e = -x; I+ = I + Ts e; u = ki I+ + kp e + kd (e - e_prev)/Ts
    g = p.M_ctrl / p.Kf
    K = g * np.array([-(ki * Ts + kp + kd / Ts), 0.0, 0.0, ki, -kd / Ts])  # i_cmd = K @ state
    Phi = np.zeros((5, 5))
    Phi[:3, :3] = Ad
    Phi[:3, :] += np.outer(Bd, K)
    Phi[3, 0], Phi[3, 3] = -Ts, 1.0
    Phi[4, 0] = -1.0
    return float(np.max(np.abs(np.linalg.eigvals(Phi))))


def plot_compensation(runs: dict, path: str) -> str:
    """Tracking error with and without compensation for each move.

    ``runs`` maps a move label to ``(off, on, metrics)`` (result arrays of
    :meth:`plants.xml350.XML350.simulate` and the :func:`compensation_reduction` dict).
    """
    plt = pyplot()

    fig, axes = plt.subplots(2, len(runs), figsize=(5.5 * len(runs), 6.5), squeeze=False)
    for j, (label, (off, on, m)) in enumerate(runs.items()):
        scale, unit = (1e6, "um") if np.ptp(off["x_d"]) > 5e-6 else (1e9, "nm")
        ax = axes[0, j]
        ax.plot(off["time"] * 1e3, off["x_d"] * scale, "k--", lw=1, label="reference x_d")
        ax.plot(off["time"] * 1e3, off["x"] * scale, color="tab:blue", label="no compensation")
        ax.plot(on["time"] * 1e3, on["x"] * scale, color="tab:red", label="LuGre feedforward")
        ax.set(title=f"{label} S-curve move", xlabel="time [ms]", ylabel=f"position [{unit}]")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
        ax = axes[1, j]
        ax.plot(off["time"] * 1e3, off["e"] * 1e9, color="tab:blue",
                label=f"no compensation (RMS {m['rms_off'] * 1e9:.2g} nm)")
        ax.plot(on["time"] * 1e3, on["e"] * 1e9, color="tab:red",
                label=f"feedforward (RMS {m['rms_on'] * 1e9:.2g} nm)")
        ax.set(xlabel="time [ms]", ylabel="tracking error x_d - x [nm]",
               title=f"RMS -{m['rms_reduction']:.1%}, peak -{m['peak_reduction']:.1%} "
                     f"(paper -{PAPER_REDUCTIONS[label]['rms_reduction']:.1%}, "
                     f"-{PAPER_REDUCTIONS[label]['peak_reduction']:.1%})")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    return save(fig, path, dpi=120)


def plot_mismatch(rows: list[dict], path: str) -> str:
    """RMS reduction against the compensator's parameter error, one panel per move
    (:func:`mismatch_table` rows)."""
    plt = pyplot()

    moves = list(dict.fromkeys(r["move"] for r in rows))
    fig, axes = plt.subplots(1, len(moves), figsize=(5.5 * len(moves), 4.2), squeeze=False)
    for ax, mv in zip(axes[0], moves):
        sub = [r for r in rows if r["move"] == mv]
        exact = next(r["rms_reduction"] for r in sub if r["param"] == "exact")
        for name in dict.fromkeys(r["param"] for r in sub if r["param"] != "exact"):
            pts = sorted([(r["error"], r["rms_reduction"]) for r in sub if r["param"] == name]
                         + [(0.0, exact)])
            e, red = zip(*pts)
            ax.plot(np.array(e) * 100, np.array(red) * 100, "o-", label=name, ms=4)
        ax.axhline(85, color="grey", ls=":", lw=1)
        ax.set(title=f"{mv}: RMS reduction vs compensator error",
               xlabel="compensator parameter error [%]", ylabel="RMS error reduction [%]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    return save(fig, path, dpi=120)


def demo_figures(out: str, summary: dict, quick: bool = False) -> None:
    """The XML-350 part of the demo stage (compensation, mismatch, identification protocol)."""
    from friction.progress import Progress, report

    os.makedirs(out, exist_ok=True)
    stage = XML350()
    runs = {}
    comp = {}
    for label, dist in MOVES.items():
        r = compensation_reduction(dist, plant=stage, return_results=True)
        off, on = r.pop("results")
        runs[label] = (off, on, r)
        comp[label] = {"rms_reduction": r["rms_reduction"],
                       "peak_reduction": r["peak_reduction"],
                       "rms_error_without": r["rms_off"], "rms_error_with": r["rms_on"],
                       "peak_error_without": r["peak_off"], "peak_error_with": r["peak_on"]}
        report(f"  xml350 {label}: RMS -{r['rms_reduction']:.1%}, peak -{r['peak_reduction']:.1%}"
               f" (paper -{PAPER_REDUCTIONS[label]['rms_reduction']:.1%}, "
               f"-{PAPER_REDUCTIONS[label]['peak_reduction']:.1%})")
    summary["xml350_compensation"] = comp
    summary["xml350_compensation_paper"] = PAPER_REDUCTIONS
    # the modelling choice made visible: untimed feedforward (literal Eqs. 14/16) and the
    # linear PID with a 2 kHz current loop
    variants = {}
    for key, plant, opts in (("ff_mode_none", stage, {"ff_mode": "none"}),
                             ("linear_pid_2kHz_current_loop",
                              XML350(f_current=2000.0), {"controller": "pid"})):
        variants[key] = {}
        for label, dist in MOVES.items():
            r = compensation_reduction(dist, plant=plant, **opts)
            variants[key][label] = {"rms_reduction": r["rms_reduction"],
                                    "peak_reduction": r["peak_reduction"]}
    summary["xml350_compensation_variants"] = variants
    figs = summary.setdefault("figures", [])
    figs.append(plot_compensation(runs, os.path.join(out, "xml350_compensation.png")))

    if quick:
        levels, names = (0.1, 0.3), ("Fc", "sigma0", "all")
    else:
        levels, names = (0.1, 0.2, 0.3), ("Fc", "Fs", "sigma0", "sigma1", "sigma2", "vs", "all")
    n = len(MOVES) * len(levels) * len(names) * 2
    with Progress(total=n, label="xml350 mismatch") as prog:
        rows = mismatch_table(levels=levels, names=names, plant=stage, progress=prog)
    summary["xml350_mismatch"] = {
        "description": "RMS/peak tracking-error reduction when one compensator parameter "
                       "(or all: 'all') is scaled by 1 + error",
        "rows": rows}
    with open(os.path.join(out, "xml350_mismatch.json"), "w") as fh:
        json.dump(rows, fh, indent=1)
    figs.append(plot_mismatch(rows, os.path.join(out, "xml350_mismatch.png")))
    worst = {mv: min(r["rms_reduction"] for r in rows if r["move"] == mv
                     and abs(r["error"]) >= 0.3 - 1e-9) for mv in MOVES}
    report(f"  xml350 mismatch: worst RMS reduction at 30 % error {worst}")

    _identification_figure(out, summary, quick)


def _identification_figure(out: str, summary: dict, quick: bool) -> None:
    plt = pyplot()

    from ..experiments import stribeck_speeds, xml350_prbs, xml350_stribeck

    law = xml350_friction()
    speeds = stribeck_speeds(8 if quick else 24, 0.03, 2e-4)
    _, v, F = xml350_stribeck(speeds, plateau=0.1 if quick else 0.2, accel=0.5)
    prbs = xml350_prbs(duration=1.0 if quick else 4.0)
    fit = prbs["fit"]
    summary["xml350_identification"] = {
        "stribeck_points": {"v": v.tolist(), "F": F.tolist()},
        "stribeck_max_rel_error": float(np.max(np.abs(F - law.steady_state(v))
                                               / np.abs(law.steady_state(v)))),
        "presliding_fit": fit, "sigma0_true": law.params.sigma0,
        "sigma1_true": law.params.sigma1}
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    vv = np.linspace(-0.03, 0.03, 1201)
    axes[0].plot(vv * 1e3, law.steady_state(vv), "k-", lw=1, label="law F_ss(v)")
    axes[0].plot(v * 1e3, F, "o", color="tab:red", label="plateau means (simulated protocol)")
    axes[0].set(xlabel="velocity [mm/s]", ylabel="friction [N]",
                title="XML-350 Stribeck curve (seed 003 static step)")
    axes[0].legend(fontsize=8)
    axes[0].grid(alpha=0.3)
    f, G = prbs["freq"], prbs["G"]
    sel = (f > 5) & (f < 600)
    w = 2 * np.pi * f[sel]
    M = 11.8
    model = 1.0 / (-M * w ** 2 + 1j * fit["sigma1"] * w + fit["sigma0"])
    axes[1].loglog(f[sel], np.abs(G[sel]), color="tab:blue", label="FRF from PRBS")
    axes[1].loglog(f[sel], np.abs(model), "k--",
                   label=f"fit: sigma0 {fit['sigma0']:.3g} N/m, sigma1 {fit['sigma1']:.3g} N.s/m")
    axes[1].set(xlabel="frequency [Hz]", ylabel="|X/F| [m/N]",
                title="pre-sliding response (seed 003 dynamic step)")
    axes[1].legend(fontsize=8)
    axes[1].grid(alpha=0.3, which="both")
    path = save(fig, os.path.join(out, "xml350_identification.png"), dpi=120)
    summary.setdefault("figures", []).append(path)
