"""Synthetic identification cases: each seed's law with the seed's parameter table, the kind
of excitation the seed used, and optional measurement noise.

Used by the benchmark (``benchmarks/bench_identification.py``), the tests and the demo. Each
case gives the true model, the dataset, the identified names, a start model (every value
off by a factor 1.5 or 0.6) and a search box around the truth (x/÷ 10 for log-scaled
parameters, [0, 3 x] for linear positive ones).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from friction import make_model
from friction.base import FrictionModel
from friction.dataset import Dataset

__all__ = ["SyntheticCase", "make_case", "CASES", "coloured_noise"]


@dataclass
class SyntheticCase:
    name: str
    seed_paper: str
    true: FrictionModel
    data: Dataset
    names: list
    start: FrictionModel
    bounds: dict

    def param_error(self, params: dict) -> float:
        """Largest relative error of identified parameters against the truth."""
        errs = []
        for n in self.names:
            t = getattr(self.true.params, n)
            errs.append(abs(params[n] - t) / max(abs(t), 1e-12))
        return float(max(errs))


def coloured_noise(t, cutoff: float, rms: float, seed: int = 0) -> np.ndarray:
    """Low-pass filtered Gaussian noise (8th-order Chebyshev I, zero phase; seed 003)."""
    from scipy import signal
    fs = 1.0 / float(np.median(np.diff(t)))
    b, a = signal.cheby1(8, 0.5, cutoff / (fs / 2))
    w = np.random.default_rng(seed).standard_normal(t.size + 2000)
    y = signal.filtfilt(b, a, w)[1000:-1000]
    return y * rms / np.std(y)


def _box(model, names, truth):
    infos = {i.name: i for i in model.Params.info()}
    out = {}
    for n in names:
        v = truth[n]
        info = infos[n]
        if info.log and v > 0:
            lo, hi = v / 10, v * 10
        elif v > 0:
            lo, hi = 0.0 if info.lower <= 0 else v / 10, 3 * v
        else:
            lo, hi = -3 * abs(v) - 1.0, 3 * abs(v) + 1.0
        lo = max(lo, info.lower if not info.lower_open else max(lo, info.lower + 1e-12 * max(1, abs(v))))
        hi = min(hi, info.upper)
        out[n] = (lo, hi)
    return out


def _start(true, names, bounds):
    vals = {}
    for k, n in enumerate(names):
        v = getattr(true.params, n)
        f = 1.5 if k % 2 == 0 else 0.6
        s = v * f if v != 0 else 0.5 * (bounds[n][0] + bounds[n][1])
        lo, hi = bounds[n]
        vals[n] = float(np.clip(s, lo + 1e-9 * (hi - lo), hi - 1e-9 * (hi - lo)))
    return true.with_values(**vals)


def _finish(name, paper, true, t, F, names, noise, seed, **cols):
    if noise:
        F = F + noise * np.std(F) * np.random.default_rng(seed + 17).standard_normal(F.size)
    data = Dataset.from_arrays(t, F, name=name, check_units=False, **cols)
    truth = {n: getattr(true.params, n) for n in names}
    bounds = _box(true, names, truth)
    return SyntheticCase(name, paper, true, data, list(names), _start(true, names, bounds), bounds)


def case_seed000(noise=0.0, seed=0):
    """SHAO (seed 000) modified LuGre (the law's defaults: Tables 1-3 are not in the seed),
    one period of the 5 Hz / 8 mm sine of the valve tests, 5 kHz."""
    true = make_model("modified_lugre")
    t = np.arange(0, 0.2, 2e-4)  # one period
    w = 2 * np.pi * 5
    v = 8e-3 * w * np.cos(w * t)
    a = -8e-3 * w * w * np.sin(w * t)
    F = true.simulate(t, v, a=a)
    names = ["sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs", "f_a", "a_s"]
    return _finish("seed000 modified_lugre", "000", true, t, F, names, noise, seed, v=v, a=a)


def case_seed001(noise=0.0, seed=0):
    """Seed 001 Table I (AGA, 4 Hz): Fc 5.27 N, Fs 34.43 N, vs 0.021 m/s, sigma2 48.55,
    sigma1 138.83, sigma0 4457.9; 4 Hz sine of 10 mm, 1 kHz."""
    true = make_model("lugre", Fc=5.27, Fs=34.43, vs=0.021, sigma2=48.55, sigma1=138.83,
                      sigma0=4457.9)
    t = np.arange(0, 1.0, 1e-3)
    w = 2 * np.pi * 4
    v = 10e-3 * w * np.cos(w * t)
    F = true.simulate(t, v)
    names = ["sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs"]
    return _finish("seed001 lugre (Table I)", "001", true, t, F, names, noise, seed, v=v)


def case_seed002(noise=0.0, seed=0):
    """YU (seed 002) improved LuGre, Table 3 reference values (the law's defaults), 4 Hz /
    8 mm shear, 256 Hz, three periods."""
    true = make_model("mre_lugre")
    t = np.arange(0, 0.75, 1 / 256)
    w = 2 * np.pi * 4
    x = 8e-3 * np.sin(w * t)
    v = 8e-3 * w * np.cos(w * t)
    F = true.simulate(t, v, x=x)
    names = ["beta", "alpha", "c0", "k0", "eps", "f0"]
    return _finish("seed002 mre_lugre (Table 3)", "002", true, t, F, names, noise, seed, v=v, x=x)


def case_seed003(noise=0.0, seed=0):
    """Seed 003 Table I (XML-350, final): Fs 1.1 N, Fc 0.95 N, sigma2 15.62, vs 1e-5 m/s,
    sigma0 11.02e6 N/m, sigma1 1.46e3, b 0.01 N (Lorentzian Stribeck curve); 10 Hz coloured
    noise velocity of 10 mm/s RMS, 1 kHz."""
    true = make_model("lugre", Fs=1.1, Fc=0.95, sigma2=15.62, vs=1e-5, sigma0=11.02e6,
                      sigma1=1.46e3, b=0.01, shape="lorentzian")
    t = np.arange(0, 3.0, 1e-3)
    v = coloured_noise(t, 10.0, 10e-3, seed=seed + 3)
    F = true.simulate(t, v)
    names = ["sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs", "b"]
    return _finish("seed003 lugre (Table I)", "003", true, t, F, names, noise, seed, v=v)


def case_seed004(noise=0.0, seed=0):
    """LI (seed 004) load-dependent LuGre, Tables 2/3 (the law's defaults): the four forging
    speeds 1.2 / 0.1 / 0.05 / 0.002 mm/s of Table 1 as plateaus with smooth transitions,
    deformation load rising with the stroke."""
    from friction.load_lugre import critical_velocity
    base = make_model("load_lugre").params
    # the regime split fixed at the no-load vc of Table 2 (0.19 mm/s), so it does not move
    # with the identified static parameters
    true = make_model("load_lugre", vc=critical_velocity(base.Fc0, base.Fs0, base.vs,
                                                         base.sigma20))
    t = np.arange(0, 40.0, 0.01)
    levels = np.array([1.2, 0.1, 0.05, 0.002, 0.05, 0.1, 1.2, 0.3]) * 1e-3
    seg = np.minimum((t / 5.0).astype(int), levels.size - 1)
    v = levels[seg]
    from scipy.ndimage import gaussian_filter1d
    v = gaussian_filter1d(v, 20)
    load = np.where(t < 20, 7.5e3 * t, 1.5e5 - 3.75e3 * (t - 20))
    F = true.simulate(t, v, load=load)
    # k2_high is left out: it multiplies exp(-(v/vs)^2) <= exp(-6.2) above vc, so no
    # plateau above vc can identify it (structurally unidentifiable, not a solver issue)
    names = ["Fc0", "Fs0", "vs", "sigma20", "k1_low", "k2_low", "k3_low", "k1_high", "k3_high"]
    return _finish("seed004 load_lugre (Tables 2/3)", "004", true, t, F, names, noise, seed,
                   v=v, load=load)


CASES = {"seed000": case_seed000, "seed001": case_seed001, "seed002": case_seed002,
         "seed003": case_seed003, "seed004": case_seed004}


def make_case(key: str, noise: float = 0.0, seed: int = 0) -> SyntheticCase:
    """One synthetic case; ``noise`` is the white-noise RMS as a fraction of std(F)."""
    try:
        return CASES[key](noise=noise, seed=seed)
    except KeyError:
        raise ValueError(f"unknown case {key!r}; choose from {sorted(CASES)}") from None
