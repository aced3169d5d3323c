/* Classic LuGre friction (friction/lugre.py), the same arithmetic as its numba kernel.
 *
 *   dz/dt = v - sigma0 |v| / g(v) z
 *   F     = sigma0 z + sigma1 dz/dt + sigma2 v + b
 *
 * method 0 (exact): z+ = z + (z - z_ss)(e^{-s} - 1), s = h sigma0 |v_m| / g(v_m),
 * z_ss = sgn(v_m) g(v_m) / sigma0, v_m the step's midpoint velocity; method 1: explicit Euler.
 */
#include "fl_law.h"
#include "fl_stribeck.h"

/* p[]: the fields of friction.lugre.LuGreParams in declaration order */
enum { P_S0, P_S1, P_S2, P_FC, P_FS, P_VS, P_ALPHA, P_B, P_FCN, P_FSN, P_VSN, P_S2N, P_SHAPE,
       P_N };
/* theta: friction.lugre._LAYOUT */
enum { S0, S1, S2P, S2N, FCP, FCN, FSP, FSN, VSP, VSN, ALPHA, B, SHAPE, TH_N };

static int lugre_pack(const double *p, double *th, char *msg, size_t msglen)
{
    if (fl_check_option("shape", p[P_SHAPE], fl_shape_names, 2, msg, msglen))
        return 1;
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
    return 0;
}

/* friction.lugre.lugre_run */
static void lugre_kernel(int n, const double *t, const double *v, const double *a,
                         const double *load, const double *x, const double *th, int method,
                         const double *state0, double *F, double *S)
{
    const double s0 = th[S0], s1 = th[S1], b = th[B];
    const double is0 = 1.0 / s0;
    const double alpha = th[ALPHA], shape = th[SHAPE];
    const fl_side cp = fl_side_constants(th[FCP], th[FSP], th[VSP], s0);
    const fl_side cn = fl_side_constants(th[FCN], th[FSN], th[VSN], s0);
    const double s2p = th[S2P], s2n = th[S2N];
    double z = state0[0];
    int k;
    (void)a;
    (void)load;
    (void)x;
    for (k = 0; k < n; ++k) {
        const double vk = v[k];
        double cg, s2, zd;
        if (vk >= 0.0) {
            fl_g_fast(vk, &cp, alpha, shape, s0, &cg);
            s2 = s2p;
        } else {
            fl_g_fast(vk, &cn, alpha, shape, s0, &cg);
            s2 = s2n;
        }
        zd = vk - cg * fabs(vk) * z;
        F[k] = s0 * z + s1 * zd + s2 * vk + b;
        S[k] = z;
        if (k + 1 < n) {
            const double h = t[k + 1] - t[k];
            if (method == 1) {
                z = z + h * zd;
            } else {
                const double vm = 0.5 * (vk + v[k + 1]);
                double gm, cgm, zss;
                if (vm >= 0.0) {
                    gm = fl_g_fast(vm, &cp, alpha, shape, s0, &cgm);
                    zss = gm * is0;
                } else {
                    gm = fl_g_fast(vm, &cn, alpha, shape, s0, &cgm);
                    zss = -gm * is0;
                }
                z = z + (z - zss) * fl_em1(h * cgm * fabs(vm));
            }
        }
    }
}

/* g(v) of the direction of v, as the Python DirectionalStribeck.g (numpy) */
static double lugre_g(const double *th, double v)
{
    if (v >= 0.0)
        return fl_stribeck_g_np(v, th[FCP], th[FSP], th[VSP], th[ALPHA], th[SHAPE]);
    return fl_stribeck_g_np(v, th[FCN], th[FSN], th[VSN], th[ALPHA], th[SHAPE]);
}

/* LuGre.derivatives */
static void lugre_derivatives(const double *th, const double *state, double v, double a,
                              double load, double x, double *dstate)
{
    (void)a;
    (void)load;
    (void)x;
    dstate[0] = v - th[S0] * fabs(v) / lugre_g(th, v) * state[0];
}

/* LuGre.force */
static double lugre_force(const double *th, const double *state, double v, double a,
                          double load, double x)
{
    double zd;
    lugre_derivatives(th, state, v, a, load, x, &zd);
    return th[S0] * state[0] + th[S1] * zd + (v >= 0.0 ? th[S2P] : th[S2N]) * v + th[B];
}

const fl_law_def fl_law_lugre = {
    "lugre", P_N, TH_N, 1, 0, lugre_pack, lugre_kernel, NULL, lugre_derivatives, lugre_force,
};
