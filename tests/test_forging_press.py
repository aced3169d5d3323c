"""Forging press of seed 004: Stribeck minimum at vc, crawling below vc, numerics."""
import numpy as np
import pytest

from friction import ParameterError
from plants.forging_press import TABLE1, ForgingPress, schedule_reference, shortened_schedule
from plants.studies.forging_press import crawl_metrics, steady_friction


def nrmse(a, b):
    return float(np.sqrt(np.mean((a - b) ** 2)) / np.std(b))


@pytest.fixture(scope="module")
def press():
    return ForgingPress()


@pytest.fixture(scope="module")
def schedule_run(press):
    return press.simulate()            # shortened Table 1 schedule with the workpiece


def test_table1_schedule_reductions():
    x, v = schedule_reference(np.array([50.0, 290.0, 370.0, 1370.0]), TABLE1)
    assert np.allclose(x * 1e3, [60.0, 84.0, 88.0, 90.0])          # 60 / 24 / 4 / 2 mm
    assert shortened_schedule(0.1)[0] == (1.2e-3, 5.0)


def test_steady_curve_minimum_at_vc(press):
    law = press.friction
    v = np.logspace(-6, -2.5, 4000)
    kw = {"load": np.zeros_like(v)} if "load" in law.extra_inputs else {}
    Fss = law.steady_state(v, **kw)
    assert v[np.argmin(Fss)] * 1e3 == pytest.approx(0.19, abs=0.005)   # Table 2: vc = 0.19 mm/s
    # the plant's friction "measured" by Eq. 1 in no-load constant-speed tests sits on it
    meas = steady_friction(press, (0.3e-3, 1.2e-3), duration=3.0)
    kw = {"load": np.zeros(2)} if "load" in law.extra_inputs else {}
    assert np.allclose(meas[:, 1], law.steady_state(meas[:, 0], **kw), rtol=5e-3)
    assert meas[1, 1] > meas[0, 1]                                  # rising branch above vc


def test_crawls_below_vc_smooth_above_in_the_schedule(schedule_run):
    """Table 1 schedule: 1.2 mm/s (> vc) smooth; 0.05 and 0.002 mm/s (< vc) crawl."""
    r = schedule_run
    fast = crawl_metrics(r, t_from=4.0, t_to=6.0)
    assert not fast["crawling"] and fast["intermittency"] == 0.0 and fast["cv"] < 0.1
    step3 = crawl_metrics(r, t_from=12.0, t_to=16.0)
    assert step3["crawling"] and step3["slips"] >= 2
    step4 = crawl_metrics(r, t_from=18.0, t_to=41.0)                 # 0.002 mm/s
    assert step4["crawling"] and step4["peak_ratio"] > 100
    assert r["F_sigma"].max() > 5e5                                  # the workpiece was forged


def test_crawl_band_without_load(press):
    """No-load constant speed: the Stribeck drop destabilises sliding below vc only."""
    slow = press.simulate(6.0, schedule=((0.05e-3, 7.0),), workpiece=False)
    above = press.simulate(3.0, schedule=((0.3e-3, 4.0),), workpiece=False)
    assert crawl_metrics(slow, t_from=2.0)["crawling"]
    ma = crawl_metrics(above, t_from=2.0)
    assert not ma["crawling"] and ma["cv"] < 0.05


def test_fast_matches_reference_and_converges(press):
    ref = press.simulate(0.3, method="reference", rtol=1e-7, workpiece=False)
    fast = press.simulate(0.3, workpiece=False)
    fine = press.simulate(0.3, substep=5e-5, workpiece=False)
    e_fast, e_fine = nrmse(fast["x"], ref["x"]), nrmse(fine["x"], ref["x"])
    assert e_fast < 1e-5 and e_fine < e_fast / 5                    # second order in the step
    assert nrmse(fast["F"], ref["F"]) < 1e-4


def test_schedule_with_load_converges_in_substep(press):
    sched = ((1.2e-3, 3.0),)
    a = press.simulate(2.0, schedule=sched)
    b = press.simulate(2.0, schedule=sched, substep=1.25e-4)
    assert nrmse(a["x"], b["x"]) < 1e-4 and nrmse(a["F_sigma"], b["F_sigma"]) < 1e-3


def test_default_friction_and_bad_input(press):
    assert press.friction.name == "load_lugre"
    with pytest.raises(ParameterError, match="A1"):
        ForgingPress(A1=-1.0)
    with pytest.raises(ValueError, match="crushed"):   # a soft, thin workpiece
        ForgingPress(H0=0.01, sigma_ref=1e5).simulate(12.0, schedule=((1.2e-3, 12.0),))
    with pytest.raises(ValueError, match="positive constant speed"):
        crawl_metrics(press.simulate(0.2, schedule=((0.0, 1.0),)))


def test_hydraulic_components():
    from plants.hydraulics import HydraulicChamber, ServoValve
    from plants.interfaces import HydraulicPort
    sv = ServoValve()
    dp = np.array([0.7e6, 2e6, 10e6, 20e6])                          # > 7 dp_lam
    reg = sv.flow(1e-3, sv.ps - dp)
    assert np.allclose(reg, sv.turbulent_flow(1e-3, dp), rtol=0.01)   # turbulent law
    small = sv.flow(1e-3, sv.ps - np.array([1e3, 2e3]))
    assert small[1] == pytest.approx(2 * small[0], rel=1e-3)          # laminar near dp = 0
    assert sv.flow(-1e-3, sv.pt) == 0.0 and sv.flow(-1e-3, 5e6) < 0   # drains to tank
    ch = HydraulicChamber(A=0.5, V0=0.2, beta_e=1e9)
    assert ch.dpdt(HydraulicPort(p=1e6, q=1e-3), 0.1, 0.0) == pytest.approx(1e9 / 0.25 * 1e-3)
    assert ch.dpdt(HydraulicPort(p=1e6, q=0.0), 0.1, 2e-3) == pytest.approx(-1e9 / 0.25 * 1e-3)
    assert ch.hydraulic_stiffness(0.0) == pytest.approx(1e9 * 0.25 / 0.2)
    with pytest.raises(ValueError, match="volume"):
        ch.volume(-1.0)
    with pytest.raises(ParameterError, match="pt"):
        ServoValve(ps=1e6, pt=2e6)


@pytest.mark.slow
def test_crawl_at_0p002_persists_and_is_step_independent(press):
    """Longer 0.002 mm/s step after the loaded faster steps: repeated slips at any substep."""
    sched = ((1.2e-3, 6.0), (0.05e-3, 5.0), (0.002e-3, 120.0))
    for sub in (None, 1.25e-4):
        r = press.simulate(131.0, schedule=sched, substep=sub)
        m = crawl_metrics(r, t_from=20.0, t_to=131.0)
        assert m["crawling"] and m["slips"] >= 2, (sub, m)


def test_press_dataset_eq1_identity(press):
    from plants.forging_press import press_dataset
    res = press.simulate(1.5)
    ds = press_dataset(res, press)
    # Eq. (1) solved for F_r returns the friction the law applied, sample by sample
    assert np.allclose(ds.F, res["F"], rtol=1e-9, atol=1e-6 * np.max(np.abs(res["F"])))
    assert np.array_equal(ds.load, res["F_sigma"]) and ds.load.max() > 0


def test_press_takes_a_classic_lugre():
    from friction import make_model
    law = make_model("lugre", sigma0=1e9, sigma1=1e6, Fc=203.23e3, Fs=377.39e3, vs=7.6e-5,
                     sigma2=1.977e7)
    p = ForgingPress(law)
    res = p.simulate(3.0, schedule=((1.2e-3, 4.0),), workpiece=False)
    assert abs(np.mean(res["v"][-50:]) - 1.2e-3) < 0.05 * 1.2e-3
    assert np.allclose(p.friction_from_eq1(res), res["F"], rtol=1e-9, atol=1e-3)


def test_servo_valve_overlap():
    from plants.hydraulics import ServoValve
    lapped = ServoValve(overlap=0.1)
    assert lapped.flow(0.05e-3, 5e6) == 0.0                           # inside the dead band
    assert lapped.flow(0.2e-3, 5e6) == pytest.approx(ServoValve().flow(0.1e-3, 5e6))


def test_substep_follows_the_load_dependent_viscous_slope(press):
    full = press.with_options(schedule=TABLE1)
    assert 1.5e6 < full.max_deformation_load() < 4e6                # ~2.3 MN after step 1
    assert full.max_substep < press.max_substep <= ForgingPress.max_substep
    assert press.with_options(workpiece=False).max_substep == ForgingPress.max_substep
