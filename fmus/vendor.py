"""Copy a package into an FMU under a unique name, so FMUs never clash in one process.

``vendor_package("friction", dest, "_fl_lugre_friction")`` copies ``friction/*.py`` to
``dest/_fl_lugre_friction/`` and rewrites:

* absolute imports of the vendored packages (``from friction.x import``, ``import plants``)
  to their unique names (the ``renames`` map);
* numba ``cache=True`` to ``cache=False`` (an FMU unpacks into a fresh temporary folder each
  time, and numba's cache does not work for modules loaded by the pythonfmu runtime);
* top-level ``from scipy... import name`` to a lazy stub that imports scipy only when
  ``name`` is called, so an FMU runs where scipy is not installed (the FMU code paths
  never call them).

Modules whose name is in ``exclude`` (the reference integrator, demos, plotting) are left out.
"""
from __future__ import annotations

import pathlib
import re
import shutil

__all__ = ["vendor_package", "rewrite_source", "DEFAULT_EXCLUDE"]

#: modules an FMU never needs (scipy/matplotlib users and demo/CLI code)
DEFAULT_EXCLUDE = ("demo", "reference", "numerics", "cli", "plotting", "plots", "report")

_LAZY = '''def {name}(*args, **kwargs):  # lazy: vendored FMU copy (scipy only if called)
    try:
        from {module} import {orig} as _f
    except ImportError:
        if "{orig}" == "brentq":  # root bracketing used by parameter set-up: pure Python
            return _fl_brentq(*args, **kwargs)
        raise ImportError("{module}.{orig} needs scipy, which this FMU does not require "
                          "for simulation") from None
    return _f(*args, **kwargs)
'''

_BRENTQ = '''def _fl_brentq(f, a, b, args=(), xtol=2e-12, rtol=8.881784197001252e-16, maxiter=200,
               **_ignored):  # bisection fallback of scipy.optimize.brentq (vendored FMU copy)
    fa, fb = f(a, *args), f(b, *args)
    if fa == 0.0:
        return a
    if fb == 0.0:
        return b
    if (fa > 0) == (fb > 0):
        raise ValueError("f(a) and f(b) must have different signs")
    for _ in range(max(int(maxiter), 200) * 4):
        m = 0.5 * (a + b)
        fm = f(m, *args)
        if fm == 0.0 or abs(b - a) <= xtol + rtol * abs(m):
            return m
        if (fm > 0) == (fa > 0):
            a, fa = m, fm
        else:
            b = m
    return 0.5 * (a + b)
'''


def rewrite_source(text: str, renames: dict[str, str]) -> str:
    """Apply the import renames, the numba-cache and the lazy-scipy rewrites to a module.

    Parameters
    ----------
    text : str
        The module's source.
    renames : dict
        ``{package: its name in the FMU}``.
    """
    for old, new in renames.items():
        text = re.sub(rf"^(\s*)from\s+{old}(\s|\.)", rf"\1from {new}\2", text, flags=re.M)
        text = re.sub(rf"^(\s*)import\s+{old}(\s*$|\.|\s+as\s)", rf"\1import {new}\2", text,
                      flags=re.M)
        text = re.sub(rf"(import_module\(\s*[\"']){old}([\"'.])", rf"\1{new}\2", text)
    text = re.sub(r"cache\s*=\s*True", "cache=False", text)

    inserted = []

    def lazy(m: re.Match) -> str:
        module, names = m.group(1), m.group(2)
        names = names.strip().strip("()")
        stubs = []
        if not inserted:  # the fallbacks go before the first stub (module code may call them)
            inserted.append(True)
            stubs.append(_BRENTQ)
        for item in filter(None, (s.strip() for s in names.split(","))):
            orig, _, alias = item.partition(" as ")
            stubs.append(_LAZY.format(name=(alias or orig).strip(), module=module,
                                      orig=orig.strip()))
        return "\n".join(stubs)

    return re.sub(r"^from\s+(scipy[\w.]*)\s+import\s+(\([^)]*\)|[^\n]+)$", lazy, text,
                  flags=re.M)


def vendor_package(src: str | pathlib.Path, dest_dir: str | pathlib.Path, new_name: str,
                   renames: dict[str, str], exclude=DEFAULT_EXCLUDE) -> pathlib.Path:
    """Copy package ``src`` (a folder) to ``dest_dir/new_name`` with rewritten imports.

    Returns the new package folder. Sub-packages are copied recursively.

    Parameters
    ----------
    src : str or path
        The package folder.
    dest_dir : str or path
        Where the copy goes.
    new_name : str
        The copy's package name.
    renames : dict
        ``{package: its name in the FMU}`` for the imports to rewrite.
    exclude : sequence of str
        Module names left out (:data:`DEFAULT_EXCLUDE`).
    """
    src = pathlib.Path(src)
    out = pathlib.Path(dest_dir) / new_name
    if out.exists():
        shutil.rmtree(out)
    out.mkdir(parents=True)
    for f in sorted(src.rglob("*.py")):
        rel = f.relative_to(src)
        if "__pycache__" in rel.parts or "tests" in rel.parts:
            continue
        if rel.stem in exclude and len(rel.parts) == 1:
            continue
        target = out / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(rewrite_source(f.read_text(), renames))
    return out
