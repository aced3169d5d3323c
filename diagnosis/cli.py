"""``frictionlab diagnose``: argument handling only."""
from __future__ import annotations

import json

from friction.dataset import load_dataset, parse_mapping

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
        res = run_benchmark(progress=not quiet, seed=args.seed)
        print(f"top-1 accuracy {100 * res['top1_accuracy']:.1f} % over {len(res['rows'])} cases; "
              f"clean cases named: {res['clean_false_attributions']}; out-of-library named: "
              f"{res['outside_named_wrongly']}")
        if args.json_out:
            with open(args.json_out, "w") as fh:
                json.dump(res, fh, indent=2, default=float)
        return 0
    if getattr(args, "plant_fmu", None):
        return _run_plant_fmu(args, quiet)
    if getattr(args, "plant", None):
        return _run_trajectory(args, quiet)
    mapping = parse_mapping(args.mapping)
    if args.load_column:
        mapping["load"] = args.load_column
    scale = _scale(args.scale)
    sets = [load_dataset(p, mapping=mapping, scale=scale, progress=not quiet)
            for p in args.data]
    from friction.progress import as_progress

    from .composite import reporting
    # the joint fits tick a bar (residual evaluations, at most once a second): a long
    # record's fits are not silent between the candidates' lines
    with as_progress(not quiet, "diagnose fits", unit="eval") as fits, \
            reporting(fits if not quiet else None):
        rep = diagnose(sets[0], args.model, validation=sets[1:] or None, seed=args.seed,
                       candidates=_candidates(args), progress=not quiet,
                       noise_level=_noise_level(args, mapping, scale),
                       executor=getattr(args, "executor", None),
                       threads=getattr(args, "threads", None))
    from .report_html import write_html
    return _emit(rep, args, write_html)


def _noise_level(args, mapping, scale):
    """``--noise-level`` [N], or the spread of a standstill record's force (``--noise-record``)."""
    level = getattr(args, "noise_level", None)
    record = getattr(args, "noise_record", None)
    if level is not None and record:
        raise ValueError("give --noise-level or --noise-record, not both")
    if record:
        import numpy as np
        F = np.asarray(load_dataset(record, mapping=mapping, scale=scale).F, float)
        return float(np.std(F))
    return level


def _candidates(args):
    text = getattr(args, "candidates", None)
    return [c.strip() for c in text.split(",") if c.strip()] if text else None


def _emit(rep, args, write_html) -> int:
    """Summary on stdout, JSON and HTML where asked for."""
    print(rep.summary())
    if args.json_out:
        rep.to_json(args.json_out)
    if args.html_out:
        write_html(rep, args.html_out)
    return 0


def _run_trajectory(args, quiet) -> int:
    """Trajectory level: DATA are measured positions of ``--plant`` under ``--experiment``."""
    import plants

    from .trajectory import diagnose_trajectory, load_record, parse_experiment
    if args.plant not in plants.PLANTS:
        raise ValueError(f"unknown plant {args.plant!r}; choose from {sorted(plants.PLANTS)}")
    specs = args.experiment or [None]
    if len(specs) not in (1, len(args.data)):
        raise ValueError(f"--experiment given {len(specs)} times for {len(args.data)} data "
                         f"files: give it once (all files) or once per file")
    specs = specs * len(args.data) if len(specs) == 1 else specs
    cls = plants.PLANTS[args.plant]
    pnames = set(cls.Params.numeric_names())
    plant_params, options = {}, []
    for spec in specs:
        opts = parse_experiment(spec)
        plant_params.update({k: v for k, v in opts.items() if k in pnames})
        rest = {k: v for k, v in opts.items() if k not in pnames}
        unknown = set(rest) - set(cls.options)
        if unknown:
            raise ValueError(f"--experiment: {sorted(unknown)} are neither options "
                             f"{sorted(cls.options)} nor parameters of plant {args.plant!r}")
        options.append(rest)
    plant = plants.make_plant(args.plant, **plant_params)
    mapping = parse_mapping(args.mapping)
    scale = _scale(args.scale)
    recs = [load_record(p, o, mapping=mapping, scale=scale) for p, o in zip(args.data, options)]
    rep = diagnose_trajectory(recs[0], plant, args.model, validation=recs[1:] or None,
                              candidates=_candidates(args), engine=args.engine,
                              progress=not quiet,
                              executor=getattr(args, "executor", None))
    from .trajectory_report import write_trajectory_html
    return _emit(rep, args, write_trajectory_html)


def _run_plant_fmu(args, quiet) -> int:
    """Trajectory level through the user's plant FMU: DATA are measured runs (the first
    fitted, the others held out), coupled as ``--connect`` says."""
    from .plant_fmu import diagnose_plant_fmu
    if getattr(args, "plant", None):
        raise ValueError("give --plant (a built-in plant model) or --plant-fmu (your plant "
                         "FMU), not both")
    for opt, flag in (("mapping", "--map"), ("scale", "--scale"),
                      ("experiment", "--experiment"), ("load_column", "--load-column")):
        if getattr(args, opt, None):
            raise ValueError(f"{flag} does not apply with --plant-fmu (the connection file "
                             f"names the columns, their scale and the plant's inputs)")
    rep = diagnose_plant_fmu(args.data[0], args.data[1:] or None, args.plant_fmu,
                             args.connect, args.model, candidates=_candidates(args),
                             native=getattr(args, "law_fmu", "native") == "native",
                             start=getattr(args, "start", None),
                             progress=not quiet,
                             executor=getattr(args, "executor", None))
    from .trajectory_report import write_trajectory_html
    return _emit(rep, args, write_trajectory_html)
