"""Transfer scoring: held-out records taken at loads the fit record never saw.

The fit record holds the load constant, so no load effect can be identified on it; the
diagnosis calibrates each candidate on one held-out record and scores it on the other. It must
name ``load`` when the truth's friction grows with the load, and must *not* name it when the
held-out records differ from the fit record by something else (a direction offset that does
not depend on the load): the transfer protocol may not favour the covariate it was triggered by.
"""
import numpy as np
import pytest

from diagnosis import diagnose
from diagnosis.transfer import transfer_applicable
from friction import make_model
from friction.dataset import Dataset

LAW = dict(sigma0=2e4, sigma1=150.0, sigma2=8.0, Fc=2.0, Fs=2.8, vs=5e-3)
L_FIT = 50.0  # pressure load of the fit record [N]


def _record(load, truth, seed, name, T=12.0, dt=2e-3, noise=0.02):
    """A stroke record at constant load ``load`` [N] (a little ripple, as a regulated pressure
    has), with friction ``truth(law_force, v, load)`` and white noise."""
    t = np.arange(0.0, T, dt)
    rng = np.random.default_rng(seed)
    f = 0.35 + 0.1 * seed  # a different stroke frequency per record [Hz]
    x = 0.02 * np.sin(2 * np.pi * f * t)
    v = 0.02 * 2 * np.pi * f * np.cos(2 * np.pi * f * t)
    a = -0.02 * (2 * np.pi * f) ** 2 * np.sin(2 * np.pi * f * t)
    L = load * (1.0 + 0.02 * np.sin(2 * np.pi * f * t + 0.3))
    F0 = make_model("lugre", **LAW).simulate(t, v)
    F = truth(F0, v, L)
    F = F + noise * np.std(F) * rng.standard_normal(t.size)
    return Dataset.from_arrays(t, F, x=x, v=v, a=a, load=L, name=name, check_units=False)


def _load_truth(F0, v, L):
    # seal friction growing with the pressure load, more in the pressurised direction
    # (sublinear, unlike the candidate's affine form)
    g = np.sqrt(L / L_FIT)
    return F0 * np.where(v > 0, g, 0.5 + 0.5 * g)


def _offset_truth(F0, v, L):
    # the held-out strokes carry a direction offset that has nothing to do with the load
    return F0 + np.where(L > 2 * L_FIT, 0.6, 0.0) + np.where(v < 0, -0.4, 0.0) * (L > 2 * L_FIT)


@pytest.fixture(scope="module")
def load_report():
    fit = _record(L_FIT, _load_truth, 1, "1 bar")
    held = [_record(5 * L_FIT, _load_truth, 2, "5 bar"), _record(7 * L_FIT, _load_truth, 3, "7 bar")]
    return diagnose(fit, "lugre", validation=held,
                    candidates=["load", "asymmetry", "drift", "acceleration"])


def test_transfer_applies_only_to_records_outside_the_fit_range():
    fit = _record(L_FIT, _load_truth, 1, "fit")
    same = [_record(L_FIT, _load_truth, 2, "a"), _record(L_FIT, _load_truth, 3, "b")]
    far = [_record(5 * L_FIT, _load_truth, 2, "a"), _record(7 * L_FIT, _load_truth, 3, "b")]
    from diagnosis.core import extrapolation
    assert not transfer_applicable(same, extrapolation(fit, same))
    assert not transfer_applicable(far[:1], extrapolation(fit, far[:1]))  # one record only
    assert transfer_applicable(far, extrapolation(fit, far))


def test_load_named_by_transfer(load_report):
    rep = load_report
    assert rep["verdict"]["cause"] == "load", rep.summary()
    assert rep["verdict"]["protocol"] == "transfer"
    top = rep["effects"][0]
    assert top["protocol"] == "transfer" and top["gap_closed"] > 0.5
    # each fold is scored on the record it was not calibrated on
    for fold in rep["transfer"]["folds"]:
        assert fold["calibrated_on"] not in fold["scored_on"]
    # the load sensitivity calibrated on either record is positive (friction grows with load)
    for p in rep["effect_details"]["load"]["transfer_params"]:
        assert p["k_L"] > 0


def test_transfer_does_not_favour_load_when_the_change_is_not_load():
    fit = _record(L_FIT, _offset_truth, 1, "1 bar")
    held = [_record(5 * L_FIT, _offset_truth, 2, "5 bar"),
            _record(7 * L_FIT, _offset_truth, 3, "7 bar")]
    rep = diagnose(fit, "lugre", validation=held,
                   candidates=["load", "asymmetry", "drift", "acceleration"])
    assert rep["verdict"]["protocol"] == "transfer"
    assert rep["verdict"]["cause"] == "asymmetry", rep.summary()


def test_held_out_records_without_a_load_column_skip_the_load_candidate():
    from dataclasses import replace
    fit = _record(L_FIT, _load_truth, 1, "fit")
    held = replace(_record(L_FIT, _load_truth, 2, "no load"), load=None)
    rep = diagnose(fit, "lugre", validation=[held], candidates=["load", "asymmetry"])
    assert "no load" in rep["skipped"]["load"] and "load column" in rep["skipped"]["load"]
    assert [e["name"] for e in rep["effects"]] == ["asymmetry"]
