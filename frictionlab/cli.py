"""``frictionlab`` command: parsing and dispatch only (fmpy ``command_line.py`` style).

Every subcommand prints ``--help``; bad input exits non-zero with a one-line message and no
traceback (set ``FRICTIONLAB_DEBUG=1`` to see the traceback).
"""
from __future__ import annotations

import argparse
import os
import sys

__all__ = ["main", "build_parser"]


def _add_data_options(p: argparse.ArgumentParser, optional: bool = False) -> None:
    # optional: the command has a mode without data (diagnose --benchmark); checked in _dispatch
    p.add_argument("data", nargs="*" if optional else "+", help="measurement file(s): CSV "
                   "(t,x,v,a,F[,load]) or .mat; the first is fitted, the others held out")
    # --model is checked in _dispatch: with --plant-fmu the connection file may name it
    p.add_argument("--model", default=None,
                   help="friction law (registry name, e.g. lugre)")
    p.add_argument("--map", dest="mapping", default=None,
                   help="column mapping NAME=COLUMN,... e.g. t=time,x=qm,F=force")
    p.add_argument("--scale", default=None,
                   help="unit factors NAME=FACTOR,... e.g. x=1e-3 for a position in mm")
    p.add_argument("--json", dest="json_out", default=None, help="write the result as JSON here")
    p.add_argument("--quiet", action="store_true", help="no progress output")
    p.add_argument("--plant-fmu", dest="plant_fmu", default=None,
                   help="your plant as an FMI 2.0 co-simulation FMU: DATA are measured runs "
                   "of it (the columns --connect names); the law is co-simulated with it")
    p.add_argument("--connect", default=None,
                   help="with --plant-fmu: the connection file (TOML) saying which plant "
                   "input takes the friction force, which outputs feed the law, which "
                   "measured columns drive and which are compared (see the README)")
    p.add_argument("--law-fmu", dest="law_fmu", default="native",
                   choices=("native", "pythonfmu"),
                   help="with --plant-fmu: the friction-law FMU kind (default native C)")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="run the evaluations on a dask.distributed cluster: the scheduler's "
                   "address, e.g. tcp://127.0.0.1:8786; FMUs and data go to each worker "
                   "once (keep the scheduler on a private network; see the README)")


def build_parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(prog="frictionlab", description="Friction modelling, "
                                 "co-simulation, identification and sim-to-real diagnosis.")
    sub = ap.add_subparsers(dest="command", metavar="COMMAND")
    sub.required = True

    d = sub.add_parser("demo", help="the main job end to end on built-in data")
    d.add_argument("--out", default="frictionlab-demo", help="output folder (default ./frictionlab-demo)")
    d.add_argument("--quick", action="store_true", help="smaller problems (for smoke tests)")
    d.add_argument("--full", action="store_true", help="full-length FMU co-simulation proofs "
                   "(about 15 min on 2 cores; the default proofs use short horizons)")
    d.add_argument("--only", default=None, help="comma-separated stages to run "
                   "(friction,plants,fmus,identification,diagnosis)")

    b = sub.add_parser("build-fmus", help="build every FMU into a folder")
    b.add_argument("--out", required=True, help="output folder")
    b.add_argument("--only", default=None, help="comma-separated FMU names to build")

    i = sub.add_parser("identify", help="identify a friction law's parameters from data")
    _add_data_options(i)
    i.add_argument("--algorithm", default=None, help="identification algorithm (default: the "
                   "fast robust one; see identification.ALGORITHMS)")
    i.add_argument("--seed", type=int, default=0, help="random seed (reproducible runs)")
    i.add_argument("--checkpoint", default=None, help="checkpoint file (JSON-lines evaluation "
                   "log, written as the run goes): a rerun with the same file resumes to the "
                   "uninterrupted result; least_squares and static_ls refuse it")
    i.add_argument("--max-evals", type=int, default=None, help="evaluation budget "
                   "(simulations, a positive integer)")
    i.add_argument("--fix", default=None, help="hold parameters at values NAME=VALUE,... "
                   "(SI units), e.g. b=0 or Fs=10.2,Fs_neg=11.5")
    i.add_argument("--static-from", dest="static_from", default=None,
                   help="two-step method, step 2: hold the static parameters (Fc, Fs, vs, "
                   "alpha, sigma2, b and their _neg twins) at the values of a JSON written by "
                   "'identify MAP.csv --json', and identify the dynamic ones (sigma0, sigma1)")
    i.add_argument("--bounds", default=None, help="search box NAME=LOW:HIGH,... (SI units), "
                   "e.g. sigma1=0:2e4")
    i.add_argument("--min-speed", dest="min_speed", type=float, default=None,
                   help="steady-state maps: drop plateaus slower than this [m/s or rad/s] "
                   "(presliding creep that no Stribeck curve describes)")

    g = sub.add_parser("diagnose", help="locate and name the sim-to-real gap of a model")
    _add_data_options(g, optional=True)
    g.add_argument("--html", dest="html_out", default=None, help="write an HTML report here")
    g.add_argument("--load-column", default=None, help="column to use as load (e.g. pressure)")
    g.add_argument("--benchmark", action="store_true", help="run the built-in attribution benchmark")
    g.add_argument("--plants", default=None, help="with --benchmark: run it on these plants "
                   "(comma-separated names, or 'all'); default: the generic mass-like cases")
    g.add_argument("--seed", type=int, default=0)
    g.add_argument("--plant", default=None, help="trajectory level: plant model (e.g. xml350, "
                   "valve); DATA are measured positions (columns t, x)")
    g.add_argument("--experiment", action="append", default=None,
                   help="trajectory level: experiment options KEY=VALUE,... of each DATA file "
                   "(once for all, or once per file), e.g. trajectory=sine:5e-5:5,controller=pid;"
                   " keys that are plant parameters (e.g. f_current=2000) set the plant model")
    g.add_argument("--start", default=None,
                   help="with --plant-fmu: start the base law and the plant parameters from "
                   "the JSON 'identify --plant-fmu ... --json' wrote")
    g.add_argument("--engine", default="plant", choices=("plant", "fmu"),
                   help="trajectory level: in-process plant (default) or plant + friction FMUs")
    g.add_argument("--candidates", default=None,
                   help="comma-separated candidate effects to try (default all), both levels")
    g.add_argument("--noise-level", type=float, default=None,
                   help="RMS of the force measurement's noise [N] (default: estimated from the "
                   "residual, which under-reads filtered, coloured noise)")
    g.add_argument("--noise-record", default=None,
                   help="a standstill record (CSV/.mat, same --map/--scale): the spread of its "
                   "force channel is the noise level")
    g.add_argument("--threads", type=int, default=None,
                   help="workers the candidates' fits run on: processes forked from this "
                   "one on Linux, else threads (default: the machine's cores, "
                   "at most 4, or FRICTIONLAB_THREADS; 1: one after the other); same report")
    return ap


class _scheduler:
    """``--scheduler ADDRESS``: connect before any work (an unreachable address is a
    one-line error naming it, within :data:`identification.cluster.CONNECT_TIMEOUT`), put
    the client on ``args.executor``, close it after the command."""

    def __init__(self, args):
        self.args = args
        self.client = None

    def __enter__(self):
        address = getattr(self.args, "scheduler", None)
        if address:
            from identification.cluster import connect
            self.client = connect(address)
        self.args.executor = self.client
        return self.client

    def __exit__(self, *exc):
        if self.client is not None:
            self.client.close()
        return False


def _dispatch(args) -> int:
    if args.command == "demo":
        from .demo import run_demo
        run_demo(args.out, quick=args.quick, full=args.full,
                 only=args.only.split(",") if args.only else None)
        return 0
    if args.command == "build-fmus":
        from fmus.build import build_all
        build_all(args.out, only=args.only.split(",") if args.only else None)
        return 0
    if args.command in ("identify", "diagnose") and bool(getattr(args, "plant_fmu", None)) \
            != bool(getattr(args, "connect", None)):
        raise ValueError("--plant-fmu and --connect go together: the plant FMU and the "
                         "connection file (TOML) that couples it")
    if args.command == "identify":
        if not args.model and not args.plant_fmu:
            raise ValueError("identify needs --model NAME (the friction law)")
        from identification.cli import run_identify_cli
        with _scheduler(args):
            return run_identify_cli(args) or 0
    if args.command == "diagnose":
        if args.benchmark and args.plants:
            from diagnosis.benchmark import run_benchmark_cli
            return run_benchmark_cli(args)
        if not args.benchmark and (not args.data or not (args.model or args.plant_fmu)):
            raise ValueError("diagnose needs DATA and --model (or --benchmark)")
        if getattr(args, "scheduler", None) and args.benchmark:
            raise ValueError("--scheduler applies to identify and to the diagnosis of your "
                             "data (its candidate fits); the built-in benchmark runs in "
                             "this process")
        from diagnosis.cli import run_diagnose_cli
        with _scheduler(args):
            return run_diagnose_cli(args) or 0
    raise ValueError(f"unknown command {args.command!r}")


def main(argv=None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return _dispatch(args)
    except KeyboardInterrupt:
        print("frictionlab: interrupted (checkpoints, if any, were kept)", file=sys.stderr)
        return 130
    except (ValueError, FileNotFoundError, KeyError, NotImplementedError, RuntimeError,
            OSError, ImportError) as exc:
        if os.environ.get("FRICTIONLAB_DEBUG"):
            raise
        # data errors carry their hints in command-line syntax too (--scale, --map)
        text = str(getattr(exc, "cli", None) or exc).strip()
        msg = text.splitlines()[0] if text else type(exc).__name__
        print(f"frictionlab {args.command}: error: {msg}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
