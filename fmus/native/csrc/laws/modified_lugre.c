/* Modified LuGre of seed 000 (friction/modified_lugre.py), the same arithmetic as its numba
 * kernel.
 *
 *   dz/dt = Gamma(v) [v - sigma0 |v| / g(v) z]
 *   F     = sigma0 z + sigma1 dz/dt + sigma2 v + F_d + b
 *   F_d^ss(v, a) = f_a sgn(a) [1 - exp(-(|a|/a_s)^beta)] exp(-(|v|/v_c)^gamma)
 *
 * Gamma: logistic (gamma_form 0) or cosine (1). Lag state q: F_d itself (fd_form 0, "lag":
 * tau dF_d/dt + F_d = F_d^ss(v, a)) or a filtered acceleration (fd_form 1: tau da_f/dt + a_f
 * = a, F_d = F_d^ss(v, a_f)); tau = 0: static F_d. Inputs v and a; states (z, q).
 */
#include "fl_law.h"
#include "fl_stribeck.h"

/* p[]: the fields of friction.modified_lugre.ModifiedLuGreParams in declaration order */
enum { P_S0, P_S1, P_S2, P_FC, P_FS, P_VS, P_ALPHA, P_B, P_FA, P_AS, P_VC, P_BETA, P_GAM,
       P_TAU, P_V1, P_V2, P_FCN, P_FSN, P_VSN, P_S2N, P_FAN, P_ASN, P_VCN, P_SHAPE, P_GFORM,
       P_FDFORM, P_N };
/* theta: friction.modified_lugre._LAYOUT (the classic LuGre block first) */
enum { S0, S1, S2P, S2N, FCP, FCN, FSP, FSN, VSP, VSN, ALPHA, B, SHAPE, FAP, FAN, ASP, ASN,
       VCP, VCN, BETA, GAM, TAU, V1, V2, GFORM, FDFORM, TH_N };

/* math.log(99.0) and math.pi, bit for bit */
#define ML_LN99 0x1.2616719161d2bp+2
#define ML_PI 0x1.921fb54442d18p+1

static const char *const ml_gamma_forms[] = {"logistic", "cosine"};
static const char *const ml_fd_forms[] = {"lag", "filtered_acceleration"};

static int ml_pack(const double *p, double *th, char *msg, size_t msglen)
{
    if (fl_check_option("shape", p[P_SHAPE], fl_shape_names, 2, msg, msglen)
        || fl_check_option("gamma_form", p[P_GFORM], ml_gamma_forms, 2, msg, msglen)
        || fl_check_option("fd_form", p[P_FDFORM], ml_fd_forms, 2, msg, msglen))
        return 1;
    if (!(p[P_V2] > p[P_V1])) {
        if (msg != NULL && msglen > 0) {
            char a[32], b[32];
            fl_fmt(p[P_V2], a, sizeof a);
            fl_fmt(p[P_V1], b, sizeof b);
            snprintf(msg, msglen, "v2 = %s must be > v1 = %s [m/s] (switch band of Gamma(v): "
                     "Gamma ~ 1 below v1, ~ 0 above v2)", a, b);
        }
        return 1;
    }
    th[S0] = p[P_S0];
    th[S1] = p[P_S1];
    th[S2P] = p[P_S2];
    th[S2N] = fl_twin(p[P_S2N], p[P_S2]);
    th[FCP] = p[P_FC];
    th[FCN] = fl_twin(p[P_FCN], p[P_FC]);
    th[FSP] = p[P_FS];
    th[FSN] = fl_twin(p[P_FSN], p[P_FS]);
    th[VSP] = p[P_VS];
    th[VSN] = fl_twin(p[P_VSN], p[P_VS]);
    th[ALPHA] = p[P_ALPHA];
    th[B] = p[P_B];
    th[SHAPE] = p[P_SHAPE];
    th[FAP] = p[P_FA];
    th[FAN] = fl_twin(p[P_FAN], p[P_FA]);
    th[ASP] = p[P_AS];
    th[ASN] = fl_twin(p[P_ASN], p[P_AS]);
    th[VCP] = p[P_VC];
    th[VCN] = fl_twin(p[P_VCN], p[P_VC]);
    th[BETA] = p[P_BETA];
    th[GAM] = p[P_GAM];
    th[TAU] = p[P_TAU];
    th[V1] = p[P_V1];
    th[V2] = p[P_V2];
    th[GFORM] = p[P_GFORM];
    th[FDFORM] = p[P_FDFORM];
    return 0;
}

/* switch Gamma(v) (numba switch_gamma) */
static double ml_switch_gamma(double v, double v1, double v2, double form)
{
    const double s = fabs(v);
    double arg, e;
    if (form == 1.0) {
        if (s <= v1)
            return 1.0;
        if (s >= v2)
            return 0.0;
        return 0.5 * (1.0 + cos(ML_PI * (s - v1) / (v2 - v1)));
    }
    arg = 2.0 * ML_LN99 / (v2 - v1) * (s - 0.5 * (v1 + v2));
    if (arg > 0.0) {
        e = exp(-arg);
        return e / (1.0 + e);
    }
    return 1.0 / (1.0 + exp(arg));
}

static double ml_pow(double r, double p)
{
    if (p == 1.0)
        return r;
    if (p == 2.0)
        return r * r;
    return pow(r, p);
}

/* F_d^ss with the + (neg 0) or - (neg 1) set, speed = |v| (numba _fd_set) */
static double ml_fd_set(double speed, double a, const double *th, int neg)
{
    double fa, as, vc, acc, vel;
    if (a == 0.0)
        return 0.0;
    if (neg) {
        fa = th[FAN];
        as = th[ASN];
        vc = th[VCN];
    } else {
        fa = th[FAP];
        as = th[ASP];
        vc = th[VCP];
    }
    acc = -expm1(-ml_pow(fabs(a) / as, th[BETA]));
    vel = exp(-ml_pow(speed / vc, th[GAM]));
    return a > 0.0 ? fa * acc * vel : -fa * acc * vel;
}

static double ml_fd_steady(double v, double a, const double *th)
{
    return ml_fd_set(fabs(v), a, th, v < 0.0);
}

static double ml_lag_input(double v, double a, const double *th, double form)
{
    return form == 0.0 ? ml_fd_steady(v, a, th) : a;
}

/* exact step of tau dq/dt + q = u for u linear from u0 to u1 over h (numba _lag_step) */
static double ml_lag_step(double q, double u0, double u1, double h, double tau)
{
    const double s = h / tau;
    const double e = exp(-s);
    const double phi = s > 1e-12 ? -expm1(-s) / s : 1.0 - 0.5 * s;
    return u1 + (q - u0) * e - (u1 - u0) * phi;
}

/* friction.modified_lugre.mlugre_run */
static void ml_kernel(int n, const double *t, const double *v, const double *a,
                      const double *load, const double *x, const double *th, int method,
                      const double *state0, double *F, double *S)
{
    const double s0 = th[S0], s1 = th[S1], b = th[B];
    const double is0 = 1.0 / s0;
    const double alpha = th[ALPHA], shape = th[SHAPE];
    const fl_side cp = fl_side_constants(th[FCP], th[FSP], th[VSP], s0);
    const fl_side cn = fl_side_constants(th[FCN], th[FSN], th[VSN], s0);
    const double s2p = th[S2P], s2n = th[S2N];
    const double v1 = th[V1], v2 = th[V2], gform = th[GFORM], form = th[FDFORM];
    const double tau = th[TAU];
    double z = state0[0], q = state0[1], u;
    double h_lag = -1.0, e_lag = 0.0, phi_lag = 0.0;
    int k;
    (void)load;
    (void)x;
    if (n <= 0)
        return;
    u = ml_lag_input(v[0], a[0], th, form);
    for (k = 0; k < n; ++k) {
        const double vk = v[k];
        double cg, s2, G, zd, Fd;
        if (vk >= 0.0) {
            fl_g_fast(vk, &cp, alpha, shape, s0, &cg);
            s2 = s2p;
        } else {
            fl_g_fast(vk, &cn, alpha, shape, s0, &cg);
            s2 = s2n;
        }
        G = ml_switch_gamma(vk, v1, v2, gform);
        zd = G * (vk - cg * fabs(vk) * z);
        if (tau == 0.0)
            q = u; /* static F_d: no memory */
        Fd = form == 0.0 ? q : ml_fd_steady(vk, q, th);
        F[k] = s0 * z + s1 * zd + s2 * vk + Fd + b;
        S[2 * k] = z;
        S[2 * k + 1] = q;
        if (k + 1 < n) {
            const double h = t[k + 1] - t[k];
            const double u1 = ml_lag_input(v[k + 1], a[k + 1], th, form);
            if (method == 1) {
                z = z + h * zd;
                if (tau > 0.0)
                    q = q + h * (u - q) / tau;
            } else {
                const double vm = 0.5 * (vk + v[k + 1]);
                double gm, cgm, zss, Gm;
                if (vm >= 0.0) {
                    gm = fl_g_fast(vm, &cp, alpha, shape, s0, &cgm);
                    zss = gm * is0;
                } else {
                    gm = fl_g_fast(vm, &cn, alpha, shape, s0, &cgm);
                    zss = -gm * is0;
                }
                Gm = ml_switch_gamma(vm, v1, v2, gform);
                z = z + (z - zss) * fl_em1(h * Gm * cgm * fabs(vm));
                if (tau > 0.0) {
                    const double vn = v[k + 1];
                    if (form == 0.0 && (vk < 0.0) != (vn < 0.0) && vk != vn) {
                        /* reversal inside the step: split it at v = 0 */
                        const double c = vk / (vk - vn);
                        const double ac = a[k] + c * (a[k + 1] - a[k]);
                        q = ml_lag_step(q, u, ml_fd_set(0.0, ac, th, vk < 0.0), c * h, tau);
                        q = ml_lag_step(q, ml_fd_set(0.0, ac, th, vn < 0.0), u1,
                                        (1.0 - c) * h, tau);
                    } else {
                        if (fabs(h - h_lag) > 1e-9 * h) { /* sampling jitter of t: reuse */
                            const double sl = h / tau;
                            e_lag = exp(-sl);
                            phi_lag = sl > 1e-12 ? -expm1(-sl) / sl : 1.0 - 0.5 * sl;
                            h_lag = h;
                        }
                        q = u1 + (q - u) * e_lag - (u1 - u) * phi_lag;
                    }
                }
            }
            u = u1;
        }
    }
}

/* ---- continuous time: the Python (numpy) ModifiedLuGre.derivatives / force ----------- */

/* gamma_switch (numpy form) */
static double ml_gamma_np(const double *th, double v)
{
    const double s = fabs(v), v1 = th[V1], v2 = th[V2];
    double r, kappa, arg, e;
    if (th[GFORM] == 1.0) {
        r = (s - v1) / (v2 - v1);
        r = r < 0.0 ? 0.0 : (r > 1.0 ? 1.0 : r);
        return 0.5 * (1.0 + cos(ML_PI * r));
    }
    kappa = 2.0 * ML_LN99 / (v2 - v1);
    arg = kappa * (s - 0.5 * (v1 + v2));
    e = exp(-fabs(arg));
    return arg > 0.0 ? e / (1.0 + e) : 1.0 / (1.0 + e);
}

/* fd_steady (numpy form) */
static double ml_fd_np(const double *th, double v, double a)
{
    const int neg = !(v >= 0.0);
    const double fa = neg ? th[FAN] : th[FAP];
    const double as = neg ? th[ASN] : th[ASP];
    const double vc = neg ? th[VCN] : th[VCP];
    const double sgn = a > 0.0 ? 1.0 : (a < 0.0 ? -1.0 : 0.0);
    const double acc = -expm1(-pow(fabs(a) / as, th[BETA]));
    const double vel = exp(-pow(fabs(v) / vc, th[GAM]));
    return fa * sgn * acc * vel;
}

static double ml_zdot(const double *th, double z, double v)
{
    const double g = v >= 0.0
        ? fl_stribeck_g_np(v, th[FCP], th[FSP], th[VSP], th[ALPHA], th[SHAPE])
        : fl_stribeck_g_np(v, th[FCN], th[FSN], th[VSN], th[ALPHA], th[SHAPE]);
    return ml_gamma_np(th, v) * (v - th[S0] * fabs(v) / g * z);
}

static void ml_derivatives(const double *th, const double *state, double v, double a,
                           double load, double x, double *dstate)
{
    double u;
    (void)load;
    (void)x;
    dstate[0] = ml_zdot(th, state[0], v);
    if (th[TAU] == 0.0) {
        dstate[1] = 0.0;
        return;
    }
    u = th[FDFORM] == 0.0 ? ml_fd_np(th, v, a) : a;
    dstate[1] = (u - state[1]) / th[TAU];
}

static double ml_force(const double *th, const double *state, double v, double a,
                       double load, double x)
{
    double Fd;
    (void)load;
    (void)x;
    if (th[TAU] == 0.0)
        Fd = ml_fd_np(th, v, a);
    else if (th[FDFORM] == 0.0)
        Fd = state[1];
    else
        Fd = ml_fd_np(th, v, state[1]);
    return th[S0] * state[0] + th[S1] * ml_zdot(th, state[0], v)
           + (v >= 0.0 ? th[S2P] : th[S2N]) * v + Fd + th[B];
}

const fl_law_def fl_law_modified_lugre = {
    "modified_lugre", P_N, TH_N, 2, FL_IN_A, ml_pack, ml_kernel, NULL, ml_derivatives,
    ml_force,
};
