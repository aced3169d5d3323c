"""Steady-state maps and the two-step method (issue 16, item 2): a map file (v, F, no t)
from the CLI and the API, per-direction static parameters, the dynamic ones with the static
ones fixed, a column of a 2-D .mat variable, and the real proof on the CICESE arm and the
joint steady-state map. Each fails on the previous main ("no time column 't'")."""
import json

import numpy as np
import pytest

from friction import make_model
from friction.dataset import Dataset, DataError, SteadyStateMap, load_dataset
from frictionlab.cli import main
from identification import identify
from identification.steady_state import (identify_static, identify_two_step, plateau,
                                         static_values)

ASYM = dict(sigma0=2e4, sigma1=50.0, sigma2=0.8, sigma2_neg=1.2, Fc=1.0, Fc_neg=1.3,
            Fs=1.6, Fs_neg=1.8, vs=4e-3, vs_neg=6e-3)
DEG = np.pi / 180


def _map(law, rng, n=24):
    s = np.geomspace(5e-4, 0.2, n)
    v = np.concatenate([-s, s])
    return SteadyStateMap(v, law.steady_state(v) + 0.003 * rng.standard_normal(v.size),
                          name="synthetic map")


def test_map_file_identifies_the_static_parameters_per_direction(tmp_path, capsys, rng):
    law = make_model("lugre", **ASYM)
    path = tmp_path / "map.csv"
    _map(law, rng).to_csv(path)
    assert load_dataset(path).__class__ is SteadyStateMap  # v, F and no t
    out = tmp_path / "static.json"
    assert main(["identify", str(path), "--model", "lugre", "--json", str(out),
                 "--quiet"]) == 0
    text = capsys.readouterr().out
    assert "steady-state map" in text and "b held at 0" in text
    d = json.loads(out.read_text())
    p = d["params"]
    for n in ("Fc", "Fc_neg", "Fs", "Fs_neg", "sigma2", "sigma2_neg"):
        assert p[n] == pytest.approx(ASYM[n], rel=0.05), n
    assert "sigma0" not in p and "sigma1" not in p  # a map carries no dynamics
    assert d["fixed"] == {"b": 0.0}
    assert d["identifiability"]["unidentified"] == []
    # the static law alike, through the API
    r = identify_static(_map(law, rng), "stribeck")
    assert r.params["Fc_neg"] == pytest.approx(1.3, rel=0.05)


def test_two_step_static_then_dynamic_api_and_cli(tmp_path, capsys, rng):
    law = make_model("lugre", **ASYM)
    smap = _map(law, rng)
    t = np.arange(0.0, 4.0, 1e-3)
    v = 1.5e-4 * np.sin(2 * np.pi * 1.0 * t) + 2e-4 * np.sin(2 * np.pi * 0.25 * t)
    d = Dataset.from_arrays(t, law.simulate(t, v) + 0.003 * rng.standard_normal(t.size), v=v,
                            name="presliding")
    two = identify_two_step(smap, d, "lugre")
    assert set(two["dynamic"].params) == {"sigma0", "sigma1"}
    assert two["dynamic"].params["sigma0"] == pytest.approx(2e4, rel=0.1)
    assert two["model"].params.Fc_neg == pytest.approx(two["static"].params["Fc_neg"])
    assert set(two["dynamic"].fixed) >= {"Fc", "Fc_neg", "Fs", "Fs_neg", "sigma2", "b"}
    # the CLI: step 1 writes the JSON step 2 reads
    mpath, dpath = tmp_path / "map.csv", tmp_path / "pre.csv"
    smap.to_csv(mpath)
    d.to_csv(dpath)
    sj, dj = tmp_path / "static.json", tmp_path / "dyn.json"
    assert main(["identify", str(mpath), "--model", "lugre", "--json", str(sj),
                 "--quiet"]) == 0
    assert main(["identify", str(dpath), "--model", "lugre", "--static-from", str(sj),
                 "--json", str(dj), "--quiet"]) == 0
    out = json.loads(dj.read_text())
    assert set(out["params"]) == {"sigma0", "sigma1"}
    assert out["params"]["sigma0"] == pytest.approx(2e4, rel=0.1)
    assert out["model"]["params"]["Fc_neg"] == pytest.approx(
        json.loads(sj.read_text())["params"]["Fc_neg"])
    assert "static from" in capsys.readouterr().out


def test_bad_inputs_are_named(tmp_path, capsys):
    path = tmp_path / "x.csv"
    path.write_text("x,F\n0,1\n1,2\n2,3\n")
    assert main(["identify", str(path), "--model", "lugre", "--quiet"]) != 0
    assert "no time column 't'" in capsys.readouterr().err
    bad = tmp_path / "bad.json"
    bad.write_text("[1, 2]")
    ok = tmp_path / "d.csv"
    Dataset.from_arrays(np.arange(20.0) * 0.01, np.sin(np.arange(20.0)),
                        v=np.cos(np.arange(20.0))).to_csv(ok)
    assert main(["identify", str(ok), "--model", "lugre", "--static-from", str(bad),
                 "--quiet"]) != 0
    assert "model.params" in capsys.readouterr().err
    assert main(["identify", str(ok), "--model", "lugre", "--bounds", "sigma1=oops",
                 "--quiet"]) != 0
    assert "NAME=LOW:HIGH" in capsys.readouterr().err
    assert main(["identify", str(ok), "--model", "lugre", "--min-speed", "0.1",
                 "--quiet"]) != 0
    assert "steady-state map" in capsys.readouterr().err


def test_plateau_of_a_run_with_a_transient():
    t = np.arange(0.0, 5.0, 0.01)
    v = np.where(t < 1.0, 0.2 * t, 0.2) + 0.001 * np.sin(40 * t)
    F = np.where(t < 1.0, 5.0, 2.0)
    run = Dataset.from_arrays(t, F, v=v, check_units=False)
    p = plateau(run, 0.2, tolerance=0.05)
    assert p["t0"] >= 0.9 and p["F"] == pytest.approx(2.0) and p["v"] == pytest.approx(0.2, rel=0.01)


def test_joint_steady_state_map_from_a_mat_column(real_data, capsys, tmp_path):
    """``--map v=log[:,1],F=log[:,0]`` splits the 800 x 2 variable; the sliding rows give
    the source's Fc = 2 and sigma2 = 1 (Script_Friction.m) per direction."""
    f = str(real_data / "joint_steady_state" / "log_cte_Vel.mat")
    assert main(["identify", f, "--model", "stribeck", "--map", "v=log", "--quiet"]) != 0
    err = capsys.readouterr().err
    assert "800x2" in err and "--map v=log[:,0]" in err
    out = tmp_path / "j.json"
    assert main(["identify", f, "--model", "stribeck", "--map", "v=log[:,1],F=log[:,0]",
                 "--min-speed", "1e-4", "--json", str(out), "--quiet"]) == 0
    p = json.loads(out.read_text())["params"]
    assert p["Fc"] == pytest.approx(2.0, rel=0.02) and p["Fc_neg"] == pytest.approx(2.0, rel=0.02)
    assert p["sigma2"] == pytest.approx(1.0, rel=0.05)
    # the log's first ~15 rows (v = -0.338 m/s) still relax from -3.05 to -2.34: they tilt
    # the v < 0 slope to 1.11
    assert p["sigma2_neg"] == pytest.approx(1.0, rel=0.15)
    assert p["Fs"] > p["Fc"] and p["Fs_neg"] > p["Fc_neg"]  # the Stribeck bump, both sides
    # with the presliding rows the report says what they are and what to do
    r = identify(load_dataset(f, {"v": "log[:,1]", "F": "log[:,0]"}), "stribeck")
    assert "Fs<Fc" in [x["label"] for x in r.identifiability["relations"]]
    assert any("--min-speed" in a for a in r.identifiability["advice"])


@pytest.fixture(scope="module")
def cicese(real_data):
    from identification.real_data import cicese_breakaway, cicese_test2_map
    return {j: (cicese_breakaway(j), cicese_test2_map(j)) for j in (1, 2)}


def test_cicese_static_friction_per_direction_within_10_percent(cicese):
    from identification.real_data import CICESE_PUBLISHED
    for j in (1, 2):
        brk, _ = cicese[j]
        pos, neg = CICESE_PUBLISHED["static"][j]
        assert brk["+"] == pytest.approx(pos, rel=0.10), (j, brk)
        assert brk["-"] == pytest.approx(neg, rel=0.10), (j, brk)


def test_cicese_stribeck_map_per_direction_then_sigma0_from_presliding(cicese):
    """The source's protocol: static friction from Test 1, a Stribeck map per direction
    from Test 2 (plateaus from 0.5 deg/s up, static levels held), sigma0 from Test 3."""
    from identification.real_data import CICESE_PUBLISHED, load_cicese_presliding
    brk, smap = cicese[1]
    assert (smap.v > 0).sum() >= 30 and (smap.v < 0).sum() >= 25  # both directions
    assert np.all(np.diff(smap.v) >= 0) and np.all(np.sign(smap.F) == np.sign(smap.v))
    r1 = identify(smap.sliding(0.45 * DEG), "lugre", fixed={"Fs": brk["+"],
                                                           "Fs_neg": -brk["-"]})
    p = r1.params
    # Coulomb level per direction between break-away and the 90 deg/s plateau
    assert brk["+"] < p["Fc"] < 17.0 and -brk["-"] - 2.0 < p["Fc_neg"] < 15.0
    # the viscous slope per direction near the source's 3.1465 N m s/rad
    for n in ("sigma2", "sigma2_neg"):
        assert p[n] == pytest.approx(CICESE_PUBLISHED["viscous"][1], rel=0.25), n
    assert "Fs<Fc" in [x["label"] for x in r1.identifiability["relations"]]
    # step 2: sigma0, sigma1 from a presliding run with the static parameters fixed,
    # scored on a repetition
    pre, rep = load_cicese_presliding(1, 1), load_cicese_presliding(1, 2)
    r2 = identify(pre, r1.model, names=["sigma0", "sigma1"], fixed=static_values(r1.model),
                  validation=rep)
    assert r2.identifiability["unidentified"] == []
    lo, hi = r2.ci["sigma0"]
    assert lo < r2.params["sigma0"] < hi and hi / lo < 1.5
    # the source's Test3.m: 6 N m over the mean peak-to-peak displacement, 2.14e4 N m/rad
    assert 1e4 < r2.params["sigma0"] < 6e4
    assert r2.validation_nrmse < 0.6
