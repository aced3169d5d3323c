"""Stribeck-curve shapes g(v) shared by the LuGre family (numba and numpy versions).

``gaussian``  : g = Fc + (Fs - Fc) exp(-|v/vs|^alpha)      (seed 000 Eq. 4; alpha=2: seeds 001/004)
``lorentzian``: g = Fc + (Fs - Fc) / (1 + (|v|/vs)^2)       (seed 003 Eq. 3)

g is in force units [N]; the bristle saturates at z_ss = g(v) sgn(v) / sigma0.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

__all__ = ["SHAPES", "stribeck_g", "stribeck_g_np", "DirectionalStribeck"]

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


class DirectionalStribeck:
    """Mixin of the laws whose parameters carry a Stribeck curve (Fc, Fs, vs, alpha, shape),
    a viscous coefficient sigma2 and their direction twins (``*_neg``, resolved by
    :meth:`friction.base.FrictionParams.resolved`): the curve and the viscous coefficient
    of the direction of each velocity sample."""

    def g(self, v) -> np.ndarray:
        """Stribeck curve g(v) [N] (direction-dependent values applied)."""
        v = np.asarray(v, dtype=float)
        p = self.params
        gp = stribeck_g_np(v, p.Fc, p.Fs, p.vs, p.alpha, p.shape)
        gn = stribeck_g_np(v, p.resolved("Fc", -1), p.resolved("Fs", -1),
                           p.resolved("vs", -1), p.alpha, p.shape)
        return np.where(v >= 0, gp, gn)

    def sigma2_of(self, v) -> np.ndarray:
        """Viscous coefficient [N.s/m] of the direction of ``v``."""
        p = self.params
        return np.where(np.asarray(v) >= 0, p.sigma2, p.resolved("sigma2", -1))
