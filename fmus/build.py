"""Build the frictionlab FMUs: native (plain C, :mod:`fmus.native`) and pythonfmu ones.

``build_all(out)`` (the ``frictionlab build-fmus --out DIR`` command) builds one FMU per
friction law in ``friction.MODELS``, the ``mass`` FMU of the mass+friction proof loop and, once
the ``plants`` package provides them, the plant and controller FMUs. Each FMU

* carries the code it needs: ``friction`` (and ``plants``) vendored under a unique package
  name (``_fl_<fmu>_friction``...), the slave runtime (``_fl_<fmu>_runtime``) and pythonfmu,
  so it runs with numpy + numba only and any set of FMUs loads into one process;
* has a complete ``modelDescription.xml`` (units, bounds, output dependencies,
  InitialUnknowns, DefaultExperiment; see :mod:`fmus.modeldescription`);
* passes ``fmpy.validation.validate_fmu`` with zero problems (checked after each build).

Error statuses: the pythonfmu 0.7 binary maps an exception raised by the slave to
``fmi2Fatal`` and a refused step to ``fmi2Discard``, and has no ``fmi2Error`` path. So each
FMU's ``binaries/linux64/<modelIdentifier>.so`` is our status shim
(:mod:`fmus.status_shim`, compiled once with the system C compiler and cached), with
pythonfmu's library next to it as ``<modelIdentifier>_pythonfmu.so``: a call during which
the slave logged an error returns ``fmi2Error``. ``binaries/win64/<modelIdentifier>.dll`` is
the same shim cross-compiled with MinGW-w64 (``x86_64-w64-mingw32-gcc``), in front of
pythonfmu's ``<modelIdentifier>_pythonfmu.dll``. Our slaves never raise on bad input; they
reject the value with an error-level message naming it (see :mod:`fmus.runtime`). Without a
C compiler (linux64) or without MinGW-w64 (win64) the build warns and ships pythonfmu's
binary for that platform as is; bad input there gives ``fmi2Discard`` at the next
``fmi2DoStep``.
"""
from __future__ import annotations

import dataclasses
import os
import pathlib
import sys
import tempfile
from typing import Callable

from frictionlab.progress import report

from . import runtime, status_shim
from .modeldescription import model_description_xml
from .vendor import vendor_package

__all__ = ["FmuRecipe", "catalogue", "build_fmu", "build_all", "validate", "REPO"]

REPO = pathlib.Path(__file__).resolve().parents[1]

#: default experiment of the friction-law and mass FMUs [s]
LAW_EXPERIMENT = {"startTime": 0.0, "stopTime": 1.0, "stepSize": 1e-4}


@dataclasses.dataclass
class FmuRecipe:
    """How to build one FMU.

    Attributes
    ----------
    name : str
        File stem (``<name>.fmu``) and the key used by ``build_all(only=...)``.
    base : str
        Slave base class in :mod:`fmus.runtime` (``LawSlave``, ``MassSlave``,
        ``StepperSlave``, ``BlockSlave``).
    variables : callable
        Returns the :class:`fmus.runtime.Var` list (build-time, from the repository packages).
    attributes : dict
        Class attributes of the generated slave class; the string ``{pkg:friction}`` (or
        ``{pkg:plants}``) is replaced by the FMU's unique vendored package name.
    packages : tuple of str
        Repository packages to vendor.
    description : str
    default_experiment : dict
    """
    name: str
    base: str
    variables: Callable[[], list]
    attributes: dict
    packages: tuple = ("friction",)
    description: str = ""
    default_experiment: dict = dataclasses.field(default_factory=lambda: dict(LAW_EXPERIMENT))

    @property
    def model_identifier(self) -> str:
        return f"fl_{self.name}"

    def package_name(self, pkg: str) -> str:
        return f"_fl_{self.name}_{pkg}"


def _law_recipes() -> list[FmuRecipe]:
    import friction
    out = []
    for name, cls in friction.MODELS.items():
        doc = (cls.__doc__ or name).strip().splitlines()[0]
        out.append(FmuRecipe(
            name=name, base="LawSlave",
            variables=(lambda cls=cls: runtime.law_variables(cls, probe=True)),
            attributes=dict(law=name, friction_package="{pkg:friction}"),
            description=f"Friction law '{name}': {doc}"))
    return out


def _mass_recipe() -> FmuRecipe:
    return FmuRecipe(name="mass", base="MassSlave", variables=runtime.mass_variables,
                     attributes={}, packages=(),
                     description="Rigid mass driven by a sinusoidal force against an "
                                 "external friction force (mass+friction proof loop)")


def _effects_recipe() -> FmuRecipe:
    return FmuRecipe(name="friction_effects", base="EffectsSlave",
                     variables=runtime.effects_variables,
                     attributes=dict(friction_package="{pkg:friction}"),
                     description="Friction effects block between a law FMU and a plant FMU: "
                                 "acceleration-dependent part, load-, position- and "
                                 "time-dependent levels (friction.extensions)")


def _plant_recipes() -> list[FmuRecipe]:
    try:
        from . import plant_fmus
    except ImportError:
        return []
    return plant_fmus.recipes()


def catalogue() -> dict[str, FmuRecipe]:
    """All FMUs this build knows, by name (laws, ``mass``, then plants and controllers)."""
    recipes = _law_recipes() + [_mass_recipe(), _effects_recipe()] + _plant_recipes()
    return {r.name: r for r in recipes}


def _script(recipe: FmuRecipe) -> str:
    rt = recipe.package_name("runtime")
    lines = [f'"""FMU slave {recipe.model_identifier} (generated by fmus.build)."""',
             f"from {rt} import {recipe.base}", "",
             "# pythonfmu <= 0.7 (issue NTNU-IHB/PythonFMU#228) re-executes this file and drops one",
             "# reference to the module's globals per instantiation; every execution adds one back",
             "# so the module survives any number of instances in a process.",
             '_fl_keepalive = globals().setdefault("_fl_keepalive_refs", [])',
             "_fl_keepalive.append(globals())", "",
             f"class {recipe.model_identifier}({recipe.base}):",
             f"    model_identifier = {recipe.model_identifier!r}",
             f"    fmu_description = {recipe.description!r}"]
    for key, value in recipe.attributes.items():
        if isinstance(value, str):
            for pkg in ("friction", "plants", "fmus"):
                value = value.replace("{pkg:%s}" % pkg, recipe.package_name(pkg))
        lines.append(f"    {key} = {value!r}")
    return "\n".join(lines) + "\n"


def _forget_modules(prefixes) -> None:
    for key in list(sys.modules):
        if any(key == p or key.startswith(p + ".") for p in prefixes):
            del sys.modules[key]


def build_fmu(recipe: FmuRecipe, out: str | os.PathLike) -> pathlib.Path:
    """Build one FMU into folder ``out``; returns the ``.fmu`` path."""
    from pythonfmu.builder import FmuBuilder
    from fmpy import read_model_description

    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    dest = out / f"{recipe.name}.fmu"
    renames = {p: recipe.package_name(p) for p in ("friction", "plants")}
    with tempfile.TemporaryDirectory(prefix=f"flfmu_{recipe.name}_") as tmp:
        stage = pathlib.Path(tmp)
        files = []
        for pkg in recipe.packages:
            files.append(vendor_package(REPO / pkg, stage, recipe.package_name(pkg), renames))
        rt = stage / f"{recipe.package_name('runtime')}.py"
        rt.write_text((pathlib.Path(__file__).parent / "runtime.py").read_text())
        files.append(rt)
        script = stage / f"{recipe.model_identifier}.py"
        script.write_text(_script(recipe))
        prefixes = [recipe.model_identifier, recipe.package_name("runtime")] + \
            [recipe.package_name(p) for p in recipe.packages]
        path_before = list(sys.path)
        try:
            FmuBuilder.build_FMU(script, dest=dest, project_files=files)
        finally:
            sys.path[:] = path_before
            _forget_modules(prefixes)
    guid = read_model_description(str(dest), validate=False).guid
    xml = model_description_xml(recipe.variables(), model_identifier=recipe.model_identifier,
                                guid=guid, description=recipe.description,
                                default_experiment=recipe.default_experiment,
                                log_categories=runtime.SlaveBase.log_categories)
    replace, rename = {"modelDescription.xml": xml}, {}
    for platform in status_shim.PLATFORMS:
        shim = status_shim.shim_or_warn(platform)
        if shim is not None:
            shim_rename, shim_replace = status_shim.shim_members(recipe.model_identifier,
                                                                 shim, platform)
            rename.update(shim_rename)
            replace.update(shim_replace)
    status_shim.rewrite_fmu(dest, replace, rename)
    return dest


def validate(path) -> list[str]:
    """``fmpy.validation.validate_fmu`` problems of one FMU (empty list: valid)."""
    from fmpy.validation import validate_fmu
    return validate_fmu(str(path))


def build_all(out: str | os.PathLike, only=None, *, progress: bool = True,
              kinds=("native", "pythonfmu")) -> dict[str, pathlib.Path]:
    """Build (and validate) every FMU into folder ``out``: the native ones
    (``<name>_native.fmu``, plain C, :mod:`fmus.native.build`) and the pythonfmu ones
    (``<name>.fmu``).

    Parameters
    ----------
    out : path
        Output folder (created).
    only : list of str, optional
        Names to build (see :func:`catalogue` and :func:`fmus.native.build.native_catalogue`);
        a name both know is built in both kinds, ``<name>_native`` natively only; default all.
    progress : bool
        Print one progress line per FMU on stderr.
    kinds : tuple of str
        ``"native"`` and/or ``"pythonfmu"``.

    Returns
    -------
    dict
        name -> path of the built FMU (native ones keyed ``<name>_native``).

    Raises
    ------
    ValueError
        Unknown names in ``only``.
    RuntimeError
        An FMU fails ``fmpy`` validation (the problems are listed), or the native FMUs could
        not be compiled (no C compiler: the message says what to install; the pythonfmu FMUs
        are built all the same).
    """
    from .native.build import SUFFIX, build_native, native_catalogue
    from .native.ckernels import NativeBuildError
    cat = catalogue() if "pythonfmu" in kinds else {}
    ncat = native_catalogue() if "native" in kinds else {}
    if not only:
        py_names, nat_names = list(cat), list(ncat)
    else:
        py_names, nat_names, unknown = [], [], []
        for n in only:
            if n.endswith(SUFFIX) and n[:-len(SUFFIX)] in ncat:
                nat_names.append(n[:-len(SUFFIX)])
                continue
            if n in ncat:
                nat_names.append(n)
            if n in cat:
                py_names.append(n)
            if n not in ncat and n not in cat:
                unknown.append(n)
        if unknown:
            raise ValueError(f"unknown FMU name(s) {unknown}; choose from "
                             f"{sorted(set(cat) | set(ncat))}")
    total = len(py_names) + len(nat_names)
    built, k, native_error = {}, 0, None
    for name in nat_names:
        k += 1
        try:
            path = build_native(name, out)
        except NativeBuildError as exc:
            native_error = exc
            report(f"[build-fmus] native FMUs skipped: {str(exc).splitlines()[0]}", progress)
            k += len(nat_names) - nat_names.index(name) - 1
            break
        _check_valid(path)
        report(f"[build-fmus {k}/{total}] {path} (native, valid)", progress)
        built[name + SUFFIX] = path
    for name in py_names:
        k += 1
        path = build_fmu(cat[name], out)
        _check_valid(path)
        report(f"[build-fmus {k}/{total}] {path} (pythonfmu, valid)", progress)
        built[name] = path
    if native_error is not None:
        raise RuntimeError(f"the native FMUs were not built ({str(native_error).splitlines()[0]}"
                           f"); the pythonfmu FMUs were") from native_error
    return built


def _check_valid(path) -> None:
    problems = validate(path)
    if problems:
        raise RuntimeError(f"{path.name} fails fmpy validation: " + "; ".join(problems))
