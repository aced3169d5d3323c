/* The friction_effects block: friction.extensions.extension_force in C.
 *
 * e[] is the packed vector of friction.extensions.EXTENSION_PARAMS (the generator writes the
 * FL_E_* indices into fl_model.h from that one Python list): switches use_* (0 or 1), the
 * acceleration part (f_a, a_s, v_c, m_a and its level parts f_e, a_e, f_o), the position map
 * (x_lo, x_hi, c_x1.., the waviness lambda_x, p_c1, p_s1, p_c2, p_s2 and the local defect
 * d_x, x_d, w_d), the drift (k_drift, t0, T, k_sat, tau_sat, k_step, t_step, w_step, the
 * periodic part P_cyc, k_c1, k_s1, k_c2, k_s2 and the resetting part P_rst, t_rst, k_r1,
 * k_r2) and the load levels (L0, k_L). */
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

/* relative level change of the stroke map at x [m]: knots, waviness, local defect
 * (friction.extensions._position_m) */
static double fl_position_m(double x, const double *e)
{
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
    if (e[FL_E_LAMBDA_X] > 0.0) {  /* periodic waviness, two harmonics */
        double phi = 2.0 * 3.14159265358979323846 * (x - e[FL_E_X_LO]) / e[FL_E_LAMBDA_X];
        m += e[FL_E_P_C1] * cos(phi) + e[FL_E_P_S1] * sin(phi)
             + e[FL_E_P_C2] * cos(2.0 * phi) + e[FL_E_P_S2] * sin(2.0 * phi);
    }
    if (e[FL_E_W_D] > 0.0) {  /* local defect */
        double q = (x - e[FL_E_X_D]) / e[FL_E_W_D];
        m += e[FL_E_D_X] * exp(-0.5 * q * q);
    }
    return m;
}

/* relative level change of the drift at t [s]: trend, saturating change, step, periodic
 * part (friction.extensions._drift_m) */
static double fl_drift_m(double t, const double *e)
{
    double s = t - e[FL_E_T0];
    double d = e[FL_E_K_DRIFT] * s / e[FL_E_T];
    if (e[FL_E_K_SAT] != 0.0 && s > 0.0)
        d += e[FL_E_TAU_SAT] > 0.0 ? e[FL_E_K_SAT] * (1.0 - exp(-s / e[FL_E_TAU_SAT]))
                                   : e[FL_E_K_SAT];
    if (e[FL_E_K_STEP] != 0.0) {
        if (e[FL_E_W_STEP] > 0.0)
            d += e[FL_E_K_STEP] * 0.5 * (1.0 + tanh(0.5 * (t - e[FL_E_T_STEP]) / e[FL_E_W_STEP]));
        else if (t >= e[FL_E_T_STEP])
            d += e[FL_E_K_STEP];
    }
    if (e[FL_E_P_CYC] > 0.0) {  /* periodic part, two harmonics */
        double psi = 2.0 * 3.14159265358979323846 * s / e[FL_E_P_CYC];
        d += e[FL_E_K_C1] * cos(psi) + e[FL_E_K_S1] * sin(psi)
             + e[FL_E_K_C2] * cos(2.0 * psi) + e[FL_E_K_S2] * sin(2.0 * psi);
    }
    if (e[FL_E_P_RST] > 0.0) {  /* resetting part: builds up over each period from 0 */
        double u = (t - e[FL_E_T_RST]) / e[FL_E_P_RST];
        u -= floor(u);
        d += (e[FL_E_K_R1] + e[FL_E_K_R2] * u) * u;
    }
    return d;
}

/* velocity weight of the acceleration part at u = |v| / v_c and exponent m >= 0:
 * exp(-u) at m = 0, else (u / m)^m exp(m - u), 1 at u = m (friction.extensions._acc_weight) */
static double fl_acc_weight(double u, double m)
{
    if (m <= 0.0) return exp(-u);
    if (u <= 0.0) return 0.0;
    return exp(m * log(u / m) + m - u);
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
    if (e[FL_E_USE_DRIFT] > 0.5) F = F * (1.0 + fl_drift_m(t, e));
    if (e[FL_E_USE_POS] > 0.5) F = F * (1.0 + fl_position_m(x, e));
    if (e[FL_E_USE_ACC] > 0.5) {  /* level parts even and odd in a; grows with |a|, along |v| */
        double over = fabs(a) - e[FL_E_A_E];
        F = F * (1.0 + e[FL_E_F_E] * (over > 0.0 ? over : 0.0) + e[FL_E_F_O] * a);
        F = F + e[FL_E_F_A] * tanh(a / e[FL_E_A_S])
                * fl_acc_weight(fabs(v) / e[FL_E_V_C], e[FL_E_M_A]);
    }
    return F;
}

#endif
