/* A minimal FMI 2.0 Co-Simulation host in plain C, for tests/test_native_hosts.py.
 *
 * It stands for a user's tool (Simulink S-function, Dymola, a C++ engine): nothing but the C
 * library and the FMU's shared library. The test compiles it with the system C compiler
 * against the FMI 2.0 headers and runs it under `env -i` (no Python anywhere).
 *
 *     host SPEC
 *
 * SPEC is a text file, one directive per line ('#' starts a comment):
 *
 *     lib PATH          the FMU's binaries/linux64/<modelIdentifier>.so (dlopen'ed)
 *     guid GUID         the modelDescription's guid
 *     resources URI     fmi2Instantiate's resourceLocation (optional)
 *     real VR VALUE     fmi2SetReal before fmi2EnterInitializationMode (VALUE: any strtod
 *                       form, hex floats included, so Python's float.hex() is exact)
 *     int VR VALUE      fmi2SetInteger (Integer and Enumeration variables)
 *     bool VR 0|1       fmi2SetBoolean
 *     inputs K VR...    Real inputs set before each fmi2DoStep (K values per step)
 *     outputs M VR...   Real outputs read after initialization and after each fmi2DoStep
 *     steps N           communication steps per cycle
 *     h H               communication step size [s]
 *     t0 T0             start time [s]
 *     infile PATH       N*K native doubles, row by row (the inputs of step k)
 *     outfile PATH      written: (N+1)*M native doubles (row 0: after initialization)
 *     cycles C          instantiate / initialize / step / terminate / free, C times; every
 *                       cycle must give the first cycle's outputs bit for bit
 *     rollback K        in every cycle, at step K: fmi2GetFMUstate, step on, serialize and
 *                       deserialize the state, fmi2SetFMUstate, redo: the redo must repeat
 *                       the first pass bit for bit
 *     reset 1           in every cycle, after fmi2Terminate: fmi2Reset and run again in the
 *                       same instance; the second run must repeat the first bit for bit
 *
 * Exit codes: 0 success; 1 usage or file error; 2 an FMI call did not return fmi2OK;
 * 3 a cycle differs from the first; 4 a rollback redo differs; 5 a reset run differs.
 * Messages go to stderr; the FMU's log messages are printed there too.
 */
#define _POSIX_C_SOURCE 200809L
#include <dlfcn.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"

#define MAXV 64

static const char *STATUS[] = {"OK", "Warning", "Discard", "Error", "Fatal", "Pending"};

typedef struct {
    fmi2InstantiateTYPE *instantiate;
    fmi2FreeInstanceTYPE *free_instance;
    fmi2SetupExperimentTYPE *setup;
    fmi2EnterInitializationModeTYPE *enter_init;
    fmi2ExitInitializationModeTYPE *exit_init;
    fmi2TerminateTYPE *terminate;
    fmi2ResetTYPE *reset;
    fmi2SetRealTYPE *set_real;
    fmi2SetIntegerTYPE *set_integer;
    fmi2SetBooleanTYPE *set_boolean;
    fmi2GetRealTYPE *get_real;
    fmi2DoStepTYPE *do_step;
    fmi2GetFMUstateTYPE *get_state;
    fmi2SetFMUstateTYPE *set_state;
    fmi2FreeFMUstateTYPE *free_state;
    fmi2SerializedFMUstateSizeTYPE *ser_size;
    fmi2SerializeFMUstateTYPE *serialize;
    fmi2DeSerializeFMUstateTYPE *deserialize;
} api;

typedef struct {
    char lib[4096], guid[200], resources[4096], infile[4096], outfile[4096];
    int n_real, n_int, n_bool, n_in, n_out;
    fmi2ValueReference vr_real[MAXV], vr_int[MAXV], vr_bool[MAXV], vr_in[MAXV], vr_out[MAXV];
    double real[MAXV];
    int integer[MAXV], boolean[MAXV];
    long steps, cycles, rollback;
    int reset;
    double h, t0;
} spec;

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status,
                   fmi2String category, fmi2String message, ...)
{
    va_list ap;
    (void)env;
    fprintf(stderr, "[%s] %s (%s): ", status <= fmi2Pending ? STATUS[status] : "?",
            name ? name : "?", category ? category : "");
    va_start(ap, message);
    vfprintf(stderr, message, ap);
    va_end(ap);
    fputc('\n', stderr);
}

static void die(int code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "host: ");
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    exit(code);
}

#define CHECK(call) do { fmi2Status s_ = (call); \
        if (s_ != fmi2OK) die(2, "%s returned %s (line %d)", #call, \
                              s_ >= 0 && s_ <= fmi2Pending ? STATUS[s_] : "?", __LINE__); \
    } while (0)

static void *sym(void *lib, const char *name)
{
    void *f = dlsym(lib, name);
    if (!f) die(1, "%s not exported: %s", name, dlerror());
    return f;
}

static int read_vrs(char *rest, fmi2ValueReference *out)
{
    char *tok = strtok(rest, " \t\r\n");
    int n, i;
    if (!tok) die(1, "a count is missing");
    n = atoi(tok);
    if (n < 0 || n > MAXV) die(1, "at most %d value references", MAXV);
    for (i = 0; i < n; i++) {
        tok = strtok(NULL, " \t\r\n");
        if (!tok) die(1, "%d value references announced, %d given", n, i);
        out[i] = (fmi2ValueReference)strtoul(tok, NULL, 10);
    }
    return n;
}

static void read_spec(const char *path, spec *s)
{
    FILE *f = fopen(path, "r");
    char line[8192], key[64];
    int off;
    if (!f) die(1, "cannot open %s", path);
    memset(s, 0, sizeof *s);
    s->cycles = 1;
    s->rollback = -1;
    s->h = 1e-4;
    while (fgets(line, sizeof line, f)) {
        char *rest;
        if (line[0] == '#' || sscanf(line, "%63s%n", key, &off) != 1) continue;
        rest = line + off;
        while (*rest == ' ' || *rest == '\t') rest++;
        rest[strcspn(rest, "\r\n")] = 0;
        if (!strcmp(key, "lib")) snprintf(s->lib, sizeof s->lib, "%s", rest);
        else if (!strcmp(key, "guid")) snprintf(s->guid, sizeof s->guid, "%s", rest);
        else if (!strcmp(key, "resources")) snprintf(s->resources, sizeof s->resources, "%s", rest);
        else if (!strcmp(key, "infile")) snprintf(s->infile, sizeof s->infile, "%s", rest);
        else if (!strcmp(key, "outfile")) snprintf(s->outfile, sizeof s->outfile, "%s", rest);
        else if (!strcmp(key, "steps")) s->steps = strtol(rest, NULL, 10);
        else if (!strcmp(key, "cycles")) s->cycles = strtol(rest, NULL, 10);
        else if (!strcmp(key, "rollback")) s->rollback = strtol(rest, NULL, 10);
        else if (!strcmp(key, "reset")) s->reset = atoi(rest);
        else if (!strcmp(key, "h")) s->h = strtod(rest, NULL);
        else if (!strcmp(key, "t0")) s->t0 = strtod(rest, NULL);
        else if (!strcmp(key, "inputs")) s->n_in = read_vrs(rest, s->vr_in);
        else if (!strcmp(key, "outputs")) s->n_out = read_vrs(rest, s->vr_out);
        else if (!strcmp(key, "real") || !strcmp(key, "int") || !strcmp(key, "bool")) {
            unsigned long vr;
            char val[200];
            if (sscanf(rest, "%lu %199s", &vr, val) != 2) die(1, "bad line: %s", line);
            if (key[0] == 'r') {
                if (s->n_real == MAXV) die(1, "too many real lines");
                s->vr_real[s->n_real] = (fmi2ValueReference)vr;
                s->real[s->n_real++] = strtod(val, NULL);
            } else if (key[0] == 'i') {
                if (s->n_int == MAXV) die(1, "too many int lines");
                s->vr_int[s->n_int] = (fmi2ValueReference)vr;
                s->integer[s->n_int++] = atoi(val);
            } else {
                if (s->n_bool == MAXV) die(1, "too many bool lines");
                s->vr_bool[s->n_bool] = (fmi2ValueReference)vr;
                s->boolean[s->n_bool++] = atoi(val) ? fmi2True : fmi2False;
            }
        } else die(1, "unknown directive %s", key);
    }
    fclose(f);
    if (!s->lib[0] || !s->guid[0]) die(1, "lib and guid are required");
    if (s->steps < 0 || s->cycles < 1) die(1, "steps >= 0 and cycles >= 1 required");
}

static double *read_inputs(const spec *s)
{
    size_t n = (size_t)s->steps * (size_t)s->n_in, got;
    double *u;
    FILE *f;
    if (n == 0) return calloc(1, sizeof(double));
    if (!s->infile[0]) die(1, "inputs given but no infile");
    f = fopen(s->infile, "rb");
    if (!f) die(1, "cannot open %s", s->infile);
    u = malloc(n * sizeof(double));
    if (!u) die(1, "out of memory");
    got = fread(u, sizeof(double), n, f);
    if (got != n) die(1, "%s holds %lu doubles, need %lu", s->infile, (unsigned long)got,
                      (unsigned long)n);
    fclose(f);
    return u;
}

/* steps k0..k1-1 from the instance's current time; outputs after step k go to row k+1 */
static void run_steps(const api *a, fmi2Component c, const spec *s, const double *u,
                      long k0, long k1, double *y)
{
    long k;
    for (k = k0; k < k1; k++) {
        double t = s->t0 + (double)k * s->h;
        if (s->n_in) CHECK(a->set_real(c, s->vr_in, (size_t)s->n_in, u + (size_t)k * s->n_in));
        CHECK(a->do_step(c, t, s->h, fmi2True));
        if (s->n_out)
            CHECK(a->get_real(c, s->vr_out, (size_t)s->n_out, y + (size_t)(k + 1) * s->n_out));
    }
}

/* the rollback check at step K: state saved, steps on, restored through serialization,
 * redone; the redo must equal the first pass */
static void rollback_check(const api *a, fmi2Component c, const spec *s, const double *u,
                           double *y)
{
    long k0 = s->rollback, k1 = s->rollback + 50 > s->steps ? s->steps : s->rollback + 50;
    size_t rows = (size_t)(k1 - k0), m = (size_t)s->n_out, size = 0;
    fmi2FMUstate saved = NULL, restored = NULL;
    fmi2Byte *bytes;
    double *first = malloc((rows + 1) * m * sizeof(double) + 1);
    if (!first) die(1, "out of memory");
    CHECK(a->get_state(c, &saved));
    run_steps(a, c, s, u, k0, k1, y);
    memcpy(first, y + (size_t)(k0 + 1) * m, rows * m * sizeof(double));
    CHECK(a->ser_size(c, saved, &size));
    bytes = malloc(size ? size : 1);
    if (!bytes) die(1, "out of memory");
    CHECK(a->serialize(c, saved, bytes, size));
    CHECK(a->deserialize(c, bytes, size, &restored));
    CHECK(a->set_state(c, restored));
    run_steps(a, c, s, u, k0, k1, y);
    if (memcmp(first, y + (size_t)(k0 + 1) * m, rows * m * sizeof(double)) != 0)
        die(4, "the redo of steps %ld..%ld after fmi2SetFMUstate differs from the first pass",
            k0, k1 - 1);
    CHECK(a->free_state(c, &saved));
    CHECK(a->free_state(c, &restored));
    free(bytes);
    free(first);
    run_steps(a, c, s, u, k1, s->steps, y);
}

/* one run in an instantiated (or reset) instance: parameters, initialization, steps */
static void run(const api *a, fmi2Component c, const spec *s, const double *u, double *y)
{
    if (s->n_real) CHECK(a->set_real(c, s->vr_real, (size_t)s->n_real, s->real));
    if (s->n_int) CHECK(a->set_integer(c, s->vr_int, (size_t)s->n_int, s->integer));
    if (s->n_bool) CHECK(a->set_boolean(c, s->vr_bool, (size_t)s->n_bool, s->boolean));
    CHECK(a->setup(c, fmi2False, 0.0, s->t0, fmi2False, 0.0));
    CHECK(a->enter_init(c));
    CHECK(a->exit_init(c));
    if (s->n_out) CHECK(a->get_real(c, s->vr_out, (size_t)s->n_out, y));
    if (s->rollback >= 0 && s->rollback < s->steps) {
        run_steps(a, c, s, u, 0, s->rollback, y);
        rollback_check(a, c, s, u, y);
    } else {
        run_steps(a, c, s, u, 0, s->steps, y);
    }
    CHECK(a->terminate(c));
}

int main(int argc, char **argv)
{
    spec s;
    api a;
    void *lib;
    double *u, *y, *y0, *y2;
    size_t ny;
    long cyc;
    fmi2CallbackFunctions cb;
    char name[64];

    if (argc != 2) die(1, "usage: host SPEC");
    read_spec(argv[1], &s);
    lib = dlopen(s.lib, RTLD_NOW | RTLD_LOCAL);
    if (!lib) die(1, "dlopen %s: %s", s.lib, dlerror());
    a.instantiate = (fmi2InstantiateTYPE *)sym(lib, "fmi2Instantiate");
    a.free_instance = (fmi2FreeInstanceTYPE *)sym(lib, "fmi2FreeInstance");
    a.setup = (fmi2SetupExperimentTYPE *)sym(lib, "fmi2SetupExperiment");
    a.enter_init = (fmi2EnterInitializationModeTYPE *)sym(lib, "fmi2EnterInitializationMode");
    a.exit_init = (fmi2ExitInitializationModeTYPE *)sym(lib, "fmi2ExitInitializationMode");
    a.terminate = (fmi2TerminateTYPE *)sym(lib, "fmi2Terminate");
    a.reset = (fmi2ResetTYPE *)sym(lib, "fmi2Reset");
    a.set_real = (fmi2SetRealTYPE *)sym(lib, "fmi2SetReal");
    a.set_integer = (fmi2SetIntegerTYPE *)sym(lib, "fmi2SetInteger");
    a.set_boolean = (fmi2SetBooleanTYPE *)sym(lib, "fmi2SetBoolean");
    a.get_real = (fmi2GetRealTYPE *)sym(lib, "fmi2GetReal");
    a.do_step = (fmi2DoStepTYPE *)sym(lib, "fmi2DoStep");
    a.get_state = (fmi2GetFMUstateTYPE *)sym(lib, "fmi2GetFMUstate");
    a.set_state = (fmi2SetFMUstateTYPE *)sym(lib, "fmi2SetFMUstate");
    a.free_state = (fmi2FreeFMUstateTYPE *)sym(lib, "fmi2FreeFMUstate");
    a.ser_size = (fmi2SerializedFMUstateSizeTYPE *)sym(lib, "fmi2SerializedFMUstateSize");
    a.serialize = (fmi2SerializeFMUstateTYPE *)sym(lib, "fmi2SerializeFMUstate");
    a.deserialize = (fmi2DeSerializeFMUstateTYPE *)sym(lib, "fmi2DeSerializeFMUstate");

    u = read_inputs(&s);
    ny = (size_t)(s.steps + 1) * (size_t)s.n_out;
    y = calloc(ny + 1, sizeof(double));
    y0 = calloc(ny + 1, sizeof(double));
    y2 = calloc(ny + 1, sizeof(double));
    if (!y || !y0 || !y2) die(1, "out of memory");
    cb.logger = logger;
    cb.allocateMemory = calloc;
    cb.freeMemory = free;
    cb.stepFinished = NULL;
    cb.componentEnvironment = NULL;

    for (cyc = 0; cyc < s.cycles; cyc++) {
        fmi2Component c;
        snprintf(name, sizeof name, "host%ld", cyc);
        c = a.instantiate(name, fmi2CoSimulation, s.guid, s.resources[0] ? s.resources : NULL,
                          &cb, fmi2False, fmi2False);
        if (!c) die(2, "fmi2Instantiate returned NULL (cycle %ld)", cyc);
        run(&a, c, &s, u, y);
        if (s.reset) {
            CHECK(a.reset(c));
            run(&a, c, &s, u, y2);
            if (memcmp(y, y2, ny * sizeof(double)) != 0)
                die(5, "cycle %ld: the run after fmi2Reset differs from the first", cyc);
        }
        a.free_instance(c);
        if (cyc == 0) memcpy(y0, y, ny * sizeof(double));
        else if (memcmp(y0, y, ny * sizeof(double)) != 0)
            die(3, "cycle %ld differs from cycle 0", cyc);
    }
    if (s.outfile[0]) {
        FILE *f = fopen(s.outfile, "wb");
        if (!f || fwrite(y0, sizeof(double), ny, f) != ny) die(1, "cannot write %s", s.outfile);
        fclose(f);
    }
    free(u);
    free(y);
    free(y0);
    free(y2);
    dlclose(lib);
    return 0;
}
