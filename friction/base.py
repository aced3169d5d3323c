"""The contract every friction law fulfils (the ``PartialFriction`` of frictionlab).

A law is two things:

* a frozen parameter dataclass (subclass of :class:`FrictionParams`) whose fields carry
  ``unit``, ``description``, admissible bounds and a default search range in their metadata;
* a model class (subclass of :class:`FrictionModel`) that fills in

  - ``theta_layout``: names of the packed float vector the numba kernels consume,
  - ``_pack(params)``: parameters -> that vector,
  - ``_kernel(t, v, a, load, x, theta, method, state0)`` -> ``(F, states)``: a numba-compiled
    prescribed-motion simulation (one parameter set),
  - ``_population_kernel(t, v, a, load, x, Theta, method)`` -> ``F[npop, N]``,
  - ``steady_state(v, **inputs)``,
  - continuous-time ``derivatives(state, v, **inputs)`` and ``force(state, v, **inputs)``
    used by the reference integrator and by the plant library.

Everything else (input validation, direction-dependent twins, building a population of
parameter vectors for identification, bound checks with :class:`friction.bounds.Bounded`) is
written once here.

The two kernels stay module-level ``@njit(cache=True)`` functions of each law, a few lines
around the law's ``*_run`` loop: numba caches only those. A kernel made by a factory (a
closure over the law's run function) or one taking the run function as an argument compiles
again in every process (measured: no cache hit across runs), seconds per law and per test.
"""
from __future__ import annotations

import dataclasses
import functools
import inspect
import math
from dataclasses import dataclass, field, fields
from typing import Any, ClassVar

import numpy as np

from ._validation import ParameterError, check_signals
from .bounds import Bounded

__all__ = ["param", "ParamInfo", "FrictionParams", "FrictionModel", "METHODS"]

#: steps of the warm-up ramp from rest of :meth:`FrictionModel.record_start_state`
WARM_UP_SAMPLES = 64

#: Bristle-update schemes. ``exact``: exponential update over each step (stable at any step
#: and stiffness). ``euler``: explicit Euler as the papers implement it (unstable when
#: h*sigma0*|v|/g(v) > 2; kept to reproduce their instability).
METHODS = {"exact": 0, "euler": 1}

#: ``True``: :meth:`FrictionModel.simulate_population` (and the fused population costs of
#: :mod:`identification.objectives`) run the population row by row through the law's
#: serial kernel in this thread instead of the ``parallel=True`` kernel (the same run code
#: from the same rest state, so the same numbers). Set in a process forked from one whose
#: numba already runs GNU OpenMP (numba's wheels): its parallel kernels abort such a child
#: ("fork() called from a process already using GNU OpenMP"); the diagnosis' forked fit
#: workers (:func:`diagnosis.cluster.local_fits`) set it
SERIAL_POPULATIONS = False


def param(default, unit: str, description: str, *, lower: float = -math.inf,
          upper: float = math.inf, lower_open: bool = False, upper_open: bool = False,
          search: tuple[float, float] | None = None, log: bool = False):
    """Declare a parameter field with unit, description and admissible bounds.

    Parameters
    ----------
    default : float or None
        Default value (``None`` for an optional direction-dependent twin: "same as +").
    unit : str
        SI unit string, e.g. ``"N/m"``.
    description : str
        One-line description.
    lower, upper : float
        Admissible bounds; violating them raises :class:`ParameterError`.
    lower_open, upper_open : bool
        Whether the bound itself is excluded (``sigma0 > 0`` is ``lower=0, lower_open=True``).
    search : (float, float), optional
        Default search range for identification.
    log : bool
        Whether identification should search this parameter on a log scale.
    """
    return field(default=default, metadata=dict(
        unit=unit, description=description, lower=lower, upper=upper,
        lower_open=lower_open, upper_open=upper_open, search=search, log=log))


@dataclass(frozen=True)
class ParamInfo(Bounded):
    """Metadata of one parameter (what a model description or a GUI shows)."""
    name: str
    default: Any
    unit: str
    description: str
    lower: float
    upper: float
    lower_open: bool
    upper_open: bool
    search: tuple[float, float] | None
    log: bool

    def bound_text(self) -> str:
        """The bounds in words, naming the parameter (``"sigma0 > 0"``)."""
        return Bounded.bound_text(self, self.name)


@dataclass(frozen=True)
class FrictionParams:
    """Base of all parameter dataclasses: validates every numeric field on creation."""

    def __post_init__(self):
        for info in self.info():
            value = getattr(self, info.name)
            if value is None or isinstance(value, (str, bool)):
                continue
            try:
                value = float(value)
            except (TypeError, ValueError):
                raise ParameterError(f"{info.name} = {value!r} is not a number") from None
            if not info.admissible(value):
                raise ParameterError(
                    f"{info.name} = {value!r} is out of bounds: must be {info.bound_text()} "
                    f"[{info.unit}] ({info.description})")
            object.__setattr__(self, info.name, value)
        self._check_relations()

    def _check_relations(self) -> None:
        """Cross-parameter constraints; subclasses override."""

    @classmethod
    def info(cls) -> list[ParamInfo]:
        out = []
        for f in fields(cls):
            md = f.metadata
            if "unit" not in md:
                continue
            out.append(ParamInfo(f.name, f.default, md["unit"], md["description"], md["lower"],
                                 md["upper"], md["lower_open"], md["upper_open"], md["search"],
                                 md["log"]))
        return out

    @classmethod
    def numeric_names(cls) -> list[str]:
        return [i.name for i in cls.info()
                if not isinstance(i.default, (str, bool))]

    def resolved(self, name: str, direction: int) -> float:
        """Value of ``name`` for direction +1 / -1: a direction-dependent law keeps the "-"
        value in ``<name>_neg``; left ``None`` (or absent) it equals the "+" value.

        Parameters
        ----------
        name : str
            The "+" parameter's name (``Fc``).
        direction : int
            +1 or -1 (the sign of the velocity).
        """
        if direction < 0:
            neg = getattr(self, name + "_neg", None)
            if neg is not None:
                return neg
        return getattr(self, name)

    def as_dict(self) -> dict[str, Any]:
        return {f.name: getattr(self, f.name) for f in fields(self)}

    def replace(self, **changes) -> "FrictionParams":
        """

        Parameters
        ----------
        **changes
            New field values by name (validated; an unknown name is a TypeError).
        """
        return dataclasses.replace(self, **changes)


def _checked_inputs(fn):
    """``fn`` (a law's ``steady_state``, ``force``...) refusing a keyword that is neither
    one of its parameters nor one of :attr:`FrictionModel.INPUT_NAMES` (TypeError)."""
    sig = inspect.signature(fn)
    allowed = frozenset(FrictionModel.INPUT_NAMES) | {
        p.name for p in sig.parameters.values()
        if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)}

    @functools.wraps(fn)
    def checked(self, *args, **kwargs):
        if kwargs and not allowed.issuperset(kwargs):
            bad = sorted(set(kwargs) - allowed)
            raise TypeError(f"{type(self).__name__}.{fn.__name__}() got an unexpected keyword "
                            f"argument {bad[0]!r} (the law's inputs are "
                            f"{', '.join(FrictionModel.INPUT_NAMES)})")
        return fn(self, *args, **kwargs)
    return checked


class FrictionModel:
    """Base class of friction laws. See the module docstring for what subclasses fill in."""

    name: ClassVar[str] = ""
    Params: ClassVar[type[FrictionParams]] = FrictionParams
    #: names of the continuous states (bristle deflection z first)
    state_names: ClassVar[tuple[str, ...]] = ("z",)
    #: extra inputs the law needs besides velocity, among ("a", "load", "x")
    extra_inputs: ClassVar[tuple[str, ...]] = ()
    #: packed float-vector layout consumed by the numba kernels
    theta_layout: ClassVar[tuple[str, ...]] = ()
    #: direction-dependent twins: name -> name of the "-" value in theta_layout
    twins: ClassVar[dict[str, str]] = {}

    #: the inputs besides velocity that ``steady_state``, ``steady_state_state``,
    #: ``derivatives`` and ``force`` accept by keyword (each law uses those in
    #: ``extra_inputs`` and ignores the others); any other keyword is a TypeError
    INPUT_NAMES: ClassVar[tuple[str, ...]] = ("a", "load", "x")

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        for name in ("steady_state", "steady_state_state", "derivatives", "force"):
            fn = cls.__dict__.get(name)
            if fn is not None and not hasattr(fn, "__wrapped__"):
                setattr(cls, name, _checked_inputs(fn))

    def __init__(self, params: FrictionParams | None = None, **kwargs):
        """A law with parameters ``params``, or the defaults changed by ``kwargs``.

        Parameters
        ----------
        params : FrictionParams, optional
            The law's parameter dataclass (``Params``); default its defaults.
        **kwargs
            Parameter values (SI units) replacing those of ``params``; an unknown name is a
            TypeError, a value out of its bounds a :class:`ParameterError`.
        """
        if params is None:
            params = self.Params(**kwargs)
        elif kwargs:
            params = params.replace(**kwargs)
        if not isinstance(params, self.Params):
            raise TypeError(f"{self.name}: params must be {self.Params.__name__}, "
                            f"got {type(params).__name__}")
        self.params = params
        self.theta = self._pack(params)

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.params!r})"

    # -- to be filled in by each law ------------------------------------------------------
    def _pack(self, params) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError

    @staticmethod
    def _kernel(t, v, a, load, x, theta, method, state0):  # pragma: no cover - abstract
        raise NotImplementedError

    @staticmethod
    def _population_kernel(t, v, a, load, x, Theta, method):  # pragma: no cover
        raise NotImplementedError

    def steady_state(self, v, **inputs) -> np.ndarray:  # pragma: no cover - abstract
        """Steady-state friction force [N] at constant velocity.

        Parameters
        ----------
        v : array_like
            Velocity [m/s].
        **inputs : array_like
            The law's other inputs (:attr:`INPUT_NAMES`): ``a`` [m/s^2], ``load`` [N],
            ``x`` [m]; another keyword is a TypeError.
        """
        raise NotImplementedError

    def derivatives(self, state, v, **inputs) -> np.ndarray:  # pragma: no cover
        """Continuous-time state derivative d(state)/dt at velocity ``v`` [m/s].

        Parameters
        ----------
        state : array_like, shape (n_states,)
            The law's state, in the units of ``state_names`` (``z`` [m], ...).
        v : float
            Velocity [m/s].
        **inputs : float
            The law's other inputs (:attr:`INPUT_NAMES`): ``a`` [m/s^2], ``load`` [N],
            ``x`` [m]; another keyword is a TypeError.
        """
        raise NotImplementedError

    def force(self, state, v, **inputs) -> float:  # pragma: no cover
        """Friction force [N] for a continuous state and velocity ``v`` [m/s].

        Parameters
        ----------
        state, v, **inputs
            As for :meth:`derivatives`: the state, velocity [m/s] and the other inputs
            ``a`` [m/s^2], ``load`` [N], ``x`` [m].
        """
        raise NotImplementedError

    def conservative_force(self, x) -> np.ndarray:
        """The part of the law's force that is not friction (a parallel spring and offset,
        as in the MRE isolator's k0 x + f0) [N] at displacement ``x`` [m]; zero for pure
        friction laws. Effects on the friction level scale the rest only.

        Parameters
        ----------
        x : array_like
            Displacement [m].
        """
        return np.zeros_like(np.asarray(x, dtype=float))

    # -- written once -------------------------------------------------------------------
    def initial_state(self) -> np.ndarray:
        """State of a contact at rest with no history: zeros (bristles undeflected)."""
        return np.zeros(len(self.state_names))

    def steady_state_state(self, v0, **inputs) -> np.ndarray:
        """The state the law settles to when sliding at the constant velocity ``v0``.

        The initial state consistent with a record that starts in motion: started from it,
        the law gives its steady-state force :meth:`steady_state` from the first sample on,
        instead of the start-up transient of an undeflected bristle (``z = 0`` at speed
        gives ``F = (sigma1 + sigma2) v``, a spike of a stiff, damped contact). For the
        classic LuGre ``z = g(v0) sgn(v0) / sigma0``.

        Written once for every law whose state equations are affine in each state and
        decoupled, ``ds_i/dt = c_i - k_i s_i`` at frozen inputs (the LuGre family: the
        bristle deflection, the MRE hysteretic variable, a first-order lag): each state
        is the root ``c_i / k_i`` of its own derivative, found from two evaluations of
        :meth:`derivatives`. A state that does not relax at ``v0`` (``k_i = 0``: at rest,
        or a rate switched off) keeps its rest value 0. Laws whose states are coupled,
        nonlinear in themselves, or frozen by design at speed override this.

        Parameters
        ----------
        v0 : float
            Velocity [m/s] at which the law slides.
        **inputs : float
            The law's other inputs at that instant, as :meth:`derivatives` takes them:
            ``a`` [m/s^2], ``load`` [N], ``x`` [m].

        Returns
        -------
        ndarray, shape (n_states,)
            The steady state, in the units of ``state_names`` (``z`` [m], ...); zeros at
            ``v0 = 0`` for the LuGre family (the rest state).
        """
        n = len(self.state_names)
        s = np.zeros(n)
        v0 = float(v0)
        if n == 0 or v0 == 0.0 or not math.isfinite(v0):
            return s
        d0 = np.asarray(self.derivatives(np.zeros(n), v0, **inputs), float)
        for i in range(n):
            e = np.zeros(n)
            # a unit step of state i: the slope -k_i is exact for an affine derivative
            e[i] = 1.0
            slope = float(np.asarray(self.derivatives(e, v0, **inputs), float)[i] - d0[i])
            if slope < 0.0 and math.isfinite(slope) and math.isfinite(d0[i]):
                s[i] = -d0[i] / slope
        return s

    def record_start_state(self, t, v, *, a=None, load=None, x=None, F=None) -> np.ndarray:
        """Initial state consistent with the first samples of a record.

        From the motion alone (``F`` not given):

        * a record that starts at rest (``v[0] = 0``): the rest state (zeros);
        * one that starts sliding and is not speeding up (``v[0]`` and the first velocity
          step ``v[1] - v[0]`` of opposite signs, or no step): it has been sliding for a
          while, so the law's steady state at ``v[0]`` (:meth:`steady_state_state`; LuGre
          ``z = g(v0) sgn(v0) / sigma0``);
        * one that starts speeding up, at ``a0 = (v[1] - v[0]) / (t[1] - t[0])`` with the
          sign of ``v[0]``: a warm-up from rest at that constant acceleration up to
          ``v[0]`` (duration ``v[0] / a0``, :data:`WARM_UP_SAMPLES` steps of the law's own
          kernel, inputs held at their first values), whose final state is taken. Long
          after the start of the motion that is the steady state; just after it (a record
          cut where the motion begins, at ``v[0]`` of 1e-17 m/s) it is nearly the rest
          state, not the saturated bristle of the steady state at a vanishing speed.

        With the measured force ``F`` (a record to score or fit), its first sample decides
        the first state (the bristle deflection, ``state_names[0]``) as well: the value at
        which the law's :meth:`force` at the first sample equals ``F[0]`` (the force is
        affine in it across the LuGre family), kept within the bristle's saturation (the
        largest deflection of the law's steady states); the other states as above. A record
        that starts in steady sliding gets its steady deflection back, one cut just before
        a reversal (sliding slowly, the bristle already unloading) or at rest under a load
        gets the deflection it has, which no rule on the motion alone can know.

        Parameters
        ----------
        t, v : array_like, shape (N,)
            Time [s] and velocity [m/s] of the record.
        a, load, x : array_like, shape (N,), optional
            Acceleration [m/s^2], load [N], displacement [m] where the law needs them.
        F : array_like, shape (N,), optional
            Measured friction force [N] (only ``F[0]`` is read).

        Returns
        -------
        ndarray, shape (n_states,)
        """
        t, v, a, load, x = self._inputs(t, v, a, load, x)
        F0 = None
        if F is not None:
            F0 = float(np.asarray(F, dtype=float).ravel()[0])
        return self._start_from(t, v, a, load, x, F0)

    def _start_from(self, t, v, a, load, x, F0=None) -> np.ndarray:
        """:meth:`record_start_state` of validated kernel inputs (see :meth:`_inputs`)."""
        n = len(self.state_names)
        if n == 0 or v.size == 0:
            return self.initial_state()
        v0 = float(v[0])
        first = {k: float(arr[0]) for k, arr in (("a", a), ("load", load), ("x", x))
                 if k in self.extra_inputs and arr.size}
        s = self._motion_start(t, v, a, load, x, first)
        if F0 is None or not math.isfinite(F0):
            return s
        bound = self._deflection_bound(v0, first)
        if not (bound > 0 and math.isfinite(bound)):
            return s
        # the force is affine in the first state: two evaluations give it
        lo, hi = s.copy(), s.copy()
        lo[0], hi[0] = 0.0, bound
        try:
            f_lo = float(self.force(lo, v0, **first))
            slope = (float(self.force(hi, v0, **first)) - f_lo) / bound
        except (ValueError, ZeroDivisionError, FloatingPointError):
            return s
        if slope == 0.0 or not (math.isfinite(slope) and math.isfinite(f_lo)):
            return s
        s[0] = min(max((F0 - f_lo) / slope, -bound), bound)
        return s

    def _motion_start(self, t, v, a, load, x, first) -> np.ndarray:
        """The state from the first samples of the motion alone (:meth:`record_start_state`
        without ``F``)."""
        v0 = float(v[0])
        if v0 == 0.0:
            return self.initial_state()
        acc = (float(v[1]) - v0) / float(t[1] - t[0]) if v.size > 1 else 0.0
        if not acc * v0 > 0.0:
            return self.steady_state_state(v0, **first)
        # speeding up: a warm-up from rest at the first acceleration, through the law
        T = v0 / acc
        tw = np.linspace(0.0, T, WARM_UP_SAMPLES)
        vw = acc * tw
        held = lambda arr: np.full(tw.size, float(arr[0])) if arr.size else np.zeros(0)
        aw = np.full(tw.size, acc) if a.size else np.zeros(0)
        # the displacement runs up to x[0] along the ramp (a spring reads it)
        xw = float(x[0]) - 0.5 * acc * (T * T - tw * tw) if x.size else np.zeros(0)
        _, S = self._kernel(tw, vw, aw, held(load), xw, self.theta, METHODS["exact"],
                            self.initial_state())
        s = np.array(S[-1], dtype=float)
        return s if np.all(np.isfinite(s)) else self.steady_state_state(v0, **first)

    def _deflection_bound(self, v0, first) -> float:
        """Largest |first state| of the law's steady states (the bristle's saturation,
        max(Fs, Fc) / sigma0 for the LuGre family) at the first sample's inputs: at a
        vanishing speed, at ``v0`` and far above it, both directions."""
        speeds = (1e-200, abs(v0), 1e3 * max(abs(v0), 1.0))
        vals = [abs(float(self.steady_state_state(sgn * sp, **first)[0]))
                for sp in speeds for sgn in (1.0, -1.0) if sp > 0]
        vals = [val for val in vals if math.isfinite(val)]
        return max(vals) if vals else 0.0

    def _inputs(self, t, v, a=None, load=None, x=None):
        t, v, extra = check_signals(t, v, a=a, load=load, x=x)
        a, load, x = extra["a"], extra["load"], extra["x"]
        if "a" in self.extra_inputs and a is None:
            a = np.gradient(v, t)  # derived acceleration, as the CSV contract allows
        if "x" in self.extra_inputs and x is None:
            # integrate v (trapezoid) from 0 when no displacement is given
            x = np.concatenate(([0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(t))))
        if "load" in self.extra_inputs and load is None:
            raise ValueError(f"{self.name} needs the load= array (normal/deformation load [N])")
        empty = np.zeros(0)
        return (t, v, a if a is not None else empty, load if load is not None else empty,
                x if x is not None else empty)

    def simulate(self, t, v, *, a=None, load=None, x=None, method: str = "exact",
                 state0=None, return_state: bool = False):
        """Friction force along a prescribed motion.

        Parameters
        ----------
        t : array_like, shape (N,)
            Time [s], strictly increasing (need not be uniform).
        v : array_like, shape (N,)
            Sliding velocity [m/s].
        a, load, x : array_like, shape (N,), optional
            Acceleration [m/s^2], normal/deformation load [N], displacement [m], for laws
            that need them (``extra_inputs``).
        method : {"exact", "euler"}
            Bristle update. ``exact`` is stable at any step size.
        state0 : array_like or "steady", optional
            Initial state (default zeros: at rest). ``"steady"``: the state consistent
            with the first sample, the law's steady state at the first velocity
            (:meth:`record_start_state`), for a record that starts in motion.
        return_state : bool
            Also return the state trajectory, shape (N, n_states).

        Returns
        -------
        F : ndarray, shape (N,)
            Friction force [N] at each sample.
        """
        if method not in METHODS:
            raise ValueError(f"method must be one of {sorted(METHODS)}, got {method!r}")
        t, v, a, load, x = self._inputs(t, v, a, load, x)
        if isinstance(state0, str):
            if state0 != "steady":
                raise ValueError(f"state0 = {state0!r}: give an array or 'steady'")
            s0 = self._start_from(t, v, a, load, x)
        else:
            s0 = self.initial_state() if state0 is None else np.asarray(state0, float).ravel()
        if s0.size != len(self.state_names):
            raise ValueError(f"state0 must have {len(self.state_names)} entries "
                             f"{self.state_names}, got {s0.size}")
        F, S = self._kernel(t, v, a, load, x, self.theta, METHODS[method], s0)
        return (F, S) if return_state else F

    # -- populations (identification fast path) -----------------------------------------
    def free_names(self) -> list[str]:
        """Numeric parameters that identification may vary (twins that are None excluded)."""
        return [n for n in self.Params.numeric_names() if getattr(self.params, n) is not None]

    def population_theta(self, names, X) -> np.ndarray:
        """Packed theta rows for a population of parameter vectors.

        Parameters
        ----------
        names : sequence of str
            Parameter names, one per column of ``X``.
        X : array_like, shape (npop, len(names))
            Parameter values.

        A symmetric law's parameter (its ``_neg`` twin left None) also sets the twin.
        """
        X = np.atleast_2d(np.asarray(X, dtype=np.float64))
        names = list(names)
        if X.shape[1] != len(names):
            raise ValueError(f"X has {X.shape[1]} columns for {len(names)} names")
        Theta = np.repeat(self.theta[None, :], X.shape[0], axis=0)
        layout = {n: i for i, n in enumerate(self.theta_layout)}
        for j, n in enumerate(names):
            if n not in layout:
                raise KeyError(f"{self.name} has no packed parameter {n!r}; "
                               f"choose from {list(self.theta_layout)}")
            Theta[:, layout[n]] = X[:, j]
            twin = self.twins.get(n)
            if twin is not None and getattr(self.params, twin, None) is None \
                    and twin not in names:
                Theta[:, layout[twin]] = X[:, j]
        return Theta

    def simulate_population(self, t, v, names, X, *, a=None, load=None, x=None,
                            method: str = "exact") -> np.ndarray:
        """Simulate many parameter sets at once: returns ``F[npop, N]`` [N].

        The kernel runs the population in parallel (numba ``prange``; row by row where
        :data:`SERIAL_POPULATIONS` is set). Parameter vectors
        are not bound-checked here (the optimiser keeps them inside its box); rows whose
        values are inadmissible may give NaN, which objectives treat as +inf cost.

        Parameters
        ----------
        t, v : array_like, shape (N,)
            Time [s] (strictly increasing) and velocity [m/s] of the prescribed motion.
        names : sequence of str
            The parameters the columns of ``X`` set (the others keep this model's values).
        X : array_like, shape (npop, len(names))
            One parameter set per row, in the units of the parameters.
        a, load, x : array_like, shape (N,), optional
            Acceleration [m/s^2], load [N], displacement [m] where the law needs them.
        method : {"exact", "euler"}
            Bristle update (:data:`METHODS`).
        """
        if method not in METHODS:
            raise ValueError(f"method must be one of {sorted(METHODS)}, got {method!r}")
        t, v, a, load, x = self._inputs(t, v, a, load, x)
        Theta = self.population_theta(names, X)
        if SERIAL_POPULATIONS:
            s0 = self.initial_state()
            F = np.empty((Theta.shape[0], t.size))
            for i in range(Theta.shape[0]):
                F[i] = self._kernel(t, v, a, load, x, Theta[i], METHODS[method], s0)[0]
            return F
        return self._population_kernel(t, v, a, load, x, Theta, METHODS[method])

    def with_values(self, **values) -> "FrictionModel":
        """A copy of this model with some parameters changed (validated).

        Parameters
        ----------
        **values
            Parameter values (SI units) by name; an unknown name is a TypeError, a value out of
            its bounds a :class:`ParameterError`.
        """
        return type(self)(self.params.replace(**values))


# the base's own steady_state_state refuses unknown inputs too (a law without states
# returns before it calls derivatives)
FrictionModel.steady_state_state = _checked_inputs(FrictionModel.steady_state_state)
