"""One EMPS trajectory identification through co-simulation on the full estimation record
(DATA_EMPS, 24,841 samples at 1 kHz), with native C FMUs and with pythonfmu FMUs in the same
run (issue 14, "Performance").

Native: ``emps_axis_native.fmu`` + ``emps_controller_native.fmu`` + ``lugre_native.fmu``
(:func:`plants.studies.emps.native_connection_dict`). pythonfmu: ``emps_loop.fmu`` (the axis
in its loop, :class:`fmus.runtime.StepperSlave`) + the pythonfmu ``lugre.fmu``
(:func:`plants.studies.emps.connection_dict`). Both through
:func:`identification.plant_fmu.identify_plant_fmu` (the path a user's plant FMU takes; the
master's per-step calls run in its compiled loop, :mod:`fmus.master_loop`), least squares on
the closed-loop voltage, from :func:`plants.studies.emps.start_model`, identifying ``Fc, Fs,
vs, sigma2, b`` and the mass. A pythonfmu evaluation takes seconds, so its identification
runs under a small budget (``--py-evals``): the seconds per evaluation (its wall time, FMU
loading and the pythonfmu FMUs' numba compilation included, over its evaluations) and their
ratio are the comparison; the wall time its identification would take at the native run's
evaluation count is projected as its wall time plus one single run per missing evaluation.
Single co-simulation runs over the whole record are timed for the three pairings (the
pythonfmu pair once, the others best of ``--repeats``).

The pythonfmu run goes first: in this process a pythonfmu law FMU instantiated after a
native one fails ``fmi2Instantiate`` (seen while writing this benchmark; not yet traced).

Figures (2 cores shared with other jobs; ``uptime`` load averages in brackets), run
``nice python benchmarks/bench_emps_cosim.py``:

see the bottom of this docstring, filled in from the run.

Run: ``nice python benchmarks/bench_emps_cosim.py [--max-evals N] [--py-evals M]
[--repeats R] [--json OUT]``
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

NAMES = ("Fc", "Fs", "vs", "sigma2", "b")


def _load() -> str:
    try:
        return subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()
    except OSError:
        return "uptime unavailable"


def one_run(plant_fmu, conn, law, mrec, native_law: bool, repeats: int) -> float:
    """Best wall time [s] of one closed-loop co-simulation over ``mrec``."""
    from fmus.connect import PlantLoop
    from fmus.master import law_parameters
    best = float("inf")
    with PlantLoop(plant_fmu, conn, law, native=native_law) as loop:
        for _ in range(repeats):
            t0 = time.perf_counter()
            loop.run(mrec, law_parameters(law))
            best = min(best, time.perf_counter() - t0)
    return best


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--max-evals", type=int, default=200,
                    help="budget of the native identification")
    ap.add_argument("--py-evals", type=int, default=8,
                    help="budget of the pythonfmu identification")
    ap.add_argument("--repeats", type=int, default=3, help="single-run timings: best of")
    ap.add_argument("--json", help="write the figures here")
    a = ap.parse_args(argv)

    from fmus.connect import parse_connection
    from plants.studies import emps as st
    E = st.load_record("estimation")
    out = tempfile.mkdtemp(prefix="bench_emps_")
    t0 = time.perf_counter()
    nat = st.build_native_fmus(os.path.join(out, "native"))
    py = st.build_fmus(os.path.join(out, "pythonfmu"))
    build_s = time.perf_counter() - t0
    start = st.start_model()
    mrec = st.measured_record(E)
    conn_nat = st.native_connection(start, "closed", nat, E.initial())
    conn_py = parse_connection(st.connection_dict(start, "closed", identify=("M",)),
                               "emps_closed.toml")
    res = {"samples": int(E.t.size), "build_s": build_s, "load_before": _load(),
           "names": list(NAMES) + ["plant.M"]}

    # -- pythonfmu first (see the docstring) ---------------------------------------------------
    single = {"pythonfmu": one_run(py["emps_loop"], conn_py, start.law, mrec, False, 1)}
    t0 = time.perf_counter()
    r_py = st.identify_native(start, E, nat, names=NAMES, max_evals=a.py_evals, native=False,
                              plant_fmu=py["emps_loop"], conn=conn_py)
    wall_py = time.perf_counter() - t0
    single["pythonfmu plant + native law"] = one_run(py["emps_loop"], conn_py, start.law, mrec,
                                                     True, a.repeats)
    single["native"] = one_run(nat["emps_axis"], conn_nat, start.law, mrec, True, a.repeats)
    t0 = time.perf_counter()
    r_nat = st.identify_native(start, E, nat, names=NAMES, max_evals=a.max_evals)
    wall_nat = time.perf_counter() - t0

    def summary(r, wall):
        return {"wall_s": wall, "evaluations": int(r.n_evals),
                "s_per_evaluation": wall / max(1, int(r.n_evals)),
                "fit_nrmse": float(r.fit_nrmse),
                "params": {k: float(v) for k, v in r.params.items()}}
    res["native"] = summary(r_nat, wall_nat)
    res["pythonfmu"] = summary(r_py, wall_py)
    res["ratio_s_per_evaluation"] = (res["pythonfmu"]["s_per_evaluation"]
                                     / res["native"]["s_per_evaluation"])
    # its identification at the native run's evaluation count: what it took (FMU loading,
    # the pythonfmu FMUs' numba compilation, its evaluations) plus one run per missing one
    res["pythonfmu_projected_wall_s"] = wall_py + single["pythonfmu"] * max(
        0, res["native"]["evaluations"] - res["pythonfmu"]["evaluations"])
    res["ratio_single_run"] = single["pythonfmu"] / single["native"]
    res["single_run_s"] = single
    res["goal_native_wall_s"] = 60.0
    res["load_after"] = _load()
    print(json.dumps(res, indent=2))
    if a.json:
        with open(a.json, "w") as fh:
            json.dump(res, fh, indent=2)
    return res


if __name__ == "__main__":
    main()
