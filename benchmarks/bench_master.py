"""Per-step cost of our co-simulation master against a bare fmpy loop and in-process numba.

Loops: ``--loop xml350`` (default): the XML-350 loop from five part FMUs (S-curve
trajectory, LuGre feedforward, SD-PID, stage mechanics, LuGre friction) at 10 kHz;
``--loop mass``: the mass + classic LuGre FMUs. Three runs of the same equations and
communication step, in the same process:

1. ``Master`` (Gauss-Seidel, prebuilt ctypes buffers, raw FMI function pointers);
2. a bare fmpy ``FMU2Slave`` loop over the same FMUs (``setReal``/``doStep``/``getReal``,
   the usual fmpy way of writing a master);
3. the in-process numba simulation of the same equations (mass with the exact bristle
   update, no FMI at all).

Prints microseconds per communication step and the ratios (master / bare fmpy: aim <= 0.7),
and the FMI calls per communication step of both loops (counted in separate short runs):
in the mass loop both make the same calls, so the ratio is the per-call overhead; in the
XML-350 loop the master's fixed-point pass skips instances whose inputs did not change,
where the bare loop re-sets and re-reads every instance with inputs.

Run: ``python benchmarks/bench_master.py [--steps N]``
"""
from __future__ import annotations

import argparse
import math
import shutil
import time

import numpy as np


def bare_fmpy(fmu_dir, n, h, counts=None):
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
    if counts is not None:
        _count_methods([ms, fs], counts, {"setReal": "fmi2SetReal", "doStep": "fmi2DoStep",
                                          "getReal": "fmi2GetReal"})
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
    if counts is not None:
        for key in counts:
            counts[key] /= n
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


def bare_loop(fmus, connections, order, n, h, settle=True, counts=None):
    """The same Gauss-Seidel scheme written the usual fmpy way (list-based calls).

    ``counts`` (a dict): filled with the FMI calls per communication step instead of timing
    (the methods are wrapped by counters, so the time returned is not meaningful).
    """
    from fmpy import extract, read_model_description
    from fmpy.fmi2 import FMU2Slave
    sl = {}
    for name, path in fmus.items():
        md = read_model_description(str(path))
        d = extract(str(path))
        s = FMU2Slave(guid=md.guid, unzipDirectory=d,
                      modelIdentifier=md.coSimulation.modelIdentifier, instanceName=name)
        s.instantiate()
        s.setupExperiment(startTime=0.0)
        s.enterInitializationMode()
        s.exitInitializationMode()
        vr = {v.name: v.valueReference for v in md.modelVariables}
        outs = [v.name for v in md.modelVariables if v.causality == "output"]
        sl[name] = (s, vr, outs, d)
    vals = {}
    ins = {name: [] for name in fmus}
    for src, dst in connections:
        di, dv = dst.split(".")
        ins[di].append((dv, src))

    def read(name):
        s, vr, outs, _ = sl[name]
        for o, val in zip(outs, s.getReal([vr[o] for o in outs])):
            vals[f"{name}.{o}"] = val

    def write(name):
        s, vr, _, _ = sl[name]
        if ins[name]:
            s.setReal([vr[v] for v, _ in ins[name]], [vals[src] for _, src in ins[name]])

    for name in order:  # no output read before its inputs are set (blocks sample t0)
        for o in sl[name][2]:
            vals[f"{name}.{o}"] = 0.0
    for name in order:  # in order after initialization, as the master does
        if ins[name]:
            write(name)
        read(name)
    for _ in range(len(order)):  # propagate through feedthrough chains
        for name in order:
            if ins[name]:
                write(name)
                read(name)
    if counts is not None:
        _count_methods([v[0] for v in sl.values()], counts,
                       {"setReal": "fmi2SetReal", "doStep": "fmi2DoStep",
                        "getReal": "fmi2GetReal"})
    t0 = time.perf_counter()
    for k in range(n):
        t = k * h
        for name in order:
            write(name)
            sl[name][0].doStep(t, h)
            read(name)
        if settle:
            for name in order:
                if ins[name]:
                    write(name)
                    read(name)
    el = time.perf_counter() - t0
    if counts is not None:
        for key in counts:
            counts[key] /= n
    for s, _, _, d in sl.values():
        s.terminate()
        s.fmi2FreeInstance(s.component)
        shutil.rmtree(d, ignore_errors=True)
    return el / n * 1e6, vals


def _count_methods(objs, counts, names):
    """Replace ``obj.<name>`` by a wrapper adding 1 to ``counts[label]`` per call."""
    for obj in objs:
        for attr, label in names.items():
            counts.setdefault(label, 0)
            fn = getattr(obj, attr)

            def wrapped(*args, _fn=fn, _label=label):
                counts[_label] += 1
                return _fn(*args)
            setattr(obj, attr, wrapped)


def master_calls_per_step(m, h, n=200):
    """FMI calls per communication step of an open Master (difference of two counted runs,
    so initialization calls drop out); the instances' function pointers are restored."""
    saved = {k: (i.raw_set, i.raw_step, i.raw_get) for k, i in m.instances.items()}
    totals = []
    try:
        for steps in (n, 2 * n):
            counts = {}
            _count_methods(m.instances.values(), counts, {"raw_set": "fmi2SetReal",
                                                          "raw_step": "fmi2DoStep",
                                                          "raw_get": "fmi2GetReal"})
            m.simulate(stop_time=steps * h, step_size=h, progress=False)
            totals.append(counts)
            for k, i in m.instances.items():
                i.raw_set, i.raw_step, i.raw_get = saved[k]
    finally:
        for k, i in m.instances.items():
            i.raw_set, i.raw_step, i.raw_get = saved[k]
    return {key: (totals[1][key] - totals[0][key]) / n for key in totals[0]}


def xml350_bench(n, repeats):
    import os
    from fmus.testing import built_fmus
    from fmus.plant_fmus import XML350_CONNECTIONS, XML350_ORDER, xml350_loop_master
    from plants.xml350 import XML350, xml350_friction
    names = ("lugre", "lugre_feedforward", "sdpid", "xml350_mechanics", "xml350_trajectory")
    fmu_dir = built_fmus(names)
    h = 1e-4
    us_m = us_b = us_n = math.inf
    with xml350_loop_master(fmu_dir) as m:
        m.simulate(stop_time=100 * h, step_size=h)  # warm-up (JIT inside the FMUs)
        fmus = {k: m.instances[k].path for k in m.instances}
        for _ in range(repeats):
            t0 = time.perf_counter()
            res = m.simulate(stop_time=n * h, step_size=h, progress=False)
            us_m = min(us_m, (time.perf_counter() - t0) / n * 1e6)
            ub, vals = bare_loop(fmus, XML350_CONNECTIONS, XML350_ORDER, n, h)
            us_b = min(us_b, ub)
            plant = XML350(friction=xml350_friction())
            plant.simulate(10 * h, method="fast")  # compile
            t0 = time.perf_counter()
            plant.simulate(n * h, method="fast")
            us_n = min(us_n, (time.perf_counter() - t0) / n * 1e6)
        calls_m = master_calls_per_step(m, h)
    calls_b = {}
    bare_loop(fmus, XML350_CONNECTIONS, XML350_ORDER, 200, h, counts=calls_b)
    same = abs(vals["mechanics.x"] - res["mechanics.x"][-1])
    print("FMI calls per communication step (set/step/get): "
          f"master {_calls(calls_m)}, bare fmpy {_calls(calls_b)}")
    return "XML-350 loop from 5 part FMUs (10 kHz)", us_m, us_b, us_n, same


def _calls(c):
    return "/".join(f"{c.get(k, 0):.2f}" for k in ("fmi2SetReal", "fmi2DoStep", "fmi2GetReal"))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=5000)
    ap.add_argument("--loop", choices=("xml350", "mass"), default="xml350")
    ap.add_argument("--repeats", type=int, default=7,
                    help="alternate the runs this often and keep each one's best (shared CPU)")
    args = ap.parse_args(argv)
    if args.loop == "xml350":
        try:
            label, us_master, us_bare, us_numba, same = xml350_bench(args.steps, args.repeats)
        except ImportError as exc:
            print(f"XML-350 parts not available ({exc}); use --loop mass")
            return
        _print(label, args.steps, 1e-4, us_master, us_bare, us_numba, same)
        return
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
        calls_m = master_calls_per_step(m, h)
    calls_b = {}
    bare_fmpy(fmu_dir, 200, h, counts=calls_b)
    print("FMI calls per communication step (set/step/get): "
          f"master {_calls(calls_m)}, bare fmpy {_calls(calls_b)}")
    same = float(np.max(np.abs(bare["x"] - res["mass.x"][1:])))
    _print("mass + LuGre loop", n, h, us_master, us_bare, us_numba, same)


def _print(label, n, h, us_master, us_bare, us_numba, same):
    print(f"{label}, {n} communication steps of {h:g} s")
    print(f"  master (ours)          : {us_master:8.1f} us/step")
    print(f"  bare fmpy FMU2Slave    : {us_bare:8.1f} us/step")
    print(f"  in-process numba       : {us_numba:8.3f} us/step")
    print(f"  ratio master / bare    : {us_master / us_bare:8.3f}  (aim <= 0.7)")
    print(f"  ratio master / numba   : {us_master / us_numba:8.0f}")
    print(f"  |x_master - x_bare|    : {same:.2e} m (same trajectory)")


if __name__ == "__main__":
    main()
