"""Demo stage of the plant library (``frictionlab demo``, stage "plants").

Writes into ``out``:

* ``xml350_compensation.png`` - S-curve moves of 100 um and 1 um with and without the
  LuGre feedforward (seed 003 Figs. 5-6), and ``summary["xml350_compensation"]``;
* ``xml350_mismatch.png`` / ``.json`` - how the reduction falls when the compensator's
  parameters are off by 10-30 % (``summary["xml350_mismatch"]``);
* ``xml350_identification.png`` - the seed 003 protocol on the simulated stage: Stribeck
  plateaus and the pre-sliding frequency response (``summary["xml350_identification"]``);
* then each machine module that exists (``plants.valve``, ``plants.damping_rig``,
  ``plants.forging_press``, ``plants.mre_isolator``) may add its figures through
  ``demo_figures(out, summary, quick)``.
"""
from __future__ import annotations

import importlib
import json
import os

import numpy as np

from frictionlab.progress import Progress, report

from .xml350 import MOVES, PAPER_REDUCTIONS, XML350, compensation_reduction, mismatch_table

__all__ = ["run_stage", "plot_compensation", "xml350_compensation_figures", "MACHINE_DEMOS"]

#: machine modules whose ``demo_figures(out, summary, quick)`` run after the XML-350 part
MACHINE_DEMOS = ("valve", "damping_rig", "forging_press", "mre_isolator")


def plot_compensation(runs: dict, path: str) -> str:
    """Tracking error with and without compensation for each move.

    ``runs`` maps a move label to ``(off, on, metrics)`` (result arrays of
    :meth:`plants.xml350.XML350.simulate` and the :func:`compensation_reduction` dict).
    """
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

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
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def _plot_mismatch(rows: list[dict], path: str) -> str:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

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
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def xml350_compensation_figures(out: str, summary: dict, quick: bool = False) -> None:
    """The XML-350 part of the stage (compensation, mismatch, identification protocol)."""
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
    figs.append(_plot_mismatch(rows, os.path.join(out, "xml350_mismatch.png")))
    worst = {mv: min(r["rms_reduction"] for r in rows if r["move"] == mv
                     and abs(r["error"]) >= 0.3 - 1e-9) for mv in MOVES}
    report(f"  xml350 mismatch: worst RMS reduction at 30 % error {worst}")

    _identification_figure(out, summary, quick)


def _identification_figure(out: str, summary: dict, quick: bool) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from .experiments import stribeck_speeds, xml350_prbs, xml350_stribeck
    from .xml350 import xml350_friction

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
    fig.tight_layout()
    path = os.path.join(out, "xml350_identification.png")
    fig.savefig(path, dpi=120)
    plt.close(fig)
    summary.setdefault("figures", []).append(path)


def run_stage(out: str, summary: dict, quick: bool = False) -> None:
    """Demo stage "plants": XML-350 figures, then every machine module's ``demo_figures``."""
    os.makedirs(out, exist_ok=True)
    xml350_compensation_figures(out, summary, quick)
    ran, missing = ["xml350"], []
    for mod in MACHINE_DEMOS:
        try:
            m = importlib.import_module(f"{__package__}.{mod}")
        except ModuleNotFoundError as exc:
            if exc.name != f"{__package__}.{mod}":
                raise
            missing.append(mod)
            continue
        fn = getattr(m, "demo_figures", None)
        if fn is None:
            missing.append(mod)
            continue
        report(f"  plants: {mod} ...")
        fn(out, summary, quick)
        ran.append(mod)
    summary["plants_demo"] = {"ran": ran, "missing": missing}
