"""Hydraulic components: compressible chamber and servo-valve orifice flow (seed 004's press).

Chamber (one side of a cylinder, volume ``V = V0 + A x``, bulk modulus ``beta_e``)::

    dp/dt = beta_e / V * (q - A dx/dt)                                  (pressure build-up)

with ``q`` the volume flow INTO the chamber [m^3/s] (:class:`plants.interfaces.HydraulicPort`
convention) and ``x`` the piston stroke that enlarges the chamber. The oil column of a chamber
is a spring of stiffness ``beta_e A^2 / V`` on the piston.

Servo valve (sharp-edged orifice, turbulent)::

    q = Cd w x_v sqrt(2 |dp| / rho) sgn(dp)

``sqrt(|dp|)`` has an infinite slope at ``dp = 0``, which stiff integrators cannot take; the
flow is regularised below the laminar transition pressure ``dp_lam``::

    q = Cd w x_v sqrt(2/rho) dp / (dp^2 + dp_lam^2)^(1/4)

which is smooth, odd, linear for ``|dp| << dp_lam`` (laminar) and within 1 % of the turbulent
law for ``|dp| > 7 dp_lam``. A 3-way valve feeds one chamber from supply ``ps`` for
``x_v > 0`` and drains it to tank ``pt`` for ``x_v < 0``; its spool follows the command
through a first-order lag ``tau_v``.

The numba kernels (:func:`orifice_flow`, :func:`valve_3way_flow`, :func:`chamber_dpdt`) are
what plant steppers call; the dataclasses validate parameters and evaluate the same equations
from Python.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from friction.base import FrictionParams, param

from .interfaces import HydraulicPort

__all__ = ["HydraulicChamber", "ServoValve", "orifice_flow", "valve_3way_flow",
           "chamber_dpdt", "OIL_DENSITY", "OIL_BULK_MODULUS"]

OIL_DENSITY = 870.0          # kg/m^3, mineral hydraulic oil
OIL_BULK_MODULUS = 7.0e8     # Pa, effective (entrained air and hoses lower it from ~1.6e9)


@njit(cache=True, inline="always")
def orifice_flow(kq, xv, dp, rho, dp_lam):
    """Regularised orifice flow [m^3/s]: ``kq xv sqrt(2/rho) dp / (dp^2 + dp_lam^2)^(1/4)``.

    ``kq = Cd w`` [m] (discharge coefficient times area gradient), ``xv`` opening [m],
    ``dp`` pressure drop across the orifice [Pa] (flow in its direction), ``rho`` [kg/m^3].
    """
    return kq * xv * math.sqrt(2.0 / rho) * dp / (dp * dp + dp_lam * dp_lam) ** 0.25


@njit(cache=True, inline="always")
def valve_3way_flow(kq, xv, ps, pt, p, rho, dp_lam, leak):
    """Flow [m^3/s] into a chamber at pressure ``p`` from a 3-way spool at opening ``xv``.

    ``xv > 0`` connects supply ``ps`` to the chamber, ``xv < 0`` the chamber to tank ``pt``;
    ``leak`` [m^3/(s Pa)] is the centred-spool leakage conductance to both.
    """
    q = leak * (ps - p) - leak * (p - pt)
    if xv > 0.0:
        q += orifice_flow(kq, xv, ps - p, rho, dp_lam)
    elif xv < 0.0:
        q -= orifice_flow(kq, -xv, p - pt, rho, dp_lam)
    return q


@njit(cache=True, inline="always")
def chamber_dpdt(beta, V, q, A, xdot):
    """dp/dt [Pa/s] of a chamber of volume ``V`` [m^3], inflow ``q``, piston ``A``, ``xdot``."""
    return beta / V * (q - A * xdot)


@dataclass(frozen=True)
class HydraulicChamber(FrictionParams):
    """One cylinder chamber (or a group of identical cylinders lumped together).

    ``x`` is the stroke that enlarges the chamber [m]; ``V = V0 + A x``.
    """
    A: float = param(0.1, "m^2", "piston area (sum over lumped cylinders)", lower=0,
                     lower_open=True)
    V0: float = param(0.05, "m^3", "chamber volume at x = 0 (incl. pipes)", lower=0,
                      lower_open=True)
    beta_e: float = param(OIL_BULK_MODULUS, "Pa", "effective bulk modulus of the oil",
                          lower=1e6, upper=3e9)
    p_min: float = param(1e4, "Pa", "pressure floor (cavitation/vapour pressure)", lower=0)

    def volume(self, x: float) -> float:
        """Chamber volume [m^3] at stroke ``x`` [m]; raises if it collapses."""
        V = self.V0 + self.A * x
        if not V > 0:
            raise ValueError(f"chamber volume V0 + A x = {V:g} m^3 <= 0 at x = {x:g} m "
                             f"(V0 = {self.V0:g} m^3 too small for the stroke)")
        return V

    def dpdt(self, port: HydraulicPort, x: float, xdot: float) -> float:
        """Pressure rate [Pa/s] for the flow at ``port`` and piston motion (x, xdot)."""
        return float(chamber_dpdt(self.beta_e, self.volume(x), port.q, self.A, xdot))

    def force(self, p: float) -> float:
        """Piston force [N] of pressure ``p`` [Pa] (pushing toward larger ``x``)."""
        return p * self.A

    def hydraulic_stiffness(self, x: float) -> float:
        """Oil-column stiffness ``beta_e A^2 / V`` [N/m] at stroke ``x``."""
        return self.beta_e * self.A ** 2 / self.volume(x)


@dataclass(frozen=True)
class ServoValve(FrictionParams):
    """3-way servo valve: regularised orifice flow and a first-order spool.

    The spool position ``x_v`` follows ``x_max u`` (normalised command ``u`` in [-1, 1]) with
    time constant ``tau_v``; the metering edge opens only beyond the overlap
    ``overlap * x_max`` (0: critically lapped).
    """
    Cd: float = param(0.61, "1", "discharge coefficient", lower=0, lower_open=True, upper=1)
    w: float = param(0.02, "m", "area gradient (orifice width per spool travel)", lower=0,
                     lower_open=True)
    x_max: float = param(1e-3, "m", "spool travel at full command", lower=0, lower_open=True)
    tau_v: float = param(5e-3, "s", "spool time constant", lower=0, lower_open=True)
    ps: float = param(25e6, "Pa", "supply pressure", lower=0)
    pt: float = param(0.2e6, "Pa", "tank pressure", lower=0)
    rho: float = param(OIL_DENSITY, "kg/m^3", "oil density", lower=0, lower_open=True)
    dp_lam: float = param(0.1e6, "Pa", "laminar-transition pressure of the regularisation",
                          lower=0, lower_open=True)
    leak: float = param(0.0, "m^3/(s.Pa)", "centred-spool leakage conductance", lower=0)
    overlap: float = param(0.0, "1", "spool overlap (dead band) as a fraction of x_max",
                           lower=0, upper=0.5)

    def _check_relations(self):
        from friction._validation import ParameterError
        if self.pt >= self.ps:
            raise ParameterError(f"pt = {self.pt:g} Pa must be below ps = {self.ps:g} Pa")

    @property
    def kq(self) -> float:
        """Cd w [m]."""
        return self.Cd * self.w

    def metering_opening(self, x_v):
        """Opening of the metering edge [m]: the spool travel beyond the overlap, signed."""
        x_v = np.asarray(x_v, float)
        return np.sign(x_v) * np.maximum(np.abs(x_v) - self.overlap * self.x_max, 0.0)

    def flow(self, x_v, p) -> np.ndarray:
        """Flow [m^3/s] into the chamber at pressure ``p`` for spool position ``x_v`` [m]."""
        xb, pb = np.broadcast_arrays(self.metering_opening(x_v), np.asarray(p, float))
        out = np.array([valve_3way_flow(self.kq, a, self.ps, self.pt, b, self.rho,
                                        self.dp_lam, self.leak)
                        for a, b in zip(xb.ravel(), pb.ravel())]).reshape(xb.shape)
        return out if out.ndim else float(out)

    def turbulent_flow(self, x_v, dp) -> np.ndarray:
        """Un-regularised ``Cd w x_v sqrt(2 |dp| / rho) sgn(dp)`` [m^3/s] (for checks)."""
        dp = np.asarray(dp, float)
        return self.kq * np.asarray(x_v, float) * np.sqrt(2 * np.abs(dp) / self.rho) * np.sign(dp)

    def spool_rate(self, x_v: float, u: float) -> float:
        """dx_v/dt [m/s] of the spool for command ``u`` (clipped to [-1, 1])."""
        u = min(1.0, max(-1.0, u))
        return (self.x_max * u - x_v) / self.tau_v
