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
                      gtol=1e-10, diff_step=1e-6, tr_solver="lsmr"):
    """Trust-region reflective least squares from ``u0`` inside the unit cube.

    ``tr_solver="lsmr"`` (default) solves the trust-region subproblems with products of the
    Jacobian only. The ``"exact"`` solver takes a dense SVD of the tall N x D Jacobian each
    iteration, which multithreaded OpenBLAS makes up to ~70 times slower on a loaded
    2-core machine (measured: 0.17 s instead of 2.4 ms for 4000 x 9).

    Returns the scipy result (``x``, ``jac``, ``fun``) or ``None`` if the budget ran out
    before the first iteration finished.

    With a checkpoint (``problem.log``) the run is one logged block: its Jacobians (D x N
    each) are too big to log, so a resume skips a finished run (result and evaluation count
    from the log, ``jac`` recomputed at ``x`` on first use: the same numbers) and reruns an
    interrupted one from ``u0``.
    """
    if getattr(problem, "log", None) is None:
        return _run_least_squares(problem, u0, method=method, max_nfev=max_nfev, ftol=ftol,
                                  xtol=xtol, gtol=gtol, diff_step=diff_step,
                                  tr_solver=tr_solver)
    u0 = np.asarray(u0, float)
    key = {"u0": u0, "x0": problem.space.to_physical(np.clip(u0, 0.0, 1.0)),
           "lower": problem.space.lower, "upper": problem.space.upper, "method": method,
           "max_nfev": max_nfev, "ftol": ftol, "xtol": xtol, "gtol": gtol,
           "diff_step": diff_step, "tr_solver": tr_solver}
    live = {}

    def compute():
        res = live["res"] = _run_least_squares(
            problem, u0, method=method, max_nfev=max_nfev, ftol=ftol, xtol=xtol, gtol=gtol,
            diff_step=diff_step, tr_solver=tr_solver)
        if res is None:
            return {"none": True}
        return {"x": res.x, "cost": float(res.cost), "message": str(res.message),
                "status": int(res.status), "nfev": int(res.nfev),
                "success": bool(res.success)}

    out = problem.run_unit("least_squares", key, compute)
    if "res" in live:
        return live["res"]
    return None if out.get("none") else _ReplayedLeastSquares(problem, out, diff_step)


class _ReplayedLeastSquares:
    """A finished least-squares run read from a checkpoint: ``x``, ``cost``, ``message``,
    ``status``, ``nfev``, ``success`` as logged; ``jac`` recomputed at ``x`` when asked."""

    def __init__(self, problem, out, diff_step):
        self._problem, self._step = problem, diff_step
        self.x = np.asarray(out["x"], float)
        self.cost = float(out["cost"])
        self.message, self.status = out["message"], out["status"]
        self.nfev, self.success = out["nfev"], out["success"]
        self._jac = None

    @property
    def jac(self):
        if self._jac is None:
            self._jac = self._problem.jacobian_uncounted(self.x, step=self._step)
        return self._jac


def _run_least_squares(problem, u0, *, method, max_nfev, ftol, xtol, gtol, diff_step,
                       tr_solver):
    cache = {}

    def fun(u):
        r = problem.residuals(u)
        cache["u"], cache["r"] = np.array(u), r
        return r

    def jac(u):
        r0 = cache["r"] if "u" in cache and np.array_equal(cache["u"], u) else None
        return problem.jacobian(u, r0=r0, step=diff_step)

    u0 = np.clip(np.asarray(u0, float), 1e-9, 1 - 1e-9)
    if u0.size == 1:
        tr_solver = "exact"  # scipy's lsmr subproblem indexes a 2-D subspace: one parameter fails
    try:
        return least_squares(fun, u0, jac=jac, bounds=(0.0, 1.0), method=method,
                             x_scale="jac", ftol=ftol, xtol=xtol, gtol=gtol, max_nfev=max_nfev,
                             tr_solver=tr_solver)
    except BudgetExhausted:
        return None


class LeastSquares(Algorithm):
    """``scipy.optimize.least_squares`` (trust-region reflective, bounded) from the model's
    current values. Fast and precise near the optimum; local."""
    name = "least_squares"
    kind = "local"
    steppable = False
    checkpointable = False
    no_checkpoint = ("it is one scipy least-squares run, which cannot be resumed part-way; "
                     "multistart_ls (the default) resumes after each of its starts")
    defaults = dict(max_nfev=200, ftol=1e-10, xtol=1e-10, gtol=1e-10, tr_solver="lsmr")
    source = "scipy.optimize.least_squares (Branch, Coleman, Li 1999 TRF)"

    def run(self, problem, rng, u0, progress=None):
        res = run_least_squares(problem, u0, max_nfev=self.max_nfev, ftol=self.ftol,
                                xtol=self.xtol, gtol=self.gtol, tr_solver=self.tr_solver)
        if progress is not None:
            progress(1, f"cost={problem.best_cost:.4g}")
        if res is None:
            return {"message": "evaluation budget exhausted"}
        return {"jac": res.jac, "u": res.x, "message": res.message, "history": [problem.best_cost]}


class MultistartLeastSquares(Algorithm):
    """Latin-hypercube screening in one population call, a full least-squares run from the
    best screened point (or the model's current values if better), then short runs from the
    next best starts; a start that beats the first is polished in full.

    Fast where one basin dominates (the first run converges and the trace reaches the optimum
    early) and robust where the LuGre family has a few basins (Stribeck velocity vs.
    stiffness trade-off): the extra starts check them.
    """
    name = "multistart_ls"
    kind = "local"
    steppable = False
    defaults = dict(n_screen=None, n_starts=3, max_nfev=15, ftol=1e-10, xtol=1e-10,
                    gtol=1e-10, polish_nfev=200, target=1e-9, tr_solver="lsmr")
    source = "Latin hypercube (scipy.stats.qmc) + scipy.optimize.least_squares"

    def _ls(self, problem, u, nfev):
        return run_least_squares(problem, u, max_nfev=nfev, ftol=self.ftol, xtol=self.xtol,
                                 gtol=self.gtol, tr_solver=self.tr_solver)

    def run(self, problem, rng, u0, progress=None):
        D = problem.dim
        n_screen = self.n_screen or max(64, 16 * D)
        u0 = np.clip(np.asarray(u0, float), 0, 1)
        U = np.vstack([u0[None, :], latin_hypercube(n_screen, D, rng)])
        history = []
        try:
            c = problem.evaluate(U)
        except BudgetExhausted:
            return {"message": "evaluation budget exhausted during screening"}
        history.append(problem.best_cost)
        order = [int(i) for i in np.argsort(c, kind="stable")]
        if 0 not in order[:self.n_starts + 1]:
            order = order[:self.n_starts] + [0]  # the user's guess is always tried
        best = self._ls(problem, U[order[0]], self.polish_nfev)
        history.append(problem.best_cost)
        if progress is not None:
            progress(1, f"start 1/{len(order[:self.n_starts + 1])} cost={problem.best_cost:.4g}")
        if best is None:
            return {"message": "evaluation budget exhausted", "history": history}
        for k, i in enumerate(order[1:self.n_starts + 1], start=2):
            if problem.best_cost < self.target or problem.exhausted:
                break  # exact fit already: the other starts add nothing
            res = self._ls(problem, U[i], self.max_nfev)
            if res is not None and res.cost < best.cost * (1 - 1e-6):
                res = self._ls(problem, res.x, self.polish_nfev) or res  # a better basin
                if res.cost < best.cost:
                    best = res
            history.append(problem.best_cost)
            if progress is not None:
                progress(1, f"start {k}/{len(order[:self.n_starts + 1])} "
                            f"cost={problem.best_cost:.4g}")
        return {"jac": best.jac, "u": best.x, "message": best.message, "history": history}
