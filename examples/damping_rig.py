"""Dynamic damping of a valve's rubber ring on the suspended-cylinder rig of seed 001.

Goal: run the damping rig plant (piston with rubber ring driven vertically, steel cylinder
hanging on four force sensors, classic LuGre with the paper's Table I) and draw what a user
of the paper looks for:

* the sensors' force against the ring's friction for the linear motor at 4 Hz (Fig. 3) and
  the piezo drive at 600 Hz (Fig. 4), where the cylinder's inertia on the sensors' stiffness
  shapes the reading (``damping_rig.png``);
* friction-velocity and friction-displacement loops for sine, triangle and trapezoid motions
  (``damping_rig_waveforms.png``);
* the open-loop identification experiment of Eqs. (17)-(18), m a = u - F with
  u = 1.1 sin 5t (third panel of ``damping_rig.png``).

Run ``python examples/damping_rig.py`` (writes into ``./damping_rig_out``).
"""
from __future__ import annotations

import json
import os

import numpy as np

from plants.damping_rig import DampingRig
from plants.studies.damping_rig import demo_figures


def run_example(show_plot: bool = False, out_dir: str = "damping_rig_out",
                quick: bool = False) -> dict:
    """Simulate the drives and waveforms; figures and JSON into ``out_dir``.

    Parameters
    ----------
    show_plot : bool
        Open the figures in windows.
    out_dir : str
        Output directory (created).
    quick : bool
        The demo's short figures and one waveform (a smoke test).

    Returns
    -------
    dict
        ``sensor_error_4Hz`` / ``sensor_error_600Hz`` (NRMSE of the sensors' force against the
        ring friction), ``dissipated`` energy per cycle [J] per waveform, ``files``.
    """
    import matplotlib
    if not show_plot:
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    os.makedirs(out_dir, exist_ok=True)
    summary: dict = {}
    files = [str(f) for f in demo_figures(out_dir, summary, quick=quick)]
    rig = DampingRig()
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    energy = {}
    for wave in ("sine",) if quick else ("sine", "triangle", "trapezoid"):
        r = rig.simulate(0.5, waveform=wave, amplitude=0.01)
        k = r["time"] >= 0.25                      # last cycle at 4 Hz
        ax[0].plot(r["v"][k], r["F_meas"][k], lw=0.8, label=wave)
        ax[1].plot(r["x"][k] * 1e3, r["F_meas"][k], lw=0.8, label=wave)
        x, F = r["x"][k], r["F_meas"][k]
        energy[wave] = float(abs(np.sum(0.5 * (F[1:] + F[:-1]) * np.diff(x))))
    ax[0].set(xlabel="v [m/s]", ylabel="sensor force [N]", title="4 Hz, 10 mm: force-velocity")
    ax[1].set(xlabel="x [mm]", ylabel="sensor force [N]", title="force-displacement")
    for a in ax:
        a.legend(fontsize=8)
    fig.tight_layout()
    p1 = os.path.join(out_dir, "damping_rig_waveforms.png")
    fig.savefig(p1, dpi=120)
    out = dict(summary["damping_rig"], dissipated=energy, files=files + [p1])
    with open(os.path.join(out_dir, "damping_rig.json"), "w") as fh:
        json.dump(out, fh, indent=2)
    if show_plot:
        plt.show()
    plt.close("all")
    return out


if __name__ == "__main__":
    res = run_example()
    print(f"sensors vs ring friction: {res['sensor_error_4Hz']:.2%} at 4 Hz (linear motor), "
          f"{res['sensor_error_600Hz']:.0%} at 600 Hz (piezo)")
    for w, e in res["dissipated"].items():
        print(f"{w}: {e:.3f} J per cycle")
