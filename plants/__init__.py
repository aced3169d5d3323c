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

import importlib

from .base import Experiment, Plant, PlantParams, structured
from .components import Damper, Mass, PositionSource, Spring
from .controllers import (PID, DiscreteBlock, DiscreteStepper, LuGreFeedforward, PIDParams,
                          StateDependentPID)
from .interfaces import HydraulicPort, PartialCompliant
from .law_stepper import FrictionComponent, FrictionStep
from .motor import LinearMotor
from .sensors import AccelerationSensor, PositionSensor, VelocitySensor
from .sources import PRBS, ColoredNoise, Sampled, SCurve, Sine, Triangle, VelocityPlateaus
from .stepper import PlantStepper

__all__ = ["PLANTS", "make_plant", "Plant", "PlantStepper", "PlantParams", "Experiment",
           "FrictionStep", "FrictionComponent", "structured", "HydraulicPort",
           "PartialCompliant", "Mass", "Spring", "Damper", "PositionSource", "PID",
           "PIDParams", "StateDependentPID", "LuGreFeedforward", "DiscreteBlock", "DiscreteStepper", "LinearMotor",
           "PositionSensor", "VelocitySensor", "AccelerationSensor", "Sine", "Triangle",
           "VelocityPlateaus", "PRBS", "ColoredNoise", "SCurve", "Sampled"]

#: registry name -> plant class (filled by the machine modules that exist)
PLANTS: dict[str, type[Plant]] = {}

# machine modules land one by one; each listed here registers once it exists
_MACHINES = (("xml350", "XML350"), ("valve", "ValveActuator"), ("damping_rig", "DampingRig"),
             ("forging_press", "ForgingPress"), ("mre_isolator", "MREIsolator"))


def _register_machines():
    for mod, cls in _MACHINES:
        try:
            m = importlib.import_module(f"{__name__}.{mod}")
        except ModuleNotFoundError as exc:
            if exc.name != f"{__name__}.{mod}":
                raise
            continue
        except Exception as exc:  # a broken machine must not take the others down
            import warnings
            warnings.warn(f"plant module {mod!r} failed to import: {exc!r}")
            continue
        klass = getattr(m, cls, None)
        if klass is None:  # the module may name its class differently: take the Plant subclass
            found = [v for v in vars(m).values() if isinstance(v, type)
                     and issubclass(v, Plant) and v is not Plant and v.__module__ == m.__name__
                     and v.name]
            if not found:
                continue
            klass = found[0]
        PLANTS[klass.name or mod] = klass


def make_plant(name: str, friction=None, **kwargs) -> Plant:
    """Create a plant by registry name (see :data:`PLANTS`); kwargs go to the constructor."""
    try:
        cls = PLANTS[name]
    except KeyError:
        raise ValueError(f"unknown plant {name!r}; choose from {sorted(PLANTS)}") from None
    return cls(friction, **kwargs)


_register_machines()
