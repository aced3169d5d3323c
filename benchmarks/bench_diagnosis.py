"""Diagnosis benchmark: attribution, localisation and shrink on data whose effect is withheld,
on each plant of the plant library, and the speed of a full diagnosis.

For every plant (valve, damping rig, forging press, MRE isolator, XML-350) and every effect of
the candidate library, several strengths and noise levels, plus clean cases and an effect
outside the library (see :mod:`diagnosis.benchmark`), prints per plant and overall:

* top-1 attribution accuracy (goal >= 95 %), also over the cases whose effect is detectable
  at all (the base fit's held-out error exceeds the true model's by the noise margin);
* clean cases given an attribution (goal 0), out-of-library cases given a name (goal 0);
* localisation accuracy: the report's ``where`` top region (largest residual-energy lift)
  in the effect's region family; and the same from the signed ``evidence`` correlations;
* mean / max absolute error of the reported gap-closed fraction against the truth's
  ``1 - val_err(truth law) / val_err(base fit)``;
* seconds per case, as a ratio to one base identification of the same plant measured in
  the same run; and a full 20,000-sample diagnosis against one base identification.

    python benchmarks/bench_diagnosis.py [--quick] [--workers N] [--generic] [--json OUT]

``--quick``: one strength and noise level, short plant protocols (about 2 min).
``--generic``: also the historical generic mass-like benchmark.
"""
import argparse
import json
import time

import numpy as np

from diagnosis import diagnose
from diagnosis.benchmark import PLANT_NAMES, make_case, run_benchmark
from identification import identify


def _pct(x):
    return "   -" if x is None else f"{100 * x:5.1f}"


def _num(x, fmt=".3f"):
    return "-" if x is None else format(x, fmt)


def print_table(res, title):
    print(f"\n== {title} ==")
    print(f"{'plant':14s} {'cases':>5s} {'top-1 %':>7s} {'detect.%':>8s} {'clean':>6s} "
          f"{'outside':>7s} {'loc %':>6s} {'evid %':>6s} {'shrink |err| mean/max':>22s} "
          f"{'s/case':>7s} {'x base id':>9s}")
    rows = list(res["per_plant"].items()) + [("OVERALL", res["overall"])]
    for name, f in rows:
        print(f"{name:14s} {f['cases']:5d} {_pct(f['top1_accuracy']):>7s} "
              f"{_pct(f['top1_accuracy_detectable']):>8s} "
              f"{f['clean_false_attributions']:>3d}/{f['clean_cases']:<2d} "
              f"{f['outside_named_wrongly']:>4d}/{f['outside_cases']:<2d} "
              f"{_pct(f['localisation_accuracy']):>6s} "
              f"{_pct(f['localisation_evidence_accuracy']):>6s} "
              f"{_num(f['shrink_abs_error_mean']):>11s}/{_num(f['shrink_abs_error_max']):<10s} "
              f"{f['seconds_per_case']:7.2f} "
              f"{_num(f['time_ratio'], '.1f'):>9s}")
    print("  clean: cases with an attribution / clean cases; outside: named / out-of-library "
          "cases; x base id: seconds per case / one base identification of that plant's clean "
          "case, timed in the same worker")
    print(f"\n{'effect':15s} {'top-1':>9s} {'where':>9s} {'evidence':>9s} {'undetect.':>9s}  "
          f"named instead")
    for eff, e in res["per_effect"].items():
        na = eff in ("clean", "outside")
        loc = "-" if na else f"{e['loc_correct']}/{e['cases']}"
        lev = "-" if na else f"{e['loc_evidence_correct']}/{e['cases']}"
        named = ", ".join(f"{k} x{v}" for k, v in sorted(e["named"].items(), key=lambda kv: -kv[1]))
        print(f"{eff:15s} {e['correct']:4d}/{e['cases']:<4d} {loc:>9s} {lev:>9s} "
              f"{e['undetectable']:9d}  {named}")
    wrong = [r for r in res["rows"] if not r["correct"]]
    if wrong:
        print("\nmisses (plant, effect, strength, noise -> verdict; truth shrink; "
              "candidate ranking):")
        for r in wrong:
            print(f"  {r['plant']:13s} {r['effect']:14s} s={r['strength']:<4g} "
                  f"noise={r['noise']:<5g} -> {r['verdict']:13s} truth shrink "
                  f"{r['truth_shrink']:5.2f} {'(undetectable)' if r['detectable'] is False else ''}"
                  f" ranking {r['ranking']}")


def speed(n=20000):
    """Full diagnosis of ``n`` samples against one base identification, same run."""
    data = make_case("asymmetry", 1.0, 0.02, n=n)
    fit, _ = data.split(0.7)
    t0 = time.perf_counter()
    identify(fit, "lugre", names=["sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs"])
    t_base = time.perf_counter() - t0
    t0 = time.perf_counter()
    rep = diagnose(data, "lugre")
    t_full = time.perf_counter() - t0
    print(f"\nfull diagnosis of {n} samples, every candidate: {t_full:.1f} s "
          f"({t_full / t_base:.1f} x one base identification of {t_base:.2f} s); verdict "
          f"{rep['verdict']['cause']}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--generic", action="store_true")
    ap.add_argument("--json", default=None)
    ap.add_argument("--plants", default=",".join(PLANT_NAMES))
    args = ap.parse_args(argv)
    strengths = (1.0,) if args.quick else (0.5, 1.0)
    noises = (0.02,) if args.quick else (0.01, 0.03)
    t0 = time.perf_counter()
    res = run_benchmark(strengths=strengths, noises=noises, plants=args.plants.split(","),
                        quick=args.quick, workers=args.workers, progress=print)
    wall = time.perf_counter() - t0
    print_table(res, f"per plant: strengths {strengths}, noise {noises} x std(F), "
                     f"{len(res['rows'])} cases, {wall:.0f} s wall on {args.workers} worker(s)")
    out = {"plants": {k: res[k] for k in ("overall", "per_plant", "per_effect", "rows")}}
    if args.generic:
        g = run_benchmark(strengths=strengths, noises=noises, workers=args.workers,
                          progress=print)
        print_table(g, "generic mass-like motion (historical)")
        out["generic"] = {k: g[k] for k in ("overall", "per_effect", "rows")}
    speed()
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(out, fh, indent=1, default=lambda o: o.item() if isinstance(o, np.generic)
                      else str(o))


if __name__ == "__main__":
    main()
