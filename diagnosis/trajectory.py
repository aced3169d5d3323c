"""Trajectory-level diagnosis: the candidate effect is put into the plant's friction and the
plant is re-simulated against measured positions.

The friction-force level (:func:`diagnosis.diagnose`) needs friction recovered by inverse
dynamics. Many machines only give a trajectory: the XML-350 stage's tracking error, the
valve's lift. Here every candidate of :mod:`diagnosis.effects` becomes a change of the
*simulated plant*, as its record's ``plant_entry`` says (``twins``, ``law``, ``force``,
``mass``, ``delay``; :class:`diagnosis.effects.Effect`). For the built-in effects:

==================  ========================================================================
candidate           how it enters the plant model
==================  ========================================================================
``asymmetry``       the law's own direction twins ``Fc_neg, Fs_neg, sigma2_neg`` and offset
                    ``b`` (LuGre family)
``stribeck_shape``  free exponent ``alpha`` (Gaussian) or the other shape
                    (:meth:`diagnosis.effects.StribeckShape.modify_law`)
``presliding``      a static map replaced by LuGre (same hook as the force level)
``acceleration``    :class:`EffectLaw`: ``F + f_a tanh(a/a_s) exp(-|v|/v_c)``
``position``        :class:`EffectLaw`: ``F (1 + piecewise-linear map in x)``
``drift``           :class:`EffectLaw`: ``F (1 + k_drift (t - t0) / T)``, absolute time
``load``            :class:`EffectLaw`: ``F max(0, 1 + k_L (load - L0) / L0)`` (plants with a load)
``inertia``         the plant's moving mass ``M -> M + dm`` (a mass error of the model)
``delay``           a time shift between the measured and the simulated position channel
==================  ========================================================================

The :class:`EffectLaw` terms are the formulas of :mod:`diagnosis.effects` evaluated inside
the plant's friction law at every integration substep (numba kernel wrapped around the base
law's kernel), so the plant's closed loop reacts to them.

Procedure (mirrors :func:`diagnosis.diagnose`)
----------------------------------------------
1. Base fit: the base law's parameters that the trajectory can see (screened by their
   sensitivity, or ``fit_names``) are fitted by ``scipy.optimize.least_squares`` on the
   position residual of the fit record, each evaluation one plant simulation.
2. Held-out score: NRMSE of the position on the held-out record(s), normalised by the
   standard deviation of the measured *tracking error* (reference - measured position; the
   reference is the plant's own command, identical in model and machine), so the score is
   the NRMSE of the tracking error the model predicts.
3. Each candidate: base parameters and the effect's parameters re-identified jointly on the
   fit record (warm start: the base fit; bounded number of plant simulations), scored on
   the held-out record(s); greedy stacking, noise floor and verdict as the force level
   (:mod:`diagnosis.verdict`: ``MIN_EXCESS_CLOSED``, ``TIE``, ``NOISE_RATIO``).

The fits are ``least_squares`` (TRF, unit-cube box) with a finite-difference Jacobian that
is refreshed every third iteration and Broyden-updated in between, and stop after
``max_sims`` plant simulations (best point kept). The noise floor is the white part of the
held-out residual (second differences, as the force level) combined with a
*reproducibility* part: a closed loop with a quantised encoder does not repeat itself to the
nanometre, and what two runs of the base model with parameters 1e-4 apart differ by is
noise no model can predict. Candidates whose held-out NRMSE is within :data:`TIE_FLOOR` of
the noise floor of the best one are tied with it (as are those within the force level's
``TIE`` of excess closed); the simpler of tied candidates is named and the others are listed
in ``verdict["tied_with"]`` (an acceleration term can mimic a mass error, not the reverse).

Cost (``benchmarks/bench_diagnosis_trajectory.py``, XML-350, 0.2 s fit + 0.34 s held-out
at 10 kHz, every candidate): about 100-150 plant simulations, 20-45 s on a shared 2-core
machine; the law-parameter candidates run on the plant's compiled kernel (milliseconds per
simulation), the :class:`EffectLaw` ones on the generic stepper (about 0.5 s each).
Attribution (``--sweep``: clean, asymmetry, frictional lag, mass error, encoder lag at two
strengths and two noise seeds, a slower current loop outside the library): 19 of 20 right;
the miss, a half-strength frictional lag, is named ``inertia`` with ``acceleration`` listed
in ``tied_with``.

Engines
-------
``engine="plant"`` (default) runs :meth:`plants.base.Plant.simulate` (``method="fast"``,
the plant's compiled kernel when it has one); ``engine="fmu"`` runs the plant FMU (external
friction) and the friction-law FMU through :class:`fmus.master.Master`, connected as
:func:`fmus.plant_fmus.plant_connections`. Both solve the same equations - the plant's
states with Heun's method and the law's stable bristle update - and differ only by the
coupling of the co-simulation (plant and friction exchange values at communication points;
the difference shrinks with ``fmu_step``). The FMU engine expresses every candidate:
``asymmetry``, ``stribeck_shape``, ``presliding`` and ``inertia`` are parameters of the
friction FMU or of the plant FMU, ``delay`` shifts the output, and the force effects of
:class:`EffectLaw` (``acceleration``, ``load``, ``position``, ``drift``) run in the
``friction_effects`` FMU block between the law and the plant (the same
:mod:`friction.extensions` formula, fed by the plant FMU's ``v``, ``a``, ``x`` and load).
"""
from __future__ import annotations

import dataclasses
import math
import time
from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares

from friction import FrictionModel, make_model
from friction.dataset import Dataset
from friction.progress import status_lines

from .report import DiagnosisReport, report_sections
from .verdict import MIN_EXCESS_CLOSED, decide, noise_floor, rank
# the records of the effects: how each enters a plant, what the FMU engine can express
from .effects import (CANDIDATES, EFFECT_NAMES, EFFECTS, FMU_EFFECTS, FORCE_EFFECTS,  # noqa: F401
                      make_context)
from .regions import band_splits, frequency_split, regime_split
# the parts of the trajectory level, re-exported here (the public names of this module)
from .effect_law import EffectLaw, _LEVELS  # noqa: F401
from .records import (TrajectoryRecord, load_record, parse_experiment,  # noqa: F401
                      record_from_result)
from .trajectory_report import trajectory_figures, write_trajectory_html  # noqa: F401
# the plant runs (engines), re-exported: their public names were this module's
from .engines import (REFERENCE_OUTPUTS, TrajectoryModel, _make_engine,  # noqa: F401
                      _options_for, simulate_record)

__all__ = ["TrajectoryRecord", "record_from_result", "load_record", "parse_experiment",
           "EffectLaw", "simulate_record", "trajectory_figures", "write_trajectory_html",
           "diagnose_trajectory", "FORCE_EFFECTS", "FMU_EFFECTS", "REFERENCE_OUTPUTS",
           "MASS_PARAMETERS", "TrajectoryModel", "TrajectoryDiagnosis", "BASE_NAMES"]

#: parameters of each law that the trajectory level screens for its base re-fit (a
#: "standard" configuration: symmetric, Gaussian alpha = 2, no offset). The force level's
#: base is identify's default law instead (:func:`diagnosis.core.base_free_names`)
BASE_NAMES = {
    "lugre": ["sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs"],
    "stribeck": ["sigma2", "Fc", "Fs", "vs"],
}

#: residual [-] (in units of the record's scale) of a trial point whose simulation fails
FAILED_RESIDUAL = 1e3

#: plant parameters that are the moving mass (``inertia`` candidate), in order of preference
MASS_PARAMETERS = ("M", "m", "mass")
#: candidates whose held-out NRMSE is within this fraction of the noise floor of the best
#: one are tied with it (the simpler one is named), besides the force level's ``TIE``
TIE_FLOOR = 0.05
#: direction twins the ``asymmetry`` candidate frees (with the offset ``b``)
ASYMMETRY_NAMES = ("b", "Fc_neg", "Fs_neg", "sigma2_neg")


# -- model setups: base + candidate effects ---------------------------------------------------
@dataclass
class _P:
    """One free coordinate: where it goes, its box and scaling."""
    name: str
    target: str      # law | extra | mass | delay
    lo: float
    hi: float
    log: bool
    x0: float
    effect: str = ""
    wide: bool = False

    def to_phys(self, u):
        if self.log:
            return float(math.exp(math.log(self.lo) + u * (math.log(self.hi) - math.log(self.lo))))
        return float(self.lo + u * (self.hi - self.lo))

    def to_unit(self, x):
        if self.log:
            return (math.log(x) - math.log(self.lo)) / (math.log(self.hi) - math.log(self.lo))
        return (x - self.lo) / (self.hi - self.lo)


def _law_coordinate(law, name, ctx, spread):
    info = {i.name: i for i in law.Params.info()}[name]
    x0 = getattr(law.params, name)
    if x0 is None:
        x0 = getattr(law.params, name[:-4]) if name.endswith("_neg") else info.default
    x0 = float(x0)
    if name == "b" or info.lower < 0 or x0 <= 0:
        half = max(abs(x0), 0.5 * ctx.sF)
        lo, hi, log = x0 - half, x0 + half, False
        if math.isfinite(info.lower):
            lo = max(lo, info.lower + (1e-9 if info.lower_open else 0.0))
        if math.isfinite(info.upper):
            hi = min(hi, info.upper)
    else:
        lo, hi, log = x0 / spread, x0 * spread, True
        if math.isfinite(info.lower):
            lo = max(lo, info.lower * (1 + 1e-9) + (1e-300 if info.lower_open else 0.0))
        if math.isfinite(info.upper):
            hi = min(hi, info.upper)
    if not hi > lo:
        hi = lo * (1 + 1e-6) + 1e-12
    return _P(name, "law", lo, hi, log, min(max(x0, lo), hi))


def _wide_coordinate(law, name, data):
    """A parameter a candidate adds without a fitted start (``alpha``; ``sigma0, sigma1`` of
    ``presliding``): the identification's default box for the data, not a spread."""
    from identification.space import default_bounds
    info = {i.name: i for i in law.Params.info()}[name]
    lo, hi = default_bounds(law, [name], data=data)[name]
    log = bool(info.log) and lo > 0
    x0 = getattr(law.params, name)
    x0 = float(info.default if x0 is None else x0)
    return _P(name, "law", lo, hi, log, min(max(x0, lo), hi), wide=True)


@dataclass
class _Setup:
    """A model configuration: law (with its free names), force effects, mass, delay."""
    law: FrictionModel
    coords: list
    effects: tuple = ()
    mass_name: str | None = None
    mass0: float = 0.0

    def unit0(self) -> np.ndarray:
        return np.array([np.clip(c.to_unit(c.x0), 0.0, 1.0) for c in self.coords])

    def values(self, u) -> dict:
        return {c.name: c.to_phys(ui) for c, ui in zip(self.coords, u)}

    def build(self, u, ctx):
        vals = self.values(u)
        law_vals = {c.name: vals[c.name] for c in self.coords if c.target == "law"}
        law = self.law.with_values(**law_vals) if law_vals else self.law
        force = {}
        for c in self.coords:
            if c.target == "extra":
                force.setdefault(c.effect, {})[c.name] = vals[c.name]
        # an effect at its neutral value is no effect: the plain law keeps the plant's
        # compiled kernel (same equations; the finite-difference columns of the effect's
        # shape parameters at zero level then cost no generic-stepper run)
        force = {k: p for k, p in force.items() if any(p[n] != 0.0 for n in _LEVELS[k])}
        if force:
            law = EffectLaw(law, force, ctx)
        pp = {c.name[len("plant."):]: vals[c.name] for c in self.coords
              if c.target == "plant"}
        if self.mass_name is not None:
            pp[self.mass_name] = self.mass0 + vals.get("dm", 0.0)
        return law, pp, vals.get("delay", 0.0), vals

    def describe(self, u, ctx) -> dict:
        law, pp, delay, vals = self.build(u, ctx)
        base = law.base if isinstance(law, EffectLaw) else law
        out = {"law": base.name, "effects": list(self.effects),
               "params": {c.name: vals[c.name] for c in self.coords},
               "shape": getattr(base.params, "shape", None)}
        if pp:
            out["plant_params"] = pp
        return out


@dataclass
class _Case:
    """A record with the window that is scored and the stop time that is simulated."""
    record: TrajectoryRecord
    mask: np.ndarray
    stop: float
    sd: float = 1.0
    ref: np.ndarray | None = None


class _Budget(Exception):
    pass


def _solve(fun, u0, *, max_sims: int, h: float = 0.03, refresh: int = 3):
    """Bounded least squares in the unit cube: scipy's TRF with a Jacobian from forward
    differences, refreshed every ``refresh`` iterations and Broyden-updated in between (one
    plant simulation per iteration instead of one per parameter). Stops after ``max_sims``
    evaluations of ``fun`` and returns the best point seen: ``(u, r, n_evals)``."""
    u0 = np.asarray(u0, float)
    best = {"c": math.inf, "u": u0.copy(), "r": None}
    count = [0]
    memo = {}

    def f(u):
        key = u.tobytes()
        if key in memo:
            return memo[key]
        if count[0] >= max_sims:
            raise _Budget
        count[0] += 1
        r = fun(u)
        c = float(r @ r)
        if c < best["c"]:
            best.update(c=c, u=u.copy(), r=r.copy())
        if len(memo) > 64:
            memo.clear()
        memo[key] = r
        return r

    state = {"J": None, "u": None, "r": None, "calls": 0}

    def jac(u):
        r = f(u)
        st = state
        if st["J"] is None or st["calls"] % refresh == 0:
            J = np.empty((r.size, u.size))
            for j in range(u.size):
                du = h if u[j] + h <= 1.0 else -h
                up = u.copy()
                up[j] += du
                J[:, j] = (f(up) - r) / du
        else:
            J = st["J"]
            s = u - st["u"]
            ss = float(s @ s)
            if ss > 0:
                J = J + np.outer((r - st["r"]) - J @ s, s) / ss
        st.update(J=J, u=u.copy(), r=r, calls=st["calls"] + 1)
        return J

    if u0.size == 0:
        f(u0)
        return best["u"], best["r"], count[0]
    try:
        least_squares(f, u0, jac=jac, bounds=(0.0, 1.0), method="trf", x_scale=1.0,
                      xtol=1e-4, ftol=1e-4, gtol=1e-8, max_nfev=10 * max_sims)
    except _Budget:
        pass
    if best["r"] is None:  # budget smaller than one evaluation
        best["r"] = fun(u0)
    return best["u"], best["r"], count[0]


# -- the diagnosis ----------------------------------------------------------------------------
def _start_law(model, plant) -> FrictionModel:
    """The base law, warm-started from the plant's own friction where the names agree."""
    if isinstance(model, FrictionModel):
        return model
    own = plant.friction if plant.friction is not None else plant.default_friction()
    if own.name == model:
        return own
    law = make_model(model)
    shared = {}
    fields_ = {f.name for f in dataclasses.fields(law.params)}
    for f in dataclasses.fields(own.params):
        if f.name in fields_ and getattr(own.params, f.name) is not None:
            shared[f.name] = getattr(own.params, f.name)
    try:
        return law.with_values(**shared)
    except (ValueError, TypeError):
        return law


def _pseudo_dataset(ts, out, name) -> Dataset:
    """Kinematics of a simulated run as a :class:`Dataset` (candidate boxes, regions)."""
    t = ts
    x, v = out["x"], out["v"]
    a = out["a"] if "a" in out else np.gradient(v, t)
    F = out["F"] if "F" in out else np.zeros_like(t)
    load = next((out[k] for k in ("load", "F_sigma", "F_N") if k in out), None)
    return Dataset(t=t, x=x, v=v, a=a, F=F, load=load, name=name)


def _kinematics(plant, law, record):
    """x, v, a, F (and load) of the base model on a record, on the record's samples."""
    p = plant._copy()
    p.friction = law
    res = p.simulate(record.t[-1], method="fast", **_options_for(plant, record.options))
    names = res.dtype.names
    keys = [k for k in ("x", "v", "a", "F", "load", "F_sigma", "F_N") if k in names]
    out = {k: np.interp(record.t, res["time"], res[k]) for k in keys}
    return _pseudo_dataset(record.t, out, record.name)


def diagnose_trajectory(measured, plant, model="lugre", validation=None, candidates=None, *,
                        engine: str = "plant", fit_names=None, fit_fraction: float = 0.7,
                        max_sims: int = 24, max_sims_base: int = 60, spread: float = 3.0,
                        greedy: bool = True, fmu_dir=None, fmu_step: float | None = None,
                        fit_plant=None, progress=None, executor=None) -> DiagnosisReport:
    """Locate and name the sim-to-real gap of a plant model from measured trajectories.

    Parameters
    ----------
    measured : TrajectoryRecord
        The fit record (measured position [m] and the experiment options behind it).
    plant : Plant or str
        The plant model (instance, or registry name of :data:`plants.PLANTS`); its own
        friction law is replaced by the base law and the candidates. With a friction
        feedforward (XML-350 ``compensation=True``) the controller's compensator is the
        record's ``compensator`` option, else the plant's default law - never the candidate.
    model : str or FrictionModel
        Base law (registry name: started from the plant's own law when the names agree, or
        from the plant law's shared values; or an instance whose values start the fit).
    validation : TrajectoryRecord or list, optional
        Held-out records (another amplitude, frequency or move). Default: the last
        ``1 - fit_fraction`` of ``measured`` (the model runs through the whole record).
    candidates : list of str, optional
        Effect names (default all of :data:`diagnosis.effects.EFFECT_NAMES`). With the FMU
        engine, a candidate it cannot express raises ``NotImplementedError`` when named
        here, and is listed under ``skipped`` when the default list is used.
    engine : {"plant", "fmu"}
        In-process plant simulation (default, fast) or plant FMU + friction FMU through
        :class:`fmus.master.Master` (same equations; see the module docstring).
    fit_names : list of str, optional
        Base parameters re-fitted on the trajectory. Default: those of
        :data:`BASE_NAMES` whose +10 % change moves the fit record's
        residual by at least a fifth of the most visible one (at most four).
    max_sims : int
        Plant simulations per candidate fit (the budget that keeps the diagnosis
        practical); ``max_sims_base`` for the base fit.
    spread : float
        Base parameters are searched within ``[x / spread, x * spread]`` of their start.
    greedy : bool
        Stack further effects on the best one while each closes a further 3 % of the gap.
    fmu_dir : path, optional
        Folder with the built FMUs (engine ``"fmu"``; default: built once into a temporary
        folder). ``fmu_step`` [s]: communication step (default a quarter of
        :func:`fmus.plant_fmus.coupling_step`).
    fit_plant : dict, optional
        Plant parameters re-fitted with the base law and with every candidate, ``name ->
        (low, high)`` or ``(low, high, log)``, started from the plant's value (coordinates
        ``plant.<name>`` in the report): what an identification fitted together with the
        law, which would otherwise stay at values that compensated for the missing effect.
        The ``inertia`` candidate is skipped when the mass is among them.
    progress : None, bool, tqdm or callable(n, info)
        As :mod:`friction.progress` says: stage lines as status (``n`` = 0), one unit per
        plant simulation; ``True``: lines and a simulation bar on stderr.
    executor : None or dask.distributed.Client
        Where the candidates' fits run: here (default), or one task per candidate on a dask
        cluster, the plant, the records and the FMU files shipped to each worker once
        (:func:`diagnosis.cluster.trajectory_fits`); the report is the same but for its
        timings. The base fit, the held-out scores and the greedy stacking stay here.
    fit_fraction : float
        Share of ``measured`` fitted when no validation is given.
    max_sims_base : int
        Plant simulations of the base fit.
    fmu_step : float, optional
        Communication step [s] of the FMU engine (see ``fmu_dir``).

    Returns
    -------
    DiagnosisReport
        The contract's ``baseline`` (metric: NRMSE of the tracking error on the position
        signal), ``where``, ``effects``, ``verdict``, plus ``level: "trajectory"``,
        ``plant``, ``engine``, ``noise_floor`` (and its ``noise_floor_parts``: white,
        reproducibility), ``greedy``, ``where_bands``, ``where_frequency``,
        ``effect_details`` (fitted values, simulations and seconds per candidate), ``base``
        (fitted names and values, screening sensitivities), ``skipped``, ``timing``
        (``seconds``, ``simulations``). ``verdict`` may carry ``runner_up`` and
        ``tied_with`` (candidates the held-out data cannot tell from the named one).

    Examples
    --------
    >>> from plants.xml350 import XML350                                  # doctest: +SKIP
    >>> from diagnosis.trajectory import TrajectoryRecord, diagnose_trajectory
    >>> opts = dict(distance=1e-4, compensation=True)      # the move that was measured
    >>> fit = TrajectoryRecord(t, x_measured, opts, name="100um")         # doctest: +SKIP
    >>> rep = diagnose_trajectory(fit, XML350(), "lugre", validation=held_out)  # doctest: +SKIP
    >>> rep["verdict"]["cause"], rep["level"]                             # doctest: +SKIP
    ('inertia', 'trajectory')
    """
    return TrajectoryDiagnosis(
        measured, plant, model, validation, candidates, engine=engine, fit_names=fit_names,
        fit_fraction=fit_fraction, max_sims=max_sims, max_sims_base=max_sims_base,
        spread=spread, greedy=greedy, fmu_dir=fmu_dir, fmu_step=fmu_step, fit_plant=fit_plant,
        progress=progress, executor=executor).run()


class TrajectoryDiagnosis:
    """One trajectory-level diagnosis, step by step (:func:`diagnose_trajectory` runs it and
    documents the parameters, which are the same).

    The steps, each a method, in the order :meth:`run` calls them: :meth:`fit_base` (screen
    and fit the base law's visible parameters), :meth:`locate` (noise floor and where the
    held-out gap lies), :meth:`try_candidate` for each candidate (fit base + effect on the
    fit record, score held out), :meth:`stack` (greedy stacking), :meth:`decide` (the
    verdict, :func:`diagnosis.verdict.decide`) and :meth:`report`. Their results are kept as
    attributes (``base_setup``, ``u_base``, ``before``, ``floor``, ``effects``,
    ``fitted``, ...); a fit or a score is one call of :meth:`fit` or :meth:`score`.
    """

    def __init__(self, measured, plant, model="lugre", validation=None, candidates=None, *,
                 engine: str = "plant", fit_names=None, fit_fraction: float = 0.7,
                 max_sims: int = 24, max_sims_base: int = 60, spread: float = 3.0,
                 greedy: bool = True, fmu_dir=None, fmu_step: float | None = None,
                 fit_plant=None, progress=None, executor=None):
        import plants as _plants
        from friction.progress import as_progress

        self.t_start = time.perf_counter()
        if isinstance(plant, str):
            plant = _plants.make_plant(plant)
        if plant.external_friction:
            raise ValueError("plant must carry its friction law (external_friction=False)")
        if not isinstance(measured, TrajectoryRecord):
            raise TypeError(f"measured must be a TrajectoryRecord, got "
                            f"{type(measured).__name__}")
        sig = measured.signal or plant.main_output
        if sig not in plant.all_output_names:
            raise ValueError(f"plant {plant.name} has no output {sig!r}; outputs: "
                             f"{list(plant.all_output_names)}")
        unit = (getattr(plant, "signals", {}) or {}).get(sig, ("m",))[0]
        if unit != "m" and not getattr(plant, "any_signal", False):
            raise ValueError(f"plant {plant.name}: the compared output {sig!r} is in {unit!r}, "
                             f"not a position; a force measurement is diagnosed at the "
                             f"friction-force level (diagnosis.diagnose)")
        self.say = status_lines(progress)
        counter = as_progress(progress, "diagnose-trajectory", unit="sim", interval=2.0)
        explicit = candidates is not None
        self.names = list(candidates) if explicit else list(EFFECT_NAMES)
        unknown = [n for n in self.names if n not in CANDIDATES]
        if unknown:
            raise ValueError(f"unknown candidate effect(s) {unknown}; choose from "
                             f"{list(EFFECT_NAMES)}")
        if not 0.2 <= fit_fraction < 1.0:
            raise ValueError(f"fit_fraction = {fit_fraction!r} is out of bounds: must be in "
                             f"[0.2, 1)")
        if engine == "fmu" and explicit:
            for n in self.names:
                if n not in FMU_EFFECTS:
                    raise NotImplementedError(
                        f"candidate {n!r}: engine='fmu' cannot express it - the friction FMU "
                        f"has no parameters for it (it needs EffectLaw inside the plant); use "
                        f"engine='plant'")
        self.plant, self.measured, self.engine = plant, measured, engine
        self.fit_names, self.fit_plant, self.spread = fit_names, fit_plant, spread
        self.max_sims, self.max_sims_base, self.greedy = max_sims, max_sims_base, greedy
        self.executor = executor
        self.eng = _make_engine(engine, plant, fmu_dir, fmu_step)
        self.tm = TrajectoryModel(plant, self.eng, counter)
        self.law0 = _start_law(model, plant)
        self._cases(measured, validation, fit_fraction)
        self.mass_name = getattr(plant, "mass_parameter", None) or \
            next((n for n in MASS_PARAMETERS if n in plant.parameter_names), None)

    def __getstate__(self):
        # what a cluster worker gets with :meth:`fit_one`: everything but the client
        state = dict(self.__dict__)
        state["executor"] = None
        return state

    def _cases(self, measured, validation, fit_fraction):
        """Fit and held-out windows, their normalisation and the fit record's scales."""
        if validation is None:
            rec = measured
            t_split = rec.t[0] + fit_fraction * (rec.t[-1] - rec.t[0])
            self.fit_case = _Case(rec, rec.t <= t_split, float(rec.t[rec.t <= t_split][-1]))
            self.val_cases = [_Case(rec, rec.t > t_split, float(rec.t[-1]))]
        else:
            vals = validation if isinstance(validation, (list, tuple)) else [validation]
            for v in vals:
                if not isinstance(v, TrajectoryRecord):
                    raise TypeError(f"validation records must be TrajectoryRecord, got "
                                    f"{type(v).__name__}")
            self.fit_case = _Case(measured, np.ones(measured.t.size, bool),
                                  float(measured.t[-1]))
            self.val_cases = [_Case(v, np.ones(v.t.size, bool), float(v.t[-1])) for v in vals]

        # normalisation: std of the measured tracking error (reference from the plant's
        # command)
        self.say(f"[diagnose-trajectory] {self.plant.name}: base {self.law0.name}, engine "
                 f"{self.engine}")
        for c in [self.fit_case] + self.val_cases:
            _, ref = self.tm._output(self.law0, {}, c.record, c.stop)
            c.ref = ref
            y = c.record.y[c.mask]
            e = (ref[c.mask] - y) if ref is not None else y
            c.sd = float(np.std(e)) or 1.0

        fit_data = _kinematics(self.plant, self.law0, self.fit_case.record)
        sel = self.fit_case.mask
        ctx = make_context(Dataset(t=fit_data.t[sel], x=fit_data.x[sel], v=fit_data.v[sel],
                                   a=fit_data.a[sel], F=fit_data.F[sel],
                                   load=None if fit_data.load is None else fit_data.load[sel]))
        ctx.t0 = float(self.fit_case.record.t_start + fit_data.t[sel][0])
        self.fit_data, self.ctx = fit_data, ctx

    # -- evaluations ---------------------------------------------------------------------------
    def residual(self, setup, u, case) -> np.ndarray:
        """Position residual [-] (per the case's spread) of ``setup`` at unit point ``u``."""
        law, pp, delay, _ = setup.build(u, self.ctx)
        try:
            y, _ = self.tm._output(law, pp, case.record, case.stop, delay)
        except (ValueError, ArithmeticError) as exc:
            # a trial point the plant cannot run (diverged, or drove the press through its
            # workpiece): a residual far worse than any run, so the search steps back
            self.say(f"[diagnose-trajectory] trial point failed: {exc}")
            return np.full(int(case.mask.sum()), FAILED_RESIDUAL)
        return (case.record.y - y)[case.mask] / case.sd

    def score(self, setup, u) -> tuple[float, list]:
        """Held-out NRMSE [-] of ``setup`` at ``u`` (pooled over the held-out records,
        normalised by the measured tracking error's spread) and the residuals [m]; ``(inf,
        None)`` when a held-out run fails."""
        rs = []
        for c in self.val_cases:
            law, pp, delay, _ = setup.build(u, self.ctx)
            try:
                y, _ = self.tm._output(law, pp, c.record, c.stop, delay)
            except (ValueError, ArithmeticError) as exc:
                self.say(f"[diagnose-trajectory] held-out run failed: {exc}")
                return math.inf, None
            rs.append((c.record.y - y)[c.mask])
        num = np.concatenate(rs)
        den = np.concatenate([((c.ref[c.mask] - c.record.y[c.mask]) if c.ref is not None
                               else c.record.y[c.mask]) for c in self.val_cases])
        return float(np.sqrt(np.mean(num ** 2)) / (np.std(den) or 1.0)), rs

    def fit(self, setup, u0, budget: int):
        """Least squares of ``setup`` on the fit record from ``u0`` within ``budget``
        simulations: ``(u, RMS residual [-], simulations)``."""
        u, r, n = _solve(lambda u: self.residual(setup, u, self.fit_case), u0,
                         max_sims=budget)
        return u, float(np.sqrt(np.mean(r ** 2))), n

    def plant_coords(self) -> list:
        """Fresh coordinates of the plant parameters fitted with every setup."""
        out = []
        for n, box in (self.fit_plant or {}).items():
            lo, hi = float(box[0]), float(box[1])
            log = bool(box[2]) if len(box) > 2 and box[2] is not None else \
                bool(lo > 0 and hi / lo > 20)
            x0 = float(getattr(self.plant.params, n))
            out.append(_P(f"plant.{n}", "plant", lo, hi, log, min(max(x0, lo), hi)))
        return out

    # -- 1. base fit: the parameters the trajectory sees ------------------------------------
    def fit_base(self) -> None:
        """Screen the base law's parameters (unless ``fit_names`` were given), fit them on
        the fit record and score the base held out (``before``)."""
        law0, ctx, spread, say = self.law0, self.ctx, self.spread, self.say
        base_all = BASE_NAMES.get(law0.name) or [
            n for n in law0.free_names() if not n.endswith("_neg") and n not in ("alpha", "b")]
        fit_names = self.fit_names
        if fit_names is None:
            say("[diagnose-trajectory] screening base parameters")
            full = _Setup(law0, [_law_coordinate(law0, n, ctx, spread) for n in base_all])
            u_ref = full.unit0()
            r0 = self.residual(full, u_ref, self.fit_case)
            sens = {}
            for j, c in enumerate(full.coords):
                u = u_ref.copy()
                step = c.to_unit(c.x0 * 1.1) if c.log else c.to_unit(c.x0 + 0.1 * (c.hi - c.lo))
                u[j] = np.clip(step, 0.0, 1.0)
                sens[c.name] = float(np.sqrt(np.mean(
                    (self.residual(full, u, self.fit_case) - r0) ** 2)))
            top = max(sens.values()) or 1.0
            fit_names = sorted([n for n in base_all if sens[n] >= 0.2 * top],
                               key=lambda n: -sens[n])[:4]
        else:
            sens = None
            bad = [n for n in fit_names if n not in law0.Params.numeric_names()]
            if bad:
                raise ValueError(f"fit_names {bad} are not parameters of {law0.name}")
        self.fit_names, self.sens = list(fit_names), sens

        unknown = [n for n in (self.fit_plant or {}) if n not in self.plant.parameter_names]
        if unknown:
            raise ValueError(f"fit_plant {unknown} are not parameters of plant "
                             f"{self.plant.name}")
        say(f"[diagnose-trajectory] base fit of "
            f"{self.fit_names + [c.name for c in self.plant_coords()]}")
        base_setup = _Setup(law0, [_law_coordinate(law0, n, ctx, spread)
                                   for n in self.fit_names] + self.plant_coords())
        u_base, self.base_fit, _ = self.fit(base_setup, base_setup.unit0(), self.max_sims_base)
        self.base_law, self.base_pp, _, self.base_vals = base_setup.build(u_base, ctx)
        self.before, self.r_val = self.score(base_setup, u_base)
        if self.r_val is None:
            raise ValueError("the fitted base model cannot run the held-out record(s) (see "
                             "the message above); check the records' experiment options")
        self.base_setup, self.u_base = base_setup, u_base
        # every candidate starts from the fitted base
        self.base_start = {c.name: c.to_phys(x) for c, x in zip(base_setup.coords, u_base)}

    # -- 2. where: noise floor and the held-out residual by regime, band, frequency ---------
    def locate(self) -> None:
        """Noise floor (white + reproducibility) and where the base's held-out residual
        lies (``where``, ``bands``, ``freq``)."""
        plant, val_cases = self.plant, self.val_cases
        kin_plant = plant.with_params(**self.base_pp) if self.base_pp else plant
        self.val_data = [_kinematics(kin_plant, self.base_law, c.record) for c in val_cases]
        parts = []
        for c, d, r in zip(val_cases, self.val_data, self.r_val):
            m = c.mask
            e = (c.ref[m] - c.record.y[m]) if c.ref is not None else c.record.y[m]
            parts.append((Dataset(t=d.t[m], x=d.x[m], v=d.v[m], a=d.a[m], F=e, name=d.name),
                          r))
        if len(parts) == 1:
            val_cat, r_cat = parts[0]
        else:
            cat = lambda k: np.concatenate([getattr(p[0], k) for p in parts])  # noqa: E731
            n_all = sum(p[0].t.size for p in parts)
            val_cat = Dataset(t=np.arange(n_all) * self.measured.dt, x=cat("x"), v=cat("v"),
                              a=cat("a"), F=cat("F"), name="held-out")
            r_cat = np.concatenate([p[1] for p in parts])
        self.white = float(np.mean([noise_floor(d, r) * np.std(d.F) for d, r in parts])
                           / (np.std(np.concatenate([d.F for d, _ in parts])) or 1.0))
        # reproducibility floor: a closed loop with a quantised encoder (or any switching)
        # does not repeat itself to the nanometre - a 1e-4 relative change of the base
        # parameters re-rolls its quantisation sequence. What two such runs differ by, no
        # smooth model can predict; it counts as noise next to the white measurement noise.
        u_base = self.u_base
        u_p = np.clip(u_base + 1e-4 * np.where(u_base < 0.5, 1.0, -1.0), 0.0, 1.0)
        _, r_pert = self.score(self.base_setup, u_p)
        den = np.std(np.concatenate([d.F for d, _ in parts])) or 1.0
        self.repro = 0.0 if r_pert is None else float(
            np.sqrt(np.mean(np.concatenate([a - b for a, b in zip(self.r_val, r_pert)]) ** 2))
            / den)
        self.floor = float(np.hypot(self.white, self.repro))
        self.where = regime_split(val_cat, r_cat)
        self.bands = band_splits(val_cat, r_cat)
        self.freq = frequency_split(parts[0][0], parts[0][1])

    # -- 3. which: each candidate re-identified on the fit record, scored held out ----------
    def setups_for(self, effs, law, base_coords_vals) -> list:
        """Model setups (variants) with the effects ``effs`` on top of ``law``, each
        coordinate started from ``base_coords_vals`` where it has a value."""
        ctx, spread, plant, fit_names = self.ctx, self.spread, self.plant, self.fit_names
        variants = [(law, list(fit_names))]
        for name in effs:
            cand = CANDIDATES[name]
            if cand.stage == "modify_law":
                new = []
                for lw, nm in variants:
                    for lv, nv in cand.modify_law(lw, nm, ctx):
                        if getattr(lv.params, "shape", None) == "lorentzian" and "alpha" in nv:
                            lv = lv.with_values(shape="gaussian")
                        new.append((lv, [n for n in nv if n in lv.Params.numeric_names()]))
                variants = new
        out = []
        for lw, nm in variants:
            coords = [_law_coordinate(lw, n, ctx, spread) if n in base_coords_vals
                      or n in fit_names or n in ASYMMETRY_NAMES
                      else _wide_coordinate(lw, n, self.fit_data) for n in dict.fromkeys(nm)]
            coords += self.plant_coords()
            extra_mass = None
            for name in effs:
                entry = EFFECTS[name].plant_entry  # how the effect enters the plant
                if entry == "twins":
                    if not all(hasattr(lw.params, n) for n in ASYMMETRY_NAMES):
                        raise _NotApplicable(f"{lw.name} has no direction twins")
                    for n in ASYMMETRY_NAMES:
                        if all(c.name != n for c in coords):
                            coords.append(_law_coordinate(lw, n, ctx, spread))
                elif entry == "force":
                    for ex in CANDIDATES[name].trajectory_extras(ctx):
                        coords.append(_P(ex.name, "extra", ex.lo, ex.hi, False, ex.x0, name))
                elif entry == "mass":
                    mass_name = self.mass_name
                    if mass_name is None:
                        raise _NotApplicable(f"plant {plant.name} has no mass parameter "
                                             f"{MASS_PARAMETERS}")
                    if mass_name in (self.fit_plant or {}):
                        raise _NotApplicable(f"the mass {mass_name} is fitted with the base "
                                             f"(fit_plant)")
                    M0 = float(getattr(plant.params, mass_name))
                    coords.append(_P("dm", "mass", -0.5 * M0, 0.5 * M0, False, 0.0, name))
                    extra_mass = (mass_name, M0)
                elif entry == "delay":
                    d = 25 * min(self.fit_case.record.dt,
                                 *(c.record.dt for c in self.val_cases))
                    coords.append(_P("delay", "delay", -d, d, False, 0.0, name))
            for c in coords:  # warm start from the fitted base (and earlier effects)
                if c.name in base_coords_vals:
                    c.x0 = float(np.clip(base_coords_vals[c.name], c.lo, c.hi))
            s = _Setup(lw, coords, tuple(effs))
            if extra_mass:
                s.mass_name, s.mass0 = extra_mass
            out.append(s)
        return out

    def applicable(self, name) -> tuple[bool, str]:
        """Whether candidate ``name`` can be tried here, and why not."""
        cand = CANDIDATES[name]
        ok, why = cand.applicable(self.base_law, self.fit_data, self.ctx)
        if not ok:
            return ok, why
        if "x" in EFFECTS[name].inputs and not self.ctx.x_hi - self.ctx.x_lo > 0:
            return False, "the fit record does not move"
        if self.engine == "fmu" and name not in FMU_EFFECTS:
            return False, ("engine='fmu': the friction FMU has no parameters for this effect "
                           "(it needs EffectLaw inside the plant; use engine='plant')")
        return True, ""

    def fit_effects(self, effs, law, start_vals, budget):
        """The best fit on the fit record of ``effs`` on top of ``law`` over its setups:
        ``(setup, u, RMS residual [-])``."""
        best = None
        for s in self.setups_for(effs, law, start_vals):
            u0 = s.unit0()
            # non-convex coordinates get a coarse grid first: a time shift, and decades-wide
            # parameters a candidate adds without a fitted start (bristle stiffness)
            for j, c in enumerate(s.coords):
                if c.name == "delay" or (c.wide and c.log):
                    costs = []
                    grid = np.linspace(0.0, 1.0, 11 if c.name == "delay" else 7)
                    for g in grid:
                        u = u0.copy()
                        u[j] = g
                        r = self.residual(s, u, self.fit_case)
                        costs.append(float(r @ r))
                    u0[j] = grid[int(np.argmin(costs))]
            u, cost, _ = self.fit(s, u0, budget)
            if best is None or cost < best[2]:
                best = (s, u, cost)
        return best

    def fit_one(self, name):
        """One candidate's fit and the simulations it ran: ``(fit or None, why not,
        simulations, seconds)`` (what a cluster worker runs, :mod:`diagnosis.cluster`)."""
        tm = self.tm
        sims0, secs0 = tm.sims, tm.sim_seconds
        try:
            out = self.fit_effects([name], self.base_law, self.base_start, self.max_sims)
        except _NotApplicable as exc:
            return None, str(exc), 0, 0.0
        return out, "", tm.sims - sims0, tm.sim_seconds - secs0

    def try_candidates(self) -> None:
        """Every candidate fitted (on the cluster behind ``executor`` when given) and scored
        held out (``effects``, ``fitted``, ``skipped``), ranked (``tied_names``)."""
        from .cluster import trajectory_fits  # on a cluster: every applicable one at once
        self.effects, self.skipped, self.fitted = [], {}, {}
        remote = trajectory_fits(self.executor,
                                 [n for n in self.names if self.applicable(n)[0]],
                                 self.fit_one, self.tm, self.eng)
        for k, name in enumerate(self.names, 1):
            ok, why = self.applicable(name)
            if not ok:
                self.skipped[name] = why
                continue
            self.say(f"[diagnose-trajectory] candidate {k}/{len(self.names)}: {name}")
            row = self.try_candidate(name, remote.get(name))
            if isinstance(row, str):
                self.skipped[name] = row
            else:
                self.effects.append(row)
        # near-ties go to the simpler effect; held-out scores closer than a twentieth of the
        # noise floor are a tie too: with a gap barely above the floor, excess fractions
        # differ by noise alone
        self.tied_names = rank(self.effects, self.floor, TIE_FLOOR)

    def try_candidate(self, name, remote=None):
        """Candidate ``name`` fitted (or its fit ``remote`` from a worker) and scored held
        out: its row of the report's ``effects``, or why it was skipped."""
        tm, before, floor = self.tm, self.before, self.floor
        sims0, secs0 = tm.sims, tm.sim_seconds
        out, why, n_sims, n_secs = remote if remote is not None else self.fit_one(name)
        if out is None:
            return why
        s, u, cost = out
        if remote is not None:  # the worker's simulations count as this run's
            tm.sims, tm.sim_seconds = sims0 + n_sims, secs0 + n_secs
        after, _ = self.score(s, u)
        cost_sims = {"simulations": tm.sims - sims0, "seconds": tm.sim_seconds - secs0}
        self.fitted[name] = (s, u)
        n_par = sum(1 for c in s.coords if c.name not in self.fit_names and c.target != "plant")
        return {"name": name, "validation_before": before, "validation_after": after,
                "gap_closed": (before - after) / before if before > 0 else 0.0,
                "excess_closed": (before - after) / max(before - floor, 1e-12),
                "n_params": n_par, "fit_before": self.base_fit, "fit_after": cost,
                "fitted": {**s.describe(u, self.ctx), **cost_sims}}

    # -- 4. greedy stacking ------------------------------------------------------------------
    def stack(self) -> None:
        """Stack further effects on the best one while each closes a further 3 % of the
        held-out gap (``sequence``, ``final_val``)."""
        effects = self.effects
        self.sequence = []
        self.final_val = self.before
        if not (self.greedy and effects and effects[0]["excess_closed"] >= MIN_EXCESS_CLOSED):
            return
        used = [effects[0]["name"]]
        cur_val = effects[0]["validation_after"]
        s_cur, u_cur = self.fitted[used[0]]
        self.sequence.append({"add": used[0], "validation": cur_val})
        for e in effects[1:3]:
            if e["gap_closed"] < 0.05:
                continue
            if CANDIDATES[e["name"]].stage == "modify_law" and any(
                    CANDIDATES[n].stage == "modify_law" for n in used):
                continue
            self.say(f"[diagnose-trajectory] greedy: {' + '.join(used)} + {e['name']}")
            start = s_cur.values(u_cur)
            try:
                s2, u2, _ = self.fit_effects(used + [e["name"]], s_cur.law, start,
                                             self.max_sims)
            except _NotApplicable:
                continue
            v2, _ = self.score(s2, u2)
            if v2 < cur_val * 0.97:  # keep only effects that close a further 3 %
                used.append(e["name"])
                s_cur, u_cur, cur_val = s2, u2, v2
                self.sequence.append({"add": e["name"], "validation": v2})
        self.final_val = cur_val

    # -- 5. verdict (the force level's rules) ------------------------------------------------
    def decide(self) -> dict:
        """The verdict (:func:`diagnosis.verdict.decide`), with ``tied_with`` where the
        held-out data cannot tell the named effect from others."""
        verdict = decide(self.effects, self.before, self.floor, noise_abs=1e-9)
        if verdict["cause"] not in ("none", "unexplained") and self.tied_names:
            verdict["tied_with"] = self.tied_names  # the held-out data cannot tell these apart
        return verdict

    def report(self, verdict: dict) -> DiagnosisReport:
        """The report of the steps run so far with ``verdict``."""
        tm, plant, fit_case, val_cases = self.tm, self.plant, self.fit_case, self.val_cases
        report = DiagnosisReport(
            level="trajectory",
            baseline={"model": self.law0.name, "metric": "nrmse", "fit": self.base_fit,
                      "validation": self.before,
                      "signal": fit_case.record.signal or plant.main_output,
                      "normalised_by": ("std of the measured tracking error "
                                        f"({tm.ref_name} - {plant.main_output})"
                                        if tm.ref_name else "std of the measured signal")},
            **report_sections(self.where, self.bands, self.freq, self.effects, verdict,
                              self.sequence, self.before, self.final_val, self.floor),
            plant=plant.name,
            engine=self.engine,
            noise_floor_parts={"white": self.white, "reproducibility": self.repro},
            effect_details={e["name"]: e["fitted"] for e in self.effects},
            base={"law": self.base_law.name, "fit_names": self.fit_names,
                  "params": self.base_vals, "sensitivity": self.sens},
            skipped=self.skipped,
            timing={"seconds": time.perf_counter() - self.t_start, "simulations": tm.sims,
                    "simulation_seconds": tm.sim_seconds,
                    "fit_samples": int(fit_case.mask.sum()),
                    "validation_samples": int(sum(c.mask.sum() for c in val_cases))},
        )
        # for plots; not serialised
        report._models = {"base": (self.base_setup, self.u_base), **self.fitted}
        report._data = {"fit": fit_case, "validation": val_cases, "ctx": self.ctx,
                        "plant": plant, "val_data": self.val_data}
        return report

    def run(self) -> DiagnosisReport:
        """All steps in order; the engine is closed before the report is made."""
        self.fit_base()
        self.locate()
        self.try_candidates()
        self.stack()
        verdict = self.decide()
        if hasattr(self.eng, "close"):
            self.eng.close()
        return self.report(verdict)


class _NotApplicable(Exception):
    pass


# -- report figures -----------------------------------------------------------------------------
