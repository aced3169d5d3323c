"""Laws whose coefficients jump at a switching speed: the smooth law of each regime, and the
one definition of the regime classification and Filippov sliding along the switch.

``load_lugre`` switches its Table 3 coefficients at |v| = vc (seed 004), so its vector field
is discontinuous there. Integrators that must converge across the switch hold one smooth
regime over each step and follow the Filippov sliding motion along |v| = vc where both
regimes push the velocity onto it. :func:`regime_split` gives them the two smooth laws; the
functions below are the rules both plant integrators (``plants.stepper.PlantStepper`` and
``plants.reference.ReferenceIntegrator``) apply on the switching surface:

* :func:`side` - the regime off the surface: ``"low"`` for |v| < vc, else ``"high"``;
* :func:`surface_rate` - d|v|/dt of a field (> 0: towards the high side, < 0: towards
  the low side);
* :func:`filippov` - from the contact acceleration under each regime's field, the rate
  d|v|/dt of each (``g_low``, ``g_high``) and the Filippov weight ``alpha`` of the low
  regime that keeps d|v|/dt = 0 (the sliding field is ``alpha low + (1 - alpha) high``);
* :func:`surface_regime` - the regime on the surface: ``"slide"`` where both regimes push
  onto it, else the side the motion leaves to; a repulsive surface keeps the caller's side.

No scipy here: the stepper and the FMUs use this module.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from .base import FrictionModel

__all__ = ["RegimeSplit", "regime_split", "side", "surface_rate", "filippov",
           "surface_regime"]


@dataclass(frozen=True)
class RegimeSplit:
    """A law whose coefficients jump at |v| = ``vc``: the smooth law of each side.

    Attributes
    ----------
    vc : float
        Switching velocity [m/s] (> 0).
    low, high : FrictionModel
        The law with the coefficients of |v| < vc, and of |v| >= vc, everywhere.
    """
    vc: float
    low: FrictionModel
    high: FrictionModel

    def side(self, v: float) -> str:
        """``"low"`` for |v| < vc, else ``"high"`` (the law's own rule)."""
        return side(v, self.vc)


def regime_split(model: FrictionModel) -> RegimeSplit | None:
    """The two smooth regimes of a law with a velocity-triggered coefficient jump (its
    ``regimes()`` method), or ``None`` for a smooth law. A load-free ``load_lugre`` run has
    no jump (the coefficients multiply the load), but the split is returned all the same."""
    fn = getattr(model, "regimes", None)
    return fn() if callable(fn) else None


def side(v: float, vc: float) -> str:
    """Regime of velocity ``v`` [m/s] off the switching surface |v| = ``vc``: ``"low"`` for
    |v| < vc, else ``"high"``."""
    return "low" if abs(v) < vc else "high"


def surface_rate(v: float, a: float) -> float:
    """d|v|/dt [m/s^2] at contact velocity ``v`` [m/s] (nonzero) and acceleration ``a``
    [m/s^2]."""
    return math.copysign(1.0, v) * a


def filippov(v: float, a_low: float, a_high: float) -> tuple[float, float, float]:
    """Filippov weight on the switching surface at contact velocity ``v`` [m/s].

    Parameters
    ----------
    v : float
        Contact velocity [m/s] (on or near |v| = vc, so nonzero).
    a_low, a_high : float
        Contact acceleration [m/s^2] under the low and under the high regime's field.

    Returns
    -------
    alpha : float
        Weight of the low regime in ``alpha low + (1 - alpha) high``, the convex
        combination of both fields tangent to the surface (d|v|/dt = 0), clipped into
        [0, 1]; 0.5 where both fields have the same rate.
    g_low, g_high : float
        d|v|/dt [m/s^2] under each regime's field.
    """
    g_low, g_high = surface_rate(v, a_low), surface_rate(v, a_high)
    alpha = min(1.0, max(0.0, g_high / (g_high - g_low))) if g_high != g_low else 0.5
    return alpha, g_low, g_high


def surface_regime(g_low: float, g_high: float, prev: str) -> str:
    """Regime on the switching surface from the rates d|v|/dt of both fields.

    ``"slide"`` where both push onto the surface (``g_low > 0`` and ``g_high < 0``);
    ``"high"`` where the low field crosses it upwards and the high one does not push back;
    ``"low"`` where the high field crosses it downwards and the low one does not push back;
    otherwise (a repulsive surface, both fields point away) ``prev``, the side the caller
    keeps.
    """
    if g_low > 0 and g_high < 0:
        return "slide"
    if g_low > 0 and g_high >= 0:
        return "high"
    if g_low <= 0 and g_high < 0:
        return "low"
    return prev
