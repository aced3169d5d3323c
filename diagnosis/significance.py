"""Is a candidate's held-out improvement real? A paired test of two models' held-out errors.

A gap whose RMS lies within the noise can still be a real effect: over thousands of held-out
samples a systematic error of a third of the noise's RMS is resolved. The test is the
Diebold-Mariano comparison of predictive accuracy: the loss differential
``d_k = r_base,k^2 - r_cand,k^2`` of the two models on the same held-out samples, its mean
over its long-run standard error (Newey-West, Bartlett weights, so a residual correlated in
time is not counted as independent samples). Under "no better than the base" the statistic is
close to standard normal; the diagnosis compares it with the one-sided quantile of a
family-wise level split over the candidates tried (Bonferroni).

Diebold, F. X., Mariano, R. S. (1995). Comparing predictive accuracy. J. Bus. Econ. Stat.
13(3), 253-263. Newey, W. K., West, K. D. (1987). Econometrica 55(3), 703-708.
"""
from __future__ import annotations

import numpy as np
from scipy.stats import norm

__all__ = ["improvement_z", "z_threshold", "FAMILY_LEVEL"]

#: family-wise false-attribution level of the significance path of :func:`diagnosis.decide`
FAMILY_LEVEL = 0.01


def improvement_z(r_base, r_cand, lags: int | None = None) -> float:
    """Diebold-Mariano statistic of a held-out improvement [-].

    Parameters
    ----------
    r_base, r_cand : array_like
        Held-out residuals (measured - predicted) [N] of the base and of the candidate, on the
        same samples.
    lags : int, optional
        Newey-West truncation lag [samples]; default ``ceil(4 (n/100)^(2/9))``.

    Returns
    -------
    float
        mean(r_base^2 - r_cand^2) / its HAC standard error: positive when the candidate
        predicts better, about N(0, 1) when it is no better; 0 for fewer than 3 samples or
        identical residuals.
    """
    rb = np.asarray(r_base, float)
    rc = np.asarray(r_cand, float)
    if rb.shape != rc.shape:
        raise ValueError(f"r_base and r_cand need the same length, got {rb.size} and {rc.size}")
    ok = np.isfinite(rb) & np.isfinite(rc)
    d = rb[ok] ** 2 - rc[ok] ** 2
    n = d.size
    if n < 3:
        return 0.0
    L = int(np.ceil(4.0 * (n / 100.0) ** (2.0 / 9.0))) if lags is None else int(lags)
    L = max(0, min(L, n - 1))
    m = float(np.mean(d))
    x = d - m
    s = float(x @ x) / n
    for k in range(1, L + 1):
        s += 2.0 * (1.0 - k / (L + 1.0)) * float(x[k:] @ x[:-k]) / n
    if s <= 0.0:  # a constant differential: no spread to compare with (kept finite for JSON)
        return 0.0 if m == 0.0 else float(np.sign(m) * 1e12)
    return float(m / np.sqrt(s / n))


def z_threshold(n_tests: int, level: float = FAMILY_LEVEL) -> float:
    """One-sided normal quantile of ``level`` split over ``n_tests`` comparisons [-]."""
    if not 0.0 < level < 1.0:
        raise ValueError(f"level must lie in (0, 1), got {level}")
    return float(norm.isf(level / max(int(n_tests), 1)))
