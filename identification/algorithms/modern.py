"""Modern library optimisers: CMA-ES (``cma``) and differential evolution (scipy)."""
from __future__ import annotations

import numpy as np

from ..problem import BudgetExhausted
from .base import Algorithm

__all__ = ["CMAES", "DifferentialEvolution", "ALGORITHM_CLASSES"]


class CMAES(Algorithm):
    """Covariance-matrix adaptation evolution strategy (Hansen), ``cma.CMAEvolutionStrategy``
    with box constraints on the unit cube; each generation is one population evaluation.
    Step-wise; a checkpoint replays the logged generations (cma draws from its own seed,
    taken from ``rng``)."""
    name = "cmaes"
    defaults = dict(sigma0=0.25, pop_size=None, max_iter=300, tol_fun=1e-14, tol_x=1e-12)
    source = "cma (N. Hansen), CMA-ES with bound handling"

    def start(self, problem, rng, u0):
        try:
            import cma
        except ImportError as exc:
            raise ImportError("algorithm 'cmaes' needs the cma package (pip install cma)") \
                from exc
        opts = {"bounds": [0.0, 1.0], "seed": int(rng.integers(1, 2**31 - 1)), "verbose": -9,
                "tolfun": self.tol_fun, "tolx": self.tol_x, "tolflatfitness": 5}
        if self.pop_size:
            opts["popsize"] = int(self.pop_size)
        es = cma.CMAEvolutionStrategy(np.clip(u0, 0.01, 0.99).tolist(), self.sigma0, opts)
        problem.evaluate(np.asarray(u0)[None, :])  # the initial guess is a candidate too
        return {"es": es, "iteration": 0}

    def step(self, problem, rng, state):
        es = state["es"]
        X = np.array(es.ask())
        c = problem.evaluate(X)
        es.tell(list(X), [float(v) if np.isfinite(v) else 1e300 for v in c])
        state["iteration"] += 1
        return state

    def finished(self, state):
        return state["iteration"] >= self.max_iter or bool(state["es"].stop())


class DifferentialEvolution(Algorithm):
    """``scipy.optimize.differential_evolution`` (best1bin, Latin-hypercube init), vectorised:
    one population evaluation per generation. One-shot (scipy drives the loop); a checkpoint
    replays the logged generations (scipy's seed is taken from ``rng``)."""
    name = "differential_evolution"
    steppable = False
    defaults = dict(pop_size=15, max_iter=200, tol=1e-10, mutation=(0.5, 1.0), recombination=0.7,
                    polish=False)
    source = "scipy.optimize.differential_evolution (Storn & Price 1997)"

    def run(self, problem, rng, u0, progress=None):
        from scipy.optimize import differential_evolution
        history = []

        def f(UT):  # vectorized=True passes (D, S)
            return problem.evaluate(np.asarray(UT).T)

        def cb(*args, **kw):
            history.append(problem.best_cost)
            if progress is not None:
                progress(1, f"evals {problem.n_evals} cost={problem.best_cost:.4g}")
            return problem.exhausted

        try:
            res = differential_evolution(
                f, [(0.0, 1.0)] * problem.dim, popsize=self.pop_size, maxiter=self.max_iter,
                tol=self.tol, atol=0.0, mutation=self.mutation, recombination=self.recombination,
                seed=int(rng.integers(2**31 - 1)), polish=self.polish, vectorized=True,
                updating="deferred", init="latinhypercube", x0=np.clip(u0, 0, 1), callback=cb)
            msg = res.message
        except BudgetExhausted:
            msg = "evaluation budget exhausted"
        return {"message": msg, "history": history or [problem.best_cost]}


ALGORITHM_CLASSES = (CMAES, DifferentialEvolution)
