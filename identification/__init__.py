"""Identification of friction-law parameters: the seeds' metaheuristics beside fast modern
optimisers, in-process and co-simulation objectives, real-data loaders.

>>> from identification import identify, ALGORITHMS
>>> from identification.real_data import load_emps
"""
from __future__ import annotations

from .algorithms import ALGORITHMS, DEFAULT_ALGORITHM, Algorithm, get_algorithm
from .api import confidence_intervals, identify
from .executors import DaskExecutor, InlineExecutor, ProcessExecutor
from .objectives import InProcessObjective, Objective
from .result import IdentificationResult
from .space import ParameterSpace, default_bounds

__all__ = ["identify", "IdentificationResult", "ALGORITHMS", "DEFAULT_ALGORITHM", "Algorithm",
           "get_algorithm", "confidence_intervals", "Objective", "InProcessObjective",
           "ParameterSpace", "default_bounds", "InlineExecutor", "ProcessExecutor",
           "DaskExecutor"]
