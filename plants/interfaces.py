"""Connectors, defined once (the ``Interfaces`` package of the Modelica library).

Sign conventions
----------------
:class:`Flange` (translational)
    ``s`` position [m], ``v`` velocity [m/s], ``f`` force [N]. ``f`` is the force acting
    ON the component at that flange, counted positive in the +s direction. A cut between
    two connected flanges carries equal and opposite forces, so the force a component
    exerts on the body attached to its flange is ``-f``.
:class:`HydraulicPort`
    ``p`` pressure [Pa], ``q`` volume flow [m^3/s], positive INTO the component.

Two-flange compliant elements (spring, damper) derive from :class:`PartialCompliant`, which
writes the action/reaction pair once; a subclass adds the one constitutive line
``force(s_rel, v_rel)`` with ``s_rel = s_b - s_a`` and ``v_rel = v_b - v_a``.
"""
from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Flange", "HydraulicPort", "PartialCompliant"]


@dataclass
class Flange:
    """Translational flange: position s [m], velocity v [m/s], force f [N] on the component.

    ``f`` is positive when it pushes the component in +s.
    """
    s: float = 0.0
    v: float = 0.0
    f: float = 0.0


@dataclass
class HydraulicPort:
    """Hydraulic port: pressure p [Pa], volume flow q [m^3/s] (positive into the component)."""
    p: float = 0.0
    q: float = 0.0


class PartialCompliant:
    """Base of elements between two flanges with one constitutive force law.

    ``f = force(s_rel, v_rel)`` is the tension of the element (positive when it pulls the
    two flanges together, e.g. a stretched spring). The element is massless, so
    ``flange_b.f = f`` and ``flange_a.f = -f`` (forces on the element); the bodies receive
    the reactions: ``-f`` at flange b, ``+f`` at flange a.
    """

    def force(self, s_rel: float, v_rel: float) -> float:  # pragma: no cover - abstract
        """Tension [N] for relative position ``s_b - s_a`` [m] and velocity [m/s]."""
        raise NotImplementedError

    def connect(self, flange_a: Flange, flange_b: Flange) -> float:
        """Fill in the flange forces from the flange kinematics; returns the tension [N]."""
        f = self.force(flange_b.s - flange_a.s, flange_b.v - flange_a.v)
        flange_b.f = f
        flange_a.f = -f
        return f

    def reaction_on_b(self, s_rel: float, v_rel: float) -> float:
        """Force [N] the element exerts on the body at flange b (+s positive): ``-f``."""
        return -self.force(s_rel, v_rel)

    def reaction_on_a(self, s_rel: float, v_rel: float) -> float:
        """Force [N] the element exerts on the body at flange a (+s positive): ``+f``."""
        return self.force(s_rel, v_rel)
