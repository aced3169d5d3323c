"""``modelDescription.xml`` and ``buildDescription.xml`` of a native FMU.

Written from the same :class:`fmus.native.variables.NVar` list as the C table, so the value
references, types, bounds and start values of the description and of the binary agree by
construction. A native FMU declares ``canGetAndSetFMUstate`` and ``canSerializeFMUstate``,
lists its ``SourceFiles`` (FMI 2.0) and also ships ``sources/buildDescription.xml`` (the
layout later FMI versions standardise), and never sets ``needsExecutionTool``.
"""
from __future__ import annotations

import datetime
from xml.dom.minidom import parseString
from xml.etree.ElementTree import Element, SubElement, tostring

from ..modeldescription import add_unit_and_type_definitions
from ..variables import fmi_min_max
from .variables import NVar

__all__ = ["model_description", "build_description", "LOG_CATEGORIES"]

#: log categories the C runtime writes
LOG_CATEGORIES = {"logStatusError": "refused values and calls, failed steps (fmi2Error)",
                  "logAll": "everything else (only with logging on)"}


def _fmt(x: float) -> str:
    return repr(float(x))


def _bounds(v: NVar) -> dict:
    return {k: _fmt(x) for k, x in fmi_min_max(v.lower, v.upper, v.lower_open,
                                                v.upper_open).items()}


def model_description(variables: list[NVar], *, model_identifier: str, guid: str,
                      description: str, sources: list[str], default_experiment: dict,
                      model_exchange: bool, n_event_indicators: int = 0) -> bytes:
    """The ``modelDescription.xml`` bytes.

    Parameters
    ----------
    variables : list of NVar
        In value-reference order.
    model_identifier, guid, description : str
    sources : list of str
        C files (relative to ``sources/``) a host compiles.
    default_experiment : dict
        ``startTime``, ``stopTime``, ``stepSize`` [s].
    model_exchange : bool
        Declare the Model Exchange interface too.
    n_event_indicators : int
        Event indicators of the Model Exchange interface.
    """
    now = datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds")
    root = Element("fmiModelDescription", dict(
        fmiVersion="2.0", modelName=model_identifier, guid=guid, description=description,
        generationTool="frictionlab (native C runtime)", generationDateAndTime=now,
        variableNamingConvention="structured",
        numberOfEventIndicators=str(n_event_indicators if model_exchange else 0)))
    common = dict(modelIdentifier=model_identifier, canGetAndSetFMUstate="true",
                  canSerializeFMUstate="true", canNotUseMemoryManagementFunctions="true",
                  canBeInstantiatedOnlyOncePerProcess="false")
    if model_exchange:
        me = SubElement(root, "ModelExchange", dict(common, completedIntegratorStepNotNeeded="true"))
        sf = SubElement(me, "SourceFiles")
        for s in sources:
            SubElement(sf, "File", dict(name=s))
    cs = SubElement(root, "CoSimulation", dict(
        common, canHandleVariableCommunicationStepSize="true", canInterpolateInputs="false"))
    sf = SubElement(cs, "SourceFiles")
    for s in sources:
        SubElement(sf, "File", dict(name=s))

    add_unit_and_type_definitions(root, variables)
    lc = SubElement(root, "LogCategories")
    for name, desc in LOG_CATEGORIES.items():
        SubElement(lc, "Category", dict(name=name, description=desc))
    SubElement(root, "DefaultExperiment", {k: _fmt(v) for k, v in default_experiment.items()})

    index = {v.name: i + 1 for i, v in enumerate(variables)}
    states = [v.derivative_of for v in variables if v.derivative_of]
    mv = SubElement(root, "ModelVariables")
    for vr, v in enumerate(variables):
        if v.causality == "local" and not model_exchange:
            # derivatives only mean something with the Model Exchange interface
            attrs = dict(name=v.name, valueReference=str(vr), description=v.description,
                         causality="local", variability="continuous", initial="calculated")
        else:
            attrs = dict(name=v.name, valueReference=str(vr), description=v.description,
                         causality=v.causality)
        if v.causality == "parameter":
            attrs.update(variability="tunable", initial="exact")
        elif v.causality == "input":
            attrs.update(variability="continuous")
        elif v.causality == "output":
            attrs.update(variability="continuous")
            attrs["initial"] = "exact" if (v.name in states and v.role == "STATE") \
                else "calculated"
        else:
            attrs.update(variability="continuous", initial="calculated")
        sv = SubElement(mv, "ScalarVariable", attrs)
        t = {}
        if v.type == "Real":
            if v.unit:
                t["unit"] = v.unit
            if v.causality == "parameter":
                t.update(_bounds(v))
            if v.derivative_of and model_exchange:
                t["derivative"] = str(index[v.derivative_of])
        if v.type == "Enumeration":
            t["declaredType"] = v.enum_type
        if v.causality in ("parameter", "input") or attrs.get("initial") == "exact":
            if v.type == "Boolean":
                t["start"] = "true" if v.start else "false"
            elif v.type in ("Integer", "Enumeration"):
                t["start"] = str(int(v.start))
            else:
                t["start"] = _fmt(v.start)
        SubElement(sv, v.type, t)

    state_idx = [index[s] for s in states]
    ms = SubElement(root, "ModelStructure")
    outs = [v for v in variables if v.causality == "output"]
    o = SubElement(ms, "Outputs")
    for v in outs:
        deps = sorted(index[d] for d in v.depends)
        if model_exchange and v.role in ("OUT_F", "OUT_A"):
            deps = sorted(set(deps) | set(state_idx))
        if v.role in ("STATE", "OUT_X", "OUT_V"):
            deps = sorted({index[v.name]} & set(state_idx)) if model_exchange else []
        SubElement(o, "Unknown", dict(index=str(index[v.name]),
                                      dependencies=" ".join(map(str, deps))))
    ders = [v for v in variables if v.derivative_of]
    if model_exchange and ders:
        d = SubElement(ms, "Derivatives")
        for v in ders:
            deps = sorted(set(index[x] for x in v.depends) | set(state_idx))
            SubElement(d, "Unknown", dict(index=str(index[v.name]),
                                          dependencies=" ".join(map(str, deps))))
    iu = SubElement(ms, "InitialUnknowns")
    for v in variables:
        if v.causality == "output" and attrs_initial(v, states) == "calculated":
            SubElement(iu, "Unknown", dict(index=str(index[v.name])))
        elif model_exchange and v.derivative_of:
            SubElement(iu, "Unknown", dict(index=str(index[v.name])))
    return parseString(tostring(root, "UTF-8")).toprettyxml(encoding="UTF-8")


def attrs_initial(v: NVar, states) -> str:
    """``initial`` of an output: a law's state starts at zero (exact), the rest is computed."""
    return "exact" if (v.name in states and v.role == "STATE") else "calculated"


def build_description(model_identifier: str, sources: list[str]) -> bytes:
    """``sources/buildDescription.xml``: one build configuration, the C files, no
    preprocessor definitions or libraries beyond the C library (libm)."""
    root = Element("fmiBuildDescription", dict(fmiVersion="3.0"))
    bc = SubElement(root, "BuildConfiguration", dict(modelIdentifier=model_identifier,
                                                     description="plain C99 and libm"))
    fs = SubElement(bc, "SourceFileSet", dict(language="C99"))
    for s in sources:
        SubElement(fs, "SourceFile", dict(name=s))
    SubElement(bc, "Library", dict(name="m", description="the C math library (libm)"))
    return parseString(tostring(root, "UTF-8")).toprettyxml(encoding="UTF-8")
