"""``--scheduler ADDRESS`` (issue 14, "When one machine is not enough"): a dask scheduler and
two workers started from the ``dask`` command line on 127.0.0.1, each worker with its own
temporary folder (as if on its own machine); ``frictionlab identify --scheduler`` and a
plant-FMU identification through the Python API give the inline executor's result, both
workers evaluate, and the FMUs reach each worker once, by value."""
from __future__ import annotations

import json
import os
import pathlib
import signal
import socket
import subprocess
import sys
import time

import numpy as np
import pytest

pytest.importorskip("distributed")

from frictionlab.cli import main  # noqa: E402
from identification.cluster import FileBundle, connect, worker_stats  # noqa: E402

DASK = [sys.executable, "-m", "dask"]


def _dask_cli() -> list:
    """The installed ``dask`` command (its entry point beside this Python), else ``python -m
    dask``."""
    exe = pathlib.Path(sys.executable).with_name("dask")
    return [str(exe)] if exe.exists() else DASK


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    """Scheduler + two single-thread workers bound to 127.0.0.1, started from the dask
    command line; torn down whatever happens. Yields (address, {worker name: TMPDIR})."""
    root = tmp_path_factory.mktemp("dask")
    sfile = root / "scheduler.json"
    procs, logs = [], []

    def start(args, name, env=None):
        log = open(root / f"{name}.log", "w")
        logs.append(log)
        procs.append(subprocess.Popen(_dask_cli() + args, stdout=log, stderr=subprocess.STDOUT,
                                      cwd=root, env=env, start_new_session=True))

    tmpdirs = {}
    try:
        start(["scheduler", "--host", "127.0.0.1", "--port", "0", "--no-dashboard",
               "--scheduler-file", str(sfile)], "scheduler")
        deadline = time.time() + 30
        while not sfile.exists() and time.time() < deadline:
            time.sleep(0.05)
        assert sfile.exists(), (root / "scheduler.log").read_text()
        time.sleep(0.1)  # the file is written whole, but give the writer its close
        address = json.loads(sfile.read_text())["address"]
        assert address.startswith("tcp://127.0.0.1:")
        for name in ("w1", "w2"):
            tmp = root / f"tmp-{name}"  # its own temporary folder: no shared FMU cache
            tmp.mkdir()
            tmpdirs[name] = str(tmp)
            env = {**os.environ, "TMPDIR": str(tmp)}
            start(["worker", "--scheduler-file", str(sfile), "--nthreads", "1",
                   "--host", "127.0.0.1", "--no-dashboard", "--name", name,
                   "--local-directory", str(tmp)], name, env)
        client = connect(address, timeout=30, workers=2)
        client.close()
        yield address, tmpdirs
    finally:
        for p in procs:
            if p.poll() is None:
                try:
                    os.killpg(p.pid, signal.SIGTERM)  # the nanny and its worker process
                except ProcessLookupError:
                    pass
        for p in procs:
            try:
                p.wait(timeout=15)
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, signal.SIGKILL)
                p.wait(timeout=5)
        for log in logs:
            log.close()


def _stats(address):
    """worker name -> its :func:`identification.cluster.worker_stats`."""
    client = connect(address, workers=2)
    try:
        names = {a: w["name"] for a, w in client.scheduler_info()["workers"].items()}
        return {names[a]: s for a, s in client.run(worker_stats).items()}
    finally:
        client.close()


def _delta(after, before, key):
    return {w: after[w][key] - before[w][key] for w in after}


def _csv(path):
    """A small synthetic LuGre record (1.2 s at 1 kHz, 1 % force noise) as a user's CSV."""
    from friction import make_model
    t = np.arange(0.0, 1.2, 1e-3)
    v = 0.01 * np.sin(2 * np.pi * t) + 0.004 * np.sin(2 * np.pi * 3.1 * t)
    law = make_model("lugre", sigma0=1e5, sigma1=300.0, sigma2=0.4, Fc=1.0, Fs=1.5, vs=1e-3)
    F = law.simulate(t, v) + np.random.default_rng(0).normal(0.0, 0.01, t.size)
    x = np.concatenate(([0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(t))))
    np.savetxt(path, np.column_stack([t, x, v, np.gradient(v, t), F]), delimiter=",",
               header="t,x,v,a,F", comments="")
    return path


def test_cli_identify_on_the_cluster_equals_inline(cluster, tmp_path, capsys):
    address, _ = cluster
    data = str(_csv(tmp_path / "run.csv"))
    argv = ["identify", data, "--model", "lugre", "--algorithm", "differential_evolution",
            "--max-evals", "120", "--seed", "3", "--quiet",
            "--fix", "sigma0=1e5,sigma1=300,alpha=2,b=0"]
    assert main(argv + ["--json", str(tmp_path / "inline.json")]) == 0
    before = _stats(address)
    assert main(argv + ["--json", str(tmp_path / "dask.json"), "--scheduler", address]) == 0
    after = _stats(address)
    inline = json.loads((tmp_path / "inline.json").read_text())
    dask = json.loads((tmp_path / "dask.json").read_text())
    assert dask["executor"] == "dask" and inline["executor"] != "dask"
    assert dask["params"] == inline["params"]          # bit for bit, same seed
    assert dask["fit_nrmse"] == inline["fit_nrmse"] and dask["n_evals"] == inline["n_evals"]
    rows = _delta(after, before, "rows")
    assert all(n > 0 for n in rows.values()), rows     # both workers evaluated
    assert sum(rows.values()) <= inline["n_evals"]     # populations; least squares local
    # the objective (with its data) went to each worker once, not once per population
    assert _delta(after, before, "objectives") == {"w1": 1, "w2": 1}
    assert max(_delta(after, before, "chunks").values()) > 1


def test_unreachable_scheduler_is_one_line_exit_2_and_nothing_lost(tmp_path, capsys,
                                                                   monkeypatch):
    import identification.cluster as cl
    monkeypatch.setattr(cl, "CONNECT_TIMEOUT", 1.0)
    with socket.socket() as s:  # a port nobody listens on
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    address = f"tcp://127.0.0.1:{port}"
    data = str(_csv(tmp_path / "run.csv"))
    out = tmp_path / "old.json"
    out.write_text('{"kept": true}')
    t0 = time.perf_counter()
    code = main(["identify", data, "--model", "lugre", "--json", str(out),
                 "--scheduler", address])
    err = capsys.readouterr().err.strip()
    assert code == 2 and time.perf_counter() - t0 < 10
    assert len(err.splitlines()) == 1 and address in err and "Traceback" not in err, err
    assert err.startswith("frictionlab identify: error: cannot reach the dask scheduler")
    assert out.read_text() == '{"kept": true}'          # nothing overwritten
    code = main(["diagnose", data, "--model", "lugre", "--scheduler", address])
    err = capsys.readouterr().err.strip()
    assert code == 2 and len(err.splitlines()) == 1 and address in err, err
    assert main(["identify", data, "--model", "lugre", "--scheduler", "nonsense://x"]) == 2
    assert "nonsense://x" in capsys.readouterr().err
    # the built-in benchmark runs in this process: refused before connecting, not ignored
    assert main(["diagnose", "--benchmark", "--scheduler", address]) == 2
    assert "the built-in benchmark runs in this process" in capsys.readouterr().err


def test_a_scheduler_without_workers_is_refused():
    from dask.distributed import LocalCluster
    from identification.cluster import SchedulerError
    with LocalCluster(n_workers=0, processes=False, protocol="tcp", host="127.0.0.1",
                      dashboard_address=":0") as lc:
        with pytest.raises(SchedulerError, match="has no worker after 0.5 s"):
            connect(lc.scheduler_address, timeout=0.5)


def test_file_bundle_is_written_once_per_machine_by_content(tmp_path, monkeypatch):
    import pickle
    import tempfile
    import identification.cluster as cl
    a = tmp_path / "a.fmu"
    a.write_bytes(b"first")
    b = tmp_path / "sub" / "b.fmu"
    b.parent.mkdir()
    b.write_bytes(b"second" * 1000)
    bundle = FileBundle({"plant": a, "law:lugre": b})
    assert bundle.nbytes == 6005 and len(bundle.digest) == 64
    assert FileBundle({"plant": a, "law:lugre": b}).digest == bundle.digest
    machine = tmp_path / "worker-tmp"
    machine.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(machine))
    monkeypatch.setattr(cl, "_EXTRACTED", {})
    n0 = cl._STATS["extracted"]
    there = pickle.loads(pickle.dumps(bundle)).paths()   # what a worker receives
    assert pathlib.Path(there["plant"]).read_bytes() == b"first"
    assert pathlib.Path(there["law:lugre"]).name == "b.fmu"
    assert str(machine) in there["plant"] and bundle.digest in there["plant"]
    monkeypatch.setattr(cl, "_EXTRACTED", {})               # another process, same machine
    assert pickle.loads(pickle.dumps(bundle)).paths() == there
    assert cl._STATS["extracted"] == n0 + 1
    assert oct(os.stat(os.path.dirname(os.path.dirname(there["plant"]))).st_mode & 0o777) \
        == "0o700"                                          # the user's private folder
    pathlib.Path(there["plant"]).write_bytes(b"FIRST")      # altered, same size: not used
    monkeypatch.setattr(cl, "_EXTRACTED", {})
    assert pickle.loads(pickle.dumps(bundle)).paths() == there
    assert pathlib.Path(there["plant"]).read_bytes() == b"first"
    assert cl._STATS["extracted"] == n0 + 2
    a.write_bytes(b"changed")                               # new content: a new folder
    assert FileBundle({"plant": a, "law:lugre": b}).digest != bundle.digest
    c = tmp_path / "sub" / "a.fmu"
    c.write_bytes(b"x")
    with pytest.raises(ValueError, match="two shipped files are named 'a.fmu'"):
        FileBundle({"plant": a, "conn:ctl": c})


def test_plant_fmu_identification_on_the_cluster_equals_inline(cluster, tmp_path):
    """A C cart FMU compiled here + the native LuGre FMU, differential evolution over Fc,
    Fs and the cart's mass: the dask run equals the inline one, both workers co-simulate,
    each writes the FMUs once into its own temporary folder (content-hash cache: a second
    identification finds them there). Least squares: its Jacobians' perturbed runs go to
    the workers, same result."""
    pytest.importorskip("fmpy")
    sys.path.insert(0, str(pathlib.Path(__file__).parent))
    from user_plants import build_c_cart
    from friction import make_model
    from friction.reference import simulate_mass
    from fmus.connect import MeasuredRecord, parse_connection
    from fmus.testing import built_native_fmus
    from identification.plant_fmu import identify_plant_fmu
    address, tmpdirs = cluster
    native = built_native_fmus(("lugre",))
    cart = build_c_cart(tmp_path / "cart")
    truth = dict(sigma0=1e5, sigma1=300.0, sigma2=0.4, Fc=1.0, Fs=1.5, vs=1e-3)
    t = np.arange(0.0, 0.4 + 1e-9, 1e-3)

    def force(t):
        return 2.2 * np.sin(2 * np.pi * 1.4 * t) + 0.6 * np.sin(2 * np.pi * 4.3 * t)

    x = simulate_mass(make_model("lugre", **truth), 1.5, t, force, rtol=1e-6)["x"]
    rec = MeasuredRecord(t, {"u": force(t) / 2.0, "x": x}, "run")
    conn = parse_connection({"step": 2e-4, "friction": {"input": "F_c", "sign": -1,
                                                        "v": "vel"},
                             "inputs": {"u": "u"}, "compare": {"pos": {"column": "x",
                                                                       "unit": "m"}},
                             "parameters": {"k_u": 2.0, "m": 1.0},
                             "identify": {"m": [0.5, 3.0]}}, "rig.toml")
    law = make_model("lugre", **truth).with_values(Fc=0.7, Fs=1.1)
    kw = dict(names=["Fc", "Fs", "plant.m"], algorithm="differential_evolution", seed=5,
              max_evals=60, fmu_dir=native, pop_size=10)
    inline = identify_plant_fmu(rec, cart, conn, law, **kw)
    client = connect(address, workers=2)
    try:
        before = _stats(address)
        res = identify_plant_fmu(rec, cart, conn, law, executor=client, **kw)
        mid = _stats(address)
        again = identify_plant_fmu(rec, cart, conn, law, executor=client, **kw)
        after = _stats(address)
    finally:
        client.close()
    assert res["executor"] == "dask" and inline["executor"] == "inline"
    assert res.params == inline.params and res.fit_nrmse == inline.fit_nrmse
    assert res.n_evals == inline.n_evals == 60 and again.params == inline.params
    rows = _delta(mid, before, "rows")
    assert all(n > 0 for n in rows.values()), rows
    # the FMUs reached each worker once, by value, into the worker's own folder...
    assert _delta(mid, before, "objectives") == {"w1": 1, "w2": 1}
    for w, s in mid.items():
        folder = s["folders"][-1]
        assert folder.startswith(tmpdirs[w]), (folder, tmpdirs[w])
        assert sorted(os.listdir(folder)) == ["cart.fmu", "lugre_native.fmu"]
    # ...once: the second identification found them by their content hash
    assert _delta(after, before, "extracted") == {"w1": 1, "w2": 1}
    assert _delta(after, mid, "reused") == {"w1": 1, "w2": 1}
    # least squares: the finite-difference Jacobian's D perturbed co-simulations per
    # iteration go to the workers too (the residual at the iterate stays here)
    kw_ls = dict(kw, algorithm="least_squares", max_evals=None, max_nfev=4)
    kw_ls.pop("pop_size")
    ls_inline = identify_plant_fmu(rec, cart, conn, law, **kw_ls)
    client = connect(address, workers=2)
    try:
        before = _stats(address)
        ls = identify_plant_fmu(rec, cart, conn, law, executor=client, **kw_ls)
        after = _stats(address)
    finally:
        client.close()
    assert ls.params == ls_inline.params and ls.fit_nrmse == ls_inline.fit_nrmse
    assert ls.n_evals == ls_inline.n_evals
    predicted = _delta(after, before, "predicted")
    assert all(n > 0 for n in predicted.values()) and sum(predicted.values()) % 3 == 0, \
        predicted


@pytest.mark.slow
def test_cli_diagnose_on_the_cluster_equals_inline(cluster, tmp_path, capsys):
    """diagnose --scheduler: the candidates' joint fits run one task per candidate on the
    workers (both get some); the report equals the in-process one."""
    address, _ = cluster
    data = str(_csv(tmp_path / "run.csv"))
    argv = ["diagnose", data, "--model", "lugre", "--quiet",
            "--candidates", "acceleration,asymmetry,inertia,delay"]
    assert main(argv + ["--json", str(tmp_path / "inline.json")]) == 0
    before = _stats(address)
    assert main(argv + ["--json", str(tmp_path / "dask.json"), "--scheduler", address]) == 0
    fits = _delta(_stats(address), before, "candidates")
    inline = json.loads((tmp_path / "inline.json").read_text())
    dask = json.loads((tmp_path / "dask.json").read_text())
    for rep in (inline, dask):
        rep.pop("timing", None)
    assert dask == inline
    assert sum(fits.values()) == 4 and all(n > 0 for n in fits.values()), fits


def _plain(rep) -> dict:
    """A report as JSON without its timings (wall-clock seconds differ run to run)."""
    d = json.loads(rep.to_json())
    d.pop("timing", None)
    for e in (d.get("effect_details") or {}).values():
        e.pop("seconds", None)
    for e in d.get("effects") or []:
        (e.get("fitted") or {}).pop("seconds", None)
    return d


@pytest.mark.slow
def test_plant_fmu_diagnosis_on_the_cluster_equals_inline(cluster, tmp_path):
    """The trajectory level through the user's plant FMU: each candidate's fit (a series of
    co-simulations of the C cart) runs on a worker, the closure with the plant, the records
    and the FMU files shipped once per worker; the report equals the in-process one."""
    pytest.importorskip("fmpy")
    sys.path.insert(0, str(pathlib.Path(__file__).parent))
    from user_plants import build_c_cart
    from friction import make_model
    from friction.reference import simulate_mass
    from fmus.connect import MeasuredRecord, parse_connection
    from fmus.testing import built_native_fmus
    from diagnosis.plant_fmu import diagnose_plant_fmu
    address, tmpdirs = cluster
    native = built_native_fmus(("friction_effects", "lugre"))
    cart = build_c_cart(tmp_path / "cart")
    truth = make_model("lugre", sigma0=1e5, sigma1=300.0, sigma2=0.4, Fc=1.0, Fs=1.5,
                       vs=1e-3).with_values(Fc_neg=0.7)  # a direction asymmetry

    def run(f1, name):
        t = np.arange(0.0, 0.5 + 1e-9, 1e-3)

        def force(t):
            return 2.2 * np.sin(2 * np.pi * f1 * t) + 0.6 * np.sin(2 * np.pi * 4.3 * t)

        x = simulate_mass(truth, 1.5, t, force, rtol=1e-6)["x"]
        return MeasuredRecord(t, {"u": force(t) / 2.0, "x": x}, name)

    fit, held = run(1.4, "fit"), run(1.9, "held")
    conn = parse_connection({"step": 2e-4, "friction": {"input": "F_c", "sign": -1,
                                                        "v": "vel", "x": "pos"},
                             "inputs": {"u": "u"}, "compare": {"pos": {"column": "x",
                                                                       "unit": "m"}},
                             "parameters": {"k_u": 2.0, "m": 1.5}}, "rig.toml")
    kw = dict(candidates=["asymmetry", "inertia", "delay"], fmu_dir=native, max_sims=4,
              max_sims_base=6, fit_names=["Fc"], greedy=False)
    inline = diagnose_plant_fmu(fit, [held], cart, conn, "lugre", **kw)
    client = connect(address, workers=2)
    try:
        before = _stats(address)
        rep = diagnose_plant_fmu(fit, [held], cart, conn, "lugre", executor=client, **kw)
        after = _stats(address)
    finally:
        client.close()
    assert _plain(rep) == _plain(inline)
    assert len(rep["effects"]) == 3
    fits = _delta(after, before, "candidates")
    assert sum(fits.values()) == 3 and all(n > 0 for n in fits.values()), fits
    for w, s in after.items():  # the FMUs written into each worker's own folder
        assert any(f.startswith(tmpdirs[w]) and "cart.fmu" in os.listdir(f)
                   for f in s["folders"]), s["folders"]


def test_a_worker_lost_between_populations_costs_time_not_results(cluster, tmp_path):
    """The worker process of w2 is killed after the objective reached it: the next
    population runs again on the worker left (then on w2's restart), the same costs. Last in
    the file: the nanny restarts w2 with fresh counters."""
    from friction import make_model
    from friction.dataset import load_dataset
    from identification.executors import DaskExecutor
    from identification.objectives import InProcessObjective
    address, _ = cluster
    obj = InProcessObjective(make_model("lugre"), load_dataset(_csv(tmp_path / "r.csv")),
                             ["Fc", "Fs"])
    X = np.array([[1.0, 1.5], [1.1, 1.4], [0.9, 1.6], [1.2, 1.3]])
    client = connect(address, workers=2)
    try:
        exe = DaskExecutor(client)
        first = exe.costs(obj, X)
        names = {a: w["name"] for a, w in client.scheduler_info()["workers"].items()}
        w2 = next(a for a, n in names.items() if n == "w2")
        pid = client.run(os.getpid, workers=[w2])[w2]
        os.kill(pid, signal.SIGKILL)
        again = exe.costs(obj, X)
        exe.close()
    finally:
        client.close()
    assert np.array_equal(first, obj.costs(X)) and np.array_equal(again, first)


def test_a_worker_dying_in_a_shipped_call_reruns_on_the_workers_left(cluster, tmp_path):
    """run_shipped (the diagnosis' candidate fits): a task that kills its worker process
    the first time it runs; the calls run again on the workers left, same results. Last
    in the file (a worker restarts)."""
    from identification.cluster import ShippedCall, run_shipped
    address, _ = cluster
    marker = tmp_path / "killed-once"

    def task(x):
        import os as os_
        import signal as signal_
        if x == 3 and not marker.exists():
            marker.write_text("a worker died here")
            os_.kill(os_.getpid(), signal_.SIGKILL)
        return x * x

    client = connect(address, workers=2)
    try:
        out = run_shipped(client, ShippedCall(task), [0, 1, 2, 3])
    finally:
        client.close()
    assert out == [0, 1, 4, 9] and marker.exists()
