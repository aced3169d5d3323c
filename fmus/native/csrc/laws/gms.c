/* Generalized Maxwell-slip friction (friction/gms.py), the same arithmetic as its numba
 * kernel.
 *
 * Four slip-blocks, stiffness k_i (geometric, sum sigma0, ratio `spread` stiffest/softest),
 * each carrying its share w_i of the Stribeck curve g(v) (geometric, sum 1, ratio `tilt`
 * softest/stiffest): break-away deflection d_i = w_i g / k_i. With s = sgn(v), u_i = s z_i and lam = C / g:
 *
 *   du_i/dt = min(|v|, lam (d_i - u_i))      (stick: move with the body; slip: attraction)
 *   du_i/dt = |v| (1 - u_i / d_i)            (element "bristle": a LuGre bristle, C unused)
 *   F       = sum_i (k_i z_i + sigma1 dw_i dz_i/dt) + sigma2 v + b,   dw_i = k_i / sigma0
 *
 * element "beside": the contact's LuGre bristle (k_1 = sigma0, share 1 - `share`, dw_1 = 1)
 * and three slip-blocks beside it (stiffness geometric summing to sigma_b, ratio `spread`;
 * shares geometric summing to `share`, ratio `tilt`; dw = 0).
 *
 * method 0 (exact): the step is cut at a velocity reversal (fl_steps.h); over each piece the
 * velocity is frozen at its midpoint value and each block's equation solved exactly;
 * method 1: explicit Euler.
 */
#include "fl_law.h"
#include "fl_steps.h"
#include "fl_stribeck.h"

#define GMS_N 4

/* p[] and theta: the fields of friction.gms.GMSParams in declaration order
 * (= friction.gms._LAYOUT) */
enum { S0, SPREAD, CA, S2, FC, FS, VS, ALPHA, B, SHAPE, S1, TILT, ELEM, SHARE, SB, TH_N };

/* friction.gms.ELEMENTS */
static const char *const gms_element_names[] = {"slip", "bristle", "beside"};

static int gms_pack(const double *p, double *th, char *msg, size_t msglen)
{
    int i;
    if (fl_check_option("shape", p[SHAPE], fl_shape_names, 2, msg, msglen))
        return 1;
    if (fl_check_option("element", p[ELEM], gms_element_names, 3, msg, msglen))
        return 1;
    for (i = 0; i < TH_N; ++i)
        th[i] = p[i];
    return 0;
}

/* friction.gms.element_stiffness */
static void gms_stiffness(double sigma0, double spread, double k[GMS_N])
{
    const double r = pow(spread, -1.0 / 3.0);
    const double c1 = r, c2 = r * r, c3 = c2 * r;
    const double tot = 1.0 + c1 + c2 + c3;
    k[0] = sigma0 / tot;
    k[1] = sigma0 * c1 / tot;
    k[2] = sigma0 * c2 / tot;
    k[3] = sigma0 * c3 / tot;
}

/* friction.gms.element_shares */
static void gms_shares(double tilt, double w[GMS_N])
{
    const double r = pow(tilt, 1.0 / 3.0);
    const double tot = 1.0 + r + r * r + r * r * r;
    w[0] = 1.0 / tot;
    w[1] = r / tot;
    w[2] = r * r / tot;
    w[3] = r * r * r / tot;
}

/* friction.gms.element_layout: stiffnesses k, shares w, damping weights dw */
static void gms_layout(const double *th, double k[GMS_N], double w[GMS_N], double dw[GMS_N])
{
    int i;
    if (th[ELEM] == 2.0) { /* friction.gms.beside_layout */
        const double r = pow(th[SPREAD], -0.5), q = pow(th[TILT], 0.5);
        const double kt = 1.0 + r + r * r, wt = 1.0 + q + q * q;
        double rk = 1.0, qk = 1.0;
        k[0] = th[S0];
        w[0] = 1.0 - th[SHARE];
        dw[0] = 1.0;
        for (i = 1; i < GMS_N; ++i) {
            k[i] = th[SB] * rk / kt;
            w[i] = th[SHARE] * qk / wt;
            dw[i] = 0.0;
            rk *= r;
            qk *= q;
        }
        return;
    }
    {
        double tot = 0.0;
        gms_stiffness(th[S0], th[SPREAD], k);
        gms_shares(th[TILT], w);
        for (i = 0; i < GMS_N; ++i)
            tot += k[i];
        for (i = 0; i < GMS_N; ++i)
            dw[i] = k[i] / tot;
    }
}

/* friction.gms.is_bristle */
static int gms_is_bristle(double elem, int i)
{
    return elem == 1.0 || (elem == 2.0 && i == 0);
}

/* friction.gms._block_piece */
static double gms_block_piece(double z, double vp, double T, double d, double lam,
                              int bristle)
{
    double s, u, sp, ustar;
    if (vp > 0.0)
        s = 1.0;
    else if (vp < 0.0)
        s = -1.0;
    else
        return z;
    u = s * z;
    if (bristle)
        return s * (u + (u - d) * fl_em1(fabs(vp) * T / d));
    sp = s * vp;
    ustar = d - sp / lam;
    if (u < ustar) {
        const double u1 = u + sp * T;
        if (u1 <= ustar) {
            u = u1;
        } else {
            const double tau = (ustar - u) / sp;
            u = d - (sp / lam) * exp(-lam * (T - tau));
        }
    } else {
        u = u + (u - d) * fl_em1(lam * T);
    }
    return s * u;
}

/* friction.gms._block_rate */
static double gms_block_rate(double z, double v, double d, double lam, int bristle)
{
    double r;
    if (bristle)
        return v - fabs(v) * z / d;
    if (v > 0.0) {
        r = lam * (d - z);
        return v < r ? v : r;
    }
    if (v < 0.0) {
        r = lam * (d + z);
        return -v < r ? v : -r;
    }
    return 0.0;
}

/* friction.gms._damping_rate: sum_i dw_i dz_i/dt, the rate sigma1 multiplies */
static double gms_damping_rate(const double *th, const double z[GMS_N], double v,
                               const double k[GMS_N], const double w[GMS_N],
                               const double dw[GMS_N])
{
    double g, lam, r = 0.0;
    int i;
    if (v == 0.0)
        return 0.0;
    g = fl_stribeck_g(v, th[FC], th[FS], th[VS], th[ALPHA], th[SHAPE]);
    lam = th[CA] / g;
    for (i = 0; i < GMS_N; ++i)
        if (dw[i] != 0.0)
            r += dw[i] * gms_block_rate(z[i], v, g * (w[i] / k[i]), lam,
                                        gms_is_bristle(th[ELEM], i));
    return r;
}

/* friction.gms.gms_run */
static void gms_kernel(int n, const double *t, const double *v, const double *a,
                       const double *load, const double *x, const double *th, int method,
                       const double *state0, double *F, double *S)
{
    double k[GMS_N], w[GMS_N], dw[GMS_N], wk[GMS_N], z[GMS_N];
    const double C = th[CA], s2 = th[S2], b = th[B];
    const double fc = th[FC], fs = th[FS], vs = th[VS], alpha = th[ALPHA], shape = th[SHAPE];
    int i, j;
    (void)a;
    (void)load;
    (void)x;
    gms_layout(th, k, w, dw);
    for (i = 0; i < GMS_N; ++i) {
        wk[i] = w[i] / k[i];
        z[i] = state0[i];
    }
    for (j = 0; j < n; ++j) {
        const double vj = v[j];
        double f = 0.0;
        for (i = 0; i < GMS_N; ++i) {
            f += k[i] * z[i];
            S[j * GMS_N + i] = z[i];
        }
        if (th[S1] != 0.0)
            f += th[S1] * gms_damping_rate(th, z, vj, k, w, dw);
        F[j] = f + s2 * vj + b;
        if (j + 1 < n) {
            const double h = t[j + 1] - t[j];
            if (method == 1) {
                const double g = fl_stribeck_g(vj, fc, fs, vs, alpha, shape);
                const double lam = C / g;
                for (i = 0; i < GMS_N; ++i)
                    z[i] = z[i] + h * gms_block_rate(z[i], vj, g * wk[i], lam,
                                                     gms_is_bristle(th[ELEM], i));
            } else {
                double T[2], pa[2], pb[2];
                int piece;
                fl_split_step(vj, v[j + 1], h, T, pa, pb);
                for (piece = 0; piece < 2; ++piece) {
                    const double vp = 0.5 * (pa[piece] + pb[piece]);
                    double g, lam;
                    if (T[piece] <= 0.0 || vp == 0.0)
                        continue;
                    g = fl_stribeck_g(vp, fc, fs, vs, alpha, shape);
                    lam = C / g;
                    for (i = 0; i < GMS_N; ++i)
                        z[i] = gms_block_piece(z[i], vp, T[piece], g * wk[i], lam,
                                               gms_is_bristle(th[ELEM], i));
                }
            }
        }
    }
}

/* GMS.derivatives */
static void gms_derivatives(const double *th, const double *state, double v, double a,
                            double load, double x, double *dstate)
{
    double k[GMS_N], w[GMS_N], dw[GMS_N];
    const double g = fl_stribeck_g_np(v, th[FC], th[FS], th[VS], th[ALPHA], th[SHAPE]);
    const double lam = th[CA] / g;
    int i;
    (void)a;
    (void)load;
    (void)x;
    gms_layout(th, k, w, dw);
    for (i = 0; i < GMS_N; ++i)
        dstate[i] = gms_block_rate(state[i], v, g * (w[i] / k[i]), lam,
                                   gms_is_bristle(th[ELEM], i));
}

/* GMS.force */
static double gms_force(const double *th, const double *state, double v, double a,
                        double load, double x)
{
    double k[GMS_N], w[GMS_N], dw[GMS_N], f = 0.0;
    int i;
    (void)a;
    (void)load;
    (void)x;
    gms_layout(th, k, w, dw);
    for (i = 0; i < GMS_N; ++i)
        f += k[i] * state[i];
    if (th[S1] != 0.0)
        f += th[S1] * gms_damping_rate(th, state, v, k, w, dw);
    return f + th[S2] * v + th[B];
}

const fl_law_def fl_law_gms = {
    "gms", TH_N, TH_N, GMS_N, 0, gms_pack, gms_kernel, NULL, gms_derivatives, gms_force,
};
