"""Layout of the diagnosis package: every module imports on its own in a fresh interpreter,
and the modules' top-level imports form no circle (issue 15 item 6)."""
import ast
import os
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PKG = os.path.join(ROOT, "diagnosis")


def _modules() -> dict:
    """Module name -> file of every module of the diagnosis package (subpackages too)."""
    out = {}
    for folder, _, files in os.walk(PKG):
        if "__pycache__" in folder:
            continue
        for f in files:
            if f.endswith(".py"):
                path = os.path.join(folder, f)
                rel = os.path.relpath(path, ROOT)[:-3].replace(os.sep, ".")
                out[rel[:-len(".__init__")] if rel.endswith(".__init__") else rel] = path
    return out


def _top_level_imports(name: str, path: str, known) -> set:
    """diagnosis modules imported at module level (not inside functions) by ``name``."""
    tree = ast.parse(open(path).read())
    pkg = name if path.endswith("__init__.py") else name.rsplit(".", 1)[0]
    out = set()
    for node in tree.body:
        if isinstance(node, ast.Import):
            mods = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parts = pkg.split(".")
                parts = parts[:len(parts) - node.level + 1]
                base = ".".join(parts + ([base] if base else []))
            mods = [f"{base}.{a.name}" if f"{base}.{a.name}" in known else base
                    for a in node.names]
        else:
            continue
        # a package's own __init__ runs before its modules: importing it is no circle
        out.update(m for m in mods if m in known and m != name
                   and not name.startswith(m + "."))
    return out


def test_no_import_circle():
    mods = _modules()
    graph = {m: _top_level_imports(m, p, mods) for m, p in mods.items()}
    state = {}

    def visit(m, stack):
        state[m] = 1  # on the current path
        for d in sorted(graph[m]):
            if state.get(d) == 1:
                pytest.fail(f"import circle: {' -> '.join(stack[stack.index(d):] + [d])}")
            if d not in state:
                visit(d, stack + [d])
        state[m] = 2

    for m in sorted(graph):
        if m not in state:
            visit(m, [m])


def test_shared_verdict_imports_neither_level():
    mods = _modules()
    deps = _top_level_imports("diagnosis.verdict", mods["diagnosis.verdict"], mods)
    assert not deps & {"diagnosis.core", "diagnosis.trajectory"}


@pytest.mark.parametrize("name", sorted(m for m in _modules() if m != "diagnosis.__main__"))
def test_module_imports_alone(name):
    r = subprocess.run([sys.executable, "-c", f"import {name}"], cwd=ROOT,
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr[-2000:]
