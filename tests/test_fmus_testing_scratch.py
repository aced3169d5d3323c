"""The test helpers' FMU folders are removed when the process that built them ends."""
import os
import subprocess
import sys
import pathlib

ROOT = pathlib.Path(__file__).resolve().parents[1]


def test_built_native_fmus_folder_is_gone_after_the_process():
    code = ("from fmus.testing import built_native_fmus\n"
            "out = built_native_fmus(('lugre',))\n"
            "assert (out / 'lugre_native.fmu').is_file()\n"
            "print(out)\n")
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         cwd=ROOT, env=env, timeout=300)
    assert res.returncode == 0, res.stderr[-2000:]
    out = pathlib.Path(res.stdout.strip().splitlines()[-1])
    assert out.name.startswith("frictionlab_native_")
    assert not out.exists()
