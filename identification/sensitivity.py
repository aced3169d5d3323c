"""Parameter sensitivity of a friction law along an experiment: local, global, Sobol.

Three analyses, generic over any :class:`friction.FrictionModel` and prescribed-motion
experiment ``(t, v, a=, load=, x=)``, all evaluated through the law's numba population kernel:

* :func:`local_sensitivity` - seed 002 section 4.4 (YU 2015, ``EQUATIONS.md`` B.1): each
  parameter is varied by -50 ... +50 % in 10 % steps (0 included) with the others at their
  reference values; the sensitivity is the RMS of the output change against the reference
  output, averaged over the variations ("mean RMSE"); shares are these means over their sum.
* :func:`global_sensitivity` - seed 002's global method: "the global analysis changes one
  parameter every time while the remaining parameters are able to be self-adjusted to
  compensate the output variation". For each variation of one parameter the others are
  re-fitted (``scipy.optimize.least_squares``) to the reference output; the RMS left after
  that compensation is the parameter's global sensitivity (averaged over the variations).
  A parameter whose effect the others can imitate scores low.
* :func:`sobol_indices` - variance-based indices with ``SALib`` (Saltelli/Sobol' sampling,
  ``SALib.analyze.sobol``) of a scalar output (default: the same RMS output change) over a
  uniform box of +-``spread`` around the reference values.

Each returns a :class:`SensitivityResult` (values, shares, ranking, details).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable, Sequence

import numpy as np
from scipy.optimize import least_squares

from friction.base import METHODS, FrictionModel

__all__ = ["DEFAULT_VARIATIONS", "SensitivityResult", "local_sensitivity",
           "global_sensitivity", "sobol_indices"]

#: seed 002: -50 % ... +50 % in 10 % steps, 0 included (11 values)
DEFAULT_VARIATIONS = tuple(round(0.1 * k, 10) for k in range(-5, 6))

_CHUNK_BYTES = 64 * 2 ** 20  # force rows held at once by the chunked population runs


@dataclass
class SensitivityResult:
    """Outcome of a sensitivity analysis.

    Attributes
    ----------
    method : str
        ``"local"``, ``"global"`` or ``"sobol"``.
    names : tuple of str
        Parameters analysed.
    values : ndarray
        One value per name: mean RMS output change [N] (local, global) or first-order
        Sobol index S1 (sobol).
    shares : ndarray
        ``values`` normalised to sum 1 (negative Sobol estimates clipped to 0 first).
    ranking : tuple of str
        Names by decreasing value.
    details : dict
        Method-specific arrays (per-variation RMS, fitted compensations, ST, confidences...).
    """
    method: str
    names: tuple
    values: np.ndarray
    shares: np.ndarray
    ranking: tuple
    details: dict = field(default_factory=dict)

    def __getitem__(self, name: str) -> float:
        return float(self.values[self.names.index(name)])

    def share(self, name: str) -> float:
        return float(self.shares[self.names.index(name)])

    def as_dict(self) -> dict:
        """JSON-friendly summary (no large arrays)."""
        return {"method": self.method,
                "values": {n: float(v) for n, v in zip(self.names, self.values)},
                "shares": {n: float(s) for n, s in zip(self.names, self.shares)},
                "ranking": list(self.ranking)}

    def table(self) -> str:
        """Plain-text table: parameter, value, share, rank."""
        head = "S1" if self.method == "sobol" else "mean RMSE"
        rows = [f"{'parameter':>10} {head:>12} {'share':>8} {'rank':>5}"]
        for n, v, s in zip(self.names, self.values, self.shares):
            rows.append(f"{n:>10} {v:12.4g} {100 * s:7.2f}% {self.ranking.index(n) + 1:5d}")
        return "\n".join(rows)


def _result(method, names, values, details) -> SensitivityResult:
    values = np.asarray(values, dtype=float)
    pos = np.clip(values, 0.0, None)
    total = pos.sum()
    shares = pos / total if total > 0 else np.zeros_like(pos)
    order = np.argsort(-values, kind="stable")
    return SensitivityResult(method, tuple(names), values, shares,
                             tuple(names[i] for i in order), details)


class _Experiment:
    """A validated experiment bound to a model: runs packed populations, scores RMS change."""

    def __init__(self, model: FrictionModel, t, v, a, load, x, method, skip_time):
        if not isinstance(model, FrictionModel):
            raise TypeError(f"model must be a friction.FrictionModel, got {type(model).__name__}")
        if method not in METHODS:
            raise ValueError(f"method must be one of {sorted(METHODS)}, got {method!r}")
        self.model = model
        self.inputs = model._inputs(t, v, a, load, x)  # validates, names bad samples
        self.method = METHODS[method]
        t = self.inputs[0]
        if not (np.isfinite(skip_time) and skip_time >= 0):
            raise ValueError(f"skip_time = {skip_time!r} is out of bounds: must be >= 0 [s]")
        self.mask = t >= t[0] + skip_time - 1e-12 * max(1.0, abs(t[0]))
        if self.mask.sum() < 2:
            raise ValueError(f"skip_time = {skip_time!r} s leaves fewer than 2 samples to score")
        self.reference = self.run(model.theta[None, :].copy())[0]
        if not np.all(np.isfinite(self.reference)):
            raise ValueError("the reference parameters give a non-finite force along this "
                             "experiment")

    def run(self, Theta: np.ndarray) -> np.ndarray:
        t, v, a, load, x = self.inputs
        return self.model._population_kernel(t, v, a, load, x, np.ascontiguousarray(Theta),
                                             self.method)

    def theta(self, names, X) -> np.ndarray:
        return self.model.population_theta(names, X)

    def rms_change(self, F: np.ndarray) -> np.ndarray:
        d = F[:, self.mask] - self.reference[self.mask]
        return np.sqrt(np.mean(d * d, axis=1))

    def scalar(self, names, X, output=None, progress=None) -> np.ndarray:
        """Scalar output per row of X, evaluated in memory-bounded chunks."""
        n = self.inputs[0].size
        chunk = max(1, int(_CHUNK_BYTES // (8 * n)))
        out = []
        for i in range(0, X.shape[0], chunk):
            F = self.run(self.theta(names, X[i:i + chunk]))
            out.append(self.rms_change(F) if output is None
                       else np.asarray(output(F, self.reference, self.mask), dtype=float))
            if progress is not None:
                progress(min(chunk, X.shape[0] - i))
        return np.concatenate(out)


def _names(model: FrictionModel, names) -> list[str]:
    names = list(model.free_names() if names is None else names)
    layout = set(model.theta_layout)
    for n in names:
        if n not in layout:
            raise KeyError(f"{model.name} has no parameter {n!r}; choose from "
                           f"{model.free_names()}")
    if not names:
        raise ValueError("names: need at least one parameter")
    return names


def _reference_values(model: FrictionModel, names) -> np.ndarray:
    idx = {n: i for i, n in enumerate(model.theta_layout)}
    return np.array([model.theta[idx[n]] for n in names], dtype=float)


def _variations(variations) -> np.ndarray:
    d = np.asarray(variations, dtype=float).ravel()
    if d.size == 0 or np.any(~np.isfinite(d)) or np.any(d <= -1.0):
        raise ValueError(f"variations = {variations!r}: need finite relative changes > -1")
    return d


def local_sensitivity(model: FrictionModel, t, v, names: Sequence[str] | None = None, *,
                      a=None, load=None, x=None, variations=DEFAULT_VARIATIONS,
                      method: str = "exact", skip_time: float = 0.0,
                      progress: Callable | None = None) -> SensitivityResult:
    """One-at-a-time local sensitivity of seed 002 section 4.4.

    Parameters
    ----------
    model : FrictionModel
        Law with its reference parameter values.
    t, v : array_like, shape (N,)
        Time [s] and velocity [m/s] of the experiment.
    names : sequence of str, optional
        Parameters to vary (default: all free numeric parameters).
    a, load, x : array_like, optional
        Extra inputs the law needs (acceleration, load [N], displacement [m]).
    variations : sequence of float
        Relative changes (default -0.5 ... 0.5 step 0.1, 0 included as in the seed).
    method : {"exact", "euler"}
        State update of the law's kernel (seed 002 used Euler, Eq. 2d).
    skip_time : float
        Initial transient not scored [s] (e.g. the first excitation cycle).
    progress : callable, optional
        Called with the number of parameter sets done.

    Returns
    -------
    SensitivityResult
        ``values`` = mean over the variations of RMS(F_varied - F_reference) [N];
        ``details["rms"]`` has shape (len(names), len(variations)).
    """
    names = _names(model, names)
    d = _variations(variations)
    exp = _Experiment(model, t, v, a, load, x, method, skip_time)
    ref = _reference_values(model, names)
    k = len(names)
    X = np.repeat(ref[None, :], k * d.size, axis=0)
    for i in range(k):
        X[i * d.size:(i + 1) * d.size, i] = ref[i] * (1.0 + d)
    rms = exp.scalar(names, X, progress=progress).reshape(k, d.size)
    return _result("local", names, rms.mean(axis=1),
                   {"variations": d, "rms": rms, "reference_values": dict(zip(names, ref)),
                    "reference_force": exp.reference})


def _box(model: FrictionModel, names, ref):
    """least_squares bounds from the parameters' admissible bounds (open ends nudged)."""
    info = {i.name: i for i in model.Params.info()}
    lo, hi = [], []
    for n, r in zip(names, ref):
        pi = info.get(n)
        low = pi.lower if pi is not None else -np.inf
        up = pi.upper if pi is not None else np.inf
        tiny = 1e-9 * max(abs(r), 1e-300)
        lo.append(low + tiny if (pi is not None and pi.lower_open) else low)
        hi.append(up - tiny if (pi is not None and pi.upper_open) else up)
    return np.array(lo), np.array(hi)


def global_sensitivity(model: FrictionModel, t, v, names: Sequence[str] | None = None, *,
                       a=None, load=None, x=None, variations=DEFAULT_VARIATIONS,
                       compensate: Sequence[str] | None = None, method: str = "exact",
                       skip_time: float = 0.0, max_nfev: int = 200,
                       progress: Callable | None = None) -> SensitivityResult:
    """Global sensitivity of seed 002: vary one parameter, let the others compensate.

    For each parameter p and each variation d, p is fixed at (1 + d) p_ref and the
    parameters in ``compensate`` (default: the other ``names``) are re-fitted by
    ``scipy.optimize.least_squares`` (trust-region reflective, inside their admissible
    bounds, started at the reference values, Jacobian by forward differences computed as
    one population run) to reproduce the reference output. The remaining RMS output change
    is the global sensitivity of p at d; ``values`` average it over the variations.

    Parameters
    ----------
    model, t, v, names, a, load, x, variations, method, skip_time, progress
        As :func:`local_sensitivity`.
    compensate : sequence of str, optional
        Parameters allowed to self-adjust (default: all ``names`` but the varied one).
    max_nfev : int
        Function-evaluation budget of each fit.

    Returns
    -------
    SensitivityResult
        ``details["rms"]`` (len(names), len(variations)) residual RMS after compensation,
        ``details["compensation"][p]`` the fitted values of the others per variation,
        ``details["nfev"]`` total model evaluations.
    """
    names = _names(model, names)
    d = _variations(variations)
    exp = _Experiment(model, t, v, a, load, x, method, skip_time)
    ref_all = dict(zip(names, _reference_values(model, names)))
    comp_all = _names(model, compensate) if compensate is not None else names
    comp_ref = dict(zip(comp_all, _reference_values(model, comp_all)))
    m = exp.mask
    nm = float(m.sum())
    rms = np.zeros((len(names), d.size))
    compensation: dict[str, np.ndarray] = {}
    nfev_total = 0
    for i, p in enumerate(names):
        others = [n for n in comp_all if n != p]
        r0 = np.array([comp_ref[n] for n in others])
        lo, hi = _box(model, others, r0)
        scale = np.where(r0 != 0, np.abs(r0), 1.0)
        fitted = np.full((d.size, len(others)), np.nan)
        for j, dj in enumerate(d):
            fixed = ref_all[p] * (1.0 + dj)
            cols = [p] + others
            if dj == 0.0 or not others:
                F = exp.run(exp.theta(cols, np.concatenate(([fixed], r0))[None, :]))
                rms[i, j] = exp.rms_change(F)[0]
                fitted[j] = r0
                nfev_total += 1
                if progress is not None:
                    progress(1)
                continue

            def resid(u, fixed=fixed, cols=cols):
                F = exp.run(exp.theta(cols, np.concatenate(([fixed], u * scale))[None, :]))[0]
                r = (F[m] - exp.reference[m]) / math.sqrt(nm)
                return np.where(np.isfinite(r), r, 1e6)

            def jac(u, fixed=fixed, cols=cols):
                h = 1e-7 * np.maximum(np.abs(u), 1.0)
                U = np.repeat(u[None, :], u.size + 1, axis=0)
                U[1:] += np.diag(h)
                X = np.column_stack([np.full(U.shape[0], fixed), U * scale])
                F = exp.run(exp.theta(cols, X))
                R = (F[:, m] - exp.reference[m]) / math.sqrt(nm)
                return ((R[1:] - R[0]) / h[:, None]).T

            u0 = np.clip(np.ones(len(others)), lo / scale, hi / scale)
            sol = least_squares(resid, u0, jac=jac, bounds=(lo / scale, hi / scale),
                                method="trf", max_nfev=max_nfev, x_scale=1.0)
            nfev_total += sol.nfev + sol.njev * (len(others) + 1)
            fitted[j] = sol.x * scale
            rms[i, j] = math.sqrt(2.0 * sol.cost)  # cost = 0.5 sum r^2 = 0.5 mean(dF^2)
            if progress is not None:
                progress(1)
        compensation[p] = fitted
    return _result("global", names, rms.mean(axis=1),
                   {"variations": d, "rms": rms, "compensation": compensation,
                    "compensate": comp_all, "nfev": nfev_total,
                    "reference_values": ref_all})


def sobol_indices(model: FrictionModel, t, v, names: Sequence[str] | None = None, *,
                  a=None, load=None, x=None, spread: float = 0.5, bounds=None, n: int = 1024,
                  seed: int | None = 0, calc_second_order: bool = False,
                  num_resamples: int = 100, method: str = "exact", skip_time: float = 0.0,
                  output: Callable | None = None,
                  progress: Callable | None = None) -> SensitivityResult:
    """Sobol' indices with SALib over a box around the reference parameters.

    Parameters
    ----------
    model, t, v, names, a, load, x, method, skip_time, progress
        As :func:`local_sensitivity`.
    spread : float
        Half-width of the uniform box relative to each reference value (0.5: +-50 %, the
        seed's range). Ignored for names given in ``bounds``.
    bounds : dict, optional
        Explicit ``name -> (low, high)`` ranges.
    n : int
        Base sample size of the Saltelli/Sobol' design (power of 2); the model runs
        ``n (D + 2)`` times (``n (2 D + 2)`` with second-order indices).
    seed : int, optional
        Seed of the scrambled Sobol' sequence and of the bootstrap.
    calc_second_order : bool
        Also estimate S2.
    num_resamples : int
        Bootstrap resamples for the confidence intervals.
    output : callable, optional
        ``output(F_rows, F_reference, mask) -> Y`` scalar per row; default the RMS output
        change against the reference over the scored samples [N].

    Returns
    -------
    SensitivityResult
        ``values`` = S1; ``details`` has ``ST``, ``S1_conf``, ``ST_conf``,
        ``ranking_total`` (by ST), ``bounds``, ``n_evaluations`` (and ``S2`` if asked).
    """
    from SALib.analyze import sobol as sobol_analyze
    from SALib.sample import sobol as sobol_sample

    names = _names(model, names)
    if not (np.isfinite(spread) and 0 < spread < 1):
        raise ValueError(f"spread = {spread!r} is out of bounds: must be 0 < spread < 1")
    if n < 2 or (n & (n - 1)) != 0:
        raise ValueError(f"n = {n!r}: the Sobol' design needs a power of 2 >= 2")
    ref = _reference_values(model, names)
    bounds = dict(bounds or {})
    box = []
    for name, r in zip(names, ref):
        if name in bounds:
            lo, hi = (float(b) for b in bounds[name])
        else:
            if r == 0:
                raise ValueError(f"{name} has reference value 0: a relative box is empty; "
                                 "give bounds={name!r: (low, high)}")
            lo, hi = sorted((r * (1 - spread), r * (1 + spread)))
        if not hi > lo:
            raise ValueError(f"bounds of {name}: need low < high, got ({lo}, {hi})")
        box.append([lo, hi])
    problem = {"num_vars": len(names), "names": list(names), "bounds": box}
    exp = _Experiment(model, t, v, a, load, x, method, skip_time)
    X = sobol_sample.sample(problem, n, calc_second_order=calc_second_order, seed=seed)
    Y = exp.scalar(names, X, output=output, progress=progress)
    if not np.all(np.isfinite(Y)):
        bad = int(np.argmax(~np.isfinite(Y)))
        raise ValueError(f"non-finite model output for parameter set {dict(zip(names, X[bad]))}")
    Si = sobol_analyze.analyze(problem, Y, calc_second_order=calc_second_order,
                               num_resamples=num_resamples, seed=seed)
    ST = np.asarray(Si["ST"], dtype=float)
    details = {"ST": ST, "S1_conf": np.asarray(Si["S1_conf"], dtype=float),
               "ST_conf": np.asarray(Si["ST_conf"], dtype=float),
               "ranking_total": tuple(names[i] for i in np.argsort(-ST, kind="stable")),
               "bounds": dict(zip(names, map(tuple, box))), "n_evaluations": int(X.shape[0]),
               "Y": Y}
    if calc_second_order:
        details["S2"] = np.asarray(Si["S2"], dtype=float)
    return _result("sobol", names, np.asarray(Si["S1"], dtype=float), details)
