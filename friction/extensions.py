"""Force extensions of a friction law: what the diagnosis' candidate effects add to a law.

``extension_force(F, v, a, x, load, t, e)`` takes a law's force ``F`` [N] and returns it with
the extensions switched on in the packed vector ``e`` (layout :data:`EXTENSION_PARAMS`),
applied in the order multiplicative then additive:

* ``load``         levels affine in the normal load (seed 004 Eqs. 9-11):
                   ``F (1 + k_L (load - L0) / L0)``, never of the opposite sign;
* ``drift``        levels changing over time: ``F (1 + k_drift (t - t0) / T)``;
* ``position``     levels along the stroke: ``F (1 + sum_k c_xk P_k(xi))`` with Legendre
                   polynomials ``P_k`` of the stroke coordinate ``xi`` in [-1, 1];
* ``acceleration`` the acceleration-dependent part of seed 000:
                   ``f_a tanh(a / a_s) exp(-|v| / v_c)``.

One formula serves the in-process diagnosis (:class:`diagnosis.effect_law.EffectLaw`) and
the ``friction_effects`` FMU block, so a candidate re-simulated through FMUs is the same
candidate.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

__all__ = ["EXTENSIONS", "EXTENSION_PARAMS", "EXTENSION_INDEX", "extension_force",
           "pack_extensions"]

#: extension names, in the order of their switches in the packed vector
EXTENSIONS = ("acceleration", "position", "drift", "load")

#: packed layout: (name, default, unit, description)
EXTENSION_PARAMS = (
    ("use_acc", 0.0, "1", "acceleration-dependent part on (1) or off (0)"),
    ("f_a", 0.0, "N", "amplitude of the acceleration-dependent part"),
    ("a_s", 1.0, "m/s2", "acceleration scale of the acceleration-dependent part (> 0)"),
    ("v_c", 1.0, "m/s", "velocity over which the acceleration-dependent part fades (> 0)"),
    ("use_pos", 0.0, "1", "position-dependent levels on (1) or off (0)"),
    ("x_lo", 0.0, "m", "start of the stroke the position series refers to"),
    ("x_hi", 1.0, "m", "end of the stroke the position series refers to (> x_lo)"),
    ("c_x1", 0.0, "1", "Legendre coefficient 1 of the relative level along the stroke"),
    ("c_x2", 0.0, "1", "Legendre coefficient 2 of the relative level along the stroke"),
    ("c_x3", 0.0, "1", "Legendre coefficient 3 of the relative level along the stroke"),
    ("c_x4", 0.0, "1", "Legendre coefficient 4 of the relative level along the stroke"),
    ("use_drift", 0.0, "1", "level drift over time on (1) or off (0)"),
    ("k_drift", 0.0, "1", "relative level change per duration T"),
    ("t0", 0.0, "s", "time the drift starts from"),
    ("T", 1.0, "s", "duration the drift rate refers to (> 0)"),
    ("use_load", 0.0, "1", "load-dependent levels on (1) or off (0)"),
    ("L0", 1.0, "N", "reference normal load (> 0)"),
    ("k_L", 0.0, "1", "relative level change per relative load change (1: Amontons)"),
)

#: index of each name in the packed vector
EXTENSION_INDEX = {p[0]: i for i, p in enumerate(EXTENSION_PARAMS)}


@njit(cache=True)
def extension_force(F, v, a, x, load, t, e):
    """Law force ``F`` [N] with the extensions of the packed vector ``e`` at velocity ``v``
    [m/s], acceleration ``a`` [m/s^2], position ``x`` [m], normal load ``load`` [N] and
    time ``t`` [s]."""
    if e[15] > 0.5:  # load: levels affine in the normal load, never of opposite sign
        r = 1.0 + e[17] * (load - e[16]) / e[16]
        F = F * max(r, 0.0)
    if e[11] > 0.5:  # drift: relative change per duration T
        F = F * (1.0 + e[12] * (t - e[13]) / e[14])
    if e[4] > 0.5:  # position: Legendre series along the stroke
        span = e[6] - e[5]
        if span < 1e-12:
            span = 1e-12
        xi = 2.0 * (x - e[5]) / span - 1.0
        xi = min(1.0, max(-1.0, xi))
        x2 = xi * xi
        p = (e[7] * xi + e[8] * 0.5 * (3.0 * x2 - 1.0) + e[9] * 0.5 * (5.0 * x2 - 3.0) * xi
             + e[10] * (35.0 * x2 * x2 - 30.0 * x2 + 3.0) / 8.0)
        F = F * (1.0 + p)
    if e[0] > 0.5:  # acceleration: grows with |a|, fades with |v|
        F = F + e[1] * math.tanh(a / e[2]) * math.exp(-abs(v) / e[3])
    return F


def pack_extensions(effects: dict, *, x_lo: float = 0.0, x_hi: float = 1.0, t0: float = 0.0,
                    T: float = 1.0, L0: float | None = None) -> np.ndarray:
    """Packed vector of :func:`extension_force`.

    Parameters
    ----------
    effects : dict
        Extension name (:data:`EXTENSIONS`) -> its parameters (``f_a`` [N], ``a_s``
        [m/s^2], ``v_c`` [m/s]; ``c_x1..c_x4`` [-]; ``k_drift`` [-]; ``k_L`` [-]).
    x_lo, x_hi : float
        Stroke the position series refers to [m].
    t0, T : float
        Start and duration the drift refers to [s].
    L0 : float
        Reference normal load [N] (needed by ``load``).
    """
    e = np.array([p[1] for p in EXTENSION_PARAMS], float)
    ix = EXTENSION_INDEX
    if "position" in effects and not x_hi > x_lo:
        raise ValueError(f"x_hi = {x_hi!r} is out of bounds: must be > x_lo = {x_lo!r} [m]")
    if "drift" in effects and not T > 0:
        raise ValueError(f"T = {T!r} is out of bounds: must be > 0 [s]")
    for name, p in effects.items():
        if name == "acceleration":
            e[ix["use_acc"]] = 1.0
            for k in ("a_s", "v_c"):
                if not p[k] > 0:
                    raise ValueError(f"{k} = {p[k]!r} is out of bounds: must be > 0 "
                                     f"[{'m/s^2' if k == 'a_s' else 'm/s'}]")
            for k in ("f_a", "a_s", "v_c"):
                e[ix[k]] = p[k]
        elif name == "position":
            e[ix["use_pos"]] = 1.0
            e[ix["x_lo"]], e[ix["x_hi"]] = x_lo, x_hi
            for k in range(1, 5):
                e[ix[f"c_x{k}"]] = p.get(f"c_x{k}", 0.0)
        elif name == "drift":
            e[ix["use_drift"]] = 1.0
            e[ix["k_drift"]] = p["k_drift"]
            e[ix["t0"]], e[ix["T"]] = t0, T
        elif name == "load":
            if L0 is None or not L0 > 0:
                raise ValueError("the load extension needs a positive reference load L0 [N]")
            e[ix["use_load"]] = 1.0
            e[ix["L0"]], e[ix["k_L"]] = L0, p["k_L"]
        else:
            raise ValueError(f"{name!r} is not a force extension; choose from {EXTENSIONS}")
    return e
