/* Static Stribeck map (friction/stribeck.py), the same arithmetic as its numba kernel.
 *
 *   F(v) = g(v) sgn(v) + sigma2 v + b,   sgn(0) = 0
 *
 * No state: the kernel evaluates the map sample by sample.
 */
#include "fl_law.h"
#include "fl_stribeck.h"

/* p[]: the fields of friction.stribeck.StribeckParams in declaration order */
enum { P_S2, P_FC, P_FS, P_VS, P_ALPHA, P_B, P_FCN, P_FSN, P_VSN, P_S2N, P_SHAPE, P_N };
/* theta: friction.stribeck._LAYOUT */
enum { S2P, S2N, FCP, FCN, FSP, FSN, VSP, VSN, ALPHA, B, SHAPE, TH_N };

static int stribeck_pack(const double *p, double *th, char *msg, size_t msglen)
{
    if (fl_check_option("shape", p[P_SHAPE], fl_shape_names, 2, msg, msglen))
        return 1;
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

/* friction.stribeck.stribeck_run */
static void stribeck_kernel(int n, const double *t, const double *v, const double *a,
                            const double *load, const double *x, const double *th, int method,
                            const double *state0, double *F, double *S)
{
    const double alpha = th[ALPHA], shape = th[SHAPE], b = th[B];
    const fl_side cp = fl_side_constants(th[FCP], th[FSP], th[VSP], 1.0);
    const fl_side cn = fl_side_constants(th[FCN], th[FSN], th[VSN], 1.0);
    const double s2p = th[S2P], s2n = th[S2N];
    double cg;
    int k;
    (void)t;
    (void)a;
    (void)load;
    (void)x;
    (void)method;
    (void)state0;
    (void)S;
    for (k = 0; k < n; ++k) {
        const double vk = v[k];
        if (vk > 0.0)
            F[k] = fl_g_fast(vk, &cp, alpha, shape, 1.0, &cg) + s2p * vk + b;
        else if (vk < 0.0)
            F[k] = -fl_g_fast(vk, &cn, alpha, shape, 1.0, &cg) + s2n * vk + b;
        else
            F[k] = b; /* sgn(0) = 0 */
    }
}

/* friction.stribeck.stribeck_force (the map at one velocity; no state) */
static double stribeck_force(const double *th, const double *state, double v, double a,
                             double load, double x)
{
    (void)state;
    (void)a;
    (void)load;
    (void)x;
    if (v > 0.0)
        return fl_stribeck_g(v, th[FCP], th[FSP], th[VSP], th[ALPHA], th[SHAPE])
               + th[S2P] * v + th[B];
    if (v < 0.0)
        return -fl_stribeck_g(v, th[FCN], th[FSN], th[VSN], th[ALPHA], th[SHAPE])
               + th[S2N] * v + th[B];
    return th[B];
}

const fl_law_def fl_law_stribeck = {
    "stribeck", P_N, TH_N, 0, 0, stribeck_pack, stribeck_kernel, NULL, NULL, stribeck_force,
};
