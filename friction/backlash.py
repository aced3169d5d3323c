"""Backlash in front of a LuGre contact: lost motion at every reversal.

The drive (velocity ``v``, the law's input) moves the contact through a gap of width
2 delta. Their offset p = x_drive - x_contact [m] stays in [-delta, delta] (a play operator
of half-width delta). The drive pushes the contact when it reaches the flank ahead of it;
otherwise the contact stands still. With u = delta - sgn(v) p the gap left ahead of the
drive [m]:

    phi(u)  = 1 for u <= 0,  1 - u / eps for 0 < u < eps,  0 for u >= eps
    v_c     = phi(u) v                                  contact velocity [m/s]
    dp/dt   = v - v_c

eps = 1e-3 delta (:data:`ENGAGE_BAND`) is a stiff flank: over the last 0.1 % of the gap the
contact takes up the drive's speed (u then closes as exp(-travel / eps)). It keeps the state
equation continuous (Lipschitz) in p, which an implicit integrator needs (a sharp flank,
phi a step, has no solution of the implicit step equations at the flank: the solver's
step shrinks towards it without end; with the band Model Exchange FMUs integrate it).

The friction of the contact is the classic LuGre law (:mod:`friction.lugre`) at the contact
velocity:

    dz/dt = v_c - sigma0 |v_c| / g(v_c) z
    F     = sigma0 z + sigma1 dz/dt + sigma2 v_c + b

So after a reversal the drive crosses the gap (travel 2 delta) while the contact and its
bristle stand still, and only then does the contact follow: F(x_drive) is LuGre's F(x)
shifted by +-delta, with a flat segment of width 2 delta at each reversal (2 delta - eps to
the first change of the force). The option ``gap`` says what the drive feels meanwhile:

* ``hold`` (default): the force the contact holds, sigma0 z + b (a force read at the
  contact, or a preloaded joint): the force lags the motion by a constant displacement;
* ``free``: only the offset b while the drive touches neither flank (a torque read at the
  motor of a geared drive): a dead zone at each reversal. Within eps of a flank the
  contact's force phi(delta - |p|) (sigma0 z + sigma1 dz/dt + sigma2 v_c) is taken up.

Whatever the option, what bridges the play adds to it while the drive touches neither flank,
(1 - phi(delta - |p|)) (``gap_bias`` + ``gap_stiffness`` p + ``gap_drag`` sgn v) [N]: a
weight or return spring the contact holds (a bias), an anti-backlash spring (the force
ramps across the gap), a slip-clutch idler (a drag against the motion). All three are 0 by
default; they change the force only, not the motion (the contact still stands still in the
gap: their force stays below its break-away).

``delta = 0`` is the LuGre law (the same arithmetic, bit for bit: no cut at reversals). At
steady sliding the contact rests on the leading flank and the force is LuGre's Stribeck
curve (:meth:`BacklashLuGre.steady_state`). A record that starts at rest starts in the
middle of the gap (p = 0), one that starts sliding on the leading flank (p = delta sgn v).

Inputs: the velocity only (``extra_inputs`` is empty). As a candidate the LuGre parameters
keep their meaning and ``delta`` [m] is the half-width of the gap (the lost motion at a
reversal is 2 delta).

Numerics (``method="exact"``): a step whose velocity changes sign is cut at the reversal
(:func:`friction.steps.split_step`); on each piece the velocity is linear and of one sign,
so the play is advanced exactly in the drive's travel: the free part of the gap closes at
the drive's speed (the instant it is closed is the root of the travel's quadratic), the band
as u = u_0 exp(-travel / eps). The bristle is advanced with the exact exponential update of
:mod:`friction.lugre` over the rest of the piece at the contact's mean velocity there (on a
piece engaged throughout: the step's midpoint velocity, as LuGre). ``method="euler"``:
explicit Euler of the bristle (as LuGre's) and of the play, clipped to the gap.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numba import njit, prange

from ._validation import ParameterError
from .base import FrictionModel, param
from .lugre import (_LAYOUT as _LUGRE_LAYOUT, ALPHA, B, FCN, FCP, FSN, FSP, S0, S1, S2N, S2P,
                    SHAPE, VSN, VSP, LuGreParams, _em1, _g_fast, side_constants)
from .shapes import SHAPES, DirectionalStribeck
from .steps import split_step

__all__ = ["BacklashLuGreParams", "BacklashLuGre", "GAP_MODES", "ENGAGE_BAND", "backlash_run"]

#: what the drive feels while it crosses the gap (option ``gap``)
GAP_MODES = {"hold": 0, "free": 1}
#: width of the stiff flank, eps = ENGAGE_BAND * delta (module docstring)
ENGAGE_BAND = 1e-3


@dataclass(frozen=True)
class BacklashLuGreParams(LuGreParams):
    """LuGre parameters plus the gap (defaults: LuGre's contact behind a gap of 2 x 2 um,
    a precision stage's lead screw; real drives show 1-3 mm of lost motion)."""
    OPTIONS: ClassVar[dict] = {"shape": SHAPES, "gap": GAP_MODES}
    delta: float = param(2e-6, "m", "half-width of the backlash gap (lost motion 2 delta at "
                         "a reversal)", lower=0.0, upper=1.0, search=(1e-6, 5e-3), log=True)
    gap: str = "hold"
    gap_bias: float = param(0.0, "N", "force the drive feels while it crosses the play, "
                            "beyond the offset b (a weight or return spring the contact holds)",
                            search=(-1.0, 1.0))
    gap_stiffness: float = param(0.0, "N/m", "stiffness of a spring across the play (an "
                                 "anti-backlash spring: the force ramps across the gap)",
                                 lower=0.0, search=(0.0, 1e5))
    gap_drag: float = param(0.0, "N", "Coulomb drag across the play, against the drive's "
                            "motion (a slip-clutch idler)", lower=0.0, search=(0.0, 1.0))

    def _check_relations(self):
        super()._check_relations()
        if self.gap not in GAP_MODES:
            raise ParameterError(f"gap = {self.gap!r}: must be one of {sorted(GAP_MODES)}")


_LAYOUT = _LUGRE_LAYOUT + ("delta", "gap", "gap_bias", "gap_stiffness", "gap_drag")
DELTA, GAP, GB, GK, GD = (len(_LUGRE_LAYOUT) + i for i in range(5))


@njit(cache=True, inline="always")
def _engage_time(r, a, b, T):
    """Time [s] at which a piece of duration T with speeds |a| -> |b| (linear) has
    travelled r (0 < r < its travel)."""
    A = abs(a)
    disc = A * A + 2.0 * (abs(b) - A) * r / T
    if disc < 0.0:
        disc = 0.0
    return 2.0 * r / (A + math.sqrt(disc))


@njit(cache=True, inline="always")
def _band(u, eps):
    """phi(u): the share of the drive's speed the contact takes with a gap u [m] left."""
    if u <= 0.0:
        return 1.0
    if u >= eps:
        return 0.0
    return 1.0 - u / eps


@njit(cache=True, inline="always")
def _push(v, p, delta, eps):
    """phi of the gap ahead of a drive at velocity v with the play p (0 at v = 0)."""
    if v > 0.0:
        return _band(delta - p, eps)
    if v < 0.0:
        return _band(delta + p, eps)
    return 0.0


@njit(cache=True, inline="always")
def _across(v, p, delta, eps, bias, stiffness, drag):
    """What the drive feels through the play itself while it touches neither flank [N]
    (``gap_bias`` + ``gap_stiffness`` p + ``gap_drag`` sgn v), faded out over the flank's
    band as the contact takes the force up."""
    w = 1.0 - _band(delta - abs(p), eps)
    if w == 0.0:
        return 0.0
    sv = 1.0 if v > 0.0 else (-1.0 if v < 0.0 else 0.0)
    return w * (bias + stiffness * p + drag * sv)


@njit(cache=True, nogil=True)
def backlash_run(t, v, th, method, z0, p0, F, Z):
    """Simulate one parameter set along (t, v); writes F[k], Z[k, 0] = z, Z[k, 1] = p."""
    n = t.size
    delta = th[DELTA]
    eps = ENGAGE_BAND * delta
    p = p0
    if p > delta:
        p = delta
    elif p < -delta:
        p = -delta
    free = th[GAP] == 1.0
    gb, gk, gd = th[GB], th[GK], th[GD]
    across = gb != 0.0 or gk != 0.0 or gd != 0.0
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
        ph = _push(vk, p, delta, eps)
        vc = vk if ph == 1.0 else ph * vk
        if vc >= 0.0:
            g, cg = _g_fast(vc, fcp, fsp, ivsp, alpha, shape, cutp, s0, rp)
            s2 = s2p
        else:
            g, cg = _g_fast(vc, fcn, fsn, ivsn, alpha, shape, cutn, s0, rn)
            s2 = s2n
        zd = vc - cg * abs(vc) * z
        if free:
            touch = _band(delta - abs(p), eps)
            if touch == 1.0:
                F[k] = s0 * z + s1 * zd + s2 * vc + b
            elif touch == 0.0:
                F[k] = b
            else:
                F[k] = touch * (s0 * z + s1 * zd + s2 * vc) + b
        else:
            F[k] = s0 * z + s1 * zd + s2 * vc + b
        if across:
            F[k] += _across(vk, p, delta, eps, gb, gk, gd)
        Z[k, 0] = z
        Z[k, 1] = p
        if k + 1 < n:
            h = t[k + 1] - t[k]
            if method == 1:
                z = z + h * zd
                p = p + h * (vk - vc)
                if p > delta:
                    p = delta
                elif p < -delta:
                    p = -delta
                continue
            if delta > 0.0:
                T1, a1, b1, T2, a2, b2 = split_step(vk, v[k + 1], h)
            else:  # no gap: LuGre's update over the whole step, bit for bit
                T1, a1, b1, T2, a2, b2 = h, vk, v[k + 1], 0.0, 0.0, 0.0
            for piece in range(2):
                if piece == 0:
                    T, va, vb = T1, a1, b1
                else:
                    T, va, vb = T2, a2, b2
                vp = 0.5 * (va + vb)
                if T <= 0.0 or vp == 0.0:
                    continue
                sg = 1.0 if vp > 0.0 else -1.0
                D = sg * vp * T       # the drive's travel over the piece
                u = delta - sg * p    # gap left ahead of the drive
                if u > eps:           # the free part of the gap first
                    if D <= u - eps:
                        p = p + vp * T
                        continue
                    tau = _engage_time(u - eps, va, vb, T)
                    xi = D - (u - eps)
                    u0 = eps
                else:
                    tau = 0.0
                    xi = D
                    u0 = u
                u1 = u0 * math.exp(-xi / eps) if u0 > 0.0 else 0.0
                p = sg * (delta - u1)
                Te = T - tau
                if u0 == 0.0:         # engaged throughout: LuGre's update
                    ve = vp
                elif Te > 0.0:
                    ve = sg * (xi - (u0 - u1)) / Te
                else:
                    ve = 0.0
                if Te > 0.0 and ve != 0.0:
                    if ve >= 0.0:
                        gm, cgm = _g_fast(ve, fcp, fsp, ivsp, alpha, shape, cutp, s0, rp)
                        zss = gm * is0
                    else:
                        gm, cgm = _g_fast(ve, fcn, fsn, ivsn, alpha, shape, cutn, s0, rn)
                        zss = -gm * is0
                    z = z + (z - zss) * _em1(Te * cgm * abs(ve))


@njit(cache=True, nogil=True)
def _kernel(t, v, a, load, x, th, method, state0):
    F = np.empty(t.size)
    Z = np.empty((t.size, 2))
    backlash_run(t, v, th, method, state0[0], state0[1], F, Z)
    return F, Z


@njit(cache=True, parallel=True)
def _population_kernel(t, v, a, load, x, Theta, method):
    npop = Theta.shape[0]
    F = np.empty((npop, t.size))
    for i in prange(npop):
        Z = np.empty((t.size, 2))
        backlash_run(t, v, Theta[i], method, 0.0, 0.0, F[i], Z)
    return F


class BacklashLuGre(DirectionalStribeck, FrictionModel):
    """LuGre contact behind a backlash gap of half-width delta; see the module docstring.

    Examples
    --------
    >>> from friction import make_model
    >>> m = make_model("backlash_lugre", delta=1e-3)
    >>> float(m.steady_state([1e-2])[0])   # doctest: +ELLIPSIS
    1.004...
    """
    name = "backlash_lugre"
    Params = BacklashLuGreParams
    state_names = ("z", "p")
    state_units = ("m", "m")
    theta_layout = _LAYOUT
    twins = {"Fc": "Fc_neg", "Fs": "Fs_neg", "vs": "vs_neg", "sigma2": "sigma2_neg"}

    _kernel = staticmethod(_kernel)
    _population_kernel = staticmethod(_population_kernel)

    def _pack(self, p: BacklashLuGreParams) -> np.ndarray:
        return np.array([p.sigma0, p.sigma1, p.sigma2, p.resolved("sigma2", -1),
                         p.Fc, p.resolved("Fc", -1), p.Fs, p.resolved("Fs", -1),
                         p.vs, p.resolved("vs", -1), p.alpha, p.b, SHAPES[p.shape],
                         p.delta, GAP_MODES[p.gap], p.gap_bias, p.gap_stiffness,
                         p.gap_drag], dtype=np.float64)

    # -- pieces of the law --------------------------------------------------------------
    def contact_velocity(self, state, v) -> float:
        """Velocity of the contact [m/s] at a state (z, p) and drive velocity ``v``.

        Parameters
        ----------
        state : array_like, shape (2,)
            The state (z [m], p [m]).
        v : float
            Drive velocity [m/s].
        """
        d = self.params.delta
        ph = _push(float(v), float(state[1]), d, ENGAGE_BAND * d)
        return float(v) if ph == 1.0 else ph * float(v)

    def z_max(self) -> float:
        """Bound of the bristle deflection: max over v of g(v)/sigma0 [m] (z0 = 0 start)."""
        p = self.params
        levels = [p.Fc, p.Fs, p.resolved("Fc", -1), p.resolved("Fs", -1)]
        return max(levels) / p.sigma0

    def state_scales(self) -> np.ndarray:
        """Typical magnitude of (z, p) [m]: the bristle's saturation and the gap."""
        zm = self.z_max()
        return np.array([zm, max(self.params.delta, zm)])

    # -- analytic pieces ----------------------------------------------------------------
    def steady_state(self, v, **inputs) -> np.ndarray:
        """Steady-state (Stribeck) force F_ss(v) = g(v) sgn(v) + sigma2 v + b [N] (the
        contact rests on the leading flank and slides with the drive)."""
        v = np.asarray(v, dtype=float)
        return self.g(v) * np.sign(v) + self.sigma2_of(v) * v + self.params.b

    def derivatives(self, state, v, **inputs) -> np.ndarray:
        """(dz/dt, dp/dt) [m/s] at a state (z, p) and drive velocity ``v`` [m/s]."""
        vc = self.contact_velocity(state, v)
        g = float(self.g(vc))
        return np.array([vc - self.params.sigma0 * abs(vc) / g * float(state[0]),
                         float(v) - vc])

    def force(self, state, v, **inputs) -> float:
        """Force on the drive [N] (``gap="free"``: only the offset b while the drive
        touches neither flank)."""
        p = self.params
        vc = self.contact_velocity(state, v)
        zd = self.derivatives(state, v)[0]
        f = p.sigma0 * float(state[0]) + p.sigma1 * zd + float(self.sigma2_of(vc)) * vc
        eps = ENGAGE_BAND * p.delta
        extra = _across(float(v), float(state[1]), p.delta, eps, p.gap_bias,
                        p.gap_stiffness, p.gap_drag)
        if p.gap == "free":
            touch = _band(p.delta - abs(float(state[1])), eps)
            if touch == 0.0:
                return p.b + extra
            if touch != 1.0:
                return touch * f + p.b + extra
        return f + p.b + extra

    def _start_from(self, t, v, a, load, x, F0=None) -> np.ndarray:
        """:meth:`record_start_state`. From the motion alone as every law (at rest: the
        middle of the gap; sliding: the leading flank; speeding up: a warm-up from rest in
        the middle of the gap). With the measured first force, and ``gap="hold"``: a force
        that opposes the motion is still the load of the previous direction, so the drive
        has just reversed and is crossing the gap from the trailing flank; the travel since
        the reversal is the warm-up's, v0^2 / (2 a0), and while it is below 2 delta the
        contact stands still holding z = (F[0] - b) / sigma0. Otherwise the bristle comes
        from the force as for LuGre (:meth:`FrictionModel.record_start_state`)."""
        s = super()._start_from(t, v, a, load, x, F0)
        p = self.params
        if F0 is None or not math.isfinite(F0) or p.gap != "hold" or p.delta == 0.0:
            return s
        v0 = float(v[0])
        if v0 == 0.0 or not (F0 - p.b) * v0 < 0.0:
            return s
        sg = math.copysign(1.0, v0)
        acc = (float(v[1]) - v0) / float(t[1] - t[0]) if v.size > 1 else 0.0
        travel = 0.5 * v0 * v0 / abs(acc) if acc * v0 > 0.0 else 0.0
        if travel >= 2.0 * p.delta:
            return s
        bound = self._deflection_bound(v0, {})
        z = min(max((F0 - p.b) / p.sigma0, -bound), bound)
        return np.array([z, sg * (travel - p.delta)])

    def steady_state_state(self, v0, **inputs) -> np.ndarray:
        """Sliding at ``v0``: the contact on the leading flank, p = delta sgn(v0), and the
        LuGre bristle at g(v0) sgn(v0) / sigma0 (zeros at rest: the middle of the gap)."""
        v0 = float(v0)
        if v0 == 0.0 or not math.isfinite(v0):
            return np.zeros(2)
        sg = math.copysign(1.0, v0)
        return np.array([float(self.g(v0)) * sg / self.params.sigma0, sg * self.params.delta])
