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

/* the text of x with digits D (nd of them, no point) and decimal exponent ex, as Python's
 * repr(float): fixed notation with at least one decimal for -4 <= ex < 16, else
 * d.ddde+XX */
static inline void fl_fmt_digits(int neg, const char *D, int nd, int ex, char *buf, size_t n)
{
    char tmp[64];
    int i, k = 0;
    if (neg)
        tmp[k++] = '-';
    if (ex >= -4 && ex < 16) {
        if (ex < 0) {
            tmp[k++] = '0';
            tmp[k++] = '.';
            for (i = 0; i < -ex - 1; ++i)
                tmp[k++] = '0';
            for (i = 0; i < nd; ++i)
                tmp[k++] = D[i];
        } else {
            for (i = 0; i <= ex; ++i)
                tmp[k++] = i < nd ? D[i] : '0';
            tmp[k++] = '.';
            if (nd > ex + 1)
                for (i = ex + 1; i < nd; ++i)
                    tmp[k++] = D[i];
            else
                tmp[k++] = '0';
        }
        tmp[k] = '\0';
    } else {
        tmp[k++] = D[0];
        if (nd > 1) {
            tmp[k++] = '.';
            for (i = 1; i < nd; ++i)
                tmp[k++] = D[i];
        }
        snprintf(tmp + k, sizeof tmp - (size_t)k, "e%+03d", ex);
    }
    snprintf(buf, n, "%s", tmp);
}

/* shortest text that reads back as x, the digits Python's repr(float) chooses: at the
 * fewest digits that round-trip, the nearest such decimal (printf's rounding, or when that
 * misses at a power of two, its neighbour one unit in the last digit away) */
static inline void fl_fmt(double x, char *buf, size_t n)
{
    char s[40], D[24];
    int prec, nd, ex, neg, i, step;
    unsigned long long m, top;
    if (n == 0)
        return;
    if (isnan(x) || isinf(x)) {
        snprintf(buf, n, "%s", isnan(x) ? "nan" : (x > 0 ? "inf" : "-inf"));
        return;
    }
    for (prec = 0; prec < 17; ++prec) {
        snprintf(s, sizeof s, "%.*e", prec, x);
        neg = s[0] == '-';
        nd = 0;
        for (i = neg; s[i] != 'e'; ++i)
            if (s[i] != '.')
                D[nd++] = s[i];
        D[nd] = '\0';
        ex = atoi(s + i + 1);
        if (strtod(s, NULL) == x)
            break;
        /* the nearest decimal of prec + 1 digits misses x: try its neighbours */
        m = strtoull(D, NULL, 10);
        for (top = 1, i = 0; i < nd; ++i)
            top *= 10u;
        for (step = -1; step <= 1; step += 2) {
            unsigned long long mm = step > 0 ? m + 1u : m - 1u;
            int e2 = ex;
            char t[40];
            if (mm >= top) {
                mm /= 10u;
                e2 += 1;
            } else if (mm < top / 10u) {
                mm = mm * 10u + 9u;
                e2 -= 1;
            }
            snprintf(t, sizeof t, "%s%llue%d", neg ? "-0." : "0.", mm, e2 + 1);
            if (strtod(t, NULL) == x) {
                snprintf(D, sizeof D, "%llu", mm);
                ex = e2;
                goto found;
            }
        }
    }
found:
    nd = (int)strlen(D);
    while (nd > 1 && D[nd - 1] == '0') /* 100 = "1" at exponent 2 */
        D[--nd] = '\0';
    fl_fmt_digits(neg, D, nd, ex, buf, n);
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
