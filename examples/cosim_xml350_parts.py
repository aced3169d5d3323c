"""Assemble the XML-350 positioning loop from five FMUs, as another tool would.

Goal: S-curve trajectory -> LuGre feedforward -> state-dependent PID -> stage mechanics,
with the stage's friction in its own LuGre FMU, connected by name (an OSP/SSP-style list,
:data:`fmus.plant_fmus.XML350_CONNECTIONS`), and compared with the plant's reference.
"""
from __future__ import annotations

import tempfile


def run_cosim_xml350_parts(show_plot: bool = False, stop: float = 0.03):
    """Returns a dict with the co-simulation result and its NRMSE against the reference."""
    from friction.metrics import nrmse
    from plants.xml350 import XML350, xml350_friction
    from fmus.build import build_all
    from fmus.plant_fmus import xml350_loop_master

    out = tempfile.mkdtemp(prefix="cosim_xml350_")
    build_all(out, only=["xml350_trajectory", "lugre_feedforward", "sdpid",
                         "xml350_mechanics", "lugre"])
    with xml350_loop_master(out) as m:
        res = m.simulate(stop_time=stop, step_size=1e-4)
    ref = XML350(friction=xml350_friction()).simulate(stop, method="reference")
    err = nrmse(ref["x"], res["mechanics.x"])
    if show_plot:
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(2, 1, sharex=True)
        ax[0].plot(res["time"], res["trajectory.x_d"] * 1e6, label="x_d")
        ax[0].plot(res["time"], res["mechanics.x"] * 1e6, label="x (FMU loop)")
        ax[0].plot(ref["time"], ref["x"] * 1e6, "--", label="x (reference)")
        ax[0].set_ylabel("position [um]")
        ax[0].legend()
        ax[1].plot(res["time"], (res["trajectory.x_d"] - res["mechanics.x"]) * 1e9)
        ax[1].set_ylabel("tracking error [nm]")
        ax[1].set_xlabel("t [s]")
        ax[0].set_title(f"XML-350 loop from 5 FMUs, NRMSE {err:.1e}")
        plt.show()
    return {"result": res, "nrmse": err}


if __name__ == "__main__":
    r = run_cosim_xml350_parts(show_plot=True)
    print(f"NRMSE of the stage position against the reference: {r['nrmse']:.2e}")
