"""Linear motor with a closed current loop (seed 003: ironless PMLSM, 27.5 N/A, 400 Hz).

The current amplifier's closed loop is a first-order lag from the commanded to the actual
current, ``di/dt = 2 pi f_c (i_cmd - i)``; the thrust is ``f = K_f i``. The commanded
current saturates at ``i_max`` (1e6 A by default, i.e. unlimited).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from friction.base import FrictionParams, param

__all__ = ["LinearMotor"]


@dataclass(frozen=True)
class LinearMotor(FrictionParams):
    """Ironless permanent-magnet linear synchronous motor with its current loop."""
    Kf: float = param(27.5, "N/A", "force constant (seed 003: 27.5 N/A_RMS)", lower=0,
                      lower_open=True)
    f_current: float = param(400.0, "Hz", "current-loop bandwidth (seed 003: 400 Hz)",
                             lower=0, lower_open=True)
    i_max: float = param(1e6, "A", "current command limit (default: unlimited)", lower=0,
                         lower_open=True)

    def current_derivative(self, i: float, i_cmd: float) -> float:
        """di/dt [A/s] of the closed current loop.

        Parameters
        ----------
        i : float
            Coil current [A].
        i_cmd : float
            Current command [A] (clipped to ``i_max``).
        """
        i_cmd = min(max(i_cmd, -self.i_max), self.i_max)
        return 2.0 * math.pi * self.f_current * (i_cmd - i)

    def force(self, i: float) -> float:
        """Thrust [N] at current ``i`` [A].

        Parameters
        ----------
        i : float
            Coil current [A].
        """
        return self.Kf * i

    def current_for(self, force: float) -> float:
        """Current command [A] for a desired thrust [N].

        Parameters
        ----------
        force : float
            Desired thrust [N].
        """
        return force / self.Kf
