"""The search space of an identification: which parameters, their box, and their scaling.

Optimisers work in the unit cube ``u in [0, 1]^D``. Each coordinate maps to a physical value
linearly, or log-linearly for parameters whose metadata says ``log=True`` (stiffness sigma0,
Stribeck velocity vs: several decades wide). This is the one place that knows about the
mapping, so every algorithm sees the same well-scaled problem.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from friction.base import FrictionModel

__all__ = ["ParameterSpace", "default_bounds", "default_names"]


def default_names(model: FrictionModel) -> list[str]:
    """The parameters :func:`identification.identify` fits when none are named, and the
    free set of the diagnosis' base law (:func:`diagnosis.core.fit_base`): one definition,
    so both commands mean the same law by a name.

    Every numeric parameter of the law that is set (:meth:`friction.base.FrictionModel.
    free_names`): for the classic LuGre sigma0, sigma1, sigma2, Fc, Fs, vs, the Stribeck
    exponent alpha and the offset b; a direction twin left ``None`` (symmetric law) and a
    law's preset constants are not identified.

    Parameters
    ----------
    model : FrictionModel
        The law.
    """
    return list(model.free_names())


def _unit_kind(unit: str) -> str:
    u = unit.replace(" ", "")
    if u in ("N", "Nm", "N.m"):
        return "force"
    if u in ("N.s/m", "Ns/m", "N.m.s/rad", "Nms/rad"):
        return "damping"
    if u in ("N/m", "N.m/rad"):
        return "stiffness"
    if u in ("m/s", "rad/s"):
        return "velocity"
    return "other"


def default_bounds(model: FrictionModel, names, data=None) -> dict[str, tuple[float, float]]:
    """Search box per parameter: the metadata ``search`` range, widened to fit the data.

    The metadata ranges are written for a small contact (forces of a few N, speeds of mm/s
    to dm/s). With data, the box grows by unit: forces up to 2 x the 99th percentile of
    ``|F|``; damping/viscous coefficients up to 2 x that force over the 99th percentile of
    ``|v|``; bristle stiffness scaled with the force level; velocities up to the largest
    speed. The box always contains the model's current value.

    Parameters
    ----------
    model : FrictionModel
        The law.
    names : list of str
        Parameters to bound.
    data : Dataset, optional
        The record the box is widened to.
    """
    infos = {i.name: i for i in model.Params.info()}
    out = {}
    sF = sv = None
    if data is not None:
        sF = float(np.percentile(np.abs(data.F), 99)) or None
        sv = float(np.percentile(np.abs(data.v), 99)) or None
    for n in names:
        if n not in infos:
            raise KeyError(f"{model.name} has no parameter {n!r}; choose from {list(infos)}")
        info = infos[n]
        lo, hi = info.search if info.search is not None else (info.lower, info.upper)
        kind = _unit_kind(info.unit)
        if sF is not None:
            if kind == "force":
                if lo < 0:
                    lo = min(lo, -2 * sF)
                hi = max(hi, 2 * sF)
            elif kind == "damping" and sv:
                hi = max(hi, 2 * sF / sv)
            elif kind == "stiffness" and sF > 1:
                hi = hi * sF  # stiffer contacts carry larger forces; keep the soft end
            elif kind == "velocity" and sv:
                hi = max(hi, sv)
        cur = getattr(model.params, n)
        if cur is not None and math.isfinite(cur):
            if cur < lo:
                lo = cur / 2 if (info.log and cur > 0) else cur - 0.5 * abs(cur)
            if cur > hi:
                hi = cur * 2 if cur > 0 else cur + 0.5 * abs(cur)
        # admissible bounds of the law cut the box
        lo = max(lo, info.lower)
        hi = min(hi, info.upper)
        if not (math.isfinite(lo) and math.isfinite(hi) and hi > lo):
            raise ValueError(f"no finite search range for {n}: give bounds={{'{n}': (lo, hi)}}")
        out[n] = (float(lo), float(hi))
    return out


@dataclass
class ParameterSpace:
    """Names, box and scaling of the identified parameters.

    Attributes
    ----------
    names : list of str
    lower, upper : ndarray
        Physical box [SI units of each parameter].
    log : ndarray of bool
        Which coordinates are searched on a log scale.
    """
    names: list
    lower: np.ndarray
    upper: np.ndarray
    log: np.ndarray

    @classmethod
    def build(cls, model: FrictionModel, names=None, bounds=None, data=None) -> "ParameterSpace":
        """The space of ``names`` of ``model`` with their search box.

        Parameters
        ----------
        model : FrictionModel
            The law (its current values and parameter metadata).
        names : list of str, optional
            Parameters to fit (default :func:`default_names`).
        bounds : dict, optional
            ``{name: (low, high)}`` replacing the default box (SI units).
        data : Dataset, optional
            The record the default box is widened to.
        """
        infos = {i.name: i for i in model.Params.info()}
        if names is None:
            names = default_names(model)
        names = list(names)
        if not names:
            raise ValueError("nothing to identify: names is empty")
        unknown = [n for n in names if n not in infos]
        if unknown:
            raise KeyError(f"{model.name} has no parameter(s) {unknown}; choose from "
                           f"{model.free_names()}")
        # the data's default box only for names without given bounds (its percentiles of
        # |F| and |v| are skipped when every name has one)
        rest = [n for n in names if n not in (bounds or {})]
        box = default_bounds(model, rest, data if rest else None)
        for n, b in (bounds or {}).items():
            if n not in names:
                raise KeyError(f"bounds given for {n!r}, which is not identified ({names})")
            lo, hi = map(float, b)
            if not hi > lo:
                raise ValueError(f"bounds for {n}: upper {hi!r} must exceed lower {lo!r}")
            box[n] = (lo, hi)
        lower = np.array([box[n][0] for n in names])
        upper = np.array([box[n][1] for n in names])
        log = np.array([infos[n].log and lower[j] > 0 for j, n in enumerate(names)])
        return cls(names, lower, upper, log)

    @property
    def dim(self) -> int:
        return len(self.names)

    def _ends(self):
        lo = np.where(self.log, np.log(np.where(self.log, self.lower, 1.0)), self.lower)
        hi = np.where(self.log, np.log(np.where(self.log, self.upper, 1.0)), self.upper)
        return lo, hi

    def to_physical(self, U) -> np.ndarray:
        """Unit-cube coordinates -> physical values (same shape).

        Parameters
        ----------
        U : array_like, shape (..., D)
            Unit-cube coordinates.
        """
        U = np.asarray(U, float)
        lo, hi = self._ends()
        s = lo + U * (hi - lo)
        with np.errstate(over="ignore"):
            return np.where(self.log, np.exp(np.where(self.log, s, 0.0)), s)

    def to_unit(self, X) -> np.ndarray:
        """Physical values -> unit-cube coordinates (not clipped).

        Parameters
        ----------
        X : array_like, shape (..., D)
            Physical values.
        """
        X = np.asarray(X, float)
        lo, hi = self._ends()
        s = np.where(self.log, np.log(np.maximum(X, 1e-300)), X)
        return (s - lo) / (hi - lo)

    def dict_of(self, x) -> dict[str, float]:
        """``{name: value}`` of a parameter vector.

        Parameters
        ----------
        x : array_like, shape (D,)
            Physical values in ``names`` order.
        """
        return {n: float(v) for n, v in zip(self.names, np.asarray(x, float))}

    def as_json(self) -> dict:
        return {n: {"lower": float(l), "upper": float(u), "log": bool(g)}
                for n, l, u, g in zip(self.names, self.lower, self.upper, self.log)}
