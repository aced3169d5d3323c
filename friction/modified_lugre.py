"""Modified LuGre of seed 000 (SHAO 2018): switch Gamma(v) and acceleration-dependent F_d.

As reconstructed in EQUATIONS.md A.3 (structure REC-M, exact forms of Gamma and F_d REC-L,
hence configurable):

    dz/dt = Gamma(v) [v - sigma0 |v| / g(v) z]                             (Eq. 7)
    F     = sigma0 z + sigma1 dz/dt + sigma2 v + F_d + b                   (Eq. 8)
    g(v)  = Fc + (Fs - Fc) exp(-|v/vs|^alpha)   (or lorentzian)            (Eq. 9)

Switch function Gamma(v) (Eq. 10), ``gamma_form``:

* ``"logistic"`` (Gamma-A, default): 1 / (1 + exp(kappa (|v| - (v1+v2)/2))),
  kappa = 2 ln 99 / (v2 - v1), so Gamma(v1) = 0.99 and Gamma(v2) = 0.01;
* ``"cosine"`` (Gamma-B): 1 for |v| <= v1, (1 + cos(pi (|v|-v1)/(v2-v1))) / 2 inside the band,
  0 for |v| >= v2.

Acceleration-dependent part (Eq. 11), ``fd_form``:

* ``"lag"`` (default): F_d is a state, tau dF_d/dt + F_d = F_d^ss(v, a);
* ``"filtered_acceleration"``: the state is a filtered acceleration, tau da_f/dt + a_f = a,
  and F_d = F_d^ss(v, a_f);

    F_d^ss(v, a) = f_a sgn(a) [1 - exp(-(|a|/a_s)^beta)] exp(-(|v|/v_c)^gamma)

with tau = 0 meaning a static F_d = F_d^ss(v, a). F_d^ss(v, 0) = 0, so at constant speed the
law reduces exactly to the Stribeck curve (Eq. 5). Direction-dependent values (the "+" set for
v >= 0, the "-" set for v < 0): Fc, Fs, vs, sigma2, f_a, a_s, v_c.

Numerics (``method="exact"``): dz/dt is still linear in z over a step, dz/dt = G v - G a z with
G = Gamma(v), a = sigma0 |v| / g(v), so the exponential update of :mod:`friction.lugre`
(z+ = z + (z - z_ss)(e^{-G a h} - 1), z_ss = g sgn(v) / sigma0) advances it exactly with the
coefficients frozen at the step's midpoint velocity (stable at any step and stiffness). The lag is advanced by its exact solution for an input that is linear over the
step (first-order hold of the sampled F_d^ss or a), stable for any h/tau.
``method="euler"`` is the paper's explicit Euler (A.9 sketch): z += h dz/dt,
F_d += h (F_d^ss - F_d)/tau. Its bristle update stays bounded wherever Gamma ~ 0 covers the
speeds with h sigma0 |v| / g(v) > 1 (choose v2 below the critical velocity of Eq. 30).

The states at sample k are the values at t_k (the force at t_k uses them; the A.9 sketch
updates F_d before the output, a one-sample shift).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from numba import njit, prange

from ._validation import ParameterError
from .base import FrictionModel, FrictionParams, param
from .lugre import _LAYOUT as _LUGRE_LAYOUT
from .lugre import ALPHA, B, FCN, FCP, FSN, FSP, S0, S1, S2N, S2P, SHAPE, VSN, VSP
from .lugre import _em1, _g_fast, side_constants
from .shapes import SHAPES, DirectionalStribeck

__all__ = ["ModifiedLuGreParams", "ModifiedLuGre", "GAMMA_FORMS", "FD_FORMS",
           "switch_gamma", "fd_steady"]

#: switch-function forms of Eq. (10)
GAMMA_FORMS = {"logistic": 0, "cosine": 1}
#: forms of the acceleration-dependent part, Eq. (11)
FD_FORMS = {"lag": 0, "filtered_acceleration": 1}

_LN99 = math.log(99.0)


@dataclass(frozen=True)
class ModifiedLuGreParams(FrictionParams):
    """Parameters of the seed-000 modified LuGre (defaults: a plausible valve/guide contact).

    Defaults give Fc/sigma0 = 1.2e-5 m (EQUATIONS.md A.7), hence an explicit-Euler critical
    velocity Fc/(sigma0 h) = 0.24 m/s at h = 5e-5 s, with the switch band v1 = 0.1 m/s,
    v2 = 0.2 m/s below it.
    """
    #: option fields -> their choices and the integer codes the kernels use
    OPTIONS: ClassVar[dict] = {"shape": SHAPES, "gamma_form": GAMMA_FORMS,
                               "fd_form": FD_FORMS}
    sigma0: float = param(5e5, "N/m", "bristle stiffness", lower=0, lower_open=True,
                          upper=1e9, search=(1e4, 1e7), log=True)
    sigma1: float = param(40.0, "N.s/m", "micro-damping of the bristles", lower=0,
                          search=(0.0, 500.0))
    sigma2: float = param(20.0, "N.s/m", "viscous coefficient (v >= 0)", lower=0,
                          search=(0.0, 100.0))
    Fc: float = param(6.0, "N", "Coulomb friction level (v >= 0)", lower=0, lower_open=True,
                      search=(0.1, 30.0))
    Fs: float = param(6.5, "N", "static (break-away) friction level (v >= 0)", lower=0,
                      lower_open=True, search=(0.1, 40.0))
    vs: float = param(5e-3, "m/s", "Stribeck velocity (v >= 0)", lower=0, lower_open=True,
                      search=(1e-4, 0.1), log=True)
    alpha: float = param(2.0, "1", "Stribeck shape exponent (gaussian shape)", lower=0,
                         lower_open=True, upper=10, search=(0.3, 4.0))
    b: float = param(0.0, "N", "constant force offset (0 in seed 000)", search=(-5.0, 5.0))
    f_a: float = param(2.0, "N", "level of the acceleration-dependent part F_d (v >= 0)",
                       lower=0, search=(0.0, 20.0))
    a_s: float = param(20.0, "m/s^2", "acceleration scale of F_d (v >= 0)", lower=0,
                       lower_open=True, search=(0.1, 1e3), log=True)
    v_c: float = param(0.1, "m/s", "velocity decay scale of F_d (v >= 0)", lower=0,
                       lower_open=True, search=(1e-3, 1.0), log=True)
    beta: float = param(1.0, "1", "acceleration shape exponent of F_d", lower=0,
                        lower_open=True, upper=10, search=(0.3, 4.0))
    gamma: float = param(1.0, "1", "velocity shape exponent of F_d", lower=0,
                         lower_open=True, upper=10, search=(0.3, 4.0))
    tau: float = param(2e-3, "s", "frictional-lag time constant of F_d (0: static F_d)",
                       lower=0, upper=10, search=(0.0, 0.05))
    v1: float = param(0.1, "m/s", "switch band start: Gamma ~ 1 for |v| < v1 (preset)",
                      lower=0, lower_open=True)
    v2: float = param(0.2, "m/s", "switch band end: Gamma ~ 0 for |v| > v2 (preset, > v1)",
                      lower=0, lower_open=True)
    Fc_neg: float | None = param(None, "N", "Coulomb level for v < 0 (None: same as Fc)",
                                 lower=0, lower_open=True, search=(0.1, 30.0))
    Fs_neg: float | None = param(None, "N", "static level for v < 0 (None: same as Fs)",
                                 lower=0, lower_open=True, search=(0.1, 40.0))
    vs_neg: float | None = param(None, "m/s", "Stribeck velocity for v < 0 (None: same as vs)",
                                 lower=0, lower_open=True, search=(1e-4, 0.1), log=True)
    sigma2_neg: float | None = param(None, "N.s/m", "viscous coefficient for v < 0 "
                                     "(None: same as sigma2)", lower=0, search=(0.0, 100.0))
    f_a_neg: float | None = param(None, "N", "F_d level for v < 0 (None: same as f_a)",
                                  lower=0, search=(0.0, 20.0))
    a_s_neg: float | None = param(None, "m/s^2", "F_d acceleration scale for v < 0 "
                                  "(None: same as a_s)", lower=0, lower_open=True,
                                  search=(0.1, 1e3), log=True)
    v_c_neg: float | None = param(None, "m/s", "F_d velocity scale for v < 0 "
                                  "(None: same as v_c)", lower=0, lower_open=True,
                                  search=(1e-3, 1.0), log=True)
    shape: str = "gaussian"
    gamma_form: str = "logistic"
    fd_form: str = "lag"

    def _check_relations(self):
        if self.shape not in SHAPES:
            raise ParameterError(f"shape = {self.shape!r}: must be one of {sorted(SHAPES)}")
        if self.gamma_form not in GAMMA_FORMS:
            raise ParameterError(f"gamma_form = {self.gamma_form!r}: must be one of "
                                 f"{sorted(GAMMA_FORMS)}")
        if self.fd_form not in FD_FORMS:
            raise ParameterError(f"fd_form = {self.fd_form!r}: must be one of "
                                 f"{sorted(FD_FORMS)}")
        if not self.v2 > self.v1:
            raise ParameterError(f"v2 = {self.v2!r} must be > v1 = {self.v1!r} [m/s] "
                                 f"(switch band of Gamma(v): Gamma ~ 1 below v1, ~ 0 above v2)")


# packed layout: the classic LuGre block first (so lugre._g_dir and its indices apply)
_LAYOUT = _LUGRE_LAYOUT + ("f_a", "f_a_neg", "a_s", "a_s_neg", "v_c", "v_c_neg", "beta",
                           "gamma", "tau", "v1", "v2", "gamma_form", "fd_form")
(FAP, FAN, ASP, ASN, VCP, VCN, BETA, GAM, TAU, V1, V2, GFORM,
 FDFORM) = range(len(_LUGRE_LAYOUT), len(_LAYOUT))


@njit(cache=True, inline="always")
def switch_gamma(v, v1, v2, form):
    """Switch Gamma(v) of Eq. (10): logistic (form 0) or cosine (form 1)."""
    s = abs(v)
    if form == 1:
        if s <= v1:
            return 1.0
        if s >= v2:
            return 0.0
        return 0.5 * (1.0 + math.cos(math.pi * (s - v1) / (v2 - v1)))
    arg = 2.0 * _LN99 / (v2 - v1) * (s - 0.5 * (v1 + v2))
    if arg > 0.0:  # written both ways so exp never overflows
        e = math.exp(-arg)
        return e / (1.0 + e)
    return 1.0 / (1.0 + math.exp(arg))


@njit(cache=True, inline="always")
def _pow(r, p):
    if p == 1.0:
        return r
    if p == 2.0:
        return r * r
    return r ** p


@njit(cache=True, inline="always")
def _fd_set(speed, a, th, neg):
    # F_d^ss with the "+" (neg False) or "-" (neg True) parameter set, speed = |v|
    if a == 0.0:
        return 0.0
    if neg:
        fa, a_s, vc = th[FAN], th[ASN], th[VCN]
    else:
        fa, a_s, vc = th[FAP], th[ASP], th[VCP]
    acc = -math.expm1(-_pow(abs(a) / a_s, th[BETA]))
    vel = math.exp(-_pow(speed / vc, th[GAM]))
    return fa * acc * vel if a > 0.0 else -fa * acc * vel


@njit(cache=True, inline="always")
def fd_steady(v, a, th):
    """F_d^ss(v, a) of Eq. (11) [N] for one sample, from a packed theta."""
    return _fd_set(abs(v), a, th, v < 0.0)


@njit(cache=True, inline="always")
def _lag_input(v, a, th, form):
    # what the first-order lag filters: F_d^ss itself (lag) or the acceleration
    return fd_steady(v, a, th) if form == 0 else a


@njit(cache=True, inline="always")
def _lag_step(q, u0, u1, h, tau):
    """Exact step of tau dq/dt + q = u for u linear from u0 to u1 over h (any h/tau)."""
    s = h / tau
    e = math.exp(-s)
    phi = -math.expm1(-s) / s if s > 1e-12 else 1.0 - 0.5 * s
    return u1 + (q - u0) * e - (u1 - u0) * phi


@njit(cache=True, nogil=True)
def mlugre_run(t, v, a, th, method, z0, q0, F, Z, Q):
    """Simulate one parameter set along (t, v, a); writes F[k], Z[k], Q[k] in place.

    Q is the lag state: F_d (``fd_form="lag"``) or the filtered acceleration.
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
    v1 = th[V1]
    v2 = th[V2]
    gform = th[GFORM]
    form = th[FDFORM]
    tau = th[TAU]
    z = z0
    q = q0
    u = _lag_input(v[0], a[0], th, form)
    h_lag = -1.0  # step whose lag factors are cached (uniform sampling: computed once)
    e_lag = 0.0
    phi_lag = 0.0
    for k in range(n):
        vk = v[k]
        if vk >= 0.0:
            g, cg = _g_fast(vk, fcp, fsp, ivsp, alpha, shape, cutp, s0, rp)
            s2 = s2p
        else:
            g, cg = _g_fast(vk, fcn, fsn, ivsn, alpha, shape, cutn, s0, rn)
            s2 = s2n
        G = switch_gamma(vk, v1, v2, gform)
        zd = G * (vk - cg * abs(vk) * z)
        if tau == 0.0:
            q = u  # static F_d: no memory
        Fd = q if form == 0 else fd_steady(vk, q, th)
        F[k] = s0 * z + s1 * zd + s2 * vk + Fd + b
        Z[k] = z
        Q[k] = q
        if k + 1 < n:
            h = t[k + 1] - t[k]
            u1 = _lag_input(v[k + 1], a[k + 1], th, form)
            if method == 1:
                z = z + h * zd
                if tau > 0.0:
                    q = q + h * (u - q) / tau
            else:
                vm = 0.5 * (vk + v[k + 1])
                if vm >= 0.0:
                    gm, cgm = _g_fast(vm, fcp, fsp, ivsp, alpha, shape, cutp, s0, rp)
                    zss = gm * is0
                else:
                    gm, cgm = _g_fast(vm, fcn, fsn, ivsn, alpha, shape, cutn, s0, rn)
                    zss = -gm * is0
                Gm = switch_gamma(vm, v1, v2, gform)
                # dz/dt = Gm (vm - a z): exact, same z_ss, rate Gm a (lugre.lugre_run form)
                z = z + (z - zss) * _em1(h * Gm * cgm * abs(vm))
                if tau > 0.0:
                    vn = v[k + 1]
                    if form == 0 and (vk < 0.0) != (vn < 0.0) and vk != vn:
                        # reversal inside the step: F_d^ss jumps between the +/- sets at
                        # v = 0; split the step there so the update stays exact
                        c = vk / (vk - vn)
                        ac = a[k] + c * (a[k + 1] - a[k])
                        q = _lag_step(q, u, _fd_set(0.0, ac, th, vk < 0.0), c * h, tau)
                        q = _lag_step(q, _fd_set(0.0, ac, th, vn < 0.0), u1,
                                      (1.0 - c) * h, tau)
                    else:
                        if abs(h - h_lag) > 1e-9 * h:  # sampling jitter of t: reuse
                            sl = h / tau
                            e_lag = math.exp(-sl)
                            phi_lag = -math.expm1(-sl) / sl if sl > 1e-12 else 1.0 - 0.5 * sl
                            h_lag = h
                        q = u1 + (q - u) * e_lag - (u1 - u) * phi_lag
            u = u1


@njit(cache=True, nogil=True)
def _kernel(t, v, a, load, x, th, method, state0):
    S = np.empty((t.size, 2))
    F = np.empty(t.size)
    Z = np.empty(t.size)
    Q = np.empty(t.size)
    mlugre_run(t, v, a, th, method, state0[0], state0[1], F, Z, Q)
    S[:, 0] = Z
    S[:, 1] = Q
    return F, S


@njit(cache=True, parallel=True)
def _population_kernel(t, v, a, load, x, Theta, method):
    npop = Theta.shape[0]
    F = np.empty((npop, t.size))
    for i in prange(npop):
        Z = np.empty(t.size)
        Q = np.empty(t.size)
        mlugre_run(t, v, a, Theta[i], method, 0.0, 0.0, F[i], Z, Q)
    return F


class ModifiedLuGre(DirectionalStribeck, FrictionModel):
    """Modified LuGre of seed 000; see the module docstring for the equations.

    Inputs: velocity ``v`` and acceleration ``a=`` [m/s^2] (derived from v by
    ``np.gradient`` when not given). States: ``z`` [m] and the lag state ``Fd`` [N]
    (``fd_form="lag"``) or ``a_f`` [m/s^2] (``fd_form="filtered_acceleration"``).

    Examples
    --------
    >>> import numpy as np
    >>> from friction import make_model
    >>> m = make_model("modified_lugre")
    >>> float(m.steady_state([0.05])[0])   # doctest: +ELLIPSIS
    7.0...
    >>> float(m.gamma_switch(m.params.v1))   # doctest: +ELLIPSIS
    0.99...
    """
    name = "modified_lugre"
    Params = ModifiedLuGreParams
    state_names = ("z", "Fd")
    extra_inputs = ("a",)
    theta_layout = _LAYOUT
    twins = {"Fc": "Fc_neg", "Fs": "Fs_neg", "vs": "vs_neg", "sigma2": "sigma2_neg",
             "f_a": "f_a_neg", "a_s": "a_s_neg", "v_c": "v_c_neg"}

    _kernel = staticmethod(_kernel)
    _population_kernel = staticmethod(_population_kernel)

    def __init__(self, params=None, **kwargs):
        """

        Parameters
        ----------
        params : ModifiedLuGreParams, optional
            The law's parameters; default their defaults.
        **kwargs
            Parameter values (SI units) replacing those of ``params`` (validated).
        """
        super().__init__(params, **kwargs)
        if self.params.fd_form == "filtered_acceleration":
            self.state_names = ("z", "a_f")

    #: preset constants of the switch (not identified in seed 000: not in its 20 parameters)
    presets = ("v1", "v2")

    def free_names(self) -> list[str]:
        """Parameters identification may vary: as the base, without the presets v1, v2."""
        return [n for n in super().free_names() if n not in self.presets]

    def _pack(self, p: ModifiedLuGreParams) -> np.ndarray:
        r = p.resolved
        return np.array([p.sigma0, p.sigma1, p.sigma2, r("sigma2", -1), p.Fc, r("Fc", -1),
                         p.Fs, r("Fs", -1), p.vs, r("vs", -1), p.alpha, p.b, SHAPES[p.shape],
                         p.f_a, r("f_a", -1), p.a_s, r("a_s", -1), p.v_c, r("v_c", -1),
                         p.beta, p.gamma, p.tau, p.v1, p.v2, GAMMA_FORMS[p.gamma_form],
                         FD_FORMS[p.fd_form]], dtype=np.float64)

    # -- analytic pieces (numpy) --------------------------------------------------------
    def _dir(self, name, v):
        p = self.params
        return np.where(np.asarray(v) >= 0, getattr(p, name), p.resolved(name, -1))

    def gamma_switch(self, v) -> np.ndarray:
        """Switch Gamma(v) in [0, 1] of Eq. (10) (``gamma_form``).

        Parameters
        ----------
        v : array_like
            Velocity [m/s].
        """
        s = np.abs(np.asarray(v, dtype=float))
        p = self.params
        if p.gamma_form == "cosine":
            r = np.clip((s - p.v1) / (p.v2 - p.v1), 0.0, 1.0)
            return 0.5 * (1.0 + np.cos(np.pi * r))
        kappa = 2.0 * _LN99 / (p.v2 - p.v1)
        arg = kappa * (s - 0.5 * (p.v1 + p.v2))
        e = np.exp(-np.abs(arg))  # stable logistic
        return np.where(arg > 0, e / (1.0 + e), 1.0 / (1.0 + e))

    def fd_steady(self, v, a) -> np.ndarray:
        """F_d^ss(v, a) [N] of Eq. (11): zero at a = 0, |F_d| up with |a|, down with |v|.

        Parameters
        ----------
        v : array_like
            Velocity [m/s].
        a : array_like
            Acceleration [m/s^2].
        """
        v = np.asarray(v, dtype=float)
        a = np.asarray(a, dtype=float)
        p = self.params
        acc = -np.expm1(-(np.abs(a) / self._dir("a_s", v)) ** p.beta)
        vel = np.exp(-(np.abs(v) / self._dir("v_c", v)) ** p.gamma)
        return self._dir("f_a", v) * np.sign(a) * acc * vel

    def steady_state(self, v, **inputs) -> np.ndarray:
        """Steady-state force at constant speed, Eq. (5): g(v) sgn(v) + sigma2 v + b [N].

        At constant speed a = 0, so F_d = 0 and dz/dt = 0. From any initial state this
        equilibrium is approached at the rate Gamma(v) sigma0 |v| / g(v): where Gamma is
        (nearly) zero the bristle state is frozen, by design of seed 000.
        """
        v = np.asarray(v, dtype=float)
        return self.g(v) * np.sign(v) + self.sigma2_of(v) * v + self.params.b

    def steady_state_state(self, v0, a=None, **inputs) -> np.ndarray:
        """State (z, q) settled at the constant velocity ``v0`` [m/s] (see
        :meth:`friction.base.FrictionModel.steady_state_state`).

        ``z = g(v0) sgn(v0) / sigma0`` [m] whatever the switch: where Gamma(v0) = 0 (the
        cosine form beyond v2) the bristle rate vanishes and the generic root finding has
        no slope, but the state the law was heading to is still this one. ``q`` is the lag
        state at the acceleration ``a`` [m/s^2] of that instant (0 when not given: constant
        speed): F_d^ss(v0, a) [N] (``fd_form="lag"``) or ``a`` itself
        (``"filtered_acceleration"``); 0 when tau = 0 (the state then carries nothing).
        """
        v0 = float(v0)
        p = self.params
        if v0 == 0.0 or not math.isfinite(v0):
            return np.zeros(2)
        z = float(self.g(v0)) * math.copysign(1.0, v0) / p.sigma0
        a0 = 0.0 if a is None else float(a)
        if p.tau == 0.0 or not math.isfinite(a0):
            q = 0.0
        elif p.fd_form == "lag":
            q = float(self.fd_steady(v0, a0))
        else:
            q = a0
        return np.array([z, q])

    def _zdot(self, z, v):
        p = self.params
        return float(self.gamma_switch(v)) * (v - p.sigma0 * abs(v) / float(self.g(v)) * z)

    def _need_a(self, a, what):
        if a is None:
            raise ValueError(f"modified_lugre.{what} needs the acceleration a= [m/s^2]")
        a = float(a)
        if not math.isfinite(a):
            raise ValueError(f"modified_lugre.{what}: a = {a!r} is not finite")
        return a

    def derivatives(self, state, v, a=None, **inputs) -> np.ndarray:
        """d(z, q)/dt at velocity ``v`` [m/s] and acceleration ``a`` [m/s^2].

        ``q`` is F_d (lag form) or the filtered acceleration; with tau = 0 it carries no
        dynamics (derivative 0) and ``a`` is not needed.
        """
        p = self.params
        zd = self._zdot(state[0], v)
        if p.tau == 0.0:
            return np.array([zd, 0.0])
        a = self._need_a(a, "derivatives")
        u = float(self.fd_steady(v, a)) if p.fd_form == "lag" else a
        return np.array([zd, (u - state[1]) / p.tau])

    def force(self, state, v, a=None, **inputs) -> float:
        """Friction force [N] of Eq. (8) from the state (z, q).

        With tau > 0, F_d follows from the lag state and ``a`` is not needed (no algebraic
        loop in a mass simulation); with tau = 0, F_d = F_d^ss(v, a) needs ``a``.
        """
        p = self.params
        if p.tau == 0.0:
            a = self._need_a(a, "force (tau = 0: F_d is algebraic in a)")
            Fd = float(self.fd_steady(v, a))
        elif p.fd_form == "lag":
            Fd = float(state[1])
        else:
            Fd = float(self.fd_steady(v, state[1]))
        return (p.sigma0 * state[0] + p.sigma1 * self._zdot(state[0], v)
                + float(self.sigma2_of(v)) * v + Fd + p.b)

    def z_max(self) -> float:
        """Bound of the bristle deflection: max over v of g(v)/sigma0 [m] (z0 = 0 start)."""
        p = self.params
        levels = [p.Fc, p.Fs, p.resolved("Fc", -1), p.resolved("Fs", -1)]
        return max(levels) / p.sigma0

