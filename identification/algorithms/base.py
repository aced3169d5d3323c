"""The contract every identification algorithm fulfils (scipy ``OdeSolver`` style).

Two shapes, both minimising :class:`identification.problem.Problem` over the unit cube:

* **step-wise** (metaheuristics, CMA-ES): ``start(problem, rng, u0) -> state`` then
  ``step(problem, rng, state) -> state`` until ``finished(state)``.
* **one-shot** (wrapped scipy solvers): ``run(problem, rng, u0, progress) -> info dict``.

The driver (:func:`identification.api.identify`) owns budget, progress, cost history and
checkpoints; the problem owns the best point. ``info`` may carry ``jac`` (for confidence
intervals) and ``message``.

Checkpoints (:mod:`identification.checkpoint`) log every ``problem.evaluate`` and replay it
on a resume, so an algorithm that draws its randomness from ``rng`` only and evaluates through
the problem resumes to the uninterrupted result with nothing more to do. Work that bypasses
``evaluate`` goes through ``problem.run_unit`` (a logged deterministic block), or the
algorithm sets ``checkpointable = False`` and says why in ``no_checkpoint``: the driver then
refuses a checkpoint instead of ignoring it.
"""
from __future__ import annotations

import numpy as np

__all__ = ["Algorithm", "chaotic_sequence", "latin_hypercube"]


class Algorithm:
    """Base class. Subclasses set ``name``, ``defaults`` and implement one of the shapes.

    Parameters
    ----------
    **options
        The algorithm's options (``defaults`` names); an unknown name is a TypeError.
    """
    name: str = ""
    #: "population" (needs only costs), "local" (least squares on residuals)
    kind: str = "population"
    steppable: bool = True
    #: option name -> default; the constructor accepts exactly these
    defaults: dict = {}
    #: one-line source (paper / library)
    source: str = ""
    #: False: a checkpoint is refused with ``no_checkpoint`` as the reason
    checkpointable: bool = True
    no_checkpoint: str = ""

    def __init__(self, **options):
        unknown = set(options) - set(self.defaults)
        if unknown:
            raise TypeError(f"algorithm {self.name!r} has no option(s) {sorted(unknown)}; "
                            f"options: {sorted(self.defaults)}")
        self.options = {**self.defaults, **options}

    def __getattr__(self, key):
        opts = self.__dict__.get("options")
        if opts is not None and key in opts:
            return opts[key]
        raise AttributeError(key)

    # step-wise shape
    def start(self, problem, rng, u0):  # pragma: no cover - interface
        """Step-wise shape: the initial state dict.

        Parameters
        ----------
        problem : Problem
            The cost over the unit cube.
        rng : numpy.random.Generator
            Random numbers of the run.
        u0 : ndarray, shape (D,)
            The start in unit-cube coordinates.
        """
        raise NotImplementedError

    def step(self, problem, rng, state):  # pragma: no cover - interface
        """Step-wise shape: one iteration; returns the next state dict.

        Parameters
        ----------
        problem : Problem
            The cost over the unit cube.
        rng : numpy.random.Generator
            Random numbers of the run.
        state : dict
            The state :meth:`start` or the previous step returned.
        """
        raise NotImplementedError

    def finished(self, state) -> bool:
        """Step-wise shape: whether the run is over (default: ``max_iter`` iterations done).

        Parameters
        ----------
        state : dict
            The current state.
        """
        return state.get("iteration", 0) >= self.options.get("max_iter", np.inf)

    # one-shot shape
    def run(self, problem, rng, u0, progress=None) -> dict:  # pragma: no cover - interface
        """One-shot shape: the whole run; returns an info dict.

        Parameters
        ----------
        problem : Problem
            The cost over the unit cube.
        rng : numpy.random.Generator
            Random numbers of the run.
        u0 : ndarray, shape (D,)
            The start in unit-cube coordinates.
        progress : callable(n, info), optional
            Progress in steps (:mod:`friction.progress`).
        """
        raise NotImplementedError


def chaotic_sequence(z0, n: int, mu: float = 4.0) -> np.ndarray:
    """Logistic map ``z_{k+1} = mu z_k (1 - z_k)`` (seed 001 Eqs. 11-12, EQUATIONS D.4).

    ``z0`` may be a vector (one chaotic variable per dimension); returns ``n`` rows. Values
    that land on the fixed points 0, 0.25, 0.5, 0.75, 1 are nudged so the orbit stays chaotic.
    """
    z = np.array(z0, float)
    out = np.empty((n,) + z.shape)
    for k in range(n):
        z = mu * z * (1.0 - z)
        stuck = (z < 1e-9) | (z > 1 - 1e-9) | np.isclose(z, 0.75) | np.isclose(z, 0.5) \
            | np.isclose(z, 0.25)
        z = np.where(stuck, z + 0.0137, z)
        z = np.clip(z, 1e-6, 1 - 1e-6)
        out[k] = z
    return out


def latin_hypercube(n: int, d: int, rng) -> np.ndarray:
    """``n`` Latin-hypercube points in ``[0, 1]^d`` (scipy.stats.qmc, seeded from ``rng``)."""
    from scipy.stats import qmc
    seed = int(rng.integers(2**31 - 1))
    return qmc.LatinHypercube(d=d, seed=seed).random(n)
