"""A small real effect within the noise: the paired held-out test (diagnosis.significance) and
the verdict path that uses it (diagnosis.decide)."""
import numpy as np
import pytest

from diagnosis import diagnose
from diagnosis.benchmark import make_case, make_plant_case
from diagnosis.core import MIN_EXCESS_CLOSED, NOISE_RATIO, decide
from diagnosis.significance import encompassing_z, improvement_z, noise_z, z_threshold
from diagnosis.verdict import EVENT_RATIO, RESOLVED_EXCESS, RESOLVED_IMPRINT
from friction import make_model


def _ar1(rng, n, phi):
    e = rng.standard_normal(n)
    out = np.empty(n)
    out[0] = e[0]
    for k in range(1, n):
        out[k] = phi * out[k - 1] + np.sqrt(1 - phi * phi) * e[k]
    return out


def test_equal_models_give_a_standard_normal_statistic():
    rng = np.random.default_rng(1)
    z = []
    for _ in range(300):
        noise = rng.standard_normal(3000)
        # two models, each off by its own independent error of the same size
        z.append(improvement_z(noise + 0.3 * rng.standard_normal(3000),
                               noise + 0.3 * rng.standard_normal(3000)))
    z = np.array(z)
    assert abs(np.mean(z)) < 0.2 and 0.8 < np.std(z) < 1.2
    assert np.mean(z > z_threshold(1, level=0.01)) < 0.03  # the 1 % level holds


def test_correlated_errors_are_not_counted_as_independent_samples():
    # neither model better, but their errors are slow (AR(1), phi 0.95): without the
    # Newey-West correction the statistic's spread would be ~6x too wide
    rng = np.random.default_rng(2)
    z_hac, z_naive = [], []
    for _ in range(200):
        n = 4000
        rb, rc = _ar1(rng, n, 0.95), _ar1(rng, n, 0.95)
        z_hac.append(improvement_z(rb, rc, lags=60))
        z_naive.append(improvement_z(rb, rc, lags=0))
    assert np.std(z_naive) > 2.0
    assert np.std(z_hac) < 1.4


def test_a_systematic_error_a_third_of_the_noise_is_resolved():
    rng = np.random.default_rng(3)
    n = 4000
    t = np.linspace(0, 20, n)
    noise = rng.standard_normal(n)
    e = 0.33 * np.sqrt(2) * np.sin(2 * np.pi * 0.7 * t)  # RMS 0.33 of the noise
    z = improvement_z(noise + e, noise)
    # RMS of the base residual only 1.05 x the noise: inside any ratio test, yet z >> 3
    assert np.sqrt(np.mean((noise + e) ** 2)) / np.std(noise) < 1.1
    assert z > 8.0
    # and the sign says which model is better
    assert improvement_z(noise, noise + e) < -8.0


def test_bad_input_named():
    with pytest.raises(ValueError, match="same length"):
        improvement_z(np.zeros(10), np.zeros(9))
    with pytest.raises(ValueError, match="level"):
        z_threshold(3, level=1.5)
    assert improvement_z([1.0, 2.0], [1.0, 2.0]) == 0.0


def test_noise_z_is_standard_normal_on_white_noise_of_the_floor_level():
    # whatever the candidate changes, a base residual that is white noise of the known
    # level gives N(0, 1): here a change made of two events
    rng = np.random.default_rng(4)
    n = 1200
    c = np.zeros(n)
    c[300:330] = np.hanning(30)
    c[900:930] = -np.hanning(30)
    z = np.array([noise_z(rb, rb - 0.5 * c, 0.2)
                  for rb in 0.2 * rng.standard_normal((400, n))])
    assert abs(np.mean(z)) < 0.15 and 0.85 < np.std(z) < 1.15
    with pytest.raises(ValueError, match="same length"):
        noise_z(np.zeros(10), np.zeros(9), 1.0)
    assert noise_z(np.ones(10), np.ones(10), 1.0) == 0.0  # no change
    assert noise_z(np.ones(10), np.zeros(10), 0.0) == 0.0  # no noise level


def test_a_gap_of_two_events_is_resolved_against_the_noise_not_by_its_events():
    # the forging press's mass errors: the held-out part holds two acceleration events.
    # The candidate that is the truth closes them; the HAC statistic counts two events
    # (z < 3), the projection against the floor's white noise counts their samples
    rng = np.random.default_rng(5)
    n, sigma = 1200, 0.02
    gap = np.zeros(n)
    gap[300:340] = 0.6 * np.hanning(40)
    gap[900:940] = -0.6 * np.hanning(40)
    noise = sigma * rng.standard_normal(n)
    rb, rc = gap + noise, noise
    z_hac, z_noise = encompassing_z(rb, rc), noise_z(rb, rc, sigma)
    z_need = z_threshold(10)  # ten candidates tried, as the diagnosis does
    assert z_hac < z_need < z_noise
    # the verdict takes the noise's statistic only where the gap is far above the floor
    sd = 1.0
    before, after = np.sqrt(np.mean(rb ** 2)) / sd, np.sqrt(np.mean(rc ** 2)) / sd
    floor = sigma / sd
    assert before >= EVENT_RATIO * floor
    e = _eff("inertia", before, after, floor, z_hac)
    e.update(noise_z=z_noise, imprint=np.sqrt(np.mean(gap ** 2)) / sd)
    others = [_eff(f"other{k}", before, before, floor, 0.0) for k in range(9)]
    assert decide([e] + others, before, floor)["cause"] == "inertia"
    # the same statistics under a gap within EVENT_RATIO x the floor, closed only in part
    # (what is left is not the floor's noise): not a name
    near = dict(e, excess_closed=0.9 * RESOLVED_EXCESS)
    v = decide([near] + others, 0.9 * EVENT_RATIO * floor, floor)
    assert v["cause"] != "inertia" and "against the noise floor" not in v["reason"]
    assert "not significant (paired z" in v["reason"]
    # ... closed to the floor with an imprint of a noise floor or more: resolved against
    # the noise left behind
    closed = dict(e, excess_closed=RESOLVED_EXCESS)
    assert e["imprint"] >= RESOLVED_IMPRINT * floor
    assert decide([closed] + others, 0.9 * EVENT_RATIO * floor, floor)["cause"] == "inertia"
    # ... but an imprint below a noise floor stays with the HAC statistic
    faint = dict(closed, imprint=0.9 * RESOLVED_IMPRINT * floor)
    v = decide([faint] + others, 0.9 * EVENT_RATIO * floor, floor)
    assert v["cause"] != "inertia" and "not significant (paired z" in v["reason"]


def _eff(name, before, after, floor, z, n_params=1):
    return {"name": name, "gap_closed": (before - after) / before,
            "excess_closed": (before - after) / (before - floor), "significance_z": z,
            "n_params": n_params}


def test_decide_names_a_small_gap_only_when_its_improvement_is_significant():
    floor, before = 0.10, 0.105  # inside NOISE_RATIO x floor
    assert before <= NOISE_RATIO * floor
    z_need = z_threshold(2)
    strong = [_eff("stribeck_shape", before, 0.101, floor, z_need + 0.5),
              _eff("load", before, 0.1049, floor, 0.3)]
    v = decide(strong, before, floor)
    assert v["cause"] == "stribeck_shape" and "significant" in v["reason"]
    weak = [_eff("stribeck_shape", before, 0.101, floor, z_need - 0.5),
            _eff("load", before, 0.1049, floor, 0.3)]
    assert decide(weak, before, floor)["cause"] == "none"
    # significant but closing too little of the gap above the floor: not a name
    small = [_eff("stribeck_shape", before, before - 0.2 * MIN_EXCESS_CLOSED * (before - floor),
                  floor, z_need + 3.0)]
    assert decide(small, before, floor)["cause"] == "none"
    # a residual at or below the floor estimate is noise whatever a candidate does
    assert decide([_eff("drift", 0.1, 0.09, 0.1001, 9.0)], 0.1, 0.1001)["cause"] == "none"
    # effects without the statistic (transfer, trajectory level) keep the ratio test
    no_z = [{k: v for k, v in strong[0].items() if k != "significance_z"}]
    assert decide(no_z, before, floor)["cause"] == "none"


def test_weak_stribeck_shape_inside_the_noise_is_named_and_reported():
    # a Lorentzian Stribeck curve under a Gaussian base: the base, which frees its exponent
    # as identify does, absorbs most of it; its held-out error is 1.06 x the noise floor,
    # yet the Lorentzian closes the rest with a significant held-out improvement. (The
    # valve's extra exponential low-speed tail, this test's case before, is now inside the
    # base's own family, a Gaussian of exponent ~1: `none` is right for it.)
    # Its held-out imprint is 0.39 x the noise floor: detected (reported with its z) but
    # below the practical size (half the noise, diagnosis.core.IMPRINT_NOISE), so no name
    rep = diagnose(make_case("stribeck_shape", 1.0, 0.02, seed=1), "lugre")
    assert rep["baseline"]["validation"] <= NOISE_RATIO * rep["noise_floor"]
    top = rep["effects"][0]
    assert top["name"] == "stribeck_shape"
    assert top["significance_z"] >= z_threshold(len(rep["effects"]))
    assert top["imprint"] < 0.5 * rep["noise_floor"]
    assert rep["verdict"]["cause"] == "none" and "imprint" in rep["verdict"]["reason"]
    # the others do not predict better than the base (squared-error test), though some of
    # their change follows the same residual (encompassing test: acceleration 4.6)
    assert all(e["improvement_z"] < 3.0 for e in rep["effects"][1:])
    assert all(e["excess_closed"] < MIN_EXCESS_CLOSED for e in rep["effects"][1:])


def test_stribeck_shape_candidate_frees_the_exponent_of_a_lorentzian_base():
    # a lorentzian base cannot take an exponent; the candidate offers the gaussian family with
    # a free one (it used to offer the plain gaussian only, and closed nothing)
    rng = np.random.default_rng(4)
    t = np.arange(12000) * 1e-3
    v = 0.02 * np.sin(2 * np.pi * 0.4 * t) + 0.004 * np.sin(2 * np.pi * 1.3 * t)
    truth = make_model("lugre", sigma0=1e5, sigma1=300.0, sigma2=5.0, Fc=1.0, Fs=2.0,
                       vs=2e-3, alpha=0.7, shape="gaussian")
    F = truth.simulate(t, v)
    from friction.dataset import Dataset
    data = Dataset.from_arrays(t, F + 0.01 * np.std(F) * rng.standard_normal(t.size),
                               v=v, x=np.cumsum(v) * 1e-3, check_units=False)
    base = make_model("lugre", sigma0=1e5, sigma1=300.0, sigma2=5.0, Fc=1.0, Fs=2.0, vs=2e-3,
                      shape="lorentzian")
    rep = diagnose(data, base, candidates=["stribeck_shape", "drift"])
    eff = {e["name"]: e for e in rep["effects"]}
    # at the force level the speed map bends the lorentzian curve (StribeckMap)
    assert eff["stribeck_shape"]["excess_closed"] > 0.7  # (was -1e-7)
    # the family form (the trajectory level's and the FMUs') finds the exponent
    from diagnosis.candidates import make_context
    from diagnosis.effects_stribeck import StribeckShape
    from diagnosis.composite import fit_composite
    fit, _ = data.split(0.7)
    ctx = make_context(fit)
    names = ["sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs"]
    fam = StribeckShape("stribeck_shape", "")
    comp, _ = min((fit_composite(lv, nv, [fam], fit, ctx)
                   for lv, nv in fam.modify_law(base, names, ctx)), key=lambda r: r[1])
    assert comp.law.params.shape == "gaussian"
    assert comp.law.params.alpha == pytest.approx(0.7, abs=0.1)
    # named only when its imprint reaches half the noise floor (practical size)
    top = eff["stribeck_shape"]
    want = "stribeck_shape" if top["imprint"] >= 0.5 * rep["noise_floor"] else "none"
    assert rep["verdict"]["cause"] == want


# -- the noise level: estimated, or given by the user ------------------------------------------
def _coloured_clean_case(tau=3.0, rel=0.02):
    """A clean valve case whose force noise went through a first-order filter (tau samples),
    as an anti-alias filter or a filtered inverse dynamics colours it."""
    from scipy.signal import lfilter

    from friction.dataset import Dataset
    case = make_plant_case("valve", "clean", 1.0, 0.0, seed=5, quick=True)
    rng = np.random.default_rng(7)
    a = np.exp(-1.0 / tau)
    n = lfilter([1 - a], [1, -a], rng.standard_normal(len(case.data)))
    n *= rel * np.std(case.truth) / np.std(n)
    d = case.data
    data = Dataset.from_arrays(d.t, case.truth + n, x=d.x, v=d.v, a=d.a, load=d.load,
                               check_units=False)
    return data, case.base, float(np.std(n))


@pytest.mark.slow  # moved out of the default run: it alone takes 15-50 s
def test_coloured_noise_is_never_given_a_name_and_is_none_once_its_level_is_known():
    data, base, sd_noise = _coloured_clean_case()
    rep = diagnose(data, base)
    # the second differences under-read filtered noise: the gap reads as structure, but no
    # candidate may claim it
    assert rep["noise_source"] == "estimated"
    assert rep["verdict"]["cause"] in ("none", "unexplained")
    given = diagnose(data, base, noise_level=sd_noise)
    assert given["noise_source"] == "given"
    assert given["verdict"]["cause"] == "none"


def test_bad_noise_level_named(tmp_path):
    data, base, sd_noise = _coloured_clean_case()
    for bad in (0.0, -1.0, float("nan"), "loud"):
        with pytest.raises(ValueError, match="noise_level"):
            diagnose(data, base, noise_level=bad, candidates=["drift"])
    # a level above the force's whole spread: a unit slip (mN for N)
    with pytest.raises(ValueError, match="unit"):
        diagnose(data, base, noise_level=1000 * sd_noise * 50, candidates=["drift"])


def test_cli_takes_the_noise_level_from_a_standstill_record(tmp_path):
    import json

    from frictionlab.cli import main
    data, base, sd_noise = _coloured_clean_case()
    fit = tmp_path / "run.csv"
    data.to_csv(fit)
    rng = np.random.default_rng(9)
    t = np.arange(2000) * data.dt
    F = 0.3 + sd_noise * rng.standard_normal(t.size)
    still = tmp_path / "standstill.csv"
    np.savetxt(still, np.c_[t, np.zeros_like(t), np.zeros_like(t), F], delimiter=",",
               header="t,x,v,F", comments="")
    out = tmp_path / "gap.json"
    assert main(["diagnose", str(fit), "--model", "lugre", "--noise-record", str(still),
                 "--json", str(out), "--candidates", "drift,asymmetry"]) == 0
    rep = json.loads(out.read_text())
    assert rep["noise_source"] == "given"
    assert rep["noise_floor"] == pytest.approx(np.std(F) / np.std(data.F[int(0.7 * len(data)):]),
                                               rel=0.05)
    assert main(["diagnose", str(fit), "--model", "lugre", "--noise-record", str(still),
                 "--noise-level", "0.1"]) != 0


def test_encompassing_statistic_is_standard_normal_without_a_common_gap_and_resolves_one():
    rng = np.random.default_rng(5)
    z0, dm, enc = [], [], []
    n = 3000
    t = np.linspace(0, 15, n)
    for _ in range(200):
        noise = rng.standard_normal(n)
        # a change fitted to other data's noise: unrelated to this record's residual
        z0.append(encompassing_z(noise, noise - 0.2 * rng.standard_normal(n)))
        # a real gap of RMS 0.2 x the noise, the candidate catching 80 % of it
        g = 0.2 * np.sqrt(2) * np.sin(2 * np.pi * 0.9 * t)
        dm.append(improvement_z(noise + g, noise + 0.2 * g))
        enc.append(encompassing_z(noise + g, noise + 0.2 * g))
    z0 = np.array(z0)
    assert abs(np.mean(z0)) < 0.2 and 0.8 < np.std(z0) < 1.2
    assert np.mean(z0 > z_threshold(1, level=0.01)) < 0.03
    # where the noise dominates it resolves the gap with a larger statistic: 1 / (1 - c/2)
    # times the squared-error test's for a candidate catching a share c of it (1.67 at 80 %)
    assert 1.45 < np.median(enc) / np.median(dm) < 1.9
    with pytest.raises(ValueError, match="same length"):
        encompassing_z(np.zeros(4), np.zeros(5))
