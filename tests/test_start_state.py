"""A record that starts in motion starts the law from its steady state (issue 15, item 5).

``FrictionModel.steady_state_state`` (one definition in ``friction/base.py``, overridden only
by the modified LuGre whose switch can freeze the bristle) and ``simulate(state0="steady")``;
``identify``'s validation scores a held-out record from that state. The real proof is the
rack-and-pinion stroke split in time (Mnich, Lodz University of Technology,
KonradMnich/friction-identification @ 8b477df1): its held-out part starts at 0.40 m/s, and
from an undeflected bristle the fitted LuGre spiked by about 760 N (sigma1 v), a held-out
NRMSE of 5.4.
"""
import subprocess
import sys

import numpy as np
import pytest

from friction import MODELS, make_model
from friction.dataset import Dataset
from identification import identify

#: a constant-speed record of each law: speed [m/s] and the extra inputs it needs
_SPEED = {"load_lugre": 1e-3}


def _record(name, v0, n=200, h=5e-5):
    t = np.arange(n) * h
    v = np.full(n, v0)
    kw = {}
    if name == "load_lugre":
        kw["load"] = np.full(n, 1e5)
    if name == "mre_lugre":
        kw["x"] = np.zeros(n)  # a still spring: the force is the hysteretic part only
    if name == "modified_lugre":
        kw["a"] = np.zeros(n)  # constant speed
    return t, v, kw


@pytest.mark.parametrize("name", sorted(MODELS))
@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_steady_start_gives_the_steady_state_force_from_the_first_sample(name, sign):
    m = make_model(name)
    v0 = sign * _SPEED.get(name, 0.05)
    t, v, kw = _record(name, v0)
    F = m.simulate(t, v, state0="steady", **kw)
    ss_kw = {k: arr[:1] for k, arr in kw.items()}
    Fss = float(m.steady_state([v0], **ss_kw)[0])
    np.testing.assert_allclose(F, Fss, rtol=1e-9, atol=1e-9 * abs(Fss))
    s0 = m.steady_state_state(v0, **{k: float(arr[0]) for k, arr in kw.items()})
    assert s0.shape == (len(m.state_names),)
    if m.state_names:
        # the state is an equilibrium of the law's own equations
        d = m.derivatives(s0, v0, **{k: float(arr[0]) for k, arr in kw.items()})
        assert np.all(np.abs(d) <= 1e-9 * abs(v0))
        # and from rest the same record starts with a transient
        assert abs(m.simulate(t, v, **kw)[0] - Fss) > 1e-3 * abs(Fss)


def test_lugre_steady_state_is_g_over_sigma0_and_rest_stays_rest():
    m = make_model("lugre", sigma0=1e5, Fc=1.0, Fs=1.5, vs=1e-3, Fc_neg=2.0, Fs_neg=2.5)
    assert m.steady_state_state(1e-3)[0] == pytest.approx(float(m.g(1e-3)) / 1e5, rel=1e-12)
    assert m.steady_state_state(-1e-3)[0] == pytest.approx(-float(m.g(-1e-3)) / 1e5, rel=1e-12)
    assert np.all(m.steady_state_state(0.0) == 0.0)
    t = np.linspace(0.0, 0.1, 11)
    # a record that starts at rest: the steady start is the rest state
    np.testing.assert_array_equal(m.simulate(t, np.sin(t), state0="steady"),
                                  m.simulate(t, np.sin(t)))
    with pytest.raises(ValueError, match="steady"):
        m.simulate(t, t, state0="settled")


def test_modified_lugre_beyond_its_switch_still_starts_saturated():
    # the cosine switch is exactly 0 beyond v2: the bristle rate vanishes there, yet the
    # state the law heads to is g / sigma0, and the lag state follows the acceleration
    m = make_model("modified_lugre", gamma_form="cosine", v1=0.1, v2=0.2)
    s = m.steady_state_state(0.5, a=2.0)
    assert s[0] == pytest.approx(float(m.g(0.5)) / m.params.sigma0, rel=1e-12)
    assert s[1] == pytest.approx(float(m.fd_steady(0.5, 2.0)), rel=1e-12)
    filt = m.with_values(fd_form="filtered_acceleration")
    assert filt.steady_state_state(0.5, a=2.0)[1] == 2.0


@pytest.fixture(scope="module")
def rack_pinion_split():
    from conftest import REAL
    if not REAL.exists():
        pytest.skip(f"shared real data not found at {REAL}")
    from identification.real_data import load_rack_pinion
    d = load_rack_pinion()
    return d.split(0.7)


def test_rack_pinion_held_out_part_scored_without_the_start_spike(rack_pinion_split):
    fit, held = rack_pinion_split
    assert held.v[0] > 0.35  # the held-out part starts in motion
    r = identify(fit, "lugre", validation=held)
    m = r.model
    spike = held.F[0] - m.simulate(held.t, held.v)[0]          # from rest: the spike
    start = held.F[0] - m.simulate(held.t, held.v, state0="steady")[0]
    assert abs(spike) > 500.0 and abs(start) < 0.1 * abs(spike)
    # the validation score is the steady start's (it was 5.4 from rest)
    P = m.simulate(held.t, held.v, state0="steady")
    assert r.validation_nrmse == pytest.approx(
        np.sqrt(np.mean((held.F - P) ** 2)) / np.std(held.F), rel=1e-6)
    assert r.validation_nrmse < 1.0


def _short_csv(tmp_path, n):
    t = np.arange(n) * 1e-3
    v = 0.01 * np.sin(40 * t) + 0.02
    d = Dataset.from_arrays(t, 0.5 * np.sign(v) + 0.1 * v + 0.01 * np.cos(7 * t), v=v,
                            name="short")
    path = tmp_path / f"short{n}.csv"
    d.to_csv(path)
    return path


def test_identify_refuses_a_held_out_file_too_short_to_score(tmp_path):
    fit = _short_csv(tmp_path, 400)
    short = _short_csv(tmp_path, 6)
    with pytest.raises(ValueError, match="too short to score"):
        identify(str(fit), "stribeck", validation=str(short), max_evals=50)
    out = subprocess.run([sys.executable, "-m", "frictionlab.cli", "identify", str(fit),
                          str(short), "--model", "stribeck", "--quiet"],
                         capture_output=True, text=True, timeout=300)
    assert out.returncode != 0
    assert "too short to score" in out.stderr
    assert "Traceback" not in out.stderr and len(out.stderr.strip().splitlines()) == 1
