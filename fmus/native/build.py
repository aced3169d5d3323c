"""Build the native FMUs: friction laws, the friction_effects block, the mass and the EMPS
axis and controller (:data:`PLANT_NATIVE`), in C.

A native FMU ``<name>_native.fmu`` holds

* ``binaries/linux64/<id>.so`` (system C compiler) and ``binaries/win64/<id>.dll`` (MinGW-w64
  cross compiler ``x86_64-w64-mingw32-gcc``, Debian package ``gcc-mingw-w64-x86-64``; without
  it the build warns and leaves win64 out) - each needs nothing at run time but the C library;
* ``sources/``: every C file and header it was compiled from (flat, so ``cc *.c`` builds it)
  and ``buildDescription.xml``, so a host can build it for a platform we did not (darwin64);
* ``modelDescription.xml`` written from the same variable list as the C table
  (:mod:`fmus.native.variables`), with Co-Simulation (and Model Exchange once declared).

The model identifier is ``fl_native_<name>``, so a native and a pythonfmu FMU of the same law
load side by side in one process.
"""
from __future__ import annotations

import hashlib
import os
import pathlib
import shutil
import subprocess
import tempfile
import uuid
import warnings
import zipfile

from .ckernels import CSRC, NativeBuildError, compiler
from .description import build_description, model_description
from .variables import (EMPS_PARAMS, NVar, c_table, effects_variables,
                        emps_axis_variables, emps_controller_variables, law_variables,
                        mass_variables)

__all__ = ["NativeRecipe", "native_catalogue", "build_native", "MINGW_CC", "SUFFIX",
           "LAW_EXPERIMENT", "PLANT_NATIVE"]

#: file-name suffix that tells a native FMU from a pythonfmu one
SUFFIX = "_native"
#: MinGW-w64 cross compiler for win64 (override: ``$FRICTIONLAB_MINGW_CC``)
MINGW_CC = "x86_64-w64-mingw32-gcc"
#: default experiment of the law, effects and mass FMUs [s]
LAW_EXPERIMENT = {"startTime": 0.0, "stopTime": 1.0, "stepSize": 1e-4}
#: the kinds whose Model Exchange interface is declared (proven against the reference)
MODEL_EXCHANGE = True
#: native FMUs of a worked plant case (Co-Simulation only: sampled blocks), built by the case
#: (:func:`plants.studies.emps.build_native_fmus`), not part of :func:`native_catalogue`:
#: name -> (C kind, variables, continuous states, description, default experiment)
PLANT_NATIVE = {
    "emps_axis": ("EMPS_AXIS", emps_axis_variables, 2,
                  "EMPS axis (native C): carriage mass driven by gtau times the drive voltage "
                  "sampled at 1/Ts and applied delay later, against an external friction force",
                  {"startTime": 0.0, "stopTime": 1.0, "stepSize": 1e-3}),
    "emps_controller": ("EMPS_CTRL", emps_controller_variables, 0,
                        "EMPS position controller (native C), sampled at 1/Ts: two-sample "
                        "average, backward difference, vir = kv (kp (qg - x) - dqf) + "
                        "pulse_gain pulse, saturated at +/- u_max",
                        {"startTime": 0.0, "stopTime": 1.0, "stepSize": 1e-3}),
}


class NativeRecipe:
    """How to build one native FMU.

    Parameters
    ----------
    name : str
        ``friction.MODELS`` key, ``friction_effects`` or ``mass``.
    """

    def __init__(self, name: str):
        import friction
        self.name = name
        self.model_exchange = MODEL_EXCHANGE
        self.experiment = LAW_EXPERIMENT
        self.model_identifier = f"fl_native_{name}"
        self.file_name = f"{name}{SUFFIX}.fmu"
        self.law_sources: list[pathlib.Path] = []
        if name in friction.MODELS:
            cls = friction.MODELS[name]
            self.kind = "LAW"
            self.variables = law_variables(cls)
            self.n_params = len(__import__("dataclasses").fields(cls.Params))
            self.n_states = len(cls.state_names)
            self.n_events = 1 if any(v.role == "IN_SHARE" for v in self.variables) else 0
            doc = (cls.__doc__ or name).strip().splitlines()[0]
            self.description = f"Friction law '{name}' (native C): {doc}"
            law_c = CSRC / "laws" / f"{name}.c"
            if not law_c.is_file():
                raise NotImplementedError(f"no C source for the law {name!r} ({law_c})")
            self.law_sources = [law_c]
        elif name == "friction_effects":
            self.kind = "EFFECTS"
            self.variables = effects_variables()
            self.n_params, self.n_states, self.n_events = 0, 0, 0
            self.description = ("Friction effects block (native C) between a law FMU and a "
                                "plant FMU: acceleration-dependent part, load-, position- and "
                                "time-dependent levels (friction.extensions)")
        elif name in PLANT_NATIVE:
            kind, variables, n_states, desc, experiment = PLANT_NATIVE[name]
            self.kind = kind
            self.variables = variables()
            self.n_params, self.n_states, self.n_events = 0, n_states, 0
            self.description = desc
            self.model_exchange = False
            self.experiment = experiment
        elif name == "mass":
            self.kind = "MASS"
            self.variables = mass_variables()
            self.n_params, self.n_states, self.n_events = 0, 2, 0
            self.description = ("Rigid mass (native C) driven by a sinusoidal force against "
                                "an external friction force (mass+friction proof loop)")
        else:
            raise ValueError(f"no native FMU {name!r}; choose from "
                             f"{sorted(native_catalogue()) + sorted(PLANT_NATIVE)}")

    # -- generated header -------------------------------------------------------------------
    def header(self, guid: str) -> str:
        lines = ["/* generated by fmus/native/build.py from the Python parameter dataclasses;",
                 " * do not edit: the modelDescription.xml is written from the same list */",
                 "#ifndef FL_MODEL_H", "#define FL_MODEL_H", "#include <math.h>",
                 '#include "fl_runtime.h"',
                 f'#define FL_MODEL_IDENTIFIER "{self.model_identifier}"',
                 f'#define FL_GUID "{guid}"',
                 f"#define FL_KIND FL_KIND_{self.kind}",
                 f"#define FL_NVARS {len(self.variables)}",
                 f"#define FL_NSTATES {self.n_states}",
                 f"#define FL_NEVENT {self.n_events}",
                 f"#define FL_HAS_ME {1 if self.model_exchange else 0}"]
        if self.kind == "LAW":
            lines += [f"#define FL_LAW fl_law_{self.name}", f"#define FL_NP {self.n_params}"]
        if self.kind == "EFFECTS":
            from friction import extensions as ext
            lines.append(f"#define FL_N_EXT {len(ext.EXTENSION_PARAMS)}")
            lines.append(f"#define FL_E_NK {ext.POSITION_KNOTS}")
            # every packed index, from the one list fl_effects.h mirrors
            for name in ext.EXTENSION_INDEX:
                lines.append(f"#define FL_E_{name.upper()} {ext.EXTENSION_INDEX[name]}")
        if self.kind.startswith("EMPS"):
            for v in self.variables:
                if v.role == "EMPS_PARAM":
                    lines.append(f"#define FL_EP_{v.name.upper()} {EMPS_PARAMS.index(v.name)}")
        lines += [c_table(self.variables), "#endif", ""]
        return "\n".join(lines)

    def source_files(self) -> dict[str, bytes]:
        """Flat ``sources/`` content: name -> bytes (without fl_model.h)."""
        files = {p.name: p.read_bytes() for p in (CSRC / "fl_fmi2.c", CSRC / "fl_runtime.h",
                                                  CSRC / "fl_law.h", CSRC / "fl_effects.h",
                                                  CSRC / "fl_emps.h")}
        for p in self.law_sources:
            files[p.name] = p.read_bytes()
        if self.law_sources:
            for h in sorted((CSRC / "laws").glob("*.h")):
                files[h.name] = h.read_bytes()
        return files

    @property
    def c_files(self) -> list[str]:
        return ["fl_fmi2.c"] + [p.name for p in self.law_sources]


def native_catalogue() -> dict[str, str]:
    """Native FMUs this build knows: name -> kind (laws with a C source, effects, mass)."""
    import friction
    out = {n: "law" for n in friction.MODELS if (CSRC / "laws" / f"{n}.c").is_file()}
    out["friction_effects"] = "effects"
    out["mass"] = "mass"
    return out


def _mingw() -> str | None:
    cc = os.environ.get("FRICTIONLAB_MINGW_CC", MINGW_CC)
    return shutil.which(cc)


def _fmi_headers() -> pathlib.Path:
    from ..status_shim import fmi2_header_dir
    return fmi2_header_dir()


def _compile(cc: str, src_dir: pathlib.Path, c_files: list[str], out: pathlib.Path,
             platform: str) -> None:
    flags = ["-std=c99", "-O2", "-shared", "-fvisibility=hidden", "-Wall", "-Wextra",
             "-Wno-unused-parameter", "-Wno-unused-function"]
    if platform == "linux64":
        flags += ["-fPIC"]
        libs = ["-lm"]
    else:
        libs = ["-static-libgcc", "-lm"]
    cmd = [cc, *flags, f"-I{src_dir}", f"-I{_fmi_headers()}",
           *[str(src_dir / f) for f in c_files], "-o", str(out), *libs]
    res = subprocess.run(cmd, capture_output=True, text=True)
    if res.returncode != 0:
        raise NativeBuildError(f"compiling {out.name} for {platform} failed:\n{res.stderr}")


def build_native(name: str, out: str | os.PathLike, *, win64: bool | None = None) -> pathlib.Path:
    """Build one native FMU into folder ``out``; returns the ``.fmu`` path.

    Parameters
    ----------
    name : str
        A key of :func:`native_catalogue` or of :data:`PLANT_NATIVE`.
    out : path
        Output folder (created).
    win64 : bool, optional
        Build the win64 DLL (default: when the MinGW-w64 compiler is found; ``True`` makes its
        absence an error).

    Raises
    ------
    NativeBuildError
        No C compiler, or a source does not compile.
    """
    recipe = NativeRecipe(name)
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    sources = recipe.source_files()
    digest = hashlib.sha256()
    for k in sorted(sources):
        digest.update(k.encode() + sources[k])
    digest.update(c_table(recipe.variables).encode())
    guid = "{" + str(uuid.UUID(digest.hexdigest()[:32])) + "}"
    sources["fl_model.h"] = recipe.header(guid).encode()
    sources["buildDescription.xml"] = build_description(recipe.model_identifier, recipe.c_files)
    mingw = _mingw()
    if win64 and not mingw:
        raise NativeBuildError(f"no MinGW-w64 cross compiler for win64 "
                               f"({os.environ.get('FRICTIONLAB_MINGW_CC', MINGW_CC)}); Debian: "
                               f"apt-get install gcc-mingw-w64-x86-64")
    with tempfile.TemporaryDirectory(prefix=f"flnative_{name}_") as tmp:
        stage = pathlib.Path(tmp)
        src = stage / "sources"
        src.mkdir()
        for k, data in sources.items():
            (src / k).write_bytes(data)
        binaries = {}
        lib = stage / f"{recipe.model_identifier}.so"
        _compile(compiler(), src, recipe.c_files, lib, "linux64")
        binaries[f"binaries/linux64/{recipe.model_identifier}.so"] = lib.read_bytes()
        if mingw and win64 is not False:
            dll = stage / f"{recipe.model_identifier}.dll"
            _compile(mingw, src, recipe.c_files, dll, "win64")
            binaries[f"binaries/win64/{recipe.model_identifier}.dll"] = dll.read_bytes()
        elif win64 is None:
            warnings.warn(f"{recipe.file_name}: no MinGW-w64 cross compiler ({MINGW_CC}; Debian "
                          f"package gcc-mingw-w64-x86-64): the FMU has no win64 binary "
                          f"(a Windows host can build it from sources/)", stacklevel=2)
        xml = model_description(recipe.variables, model_identifier=recipe.model_identifier,
                                guid=guid, description=recipe.description,
                                sources=recipe.c_files, default_experiment=recipe.experiment,
                                model_exchange=recipe.model_exchange,
                                n_event_indicators=recipe.n_events)
        dest = out / recipe.file_name
        tmp_dest = dest.with_suffix(".fmu.tmp")
        with zipfile.ZipFile(tmp_dest, "w", zipfile.ZIP_DEFLATED) as z:
            z.writestr("modelDescription.xml", xml)
            for k in sorted(sources):
                z.writestr(f"sources/{k}", sources[k])
            for k, data in binaries.items():
                z.writestr(k, data)
        os.replace(tmp_dest, dest)
    return dest
