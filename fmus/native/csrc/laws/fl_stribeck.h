/* frictionlab native FMUs: helpers shared by the LuGre-family laws (static inline, no state).
 *
 * The Stribeck curve g(v) of friction/shapes.py and the sample-loop helpers of
 * friction/lugre.py (_g_fast, _cutoff, _em1, side_constants), written with the same
 * arithmetic in the same order so that the C kernels equal the numba ones; plus the small
 * pieces every pack() needs (direction twins, option codes, messages).
 */
#ifndef FL_STRIBECK_H
#define FL_STRIBECK_H

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* shape codes of friction.shapes.SHAPES */
#define FL_SHAPE_GAUSSIAN 0
#define FL_SHAPE_LORENTZIAN 1

/* g(v) [N] for one sample (friction.shapes.stribeck_g, the numba version). */
static inline double fl_stribeck_g(double v, double Fc, double Fs, double vs, double alpha,
                                   double shape)
{
    double r = fabs(v) / vs, e;
    if (shape == 1.0)
        e = 1.0 / (1.0 + r * r);
    else if (alpha == 2.0)
        e = exp(-r * r);
    else
        e = exp(-pow(r, alpha));
    return Fc + (Fs - Fc) * e;
}

/* g(v) [N] as friction.shapes.stribeck_g_np (numpy; used by the Python continuous-time
 * derivatives/force): no alpha == 2 fast path. */
static inline double fl_stribeck_g_np(double v, double Fc, double Fs, double vs,
                                      double alpha, double shape)
{
    double r = fabs(v) / vs, e;
    if (shape == 1.0)
        e = 1.0 / (1.0 + r * r);
    else
        e = exp(-pow(r, alpha));
    return Fc + (Fs - Fc) * e;
}

/* x = |v/vs|^alpha beyond which (Fs - Fc) e^{-x} < Fc 2^-54: g rounds to Fc exactly
 * (friction.lugre._cutoff). */
static inline double fl_cutoff(double Fc, double Fs)
{
    double d = fabs(Fs - Fc);
    if (d == 0.0)
        return -1.0; /* no Stribeck bump: g = Fc at every speed */
    return 38.5 + log(d / Fc);
}

/* loop constants of one direction (friction.lugre.side_constants) */
typedef struct fl_side {
    double Fc, Fs, ivs, cut, s0_fc;
} fl_side;

static inline fl_side fl_side_constants(double Fc, double Fs, double vs, double s0)
{
    fl_side c;
    c.Fc = Fc;
    c.Fs = Fs;
    c.ivs = 1.0 / vs;
    c.cut = fl_cutoff(Fc, Fs);
    c.s0_fc = s0 / Fc;
    return c;
}

/* g(v) and *cg = sigma0 / g(v) (friction.lugre._g_fast) */
static inline double fl_g_fast(double v, const fl_side *c, double alpha, double shape,
                               double s0, double *cg)
{
    double r = fabs(v) * c->ivs, x, g;
    if (shape == 1.0) {
        g = c->Fc + (c->Fs - c->Fc) / (1.0 + r * r);
        *cg = s0 / g;
        return g;
    }
    x = alpha == 2.0 ? r * r : pow(r, alpha);
    if (x > c->cut) {
        *cg = c->s0_fc;
        return c->Fc;
    }
    g = c->Fc + (c->Fs - c->Fc) * exp(-x);
    *cg = s0 / g;
    return g;
}

/* e^{-s} - 1 for s >= 0 (friction.lugre._em1) */
static inline double fl_em1(double s)
{
    if (s > 40.0)
        return -1.0;
    if (s > 0.5)
        return exp(-s) - 1.0;
    return expm1(-s);
}

/* ---- pack() helpers ------------------------------------------------------------------ */

/* value of a direction twin: NAN (Python None) means "same as the + value" */
static inline double fl_twin(double neg, double pos)
{
    return isnan(neg) ? pos : neg;
}

/* shortest text that reads back as x, as Python's repr(float): fixed notation with at least
 * one decimal for 1e-4 <= |x| < 1e16, else d.ddde+XX */
static inline void fl_fmt(double x, char *buf, size_t n)
{
    int prec, ex, dec;
    size_t len;
    const char *e;
    if (n == 0)
        return;
    if (isnan(x)) {
        snprintf(buf, n, "nan");
        return;
    }
    if (isinf(x)) {
        snprintf(buf, n, x > 0 ? "inf" : "-inf");
        return;
    }
    for (prec = 0; prec < 17; ++prec) {
        snprintf(buf, n, "%.*e", prec, x);
        if (strtod(buf, NULL) == x)
            break;
    }
    e = strchr(buf, 'e');
    ex = e ? atoi(e + 1) : 0;
    if (ex < -4 || ex >= 16)
        return; /* exponent form, as printed */
    dec = prec - ex > 0 ? prec - ex : 0;
    snprintf(buf, n, "%.*f", dec, x);
    len = strlen(buf);
    if (dec == 0 && len + 2 < n) {
        buf[len] = '.';
        buf[len + 1] = '0';
        buf[len + 2] = '\0';
    }
}

/* an option field's code must be one of 0 .. nchoices-1; else a message naming it */
static inline int fl_check_option(const char *name, double code, const char *const *choices,
                                  int nchoices, char *msg, size_t msglen)
{
    char num[32];
    int i;
    size_t used;
    for (i = 0; i < nchoices; ++i)
        if (code == (double)i)
            return 0;
    if (msg == NULL || msglen == 0)
        return 1;
    fl_fmt(code, num, sizeof num);
    snprintf(msg, msglen, "%s = %s is not an option code: must be one of", name, num);
    for (i = 0; i < nchoices; ++i) {
        used = strlen(msg);
        if (used + 1 >= msglen)
            break;
        snprintf(msg + used, msglen - used, "%s %d (%s)", i ? "," : "", i, choices[i]);
    }
    return 1;
}

static const char *const fl_shape_names[] = {"gaussian", "lorentzian"};

#endif
