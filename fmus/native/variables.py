"""Variables of the native FMUs, generated from the Python parameter dataclasses.

One source of truth: a law's FMU parameters (names, units, bounds, defaults, descriptions,
options) come from its ``Params`` dataclass (``friction.base.param`` metadata and the
``OPTIONS`` of its option fields), the effects block's from
``friction.extensions.EXTENSION_PARAMS``, the mass's from ``fmus.runtime.mass_variables``.
The same list becomes the C table (``fl_model.h``, :func:`c_table`) and the
``modelDescription.xml`` (:mod:`fmus.native.description`).

Compared with the pythonfmu FMUs: an option is an FMI ``Enumeration`` (not a String); an
optional parameter (Python ``None``) has a ``Boolean`` flag ``use_<name>`` instead of a
sentinel value; an exclusive bound (``sigma0 > 0``) is written as the next representable
double (``min = 5e-324``), so a host that checks ``min`` checks the law's own bound.
"""
from __future__ import annotations

import dataclasses
import math

from .. import runtime

__all__ = ["NVar", "law_variables", "effects_variables", "mass_variables", "c_table",
           "exclusive_min", "exclusive_max", "law_inputs"]


@dataclasses.dataclass
class NVar:
    """One variable of a native FMU (value reference = its index in the list)."""
    name: str
    type: str                  # Real | Integer | Boolean | Enumeration
    causality: str             # parameter | input | output | local
    role: str                  # FL_R_* role of fl_runtime.h, without the prefix
    idx: int = 0
    start: float = 0.0
    lower: float = -math.inf
    upper: float = math.inf
    lower_open: bool = False
    upper_open: bool = False
    unit: str = ""
    description: str = ""
    depends: tuple = ()        # outputs: the inputs they depend on directly
    enum: tuple = ()           # Enumeration: item names (codes 1..n)
    enum_type: str = ""        # Enumeration: TypeDefinitions name
    derivative_of: str = ""    # Model Exchange: name of the state this is the derivative of

    def bound_text(self) -> str:
        parts = []
        if self.lower > -math.inf:
            parts.append(f"{'>' if self.lower_open else '>='} {self.lower:g}")
        if self.upper < math.inf:
            parts.append(f"{'<' if self.upper_open else '<='} {self.upper:g}")
        return " and ".join(parts)


def exclusive_min(lower: float) -> float:
    """The smallest double admissible under ``x > lower``."""
    return math.nextafter(lower, math.inf)


def exclusive_max(upper: float) -> float:
    """The largest double admissible under ``x < upper``."""
    return math.nextafter(upper, -math.inf)


def law_inputs(model_cls) -> list[str]:
    """Kinematic inputs of a law's FMU: ``v`` and whichever of ``a``, ``load``, ``x``."""
    return ["v"] + [n for n in ("a", "load", "x") if n in model_cls.extra_inputs]


def _unit(u: str) -> str:
    # one spelling of the units in every FMU (m/s2, not m/s^2)
    return u.replace("^", "")


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


def law_variables(model_cls) -> list[NVar]:
    """Variables of the native FMU of a friction law class (``friction.MODELS`` entry)."""
    P = model_cls.Params
    options = getattr(P, "OPTIONS", {})
    fields = dataclasses.fields(P)
    out: list[NVar] = []
    flags: list[NVar] = []
    for k, f in enumerate(fields):
        md = f.metadata
        desc = md.get("description", f.name)
        if f.name in options:
            items = tuple(sorted(options[f.name], key=options[f.name].get))
            if [options[f.name][i] for i in items] != list(range(len(items))):
                raise ValueError(f"{P.__name__}.OPTIONS[{f.name!r}] codes must be 0..n-1")
            out.append(NVar(f.name, "Enumeration", "parameter", "PARAM", k,
                            start=items.index(f.default) + 1, lower=1, upper=len(items),
                            description=f"{f.name}: one of {', '.join(items)}",
                            enum=items, enum_type=f"{model_cls.name}.{f.name}"))
            continue
        if isinstance(f.default, bool):
            out.append(NVar(f.name, "Boolean", "parameter", "PARAM", k, start=float(f.default),
                            description=f.name.replace("_", " ")))
            continue
        if "unit" not in md:
            raise ValueError(f"{P.__name__}.{f.name} has no unit metadata and is no option")
        lower, upper = md["lower"], md["upper"]
        unit = _unit(md["unit"])
        v = NVar(f.name, "Real", "parameter", "PARAM", k, lower=lower, upper=upper,
                 lower_open=md["lower_open"], upper_open=md["upper_open"], unit=unit)
        if f.default is None:
            v.start = _optional_start(f, md, fields)
            short = desc.split(" (None")[0]
            v.description = f"{short} [{unit}], used when use_{f.name} is true"
            flags.append(NVar(f"use_{f.name}", "Boolean", "parameter", "TWIN_FLAG", k,
                              start=0.0, description=f"use {f.name} ({desc})"))
        else:
            v.start = float(f.default)
            v.description = f"{desc} [{unit}]"
        bt = v.bound_text()
        if bt:
            v.description += f" ({bt})"
        out.append(v)
    out += flags
    ins = law_inputs(model_cls)
    roles = {"v": "IN_V", "a": "IN_A", "load": "IN_LOAD", "x": "IN_X"}
    for n in ins:
        unit, desc = runtime.INPUT_INFO[n]
        out.append(NVar(n, "Real", "input", roles[n], unit=unit, description=f"{desc} [{unit}]"))
    switching = runtime.has_switch(model_cls)
    if model_cls.state_names:
        out.append(NVar(runtime.MEAN_INPUT, "Real", "input", "IN_VMEAN", unit="m/s",
                        description="mean velocity over the last step, travel / step "
                                    "(connect plant.v_mean; used with use_v_mean) [m/s]"))
        out.append(NVar("use_v_mean", "Boolean", "parameter", "USE_VMEAN",
                        description="advance the state over a step with the input v_mean (the "
                                    "plant's travel) instead of the velocities at both ends"))
    if switching:
        out.append(NVar(runtime.SHARE_INPUT, "Real", "input", "IN_SHARE", unit="1",
                        description="share of the last step the plant spent below v_switch "
                                    "(connect plant.low_share; used with use_low_share and "
                                    "inputs_at_step_end) [1]"))
        out.append(NVar("use_low_share", "Boolean", "parameter", "USE_SHARE",
                        description="advance the state with the mix of both regimes the "
                                    "input low_share gives (Gauss-Seidel, plant first)"))
    deps = runtime.law_feedthrough(model_cls, ins)
    out.append(NVar("F", "Real", "output", "OUT_F", unit="N", description="friction force [N]",
                    depends=deps))
    lin_names = runtime.COUPLING_OUTPUTS + (runtime.SWITCH_OUTPUTS if switching else ())
    for v in runtime.coupling_variables(ins, switching):
        if v.causality == "parameter":
            role = "H_LIN" if v.name == "h_lin" else "FOH"
            nv = NVar(v.name, v.type, "parameter", role, start=float(v.start), unit=v.unit,
                      description=v.description, lower=v.lower)
            out.append(nv)
        else:
            out.append(NVar(v.name, "Real", "output", "OUT_LIN", lin_names.index(v.name),
                            unit=_unit(v.unit), description=v.description.replace("^", ""),
                            depends=tuple(v.depends)))
    units = getattr(model_cls, "state_units", None)
    for j, s in enumerate(model_cls.state_names):
        unit = units[j] if units else ("m" if j == 0 else "N" if s.startswith("F") else "")
        desc = "bristle deflection" if j == 0 else f"internal state {s}"
        out.append(NVar(s, "Real", "output", "STATE", j, unit=unit,
                        description=f"{desc}" + (f" [{unit}]" if unit else "")))
    for j, s in enumerate(model_cls.state_names):
        unit = units[j] if units else ("m" if j == 0 else "N" if s.startswith("F") else "")
        out.append(NVar(f"der({s})", "Real", "local", "DER", j,
                        unit=f"{unit}/s" if unit else "1/s",
                        description=f"time derivative of {s} (Model Exchange)",
                        derivative_of=s, depends=deps))
    return out


#: effects block: parameters that must be > 0 (the others are free or switches)
_EFFECTS_POSITIVE = ("a_s", "v_c", "T", "L0")
_EFFECTS_INPUTS = (("F", "IN_F", "N", "force of the friction law"),
                   ("v", "IN_V", "m/s", "sliding velocity"),
                   ("a", "IN_A", "m/s2", "acceleration"),
                   ("x", "IN_X", "m", "position"),
                   ("load", "IN_LOAD", "N", "normal load"))


def effects_variables() -> list[NVar]:
    """Variables of the native ``friction_effects`` block (``friction.extensions``)."""
    from friction import extensions as ext
    out = []
    for k, (name, start, unit, desc) in enumerate(ext.EXTENSION_PARAMS):
        unit = _unit(unit)
        if name.startswith("use_"):
            out.append(NVar(name, "Boolean", "parameter", "EXT", k, start=float(start),
                            description=desc.replace(" on (1) or off (0)", " on")))
        elif name in _EFFECTS_POSITIVE:
            out.append(NVar(name, "Real", "parameter", "EXT", k, start=float(start), lower=0.0,
                            lower_open=True, unit=unit, description=f"{desc} [{unit}]"))
        else:
            out.append(NVar(name, "Real", "parameter", "EXT", k, start=float(start), unit=unit,
                            description=f"{desc} [{unit}]"))
    for name, role, unit, desc in _EFFECTS_INPUTS:
        out.append(NVar(name if name != "F" else "F_law", "Real", "input", role,
                        start=1.0 if name == "load" else 0.0, unit=unit,
                        description=f"{desc} [{unit}]"))
    out.append(NVar("F", "Real", "output", "OUT_F", unit="N",
                    description="friction force with the switched-on extensions [N]",
                    depends=("F_law", "v", "a", "x", "load")))
    return out


def mass_variables() -> list[NVar]:
    """Variables of the native rigid mass (the pythonfmu mass's, plus its derivatives)."""
    out = []
    k = 0
    for v in runtime.mass_variables():
        if v.causality == "parameter":
            out.append(NVar(v.name, "Real", "parameter", "MASS_PARAM", k, start=float(v.start),
                            lower=v.lower, upper=v.upper, lower_open=v.lower_open,
                            upper_open=v.upper_open, unit=v.unit, description=v.description))
            k += 1
        elif v.causality == "input":
            out.append(NVar(v.name, "Real", "input",
                            "IN_FEXT" if v.name == "F_ext" else "IN_FFRIC", start=float(v.start),
                            unit=v.unit, description=v.description))
        else:
            role = {"x": "OUT_X", "v": "OUT_V", "a": "OUT_A"}[v.name]
            out.append(NVar(v.name, "Real", "output", role, unit=_unit(v.unit),
                            description=v.description, depends=tuple(v.depends)))
    names = [v.name for v in out]
    if names[:6] != ["m", "x0", "v0", "u0", "u_amp", "u_freq"]:
        raise ValueError(f"mass parameters changed order: {names[:6]} (fl_fmi2.c reads them "
                         "by index)")
    out.append(NVar("der(x)", "Real", "local", "DER", 0, unit="m/s",
                    description="velocity, time derivative of x (Model Exchange)",
                    derivative_of="x"))
    out.append(NVar("der(v)", "Real", "local", "DER", 1, unit="m/s2",
                    description="acceleration, time derivative of v (Model Exchange)",
                    derivative_of="v", depends=("F_ext", "F_friction")))
    return out


_TYPES = {"Real": "FL_REAL", "Integer": "FL_INTEGER", "Boolean": "FL_BOOLEAN",
          "Enumeration": "FL_ENUM"}
_CAUS = {"parameter": "FL_PARAMETER", "input": "FL_INPUT", "output": "FL_OUTPUT",
         "local": "FL_LOCAL"}


def _c_double(x: float) -> str:
    if math.isnan(x):
        return "NAN"
    if math.isinf(x):
        return "INFINITY" if x > 0 else "-INFINITY"
    return repr(float(x))


def _c_str(s: str) -> str:
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def c_table(variables: list[NVar]) -> str:
    """The ``FL_VARS`` initializer of ``fl_model.h``."""
    rows = []
    for v in variables:
        rows.append("    {%s, %s, %s, FL_R_%s, %d, %s, %s, %s, %d, %d, %s}" % (
            _c_str(v.name), _TYPES[v.type], _CAUS[v.causality], v.role, v.idx,
            _c_double(v.start), _c_double(v.lower), _c_double(v.upper), int(v.lower_open),
            int(v.upper_open), _c_str(v.unit)))
    return "static const fl_var FL_VARS[FL_NVARS] = {\n" + ",\n".join(rows) + "\n};\n"
