"""Every FMU runs in a clean virtual environment without frictionlab (slow)."""
from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap

import pytest

SCRIPT = textwrap.dedent('''
    import json, sys, glob, os
    from fmpy import simulate_fmu
    from fmpy.validation import validate_fmu
    out = {}
    for path in sorted(glob.glob(os.path.join(sys.argv[1], "*.fmu"))):
        name = os.path.basename(path)[:-4]
        problems = validate_fmu(path)
        log = []
        def logger(*args):
            log.append(" ".join(a.decode() if isinstance(a, bytes) else str(a) for a in args[-2:]))
        try:
            res = simulate_fmu(path, stop_time=0.01, output_interval=1e-3, logger=logger)
        except Exception as exc:
            out[name] = {"problems": problems, "error": repr(exc), "log": log[-5:]}
            continue
        out[name] = {"problems": problems, "rows": len(res), "error": None, "log": log[-5:],
                     "finite": bool(all(all(abs(float(v)) < 1e300 for v in row) for row in res))}
    try:
        import frictionlab  # noqa: F401
        out["_frictionlab_importable"] = True
    except ImportError:
        out["_frictionlab_importable"] = False
    try:
        import scipy  # noqa: F401
        out["_scipy_importable"] = True
    except ImportError:
        out["_scipy_importable"] = False
    print(json.dumps(out))
''')


@pytest.mark.slow
def test_every_fmu_runs_in_a_clean_venv(tmp_path):
    from fmus.build import build_all, catalogue
    fmu_dir = tmp_path / "fmus"
    build_all(fmu_dir, progress=False, kinds=("pythonfmu",))
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    py = venv / "bin" / "python"
    pip = subprocess.run([str(py), "-m", "pip", "install", "-q", "numpy", "fmpy", "numba"],
                         capture_output=True, text=True)
    if pip.returncode != 0:
        pytest.skip(f"cannot install numpy/fmpy/numba into a venv: {pip.stderr[-300:]}")
    script = tmp_path / "run.py"
    script.write_text(SCRIPT)
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH",)}
    proc = subprocess.run([str(py), str(script), str(fmu_dir)], capture_output=True,
                          text=True, cwd=tmp_path, env=env, timeout=1800)
    assert proc.returncode == 0, proc.stderr[-2000:]
    out = json.loads(proc.stdout.strip().splitlines()[-1])
    assert out.pop("_frictionlab_importable") is False
    assert out.pop("_scipy_importable") is False
    assert set(out) == set(catalogue())
    for name, r in out.items():
        assert r["problems"] == [], name
        assert r["error"] is None, (name, r)
        assert r["rows"] >= 10 and r["finite"], (name, r)
