/* The friction_effects block: friction.extensions.extension_force in C.
 *
 * e[] is the packed vector of friction.extensions.EXTENSION_PARAMS (the generator writes the
 * FL_E_* indices into fl_model.h from that one Python list): switches use_* (0 or 1), the
 * acceleration part (f_a, a_s, v_c), the position map (x_lo, x_hi, c_x1..), the drift
 * (k_drift, t0, T) and the load levels (L0, k_L). */
#ifndef FL_EFFECTS_H
#define FL_EFFECTS_H

#include <math.h>
#include <stdio.h>

/* relations the variables' own bounds cannot state; nonzero and a message if violated */
static int fl_effects_check(const double *e, char *msg, size_t n)
{
    if (e[FL_E_USE_POS] > 0.5 && !(e[FL_E_X_HI] > e[FL_E_X_LO])) {
        snprintf(msg, n, "x_hi = %.17g is out of bounds: must be > x_lo = %.17g [m]",
                 e[FL_E_X_HI], e[FL_E_X_LO]);
        return 1;
    }
    return 0;
}

/* law force F [N] with the switched-on extensions at v [m/s], a [m/s^2], x [m], load [N],
 * time t [s]: multiplicative (load, drift, position) then additive (acceleration) */
static double fl_extension_force(double F, double v, double a, double x, double load,
                                 double t, const double *e)
{
    if (e[FL_E_USE_LOAD] > 0.5) {  /* levels affine in the load, never of opposite sign */
        double r = 1.0 + e[FL_E_K_L] * (load - e[FL_E_L0]) / e[FL_E_L0];
        F = F * (r > 0.0 ? r : 0.0);
    }
    if (e[FL_E_USE_DRIFT] > 0.5) F = F * (1.0 + e[FL_E_K_DRIFT] * (t - e[FL_E_T0]) / e[FL_E_T]);
    if (e[FL_E_USE_POS] > 0.5) {  /* piecewise-linear map along the stroke */
        double span = e[FL_E_X_HI] - e[FL_E_X_LO], u, m, lo, w;
        int j;
        if (span < 1e-12) span = 1e-12;
        u = (x - e[FL_E_X_LO]) / span * (FL_E_NK - 1);
        if (u <= 0.0) {
            m = 0.0;
        } else if (u >= FL_E_NK - 1) {
            m = e[FL_E_C_X1 + FL_E_NK - 2];
        } else {
            j = (int)u;
            w = u - j;
            lo = j == 0 ? 0.0 : e[FL_E_C_X1 + j - 1];
            m = lo + w * (e[FL_E_C_X1 + j] - lo);
        }
        F = F * (1.0 + m);
    }
    if (e[FL_E_USE_ACC] > 0.5)  /* grows with |a|, fades with |v| */
        F = F + e[FL_E_F_A] * tanh(a / e[FL_E_A_S]) * exp(-fabs(v) / e[FL_E_V_C]);
    return F;
}

#endif
