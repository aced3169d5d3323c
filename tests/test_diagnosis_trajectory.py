"""Trajectory-level diagnosis: candidates put into the plant's friction, the plant
re-simulated against measured positions (synthetic XML-350 measurements whose truth carries
an effect the base model lacks, in a form that differs from the candidate's formula)."""
from __future__ import annotations

import json
import math

import numpy as np
import pytest

import plants
from diagnosis import diagnose_trajectory
from diagnosis.effects import CANDIDATES, make_context
from diagnosis.trajectory import (EffectLaw, TrajectoryRecord, parse_experiment,
                                  record_from_result, simulate_record)
from friction import make_model
from friction.dataset import Dataset
from plants.sources import Sine
from plants.xml350 import XML350, xml350_friction

LUGRE_KEYS = ("sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs", "b", "shape")
#: identification configuration of the stage: linear PID, 2 kHz current loop, no feedforward
LOOP = dict(compensation=False, controller="pid")
NOISE = 3e-10  # encoder noise [m] on top of the 1 nm quantisation
SUBSET = ["asymmetry", "acceleration", "inertia", "delay", "stribeck_shape"]


def _sine(A, f):
    return Sine(A, f, offset=A, phase=-0.5 * math.pi)  # starts at rest


FIT = dict(trajectory=_sine(50e-6, 5.0), **LOOP)
VAL = dict(trajectory=_sine(100e-6, 3.0), **LOOP)


def _truth(kind):
    """Truth friction of the 'real' stage. Forms differ from the candidates' formulas: the
    asymmetry also has a direction-dependent Stribeck velocity (the candidate frees only the
    levels, viscous slope and offset), the acceleration part is seed 000's frictional lag
    (first-order state, 1 - exp shape) instead of the candidate's static tanh term."""
    p = {k: getattr(xml350_friction().params, k) for k in LUGRE_KEYS}
    if kind == "clean":
        return xml350_friction()
    if kind == "asymmetry":
        return make_model("modified_lugre", **p, f_a=0.0, Fc_neg=0.80, Fs_neg=0.95,
                          vs_neg=2e-5, sigma2_neg=12.0)
    if kind == "acceleration":
        return make_model("modified_lugre", **p, f_a=0.3, a_s=0.05, v_c=2e-3, tau=5e-3)
    raise ValueError(kind)


def _records(kind, T_fit=0.2, T_val=0.25):
    stage = XML350(_truth(kind), f_current=2000.0)
    rf = stage.simulate(T_fit, **FIT)
    rv = stage.simulate(T_val, **VAL)
    fit = record_from_result(rf, FIT, signal="x_meas", noise=NOISE, seed=1, name="fit")
    val = record_from_result(rv, VAL, signal="x_meas", noise=NOISE, seed=2, name="held-out")
    return fit, val, rv


def _model():
    # the model the user has: the paper's law with a 5 % wrong Coulomb level
    return XML350(xml350_friction(Fc=1.0), f_current=2000.0)


# -- the friction law with effects ---------------------------------------------------------------
def _motion(n=3000, dt=1e-3):
    t = np.arange(n) * dt
    v = 2e-3 * np.sin(2 * np.pi * 1.3 * t) + 5e-4 * np.sin(2 * np.pi * 4.1 * t)
    x = np.concatenate(([0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * dt)))
    a = np.gradient(v, t)
    return t, x, v, a


def test_load_effect_is_the_candidate_formula():
    t, x, v, a = _motion()
    load = 100.0 + 40.0 * np.sin(2 * np.pi * 0.3 * t)
    base = xml350_friction()
    F0 = base.simulate(t, v)
    data = Dataset(t=t, x=x, v=v, a=a, F=F0, load=load)
    ctx = make_context(data)
    law = EffectLaw(base, {"load": {"k_L": 0.7}}, ctx)
    assert law.extra_inputs == ("load",)
    expect = CANDIDATES["load"].apply(F0, {"k_L": 0.7}, data, ctx)
    assert np.allclose(law.simulate(t, v, load=load), expect, rtol=1e-12, atol=1e-14)


def test_drift_runs_on_absolute_time():
    """The time state starts at the record's absolute start: a friction level that drifts
    over the session is extrapolated to a record taken later."""
    t, x, v, a = _motion(500)
    base = xml350_friction()
    F0 = base.simulate(t, v)
    ctx = make_context(Dataset(t=t, x=x, v=v, a=a, F=F0))
    law = EffectLaw(base, {"drift": {"k_drift": 0.5}}, ctx, time0=2.0)
    expect = F0 * (1 + 0.5 * (2.0 + t - ctx.t0) / ctx.T)
    assert np.allclose(law.simulate(t, v), expect, rtol=1e-12, atol=1e-14)
    # in the plant: the same run recorded 0.5 s into the session is predicted differently
    opts = dict(distance=1e-4, compensation=False, controller="sdpid")
    stage = XML350(base, f_current=2000.0)
    r = stage.simulate(0.03, **opts)
    early = record_from_result(r, opts, t_start=0.0)
    late = record_from_result(r, opts, t_start=0.5)
    law0 = EffectLaw(base, {"drift": {"k_drift": 0.5}}, ctx)
    y0, y1 = simulate_record(stage, law0, early), simulate_record(stage, law0, late)
    assert np.sqrt(np.mean((y1 - y0) ** 2)) > 0.05 * np.std(r["x_d"] - r["x"])


@pytest.mark.parametrize("effects", [
    {"acceleration": {"f_a": 0.3, "a_s": 0.02, "v_c": 1e-3}},
    {"position": {"c_x1": 0.2, "c_x2": -0.1, "c_x3": 0.05, "c_x4": 0.1}},
    {"drift": {"k_drift": 0.4}},
    {"drift": {"k_drift": -0.3}, "acceleration": {"f_a": -0.2, "a_s": 0.05, "v_c": 5e-4}},
])
def test_effect_law_force_is_the_candidate_formula(effects):
    t, x, v, a = _motion()
    base = xml350_friction()
    F0 = base.simulate(t, v)
    data = Dataset(t=t, x=x, v=v, a=a, F=F0)
    ctx = make_context(data)
    law = EffectLaw(base, effects, ctx)
    F = law.simulate(t, v, a=a, x=x)
    expect = F0
    for stage in ("multiplicative", "additive"):  # the stage order of diagnosis.composite
        for name, p in effects.items():
            if CANDIDATES[name].stage == stage:
                expect = CANDIDATES[name].apply(expect, p, data, ctx)
    assert np.max(np.abs(F - expect)) <= 1e-12 * np.max(np.abs(expect)) + 1e-14
    assert np.max(np.abs(F - F0)) > 1e-3  # the effect is really there
    # the scalar force of the reference integrator agrees with the kernel
    F2, S = law.simulate(t, v, a=a, x=x, return_state=True)
    k = 1234
    assert law.force(S[k], v[k], a=a[k], x=x[k]) == pytest.approx(F2[k], rel=1e-9, abs=1e-12)
    assert S[k, -1] == pytest.approx(t[k])  # the time state


def test_neutral_effect_law_reproduces_the_plant():
    """Effects at zero: the plant with EffectLaw (generic stepper) equals the plant with the
    plain law (compiled XML-350 kernel) - the wrapper adds nothing but the effect."""
    base = xml350_friction()
    t, x, v, a = _motion(300)
    ctx = make_context(Dataset(t=t, x=x, v=v, a=a, F=base.simulate(t, v)))
    law = EffectLaw(base, {"acceleration": {"f_a": 0.0, "a_s": 0.05, "v_c": 1e-3},
                           "drift": {"k_drift": 0.0}}, ctx)
    opts = dict(trajectory=_sine(20e-6, 10.0), **LOOP)
    ref = XML350(base, f_current=2000.0).simulate(0.05, **opts)
    got = XML350(law, f_current=2000.0).simulate(0.05, **opts)
    e = ref["x_d"] - ref["x"]
    assert np.sqrt(np.mean((got["x"] - ref["x"]) ** 2)) <= 1e-9 * np.std(e) + 1e-18
    # and a non-zero effect changes the closed-loop trajectory
    law2 = EffectLaw(base, {"acceleration": {"f_a": 0.5, "a_s": 0.05, "v_c": 1e-3}}, ctx)
    got2 = XML350(law2, f_current=2000.0).simulate(0.05, **opts)
    assert np.sqrt(np.mean((got2["x"] - ref["x"]) ** 2)) > 0.05 * np.std(e)


def test_bad_records_are_refused_with_a_clear_message():
    t = np.arange(100) * 1e-4
    y = np.zeros(100)
    with pytest.raises(ValueError, match=r"y\[7\] = nan is not finite"):
        TrajectoryRecord(t, np.where(np.arange(100) == 7, np.nan, y))
    with pytest.raises(ValueError, match="strictly increasing"):
        TrajectoryRecord(t[::-1], y)
    with pytest.raises(ValueError, match="y has 99"):
        TrajectoryRecord(t, y[:99])
    with pytest.raises(ValueError, match="in m"):
        TrajectoryRecord(t, y + 100.0)  # mm given as m
    fit, _, _ = _records("clean", 0.02, 0.02)
    with pytest.raises(ValueError, match="unknown candidate"):
        diagnose_trajectory(fit, _model(), candidates=["gremlins"])
    with pytest.raises(ValueError, match="engine"):
        diagnose_trajectory(fit, _model(), engine="quantum")
    with pytest.raises(ValueError, match="sine:AMPLITUDE"):
        parse_experiment("trajectory=sine:1e-4")


# -- the diagnosis ------------------------------------------------------------------------------
def _truth_closed(kind, val, rv, before):
    """Fraction of the held-out gap the truth model itself closes (noise stays)."""
    sd = np.std(rv["x_d"] - val.y)
    after = np.sqrt(np.mean((val.y - rv["x"]) ** 2)) / sd
    return (before - after) / before


def test_asymmetry_is_named_and_the_gap_closed_matches_the_truth():
    fit, val, rv = _records("asymmetry")
    rep = diagnose_trajectory(fit, _model(), "lugre", validation=val, candidates=SUBSET)
    assert rep["level"] == "trajectory" and rep["plant"] == "xml350"
    assert rep["verdict"]["cause"] == "asymmetry", rep.summary()
    top = rep["effects"][0]
    assert top["name"] == "asymmetry"
    assert top["excess_closed"] >= 0.7, rep.summary()
    truth = _truth_closed("asymmetry", val, rv, rep["baseline"]["validation"])
    assert abs(top["gap_closed"] - truth) <= 0.15, (top, truth)
    # the fitted twins point the right way: lower levels for v < 0 (truth 0.80 vs 0.95)
    p = rep["effect_details"]["asymmetry"]["params"]
    assert p["Fc_neg"] < p["Fc"]
    # contract shape
    doc = json.loads(rep.to_json())
    assert set(doc) >= {"baseline", "where", "effects", "verdict", "level"}
    assert doc["baseline"]["metric"] == "nrmse"
    shares = [w["share"] for w in doc["where"]]
    assert shares == sorted(shares, reverse=True) and abs(sum(shares) - 1) < 1e-9
    gaps = [e["gap_closed"] for e in doc["effects"][1:]]
    assert gaps == sorted(gaps, reverse=True)
    for e in doc["effects"]:
        assert e["gap_closed"] == pytest.approx(
            (e["validation_before"] - e["validation_after"]) / e["validation_before"])
    assert rep["timing"]["simulations"] > 0


def test_clean_truth_gives_none():
    fit, val, _ = _records("clean")
    stage = XML350(_truth("clean"), f_current=2000.0)
    opts = dict(trajectory=_sine(30e-6, 8.0), **LOOP)
    val2 = record_from_result(stage.simulate(0.15, **opts), opts, signal="x_meas",
                              noise=NOISE, seed=4, name="held-out 2")
    rep = diagnose_trajectory(fit, _model(), "lugre", validation=[val, val2],
                              candidates=["asymmetry", "inertia", "delay"])
    assert rep["timing"]["validation_samples"] == val.t.size + val2.t.size
    assert rep["verdict"]["cause"] == "none", rep.summary()
    # the wrong Coulomb level of the start model was fitted away on the trajectory
    assert rep["base"]["params"]["Fc"] == pytest.approx(0.95, rel=0.03)


@pytest.mark.slow
def test_acceleration_is_named_with_every_candidate():
    fit, val, rv = _records("acceleration", 0.2, 0.34)
    rep = diagnose_trajectory(fit, _model(), "lugre", validation=val)
    assert rep["verdict"]["cause"] == "acceleration", rep.summary()
    assert rep["effects"][0]["excess_closed"] >= 0.7
    truth = _truth_closed("acceleration", val, rv, rep["baseline"]["validation"])
    assert abs(rep["effects"][0]["gap_closed"] - truth) <= 0.15
    assert set(rep["skipped"]) == {"load", "presliding"}  # no load; LuGre has bristles


@pytest.mark.slow
def test_asymmetry_is_named_with_every_candidate():
    fit, val, _ = _records("asymmetry", 0.2, 0.34)
    rep = diagnose_trajectory(fit, _model(), "lugre", validation=val)
    assert rep["verdict"]["cause"] == "asymmetry", rep.summary()


# -- engines ------------------------------------------------------------------------------------
def test_fmu_engine_agrees_with_the_in_process_plant():
    """Same equations: the plant FMU + friction FMU loop reproduces the in-process plant for
    a candidate expressed as friction-FMU parameters (direction twins and offset), far
    closer than the candidate's own effect on the trajectory."""
    opts = dict(distance=1e-4, compensation=False, controller="sdpid")
    stage = XML350(xml350_friction(), f_current=2000.0)
    rec = record_from_result(stage.simulate(0.03, **opts), opts, name="scurve")
    cand = xml350_friction(Fc_neg=0.8, Fs_neg=0.9, b=0.05)
    y_plant = simulate_record(stage, cand, rec)
    y_fmu = simulate_record(stage, cand, rec, engine="fmu")
    sd = np.std(stage.simulate(0.03, **opts)["x_d"] - rec.y)
    engines = np.sqrt(np.mean((y_fmu - y_plant) ** 2)) / sd
    effect = np.sqrt(np.mean((y_plant - rec.y) ** 2)) / sd
    assert effect > 0.03
    assert engines < 0.2 * effect, (engines, effect)


def test_fmu_engine_runs_the_force_effects_in_the_effects_block():
    """acceleration, position and drift (EffectLaw) through the friction_effects FMU block
    between the law FMU and the plant FMU: the loop reproduces the in-process plant with the
    same EffectLaw far closer than the effects' own imprint on the trajectory."""
    opts = dict(distance=1e-4, compensation=False, controller="sdpid")
    stage = XML350(xml350_friction(), f_current=2000.0)
    rec = record_from_result(stage.simulate(0.03, **opts), opts, name="scurve")
    t, x, v, a = _motion(100)
    ctx = make_context(Dataset(t=t, x=x * 1e-3, v=v * 1e-3, a=a, F=np.ones_like(t)))
    law = EffectLaw(xml350_friction(), {"acceleration": {"f_a": 0.3, "a_s": 0.05, "v_c": 1e-3},
                                        "drift": {"k_drift": 2.0},
                                        "position": {"c_x1": 0.3, "c_x2": 0.2}}, ctx)
    y_plant = simulate_record(stage, law, rec)
    y_fmu = simulate_record(stage, law, rec, engine="fmu")
    y_base = simulate_record(stage, xml350_friction(), rec)
    sd = np.std(stage.simulate(0.03, **opts)["x_d"] - rec.y)
    engines = np.sqrt(np.mean((y_fmu - y_plant) ** 2)) / sd
    effect = np.sqrt(np.mean((y_plant - y_base) ** 2)) / sd
    assert effect > 0.03
    assert engines < 0.2 * effect, (engines, effect)


# -- command line -------------------------------------------------------------------------------
def test_cli_trajectory_level(tmp_path):
    from frictionlab.cli import main
    fit, val, _ = _records("asymmetry", 0.2, 0.25)
    paths = []
    for rec in (fit, val):
        p = tmp_path / f"{rec.name}.csv"
        np.savetxt(p, np.column_stack([rec.t, rec.y * 1e6]), delimiter=",", header="t,x_um",
                   comments="")
        paths.append(str(p))
    out = tmp_path / "rep.json"
    html = tmp_path / "rep.html"
    rc = main(["diagnose", *paths, "--model", "lugre", "--plant", "xml350", "--quiet",
               "--map", "x=x_um", "--scale", "x=1e-6",
               "--experiment", "trajectory=sine:5e-5:5,controller=pid,compensation=false,"
                               "f_current=2000",
               "--experiment", "trajectory=sine:1e-4:3,controller=pid,compensation=false,"
                               "f_current=2000",
               "--candidates", "asymmetry,inertia", "--json", str(out), "--html", str(html)])
    assert rc == 0
    doc = json.loads(out.read_text())
    assert doc["level"] == "trajectory" and doc["verdict"]["cause"] == "asymmetry"
    assert html.read_text().count("data:image/png;base64") == 3
    # bad input: one line, non-zero exit
    assert main(["diagnose", paths[0], "--model", "lugre", "--plant", "xml350", "--quiet",
                 "--map", "x=x_um", "--experiment", "warp=9"]) == 2


# -- the paper's S-curve moves (SD-PID, 400 Hz current loop, LuGre feedforward) -------------------
def _scurve_records():
    """The real stage is 1 kg heavier than the model (a mass error, seen in the tracking
    error of the compensated 100 um / 200 um moves)."""
    fo, vo = dict(distance=1e-4, compensation=True), dict(distance=2e-4, compensation=True)
    truth = XML350(xml350_friction(), M=12.8)
    fit = record_from_result(truth.simulate(0.04, **fo), fo, signal="x_meas", noise=1e-10,
                             seed=1, name="100um")
    val = record_from_result(truth.simulate(0.05, **vo), vo, signal="x_meas", noise=1e-10,
                             seed=2, name="200um")
    return fit, val


SCURVE_CANDIDATES = ["inertia", "asymmetry", "delay", "stribeck_shape"]


def test_mass_error_is_named_on_the_compensated_scurve_moves():
    fit, val = _scurve_records()
    rep = diagnose_trajectory(fit, XML350(xml350_friction()), "lugre", validation=val,
                              candidates=SCURVE_CANDIDATES)
    assert rep["verdict"]["cause"] == "inertia", rep.summary()
    assert rep["effects"][0]["gap_closed"] > 0.9
    assert rep["effect_details"]["inertia"]["plant_params"]["M"] == pytest.approx(12.8, rel=0.02)


@pytest.mark.slow
def test_fmu_engine_diagnosis_matches_the_plant_engine():
    """The whole diagnosis through plant FMU + friction FMU (the candidate as FMU
    parameters: the plant FMU's mass, the law FMU's twins and shape)."""
    fit, val = _scurve_records()
    reps = {eng: diagnose_trajectory(fit, XML350(xml350_friction()), "lugre", validation=val,
                                     candidates=SCURVE_CANDIDATES, engine=eng)
            for eng in ("plant", "fmu")}
    assert reps["fmu"]["engine"] == "fmu"
    assert reps["fmu"]["verdict"]["cause"] == reps["plant"]["verdict"]["cause"] == "inertia"
    assert reps["fmu"]["verdict"]["gap_closed"] == pytest.approx(
        reps["plant"]["verdict"]["gap_closed"], abs=0.05)
    assert reps["fmu"]["baseline"]["validation"] == pytest.approx(
        reps["plant"]["baseline"]["validation"], rel=0.05)


# -- the valve (seed 000): lift tracking with a frictional lag the classic LuGre lacks -------------
@pytest.mark.slow
def test_valve_frictional_lag_is_named():
    from plants.valve import ValveActuator, classic_lugre_twin, valve_friction
    truth_law = valve_friction(v1=0.3, v2=0.5)  # seed 000 law, switch band above the speeds
    truth = ValveActuator(truth_law)
    fo, vo = dict(freq=10.0, magnitude=4e-3), dict(freq=7.0, magnitude=6e-3)
    fit = record_from_result(truth.simulate(0.1, **fo), fo, signal="S_meas", noise=2e-8,
                             seed=1, name="10Hz")
    val = record_from_result(truth.simulate(0.143, **vo), vo, signal="S_meas", noise=2e-8,
                             seed=2, name="7Hz")
    model = ValveActuator(classic_lugre_twin(truth_law))  # same levels and twins, no F_d
    rep = diagnose_trajectory(fit, model, "lugre", validation=val,
                              candidates=["acceleration", "inertia", "asymmetry", "delay"])
    assert rep["plant"] == "valve"
    assert rep["verdict"]["cause"] == "acceleration", rep.summary()
    assert rep["effects"][0]["excess_closed"] >= 0.7


def test_chronological_hold_out_of_one_record():
    """No validation record: fitted on the first 70 %, scored on the rest, which the model
    predicts by running through the whole record."""
    stage = XML350(_truth("asymmetry"), f_current=2000.0)
    rec = record_from_result(stage.simulate(0.34, **VAL), VAL, signal="x_meas", noise=NOISE,
                             seed=3, name="one record")
    rep = diagnose_trajectory(rec, _model(), "lugre",
                              candidates=["asymmetry", "inertia", "delay"])
    assert rep["timing"]["fit_samples"] + rep["timing"]["validation_samples"] == rec.t.size
    assert rep["verdict"]["cause"] == "asymmetry", rep.summary()


def test_force_output_plants_are_sent_to_the_force_level():
    rig = plants.make_plant("damping_rig")
    t = np.arange(200) * 1e-3
    with pytest.raises(ValueError, match="friction-force"):
        diagnose_trajectory(TrajectoryRecord(t, np.zeros_like(t)), rig)


def test_static_map_base_gets_its_missing_bristles_back():
    """A static Stribeck map in the closed loop: ``presliding`` (LuGre bristles) is named and
    the re-identified bristle stiffness is the stage's (11.02e6 N/m, seed 003 Table I)."""
    fit, val = _scurve_records()
    model = XML350(xml350_friction(), M=12.8)  # the mass is right this time
    rep = diagnose_trajectory(fit, model, "stribeck", validation=val,
                              candidates=["presliding", "inertia"])
    assert rep["verdict"]["cause"] == "presliding", rep.summary()
    assert rep["effects"][0]["gap_closed"] > 0.8
    p = rep["effect_details"]["presliding"]["params"]
    assert p["sigma0"] == pytest.approx(11.02e6, rel=0.2)


# -- a gap outside the library: the stage's current loop is slower than the model's ---------------
@pytest.mark.parametrize("candidates", [
    ["asymmetry", "inertia", "delay", "stribeck_shape"],
    pytest.param(None, marks=pytest.mark.slow),
])
def test_actuator_lag_outside_the_library_is_unexplained(candidates):
    """The real current loop has 1 kHz bandwidth, the model 2 kHz: a structured gap that no
    friction candidate (nor mass, nor a channel delay) closes -> ``unexplained``."""
    truth = XML350(xml350_friction(), f_current=1000.0)
    fit = record_from_result(truth.simulate(0.2, **FIT), FIT, signal="x_meas", noise=NOISE,
                             seed=1)
    val = record_from_result(truth.simulate(0.25, **VAL), VAL, signal="x_meas", noise=NOISE,
                             seed=2)
    rep = diagnose_trajectory(fit, _model(), validation=val, candidates=candidates)
    assert rep["baseline"]["validation"] > 1.5 * rep["noise_floor"]  # a real gap
    assert rep["verdict"]["cause"] == "unexplained", rep.summary()


@pytest.mark.slow
def test_fmu_engine_carries_the_load_effect_on_the_press():
    """The load effect through the friction_effects block, fed by the press FMU's load
    output: the same trajectory as the in-process press with the same EffectLaw."""
    from diagnosis.effects import Context
    from plants.forging_press import ForgingPress
    press = ForgingPress()
    res = press.simulate(2.0)
    rec = record_from_result(res, {}, name="press 2 s")
    L0 = float(np.mean(res["load"]))
    ctx = Context(sF=1e5, sv=1e-3, sa=1e-3, x_lo=0.0, x_hi=1.0, t0=0.0, T=2.0, dt=0.01,
                  L0=L0, L_span=1.0, L_hi=L0)
    law = EffectLaw(press.friction, {"load": {"k_L": 0.5}}, ctx)
    y_plant = simulate_record(press, law, rec)
    y_fmu = simulate_record(press, law, rec, engine="fmu")
    effect = np.sqrt(np.mean((y_plant - simulate_record(press, press.friction, rec)) ** 2))
    assert effect > 0
    assert np.sqrt(np.mean((y_fmu - y_plant) ** 2)) < 1e-3 * effect


@pytest.mark.slow
def test_press_load_dependence_is_named_from_positions():
    """Forging press (seed 004): the real press's friction depends on the deformation load
    (load-dependent LuGre, Table 3), the model has the classic LuGre at the no-load levels.
    From the beam positions of a 1.2 -> 0.1 mm/s schedule, held out on 0.6 -> 0.05 mm/s, the
    load effect (an affine level factor, not seed 004's per-parameter form) is named."""
    from fmus.plant_fmus import classic_lugre_for
    from plants.forging_press import ForgingPress
    fo = dict(schedule=((1.2e-3, 3.0), (0.1e-3, 3.0)))
    vo = dict(schedule=((0.6e-3, 3.0), (0.05e-3, 3.0)))
    truth = ForgingPress()
    fit = record_from_result(truth.with_options(**fo).simulate(6.0), fo, signal="x",
                             noise=1e-7, seed=1, name="1.2 -> 0.1 mm/s")
    val = record_from_result(truth.with_options(**vo).simulate(6.0), vo, signal="x",
                             noise=1e-7, seed=2, name="0.6 -> 0.05 mm/s")
    model = ForgingPress(classic_lugre_for(ForgingPress))
    rep = diagnose_trajectory(fit, model, "lugre", validation=val,
                              candidates=["load", "asymmetry", "inertia"])
    assert rep["verdict"]["cause"] == "load", rep.summary()
    assert rep["effects"][0]["gap_closed"] > 0.5


@pytest.mark.parametrize("effects, kw, name", [
    ({"acceleration": {"f_a": 0.1, "a_s": 0.0, "v_c": 1e-3}}, {}, "a_s"),
    ({"acceleration": {"f_a": 0.1, "a_s": 0.1, "v_c": -1.0}}, {}, "v_c"),
    ({"drift": {"k_drift": 0.1}}, {"T": 0.0}, "T"),
    ({"position": {"c_x1": 0.1}}, {"x_lo": 0.2, "x_hi": 0.1}, "x_hi"),
    ({"load": {"k_L": 0.1}}, {"L0": -5.0}, "L0"),
])
def test_extensions_refuse_impossible_parameters_naming_them(effects, kw, name):
    from friction.extensions import pack_extensions
    with pytest.raises(ValueError, match=name):
        pack_extensions(effects, **kw)
