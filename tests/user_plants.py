"""Plant FMUs that the plant library did not build, for the tests of the user's-own-plant path
(``fmus.connect``, ``identification.plant_fmu``, ``diagnosis.plant_fmu``).

* :func:`build_c_cart`: a tiny FMI 2.0 co-simulation FMU in plain C, compiled here against
  fmpy's FMI 2 headers: a cart ``m a = k_u u + F_c - d v`` (drive voltage ``u`` [V] through a
  gain ``k_u`` [N/V], contact force ``F_c`` [N] *added*, viscous damping ``d`` [N.s/m]; a
  negative ``d`` makes it unstable), integrated with classical RK4 substeps, outputs ``pos``,
  ``vel``, ``acc``; ``m <= 0`` fails fmi2ExitInitializationMode with a logged message. An
  input ``F_kN`` declared in kN serves the unit-mismatch test.
* :func:`build_c_pd`: a stateless PD position controller as a second C FMU (a further
  plant-side FMU of a connection's ``[fmus]``).
* :func:`build_python_cart`: the same kind of plant as a pythonfmu FMU written only for the
  tests (``m dv/dt = F_drive - F_friction``, semi-implicit Euler substeps), no units declared.
"""
from __future__ import annotations

import pathlib
import shutil
import subprocess
import uuid
import zipfile

C_SOURCE = r"""
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fmi2Functions.h"

enum { VR_M, VR_D, VR_KU, VR_X0, VR_U, VR_FC, VR_POS, VR_VEL, VR_ACC, VR_FKN, N_VR };
static const double START[N_VR] = {1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};

typedef struct {
    double r[N_VR];
    double x, v;
    int initialized;
    fmi2CallbackFunctions cb;
    char name[64];
} Cart;

static void logf_(Cart *c, fmi2Status st, const char *msg)
{
    /* the message as the format (no '%' in it): hosts calling back through ctypes (fmpy)
     * do not format variadic arguments */
    if (c->cb.logger) c->cb.logger(c->cb.componentEnvironment, c->name, st, "error", msg);
}

static double accel(const Cart *c, double v)
{
    return (c->r[VR_KU] * c->r[VR_U] + c->r[VR_FC] - c->r[VR_D] * v) / c->r[VR_M];
}

static void outputs(Cart *c)
{
    c->r[VR_POS] = c->x;
    c->r[VR_VEL] = c->v;
    c->r[VR_ACC] = accel(c, c->v);
}

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }
fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t n, const fmi2String cat[])
{ (void)c; (void)on; (void)n; (void)cat; return fmi2OK; }

fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid,
                              fmi2String res, const fmi2CallbackFunctions *cb,
                              fmi2Boolean vis, fmi2Boolean log)
{
    Cart *c;
    (void)guid; (void)res; (void)vis; (void)log;
    if (type != fmi2CoSimulation) return NULL;
    c = (Cart *)calloc(1, sizeof(Cart));
    if (!c) return NULL;
    memcpy(c->r, START, sizeof(START));
    if (cb) c->cb = *cb;
    strncpy(c->name, name ? name : "cart", sizeof(c->name) - 1);
    return c;
}

void fmi2FreeInstance(fmi2Component c) { free(c); }

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean tolDef, fmi2Real tol,
                               fmi2Real t0, fmi2Boolean stopDef, fmi2Real stop)
{ (void)c; (void)tolDef; (void)tol; (void)t0; (void)stopDef; (void)stop; return fmi2OK; }

fmi2Status fmi2EnterInitializationMode(fmi2Component c) { (void)c; return fmi2OK; }

fmi2Status fmi2ExitInitializationMode(fmi2Component comp)
{
    Cart *c = (Cart *)comp;
    char msg[160];
    if (!(c->r[VR_M] > 0)) {
        snprintf(msg, sizeof msg, "m = %g is out of bounds: must be > 0 [kg]", c->r[VR_M]);
        logf_(c, fmi2Error, msg);
        return fmi2Error;
    }
    c->x = c->r[VR_X0];
    c->v = 0.0;
    c->initialized = 1;
    outputs(c);
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c) { (void)c; return fmi2OK; }

fmi2Status fmi2Reset(fmi2Component comp)
{
    Cart *c = (Cart *)comp;
    memcpy(c->r, START, sizeof(START));
    c->x = c->v = 0.0;
    c->initialized = 0;
    return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component comp, const fmi2ValueReference vr[], size_t n,
                       fmi2Real value[])
{
    Cart *c = (Cart *)comp;
    size_t i;
    if (c->initialized) outputs(c);
    for (i = 0; i < n; i++) {
        if (vr[i] >= N_VR) return fmi2Error;
        value[i] = c->r[vr[i]];
    }
    return fmi2OK;
}

fmi2Status fmi2SetReal(fmi2Component comp, const fmi2ValueReference vr[], size_t n,
                       const fmi2Real value[])
{
    Cart *c = (Cart *)comp;
    size_t i;
    for (i = 0; i < n; i++) {
        if (vr[i] >= N_VR || vr[i] == VR_POS || vr[i] == VR_VEL || vr[i] == VR_ACC)
            return fmi2Error;
        c->r[vr[i]] = value[i];
    }
    return fmi2OK;
}

fmi2Status fmi2DoStep(fmi2Component comp, fmi2Real t, fmi2Real h, fmi2Boolean nsp)
{
    Cart *c = (Cart *)comp;
    int k, nsub = 4;
    double dt = h / nsub;
    (void)t; (void)nsp;
    for (k = 0; k < nsub; k++) {   /* classical RK4 with the inputs held */
        double x1 = c->v, v1 = accel(c, c->v);
        double x2 = c->v + 0.5 * dt * v1, v2 = accel(c, x2);
        double x3 = c->v + 0.5 * dt * v2, v3 = accel(c, x3);
        double x4 = c->v + dt * v3, v4 = accel(c, x4);
        c->x += dt / 6.0 * (x1 + 2.0 * x2 + 2.0 * x3 + x4);
        c->v += dt / 6.0 * (v1 + 2.0 * v2 + 2.0 * v3 + v4);
    }
    return fmi2OK;
}

"""

C_STUBS = r"""
#define UNSUPPORTED return fmi2Error
fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Integer v[]) { (void)c; (void)vr; (void)v; return n ? fmi2Error : fmi2OK; }
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Boolean v[]) { (void)c; (void)vr; (void)v; return n ? fmi2Error : fmi2OK; }
fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2String v[]) { (void)c; (void)vr; (void)v; return n ? fmi2Error : fmi2OK; }
fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer v[]) { (void)c; (void)vr; (void)v; return n ? fmi2Error : fmi2OK; }
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Boolean v[]) { (void)c; (void)vr; (void)v; return n ? fmi2Error : fmi2OK; }
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2String v[]) { (void)c; (void)vr; (void)v; return n ? fmi2Error : fmi2OK; }
fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *s) { (void)c; (void)s; UNSUPPORTED; }
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate s) { (void)c; (void)s; UNSUPPORTED; }
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *s) { (void)c; (void)s; UNSUPPORTED; }
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate s, size_t *n) { (void)c; (void)s; (void)n; UNSUPPORTED; }
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate s, fmi2Byte b[], size_t n) { (void)c; (void)s; (void)b; (void)n; UNSUPPORTED; }
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte b[], size_t n, fmi2FMUstate *s) { (void)c; (void)b; (void)n; (void)s; UNSUPPORTED; }
fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference a[], size_t na, const fmi2ValueReference b[], size_t nb, const fmi2Real dv[], fmi2Real df[]) { (void)c; (void)a; (void)na; (void)b; (void)nb; (void)dv; (void)df; UNSUPPORTED; }
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer o[], const fmi2Real v[]) { (void)c; (void)vr; (void)n; (void)o; (void)v; UNSUPPORTED; }
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer o[], fmi2Real v[]) { (void)c; (void)vr; (void)n; (void)o; (void)v; UNSUPPORTED; }
fmi2Status fmi2CancelStep(fmi2Component c) { (void)c; UNSUPPORTED; }
fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind k, fmi2Status *v) { (void)c; (void)k; (void)v; UNSUPPORTED; }
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind k, fmi2Real *v) { (void)c; (void)k; (void)v; UNSUPPORTED; }
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind k, fmi2Integer *v) { (void)c; (void)k; (void)v; UNSUPPORTED; }
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind k, fmi2Boolean *v) { (void)c; (void)k; (void)v; UNSUPPORTED; }
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind k, fmi2String *v) { (void)c; (void)k; (void)v; UNSUPPORTED; }
"""

_C_VARIABLES = [  # name, vr, causality, unit, start, description
    ("m", 0, "parameter", "kg", 1.0, "moving mass"),
    ("d", 1, "parameter", "N.s/m", 0.0, "viscous damping (negative: unstable)"),
    ("k_u", 2, "parameter", "N/V", 1.0, "drive gain"),
    ("x0", 3, "parameter", "m", 0.0, "initial position"),
    ("u", 4, "input", "V", 0.0, "drive voltage"),
    ("F_c", 5, "input", "N", 0.0, "contact force along +x (added)"),
    ("pos", 6, "output", "m", None, "position"),
    ("vel", 7, "output", "m/s", None, "velocity"),
    ("acc", 8, "output", "m/s2", None, "acceleration"),
    ("F_kN", 9, "input", "kN", 0.0, "an unused force input in kN"),
]


def _c_model_description(guid: str, ident: str = "cart", variables=None,
                         deps=None) -> str:
    variables = _C_VARIABLES if variables is None else variables
    deps = {"acc": ("u", "F_c")} if deps is None else deps
    units = sorted({u for _, _, _, u, _, _ in variables})
    udefs = "\n".join(f'    <Unit name="{u}"/>' for u in units)
    rows = []
    for name, vr, caus, unit, start, desc in variables:
        if caus == "output":
            rows.append(f'    <ScalarVariable name="{name}" valueReference="{vr}" '
                        f'causality="output" variability="continuous" initial="calculated" '
                        f'description="{desc}"><Real unit="{unit}"/></ScalarVariable>')
        else:
            var = "fixed" if caus == "parameter" else "continuous"
            rows.append(f'    <ScalarVariable name="{name}" valueReference="{vr}" '
                        f'causality="{caus}" variability="{var}" description="{desc}">'
                        f'<Real unit="{unit}" start="{start!r}"/></ScalarVariable>')
    index = {name: k + 1 for k, (name, *_r) in enumerate(variables)}
    outs = "\n".join(
        f'      <Unknown index="{index[name]}" dependencies="'
        f'{" ".join(str(index[d]) for d in deps.get(name, ()))}"/>'
        for name, _, caus, *_r in variables if caus == "output")
    head = (f'<?xml version="1.0" encoding="UTF-8"?>\n'
            f'<fmiModelDescription fmiVersion="2.0" modelName="{ident}" guid="{guid}" '
            f'generationTool="frictionlab tests" numberOfEventIndicators="0">\n'
            f'  <CoSimulation modelIdentifier="{ident}" '
            f'canHandleVariableCommunicationStepSize="true"/>\n'
            f'  <UnitDefinitions>\n{udefs}\n  </UnitDefinitions>\n'
            f'  <DefaultExperiment startTime="0" stopTime="1" stepSize="1e-3"/>\n')
    return (head + "  <ModelVariables>\n" + "\n".join(rows) + "\n  </ModelVariables>\n"
            "  <ModelStructure>\n    <Outputs>\n" + outs + "\n    </Outputs>\n"
            "    <InitialUnknowns>\n" + outs + "\n    </InitialUnknowns>\n"
            "  </ModelStructure>\n</fmiModelDescription>\n")


def _build_c_fmu(out_dir, ident, source, md) -> pathlib.Path:
    from fmus.status_shim import fmi2_header_dir
    out = pathlib.Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    src = out / f"{ident}.c"
    src.write_text(source)
    so = out / f"{ident}.so"
    cc = shutil.which("cc") or shutil.which("gcc")
    if cc is None:
        raise RuntimeError("no C compiler")
    subprocess.run([cc, "-std=c99", "-O2", "-shared", "-fPIC", "-Wall", "-Wextra",
                    f"-I{fmi2_header_dir()}", str(src), "-o", str(so), "-lm"], check=True,
                   capture_output=True, text=True)
    fmu = out / f"{ident}.fmu"
    with zipfile.ZipFile(fmu, "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr("modelDescription.xml", md)
        z.write(so, f"binaries/linux64/{ident}.so")
        z.write(src, f"sources/{ident}.c")
    return fmu


def build_c_cart(out_dir) -> pathlib.Path:
    """Compile the C cart into ``out_dir/cart.fmu`` (linux64 binary; needs a C compiler)."""
    return _build_c_fmu(out_dir, "cart", C_SOURCE + C_STUBS,
                        _c_model_description("{" + str(uuid.uuid4()) + "}"))


PD_SOURCE = r"""
#include <stdlib.h>
#include <string.h>
#include "fmi2Functions.h"

/* a PD position controller without state: u = kp (r - y) - kd ydot [V] */
enum { VR_KP, VR_KD, VR_R, VR_Y, VR_YD, VR_U, N_VR };
static const double START[N_VR] = {20.0, 2.0, 0.0, 0.0, 0.0, 0.0};
typedef struct { double r[N_VR]; } Pd;

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }
fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t n, const fmi2String cat[])
{ (void)c; (void)on; (void)n; (void)cat; return fmi2OK; }
fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid, fmi2String res,
                              const fmi2CallbackFunctions *cb, fmi2Boolean vis, fmi2Boolean log)
{
    Pd *c;
    (void)name; (void)guid; (void)res; (void)cb; (void)vis; (void)log;
    if (type != fmi2CoSimulation) return NULL;
    c = (Pd *)calloc(1, sizeof(Pd));
    if (c) memcpy(c->r, START, sizeof(START));
    return c;
}
void fmi2FreeInstance(fmi2Component c) { free(c); }
fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean a, fmi2Real b, fmi2Real t0, fmi2Boolean d, fmi2Real e)
{ (void)c; (void)a; (void)b; (void)t0; (void)d; (void)e; return fmi2OK; }
fmi2Status fmi2EnterInitializationMode(fmi2Component c) { (void)c; return fmi2OK; }
fmi2Status fmi2ExitInitializationMode(fmi2Component c) { (void)c; return fmi2OK; }
fmi2Status fmi2Terminate(fmi2Component c) { (void)c; return fmi2OK; }
fmi2Status fmi2Reset(fmi2Component comp) { memcpy(((Pd *)comp)->r, START, sizeof(START)); return fmi2OK; }
fmi2Status fmi2GetReal(fmi2Component comp, const fmi2ValueReference vr[], size_t n, fmi2Real v[])
{
    Pd *c = (Pd *)comp;
    size_t i;
    c->r[VR_U] = c->r[VR_KP] * (c->r[VR_R] - c->r[VR_Y]) - c->r[VR_KD] * c->r[VR_YD];
    for (i = 0; i < n; i++) { if (vr[i] >= N_VR) return fmi2Error; v[i] = c->r[vr[i]]; }
    return fmi2OK;
}
fmi2Status fmi2SetReal(fmi2Component comp, const fmi2ValueReference vr[], size_t n, const fmi2Real v[])
{
    Pd *c = (Pd *)comp;
    size_t i;
    for (i = 0; i < n; i++) { if (vr[i] >= VR_U) return fmi2Error; c->r[vr[i]] = v[i]; }
    return fmi2OK;
}
fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean nsp)
{ (void)c; (void)t; (void)h; (void)nsp; return fmi2OK; }
"""

_PD_VARIABLES = [
    ("kp", 0, "parameter", "V/m", 20.0, "proportional gain"),
    ("kd", 1, "parameter", "V.s/m", 2.0, "derivative gain"),
    ("r", 2, "input", "m", 0.0, "reference position"),
    ("y", 3, "input", "m", 0.0, "measured position"),
    ("ydot", 4, "input", "m/s", 0.0, "measured velocity"),
    ("u", 5, "output", "V", None, "command"),
]


def build_c_pd(out_dir) -> pathlib.Path:
    """Compile a PD position controller (``u = kp (r - y) - kd ydot``) into
    ``out_dir/pd.fmu``: a second plant-side FMU for the connection's ``[fmus]``."""
    return _build_c_fmu(out_dir, "pd", PD_SOURCE + C_STUBS, _c_model_description(
        "{" + str(uuid.uuid4()) + "}", "pd", _PD_VARIABLES, {"u": ("r", "y", "ydot")}))


PY_SOURCE = '''
from pythonfmu import Fmi2Causality, Fmi2Initial, Fmi2Slave, Fmi2Variability, Real


class {cls}(Fmi2Slave):
    """A cart written for the tests: m dv/dt = F_drive - F_friction."""

    author = "frictionlab tests"
    description = "cart m dv/dt = F_drive - F_friction (semi-implicit Euler substeps)"

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.m = 1.0
        self.F_drive = 0.0
        self.F_friction = 0.0
        self.x = 0.0
        self.v = 0.0
        self.register_variable(Real("m", causality=Fmi2Causality.parameter,
                                    variability=Fmi2Variability.tunable))
        self.register_variable(Real("F_drive", causality=Fmi2Causality.input))
        self.register_variable(Real("F_friction", causality=Fmi2Causality.input))
        self.register_variable(Real("x", causality=Fmi2Causality.output,
                                    initial=Fmi2Initial.exact))
        self.register_variable(Real("v", causality=Fmi2Causality.output,
                                    initial=Fmi2Initial.exact))

    def exit_initialization_mode(self):
        self.x = 0.0
        self.v = 0.0

    def do_step(self, current_time, step_size):
        n = 4
        dt = step_size / n
        for _ in range(n):
            self.v += dt * (self.F_drive - self.F_friction) / self.m
            self.x += dt * self.v
        return True
'''


def build_python_cart(out_dir, cls: str = "PyCartForTests") -> pathlib.Path:
    """Build the pythonfmu cart into ``out_dir/<cls>.fmu`` (the module name ``cls`` must be
    unique in the process that runs it)."""
    from pythonfmu.builder import FmuBuilder
    out = pathlib.Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    script = out / f"{cls}.py"
    script.write_text(PY_SOURCE.format(cls=cls))
    return pathlib.Path(FmuBuilder.build_FMU(script, dest=out))
