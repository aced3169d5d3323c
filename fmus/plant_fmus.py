"""FMUs of the plants (external friction) and the co-simulation proof against each plant's
reference integrator.

Each plant of ``plants.PLANTS`` becomes ``<plant>.fmu``: the plant in external-friction mode
(input ``F_friction`` [N]; outputs its signals, among them the kinematics ``x, v, a`` and the
load the law needs). A friction-law FMU closes the loop::

    plant.v -> friction.v, plant.a -> friction.a, plant.x -> friction.x,
    plant.<load> -> friction.load, friction.F -> plant.F_friction

:func:`plant_proof` runs that loop with our master at the plant's data rate and compares the
main output with ``Plant(friction=law).simulate(method="reference")`` (monolithic
``solve_ivp``), for the classic LuGre and for the plant's own seed law.
"""
from __future__ import annotations

import dataclasses
import math
import os

import numpy as np

from . import runtime

__all__ = ["recipes", "plant_connections", "classic_lugre_for", "plant_laws",
           "plant_master", "plant_proof", "coupling_step", "MAX_COUPLING_STEP", "LOAD_SIGNALS",
           "XML350_ORDER", "XML350_CONNECTIONS", "xml350_loop_master"]

#: plant output carrying the friction law's load input, in order of preference
LOAD_SIGNALS = ("load", "F_sigma", "F_N")


def recipes():
    """Build recipes of the plant FMUs (one per registered plant)."""
    from .build import FmuRecipe
    import plants
    out = []
    for name, cls in plants.PLANTS.items():
        de = cls.default_experiment
        doc = (cls.__doc__ or name).strip().splitlines()[0]
        out.append(FmuRecipe(
            name=name, base="StepperSlave",
            variables=(lambda cls=cls: runtime.plant_variables(cls, probe=True)),
            attributes=dict(plant=name, plants_package="{pkg:plants}"),
            packages=("friction", "plants"),
            description=f"Plant '{name}' with external friction (input F_friction): {doc}",
            default_experiment={"startTime": float(de.start), "stopTime": float(de.stop),
                                "stepSize": float(de.step)}))
    out += _xml350_part_recipes()
    return out


def _xml350_part_recipes():
    """The XML-350 loop from parts: stage mechanics, SD-PID, LuGre feedforward, trajectory."""
    from .build import FmuRecipe
    try:
        from plants import xml350
    except ImportError:
        return []
    mech = xml350.XML350Mechanics
    de = {"startTime": 0.0, "stopTime": float(mech.default_experiment.stop),
          "stepSize": float(mech.default_experiment.step)}
    out = [FmuRecipe(
        name="xml350_mechanics", base="StepperSlave",
        variables=lambda: runtime.plant_variables(mech, probe=True),
        attributes=dict(plant="xml350:XML350Mechanics", plants_package="{pkg:plants}"),
        packages=("friction", "plants"), default_experiment=dict(de),
        description="XML-350 stage mechanics (current loop, mass, encoder) with external "
                    "friction: inputs i_cmd [A], F_friction [N]")]
    descs = {"sdpid": "State-dependent PID of seed 003 Eq. (15) (acceleration units) with "
                      "current command output i_cmd = M_ctrl u / Kf",
             "lugre_feedforward": "LuGre friction feedforward of seed 003 Eq. (16)",
             "xml350_trajectory": "S-curve point-to-point trajectory of the XML-350 tests"}
    for kind, desc in descs.items():
        out.append(FmuRecipe(
            name=kind, base="BlockSlave",
            variables=(lambda kind=kind: runtime.block_variables(kind, "plants")),
            attributes=dict(block=kind, plants_package="{pkg:plants}"),
            packages=("friction", "plants"), default_experiment=dict(de), description=desc))
    return out


#: the XML-350 loop from part FMUs: Gauss-Seidel order and connections (the controller
#: samples after the stage has advanced, the stage uses the friction of the previous
#: communication point; reproduces ``plants.xml350.run_assembled(separate_friction=True)``)
XML350_ORDER = ["trajectory", "feedforward", "mechanics", "friction", "controller"]
XML350_CONNECTIONS = [
    ("trajectory.x_ff", "feedforward.x_d"), ("trajectory.v_ff", "feedforward.v_d"),
    ("trajectory.a_ff", "feedforward.a_d"),
    ("trajectory.x_d", "controller.x_d"), ("trajectory.v_d", "controller.v_d"),
    ("trajectory.a_ff", "controller.a_d"), ("trajectory.x_f", "controller.x_f"),
    ("feedforward.u_ff", "controller.u_ff"), ("mechanics.x_meas", "controller.x"),
    ("controller.i_cmd", "mechanics.i_cmd"),
    ("mechanics.v", "friction.v"), ("friction.F", "mechanics.F_friction"),
]


def xml350_loop_master(fmu_dir, *, friction_params: dict | None = None, record=None):
    """An open :class:`fmus.master.Master` of the XML-350 loop assembled from part FMUs."""
    from plants.xml350 import xml350_friction
    from .master import Master
    fmus = {"trajectory": "xml350_trajectory", "feedforward": "lugre_feedforward",
            "mechanics": "xml350_mechanics", "friction": "lugre", "controller": "sdpid"}
    fmus = {k: os.path.join(fmu_dir, f"{v}.fmu") for k, v in fmus.items()}
    law = xml350_friction()
    params = {"friction": {**_law_params(law), **(friction_params or {})}}
    return Master(fmus, XML350_CONNECTIONS, order=XML350_ORDER, iterations=1,
                  parameters=params,
                  record=record or ["mechanics.x", "trajectory.x_d", "controller.i_cmd",
                                    "friction.F"])


def plant_connections(plant_cls, law_cls) -> list[tuple[str, str]]:
    """Connections plant <-> friction law for the law's inputs."""
    outs = plant_cls(external_friction=True).all_output_names
    conns = [("plant.v", "friction.v"), ("friction.F", "plant.F_friction")]
    if "a" in law_cls.extra_inputs:
        conns.append(("plant.a", "friction.a"))
    if "x" in law_cls.extra_inputs:
        conns.append(("plant.x", "friction.x"))
    if "load" in law_cls.extra_inputs:
        src = next((s for s in LOAD_SIGNALS if s in outs), None)
        if src is None:
            raise ValueError(f"plant {plant_cls.name!r} has no load output for law "
                             f"{law_cls.name!r} (looked for {LOAD_SIGNALS})")
        conns.append((f"plant.{src}", "friction.load"))
    return conns


def classic_lugre_for(plant_cls):
    """Classic LuGre at the levels of the plant's seed law.

    Shared names carry over (``sigma0, sigma1, sigma2, Fc, Fs, vs, alpha, b, shape``); the
    load law's no-load levels map ``Fc0, Fs0, sigma20 -> Fc, Fs, sigma2``; the MRE law maps
    ``beta, eps, c0, f0 -> sigma0, sigma1, sigma2, b`` with ``Fc = Fs = beta / alpha`` (its
    saturated hysteretic force; the spring k0 x has no LuGre counterpart). Values are
    clipped into LuGre's admissible bounds (a press contact stiffer than 1e9 N/m).
    """
    import friction
    seed = plant_cls.default_friction()
    if seed.name == "lugre":
        return seed
    vals = {f.name: getattr(seed.params, f.name) for f in dataclasses.fields(seed.params)}
    if seed.name == "mre_lugre":
        level = vals["beta"] / vals["alpha"]
        kw = dict(sigma0=vals["beta"], sigma1=vals["eps"], sigma2=vals["c0"], Fc=level,
                  Fs=level, b=vals["f0"])
    else:
        alias = {"Fc0": "Fc", "Fs0": "Fs", "sigma20": "sigma2"}
        lugre_fields = {f.name for f in dataclasses.fields(friction.LuGreParams)}
        kw = {}
        for k, v in vals.items():
            k2 = alias.get(k, k)
            if k2 in lugre_fields and v is not None:
                kw[k2] = v
    info = {i.name: i for i in friction.LuGreParams.info()}
    for k, v in list(kw.items()):
        i = info.get(k)
        if i is not None and isinstance(v, float):
            kw[k] = min(max(v, i.lower), i.upper)
    return friction.make_model("lugre", **kw)


def plant_laws(plant_cls) -> dict:
    """The two laws of the proof: ``{"lugre": classic LuGre, <seed name>: seed law}``."""
    seed = plant_cls.default_friction()
    laws = {"lugre": classic_lugre_for(plant_cls)}
    laws[seed.name] = seed
    return laws


def _law_params(model) -> dict:
    out = {}
    for f in dataclasses.fields(model.params):
        v = getattr(model.params, f.name)
        if v is None:
            continue  # the FMU's "unset" start value already means None
        out[f.name] = v
    return out


def plant_master(fmu_dir, plant_name: str, law, *, algorithm: str = "gauss-seidel",
                 iterations: int = 0, record=None):
    """An open :class:`fmus.master.Master` of ``<plant>.fmu`` + ``<law>.fmu``."""
    import plants
    from .master import Master
    cls = plants.PLANTS[plant_name]
    fmus = {"plant": os.path.join(fmu_dir, f"{plant_name}.fmu"),
            "friction": os.path.join(fmu_dir, f"{law.name}.fmu")}
    main = cls.main_output
    return Master(fmus, plant_connections(cls, type(law)), algorithm=algorithm,
                  parameters={"friction": _law_params(law)}, iterations=iterations,
                  record=record or [f"plant.{main}", "friction.F"])


#: longest communication step of a plant + friction loop [s]: a stiff contact coupled
#: explicitly (force held over a step) needs about 10 kHz; slower data rates communicate at
#: an integer fraction of their sample period
MAX_COUPLING_STEP = 1e-4


def coupling_step(plant_cls, max_step: float = MAX_COUPLING_STEP) -> float:
    """Communication step of the plant + friction loop [s].

    The data period (or the controller period when the controller samples faster) divided
    by the smallest integer that brings it to ``max_step`` or below, so results fall on
    the data samples. (The forging press records at 100 Hz and the damping rig at 1 kHz; an
    explicit coupling of their contacts over 10 ms or 1 ms is unstable or inaccurate.)
    """
    h = 1.0 / plant_cls.data_rate
    if plant_cls.control_rate:
        h = min(h, 1.0 / plant_cls.control_rate)
    return h / max(1, math.ceil(h / max_step - 1e-9))


def _guarded(law, budget: float):
    """A copy of ``law`` whose ``force`` raises ``TimeoutError`` once ``budget`` s passed
    (the reference integrator evaluates it at every right-hand side call)."""
    import copy
    import time
    t_end = time.monotonic() + budget
    inner = law.force
    g = copy.copy(law)

    def force(*args, **kwargs):
        if time.monotonic() > t_end:
            raise TimeoutError(f"reference integrator of {law.name} exceeded the time budget "
                               f"of {budget:g} s")
        return inner(*args, **kwargs)

    g.force = force
    return g


def plant_proof(fmu_dir, plant_name: str, law, *, refinements: int = 2,
                stop: float | None = None, rtol: float = 1e-9, tol: float = 1e-3,
                max_halvings: int = 4, time_budget: float | None = None) -> dict:
    """NRMSE of the co-simulated main output against the plant's reference integrator.

    The loop communicates at ``h0`` = :func:`coupling_step` and at ``h0 / 2**k``; results
    are compared with the reference at the plant's data rate. Halving continues (at most
    ``max_halvings`` times) until the NRMSE is at most ``tol``, and at least ``refinements``
    steps are run for the observed order. Below the data period the plant's internal
    substep (<= the communication step) shrinks too, so the coupling error is not masked
    by a fixed integrator error. ``time_budget`` [s] stops a reference integration that
    crawls (e.g. across a discontinuity of the law) with ``TimeoutError``.

    Returns
    -------
    dict
        ``nrmse`` and ``step``: the first communication step meeting ``tol`` (else the
        finest); ``steps``, ``errors``, ``order`` (slope of log error over log step),
        ``data_step``, ``stop``, ``law``.
    """
    import plants
    from friction.metrics import nrmse
    from .proof import observed_order
    cls = plants.PLANTS[plant_name]
    plant = cls(friction=_guarded(law, time_budget) if time_budget else law)
    hd = 1.0 / cls.data_rate
    h = coupling_step(cls)
    per = int(round(hd / h))  # communication steps per data sample
    if abs(per * h - hd) > 1e-9 * hd:
        raise ValueError(f"{plant_name}: communication step {h!r} does not divide the data "
                         f"period {hd!r}")
    stop = float(cls.default_experiment.stop) if stop is None else float(stop)
    n = int(round(stop / hd))
    ref = plant.simulate(n * hd, method="reference", rtol=rtol)
    main = cls.main_output
    steps, errors = [], []
    with plant_master(fmu_dir, plant_name, law) as m:
        for k in range(max_halvings + 1):
            hk = h / 2 ** k
            res = m.simulate(stop_time=n * hd, step_size=hk)
            errors.append(nrmse(ref[main], res[f"plant.{main}"][:: per * 2 ** k]))
            steps.append(hk)
            if k + 1 >= refinements and min(errors) <= tol:
                break
    ok = [i for i, e in enumerate(errors) if e <= tol]
    i = ok[0] if ok else len(errors) - 1
    return {"nrmse": errors[i], "step": steps[i], "steps": steps, "errors": errors,
            "order": observed_order(steps, errors) if len(steps) > 1 else float("nan"),
            "law": law.name, "data_step": hd, "stop": n * hd}
