"""Write a complete FMI 2.0 co-simulation ``modelDescription.xml`` from a variable list.

pythonfmu's own description has no units, no bounds and no output dependencies; tools then
report false algebraic loops. This module writes the description from the same
:class:`fmus.variables.Var` list the slave registers (value reference = list index):

* ``UnitDefinitions`` with SI ``BaseUnit`` exponents for every unit string used
  (``N.s/m``, ``m/s2``, ``m3/s`` ...);
* ``TypeDefinitions`` with the Enumerations of the options (``shape``: ``gaussian``,
  ``lorentzian``), values 1..n;
* ``Real`` attributes ``unit``, ``start``, ``min``/``max`` from the parameter bounds (an
  exclusive bound as the next representable double, :func:`fmus.variables.fmi_min_max`);
* ``canGetAndSetFMUstate`` / ``canSerializeFMUstate`` as the slave kind supports them;
* ``ModelStructure``: every output with the inputs it depends on directly, and the
  ``InitialUnknowns`` (all outputs are ``initial="calculated"``) with their dependencies on
  inputs and parameters.
"""
from __future__ import annotations

import datetime
import re
from xml.dom.minidom import parseString
from xml.etree.ElementTree import Element, SubElement, tostring

from .variables import fmi_min_max

__all__ = ["base_unit", "model_description_xml", "add_unit_and_type_definitions"]

# SI base-unit exponents (kg, m, s, A, K, mol, cd, rad) of the symbols we use
_SYMBOLS = {
    "1": {}, "m": {"m": 1}, "s": {"s": 1}, "kg": {"kg": 1}, "A": {"A": 1}, "K": {"K": 1},
    "rad": {"rad": 1}, "mol": {"mol": 1}, "cd": {"cd": 1},
    "N": {"kg": 1, "m": 1, "s": -2}, "Pa": {"kg": 1, "m": -1, "s": -2},
    "J": {"kg": 1, "m": 2, "s": -2}, "W": {"kg": 1, "m": 2, "s": -3},
    "Hz": {"s": -1}, "V": {"kg": 1, "m": 2, "s": -3, "A": -1},
    "T": {"kg": 1, "s": -2, "A": -1}, "Ohm": {"kg": 1, "m": 2, "s": -3, "A": -2},
}
_TOKEN = re.compile(r"^([A-Za-z]+|1)(?:\^?(-?\d+))?$")


def base_unit(unit: str) -> dict[str, int] | None:
    """SI base-unit exponents of a unit string such as ``"N.s/m"`` or ``"m/s^2"``.

    Returns ``None`` when a symbol is unknown (the unit is then declared without a
    ``BaseUnit``, which FMI allows).

    Parameters
    ----------
    unit : str
        A unit string (``"N.s/m"``, ``"m/s^2"``, ``"m/s2"``).
    """
    exps: dict[str, int] = {}
    parts = unit.replace("*", ".").split("/")
    for k, part in enumerate(parts):
        sign = 1 if k == 0 else -1
        for tok in filter(None, part.split(".")):
            m = _TOKEN.match(tok.strip())
            if not m:
                return None
            sym, power = m.group(1), int(m.group(2) or 1)
            if sym not in _SYMBOLS:
                # trailing digits glued to the symbol, e.g. "s2", "m3"
                m2 = re.match(r"^([A-Za-z]+?)(\d+)$", tok)
                if not m2 or m2.group(1) not in _SYMBOLS:
                    return None
                sym, power = m2.group(1), int(m2.group(2))
            for b, e in _SYMBOLS[sym].items():
                exps[b] = exps.get(b, 0) + sign * power * e
    return {b: e for b, e in exps.items() if e != 0}


def _fmt(x: float) -> str:
    return repr(float(x))


def add_unit_and_type_definitions(root, variables) -> None:
    """``UnitDefinitions`` (SI ``BaseUnit`` exponents of every Real's unit) and
    ``TypeDefinitions`` (the Enumerations, values 1..n) of either FMU kind's variables
    (:class:`fmus.variables.Var` items, :class:`fmus.native.variables.NVar` enum).

    Parameters
    ----------
    root : xml.etree.ElementTree.Element
        The ``fmiModelDescription`` element.
    variables : sequence
        The FMU's variables.
    """
    units = sorted({v.unit for v in variables if v.type == "Real" and v.unit})
    if units:
        ud = SubElement(root, "UnitDefinitions")
        for u in units:
            el = SubElement(ud, "Unit", dict(name=u))
            bu = base_unit(u)
            if bu is not None:
                SubElement(el, "BaseUnit", {k: str(e) for k, e in bu.items()})
    enums = {}
    for v in variables:
        if v.type == "Enumeration":
            enums.setdefault(v.enum_type, getattr(v, "items", None) or v.enum)
    if enums:
        td = SubElement(root, "TypeDefinitions")
        for name, items in enums.items():
            en = SubElement(SubElement(td, "SimpleType", dict(name=name)), "Enumeration")
            for k, item in enumerate(items, 1):
                SubElement(en, "Item", dict(name=item, value=str(k)))


def model_description_xml(variables, *, model_identifier: str, guid: str, description: str = "",
                          default_experiment: dict | None = None, log_categories=None,
                          generation_tool: str = "frictionlab (pythonfmu runtime)",
                          state: bool = False) -> bytes:
    """Return the ``modelDescription.xml`` bytes for ``variables`` (a list of ``Var``).

    Parameters
    ----------
    variables : list of fmus.variables.Var
        In value-reference order.
    model_identifier, guid, description : str
    default_experiment : dict, optional
        ``startTime``, ``stopTime``, ``stepSize`` (and ``tolerance``) [s].
    log_categories : dict, optional
        name -> description.
    state : bool
        The slave saves and restores its whole state, also serialized
        (``canGetAndSetFMUstate``, ``canSerializeFMUstate``).
    generation_tool : str
        The ``generationTool`` attribute.
    """
    now = datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds")
    root = Element("fmiModelDescription", dict(
        fmiVersion="2.0", modelName=model_identifier, guid=guid, description=description,
        generationTool=generation_tool, generationDateAndTime=now,
        variableNamingConvention="structured", numberOfEventIndicators="0"))
    SubElement(root, "CoSimulation", dict(
        modelIdentifier=model_identifier, needsExecutionTool="true",
        canHandleVariableCommunicationStepSize="true", canInterpolateInputs="false",
        canBeInstantiatedOnlyOncePerProcess="false", canNotUseMemoryManagementFunctions="true",
        canGetAndSetFMUstate=str(bool(state)).lower(),
        canSerializeFMUstate=str(bool(state)).lower()))

    add_unit_and_type_definitions(root, variables)
    if log_categories:
        lc = SubElement(root, "LogCategories")
        for name, desc in log_categories.items():
            SubElement(lc, "Category", dict(name=name, description=desc))
    if default_experiment:
        SubElement(root, "DefaultExperiment",
                   {k: _fmt(v) for k, v in default_experiment.items() if v is not None})

    mv = SubElement(root, "ModelVariables")
    for vr, v in enumerate(variables):
        attrs = dict(name=v.name, valueReference=str(vr), description=v.description,
                     causality=v.causality)
        if v.causality == "parameter":
            attrs.update(variability="tunable", initial="exact")
        elif v.causality == "input":
            attrs.update(variability="continuous" if v.type == "Real" else "discrete")
        else:
            attrs.update(variability="continuous" if v.type == "Real" else "discrete",
                         initial="calculated")
        sv = SubElement(mv, "ScalarVariable", attrs)
        tattrs = {}
        if v.type == "Real":
            if v.unit:
                tattrs["unit"] = v.unit
            if v.causality == "parameter":
                tattrs.update({k: _fmt(x) for k, x in fmi_min_max(
                    v.lower, v.upper, v.lower_open, v.upper_open).items()})
        elif v.type == "Enumeration":
            tattrs["declaredType"] = v.enum_type
        if v.causality != "output":
            if v.type == "Real":
                tattrs["start"] = _fmt(v.start)
            elif v.type == "Boolean":
                tattrs["start"] = "true" if v.start else "false"
            elif v.type in ("Integer", "Enumeration"):
                tattrs["start"] = str(int(v.start))
            else:
                tattrs["start"] = str(v.start)
        SubElement(sv, v.type, tattrs)

    index = {v.name: i + 1 for i, v in enumerate(variables)}
    params = [index[v.name] for v in variables if v.causality == "parameter"]
    ms = SubElement(root, "ModelStructure")
    outs = [v for v in variables if v.causality == "output"]
    if outs:
        o = SubElement(ms, "Outputs")
        for v in outs:
            deps = [index[d] for d in v.depends]
            SubElement(o, "Unknown", dict(index=str(index[v.name]),
                                          dependencies=" ".join(map(str, deps)),
                                          dependenciesKind=" ".join(["dependent"] * len(deps))))
        iu = SubElement(ms, "InitialUnknowns")
        for v in outs:
            deps = sorted([index[d] for d in v.depends] + params)
            SubElement(iu, "Unknown", dict(index=str(index[v.name]),
                                           dependencies=" ".join(map(str, deps)),
                                           dependenciesKind=" ".join(["dependent"] * len(deps))))
    return parseString(tostring(root, "UTF-8")).toprettyxml(encoding="UTF-8")
