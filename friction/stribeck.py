"""Static Stribeck map: Coulomb + Stribeck + viscous friction, the baseline without state.

    F(v) = g(v) sgn(v) + sigma2 v + b                                    (seed 000 Eq. 5)
    g(v) = Fc + (Fs - Fc) exp(-|v/vs|^alpha)     (gaussian, seed 000 Eq. 4)
         = Fc + (Fs - Fc) / (1 + (v/vs)^2)       (lorentzian, seed 003 Eq. 3)
    sgn(0) = 0                                                           (seed 000 Eq. 6)

It is the steady-state curve of every LuGre-family law, used as a memory-free baseline
(identification of the static parameter group, diagnosis of "is the dynamics worth it").
Direction-dependent values (seeds 000 and 003): ``Fc_neg, Fs_neg, vs_neg, sigma2_neg`` are
used when v < 0; left ``None`` they equal the "+" values.

The law has no state (``state_names = ()``): ``simulate`` evaluates the map sample by
sample, so it is exact at any step size.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit, prange

from .base import FrictionModel
from .lugre import _g_fast, side_constants
from .shapes import SHAPES, DirectionalStribeck, DirectionalStribeckParams, stribeck_g

__all__ = ["StribeckParams", "StaticStribeck", "stribeck_force", "stribeck_run"]


@dataclass(frozen=True)
class StribeckParams(DirectionalStribeckParams):
    """Parameters of the static Stribeck map (defaults: those of the classic LuGre); the
    fields are :class:`friction.shapes.DirectionalStribeckParams`'s."""


_LAYOUT = ("sigma2", "sigma2_neg", "Fc", "Fc_neg", "Fs", "Fs_neg", "vs", "vs_neg", "alpha",
           "b", "shape")
S2P, S2N, FCP, FCN, FSP, FSN, VSP, VSN, ALPHA, B, SHAPE = range(len(_LAYOUT))


@njit(cache=True, inline="always")
def stribeck_force(v, th):
    """F(v) = g(v) sgn(v) + sigma2 v + b [N] for one sample, from a packed theta."""
    if v > 0.0:
        return stribeck_g(v, th[FCP], th[FSP], th[VSP], th[ALPHA], th[SHAPE]) \
            + th[S2P] * v + th[B]
    if v < 0.0:
        return -stribeck_g(v, th[FCN], th[FSN], th[VSN], th[ALPHA], th[SHAPE]) \
            + th[S2N] * v + th[B]
    return th[B]  # sgn(0) = 0 (seed 000 Eq. 6)


@njit(cache=True, nogil=True)
def stribeck_run(v, th, F):
    """F[k] = F(v[k]) for a packed theta, constants hoisted and the exp skipped where it
    cannot change g (see :func:`friction.lugre._g_fast`)."""
    alpha = th[ALPHA]
    shape = th[SHAPE]
    b = th[B]
    fcp, fsp, ivsp, cutp, _ = side_constants(th[FCP], th[FSP], th[VSP], 1.0)
    fcn, fsn, ivsn, cutn, _ = side_constants(th[FCN], th[FSN], th[VSN], 1.0)
    s2p, s2n = th[S2P], th[S2N]
    for k in range(v.size):
        vk = v[k]
        if vk > 0.0:
            g, _ = _g_fast(vk, fcp, fsp, ivsp, alpha, shape, cutp, 1.0, 1.0)
            F[k] = g + s2p * vk + b
        elif vk < 0.0:
            g, _ = _g_fast(vk, fcn, fsn, ivsn, alpha, shape, cutn, 1.0, 1.0)
            F[k] = -g + s2n * vk + b
        else:
            F[k] = b  # sgn(0) = 0 (seed 000 Eq. 6)


@njit(cache=True, nogil=True)
def _kernel(t, v, a, load, x, th, method, state0):
    F = np.empty(t.size)
    stribeck_run(v, th, F)
    return F, np.empty((t.size, 0))


@njit(cache=True, parallel=True)
def _population_kernel(t, v, a, load, x, Theta, method):
    npop = Theta.shape[0]
    F = np.empty((npop, t.size))
    for i in prange(npop):
        stribeck_run(v, Theta[i], F[i])
    return F


class StaticStribeck(DirectionalStribeck, FrictionModel):
    """Static Stribeck map (no state); see the module docstring for the equations.

    Examples
    --------
    >>> from friction import make_model
    >>> m = make_model("stribeck", Fc=1.0, Fs=1.5, vs=1e-3, sigma2=0.4)
    >>> float(m.steady_state([1e-2])[0])   # doctest: +ELLIPSIS
    1.004...
    """
    name = "stribeck"
    Params = StribeckParams
    state_names = ()
    theta_layout = _LAYOUT
    twins = {"Fc": "Fc_neg", "Fs": "Fs_neg", "vs": "vs_neg", "sigma2": "sigma2_neg"}

    _kernel = staticmethod(_kernel)
    _population_kernel = staticmethod(_population_kernel)

    def _pack(self, p: StribeckParams) -> np.ndarray:
        return np.array([p.sigma2, p.resolved("sigma2", -1), p.Fc, p.resolved("Fc", -1),
                         p.Fs, p.resolved("Fs", -1), p.vs, p.resolved("vs", -1), p.alpha,
                         p.b, SHAPES[p.shape]], dtype=np.float64)

    def steady_state(self, v, **inputs) -> np.ndarray:
        """F(v) = g(v) sgn(v) + sigma2 v + b [N] (the map itself)."""
        v = np.asarray(v, dtype=float)
        return self.g(v) * np.sign(v) + self.sigma2_of(v) * v + self.params.b

    def derivatives(self, state, v, **inputs) -> np.ndarray:
        """No state: an empty derivative vector."""
        return np.zeros(0)

    def force(self, state, v, **inputs) -> float:
        """Friction force [N] at velocity ``v`` [m/s] (``state`` is empty)."""
        return float(self.steady_state(float(v)))
