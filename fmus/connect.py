"""The user's own plant FMU: a connection file (TOML) couples it with a friction-law FMU and
with measured signals, and :class:`PlantLoop` co-simulates the three through the project's
master (:class:`fmus.master.Master`).

A connection file says how frictionlab meets a plant it did not build (an FMU exported from
Modelica, Simulink, C...)::

    step = 1e-4                 # communication step [s] (default: the data's interval)
    time = "t"                  # time column of the measured files (default "t")
    mass = "m"                  # plant parameter that is the moving mass (diagnosis)

    [friction]                  # where the friction law meets the plant
    input = "F_fric"            # plant input taking the friction force [N]
    sign = 1                    # +1: the plant subtracts it (m a = ... - F_fric);
                                # -1: it adds it (m a = ... + F_ext): the law's force negated
    v = "v"                     # plant outputs the law reads: velocity (required) ...
    x = "x"                     # ... position, acceleration, normal load (as the law or a
    # a = "a"                   #     diagnosis candidate needs them)
    # load = "F_N"

    [inputs]                    # plant inputs driven by measured columns
    F_drive = "u"               # or {column = "u", scale = 1.0, unit = "N", hold = "linear"}

    [compare]                   # plant outputs compared with measured columns
    x = "x"                     # or {column = "pos_mm", scale = 1e-3, unit = "m", weight = 1}

    [parameters]                # plant parameters set before every run
    m = 2.0

    [identify]                  # plant parameters identified with the law (bounds)
    m = [1.0, 4.0]              # or {bounds = [1.0, 4.0], start = 2.0, log = false}

    [law]                       # optional: the friction law's model, start values, boxes
    model = "lugre"
    names = ["Fc", "Fs", "vs", "sigma2"]
    start = {Fc = 1.0, Fs = 1.5}
    bounds = {Fc = [0.2, 5.0]}

Keys of ``[inputs]``, ``[compare]``, ``[parameters]`` and ``[identify]`` are variables of
the plant FMU; values name columns of the measured file.

Further FMUs on the plant's side (a controller, a sensor...) join with ``[fmus]`` (instance
name = path, relative to the connection file) and ``[connections]`` (``"inst.output" =
"inst.input"``, the plant being ``plant``); anywhere else a variable ``inst.name`` of such an
instance is named with its instance prefix (a bare name is the plant's), and ``order`` lists
the stepping order (default: plant, the further FMUs as listed, then the law)::

    order = ["controller", "plant", "friction"]

    [fmus]
    controller = "pid.fmu"

    [connections]
    "plant.pos" = "controller.y"
    "controller.u" = "plant.F_drive"

    [inputs]
    "controller.r" = "ref"        # the measured reference drives the controller

    [compare]
    "controller.u" = "F_motor"    # and its output is compared with the measured command ``hold`` of an input: ``"linear"``
(default; the signal linearly interpolated at the middle of each communication step, its
mean over the step) or ``"previous"`` (the last sample at or before the step's start: a
sampled command held by a digital controller). ``scale`` converts a column to the plant
variable's unit; ``unit``, where given, must equal the unit the FMU declares.

Everything a connection names is checked against the FMU's model description before a run
(:func:`check_plant`): a missing variable, a connection to an output where an input is
needed (or the reverse), a declared unit that differs (the law's ``v`` is in m/s, its force
in N) and a measured column the file lacks are each a one-line :class:`ConnectError` naming
the table and the variable. A plant that fails to initialise or diverges mid-run raises a
:class:`PlantRunError` naming the variable and the time.

:func:`builtin_connection` writes the same description for the project's own ``mass`` FMU
and plant FMUs, so they run through this path too.
"""
from __future__ import annotations

import copy
import math
import os
from dataclasses import dataclass, field

import numpy as np

__all__ = ["PlantConnection", "InputSpec", "CompareSpec", "PlantParameter", "ConnectError",
           "PlantRunError", "MeasuredRecord", "load_connection", "parse_connection",
           "read_columns", "load_measured", "check_plant", "check_columns", "PlantLoop",
           "PlantRun", "builtin_connection", "LAW_INPUTS", "HOLDS", "DIVERGED"]

#: the law's kinematic inputs a plant output may feed, with the unit the law expects
LAW_INPUTS = {"v": "m/s", "x": "m", "a": "m/s2", "load": "N"}
#: how a measured column is held over a communication step
HOLDS = ("linear", "previous")
#: magnitude beyond which a plant output counts as diverged (besides inf and NaN)
DIVERGED = 1e100


class ConnectError(ValueError):
    """A connection file that does not fit its plant FMU or its measured data."""


class PlantRunError(ValueError):
    """The plant FMU failed to initialise, refused a step or diverged (names the time)."""

    def __init__(self, message, time=None, variable=None):
        super().__init__(message)
        self.time, self.variable = time, variable


# -- the connection file ----------------------------------------------------------------------
@dataclass
class InputSpec:
    """Plant input ``variable`` driven by the measured ``column`` (times ``scale``)."""
    variable: str
    column: str
    scale: float = 1.0
    unit: str | None = None
    hold: str = "linear"


@dataclass
class CompareSpec:
    """Plant output ``variable`` compared with the measured ``column`` (times ``scale``)."""
    variable: str
    column: str
    scale: float = 1.0
    unit: str | None = None
    weight: float = 1.0


@dataclass
class PlantParameter:
    """A plant parameter identified with the law: search box, start, scaling."""
    name: str
    lower: float
    upper: float
    start: float | None = None
    log: bool | None = None


@dataclass
class PlantConnection:
    """What a connection file says (see the module docstring)."""
    friction_input: str
    sign: float = 1.0
    law_inputs: dict = field(default_factory=dict)          # law input -> plant output
    inputs: list = field(default_factory=list)              # [InputSpec]
    compare: list = field(default_factory=list)             # [CompareSpec]
    parameters: dict = field(default_factory=dict)          # plant parameter -> value
    identify: list = field(default_factory=list)            # [PlantParameter]
    step: float | None = None
    time: str = "t"
    mass: str | None = None
    algorithm: str = "gauss-seidel"
    law_model: str | None = None
    law_names: list | None = None
    law_start: dict = field(default_factory=dict)
    law_bounds: dict = field(default_factory=dict)
    source: str = "<connection>"
    fmus: dict = field(default_factory=dict)                # further instance -> FMU path
    links: list = field(default_factory=list)               # [(source key, target key)]
    order: list | None = None

    def split(self, key: str) -> tuple[str, str]:
        """(instance, variable) of a variable key: ``inst.name`` of a further FMU, else the
        plant's ``name``."""
        inst, dot, var = key.partition(".")
        if dot and inst in self.fmus:
            return inst, var
        return "plant", key

    def key(self, ref: str) -> str:
        """The key of a variable reference: ``plant.name`` -> ``name`` (the plant's),
        ``inst.name`` of a further FMU as it is, a bare name as it is."""
        inst, dot, var = ref.partition(".")
        if dot and inst == "plant" and "plant" not in self.fmus:
            return var
        return ref

    def ref(self, key: str) -> str:
        """``instance.variable`` of a key, for the master."""
        inst, var = self.split(key)
        return f"{inst}.{var}"

    @property
    def columns(self) -> list[str]:
        """Measured columns the connection reads (time first)."""
        out = [self.time]
        for s in list(self.inputs) + list(self.compare):
            if s.column not in out:
                out.append(s.column)
        return out

    def plant_names(self) -> list[str]:
        """Identified plant parameters as named in results (``plant.<name>``)."""
        return [f"plant.{p.name}" for p in self.identify]


_TOP = {"step", "time", "mass", "algorithm", "friction", "inputs", "compare", "parameters",
        "identify", "law", "fmus", "connections", "order"}
#: instance names the master uses itself
RESERVED = ("plant", "friction", "effects")


def _flat(table, prefix="") -> dict:
    """A TOML table with dotted keys written unquoted (nested tables) flattened back to
    ``"a.b" = value``."""
    out = {}
    for k, v in table.items():
        if isinstance(v, dict):
            out.update(_flat(v, f"{prefix}{k}."))
        else:
            out[f"{prefix}{k}"] = v
    return out


def _a(word: str) -> str:
    """``word`` with its indefinite article (an input, a parameter)."""
    return f"{'an' if word[:1] in 'aeiou' else 'a'} {word}"


def _err(src, where, msg) -> ConnectError:
    return ConnectError(f"{src}: {where}: {msg}")


def _number(src, where, value, positive=False) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise _err(src, where, f"{value!r} is not a number")
    value = float(value)
    if not math.isfinite(value) or (positive and not value > 0):
        raise _err(src, where, f"{value!r} must be {'> 0' if positive else 'finite'}")
    return value


def _table(src, raw, key) -> dict:
    val = raw.get(key, {})
    if not isinstance(val, dict):
        raise _err(src, f"[{key}]", f"must be a table, got {type(val).__name__}")
    return val


def _entry(src, where, value, allowed, defaults) -> dict:
    """A ``name = "column"`` or ``name = {column = ..., ...}`` entry."""
    if isinstance(value, str):
        return {**defaults, "column": value}
    if not isinstance(value, dict):
        raise _err(src, where, f"give a column name or a table {{column = ...}}, got "
                               f"{value!r}")
    unknown = set(value) - set(allowed)
    if unknown:
        raise _err(src, where, f"unknown key(s) {sorted(unknown)}; allowed: {list(allowed)}")
    if "column" not in value or not isinstance(value["column"], str):
        raise _err(src, where, "needs column = \"NAME\" (the measured column)")
    return {**defaults, **value}


def parse_connection(raw: dict, source: str = "<connection>",
                     base_dir: str | None = None) -> PlantConnection:
    """A :class:`PlantConnection` from the parsed TOML (a dict); one-line
    :class:`ConnectError` naming the key on a malformed file. ``base_dir``: where the paths
    of ``[fmus]`` are relative to (default: the working folder)."""
    src = source
    unknown = set(raw) - _TOP
    if unknown:
        raise _err(src, "top level", f"unknown key(s) {sorted(unknown)}; allowed: "
                                     f"{sorted(_TOP)}")
    fmus = {}
    for name, path in _table(src, raw, "fmus").items():
        if not isinstance(path, str):
            raise _err(src, f"[fmus] {name}", f"{path!r}: give the FMU's path")
        if name in RESERVED or not name.isidentifier():
            raise _err(src, f"[fmus] {name}", f"instance name {name!r} must be an identifier "
                                              f"other than {', '.join(RESERVED)}")
        fmus[name] = path if os.path.isabs(path) or base_dir is None else \
            os.path.join(base_dir, path)
    probe = PlantConnection(friction_input="", fmus=fmus)
    norm = probe.key
    raw = dict(raw)
    for t in ("inputs", "compare", "parameters", "identify"):
        if isinstance(raw.get(t), dict):
            # a key "inst.name" written without quotes reads as a nested table
            flat = {}
            for k, v in raw[t].items():
                if isinstance(v, dict) and k in (*fmus, "plant") and not (
                        set(v) & {"column", "bounds"}):
                    flat.update({f"{k}.{kk}": vv for kk, vv in v.items()})
                else:
                    flat[k] = v
            raw[t] = {norm(k): v for k, v in flat.items()}
    links = []
    for a, b in _flat(_table(src, raw, "connections")).items():
        if not isinstance(b, str):
            raise _err(src, f"[connections] {a}", f"{b!r}: give the input it drives as "
                                                  f"\"instance.variable\"")
        for end in (a, b):
            inst = end.partition(".")[0]
            if "." not in end or inst not in (*fmus, "plant"):
                raise _err(src, f"[connections] {a}", f"{end!r}: name an instance "
                                                      f"(plant, {', '.join(fmus) or '...'}) "
                                                      f"and its variable: \"instance.name\"")
        links.append((norm(a), norm(b)))
    order = raw.get("order")
    if order is not None:
        if not (isinstance(order, list) and all(isinstance(o, str) for o in order)):
            raise _err(src, "order", f"{order!r}: give a list of instance names")
        want = {"plant", "friction", *fmus}
        if set(order) - {"effects"} != want or len(set(order)) != len(order):
            raise _err(src, "order", f"{order!r} must list each of {sorted(want)} once")
    fr = _table(src, raw, "friction")
    if not fr:
        raise _err(src, "[friction]", "missing: say which plant input takes the friction "
                                      "force (input = \"NAME\") and which output is v")
    bad = set(fr) - {"input", "sign", *LAW_INPUTS}
    if bad:
        raise _err(src, "[friction]", f"unknown key(s) {sorted(bad)}; allowed: input, sign, "
                                      f"{', '.join(LAW_INPUTS)}")
    if not isinstance(fr.get("input"), str):
        raise _err(src, "[friction]", "needs input = \"NAME\" (the plant input taking the "
                                      "friction force)")
    sign = _number(src, "[friction] sign", fr.get("sign", 1))
    if sign not in (1.0, -1.0):
        raise _err(src, "[friction] sign", f"{fr['sign']!r} must be 1 (the plant subtracts "
                                           f"the force) or -1 (it adds it)")
    law_inputs = {}
    for k in LAW_INPUTS:
        if k in fr:
            if not isinstance(fr[k], str):
                raise _err(src, f"[friction] {k}", f"{fr[k]!r}: give the plant output's name")
            law_inputs[k] = norm(fr[k])
    if "v" not in law_inputs:
        raise _err(src, "[friction]", "needs v = \"NAME\" (the plant output giving the "
                                      "sliding velocity)")
    inputs = []
    for name, val in _table(src, raw, "inputs").items():
        e = _entry(src, f"[inputs] {name}", val, ("column", "scale", "unit", "hold"),
                   {"scale": 1.0, "unit": None, "hold": "linear"})
        if e["hold"] not in HOLDS:
            raise _err(src, f"[inputs] {name}", f"hold = {e['hold']!r}: choose from {HOLDS}")
        inputs.append(InputSpec(name, e["column"], _number(src, f"[inputs] {name} scale",
                                                           e["scale"]), e["unit"], e["hold"]))
    compare = []
    for name, val in _table(src, raw, "compare").items():
        e = _entry(src, f"[compare] {name}", val, ("column", "scale", "unit", "weight"),
                   {"scale": 1.0, "unit": None, "weight": 1.0})
        compare.append(CompareSpec(name, e["column"],
                                   _number(src, f"[compare] {name} scale", e["scale"]),
                                   e["unit"], _number(src, f"[compare] {name} weight",
                                                      e["weight"], positive=True)))
    if not compare:
        raise _err(src, "[compare]", "missing: say which plant output is compared with which "
                                     "measured column (e.g. x = \"x\")")
    params = {}
    for name, val in _table(src, raw, "parameters").items():
        if isinstance(val, (dict, list)):
            raise _err(src, f"[parameters] {name}", f"{val!r}: give a number, Boolean or "
                                                    f"string")
        params[name] = val
    ident = []
    for name, val in _table(src, raw, "identify").items():
        where = f"[identify] {name}"
        if isinstance(val, list):
            val = {"bounds": val}
        if not isinstance(val, dict) or "bounds" not in val:
            raise _err(src, where, "give bounds: name = [LOW, HIGH] or {bounds = [LOW, HIGH],"
                                   " start = ..., log = ...}")
        bad = set(val) - {"bounds", "start", "log"}
        if bad:
            raise _err(src, where, f"unknown key(s) {sorted(bad)}; allowed: bounds, start, "
                                   f"log")
        b = val["bounds"]
        if not isinstance(b, list) or len(b) != 2:
            raise _err(src, where, f"bounds = {b!r}: need [LOW, HIGH]")
        lo, hi = (_number(src, f"{where} bounds", x) for x in b)
        if not hi > lo:
            raise _err(src, where, f"bounds = {b!r}: HIGH must exceed LOW")
        start = val.get("start", params.get(name))
        start = None if start is None else _number(src, f"{where} start", start)
        if start is not None and not lo <= start <= hi:
            raise _err(src, where, f"start = {start!r} is outside bounds [{lo!r}, {hi!r}]")
        log = val.get("log")
        if log is not None and not isinstance(log, bool):
            raise _err(src, f"{where} log", f"{log!r} must be true or false")
        if log and not lo > 0:
            raise _err(src, f"{where} log", "a log-scaled search needs LOW > 0")
        ident.append(PlantParameter(name, lo, hi, start, log))
    step = raw.get("step")
    step = None if step is None else _number(src, "step", step, positive=True)
    for key in ("time", "mass", "algorithm"):
        if key in raw and not isinstance(raw[key], str):
            raise _err(src, key, f"{raw[key]!r} must be a string")
    from .master import ALGORITHMS
    algorithm = raw.get("algorithm", "gauss-seidel")
    if algorithm not in ALGORITHMS:
        raise _err(src, "algorithm", f"{algorithm!r}: choose from {ALGORITHMS}")
    law = _table(src, raw, "law")
    bad = set(law) - {"model", "names", "start", "bounds"}
    if bad:
        raise _err(src, "[law]", f"unknown key(s) {sorted(bad)}; allowed: model, names, "
                                 f"start, bounds")
    names = law.get("names")
    if names is not None and not (isinstance(names, list) and
                                  all(isinstance(n, str) for n in names) and names):
        raise _err(src, "[law] names", f"{names!r}: give a list of parameter names")
    start = law.get("start", {})
    if not isinstance(start, dict):
        raise _err(src, "[law] start", "must be a table {NAME = VALUE}")
    bounds = {}
    for k, b in (law.get("bounds") or {}).items():
        if not isinstance(b, list) or len(b) != 2:
            raise _err(src, f"[law] bounds {k}", f"{b!r}: need [LOW, HIGH]")
        lo, hi = (_number(src, f"[law] bounds {k}", x) for x in b)
        if not hi > lo:
            raise _err(src, f"[law] bounds {k}", f"{b!r}: HIGH must exceed LOW")
        bounds[k] = (lo, hi)
    model = law.get("model")
    if model is not None and not isinstance(model, str):
        raise _err(src, "[law] model", f"{model!r} must be a registry name")
    return PlantConnection(
        friction_input=norm(fr["input"]), sign=sign, law_inputs=law_inputs, inputs=inputs,
        compare=compare, parameters=params, identify=ident, step=step,
        time=raw.get("time", "t"), mass=None if raw.get("mass") is None else norm(raw["mass"]),
        algorithm=algorithm, law_model=model, law_names=list(names) if names else None,
        law_start=dict(start), law_bounds=bounds, source=src, fmus=fmus, links=links,
        order=list(order) if order is not None else None)


def load_connection(path) -> PlantConnection:
    """Read and check a connection file (TOML); a :class:`PlantConnection` passes through."""
    if isinstance(path, PlantConnection):
        return path
    if isinstance(path, dict):
        return parse_connection(path)
    import tomllib
    path = os.fspath(path)
    if not os.path.isfile(path):
        raise FileNotFoundError(f"no such connection file: {path}")
    try:
        with open(path, "rb") as fh:
            raw = tomllib.load(fh)
    except tomllib.TOMLDecodeError as exc:
        raise ConnectError(f"{os.path.basename(path)}: not valid TOML: {exc}") from None
    return parse_connection(raw, os.path.basename(path),
                            os.path.dirname(os.path.abspath(path)))


# -- the plant FMU against the connection -------------------------------------------------------
def _norm_unit(u) -> str:
    u = (u or "").replace(" ", "").replace("^", "").replace("*", ".").replace("·", ".")
    return {"kg.m/s2": "N", "m/s/s": "m/s2", "Ns/m": "N.s/m", "1": ""}.get(u, u)


def _declared_unit(var) -> str | None:
    unit = getattr(var, "unit", None)
    if not unit and getattr(var, "declaredType", None) is not None:
        unit = getattr(var.declaredType, "unit", None)
    return unit or None


@dataclass
class _PlantInfo:
    path: str
    variables: dict
    label: str


def _plant_info(plant_fmu) -> _PlantInfo:
    from fmpy import read_model_description
    path = os.fspath(plant_fmu)
    if not os.path.isfile(path):
        raise FileNotFoundError(f"no such plant FMU: {path}")
    try:
        md = read_model_description(path)
    except Exception as exc:  # noqa: BLE001 - a broken file is bad input
        raise ConnectError(f"{os.path.basename(path)}: not a readable FMU: "
                           f"{str(exc).splitlines()[0] if str(exc) else exc!r}") from None
    if md.coSimulation is None:
        raise ConnectError(f"{os.path.basename(path)}: not a co-simulation FMU (frictionlab "
                           f"couples FMI 2.0 co-simulation FMUs)")
    return _PlantInfo(path, {v.name: v for v in md.modelVariables}, os.path.basename(path))


def check_plant(conn: PlantConnection, plant_fmu, law=None) -> dict:
    """Check every variable the connection names against the plant FMU and the further
    FMUs of ``[fmus]`` (and the law's inputs); returns ``{key: fmpy ScalarVariable}`` (the
    plant's variables by name, a further FMU's as ``inst.name``). One-line
    :class:`ConnectError` naming the table and the variable otherwise."""
    infos = {"plant": _plant_info(plant_fmu)}
    for inst, path in conn.fmus.items():
        if not os.path.isfile(path):
            raise FileNotFoundError(f"{conn.source}: [fmus] {inst}: no such FMU: {path}")
        infos[inst] = _plant_info(path)
    src = conn.source

    def listing(inst, causality):
        V = infos[inst].variables
        names = sorted(n for n, v in V.items() if v.causality == causality)
        return ", ".join(names[:12]) + (" ..." if len(names) > 12 else "") or "none"

    def lookup(where, key, causality):
        inst, name = conn.split(key)
        info = infos[inst]
        var = info.variables.get(name)
        if var is None:
            raise _err(src, where, f"{info.label} has no variable {name!r} ({causality}s: "
                                   f"{listing(inst, causality)})")
        return inst, name, var, info.label

    def need(where, key, causality, unit=None, what=""):
        inst, name, var, fmu = lookup(where, key, causality)
        if var.causality != causality:
            raise _err(src, where, f"{name!r} is {_a(var.causality)} of {fmu}, not "
                                   f"{_a(causality)}; {what} must be {_a(causality)} "
                                   f"({causality}s: {listing(inst, causality)})")
        if causality in ("input", "output") and var.type != "Real":
            raise _err(src, where, f"{name!r} is a {var.type} {causality}; only Real "
                                   f"variables can be connected")
        declared = _declared_unit(var)
        if unit is not None and declared is not None and _norm_unit(declared) != _norm_unit(unit):
            raise _err(src, where, f"unit mismatch: {fmu} declares {name!r} in {declared!r}, "
                                   f"but {what or 'it'} is in {unit!r}")
        return var

    need("[friction] input", conn.friction_input, "input", "N", "the friction force")
    for k, name in conn.law_inputs.items():
        need(f"[friction] {k}", name, "output", LAW_INPUTS[k], f"the law's input {k}")
    if law is not None:
        missing = [k for k in law.extra_inputs if k not in conn.law_inputs]
        if missing:
            raise _err(src, "[friction]", f"the law {law.name!r} needs input(s) {missing}: "
                                          f"name the plant output(s) giving them "
                                          f"({', '.join(f'{k} = NAME' for k in missing)})")
    seen = {conn.friction_input: "[friction] input"}
    for a, b in conn.links:
        where = f"[connections] {conn.ref(a)}"
        va, vb = need(where, a, "output", what="a connection's source"), \
            need(where, b, "input", what="a connection's target")
        ua, ub = _declared_unit(va), _declared_unit(vb)
        if ua and ub and _norm_unit(ua) != _norm_unit(ub):
            raise _err(src, where, f"unit mismatch: {conn.ref(a)} is in {ua!r}, "
                                   f"{conn.ref(b)} in {ub!r}")
        if b in seen:
            raise _err(src, where, f"input {conn.ref(b)} is already driven by {seen[b]}")
        seen[b] = where
    for s in conn.inputs:
        where = f"[inputs] {s.variable}"
        need(where, s.variable, "input", s.unit, f"column {s.column!r}")
        if s.variable in seen:
            raise _err(src, where, f"plant input {s.variable!r} is already driven by "
                                   f"{seen[s.variable]}")
        seen[s.variable] = where
    for s in conn.compare:
        need(f"[compare] {s.variable}", s.variable, "output", s.unit, f"column {s.column!r}")
    for name in conn.parameters:
        inst, vname, var, fmu = lookup(f"[parameters] {name}", name, "parameter")
        if var.causality not in ("parameter", "input"):
            raise _err(src, f"[parameters] {name}", f"{vname!r} is {_a(var.causality)} of "
                                                    f"{fmu}; only parameters (and input "
                                                    f"start values) can be set")
        if var.causality == "input" and name in seen:
            raise _err(src, f"[parameters] {name}", f"input {name!r} is driven by "
                                                    f"{seen[name]}; it has no value to set")
    for p in conn.identify:
        var = need(f"[identify] {p.name}", p.name, "parameter", what="an identified value")
        if var.type != "Real":
            raise _err(src, f"[identify] {p.name}", f"{p.name!r} is a {var.type}; only Real "
                                                    f"parameters can be identified")
    if conn.mass is not None:
        need("mass", conn.mass, "parameter", what="the moving mass")
    out = dict(infos["plant"].variables)
    for inst, info in infos.items():
        if inst != "plant":
            out.update({f"{inst}.{n}": v for n, v in info.variables.items()})
    return out


# -- measured data --------------------------------------------------------------------------------
def read_columns(path) -> tuple[dict, list]:
    """Every numeric column of a CSV (header row; the separators, decimal commas and
    byte-order marks :func:`friction.dataset.load_csv` reads) or of a ``.mat`` file (1-D
    variables); returns ``(columns, notes)``."""
    import csv
    from friction.dataset import DataError, _decode, _sniff, _to_floats
    path = os.fspath(path)
    if not os.path.isfile(path):
        raise FileNotFoundError(f"no such data file: {path}")
    name = os.path.basename(path)
    if path.lower().endswith(".mat"):
        from scipy.io import loadmat
        cols = {k: np.asarray(v, float).ravel() for k, v in loadmat(path).items()
                if not k.startswith("__") and np.asarray(v).dtype.kind in "fiu"
                and np.asarray(v).size > 1 and min(np.asarray(v).shape) == 1}
        return cols, []
    with open(path, "rb") as fh:
        text, notes = _decode(fh.read())
    lines = [ln for ln in text.splitlines() if ln.strip()]
    if len(lines) < 2:
        raise DataError(f"{name}: need a header row and data rows")
    sep = _sniff(lines)
    rows = [ln.split() for ln in lines] if sep is None else list(csv.reader(lines,
                                                                            delimiter=sep))
    header = [h.strip().strip('"').strip() for h in rows[0]]
    if all(_to_floats([h], True) is not None for h in header if h):
        raise DataError(f"{name}: the first line holds numbers, not column names: add a "
                        f"header row naming the columns")
    for lineno, r in enumerate(rows[1:], start=2):
        if len(r) != len(header):
            raise DataError(f"{name}:{lineno}: {len(r)} fields, header has {len(header)}")
    cols = {}
    for j, h in enumerate(header):
        cells = [r[j] for r in rows[1:]]
        arr = _to_floats(cells, decimal_comma=False)
        if arr is None and sep not in (",", None):
            arr = _to_floats(cells, decimal_comma=True)
        if arr is not None:
            cols[h] = arr
    return cols, notes


@dataclass
class MeasuredRecord:
    """One measured run: time [s] and the columns a connection reads (SI after ``scale``)."""
    t: np.ndarray
    columns: dict
    name: str = "measured"

    def __post_init__(self):
        from friction._validation import check_time
        self.t = np.asarray(self.t, float).ravel()
        if self.t.size < 10:
            raise ConnectError(f"{self.name}: {self.t.size} samples; need at least 10")
        try:
            check_time(self.t)
        except ValueError as exc:
            raise ConnectError(f"{self.name}: {exc}") from None
        cols = {}
        for k, v in self.columns.items():
            v = np.asarray(v, float).ravel()
            if v.size != self.t.size:
                raise ConnectError(f"{self.name}: column {k!r} has {v.size} values, time has "
                                   f"{self.t.size}")
            cols[k] = v
        self.columns = cols

    def column(self, name) -> np.ndarray:
        try:
            return self.columns[name]
        except KeyError:
            raise ConnectError(f"{self.name}: measured column {name!r} not found; columns: "
                               f"{', '.join(sorted(self.columns))}") from None

    @property
    def dt(self) -> float:
        return float(np.median(np.diff(self.t)))

    def window(self, mask) -> "MeasuredRecord":
        return MeasuredRecord(self.t[mask], {k: v[mask] for k, v in self.columns.items()},
                              self.name)


def check_columns(conn: PlantConnection, record: MeasuredRecord) -> None:
    """Every column the connection reads is in the record, finite."""
    for s in conn.inputs:
        _col(conn, record, s.column, f"[inputs] {s.variable}")
    for s in conn.compare:
        _col(conn, record, s.column, f"[compare] {s.variable}")


def _col(conn, record, column, where):
    if column not in record.columns:
        raise ConnectError(f"{record.name}: measured column {column!r} not found (named in "
                           f"{conn.source} {where}); columns: "
                           f"{', '.join(sorted(record.columns))}")
    arr = record.columns[column]
    bad = ~np.isfinite(arr)
    if bad.any():
        i = int(np.argmax(bad))
        raise ConnectError(f"{record.name}: column {column!r} is {arr[i]!r} at t = "
                           f"{record.t[i]:.9g} s (row {i + 1}); measured values must be "
                           f"finite")
    return arr


def load_measured(path, conn: PlantConnection, name: str | None = None) -> MeasuredRecord:
    """A measured file (CSV/.mat) with the columns ``conn`` reads (refused by name if one
    is missing)."""
    cols, _ = read_columns(path)
    label = name or os.path.basename(os.fspath(path))
    if conn.time not in cols:
        raise ConnectError(f"{label}: no time column {conn.time!r} (set time = \"NAME\" in "
                           f"{conn.source}); columns: {', '.join(sorted(cols))}")
    keep = {k: v for k, v in cols.items() if k in conn.columns[1:]}
    for s in conn.inputs:
        if s.column not in cols:
            raise ConnectError(f"{label}: measured column {s.column!r} not found (named in "
                               f"{conn.source} [inputs] {s.variable}); columns: "
                               f"{', '.join(sorted(cols))}")
    for s in conn.compare:
        if s.column not in cols:
            raise ConnectError(f"{label}: measured column {s.column!r} not found (named in "
                               f"{conn.source} [compare] {s.variable}); columns: "
                               f"{', '.join(sorted(cols))}")
    rec = MeasuredRecord(cols[conn.time], keep, label)
    check_columns(conn, rec)
    return rec


# -- the co-simulation -------------------------------------------------------------------------
@dataclass
class PlantRun:
    """One co-simulation: the communication points and the recorded variables on them
    (plant variables by name, the law's force as ``friction.F``)."""
    time: np.ndarray
    values: dict

    def at(self, name, t) -> np.ndarray:
        """Variable ``name`` linearly interpolated at times ``t``."""
        return np.interp(np.asarray(t, float), self.time, self.values[name])


class PlantLoop:
    """The user's plant FMU + a friction-law FMU (+ optionally the ``friction_effects``
    block between them) coupled as ``conn`` says, in one :class:`fmus.master.Master`.

    Parameters
    ----------
    plant_fmu : path
    conn : PlantConnection or path
    law : FrictionModel or str
        The law (its class decides the law FMU and its inputs).
    native : bool
        The native C law FMU ``<law>_native.fmu`` (default) or the pythonfmu one.
    fmu_dir : path, optional
        Folder with the law (and effects) FMUs; default: built once per process.
    effects : bool
        Put the ``friction_effects`` block between law and plant (its parameters go to
        :meth:`run` as ``effects=``); it reads the plant outputs of ``[friction]`` v, a, x,
        load where connected.
    record : list of str
        Further plant outputs to record.
    """

    def __init__(self, plant_fmu, conn, law, *, native: bool = True, fmu_dir=None,
                 effects: bool = False, record=()):
        import friction
        from .master import Master, fmu_file
        self.conn = conn = load_connection(conn)
        self.law_cls = friction.MODELS[law] if isinstance(law, str) else type(law)
        self.plant_vars = check_plant(conn, plant_fmu, self.law_cls)
        self.plant_fmu = os.fspath(plant_fmu)
        self.native, self.effects = bool(native), bool(effects)
        from identification.cosim import fmu_dir_for
        names = [self.law_cls.name] + (["friction_effects"] if effects else [])
        d = fmu_dir_for(names, fmu_dir, self.native)
        fmus = {"plant": self.plant_fmu, **conn.fmus,
                "friction": fmu_file(d, self.law_cls.name, native)}
        law_needs = ("v",) + tuple(self.law_cls.extra_inputs)
        conns = [(conn.ref(conn.law_inputs[k]), f"friction.{k}") for k in law_needs]
        conns += [(conn.ref(a), conn.ref(b)) for a, b in conn.links]
        into_plant = conn.ref(conn.friction_input)
        if effects:
            fmus["effects"] = fmu_file(d, "friction_effects", native)
            conns.append(("friction.F", "effects.F_law"))
            conns.append(("effects.F", into_plant, conn.sign))
            for k, src in conn.law_inputs.items():
                conns.append((conn.ref(src), f"effects.{k}"))
        else:
            conns.append(("friction.F", into_plant, conn.sign))
        self.kinematics = dict(conn.law_inputs)
        keys = [s.variable for s in conn.compare] + list(conn.law_inputs.values()) + \
            [conn.key(n) for n in record]
        self.record = list(dict.fromkeys([conn.ref(k) for k in keys] + ["friction.F"]))
        order = list(conn.order) if conn.order else ["plant", *conn.fmus, "friction"]
        if effects and "effects" not in order:
            order.insert(order.index("friction") + 1, "effects")
        if not effects and "effects" in order:
            order.remove("effects")
        self.master = Master(fmus, conns, algorithm=conn.algorithm, order=order,
                             parameters=self._grouped(conn.parameters),
                             inputs=[conn.ref(s.variable) for s in conn.inputs],
                             record=self.record)
        self._grid_cache = {}

    def _grouped(self, values: dict) -> dict:
        """``{key: value}`` -> ``{instance: {variable: value}}``."""
        out = {"plant": {}, **{inst: {} for inst in self.conn.fmus}}
        for k, v in values.items():
            inst, var = self.conn.split(k)
            out[inst][var] = v
        return out

    def step_for(self, record: MeasuredRecord) -> float:
        return float(self.conn.step) if self.conn.step else record.dt

    def _grid(self, record: MeasuredRecord, start: float | None, stop: float | None = None):
        """Communication grid and the external inputs' values on it (cached per record)."""
        key = (id(record), start, stop)
        hit = self._grid_cache.get(key)
        if hit is not None and hit[0] is record:
            return hit[1:]
        h = self.step_for(record)
        t0 = float(record.t[0]) if start is None else float(start)
        t1 = float(record.t[-1]) if stop is None else float(stop)
        n = max(1, int(math.ceil((t1 - t0) / h - 1e-9)))
        tk = t0 + h * np.arange(n + 1)
        inputs = {}
        for s in self.conn.inputs:
            col = record.column(s.column) * s.scale
            if s.hold == "previous":
                idx = np.clip(np.searchsorted(record.t, tk + 1e-9 * h, side="right") - 1,
                              0, record.t.size - 1)
                vals = col[idx]
            else:
                vals = np.interp(tk + 0.5 * h, record.t, col)
            inputs[self.conn.ref(s.variable)] = vals
        if len(self._grid_cache) > 8:
            self._grid_cache.clear()
        self._grid_cache[key] = (record, t0, h, n, inputs)
        return t0, h, n, inputs

    def run(self, record: MeasuredRecord, law_params: dict, plant_values: dict | None = None,
            effects: dict | None = None, *, start: float | None = None,
            stop: float | None = None) -> PlantRun:
        """Co-simulate over ``record`` (from its first sample, or ``start``, to its last, or
        ``stop``; measured inputs hold their first value before it) with the law's
        parameters (Python values: :func:`fmus.master.law_parameters`), plant parameters on
        top of the connection's, and the effects block's parameters (with ``effects=True``).

        Raises :class:`PlantRunError` naming the time when the plant fails to initialise,
        refuses a step or an output diverges (not finite or beyond :data:`DIVERGED`).
        """
        from .master import FMUError
        t0, h, n, inputs = self._grid(record, start, stop)
        m = self.master
        m.parameters.update(self._grouped({**self.conn.parameters, **(plant_values or {})}))
        m.parameters["friction"] = dict(law_params)
        if self.effects:
            m.parameters["effects"] = dict(effects or {})
        try:
            res = m.simulate(start_time=t0, stop_time=t0 + n * h, step_size=h,
                             inputs=inputs, progress=False)
        except FMUError as exc:
            init = exc.call in ("fmi2Reset", "fmi2SetupExperiment",
                                "fmi2EnterInitializationMode", "fmi2ExitInitializationMode")
            blamed = self._diverged_input(exc) if not init else None
            if blamed is not None:
                raise PlantRunError(blamed, exc.time) from None
            what = "failed to initialise" if init or "(" in exc.call else "failed"
            raise PlantRunError(f"{self._label(exc.instance)} {what}: {exc}", exc.time) \
                from None
        values = {}
        for ref in self.record:
            inst, var = ref.split(".", 1)
            key = var if inst == "plant" else ref
            y = np.asarray(res[ref], float)
            bad = ~np.isfinite(y) | (np.abs(y) > DIVERGED)
            if bad.any():
                k = int(np.argmax(bad))
                raise PlantRunError(
                    f"{self._label(inst)} diverged: output {var!r} is {y[k]!r} at t = "
                    f"{res['time'][k]:.9g} s (communication step {h:.3g} s)",
                    float(res["time"][k]), var)
            values[key] = y
        return PlantRun(np.asarray(res["time"], float), values)

    def _diverged_input(self, exc) -> str | None:
        """The law (or effects) FMU refused a non-finite input mid-run: the plant output
        feeding it diverged. The message naming that output and the time, or None."""
        import re
        if exc.instance == "plant":
            return None
        for msg in reversed(exc.messages):
            m = re.search(r"input (\w+) = (\S+) is not finite", msg)
            if m and m.group(1) in self.kinematics:
                inst, var = self.conn.split(self.kinematics[m.group(1)])
                return (f"{self._label(inst)} diverged: output {var!r} is {m.group(2)} at t = "
                        f"{exc.time:.9g} s (the {exc.instance} FMU refused it as its input "
                        f"{m.group(1)})")
        return None

    def _label(self, inst) -> str:
        if inst == "plant":
            return f"plant FMU {os.path.basename(self.plant_fmu)}"
        if inst in self.conn.fmus:
            return f"{inst} FMU {os.path.basename(self.conn.fmus[inst])}"
        return f"{inst} FMU"

    def close(self):
        if getattr(self, "master", None) is not None:
            self.master.close()
            self.master = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def compared(conn: PlantConnection, record: MeasuredRecord, run: PlantRun) -> list:
    """Per compared channel: ``(spec, measured [SI], simulated at the record's times)``."""
    out = []
    for s in conn.compare:
        out.append((s, record.column(s.column) * s.scale, run.at(s.variable, record.t)))
    return out


# -- the project's own FMUs as special cases ----------------------------------------------------
def builtin_connection(name: str, law=None, **parameters) -> PlantConnection:
    """The connection of one of the project's FMUs: ``"mass"`` (``m dv/dt = u(t) + F_ext -
    F_friction``, drive from its parameters ``u0, u_amp, u_freq``; external force
    ``F_ext`` from a measured column ``F_ext`` if one is given as ``inputs={"F_ext":
    "COLUMN"}``) or a plant of :data:`plants.PLANTS` (external friction, held over a
    communication step). Compared output: ``x`` (mass) or the plant's main output, against
    the column of the same name. ``parameters`` are plant parameters set before each run."""
    inputs = parameters.pop("inputs", {}) or {}
    if name == "mass":
        law_inputs = {"v": "v", "x": "x", "a": "a"}
        compare = [CompareSpec("x", "x")]
    else:
        import friction
        import plants
        from .plant_fmus import plant_connections
        cls = plants.PLANTS[name]
        law_cls = type(law) if law is not None and not isinstance(law, str) else \
            friction.MODELS[law or "lugre"]
        law_inputs = {}
        for src, dst in plant_connections(cls, law_cls, "hold"):
            if dst.startswith("friction."):
                law_inputs[dst.split(".", 1)[1]] = src.split(".", 1)[1]
        outs = cls(external_friction=True).all_output_names
        for k in ("x", "a"):
            if k not in law_inputs and k in outs:
                law_inputs[k] = k
        compare = [CompareSpec(cls.main_output, cls.main_output)]
    return PlantConnection(friction_input="F_friction", sign=1.0, law_inputs=law_inputs,
                           inputs=[InputSpec(k, v) for k, v in inputs.items()],
                           compare=compare, parameters=dict(parameters),
                           source=f"<builtin {name}>")


def with_parameters(conn: PlantConnection, **values) -> PlantConnection:
    """A copy of ``conn`` with further plant parameters set."""
    out = copy.deepcopy(conn)
    out.parameters.update(values)
    return out
