"""``frictionlab demo``: every stage of the project end to end, into one folder.

Each stage is a module with ``run_stage(out_dir, summary, quick)`` that writes its PNG/JSON
files into ``out_dir`` and its figures into the shared ``summary`` dict
(:data:`STAGE_MODULES`: ``frictionlab.demo.<package>_stage``, and for the plants the studies'
``plants.studies.demo``); the library packages hold no demo or plotting code.
A stage that fails to import stops the demo with that error.
"""
from __future__ import annotations

import importlib
import json
import os
import time

from friction.progress import report

__all__ = ["run_demo", "STAGES", "STAGE_MODULES"]

STAGES = ("friction", "plants", "fmus", "identification", "diagnosis")

#: stage -> module holding its ``run_stage``
STAGE_MODULES = {"friction": "frictionlab.demo.friction_stage",
                 "plants": "plants.studies.demo", "fmus": "frictionlab.demo.fmus_stage",
                 "identification": "frictionlab.demo.identification_stage",
                 "diagnosis": "frictionlab.demo.diagnosis_stage"}


#: stages whose full-length run is opt-in (``--full``): the co-simulation proofs take ~15 min
LONG_STAGES = ("fmus",)


def run_demo(out: str = "frictionlab-demo", *, quick: bool = False, full: bool = False,
             only=None) -> dict:
    """Run the demo stages and write ``<out>/summary.json``.

    Parameters
    ----------
    out : str
        Output folder (created).
    quick : bool
        Smaller problems, for smoke tests.
    full : bool
        Run the long stages (:data:`LONG_STAGES`) at full length too.
    only : list of str, optional
        Run only these stages.
    """
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, "summary.json")
    summary: dict = {}
    if os.path.exists(path) and only:
        with open(path) as fh:  # keep other stages' results when re-running one stage
            summary = json.load(fh)
    summary.pop("stages_missing", None)   # written by earlier versions
    stages = [s for s in STAGES if not only or s in only]
    unknown = set(only or ()) - set(STAGES)
    if unknown:
        raise ValueError(f"unknown demo stage(s) {sorted(unknown)}; choose from {STAGES}")
    for k, name in enumerate(stages, 1):
        mod = importlib.import_module(STAGE_MODULES[name])
        t0 = time.monotonic()
        report(f"[demo {k}/{len(stages)}] {name} ...")
        stage_quick = quick or (name in LONG_STAGES and not full)
        summary.setdefault("stage_settings", {})[name] = "quick" if stage_quick else "full"
        mod.run_stage(out, summary, quick=stage_quick)
        report(f"[demo {k}/{len(stages)}] {name} done in {time.monotonic() - t0:.1f} s")
        with open(path, "w") as fh:  # written after every stage: an interrupted demo keeps its results
            json.dump(summary, fh, indent=2, default=float)
    with open(path, "w") as fh:
        json.dump(summary, fh, indent=2, default=float)
    report(f"demo results in {os.path.abspath(out)} (summary.json)")
    return summary
