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

Levels scaled along the record (:meth:`LuGre.simulate_level`, :func:`lugre_level_run`): the
curve ``l(t) g(v)`` and the viscous term ``l(t) sigma2 v`` with a relative level ``l > 0``
given at the samples - a change of the friction levels *inside* the bristle dynamics (the
diagnosis's speed map of the Stribeck curve), advanced by the same exact update.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit, prange

from .base import METHODS, FrictionModel, FrictionParams, param
from .shapes import SHAPES, DirectionalStribeck, DirectionalStribeckParams, stribeck_g

__all__ = ["LuGreParams", "LuGre", "bristle_update", "lugre_run", "lugre_sensitivity_run",
           "lugre_normal_equations", "lugre_level_run"]


@dataclass(frozen=True)
class _BristleParams(FrictionParams):
    """The bristle fields of the classic LuGre, first in its field order."""
    sigma0: float = param(1e5, "N/m", "bristle stiffness", lower=0, lower_open=True,
                          upper=1e9, search=(1e3, 1e7), log=True)
    sigma1: float = param(300.0, "N.s/m", "micro-damping of the bristles", lower=0,
                          search=(0.0, 2e3))


@dataclass(frozen=True)
class LuGreParams(DirectionalStribeckParams, _BristleParams):
    """Parameters of the classic LuGre law (defaults: a small precision-stage contact):
    ``sigma0, sigma1``, then the Stribeck block of
    :class:`friction.shapes.DirectionalStribeckParams` (fields in that order)."""


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


@njit(cache=True, nogil=True)
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


@njit(cache=True, nogil=True)
def lugre_level_run(t, v, th, level, z0, F):
    """:func:`lugre_run` (exact update) with the law's friction levels scaled by ``level``
    [-] at every sample, *inside* the bristle dynamics; writes F[k] in place.

    The Stribeck curve is ``level g(v)`` (the bristle's steady deflection and its rate
    follow it) and the viscous term ``level sigma2 v``: a relative change of the levels
    along a signal the caller computes from the record (a map of the speed, a memory of
    the motion). Between samples the level is the mean of its two ends, as the velocity
    at the step's midpoint. ``level = 1`` everywhere is :func:`lugre_run` to rounding.

    Parameters
    ----------
    t, v : ndarray
        Time [s] and velocity [m/s].
    th : ndarray
        Packed LuGre parameters (:data:`_LAYOUT`).
    level : ndarray
        Relative level at the samples [-], > 0.
    z0 : float
        Initial bristle deflection [m].
    F : ndarray
        Output force [N].
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
        lk = level[k]
        if vk >= 0.0:
            g, cg = _g_fast(vk, fcp, fsp, ivsp, alpha, shape, cutp, s0, rp)
            s2 = s2p
        else:
            g, cg = _g_fast(vk, fcn, fsn, ivsn, alpha, shape, cutn, s0, rn)
            s2 = s2n
        zd = vk - cg / lk * abs(vk) * z
        F[k] = s0 * z + s1 * zd + lk * s2 * vk + b
        if k + 1 < n:
            h = t[k + 1] - t[k]
            vm = 0.5 * (vk + v[k + 1])
            lm = 0.5 * (lk + level[k + 1])
            if vm >= 0.0:
                gm, cgm = _g_fast(vm, fcp, fsp, ivsp, alpha, shape, cutp, s0, rp)
                zss = lm * gm * is0
            else:
                gm, cgm = _g_fast(vm, fcn, fsn, ivsn, alpha, shape, cutn, s0, rn)
                zss = -lm * gm * is0
            z = z + (z - zss) * _em1(h * cgm / lm * abs(vm))


@njit(cache=True, inline="always")
def _g_partials(v, Fc, Fs, ivs, alpha, shape, cut, ifc, need_alpha):
    """g(v) of one direction, 1/g, and the partial derivatives of g with respect to that
    direction's Fc, Fs, vs and the exponent alpha:
    ``(g, 1/g, dg/dFc, dg/dFs, dg/dvs, dg/dalpha)``.

    The value is :func:`_g_fast`'s. Beyond the cut-off ``cut`` (gaussian shape,
    :func:`_cutoff`) g is Fc exactly (``ifc`` = 1/Fc) and the other partials below
    2^-54 Fc (returned as 0); Fs = Fc has no cut-off (``cut`` infinite: dg/dFs is e^{-x}
    there). dg/dalpha (a logarithm) only where ``need_alpha``."""
    r = abs(v) * ivs
    d = Fs - Fc
    if shape == 1:
        q = 1.0 + r * r
        g = Fc + d / q
        L = 1.0 / q
        return g, 1.0 / g, 1.0 - L, L, 2.0 * d * r * r * L * L * ivs, 0.0
    if r == 0.0:
        g = Fc + d
        return g, 1.0 / g, 0.0, 1.0, 0.0, 0.0
    x = r * r if alpha == 2.0 else r ** alpha
    if x > cut:
        return Fc, ifc, 1.0, 0.0, 0.0, 0.0
    E = math.exp(-x)
    dE = d * E
    gal = -dE * x * math.log(r) if need_alpha else 0.0
    g = Fc + dE
    return g, 1.0 / g, 1.0 - E, E, dE * alpha * x * ivs, gal


@njit(cache=True, inline="always")
def _sens_cutoff(Fc, Fs):
    """:func:`_cutoff`, infinite where Fs = Fc (see :func:`_g_partials`)."""
    if Fs == Fc:
        return math.inf
    return _cutoff(Fc, Fs)


#: samples per block of the normal-equation sums of :func:`_sensitivity_pass`
_NE_BLOCK = 64


#: floating-point freedom of the sensitivity kernels: fused multiply-adds only (no
#: reassociation: see :func:`_dot4`; no assumption about NaN or infinities: a parameter set
#: that overflows must still give a non-finite cost)
_SENS_MATH = {"contract"}


@njit(cache=True, inline="always", fastmath=_SENS_MATH)
def _dot4(a, b, m):
    """``sum_k a[k] b[k]`` over ``k < m`` in four interleaved partial sums, added in a
    fixed order: the compiler may vectorise the four lanes without reassociating, so the
    sum is the same bits however the kernel was compiled (fresh or from numba's cache,
    inlined into one caller or another). With ``fastmath`` reassociation the vectoriser's
    choice depended on the compile: an identification run in a fresh process differed
    from a cached one in the last bits of ``J^T J``, and a diagnosis downstream flipped."""
    a0 = 0.0
    a1 = 0.0
    a2 = 0.0
    a3 = 0.0
    k = 0
    while k + 4 <= m:
        a0 += a[k] * b[k]
        a1 += a[k + 1] * b[k + 1]
        a2 += a[k + 2] * b[k + 2]
        a3 += a[k + 3] * b[k + 3]
        k += 4
    while k < m:
        a0 += a[k] * b[k]
        k += 1
    return (a0 + a1) + (a2 + a3)


@njit(cache=True, inline="always", fastmath=_SENS_MATH)
def _flush_normal(R, rb, m, D, H, G):
    """Add the block's ``R[:, :m]^T R[:, :m]`` (lower triangle) to ``H`` and
    ``R[:, :m] rb[:m]`` to ``G`` (contiguous dot products, :func:`_dot4`)."""
    for i in range(D):
        Ri = R[i]
        G[i] += _dot4(Ri, rb, m)
        for j in range(i + 1):
            H[i, j] += _dot4(Ri, R[j], m)


@njit(cache=True, nogil=True, fastmath=_SENS_MATH)
def _sensitivity_pass(t, v, th, method, z0, cols, F, J, Fm, scale, H, G):
    """One pass of the LuGre force with its forward sensitivities; see
    :func:`lugre_sensitivity_run` and :func:`lugre_normal_equations`.

    Stores ``F`` and ``J`` where they have ``N`` rows; accumulates the residual
    ``r = (F - Fm) scale`` into ``H += (scale J)^T (scale J)``, ``G += (scale J)^T r`` and
    the returned ``sum r^2`` where ``Fm`` has ``N`` entries.

    The sensitivity ``dz[j] = dz/dp_j`` of the bristle deflection to column ``j``'s
    parameter is propagated with the state: every column through the terms in ``dz``
    (the force's ``s0 - s1 |v| sigma0/g`` and the update's decay ``e^{-s}``), and the few
    columns a sample's partial derivatives touch (the Stribeck parameters of its direction,
    sigma0, sigma1, the direction's sigma2, b) through their own terms.
    """
    n = t.size
    D = J.shape[1] if J.shape[0] == n else G.size
    store = J.shape[0] == n
    accumulate = Fm.size == n
    dz = np.zeros(D)
    row = np.empty(D)
    R = np.empty((D, _NE_BLOCK))  # a block of scaled Jacobian rows, one row per column
    rb = np.empty(_NE_BLOCK)
    m = 0
    s0 = th[S0]
    s1 = th[S1]
    b = th[B]
    is0 = 1.0 / s0
    alpha = th[ALPHA]
    shape = th[SHAPE]
    ivsp = 1.0 / th[VSP]
    ivsn = 1.0 / th[VSN]
    c_s0 = cols[S0]
    c_s1 = cols[S1]
    c_al = cols[ALPHA]
    c_b = cols[B]
    need_al = c_al >= 0
    cutp = _sens_cutoff(th[FCP], th[FSP])
    cutn = _sens_cutoff(th[FCN], th[FSN])
    ifcp = 1.0 / th[FCP]
    ifcn = 1.0 / th[FCN]
    sse = 0.0
    z = z0
    for k in range(n):
        vk = v[k]
        av = abs(vk)
        if vk >= 0.0:
            side = 0
            g, ig, gfc, gfs, gvs, gal = _g_partials(vk, th[FCP], th[FSP], ivsp, alpha,
                                                    shape, cutp, ifcp, need_al)
        else:
            side = 1
            g, ig, gfc, gfs, gvs, gal = _g_partials(vk, th[FCN], th[FSN], ivsn, alpha,
                                                    shape, cutn, ifcn, need_al)
        cg = s0 * ig
        zd = vk - cg * av * z
        f = s0 * z + s1 * zd + th[S2P + side] * vk + b
        # dF = A dz + Bg dg + direct terms
        A = s0 - s1 * av * cg
        avz = av * z
        Bg = s1 * avz * cg * ig
        for j in range(D):
            row[j] = A * dz[j]
        c = cols[FCP + side]
        if c >= 0:
            row[c] += Bg * gfc
        c = cols[FSP + side]
        if c >= 0:
            row[c] += Bg * gfs
        c = cols[VSP + side]
        if c >= 0:
            row[c] += Bg * gvs
        if c_al >= 0:
            row[c_al] += Bg * gal
        if c_s0 >= 0:
            row[c_s0] += z - s1 * avz * ig
        if c_s1 >= 0:
            row[c_s1] += zd
        c = cols[S2P + side]
        if c >= 0:
            row[c] += vk
        if c_b >= 0:
            row[c_b] += 1.0
        if store:
            F[k] = f
            for j in range(D):
                J[k, j] = row[j]
        if accumulate:
            r = (f - Fm[k]) * scale
            sse += r * r
            rb[m] = r
            for j in range(D):
                R[j, m] = row[j] * scale
            m += 1
            if m == _NE_BLOCK:
                _flush_normal(R, rb, m, D, H, G)
                m = 0
        if k + 1 < n:
            h = t[k + 1] - t[k]
            if method == 1:
                # z+ = z + h zd: dz+ = (1 - h |v| s0/g) dz + h |v| z s0/g^2 dg - h |v| z/g [s0]
                K = 1.0 - h * av * cg
                for j in range(D):
                    dz[j] *= K
                Bz = h * avz * cg * ig
                c = cols[FCP + side]
                if c >= 0:
                    dz[c] += Bz * gfc
                c = cols[FSP + side]
                if c >= 0:
                    dz[c] += Bz * gfs
                c = cols[VSP + side]
                if c >= 0:
                    dz[c] += Bz * gvs
                if c_al >= 0:
                    dz[c_al] += Bz * gal
                if c_s0 >= 0:
                    dz[c_s0] -= h * avz * ig
                z = z + h * zd
                continue
            vm = 0.5 * (vk + v[k + 1])
            avm = abs(vm)
            if vm >= 0.0:
                sm = 0
                gm, igm, mfc, mfs, mvs, mal = _g_partials(vm, th[FCP], th[FSP], ivsp,
                                                          alpha, shape, cutp, ifcp, need_al)
                sg = 1.0
            else:
                sm = 1
                gm, igm, mfc, mfs, mvs, mal = _g_partials(vm, th[FCN], th[FSN], ivsn,
                                                          alpha, shape, cutn, ifcn, need_al)
                sg = -1.0
            zss = sg * gm * is0
            hv = h * avm
            em = _em1(hv * (s0 * igm))
            e = em + 1.0
            dev = z - zss
            # z+ = z + (z - zss) em(s), s = h s0 |vm| / gm, zss = sgn gm / s0:
            # dz+ = e dz - em dzss - (z - zss) e ds
            for j in range(D):
                dz[j] *= e
            dve = dev * e * hv * igm
            P = -em * sg * is0 + dve * s0 * igm
            c = cols[FCP + sm]
            if c >= 0:
                dz[c] += P * mfc
            c = cols[FSP + sm]
            if c >= 0:
                dz[c] += P * mfs
            c = cols[VSP + sm]
            if c >= 0:
                dz[c] += P * mvs
            if c_al >= 0:
                dz[c_al] += P * mal
            if c_s0 >= 0:
                dz[c_s0] += em * sg * gm * is0 * is0 - dve
            z = z + dev * em
    if accumulate:
        if m > 0:
            _flush_normal(R, rb, m, D, H, G)
        for i in range(D):
            for j in range(i):
                H[j, i] = H[i, j]
    return sse


@njit(cache=True, nogil=True)
def lugre_sensitivity_run(t, v, th, method, z0, cols, F, J):
    """Forward sensitivities of the classic LuGre force along (t, v): the force F[k] and
    its derivatives with respect to chosen parameters, integrated with the bristle state
    in one pass (the update of :func:`lugre_run`, differentiated exactly).

    Parameters
    ----------
    t, v : ndarray, shape (N,)
        Time [s] and velocity [m/s].
    th : ndarray
        Packed parameters (:data:`_LAYOUT`).
    method : int
        0 exact exponential bristle update, 1 explicit Euler.
    z0 : float
        Initial bristle deflection [m] (held fixed: its sensitivity is zero).
    cols : ndarray of int64, shape (len(_LAYOUT),)
        Column of ``J`` of each packed parameter, -1 for none; a symmetric parameter maps
        both of its direction entries to one column (:meth:`LuGre.jacobian_columns`).
    F : ndarray, shape (N,)
        Written: the force [N] (equal to :func:`lugre_run`'s to rounding).
    J : ndarray, shape (N, D)
        Written: ``J[k, j] = dF[k]/dp_j`` [N per unit of the parameter].
    """
    _sensitivity_pass(t, v, th, method, z0, cols, F, J, np.empty(0), 1.0,
                      np.empty((0, 0)), np.empty(J.shape[1]))


@njit(cache=True, nogil=True)
def lugre_normal_equations(t, v, th, method, z0, cols, Fm, scale, H, G):
    """Gauss-Newton normal equations of the scaled residual ``r = (F - Fm) scale`` in one
    sensitivity pass, without storing the ``N x D`` Jacobian: adds ``(scale J)^T (scale J)``
    to ``H`` (D x D) and ``(scale J)^T r`` to ``G`` (D), returns ``sum r^2``. Arguments as
    :func:`lugre_sensitivity_run`; ``Fm`` the measured force [N]."""
    return _sensitivity_pass(t, v, th, method, z0, cols, np.empty(0), np.empty((0, G.size)),
                             Fm, scale, H, G)


@njit(cache=True, nogil=True)
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


#: samples per block of :func:`_population_sse_kernel` (the force of one block in memory)
_SSE_BLOCK = 4096


@njit(cache=True, nogil=True)
def _row_sse(t, v, th, method, Fm):
    """``sum_k (F[k] - Fm[k])^2`` of one parameter row without its force record:
    :func:`lugre_run` block by block, the state carried across (the same forces)."""
    n = t.size
    F = np.empty(_SSE_BLOCK + 1)
    Z = np.empty(_SSE_BLOCK + 1)
    z = 0.0
    acc = 0.0
    k0 = 0
    while True:
        k1 = min(k0 + _SSE_BLOCK, n - 1)
        m = k1 - k0 + 1
        lugre_run(t[k0:k1 + 1], v[k0:k1 + 1], th, method, z, F[:m], Z[:m])
        last = m if k1 == n - 1 else m - 1  # the block's last sample starts the next
        for k in range(last):
            d = F[k] - Fm[k0 + k]
            acc += d * d
        if k1 == n - 1:
            break
        z = Z[m - 1]
        k0 = k1
    return acc


@njit(cache=True, parallel=True)
def _population_sse_kernel(t, v, Theta, method, Fm):
    """:func:`_row_sse` of every parameter row, in parallel over the rows (no
    ``npop x N`` force matrix)."""
    npop = Theta.shape[0]
    out = np.empty(npop)
    for i in prange(npop):
        out[i] = _row_sse(t, v, Theta[i], method, Fm)
    return out


@njit(cache=True, nogil=True)
def _serial_sse_kernel(t, v, Theta, method, Fm):
    """:func:`_population_sse_kernel` row after row in this thread
    (:data:`friction.base.SERIAL_POPULATIONS`)."""
    out = np.empty(Theta.shape[0])
    for i in range(Theta.shape[0]):
        out[i] = _row_sse(t, v, Theta[i], method, Fm)
    return out


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
    #: forward-sensitivity kernel (identification's analytic Jacobian; see
    #: :meth:`force_jacobian`)
    _sensitivity_kernel = staticmethod(lugre_sensitivity_run)
    #: the same pass accumulating Gauss-Newton normal equations (no N x D Jacobian)
    _normal_equations_kernel = staticmethod(lugre_normal_equations)
    #: population sums of squared force errors without the population's forces
    _population_sse_kernel = staticmethod(_population_sse_kernel)
    #: the same sums row after row (:data:`friction.base.SERIAL_POPULATIONS`)
    _serial_sse_kernel = staticmethod(_serial_sse_kernel)

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

    # -- forward sensitivities (identification's analytic Jacobian) ----------------------
    def jacobian_columns(self, names) -> np.ndarray:
        """The ``cols`` argument of :func:`lugre_sensitivity_run` for the parameters
        ``names`` (the columns of the Jacobian): a symmetric parameter (its ``_neg`` twin
        left None and not named) also owns its twin's entry, as
        :meth:`friction.base.FrictionModel.population_theta` sets both.

        Parameters
        ----------
        names : sequence of str
            Parameter names (``theta_layout`` names, direction twins included).
        """
        layout = {n: i for i, n in enumerate(self.theta_layout)}
        cols = np.full(len(self.theta_layout), -1, dtype=np.int64)
        for j, n in enumerate(names):
            if n not in layout or n == "shape":
                raise KeyError(f"{self.name} has no packed parameter {n!r}; "
                               f"choose from {list(self.theta_layout[:-1])}")
            cols[layout[n]] = j
            twin = self.twins.get(n)
            if twin is not None and getattr(self.params, twin, None) is None \
                    and twin not in names:
                cols[layout[twin]] = j
        return cols

    def force_jacobian(self, t, v, names, *, method: str = "exact", state0=None):
        """Friction force along a prescribed motion and its Jacobian with respect to the
        parameters ``names``, from forward sensitivities of the bristle state integrated
        with it (one pass; no finite differences).

        Parameters
        ----------
        t, v : array_like, shape (N,)
            Time [s] and velocity [m/s].
        names : sequence of str
            Parameters to differentiate with respect to (e.g. ``["sigma0", "Fc"]``); a
            symmetric parameter (``Fc`` with ``Fc_neg`` None) acts on both directions.
        method : {"exact", "euler"}
            Bristle update, as in :meth:`simulate`.
        state0 : array_like, optional
            Initial bristle deflection (default at rest); it is held fixed.

        Returns
        -------
        F : ndarray, shape (N,)
            Force [N] (as :meth:`simulate` gives it, to rounding).
        J : ndarray, shape (N, len(names))
            ``dF/d(name)`` [N per unit of each parameter].
        """
        if method not in METHODS:
            raise ValueError(f"method must be one of {sorted(METHODS)}, got {method!r}")
        t, v, _, _, _ = self._inputs(t, v)
        names = list(names)
        z0 = 0.0 if state0 is None else float(np.asarray(state0, float).ravel()[0])
        F = np.empty(t.size)
        J = np.empty((t.size, len(names)))
        lugre_sensitivity_run(t, v, self.theta, METHODS[method], z0,
                              self.jacobian_columns(names), F, J)
        return F, J

    def simulate_level(self, t, v, level, *, state0=None) -> np.ndarray:
        """Friction force along a prescribed motion with the friction levels scaled by
        ``level`` inside the bristle dynamics (:func:`lugre_level_run`, exact update).

        Parameters
        ----------
        t, v : array_like, shape (N,)
            Time [s] and velocity [m/s].
        level : array_like, shape (N,)
            Relative level of the Stribeck curve and the viscous term at the samples [-],
            finite and > 0.
        state0 : array_like, optional
            Initial bristle deflection [m] (default at rest).

        Returns
        -------
        ndarray, shape (N,)
            Force [N].
        """
        t, v, _, _, _ = self._inputs(t, v)
        lev = np.ascontiguousarray(level, dtype=float)
        if lev.shape != t.shape:
            raise ValueError(f"level has {lev.size} samples, the motion {t.size}")
        if not np.all(np.isfinite(lev) & (lev > 0.0)):
            k = int(np.flatnonzero(~(np.isfinite(lev) & (lev > 0.0)))[0])
            raise ValueError(f"level[{k}] = {float(lev[k])!r} is out of bounds: must be finite and "
                             f"> 0 [-]")
        z0 = 0.0 if state0 is None else float(np.asarray(state0, float).ravel()[0])
        F = np.empty(t.size)
        lugre_level_run(t, v, self.theta, lev, z0, F)
        return F

    def z_max(self) -> float:
        """Bound of the bristle deflection: max over v of g(v)/sigma0 [m] (z0 = 0 start)."""
        p = self.params
        levels = [p.Fc, p.Fs, p.resolved("Fc", -1), p.resolved("Fs", -1)]
        return max(levels) / p.sigma0
