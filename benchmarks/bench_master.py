"""Per-step cost of our co-simulation master against a bare fmpy loop and in-process numba.

Loop: the mass + classic LuGre FMUs (the XML-350 loop from parts is not available as FMUs
yet). Three runs of the same equations and communication step, in the same process:

1. ``Master`` (Gauss-Seidel, prebuilt ctypes buffers, raw FMI function pointers);
2. a bare fmpy ``FMU2Slave`` loop over the same FMUs (``setReal``/``doStep``/``getReal``,
   the usual fmpy way of writing a master);
3. the in-process numba simulation of the same equations (mass with the exact bristle
   update, no FMI at all).

Prints microseconds per communication step and the ratios (master / bare fmpy: aim <= 0.7).

Run: ``python benchmarks/bench_master.py [--steps N]``
"""
from __future__ import annotations

import argparse
import math
import shutil
import time

import numpy as np


def bare_fmpy(fmu_dir, n, h):
    from fmpy import extract, read_model_description
    from fmpy.fmi2 import FMU2Slave
    out = {}
    slaves = {}
    for name, f in (("mass", "mass.fmu"), ("friction", "lugre.fmu")):
        path = str(fmu_dir / f)
        md = read_model_description(path)
        d = extract(path)
        s = FMU2Slave(guid=md.guid, unzipDirectory=d,
                      modelIdentifier=md.coSimulation.modelIdentifier, instanceName=name)
        s.instantiate()
        s.setupExperiment(startTime=0.0)
        s.enterInitializationMode()
        s.exitInitializationMode()
        slaves[name] = (s, {v.name: v.valueReference for v in md.modelVariables}, d)
    ms, mv, _ = slaves["mass"]
    fs, fv, _ = slaves["friction"]
    F = fs.getReal([fv["F"]])[0]
    x = np.empty(n)
    t0 = time.perf_counter()
    for k in range(n):
        t = k * h
        ms.setReal([mv["F_friction"]], [F])
        ms.doStep(t, h)
        xv = ms.getReal([mv["x"], mv["v"]])
        fs.setReal([fv["v"]], [xv[1]])
        fs.doStep(t, h)
        F = fs.getReal([fv["F"]])[0]
        x[k] = xv[0]
    el = time.perf_counter() - t0
    for s, _, d in slaves.values():
        s.terminate()
        s.fmi2FreeInstance(s.component)
        shutil.rmtree(d, ignore_errors=True)
    out["x"] = x
    return el / n * 1e6, out


def numba_inprocess(n, h):
    """The same loop in numba: mass (held force, exact sine integral) + LuGre exact update."""
    from numba import njit
    import friction
    from friction.lugre import _g_dir, bristle_update
    th = friction.make_model("lugre").theta
    s0, s1 = th[0], th[1]

    @njit(cache=False)
    def run(n, h, th, x):
        xm, vm, z = 0.0, 0.0, 0.0
        w = 2.0 * math.pi
        F = 0.0
        for k in range(n):
            t = k * h
            c0, c1 = math.cos(w * t), math.cos(w * (t + h))
            s_0, s_1 = math.sin(w * t), math.sin(w * (t + h))
            i1 = 2.0 * (c0 - c1) / w
            i2 = 2.0 * (h * c0 / w - (s_1 - s_0) / (w * w))
            xm = xm + vm * h + (-0.5 * F * h * h + i2)
            vm = vm + (-F * h + i1)
            g, s2 = _g_dir(vm, th)
            z = bristle_update(z, vm, s0 * abs(vm) / g, h, 0)
            g, s2 = _g_dir(vm, th)
            F = s0 * z + s1 * (vm - s0 * abs(vm) / g * z) + s2 * vm + th[11]
            x[k] = xm
        return x

    x = np.empty(n)
    run(10, h, th, np.empty(10))  # compile
    t0 = time.perf_counter()
    run(n, h, th, x)
    return (time.perf_counter() - t0) / n * 1e6


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=20000)
    ap.add_argument("--repeats", type=int, default=3,
                    help="alternate the runs this often and keep each one's best (shared CPU)")
    args = ap.parse_args(argv)
    from fmus.testing import built_fmus
    from fmus.proof import mass_master
    fmu_dir = built_fmus(("mass", "lugre"))
    n, h = args.steps, 1e-4
    sc = dict(m=1.0, u0=0.0, u_amp=2.0, u_freq=1.0, v0=0.0, stop=n * h)
    us_master = us_bare = us_numba = math.inf
    with mass_master(fmu_dir, "lugre", scenario=sc) as m:
        m.simulate(stop_time=100 * h, step_size=h)  # warm-up (numba compile inside the FMU)
        for _ in range(args.repeats):
            t0 = time.perf_counter()
            res = m.simulate(stop_time=n * h, step_size=h, progress=False)
            us_master = min(us_master, (time.perf_counter() - t0) / n * 1e6)
            ub, bare = bare_fmpy(fmu_dir, n, h)
            us_bare = min(us_bare, ub)
            us_numba = min(us_numba, numba_inprocess(n, h))
    same = float(np.max(np.abs(bare["x"] - res["mass.x"][1:])))
    print(f"mass + LuGre loop, {n} communication steps of {h:g} s")
    print(f"  master (ours)          : {us_master:8.1f} us/step")
    print(f"  bare fmpy FMU2Slave    : {us_bare:8.1f} us/step")
    print(f"  in-process numba       : {us_numba:8.3f} us/step")
    print(f"  ratio master / bare    : {us_master / us_bare:8.3f}  (aim <= 0.7)")
    print(f"  ratio master / numba   : {us_master / us_numba:8.0f}")
    print(f"  max |x_master - x_bare|: {same:.2e} m (same trajectory)")


if __name__ == "__main__":
    main()
