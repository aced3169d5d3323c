"""``frictionlab diagnose``: argument handling only."""
from __future__ import annotations

import json
import sys

from friction.dataset import load_dataset, parse_mapping
from frictionlab.progress import report as say

from .core import diagnose

__all__ = ["run_diagnose_cli"]


def _scale(text):
    out = {}
    for k, v in parse_mapping(text).items():
        try:
            out[k] = float(v)
        except ValueError:
            raise ValueError(f"--scale {k}={v}: factor must be a number") from None
    return out


def run_diagnose_cli(args) -> int:
    quiet = getattr(args, "quiet", False)
    if getattr(args, "benchmark", False):
        from .benchmark import run_benchmark
        res = run_benchmark(progress=None if quiet else say, seed=args.seed)
        print(f"top-1 accuracy {100 * res['top1_accuracy']:.1f} % over {len(res['rows'])} cases; "
              f"clean cases named: {res['clean_false_attributions']}; out-of-library named: "
              f"{res['outside_named_wrongly']}")
        if args.json_out:
            with open(args.json_out, "w") as fh:
                json.dump(res, fh, indent=2, default=float)
        return 0
    mapping = parse_mapping(args.mapping)
    if args.load_column:
        mapping["load"] = args.load_column
    scale = _scale(args.scale)
    sets = [load_dataset(p, mapping=mapping, scale=scale) for p in args.data]
    rep = diagnose(sets[0], args.model, validation=sets[1:] or None, seed=args.seed,
                   progress=None if quiet else say)
    print(rep.summary())
    if args.json_out:
        rep.to_json(args.json_out)
    if args.html_out:
        from .report_html import write_html
        write_html(rep, args.html_out)
    return 0
