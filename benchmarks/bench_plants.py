"""Speed of the plant library's fast stepper against the reference integrator of the same
plant, measured in the same run.

Figures (XML-350, seed 003 S-curve move of 1 um under the SD-PID with LuGre feedforward,
10 kHz control, encoder quantisation off so both integrators solve the same problem):

1. wall time of ``simulate(method="fast")`` and of ``simulate(method="reference")``
   (solve_ivp Radau, rtol 1e-9) for the same horizon, and their ratio;
2. the fast stepper's cost per simulated second and its real-time factor;
3. the accuracy bought: NRMSE of the fast position against the reference.

Each timing is the best of ``--repeats`` runs after a warm-up (numba compilation excluded);
CPU time is printed next to wall time because the machine's cores are shared.

Usage: ``python benchmarks/bench_plants.py [--quick] [--repeats N]``
"""
from __future__ import annotations

import argparse
import os
import time

from friction.metrics import nrmse
from plants.xml350 import XML350


def _best(fn, repeats):
    wall, cpu, out = float("inf"), float("inf"), None
    for _ in range(repeats):
        w0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        wall = min(wall, time.perf_counter() - w0)
        cpu = min(cpu, time.process_time() - c0)
    return wall, cpu, out


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="shorter horizon")
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args(argv)
    horizon = 0.01 if args.quick else 0.03
    stage = XML350(resolution=0.0)
    stage.simulate(0.002, distance=1e-6)  # warm-up: numba kernels, caches
    stage.simulate(0.02, distance=1e-6, engine="numba")  # warm-up / load the cached kernel
    wf, cf, fast = _best(lambda: stage.simulate(horizon, distance=1e-6, engine="python"),
                         args.repeats)
    wn, cn, fastn = _best(lambda: stage.simulate(horizon, distance=1e-6, engine="numba"),
                          args.repeats)
    wr, cr, ref = _best(lambda: stage.simulate(horizon, method="reference", distance=1e-6),
                        1 if args.quick else max(1, args.repeats // 2))
    err = nrmse(ref["x"], fast["x"])
    print(f"XML-350 S-curve 1 um, horizon {horizon * 1e3:.0f} ms at 10 kHz "
          f"(load average {os.getloadavg()[0]:.2f})")
    print(f"  reference (solve_ivp Radau, rtol 1e-9): {wr:8.3f} s wall, {cr:8.3f} s CPU")
    print(f"  fast, Python stepper (Heun + exact)     : {wf:8.3f} s wall, {cf:8.3f} s CPU")
    print(f"  fast, compiled kernel (same scheme)     : {wn:8.4f} s wall, {cn:8.4f} s CPU")
    print(f"  speed-up stepper / reference            : {wr / wf:8.1f} x wall, "
          f"{cr / cf:8.1f} x CPU")
    print(f"  speed-up kernel / reference             : {wr / wn:8.1f} x wall, "
          f"{cr / max(cn, 1e-9):8.1f} x CPU")
    print(f"  stepper cost per simulated second       : {wf / horizon:8.2f} s "
          f"(real-time factor {horizon / wf:.2f})")
    print(f"  kernel cost per simulated second        : {wn / horizon:8.3f} s "
          f"(real-time factor {horizon / wn:.1f})")
    print(f"  NRMSE(x) fast vs reference              : {err:8.2e}")
    print(f"  max |x_kernel - x_stepper| / max|x|     : "
          f"{abs(fastn['x'] - fast['x']).max() / abs(fast['x']).max():8.1e}")
    return {"fast_wall": wf, "kernel_wall": wn, "reference_wall": wr, "speedup": wr / wf,
            "kernel_speedup": wr / wn, "nrmse_x": err}


if __name__ == "__main__":
    main()
