"""Sim-to-real gap diagnosis: where the gap lies, which unmodelled effect causes it, and how
far it shrinks once that effect is added, measured on held-out data.

>>> from diagnosis import diagnose
>>> report = diagnose("fit.csv", "lugre", validation="heldout.csv")   # doctest: +SKIP
>>> report["verdict"]                                                  # doctest: +SKIP
"""
from .core import diagnose
from .effects import CANDIDATES, EFFECT_NAMES
from .report import DiagnosisReport
from .trajectory import (BASE_NAMES, EffectLaw, TrajectoryRecord, diagnose_trajectory,
                         record_from_result, simulate_record)
from .verdict import noise_floor

__all__ = ["diagnose", "diagnose_trajectory", "DiagnosisReport", "CANDIDATES", "EFFECT_NAMES", "noise_floor",
           "BASE_NAMES", "TrajectoryRecord", "record_from_result", "simulate_record",
           "EffectLaw"]
