"""Identification through the user's own plant FMU: every evaluation co-simulates the
friction-law FMU (native C by default) with the plant FMU, coupled and driven by measured
columns as a connection file says (:mod:`fmus.connect`), and compares plant outputs with the
measured ones.

>>> from identification.plant_fmu import identify_plant_fmu          # doctest: +SKIP
>>> res = identify_plant_fmu("run1.csv", "rig.fmu", "rig.toml", "lugre")
>>> res.params      # law parameters and the plant's identified ones ("plant.m")
>>> res.fit_nrmse   # NRMSE of the compared output(s), e.g. the position

The cost is the NRMSE of the compared channel, ``RMS(y_sim - y_meas) / std(y_meas)``; with
several ``[compare]`` channels, the root of their weighted mean square NRMSE. A trial point
whose co-simulation fails (the plant diverges, an FMU refuses a value) costs ``inf`` (its
residuals a large constant) and the search goes on; the start point must run, so a plant
that cannot initialise or diverges with the user's own values is a one-line error naming
the variable and the time.

The built-in cases are special cases of the same path: the project's ``mass`` FMU with
:func:`fmus.connect.builtin_connection` is the closed loop of
:class:`identification.cosim.ClosedLoopCoSimObjective`, bit for bit.
"""
from __future__ import annotations

import math
import os
import time
from types import SimpleNamespace

import numpy as np

from friction import make_model
from friction.base import FrictionModel

from .cosim import _MasterHolder
from .objectives import Objective
from .space import ParameterSpace

__all__ = ["PlantFMUObjective", "identify_plant_fmu", "plant_fmu_space", "start_law",
           "default_law_names", "FAILED_RESIDUAL"]

#: residual of a failed trial point (per sample, in units of the channel's spread)
FAILED_RESIDUAL = 1e3


def default_law_names(model: FrictionModel) -> list[str]:
    """Law parameters a trajectory fit identifies by default: the trajectory level's base
    set (:data:`diagnosis.trajectory.BASE_NAMES`: symmetric, no offset, Stribeck exponent
    kept), else every free parameter but ``alpha`` and ``b``."""
    try:
        from diagnosis.trajectory import BASE_NAMES
    except ImportError:  # pragma: no cover
        BASE_NAMES = {}
    if model.name in BASE_NAMES:
        return list(BASE_NAMES[model.name])
    return [n for n in model.free_names() if n not in ("alpha", "b")
            and not n.endswith("_neg")]


def start_law(model, conn) -> FrictionModel:
    """The law to start from: ``model`` (name or instance; default the connection's ``[law]
    model`` or ``lugre``) with the connection's ``[law] start`` values."""
    if model is None:
        model = conn.law_model or "lugre"
    law = make_model(model) if isinstance(model, str) else model
    if not isinstance(law, FrictionModel):
        raise TypeError(f"model must be a registry name or a FrictionModel, got "
                        f"{type(model).__name__}")
    if conn.law_start:
        try:
            law = law.with_values(**conn.law_start)
        except (TypeError, ValueError, KeyError) as exc:
            raise ValueError(f"{conn.source}: [law] start: {exc}") from None
    return law


class _Stacked:
    """What :class:`identification.problem.Problem` reads as ``objective.data``: the compared
    channels stacked, each scaled by sqrt(weight / mean weight) / its spread, so that the
    RMS of the stacked residual is the root of the weighted mean square NRMSE (channels
    of equal length)."""

    def __init__(self, t, F, name):
        self.t, self.F, self.name = t, F, name

    def __len__(self):
        return int(self.F.size)


class PlantFMUObjective(_MasterHolder, Objective):
    """Cost of law (and plant) parameters through the co-simulation with the plant FMU.

    Parameters
    ----------
    model : FrictionModel
        The law; its values fix every law parameter not in ``names``.
    record : fmus.connect.MeasuredRecord
        Measured columns (inputs and compared outputs).
    names : list of str
        Identified parameters: law names and ``plant.<name>`` for plant parameters.
    conn : fmus.connect.PlantConnection or path
    plant_fmu : path
    native : bool
        The native C law FMU (default) or the pythonfmu one.
    fmu_dir : path, optional
        Folder with the law FMU (default: built once per process).
    """
    parallel_inside = False

    def __init__(self, model, record, names, conn, plant_fmu, *, native: bool = True,
                 fmu_dir=None):
        from fmus.connect import check_columns, check_plant, load_connection
        from .cosim import fmu_dir_for
        self.model = model
        self.conn = load_connection(conn)
        self.plant_fmu = os.fspath(plant_fmu)
        check_plant(self.conn, self.plant_fmu, model)
        check_columns(self.conn, record)
        self.record = record
        self.names = list(names)
        self.native = bool(native)
        self.fmu_dir = fmu_dir_for([model.name], fmu_dir, self.native)
        law_names = set(model.Params.numeric_names())
        plant_names = {f"plant.{p.name}" for p in self.conn.identify}
        bad = [n for n in self.names if n not in law_names and n not in plant_names]
        if bad:
            raise KeyError(f"{bad}: not parameters of {model.name} nor plant parameters in "
                           f"{self.conn.source} [identify] ({sorted(plant_names) or 'none'})")
        weights = np.array([s.weight for s in self.conn.compare], float)
        self.channels = []
        parts = []
        for s, w in zip(self.conn.compare, weights / weights.mean()):
            y = record.column(s.column) * s.scale
            sd = float(np.std(y))
            if not sd > 0:
                raise ValueError(f"{record.name}: compared column {s.column!r} is constant; "
                                 f"its NRMSE is undefined")
            k = math.sqrt(w) / sd
            self.channels.append((s, k, y))
            parts.append(y * k)
        self.data = _Stacked(record.t, np.concatenate(parts), record.name)
        self._master = None
        self.n_runs = 0

    @property
    def _sd(self) -> float:
        return 1.0

    @property
    def _rscale(self) -> float:
        return 1.0 / math.sqrt(len(self.data.F))

    def _open(self):
        if self._master is None:
            from fmus.connect import PlantLoop
            self._master = PlantLoop(self.plant_fmu, self.conn, self.model,
                                     native=self.native, fmu_dir=self.fmu_dir)
        return self._master

    def values(self, x) -> tuple[dict, dict]:
        """(law parameters for the FMU, plant parameters) of one parameter vector."""
        from fmus.master import law_parameters
        law = law_parameters(self.model)
        plant = {}
        for n, v in zip(self.names, np.asarray(x, float)):
            if n.startswith("plant."):
                plant[n[6:]] = float(v)
            else:
                law[n] = float(v)
        return law, plant

    def simulate(self, x, record=None):
        """The co-simulation (:class:`fmus.connect.PlantRun`) of one parameter vector on
        the fitted record (or another ``record``); raises on failure."""
        law, plant = self.values(x)
        self.n_runs += 1
        return self._open().run(record or self.record, law, plant)

    def stacked(self, run, record=None) -> np.ndarray:
        rec = record or self.record
        return np.concatenate([run.at(s.variable, rec.t) * k for s, k, _ in self.channels])

    def predict(self, X) -> np.ndarray:
        X = np.atleast_2d(np.asarray(X, float))
        out = np.empty((X.shape[0], len(self.data)))
        for i, x in enumerate(X):
            try:
                out[i] = self.stacked(self.simulate(x))
            except Exception:  # noqa: BLE001 - a failed trial point costs inf, not the run
                out[i] = np.nan
                self.close()  # a refused call may leave an instance unusable: reopen
        return out

    def residuals(self, x) -> np.ndarray:
        r = super().residuals(x)
        return np.where(np.isfinite(r), r, FAILED_RESIDUAL * self._rscale)

    def channel_nrmse(self, x, record=None) -> dict:
        """NRMSE per compared channel (plant output name -> value) of one parameter vector
        on the fitted record or another ``record``."""
        rec = record or self.record
        run = self.simulate(x, rec)
        out = {}
        for s in self.conn.compare:
            y = rec.column(s.column) * s.scale
            d = run.at(s.variable, rec.t) - y
            out[s.variable] = float(np.sqrt(np.mean(d * d)) / np.std(y))
        return out


def plant_fmu_space(model, names, conn, bounds=None, data=None) -> ParameterSpace:
    """Search space: the law's names with their default (data-widened) or given boxes, then
    the plant parameters with the connection's ``[identify]`` boxes (log-scaled where
    ``log = true``, or positive and spanning more than a factor 20)."""
    law_names = [n for n in names if not n.startswith("plant.")]
    plant = {f"plant.{p.name}": p for p in conn.identify}
    lower, upper, log = [], [], []
    if law_names:
        lb = {**conn.law_bounds, **(bounds or {})}
        lb = {k: v for k, v in lb.items() if k in law_names}
        sp = ParameterSpace.build(model, law_names, lb, data)
        lower += list(sp.lower)
        upper += list(sp.upper)
        log += list(sp.log)
    for n in names:
        if not n.startswith("plant."):
            continue
        p = plant[n]
        lo, hi = p.lower, p.upper
        if bounds and n in bounds:
            lo, hi = map(float, bounds[n])
        lg = p.log if p.log is not None else bool(lo > 0 and hi / lo > 20)
        lower.append(lo)
        upper.append(hi)
        log.append(lg)
    ordered = law_names + [n for n in names if n.startswith("plant.")]
    return ParameterSpace(ordered, np.array(lower, float), np.array(upper, float),
                          np.array(log, bool))


def _identifiability(space, u, cost, jac, n, level=0.95) -> tuple[dict, dict]:
    """Gauss-Newton report from the final Jacobian: ``at_bound``, ``unidentified`` (an
    interval wider than the search box), ``advice``, ``intervals``."""
    from .api import confidence_intervals
    names = list(space.names)
    at_bound = [nm for nm, ui in zip(names, u) if ui <= 1e-3 or ui >= 1 - 1e-3]
    ci, intervals, unidentified = {}, {}, []
    if jac is not None and np.all(np.isfinite(jac)):
        ci = confidence_intervals(space, u, jac, cost, n, level)
        for nm, lo_box, hi_box in zip(names, space.lower, space.upper):
            lo, hi = ci[nm]
            open_ = [s for s, hit in (("lower", lo <= lo_box), ("upper", hi >= hi_box)) if hit]
            ci[nm] = (max(lo, float(lo_box)), min(hi, float(hi_box)))
            intervals[nm] = {"low": ci[nm][0], "high": ci[nm][1], "method": "gauss-newton",
                             "open": open_}
            if len(open_) == 2:
                unidentified.append(nm)
    bounds = {}
    for nm, ui, lo_box, hi_box, xi in zip(names, u, space.lower, space.upper,
                                          space.to_physical(u)):
        if nm in at_bound:
            low = ui <= 0.5
            bounds[nm] = {"side": "lower" if low else "upper", "kind": "search box",
                          "bound": float(lo_box if low else hi_box), "value": float(xi)}
    advice = []
    for nm in at_bound:
        advice.append(f"{nm} sits at the edge of its search box: widen its bounds (or fix "
                      f"it) and run again")
    for nm in unidentified:
        advice.append(f"{nm} is not determined by this record (its interval spans the whole "
                      f"box): fix it, or measure a motion that excites it")
    return {"at_bound": at_bound, "unidentified": unidentified, "advice": advice,
            "bounds": bounds, "intervals": intervals, "level": level,
            "method": "gauss-newton"}, ci


def _as_record(data, conn, what):
    from fmus.connect import MeasuredRecord, load_measured
    if isinstance(data, MeasuredRecord):
        return data
    if isinstance(data, (str, os.PathLike)):
        return load_measured(data, conn)
    raise TypeError(f"{what} must be a file path or a fmus.connect.MeasuredRecord, got "
                    f"{type(data).__name__}")


def identify_plant_fmu(data, plant_fmu, connect, model=None, *, names=None, bounds=None,
                       algorithm=None, seed: int = 0, max_evals=None, validation=None,
                       progress=None, executor="inline", native: bool = True, fmu_dir=None,
                       **options):
    """Identify a friction law (and plant parameters) through the user's plant FMU.

    Parameters
    ----------
    data : path or fmus.connect.MeasuredRecord
        The measured run (CSV/.mat with the columns the connection names).
    plant_fmu : path
        The plant (FMI 2.0 co-simulation FMU).
    connect : path, dict or fmus.connect.PlantConnection
        The connection file (see :mod:`fmus.connect`).
    model : str or FrictionModel, optional
        The law (default: the connection's ``[law] model``, else ``lugre``), started from
        its values and the connection's ``[law] start``.
    names : list of str, optional
        Identified parameters (default: the connection's ``[law] names`` or
        :func:`default_law_names`, plus every ``[identify]`` plant parameter as
        ``plant.<name>``).
    bounds : dict, optional
        ``name -> (low, high)`` over the connection's and the default boxes.
    algorithm, seed, max_evals, progress, executor, **options
        As :func:`identification.identify` (``executor`` default ``"inline"``: one
        co-simulation at a time in this process).
    validation : path, record or list, optional
        Held-out run(s), scored with the identified values (``validation_nrmse``).
    native : bool
        Native C law FMU (default) or the pythonfmu one.

    Returns
    -------
    IdentificationResult
        ``params`` (law and ``plant.<name>``), ``model`` (the fitted law), ``plant_params``,
        ``fit_nrmse`` / ``validation_nrmse`` (compared channels), ``channels`` (per-channel
        NRMSE), ``ci``, ``identifiability`` (Gauss-Newton: ``at_bound``, ``unidentified``,
        ``advice``), evaluations, trace and wall time.
    """
    from fmus.connect import PlantRunError, check_plant, load_connection
    from .algorithms import DEFAULT_ALGORITHM, get_algorithm
    from .api import _as_progress
    from .executors import make_executor
    from .problem import BudgetExhausted, Problem
    from .result import IdentificationResult

    t_start = time.perf_counter()
    conn = load_connection(connect)
    law = start_law(model, conn)
    check_plant(conn, plant_fmu, law)
    record = _as_record(data, conn, "data")
    vals = validation if isinstance(validation, (list, tuple)) else \
        ([] if validation is None else [validation])
    val_records = [_as_record(v, conn, "validation") for v in vals]
    if names is None:
        names = list(conn.law_names or default_law_names(law)) + conn.plant_names()
    names = list(dict.fromkeys(names))
    if not names:
        raise ValueError("nothing to identify: names is empty")
    alg = get_algorithm(algorithm if algorithm is not None else DEFAULT_ALGORITHM, **options)
    if max_evals is not None and not (isinstance(max_evals, (int, np.integer))
                                      and max_evals > 0):
        raise ValueError(f"max_evals = {max_evals!r}: the evaluation budget must be a "
                         f"positive integer")
    obj = PlantFMUObjective(law, record, names, conn, plant_fmu, native=native,
                            fmu_dir=fmu_dir)
    plant_start = {f"plant.{p.name}": p.start for p in conn.identify}
    x0 = []
    for n in names:
        if n.startswith("plant."):
            v = plant_start.get(n)
            if v is None:
                v = obj_plant_start(conn, plant_fmu, n[6:])
        else:
            v = getattr(law.params, n)
            if v is None and n.endswith("_neg"):
                v = getattr(law.params, n[:-4])
        x0.append(float(v))
    x0 = np.array(x0, float)
    # the start point must run: a plant that cannot initialise or diverges with the
    # user's own values is bad input, named here (trial points later only cost inf)
    try:
        run0 = obj.simulate(x0)
    except PlantRunError:
        obj.close()
        raise
    kin = obj.conn.law_inputs
    v0 = run0.at(kin["v"], record.t)
    F_drive = [record.column(s.column) * s.scale for s in conn.inputs
               if _unit_of(obj, s.variable) == "N"]
    F_scale = np.abs(np.concatenate(F_drive)) if F_drive else \
        np.abs(run0.at("friction.F", record.t))
    pseudo = SimpleNamespace(F=F_scale if np.any(F_scale > 0) else np.ones(1),
                             v=v0 if np.any(v0 != 0) else np.ones(1))
    space = plant_fmu_space(law, names, conn, bounds, pseudo)
    order = [names.index(n) for n in space.names]
    x0 = x0[order]
    obj.names = list(space.names)
    exe = make_executor(executor, obj)
    problem = Problem(obj, space, exe, max_evals=max_evals)
    rng = np.random.default_rng(seed)
    u0 = np.clip(space.to_unit(x0), 0.0, 1.0)
    prog = _as_progress(progress, f"identify {alg.name} (plant FMU)")
    history: list[float] = []
    info: dict = {}
    try:
        if alg.steppable:
            state = None
            try:
                state = alg.start(problem, rng, u0)
                history.append(problem.best_cost)
                while not alg.finished(state) and not problem.exhausted:
                    state = alg.step(problem, rng, state)
                    history.append(problem.best_cost)
                    if prog is not None:
                        prog(1, f"it {state.get('iteration')} evals {problem.n_evals} "
                                f"cost={problem.best_cost:.4g}")
            except BudgetExhausted:
                pass
            info = dict(state.get("info", {})) if state else {}
        else:
            info = alg.run(problem, rng, u0, progress=prog) or {}
            history = list(info.pop("history", [problem.best_cost]))
    finally:
        if exe is not None and not (executor is not None and hasattr(executor, "costs")):
            exe.close()
    if prog is not None:
        prog.close()  # a bar made here ends with its last line
    if problem.best_u is None:
        obj.close()
        raise RuntimeError(f"{alg.name}: no trial point ran through the plant FMU (every "
                           f"co-simulation failed); check the connection and the bounds")
    u_best = problem.best_u
    x_best = space.to_physical(u_best)
    params = space.dict_of(x_best)
    law_fit = {n: v for n, v in params.items() if not n.startswith("plant.")}
    try:
        fitted = law.with_values(**law_fit)
    except Exception as exc:  # noqa: BLE001
        obj.close()
        raise ValueError(f"identified parameters are not admissible for {law.name}: "
                         f"{exc}") from None
    jac = None
    if info.get("jac") is not None and info.get("u") is not None and \
            np.allclose(np.asarray(info["u"], float), u_best):
        jac = info["jac"]
    else:
        try:
            jac = problem.jacobian_uncounted(u_best)
        except Exception:  # noqa: BLE001 - intervals are a bonus, not the result
            jac = None
    ident, ci = _identifiability(space, u_best, problem.best_cost, jac, len(obj.data))
    channels = {"fit": obj.channel_nrmse(x_best)}
    val = None
    if val_records:
        per = []
        for rec in val_records:
            vobj = PlantFMUObjective(law, rec, space.names, conn, plant_fmu, native=native,
                                     fmu_dir=obj.fmu_dir)
            try:
                c = vobj.costs(x_best[None, :])[0]
                channels[rec.name] = vobj.channel_nrmse(x_best) if math.isfinite(c) else None
            finally:
                vobj.close()
            per.append(c)
        val = float(np.sqrt(np.mean(np.square(per))))
    obj.close()
    wall = time.perf_counter() - t_start
    return IdentificationResult(
        params=params, model=fitted, fit_nrmse=float(problem.best_cost),
        validation_nrmse=val, cost_history=[float(c) for c in history],
        n_evals=int(problem.n_evals),
        trace=[[int(n), float(sec), float(c)] for n, sec, c in problem.trace],
        wall_time=float(wall), ci=ci or None, algorithm=alg.name, seed=seed,
        options=dict(alg.options), bounds=space.as_json(), resumed=False,
        message=str(info.get("message", "")), data=record.name,
        executor=getattr(exe, "name", type(exe).__name__), identifiability=ident, fixed={},
        plant_params={n[6:]: v for n, v in params.items() if n.startswith("plant.")},
        channels=channels, plant_fmu=os.path.basename(os.fspath(plant_fmu)),
        connection=conn.source, law_fmu="native" if native else "pythonfmu")


def obj_plant_start(conn, plant_fmu, name) -> float:
    """Start value of an identified plant parameter without ``start``: the connection's
    ``[parameters]`` value, else the FMU's declared start."""
    if name in conn.parameters:
        return float(conn.parameters[name])
    from fmus.connect import check_plant
    var = check_plant(conn, plant_fmu)[name]
    if var.start in (None, ""):
        raise ValueError(f"{conn.source}: [identify] {name}: no start value (give start = "
                         f"..., or set it in [parameters])")
    return float(var.start)


def _unit_of(obj, variable) -> str | None:
    from fmus.connect import _declared_unit, _norm_unit, check_plant
    if not hasattr(obj, "_units"):
        V = check_plant(obj.conn, obj.plant_fmu)
        obj._units = {k: _norm_unit(_declared_unit(v)) for k, v in V.items()}
    return obj._units.get(variable)
