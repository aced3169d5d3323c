"""python-control's meta-tests (``docstrings_test.py``, ``kwargs_test.py``) for frictionlab.

* every public function, method and constructor (what each package's ``__all__`` exports,
  and for an exported module what its ``__all__`` exports) documents every parameter in a
  numpydoc ``Parameters`` section;
* a public function taking ``**kwargs`` documents it and refuses an unknown keyword with
  ``TypeError``;
* every example in ``examples/`` has a ``run_*`` function and a ``__main__`` guard, and the
  tests below run each (cheaply: the ``quick`` arguments).
"""
from __future__ import annotations

import ast
import importlib
import importlib.util
import inspect
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
PACKAGES = ("friction", "plants", "fmus", "identification", "diagnosis")

_HEADER = re.compile(r"^\s*-{3,}\s*$")


# -- collecting the public callables ----------------------------------------------------------
def _own(obj) -> bool:
    mod = getattr(obj, "__module__", None) or ""
    return mod.split(".")[0] in PACKAGES + ("frictionlab",)


def _exported():
    """(qualified name, object) of every public function and class the packages export."""
    seen, out = set(), []

    def add(prefix, obj):
        if id(obj) in seen or not _own(obj):
            return
        seen.add(id(obj))
        out.append((f"{obj.__module__}.{obj.__qualname__}", obj))

    for pkg in PACKAGES:
        mod = importlib.import_module(pkg)
        for name in getattr(mod, "__all__", ()):
            obj = getattr(mod, name, None)
            if obj is None:  # a submodule the package lists without importing it
                obj = importlib.import_module(f"{pkg}.{name}")
            if inspect.ismodule(obj):
                for sub in getattr(obj, "__all__", ()):
                    o = getattr(obj, sub)
                    if inspect.isfunction(o) or inspect.isclass(o):
                        add(obj.__name__, o)
            elif inspect.isfunction(obj) or inspect.isclass(obj):
                add(pkg, obj)
    return out


def _generated(fn) -> bool:
    """A method written by dataclasses or an Enum (no source of its own)."""
    code = getattr(fn, "__code__", None)
    return code is None or code.co_filename.startswith("<")


def _params(fn, skip_first: bool) -> list[str]:
    try:
        sig = inspect.signature(fn)
    except (TypeError, ValueError):
        return []
    names = []
    for k, p in enumerate(sig.parameters.values()):
        if k == 0 and skip_first:
            continue
        if p.kind is p.VAR_POSITIONAL:
            names.append("*" + p.name)
        elif p.kind is p.VAR_KEYWORD:
            names.append("**" + p.name)
        else:
            names.append(p.name)
    return names


def _unwrap(attr):
    return attr.__func__ if isinstance(attr, (staticmethod, classmethod)) else attr


def _overrides_documented(cls, name, attr) -> bool:
    """An override with its base's parameters, which the base documents: the contract is
    written once, in the base (``FrictionModel.steady_state`` for every law)."""
    fn = _unwrap(attr)
    if not inspect.isfunction(fn):
        return False
    for base in cls.__mro__[1:]:
        if name in vars(base) and not _own(base) and base is not object:
            return True  # implements a library's interface (pythonfmu's Fmi2Slave.do_step)
        if name in vars(base) and _own(base):
            b = _unwrap(vars(base)[name])
            if not inspect.isfunction(b):
                return False
            mine, theirs = _params(fn, True), _params(b, True)
            bdoc = inspect.getdoc(b) or ""
            if undocumented(theirs, bdoc):
                return False
            # the same parameters, or some of the base's ``**inputs`` made explicit (the base
            # names them in that entry: ``load`` of FrictionModel.force's ``**inputs``)
            extra = [p for p in mine if p not in theirs]
            star = any(p.startswith("**") for p in theirs)
            return [p for p in mine if p in theirs] == [p for p in theirs if p in mine] and \
                all(star and f"``{p}``" in bdoc for p in extra) and \
                all(p in mine or p.startswith("*") for p in theirs)
    return False


def _callables():
    """(qualified name, function, parameter names, docstring) of every public function,
    constructor and public method of an exported class (methods documented where they are
    written: an inherited method is checked once, in its own class)."""
    out, seen = [], set()
    for qual, obj in _exported():
        if inspect.isfunction(obj):
            out.append((qual, obj, _params(obj, False), inspect.getdoc(obj) or ""))
            continue
        for cls in obj.__mro__:
            if not _own(cls) or id(cls) in seen:
                continue
            seen.add(id(cls))
            cq = f"{cls.__module__}.{cls.__qualname__}"
            init = cls.__dict__.get("__init__")
            if init is not None and not _generated(init) and not issubclass(cls, Exception):
                doc = (inspect.getdoc(cls) or "") + "\n" + (init.__doc__ and
                                                             inspect.cleandoc(init.__doc__) or "")
                out.append((cq + ".__init__", init, _params(init, True), doc))
            for name, attr in vars(cls).items():
                if name.startswith("_"):
                    continue
                if _overrides_documented(cls, name, attr):
                    continue
                skip_first = True
                if isinstance(attr, staticmethod):
                    attr, skip_first = attr.__func__, False
                elif isinstance(attr, classmethod):
                    attr = attr.__func__
                if not inspect.isfunction(attr) or _generated(attr):
                    continue
                out.append((f"{cq}.{name}", attr, _params(attr, skip_first),
                            inspect.getdoc(attr) or ""))
    return out


def documented(doc: str) -> set[str]:
    """Names listed in the numpydoc ``Parameters`` (and ``Other Parameters``) sections."""
    lines = doc.splitlines()
    names: set[str] = set()
    k = 0
    while k < len(lines) - 1:
        head = lines[k].strip()
        if head in ("Parameters", "Other Parameters") and _HEADER.match(lines[k + 1]):
            base = len(lines[k]) - len(lines[k].lstrip())
            j = k + 2
            while j < len(lines):
                line = lines[j]
                if j + 1 < len(lines) and _HEADER.match(lines[j + 1]) and line.strip():
                    break  # the next section
                indent = len(line) - len(line.lstrip())
                if line.strip() and indent == base:
                    left = line.split(" : ")[0].strip().rstrip(":")
                    for part in left.split(","):
                        part = part.strip()
                        if part:
                            names.add(part)
                j += 1
            k = j
        else:
            k += 1
    return names


def undocumented(params, doc) -> list[str]:
    listed = documented(doc)
    bare = {n.lstrip("*") for n in listed}
    return [p for p in params if p not in listed and p.lstrip("*") not in bare]


CALLABLES = _callables()


def test_the_collector_sees_the_api():
    names = {q for q, *_ in CALLABLES}
    assert "friction.make_model" in names or any(q.endswith(".make_model") for q in names)
    assert any(q.endswith("identification.api.identify") for q in names)
    assert len(CALLABLES) > 150
    # the section parser: names, groups, *args/**kwargs, the next section ends it
    doc = "S.\n\nParameters\n----------\na, b : float\n    x.\n**kw\n    y.\n\nReturns\n" \
          "-------\nc : int\n"
    assert documented(doc) == {"a", "b", "**kw"}


@pytest.mark.parametrize("qual,fn,params,doc", CALLABLES, ids=[c[0] for c in CALLABLES])
def test_every_parameter_is_documented(qual, fn, params, doc):
    missing = undocumented(params, doc)
    assert not missing, f"{qual}: no numpydoc Parameters entry for {missing}"


# -- **kwargs: documented and validated -----------------------------------------------------
def _var_keyword(fn):
    try:
        sig = inspect.signature(fn)
    except (TypeError, ValueError):
        return None
    return next((p.name for p in sig.parameters.values() if p.kind is p.VAR_KEYWORD), None)


KWARGS = [(q, fn) for q, fn, params, doc in CALLABLES if _var_keyword(fn)]

#: callables with **kwargs whose keywords come from a fixed caller, not from a user
KWARGS_EXEMPT = {
    "fmus.runtime.SlaveBase.__init__": "pythonfmu's runtime constructs a slave with its own "
                                       "keywords (instance_name, resources...), passed on "
                                       "to Fmi2Slave",
}


def _law_calls():
    """A call per law and per method taking the law's ``**inputs``/``**values``."""
    import numpy as np
    from friction import MODELS, make_model
    out = {}
    for name in MODELS:
        law = make_model(name)
        name = type(law).__name__
        st = np.zeros(len(law.state_names))
        out[f"{name}.steady_state"] = lambda bad, law=law: law.steady_state([0.01], **bad)
        out[f"{name}.force"] = lambda bad, law=law, st=st: law.force(st, 0.01, a=0.0, **bad)
        out[f"{name}.derivatives"] = lambda bad, law=law, st=st: law.derivatives(
            st, 0.01, a=0.0, load=1.0, x=0.0, **bad)
        out[f"{name}.steady_state_state"] = lambda bad, law=law: law.steady_state_state(
            0.01, a=0.0, load=1.0, x=0.0, **bad)
        out[f"{name}.with_values"] = lambda bad, law=law: law.with_values(**bad)
        out[f"{name}.__init__"] = lambda bad, law=law: type(law)(None, **bad)
        out[f"{name}.simulate"] = lambda bad, law=law: law.simulate(
            np.arange(3) * 1e-3, np.full(3, 0.01), a=np.zeros(3), load=np.ones(3), **bad)
    return out


def _kwargs_calls():
    """How to call each public callable with **kwargs and one unknown keyword ``bad``
    (the other arguments the cheapest valid ones); every entry of KWARGS is covered by
    one of these (by its last two name parts) or by :data:`KWARGS_EXEMPT`."""
    import numpy as np
    from friction import make_model
    from friction.dataset import Dataset, SteadyStateMap
    from friction.mre_lugre import MRELuGre
    from plants import PLANTS, make_plant
    from plants.controllers import PID, StateDependentPID
    from identification import identify, identify_static
    from identification.algorithms import get_algorithm
    from identification.functions import minimize
    from diagnosis.effect_law import EffectLaw
    t = np.arange(0.0, 0.05, 1e-3)
    v = 0.01 * np.sin(2 * np.pi * 10 * t)
    law = make_model("lugre")
    data = Dataset.from_arrays(t, law.simulate(t, v), v=v)
    smap = SteadyStateMap(np.array([-0.02, -0.01, 0.01, 0.02]),
                          law.steady_state(np.array([-0.02, -0.01, 0.01, 0.02])))
    calls = {
        "friction.make_model": lambda bad: make_model("lugre", **bad),
        "FrictionParams.replace": lambda bad: law.params.replace(**bad),
        "MRELuGre.from_paper_units": lambda bad: MRELuGre.from_paper_units(**bad),
        "MRELuGre.simplified": lambda bad: MRELuGre.simplified(10.0, 100.0, 50.0, **bad),
        "plants.make_plant": lambda bad: make_plant("valve", **bad),
        "PlantStepper.set_parameters":
            lambda bad: make_plant("valve").stepper().set_parameters(**bad),
        "PID.__init__": lambda bad: PID(**bad),
        "StateDependentPID.__init__": lambda bad: StateDependentPID(**bad),
        "fmus.master.simulate_cosim": lambda bad: _cosim_with(bad),
        "LoggedSlave.init": lambda bad: _logged_init(bad),
        "identification.api.identify": lambda bad: identify(data, "lugre", **bad),
        "Algorithm.__init__": lambda bad: get_algorithm("cmaes", **bad),
        "identification.algorithms.get_algorithm":
            lambda bad: get_algorithm("differential_evolution", **bad),
        "identification.functions.minimize":
            lambda bad: minimize(lambda x: float(x @ x), [0, 0], [1, 1], max_evals=4, **bad),
        "identification.steady_state.identify_static":
            lambda bad: identify_static(smap, "lugre", **bad),
        "EffectLaw.with_values": lambda bad: _effect_law().with_values(**bad),
        "EffectLaw.force": lambda bad: _effect_law().force(
            np.zeros(len(_effect_law().state_names)), 0.01, **bad),
        "EffectLaw.derivatives": lambda bad: _effect_law().derivatives(
            np.zeros(len(_effect_law().state_names)), 0.01, **bad),
        "EffectLaw.steady_state": lambda bad: _effect_law().steady_state([0.01], **bad),
    }
    for name, cls in PLANTS.items():
        c = cls.__name__
        calls[f"{c}.__init__"] = lambda bad, cls=cls: cls(**bad)
        calls[f"{c}.with_options"] = lambda bad, name=name: make_plant(name).with_options(**bad)
        calls[f"{c}.with_params"] = lambda bad, name=name: make_plant(name).with_params(**bad)
        calls[f"{c}.stepper"] = lambda bad, name=name: make_plant(name).stepper(**bad)
        calls[f"{c}.simulate"] = lambda bad, name=name: make_plant(name).simulate(1e-3, **bad)
    calls.update(_law_calls())
    return calls


def _effect_law():
    import numpy as np
    from diagnosis.effect_law import EffectLaw
    from diagnosis.effects import make_context
    from friction import make_model
    from friction.dataset import Dataset
    t = np.arange(0.0, 0.05, 1e-3)
    v = 0.01 * np.sin(2 * np.pi * 10 * t)
    base = make_model("lugre")
    ctx = make_context(Dataset.from_arrays(t, base.simulate(t, v), v=v))
    return EffectLaw(base, {"drift": {"k_drift": 0.5}}, ctx)


def _cosim_with(bad):
    from fmus.master import simulate_cosim
    return simulate_cosim({}, (), stop_time=1.0, step_size=0.1, **bad)


def _logged_init(bad):
    from fmus.testing import LoggedSlave
    slave = LoggedSlave.__new__(LoggedSlave)  # the check comes before any FMI call
    slave.vr, slave.name = {"x": 0}, "inst"
    return slave.init(**bad)


CALLS = _kwargs_calls()


#: base classes whose method is covered by the calls of its subclasses' (every law, plant)
BASES = ("FrictionModel", "Plant")


def _covered(qual) -> bool:
    cls, method = qual.split(".")[-2:]
    if qual in KWARGS_EXEMPT or f"{cls}.{method}" in CALLS or qual in CALLS:
        return True
    return cls in BASES and any(k.endswith("." + method) for k in CALLS)


def test_every_var_keyword_callable_is_checked():
    missing = [q for q, _ in KWARGS if not _covered(q)]
    assert not missing, f"add a call with an unknown keyword for {missing}"


def test_var_keyword_arguments_are_documented():
    for qual, fn in KWARGS:
        name = "**" + _var_keyword(fn)
        doc = next(d for q, f, p, d in CALLABLES if q == qual)
        assert name in documented(doc) or name.lstrip("*") in documented(doc), qual


@pytest.mark.parametrize("key", sorted(CALLS))
def test_an_unknown_keyword_raises_type_error(key):
    with pytest.raises(TypeError, match="not_a_keyword"):
        CALLS[key]({"not_a_keyword": 1.0})


# -- examples ----------------------------------------------------------------------------
EXAMPLES = sorted((ROOT / "examples").glob("*.py"))


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_every_example_has_a_run_function_and_a_main_guard(path):
    tree = ast.parse(path.read_text())
    runs = [n.name for n in tree.body if isinstance(n, ast.FunctionDef)
            and n.name.startswith("run_")]
    assert runs, f"{path.name}: no run_* function"
    guards = [n for n in tree.body if isinstance(n, ast.If)
              and "__name__" in ast.unparse(n.test) and "__main__" in ast.unparse(n.test)]
    assert guards, f"{path.name}: no __main__ guard"
    assert ast.get_docstring(tree), f"{path.name}: no goal docstring"


def _example(name):
    path = ROOT / "examples" / f"{name}.py"
    spec = importlib.util.spec_from_file_location(f"example_{name}", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


#: example -> (its run_* call with cheap arguments, checks on the result); ``tmp`` is a
#: folder for the files it writes
RUNS = {
    "xml350_compensation": (lambda m, tmp: m.run_example(out_dir=tmp, mismatch=False),
                            lambda r: all(0 < x["rms_reduction"] < 1
                                          for x in r["reductions"].values())),
    "mre_sensitivity": (lambda m, tmp: m.run_example(out_dir=tmp, rate=500.0, sobol_n=16),
                        lambda r: set(r["local"]["ranking"]) == set(r["global"]["ranking"])),
    "identify_xml350": (lambda m, tmp: m.run_identify_xml350(quick=True),
                        lambda r: r["accuracy"]["validation"] > 0.5),
    "identify_franka": (lambda m, tmp: m.run_identify_franka(cases=(3,), speeds=("slow",),
                                                             every=20, max_evals=30),
                        lambda r: all(ours > 0 for ours, _ in r.values())),
    "identify_emps": (lambda m, tmp: m.run_identify_emps(max_evals=20, every=20,
                                                         progress=False),
                      lambda r: set(r["errors"]) == {"DATA_EMPS", "DATA_EMPS_PULSES"}),
    "cosim_mass_friction": (lambda m, tmp: m.run_cosim_mass_friction(stop=0.05),
                            lambda r: r["nrmse"] < 1e-3),
    "damping_rig": (lambda m, tmp: m.run_example(out_dir=tmp, quick=True),
                    lambda r: r["dissipated"]["sine"] > 0),
    "diagnose_real": (lambda m, tmp: m.run_diagnose_real(only=("emps",), quick=True),
                      lambda r: r["rows"][0]["verdict"] == "asymmetry"),
}
#: the heavy ones (a minute or more each on two shared cores), run with -m slow
SLOW_RUNS = {
    "valve_loops": (lambda m, tmp: m.run_example(out_dir=tmp, quick=True),
                    lambda r: len(r["frequency"]) == 1),
    "forging_press_crawl": (lambda m, tmp: m.run_example(out_dir=tmp, sweep=(0.3e-3,),
                                                         duration=1.0),
                            lambda r: len(r["sweep"]) == 1),
    "cosim_xml350_parts": (lambda m, tmp: m.run_cosim_xml350_parts(stop=0.005),
                           lambda r: r["nrmse"] < 1e-2),
    "diagnose_emps": (lambda m, tmp: m.run_diagnose_emps(out=tmp),
                      lambda r: r["verdict"]["cause"] is not None),
    "diagnose_franka": (lambda m, tmp: m.run_diagnose_franka(cases=(4,), verbose=False),
                        lambda r: r[4]["verdict"]["cause"] is not None),
    "diagnose_xml350_trajectory": (lambda m, tmp: m.run_diagnose_xml350_trajectory(out=tmp),
                                   lambda r: r["verdict"]["cause"] is not None),
}


def test_every_example_is_run_by_a_test():
    assert set(RUNS) | set(SLOW_RUNS) == {p.stem for p in EXAMPLES}
    assert len(RUNS) * 2 > len(EXAMPLES)  # most run in the default suite


def _run(name, table, tmp_path):
    import matplotlib
    matplotlib.use("Agg")
    call, check = table[name]
    result = call(_example(name), str(tmp_path / name))
    assert check(result), name


@pytest.mark.parametrize("name", sorted(RUNS))
def test_example_runs(name, tmp_path):
    _run(name, RUNS, tmp_path)


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(SLOW_RUNS))
def test_heavy_example_runs(name, tmp_path):
    _run(name, SLOW_RUNS, tmp_path)
