"""Classic LuGre: analytic limits, reference integrator, stability, bad input."""
import numpy as np
import pytest

from friction import ParameterError, make_model
from friction.numerics import euler_critical_velocity
from friction.reference import simulate_prescribed


def test_constant_velocity_reaches_stribeck_curve():
    for shape in ("gaussian", "lorentzian"):
        m = make_model("lugre", shape=shape, Fc_neg=0.8, Fs_neg=1.2, sigma2_neg=0.6, b=0.05)
        for vc in (-0.02, -1e-3, 2e-4, 1e-3, 0.3):
            # 40 bristle time constants g/(sigma0 |v|): e^-40 is below 1e-9
            T = 40 * 1.5 / (m.params.sigma0 * abs(vc))
            t = np.linspace(0, T, 4000)
            F = m.simulate(t, np.full(t.size, vc))
            Fss = m.steady_state(np.array([vc]))[0]
            assert abs(F[-1] - Fss) <= 1e-9 * abs(Fss)


def test_presliding_stiffness_is_sigma0():
    m = make_model("lugre", sigma0=1e6, sigma1=0.0, sigma2=0.0)
    amp = 1e-3 * m.z_max()  # deep inside pre-sliding
    t = np.linspace(0, 1, 20001)
    x = amp * np.sin(2 * np.pi * t)
    v = np.gradient(x, t)
    v = amp * 2 * np.pi * np.cos(2 * np.pi * t)
    F = m.simulate(t, v)
    k = np.polyfit(x, F, 1)[0]
    assert k == pytest.approx(1e6, rel=2e-3)


def test_matches_reference_and_converges_second_order():
    m = make_model("lugre", sigma0=1e5, sigma1=300.0)
    T = 0.1
    errs = []
    # reference once, on a fine grid (its linear interpolation is the 'true' motion)
    tf = np.linspace(0, T, 2401)
    vf = 5e-3 * np.sin(2 * np.pi * 10 * tf)
    Fr = simulate_prescribed(m, tf, vf)
    for n in (76, 151, 301):
        t = np.linspace(0, T, n)
        v = 5e-3 * np.sin(2 * np.pi * 10 * t)
        F = m.simulate(t, v)
        errs.append(np.sqrt(np.mean((F - np.interp(t, tf, Fr)) ** 2)))
    order = np.log2(errs[0] / errs[1]), np.log2(errs[1] / errs[2])
    assert min(order) > 1.6, (errs, order)


def test_euler_oscillates_at_critical_velocity_exact_does_not():
    m = make_model("lugre", sigma0=1e5, sigma1=0.0, sigma2=0.0, Fc=1.0, Fs=1.0)
    h = 5e-5
    vcr = euler_critical_velocity(m, h)
    assert vcr == pytest.approx(1.0 / (1e5 * h), rel=1e-6)
    t = np.arange(400) * h

    def zigzag(speed, method):
        # fraction of the first steps whose error z_k - z_ss changes sign (oscillation)
        _, Z = m.simulate(t, np.full(t.size, speed), method=method, state0=[0.0],
                          return_state=True)
        e = Z[:8, 0] - 1.0 / 1e5
        return np.mean(np.sign(e[1:]) != np.sign(e[:-1]))

    assert zigzag(1.05 * vcr, "euler") > 0.9
    assert zigzag(0.95 * vcr, "euler") == 0
    assert zigzag(1.05 * vcr, "exact") == 0
    _, Z = m.simulate(t, np.full(t.size, 2.2 * vcr), method="euler", return_state=True)
    assert np.abs(Z[-1, 0]) > 1e3 * m.z_max()  # diverges past 2 v_cr
    F = m.simulate(t, np.full(t.size, 2.2 * vcr), method="exact")
    assert np.all(np.isfinite(F))


@pytest.mark.parametrize("bad, name", [({"sigma0": 0.0}, "sigma0"), ({"Fs": -1.0}, "Fs"),
                                       ({"vs": 0.0}, "vs"), ({"sigma1": -1}, "sigma1")])
def test_impossible_parameters_name_the_bound(bad, name):
    with pytest.raises(ParameterError, match=name):
        make_model("lugre", **bad)


def test_bad_signals():
    m = make_model("lugre")
    t = np.linspace(0, 1, 10)
    v = np.zeros(10)
    v[3] = np.nan
    with pytest.raises(ValueError, match=r"v\[3\]"):
        m.simulate(t, v)
    with pytest.raises(ValueError, match="strictly increasing"):
        m.simulate(t[::-1], np.zeros(10))
    with pytest.raises(ValueError, match="length mismatch"):
        m.simulate(t, np.zeros(9))


def test_population_matches_single_runs():
    m = make_model("lugre")
    t = np.linspace(0, 0.5, 2001)
    v = 4e-3 * np.sin(2 * np.pi * 3 * t)
    X = np.array([[1e5, 1.0], [3e5, 0.7], [5e4, 1.3]])
    P = m.simulate_population(t, v, ["sigma0", "Fc"], X)
    for i, row in enumerate(X):
        ref = m.with_values(sigma0=row[0], Fc=row[1]).simulate(t, v)
        np.testing.assert_allclose(P[i], ref, rtol=0, atol=1e-12)
