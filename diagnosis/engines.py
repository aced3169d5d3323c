"""Running a plant with a friction law on measured records: the simulation engines of the
trajectory level (:mod:`diagnosis.trajectory`) and its report (:mod:`diagnosis.
trajectory_report`).

``engine="plant"`` (:class:`_PlantEngine`) runs :meth:`plants.base.Plant.simulate`
(``method="fast"``); ``engine="fmu"`` (:class:`_FMUEngine`) runs the plant FMU (external
friction), the friction-law FMU and, for force effects, the ``friction_effects`` block
through :class:`fmus.master.Master`. :class:`TrajectoryModel` counts the runs and samples
the output at a record's instants; :func:`simulate_record` is one run.
"""
from __future__ import annotations

import dataclasses
import math
import time

import numpy as np

from friction import FrictionModel

from .effect_law import EffectLaw
from .effects import INPUTS
from .records import TrajectoryRecord

__all__ = ["REFERENCE_OUTPUTS", "TrajectoryModel", "simulate_record"]

#: outputs holding a plant's own position command (the tracking error's reference)
REFERENCE_OUTPUTS = ("x_d", "S_ref", "x_ref")


# -- simulation engines ---------------------------------------------------------------------
def _reference_output(plant) -> str | None:
    names = plant.all_output_names
    return next((r for r in REFERENCE_OUTPUTS if r in names), None)


def _options_for(plant, record_options: dict) -> dict:
    """Experiment options of one run. A friction feedforward is part of the controller that
    ran on the machine, not of the friction model under test: unless the record names its
    ``compensator``, it is the plant's default law (what the plant FMU uses too), never the
    candidate being simulated."""
    opts = dict(record_options)
    if "compensator" in plant.options and opts.get("compensation",
                                                  plant.opts.get("compensation", False)):
        if opts.get("compensator", plant.opts.get("compensator")) is None:
            opts["compensator"] = plant.default_friction()
    return opts


class _PlantEngine:
    """In-process plant simulation (``Plant.simulate(method="fast")``)."""
    name = "plant"

    def __init__(self, plant):
        self.plant = plant

    def run(self, law, plant_params: dict, options: dict, stop: float, signals):
        p = self.plant.with_params(**plant_params) if plant_params else self.plant._copy()
        p.friction = law
        res = p.simulate(stop, method="fast", **_options_for(self.plant, options))
        return res["time"], {s: np.asarray(res[s], float) for s in signals}


class _FMUEngine:
    """Plant FMU (external friction) + friction-law FMU through :class:`fmus.master.Master`."""
    name = "fmu"

    def __init__(self, plant, fmu_dir=None, step: float | None = None):
        from fmus.plant_fmus import coupling_step
        self.plant = plant
        self.fmu_dir = fmu_dir
        self.step = float(step) if step else coupling_step(type(plant)) / 4.0
        self.masters = {}

    def _master(self, law_name, signals, effects=()):
        import os
        from fmus.master import Master
        from fmus.plant_fmus import LOAD_SIGNALS, plant_connections
        key = (law_name, tuple(signals), tuple(effects))
        if key in self.masters:
            return self.masters[key]
        import friction
        fmu_dir = self.fmu_dir
        need = {self.plant.name, law_name, "lugre"} | ({"friction_effects"} if effects else set())
        if fmu_dir is None or not all(os.path.isfile(os.path.join(fmu_dir, f"{n}.fmu"))
                                      for n in need):
            from fmus.testing import built_fmus
            fmu_dir = self.fmu_dir = str(built_fmus(tuple(sorted(need))))
        cls = type(self.plant)
        fmus = {"plant": os.path.join(fmu_dir, f"{cls.name}.fmu"),
                "friction": os.path.join(fmu_dir, f"{law_name}.fmu")}
        conns = plant_connections(cls, friction.MODELS[law_name])
        if effects:
            # the effects block sits between the law and the plant (friction.extensions)
            fmus["effects"] = os.path.join(fmu_dir, "friction_effects.fmu")
            conns = [c for c in conns if c != ("friction.F", "plant.F_friction")]
            conns += [("friction.F", "effects.F_law"), ("effects.F", "plant.F_friction"),
                      ("plant.v", "effects.v"), ("plant.a", "effects.a"),
                      ("plant.x", "effects.x")]
            if any("load" in INPUTS[e] for e in effects):
                outs = cls(external_friction=True).all_output_names
                src = next((n for n in LOAD_SIGNALS if n in outs), None)
                if src is None:
                    raise ValueError(f"plant {cls.name!r} has no load output for the load "
                                     f"effect (looked for {LOAD_SIGNALS})")
                conns.append((f"plant.{src}", "effects.load"))
        m = Master(fmus, conns, record=[f"plant.{s}" for s in signals])
        self.masters[key] = m
        return m

    def run(self, law, plant_params: dict, options: dict, stop: float, signals):
        effects = ()
        block = {}
        if isinstance(law, EffectLaw):
            from friction.extensions import EXTENSION_INDEX
            effects = tuple(sorted(law.effects))
            block = {n: float(law._e[i]) for n, i in EXTENSION_INDEX.items()}
            # the block's clock starts at 0 with the run; the law's at its time0
            block["t0"] -= law.time0
            law = law.base
        bad = {k: type(v).__name__ for k, v in options.items()
               if v is not None and not isinstance(v, (bool, int, float, str))}
        if bad:
            raise NotImplementedError(f"engine='fmu': experiment option(s) {bad} are not "
                                      f"scalars; the plant FMU exposes only scalar options")
        m = self._master(law.name, signals, effects)
        fmu_vars = m.instances["plant"].vars
        pvals = {n: getattr(self.plant.params, n) for n in self.plant.parameter_names}
        pvals.update(plant_params)
        default = type(self.plant.params)()
        missing = [n for n in pvals if n not in fmu_vars
                   and pvals[n] != getattr(default, n, None)]
        if missing:
            raise NotImplementedError(f"engine='fmu': the plant FMU has no parameter(s) "
                                      f"{missing} (rebuild the FMUs)")
        pvals = {n: v for n, v in pvals.items() if n in fmu_vars}
        opts = {k: v for k, v in options.items() if v is not None}
        lvals = {f.name: getattr(law.params, f.name) for f in dataclasses.fields(law.params)
                 if getattr(law.params, f.name) is not None}
        m.parameters = {"plant": {**pvals, **opts}, "friction": lvals,
                        **({"effects": block} if effects else {})}
        n = int(math.ceil(stop / self.step - 1e-9))
        res = m.simulate(start_time=0.0, stop_time=n * self.step, step_size=self.step)
        return res["time"], {s: np.asarray(res[f"plant.{s}"], float) for s in signals}

    def close(self):
        for m in self.masters.values():
            m.close()
        self.masters.clear()


def _make_engine(engine, plant, fmu_dir=None, fmu_step=None):
    if hasattr(plant, "trajectory_engine"):
        # a plant that brings its own co-simulation (the user's plant FMU,
        # diagnosis.plant_fmu.FMUPlantModel)
        return plant.trajectory_engine(engine)
    if engine == "plant":
        return _PlantEngine(plant)
    if engine == "fmu":
        return _FMUEngine(plant, fmu_dir, fmu_step)
    raise ValueError(f"engine must be 'plant' or 'fmu', got {engine!r}")


def simulate_record(plant, law: FrictionModel, record: TrajectoryRecord, *,
                    engine: str = "plant", plant_params: dict | None = None,
                    delay: float = 0.0, fmu_dir=None, fmu_step: float | None = None
                    ) -> np.ndarray:
    """Simulated output of ``plant`` with friction ``law`` at the record's samples [m].

    Parameters
    ----------
    plant : Plant
    law : FrictionModel
        Friction law inside the plant (an :class:`EffectLaw` for force effects).
    record : TrajectoryRecord
    engine : {"plant", "fmu"}
        In-process plant or plant FMU + friction FMU (see the module docstring).
    plant_params : dict, optional
        Plant parameters changed for this run (e.g. the mass).
    delay : float
        Measured channel lagging the simulation by ``delay`` [s].
    fmu_dir : path, optional
        Folder with the built FMUs (engine ``"fmu"``).
    fmu_step : float, optional
        Communication step [s] of the FMU engine.
    """
    eng = _make_engine(engine, plant, fmu_dir, fmu_step)
    try:
        return TrajectoryModel(plant, eng)._output(law, plant_params or {}, record,
                                                   record.t[-1], delay)[0]
    finally:
        if hasattr(eng, "close"):
            eng.close()


class TrajectoryModel:
    """Runs one plant with a given friction law on measured records.

    Parameters
    ----------
    plant : Plant
        The plant model (its friction is replaced per run).
    engine : object
        ``_PlantEngine`` or ``_FMUEngine`` (see :func:`simulate_record`).
    progress : callable, optional
        ``progress(n, info)`` after each simulation (a :class:`friction.progress.Progress`).

    Attributes
    ----------
    sims : int
        Plant simulations run so far; ``sim_seconds`` [s] their wall time.
    ref_name : str or None
        Output holding the plant's position command (tracking-error reference).
    """

    def __init__(self, plant, engine, progress=None):
        self.plant = plant
        self.engine = engine
        self.sims = 0
        self.sim_seconds = 0.0
        self.progress = progress
        self.signal_default = plant.main_output
        self.ref_name = _reference_output(plant)

    def _output(self, law, plant_params, record, stop, delay=0.0):
        sig = record.signal or self.signal_default
        signals = [sig] + ([self.ref_name] if self.ref_name else [])
        if isinstance(law, EffectLaw) and record.t_start != law.time0:
            law = law.with_time0(record.t_start)
        t0 = time.perf_counter()
        ts, out = self.engine.run(law, plant_params, record.options, stop, signals)
        self.sim_seconds += time.perf_counter() - t0
        self.sims += 1
        if self.progress is not None:
            self.progress(1, f"{law.name} on {record.name}")
        y = out[sig]
        if not np.all(np.isfinite(y)):
            raise FloatingPointError(f"simulation of {record.name} with {law.name} diverged")
        # a lagging measurement channel sees the simulated output delay seconds late
        y_at = np.interp(record.t - delay, ts, y)
        ref = np.interp(record.t, ts, out[self.ref_name]) if self.ref_name else None
        return y_at, ref
