"""Seed 002 study on the MRE isolator: force-displacement loops against amplitude and coil
current (Figs. 9-10) and their stiffness and dissipated energy (the isolator part of the
``plants`` demo stage).
"""
from __future__ import annotations

import numpy as np

from ..mre_isolator import AMPLITUDES, CURRENTS, MREIsolator

from ._figures import folder, pyplot, save

__all__ = ["loop_metrics", "demo_figures"]


def loop_metrics(res, freq: float = 4.0, cycles: int = 1):
    """Effective stiffness and loop area of the last ``cycles`` force-displacement cycles.

    Returns
    -------
    dict
        ``k_eff`` = (F(x_max) - F(x_min)) / (x_max - x_min) [N/m] (slope of the loop),
        ``area`` = closed-loop integral of F dx [J] (energy dissipated per cycle), ``F_max``.
    """
    t = np.asarray(res["time"])
    n = int(round(cycles / freq / (t[1] - t[0])))
    x = np.asarray(res["x"])[-n - 1:]
    F = np.asarray(res["F_meas"])[-n - 1:]
    i, j = int(np.argmax(x)), int(np.argmin(x))
    k_eff = (F[i] - F[j]) / (x[i] - x[j])
    area = abs(float(np.sum(0.5 * (F[1:] + F[:-1]) * np.diff(x)))) / cycles
    return {"k_eff": float(k_eff), "area": area, "F_max": float(np.max(np.abs(F)))}


def demo_figures(out, summary: dict, quick: bool = True):
    """Isolator figures: loops vs amplitude at 2 A (Fig. 9) and vs current at 4 mm (Fig. 10)."""
    plt = pyplot()
    out = folder(out)
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    rows = {}
    for A in AMPLITUDES:
        r = MREIsolator().simulate(1.0, amplitude=A)
        k = r["time"] >= 0.75
        ax[0].plot(r["x"][k] * 1e3, r["F_meas"][k], label=f"{A * 1e3:g} mm")
        rows[f"2A_{A * 1e3:g}mm"] = {k2: round(v2, 4) for k2, v2 in loop_metrics(r).items()}
    for I in CURRENTS:
        r = MREIsolator(current=I).simulate(1.0, amplitude=4e-3)
        k = r["time"] >= 0.75
        ax[1].plot(r["x"][k] * 1e3, r["F_meas"][k], label=f"{I:g} A")
        rows[f"{I:g}A_4mm"] = {k2: round(v2, 4) for k2, v2 in loop_metrics(r).items()}
    ax[0].set(xlabel="x [mm]", ylabel="F [N]", title="4 Hz, 2 A (seed 002 Fig. 9)")
    ax[1].set(xlabel="x [mm]", ylabel="F [N]", title="4 Hz, 4 mm (seed 002 Fig. 10)")
    for a in ax:
        a.legend(fontsize=7)
    p1 = save(fig, out / "mre_isolator_loops.png")
    summary.setdefault("figures", []).append(str(p1))
    summary["mre_isolator"] = rows
    return [p1]
