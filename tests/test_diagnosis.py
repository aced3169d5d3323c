"""Diagnosis: withheld effects are named, clean data gets 'none', an effect outside the
library gets 'unexplained', and the real EMPS data points at its documented asymmetry."""
import json
from dataclasses import replace

import numpy as np
import pytest

from diagnosis import EFFECT_NAMES, diagnose
from diagnosis.benchmark import make_case
from frictionlab.cli import main


@pytest.mark.parametrize("effect", ["asymmetry", "inertia",
                                    pytest.param("drift", marks=pytest.mark.slow),
                                    pytest.param("delay", marks=pytest.mark.slow)])
def test_withheld_effect_is_named(effect):
    rep = diagnose(make_case(effect, 1.0, 0.02, n=8000, seed=11), "lugre")
    assert rep["verdict"]["cause"] == effect
    top = rep["effects"][0]
    assert top["name"] == effect and top["gap_closed"] > 0.2
    assert top["validation_after"] < top["validation_before"]


def test_clean_data_gets_none_and_outside_effect_unexplained():
    assert diagnose(make_case("clean", 1.0, 0.02, n=8000, seed=5), "lugre")["verdict"]["cause"] \
        == "none"
    assert diagnose(make_case("outside", 1.0, 0.02, n=8000, seed=5), "lugre")["verdict"]["cause"] \
        == "unexplained"


def test_report_follows_the_contract():
    rep = diagnose(make_case("asymmetry", 1.0, 0.02, n=6000, seed=2), "lugre")
    d = json.loads(rep.to_json())
    assert set(d["baseline"]) >= {"model", "metric", "fit", "validation"}
    assert d["baseline"]["metric"] == "nrmse"
    shares = [w["share"] for w in d["where"]]
    assert shares == sorted(shares, reverse=True) and abs(sum(shares) - 1) < 1e-9
    gaps = [e["gap_closed"] for e in d["effects"][1:]]
    assert gaps == sorted(gaps, reverse=True)
    for e in d["effects"]:
        assert e["name"] in EFFECT_NAMES
        assert e["gap_closed"] == pytest.approx(
            (e["validation_before"] - e["validation_after"]) / e["validation_before"])
    assert d["verdict"]["cause"] in set(EFFECT_NAMES) | {"none", "unexplained"}


def test_emps_points_at_direction_asymmetry(real_data):
    from identification.real_data import load_emps
    rep = diagnose(load_emps("estimation"), "lugre", validation=load_emps("validation"))
    # The base is identify's default law, offset b included (the published IDIM-LS model
    # has one, OF = -3.16 N; the base finds -3.2 N). Of the 25 % that `asymmetry` closed
    # over a base without it, most was that offset: the direction twins alone close 9 %
    # of the pulse set's held-out gap, under the one-third rule. Most of that gap is the
    # response to the record's 5 V controller-output steps (178 N of motor force, already
    # in gtau * vir: identification.real_data.emps_pulse_evidence; not an external 5 N)
    # and the structural flexibility they excite, outside the library. So the verdict
    # names no *other* effect; asymmetry ranked first until the position map had its
    # smooth force along the stroke, which closes a little more here (11.2 % against
    # 9.4 %, both far under the rule); fitted and held out on the two halves of DATA_EMPS
    # it names asymmetry (tests/test_real_diagnosis.py).
    assert rep["base"]["params"]["b"] == pytest.approx(-3.16, abs=0.3)
    assert rep["verdict"]["cause"] in ("asymmetry", "unexplained"), rep.summary()
    by = {e["name"]: e for e in rep["effects"]}
    assert rep["effects"][0]["name"] in ("asymmetry", "position")
    assert by["asymmetry"]["gap_closed"] > 0.05
    # the fitted direction twins show the worn screw (README of emps/: Fv+ 166.7, Fv- 240.4
    # N s/m, ratio 1.44; Fc+ 20.14, Fc- 20.63 N)
    p = rep["effect_details"]["asymmetry"]["params"]
    assert 1.3 < p["sigma2_neg"] / p["sigma2"] < 1.7
    assert p["sigma2_neg"] == pytest.approx(240.4, rel=0.1)
    assert p["Fc"] + p["b"] == pytest.approx(20.14, rel=0.15)      # sliding level, v > 0
    assert p["Fc_neg"] - p["b"] == pytest.approx(20.63, rel=0.15)  # and v < 0


@pytest.fixture(scope="module")
def pneumatic_report(real_data):
    from identification.real_data import load_pneumatic
    return diagnose(load_pneumatic("O-ring", 1), "lugre",
                    validation=[load_pneumatic("O-ring", 5), load_pneumatic("O-ring", 7)])


@pytest.mark.slow  # moved out of the default run: it alone takes 15-50 s
def test_pneumatic_points_at_load(pneumatic_report):
    """Fit at 1 bar, held out at 5 and 7 bar with the pressure as the load: ``load``.

    The 1-bar record spans 46-50 N of pressure load, the held-out records 243-347 N, so no
    load effect can be identified on the fit record: the report says so (extrapolation) and
    scores every candidate by transfer (calibrated on one held-out pressure, scored on the
    other). Load then wins on both folds, and the seal's friction grows with the pressure:
    the level's slope over the load, inside the bristle (``k_L``) and on the output
    (``k_Lo``, :class:`diagnosis.effects_load.LoadInside`), is positive calibrated at
    either pressure (0.44 and 0.29 per unit of relative load; the output slope carries most
    of it, so ``k_L`` alone is not the figure)."""
    rep = pneumatic_report
    assert rep["verdict"]["cause"] == "load", rep.summary()
    assert rep["verdict"]["protocol"] == "transfer"
    assert rep["effects"][0]["gap_closed"] > 0.5
    for fold in rep["transfer"]["folds"]:
        best = min(fold["after"], key=fold["after"].get)
        assert best == "load", fold
    for p in rep["effect_details"]["load"]["transfer_params"]:
        assert p["k_L"] + p["k_Lo"] > 0.05, p
    shift = rep["extrapolation"]["load"]
    assert shift["outside_share"] > 0.99
    assert 40 < shift["fit_range"][0] < shift["fit_range"][1] < 55
    assert shift["validation_range"][0] > 200


@pytest.mark.slow
@pytest.mark.parametrize("seal", ["NAPN", "KDN"])
def test_other_pneumatic_seals_point_at_load(real_data, seal):
    from identification.real_data import load_pneumatic
    rep = diagnose(load_pneumatic(seal, 1), "lugre",
                   validation=[load_pneumatic(seal, 5), load_pneumatic(seal, 7)])
    assert rep["verdict"]["cause"] == "load", rep.summary()


def test_extrapolation_flags_only_covariates_outside_the_fit_range():
    from diagnosis.core import extrapolation
    fit = make_case("load", 1.0, 0.02, n=4000, seed=3)
    same = make_case("load", 1.0, 0.02, n=4000, seed=4)
    assert extrapolation(fit, [same]) == {}
    far = replace(same, load=same.load * 10.0 + 5 * np.ptp(fit.load))
    out = extrapolation(fit, [far])
    assert set(out) == {"load"} and out["load"]["outside_share"] > 0.9


def test_cli_writes_json_and_html(tmp_path):
    data = make_case("inertia", 1.0, 0.02, n=5000, seed=4)
    p = tmp_path / "run.csv"
    data.to_csv(p)
    assert main(["diagnose", str(p), "--model", "lugre", "--json", str(tmp_path / "d.json"),
                 "--html", str(tmp_path / "d.html"), "--quiet"]) == 0
    d = json.loads((tmp_path / "d.json").read_text())
    assert d["verdict"]["cause"] == "inertia"
    page = (tmp_path / "d.html").read_text()
    assert page.count("data:image/png;base64") >= 3
    # the named effect's own fitted parameters with units, and the shrink sequence
    assert "Fitted parameters of <code>inertia</code>" in page and "<td>dm</td>" in page
    assert "<td>kg</td>" in page and "How far it shrinks" in page


def test_bad_input(tmp_path):
    with pytest.raises(ValueError, match="unknown candidate"):
        diagnose(make_case("clean", n=3000), "lugre", candidates=["friction_of_the_gods"])
    bad = tmp_path / "bad.csv"
    bad.write_text("t,x,F\n0,0,0\n0.001,nan,1\n0.002,0,1\n")
    assert main(["diagnose", str(bad), "--model", "lugre"]) == 2
    good = tmp_path / "good.csv"
    make_case("clean", n=3000).to_csv(good)
    assert main(["diagnose", str(good), "--model", "lugre", "--candidates", "load,nope"]) == 2


def test_friction_level_effects_leave_the_isolator_spring_alone():
    # mre_lugre's k0 x + f0 is elastic: drift/load/position scale the hysteretic rest only
    from diagnosis.composite import Composite
    from diagnosis.effects import CANDIDATES, make_context
    from friction import make_model
    from friction.dataset import Dataset
    law = make_model("mre_lugre")
    t = np.arange(0, 1.0, 1 / 256)
    x = 4e-3 * np.sin(2 * np.pi * 4 * t)
    v = np.gradient(x, t)
    # (a composite predicts a record from the law's steady state at its first velocity)
    F = law.simulate(t, v, x=x, state0="steady")
    data = Dataset(t=t, x=x, v=v, a=np.gradient(v, t), F=F)
    ctx = make_context(data)
    drifted = Composite(law, [], [CANDIDATES["drift"]], {"k_drift": 0.5}, ctx).predict(data)
    spring = law.conservative_force(x)
    np.testing.assert_allclose(spring, law.params.k0 * x + law.params.f0)
    np.testing.assert_allclose(drifted - spring, (F - spring) * (1 + 0.5 * (t - t[0]) / ctx.T),
                               rtol=1e-12, atol=1e-12)
    # a pure friction law has no such part
    assert np.all(make_model("lugre").conservative_force(x) == 0.0)


def test_load_effect_is_affine_in_the_load_and_amontons_at_one():
    from diagnosis.effects import CANDIDATES, make_context
    data = make_case("load", 1.0, 0.02, n=3000, seed=5)
    ctx = make_context(data)
    F = np.ones_like(data.t)
    load = CANDIDATES["load"]
    np.testing.assert_allclose(load.apply(F, {"k_L": 1.0}, data, ctx), data.load / ctx.L0)
    np.testing.assert_allclose(load.apply(F, {"k_L": 0.0}, data, ctx), 1.0)
    lo = load.extras(ctx)[0].lo
    assert -1.0 <= lo < 0.0  # falling with load allowed (seed 004 k1 < 0), down to zero level
    assert np.all(load.apply(F, {"k_L": lo}, data, ctx) >= 0.0)
