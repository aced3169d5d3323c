"""The diagnosis' base law (issue 15, items 2 and 5).

* ``frictionlab identify`` and ``frictionlab diagnose`` fit the same base law: the free set
  is :func:`identification.space.default_names` for both. Franka case 4 (joint 7; source:
  longshike/NNFM-A-Novel-Neural-Network-Modeling-Approach-for-Robot-Flexible-Joints-Friction
  @ a343d3a3), fit on the slow record: the diagnosis base fitted it at NRMSE 1.10 without
  the offset b and the exponent alpha, while identify reaches 0.24.
* A base worse than a constant (fit NRMSE >= 1) stops the diagnosis with one line.
* Held-out records start from the law's steady state at their first velocity
  (rack-and-pinion stroke split in time, Mnich, KonradMnich/friction-identification
  @ 8b477df1); one too short to score is refused in one line.
"""
import numpy as np
import pytest

from conftest import REAL
from diagnosis import diagnose
from diagnosis.benchmark import make_case
from diagnosis.core import (BASE_FIT_LIMIT, MIN_SCORED_SAMPLES, BaseFitError,
                            base_free_names, fit_base, warm_up)
from frictionlab.cli import main

FRANKA = REAL / "franka_joint"
#: the base set the diagnosis used before: no offset, Gaussian exponent fixed at 2
OLD_BASE = ["sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs"]
FRANKA_MAP = "t=time,x=q7,v=dq7,F=q7_tau_J_compensate"


@pytest.fixture(scope="module")
def franka4():
    if not REAL.exists():
        pytest.skip(f"shared real data not found at {REAL}")
    from identification.real_data import load_franka
    return {s: load_franka(4, s) for s in ("slow", "middle", "high")}


def test_base_is_identify_default_set():
    from friction import MODELS, make_model
    from identification.space import ParameterSpace, default_names
    for name in MODELS:
        law = make_model(name)
        assert base_free_names(law) == default_names(law) == ParameterSpace.build(law).names
    assert {"alpha", "b"} <= set(base_free_names(make_model("lugre")))


def test_franka_case4_base_fits_as_identify_does(franka4):
    from identification import identify
    fit = franka4["slow"]
    ident = identify(fit, "lugre")
    base, names, base_fit = fit_base(fit, "lugre")
    assert names == ident.model.free_names()
    assert ident.fit_nrmse < 0.3
    # the same law, the same record: the same figure (the base is polished by the least
    # squares every candidate is fitted with, from its steady start)
    assert base_fit == pytest.approx(ident.fit_nrmse, rel=0.05)
    assert base.law.params.b == pytest.approx(ident.params["b"], abs=0.02)  # ~ -0.22 N m


def test_franka_case4_broken_base_stops_the_diagnosis(franka4):
    held = [franka4["middle"], franka4["high"]]
    with pytest.raises(BaseFitError, match=r"NRMSE 1\.1\d? >= 1, worse than the record's mean") \
            as err:
        diagnose(franka4["slow"], "lugre", validation=held, base_names=OLD_BASE)
    assert err.value.fit_nrmse >= BASE_FIT_LIMIT
    assert "\n" not in str(err.value)


def test_cli_stops_on_a_base_worse_than_a_constant(franka4, monkeypatch, capsys):
    # the old base set, put back in the shared definition: the command stops in one line
    import diagnosis.core
    monkeypatch.setattr(diagnosis.core, "base_free_names", lambda law: list(OLD_BASE))
    files = [str(FRANKA / f"franka_case4_{s}.csv") for s in ("slow", "middle", "high")]
    code = main(["diagnose", *files, "--model", "lugre", "--map", FRANKA_MAP, "--quiet"])
    err = capsys.readouterr().err.strip()
    assert code != 0
    assert err.startswith("frictionlab diagnose: error: the base lugre fits its own fit record")
    assert "worse than the record's mean" in err and len(err.splitlines()) == 1


@pytest.fixture(scope="module")
def rack_pinion_split():
    if not REAL.exists():
        pytest.skip(f"shared real data not found at {REAL}")
    from identification.real_data import load_rack_pinion
    return load_rack_pinion().split(0.7)


@pytest.mark.parametrize("seed", [0, pytest.param(1, marks=pytest.mark.slow)])
def test_rack_pinion_held_out_part_is_scored_from_its_steady_start(rack_pinion_split, seed):
    """The held-out part starts in motion (0.40 m/s): it is scored from the state consistent
    with its first samples, not from an undeflected bristle.

    The base's own values are not pinned: its cost is flat along sigma1 (on its upper
    bound 2000 or near it) and identify's multistart lands in one of two basins by seed
    (seed 0: fit NRMSE 0.368, polished to 0.343, held-out 0.67; seeds 1-4: 0.387, held-out
    0.99), so the absolute limits this test used (start spike > 500 N, held-out NRMSE <
    0.8) held for seed 0's basin only. What is asserted holds in both: the spike from rest
    is the law's own bristle-rate term (about sigma1 v), the steady start removes it, and
    the score is the held-out residual's NRMSE, far below the score from rest."""
    fit, held = rack_pinion_split
    assert held.v[0] > 0.35 and warm_up(held) == 0  # starts in motion: every sample scored
    rep = diagnose(fit, "lugre", validation=[held], seed=seed,
                   candidates=["stribeck_shape", "drift", "position"])
    base = rep._models["base"]
    law = base.law
    sd = np.std(held.F)
    r = held.F - base.predict(held)
    r_rest = held.F - law.simulate(held.t, held.v)
    # from an undeflected bristle the first sample is off by about sigma1 v (-777 N before)
    spike = law.params.sigma1 * held.v[0]
    assert spike > 5 * sd
    assert abs(r_rest[0]) > 0.5 * spike
    # from the state consistent with the first samples: no start spike
    assert abs(r[0]) < 0.05 * abs(r_rest[0])
    assert np.max(np.abs(r)) < 3.0 * sd
    before = rep["baseline"]["validation"]
    assert before == pytest.approx(np.sqrt(np.mean(r ** 2)) / sd, rel=1e-9)
    # the spike left in the score gave 5.4 (1.08 with it left out)
    assert before < 0.25 * np.sqrt(np.mean(r_rest ** 2)) / sd


def test_warm_up_only_for_a_record_that_starts_at_rest():
    d = make_case("clean", n=3000)
    assert d.v[0] != 0 and warm_up(d) == 0
    from dataclasses import replace
    rest = replace(d, v=np.concatenate([[0.0], d.v[1:]]))
    assert warm_up(rest) == 60


def test_held_out_record_too_short_to_score_is_refused(tmp_path, capsys):
    d = make_case("clean", n=3000)
    short = d.select(slice(100, 100 + MIN_SCORED_SAMPLES - 1))
    with pytest.raises(ValueError, match="too short to score"):
        diagnose(d, "lugre", validation=[short])
    # the chronological hold-out alike
    with pytest.raises(ValueError, match="held-out part of the record has 9 samples"):
        diagnose(d.select(slice(0, 30)), "lugre")
    fit_csv, short_csv = tmp_path / "fit.csv", tmp_path / "short.csv"
    d.to_csv(fit_csv)
    short.to_csv(short_csv)
    assert main(["diagnose", str(fit_csv), str(short_csv), "--model", "lugre", "--quiet"]) != 0
    err = capsys.readouterr().err.strip()
    assert "too short to score" in err and "short.csv" in err and len(err.splitlines()) == 1
