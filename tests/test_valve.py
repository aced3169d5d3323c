"""Valve actuator of seed 000: force table, control, Euler observer (Fig. 10), loops (Figs 5-7)."""
import math

import numpy as np
import pytest

from plants.tables import Table2D, make_fmag_table
from plants.studies.valve import euler_observer, loop_features, loops_at
from plants.valve import (FREQUENCIES, SAMPLE_RATE, ValveActuator, classic_lugre_twin,
                          recover_friction, sine_reference, valve_friction)


def nrmse(a, b):
    return float(np.sqrt(np.mean((a - b) ** 2)) / np.std(b))


@pytest.fixture(scope="module")
def plant():
    return ValveActuator()


def test_fmag_table_nearly_proportional_mild_position_dependence():
    tab = make_fmag_table()
    S = np.linspace(0, 8e-3, 9)
    for i in (0.5, 1.0, 2.0, 4.0):
        ratio = tab(S, i) / i
        assert np.all(np.abs(ratio / 25.0 - 1) < 0.08)          # nearly proportional
        assert np.ptp(ratio) > 0.005 * 25.0                      # but position matters
    assert tab(4e-3, -2.0) == pytest.approx(-tab(4e-3, 2.0))     # bidirectional force
    i = np.array([-3.0, -0.2, 0.0, 1.3, 7.0])
    assert np.allclose(tab.inverse(2e-3, tab(2e-3, i)), i, atol=1e-9)
    # bilinear interpolation is exact on a bilinear function
    x, y = np.array([0.0, 1.0, 3.0]), np.array([-1.0, 2.0])
    t2 = Table2D(x, y, 2 * x[:, None] + 3 * y[None, :] + x[:, None] * y[None, :])
    assert t2(2.0, 0.5) == pytest.approx(2 * 2 + 3 * 0.5 + 2 * 0.5)
    assert t2(10.0, 0.5) == pytest.approx(t2(3.0, 0.5))          # edge value held


def test_table_rejects_bad_grids():
    with pytest.raises(ValueError, match="strictly increasing"):
        Table2D([0, 1, 1], [0, 1], np.zeros((3, 2)))
    with pytest.raises(ValueError, match="shape"):
        Table2D([0, 1], [0, 1], np.zeros((3, 2)))
    with pytest.raises(ValueError, match="not finite"):
        Table2D([0, 1], [0, 1], [[0, np.nan], [0, 0]])


def test_default_friction_is_seed_000_law_with_euler_critical_velocity():
    law = valve_friction()
    assert law.name == "modified_lugre"
    p = law.params
    assert p.Fc / p.sigma0 == pytest.approx(1.235e-5, rel=0.01)   # EQUATIONS.md A.7
    assert p.Fc / (p.sigma0 / SAMPLE_RATE) == pytest.approx(0.247, abs=0.002)


def test_tracking_and_spring_preload(plant):
    res = plant.simulate(0.1)                                      # 10 Hz, 8 mm
    S_ref, _, _ = sine_reference(res["time"], 10.0, 8e-3)
    assert np.max(np.abs(res["x"] - S_ref)) < 2e-4                 # < 2.5 % of the stroke
    assert res["x"].max() == pytest.approx(8e-3, abs=3e-4)
    # at rest on the seat the coil holds the 6 mm spring preload: fmag = k * const
    p = plant.params
    assert float(plant.fmag(0.0, res["i"][0])) == pytest.approx(p.k * p.const, rel=1e-6)


def test_fast_matches_reference(plant):
    ref = plant.simulate(0.01, method="reference", rtol=1e-8)
    fast = plant.simulate(0.01)
    assert nrmse(fast["x"], ref["x"]) < 1e-4
    assert nrmse(fast["F"], ref["F"]) < 5e-3


def test_convergence_with_substep(plant):
    coarse = plant.simulate(0.05)
    fine = plant.simulate(0.05, substep=5e-6)
    finer = plant.simulate(0.05, substep=2.5e-6)
    e1 = nrmse(coarse["x"], finer["x"])
    e2 = nrmse(fine["x"], finer["x"])
    assert e1 < 1e-4 and e2 < e1


def test_euler_observer_oscillates_for_classic_lugre_not_modified(plant):
    """Seed 000 Fig. 10: classic LuGre + explicit Euler at 20 kHz oscillates at 10 Hz / 8 mm."""
    law = plant.friction
    classic = classic_lugre_twin(law)
    t = np.arange(0.0, 0.1, 1.0 / SAMPLE_RATE)
    # 5 Hz, 8 mm: v_max = 0.126 m/s < v_cr: never oscillates
    _, v5, _ = sine_reference(t, 5.0, 8e-3)
    o5 = euler_observer(classic, t, v5)
    assert math.isnan(o5["onset_time"])
    assert np.all(o5["error"][:20] >= 0)                           # error decays, no sign flips
    # 10 Hz, 8 mm: factor turns negative at 0.0225 s, 0.247 m/s (paper's numbers)
    _, v10, a10 = sine_reference(t, 10.0, 8e-3)
    o10 = euler_observer(classic, t, v10)
    assert o10["onset_time"] == pytest.approx(0.0225, abs=6e-4)
    assert o10["onset_speed"] == pytest.approx(0.247, abs=3e-3)
    e = o10["error"][:5]
    assert np.all(np.sign(e[1:]) == -np.sign(e[:-1]))            # flips every sample
    # modified LuGre: Gamma ~ 0 there, the error is frozen (no flip), the observer stays put
    kw = {"a": a10} if "a" in law.extra_inputs else {}
    m10 = euler_observer(law, t, v10, h_inject=t[o10["k0"]], **kw)
    em = m10["error"][:40]
    assert np.all(em > 0) and np.all(np.abs(em) <= abs(em[0]) * 1.0000001)
    assert np.max(np.abs(m10["z"])) < 1.1 * law.params.Fs / law.params.sigma0
    # 20 Hz, 8 mm: above 2 v_cr the error grows (divergence) for the classic update
    _, v20, _ = sine_reference(t, 20.0, 8e-3)
    o20 = euler_observer(classic, t, v20)
    kgrow = int(np.argmax(o20["factor"] < -1.0))
    g20 = euler_observer(classic, t, v20, h_inject=t[kgrow])
    n = int(np.argmax(o20["factor"][kgrow:] > -1.0))
    assert n > 10 and abs(g20["error"][n]) > 1.5 * abs(g20["error"][0])


@pytest.fixture(scope="module")
def loops(plant):
    return loops_at(FREQUENCIES, cycles=1.25, plant=plant)


def test_double_hysteresis_loops(loops):
    """Figs. 5-7: clockwise vertical loop in sliding + counter-clockwise horizontal loop."""
    vert = []
    for f in FREQUENCIES:
        r = loops[f]["rec"]
        fe = loop_features(r["v"], r["F"], acc=r["a"])
        assert fe["vertical"] > 0.0, f                            # more friction accelerating
        assert fe["horizontal"] > 0.0, f                          # force lags the reversal
        vert.append(fe["vertical"])
        # recovery of Eq. (1) from filtered encoder/current signals is close to the truth
        assert np.sqrt(np.mean((r["F"] - loops[f]["true_F"]) ** 2)) < 0.25 * np.ptp(r["F"])
    assert np.all(np.diff(vert[:3]) > 0)                           # grows with frequency


def test_classic_lugre_has_no_vertical_loop():
    plant = ValveActuator(classic_lugre_twin(valve_friction()))
    d = loops_at((10.0,), cycles=1.25, plant=plant)[10.0]
    fe = loop_features(d["rec"]["v"], d["true_F"], acc=d["rec"]["a"])
    fm = loop_features(d["rec"]["v"], d["rec"]["F"], acc=d["rec"]["a"])
    assert abs(fe["vertical"]) < 0.05 and fm["horizontal"] > 0
    # the modified law's vertical loop at 10 Hz is an order of magnitude larger
    dm = loops_at((10.0,), cycles=1.25)[10.0]
    fmod = loop_features(dm["rec"]["v"], dm["true_F"], acc=dm["rec"]["a"])
    assert fmod["vertical"] > 10 * abs(fe["vertical"])


def test_vertical_loop_grows_with_magnitude(plant):
    vals = []
    for M in (2e-3, 8e-3):
        d = loops_at((5.0,), magnitude=M, cycles=1.25, plant=plant)[5.0]
        vals.append(loop_features(d["rec"]["v"], d["rec"]["F"], acc=d["rec"]["a"])["vertical"])
    assert vals[1] > vals[0] > 0


def test_external_friction_stepper_outputs_kinematics():
    ext = ValveActuator(external_friction=True)
    st = ext.stepper()
    assert st.input_names == ("F_friction",)
    assert {"x", "v", "a"} <= set(st.output_names)
    st.set_inputs({"F_friction": 0.0})
    for k in range(40):
        st.do_step(k / SAMPLE_RATE, 1.0 / SAMPLE_RATE)
    out = st.outputs()
    assert out["x"] > 0 and np.isfinite(out["a"])
    with pytest.raises(KeyError):
        st.set_inputs({"nope": 1.0})


def test_recover_friction_rejects_bad_cutoff(plant):
    res = plant.simulate(0.01)
    with pytest.raises(ValueError, match="Nyquist"):
        recover_friction(res, plant, cutoff=20_000.0)


def test_valve_dataset_contract():
    from plants.valve import valve_dataset
    ds = valve_dataset(5.0, cycles=1.25, current_noise=0.005)
    assert ds.t.size == int(round(1.25 / 5.0 * SAMPLE_RATE)) + 1
    err = np.sqrt(np.mean((ds.F - ds.extra["F_true"]) ** 2))
    assert err < 0.05 * np.ptp(ds.extra["F_true"])


@pytest.mark.parametrize("name", ["lugre", "stribeck"])
def test_valve_takes_other_laws(name):
    from friction import make_model
    kw = dict(Fc=6.0, Fs=6.5, vs=5e-3, sigma2=20.0)
    if name == "lugre":
        kw.update(sigma0=4.86e5, sigma1=40.0)
    res = ValveActuator(make_model(name, **kw)).simulate(0.03)
    S_ref, _, _ = sine_reference(res["time"], 10.0, 8e-3)
    assert np.all(np.isfinite(res["F"])) and np.max(np.abs(res["x"] - S_ref)) < 3e-4


def test_steady_state_tests_recover_stribeck_curve(plant):
    """Seed 000 Fig. 9: constant-speed strokes, friction by Eq. (1), on the law's Eq. (5)."""
    from plants.studies.valve import stribeck_points
    pts = stribeck_points([-0.02, -0.005, 0.005, 0.02], plant=plant)
    Fss = plant.friction.steady_state(pts[:, 0])
    assert np.allclose(pts[:, 1], Fss, rtol=2e-3)
    assert pts[3, 1] > pts[2, 1] and pts[0, 1] < 0                   # asymmetric law: +/-
    with pytest.raises(ValueError, match="nonzero"):
        stribeck_points([0.0], plant=plant)
