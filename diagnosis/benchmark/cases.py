"""Benchmark cases: datasets whose truth carries an effect the base law lacks.

* **generic** (:func:`make_case`): a multi-sine motion of a mass-like axis and one classic
  LuGre parameter set (:data:`BASE`);
* **per plant** (:func:`make_plant_case`): a plant's simulated contact motion
  (:mod:`.kinematics`), a truth force along it (:mod:`.truths`) calibrated to the requested
  strength, and white noise.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from friction.dataset import Dataset

from .kinematics import (_PLANT_RUNS, FINE, PLANT_NAMES, fine_kinematics, measure_motion,
                         noise_signal, plant_kinematics)
from ..effects import EFFECTS, resolve
from .truths import BASE, BENCH_CASES, BENCH_GENERIC, base_force, sampled_base_force

__all__ = ["BASE", "CASES", "PLANT_NAMES", "PLANT_CASES", "EFFECT_SIZE", "make_case",
           "expected", "BenchCase", "applicable", "make_plant_case"]

#: the cases: every effect whose record has truth forms (:mod:`diagnosis.effects`), in the
#: records' order, then the base law alone and an effect outside the library
CASES = tuple(n for n, e in EFFECTS.items() if e.truths) + tuple(BENCH_CASES)
PLANT_CASES = CASES
#: per-plant cases: effect RMS (truth - base) per unit strength, as a fraction of std(F_base)
EFFECT_SIZE = 0.15
#: what ``make_plant_case(measured=...)`` takes: encoder counts per sample at the top speed,
#: how the velocity is differentiated (:func:`.kinematics.measure_motion`), noise colour
MEASURED_KEYS = ("counts", "velocity", "colour")


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
              dt: float = 1e-3, seed: int = 0, return_truth: bool = False):
    """One generic benchmark dataset whose truth carries ``effect`` (relative ``strength``).

    Parameters
    ----------
    effect : str
        One of :data:`CASES`.
    strength : float
        Relative size of the effect [-].
    noise : float
        White measurement noise, as a fraction of std(F) [-].
    n : int
        Samples.
    dt : float
        Sample interval [s].
    seed : int
        Seed of the motion phases and the noise.
    return_truth : bool
        Also return the noise-free truth force [N].

    Returns
    -------
    Dataset, or (Dataset, ndarray) with ``return_truth``.
    """
    rng = np.random.default_rng(seed)
    t, x, v, a = _motion(n, dt, rng)
    F0, load = _generic_truth(effect)(strength, t, x, v, a)
    sd = float(np.std(F0))
    F = F0 + noise * sd * rng.standard_normal(n)
    data = Dataset.from_arrays(t, F, x=x, v=v, a=a, load=load, name=f"{effect}-s{strength}")
    return (data, F0) if return_truth else data


def _generic_truth(effect: str):
    """``truth(s, t, x, v, a) -> (F, load)`` of the generic case ``effect``."""
    if effect in BENCH_GENERIC:
        return BENCH_GENERIC[effect]
    fn = resolve(EFFECTS[effect].generic_truth) if effect in EFFECTS else None
    if fn is None:
        raise ValueError(f"unknown benchmark effect {effect!r}; choose from {CASES}")
    return fn


def _plant_truth(effect: str, form: str | None = None):
    """``truth(kin, s) -> F`` of the per-plant case ``effect`` (its record's truth form
    ``form``, sealed forms included; default: the first)."""
    if effect in BENCH_CASES:
        return BENCH_CASES[effect]
    if effect not in EFFECTS or not EFFECTS[effect].truths:
        raise ValueError(f"unknown benchmark effect {effect!r}; choose from {PLANT_CASES}")
    return EFFECTS[effect].truth(form)


def expected(effect: str) -> str:
    """Verdict the benchmark expects for a case of ``effect``."""
    return {"clean": "none", "outside": "unexplained"}.get(effect, effect)


@dataclass
class BenchCase:
    """One per-plant case: the dataset, its noise-free truth force and what is expected."""
    plant: str
    effect: str
    strength: float
    noise: float
    data: Dataset
    truth: np.ndarray
    base: object
    expected: str = ""
    effect_rms: float = 0.0  # RMS(truth - base) / std(base) [-]
    info: dict = field(default_factory=dict)


def applicable(plant: str, effect: str, quick: bool = False) -> bool:
    """Whether a per-plant case exists: the effect record's ``truth_applies`` on the plant's
    motion (the isolator's mre_lugre has no Stribeck curve; a ``position`` defect needs a
    record whose held-out part revisits the fit part's positions, not the press's one-way
    stroke, see :func:`_bump_centre`).

    Parameters
    ----------
    plant : str
        One of :data:`PLANT_NAMES`.
    effect : str
        One of :data:`PLANT_CASES`.
    quick : bool
        Short protocol of :func:`plant_kinematics`.

    Returns
    -------
    bool
    """
    if effect in BENCH_CASES or effect not in EFFECTS or EFFECTS[effect].truth_applies is None:
        return True
    # on the motion the truths are integrated along
    return EFFECTS[effect].applies(fine_kinematics(plant_kinematics(plant, quick)))


def _calibrate(truth, kin, Fb, target: float, tol: float = 0.05, most: int = 6):
    """Amplitude factor ``s`` of ``truth(kin, s)`` whose deviation from the base force ``Fb``
    has an RMS of ``target`` x std(Fb): secant steps on log(RMS) against log(s) (exact in
    one for effects linear in ``s``). Returns ``(s, truth force)``."""
    sdb = float(np.std(Fb)) or 1.0

    def size(a):
        F = truth(kin, a)
        return F, float(np.sqrt(np.mean((F - Fb) ** 2))) / sdb
    a, (F, r) = 1.0, size(1.0)
    prev = None
    best = (abs(np.log(r / target)) if r > 0 else np.inf, a, F)
    for _ in range(most):
        if not (r > 0 and np.isfinite(r)) or abs(r / target - 1.0) <= tol:
            break
        slope = 1.0
        if prev is not None and prev[1] > 0 and prev[1] != r and prev[0] != a:
            slope = float(np.log(r / prev[1]) / np.log(a / prev[0]))
            if slope < 0.3:
                # the size hardly follows the amplitude (a truth that differs from the base
                # in more than its effect, e.g. a presliding model's sliding regime): keep
                # the closest so far rather than drive the amplitude to nothing
                return best[1], best[2]
            slope = min(slope, 5.0)
        prev = (a, r)
        # at most a factor 4 per step: a stiff truth (a tiny presliding distance) integrates
        # ever more slowly
        a = a * float(np.clip((target / r) ** (1.0 / slope), 0.25, 4.0))
        F, r = size(a)
        if r > 0 and abs(np.log(r / target)) < best[0]:
            best = (abs(np.log(r / target)), a, F)
    return best[1], best[2]


def make_plant_case(plant: str, effect: str, strength: float = 1.0, noise: float = 0.02,
                    seed: int = 0, quick: bool = False, form: str | None = None,
                    measured: dict | None = None) -> BenchCase:
    """A per-plant case: the plant's kinematics, a truth force carrying ``effect``, noise.

    The truth is integrated along the plant's continuous motion on a grid
    :data:`.kinematics.FINE` x finer than the data and sampled at the data's instants, as
    is the base force its effect size is measured against.

    Parameters
    ----------
    plant : str
        One of :data:`PLANT_NAMES`.
    effect : str
        One of :data:`PLANT_CASES`.
    strength : float
        Relative size of the effect [-]: the truth's deviation from the base law has an
        RMS of ``strength x EFFECT_SIZE`` x std(F_base) (the ``delay`` lag is capped at
        ``MAX_DELAY_SAMPLES``, the ``load`` slope at 0.96 of proportionality).
    noise : float
        Measurement noise RMS, as a fraction of std(F) [-].
    seed : int
        Noise seed.
    quick : bool
        Use the short protocol of :func:`plant_kinematics`.
    form : str, optional
        The effect record's truth form (its ``truths`` or ``sealed``; default: the first).
    measured : dict, optional
        Motion channels as a user records them (:func:`.kinematics.measure_motion`):
        ``counts`` (encoder counts per sample at the top speed [-]) and ``velocity`` (how it
        is differentiated), and the noise's ``colour`` (``"white"``/``"coloured"``);
        default: the exact sampled motion and white noise.

    Returns
    -------
    BenchCase
        ``info["discretisation"]`` [N]: the base force integrated on the fine grid minus the
        same law at the sample rate; the benchmark's oracle (detectable, truth shrink) scores
        ``truth - discretisation``, the effect as the data-rate law would carry it.
    """
    if not (np.isfinite(strength) and strength > 0):
        raise ValueError(f"strength = {strength!r} is out of bounds: must be a finite number "
                         f"> 0 [-]")
    if not (np.isfinite(noise) and noise >= 0):
        raise ValueError(f"noise = {noise!r} is out of bounds: must be a finite number >= 0 "
                         f"[-]")
    unknown = set(measured or {}) - set(MEASURED_KEYS)
    if unknown:
        raise ValueError(f"measured: unknown key(s) {sorted(unknown)}; choose from "
                         f"{MEASURED_KEYS}")
    if plant in _PLANT_RUNS and effect in PLANT_CASES and not applicable(plant, effect, quick):
        raise ValueError(f"{effect!r} does not apply to {plant!r} "
                         f"({EFFECTS[effect].truth_applies} is false for its motion)")
    kin = plant_kinematics(plant, quick)
    truth = _plant_truth(effect, form)
    Fb = base_force(kin)
    sdb = float(np.std(Fb)) or 1.0
    amp = 0.0
    if effect == "clean":
        F0 = Fb
    else:
        amp, F0 = _calibrate(truth, kin, Fb, strength * EFFECT_SIZE)
    sd = float(np.std(F0)) or 1.0
    rng = np.random.default_rng(seed)
    m = dict(measured or {})
    e = noise_signal(F0.size, m.pop("colour", "white"), rng)
    F = F0 + noise * sd * e
    if m:
        x, v, a = measure_motion(kin, **m)
    else:  # the exact motion: the position the truths were integrated along
        x, v, a = fine_kinematics(kin).x[::FINE], kin.v, kin.a
    tag = "" if form is None else f"-{form}"
    tag += "".join(f"-{val}" for val in m.values())
    data = Dataset.from_arrays(kin.t, F, x=x, v=v, a=a, load=kin.load,
                               name=f"{plant}-{effect}{tag}-s{strength}-n{noise}",
                               check_units=False)
    return BenchCase(plant, effect, strength, noise, data, F0, kin.base, expected(effect),
                     float(np.sqrt(np.mean((F0 - Fb) ** 2)) / sdb),
                     {"amplitude": amp, "form": form, "measured": dict(measured or {}),
                      # the base force the truth's size is measured against [N]
                      "base_force": Fb,
                      # the base's discretisation at the data rate [N] (fine - sampled)
                      "discretisation": Fb - sampled_base_force(kin)})
