"""The force level's candidate fits on threads of this process (diagnosis.cluster.thread_fits,
where the platform does not fork or cluster.PROCESSES is off): the same report as one after
the other, the fits really side by side, bad counts refused."""
import threading

import numpy as np
import pytest

from diagnosis import cluster, diagnose
from diagnosis.benchmark import make_case


@pytest.fixture(autouse=True)
def threads_only(monkeypatch):
    monkeypatch.setattr(cluster, "PROCESSES", False)  # forked workers: test_diagnosis_forked


@pytest.fixture(scope="module")
def case():
    return make_case("drift", 1.0, 0.02, n=3000, seed=3)


def _effects(rep):
    return {e["name"]: (e["gap_closed"], e["validation_after"], e["significance_z"])
            for e in rep["effects"]}


@pytest.mark.slow  # 9 s: the suite's budget; test_the_fits_run_on_two_threads stays
def test_two_threads_give_the_serial_report_bit_for_bit(case):
    serial = diagnose(case, "lugre", threads=1)
    threaded = diagnose(case, "lugre", threads=2)
    assert _effects(serial) == _effects(threaded)
    assert serial["verdict"] == threaded["verdict"]
    assert len(serial["effects"]) >= 8  # every candidate that applies was fitted


def test_the_fits_run_on_two_threads(case, monkeypatch):
    from threadpoolctl import threadpool_info
    seen, blas = {}, set()
    fit_one = cluster._fit_one

    def spy(name, **kw):
        seen[name] = threading.get_ident()
        # side by side, each fit's SVDs run on one BLAS thread (no oversubscription)
        blas.update(i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas")
        return fit_one(name, **kw)
    monkeypatch.setattr(cluster, "_fit_one", spy)
    diagnose(case, "lugre", candidates=["delay", "drift", "inertia", "asymmetry"], threads=2)
    assert set(seen) == {"delay", "drift", "inertia", "asymmetry"}
    assert len(set(seen.values())) == 2
    assert threading.get_ident() not in seen.values()
    assert blas == {1}
    seen.clear()
    diagnose(case, "lugre", candidates=["delay", "drift"], threads=1)
    assert seen == {}  # one thread: the caller's own loop fits them


def test_a_count_below_one_is_refused_by_name(case):
    with pytest.raises(ValueError, match="threads = 0"):
        cluster.thread_count(0)
    assert cluster.thread_count(3) == 3
    assert 1 <= cluster.thread_count() <= cluster.MAX_THREADS


def test_progress_reaches_the_caller_from_the_threads(case):
    lines = []
    diagnose(case, "lugre", candidates=["delay", "drift", "inertia"], threads=2,
             progress=lambda n, info: lines.append(info))
    assert any("candidate" in ln for ln in lines)
    assert np.all([isinstance(ln, str) for ln in lines])


def test_the_environment_sets_the_count_and_a_bad_one_is_named(monkeypatch):
    monkeypatch.setenv("FRICTIONLAB_THREADS", "1")
    assert cluster.thread_count() == 1
    monkeypatch.setenv("FRICTIONLAB_THREADS", "two")
    with pytest.raises(ValueError, match="FRICTIONLAB_THREADS = 'two'"):
        cluster.thread_count()
    assert cluster.thread_count(2) == 2  # an explicit count wins


def test_cli_bad_thread_count_is_one_line_before_any_fit(tmp_path, capsys):
    from frictionlab.cli import main
    data = make_case("delay", 1.0, 0.02, n=1500, seed=4)
    p = tmp_path / "run.csv"
    data.to_csv(p)
    code = main(["diagnose", str(p), "--model", "lugre", "--threads", "0", "--quiet"])
    err = capsys.readouterr().err
    assert code != 0
    assert "threads = 0" in err and "Traceback" not in err
