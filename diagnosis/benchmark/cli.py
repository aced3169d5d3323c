"""Text output and command line of the benchmark (``frictionlab diagnose --benchmark``,
``python -m diagnosis.benchmark``)."""
from __future__ import annotations

from .runner import run_benchmark

__all__ = ["format_summary", "run_benchmark_cli", "main"]


def _pct(x):
    # percentage, or a dash where a figure does not apply
    return "   -" if x is None else f"{100 * x:5.1f}"


def _num(x, fmt=".3f"):
    return "-" if x is None else format(x, fmt)


def format_summary(res, title: str = "withheld-effect benchmark") -> str:
    """The benchmark figures as a text table: per plant, overall, per effect, misses."""
    out = []
    out.append(f"\n== {title} ==")
    out.append(f"{'plant':14s} {'cases':>5s} {'top-1 %':>7s} {'detect.%':>8s} {'clean':>6s} "
               f"{'outside':>7s} {'loc %':>6s} {'evid %':>6s} {'true %':>6s} "
               f"{'shrink |err| mean/max':>22s} "
               f"{'s/case':>7s} {'x base id':>9s}")
    rows = list(res["per_plant"].items()) + [("OVERALL", res["overall"])]
    for name, f in rows:
        out.append(f"{name:14s} {f['cases']:5d} {_pct(f['top1_accuracy']):>7s} "
                   f"{_pct(f['top1_accuracy_detectable']):>8s} "
                   f"{f['clean_false_attributions']:>3d}/{f['clean_cases']:<2d} "
                   f"{f['outside_named_wrongly']:>4d}/{f['outside_cases']:<2d} "
                   f"{_pct(f['localisation_accuracy']):>6s} "
                   f"{_pct(f['localisation_evidence_accuracy']):>6s} "
                   f"{_pct(f.get('localisation_truth_accuracy')):>6s} "
                   f"{_num(f['shrink_abs_error_mean']):>11s}/"
                   f"{_num(f['shrink_abs_error_max']):<10s} "
                   f"{f['seconds_per_case']:7.2f} "
                   f"{_num(f['time_ratio'], '.1f'):>9s}")
    out.append("  clean: cases with an attribution / clean cases; outside: named / out-of-library "
               "cases; x base id: seconds per case / one base identification of that plant's clean "
               "case, timed in the same worker; loc/evid: top region in the effect's family "
               "(EXPECTED_FAMILIES / EXPECTED_EVIDENCE); true: the report's top region is the "
               "noise-free gap's (truth - base fit)")
    below = res["overall"].get("below_practical_cases", 0)
    if below:
        out.append(f"  detect.: over the cases an oracle tells from the base; {below} of the "
                   f"undetectable are below their effect's practical size (a truth whose "
                   f"own held-out imprint is below what a name needs, or a delay of less "
                   f"than a sample: no verdict may name them)")
    out.append(f"\n{'effect':15s} {'top-1':>9s} {'where':>9s} {'evidence':>9s} {'true':>9s} "
               f"{'undetect.':>9s}  named instead")
    for eff, e in res["per_effect"].items():
        na = eff in ("clean", "outside")
        loc = "-" if na else f"{e['loc_correct']}/{e['cases']}"
        lev = "-" if na else f"{e['loc_evidence_correct']}/{e['cases']}"
        ltr = "-" if na else f"{e.get('loc_truth', 0)}/{e['cases']}"
        named = ", ".join(f"{k} x{v}" for k, v in sorted(e["named"].items(), key=lambda kv: -kv[1]))
        out.append(f"{eff:15s} {e['correct']:4d}/{e['cases']:<4d} {loc:>9s} {lev:>9s} {ltr:>9s} "
                   f"{e['undetectable']:9d}  {named}")
    plants = list(res["per_plant"])
    if len(plants) > 1:  # correct / cases of each effect on each plant
        out.append("\n" + f"{'top-1 by plant':15s} " + " ".join(f"{p[:13]:>13s}" for p in plants))
        for eff in res["per_effect"]:
            cells = []
            for p in plants:
                rs = [r for r in res["rows"] if r["plant"] == p and r["effect"] == eff]
                cells.append(f"{sum(r['correct'] for r in rs)}/{len(rs)}" if rs else "n/a")
            out.append(f"{eff:15s} " + " ".join(f"{c:>13s}" for c in cells))
    if res.get("per_form"):
        out.append(f"\n{'effect/truth form':36s} {'top-1':>9s} {'detectable':>10s} "
                   f"{'|shrink err|':>12s}  named instead")
        for key, e in res["per_form"].items():
            named = ", ".join(f"{k} x{v}" for k, v in sorted(e["named"].items(),
                                                             key=lambda kv: -kv[1]))
            out.append(f"{key:36s} {e['correct']:4d}/{e['cases']:<4d} "
                       f"{e['correct_detectable']:4d}/{e['detectable']:<5d} "
                       f"{_num(e['shrink_abs_error_mean']):>12s}  {named}")
    for r in res.get("skipped", []):
        out.append(f"skipped: {r['plant']} {r['effect']}/{r['form']} s={r['strength']}: "
                   f"{r['skipped']}")
    wrong = [r for r in res["rows"] if not r["correct"]]
    if wrong:
        out.append("\nmisses (plant, effect, strength, noise -> verdict; truth shrink; "
                   "candidate ranking):")
        for r in wrong:
            und = ("(below practical size)" if r.get("below_practical") else
                   "(undetectable)" if r["detectable"] is False else "")
            out.append(f"  {r['plant']:13s} {r['effect']:14s} {r.get('form', '')[:18]:18s} "
                       f"{r.get('measured', '')[:14]:14s} s={r['strength']:<4g} "
                       f"noise={r['noise']:<5g} -> {r['verdict']:13s} truth shrink "
                       f"{r['truth_shrink']:5.2f} {und}"
                       f" ranking {r['ranking']}")
    return "\n".join(out)


def run_benchmark_cli(args) -> int:
    """``frictionlab diagnose --benchmark --plants LIST|all``: the per-plant benchmark at one
    strength (1) and noise level (0.02 x std(F)); ``benchmarks/bench_diagnosis.py`` runs the
    full grid."""
    plants = None if args.plants in (None, "", "generic") else (
        "all" if args.plants == "all" else args.plants.split(","))
    quiet = getattr(args, "quiet", False)
    res = run_benchmark(plants=plants, seed=getattr(args, "seed", 0), strengths=(1.0,),
                        noises=(0.02,), progress=not quiet)
    print(format_summary(res))
    if getattr(args, "json_out", None):
        import json
        with open(args.json_out, "w") as fh:
            json.dump({k: res[k] for k in ("overall", "per_plant", "per_effect", "rows")}, fh,
                      indent=1, default=float)
    return 0


def main(argv=None) -> int:
    """``python -m diagnosis.benchmark [--plants LIST|all] [--seed N] [--json-out FILE]
    [--quiet]``: :func:`run_benchmark_cli` (one strength, one noise level); the full grid is
    ``benchmarks/bench_diagnosis.py``.

    Parameters
    ----------
    argv : list of str, optional
        Arguments (default ``sys.argv[1:]``).

    Returns
    -------
    int
        Exit status (0).
    """
    import argparse
    ap = argparse.ArgumentParser(prog="python -m diagnosis.benchmark",
                                 description="withheld-effect diagnosis benchmark")
    ap.add_argument("--plants", default=None,
                    help="'all', a comma-separated list of plants, or none: the generic cases")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--json-out", dest="json_out", default=None)
    ap.add_argument("--quiet", action="store_true")
    return run_benchmark_cli(ap.parse_args(argv))
