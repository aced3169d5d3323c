"""Co-simulation master: algorithms, proof against the reference, errors, external tools."""
from __future__ import annotations

import json
import pathlib
import subprocess
import sys
import textwrap

import fmpy
import numpy as np
import pytest

from fmus.master import FMUError, Master
from fmus.proof import mass_connections, mass_proof
from fmus.testing import built_fmus

REC = ["mass.x", "friction.F"]


@pytest.fixture(scope="session")
def fmu_dir():
    import friction
    return built_fmus(tuple(sorted(friction.MODELS)) + ("mass",))


def _loop(fmu_dir, law="lugre"):
    return {"mass": fmu_dir / "mass.fmu", "friction": fmu_dir / f"{law}.fmu"}


def test_result_is_a_structured_array_with_time_first(fmu_dir):
    with Master(_loop(fmu_dir), mass_connections("lugre")) as m:
        res = m.simulate(stop_time=0.01, step_size=1e-3)
    assert res.dtype.names[0] == "time"
    # default record: every output of every instance
    expect = {f"{inst}.{v.name}" for inst, path in _loop(fmu_dir).items()
              for v in fmpy.read_model_description(str(path)).modelVariables
              if v.causality == "output"}
    assert set(res.dtype.names[1:]) == expect
    assert {"mass.x", "mass.v", "mass.a", "friction.F", "friction.z"} <= expect
    np.testing.assert_allclose(res["time"], 1e-3 * np.arange(11), atol=1e-15)


def test_defaults_come_from_the_default_experiment(fmu_dir):
    with Master(_loop(fmu_dir), mass_connections("lugre"), record=["mass.x"]) as m:
        de = m.default_experiment()
        assert de == {"start_time": 0.0, "stop_time": 1.0, "step_size": 1e-4}
        res = m.simulate()
    assert res.size == 10001 and res["time"][-1] == pytest.approx(1.0)


def test_gauss_seidel_and_jacobi_converge_first_order_to_the_reference(fmu_dir):
    # the mass + LuGre loop against the monolithic solve_ivp reference (stick-slip)
    for alg, bound in (("gauss-seidel", 1e-3), ("jacobi", 3e-3)):
        r = mass_proof(fmu_dir, "lugre", stop=0.2, rtol=1e-8, algorithm=alg)
        assert r["nrmse"] < bound, (alg, r)
        assert r["order"] > 0.9, (alg, r)
        assert r["errors"][0] > 1.8 * r["errors"][1], (alg, r)


def test_jacobi_lags_gauss_seidel_by_the_coupling_delay(fmu_dir):
    out = {}
    for alg in ("gauss-seidel", "jacobi"):
        with Master(_loop(fmu_dir), mass_connections("lugre"), algorithm=alg, record=REC) as m:
            out[alg] = m.simulate(stop_time=0.05, step_size=1e-4)
    d = np.abs(out["jacobi"]["mass.x"] - out["gauss-seidel"]["mass.x"])
    assert d.max() > 0
    assert d.max() < 1e-2 * np.ptp(out["gauss-seidel"]["mass.x"])


@pytest.mark.slow
def test_fixed_point_iteration_makes_the_loop_consistent(fmu_dir):
    # mass.a is a feedthrough of F_friction: after the step the friction force changes, so
    # without iteration the recorded acceleration is stale; with it, m a = u(t) - F holds
    conns = mass_connections("modified_lugre")
    rec = ["mass.a", "friction.F"]
    params = {"mass": {"u_amp": 12.0, "u0": 0.0, "u_freq": 1.0, "m": 1.0}}
    gaps = {}
    for it in (0, 10):
        with Master(_loop(fmu_dir, "modified_lugre"), conns, iterations=it, record=rec,
                    parameters=params) as m:
            res = m.simulate(stop_time=0.05, step_size=1e-4)
        u = 12.0 * np.sin(2 * np.pi * res["time"])
        gaps[it] = np.max(np.abs(res["mass.a"] - (u - res["friction.F"])))
    assert gaps[0] > 1e-3
    assert gaps[10] < 1e-9 * (1 + gaps[0])


def test_parameters_and_start_values_per_instance(fmu_dir):
    res = {}
    for m_ in (1.0, 4.0):
        with Master(_loop(fmu_dir), mass_connections("lugre"), record=["mass.x"],
                    parameters={"mass": {"m": m_, "u0": 5.0, "u_amp": 0.0}}) as m:
            res[m_] = m.simulate(stop_time=0.2, step_size=1e-4)["mass.x"][-1]
    assert res[1.0] > 3.5 * res[4.0] > 0  # x ~ (u0 - F) t^2 / 2m


def test_connection_and_name_errors_are_clear(fmu_dir):
    fmus = _loop(fmu_dir)
    with pytest.raises(ValueError, match="no variable 'vel'"):
        Master(fmus, [("mass.vel", "friction.v")])
    with pytest.raises(ValueError, match="unknown instance 'bogus'"):
        Master(fmus, [("bogus.v", "friction.v")])
    with pytest.raises(ValueError, match="not an output"):
        Master(fmus, [("friction.v", "mass.F_friction")])
    with pytest.raises(ValueError, match="driven twice"):
        Master(fmus, [("mass.v", "friction.v"), ("mass.x", "friction.v")])
    with pytest.raises(ValueError, match="algorithm"):
        Master(fmus, [], algorithm="newton")


def test_fmu_errors_name_the_instance_the_call_and_the_time(fmu_dir):
    # an inadmissible parameter: fmi2Error from the fmi2SetReal that sets it
    with Master(_loop(fmu_dir), mass_connections("lugre"),
                parameters={"friction": {"sigma0": -1.0}}) as m:
        with pytest.raises(FMUError) as exc:
            m.simulate(stop_time=0.51, step_size=1e-3, start_time=0.5)
    e = exc.value
    assert e.instance == "friction" and e.call == "fmi2SetReal(sigma0)"
    assert e.time == pytest.approx(0.5)
    assert "sigma0" in str(e) and "friction" in str(e) and "t = 0.5" in str(e)
    # an overflow inside the mass FMU at a later time
    with Master(_loop(fmu_dir), mass_connections("lugre"),
                parameters={"mass": {"m": 1e-300, "u0": 0.0, "u_amp": 1e-10,
                                     "u_freq": 1.0}}) as m:
        with pytest.raises(FMUError) as exc:
            m.simulate(stop_time=1.0, step_size=1e-3)
    assert exc.value.instance == "mass" and "not finite" in str(exc.value)


def test_progress_is_shown_on_long_runs(fmu_dir, capsys):
    with Master(_loop(fmu_dir), mass_connections("lugre"), record=["mass.x"]) as m:
        m.simulate(stop_time=0.2, step_size=1e-4, progress=True)
    err = capsys.readouterr().err
    assert "[cosim]" in err and "2000/2000" in err and ("step/s" in err or "s/step" in err)
    assert "<" in err  # elapsed<remaining: the ETA of a run of known length


# -- external tools ------------------------------------------------------------------------

def test_libcosim_gives_our_jacobi_trajectories(fmu_dir):
    pytest.importorskip("libcosimpy", reason="libcosimpy (OSP libcosim) is not importable")
    from fmus.external import run_libcosim
    fmus, conns = _loop(fmu_dir), mass_connections("lugre")
    ext = run_libcosim(fmus, conns, step_size=1e-4, stop_time=0.1, record=REC)
    with Master(fmus, conns, algorithm="jacobi", record=REC) as m:
        ours = m.simulate(stop_time=0.1, step_size=1e-4)
    np.testing.assert_allclose(ext["time"], ours["time"][1:], atol=1e-12)
    for c in REC:
        np.testing.assert_allclose(ext[c], ours[c][1:], rtol=1e-9,
                                   atol=1e-12 * np.max(np.abs(ours[c])))


def test_libcosim_is_never_handed_a_missing_or_broken_fmu(fmu_dir, tmp_path):
    """libcosim itself dies with SIGSEGV on a missing FMU path; ``run_libcosim`` must answer
    a Python error naming the instance and file first. Run in a child process, so that a
    regression fails this test instead of killing the test session."""
    pytest.importorskip("libcosimpy", reason="libcosimpy (OSP libcosim) is not importable")
    broken = tmp_path / "broken.fmu"
    broken.write_bytes(b"not a zip")
    good = str(_loop(fmu_dir)["friction"])
    code = textwrap.dedent(f"""
        import json, sys
        sys.path.insert(0, {str(pathlib.Path(__file__).resolve().parents[1])!r})
        from fmus.external import run_libcosim
        out = []
        for bad in ({str(tmp_path / 'gone.fmu')!r}, {str(broken)!r}):
            fmus = {{"friction": {good!r}, "mass": bad}}
            try:
                run_libcosim(fmus, [], step_size=1e-4, stop_time=1e-3, record=[])
                out.append(["no error", ""])
            except Exception as exc:
                out.append([type(exc).__name__, str(exc)])
        print(json.dumps(out))
    """)
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=300)
    assert res.returncode == 0, f"child died (rc {res.returncode}): {res.stderr[-2000:]}"
    (k1, m1), (k2, m2) = json.loads(res.stdout.strip().splitlines()[-1])
    assert k1 == "FileNotFoundError" and "'mass'" in m1 and "gone.fmu" in m1
    assert k2 == "ValueError" and "'mass'" in m2 and "broken.fmu" in m2


@pytest.mark.parametrize("sequential,alg", [(True, "gauss-seidel"), (False, "jacobi")])
def test_container_fmu_gives_our_trajectories(fmu_dir, tmp_path, sequential, alg):
    pytest.importorskip("fmu_manipulation_toolbox",
                        reason="fmu-manipulation-toolbox is not importable")
    from fmus.build import validate
    from fmus.external import make_container
    fmus, conns = _loop(fmu_dir), mass_connections("lugre")
    cont = make_container(fmus, conns, tmp_path / "loop.fmu", step_size=1e-4, expose=REC,
                          sequential=sequential)
    assert validate(cont) == []
    with Master({"c": cont}, [], record=["c.mass_x", "c.friction_F"]) as m:
        ext = m.simulate(stop_time=0.1, step_size=1e-4)
    with Master(fmus, conns, algorithm=alg, record=REC) as m:
        ours = m.simulate(stop_time=0.1, step_size=1e-4)
    np.testing.assert_allclose(ext["c.mass_x"], ours["mass.x"], rtol=1e-12, atol=1e-18)
    np.testing.assert_allclose(ext["c.friction_F"], ours["friction.F"], rtol=1e-10, atol=1e-14)


@pytest.mark.slow
@pytest.mark.parametrize("law", ["stribeck", "modified_lugre", "load_lugre", "mre_lugre", "gms",
                                 "backlash_lugre"])
def test_every_law_in_the_mass_loop_matches_the_reference(fmu_dir, law):
    r = mass_proof(fmu_dir, law, rtol=1e-9)
    assert r["nrmse"] <= 1e-3, r
    assert r["order"] > 0.9, r
