"""Error metrics shared by identification, diagnosis and the co-simulation proofs."""
from __future__ import annotations

import numpy as np

__all__ = ["nrmse", "rmse"]


def rmse(measured, model) -> float:
    """Root-mean-square error [unit of the signal]."""
    d = np.asarray(measured, float) - np.asarray(model, float)
    return float(np.sqrt(np.mean(d * d)))


def nrmse(measured, model) -> float:
    """RMS(measured - model) / std(measured) (the contract's ``nrmse``; 0 is a perfect fit).

    Raises ``ValueError`` if the measured signal is constant (std = 0).
    """
    m = np.asarray(measured, float)
    sd = float(np.std(m))
    if not sd > 0:
        raise ValueError("nrmse: the measured signal is constant (standard deviation 0)")
    return rmse(m, model) / sd
