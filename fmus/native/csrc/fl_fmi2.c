/* frictionlab native FMU runtime: FMI 2.0 Co-Simulation and Model Exchange in plain C.
 *
 * One file serves every native FMU; what differs is the generated fl_model.h (the variable
 * table written by fmus/native/build.py from the Python parameter dataclasses) and, for a
 * friction law, which laws/<name>.c supplies FL_LAW. Nothing is needed at run time but the
 * C library: no Python, no numpy, no numba.
 *
 * Kinds (FL_KIND): a friction law (inputs v [, a, load, x], output F and the coupling
 * outputs of the linearly implicit plant coupling), the friction_effects block
 * (friction.extensions), the rigid mass of the mass + friction proof loop, and the EMPS axis
 * and its position controller (fl_emps.h, Co-Simulation only).
 *
 * Semantics the tests hold us to:
 * - Co-Simulation: the law's state advances by its own stable kernel (exact exponential
 *   bristle update) over the communication step, the inputs held or first-order held
 *   (inputs_at_step_end), exactly as the Python slave fmus/runtime.py LawSlave does, so the
 *   native and the pythonfmu FMU of a law agree to rounding.
 * - Bad input never gets fmi2OK: a non-finite input or parameter, or a parameter outside its
 *   bounds, is refused with fmi2Error and a log message naming the variable and its bound, and
 *   the previous value is kept; h <= 0, a non-finite h, a communication point that is not the
 *   instance's time, or a call in the wrong state answer fmi2Error.
 * - No global mutable state: every instance owns its data (two instances, two threads).
 * - fmi2GetFMUstate / fmi2SetFMUstate / serialization copy the whole instance data, so a
 *   rollback and redo repeats the first run bit for bit.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"
#include "fl_runtime.h"
#include "fl_law.h"
#include "fl_model.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define MAXS 4        /* most continuous states of any kind */
#define MAXTH 64      /* longest packed theta */
#define NLIN 10       /* coupling outputs: 6 + 4 of a switching law */

enum { M_INSTANTIATED, M_INIT, M_STEP, M_EVENT, M_CONT, M_TERMINATED };
static const char *MODE_NAME[] = {"instantiated", "initialization mode", "step mode",
                                  "event mode", "continuous-time mode", "terminated"};

#define FAIL_PARAMS 1
#define FAIL_STEP 2

/* everything a rollback must restore: one plain struct, copied as a whole */
typedef struct {
    unsigned magic;
    double val[FL_NVARS];
    double state[MAXS];
    double time;
    int mode;
    int params_dirty, outputs_dirty;
    int failed;
    char fail_msg[600];
    /* law: packed parameters and the switch split */
    double theta[MAXTH], th_lo[MAXTH], th_hi[MAXTH], vc;
    int has_switch;
    /* law: memory of the last communication point (coupling extrapolation) */
    double last_in[4];
    int have_last, have_dv, stepped;
    double slope_v, curv_v, dv_last;
    /* EMPS axis and controller: sample clock and held values (fl_emps.h) */
    double ds[8];
} fl_data;

typedef struct {
    fl_data d;
    fmi2CallbackFunctions cb;
    char name[200];
    int logging;
    int me;           /* instantiated as Model Exchange */
    /* value references by role (-1: none) */
    int vr_in[4];     /* v, a, load, x */
    int vr_vmean, vr_share, vr_hlin, vr_foh, vr_use_vmean, vr_use_share, vr_F;
    int vr_lin[NLIN];
    int vr_state[MAXS], vr_der[MAXS];
    int vr_Fin, vr_fext, vr_ffric, vr_x, vr_v, vr_a;
    int vr_ep[FL_EP_MAX], vr_uin, vr_qg, vr_pulse, vr_uout, vr_fmotor;
    int n_states;
} fl_inst;

#define FL_MAGIC 0x464c4e31u  /* "FLN1" */

/* ---------------------------------------------------------------------------------------- */
/* logging */

static void fl_log(fl_inst *c, fmi2Status status, const char *category, const char *fmt, ...)
{
    char raw[1200], esc[2400];
    va_list ap;
    size_t i, j = 0;
    if (!c || !c->cb.logger) return;
    if (status == fmi2OK && !c->logging) return;
    va_start(ap, fmt);
    vsnprintf(raw, sizeof raw, fmt, ap);
    va_end(ap);
    /* the host's logger treats the message as a printf format: double every '%' */
    for (i = 0; raw[i] && j + 2 < sizeof esc; i++) {
        esc[j++] = raw[i];
        if (raw[i] == '%') esc[j++] = '%';
    }
    esc[j] = 0;
    c->cb.logger(c->cb.componentEnvironment, c->name, status, category, esc);
}

#define ERR(c, ...) (fl_log((c), fmi2Error, "logStatusError", __VA_ARGS__), fmi2Error)

static int bad_mode(fl_inst *c, const char *call, int ok_mask)
{
    if (ok_mask & (1 << c->d.mode)) return 0;
    fl_log(c, fmi2Error, "logStatusError", "%s: %s is not allowed in %s", c->name, call,
           MODE_NAME[c->d.mode]);
    return 1;
}
#define ANY_MODE 0x3f
#define B(m) (1 << (m))

/* ---------------------------------------------------------------------------------------- */
/* variables */

static void bound_text(const fl_var *v, char *out, size_t n)
{
    char a[80] = "", b[80] = "";
    if (isfinite(v->lo)) snprintf(a, sizeof a, "%s %s %.17g", v->name, v->lo_open ? ">" : ">=", v->lo);
    if (isfinite(v->hi)) snprintf(b, sizeof b, "%s %s %.17g", v->name, v->hi_open ? "<" : "<=", v->hi);
    if (a[0] && b[0]) snprintf(out, n, "%s and %s", a, b);
    else if (a[0] || b[0]) snprintf(out, n, "%s", a[0] ? a : b);
    else snprintf(out, n, "finite");
}

static int admissible(const fl_var *v, double x)
{
    if (!isfinite(x)) return 0;
    if (x < v->lo || (v->lo_open && x == v->lo)) return 0;
    if (x > v->hi || (v->hi_open && x == v->hi)) return 0;
    return 1;
}

static void set_start_values(fl_inst *c)
{
    int i;
    for (i = 0; i < FL_NVARS; i++) c->d.val[i] = FL_VARS[i].start;
}

static int find_role(int role, int idx)
{
    int i;
    for (i = 0; i < FL_NVARS; i++)
        if (FL_VARS[i].role == role && (idx < 0 || FL_VARS[i].idx == idx)) return i;
    return -1;
}

/* ---------------------------------------------------------------------------------------- */
/* the friction law */

#if FL_KIND == FL_KIND_LAW
static const fl_law_def *const LAW = &FL_LAW;

static void law_inputs(fl_inst *c, double in[4])
{
    int j;
    for (j = 0; j < 4; j++) in[j] = c->vr_in[j] >= 0 ? c->d.val[c->vr_in[j]] : 0.0;
}

/* the law's kernel over one sample (force at a state and inputs) */
static double kernel1(const fl_inst *c, const double *theta, const double *state,
                      const double in[4], double *snew)
{
    double t = 0.0, F, S[MAXS], s0[MAXS] = {0};
    int m = LAW->inputs, j;
    for (j = 0; j < c->n_states; j++) s0[j] = state[j];
    LAW->kernel(1, &t, &in[0], (m & FL_IN_A) ? &in[1] : NULL, (m & FL_IN_LOAD) ? &in[2] : NULL,
                (m & FL_IN_X) ? &in[3] : NULL, theta, 0, s0, &F, S);
    if (snew) for (j = 0; j < c->n_states; j++) snew[j] = S[j];
    return F;
}

/* the law's kernel over [0, h] from inputs in0 to in1: force and state at the end */
static double kernel2(const fl_inst *c, const double *theta, const double *state,
                      const double in0[4], const double in1[4], double h, double *send)
{
    double t[2] = {0.0, h}, v[2] = {in0[0], in1[0]}, a[2] = {in0[1], in1[1]};
    double l[2] = {in0[2], in1[2]}, x[2] = {in0[3], in1[3]}, F[2], S[2 * MAXS], s0[MAXS] = {0};
    int m = LAW->inputs, j, ns = c->n_states;
    for (j = 0; j < ns; j++) s0[j] = state[j];
    LAW->kernel(2, t, v, (m & FL_IN_A) ? a : NULL, (m & FL_IN_LOAD) ? l : NULL,
                (m & FL_IN_X) ? x : NULL, theta, 0, s0, F, S);
    if (send) for (j = 0; j < ns; j++) send[j] = S[ns + j];
    return F[1];
}

/* end force of the step v0 -> v1 with travel to x1, other inputs held (law_linearisation) */
static double f_end(const fl_inst *c, const double *theta, const double *state,
                    const double in[4], double h, double v0, double v1, double x1)
{
    double a[4], b[4];
    memcpy(a, in, sizeof a);
    memcpy(b, in, sizeof b);
    a[0] = v0;
    b[0] = v1;
    b[3] = x1;
    return kernel2(c, theta, state, a, b, h, NULL);
}

static int reversal_time(double v, double a, double b, double h, double *tk)
{
    double roots[2], best = INFINITY;
    int n = 0, i;
    if (v == 0.0) return 0;
    if (b == 0.0) {
        if (a != 0.0) roots[n++] = -v / a;
    } else {
        double disc = a * a - 2.0 * b * v;
        if (disc >= 0.0) {
            double q = sqrt(disc);
            roots[n++] = (-a - q) / b;
            roots[n++] = (-a + q) / b;
        }
    }
    for (i = 0; i < n; i++)
        if (roots[i] > 0.02 * h && roots[i] < 0.98 * h && roots[i] < best) best = roots[i];
    if (!isfinite(best)) return 0;
    *tk = best;
    return 1;
}

/* fmus.runtime.law_linearisation with dv_dt given: (dF_dx, dF_dv, dF_dt, d2F_dt2, t_kink,
 * dF_dt_kink) of the law's step map over h */
static void law_linearisation(const fl_inst *c, const double *theta, const double *state,
                              const double in[4], double h, double dv_dt, double d2v_dt2,
                              double out[6])
{
    double v = in[0], x = in[3], v1, trav, dv, F0, K = 0, D = 0, best = -1, F_now, tk;
    int k;
    v1 = v + (dv_dt + 0.5 * d2v_dt2 * h) * h;
    trav = 0.5 * (v + v1) * h;
    dv = 1e-6 * fmax(fabs(v), fabs(v1)) + 1e-9;
    F0 = f_end(c, theta, state, in, h, v, v1, x + trav);
    for (k = 0; k < 2; k++) {
        double d = k == 0 ? dv : -dv, Dk, Kk, size;
        Dk = (f_end(c, theta, state, in, h, v - d, v1 + d, x + trav) - F0) / d;
        Kk = (f_end(c, theta, state, in, h, v + d, v1 + d, x + trav + d * h) - F0 - Dk * d) / (d * h);
        size = fabs(Kk) * h + fabs(Dk);
        if (best < 0 || size < best) {
            best = size;
            K = Kk;
            D = Dk;
        }
    }
    out[0] = K;
    out[1] = D;
    F_now = kernel1(c, theta, state, in, NULL);
#define RESID(tau, r) do { double vt_ = v + (dv_dt + 0.5 * d2v_dt2 * (tau)) * (tau); \
        double tr_ = 0.5 * (v + vt_) * (tau); \
        (r) = f_end(c, theta, state, in, (tau), v, vt_, x + tr_) - F_now - K * tr_ - D * (vt_ - v); \
    } while (0)
    if (reversal_time(v, dv_dt, d2v_dt2, h, &tk)) {
        double r_k, r_end, s1, s2;
        RESID(tk, r_k);
        RESID(h, r_end);
        s1 = r_k / tk;
        s2 = (r_end - r_k) / (h - tk);
        out[2] = s1; out[3] = 0.0; out[4] = tk; out[5] = s2 - s1;
    } else {
        double r_mid, r_end, curv;
        RESID(0.5 * h, r_mid);
        RESID(h, r_end);
        curv = 4.0 * (r_end - 2.0 * r_mid) / (h * h);
        out[2] = (r_end - 0.5 * curv * h * h) / h; out[3] = curv; out[4] = 0.0; out[5] = 0.0;
    }
#undef RESID
}

/* coupling outputs at the current state and inputs (fmus.runtime LawSlave._linearise) */
static void linearise(fl_inst *c)
{
    double h = c->vr_hlin >= 0 ? c->d.val[c->vr_hlin] : 0.0, in[4], out[NLIN] = {0};
    int j, n = c->d.has_switch ? 10 : 6;
    if (c->vr_lin[0] < 0) return;
    if (h > 0.0) {
        law_inputs(c, in);
        if (c->d.has_switch) {
            int low = fabs(in[0]) < c->d.vc;
            const double *side = low ? c->d.th_lo : c->d.th_hi, *other = low ? c->d.th_hi : c->d.th_lo;
            double o2[6], Fs, Fo;
            law_linearisation(c, side, c->d.state, in, h, c->d.slope_v, c->d.curv_v, out);
            law_linearisation(c, other, c->d.state, in, h, c->d.slope_v, c->d.curv_v, o2);
            Fs = kernel1(c, side, c->d.state, in, NULL);
            Fo = kernel1(c, other, c->d.state, in, NULL);
            out[6] = c->d.vc; out[7] = Fo - Fs; out[8] = o2[0] - out[0]; out[9] = o2[1] - out[1];
        } else {
            law_linearisation(c, c->d.theta, c->d.state, in, h, c->d.slope_v, c->d.curv_v, out);
        }
    }
    for (j = 0; j < n; j++) if (c->vr_lin[j] >= 0) c->d.val[c->vr_lin[j]] = out[j];
}

/* law parameters from the variable table into p[] and theta (fails naming the relation) */
static int build_model(fl_inst *c)
{
    double p[FL_NP];
    char msg[500] = "";
    int i;
    for (i = 0; i < FL_NP; i++) p[i] = NAN;
    for (i = 0; i < FL_NVARS; i++) {
        const fl_var *v = &FL_VARS[i];
        if (v->role == FL_R_PARAM) {
            p[v->idx] = v->type == FL_ENUM ? c->d.val[i] - 1.0 : c->d.val[i];
        }
    }
    for (i = 0; i < FL_NVARS; i++) {  /* an unset twin is "same as +": NAN in p[] */
        const fl_var *v = &FL_VARS[i];
        if (v->role == FL_R_TWIN_FLAG && c->d.val[i] == 0.0) p[v->idx] = NAN;
    }
    if (LAW->pack(p, c->d.theta, msg, sizeof msg)) {
        c->d.failed |= FAIL_PARAMS;
        snprintf(c->d.fail_msg, sizeof c->d.fail_msg, "%s: invalid parameters: %s", c->name, msg);
        return 0;
    }
    c->d.has_switch = 0;
    if (LAW->regimes) {
        if (LAW->regimes(c->d.theta, &c->d.vc, c->d.th_lo, c->d.th_hi)) {
            c->d.failed |= FAIL_PARAMS;
            snprintf(c->d.fail_msg, sizeof c->d.fail_msg, "%s: invalid parameters: the "
                     "regime split at vc failed", c->name);
            return 0;
        }
        c->d.has_switch = 1;
    }
    c->d.failed &= ~FAIL_PARAMS;
    return 1;
}

static void law_outputs(fl_inst *c)
{
    double in[4];
    int j;
    law_inputs(c, in);
    if (c->me) {
        c->d.val[c->vr_F] = LAW->force(c->d.theta, c->d.state, in[0], in[1], in[2], in[3]);
    } else {
        c->d.val[c->vr_F] = kernel1(c, c->d.theta, c->d.state, in, NULL);
    }
    for (j = 0; j < c->n_states; j++) if (c->vr_state[j] >= 0) c->d.val[c->vr_state[j]] = c->d.state[j];
    if (c->me) {
        double dx[MAXS];
        if (c->n_states) {
            LAW->derivatives(c->d.theta, c->d.state, in[0], in[1], in[2], in[3], dx);
            for (j = 0; j < c->n_states; j++) if (c->vr_der[j] >= 0) c->d.val[c->vr_der[j]] = dx[j];
        }
        return;
    }
    if (!c->d.stepped) {
        memcpy(c->d.last_in, in, sizeof in);
        c->d.have_last = 1;
    }
    linearise(c);
}

/* one communication step of the law (fmus.runtime LawSlave.advance); 0: state non-finite */
static int law_advance(fl_inst *c, double h)
{
    double now[4], in0[4], in1[4], snew[MAXS], F;
    double hlin = c->vr_hlin >= 0 ? c->d.val[c->vr_hlin] : 0.0;
    int foh = c->vr_foh >= 0 && c->d.val[c->vr_foh] != 0.0, j;
    if (c->n_states == 0) {
        law_outputs(c);
        return 1;
    }
    law_inputs(c, now);
    memcpy(in0, now, sizeof now);
    memcpy(in1, now, sizeof now);
    if (hlin > 0.0 || foh) {
        if (c->d.have_last) {
            double d1 = now[0] - c->d.last_in[0];
            double d2 = c->d.have_dv ? d1 - c->d.dv_last : 0.0;
            c->d.slope_v = (d1 + 0.5 * d2) / h;
            c->d.curv_v = d2 / (h * h);
            c->d.dv_last = d1;
            c->d.have_dv = 1;
            if (foh) memcpy(in0, c->d.last_in, sizeof in0);
        }
        memcpy(c->d.last_in, now, sizeof now);
        c->d.have_last = 1;
    }
    c->d.stepped = 1;
    {
        int use_mean = c->vr_use_vmean >= 0 && c->d.val[c->vr_use_vmean] != 0.0;
        int use_share = c->d.has_switch && foh && c->vr_use_share >= 0 &&
                        c->d.val[c->vr_use_share] != 0.0;
        if (use_mean) {  /* the state follows the plant's travel over the step */
            in0[0] = in1[0] = c->d.val[c->vr_vmean];
        }
        if (use_share) {  /* the step's mix of both regimes, as the plant saw it */
            double share = c->d.val[c->vr_share], s_lo[MAXS], s_hi[MAXS];
            kernel2(c, c->d.th_lo, c->d.state, in0, in1, h, s_lo);
            kernel2(c, c->d.th_hi, c->d.state, in0, in1, h, s_hi);
            for (j = 0; j < c->n_states; j++) snew[j] = share * s_lo[j] + (1.0 - share) * s_hi[j];
            F = kernel1(c, c->d.theta, snew, now, NULL);
        } else {
            F = kernel2(c, c->d.theta, c->d.state, in0, in1, h, snew);
            if (use_mean) F = kernel1(c, c->d.theta, snew, now, NULL);
        }
    }
    for (j = 0; j < c->n_states; j++) {
        if (!isfinite(snew[j])) {
            c->d.failed |= FAIL_STEP;
            snprintf(c->d.fail_msg, sizeof c->d.fail_msg, "%s: state %s = %g became non-finite "
                     "in the step to t = %.17g", c->name,
                     c->vr_state[j] >= 0 ? FL_VARS[c->vr_state[j]].name : "?", snew[j], c->d.time + h);
            return 0;
        }
    }
    for (j = 0; j < c->n_states; j++) {
        c->d.state[j] = snew[j];
        if (c->vr_state[j] >= 0) c->d.val[c->vr_state[j]] = snew[j];
    }
    c->d.val[c->vr_F] = F;
    linearise(c);
    return 1;
}
#endif /* FL_KIND_LAW */

/* ---------------------------------------------------------------------------------------- */
/* the friction_effects block (friction.extensions.extension_force) */

#if FL_KIND == FL_KIND_EFFECTS
#include "fl_effects.h"

static int build_model(fl_inst *c)
{
    double e[FL_N_EXT];
    char msg[300] = "";
    int i;
    for (i = 0; i < FL_NVARS; i++)
        if (FL_VARS[i].role == FL_R_EXT) e[FL_VARS[i].idx] = c->d.val[i];
    if (fl_effects_check(e, msg, sizeof msg)) {
        c->d.failed |= FAIL_PARAMS;
        snprintf(c->d.fail_msg, sizeof c->d.fail_msg, "%s: invalid parameters: %s", c->name, msg);
        return 0;
    }
    memcpy(c->d.theta, e, sizeof e);
    c->d.failed &= ~FAIL_PARAMS;
    return 1;
}

static void effects_outputs(fl_inst *c)
{
    double *v = c->d.val;
    c->d.val[c->vr_F] = fl_extension_force(v[c->vr_Fin], v[c->vr_in[0]], v[c->vr_in[1]],
                                           v[c->vr_in[3]], v[c->vr_in[2]], c->d.time, c->d.theta);
}
#endif

/* ---------------------------------------------------------------------------------------- */
/* the rigid mass: m dv/dt = u0 + u_amp sin(2 pi u_freq t) + F_ext - F_friction */

#if FL_KIND == FL_KIND_MASS
static double mp(const fl_inst *c, int k)
{
    int i;
    for (i = 0; i < FL_NVARS; i++)
        if (FL_VARS[i].role == FL_R_MASS_PARAM && FL_VARS[i].idx == k) return c->d.val[i];
    return 0.0;
}

static int build_model(fl_inst *c)
{
    c->d.failed &= ~FAIL_PARAMS;  /* m > 0 is the variable's own bound */
    return 1;
}

static void mass_outputs(fl_inst *c)
{
    double *v = c->d.val, w = 2.0 * M_PI * mp(c, 5);
    v[c->vr_x] = c->d.state[0];
    v[c->vr_v] = c->d.state[1];
    v[c->vr_a] = (mp(c, 3) + mp(c, 4) * sin(w * c->d.time) + v[c->vr_fext] - v[c->vr_ffric]) / mp(c, 0);
    if (c->vr_der[0] >= 0) v[c->vr_der[0]] = c->d.state[1];
    if (c->vr_der[1] >= 0) v[c->vr_der[1]] = v[c->vr_a];
}

static void mass_advance(fl_inst *c, double t, double h)
{
    double *v = c->d.val, m = mp(c, 0), amp = mp(c, 4), w = 2.0 * M_PI * mp(c, 5);
    double held = mp(c, 3) + v[c->vr_fext] - v[c->vr_ffric], i1 = 0.0, i2 = 0.0;
    if (w > 0.0) {  /* the sinusoid integrated in closed form: exact for held inputs */
        double c0 = cos(w * t), c1 = cos(w * (t + h)), s0 = sin(w * t), s1 = sin(w * (t + h));
        i1 = amp * (c0 - c1) / w;
        i2 = amp * (h * c0 / w - (s1 - s0) / (w * w));
    }
    c->d.state[0] = c->d.state[0] + c->d.state[1] * h + (0.5 * held * h * h + i2) / m;
    c->d.state[1] = c->d.state[1] + (held * h + i1) / m;
}
#endif

/* ---------------------------------------------------------------------------------------- */
/* the EMPS axis and its position controller */

#if FL_KIND == FL_KIND_EMPS_AXIS || FL_KIND == FL_KIND_EMPS_CTRL
#include "fl_emps.h"
#endif

/* ---------------------------------------------------------------------------------------- */
/* shared by the kinds */

static int ensure_model(fl_inst *c)
{
    if (c->d.params_dirty) {
        if (!build_model(c)) return 0;
        c->d.params_dirty = 0;
        c->d.outputs_dirty = 1;
    }
    return !(c->d.failed & FAIL_PARAMS);
}

static void compute_outputs(fl_inst *c)
{
#if FL_KIND == FL_KIND_LAW
    law_outputs(c);
#elif FL_KIND == FL_KIND_EFFECTS
    effects_outputs(c);
#elif FL_KIND == FL_KIND_MASS
    mass_outputs(c);
#else
    emps_outputs(c);
#endif
    c->d.outputs_dirty = 0;
}

static int update_outputs(fl_inst *c)
{
    if (!ensure_model(c)) return 0;
    if (c->d.outputs_dirty) compute_outputs(c);
    return 1;
}

static void initial_state(fl_inst *c)
{
    memset(c->d.state, 0, sizeof c->d.state);
#if FL_KIND == FL_KIND_MASS
    c->d.state[0] = mp(c, 1);
    c->d.state[1] = mp(c, 2);
#endif
    memset(c->d.ds, 0, sizeof c->d.ds);
#if FL_KIND == FL_KIND_EMPS_AXIS || FL_KIND == FL_KIND_EMPS_CTRL
    c->d.ds[DS_START] = c->d.time;
    emps_initial(c);
#endif
    c->d.have_last = c->d.have_dv = c->d.stepped = 0;
    c->d.slope_v = c->d.curv_v = c->d.dv_last = 0.0;
}

static void reset_data(fl_inst *c)
{
    memset(&c->d, 0, sizeof c->d);
    c->d.magic = FL_MAGIC;
    set_start_values(c);
    c->d.mode = M_INSTANTIATED;
    c->d.params_dirty = 1;
    c->d.outputs_dirty = 1;
}

/* ---------------------------------------------------------------------------------------- */
/* FMI 2.0 common functions */

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

fmi2Status fmi2SetDebugLogging(fmi2Component comp, fmi2Boolean loggingOn, size_t n,
                               const fmi2String categories[])
{
    fl_inst *c = (fl_inst *)comp;
    (void)n; (void)categories;
    if (!c) return fmi2Error;
    c->logging = loggingOn ? 1 : 0;
    return fmi2OK;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String guid,
                              fmi2String resourceLocation,
                              const fmi2CallbackFunctions *functions, fmi2Boolean visible,
                              fmi2Boolean loggingOn)
{
    fl_inst *c;
    int j;
    (void)resourceLocation; (void)visible;
    c = (fl_inst *)calloc(1, sizeof(fl_inst));
    if (!c) return NULL;
    if (functions) c->cb = *functions;
    snprintf(c->name, sizeof c->name, "%s", instanceName ? instanceName : "?");
    c->logging = loggingOn ? 1 : 0;
    if (!guid || strcmp(guid, FL_GUID) != 0) {
        fl_log(c, fmi2Error, "logStatusError", "%s: GUID %s does not match this FMU's %s "
               "(modelDescription.xml and binary from different builds)", c->name,
               guid ? guid : "(null)", FL_GUID);
        free(c);
        return NULL;
    }
    if (fmuType == fmi2ModelExchange && !FL_HAS_ME) {
        fl_log(c, fmi2Error, "logStatusError", "%s: this FMU has no Model Exchange interface",
               c->name);
        free(c);
        return NULL;
    }
    c->me = fmuType == fmi2ModelExchange;
    for (j = 0; j < 4; j++) c->vr_in[j] = find_role(FL_R_IN_V + j, -1);
    c->vr_vmean = find_role(FL_R_IN_VMEAN, -1);
    c->vr_share = find_role(FL_R_IN_SHARE, -1);
    c->vr_hlin = find_role(FL_R_H_LIN, -1);
    c->vr_foh = find_role(FL_R_FOH, -1);
    c->vr_use_vmean = find_role(FL_R_USE_VMEAN, -1);
    c->vr_use_share = find_role(FL_R_USE_SHARE, -1);
    c->vr_F = find_role(FL_R_OUT_F, -1);
    c->vr_Fin = find_role(FL_R_IN_F, -1);
    c->vr_fext = find_role(FL_R_IN_FEXT, -1);
    c->vr_ffric = find_role(FL_R_IN_FFRIC, -1);
    c->vr_x = find_role(FL_R_OUT_X, -1);
    c->vr_v = find_role(FL_R_OUT_V, -1);
    c->vr_a = find_role(FL_R_OUT_A, -1);
    for (j = 0; j < FL_EP_MAX; j++) c->vr_ep[j] = find_role(FL_R_EMPS_PARAM, j);
    c->vr_uin = find_role(FL_R_IN_U, -1);
    c->vr_qg = find_role(FL_R_IN_QG, -1);
    c->vr_pulse = find_role(FL_R_IN_PULSE, -1);
    c->vr_uout = find_role(FL_R_OUT_U, -1);
    c->vr_fmotor = find_role(FL_R_OUT_FMOTOR, -1);
    for (j = 0; j < NLIN; j++) c->vr_lin[j] = find_role(FL_R_OUT_LIN, j);
    for (j = 0; j < MAXS; j++) {
        c->vr_state[j] = find_role(FL_R_STATE, j);
        c->vr_der[j] = find_role(FL_R_DER, j);
    }
    c->n_states = FL_NSTATES;
    reset_data(c);
    initial_state(c);
    return c;
}

void fmi2FreeInstance(fmi2Component comp)
{
    free(comp);
}

fmi2Status fmi2SetupExperiment(fmi2Component comp, fmi2Boolean toleranceDefined,
                               fmi2Real tolerance, fmi2Real startTime, fmi2Boolean stopTimeDefined,
                               fmi2Real stopTime)
{
    fl_inst *c = (fl_inst *)comp;
    (void)toleranceDefined; (void)tolerance; (void)stopTimeDefined; (void)stopTime;
    if (!c) return fmi2Error;
    if (bad_mode(c, "fmi2SetupExperiment", B(M_INSTANTIATED))) return fmi2Error;
    if (!isfinite(startTime))
        return ERR(c, "%s: fmi2SetupExperiment: startTime = %g is not finite", c->name, startTime);
    c->d.time = startTime;
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component comp)
{
    fl_inst *c = (fl_inst *)comp;
    if (!c) return fmi2Error;
    if (bad_mode(c, "fmi2EnterInitializationMode", B(M_INSTANTIATED))) return fmi2Error;
    c->d.mode = M_INIT;
    return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component comp)
{
    fl_inst *c = (fl_inst *)comp;
    if (!c) return fmi2Error;
    if (bad_mode(c, "fmi2ExitInitializationMode", B(M_INIT))) return fmi2Error;
    c->d.params_dirty = 1;
    if (!ensure_model(c)) {
        c->d.mode = c->me ? M_EVENT : M_STEP;
        return ERR(c, "%s (initialization)", c->d.fail_msg);
    }
    initial_state(c);
    c->d.outputs_dirty = 1;
    c->d.mode = c->me ? M_EVENT : M_STEP;
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component comp)
{
    fl_inst *c = (fl_inst *)comp;
    if (!c) return fmi2Error;
    if (bad_mode(c, "fmi2Terminate", B(M_STEP) | B(M_EVENT) | B(M_CONT))) return fmi2Error;
    c->d.mode = M_TERMINATED;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component comp)
{
    fl_inst *c = (fl_inst *)comp;
    if (!c) return fmi2Error;
    reset_data(c);
    initial_state(c);
    return fmi2OK;
}

static int check_vr(fl_inst *c, const char *call, fmi2ValueReference vr, int type)
{
    static const char *TYPE[] = {"Real", "Integer", "Boolean", "Integer (Enumeration)"};
    if (vr >= FL_NVARS) {
        fl_log(c, fmi2Error, "logStatusError", "%s: %s: value reference %u does not exist "
               "(valid: 0..%d)", c->name, call, (unsigned)vr, FL_NVARS - 1);
        return 0;
    }
    if (FL_VARS[vr].type != type && !(type == FL_INTEGER && FL_VARS[vr].type == FL_ENUM)) {
        fl_log(c, fmi2Error, "logStatusError", "%s: %s: %s (value reference %u) is not a %s "
               "variable", c->name, call, FL_VARS[vr].name, (unsigned)vr, TYPE[type]);
        return 0;
    }
    return 1;
}

static fmi2Status get_values(fl_inst *c, const char *call, const fmi2ValueReference vr[],
                             size_t n, int type, double *out)
{
    size_t i;
    fmi2Status st = fmi2OK;
    if (bad_mode(c, call, ANY_MODE & ~B(M_INSTANTIATED))) {
        /* values of parameters and inputs are their start values: allowed? FMI says no */
        return fmi2Error;
    }
    if (c->d.mode != M_INIT && !update_outputs(c)) {
        fl_log(c, fmi2Error, "logStatusError", "%s (values read by %s are not valid)",
               c->d.fail_msg, call);
        st = fmi2Error;
    } else if (c->d.mode != M_INIT && (c->d.failed & FAIL_STEP)) {
        fl_log(c, fmi2Error, "logStatusError", "%s (values read by %s are not valid)",
               c->d.fail_msg, call);
        st = fmi2Error;
    } else if (c->d.mode == M_INIT && c->d.params_dirty) {
        /* outputs during initialization: evaluated from the start state */
        if (ensure_model(c)) {
            initial_state(c);
            compute_outputs(c);
        } else {
            fl_log(c, fmi2Error, "logStatusError", "%s (values read by %s)", c->d.fail_msg, call);
            st = fmi2Error;
        }
    } else if (c->d.mode == M_INIT && c->d.outputs_dirty && ensure_model(c)) {
        compute_outputs(c);
    }
    for (i = 0; i < n; i++) {
        if (!check_vr(c, call, vr[i], type)) {
            out[i] = 0.0;
            st = fmi2Error;
            continue;
        }
        out[i] = c->d.val[vr[i]];
    }
    return st;
}

static fmi2Status set_value(fl_inst *c, const char *call, fmi2ValueReference vr, double x,
                            int type)
{
    const fl_var *v;
    char bt[300];
    if (!check_vr(c, call, vr, type)) return fmi2Error;
    v = &FL_VARS[vr];
    if (v->causality == FL_OUTPUT || v->causality == FL_LOCAL)
        return ERR(c, "%s: %s: %s is an output and cannot be set; %.17g ignored", c->name, call,
                   v->name, x);
    if (v->causality == FL_PARAMETER && c->d.mode == M_TERMINATED)
        return ERR(c, "%s: %s: parameter %s cannot be set after fmi2Terminate", c->name, call,
                   v->name);
    if (v->causality == FL_INPUT && !(type == FL_REAL) && 0) return fmi2Error;
    if (type == FL_REAL) {
        if (!isfinite(x))
            return ERR(c, "%s: %s %s = %g is not finite; value rejected, %s keeps %.17g",
                       c->name, v->causality == FL_INPUT ? "input" : "parameter", v->name, x,
                       v->name, c->d.val[vr]);
        if (v->causality == FL_PARAMETER && !admissible(v, x)) {
            bound_text(v, bt, sizeof bt);
            return ERR(c, "%s: parameter %s = %.17g is out of bounds: must be %s [%s]; value "
                       "rejected, %s keeps %.17g", c->name, v->name, x, bt, v->unit, v->name,
                       c->d.val[vr]);
        }
    } else if (v->type == FL_ENUM || v->type == FL_INTEGER) {
        if (x < v->lo || x > v->hi)
            return ERR(c, "%s: %s = %.0f is out of range: must be %.0f..%.0f; value rejected, "
                       "%s keeps %.0f", c->name, v->name, x, v->lo, v->hi, v->name, c->d.val[vr]);
    }
    c->d.val[vr] = x;
    if (v->causality == FL_PARAMETER) c->d.params_dirty = 1;
    c->d.outputs_dirty = 1;
    return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[])
{
    fl_inst *c = (fl_inst *)comp;
    if (!c) return fmi2Error;
    return get_values(c, "fmi2GetReal", vr, nvr, FL_REAL, value);
}

fmi2Status fmi2GetInteger(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Integer value[])
{
    fl_inst *c = (fl_inst *)comp;
    double buf[64];
    size_t i, k;
    fmi2Status st = fmi2OK, s;
    if (!c) return fmi2Error;
    for (k = 0; k < nvr; k += 64) {
        size_t m = nvr - k < 64 ? nvr - k : 64;
        s = get_values(c, "fmi2GetInteger", vr + k, m, FL_INTEGER, buf);
        if (s > st) st = s;
        for (i = 0; i < m; i++) value[k + i] = (fmi2Integer)buf[i];
    }
    return st;
}

fmi2Status fmi2GetBoolean(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Boolean value[])
{
    fl_inst *c = (fl_inst *)comp;
    double buf[64];
    size_t i, k;
    fmi2Status st = fmi2OK, s;
    if (!c) return fmi2Error;
    for (k = 0; k < nvr; k += 64) {
        size_t m = nvr - k < 64 ? nvr - k : 64;
        s = get_values(c, "fmi2GetBoolean", vr + k, m, FL_BOOLEAN, buf);
        if (s > st) st = s;
        for (i = 0; i < m; i++) value[k + i] = buf[i] != 0.0 ? fmi2True : fmi2False;
    }
    return st;
}

fmi2Status fmi2GetString(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                         fmi2String value[])
{
    fl_inst *c = (fl_inst *)comp;
    (void)vr; (void)value;
    if (!c) return fmi2Error;
    if (nvr == 0) return fmi2OK;
    return ERR(c, "%s: fmi2GetString: this FMU has no String variables", c->name);
}

fmi2Status fmi2SetReal(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[])
{
    fl_inst *c = (fl_inst *)comp;
    size_t i;
    fmi2Status st = fmi2OK, s;
    if (!c) return fmi2Error;
    if (bad_mode(c, "fmi2SetReal", ANY_MODE)) return fmi2Error;
    for (i = 0; i < nvr; i++) {
        s = set_value(c, "fmi2SetReal", vr[i], value[i], FL_REAL);
        if (s > st) st = s;
    }
    return st;
}

fmi2Status fmi2SetInteger(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Integer value[])
{
    fl_inst *c = (fl_inst *)comp;
    size_t i;
    fmi2Status st = fmi2OK, s;
    if (!c) return fmi2Error;
    for (i = 0; i < nvr; i++) {
        s = set_value(c, "fmi2SetInteger", vr[i], (double)value[i], FL_INTEGER);
        if (s > st) st = s;
    }
    return st;
}

fmi2Status fmi2SetBoolean(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Boolean value[])
{
    fl_inst *c = (fl_inst *)comp;
    size_t i;
    fmi2Status st = fmi2OK, s;
    if (!c) return fmi2Error;
    for (i = 0; i < nvr; i++) {
        s = set_value(c, "fmi2SetBoolean", vr[i], value[i] ? 1.0 : 0.0, FL_BOOLEAN);
        if (s > st) st = s;
    }
    return st;
}

fmi2Status fmi2SetString(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                         const fmi2String value[])
{
    fl_inst *c = (fl_inst *)comp;
    (void)vr; (void)value;
    if (!c) return fmi2Error;
    if (nvr == 0) return fmi2OK;
    return ERR(c, "%s: fmi2SetString: this FMU has no String variables", c->name);
}

/* FMU state: a heap copy of the instance data */
fmi2Status fmi2GetFMUstate(fmi2Component comp, fmi2FMUstate *state)
{
    fl_inst *c = (fl_inst *)comp;
    fl_data *copy;
    if (!c || !state) return fmi2Error;
    copy = *state ? (fl_data *)*state : (fl_data *)malloc(sizeof(fl_data));
    if (!copy) return ERR(c, "%s: fmi2GetFMUstate: out of memory", c->name);
    memcpy(copy, &c->d, sizeof(fl_data));
    *state = copy;
    return fmi2OK;
}

fmi2Status fmi2SetFMUstate(fmi2Component comp, fmi2FMUstate state)
{
    fl_inst *c = (fl_inst *)comp;
    if (!c) return fmi2Error;
    if (!state || ((fl_data *)state)->magic != FL_MAGIC)
        return ERR(c, "%s: fmi2SetFMUstate: not a state of this FMU", c->name);
    memcpy(&c->d, state, sizeof(fl_data));
    return fmi2OK;
}

fmi2Status fmi2FreeFMUstate(fmi2Component comp, fmi2FMUstate *state)
{
    (void)comp;
    if (state && *state) {
        free(*state);
        *state = NULL;
    }
    return fmi2OK;
}

/* serialized form: GUID (fixed 40 bytes) + size + the data struct */
#define SER_HEAD 48
fmi2Status fmi2SerializedFMUstateSize(fmi2Component comp, fmi2FMUstate state, size_t *size)
{
    (void)comp; (void)state;
    if (!size) return fmi2Error;
    *size = SER_HEAD + sizeof(fl_data);
    return fmi2OK;
}

fmi2Status fmi2SerializeFMUstate(fmi2Component comp, fmi2FMUstate state, fmi2Byte bytes[],
                                 size_t size)
{
    fl_inst *c = (fl_inst *)comp;
    unsigned long long n = sizeof(fl_data);
    if (!c) return fmi2Error;
    if (!state || !bytes || size < SER_HEAD + sizeof(fl_data))
        return ERR(c, "%s: fmi2SerializeFMUstate: buffer of %lu bytes, need %lu", c->name,
                   (unsigned long)size, (unsigned long)(SER_HEAD + sizeof(fl_data)));
    memset(bytes, 0, SER_HEAD);
    strncpy((char *)bytes, FL_GUID, 39);
    memcpy(bytes + 40, &n, 8);
    memcpy(bytes + SER_HEAD, state, sizeof(fl_data));
    return fmi2OK;
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component comp, const fmi2Byte bytes[], size_t size,
                                   fmi2FMUstate *state)
{
    fl_inst *c = (fl_inst *)comp;
    unsigned long long n;
    fl_data *copy;
    char guid[40];
    if (!c || !state) return fmi2Error;
    if (!bytes || size != SER_HEAD + sizeof(fl_data))
        return ERR(c, "%s: fmi2DeSerializeFMUstate: %lu bytes is not a serialized state of "
                   "this FMU (%lu bytes)", c->name, (unsigned long)size,
                   (unsigned long)(SER_HEAD + sizeof(fl_data)));
    memcpy(guid, bytes, 39);
    guid[39] = 0;
    memcpy(&n, bytes + 40, 8);
    if (strncmp(guid, FL_GUID, 39) != 0 || n != sizeof(fl_data))
        return ERR(c, "%s: fmi2DeSerializeFMUstate: the bytes are a state of another FMU "
                   "(GUID %s)", c->name, guid);
    copy = (fl_data *)malloc(sizeof(fl_data));
    if (!copy) return ERR(c, "%s: fmi2DeSerializeFMUstate: out of memory", c->name);
    memcpy(copy, bytes + SER_HEAD, sizeof(fl_data));
    if (copy->magic != FL_MAGIC) {
        free(copy);
        return ERR(c, "%s: fmi2DeSerializeFMUstate: corrupt state", c->name);
    }
    *state = copy;
    return fmi2OK;
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component comp, const fmi2ValueReference u[],
                                        size_t nu, const fmi2ValueReference z[], size_t nz,
                                        const fmi2Real dv[], fmi2Real dz[])
{
    fl_inst *c = (fl_inst *)comp;
    (void)u; (void)nu; (void)z; (void)nz; (void)dv; (void)dz;
    if (!c) return fmi2Error;
    return ERR(c, "%s: fmi2GetDirectionalDerivative is not provided "
               "(providesDirectionalDerivative = false)", c->name);
}

/* ---------------------------------------------------------------------------------------- */
/* Co-Simulation */

fmi2Status fmi2SetRealInputDerivatives(fmi2Component comp, const fmi2ValueReference vr[],
                                       size_t nvr, const fmi2Integer order[],
                                       const fmi2Real value[])
{
    fl_inst *c = (fl_inst *)comp;
    (void)vr; (void)nvr; (void)order; (void)value;
    if (!c) return fmi2Error;
    return ERR(c, "%s: fmi2SetRealInputDerivatives: canInterpolateInputs = false", c->name);
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component comp, const fmi2ValueReference vr[],
                                        size_t nvr, const fmi2Integer order[],
                                        fmi2Real value[])
{
    fl_inst *c = (fl_inst *)comp;
    (void)vr; (void)nvr; (void)order; (void)value;
    if (!c) return fmi2Error;
    return ERR(c, "%s: fmi2GetRealOutputDerivatives: maxOutputDerivativeOrder = 0", c->name);
}

fmi2Status fmi2DoStep(fmi2Component comp, fmi2Real t, fmi2Real h,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint)
{
    fl_inst *c = (fl_inst *)comp;
    double tol;
    (void)noSetFMUStatePriorToCurrentPoint;
    if (!c) return fmi2Error;
    if (c->me) return ERR(c, "%s: fmi2DoStep on a Model Exchange instance", c->name);
    if (bad_mode(c, "fmi2DoStep", B(M_STEP))) return fmi2Error;
    if (!isfinite(h) || !(h > 0.0))
        return ERR(c, "%s: fmi2DoStep: communicationStepSize = %g must be finite and > 0 [s]",
                   c->name, h);
    tol = 1e-9 * fmax(1.0, fabs(c->d.time)) + 1e-9 * h;
    if (!isfinite(t) || fabs(t - c->d.time) > tol)
        return ERR(c, "%s: fmi2DoStep: currentCommunicationPoint = %.17g is not this instance's "
                   "time %.17g (a time jump; roll back with fmi2SetFMUstate)", c->name, t,
                   c->d.time);
    if (!ensure_model(c))
        return ERR(c, "%s (step at t = %.17g refused)", c->d.fail_msg, t);
    if (c->d.failed & FAIL_STEP)
        return ERR(c, "%s (the instance refuses further steps; fmi2Reset or fmi2SetFMUstate)",
                   c->d.fail_msg);
#if FL_KIND == FL_KIND_LAW
    if (!law_advance(c, h))
        return ERR(c, "%s (the instance refuses further steps)", c->d.fail_msg);
    c->d.time = t + h;
    c->d.outputs_dirty = 0;
#elif FL_KIND == FL_KIND_EFFECTS
    c->d.time = t + h;
    compute_outputs(c);
#elif FL_KIND == FL_KIND_MASS
    mass_advance(c, t, h);
    c->d.time = t + h;
    compute_outputs(c);
#else
    emps_advance(c, t, h);
    c->d.time = t + h;
    compute_outputs(c);
#endif
    {
        int i;
        for (i = 0; i < FL_NVARS; i++) {
            if (FL_VARS[i].causality == FL_OUTPUT && !isfinite(c->d.val[i])) {
                c->d.failed |= FAIL_STEP;
                snprintf(c->d.fail_msg, sizeof c->d.fail_msg, "%s: output %s = %g is not finite "
                         "after the step to t = %.17g", c->name, FL_VARS[i].name, c->d.val[i],
                         c->d.time);
                return ERR(c, "%s (the instance refuses further steps)", c->d.fail_msg);
            }
        }
    }
    return fmi2OK;
}

fmi2Status fmi2CancelStep(fmi2Component comp)
{
    fl_inst *c = (fl_inst *)comp;
    if (!c) return fmi2Error;
    return ERR(c, "%s: fmi2CancelStep: steps are never asynchronous", c->name);
}

fmi2Status fmi2GetStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Status *value)
{
    fl_inst *c = (fl_inst *)comp;
    (void)s; (void)value;
    if (!c) return fmi2Error;
    return fmi2Discard;
}

fmi2Status fmi2GetRealStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Real *value)
{
    fl_inst *c = (fl_inst *)comp;
    if (!c || !value) return fmi2Error;
    if (s == fmi2LastSuccessfulTime) {
        *value = c->d.time;
        return fmi2OK;
    }
    return fmi2Discard;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Integer *value)
{
    (void)comp; (void)s; (void)value;
    return fmi2Discard;
}

fmi2Status fmi2GetBooleanStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Boolean *value)
{
    (void)comp;
    if (s == fmi2Terminated && value) {
        *value = fmi2False;
        return fmi2OK;
    }
    return fmi2Discard;
}

fmi2Status fmi2GetStringStatus(fmi2Component comp, const fmi2StatusKind s, fmi2String *value)
{
    (void)comp; (void)s; (void)value;
    return fmi2Discard;
}

/* ---------------------------------------------------------------------------------------- */
/* Model Exchange: the law's states integrated by the host's solver */

/* Scale of state j (the host's absolute tolerance is its relative tolerance times this):
 * the law's steady state at a slow creep in either direction (the bristle's saturated
 * deflection g/sigma0), found by one exact kernel step far longer than any time constant. */
static double state_nominal(fl_inst *c, int j)
{
#if FL_KIND == FL_KIND_LAW
    double in0[4], in1[4], s[MAXS], zero[MAXS] = {0}, best = 0.0;
    int k;
    if (!ensure_model(c)) return 1.0;
    law_inputs(c, in0);
    for (k = 0; k < 2; k++) {
        in0[0] = k ? -1e-4 : 1e-4;
        memcpy(in1, in0, sizeof in1);
        kernel2(c, c->d.theta, zero, in0, in1, 1e6, s);
        if (isfinite(s[j]) && fabs(s[j]) > best) best = fabs(s[j]);
    }
    return best > 0.0 ? best : 1.0;
#else
    (void)c; (void)j;
    return 1.0;
#endif
}

fmi2Status fmi2EnterEventMode(fmi2Component comp)
{
    fl_inst *c = (fl_inst *)comp;
    if (!c) return fmi2Error;
    if (bad_mode(c, "fmi2EnterEventMode", B(M_EVENT) | B(M_CONT))) return fmi2Error;
    c->d.mode = M_EVENT;
    return fmi2OK;
}

fmi2Status fmi2NewDiscreteStates(fmi2Component comp, fmi2EventInfo *info)
{
    fl_inst *c = (fl_inst *)comp;
    if (!c || !info) return fmi2Error;
    if (bad_mode(c, "fmi2NewDiscreteStates", B(M_EVENT))) return fmi2Error;
    info->newDiscreteStatesNeeded = fmi2False;
    info->terminateSimulation = fmi2False;
    info->nominalsOfContinuousStatesChanged = fmi2False;
    info->valuesOfContinuousStatesChanged = fmi2False;
    info->nextEventTimeDefined = fmi2False;
    info->nextEventTime = 0.0;
    return fmi2OK;
}

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component comp)
{
    fl_inst *c = (fl_inst *)comp;
    if (!c) return fmi2Error;
    if (bad_mode(c, "fmi2EnterContinuousTimeMode", B(M_EVENT))) return fmi2Error;
    c->d.mode = M_CONT;
    return fmi2OK;
}

fmi2Status fmi2CompletedIntegratorStep(fmi2Component comp, fmi2Boolean noSetPrior,
                                       fmi2Boolean *enterEventMode, fmi2Boolean *terminate)
{
    fl_inst *c = (fl_inst *)comp;
    (void)noSetPrior;
    if (!c) return fmi2Error;
    if (bad_mode(c, "fmi2CompletedIntegratorStep", B(M_CONT))) return fmi2Error;
    if (enterEventMode) *enterEventMode = fmi2False;
    if (terminate) *terminate = fmi2False;
    return fmi2OK;
}

fmi2Status fmi2SetTime(fmi2Component comp, fmi2Real time)
{
    fl_inst *c = (fl_inst *)comp;
    if (!c) return fmi2Error;
    if (!isfinite(time)) return ERR(c, "%s: fmi2SetTime: time = %g is not finite", c->name, time);
    c->d.time = time;
    c->d.outputs_dirty = 1;
    return fmi2OK;
}

fmi2Status fmi2SetContinuousStates(fmi2Component comp, const fmi2Real x[], size_t nx)
{
    fl_inst *c = (fl_inst *)comp;
    size_t j;
    if (!c) return fmi2Error;
    if (bad_mode(c, "fmi2SetContinuousStates", B(M_EVENT) | B(M_CONT))) return fmi2Error;
    if ((int)nx != c->n_states)
        return ERR(c, "%s: fmi2SetContinuousStates: nx = %lu, this FMU has %d states", c->name,
                   (unsigned long)nx, c->n_states);
    for (j = 0; j < nx; j++)
        if (!isfinite(x[j]))
            return ERR(c, "%s: fmi2SetContinuousStates: state %s = %g is not finite; states "
                       "rejected", c->name, c->vr_state[j] >= 0 ? FL_VARS[c->vr_state[j]].name : "?", x[j]);
    for (j = 0; j < nx; j++) c->d.state[j] = x[j];
    c->d.outputs_dirty = 1;
    return fmi2OK;
}

fmi2Status fmi2GetDerivatives(fmi2Component comp, fmi2Real dx[], size_t nx)
{
    fl_inst *c = (fl_inst *)comp;
    size_t j;
    if (!c) return fmi2Error;
    if ((int)nx != c->n_states)
        return ERR(c, "%s: fmi2GetDerivatives: nx = %lu, this FMU has %d states", c->name,
                   (unsigned long)nx, c->n_states);
    if (!update_outputs(c))
        return ERR(c, "%s (fmi2GetDerivatives)", c->d.fail_msg);
    for (j = 0; j < nx; j++) dx[j] = c->vr_der[j] >= 0 ? c->d.val[c->vr_der[j]] : 0.0;
    return fmi2OK;
}

fmi2Status fmi2GetEventIndicators(fmi2Component comp, fmi2Real ind[], size_t ni)
{
    fl_inst *c = (fl_inst *)comp;
    if (!c) return fmi2Error;
    if ((int)ni != FL_NEVENT)
        return ERR(c, "%s: fmi2GetEventIndicators: ni = %lu, this FMU has %d", c->name,
                   (unsigned long)ni, FL_NEVENT);
#if FL_KIND == FL_KIND_LAW
    if (ni > 0) {
        if (!ensure_model(c)) return ERR(c, "%s (fmi2GetEventIndicators)", c->d.fail_msg);
        /* the load law's coefficients jump at |v| = vc */
        ind[0] = fabs(c->d.val[c->vr_in[0]]) - c->d.vc;
    }
#else
    (void)ind;
#endif
    return fmi2OK;
}

fmi2Status fmi2GetContinuousStates(fmi2Component comp, fmi2Real x[], size_t nx)
{
    fl_inst *c = (fl_inst *)comp;
    size_t j;
    if (!c) return fmi2Error;
    if ((int)nx != c->n_states)
        return ERR(c, "%s: fmi2GetContinuousStates: nx = %lu, this FMU has %d states", c->name,
                   (unsigned long)nx, c->n_states);
    for (j = 0; j < nx; j++) x[j] = c->d.state[j];
    return fmi2OK;
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component comp, fmi2Real x_nominal[], size_t nx)
{
    fl_inst *c = (fl_inst *)comp;
    size_t j;
    if (!c) return fmi2Error;
    if ((int)nx != c->n_states)
        return ERR(c, "%s: fmi2GetNominalsOfContinuousStates: nx = %lu, this FMU has %d states",
                   c->name, (unsigned long)nx, c->n_states);
    for (j = 0; j < nx; j++) x_nominal[j] = state_nominal(c, (int)j);
    return fmi2OK;
}
