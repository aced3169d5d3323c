"""Sim-to-real gap diagnosis: where the gap lies, which unmodelled effect causes it, and how
far it shrinks once that effect is added, measured on held-out data.

>>> from diagnosis import diagnose
>>> report = diagnose("fit.csv", "lugre", validation="heldout.csv")   # doctest: +SKIP
>>> report["verdict"]                                                  # doctest: +SKIP

Layout (one concept, one home)
------------------------------
==========================  ==================================================================
module                      concept
==========================  ==================================================================
:mod:`.core`                the friction-force level: :func:`diagnose`, base fit, warm-up,
                            extrapolation, transfer hand-off
:mod:`.trajectory`          the trajectory level: :class:`~.trajectory.TrajectoryDiagnosis`
                            (steps as methods), :func:`diagnose_trajectory`
:mod:`.engines`             running a plant with a law on measured records (plant, FMUs)
:mod:`.verdict`             the verdict both levels share: noise floor, ranking, practical
                            size, :func:`~.verdict.decide`
:mod:`.report`              :class:`DiagnosisReport` and the sections both levels share
:mod:`.effects`             **one record per effect** (:class:`~.effects.Effect`) and every
                            list derived from them; how to add an effect
:mod:`.candidates`          the candidate builders (parameters, formulas, starts)
``effects_<name>.py``       an effect's candidate and truth forms in a module of its own
                            (``backlash``, ``gms``), registered in :mod:`.effects`
:mod:`.effect_law`          a law plus force effects as one law a plant can take
:mod:`.composite`           base + candidates fitted jointly at the force level
:mod:`.regions`             where: the residual by regime, band, frequency
:mod:`.significance`        the paired held-out test
:mod:`.transfer`            scores when held-out conditions lie outside the fit range
:mod:`.cluster`             the candidates' fits on a dask cluster
:mod:`.records`             measured trajectories (:class:`TrajectoryRecord`)
:mod:`.benchmark`           the withheld-effect benchmark (cases, kinematics, truths,
                            scoring, runner, cli)
:mod:`.clean_records`       clean records made as real ones are (no name allowed)
:mod:`.plant_fmu`           a user's plant FMU at the trajectory level
:mod:`.cli`, :mod:`.demo`   command line and demo
:mod:`.report_html`,        HTML reports
:mod:`.trajectory_report`
==========================  ==================================================================
"""
from .core import diagnose
from .effects import CANDIDATES, EFFECT_NAMES
from .report import DiagnosisReport
from .trajectory import (BASE_NAMES, EffectLaw, TrajectoryRecord, diagnose_trajectory,
                         record_from_result, simulate_record)
from .verdict import noise_floor

__all__ = ["diagnose", "diagnose_trajectory", "DiagnosisReport", "CANDIDATES", "EFFECT_NAMES",
           "noise_floor", "BASE_NAMES", "TrajectoryRecord", "record_from_result", "simulate_record",
           "EffectLaw"]
