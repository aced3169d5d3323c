"""Crawling of a hydraulic forging press at ultra-low speed (seed 004, LI, PAN, HUANG 2013).

Goal: run the press plant (moving beam with gravity, major and supporting cylinders with
oil compressibility, servo-valve speed control, viscoplastic titanium workpiece, seals +
guide friction ``load_lugre`` with Tables 2-3) and draw what a user of the paper looks for:

* the no-load Stribeck curve with its minimum at the critical velocity vc = 0.19 mm/s
  (Fig. 7), with the plant's friction obtained by Eq. (1) from constant-speed tests;
* a speed sweep of no-load constant-speed runs: where the beam crawls (stick-slip) and where
  it moves smoothly, against vc (``forging_press_crawl_map.png``);
* the isothermal forging schedule of Table 1 (shortened), with the beam velocity at 1.2 mm/s
  (smooth) and at 0.002 mm/s (crawling), the deformation resistance and the friction
  (``forging_press_crawl.png``, ``forging_press_schedule.png``).

Run ``python examples/forging_press_crawl.py`` (writes into ``./forging_press_out``); add
``--full`` to run the whole 1370 s schedule of Table 1 instead of the shortened one (about
10-20 minutes, with progress lines).
"""
from __future__ import annotations

import json
import os
import sys

import numpy as np

from friction.progress import Progress
from plants.forging_press import TABLE1, ForgingPress
from plants.studies.forging_press import crawl_metrics, demo_figures

SWEEP = (0.01e-3, 0.03e-3, 0.05e-3, 0.1e-3, 0.15e-3, 0.3e-3, 0.6e-3, 1.2e-3)   # m/s


def run_example(show_plot: bool = False, out_dir: str = "forging_press_out",
                sweep=SWEEP, duration: float = 8.0, full: bool = False) -> dict:
    """Speed sweep, schedule run and Stribeck curve; figures and JSON into ``out_dir``.

    Parameters
    ----------
    show_plot : bool
        Open the figures in windows.
    out_dir : str
        Output directory (created).
    sweep : sequence of float
        No-load constant speeds [m/s].
    duration : float
        Length of each constant-speed run [s].
    full : bool
        Plot the full Table 1 schedule (1370 s) instead of the shortened default experiment.

    Returns
    -------
    dict
        ``sweep`` (speed [mm/s] -> crawl metrics), ``schedule`` (step -> crawl metrics),
        ``vc_mm_s``, ``files``.
    """
    import matplotlib
    if not show_plot:
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    os.makedirs(out_dir, exist_ok=True)
    press = ForgingPress()
    rows = {}
    for v in sweep:
        r = press.simulate(duration, schedule=((v, duration + 1.0),), workpiece=False)
        rows[f"{v * 1e3:g}"] = crawl_metrics(r, t_from=0.3 * duration)
    summary: dict = {}
    files = [str(f) for f in demo_figures(out_dir, summary, quick=False)]
    vc = summary["forging_press"]["vc_mm_s"]

    fig, ax = plt.subplots(figsize=(6.5, 4))
    sp = np.array([float(k) for k in rows])
    ax.loglog(sp, [max(m["peak_ratio"], 1e-3) for m in rows.values()], "o-",
              label="max |v - v_ref| / v_ref")
    ax.loglog(sp, [max(m["intermittency"], 1e-3) for m in rows.values()], "s-",
              label="share of time below v_ref / 2")
    ax.axvline(vc, color="k", ls="--", label=f"vc = {vc:.3f} mm/s (Eq. 13)")
    ax.set(xlabel="speed [mm/s]", title="no-load constant speed: crawl map")
    ax.legend(fontsize=8)
    fig.tight_layout()
    p1 = os.path.join(out_dir, "forging_press_crawl_map.png")
    fig.savefig(p1, dpi=120)

    if full:
        exp = press.default_experiment
        n = int(sum(d for _, d in TABLE1) / exp.step) + 1
        with Progress(total=n, label="press Table 1", interval=10.0) as prog:
            res = press.simulate(sum(d for _, d in TABLE1), schedule=TABLE1, progress=prog)
    else:
        res = press.simulate()
    fig2, ax2 = plt.subplots(3, 1, figsize=(9, 7), sharex=True)
    ax2[0].plot(res["time"], res["v"] * 1e3, lw=0.7, label="beam")
    ax2[0].plot(res["time"], res["v_ref"] * 1e3, "k--", lw=0.7, label="schedule")
    ax2[0].set(ylabel="v [mm/s]", ylim=(-1, 2.5))
    ax2[0].legend(fontsize=8)
    ax2[1].plot(res["time"], res["F_sigma"] / 1e6)
    ax2[1].set(ylabel="F_sigma [MN]")
    ax2[2].plot(res["time"], res["F"] / 1e3)
    ax2[2].set(ylabel="friction [kN]", xlabel="t [s]")
    fig2.tight_layout()
    p2 = os.path.join(out_dir, "forging_press_schedule.png")
    fig2.savefig(p2, dpi=120)

    out = {"vc_mm_s": vc, "sweep": rows, "schedule": summary["forging_press"]["crawl"],
           "files": [p1, p2] + files}
    with open(os.path.join(out_dir, "forging_press.json"), "w") as fh:
        json.dump(out, fh, indent=2)
    if show_plot:
        plt.show()
    plt.close("all")
    return out


if __name__ == "__main__":
    res = run_example(full="--full" in sys.argv[1:])
    print(f"vc = {res['vc_mm_s']} mm/s")
    for k, m in res["sweep"].items():
        print(f"no load {k:>6} mm/s: {'crawls' if m['crawling'] else 'smooth'} "
              f"(peak {m['peak_ratio']:.3g} v_ref, below v_ref/2 {m['intermittency']:.0%})")
    for k, m in res["schedule"].items():
        state = "crawls" if m["crawling"] else ("stalled" if m["stalled"] else "smooth")
        print(f"schedule {k:>10}: {state}")
