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
* ``output(t, s, d, F, u) -> dict`` of the outputs;
* optionally ``build_parts()``: the components (:mod:`plants.components`: masses, springs,
  dampers, ...) built from the parameters, read back through :attr:`Plant.parts`.

The base then provides :meth:`Plant.simulate` (``"fast"``: the fixed-step
:class:`plants.stepper.PlantStepper`, numpy/numba only; ``"reference"``: the monolithic ODE
with ``scipy.integrate.solve_ivp`` between sample instants,
:class:`plants.reference.ReferenceIntegrator`) and :meth:`Plant.stepper` (the FMU-facing
object, no scipy). Both treat a law whose coefficients jump at |v| = vc with the one set of
rules of :mod:`friction.regimes` (regime of each side, Filippov sliding along the switch).

``PlantStepper``, ``FrictionStep`` and ``FrictionComponent`` stay importable from here.
"""
from __future__ import annotations

import copy
import math
from dataclasses import dataclass, fields
from typing import Any, Callable, ClassVar

import numpy as np

from friction.base import FrictionModel, FrictionParams
from friction.progress import as_progress

from .law_stepper import FrictionComponent, FrictionStep
from .stepper import PlantStepper

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
    """Structured array (fmpy result layout) from ordered columns; ``time`` must come first.

    Parameters
    ----------
    columns : dict of str to ndarray
        Equal-length columns in order, ``time`` first.
    """
    names = list(columns)
    if names[0] != "time":
        raise ValueError(f"first column must be 'time', got {names[0]!r}")
    n = len(columns["time"])
    out = np.empty(n, dtype=[(k, "f8") for k in names])
    for k, col in columns.items():
        out[k] = col
    return out


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
        """Time derivative of the continuous state.

        Parameters
        ----------
        t : float
            Time [s].
        s : ndarray, shape (n_states,)
            Continuous state (``state_names``, SI units).
        d : ndarray, shape (n_discrete,)
            Discrete state held since the last sample (``discrete_names``).
        F : float
            Friction force on the contact [N].
        u : dict
            External inputs by name (``all_input_names``), SI units.
        """
        raise NotImplementedError

    def contact(self, t, s, d, u) -> tuple[float, float, float | None]:  # pragma: no cover
        """The contact's kinematics ``(x, v, load)`` [m, m/s, N] (load None without one).

        Parameters
        ----------
        t, s, d, u
            Time [s], continuous state, discrete state and inputs, as for
            :meth:`derivatives`.
        """
        raise NotImplementedError

    def contact_acceleration(self, t, s, ds, d, u) -> float:
        """Acceleration of the contact [m/s^2] (default: the derivative of state ``v``).

        Parameters
        ----------
        t, s, d, u
            As for :meth:`derivatives`.
        ds : ndarray, shape (n_states,)
            The time derivative of ``s`` (:meth:`derivatives`).
        """
        return float(ds[self.state_names.index("v")])

    def discrete_update(self, t, s, d, u) -> np.ndarray:
        """The discrete state after the sample at ``t`` (controllers; default unchanged).

        Parameters
        ----------
        t, s, d, u
            Sample time [s], continuous state, discrete state before the sample and inputs,
            as for :meth:`derivatives`.
        """
        return d

    def output(self, t, s, d, F, u) -> dict[str, float]:  # pragma: no cover - abstract
        """The outputs by name (``output_names``), SI units.

        Parameters
        ----------
        t, s, d, F, u
            As for :meth:`derivatives`.
        """
        raise NotImplementedError

    def build_parts(self) -> tuple:
        """The plant's components built from its parameters (default: none)."""
        return ()

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
        """A copy of this plant with experiment options changed (unknown names: TypeError).

        Parameters
        ----------
        **options
            Experiment options by name (``options``); an unknown name is a TypeError.
        """
        unknown = set(options) - set(self.options)
        if unknown:
            raise TypeError(f"{self.name}: unknown experiment option(s) {sorted(unknown)}; "
                            f"choose from {sorted(self.options)}")
        new = self._copy()
        new.opts = {**self.opts, **options}
        return new

    def with_params(self, **values) -> "Plant":
        """A copy with some plant parameters changed (validated).

        Parameters
        ----------
        **values
            Plant parameter values (SI units) by name (validated; an unknown name is a TypeError).
        """
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

    @property
    def parts(self) -> tuple:
        """:meth:`build_parts`, built once per parameter set (copies rebuild it)."""
        parts = self.cache.get("parts")
        if parts is None:
            parts = self.cache["parts"] = self.build_parts()
        return parts

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
        progress : None, bool, tqdm or callable(n, info), optional
            Progress in output samples (the convention of :mod:`friction.progress`).
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
        if method not in ("fast", "reference"):
            raise ValueError(f"method must be 'fast' or 'reference', got {method!r}")
        with as_progress(progress, f"simulate {self.name}", total=exp.times().size,
                         unit="sample") as prog:
            if method == "fast":
                return plant._simulate_fast(exp, prog, inputs, substep)
            return plant._simulate_reference(exp, rtol, prog, inputs, time_budget)

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
        from .reference import ReferenceIntegrator
        return ReferenceIntegrator(self, exp, rtol, progress, inputs, time_budget).run()
