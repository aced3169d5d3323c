"""``frictionlab identify DATA [VALIDATION] --model NAME [--algorithm NAME] [--seed N]
[--json OUT]``: load, identify, print a readable summary."""
from __future__ import annotations

import sys

from friction.dataset import load_dataset, parse_mapping

__all__ = ["run_identify_cli", "parse_scale"]


def parse_scale(text):
    """Parse ``"x=1e-3,t=1e-3"`` into ``{"x": 0.001, "t": 0.001}``."""
    if not text:
        return None
    out = {}
    for item in text.split(","):
        if "=" not in item:
            raise ValueError(f"bad scale item {item!r}: expected NAME=FACTOR")
        k, v = item.split("=", 1)
        try:
            out[k.strip()] = float(v)
        except ValueError:
            raise ValueError(f"bad scale factor {v!r} for {k.strip()!r}: not a number") from None
    return out


def run_identify_cli(args) -> int:
    """Entry point used by ``frictionlab identify`` (see :mod:`frictionlab.cli`)."""
    from . import identify
    max_evals = getattr(args, "max_evals", None)
    if max_evals is not None and max_evals <= 0:
        # refused before loading anything: a zero budget is not a data problem
        raise ValueError(f"--max-evals {max_evals}: the evaluation budget must be a positive "
                         f"integer (simulations)")
    mapping = parse_mapping(getattr(args, "mapping", None))
    scale = parse_scale(getattr(args, "scale", None))
    files = list(args.data)
    data = load_dataset(files[0], mapping=mapping, scale=scale)
    validation = None
    if len(files) > 2:
        raise ValueError(f"give one fit file and at most one validation file, got {len(files)}")
    if len(files) == 2:
        validation = load_dataset(files[1], mapping=mapping, scale=scale)
    quiet = getattr(args, "quiet", False)
    result = identify(data, args.model, algorithm=getattr(args, "algorithm", None),
                      seed=getattr(args, "seed", 0), max_evals=max_evals,
                      validation=validation, progress=not quiet,
                      checkpoint=getattr(args, "checkpoint", None))
    print(f"data        : {files[0]} ({len(data)} samples"
          + (f"; read as {', '.join(data.notes)})" if data.notes else ")"))
    if validation is not None:
        print(f"validation  : {files[1]} ({len(validation)} samples)")
    print(result.summary())
    out = getattr(args, "json_out", None)
    if out:
        result.to_json(out)
        print(f"written     : {out}")
    sys.stdout.flush()
    return 0
