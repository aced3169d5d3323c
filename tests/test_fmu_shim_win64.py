"""The FMI status shim cross-compiled for win64 (MinGW-w64) and run under Wine.

The win64 shim is the same C source as the linux64 one (``fmus/shim/fmi2_status_shim.c``,
``#ifdef _WIN32`` for the loading only). These tests check the DLL's export and import tables
(``x86_64-w64-mingw32-objdump -p``), its place in a built FMU and the fallback without
MinGW-w64, and run it under Wine in front of a small fake "inner" DLL that behaves like
pythonfmu's (logs a rejected non-finite value at error level through the FMI logger and
returns ``fmi2OK``), driven by a small importer ``.exe``: the call must return ``fmi2Error``
with the message naming the variable. Skipped with the reason when MinGW-w64 (Debian package
``gcc-mingw-w64-x86-64``) or Wine (``wine64``) is absent. The first Wine run on a machine
creates its prefix (about 10 s, once; under ``$FRICTIONLAB_CACHE``); later runs take ~2 s.
"""
from __future__ import annotations

import os
import pathlib
import re
import shutil
import subprocess
import warnings
import zipfile

import pytest

from fmus import status_shim

try:
    WIN64_SHIM = status_shim.shim_library("win64")
    WIN64_REASON = None
except status_shim.ShimUnavailable as exc:
    WIN64_SHIM, WIN64_REASON = None, str(exc)
needs_mingw = pytest.mark.skipif(WIN64_REASON is not None,
                                 reason=f"no win64 status shim: {WIN64_REASON}")


def _tool(name: str) -> str | None:
    cc = os.environ.get("FRICTIONLAB_MINGW_CC") or status_shim.MINGW_CC
    prefix = cc.rsplit("gcc", 1)[0] if cc.endswith("gcc") else "x86_64-w64-mingw32-"
    return shutil.which(prefix + name)


def _wine() -> str | None:
    for cand in ("wine64", "wine", "/usr/lib/wine/wine64"):
        path = shutil.which(cand)
        if path:
            return path
    return None


def fmi2_function_names() -> set[str]:
    """The common and co-simulation functions the FMI 2.0 header declares
    (``FMI2_Export fmi2XTYPE fmi2X;``; the model-exchange section left out)."""
    text = (status_shim.fmi2_header_dir() / "fmi2Functions.h").read_text()
    me = text.index("Functions for FMI2 for Model Exchange", text.index("FMI2_Export fmi2"))
    cs = text.index("Functions for FMI2 for Co-Simulation", me)
    text = text[:me] + text[cs:]
    names = set(re.findall(r"FMI2_Export\s+fmi2\w+TYPE\s+(fmi2\w+)\s*;", text))
    assert {"fmi2Instantiate", "fmi2SetReal", "fmi2DoStep", "fmi2GetStringStatus"} <= names
    assert "fmi2SetTime" not in names
    return names


def pe_tables(dll: pathlib.Path) -> tuple[set[str], set[str]]:
    """(exported names, imported DLL names) from ``objdump -p``."""
    objdump = _tool("objdump")
    if objdump is None:
        pytest.skip("x86_64-w64-mingw32-objdump not found (binutils-mingw-w64-x86-64)")
    out = subprocess.run([objdump, "-p", str(dll)], capture_output=True, text=True,
                         check=True).stdout
    table = out.split("[Ordinal/Name Pointer] Table", 1)[-1].split("\n\n", 1)[0]
    exports = set(re.findall(r"^\s*\[\s*\d+\]\s+(\w+)\s*$", table, flags=re.M))
    imports = set(re.findall(r"DLL Name:\s*(\S+)", out))
    return exports, imports


@needs_mingw
def test_win64_dll_exports_exactly_the_fmi2_functions_and_needs_only_system_dlls():
    exports, imports = pe_tables(WIN64_SHIM)
    assert exports == fmi2_function_names()
    try:  # the linux64 shim (same source) exports the same functions
        so = status_shim.shim_library("linux64")
    except status_shim.ShimUnavailable:
        so = None
    if so is not None and shutil.which("nm"):
        out = subprocess.run(["nm", "-D", "--defined-only", str(so)], capture_output=True,
                             text=True, check=True).stdout
        assert set(re.findall(r" T (\w+)$", out, flags=re.M)) == exports
    # nothing a plain Windows lacks (no libgcc_s / libwinpthread DLL next to it)
    assert {i.lower() for i in imports} <= {"kernel32.dll", "msvcrt.dll"}, imports
    # pythonfmu's DLL, the one behind it, has the functions the shim looks up
    import pythonfmu
    inner = pathlib.Path(pythonfmu.__file__).parent / "resources" / "binaries" / "win64" / \
        "pythonfmu-export.dll"
    inner_exports, _ = pe_tables(inner)
    assert fmi2_function_names() <= inner_exports


@needs_mingw
def test_win64_shim_is_cached_by_source_hash_and_reproducible(tmp_path, monkeypatch):
    monkeypatch.setenv("FRICTIONLAB_CACHE", str(tmp_path / "a"))
    dll = status_shim.shim_library("win64")
    assert dll.suffix == ".dll" and dll.parent.parent == tmp_path / "a"
    mtime = dll.stat().st_mtime_ns
    assert status_shim.shim_library("win64") == dll and dll.stat().st_mtime_ns == mtime
    assert list(dll.parent.iterdir()) == [dll]  # no leftover temporary files
    # no link timestamp: a second compilation elsewhere gives the same bytes
    monkeypatch.setenv("FRICTIONLAB_CACHE", str(tmp_path / "b"))
    again = status_shim.shim_library("win64")
    assert again != dll and again.read_bytes() == dll.read_bytes()


def test_without_mingw_the_build_warns_and_win64_keeps_pythonfmus_dll(tmp_path, monkeypatch):
    import pythonfmu
    from fmus.build import build_fmu, catalogue, validate

    def no_mingw():
        raise status_shim.ShimUnavailable("no MinGW-w64 cross compiler found (test)")
    monkeypatch.setattr(status_shim, "_mingw_compiler", no_mingw)
    monkeypatch.setenv("FRICTIONLAB_CACHE", str(tmp_path / "cache"))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        path = build_fmu(catalogue()["mass"], tmp_path)
    win = [str(w.message) for w in caught if "win64" in str(w.message)]
    assert len(win) == 1, [str(w.message) for w in caught]
    assert "MinGW-w64" in win[0] and "fmi2Discard" in win[0] and "pythonfmu's DLL" in win[0]
    dll = (pathlib.Path(pythonfmu.__file__).parent / "resources" / "binaries" / "win64" /
           "pythonfmu-export.dll").read_bytes()
    with zipfile.ZipFile(path) as z:
        names = set(z.namelist())
        assert {n for n in names if n.startswith("binaries/win64/")} == \
            {"binaries/win64/fl_mass.dll"}
        assert z.read("binaries/win64/fl_mass.dll") == dll
        try:  # linux64 is unaffected
            so = status_shim.shim_library("linux64").read_bytes()
        except status_shim.ShimUnavailable:
            so = None
        if so is not None:
            assert z.read("binaries/linux64/fl_mass.so") == so
    assert validate(path) == []


def test_unknown_platform_is_refused_naming_the_choices():
    with pytest.raises(ValueError, match="linux64.*win64.*'win32'"):
        status_shim.shim_library("win32")


# -- under Wine -------------------------------------------------------------------------------

FAKE_INNER = r'''
/* stand-in for pythonfmu's DLL: a non-finite value is logged at error level through the
 * FMI logger and not stored, and the call returns fmi2OK (what the shim turns into
 * fmi2Error); a negative input makes the step log a warning */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "fmi2Functions.h"

typedef struct { fmi2CallbackFunctions cb; char name[64]; fmi2Real u; } Fake;
static const char *NAMES[] = {"v", "sigma0"};

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }
fmi2Component fmi2Instantiate(fmi2String n, fmi2Type t, fmi2String g, fmi2String r,
                              const fmi2CallbackFunctions *f, fmi2Boolean vis, fmi2Boolean lo) {
    Fake *s = calloc(1, sizeof *s);
    s->cb = *f;
    snprintf(s->name, sizeof s->name, "%s", n);
    return s;
}
void fmi2FreeInstance(fmi2Component c) { free(c); }
fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                       const fmi2Real v[]) {
    Fake *s = c;
    char msg[256];
    size_t i;
    for (i = 0; i < n; i++) {
        if (!isfinite(v[i])) {
            snprintf(msg, sizeof msg, "%s: input %s = %s is not finite: value rejected "
                     "(inner " TAG ")", s->name, NAMES[vr[i] % 2], isnan(v[i]) ? "nan" : "inf");
            s->cb.logger(s->cb.componentEnvironment, s->name, fmi2Error, "logStatusError", msg);
            continue;
        }
        if (vr[i] == 0) s->u = v[i];
    }
    return fmi2OK;
}
fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                       fmi2Real v[]) {
    size_t i;
    for (i = 0; i < n; i++) v[i] = ((Fake *)c)->u;
    return fmi2OK;
}
fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean nsp) {
    Fake *s = c;
    if (s->u < 0)
        s->cb.logger(s->cb.componentEnvironment, s->name, fmi2Warning, "logStatusWarning",
                     "negative input");
    return fmi2OK;
}
#define OK0(f) fmi2Status f(fmi2Component c) { return fmi2OK; }
OK0(fmi2EnterInitializationMode) OK0(fmi2ExitInitializationMode) OK0(fmi2Terminate)
OK0(fmi2Reset) OK0(fmi2CancelStep)
fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean l, size_t n, const fmi2String k[]) {
    return fmi2OK; }
fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean a, fmi2Real b, fmi2Real d,
                               fmi2Boolean e, fmi2Real f) { return fmi2OK; }
#define NO(f, ...) fmi2Status f(fmi2Component c, __VA_ARGS__) { return fmi2Error; }
NO(fmi2GetInteger, const fmi2ValueReference vr[], size_t n, fmi2Integer v[])
NO(fmi2GetBoolean, const fmi2ValueReference vr[], size_t n, fmi2Boolean v[])
NO(fmi2GetString, const fmi2ValueReference vr[], size_t n, fmi2String v[])
NO(fmi2SetInteger, const fmi2ValueReference vr[], size_t n, const fmi2Integer v[])
NO(fmi2SetBoolean, const fmi2ValueReference vr[], size_t n, const fmi2Boolean v[])
NO(fmi2SetString, const fmi2ValueReference vr[], size_t n, const fmi2String v[])
NO(fmi2GetFMUstate, fmi2FMUstate *s)
NO(fmi2SetFMUstate, fmi2FMUstate s)
NO(fmi2FreeFMUstate, fmi2FMUstate *s)
NO(fmi2SerializedFMUstateSize, fmi2FMUstate s, size_t *n)
NO(fmi2SerializeFMUstate, fmi2FMUstate s, fmi2Byte b[], size_t n)
NO(fmi2DeSerializeFMUstate, const fmi2Byte b[], size_t n, fmi2FMUstate *s)
NO(fmi2GetDirectionalDerivative, const fmi2ValueReference a[], size_t na,
   const fmi2ValueReference b[], size_t nb, const fmi2Real d[], fmi2Real e[])
NO(fmi2SetRealInputDerivatives, const fmi2ValueReference vr[], size_t n,
   const fmi2Integer o[], const fmi2Real v[])
NO(fmi2GetRealOutputDerivatives, const fmi2ValueReference vr[], size_t n,
   const fmi2Integer o[], fmi2Real v[])
NO(fmi2GetStatus, const fmi2StatusKind k, fmi2Status *v)
NO(fmi2GetRealStatus, const fmi2StatusKind k, fmi2Real *v)
NO(fmi2GetIntegerStatus, const fmi2StatusKind k, fmi2Integer *v)
NO(fmi2GetBooleanStatus, const fmi2StatusKind k, fmi2Boolean *v)
NO(fmi2GetStringStatus, const fmi2StatusKind k, fmi2String *v)
'''

HOST = r'''
/* minimal FMI 2.0 importer: argv[1..] = loggingOn (0/1) followed by a shim DLL's path, all
 * loaded into this one process before any runs; prints every status and logged message */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <windows.h>
#include "fmi2Functions.h"

#define MAX_LIBS 8

static void logger(fmi2ComponentEnvironment env, fmi2String inst, fmi2Status st,
                   fmi2String cat, fmi2String msg, ...) {
    printf("LOG|%s|%s|%d|%s|%s\n", (const char *)env, inst, (int)st, cat ? cat : "-", msg);
}

#define FN(f) ((f##TYPE *)(void *)GetProcAddress(lib[k], #f))
#define SHOW(what, call) printf("STATUS|%s|" what "|%d\n", path[k], (int)(call))

int main(int argc, char **argv) {
    HMODULE lib[MAX_LIBS];
    fmi2Component c[MAX_LIBS];
    fmi2CallbackFunctions cb[MAX_LIBS];
    const char *path[MAX_LIBS];
    char inner[MAX_PATH];
    int k, n = argc - 1;
    fmi2ValueReference v = 0;
    fmi2Real x, nan = NAN, inf = INFINITY, good = 0.25, neg = -1.0;
    fmi2Status st;
    if (n < 1 || n > MAX_LIBS) return 2;
    for (k = 0; k < n; k++) {
        path[k] = argv[k + 1] + 1;
        lib[k] = LoadLibraryA(path[k]);
        if (lib[k] == NULL) { printf("LOADFAIL|%s|%lu\n", path[k], GetLastError()); return 2; }
        cb[k] = (fmi2CallbackFunctions){logger, calloc, free, NULL, (void *)path[k]};
        c[k] = FN(fmi2Instantiate)("fr", fmi2CoSimulation, "{guid}", "file:///", &cb[k],
                                   fmi2False, argv[k + 1][0] == '1');
        printf("INSTANTIATE|%s|%s\n", path[k], c[k] ? "ok" : "null");
    }
    for (k = 0; k < n; k++) {
        if (c[k] == NULL) continue;
        SHOW("setup", FN(fmi2SetupExperiment)(c[k], fmi2False, 0.0, 0.0, fmi2False, 1.0));
        SHOW("enter", FN(fmi2EnterInitializationMode)(c[k]));
        SHOW("exit", FN(fmi2ExitInitializationMode)(c[k]));
        SHOW("set_good", FN(fmi2SetReal)(c[k], &v, 1, &good));
        SHOW("set_nan", FN(fmi2SetReal)(c[k], &v, 1, &nan));
        st = FN(fmi2GetReal)(c[k], &v, 1, &x);
        printf("STATUS|%s|get|%d|%.17g\n", path[k], (int)st, x);
        SHOW("step", FN(fmi2DoStep)(c[k], 0.0, 0.1, fmi2True));
        SHOW("set_inf", FN(fmi2SetReal)(c[k], &v, 1, &inf));
        SHOW("set_neg", FN(fmi2SetReal)(c[k], &v, 1, &neg));
        SHOW("step_warn", FN(fmi2DoStep)(c[k], 0.1, 0.1, fmi2True));
        SHOW("terminate", FN(fmi2Terminate)(c[k]));
    }
    for (k = 0; k < n; k++) {   /* the inner DLL goes with the shim (its DllMain) */
        if (c[k] != NULL) FN(fmi2FreeInstance)(c[k]);
        snprintf(inner, sizeof inner, "%.*s_pythonfmu.dll", (int)strlen(path[k]) - 4, path[k]);
        printf("INNER|%s|loaded|%d\n", path[k], GetModuleHandleA(inner) != NULL);
        FreeLibrary(lib[k]);
        printf("INNER|%s|after_unload|%d\n", path[k], GetModuleHandleA(inner) != NULL);
    }
    fflush(stdout);
    return 0;
}
'''


def _wine_prefix() -> pathlib.Path:
    base = os.environ.get("FRICTIONLAB_CACHE") or \
        os.path.join(os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"),
                     "frictionlab")
    return pathlib.Path(base) / "wine64-prefix"


@pytest.fixture(scope="module")
def wine_run(tmp_path_factory):
    """Build the fake inner DLLs and the host, run it once under Wine with shims ``a``
    (logging on), ``b`` (logging off) and ``lonely`` (no inner DLL; logging off) in one
    process; returns the parsed output per shim."""
    if WIN64_REASON is not None:
        pytest.skip(f"no win64 status shim: {WIN64_REASON}")
    wine = _wine()
    if wine is None:
        pytest.skip("Wine not found (Debian package wine64)")
    cc = status_shim._mingw_compiler()
    inc = f"-I{status_shim.fmi2_header_dir()}"
    d = tmp_path_factory.mktemp("win64shim")
    (d / "fake_inner.c").write_text(FAKE_INNER)
    (d / "host.c").write_text(HOST)
    # two FMUs whose shims have the same file name, in two folders, plus one whose inner
    # library is missing: each shim must load the inner DLL next to itself
    for tag in ("a", "b", "lonely"):
        (d / tag).mkdir()
        shutil.copy(WIN64_SHIM, d / tag / "probe.dll")
        if tag != "lonely":
            subprocess.run(cc + ["-shared", "-O2", "-static-libgcc", f'-DTAG="{tag}"', inc,
                                 str(d / "fake_inner.c"), "-o",
                                 str(d / tag / "probe_pythonfmu.dll")], check=True)
    subprocess.run(cc + ["-O2", "-static-libgcc", inc, str(d / "host.c"), "-o",
                         str(d / "host.exe")], check=True)
    env = dict(os.environ, WINEDEBUG="-all", WINEDLLOVERRIDES="mscoree,mshtml=")
    env.setdefault("WINEPREFIX", str(_wine_prefix()))
    pathlib.Path(env["WINEPREFIX"]).parent.mkdir(parents=True, exist_ok=True)
    shims = {tag: "Z:" + str(d / tag / "probe.dll").replace("/", "\\")
             for tag in ("a", "b", "lonely")}
    logging = {"a": "1", "b": "0", "lonely": "0"}
    proc = subprocess.run([wine, str(d / "host.exe"),
                           *(logging[tag] + p for tag, p in shims.items())],
                          capture_output=True, text=True, env=env, timeout=300)
    assert proc.returncode == 0, (proc.stdout, proc.stderr)
    out = {tag: {"status": {}, "log": [], "inner": {}} for tag in shims}
    by_path = {p: tag for tag, p in shims.items()}
    for line in proc.stdout.splitlines():
        kind, path, *rest = line.split("|")
        rec = out[by_path[path]]
        if kind == "STATUS":
            rec["status"][rest[0]] = tuple(float(r) if "." in r else int(r) for r in rest[1:])
        elif kind == "LOG":
            inst, st, cat, msg = rest
            rec["log"].append((int(st), cat, msg))
        elif kind == "INSTANTIATE":
            rec["instance"] = rest[0]
        elif kind == "INNER":
            rec["inner"][rest[0]] = int(rest[1])
    return out


def test_under_wine_non_finite_set_real_is_fmi2_error_naming_the_variable(wine_run):
    out = wine_run
    # both shims (same file name, two folders) in one process, each in front of its own
    # inner DLL; a with the importer's logging on, b with it off
    for tag, logging_on in (("a", True), ("b", False)):
        rec = out[tag]
        st = rec["status"]
        assert rec["instance"] == "ok"
        assert st["setup"] == st["enter"] == st["exit"] == st["set_good"] == (0,)
        assert st["set_nan"] == (3,) and st["set_inf"] == (3,)    # fmi2Error
        assert st["get"] == (0, 0.25)           # the rejected value was not stored
        assert st["step"] == (0,)               # reset per call: the next step is OK
        assert st["set_neg"] == (0,) and st["step_warn"] == (1,)  # a logged warning
        assert st["terminate"] == (0,)
        errors = [m for s, _, m in rec["log"] if s == 3]
        assert errors == [f"fr: input v = nan is not finite: value rejected (inner {tag})",
                          f"fr: input v = inf is not finite: value rejected (inner {tag})"]
        warn = [(c, m) for s, c, m in rec["log"] if s == 1]
        # the importer's loggingOn filters non-error messages; errors always arrive
        assert warn == ([("logStatusWarning", "negative input")] if logging_on else [])
        assert rec["inner"] == {"loaded": 1, "after_unload": 0}  # unloaded with the shim


def test_under_wine_missing_inner_dll_is_a_fatal_message_naming_it(wine_run):
    rec = wine_run["lonely"]
    assert rec["instance"] == "null" and rec["status"] == {}
    [(status, cat, msg)] = rec["log"]
    assert status == 4 and cat == "logStatusFatal"
    assert msg.startswith("fmi2 status shim: cannot load ") and \
        msg.split(": ")[1].endswith("\\lonely\\probe_pythonfmu.dll"), msg


def test_slave_knows_it_runs_behind_the_win64_shim(tmp_path, monkeypatch):
    # the slave keeps working after a rejected value only behind the shim (the call gives
    # fmi2Error); without it the next step is refused (fmi2Discard): on Windows it must look
    # for <id>_pythonfmu.dll in binaries/win64
    import sys
    from fmus import runtime
    resources = tmp_path / "resources"
    resources.mkdir()
    (tmp_path / "binaries" / "win64").mkdir(parents=True)
    (tmp_path / "binaries" / "linux64").mkdir(parents=True)
    (tmp_path / "binaries" / "win64" / "fl_lugre.dll").write_bytes(b"")
    monkeypatch.setattr(sys, "platform", "win32")
    assert not runtime.behind_status_shim(str(resources), "fl_lugre")  # pythonfmu's DLL
    (tmp_path / "binaries" / "linux64" / "fl_lugre_pythonfmu.so").write_bytes(b"")
    assert not runtime.behind_status_shim(str(resources), "fl_lugre")  # linux64's shim
    (tmp_path / "binaries" / "win64" / "fl_lugre_pythonfmu.dll").write_bytes(b"")
    assert runtime.behind_status_shim(str(resources), "fl_lugre")
    monkeypatch.setattr(sys, "platform", "darwin")  # no shim built for other platforms
    assert not runtime.behind_status_shim(str(resources), "fl_lugre")
    monkeypatch.setattr(sys, "platform", "linux")
    assert runtime.behind_status_shim(str(resources), "fl_lugre")
