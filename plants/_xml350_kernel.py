"""Numba kernel of the XML-350 closed loop for the classic LuGre law (fast path of
:meth:`plants.xml350.XML350.simulate` on long runs).

It is the same hybrid scheme as :class:`plants.stepper.PlantStepper` with the XML-350's
discrete part inlined: at each control instant the SD-PID (Eq. 15) and the LuGre
feedforward (Eq. 16) run on the sampled encoder position, then the stage (mass, 400 Hz
current loop, friction) advances over the control period in ``nsub`` Heun substeps with the
friction state on LuGre's exact exponential update (``friction.lugre.lugre_run`` over
two-sample records, exactly as ``FrictionStep`` calls the law's kernel). Only classic
LuGre laws are inlined; other laws run on the Python stepper.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from friction.lugre import lugre_run

__all__ = ["xml350_loop", "PARS", "REF_COLS", "OUT_COLS"]

#: layout of the packed parameter vector
PARS = ("M", "Kf", "wc", "res", "Ts", "M_ctrl", "Kp", "Ki", "Kd", "alpha_p", "alpha_i",
        "alpha_d", "beta", "open_loop", "i_max", "use_ff")
#: columns of the reference array (one row per control instant)
REF_COLS = ("x_d", "v_d", "a_d", "x_f", "x_ff", "v_ff", "a_ff")
#: columns of the output array
OUT_COLS = ("x", "v", "a", "x_meas", "x_d", "v_d", "a_d", "e", "i", "u", "u_ff", "F")


@njit(cache=True)
def _deriv(x, v, i, F, i_cmd, M, Kf, wc, i_max, out):
    ic = min(max(i_cmd, -i_max), i_max)
    out[0] = v
    out[1] = (Kf * i - F) / M
    out[2] = wc * (ic - i)


@njit(cache=True)
def xml350_loop(times, ref, theta, theta_ff, pars, nsub, s0, out):
    """Run the loop; ``times`` are the control instants, ``ref`` (N, 7) the sampled
    reference (:data:`REF_COLS`), ``s0`` the initial (x, v, i), ``out`` (N, 12) receives
    :data:`OUT_COLS`."""
    M, Kf, wc, res, Ts = pars[0], pars[1], pars[2], pars[3], pars[4]
    M_ctrl, Kp, Ki, Kd = pars[5], pars[6], pars[7], pars[8]
    ap, ai, ad, beta = pars[9], pars[10], pars[11], pars[12]
    open_loop, i_max, use_ff = pars[13] > 0, pars[14], pars[15] > 0
    n = times.size
    t1 = np.zeros(1)
    v1 = np.zeros(1)
    F1 = np.zeros(1)
    Z1 = np.zeros(1)
    t2 = np.zeros(2)
    v2 = np.zeros(2)
    F2 = np.zeros(2)
    Z2 = np.zeros(2)
    k1 = np.zeros(3)
    k2 = np.zeros(3)
    # continuous states, friction state, discrete states
    x, v, i = s0[0], s0[1], s0[2]
    z = 0.0
    integral, e_prev, pid_started = 0.0, 0.0, False
    z_ff, v_ff_prev, ff_started = 0.0, 0.0, False
    v1[0] = v
    lugre_run(t1, v1, theta, 0, z, F1, Z1)   # force at the start, state z = 0
    F = F1[0]
    a_held = 0.0
    for k in range(n):
        # -- discrete part at the control instant -------------------------------------
        x_d, v_d, a_d, x_f = ref[k, 0], ref[k, 1], ref[k, 2], ref[k, 3]
        v_ffk, a_ffk = ref[k, 5], ref[k, 6]
        if res > 0:
            x_meas = round(x / res) * res
        else:
            x_meas = x
        u_ff = 0.0
        if use_ff:
            if ff_started:
                t2[1] = Ts
                v2[0] = v_ff_prev
                v2[1] = v_ffk
                lugre_run(t2, v2, theta_ff, 0, z_ff, F2, Z2)
                z_ff = Z2[1]
                F_ff = F2[1]
            else:
                v1[0] = v_ffk
                lugre_run(t1, v1, theta_ff, 0, z_ff, F1, Z1)
                F_ff = F1[0]
            v_ff_prev = v_ffk
            ff_started = True
            u_ff = F_ff / M_ctrl
        if open_loop:
            u_sd = a_ffk
        else:
            e = x_d - x_meas
            integral = integral + Ts * e
            if pid_started:
                de = (e - e_prev) / Ts
            else:
                de = v_d
            w = beta / (abs(x_f - x_meas) + beta)
            kp = (1 + ap * w) * Kp
            ki = (1 + ai * w) * Ki
            kd = (1 + ad * w) * Kd
            u_sd = ki * integral + kp * e + kd * de + 1.0 * a_ffk
            e_prev = e
            pid_started = True
        u = u_sd + u_ff
        i_cmd = M_ctrl * u / Kf
        out[k, 0] = x
        out[k, 1] = v
        out[k, 2] = (Kf * i - F) / M
        out[k, 3] = x_meas
        out[k, 4] = x_d
        out[k, 5] = v_d
        out[k, 6] = a_d
        out[k, 7] = x_d - x
        out[k, 8] = i
        out[k, 9] = u
        out[k, 10] = u_ff
        out[k, 11] = F
        if k + 1 == n:
            break
        # -- continuous part over the control period -------------------------------------
        h = (times[k + 1] - times[k]) / nsub
        t2[1] = h
        for _ in range(nsub):
            _deriv(x, v, i, F, i_cmd, M, Kf, wc, i_max, k1)
            xp = x + h * k1[0]
            vp = v + h * k1[1]
            ip = i + h * k1[2]
            v2[0] = v
            v2[1] = vp
            lugre_run(t2, v2, theta, 0, z, F2, Z2)
            _deriv(xp, vp, ip, F2[1], i_cmd, M, Kf, wc, i_max, k2)
            hh = 0.5 * h
            x = x + hh * (k1[0] + k2[0])
            vn = v + hh * (k1[1] + k2[1])
            i = i + hh * (k1[2] + k2[2])
            v2[1] = vn
            lugre_run(t2, v2, theta, 0, z, F2, Z2)
            z = Z2[1]
            F = F2[1]
            v = vn
            a_held = 0.5 * (k1[1] + k2[1])
    return a_held
