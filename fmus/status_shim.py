"""The FMI status shim: compile it once, put it in front of pythonfmu's binary in an FMU.

pythonfmu 0.7's binary answers ``fmi2OK`` whenever the Python slave returns normally,
``fmi2Discard`` for a refused step and ``fmi2Fatal`` (instance destroyed) for an exception,
so a slave cannot answer ``fmi2Error`` for a rejected value. ``shim/fmi2_status_shim.c``
(plain C, one file for both platforms) becomes ``binaries/linux64/<modelIdentifier>.so`` and
``binaries/win64/<modelIdentifier>.dll`` and forwards every FMI 2.0 co-simulation call to
pythonfmu's library, shipped next to it as ``<modelIdentifier>_pythonfmu.so`` /
``<modelIdentifier>_pythonfmu.dll``; a call returns the worst of the inner status and the
statuses the slave logged during it (see the C file's header).

:func:`shim_library` compiles the shim against the FMI 2.0 headers shipped with fmpy:
linux64 with the system C compiler (``$CC``, Python's ``CC`` or ``cc``, on a linux x86_64
host), win64 with the MinGW-w64 cross compiler (``$FRICTIONLAB_MINGW_CC`` or
``x86_64-w64-mingw32-gcc``, Debian/Ubuntu package ``gcc-mingw-w64-x86-64``; any host). Each
result is cached by a hash of source, headers, compiler and flags under ``$FRICTIONLAB_CACHE``
(default ``~/.cache/frictionlab``). A platform whose shim cannot be built keeps pythonfmu's
binary (:func:`shim_or_warn` says so): there bad input is refused at the next ``fmi2DoStep``
with ``fmi2Discard`` instead of ``fmi2Error`` at the call.
"""
from __future__ import annotations

import hashlib
import io
import os
import pathlib
import platform as platform_mod
import shlex
import shutil
import subprocess
import sys
import sysconfig
import tempfile
import warnings
import zipfile

__all__ = ["SOURCE", "INNER_SUFFIX", "PLATFORM", "PLATFORMS", "MINGW_CC", "shim_library", "libpython",
           "inner_name", "library_name", "fmi2_header_dir", "ShimUnavailable", "shim_or_warn",
           "shim_members", "rewrite_fmu", "install"]

SOURCE = pathlib.Path(__file__).resolve().parent / "shim" / "fmi2_status_shim.c"
#: file name suffix of pythonfmu's library behind the linux64 shim (must match the C source)
INNER_SUFFIX = "_pythonfmu.so"
#: FMI platform folder of the shim built by the system C compiler
PLATFORM = "linux64"
#: FMI platform folders the shim is built for (win64: MinGW-w64 cross compiler)
PLATFORMS = ("linux64", "win64")
#: default MinGW-w64 cross compiler for win64 (override: ``$FRICTIONLAB_MINGW_CC``)
MINGW_CC = "x86_64-w64-mingw32-gcc"
_EXT = {"linux64": ".so", "win64": ".dll"}


class ShimUnavailable(RuntimeError):
    """The shim cannot be built here (linux64: not a linux x86_64 host or no C compiler;
    win64: no MinGW-w64 cross compiler; either: no FMI headers or compilation failed)."""


def _check_platform(platform: str) -> None:
    if platform not in PLATFORMS:
        raise ValueError(f"platform must be one of {PLATFORMS}, got {platform!r}")


def library_name(model_identifier: str, platform: str = PLATFORM) -> str:
    """File name of the FMU's binary in ``binaries/<platform>`` (``<id>.so`` / ``<id>.dll``).

    Parameters
    ----------
    model_identifier : str
        The FMU's model identifier.
    platform : str
        ``linux64`` or ``win64``.
    """
    _check_platform(platform)
    return f"{model_identifier}{_EXT[platform]}"


def inner_name(model_identifier: str, platform: str = PLATFORM) -> str:
    """File name of pythonfmu's library behind the shim in ``binaries/<platform>``.

    Parameters
    ----------
    model_identifier, platform : str
        As for :func:`library_name`.
    """
    _check_platform(platform)
    return f"{model_identifier}_pythonfmu{_EXT[platform]}"


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


def _mingw_compiler() -> list[str]:
    cand = os.environ.get("FRICTIONLAB_MINGW_CC") or MINGW_CC
    argv = shlex.split(cand)
    if argv and shutil.which(argv[0]):
        return argv
    raise ShimUnavailable(f"no MinGW-w64 cross compiler found ({cand}; Debian/Ubuntu package "
                          f"gcc-mingw-w64-x86-64)")


_FLAGS = ["-shared", "-fPIC", "-O2", "-fvisibility=hidden", "-Wall"]


def libpython() -> tuple[str, str]:
    """(path, soname) of the libpython the linux64 shim loads in a host without Python
    (from this Python's ``sysconfig``: ``LIBDIR`` / ``INSTSONAME``); ``("", "")`` for a Python
    without a shared libpython. A host overrides it with ``$FRICTIONLAB_LIBPYTHON``."""
    name = sysconfig.get_config_var("INSTSONAME") or ""
    libdir = sysconfig.get_config_var("LIBDIR") or ""
    if not sysconfig.get_config_var("Py_ENABLE_SHARED") or not name.endswith(
            tuple(f".so{x}" for x in ("", ".1", ".1.0"))):
        return "", ""
    path = os.path.join(libdir, name)
    return (path if os.path.isfile(path) else ""), name


def _libpython_flags() -> list[str]:
    path, name = libpython()
    return [f'-DFL_LIBPYTHON="{path}"', f'-DFL_LIBPYTHON_NAME="{name}"']
_LIBS = ["-ldl", "-lpthread"]
# win64: the fmi2 functions are exported by the header's FMI2_Export (__declspec(dllexport));
# libgcc linked in, so the DLL needs only KERNEL32 and msvcrt (present on every Windows);
# no link timestamp and no image base hashed from the file name: the same source gives the
# same bytes (the output's file name, in the export table, is fixed too: see shim_library)
_WIN64_FLAGS = ["-shared", "-O2", "-Wall", "-static-libgcc", "-Wl,--no-insert-timestamp",
                "-Wl,--disable-auto-image-base"]
_WIN64_LIBS: list[str] = []


def shim_library(platform: str = PLATFORM) -> pathlib.Path:
    """Path of the compiled shim for ``platform`` (compiled on first use, then cached).

    Parameters
    ----------
    platform : {"linux64", "win64"}
        linux64: ``<...>.so`` built by the system C compiler; win64: ``<...>.dll`` built by
        the MinGW-w64 cross compiler.

    Raises
    ------
    ShimUnavailable
        linux64 on a host other than linux x86_64, no (cross) compiler, no FMI headers, or
        compilation failed (the compiler's message is included).
    """
    _check_platform(platform)
    if platform == "linux64":
        if not (sys.platform.startswith("linux") and platform_mod.machine() in ("x86_64",
                                                                                "AMD64")):
            raise ShimUnavailable(f"the shim is built for {PLATFORM} on a linux x86_64 host "
                                  f"only (this host: {sys.platform} {platform_mod.machine()})")
        flags, libs = _FLAGS + _libpython_flags(), _LIBS
    else:
        flags, libs = _WIN64_FLAGS, _WIN64_LIBS
    headers = fmi2_header_dir()
    cc = _compiler() if platform == "linux64" else _mingw_compiler()
    h = hashlib.sha256()
    h.update(SOURCE.read_bytes())
    for name in ("fmi2Functions.h", "fmi2FunctionTypes.h", "fmi2TypesPlatform.h"):
        h.update((headers / name).read_bytes())
    h.update(" ".join(cc + flags + libs).encode())
    key = h.hexdigest()[:16]
    ext = _EXT[platform]
    for cache in (_cache_dir(), pathlib.Path(tempfile.gettempdir()) / "frictionlab_shim"):
        lib = cache / f"fmi2_status_shim_{key}{ext}"
        if lib.is_file():
            return lib
        try:
            cache.mkdir(parents=True, exist_ok=True)
            tmpdir = tempfile.mkdtemp(dir=cache)
        except OSError:
            continue  # cache not writable: try the next place
        try:
            # a fixed output name: a DLL records it in its export table
            tmp = os.path.join(tmpdir, f"fmi2_status_shim{ext}")
            cmd = cc + flags + [f"-I{headers}", str(SOURCE), "-o", tmp] + libs
            proc = subprocess.run(cmd, capture_output=True, text=True)
            if proc.returncode != 0:
                raise ShimUnavailable(f"compiling the {platform} status shim failed "
                                      f"({' '.join(cmd)}): {proc.stderr.strip()[-1500:]}")
            os.replace(tmp, lib)  # atomic: concurrent builds see a complete file
        finally:
            shutil.rmtree(tmpdir, ignore_errors=True)
        return lib
    raise ShimUnavailable("no writable cache folder for the compiled shim")


def shim_or_warn(platform: str = PLATFORM) -> pathlib.Path | None:
    """:func:`shim_library`, or None with a warning that bad input then gives fmi2Discard
    (on that platform: the FMU keeps pythonfmu's binary there).

    Parameters
    ----------
    platform : str
        ``linux64`` or ``win64``.
    """
    try:
        return shim_library(platform)
    except ShimUnavailable as exc:
        if platform == "linux64":
            warnings.warn(f"FMI status shim not built ({exc}); the FMUs use pythonfmu's binary "
                          f"as is, so bad input is refused at the next fmi2DoStep with "
                          f"fmi2Discard instead of fmi2Error", RuntimeWarning, stacklevel=2)
        else:
            warnings.warn(f"FMI status shim for {platform} not built ({exc}); binaries/"
                          f"{platform} is pythonfmu's DLL as is, so on Windows bad input is "
                          f"refused at the next fmi2DoStep with fmi2Discard instead of "
                          f"fmi2Error", RuntimeWarning, stacklevel=2)
        return None


def shim_members(model_identifier: str, shim: pathlib.Path,
                 platform: str = PLATFORM) -> tuple[dict, dict]:
    """Archive changes that put ``shim`` in front of pythonfmu's library in
    ``binaries/<platform>``: ``(rename, replace)`` for :func:`rewrite_fmu`.

    Parameters
    ----------
    model_identifier : str
        The FMU's model identifier.
    shim : path
        The compiled shim library.
    platform : str
        ``linux64`` or ``win64``.
    """
    lib = f"binaries/{platform}/{library_name(model_identifier, platform)}"
    return ({lib: f"binaries/{platform}/{inner_name(model_identifier, platform)}"},
            {lib: pathlib.Path(shim).read_bytes()})


def rewrite_fmu(fmu: pathlib.Path, replace: dict, rename: dict) -> None:
    """Rewrite the FMU archive: members in ``replace`` get new bytes (added if absent),
    members in ``rename`` (old -> new name) move.

    Parameters
    ----------
    fmu : path
        The ``.fmu`` archive (rewritten in place).
    replace : dict
        ``{member: bytes}``.
    rename : dict
        ``{old member name: new name}``.
    """
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
            info.external_attr = (0o755 if member.endswith((".so", ".dll")) else 0o644) << 16
            zout.writestr(info, data)
    fmu.write_bytes(buf.getvalue())


def install(fmu, platforms=None) -> pathlib.Path:
    """Put the status shim into an existing pythonfmu FMU (in place); returns its path.

    Parameters
    ----------
    fmu : path
        The ``.fmu`` file.
    platforms : sequence of str, optional
        Platforms to shim, each required. Default: linux64 (required) and win64 when its
        shim can be built (otherwise a warning, and win64 keeps pythonfmu's DLL).

    Raises
    ------
    ShimUnavailable
        A required platform's shim cannot be built here.
    ValueError
        The FMU has no library ``binaries/<platform>/<modelIdentifier>.so|.dll`` for a
        required platform, or already has the shim.
    """
    from fmpy import read_model_description
    fmu = pathlib.Path(fmu)
    mid = read_model_description(str(fmu), validate=False).coSimulation.modelIdentifier
    with zipfile.ZipFile(fmu) as z:
        names = set(z.namelist())
    wanted = [(PLATFORM, True), ("win64", False)] if platforms is None else \
        [(p, True) for p in platforms]
    rename, replace = {}, {}
    for plat, required in wanted:
        if f"binaries/{plat}/{inner_name(mid, plat)}" in names:
            raise ValueError(f"{fmu.name} already has the {plat} status shim")
        lib = f"binaries/{plat}/{library_name(mid, plat)}"
        if lib not in names:
            if required:
                raise ValueError(f"{fmu.name} has no {lib}")
            continue
        shim = shim_library(plat) if required else shim_or_warn(plat)
        if shim is None:
            continue
        ren, rep = shim_members(mid, shim, plat)
        rename.update(ren)
        replace.update(rep)
    rewrite_fmu(fmu, replace, rename)
    return fmu
