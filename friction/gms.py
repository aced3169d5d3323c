"""Generalized Maxwell-slip (GMS) friction: presliding hysteresis with nonlocal memory.

The contact is N = 4 elementary slip-blocks in parallel (after Al-Bender, Lampaert and
Swevers, IEEE Trans. Autom. Control 50 (2005) 1883, written here from the model's
description). Block i is tied to the moving body by a spring of stiffness k_i; its
deflection z_i [m] carries the force F_i = k_i z_i. The block can carry at most its share
of the Stribeck curve, w_i g(v) (geometric shares summing to 1, ratio ``tilt`` of the
softest block's to the stiffest's; ``tilt`` = 1: w_i = 1/N), i.e. a deflection

    d_i(v) = w_i g(v) / k_i,      g(v) = Fc + (Fs - Fc) exp(-|v/vs|^alpha)   (or lorentzian).

Each block either sticks or slips, and it does whichever is slower. Sticking, it moves
with the body: its force grows at the elastic rate k_i |v|. Slipping, its force is attracted
to its share of the Stribeck curve at the attraction rate C [N/s]:
dF_i/dt = C (w_i s - F_i / g(v)), s = sgn(v). With u_i = s z_i (the deflection in the
direction of motion) and lam = C / g(v) [1/s]:

    du_i/dt = min(|v|, lam (d_i(v) - u_i)),      dz_i/dt = s du_i/dt   (0 at v = 0).

So a block sticks while it is far below its saturation (and after every reversal, where
u_i <= 0), starts slipping once the attraction is the slower rate, at
u_i = d_i - |v| / lam, just below its break-away deflection, and then settles on d_i;
beyond d_i (the curve fell under it) it relaxes down at the rate lam. The friction force is

    F = sum_i (k_i z_i + sigma1 (k_i / sigma0) dz_i/dt) + sigma2 v + b.

The second term is the blocks' micro-damping (the published GMS gives each element a
damping of its own; here it is proportional to the element's stiffness, so ``sigma1`` is
LuGre's bristle damping: right after a reversal, every block sticking, it adds
sigma1 v, and it vanishes once the blocks slip at a steady speed). It is an output term:
the deflections' equation does not depend on it.

At a constant speed every block ends at d_i(v) and F = g(v) sgn(v) + sigma2 v + b: the
Stribeck curve. The slipping blocks follow a changing curve with the lag g/C both when
speeding up (friction above the curve) and when slowing down (below it): the frictional
lag. Slow presliding (|v| g / C << d_i) makes every block an ideal elastoplastic element
(stiffness k_i, yield force w_i g): the presliding force is rate-independent and has the
nonlocal memory of a Maxwell-slip model: an inner loop closes where it started and the
motion then continues on the branch it left (return-point memory and wiping-out), and a
branch started at a reversal (x_r, F_r) follows Masing's rule F - F_r = 2 F_v((x - x_r)/2),
F_v the virgin curve.

Compact parametrisation: the stiffnesses are geometric, k_i = sigma0 c_i / sum(c) with
c_i = spread^(-(i-1)/(N-1)), so ``sigma0`` is the stiffness right after a reversal (every
block sticking; LuGre's sigma0) and ``spread`` the ratio of the stiffest to the softest
block: 1 makes the four blocks one elastoplastic element (a sharp corner at F = g), a large
spread a gradual presliding curve. The blocks break away at the deflections d_i, from
g / (N sigma0) (the stiffest block at ``spread`` = 1) up to the presliding distance
:meth:`GMS.presliding_distance`.

Inputs: the velocity only (``extra_inputs`` is empty). As a candidate: ``sigma0``,
``spread`` and ``C`` describe the presliding and the lag; ``Fc, Fs, vs, alpha, sigma2, b``
the steady-state curve (:meth:`GMS.steady_state`), shared with the LuGre law.

Difference from the published GMS: there a block sticks until its force reaches w_i g
exactly and then slips until the velocity reverses; the mode is a memory of its own. Here
the mode is a function of the state (the slower of the two rates), which the
continuous-time reference and a Model Exchange FMU need (their states are the four
deflections, no mode flags), and it makes the state equation continuous (Lipschitz in z),
so a stiff integrator follows it. The two agree except that a block starts slipping a
deflection |v| g / C before its break-away: the presliding corners are rounded by that
much (vanishing for slow motion or a fast attraction), and after a reversal faster than
2 C d_i / g a block reloads at the attraction rate rather than elastically.

Numerics (``method="exact"``): a step whose velocity changes sign is cut at the reversal
(:func:`friction.steps.split_step`); over each piece the velocity is frozen at the
piece's midpoint value (exact for the travel of a linearly interpolated velocity) and each
block's equation is solved exactly: a translation at |v_p| until the switch
u* = d_i - |v_p| / lam, then u = d_i - (|v_p| / lam) e^{-lam (T - tau)}; from beyond the
switch u = d_i + (u - d_i) e^{-lam T}. Every update is a translation clipped by a
contraction, stable at any step and stiffness. Explicit Euler of the same equations is
``method="euler"`` (it overshoots the break-away and oscillates once h C / g > 2).

Bristle elements (``element="bristle"``, :data:`ELEMENTS`): each element is a LuGre bristle
instead, du_i/dt = |v| (1 - u_i / d_i), with the same stiffnesses, shares, damping and
curve (``C`` unused). Its presliding from rest is a sum of exponentials, sum_i k_i d_i
(1 - e^{-x / d_i}); right after a reversal a bristle moves at up to twice the body's speed
(LuGre's), where a sticking block moves with it. Four equal bristles (``spread`` = ``tilt``
= 1) are the LuGre law; the exact update over a piece is LuGre's exponential,
u = d_i + (u - d_i) e^{-|v_p| T / d_i}.

Beside elements (``element="beside"``): the contact's own LuGre bristle (stiffness
``sigma0``, damping ``sigma1``, share 1 - ``share`` of the curve) and three slip-blocks
beside it (stiffnesses geometric summing to ``sigma_b`` with the ratio ``spread``, shares
geometric summing to ``share`` with the ratio ``tilt``, undamped, attracted at ``C``): a
seal, wiper, cable or second contact in parallel with the sliding one, whose presliding
spans another scale than the contact's bristle. Four geometric elements cannot draw that:
one stiff element with most of the level and a tail of soft ones, decades apart. At
``share`` = 0 the law is the LuGre law (the blocks carry nothing). The force is
F = sigma0 z_1 + sigma1 dz_1/dt + sum_{i>1} k_i z_i + sigma2 v + b.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numba import njit, prange

from ._validation import ParameterError
from .base import FrictionModel, FrictionParams, param
from .lugre import _em1
from .shapes import SHAPES, stribeck_g, stribeck_g_np
from .steps import split_step

__all__ = ["GMSParams", "GMS", "N_ELEMENTS", "ELEMENTS", "gms_run", "element_stiffness"]

#: number of slip-blocks (fixed: a native FMU holds at most four continuous states)
N_ELEMENTS = 4
#: what each element is: a Maxwell-slip block (``slip``: sticks, then slips attracted to
#: its share of the curve at the rate C) or a LuGre bristle (``bristle``: dz/dt = v -
#: |v| z / d, d its break-away deflection; C unused). Four equal bristles (spread and tilt
#: 1) are exactly the LuGre law, so a base whose damped bristle carries its reversals
#: (sigma1 dz/dt, up to 2 sigma1 |v| right after one, where a sticking block gives sigma1
#: |v|) is nested: a presliding beside such a contact is reachable from it. ``beside``: the
#: contact's own LuGre bristle (stiffness ``sigma0``, damping ``sigma1``, share 1 -
#: ``share`` of the curve) and, beside it, three slip-blocks (total stiffness ``sigma_b``,
#: ratio ``spread``, shares ``share`` split by ``tilt``): a seal, wiper or second contact
#: whose presliding spans another scale than the contact's (at ``share`` 0 the LuGre law)
ELEMENTS = {"slip": 0, "bristle": 1, "beside": 2}


@dataclass(frozen=True)
class GMSParams(FrictionParams):
    """Parameters of the GMS law (defaults: a small precision-stage contact like LuGre's)."""
    OPTIONS: ClassVar[dict] = {"shape": SHAPES, "element": ELEMENTS}
    sigma0: float = param(1e5, "N/m", "total stiffness of the slip-blocks, the presliding "
                          "stiffness right after a reversal", lower=0, lower_open=True,
                          upper=1e9, search=(1e3, 1e7), log=True)
    spread: float = param(10.0, "1", "stiffness ratio of the stiffest to the softest "
                          "slip-block (geometric; 1: one elastoplastic element)", lower=1.0,
                          upper=1e6, search=(1.0, 1e5), log=True)
    C: float = param(1e4, "N/s", "attraction rate of a slipping block's force to its share "
                     "of the Stribeck curve (frictional lag g/C)", lower=0, lower_open=True,
                     upper=1e12, search=(1.0, 1e6), log=True)
    sigma2: float = param(0.4, "N.s/m", "viscous coefficient", lower=0, search=(0.0, 50.0))
    Fc: float = param(1.0, "N", "Coulomb friction level", lower=0, lower_open=True,
                      search=(1e-2, 50.0))
    Fs: float = param(1.5, "N", "static (break-away) friction level", lower=0,
                      lower_open=True, search=(1e-2, 60.0))
    vs: float = param(1e-3, "m/s", "Stribeck velocity", lower=0, lower_open=True,
                      search=(1e-5, 0.1), log=True)
    alpha: float = param(2.0, "1", "Stribeck shape exponent (gaussian shape)", lower=0,
                         lower_open=True, upper=10, search=(0.3, 4.0))
    b: float = param(0.0, "N", "constant force offset", search=(-5.0, 5.0))
    shape: str = "gaussian"
    # last, so that the FMU's value references of the parameters before it keep theirs
    sigma1: float = param(0.0, "N.s/m", "micro-damping of the slip-blocks (LuGre's sigma1: "
                          "sigma1 v right after a reversal)", lower=0, search=(0.0, 1e3))
    tilt: float = param(1.0, "1", "break-away share of the softest slip-block over the "
                        "stiffest's (geometric; 1: equal shares)", lower=1e-4, upper=1e4,
                        search=(1e-2, 1e2), log=True)
    element: str = "slip"
    # the two below only act with element "beside" (after ``element``, so that the FMU's
    # value references of the parameters before them keep theirs)
    share: float = param(0.0, "1", "share of the Stribeck curve the three slip-blocks beside "
                         "the contact's bristle carry (element \"beside\")", lower=0.0,
                         upper=0.95, search=(0.0, 0.9))
    sigma_b: float = param(1e3, "N/m", "total stiffness of the three slip-blocks beside the "
                           "contact's bristle (element \"beside\")", lower=0,
                           lower_open=True, upper=1e9, search=(1.0, 1e7), log=True)

    def _check_relations(self):
        if self.shape not in SHAPES:
            raise ParameterError(f"shape = {self.shape!r}: must be one of {sorted(SHAPES)}")
        if self.element not in ELEMENTS:
            raise ParameterError(f"element = {self.element!r}: must be one of "
                                 f"{sorted(ELEMENTS)}")


_LAYOUT = ("sigma0", "spread", "C", "sigma2", "Fc", "Fs", "vs", "alpha", "b", "shape",
           "sigma1", "tilt", "element", "share", "sigma_b")
S0, SPREAD, CA, S2, FC, FS, VS, ALPHA, B, SHAPE, S1, TILT, ELEM, SHARE, SB = range(len(_LAYOUT))


@njit(cache=True, inline="always")
def element_stiffness(sigma0, spread, k):
    """Fill ``k[0..3]`` with the blocks' stiffnesses [N/m]: geometric, summing to sigma0."""
    r = spread ** (-1.0 / 3.0)
    c1 = r
    c2 = r * r
    c3 = c2 * r
    tot = 1.0 + c1 + c2 + c3
    k[0] = sigma0 / tot
    k[1] = sigma0 * c1 / tot
    k[2] = sigma0 * c2 / tot
    k[3] = sigma0 * c3 / tot


@njit(cache=True, inline="always")
def element_shares(tilt, w):
    """Fill ``w[0..3]`` with the blocks' break-away shares [-]: geometric from the stiffest
    block to the softest (ratio ``tilt``), summing to 1."""
    r = tilt ** (1.0 / 3.0)
    tot = 1.0 + r + r * r + r * r * r
    w[0] = 1.0 / tot
    w[1] = r / tot
    w[2] = r * r / tot
    w[3] = r * r * r / tot


@njit(cache=True, inline="always")
def beside_layout(sigma0, spread, tilt, share, sigma_b, k, w):
    """Fill ``k[0..3]`` [N/m] and ``w[0..3]`` [-] of element ``beside``: the contact's
    bristle (``sigma0``, 1 - ``share``) first, then three slip-blocks beside it, stiffness
    geometric summing to ``sigma_b`` (ratio ``spread`` stiffest/softest), shares geometric
    summing to ``share`` (ratio ``tilt`` softest/stiffest)."""
    r = spread ** -0.5
    q = tilt ** 0.5
    kt = 1.0 + r + r * r
    wt = 1.0 + q + q * q
    k[0] = sigma0
    w[0] = 1.0 - share
    for i in range(3):
        k[i + 1] = sigma_b * r ** i / kt
        w[i + 1] = share * q ** i / wt


@njit(cache=True, inline="always")
def element_layout(th, k, w, dw):
    """Fill the elements' stiffnesses ``k`` [N/m], break-away shares ``w`` [-] and
    micro-damping weights ``dw`` [-] (the share of ``sigma1`` dz_i/dt in the force) of
    the packed parameters ``th``: k_i / sum(k) for slip-blocks and bristles alike, the
    contact's bristle alone for ``beside`` (LuGre's sigma1 dz/dt; the blocks beside it
    undamped)."""
    if th[ELEM] == 2.0:
        beside_layout(th[S0], th[SPREAD], th[TILT], th[SHARE], th[SB], k, w)
        for i in range(N_ELEMENTS):
            dw[i] = 1.0 if i == 0 else 0.0
        return
    element_stiffness(th[S0], th[SPREAD], k)
    element_shares(th[TILT], w)
    tot = 0.0
    for i in range(N_ELEMENTS):
        tot += k[i]
    for i in range(N_ELEMENTS):
        dw[i] = k[i] / tot


@njit(cache=True, inline="always")
def is_bristle(elem, i):
    """Whether element ``i`` of the element mode ``elem`` (:data:`ELEMENTS`' code) is a LuGre
    bristle: all of ``bristle``'s, the first of ``beside``'s."""
    return elem == 1.0 or (elem == 2.0 and i == 0)


@njit(cache=True, inline="always")
def _block_piece(z, vp, T, d, lam, bristle):
    """Exact update of one block over a piece of duration T [s] at the frozen velocity
    ``vp`` [m/s], break-away deflection ``d`` [m] and attraction rate ``lam`` = C/g [1/s]:
    du/dt = min(|vp|, lam (d - u)) for u = sgn(vp) z; a ``bristle`` element (:data:`ELEMENTS`)
    du/dt = |vp| (1 - u / d), LuGre's exact exponential."""
    if vp > 0.0:
        s = 1.0
    elif vp < 0.0:
        s = -1.0
    else:
        return z
    u = s * z
    if bristle:
        return s * (u + (u - d) * _em1(abs(vp) * T / d))
    sp = s * vp
    ustar = d - sp / lam  # where the attraction becomes the slower rate
    if u < ustar:
        u1 = u + sp * T  # sticking: moves with the body
        if u1 <= ustar:
            u = u1
        else:  # reaches the switch inside the piece, then slips for the rest of it
            tau = (ustar - u) / sp
            u = d - (sp / lam) * math.exp(-lam * (T - tau))
    else:
        u = u + (u - d) * _em1(lam * T)  # slipping: relaxes onto d
    return s * u


@njit(cache=True, inline="always")
def _block_rate(z, v, d, lam, bristle):
    """dz/dt [m/s] of one block at velocity ``v``: sgn(v) min(|v|, lam (d - sgn(v) z)),
    with d = w g / k [m] and lam = C / g [1/s]; a ``bristle`` element v - |v| z / d."""
    if bristle:
        return v - abs(v) * z / d
    if v > 0.0:
        r = lam * (d - z)
        return v if v < r else r
    if v < 0.0:
        r = lam * (d + z)
        return v if -v < r else -r
    return 0.0


@njit(cache=True)
def _start_family(u, d, sgn, moving, z):
    """The start family of :meth:`GMS._start_from` at ``u`` [m] into ``z``: at rest
    clip(u, -d_i, d_i), in motion ``sgn`` clip(u - d_i, -d_i, d_i)."""
    for i in range(N_ELEMENTS):
        w = u - d[i] if moving else u
        w = min(max(w, -d[i]), d[i])
        z[i] = sgn * w if moving else w


@njit(cache=True)
def _start_force(u, d, k, sgn, moving, damp, v0, lam, z):
    """sgn (sum_i k_i z_i + ``damp`` sum_i k_i dz_i/dt) [N] of the start family at ``u``
    (``damp`` = sigma1 / sum k, 0 undamped): increasing in u."""
    _start_family(u, d, sgn, moving, z)
    f = 0.0
    r = 0.0
    for i in range(N_ELEMENTS):
        f += k[i] * z[i]
        if damp != 0.0:
            r += k[i] * _block_rate(z[i], v0, d[i], lam, False)
    return (f + damp * r) * sgn


@njit(cache=True)
def _start_bisect(d, k, sgn, moving, damp, v0, lam, lo, hi, want):
    """The start family's state whose force is ``want`` (:func:`_start_force`), by
    bisection of u on [``lo``, ``hi``] (the saturated end beyond it)."""
    z = np.empty(N_ELEMENTS)
    if want <= _start_force(lo, d, k, sgn, moving, damp, v0, lam, z):
        return z
    if want >= _start_force(hi, d, k, sgn, moving, damp, v0, lam, z):
        return z
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid <= lo or mid >= hi:
            break
        if _start_force(mid, d, k, sgn, moving, damp, v0, lam, z) < want:
            lo = mid
        else:
            hi = mid
    _start_family(0.5 * (lo + hi), d, sgn, moving, z)
    return z


@njit(cache=True, inline="always")
def _damping_rate(z, v, wk, dw, C, fc, fs, vs, alpha, shape, elem):
    """sum_i ``dw``_i dz_i/dt [m/s]: the elements' deflection rate the micro-damping sigma1
    multiplies (:func:`element_layout`; v while every block sticks, 0 once they slip at a
    steady speed); ``wk`` the shares over the stiffnesses [m/N]."""
    if v == 0.0:
        return 0.0
    g = stribeck_g(v, fc, fs, vs, alpha, shape)
    lam = C / g
    r = 0.0
    for i in range(N_ELEMENTS):
        if dw[i] != 0.0:
            r += dw[i] * _block_rate(z[i], v, g * wk[i], lam, is_bristle(elem, i))
    return r


@njit(cache=True, nogil=True)
def gms_run(t, v, th, method, z0, F, Z):
    """Simulate one parameter set along (t, v); writes F[k] and Z[k, :] in place."""
    n = t.size
    k = np.empty(N_ELEMENTS)
    wk = np.empty(N_ELEMENTS)
    dw = np.empty(N_ELEMENTS)
    element_layout(th, k, wk, dw)
    for i in range(N_ELEMENTS):
        wk[i] = wk[i] / k[i]
    C = th[CA]
    s2 = th[S2]
    b = th[B]
    s1 = th[S1]
    fc, fs, vs, alpha, shape = th[FC], th[FS], th[VS], th[ALPHA], th[SHAPE]
    elem = th[ELEM]
    z = np.empty(N_ELEMENTS)
    for i in range(N_ELEMENTS):
        z[i] = z0[i]
    for j in range(n):
        vj = v[j]
        f = 0.0
        for i in range(N_ELEMENTS):
            f += k[i] * z[i]
            Z[j, i] = z[i]
        if s1 != 0.0:
            f += s1 * _damping_rate(z, vj, wk, dw, C, fc, fs, vs, alpha, shape, elem)
        F[j] = f + s2 * vj + b
        if j + 1 < n:
            h = t[j + 1] - t[j]
            if method == 1:
                g = stribeck_g(vj, fc, fs, vs, alpha, shape)
                lam = C / g
                for i in range(N_ELEMENTS):
                    z[i] = z[i] + h * _block_rate(z[i], vj, g * wk[i], lam,
                                                   is_bristle(elem, i))
            else:
                T1, a1, b1, T2, a2, b2 = split_step(vj, v[j + 1], h)
                for piece in range(2):
                    if piece == 0:
                        T, vp = T1, 0.5 * (a1 + b1)
                    else:
                        T, vp = T2, 0.5 * (a2 + b2)
                    if T <= 0.0 or vp == 0.0:
                        continue
                    g = stribeck_g(vp, fc, fs, vs, alpha, shape)
                    lam = C / g
                    for i in range(N_ELEMENTS):
                        z[i] = _block_piece(z[i], vp, T, g * wk[i], lam, is_bristle(elem, i))


@njit(cache=True, nogil=True)
def _kernel(t, v, a, load, x, th, method, state0):
    F = np.empty(t.size)
    Z = np.empty((t.size, N_ELEMENTS))
    gms_run(t, v, th, method, state0, F, Z)
    return F, Z


@njit(cache=True, parallel=True)
def _population_kernel(t, v, a, load, x, Theta, method):
    npop = Theta.shape[0]
    F = np.empty((npop, t.size))
    for i in prange(npop):
        Z = np.empty((t.size, N_ELEMENTS))
        gms_run(t, v, Theta[i], method, np.zeros(N_ELEMENTS), F[i], Z)
    return F


class GMS(FrictionModel):
    """Generalized Maxwell-slip law with four slip-blocks; see the module docstring.

    Examples
    --------
    >>> from friction import make_model
    >>> m = make_model("gms", sigma0=1e5, spread=10.0, C=1e4, Fc=1.0, Fs=1.5, vs=1e-3)
    >>> float(m.steady_state([1e-2])[0])   # doctest: +ELLIPSIS
    1.004...
    """
    name = "gms"
    Params = GMSParams
    state_names = tuple(f"z{i + 1}" for i in range(N_ELEMENTS))
    state_units = ("m",) * N_ELEMENTS
    theta_layout = _LAYOUT
    twins: ClassVar[dict] = {}

    _kernel = staticmethod(_kernel)
    _population_kernel = staticmethod(_population_kernel)

    def _pack(self, p: GMSParams) -> np.ndarray:
        return np.array([p.sigma0, p.spread, p.C, p.sigma2, p.Fc, p.Fs, p.vs, p.alpha, p.b,
                         SHAPES[p.shape], p.sigma1, p.tilt, ELEMENTS[p.element], p.share,
                         p.sigma_b],
                        dtype=np.float64)

    # -- pieces of the law --------------------------------------------------------------
    def _layout(self):
        """(k, w, dw): the elements' stiffnesses [N/m], shares [-] and damping weights [-]
        (:func:`element_layout`)."""
        k, w, dw = (np.empty(N_ELEMENTS) for _ in range(3))
        element_layout(self._pack(self.params), k, w, dw)
        return k, w, dw

    def element_shares(self) -> np.ndarray:
        """Break-away shares w_i of the four elements [-] (they sum to 1; slip-blocks and
        bristles stiffest first, ``beside`` the contact's bristle first)."""
        return self._layout()[1]

    def element_stiffness(self) -> np.ndarray:
        """Stiffnesses k_i of the four elements [N/m] (slip-blocks and bristles stiffest
        first, summing to sigma0; ``beside``: sigma0, then the blocks summing to sigma_b)."""
        return self._layout()[0]

    def g(self, v) -> np.ndarray:
        """Stribeck curve g(v) [N].

        Parameters
        ----------
        v : array_like
            Velocity [m/s].
        """
        p = self.params
        return stribeck_g_np(v, p.Fc, p.Fs, p.vs, p.alpha, p.shape)

    def saturation(self, v) -> np.ndarray:
        """Break-away deflections d_i(v) = g(v) / (N k_i) of the blocks [m] at velocity v.

        Parameters
        ----------
        v : float
            Velocity [m/s].
        """
        return float(self.g(float(v))) * (self.element_shares() / self.element_stiffness())

    def presliding_distance(self, level: float | None = None) -> float:
        """Travel from a state of rest without history until every block slips [m]: the
        largest break-away deflection of the elements at the level ``level`` [N] (default Fs, the
        level at rest). After a reversal from sliding the transition takes twice that.

        Parameters
        ----------
        level : float, optional
            Friction level [N] (default ``Fs``).
        """
        level = self.params.Fs if level is None else float(level)
        return float(level * np.max(self.element_shares() / self.element_stiffness()))

    def virgin_force(self, x, level: float | None = None) -> np.ndarray:
        """Presliding force [N] of a first loading from rest without history by the
        displacement ``x`` [m] at the constant level ``level`` [N] (default Fs):
        F_v(x) = sum_i k_i clip(x, -d_i, d_i), d_i = level / (N k_i). Rate terms
        (sigma2, b) not included.

        Parameters
        ----------
        x : array_like
            Displacement from rest [m].
        level : float, optional
            Friction level [N] (default ``Fs``).
        """
        level = self.params.Fs if level is None else float(level)
        k = self.element_stiffness()
        d = level * (self.element_shares() / k)
        x = np.asarray(x, dtype=float)
        return np.sum(k * np.clip(x[..., None], -d, d), axis=-1)

    def z_max(self) -> float:
        """Bound of every block's deflection [m]: the softest block's break-away deflection
        at the larger level max(Fc, Fs) (from a start within the bounds)."""
        return self.presliding_distance(max(self.params.Fc, self.params.Fs))

    def state_scales(self) -> np.ndarray:
        """Typical magnitude of each state [m]: each block's largest break-away deflection
        (the reference integrator's absolute tolerance scales with it)."""
        return max(self.params.Fc, self.params.Fs) * (self.element_shares() / self.element_stiffness())

    # -- analytic pieces ----------------------------------------------------------------
    def steady_state(self, v, **inputs) -> np.ndarray:
        """Steady-state (Stribeck) force F_ss(v) = g(v) sgn(v) + sigma2 v + b [N]."""
        v = np.asarray(v, dtype=float)
        p = self.params
        return self.g(v) * np.sign(v) + p.sigma2 * v + p.b

    def derivatives(self, state, v, **inputs) -> np.ndarray:
        """dz_i/dt [m/s] of the four blocks at velocity ``v`` [m/s] (module docstring)."""
        return self._rates_at(float(v))(state)

    def _rates_at(self, v: float):
        """``rates(state) -> dz/dt`` [m/s] of the four blocks at the velocity ``v`` [m/s]:
        what depends on ``v`` alone (g(v), each block's break-away deflection, the slip
        rate C / g) computed once, for a loop over states at one speed."""
        p = self.params
        g = float(self.g(v))
        k = self.element_stiffness()
        w = self.element_shares()
        lam = p.C / g
        d = [g * (w[i] / k[i]) for i in range(N_ELEMENTS)]
        elem = float(ELEMENTS[p.element])

        def rates(state):
            out = np.empty(N_ELEMENTS)
            for i in range(N_ELEMENTS):
                out[i] = _block_rate(float(state[i]), v, d[i], lam, is_bristle(elem, i))
            return out
        return rates

    def force(self, state, v, **inputs) -> float:
        """F = sum_i (k_i z_i + sigma1 dw_i dz_i/dt) + sigma2 v + b [N] (dw_i = k_i / sigma0;
        ``beside``: 1 for the contact's bristle, 0 for the blocks)."""
        p = self.params
        k, _, dw = self._layout()
        f = 0.0
        for i in range(N_ELEMENTS):
            f += k[i] * float(state[i])
        if p.sigma1:
            f += p.sigma1 * float(dw @ self.derivatives(state, v))
        return f + p.sigma2 * float(v) + p.b

    def steady_state_state(self, v0, **inputs) -> np.ndarray:
        """Every block at its break-away deflection in the direction of ``v0``:
        z_i = sgn(v0) d_i(v0) [m] (zeros at rest); the slip rates vanish there."""
        v0 = float(v0)
        if v0 == 0.0 or not math.isfinite(v0):
            return np.zeros(N_ELEMENTS)
        k = self.element_stiffness()
        g = float(self.g(v0))
        d = g * (self.element_shares() / k)
        return d if v0 > 0 else -d

    def _start_from(self, t, v, a, load, x, F0=None) -> np.ndarray:
        """:meth:`record_start_state`; with a measured first force the four deflections
        come from the one-parameter family of states the force can tell apart:

        * at rest (``v[0] = 0``): a first loading from rest without history,
          z_i = clip(u, -d_i, d_i) at the level Fs;
        * in motion with sign s: a branch started at a reversal from sliding the other
          way, z_i = s clip(u - d_i, -d_i, d_i), u >= 0, at the level g(v[0]) (the state
          a record cut in the presliding after a reversal has; u >= 2 d_i: sliding).

        u solves F(z(u)) = F[0] (monotone in u, by bisection); a force beyond the law's
        reach gives the saturated end of the family. The force cannot tell the four
        deflections apart in general (a record started from an undeflected contact at
        speed is not in this family): it picks the state of the common cases.
        """
        s = self._motion_start(t, v, a, load, x, {})
        if F0 is None or not math.isfinite(F0):
            return s
        p = self.params
        v0 = float(v[0])
        k = self.element_stiffness()
        if p.element != "slip":
            # LuGre's rule (:meth:`FrictionModel._start_from`) for every bristle alike: each
            # at the same share of its largest deflection, the share at which the force
            # (affine in it) is F[0], within +-1 (four equal bristles: the LuGre start; the
            # blocks beside a bristle at the same share as it)
            top = max(p.Fc, p.Fs) * (self.element_shares() / k)
            f0 = self.force(np.zeros(N_ELEMENTS), v0)
            f1 = self.force(top, v0)
            if not (math.isfinite(f0) and math.isfinite(f1)) or f1 == f0:
                return s
            return min(max((F0 - f0) / (f1 - f0), -1.0), 1.0) * top
        target = F0 - p.sigma2 * v0 - p.b
        if v0 == 0.0:
            d = p.Fs * (self.element_shares() / k)
            sgn, lo, hi = 1.0, -float(np.max(d)), float(np.max(d))
        else:
            # the blocks' break-away deflections at v0 (what :meth:`derivatives` reads too)
            g0 = float(self.g(v0))
            d = g0 * (self.element_shares() / k)
            sgn, lo, hi = math.copysign(1.0, v0), 0.0, 2.0 * float(np.max(d))
        # the micro-damping's part of the force (increasing in u all the same: it falls as
        # blocks start slipping, by less than their springs' part grows)
        damped = bool(p.sigma1) and v0 != 0.0
        damp = p.sigma1 / float(np.sum(k)) if damped else 0.0  # slip: dw_i = k_i / sum k
        lam = p.C / g0 if damped else 0.0
        # a compiled bisection: in Python it was a third of the gms candidate's joint fit
        return _start_bisect(np.ascontiguousarray(d, dtype=float), k, sgn, v0 != 0.0, damp,
                             v0, lam, lo, hi, target * sgn)
