"""The force level's candidate fits in worker processes forked from the caller's
(diagnosis.cluster.process_fits, the default where the platform forks): the serial loop's
report bit for bit, the fits really in other processes, their progress back in the caller,
a dead worker's candidates fitted by the caller; and the row-by-row population kernels the
workers run (friction.base.SERIAL_POPULATIONS) equal to the parallel ones bit for bit."""
import json
import os

import numpy as np
import pytest

from diagnosis import cluster, diagnose
from diagnosis.benchmark import make_case
from friction import MODELS, base, make_model

pytestmark = pytest.mark.skipif(not cluster.can_fork(), reason="forked workers: Linux only")


@pytest.fixture(scope="module")
def case():
    return make_case("drift", 1.0, 0.02, n=3000, seed=3)


def _report(rep):
    return json.dumps({k: rep[k] for k in ("effects", "verdict")}, default=str,
                      sort_keys=True)


def test_forked_workers_give_the_serial_report_bit_for_bit(case):
    cands = ["delay", "drift", "inertia", "asymmetry", "gms"]
    serial = diagnose(case, "lugre", candidates=cands, threads=1)
    forked = diagnose(case, "lugre", candidates=cands, threads=2)
    assert _report(serial) == _report(forked)
    assert {e["name"] for e in forked["effects"]} == set(cands)


def test_the_fits_run_in_other_processes_and_report_progress(case, monkeypatch):
    fit_one = cluster._fit_one

    def tagged(name, **kw):
        # runs in a worker (the forked copy of this patch): its pid rides on the result
        comp, cost = fit_one(name, **kw)
        comp.extras["_pid"] = os.getpid()
        return comp, cost
    monkeypatch.setattr(cluster, "_fit_one", tagged)
    ticks = []
    from diagnosis import composite
    from diagnosis.composite import reporting
    monkeypatch.setattr(composite, "TICK_EVERY", 0.0)  # a tick each evaluation (short fits)
    with reporting(lambda n, info: ticks.append((n, info))):
        remote = cluster.process_fits(["delay", "drift", "inertia"], *_base(case),
                                      threads=2)
    pids = {comp.extras.pop("_pid") for comp, _ in remote.values()}
    assert set(remote) == {"delay", "drift", "inertia"}
    assert os.getpid() not in pids and 1 <= len(pids) <= 2
    # the ticks of the workers' fits reached the caller's reporter (evaluations > 0)
    assert ticks and all(n > 0 and isinstance(info, str) for n, info in ticks)
    assert any(info.startswith("fit drift") for _, info in ticks)


def _base(case):
    """(law, base_names, fit, ctx) as diagnose gives its candidate fits."""
    from diagnosis.core import fit_base, make_context
    fit, _ = case.split(0.7)
    ctx = make_context(fit)
    base_fit, names, _ = fit_base(fit, "lugre", ctx, align=False)
    return base_fit.law, names, fit, ctx


def test_a_dead_worker_leaves_its_candidates_to_the_caller(case, monkeypatch):
    fit_one = cluster._fit_one

    def dies(name, **kw):
        if name == "drift":
            os._exit(3)  # a worker killed mid-fit (out of memory, a signal)
        return fit_one(name, **kw)
    monkeypatch.setattr(cluster, "_fit_one", dies)
    law, names, fit, ctx = _base(case)
    remote = cluster.process_fits(["delay", "drift", "inertia"], law, names, fit, ctx,
                                  threads=2)
    # what the broken pool had not finished is left out (the caller's loop fits it),
    # never a wrong result
    assert "drift" not in remote and set(remote) <= {"delay", "inertia"}
    monkeypatch.setattr(cluster, "_fit_one", fit_one)
    rep = diagnose(case, "lugre", candidates=["delay", "drift"], threads=2)
    assert {e["name"] for e in rep["effects"]} == {"delay", "drift"}


def test_processes_off_another_platform_or_a_daemon_falls_back_to_threads(monkeypatch):
    assert cluster.can_fork()
    monkeypatch.setattr(cluster, "PROCESSES", False)
    assert not cluster.can_fork()
    monkeypatch.setattr(cluster, "PROCESSES", True)
    monkeypatch.setattr(cluster.sys, "platform", "darwin")  # forks, but spawns by default
    assert not cluster.can_fork()
    monkeypatch.setattr(cluster.sys, "platform", "linux")
    import multiprocessing
    monkeypatch.setattr(multiprocessing.current_process(), "_config",
                        {**multiprocessing.current_process()._config, "daemon": True})
    assert not cluster.can_fork()


@pytest.mark.parametrize("name", sorted(MODELS))
def test_row_by_row_populations_equal_the_parallel_kernel(name, monkeypatch):
    law = make_model(name)
    rng = np.random.default_rng(7)
    t = np.linspace(0.0, 2.0, 801)
    v = 0.02 * np.sin(2 * np.pi * 1.3 * t) + 0.004 * rng.standard_normal(t.size)
    inputs = {"a": np.gradient(v, t), "load": 100.0 + 20.0 * np.sin(t),
              "x": np.cumsum(v) * (t[1] - t[0])}
    inputs = {k: val for k, val in inputs.items() if k in law.extra_inputs}
    pick = [n for n in law.params.numeric_names() if getattr(law.params, n) not in (None, 0.0)][:2]
    X = np.array([[getattr(law.params, n) * f for n in pick] for f in (0.8, 1.0, 1.3)])
    par = law.simulate_population(t, v, pick, X, **inputs)
    monkeypatch.setattr(base, "SERIAL_POPULATIONS", True)
    ser = law.simulate_population(t, v, pick, X, **inputs)
    assert np.all(np.isfinite(par)) and par.shape == (3, t.size)
    assert np.array_equal(par, ser)


def test_serial_population_costs_equal_the_fused_parallel_ones(monkeypatch):
    from friction.dataset import Dataset
    from identification.objectives import InProcessObjective
    law = make_model("lugre")
    t = np.linspace(0.0, 3.0, 9001)  # more than two of the fused kernel's blocks
    v = 0.01 * np.sin(2 * np.pi * t)
    F = law.simulate(t, v) + 0.01 * np.cos(7 * t)
    data = Dataset(t=t, x=np.cumsum(v) * (t[1] - t[0]), v=v, a=np.gradient(v, t), F=F)
    obj = InProcessObjective(law, data, ["Fc", "sigma0"])
    X = np.array([[law.params.Fc * f, law.params.sigma0] for f in (0.9, 1.0, 1.1)])
    par = obj.costs(X)
    monkeypatch.setattr(base, "SERIAL_POPULATIONS", True)
    assert np.array_equal(par, obj.costs(X))
    assert np.argmin(par) == 1


def test_two_callers_threads_each_get_their_own_fits(case):
    # two diagnoses from two threads of one process: each pool forks with its own job
    from concurrent.futures import ThreadPoolExecutor
    law, names, fit, ctx = _base(case)
    other = make_case("asymmetry", 1.0, 0.02, n=3000, seed=5)
    law2, names2, fit2, ctx2 = _base(other)
    jobs = [(law, names, fit, ctx), (law2, names2, fit2, ctx2)]
    with ThreadPoolExecutor(2) as pool:
        got = list(pool.map(lambda j: cluster.process_fits(["delay", "inertia"], *j,
                                                             threads=2), jobs))
    for (lw, nm, ft, cx), remote in zip(jobs, got):
        for cand in ("delay", "inertia"):
            serial = cluster._fit_one(cand, law=lw, base_names=nm, fit=ft, ctx=cx)
            assert remote[cand][1] == serial[1]
            assert remote[cand][0].extras == serial[0].extras


def test_a_fit_that_raises_in_a_worker_raises_in_the_caller_with_its_message(case,
                                                                             monkeypatch):
    fit_one = cluster._fit_one

    def refuses(name, **kw):
        if name == "drift":
            raise ValueError("drift_tau = -1 is out of bounds: must be > 0 [s]")
        return fit_one(name, **kw)
    monkeypatch.setattr(cluster, "_fit_one", refuses)
    with pytest.raises(ValueError, match="drift_tau = -1 is out of bounds"):
        cluster.process_fits(["delay", "drift", "inertia"], *_base(case), threads=2)


def test_the_costliest_fits_start_first(case, monkeypatch):
    # measured costs first (the GMS fit, the costliest, no longer starts last and runs
    # alone), then the unmeasured ones by their Jacobian's width; and the pool submits in
    # that order
    names = ["asymmetry", "inertia", "position", "gms", "drift", "acceleration"]
    law, base_names, fit, ctx = _base(case)
    order = cluster.costliest_first(names, law, base_names, ctx)
    from diagnosis.effects import CANDIDATES
    costs = [CANDIDATES[n].specialise(law).fit_cost for n in order]
    assert order[:2] == ["gms", "acceleration"]
    assert costs == sorted(costs, reverse=True) and min(costs) > 0.0
    monkeypatch.setattr(type(CANDIDATES["inertia"].specialise(law)), "fit_cost", 0.0)
    order0 = cluster.costliest_first(names, law, base_names, ctx)
    assert order0[-1] == "inertia" and order0[:-1] == [n for n in order if n != "inertia"]
    submitted = []
    real = cluster.costliest_first
    monkeypatch.setattr(cluster, "costliest_first",
                        lambda *a: submitted.extend(real(*a)) or list(submitted))
    cluster.process_fits(["inertia", "gms", "delay"], law, base_names, fit, ctx, threads=2)
    assert submitted == ["gms", "delay", "inertia"]
