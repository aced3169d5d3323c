"""Diagnosis benchmark: attribution accuracy on data whose effect is withheld, and speed.

Prints top-1 accuracy, clean-case and out-of-library behaviour, the error of the reported
shrink, and the time of a full 20,000-sample diagnosis as a ratio to one base fit measured in
the same run.

    python benchmarks/bench_diagnosis.py [--quick]
"""
import sys
import time

import numpy as np

from diagnosis import diagnose
from diagnosis.benchmark import make_case, run_benchmark
from identification import identify


def main(quick=False):
    strengths = (1.0,) if quick else (0.5, 1.0, 2.0)
    noises = (0.02,) if quick else (0.01, 0.03)
    res = run_benchmark(strengths=strengths, noises=noises, progress=print)
    print(f"\ntop-1 accuracy: {100 * res['top1_accuracy']:.1f} % over {len(res['rows'])} cases")
    print(f"clean cases with an attribution: {res['clean_false_attributions']}")
    print(f"out-of-library cases given a wrong name: {res['outside_named_wrongly']}")
    by = {}
    for r in res["rows"]:
        by.setdefault(r["effect"], []).append(r["correct"])
    for k, v in by.items():
        print(f"  {k:15s} {100 * np.mean(v):5.0f} %  ({sum(v)}/{len(v)})")
    # speed: 20,000 samples, every candidate, against one base identification
    data = make_case("asymmetry", 1.0, 0.02, n=20000)
    t0 = time.perf_counter()
    fit, _ = data.split(0.7)
    identify(fit, "lugre", names=["sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs"])
    t_base = time.perf_counter() - t0
    t0 = time.perf_counter()
    rep = diagnose(data, "lugre")
    t_full = time.perf_counter() - t0
    print(f"\nfull diagnosis of 20,000 samples, every candidate: {t_full:.1f} s "
          f"({t_full / t_base:.1f} x one base identification of {t_base:.2f} s); verdict "
          f"{rep['verdict']['cause']}")


if __name__ == "__main__":
    main(quick="--quick" in sys.argv)
