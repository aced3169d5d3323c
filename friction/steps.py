"""Sample steps cut where the velocity changes sign (shared by the rate-independent laws).

The kernels take the motion as linearly interpolated velocity samples. A step whose end
velocities have opposite signs contains a reversal at ``tr = h v0 / (v0 - v1)``; laws whose
state depends on the path of the displacement, not only on its net change (the elastoplastic
elements of :mod:`friction.gms`, the play operator of :mod:`friction.backlash`), advance
each side of the reversal separately. On each piece the velocity is linear in time and of
one sign, so its mean is the velocity at the piece's midpoint and its travel is exact.

``fmus/native/csrc/laws/fl_steps.h`` is the C twin of :func:`split_step`.
"""
from __future__ import annotations

from numba import njit

__all__ = ["split_step"]


@njit(cache=True, inline="always")
def split_step(v0, v1, h):
    """The step [0, h] with end velocities ``v0``, ``v1`` [m/s] as one or two pieces.

    Returns
    -------
    (T1, a1, b1, T2, a2, b2) : floats
        Durations [s] and end velocities [m/s] of the pieces; the second has ``T2 = 0``
        when the velocity keeps its sign over the step (then the first is the whole step).
        Across a reversal the first piece runs from ``v0`` to 0 and the second from 0 to
        ``v1``.
    """
    if v0 * v1 < 0.0:
        tr = h * (v0 / (v0 - v1))
        return tr, v0, 0.0, h - tr, 0.0, v1
    return h, v0, v1, 0.0, 0.0, 0.0
