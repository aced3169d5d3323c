"""The pythonfmu slave runtime: the ``Fmi2Slave`` classes that every pythonfmu FMU runs.

This module travels inside each pythonfmu FMU with :mod:`fmus.coupling` and
:mod:`fmus.variables` (vendored as the package ``_fl_<fmu>_fmus``, see :mod:`fmus.build`); it
needs only ``pythonfmu`` (bundled by the builder), numpy, and the vendored ``friction`` /
``plants`` copies whose module names the generated slave script passes in. It must not import
frictionlab, scipy or matplotlib.

Five slave kinds share one base (:class:`SlaveBase`):

* :class:`LawSlave` - a friction law from ``friction.MODELS``. Inputs ``v`` [m/s] (and
  ``a``, ``load``, ``x`` when the law needs them), outputs ``F`` [N] (direct feedthrough
  of the inputs), the coupling outputs (:mod:`fmus.coupling`) and the law's states.
* :class:`MassSlave` - a rigid mass driven by a built-in force signal plus the inputs
  ``F_ext`` and ``F_friction`` (the mass+friction proof loop).
* :class:`EffectsSlave` - the ``friction_effects`` block (``friction.extensions``).
* :class:`StepperSlave` - a plant of the ``plants`` package in external-friction mode through
  its ``stepper()`` (numpy/numba only);
* :class:`BlockSlave` - a discrete block of the XML-350 loop (state-dependent PID, LuGre
  feedforward, S-curve trajectory) through ``plants.controllers.DiscreteStepper``.

The variable list of a slave (:mod:`fmus.variables`) is the single source for both the runtime
and the ``modelDescription.xml`` written by ``fmus.build``: the value reference of a variable
is its index in that list. Options are Enumerations (set with ``fmi2SetInteger``, codes
1..n), an optional parameter is used when its Boolean ``use_<name>`` is true.

Bad input: a NaN/inf on any input or parameter, a parameter outside its bounds or an
Enumeration code that is not an item is never stored: the setter logs it at error level
naming the variable and its bound and keeps the previous value, so the call returns
``fmi2Error`` and the instance keeps working. ``fmi2DoStep`` with a step size that is not
finite and > 0 is refused the same way. The status comes from the FMU's status shim
(``fmus/shim``, in front of pythonfmu's binary on linux64 and win64): a call during which the
slave logged an error returns ``fmi2Error``. The slaves never raise, because pythonfmu 0.7
turns an exception into ``fmi2Fatal`` and destroys the instance (and leaves the embedding
interpreter corrupt: a later garbage collection segfaults). An inadmissible parameter
combination (found when the model is built), a failed output evaluation or a step that would
produce a non-finite output is logged at error level by the call that finds it, and every
later ``fmi2DoStep`` is refused (``do_step`` returns False) with the message again; these give
``fmi2Error`` too. Without the shim (an FMU built without a C compiler for linux64 or without
MinGW-w64 for win64) the statuses are pythonfmu's: the call that logs answers ``fmi2OK``, so a
rejected value also refuses the next ``fmi2DoStep``, with ``fmi2Discard``.

FMU state: ``fmi2GetFMUstate`` / ``fmi2SetFMUstate`` (pythonfmu calls ``_get_fmu_state`` /
``_set_fmu_state``) save and restore everything a step depends on - the variable values, the
time, the law's state and input history, the parameters the model was built from - so a
rollback and redo repeats the first run bit for bit; the state serializes to JSON (exact
floats) and restores into another instance of the same FMU. A kind that cannot save its state
(:attr:`SlaveBase.can_get_state` false: the plants and loop blocks, whose steppers hold
numba-compiled state) answers ``fmi2Error`` with a message instead, and its model description
says ``canGetAndSetFMUstate="false"``.
"""
from __future__ import annotations

import dataclasses
import importlib
import json
import math
import operator
import os
import sys

import numpy as np
from pythonfmu import Fmi2Causality, Fmi2Slave, Fmi2Variability
from pythonfmu.enums import Fmi2Status
from pythonfmu.variables import Boolean, Integer, Real, String

from .coupling import (COUPLING_OUTPUTS, INPUT_INFO, MEAN_INPUT, SHARE_INPUT,  # noqa: F401
                       SWITCH_OUTPUTS, has_switch, law_inputs, law_linearisation,
                       switch_linearisation)
from .variables import (BLOCKS, EFFECTS_INPUTS, Var, block_variables,  # noqa: F401
                        effects_variables, law_variables, mass_variables, plant_variables)

__all__ = ["SlaveBase", "LawSlave", "MassSlave", "StepperSlave", "BlockSlave", "EffectsSlave",
           "behind_status_shim", "STATE_FORMAT"]

#: tag of a saved FMU state (``_get_fmu_state``), checked when it is restored
STATE_FORMAT = "frictionlab-pythonfmu-state-1"

#: binaries folder and file name suffix of pythonfmu's library behind the status shim
#: (fmus.status_shim), by host platform
_SHIM_INNER = {"linux": ("linux64", "_pythonfmu.so"), "win32": ("win64", "_pythonfmu.dll")}


def behind_status_shim(resources, model_identifier: str) -> bool:
    """True when this FMU runs its linux64 or win64 binary and that binary is the status shim
    (which turns error-level log messages into ``fmi2Error``).

    Parameters
    ----------
    resources : str
        The FMU's resources folder.
    model_identifier : str
        The FMU's model identifier.
    """
    key = "linux" if sys.platform.startswith("linux") else sys.platform
    if key not in _SHIM_INNER or not resources:
        return False
    folder, suffix = _SHIM_INNER[key]
    return os.path.isfile(os.path.join(resources, os.pardir, "binaries", folder,
                                       model_identifier + suffix))


_CAUS = {"parameter": Fmi2Causality.parameter, "input": Fmi2Causality.input,
         "output": Fmi2Causality.output}
# an Enumeration is set and read with fmi2SetInteger / fmi2GetInteger
_TYPES = {"Real": Real, "Integer": Integer, "Boolean": Boolean, "String": String,
          "Enumeration": Integer}


class SlaveBase(Fmi2Slave):
    """Value store, bound checks and error reporting shared by all frictionlab slaves.

    Subclasses set ``model_identifier`` and implement ``make_variables``, ``rebuild``
    (parameters changed), ``compute_outputs`` (fill output values from state + inputs) and
    ``advance(t, h)``.
    """
    model_identifier = "frictionlab"
    fmu_description = ""
    #: the kind can save and restore its whole state (fmi2GetFMUstate / fmi2SetFMUstate)
    can_get_state = True

    def __init__(self, **kwargs):
        """The slave with its variables registered and their start values set.

        Parameters
        ----------
        **kwargs
            What pythonfmu's runtime passes to ``Fmi2Slave`` (``instance_name``,
            ``resources``, ...).
        """
        super().__init__(**kwargs)
        self.modelName = self.model_identifier
        self.description = self.fmu_description
        self.variables = self.make_variables()
        self.values = [v.start for v in self.variables]
        self.index = {v.name: i for i, v in enumerate(self.variables)}
        self.roles = [v.causality for v in self.variables]
        self.param_idx = [i for i, r in enumerate(self.roles) if r == "parameter"]
        #: the parameter values the model was last built from (None: not built)
        self._built = None
        self.output_idx = [i for i, r in enumerate(self.roles) if r == "output"]
        #: the output values as a tuple (one C call: do_step's finiteness test)
        idx = self.output_idx
        self.output_values = operator.itemgetter(*idx) if len(idx) > 1 else \
            (lambda vals, i=idx[0]: (vals[i],)) if idx else (lambda vals: ())
        #: per value reference: a Real input (set_real's fast path)
        self.fast_input = [v.causality == "input" and v.type == "Real" for v in self.variables]
        for i, v in enumerate(self.variables):
            var_cls = _TYPES[v.type]
            variability = (Fmi2Variability.tunable if v.causality == "parameter"
                           else Fmi2Variability.continuous if v.type == "Real"
                           else Fmi2Variability.discrete)
            self.register_variable(var_cls(
                v.name, causality=_CAUS[v.causality], variability=variability,
                description=v.description,
                getter=(lambda i=i: self.values[i]),
                setter=(lambda value, i=i: self.values.__setitem__(i, value))),
                nested=False)
        self.params_dirty = True
        self.outputs_dirty = True
        #: failures that refuse every step until fixed: "parameters" (model cannot be
        #: built), "outputs" (evaluation failed), "step" (a step failed; until reset)
        self.failed: dict[str, str] = {}
        #: without the status shim only: rejected values, refusing the next step
        self.pending: dict[str, str] = {}
        self.status_shim = behind_status_shim(self.resources, self.model_identifier)
        self.time = 0.0

    # subclasses ---------------------------------------------------------------------------
    def make_variables(self) -> list[Var]:  # pragma: no cover - abstract
        raise NotImplementedError

    def rebuild(self, initial: bool) -> None:  # pragma: no cover - abstract
        """Build the model from the current parameter values (ParameterError if refused).

        Parameters
        ----------
        initial : bool
            Called at initialization (else after a parameter changed later).
        """
        raise NotImplementedError

    def compute_outputs(self) -> None:  # pragma: no cover - abstract
        raise NotImplementedError

    def advance(self, t: float, h: float) -> bool:  # pragma: no cover - abstract
        """Integrate [t, t+h] with the inputs held; return True if the outputs at t+h were
        set as well (otherwise ``compute_outputs`` runs).

        Parameters
        ----------
        t : float
            Current communication point [s].
        h : float
            Communication step [s].
        """
        raise NotImplementedError

    # helpers ------------------------------------------------------------------------------
    def log(self, msg, status=Fmi2Status.ok, category=None, debug=None):
        # pythonfmu hands the message to the FMI logger as a printf format without
        # arguments: a literal '%' (e.g. "about 2 %" in a description) is doubled, or a
        # formatting logger (fmpy's default one uses vsnprintf) reads past its arguments
        super().log(msg.replace("%", "%%"), status, category)

    def reject(self, key: str, message: str) -> None:
        """Log a rejected value at error level (the call returns ``fmi2Error`` behind the
        status shim); without the shim the next step is refused as well (``fmi2Discard``).

        Parameters
        ----------
        key : str
            What was rejected (the variable name).
        message : str
            The log message.
        """
        msg = f"{self.instance_name}: {message}"
        self.log(msg, Fmi2Status.error)
        if not self.status_shim:
            self.pending[key] = msg

    def fail(self, key: str, message: str) -> None:
        """Record a failure that refuses every step until cleared (see ``failed``); the
        FMI call that found it reports it with :meth:`report`.

        Parameters
        ----------
        key : str
            What failed (cleared by the same key).
        message : str
            The log message.
        """
        self.failed[key] = f"{self.instance_name}: {message}"

    def report(self, what: str) -> None:
        """Log every recorded failure at error level, saying what it prevents.

        Parameters
        ----------
        what : str
            What the failure prevents (the FMI call).
        """
        for msg in self.failed.values():
            self.log(f"{msg} ({what})", Fmi2Status.error)

    def param_values(self) -> dict:
        """Every parameter as a Python value: an Enumeration as its item name, an optional
        parameter as None while its ``use_<name>`` flag is off (the flags as Booleans)."""
        out = {}
        vals = self.values
        flags = {v.twin_of: vals[i] for i, v in enumerate(self.variables) if v.twin_of}
        for i in self.param_idx:
            v, value = self.variables[i], vals[i]
            if v.type == "Enumeration":
                value = v.items[int(value) - 1]
            elif v.type == "Boolean":
                value = bool(value)
            elif v.name in flags and not flags[v.name]:
                value = None
            out[v.name] = value
        return out

    def field_values(self) -> dict:
        """The parameters that are fields of the slave's Params dataclass
        (:meth:`param_values` without the flags and the FMU's own parameters)."""
        pv = self.param_values()
        return {v.name: pv[v.name] for v in self.variables
                if v.causality == "parameter" and v.field >= 0 and not v.twin_of}

    def value(self, name: str):
        """Current value of a variable.

        Parameters
        ----------
        name : str
            Variable name.
        """
        return self.values[self.index[name]]

    def _ensure_model(self, initial: bool = False) -> bool:
        if self.params_dirty:
            try:
                self.rebuild(initial)
            except Exception as exc:  # noqa: BLE001 - ParameterError names the parameter
                self.fail("parameters", f"invalid parameters: {type(exc).__name__}: {exc}")
                return False
            self.failed.pop("parameters", None)
            self.params_dirty = False
            self._built = [self.values[i] for i in self.param_idx]
            self.outputs_dirty = True
        return "parameters" not in self.failed

    def _update_outputs(self) -> bool:
        if not self._ensure_model():
            return False
        try:
            self.compute_outputs()
        except Exception as exc:  # noqa: BLE001
            self.fail("outputs", f"output evaluation failed: {type(exc).__name__}: {exc}")
            return False
        self.failed.pop("outputs", None)
        self.outputs_dirty = False
        return True

    # FMI ----------------------------------------------------------------------------------
    def setup_experiment(self, start_time, stop_time=None, tolerance=None):
        self.time = float(start_time)

    def exit_initialization_mode(self):
        self._ensure_model(initial=True)
        if self.failed:
            self.report("initialization")

    def do_step(self, current_time, step_size):
        if not (step_size > 0.0 and step_size - step_size == 0.0) or \
                current_time - current_time != 0.0:
            # h <= 0, NaN or inf (or a non-finite communication point): refused, the
            # instance stays where it was (fmi2Error behind the status shim)
            self.log(f"{self.instance_name}: fmi2DoStep refused: the communication step "
                     f"size (communicationStepSize) h = {step_size!r} at t = "
                     f"{current_time!r} must be finite and > 0 (and the communication point "
                     f"finite); the instance stays at t = {self.time!r}", Fmi2Status.error)
            return False
        if self.params_dirty:
            self._ensure_model()  # a fixed parameter clears its failure here
        if self.failed or self.pending:
            what = f"step at t = {current_time:g} refused"
            self.report(what)
            for msg in self.pending.values():
                self.log(f"{msg} ({what})", Fmi2Status.error)
            return False
        try:
            done = self.advance(current_time, step_size)
        except Exception as exc:  # noqa: BLE001 - never let an exception become fmi2Fatal
            self.fail("step", f"step [{current_time:g}, +{step_size:g}] failed: "
                              f"{type(exc).__name__}: {exc}")
            self.report("the instance refuses further steps")
            return False
        self.time = current_time + step_size
        if done:  # advance() already set the outputs for the held inputs
            self.outputs_dirty = False
        elif not self._update_outputs():
            self.report(f"step to t = {self.time:g}")
            return False
        values = self.values
        total = sum(self.output_values(values))  # inf/NaN if an output is (or on overflow)
        if total - total != 0.0:
            for i in self.output_idx:
                if not math.isfinite(values[i]):
                    self.fail("step", f"output {self.variables[i].name} = {values[i]!r} is "
                                      f"not finite after the step to t = {self.time:g}")
                    self.report("the instance refuses further steps")
                    return False
        return True

    def _check_set(self, vr, value):
        v = self.variables[vr]
        role = self.roles[vr]
        if role == "output":
            self.reject(v.name, f"{v.name} is an output and cannot be set; {value!r} ignored")
            return
        bounded = False
        if v.type == "Enumeration":
            if isinstance(value, float) and value == int(value):
                value = int(value)
            bounded = True
        elif v.type == "Boolean":
            value = bool(value)
        elif v.type == "Real":
            value = float(value)
            if not math.isfinite(value):
                self.reject(v.name, f"{role} {v.name} = {value!r} is not finite "
                                    f"({v.description}); value rejected, {v.name} keeps "
                                    f"{self.values[vr]!r}")
                return
            bounded = role == "parameter"
        if bounded and not v.admissible(value):
            unit = f" [{v.unit}]" if v.type == "Real" else ""
            self.reject(v.name, f"{role} {v.name} = {value!r} is out of bounds: must be "
                                f"{v.bound_text()}{unit} ({v.description}); value rejected, "
                                f"{v.name} keeps {self.values[vr]!r}")
            return
        self.pending.pop(v.name, None)
        self.values[vr] = value
        if role == "parameter":
            self.params_dirty = True
        self.outputs_dirty = True

    # An exception escaping to pythonfmu 0.7 gives fmi2Fatal and leaves the embedding
    # interpreter corrupt (a later garbage collection segfaults), so even an invalid value
    # reference is caught here and logged as an error (fmi2Error behind the status shim).
    def _bad_call(self, call, vrs, exc):
        self.log(f"{self.instance_name}: {call} with value references {list(vrs)} failed "
                 f"(valid: 0..{len(self.variables) - 1}): {type(exc).__name__}: {exc}",
                 Fmi2Status.error)

    def set_values(self, vrs, values):
        """Set any variables, each checked by ``_check_set``.

        Parameters
        ----------
        vrs : sequence of int
            Value references.
        values : sequence
            The values, one per reference.
        """
        try:
            for vr, value in zip(vrs, values):
                self._check_set(vr, value)
        except (IndexError, TypeError, ValueError) as exc:
            self._bad_call("set", vrs, exc)

    def set_real(self, vrs, values):
        # fast path for finite Real inputs (every communication step); everything else,
        # and every value while a refusal is pending, goes through _check_set
        if self.pending:
            self.set_values(vrs, values)
            return
        fast, vals = self.fast_input, self.values
        try:
            for vr, value in zip(vrs, values):
                if fast[vr] and value - value == 0.0:  # 0.0 exactly when value is finite
                    vals[vr] = value
                else:
                    self._check_set(vr, value)
        except (IndexError, TypeError, ValueError) as exc:
            self._bad_call("fmi2SetReal", vrs, exc)
        self.outputs_dirty = True

    set_integer = set_values
    set_boolean = set_values
    set_string = set_values

    def get_real(self, vrs):
        if self.outputs_dirty:
            self._update_outputs()
        if self.failed:  # the values may be stale or non-finite: say so (fmi2Error)
            self.report("values read by fmi2GetReal are not valid")
        values = self.values
        try:
            return [float(values[vr]) for vr in vrs]
        except (IndexError, TypeError, ValueError) as exc:
            self._bad_call("fmi2GetReal", vrs, exc)
            return [math.nan] * len(vrs)

    def _get_as(self, call, kind, vrs, bad):
        try:
            return [kind(self.values[vr]) for vr in vrs]
        except (IndexError, TypeError, ValueError) as exc:
            self._bad_call(call, vrs, exc)
            return [bad] * len(vrs)

    def get_integer(self, vrs):
        return self._get_as("fmi2GetInteger", int, vrs, 0)

    def get_boolean(self, vrs):
        return self._get_as("fmi2GetBoolean", bool, vrs, False)

    def get_string(self, vrs):
        return self._get_as("fmi2GetString", str, vrs, "")

    # FMU state (pythonfmu 0.7 calls these for fmi2GetFMUstate / fmi2SetFMUstate and the
    # class's _fmu_state_to_bytes / _fmu_state_from_bytes for (de)serialization) ----------
    def dynamic_state(self):
        """What a step changes beyond the variable values and the time, as JSON-able data
        (a copy); None while no model was built. Subclasses extend it."""
        return None if self._built is None else {}

    def restore_dynamic(self, data) -> None:
        """Restore :meth:`dynamic_state` data (None: as before the first build).

        Parameters
        ----------
        data : dict or None
            What :meth:`dynamic_state` returned.
        """

    def _state_refused(self, call: str) -> None:
        self.log(f"{self.instance_name}: {call} refused: this FMU ({self.model_identifier}) "
                 f"cannot save and restore its state (canGetAndSetFMUstate = false)",
                 Fmi2Status.error)

    def _get_fmu_state(self):
        if not self.can_get_state:
            self._state_refused("fmi2GetFMUstate")
            return {"format": STATE_FORMAT, "invalid": "no state saved (not supported)"}
        try:
            return {"format": STATE_FORMAT, "fmu": self.model_identifier,
                    "values": list(self.values), "time": self.time,
                    "failed": dict(self.failed), "pending": dict(self.pending),
                    "params_dirty": self.params_dirty, "outputs_dirty": self.outputs_dirty,
                    "built": None if self._built is None else list(self._built),
                    "dynamic": self.dynamic_state()}
        except Exception as exc:  # noqa: BLE001 - never raise into pythonfmu
            msg = f"fmi2GetFMUstate failed: {type(exc).__name__}: {exc}"
            self.log(f"{self.instance_name}: {msg}", Fmi2Status.error)
            return {"format": STATE_FORMAT, "invalid": msg}

    def _set_fmu_state(self, state):
        if not self.can_get_state:
            self._state_refused("fmi2SetFMUstate")
            return
        try:
            why = None
            if not isinstance(state, dict) or state.get("format") != STATE_FORMAT or \
                    "invalid" in state:
                why = (f"not a state saved by a frictionlab FMU "
                       f"({isinstance(state, dict) and state.get('invalid') or 'unknown format'})")
            elif state.get("fmu") != self.model_identifier or \
                    len(state["values"]) != len(self.variables):
                why = (f"the state was saved by another FMU ({state.get('fmu')!r}), not by "
                       f"{self.model_identifier!r}")
            if why is not None:
                self.log(f"{self.instance_name}: fmi2SetFMUstate refused: {why}; the instance "
                         f"is unchanged", Fmi2Status.error)
                return
            built = state["built"]
            if built is not None and built != self._built:
                # the model the state was stepped with: build it from those parameters
                values = list(state["values"])
                for i, val in zip(self.param_idx, built):
                    values[i] = val
                self.values = values
                self.rebuild(True)
            self.values = list(state["values"])
            self._built = None if built is None else list(built)
            self.time = state["time"]
            self.failed = dict(state["failed"])
            self.pending = dict(state["pending"])
            self.params_dirty = state["params_dirty"]
            self.outputs_dirty = state["outputs_dirty"]
            self.restore_dynamic(state["dynamic"])
        except Exception as exc:  # noqa: BLE001 - never raise into pythonfmu
            self.fail("state", f"fmi2SetFMUstate failed: {type(exc).__name__}: {exc}")
            self.report("the instance refuses further steps")

    @staticmethod
    def _fmu_state_to_bytes(state) -> bytes:
        # JSON writes a float as its shortest round-trip repr (NaN/inf too): exact
        return json.dumps(state, default=float).encode("utf-8")

    @staticmethod
    def _fmu_state_from_bytes(data: bytes):
        try:
            state = json.loads(data.decode("utf-8"))
        except Exception:  # noqa: BLE001 - never raise into pythonfmu
            state = None
        if not isinstance(state, dict):
            return {"format": STATE_FORMAT, "invalid": "not a serialized frictionlab state"}
        return state


class LawSlave(SlaveBase):
    """FMU of one friction law (``law`` = registry name in ``<friction_package>.MODELS``).

    Inputs are held constant over a communication step (zero-order hold; with the
    parameter ``inputs_at_step_end`` the step runs from the previous inputs to the current
    ones, first-order hold); the state is advanced by the law's own stable kernel (exact
    exponential bristle update), so any step size is stable. ``F`` is evaluated from the
    current state and the current inputs (direct feedthrough), as the law's ``simulate``
    does at a sample. With ``h_lin > 0`` the outputs ``dF_dx, dF_dv, dF_dt, d2F_dt2`` give
    the law's linearisation over the coming step (:func:`law_linearisation`) for a plant
    that integrates the stiff contact itself (``plants.base.PlantStepper``).
    """
    law = "lugre"
    friction_package = "friction"

    @classmethod
    def model_class(cls):
        return importlib.import_module(cls.friction_package).MODELS[cls.law]

    def make_variables(self):
        return law_variables(self.model_class())

    def rebuild(self, initial):
        cls = self.model_class()
        model = cls(cls.Params(**self.field_values()))
        self.model = model
        self.theta = np.ascontiguousarray(model.theta, dtype=np.float64)
        self.kernel = model._kernel
        if initial or not hasattr(self, "state"):
            self.state = np.asarray(model.initial_state(), dtype=np.float64).copy()
        ins = law_inputs(cls)
        self.in_idx = [self.index[n] for n in ins]
        self.F_idx = self.index["F"]
        self.state_idx = [self.index[s] for s in cls.state_names]
        empty = np.zeros(0)
        self.t1 = np.zeros(1)
        self.t2 = np.zeros(2)
        self.buf1 = {n: (np.zeros(1) if n in ins else empty) for n in ("v", "a", "load", "x")}
        self.buf2 = {n: (np.zeros(2) if n in ins else empty) for n in ("v", "a", "load", "x")}
        self.names = ins
        # per step: (buffer, value index) pairs to fill and the kernel's leading arguments
        self.fill1 = [(self.buf1[n], i) for n, i in zip(ins, self.in_idx)]
        self.fill2 = [(self.buf2[n], i) for n, i in zip(ins, self.in_idx)]
        self.args1 = (self.t1,) + tuple(self.buf1[n] for n in ("v", "a", "load", "x"))
        self.args2 = (self.t2,) + tuple(self.buf2[n] for n in ("v", "a", "load", "x"))
        self.lin_idx = [self.index[n] for n in COUPLING_OUTPUTS]
        self.switch = None       # a regime switch: (vc, {"low": theta, "high": theta})
        if has_switch(cls):
            split = model.regimes()
            self.switch = (float(split.vc),
                           {r: np.ascontiguousarray(getattr(split, r).theta, dtype=np.float64)
                            for r in ("low", "high")})
            self.lin_idx += [self.index[n] for n in SWITCH_OUTPUTS]
            self.share_idx = self.index[SHARE_INPUT]
            self.use_share = bool(self.values[self.index["use_low_share"]])
        self.lin_zeroed = False  # h_lin = 0: the coupling outputs are written once
        self.h_lin = float(self.values[self.index["h_lin"]])
        self.foh = bool(self.values[self.index["inputs_at_step_end"]])
        self.mean_idx = (self.index[MEAN_INPUT]
                         if cls.state_names and self.values[self.index["use_v_mean"]] else None)
        if initial or not hasattr(self, "last_in"):
            self.last_in = None    # inputs at the last communication point
            self.slope_v = 0.0     # dv/dt at the last input sample [m/s^2]
            self.curv_v = 0.0      # d2v/dt2 of the last three input samples [m/s^3]
            self.dv_last = None    # last backward difference of v [m/s]
            self.stepped = False

    def dynamic_state(self):
        if self._built is None or not hasattr(self, "state"):
            return None
        return {"state": self.state.tolist(),
                "last_in": None if self.last_in is None else list(self.last_in),
                "slope_v": self.slope_v, "curv_v": self.curv_v, "dv_last": self.dv_last,
                "stepped": self.stepped, "lin_zeroed": self.lin_zeroed}

    def restore_dynamic(self, data):
        if data is None:  # as before the first build: the next build starts afresh
            for name in ("state", "last_in"):
                self.__dict__.pop(name, None)
            return
        self.state = np.array(data["state"], dtype=np.float64)
        self.last_in = None if data["last_in"] is None else list(data["last_in"])
        self.slope_v, self.curv_v = data["slope_v"], data["curv_v"]
        self.dv_last, self.stepped = data["dv_last"], data["stepped"]
        self.lin_zeroed = data["lin_zeroed"]

    def _inputs(self) -> list:
        vals = self.values
        return [vals[i] for i in self.in_idx]

    def _linearise(self):
        """Coupling outputs at the current state and inputs (0 if h_lin = 0)."""
        if self.h_lin > 0.0:
            inputs = dict(zip(self.names, self._inputs()))
            if self.switch is not None:
                lin = switch_linearisation(self.kernel, self.switch[1], self.switch[0],
                                           self.state, inputs, self.h_lin, self.slope_v,
                                           self.curv_v)
            else:
                lin = law_linearisation(self.kernel, self.theta, self.state, inputs,
                                        self.h_lin, self.slope_v, self.curv_v)
        elif self.lin_zeroed:
            return  # constant zeros, already written (per-step cost of the plain loops)
        else:
            lin = (0.0,) * len(self.lin_idx)
            self.lin_zeroed = True
        for i, val in zip(self.lin_idx, lin):
            self.values[i] = float(val)

    def _fill(self, pairs):
        vals = self.values
        for buf, i in pairs:
            buf.fill(vals[i])

    def compute_outputs(self):
        self._fill(self.fill1)
        F, _ = self.kernel(*self.args1, self.theta, 0, self.state)
        vals = self.values
        vals[self.F_idx] = F.item(0)
        for i, z in zip(self.state_idx, self.state.tolist()):
            vals[i] = z
        if not self.stepped:
            self.last_in = self._inputs()  # the start of the first step
        self._linearise()

    def advance(self, t, h):
        if self.state.size == 0:
            return False  # a static map: nothing to integrate
        self._fill(self.fill2)
        if self.h_lin > 0.0 or self.foh:
            now = self._inputs()
            if self.last_in is not None:
                # Newton backward polynomial through the last three samples of v
                d1 = now[0] - self.last_in[0]
                d2 = 0.0 if self.dv_last is None else d1 - self.dv_last
                self.slope_v = (d1 + 0.5 * d2) / h
                self.curv_v = d2 / (h * h)
                self.dv_last = d1
                if self.foh:  # first-order hold: the step starts at the last inputs
                    for n, v0 in zip(self.names, self.last_in):
                        self.buf2[n][0] = v0
            self.last_in = now
        self.stepped = True
        self.t2[1] = h
        v_end = None
        if self.mean_idx is not None:
            # the state follows the plant's travel over the step (mean velocity held); the
            # force at the end still sees the velocity at the end
            vbuf = self.buf2["v"]
            v_end = vbuf[1]
            vbuf.fill(self.values[self.mean_idx])
        # the plant's low_share describes this step only when it stepped first (Gauss-Seidel)
        if self.switch is not None and self.foh and self.use_share:
            share = self.values[self.share_idx]
            # the plant says which share of the step lay below v_switch (sliding along it
            # with its Filippov weight): the state advances with that mix of both regimes
            thetas = self.switch[1]
            S = (share * self.kernel(*self.args2, thetas["low"], 0, self.state)[1]
                 + (1.0 - share) * self.kernel(*self.args2, thetas["high"], 0, self.state)[1])
            self._fill(self.fill1)
            F = np.array([0.0, self.kernel(*self.args1, self.theta, 0, S[1])[0].item(0)])
        else:
            F, S = self.kernel(*self.args2, self.theta, 0, self.state)
            if v_end is not None:
                self._fill(self.fill1)
                F = np.array([0.0, self.kernel(*self.args1, self.theta, 0, S[1])[0].item(0)])
        new = S[1].tolist()
        for j, zj in enumerate(new):
            if zj - zj != 0.0:  # inf or NaN: the state is kept as it was
                raise ValueError(f"state {self.model.state_names[j]} = {zj!r} became non-finite")
        vals, state = self.values, self.state
        for j, (i, zj) in enumerate(zip(self.state_idx, new)):
            vals[i] = zj
            state[j] = zj  # in place: no array per step
        # the kernel's force at the second sample: new state, inputs at the step's end
        vals[self.F_idx] = F.item(1)
        self._linearise()
        return True




class MassSlave(SlaveBase):
    """A rigid mass, m dv/dt = u0 + u_amp sin(2 pi u_freq t) + F_ext - F_friction.

    The inputs are held over the step and the sinusoid is integrated in closed form, so the
    step is exact for held inputs; ``a`` is the acceleration at the current time with the
    current inputs (direct feedthrough of ``F_friction`` and ``F_ext``).
    """
    model_identifier = "fl_mass"
    fmu_description = "Rigid mass driven by a sinusoidal force against an external friction force"

    def make_variables(self):
        return mass_variables()

    def rebuild(self, initial):
        p = self.param_values()
        if not p["m"] > 0:
            raise ValueError(f"m = {p['m']!r} is out of bounds: must be > 0 [kg]")
        self.p = p
        # per step: plain attributes and value slots instead of dict look-ups
        self.m, self.u0, self.u_amp = p["m"], p["u0"], p["u_amp"]
        self.w = 2.0 * math.pi * p["u_freq"]
        ix = self.index
        self.slots = (ix["x"], ix["v"], ix["a"], ix["F_ext"], ix["F_friction"])
        if initial or not hasattr(self, "x"):
            self.x, self.v = float(p["x0"]), float(p["v0"])

    def dynamic_state(self):
        if self._built is None or not hasattr(self, "x"):
            return None
        return {"x": self.x, "v": self.v}

    def restore_dynamic(self, data):
        if data is None:
            self.__dict__.pop("x", None)
            return
        self.x, self.v = data["x"], data["v"]

    def drive(self, t):
        """The sinusoidal drive force u0 + u_amp sin(w t) [N].

        Parameters
        ----------
        t : float
            Time [s].
        """
        return self.u0 + self.u_amp * math.sin(self.w * t)

    def compute_outputs(self):
        vals = self.values
        i_x, i_v, i_a, i_ext, i_fr = self.slots
        vals[i_x] = self.x
        vals[i_v] = self.v
        vals[i_a] = (self.drive(self.time) + vals[i_ext] - vals[i_fr]) / self.m

    def advance(self, t, h):
        vals = self.values
        _, _, _, i_ext, i_fr = self.slots
        held = self.u0 + vals[i_ext] - vals[i_fr]
        w = self.w
        if w > 0.0:
            c0, c1 = math.cos(w * t), math.cos(w * (t + h))
            s0, s1 = math.sin(w * t), math.sin(w * (t + h))
            i1 = self.u_amp * (c0 - c1) / w                           # int sin
            i2 = self.u_amp * (h * c0 / w - (s1 - s0) / (w * w))       # double integral
        else:
            i1 = i2 = 0.0
        m = self.m
        self.x = self.x + self.v * h + (0.5 * held * h * h + i2) / m
        self.v = self.v + (held * h + i1) / m
        self.time = t + h
        self.compute_outputs()
        return True


class StepperSlave(SlaveBase):
    """FMU of a plant of the ``plants`` package (external friction: input ``F_friction``)
    through its ``stepper()``; parameters are the plant's ``Params`` and scalar options.

    Parameters are structural for a plant (they shape its state and controllers): changes
    after initialization are applied by rebuilding the stepper only before the first step.
    """
    plant = "xml350"
    plants_package = "plants"
    #: the plant's stepper (numba-compiled state) is not saved: fmi2Get/SetFMUstate refused
    can_get_state = False

    @classmethod
    def plant_class(cls):
        if ":" in cls.plant:  # a plant outside the registry, e.g. "xml350:XML350Mechanics"
            mod, _, name = cls.plant.partition(":")
            return getattr(importlib.import_module(f"{cls.plants_package}.{mod}"), name)
        return importlib.import_module(cls.plants_package).PLANTS[cls.plant]

    def make_variables(self):
        return plant_variables(self.plant_class())

    def rebuild(self, initial):
        if not initial and getattr(self, "stepped", False):
            raise ValueError("plant parameters cannot change after the first step")
        cls = self.plant_class()
        values = self.param_values()
        pnames = {f.name for f in dataclasses.fields(cls.Params)}
        params = {k: v for k, v in values.items() if k in pnames}
        options = {k: v for k, v in values.items() if k not in pnames and k in cls.options}
        plant = cls(external_friction=True, **params)
        self.stepper = plant.stepper(**options)
        self.stepper.reset(self.time)
        self.in_names = list(self.stepper.input_names) + [
            n for n in getattr(self.stepper, "coupling_names", ()) if n in self.index]
        self.out_names = list(self.stepper.output_names)
        self.in_idx = [self.index[n] for n in self.in_names]
        self.out_idx = [self.index[n] for n in self.out_names]
        self.stepped = False

    def _push_inputs(self):
        self.stepper.set_inputs({n: self.values[i] for n, i in zip(self.in_names, self.in_idx)})

    def compute_outputs(self):
        self._push_inputs()
        out = self.stepper.outputs()
        for n, i in zip(self.out_names, self.out_idx):
            self.values[i] = float(out[n])

    def advance(self, t, h):
        self._push_inputs()
        self.stepper.do_step(t, h)
        self.stepped = True
        return False



# -- discrete blocks of the XML-350 loop (controllers, feedforward, trajectory) -------------

class BlockSlave(SlaveBase):
    """FMU of a discrete block of the XML-350 loop (state-dependent PID of seed 003 Eq. 15,
    LuGre feedforward Eq. 16, S-curve trajectory) through ``plants.controllers
    .DiscreteStepper``: the block samples at ``start + k Ts``; reading the outputs at a
    sample instant runs that sample with the inputs just set (direct feedthrough), a step
    runs the samples inside it with the inputs held."""
    block = "sdpid"
    plants_package = "plants"
    #: the block's stepper is not saved: fmi2Get/SetFMUstate refused
    can_get_state = False

    def make_variables(self):
        return block_variables(self.block, self.plants_package)

    def exit_initialization_mode(self):
        # outputs read during initialization may have run the sample at t0 before the
        # inputs were connected: start from a fresh block so t0 samples the final inputs
        self.params_dirty = True
        super().exit_initialization_mode()

    def rebuild(self, initial):
        if not initial and getattr(self, "stepped", False):
            raise ValueError("block parameters cannot change after the first step")
        pk = self.plants_package
        xml = importlib.import_module(f"{pk}.xml350")
        ctrl = importlib.import_module(f"{pk}.controllers")
        vals = self.param_values()
        self.gain = None
        if self.block in ("sdpid", "pid"):
            names = {f.name for f in dataclasses.fields(ctrl.PIDParams)}
            blk = ctrl.PID(ctrl.PIDParams(**{k: v for k, v in vals.items() if k in names}))
            self.gain = vals["M_ctrl"] / vals["Kf"]
        elif self.block == "lugre_feedforward":
            fr = importlib.import_module(pk.replace("_plants", "_friction")
                                         if pk.endswith("_plants") else "friction")
            names = {f.name for f in dataclasses.fields(fr.LuGreParams)}
            law = fr.LuGre(fr.LuGreParams(**{k: v for k, v in vals.items() if k in names}))
            blk = ctrl.LuGreFeedforward(law, vals["mass"], vals["Ts"])
        else:
            src = importlib.import_module(f"{pk}.sources")
            blk = xml.TrajectoryBlock(src.SCurve(vals["distance"], t0=vals["t_move"]),
                                      sample_time=vals["Ts"], f_current=vals["f_current"],
                                      ff_mode=vals["ff_mode"])
        self.stepper = ctrl.DiscreteStepper(blk, start=self.time)
        self.in_names = list(self.stepper.input_names)
        self.in_idx = [self.index[n] for n in self.in_names]
        self.out_names = list(self.stepper.output_names)
        self.out_idx = [self.index[n] for n in self.out_names]
        self.stepped = False

    def _push_inputs(self):
        if self.in_names:
            self.stepper.set_inputs({n: self.values[i]
                                     for n, i in zip(self.in_names, self.in_idx)})

    def compute_outputs(self):
        self._push_inputs()
        out = self.stepper.outputs()
        for n, i in zip(self.out_names, self.out_idx):
            self.values[i] = float(out[n])
        if self.gain is not None:
            self.values[self.index["i_cmd"]] = self.gain * self.values[self.index["u"]]

    def advance(self, t, h):
        self._push_inputs()
        self.stepper.do_step(t, h)
        self.stepped = True
        return False



# -- friction effects block ------------------------------------------------------------------

class EffectsSlave(SlaveBase):
    """FMU block between a friction-law FMU and a plant FMU: ``F = extension_force(F_law, v,
    a, x, load, t, e)`` (``friction.extensions``: the diagnosis' acceleration, load, position
    and drift candidates), evaluated at the communication points; no state but the time."""
    friction_package = "friction"

    def make_variables(self):
        return effects_variables(self.friction_package)

    def rebuild(self, initial):
        ext = importlib.import_module(f"{self.friction_package}.extensions")
        p = self.param_values()
        if p["use_pos"] > 0.5 and not p["x_hi"] > p["x_lo"]:
            raise ValueError(f"x_hi = {p['x_hi']!r} must be > x_lo = {p['x_lo']!r} [m]")
        self.e = np.array([float(p[n]) for n, _, _, _ in ext.EXTENSION_PARAMS])
        self.kernel = ext.extension_force
        self.in_idx = [self.index[n] for n, _, _ in EFFECTS_INPUTS]
        self.out_i = self.index["F"]

    def compute_outputs(self):
        vals = self.values
        F, v, a, x, load = (vals[i] for i in self.in_idx)
        vals[self.out_i] = float(self.kernel(F, v, a, x, load, self.time, self.e))

    def advance(self, t, h):
        self.time = t + h
        return False
