"""identify(): the least-squares path, result contents, reproducibility, bad data."""
import json

import numpy as np
import pytest

from friction import make_model
from friction.dataset import Dataset
from identification import identify, IdentificationResult

TRUE = dict(sigma0=1e5, sigma1=300.0, sigma2=0.4, Fc=1.0, Fs=1.5, vs=1e-3)
NAMES = list(TRUE)


@pytest.fixture(scope="module")
def synthetic():
    true = make_model("lugre", **TRUE)
    t = np.arange(0, 4, 1e-3)
    v = 0.01 * np.sin(2 * np.pi * 0.5 * t) + 0.002 * np.sin(2 * np.pi * 3 * t)
    return Dataset.from_arrays(t, true.simulate(t, v), v=v, name="synthetic lugre")


@pytest.fixture(scope="module")
def start():
    return make_model("lugre", sigma0=3e4, sigma1=100.0, sigma2=1.0, Fc=0.5, Fs=2.5, vs=5e-3)


def test_least_squares_recovers_lugre_from_a_distant_start(synthetic, start):
    r = identify(synthetic, start, algorithm="least_squares", names=NAMES)
    assert isinstance(r, IdentificationResult)
    for n, v in TRUE.items():
        assert r.params[n] == pytest.approx(v, rel=1e-3), n
    assert r.fit_nrmse < 1e-5
    assert r.n_evals > 0 and r.wall_time > 0
    # the fitted model carries the identified values and keeps the others
    assert r.model.params.sigma0 == pytest.approx(1e5, rel=1e-3)
    assert r.model.params.alpha == start.params.alpha
    # the history ends at the reported cost and never increases (best-so-far)
    h = np.array(r.cost_history)
    assert np.all(np.diff(h) <= 1e-15)
    assert h[-1] == pytest.approx(r.fit_nrmse, rel=1e-6, abs=1e-12)


def test_confidence_intervals_cover_truth_under_noise(synthetic, start):
    rng = np.random.default_rng(3)
    noisy = Dataset.from_arrays(synthetic.t, synthetic.F + 0.01 * rng.standard_normal(len(synthetic)),
                                v=synthetic.v)
    r = identify(noisy, start, algorithm="least_squares", names=NAMES, validation=synthetic)
    assert r.ci is not None
    for n in ("sigma2", "Fc", "Fs"):
        lo, hi = r.ci[n]
        assert lo < r.params[n] < hi
        assert lo <= TRUE[n] <= hi, (n, lo, hi)
    # validation on noise-free data: the fit error is about the noise level, the
    # validation error far below it
    assert r.validation_nrmse < r.fit_nrmse


def test_same_seed_same_result_and_json(synthetic, start, tmp_path):
    a = identify(synthetic, start, algorithm="multistart_ls", names=NAMES, seed=7, max_evals=300)
    b = identify(synthetic, start, algorithm="multistart_ls", names=NAMES, seed=7, max_evals=300)
    assert a.params == b.params and a.n_evals == b.n_evals <= 300
    out = tmp_path / "r.json"
    a.to_json(out)
    d = json.loads(out.read_text())
    assert d["algorithm"] == "multistart_ls" and d["model"]["name"] == "lugre"
    assert set(d["params"]) == set(NAMES)


def test_bad_data_and_bad_arguments_are_named(synthetic):
    const = Dataset.from_arrays(synthetic.t, np.ones(len(synthetic)), v=synthetic.v)
    with pytest.raises(ValueError, match="constant"):
        identify(const, "lugre", algorithm="least_squares")
    with pytest.raises(ValueError, match="unknown algorithm"):
        identify(synthetic, "lugre", algorithm="nope")
    with pytest.raises(KeyError, match="no parameter"):
        identify(synthetic, "lugre", names=["sigma9"])
    with pytest.raises(ValueError, match="upper"):
        identify(synthetic, "lugre", names=["Fc"], bounds={"Fc": (2.0, 1.0)})
    with pytest.raises(TypeError, match="Dataset"):
        identify({"t": [0, 1]}, "lugre")


def test_real_data_folder_missing_gives_a_clear_error(monkeypatch, tmp_path):
    from identification.real_data import load_emps
    monkeypatch.setenv("FRICTIONLAB_SHARED", str(tmp_path / "nowhere"))
    with pytest.raises(FileNotFoundError, match="FRICTIONLAB_SHARED"):
        load_emps()


def test_progress_lines_and_path_input(synthetic, start, tmp_path, capsys):
    csv = tmp_path / "d.csv"
    synthetic.to_csv(csv)
    r = identify(str(csv), start, algorithm="cmaes", names=NAMES, max_iter=3, progress=True)
    err = capsys.readouterr().err
    assert "[identify cmaes]" in err and "cost=" in err and ("it/s" in err or "s/it" in err)
    assert r.n_evals > 0 and len(r.trace) >= 1
    # the trace is monotone in evaluations, time and cost
    tr = np.array(r.trace)
    assert np.all(np.diff(tr[:, 0]) >= 0) and np.all(np.diff(tr[:, 2]) < 0)


def test_direction_twins_can_be_identified_from_a_symmetric_start():
    true = make_model("lugre", Fc=1.0, Fc_neg=1.4, sigma2=0.4, sigma2_neg=0.8)
    t = np.arange(0, 4, 1e-3)
    v = 0.01 * np.sin(2 * np.pi * 0.5 * t)
    d = Dataset.from_arrays(t, true.simulate(t, v), v=v)
    r = identify(d, "lugre", names=["Fc", "Fc_neg", "sigma2", "sigma2_neg"],
                 algorithm="least_squares")
    assert r.params["Fc_neg"] == pytest.approx(1.4, rel=1e-4)
    assert r.params["sigma2_neg"] == pytest.approx(0.8, rel=1e-3)
    assert r.model.params.Fc_neg == pytest.approx(1.4, rel=1e-4)
