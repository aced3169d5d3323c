"""Clean records made as real ones are: the diagnosis must put no name on them.

A *clean* record carries no effect outside the base law, but it is not the base law's own
output either. Each record here differs from what the diagnosis' candidates and base compute
in the ways real acquisition differs:

* **truth on a finer grid**: the plant's contact motion (:func:`diagnosis.benchmark.
  plant_kinematics`) is made continuous (a shape-preserving cubic through the sampled
  velocity, the position its exact integral) and the base law is integrated along it on a
  grid :data:`FINE` times finer than the data, either with the law's own compiled update at
  that step (``truth="fine"``) or with the friction package's reference integrator
  (``truth="reference"``: :func:`friction.reference.simulate_prescribed`, Radau, a different
  integrator), then sampled at the data rate (``sampling="point"``: the value at the sample
  instant, or ``"average"``: the mean over the preceding sample period, an integrating
  converter, half a sample late);
* **positions quantised and differentiated as a user would**: the position at the sample
  instants rounded to an encoder count of ``v99 dt / counts`` (``counts`` counts per sample
  at the record's top speed), the velocity from those counts by backward differences
  (``velocity="backward"``, half a sample late), by ``np.gradient`` (``"gradient"``) or
  ``np.gradient`` then a zero-phase second-order Butterworth low-pass at a fifth of the
  Nyquist frequency (``"lowpass"``), the acceleration ``np.gradient`` of that velocity;
* **noise**: white or coloured (white through a first-order low-pass of
  :data:`COLOUR_SAMPLES` samples, rescaled) at ``noise`` x std(F) [-]; the RMS of the added
  noise is returned as the figure a user would give for coloured noise (``noise_level=``,
  ``--noise-level``; from a standstill record).

:func:`clean_grid` lists the variants, :func:`run_clean` diagnoses them (resumable, see
``benchmarks/bench_diagnosis_clean.py``); the goal is no name at all: every verdict
``none`` or ``unexplained``.
"""
from __future__ import annotations

import itertools
import json
import os
import time

import numpy as np
from scipy.interpolate import PchipInterpolator

from friction.dataset import Dataset
from friction.progress import status_lines

# the benchmark's grid of the truth and its motion between samples (one definition)
from .benchmark.kinematics import (COLOUR_SAMPLES, FINE, fine_kinematics, measure_motion,
                                   noise_signal)
from .benchmark.truths import _lugre_run
from .verdict import decision_entries

__all__ = ["FINE", "COLOUR_SAMPLES", "fine_truth", "clean_record", "clean_grid", "run_clean",
           "clean_summary", "NO_NAME", "level_truth_record"]

#: verdicts that put no name on a record
NO_NAME = ("none", "unexplained", "base_unfit")

_TRUTH_CACHE: dict = {}


def fine_truth(kin, truth: str = "fine", cache_dir=None) -> dict:
    """Noise-free friction force of the plant's base law along its continuous motion.

    Parameters
    ----------
    kin : diagnosis.benchmark.PlantKinematics
        The plant's sampled motion and base law.
    truth : str
        ``"fine"``: the law's compiled update at a step of dt / :data:`FINE`;
        ``"reference"``: :func:`friction.reference.simulate_prescribed` (Radau) evaluated
        at the same fine grid.
    cache_dir : str, optional
        Directory the (slow) reference truth is stored in as ``.npz`` and read back from.

    Returns
    -------
    dict
        ``t_f`` [s], ``x_f`` [m], ``v_f`` [m/s], ``a_f`` [m/s^2], ``F_f`` [N] on the fine
        grid.
    """
    key = (kin.plant, kin.t.size, truth)
    if key in _TRUTH_CACHE:
        return _TRUTH_CACHE[key]
    path = None
    if cache_dir is not None:
        os.makedirs(cache_dir, exist_ok=True)
        path = os.path.join(cache_dir, f"truth-{kin.plant}-{kin.t.size}-{truth}.npz")
        if os.path.exists(path):
            with np.load(path) as z:
                out = {k: z[k] for k in z.files}
            _TRUTH_CACHE[key] = out
            return out
    fk = fine_kinematics(kin)
    t_f, x_f, v_f, a_f = fk.t, fk.x, fk.v, fk.a
    law = kin.base
    kw = {"x": x_f} if "x" in law.extra_inputs else {}
    if truth == "fine":
        F_f = law.simulate(t_f, v_f, **kw)
    elif truth == "reference":
        from friction.reference import simulate_prescribed
        F_f = simulate_prescribed(law, t_f, v_f, **kw)
    else:
        raise ValueError(f"truth must be 'fine' or 'reference', got {truth!r}")
    out = {"t_f": t_f, "x_f": x_f, "v_f": v_f, "a_f": a_f, "F_f": np.asarray(F_f, float)}
    if path is not None:
        np.savez(path, **out)
    _TRUTH_CACHE[key] = out
    return out


def clean_record(kin, *, truth: str = "fine", sampling: str = "point",
                 velocity: str = "gradient", counts: float = 200.0, noise: float = 0.01,
                 colour: str = "white", seed: int = 0, cache_dir=None):
    """One clean record of a plant (see the module docstring for the variants).

    Parameters
    ----------
    kin : diagnosis.benchmark.PlantKinematics
    truth : {"fine", "reference"}
        Integrator of the truth on the fine grid.
    sampling : {"point", "average"}
        Force sampled at the instant or averaged over the preceding sample period.
    velocity : {"backward", "gradient", "lowpass"}
        How the velocity is differentiated from the quantised position.
    counts : float
        Encoder counts per sample at the record's top speed (99th percentile of |v|) [-].
    noise : float
        Noise RMS as a fraction of std(F) [-].
    colour : {"white", "coloured"}
        White noise, or white noise through a first-order low-pass of
        :data:`COLOUR_SAMPLES` samples.
    seed : int
        Seed of the noise.

    Returns
    -------
    (Dataset, float)
        The record (``t`` [s], ``x`` [m], ``v`` [m/s], ``a`` [m/s^2], ``F`` [N], ``load``
        [N]) and the RMS of the added noise [N].
    """
    ft = fine_truth(kin, truth, cache_dir)
    n = kin.t.size
    t = kin.t
    idx = np.arange(n) * FINE
    if sampling == "point":
        F0 = ft["F_f"][idx]
    elif sampling == "average":
        Ff = ft["F_f"]
        # mean over the FINE + 1 fine points of [t_k - dt, t_k] (trapezoid), the first sample
        # at the instant
        c = np.concatenate([[0.0], np.cumsum(0.5 * (Ff[1:] + Ff[:-1]))])
        F0 = np.empty(n)
        F0[0] = Ff[0]
        F0[1:] = (c[idx[1:]] - c[idx[1:] - FINE]) / FINE
    else:
        raise ValueError(f"sampling must be 'point' or 'average', got {sampling!r}")
    x, v, a = measure_motion(kin, counts, velocity)
    e = noise_signal(n, colour, np.random.default_rng(seed))
    sd = float(np.std(F0)) or 1.0
    w = noise * sd * e
    name = f"{kin.plant}-clean-{truth}-{sampling}-{velocity}-c{counts:g}-{colour}-n{noise:g}-s{seed}"
    data = Dataset.from_arrays(t, F0 + w, x=x, v=v, a=a, load=kin.load, name=name,
                               check_units=False)
    return data, float(np.sqrt(np.mean(w ** 2)))


def clean_grid(plants, count: int, seed: int = 0) -> list[dict]:
    """``count`` clean-record variants spread evenly over ``plants`` and the variant axes
    (truth, sampling, velocity, counts, noise level, colour), each with its own noise seed.

    Returns
    -------
    list of dict
        Keyword arguments of :func:`clean_record` plus ``plant`` and ``key``.
    """
    axes = list(itertools.product(("fine", "reference"), ("point", "average"),
                                  ("backward", "gradient", "lowpass"), (50.0, 1000.0),
                                  (0.005, 0.01, 0.02, 0.05), ("white", "coloured")))
    rng = np.random.default_rng(seed)
    order = rng.permutation(len(axes))
    jobs = []
    per = -(-count // len(plants))
    for p in plants:
        for j in range(per):
            tr, sm, vel, cnt, nz, col = axes[order[(j + 7 * len(jobs)) % len(axes)]]
            s = seed * 100003 + len(jobs) + 1
            jobs.append({"plant": p, "truth": tr, "sampling": sm, "velocity": vel,
                         "counts": cnt, "noise": nz, "colour": col, "seed": s,
                         "key": f"{p}|{tr}|{sm}|{vel}|{cnt:g}|{nz:g}|{col}|{s}"})
    return jobs[:count] if len(plants) == 1 else _spread(jobs, count, len(plants))


def _spread(jobs, count, n_plants):
    # interleave the plants so any prefix of the list covers all of them
    per = len(jobs) // n_plants
    out = [jobs[p * per + j] for j in range(per) for p in range(n_plants)]
    return out[:count]


def _run_one(job, quick=False, cache_dir=None, give_level="coloured"):
    from .benchmark import plant_kinematics
    from .core import BaseFitError, diagnose
    kin = plant_kinematics(job["plant"], quick)
    kw = {k: job[k] for k in ("truth", "sampling", "velocity", "counts", "noise", "colour",
                              "seed")}
    data, level = clean_record(kin, cache_dir=cache_dir, **kw)
    given = level if (give_level == "all" or (give_level == "coloured"
                                               and job["colour"] == "coloured")) else None
    t0 = time.perf_counter()
    row = {"key": job["key"], **{k: job[k] for k in ("plant", *kw)},
           "samples": len(data), "noise_level_given": given}
    try:
        rep = diagnose(data, kin.base, noise_level=given, seed=0)
    except BaseFitError as exc:
        row.update(verdict="base_unfit", base_fit_nrmse=exc.fit_nrmse,
                   seconds=time.perf_counter() - t0)
        return row
    v = rep["verdict"]
    top = rep["effects"][0] if rep["effects"] else {}
    row.update(verdict=v["cause"], reason=v.get("reason", ""),
               validation=rep["baseline"]["validation"], noise_floor=rep["noise_floor"],
               top=top.get("name", ""), top_excess_closed=top.get("excess_closed"),
               top_gap_closed=top.get("gap_closed"), top_z=top.get("significance_z"),
               top_imprint=top.get("imprint"), top_size_reason=top.get("size_reason", ""),
               delay_samples=(rep["effect_details"].get("delay", {}).get("extras", {})
                              .get("delay", float("nan")) / data.dt),
               effects=decision_entries(rep["effects"]),
               seconds=time.perf_counter() - t0)
    return row


def _worker_init(cache, quick, cache_dir):
    from . import benchmark
    benchmark._KIN_CACHE.update(cache)
    os.environ["FRICTIONLAB_THREADS"] = "1"  # the pool's processes keep the cores busy


def _call(args):
    return _run_one(*args)


def run_clean(count: int = 500, plants=None, *, quick: bool = False, workers: int = 1,
              checkpoint=None, cache_dir=None, progress=None, seed: int = 0,
              give_level: str = "coloured") -> dict:
    """Diagnose ``count`` clean records (:func:`clean_grid`) and count the names given.

    Parameters
    ----------
    count : int
        Number of records.
    plants : sequence of str, optional
        Default: every plant of :data:`diagnosis.benchmark.PLANT_NAMES`.
    quick : bool
        The plants' short protocols.
    workers : int
        Processes.
    checkpoint : str, optional
        JSON-lines file of finished rows; a run given the same file skips them (resume).
    cache_dir : str, optional
        Where the reference truths are kept between runs.
    give_level : {"coloured", "all", "none"}
        Records whose noise RMS is passed to the diagnosis as ``noise_level`` (the user's
        standstill figure): the coloured ones by default.

    Returns
    -------
    dict
        ``rows``, ``records``, ``named`` (rows whose verdict is a name), ``verdicts``
        (count per verdict), ``per_plant``.
    """
    from .benchmark import PLANT_NAMES, plant_kinematics
    from .benchmark.runner import load_checkpoint
    plants = list(plants or PLANT_NAMES)
    say = status_lines(progress)
    jobs = clean_grid(plants, count, seed)
    done = load_checkpoint(checkpoint, {j["key"] for j in jobs})
    todo = [j for j in jobs if j["key"] not in done]
    if done:
        say(f"[clean] resuming: {len(jobs) - len(todo)} of {len(jobs)} records read from "
            f"{checkpoint}")
    for p in plants:
        kin = plant_kinematics(p, quick)
        for tr in ("fine", "reference"):
            if any(j["plant"] == p and j["truth"] == tr for j in todo):
                fine_truth(kin, tr, cache_dir)
    rows = [done[j["key"]] for j in jobs if j["key"] in done]

    def finish(row):
        rows.append(row)
        if checkpoint is not None:
            with open(checkpoint, "a") as fh:
                fh.write(json.dumps(row, default=float) + "\n")
        say(f"[clean {len(rows)}/{len(jobs)}] {row['key']}: {row['verdict']}"
            + (f" (top {row.get('top')}: excess {row.get('top_excess_closed') or 0:.2f}, "
               f"z {row.get('top_z') or 0:.1f}, imprint {row.get('top_imprint') or 0:.3g})"
               if row.get("top") else "") + f"; {row['seconds']:.1f} s")

    args = [(j, quick, cache_dir, give_level) for j in todo]
    if workers > 1 and len(todo) > 1:
        import multiprocessing as mp
        from concurrent.futures import ProcessPoolExecutor
        from . import benchmark
        with ProcessPoolExecutor(max_workers=workers, mp_context=mp.get_context("spawn"),
                                 initializer=_worker_init,
                                 initargs=(dict(benchmark._KIN_CACHE), quick, cache_dir)) as ex:
            for row in ex.map(_call, args):
                finish(row)
    else:
        for a in args:
            finish(_run_one(*a))
    return clean_summary(rows)


def clean_summary(rows) -> dict:
    """Counts of a clean run: records, names given (verdicts outside :data:`NO_NAME`),
    verdicts, and the same per plant."""
    def counts(rs):
        verdicts = {}
        for r in rs:
            verdicts[r["verdict"]] = verdicts.get(r["verdict"], 0) + 1
        return {"records": len(rs), "named": sum(r["verdict"] not in NO_NAME for r in rs),
                "verdicts": verdicts}
    out = counts(rows)
    out["rows"] = rows
    out["per_plant"] = {p: counts([r for r in rows if r["plant"] == p])
                        for p in sorted({r["plant"] for r in rows})}
    return out


# -- truths from another mechanism: levels varying inside the bristle dynamics ---------------
def level_truth_record(level, *, params=None, n: int = 12000, dt: float = 1e-3,
                       noise: float = 0.02, counts: float = 200.0, visc: float = 0.0,
                       seed: int = 0, name: str = "level-truth", static: bool = False):
    """A record whose friction level varies along the stroke or in time *inside* the bristle
    dynamics (not the candidates' output scaling), integrated :data:`FINE` x finer than
    sampled, with positions quantised and differentiated as a user would.

    Parameters
    ----------
    level : callable
        ``level(x, t, x_lo, x_hi, T) -> ndarray``: relative friction level [-] (1: the base)
        at positions ``x`` [m] and times ``t`` [s] of the fine grid; the record's stroke
        ``x_lo, x_hi`` [m] and duration ``T`` [s] are given for scaling.
    params : dict, optional
        LuGre parameters (default :data:`diagnosis.benchmark.BASE`, alpha 2).
    n, dt : int, float
        Samples and sample interval [s] of the record.
    noise : float
        White noise RMS as a fraction of std(F) [-].
    counts : float
        Encoder counts per sample at the top speed [-]; v = ``np.gradient`` of the counts.
    visc : float
        A quadratic viscous term ``visc v |v|`` [N s^2/m^2] (a symmetric map the base's
        linear viscous term cannot follow).
    seed : int
        Seed of the motion phases and the noise.
    static : bool
        A static map instead of the bristle dynamics: ``F = tanh(v / v_r) level g(v) +
        level sigma2 v + visc v |v|`` with a Lorentzian Stribeck curve and ``v_r`` a
        twentieth of ``vs`` (symmetric in v; no presliding).

    Returns
    -------
    (Dataset, ndarray)
        The record and its noise-free force [N].
    """
    from .benchmark import BASE, _motion
    p = dict(BASE, alpha=2.0, **(params or {}))
    rng = np.random.default_rng(seed)
    t, x, v, _ = _motion(n, dt, rng)
    t_f = t[0] + np.arange((n - 1) * FINE + 1) * (dt / FINE)
    vi = PchipInterpolator(t, v)
    v_f = vi(t_f)
    x_f = x[0] + vi.antiderivative()(t_f) - vi.antiderivative()(t[0])
    lev = np.asarray(level(x_f, t_f, float(x.min()), float(x.max()), float(t[-1] - t[0])),
                     float) * np.ones_like(t_f)
    if static:
        g = p["Fc"] + (p["Fs"] - p["Fc"]) / (1.0 + (v_f / p["vs"]) ** 2)
        F_f = (np.tanh(v_f / (0.05 * p["vs"])) * lev * g + p["sigma2"] * lev * v_f
               + visc * lev * v_f * np.abs(v_f))
    else:  # the benchmark's LuGre with levels varying inside the bristle dynamics
        def g(vv):
            return p["Fc"] + (p["Fs"] - p["Fc"]) * np.exp(-np.abs(vv / p["vs"]) ** p["alpha"])
        vm = 0.5 * (v_f[1:] + v_f[:-1])
        F_f = _lugre_run(t_f, v_f, lev * g(v_f), 0.5 * (lev[1:] + lev[:-1]) * g(vm),
                         p["sigma0"], p["sigma1"],
                         (p["sigma2"] * v_f + visc * v_f * np.abs(v_f)) * lev)
    F0 = F_f[::FINE]
    xs = x_f[::FINE]
    v99 = float(np.percentile(np.abs(v), 99))
    q = v99 * dt / counts
    xq = np.round((xs - xs[0]) / q) * q + xs[0]
    vq = np.gradient(xq, dt)
    aq = np.gradient(vq, dt)
    F = F0 + noise * float(np.std(F0)) * rng.standard_normal(n)
    return Dataset.from_arrays(t, F, x=xq, v=vq, a=aq, name=name, check_units=False), F0
