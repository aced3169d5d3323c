"""The one progress convention (friction.progress): None/False silent, True a tqdm bar on
stderr (rate, ETA when the total is known; plain lines in a log), a tqdm bar advanced in
place, a callable(n, info); the CLI's --quiet prints nothing."""
from __future__ import annotations

import io

import numpy as np
import pytest
from tqdm import tqdm

from friction.progress import Progress, as_progress, report


def test_none_and_false_are_silent(capsys):
    for arg in (None, False):
        with as_progress(arg, "x", total=3) as p:
            p(1, "info")
            assert not p
    assert capsys.readouterr().err == ""


def test_true_is_a_bar_with_rate_and_eta_in_plain_log_lines(capsys):
    with as_progress(True, "run", total=4, unit="step", interval=0) as p:
        for k in range(4):
            p(1, f"cost={k}")
    err = capsys.readouterr().err
    assert "\r" not in err  # stderr is not a terminal: one plain line per redraw
    last = err.strip().splitlines()[-1]
    assert last.startswith("[run]") and "4/4" in last and "cost=3" in last
    assert "step/s" in last or "s/step" in last  # rate
    assert "<" in last  # elapsed<remaining: the ETA


def test_a_bar_that_never_advances_prints_nothing(capsys):
    with as_progress(True, "never", total=10):
        pass
    assert capsys.readouterr().err == ""


def test_a_callable_gets_n_and_info_and_a_tqdm_bar_is_advanced_in_place():
    calls = []
    with as_progress(lambda n, info: calls.append((n, info)), "x") as p:
        p(2, "a")
        p(0, "status")
    assert calls == [(2, "a"), (0, "status")]
    bar = tqdm(total=5, file=io.StringIO())
    with as_progress(bar) as p:
        p(3, "half")
    assert bar.n == 3 and not bar.disable and "half" in str(bar)  # still open: the caller's
    bar.close()
    inner = Progress(bar=lambda n, info: calls.append((n, info)))
    as_progress(inner)(1, "through")  # a Progress is itself a progress argument
    assert calls[-1] == (1, "through")
    with pytest.raises(TypeError, match="progress"):
        as_progress(3)


def test_report_writes_one_line(capsys):
    report("[demo 1/5] friction ...")
    report("hidden", enabled=False)
    assert capsys.readouterr().err == "[demo 1/5] friction ...\n"


def test_plant_simulate_counts_output_samples():
    from plants import make_plant
    plant = make_plant("damping_rig")
    got = []
    res = plant.simulate(0.05, progress=lambda n, info: got.append(n))
    assert got and sum(got) <= len(res) and all(n > 0 for n in got)


def test_cli_quiet_is_quiet_and_loud_shows_the_rate(tmp_path, capsys):
    from frictionlab.cli import main
    from friction import make_model
    t = np.arange(0.0, 0.5, 1e-3)
    v = 0.02 * np.sin(2 * np.pi * 2 * t)
    model = make_model("lugre")
    F = model.simulate(t, v)
    csv = tmp_path / "d.csv"
    x = np.concatenate([[0.0], np.cumsum(v[1:] * np.diff(t))])
    np.savetxt(csv, np.column_stack([t, x, v, F]), delimiter=",", header="t,x,v,F",
               comments="")
    assert main(["identify", str(csv), "--model", "lugre", "--quiet", "--max-evals", "40"]) == 0
    assert capsys.readouterr().err == ""
    assert main(["identify", str(csv), "--model", "lugre", "--max-evals", "40"]) == 0
    err = capsys.readouterr().err
    assert "[identify multistart_ls]" in err and ("it/s" in err or "s/it" in err)
