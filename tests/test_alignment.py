"""The motion channels on one time base (friction.alignment): a velocity differentiated
backward lags its position by half a sample; identify and diagnose advance it by its
measured lag."""
import numpy as np
import pytest

from diagnosis import diagnose
from friction.alignment import MIN_ALIGN_SAMPLES, align_motion, channel_lag, velocity_lag
from friction.dataset import Dataset


def _counts(n=4000, dt=1e-3, counts=1e-6):
    t = np.arange(n) * dt
    x = np.round(0.01 * np.sin(2 * np.pi * 1.3 * t) / counts) * counts
    return t, x


def test_backward_differences_lag_half_a_sample_and_are_advanced_by_it():
    t, x = _counts(counts=1e-8)   # a 10 nm encoder: the acceleration's lag reads true
    v = np.concatenate([[0.0], np.diff(x) / np.diff(t)])
    a = np.concatenate([[0.0], np.diff(v) / np.diff(t)])   # differentiated again: 1 sample
    data = Dataset.from_arrays(t=t, x=x, v=v, a=a, F=np.sin(t))
    assert velocity_lag(data) == pytest.approx(0.5, abs=0.05)
    moved, d = align_motion(data)
    assert d == pytest.approx(0.5, abs=0.05)
    # the moved velocity is the central difference of the counts, and lags nothing
    assert velocity_lag(moved) == pytest.approx(0.0, abs=0.05)
    assert np.allclose(moved.v[5:-5], np.gradient(x, t)[5:-5], atol=1e-3 * np.ptp(v))
    # the acceleration differentiated from the lagging velocity is moved with it
    assert channel_lag(moved.v, data.a, t) == pytest.approx(1.0, abs=0.1)
    assert abs(channel_lag(moved.v, moved.a, t)) < 0.1
    assert any(f"advanced by {d:.2f} samples" in n for n in moved.notes)
    # the force and the position are never moved
    assert np.array_equal(moved.F, data.F) and np.array_equal(moved.x, data.x)
    # an acceleration that is the central differences of the velocity is taken again
    grad = Dataset.from_arrays(t=t, x=x, v=v, a=np.gradient(v, t), F=np.sin(t))
    assert np.array_equal(align_motion(grad)[0].a, np.gradient(moved.v, t))


def test_channels_without_a_lag_or_derived_from_each_other_are_left_as_they_are():
    t, x = _counts()
    central = Dataset.from_arrays(t=t, x=x, v=np.gradient(x, t), F=np.sin(t))
    assert align_motion(central) == (central, 0.0)
    derived = Dataset.from_arrays(t=t, x=x, F=np.sin(t))        # v derived from x
    assert align_motion(derived, 0.5) == (derived, 0.0)
    # a lag below the threshold is what quantisation alone reads: not moved
    v = np.concatenate([[0.0], np.diff(x) / np.diff(t)])
    data = Dataset.from_arrays(t=t, x=x, v=v, F=np.sin(t))
    assert align_motion(data, 0.5 * MIN_ALIGN_SAMPLES)[1] == 0.0


@pytest.mark.slow  # about 50 s (two full diagnoses); the lag itself is tested above
def test_xml350_clean_record_differentiated_backward_fits_as_central_differences_do():
    # the XML-350's stiff presliding: with backward differences the base missed the
    # held-out force by 4.6 x the noise floor (central differences of the same counts:
    # 1.9 x); advanced by its measured lag the record is the central one's
    from diagnosis.benchmark.cases import make_plant_case
    reps = {}
    for velocity in ("backward", "gradient"):
        case = make_plant_case("xml350", "clean", 1.0, 0.01, seed=1, quick=True,
                               measured={"counts": 200.0, "velocity": velocity})
        reps[velocity] = diagnose(case.data, case.base, seed=0, candidates=["delay"])
    back, cent = reps["backward"], reps["gradient"]
    assert back["velocity_alignment"]["applied"]
    assert back["velocity_alignment"]["lag_samples"] == pytest.approx(0.5, abs=0.05)
    assert not cent["velocity_alignment"]["applied"]
    assert back["baseline"]["validation"] == pytest.approx(cent["baseline"]["validation"],
                                                          rel=0.02)
    assert back["baseline"]["validation"] < 2.0 * back["noise_floor"]


def test_channels_that_disagree_in_scale_have_no_lag_to_move():
    # Franka case 4: the time column runs twice as long as the velocity implies, so the
    # position's derivative is half the velocity and their difference no lag
    from friction.alignment import velocity_scale
    t, x = _counts(counts=1e-8)
    v = np.concatenate([[0.0], np.diff(x) / np.diff(t)])
    data = Dataset.from_arrays(t=2.0 * t, x=x, v=v, F=np.sin(t))
    assert velocity_scale(data) == pytest.approx(0.5, rel=1e-3)
    assert velocity_lag(data) == 0.0
    assert align_motion(data) == (data, 0.0)
    ok = Dataset.from_arrays(t=t, x=x, v=v, F=np.sin(t))
    assert velocity_scale(ok) == pytest.approx(1.0, abs=1e-3)


def test_cli_report_says_the_velocity_was_advanced(tmp_path):
    # a user's CSV whose velocity column is the backward differences of the position
    import json
    from dataclasses import replace
    from diagnosis.benchmark import make_case
    from frictionlab.cli import main
    data = make_case("clean", 1.0, 0.02, n=4000, seed=2)
    v = np.concatenate([[data.v[0]], np.diff(data.x) / np.diff(data.t)])
    p = tmp_path / "run.csv"
    replace(data, v=v).to_csv(p)
    assert main(["diagnose", str(p), "--model", "lugre", "--candidates", "delay", "--json",
                 str(tmp_path / "d.json"), "--html", str(tmp_path / "d.html"), "--quiet"]) == 0
    va = json.loads((tmp_path / "d.json").read_text())["velocity_alignment"]
    assert va["applied"] and va["lag_samples"] == pytest.approx(0.5, abs=0.05)
    assert va["velocity_scale"] == pytest.approx(1.0, abs=0.01)
    assert "advanced by that much" in (tmp_path / "d.html").read_text()


def test_identify_fits_the_law_diagnose_fits_on_a_backward_differenced_record():
    # the two commands agree on the base: identify advances the velocity as diagnose does,
    # so a record differentiated backward gives the law the central differences give
    from friction import make_model
    from identification import identify
    from diagnosis.benchmark.cases import make_plant_case
    fits = {}
    for velocity in ("backward", "gradient"):
        case = make_plant_case("xml350", "clean", 1.0, 0.01, seed=1, quick=True,
                               measured={"counts": 200.0, "velocity": velocity})
        fit, _ = case.data.split(0.7)
        fits[velocity] = identify(fit, case.base, names=["sigma0", "sigma1", "sigma2", "Fc",
                                                         "Fs", "vs", "b"], seed=0)
    back, cent = fits["backward"], fits["gradient"]
    assert back.fit_nrmse == pytest.approx(cent.fit_nrmse, rel=0.02)
    assert any("velocity advanced by" in n for n in back.identifiability["notes"])
    assert not any("velocity advanced by" in n for n in cent.identifiability["notes"])
    assert "velocity advanced by" in back.summary()


def test_a_record_is_moved_once():
    # a velocity filtered rather than delayed reads a lag again after a move (Franka case
    # 3: 0.45, 0.39, 0.31 samples); diagnose moves it, and the identify inside it must not
    t, x = _counts(counts=1e-8)
    v = np.concatenate([[0.0], np.diff(x) / np.diff(t)])
    data = Dataset.from_arrays(t=t, x=x, v=v, F=np.sin(t))
    once, d = align_motion(data)
    assert d > 0.4
    assert align_motion(once) == (once, 0.0)
    assert align_motion(once, 0.5) == (once, 0.0)


def test_an_unevenly_sampled_record_has_no_lag_in_samples():
    rng = np.random.default_rng(0)
    t = np.cumsum(np.r_[0.0, rng.uniform(0.5e-3, 1.5e-3, 1999)])
    x = 0.01 * np.sin(2 * np.pi * t)
    v = np.concatenate([[0.0], np.diff(x) / np.diff(t)])
    data = Dataset.from_arrays(t=t, x=x, v=v, F=np.sin(t))
    assert velocity_lag(data) == 0.0
    assert align_motion(data) == (data, 0.0)
    # an impossible lag given by hand moves nothing
    even = Dataset.from_arrays(t=np.arange(2000) * 1e-3, x=x, v=v, F=np.sin(t))
    assert align_motion(even, float("nan")) == (even, 0.0)
