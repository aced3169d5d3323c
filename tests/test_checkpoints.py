"""Checkpoints (issue 16, item 3): every algorithm resumes to the uninterrupted result or
refuses a checkpoint by name; a checkpoint is a JSON-lines evaluation log that cannot run
code on load, and a file that is not one is refused."""
import json
import os
import pickle

import numpy as np
import pytest

from friction import make_model
from friction.dataset import Dataset
from identification import InProcessObjective, identify

TRUE = dict(sigma0=1e5, sigma1=300.0, sigma2=0.4, Fc=1.0, Fs=1.5, vs=1e-3)
NAMES = list(TRUE)


@pytest.fixture(scope="module")
def data():
    true = make_model("lugre", **TRUE)
    t = np.arange(0, 1.5, 1e-3)
    v = 0.01 * np.sin(2 * np.pi * 1.0 * t) + 0.002 * np.sin(2 * np.pi * 6 * t)
    F = true.simulate(t, v) + 0.01 * np.random.default_rng(0).standard_normal(t.size)
    return Dataset.from_arrays(t, F, v=v, name="syn")


@pytest.fixture(scope="module")
def start():
    return make_model("lugre", sigma0=3e4, sigma1=100.0, sigma2=1.0, Fc=0.5, Fs=2.5, vs=5e-3)


class Counting(InProcessObjective):
    """Counts simulated parameter sets (to see that a resume replays instead of simulating)."""
    sims = 0

    def predict(self, X):
        Counting.sims += np.atleast_2d(X).shape[0]
        return super().predict(X)


def _counting(model, data, names):
    return Counting(model, data, names)


def _interrupt_at(k):
    calls = {"n": 0}

    def progress(n=1, info=""):
        if n:
            calls["n"] += 1
            if calls["n"] == k:
                raise KeyboardInterrupt

    return progress


CASES = [  # algorithm, options, progress call to interrupt at
    (None, {}, 2),  # the default (multistart_ls): interrupted after its first start
    ("differential_evolution", dict(pop_size=5, max_iter=8), 4),
    ("cmaes", dict(max_iter=8), 4),
    ("chaotic_pso", dict(pop_size=10, max_iter=8), 4),
    ("iafsa", dict(n_fish=10, max_iter=6), 3),
    ("iffoa", dict(pop_size=20, max_iter=8), 4),
    ("adaptive_ga", dict(pop_size=10, max_iter=8), 4),
]


@pytest.mark.parametrize("algorithm,options,at", CASES,
                         ids=[c[0] or "default" for c in CASES])
def test_interrupted_run_resumes_to_the_uninterrupted_result(algorithm, options, at, data,
                                                             start, tmp_path):
    ck = tmp_path / "run.ckpt"
    kw = dict(algorithm=algorithm, names=NAMES, seed=7, objective=_counting, **options)
    Counting.sims = 0
    full = identify(data, start, **kw)
    full_sims = Counting.sims
    with pytest.raises(KeyboardInterrupt):
        identify(data, start, checkpoint=ck, progress=_interrupt_at(at), **kw)
    assert ck.exists(), "the interrupted run wrote nothing"
    Counting.sims = 0
    resumed = identify(data, start, checkpoint=ck, **kw)
    assert resumed.resumed
    assert resumed.params == full.params
    assert resumed.n_evals == full.n_evals
    assert resumed.cost_history == full.cost_history
    assert resumed.ci == full.ci
    # the logged part was replayed, not simulated again
    assert Counting.sims < full_sims
    # a finished log replays entirely: the same result without one simulation of the search
    Counting.sims = 0
    again = identify(data, start, checkpoint=ck, **kw)
    assert again.params == full.params
    assert Counting.sims <= 1 + len(NAMES) + 1  # final prediction (+ a recomputed Jacobian)


def test_alternating_ls_resumes_after_each_alternation(tmp_path):
    true = make_model("lugre", sigma0=1e5, sigma1=300.0, sigma2=0.4, Fc=1.0, Fs=1.5, vs=1e-3,
                      b=0.05)
    t = np.arange(0, 3, 1e-3)
    v = 0.01 * np.sin(2 * np.pi * 0.5 * t) + 0.003 * np.sin(2 * np.pi * 2 * t)
    d = Dataset.from_arrays(t, true.simulate(t, v), v=v)
    names = ["sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs", "b"]
    init = dict(sigma0=8e4, sigma1=250.0, sigma2=0.5, Fc=0.9, Fs=1.4, vs=1.2e-3, b=0.0)
    kw = dict(algorithm="alternating_ls", names=names, init=init, k=3)
    full = identify(d, make_model("lugre"), **kw)
    ck = tmp_path / "als.ckpt"
    with pytest.raises(KeyboardInterrupt):
        identify(d, make_model("lugre"), checkpoint=ck, progress=_interrupt_at(2), **kw)
    lines = ck.read_text().splitlines()
    assert len(lines) == 1 + 2  # header + the two finished alternations
    resumed = identify(d, make_model("lugre"), checkpoint=ck, **kw)
    assert resumed.resumed and resumed.params == full.params
    assert resumed.cost_history == full.cost_history and resumed.n_evals == full.n_evals


def _static_case():
    """Seed 004's constant-speed tests (no load, then loaded): what static_ls fits."""
    true = make_model("load_lugre")
    v = np.concatenate([np.geomspace(2e-6, 2e-3, 30)] * 2)
    load = np.concatenate([np.zeros(30), np.full(30, 5e4)])
    d = Dataset.from_arrays(np.arange(v.size, dtype=float), true.steady_state(v, load=load),
                            v=v, a=np.zeros_like(v), load=load, check_units=False)
    return d, true, ["Fc0", "Fs0", "vs", "sigma20"]


@pytest.mark.parametrize("algorithm", ["least_squares", "static_ls"])
def test_algorithms_that_cannot_resume_refuse_a_checkpoint_by_name(algorithm, data, start,
                                                                   tmp_path):
    d, model, names = (data, start, NAMES) if algorithm == "least_squares" else _static_case()
    identify(d, model, algorithm=algorithm, names=names)  # fine without a checkpoint
    ck = tmp_path / "x.ckpt"
    with pytest.raises(ValueError, match=f"{algorithm}.*cannot use a checkpoint") as exc:
        identify(d, model, algorithm=algorithm, names=names, checkpoint=ck)
    assert "\n" not in str(exc.value)
    assert not ck.exists()


def test_cli_default_algorithm_writes_and_resumes_a_checkpoint(data, tmp_path, capsys):
    from frictionlab.cli import main
    csv, ck, out = tmp_path / "d.csv", tmp_path / "run.ckpt", tmp_path / "r.json"
    data.to_csv(csv)
    args = ["identify", str(csv), "--model", "lugre", "--seed", "1", "--checkpoint", str(ck),
            "--json", str(out)]
    assert main(args) == 0
    first = json.loads(out.read_text())
    head = json.loads(ck.read_text().splitlines()[0])
    assert head["format"] == "frictionlab-checkpoint" and head["algorithm"] == "multistart_ls"
    assert main(args) == 0
    second = json.loads(out.read_text())
    assert second["resumed"] and second["params"] == first["params"]
    capsys.readouterr()
    assert main(["identify", str(csv), "--model", "lugre", "--algorithm", "least_squares",
                 "--checkpoint", str(tmp_path / "ls.ckpt")]) == 2
    err = capsys.readouterr().err.strip()
    assert "least_squares" in err and "checkpoint" in err and len(err.splitlines()) == 1


class _Exploit:
    """Unpickling this runs ``os.mkdir(marker)``: what a pickle checkpoint could do."""

    def __init__(self, marker):
        self.marker = marker

    def __reduce__(self):
        return (os.mkdir, (self.marker,))


@pytest.mark.parametrize("algorithm", [None, "cmaes", "differential_evolution"])
def test_a_pickle_checkpoint_is_refused_and_never_executed(algorithm, data, start, tmp_path):
    marker = tmp_path / "pwned"
    ck = tmp_path / "evil.ckpt"
    ck.write_bytes(pickle.dumps({"version": 1, "state": _Exploit(str(marker))}))
    with pytest.raises(ValueError, match="not a frictionlab checkpoint"):
        identify(data, start, algorithm=algorithm, names=NAMES, checkpoint=ck, max_evals=50)
    assert not marker.exists()


@pytest.mark.parametrize("content", [b"hello, world\n", b'{"some": "json"}\n', b"\x00\x01\x02",
                                     b"[1, 2, 3]\n"])
def test_a_file_that_is_not_a_checkpoint_is_refused(content, data, start, tmp_path):
    ck = tmp_path / "other.ckpt"
    ck.write_bytes(content)
    with pytest.raises(ValueError, match="not a frictionlab checkpoint") as exc:
        identify(data, start, names=NAMES, checkpoint=ck)
    assert "\n" not in str(exc.value)
    assert ck.read_bytes() == content  # left untouched


def test_a_truncated_last_line_is_tolerated_and_a_corrupt_middle_refused(data, start,
                                                                         tmp_path):
    kw = dict(algorithm="chaotic_pso", names=NAMES, seed=3, pop_size=10, max_iter=6)
    full = identify(data, start, **kw)
    ck = tmp_path / "cut.ckpt"
    identify(data, start, checkpoint=ck, **kw)
    lines = ck.read_bytes().split(b"\n")[:-1]
    # an interrupted write: the last record cut in the middle
    ck.write_bytes(b"\n".join(lines[:-1]) + b"\n" + lines[-1][: len(lines[-1]) // 2])
    r = identify(data, start, checkpoint=ck, **kw)
    assert r.resumed and r.params == full.params and r.n_evals == full.n_evals
    assert ck.read_bytes().endswith(b"\n")  # the cut line was replaced by a whole one
    for line in ck.read_bytes().split(b"\n")[:-1]:
        json.loads(line)
    # damage in the middle is not an interrupted write: refused
    lines = ck.read_bytes().split(b"\n")
    lines[2] = lines[2][:10]
    ck.write_bytes(b"\n".join(lines))
    with pytest.raises(ValueError, match="corrupt at line 3"):
        identify(data, start, checkpoint=ck, **kw)


def test_another_runs_checkpoint_is_refused(data, start, tmp_path):
    ck = tmp_path / "a.ckpt"
    kw = dict(algorithm="chaotic_pso", names=NAMES, pop_size=10, max_iter=2)
    identify(data, start, seed=1, checkpoint=ck, **kw)
    with pytest.raises(ValueError, match="another run"):
        identify(data, start, seed=2, checkpoint=ck, **kw)
    other = start.with_values(sigma2=0.9)  # a different starting / fixed value
    with pytest.raises(ValueError, match="another run"):
        identify(data, other, seed=1, checkpoint=ck, **kw)


def test_changed_options_continue_live_from_where_the_log_differs(data, start, tmp_path):
    """IFFOA's flight radius depends on max_iter: a longer run asks differently from the
    first iteration on; the log is then dropped past that point and the result is the
    uninterrupted one."""
    ck = tmp_path / "o.ckpt"
    kw = dict(algorithm="iffoa", names=NAMES, seed=2, pop_size=10)
    identify(data, start, checkpoint=ck, max_iter=4, **kw)
    full = identify(data, start, max_iter=8, **kw)
    r = identify(data, start, checkpoint=ck, max_iter=8, **kw)
    assert r.params == full.params and r.cost_history == full.cost_history
