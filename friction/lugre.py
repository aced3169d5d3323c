"""Classic LuGre friction (Canudas de Wit et al. 1995), as written by seeds 000, 001, 003, 004.

    dz/dt = v - sigma0 |v| / g(v) * z                                   (000 Eq. 2)
    F     = sigma0 z + sigma1 dz/dt + sigma2 v + b                      (000 Eq. 3, 003 Eq. 4)
    g(v)  = Stribeck curve, gaussian with exponent alpha or lorentzian  (000 Eq. 4, 003 Eq. 3)
    F_ss  = g(v) sgn(v) + sigma2 v + b                                  (000 Eq. 5, 003 Eq. 6)

Direction-dependent values (seeds 000 and 003): ``Fc_neg, Fs_neg, vs_neg, sigma2_neg`` are
used when v < 0; left ``None`` they equal the "+" values.

Numerics: over a step of length h the bristle equation is linear in z,
dz/dt = v - a z with a = sigma0 |v| / g(v) >= 0, so the exact solution with the coefficients
frozen at the step's midpoint velocity is

    z(t+h) = z e^{-a h} + v h phi(a h),     phi(s) = (1 - e^{-s}) / s,

which is unconditionally stable (|e^{-a h}| <= 1 for any h and sigma0) and second-order
accurate for sampled motion. Explicit Euler ``z += h (v - a z)`` is kept as ``method="euler"``:
it oscillates once h a > 1 and diverges once h a > 2 (seed 000 Eqs. 27-30).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numba import njit, prange

from ._validation import ParameterError
from .base import FrictionModel, FrictionParams, param
from .shapes import SHAPES, DirectionalStribeck, stribeck_g

__all__ = ["LuGreParams", "LuGre", "bristle_update", "lugre_run"]


@dataclass(frozen=True)
class LuGreParams(FrictionParams):
    """Parameters of the classic LuGre law (defaults: a small precision-stage contact)."""
    #: option fields -> their choices and the integer codes the kernels use
    OPTIONS: ClassVar[dict] = {"shape": SHAPES}
    sigma0: float = param(1e5, "N/m", "bristle stiffness", lower=0, lower_open=True,
                          upper=1e9, search=(1e3, 1e7), log=True)
    sigma1: float = param(300.0, "N.s/m", "micro-damping of the bristles", lower=0,
                          search=(0.0, 2e3))
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


# packed layout: index constants are used inside the kernels
_LAYOUT = ("sigma0", "sigma1", "sigma2", "sigma2_neg", "Fc", "Fc_neg", "Fs", "Fs_neg",
           "vs", "vs_neg", "alpha", "b", "shape")
S0, S1, S2P, S2N, FCP, FCN, FSP, FSN, VSP, VSN, ALPHA, B, SHAPE = range(len(_LAYOUT))


@njit(cache=True, inline="always")
def _g_dir(v, th):
    """g(v) and sigma2 of the direction of v, from a packed theta."""
    if v >= 0.0:
        return stribeck_g(v, th[FCP], th[FSP], th[VSP], th[ALPHA], th[SHAPE]), th[S2P]
    return stribeck_g(v, th[FCN], th[FSN], th[VSN], th[ALPHA], th[SHAPE]), th[S2N]


@njit(cache=True, inline="always")
def bristle_update(z, v, a, h, method):
    """Advance dz/dt = v - a z over h: exact exponential (method 0) or explicit Euler (1)."""
    if method == 1:
        return z + h * (v - a * z)
    s = a * h
    if s < 1e-8:
        return z + h * (v - a * z)  # phi(s) = 1 - s/2 + ..., e^{-s} = 1 - s: Euler is exact to O(s^2)
    e = math.exp(-s)
    return z * e + v * (1.0 - e) / a


@njit(cache=True, inline="always")
def _cutoff(Fc, Fs):
    """x = |v/vs|^alpha beyond which (Fs - Fc) e^{-x} < Fc 2^-54: g rounds to Fc exactly."""
    d = abs(Fs - Fc)
    if d == 0.0:
        return -1.0  # no Stribeck bump: g = Fc at every speed
    return 38.5 + math.log(d / Fc)  # 54 ln 2 = 37.43, plus margin


@njit(cache=True, inline="always")
def _g_fast(v, Fc, Fs, ivs, alpha, shape, cut, s0, s0_fc):
    """(g(v), sigma0/g(v)) as :func:`friction.shapes.stribeck_g`, with 1/vs and sigma0/Fc
    given; exp and division are skipped where they cannot change the result (high speed,
    the common sliding case)."""
    r = abs(v) * ivs
    if shape == 1:
        g = Fc + (Fs - Fc) / (1.0 + r * r)
        return g, s0 / g
    x = r * r if alpha == 2.0 else r ** alpha
    if x > cut:
        return Fc, s0_fc
    g = Fc + (Fs - Fc) * math.exp(-x)
    return g, s0 / g


@njit(cache=True, inline="always")
def side_constants(Fc, Fs, vs, s0):
    """Loop constants of one direction for :func:`_g_fast`: (Fc, Fs, 1/vs, cut-off,
    sigma0/Fc); hoisted out of the sample loops of every LuGre-family kernel."""
    return Fc, Fs, 1.0 / vs, _cutoff(Fc, Fs), s0 / Fc


@njit(cache=True, inline="always")
def _em1(s):
    """e^{-s} - 1 for s >= 0: expm1 only where the plain exp would lose digits."""
    if s > 40.0:
        return -1.0  # e^{-s} < 5e-18: below rounding of 1
    if s > 0.5:
        return math.exp(-s) - 1.0
    return math.expm1(-s)


@njit(cache=True)
def lugre_run(t, v, th, method, z0, F, Z):
    """Simulate one parameter set along (t, v); writes F[k] and Z[k] in place.

    The exact update is written as z+ = z + (z - z_ss) (e^{-s} - 1), with
    s = h sigma0 |v_m| / g and z_ss = sgn(v_m) g / sigma0 (the same as
    :func:`bristle_update`, without dividing by s and accurate for small s).
    """
    n = t.size
    s0 = th[S0]
    s1 = th[S1]
    b = th[B]
    is0 = 1.0 / s0
    alpha = th[ALPHA]
    shape = th[SHAPE]
    fcp, fsp, ivsp, cutp, rp = side_constants(th[FCP], th[FSP], th[VSP], s0)
    fcn, fsn, ivsn, cutn, rn = side_constants(th[FCN], th[FSN], th[VSN], s0)
    s2p, s2n = th[S2P], th[S2N]
    z = z0
    for k in range(n):
        vk = v[k]
        if vk >= 0.0:
            g, cg = _g_fast(vk, fcp, fsp, ivsp, alpha, shape, cutp, s0, rp)
            s2 = s2p
        else:
            g, cg = _g_fast(vk, fcn, fsn, ivsn, alpha, shape, cutn, s0, rn)
            s2 = s2n
        zd = vk - cg * abs(vk) * z
        F[k] = s0 * z + s1 * zd + s2 * vk + b
        Z[k] = z
        if k + 1 < n:
            h = t[k + 1] - t[k]
            if method == 1:
                z = z + h * zd
            else:
                vm = 0.5 * (vk + v[k + 1])
                if vm >= 0.0:
                    gm, cgm = _g_fast(vm, fcp, fsp, ivsp, alpha, shape, cutp, s0, rp)
                    zss = gm * is0
                else:
                    gm, cgm = _g_fast(vm, fcn, fsn, ivsn, alpha, shape, cutn, s0, rn)
                    zss = -gm * is0
                z = z + (z - zss) * _em1(h * cgm * abs(vm))


@njit(cache=True)
def _kernel(t, v, a, load, x, th, method, state0):
    F = np.empty(t.size)
    Z = np.empty(t.size)  # contiguous 1-D for the loop; the (N, 1) state view is free
    lugre_run(t, v, th, method, state0[0], F, Z)
    return F, Z.reshape(t.size, 1)


@njit(cache=True, parallel=True)
def _population_kernel(t, v, a, load, x, Theta, method):
    npop = Theta.shape[0]
    F = np.empty((npop, t.size))
    for i in prange(npop):
        Z = np.empty(t.size)
        lugre_run(t, v, Theta[i], method, 0.0, F[i], Z)
    return F


class LuGre(DirectionalStribeck, FrictionModel):
    """Classic LuGre law; see the module docstring for the equations.

    Examples
    --------
    >>> from friction import make_model
    >>> m = make_model("lugre", sigma0=1e5, sigma1=300.0, sigma2=0.4, Fc=1.0, Fs=1.5, vs=1e-3)
    >>> float(m.steady_state([1e-2])[0])   # doctest: +ELLIPSIS
    1.004...
    """
    name = "lugre"
    Params = LuGreParams
    state_names = ("z",)
    theta_layout = _LAYOUT
    twins = {"Fc": "Fc_neg", "Fs": "Fs_neg", "vs": "vs_neg", "sigma2": "sigma2_neg"}

    _kernel = staticmethod(_kernel)
    _population_kernel = staticmethod(_population_kernel)

    def _pack(self, p: LuGreParams) -> np.ndarray:
        return np.array([p.sigma0, p.sigma1, p.sigma2, p.resolved("sigma2", -1),
                         p.Fc, p.resolved("Fc", -1), p.Fs, p.resolved("Fs", -1),
                         p.vs, p.resolved("vs", -1), p.alpha, p.b, SHAPES[p.shape]],
                        dtype=np.float64)

    # -- analytic pieces ----------------------------------------------------------------
    def steady_state(self, v, **inputs) -> np.ndarray:
        """Steady-state (Stribeck) force F_ss(v) = g(v) sgn(v) + sigma2 v + b [N]."""
        v = np.asarray(v, dtype=float)
        return self.g(v) * np.sign(v) + self.sigma2_of(v) * v + self.params.b

    def derivatives(self, state, v, **inputs) -> np.ndarray:
        z = state[0]
        g = float(self.g(v))
        return np.array([v - self.params.sigma0 * abs(v) / g * z])

    def force(self, state, v, **inputs) -> float:
        p = self.params
        zd = self.derivatives(state, v)[0]
        return p.sigma0 * state[0] + p.sigma1 * zd + float(self.sigma2_of(v)) * v + p.b

    def z_max(self) -> float:
        """Bound of the bristle deflection: max over v of g(v)/sigma0 [m] (z0 = 0 start)."""
        p = self.params
        levels = [p.Fc, p.Fs, p.resolved("Fc", -1), p.resolved("Fs", -1)]
        return max(levels) / p.sigma0
