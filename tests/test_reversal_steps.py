"""A sample added at each velocity reversal inside a step (friction.steps.split_at_reversals)
and the diagnosis's simulation on it (diagnosis.composite.simulate_split): checked against
the same law integrated 20 x finer (the reference), on a stiff contact sampled at 1 kHz."""
import numpy as np
import pytest

from diagnosis.composite import simulate_split
from friction import make_model
from friction.steps import split_at_reversals


def test_reversal_samples_sit_where_the_linear_velocity_crosses_zero():
    t = np.arange(6.0)
    v = np.array([1.0, -1.0, -2.0, 3.0, 3.0, -1.0])
    x = 10.0 * t
    tt, vv, (xx, empty), idx = split_at_reversals(t, v, x, np.zeros(0))
    np.testing.assert_array_equal(tt, [0, 0.5, 1, 2, 2.4, 3, 4, 4.75, 5])
    np.testing.assert_array_equal(vv, [1, 0, -1, -2, 0, 3, 3, 0, -1])
    np.testing.assert_allclose(xx, 10.0 * tt)  # linear channels are interpolated
    assert empty.size == 0
    np.testing.assert_array_equal(tt[idx], t)
    np.testing.assert_array_equal(vv[idx], v)


def test_a_record_without_reversal_is_returned_as_it_is():
    t = np.linspace(0.0, 1.0, 11)
    v = np.abs(np.sin(3 * t)) + 0.1
    tt, vv, chans, idx = split_at_reversals(t, v, 2 * t)
    assert idx is None and tt is t and vv is v
    np.testing.assert_array_equal(chans[0], 2 * t)
    # a sign change onto a sample (v = 0 there) needs no sample either
    v0 = np.array([1.0, 0.0, -1.0])
    assert split_at_reversals(np.arange(3.0), v0)[3] is None


@pytest.fixture(scope="module")
def stiff():
    law = make_model("lugre", sigma0=1.1e7, sigma1=1460.0, sigma2=15.6, Fc=0.95, Fs=1.1,
                     vs=1e-5, shape="lorentzian")
    dt, m = 1e-3, 20
    tf = np.arange(0, 2000 * m + 1) * (dt / m)
    vf = 0.014 * np.sin(2 * np.pi * 3.0 * tf + 0.3) + 0.004 * np.sin(2 * np.pi * 7.3 * tf)
    ref = law.simulate(tf, vf)[::m]   # the reference: 20 x finer
    return law, tf[::m], vf[::m], ref


def test_the_split_simulation_is_near_the_fine_reference_on_a_stiff_contact(stiff):
    law, t, v, ref = stiff
    sd = np.std(ref)
    err_plain = np.sqrt(np.mean((law.simulate(t, v) - ref) ** 2)) / sd
    err_split = np.sqrt(np.mean((simulate_split(law, t, v, {}, np.zeros(1)) - ref) ** 2)) / sd
    assert err_plain > 0.01          # the mean velocity of a reversing step: about 1-2 %
    assert err_split < 0.25 * err_plain
    assert err_split < 0.005


def test_the_split_simulation_with_levels_equals_the_level_one_at_level_one(stiff):
    law, t, v, _ = stiff
    a = simulate_split(law, t, v, {}, np.zeros(1))
    b = simulate_split(law, t, v, {}, np.zeros(1), level=np.ones(t.size))
    np.testing.assert_allclose(b, a, rtol=1e-12, atol=1e-12)
