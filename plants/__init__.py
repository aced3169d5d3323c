"""Modelica-style plant library: connectors, components, sources, sensors, controllers and
the machines of the seed papers, each taking any friction law of :mod:`friction`.

>>> from plants import PLANTS, make_plant
>>> stage = make_plant("xml350")               # seed 003 XML-350 stage, its own LuGre
>>> res = stage.simulate(method="fast")        # structured array, ``time`` first

Layout (MSL roles): :mod:`plants.interfaces` (HydraulicPort, PartialCompliant),
:mod:`plants.components` (mass, spring, damper, position source: what the machines are
built from), :mod:`plants.sources` (trajectories), :mod:`plants.sensors`, :mod:`plants.controllers`,
:mod:`plants.motor`, :mod:`plants.base` (the plant contract), :mod:`plants.stepper` (the
fast fixed-step integrator, what FMUs run), :mod:`plants.reference` (the ``solve_ivp``
reference integrator), :mod:`plants.law_stepper` (a friction law stepped on its own), one
module per machine, and :mod:`plants.experiments` (the seeds' protocols producing datasets).
The seeds' studies (paper comparisons, stability analyses, figures and the ``plants`` demo
stage) sit apart, in :mod:`plants.studies`; the library modules hold no plotting code.
"""
from __future__ import annotations

from .base import Experiment, Plant, PlantParams, structured
from .components import Damper, Mass, PositionSource, Spring
from .controllers import (PID, DiscreteBlock, DiscreteStepper, LuGreFeedforward, PIDParams,
                          StateDependentPID)
from .damping_rig import DampingRig
from .forging_press import ForgingPress
from .interfaces import HydraulicPort, PartialCompliant
from .law_stepper import FrictionComponent, FrictionStep
from .motor import LinearMotor
from .mre_isolator import MREIsolator
from .sensors import AccelerationSensor, PositionSensor, VelocitySensor
from .sources import PRBS, ColoredNoise, Sampled, SCurve, Sine, Triangle, VelocityPlateaus
from .stepper import PlantStepper
from .valve import ValveActuator
from .xml350 import XML350

__all__ = ["PLANTS", "make_plant", "Plant", "PlantStepper", "PlantParams", "Experiment",
           "FrictionStep", "FrictionComponent", "structured", "HydraulicPort",
           "PartialCompliant", "Mass", "Spring", "Damper", "PositionSource", "PID",
           "PIDParams", "StateDependentPID", "LuGreFeedforward", "DiscreteBlock",
           "DiscreteStepper", "LinearMotor", "PositionSensor", "VelocitySensor",
           "AccelerationSensor", "Sine", "Triangle", "VelocityPlateaus", "PRBS", "ColoredNoise",
           "SCurve", "Sampled", "XML350", "ValveActuator", "DampingRig", "ForgingPress",
           "MREIsolator"]

#: registry name -> plant class: the machines of the seed papers
PLANTS: dict[str, type[Plant]] = {cls.name: cls for cls in (XML350, ValveActuator, DampingRig,
                                                            ForgingPress, MREIsolator)}


def make_plant(name: str, friction=None, **kwargs) -> Plant:
    """Create a plant by registry name (see :data:`PLANTS`); kwargs go to the constructor.

    Parameters
    ----------
    name : str
        One of :data:`PLANTS`.
    friction : FrictionModel or str, optional
        The contact's friction law, or a registry name (default: the plant's own law).
    **kwargs
        Constructor arguments of the plant class (parameter values in SI units,
        ``external_friction``, ``params``); an unknown name is a TypeError.
    """
    try:
        cls = PLANTS[name]
    except KeyError:
        raise ValueError(f"unknown plant {name!r}; choose from {sorted(PLANTS)}") from None
    return cls(friction, **kwargs)
