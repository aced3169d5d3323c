"""Layout of the diagnosis package: every module imports on its own in a fresh interpreter,
the modules' imports form no circle - neither at the top nor inside functions - and every
effect is one record (issue 15 item 6)."""
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


def _top_level_imports(name: str, path: str, known, lazy: bool = False) -> set:
    """diagnosis modules imported by ``name`` at module level (and inside functions too
    with ``lazy``)."""
    tree = ast.parse(open(path).read())
    pkg = name if path.endswith("__init__.py") else name.rsplit(".", 1)[0]
    out = set()
    for node in (ast.walk(tree) if lazy else tree.body):
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


#: function-level imports that still close a circle (none left)
KNOWN_LAZY = set()


@pytest.mark.parametrize("lazy", [False, True], ids=["top-level", "with-function-level"])
def test_no_import_circle(lazy):
    mods = _modules()
    graph = {m: _top_level_imports(m, p, mods, lazy) for m, p in mods.items()}
    for a, b in KNOWN_LAZY if lazy else ():
        graph.get(a, set()).discard(b)
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


#: run in one fresh interpreter: the third-party libraries loaded once, then each module
#: imported in a forked child that has loaded none of ours (one interpreter per module spent
#: 34 s of the suite's 10-minute budget loading numpy, scipy and numba a hundred times)
_IMPORT_EACH = r"""
import os, sys
import numpy, scipy.optimize, scipy.signal, scipy.interpolate, scipy.linalg, numba
assert not [m for m in sys.modules if m.split('.')[0] in
            ('diagnosis', 'friction', 'identification', 'plants', 'fmus', 'frictionlab')]
failed, running = [], {}
names = sys.argv[1:]
while names or running:
    if names and len(running) < 2:  # two children at a time: the suite's 2 cores
        name = names.pop(0)
        pid = os.fork()
        if pid == 0:
            try:
                __import__(name)
            except BaseException as exc:
                sys.stderr.write(f"{name}: {type(exc).__name__}: {exc}\n")
                os._exit(1)
            os._exit(0)
        running[pid] = name
        continue
    pid, status = os.wait()
    if status != 0:
        failed.append(running[pid])
    del running[pid]
print(' '.join(sorted(failed)))
"""


def test_every_module_imports_alone():
    # __main__ modules run the benchmark when imported
    names = sorted(m for m in _modules() if not m.endswith(".__main__"))
    r = subprocess.run([sys.executable, "-c", _IMPORT_EACH, *names], cwd=ROOT,
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr[-2000:]
    assert r.stdout.split() == [], r.stderr[-4000:]


def test_a_module_that_cannot_import_alone_is_caught(tmp_path):
    # the check itself: a module whose import fails is reported by name
    (tmp_path / "broken_mod.py").write_text("import diagnosis.no_such_module\n")
    r = subprocess.run([sys.executable, "-c", _IMPORT_EACH, "broken_mod", "json"],
                       cwd=ROOT, capture_output=True, text=True,
                       env={**os.environ, "PYTHONPATH": f"{tmp_path}{os.pathsep}{ROOT}"})
    assert r.stdout.split() == ["broken_mod"]
    assert "no_such_module" in r.stderr


def test_effect_records_hold_together():
    """Each effect is one record (diagnosis.effects.EFFECTS); the lists the package uses are
    derived from it and its references resolve."""
    from friction.extensions import EXTENSIONS
    from diagnosis import effects
    from diagnosis.benchmark import CASES, EXPECTED_EVIDENCE, EXPECTED_FAMILIES
    from diagnosis.effect_law import FORCE_EFFECTS
    from diagnosis.trajectory import FMU_EFFECTS
    from diagnosis.effects import make_context
    from diagnosis.benchmark import make_case
    ctx = make_context(make_case("load", n=2000))
    for name, e in effects.EFFECTS.items():
        assert e.name == name == e.candidate.name
        assert e.plant_entry in effects.PLANT_ENTRIES
        if e.plant_entry == "force":
            # the friction_effects block and EffectLaw run friction.extensions' formula
            assert name in EXTENSIONS and e.levels
            assert set(e.levels) <= {x.name for x in e.parameters(ctx, "formula")}
        for form in e.truths:
            assert callable(e.truth(form))
        for ref in (e.generic_truth, e.truth_applies):
            assert ref is None or callable(effects.resolve(ref))
        for p in e.parameters(ctx):
            assert p.lo <= p.x0 <= p.hi and p.unit, (name, p)
    assert effects.EFFECT_NAMES == tuple(effects.CANDIDATES) == tuple(effects.EFFECTS)
    assert FORCE_EFFECTS == effects.FORCE_EFFECTS
    assert FMU_EFFECTS == effects.FMU_EFFECTS
    assert EXPECTED_FAMILIES == effects.EXPECTED_FAMILIES
    assert EXPECTED_EVIDENCE == effects.EXPECTED_EVIDENCE
    assert CASES[-2:] == ("clean", "outside")
    assert set(CASES[:-2]) == {n for n, e in effects.EFFECTS.items() if e.truths}
