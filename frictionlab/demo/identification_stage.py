"""Demo stage ``identification``: identify on built-in synthetic data and on real EMPS data.

Writes PNG figures and fills ``summary["identification"]`` (called by ``frictionlab demo``).
Quick mode (< 15 s): the synthetic seed 001 case and the EMPS fit. Full mode (< 60 s) adds a
convergence comparison of the default against seed metaheuristics, a Franka joint and seed
003's XML-350 protocol (short records).
"""
from __future__ import annotations

import os
import time

import numpy as np

from friction.progress import report

__all__ = ["run_stage"]

LUGRE_ASYM = ["sigma0", "sigma1", "sigma2", "sigma2_neg", "Fc", "Fc_neg", "Fs", "Fs_neg", "vs",
              "b"]


def _plt():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def _synthetic(out, entry, quick):
    from identification import identify
    from identification.synthetic import make_case
    case = make_case("seed001", noise=0.02)
    r = identify(case.data, case.start, names=case.names, bounds=case.bounds, seed=0)
    entry["synthetic_seed001"] = dict(
        algorithm=r.algorithm, fit_nrmse=r.fit_nrmse, n_evals=r.n_evals, wall_time=r.wall_time,
        max_param_error=case.param_error(r.params), params=r.params,
        true={n: getattr(case.true.params, n) for n in case.names}, noise="2 % of std(F)")
    plt = _plt()
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    d = case.data
    ax[0].plot(d.t, d.F, ".", ms=2, label="measured (synthetic, 2 % noise)")
    ax[0].plot(d.t, r.model.simulate(d.t, d.v), "-", label=f"identified ({r.algorithm})")
    ax[0].set(xlabel="t [s]", ylabel="F [N]", title="seed 001 LuGre (Table I)")
    ax[0].legend(fontsize=8)
    ax[1].plot(d.v, d.F, ".", ms=2)
    ax[1].plot(d.v, r.model.simulate(d.t, d.v), "-")
    ax[1].set(xlabel="v [m/s]", ylabel="F [N]", title=f"NRMSE {r.fit_nrmse:.3g}")
    fig.tight_layout()
    path = os.path.join(out, "identification_synthetic.png")
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return path


def _emps(out, entry):
    from friction import make_model
    from identification import identify
    from identification.real_data import EMPS_PUBLISHED, emps_baseline, load_emps
    est, val = load_emps("estimation"), load_emps("validation")
    base = emps_baseline()
    start = make_model("lugre", sigma0=1e5, sigma1=100.0, sigma2=200.0, sigma2_neg=200.0,
                       Fc=20.0, Fc_neg=20.0, Fs=25.0, Fs_neg=25.0, vs=0.01, b=-3.0)
    r = identify(est, start, algorithm="least_squares", names=LUGRE_ASYM, validation=val)

    def rel(ds, Ff):
        y = ds.extra["motor_force"]
        return float(np.linalg.norm(y - (EMPS_PUBLISHED["M"] * ds.a + Ff)) / np.linalg.norm(y))

    entry["emps"] = dict(
        source="EMPS benchmark (Janot, Gautier, Brunot), nonlinearbenchmark.org",
        baseline=base.as_dict(), published=EMPS_PUBLISHED,
        baseline_deviation={k: abs(getattr(base, k) / v - 1) for k, v in EMPS_PUBLISHED.items()},
        lugre=dict(params=r.params, fit_nrmse=r.fit_nrmse, validation_nrmse=r.validation_nrmse,
                   wall_time=r.wall_time),
        relative_error=dict(
            baseline_estimation=rel(est, base.friction(est.v)),
            baseline_pulses=rel(val, base.friction(val.v)),
            lugre_estimation=rel(est, r.model.simulate(est.t, est.v)),
            lugre_pulses=rel(val, r.model.simulate(val.t, val.v))))
    plt = _plt()
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    ax[0].plot(est.v, est.F, ".", ms=2, color="0.6", label="DATA_EMPS (inverse dynamics)")
    vv = np.linspace(est.v.min(), est.v.max(), 400)
    ax[0].plot(vv, base.friction(vv), "k--", label="published-form baseline")
    ax[0].plot(vv, r.model.steady_state(vv), "r-", label="LuGre (asymmetric) steady state")
    ax[0].set(xlabel="v [m/s]", ylabel="friction [N]", title="EMPS estimation set")
    ax[0].legend(fontsize=8)
    sl = slice(0, None)
    ax[1].plot(val.t[sl], val.F[sl], color="0.6", lw=0.8, label="DATA_EMPS_PULSES")
    ax[1].plot(val.t[sl], base.friction(val.v[sl]), "k--", lw=0.8,
               label=f"baseline ({entry['emps']['relative_error']['baseline_pulses']:.1%})")
    ax[1].plot(val.t[sl], r.model.simulate(val.t, val.v)[sl], "r-", lw=0.8,
               label=f"LuGre ({entry['emps']['relative_error']['lugre_pulses']:.1%})")
    ax[1].set(xlabel="t [s]", ylabel="friction [N]", title="validation (relative motor-force error)")
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    path = os.path.join(out, "identification_emps.png")
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return path


def _convergence(out, entry):
    from identification import DEFAULT_ALGORITHM, identify
    from identification.synthetic import make_case
    case = make_case("seed003", noise=0.02)
    plt = _plt()
    fig, ax = plt.subplots(figsize=(6, 4))
    rows = {}
    for alg in (DEFAULT_ALGORITHM, "iafsa", "chaotic_pso", "adaptive_ga", "cmaes"):
        kw = {} if alg == DEFAULT_ALGORITHM else {"max_evals": 6000}
        r = identify(case.data, case.start, algorithm=alg, names=case.names,
                     bounds=case.bounds, seed=0, **kw)
        rows[alg] = dict(cost=r.fit_nrmse, n_evals=r.n_evals, wall_time=r.wall_time)
        tr = np.array(r.trace)  # every improvement with its real time
        ax.step(np.append(tr[:, 1], r.wall_time), np.append(tr[:, 2], tr[-1, 2]),
                where="post", label=f"{alg}")
    ax.set_yscale("log")
    ax.set(xlabel="wall time [s]", ylabel="best NRMSE", xscale="log",
           title="seed 003 LuGre, 2 % noise (others: 6000 evaluations)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    path = os.path.join(out, "identification_convergence.png")
    fig.savefig(path, dpi=90)
    plt.close(fig)
    entry["convergence_seed003"] = rows
    return path


def _franka(entry):
    from friction import make_model
    from friction.metrics import rmse
    from identification import identify
    from identification.real_data import franka_paper_rms, load_franka
    d = load_franka(4, "high")
    start = make_model("lugre", sigma0=100.0, sigma1=1.0, sigma2=0.5, sigma2_neg=0.5, Fc=0.3,
                       Fc_neg=0.3, Fs=0.4, Fs_neg=0.4, vs=0.01, b=0.0)
    r = identify(d.select(slice(0, None, 5)), start, algorithm="least_squares", names=LUGRE_ASYM)
    entry["franka_case4_high"] = dict(rms_ours=rmse(d.F, r.model.simulate(d.t, d.v)),
                                      rms_paper_lugre=franka_paper_rms(4, "high"),
                                      unit="N m")


def _rack_pinion(entry):
    from friction.metrics import rmse
    from identification import identify
    from identification.real_data import load_rack_pinion
    d = load_rack_pinion()
    covered = ~np.isnan(d.extra["F_model_source"])
    res = {"rms_source_model": rmse(d.F[covered], d.extra["F_model_source"][covered]),
           "unit": "N", "samples": int(covered.sum())}
    for law in ("stribeck", "lugre"):
        r = identify(d, law)
        res[f"rms_{law}"] = rmse(d.F[covered], r.model.simulate(d.t, d.v)[covered])
    entry["rack_pinion"] = res


def run_stage(out, summary: dict, quick: bool = False) -> None:
    """Identification demo stage (see the module docstring)."""
    os.makedirs(out, exist_ok=True)
    entry = summary.setdefault("identification", {})
    figures = entry.setdefault("figures", [])
    t0 = time.monotonic()
    figures.append(_synthetic(out, entry, quick))
    report(f"  identification: synthetic seed 001 case done ({time.monotonic() - t0:.1f} s)")
    try:
        figures.append(_emps(out, entry))
        report(f"  identification: EMPS real data done ({time.monotonic() - t0:.1f} s)")
    except FileNotFoundError as exc:
        entry["emps"] = {"skipped": str(exc)}
    try:
        _rack_pinion(entry)
    except FileNotFoundError as exc:
        entry["rack_pinion"] = {"skipped": str(exc)}
    if not quick:
        figures.append(_convergence(out, entry))
        report(f"  identification: convergence comparison done ({time.monotonic() - t0:.1f} s)")
        try:
            _franka(entry)
        except FileNotFoundError as exc:
            entry["franka_case4_high"] = {"skipped": str(exc)}
        try:
            from identification.xml350_protocol import run_xml350_protocol
        except ImportError as exc:  # the plant library is not there
            entry["xml350_protocol"] = {"skipped": str(exc)}
        else:
            res = run_xml350_protocol(quick=True)
            entry["xml350_protocol"] = {k: res[k] for k in (
                "init", "final", "true", "accuracy", "paper_accuracy", "samples", "dynamic")}
            report(f"  identification: XML-350 protocol done ({time.monotonic() - t0:.1f} s)")
    entry["figures"] = sorted(set(os.path.basename(f) for f in figures))
    entry["wall_time"] = time.monotonic() - t0
