"""Stribeck-curve shapes g(v) shared by the LuGre family (numba and numpy versions).

``gaussian``  : g = Fc + (Fs - Fc) exp(-|v/vs|^alpha)      (seed 000 Eq. 4; alpha=2: seeds 001/004)
``lorentzian``: g = Fc + (Fs - Fc) / (1 + (|v|/vs)^2)       (seed 003 Eq. 3)

g is in force units [N]; the bristle saturates at z_ss = g(v) sgn(v) / sigma0.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numba import njit

from ._validation import ParameterError
from .base import FrictionParams, param

__all__ = ["SHAPES", "stribeck_g", "stribeck_g_np", "DirectionalStribeck",
           "DirectionalStribeckParams"]

SHAPES = {"gaussian": 0, "lorentzian": 1}


@njit(cache=True, inline="always")
def stribeck_g(v, Fc, Fs, vs, alpha, shape):
    """g(v) [N] for one sample; ``shape`` is the integer code of :data:`SHAPES`."""
    r = abs(v) / vs
    if shape == 1:
        e = 1.0 / (1.0 + r * r)
    elif alpha == 2.0:
        e = math.exp(-r * r)  # the common case, without the pow
    else:
        e = math.exp(-r ** alpha)
    return Fc + (Fs - Fc) * e


def stribeck_g_np(v, Fc, Fs, vs, alpha=2.0, shape="gaussian"):
    """Vectorised g(v) [N] (numpy)."""
    r = np.abs(np.asarray(v, dtype=float)) / vs
    if shape == "lorentzian" or shape == 1:
        e = 1.0 / (1.0 + r * r)
    else:
        e = np.exp(-r ** alpha)
    return Fc + (Fs - Fc) * e


@dataclass(frozen=True)
class DirectionalStribeckParams(FrictionParams):
    """The parameter block of a direction-dependent Stribeck curve with viscous friction and
    an offset (``sigma2, Fc, Fs, vs, alpha, b``, their ``*_neg`` twins and ``shape``), the
    one definition the static map (:class:`friction.stribeck.StribeckParams`) and the classic
    LuGre (:class:`friction.lugre.LuGreParams`, after its bristle fields) share. Defaults:
    a small precision-stage contact."""
    #: option fields -> their choices and the integer codes the kernels use
    OPTIONS: ClassVar[dict] = {"shape": SHAPES}
    sigma2: float = param(0.4, "N.s/m", "viscous coefficient (v >= 0)", lower=0,
                          search=(0.0, 50.0))
    Fc: float = param(1.0, "N", "Coulomb friction level (v >= 0)", lower=0, lower_open=True,
                      search=(1e-2, 50.0))
    Fs: float = param(1.5, "N", "static (break-away) friction level (v >= 0)", lower=0,
                      lower_open=True, search=(1e-2, 60.0))
    vs: float = param(1e-3, "m/s", "Stribeck velocity (v >= 0)", lower=0, lower_open=True,
                      search=(1e-5, 0.1), log=True)
    alpha: float = param(2.0, "1", "Stribeck shape exponent (gaussian shape)", lower=0,
                         lower_open=True, upper=10, search=(0.3, 4.0))
    b: float = param(0.0, "N", "constant force offset (seed 003 Eq. 4)", search=(-5.0, 5.0))
    Fc_neg: float | None = param(None, "N", "Coulomb level for v < 0 (None: same as Fc)",
                                 lower=0, lower_open=True, search=(1e-2, 50.0))
    Fs_neg: float | None = param(None, "N", "static level for v < 0 (None: same as Fs)",
                                 lower=0, lower_open=True, search=(1e-2, 60.0))
    vs_neg: float | None = param(None, "m/s", "Stribeck velocity for v < 0 (None: same as vs)",
                                 lower=0, lower_open=True, search=(1e-5, 0.1), log=True)
    sigma2_neg: float | None = param(None, "N.s/m", "viscous coefficient for v < 0 "
                                     "(None: same as sigma2)", lower=0, search=(0.0, 50.0))
    shape: str = "gaussian"

    def _check_relations(self):
        if self.shape not in SHAPES:
            raise ParameterError(f"shape = {self.shape!r}: must be one of {sorted(SHAPES)}")


class DirectionalStribeck:
    """Mixin of the laws whose parameters carry a Stribeck curve (Fc, Fs, vs, alpha, shape),
    a viscous coefficient sigma2 and their direction twins (``*_neg``, resolved by
    :meth:`friction.base.FrictionParams.resolved`): the curve and the viscous coefficient
    of the direction of each velocity sample."""

    def g(self, v) -> np.ndarray:
        """Stribeck curve g(v) [N] (direction-dependent values applied).

        Parameters
        ----------
        v : array_like
            Velocity [m/s].
        """
        v = np.asarray(v, dtype=float)
        p = self.params
        gp = stribeck_g_np(v, p.Fc, p.Fs, p.vs, p.alpha, p.shape)
        gn = stribeck_g_np(v, p.resolved("Fc", -1), p.resolved("Fs", -1),
                           p.resolved("vs", -1), p.alpha, p.shape)
        return np.where(v >= 0, gp, gn)

    def sigma2_of(self, v) -> np.ndarray:
        """Viscous coefficient [N.s/m] of the direction of ``v``.

        Parameters
        ----------
        v : array_like
            Velocity [m/s].
        """
        p = self.params
        return np.where(np.asarray(v) >= 0, p.sigma2, p.resolved("sigma2", -1))
