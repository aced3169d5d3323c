"""Franka cases 3 (joint 2) and 4 (joint 7), issue 15: fit one speed, hold out the others,
scored as the source scores (:mod:`identification.franka`; source: longshike/NNFM-... @
a343d3a3). Skipped without the shared real data.

What holds, and is asserted with the figures' own margins:

* the source's table is the RMS after a zero-phase 4th-order Butterworth at 1 Hz on the files'
  time base (to 1e-6 here, 1e-8 measured); the 10 Hz its script names does not reproduce it;
* the source's classical columns are one parameter set per case (CV identical across speeds);
* case 4's time column runs twice as long as its ``dq`` implies;
* case 3: at the same joint state (q, dq, ddq) the measured torque of the middle record lies
  0.38 N m above the slow one's, while each record repeats itself to 0.03 N m; the PINN's
  column carries most of that offset, so it is not a function of joint 2's own state fitted
  on one record;
* our LuGre fitted on the slow record is far from the PINN on case 3's held-out speeds (8.1x,
  5.5x) and near it on case 4's middle (1.28x), 2.3x on its high: the issue's goal is not
  reached, and the diagnosis says ``unexplained`` on both cases (slow test).
"""
import numpy as np
import pytest

from identification.franka import (SCRIPT_CUTOFF_HZ, column_rms, matched_state_difference,
                                   source_lowpass, source_rms, velocity_time_ratio)

SPEEDS = ("slow", "middle", "high")
MODELS = ("CV", "Dahl", "Stribeck", "LuGre", "SVM", "Light_Transformer", "PINN", "NNFM")


@pytest.fixture(scope="module")
def records(real_data):
    from identification.real_data import load_franka
    return {(c, s): load_franka(c, s) for c in (3, 4) for s in SPEEDS}


@pytest.fixture(scope="module")
def bases(records):
    # the diagnosis' base (identify's default LuGre set, polished), fitted on the slow record
    from diagnosis.core import fit_base
    return {c: fit_base(records[(c, "slow")], "lugre")[0] for c in (3, 4)}


def test_column_rms_reproduces_the_published_table(records):
    from identification.real_data import franka_paper_rms
    for (case, speed), d in records.items():
        for m in MODELS:
            paper = franka_paper_rms(case, speed, m)
            ours = column_rms(d, m)
            if np.isinf(paper):  # the source's LuGre diverges on case 3, high
                assert np.isinf(ours), (case, speed, m)
            else:
                assert ours == pytest.approx(paper, rel=1e-6), (case, speed, m)


def test_the_script_named_10_hz_does_not_reproduce_the_table(records):
    from identification.real_data import franka_paper_rms
    d = records[(3, "high")]
    assert column_rms(d, "PINN", SCRIPT_CUTOFF_HZ) / franka_paper_rms(3, "high", "PINN") > 1.4


def test_scoring_refuses_bad_input(records):
    d = records[(4, "slow")]
    with pytest.raises(ValueError, match="shape"):
        source_rms(d, d.F[:-1])
    with pytest.raises(ValueError, match="cutoff_hz"):
        source_lowpass(d.t, d.F, cutoff_hz=1e4)
    with pytest.raises(KeyError, match="column"):
        column_rms(d, "GPT")
    assert source_rms(d, d.F) == 0.0


def test_the_source_classical_models_are_one_fit_per_case(records):
    # the CV column is Fc sgn(dq) + fv dq with the same two numbers on every speed of a case
    fc_fv = {}
    for case in (3, 4):
        coef = []
        for s in SPEEDS:
            d = records[(case, s)]
            A = np.column_stack([np.sign(d.v), d.v])
            coef.append(np.linalg.lstsq(A, d.extra["CV"], rcond=None)[0])
        np.testing.assert_allclose(coef[1], coef[0], rtol=1e-5)
        np.testing.assert_allclose(coef[2], coef[0], rtol=1e-5)
        fc_fv[case] = coef[0]
    # identified_params/franka_case3_cv.mat: Fc 0.3344 N m, fv -0.3870 N m s/rad (fitted on
    # the 25,390 samples of the slow record); case 4: 0.1512, 2.0394 (its "high" record)
    np.testing.assert_allclose(fc_fv[3], [0.33444, -0.38703], atol=1e-4)
    np.testing.assert_allclose(fc_fv[4], [0.15119, 2.03942], atol=1e-4)


def test_case4_time_column_runs_twice_as_long_as_dq_implies(records):
    for s in SPEEDS:
        assert velocity_time_ratio(records[(3, s)]) == pytest.approx(1.0, abs=0.02)
        assert velocity_time_ratio(records[(4, s)]) == pytest.approx(0.5, abs=0.02)


def test_case3_torque_at_the_same_joint_state_differs_between_records(records):
    slow, middle = records[(3, "slow")], records[(3, "middle")]
    # each record repeats itself (passes >= 3 s apart): 0.032 and 0.024 N m
    for d in (slow, middle):
        assert matched_state_difference(d, d)["rms"] < 0.05
    # the middle record at the slow one's states: +0.377 N m mean, 0.397 rms (2126 pairs)
    cross = matched_state_difference(slow, middle)
    assert cross["n"] > 1000
    assert cross["mean"] > 0.3 and cross["rms"] > 0.3
    # the PINN's column moves with the record (+0.30 N m at the same states): it is not one
    # function of joint 2's (q, dq, ddq) fitted on one record
    assert cross["pinn_mean"] > 0.2


def test_lugre_fitted_on_slow_misses_the_pinn_on_case3(records, bases):
    ratios = {}
    for s in ("middle", "high"):
        d = records[(3, s)]
        ratios[s] = source_rms(d, bases[3].predict(d)) / column_rms(d, "PINN")
    # 8.08 and 5.50 (8.20 and 3.16 before the velocity, which lags q by 0.45 samples on
    # the slow record, was advanced: the slow record fits better, 0.410 -> 0.399, the high
    # one is predicted worse): the goal (ratio <= 1) is far
    assert ratios["middle"] > 5.0 and ratios["high"] > 2.0
    # most of the middle gap is one offset over the whole record (+0.48 N m of 0.52 RMS)
    d = records[(3, "middle")]
    r = source_lowpass(d.t, d.F) - source_lowpass(d.t, bases[3].predict(d))
    assert np.mean(r) > 0.4 and np.std(r) < 0.5 * np.sqrt(np.mean(r ** 2))


def test_lugre_fitted_on_slow_on_case4(records, bases):
    d_mid, d_high = records[(4, "middle")], records[(4, "high")]
    mid = source_rms(d_mid, bases[4].predict(d_mid)) / column_rms(d_mid, "PINN")
    high = source_rms(d_high, bases[4].predict(d_high)) / column_rms(d_high, "PINN")
    # 1.28 and 2.31: near the PINN on middle, not within it; the "high" record is the slowest
    # (|dq| 99th percentile 0.12 rad/s against the slow record's 0.43)
    assert 1.0 < mid < 1.6
    assert 1.8 < high < 2.9


@pytest.mark.slow
def test_example_diagnoses_both_cases_unexplained(real_data):
    import importlib.util
    import pathlib
    path = pathlib.Path(__file__).resolve().parents[1] / "examples" / "diagnose_franka.py"
    spec = importlib.util.spec_from_file_location("diagnose_franka", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    out = mod.run_diagnose_franka(verbose=False)
    for case in (3, 4):
        row = out[case]
        # no candidate closes a third of the held-out gap (case 3's best: load on the
        # |sin q2| proxy, 0.30 with the velocity advanced by its measured lag, 0.13 before;
        # case 4's: under 0.03)
        assert row["verdict"]["cause"] == "unexplained"
        assert max(g for _, g in row["effects"]) < 1.0 / 3.0
        assert row["fit_nrmse"] < 0.5
        for s, r in row["held_out"].items():
            assert r["ratio"] > 1.0, (case, s)  # the goal is not reached on any speed
            assert r["pinn"] == pytest.approx(column_rms_of(case, s), rel=1e-6)
        assert all(u for _, u in row["params"].values())  # every parameter has a unit
        assert {"sigma0", "Fc", "Fs", "vs", "alpha", "b"} <= set(row["params"])
    assert out[3]["held_out"]["middle"]["ratio"] > 5.0


def column_rms_of(case, speed):
    from identification.real_data import franka_paper_rms
    return franka_paper_rms(case, speed, "PINN")
