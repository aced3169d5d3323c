"""Plant + friction-law co-simulation: the connections, the master of a plant FMU with a law FMU
and the proof against each plant's reference integrator (the plant FMUs' recipes are in
:mod:`fmus.recipes`, the port names in :mod:`fmus.coupling`).

Each plant of ``plants.PLANTS`` becomes ``<plant>.fmu``: the plant in external-friction mode
(input ``F_friction`` [N]; outputs its signals, among them the kinematics ``x, v, a`` and the
load the law needs). A friction-law FMU closes the loop::

    plant.v -> friction.v, plant.a -> friction.a, plant.x -> friction.x,
    plant.<load> -> friction.load, friction.F -> plant.F_friction
    friction.<c> -> plant.<c> for c in COUPLING_OUTPUTS          (coupling "linearised")

Coupling. Holding the friction force over a communication step (``"hold"``) destabilises a
stiff contact (the press bristle on 80 t at the 100 Hz data rate) or, where the friction
reverses within a data period, rings a stiff, lightly damped sensor mode (the rig's 1.1 kHz
force sensors, the isolator's 225 Hz load cell), unless the step is far below the data
period. The default ``"linearised"`` coupling is linearly implicit: the law FMU also outputs
its local linearisation over the coming step (``fmus.coupling.law_linearisation``; parameter
``h_lin`` = the communication step):

* ``dF_dx`` [N/m], ``dF_dv`` [N.s/m]: slopes of its step map against the travel and the end
  velocity (sticking: the bristle spring and damping; sliding: the viscous slope), taken
  around the motion extrapolated from its last three input samples;
* ``dF_dt`` [N/s], ``d2F_dt2`` [N/s^2]: what those slopes miss along that motion, quadratic
  in time through the middle and the end of the step;
* ``t_kink`` [s], ``dF_dt_kink`` [N/s]: where the extrapolated velocity reverses inside the
  step, the residual is piecewise linear instead, with this change of slope there (|v|);
* a law whose coefficients jump at |v| = vc (``load_lugre``): ``v_switch`` [m/s] and the
  other side's force and slopes (``dF_switch``, ``dF_dx_switch``, ``dF_dv_switch``;
  ``fmus.coupling.switch_linearisation``). The plant's substeps hold the side of their own
  velocity, cut at the crossing and slide along |v| = vc (Filippov) where both sides push
  onto it; the plant's output ``low_share`` (share of the step below vc, a sliding stretch
  with its Filippov weight) goes back to the law, whose bristle state advances with that mix
  of both regimes. Without this the law at the 10 ms data period of the press linearises
  across the jump and the loop rings between the regimes (3.6e-3 over 2 s).

The plant also outputs ``v_mean`` (travel over the step / step) and the law FMU advances its
state with it (parameter ``use_v_mean``, set with Gauss-Seidel): the state then follows the
travel the plant really made, not the trapezoid of the end-point velocities, which aliases
the bristle-mass mode inside a long step (the press at 10 ms went unstable while its bristle
re-deflects during the 0.002 mm/s creep).

The plant FMU integrates its step with
``F(t) = F_k + dF_dx (x(t) - x_k) + dF_dv (v(t) - v_k) + R(t - t_k)`` (``R`` the residual
above), so the stiff part of the contact is resolved inside the plant's own substeps
(``plants.stepper.PlantStepper``). With Gauss-Seidel (plant first) the law advances its state
with its inputs at both ends of the step (parameter ``inputs_at_step_end``).

:func:`plant_proof` runs that loop with our master at the plant's data rate and compares the main output with
``Plant(friction=law).simulate(method="reference")`` (monolithic ``solve_ivp``), for the
classic LuGre and for the plant's own seed law.
"""
from __future__ import annotations

import dataclasses
import math

from .coupling import COUPLING_OUTPUTS, MEAN_INPUT, SHARE_INPUT, SWITCH_OUTPUTS, has_switch

__all__ = ["plant_connections", "classic_lugre_for", "plant_laws",
           "plant_master", "plant_proof", "coupling_step", "data_step", "MAX_COUPLING_STEP",
           "COUPLINGS", "LOAD_SIGNALS", "XML350_ORDER", "XML350_CONNECTIONS",
           "xml350_loop_master"]

#: coupling of plant and friction FMU: linearly implicit (default) or force held over a step
COUPLINGS = ("linearised", "hold")

#: plant output carrying the friction law's load input, in order of preference
LOAD_SIGNALS = ("load", "F_sigma", "F_N")


#: the XML-350 loop from part FMUs: Gauss-Seidel order and connections (the controller
#: samples after the stage has advanced, the stage uses the friction of the previous
#: communication point; reproduces ``plants.studies.xml350.run_assembled(separate_friction=True)``)
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


def xml350_loop_master(fmu_dir, *, friction_params: dict | None = None, record=None,
                       native: bool = False):
    """An open :class:`fmus.master.Master` of the XML-350 loop assembled from part FMUs
    (``native``: the friction law is ``lugre_native.fmu``, the parts stay pythonfmu FMUs).

    Parameters
    ----------
    fmu_dir : str or path
        Folder of built FMUs.
    friction_params : dict, optional
        Parameter values of the LuGre law FMU.
    record : list of str, optional
        ``"instance.variable"`` to record.
    native : bool
        See above.
    """
    from plants.xml350 import xml350_friction
    from .master import Master, fmu_file
    fmus = {"trajectory": "xml350_trajectory", "feedforward": "lugre_feedforward",
            "mechanics": "xml350_mechanics", "friction": "lugre", "controller": "sdpid"}
    fmus = {k: fmu_file(fmu_dir, v, native and k == "friction") for k, v in fmus.items()}
    law = xml350_friction()
    params = {"friction": {**_law_params(law), **(friction_params or {})}}
    return Master(fmus, XML350_CONNECTIONS, order=XML350_ORDER, iterations=1,
                  parameters=params,
                  record=record or ["mechanics.x", "trajectory.x_d", "controller.i_cmd",
                                    "friction.F"])


def plant_connections(plant_cls, law_cls, coupling: str = "hold") -> list[tuple[str, str]]:
    """Connections plant <-> friction law for the law's inputs (and, for the
    ``"linearised"`` coupling, the law's coupling outputs into the plant; that needs the
    law's ``h_lin`` set, as :func:`plant_master` does).

    Parameters
    ----------
    plant_cls : type
        The plant class.
    law_cls : type
        The friction-law class.
    coupling : {"hold", "linearised"}
        How the force couples (see above).
    """
    if coupling not in COUPLINGS:
        raise ValueError(f"coupling must be one of {COUPLINGS}, got {coupling!r}")
    outs = plant_cls(external_friction=True).all_output_names
    conns = [("plant.v", "friction.v"), ("friction.F", "plant.F_friction")]
    if coupling == "linearised":
        conns += [(f"friction.{n}", f"plant.{n}") for n in COUPLING_OUTPUTS]
        if law_cls.state_names:   # the law's state follows the plant's travel
            conns.append((f"plant.{MEAN_INPUT}", f"friction.{MEAN_INPUT}"))
        if has_switch(law_cls):   # coefficients jump at |v| = v_switch
            conns += [(f"friction.{n}", f"plant.{n}") for n in SWITCH_OUTPUTS]
            conns.append((f"plant.{SHARE_INPUT}", f"friction.{SHARE_INPUT}"))
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

    Parameters
    ----------
    plant_cls : type
        The plant class.
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
    """The two laws of the proof: ``{"lugre": classic LuGre, <seed name>: seed law}``.

    Parameters
    ----------
    plant_cls : type
        The plant class.
    """
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
                 iterations: int = 0, record=None, coupling: str = "linearised",
                 step: float | None = None, native: bool = False):
    """An open :class:`fmus.master.Master` of ``<plant>.fmu`` + ``<law>.fmu``.

    ``coupling``: ``"linearised"`` (the law's ``dF_dx``, ``dF_dv``, ``dF_dt`` drive the
    plant; the law's ``h_lin`` is set to ``step``, default :func:`data_step`; change
    ``master.parameters["friction"]["h_lin"]`` when running at another step; with
    Gauss-Seidel the law advances its state with the inputs at both ends of the step) or
    ``"hold"``. ``native``: the law is the native C FMU ``<law>_native.fmu`` of ``fmu_dir``
    (the same results; its switching law reads ``low_share`` only with ``use_low_share``,
    which is set where the coupling connects it).

    Parameters
    ----------
    fmu_dir : str or path
        Folder of built FMUs.
    plant_name : str
        Registry name of the plant.
    law : FrictionModel
        The friction law (its FMU is ``<law.name>.fmu``).
    algorithm : {"gauss-seidel", "jacobi"}
        Master algorithm.
    iterations : int
        Fixed-point iterations per step.
    record : list of str, optional
        ``"instance.variable"`` to record (default the plant's outputs).
    coupling : {"linearised", "hold"}
        See above.
    step : float, optional
        Communication step [s] for ``h_lin`` (default :func:`data_step`).
    native : bool
        See above.
    """
    import plants
    from .master import Master, fmu_file
    cls = plants.PLANTS[plant_name]
    fmus = {"plant": fmu_file(fmu_dir, plant_name),
            "friction": fmu_file(fmu_dir, law.name, native)}
    main = cls.main_output
    params = _law_params(law)
    if has_switch(type(law)) and "vc" not in params and \
            "vc" in {f.name for f in dataclasses.fields(law.params)}:
        # the regime-split velocity the law derives (load_lugre: Eq. 13's root), passed as
        # the very double the reference uses: a root finder of the FMU's own may land an ulp
        # away, and a plant sliding along |v| = vc then sees the other regime at the tie
        params["vc"] = float(law.vc)
    if coupling == "linearised":
        params["h_lin"] = float(step if step is not None else data_step(cls))
        # Gauss-Seidel, plant first: the law's inputs at its step are those at the end
        params["inputs_at_step_end"] = algorithm == "gauss-seidel"
        if law.state_names:  # plant.v_mean of the same step (Gauss-Seidel, plant first)
            params["use_v_mean"] = algorithm == "gauss-seidel"
        if has_switch(type(law)):  # plant.low_share of the same step, likewise
            params["use_low_share"] = algorithm == "gauss-seidel"
    m = Master(fmus, plant_connections(cls, type(law), coupling), algorithm=algorithm,
               parameters={"friction": params}, iterations=iterations,
               record=record or [f"plant.{main}", "friction.F"])
    return m


#: longest communication step of the finer-step fallback [s]: a stiff contact coupled with
#: the force held over a step needs about 10 kHz
MAX_COUPLING_STEP = 1e-4


def data_step(plant_cls) -> float:
    """The plant's data period 1 / data_rate [s]: the communication step of the proof at the
    data rate. A controller sampling faster (the press: 1 kHz under 100 Hz data) runs at its
    own instants inside the plant FMU's step.

    Parameters
    ----------
    plant_cls : type
        The plant class.
    """
    return 1.0 / plant_cls.data_rate


def coupling_step(plant_cls, max_step: float | None = MAX_COUPLING_STEP) -> float:
    """Communication step of a plant + friction loop with the force held over a step [s].

    :func:`data_step` divided by the smallest integer that brings it to ``max_step`` or
    below, so results fall on the data samples (``max_step=None``: :func:`data_step`
    itself, what the linearised coupling of :func:`plant_proof` uses).

    Parameters
    ----------
    plant_cls : type
        The plant class.
    max_step : float, optional
        Largest communication step [s].
    """
    h = data_step(plant_cls)
    if max_step is None:
        return h
    return h / max(1, math.ceil(h / max_step - 1e-9))


def plant_proof(fmu_dir, plant_name: str, law, *, refinements: int = 2,
                stop: float | None = None, rtol: float = 1e-9, tol: float = 1e-3,
                max_halvings: int = 4, time_budget: float | None = None,
                coupling: str = "linearised", max_step: float | None = None,
                coarser: bool = False, plant_params: dict | None = None,
                native: bool = False) -> dict:
    """NRMSE of the co-simulated main output against the plant's reference integrator.

    The loop communicates at ``h0`` = :func:`data_step` (or, with ``max_step`` for the
    finer-step fallback, :func:`coupling_step`) and at ``h0 / 2**k``; results are
    compared with the reference at the plant's data rate. At least ``refinements`` steps
    are run (for the observed order); halving continues (at most ``max_halvings`` times)
    until the NRMSE is at most ``tol``. Below the data period the plant's internal substep
    (<= the communication step) shrinks too, so the coupling error is not masked by a fixed
    integrator error. ``plant_params`` changes plant parameters in the reference and the
    plant FMU alike (e.g. an encoder resolution of 0: a quantised closed loop does not repeat
    itself to the last count, a floor no step size removes). ``time_budget`` [s] stops a
    reference integration that crawls with
    ``TimeoutError``. ``coarser=True`` also runs the steps between ``h0`` and the data
    period that divide it (a plant whose controller samples faster than its data: the press
    at 1 kHz, data at 100 Hz), for an observed order above the integrator's error floor.
    ``native``: the law is the native C FMU (``<law>_native.fmu``; :func:`plant_master`).

    Parameters
    ----------
    fmu_dir, plant_name, law
        As for :func:`plant_master`.
    refinements : int
        Minimum number of communication steps run.
    stop : float, optional
        End of the run [s] (default: a few hundred data periods).
    rtol : float
        Relative tolerance of the reference integrator.
    tol : float
        NRMSE goal.
    max_halvings : int
        Most halvings of the step.
    time_budget : float, optional
        Wall-clock budget of the reference [s].
    coupling : {"linearised", "hold"}
        See :func:`plant_master`.
    max_step : float, optional
        Largest communication step [s] of the finer-step fallback.
    coarser : bool
        Also run at twice the data step.
    plant_params : dict, optional
        Plant parameter values (SI units) for the reference and the plant FMU.
    native : bool
        Use the native C law FMU.

    Returns
    -------
    dict
        ``nrmse`` and ``step``: the first communication step meeting ``tol`` (else the
        finest); ``nrmse_first`` at ``h0``; ``meets_tol_first``; ``steps``, ``errors``,
        ``order`` (least-squares slope of log error over log step), ``data_step``,
        ``stop``, ``law``, ``coupling``; with ``coarser``: ``coarse_steps``,
        ``coarse_errors`` (from the data period down to ``h0``) and ``coarse_order``.
    """
    import plants
    from friction.metrics import nrmse
    from .master import FMUError
    from .proof import observed_order
    cls = plants.PLANTS[plant_name]
    plant = cls(friction=law)
    if plant_params:
        plant = plant.with_params(**plant_params)
    hd = 1.0 / cls.data_rate
    h = data_step(cls) if max_step is None else coupling_step(cls, max_step)
    per = int(round(hd / h))  # communication steps per data sample
    if abs(per * h - hd) > 1e-9 * hd:
        raise ValueError(f"{plant_name}: communication step {h!r} does not divide the data "
                         f"period {hd!r}")
    stop = float(cls.default_experiment.stop) if stop is None else float(stop)
    n = int(round(stop / hd))
    ref = plant.simulate(n * hd, method="reference", rtol=rtol, time_budget=time_budget)
    main = cls.main_output
    steps, errors = [], []
    with plant_master(fmu_dir, plant_name, law, coupling=coupling, step=h,
                      native=native) as m:
        if plant_params:
            m.parameters["plant"] = {k: float(v) for k, v in plant_params.items()}
        for k in range(max_halvings + 1):
            hk = h / 2 ** k
            if coupling == "linearised":
                m.parameters["friction"]["h_lin"] = hk
            try:
                res = m.simulate(stop_time=n * hd, step_size=hk)
                err = float(nrmse(ref[main], res[f"plant.{main}"][:: per * 2 ** k]))
            except FMUError:  # a coarse step that diverges is a result, not a failure
                if k >= max_halvings:
                    raise
                err = math.inf
            errors.append(err if math.isfinite(err) else math.inf)
            steps.append(hk)
            if k + 1 >= refinements and min(errors) <= tol:
                break
        coarse = {}
        if coarser and per > 1:
            cs = [hd / q for q in range(1, per) if per % q == 0]   # data period ... > h0
            ce = []
            for hc in cs:
                if coupling == "linearised":
                    m.parameters["friction"]["h_lin"] = hc
                try:
                    res = m.simulate(stop_time=n * hd, step_size=hc)
                    stride = int(round(hd / hc))
                    ce.append(float(nrmse(ref[main], res[f"plant.{main}"][::stride])))
                except FMUError:
                    ce.append(math.inf)
            cs, ce = cs + [steps[0]], ce + [errors[0]]
            fin = [j for j, e in enumerate(ce) if math.isfinite(e)]
            coarse = {"coarse_steps": cs, "coarse_errors": ce,
                      "coarse_order": (observed_order([cs[j] for j in fin], [ce[j] for j in fin])
                                       if len(fin) > 1 else float("nan"))}
    ok = [i for i, e in enumerate(errors) if e <= tol]
    i = ok[0] if ok else len(errors) - 1
    fin = [j for j, e in enumerate(errors) if math.isfinite(e)]
    return {"nrmse": errors[i], "step": steps[i], "nrmse_first": errors[0],
            "meets_tol_first": bool(errors[0] <= tol), "steps": steps, "errors": errors,
            "order": (observed_order([steps[j] for j in fin], [errors[j] for j in fin])
                      if len(fin) > 1 else float("nan")),
            "law": law.name, "data_step": hd, "stop": n * hd, "coupling": coupling, **coarse}
