"""FMI error statuses on bad input: the status shim in front of pythonfmu's binary.

NaN/inf on an input or an out-of-bounds parameter must give ``fmi2Error`` with a log message
naming the variable (and its bound), never a crash or a silent NaN; the rejected value is not
stored, so the instance keeps working exactly as if the bad call had not happened.
"""
from __future__ import annotations

import math
import shutil
import zipfile

import fmpy
import numpy as np
import pytest
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import fmi2Error, fmi2OK

from fmus import status_shim
from fmus.build import build_fmu, catalogue, validate
from fmus.master import FMUError, Master
from fmus.testing import LoggedSlave

try:
    status_shim.shim_library()
    SHIM_REASON = None
except status_shim.ShimUnavailable as exc:  # pragma: no cover - no C compiler here
    SHIM_REASON = str(exc)
needs_shim = pytest.mark.skipif(SHIM_REASON is not None, reason=f"no status shim: {SHIM_REASON}")
try:
    status_shim.shim_library("win64")
    WIN64_REASON = None
except status_shim.ShimUnavailable as exc:  # no MinGW-w64 here
    WIN64_REASON = str(exc)

NAN, INF = float("nan"), float("inf")


@pytest.fixture(scope="module")
def fmu_dir(tmp_path_factory):
    out = tmp_path_factory.mktemp("fmus_status")
    cat = catalogue()
    for name in ("lugre", "mass", "damping_rig"):
        build_fmu(cat[name], out)
    return out


def test_linux64_binary_is_the_shim_in_front_of_pythonfmu(fmu_dir):
    import pythonfmu
    import pathlib
    res = pathlib.Path(pythonfmu.__file__).parent / "resources" / "binaries"
    for name in ("lugre", "mass", "damping_rig"):
        path = fmu_dir / f"{name}.fmu"
        mid = f"fl_{name}"
        with zipfile.ZipFile(path) as z:
            names = set(z.namelist())
            if SHIM_REASON is None:
                assert z.read(f"binaries/linux64/{mid}.so") == \
                    status_shim.shim_library().read_bytes()
                assert z.read(f"binaries/linux64/{mid}_pythonfmu.so") == \
                    (res / "linux64" / "libpythonfmu-export.so").read_bytes()
            # win64: the same shim cross-compiled with MinGW-w64 when it is installed,
            # otherwise pythonfmu's DLL untouched (tests/test_fmu_shim_win64.py checks both)
            win64 = {n for n in names if n.startswith("binaries/win64/")}
            pyfmu_dll = (res / "win64" / "pythonfmu-export.dll").read_bytes()
            if WIN64_REASON is None:
                assert win64 == {f"binaries/win64/{mid}.dll",
                                 f"binaries/win64/{mid}_pythonfmu.dll"}
                assert z.read(f"binaries/win64/{mid}.dll") == \
                    status_shim.shim_library("win64").read_bytes()
                assert z.read(f"binaries/win64/{mid}_pythonfmu.dll") == pyfmu_dll
            else:
                assert win64 == {f"binaries/win64/{mid}.dll"}
                assert z.read(f"binaries/win64/{mid}.dll") == pyfmu_dll
        assert validate(path) == [], name


def _lugre_run(path, n=40, bad=None, at=20, logging_on=True):
    """Drive v(t) through the LuGre FMU; ``bad`` = (variable, value) set once at step ``at``.
    Returns (F samples, statuses of the bad call, messages)."""
    s = LoggedSlave(path, "fr", logging_on)
    status = None
    try:
        s.init()
        F = []
        for k in range(n):
            v = 2e-3 * math.sin(2 * math.pi * 10 * k * 1e-4) + 5e-4
            assert s.set("v", v) == fmi2OK
            if bad is not None and k == at:
                before = s.get("F")
                status = s.set(*bad)
                assert s.get("F") == before  # the rejected value changed nothing
            F.append(s.get("F"))
            assert s.step(k * 1e-4, 1e-4) == fmi2OK
        F.append(s.get("F"))
        return np.array(F), status, s.messages
    finally:
        s.close()


@needs_shim
@pytest.mark.parametrize("bad", [NAN, INF, -INF])
def test_non_finite_input_gives_fmi2_error_naming_it_and_the_run_goes_on(fmu_dir, bad):
    path = fmu_dir / "lugre.fmu"
    ref, _, ref_msgs = _lugre_run(path)
    F, status, msgs = _lugre_run(path, bad=("v", bad))
    assert status == fmi2Error
    errors = [m for st, m in msgs if st >= fmi2Error]
    assert len(errors) == 1, msgs
    assert "input v" in errors[0] and "not finite" in errors[0] and repr(bad) in errors[0]
    assert "fr" in errors[0]  # the instance
    # the old value was kept: every later step is OK and the run equals the clean one
    assert np.all(np.isfinite(F))
    np.testing.assert_array_equal(F, ref)
    assert not [m for st, m in ref_msgs if st >= fmi2Error]


@needs_shim
@pytest.mark.parametrize("name, value, text", [("sigma0", -5.0, "> 0"),
                                               ("Fc", NAN, "not finite"),
                                               ("alpha", 11.0, "<= 10")])
def test_out_of_bounds_parameter_gives_fmi2_error_naming_it_and_its_bound(fmu_dir, name,
                                                                          value, text):
    path = fmu_dir / "lugre.fmu"
    s = LoggedSlave(path, "fr")
    try:
        start = s.get(name)
        assert s.set(name, value) == fmi2Error
        errors = s.errors()
        assert len(errors) == 1 and name in errors[0] and text in errors[0], s.messages
        assert s.get(name) == start  # rejected: the previous (default) value stays
        s.init()
        assert s.set("v", 1e-3) == fmi2OK
        for k in range(20):
            assert s.step(k * 1e-4, 1e-4) == fmi2OK
        F = s.get("F")
    finally:
        s.close()
    clean = LoggedSlave(path, "fr")  # the same run without the bad call
    try:
        clean.init()
        clean.set("v", 1e-3)
        for k in range(20):
            clean.step(k * 1e-4, 1e-4)
        assert F == clean.get("F")
    finally:
        clean.close()


@needs_shim
def test_tunable_parameter_during_the_run_rejected_without_losing_the_state(fmu_dir):
    path = fmu_dir / "lugre.fmu"
    ref, _, _ = _lugre_run(path)
    F, status, msgs = _lugre_run(path, bad=("sigma0", -1.0))
    assert status == fmi2Error
    assert any("sigma0" in m and "> 0" in m for st, m in msgs if st >= fmi2Error), msgs
    np.testing.assert_array_equal(F, ref)


@needs_shim
def test_error_messages_arrive_with_logging_off(fmu_dir):
    # an error explains the status of the call: forwarded even when debug logging is off
    F, status, msgs = _lugre_run(fmu_dir / "lugre.fmu", bad=("v", NAN), logging_on=False)
    assert status == fmi2Error
    assert [st for st, m in msgs] == [fmi2Error] and "input v" in msgs[0][1]


@needs_shim
def test_plant_fmu_non_finite_input_and_bad_parameter(fmu_dir):
    path = fmu_dir / "damping_rig.fmu"

    def run(bad_input=False, bad_param=False):
        s = LoggedSlave(path, "rig")
        try:
            if bad_param:
                assert s.set("m_c", -1.0) == fmi2Error
                assert any("m_c" in m and "> 0" in m for m in s.errors()), s.messages
            s.init()
            x = []
            for k in range(30):
                assert s.set("F_friction", 5.0 * math.sin(k * 0.3)) == fmi2OK
                if bad_input and k == 15:
                    assert s.set("F_friction", NAN) == fmi2Error
                    assert any("F_friction" in m and "not finite" in m
                               for m in s.errors()), s.messages
                assert s.step(k * 1e-4, 1e-4) == fmi2OK
                x.append(s.get("x"))
            return np.array(x), len(s.errors())
        finally:
            s.close()

    ref, n_ref = run()
    assert n_ref == 0 and np.ptp(ref) > 0
    for kw in ({"bad_input": True}, {"bad_param": True}):
        x, n_err = run(**kw)
        assert n_err == 1
        np.testing.assert_array_equal(x, ref)


@needs_shim
def test_percent_in_a_message_is_safe_for_a_formatting_logger(fmu_dir, capfd):
    # c_s's description says "about 2 %"; fmpy's default logger formats the message with
    # vsnprintf (it is a printf format), so the slave doubles the '%'
    from fmpy.fmi2 import FMU2Slave
    path = fmu_dir / "damping_rig.fmu"
    md = fmpy.read_model_description(str(path))
    d = fmpy.extract(str(path))
    vr = {v.name: v.valueReference for v in md.modelVariables}
    s = FMU2Slave(guid=md.guid, unzipDirectory=d, modelIdentifier=md.coSimulation.modelIdentifier,
                  instanceName="rig")
    try:
        s.instantiate()  # fmpy's default callbacks: the formatting logger proxy
        with pytest.raises(FMICallException) as exc:
            s.setReal([vr["c_s"]], [-1.0])
        assert exc.value.status == fmi2Error
        out = capfd.readouterr()
        text = out.out + out.err
        assert "c_s" in text and "about 2 %)" in text and "%%" not in text, text
    finally:
        s.fmi2FreeInstance(s.component)
        shutil.rmtree(d, ignore_errors=True)


@needs_shim
def test_an_option_code_that_is_no_item_is_refused_naming_the_items(fmu_dir):
    s = LoggedSlave(fmu_dir / "lugre.fmu", "fr")
    try:
        assert s.set("shape", 3) == fmi2Error  # shape: 1 gaussian, 2 lorentzian
        assert any("shape = 3" in m and "2 (lorentzian)" in m for m in s.errors()), s.messages
        assert s.s.getInteger([s.vr["shape"]]) == [1]  # rejected: the default stays
        assert s.set("shape", 2) == fmi2OK
        s.init()
        assert s.set("v", 1e-3) == fmi2OK and s.step(0.0, 1e-4) == fmi2OK
    finally:
        s.close()


@needs_shim
def test_inadmissible_combination_is_an_error_at_initialization_and_refuses_steps(tmp_path):
    path = build_fmu(catalogue()["modified_lugre"], tmp_path)
    s = LoggedSlave(path, "fr")
    try:
        assert s.set("v1", 0.3) == fmi2OK  # v1 alone is admissible; v2 = 0.2 is below it
        with pytest.raises(FMICallException) as exc:
            s.init()
        assert exc.value.status == fmi2Error
        assert any("v2" in m and "v1" in m for m in s.errors()), s.messages
        assert s.step(0.0, 1e-4) == fmi2Error  # no model: every step refused, loudly
        assert "refused" in s.errors()[-1]
        assert s.set("v2", 0.5) == fmi2OK and s.step(0.0, 1e-4) == fmi2OK  # fixed: it runs
    finally:
        s.close()


@needs_shim
@pytest.mark.parametrize("h", [0.0, -1e-4, NAN, INF])
def test_a_step_size_that_is_not_finite_and_positive_is_refused(fmu_dir, h):
    s = LoggedSlave(fmu_dir / "lugre.fmu", "fr")
    try:
        s.init()
        assert s.set("v", 1e-3) == fmi2OK
        assert s.step(0.0, 1e-4) == fmi2OK
        before = s.get("F")
        assert s.step(1e-4, h) == fmi2Error
        msg = s.errors()[-1]
        assert "communicationStepSize" in msg and repr(h) in msg and "> 0" in msg, msg
        assert s.get("F") == before  # the instance stayed where it was
        assert s.step(1e-4, 1e-4) == fmi2OK and s.errors() == [msg]
    finally:
        s.close()


@needs_shim
def test_rollback_and_redo_is_bit_for_bit_and_restores_in_another_instance(fmu_dir):
    """fmi2GetFMUstate / fmi2SetFMUstate restore the law's whole state (the bristle, the
    input history of the coupling outputs, the time): a redo repeats the first run bit for
    bit, also in another instance through fmi2SerializeFMUstate."""
    md = fmpy.read_model_description(str(fmu_dir / "lugre.fmu"))
    assert md.coSimulation.canGetAndSetFMUstate and md.coSimulation.canSerializeFMUstate
    h = 1e-4
    t = h * np.arange(501)
    v = 2e-3 * np.sin(2 * np.pi * 10 * t) + 5e-4

    def series(s, k0, k1):
        out = []
        for k in range(k0, k1):
            assert s.set("v", float(v[k])) == fmi2OK
            out.append(s.s.getReal([s.vr[n] for n in ("F", "z", "dF_dx", "dF_dt")]))
            assert s.step(t[k], h) == fmi2OK
        return np.array(out)

    s, other = LoggedSlave(fmu_dir / "lugre.fmu", "a"), LoggedSlave(fmu_dir / "lugre.fmu", "b")
    try:
        s.init(h_lin=h, inputs_at_step_end=True)
        series(s, 0, 100)
        state = s.s.getFMUstate()
        first = series(s, 100, 500)
        s.s.setFMUstate(state)
        redo = series(s, 100, 500)
        assert np.array_equal(first, redo)  # was 3.5e-2 N off before the fix
        blob = s.s.serializeFMUstate(state)
        s.s.freeFMUstate(state)
        other.init()  # other parameters (h_lin = 0): the state brings the stepped ones
        restored = other.s.deSerializeFMUstate(blob)
        other.s.setFMUstate(restored)
        other.s.freeFMUstate(restored)
        assert np.array_equal(series(other, 100, 500), first)
        assert s.errors() == [] and other.errors() == []
    finally:
        s.close()
        other.close()
    m = LoggedSlave(fmu_dir / "mass.fmu", "m")  # a state of another FMU is refused
    try:
        m.init()
        restored = m.s.deSerializeFMUstate(blob)
        with pytest.raises(FMICallException) as exc:
            m.s.setFMUstate(restored)
        assert exc.value.status == fmi2Error and "another FMU" in m.errors()[-1]
    finally:
        m.close()


@needs_shim
def test_the_mass_rolls_back_bit_for_bit(fmu_dir):
    s = LoggedSlave(fmu_dir / "mass.fmu", "m")
    try:
        s.init(u_amp=3.0, u_freq=7.0)

        def run(k0, k1):
            out = []
            for k in range(k0, k1):
                assert s.set("F_friction", 0.5 * math.sin(0.1 * k)) == fmi2OK
                assert s.step(k * 1e-3, 1e-3) == fmi2OK
                out.append(s.s.getReal([s.vr["x"], s.vr["v"], s.vr["a"]]))
            return np.array(out)

        run(0, 50)
        state = s.s.getFMUstate()
        first = run(50, 200)
        s.s.setFMUstate(state)
        s.s.freeFMUstate(state)
        assert np.array_equal(run(50, 200), first) and s.errors() == []
    finally:
        s.close()


@needs_shim
def test_a_plant_fmu_refuses_state_get_and_set_as_it_declares(fmu_dir):
    md = fmpy.read_model_description(str(fmu_dir / "damping_rig.fmu"))
    assert not md.coSimulation.canGetAndSetFMUstate
    s = LoggedSlave(fmu_dir / "damping_rig.fmu", "rig")
    try:
        s.init()
        with pytest.raises(FMICallException) as exc:
            s.s.getFMUstate()
        assert exc.value.status == fmi2Error
        assert "canGetAndSetFMUstate = false" in s.errors()[-1]
        assert s.step(0.0, 1e-4) == fmi2OK  # and the instance goes on
    finally:
        s.close()


@needs_shim
def test_non_finite_output_makes_the_step_an_error(fmu_dir):
    s = LoggedSlave(fmu_dir / "mass.fmu", "mass")
    try:
        # a = u0 / m = 1e307 m/s2, 1 s steps: x = a t^2 / 2 overflows after a few steps
        for k, v in dict(m=1e-300, u0=1e7, u_amp=0.0).items():
            assert s.set(k, v) == fmi2OK
        s.init()
        statuses = [s.step(float(k), 1.0) for k in range(20)]
        bad = statuses.index(fmi2Error)  # the overflow: error, not discard
        assert bad >= 3
        assert set(statuses[:bad]) == {fmi2OK} and set(statuses[bad:]) == {fmi2Error}
        assert any("not finite" in m for m in s.errors())
        with pytest.raises(FMICallException) as exc:  # no silent NaN on read either
            s.get("x")
        assert exc.value.status == fmi2Error
    finally:
        s.close()


def test_large_finite_outputs_are_not_mistaken_for_an_overflow(fmu_dir):
    # x + v overflows to inf although both are finite: the step must still be OK
    s = LoggedSlave(fmu_dir / "mass.fmu", "mass")
    try:
        for k, v in dict(x0=1e308, v0=1e308, u_amp=0.0).items():
            assert s.set(k, v) == fmi2OK
        s.init()
        assert s.step(0.0, 1e-4) == fmi2OK and s.errors() == []
        assert s.get("x") == 1e308 + 1e308 * 1e-4 and s.get("v") == 1e308
    finally:
        s.close()


@needs_shim
def test_invalid_value_reference_is_an_error_not_a_crash(fmu_dir):
    import ctypes
    import gc
    s = LoggedSlave(fmu_dir / "lugre.fmu", "fr")
    try:
        s.init()
        f, c = s.s._functions, s.s.component
        bad = (ctypes.c_uint * 2)(s.vr["F"], 9999)
        out = (ctypes.c_double * 2)()
        assert f["fmi2GetReal"](c, bad, 2, out) == fmi2Error
        assert math.isnan(out[1])
        assert f["fmi2SetReal"](c, bad, 2, (ctypes.c_double * 2)(1.0, 2.0)) == fmi2Error
        assert any("9999" in m and "value references" in m for m in s.errors()), s.messages
        assert s.set("v", 1e-3) == fmi2OK and s.step(0.0, 1e-4) == fmi2OK
        assert math.isfinite(s.get("F"))
    finally:
        s.close()
    gc.collect()  # pythonfmu after an exception would leave the interpreter corrupt here


@needs_shim
def test_master_raises_fmu_error_naming_instance_call_and_time(fmu_dir):
    fmus = {"mass": fmu_dir / "mass.fmu", "friction": fmu_dir / "lugre.fmu"}
    conns = [("mass.v", "friction.v"), ("friction.F", "mass.F_friction")]
    with Master(fmus, conns, parameters={"friction": {"sigma0": -1.0}}) as m:
        with pytest.raises(FMUError) as exc:
            m.simulate(stop_time=0.51, step_size=1e-3, start_time=0.5)
    e = exc.value
    assert (e.instance, e.call, e.status) == ("friction", "fmi2SetReal(sigma0)", fmi2Error)
    assert e.time == pytest.approx(0.5)
    assert "sigma0" in str(e) and "> 0" in str(e) and "t = 0.5" in str(e)
    with Master(fmus, conns, start_values={"mass": {"F_ext": NAN}}) as m:
        with pytest.raises(FMUError) as exc:
            m.simulate(stop_time=0.01, step_size=1e-3)
    assert exc.value.instance == "mass" and exc.value.call == "fmi2SetReal(F_ext)"
    assert "F_ext" in str(exc.value) and "not finite" in str(exc.value)
    with Master(fmus, conns, parameters={"mass": {"m": 1e-300, "u0": 0.0, "u_amp": 1e-10}}) as m:
        with pytest.raises(FMUError) as exc:
            m.simulate(stop_time=1.0, step_size=1e-3)
    e = exc.value
    assert (e.instance, e.call, e.status) == ("mass", "fmi2DoStep", fmi2Error)
    assert 0.0 < e.time < 1.0 and f"t = {e.time:.9g}" in str(e) and "not finite" in str(e)


def test_without_a_compiler_the_build_warns_and_bad_input_gives_discard(tmp_path,
                                                                        monkeypatch):
    def no_compiler():
        raise status_shim.ShimUnavailable("no C compiler found (test)")
    monkeypatch.setattr(status_shim, "_compiler", no_compiler)
    monkeypatch.setenv("FRICTIONLAB_CACHE", str(tmp_path / "cache"))
    with pytest.warns(RuntimeWarning, match="fmi2Discard"):
        path = build_fmu(catalogue()["lugre"], tmp_path)
    assert validate(path) == []
    with zipfile.ZipFile(path) as z:
        assert "binaries/linux64/fl_lugre_pythonfmu.so" not in z.namelist()
    s = LoggedSlave(path, "fr")
    try:
        s.init()
        assert s.set("v", NAN) == fmi2OK  # pythonfmu's own binary: no error status
        assert any("input v" in m for m in s.errors())
        assert s.step(0.0, 1e-4) == 2  # fmi2Discard: the step is refused instead
        assert s.set("v", 1e-3) == fmi2OK
        assert s.step(0.0, 1e-4) == fmi2OK
        assert math.isfinite(s.get("F"))
    finally:
        s.close()


@pytest.mark.skipif(SHIM_REASON is not None, reason=f"no status shim: {SHIM_REASON}")
def test_shim_is_compiled_once_per_source_and_cached(tmp_path, monkeypatch):
    monkeypatch.setenv("FRICTIONLAB_CACHE", str(tmp_path))
    lib = status_shim.shim_library()
    assert lib.parent.parent == tmp_path and lib.is_file()
    mtime = lib.stat().st_mtime_ns
    assert status_shim.shim_library() == lib and lib.stat().st_mtime_ns == mtime
    assert list(lib.parent.iterdir()) == [lib]  # no leftover temporary files
