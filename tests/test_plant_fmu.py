"""The user's own plant FMU (issue 14 section 1): connection files (fmus.connect), the master's
connection factors and measured inputs, identification and trajectory-level diagnosis
through plant FMUs the plant library did not build (a C FMU compiled here, a pythonfmu FMU
written here; tests/user_plants.py)."""
from __future__ import annotations

import json
import math

import numpy as np
import pytest

pytest.importorskip("fmpy")

from friction import make_model  # noqa: E402
from fmus.connect import (ConnectError, MeasuredRecord, PlantLoop,  # noqa: E402
                          builtin_connection, load_connection, parse_connection)
from fmus.master import Master, fmu_file, law_parameters  # noqa: E402

LAWS = ("friction_effects", "lugre", "mass")


@pytest.fixture(scope="module")
def native_dir():
    from fmus.testing import built_native_fmus
    return built_native_fmus(LAWS)


@pytest.fixture(scope="module")
def cart(tmp_path_factory):
    from user_plants import build_c_cart
    return build_c_cart(tmp_path_factory.mktemp("c_cart"))


@pytest.fixture(scope="module")
def py_cart(tmp_path_factory):
    pytest.importorskip("pythonfmu")
    from user_plants import build_python_cart
    return build_python_cart(tmp_path_factory.mktemp("py_cart"), "PyCartPlantFmuTests")


def _record(T=1.0, dt=1e-3, **cols):
    t = np.arange(0.0, T + 1e-9, dt)
    return MeasuredRecord(t, {k: f(t) for k, f in cols.items()}, "rec")


CART = {  # the C cart: the law's force enters F_c, which the cart *adds* (sign -1)
    "step": 1e-4,
    "friction": {"input": "F_c", "sign": -1, "v": "vel", "x": "pos", "a": "acc"},
    "inputs": {"u": "u"},
    "compare": {"pos": {"column": "x", "unit": "m"}},
    "parameters": {"k_u": 2.0, "m": 1.5},
    "identify": {"m": [0.5, 3.0]},
}


# -- the master: connection factors, measured inputs ------------------------------------------
def test_master_connection_factor_and_external_inputs_c_loop_equals_python(native_dir):
    """friction.F -> mass.F_ext with factor -1 is the plain connection into F_friction; an
    external input table drives F_ext; the compiled loop equals the Python loop bit for bit
    and a step's recorded input is the table's row held over it."""
    mass, law = fmu_file(native_dir, "mass", True), fmu_file(native_dir, "lugre", True)
    par = {"mass": {"m": 1.0, "u_amp": 2.0, "u_freq": 1.0}}
    plain = Master({"mass": mass, "friction": law}, [("mass.v", "friction.v"),
                                                    ("friction.F", "mass.F_friction")],
                   parameters=par, record=["mass.x"])
    neg = Master({"mass": mass, "friction": law}, [("mass.v", "friction.v"),
                                                  ("friction.F", "mass.F_ext", -1.0)],
                 parameters=par, record=["mass.x"])
    with plain, neg:
        a = plain.simulate(stop_time=0.5, step_size=1e-4)
        b = neg.simulate(stop_time=0.5, step_size=1e-4)
    assert np.array_equal(a["mass.x"], b["mass.x"])

    n = 5000
    u = 1.5 * np.sin(2 * np.pi * 2.0 * 1e-4 * np.arange(n + 1))
    out = {}
    for loop in ("c", "python"):
        with Master({"mass": mass, "friction": law},
                    [("mass.v", "friction.v"), ("friction.F", "mass.F_friction")],
                    parameters={"mass": {"m": 1.0, "u_amp": 0.0}}, inputs=["mass.F_ext"],
                    record=["mass.x", "mass.F_ext"], loop=loop) as m:
            out[loop] = m.simulate(stop_time=0.5, step_size=1e-4, inputs={"mass.F_ext": u})
    assert np.array_equal(out["c"]["mass.x"], out["python"]["mass.x"])
    assert np.array_equal(out["c"]["mass.F_ext"][1:], u[:n])
    assert np.ptp(out["c"]["mass.x"]) > 1e-3
    with Master({"mass": mass}, [], inputs=["mass.F_ext"]) as m:
        with pytest.raises(ValueError, match="F_ext: 3 values for 10 steps"):
            m.simulate(stop_time=1e-3, step_size=1e-4, inputs={"mass.F_ext": [0, 1, 2]})
        with pytest.raises(ValueError, match="no values given"):
            m.simulate(stop_time=1e-3, step_size=1e-4)
    with pytest.raises(ValueError, match="mass.x is a output, not an input"):
        Master({"mass": mass}, [], inputs=["mass.x"])


# -- connection files ----------------------------------------------------------------------------
def _readme_toml() -> str:
    """The complete connection file of the README's "Your own plant FMU" section."""
    import pathlib
    text = (pathlib.Path(__file__).resolve().parents[1] / "README.md").read_text()
    sec = text[text.index("### Your own plant FMU"):]
    return sec[sec.index("```toml") + len("```toml"):sec.index("```", sec.index("```toml") + 7)]




def test_connection_file_parses_and_checks_against_the_plant(tmp_path, cart):
    from fmus.connect import check_plant
    p = tmp_path / "rig.toml"
    p.write_text(_readme_toml())
    conn = load_connection(p)
    assert conn.sign == -1.0 and conn.friction_input == "F_c"
    assert conn.law_inputs == {"v": "vel", "x": "pos", "a": "acc"}
    assert conn.inputs[0].column == "volt" and conn.inputs[0].hold == "previous"
    assert conn.compare[0].scale == 1e-3 and conn.identify[0].start == 1.4
    assert conn.law_bounds == {"Fc": (0.1, 5.0)} and conn.law_names[0] == "Fc"
    assert conn.columns == ["t", "volt", "x_mm"]
    V = check_plant(conn, cart, make_model("lugre"))
    assert V["pos"].causality == "output"
    for raw, match in [({"friction": {"input": "F_c"}}, r"needs v ="),
                       ({"friction": {"input": "F_c", "v": "vel", "sign": 2}}, "sign"),
                       ({"friction": {"input": "F_c", "v": "vel"}}, r"\[compare\]: missing"),
                       ({"friction": {"input": "F_c", "v": "vel"}, "compare": {"pos": "x"},
                         "identify": {"m": [3, 1]}}, "HIGH must exceed LOW"),
                       ({"friction": {"input": "F_c", "v": "vel"}, "compare": {"pos": "x"},
                         "inputs": {"u": {"column": "v", "hold": "cubic"}}}, "hold"),
                       ({"friction": {"input": "F_c", "v": "vel"}, "compare": {"pos": "x"},
                         "stpe": 1e-3}, "unknown key")]:
        with pytest.raises(ConnectError, match=match):
            parse_connection(raw, "rig.toml")


def test_builtin_mass_is_a_special_case_of_the_same_path(native_dir):
    """The project's mass FMU through a connection = the mass + law master of the proofs
    (fmus.proof.mass_master, ClosedLoopCoSimObjective's loop), bit for bit."""
    from fmus.proof import mass_master, mass_scenario
    law = make_model("lugre")
    sc = mass_scenario("lugre")
    conn = builtin_connection("mass", **{k: sc[k] for k in ("m", "u0", "u_amp", "u_freq",
                                                           "v0")})
    conn.step = 1e-4
    rec = _record(1.0, x=np.zeros_like)
    with PlantLoop(fmu_file(native_dir, "mass", True), conn, law, fmu_dir=native_dir) as pl:
        run = pl.run(rec, law_parameters(law))
    with mass_master(native_dir, "lugre", native=True) as m:
        ref = m.simulate(stop_time=1.0, step_size=1e-4)
    assert np.array_equal(run.values["x"], ref["mass.x"])
    assert np.array_equal(run.values["friction.F"], ref["friction.F"])


@pytest.mark.slow
def test_builtin_plant_fmu_is_a_special_case_of_the_same_path(native_dir):
    """A plant FMU of the plant library (valve, external friction) through its connection
    = fmus.plant_fmus.plant_master with the force held over a step, bit for bit."""
    import shutil
    import plants
    from fmus.plant_fmus import classic_lugre_for, plant_master
    from fmus.testing import built_fmus
    d = built_fmus(("valve",))
    shutil.copy(fmu_file(native_dir, "lugre", True), fmu_file(d, "lugre", True))
    cls = plants.PLANTS["valve"]
    law = classic_lugre_for(cls)
    h = 0.25 / cls.data_rate
    with plant_master(d, "valve", law, coupling="hold", native=True,
                      record=["plant.x", "friction.F"]) as m:
        ref = m.simulate(stop_time=0.05, step_size=h)
    conn = builtin_connection("valve", law)
    conn.step = h
    t = np.arange(0.0, 0.05 + 1e-12, 1.0 / cls.data_rate)
    with PlantLoop(fmu_file(d, "valve"), conn, law, fmu_dir=d) as pl:
        run = pl.run(MeasuredRecord(t, {"x": np.zeros_like(t)}), law_parameters(law))
    assert np.ptp(ref["plant.x"]) > 1e-3
    assert np.array_equal(run.values["x"], ref["plant.x"])


def test_further_plant_side_fmus_close_the_loop_through_the_connection(tmp_path, cart,
                                                                        native_dir):
    """A controller FMU beside the plant ([fmus], [connections], qualified names): the
    measured reference drives the controller, the controller the cart; the loop equals a
    Master of the same three FMUs built by hand bit for bit, and the law's Fc and the
    cart's mass are identified against position and command together."""
    from identification.plant_fmu import identify_plant_fmu
    from user_plants import build_c_pd
    pd = build_c_pd(tmp_path)
    text = f"""
step = 1e-4
order = ["plant", "pd", "friction"]

[fmus]
pd = "{pd.name}"

[connections]
"plant.pos" = "pd.y"
"plant.vel" = "pd.ydot"
pd.u = "plant.u"

[friction]
input = "F_c"
sign = -1
v = "vel"

[inputs]
"pd.r" = "ref"

[compare]
pos = "x"
"pd.u" = {{ column = "cmd", unit = "V", weight = 0.5 }}

[parameters]
k_u = 2.0
m = 1.5
pd.kp = 40.0

[identify]
m = [0.5, 3.0]
"""
    (tmp_path / "loop.toml").write_text(text)
    conn = load_connection(tmp_path / "loop.toml")
    assert conn.links == [("pos", "pd.y"), ("vel", "pd.ydot"), ("pd.u", "u")]
    assert conn.parameters == {"k_u": 2.0, "m": 1.5, "pd.kp": 40.0}
    law = make_model("lugre")
    t = np.arange(0.0, 2.0 + 1e-9, 1e-3)
    ref = 0.05 * (1 - np.cos(2 * np.pi * 0.5 * t))
    probe = MeasuredRecord(t, {"ref": ref, "x": ref, "cmd": ref}, "probe")
    with PlantLoop(cart, conn, law, fmu_dir=native_dir) as pl:
        run = pl.run(probe, law_parameters(law))
    n = 20000
    r_mid = np.interp(1e-4 * np.arange(n + 1) + 0.5e-4, t, ref)  # "linear" hold
    with Master({"plant": str(cart), "pd": str(pd),
                 "friction": fmu_file(native_dir, "lugre", True)},
                [("plant.pos", "pd.y"), ("plant.vel", "pd.ydot"), ("pd.u", "plant.u"),
                 ("plant.vel", "friction.v"), ("friction.F", "plant.F_c", -1.0)],
                parameters={"plant": {"k_u": 2.0, "m": 1.5}, "pd": {"kp": 40.0},
                            "friction": law_parameters(law)},
                inputs=["pd.r"], record=["plant.pos", "pd.u"]) as m:
        hand = m.simulate(stop_time=2.0, step_size=1e-4, inputs={"pd.r": r_mid})
    assert np.array_equal(run.values["pos"], hand["plant.pos"])
    assert np.array_equal(run.values["pd.u"], hand["pd.u"])
    assert np.ptp(hand["plant.pos"]) > 0.05

    truth = law.with_values(Fc=1.3)
    with PlantLoop(cart, conn, truth, fmu_dir=native_dir) as pl:
        r2 = pl.run(probe, law_parameters(truth), {"m": 1.8})
    rec = MeasuredRecord(t, {"ref": ref, "x": r2.at("pos", t), "cmd": r2.at("pd.u", t)},
                         "loop")
    res = identify_plant_fmu(rec, cart, conn, law, names=["Fc", "plant.m"],
                             algorithm="least_squares", fmu_dir=native_dir)
    assert abs(res.params["Fc"] - 1.3) < 1e-4 and abs(res.params["plant.m"] - 1.8) < 1e-4
    assert set(res.channels["fit"]) == {"pos", "pd.u"}
    # the cost: root of the weighted (1 : 0.5) mean square of the channels' NRMSE
    from identification.plant_fmu import PlantFMUObjective
    obj = PlantFMUObjective(law, rec, ["Fc", "plant.m"], conn, cart, fmu_dir=native_dir)
    x = np.array([1.2, 1.7])
    per = obj.channel_nrmse(x)
    want = math.sqrt((1.0 * per["pos"] ** 2 + 0.5 * per["pd.u"] ** 2) / 1.5)
    assert obj.costs(x[None, :])[0] == pytest.approx(want, rel=1e-12)
    assert float(np.sum(obj.residuals(x) ** 2)) == pytest.approx(want ** 2, rel=1e-12)
    obj.close()


# -- bad input: one line each, naming the variable or the time --------------------------------
def _cli(capsys, argv):
    from frictionlab.cli import main
    code = main(argv)
    err = capsys.readouterr().err.strip()
    return code, err


def _write_run(path, t, volt, x):
    np.savetxt(path, np.column_stack([t, volt, x]), delimiter=",", header="t,volt,x",
               comments="")


@pytest.mark.parametrize("edit, match", [
    (lambda c: c["friction"].update(v="speed"),
     r"\[friction\] v: cart.fmu has no variable 'speed' \(outputs: acc, pos, vel\)"),
    (lambda c: c["friction"].update(input="pos"),
     r"\[friction\] input: 'pos' is an output of cart.fmu, not an input"),
    (lambda c: c["compare"].update(F_c="x"),
     r"\[compare\] F_c: 'F_c' is an input of cart.fmu, not an output"),
    (lambda c: c["friction"].update(input="F_kN"),
     r"unit mismatch: cart.fmu declares 'F_kN' in 'kN', but the friction force is in 'N'"),
    (lambda c: c["compare"].update(pos={"column": "x", "unit": "mm"}),
     r"\[compare\] pos: unit mismatch: cart.fmu declares 'pos' in 'm', but column 'x' is in "
     r"'mm'"),
    (lambda c: c["inputs"].update(u="current"),
     r"measured column 'current' not found \(named in rig.toml \[inputs\] u\); columns: t, "
     r"volt, x"),
    (lambda c: c["parameters"].update(m=0.0),
     r"plant FMU cart.fmu failed to initialise: .*fmi2ExitInitializationMode returned error "
     r"at t = 0 s: m = 0 is out of bounds: must be > 0 \[kg\]"),
    (lambda c: c["parameters"].update(d=-3e4),
     r"plant FMU cart.fmu diverged: output '(pos|vel)' is \S+ at t = 0\.0\d+ s"),
])
def test_bad_input_is_one_line_naming_the_variable_or_the_time(tmp_path, capsys, cart,
                                                               native_dir, monkeypatch, edit,
                                                               match):
    raw = {"step": 1e-4, "friction": {"input": "F_c", "sign": -1, "v": "vel"},
           "inputs": {"u": "volt"}, "compare": {"pos": "x"},
           "parameters": {"k_u": 2.0, "m": 1.5}, "law": {"names": ["Fc"]}}
    edit(raw)
    (tmp_path / "rig.toml").write_text(_toml(raw))
    t = np.arange(0, 0.3, 1e-3)
    _write_run(tmp_path / "run.csv", t, np.sin(10 * t), 1e-3 * np.sin(10 * t))
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr("identification.cosim.fmu_dir_for",
                        lambda laws, d=None, native=False: str(native_dir))
    import re
    for argv in (["identify", "run.csv", "--max-evals", "3"],
                 ["diagnose", "run.csv", "run.csv", "--candidates", "delay"]):
        code, err = _cli(capsys, argv + ["--plant-fmu", str(cart), "--connect", "rig.toml",
                                         "--quiet"])
        assert code == 2, argv
        assert len(err.splitlines()) == 1, err
        assert re.search(match, err), err


def _toml(raw) -> str:
    """A small TOML writer for the tests' connection dicts."""
    def val(v):
        if isinstance(v, str):
            return json.dumps(v)
        if isinstance(v, bool):
            return "true" if v else "false"
        if isinstance(v, (list, tuple)):
            return "[" + ", ".join(val(x) for x in v) + "]"
        if isinstance(v, dict):
            return "{ " + ", ".join(f"{k} = {val(x)}" for k, x in v.items()) + " }"
        return repr(float(v))
    top = [f"{k} = {val(v)}" for k, v in raw.items() if not isinstance(v, dict)]
    tables = [f"[{k}]\n" + "\n".join(f"{kk} = {val(vv)}" for kk, vv in v.items())
              for k, v in raw.items() if isinstance(v, dict)]
    return "\n".join(top) + "\n\n" + "\n\n".join(tables) + "\n"


def test_a_diverging_trial_point_costs_inf_and_the_run_goes_on(cart, native_dir):
    """The plant's damping d identified in a box whose negative end makes the cart unstable:
    those trial points cost inf (their residuals a large constant) and the identification
    finishes at the truth."""
    from identification.plant_fmu import PlantFMUObjective, identify_plant_fmu
    law = make_model("lugre", Fc=1.0, Fs=1.5)
    conn = parse_connection({**CART, "step": 2e-4,
                             "identify": {"d": {"bounds": [-4e4, 20.0], "start": 5.0}},
                             "parameters": {"k_u": 2.0, "m": 1.5, "d": 2.0}})
    t = np.arange(0, 0.8 + 1e-9, 1e-3)
    volt = 1.3 * np.sin(2 * np.pi * 1.5 * t)
    truth = MeasuredRecord(t, {"u": volt, "x": np.zeros_like(t)}, "truth")
    with PlantLoop(cart, conn, law, fmu_dir=native_dir) as pl:
        x = pl.run(truth, law_parameters(law), {"d": 2.0}).at("pos", t)
    rec = MeasuredRecord(t, {"u": volt, "x": x}, "run")
    obj = PlantFMUObjective(law, rec, ["plant.d"], conn, cart, fmu_dir=native_dir)
    costs = obj.costs(np.array([[2.0], [-4e4], [5.0]]))
    assert costs[0] < 1e-9 and costs[1] == np.inf and 0 < costs[2] < 1
    assert np.all(obj.residuals(np.array([-4e4])) > 0)
    import pickle  # what a process pool or a dask worker receives: opens its own FMUs
    twin = pickle.loads(pickle.dumps(obj))
    assert np.array_equal(twin.costs(np.array([[5.0]])), costs[2:])
    twin.close()
    obj.close()
    res = identify_plant_fmu(rec, cart, conn, law, names=["plant.d"], fmu_dir=native_dir,
                             algorithm="multistart_ls", n_screen=12, n_starts=1,
                             polish_nfev=30)
    assert abs(res.params["plant.d"] - 2.0) < 1e-3, res.params


# -- identification through the user's plant: recovers law and plant parameters ----------------
TRUTH = dict(sigma0=1e5, sigma1=300.0, sigma2=0.4, Fc=1.0, Fs=1.5, vs=1e-3)
M_TRUE, K_U = 1.5, 2.0


def _drive(t, A=2.2, f1=0.7, f2=2.3, bias=0.0):
    return A * np.sin(2 * np.pi * f1 * t) + 0.6 * np.sin(2 * np.pi * f2 * t) + bias


def _measured(model, T, dt, force, seed, name, noise=1e-6, volt=True):
    """A measured run made by the reference integrator (Radau, monolithic mass + law states,
    friction.reference.simulate_mass) at the data interval, white position noise added: a
    different integrator and coupling than the co-simulation that fits it."""
    from friction.reference import simulate_mass
    t = np.arange(0.0, T + 1e-9, dt)
    ref = simulate_mass(model, M_TRUE, t, force, rtol=1e-6)
    x = ref["x"] + np.random.default_rng(seed).normal(0.0, noise, t.size)
    drive = force(t) / K_U if volt else force(t)
    return MeasuredRecord(t, {"u" if volt else "F": drive, "x": x}, name)


@pytest.fixture(scope="module")
def lugre_run():
    return _measured(make_model("lugre", **TRUTH), 2.5, 1e-3, _drive, 1, "stick-slip")


def test_identification_through_a_c_plant_fmu_recovers_law_and_mass(cart, native_dir,
                                                                     lugre_run):
    """Synthetic stick-slip run of a 1.5 kg cart (2.5 s at 1 kHz, 1 um noise) from the
    reference integrator; the law FMU (native LuGre) co-simulated with the C cart at 0.1 ms
    recovers Fc, Fs, vs, sigma2 and the cart's mass from a start 30-100 % off."""
    from identification.plant_fmu import identify_plant_fmu
    rec = lugre_run
    conn = parse_connection({**CART, "parameters": {"k_u": K_U, "m": 1.0},
                             "law": {"start": {"Fc": 0.7, "Fs": 1.1, "vs": 2e-3,
                                               "sigma2": 0.8}}}, "rig.toml")
    res = identify_plant_fmu(rec, cart, conn, "lugre",
                             names=["Fc", "Fs", "vs", "sigma2", "plant.m"],
                             algorithm="least_squares", fmu_dir=native_dir)
    p = res.params
    assert abs(p["Fc"] / TRUTH["Fc"] - 1) < 0.01, p
    assert abs(p["Fs"] / TRUTH["Fs"] - 1) < 0.02, p
    assert abs(p["vs"] / TRUTH["vs"] - 1) < 0.05, p
    assert abs(p["sigma2"] / TRUTH["sigma2"] - 1) < 0.03, p
    assert abs(p["plant.m"] / M_TRUE - 1) < 0.005, p
    assert res.fit_nrmse < 2e-4 and res.plant_params == {"m": p["plant.m"]}
    assert res.identifiability["at_bound"] == [] and set(res.ci) == set(p)
    json.loads(res.to_json())


def test_identification_through_a_pythonfmu_plant_fmu(py_cart, native_dir):
    """The same through a pythonfmu cart written for the test (m dv/dt = F_drive -
    F_friction, friction subtracted: sign +1; measured force drives it; no units
    declared): Fc, sigma2 and the mass."""
    from identification.plant_fmu import identify_plant_fmu
    law = make_model("lugre", **{**TRUTH, "sigma0": 1e4, "sigma1": 100.0})
    rec = _measured(law, 1.5, 2e-3, _drive, 3, "py", volt=False)
    conn = parse_connection({
        "step": 1e-3, "friction": {"input": "F_friction", "v": "v"},
        "inputs": {"F_drive": "F"}, "compare": {"x": "x"}, "parameters": {"m": 1.0},
        "identify": {"m": [0.5, 3.0]}}, "py.toml")
    res = identify_plant_fmu(rec, py_cart, conn, law.with_values(Fc=0.7, sigma2=0.8),
                             names=["Fc", "sigma2", "plant.m"], algorithm="least_squares",
                             fmu_dir=native_dir)
    p = res.params
    assert abs(p["Fc"] - 1.0) < 0.01 and abs(p["sigma2"] - 0.4) < 0.02, p
    assert abs(p["plant.m"] - M_TRUE) < 0.015, p


# -- trajectory-level diagnosis through the user's plant ----------------------------------------
class TrackLuGre:
    """The 'real' contact: LuGre whose Coulomb and static levels change along the stroke
    (a worn track, 1 + c sin(2 pi x / lam) inside the Stribeck curve, so the bristle dynamics
    see it) - not the candidate's form (the whole force times a piecewise-linear map)."""
    name = "lugre_track"
    state_names = ("z",)
    extra_inputs = ("x",)

    def __init__(self, c=0.4, lam=0.8, **p):
        self.c, self.lam, self.p = c, lam, {**TRUTH, **p}

    def initial_state(self):
        return np.zeros(1)

    def _dz(self, s, v, x):
        p = self.p
        g = (1 + self.c * math.sin(2 * math.pi * x / self.lam)) * (
            p["Fc"] + (p["Fs"] - p["Fc"]) * math.exp(-(v / p["vs"]) ** 2))
        return v - p["sigma0"] * abs(v) * s[0] / g

    def derivatives(self, s, v, x=0.0):
        return np.array([self._dz(s, v, x)])

    def force(self, s, v, x=0.0):
        p = self.p
        return p["sigma0"] * s[0] + p["sigma1"] * self._dz(s, v, x) + p["sigma2"] * v


@pytest.fixture(scope="module")
def track_runs():
    truth = TrackLuGre()
    fit = _measured(truth, 3.0, 1e-3, lambda t: _drive(t, 2.5, 0.7, 2.3), 1, "fit")
    held = _measured(truth, 3.0, 1e-3, lambda t: _drive(t, 2.5, 0.56, 3.0), 2, "held-out")
    return fit, held


TRACK_CONN = {**CART, "step": 2e-4, "identify": {},
              "law": {"start": {"Fc": 1.05, "Fs": 1.5, "vs": 1e-3, "sigma2": 0.4}}}


def test_diagnosis_through_the_plant_fmu_names_the_withheld_position_effect(cart, native_dir,
                                                                            track_runs):
    """The fit and held-out runs come from a cart whose friction levels change along the
    track; the model the user has is plain LuGre (Coulomb level 5 % off) in their plant FMU.
    Every candidate runs through the friction_effects block between the law FMU and the C
    cart; position is named."""
    from diagnosis.plant_fmu import diagnose_plant_fmu
    fit, held = track_runs
    conn = parse_connection(TRACK_CONN, "rig.toml")
    rep = diagnose_plant_fmu(fit, [held], cart, conn, "lugre", max_sims=40,
                             candidates=["position", "asymmetry", "inertia", "acceleration",
                                         "drift"], fmu_dir=native_dir)
    assert rep["verdict"]["cause"] == "position", rep.summary()
    assert rep["verdict"]["gap_closed"] > 0.5, rep.summary()
    assert rep["engine"] == "fmu" and rep["plant"] == "cart" and rep["level"] == "trajectory"
    assert rep["effect_details"]["position"]["effects"] == ["position"]
    json.loads(rep.to_json())


def test_diagnosis_refits_the_identified_plant_parameters(cart, native_dir, lugre_run):
    """Plain LuGre truth, the user's mass 20 % off but declared identified ([identify] m):
    the base fit re-fits it with the law (no effect is needed: verdict none) and the
    inertia candidate is skipped as already fitted."""
    from diagnosis.plant_fmu import diagnose_plant_fmu
    conn = parse_connection({**CART, "parameters": {"k_u": K_U, "m": 1.2},
                             "law": {"start": {"Fc": 1.05}}}, "rig.toml")
    rep = diagnose_plant_fmu(lugre_run, None, cart, conn, "lugre", fmu_dir=native_dir,
                             candidates=["inertia", "asymmetry"], fit_names=["Fc"],
                             max_sims=8, max_sims_base=30, greedy=False)
    assert abs(rep["base"]["params"]["plant.m"] - M_TRUE) < 0.02, rep["base"]
    assert "fitted with the base" in rep["skipped"]["inertia"]
    assert rep["verdict"]["cause"] == "none", rep.summary()


def test_diagnosis_lists_what_the_connection_cannot_express(cart, native_dir, track_runs):
    from diagnosis.plant_fmu import diagnose_plant_fmu
    fit, _ = track_runs
    raw = {**TRACK_CONN, "friction": {"input": "F_c", "sign": -1, "v": "vel"}}
    conn = parse_connection(raw, "rig.toml")
    with pytest.raises(ValueError, match=r"'position' cannot run through cart: no plant "
                                         r"output gives the position"):
        diagnose_plant_fmu(fit, None, cart, conn, "lugre", candidates=["position"],
                           fmu_dir=native_dir)
    rep = diagnose_plant_fmu(fit, None, cart, conn, "lugre", fmu_dir=native_dir,
                             max_sims=4, max_sims_base=6, fit_names=["Fc"], greedy=False)
    for c in ("position", "acceleration", "load"):
        assert "[friction]" in rep["skipped"][c], rep["skipped"]
    # the law-changing candidates need their law FMUs, which the given folder lacks
    for c, law in (("backlash", "backlash_lugre"), ("gms", "gms")):
        assert f"{law}_native.fmu is not in" in rep["skipped"][c], rep["skipped"]
        assert "build-fmus --out" in rep["skipped"][c]
    assert {e["name"] for e in rep["effects"]} >= {"asymmetry", "inertia", "delay"}


# -- the command line ----------------------------------------------------------------------------
def test_cli_identify_then_diagnose_through_the_plant_fmu(tmp_path, capsys, cart, native_dir,
                                                          track_runs, monkeypatch):
    """identify FIT --plant-fmu --connect --json (params, ci, identifiability, plant_params),
    then diagnose FIT HELDOUT --plant-fmu --connect --start ID.json --json --html."""
    fit, held = track_runs
    for rec in (fit, held):  # as a user's logger writes them: ';', volts, position in mm
        np.savetxt(tmp_path / f"{rec.name}.csv",
                   np.column_stack([rec.t, rec.columns["u"], rec.columns["x"] * 1e3]),
                   delimiter=";", header="time;volt;x_mm", comments="")
    raw = {**TRACK_CONN, "time": "time", "inputs": {"u": "volt"},
           "compare": {"pos": {"column": "x_mm", "scale": 1e-3, "unit": "m"}},
           "law": {"names": ["Fc"]}}
    (tmp_path / "rig.toml").write_text(_toml(raw))
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr("identification.cosim.fmu_dir_for",
                        lambda laws, d=None, native=False: str(native_dir))
    from frictionlab.cli import main
    assert main(["identify", "fit.csv", "--plant-fmu", str(cart), "--connect", "rig.toml",
                 "--quiet", "--algorithm", "least_squares", "--json", "id.json"]) == 0
    out = capsys.readouterr().out
    assert "Fc" in out and "NRMSE fit" in out
    d = json.loads((tmp_path / "id.json").read_text())
    assert set(d["params"]) == {"Fc"} and set(d["ci"]) == {"Fc"}
    assert {"at_bound", "unidentified", "advice"} <= set(d["identifiability"])
    assert d["plant_params"] == {} and d["connection"] == "rig.toml"
    assert main(["diagnose", "fit.csv", "held-out.csv", "--plant-fmu", str(cart),
                 "--connect", "rig.toml", "--start", "id.json", "--quiet",
                 "--candidates", "position,inertia", "--json", "gap.json",
                 "--html", "gap.html"]) == 0
    rep = json.loads((tmp_path / "gap.json").read_text())
    assert rep["verdict"]["cause"] == "position", rep
    assert rep["plant_fmu"] == "cart.fmu" and (tmp_path / "gap.html").stat().st_size > 1e4
