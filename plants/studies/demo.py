"""Demo stage of the plant library (``frictionlab demo``, stage "plants").

Runs each study's figures into ``out`` and its numbers into ``summary``:

* :func:`plants.studies.xml350.demo_figures` - ``xml350_compensation.png`` (S-curve moves
  of 100 um and 1 um with and without the LuGre feedforward, seed 003 Figs. 5-6),
  ``xml350_mismatch.png`` / ``.json`` (the reduction when the compensator's parameters are
  off by 10-30 %) and ``xml350_identification.png`` (the seed 003 protocol on the
  simulated stage);
* then the machines' studies (:data:`MACHINE_DEMOS`): :mod:`plants.studies.valve`,
  :mod:`plants.studies.damping_rig`, :mod:`plants.studies.forging_press`,
  :mod:`plants.studies.mre_isolator`, and the real EMPS axis in closed and open loop
  (:mod:`plants.studies.emps`: ``emps_trajectory.png`` / ``.json``,
  ``summary["emps_trajectory"]``).
"""
from __future__ import annotations

import os

from friction.progress import report

from . import damping_rig, emps, forging_press, mre_isolator, valve, xml350

__all__ = ["run_stage", "MACHINE_DEMOS"]

#: machine -> its study's ``demo_figures(out, summary, quick)``, run after the XML-350 part
MACHINE_DEMOS = {"valve": valve.demo_figures, "damping_rig": damping_rig.demo_figures,
                 "forging_press": forging_press.demo_figures,
                 "mre_isolator": mre_isolator.demo_figures, "emps": emps.demo_figures}


def run_stage(out: str, summary: dict, quick: bool = False) -> None:
    """Demo stage "plants": the XML-350 figures, then every machine study's figures."""
    os.makedirs(out, exist_ok=True)
    xml350.demo_figures(out, summary, quick)
    ran = ["xml350"]
    for name, figures in MACHINE_DEMOS.items():
        report(f"  plants: {name} ...")
        figures(out, summary, quick)
        ran.append(name)
    summary["plants_demo"] = {"ran": ran}
