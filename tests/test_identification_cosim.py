"""Co-simulation objectives: the FMU runs through fmus.master give the in-process cost."""
import numpy as np
import pytest

from friction import make_model
from friction.dataset import Dataset
from friction.reference import simulate_mass
from identification import identify
from identification.cosim import ClosedLoopCoSimObjective, CoSimObjective
from identification.objectives import InProcessObjective

TRUE = dict(sigma0=1e5, sigma1=300.0, sigma2=0.4, Fc=1.0, Fs=1.5, vs=1e-3)


@pytest.fixture(scope="module")
def prescribed():
    true = make_model("lugre", **TRUE)
    t = np.arange(0, 0.6, 1e-3)
    v = 0.01 * np.sin(2 * np.pi * 2 * t) + 0.002 * np.sin(2 * np.pi * 9 * t)
    noise = 0.01 * np.random.default_rng(0).standard_normal(t.size)
    return Dataset.from_arrays(t, true.simulate(t, v) + noise, v=v)


def test_prescribed_motion_cosim_cost_equals_in_process_cost(prescribed):
    names = ["sigma0", "sigma1", "Fc", "Fs", "vs"]
    X = np.array([[1e5, 300.0, 1.0, 1.5, 1e-3], [4e4, 80.0, 0.7, 2.2, 4e-3],
                  [3e6, 1500.0, 1.3, 1.4, 2e-4]])
    model = make_model("lugre", **TRUE)
    c_in = InProcessObjective(model, prescribed, names).costs(X)
    co = CoSimObjective(model, prescribed, names)
    try:
        c_co = co.costs(X)
    finally:
        co.close()
    assert np.all(np.isfinite(c_co))
    np.testing.assert_allclose(c_co, c_in, rtol=1e-9, atol=0)


def test_identify_with_cosim_objective_matches_in_process(prescribed):
    names = ["Fc", "Fs"]
    start = make_model("lugre", **TRUE).with_values(Fc=0.7, Fs=2.0)
    a = identify(prescribed, start, algorithm="least_squares", names=names)
    b = identify(prescribed, start, algorithm="least_squares", names=names, objective="cosim",
                 executor="inline")
    for n in names:
        assert b.params[n] == pytest.approx(a.params[n], rel=1e-6)
    assert b.fit_nrmse == pytest.approx(a.fit_nrmse, rel=1e-9)


@pytest.mark.slow
def test_closed_loop_cosim_reaches_the_in_process_optimum():
    """Seed 001's open-loop drive u = 1.1 sin 5t on a 1 kg mass; the friction acts on the
    motion it produces. Data from the monolithic reference integrator."""
    true = make_model("lugre", sigma0=1e4, sigma1=20.0, sigma2=0.4, Fc=0.5, Fs=0.8, vs=1e-2)
    t = np.arange(0, 1.3 + 1e-9, 1e-3)
    ref = simulate_mass(true, 1.0, t, lambda tq: 1.1 * np.sin(5 * tq))
    d = Dataset.from_arrays(t, ref["F"], v=ref["v"], x=ref["x"], check_units=False)
    names = ["Fc", "Fs", "sigma2"]
    start = true.with_values(Fc=0.4, Fs=1.0, sigma2=0.6)
    ri = identify(d, start, algorithm="least_squares", names=names)

    def factory(m, dd, n):
        return ClosedLoopCoSimObjective(m, dd, n, mass=1.0, u_amp=1.1, u_freq=5 / (2 * np.pi))

    rc = identify(d, start, algorithm="least_squares", names=names, objective=factory,
                  executor="inline")
    for n in names:
        truth = getattr(true.params, n)
        assert ri.params[n] == pytest.approx(truth, rel=5e-3)
        assert rc.params[n] == pytest.approx(truth, rel=5e-3)
        assert rc.params[n] == pytest.approx(ri.params[n], rel=5e-3)


def test_cosim_objective_runs_in_worker_processes(prescribed):
    from identification.executors import ProcessExecutor, make_executor
    names = ["Fc", "Fs"]
    model = make_model("lugre", **TRUE)
    co = CoSimObjective(model, prescribed, names)
    assert isinstance(make_executor("auto", co), ProcessExecutor)  # FMU runs are serial
    X = np.array([[1.0, 1.5], [0.8, 2.0], [1.2, 1.3], [0.9, 1.6]])
    ex = ProcessExecutor(workers=2)
    try:
        c_proc = ex.costs(co, X)
    finally:
        ex.close()
    c_in = InProcessObjective(model, prescribed, names).costs(X)
    np.testing.assert_allclose(c_proc, c_in, rtol=1e-9)
