"""Speed of the friction-law kernels against a plain-numpy baseline measured in the same run.

Two figures per law (issue 2, "Performance"):

1. ns per sample of the single-parameter-set kernel at N = 1e6 on one core
   (``numba.set_num_threads(1)``; aim <= 30 ns for classic LuGre);
2. a population of 64 parameter sets x 10,000 samples through the parallel population
   kernel on all cores (aim <= 20 ms on 2 cores).

Baselines, measured in the same run and scaled per sample:

* ``py``: the very same kernel source run as plain Python over numpy scalars and arrays
  (a child process with ``NUMBA_DISABLE_JIT=1``), on a shorter record;
* ``np-pop`` (classic LuGre): the population update vectorised over the 64 parameter sets
  with numpy, a Python loop over the samples.

Each timing is the best of several repeats after a warm-up call (compilation excluded).

Usage: ``python benchmarks/bench_friction_kernels.py [--quick]``
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time

import numpy as np

H = 5e-5  # 20 kHz, the valve's sampling (seed 000)


def _record(model, n):
    """A prescribed motion of n samples at the law's typical speed, plus its extra inputs."""
    t = np.arange(n) * H
    scale = getattr(model, "velocity_scale", lambda: 0.02)()
    w = 2 * np.pi * 5.0
    v = scale * np.sin(w * t) + 0.1 * scale * np.sin(7.3 * w * t)
    kw = {}
    if "a" in model.extra_inputs:
        kw["a"] = scale * w * np.cos(w * t) + 0.1 * scale * 7.3 * w * np.cos(7.3 * w * t)
    if "load" in model.extra_inputs:
        kw["load"] = 1e5 + 2e4 * np.sin(2 * np.pi * 0.5 * t)
    return t, v, kw


def _best(fn, repeats, clock=time.perf_counter):
    best = np.inf
    for _ in range(repeats):
        t0 = clock()
        fn()
        best = min(best, clock() - t0)
    return best


def _population_X(model, npop, seed=0):
    """npop parameter sets: the first (up to) three free parameters spread by +-20 %."""
    names = [n for n in model.free_names() if n in model.theta_layout
             and getattr(model.params, n) not in (0.0, None)][:3]
    rng = np.random.default_rng(seed)
    base = np.array([getattr(model.params, n) for n in names])
    return names, base * rng.uniform(0.8, 1.2, size=(npop, len(names)))


def measure(names, n_single, n_pop, npop, repeats, threads):
    """Seconds per sample of the single and population kernels of each law."""
    import numba

    from friction import METHODS, make_model

    out = {}
    for name in names:
        m = make_model(name)
        t, v, kw = _record(m, n_single)
        m.simulate(t[:1000], v[:1000], **{k: a[:1000] for k, a in kw.items()})  # validates
        ti, vi, ai, li, xi = m._inputs(t, v, **kw)
        s0 = m.initial_state()
        numba.set_num_threads(1)
        m._kernel(ti[:100], vi[:100], ai[:100] if ai.size else ai, li[:100] if li.size else li,
                  xi[:100] if xi.size else xi, m.theta, METHODS["exact"], s0)  # compile
        def run_single():
            m._kernel(ti, vi, ai, li, xi, m.theta, METHODS["exact"], s0)
        single = _best(run_single, repeats) / n_single
        # CPU time of this thread: robust when other processes share the cores
        single_cpu = _best(run_single, repeats, time.thread_time) / n_single
        tp, vp, kwp = _record(m, n_pop)
        pnames, X = _population_X(m, npop)
        numba.set_num_threads(threads)
        m.simulate_population(tp[:100], vp[:100], pnames, X[:2],
                              **{k: a[:100] for k, a in kwp.items()})  # compile
        tq, vq, aq, lq, xq = m._inputs(tp, vp, **kwp)
        Theta = m.population_theta(pnames, X)
        def run_pop():
            m._population_kernel(tq, vq, aq, lq, xq, Theta, METHODS["exact"])
        pop = _best(run_pop, repeats)
        pop_cpu = _best(run_pop, repeats, time.process_time)  # summed over the threads
        out[name] = {"single_s_per_sample": single, "single_cpu_s_per_sample": single_cpu,
                     "pop_s": pop, "pop_cpu_s": pop_cpu,
                     "pop_s_per_sample": pop / (npop * n_pop)}
    return out


def numpy_population_lugre(n, npop, repeats):
    """Classic LuGre population vectorised over the parameter sets (numpy), loop over samples."""
    from friction import make_model
    from friction.lugre import _LAYOUT

    m = make_model("lugre")
    t, v, _ = _record(m, n)
    names, X = _population_X(m, npop)
    th = m.population_theta(names, X)
    L = {k: i for i, k in enumerate(_LAYOUT)}

    def run():
        z = np.zeros(npop)
        F = np.empty((npop, n))
        s0 = th[:, L["sigma0"]]
        s1 = th[:, L["sigma1"]]
        for k in range(n):
            vk = v[k]
            neg = vk < 0
            Fc = th[:, L["Fc_neg"]] if neg else th[:, L["Fc"]]
            Fs = th[:, L["Fs_neg"]] if neg else th[:, L["Fs"]]
            vs = th[:, L["vs_neg"]] if neg else th[:, L["vs"]]
            s2 = th[:, L["sigma2_neg"]] if neg else th[:, L["sigma2"]]
            g = Fc + (Fs - Fc) * np.exp(-(vk / vs) ** 2)
            zd = vk - s0 * abs(vk) / g * z
            F[:, k] = s0 * z + s1 * zd + s2 * vk
            if k + 1 < n:
                vm = 0.5 * (vk + v[k + 1])
                gm = Fc + (Fs - Fc) * np.exp(-(vm / vs) ** 2)
                a = s0 * abs(vm) / gm
                e = np.exp(-a * (t[k + 1] - t[k]))
                z = np.where(a > 0, z * e + vm * (1 - e) / np.where(a > 0, a, 1.0), z)
        return F

    return _best(run, repeats) / (npop * n)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="smaller records (smoke run)")
    ap.add_argument("--baseline-child", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("--laws", nargs="*", default=None)
    args = ap.parse_args(argv)

    from friction import MODELS

    laws = args.laws or sorted(MODELS)
    if args.baseline_child:  # plain Python over numpy: NUMBA_DISABLE_JIT=1 set by the parent
        res = measure(laws, n_single=5_000 if args.quick else 20_000, n_pop=200, npop=64,
                      repeats=2, threads=1)
        print(json.dumps(res))
        return

    import numba

    n_single = 100_000 if args.quick else 1_000_000
    n_pop, npop = 10_000, 64
    threads = numba.config.NUMBA_NUM_THREADS
    print(f"# friction kernels: N = {n_single:.0e} single, population {npop} x {n_pop}, "
          f"{threads} threads for the population, numba {numba.__version__}, "
          f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores", flush=True)
    fast = measure(laws, n_single, n_pop, npop, repeats=3 if args.quick else 7,
                   threads=threads)
    env = dict(os.environ, NUMBA_DISABLE_JIT="1")
    child = subprocess.run([sys.executable, __file__, "--baseline-child", "--laws", *laws]
                           + (["--quick"] if args.quick else []),
                           env=env, capture_output=True, text=True, check=True)
    slow = json.loads(child.stdout.strip().splitlines()[-1])
    np_pop = numpy_population_lugre(2_000 if args.quick else 5_000, npop, 2)

    hdr = (f"{'law':16s} {'ns/sample':>9s} {'(cpu)':>6s} {'py ns':>7s} {'speed-up':>8s} | "
           f"{'pop ms':>7s} {'(cpu)':>6s} {'py pop ms':>9s} {'speed-up':>8s}")
    print(hdr)
    print("-" * len(hdr))
    for name in laws:
        f, s = fast[name], slow[name]
        py_pop_ms = s["pop_s_per_sample"] * npop * n_pop * 1e3
        print(f"{name:16s} {f['single_s_per_sample'] * 1e9:9.1f} "
              f"{f['single_cpu_s_per_sample'] * 1e9:6.1f} "
              f"{s['single_s_per_sample'] * 1e9:7.0f} "
              f"{s['single_s_per_sample'] / f['single_s_per_sample']:8.0f} | "
              f"{f['pop_s'] * 1e3:7.2f} {f['pop_cpu_s'] * 1e3:6.1f} {py_pop_ms:9.0f} "
              f"{s['pop_s_per_sample'] * npop * n_pop / f['pop_s']:8.0f}")
    print("(ns/sample: best wall time, one thread; (cpu): thread CPU time, robust to other "
          "load. pop: 64 sets x 1e4 samples, wall / CPU summed over threads. py: the same "
          "kernel source without JIT, per sample, scaled from a shorter record.)")
    lp = fast.get("lugre")
    if lp:
        print(f"\nclassic LuGre population vs numpy vectorised over the 64 sets: "
              f"{np_pop * npop * n_pop * 1e3:.1f} ms -> {lp['pop_s'] * 1e3:.2f} ms "
              f"(speed-up {np_pop * npop * n_pop / lp['pop_s']:.0f})")
        print(f"aims: classic LuGre single <= 30 ns/sample: "
              f"{'met' if lp['single_s_per_sample'] <= 30e-9 else 'MISSED'} "
              f"({lp['single_s_per_sample'] * 1e9:.1f} ns wall, "
              f"{lp['single_cpu_s_per_sample'] * 1e9:.1f} ns CPU); population <= 20 ms: "
              f"{'met' if lp['pop_s'] <= 20e-3 else 'MISSED'} ({lp['pop_s'] * 1e3:.2f} ms wall, "
              f"{lp['pop_cpu_s'] * 1e3:.1f} ms CPU over the threads)")
    print(f"load average now {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
