"""No name without practical size (issue 15 item 1) and candidates that reach the forms real
data show (item 2): the waviness, the saturating warm-up, the step, the narrow defect, the
symmetric map; the clean-record benchmark (slow) gives no name."""
import numpy as np
import pytest

from diagnosis import diagnose
from diagnosis.clean_records import NO_NAME, clean_record, level_truth_record, run_clean
from diagnosis.core import IMPRINT_GAP, IMPRINT_NOISE, decide, practical_size, rank
from diagnosis.effects import CANDIDATES, Delay, make_context
from friction.extensions import drift_change, pack_extensions, position_change

NAMES = ("acceleration", "load", "asymmetry", "stribeck_shape", "presliding", "position",
         "inertia", "delay", "drift")


def _effect(name, gap, excess, z, imprint, size_reason=""):
    return {"name": name, "gap_closed": gap, "excess_closed": excess, "significance_z": z,
            "imprint": imprint, "size_reason": size_reason, "n_params": 1}


def test_the_issue_delay_miss_is_refused_by_its_imprint():
    # issue 15: a clean record, base within 1.2 x the floor (here 1.024), the delay closes
    # 1.7 % of the gap (73 % of the sliver above the floor) with paired z = 4.0; its own
    # imprint is about sqrt(2 x 0.017) = 0.18 of the gap: no name
    floor = 0.02
    before = 1.024 * floor
    imp = np.sqrt(2 * 0.017) * before
    eff = [_effect("delay", 0.017, 0.73, 4.0, imp),
           _effect("inertia", 0.001, 0.04, 0.5, 0.1 * floor)]
    v = decide(eff, before, floor)
    assert v["cause"] == "none"
    assert "imprint" in v["reason"] and "delay" in v["reason"]
    # the same figures with an imprint of practical size would be a small real effect
    ok = [dict(eff[0], imprint=0.6 * floor), eff[1]]
    assert decide(ok, before, floor)["cause"] == "delay"


def test_each_part_of_the_rule_names_its_reason():
    floor, before = 0.02, 0.10
    n = len(NAMES)
    assert practical_size(_effect("drift", 0.5, 0.6, 30.0, 0.05), before, floor, n) == ""
    assert "not significant" in practical_size(_effect("asymmetry", 0.537, 0.6, 1.1, 0.05),
                                               before, floor, n)
    assert "noise floor" in practical_size(_effect("x", 0.5, 0.6, 30.0,
                                                   0.9 * IMPRINT_NOISE * floor),
                                           before, floor, n)
    assert "gap" in practical_size(_effect("x", 0.5, 0.6, 30.0, 0.9 * IMPRINT_GAP * before),
                                   before, floor, n)
    assert "samples" in practical_size(_effect("delay", 0.5, 0.6, 30.0, 0.05,
                                               "its shift of 0.50 samples is below 1.5"),
                                       before, floor, n)
    # entries without the figures (transfer scores, trajectory level) keep the share rule
    bare = {"name": "load", "gap_closed": 0.5, "excess_closed": 0.6, "n_params": 1}
    assert practical_size(bare, before, floor, n) == ""
    assert decide([bare], before, floor)["cause"] == "load"


def test_a_dominant_candidate_under_a_third_is_named_and_says_why():
    """Beyond the noise ratio a candidate that closes a quarter to a third of the excess is
    named where it closes >= DOMINANCE x every other one (the only form that follows the
    gap), with practical size; not where another closes a third of it, not under a
    quarter, not inside the noise ratio, not without significance."""
    from diagnosis.verdict import DOMINANCE, DOMINANT_EXCESS, dominant
    floor, before = 0.01, 0.05
    lone = [_effect("position", 0.23, 0.29, 6.0, 0.02),
            _effect("stribeck_shape", 0.004, 0.005, 0.5, 0.002)]
    v = decide(lone, before, floor)
    assert v["cause"] == "position" and "less than a third" in v["reason"]
    assert dominant(lone)
    rival = [lone[0], _effect("delay", 0.08, 0.29 / DOMINANCE + 0.01, 4.0, 0.01)]
    assert not dominant(rival) and decide(rival, before, floor)["cause"] == "unexplained"
    small = [_effect("position", 0.2, DOMINANT_EXCESS - 0.01, 6.0, 0.02), lone[1]]
    assert decide(small, before, floor)["cause"] == "unexplained"
    # inside the noise ratio only a third (with the paired statistic) names
    assert decide(lone, 1.1 * floor, floor)["cause"] == "none"
    weak = [_effect("position", 0.23, 0.29, 1.0, 0.02), lone[1]]
    v = decide(weak, before, floor)
    assert v["cause"] == "unexplained" and "not significant" in v["reason"]


def test_symmetric_map_case_is_not_named_asymmetry():
    # issue 15: a symmetric map named asymmetry at 53.7 % of the gap with z = 1.1: outside
    # the noise ratio too, a name needs a significant held-out improvement
    floor, before = 0.02, 0.06
    eff = [_effect("asymmetry", 0.537, 0.8, 1.1, 0.04),
           _effect("delay", 0.02, 0.03, 0.4, 0.01)]
    v = decide(eff, before, floor)
    assert v["cause"] == "unexplained" and "not significant" in v["reason"]


def test_a_weaker_candidate_is_not_named_in_place_of_a_refused_best_one():
    # the best explanation is a sub-sample shift; a position map that mimics part of it on a
    # sinusoidal stroke closes less and is not named instead
    floor, before = 0.005, 0.03
    eff = [_effect("delay", 0.8, 0.99, 10.0, 0.02, "its shift of 0.6 samples is below 1.5"),
           _effect("position", 0.4, 0.5, 8.0, 0.015)]
    assert decide(eff, before, floor)["cause"] == "unexplained"


def test_delay_shorter_than_the_discretisation_has_no_practical_size():
    ctx = make_context(level_truth_record(lambda *a: 1.0, n=2000)[0])
    d = CANDIDATES["delay"]
    assert "samples" in d.practical({"delay": 0.9 * Delay.MIN_SAMPLES * ctx.dt}, ctx)
    assert d.practical({"delay": -1.1 * Delay.MIN_SAMPLES * ctx.dt}, ctx) == ""


def test_clean_record_sampled_half_a_sample_late_is_not_named():
    # an isolator record whose force is averaged over each sample period (half a sample
    # late) at 0.5 % noise: before the rule it was named delay (excess 1.19, z = 12.5)
    from diagnosis.benchmark import plant_kinematics
    kin = plant_kinematics("mre_isolator", quick=True)
    data, _ = clean_record(kin, truth="fine", sampling="average", velocity="gradient",
                           counts=50.0, noise=0.005, colour="white", seed=39)
    rep = diagnose(data, kin.base, candidates=["delay", "inertia", "position", "asymmetry"])
    assert rep["verdict"]["cause"] in NO_NAME
    delay = next(e for e in rep["effects"] if e["name"] == "delay")
    assert "samples" in delay["size_reason"]


# -- forms the candidates reach (truths: levels inside the bristle dynamics, integrated 10 x
# finer than sampled, v from quantised positions by np.gradient) ------------------------------
def _diag(level, candidates, **kw):
    data, truth = level_truth_record(level, noise=0.02, **kw)
    return diagnose(data, "lugre", candidates=candidates)


def test_waviness_of_seven_percent_of_the_stroke_is_position():
    # issue 15: period 7 % of the stroke, +/- 35 %: the 12-knot map closed 1 % (0.5 % here)
    rep = _diag(lambda x, t, lo, hi, T: 1 + 0.35 * np.sin(2 * np.pi * (x - lo)
                                                          / (0.07 * (hi - lo)) + 0.3),
                ["position", "drift", "asymmetry", "delay"])
    assert rep["verdict"]["cause"] == "position"
    assert rep["verdict"]["gap_closed"] > 0.45  # measured 0.54
    lam = rep["effect_details"]["position"]["extras"]["lambda_x"]
    data = level_truth_record(lambda *a: 1.0)[0]
    assert lam == pytest.approx(0.07 * np.ptp(data.x), rel=0.03)  # the wavelength found


def test_narrow_local_defect_is_position():
    # a defect 2 % of the stroke wide (sigma): 12 knots 9 % apart closed 0.22
    rep = _diag(lambda x, t, lo, hi, T: 1 + 0.5 * np.exp(-0.5 * ((x - lo - 0.6 * (hi - lo))
                                                                 / (0.02 * (hi - lo))) ** 2),
                ["position", "drift", "asymmetry"])
    assert rep["verdict"]["cause"] == "position"
    assert rep["verdict"]["gap_closed"] > 0.5  # measured 0.69


def test_saturating_warm_up_is_drift():
    # issue 15: +60 % with a time constant of a third of the record: the linear drift closed
    # 23 % (19.5 % here), below the one-third rule
    rep = _diag(lambda x, t, lo, hi, T: 1 + 0.6 * (1 - np.exp(-t / (T / 3))),
                ["drift", "position", "asymmetry"])
    assert rep["verdict"]["cause"] == "drift"
    assert rep["verdict"]["gap_closed"] > 0.6  # measured 0.79


def test_drift_fit_stops_once_its_cost_crawls(monkeypatch):
    # Drift.FTOL = 1e-4 (the other fits 1e-8): on the warm-up record the fit stops within a
    # few steps of scipy's tight stop, at a cost within 0.1 % of it
    from diagnosis import composite
    from diagnosis.core import fit_base
    data, _ = level_truth_record(lambda x, t, lo, hi, T: 1 + 0.6 * (1 - np.exp(-t / (T / 3))),
                                 noise=0.02)
    fit = data.split(0.7)[0]
    ctx = make_context(fit)
    base, names, _ = fit_base(fit, "lugre", ctx)
    drift = CANDIDATES["drift"]
    runs = []
    real = composite.least_squares

    def counted(*a, **kw):
        sol = real(*a, **kw)
        runs.append((kw["ftol"], sol.nfev))
        return sol
    monkeypatch.setattr(composite, "least_squares", counted)
    loose = composite.fit_composite(base.law, names, [drift], fit, ctx)
    n_loose = sum(n for _, n in runs)
    assert {f for f, _ in runs} == {drift.FTOL} and drift.FTOL == 1e-4
    runs.clear()
    monkeypatch.setattr(type(drift), "FTOL", composite.FTOL)
    tight = composite.fit_composite(base.law, names, [drift], fit, ctx)
    assert {f for f, _ in runs} == {1e-8}
    assert sum(n for _, n in runs) > n_loose
    assert loose[1] == pytest.approx(tight[1], rel=1e-3)


def test_step_change_of_the_level_is_drift():
    # +30 % within 10 ms at 45 % of the record (a lubricant change): linear drift closed 0.33
    rep = _diag(lambda x, t, lo, hi, T: 1 + 0.15 * (1 + np.tanh((t - 0.45 * T) / 0.005)),
                ["drift", "position", "asymmetry"])
    assert rep["verdict"]["cause"] == "drift"
    assert rep["verdict"]["gap_closed"] > 0.6  # measured 0.80


def test_symmetric_static_map_gets_no_name():
    # a symmetric static map (no presliding, Lorentzian curve): the base cannot follow its
    # sharp reversals; the shift that mimics them is a sub-sample one and not significant,
    # and asymmetry is not named
    data, _ = level_truth_record(lambda *a: 1.0, noise=0.015, static=True)
    rep = diagnose(data, "lugre", candidates=["asymmetry", "delay", "acceleration"])
    assert rep["verdict"]["cause"] in NO_NAME


# -- the one formula -----------------------------------------------------------------------------
def test_stroke_map_and_drift_forms_are_the_documented_formulas():
    x = np.linspace(-0.01, 0.11, 301)
    e = pack_extensions({"position": {"lambda_x": 0.007, "p_c1": 0.1, "p_s1": -0.2,
                                      "p_c2": 0.05, "p_s2": 0.03, "d_x": 0.3, "x_d": 0.04,
                                      "w_d": 0.01}}, x_lo=0.0, x_hi=0.1)
    ph = 2 * np.pi * x / 0.007
    want = (0.1 * np.cos(ph) - 0.2 * np.sin(ph) + 0.05 * np.cos(2 * ph) + 0.03 * np.sin(2 * ph)
            + 0.3 * np.exp(-0.5 * ((x - 0.04) / 0.01) ** 2))
    np.testing.assert_allclose(position_change(x, e), want, atol=1e-14)
    t = np.linspace(-0.5, 3.0, 401)
    e = pack_extensions({"drift": {"k_drift": 0.1, "k_sat": 0.6, "tau_sat": 0.4,
                                   "k_step": -0.2, "t_step": 1.5, "w_step": 0.05}},
                        t0=0.0, T=2.0)
    want = (0.1 * t / 2.0 + 0.6 * (1 - np.exp(-np.clip(t, 0, None) / 0.4))
            - 0.2 / (1 + np.exp(-(t - 1.5) / 0.05)))
    np.testing.assert_allclose(drift_change(t, e), want, atol=1e-12)
    # a sharp step and a saturation at once (tau_sat <= 0) are allowed
    e = pack_extensions({"drift": {"k_sat": 0.5, "tau_sat": 0.0, "k_step": 0.2,
                                   "t_step": 1.0, "w_step": 0.0}}, t0=0.0, T=2.0)
    np.testing.assert_allclose(drift_change(np.array([-1.0, 0.5, 1.0, 2.0]), e),
                               [0.0, 0.5, 0.7, 0.7])
    # the periodic part: two harmonics of period P_cyc from t0; P_cyc <= 0 switches it off
    e = pack_extensions({"drift": {"P_cyc": 0.7, "k_c1": 0.1, "k_s1": -0.2, "k_c2": 0.05,
                                   "k_s2": 0.03}}, t0=0.5, T=2.0)
    ps = 2 * np.pi * (t - 0.5) / 0.7
    want = (0.1 * np.cos(ps) - 0.2 * np.sin(ps) + 0.05 * np.cos(2 * ps)
            + 0.03 * np.sin(2 * ps))
    np.testing.assert_allclose(drift_change(t, e), want, atol=1e-14)
    e = pack_extensions({"drift": {"P_cyc": 0.0, "k_c1": 0.1}}, t0=0.5, T=2.0)
    assert not np.any(drift_change(t, e))
    with pytest.raises(ValueError, match="k_s2 = .*nan.* is not a finite number"):
        pack_extensions({"drift": {"P_cyc": 0.7, "k_s2": float("nan")}}, t0=0.5, T=2.0)
    # the resetting part: k_r1 u + k_r2 u^2 of the phase u since the last reset, every
    # P_rst from t_rst (before it too); back to 0 at each reset; P_rst <= 0 switches it off
    e = pack_extensions({"drift": {"P_rst": 0.4, "t_rst": 0.3, "k_r1": 0.2, "k_r2": -0.1}},
                        t0=0.5, T=2.0)
    ph = ((t - 0.3) / 0.4) % 1.0
    np.testing.assert_allclose(drift_change(t, e), 0.2 * ph - 0.1 * ph ** 2, atol=1e-13)
    np.testing.assert_allclose(drift_change(np.array([0.3, 0.7 - 1e-9, 0.7 + 1e-9, 1.3]), e),
                               [0.0, 0.2 - 0.1, 0.0, 0.5 * 0.2 - 0.25 * 0.1], atol=1e-8)
    e = pack_extensions({"drift": {"P_rst": 0.0, "k_r1": 0.2}}, t0=0.5, T=2.0)
    assert not np.any(drift_change(t, e))
    with pytest.raises(ValueError, match="t_rst = .*nan.* is not a finite number"):
        pack_extensions({"drift": {"P_rst": 0.4, "t_rst": float("nan")}}, t0=0.5, T=2.0)



def test_drift_parts_kept_for_new_amplitudes_give_the_same_bits():
    # a fit's Jacobian moves the drift's amplitudes alone in most columns: the parts of its
    # time scales, computed once, must give exactly the formula's d(t), whatever amplitude
    # is 0 when they are computed; and a drift candidate's apply reuses them
    from friction.extensions import drift_parts
    rng = np.random.default_rng(7)
    t = np.sort(rng.uniform(-1.0, 12.0, 2000))
    for _ in range(50):
        scales = {"tau_sat": rng.choice([0.0, rng.uniform(0.1, 5.0)]),
                  "t_step": rng.uniform(0.0, 10.0),
                  "w_step": rng.choice([0.0, rng.uniform(0.01, 1.0)]),
                  "P_cyc": rng.choice([0.0, rng.uniform(1.0, 5.0)]),
                  "P_rst": rng.choice([0.0, rng.uniform(1.0, 5.0)]),
                  "t_rst": rng.uniform(0.0, 3.0)}
        parts = drift_parts(t, pack_extensions({"drift": scales}, t0=0.3, T=10.0))
        for _ in range(3):
            amps = {k: rng.choice([0.0, rng.normal()]) for k in
                    ("k_drift", "k_sat", "k_step", "k_c1", "k_s1", "k_c2", "k_s2",
                     "k_r1", "k_r2")}
            e = pack_extensions({"drift": {**scales, **amps}}, t0=0.3, T=10.0)
            assert np.array_equal(drift_change(t, e, parts), drift_change(t, e))
    with pytest.raises(ValueError, match=r"parts has shape \(7, 2000\), expected \(7, 5\)"):
        drift_change(t[:5], e, parts)


def test_acceleration_level_part_is_even_in_a_and_starts_at_its_onset():
    # F (1 + f_e max(|a| - a_e, 0)) beside the odd part: braking raises the level as
    # accelerating does; a negative onset is refused by name
    from friction.extensions import extension_force
    e = pack_extensions({"acceleration": {"f_a": 0.0, "a_s": 1.0, "v_c": 1.0,
                                          "f_e": 0.2, "a_e": 0.5}})
    for a, want in ((0.3, 2.0), (-0.3, 2.0), (1.5, 2.0 * 1.2), (-1.5, 2.0 * 1.2)):
        assert extension_force(2.0, 0.1, a, 0.0, 1.0, 0.0, e) == pytest.approx(want)
    with pytest.raises(ValueError, match="a_e = -0.1 is out of bounds"):
        pack_extensions({"acceleration": {"f_a": 0.0, "a_s": 1.0, "v_c": 1.0, "a_e": -0.1}})
    # the odd level part F (1 + f_o a): braking lowers the level accelerating raises
    e = pack_extensions({"acceleration": {"f_a": 0.0, "a_s": 1.0, "v_c": 1.0, "f_o": 0.1}})
    for a, want in ((1.5, 2.0 * 1.15), (-1.5, 2.0 * 0.85), (0.0, 2.0)):
        assert extension_force(2.0, 0.1, a, 0.0, 1.0, 0.0, e) == pytest.approx(want)
    assert extension_force(-2.0, -0.1, 1.5, 0.0, 1.0, 0.0, e) == pytest.approx(-2.0 * 1.15)
    for k in ("f_e", "f_a", "a_e", "f_o"):
        with pytest.raises(ValueError, match=f"{k} = nan"):
            pack_extensions({"acceleration": {"f_a": 0.0, "a_s": 1.0, "v_c": 1.0,
                                              k: float("nan")}})


@pytest.mark.slow
def test_clean_records_across_the_plants_get_no_name(tmp_path):
    # 40 clean records (the benchmark script runs 500): truth 10 x finer, sampled at the
    # instant or averaged, quantised encoder positions differentiated three ways, white and
    # coloured noise at 0.5-5 %
    res = run_clean(40, quick=True, workers=2, cache_dir=str(tmp_path))
    assert res["records"] == 40
    assert res["named"] == 0, [(r["key"], r["verdict"]) for r in res["rows"]
                               if r["verdict"] not in NO_NAME]


def test_an_acceleration_part_that_is_a_mass_term_defers_to_inertia():
    # the part f_a tanh(a / a_s) w(v): with a_s far above the record's accelerations and
    # v_c far above its speeds it is dm a (a mass error); with v_c below the top speed it
    # fades with |v| (seed 000's form) and stays acceleration
    from friction.dataset import Dataset
    t = np.linspace(0.0, 2.0, 2001)
    v = 0.1 * np.sin(2 * np.pi * t)
    a = 0.2 * np.pi * np.cos(2 * np.pi * t)
    fit = Dataset.from_arrays(t, np.cos(t), x=-np.cos(2 * np.pi * t) / (20 * np.pi), v=v, a=a)
    ctx = make_context(fit)
    acc = CANDIDATES["acceleration"]
    mass_like = {"f_a": 3.0, "a_s": 3 * ctx.sa, "v_c": 20 * ctx.sv, "m_a": 0.0}
    to, why = acc.defers(mass_like, fit, ctx)
    assert to == "inertia" and "mass term" in why
    fading = dict(mass_like, a_s=0.3 * ctx.sa, v_c=0.2 * ctx.sv)
    assert acc.defers(fading, fit, ctx) == ("", "")
    # a small mass-like odd part beside a level part raised by |a| (it follows the
    # direction of sliding, not the sign of a): the candidate is no mass term
    level = dict(mass_like, f_a=0.05, f_e=0.5 / ctx.sa, a_e=0.0)
    fit_F = Dataset.from_arrays(t, np.sign(v) + 0.01 * v, x=fit.x, v=v, a=a)
    assert acc.defers(level, fit_F, ctx) == ("", "")
    assert acc.defers(dict(level, f_e=0.0), fit_F, ctx)[0] == "inertia"
    # ... but a mass term with a smaller level part beside it (a gear stage's losses on its
    # reflected inertia) is still the mass error
    geared = dict(level, f_a=3.0, f_e=0.3 / ctx.sa)  # level part 0.3 x the odd part
    assert acc.defers(geared, fit_F, ctx)[0] == "inertia"
    # the odd level part F f_o a: on a reversing stroke it follows the direction of
    # sliding (no mass term); on a one-way stroke (F of one sign) it is dm a
    odd_level = dict(mass_like, f_a=0.0, f_o=0.5 / ctx.sa)
    assert acc.defers(odd_level, fit_F, ctx) == ("", "")
    one_way = Dataset.from_arrays(t, 1.0 + 0.01 * v, x=fit.x, v=v, a=a)
    assert acc.defers(odd_level, one_way, ctx)[0] == "inertia"
    with pytest.raises(ValueError, match="a_s"):
        acc.defers(dict(mass_like, a_s=0.0), fit, ctx)
    # the other candidates never defer
    assert CANDIDATES["inertia"].defers({"dm": 1.0}, fit, ctx) == ("", "")


def test_a_deferring_candidate_ranks_behind_its_simpler_form_and_is_not_named():
    floor, before = 0.01, 0.10
    acc = dict(_effect("acceleration", 0.80, 0.89, 11.0, 0.07), n_params=5,
               validation_after=0.02, defers_to="inertia",
               defer_reason="its fitted part is a mass term")
    ine = dict(_effect("inertia", 0.75, 0.83, 10.5, 0.06), n_params=2, validation_after=0.025)
    dly = dict(_effect("delay", 0.10, 0.11, 5.0, 0.02), n_params=1, validation_after=0.09)
    effects = [dly, acc, ine]
    rank(effects)
    assert [e["name"] for e in effects] == ["inertia", "acceleration", "delay"]
    v = decide(effects, before, floor)
    assert v["cause"] == "inertia"
    # without the deferral the flexible candidate is ahead by more than the ties allow
    plain = [dict(acc, defers_to=""), ine, dly]
    rank(plain)
    assert decide(plain, before, floor)["cause"] == "acceleration"
    # with nothing to defer to it is refused, and a weaker candidate is not named instead
    alone = [dict(acc), dly]
    rank(alone)
    v = decide(alone, before, floor)
    assert v["cause"] == "unexplained" and "mass term" in v["reason"]


def test_a_deferral_the_held_out_records_contradict_is_overruled():
    # seen23's belt creep on the XML-350: the acceleration part is 99 % a mass term on the
    # fit record, but held out it closes 0.92 of the gap above the floor, the mass error 0.52
    floor, before = 0.0157, 0.113
    acc = dict(_effect("acceleration", 0.79, 0.92, 4.7, 0.10), n_params=5,
               validation_after=0.03, defers_to="inertia",
               defer_reason="its fitted part is a mass term")
    ine = dict(_effect("inertia", 0.45, 0.52, 5.8, 0.09), n_params=2, validation_after=0.06)
    effects = [dict(ine), dict(acc)]   # rank drops an overruled deferral in place
    rank(effects)
    assert [e["name"] for e in effects] == ["acceleration", "inertia"]
    assert "defers_to" not in effects[0]
    assert "mass term" in effects[0]["deferral_overruled"]
    assert "inertia closes 52 %" in effects[0]["deferral_overruled"]
    assert decide(effects, before, floor)["cause"] == "acceleration"
    # at DEFER_SHARE of its share the mass error keeps the name
    from diagnosis.verdict import DEFER_SHARE
    kept = [dict(ine, excess_closed=DEFER_SHARE * 0.92 + 1e-9), dict(acc)]
    rank(kept)
    assert kept[0]["name"] == "inertia" and kept[1]["defers_to"] == "inertia"
    assert decide(kept, before, floor)["cause"] == "inertia"
    # a deferring candidate that closes nothing keeps its deferral
    worse = [dict(ine, excess_closed=-0.9), dict(acc, excess_closed=-0.1)]
    rank(worse)
    assert worse[1]["defers_to"] == "inertia" and "deferral_overruled" not in worse[1]


@pytest.mark.slow  # 21 s: the suite's budget; inertia against acceleration is also test_diagnosis's
def test_an_added_mass_with_memory_is_named_inertia_not_acceleration():
    # grid case (valve, basset_added_mass, 1 % noise, gradient of 200-count positions): the
    # acceleration part closed 0.87 of the gap above the floor as dm a (a_s, v_c at the top
    # of their boxes) against the mass error's 0.79, and took the name
    from diagnosis.benchmark.cases import make_plant_case
    from diagnosis.benchmark.runner import MEASURED
    case = make_plant_case("valve", "inertia", 1.0, 0.01, seed=1, quick=True,
                           form="basset_added_mass", measured=MEASURED[0])
    rep = diagnose(case.data, case.base, seed=0)
    ranked = {e["name"]: e for e in rep["effects"]}
    assert ranked["acceleration"]["excess_closed"] > ranked["inertia"]["excess_closed"]
    assert ranked["acceleration"].get("defers_to") == "inertia"
    assert rep["verdict"]["cause"] == "inertia"
