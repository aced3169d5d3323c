"""Load-dependent LuGre friction of a giant forging press (seed 004, LI, PAN, HUANG 2013).

    dz/dt = v - sigma0 |v| / g(v) z                                        (Eq. 5)
    F     = sigma0 z + sigma1 dz/dt + sigma2 v                             (Eq. 4)
    g(v)  = Fc + (Fs - Fc) exp(-(v/vs)^2)                                  (Eq. 6)
    Fc = Fc0 + k1 F_sigma,  Fs = Fs0 + k2 F_sigma,  sigma2 = sigma20 + k3 F_sigma   (Eqs. 9-11)

F_sigma is the deformation load (input ``load=`` [N]). The coefficients (k1, k2, k3) take
one set below the critical velocity vc and another above it (Table 3). The steady state is
F_ss = g(v) sgn(v) + sigma2 v (Eq. 8); without load its minimum lies at vc, the larger root of

    2 v (Fs - Fc) exp(-(v/vs)^2) = sigma2 vs^2                            (Eq. 13)

(:func:`critical_velocity`; Table 2 gives vc = 0.19 mm/s).

Regime split. The paper splits the coefficients "taking vc as the critical velocity" and
defines vc for the no-load curve; the loaded vc depends on which coefficients apply, which
would make the split circular. We therefore split at the **no-load** critical velocity vc0
computed from (Fc0, Fs0, vs, sigma20) by Eq. (13), unless the parameter ``vc`` is given
explicitly. Under load the steady-state curve jumps at vc (the coefficients change there),
as the paper's two-regime Table 3 implies. Eq. (12) is only a diagnostic
(:func:`regime_condition`): its literal decode contradicts Table 3 (``EQUATIONS.md`` C).

Units. The paper uses kN, mm/s and kN.s/mm; this module is SI. Table 2/3 converted:
Fs0 = 377.39 kN = 3.7739e5 N, Fc0 = 2.0323e5 N, vs = 0.076 mm/s = 7.6e-5 m/s,
sigma20 = 19.77 kN.s/mm = 1.977e7 N.s/m; k1, k2 are dimensionless (kN/kN = N/N);
k3 [s/mm] -> [s/m] is x 1000 (sigma2/F_sigma: kN.s/mm / kN = s/mm), so k3 = 0.04 s/mm is 40 s/m
and 319.91 s/mm is 3.1991e5 s/m. The seed gives no sigma0 / sigma1: the defaults
(sigma0 = 4e9 N/m, i.e. a pre-sliding deflection Fs0/sigma0 of about 0.1 mm; sigma1 = 1e6 N.s/m)
are assumptions, not paper values.

Numerics: as :mod:`friction.lugre` (exact exponential bristle update with the midpoint
velocity and load; ``method="euler"`` available).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit, prange
from scipy.optimize import brentq

from ._validation import ParameterError
from .base import FrictionModel, FrictionParams, param
from .lugre import bristle_update
from .regimes import RegimeSplit

__all__ = ["LoadLuGreParams", "LoadLuGre", "critical_velocity", "regime_condition",
           "load_lugre_run", "TABLE2_SI", "TABLE3_SI"]

#: seed 004 Table 2 in SI (Fs0, Fc0 [N], vs [m/s], sigma20 [N.s/m]); printed vc = 0.19 mm/s
TABLE2_SI = {"Fs0": 377.39e3, "Fc0": 203.23e3, "vs": 0.076e-3, "sigma20": 19.77e3 / 1e-3}
#: seed 004 Table 3 in SI: (k1 [-], k2 [-], k3 [s/m]) below and above vc
TABLE3_SI = {"low": (-0.87, 0.33, 0.04e3), "high": (103.95, 102.88, 319.91e3)}


def critical_velocity(Fc: float, Fs: float, vs: float, sigma2: float) -> float:
    """Velocity of the minimum of the steady-state curve, Eq. (13) [m/s].

    Solves 2 v (Fs - Fc) exp(-(v/vs)^2) = sigma2 vs^2 for its larger root (the smaller one
    is the local maximum near v = 0).

    Parameters
    ----------
    Fc, Fs : float
        Coulomb and static friction levels [N].
    vs : float
        Stribeck velocity [m/s] (> 0).
    sigma2 : float
        Viscous coefficient [N.s/m] (>= 0).

    Returns
    -------
    float
        vc [m/s]; ``nan`` when the curve has no interior minimum (Fs <= Fc, or sigma2 too
        large for the Stribeck dip: (Fs - Fc)/sigma2 < vs e^{1/2}/sqrt(2)); ``inf`` when
        sigma2 = 0 and Fs > Fc (the curve decreases towards Fc for ever).
    """
    for name, val in (("Fc", Fc), ("Fs", Fs), ("vs", vs), ("sigma2", sigma2)):
        if not math.isfinite(val):
            raise ValueError(f"{name} = {val!r} is not finite")
    if not vs > 0:
        raise ParameterError(f"vs = {vs!r} is out of bounds: must be vs > 0 [m/s]")
    if sigma2 < 0:
        raise ParameterError(f"sigma2 = {sigma2!r} is out of bounds: must be sigma2 >= 0 [N.s/m]")
    dF = Fs - Fc
    if dF <= 0:
        return math.nan
    if sigma2 == 0:
        return math.inf
    # h(u) = 2 u D e^{-u^2} - vs with u = v/vs, D = dF/sigma2 [m/s]: max at u = 1/sqrt(2)
    D = dF / sigma2

    def h(u):
        return 2.0 * u * D * math.exp(-u * u) - vs

    lo = 1.0 / math.sqrt(2.0)
    if h(lo) < 0:
        return math.nan
    hi = 2.0 * lo
    while h(hi) > 0:
        hi *= 2.0
    return vs * brentq(h, lo, hi, xtol=1e-15, rtol=4 * np.finfo(float).eps)


def regime_condition(k1: float, k2: float, k3: float, Fs0: float, Fc0: float,
                     sigma20: float) -> dict:
    """Diagnostic of Eq. (12) for one set of coefficients (SI units).

    Delta = (k2 - k1) sigma20 - k3 (Fs0 - Fc0) [N.s/m] is the sign of
    d[(Fs - Fc)/sigma2]/dF_sigma at zero load; on the branch v > vs/sqrt(2) a larger
    (Fs - Fc)/sigma2 moves the critical velocity up, so Delta > 0 means vc rises with load.

    Returns
    -------
    dict
        ``delta``; ``literal_low`` / ``literal_high``: whether the literal decode of Eq. (12)
        for the regime 0 < v < vc (Delta < 0) / v > vc (Delta >= 0) holds;
        ``vc_moves``: ``"up"``, ``"down"`` or ``"none"`` with load (alternative reading).
    """
    delta = (k2 - k1) * sigma20 - k3 * (Fs0 - Fc0)
    return {"delta": float(delta), "literal_low": bool(delta < 0),
            "literal_high": bool(delta >= 0),
            "vc_moves": "up" if delta > 0 else ("down" if delta < 0 else "none")}


@dataclass(frozen=True)
class LoadLuGreParams(FrictionParams):
    """Parameters of the load-dependent LuGre law (SI; defaults seed 004 Tables 2 and 3)."""
    sigma0: float = param(4e9, "N/m", "bristle stiffness (assumed; not in seed 004)", lower=0,
                          lower_open=True, upper=1e13, search=(1e7, 1e11), log=True)
    sigma1: float = param(1e6, "N.s/m", "micro-damping (assumed; not in seed 004)", lower=0,
                          search=(0.0, 1e8))
    Fc0: float = param(TABLE2_SI["Fc0"], "N", "Coulomb friction without load", lower=0,
                       lower_open=True, search=(1e4, 1e6))
    Fs0: float = param(TABLE2_SI["Fs0"], "N", "static friction without load", lower=0,
                       lower_open=True, search=(1e4, 1e6))
    vs: float = param(TABLE2_SI["vs"], "m/s", "Stribeck velocity", lower=0, lower_open=True,
                      search=(1e-6, 1e-3), log=True)
    sigma20: float = param(TABLE2_SI["sigma20"], "N.s/m", "viscous coefficient without load",
                           lower=0, search=(0.0, 1e8))
    k1_low: float = param(TABLE3_SI["low"][0], "1", "dFc/dF_sigma for |v| < vc",
                          search=(-10.0, 10.0))
    k2_low: float = param(TABLE3_SI["low"][1], "1", "dFs/dF_sigma for |v| < vc",
                          search=(-10.0, 10.0))
    k3_low: float = param(TABLE3_SI["low"][2], "s/m", "dsigma2/dF_sigma for |v| < vc",
                          search=(-1e3, 1e3))
    k1_high: float = param(TABLE3_SI["high"][0], "1", "dFc/dF_sigma for |v| >= vc",
                           search=(-200.0, 200.0))
    k2_high: float = param(TABLE3_SI["high"][1], "1", "dFs/dF_sigma for |v| >= vc",
                           search=(-200.0, 200.0))
    k3_high: float = param(TABLE3_SI["high"][2], "s/m", "dsigma2/dF_sigma for |v| >= vc",
                           search=(-1e6, 1e6))
    vc: float | None = param(None, "m/s", "regime-split velocity (None: no-load critical "
                             "velocity of Eq. 13)", lower=0, lower_open=True,
                             search=(1e-5, 1e-3), log=True)

    def split_velocity(self) -> float:
        """Velocity at which the coefficients switch regime [m/s] (see module docstring)."""
        if self.vc is not None:
            return self.vc
        return critical_velocity(self.Fc0, self.Fs0, self.vs, self.sigma20)

    def _check_relations(self):
        vc = self.split_velocity()
        if not (vc > 0) or math.isinf(vc):
            raise ParameterError(
                f"the no-load curve (Fc0 = {self.Fc0:g}, Fs0 = {self.Fs0:g}, vs = {self.vs:g}, "
                f"sigma20 = {self.sigma20:g}) has no Stribeck minimum (Eq. 13 has no root); "
                "give the regime-split velocity vc explicitly")

    def coefficients(self, regime: str) -> tuple[float, float, float]:
        """(k1, k2, k3) of ``regime`` ``"low"`` (|v| < vc) or ``"high"``."""
        if regime not in ("low", "high"):
            raise ValueError(f"regime must be 'low' or 'high', got {regime!r}")
        return (getattr(self, f"k1_{regime}"), getattr(self, f"k2_{regime}"),
                getattr(self, f"k3_{regime}"))


_LAYOUT = ("sigma0", "sigma1", "Fc0", "Fs0", "vs", "sigma20", "k1_low", "k2_low", "k3_low",
           "k1_high", "k2_high", "k3_high", "vc")
S0, S1, FC0, FS0, VS, S20, K1L, K2L, K3L, K1H, K2H, K3H, VC = range(len(_LAYOUT))


@njit(cache=True, inline="always")
def _loaded(v, load, th):
    """g(v) and sigma2 at velocity v and deformation load ``load`` (regime by |v| vs vc)."""
    if abs(v) < th[VC]:
        k1, k2, k3 = th[K1L], th[K2L], th[K3L]
    else:
        k1, k2, k3 = th[K1H], th[K2H], th[K3H]
    fc = th[FC0] + k1 * load
    fs = th[FS0] + k2 * load
    r = v / th[VS]
    return fc + (fs - fc) * math.exp(-r * r), th[S20] + k3 * load


@njit(cache=True, nogil=True)
def load_lugre_run(t, v, load, th, method, z0, F, Z):
    """Simulate one parameter set along (t, v, load); writes F[k], Z[k] in place.

    A sample whose loaded Stribeck level g is not positive, or a theta whose split velocity
    vc is not positive/NaN, gives NaN from there on (inadmissible parameter set).
    """
    n = t.size
    s0 = th[S0]
    s1 = th[S1]
    z = z0
    if not th[VC] > 0.0:  # no regime split (a population row without Stribeck minimum)
        F[:] = np.nan
        Z[:] = np.nan
        return
    for k in range(n):
        vk = v[k]
        g, s2 = _loaded(vk, load[k], th)
        if not g > 0.0:
            for j in range(k, n):
                F[j] = np.nan
                Z[j] = np.nan
            return
        zd = vk - s0 * abs(vk) / g * z
        F[k] = s0 * z + s1 * zd + s2 * vk
        Z[k] = z
        if k + 1 < n:
            h = t[k + 1] - t[k]
            if method == 1:
                z = z + h * zd
            else:
                vm = 0.5 * (vk + v[k + 1])
                gm, _ = _loaded(vm, 0.5 * (load[k] + load[k + 1]), th)
                if not gm > 0.0:
                    gm = g
                z = bristle_update(z, vm, s0 * abs(vm) / gm, h, 0)


@njit(cache=True, nogil=True)
def _kernel(t, v, a, load, x, th, method, state0):
    F = np.empty(t.size)
    Z = np.empty((t.size, 1))
    load_lugre_run(t, v, load, th, method, state0[0], F, Z[:, 0])
    return F, Z


@njit(cache=True, parallel=True)
def _population_kernel(t, v, a, load, x, Theta, method):
    npop = Theta.shape[0]
    F = np.empty((npop, t.size))
    for i in prange(npop):
        Z = np.empty(t.size)
        load_lugre_run(t, v, load, Theta[i], method, 0.0, F[i], Z)
    return F


class LoadLuGre(FrictionModel):
    """Load-dependent LuGre law of seed 004; see the module docstring.

    Examples
    --------
    >>> import numpy as np
    >>> from friction import make_model
    >>> m = make_model("load_lugre")
    >>> round(m.vc * 1e3, 3)                       # no-load critical velocity [mm/s]
    0.192
    >>> m.steady_state([1e-3], load=[1e5]).shape   # 1 mm/s under 100 kN
    (1,)
    """
    name = "load_lugre"
    Params = LoadLuGreParams
    state_names = ("z",)
    extra_inputs = ("load",)
    theta_layout = _LAYOUT

    _kernel = staticmethod(_kernel)
    _population_kernel = staticmethod(_population_kernel)

    def _pack(self, p: LoadLuGreParams) -> np.ndarray:
        return np.array([p.sigma0, p.sigma1, p.Fc0, p.Fs0, p.vs, p.sigma20, p.k1_low,
                         p.k2_low, p.k3_low, p.k1_high, p.k2_high, p.k3_high,
                         p.split_velocity()], dtype=np.float64)

    @property
    def vc(self) -> float:
        """Regime-split velocity [m/s] (no-load critical velocity unless given)."""
        return float(self.theta[VC])

    def regimes(self) -> RegimeSplit:
        """The smooth law of each side of |v| = vc (:class:`friction.regimes.RegimeSplit`):
        the coefficients of |v| < vc, and of |v| >= vc, at every speed."""
        cached = getattr(self, "_regimes", None)
        if cached is None or cached[0] is not self.params:  # cached per parameter set
            p = self.params
            vc = self.vc
            low = type(self)(p.replace(k1_high=p.k1_low, k2_high=p.k2_low, k3_high=p.k3_low,
                                       vc=vc))
            high = type(self)(p.replace(k1_low=p.k1_high, k2_low=p.k2_high,
                                        k3_low=p.k3_high, vc=vc))
            cached = self._regimes = (p, RegimeSplit(vc, low, high))
        return cached[1]

    def population_theta(self, names, X) -> np.ndarray:
        """As the base, but an automatic vc follows varied no-load parameters row by row."""
        Theta = super().population_theta(names, X)
        names = list(names)
        if (self.params.vc is None and "vc" not in names
                and any(n in names for n in ("Fc0", "Fs0", "vs", "sigma20"))):
            for row in Theta:
                try:
                    vc = critical_velocity(row[FC0], row[FS0], row[VS], row[S20])
                except ValueError:
                    vc = math.nan
                row[VC] = vc if vc > 0 and math.isfinite(vc) else math.nan
        return Theta

    # -- checks on the load ---------------------------------------------------------------
    def _check_load(self, v, load):
        """Raise if the load makes a Stribeck level or sigma2 inadmissible (naming the sample)."""
        g, s2, fc, fs = self._levels(v, load)
        for name, arr, ok in (("Fc", fc, fc > 0), ("Fs", fs, fs > 0), ("sigma2", s2, s2 >= 0)):
            bad = ~ok
            if np.any(bad):
                i = int(np.argmax(bad))
                raise ValueError(
                    f"load[{i}] = {float(np.broadcast_to(load, bad.shape)[i])!r} N makes {name} = "
                    f"{float(arr[i]):g} out of bounds (must be {name} {'>=' if name == 'sigma2' else '>'} 0)")

    def _levels(self, v, load):
        p = self.params
        v = np.asarray(v, float)
        load = np.asarray(load, float)
        low = np.abs(v) < self.vc
        k1 = np.where(low, p.k1_low, p.k1_high)
        k2 = np.where(low, p.k2_low, p.k2_high)
        k3 = np.where(low, p.k3_low, p.k3_high)
        fc = p.Fc0 + k1 * load
        fs = p.Fs0 + k2 * load
        s2 = p.sigma20 + k3 * load
        g = fc + (fs - fc) * np.exp(-(v / p.vs) ** 2)
        return g, s2, fc, fs

    def simulate(self, t, v, *, load=None, **kwargs):
        """Friction force along a prescribed motion under a deformation load.

        Parameters
        ----------
        t, v : array_like, shape (N,)
            Time [s] and velocity [m/s].
        load : array_like, shape (N,)
            Deformation load F_sigma [N] (required).
        **kwargs
            ``method``, ``state0``, ``return_state`` as :meth:`FrictionModel.simulate`.
        """
        if load is None:
            raise ValueError(f"{self.name} needs the load= array (deformation load [N])")
        _, v_arr, _, load_arr, _ = self._inputs(t, v, load=load)  # names bad samples
        self._check_load(v_arr, load_arr)
        return super().simulate(t, v, load=load_arr, **kwargs)

    def g(self, v, load=0.0) -> np.ndarray:
        """Loaded Stribeck curve g(v) [N].

        Parameters
        ----------
        v : array_like
            Velocity [m/s].
        load : float or array_like
            Deformation load F_sigma [N].
        """
        return self._levels(v, load)[0]

    def steady_state(self, v, load=None, **inputs) -> np.ndarray:
        """Steady-state force F_ss = g(v) sgn(v) + sigma2 v [N] (Eq. 8) at load ``load`` [N].

        ``load`` defaults to 0 (the no-load Stribeck curve of Table 2).
        """
        v = np.asarray(v, dtype=float)
        load = np.zeros_like(v) if load is None else np.asarray(load, dtype=float)
        if np.any(~np.isfinite(load)):
            flat = np.atleast_1d(load)
            i = int(np.argmax(~np.isfinite(flat)))
            raise ValueError(f"load[{i}] = {flat[i]!r} is not finite")
        self._check_load(v, load)
        g, s2, _, _ = self._levels(v, load)
        return g * np.sign(v) + s2 * v

    def loaded_critical_velocity(self, load: float, regime: str = "high") -> float:
        """Critical velocity of Eq. (13) with the loaded levels of ``regime`` [m/s].

        Parameters
        ----------
        load : float
            Deformation load F_sigma [N].
        regime : {"low", "high"}
            Whose coefficients k1, k2, k3 load the levels.
        """
        k1, k2, k3 = self.params.coefficients(regime)
        p = self.params
        return critical_velocity(p.Fc0 + k1 * load, p.Fs0 + k2 * load, p.vs,
                                 p.sigma20 + k3 * load)

    def regime_condition(self) -> dict:
        """Eq. (12) diagnostic for both regimes (see :func:`regime_condition`)."""
        p = self.params
        return {r: regime_condition(*p.coefficients(r), p.Fs0, p.Fc0, p.sigma20)
                for r in ("low", "high")}

    def derivatives(self, state, v, load=0.0, **inputs) -> np.ndarray:
        g, _, _, _ = self._levels(v, load)
        return np.array([v - self.params.sigma0 * abs(v) / float(g) * state[0]])

    def force(self, state, v, load=0.0, **inputs) -> float:
        _, s2, _, _ = self._levels(v, load)
        zd = self.derivatives(state, v, load=load)[0]
        return self.params.sigma0 * state[0] + self.params.sigma1 * zd + float(s2) * v

    def z_max(self, load: float = 0.0) -> float:
        """Largest steady bristle deflection max(Fc, Fs)/sigma0 at ``load`` [m].

        Parameters
        ----------
        load : float
            Deformation load F_sigma [N].
        """
        p = self.params
        levels = [p.Fc0 + p.k1_low * load, p.Fc0 + p.k1_high * load,
                  p.Fs0 + p.k2_low * load, p.Fs0 + p.k2_high * load]
        return max(levels) / p.sigma0

    def velocity_scale(self) -> float:
        """Typical speed of the press: ten times the critical velocity [m/s]."""
        return 10.0 * self.vc
