"""MRE isolator shake-table test of seed 002 (4 Hz, 2/4/8 mm, 0-3 A, 256 Hz)."""
import numpy as np
import pytest

from friction import ParameterError
from friction.mre_lugre import parameters_at_current
from plants.mre_isolator import AMPLITUDES, CURRENTS, SAMPLE_RATE, MREIsolator
from plants.studies.mre_isolator import loop_metrics


def nrmse(a, b):
    return float(np.sqrt(np.mean((a - b) ** 2)) / np.std(b))


def test_default_law_follows_current():
    for I in (0.0, 3.0):
        p = MREIsolator(current=I).friction.params
        ref = parameters_at_current(I)
        assert p.k0 == pytest.approx(ref["k0"]) and p.alpha == pytest.approx(ref["alpha"])
    assert MREIsolator.data_rate == SAMPLE_RATE == 256.0


def test_fast_matches_reference_and_converges():
    plant = MREIsolator()
    ref = plant.simulate(0.25, method="reference", rtol=1e-8)
    fast = plant.simulate(0.25)
    fine = plant.simulate(0.25, substep=2.5e-5)
    e_fast = nrmse(fast["F_meas"], ref["F_meas"])
    assert e_fast < 1e-3 and nrmse(fine["F_meas"], ref["F_meas"]) < e_fast


def test_load_cell_reads_the_isolator_force_and_table_tracks():
    r = MREIsolator().simulate()
    k = r["time"] > 0.25
    assert nrmse(r["F_meas"][k], r["F"][k]) < 0.01
    assert np.max(np.abs(r["x_table"] - r["x_ref"])) < 0.01 * 8e-3


def test_loops_vs_amplitude_fig9():
    """2 A: effective stiffness declines mildly with amplitude, loop area grows."""
    m = [loop_metrics(MREIsolator().simulate(1.0, amplitude=A)) for A in AMPLITUDES]
    k = [x["k_eff"] for x in m]
    area = [x["area"] for x in m]
    assert k[0] > k[1] > k[2] > 0.7 * k[0]
    assert area[0] < area[1] < area[2]


def test_loops_vs_current_fig10():
    """4 mm: effective stiffness, peak force and dissipated energy grow with current."""
    m = [loop_metrics(MREIsolator(current=I).simulate(1.0, amplitude=4e-3)) for I in CURRENTS]
    assert all(np.diff([x["k_eff"] for x in m]) > 0)
    assert all(np.diff([x["F_max"] for x in m]) > 0)
    assert all(np.diff([x["area"] for x in m]) > 0)          # MR damping grows too


def test_bad_input():
    with pytest.raises(ParameterError, match="current"):
        MREIsolator(current=4.0)
    with pytest.raises(ValueError, match="amplitude"):
        MREIsolator().simulate(0.1, amplitude=0.2)


def test_isolator_dataset():
    from plants.mre_isolator import isolator_dataset
    res = MREIsolator().simulate(0.5)
    ds = isolator_dataset(res)
    assert np.array_equal(ds.F, res["F_meas"]) and np.array_equal(ds.x, res["x"])


def test_isolator_takes_a_classic_lugre():
    from friction import make_model
    law = make_model("lugre", sigma0=1e5, sigma1=100.0, sigma2=300.0, Fc=20.0, Fs=25.0)
    res = MREIsolator(law).simulate(0.5)
    k = res["time"] > 0.25
    assert np.all(np.isfinite(res["F_meas"])) and nrmse(res["F_meas"][k], res["F"][k]) < 0.02
