"""Variables of the native FMUs, generated from the Python parameter dataclasses.

One source of truth for both FMU kinds: the variable lists of :mod:`fmus.variables` (a law's
parameters from its ``Params`` dataclass, options as ``Enumeration``, optional values with a
``Boolean`` flag ``use_<name>``, exclusive bounds as the next representable double), here with
each variable's role in the C runtime. The same list becomes the C table (``fl_model.h``,
:func:`c_table`) and the ``modelDescription.xml`` (:mod:`fmus.native.description`).
"""
from __future__ import annotations

import dataclasses
import math

from .. import coupling
from .. import variables as shared
from ..coupling import law_inputs  # noqa: F401 (re-exported)
from ..variables import Var, exclusive_max, exclusive_min  # noqa: F401 (re-exported)

__all__ = ["NVar", "law_variables", "effects_variables", "mass_variables", "c_table",
           "exclusive_min", "exclusive_max", "law_inputs", "emps_axis_variables",
           "emps_controller_variables", "EMPS_PARAMS", "EMPS_FEEDBACK"]


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


def _native(v: Var, role: str, idx: int = 0, **kw) -> NVar:
    """A shared :class:`fmus.variables.Var` with its C role."""
    t = v.type
    start = kw.pop("start", None)
    if start is None:
        start = 0.0 if v.start is None else \
            int(v.start) if t == "Enumeration" else float(v.start)
    return NVar(v.name, t, v.causality, role, idx, start=start,
                lower=kw.pop("lower", v.lower if t == "Real" else
                             (1 if t == "Enumeration" else -math.inf)),
                upper=kw.pop("upper", v.upper if t == "Real" else
                             (len(v.items) if t == "Enumeration" else math.inf)),
                lower_open=v.lower_open, upper_open=v.upper_open, unit=v.unit,
                description=v.description, depends=tuple(v.depends), enum=tuple(v.items),
                enum_type=v.enum_type, **kw)


_INPUT_ROLES = {"v": "IN_V", "a": "IN_A", "load": "IN_LOAD", "x": "IN_X",
                coupling.MEAN_INPUT: "IN_VMEAN", coupling.SHARE_INPUT: "IN_SHARE"}
_PARAM_ROLES = {"use_v_mean": "USE_VMEAN", "use_low_share": "USE_SHARE", "h_lin": "H_LIN",
                "inputs_at_step_end": "FOH"}


def law_variables(model_cls) -> list[NVar]:
    """Variables of the native FMU of a friction law class (``friction.MODELS`` entry): the
    shared list (:func:`fmus.variables.law_variables`, feedthrough probed) with the C roles,
    plus the states' derivatives (Model Exchange)."""
    switching = coupling.has_switch(model_cls)
    lin_names = coupling.COUPLING_OUTPUTS + (coupling.SWITCH_OUTPUTS if switching else ())
    out: list[NVar] = []
    deps = ()
    for v in shared.law_variables(model_cls, probe=True):
        if v.causality == "parameter":
            if v.field >= 0:
                out.append(_native(v, "TWIN_FLAG" if v.twin_of else "PARAM", v.field))
            else:
                out.append(_native(v, _PARAM_ROLES[v.name]))
        elif v.causality == "input":
            out.append(_native(v, _INPUT_ROLES[v.name]))
        elif v.name == "F":
            deps = tuple(v.depends)
            out.append(_native(v, "OUT_F"))
        elif v.name in lin_names:
            out.append(_native(v, "OUT_LIN", lin_names.index(v.name)))
        else:
            out.append(_native(v, "STATE", model_cls.state_names.index(v.name)))
    for j, s in enumerate(model_cls.state_names):
        unit = shared.state_unit(model_cls, j)
        out.append(NVar(f"der({s})", "Real", "local", "DER", j,
                        unit=f"{unit}/s" if unit else "1/s",
                        description=f"time derivative of {s} (Model Exchange)",
                        derivative_of=s, depends=deps))
    return out


_EFFECTS_ROLES = {"F_law": "IN_F", "v": "IN_V", "a": "IN_A", "x": "IN_X", "load": "IN_LOAD"}


def effects_variables() -> list[NVar]:
    """Variables of the native ``friction_effects`` block (``friction.extensions``): the
    shared list (:func:`fmus.variables.effects_variables`) with the C roles."""
    out = []
    for v in shared.effects_variables():
        if v.causality == "parameter":
            out.append(_native(v, "EXT", v.field))
        elif v.causality == "input":
            out.append(_native(v, _EFFECTS_ROLES[v.name]))
        else:
            out.append(_native(v, "OUT_F"))
    return out


def mass_variables() -> list[NVar]:
    """Variables of the native rigid mass (the pythonfmu mass's, plus its derivatives)."""
    out = []
    k = 0
    for v in shared.mass_variables():
        if v.causality == "parameter":
            out.append(_native(v, "MASS_PARAM", k))
            k += 1
        elif v.causality == "input":
            out.append(_native(v, "IN_FEXT" if v.name == "F_ext" else "IN_FFRIC"))
        else:
            out.append(_native(v, {"x": "OUT_X", "v": "OUT_V", "a": "OUT_A"}[v.name]))
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


#: the EMPS FMUs' parameters in the C index order of ``FL_EP_*`` (fl_emps.h reads them by
#: these names; a name an FMU lacks gets no define)
EMPS_PARAMS = ("M", "gtau", "kp", "kv", "Ts", "u_max", "delay", "pulse_gain",
               "position_feedback", "x0", "v0", "u0")
#: position feedback of the EMPS controller (Enumeration items, codes 1..n)
EMPS_FEEDBACK = ("sample", "average")


def _emps_param(name: str) -> NVar:
    """One EMPS parameter: the fields of :class:`plants.emps.EMPSParams` with their units,
    bounds and descriptions; the initial conditions and the feedback switch here."""
    from plants.emps import EMPSParams
    k = EMPS_PARAMS.index(name)
    own = {v.name: v for v in shared.param_vars(EMPSParams)}
    if name in own:
        return _native(own[name], "EMPS_PARAM", k)
    extra = {
        "position_feedback": Var("position_feedback", "parameter", "Enumeration", 1,
                                 description="position in the error: sample (the sampled "
                                             "position, what the recorded vir obeys) or "
                                             "average (the two-sample average qf)",
                                 lower=1, upper=len(EMPS_FEEDBACK), items=EMPS_FEEDBACK,
                                 enum_type="EMPS.position_feedback"),
        "x0": Var("x0", "parameter", "Real", 0.0, "m", "initial position [m]"),
        "v0": Var("v0", "parameter", "Real", 0.0, "m/s", "initial velocity [m/s] (the "
                  "controller: the velocity before the start, on which its two earlier "
                  "position samples lie)"),
        "u0": Var("u0", "parameter", "Real", 0.0, "V", "voltage acting before the first "
                  "sample's voltage reaches the carriage [V]"),
    }
    return _native(extra[name], "EMPS_PARAM", k)


def emps_axis_variables() -> list[NVar]:
    """Variables of the native EMPS axis (:mod:`fmus.native.csrc` ``fl_emps.h``): mass driven
    by ``gtau`` times the sampled, delayed voltage ``u`` against the friction force input."""
    out = [_emps_param(n) for n in ("M", "gtau", "Ts", "delay", "x0", "v0", "u0")]
    out += [NVar("u", "Real", "input", "IN_U", unit="V",
                 description="drive voltage [V], sampled at start + k Ts (its value at the "
                             "sample instant), acting delay seconds later"),
            NVar("F_friction", "Real", "input", "IN_FFRIC", unit="N",
                 description="friction force opposing the motion [N]"),
            NVar("x", "Real", "output", "OUT_X", unit="m", description="carriage position [m]"),
            NVar("v", "Real", "output", "OUT_V", unit="m/s",
                 description="carriage velocity [m/s]"),
            NVar("a", "Real", "output", "OUT_A", unit="m/s2",
                 description="carriage acceleration [m/s2] (with the voltage acting right "
                             "after the communication point)", depends=("F_friction",))]
    return out


def emps_controller_variables() -> list[NVar]:
    """Variables of the native EMPS position controller (``fl_emps.h``): sampled at 1/Ts,
    two-sample average, backward difference, saturation, pulse voltage at its output."""
    out = [_emps_param(n) for n in ("kp", "kv", "Ts", "u_max", "pulse_gain", "gtau",
                                    "position_feedback", "v0")]
    out += [NVar("x", "Real", "input", "IN_X", unit="m",
                 description="measured carriage position [m]"),
            NVar("qg", "Real", "input", "IN_QG", unit="m",
                 description="reference position [m]"),
            NVar("pulse", "Real", "input", "IN_PULSE",
                 description="pulse signal (the PULSES file's 0/5), added as pulse_gain * "
                             "pulse volts at the output"),
            NVar("u", "Real", "output", "OUT_U", unit="V",
                 description="controller output voltage (vir) of the last sample [V]",
                 depends=("x", "qg", "pulse")),
            NVar("F_motor", "Real", "output", "OUT_FMOTOR", unit="N",
                 description="motor force gtau * u of the last sample [N]",
                 depends=("x", "qg", "pulse"))]
    return out
