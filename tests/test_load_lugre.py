"""Load-dependent LuGre of the forging press (seed 004): Eq. (13), steady state, reference."""
import functools

import numpy as np
import pytest

from friction import ParameterError, make_model
from friction.load_lugre import TABLE2_SI, critical_velocity, regime_condition
from friction.reference import simulate_prescribed


def test_table2_critical_velocity_is_019_mm_per_s():
    p = TABLE2_SI
    vc = critical_velocity(p["Fc0"], p["Fs0"], p["vs"], p["sigma20"])
    assert vc == pytest.approx(0.19e-3, rel=0.01)        # printed, two digits
    assert vc == pytest.approx(0.1918e-3, rel=5e-3)      # EQUATIONS.md C, V-NUM
    # it solves Eq. (13) ...
    lhs = 2 * vc * (p["Fs0"] - p["Fc0"]) * np.exp(-(vc / p["vs"]) ** 2)
    assert lhs == pytest.approx(p["sigma20"] * p["vs"] ** 2, rel=1e-10)
    # ... and is the minimum of the no-load steady-state curve (Eq. 8), F_min = 207.3 kN
    m = make_model("load_lugre")
    assert m.vc == vc
    v = np.linspace(1e-6, 2e-3, 400001)
    F = m.steady_state(v)
    assert v[np.argmin(F)] == pytest.approx(vc, abs=2 * (v[1] - v[0]))
    assert F.min() == pytest.approx(207.3e3, rel=1e-3)


def test_critical_velocity_edge_cases():
    assert np.isnan(critical_velocity(2.0, 1.0, 1e-3, 10.0))       # no Stribeck dip
    assert np.isnan(critical_velocity(1.0, 1.001, 1e-3, 1e3))      # viscous term hides it
    assert critical_velocity(1.0, 2.0, 1e-3, 0.0) == np.inf
    with pytest.raises(ParameterError, match="vs"):
        critical_velocity(1.0, 2.0, 0.0, 1.0)


@pytest.mark.parametrize("speed", [-5e-4, -3e-5, 2e-5, 1.5e-4, 4e-4, 1.2e-3])
@pytest.mark.parametrize("load", [0.0, 5e3, 2e5])
def test_constant_velocity_under_constant_load_reaches_steady_state(speed, load):
    m = make_model("load_lugre")
    g = float(m.g(speed, load))
    T = 40 * g / (m.params.sigma0 * abs(speed))  # 40 bristle time constants
    t = np.linspace(0.0, T, 4001)
    F = m.simulate(t, np.full(t.size, speed), load=np.full(t.size, load))
    Fss = m.steady_state(np.array([speed]), load=np.array([load]))[0]
    assert abs(F[-1] - Fss) <= 1e-9 * abs(Fss)


def test_load_coefficients_follow_table3_per_regime():
    m = make_model("load_lugre")
    p = m.params
    L = 1e4
    for speed, (k1, k2, k3) in ((0.5 * m.vc, (-0.87, 0.33, 40.0)),
                                (3.0 * m.vc, (103.95, 102.88, 319.91e3))):
        xi = np.exp(-(speed / p.vs) ** 2)
        dF = m.steady_state([speed], load=[L])[0] - m.steady_state([speed])[0]
        # Eq. (18) row: dF/dF_sigma = k1 (1 - xi) + k2 xi + k3 v
        assert dF / L == pytest.approx(k1 * (1 - xi) + k2 * xi + k3 * speed, rel=1e-9)
    # SI conversion of Table 2 / Table 3
    assert (p.Fs0, p.Fc0, p.vs, p.sigma20) == pytest.approx((377.39e3, 203.23e3, 7.6e-5, 1.977e7))
    assert (p.k3_low, p.k3_high) == pytest.approx((40.0, 319910.0))


@functools.lru_cache(maxsize=None)
def _reference(load_amp, crossing):
    m = make_model("load_lugre")
    T = 4.0
    tf = np.linspace(0.0, T, 4097)
    vf, lf = _profile(m, tf, load_amp, crossing)
    return m, tf, simulate_prescribed(m, tf, vf, load=lf)


def _profile(m, t, load_amp, crossing):
    T = 4.0
    if crossing:   # 0 .. 2 vc: crosses the regime split
        v = m.vc * (1.0 - np.cos(2 * np.pi * t / T))
    else:          # stays in the low regime, 0.1 .. 0.7 vc
        v = m.vc * (0.4 - 0.3 * np.cos(2 * np.pi * t / T))
    return v, load_amp * (0.5 + 0.5 * np.sin(2 * np.pi * t / T))


def _conv(load_amp, crossing, method="exact", ns=(129, 257, 513)):
    m, tf, Fr = _reference(load_amp, crossing)
    errs = []
    for n in ns:
        t = np.linspace(0.0, tf[-1], n)
        v, load = _profile(m, t, load_amp, crossing)
        F = m.simulate(t, v, load=load, method=method)
        errs.append(np.sqrt(np.mean((F - np.interp(t, tf, Fr)) ** 2)))
    errs = np.array(errs)
    return errs, np.log2(errs[:-1] / errs[1:])


def test_exact_update_converges_second_order_under_varying_load():
    errs, order = _conv(2e5, crossing=False)
    assert errs[-1] < 1e-5 * 2e5
    assert order.min() > 1.8, (errs, order)
    errs, order = _conv(2e5, crossing=False, method="euler")
    assert 0.85 < order.min() and order.max() < 1.3, (errs, order)


def test_converges_across_the_regime_split():
    # the crossings of vc (t = T/4, 3T/4) fall on samples of these grids; the force jumps
    # there under load, so off-grid crossings cannot be compared by interpolating the reference
    errs, order = _conv(1e3, crossing=True)
    assert order.min() > 1.8, (errs, order)


def test_population_matches_single_runs_and_vc_follows_the_no_load_parameters():
    m = make_model("load_lugre")
    t = np.linspace(0.0, 4.0, 2001)
    v = m.vc * (1.0 - np.cos(2 * np.pi * t / 4.0))
    load = np.full(t.size, 1e3)
    X = np.array([[2.0e5, 4.0e5], [1.5e5, 3.5e5], [2.2e5, 2.6e5]])
    P = m.simulate_population(t, v, ["Fc0", "Fs0"], X, load=load)
    for i, row in enumerate(X):
        single = m.with_values(Fc0=row[0], Fs0=row[1])
        assert single.vc != m.vc
        np.testing.assert_allclose(P[i], single.simulate(t, v, load=load), rtol=1e-12, atol=1e-6)
    # inadmissible rows give NaN instead of a silent wrong regime: no Stribeck minimum
    # (Fs0 < Fc0) or a load that drives Fc negative
    P = m.simulate_population(t, v, ["Fs0", "Fc0"], [[1e5, 2e5]], load=load)
    assert np.all(np.isnan(P))
    P = m.simulate_population(t, v, ["k1_low"], [[-1e3]], load=load)
    assert np.isnan(P[0, -1]) and np.isfinite(P[0, 0])


def test_regime_condition_diagnostic_matches_equations_md():
    m = make_model("load_lugre")
    d = m.regime_condition()
    # EQUATIONS.md C: (k2-k1) sigma20 = 23.72 vs k3 (Fs0-Fc0) = 6.97 [kN.s/mm] in the low regime
    assert d["low"]["delta"] == pytest.approx((23.72 - 6.97) * 1e6, rel=2e-3)
    assert d["low"]["literal_low"] is False   # the literal Eq. (12) contradicts Table 3
    assert d["high"]["literal_high"] is False
    # alternative reading: Delta > 0 <=> the loaded critical velocity rises with load
    assert d["low"]["vc_moves"] == "up"
    assert m.loaded_critical_velocity(1e4, "low") > m.vc
    p = m.params
    down = regime_condition(0.5, 0.0, 0.0, p.Fs0, p.Fc0, p.sigma20)
    assert down["vc_moves"] == "down"
    m2 = m.with_values(k1_low=0.5, k2_low=0.0, k3_low=0.0)
    assert m2.loaded_critical_velocity(1e4, "low") < m.vc


def test_explicit_split_velocity_is_used():
    m = make_model("load_lugre", vc=1e-4)
    assert m.vc == 1e-4
    below, above = m.steady_state([0.99e-4, 1.01e-4], load=[1e3, 1e3])
    assert above - below > 0.9 * 1e3 * (103.95 - (-0.87))  # the Fc jump of the regime switch


# -- bad input --------------------------------------------------------------------------------
def test_load_is_required_and_checked():
    m = make_model("load_lugre")
    t = np.linspace(0.0, 1.0, 11)
    v = np.full(11, 1e-4)
    with pytest.raises(ValueError, match="load="):
        m.simulate(t, v)
    load = np.zeros(11)
    load[4] = np.nan
    with pytest.raises(ValueError, match=r"load\[4\]"):
        m.simulate(t, v, load=load)
    with pytest.raises(ValueError, match="length mismatch"):
        m.simulate(t, v, load=np.zeros(10))
    # a load that drives the loaded Coulomb level negative (k1_low = -0.87) is named
    big = np.full(11, 3e5)
    with pytest.raises(ValueError, match=r"load\[0\] = 300000.0 N makes Fc = .*must be Fc > 0"):
        m.simulate(t, v, load=big)
    with pytest.raises(ValueError, match=r"load\[0\]"):
        m.steady_state(np.array([np.nan, 1e-4]) * 0 + 1e-4, load=np.array([np.inf, 0.0]))


@pytest.mark.parametrize("bad, name, bound", [({"sigma0": 0.0}, "sigma0", "sigma0 > 0"),
                                              ({"Fc0": -1.0}, "Fc0", "Fc0 > 0"),
                                              ({"Fs0": 0.0}, "Fs0", "Fs0 > 0"),
                                              ({"vs": -1e-5}, "vs", "vs > 0"),
                                              ({"sigma20": -1.0}, "sigma20", "sigma20 >= 0"),
                                              ({"sigma1": -1.0}, "sigma1", "sigma1 >= 0"),
                                              ({"vc": 0.0}, "vc", "vc > 0")])
def test_impossible_parameters_name_the_bound(bad, name, bound):
    with pytest.raises(ParameterError, match=f"{name} = .* must be {bound}"):
        make_model("load_lugre", **bad)


def test_no_stribeck_minimum_needs_explicit_vc():
    with pytest.raises(ParameterError, match="give the regime-split velocity vc"):
        make_model("load_lugre", Fs0=1.0e5, Fc0=2.0e5)
    m = make_model("load_lugre", Fs0=1.0e5, Fc0=2.0e5, vc=2e-4)
    assert m.vc == 2e-4
