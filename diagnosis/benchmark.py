"""Built-in attribution benchmark: data whose effect is withheld from the model.

Each case simulates a *truth* that carries one effect in a form that differs from the
candidate's own formula (a modified-LuGre lag for ``acceleration``, a seed-004 load law for
``load``, direction twins for ``asymmetry``, a saturating warm-up for ``drift``, a cosine
ripple along the stroke for ``position``, ...), adds measurement noise, and asks
:func:`diagnosis.diagnose` with the plain base law. Clean cases must give ``none``; an effect
outside the library (an electrical ripple in time) must give ``unexplained``.
"""
from __future__ import annotations

import time

import numpy as np

from friction import make_model
from friction.dataset import Dataset

from .core import diagnose

__all__ = ["make_case", "run_benchmark", "CASES"]

BASE = dict(sigma0=2e4, sigma1=150.0, sigma2=8.0, Fc=2.0, Fs=2.8, vs=5e-3)
CASES = ("acceleration", "load", "asymmetry", "stribeck_shape", "position", "inertia",
         "delay", "drift", "clean", "outside")


def _motion(n, dt, rng):
    t = np.arange(n) * dt
    v = np.zeros(n)
    # a multi-sine velocity with slowly varying amplitude: both directions, reversals, plateaus
    for f, amp in ((0.7, 0.05), (1.9, 0.03), (4.3, 0.012)):
        v += amp * np.sin(2 * np.pi * f * t + rng.uniform(0, 2 * np.pi))
    v *= 0.6 + 0.4 * np.sin(2 * np.pi * 0.13 * t) ** 2
    x = np.concatenate(([0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * dt)))
    a = np.gradient(v, t)
    return t, x, v, a


def make_case(effect: str, strength: float = 1.0, noise: float = 0.02, n: int = 12000,
              dt: float = 1e-3, seed: int = 0) -> Dataset:
    """One benchmark dataset whose truth carries ``effect`` (relative ``strength``)."""
    rng = np.random.default_rng(seed)
    t, x, v, a = _motion(n, dt, rng)
    load = None
    base = make_model("lugre", **BASE)
    s = strength
    if effect == "acceleration":
        truth = make_model("modified_lugre", sigma0=BASE["sigma0"], sigma1=BASE["sigma1"],
                           sigma2=BASE["sigma2"], Fc=BASE["Fc"], Fs=BASE["Fs"], vs=BASE["vs"])
        truth = truth.with_values(f_a=1.5 * s, a_s=0.3, v_c=0.04, tau=0.01)
        F = truth.simulate(t, v, a=a)
    elif effect == "load":
        load = 100.0 + 60.0 * np.sin(2 * np.pi * 0.05 * t) ** 2 + 20 * (t / t[-1])
        levels = 1.0 + 0.6 * s * (load - 100.0) / 100.0  # seed-004 style: levels linear in load
        F = base.simulate(t, v) * levels
    elif effect == "asymmetry":
        F = base.with_values(Fc_neg=BASE["Fc"] * (1 + 0.5 * s), Fs_neg=BASE["Fs"] * (1 + 0.5 * s),
                             sigma2_neg=BASE["sigma2"] * (1 + 0.6 * s)).simulate(t, v)
    elif effect == "stribeck_shape":
        # a long Lorentzian tail: the Gaussian base cannot bend like it
        F = base.with_values(shape="lorentzian", Fc=BASE["Fc"] * 0.6,
                             Fs=BASE["Fs"] * (1 + 1.5 * s), vs=BASE["vs"] * 3).simulate(t, v)
    elif effect == "position":
        span = np.ptp(x)
        F = base.simulate(t, v) + 0.8 * s * np.cos(np.pi * (x - x.min()) / span) * np.tanh(v / 2e-3)
    elif effect == "inertia":
        F = base.simulate(t, v) + 1.2 * s * a  # 1.2 kg mass error in the inverse dynamics
    elif effect == "delay":
        F0 = base.simulate(t, v)
        F = np.interp(t - 4.5 * s * dt, t, F0)
    elif effect == "drift":
        warm = 1.0 + 0.5 * s * (1.0 - np.exp(-t / (0.6 * t[-1])))  # saturating warm-up
        F = base.simulate(t, v) * warm
    elif effect == "clean":
        F = base.simulate(t, v)
    elif effect == "outside":
        # an electrical ripple at 13 Hz, unrelated to motion: no candidate can express it
        F = base.simulate(t, v) + 0.6 * s * np.sin(2 * np.pi * 13.0 * t)
    else:
        raise ValueError(f"unknown benchmark effect {effect!r}; choose from {CASES}")
    sd = float(np.std(F))
    F = F + noise * sd * rng.standard_normal(n)
    return Dataset.from_arrays(t, F, x=x, v=v, a=a, load=load, name=f"{effect}-s{strength}")


def expected(effect: str) -> str:
    return {"clean": "none", "outside": "unexplained"}.get(effect, effect)


def run_benchmark(effects=CASES, strengths=(0.5, 1.0), noises=(0.01, 0.03), seed=0,
                  progress=None) -> dict:
    """Run every case; returns rows and the top-1 accuracy."""
    rows = []
    k = 0
    total = len(effects) * len(strengths) * len(noises)
    for eff in effects:
        for s in strengths:
            for nz in noises:
                k += 1
                data = make_case(eff, s, nz, seed=seed + k)
                t0 = time.perf_counter()
                rep = diagnose(data, "lugre", seed=seed)
                dt = time.perf_counter() - t0
                cause = rep["verdict"]["cause"]
                exp = expected(eff)
                top_where = rep["where"][0]["label"] if rep["where"] else ""
                rows.append({"effect": eff, "strength": s, "noise": nz, "verdict": cause,
                             "expected": exp, "correct": cause == exp,
                             "gap_closed": rep["verdict"]["gap_closed"],
                             "validation_before": rep["baseline"]["validation"],
                             "noise_floor": rep["noise_floor"], "where_top": top_where,
                             "seconds": dt})
                if progress:
                    progress(f"[benchmark {k}/{total}] {eff} s={s} noise={nz}: {cause} "
                             f"({'ok' if cause == exp else 'WRONG, expected ' + exp}) {dt:.1f} s")
    acc = float(np.mean([r["correct"] for r in rows]))
    return {"rows": rows, "top1_accuracy": acc,
            "clean_false_attributions": sum(1 for r in rows if r["effect"] == "clean"
                                            and r["verdict"] != "none"),
            "outside_named_wrongly": sum(1 for r in rows if r["effect"] == "outside"
                                         and r["verdict"] not in ("unexplained",))}
