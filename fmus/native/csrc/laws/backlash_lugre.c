/* LuGre contact behind a backlash gap (friction/backlash.py), the same arithmetic as its
 * numba kernel.
 *
 * p = x_drive - x_contact in [-delta, delta] (play operator); u = delta - sgn(v) p the gap
 * left ahead of the drive, a stiff flank of width eps = 1e-3 delta:
 *   phi(u) = 1 (u <= 0), 1 - u / eps (0 < u < eps), 0 (u >= eps);  v_c = phi v
 *   dp/dt = v - v_c
 *   dz/dt = v_c - sigma0 |v_c| / g(v_c) z
 *   F     = sigma0 z + sigma1 dz/dt + sigma2 v_c + b
 *           (gap "free": phi(delta - |p|) (sigma0 z + sigma1 dz/dt + sigma2 v_c) + b)
 *         + (1 - phi(delta - |p|)) (gap_bias + gap_stiffness p + gap_drag sgn v)
 *           (what bridges the play, while the drive touches neither flank)
 *
 * method 0 (exact): the step is cut at a velocity reversal (fl_steps.h, delta > 0 only);
 * the play is advanced exactly in the drive's travel on each piece (the free gap closes at
 * the root of the travel's quadratic, the band as exp(-travel / eps)) and the bristle with
 * LuGre's exponential update over the rest of the piece at the contact's mean velocity;
 * method 1: explicit Euler, the play clipped to the gap.
 */
#include "fl_law.h"
#include "fl_steps.h"
#include "fl_stribeck.h"

/* p[]: the fields of friction.backlash.BacklashLuGreParams in declaration order */
enum { P_S0, P_S1, P_S2, P_FC, P_FS, P_VS, P_ALPHA, P_B, P_FCN, P_FSN, P_VSN, P_S2N, P_SHAPE,
       P_DELTA, P_GAP, P_GB, P_GK, P_GD, P_N };
/* theta: friction.backlash._LAYOUT */
enum { S0, S1, S2P, S2N, FCP, FCN, FSP, FSN, VSP, VSN, ALPHA, B, SHAPE, DELTA, GAP, GB, GK, GD,
       TH_N };

static const char *const bl_gap_names[] = {"hold", "free"};

/* friction.backlash.ENGAGE_BAND */
#define BL_BAND 1e-3

static int bl_pack(const double *p, double *th, char *msg, size_t msglen)
{
    if (fl_check_option("shape", p[P_SHAPE], fl_shape_names, 2, msg, msglen))
        return 1;
    if (fl_check_option("gap", p[P_GAP], bl_gap_names, 2, msg, msglen))
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
    th[DELTA] = p[P_DELTA];
    th[GAP] = p[P_GAP];
    th[GB] = p[P_GB];
    th[GK] = p[P_GK];
    th[GD] = p[P_GD];
    return 0;
}

/* friction.backlash._engage_time */
static double bl_engage_time(double r, double a, double b, double T)
{
    const double A = fabs(a);
    double disc = A * A + 2.0 * (fabs(b) - A) * r / T;
    if (disc < 0.0)
        disc = 0.0;
    return 2.0 * r / (A + sqrt(disc));
}

/* friction.backlash._band */
static double bl_band(double u, double eps)
{
    if (u <= 0.0)
        return 1.0;
    if (u >= eps)
        return 0.0;
    return 1.0 - u / eps;
}

/* friction.backlash._push */
static double bl_push(double v, double p, double delta, double eps)
{
    if (v > 0.0)
        return bl_band(delta - p, eps);
    if (v < 0.0)
        return bl_band(delta + p, eps);
    return 0.0;
}

/* friction.backlash._across */
static double bl_across(double v, double p, double delta, double eps, const double *th)
{
    const double w = 1.0 - bl_band(delta - fabs(p), eps);
    const double sv = v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0);
    if (w == 0.0)
        return 0.0;
    return w * (th[GB] + th[GK] * p + th[GD] * sv);
}

/* friction.backlash.backlash_run */
static void bl_kernel(int n, const double *t, const double *v, const double *a,
                      const double *load, const double *x, const double *th, int method,
                      const double *state0, double *F, double *S)
{
    const double delta = th[DELTA];
    const double eps = BL_BAND * delta;
    const int free_gap = th[GAP] == 1.0;
    const int across = th[GB] != 0.0 || th[GK] != 0.0 || th[GD] != 0.0;
    const double s0 = th[S0], s1 = th[S1], b = th[B];
    const double is0 = 1.0 / s0;
    const double alpha = th[ALPHA], shape = th[SHAPE];
    const fl_side cp = fl_side_constants(th[FCP], th[FSP], th[VSP], s0);
    const fl_side cn = fl_side_constants(th[FCN], th[FSN], th[VSN], s0);
    const double s2p = th[S2P], s2n = th[S2N];
    double z = state0[0], p = state0[1];
    int k;
    (void)a;
    (void)load;
    (void)x;
    if (p > delta)
        p = delta;
    else if (p < -delta)
        p = -delta;
    for (k = 0; k < n; ++k) {
        const double vk = v[k];
        const double ph = bl_push(vk, p, delta, eps);
        const double vc = ph == 1.0 ? vk : ph * vk;
        double cg, s2, zd;
        if (vc >= 0.0) {
            fl_g_fast(vc, &cp, alpha, shape, s0, &cg);
            s2 = s2p;
        } else {
            fl_g_fast(vc, &cn, alpha, shape, s0, &cg);
            s2 = s2n;
        }
        zd = vc - cg * fabs(vc) * z;
        if (free_gap) {
            const double touch = bl_band(delta - fabs(p), eps);
            if (touch == 1.0)
                F[k] = s0 * z + s1 * zd + s2 * vc + b;
            else if (touch == 0.0)
                F[k] = b;
            else
                F[k] = touch * (s0 * z + s1 * zd + s2 * vc) + b;
        } else {
            F[k] = s0 * z + s1 * zd + s2 * vc + b;
        }
        if (across)
            F[k] += bl_across(vk, p, delta, eps, th);
        S[2 * k] = z;
        S[2 * k + 1] = p;
        if (k + 1 < n) {
            const double h = t[k + 1] - t[k];
            double T[2], pa[2], pb[2];
            int piece;
            if (method == 1) {
                z = z + h * zd;
                p = p + h * (vk - vc);
                if (p > delta)
                    p = delta;
                else if (p < -delta)
                    p = -delta;
                continue;
            }
            if (delta > 0.0) {
                fl_split_step(vk, v[k + 1], h, T, pa, pb);
            } else { /* no gap: LuGre's update over the whole step, bit for bit */
                T[0] = h;
                pa[0] = vk;
                pb[0] = v[k + 1];
                T[1] = pa[1] = pb[1] = 0.0;
            }
            for (piece = 0; piece < 2; ++piece) {
                const double Tp = T[piece], va = pa[piece], vb = pb[piece];
                const double vp = 0.5 * (va + vb);
                double sg, D, u, tau, xi, u0, u1, Te, ve;
                if (Tp <= 0.0 || vp == 0.0)
                    continue;
                sg = vp > 0.0 ? 1.0 : -1.0;
                D = sg * vp * Tp;
                u = delta - sg * p;
                if (u > eps) {
                    if (D <= u - eps) {
                        p = p + vp * Tp;
                        continue;
                    }
                    tau = bl_engage_time(u - eps, va, vb, Tp);
                    xi = D - (u - eps);
                    u0 = eps;
                } else {
                    tau = 0.0;
                    xi = D;
                    u0 = u;
                }
                u1 = u0 > 0.0 ? u0 * exp(-xi / eps) : 0.0;
                p = sg * (delta - u1);
                Te = Tp - tau;
                if (u0 == 0.0)
                    ve = vp;
                else if (Te > 0.0)
                    ve = sg * (xi - (u0 - u1)) / Te;
                else
                    ve = 0.0;
                if (Te > 0.0 && ve != 0.0) {
                    double gm, cgm, zss;
                    if (ve >= 0.0) {
                        gm = fl_g_fast(ve, &cp, alpha, shape, s0, &cgm);
                        zss = gm * is0;
                    } else {
                        gm = fl_g_fast(ve, &cn, alpha, shape, s0, &cgm);
                        zss = -gm * is0;
                    }
                    z = z + (z - zss) * fl_em1(Te * cgm * fabs(ve));
                }
            }
        }
    }
}

/* g(v) of the direction of v (DirectionalStribeck.g, numpy) */
static double bl_g(const double *th, double v)
{
    if (v >= 0.0)
        return fl_stribeck_g_np(v, th[FCP], th[FSP], th[VSP], th[ALPHA], th[SHAPE]);
    return fl_stribeck_g_np(v, th[FCN], th[FSN], th[VSN], th[ALPHA], th[SHAPE]);
}

/* BacklashLuGre.contact_velocity */
static double bl_contact_velocity(const double *th, const double *state, double v)
{
    const double d = th[DELTA];
    const double ph = bl_push(v, state[1], d, BL_BAND * d);
    return ph == 1.0 ? v : ph * v;
}

/* BacklashLuGre.derivatives */
static void bl_derivatives(const double *th, const double *state, double v, double a,
                           double load, double x, double *dstate)
{
    const double vc = bl_contact_velocity(th, state, v);
    const double g = bl_g(th, vc);
    (void)a;
    (void)load;
    (void)x;
    dstate[0] = vc - th[S0] * fabs(vc) / g * state[0];
    dstate[1] = v - vc;
}

/* BacklashLuGre.force */
static double bl_force(const double *th, const double *state, double v, double a,
                       double load, double x)
{
    double d[2], vc, f, extra;
    vc = bl_contact_velocity(th, state, v);
    bl_derivatives(th, state, v, a, load, x, d);
    f = th[S0] * state[0] + th[S1] * d[0] + (vc >= 0.0 ? th[S2P] : th[S2N]) * vc;
    extra = bl_across(v, state[1], th[DELTA], BL_BAND * th[DELTA], th);
    if (th[GAP] == 1.0) {
        const double touch = bl_band(th[DELTA] - fabs(state[1]), BL_BAND * th[DELTA]);
        if (touch == 0.0)
            return th[B] + extra;
        if (touch != 1.0)
            return touch * f + th[B] + extra;
    }
    return f + th[B] + extra;
}

const fl_law_def fl_law_backlash_lugre = {
    "backlash_lugre", P_N, TH_N, 2, 0, bl_pack, bl_kernel, NULL, bl_derivatives, bl_force,
};
