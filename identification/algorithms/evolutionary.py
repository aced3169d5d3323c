"""Adaptive genetic algorithm of seed 001 (EQUATIONS D.3), real coded, in the unit cube.

* fitness ``f = max J - J`` (Eq. 25), J the cost;
* normalised-geometric rank selection ``P(r) = q (1-q)^(r-1) / (1 - (1-q)^n)`` (Eq. 4);
* arithmetic crossover ``X* = lam X(i) + (1-lam) X(i+1)`` (Eq. 5), lam uniform in (0, 1);
* mutation ``X* = (Min + Max)/2 + (Max - Min)/2 (phi - 0.5)`` (Eq. 6), Min/Max the search
  box of the gene (``mutation_range="box"``, default) or the current population's range
  (``"population"``; the seed's "minimum/maximum of X*(i)" is ambiguous, and this reading
  collapses the population onto its centroid within a few generations);
* adaptive probabilities (Eqs. 7-8): ``Pc = Pc1 - (Pc1 - Pc2)(f' - f_avg)/(f_max - f_avg)``
  for ``f' >= f_avg`` else ``Pc1`` (Pc1 = 0.9, Pc2 = 0.6), the same for Pm (0.1, 0.01);
* elitism: the best individual survives (so the bulletin never worsens).
"""
from __future__ import annotations

import numpy as np

from .base import Algorithm

__all__ = ["AdaptiveGA", "ALGORITHM_CLASSES"]


class AdaptiveGA(Algorithm):
    """Adaptive GA of seed 001 (Srinivas-Patnaik probabilities, bounded variant)."""
    name = "adaptive_ga"
    defaults = dict(pop_size=50, max_iter=500, q=0.08, pc1=0.9, pc2=0.6, pm1=0.1, pm2=0.01,
                    mutation_range="box")
    source = "seed 001 Eqs. 4-8, 24-25; Srinivas & Patnaik 1994"

    def start(self, problem, rng, u0):
        X = rng.random((self.pop_size, problem.dim))
        X[0] = u0
        return {"X": X, "J": problem.evaluate(X), "iteration": 0}

    @staticmethod
    def _adaptive(p1, p2, f, favg, fmax):
        span = fmax - favg
        frac = np.where(span > 0, (f - favg) / np.where(span > 0, span, 1.0), 0.0)
        return np.where(f >= favg, p1 - (p1 - p2) * frac, p1)

    def step(self, problem, rng, state):
        X, J = state["X"], state["J"]
        n, D = X.shape
        Jf = np.where(np.isfinite(J), J, np.nanmax(np.where(np.isfinite(J), J, -np.inf)) * 10 + 1)
        fit = Jf.max() - Jf  # Eq. 25
        order = np.argsort(-fit)  # rank 1 = best
        q = self.q
        ranks = np.arange(1, n + 1)
        P = q * (1 - q) ** (ranks - 1) / (1 - (1 - q) ** n)  # Eq. 4
        P = P / P.sum()
        parents = order[rng.choice(n, size=n, p=P)]
        Xc, fc = X[parents].copy(), fit[parents]
        favg, fmax = fit.mean(), fit.max()
        # crossover of consecutive pairs (Eq. 5) with the adaptive Pc of the fitter parent (Eq. 7)
        for i in range(0, n - 1, 2):
            fprime = max(fc[i], fc[i + 1])
            if rng.random() < self._adaptive(self.pc1, self.pc2, fprime, favg, fmax):
                lam = rng.random()
                a, b = Xc[i].copy(), Xc[i + 1].copy()
                Xc[i] = lam * a + (1 - lam) * b
                Xc[i + 1] = (1 - lam) * a + lam * b
        # mutation (Eq. 6) with the adaptive Pm of the individual (Eq. 8)
        pm = self._adaptive(self.pm1, self.pm2, fc, favg, fmax)
        if self.mutation_range == "population":
            lo, hi = X.min(axis=0), X.max(axis=0)
        else:  # the search box (the cube)
            lo, hi = np.zeros(D), np.ones(D)
        mut = rng.random((n, D)) < pm[:, None]
        phi = rng.random((n, D))
        Xc = np.where(mut, (lo + hi) / 2 + (hi - lo) / 2 * (phi - 0.5), Xc)
        Jc = problem.evaluate(Xc)
        # elitism: the best of the old generation replaces the worst child
        b = int(np.argmin(J))
        w = int(np.argmax(Jc))
        if J[b] < Jc.min():
            Xc[w], Jc[w] = X[b], J[b]
        state.update(X=Xc, J=Jc, iteration=state["iteration"] + 1)
        return state


ALGORITHM_CLASSES = (AdaptiveGA,)
