"""Plain function minimisation with the identification algorithms, and the benchmark
functions seed 002 tests its IFFOA on (YU Eqs. 11-12, EQUATIONS B.5).

>>> from identification.functions import minimize, ackley
>>> r = minimize(ackley, [-5, -5], [5, 5], algorithm="cmaes", seed=0, max_evals=3000)
"""
from __future__ import annotations

import numpy as np

from .algorithms import get_algorithm
from .executors import InlineExecutor
from .problem import BudgetExhausted, Problem
from .space import ParameterSpace

__all__ = ["minimize", "ackley", "griewank", "FunctionObjective"]


def ackley(X) -> np.ndarray:
    """Ackley function (YU Eq. 11), rows of ``X``; minimum 0 at the origin."""
    X = np.atleast_2d(X)
    n = X.shape[1]
    return (-20 * np.exp(-0.2 * np.sqrt(np.sum(X * X, axis=1) / n))
            - np.exp(np.sum(np.cos(2 * np.pi * X), axis=1) / n) + 20 + np.e)


def griewank(X) -> np.ndarray:
    """Griewank function (YU Eq. 12), rows of ``X``; minimum 0 at the origin."""
    X = np.atleast_2d(X)
    i = np.arange(1, X.shape[1] + 1)
    return 1 + np.sum(X * X, axis=1) / 4000 - np.prod(np.cos(X / np.sqrt(i)), axis=1)


class FunctionObjective:
    """A vectorised cost ``fun(X[npop, D]) -> cost[npop]`` as an objective."""
    parallel_inside = True

    def __init__(self, fun):
        self.fun = fun

    def costs(self, X):
        c = np.asarray(self.fun(np.atleast_2d(X)), float)
        return np.where(np.isfinite(c), c, np.inf)


def minimize(fun, lower, upper, algorithm="cmaes", seed: int = 0, max_evals=None, x0=None,
             **options) -> dict:
    """Minimise a vectorised function over a box with a population algorithm.

    Parameters
    ----------
    fun : callable
        ``fun(X) -> costs``: X of shape (npop, D), one cost per row.
    lower, upper : array_like, shape (D,)
        The box.
    algorithm : str
        Population algorithm (:data:`identification.ALGORITHMS`).
    seed : int
        Random seed.
    max_evals : int, optional
        Budget of function evaluations (rows).
    x0 : array_like, shape (D,), optional
        Start (default the box's centre).
    **options
        The algorithm's options; an unknown name is a TypeError.

    Returns
    -------
    dict
        ``x``, ``fun`` (best value), ``n_evals``, ``history`` (best after each iteration),
        ``state`` (the algorithm's final state).
    """
    alg = get_algorithm(algorithm, **options)
    if alg.kind != "population":
        raise ValueError(f"{alg.name} needs residuals, not a plain function")
    lower, upper = np.asarray(lower, float), np.asarray(upper, float)
    space = ParameterSpace([f"x{j}" for j in range(lower.size)], lower, upper,
                           np.zeros(lower.size, bool))
    problem = Problem(FunctionObjective(fun), space, InlineExecutor(), max_evals=max_evals)
    rng = np.random.default_rng(seed)
    u0 = rng.random(lower.size) if x0 is None else space.to_unit(x0)
    history = []
    state = None
    try:
        if alg.steppable:
            state = alg.start(problem, rng, u0)
            while not alg.finished(state) and not problem.exhausted:
                state = alg.step(problem, rng, state)
                history.append(problem.best_cost)
        else:
            alg.run(problem, rng, u0)
    except BudgetExhausted:
        pass
    return {"x": space.to_physical(problem.best_u), "fun": problem.best_cost,
            "n_evals": problem.n_evals, "history": history, "state": state}
