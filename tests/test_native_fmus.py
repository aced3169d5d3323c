"""Native FMUs (plain C, no Python at run time): layout, one source of truth for the
variables, equality with the pythonfmu FMUs, FMI semantics (state rollback, serialization,
reset, two instances, threads) and bad input through the FMI API with status and message."""
from __future__ import annotations

import dataclasses
import math
import pathlib
import shutil
import subprocess
import tempfile
import threading
import zipfile

import numpy as np
import pytest
import fmpy
from fmpy.fmi1 import FMICallException

import friction
from fmus.native.build import SUFFIX, native_catalogue
from fmus.native.ckernels import compiler
from fmus.native.variables import exclusive_min
from fmus.status_shim import fmi2_header_dir
from fmus.testing import LoggedSlave, built_fmus, built_native_fmus

LAWS = sorted(friction.MODELS)


@pytest.fixture(scope="module")
def ndir():
    return built_native_fmus()


@pytest.fixture(scope="module")
def pdir():
    # the same set test_fmus.py builds, so one build serves both files
    return built_fmus(tuple(sorted(friction.MODELS)) + ("mass",))


def _path(ndir, name):
    return ndir / f"{name}{SUFFIX}.fmu"


def test_catalogue_has_every_law_the_effects_block_and_the_mass():
    assert set(native_catalogue()) == set(friction.MODELS) | {"friction_effects", "mass"}


@pytest.mark.parametrize("name", LAWS + ["friction_effects", "mass"])
def test_layout_sources_and_capabilities(ndir, name):
    path = _path(ndir, name)
    with zipfile.ZipFile(path) as z:
        names = set(z.namelist())
    ident = f"fl_native_{name}"
    assert f"binaries/linux64/{ident}.so" in names
    if shutil.which("x86_64-w64-mingw32-gcc"):
        assert f"binaries/win64/{ident}.dll" in names
    for f in ("sources/fl_fmi2.c", "sources/fl_model.h", "sources/buildDescription.xml"):
        assert f in names, f
    if name in friction.MODELS:
        assert f"sources/{name}.c" in names
    md = fmpy.read_model_description(str(path))
    cs, me = md.coSimulation, md.modelExchange
    assert not cs.needsExecutionTool and cs.canGetAndSetFMUstate and cs.canSerializeFMUstate
    assert me is not None and me.canGetAndSetFMUstate
    files = [f for b in md.buildConfigurations for fs in b.sourceFileSets
             for f in fs.sourceFiles]
    assert "fl_fmi2.c" in files
    assert not [v for v in md.modelVariables if v.type == "String"]


@pytest.mark.parametrize("law", LAWS)
def test_parameters_come_from_the_dataclass(ndir, law):
    cls = friction.MODELS[law]
    md = fmpy.read_model_description(str(_path(ndir, law)))
    var = {v.name: v for v in md.modelVariables}
    types = {t.name: t for t in md.typeDefinitions}
    options = getattr(cls.Params, "OPTIONS", {})
    for f in dataclasses.fields(cls.Params):
        v = var[f.name]
        assert v.causality == "parameter" and v.variability == "tunable"
        if f.name in options:
            assert v.type == "Enumeration"
            items = [i.name for i in types[v.declaredType.name].items]
            assert items == sorted(options[f.name], key=options[f.name].get)
            assert int(v.start) == options[f.name][f.default] + 1
            continue
        if isinstance(f.default, bool):
            assert v.type == "Boolean"
            continue
        md_ = f.metadata
        assert v.type == "Real" and v.unit == md_["unit"].replace("^", ""), f.name
        if math.isfinite(md_["lower"]):
            want = exclusive_min(md_["lower"]) if md_["lower_open"] else md_["lower"]
            assert float(v.min) == want, f.name
        if f.default is None:  # an optional value: a Boolean flag, no sentinel
            flag = var[f"use_{f.name}"]
            assert flag.type == "Boolean" and flag.start in ("false", False), f.name
        else:
            assert float(v.start) == f.default, f.name


def _drive(law, t):
    v = 2e-3 * np.sin(2 * np.pi * 10 * t) + 5e-4
    if law == "mre_lugre":
        v = 0.05 * np.sin(2 * np.pi * 4 * t)
    x = np.concatenate(([0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(t))))
    return {"v": v, "a": np.gradient(v, t), "x": x,
            "load": 1e3 * (1 + np.sin(2 * np.pi * 3 * t))}


OUTS = ("F", "dF_dx", "dF_dv", "dF_dt", "d2F_dt2", "t_kink", "dF_dt_kink")


def _run(path, law, n=400, h=1e-4, start=None, name="inst"):
    cls = friction.MODELS[law]
    ins = ["v"] + [k for k in ("a", "load", "x") if k in cls.extra_inputs]
    t = h * np.arange(n + 1)
    sig = _drive(law, t)
    s = LoggedSlave(path, name)
    try:
        s.init(**(start or {}))
        vr_in, vr_out = [s.vr[k] for k in ins], [s.vr[k] for k in OUTS]
        out = np.empty((t.size, len(OUTS)))
        for k in range(t.size):
            s.s.setReal(vr_in, [float(sig[i][k]) for i in ins])
            out[k] = s.s.getReal(vr_out)
            if k < n:
                s.s.doStep(t[k], h)
    finally:
        s.close()
    return out


@pytest.mark.parametrize("law", LAWS)
def test_native_equals_pythonfmu_with_the_coupling_outputs(ndir, pdir, law):
    for start in ({}, {"h_lin": 1e-4, "inputs_at_step_end": True}):
        a = _run(pdir / f"{law}.fmu", law, start=start)
        b = _run(_path(ndir, law), law, start=start)
        scale = np.abs(a).max(axis=0) + 1e-300
        assert np.all(np.abs(a - b) <= 1e-10 * scale), (law, start, np.abs(a - b).max(axis=0))


def test_options_and_twins_reach_the_law(ndir):
    """A lorentzian, asymmetric LuGre set through the Enumeration and the use_ flags equals
    the Python law with those values."""
    h, n = 1e-4, 600
    t = h * np.arange(n + 1)
    v = 3e-3 * np.sin(2 * np.pi * 5 * t)
    s = LoggedSlave(_path(ndir, "lugre"))
    s.init(shape=2, use_Fc_neg=True, Fc_neg=0.7, use_Fs_neg=True, Fs_neg=0.9, sigma1=100.0)
    F = np.empty(t.size)
    for k in range(t.size):
        s.set("v", float(v[k]))
        F[k] = s.get("F")
        if k < n:
            s.s.doStep(t[k], h)
    s.close()
    model = friction.make_model("lugre", shape="lorentzian", Fc_neg=0.7, Fs_neg=0.9,
                                sigma1=100.0)
    # the FMU holds the input over a step: the Python kernel stepped the same way
    def held(model):
        state, ref = model.initial_state(), np.empty(t.size)
        e = np.zeros(0)
        for k in range(t.size):
            ref[k] = model._kernel(np.zeros(1), v[k:k + 1], e, e, e, model.theta, 0, state)[0][0]
            state = model._kernel(np.array([0.0, h]), np.array([v[k], v[k]]), e, e, e,
                                  model.theta, 0, state)[1][1]
        return ref
    assert np.array_equal(F, held(model))
    # the options changed the force: the defaults' run is far from it
    assert np.max(np.abs(F - held(friction.make_model("lugre")))) > 0.1


def _step_series(s, law, t, h, k0, k1, sig, ins):
    out = []
    for k in range(k0, k1):
        s.s.setReal([s.vr[i] for i in ins], [float(sig[i][k]) for i in ins])
        out.append(s.get("F"))
        s.s.doStep(t[k], h)
    return np.array(out)


@pytest.mark.parametrize("law", ["lugre", "modified_lugre", "load_lugre"])
def test_rollback_and_redo_is_bit_for_bit(ndir, law):
    cls = friction.MODELS[law]
    ins = ["v"] + [k for k in ("a", "load", "x") if k in cls.extra_inputs]
    h, n = 1e-4, 500
    t = h * np.arange(n + 1)
    sig = _drive(law, t)
    s = LoggedSlave(_path(ndir, law), "a")
    s.init(h_lin=h)
    _step_series(s, law, t, h, 0, 100, sig, ins)
    state = s.s.getFMUstate()
    first = _step_series(s, law, t, h, 100, 500, sig, ins)
    s.s.setFMUstate(state)
    redo = _step_series(s, law, t, h, 100, 500, sig, ins)
    assert np.array_equal(first, redo)
    # serialized, then restored in another instance
    s.s.setFMUstate(state)
    blob = s.s.serializeFMUstate(state)
    s.s.freeFMUstate(state)
    other = LoggedSlave(_path(ndir, law), "b")
    other.init()
    restored = other.s.deSerializeFMUstate(blob)
    other.s.setFMUstate(restored)
    other.s.freeFMUstate(restored)
    again = _step_series(other, law, t, h, 100, 500, sig, ins)
    assert np.array_equal(first, again)
    # a state of another FMU is refused with a message
    foreign = LoggedSlave(_path(ndir, "stribeck" if law != "stribeck" else "lugre"), "c")
    foreign.init()
    with pytest.raises(FMICallException):
        foreign.s.deSerializeFMUstate(blob)
    assert any("another FMU" in m or "not a serialized state" in m for m in foreign.errors())
    for x in (s, other, foreign):
        x.close()


def test_reset_repeats_the_first_run(ndir):
    h, n = 1e-4, 300
    t = h * np.arange(n + 1)
    sig = _drive("lugre", t)
    s = LoggedSlave(_path(ndir, "lugre"))
    s.init(sigma1=50.0)
    first = _step_series(s, "lugre", t, h, 0, n, sig, ["v"])
    s.s.reset()
    s.s.setupExperiment(startTime=0.0)
    s.init(sigma1=50.0)
    again = _step_series(s, "lugre", t, h, 0, n, sig, ["v"])
    s.close()
    assert np.array_equal(first, again)


def test_two_instances_and_two_threads_are_independent(ndir):
    h, n = 1e-4, 400
    t = h * np.arange(n + 1)
    sig = _drive("lugre", t)
    alone = {}
    for sigma0 in (1e5, 3e4):
        s = LoggedSlave(_path(ndir, "lugre"), f"alone{sigma0:g}")
        s.init(sigma0=sigma0)
        alone[sigma0] = _step_series(s, "lugre", t, h, 0, n, sig, ["v"])
        s.close()
    # interleaved in one thread
    a, b = LoggedSlave(_path(ndir, "lugre"), "a"), LoggedSlave(_path(ndir, "lugre"), "b")
    a.init(sigma0=1e5)
    b.init(sigma0=3e4)
    fa, fb = [], []
    for k in range(n):
        fa.append(_step_series(a, "lugre", t, h, k, k + 1, sig, ["v"])[0])
        fb.append(_step_series(b, "lugre", t, h, k, k + 1, sig, ["v"])[0])
    assert np.array_equal(fa, alone[1e5]) and np.array_equal(fb, alone[3e4])
    a.close()
    b.close()
    # two threads, one instance each
    res = {}

    def work(sigma0):
        s = LoggedSlave(_path(ndir, "lugre"), f"thread{sigma0:g}")
        s.init(sigma0=sigma0)
        res[sigma0] = _step_series(s, "lugre", t, h, 0, n, sig, ["v"])
        s.close()
    threads = [threading.Thread(target=work, args=(s0,)) for s0 in (1e5, 3e4)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    assert np.array_equal(res[1e5], alone[1e5]) and np.array_equal(res[3e4], alone[3e4])


def _fresh(ndir, law="lugre", **start):
    s = LoggedSlave(_path(ndir, law))
    s.init(**start)
    return s


def test_bad_inputs_and_parameters_answer_error_naming_the_variable(ndir):
    s = _fresh(ndir)
    s.set("v", 1e-3)
    F0 = s.get("F")
    # a NaN input is refused and the previous value kept
    assert s.set("v", math.nan) == 3
    assert "v = nan is not finite" in s.errors()[-1] and "keeps 0.001" in s.errors()[-1]
    assert s.get("F") == F0
    assert s.set("v", math.inf) == 3
    # a parameter outside its bound, exclusive bounds included
    for value in (-1.0, 0.0):
        assert s.set("sigma0", value) == 3
        assert "sigma0" in s.errors()[-1] and "sigma0 > 0" in s.errors()[-1]
    assert s.set("alpha", 11.0) == 3 and "alpha <= 10" in s.errors()[-1]
    # an enumeration outside its items, a Real setter on it, an output
    assert s.set("shape", 3) == 3 and "shape" in s.errors()[-1]
    with pytest.raises(FMICallException):
        s.s.setReal([s.vr["shape"]], [1.0])
    assert "not a Real variable" in s.errors()[-1]
    assert s.set("F", 1.0) == 3 and "F is an output" in s.errors()[-1]
    # the instance keeps working with its previous values
    assert s.step(0.0, 1e-4) == 0
    s.close()


def test_bad_steps_and_calls_in_the_wrong_state_answer_error(ndir):
    s = _fresh(ndir)
    for h in (0.0, -1e-4, math.nan, math.inf):
        assert s.step(0.0, h) == 3
        assert "communicationStepSize" in s.errors()[-1]
    assert s.step(0.5, 1e-4) == 3 and "time jump" in s.errors()[-1]
    assert s.step(0.0, 1e-4) == 0
    s.close()
    # fmi2DoStep before initialization
    s = LoggedSlave(_path(ndir, "lugre"))
    assert s.step(0.0, 1e-4) == 3 and "not allowed in instantiated" in s.errors()[-1]
    s.close()


def test_an_impossible_parameter_relation_is_named_at_initialization(ndir):
    s = LoggedSlave(_path(ndir, "modified_lugre"))
    assert s.set("v1", 0.3) == 0  # v1 alone is admissible; v2 = 0.2 is now below it
    with pytest.raises(FMICallException):
        s.s.enterInitializationMode()
        s.s.exitInitializationMode()
    assert any("v2" in m and "v1" in m for m in s.errors())
    assert s.step(0.0, 1e-4) == 3  # and every step is refused with the message
    assert "v2" in s.errors()[-1]
    assert s.set("v2", 0.5) == 0 and s.step(0.0, 1e-4) == 0  # fixed: it runs
    s.close()


def test_effects_block_equals_the_formula(ndir):
    from friction.extensions import EXTENSION_INDEX, extension_force, pack_extensions
    # every part of the stroke map (knots, waviness, local defect) and of the drift (trend,
    # saturating change, step, periodic part, resetting part); the acceleration part's
    # weight peaking away from standstill
    e = pack_extensions({"acceleration": {"f_a": 0.3, "a_s": 2.0, "v_c": 0.01, "m_a": 1.7,
                                          "f_e": 0.05, "a_e": 1.5, "f_o": -0.04},
                         "position": {"c_x3": 0.2, "c_x7": -0.1, "lambda_x": 0.007,
                                      "p_c1": 0.1, "p_s1": -0.2, "p_c2": 0.05, "p_s2": 0.03,
                                      "d_x": 0.3, "x_d": 0.04, "w_d": 0.01},
                         "drift": {"k_drift": 0.05, "k_sat": 0.4, "tau_sat": 0.01,
                                   "k_step": -0.2, "t_step": 0.02, "w_step": 0.002,
                                   "P_cyc": 0.013, "k_c1": 0.1, "k_s1": -0.05, "k_c2": 0.02,
                                   "k_s2": -0.03, "P_rst": 0.017, "t_rst": 0.004,
                                   "k_r1": -0.15, "k_r2": 0.06},
                         "load": {"k_L": 0.8}},
                        x_lo=0.0, x_hi=0.1, t0=0.0, T=2.0, L0=50.0)
    s = LoggedSlave(_path(ndir, "friction_effects"))
    start = {}
    for name, k in EXTENSION_INDEX.items():
        start[name] = bool(e[k] > 0.5) if name.startswith("use_") else float(e[k])
    s.init(**start)
    rng = np.random.default_rng(1)
    h, t = 1e-3, 0.0
    for _ in range(50):
        F, v, a, x, load = rng.normal(1, 1), rng.normal(0, 0.01), rng.normal(0, 3), \
            rng.uniform(-0.01, 0.11), rng.uniform(10, 90)
        for name, val in (("F_law", F), ("v", v), ("a", a), ("x", x), ("load", load)):
            s.set(name, float(val))
        want = extension_force(F, v, a, x, load, t, e)
        assert s.get("F") == pytest.approx(want, rel=1e-13, abs=1e-15)
        assert s.step(t, h) == 0
        t += h
    assert s.set("a_s", 0.0) == 3 and "a_s > 0" in s.errors()[-1]
    assert s.set("m_a", -0.5) == 3 and "m_a >= 0" in s.errors()[-1]
    assert s.set("a_e", -0.5) == 3 and "a_e >= 0" in s.errors()[-1]
    # the odd level part refuses NaN by name and keeps its value
    assert s.set("f_o", float("nan")) == 3 and "f_o = nan is not finite" in s.errors()[-1]
    assert s.get("f_o") == pytest.approx(-0.04)
    # so do the drift's resetting part's period and reset time
    for name, kept in (("P_rst", 0.017), ("t_rst", 0.004)):
        assert s.set(name, float("nan")) == 3
        assert f"{name} = nan is not finite" in s.errors()[-1]
        assert s.get(name) == pytest.approx(kept)
    assert s.set("m_a", 0.0) == 0  # seed 000's weight, exp(-|v| / v_c)
    s.close()


def test_the_mass_matches_the_pythonfmu_mass(ndir, pdir):
    outs = []
    for path in (pdir / "mass.fmu", _path(ndir, "mass")):
        s = LoggedSlave(path)
        s.init(m=0.5, u_amp=2.0, u_freq=3.0, v0=0.1)
        rows = []
        for k in range(200):
            s.set("F_friction", 0.3 * math.sin(k * 0.05))
            rows.append([s.get("x"), s.get("v"), s.get("a")])
            s.step(k * 1e-3, 1e-3)
        s.close()
        outs.append(np.array(rows))
    assert np.allclose(outs[0], outs[1], rtol=1e-13, atol=1e-15)


def test_a_host_builds_the_fmu_from_its_sources(ndir, tmp_path):
    """sources/ and buildDescription.xml are enough: cc *.c gives a binary that runs the
    same steps as the shipped one (what a darwin64 host would do)."""
    with zipfile.ZipFile(_path(ndir, "lugre")) as z:
        z.extractall(tmp_path / "fmu")
    src = tmp_path / "fmu" / "sources"
    lib = tmp_path / "fmu" / "binaries" / "linux64" / "fl_native_lugre.so"
    lib.unlink()
    cmd = [compiler(), "-shared", "-fPIC", "-O2", f"-I{fmi2_header_dir()}",
           *map(str, sorted(src.glob("*.c"))), "-o", str(lib), "-lm"]
    subprocess.run(cmd, check=True, capture_output=True)
    rebuilt = tmp_path / "rebuilt.fmu"
    with zipfile.ZipFile(rebuilt, "w") as z:
        for p in (tmp_path / "fmu").rglob("*"):
            if p.is_file():
                z.write(p, p.relative_to(tmp_path / "fmu").as_posix())
    a = _run(_path(ndir, "lugre"), "lugre", n=200)
    b = _run(rebuilt, "lugre", n=200)
    assert np.array_equal(a, b)


def test_build_fmus_names_the_missing_compiler_and_still_builds_pythonfmu(tmp_path):
    """No C compiler on PATH: a one-line error that says what to install, exit code 2, and
    the pythonfmu FMU of the law is there all the same."""
    import os
    import sys
    bindir = pathlib.Path(sys.executable).parent
    env = {"PATH": str(bindir), "HOME": os.environ.get("HOME", str(tmp_path))}
    proc = subprocess.run([str(bindir / "frictionlab"), "build-fmus", "--out",
                           str(tmp_path / "out"), "--only", "stribeck"],
                          capture_output=True, text=True, env=env, timeout=300)
    assert proc.returncode == 2
    err = [line for line in proc.stderr.splitlines() if "error:" in line]
    assert len(err) == 1 and "no C compiler" in err[0] and "apt-get install gcc" in err[0]
    assert (tmp_path / "out" / "stribeck.fmu").is_file()
    assert not (tmp_path / "out" / f"stribeck{SUFFIX}.fmu").exists()


def test_build_all_builds_both_kinds(tmp_path):
    from fmus.build import build_all
    built = build_all(tmp_path, only=["stribeck", "mass_native"], progress=False)
    assert set(built) == {"stribeck", "stribeck_native", "mass_native"}
    for p in built.values():
        assert p.is_file()
