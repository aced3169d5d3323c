"""Demo stage: diagnosis on real data (EMPS asymmetry, pneumatic seals) and the benchmark."""
from __future__ import annotations

import os

from frictionlab.progress import report as say

from .core import diagnose
from .report_html import write_html


def run_stage(out: str, summary: dict, quick: bool = False) -> None:
    from identification.real_data import load_emps, load_pneumatic
    res = {}
    rep = diagnose(load_emps("estimation"), "lugre", validation=load_emps("validation"))
    rep.to_json(os.path.join(out, "diagnosis_emps.json"))
    write_html(rep, os.path.join(out, "diagnosis_emps.html"))
    res["emps"] = {"verdict": rep["verdict"], "baseline": rep["baseline"],
                   "seconds": rep["timing"]["seconds"]}
    say(f"  diagnosis EMPS (fit DATA_EMPS, held out DATA_EMPS_PULSES): {rep['verdict']['cause']}")
    rep = diagnose(load_pneumatic("O-ring", 1), "lugre",
                   validation=[load_pneumatic("O-ring", 5), load_pneumatic("O-ring", 7)])
    rep.to_json(os.path.join(out, "diagnosis_pneumatic.json"))
    write_html(rep, os.path.join(out, "diagnosis_pneumatic.html"))
    res["pneumatic_o_ring"] = {"verdict": rep["verdict"], "baseline": rep["baseline"]}
    say(f"  diagnosis pneumatic O-ring (fit 1 bar, held out 5+7 bar): {rep['verdict']['cause']}")
    from .benchmark import CASES, run_benchmark
    bench = run_benchmark(effects=CASES, strengths=(1.0,), noises=(0.02,))
    res["benchmark"] = {k: bench[k] for k in ("top1_accuracy", "clean_false_attributions",
                                               "outside_named_wrongly")}
    res["benchmark"]["cases"] = [{k: r[k] for k in ("effect", "verdict", "correct")}
                                 for r in bench["rows"]]
    say(f"  diagnosis benchmark: top-1 {100 * bench['top1_accuracy']:.0f} %")
    summary["diagnosis"] = res
