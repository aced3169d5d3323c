"""The problem an algorithm sees: minimise the cost over the unit cube, with bookkeeping.

:class:`Problem` wraps an objective, the parameter space and an executor. Algorithms call
``evaluate(U)`` (a population in unit-cube coordinates) or, for least squares,
``residuals(u)`` / ``jacobian(u)``. The problem counts simulations, keeps the best point
and enforces the evaluation budget.
"""
from __future__ import annotations

import time

import numpy as np

from .space import ParameterSpace

__all__ = ["Problem", "BudgetExhausted"]


class BudgetExhausted(Exception):
    """Raised inside an algorithm when the evaluation budget is spent."""


class Problem:
    """Cost over the unit cube ``[0, 1]^D``.

    Attributes
    ----------
    n_evals : int
        Simulations run so far (one per parameter set).
    best_u, best_cost : ndarray, float
        Best point seen and its cost (NRMSE).
    """

    def __init__(self, objective, space: ParameterSpace, executor, max_evals: int | None = None):
        self.objective = objective
        self.space = space
        self.executor = executor
        self.max_evals = max_evals
        self.n_evals = 0
        self.best_u = None
        self.best_cost = np.inf
        #: (evaluations, seconds since start, best cost) after every improvement
        self.trace: list[tuple[int, float, float]] = []
        self._t0 = time.perf_counter()

    @property
    def dim(self) -> int:
        return self.space.dim

    @property
    def remaining(self) -> float:
        return np.inf if self.max_evals is None else self.max_evals - self.n_evals

    @property
    def exhausted(self) -> bool:
        return self.max_evals is not None and self.n_evals >= self.max_evals

    def _track(self, U, c):
        k = int(np.argmin(c))
        if c[k] < self.best_cost:
            self.best_cost = float(c[k])
            self.best_u = np.array(U[k], float)
            self.trace.append((self.n_evals, time.perf_counter() - self._t0, self.best_cost))

    def time_to(self, target: float) -> float | None:
        """Seconds until the best cost first reached ``target`` (None if never)."""
        for _, sec, c in self.trace:
            if c <= target:
                return sec
        return None

    def evaluate(self, U) -> np.ndarray:
        """Costs of a population ``U[npop, D]`` (clipped into the cube). Rows past the budget
        get ``inf`` and :class:`BudgetExhausted` is raised once nothing is left."""
        U = np.clip(np.atleast_2d(np.asarray(U, float)), 0.0, 1.0)
        if self.exhausted:
            raise BudgetExhausted
        n = U.shape[0]
        take = int(min(n, self.remaining))
        c = np.full(n, np.inf)
        X = self.space.to_physical(U[:take])
        c[:take] = self.executor.costs(self.objective, X)
        self.n_evals += take
        self._track(U[:take], c[:take])
        return c

    def residuals(self, u) -> np.ndarray:
        """Scaled residual vector at ``u`` (``sum r^2 = nrmse^2``)."""
        if self.exhausted:
            raise BudgetExhausted
        u = np.clip(np.asarray(u, float), 0.0, 1.0)
        r = self.objective.residuals(self.space.to_physical(u))
        self.n_evals += 1
        c = float(np.sqrt(np.sum(r * r))) if np.all(np.isfinite(r)) else np.inf
        self._track(u[None, :], np.array([c]))
        return np.where(np.isfinite(r), r, 1e3)

    def jacobian(self, u, r0=None, step: float = 1e-6) -> np.ndarray:
        """Forward-difference Jacobian of the residuals in unit-cube coordinates, all D
        perturbed sets simulated in one population call."""
        u = np.clip(np.asarray(u, float), 0.0, 1.0)
        D = u.size
        if self.remaining < D + (r0 is None):
            raise BudgetExhausted
        h = np.full(D, step)
        h = np.where(u + h > 1.0, -h, h)  # step inward at the upper face
        U = np.repeat(u[None, :], D, axis=0) + np.diag(h)
        X = self.space.to_physical(U)
        F = self.objective.predict(X)
        self.n_evals += D
        if r0 is None:
            r0 = self.objective.residuals(self.space.to_physical(u))
            self.n_evals += 1
        R = (F - self.objective.data.F[None, :]) * self.objective._rscale
        J = (R - r0[None, :]) / h[:, None]
        return np.where(np.isfinite(J), J, 0.0).T
