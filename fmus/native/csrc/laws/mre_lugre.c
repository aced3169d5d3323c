/* Improved LuGre model of an MRE base isolator (seed 002, Eqs. 1a/1b): the C twin of
 * friction/mre_lugre.py (its numba kernel mre_run, _pack, _check_relations, derivatives()
 * and force()).
 *
 *     F     = beta y + gain dy/dt + c0 v + k0 x + f0                          (1a)
 *     dy/dt = v - decay |v| y                                                 (1b)
 *
 * decay = alpha, gain = eps; swap_alpha_eps = 1 exchanges them. The force includes the
 * parallel spring and offset k0 x + f0 (the Python conservative_force), as the Python
 * kernel and force() do.
 */
#include <math.h>
#include <stdio.h>

#include "fl_law.h"

/* p[] (MRELuGreParams field order) == theta layout (friction.mre_lugre._LAYOUT) */
enum { BETA, ALPHA, C0, K0, EPS, F0, SWAP, N_THETA };

static int mre_pack(const double *p, double *theta, char *msg, size_t msglen)
{
    int i;
    if (!(p[SWAP] == 0.0 || p[SWAP] == 1.0)) {
        if (msg && msglen)
            snprintf(msg, msglen, "swap_alpha_eps must be a bool, got %g", p[SWAP]);
        return 1;
    }
    for (i = 0; i < N_THETA; ++i)
        theta[i] = p[i];
    return 0;
}

/* coefficient of |v| y in (1b) and of dy/dt in (1a) */
static void mre_roles(const double *th, double *decay, double *gain)
{
    if (th[SWAP] != 0.0) {
        *decay = th[EPS];
        *gain = th[ALPHA];
    } else {
        *decay = th[ALPHA];
        *gain = th[EPS];
    }
}

/* dy/dt = v - a y over h: exact exponential update (friction.lugre.bristle_update) */
static double mre_bristle_exact(double y, double v, double a, double h)
{
    double s = a * h, e;
    if (s < 1e-8)
        return y + h * (v - a * y);
    e = exp(-s);
    return y * e + v * (1.0 - e) / a;
}

static void mre_kernel(int n, const double *t, const double *v, const double *a,
                       const double *load, const double *x, const double *th, int method,
                       const double *state0, double *F, double *S)
{
    const double beta = th[BETA], c0 = th[C0], k0 = th[K0], f0 = th[F0];
    double decay, gain, y = state0[0];
    int k;
    (void)a;
    (void)load;
    mre_roles(th, &decay, &gain);
    for (k = 0; k < n; ++k) {
        const double vk = v[k], xk = x ? x[k] : 0.0;
        const double yd = vk - decay * fabs(vk) * y;
        F[k] = beta * y + gain * yd + c0 * vk + k0 * xk + f0;
        S[k] = y;
        if (k + 1 < n) {
            const double h = t[k + 1] - t[k];
            if (method == 1) {
                y = y + h * yd; /* Eq. (2d) */
            } else {
                const double vm = 0.5 * (vk + v[k + 1]);
                y = mre_bristle_exact(y, vm, decay * fabs(vm), h);
            }
        }
    }
}

static void mre_derivatives(const double *theta, const double *state, double v, double a,
                            double load, double x, double *dstate)
{
    double decay, gain;
    (void)a;
    (void)load;
    (void)x;
    mre_roles(theta, &decay, &gain);
    dstate[0] = v - decay * fabs(v) * state[0];
}

static double mre_force(const double *theta, const double *state, double v, double a,
                        double load, double x)
{
    double decay, gain, yd;
    (void)a;
    (void)load;
    mre_roles(theta, &decay, &gain);
    yd = v - decay * fabs(v) * state[0];
    return theta[BETA] * state[0] + gain * yd + theta[C0] * v + theta[K0] * x + theta[F0];
}

const fl_law_def fl_law_mre_lugre = {
    "mre_lugre", N_THETA, N_THETA, 1, FL_IN_X,
    mre_pack, mre_kernel, NULL, mre_derivatives, mre_force,
};
