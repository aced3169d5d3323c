"""The FMI status shim: compile it once, put it in front of pythonfmu's binary in an FMU.

pythonfmu 0.7's binary answers ``fmi2OK`` whenever the Python slave returns normally,
``fmi2Discard`` for a refused step and ``fmi2Fatal`` (instance destroyed) for an exception,
so a slave cannot answer ``fmi2Error`` for a rejected value. ``shim/fmi2_status_shim.c``
(plain C) becomes ``binaries/linux64/<modelIdentifier>.so`` and forwards every FMI 2.0
co-simulation call to pythonfmu's library, shipped next to it as
``<modelIdentifier>_pythonfmu.so``; a call returns the worst of the inner status and the
statuses the slave logged during it (see the C file's header).

:func:`shim_library` compiles the shim with the system C compiler (``$CC``, Python's
``CC`` or ``cc``) against the FMI 2.0 headers shipped with fmpy, caching the result by a
hash of source, headers and compiler under ``$FRICTIONLAB_CACHE`` (default
``~/.cache/frictionlab``). Only linux64 gets the shim; win64 keeps pythonfmu's binary.
"""
from __future__ import annotations

import hashlib
import io
import os
import pathlib
import platform
import shlex
import shutil
import subprocess
import sys
import sysconfig
import tempfile
import warnings
import zipfile

__all__ = ["SOURCE", "INNER_SUFFIX", "PLATFORM", "shim_library", "inner_name",
           "fmi2_header_dir", "ShimUnavailable", "shim_or_warn", "shim_members", "rewrite_fmu",
           "install"]

SOURCE = pathlib.Path(__file__).resolve().parent / "shim" / "fmi2_status_shim.c"
#: file name suffix of pythonfmu's library behind the shim (must match the C source)
INNER_SUFFIX = "_pythonfmu.so"
#: FMI platform folder the shim is built for
PLATFORM = "linux64"


class ShimUnavailable(RuntimeError):
    """The shim cannot be built here (not linux64, no C compiler or no FMI headers)."""


def inner_name(model_identifier: str) -> str:
    """File name of pythonfmu's library behind the shim in ``binaries/linux64``."""
    return f"{model_identifier}{INNER_SUFFIX}"


def fmi2_header_dir() -> pathlib.Path:
    """Folder holding ``fmi2Functions.h`` (the standard headers fmpy ships)."""
    try:
        import fmpy
    except ImportError as exc:
        raise ShimUnavailable("fmpy (source of the FMI 2.0 headers) is not importable") from exc
    d = pathlib.Path(fmpy.__file__).resolve().parent / "c-code"
    if not (d / "fmi2Functions.h").is_file():
        raise ShimUnavailable(f"fmi2Functions.h not found in {d}")
    return d


def _compiler() -> list[str]:
    for cand in (os.environ.get("CC"), sysconfig.get_config_var("CC"), "cc", "gcc"):
        if not cand:
            continue
        argv = shlex.split(cand)
        if argv and shutil.which(argv[0]):
            return argv
    raise ShimUnavailable("no C compiler found ($CC, Python's CC, cc, gcc)")


def _cache_dir() -> pathlib.Path:
    base = os.environ.get("FRICTIONLAB_CACHE") or \
        os.path.join(os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"),
                     "frictionlab")
    return pathlib.Path(base) / "fmi2_status_shim"


_FLAGS = ["-shared", "-fPIC", "-O2", "-fvisibility=hidden", "-Wall"]
_LIBS = ["-ldl", "-lpthread"]


def shim_library() -> pathlib.Path:
    """Path of the compiled shim (compiled on first use, then cached).

    Raises
    ------
    ShimUnavailable
        Not a linux x86_64 host, no C compiler, no FMI headers, or compilation failed
        (the compiler's message is included).
    """
    if not (sys.platform.startswith("linux") and platform.machine() in ("x86_64", "AMD64")):
        raise ShimUnavailable(f"the shim is built for {PLATFORM} only (this host: "
                              f"{sys.platform} {platform.machine()})")
    headers = fmi2_header_dir()
    cc = _compiler()
    h = hashlib.sha256()
    h.update(SOURCE.read_bytes())
    for name in ("fmi2Functions.h", "fmi2FunctionTypes.h", "fmi2TypesPlatform.h"):
        h.update((headers / name).read_bytes())
    h.update(" ".join(cc + _FLAGS + _LIBS).encode())
    key = h.hexdigest()[:16]
    for cache in (_cache_dir(), pathlib.Path(tempfile.gettempdir()) / "frictionlab_shim"):
        lib = cache / f"fmi2_status_shim_{key}.so"
        if lib.is_file():
            return lib
        try:
            cache.mkdir(parents=True, exist_ok=True)
            fd, tmp = tempfile.mkstemp(suffix=".so", dir=cache)
            os.close(fd)
        except OSError:
            continue  # cache not writable: try the next place
        cmd = cc + _FLAGS + [f"-I{headers}", str(SOURCE), "-o", tmp] + _LIBS
        proc = subprocess.run(cmd, capture_output=True, text=True)
        if proc.returncode != 0:
            os.unlink(tmp)
            raise ShimUnavailable(f"compiling the status shim failed ({' '.join(cmd)}): "
                                  f"{proc.stderr.strip()[-1500:]}")
        os.replace(tmp, lib)  # atomic: concurrent builds see a complete file
        return lib
    raise ShimUnavailable("no writable cache folder for the compiled shim")


def shim_or_warn() -> pathlib.Path | None:
    """:func:`shim_library`, or None with a warning that bad input then gives fmi2Discard."""
    try:
        return shim_library()
    except ShimUnavailable as exc:
        warnings.warn(f"FMI status shim not built ({exc}); the FMUs use pythonfmu's binary "
                      f"as is, so bad input is refused at the next fmi2DoStep with "
                      f"fmi2Discard instead of fmi2Error", RuntimeWarning, stacklevel=2)
        return None


def shim_members(model_identifier: str, shim: pathlib.Path) -> tuple[dict, dict]:
    """Archive changes that put ``shim`` in front of pythonfmu's linux64 library:
    ``(rename, replace)`` for :func:`rewrite_fmu`."""
    lib = f"binaries/{PLATFORM}/{model_identifier}.so"
    return ({lib: f"binaries/{PLATFORM}/{inner_name(model_identifier)}"},
            {lib: pathlib.Path(shim).read_bytes()})


def rewrite_fmu(fmu: pathlib.Path, replace: dict, rename: dict) -> None:
    """Rewrite the FMU archive: members in ``replace`` get new bytes (added if absent),
    members in ``rename`` (old -> new name) move."""
    buf = io.BytesIO()
    with zipfile.ZipFile(fmu) as zin, zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as zout:
        for item in zin.infolist():
            if item.filename in replace and item.filename not in rename:
                continue
            data = zin.read(item.filename)
            if item.filename in rename:
                item = zipfile.ZipInfo(rename[item.filename], item.date_time)
                item.compress_type = zipfile.ZIP_DEFLATED
                item.external_attr = 0o755 << 16
            zout.writestr(item, data)
        for member, data in replace.items():
            info = zipfile.ZipInfo(member, (2020, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = (0o755 if member.endswith(".so") else 0o644) << 16
            zout.writestr(info, data)
    fmu.write_bytes(buf.getvalue())


def install(fmu) -> pathlib.Path:
    """Put the status shim into an existing pythonfmu FMU (in place); returns its path.

    Raises
    ------
    ShimUnavailable
        The shim cannot be built here.
    ValueError
        The FMU has no linux64 library ``<modelIdentifier>.so`` or already has the shim.
    """
    from fmpy import read_model_description
    fmu = pathlib.Path(fmu)
    mid = read_model_description(str(fmu), validate=False).coSimulation.modelIdentifier
    with zipfile.ZipFile(fmu) as z:
        names = set(z.namelist())
    if f"binaries/{PLATFORM}/{inner_name(mid)}" in names:
        raise ValueError(f"{fmu.name} already has the status shim")
    if f"binaries/{PLATFORM}/{mid}.so" not in names:
        raise ValueError(f"{fmu.name} has no binaries/{PLATFORM}/{mid}.so")
    rename, replace = shim_members(mid, shim_library())
    rewrite_fmu(fmu, replace, rename)
    return fmu
