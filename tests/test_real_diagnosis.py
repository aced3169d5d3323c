"""The diagnosis on the real machines (issue 15): what it names, under which held-out
protocol, and why (examples/diagnose_real.py runs them all and prints the table).

* EMPS: the pulse signal is a 5 V step of the controller output, already inside the measured
  motor force (not an external force on the carriage); fitted on the first half of DATA_EMPS
  and held out on the second, the diagnosis names the worn screw's direction asymmetry.
  Held out on the pulse record, asymmetry ranks first but the 178 N steps' transients (a
  structural flexibility outside the library) keep it under or at the one-third rule.
* Pneumatic seals: fit at 1 bar, held out at 5 and 7 bar: ``load`` for the three seals.
* CICESE arm: on the Test 2 plateaus (interleaved speeds) joint 2 points at ``position``,
  joint 1 at nothing of practical size.
"""
import numpy as np
import pytest

from diagnosis import EFFECT_NAMES, diagnose

#: README of emps/: the worn ball screw's direction twins
EMPS_FV = {"+": 166.7, "-": 240.4}
EMPS_FC = {"+": 20.14, "-": 20.63}
CICESE = [n for n in EFFECT_NAMES if n != "backlash"]  # as examples/diagnose_real.py


def _twins(rep):
    p = rep["effect_details"]["asymmetry"]["params"]
    return p["sigma2"], p["sigma2_neg"], p["Fc"] + p["b"], p["Fc_neg"] - p["b"]


def test_emps_pulse_is_a_controller_output_step_inside_the_motor_force(real_data):
    from identification.real_data import emps_pulse_evidence
    ev = emps_pulse_evidence()
    # vir = the benchmark's PD law + 1 V per unit of pulses_N, same sample: the logged
    # controller output holds the pulse; with it the reconstruction is as good as on the
    # record without pulses (the rest is the encoder's quantisation through kv)
    assert ev["lag"] == 0 and ev["volts_per_unit"] == pytest.approx(1.0, abs=0.05)
    assert ev["rms_with"] == pytest.approx(ev["rms_estimation"], rel=0.05)
    assert ev["rms_without"] > 2 * ev["rms_with"]
    assert ev["step_force"] == pytest.approx(5 * 35.15, rel=0.05)  # a 176-178 N step
    # steady motion: an external 5 N would move the motor force by 5 N; it moves < 0.5 N
    assert all(abs(dF) < 0.5 for dF in ev["steady_force_change"].values())
    # the PD loop absorbs the 5 V in its position error: -5 V / (kv kp) = -130 um
    assert ev["error_shift"] == pytest.approx(ev["error_shift_expected"], rel=0.1)


@pytest.mark.parametrize("fraction", [0.5, pytest.param(0.6, marks=pytest.mark.slow)])
def test_emps_time_split_names_asymmetry(real_data, fraction):
    """Fit the first part of DATA_EMPS, hold out the rest (both directions at every speed):
    asymmetry closes about 21 % of the held-out gap, 42-46 % of it above the noise floor,
    with the runner-up (position) far behind; the twins are the worn screw's."""
    from identification.real_data import load_emps
    est = load_emps("estimation")
    k = int(fraction * len(est))
    rep = diagnose(est.select(slice(0, k)), "lugre", validation=est.select(slice(k, None)))
    assert rep["verdict"]["cause"] == "asymmetry", rep.summary()
    top, runner = rep["effects"][0], rep["effects"][1]
    assert top["name"] == "asymmetry" and 0.15 < top["gap_closed"] < 0.30
    assert top["excess_closed"] > 0.38  # the rule is 1/3
    # the runner-up is position: with its additive force of the position (about 1 N at a
    # 77 mm period along the 246 mm stroke) it closes 13.6 % at the half split (z 7.1; 5.8 %
    # as a level scale alone), 15.3 % at 0.6 (asymmetry 20.3 %): behind. Since the position
    # map's later starts it closes 17.6 % at 0.6 against asymmetry's 21.3 % (0.83 of it,
    # on 1c7014e and after), 16.4 % against 21.3 % at the half split: behind, less far
    assert runner["gap_closed"] < (0.8 if fraction == 0.5 else 0.9) * top["gap_closed"]
    fv_pos, fv_neg, fc_pos, fc_neg = _twins(rep)
    assert 1.3 < fv_neg / fv_pos < 1.7  # README 1.44
    assert fv_pos == pytest.approx(EMPS_FV["+"], rel=0.15)
    assert fv_neg == pytest.approx(EMPS_FV["-"], rel=0.10)
    assert fc_pos == pytest.approx(EMPS_FC["+"], rel=0.15)
    assert fc_neg == pytest.approx(EMPS_FC["-"], rel=0.15)


def test_emps_reverse_time_split_ranks_asymmetry_first(real_data):
    """The halves swapped (fit the second, hold out the first): asymmetry still first with
    its twins, but at the rule (33 % above the floor): the forward split is the robust one.
    Since the position map has its smooth force along the stroke it runs second closer
    behind (15.7 % against 18.1 %; it was under 0.7 x)."""
    from identification.real_data import load_emps
    est = load_emps("estimation")
    k = len(est) // 2
    rep = diagnose(est.select(slice(k, None)), "lugre", validation=est.select(slice(0, k)))
    assert rep["verdict"]["cause"] in ("asymmetry", "unexplained"), rep.summary()
    top, runner = rep["effects"][0], rep["effects"][1]
    assert top["name"] == "asymmetry" and 0.12 < top["gap_closed"] < 0.28
    assert top["excess_closed"] > 0.28 and runner["gap_closed"] < 0.95 * top["gap_closed"]
    fv_pos, fv_neg, _, _ = _twins(rep)
    assert 1.3 < fv_neg / fv_pos < 1.7


def test_emps_pulse_record_without_step_transients(real_data):
    """Held out on the pulse record between its steps (30 ms after each left out):
    asymmetry closes about a third of the gap above the floor - at the rule, so the verdict
    is not robust (it names asymmetry at 30-50 ms, not at 10, 20 or 100 ms); with the steps
    kept it closes a tenth of the gap (test_diagnosis). The position map with its smooth
    force along the stroke (1.5 N over the 0.25 m stroke, 4 % of std(F)) closes as much
    (17.3 % against 16.5 %) and is named by a hair: the two tie, and neither is robust."""
    from identification.real_data import emps_pulse_segments, load_emps
    rep = diagnose(load_emps("estimation"), "lugre", validation=emps_pulse_segments(0.03))
    assert rep["verdict"]["cause"] in ("asymmetry", "position", "unexplained"), rep.summary()
    by = {e["name"]: e for e in rep["effects"]}
    asym, top = by["asymmetry"], rep["effects"][0]
    assert top["name"] in ("asymmetry", "position")
    assert 0.12 < asym["gap_closed"] < 0.25 and 0.25 < asym["excess_closed"] < 0.42
    assert asym["significance_z"] > 5
    # the two lead, nearly tied, far ahead of every other candidate
    rest = [e for e in rep["effects"] if e["name"] not in ("asymmetry", "position")]
    assert all(e["gap_closed"] < 0.7 * asym["gap_closed"] for e in rest)
    assert abs(by["position"]["gap_closed"] - asym["gap_closed"]) < 0.15 * asym["gap_closed"]
    fv_pos, fv_neg, _, _ = _twins(rep)
    assert 1.3 < fv_neg / fv_pos < 1.7


def test_emps_pulse_segments_cut_at_the_steps(real_data):
    from identification.real_data import emps_pulse_segments
    segs = emps_pulse_segments(drop=0.03)
    assert len(segs) == 49  # the 49 steps of the 24.8 s record
    for s in segs:
        assert np.ptp(s.extra["pulses_N"]) == 0  # no step inside a segment
        assert 0.4 < s.t[-1] - s.t[0] < 0.5
    assert len(emps_pulse_segments(drop=0.03, keep_start=True)) == 50


def test_cicese_speed_split_deals_speeds_alternately(real_data):
    from identification.real_data import cicese_plateau_runs, cicese_speed_split
    runs = cicese_plateau_runs(2, -1)
    speeds = [abs(v) for _, v, _ in runs]
    assert speeds == sorted(speeds) and min(speeds) > 0.45 * np.pi / 180
    fit, held = cicese_speed_split(2, -1)
    assert len(held) == len(runs) // 2 and len(fit) + sum(map(len, held)) == \
        sum(len(r) for _, _, r in runs)
    assert np.all(np.diff(fit.t) > 0) and np.all(fit.v < 0)
    fit2, held2 = cicese_speed_split(2)
    assert (fit2.v > 0).any() and (fit2.v < 0).any()
    assert {np.sign(h.v.mean()) for h in held2} == {1.0, -1.0}


def test_cicese_joint2_points_at_position(real_data):
    """Joint 2 (elbow), Test 2 plateaus, the odd speeds fitted and the even ones held out:
    in the negative direction ``position`` closes about a fifth of the held-out gap (58 %
    above the floor; nothing else 2 %). With the other parity fitted it is named too
    (14 %, 41 %), and in the positive direction (22 %, 50 %; 11 %, 23 % with this parity).
    What it fits is odd in q (+0.17 N m near q = -135 deg, -0.15 near +135, the reverse
    near +-45 deg): a conservative torque about 0.1 sin 2q N m rather than a friction
    level, the shape of a 6 % error in the elbow's gravity term (README: 1.82 sin(q1 + q2)
    N m, q1 = q2 in Test 2). Test 2 drives q and v with the same sign, so a friction map
    over q cannot be told from it. Both directions together: position first, at the rule
    (34-39 % above the floor, depending on the staircase's parity)."""
    from identification.real_data import cicese_speed_split
    fit, held = cicese_speed_split(2, -1)
    rep = diagnose(fit, "lugre", validation=held, candidates=CICESE)
    assert rep["verdict"]["cause"] == "position", rep.summary()
    top, runner = rep["effects"][0], rep["effects"][1]
    assert 0.12 < top["gap_closed"] < 0.30 and top["excess_closed"] > 0.45
    assert runner["gap_closed"] < 0.05
    fit, held = cicese_speed_split(2)
    rep = diagnose(fit, "lugre", validation=held, candidates=CICESE)
    assert rep["verdict"]["cause"] in ("position", "unexplained"), rep.summary()
    assert rep["effects"][0]["name"] == "position"
    assert 0.10 < rep["effects"][0]["gap_closed"] < 0.25
    # the base's sliding level and viscous slope of the elbow (source: viscous 0.1237 N m s/rad)
    base = rep["base"]["params"]
    assert 1.5 < base["Fc"] < 2.1 and 0.08 < base["sigma2"] < 0.2


@pytest.mark.slow  # about 10 s
def test_cicese_joint1_names_nothing_of_practical_size(real_data):
    """Joint 1 (shoulder): per direction and both together, no candidate closes more than a
    tenth of the held-out gap; the plateaus' 1-4 N m torque ripple is most of it (noise
    floor 0.57-0.72 of the NRMSE per direction)."""
    from identification.real_data import cicese_speed_split
    for direction in (None, 1, -1):
        fit, held = cicese_speed_split(1, direction)
        rep = diagnose(fit, "lugre", validation=held, candidates=CICESE)
        assert rep["verdict"]["cause"] in ("unexplained", "none"), rep.summary()
        assert rep["effects"][0]["gap_closed"] < 0.10


@pytest.mark.slow  # 5-20 s per seal
@pytest.mark.parametrize("seal", ["O-ring", "NAPN", "KDN"])
def test_pneumatic_seals_name_load_with_runner_up(real_data, seal):
    """Fit at 1 bar, held out at 5 and 7 bar (transfer scores): load closes 66-81 % of the
    gap (session 10: O-ring 78.7, NAPN 80.5, KDN 65.7 %); the runner-up (asymmetry or
    position, calibrated on a held-out pressure too) closes 58-66 %, so the name rests on
    an 8-17 point lead."""
    from identification.real_data import load_pneumatic
    rep = diagnose(load_pneumatic(seal, 1), "lugre",
                   validation=[load_pneumatic(seal, 5), load_pneumatic(seal, 7)])
    assert rep["verdict"]["cause"] == "load", rep.summary()
    top, runner = rep["effects"][0], rep["effects"][1]
    assert top["name"] == "load" and top["gap_closed"] > 0.65
    assert runner["gap_closed"] < top["gap_closed"] - 0.05


@pytest.mark.slow  # about 10 s; examples/diagnose_real.py is not in test_docstrings' tables
def test_example_diagnose_real_quick(real_data):
    import importlib.util
    import pathlib
    path = pathlib.Path(__file__).resolve().parents[1] / "examples" / "diagnose_real.py"
    spec = importlib.util.spec_from_file_location("example_diagnose_real", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    res = mod.run_diagnose_real(only=("emps", "cicese"), quick=True)
    rows = {r["dataset"]: r for r in res["rows"]}
    assert rows["EMPS"]["verdict"] == "asymmetry" and rows["EMPS"]["runner_up"] is not None
    assert rows["CICESE joint 2"]["top"] == "position"
    assert res["pulse_evidence"]["lag"] == 0
    assert "asymmetry" in mod.format_rows(res["rows"])
