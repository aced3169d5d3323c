"""Identification algorithms by name (``ALGORITHMS``); see :mod:`.base` for the contract."""
from __future__ import annotations

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


def _register_optional():
    import importlib
    for mod in ("modern", "swarm", "evolutionary", "structured"):
        try:
            m = importlib.import_module(f"{__name__}.{mod}")
        except ModuleNotFoundError as exc:
            if exc.name != f"{__name__}.{mod}":
                raise
            continue
        for cls in getattr(m, "ALGORITHM_CLASSES", ()):
            ALGORITHMS[cls.name] = cls


_register_optional()


def get_algorithm(name, **options) -> Algorithm:
    """Instantiate an algorithm by registry name (or pass an instance through)."""
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
