"""Valve damping rig of seed 001: suspended cylinder on force sensors, drives, Eqs. 17-18."""
import numpy as np
import pytest

from plants.damping_rig import PIEZO_RATE, TABLE_I, DampingRig, Trapezoid, rig_friction


def nrmse(a, b):
    return float(np.sqrt(np.mean((a - b) ** 2)) / np.std(b))


@pytest.fixture(scope="module")
def rig():
    return DampingRig()


def test_default_friction_is_table_I(rig):
    p = rig.friction.params
    assert (p.Fc, p.Fs, p.vs, p.sigma2, p.sigma1, p.sigma0) == TABLE_I[4.0]


def test_sensors_read_friction_at_low_frequency_not_near_resonance(rig):
    lin = rig.simulate(0.5)                                   # linear motor, 4 Hz sine, 1 kHz
    assert nrmse(lin["F_meas"], lin["F"]) < 0.01
    # the sensor reading is the friction minus the cylinder's inertia: F - m_c a_c
    p = rig.params
    pz_rig = DampingRig(rig_friction(600.0))
    pz = pz_rig.simulate(2.0 / 600.0, step=1.0 / PIEZO_RATE, drive="piezo", freq=600.0,
                         amplitude=30e-6)
    assert nrmse(pz["F_meas"], pz["F"]) > 0.2                 # near the 1.1 kHz resonance
    st = pz_rig.with_options(drive="piezo", freq=600.0, amplitude=30e-6).stepper()
    for k in range(60):
        st.do_step(k / PIEZO_RATE, 1.0 / PIEZO_RATE)
    out = st.outputs()
    ds = pz_rig.derivatives(st.time, st.s, st.d, out["F"], st.u)
    assert out["F_meas"] == pytest.approx(out["F"] - p.m_c * ds[3], rel=1e-9, abs=1e-9)


def test_fast_matches_reference_and_converges(rig):
    ref = rig.simulate(0.05, method="reference", rtol=1e-8)
    fast = rig.simulate(0.05)
    fine = rig.simulate(0.05, substep=1e-5)
    assert nrmse(fast["F"], ref["F"]) < 1e-4
    assert nrmse(fast["F_meas"], ref["F_meas"]) < 5e-3
    assert nrmse(fine["F_meas"], ref["F_meas"]) < nrmse(fast["F_meas"], ref["F_meas"])


def test_waveforms(rig):
    tri = rig.simulate(0.25, waveform="triangle", amplitude=0.01)
    speed = 4 * 0.01 * 4.0
    assert np.mean(np.isclose(np.abs(tri["v"]), speed, rtol=0.02)) > 0.8   # constant speed
    trap = Trapezoid(0.01, 4.0, dwell=0.2)
    s, v, _ = trap(np.linspace(0, 0.25, 1001))
    assert s.max() == pytest.approx(0.01) and np.mean(v == 0) == pytest.approx(0.4, abs=0.01)


def test_open_loop_experiment_eqs_17_18(rig):
    res = rig.simulate(1.3, drive="open_loop")
    p = rig.params
    u = p.U * np.sin(p.w_u * res["time"])
    assert np.allclose(res["u"], u)
    # Eq. (17) m a = u - F holds sample by sample (a relative to the nearly fixed cylinder)
    assert np.max(np.abs(p.m_p * res["a"] - (u - res["F"]))) < 2e-3 * p.U
    # |u| = 1.1 N < Fc: the ring never slides, the piston stays in pre-sliding (z ~ u/sigma0)
    s0 = rig.friction.params.sigma0
    assert np.max(np.abs(res["x_p"])) < 1.5 * p.U / s0
    assert np.allclose(res["x"], res["x_p"] - res["x_c"])


def test_drive_ranges_are_checked():
    with pytest.raises(ValueError, match="linear motor"):
        DampingRig().simulate(0.1, freq=300.0)
    with pytest.raises(ValueError, match="piezo"):
        DampingRig().simulate(0.01, drive="piezo", freq=600.0, amplitude=1e-3)
    with pytest.raises(ValueError, match="drive"):
        DampingRig().with_options(drive="hydraulic")
    with pytest.raises(ValueError, match="Table I"):
        rig_friction(5.0)


def test_rig_dataset(rig):
    from plants.damping_rig import rig_dataset
    res = rig.simulate(0.1)
    ds = rig_dataset(res)
    assert np.array_equal(ds.F, res["F_meas"]) and np.array_equal(ds.v, res["v"])


@pytest.mark.parametrize("name", ["mre_lugre", "stribeck"])
def test_rig_takes_other_laws(name):
    from friction import make_model
    law = make_model(name) if name == "mre_lugre" else make_model(name, Fc=5.0, Fs=30.0,
                                                                   vs=0.02, sigma2=50.0)
    res = DampingRig(law).simulate(0.25)
    assert np.all(np.isfinite(res["F_meas"]))
    # force steps of these laws ring the sensor resonance, but on average the sensors carry
    # the friction (the suspension is in equilibrium between steps)
    assert abs(np.mean(res["F_meas"]) - np.mean(res["F"])) < 0.05 * np.std(res["F"])
