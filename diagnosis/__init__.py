"""Sim-to-real gap diagnosis: where the gap lies, which unmodelled effect causes it, and how
far it shrinks once that effect is added, measured on held-out data.

>>> from diagnosis import diagnose
>>> report = diagnose("fit.csv", "lugre", validation="heldout.csv")   # doctest: +SKIP
>>> report["verdict"]                                                  # doctest: +SKIP
"""
from .core import BASE_NAMES, DiagnosisReport, diagnose, diagnose_trajectory, noise_floor
from .effects import CANDIDATES, EFFECT_NAMES
from .trajectory import EffectLaw, TrajectoryRecord, record_from_result, simulate_record

__all__ = ["diagnose", "diagnose_trajectory", "DiagnosisReport", "CANDIDATES", "EFFECT_NAMES", "noise_floor",
           "BASE_NAMES", "TrajectoryRecord", "record_from_result", "simulate_record",
           "EffectLaw"]
