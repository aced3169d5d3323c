"""The project's FMU users with native FMUs: the master (parameters translated for either FMU
kind, the compiled per-step loop), the plant recipe and the co-simulation objectives give the
results of the pythonfmu FMUs."""
import math

import numpy as np
import pytest

import friction
from fmus import master_loop
from fmus.master import FMUError, Master, fmu_file, fmu_values, law_parameters
from fmus.native.ckernels import NativeBuildError, compiler
from fmus.proof import mass_connections, mass_master

try:
    compiler()
except NativeBuildError as exc:  # pragma: no cover - a host without a C compiler
    pytest.skip(f"no C compiler: {exc}", allow_module_level=True)

from fmus.testing import built_fmus, built_native_fmus  # noqa: E402

LAWS = ("lugre", "mass")


@pytest.fixture(scope="module")
def dirs():
    """(pythonfmu folder, native folder) with mass and lugre."""
    return built_fmus(LAWS), built_native_fmus(LAWS)


def _variables(path):
    from fmpy import read_model_description
    return {v.name: v for v in read_model_description(str(path)).modelVariables}


def _max_diff(a, b):
    return max(float(np.max(np.abs(a[c] - b[c]))) for c in a.dtype.names)


# -- parameters for either FMU kind -----------------------------------------------------------

def test_python_values_are_translated_for_either_kind(dirs):
    py = _variables(fmu_file(dirs[0], "lugre"))
    nat = _variables(fmu_file(dirs[1], "lugre", native=True))
    values = {"shape": "lorentzian", "Fc_neg": 0.8, "Fs_neg": None, "sigma0": 2e5,
              "inputs_at_step_end": 1}
    n = fmu_values(nat, values)
    assert n == {"shape": 2, "use_Fc_neg": True, "Fc_neg": 0.8, "use_Fs_neg": False,
                 "sigma0": 2e5, "inputs_at_step_end": True}
    assert type(n["shape"]) is int and type(n["inputs_at_step_end"]) is bool
    # the pythonfmu FMU declares the same Enumerations and use_ flags: the same values
    p = fmu_values(py, values)
    assert p == n and type(p["shape"]) is int
    assert py["shape"].type == "Enumeration" and py["use_Fs_neg"].type == "Boolean"
    with pytest.raises(ValueError, match="gaussian, lorentzian"):
        fmu_values(py, {"shape": "cosine"})
    with pytest.raises(ValueError, match="no flag use_sigma0"):
        fmu_values(py, {"sigma0": None})
    # an enumeration also takes its code, and refuses what is neither
    assert fmu_values(nat, {"shape": 1}) == {"shape": 1}
    with pytest.raises(ValueError, match="gaussian, lorentzian"):
        fmu_values(nat, {"shape": "cosine"})
    with pytest.raises(ValueError, match="no variable 'sigma9'"):
        fmu_values(nat, {"sigma9": 1.0})
    with pytest.raises(ValueError, match="Boolean"):
        fmu_values(nat, {"use_v_mean": "maybe"})
    # the master refuses an untranslatable value when it is built, naming the instance
    with pytest.raises(ValueError, match="instance 'friction'.*cosine"):
        Master({"friction": fmu_file(dirs[1], "lugre", True)},
               parameters={"friction": {"shape": "cosine"}})


def test_law_parameters_cover_options_and_unset_twins():
    law = friction.make_model("lugre", shape="lorentzian", Fc_neg=0.8)
    p = law_parameters(law, exclude={"sigma1"})
    assert p["shape"] == "lorentzian" and p["Fc_neg"] == 0.8 and p["Fs_neg"] is None
    assert "sigma1" not in p


# -- the master ---------------------------------------------------------------------------

@pytest.mark.parametrize("options", [{}, {"shape": "lorentzian", "Fc_neg": 0.6, "vs_neg": 3e-3}])
def test_mass_and_lugre_native_equal_pythonfmu_through_the_master(dirs, options):
    res = []
    for native, d in zip((False, True), dirs):
        with mass_master(d, "lugre", native=native) as m:
            m.parameters["friction"] = dict(options)
            res.append(m.simulate(stop_time=0.5, step_size=1e-4))
    py, nat = res
    assert nat.dtype.names == py.dtype.names
    for c in py.dtype.names:
        np.testing.assert_allclose(nat[c], py[c], rtol=0, atol=1e-12 * np.max(np.abs(py[c])))
    if options:  # the options reached both FMUs: the motion differs from the defaults'
        with mass_master(dirs[1], "lugre", native=True) as m:
            base = m.simulate(stop_time=0.5, step_size=1e-4)
        assert np.max(np.abs(base["friction.F"] - nat["friction.F"])) > 1e-3


@pytest.mark.parametrize("algorithm, iterations", [("gauss-seidel", 0), ("jacobi", 0),
                                                   ("gauss-seidel", 2), ("jacobi", 3)])
def test_compiled_loop_equals_the_python_loop_bit_for_bit(dirs, algorithm, iterations):
    if master_loop.library() is None:
        pytest.skip(f"no compiled master loop: {master_loop.UNAVAILABLE}")
    out = {}
    for loop in ("python", "c"):
        with mass_master(dirs[1], "lugre", native=True, algorithm=algorithm,
                         iterations=iterations) as m:
            m.loop = loop
            out[loop] = [m.simulate(stop_time=0.3, step_size=2e-4, progress=False)
                         for _ in range(2)]   # a second run after fmi2Reset
    for a, b in zip(out["python"], out["c"]):
        assert _max_diff(a, b) == 0.0


def test_compiled_loop_drives_pythonfmu_fmus_alike(dirs):
    if master_loop.library() is None:
        pytest.skip(f"no compiled master loop: {master_loop.UNAVAILABLE}")
    out = {}
    for loop in ("python", "c"):
        with mass_master(dirs[0], "lugre", iterations=1) as m:
            m.loop = loop
            out[loop] = m.simulate(stop_time=0.05, step_size=1e-4)
    assert _max_diff(out["python"], out["c"]) == 0.0


@pytest.mark.parametrize("native", [False, True])
def test_compiled_loop_reports_a_failed_call_like_the_python_loop(dirs, native):
    if master_loop.library() is None:
        pytest.skip(f"no compiled master loop: {master_loop.UNAVAILABLE}")
    # the mass overflows at a later time: the same instance, call and time from both loops
    errs = {}
    for loop in ("python", "c"):
        with Master({"mass": fmu_file(dirs[native], "mass", native),
                     "friction": fmu_file(dirs[native], "lugre", native)},
                    mass_connections("lugre"), loop=loop,
                    parameters={"mass": {"m": 1e-300, "u0": 0.0, "u_amp": 1e-10,
                                         "u_freq": 1.0}}) as m:
            with pytest.raises(FMUError) as exc:
                m.simulate(stop_time=1.0, step_size=1e-3)
        errs[loop] = exc.value
    a, b = errs["python"], errs["c"]
    assert (b.instance, b.call, b.status, b.time) == (a.instance, a.call, a.status, a.time)
    assert b.instance == "mass" and "not finite" in str(b) and b.time > 0
    with pytest.raises(ValueError, match="loop must be one of"):
        Master({"mass": fmu_file(dirs[1], "mass", True)}, loop="fortran")


# -- co-simulation objectives -----------------------------------------------------------------

@pytest.fixture(scope="module")
def prescribed():
    from friction.dataset import Dataset
    true = friction.make_model("lugre", sigma0=1e5, sigma1=300.0, sigma2=0.4, Fc=1.0, Fs=1.5,
                               vs=1e-3)
    t = np.arange(0, 0.4, 1e-3)
    v = 0.01 * np.sin(2 * np.pi * 2 * t) + 0.002 * np.sin(2 * np.pi * 9 * t)
    noise = 0.01 * np.random.default_rng(0).standard_normal(t.size)
    return Dataset.from_arrays(t, true.simulate(t, v) + noise, v=v)


def test_cosim_objective_cost_is_the_same_with_native_fmus(dirs, prescribed):
    from identification.cosim import CoSimObjective
    from identification.objectives import InProcessObjective
    names = ["sigma0", "sigma1", "Fc", "Fs", "vs"]
    X = np.array([[1e5, 300.0, 1.0, 1.5, 1e-3], [4e4, 80.0, 0.7, 2.2, 4e-3]])
    # an option and a direction twin that the objective must pass to either FMU kind
    model = friction.make_model("lugre", shape="lorentzian", Fc_neg=0.8)
    c_in = InProcessObjective(model, prescribed, names).costs(X)
    costs = {}
    for native, d in zip((False, True), dirs):
        obj = CoSimObjective(model, prescribed, names, fmu_dir=d, native=native)
        try:
            costs[native] = obj.costs(X)
        finally:
            obj.close()
    np.testing.assert_allclose(costs[True], costs[False], rtol=1e-9, atol=0)
    np.testing.assert_allclose(costs[True], c_in, rtol=1e-9, atol=0)
    with pytest.raises(FileNotFoundError, match="lugre_native.fmu"):
        CoSimObjective(model, prescribed, names, fmu_dir=dirs[0], native=True)


def test_closed_loop_objective_cost_is_the_same_with_native_fmus(dirs):
    from friction.dataset import Dataset
    from friction.reference import simulate_mass
    from identification.cosim import ClosedLoopCoSimObjective
    true = friction.make_model("lugre", sigma0=1e4, sigma1=20.0, sigma2=0.4, Fc=0.5, Fs=0.8,
                               vs=1e-2)
    t = np.arange(0, 0.3 + 1e-9, 1e-3)
    ref = simulate_mass(true, 1.0, t, lambda tq: 1.1 * np.sin(5 * tq))
    data = Dataset.from_arrays(t, ref["F"], v=ref["v"], x=ref["x"], check_units=False)
    X = np.array([[0.5, 0.8], [0.6, 0.7]])
    costs = {}
    for native, d in zip((False, True), dirs):
        obj = ClosedLoopCoSimObjective(true, data, ["Fc", "Fs"], mass=1.0, u_amp=1.1,
                                       u_freq=5 / (2 * math.pi), step=5e-4, fmu_dir=d,
                                       native=native)
        try:
            costs[native] = obj.costs(X)
        finally:
            obj.close()
    assert np.all(np.isfinite(costs[True]))
    np.testing.assert_allclose(costs[True], costs[False], rtol=1e-9, atol=0)


# -- plants with a native law -----------------------------------------------------------------

@pytest.fixture(scope="module")
def press_dirs():
    return built_fmus(("forging_press", "load_lugre")), built_native_fmus(("load_lugre",))


def test_press_with_the_native_load_law_equals_the_pythonfmu_law(press_dirs):
    # the switching law reads plant.low_share (use_low_share set by the recipe): without it
    # the law's bristle would advance in one regime and the force differ by ~1e4 N
    import shutil
    import tempfile
    from fmus.plant_fmus import plant_laws, plant_master
    from plants.forging_press import ForgingPress
    law = plant_laws(ForgingPress)["load_lugre"]
    with tempfile.TemporaryDirectory() as d:
        for src, name in ((press_dirs[0], "forging_press.fmu"), (press_dirs[0], "load_lugre.fmu"),
                          (press_dirs[1], "load_lugre_native.fmu")):
            shutil.copy(src / name, d)
        res = {}
        rec = ["plant.x", "friction.F", "plant.low_share", "friction.z"]
        for native in (False, True):
            with plant_master(d, "forging_press", law, native=native, record=rec) as m:
                # both kinds read plant.low_share only with use_low_share (no special case)
                assert m.parameters["friction"]["use_low_share"] is True
                res[native] = m.simulate(stop_time=0.4, step_size=0.01, progress=False)
    for c in rec:
        scale = np.max(np.abs(res[False][c]))
        np.testing.assert_allclose(res[True][c], res[False][c], rtol=0, atol=1e-12 * scale)
    assert np.ptp(res[False]["plant.low_share"]) > 0.5   # the switch is exercised


@pytest.mark.slow
def test_press_proof_with_the_native_load_law_gives_the_same_errors(press_dirs):
    import shutil
    import tempfile
    from fmus.plant_fmus import plant_laws, plant_proof
    from plants.forging_press import ForgingPress
    law = plant_laws(ForgingPress)["load_lugre"]
    with tempfile.TemporaryDirectory() as d:
        for src, name in ((press_dirs[0], "forging_press.fmu"), (press_dirs[0], "load_lugre.fmu"),
                          (press_dirs[1], "load_lugre_native.fmu")):
            shutil.copy(src / name, d)
        r = {native: plant_proof(d, "forging_press", law, stop=0.4, refinements=2,
                                 max_halvings=1, time_budget=120, native=native)
             for native in (False, True)}
    np.testing.assert_allclose(r[True]["errors"], r[False]["errors"], rtol=1e-9, atol=0)
    assert r[True]["errors"][0] < 5e-3


def test_identify_with_the_native_cosim_objective(prescribed):
    from identification import identify
    start = friction.make_model("lugre", sigma0=1e5, sigma1=300.0, sigma2=0.4, Fc=0.7, Fs=2.0,
                                vs=1e-3)
    a = identify(prescribed, start, algorithm="least_squares", names=["Fc", "Fs"])
    b = identify(prescribed, start, algorithm="least_squares", names=["Fc", "Fs"],
                 objective="cosim_native", executor="inline")
    for n in ("Fc", "Fs"):
        assert b.params[n] == pytest.approx(a.params[n], rel=1e-6)
    assert b.fit_nrmse == pytest.approx(a.fit_nrmse, rel=1e-9)
