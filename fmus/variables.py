"""The variables of the frictionlab FMUs, generated from the parameter dataclasses.

One schema for both FMU kinds: a law's parameters (names, units, bounds, defaults,
descriptions, options) come from its ``Params`` dataclass (``friction.base.param`` metadata and
the ``OPTIONS`` of its option fields), the effects block's from
``friction.extensions.EXTENSION_PARAMS``, a plant's from its ``Params`` and options. The
pythonfmu slaves (:mod:`fmus.runtime`) register these lists and :mod:`fmus.modeldescription`
writes them; the native FMUs (:mod:`fmus.native.variables`) add their C roles to the same
lists. The value reference of a variable is its index in its list.

* an option is an FMI ``Enumeration`` (items in code order, FMI values 1..n), not a String;
* an optional parameter (Python ``None``, e.g. a direction twin ``Fc_neg``) is a Real used
  when its ``Boolean`` flag ``use_<name>`` is true, not a sentinel value;
* an exclusive bound (``sigma0 > 0``) is written as the next representable double
  (:func:`exclusive_min`: ``min = 5e-324``), so a host that checks ``min`` checks the law's
  own bound;
* units have one spelling (:func:`fmus.coupling.fmi_unit`).

This module travels inside every pythonfmu FMU with :mod:`fmus.runtime`; it needs numpy (for
the build-time feedthrough probes only) and the vendored ``friction`` / ``plants`` packages
whose module names the slaves pass in.
"""
from __future__ import annotations

import dataclasses
import importlib
import math

from friction.bounds import Bounded  # the FMU's copy in its runtime package (fmus.build)

from .coupling import (INPUT_INFO, LAW_PORTS, MEAN_INPUT, PLANT_PORTS, SHARE_INPUT,
                       SWITCH_OUTPUTS, COUPLING_OUTPUTS, fmi_unit, has_switch, law_inputs)

__all__ = ["Var", "exclusive_min", "exclusive_max", "fmi_min_max", "param_vars",
           "law_variables", "law_feedthrough", "mass_variables", "effects_variables",
           "EFFECTS_INPUTS", "plant_variables", "plant_feedthrough", "plant_coupling_inputs",
           "block_variables", "BLOCKS", "coupling_variables", "state_unit"]


@dataclasses.dataclass
class Var(Bounded):
    """One FMU variable (what the model description lists and the runtime stores)."""
    name: str
    causality: str                  # "parameter" | "input" | "output"
    type: str = "Real"              # "Real" | "Integer" | "Boolean" | "String" | "Enumeration"
    start: object = 0.0
    unit: str = ""
    description: str = ""
    lower: float = -math.inf
    upper: float = math.inf
    lower_open: bool = False
    upper_open: bool = False
    #: outputs: names of the inputs they depend on directly (feedthrough)
    depends: tuple = ()
    #: Enumeration: item names in code order (FMI values 1..n)
    items: tuple = ()
    #: Enumeration: name of its TypeDefinitions entry
    enum_type: str = ""
    #: parameter: index of the field in its Params dataclass (-1: not a field)
    field: int = -1
    #: Boolean flag ``use_<name>``: the optional parameter it switches on
    twin_of: str = ""

    def __post_init__(self):
        self.unit = fmi_unit(self.unit)

    def bound_text(self) -> str:
        if self.type == "Enumeration":
            return "one of " + ", ".join(f"{k} ({item})" for k, item in enumerate(self.items, 1))
        return Bounded.bound_text(self)

    def admissible(self, value) -> bool:
        if self.type == "Enumeration":
            return isinstance(value, int) and 1 <= value <= len(self.items)
        return Bounded.admissible(self, value)


def exclusive_min(lower: float) -> float:
    """The smallest double admissible under ``x > lower``.

    Parameters
    ----------
    lower : float
        The excluded lower bound.
    """
    return math.nextafter(lower, math.inf)


def exclusive_max(upper: float) -> float:
    """The largest double admissible under ``x < upper``.

    Parameters
    ----------
    upper : float
        The excluded upper bound.
    """
    return math.nextafter(upper, -math.inf)


def fmi_min_max(lower: float, upper: float, lower_open: bool, upper_open: bool) -> dict:
    """``min``/``max`` of a Real in the model description (finite bounds only; an exclusive
    bound as the next representable double inside it).

    Parameters
    ----------
    lower, upper : float
        Bounds (infinite: none).
    lower_open, upper_open : bool
        Whether each bound itself is excluded.
    """
    out = {}
    if math.isfinite(lower):
        out["min"] = exclusive_min(lower) if lower_open else float(lower)
    if math.isfinite(upper):
        out["max"] = exclusive_max(upper) if upper_open else float(upper)
    return out


def _optional_start(f, md, fields) -> float:
    """Start value of an optional parameter's Real (its flag is off): the '+' twin's default,
    else the middle of its search range, else a value inside its bounds."""
    if f.name.endswith("_neg"):
        plus = f.name[:-4]
        for g in fields:
            if g.name == plus and isinstance(g.default, (int, float)):
                return float(g.default)
    if md.get("search"):
        lo, hi = md["search"]
        return math.sqrt(lo * hi) if md.get("log") and lo > 0 else 0.5 * (lo + hi)
    lower = md.get("lower", -math.inf)
    return lower + 1.0 if math.isfinite(lower) else 0.0


def _field_default(f):
    if f.default is not dataclasses.MISSING:
        return f.default
    if f.default_factory is not dataclasses.MISSING:  # type: ignore[misc]
        return f.default_factory()  # type: ignore[misc]
    return dataclasses.MISSING


def param_vars(params_cls, *, strict: bool = False, enum_prefix: str | None = None
               ) -> list[Var]:
    """FMU parameters from a frozen parameter dataclass, in field order, followed by the
    ``use_<name>`` flags of its optional fields.

    Parameters
    ----------
    params_cls : dataclass type
        ``friction.base.param`` metadata (unit, description, bounds) on its fields; options
        in its ``OPTIONS`` mapping (field -> {item: code 0..n-1}).
    strict : bool
        A law's parameters: every field is an option, a Boolean or a number with a unit
        (raises ``ValueError`` otherwise). Else (plants, blocks) a String, an ``int`` without
        metadata (Integer) and a field that is no FMU scalar (skipped) are allowed too.
    enum_prefix : str, optional
        Prefix of the Enumeration type names (default: the dataclass name).
    """
    options = getattr(params_cls, "OPTIONS", {}) or {}
    fields = dataclasses.fields(params_cls)
    prefix = enum_prefix or params_cls.__name__
    out: list[Var] = []
    flags: list[Var] = []
    for k, f in enumerate(fields):
        if f.name.startswith("_"):
            continue
        md = f.metadata
        default = _field_default(f)
        if default is dataclasses.MISSING:
            if strict:
                raise ValueError(f"{params_cls.__name__}.{f.name} has no default")
            continue
        desc = md.get("description", f.name)
        if f.name in options:
            opts = options[f.name]
            items = tuple(sorted(opts, key=opts.get))
            if [opts[i] for i in items] != list(range(len(items))):
                raise ValueError(f"{params_cls.__name__}.OPTIONS[{f.name!r}] codes must be "
                                 f"0..n-1")
            out.append(Var(f.name, "parameter", "Enumeration", items.index(default) + 1,
                           description=f"{f.name}: one of {', '.join(items)}", lower=1,
                           upper=len(items), items=items, enum_type=f"{prefix}.{f.name}",
                           field=k))
            continue
        if isinstance(default, bool):
            out.append(Var(f.name, "parameter", "Boolean", bool(default),
                           description=f.name.replace("_", " ") if strict else desc, field=k))
            continue
        if not strict and isinstance(default, str):
            out.append(Var(f.name, "parameter", "String", default, description=desc, field=k))
            continue
        if not strict and isinstance(default, int) and not md:
            out.append(Var(f.name, "parameter", "Integer", int(default), description=desc,
                           field=k))
            continue
        if default is not None and not isinstance(default, (int, float)):
            if strict:
                raise ValueError(f"{params_cls.__name__}.{f.name} is no FMU scalar")
            continue  # arrays, nested objects: not an FMU scalar
        if strict and "unit" not in md:
            raise ValueError(f"{params_cls.__name__}.{f.name} has no unit metadata and is no "
                             f"option")
        unit = fmi_unit(md.get("unit", ""))
        v = Var(f.name, "parameter", "Real", 0.0, unit, "", md.get("lower", -math.inf),
                md.get("upper", math.inf), md.get("lower_open", False),
                md.get("upper_open", False), field=k)
        if default is None:
            v.start = _optional_start(f, md, fields)
            short = desc.split(" (None")[0]
            v.description = f"{short} [{unit}], used when use_{f.name} is true"
            flags.append(Var(f"use_{f.name}", "parameter", "Boolean", False,
                             description=f"use {f.name} ({desc})", field=k, twin_of=f.name))
        else:
            v.start = float(default)
            v.description = f"{desc} [{unit}]" if unit else desc
        bt = v.bound_text()
        if bt != "finite":
            v.description += f" ({bt})"
        out.append(v)
    return out + flags


#: probe point of the feedthrough test (typical magnitudes; perturbed by 10 % each)
_PROBE = {"v": 1e-3, "a": 0.5, "load": 1e3, "x": 1e-4}


def law_feedthrough(model_cls, inputs) -> tuple:
    """Inputs the force output depends on directly, probed at the default parameters.

    ``F`` is evaluated by the law's ``force(state, v, **inputs)`` at a probe point and with
    each input perturbed; an input that changes ``F`` is a direct dependency. The probe is
    made at the rest state and at the law's steady sliding state at the probe velocity (a
    backlash law's force does not depend on the velocity while the drive crosses its gap,
    as at rest, but does once the contact slides). (A law whose structure changes with a
    parameter, e.g. modified LuGre with tau = 0 where F_d becomes algebraic in ``a``, is
    described at its defaults.)

    Parameters
    ----------
    model_cls : type
        A friction-law class.
    inputs : sequence of str
        The law FMU's inputs (``v`` and the law's ``a``, ``load``, ``x``).
    """
    import numpy as np
    try:
        model = model_cls()
        base = {n: _PROBE[n] for n in inputs}
        rest = np.asarray(model.initial_state(), dtype=float)
        sliding = np.asarray(model.steady_state_state(
            base["v"], **{k: base[k] for k in inputs if k != "v"}), dtype=float)
        deps = set()
        for state in (rest, sliding):

            def F(vals):
                kw = {k: vals[k] for k in inputs if k != "v"}
                return float(model.force(state, vals["v"], **kw))

            f0 = F(base)
            for n in inputs:
                pert = dict(base)
                pert[n] = base[n] * 1.1 + 1e-9
                if abs(F(pert) - f0) > 1e-12 * (1.0 + abs(f0)):
                    deps.add(n)
        return tuple(n for n in inputs if n in deps)
    except Exception:  # noqa: BLE001 - cannot probe: declare every input (safe side)
        return tuple(inputs)


def state_unit(model_cls, j: int) -> str:
    """Unit of the law's state ``j``.

    Parameters
    ----------
    model_cls : type
        A friction-law class.
    j : int
        Index of the state in ``state_names``.
    """
    units = getattr(model_cls, "state_units", None)
    s = model_cls.state_names[j]
    return units[j] if units else ("m" if j == 0 else "N" if s.startswith("F") else "")


def coupling_variables(inputs, switching: bool = False) -> list[Var]:
    """Parameters ``h_lin``, ``inputs_at_step_end`` and the coupling outputs of a law FMU:
    the local linearisation of the law over the coming step (computed from the current
    inputs, so they depend directly on every input; :mod:`fmus.coupling`); with
    ``switching`` first the outputs of :data:`fmus.coupling.SWITCH_OUTPUTS`.

    Parameters
    ----------
    inputs : sequence of str
        The law FMU's inputs.
    switching : bool
        The law's coefficients jump at a speed (:func:`fmus.coupling.has_switch`).
    """
    def out(name):
        unit, description = LAW_PORTS[name]
        return Var(name, "output", "Real", None, unit, f"{description} [{unit}]",
                   depends=tuple(inputs))

    extra = [out(n) for n in SWITCH_OUTPUTS] if switching else []
    return extra + [
        Var("h_lin", "parameter", "Real", 0.0, "s",
            "horizon of the coupling linearisation dF_dx, dF_dv, dF_dt, normally the "
            "communication step [s] (0: not computed, the outputs stay 0) (>= 0)", 0.0),
        Var("inputs_at_step_end", "parameter", "Boolean", False, "",
            "the inputs set before fmi2DoStep are the values at the end of the step "
            "(Gauss-Seidel after the plant): the state advances with the inputs at both "
            "ends (first-order hold) instead of holding them"),
    ] + [out(n) for n in COUPLING_OUTPUTS]


def law_variables(model_cls, probe: bool = False) -> list[Var]:
    """Parameters, inputs and outputs of the FMU of a friction law class (both kinds).

    ``probe=True`` (build time) narrows the declared dependencies of ``F`` to the inputs it
    really depends on (:func:`law_feedthrough`); otherwise all inputs are declared.

    Parameters
    ----------
    model_cls : type
        A friction-law class (``friction.MODELS`` value).
    probe : bool
        Probe the direct dependencies of ``F`` (build time).
    """
    out = param_vars(model_cls.Params, strict=True, enum_prefix=model_cls.name)
    ins = law_inputs(model_cls)
    for n in ins:
        unit, desc = INPUT_INFO[n]
        out.append(Var(n, "input", "Real", 0.0, unit, f"{desc} [{unit}]"))
    switching = has_switch(model_cls)
    if model_cls.state_names:
        unit, desc = LAW_PORTS[MEAN_INPUT]
        out.append(Var(MEAN_INPUT, "input", "Real", 0.0, unit, f"{desc} [{unit}]"))
        out.append(Var("use_v_mean", "parameter", "Boolean", False,
                       description="advance the state over a step with the input v_mean (the "
                                   "plant's travel) instead of the velocities at both ends"))
    if switching:
        unit, desc = LAW_PORTS[SHARE_INPUT]
        out.append(Var(SHARE_INPUT, "input", "Real", 0.0, unit, f"{desc} [{unit}]"))
        out.append(Var("use_low_share", "parameter", "Boolean", False,
                       description="advance the state with the mix of both regimes the "
                                   "input low_share gives (Gauss-Seidel, plant first)"))
    deps = law_feedthrough(model_cls, ins) if probe else tuple(ins)
    out.append(Var("F", "output", "Real", None, "N", "friction force [N]", depends=deps))
    out += coupling_variables(ins, switching)
    for j, s in enumerate(model_cls.state_names):
        unit = state_unit(model_cls, j)
        desc = "bristle deflection" if j == 0 else f"internal state {s}"
        out.append(Var(s, "output", "Real", None, unit,
                       desc + (f" [{unit}]" if unit else ""), depends=()))
    return out


def mass_variables() -> list[Var]:
    """A rigid mass on a line, driven by u(t) = u0 + u_amp sin(2 pi u_freq t) + F_ext - F_friction."""
    return [
        Var("m", "parameter", "Real", 1.0, "kg", "moving mass [kg] (> 0)", 0.0, math.inf, True),
        Var("x0", "parameter", "Real", 0.0, "m", "initial position [m]"),
        Var("v0", "parameter", "Real", 0.0, "m/s", "initial velocity [m/s]"),
        Var("u0", "parameter", "Real", 0.0, "N", "constant drive force [N]"),
        Var("u_amp", "parameter", "Real", 2.0, "N", "amplitude of the sinusoidal drive force [N]"),
        Var("u_freq", "parameter", "Real", 1.0, "Hz", "frequency of the drive force [Hz] (>= 0)",
            0.0),
        Var("F_friction", "input", "Real", 0.0, "N", "friction force opposing the motion [N]"),
        Var("F_ext", "input", "Real", 0.0, "N", "additional external force along +x [N]"),
        Var("x", "output", "Real", None, "m", "position [m]"),
        Var("v", "output", "Real", None, "m/s", "velocity [m/s]"),
        Var("a", "output", "Real", None, "m/s2", "acceleration [m/s2]",
            depends=("F_friction", "F_ext")),
    ]


#: inputs of the friction_effects block: (name, unit, description)
EFFECTS_INPUTS = (("F_law", "N", "force of the friction law"),
                  ("v", "m/s", "sliding velocity"),
                  ("a", "m/s2", "acceleration"),
                  ("x", "m", "position"),
                  ("load", "N", "normal load"))
#: effects block: parameters that must be > 0 (the others are free or switches)
EFFECTS_POSITIVE = ("a_s", "v_c", "T", "L0")
#: parameters of the ``friction_effects`` block that must be >= 0
EFFECTS_NONNEGATIVE = ("m_a", "a_e")


def effects_variables(friction_package: str = "friction") -> list[Var]:
    """Variables of the ``friction_effects`` block: the law's force in, the force with the
    extensions of ``friction.extensions`` out (switches ``use_*``: Booleans).

    Parameters
    ----------
    friction_package : str
        Module name of the ``friction`` package (its vendored name inside an FMU).
    """
    ext = importlib.import_module(f"{friction_package}.extensions")
    out = []
    for k, (name, start, unit, desc) in enumerate(ext.EXTENSION_PARAMS):
        unit = fmi_unit(unit)
        if name.startswith("use_"):
            out.append(Var(name, "parameter", "Boolean", bool(start),
                           description=desc.replace(" on (1) or off (0)", " on"), field=k))
        elif name in EFFECTS_POSITIVE or name in EFFECTS_NONNEGATIVE:
            out.append(Var(name, "parameter", "Real", float(start), unit, f"{desc} [{unit}]",
                           0.0, math.inf, name in EFFECTS_POSITIVE, field=k))
        else:
            out.append(Var(name, "parameter", "Real", float(start), unit, f"{desc} [{unit}]",
                           field=k))
    for name, unit, desc in EFFECTS_INPUTS:
        out.append(Var(name, "input", "Real", 1.0 if name == "load" else 0.0, unit,
                       f"{desc} [{unit}]"))
    out.append(Var("F", "output", "Real", None, "N",
                   "friction force with the switched-on extensions [N]",
                   depends=tuple(n for n, _, _ in EFFECTS_INPUTS)))
    return out


# -- plants and the loop blocks (pythonfmu FMUs only) ------------------------------------------

def _option_vars(options: dict) -> list[Var]:
    """Scalar experiment options of a plant as FMU parameters (None/tuples are not exposed)."""
    out = []
    for k, v in options.items():
        desc = f"experiment option {k} (see the plant's options)"
        if isinstance(v, bool):
            out.append(Var(k, "parameter", "Boolean", v, "", desc))
        elif isinstance(v, str):
            out.append(Var(k, "parameter", "String", v, "", desc))
        elif isinstance(v, (int, float)):
            out.append(Var(k, "parameter", "Real", float(v), "", desc))
    return out


def plant_feedthrough(plant_cls) -> dict:
    """Outputs of the external-friction plant that change at once with ``F_friction``.

    Parameters
    ----------
    plant_cls : type
        A plant class.
    """
    try:
        st = plant_cls(external_friction=True).stepper()
        st.set_inputs({"F_friction": 0.0})
        o0 = st.outputs()
        st.set_inputs({"F_friction": 1.0})
        o1 = st.outputs()
        return {n: ("F_friction",) for n in st.output_names
                if abs(o1[n] - o0[n]) > 1e-12 * (1.0 + abs(o0[n]))}
    except Exception:  # noqa: BLE001 - cannot probe: every output depends (safe side)
        return {n: tuple(plant_cls(external_friction=True).all_input_names)
                for n in plant_cls(external_friction=True).all_output_names}


def plant_coupling_inputs(plant) -> list[Var]:
    """The coupling inputs (:data:`fmus.coupling.PLANT_INPUTS`) a plant FMU in
    external-friction mode takes; none if its stepper does not take them.

    Parameters
    ----------
    plant : Plant
        A plant in external-friction mode.
    """
    names = getattr(plant.stepper(), "coupling_names", ()) if plant.external_friction else ()
    out = []
    for n in names:
        unit, desc = PLANT_PORTS[n]
        out.append(Var(n, "input", "Real", 0.0, unit, f"{desc} [{fmi_unit(unit)}]"))
    return out


def plant_variables(plant_cls, probe: bool = False) -> list[Var]:
    """Parameters (plant ``Params`` and scalar options), inputs and outputs of the FMU of a
    plant in external-friction mode (input ``F_friction``).

    Parameters
    ----------
    plant_cls : type
        A plant class (``plants.PLANTS`` value).
    probe : bool
        Probe which outputs depend directly on ``F_friction`` (build time).
    """
    plant = plant_cls(external_friction=True)
    numeric = set(plant.parameter_names)
    vs = [v for v in param_vars(plant_cls.Params) if v.name in numeric or v.type != "Real"]
    names = {v.name for v in vs}
    vs = [v for v in vs if not v.twin_of or v.twin_of in names]
    vs += [v for v in _option_vars(dict(plant_cls.options)) if v.name not in names]
    signals = dict(getattr(plant_cls, "signals", {}) or {})
    signals.setdefault("F_friction", ("N", "friction force on the contact, opposing the "
                                           "sliding velocity"))
    deps = plant_feedthrough(plant_cls) if probe else \
        {n: tuple(plant.all_input_names) for n in plant.all_output_names}
    for n in plant.all_input_names:
        unit, desc = signals.get(n, ("", n))
        unit = fmi_unit(unit)
        vs.append(Var(n, "input", "Real", 0.0, unit, desc + (f" [{unit}]" if unit else "")))
    vs += plant_coupling_inputs(plant)
    for n in (SHARE_INPUT, MEAN_INPUT):
        signals.setdefault(n, PLANT_PORTS[n])
    outs = plant.all_output_names + tuple(
        n for n in getattr(plant.stepper(), "output_names", ()) if n in (SHARE_INPUT,
                                                                         MEAN_INPUT))
    for n in outs:
        unit, desc = signals.get(n, ("", n))
        unit = fmi_unit(unit)
        vs.append(Var(n, "output", "Real", None, unit, desc + (f" [{unit}]" if unit else ""),
                      depends=tuple(deps.get(n, ()))))
    return vs


#: units of the loop signals (those not in the plant's ``signals``)
_LOOP_UNITS = {"x_d": ("m", "desired position"), "v_d": ("m/s", "desired velocity"),
               "a_d": ("m/s2", "desired acceleration"), "x": ("m", "measured position"),
               "x_f": ("m", "target position of the move"),
               "u_ff": ("m/s2", "friction feedforward (acceleration)"),
               "u": ("m/s2", "acceleration command"),
               "u_sd": ("m/s2", "feedback + acceleration feedforward"),
               "e": ("m", "position error x_d - x"), "i_cmd": ("A", "current command M_ctrl u / Kf"),
               "F_ff": ("N", "feedforward friction force estimate"),
               "x_ff": ("m", "feedforward position"), "v_ff": ("m/s", "feedforward velocity"),
               "a_ff": ("m/s2", "feedforward acceleration")}

BLOCKS = ("sdpid", "pid", "lugre_feedforward", "xml350_trajectory")


def _block_parts(kind: str, plants_package: str):
    """(parameter Var list, input names, output names) of a loop block."""
    xml = importlib.import_module(f"{plants_package}.xml350")
    ctrl = importlib.import_module(f"{plants_package}.controllers")
    P = xml.XML350Params()
    if kind in ("sdpid", "pid"):
        pid = P.pid(state_dependent=kind == "sdpid")
        pv = param_vars(ctrl.PIDParams)
        for v in pv:
            v.start = float(getattr(pid.params, v.name))
        pv += [Var("M_ctrl", "parameter", "Real", P.M_ctrl, "kg",
                   "mass converting acceleration to force in i_cmd [kg] (> 0)", 0.0, math.inf,
                   True),
               Var("Kf", "parameter", "Real", P.Kf, "N/A",
                   "motor force constant converting force to current in i_cmd [N/A] (> 0)",
                   0.0, math.inf, True)]
        return pv, list(ctrl.PID.input_names), list(ctrl.PID.output_names) + ["i_cmd"]
    if kind == "lugre_feedforward":
        law = xml.xml350_friction()
        pv = param_vars(type(law.params), strict=True, enum_prefix=law.name)
        for v in pv:
            if v.twin_of:
                v.start = getattr(law.params, v.twin_of) is not None
                continue
            val = getattr(law.params, v.name)
            if val is None:
                continue  # the flag is off; the Real keeps its start
            if v.type == "Enumeration":
                v.start = v.items.index(val) + 1
            elif v.type == "Boolean":
                v.start = bool(val)
            else:
                v.start = float(val)
        pv += [Var("mass", "parameter", "Real", P.M_ctrl, "kg",
                   "mass converting the friction force to acceleration [kg] (> 0)", 0.0,
                   math.inf, True),
               Var("Ts", "parameter", "Real", P.Ts, "s", "sample time [s] (> 0)", 0.0,
                   math.inf, True)]
        return pv, list(ctrl.LuGreFeedforward.input_names), \
            list(ctrl.LuGreFeedforward.output_names)
    if kind == "xml350_trajectory":
        modes = tuple(xml.TrajectoryBlock.MODES)
        pv = [Var("distance", "parameter", "Real", 1e-4, "m", "S-curve move distance [m]"),
              Var("t_move", "parameter", "Real", 1e-3, "s", "start time of the move [s] (>= 0)",
                  0.0),
              Var("Ts", "parameter", "Real", P.Ts, "s", "sample time [s] (> 0)", 0.0,
                  math.inf, True),
              Var("f_current", "parameter", "Real", P.f_current, "Hz",
                  "current-loop bandwidth used to time the feedforward [Hz] (> 0)", 0.0,
                  math.inf, True),
              Var("ff_mode", "parameter", "Enumeration", modes.index("invert") + 1, "",
                  f"feedforward timing: one of {', '.join(modes)}", 1, len(modes), items=modes,
                  enum_type="xml350_trajectory.ff_mode")]
        return pv, [], list(xml.TrajectoryBlock.output_names)
    raise ValueError(f"unknown block {kind!r}; choose from {BLOCKS}")


def block_variables(kind: str, plants_package: str = "plants") -> list[Var]:
    """Variables of a loop block FMU; outputs depend directly on every input (a block
    samples at the communication point with the inputs just set).

    Parameters
    ----------
    kind : str
        One of :data:`BLOCKS`.
    plants_package : str
        Module name of the ``plants`` package (its vendored name inside an FMU).
    """
    pv, ins, outs = _block_parts(kind, plants_package)
    vs = list(pv)
    for n in ins:
        unit, desc = _LOOP_UNITS.get(n, ("", n))
        vs.append(Var(n, "input", "Real", 0.0, unit, desc + (f" [{unit}]" if unit else "")))
    for n in outs:
        unit, desc = _LOOP_UNITS.get(n, ("", n))
        vs.append(Var(n, "output", "Real", None, unit, desc + (f" [{unit}]" if unit else ""),
                      depends=tuple(ins)))
    return vs
