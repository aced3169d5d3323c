"""Seed 001 study on the damping rig: what the force sensors read against the ring's
friction with the linear motor (4 Hz) and the piezo (600 Hz), and the open-loop experiment
of Eqs. 17-18 (the rig part of the ``plants`` demo stage).
"""
from __future__ import annotations

import numpy as np

from ..damping_rig import PIEZO_RATE, DampingRig, rig_friction

from ._figures import folder, pyplot, save

__all__ = ["demo_figures"]


def demo_figures(out, summary: dict, quick: bool = True):
    """Rig figures: measured vs true friction at 4 Hz (linear) and 600 Hz (piezo), Eq. 17-18."""
    plt = pyplot()
    out = folder(out)
    rig = DampingRig()
    lin = rig.simulate(0.5)
    pz = DampingRig(rig_friction(600.0)).simulate(2.0 / 600.0, step=1.0 / PIEZO_RATE,
                                                  drive="piezo", freq=600.0, amplitude=30e-6)
    ol = rig.simulate(4.0 if quick else 8.0, drive="open_loop", step=1e-3)
    fig, ax = plt.subplots(1, 3, figsize=(14, 4))
    ax[0].plot(lin["time"], lin["F_meas"], label="sensors")
    ax[0].plot(lin["time"], lin["F"], "--", label="ring friction")
    ax[0].set(xlabel="t [s]", ylabel="force [N]", title="linear motor, sine 4 Hz (Fig. 3)")
    ax[1].plot(pz["time"] * 1e3, pz["F_meas"], label="sensors")
    ax[1].plot(pz["time"] * 1e3, pz["F"], "--", label="ring friction")
    ax[1].set(xlabel="t [ms]", ylabel="force [N]", title="piezo, sine 600 Hz (Fig. 4)")
    ax[2].plot(ol["time"], ol["x_p"] * 1e3)
    ax[2].set(xlabel="t [s]", ylabel="s [mm]", title="open loop, u = 1.1 sin 5t (Eqs. 17-18)")
    for a in ax[:2]:
        a.legend(fontsize=7)
    p1 = save(fig, out / "damping_rig.png")

    def rel(r):
        return float(np.sqrt(np.mean((r["F_meas"] - r["F"]) ** 2)) / np.std(r["F"]))

    summary.setdefault("figures", []).append(str(p1))
    summary["damping_rig"] = {"sensor_error_4Hz": round(rel(lin), 5),
                              "sensor_error_600Hz": round(rel(pz), 5)}
    return [p1]
