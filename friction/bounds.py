"""Admissible bounds of a parameter, written once.

:class:`friction.base.ParamInfo` (a law's or a plant's parameter) and
:class:`fmus.variables.Var` (an FMU variable) check values and word their bounds with
:class:`Bounded`. The module imports nothing from the project: :mod:`fmus.build` carries it
into every pythonfmu FMU beside the slave runtime.
"""
from __future__ import annotations

import math

__all__ = ["Bounded"]


class Bounded:
    """Mixin of an object with attributes ``lower``, ``upper`` (floats, infinite: no bound)
    and ``lower_open``, ``upper_open`` (the bound itself excluded)."""

    lower: float
    upper: float
    lower_open: bool
    upper_open: bool

    def bound_text(self, name: str = "") -> str:
        """The bounds in words: ``"sigma0 > 0 and sigma0 <= 1e+09"`` (``"> 0"`` without a
        name), ``"finite"`` without bounds.

        Parameters
        ----------
        name : str
            Written before each bound.
        """
        lead = f"{name} " if name else ""
        parts = []
        if self.lower > -math.inf:
            parts.append(f"{lead}{'>' if self.lower_open else '>='} {self.lower:g}")
        if self.upper < math.inf:
            parts.append(f"{lead}{'<' if self.upper_open else '<='} {self.upper:g}")
        return " and ".join(parts) or "finite"

    def admissible(self, value) -> bool:
        """Whether ``value`` is finite and within the bounds.

        Parameters
        ----------
        value : float
            The value to check.
        """
        if not math.isfinite(value):
            return False
        if value < self.lower or (self.lower_open and value == self.lower):
            return False
        if value > self.upper or (self.upper_open and value == self.upper):
            return False
        return True
