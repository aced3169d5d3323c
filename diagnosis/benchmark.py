"""Built-in attribution benchmark: data whose effect is withheld from the model.

Two families of cases, both asked of :func:`diagnosis.diagnose` with a base law that lacks the
effect:

* **generic** (:func:`make_case`, ``run_benchmark(plants=None)``, the historical benchmark): a
  multi-sine motion of a mass-like axis and one classic LuGre parameter set (:data:`BASE`).
* **per plant** (:func:`make_plant_case`, ``run_benchmark(plants="all")``): the kinematics of
  each machine of :data:`plants.PLANTS` under its seed protocol, the plant's own seed-law
  parameters as the base, the plant's sample rate and force level.

How the per-plant data are made
-------------------------------
Simulating each plant with every truth law inside would cost a plant run per case. Instead the
plant is simulated **once** with its own seed law (:func:`plant_kinematics`, cached): its
contact kinematics (time, x, v, a and the normal load) are kept, and the *truth* friction
force of a case is computed along that measured motion with the truth law (state-dependent
laws integrated with the friction package's ``simulate()``, or the benchmark's own
exponential LuGre update for the custom Stribeck curve), then white noise of ``noise`` x
std(F) is added. The dataset is what an inverse-dynamics friction measurement would give
(``t, x, v, a, F[, load]``); the plant's closed loop is not re-run with the effect inside.

Protocols (seed papers): valve - seed 000 sinusoids (5/10/20 Hz, 4-8 mm lift) at 20 kHz;
damping rig - seed 001 linear-motor sine/triangle/trapezoid strokes at 1 kHz; forging press -
seed 004 speeds (1.2 ... 0.002 mm/s, each slow step after a loaded 1.2 mm/s one,
:data:`PRESS_SCHEDULE`) with the workpiece at 100 Hz, load = deformation resistance; MRE
isolator - seed 002 4 Hz shear of 2/4/8 mm at 256 Hz; XML-350 - seed 003 coloured-noise
refinement run under the linear PID, decimated to 1 kHz. Plants without a
measured normal load (all but the press) get a slowly varying, non-monotonic normal-load
channel (seal preload / supply pressure) so the ``load`` candidate is always in play.

Base law per plant: classic LuGre with the seed law's levels (valve: the modified LuGre's
"+" values without its acceleration part; press: the no-load levels Fc0, Fs0, sigma20 of
``load_lugre``; XML-350: Table I without the 0.01 N offset b, which the base fit does not
identify), and for the MRE isolator its own ``mre_lugre`` (the elastic k0 x dominates the
force, a LuGre base could not fit even the clean case).

Truth forms differ from the candidates' formulas (:mod:`diagnosis.effects`):

==================  ==========================================================================
effect              truth
==================  ==========================================================================
acceleration        modified LuGre (seed 000) with a lagged F_d (``fd_form="lag"``);
                    isolator: a first-order-lagged a/sqrt(a^2+a_s^2) fading as 1/(1+(v/v_c)^2)
load                seed-004 levels affine in the load inside the bristle dynamics
                    (``load_lugre``; press: the seed's own Table 3 coefficients x strength)
asymmetry           direction twins Fc_neg, Fs_neg, sigma2_neg (isolator: hysteretic part
                    scaled on v < 0)
stribeck_shape      LuGre whose Stribeck curve has an extra exponential low-speed tail (neither
                    Gaussian-alpha nor Lorentzian); not applicable to the isolator
position            a local defect: friction raised by a Gaussian bump along the stroke,
                    centred where fit and held-out parts both pass (not on the press,
                    whose one-way stroke never revisits a position)
inertia             mass error times the *filtered* acceleration of the inverse dynamics
delay               force channel delayed (cubic-spline fractional shift, at most
                    :data:`MAX_DELAY_SAMPLES`) then through a half-sample first-order lag
drift               saturating warm-up of the friction level
clean               the base law itself (expected verdict ``none``)
outside             a sinusoidal electrical ripple at 0.0537 x the sample rate (expected
                    ``unexplained``)
==================  ==========================================================================

Scores (:func:`run_benchmark`): top-1 accuracy, clean cases with an attribution, out-of-library
cases given a name, **localisation** (:func:`localise`: does the report's ``where`` section put
the gap in the region family the effect belongs to) and **shrink error** (:func:`truth_shrink`:
the reported gap-closed fraction against ``1 - val_err(truth) / val_err(base fit)``).
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np
from numba import njit

from friction import make_model
from friction.dataset import Dataset
from friction.metrics import nrmse

from .core import BaseFitError, diagnose
from .regions import band_splits, regime_split

__all__ = ["make_case", "run_benchmark", "CASES", "BASE", "expected", "PLANT_NAMES",
           "PLANT_CASES", "EXPECTED_FAMILIES", "PlantKinematics", "BenchCase",
           "plant_kinematics", "make_plant_case", "applicable", "localise", "truth_shrink",
           "summarise", "format_summary", "run_benchmark_cli"]

BASE = dict(sigma0=2e4, sigma1=150.0, sigma2=8.0, Fc=2.0, Fs=2.8, vs=5e-3)
CASES = ("acceleration", "load", "asymmetry", "stribeck_shape", "position", "inertia",
         "delay", "drift", "clean", "outside")
#: plants of the per-plant benchmark (all registered machines)
PLANT_NAMES = ("valve", "damping_rig", "forging_press", "mre_isolator", "xml350")
PLANT_CASES = CASES
#: per-plant cases: effect RMS (truth - base) per unit strength, as a fraction of std(F_base)
EFFECT_SIZE = 0.15
#: longest force-channel delay of the ``delay`` truth [samples] (the candidate reaches 25)
MAX_DELAY_SAMPLES = 20.0
#: speed scale of the extra low-speed tail of the ``stribeck_shape`` truth, x v99 [-]
STRIBECK_TAIL = 0.05

#: region families where each effect should concentrate the held-out gap (see :func:`localise`)
EXPECTED_FAMILIES = {
    "acceleration": ("accel/decel", "|a|"),
    "inertia": ("|a|", "accel/decel"),
    "delay": ("|a|", "frequency", "accel/decel"),
    "asymmetry": ("direction",),
    "load": ("load",),
    "position": ("x",),
    "drift": ("t",),
    "presliding": ("pre-sliding",),
    "stribeck_shape": ("|v|", "pre-sliding"),
}


# -- generic benchmark (historical) -----------------------------------------------------------
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


def _generic_truth(effect, s, t, x, v, a):
    """Noise-free truth force and load of a generic case."""
    load = None
    base = make_model("lugre", **BASE)
    dt = t[1] - t[0]
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
    return F, load


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
    F0, load = _generic_truth(effect, strength, t, x, v, a)
    sd = float(np.std(F0))
    F = F0 + noise * sd * rng.standard_normal(n)
    data = Dataset.from_arrays(t, F, x=x, v=v, a=a, load=load, name=f"{effect}-s{strength}")
    return (data, F0) if return_truth else data


def expected(effect: str) -> str:
    """Verdict the benchmark expects for a case of ``effect``."""
    return {"clean": "none", "outside": "unexplained"}.get(effect, effect)


# -- per-plant kinematics ---------------------------------------------------------------------
@dataclass
class PlantKinematics:
    """A plant's simulated contact motion and the base law of its benchmark cases.

    Attributes
    ----------
    plant : str
    t, x, v, a : ndarray
        Time [s], position [m], velocity [m/s], acceleration [m/s^2] at the plant's data rate.
    load : ndarray
        Normal load [N] (press: the deformation resistance; others: a synthetic preload).
    base : FrictionModel
        The base law (seed-law parameters) the cases are diagnosed with.
    seed_law : FrictionModel
        The plant's own seed law (as simulated).
    protocol : str
        What was run.
    seconds : float
        Wall time of the plant simulation [s].
    """
    plant: str
    t: np.ndarray
    x: np.ndarray
    v: np.ndarray
    a: np.ndarray
    load: np.ndarray
    base: object
    seed_law: object
    protocol: str
    seconds: float = 0.0

    @property
    def dt(self) -> float:
        return float(self.t[1] - self.t[0])

    @property
    def scales(self) -> dict:
        return {"v99": float(np.percentile(np.abs(self.v), 99)),
                "a99": float(np.percentile(np.abs(self.a), 99)),
                "x_lo": float(np.min(self.x)), "x_hi": float(np.max(self.x))}


def _concat(parts, dt):
    """Concatenate segment results (each from rest) on one uniform time axis."""
    cols = {k: np.concatenate([p[k] for p in parts]) for k in ("x", "v", "a")}
    n = cols["x"].size
    return np.arange(n) * dt, cols


def _synthetic_load(t, L0):
    # a measured normal load (seal preload / supply pressure) that varies slowly and is not
    # monotonic in time, so load, drift and position stay distinguishable
    T = t[-1] - t[0] or 1.0
    u = (t - t[0]) / T
    return L0 * (1.0 + 0.25 * np.sin(2 * np.pi * 2.7 * u + 0.4) + 0.1 * np.sin(2 * np.pi * 7.3 * u))


def _valve(quick):
    from plants.valve import ValveActuator, SAMPLE_RATE
    plant = ValveActuator()
    segs = ([(10.0, 8e-3, 1), (20.0, 8e-3, 1), (10.0, 6e-3, 1)] if quick else
            [(10.0, 8e-3, 1), (20.0, 8e-3, 1), (5.0, 6e-3, 1), (20.0, 4e-3, 2), (10.0, 6e-3, 1),
             (20.0, 8e-3, 1), (10.0, 8e-3, 1)])
    parts = []
    for f, M, c in segs:
        r = plant.simulate(c / f, freq=f, magnitude=M)
        parts.append({k: np.asarray(r[k])[:-1] for k in ("x", "v", "a")})
    t, c = _concat(parts, 1.0 / SAMPLE_RATE)
    law = plant.friction
    p = law.params
    base = make_model("lugre", sigma0=p.sigma0, sigma1=p.sigma1, sigma2=p.sigma2, Fc=p.Fc,
                      Fs=p.Fs, vs=p.vs)
    proto = "seed 000 sinusoids " + ", ".join(f"{f:g} Hz/{M * 1e3:g} mm x{n}" for f, M, n in segs)
    return t, c, _synthetic_load(t, 200.0), base, law, proto


def _damping_rig(quick):
    from plants.damping_rig import DampingRig, LINEAR_RATE
    plant = DampingRig()
    segs = ([("sine", 4.0, 0.02, 2), ("triangle", 2.0, 0.01, 1), ("sine", 10.0, 0.005, 4)]
            if quick else
            [("sine", 4.0, 0.02, 4), ("triangle", 2.0, 0.01, 2), ("trapezoid", 1.0, 0.02, 1),
             ("sine", 10.0, 0.005, 6), ("sine", 4.0, 0.01, 3), ("triangle", 2.0, 0.02, 1),
             ("sine", 4.0, 0.02, 2)])
    parts = []
    for w, f, A, n in segs:
        r = plant.simulate(n / f, waveform=w, freq=f, amplitude=A)
        parts.append({k: np.asarray(r[k])[:-1] for k in ("x", "v", "a")})
    t, c = _concat(parts, 1.0 / LINEAR_RATE)
    law = plant.friction
    proto = "seed 001 linear motor " + ", ".join(f"{w} {f:g} Hz/{A * 1e3:g} mm x{n}"
                                                 for w, f, A, n in segs)
    return t, c, _synthetic_load(t, 500.0), law, law, proto


#: press speed steps [m/s, s]: seed 004's speeds, each slow step after a loaded fast one, so
#: the chronological hold-out still sees the workpiece loaded (in the default schedule the
#: last 30 % is the 0.002 mm/s crawl with the workpiece relaxed to zero load)
PRESS_SCHEDULE = ((1.2e-3, 8.0), (0.05e-3, 6.0), (1.2e-3, 6.0), (0.1e-3, 6.0), (1.2e-3, 6.0),
                  (0.002e-3, 8.0))


def _forging_press(quick):
    from plants.forging_press import ForgingPress
    plant = ForgingPress()
    r = plant.simulate(40.0, schedule=PRESS_SCHEDULE)
    t = np.asarray(r["time"])
    c = {k: np.asarray(r[k]) for k in ("x", "v", "a")}
    law = plant.friction
    p = law.params
    # the classic LuGre caps sigma0 at 1e9 N/m (the seed's assumed 2e10 is a pre-sliding
    # deflection of 19 um); truth and base use the same capped value
    s0 = min(p.sigma0, 1e9)
    base = make_model("lugre", sigma0=s0, sigma1=p.sigma1, sigma2=p.sigma20, Fc=p.Fc0,
                      Fs=p.Fs0, vs=p.vs)
    steps = ", ".join(f"{v * 1e3:g} mm/s {d:g} s" for v, d in PRESS_SCHEDULE)
    return (t, c, np.asarray(r["F_sigma"]), base, law.with_values(sigma0=s0),
            f"seed 004 speeds ({steps}), workpiece, 100 Hz")


def _mre_isolator(quick):
    from plants.mre_isolator import MREIsolator, SAMPLE_RATE
    plant = MREIsolator()
    amps = (8e-3, 4e-3, 2e-3) if quick else (8e-3, 4e-3, 2e-3, 8e-3, 4e-3)
    parts = []
    for A in amps:
        r = plant.simulate(2.5, amplitude=A)
        parts.append({k: np.asarray(r[k])[:-1] for k in ("x", "v", "a")})
    t, c = _concat(parts, 1.0 / SAMPLE_RATE)
    law = plant.friction
    proto = "seed 002 4 Hz shear " + ", ".join(f"{A * 1e3:g} mm" for A in amps) + " (2.5 s each)"
    return t, c, _synthetic_load(t, 5e3), law, law, proto


def _xml350(quick):
    from plants.experiments import identification_stage, refinement_reference
    duration = 4.0 if quick else 10.0
    ref = refinement_reference(rms=5e-3, seed=0, duration=duration)
    stage = identification_stage()
    r = stage.simulate(duration, controller="pid", compensation=False, trajectory=ref)
    k = 10  # 10 kHz -> 1 kHz, as the seed's processed data
    t = np.asarray(r["time"])[::k]
    c = {n: np.asarray(r[n])[::k] for n in ("x", "v", "a")}
    law = stage.friction
    base = law.with_values(b=0.0)
    return (t, c, _synthetic_load(t, 100.0), base, law,
            f"seed 003 refinement: 10 Hz coloured-noise velocity, 5 mm/s RMS, {duration:g} s, "
            f"linear PID, 1 kHz")


_PLANT_RUNS = {"valve": _valve, "damping_rig": _damping_rig, "forging_press": _forging_press,
               "mre_isolator": _mre_isolator, "xml350": _xml350}


_KIN_CACHE: dict = {}


def plant_kinematics(plant: str, quick: bool = False) -> PlantKinematics:
    """Simulate ``plant`` once under its seed protocol; cached per (plant, quick).

    ``quick`` runs a shorter protocol (fewer segments) for tests.
    """
    if plant not in _PLANT_RUNS:
        raise ValueError(f"unknown plant {plant!r}; choose from {PLANT_NAMES}")
    key = (plant, bool(quick))
    if key not in _KIN_CACHE:
        t0 = time.perf_counter()
        t, c, load, base, law, proto = _PLANT_RUNS[plant](quick)
        _KIN_CACHE[key] = PlantKinematics(plant, t, c["x"], c["v"], c["a"],
                                          np.asarray(load, float), base, law, proto,
                                          time.perf_counter() - t0)
    return _KIN_CACHE[key]


def _init_worker(cache):
    # worker processes start fresh (spawn: numba's OpenMP forbids fork) and get the plants'
    # kinematics from the parent instead of re-simulating them
    _KIN_CACHE.update(cache)


# -- truth laws along the measured motion ------------------------------------------------------
@njit(cache=True)
def _lugre_table_g(t, v, g, gm, s0, s1, s2):
    """LuGre with a tabulated Stribeck curve: g at the samples and at the step midpoints."""
    n = t.size
    F = np.empty(n)
    z = 0.0
    for k in range(n):
        zd = v[k] - s0 * abs(v[k]) * z / g[k]
        F[k] = s0 * z + s1 * zd + s2 * v[k]
        if k + 1 < n:
            h = t[k + 1] - t[k]
            vm = 0.5 * (v[k] + v[k + 1])
            zss = np.sign(vm) * gm[k] / s0
            r = h * s0 * abs(vm) / gm[k]
            z = zss + (z - zss) * np.exp(-r)
    return F


def _lag(t, u, tau):
    """Causal first-order lag tau dy/dt + y = u (exact for a piecewise-linear input)."""
    from scipy.signal import lfilter
    dt = float(t[1] - t[0])
    e = np.exp(-dt / tau)
    y = lfilter([1.0 - e], [1.0, -e], u, zi=[u[0] * e])[0]
    return y


#: share of the record :func:`diagnosis.diagnose` fits on by default (the rest is held out)
FIT_FRACTION = 0.7


def _bump_centre(kin: PlantKinematics, min_overlap: float = 0.2):
    """Centre [m] of the ``position`` defect: the median held-out position among those the
    fit part also visits, so the defect is seen in both parts; ``None`` if fewer than
    ``min_overlap`` of the held-out samples lie within the fit part's range (a one-way
    stroke, e.g. the press: nothing to learn the defect from)."""
    m = int(round(FIT_FRACTION * kin.x.size))
    xf, xh = kin.x[:m], kin.x[m:]
    inside = (xh >= xf.min()) & (xh <= xf.max())
    if inside.mean() < min_overlap:
        return None
    return float(np.median(xh[inside]))


def _base_parts(kin: PlantKinematics):
    """(F_base, F_friction_part): the force of the base law and the part effects act on."""
    law, t, v, x = kin.base, kin.t, kin.v, kin.x
    if law.name == "mre_lugre":
        p = law.params
        F = law.simulate(t, v, x=x)
        return F, F - p.k0 * x - p.f0  # the spring and offset carry no friction
    F = law.simulate(t, v)
    return F, F


def _level(kin: PlantKinematics) -> float:
    """Friction level of the base law [N] (Coulomb level or saturated hysteretic force)."""
    p = kin.base.params
    if kin.base.name == "mre_lugre":
        return float(p.beta / p.alpha)
    return float(p.Fc)


def _truth(kin: PlantKinematics, effect: str, s: float) -> np.ndarray:
    """Noise-free truth force [N] of ``effect`` with amplitude factor ``s`` along the motion
    (:func:`make_plant_case` calibrates ``s`` to the requested strength)."""
    t, x, v, a, L = kin.t, kin.x, kin.v, kin.a, kin.load
    law = kin.base
    mre = law.name == "mre_lugre"
    F, Ff = _base_parts(kin)
    Fk = _level(kin)
    sc = kin.scales
    dt = kin.dt
    if effect == "clean":
        return F
    if effect == "outside":
        fr = 0.0537 / dt  # electrical ripple, unrelated to the motion
        return F + 0.25 * s * Fk * np.sin(2 * np.pi * fr * t + 0.3)
    if effect == "acceleration":
        if not mre:
            p = law.params
            tru = make_model("modified_lugre", sigma0=p.sigma0, sigma1=p.sigma1, sigma2=p.sigma2,
                             Fc=p.Fc, Fs=p.Fs, vs=p.vs, alpha=p.alpha, shape=p.shape,
                             v1=1e3 * sc["v99"], v2=2e3 * sc["v99"],
                             f_a=0.5 * s * Fk, a_s=0.1 * sc["a99"], v_c=0.2 * sc["v99"],
                             beta=1.0, gamma=1.0, tau=3 * dt)
            return tru.simulate(t, v, a=a)
        a_s = 0.1 * sc["a99"]
        u = a / np.sqrt(a * a + a_s * a_s) / (1.0 + (v / (0.2 * sc["v99"])) ** 2)
        return F + 0.5 * s * Fk * _lag(t, u, 3 * dt)
    if effect == "load":
        if kin.plant == "forging_press":
            # the seed's own load law, its Table 3 coefficients scaled by the strength
            q = kin.seed_law.params
            tru = kin.seed_law.with_values(**{k: getattr(q, k) * s for k in
                                              ("k1_low", "k2_low", "k3_low", "k1_high",
                                               "k2_high", "k3_high")})
            return tru.simulate(t, v, load=L)
        if not mre:
            p = law.params
            L0 = float(np.mean(L))
            # levels change by 0.4 s x the relative load change (s <= 2.4: Fc0 stays > 0)
            k = 0.4 * min(s, 2.4) / L0
            tru = make_model("load_lugre", sigma0=p.sigma0, sigma1=p.sigma1,
                             Fc0=p.Fc * (1 - k * L0), Fs0=p.Fs * (1 - k * L0), vs=p.vs,
                             sigma20=p.sigma2 * (1 - k * L0),
                             k1_low=k * p.Fc, k2_low=k * p.Fs, k3_low=k * p.sigma2,
                             k1_high=k * p.Fc, k2_high=k * p.Fs, k3_high=k * p.sigma2)
            return tru.simulate(t, v, load=L)
        rel = (L - np.mean(L)) / np.mean(L)
        return F + Ff * 0.6 * s * rel
    if effect == "asymmetry":
        if not mre:
            p = law.params
            return law.with_values(Fc_neg=p.Fc * (1 + 0.4 * s), Fs_neg=p.Fs * (1 + 0.4 * s),
                                   sigma2_neg=p.sigma2 * (1 + 0.5 * s)).simulate(t, v)
        neg = 0.5 * (1 - np.tanh(v / (0.01 * sc["v99"])))
        return F + Ff * 0.4 * s * neg
    if effect == "stribeck_shape":
        if mre:
            raise ValueError("stribeck_shape: the mre_lugre base has no Stribeck curve")
        p = law.params
        tail = 0.4 * s * p.Fc
        vt = STRIBECK_TAIL * sc["v99"]

        def g(vv):
            return law.g(vv) + tail * np.exp(-np.abs(vv) / vt)
        vm = 0.5 * (v[1:] + v[:-1])
        gm = np.concatenate([g(vm), [1.0]])
        return _lugre_table_g(t, v, g(v), gm, p.sigma0, p.sigma1, p.sigma2)
    if effect == "position":
        span = sc["x_hi"] - sc["x_lo"] or 1.0
        xc = _bump_centre(kin)
        if xc is None:
            raise ValueError(f"position: the held-out part of the {kin.plant} record never "
                             f"revisits the positions of its fit part")
        bump = np.exp(-0.5 * ((x - xc) / (0.08 * span)) ** 2)
        return F + Ff * 0.6 * s * bump
    if effect == "inertia":
        from scipy.signal import butter, filtfilt
        fs = 1.0 / dt
        b, aa = butter(2, min(0.2 * fs, 100.0 * max(1.0, fs / 1000.0)) / (0.5 * fs))
        af = filtfilt(b, aa, a)
        dm = 0.3 * s * Fk / sc["a99"]
        return F + dm * af
    if effect == "delay":
        # an acquisition pipeline: transport delay of the force channel (cubic-spline
        # fractional shift) followed by a half-sample first-order anti-alias lag
        from scipy.interpolate import CubicSpline
        d = min(s, MAX_DELAY_SAMPLES) * dt
        Fd = CubicSpline(t, F)(np.clip(t - d, t[0], None))
        return _lag(t, Fd, 0.5 * dt)
    if effect == "drift":
        T = t[-1] - t[0]
        return F + Ff * 0.4 * s * (1.0 - np.exp(-(t - t[0]) / T))
    raise ValueError(f"unknown benchmark effect {effect!r}; choose from {PLANT_CASES}")


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
    """Whether a per-plant case exists: the isolator's mre_lugre has no Stribeck curve, and a
    ``position`` defect needs a record whose held-out part revisits the fit part's
    positions (not the press's one-way stroke, see :func:`_bump_centre`)."""
    if plant == "mre_isolator" and effect == "stribeck_shape":
        return False
    if effect == "position":
        return _bump_centre(plant_kinematics(plant, quick)) is not None
    return True


def make_plant_case(plant: str, effect: str, strength: float = 1.0, noise: float = 0.02,
                    seed: int = 0, quick: bool = False) -> BenchCase:
    """A per-plant case: the plant's kinematics, a truth force carrying ``effect``, noise.

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
        White measurement noise, as a fraction of std(F) [-].
    seed : int
        Noise seed.
    quick : bool
        Use the short protocol of :func:`plant_kinematics`.
    """
    if plant in _PLANT_RUNS and effect in PLANT_CASES and not applicable(plant, effect, quick):
        raise ValueError(f"{effect!r} does not apply to {plant!r} (no Stribeck curve in its "
                         f"base law, or no position revisited by its held-out part)")
    kin = plant_kinematics(plant, quick)
    Fb = _base_parts(kin)[0]
    sdb = float(np.std(Fb)) or 1.0
    amp = 0.0
    if effect == "clean":
        F0 = Fb
    else:
        # calibrate the amplitude factor so the effect's RMS is strength x EFFECT_SIZE of
        # std(F_base) on every plant (one rescaling: exact for effects linear in it)
        F1 = _truth(kin, effect, 1.0)
        r1 = float(np.sqrt(np.mean((F1 - Fb) ** 2))) / sdb
        amp = strength * EFFECT_SIZE / r1 if r1 > 0 else strength
        F0 = _truth(kin, effect, amp)
        r2 = float(np.sqrt(np.mean((F0 - Fb) ** 2))) / sdb
        if r2 > 0 and abs(r2 / (strength * EFFECT_SIZE) - 1.0) > 0.05:  # nonlinear in amp
            amp *= strength * EFFECT_SIZE / r2
            F0 = _truth(kin, effect, amp)
    sd = float(np.std(F0)) or 1.0
    rng = np.random.default_rng(seed)
    F = F0 + noise * sd * rng.standard_normal(F0.size)
    data = Dataset.from_arrays(kin.t, F, x=kin.x, v=kin.v, a=kin.a, load=kin.load,
                               name=f"{plant}-{effect}-s{strength}-n{noise}", check_units=False)
    return BenchCase(plant, effect, strength, noise, data, F0, kin.base, expected(effect),
                     float(np.sqrt(np.mean((F0 - Fb) ** 2)) / sdb), {"amplitude": amp})


# -- scoring -----------------------------------------------------------------------------------
def _regime_families(where):
    """Marginal regions of the disjoint regimes: direction, accel/decel, pre-sliding."""
    tot = sum(w["samples"] for w in where) or 1
    fam = {"direction": {}, "accel/decel": {}, "pre-sliding": {}}
    for w in where:
        pre, acc, d = [s.strip() for s in w["label"].split(",")]
        for f, lab in (("direction", d), ("accel/decel", acc), ("pre-sliding", pre)):
            e = fam[f].setdefault(lab, [0.0, 0])
            e[0] += w["share"]
            e[1] += w["samples"]
    out = []
    for f, regs in fam.items():
        for lab, (share, n) in regs.items():
            out.append({"family": f, "label": lab, "share": share, "fraction": n / tot})
    return out


_BAND_FAMILY = {"|v|": "|v|", "|a|": "|a|", "x": "x", "t": "t", "load": "load"}


#: evidence feature of the report -> region family it points at
_EVIDENCE_FAMILY = {"corr_sign_v": "direction", "corr_v": "direction", "corr_a": "|a|",
                    "corr_x": "x", "corr_t": "t", "corr_load": "load", "corr_dFdt": "dF/dt",
                    "corr_level_x": "x", "corr_level_t": "t", "corr_level_load": "load"}
#: families each effect should point at by the signed evidence correlations
EXPECTED_EVIDENCE = {"acceleration": ("|a|",), "inertia": ("|a|",), "delay": ("dF/dt", "|a|"),
                     "asymmetry": ("direction",), "load": ("load",), "position": ("x",),
                     "drift": ("t",)}


def localise(report, min_fraction: float = 0.05, method: str = "where") -> dict:
    """Where the report puts the gap.

    ``method="where"`` (the report's ``where`` sections): candidate regions are the
    marginals of the disjoint regimes (``where``: direction, accelerating/decelerating,
    pre-sliding/sliding) and the quantile bands (``where_bands``: |v|, |a|, x, t, load). A
    region's **lift** is its share of the residual energy over its share of the samples (its
    local mean-square error over the record's): 1 means no concentration. The top region is
    the one with the largest lift; regions holding fewer than ``min_fraction`` of the
    samples are ignored (a few samples at reversals would win by chance). Energy is blind
    to sign: a direction asymmetry that the base fit splits evenly between the directions
    shows no lift.

    ``method="evidence"``: the report's signed ``evidence`` correlations of the held-out
    residual with sign(v), v, a, x, t, load and dF/dt; the top family is that of the largest
    absolute correlation.

    Returns
    -------
    dict
        ``family`` and ``label`` of the top region, its ``lift`` (or |correlation|), and
        ``ranking`` (best value of each family, descending).
    """
    if method == "evidence":
        ev = report.get("evidence", {})
        best = {}
        for k, val in ev.items():
            fam = _EVIDENCE_FAMILY.get(k)
            if fam and (fam not in best or abs(val) > best[fam][1]):
                best[fam] = (k, abs(float(val)))
        ranking = sorted(best.items(), key=lambda kv: -kv[1][1])
        if not ranking:
            return {"family": "", "label": "", "lift": 0.0, "ranking": []}
        fam, (lab, val) = ranking[0]
        return {"family": fam, "label": lab, "lift": val,
                "ranking": [(f, k, round(v, 3)) for f, (k, v) in ranking]}
    if method != "where":
        raise ValueError(f"method must be 'where' or 'evidence', got {method!r}")
    regions = _regime_families(report["where"])
    for b in report.get("where_bands", []):
        regions.append({"family": _BAND_FAMILY.get(b.get("signal"), b.get("signal")),
                        "label": b["label"], "share": b["share"],
                        "fraction": b["fraction_of_samples"]})
    regions = [r for r in regions if r["fraction"] >= min_fraction]
    for r in regions:
        r["lift"] = r["share"] / r["fraction"]
    best = {}
    for r in regions:
        if r["family"] not in best or r["lift"] > best[r["family"]]["lift"]:
            best[r["family"]] = r
    ranking = sorted(best.values(), key=lambda r: -r["lift"])
    top = ranking[0] if ranking else {"family": "", "label": "", "lift": 0.0}
    return {"family": top["family"], "label": top["label"], "lift": top["lift"],
            "ranking": [(r["family"], r["label"], round(r["lift"], 3)) for r in ranking]}


def localise_gap(held: Dataset, gap: np.ndarray, min_fraction: float = 0.05) -> dict:
    """:func:`localise` (``where`` method) of a given held-out gap, e.g. the noise-free one
    ``truth - base fit``: the region a report of that gap would put on top."""
    pseudo = {"where": regime_split(held, gap), "where_bands": band_splits(held, gap)[:12]}
    return localise(pseudo, min_fraction=min_fraction)


def truth_shrink(data: Dataset, truth: np.ndarray, report, base_truth=None) -> dict:
    """The gap fraction the true model closes on the report's held-out part, vs the report.

    ``truth = 1 - val_err(truth law) / val_err(base fit)`` with both errors the pooled
    held-out NRMSE of :func:`diagnosis.diagnose` (chronological hold-out: the samples after
    ``timing.fit_samples``); ``reported`` is the verdict's ``gap_closed``.

    Returns
    -------
    dict with ``truth``, ``reported``, ``error`` (reported - truth) and ``val_truth``.
    """
    k = int(report["timing"]["fit_samples"])
    if k + int(report["timing"]["validation_samples"]) != len(data):
        raise ValueError("truth_shrink needs a report of a chronological hold-out of the same "
                         "data (validation=None)")
    val_truth = nrmse(data.F[k:], np.asarray(truth)[k:])
    before = float(report["baseline"]["validation"])
    tru = 1.0 - val_truth / before if before > 0 else 0.0
    rep = float(report["verdict"]["gap_closed"])
    return {"truth": tru, "reported": rep, "error": rep - tru, "val_truth": val_truth}


def _score(case_effect, exp, rep, data, truth, seconds) -> dict:
    from .verdict import NOISE_RATIO
    from .significance import improvement_z, z_threshold
    cause = rep["verdict"]["cause"]
    loc = localise(rep)
    loc_ev = localise(rep, method="evidence")
    fams = EXPECTED_FAMILIES.get(case_effect)
    fams_ev = EXPECTED_EVIDENCE.get(case_effect)
    sh = truth_shrink(data, truth, rep)
    # detectable: an oracle that knows the truth tells it from the base fit by either path of
    # the verdict: the base fit's held-out error exceeds the truth's by the noise ratio, or
    # the truth's held-out improvement over it is significant at the diagnosis' level
    k = int(rep["timing"]["fit_samples"])
    base_pred = rep._models["base"].predict(data)[k:] if hasattr(rep, "_models") else None
    z_truth = (improvement_z(data.F[k:] - base_pred, data.F[k:] - np.asarray(truth)[k:])
               if base_pred is not None else 0.0)
    detectable = bool(rep["baseline"]["validation"] > NOISE_RATIO * sh["val_truth"]
                      or z_truth >= z_threshold(max(len(rep["effects"]), 1)))
    # where the gap truly lies: the same sections on the noise-free gap (truth - base fit)
    loc_true = (localise_gap(data.select(slice(k, None)), np.asarray(truth)[k:] - base_pred)
                if base_pred is not None else {"family": "", "label": ""})
    return {"verdict": cause, "expected": exp, "correct": cause == exp,
            "gap_closed": rep["verdict"]["gap_closed"], "truth_shrink": sh["truth"],
            "shrink_error": sh["error"], "validation_before": rep["baseline"]["validation"],
            "validation_truth": sh["val_truth"], "noise_floor": rep["noise_floor"],
            "where_top": rep["where"][0]["label"] if rep["where"] else "",
            "loc_family": loc["family"], "loc_label": loc["label"], "loc_lift": loc["lift"],
            "loc_correct": (loc["family"] in fams) if fams else None,
            "loc_evidence_family": loc_ev["family"],
            "loc_evidence_correct": (loc_ev["family"] in fams_ev) if fams_ev else None,
            "loc_true_family": loc_true["family"], "loc_true_label": loc_true["label"],
            "loc_matches_truth": (loc["label"] == loc_true["label"]
                                  if case_effect not in ("clean", "outside") else None),
            "detectable": detectable if case_effect not in ("clean", "outside") else None,
            "truth_z": z_truth,
            "runner_up": rep["verdict"].get("runner_up", ""),
            "ranking": [e["name"] for e in rep["effects"][:3]], "seconds": seconds}


_BASE_SECONDS: dict = {}


def _run_one(job):
    plant, eff, s, nz, seed, quick, dseed = job
    key = (plant, quick)
    if key not in _BASE_SECONDS:
        # the time baseline, measured where and while the cases run (same load, same process)
        _BASE_SECONDS[key] = _base_identification_seconds(plant, quick, dseed)
    if plant is None:
        data, truth = make_case(eff, s, nz, seed=seed, return_truth=True)
        model, erms = "lugre", None
    else:
        case = make_plant_case(plant, eff, s, nz, seed=seed, quick=quick)
        data, truth, model, erms = case.data, case.truth, case.base, case.effect_rms
    t0 = time.perf_counter()
    row = {"plant": plant or "generic", "effect": eff, "strength": s, "noise": nz,
           "samples": len(data), "effect_rms": erms, "base_id_seconds": _BASE_SECONDS[key],
           "_job": job}
    try:
        rep = diagnose(data, model, seed=dseed)
    except BaseFitError as exc:
        # the diagnosis stopped on a base that fits worse than a constant: a miss of the
        # case (never a name), scored as such instead of ending the benchmark
        row.update(_base_failed_row(eff, exc, time.perf_counter() - t0))
        return row
    dt = time.perf_counter() - t0
    row.update(_score(eff, expected(eff), rep, data, truth, dt))
    return row


def _base_failed_row(case_effect, exc, seconds) -> dict:
    """Score row of a case whose diagnosis stopped with :class:`diagnosis.core.BaseFitError`."""
    exp = expected(case_effect)
    nan = float("nan")
    return {"verdict": "base_unfit", "expected": exp, "correct": False, "gap_closed": 0.0,
            "truth_shrink": nan, "shrink_error": nan, "validation_before": nan,
            "validation_truth": nan, "noise_floor": nan, "where_top": "", "loc_family": "",
            "loc_label": "", "loc_lift": 0.0, "loc_correct": None, "loc_evidence_family": "",
            "loc_evidence_correct": None, "loc_true_family": "", "loc_true_label": "",
            "loc_matches_truth": None,
            "detectable": True if case_effect not in ("clean", "outside") else None,
            "truth_z": nan, "runner_up": "", "ranking": [], "seconds": seconds,
            "base_fit_nrmse": exc.fit_nrmse}


def _base_identification_seconds(plant, quick, seed):
    """Wall time of one base identification on the plant's clean case (the time baseline)."""
    from identification import identify
    from .core import _base_law
    if plant is None:
        data = make_case("clean", 1.0, 0.02, seed=seed)
        model = "lugre"
    else:
        case = make_plant_case(plant, "clean", 1.0, 0.02, seed=seed, quick=quick)
        data, model = case.data, case.base
    fit, _ = data.split(0.7)
    law, names = _base_law(model, fit)
    t0 = time.perf_counter()
    identify(fit, law, names=names, seed=seed)
    return time.perf_counter() - t0


def _job_key(job) -> str:
    plant, eff, s, nz, seed, quick, dseed = job
    return f"{plant}|{eff}|{s!r}|{nz!r}|{seed}|{int(bool(quick))}|{dseed}"


def _load_checkpoint(path, keys) -> dict:
    """Rows already scored in the checkpoint file ``path`` (one JSON object per line, with
    its job ``key``), for the jobs in ``keys``; a truncated last line (a run killed while
    writing) is ignored."""
    import json
    import os
    done = {}
    if path is None or not os.path.exists(path):
        return done
    with open(path) as fh:
        for line in fh:
            try:
                row = json.loads(line)
            except json.JSONDecodeError:
                continue
            if isinstance(row, dict) and row.get("key") in keys:
                done[row["key"]] = row
    return done


def run_benchmark(effects=CASES, strengths=(0.5, 1.0), noises=(0.01, 0.03), seed=0,
                  progress=None, plants=None, quick: bool = False, workers: int = 1,
                  clean_repeats: int = 1, checkpoint=None) -> dict:
    """Run every case and score it.

    Parameters
    ----------
    effects : sequence of str
        Effects to withhold (``clean`` and ``outside`` included by default).
    strengths, noises : sequence of float
        Effect strengths [-] and noise levels (fraction of std(F)) [-].
    seed : int
        Base seed (noise seeds are ``seed + case number``; the diagnosis uses ``seed``).
    progress : callable, optional
        Called with one line per case.
    plants : None, "all" or sequence of str
        ``None``: the generic mass-like benchmark (historical); ``"all"``: every plant of
        :data:`PLANT_NAMES`; or a list of plant names.
    quick : bool
        Short plant protocols (tests).
    workers : int
        Processes running cases in parallel (1: in this process).
    clean_repeats : int
        Clean cases per (noise, strength) with different noise seeds.
    checkpoint : str or path, optional
        File the scored rows are appended to as they finish (JSON lines); a run started
        again with the same file and grid skips the cases already in it (resume after an
        interruption).

    Returns
    -------
    dict
        ``rows`` (one per case), ``top1_accuracy``, ``clean_false_attributions``,
        ``outside_named_wrongly``, and (see :func:`summarise`) ``overall``, ``per_plant``
        and ``per_effect`` figures: localisation accuracy, shrink error, seconds per case
        and, as the time baseline, one base identification of the plant's clean case timed
        in the same process as its cases (``time_ratio`` = seconds per case / baseline).
    """
    if plants == "all":
        plants = PLANT_NAMES
    plist = [None] if plants is None else list(plants)
    for plant in plist:  # simulate each plant once here; workers get the kinematics
        if plant is not None:
            plant_kinematics(plant, quick)
    jobs = []
    for plant in plist:
        for eff in effects:
            if plant is not None and not applicable(plant, eff, quick):
                continue
            reps = clean_repeats if eff == "clean" else 1
            for s in strengths:
                for nz in noises:
                    for r in range(reps):
                        jobs.append((plant, eff, s, nz, seed + len(jobs) + 1, quick, seed))
    say = progress or (lambda msg: None)
    rows = []
    keys = [_job_key(j) for j in jobs]
    resumed = _load_checkpoint(checkpoint, set(keys))
    if resumed:
        say(f"[benchmark] resuming: {len(resumed)} of {len(jobs)} cases read from {checkpoint}")
        rows.extend(resumed[k] for k in keys if k in resumed)
    todo = [j for j, k in zip(jobs, keys) if k not in resumed]
    if checkpoint is not None and resumed:
        with open(checkpoint, "rb+") as fh:  # a line cut by the interruption: end it
            fh.seek(0, 2)
            if fh.tell() > 0:
                fh.seek(-1, 2)
                if fh.read(1) != b"\n":
                    fh.write(b"\n")

    def done(row, k):
        rows.append(row)
        if checkpoint is not None:
            import json
            row["key"] = _job_key(row.pop("_job"))
            with open(checkpoint, "a") as fh:
                fh.write(json.dumps(row, default=float) + "\n")
        else:
            row.pop("_job", None)
        k += len(resumed)
        lc = row["loc_correct"]
        lc = "-" if lc is None else "ok" if lc else "miss"
        say(f"[benchmark {k}/{len(jobs)}] {row['plant']} {row['effect']} s={row['strength']} "
            f"noise={row['noise']}: {row['verdict']} "
            f"({'ok' if row['correct'] else 'WRONG, expected ' + row['expected']}); where "
            f"{row['loc_family']} ({lc}); "
            f"shrink {row['gap_closed']:.2f} vs truth {row['truth_shrink']:.2f}; "
            f"{row['seconds']:.1f} s")

    if workers > 1 and len(todo) > 1:
        import multiprocessing as mp
        from concurrent.futures import ProcessPoolExecutor
        with ProcessPoolExecutor(max_workers=workers, mp_context=mp.get_context("spawn"),
                                 initializer=_init_worker, initargs=(dict(_KIN_CACHE),)) as ex:
            for k, row in enumerate(ex.map(_run_one, todo), 1):
                done(row, k)
    else:
        for k, job in enumerate(todo, 1):
            done(_run_one(job), k)
    if checkpoint is not None:  # the grid's order, resumed or not
        order = {k: i for i, k in enumerate(keys)}
        rows.sort(key=lambda r: order[r["key"]])
    return summarise(rows)


def summarise(rows) -> dict:
    """Overall and per-plant figures of benchmark rows (see :func:`run_benchmark`)."""
    def figures(rs):
        if not rs:
            return {}
        lib = [r for r in rs if r["effect"] not in ("clean", "outside")]
        loc = [r for r in lib if r["loc_correct"] is not None]
        loc_ev = [r for r in lib if r["loc_evidence_correct"] is not None]
        loc_tr = [r for r in lib if r.get("loc_matches_truth") is not None]
        det = [r for r in rs if r["detectable"] is not False]
        # a case whose base did not fit (BaseFitError) has no shrink to compare
        sh = np.array([r["shrink_error"] for r in lib if np.isfinite(r["shrink_error"])])
        shc = np.array([r["shrink_error"] for r in lib if r["correct"]])
        out = {"cases": len(rs),
               "top1_accuracy": float(np.mean([r["correct"] for r in rs])),
               "clean_cases": sum(r["effect"] == "clean" for r in rs),
               "clean_false_attributions": sum(1 for r in rs if r["effect"] == "clean"
                                               and r["verdict"] != "none"),
               "outside_cases": sum(r["effect"] == "outside" for r in rs),
               "outside_named_wrongly": sum(1 for r in rs if r["effect"] == "outside"
                                            and r["verdict"] != "unexplained"),
               "library_accuracy": float(np.mean([r["correct"] for r in lib])) if lib else None,
               "top1_accuracy_detectable": float(np.mean([r["correct"] for r in det])),
               "undetectable_cases": len(rs) - len(det),
               "localisation_accuracy": (float(np.mean([r["loc_correct"] for r in loc]))
                                         if loc else None),
               "localisation_evidence_accuracy": (
                   float(np.mean([r["loc_evidence_correct"] for r in loc_ev])) if loc_ev
                   else None),
               "localisation_truth_accuracy": (
                   float(np.mean([r["loc_matches_truth"] for r in loc_tr])) if loc_tr else None),
               "shrink_abs_error_mean": float(np.mean(np.abs(sh))) if sh.size else None,
               "shrink_abs_error_max": float(np.max(np.abs(sh))) if sh.size else None,
               "shrink_abs_error_mean_correct": (float(np.mean(np.abs(shc))) if shc.size
                                                 else None),
               "seconds_per_case": float(np.mean([r["seconds"] for r in rs])),
               "base_identification_seconds": float(np.mean([r["base_id_seconds"]
                                                             for r in rs]))}
        out["time_ratio"] = out["seconds_per_case"] / out["base_identification_seconds"]
        return out

    plants = sorted({r["plant"] for r in rows}, key=lambda p: (p != "generic", p))
    per_plant = {p: figures([r for r in rows if r["plant"] == p]) for p in plants}
    per_effect = {}
    for r in rows:
        e = per_effect.setdefault(r["effect"], {"cases": 0, "correct": 0, "loc_correct": 0,
                                                "loc_evidence_correct": 0, "loc_truth": 0,
                                                "undetectable": 0, "named": {}})
        e["cases"] += 1
        e["correct"] += bool(r["correct"])
        e["loc_correct"] += bool(r["loc_correct"])
        e["loc_evidence_correct"] += bool(r["loc_evidence_correct"])
        e["loc_truth"] += bool(r.get("loc_matches_truth"))
        e["undetectable"] += r["detectable"] is False
        if not r["correct"]:
            e["named"][r["verdict"]] = e["named"].get(r["verdict"], 0) + 1
    overall = figures(rows)
    return {"rows": rows, "top1_accuracy": overall["top1_accuracy"],
            "clean_false_attributions": overall["clean_false_attributions"],
            "outside_named_wrongly": overall["outside_named_wrongly"],
            "overall": overall, "per_plant": per_plant, "per_effect": per_effect}


# -- text output -------------------------------------------------------------------------------
def _pct(x):
    # percentage, or a dash where a figure does not apply
    return "   -" if x is None else f"{100 * x:5.1f}"


def _num(x, fmt=".3f"):
    return "-" if x is None else format(x, fmt)


def format_summary(res, title: str = "withheld-effect benchmark") -> str:
    """The benchmark figures as a text table: per plant, overall, per effect, misses."""
    out = []
    out.append(f"\n== {title} ==")
    out.append(f"{'plant':14s} {'cases':>5s} {'top-1 %':>7s} {'detect.%':>8s} {'clean':>6s} "
               f"{'outside':>7s} {'loc %':>6s} {'evid %':>6s} {'true %':>6s} "
               f"{'shrink |err| mean/max':>22s} "
               f"{'s/case':>7s} {'x base id':>9s}")
    rows = list(res["per_plant"].items()) + [("OVERALL", res["overall"])]
    for name, f in rows:
        out.append(f"{name:14s} {f['cases']:5d} {_pct(f['top1_accuracy']):>7s} "
                   f"{_pct(f['top1_accuracy_detectable']):>8s} "
                   f"{f['clean_false_attributions']:>3d}/{f['clean_cases']:<2d} "
                   f"{f['outside_named_wrongly']:>4d}/{f['outside_cases']:<2d} "
                   f"{_pct(f['localisation_accuracy']):>6s} "
                   f"{_pct(f['localisation_evidence_accuracy']):>6s} "
                   f"{_pct(f.get('localisation_truth_accuracy')):>6s} "
                   f"{_num(f['shrink_abs_error_mean']):>11s}/"
                   f"{_num(f['shrink_abs_error_max']):<10s} "
                   f"{f['seconds_per_case']:7.2f} "
                   f"{_num(f['time_ratio'], '.1f'):>9s}")
    out.append("  clean: cases with an attribution / clean cases; outside: named / out-of-library "
               "cases; x base id: seconds per case / one base identification of that plant's clean "
               "case, timed in the same worker; loc/evid: top region in the effect's family "
               "(EXPECTED_FAMILIES / EXPECTED_EVIDENCE); true: the report's top region is the "
               "noise-free gap's (truth - base fit)")
    out.append(f"\n{'effect':15s} {'top-1':>9s} {'where':>9s} {'evidence':>9s} {'true':>9s} "
               f"{'undetect.':>9s}  named instead")
    for eff, e in res["per_effect"].items():
        na = eff in ("clean", "outside")
        loc = "-" if na else f"{e['loc_correct']}/{e['cases']}"
        lev = "-" if na else f"{e['loc_evidence_correct']}/{e['cases']}"
        ltr = "-" if na else f"{e.get('loc_truth', 0)}/{e['cases']}"
        named = ", ".join(f"{k} x{v}" for k, v in sorted(e["named"].items(), key=lambda kv: -kv[1]))
        out.append(f"{eff:15s} {e['correct']:4d}/{e['cases']:<4d} {loc:>9s} {lev:>9s} {ltr:>9s} "
                   f"{e['undetectable']:9d}  {named}")
    plants = list(res["per_plant"])
    if len(plants) > 1:  # correct / cases of each effect on each plant
        out.append("\n" + f"{'top-1 by plant':15s} " + " ".join(f"{p[:13]:>13s}" for p in plants))
        for eff in res["per_effect"]:
            cells = []
            for p in plants:
                rs = [r for r in res["rows"] if r["plant"] == p and r["effect"] == eff]
                cells.append(f"{sum(r['correct'] for r in rs)}/{len(rs)}" if rs else "n/a")
            out.append(f"{eff:15s} " + " ".join(f"{c:>13s}" for c in cells))
    wrong = [r for r in res["rows"] if not r["correct"]]
    if wrong:
        out.append("\nmisses (plant, effect, strength, noise -> verdict; truth shrink; "
                   "candidate ranking):")
        for r in wrong:
            und = "(undetectable)" if r["detectable"] is False else ""
            out.append(f"  {r['plant']:13s} {r['effect']:14s} s={r['strength']:<4g} "
                       f"noise={r['noise']:<5g} -> {r['verdict']:13s} truth shrink "
                       f"{r['truth_shrink']:5.2f} {und}"
                       f" ranking {r['ranking']}")
    return "\n".join(out)


def run_benchmark_cli(args) -> int:
    """``frictionlab diagnose --benchmark --plants LIST|all``: the per-plant benchmark at one
    strength (1) and noise level (0.02 x std(F)); ``benchmarks/bench_diagnosis.py`` runs the
    full grid."""
    from frictionlab.progress import report as say
    plants = None if args.plants in (None, "", "generic") else (
        "all" if args.plants == "all" else args.plants.split(","))
    quiet = getattr(args, "quiet", False)
    res = run_benchmark(plants=plants, seed=getattr(args, "seed", 0), strengths=(1.0,),
                        noises=(0.02,), progress=None if quiet else say)
    print(format_summary(res))
    if getattr(args, "json_out", None):
        import json
        with open(args.json_out, "w") as fh:
            json.dump({k: res[k] for k in ("overall", "per_plant", "per_effect", "rows")}, fh,
                      indent=1, default=float)
    return 0
