"""Mechanical components (the ``Components`` and ``Sources`` roles of the Modelica library).

Each component is a frozen dataclass whose fields are parameters with unit, description and
bounds (``friction.base.param``), validated on creation. Compliant elements derive from
:class:`plants.interfaces.PartialCompliant` and add one constitutive line each.

The machines are built from them: the valve (seed 000) is a :class:`Mass` on a preloaded
:class:`Spring`; the damping rig's cylinder (seed 001) and the isolator's top plate
(seed 002) are masses on the :class:`Spring` and :class:`Damper` of their force sensors, the
rig's piston a :class:`Mass` or a :class:`PositionSource`; the XML-350 stage (seed 003) a
:class:`Mass` driven by :class:`plants.motor.LinearMotor`.

Examples
--------
>>> from plants.components import Mass, Spring, Damper
>>> body, spring, damper = Mass(m=2.0), Spring(c=1e3, preload=6e-3), Damper(d=5.0)
>>> s, v = 1e-3, 0.0                     # body on flange b, support (flange a) at 0
>>> f_on_body = spring.reaction_on_b(s, v) + damper.reaction_on_b(s, v)
>>> round(body.acceleration(f_on_body), 6)
-3.5
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from friction.base import FrictionParams, param

from .interfaces import PartialCompliant

__all__ = ["Mass", "Spring", "Damper", "PositionSource", "STANDARD_GRAVITY"]

STANDARD_GRAVITY = 9.80665  # m/s^2


@dataclass(frozen=True)
class Mass(FrictionParams):
    """Sliding mass: ``m a = sum of forces on it`` (+ gravity along +s if ``g`` != 0).

    ``g`` is the gravity component along +s [m/s^2] (``-9.80665`` for a body moving
    vertically with +s upwards, 0 for a horizontal stage).
    """
    m: float = param(1.0, "kg", "mass", lower=0, lower_open=True)
    g: float = param(0.0, "m/s^2", "gravity component along +s", lower=-100, upper=100)

    def acceleration(self, force: float) -> float:
        """Acceleration [m/s^2] under the total external force [N] (+s positive).

        Parameters
        ----------
        force : float
            Total external force on the mass [N] (+s positive).
        """
        return force / self.m + self.g

    def weight(self) -> float:
        """Gravity force along +s [N]."""
        return self.m * self.g


@dataclass(frozen=True)
class Spring(FrictionParams, PartialCompliant):
    """Linear spring with preload: tension ``f = c (s_rel + preload)``.

    ``preload`` [m] is the pre-deflection at ``s_rel = 0`` (seed 000: a valve spring
    compressed by 6 mm pushes the valve back with ``k (S + 6 mm)``).
    """
    c: float = param(1e3, "N/m", "spring stiffness", lower=0)
    preload: float = param(0.0, "m", "pre-deflection at zero relative position")

    def force(self, s_rel, v_rel=0.0):
        return self.c * (s_rel + self.preload)


@dataclass(frozen=True)
class Damper(FrictionParams, PartialCompliant):
    """Linear damper: tension ``f = d v_rel``."""
    d: float = param(0.0, "N.s/m", "damping coefficient", lower=0)

    def force(self, s_rel, v_rel):
        return self.d * v_rel


@dataclass(frozen=True)
class PositionSource:
    """Prescribed motion (an ideal kinematic drive) from a trajectory
    ``traj(t) -> (s, v, a)`` [m, m/s, m/s^2].

    ``traj`` is typically a :mod:`plants.sources` generator.
    """
    traj: Callable[[float], tuple[float, float, float]]

    def kinematics(self, t: float) -> tuple[float, float, float]:
        """Position [m], velocity [m/s] and acceleration [m/s^2] at time ``t`` [s].

        Parameters
        ----------
        t : float
            Time [s].
        """
        s, v, a = self.traj(t)
        return float(s), float(v), float(a)
