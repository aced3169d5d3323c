"""Identification of friction-law parameters: the seeds' metaheuristics beside fast modern
optimisers, in-process and co-simulation objectives, real-data loaders.

Modules: :mod:`.api` (``identify``), :mod:`.algorithms` (``ALGORITHMS``), :mod:`.objectives`
and :mod:`.cosim` (in-process / FMU co-simulation costs), :mod:`.executors` (inline,
processes, dask), :mod:`.real_data` (loaders of ``../shared/data/real``), :mod:`.synthetic`
(the seeds' laws and tables as test cases), :mod:`.xml350_protocol` (seed 003 end to end),
:mod:`.functions` (plain minimisation, Ackley/Griewank), :mod:`.sensitivity` (seed 002
sensitivity, by helper "laws-2"), :mod:`.identifiability` (the report attached to every
result), :mod:`.steady_state` (steady-state maps, the two-step method), :mod:`.cli`,
:mod:`.demo`.

>>> from identification import identify, ALGORITHMS
>>> from identification.real_data import load_emps
"""
from __future__ import annotations

from .algorithms import ALGORITHMS, DEFAULT_ALGORITHM, Algorithm, get_algorithm
from .api import confidence_intervals, identify
from .executors import DaskExecutor, InlineExecutor, ProcessExecutor
from .functions import minimize
from .objectives import InProcessObjective, Objective
from .result import IdentificationResult
from .space import ParameterSpace, default_bounds, default_names
from .identifiability import assess_identifiability
from .steady_state import identify_static, identify_two_step

__all__ = ["identify", "IdentificationResult", "ALGORITHMS", "DEFAULT_ALGORITHM", "Algorithm",
           "get_algorithm", "confidence_intervals", "Objective", "InProcessObjective",
           "ParameterSpace", "default_bounds", "default_names", "InlineExecutor",
           "ProcessExecutor", "DaskExecutor", "minimize", "assess_identifiability",
           "identify_static", "identify_two_step"]
