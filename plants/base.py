"""The plant contract (``PartialPlant``): a hybrid system of continuous states, the friction
law's own states and discrete controllers with zero-order hold.

A machine subclasses :class:`Plant` and fills in

=======================  ==================================================================
class attribute          meaning
=======================  ==================================================================
``name``                 registry name ("valve", "damping_rig", "forging_press", "xml350", ...)
``Params``               frozen parameter dataclass (``friction.base.param`` fields)
``main_output``          output compared in proofs (e.g. ``"x"``)
``data_rate``            output sample rate [Hz]
``default_experiment``   :class:`Experiment` (start, stop, step = 1/data_rate)
``state_names``          continuous plant states (without the friction law's states)
``state_scale``          typical magnitude of each state (absolute tolerances)
``output_names``         outputs; ``"F"`` (friction force [N]) is appended automatically
                         when the law is internal
``input_names``          external inputs besides ``F_friction`` (usually empty)
``discrete_names``       values held by the discrete part between samples (ZOH)
``control_rate``         sample rate of the discrete part [Hz] (``None``: none)
``max_substep``          largest internal step of the fast integrator [s]
``options``              plant-specific experiment options and their defaults
``signals``              name -> (unit, description) of inputs/outputs (FMU metadata)
=======================  ==================================================================

and the methods (``s`` continuous states, ``d`` held discrete values, ``u`` dict of
external inputs, ``F`` friction force [N] on the contact, opposing the sliding velocity):

* ``initial_state() -> s0`` and ``initial_discrete() -> d0``;
* ``derivatives(t, s, d, F, u) -> ds/dt``;
* ``contact(t, s, d, u) -> (x, v, load)``: sliding displacement [m], velocity [m/s] and
  normal load [N] (``load`` may be ``None``) seen by the friction law;
* ``contact_acceleration(t, s, ds, d, u) -> a`` [m/s^2] (default: ``ds`` of state ``"v"``);
* ``discrete_update(t, s, d, u) -> d_new`` at each sample instant ``start + k/control_rate``;
* ``output(t, s, d, F, u) -> dict`` of the outputs.

The base then provides :meth:`Plant.simulate` (``"fast"`` fixed-step, numpy/numba only;
``"reference"``: the monolithic ODE with ``scipy.integrate.solve_ivp`` between sample
instants) and :meth:`Plant.stepper` (the FMU-facing object, no scipy).

Fast integrator
---------------
Heun's method (second order) on the plant states; the friction law's states advance with
the law's own numba kernel (for LuGre the exact exponential bristle update, stable at any
step and stiffness), called over the substep with the velocity at both ends. The friction
force entering the derivatives is the kernel's output at the step ends, so the stiff
bristle never sees an explicit update. Discrete updates run eagerly when time reaches a
sample instant, so outputs at an instant show the controller output computed from it.
A law whose coefficients jump at |v| = vc (:func:`friction.regimes.regime_split`) is
stepped regime by regime: each substep holds one regime, a substep crossing vc is cut at
the crossing, and the motion slides along |v| = vc (Filippov) where both regimes push onto
it (:class:`PlantStepper`), as the reference integrator does with located events.
"""
from __future__ import annotations

import copy
import math
from dataclasses import dataclass, fields
from typing import Any, Callable, ClassVar

import numpy as np

from friction.base import FrictionModel, FrictionParams

__all__ = ["Experiment", "Plant", "PlantStepper", "FrictionStep", "FrictionComponent",
           "PlantParams", "structured"]

#: parameter dataclasses of plants use the same validated base as friction laws
PlantParams = FrictionParams


@dataclass(frozen=True)
class Experiment:
    """Default experiment of a plant (fmpy's ``DefaultExperiment``).

    Attributes
    ----------
    start, stop : float
        Start and stop time [s].
    step : float
        Output interval [s] (``1 / data_rate``).
    """
    start: float = 0.0
    stop: float = 1.0
    step: float = 1e-3

    def __post_init__(self):
        for name in ("start", "stop", "step"):
            if not math.isfinite(getattr(self, name)):
                raise ValueError(f"Experiment.{name} = {getattr(self, name)!r} is not finite")
        if not self.step > 0:
            raise ValueError(f"Experiment.step = {self.step!r} is out of bounds: must be > 0 [s]")
        if not self.stop > self.start:
            raise ValueError(f"Experiment.stop = {self.stop!r} must be > start = {self.start!r}")

    def times(self) -> np.ndarray:
        """Output instants start, start+step, ..., stop (stop included when on the grid)."""
        n = int(math.floor((self.stop - self.start) / self.step + 1e-9))
        return self.start + self.step * np.arange(n + 1)


def structured(columns: dict[str, np.ndarray]) -> np.ndarray:
    """Structured array (fmpy result layout) from ordered columns; ``time`` must come first."""
    names = list(columns)
    if names[0] != "time":
        raise ValueError(f"first column must be 'time', got {names[0]!r}")
    n = len(columns["time"])
    out = np.empty(n, dtype=[(k, "f8") for k in names])
    for k, col in columns.items():
        out[k] = col
    return out


class FrictionStep:
    """A friction law driven step by step through its numba kernel (no scipy).

    Parameters
    ----------
    law : FrictionModel
    method : {"exact", "euler"}
        Bristle update of the law's kernel (``exact`` is stable at any step).

    Notes
    -----
    The law's prescribed-motion kernel evaluated on a two-sample record ``[t, t+h]``
    advances the state over the step (velocity at both ends) and returns the force at both
    ends; a one-sample record gives the force at the current state.
    """

    def __init__(self, law: FrictionModel, method: str = "exact"):
        from friction.base import METHODS
        if method not in METHODS:
            raise ValueError(f"method must be one of {sorted(METHODS)}, got {method!r}")
        self.law = law
        self.method = METHODS[method]
        self.n_states = len(law.state_names)
        self.needs = law.extra_inputs
        self._t2 = np.zeros(2)
        self._empty = np.zeros(0)

    def _extra(self, key, values):
        return np.array(values) if key in self.needs else self._empty

    def force(self, state, x, v, a=0.0, load=None) -> float:
        """Friction force [N] at the given state and kinematics."""
        one = np.zeros(1)
        F, _ = self.law._kernel(one, np.array([v]), self._extra("a", [a]),
                                self._extra("load", [load if load is not None else 0.0]),
                                self._extra("x", [x]), self.law.theta, self.method,
                                np.asarray(state, dtype=np.float64))
        return float(F[0])

    def advance(self, state, h, k0, k1):
        """Advance the state over a step of length ``h`` [s].

        ``k0``, ``k1`` are ``(x, v, a, load)`` at the start and the end. Returns
        ``(new_state, force_at_end)``.
        """
        t = self._t2
        t[1] = h
        F, S = self.law._kernel(
            t, np.array([k0[1], k1[1]]), self._extra("a", [k0[2], k1[2]]),
            self._extra("load", [k0[3] or 0.0, k1[3] or 0.0]), self._extra("x", [k0[0], k1[0]]),
            self.law.theta, self.method, np.asarray(state, dtype=np.float64))
        return S[1].copy(), float(F[1])


class Plant:
    """Abstract plant; see the module docstring for what a subclass fills in.

    Parameters
    ----------
    friction : FrictionModel or str, optional
        Friction law (instance, or registry name with default parameters). ``None``:
        the plant's own seed law (:meth:`default_friction`).
    external_friction : bool
        The friction force is the input ``F_friction`` [N] (co-simulation with a separate
        friction FMU); the plant then has no friction states and outputs the kinematics.
    params : Params, optional
        Plant parameters (defaults: the seed's numbers).
    **param_overrides
        Individual parameter values, validated against their bounds.
    """

    name: ClassVar[str] = ""
    Params: ClassVar[type] = PlantParams
    main_output: ClassVar[str] = "x"
    data_rate: ClassVar[float] = 1000.0
    default_experiment: ClassVar[Experiment] = Experiment()
    state_names: ClassVar[tuple[str, ...]] = ()
    state_scale: ClassVar[tuple[float, ...] | None] = None
    output_names: ClassVar[tuple[str, ...]] = ()
    input_names: ClassVar[tuple[str, ...]] = ()
    discrete_names: ClassVar[tuple[str, ...]] = ()
    control_rate: ClassVar[float | None] = None
    max_substep: ClassVar[float] = 1e-4
    options: ClassVar[dict[str, Any]] = {}
    signals: ClassVar[dict[str, tuple[str, str]]] = {}

    def __init__(self, friction: FrictionModel | str | None = None, *,
                 external_friction: bool = False, params=None, **param_overrides):
        if params is None:
            params = self.Params(**param_overrides)
        elif param_overrides:
            params = params.replace(**param_overrides)
        if not isinstance(params, self.Params):
            raise TypeError(f"{self.name}: params must be {self.Params.__name__}, "
                            f"got {type(params).__name__}")
        self.params = params
        self.external_friction = bool(external_friction)
        if self.external_friction:
            if friction is not None:
                raise ValueError("external_friction=True takes the friction force as the input "
                                 "F_friction: do not pass a friction law as well")
            self.friction = None
        elif friction is None:
            self.friction = self.default_friction()
        elif isinstance(friction, str):
            from friction import make_model
            self.friction = make_model(friction)
        elif isinstance(friction, FrictionModel):
            self.friction = friction
        else:
            raise TypeError(f"friction must be a FrictionModel, a registry name or None, "
                            f"got {type(friction).__name__}")
        self.opts = dict(self.options)

    # -- to be filled in by each plant ------------------------------------------------------
    @classmethod
    def default_friction(cls) -> FrictionModel:  # pragma: no cover - abstract
        """The plant's own seed law with seed-like parameters."""
        raise NotImplementedError

    def initial_state(self) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError

    def initial_discrete(self) -> np.ndarray:
        return np.zeros(len(self.discrete_names))

    def derivatives(self, t, s, d, F, u) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError

    def contact(self, t, s, d, u) -> tuple[float, float, float | None]:  # pragma: no cover
        raise NotImplementedError

    def contact_acceleration(self, t, s, ds, d, u) -> float:
        return float(ds[self.state_names.index("v")])

    def discrete_update(self, t, s, d, u) -> np.ndarray:
        return d

    def output(self, t, s, d, F, u) -> dict[str, float]:  # pragma: no cover - abstract
        raise NotImplementedError

    # -- written once -------------------------------------------------------------------------
    def __repr__(self) -> str:
        law = "external" if self.external_friction else type(self.friction).__name__
        return f"{type(self).__name__}(friction={law}, params={self.params!r})"

    @property
    def all_input_names(self) -> tuple[str, ...]:
        """External inputs, with ``F_friction`` [N] first in external-friction mode."""
        return (("F_friction",) if self.external_friction else ()) + tuple(self.input_names)

    @property
    def all_output_names(self) -> tuple[str, ...]:
        """Outputs, with the friction force ``F`` [N] last when the law is internal."""
        return tuple(self.output_names) + (() if self.external_friction else ("F",))

    @property
    def parameter_names(self) -> tuple[str, ...]:
        return tuple(self.Params.numeric_names())

    def with_options(self, **options) -> "Plant":
        """A copy of this plant with experiment options changed (unknown names: TypeError)."""
        unknown = set(options) - set(self.options)
        if unknown:
            raise TypeError(f"{self.name}: unknown experiment option(s) {sorted(unknown)}; "
                            f"choose from {sorted(self.options)}")
        new = self._copy()
        new.opts = {**self.opts, **options}
        return new

    def with_params(self, **values) -> "Plant":
        """A copy with some plant parameters changed (validated)."""
        new = self._copy()
        new.params = self.params.replace(**values)
        return new

    def _copy(self) -> "Plant":
        # shallow copy without derived data: a subclass may cache objects built from
        # params/options in ``self._cache`` (dict), rebuilt on first use
        new = copy.copy(self)
        new._cache = {}
        return new

    @property
    def cache(self) -> dict:
        """Per-instance store for objects derived from params/options (cleared on copies)."""
        c = self.__dict__.get("_cache")
        if c is None:
            c = self._cache = {}
        return c

    def _experiment(self, stop_time, experiment_options) -> tuple[Experiment, dict]:
        exp_fields = {f.name for f in fields(Experiment)}
        exp_kw = {k: experiment_options.pop(k) for k in list(experiment_options)
                  if k in exp_fields}
        if stop_time is not None:
            exp_kw["stop"] = stop_time
        d = self.default_experiment
        exp = Experiment(**{**{f.name: getattr(d, f.name) for f in fields(Experiment)},
                            **exp_kw})
        return exp, experiment_options

    def stepper(self, *, substep: float | None = None, friction_method: str = "exact",
                **options) -> "PlantStepper":
        """The FMU-facing step-by-step object (numpy/numba only).

        Parameters
        ----------
        substep : float, optional
            Largest internal step [s] (default ``max_substep``).
        friction_method : {"exact", "euler"}
            Bristle update of the law.
        **options
            Experiment options (see ``options``).
        """
        plant = self.with_options(**options) if options else self
        return PlantStepper(plant, substep=substep, friction_method=friction_method)

    def simulate(self, stop_time: float | None = None, *, method: str = "fast",
                 rtol: float = 1e-9, progress: Callable | None = None,
                 inputs: Callable[[float], dict] | None = None, substep: float | None = None,
                 time_budget: float | None = None, **experiment_options) -> np.ndarray:
        """Simulate the default experiment (or a changed one).

        Parameters
        ----------
        stop_time : float, optional
            Stop time [s] (default: ``default_experiment.stop``).
        method : {"fast", "reference"}
            ``fast``: fixed-step stepper (Heun + the law's stable update).
            ``reference``: ``solve_ivp`` (Radau, tolerance ``rtol``) of plant + friction
            states between sample instants, discrete values held. A law whose coefficients
            jump at |v| = vc (``friction.reference.regime_split``) is integrated regime by
            regime with the crossings located as events, and along the switching surface
            as a Filippov sliding motion where both regimes push the velocity onto it.
        rtol : float
            Relative tolerance of the reference integrator.
        progress : callable, optional
            Called as ``progress(n, info)`` while output samples are produced.
        inputs : callable, optional
            ``inputs(t) -> dict`` of external input values (e.g. ``F_friction``), held over
            each output interval.
        substep : float, optional
            Internal step of the fast method [s] (default ``max_substep``).
        time_budget : float, optional
            Reference only: wall-clock budget [s]; ``TimeoutError`` once exceeded.
        **experiment_options
            ``start``/``step`` of :class:`Experiment`, and the plant's ``options``.

        Returns
        -------
        ndarray
            Structured array, ``time`` first, then ``all_output_names``.
        """
        exp, rest = self._experiment(stop_time, dict(experiment_options))
        plant = self.with_options(**rest) if rest else self
        if method == "fast":
            return plant._simulate_fast(exp, progress, inputs, substep)
        if method == "reference":
            return plant._simulate_reference(exp, rtol, progress, inputs, time_budget)
        raise ValueError(f"method must be 'fast' or 'reference', got {method!r}")

    # -- helpers shared by both integrators ------------------------------------------------------
    def _u(self, u: dict | None) -> dict:
        base = {n: 0.0 for n in self.all_input_names}
        if u:
            unknown = set(u) - set(base)
            if unknown:
                raise KeyError(f"{self.name}: unknown input(s) {sorted(unknown)}; inputs are "
                               f"{list(base)}")
            base.update({k: float(v) for k, v in u.items()})
        return base

    def _sample_period(self) -> float | None:
        return None if not self.control_rate else 1.0 / self.control_rate

    def _simulate_fast(self, exp: Experiment, progress, inputs, substep) -> np.ndarray:
        st = PlantStepper(self, substep=substep, start=exp.start)
        times = exp.times()
        cols = {n: np.empty(times.size) for n in self.all_output_names}
        for i, tk in enumerate(times):
            if i > 0:
                st.do_step(times[i - 1], tk - times[i - 1])
            if inputs is not None:
                st.set_inputs(inputs(tk))
            out = st.outputs()
            for n in cols:
                cols[n][i] = out[n]
            if progress is not None and i % 100 == 0:
                progress(min(100, times.size - i), f"t={tk:.4g} s")
        return structured({"time": times, **cols})

    def _simulate_reference(self, exp: Experiment, rtol, progress, inputs,
                            time_budget=None) -> np.ndarray:
        import time as _time

        from scipy.integrate import solve_ivp  # reference only: FMUs must not need scipy

        from friction.reference import regime_split

        if self.external_friction:
            raise ValueError("the reference integrator needs an internal friction law "
                             "(external_friction=False)")
        law = self.friction
        ns = len(self.state_names)
        nz = len(law.state_names)
        times = exp.times()
        Ts = self._sample_period()
        # breakpoints: sample instants of the discrete part and the output instants
        if Ts is not None:
            nsamp = int(math.floor((exp.stop - exp.start) / Ts + 1e-9))
            samples = exp.start + Ts * np.arange(nsamp + 1)
        else:
            samples = np.array([exp.start])
        eps = 1e-12 * max(1.0, abs(exp.stop))
        # segment ends: sample instants of the discrete part, the stop time, and the output
        # instants when inputs are given (they are held over each output interval)
        bps = np.union1d(samples, [times[-1]])
        if inputs is not None:
            bps = np.union1d(bps, times)
        bps = bps[np.concatenate(([True], np.diff(bps) > eps))]
        is_sample = np.zeros(bps.size, bool)
        is_sample[np.searchsorted(bps, samples - eps)] = True
        scale = np.ones(ns) if self.state_scale is None else np.asarray(self.state_scale, float)
        zscale = np.full(nz, getattr(law, "z_max", lambda: 1e-5)())
        atol = rtol * np.concatenate((scale, zscale)) * 10.0
        deadline = None if time_budget is None else _time.monotonic() + float(time_budget)

        # a law with a coefficient jump at |v| = vc: one smooth law per regime ("low",
        # "high"), and the Filippov sliding motion "slide" along |v| = vc
        split = regime_split(law)
        laws = {"smooth": law} if split is None else {"low": split.low, "high": split.high}

        def friction_force(t, y, d, u, lw, a_guess=0.0):
            x, v, load = self.contact(t, y[:ns], d, u)
            kw = {}
            if "x" in lw.extra_inputs:
                kw["x"] = x
            if "load" in lw.extra_inputs:
                kw["load"] = load
            if "a" in lw.extra_inputs:
                kw["a"] = a_guess
            return lw.force(y[ns:], v, **kw), v, kw

        def parts_of(t, y, d, u, lw):
            F, v, kw = friction_force(t, y, d, u, lw)
            ds = self.derivatives(t, y[:ns], d, F, u)
            if "a" in lw.extra_inputs:  # acceleration-dependent law: fixed point on a
                for _ in range(4):
                    a = self.contact_acceleration(t, y[:ns], ds, d, u)
                    F, v, kw = friction_force(t, y, d, u, lw, a)
                    ds = self.derivatives(t, y[:ns], d, F, u)
            dz = lw.derivatives(y[ns:], v, **kw)
            return F, ds, dz

        def sigma(t, y, d, u):
            """Distance |v| - vc from the switching surface [m/s]."""
            return abs(self.contact(t, y[:ns], d, u)[1]) - split.vc

        def dsigma(t, y, d, u, ds):
            """d|v|/dt under one regime's field [m/s^2]."""
            v = self.contact(t, y[:ns], d, u)[1]
            return math.copysign(1.0, v) * self.contact_acceleration(t, y[:ns], ds, d, u)

        def sliding_parts(t, y, d, u):
            Fl, dsl, dzl = parts_of(t, y, d, u, laws["low"])
            Fh, dsh, dzh = parts_of(t, y, d, u, laws["high"])
            gl, gh = dsigma(t, y, d, u, dsl), dsigma(t, y, d, u, dsh)
            # Filippov: the convex combination of both fields tangent to the surface
            al = min(1.0, max(0.0, gh / (gh - gl))) if gh != gl else 0.5
            return (al * Fl + (1 - al) * Fh, al * dsl + (1 - al) * dsh,
                    al * dzl + (1 - al) * dzh)

        def rhs_parts(t, y, d, u, mode):
            if deadline is not None and _time.monotonic() > deadline:
                raise TimeoutError(f"{self.name}: reference integrator of {law.name} exceeded "
                                   f"the time budget of {time_budget:g} s at t = {t:.6g} s")
            if mode == "slide":
                return sliding_parts(t, y, d, u)
            return parts_of(t, y, d, u, laws[mode])

        def rhs(t, y, d, u, mode):
            _, ds, dz = rhs_parts(t, y, d, u, mode)
            return np.concatenate((ds, dz))

        def classify(t, y, d, u, prev):
            """Regime at (t, y): by the side of the surface, or on it by where the two
            fields push (both towards it: sliding; otherwise the side they cross to)."""
            if split is None:
                return "smooth"
            sg = sigma(t, y, d, u)
            if prev == "slide" or abs(sg) <= 1e-9 * split.vc:
                gl = dsigma(t, y, d, u, parts_of(t, y, d, u, laws["low"])[1])
                gh = dsigma(t, y, d, u, parts_of(t, y, d, u, laws["high"])[1])
                if gl > 0 and gh < 0:
                    return "slide"
                if gl > 0 and gh >= 0:
                    return "high"
                if gl <= 0 and gh < 0:
                    return "low"
                # repulsive surface (both fields point away): stay on the present side
                return prev if prev in ("low", "high") else ("low" if sg < 0 else "high")
            return "low" if sg < 0 else "high"

        def segment(ta, tb, y, d, u, t_eval, mode):
            """Integrate [ta, tb] with d, u held; returns ([(tk, yk, mode)], y(tb), mode)."""
            out = []
            t = ta
            n_events = 0
            t_ev = np.concatenate((t_eval, [tb])) if (
                t_eval.size == 0 or abs(t_eval[-1] - tb) > eps) else t_eval
            forced = None
            while True:
                mode = forced or classify(t, y, d, u, mode)
                forced = None
                events = []
                if mode in ("low", "high"):
                    def cross(tq, yq, *_):
                        return sigma(tq, yq, d, u)
                    cross.terminal = True
                    cross.direction = 1.0 if mode == "low" else -1.0
                    events = [cross]
                elif mode == "slide":
                    def leave_low(tq, yq, *_):  # the low side stops pushing up: leave down
                        return dsigma(tq, yq, d, u, parts_of(tq, yq, d, u, laws["low"])[1])
                    leave_low.terminal = True
                    leave_low.direction = -1.0

                    def leave_high(tq, yq, *_):  # the high side stops pushing down: leave up
                        return dsigma(tq, yq, d, u, parts_of(tq, yq, d, u, laws["high"])[1])
                    leave_high.terminal = True
                    leave_high.direction = 1.0
                    events = [leave_low, leave_high]
                te = t_ev[t_ev > t + eps]
                sol = solve_ivp(rhs, (t, tb), y, method="Radau", rtol=rtol, atol=atol,
                                args=(d, u, mode), first_step=min(tb - t, 1e-7),
                                t_eval=te, events=events or None)
                if sol.status < 0:
                    raise RuntimeError(f"{self.name}: reference integrator failed at "
                                       f"t={t:.6g} s: {sol.message}")
                for k, tk in enumerate(sol.t):
                    if abs(tk - tb) > eps:
                        out.append((tk, sol.y[:, k], mode))
                if sol.status == 0:
                    return out, sol.y[:, -1], mode
                # an event: continue from it in the regime it leads to
                j = next(i for i, ev in enumerate(sol.t_events) if ev.size)
                t, y = float(sol.t_events[j][0]), sol.y_events[j][0]
                if mode == "slide":
                    forced = "low" if j == 0 else "high"
                n_events += 1
                if n_events > 10_000:
                    raise RuntimeError(f"{self.name}: more than 10000 regime switches of "
                                       f"{law.name} in [{ta:.6g}, {tb:.6g}] s (Zeno)")
                if t >= tb - eps:
                    return out, y, (forced or classify(t, y, d, u, mode))

        y = np.concatenate((np.asarray(self.initial_state(), float), law.initial_state()))
        d = np.asarray(self.initial_discrete(), float)
        u = self._u(inputs(exp.start) if inputs else None)
        cols = {n: np.empty(times.size) for n in self.all_output_names}
        ti = 0
        mode = classify(exp.start, y, d, u, "low")

        def record(t, y, d, u, mode):
            nonlocal ti
            F, _, _ = rhs_parts(t, y, d, u, mode)
            out = self.output(t, y[:ns], d, F, u)
            out["F"] = F
            for n in cols:
                cols[n][ti] = out[n]
            ti += 1
            if progress is not None and ti % 100 == 0:
                progress(100, f"t={t:.4g} s")

        if abs(times[0] - bps[0]) <= eps:  # the start instant
            if is_sample[0]:
                d = np.asarray(self.discrete_update(bps[0], y[:ns], d, u), float)
            record(bps[0], y, d, u, classify(bps[0], y, d, u, mode))
        for j in range(1, bps.size):
            ta, tb = bps[j - 1], bps[j]
            lo = np.searchsorted(times, ta + eps, side="left")
            hi = np.searchsorted(times, tb + eps, side="left")
            inner, y, mode = segment(ta, tb, y, d, u, times[lo:hi], mode)
            for tk, yk, mk in inner:
                record(tk, yk, d, u, mk)   # output inside the segment: d held
            if is_sample[j]:
                d = np.asarray(self.discrete_update(tb, y[:ns], d, u), float)
            if ti < times.size and abs(tb - times[ti]) <= eps:
                if inputs is not None:
                    u = self._u(inputs(tb))
                record(tb, y, d, u, classify(tb, y, d, u, mode))
        return structured({"time": times, **cols})


class FrictionComponent:
    """A friction law as a stand-alone stepper component (friction FMU of an assembled loop).

    Inputs ``v`` [m/s] and, if the law needs them, ``x`` [m], ``a`` [m/s^2], ``load`` [N];
    output ``F`` [N]. Same interface as :class:`PlantStepper`.

    Semantics: the state over ``[t, t+h]`` is advanced lazily, when the inputs at ``t+h``
    arrive (``set_inputs``) or the outputs are read, with the law's stable update between
    the inputs at both ends - exactly ``law.simulate`` on the sampled motion. ``F`` depends
    on the current inputs (direct feedthrough), so a Gauss-Seidel master reads it after
    setting ``v`` at each communication point.
    """

    def __init__(self, law: FrictionModel, method: str = "exact", start: float = 0.0):
        self.law = law
        self.fric = FrictionStep(law, method)
        self.input_names = ("v",) + tuple(n for n in ("x", "a", "load")
                                          if n in law.extra_inputs)
        self.output_names = ("F",)
        self.parameter_names = tuple(n for n in law.Params.numeric_names()
                                     if getattr(law.params, n) is not None)
        self.start = float(start)
        self.reset()

    def reset(self, start: float | None = None) -> None:
        if start is not None:
            self.start = float(start)
        self.time = self.start
        self.z = self.law.initial_state().astype(float)
        self.inputs = {n: 0.0 for n in self.input_names}
        self._pending = 0.0

    def _kin(self, inp):
        return (inp.get("x", 0.0), inp["v"], inp.get("a", 0.0), inp.get("load"))

    def _advance(self, new_inputs) -> None:
        if self._pending > 0:
            self.z, _ = self.fric.advance(self.z, self._pending, self._kin(self.inputs),
                                          self._kin(new_inputs))
            self._pending = 0.0

    def set_inputs(self, values: dict) -> None:
        for k in values:
            if k not in self.inputs:
                raise KeyError(f"{self.law.name}: unknown input {k!r}; inputs are "
                               f"{list(self.inputs)}")
        new = {**self.inputs, **{k: float(v) for k, v in values.items()}}
        self._advance(new)
        self.inputs = new

    def outputs(self) -> dict[str, float]:
        self._advance(self.inputs)  # no new inputs arrived: held over the step
        i = self.inputs
        return {"F": self.fric.force(self.z, i.get("x", 0.0), i["v"], i.get("a", 0.0),
                                     i.get("load"))}

    def do_step(self, t: float, h: float) -> bool:
        if abs(t - self.time) > 1e-9 * max(1.0, abs(t)):
            raise ValueError(f"do_step(t={t!r}) but the component is at time {self.time!r}")
        if not h > 0:
            raise ValueError(f"h = {h!r} is out of bounds: must be > 0 [s]")
        self._pending += h
        self.time = t + h
        return True


class PlantStepper:
    """Step-by-step simulation of a plant (what an FMU's ``doStep`` calls).

    Attributes
    ----------
    input_names, output_names, parameter_names : tuple of str
    time : float
        Current time [s].

    Notes
    -----
    ``do_step(t, h)`` integrates ``[t, t+h]`` with internal substeps no longer than
    ``substep``; discrete updates run at every sample instant ``start + k / control_rate``
    reached on the way (including ``t+h`` itself). External inputs are held over the step.

    Linearly implicit coupling (external friction only): the optional inputs
    ``coupling_names`` = ``("dF_dx", "dF_dv", "dF_dt", "d2F_dt2", "t_kink", "dF_dt_kink")``
    [N/m, N.s/m, N/s, N/s^2, s, N/s] are the friction law's local linearisation over the
    coming step. The step then integrates with

        F(t) = F_friction + dF_dx (x(t) - x_k) + dF_dv (v(t) - v_k)
               + dF_dt (t - t_k) + d2F_dt2 (t - t_k)^2 / 2
               + dF_dt_kink max(0, t - t_k - t_kink)

    where ``x_k, v_k`` is the contact motion at the start of the step, so the stiff part of
    the contact (bristle spring, damping) is resolved inside the plant's own substeps instead
    of being held over the communication step; the substep shrinks so that the explicit
    integrator stays stable against that stiffness. All default to 0 (force held).

    The output ``v_mean`` [m/s] (travel over the last step / step) lets the law FMU advance
    its state with the plant's real travel instead of the end-point velocities (which alias
    the contact's fast motion inside a long step).

    A law whose coefficients jump at |v| = ``v_switch`` [m/s] (``load_lugre``) adds the
    other side's linearisation: where |v(t)| lies on the other side of ``v_switch`` than
    ``v_k``, ``F`` gains ``dF_switch + dF_dx_switch (x - x_k) + dF_dv_switch (v - v_k)``
    [N, N/m, N.s/m]. The substeps then treat the switch like the internal law's (below), and
    the output ``low_share`` [1] tells the law FMU which share of the step its state spent on
    the low side.

    Regime switches. For a law with a :func:`friction.regimes.regime_split` (internal, or
    through ``v_switch``) each substep holds one regime (both Heun stages and the law's state
    update), so the regime that drives the motion is the one that drives the law's state; a
    substep that crosses |v| = vc is cut at the crossing (linear interpolation), and where
    both regimes push the velocity onto the surface the motion slides along it: the Filippov
    combination ``alpha low + (1 - alpha) high`` of the whole field (force and law state),
    with alpha keeping d|v|/dt = 0, until one side stops pushing. This converges to the
    reference integrator's Filippov solution as the substep shrinks; switching regimes
    sample by sample (chattering) does not.
    """

    #: inputs of the linearly implicit coupling (external friction mode)
    COUPLING_INPUTS = ("dF_dx", "dF_dv", "dF_dt", "d2F_dt2", "t_kink", "dF_dt_kink",
                       "v_switch", "dF_switch", "dF_dx_switch", "dF_dv_switch")
    #: output of the coupling (external friction mode): share of the last step spent on the
    #: low side of |v| = v_switch (a sliding stretch counts with its Filippov weight)
    SHARE_OUTPUT = "low_share"
    #: output of the coupling (external friction mode): mean contact velocity over the last
    #: step, travel / step [m/s] (the law advances its state with the plant's real travel)
    MEAN_OUTPUT = "v_mean"

    def __init__(self, plant: Plant, *, substep: float | None = None, start: float = 0.0,
                 friction_method: str = "exact"):
        self.plant = plant
        self.coupling_names = self.COUPLING_INPUTS if plant.external_friction else ()
        self.input_names = plant.all_input_names
        self.output_names = plant.all_output_names + (
            (self.SHARE_OUTPUT, self.MEAN_OUTPUT) if plant.external_friction else ())
        self.parameter_names = plant.parameter_names
        self.substep = float(substep or plant.max_substep)
        if not self.substep > 0:
            raise ValueError(f"substep = {substep!r} is out of bounds: must be > 0 [s]")
        self.start = float(start)
        self.fric = None if plant.external_friction else FrictionStep(plant.friction,
                                                                      friction_method)
        self._sides = None   # internal law with a regime split: (vc, {side: FrictionStep})
        if self.fric is not None:
            from friction.regimes import regime_split
            split = regime_split(plant.friction)
            if split is not None:
                self._sides = (split.vc, {"low": FrictionStep(split.low, friction_method),
                                          "high": FrictionStep(split.high, friction_method)})
        self.reset()

    # -- public API -------------------------------------------------------------------------
    def reset(self, start: float | None = None) -> None:
        """Back to the initial state at time ``start`` (default: the stepper's start)."""
        if start is not None:
            self.start = float(start)
        p = self.plant
        self.time = self.start
        self.s = np.asarray(p.initial_state(), dtype=float).copy()
        self.d = np.asarray(p.initial_discrete(), dtype=float).copy()
        self.u = p._u(None)
        self.z = None if self.fric is None else p.friction.initial_state().astype(float)
        self._a = 0.0
        # coupling: dF_dx [N/m], dF_dv [N.s/m], dF_dt [N/s], d2F_dt2 [N/s^2], t_kink [s],
        # dF_dt_kink [N/s]
        self._lin = [0.0] * len(self.COUPLING_INPUTS)
        self._lin_ref = None    # (F_k, x_k, v_k, substep) of the current step when linearised
        self._mode = None       # regime held by the substeps: "low", "high" or "slide"
        self._low_share = 0.0   # share of the last step on the low side (Filippov weighted)
        self._v_mean = 0.0      # travel / step of the last step [m/s]
        self._carry = None      # (side, force at the end of the last substep on that side)
        Ts = p._sample_period()
        self._Ts = Ts
        self._k = 0  # index of the next sample instant
        self._F = self._friction_now()
        self._sample_due(self.time)

    def set_inputs(self, values: dict) -> None:
        """Set external inputs (held until changed); unknown names raise ``KeyError``."""
        for k, val in values.items():
            if k in self.coupling_names:
                self._lin[self.coupling_names.index(k)] = float(val)
                continue
            if k not in self.u:
                raise KeyError(f"{self.plant.name}: unknown input {k!r}; inputs are "
                               f"{list(self.u) + list(self.coupling_names)}")
            self.u[k] = float(val)
        if self.fric is None:
            self._F = self.u["F_friction"]

    def set_parameters(self, **values) -> None:
        """Change plant parameters (validated); call before ``reset`` for initial values."""
        self.plant = self.plant.with_params(**values)

    def outputs(self) -> dict[str, float]:
        """Current outputs (names ``output_names``)."""
        p = self.plant
        out = dict(p.output(self.time, self.s, self.d, self._F, self.u))
        if self.fric is not None:
            out["F"] = self._F
        else:
            out[self.SHARE_OUTPUT] = self._low_share
            out[self.MEAN_OUTPUT] = self._v_mean
        return out

    def do_step(self, t: float, h: float) -> bool:
        """Integrate from ``t`` to ``t + h`` [s]; returns True."""
        if abs(t - self.time) > 1e-9 * max(1.0, abs(t)):
            raise ValueError(f"do_step(t={t!r}) but the stepper is at time {self.time!r}")
        if not h > 0:
            raise ValueError(f"h = {h!r} is out of bounds: must be > 0 [s]")
        t_end = t + h
        tol = 1e-12 * max(1.0, abs(t_end))
        tc = self.time
        self._lin_ref = None
        self._t_low = 0.0
        x_start = self.plant.contact(tc, self.s, self.d, self.u)[0] if self.fric is None \
            else 0.0
        if self.fric is None and any(c != 0.0 for c in self._lin):
            x_k, v_k, _ = self.plant.contact(tc, self.s, self.d, self.u)
            self._lin_ref = (self.u["F_friction"], float(x_k), float(v_k),
                             self._coupled_substep(), tc)
        while tc < t_end - tol:
            t_next = t_end
            if self._Ts is not None:
                ts = self.start + self._k * self._Ts
                if ts < t_end - tol:
                    t_next = ts
            self._integrate(tc, t_next)
            tc = t_next
            self.time = tc
            self._sample_due(tc)
        self.time = t_end
        self._low_share = min(1.0, max(0.0, self._t_low / h))
        if self.fric is None:
            self._v_mean = (self.plant.contact(t_end, self.s, self.d, self.u)[0] - x_start) / h
        return True

    # -- internals ---------------------------------------------------------------------------
    def _sample_due(self, t: float) -> None:
        if self._Ts is None:
            return
        tol = 1e-9 * self._Ts
        while self.start + self._k * self._Ts <= t + tol:
            self.d = np.asarray(self.plant.discrete_update(t, self.s, self.d, self.u), float)
            self._k += 1

    def _kin(self, t, s, ds):
        x, v, load = self.plant.contact(t, s, self.d, self.u)
        a = self.plant.contact_acceleration(t, s, ds, self.d, self.u) if ds is not None \
            else self._a
        return (x, v, a, load)

    def _friction_now(self) -> float:
        if self.fric is None:
            return self.u["F_friction"]
        x, v, load = self.plant.contact(self.time, self.s, self.d, self.u)
        if self._sides is not None:
            vc, sides = self._sides
            self._mode = "low" if abs(v) < vc else "high"
            return sides[self._mode].force(self.z, x, v, self._a, load)
        return self.fric.force(self.z, x, v, self._a, load)

    def _coupled_substep(self) -> float:
        """Largest stable substep [s] against the linearised friction (Heun: |h lambda| <= 1
        on the damping, omega h <= 0.2 on the spring, a margin on the imaginary axis); with
        a regime switch, against the stiffer of both sides."""
        p, t, s, d, u = self.plant, self.time, self.s, self.d, self.u
        F = self.u["F_friction"]
        ds0 = p.derivatives(t, s, d, F, u)
        dF = 1.0 + 1e-6 * abs(F)
        ds1 = p.derivatives(t, s, d, F + dF, u)
        # the contact's inverse mass: d(acceleration)/dF
        w = abs(p.contact_acceleration(t, s, ds1, d, u)
                - p.contact_acceleration(t, s, ds0, d, u)) / dF
        K, D = abs(self._lin[0]), abs(self._lin[1])
        if self._lin[6] > 0.0:
            K = max(K, abs(self._lin[0] + self._lin[8]))
            D = max(D, abs(self._lin[1] + self._lin[9]))
        h = self.substep
        if w * D > 0:
            h = min(h, 1.0 / (w * D))
        if w * K > 0:
            h = min(h, 0.2 / math.sqrt(w * K))
        return h

    def _coupled_force(self, t, s, side=None) -> float:
        """Linearised friction at (t, s); ``side`` ("low"/"high") forces a side of the
        switch (default: the side of the contact velocity)."""
        F_k, x_k, v_k, _, t_k = self._lin_ref
        x, v, _ = self.plant.contact(t, s, self.d, self.u)
        K, D, r, c, t_kink, r_kink, v_sw, J, dK, dD = self._lin
        tau = t - t_k
        F = F_k + K * (x - x_k) + D * (v - v_k) + (r + 0.5 * c * tau) * tau
        if r_kink != 0.0 and tau > t_kink:
            F += r_kink * (tau - t_kink)
        if v_sw > 0.0:
            low = (abs(v) < v_sw) if side is None else side == "low"
            if low != (abs(v_k) < v_sw):  # the other side of the switch than the law's
                F += J + dK * (x - x_k) + dD * (v - v_k)
        return F

    def _integrate_coupled(self, ta: float, tb: float) -> None:
        """Heun substeps with the linearised friction evaluated at every stage."""
        n = max(1, int(math.ceil((tb - ta) / self._lin_ref[3] - 1e-9)))
        h = (tb - ta) / n
        p, d, u = self.plant, self.d, self.u
        s = self.s
        if self._lin[6] > 0.0:   # a regime switch: substeps hold a regime, slide along it
            v_sw = self._lin[6]
            self._carry = None
            for i in range(n):
                s = self._regime_substep(ta + i * h, h, s, None, v_sw, self._coupled_side)[0]
            F = (self._filippov(tb, s, None, self._coupled_side)[1] if self._mode == "slide"
                 else self._coupled_force(tb, s))
        else:
            F = self._coupled_force(ta, s)
            for i in range(n):
                t0 = ta + i * h
                k1 = p.derivatives(t0, s, d, F, u)
                s_pred = s + h * k1
                k2 = p.derivatives(t0 + h, s_pred, d, self._coupled_force(t0 + h, s_pred), u)
                s = s + 0.5 * h * (k1 + k2)
                F = self._coupled_force(t0 + h, s)
        if not (np.all(np.isfinite(s)) and math.isfinite(F)):
            raise FloatingPointError(
                f"{p.name}: the fast integrator diverged between t={ta:.6g} s and {tb:.6g} s "
                f"(substep {h:.3g} s, coupling dF_dx = {self._lin[0]:g} N/m, dF_dv = "
                f"{self._lin[1]:g} N.s/m)")
        self.s, self._F = s, F

    # -- regime switches (friction.regimes) ---------------------------------------------------
    def _coupled_side(self, side, t, s, z, h=0.0, kin0=None, kin1=None):
        """Linearised friction of one side (external friction): (F, state) - no law state."""
        return self._coupled_force(t, s, side), None

    def _internal_side(self, side, t, s, z, h=0.0, kin0=None, kin1=None):
        """Internal law of one side: force at (t, s) with state z, or, with ``h`` > 0, the
        state advanced over [t - h, t] from kin0 to kin1 and the force at its end."""
        f = self._sides[1][side]
        if h > 0.0:
            z1, F = f.advance(z, h, kin0, kin1)
            return F, z1
        x, v, load = self.plant.contact(t, s, self.d, self.u)
        return f.force(z, x, v, self._a, load), z

    def _filippov(self, t, s, z, side_fn):
        """Filippov weight on |v| = v_switch at (t, s): ``(alpha, F_mix, g_low, g_high)``
        with g the d|v|/dt under each side's force; alpha (of the low side, clipped into
        [0, 1]) keeps d|v|/dt = 0."""
        p, d, u = self.plant, self.d, self.u
        F_l = side_fn("low", t, s, z)[0]
        F_h = side_fn("high", t, s, z)[0]
        v = p.contact(t, s, d, u)[1]
        sg = 1.0 if v >= 0.0 else -1.0
        g_l = sg * p.contact_acceleration(t, s, p.derivatives(t, s, d, F_l, u), d, u)
        g_h = sg * p.contact_acceleration(t, s, p.derivatives(t, s, d, F_h, u), d, u)
        al = min(1.0, max(0.0, g_h / (g_h - g_l))) if g_h != g_l else 0.5
        return al, al * F_l + (1.0 - al) * F_h, g_l, g_h

    def _classify(self, t, s, z, side_fn, prev):
        """Regime on the switching surface: sliding where both sides push onto it, else the
        side the motion leaves to (a repulsive surface keeps ``prev``)."""
        _, _, g_l, g_h = self._filippov(t, s, z, side_fn)
        if g_l > 0.0 and g_h < 0.0:
            return "slide"
        if g_l > 0.0:
            return "high"
        if g_h < 0.0:
            return "low"
        return prev

    def _regime_substep(self, t0, h, s, z, v_sw, side_fn, split=True):
        """One Heun substep holding a regime (or sliding); returns (s, z) at t0 + h.

        A side substep that ends on the other side is cut at the crossing (linear in the
        states) and the rest of it runs in the regime the surface leads to.
        """
        p, d, u = self.plant, self.d, self.u
        v0 = p.contact(t0, s, d, u)[1]
        mode = self._mode
        if not split:
            pass   # the rest of a substep cut at a crossing: the regime the surface chose
        elif mode == "slide":
            mode = self._classify(t0, s, z, side_fn, "low" if abs(v0) < v_sw else "high")
        elif mode is None or (mode == "low") != (abs(v0) < v_sw):
            mode = "low" if abs(v0) < v_sw else "high"
        self._mode = mode
        internal = self.fric is not None
        if mode == "slide":
            al, F0, _, _ = self._filippov(t0, s, z, side_fn)
            k1 = p.derivatives(t0, s, d, F0, u)
            s_pred = s + h * k1
            z_pred = z
            if internal:
                kin0, kp = self._kin(t0, s, k1), self._kin(t0 + h, s_pred, k1)
                z_pred = (al * side_fn("low", t0 + h, s_pred, z, h, kin0, kp)[1]
                          + (1.0 - al) * side_fn("high", t0 + h, s_pred, z, h, kin0, kp)[1])
            al2, F2, _, _ = self._filippov(t0 + h, s_pred, z_pred, side_fn)
            k2 = p.derivatives(t0 + h, s_pred, d, F2, u)
            s1 = s + 0.5 * h * (k1 + k2)
            w = 0.5 * (al + al2)
            self._t_low += w * h
            if internal:
                ds_mean = 0.5 * (k1 + k2)
                kin1 = self._kin(t0 + h, s1, ds_mean)
                z = (w * side_fn("low", t0 + h, s1, z, h, kin0, kin1)[1]
                     + (1.0 - w) * side_fn("high", t0 + h, s1, z, h, kin0, kin1)[1])
                self._a = p.contact_acceleration(t0 + h, s1, ds_mean, d, u)
            return s1, z
        # one side held over both stages (and the law's state update); the force at the
        # start is the last substep's end force when it ran on the same side
        carry, self._carry = self._carry, None
        F0 = carry[1] if carry is not None and carry[0] == mode else side_fn(mode, t0, s, z)[0]
        k1 = p.derivatives(t0, s, d, F0, u)
        s_pred = s + h * k1
        if internal:
            kin0 = self._kin(t0, s, k1)
            F_pred = side_fn(mode, t0 + h, s_pred, z, h, kin0,
                             self._kin(t0 + h, s_pred, k1))[0]
        else:
            F_pred = side_fn(mode, t0 + h, s_pred, z)[0]
        k2 = p.derivatives(t0 + h, s_pred, d, F_pred, u)
        s1 = s + 0.5 * h * (k1 + k2)
        z1 = z
        F1 = None
        if internal:
            ds_mean = 0.5 * (k1 + k2)
            F1, z1 = side_fn(mode, t0 + h, s1, z, h, kin0, self._kin(t0 + h, s1, ds_mean))
            self._a = p.contact_acceleration(t0 + h, s1, ds_mean, d, u)
        a0, a1 = abs(v0), abs(p.contact(t0 + h, s1, d, u)[1])
        crossed = (a1 >= v_sw) if mode == "low" else (a1 < v_sw)
        if not (crossed and split) or a1 == a0:
            if mode == "low":
                self._t_low += h
            if not crossed and F1 is not None:
                self._carry = (mode, F1)
            return s1, z1
        th = min(1.0, max(0.0, (v_sw - a0) / (a1 - a0)))
        s_c = s + th * (s1 - s)
        z_c = None if z is None else z + th * (z1 - z)
        if mode == "low":
            self._t_low += th * h
        other = "high" if mode == "low" else "low"
        nxt = self._classify(t0 + th * h, s_c, z_c, side_fn, other)
        if nxt == mode or th >= 1.0:  # pushed back at once (discretisation): keep the end
            if mode == "low":
                self._t_low += (1.0 - th) * h
            self._mode = "low" if a1 < v_sw else "high"
            return s1, z1
        self._mode = nxt
        return self._regime_substep(t0 + th * h, (1.0 - th) * h, s_c, z_c, v_sw, side_fn,
                                    split=False)

    def _integrate(self, ta: float, tb: float) -> None:
        if self._lin_ref is not None:
            return self._integrate_coupled(ta, tb)
        n = max(1, int(math.ceil((tb - ta) / self.substep - 1e-9)))
        h = (tb - ta) / n
        p = self.plant
        d, u = self.d, self.u
        s, z, F = self.s, self.z, self._F
        if self._sides is not None:   # a regime switch: substeps hold a regime, slide along it
            vc = self._sides[0]
            self._carry = None
            for i in range(n):
                s, z = self._regime_substep(ta + i * h, h, s, z, vc, self._internal_side)
            if self._mode == "slide":
                F = self._filippov(tb, s, z, self._internal_side)[1]
            else:
                x, v, load = p.contact(tb, s, d, u)
                self._mode = "low" if abs(v) < vc else "high"
                F = self._internal_side(self._mode, tb, s, z)[0]
        else:
            for i in range(n):
                t0 = ta + i * h
                k1 = p.derivatives(t0, s, d, F, u)
                s_pred = s + h * k1
                if self.fric is None:
                    k2 = p.derivatives(t0 + h, s_pred, d, F, u)
                    s = s + 0.5 * h * (k1 + k2)
                    F = self.u["F_friction"]
                    continue
                kin0 = self._kin(t0, s, k1)
                _, F_pred = self.fric.advance(z, h, kin0, self._kin(t0 + h, s_pred, k1))
                k2 = p.derivatives(t0 + h, s_pred, d, F_pred, u)
                s = s + 0.5 * h * (k1 + k2)
                ds_mean = 0.5 * (k1 + k2)
                z, F = self.fric.advance(z, h, kin0, self._kin(t0 + h, s, ds_mean))
                self._a = p.contact_acceleration(t0 + h, s, ds_mean, d, u)
        if not (np.all(np.isfinite(s)) and math.isfinite(F)):
            raise FloatingPointError(
                f"{p.name}: the fast integrator diverged between t={ta:.6g} s and {tb:.6g} s "
                f"(substep {h:.3g} s); try a smaller substep= or check the parameters")
        self.s, self.z, self._F = s, z, F
