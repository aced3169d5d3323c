"""``frictionlab identify DATA [VALIDATION] --model NAME [--algorithm NAME] [--seed N]
[--json OUT] [--fix N=V,...] [--static-from JSON] [--bounds N=LO:HI,...] [--min-speed V]``:
load, identify, print a readable summary with the identifiability report.

DATA may be a time series (``t, v, F``...) or a steady-state map (columns ``v, F`` and no
``t``: the static parameters, per direction). The two-step method: ``identify MAP.csv
--model lugre --json static.json``, then ``identify PRESLIDING.csv --model lugre
--static-from static.json``."""
from __future__ import annotations

import sys

from friction.dataset import load_dataset, parse_mapping

__all__ = ["run_identify_cli", "parse_scale", "parse_fix", "parse_bounds", "static_from_json"]


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


def parse_fix(text):
    """Parse ``"b=0,Fs=10.2"`` into ``{"b": 0.0, "Fs": 10.2}``."""
    if not text:
        return {}
    out = {}
    for item in text.split(","):
        if "=" not in item:
            raise ValueError(f"bad --fix item {item!r}: expected NAME=VALUE")
        k, v = item.split("=", 1)
        try:
            out[k.strip()] = float(v)
        except ValueError:
            raise ValueError(f"bad --fix value {v!r} for {k.strip()!r}: not a number") from None
    return out


def parse_bounds(text):
    """Parse ``"sigma1=0:2e4,vs=1e-6:0.1"`` into ``{"sigma1": (0.0, 2e4), ...}``."""
    if not text:
        return None
    out = {}
    for item in text.split(","):
        if "=" not in item or ":" not in item.split("=", 1)[1]:
            raise ValueError(f"bad --bounds item {item!r}: expected NAME=LOW:HIGH")
        k, v = item.split("=", 1)
        lo, hi = v.split(":", 1)
        try:
            out[k.strip()] = (float(lo), float(hi))
        except ValueError:
            raise ValueError(f"bad --bounds range {v!r} for {k.strip()!r}: expected two "
                             f"numbers LOW:HIGH") from None
    return out


def static_from_json(path, model_name: str):
    """The static parameter values (and Stribeck shape) of a result JSON written by
    ``identify --json`` (its fitted model's parameters), for the two-step method.

    Returns
    -------
    (dict values, str or None shape)
    """
    import json
    import os
    from .steady_state import STATIC_NAMES
    if not os.path.exists(path):
        raise FileNotFoundError(f"--static-from: no such file: {path}")
    try:
        with open(path) as fh:
            d = json.load(fh)
    except (OSError, ValueError) as exc:
        raise ValueError(f"--static-from {path}: not a JSON result of identify ({exc})") from None
    params = (d.get("model") or {}).get("params") if isinstance(d, dict) else None
    if not isinstance(params, dict):
        raise ValueError(f"--static-from {path}: no 'model.params' in it (write it with "
                         f"'frictionlab identify MAP.csv --model {model_name} --json FILE')")
    values = {k: float(v) for k, v in params.items() if k in STATIC_NAMES and v is not None}
    if not values:
        raise ValueError(f"--static-from {path}: no static parameter in it")
    return values, params.get("shape")


def _load_progress(path, quiet):
    """Progress while a long file is read (a bar ``[load <file>]``; none with ``--quiet``)."""
    return not quiet


def run_identify_cli(args) -> int:
    """Entry point used by ``frictionlab identify`` (see :mod:`frictionlab.cli`)."""
    from . import identify
    max_evals = getattr(args, "max_evals", None)
    if max_evals is not None and max_evals <= 0:
        # refused before loading anything: a zero budget is not a data problem
        raise ValueError(f"--max-evals {max_evals}: the evaluation budget must be a positive "
                         f"integer (simulations)")
    if getattr(args, "plant_fmu", None):
        return _run_plant_fmu(args, max_evals)
    from friction import make_model
    from friction.dataset import SteadyStateMap
    mapping = parse_mapping(getattr(args, "mapping", None))
    scale = parse_scale(getattr(args, "scale", None))
    fixed = parse_fix(getattr(args, "fix", None))
    bounds = parse_bounds(getattr(args, "bounds", None))
    files = list(args.data)
    if len(files) > 2:
        raise ValueError(f"give one fit file and at most one validation file, got {len(files)}")
    model = args.model
    static_from = getattr(args, "static_from", None)
    if static_from:
        values, shape = static_from_json(static_from, args.model)
        law = make_model(args.model)
        if shape is not None and hasattr(law.params, "shape"):
            law = law.with_values(shape=shape)
        unknown = [k for k in values if not hasattr(law.params, k)]
        if unknown:
            raise ValueError(f"--static-from {static_from}: {unknown} are not parameters of "
                             f"{args.model}")
        fixed = {**values, **fixed}  # an explicit --fix wins
        model = law
    quiet = getattr(args, "quiet", False)
    data = load_dataset(files[0], mapping=mapping, scale=scale,
                        progress=_load_progress(files[0], quiet))
    validation = None
    if len(files) == 2:
        validation = load_dataset(files[1], mapping=mapping, scale=scale,
                                  progress=_load_progress(files[1], quiet))
    min_speed = getattr(args, "min_speed", None)
    if min_speed is not None:
        if not isinstance(data, SteadyStateMap):
            raise ValueError("--min-speed applies to a steady-state map (columns v, F and no "
                             "t)")
        data = data.sliding(min_speed)
        if isinstance(validation, SteadyStateMap):
            validation = validation.sliding(min_speed)
    result = identify(data, model, algorithm=getattr(args, "algorithm", None),
                      seed=getattr(args, "seed", 0), max_evals=max_evals,
                      validation=validation, progress=not quiet,
                      checkpoint=getattr(args, "checkpoint", None), fixed=fixed or None,
                      bounds=bounds, executor=getattr(args, "executor", None))
    kind = "plateaus, steady-state map" if isinstance(data, SteadyStateMap) else "samples"
    print(f"data        : {files[0]} ({len(data)} {kind}"
          + (f"; read as {', '.join(data.notes)})" if data.notes else ")"))
    if validation is not None:
        print(f"validation  : {files[1]} ({len(validation)} "
              f"{'plateaus' if isinstance(validation, SteadyStateMap) else 'samples'})")
    if static_from:
        print(f"static from : {static_from} (held: {', '.join(sorted(fixed))})")
    print(result.summary())
    out = getattr(args, "json_out", None)
    if out:
        result.to_json(out)
        print(f"written     : {out}")
    sys.stdout.flush()
    return 0


def _run_plant_fmu(args, max_evals) -> int:
    """``identify DATA [VALIDATION...] --plant-fmu PLANT.fmu --connect RIG.toml``: the law
    co-simulated with the user's plant FMU (:func:`identification.plant_fmu.
    identify_plant_fmu`)."""
    from fmus.connect import load_connection
    from .plant_fmu import identify_plant_fmu, start_law
    for opt, flag in (("mapping", "--map"), ("scale", "--scale"), ("checkpoint", "--checkpoint"),
                      ("static_from", "--static-from"), ("min_speed", "--min-speed")):
        if getattr(args, opt, None) is not None:
            raise ValueError(f"{flag} does not apply with --plant-fmu (the connection file "
                             f"names the columns and their scale)")
    conn = load_connection(args.connect)
    law = start_law(args.model, conn)
    fixed = parse_fix(getattr(args, "fix", None))
    if fixed:
        try:
            law = law.with_values(**fixed)
        except (TypeError, ValueError, KeyError) as exc:
            raise ValueError(f"--fix: {exc}") from None
    names = None
    if fixed:
        from .plant_fmu import default_law_names
        names = [n for n in (conn.law_names or default_law_names(law)) if n not in fixed] \
            + conn.plant_names()
    files = list(args.data)
    quiet = getattr(args, "quiet", False)
    result = identify_plant_fmu(files[0], args.plant_fmu, conn, law, names=names,
                                bounds=parse_bounds(getattr(args, "bounds", None)),
                                algorithm=getattr(args, "algorithm", None),
                                seed=getattr(args, "seed", 0), max_evals=max_evals,
                                validation=files[1:] or None, progress=not quiet,
                                native=getattr(args, "law_fmu", "native") == "native",
                                executor=getattr(args, "executor", None) or "inline")
    print(f"plant FMU   : {args.plant_fmu} (connection {args.connect}; law FMU "
          f"{result['law_fmu']})")
    print(f"data        : {files[0]}")
    for f in files[1:]:
        print(f"validation  : {f}")
    print(result.summary())
    for rec, per in result["channels"].items():
        if per:
            print(f"NRMSE {rec:<6s}: " + ", ".join(f"{k} {v:.4g}" for k, v in per.items()))
    out = getattr(args, "json_out", None)
    if out:
        result.to_json(out)
        print(f"written     : {out}")
    sys.stdout.flush()
    return 0
