"""FMUs of the friction laws: build, validation, model description, behaviour, bad input."""
from __future__ import annotations

import math

import fmpy
import numpy as np
import pytest

import friction
from friction.metrics import nrmse
from fmus.build import catalogue, validate
from fmus.coupling import fmi_unit
from fmus.modeldescription import base_unit
from fmus.variables import exclusive_min
from fmus.testing import LoggedSlave, built_fmus


@pytest.fixture(scope="session")
def fmu_dir():
    # laws and mass only: the plant FMUs are built by the slow tests
    return built_fmus(tuple(sorted(friction.MODELS)) + ("mass",))


def _md(fmu_dir, name):
    return fmpy.read_model_description(str(fmu_dir / f"{name}.fmu"))


def test_catalogue_covers_every_law_and_the_mass(fmu_dir):
    cat = catalogue()
    assert set(friction.MODELS) <= set(cat)
    assert "mass" in cat
    for name in list(friction.MODELS) + ["mass"]:
        assert (fmu_dir / f"{name}.fmu").is_file()


def test_every_fmu_validates_with_zero_problems(fmu_dir):
    for name in list(friction.MODELS) + ["mass"]:
        assert validate(fmu_dir / f"{name}.fmu") == [], name


def test_every_fmu_has_a_default_experiment(fmu_dir):
    for name in list(friction.MODELS) + ["mass"]:
        de = _md(fmu_dir, name).defaultExperiment
        assert de is not None and float(de.stepSize) > 0 and float(de.stopTime) > 0, name


def test_base_units():
    assert base_unit("N/m") == {"kg": 1, "s": -2}
    assert base_unit("N.s/m") == {"kg": 1, "s": -1}
    assert base_unit("m/s2") == {"m": 1, "s": -2}
    assert base_unit("m^3/s") == {"m": 3, "s": -1}
    assert base_unit("1") == {}
    assert base_unit("furlong") is None


def test_law_fmu_parameters_carry_unit_description_bounds(fmu_dir):
    for name, cls in friction.MODELS.items():
        md = _md(fmu_dir, name)
        units = {u.name for u in md.unitDefinitions}
        vars_ = {v.name: v for v in md.modelVariables}
        for info in cls.Params.info():
            v = vars_[info.name]
            assert v.causality == "parameter" and v.variability == "tunable", info.name
            assert v.unit == fmi_unit(info.unit) and v.unit in units, (name, info.name)
            assert info.description.split(" (")[0] in v.description, (name, info.name)
            if math.isfinite(info.lower):  # an exclusive bound: the next double inside it
                want = exclusive_min(info.lower) if info.lower_open else info.lower
                assert float(v.min) == want, (name, info.name)
            if info.default is None:  # optional: a Boolean flag, no sentinel
                flag = vars_[f"use_{info.name}"]
                assert flag.type == "Boolean" and flag.start in ("false", False)
        # options are Enumerations (no Strings in any law FMU)
        assert not [v for v in md.modelVariables if v.type == "String"], name
        for opt, codes in getattr(cls.Params, "OPTIONS", {}).items():
            assert vars_[opt].type == "Enumeration"
            items = [i.name for t in md.typeDefinitions if t.name == vars_[opt].declaredType.name
                     for i in t.items]
            assert items == sorted(codes, key=codes.get), (name, opt)
        assert vars_["F"].unit == "N" and vars_["v"].unit == "m/s"


def test_model_structure_lists_true_dependencies(fmu_dir):
    from fmus.runtime import COUPLING_OUTPUTS
    def deps(name):
        md = _md(fmu_dir, name)
        out = {u.variable.name: sorted(d.name for d in u.dependencies) for u in md.outputs}
        init = {u.variable.name for u in md.initialUnknowns}
        return out, init
    out, init = deps("lugre")
    # the law's linearisation over a step for the plant coupling (fmus.runtime)
    coupling = {n: ["v"] for n in COUPLING_OUTPUTS}
    assert out == {"F": ["v"], "z": [], **coupling}
    assert init == {"F", "z", *coupling}
    # tau > 0: F_d is a state, so F does not depend on the acceleration input (no false loop)
    assert deps("modified_lugre")[0]["F"] == ["v"]
    assert deps("load_lugre")[0]["F"] == ["load", "v"]
    assert deps("mre_lugre")[0]["F"] == ["v", "x"]
    assert deps("mass")[0] == {"x": [], "v": [], "a": ["F_ext", "F_friction"]}


def _drive(law, t):
    """Smooth prescribed motion (and load) for one law."""
    v = 2e-3 * np.sin(2 * np.pi * 10 * t) + 5e-4
    if law == "mre_lugre":
        v = 0.05 * np.sin(2 * np.pi * 4 * t)
    extra = {"a": np.gradient(v, t), "x": np.concatenate(([0.0], np.cumsum(
        0.5 * (v[1:] + v[:-1]) * np.diff(t)))), "load": 1e3 * (1 + np.sin(2 * np.pi * 3 * t))}
    return v, extra


def _fmu_run(path, law, h, T, start=None):
    cls = friction.MODELS[law]
    names = ["v"] + [n for n in ("a", "load", "x") if n in cls.extra_inputs]
    t = h * np.arange(int(round(T / h)) + 1)
    v, extra = _drive(law, t)
    sig = {"v": v, **extra}
    s = LoggedSlave(path, law)
    try:
        s.init(**(start or {}))
        F = np.empty(t.size)
        for k in range(t.size):
            s.s.setReal([s.vr[n] for n in names], [float(sig[n][k]) for n in names])
            F[k] = s.s.getReal([s.vr["F"]])[0]
            if k + 1 < t.size:
                s.s.doStep(t[k], h)
    finally:
        s.close()
    kw = {n: sig[n] for n in names if n != "v"}
    return t, F, friction.make_model(law).simulate(t, v, **kw)


@pytest.mark.parametrize("law", [pytest.param(law, marks=() if law in ("lugre", "stribeck")
                                              else pytest.mark.slow)
                                 for law in sorted(friction.MODELS)])
def test_law_fmu_reproduces_the_law_first_order_in_step(fmu_dir, law):
    # the FMU holds its inputs over a step (ZOH), the law's simulate() interpolates them:
    # the two agree to O(h)
    errs = []
    for h in (2e-4, 1e-4):
        t, F_fmu, F_law = _fmu_run(fmu_dir / f"{law}.fmu", law, h, 0.1)
        errs.append(nrmse(F_law, F_fmu))
    if not friction.MODELS[law].state_names:  # a static map: no hold error at all
        assert max(errs) < 1e-12, errs
        return
    assert errs[1] < 2e-2, errs
    assert errs[0] / errs[1] > 1.6, errs  # first order (ratio 2)


@pytest.mark.slow
def test_load_input_changes_the_force(fmu_dir):
    # constant inputs: the hold is exact, so the FMU equals the law's own simulate()
    law = "load_lugre"
    model = friction.make_model(law)
    t = 1e-4 * np.arange(1001)
    out, expect = [], []
    for load in (0.0, 2e4):
        s = LoggedSlave(fmu_dir / f"{law}.fmu")
        try:
            s.init(load=load)
            s.s.setReal([s.vr["v"]], [1e-2])
            for k in range(t.size - 1):
                s.s.doStep(t[k], 1e-4)
            out.append(s.s.getReal([s.vr["F"]])[0])
        finally:
            s.close()
        expect.append(model.simulate(t, np.full(t.size, 1e-2), load=np.full(t.size, load))[-1])
    np.testing.assert_allclose(out, expect, rtol=1e-9)
    assert out[1] > 10 * out[0]  # Fc, Fs, sigma2 grow with the load (seed 004 Eqs. 9-11)


# bad input (fmi2Error naming the variable and its bound): tests/test_fmu_status.py


def test_optional_twin_parameter_makes_the_law_asymmetric(fmu_dir):
    # use_Fc_neg = false means "same as Fc"; Fc_neg set with its flag changes only the
    # negative branch
    res = {}
    for fc_neg in (-1.0, 2.0):
        s = LoggedSlave(fmu_dir / "lugre.fmu")
        try:
            s.init(**({} if fc_neg < 0 else {"use_Fc_neg": True, "Fc_neg": fc_neg}))
            vals = []
            for v in (0.05, -0.05):
                s.s.setReal([s.vr["v"]], [v])
                for k in range(300):
                    s.s.doStep(k * 1e-4, 1e-4)
                vals.append(s.s.getReal([s.vr["F"]])[0])
            res[fc_neg] = vals
        finally:
            s.close()
    m0 = friction.make_model("lugre")
    m1 = friction.make_model("lugre", Fc_neg=2.0)
    np.testing.assert_allclose(res[-1.0], m0.steady_state(np.array([0.05, -0.05])), rtol=1e-6)
    np.testing.assert_allclose(res[2.0], m1.steady_state(np.array([0.05, -0.05])), rtol=1e-6)


@pytest.mark.slow
def test_all_fmus_load_together_in_one_process(fmu_dir):
    from fmus.master import Master
    laws = sorted(friction.MODELS)
    fmus = {"mass": fmu_dir / "mass.fmu", **{law: fmu_dir / f"{law}.fmu" for law in laws}}
    conns = [("mass.v", f"{law}.v") for law in laws] + [("lugre.F", "mass.F_friction")]
    for law in laws:
        cls = friction.MODELS[law]
        if "a" in cls.extra_inputs:
            conns.append(("mass.a", f"{law}.a"))
        if "x" in cls.extra_inputs:
            conns.append(("mass.x", f"{law}.x"))
    with Master(fmus, conns) as m:
        res = m.simulate(stop_time=0.05, step_size=1e-4)
    for law in laws:
        F = res[f"{law}.F"]
        assert np.all(np.isfinite(F)) and np.ptp(F) > 0, law
    # the lugre instance is the one in the loop: compare with a lone mass+lugre run
    from fmus.proof import mass_cosim
    ref = mass_cosim(fmu_dir, "lugre", step=1e-4, stop=0.05,
                     scenario=dict(m=1.0, u0=0.0, u_amp=2.0, u_freq=1.0, v0=0.0, stop=0.05))
    np.testing.assert_allclose(res["mass.x"], ref["mass.x"], rtol=1e-12, atol=1e-15)


def test_cli_build_fmus(tmp_path, capsys):
    from frictionlab.cli import main
    assert main(["build-fmus", "--out", str(tmp_path), "--only", "stribeck"]) == 0
    assert validate(tmp_path / "stribeck.fmu") == []
    assert validate(tmp_path / "stribeck_native.fmu") == []  # both kinds
    err = capsys.readouterr().err
    assert "[build-fmus]" in err and "1/2" in err and "2/2" in err  # a tqdm line per FMU
    assert "stribeck_native.fmu (native, valid)" in err and ("s/fmu" in err or "fmu/s" in err)
    assert main(["build-fmus", "--out", str(tmp_path), "--only", "nonsense"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "unknown FMU name" in err[0] and "nonsense" in err[0]


def test_friction_effects_block_is_the_extension_formula():
    """The friction_effects block (law force in, force with the diagnosis' extensions out)
    validates, and under fmpy's input tables gives friction.extensions.extension_force of
    the inputs held over each step, at the step's end time, to rounding."""
    from friction.extensions import extension_force, pack_extensions
    path = built_fmus(("friction_effects",)) / "friction_effects.fmu"
    assert validate(path) == []
    effects = {"acceleration": dict(f_a=0.3, a_s=0.5, v_c=0.01), "load": dict(k_L=0.4),
               "drift": dict(k_drift=0.5), "position": dict(c_x1=0.2, c_x2=-0.1)}
    e = pack_extensions(effects, L0=100.0, t0=0.0, T=1.0, x_lo=-1.0, x_hi=1.0)
    start = {"use_acc": 1.0, "f_a": 0.3, "a_s": 0.5, "v_c": 0.01, "use_load": 1.0,
             "L0": 100.0, "k_L": 0.4, "use_drift": 1.0, "k_drift": 0.5, "t0": 0.0, "T": 1.0,
             "use_pos": 1.0, "x_lo": -1.0, "x_hi": 1.0, "c_x1": 0.2, "c_x2": -0.1}
    sig = {"F_law": lambda t: np.sin(3 * t), "v": lambda t: 0.01 * np.cos(2 * t),
           "a": lambda t: np.sin(5 * t), "x": lambda t: 0.5 * np.sin(t),
           "load": lambda t: 100 + 50 * t}
    t = np.linspace(0.0, 1.0, 101)
    inp = np.zeros(t.size, dtype=[("time", float)] + [(k, float) for k in sig])
    inp["time"] = t
    for k, g in sig.items():
        inp[k] = g(t)
    res = fmpy.simulate_fmu(str(path), stop_time=1.0, output_interval=0.01, input=inp,
                            start_values=start, output=["F"])
    tt = res["time"][1:]
    ref = [extension_force(*(g(ti - 0.01) for g in sig.values()), ti, e) for ti in tt]
    assert np.max(np.abs(res["F"][1:] - ref)) < 1e-12
    # a variable's bound is named when violated (fmi2Error behind the status shim)
    s = LoggedSlave(path)
    try:
        s.init()
        assert s.set("a_s", -1.0) != 0
        assert any("a_s" in m for m in s.errors())
        assert s.set("v", math.nan) != 0
        assert s.step(0.0, 0.01) == 0 and math.isfinite(s.get("F"))
    finally:
        s.close()
