"""Reproduce seed 000's friction loops and observer stability on the voice-coil valve.

Goal: run the valve actuator plant (moving mass, 6 mm preloaded spring, fmag(S, i) force
table, 20 kHz position control) through the paper's sinusoid grid, recover the friction
with Eq. (1) from the Butterworth-filtered encoder and current signals, and draw

* friction-velocity loops at 1/5/10/20 Hz with 8 mm (Fig. 6) and at 2/4/6/8 mm with 5 Hz
  (Fig. 7): the clockwise vertical loop in sliding and the counter-clockwise horizontal loop
  at the reversals (``valve_loops_grid.png``);
* the classic LuGre against the modified LuGre at 1 Hz / 8 mm (Fig. 11)
  (``valve_classic_vs_modified.png``);
* the steady-state tests (Fig. 9): friction at constant speeds in +-0.02 m/s against the
  law's Stribeck curve (``valve_stribeck.png``);
* the explicit-Euler observer of Eqs. (27)-(30) at 5/10/20 Hz (Fig. 10)
  (``valve_euler_observer.png``), and the loop features as JSON (``valve_loops.json``).

Run ``python examples/valve_loops.py`` (writes into ``./valve_loops_out``).
"""
from __future__ import annotations

import json
import os

import numpy as np

from plants.studies.valve import demo_figures, loop_features, loops_at, stribeck_points
from plants.valve import (FREQUENCIES, MAGNITUDES, ValveActuator, classic_lugre_twin,
                          valve_friction)


def run_example(show_plot: bool = False, out_dir: str = "valve_loops_out",
                quick: bool = False) -> dict:
    """Simulate the sinusoid grid, save the figures and the loop features.

    Parameters
    ----------
    show_plot : bool
        Open the figures in windows (otherwise they are only saved).
    out_dir : str
        Output directory (created).
    quick : bool
        One frequency, one magnitude, two constant-speed tests (a smoke test).

    Returns
    -------
    dict
        ``frequency`` and ``magnitude`` loop features (vertical [N], horizontal [m/s]),
        ``euler`` onset times/speeds, ``files``.
    """
    import matplotlib
    if not show_plot:
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    os.makedirs(out_dir, exist_ok=True)
    plant = ValveActuator()
    freqs, magnitudes = (FREQUENCIES[:1], MAGNITUDES[:1]) if quick else (FREQUENCIES, MAGNITUDES)
    by_f = loops_at(freqs, magnitude=8e-3, cycles=2.0, plant=plant)
    by_m = {M: loops_at((5.0,), magnitude=M, cycles=2.0, plant=plant)[5.0] for M in magnitudes}
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    out = {"frequency": {}, "magnitude": {}}
    for f, d in by_f.items():
        r = d["rec"]
        ax[0].plot(r["v"], r["F"], lw=0.8, label=f"{f:g} Hz")
        out["frequency"][f"{f:g}Hz"] = loop_features(r["v"], r["F"], acc=r["a"])
    for M, d in by_m.items():
        r = d["rec"]
        ax[1].plot(r["v"], r["F"], lw=0.8, label=f"{M * 1e3:g} mm")
        out["magnitude"][f"{M * 1e3:g}mm"] = loop_features(r["v"], r["F"], acc=r["a"])
    ax[0].set(xlabel="v [m/s]", ylabel="friction (Eq. 1) [N]", title="8 mm (Fig. 6)")
    ax[1].set(xlabel="v [m/s]", ylabel="friction (Eq. 1) [N]", title="5 Hz (Fig. 7)")
    for a in ax:
        a.legend(fontsize=8)
    fig.tight_layout()
    p1 = os.path.join(out_dir, "valve_loops_grid.png")
    fig.savefig(p1, dpi=120)

    classic = ValveActuator(classic_lugre_twin(valve_friction()))
    fig2, ax2 = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    for a, pl, title in ((ax2[0], classic, "classic LuGre"), (ax2[1], plant, "modified LuGre")):
        d = loops_at((1.0,), cycles=1.25, plant=pl)[1.0]
        a.plot(d["rec"]["v"], d["true_F"], lw=0.8)
        a.set(xlabel="v [m/s]", title=f"{title}, 1 Hz / 8 mm (Fig. 11)")
    ax2[0].set_ylabel("friction [N]")
    fig2.tight_layout()
    p2 = os.path.join(out_dir, "valve_classic_vs_modified.png")
    fig2.savefig(p2, dpi=120)

    mags = np.geomspace(1e-3, 0.02, 1 if quick else 8)
    pts = stribeck_points(np.concatenate((-mags[::-1], mags)), plant=plant)
    vg = np.linspace(-0.021, 0.021, 801)
    fig3, ax3 = plt.subplots(figsize=(6, 4))
    ax3.plot(vg, plant.friction.steady_state(vg), label="law, Eq. (5)")
    ax3.plot(pts[:, 0], pts[:, 1], "o", label="constant-speed tests, Eq. (1)")
    ax3.set(xlabel="v [m/s]", ylabel="friction [N]", title="steady state (Fig. 9)")
    ax3.legend(fontsize=8)
    fig3.tight_layout()
    p3 = os.path.join(out_dir, "valve_stribeck.png")
    fig3.savefig(p3, dpi=120)
    out["stribeck"] = pts.tolist()

    summary: dict = {}
    files = demo_figures(out_dir, summary, quick=True)
    out["euler"] = summary["valve"]["euler_onset"]
    out["v_cr"] = summary["valve"]["v_cr"]
    out["files"] = [p1, p2, p3] + [str(f) for f in files]
    with open(os.path.join(out_dir, "valve_loops.json"), "w") as fh:
        json.dump(out, fh, indent=2, default=lambda x: None if np.isnan(x) else float(x))
    if show_plot:
        plt.show()
    plt.close("all")
    return out


if __name__ == "__main__":
    res = run_example()
    for k, v in res["frequency"].items():
        print(f"8 mm {k}: vertical loop {v['vertical']:.3f} N, "
              f"horizontal {v['horizontal']:.4f} m/s")
    print("Euler onset (classic LuGre, h = 50 us):", res["euler"])
