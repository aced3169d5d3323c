"""Small validators that name the bad argument (scipy ``common.py`` style).

Every public entry point of frictionlab passes user arrays through these before any
numerics run, so bad input fails fast with a message that says *what* and *where*.
"""
from __future__ import annotations

import numpy as np

__all__ = ["ParameterError", "as_float_array", "check_finite", "check_time",
           "check_same_length", "check_signals"]


class ParameterError(ValueError):
    """A model parameter violates its admissible bound."""


def as_float_array(name: str, values) -> np.ndarray:
    """Convert ``values`` to a 1-D float64 array or raise naming ``name``."""
    try:
        arr = np.asarray(values, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{name}: cannot convert to a float array ({exc})") from None
    if arr.ndim == 0:
        raise ValueError(f"{name}: expected a 1-D array of samples, got a scalar")
    if arr.ndim != 1:
        raise ValueError(f"{name}: expected a 1-D array of samples, got shape {arr.shape}")
    return arr


def check_finite(name: str, arr: np.ndarray) -> None:
    """Raise ``ValueError`` naming the first NaN/inf sample of ``arr``."""
    bad = ~np.isfinite(arr)
    if bad.any():
        i = int(np.argmax(bad))
        raise ValueError(f"{name}[{i}] = {float(arr[i])!r} is not finite (first bad sample of "
                         f"{int(bad.sum())} in {name})")


def check_time(t: np.ndarray, name: str = "t") -> None:
    """Require a finite, strictly increasing time vector with at least 2 samples."""
    check_finite(name, t)
    if t.size < 2:
        raise ValueError(f"{name}: need at least 2 samples, got {t.size}")
    dt = np.diff(t)
    if np.any(dt <= 0):
        i = int(np.argmax(dt <= 0))
        raise ValueError(f"{name} must be strictly increasing: {name}[{i + 1}] = "
                         f"{float(t[i + 1])!r} <= {name}[{i}] = {float(t[i])!r}")


def check_same_length(reference: str, n: int, **arrays) -> None:
    """Raise if any of ``arrays`` does not have ``n`` samples."""
    for key, arr in arrays.items():
        if arr is not None and len(arr) != n:
            raise ValueError(f"length mismatch: {key} has {len(arr)} samples but {reference} "
                             f"has {n}")


def check_signals(t, v, **extra) -> tuple[np.ndarray, np.ndarray, dict]:
    """Validate a prescribed-motion record ``(t, v, extra...)``.

    Returns float arrays; ``extra`` entries that are ``None`` stay ``None``.
    """
    t = as_float_array("t", t)
    check_time(t)
    v = as_float_array("v", v)
    check_same_length("t", t.size, v=v)
    check_finite("v", v)
    out = {}
    for key, val in extra.items():
        if val is None:
            out[key] = None
            continue
        arr = as_float_array(key, val)
        check_same_length("t", t.size, **{key: arr})
        check_finite(key, arr)
        out[key] = arr
    return t, v, out
