/*
 * fmi2_status_shim.c - FMI 2.0 co-simulation status shim for pythonfmu FMUs (frictionlab).
 *
 * Why: the pythonfmu 0.7 binary returns fmi2OK whenever the Python slave returns normally,
 * fmi2Discard when do_step returns False, and fmi2Fatal (destroying the Python instance) when
 * the slave raises. A slave therefore cannot answer fmi2Error, the status FMI 2.0 asks for on
 * a rejected value. This library sits in front of it:
 *
 *   binaries/linux64/<modelIdentifier>.so            <- this shim (what the importer loads)
 *   binaries/linux64/<modelIdentifier>_pythonfmu.so  <- pythonfmu's libpythonfmu-export.so
 *
 * The shim loads the inner library next to itself once per process (linux64: dlopen with
 * RTLD_LOCAL, so any number of FMUs load into one process; win64: LoadLibraryW on the full
 * path, see load_inner_path; either is unloaded with the shim), forwards every FMI 2.0
 * co-simulation function, and gives the inner instance its own logger. That logger forwards
 * each message unchanged to the importer's logger (with the importer's componentEnvironment)
 * and records the worst status logged during the current call; each forwarded call returns
 * max(inner status, worst logged status). A slave that logs at error level and returns
 * normally thus makes the call return fmi2Error.
 *
 * The same file builds the win64 binary (MinGW-w64 cross compiler):
 *
 *   binaries/win64/<modelIdentifier>.dll             <- this shim
 *   binaries/win64/<modelIdentifier>_pythonfmu.dll   <- pythonfmu's pythonfmu-export.dll
 *
 * Only the loading differs (#ifdef _WIN32 below); the forwarding is the same code.
 *
 * Python (linux64): pythonfmu's library needs the CPython API but does not link libpython.
 * A Python host (fmpy, PyFMI) has it; a plain C host does not, so before loading the inner
 * library the shim loads libpython with RTLD_GLOBAL when Py_IsInitialized is not yet
 * visible: the path in $FRICTIONLAB_LIBPYTHON, else the build machine's (FL_LIBPYTHON, from
 * Python's sysconfig at build time), else its soname (FL_LIBPYTHON_NAME) on the loader's
 * search path. pythonfmu then initializes that Python; numpy and numba must be importable
 * by it (its site-packages or PYTHONPATH).
 *
 * Exit (linux64): pythonfmu 0.7 keeps its interpreter guard in a static std::shared_ptr and
 * resets it from an ELF destructor (finalizePythonInterpreter). Its library cannot be
 * unloaded (it has STB_GNU_UNIQUE symbols), so both run at process exit, the C++ static
 * destructor first (exit handlers run before the ELF destructors): the ELF destructor then
 * resets a destroyed shared_ptr and frees its control block a second time - the "corrupted
 * double-linked list" abort seen at exit of about one fresh FMU process in 30 (valgrind:
 * invalid read in finalizePythonInterpreter of a block freed by __run_exit_handlers). The
 * shim registers its own exit handler right after loading the inner library, so it runs
 * before that static destructor, and calls finalizePythonInterpreter there: the guard is
 * released once, while it is alive, and the later resets find it empty. The shim then stays
 * loaded (RTLD_NODELETE, as the inner library does), so the handler runs at exit only.
 *
 * Logging: pythonfmu 0.7 drops every message unless logging is on, so the inner instance
 * always runs with logging on (all categories) and the shim applies the importer's
 * loggingOn / categories itself. Messages with status fmi2Error or fmi2Fatal are always
 * forwarded: they explain the status the call returns.
 *
 * Build: cc -shared -fPIC -O2 -I<dir of fmi2Functions.h> fmi2_status_shim.c -o <id>.so -ldl
 *        x86_64-w64-mingw32-gcc -shared -O2 -static-libgcc -I<dir> fmi2_status_shim.c
 *            -o <id>.dll   (the fmi2 functions are exported by the header's
 *            FMI2_Export = __declspec(dllexport) on _WIN32)
 */
#ifdef _WIN32
#ifndef _WIN32_WINNT
#define _WIN32_WINNT 0x0601              /* InitOnceExecuteOnce, GetModuleHandleExW */
#endif
#define WIN32_LEAN_AND_MEAN
#define __USE_MINGW_ANSI_STDIO 1         /* C99 snprintf (always NUL-terminated) */
#include <windows.h>
#else
#define _GNU_SOURCE
#include <dlfcn.h>
#include <pthread.h>
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"

#ifdef _WIN32
#define INNER_SUFFIX L"_pythonfmu.dll"
#else
#define INNER_SUFFIX "_pythonfmu.so"
#endif
#define MAX_CATEGORIES 32
#define CATEGORY_LEN 64

/* -- the inner (pythonfmu) library ---------------------------------------------------- */

typedef struct {
    fmi2SetDebugLoggingTYPE *SetDebugLogging;
    fmi2InstantiateTYPE *Instantiate;
    fmi2FreeInstanceTYPE *FreeInstance;
    fmi2SetupExperimentTYPE *SetupExperiment;
    fmi2EnterInitializationModeTYPE *EnterInitializationMode;
    fmi2ExitInitializationModeTYPE *ExitInitializationMode;
    fmi2TerminateTYPE *Terminate;
    fmi2ResetTYPE *Reset;
    fmi2GetRealTYPE *GetReal;
    fmi2GetIntegerTYPE *GetInteger;
    fmi2GetBooleanTYPE *GetBoolean;
    fmi2GetStringTYPE *GetString;
    fmi2SetRealTYPE *SetReal;
    fmi2SetIntegerTYPE *SetInteger;
    fmi2SetBooleanTYPE *SetBoolean;
    fmi2SetStringTYPE *SetString;
    fmi2GetFMUstateTYPE *GetFMUstate;
    fmi2SetFMUstateTYPE *SetFMUstate;
    fmi2FreeFMUstateTYPE *FreeFMUstate;
    fmi2SerializedFMUstateSizeTYPE *SerializedFMUstateSize;
    fmi2SerializeFMUstateTYPE *SerializeFMUstate;
    fmi2DeSerializeFMUstateTYPE *DeSerializeFMUstate;
    fmi2GetDirectionalDerivativeTYPE *GetDirectionalDerivative;
    fmi2SetRealInputDerivativesTYPE *SetRealInputDerivatives;
    fmi2GetRealOutputDerivativesTYPE *GetRealOutputDerivatives;
    fmi2DoStepTYPE *DoStep;
    fmi2CancelStepTYPE *CancelStep;
    fmi2GetStatusTYPE *GetStatus;
    fmi2GetRealStatusTYPE *GetRealStatus;
    fmi2GetIntegerStatusTYPE *GetIntegerStatus;
    fmi2GetBooleanStatusTYPE *GetBooleanStatus;
    fmi2GetStringStatusTYPE *GetStringStatus;
} Inner;

static Inner inner;
static char inner_error[5120] = "";

/* the message goes out as a printf format without arguments (as pythonfmu's do) */
static void no_percent(char *text) {
    for (; *text; text++)
        if (*text == '%')
            *text = '?';
}

#ifdef _WIN32
/* -- win64: LoadLibraryW / GetProcAddress ------------------------------------------------ */

#define PATH_CHARS 32768                 /* longest Windows path, in wide characters */

static HMODULE inner_handle = NULL;
static INIT_ONCE inner_once = INIT_ONCE_STATIC_INIT;

/* text of GetLastError() (no trailing newline) */
static const char *last_error_text(void) {
    static char text[512];
    DWORD err = GetLastError();
    DWORD n = FormatMessageA(FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS, NULL,
                             err, 0, text, sizeof text, NULL);
    while (n > 0 && (text[n - 1] == '\n' || text[n - 1] == '\r' || text[n - 1] == ' '))
        text[--n] = '\0';
    if (n == 0)
        snprintf(text, sizeof text, "error %lu", (unsigned long)err);
    return text;
}

/* a wide path as UTF-8 for the log message */
static const char *utf8(const wchar_t *w) {
    static char text[4096];
    if (WideCharToMultiByte(CP_UTF8, 0, w, -1, text, sizeof text, NULL, NULL) == 0)
        snprintf(text, sizeof text, "(path not representable)");
    return text;
}

static void *sym(const char *name) {
    void *p = (void *)GetProcAddress(inner_handle, name);
    if (p == NULL && inner_error[0] == '\0')
        snprintf(inner_error, sizeof inner_error, "fmi2 status shim: %s missing in the inner "
                 "library: %s", name, last_error_text());
    return p;
}

/* Load <own path without .dll>_pythonfmu.dll once per process. */
static int load_inner_path(void) {
    static wchar_t path[PATH_CHARS];
    HMODULE self = NULL;
    DWORD n;
    /* this DLL's own module (its folder is the FMU's binaries/win64), not the host's */
    if (!GetModuleHandleExW(GET_MODULE_HANDLE_EX_FLAG_FROM_ADDRESS |
                                GET_MODULE_HANDLE_EX_FLAG_UNCHANGED_REFCOUNT,
                            (LPCWSTR)(void *)&load_inner_path, &self)) {
        snprintf(inner_error, sizeof inner_error, "fmi2 status shim: GetModuleHandleExW "
                 "failed: %s", last_error_text());
        return 0;
    }
    n = GetModuleFileNameW(self, path, PATH_CHARS);
    if (n == 0 || n >= PATH_CHARS) {
        snprintf(inner_error, sizeof inner_error, "fmi2 status shim: GetModuleFileNameW "
                 "failed: %s", last_error_text());
        return 0;
    }
    if (n < 4 || _wcsicmp(path + n - 4, L".dll") != 0 ||
        n - 4 + sizeof INNER_SUFFIX / sizeof(wchar_t) > PATH_CHARS) {
        snprintf(inner_error, sizeof inner_error, "fmi2 status shim: unexpected library "
                 "path %s", utf8(path));
        return 0;
    }
    memcpy(path + n - 4, INNER_SUFFIX, sizeof INNER_SUFFIX);
    /* LoadLibraryW with the full path: the inner library's own imports (python3.dll) are
     * found by the standard search order, which starts at the host's folder (python.exe's,
     * where python3.dll lives) and ends on PATH - as when the host loads it directly */
    inner_handle = LoadLibraryW(path);
    if (inner_handle == NULL) {
        snprintf(inner_error, sizeof inner_error, "fmi2 status shim: cannot load %s: %s",
                 utf8(path), last_error_text());
        return 0;
    }
    return 1;
}

#else
/* -- linux64: dlopen / dlsym ----------------------------------------------------------- */

#ifndef FL_LIBPYTHON
#define FL_LIBPYTHON ""                  /* build machine's libpython (fmus.status_shim) */
#endif
#ifndef FL_LIBPYTHON_NAME
#define FL_LIBPYTHON_NAME ""             /* its soname, e.g. libpython3.11.so.1.0 */
#endif

static void *inner_handle = NULL;
static void *python_handle = NULL;
static pthread_once_t inner_once = PTHREAD_ONCE_INIT;

/* Make the CPython API visible to the inner library (a C host has none). */
static int load_libpython(void) {
    const char *env = getenv("FRICTIONLAB_LIBPYTHON");
    const char *tried[3];
    int n = 0, i;
    if (dlsym(RTLD_DEFAULT, "Py_IsInitialized") != NULL)
        return 1;                        /* a Python host, or libpython preloaded */
    if (env != NULL && env[0] != '\0')
        tried[n++] = env;                /* the user's choice only */
    else {
        if (FL_LIBPYTHON[0] != '\0') tried[n++] = FL_LIBPYTHON;
        if (FL_LIBPYTHON_NAME[0] != '\0') tried[n++] = FL_LIBPYTHON_NAME;
    }
    for (i = 0; i < n && python_handle == NULL; i++)
        python_handle = dlopen(tried[i], RTLD_NOW | RTLD_GLOBAL);
    if (python_handle == NULL) {
        snprintf(inner_error, sizeof inner_error, "fmi2 status shim: this pythonfmu FMU needs "
                 "libpython (Python %s with numpy and numba importable) and could not load "
                 "it (%s%s%s): %s; set FRICTIONLAB_LIBPYTHON to the path of the "
                 "libpython3.x.so of a Python that has numpy and numba",
                 FL_LIBPYTHON_NAME[0] ? FL_LIBPYTHON_NAME : "3",
                 n > 0 ? tried[0] : "no path known", n > 1 ? ", " : "", n > 1 ? tried[1] : "",
                 n > 0 ? dlerror() : "FRICTIONLAB_LIBPYTHON is not set");
        return 0;
    }
    return 1;
}

/* pythonfmu's exit-time reset of its interpreter guard, called before its static
 * destructor runs (see the header: the exit-time heap corruption) */
typedef void finalize_fn(void);
static finalize_fn *inner_finalize = NULL;

static void release_python_guard(void) {
    finalize_fn *f = inner_finalize;
    inner_finalize = NULL;
    if (f != NULL)
        f();
}

static void *sym(const char *name) {
    void *p = dlsym(inner_handle, name);
    if (p == NULL && inner_error[0] == '\0')
        snprintf(inner_error, sizeof inner_error, "fmi2 status shim: %s missing in the inner "
                 "library: %s", name, dlerror());
    return p;
}

/* Load <own path without .so>_pythonfmu.so once per process. */
static int load_inner_path(void) {
    Dl_info info;
    char path[4096];
    size_t n;
    if (!dladdr((void *)&load_inner_path, &info) || info.dli_fname == NULL) {
        snprintf(inner_error, sizeof inner_error, "fmi2 status shim: dladdr failed");
        return 0;
    }
    n = strlen(info.dli_fname);
    if (n < 3 || strcmp(info.dli_fname + n - 3, ".so") != 0 ||
        n - 3 + sizeof INNER_SUFFIX > sizeof path) {
        snprintf(inner_error, sizeof inner_error, "fmi2 status shim: unexpected library "
                 "path %s", info.dli_fname);
        return 0;
    }
    memcpy(path, info.dli_fname, n - 3);
    memcpy(path + n - 3, INNER_SUFFIX, sizeof INNER_SUFFIX);
    if (!load_libpython())
        return 0;
    /* RTLD_NOW | RTLD_LOCAL: what ctypes and most importers use for an FMU binary */
    inner_handle = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (inner_handle == NULL) {
        snprintf(inner_error, sizeof inner_error, "fmi2 status shim: cannot load %s: %s",
                 path, dlerror());
        return 0;
    }
    /* registered after the inner library's static constructors: runs before its static
     * destructors, at process exit - this shim stays loaded like the inner library (which
     * cannot be unloaded), so the guard (and a Python the inner library initialized) is not
     * released while the host may instantiate again */
    inner_finalize = (finalize_fn *)dlsym(inner_handle, "finalizePythonInterpreter");
    if (inner_finalize != NULL &&
        dlopen(info.dli_fname, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE) != NULL)
        atexit(release_python_guard);
    return 1;
}
#endif

static void load_inner(void) {
    if (!load_inner_path())
        return;
#define LOAD(f) inner.f = (fmi2##f##TYPE *)sym("fmi2" #f)
    LOAD(SetDebugLogging); LOAD(Instantiate); LOAD(FreeInstance); LOAD(SetupExperiment);
    LOAD(EnterInitializationMode); LOAD(ExitInitializationMode); LOAD(Terminate); LOAD(Reset);
    LOAD(GetReal); LOAD(GetInteger); LOAD(GetBoolean); LOAD(GetString);
    LOAD(SetReal); LOAD(SetInteger); LOAD(SetBoolean); LOAD(SetString);
    LOAD(GetFMUstate); LOAD(SetFMUstate); LOAD(FreeFMUstate); LOAD(SerializedFMUstateSize);
    LOAD(SerializeFMUstate); LOAD(DeSerializeFMUstate); LOAD(GetDirectionalDerivative);
    LOAD(SetRealInputDerivatives); LOAD(GetRealOutputDerivatives); LOAD(DoStep);
    LOAD(CancelStep); LOAD(GetStatus); LOAD(GetRealStatus); LOAD(GetIntegerStatus);
    LOAD(GetBooleanStatus); LOAD(GetStringStatus);
#undef LOAD
}

static void load_inner_once(void) {
    load_inner();
    no_percent(inner_error);
}

#ifdef _WIN32
static BOOL CALLBACK load_inner_once_cb(PINIT_ONCE once, PVOID param, PVOID *context) {
    (void)once; (void)param; (void)context;
    load_inner_once();
    return TRUE;
}
#define LOAD_INNER_ONCE() InitOnceExecuteOnce(&inner_once, load_inner_once_cb, NULL, NULL)

BOOL WINAPI DllMain(HINSTANCE self, DWORD reason, LPVOID reserved) {
    (void)self;
    /* the importer unloads this library (FreeLibrary: reserved == NULL): unload the inner
     * one with it, as it would have; at process exit the system unloads both */
    if (reason == DLL_PROCESS_DETACH && reserved == NULL && inner_handle != NULL) {
        FreeLibrary(inner_handle);
        inner_handle = NULL;
    }
    return TRUE;
}
#else
#define LOAD_INNER_ONCE() pthread_once(&inner_once, load_inner_once)

__attribute__((destructor)) static void unload_inner(void) {
    /* the importer unloads this library: unload the inner one with it, as it would have */
    if (inner_handle != NULL)
        dlclose(inner_handle);
    inner_handle = NULL;
}
#endif

/* -- per-instance record ---------------------------------------------------------------- */

typedef struct {
    fmi2Component inner;                 /* the pythonfmu instance */
    fmi2CallbackFunctions user;          /* the importer's callbacks (copy) */
    fmi2CallbackFunctions own;           /* what the inner instance gets (kept alive here) */
    int worst;                           /* worst status logged during the current call */
    int logging_on;                      /* importer's debug-logging switch */
    size_t n_categories;                 /* 0: all categories */
    char categories[MAX_CATEGORIES][CATEGORY_LEN];
} Shim;

static int category_enabled(const Shim *s, fmi2String category) {
    size_t i;
    if (s->n_categories == 0)
        return 1;
    if (category == NULL)
        return 0;
    for (i = 0; i < s->n_categories; i++)
        if (strncmp(s->categories[i], category, CATEGORY_LEN) == 0)
            return 1;
    return 0;
}

/* The inner instance's logger: forward the message unchanged (pythonfmu passes it as the
 * format with no arguments) and remember the worst status of the current call. */
static void shim_logger(fmi2ComponentEnvironment env, fmi2String instanceName,
                        fmi2Status status, fmi2String category, fmi2String message, ...) {
    Shim *s = (Shim *)env;
    if (s == NULL)
        return;
    if ((int)status > s->worst)
        s->worst = (int)status;
    if (s->user.logger == NULL)
        return;
    if (status >= fmi2Error || (s->logging_on && category_enabled(s, category)))
        s->user.logger(s->user.componentEnvironment, instanceName, status, category, message);
}

static void set_user_logging(Shim *s, fmi2Boolean loggingOn, size_t n, const fmi2String c[]) {
    size_t i;
    s->logging_on = loggingOn ? 1 : 0;
    s->n_categories = 0;
    if (n > MAX_CATEGORIES || c == NULL)
        return;                          /* too many to track: treat as all categories */
    for (i = 0; i < n; i++) {
        if (c[i] == NULL)
            continue;
        strncpy(s->categories[s->n_categories], c[i], CATEGORY_LEN - 1);
        s->categories[s->n_categories][CATEGORY_LEN - 1] = '\0';
        s->n_categories++;
    }
}

static fmi2Status combine(Shim *s, fmi2Status st) {
    return (int)st >= s->worst ? st : (fmi2Status)s->worst;
}

#define SHIM(c) ((Shim *)(c))
/* forward a call returning fmi2Status; reset the worst logged status first */
#define FORWARD(f, c, ...)                                   \
    do {                                                     \
        Shim *s_ = SHIM(c);                                  \
        fmi2Status st_;                                      \
        if (s_ == NULL || inner.f == NULL) return fmi2Error; \
        s_->worst = fmi2OK;                                  \
        st_ = inner.f(s_->inner, __VA_ARGS__);               \
        return combine(s_, st_);                             \
    } while (0)
#define FORWARD0(f, c)                                       \
    do {                                                     \
        Shim *s_ = SHIM(c);                                  \
        fmi2Status st_;                                      \
        if (s_ == NULL || inner.f == NULL) return fmi2Error; \
        s_->worst = fmi2OK;                                  \
        st_ = inner.f(s_->inner);                            \
        return combine(s_, st_);                             \
    } while (0)

/* -- FMI 2.0 functions ------------------------------------------------------------------ */

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }

const char *fmi2GetVersion(void) { return fmi2Version; }

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation,
                              const fmi2CallbackFunctions *functions, fmi2Boolean visible,
                              fmi2Boolean loggingOn) {
    Shim *s;
    LOAD_INNER_ONCE();
    if (functions == NULL)
        return NULL;
    if (inner_handle == NULL || inner_error[0] != '\0') {
        if (functions->logger != NULL)
            functions->logger(functions->componentEnvironment, instanceName, fmi2Fatal,
                              "logStatusFatal", inner_error);
        return NULL;
    }
    s = (Shim *)calloc(1, sizeof(Shim));
    if (s == NULL)
        return NULL;
    s->user = *functions;
    s->own = *functions;
    s->own.logger = shim_logger;
    s->own.componentEnvironment = s;
    set_user_logging(s, loggingOn, 0, NULL);
    s->inner = inner.Instantiate(instanceName, fmuType, fmuGUID, fmuResourceLocation, &s->own,
                                 visible, fmi2True);
    if (s->inner == NULL) {
        free(s);
        return NULL;
    }
    return (fmi2Component)s;
}

void fmi2FreeInstance(fmi2Component c) {
    Shim *s = SHIM(c);
    if (s == NULL)
        return;
    if (inner.FreeInstance != NULL)
        inner.FreeInstance(s->inner);
    free(s);
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[]) {
    Shim *s = SHIM(c);
    if (s == NULL)
        return fmi2Error;
    set_user_logging(s, loggingOn, nCategories, categories);
    return fmi2OK;  /* the inner instance keeps logging everything to the shim */
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined,
                               fmi2Real tolerance, fmi2Real startTime,
                               fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    FORWARD(SetupExperiment, c, toleranceDefined, tolerance, startTime, stopTimeDefined,
            stopTime);
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) { FORWARD0(EnterInitializationMode, c); }
fmi2Status fmi2ExitInitializationMode(fmi2Component c) { FORWARD0(ExitInitializationMode, c); }
fmi2Status fmi2Terminate(fmi2Component c) { FORWARD0(Terminate, c); }
fmi2Status fmi2Reset(fmi2Component c) { FORWARD0(Reset, c); }

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[]) { FORWARD(GetReal, c, vr, nvr, value); }
fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Integer value[]) { FORWARD(GetInteger, c, vr, nvr, value); }
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Boolean value[]) { FORWARD(GetBoolean, c, vr, nvr, value); }
fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         fmi2String value[]) { FORWARD(GetString, c, vr, nvr, value); }

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[]) { FORWARD(SetReal, c, vr, nvr, value); }
fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Integer value[]) { FORWARD(SetInteger, c, vr, nvr, value); }
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Boolean value[]) { FORWARD(SetBoolean, c, vr, nvr, value); }
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         const fmi2String value[]) { FORWARD(SetString, c, vr, nvr, value); }

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *FMUstate) {
    FORWARD(GetFMUstate, c, FMUstate);
}
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate) {
    FORWARD(SetFMUstate, c, FMUstate);
}
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *FMUstate) {
    FORWARD(FreeFMUstate, c, FMUstate);
}
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t *size) {
    FORWARD(SerializedFMUstateSize, c, FMUstate, size);
}
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate,
                                 fmi2Byte serializedState[], size_t size) {
    FORWARD(SerializeFMUstate, c, FMUstate, serializedState, size);
}
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[],
                                   size_t size, fmi2FMUstate *FMUstate) {
    FORWARD(DeSerializeFMUstate, c, serializedState, size, FMUstate);
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[],
                                        size_t nUnknown, const fmi2ValueReference vKnown_ref[],
                                        size_t nKnown, const fmi2Real dvKnown[],
                                        fmi2Real dvUnknown[]) {
    FORWARD(GetDirectionalDerivative, c, vUnknown_ref, nUnknown, vKnown_ref, nKnown, dvKnown,
            dvUnknown);
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[],
                                       size_t nvr, const fmi2Integer order[],
                                       const fmi2Real value[]) {
    FORWARD(SetRealInputDerivatives, c, vr, nvr, order, value);
}
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[],
                                        size_t nvr, const fmi2Integer order[],
                                        fmi2Real value[]) {
    FORWARD(GetRealOutputDerivatives, c, vr, nvr, order, value);
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
    FORWARD(DoStep, c, currentCommunicationPoint, communicationStepSize,
            noSetFMUStatePriorToCurrentPoint);
}
fmi2Status fmi2CancelStep(fmi2Component c) { FORWARD0(CancelStep, c); }

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value) {
    FORWARD(GetStatus, c, s, value);
}
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value) {
    FORWARD(GetRealStatus, c, s, value);
}
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value) {
    FORWARD(GetIntegerStatus, c, s, value);
}
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value) {
    FORWARD(GetBooleanStatus, c, s, value);
}
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value) {
    FORWARD(GetStringStatus, c, s, value);
}
