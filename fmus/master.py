"""A fixed-step co-simulation master for FMI 2.0 co-simulation FMUs on the fmpy runtime.

FMUs are connected by instance and variable name, as in an SSP/OSP connection list::

    from fmus.master import Master
    fmus = {"mass": "out/mass.fmu", "friction": "out/lugre.fmu"}
    connections = [("mass.v", "friction.v"), ("friction.F", "mass.F_friction")]
    with Master(fmus, connections, parameters={"mass": {"m": 0.5}}) as m:
        res = m.simulate(stop_time=1.0, step_size=1e-4)
    res["time"], res["mass.x"]          # numpy structured array, ``time`` first

Algorithms (fixed communication step ``h``):

* ``"gauss-seidel"`` (default): the instances step one after the other in ``order``; each
  takes its inputs from the newest outputs (those of instances already stepped to t+h);
* ``"jacobi"``: all instances take their inputs from the outputs at t, then all step (the
  scheme of OSP libcosim's fixed-step algorithm and of parallel FMU containers).

``iterations > 0`` adds a fixed-point iteration at every communication point for algebraic
loops through direct-feedthrough outputs: inputs are re-set and the outputs re-read (no
stepping) until the connected values change by less than ``tolerance`` (relative).
Initialization propagates connected values through feedthrough chains in
initialization mode.

Per-step overhead is kept low: value references and ctypes buffers are built once; per
communication step each instance gets one ``fmi2SetReal`` (all its connected inputs), one
``fmi2DoStep`` and one ``fmi2GetReal`` (only the outputs that are connected or recorded);
the fixed-point pass re-sets only instances whose inputs changed. These calls run in a small
compiled loop (:mod:`fmus.master_loop`, built with the system C compiler on first use) on
those buffers, through the FMUs' own function pointers, so a native FMU's step is not buried
under a Python round trip per call; without a C compiler (or with ``loop="python"``) the same
calls run from Python through ctypes pointers without argtypes on ready ctypes arguments.
Both loops give the same results bit for bit.

Parameters are set with the FMI setter of each variable's type, from Python-style values
translated for either FMU kind (:func:`fmu_values`: ``shape="lorentzian"`` becomes a native
FMU's Enumeration code, a twin ``Fc_neg=None`` its ``use_Fc_neg = false``).

Any FMU call returning fmi2Discard or worse (our FMUs answer fmi2Error for bad input, see
:mod:`fmus.status_shim`) raises :class:`FMUError` naming the instance, the call, the time
and the FMU's last log messages.
"""
from __future__ import annotations

import array
import ctypes
import math
import os
import shutil
from collections import deque
from dataclasses import dataclass
from typing import Iterable, Mapping

import numpy as np

from friction.progress import as_progress

__all__ = ["Master", "Connection", "FMUError", "simulate_cosim", "ALGORITHMS", "fmu_values",
           "fmu_file", "law_parameters", "FMU_KINDS"]

ALGORITHMS = ("gauss-seidel", "jacobi")
_STATUS = ["ok", "warning", "discard", "error", "fatal", "pending"]


class FMUError(RuntimeError):
    """An FMU call failed: names the instance, the FMI call and the simulation time."""

    def __init__(self, instance: str, call: str, time: float, status: int, messages=()):
        self.instance, self.call, self.time, self.status = instance, call, time, status
        self.messages = list(messages)
        label = _STATUS[status] if 0 <= status < len(_STATUS) else str(status)
        msg = f"FMU instance '{instance}': {call} returned {label} at t = {time:.9g} s"
        if self.messages:
            msg += ": " + " | ".join(self.messages[-3:])
        super().__init__(msg)


@dataclass(frozen=True)
class Connection:
    """``source`` output ``"instance.variable"`` drives ``target`` input ``"instance.variable"``,
    multiplied by ``factor`` (SSP's linear transformation without offset; ``-1.0`` turns a
    friction force into the force a plant adds)."""
    source: str
    target: str
    factor: float = 1.0

    @staticmethod
    def split(ref: str) -> tuple[str, str]:
        """``(instance, variable)`` of a connection end (ValueError if malformed).

        Parameters
        ----------
        ref : str
            A connection end ``"instance.variable"``.
        """
        inst, dot, var = ref.partition(".")
        if not dot or not inst or not var:
            raise ValueError(f"connection end {ref!r} must be 'instance.variable'")
        return inst, var


#: the two kinds of frictionlab FMU: ``<name>.fmu`` (pythonfmu) and ``<name>_native.fmu`` (C)
FMU_KINDS = ("pythonfmu", "native")


def fmu_file(fmu_dir, name: str, native: bool = False) -> str:
    """Path of the FMU ``name`` in ``fmu_dir``: ``<name>.fmu`` (pythonfmu) or, with
    ``native``, ``<name>_native.fmu`` (:mod:`fmus.native.build`).

    Parameters
    ----------
    fmu_dir : str or path
        Folder of built FMUs.
    name : str
        FMU name (``lugre``, ``mass``, a plant).
    native : bool
        The native C FMU.
    """
    suffix = "_native" if native else ""
    return os.path.join(os.fspath(fmu_dir), f"{name}{suffix}.fmu")


def _enum_code(var, value):
    items = list(getattr(var.declaredType, "items", None) or [])
    if isinstance(value, str):
        for item in items:
            if item.name == value:
                return int(item.value)
        raise ValueError(f"{var.name} = {value!r} is not one of "
                         f"{', '.join(i.name for i in items) or '(no items)'}")
    if isinstance(value, bool) or int(value) != value:
        raise ValueError(f"{var.name} = {value!r}: give an item name or an integer code")
    return int(value)


def _as_bool(name, value):
    if isinstance(value, str):
        low = value.strip().lower()
        if low in ("true", "1"):
            return True
        if low in ("false", "0"):
            return False
        raise ValueError(f"{name} = {value!r} is not a Boolean")
    return bool(value)


def fmu_values(variables: Mapping, values: Mapping) -> dict:
    """Python-style values (a law's parameters, start values) -> values of the FMU's variables,
    for either FMU kind; returns ``{variable name: value}`` typed for its FMI setter
    (``float`` for Real, ``int`` for Integer and Enumeration, ``bool``, ``str``).

    ``variables``: name -> fmpy ``ScalarVariable`` of the FMU. Both kinds declare the same
    variables (:mod:`fmus.variables`), so the translation is the same. Translated:

    * an option by name (``shape="lorentzian"``) -> its Enumeration code (an integer code
      passes as it is; a String variable, e.g. a plant's option, keeps the text);
    * an optional parameter (Python ``None``, e.g. a direction twin ``Fc_neg``): ``None`` ->
      ``use_Fc_neg = False``; a number -> ``use_Fc_neg = True`` and the number;
    * Booleans (``True``, ``1``, ``"true"``), Integers and Reals by type.

    Raises ``ValueError`` naming an unknown variable or an untranslatable value.

    Parameters
    ----------
    variables : Mapping
        Variable name -> fmpy ``ScalarVariable`` of the FMU.
    values : Mapping
        Python-style values by name (see above).
    """
    out = {}
    for name, value in values.items():
        var = variables.get(name)
        if var is None:
            raise ValueError(f"no variable {name!r}; variables: {sorted(variables)}")
        flag = variables.get(f"use_{name}")
        twin = flag is not None and flag.type == "Boolean" and var.type == "Real"
        if value is None:
            if not twin:
                raise ValueError(f"{name} = None: the FMU has no flag use_{name} (the "
                                 f"parameter is not optional)")
            out[flag.name] = False
            continue
        if twin:
            out[flag.name] = True
        t = var.type
        try:
            if t == "Real":
                out[name] = float(value)
            elif t == "Enumeration":
                out[name] = _enum_code(var, value)
            elif t == "Integer":
                if isinstance(value, str) or int(value) != value:
                    raise ValueError(f"{name} = {value!r} is not an integer")
                out[name] = int(value)
            elif t == "Boolean":
                out[name] = _as_bool(name, value)
            else:
                out[name] = str(value)
        except (TypeError, ValueError) as exc:
            if isinstance(exc, ValueError) and str(exc).startswith(name):
                raise
            raise ValueError(f"{name} = {value!r} cannot be a {t}: {exc}") from None
    return out


def law_parameters(model, exclude=()) -> dict:
    """Every parameter of a friction law (a ``friction.MODELS`` instance) as a dict for
    :class:`Master` ``parameters``, options (``shape``) and unset twins (``None``) included;
    :func:`fmu_values` turns it into either FMU kind's values. ``exclude``: names left out.

    Parameters
    ----------
    model : FrictionModel
        The law.
    exclude : sequence of str
        Parameter names left out.
    """
    import dataclasses
    return {f.name: getattr(model.params, f.name) for f in dataclasses.fields(model.params)
            if f.name not in exclude}


class _GILHeldFunction(ctypes._CFuncPtr):
    """An FMU function called with the GIL held: no release and re-acquisition around each
    call (about 0.2 of the 0.7 us a call from Python costs). The per-step calls last
    microseconds, and an FMU that runs Python itself (pythonfmu) takes the GIL with
    ``PyGILState_Ensure``, which the calling thread already holds; so do log callbacks."""
    _flags_ = ctypes._FUNCFLAG_CDECL | ctypes._FUNCFLAG_PYTHONAPI
    _restype_ = ctypes.c_int


def _raw_function(dll, name):
    """``name`` from the loaded FMU library as a ctypes function returning fmi2Status, with
    no argtypes (callers pass ctypes objects: c_void_p, arrays, c_size_t, c_double, c_int)."""
    return _GILHeldFunction((name, dll))


_TRUE = ctypes.c_int(1)


class _Instance:
    """One FMU instance with its prebuilt buffers."""

    def __init__(self, name, path, md, unzipdir, callbacks):
        from fmpy.fmi2 import FMU2Slave
        self.name, self.path, self.md = name, path, md
        self.vars = {v.name: v for v in md.modelVariables}
        self.slave = FMU2Slave(guid=md.guid, unzipDirectory=unzipdir,
                               modelIdentifier=md.coSimulation.modelIdentifier,
                               instanceName=name)
        # loggingOn: warnings too (our FMUs' status shim forwards errors in any case)
        self.slave.instantiate(callbacks=callbacks, loggingOn=True)
        self.c = self.slave.component
        # fmpy's function pointers (argtypes set: plain Python arguments), kept for callers
        # that drive an instance themselves (e.g. identification.cosim)
        f = self.slave._functions
        self.f_set, self.f_get, self.f_step = f["fmi2SetReal"], f["fmi2GetReal"], f["fmi2DoStep"]
        # the master's per-step calls: own pointers without argtypes, given ready ctypes
        # objects (c_void_p, arrays, c_size_t, c_double, c_int): no per-call conversion
        self.cv = ctypes.c_void_p(self.c)
        self.raw_set = _raw_function(self.slave.dll, "fmi2SetReal")
        self.raw_get = _raw_function(self.slave.dll, "fmi2GetReal")
        self.raw_step = _raw_function(self.slave.dll, "fmi2DoStep")
        self.inputs: list[str] = []
        self.outputs: list[str] = [v.name for v in md.modelVariables if v.causality == "output"]
        deps = {}
        for u in md.outputs:
            deps[u.variable.name] = [d.name for d in (u.dependencies or [])] \
                if u.dependencies is not None else None
        self.deps = deps
        self.terminated = False

    def var(self, name):
        try:
            return self.vars[name]
        except KeyError:
            raise ValueError(f"instance '{self.name}' ({os.path.basename(self.path)}) has no "
                             f"variable {name!r}; variables: {sorted(self.vars)}") from None

    def finalize_buffers(self):
        n_in, n_out = len(self.inputs), len(self.outputs)
        self.n_in, self.n_out = n_in, n_out
        self.n_in_c, self.n_out_c = ctypes.c_size_t(n_in), ctypes.c_size_t(n_out)
        self.in_vr = (ctypes.c_uint * max(n_in, 1))(*[self.vars[n].valueReference for n in self.inputs])
        self.out_vr = (ctypes.c_uint * max(n_out, 1))(*[self.vars[n].valueReference for n in self.outputs])
        self.in_buf = (ctypes.c_double * max(n_in, 1))()
        self.out_buf = (ctypes.c_double * max(n_out, 1))()
        self.in_np = np.ctypeslib.as_array(self.in_buf)[:n_in]
        for j, name in enumerate(self.inputs):  # unconnected inputs keep their start values
            start = self.vars[name].start
            self.in_np[j] = float(start) if start not in (None, "") else 0.0
        self.out_np = np.ctypeslib.as_array(self.out_buf)[:n_out]
        # feedthrough: some connected input reaches an output the master reads directly
        # (an output missing from ModelStructure or without dependencies counts as such)
        conn = set(self.inputs)
        self.feedthrough = any(self.deps.get(o) is None or conn.intersection(self.deps[o])
                               for o in self.outputs) if n_in else False


class Master:
    """Fixed-step co-simulation of connected FMI 2.0 co-simulation FMUs (fmpy runtime).

    Parameters
    ----------
    fmus : mapping
        Instance name -> path of the ``.fmu`` file (one FMU file may back several instances).
    connections : iterable
        :class:`Connection` objects, ``(source, target)`` pairs of ``"instance.variable"``
        or ``(source, target, factor)`` triples; sources are outputs, targets are inputs
        (each input driven at most once); the target receives ``factor * source``.
    algorithm : {"gauss-seidel", "jacobi"}
    order : list of str, optional
        Stepping order of the instances (default: the order of ``fmus``).
    iterations : int
        Maximum fixed-point iterations per communication point for algebraic loops (0: none).
    tolerance : float
        Relative convergence tolerance of the fixed-point iteration.
    parameters, start_values : mapping, optional
        Instance -> {variable: value}; set after instantiation, before initialization
        (parameters, and start values of inputs), each with the FMI setter of its type.
        Python-style values are translated for either FMU kind (:func:`fmu_values`): an
        option by name (``shape="lorentzian"``), ``None`` for an unset optional parameter.
    record : list of str, optional
        ``"instance.variable"`` columns of the result (outputs or inputs); default every
        output of every instance.
    inputs : list of str, optional
        ``"instance.variable"`` inputs driven from outside per communication step (measured
        signals): their values are given to :meth:`simulate` (``inputs=``), one per
        communication point, and held over the step that starts there.
    loop : {"auto", "c", "python"}, optional
        Where the per-step loop runs: ``"c"`` the compiled loop of :mod:`fmus.master_loop`
        (the same calls on the same buffers, without a Python round trip per FMI call),
        ``"python"`` the Python loop, ``"auto"`` (default, or ``$FRICTIONLAB_MASTER_LOOP``)
        the C loop when a C compiler could build it. Both give the same results bit for bit.
    """

    def __init__(self, fmus: Mapping[str, str], connections: Iterable = (), *,
                 algorithm: str = "gauss-seidel", order=None, iterations: int = 0,
                 tolerance: float = 1e-10, parameters=None, start_values=None, record=None,
                 loop: str | None = None, inputs=()):
        from fmpy import extract, read_model_description
        from fmpy.fmi2 import fmi2CallbackFunctions, fmi2CallbackLoggerTYPE, \
            fmi2CallbackAllocateMemoryTYPE, fmi2CallbackFreeMemoryTYPE
        from fmpy.fmi2 import calloc, free

        if algorithm not in ALGORITHMS:
            raise ValueError(f"algorithm must be one of {ALGORITHMS}, got {algorithm!r}")
        if int(iterations) < 0:
            raise ValueError(f"iterations = {iterations!r} is out of bounds: must be >= 0")
        if not fmus:
            raise ValueError("fmus: need at least one FMU instance")
        from .master_loop import LOOPS
        loop = loop if loop is not None else os.environ.get("FRICTIONLAB_MASTER_LOOP", "auto")
        if loop not in LOOPS:
            raise ValueError(f"loop must be one of {LOOPS}, got {loop!r}")
        self.loop = loop
        self.algorithm, self.iterations, self.tolerance = algorithm, int(iterations), float(tolerance)
        self.log: dict[str, deque] = {name: deque(maxlen=50) for name in fmus}

        def logger(env, instance_name, status, category, message):
            name = instance_name.decode("utf-8", "replace") if instance_name else "?"
            text = message.decode("utf-8", "replace") if message else ""
            self.log.setdefault(name, deque(maxlen=50)).append(text)

        cb = fmi2CallbackFunctions()
        cb.logger = fmi2CallbackLoggerTYPE(logger)
        cb.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        cb.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        self._callbacks, self._logger = cb, logger  # keep alive

        self._unzipped: dict[str, str] = {}
        mds = {}
        self.instances: dict[str, _Instance] = {}
        try:
            for name, path in fmus.items():
                path = os.fspath(path)
                if not os.path.isfile(path):
                    raise FileNotFoundError(f"instance '{name}': FMU file {path!r} not found")
                if path not in self._unzipped:
                    mds[path] = read_model_description(path)
                    if mds[path].coSimulation is None:
                        raise ValueError(f"instance '{name}': {path} is not a co-simulation FMU")
                    self._unzipped[path] = extract(path)
                self.instances[name] = _Instance(name, path, mds[path], self._unzipped[path], cb)
        except Exception:
            self.close()
            raise

        self.order = list(order) if order is not None else list(fmus)
        if sorted(self.order) != sorted(fmus):
            raise ValueError(f"order {self.order} must list every instance {list(fmus)} once")

        # connections -> (dst, dst input slot, src, src output slot)
        self.connections = []
        driven = {}
        factors = {}
        for c in connections:
            c = c if isinstance(c, Connection) else Connection(*c)
            if not math.isfinite(float(c.factor)):
                raise ValueError(f"connection {c.source} -> {c.target}: factor = {c.factor!r} "
                                 f"is not finite")
            si, sv = Connection.split(c.source)
            di, dv = Connection.split(c.target)
            for inst in (si, di):
                if inst not in self.instances:
                    raise ValueError(f"connection {c.source} -> {c.target}: unknown instance "
                                     f"{inst!r}; instances: {list(self.instances)}")
            svar, dvar = self.instances[si].var(sv), self.instances[di].var(dv)
            if svar.causality != "output":
                raise ValueError(f"connection source {c.source} is a {svar.causality}, not an output")
            if dvar.causality != "input":
                raise ValueError(f"connection target {c.target} is a {dvar.causality}, not an input")
            if svar.type != "Real" or dvar.type != "Real":
                raise ValueError(f"connection {c.source} -> {c.target}: only Real variables "
                                 f"are supported, got {svar.type} -> {dvar.type}")
            if c.target in driven:
                raise ValueError(f"input {c.target} is driven twice ({driven[c.target]} and "
                                 f"{c.source})")
            driven[c.target] = c.source
            dst = self.instances[di]
            if dv not in dst.inputs:
                dst.inputs.append(dv)
            self.connections.append((di, dv, si, sv))
            factors[(di, dv)] = float(c.factor)
        # inputs driven from outside (measured signals), per communication step
        self.external = []
        for ref in inputs or ():
            inst, var = Connection.split(ref)
            if inst not in self.instances:
                raise ValueError(f"external input {ref!r}: unknown instance {inst!r}; "
                                 f"instances: {list(self.instances)}")
            v = self.instances[inst].var(var)
            if v.causality != "input":
                raise ValueError(f"external input {ref} is a {v.causality}, not an input")
            if v.type != "Real":
                raise ValueError(f"external input {ref}: only Real inputs can be driven, "
                                 f"this is a {v.type}")
            if ref in driven or ref in self.external:
                raise ValueError(f"input {ref} is driven twice ("
                                 f"{driven.get(ref, 'external')} and external)")
            if var not in self.instances[inst].inputs:
                self.instances[inst].inputs.append(var)
            self.external.append(ref)
        # recorded inputs that are not connected still get a buffer slot
        self.record = list(record) if record is not None else \
            [f"{n}.{o}" for n in self.order for o in self.instances[n].outputs]
        for ref in self.record:
            inst, var = Connection.split(ref)
            if inst not in self.instances:
                raise ValueError(f"record {ref!r}: unknown instance {inst!r}")
            v = self.instances[inst].var(var)
            if v.causality == "input" and var not in self.instances[inst].inputs:
                self.instances[inst].inputs.append(var)
            elif v.causality not in ("input", "output"):
                raise ValueError(f"record {ref!r}: only outputs and inputs can be recorded "
                                 f"(this is a {v.causality})")
        # read only what is connected or recorded (one fmi2GetReal of just those per step)
        needed = {(si, sv) for _, _, si, sv in self.connections}
        needed |= {tuple(Connection.split(ref)) for ref in self.record}
        for inst in self.instances.values():
            inst.outputs = [o for o in inst.outputs if (inst.name, o) in needed]
            inst.finalize_buffers()
        # per destination instance: list of (input slot, source out_np, source slot)
        self._gather = {n: [] for n in self.instances}
        for di, dv, si, sv in self.connections:
            dst, src = self.instances[di], self.instances[si]
            self._gather[di].append((dst.inputs.index(dv), src, src.outputs.index(sv),
                                     factors[(di, dv)]))
        for inst in self.instances.values():
            inst.gather = self._gather[inst.name]
        self._feedthrough = [self.instances[n] for n in self.order
                             if self.instances[n].feedthrough]
        self._conn_src = [(self.instances[si].out_buf, self.instances[si].outputs.index(sv))
                          for _, _, si, sv in self.connections]
        # where each external input's value goes: (instance, input slot)
        self._ext_dst = []
        for ref in self.external:
            inst, var = Connection.split(ref)
            obj = self.instances[inst]
            self._ext_dst.append((obj, obj.inputs.index(var)))
        self._columns = []
        for ref in self.record:
            inst, var = Connection.split(ref)
            obj = self.instances[inst]
            if obj.vars[var].causality == "output":
                self._columns.append((obj, "out", obj.outputs.index(var)))
            else:
                self._columns.append((obj, "in", obj.inputs.index(var)))
        self.parameters = {k: dict(v) for k, v in (parameters or {}).items()}
        self.start_values = {k: dict(v) for k, v in (start_values or {}).items()}
        for group in (self.parameters, self.start_values):
            for inst, vals in group.items():
                if inst not in self.instances:
                    raise ValueError(f"values given for unknown instance {inst!r}; instances: "
                                     f"{list(self.instances)}")
                for var in vals:
                    self.instances[inst].var(var)
                self._fmu_values(self.instances[inst], vals)  # refused here, not mid-run
        self._runs = 0

    # -- helpers ------------------------------------------------------------------------
    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _check(self, inst, call, status, t):
        if status > 1:
            raise FMUError(inst.name, call, t, status, self.log.get(inst.name, ()))

    def _call(self, inst, call, t, fn, *args):
        from fmpy.fmi1 import FMICallException
        try:
            fn(*args)
        except FMICallException as exc:
            raise FMUError(inst.name, call, t, exc.status, self.log.get(inst.name, ())) from None

    def _fmu_values(self, inst, values):
        try:
            return fmu_values(inst.vars, values)
        except ValueError as exc:
            raise ValueError(f"instance '{inst.name}' ({os.path.basename(inst.path)}): "
                             f"{exc}") from None

    def _set_values(self, inst, values, t):
        """Set Python-style values (:func:`fmu_values`) by the variables' types."""
        s = inst.slave
        for name, value in self._fmu_values(inst, values).items():
            v = inst.vars[name]
            vr = [v.valueReference]
            if v.type == "Real":
                self._call(inst, f"fmi2SetReal({name})", t, s.setReal, vr, [value])
            elif v.type in ("Integer", "Enumeration"):
                self._call(inst, f"fmi2SetInteger({name})", t, s.setInteger, vr, [value])
            elif v.type == "Boolean":
                self._call(inst, f"fmi2SetBoolean({name})", t, s.setBoolean, vr, [value])
            else:
                self._call(inst, f"fmi2SetString({name})", t, s.setString, vr, [value])
            if v.causality == "input" and name in inst.inputs:
                inst.in_np[inst.inputs.index(name)] = float(value)

    def default_experiment(self) -> dict:
        """Start, stop and step from the FMUs' DefaultExperiments (earliest start, latest
        stop, finest step)."""
        starts, stops, steps = [], [], []
        for inst in self.instances.values():
            de = inst.md.defaultExperiment
            if de is None:
                continue
            if de.startTime is not None:
                starts.append(float(de.startTime))
            if de.stopTime is not None:
                stops.append(float(de.stopTime))
            if de.stepSize is not None:
                steps.append(float(de.stepSize))
        return {"start_time": min(starts) if starts else 0.0,
                "stop_time": max(stops) if stops else None,
                "step_size": min(steps) if steps else None}

    def _gather_set(self, inst, t, only_changed=False):
        """Copy connected source outputs into inst's input buffer and set them (one
        fmi2SetReal for all inputs). ``only_changed``: skip the call when no input changed
        since the last set; returns whether it was made."""
        buf = inst.in_buf
        if only_changed:
            same = True
            for slot, src, k, fac in inst.gather:
                value = fac * src.out_buf[k]
                if buf[slot] != value:
                    buf[slot] = value
                    same = False
            if same:
                return False
        else:
            for slot, src, k, fac in inst.gather:
                buf[slot] = fac * src.out_buf[k]
        if inst.n_in:
            st = inst.raw_set(inst.cv, inst.in_vr, inst.n_in_c, buf)
            if st > 1:
                self._check(inst, "fmi2SetReal", st, t)
        return True

    def _get(self, inst, t):
        if inst.n_out:
            st = inst.raw_get(inst.cv, inst.out_vr, inst.n_out_c, inst.out_buf)
            if st > 1:
                self._check(inst, "fmi2GetReal", st, t)

    def _connected_values(self):
        return np.array([buf[k] for buf, k in self._conn_src])

    def _settle(self, t, passes):
        """Propagate connected values through feedthrough outputs (fixed-point iteration).

        An instance whose inputs did not change since they were last set is skipped (its
        outputs cannot have changed); a pass in which nothing changed ends the iteration,
        and the relative-tolerance test runs only when another pass may follow.
        """
        ft = self._feedthrough
        if not ft:
            return 0
        check = passes > 1
        prev = self._connected_values() if check else None
        for it in range(1, passes + 1):
            changed = False
            for inst in ft:
                if self._gather_set(inst, t, only_changed=True):
                    self._get(inst, t)
                    changed = True
            if not changed:
                return it
            if check and it < passes:
                cur = self._connected_values()
                if np.all(np.abs(cur - prev) <= self.tolerance * (1.0 + np.abs(cur))):
                    return it
                prev = cur
        return passes

    def _c_loop(self, insts, srcs):
        """The compiled loop of :mod:`fmus.master_loop` for this run, or None (Python loop:
        ``loop="python"``, no C compiler, or an instance's raw calls replaced, e.g. by call
        counters)."""
        if self.loop == "python":
            return None
        from . import master_loop
        raw = all(isinstance(f, ctypes._CFuncPtr) for i in insts
                  for f in (i.raw_set, i.raw_step, i.raw_get))
        lib = master_loop.library() if raw else None
        if lib is None:
            if self.loop == "c":
                raise RuntimeError("loop='c': the C master loop is not available: " +
                                   (master_loop.UNAVAILABLE if raw else
                                    "an instance's FMI calls are not the FMU's functions"))
            return None
        return master_loop.CLoop(insts, jacobi=self.algorithm == "jacobi",
                                 iterations=self.iterations, tolerance=self.tolerance,
                                 feedthrough=self._feedthrough, conn_src=self._conn_src,
                                 rec_src=srcs,
                                 ext_dst=[(o.in_buf, j) for o, j in self._ext_dst])

    def _run_c(self, cloop, t0, h, n, srcs, prog, chunk, table=None) -> np.ndarray:
        """Steps 1..n in the C loop, in chunks between progress reports; returns the
        recorded values, one row per communication point. ``table``: the external inputs'
        values, one row per communication point (row k - 1 is held over step k)."""
        out = np.empty((n + 1, len(srcs)))
        out[0] = [buf[slot] for buf, slot in srcs]
        if table is not None:
            cloop.set_table(table)
        k = 1
        while k <= n:
            end = min(n, ((k - 1) // chunk + 1) * chunk)
            if not cloop.run(t0, h, k, end, out[k:end + 1]):
                inst, call, status, t = cloop.error()
                self._check(inst, call, status, t)
                raise FMUError(inst.name, call, t, status, self.log.get(inst.name, ()))
            if end % chunk == 0:
                prog(chunk)
            k = end + 1
        return out

    def _run_python(self, insts, t0, h, n, srcs, prog, chunk, table=None) -> np.ndarray:
        """Steps 1..n in Python (the reference of the C loop); returns the recorded values,
        one row per communication point."""
        ext = [(o.in_buf, j) for o, j in self._ext_dst] if table is not None else []
        rows = table.tolist() if ext else None
        # recorded values go straight from the ctypes buffers into a flat array of doubles
        flat = array.array("d")
        keep = flat.extend
        keep([buf[slot] for buf, slot in srcs])
        gs = self.algorithm == "gauss-seidel"
        iters = self.iterations
        # per instance, everything a step touches, unpacked once (the loop below is the
        # per-step overhead of the master: one fmi2SetReal, fmi2DoStep, fmi2GetReal each)
        plan = [(inst, inst.cv, [(slot, src.out_buf, j, fac) for slot, src, j, fac
                                 in inst.gather],
                 inst.in_buf, inst.in_vr, inst.n_in and inst.n_in_c, inst.raw_set,
                 inst.raw_step, inst.out_buf, inst.out_vr, inst.n_out and inst.n_out_c,
                 inst.raw_get)
                for inst in insts]
        hc, c_double = ctypes.c_double(h), ctypes.c_double
        check = self._check
        for k in range(1, n + 1):
            t = t0 + (k - 1) * h
            tc = c_double(t)
            if ext:
                for (buf, slot), value in zip(ext, rows[k - 1]):
                    buf[slot] = value
            if gs:
                for inst, c, gather, ibuf, ivr, nin, fset, fstep, obuf, ovr, nout, fget in plan:
                    if nin:
                        for slot, src, j, fac in gather:
                            ibuf[slot] = fac * src[j]
                        st = fset(c, ivr, nin, ibuf)
                        if st > 1:
                            check(inst, "fmi2SetReal", st, t)
                    st = fstep(c, tc, hc, _TRUE)
                    if st > 1:
                        check(inst, "fmi2DoStep", st, t)
                    if nout:
                        st = fget(c, ovr, nout, obuf)
                        if st > 1:
                            check(inst, "fmi2GetReal", st, t + h)
            else:
                for inst in insts:
                    self._gather_set(inst, t)
                for inst in insts:
                    st = inst.raw_step(inst.cv, tc, hc, _TRUE)
                    if st > 1:
                        check(inst, "fmi2DoStep", st, t)
                for inst in insts:
                    self._get(inst, t + h)
            if iters:
                self._settle(t + h, iters)
            keep([buf[slot] for buf, slot in srcs])
            if k % chunk == 0:
                prog(chunk)
        return np.frombuffer(flat, dtype=np.float64).reshape(n + 1, len(srcs))

    # -- simulation -----------------------------------------------------------------------
    def simulate(self, stop_time: float | None = None, step_size: float | None = None,
                 start_time: float | None = None, *, progress=None,
                 inputs=None) -> np.ndarray:
        """Run the co-simulation; returns a structured array (``time`` first, then ``record``).

        ``None`` arguments are taken from the FMUs' DefaultExperiments. ``progress``: None
        (a bar when the run has more than 20000 steps), or as :mod:`friction.progress`
        says (False, True, a tqdm bar, ``callable(n, info)``), in communication steps. ``inputs``: ``{"instance.variable": values}`` for every
        external input declared at construction; ``values[k]`` (``n`` or ``n + 1`` of them
        for ``n`` steps) is set at the communication point ``t_k`` (at initialization for
        ``k = 0``) and held over the step from ``t_k``; a recorded external input shows the
        value held over the step that ended at its row.

        Parameters
        ----------
        stop_time : float, optional
            End of the run [s] (default: the DefaultExperiment's).
        step_size : float, optional
            Communication step [s] (default: the DefaultExperiment's).
        start_time : float, optional
            Start of the run [s] (default: the DefaultExperiment's, else 0).
        progress : None, bool, tqdm or callable(n, info), optional
            Progress in communication steps (see above).
        inputs : dict, optional
            ``{"instance.variable": values}`` of the external inputs (see above).
        """
        de = self.default_experiment()
        t0 = de["start_time"] if start_time is None else float(start_time)
        stop = de["stop_time"] if stop_time is None else float(stop_time)
        h = de["step_size"] if step_size is None else float(step_size)
        if stop is None or h is None:
            raise ValueError("stop_time and step_size are needed (no DefaultExperiment gives them)")
        if not (math.isfinite(h) and h > 0):
            raise ValueError(f"step_size = {h!r} is out of bounds: must be > 0 [s]")
        if not stop > t0:
            raise ValueError(f"stop_time = {stop!r} must be > start_time = {t0!r}")
        n = int(round((stop - t0) / h))
        if abs(n * h - (stop - t0)) > 1e-9 * max(1.0, abs(stop)):
            raise ValueError(f"(stop_time - start_time) = {stop - t0!r} is not a multiple of "
                             f"step_size = {h!r}")
        insts = [self.instances[k] for k in self.order]
        table = self._input_table(inputs, n)
        if table is not None:
            for (obj, slot), value in zip(self._ext_dst, table[0]):
                obj.in_np[slot] = value

        # initialization
        for inst in insts:
            s = inst.slave
            if self._runs:
                self._call(inst, "fmi2Reset", t0, s.reset)
            self._call(inst, "fmi2SetupExperiment", t0, s.setupExperiment, None, t0)
            self._set_values(inst, self.parameters.get(inst.name, {}), t0)
            self._set_values(inst, self.start_values.get(inst.name, {}), t0)
            self._call(inst, "fmi2EnterInitializationMode", t0, s.enterInitializationMode)
        self._runs += 1
        for _ in range(len(insts) + 1):  # propagate start values along the connections
            for inst in insts:
                self._get(inst, t0)
            for inst in insts:
                self._gather_set(inst, t0)
        for inst in insts:
            self._call(inst, "fmi2ExitInitializationMode", t0, inst.slave.exitInitializationMode)
        for inst in insts:  # in order: a discrete block samples t0 with its inputs at t0
            self._gather_set(inst, t0)
            self._get(inst, t0)
        self._settle(t0, max(self.iterations, len(insts)))

        cols = self._columns
        srcs = [(c[0].out_buf if c[1] == "out" else c[0].in_buf, c[2]) for c in cols]
        chunk = max(1, n // 100)
        cloop = self._c_loop(insts, srcs)
        with as_progress(n > 20000 if progress is None else progress, "cosim", total=n,
                         unit="step") as prog:
            if cloop is not None:
                out = self._run_c(cloop, t0, h, n, srcs, prog, chunk, table)
            else:
                out = self._run_python(insts, t0, h, n, srcs, prog, chunk, table)
        time = t0 + h * np.arange(n + 1)
        dtype = [("time", np.float64)] + [(c, np.float64) for c in self.record]
        res = np.empty(n + 1, dtype=dtype)
        res["time"] = time
        for j, c in enumerate(self.record):
            res[c] = out[:, j]
        return res

    def _input_table(self, inputs, n):
        """The external inputs' values as a C-contiguous ``(n, n_external)`` array (row
        ``k`` held over step ``k + 1``), or None without external inputs."""
        inputs = dict(inputs or {})
        unknown = [r for r in inputs if r not in self.external]
        if unknown:
            raise ValueError(f"inputs given for {unknown}, which are not external inputs "
                             f"of this master ({self.external or 'none declared'})")
        if not self.external:
            return None
        missing = [r for r in self.external if r not in inputs]
        if missing:
            raise ValueError(f"no values given for the external input(s) {missing}")
        cols = []
        for ref in self.external:
            col = np.asarray(inputs[ref], dtype=np.float64).ravel()
            if col.size not in (n, n + 1):
                raise ValueError(f"external input {ref}: {col.size} values for {n} steps "
                                 f"(give {n} or {n + 1}, one per communication point)")
            bad = ~np.isfinite(col[:n])
            if bad.any():
                raise ValueError(f"external input {ref}: value {int(np.argmax(bad))} is "
                                 f"{col[int(np.argmax(bad))]!r}, not finite")
            cols.append(col[:n])
        return np.ascontiguousarray(np.column_stack(cols))

    def close(self) -> None:
        """Terminate and free all instances and delete the extracted FMU folders."""
        for inst in getattr(self, "instances", {}).values():
            if inst.terminated:
                continue
            inst.terminated = True
            try:
                inst.slave.fmi2Terminate(inst.c)
            except Exception:  # noqa: BLE001 - closing must not mask the original error
                pass
            try:
                inst.slave.fmi2FreeInstance(inst.c)
            except Exception:  # noqa: BLE001
                pass
        for d in getattr(self, "_unzipped", {}).values():
            shutil.rmtree(d, ignore_errors=True)
        self._unzipped = {}


def simulate_cosim(fmus, connections=(), *, stop_time=None, step_size=None, start_time=None,
                   progress=None, **options) -> np.ndarray:
    """One-shot :class:`Master` run (built, simulated, closed); returns the result array.

    Parameters
    ----------
    fmus : dict
        ``{instance name: path of its .fmu}``.
    connections : sequence of Connection or (str, str)
        ``("instance.output", "instance.input")`` pairs.
    stop_time, step_size, start_time : float, optional
        As for :meth:`Master.simulate` [s].
    progress : None, bool, tqdm or callable(n, info), optional
        As for :meth:`Master.simulate`.
    **options
        Further :class:`Master` arguments (``record``, ``parameters``, ``algorithm``, ...);
        an unknown name is a TypeError.
    """
    with Master(fmus, connections, **options) as m:
        return m.simulate(stop_time, step_size, start_time, progress=progress)
