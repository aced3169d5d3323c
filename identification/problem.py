"""The problem an algorithm sees: minimise the cost over the unit cube, with bookkeeping.

:class:`Problem` wraps an objective, the parameter space and an executor. Algorithms call
``evaluate(U)`` (a population in unit-cube coordinates) or, for least squares,
``residuals(u)`` / ``jacobian(u)``. The problem counts simulations, keeps the best point
and enforces the evaluation budget. With a checkpoint (``log``, an
:class:`identification.checkpoint.EvaluationLog`) every population evaluation and every
deterministic block run through :meth:`Problem.run_unit` is logged, and replayed from the log
on a resume.
"""
from __future__ import annotations

import json
import math
import time

import numpy as np

from .checkpoint import finite_or_none, plain
from .space import ParameterSpace

__all__ = ["Problem", "BudgetExhausted"]


#: bytes of simulated forces one population call may hold at once: a larger population
#: (long records: 129 screened sets x 2,000,000 samples would be 2 GB, and its residuals as
#: much again) is evaluated in chunks of rows
CHUNK_BYTES = 64 * 2**20


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
    progress : callable(n, info) or None
        Ticked with ``n = 0`` at most every ``tick_every`` seconds during long work
        (population chunks, least-squares iterations).
    """
    #: default seconds between progress ticks
    TICK_EVERY = 1.0

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
        #: checkpoint log (EvaluationLog) or None
        self.log = None
        self._in_unit = False
        #: progress callable(n, info) ticked (n = 0) at most once per ``tick_every`` seconds
        #: during long evaluations (population chunks, least-squares iterations)
        self.progress = None
        self.tick_every = self.TICK_EVERY
        self._last_tick = time.perf_counter()

    @property
    def dim(self) -> int:
        return self.space.dim

    @property
    def remaining(self) -> float:
        return np.inf if self.max_evals is None else self.max_evals - self.n_evals

    @property
    def exhausted(self) -> bool:
        return self.max_evals is not None and self.n_evals >= self.max_evals

    def tick(self, info: str = "") -> None:
        """A progress line (``progress(0, info)``) if one is due: long records show life
        between an algorithm's own progress lines."""
        if self.progress is None:
            return
        now = time.perf_counter()
        if now - self._last_tick >= self.tick_every:
            self._last_tick = now
            best = f" best cost={self.best_cost:.4g}" if np.isfinite(self.best_cost) else ""
            self.progress(0, f"evals {self.n_evals}{best}{' ' + info if info else ''}")

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
        c[:take] = self._costs(X)
        self.n_evals += take
        self._track(U[:take], c[:take])
        return c

    def _costs(self, X) -> np.ndarray:
        """Costs of physical rows ``X``: replayed from the checkpoint log while the run
        asks for exactly the logged rows, else simulated (and logged)."""
        log = None if self._in_unit else self.log
        if log is not None:
            rec = log.replay_costs(X)
            if rec is not None:
                # the original run's clock: trace times and wall time carry on from it
                self._t0 = time.perf_counter() - float(rec["s"])
                return np.array([np.inf if c is None else c for c in rec["c"]], float)
        c = self._chunked_costs(X)
        if log is not None:
            log.append({"k": "costs", "X": X, "c": [finite_or_none(v) for v in c],
                        "s": time.perf_counter() - self._t0})
        return c

    def _chunked_costs(self, X) -> np.ndarray:
        """``executor.costs`` over the rows of ``X``, in chunks whose simulated forces fit
        :data:`CHUNK_BYTES` (one call when the record is short)."""
        n_samples = len(self.objective.data.F) if hasattr(self.objective, "data") else 0
        rows = max(1, int(CHUNK_BYTES // max(8 * n_samples, 1)))
        if rows >= len(X):
            return np.asarray(self.executor.costs(self.objective, X), float)
        out = np.empty(len(X))
        for i in range(0, len(X), rows):
            out[i:i + rows] = np.asarray(self.executor.costs(self.objective, X[i:i + rows]),
                                         float)
            self.tick(f"population {min(i + rows, len(X))}/{len(X)}")
        return out

    def run_unit(self, kind: str, key: dict, compute):
        """Run a deterministic block ``compute() -> dict`` (JSON-able numbers, strings,
        lists) once per checkpoint.

        Without a log this is ``compute()``. With one, a block whose ``kind`` and ``key``
        (its inputs) match the next logged record is not run: its logged output is returned
        and the evaluations, best point and trace it produced are restored. Otherwise it runs
        and is logged when it finishes (an interrupted block reruns from its start on
        resume). Both paths return the output after a JSON round trip, so they return equal
        objects.
        """
        log = None if self._in_unit else self.log
        if log is None:
            return compute()
        rec = log.replay_unit(kind, key)
        if rec is not None:
            after = rec["after"]
            self.n_evals = int(after["n_evals"])
            self.best_cost = np.inf if after["best_cost"] is None else float(after["best_cost"])
            self.best_u = None if after["best_u"] is None else np.array(after["best_u"], float)
            self.trace.extend((int(n), float(s), float(c)) for n, s, c in after["trace"])
            self._t0 = time.perf_counter() - float(rec["s"])
            return rec["out"]
        n_trace = len(self.trace)
        self._in_unit = True  # a block is atomic: nothing inside it is logged on its own
        try:
            out = json.loads(json.dumps(plain(compute())))
        finally:
            self._in_unit = False
        log.append({"k": "unit", "kind": kind, "key": key, "out": out,
                    "after": {"n_evals": self.n_evals,
                              "best_cost": finite_or_none(self.best_cost),
                              "best_u": self.best_u, "trace": self.trace[n_trace:]},
                    "s": time.perf_counter() - self._t0})
        return out

    def residuals(self, u) -> np.ndarray:
        """Scaled residual vector at ``u`` (``sum r^2 = nrmse^2``)."""
        if self.exhausted:
            raise BudgetExhausted
        u = np.clip(np.asarray(u, float), 0.0, 1.0)
        r = self.objective.residuals(self.space.to_physical(u))
        self.n_evals += 1
        finite = np.isfinite(r)
        ok = bool(finite.all())
        c = float(np.sqrt(np.sum(r * r))) if ok else np.inf
        self._track(u[None, :], np.array([c]))
        self.tick()
        return r if ok else np.where(finite, r, 1e3)

    def jacobian_uncounted(self, u, step: float = 1e-6) -> np.ndarray:
        """The Jacobian :meth:`jacobian` gives at ``u`` with ``r0`` from :meth:`residuals`
        (the same numbers), neither counted nor tracked: a replayed least-squares run
        recomputes its final Jacobian (for confidence intervals) with it."""
        u = np.clip(np.asarray(u, float), 0.0, 1.0)
        J = self._analytic_jacobian(u)
        if J is not None:
            return J
        r = self.objective.residuals(self.space.to_physical(u))
        return self._jacobian_values(u, np.where(np.isfinite(r), r, 1e3), step)

    def jacobian(self, u, r0=None, step: float = 1e-6) -> np.ndarray:
        """Jacobian of the residuals in unit-cube coordinates: analytic where the objective
        gives one (:meth:`identification.objectives.Objective.jacobian`: the LuGre
        forward sensitivities, one simulation with its sensitivities, counted as one
        evaluation), else forward differences with all D perturbed sets simulated in one
        population call (D evaluations, D + 1 without ``r0``)."""
        u = np.clip(np.asarray(u, float), 0.0, 1.0)
        D = u.size
        if self.has_analytic_jacobian:
            if self.remaining < 1:
                raise BudgetExhausted
            self.n_evals += 1
            J = self._analytic_jacobian(u)
            self.tick()
            return J
        if self.remaining < D + (r0 is None):
            raise BudgetExhausted
        self.n_evals += D
        if r0 is None:
            r0 = self.objective.residuals(self.space.to_physical(u))
            self.n_evals += 1
        J = self._jacobian_values(u, r0, step)
        self.tick()
        return J

    @property
    def has_analytic_jacobian(self) -> bool:
        """Whether :meth:`jacobian` is analytic (the objective's ``has_jacobian()``)."""
        flag = self.__dict__.get("_analytic")
        if flag is None:
            ask = getattr(self.objective, "has_jacobian", None)
            flag = self._analytic = bool(ask()) if callable(ask) else False
        return flag

    def normal_equations(self, u):
        """``(sum r^2, J^T r, J^T J)`` of the residuals at ``u`` in cube coordinates from
        one analytic sensitivity pass (counted as one evaluation and tracked), or ``None``
        when the objective has no analytic Jacobian. Memory O(D^2): the Jacobian of a long
        record is never held."""
        if not self.has_analytic_jacobian:
            return None
        if self.exhausted:
            raise BudgetExhausted
        u = np.minimum(np.maximum(np.asarray(u, float), 0.0), 1.0)
        # to_physical and dx/du in one go (a least-squares run asks once per pass)
        lo, hi = self.space._ends()
        w = hi - lo
        log = self.space.log
        y = lo + u * w
        x = np.where(log, np.exp(np.where(log, y, 0.0)), y)
        out = self.objective.normal_equations(x)
        if out is None:
            return None
        c2, g, H = out
        self.n_evals += 1
        c = math.sqrt(c2) if math.isfinite(c2) and np.isfinite(H).all() else math.inf
        if c < self.best_cost:
            self.best_cost = c
            self.best_u = u.copy()
            self.trace.append((self.n_evals, time.perf_counter() - self._t0, c))
        if self.progress is not None:
            self.tick()
        if not math.isfinite(c):
            return math.inf, np.zeros_like(g), np.zeros_like(H)
        s = np.where(log, x * w, w)  # dx/du
        return float(c2), g * s, H * (s[:, None] * s[None, :])

    def _dx_du(self, u, x=None):
        """Slope of the physical value along each cube coordinate."""
        if x is None:
            x = self.space.to_physical(u)
        lo, hi = self.space._ends()
        return np.where(self.space.log, x * (hi - lo), hi - lo)

    def _analytic_jacobian(self, u):
        """The objective's analytic residual Jacobian at ``u`` in cube coordinates
        (physical Jacobian times dx/du), or None."""
        if not self.has_analytic_jacobian:
            return None
        x = self.space.to_physical(u)
        J = self.objective.jacobian(x)
        if J is None:
            return None
        J *= self._dx_du(u, x)[None, :]
        bad = ~np.isfinite(J)
        if bad.any():
            J[bad] = 0.0
        return J

    def _jacobian_values(self, u, r0, step) -> np.ndarray:
        D = u.size
        h = np.full(D, step)
        h = np.where(u + h > 1.0, -h, h)  # step inward at the upper face
        U = np.repeat(u[None, :], D, axis=0) + np.diag(h)
        X = self.space.to_physical(U)
        predict = getattr(self.executor, "predict", None)  # a cluster runs the D sets at once
        F = self.objective.predict(X) if predict is None else predict(self.objective, X)
        R = (F - self.objective.data.F[None, :]) * self.objective._rscale
        J = (R - r0[None, :]) / h[:, None]
        return np.where(np.isfinite(J), J, 0.0).T
