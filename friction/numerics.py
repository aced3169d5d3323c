"""Stability facts of the discrete bristle update (seed 000 Eqs. 27-30) and passivity.

Explicit Euler on dz/dt = v - a z, a = sigma0 |v| / g(v), has the homogeneous factor
(1 - h a): it changes sign (oscillation) once h a > 1 and grows once h a > 2.
"""
from __future__ import annotations

import numpy as np
from scipy.optimize import brentq

__all__ = ["euler_critical_velocity", "lugre_dissipative_on"]


def euler_critical_velocity(model, h: float, *, growth: bool = False,
                            direction: int = 1) -> float:
    """Velocity above which explicit Euler's bristle update oscillates (seed 000 Eq. 30).

    Solves |v| = k g(v) / (sigma0 h) with k = 1 (oscillation onset) or k = 2 (growth), i.e.
    h sigma0 |v| / g(v) = k. For |v| >> vs this is k Fc / (sigma0 h).

    Parameters
    ----------
    model : LuGre-family model with ``g(v)`` and ``params.sigma0``
    h : float
        Step size [s] (> 0).
    growth : bool
        Return the divergence threshold (k = 2) instead of the oscillation onset.
    direction : {+1, -1}
        Which branch of a direction-dependent law.

    Returns
    -------
    float
        Critical speed [m/s] (positive).
    """
    if not h > 0:
        raise ValueError(f"h = {h!r} is out of bounds: must be > 0 [s]")
    k = 2.0 if growth else 1.0
    s0 = model.params.sigma0
    sgn = 1.0 if direction >= 0 else -1.0

    def f(speed):
        return h * s0 * speed / float(model.g(sgn * speed)) - k

    hi = 1e-12
    while f(hi) < 0:
        hi *= 2.0
        if hi > 1e9:
            raise ValueError("no critical velocity: the bristle update is stable at every speed")
    lo = hi / 2.0 if hi > 1e-12 else 0.0
    return float(brentq(f, lo, hi, xtol=1e-15, rtol=1e-14))


def lugre_dissipative_on(model, vmax: float, n: int = 2001) -> bool:
    """Olsson's sufficient passivity condition sigma1 |v| < 4 g(v) on |v| <= vmax."""
    v = np.linspace(-vmax, vmax, n)
    return bool(np.all(model.params.sigma1 * np.abs(v) < 4.0 * model.g(v)))
