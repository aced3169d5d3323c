"""Hydraulic forging press at ultra-low speed (seed 004, LI, PAN, HUANG 2013).

Moving beam (x downward, [m]) driven by the major cylinders, held up by the supporting
(return) cylinders, loaded by the workpiece's deformation resistance and by friction
(seed 004 Eq. 1 solved for the acceleration)::

    m d2x/dt2 = p1 A1 + m g - F_sigma - p2 A2 - F_r                         (Eq. 1)

Hydraulics (:mod:`plants.hydraulics`):

* major chamber ``V1 = V10 + A1 x``, fed by a 3-way servo valve from supply ``ps``
  (drained to tank for a negative command): ``dp1/dt = beta/V1 (q_v - A1 dx/dt)``;
* supporting chamber ``V2 = V20 - A2 x``, discharging through a fixed orifice into the
  back-pressure accumulator ``p_acc`` that balances the beam:
  ``dp2/dt = beta/V2 (A2 dx/dt - q_o)``;
* spool ``tau_v dx_v/dt = x_max u - x_v``.

Deformation resistance F_sigma = f(T, rate, extent) (Eq. 2): the die/frame stiffness ``k_w``
in series with the viscoplastic flow of the workpiece (volume constant, height
``h = H0 - x_p``, contact area ``V_w / h``)::

    F_sigma = k_w max(x - gap - x_p, 0),    sigma = F_sigma h / V_w
    dx_p/dt = h eps_ref (sigma / sigma_f)^(1/m_r)
    sigma_f = sigma_ref (eps + eps0)^n exp(Q/(R T) - Q/(R T_ref))

so that in steady flow sigma = sigma_f (rate / eps_ref)^m_r: the flow stress of a hot titanium
alloy with strain-rate sensitivity ``m_r`` and hardening ``n`` at temperature ``T``.
Writing the rate law this way (plastic state, elastic force) keeps the ODE non-stiff at
ultra-low speed, where a rate-sensitive force ``F(v)`` would have a slope of 1e11 N.s/m.

Speed control (1 kHz, the paper's "speed control of the servo system"): the reference
position integrates the speed schedule of Table 1 (1.2, 0.1, 0.05, 0.002 mm/s for 50, 240, 80,
1000 s); the servo command is a flow feedforward ``A1 v_ref / (kq x_max sqrt(2 (ps - p1)/rho))``
(from the measured p1) plus a PI on the position error.

Friction: ``load_lugre`` (seed 004 Eqs. 4-11), load = F_sigma. Its Table 3 coefficients are
read per MN of deformation resistance (k1 = 103.95 kN/MN, k3 = 319.91 kN.s/mm per MN): the
per-kN reading makes the friction of a 1 MN load reach 1e8 N, which no press could move.

Crawling, the no-load Stribeck curve and their figure are studied in
:mod:`plants.studies.forging_press`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from friction.base import FrictionModel, param

from .base import Experiment, Plant, PlantParams
from .hydraulics import (OIL_BULK_MODULUS, OIL_DENSITY, chamber_dpdt, orifice_flow,
                         valve_3way_flow)

__all__ = ["ForgingPressParams", "ForgingPress", "press_friction", "TABLE1",
           "schedule_reference", "shortened_schedule", "press_dataset", "GAS_CONSTANT"]

GAS_CONSTANT = 8.314  # J/(mol K)
#: seed 004 Table 1 (isothermal forging rule): (speed [m/s], duration [s]); reductions
#: 60 / 24 / 4 / 2 mm
TABLE1 = ((1.2e-3, 50.0), (0.1e-3, 240.0), (0.05e-3, 80.0), (0.002e-3, 1000.0))


@dataclass(frozen=True)
class ForgingPressParams(PlantParams):
    """Press parameters (seed 004 prints none of them: a plausible isothermal press)."""
    m: float = param(8.0e4, "kg", "moving beam + pistons", lower=0, lower_open=True)
    g: float = param(9.80665, "m/s^2", "gravity (x points down)", lower=0)
    A1: float = param(0.75, "m^2", "major cylinders' area (3 cylinders)", lower=0,
                      lower_open=True)
    V10: float = param(0.3, "m^3", "major chamber volume at x = 0 (incl. pipes)", lower=0,
                       lower_open=True)
    A2: float = param(0.2, "m^2", "supporting cylinders' area (4 cylinders)", lower=0,
                      lower_open=True)
    V20: float = param(0.15, "m^3", "supporting chamber volume at x = 0", lower=0,
                       lower_open=True)
    beta_e: float = param(OIL_BULK_MODULUS, "Pa", "effective bulk modulus", lower=1e6)
    rho: float = param(OIL_DENSITY, "kg/m^3", "oil density", lower=0, lower_open=True)
    ps: float = param(25e6, "Pa", "supply pressure", lower=0, lower_open=True)
    pt: float = param(0.3e6, "Pa", "tank pressure", lower=0)
    p_acc: float = param(11.5e6, "Pa", "back-pressure accumulator of the supporting side",
                         lower=0)
    kq: float = param(0.61 * 0.02, "m", "servo valve Cd * area gradient", lower=0,
                      lower_open=True)
    x_max: float = param(1e-3, "m", "servo spool travel", lower=0, lower_open=True)
    tau_v: float = param(5e-3, "s", "spool time constant", lower=0, lower_open=True)
    overlap: float = param(0.0, "1", "spool overlap (dead band) as a fraction of x_max",
                           lower=0, upper=0.5)
    dp_lam: float = param(0.1e6, "Pa", "laminar-transition pressure of the orifice laws",
                          lower=0, lower_open=True)
    kq2_open: float = param(0.61 * 0.05 * 2e-3, "m^2", "supporting-side orifice Cd * area",
                            lower=0, lower_open=True)
    Kv: float = param(1.5, "1/s", "position-loop gain (flow units: u = Kv A1 e / Q_u)",
                      lower=0)
    Ki: float = param(0.5, "1/s", "integral gain relative to Kv", lower=0)
    q_x: float = param(5e-8, "m", "displacement sensor resolution (0: none)", lower=0)
    # workpiece (isothermal forging of a titanium-alloy disk)
    H0: float = param(0.12, "m", "workpiece initial height", lower=0, lower_open=True)
    D0: float = param(0.15, "m", "workpiece initial diameter", lower=0, lower_open=True)
    sigma_ref: float = param(30e6, "Pa", "flow stress at eps_ref, strain 1-eps0, T_ref",
                             lower=0)
    eps_ref: float = param(1e-3, "1/s", "reference strain rate", lower=0, lower_open=True)
    m_rate: float = param(0.25, "1", "strain-rate sensitivity", lower=0.01, upper=1)
    n_hard: float = param(0.05, "1", "strain-hardening exponent", lower=0, upper=1)
    eps0: float = param(0.02, "1", "strain offset of the hardening law", lower=0,
                        lower_open=True)
    T: float = param(1223.0, "K", "deformation temperature (isothermal)", lower=0,
                     lower_open=True)
    T_ref: float = param(1223.0, "K", "reference temperature of sigma_ref", lower=0,
                         lower_open=True)
    Q_act: float = param(3.0e5, "J/mol", "activation energy of the flow stress", lower=0)
    k_w: float = param(5e9, "N/m", "die + frame stiffness in series with the workpiece",
                       lower=0, lower_open=True)
    contact_gap: float = param(0.0, "m", "beam travel before the die touches", lower=0)

    @property
    def V_w(self) -> float:
        """Workpiece volume [m^3]."""
        return math.pi * (0.5 * self.D0) ** 2 * self.H0


def press_friction(**overrides) -> FrictionModel:
    """Seed-004 friction of seals + guide: ``load_lugre`` (Tables 2, 3 per MN)."""
    from friction import make_model
    base = dict(sigma0=2e10, k1_low=-0.87e-3, k2_low=0.33e-3, k3_low=0.04, k1_high=103.95e-3,
                k2_high=102.88e-3, k3_high=319.91)
    base.update(overrides)
    return make_model("load_lugre", **base)


def schedule_reference(t, schedule):
    """Reference position [m] and speed [m/s] of a piecewise-constant speed schedule.

    ``schedule`` is a sequence of (speed [m/s], duration [s]); after its end the reference
    holds still.
    """
    t = np.asarray(t, float)
    x = np.zeros_like(t)
    v = np.zeros_like(t)
    t0 = 0.0
    x0 = 0.0
    for speed, dur in schedule:
        m = (t >= t0) & (t < t0 + dur)
        x = np.where(m, x0 + speed * (t - t0), x)
        v = np.where(m, speed, v)
        x0 += speed * dur
        t0 += dur
        x = np.where(t >= t0, x0, x)
    return x, v


def shortened_schedule(factor: float = 0.1, min_duration: float = 5.0):
    """Table 1 with every step shortened by ``factor`` (at least ``min_duration`` [s])."""
    return tuple((v, max(min_duration, d * factor)) for v, d in TABLE1)


class ForgingPress(Plant):
    """Isothermal forging press of seed 004 under servo speed control (module docstring).

    Outputs: ``x`` beam travel [m] (down), ``v`` [m/s], ``a`` [m/s^2], ``p1``, ``p2`` [Pa],
    ``F_sigma`` deformation resistance [N], ``load`` (= F_sigma, the friction law's load
    input) [N], ``x_ref`` [m], ``v_ref`` [m/s], ``u`` valve
    command [-], ``F`` friction [N]. Options: ``schedule`` ((speed, duration), ...),
    ``workpiece`` (False: the no-load constant-speed tests of Section 4).

    Parameters
    ----------
    friction : FrictionModel or str, optional
        The guide's friction law (default :func:`press_friction`).
    **kwargs
        Plant parameter values (SI units), ``external_friction`` or ``params``, as for
        :class:`plants.base.Plant`.
    """

    name = "forging_press"
    Params = ForgingPressParams
    main_output = "x"
    data_rate = 100.0
    default_experiment = Experiment(start=0.0, stop=41.0, step=0.01)
    state_names = ("x", "v", "p1", "p2", "x_v", "x_p")
    state_scale = (1e-3, 1e-3, 1e6, 1e6, 1e-4, 1e-3)
    output_names = ("x", "v", "a", "p1", "p2", "F_sigma", "load", "x_ref", "v_ref", "u")
    discrete_names = ("u", "integ")
    control_rate = 1000.0
    max_substep = 2.5e-4
    options = {"schedule": ((1.2e-3, 6.0), (0.1e-3, 5.0), (0.05e-3, 5.0), (0.002e-3, 25.0)),
               "workpiece": True}
    signals = {"x": ("m", "beam travel, downwards"), "v": ("m/s", "beam velocity"),
               "a": ("m/s^2", "beam acceleration"), "p1": ("Pa", "major chamber pressure"),
               "p2": ("Pa", "supporting chamber pressure"),
               "F_sigma": ("N", "deformation resistance"),
               "load": ("N", "load input of the friction law (= F_sigma)"),
               "x_ref": ("m", "position reference"),
               "v_ref": ("m/s", "speed reference"), "u": ("1", "servo valve command"),
               "F": ("N", "friction (seals + guide), opposing v"),
               "F_friction": ("N", "friction force input (external friction)")}

    def __init__(self, friction=None, **kwargs):
        super().__init__(friction, **kwargs)
        self._set_substep()

    @classmethod
    def default_friction(cls) -> FrictionModel:
        return press_friction()

    def with_options(self, **options):
        new = super().with_options(**options)
        new._set_substep()
        return new

    def with_params(self, **values):
        new = super().with_params(**values)
        new._set_substep()
        return new

    # -- explicit stability of the fast integrator -------------------------------------------------
    def max_deformation_load(self) -> float:
        """Upper estimate of F_sigma over the schedule [N] (steady flow at each step's end)."""
        p = self.params
        if not self.opts["workpiece"]:
            return 0.0
        temp = math.exp(p.Q_act / GAS_CONSTANT * (1.0 / p.T - 1.0 / p.T_ref))
        red, Fmax = 0.0, 0.0
        for speed, dur in self.opts["schedule"]:
            red += max(speed, 0.0) * dur
            h = max(p.H0 - max(red - p.contact_gap, 0.0), 0.05 * p.H0)
            rate = max(speed, 0.0) / h
            strain = math.log(p.H0 / h)
            sigma = (p.sigma_ref * temp * (strain + p.eps0) ** p.n_hard
                     * (rate / p.eps_ref) ** p.m_rate)
            Fmax = max(Fmax, sigma * p.V_w / h)
        return min(Fmax, p.ps * p.A1 + p.m * p.g)  # the press cannot push harder than this

    def _set_substep(self) -> None:
        """Keep Heun stable against the friction's (load-dependent) viscous slope.

        The friction force enters the explicit update, so the step must satisfy
        h c / m < 2 with c = dF_ss/dv + sigma1 at the largest deformation load of the
        schedule (load_lugre's sigma2 grows with F_sigma); a factor 2 margin is kept.
        """
        base = type(self).max_substep
        law = self.friction
        if law is None:
            self.max_substep = base
            return
        speeds = [abs(sp) for sp, _ in self.opts["schedule"]] or [1e-3]
        v = max(max(speeds), 1e-4)
        vv = np.array([v, 1.01 * v])
        kw = {}
        if "load" in law.extra_inputs:
            kw["load"] = np.full(2, 1.2 * self.max_deformation_load())
        try:
            F = law.steady_state(vv, **kw)
        except Exception:  # a law without a steady state (or inadmissible load): keep default
            self.max_substep = base
            return
        c = abs(float(F[1] - F[0])) / (0.01 * v) + float(getattr(law.params, "sigma1", 0.0))
        self.max_substep = min(base, self.params.m / c) if c > 0 else base

    # -- pieces --------------------------------------------------------------------------------
    def _p1_balance(self) -> float:
        p = self.params
        return (p.p_acc * p.A2 - p.m * p.g) / p.A1

    def _theta(self) -> np.ndarray:
        """Packed parameters for the numba kernels (rebuilt when params change)."""
        p = self.params
        if getattr(self, "_theta_key", None) is not p:
            temp = math.exp(p.Q_act / GAS_CONSTANT * (1.0 / p.T - 1.0 / p.T_ref))
            self._theta_arr = np.array([
                p.m, p.g, p.A1, p.V10, p.A2, p.V20, p.beta_e, p.rho, p.ps, p.pt, p.p_acc,
                p.kq, p.x_max, p.tau_v, p.dp_lam, p.kq2_open, p.overlap, p.H0, p.V_w,
                p.sigma_ref * temp, p.eps_ref, p.m_rate, p.n_hard, p.eps0, p.k_w,
                p.contact_gap], dtype=np.float64)
            self._theta_key = p
        return self._theta_arr

    def deformation(self, x, x_p):
        """(F_sigma [N], plastic rate dx_p/dt [m/s]) at beam travel x and plastic reduction x_p.

        Parameters
        ----------
        x : float
            Beam travel [m].
        x_p : float
            Plastic reduction of the workpiece [m].
        """
        if not self.opts["workpiece"]:
            return 0.0, 0.0
        p = self.params
        if p.H0 - x_p <= 0.05 * p.H0:
            raise ValueError(f"workpiece crushed to h = {p.H0 - x_p:g} m (H0 = {p.H0:g} m): "
                             "schedule too long for the workpiece")
        return _deformation(x, x_p, self._theta())

    def _ref(self, t):
        x0 = 0.0
        t0 = 0.0
        for speed, dur in self.opts["schedule"]:
            if t < t0 + dur:
                return x0 + speed * max(t - t0, 0.0), speed
            x0 += speed * dur
            t0 += dur
        return x0, 0.0

    def _quantise(self, x):
        q = self.params.q_x
        return x if q == 0 else q * math.floor(x / q + 0.5)

    def _flow_gain(self, p1) -> float:
        p = self.params
        return p.kq * p.x_max * math.sqrt(2.0 * max(p.ps - p1, 0.1 * p.ps) / p.rho)

    # -- plant contract -------------------------------------------------------------------------
    def initial_state(self):
        p = self.params
        return np.array([0.0, 0.0, self._p1_balance(), p.p_acc, 0.0, 0.0])

    def initial_discrete(self):
        return np.array([0.0, 0.0])

    def derivatives(self, t, s, d, F, u):
        return _press_rhs(np.asarray(s, dtype=np.float64), float(d[0]), float(F),
                          self._theta(), bool(self.opts["workpiece"]))

    def contact(self, t, s, d, u):
        Fs, _ = self.deformation(float(s[0]), float(s[5]))
        return float(s[0]), float(s[1]), Fs

    def discrete_update(self, t, s, d, u):
        p = self.params
        Ts = 1.0 / self.control_rate
        self.deformation(float(s[0]), float(s[5]))  # raises if the workpiece is crushed
        x_m = self._quantise(float(s[0]))
        x_r, v_r = self._ref(t)
        e = x_r - x_m
        integ = d[1] + p.Ki * e * Ts
        Qu = self._flow_gain(float(s[2]))
        u_cmd = p.A1 * (v_r + p.Kv * (e + integ)) / Qu
        if abs(u_cmd) > 1.0:  # anti-windup: hold the integrator while saturated
            integ = d[1]
            u_cmd = max(-1.0, min(1.0, u_cmd))
        return np.array([u_cmd, integ])

    def output(self, t, s, d, F, u):
        ds = self.derivatives(t, s, d, F, u)
        Fs, _ = self.deformation(float(s[0]), float(s[5]))
        x_r, v_r = self._ref(t)
        return {"x": float(s[0]), "v": float(s[1]), "a": float(ds[1]), "p1": float(s[2]),
                "p2": float(s[3]), "F_sigma": Fs, "load": Fs, "x_ref": x_r, "v_ref": v_r,
                "u": float(d[0])}

    # -- analysis ---------------------------------------------------------------------------------
    def friction_from_eq1(self, res) -> np.ndarray:
        """Comprehensive friction F_r [N] from the recorded signals by Eq. 1 (the paper's way).

        Parameters
        ----------
        res : ndarray
            A simulation result (structured array with ``p1``, ``p2``, ``F_sigma``, ``a``).
        """
        p = self.params
        return (res["p1"] * p.A1 + p.m * p.g - res["F_sigma"] - res["p2"] * p.A2
                - p.m * res["a"])


# packed-parameter indices of the numba kernels
(_M, _G, _A1, _V10, _A2, _V20, _BETA, _RHO, _PS, _PT, _PACC, _KQ, _XMAX, _TAUV, _DPLAM, _KQ2,
 _OL, _H0, _VW, _SIGF, _EPSREF, _MR, _NH, _EPS0, _KW, _GAP) = range(26)


@njit(cache=True)
def _deformation(x, xp, th):
    """Elastic die/frame force and viscoplastic flow rate of the workpiece."""
    el = x - th[_GAP] - xp
    if el <= 0.0:
        return 0.0, 0.0
    F = th[_KW] * el
    h = th[_H0] - xp
    sigma = F * h / th[_VW]
    strain = math.log(th[_H0] / h)
    sigma_f = th[_SIGF] * (strain + th[_EPS0]) ** th[_NH]
    rate = th[_EPSREF] * (sigma / sigma_f) ** (1.0 / th[_MR])
    return F, h * rate


@njit(cache=True)
def _press_rhs(s, u_cmd, F, th, workpiece):
    """State derivative of the press (Eq. 1 + chambers + spool + workpiece)."""
    x, v, p1, p2, xv, xp = s[0], s[1], s[2], s[3], s[4], s[5]
    Fs = 0.0
    xp_dot = 0.0
    if workpiece:
        Fs, xp_dot = _deformation(x, xp, th)
    V1 = th[_V10] + th[_A1] * x
    V2 = th[_V20] - th[_A2] * x
    ol = th[_OL] * th[_XMAX]  # spool lap: no metering edge opens inside the dead band
    xe = max(abs(xv) - ol, 0.0)
    if xv < 0.0:
        xe = -xe
    q1 = valve_3way_flow(th[_KQ], xe, th[_PS], th[_PT], p1, th[_RHO], th[_DPLAM], 0.0)
    qo = orifice_flow(th[_KQ2], 1.0, p2 - th[_PACC], th[_RHO], th[_DPLAM])
    out = np.empty(6)
    out[0] = v
    out[1] = (p1 * th[_A1] + th[_M] * th[_G] - Fs - p2 * th[_A2] - F) / th[_M]
    out[2] = chamber_dpdt(th[_BETA], V1, q1, th[_A1], v)
    out[3] = chamber_dpdt(th[_BETA], V2, -qo, th[_A2], -v)  # stroke -x, outflow q_o
    out[4] = (th[_XMAX] * min(1.0, max(-1.0, u_cmd)) - xv) / th[_TAUV]
    out[5] = xp_dot
    return out


def press_dataset(res, plant: ForgingPress, name: str = "forging_press"):
    """A press run as a :class:`friction.dataset.Dataset`: F from Eq. 1, load = F_sigma."""
    from friction.dataset import Dataset
    return Dataset.from_arrays(res["time"], plant.friction_from_eq1(res), x=res["x"],
                               v=res["v"], a=res["a"], load=res["F_sigma"], name=name,
                               extra={"p1": np.asarray(res["p1"]), "p2": np.asarray(res["p2"])})
