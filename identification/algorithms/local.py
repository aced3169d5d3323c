"""Gradient-based least squares (scipy.optimize.least_squares) and its multistart variant.

The residual is the simulated minus measured force, scaled so that ``sum r^2 = nrmse^2``.
The Jacobian is a forward difference whose D perturbed parameter sets run as one population
through the numba kernel (one parallel call per Jacobian instead of D serial simulations).
Confidence intervals follow from the final Jacobian (Gauss-Newton covariance).
"""
from __future__ import annotations

import numpy as np
from scipy.optimize import least_squares

from ..problem import BudgetExhausted
from .base import Algorithm, latin_hypercube

__all__ = ["LeastSquares", "MultistartLeastSquares", "run_least_squares"]


def run_least_squares(problem, u0, *, method="trf", max_nfev=None, ftol=1e-10, xtol=1e-10,
                      gtol=1e-10, diff_step=1e-6):
    """Trust-region reflective least squares from ``u0`` inside the unit cube.

    Returns the scipy result (``x``, ``jac``, ``fun``) or ``None`` if the budget ran out
    before the first iteration finished.
    """
    cache = {}

    def fun(u):
        r = problem.residuals(u)
        cache["u"], cache["r"] = np.array(u), r
        return r

    def jac(u):
        r0 = cache["r"] if "u" in cache and np.array_equal(cache["u"], u) else None
        return problem.jacobian(u, r0=r0, step=diff_step)

    u0 = np.clip(np.asarray(u0, float), 1e-9, 1 - 1e-9)
    try:
        return least_squares(fun, u0, jac=jac, bounds=(0.0, 1.0), method=method,
                             x_scale="jac", ftol=ftol, xtol=xtol, gtol=gtol, max_nfev=max_nfev)
    except BudgetExhausted:
        return None


class LeastSquares(Algorithm):
    """``scipy.optimize.least_squares`` (trust-region reflective, bounded) from the model's
    current values. Fast and precise near the optimum; local."""
    name = "least_squares"
    kind = "local"
    steppable = False
    defaults = dict(max_nfev=200, ftol=1e-10, xtol=1e-10, gtol=1e-10)
    source = "scipy.optimize.least_squares (Branch, Coleman, Li 1999 TRF)"

    def run(self, problem, rng, u0, progress=None):
        res = run_least_squares(problem, u0, max_nfev=self.max_nfev, ftol=self.ftol,
                                xtol=self.xtol, gtol=self.gtol)
        if progress is not None:
            progress(1, f"cost={problem.best_cost:.4g}")
        if res is None:
            return {"message": "evaluation budget exhausted"}
        return {"jac": res.jac, "u": res.x, "message": res.message, "history": [problem.best_cost]}


class MultistartLeastSquares(Algorithm):
    """Latin-hypercube screening in one population call, then least squares from the best
    few starts (and from the model's current values).

    Each start gets a short run (``max_nfev`` iterations); the best is then polished with
    ``polish_nfev``. Global enough for the LuGre family's few basins (Stribeck velocity vs.
    stiffness trade-off) and as precise as least squares.
    """
    name = "multistart_ls"
    kind = "local"
    steppable = False
    defaults = dict(n_screen=None, n_starts=3, max_nfev=15, ftol=1e-10, xtol=1e-10,
                    gtol=1e-10, polish_nfev=200, target=1e-9)
    source = "Latin hypercube (scipy.stats.qmc) + scipy.optimize.least_squares"

    def run(self, problem, rng, u0, progress=None):
        D = problem.dim
        n_screen = self.n_screen or max(64, 16 * D)
        U = latin_hypercube(n_screen, D, rng)
        history = []
        try:
            c = problem.evaluate(U)
        except BudgetExhausted:
            return {"message": "evaluation budget exhausted during screening"}
        history.append(problem.best_cost)
        order = np.argsort(c)
        starts = [np.clip(np.asarray(u0, float), 0, 1)] + [U[i] for i in order[:self.n_starts]]
        best = None
        for k, s in enumerate(starts):
            res = run_least_squares(problem, s, max_nfev=self.max_nfev, ftol=self.ftol,
                                    xtol=self.xtol, gtol=self.gtol)
            history.append(problem.best_cost)
            if progress is not None:
                progress(1, f"start {k + 1}/{len(starts)} cost={problem.best_cost:.4g}")
            if res is None:
                break
            if best is None or res.cost < best.cost:
                best = res
            if problem.best_cost < self.target:  # exact fit already: the other starts add nothing
                break
        if best is not None and not problem.exhausted and self.polish_nfev:
            res = run_least_squares(problem, best.x, max_nfev=self.polish_nfev, ftol=self.ftol,
                                    xtol=self.xtol, gtol=self.gtol)
            if res is not None and res.cost <= best.cost:
                best = res
            history.append(problem.best_cost)
        if best is None:
            return {"message": "evaluation budget exhausted", "history": history}
        return {"jac": best.jac, "u": best.x, "message": best.message, "history": history}
