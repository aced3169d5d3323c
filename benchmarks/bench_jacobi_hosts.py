"""What a Jacobi-only co-simulation host (OSP libcosim, ecos) makes of our FMUs, per plant.

Each plant FMU (pythonfmu, external friction) is coupled with its friction law as a native
Co-Simulation FMU and run to the plant's reference integrator (``Plant.simulate(method=
"reference")``, monolithic Radau); the error is the NRMSE of the plant's main output at its
data rate. Rows:

* ``GS linearised`` - our recipe: Gauss-Seidel, plant first, the law's coupling outputs
  (``dF_dx`` ...) wired to the plant, ``h_lin`` = the step (what ``plant_master`` does);
* ``Jacobi hold`` - what a user of a Jacobi host wires by hand: ``v`` to the law, ``F`` back,
  every FMU stepping with the inputs of the previous communication point (libcosim's and
  ecos' fixed-step algorithm; our master's ``algorithm="jacobi"`` is the same scheme, and the
  script checks it against libcosim itself at the data step);
* ``Jacobi linearised`` - the same host with the coupling outputs wired too.

For the Jacobi rows the step is halved until the NRMSE is at most ``--tol`` (1e-3): the
communication step such a host needs. The Model Exchange route (the law's states in the
host's own solver) is available only where the host integrates ME FMUs - libcosim and ecos
do not; for a mass + law loop it is measured by ``tests/test_native_me.py`` (NRMSE 1e-9).

Run: ``python benchmarks/bench_jacobi_hosts.py [--plants valve,damping_rig] [--samples 400]``
(the plant FMUs are built first: about a minute). Prints a table and writes
``bench_jacobi_hosts.json``.
"""
from __future__ import annotations

import argparse
import json
import math
import pathlib
import tempfile
import time


def nrmse_run(master, ref, main, stop, hd, h):
    from friction.metrics import nrmse
    from fmus.master import FMUError
    per = int(round(hd / h))
    if "h_lin" in master.parameters.get("friction", {}):
        master.parameters["friction"]["h_lin"] = h
    try:
        res = master.simulate(stop_time=stop, step_size=h)
    except FMUError:
        return math.inf
    err = float(nrmse(ref[main], res[f"plant.{main}"][::per]))
    return err if math.isfinite(err) else math.inf


def step_needed(master, ref, main, stop, hd, tol, max_halvings):
    """(error at the data step, the first step meeting tol or None, its error)."""
    first = None
    for k in range(max_halvings + 1):
        h = hd / 2 ** k
        e = nrmse_run(master, ref, main, stop, hd, h)
        if first is None:
            first = e
        if e <= tol:
            return first, h, e
    return first, None, e


def libcosim_check(fmu_dir, plant_name, law, stop, hd):
    """Max |libcosim - our Jacobi master| of the main output at the data step (hold)."""
    import numpy as np
    import plants
    from fmus.external import run_libcosim
    from fmus.master import Master, fmu_file, fmu_values, law_parameters
    from fmus.plant_fmus import plant_connections
    cls = plants.PLANTS[plant_name]
    fmus = {"plant": fmu_file(fmu_dir, plant_name), "friction": fmu_file(fmu_dir, law.name, True)}
    conns = plant_connections(cls, type(law), "hold")
    main = cls.main_output
    with Master(fmus, conns, algorithm="jacobi", parameters={"friction": law_parameters(law)},
                record=[f"plant.{main}"]) as m:
        ours = m.simulate(stop_time=stop, step_size=hd)
        variables = m.instances["friction"].vars
    params = {"friction": fmu_values(variables, law_parameters(law))}
    theirs = run_libcosim(fmus, conns, step_size=hd, stop_time=stop, parameters=params,
                          record=[f"plant.{main}"])
    a = ours[f"plant.{main}"][1:]
    b = theirs[f"plant.{main}"][:a.size]
    return float(np.max(np.abs(a - b)) / (np.max(np.abs(a)) + 1e-300))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--plants", default=None, help="comma-separated plant names (default all)")
    ap.add_argument("--samples", type=int, default=400, help="data samples per run")
    ap.add_argument("--tol", type=float, default=1e-3)
    ap.add_argument("--max-halvings", type=int, default=6)
    ap.add_argument("--fmu-dir", default=None)
    ap.add_argument("--out", default="bench_jacobi_hosts.json")
    args = ap.parse_args(argv)

    import plants
    from fmus.build import build_all
    from fmus.plant_fmus import plant_laws, plant_master
    names = args.plants.split(",") if args.plants else list(plants.PLANTS)
    fmu_dir = pathlib.Path(args.fmu_dir or tempfile.mkdtemp(prefix="bench_jacobi_"))
    laws = sorted({n for p in names for n in plant_laws(plants.PLANTS[p])})
    t0 = time.monotonic()
    build_all(fmu_dir, only=names + [f"{n}_native" for n in laws], progress=False,
              kinds=("native", "pythonfmu"))
    print(f"FMUs built in {time.monotonic() - t0:.0f} s into {fmu_dir}")
    rows = []
    for pname in names:
        cls = plants.PLANTS[pname]
        hd = 1.0 / cls.data_rate
        stop = min(float(cls.default_experiment.stop), args.samples * hd)
        n = int(round(stop / hd))
        stop = n * hd
        main = cls.main_output
        for lname, law in plant_laws(cls).items():
            t1 = time.monotonic()
            ref = cls(friction=law).simulate(stop, method="reference", rtol=1e-9)
            row = {"plant": pname, "law": lname, "data_step": hd, "stop": stop}
            with plant_master(fmu_dir, pname, law, native=True) as m:
                row["gs_linearised"] = nrmse_run(m, ref, main, stop, hd, hd)
            for coupling in ("hold", "linearised"):
                with plant_master(fmu_dir, pname, law, native=True, algorithm="jacobi",
                                  coupling=coupling) as m:
                    first, h, e = step_needed(m, ref, main, stop, hd, args.tol,
                                              args.max_halvings)
                row[f"jacobi_{coupling}"] = first
                row[f"jacobi_{coupling}_step_for_tol"] = h
                row[f"jacobi_{coupling}_steps_per_sample"] = (None if h is None
                                                             else int(round(hd / h)))
            try:
                row["libcosim_vs_our_jacobi"] = libcosim_check(fmu_dir, pname, law, stop, hd)
            except Exception as exc:  # noqa: BLE001 - report, keep the table
                row["libcosim_vs_our_jacobi"] = f"{type(exc).__name__}: {exc}"
            row["seconds"] = round(time.monotonic() - t1, 1)
            rows.append(row)
            print(json.dumps(row), flush=True)
    print()
    print(f"{'plant':14s} {'law':15s} {'GS lin':>9s} {'Jac hold':>9s} {'x/GS':>7s} "
          f"{'Jac lin':>9s} {'hold: steps/sample':>19s} {'lin: steps/sample':>18s} "
          f"{'libcosim=ours':>13s}")
    for r in rows:
        ratio = r["jacobi_hold"] / r["gs_linearised"] if r["gs_linearised"] > 0 else math.inf
        lc = r["libcosim_vs_our_jacobi"]
        lc = f"{lc:.1e}" if isinstance(lc, float) else "n/a"
        print(f"{r['plant']:14s} {r['law']:15s} {r['gs_linearised']:9.2e} "
              f"{r['jacobi_hold']:9.2e} {ratio:7.0f} {r['jacobi_linearised']:9.2e} "
              f"{str(r['jacobi_hold_steps_per_sample']):>19s} "
              f"{str(r['jacobi_linearised_steps_per_sample']):>18s} {lc:>13s}")
    pathlib.Path(args.out).write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    main()
