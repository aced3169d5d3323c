"""The ``frictionlab`` command: help for every subcommand, one-line errors, the demo."""
import json
import subprocess
import sys

import pytest

from frictionlab.cli import main

SUBCOMMANDS = ["demo", "build-fmus", "identify", "diagnose"]


def _run(*args):
    return subprocess.run([sys.executable, "-m", "frictionlab.cli", *args], capture_output=True,
                          text=True, timeout=600)


@pytest.mark.parametrize("cmd", SUBCOMMANDS)
def test_help(cmd, capsys):
    with pytest.raises(SystemExit) as e:
        main([cmd, "--help"])
    assert e.value.code == 0
    assert "usage: frictionlab" in capsys.readouterr().out


def test_bad_input_is_one_line_without_traceback(tmp_path):
    r = _run("identify", str(tmp_path / "missing.csv"), "--model", "lugre")
    assert r.returncode != 0
    assert "Traceback" not in r.stderr
    lines = [ln for ln in r.stderr.strip().splitlines() if ln.strip()]
    assert len(lines) == 1 and "error" in lines[0]
    bad = tmp_path / "bad.csv"
    bad.write_text("t,x,F\n0,0,0\n0.001,nan,1\n0.002,0,1\n")
    r = _run("diagnose", str(bad), "--model", "lugre")
    assert r.returncode != 0 and "Traceback" not in r.stderr


def test_unknown_demo_stage_fails_cleanly(tmp_path):
    assert main(["demo", "--out", str(tmp_path), "--only", "nonsense"]) == 2


def test_demo_friction_stage_writes_plots_and_summary(tmp_path):
    assert main(["demo", "--out", str(tmp_path), "--only", "friction", "--quick"]) == 0
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert "lugre" in summary["friction_laws"]["models"]
    for png in summary["friction_laws"]["figures"]:
        assert (tmp_path / png).stat().st_size > 10_000


@pytest.mark.slow
def test_demo_fmus_stage_writes_the_contract_cosim_summary(tmp_path):
    # CONTRACT.md: cosim_vs_reference = {plant: NRMSE at its data rate}, numbers
    assert main(["demo", "--out", str(tmp_path), "--only", "fmus", "--quick"]) == 0
    summary = json.loads((tmp_path / "summary.json").read_text())
    cvr = summary["cosim_vs_reference"]
    assert {"valve", "damping_rig", "forging_press", "xml350"} <= set(cvr)
    for plant, value in cvr.items():
        assert isinstance(value, float) and 0 <= value <= 1e-3, (plant, value)
        laws = summary["cosim_vs_reference_by_law"][plant]
        assert value == max(e["nrmse"] for e in laws.values())


@pytest.mark.slow  # about a minute: the real machines' diagnoses and the quick benchmark
def test_demo_diagnosis_stage_names_the_real_machines(tmp_path):
    assert main(["demo", "--out", str(tmp_path), "--only", "diagnosis"]) == 0
    d = json.loads((tmp_path / "summary.json").read_text())["diagnosis"]
    # EMPS: the worn screw's asymmetry on the second half of DATA_EMPS (the pulse record's
    # gap is the response to its controller steps: unexplained there)
    assert d["emps_time_split"]["verdict"]["cause"] == "asymmetry"
    assert d["emps"]["verdict"]["cause"] in ("asymmetry", "unexplained")
    assert d["pneumatic_o_ring"]["verdict"]["cause"] == "load"
    assert (tmp_path / "diagnosis_emps_time_split.html").exists()


def test_python_dash_m_frictionlab_is_the_command(tmp_path):
    # a venv used without activating it has no ``frictionlab`` on PATH: the package runs
    r = subprocess.run([sys.executable, "-m", "frictionlab", "identify",
                        str(tmp_path / "missing.csv"), "--model", "lugre"],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 2
    assert r.stderr.startswith("frictionlab identify: error:") and "missing.csv" in r.stderr
