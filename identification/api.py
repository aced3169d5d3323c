"""``identify(data, model, ...)``: one interface over every algorithm and objective."""
from __future__ import annotations

import os
import time

import numpy as np

from friction import make_model
from friction.alignment import align_motion
from friction.base import FrictionModel
from friction.dataset import Dataset, load_dataset
from friction.metrics import nrmse
from friction.progress import as_progress

from .algorithms import DEFAULT_ALGORITHM, get_algorithm
from .checkpoint import CHECKPOINT_VERSION, EvaluationLog, fingerprint
from .objectives import InProcessObjective, Objective, check_data
from .executors import make_executor
from .problem import BudgetExhausted, Problem
from .result import IdentificationResult
from .space import ParameterSpace

__all__ = ["identify", "confidence_intervals", "CHECKPOINT_VERSION"]


def confidence_intervals(space: ParameterSpace, u, jac, cost: float, n: int,
                         level: float = 0.95) -> dict:
    """Gauss-Newton confidence intervals from the residual Jacobian in cube coordinates.

    ``cov_u = s^2 (J^T J)^-1`` with ``s^2 = sum(r^2) / (N - D)`` (residuals scaled by the same
    factor as ``J``, so the scale cancels); the interval ``u +- z sqrt(cov_uu)`` is mapped to
    physical values (asymmetric for log-scaled parameters). Assumes white residuals:
    coloured noise makes the intervals optimistic.

    Parameters
    ----------
    space : ParameterSpace
        The fitted parameters and their box.
    u : ndarray, shape (D,)
        The optimum in unit-cube coordinates.
    jac : ndarray, shape (N, D)
        Jacobian of the scaled residuals in unit-cube coordinates.
    cost : float
        NRMSE at the optimum.
    n : int
        Number of residuals N.
    level : float
        Confidence level (0.95: 95 %).
    """
    from statistics import NormalDist
    J = np.asarray(jac, float)
    D = J.shape[1]
    dof = max(n - D, 1)
    s2 = cost ** 2 / dof  # cost**2 = sum r^2
    cov = s2 * np.linalg.pinv(J.T @ J)
    sd = np.sqrt(np.clip(np.diag(cov), 0.0, None))
    z = float(NormalDist().inv_cdf(0.5 + level / 2))
    lo = space.to_physical(u - z * sd)
    hi = space.to_physical(u + z * sd)
    return {n_: (float(min(a, b)), float(max(a, b))) for n_, a, b in zip(space.names, lo, hi)}


def _as_progress(progress, label):
    """None when silent, else the :class:`friction.progress.Progress` of ``progress``
    (a bar labelled ``label`` for True; close it at the end of the run)."""
    if progress is None or progress is False:
        return None
    return as_progress(progress, label)


def _fitted_model(model: FrictionModel, params: dict) -> FrictionModel:
    return model.with_values(**params)


def identify(data, model, algorithm=None, names=None, bounds=None, seed=0, max_evals=None,
             validation=None, progress=None, checkpoint=None, *, objective=None,
             executor=None, method: str = "exact", checkpoint_every: int = 5,
             fixed=None, identifiability=True, per_direction="auto", align: bool = True,
             **options) -> IdentificationResult:
    """Identify friction-law parameters from measured motion and friction force.

    Parameters
    ----------
    data : Dataset or path
        Measurement (``t, v, F`` and, as the law needs, ``a, load, x``); SI units.
    model : str or FrictionModel
        Registry name (defaults as initial values) or an instance whose current values are
        the initial guess and the fixed values of parameters not in ``names``.
    algorithm : str or Algorithm, optional
        A name of :data:`identification.ALGORITHMS` (default :data:`DEFAULT_ALGORITHM`).
    names : list of str, optional
        Parameters to identify (default: every numeric parameter of the law that is set).
    bounds : dict, optional
        ``name -> (low, high)`` search box overriding :func:`default_bounds`.
    seed : int
        Random seed; the same seed gives the same result.
    max_evals : int, optional
        Budget of simulations (one per parameter set).
    validation : Dataset or path, optional
        Held-out data for ``validation_nrmse``.
    progress : None, True or callable(n, info)
        ``True`` prints progress lines on stderr.
    checkpoint : path, optional
        Evaluation log (JSON lines, :mod:`identification.checkpoint`): every evaluation is
        appended as it finishes, and a run given an existing log of the same data, model,
        parameters, algorithm and seed replays it, then continues live, giving the result of
        an uninterrupted run. A file that is not such a log is refused, never executed.
        Algorithms that cannot resume (``least_squares``, ``static_ls``) refuse it.
    objective : None, "cosim", "cosim_native", Objective, or callable(model, data, names) -> Objective
        Default: the in-process numba objective. ``"cosim"``: every evaluation runs the law's
        FMU (:class:`identification.cosim.CoSimObjective`); ``"cosim_native"``: its native
        C FMU (the same cost, faster).
    executor : None, "auto", "inline", "processes", dask Client, or object
        Where population evaluations run (see :mod:`identification.executors`).
    method : {"exact", "euler"}
        Bristle update of the in-process objective.
    checkpoint_every : int
        ``os.fsync`` the checkpoint every this many logged records (each is flushed to the
        operating system at once, so an interrupt or a killed process loses nothing).
    fixed : dict, optional
        ``name -> value`` [parameter units] held fixed (set on the model and left out of the
        identified names): e.g. the static parameters of a steady-state map in the
        two-step method (:func:`identification.steady_state.identify_two_step`).
    identifiability : bool or "fast"
        Attach the identifiability report (:mod:`identification.identifiability`):
        parameters at a bound, degenerate combinations, domain-respecting intervals (profile
        likelihood where Gauss-Newton is not trustworthy) and excitation advice. ``"fast"``:
        Gauss-Newton intervals only (no profiles; the default for co-simulation
        objectives, whose evaluations are FMU runs). ``False``: none (``ci`` as before,
        Gauss-Newton from the final least-squares Jacobian).
    per_direction : "auto" or bool
        Steady-state maps only: a level per direction when the map covers both
        (:func:`identification.steady_state.prepare_static`).
    align : bool
        Advance a velocity that lags its position by its measured lag, in ``data`` and
        ``validation`` (:func:`friction.alignment.align_motion`); ``False``: the channels as
        given (a caller that aligned them already, as ``diagnose`` does).
    **options
        Algorithm options (e.g. ``pop_size``, ``max_iter``).

    Returns
    -------
    IdentificationResult
        With ``identifiability`` (a dict, see
        :func:`identification.identifiability.assess_identifiability`) and ``ci`` from it.

    Notes
    -----
    A steady-state map (:class:`friction.dataset.SteadyStateMap`: pairs v, F without time,
    one per constant-velocity plateau) is fitted through the law's steady-state curve
    (:class:`identification.steady_state.SteadyStateObjective`): only the static
    parameters are identified, per direction when the map covers both (see
    :func:`identification.steady_state.identify_static`).
    """
    t_start = time.perf_counter()
    if isinstance(data, (str, os.PathLike)):
        data = load_dataset(data)
    if isinstance(validation, (str, os.PathLike)):
        validation = load_dataset(validation)
    from friction.dataset import SteadyStateMap
    is_map = isinstance(data, SteadyStateMap)
    notes = []
    if is_map:
        from .steady_state import check_map, prepare_static
        check_map(data)
        if objective is not None:
            raise ValueError("a steady-state map is fitted through the law's steady-state "
                             "curve: objective= does not apply")
        if validation is not None and not isinstance(validation, SteadyStateMap):
            raise ValueError("a steady-state map is validated on another map (v, F), not "
                             "on a time series")
        if validation is not None:
            check_map(validation, role="validation")
        model, names, fixed, notes = prepare_static(data, model, names, fixed,
                                                    per_direction)
    else:
        check_data(data)
        if isinstance(validation, SteadyStateMap):
            raise ValueError("a time series is validated on another time series, not on a "
                             "steady-state map")
        if validation is not None:
            check_data(validation, role="validation")
        # the motion channels on one time base, as diagnose has them (a velocity that lags
        # its position is advanced by its measured lag): both commands fit the same law
        if align:
            data, lag = align_motion(data)
            if lag:
                notes.append(data.notes[-1])
            if validation is not None:
                validation = align_motion(validation)[0]
    if isinstance(model, str):
        model = make_model(model)
    if not isinstance(model, FrictionModel):
        raise TypeError(f"model must be a registry name or a FrictionModel, got "
                        f"{type(model).__name__}")
    model, names = apply_fixed(model, names, fixed)
    alg = get_algorithm(algorithm if algorithm is not None else DEFAULT_ALGORITHM, **options)
    if checkpoint is not None and not getattr(alg, "checkpointable", True):
        # refused, not ignored: a user who asked for a checkpoint must not lose the run
        raise ValueError(f"algorithm {alg.name!r} cannot use a checkpoint: "
                         f"{alg.no_checkpoint or 'it cannot resume'}; run it without one")
    if max_evals is not None and not (isinstance(max_evals, (int, np.integer))
                                      and max_evals > 0):
        raise ValueError(f"max_evals = {max_evals!r}: the evaluation budget must be a "
                         f"positive integer")
    space = ParameterSpace.build(model, names, bounds, data)

    if is_map:
        from .steady_state import SteadyStateObjective
        obj = SteadyStateObjective(model, data, space.names)
    elif objective is None:
        obj = InProcessObjective(model, data, space.names, method=method)
    elif objective in ("cosim", "cosim_native"):
        from .cosim import CoSimObjective
        obj = CoSimObjective(model, data, space.names, native=objective == "cosim_native")
    elif isinstance(objective, Objective):
        obj = objective
    elif callable(objective):
        obj = objective(model, data, space.names)
    else:
        raise ValueError(f"objective = {objective!r}: use None, 'cosim', 'cosim_native', an "
                         f"Objective or a factory")
    exe = make_executor(executor, obj)
    problem = Problem(obj, space, exe, max_evals=max_evals)
    rng = np.random.default_rng(seed)
    def _initial(n):  # a direction twin left None starts from its "+" value
        v = getattr(model.params, n)
        if v is None and n.endswith("_neg"):
            v = getattr(model.params, n[:-4], None)
        if v is None:
            raise ValueError(f"{n} has no value to start from; set it on the model first")
        return float(v)

    x0 = np.array([_initial(n) for n in space.names], float)
    u0 = np.clip(space.to_unit(x0), 0.0, 1.0)
    prog = _as_progress(progress, f"identify {alg.name}")
    problem.progress = prog  # life signs between the algorithm's lines (long records)

    history: list[float] = []
    info: dict = {}
    log = None
    t_problem0 = problem._t0
    try:
        if checkpoint is not None:
            obj_kind = objective if isinstance(objective, (str, type(None))) \
                else type(objective).__name__
            fp = fingerprint(data, model, space.names, alg.name, seed,
                             extra=(obj_kind, method))
            log = problem.log = EvaluationLog(
                checkpoint, {"fingerprint": fp, "algorithm": alg.name, "model": model.name,
                             "names": space.names, "seed": seed, "data": data.name},
                sync_every=checkpoint_every)
            if prog is not None and log.n_logged:
                prog(0, f"resuming from {checkpoint}: replaying {log.n_logged} logged "
                        f"records")
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
        if log is not None:
            log.close()  # every finished evaluation is in the file, interrupted or not
        if exe is not None and not (executor is not None and hasattr(executor, "costs")):
            exe.close()
    resumed = log is not None and log.n_replayed > 0
    if log is not None and log.diverged is not None and prog is not None:
        prog(0, f"checkpoint: the run left the log at record {log.diverged + 1} of "
                f"{log.n_logged} (changed options?) and continued live")
    if prog is not None:
        prog.close()  # a bar made here ends with its last line

    if problem.best_u is None:
        raise RuntimeError(f"{alg.name}: no finite cost found (every simulated parameter set "
                           f"failed); check the data and bounds")
    u_best = problem.best_u
    x_best = space.to_physical(u_best)
    params = space.dict_of(x_best)
    try:
        fitted = _fitted_model(model, params)
    except Exception as exc:  # an inadmissible box edge: report it clearly
        raise ValueError(f"identified parameters are not admissible for {model.name}: {exc}") \
            from None
    # the reported cost is the objective's own prediction (the numba kernel, without the
    # input-range checks of simulate(), so a box edge the law rejects still gets a number)
    if type(obj) is InProcessObjective and np.isfinite(problem.best_cost):
        # the search scored the best point with this kernel already (every path of the
        # in-process objective computes the NRMSE of the same simulation): not run again
        fit = problem.best_cost
    else:
        F_fit = obj.predict(x_best[None, :])[0]
        fit = nrmse(data.F, F_fit)
    val = None
    if validation is not None and is_map:
        from .steady_state import SteadyStateObjective
        F_val = SteadyStateObjective(model, validation, space.names).predict(
            x_best[None, :])[0]
        val = nrmse(validation.F, F_val)
    elif validation is not None:
        # scored from the state consistent with the record's first samples: a held-out
        # record that starts in motion is not a start from rest
        F_val = InProcessObjective(model, validation, space.names, method=method,
                                   start="record").predict(x_best[None, :])[0]
        val = nrmse(validation.F, F_val)
    ci = None
    jac_of = None  # () -> the final residual Jacobian (N x D), for the intervals
    if info.get("jac") is not None and info.get("u") is not None:
        u_ci = np.asarray(info["u"], float)
        if np.array_equal(u_ci, u_best) or np.allclose(u_ci, u_best):
            # an algorithm may give it as a callable: computed only if an interval needs it
            # (an analytic N x D Jacobian of a long record is one more pass and N x D floats)
            jac_of = info["jac"] if callable(info["jac"]) else (lambda j=info["jac"]: j)
            if not identifiability:
                ci = confidence_intervals(space, u_ci, jac_of(), problem.best_cost, len(data))
    report = None
    deferred = None
    if identifiability:
        from .identifiability import assess_identifiability
        fast = identifiability == "fast" or (identifiability is True and objective in
                                              ("cosim", "cosim_native"))
        best_cost = problem.best_cost

        def deferred():
            # post-processing, not part of the search: an instrumented in-process objective
            # (a subclass counting simulations for a budget or a checkpoint test) is
            # replaced by the plain one it specialises, which gives the same forces
            target = obj
            if isinstance(obj, InProcessObjective) and type(obj) is not InProcessObjective:
                target = InProcessObjective(obj.model, obj.data, obj.names, method=obj.method,
                                            start=obj.start)
            rep, ci_ = assess_identifiability(target, space, u_best, best_cost, model=fitted,
                                              data=data, jac=None if jac_of is None
                                              else jac_of(), profile=not fast)
            rep["notes"] = list(notes) + rep["notes"]
            return {"identifiability": rep, "ci": ci_}

        if obj is not objective and hasattr(obj, "close"):
            # an objective opened here (FMU instances) is closed below: assess it now
            ready = deferred()
            report, ci, deferred = ready["identifiability"], ready["ci"], None
    if obj is not objective and hasattr(obj, "close"):
        obj.close()  # FMU instances we opened are freed now, not at interpreter exit
    # a replay moves the problem's clock back to the original run's (problem._t0)
    wall = time.perf_counter() - t_start + (t_problem0 - problem._t0)
    result = IdentificationResult(
        params=params, model=fitted, fit_nrmse=float(fit),
        validation_nrmse=None if val is None else float(val),
        cost_history=[float(c) for c in history], n_evals=int(problem.n_evals),
        trace=[[int(n), float(sec), float(c)] for n, sec, c in problem.trace],
        wall_time=float(wall), ci=ci, algorithm=alg.name, seed=seed,
        options=dict(alg.options), bounds=space.as_json(), resumed=resumed,
        message=str(info.get("message", "")), data=data.name,
        executor=getattr(exe, "name", type(exe).__name__), identifiability=report,
        fixed=dict(fixed or {}))
    if deferred is not None:
        # computed when first read (result.identifiability, result.ci, summary, JSON): a
        # caller that fits many laws and reads only the parameters (the diagnosis) does
        # not pay for the profiles
        result.defer(("identifiability", "ci"), deferred)
    return result


def apply_fixed(model: FrictionModel, names, fixed):
    """Set ``fixed`` (``name -> value``) on ``model`` and drop those names from the
    identified set (default: :func:`identification.space.default_names` of the model).

    Returns
    -------
    (FrictionModel, list of str or None)
    """
    if not fixed:
        return model, names
    from .space import default_names
    fixed = dict(fixed)
    layout = set(model.Params.numeric_names())
    unknown = [n for n in fixed if n not in layout]
    if unknown:
        raise KeyError(f"fixed parameter(s) {unknown} not in {model.name}; choose from "
                       f"{sorted(layout)}")
    try:
        model = model.with_values(**{n: float(v) for n, v in fixed.items()})
    except Exception as exc:
        raise ValueError(f"fixed values not admissible for {model.name}: {exc}") from None
    if names is None:
        names = default_names(model)
    names = [n for n in names if n not in fixed]
    if not names:
        raise ValueError(f"nothing left to identify: every parameter is fixed "
                         f"({sorted(fixed)})")
    return model, names
