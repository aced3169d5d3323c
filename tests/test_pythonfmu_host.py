"""pythonfmu FMUs outside a Python process, and at process exit (issue 13, item 3).

* A plain C host (``tests/native_host/host.c``: dlopen, fmi2Instantiate, no Python linked)
  loads a pythonfmu FMU through its status shim, which loads libpython itself (the path found
  at build time, or ``$FRICTIONLAB_LIBPYTHON``): no ``LD_PRELOAD``, no ``LD_LIBRARY_PATH``,
  only ``PYTHONPATH`` for numpy and numba (this venv's; a Python that has them in its own
  site-packages needs nothing). The host's outputs equal the FMU stepped from Python bit for
  bit, and its rollback (get, serialize, deserialize, set state, redo) repeats the run.
* Fresh processes that instantiate, step and free a pythonfmu FMU exit cleanly: pythonfmu
  0.7 freed its interpreter guard twice at exit ("corrupted double-linked list" in about 1 of
  30 processes); the shim releases it once, before pythonfmu's static destructor.
"""
from __future__ import annotations

import os
import pathlib
import subprocess
import sys
import textwrap

import fmpy
import numpy as np
import pytest

import test_native_hosts as nh
from test_native_hosts import host  # noqa: F401 (the compiled C host: a fixture)

from fmus import status_shim
from fmus.master import fmu_values
from fmus.testing import built_fmus

try:
    status_shim.shim_library()
except status_shim.ShimUnavailable as exc:  # pragma: no cover - no C compiler here
    pytest.skip(f"no status shim: {exc}", allow_module_level=True)


def _python_path() -> str:
    """Where this Python finds numpy and numba (the host's Python needs them importable)."""
    import numba
    import numpy
    dirs = []
    for mod in (numpy, numba):
        d = str(pathlib.Path(mod.__file__).resolve().parents[1])
        if d not in dirs:
            dirs.append(d)
    return os.pathsep.join(dirs)


def _settings(md_vars, values) -> list:
    """(kind, name, value) host settings from Python parameter values (any FMU kind)."""
    kinds = {"Real": "real", "Boolean": "bool", "Integer": "int", "Enumeration": "int"}
    return [(kinds[md_vars[n].type], n, v) for n, v in fmu_values(md_vars, values).items()]


def _run(host, spec, where, env, timeout=300.0):
    path = nh.write_spec(spec, where)
    return subprocess.run([nh.ENV, "-i", *[f"{k}={v}" for k, v in env.items()], str(host),
                           str(path)], capture_output=True, text=True, cwd=where,
                          timeout=timeout)


def test_a_c_host_loads_a_pythonfmu_fmu_through_the_shim(host, tmp_path):
    path, name = status_shim.libpython()
    if not path:
        pytest.skip("this Python has no shared libpython for the shim to load")
    fmu = built_fmus(("lugre",)) / "lugre.fmu"
    un = nh.Unpacked(fmu, tmp_path)
    params, extra = nh.case_settings("lugre")
    values = {**params, **extra}
    inputs, outputs = nh.law_io("lugre", un.var)
    steps = 400
    U = np.column_stack([nh.recorded_motion("lugre", steps)[n] for n in inputs])
    spec = nh.host_spec(un, _settings(un.var, values), inputs, outputs, steps, tmp_path, U,
                        rollback=150, cycles=2)
    # nothing but PYTHONPATH (numpy, numba): no LD_PRELOAD of libpython any more
    res = _run(host, spec, tmp_path, {"PYTHONPATH": _python_path()})
    assert res.returncode == 0, res.stderr[-3000:]
    Yc = np.fromfile(tmp_path / "out.bin").reshape(steps + 1, len(outputs))
    Yp = nh.step_pythonfmu(fmu, values, inputs, outputs, U)
    assert np.array_equal(Yc, Yp)
    assert np.ptp(Yc[:, outputs.index("F")]) > 0.1  # the motion drove the law
    # a libpython that cannot be loaded is named, with what to set
    res = _run(host, spec, tmp_path, {"PYTHONPATH": _python_path(),
                                      "FRICTIONLAB_LIBPYTHON": "/nonexistent/libpython3.so"})
    assert res.returncode == 2, res.stderr[-2000:]
    assert "FRICTIONLAB_LIBPYTHON" in res.stderr and "/nonexistent/libpython3.so" in res.stderr


_CYCLES = textwrap.dedent('''
    import shutil, sys
    import fmpy
    from fmpy.fmi2 import FMU2Slave
    path, cycles = sys.argv[1], int(sys.argv[2])
    md = fmpy.read_model_description(path)
    for c in range(cycles):
        d = fmpy.extract(path)
        s = FMU2Slave(guid=md.guid, unzipDirectory=d,
                      modelIdentifier=md.coSimulation.modelIdentifier, instanceName="x")
        s.instantiate()
        s.setupExperiment(startTime=0.0)
        s.enterInitializationMode()
        s.exitInitializationMode()
        vr = {v.name: v.valueReference for v in md.modelVariables}
        for k in range(20):
            s.setReal([vr["v"]], [1e-3 * (1 + k % 3)])
            s.doStep(k * 1e-4, 1e-4)
        s.terminate()
        s.freeInstance()          # fmi2FreeInstance and unload the library, as fmpy does
        shutil.rmtree(d, ignore_errors=True)
    print("cycles done", cycles)
''')


def _fresh_processes(n_proc: int, cycles: int, tmp_path) -> list:
    fmu = built_fmus(("lugre",)) / "lugre.fmu"
    script = tmp_path / "cycles.py"
    script.write_text(_CYCLES)
    bad = []
    for k in range(n_proc):
        res = subprocess.run([sys.executable, str(script), str(fmu), str(cycles)],
                             capture_output=True, text=True, timeout=600)
        if res.returncode != 0 or f"cycles done {cycles}" not in res.stdout:
            bad.append((k, res.returncode, res.stderr[-500:]))
    return bad


def test_fresh_fmu_processes_exit_without_heap_corruption(tmp_path):
    # before the fix about 1 process in 3 to 12 aborted here ("corrupted double-linked list")
    assert _fresh_processes(6, 3, tmp_path) == []


@pytest.mark.slow
def test_a_thousand_cycles_in_fresh_processes_exit_cleanly(tmp_path):
    """1,020 instantiate/step/free cycles in 30 fresh processes: no abort, no error."""
    assert _fresh_processes(30, 34, tmp_path) == []


@pytest.mark.slow
def test_an_fmu_process_is_clean_under_valgrind(tmp_path):
    """valgrind memcheck over a process that instantiates, steps, frees and unloads the
    pythonfmu LuGre FMU and exits: no invalid read, write or free in the FMU's binaries (the
    shim, pythonfmu's library). pythonfmu 0.7 alone read its interpreter guard after its static
    destructor had freed it (``finalizePythonInterpreter``, at exit). numba's JIT is off
    (interpreted kernels; minutes instead of an hour under valgrind) - the exit path is the
    same. CPython's own uninitialised-value reports and ld.so's strncmp over-reads are not
    counted (no frame in the FMU)."""
    import shutil
    valgrind = shutil.which("valgrind")
    if valgrind is None:
        pytest.skip("valgrind is not installed")
    fmu = built_fmus(("lugre",)) / "lugre.fmu"
    script = tmp_path / "cycles.py"
    script.write_text(_CYCLES)
    log = tmp_path / "valgrind.txt"
    env = {**os.environ, "PYTHONMALLOC": "malloc", "NUMBA_DISABLE_JIT": "1"}
    res = subprocess.run([valgrind, "--error-limit=no", "--num-callers=30",
                          f"--log-file={log}", sys.executable, str(script), str(fmu), "1"],
                         capture_output=True, text=True, env=env, timeout=3000)
    assert res.returncode == 0 and "cycles done 1" in res.stdout, res.stderr[-2000:]
    text = log.read_text()
    assert "ERROR SUMMARY" in text
    bad = [b for b in _error_blocks(text)
           if any(k in b for k in ("Invalid read", "Invalid write", "Invalid free",
                                   "free'd", "Mismatched"))
           and ("_pythonfmu.so" in b or "fl_lugre.so" in b)]
    assert bad == [], "\n\n".join(bad)[:4000]


def _error_blocks(text: str) -> list[str]:
    """valgrind's error reports (one per block of lines between blank '==PID==' lines)."""
    out, cur = [], []
    for line in text.splitlines():
        body = line.split("== ", 1)[1] if "== " in line else ""
        if not body.strip():
            if cur:
                out.append("\n".join(cur))
            cur = []
        else:
            cur.append(body)
    if cur:
        out.append("\n".join(cur))
    return out
