"""Native (C) FMUs against the pythonfmu FMUs of the same laws, measured in the same run.

Four figures, each with its pythonfmu baseline and the ratio:

1. one law FMU (classic LuGre): ``fmi2SetReal`` + ``fmi2DoStep`` + ``fmi2GetReal`` per
   communication step, called from Python the way our master's Python loop calls them
   (ctypes pointers without argtypes on prebuilt buffers, the GIL held; goal <= 2 us native)
   and from the master's compiled loop (:mod:`fmus.master_loop`; the same three calls from C);
2. from the FMU file to its first step in a fresh process per FMU kind, per phase: fmpy reads
   the description and unpacks the archive, the binary is loaded, ``fmi2Instantiate``
   (goal <= 50 ms native, no JIT), initialization and the first ``fmi2DoStep`` (where the
   pythonfmu FMU compiles its numba kernels, as every new process does);
3. our master, mass + LuGre, per communication step (Gauss-Seidel, 10 kHz): native FMUs in the
   compiled loop (goal <= 3 us) and in the Python loop; pythonfmu FMUs in both loops (the
   pythonfmu FMUs in the Python loop are the master as it was);
4. the prescribed-motion co-simulation identification objective
   (:class:`identification.cosim.CoSimObjective`) on the same data and parameter sets, native
   against pythonfmu FMUs: seconds per evaluation and the largest relative cost difference
   (goal: >= 10x faster, same cost to 1e-9).

Each timing alternates the kinds ``--repeats`` times and keeps each one's best (the machine
is shared). Run: ``python benchmarks/bench_native_fmus.py [--steps N] [--repeats R]``
"""
from __future__ import annotations

import argparse
import ctypes
import json
import math
import subprocess
import sys
import time

import numpy as np

LAW = "lugre"


def _dirs():
    from fmus.testing import built_fmus, built_native_fmus
    return built_fmus((LAW, "mass")), built_native_fmus((LAW, "mass"))


def _open_law(path):
    """A Master holding one law instance, initialized (its _Instance has the raw calls)."""
    from fmus.master import Master
    m = Master({"friction": str(path)}, [], record=[])
    m.simulate(stop_time=1e-3, step_size=1e-4)  # initialized, and a pythonfmu FMU compiled
    return m


def law_triple_python(path, n: int) -> float:
    """us per set + doStep + get from Python (the master's Python-loop calls)."""
    m = _open_law(path)
    try:
        inst = m.instances["friction"]
        vr = (ctypes.c_uint * 1)(inst.vars["v"].valueReference)
        buf = (ctypes.c_double * 1)()
        one = ctypes.c_size_t(1)
        ovr = (ctypes.c_uint * 1)(inst.vars["F"].valueReference)
        obuf = (ctypes.c_double * 1)()
        c, fset, fstep, fget = inst.cv, inst.raw_set, inst.raw_step, inst.raw_get
        h = 1e-4
        hc, c_double, true = ctypes.c_double(h), ctypes.c_double, ctypes.c_int(1)
        t = 1e-3  # where the initializing run ended
        v = (1e-3 * np.sin(np.arange(n) * 2 * math.pi * 1e-3)).tolist()
        t0 = time.perf_counter()
        for k in range(n):
            buf[0] = v[k]
            fset(c, vr, one, buf)
            fstep(c, c_double(t + k * h), hc, true)
            fget(c, ovr, one, obuf)
        el = time.perf_counter() - t0
    finally:
        m.close()
    return el / n * 1e6


def law_triple_c(path, n: int) -> float:
    """us per set + doStep + get from the master's compiled loop (input held)."""
    from types import SimpleNamespace
    from fmus import master_loop
    m = _open_law(path)
    try:
        inst = m.instances["friction"]
        vr = (ctypes.c_uint * 1)(inst.vars["v"].valueReference)
        buf = (ctypes.c_double * 1)(1e-3)
        ovr = (ctypes.c_uint * 1)(inst.vars["F"].valueReference)
        obuf = (ctypes.c_double * 1)()
        drive = SimpleNamespace(cv=inst.cv, raw_set=inst.raw_set, raw_step=inst.raw_step,
                                raw_get=inst.raw_get, in_vr=vr, in_buf=buf, n_in=1,
                                out_vr=ovr, out_buf=obuf, n_out=1, gather=())
        loop = master_loop.CLoop([drive], rec_src=[(obuf, 0)])
        rec = np.empty(n)
        # communication points k = 11.. continue the initializing run's 10 steps
        t0 = time.perf_counter()
        ok = loop.run(0.0, 1e-4, 11, 10 + n, rec)
        el = time.perf_counter() - t0
        if not ok:
            raise RuntimeError(f"compiled loop failed: {loop.error()}")
    finally:
        m.close()
    return el / n * 1e6


_INSTANTIATE = r"""
import json, shutil, sys, time
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave
path = sys.argv[1]
t0 = time.perf_counter()
md = read_model_description(path)
t1 = time.perf_counter()
d = extract(path)
t2 = time.perf_counter()
s = FMU2Slave(guid=md.guid, unzipDirectory=d, modelIdentifier=md.coSimulation.modelIdentifier,
              instanceName="law")
t3 = time.perf_counter()
s.instantiate()
t4 = time.perf_counter()
s.setupExperiment(startTime=0.0)
s.enterInitializationMode()
s.exitInitializationMode()
s.doStep(0.0, 1e-4)
t5 = time.perf_counter()
s.terminate()
s.freeInstance()
shutil.rmtree(d, ignore_errors=True)
print(json.dumps({"description": t1 - t0, "unpack": t2 - t1, "load": t3 - t2,
                  "instantiate": t4 - t3, "first_step": t5 - t4, "total": t5 - t0}))
"""
PHASES = ("description", "unpack", "load", "instantiate", "first_step", "total")


def instantiate(path) -> dict:
    """Seconds per phase from the FMU file to the end of its first ``fmi2DoStep``, in a fresh
    Python process (fmpy imported before the clock starts): fmpy reads the description and
    unpacks the archive, loads the binary, ``fmi2Instantiate``, then initialization and the
    first step (a pythonfmu FMU compiles its numba kernels there)."""
    out = subprocess.run([sys.executable, "-c", _INSTANTIATE, str(path)],
                         capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def master_step(d, native: bool, loop: str, n: int) -> tuple[float, np.ndarray]:
    """us per communication step of our master, mass + LuGre, and the position."""
    from fmus.proof import mass_master
    sc = dict(m=1.0, u0=0.0, u_amp=2.0, u_freq=1.0, v0=0.0, stop=n * 1e-4)
    with mass_master(d, LAW, scenario=sc, native=native) as m:
        m.loop = loop
        m.simulate(stop_time=100e-4, step_size=1e-4)  # warm-up (JIT inside a pythonfmu FMU)
        t0 = time.perf_counter()
        res = m.simulate(stop_time=n * 1e-4, step_size=1e-4, progress=False)
        el = time.perf_counter() - t0
    return el / n * 1e6, res["mass.x"]


def _objective_data():
    import friction
    from friction.dataset import Dataset
    true = friction.make_model(LAW, sigma0=1e5, sigma1=300.0, sigma2=0.4, Fc=1.0, Fs=1.5,
                               vs=1e-3)
    t = np.arange(0, 2.0, 1e-3)
    v = 0.01 * np.sin(2 * np.pi * 2 * t) + 0.002 * np.sin(2 * np.pi * 9 * t)
    noise = 0.01 * np.random.default_rng(0).standard_normal(t.size)
    data = Dataset.from_arrays(t, true.simulate(t, v) + noise, v=v)
    names = ["sigma0", "sigma1", "Fc", "Fs", "vs"]
    X = np.array([[1e5, 300.0, 1.0, 1.5, 1e-3], [4e4, 80.0, 0.7, 2.2, 4e-3],
                  [3e6, 1500.0, 1.3, 1.4, 2e-4], [2e5, 500.0, 0.9, 1.6, 1e-3]])
    return true, data, names, X


def objective(d, native: bool, obj_cache: dict) -> tuple[float, np.ndarray]:
    """Seconds per evaluation of the cosim objective, and the costs."""
    from identification.cosim import CoSimObjective
    true, data, names, X = obj_cache.setdefault("data", _objective_data())
    key = ("obj", native)
    if key not in obj_cache:
        obj_cache[key] = CoSimObjective(true, data, names, fmu_dir=d, native=native)
        obj_cache[key].costs(X[:1])  # opened, and a pythonfmu FMU compiled
    obj = obj_cache[key]
    t0 = time.perf_counter()
    c = obj.costs(X)
    return (time.perf_counter() - t0) / len(X), c


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=20000,
                    help="communication steps per timed run (master, single FMU)")
    ap.add_argument("--repeats", type=int, default=5,
                    help="alternate the runs this often and keep each one's best")
    args = ap.parse_args(argv)
    from fmus import master_loop
    from fmus.master import fmu_file
    py_dir, nat_dir = _dirs()
    paths = {False: fmu_file(py_dir, LAW), True: fmu_file(nat_dir, LAW, True)}
    has_c = master_loop.library() is not None
    n, reps = args.steps, args.repeats
    inf = math.inf

    # 1. one law FMU: set + doStep + get
    tri_py = {False: inf, True: inf}
    tri_c = {False: inf, True: inf}
    for _ in range(reps):
        for native in (False, True):
            m = n if native else max(2000, n // 5)
            tri_py[native] = min(tri_py[native], law_triple_python(paths[native], m))
            if has_c:
                tri_c[native] = min(tri_c[native], law_triple_c(paths[native], m))

    # 2. instantiate (fresh processes)
    inst = {False: dict.fromkeys(PHASES, inf), True: dict.fromkeys(PHASES, inf)}
    for _ in range(max(1, min(reps, 3))):
        for native in (False, True):
            r = instantiate(paths[native])
            for k in r:
                inst[native][k] = min(inst[native][k], r[k])

    # 3. master, mass + LuGre
    loops = ("c", "python") if has_c else ("python",)
    ms = {(nat, lp): inf for nat in (False, True) for lp in loops}
    xs = {}
    for _ in range(reps):
        for native in (False, True):
            for lp in loops:
                m = n if native else max(2000, n // 5)
                us, x = master_step(nat_dir if native else py_dir, native, lp, m)
                ms[native, lp] = min(ms[native, lp], us)
                xs[native, lp] = x
    k = min(len(x) for x in xs.values())
    same_x = max(float(np.max(np.abs(x[:k] - xs[False, "python"][:k]))) for x in xs.values())

    # 4. the cosim identification objective
    cache = {}
    ob = {False: inf, True: inf}
    costs = {}
    for _ in range(reps):
        for native in (False, True):
            s, c = objective(nat_dir if native else py_dir, native, cache)
            ob[native] = min(ob[native], s)
            costs[native] = c
    for k, v in cache.items():
        if k != "data":
            v.close()
    rel = float(np.max(np.abs(costs[True] / costs[False] - 1.0)))
    n_samples = len(cache["data"][1])

    print(f"Native (C) vs pythonfmu FMUs, law '{LAW}' (same run; best of {reps})")
    print("1. one law FMU, set + doStep + get per communication step")
    print(f"   from Python (master's ctypes path): native {tri_py[True]:7.2f} us   pythonfmu "
          f"{tri_py[False]:7.2f} us   ratio {tri_py[False] / tri_py[True]:6.1f}x   "
          f"(goal native <= 2 us)")
    if has_c:
        print(f"   from the compiled master loop     : native {tri_c[True]:7.2f} us   pythonfmu "
              f"{tri_c[False]:7.2f} us   ratio {tri_c[False] / tri_c[True]:6.1f}x")
    print("2. from the FMU file to its first step, in a fresh process")
    for k, label in (("instantiate", "fmi2Instantiate"),
                     ("first_step", "initialize + first fmi2DoStep"),
                     ("description", "(host) fmpy reads the description"),
                     ("unpack", "(host) fmpy unpacks the archive"),
                     ("load", "(host) dlopen of the binary"),
                     ("total", "all of the above")):
        goal = "   (goal native instantiate <= 50 ms, no JIT)" if k == "instantiate" else \
            "   (pythonfmu: numba JIT)" if k == "first_step" else ""
        print(f"   {label:35s}: native {inst[True][k] * 1e3:8.2f} ms   pythonfmu "
              f"{inst[False][k] * 1e3:8.1f} ms{goal}")
    print("3. our master, mass + LuGre, Gauss-Seidel, per communication step of 1e-4 s")
    base = ms[False, "python"]
    for lp in loops:
        print(f"   {lp:6s} loop                        : native {ms[True, lp]:7.2f} us   "
              f"pythonfmu {ms[False, lp]:7.2f} us   native vs pythonfmu (python loop) "
              f"{base / ms[True, lp]:6.1f}x" + ("   (goal native <= 3 us)" if lp == "c" else ""))
    print(f"   |x native - x pythonfmu|           : {same_x:.1e} m (same trajectory)")
    print(f"4. cosim identification objective ({n_samples} samples, prescribed motion)")
    print(f"   per evaluation                     : native {ob[True] * 1e3:7.2f} ms   pythonfmu "
          f"{ob[False] * 1e3:7.2f} ms   ratio {ob[False] / ob[True]:6.1f}x   (goal >= 10x)")
    print(f"   max |cost native / pythonfmu - 1|  : {rel:.1e}   (goal <= 1e-9)")
    if not has_c:
        print(f"(no compiled master loop: {master_loop.UNAVAILABLE})")


if __name__ == "__main__":
    main()
