"""Improved LuGre model of an MRE base isolator (seed 002, YU et al. 2015, Eqs. 1a/1b).

    F    = beta y + eps dy/dt + c0 dx/dt + k0 x + f0                        (1a)
    dy/dt = dx/dt - alpha |dx/dt| y                                         (1b)

A LuGre element (beta ~ sigma0, eps ~ sigma1, alpha ~ sigma0/g, so the hysteretic variable
saturates at y_ss = sgn(v)/alpha) in parallel with a viscous damper c0, a spring k0 and an
offset f0 (reconstruction of ``EQUATIONS.md`` B.1, numerically corroborated by Table 4).

``swap_alpha_eps=True`` selects the alternative reading of B.1 (F = beta y + alpha dy/dt + ...,
dy/dt = dx/dt - eps |dx/dt| y): the roles *and units* of alpha and eps are exchanged. It
matches the paper's qualitative Fig. 12/15 text but not its Table 4.

Units. The paper works in mm, mm/s and (assumed) N. This module is SI: the state y is a
length [m], and every parameter that multiplies a length or a speed is converted by 1000:

    =======  =============  ===========  ======================
    name     paper unit     SI unit      SI value = paper x
    =======  =============  ===========  ======================
    beta     N/mm           N/m          1000
    alpha    1/mm           1/m          1000
    c0       N.s/mm         N.s/m        1000
    k0       N/mm           N/m          1000
    eps      N.s/mm         N.s/m        1000
    f0       N              N            1
    =======  =============  ===========  ======================

The forces are therefore the paper's forces, sample for sample (``from_paper_units`` does the
conversion). Defaults are Table 3 (the sensitivity reference set).

Simplified model (13a,b): beta = 10 N/mm, c0 = 0.1 N.s/mm, f0 = 0.01 N fixed
(:meth:`MRELuGre.simplified`). Current dependence (14a-c): the paper's coefficients are not
recoverable; :func:`parameters_at_current` uses the re-fits (14a*-c*) of ``EQUATIONS.md`` B.7 to
Table 6, and :func:`fit_current_dependence` redoes that fit.

Numerics: over one step (1b) is linear in y with decay a = alpha |v|, so the same exact
exponential update as the LuGre bristle (midpoint velocity) is stable at any step;
``method="euler"`` is the paper's Eq. (2d), y(t_{i+1}) = y(t_i) + dt dy/dt(t_i).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit, prange
from scipy.optimize import curve_fit

from .base import FrictionModel, FrictionParams, param
from .lugre import bristle_update

__all__ = ["MRELuGreParams", "MRELuGre", "mre_run", "PAPER_UNIT_SCALE", "TABLE3", "TABLE6",
           "SIMPLIFIED_FIXED", "parameters_at_current", "fit_current_dependence",
           "CURRENT_FIT", "TABLE4", "TABLE4_RANKING", "harmonic_motion"]

#: SI value = paper value x scale (paper: mm, mm/s, N)
PAPER_UNIT_SCALE = {"beta": 1e3, "alpha": 1e3, "c0": 1e3, "k0": 1e3, "eps": 1e3, "f0": 1.0}

#: seed 002 Table 3, paper units (N/mm, 1/mm, N.s/mm, N/mm, N.s/mm, N)
TABLE3 = {"beta": 3.2284, "alpha": 0.2014, "c0": 0.0489, "k0": 40.8042, "eps": 1.1224,
          "f0": 2.7990}

#: seed 002 Table 6 (simplified model, 4 Hz, 8 mm): current [A] -> (alpha 1/mm, k0 N/mm,
#: eps N.s/mm)
TABLE6 = {0.0: (1.89068, 5.85267, 0.00465), 1.0: (0.65156, 16.59743, 0.54887),
          2.0: (0.21915, 26.62946, 0.70404), 3.0: (0.17784, 36.32007, 0.82618)}

#: seed 002 Table 4: local / global sensitivity, (mean RMSE [N], proportion) per parameter
TABLE4 = {"local": {"beta": (3.2438, 0.0267), "alpha": (22.1178, 0.1822), "c0": (1.9210, 0.0158),
                    "k0": (64.4635, 0.5307), "eps": (28.9533, 0.2384), "f0": (0.7634, 0.0063)},
          "global": {"beta": (13.5312, 0.0353), "alpha": (5.4096, 0.217073),
                     "c0": (11.5693, 0.0249), "k0": (20.8427, 0.5211),
                     "eps": (4.1479, 0.1948), "f0": (0.0883, 0.0069)}}
#: Table 4 rankings as printed (the global one follows the proportions, not the mean RMSE)
TABLE4_RANKING = {"local": ("k0", "eps", "alpha", "beta", "c0", "f0"),
                  "global": ("k0", "alpha", "eps", "beta", "c0", "f0")}

#: Eq. (13a) constants, paper units (beta N/mm, c0 N.s/mm, f0 N)
SIMPLIFIED_FIXED = {"beta": 10.0, "c0": 0.1, "f0": 0.01}

#: Eqs. (14a*-c*) of EQUATIONS.md B.7 (our re-fit to Table 6, paper units):
#: alpha = A e^{-B I} + C,  k0 = A I + C,  eps = A (1 - e^{-B I}) + C
CURRENT_FIT = {"alpha": (1.788, 1.219, 0.105), "k0": (10.143, None, 6.135),
               "eps": (0.849, 0.969, 0.007)}


def _si(name: str, value: float) -> float:
    return value * PAPER_UNIT_SCALE[name]


@dataclass(frozen=True)
class MRELuGreParams(FrictionParams):
    """Parameters of Eqs. (1a,b) in SI units; defaults are seed 002 Table 3 converted."""
    beta: float = param(_si("beta", TABLE3["beta"]), "N/m",
                        "stiffness of the hysteretic LuGre element (sigma0-like)", lower=0,
                        search=(0.0, 2e4))
    alpha: float = param(_si("alpha", TABLE3["alpha"]), "1/m",
                         "inverse saturation of y (y_ss = 1/alpha); N.s/m if swap_alpha_eps",
                         lower=0, search=(1.0, 5e3), log=True)
    c0: float = param(_si("c0", TABLE3["c0"]), "N.s/m", "viscous damping", lower=0,
                      search=(0.0, 500.0))
    k0: float = param(_si("k0", TABLE3["k0"]), "N/m", "parallel spring stiffness", lower=0,
                      search=(0.0, 1e5))
    eps: float = param(_si("eps", TABLE3["eps"]), "N.s/m",
                       "gain on dy/dt (sigma1-like); 1/m if swap_alpha_eps", lower=0,
                       search=(0.0, 5e3))
    f0: float = param(TABLE3["f0"], "N", "initial force (offset)", search=(-10.0, 10.0))
    swap_alpha_eps: bool = False

    def _check_relations(self):
        if not isinstance(self.swap_alpha_eps, (bool, np.bool_)):
            raise TypeError(f"swap_alpha_eps must be a bool, got {self.swap_alpha_eps!r}")

    @property
    def decay(self) -> float:
        """Coefficient of |v| y in (1b) [1/m]."""
        return self.eps if self.swap_alpha_eps else self.alpha

    @property
    def ydot_gain(self) -> float:
        """Coefficient of dy/dt in (1a) [N.s/m]."""
        return self.alpha if self.swap_alpha_eps else self.eps


_LAYOUT = ("beta", "alpha", "c0", "k0", "eps", "f0", "swap_alpha_eps")
BETA, ALPHA, C0, K0, EPS, F0, SWAP = range(len(_LAYOUT))


@njit(cache=True, nogil=True)
def mre_run(t, v, x, th, method, y0, F, Y):
    """Simulate Eqs. (1a,b) for one packed theta along (t, v, x); writes F and Y in place."""
    n = t.size
    beta = th[BETA]
    c0 = th[C0]
    k0 = th[K0]
    f0 = th[F0]
    if th[SWAP] != 0.0:
        decay = th[EPS]
        gain = th[ALPHA]
    else:
        decay = th[ALPHA]
        gain = th[EPS]
    y = y0
    for k in range(n):
        vk = v[k]
        yd = vk - decay * abs(vk) * y
        F[k] = beta * y + gain * yd + c0 * vk + k0 * x[k] + f0
        Y[k] = y
        if k + 1 < n:
            h = t[k + 1] - t[k]
            if method == 1:
                y = y + h * yd  # Eq. (2d)
            else:
                vm = 0.5 * (vk + v[k + 1])
                y = bristle_update(y, vm, decay * abs(vm), h, 0)


@njit(cache=True, nogil=True)
def _kernel(t, v, a, load, x, th, method, state0):
    F = np.empty(t.size)
    Y = np.empty((t.size, 1))
    mre_run(t, v, x, th, method, state0[0], F, Y[:, 0])
    return F, Y


@njit(cache=True, parallel=True)
def _population_kernel(t, v, a, load, x, Theta, method):
    npop = Theta.shape[0]
    F = np.empty((npop, t.size))
    for i in prange(npop):
        Y = np.empty(t.size)
        mre_run(t, v, x, Theta[i], method, 0.0, F[i], Y)
    return F


class MRELuGre(FrictionModel):
    """Improved LuGre model of seed 002 (MRE base isolator); see the module docstring.

    Inputs: velocity ``v`` [m/s] and displacement ``x=`` [m] (integrated from v when absent).

    Examples
    --------
    >>> import numpy as np
    >>> from friction import make_model
    >>> m = make_model("mre_lugre")                     # Table 3, SI units
    >>> t = np.arange(0, 0.75, 1 / 2560)
    >>> x = 8e-3 * np.sin(2 * np.pi * 4 * t)
    >>> F = m.simulate(t, np.gradient(x, t), x=x)       # shear force [N]
    """
    name = "mre_lugre"
    Params = MRELuGreParams
    state_names = ("y",)
    extra_inputs = ("x",)
    theta_layout = _LAYOUT

    _kernel = staticmethod(_kernel)
    _population_kernel = staticmethod(_population_kernel)

    def conservative_force(self, x) -> np.ndarray:
        """Parallel spring and offset k0 x + f0 [N] (Eq. 1a): elastic, not friction."""
        return self.params.k0 * np.asarray(x, dtype=float) + self.params.f0

    def _pack(self, p: MRELuGreParams) -> np.ndarray:
        return np.array([p.beta, p.alpha, p.c0, p.k0, p.eps, p.f0,
                         1.0 if p.swap_alpha_eps else 0.0], dtype=np.float64)

    # -- constructors ---------------------------------------------------------------------
    @classmethod
    def from_paper_units(cls, **values) -> "MRELuGre":
        """Model from values in the paper's units (N/mm, 1/mm, N.s/mm, N); others default.

        Parameters
        ----------
        **values
            Parameter values in the paper's units (``beta`` [N/mm], ``alpha`` [1/mm], ``c0``
            [N.s/mm], ``k0`` [N/mm], ``eps`` [N.s/mm], ``f0`` [N]); an unknown name is a TypeError.
        """
        conv = {}
        for k, val in values.items():
            conv[k] = val * PAPER_UNIT_SCALE[k] if k in PAPER_UNIT_SCALE else val
        return cls(**conv)

    @classmethod
    def simplified(cls, alpha: float, k0: float, eps: float, **kwargs) -> "MRELuGre":
        """Simplified model (13a,b): beta = 1e4 N/m, c0 = 100 N.s/m, f0 = 0.01 N fixed.

        Parameters
        ----------
        alpha : float
            Inverse saturation [1/m].
        k0 : float
            Spring stiffness [N/m].
        eps : float
            Gain on dy/dt [N.s/m].
        **kwargs
            Further parameter values (SI units), as for :class:`MRELuGreParams`.
        """
        fixed = {k: _si(k, val) for k, val in SIMPLIFIED_FIXED.items()}
        return cls(alpha=alpha, k0=k0, eps=eps, **fixed, **kwargs)

    @classmethod
    def at_current(cls, current: float) -> "MRELuGre":
        """Simplified model with the current-dependent parameters of Eqs. (14a*-c*).

        Parameters
        ----------
        current : float
            Coil current [A].
        """
        return cls.simplified(**parameters_at_current(current))

    # -- analytic pieces ------------------------------------------------------------------
    def steady_state(self, v, x=0.0, **inputs) -> np.ndarray:
        """Force once y has saturated at constant velocity [N].

        F_ss = beta sgn(v) / a + c0 v + k0 x + f0, with a = alpha (eps if swapped); the
        spring term needs the displacement ``x`` [m] at which the force is read (default 0).
        At v = 0 the hysteretic variable keeps its history; this returns its y = 0 value.
        """
        p = self.params
        v = np.asarray(v, dtype=float)
        x = np.asarray(x, dtype=float)
        if p.decay <= 0:
            raise ValueError("no steady state: with "
                             f"{'eps' if p.swap_alpha_eps else 'alpha'} = 0 the hysteretic "
                             "variable y grows without bound at constant velocity")
        return p.beta * np.sign(v) / p.decay + p.c0 * v + p.k0 * x + p.f0

    def derivatives(self, state, v, **inputs) -> np.ndarray:
        p = self.params
        return np.array([v - p.decay * abs(v) * state[0]])

    def force(self, state, v, x=0.0, **inputs) -> float:
        p = self.params
        yd = self.derivatives(state, v)[0]
        return p.beta * state[0] + p.ydot_gain * yd + p.c0 * v + p.k0 * x + p.f0

    def z_max(self) -> float:
        """Bound of |y| from a zero start [m]: 1/alpha (1/eps if swapped)."""
        d = self.params.decay
        return 1.0 / d if d > 0 else 1.0

    def velocity_scale(self) -> float:
        """Typical speed of the seed's test (4 Hz, 8 mm): 0.2 m/s."""
        return 0.2

    def loop_area(self, t, v, x=None, *, method: str = "exact") -> float:
        """Dissipated energy per record, the integral of F dx along the motion [J].

        Parameters
        ----------
        t, v : array_like, shape (N,)
            Time [s] and velocity [m/s] of the motion.
        x : array_like, shape (N,), optional
            Displacement [m] (default: integrated from ``v``).
        method : {"exact", "euler"}
            Update of the hysteretic state (:data:`friction.base.METHODS`).
        """
        F = self.simulate(t, v, x=x, method=method)
        t = np.asarray(t, float)
        return float(np.trapezoid(F * np.asarray(v, float), t))


def parameters_at_current(current) -> dict:
    """Simplified-model parameters at coil current ``current`` [A], SI (Eqs. 14a*-c*).

    The paper's Eq. (14) coefficients are not recoverable; these are the least-squares
    re-fits of ``EQUATIONS.md`` B.7 to Table 6 (valid on 0-3 A):
    alpha = 1.788 e^{-1.219 I} + 0.105 [1/mm], k0 = 10.143 I + 6.135 [N/mm],
    eps = 0.849 (1 - e^{-0.969 I}) + 0.007 [N.s/mm].

    Returns
    -------
    dict with ``alpha`` [1/m], ``k0`` [N/m], ``eps`` [N.s/m] (floats or arrays like
    ``current``).
    """
    current = np.asarray(current, dtype=float)
    if np.any(~np.isfinite(current)) or np.any(current < 0):
        raise ValueError(f"current = {current!r} is out of bounds: must be finite and >= 0 [A]")
    A, B, C = CURRENT_FIT["alpha"]
    alpha = A * np.exp(-B * current) + C
    A, _, C = CURRENT_FIT["k0"]
    k0 = A * current + C
    A, B, C = CURRENT_FIT["eps"]
    eps = A * (1.0 - np.exp(-B * current)) + C
    out = {"alpha": _si("alpha", alpha), "k0": _si("k0", k0), "eps": _si("eps", eps)}
    return {k: (float(val) if np.ndim(val) == 0 else val) for k, val in out.items()}


def fit_current_dependence(current=None, alpha=None, k0=None, eps=None) -> dict:
    """Least-squares fit of the forms of Eqs. (14a*-c*) to (current, parameter) data.

    Parameters
    ----------
    current : array_like, optional
        Currents [A]; default the Table 6 currents.
    alpha, k0, eps : array_like, optional
        Parameter values at those currents, any consistent units (default Table 6,
        paper units).

    Returns
    -------
    dict
        ``alpha: (A, B, C)`` for A e^{-B I} + C, ``k0: (A, None, C)`` for A I + C,
        ``eps: (A, B, C)`` for A (1 - e^{-B I}) + C, in the units of the data.
    """
    if current is None:
        current = np.array(sorted(TABLE6))
        rows = np.array([TABLE6[c] for c in current])
        alpha, k0, eps = (rows[:, 0] if alpha is None else alpha,
                          rows[:, 1] if k0 is None else k0,
                          rows[:, 2] if eps is None else eps)
    current = np.asarray(current, float)
    alpha, k0, eps = (np.asarray(a, float) for a in (alpha, k0, eps))
    pa, _ = curve_fit(lambda i, A, B, C: A * np.exp(-B * i) + C, current, alpha,
                      p0=[alpha[0] - alpha[-1], 1.0, alpha[-1]])
    pk = np.polyfit(current, k0, 1)
    pe, _ = curve_fit(lambda i, A, B, C: A * (1.0 - np.exp(-B * i)) + C, current, eps,
                      p0=[eps[-1] - eps[0], 1.0, eps[0]])
    return {"alpha": tuple(float(c) for c in pa), "k0": (float(pk[0]), None, float(pk[1])),
            "eps": tuple(float(c) for c in pe)}


def harmonic_motion(frequency: float = 4.0, amplitude: float = 8e-3, rate: float = 256.0,
                    cycles: float = 3.0):
    """The seed's sinusoidal shear test: x = A sin(2 pi f t) sampled at ``rate``.

    Parameters
    ----------
    frequency : float
        Excitation frequency [Hz] (seed: 4 Hz).
    amplitude : float
        Displacement amplitude [m] (seed: 2, 4, 8 mm).
    rate : float
        Sampling rate [Hz] (seed: 256 Hz).
    cycles : float
        Number of cycles.

    Returns
    -------
    t, x, v : ndarray
        Time [s], displacement [m], velocity [m/s] (analytic derivative).
    """
    for name, val in (("frequency", frequency), ("amplitude", amplitude), ("rate", rate),
                      ("cycles", cycles)):
        if not (np.isfinite(val) and val > 0):
            raise ValueError(f"{name} = {val!r} is out of bounds: must be > 0")
    t = np.arange(0.0, cycles / frequency, 1.0 / rate)
    w = 2.0 * np.pi * frequency
    return t, amplitude * np.sin(w * t), amplitude * w * np.cos(w * t)
