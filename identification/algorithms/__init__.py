"""Identification algorithms by name (``ALGORITHMS``); see :mod:`.base` for the contract.

Default: ``multistart_ls`` (Latin-hypercube screening in one population call, then
trust-region least squares). ``benchmarks/bench_identification.py`` (one run, shared 2-core
machine) justifies it: on the seeds' five laws with their tables and on the EMPS and Franka
real data it reaches a cost no worse than the best seed metaheuristic (chaotic PSO in every
case, 10 000 evaluations) in 1-8 % of that metaheuristic's wall time, recovers every
parameter within 1 % on noise-free data (worst 0.13 %, seed 004), and from 8 random starts
in the box it found the optimum 8/8 times where plain least squares found it 5/8 (seed 001).
For the classic LuGre its least squares use the analytic Jacobian (forward sensitivities,
:func:`friction.lugre.lugre_normal_equations`) and start from the guess: on seed 001's
6-parameter LuGre at 10,000 samples it takes 0.2x the time of a by-hand
``scipy.optimize.least_squares`` fit (``benchmarks/bench_identification.py --speed``;
previously 16-20x).
"""
from __future__ import annotations

from . import evolutionary, modern, structured, swarm
from .base import Algorithm
from .local import LeastSquares, MultistartLeastSquares

__all__ = ["ALGORITHMS", "DEFAULT_ALGORITHM", "get_algorithm", "Algorithm"]

#: registry name -> algorithm class
ALGORITHMS: dict[str, type[Algorithm]] = {
    LeastSquares.name: LeastSquares,
    MultistartLeastSquares.name: MultistartLeastSquares,
}

#: chosen by benchmarks/bench_identification.py (fast and robust; see the module docs)
DEFAULT_ALGORITHM = "multistart_ls"


# every algorithm module is the project's own: one that fails to import fails this package
# (a third-party library an algorithm needs, e.g. cma, is imported when the algorithm runs
# and its absence named then)
for _module in (modern, swarm, evolutionary, structured):
    for _cls in _module.ALGORITHM_CLASSES:
        ALGORITHMS[_cls.name] = _cls
del _module, _cls


def get_algorithm(name, **options) -> Algorithm:
    """Instantiate an algorithm by registry name (or pass an instance through).

    Parameters
    ----------
    name : str or Algorithm
        Registry name (:data:`ALGORITHMS`) or an instance.
    **options
        The algorithm's options; an unknown name is a TypeError.
    """
    if isinstance(name, Algorithm):
        if options:
            raise TypeError("options given together with an algorithm instance")
        return name
    if name is None:
        name = DEFAULT_ALGORITHM
    try:
        cls = ALGORITHMS[name]
    except KeyError:
        raise ValueError(f"unknown algorithm {name!r}; choose from {sorted(ALGORITHMS)}") from None
    return cls(**options)
