"""Interfaces, defined once (the ``Interfaces`` package of the Modelica library).

Sign conventions
----------------
Translational (:class:`PartialCompliant`)
    A massless element between two flanges: flange ``a`` (the support side) and flange
    ``b`` (the body side), relative position ``s_rel = s_b - s_a`` [m] and velocity
    ``v_rel = v_b - v_a`` [m/s]. Forces on bodies are counted positive in +s.
:class:`HydraulicPort`
    ``p`` pressure [Pa], ``q`` volume flow [m^3/s], positive INTO the component.

Two-flange compliant elements (spring, damper) derive from :class:`PartialCompliant`, which
writes the action/reaction pair once; a subclass adds the one constitutive line
``force(s_rel, v_rel)``. The machines build their springs and dampers from them
(:mod:`plants.components`).
"""
from __future__ import annotations

from dataclasses import dataclass

__all__ = ["HydraulicPort", "PartialCompliant"]


@dataclass
class HydraulicPort:
    """Hydraulic port: pressure p [Pa], volume flow q [m^3/s] (positive into the component)."""
    p: float = 0.0
    q: float = 0.0


class PartialCompliant:
    """Base of elements between two flanges with one constitutive force law.

    ``f = force(s_rel, v_rel)`` is the tension of the element (positive when it pulls the
    two flanges together, e.g. a stretched spring). The element is massless, so the bodies
    receive equal and opposite reactions: ``-f`` at flange b, ``+f`` at flange a.
    """

    def force(self, s_rel: float, v_rel: float) -> float:  # pragma: no cover - abstract
        """Tension [N] for relative position ``s_b - s_a`` [m] and velocity [m/s].

        Parameters
        ----------
        s_rel : float
            Relative position ``s_b - s_a`` [m].
        v_rel : float
            Relative velocity [m/s].
        """
        raise NotImplementedError

    def reaction_on_b(self, s_rel: float, v_rel: float) -> float:
        """Force [N] the element exerts on the body at flange b (+s positive): ``-f``.

        Parameters
        ----------
        s_rel, v_rel : float
            As for :meth:`force`.
        """
        return -self.force(s_rel, v_rel)

    def reaction_on_a(self, s_rel: float, v_rel: float) -> float:
        """Force [N] the element exerts on the body at flange a (+s positive): ``+f``.

        Parameters
        ----------
        s_rel, v_rel : float
            As for :meth:`force`.
        """
        return self.force(s_rel, v_rel)
