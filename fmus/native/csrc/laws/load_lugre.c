/* Load-dependent LuGre friction of a giant forging press (seed 004): the C twin of
 * friction/load_lugre.py (its numba kernel load_lugre_run, _pack, _check_relations,
 * regimes(), derivatives() and force()).
 *
 *     dz/dt = v - sigma0 |v| / g(v) z
 *     F     = sigma0 z + sigma1 dz/dt + sigma2 v
 *     g(v)  = Fc + (Fs - Fc) exp(-(v/vs)^2)
 *     Fc = Fc0 + k1 load,  Fs = Fs0 + k2 load,  sigma2 = sigma20 + k3 load
 *
 * (k1, k2, k3) are the "low" set for |v| < vc and the "high" set otherwise. vc is the
 * parameter vc, or (NAN) the no-load critical velocity of Eq. (13).
 */
#include <float.h>
#include <math.h>
#include <stdio.h>

#include "fl_law.h"

/* p[] (LoadLuGreParams field order) == theta layout (friction.load_lugre._LAYOUT) */
enum { S0, S1, FC0, FS0, VS, S20, K1L, K2L, K3L, K1H, K2H, K3H, VC, N_THETA };

/* h(u) = 2 u D e^{-u^2} - vs of critical_velocity (u = v / vs, D = (Fs - Fc) / sigma2) */
static double ll_h(double u, double D, double vs)
{
    return 2.0 * u * D * exp(-u * u) - vs;
}

/* Root of ll_h in [a, b] with ll_h(a) >= 0 >= ll_h(b): Brent's method (inverse quadratic
 * interpolation / secant, falling back to bisection), run until the bracket is about one
 * ulp wide, so it returns the floating-point sign change of h (the point scipy's brentq
 * with xtol = 1e-15, rtol = 4 eps reaches within its tolerance). */
static double ll_root(double a, double b, double D, double vs)
{
    double fa = ll_h(a, D, vs), fb = ll_h(b, D, vs);
    double c, fc, d, e;
    int it;
    if (fa == 0.0)
        return a;
    if (fb == 0.0)
        return b;
    c = a;
    fc = fa;
    d = e = b - a;
    for (it = 0; it < 500; ++it) {
        double tol, m;
        if (fabs(fc) < fabs(fb)) { /* b: the best estimate, c: the other end of the bracket */
            a = b; fa = fb;
            b = c; fb = fc;
            c = a; fc = fa;
        }
        tol = DBL_EPSILON * fabs(b) + DBL_MIN;
        m = 0.5 * (c - b);
        if (fabs(m) <= tol || fb == 0.0)
            return b;
        if (fabs(e) < tol || fabs(fa) <= fabs(fb)) {
            d = e = m; /* bisection */
        } else {
            double p, q, s = fb / fa;
            if (a == c) { /* secant */
                p = 2.0 * m * s;
                q = 1.0 - s;
            } else { /* inverse quadratic interpolation */
                double r = fb / fc, t = fa / fc;
                p = s * (2.0 * m * t * (t - r) - (b - a) * (r - 1.0));
                q = (t - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if (p > 0.0)
                q = -q;
            else
                p = -p;
            if (2.0 * p < fmin(3.0 * m * q - fabs(tol * q), fabs(e * q))) {
                e = d;
                d = p / q;
            } else {
                d = e = m;
            }
        }
        a = b;
        fa = fb;
        b += fabs(d) > tol ? d : (m > 0.0 ? tol : -tol);
        fb = ll_h(b, D, vs);
        if ((fb > 0.0) == (fc > 0.0) && fb != 0.0 && fc != 0.0) {
            c = a; /* the sign change is between a and b again */
            fc = fa;
            d = e = b - a;
        }
    }
    return b;
}

/* Velocity of the minimum of the steady-state curve, Eq. (13) (critical_velocity):
 * NAN without interior minimum, INFINITY when sigma2 = 0 and Fs > Fc. *overflow is set
 * (and NAN returned) when h is NaN at the end of the bracket (2 u D overflows while
 * e^{-u^2} underflows: sigma2 below ~1e-300 (Fs - Fc) / vs), where the Python brentq raises
 * "the function value is NaN". */
static double ll_critical_velocity(double Fc, double Fs, double vs, double sigma2,
                                   int *overflow)
{
    double dF = Fs - Fc, D, lo, hi, fhi;
    *overflow = 0;
    if (!(dF > 0.0))
        return NAN;
    if (sigma2 == 0.0)
        return INFINITY;
    D = dF / sigma2;
    lo = 1.0 / sqrt(2.0);
    if (ll_h(lo, D, vs) < 0.0)
        return NAN;
    hi = 2.0 * lo;
    while ((fhi = ll_h(hi, D, vs)) > 0.0)
        hi *= 2.0;
    if (isnan(fhi) || isnan(ll_h(lo, D, vs))) {
        *overflow = 1;
        return NAN;
    }
    return vs * ll_root(lo, hi, D, vs);
}

static int ll_pack(const double *p, double *theta, char *msg, size_t msglen)
{
    int i, overflow = 0;
    double vc;
    for (i = 0; i < VC; ++i)
        theta[i] = p[i];
    vc = isnan(p[VC]) ? ll_critical_velocity(p[FC0], p[FS0], p[VS], p[S20], &overflow)
                      : p[VC];
    theta[VC] = vc;
    if (overflow) {
        if (msg && msglen)
            snprintf(msg, msglen,
                     "the no-load curve (Fc0 = %g, Fs0 = %g, vs = %g, sigma20 = %g) overflows "
                     "Eq. 13 (sigma20 too small for its critical velocity); give the "
                     "regime-split velocity vc explicitly", p[FC0], p[FS0], p[VS], p[S20]);
        return 1;
    }
    if (!(vc > 0.0) || isinf(vc)) {
        if (msg && msglen)
            snprintf(msg, msglen,
                     "the no-load curve (Fc0 = %g, Fs0 = %g, vs = %g, sigma20 = %g) has no "
                     "Stribeck minimum (Eq. 13 has no root); give the regime-split velocity "
                     "vc explicitly", p[FC0], p[FS0], p[VS], p[S20]);
        return 1;
    }
    return 0;
}

/* g(v) and sigma2 at velocity v and load (the coefficients of the regime of |v|) */
static double ll_loaded(double v, double load, const double *th, double *s2)
{
    double k1, k2, k3, fc, fs, r;
    if (fabs(v) < th[VC]) {
        k1 = th[K1L]; k2 = th[K2L]; k3 = th[K3L];
    } else {
        k1 = th[K1H]; k2 = th[K2H]; k3 = th[K3H];
    }
    fc = th[FC0] + k1 * load;
    fs = th[FS0] + k2 * load;
    r = v / th[VS];
    *s2 = th[S20] + k3 * load;
    return fc + (fs - fc) * exp(-r * r);
}

/* dz/dt = v - a z over h: exact exponential update (friction.lugre.bristle_update) */
static double ll_bristle_exact(double z, double v, double a, double h)
{
    double s = a * h, e;
    if (s < 1e-8)
        return z + h * (v - a * z);
    e = exp(-s);
    return z * e + v * (1.0 - e) / a;
}

static void ll_kernel(int n, const double *t, const double *v, const double *a,
                      const double *load, const double *x, const double *th, int method,
                      const double *state0, double *F, double *S)
{
    const double s0 = th[S0], s1 = th[S1];
    double z = state0[0];
    int k, j;
    (void)a;
    (void)x;
    if (!(th[VC] > 0.0)) { /* no regime split: inadmissible theta */
        for (k = 0; k < n; ++k)
            F[k] = S[k] = NAN;
        return;
    }
    for (k = 0; k < n; ++k) {
        const double vk = v[k], lk = load ? load[k] : 0.0;
        double s2, g = ll_loaded(vk, lk, th, &s2), zd;
        if (!(g > 0.0)) {
            for (j = k; j < n; ++j)
                F[j] = S[j] = NAN;
            return;
        }
        zd = vk - s0 * fabs(vk) / g * z;
        F[k] = s0 * z + s1 * zd + s2 * vk;
        S[k] = z;
        if (k + 1 < n) {
            const double h = t[k + 1] - t[k];
            if (method == 1) {
                z = z + h * zd;
            } else {
                const double vm = 0.5 * (vk + v[k + 1]);
                const double lm = load ? 0.5 * (load[k] + load[k + 1]) : 0.0;
                double s2m, gm = ll_loaded(vm, lm, th, &s2m);
                if (!(gm > 0.0))
                    gm = g;
                z = ll_bristle_exact(z, vm, s0 * fabs(vm) / gm, h);
            }
        }
    }
}

/* The law with the low coefficients everywhere, and with the high ones (regimes()) */
static int ll_regimes(const double *theta, double *vc, double *theta_low, double *theta_high)
{
    int i;
    const double c = theta[VC];
    if (!(c > 0.0) || isinf(c))
        return 1;
    for (i = 0; i < N_THETA; ++i)
        theta_low[i] = theta_high[i] = theta[i];
    theta_low[K1H] = theta[K1L];
    theta_low[K2H] = theta[K2L];
    theta_low[K3H] = theta[K3L];
    theta_high[K1L] = theta[K1H];
    theta_high[K2L] = theta[K2H];
    theta_high[K3L] = theta[K3H];
    *vc = c;
    return 0;
}

static void ll_derivatives(const double *theta, const double *state, double v, double a,
                           double load, double x, double *dstate)
{
    double s2, g = ll_loaded(v, load, theta, &s2);
    (void)a;
    (void)x;
    dstate[0] = v - theta[S0] * fabs(v) / g * state[0];
}

static double ll_force(const double *theta, const double *state, double v, double a,
                       double load, double x)
{
    double s2, g = ll_loaded(v, load, theta, &s2);
    double zd = v - theta[S0] * fabs(v) / g * state[0];
    (void)a;
    (void)x;
    return theta[S0] * state[0] + theta[S1] * zd + s2 * v;
}

const fl_law_def fl_law_load_lugre = {
    "load_lugre", N_THETA, N_THETA, 1, FL_IN_LOAD,
    ll_pack, ll_kernel, ll_regimes, ll_derivatives, ll_force,
};
