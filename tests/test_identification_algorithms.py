"""Every registered algorithm on a small synthetic LuGre problem; checkpoint/resume; executors;
the seeds' operators (chaos, adaptive probabilities); the CLI."""
import json
import subprocess
import sys

import numpy as np
import pytest

from friction import make_model
from friction.dataset import Dataset
from identification import ALGORITHMS, DEFAULT_ALGORITHM, identify
from identification.algorithms.base import chaotic_sequence
from identification.algorithms.evolutionary import AdaptiveGA
from identification.algorithms.structured import stribeck_fit

TRUE = dict(sigma0=1e5, sigma1=300.0, sigma2=0.4, Fc=1.0, Fs=1.5, vs=1e-3)
NAMES = list(TRUE)


@pytest.fixture(scope="module")
def data():
    true = make_model("lugre", **TRUE)
    t = np.arange(0, 2, 1e-3)
    v = 0.01 * np.sin(2 * np.pi * 1.0 * t) + 0.002 * np.sin(2 * np.pi * 6 * t)
    return Dataset.from_arrays(t, true.simulate(t, v), v=v, name="syn")


@pytest.fixture(scope="module")
def start():
    return make_model("lugre", sigma0=3e4, sigma1=100.0, sigma2=1.0, Fc=0.5, Fs=2.5, vs=5e-3)


GENERIC = ["afsa", "iafsa", "ffoa", "iffoa", "chaotic_pso", "adaptive_ga", "cmaes",
           "differential_evolution", "least_squares", "multistart_ls"]


def test_registry_has_the_seeds_and_the_modern_algorithms():
    assert set(GENERIC) | {"alternating_ls", "static_ls"} <= set(ALGORITHMS)
    assert DEFAULT_ALGORITHM in ALGORITHMS


@pytest.mark.parametrize("name", GENERIC)
def test_every_algorithm_improves_on_its_start_within_budget(name, data, start):
    F0 = start.simulate(data.t, data.v)
    c0 = np.sqrt(np.mean((F0 - data.F) ** 2)) / np.std(data.F)
    r = identify(data, start, algorithm=name, names=NAMES, seed=3, max_evals=1500)
    assert r.n_evals <= 1500
    assert r.fit_nrmse <= c0 + 1e-12
    assert r.algorithm == name
    # the reported cost is the cost of the reported parameters
    F = r.model.simulate(data.t, data.v)
    assert r.fit_nrmse == pytest.approx(np.sqrt(np.mean((F - data.F) ** 2)) / np.std(data.F),
                                        rel=1e-9, abs=1e-14)


def test_population_algorithms_are_reproducible(data, start):
    a = identify(data, start, algorithm="chaotic_pso", names=NAMES, seed=11, max_evals=800)
    b = identify(data, start, algorithm="chaotic_pso", names=NAMES, seed=11, max_evals=800)
    c = identify(data, start, algorithm="chaotic_pso", names=NAMES, seed=12, max_evals=800)
    assert a.params == b.params and a.cost_history == b.cost_history
    assert a.params != c.params


def test_checkpoint_resume_equals_uninterrupted_run(data, start, tmp_path):
    ck = tmp_path / "run.ckpt"
    full = identify(data, start, algorithm="iafsa", names=NAMES, seed=5, max_iter=12)
    # first leg stops after 6 iterations (as an interrupt would), second resumes to 12
    leg1 = identify(data, start, algorithm="iafsa", names=NAMES, seed=5, max_iter=6,
                    checkpoint=ck, checkpoint_every=2)
    assert ck.exists() and not leg1.resumed
    # a resumed run must use the same options except the stop; the state carries the swarm
    leg2 = identify(data, start, algorithm="iafsa", names=NAMES, seed=5, max_iter=12,
                    checkpoint=ck)
    assert leg2.resumed
    assert leg2.params == full.params
    assert leg2.n_evals == full.n_evals
    assert leg2.cost_history == full.cost_history
    # another run's checkpoint is refused with a clear message
    with pytest.raises(ValueError, match="another run"):
        identify(data, start, algorithm="iafsa", names=NAMES, seed=6, checkpoint=ck)


def test_interrupt_saves_a_checkpoint_that_resumes(data, start, tmp_path):
    ck = tmp_path / "int.ckpt"
    calls = {"n": 0}

    def progress(n=1, info=""):
        calls["n"] += 1
        if calls["n"] == 4:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        identify(data, start, algorithm="cmaes", names=NAMES, seed=2, max_iter=10,
                 checkpoint=ck, progress=progress)
    assert ck.exists()
    resumed = identify(data, start, algorithm="cmaes", names=NAMES, seed=2, max_iter=10,
                       checkpoint=ck)
    full = identify(data, start, algorithm="cmaes", names=NAMES, seed=2, max_iter=10)
    assert resumed.resumed and resumed.params == full.params


def test_process_executor_gives_the_inline_costs(data, start):
    a = identify(data, start, algorithm="chaotic_pso", names=NAMES, seed=1, max_evals=200,
                 executor="inline")
    b = identify(data, start, algorithm="chaotic_pso", names=NAMES, seed=1, max_evals=200,
                 executor="processes")
    assert b.executor == "processes"
    assert a.params == b.params and a.cost_history == b.cost_history


def test_dask_local_cluster_executor(data, start):
    from dask import distributed
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        r = identify(data, start, algorithm="cmaes", names=NAMES, seed=4, max_evals=120,
                     executor=client)
    ref = identify(data, start, algorithm="cmaes", names=NAMES, seed=4, max_evals=120)
    assert r.executor == "dask"
    assert r.params == ref.params


def test_default_recovers_every_parameter_within_one_percent(data, start):
    r = identify(data, start, names=NAMES, seed=0)
    for n, v in TRUE.items():
        assert r.params[n] == pytest.approx(v, rel=0.01), n


def test_alternating_ls_improves_inside_theta_delta():
    true = make_model("lugre", sigma0=1e5, sigma1=300.0, sigma2=0.4, Fc=1.0, Fs=1.5, vs=1e-3,
                      b=0.05)
    t = np.arange(0, 6, 1e-3)
    v = 0.01 * np.sin(2 * np.pi * 0.25 * t) + 0.003 * np.sin(2 * np.pi * 2 * t)
    d = Dataset.from_arrays(t, true.simulate(t, v), v=v)
    names = ["sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs", "b"]
    init = dict(sigma0=8e4, sigma1=250.0, sigma2=0.5, Fc=0.9, Fs=1.4, vs=1.2e-3, b=0.0)
    r = identify(d, make_model("lugre"), algorithm="alternating_ls", names=names, init=init)
    h = r.cost_history
    assert len(h) == 5 and h[-1] <= h[0]
    # every estimate stays in Theta(0.5) around its initial value
    for n in ("sigma0", "sigma1", "sigma2"):
        assert 0.5 * init[n] - 1e-9 <= r.params[n] <= 1.5 * init[n] + 1e-9
    assert r.fit_nrmse < 0.05
    with pytest.raises(ValueError, match="exactly"):
        identify(d, make_model("lugre"), algorithm="alternating_ls", names=["Fc"])


def test_stribeck_fit_recovers_static_parameters():
    v = np.concatenate([-np.geomspace(1e-4, 0.03, 40), np.geomspace(1e-4, 0.03, 40)])
    m = make_model("lugre", Fc=1.0, Fs=1.5, vs=1e-3, sigma2=4.0, b=0.02)
    p = stribeck_fit(v, m.steady_state(v))
    assert p["Fc"] == pytest.approx(1.0, rel=1e-4)
    assert p["Fs"] == pytest.approx(1.5, rel=1e-4)
    assert p["vs"] == pytest.approx(1e-3, rel=1e-4)
    assert p["sigma2"] == pytest.approx(4.0, rel=1e-4)


def test_seed_operators():
    z = chaotic_sequence([0.3], 200)[:, 0]
    assert np.all((z > 0) & (z < 1))
    assert z[0] == pytest.approx(4 * 0.3 * 0.7)  # seed 001 Eq. 11
    assert len(np.unique(np.round(z, 6))) > 150  # not stuck on a cycle
    # seed 001 Eqs. 7-8: Pc1 below the mean, Pc2 at the best, linear in between
    pc = AdaptiveGA._adaptive(0.9, 0.6, np.array([0.0, 1.0, 2.0, 1.5]), 1.0, 2.0)
    assert np.allclose(pc, [0.9, 0.9, 0.6, 0.75])


def test_cli_identify_writes_json(data, tmp_path):
    csv = tmp_path / "d.csv"
    data.to_csv(csv)
    out = tmp_path / "r.json"
    p = subprocess.run([sys.executable, "-m", "frictionlab.cli", "identify", str(csv), str(csv),
                        "--model", "lugre", "--algorithm", "least_squares", "--json", str(out),
                        "--quiet"], capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    assert "fit NRMSE" in p.stdout and "valid NRMSE" in p.stdout
    d = json.loads(out.read_text())
    assert d["algorithm"] == "least_squares" and d["fit_nrmse"] < 1e-6
    bad = subprocess.run([sys.executable, "-m", "frictionlab.cli", "identify", str(csv),
                          "--model", "nope"], capture_output=True, text=True, timeout=120)
    assert bad.returncode != 0 and "unknown friction model" in bad.stderr
    assert "Traceback" not in bad.stderr


def test_benchmark_functions_of_seed_002():
    from identification.functions import ackley, griewank, minimize
    assert ackley(np.zeros((1, 3)))[0] == pytest.approx(0.0, abs=1e-12)
    assert griewank(np.zeros((1, 3)))[0] == pytest.approx(0.0, abs=1e-12)
    # 2-D, the papers' small settings: the swarm methods get close to the global minimum 0
    for alg, kw in [("chaotic_pso", dict(max_iter=100)), ("cmaes", {}),
                    ("ffoa", dict(pop_size=30, max_iter=100))]:
        r = minimize(ackley, [-5, -5], [5, 5], algorithm=alg, seed=1, **kw)
        assert r["fun"] < 0.1, alg
    # IAFSA's stall handling (Gauss mutation of the worst fish, chaotic search) fires
    r = minimize(griewank, [-5, -5], [5, 5], algorithm="iafsa", seed=1, max_iter=40)
    assert r["state"]["n_chaos"] > 0 and r["state"]["n_mutations"] > 0
    assert r["fun"] < 0.05


def test_static_ls_recovers_seed_004_tables_from_constant_speed_tests():
    """Seed 004: Phi = [Fc0, Fs0, vs, sigma20] from no-load constant-speed tests (Eq. 16), then
    [k1, k2, k3] per regime from loaded ones by the linear system of Eq. 18."""
    from friction.load_lugre import critical_velocity
    base = make_model("load_lugre").params
    vc = critical_velocity(base.Fc0, base.Fs0, base.vs, base.sigma20)
    true = make_model("load_lugre", vc=vc)
    v_free = np.geomspace(2e-6, 2e-3, 40)
    v_low = np.geomspace(3e-6, 0.9 * vc, 12)
    v_high = np.geomspace(1.2 * vc, 2e-3, 12)
    v = np.concatenate([v_free, v_low, v_low, v_high, v_high])
    load = np.concatenate([np.zeros(40), np.full(12, 5e4), np.full(12, 1.2e5),
                           np.full(12, 5e4), np.full(12, 1.2e5)])
    F = true.steady_state(v, load=load)
    d = Dataset.from_arrays(np.arange(v.size, dtype=float), F, v=v, a=np.zeros_like(v),
                            load=load, check_units=False)
    names = ["Fc0", "Fs0", "vs", "sigma20", "k1_low", "k2_low", "k3_low", "k1_high", "k2_high",
             "k3_high"]
    r = identify(d, make_model("load_lugre", vc=vc), algorithm="static_ls", names=names)
    for n in ("Fc0", "Fs0", "vs", "sigma20", "k1_low", "k2_low", "k3_low", "k1_high",
              "k3_high"):
        assert r.params[n] == pytest.approx(getattr(true.params, n), rel=1e-3, abs=1e-6), n
    with pytest.raises(ValueError, match="load_lugre"):
        identify(d, "lugre", algorithm="static_ls")


def test_algorithm_variants_and_option_errors():
    from identification.functions import ackley, minimize
    r = minimize(ackley, [-5, -5], [5, 5], algorithm="afsa", seed=1, crowd_test="food",
                 max_iter=30)
    assert r["fun"] < 0.1
    for sched in ("power", "one_minus_power", "exp"):
        r = minimize(ackley, [-5, -5], [5, 5], algorithm="iffoa", seed=1, schedule=sched,
                     pop_size=30, max_iter=50)
        assert np.isfinite(r["fun"]) and r["n_evals"] == 30 * 50 + 1
    with pytest.raises(ValueError, match="crowd_test"):
        minimize(ackley, [-5, -5], [5, 5], algorithm="afsa", crowd_test="nope", max_iter=2)
    with pytest.raises(TypeError, match="no option"):
        minimize(ackley, [-5, -5], [5, 5], algorithm="afsa", bogus=1)
