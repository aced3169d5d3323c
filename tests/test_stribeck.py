"""Static Stribeck map: the analytic curve, the LuGre steady state, reference, bad input."""
import numpy as np
import pytest

from friction import ParameterError, make_model
from friction.reference import simulate_mass, simulate_prescribed

ASYM = dict(Fc=1.0, Fs=1.5, vs=1e-3, sigma2=0.4, Fc_neg=0.7, Fs_neg=1.2, vs_neg=2e-3,
            sigma2_neg=0.9, b=0.05)


@pytest.mark.parametrize("shape", ["gaussian", "lorentzian"])
def test_constant_velocity_is_steady_state_and_the_formula(shape):
    m = make_model("stribeck", shape=shape, alpha=1.3, **ASYM)
    for vc in (-0.3, -2e-3, -1e-4, 1e-4, 1e-3, 0.02):
        t = np.linspace(0, 0.1, 50)
        F = m.simulate(t, np.full(t.size, vc))
        Fss = m.steady_state(np.array([vc]))[0]
        assert np.max(np.abs(F - Fss)) <= 1e-9 * abs(Fss)
        # the formula written out independently of the package
        d = "_neg" if vc < 0 else ""
        p = m.params
        Fc, Fs, vs, s2 = (getattr(p, n + d) for n in ("Fc", "Fs", "vs", "sigma2"))
        r = abs(vc) / vs
        e = 1 / (1 + r * r) if shape == "lorentzian" else np.exp(-r ** 1.3)
        expected = (Fc + (Fs - Fc) * e) * np.sign(vc) + s2 * vc + p.b
        assert Fss == pytest.approx(expected, rel=1e-12)


def test_same_curve_as_lugre_steady_state():
    s = make_model("stribeck", **ASYM)
    lg = make_model("lugre", **ASYM)
    v = np.linspace(-0.05, 0.05, 1001)
    np.testing.assert_allclose(s.steady_state(v), lg.steady_state(v), rtol=1e-13, atol=0)
    # and the LuGre simulation at constant speed ends on it
    for vc in (-0.01, 0.004):
        t = np.linspace(0, 40 * 1.5 / (1e5 * abs(vc)), 3000)
        F = lg.simulate(t, np.full(t.size, vc))
        assert F[-1] == pytest.approx(s.simulate(t[:2], np.full(2, vc))[0], rel=1e-9)


def test_sign_convention_and_limits():
    m = make_model("stribeck", **ASYM)
    F = m.simulate(np.array([0.0, 1.0, 2.0]), np.array([0.0, 1e-9, -1e-9]))
    assert F[0] == pytest.approx(0.05)           # sgn(0) = 0: only the offset
    assert F[1] == pytest.approx(1.5 + 0.05, rel=1e-6)   # break-away level Fs (+)
    assert F[2] == pytest.approx(-1.2 + 0.05, rel=1e-6)  # break-away level Fs_neg (-)
    big = m.steady_state(np.array([1.0, -1.0]))
    np.testing.assert_allclose(big, [1.0 + 0.4 + 0.05, -0.7 - 0.9 + 0.05], rtol=1e-12)


def test_reference_integrator_handles_the_stateless_law():
    m = make_model("stribeck", **ASYM)
    t = np.linspace(0, 1, 201)
    v = 3e-3 * np.sin(2 * np.pi * 2 * t)
    np.testing.assert_allclose(simulate_prescribed(m, t, v), m.simulate(t, v), rtol=1e-14)
    # mass pushed by a constant force: m dv/dt = u - Fc - sigma2 v (Fc = Fs), exponential
    mm = make_model("stribeck", Fc=1.0, Fs=1.0, sigma2=2.0)
    mass, u, v0 = 0.5, 3.0, 1e-6
    out = simulate_mass(mm, mass, np.linspace(0, 1, 201), lambda tq: u, v0=v0)
    vinf = (u - 1.0) / 2.0
    vex = vinf + (v0 - vinf) * np.exp(-2.0 * out["t"] / mass)
    np.testing.assert_allclose(out["v"], vex, rtol=0, atol=1e-8)
    np.testing.assert_allclose(out["F"], 1.0 + 2.0 * out["v"], rtol=1e-12)


def test_population_matches_single_runs():
    m = make_model("stribeck")
    t = np.linspace(0, 0.5, 1001)
    v = 4e-3 * np.sin(2 * np.pi * 3 * t)
    X = np.array([[1.0, 0.4], [0.6, 2.0], [2.0, 0.0]])
    P = m.simulate_population(t, v, ["Fc", "sigma2"], X)
    for i, row in enumerate(X):
        ref = m.with_values(Fc=row[0], sigma2=row[1]).simulate(t, v)
        np.testing.assert_allclose(P[i], ref, rtol=0, atol=1e-13)
    # symmetric law: a "+" value in the population also sets its unset twin
    Fneg = m.simulate_population(t, -np.abs(v) - 1e-3, ["Fc"], [[0.3]])[0]
    assert np.all(Fneg < -0.29)


@pytest.mark.parametrize("bad, name", [({"vs": 0.0}, "vs"), ({"Fs": -1.0}, "Fs"),
                                       ({"Fc_neg": 0.0}, "Fc_neg"), ({"sigma2": -0.1}, "sigma2"),
                                       ({"alpha": 0.0}, "alpha"), ({"shape": "cubic"}, "shape")])
def test_impossible_parameters_name_the_bound(bad, name):
    with pytest.raises(ParameterError, match=name):
        make_model("stribeck", **bad)


def test_bad_signals():
    m = make_model("stribeck")
    t = np.linspace(0, 1, 10)
    v = np.zeros(10)
    v[4] = np.inf
    with pytest.raises(ValueError, match=r"v\[4\]"):
        m.simulate(t, v)
    with pytest.raises(ValueError, match="strictly increasing"):
        m.simulate(np.r_[t[:5], t[:5]], np.zeros(10))
    with pytest.raises(ValueError, match="length mismatch"):
        m.simulate(t, np.zeros(11))
