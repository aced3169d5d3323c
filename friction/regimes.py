"""Laws whose coefficients jump at a switching speed: the smooth law of each regime.

``load_lugre`` switches its Table 3 coefficients at |v| = vc (seed 004), so its vector field
is discontinuous there. Integrators that must converge across the switch hold one smooth
regime over each step and follow the Filippov sliding motion along |v| = vc where both
regimes push the velocity onto it (``plants.base.PlantStepper``, the plants' reference
integrator). :func:`regime_split` gives them the two smooth laws. No scipy here: the
stepper and the FMUs use this module.
"""
from __future__ import annotations

from dataclasses import dataclass

from .base import FrictionModel

__all__ = ["RegimeSplit", "regime_split"]


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
        return "low" if abs(v) < self.vc else "high"


def regime_split(model: FrictionModel) -> RegimeSplit | None:
    """The two smooth regimes of a law with a velocity-triggered coefficient jump (its
    ``regimes()`` method), or ``None`` for a smooth law. A load-free ``load_lugre`` run has
    no jump (the coefficients multiply the load), but the split is returned all the same."""
    fn = getattr(model, "regimes", None)
    return fn() if callable(fn) else None
