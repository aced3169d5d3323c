"""EMPS as the worked real case (issue 14, section 2): the benchmark's axis and controller
simulated in closed loop (reference in, motor force out) and open loop (measured motor force
in, position out) on the real records of ``../shared/data/real/emps/``.

Tolerances of the baseline reproduction (the data README's figures of the published
IDIM-LS model in the benchmark's loop): the README does not say how its loop was
integrated. Its pulse-set force error (11.9 %) and its open-loop figures (6.75 / 9.22 mm,
from rest) are reproduced closely; its estimation-set force error (7.4 %) is not reached by
any converged integration of the loop it describes (Heun, semi-implicit Euler or RK4 at 1-50
substeps per sample give 8.5-9.3 %; only an unconverged 2-substep Euler gives 7.3 %), so
that figure gets a wider band. Measured here: 11.82 %, 8.55 %, 6.53 mm, 9.09 mm.
"""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from friction import make_model
from plants.base import Experiment, Plant
from plants.emps import EMPS, EMPSAxis, EMPSParams, force_error, position_metrics
from plants.studies import emps as studies


def _records():
    try:
        return studies.load_record("estimation"), studies.load_record("pulses")
    except FileNotFoundError as exc:  # the shared data folder is not mounted
        pytest.skip(str(exc))


@pytest.fixture(scope="module")
def records():
    return _records()


def test_controller_and_pulse_established_from_the_data(records):
    E, P = records
    for rec in (E, P):
        ev = studies.controller_evidence(rec)
        # the recorded voltage obeys the law with the sampled position in the error ...
        assert ev["sample"]["residual_rms_V"] < 0.06
        assert ev["sample"]["fit"]["residual_rms_V"] < 0.01
        assert abs(ev["sample"]["fit"]["kpkv_factor"] - 1) < 1e-3
        assert abs(ev["sample"]["fit"]["kv_factor"] - 1) < 1e-3
        # ... not with the two-sample average the data README writes
        assert ev["average"]["residual_rms_V"] > 1.0
    pe = studies.pulse_evidence(P, E)
    assert pe["edges"] == 49
    # a voltage at the controller output, about 1.016 V per unit, in the sample of the edge
    assert 1.0 < pe["jump_V_per_unit"]["mean"] < 1.03
    assert pe["jump_V_per_unit"]["std"] < 0.01
    acc = pe["accel_after_rise"]
    assert abs(acc["measured_m_s2"] / acc["if_volts_m_s2"] - 1) < 0.2
    assert acc["measured_m_s2"] > 10 * acc["if_newtons_m_s2"]
    for d in pe["friction_on_off_N"].values():   # recorded inside vir
        assert abs(d["on"] - d["off"]) < 1.0
    assert abs(studies.PULSE_GAIN - pe["jump_V_per_unit"]["mean"]) < 0.005


def test_baseline_reproduces_the_readme_figures(records):
    E, P = records
    base = studies.baseline_model("benchmark")
    readme = studies.README_FIGURES
    got = {rec.name: studies.scores(base, rec) for rec in (E, P)}
    cl_e = got[E.name]["closed_loop"]["force_error"]
    cl_p = got[P.name]["closed_loop"]["force_error"]
    assert abs(cl_p - readme["closed_loop_force_error"]["pulses"]) < 0.005
    assert abs(cl_e - readme["closed_loop_force_error"]["estimation"]) < 0.015
    for rec in (E, P):   # the README's 0.03 % position error
        assert 2e-4 < got[rec.name]["closed_loop"]["position_error"] < 4e-4
    for rec, key in ((E, "estimation"), (P, "pulses")):
        ol = got[rec.name]["open_loop_from_rest"]
        assert abs(ol["rmse_mm"] - readme["open_loop_rmse_mm"][key]) < 0.3
        assert abs(ol["r2"] - readme["open_loop_r2"][key]) < 0.002


def test_ours_beats_the_baseline_on_the_pulse_set(records):
    _, P = records
    base = studies.scores(studies.baseline_model("benchmark"), P)
    base_measured = studies.scores(studies.baseline_model("measured"), P)
    ours = studies.scores(studies.stored_model("lugre"), P)
    asym = studies.scores(studies.stored_model("lugre+asymmetry"), P)
    cl = ours["closed_loop"]["force_error"]
    assert cl <= 0.06                                     # the goal
    assert cl < 0.5 * base["closed_loop"]["force_error"]
    assert cl < 0.5 * base_measured["closed_loop"]["force_error"]   # not the loop alone
    assert asym["closed_loop"]["force_error"] < cl        # the diagnosed asymmetry helps
    for key in ("open_loop", "open_loop_from_rest"):
        assert ours[key]["rmse_mm"] < 0.7 * base[key]["rmse_mm"]


@pytest.mark.parametrize("delay", [0.0, 0.4e-3, 1e-3])
def test_kernel_equals_the_generic_stepper(records, delay):
    """The compiled loop and the plant contract's stepper solve the same equations (the law
    from rest). A fractional delay: the stepper's Heun stage at the switch instant takes the
    new voltage, the kernel integrates up to it with the old one (first order in the
    substep), hence the looser bound."""
    _, P = records
    law = make_model("lugre", Fc=20.0, Fs=25.0, vs=0.005, sigma2=200.0, sigma0=1e6,
                     sigma1=1e3)
    exp = Experiment(0.0, 0.4, 1e-3)
    exact = delay in (0.0, 1e-3)
    tol_x, tol_u = (1e-12, 1e-9) if exact else (1e-6, 0.05)
    pl = EMPS(law, delay=delay)
    opts = dict(reference=P.qg, pulses=P.pulses)
    fast = pl.simulate(0.4, substeps=100, **opts)
    slow = Plant._simulate_fast(pl.with_options(**opts), exp, None, None, 1e-5)
    assert np.max(np.abs(fast["x"] - slow["x"])) < tol_x
    assert np.max(np.abs(fast["u"] - slow["u"])) < tol_u
    ax = EMPSAxis(law, delay=delay)
    fast = ax.simulate(0.4, voltage=P.vir, substeps=100)
    slow = Plant._simulate_fast(ax.with_options(voltage=P.vir), exp, None, None, 1e-5)
    assert np.max(np.abs(fast["x"] - slow["x"])) < tol_x


def test_bad_input_is_named():
    with pytest.raises(ValueError, match="delay"):
        EMPSParams(delay=2e-3)
    with pytest.raises(ValueError, match="needs 101"):
        EMPS().simulate(0.1, reference=np.zeros(50))
    with pytest.raises(ValueError, match="position_feedback"):
        EMPS().simulate(0.1, reference=np.zeros(200), position_feedback="filtered")
    with pytest.raises(ValueError, match="initial"):
        EMPSAxis().simulate(0.1, voltage=np.zeros(200), initial=[0.0, 1.0])
    with pytest.raises(ValueError, match="not finite"):
        EMPSAxis().simulate(0.1, voltage=np.full(200, np.nan))


def test_metrics():
    assert math.isclose(force_error([1.0, 2.0], [1.0, 1.0]), 1 / math.sqrt(2))
    m = position_metrics([0.0, 0.002], [0.0, 0.0])
    assert math.isclose(m["rmse_mm"], math.sqrt(2))


@pytest.mark.slow
def test_identification_through_the_simulation_reproduces_the_stored_models(records):
    """fit_models (least squares through the closed- and open-loop simulation of DATA_EMPS)
    lands where IDENTIFIED says (about 2-4 min on a shared 2-core machine)."""
    E, P = records
    fits = studies.fit_models(E, max_evals=300)
    for name, r in fits.items():
        stored = studies.scores(studies.stored_model(name), P)
        got = studies.scores(r["model"], P)
        assert abs(got["closed_loop"]["force_error"]
                   - stored["closed_loop"]["force_error"]) < 0.005
        for n, v in studies.IDENTIFIED[name]["plant"].items():
            if n != "delay":
                assert abs(r["params"][n] - v) <= 0.02 * abs(v) + 2e-5
                continue
            # a sub-sample delay the closed loop pins to about 5 % of a sample: the stored
            # "lugre" scores 0.03708 on DATA_EMPS at its 0.2253 ms and at 0.2516 ms (a fit
            # of session 28), 0.03748 at 0.35 ms, 0.03892 at 0
            assert abs(r["params"][n] - v) <= 0.05 * E.Ts, (name, r["params"][n], v)
            model = studies.stored_model(name)
            moved = replace(model, params=replace(model.params, delay=r["params"][n]))
            assert abs(studies.scores(moved, E)["closed_loop"]["force_error"]
                       - studies.scores(model, E)["closed_loop"]["force_error"]) < 1e-4


@pytest.mark.slow
def test_diagnosis_points_at_the_asymmetry_and_names_no_flexibility(records):
    """Fit DATA_EMPS, held out DATA_EMPS_PULSES: the asymmetry is the best candidate; the
    gap it leaves (a residual both records share, the pulses' structural response) gets no
    confident wrong name. Within DATA_EMPS (last 30 % held out) the asymmetry is named."""
    E, P = records
    model = studies.stored_model("lugre")
    rep = studies.diagnose(model, E, P)
    assert rep["verdict"]["cause"] in ("asymmetry", "unexplained")
    assert rep["effects"][0]["name"] == "asymmetry"
    assert rep["effects"][0]["gap_closed"] > 0.15
    for e in rep["effects"][1:]:
        if e["name"] in ("inertia", "delay", "acceleration", "drift", "stribeck_shape"):
            assert e["gap_closed"] < 0.1
    det = rep["effect_details"]["asymmetry"]["params"]
    assert det["sigma2_neg"] > 1.2 * det["sigma2"]      # documented: 166.7 vs 240.4 N s/m
    rep2 = studies.diagnose(model, E, None)
    assert rep2["verdict"]["cause"] == "asymmetry"


# -- the same case through the plant FMUs and their connection files ----------------------------
@pytest.fixture(scope="module")
def emps_fmus(tmp_path_factory):
    return studies.build_fmus(tmp_path_factory.mktemp("emps_fmus"))


def test_connection_files_parse(tmp_path):
    from fmus.connect import load_connection
    model = studies.stored_model("lugre")
    for kind in ("closed", "open"):
        path = tmp_path / f"emps_{kind}.toml"
        path.write_text(studies.connection_toml(studies.connection_dict(model, kind)))
        conn = load_connection(path)
        assert conn.friction_input == "F_friction" and conn.mass == "M"
        assert conn.parameters["M"] == pytest.approx(model.params.M)


def test_through_the_plant_fmus_equals_in_process(records, emps_fmus):
    """The EMPS loop FMU (and the axis FMU) with the native LuGre FMU, coupled by the
    connection file as a user's plant FMU is, against the in-process run from the same
    start, on 3 s of the pulse record (pulses at 0.34 s and 0.84 s ... included)."""
    _, P = records
    r = studies.run_through_fmus(studies.stored_model("lugre"), P.window(3.0), emps_fmus)
    cl, ol = r["closed"], r["open"]
    assert cl["max_abs_du_V"] < 0.1           # of a 1.6 V RMS voltage; coupling at 1 ms
    assert cl["max_abs_dx_m"] < 5e-6
    assert abs(cl["fmu_force_error"] - cl["inprocess_force_error"]) < 0.003
    # open loop: nothing pulls the position back, so the law FMU's coupling over 1 ms steps
    # (measured 0.13 mm after 3 s, 0.2 mm after 25 s) stays in the position
    assert ol["max_abs_dx_m"] < 3e-4
    assert abs(ol["fmu"]["rmse_mm"] - ol["inprocess"]["rmse_mm"]) < 0.1


@pytest.mark.slow
def test_identification_through_the_plant_fmu(records, emps_fmus):
    """Least squares through the closed-loop plant FMU (identification.plant_fmu, the path a
    user's plant FMU takes) lands where the in-process identification of the same
    parameters on the same window does."""
    E, _ = records
    start = studies.start_model()
    win = E.window(6.0)
    via_fmu = studies.identify_through_fmus(start, E, emps_fmus, stop=6.0, max_evals=60)
    coords = [c for c in studies.LUGRE_COORDS if c[0] in ("Fc", "sigma2", "b", "M")]
    inproc = studies.identify_trajectory(start, win, coords, parts=("closed",),
                                         max_evals=60, substeps=10)
    for name, key in (("Fc", "Fc"), ("sigma2", "sigma2"), ("b", "b"), ("M", "plant.M")):
        a, b = via_fmu["params"][key], inproc["params"][name]
        assert abs(a - b) <= 0.03 * abs(b) + 0.3, (name, a, b)
