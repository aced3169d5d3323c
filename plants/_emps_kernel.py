"""Numba kernel of the EMPS axis and its 1 kHz position controller (fast path of
:mod:`plants.emps`).

One control period ``[t_k, t_k + Ts)``:

1. the controller samples the position ``qm(k)`` and computes the voltage
   ``u(k) = kv (kp (qg(k) - e_pos) - dqf(k)) + pulse_gain * pulse(k)``, saturated at
   ``+/- u_max``, with ``qf(k) = (qm(k) + qm(k-1)) / 2``, ``dqf(k) = (qf(k) - qf(k-1)) / Ts``
   and ``e_pos = qm(k)`` (``err_avg = 0``) or ``qf(k)`` (``err_avg = 1``); in open loop
   ``u(k)`` is the measured voltage instead;
2. the motor force ``gtau * u`` reaches the carriage ``delay`` seconds after the sample
   (``0 <= delay <= Ts``): ``u(k-1)`` acts over ``[t_k, t_k + delay)`` and ``u(k)`` over
   ``[t_k + delay, t_k + Ts)``; ``delay = Ts`` is the benchmark's one sample of delay;
3. the carriage ``M dv/dt = gtau u - F``, ``dq/dt = v`` advances in Heun substeps, the
   friction law's state with the law's own kernel (for LuGre the exact exponential bristle
   update) over two-sample records, as :class:`plants.base.FrictionStep` calls it.

The law enters through its numba ``_kernel(t, v, a, load, x, theta, method, state0)``, so
any law of :mod:`friction` (and :class:`diagnosis.effect_law.EffectLaw`, whose position map
reads ``x``) runs in the loop unchanged.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

__all__ = ["emps_loop", "PARS", "OUT_COLS", "INIT"]

#: layout of the packed parameter vector
PARS = ("M", "gtau", "kp", "kv", "Ts", "u_max", "delay", "pulse_gain", "err_avg", "closed")
#: layout of the initial-condition vector: position, velocity, the two previous measured
#: positions and the voltage applied before the first sample
INIT = ("q0", "v0", "q_m1", "q_m2", "u_m1")
#: columns of the output array (one row per control instant)
OUT_COLS = ("q", "v", "a", "F", "u")


@njit
def emps_loop(kern, theta, method, state0, pars, qg, u_in, pulse, init, nsub, out):
    """Run the axis over ``qg.size`` control periods; ``out[k]`` receives :data:`OUT_COLS`
    at the control instant ``k`` (``u`` is the voltage computed there, ``a`` the mean
    acceleration of the substep ending there). Returns the law's final state."""
    M, gtau, kp, kv, Ts = pars[0], pars[1], pars[2], pars[3], pars[4]
    u_max, delay, pgain = pars[5], pars[6], pars[7]
    err_avg, closed = pars[8] > 0.5, pars[9] > 0.5
    n = qg.size
    if out.shape[0] < n or pulse.size < n or (not closed and u_in.size < n):
        raise ValueError("emps_loop: out, pulse and u_in need qg.size rows")
    q, v = init[0], init[1]
    q_prev = init[2]
    qf_prev = 0.5 * (init[2] + init[3])
    u_prev = init[4]
    z = state0.copy()
    t1 = np.zeros(1)
    w1 = np.zeros(1)
    x1 = np.zeros(1)
    a1 = np.zeros(1)
    t2 = np.zeros(2)
    v2 = np.zeros(2)
    x2 = np.zeros(2)
    a2 = np.zeros(2)
    load0 = np.zeros(0)
    w1[0] = v
    x1[0] = q
    F1, _ = kern(t1, w1, a1, load0, x1, theta, method, z)
    F = F1[0]
    acc = 0.0
    for k in range(n):
        # -- the controller at the sample instant ------------------------------------
        qf = 0.5 * (q + q_prev)
        dqf = (qf - qf_prev) / Ts
        if closed:
            e = qg[k] - (qf if err_avg else q)
            u = kv * (kp * e - dqf) + pgain * pulse[k]
            if u > u_max:
                u = u_max
            elif u < -u_max:
                u = -u_max
        else:
            u = u_in[k]
        out[k, 0] = q
        out[k, 1] = v
        out[k, 2] = acc
        out[k, 3] = F
        out[k, 4] = u
        q_prev = q
        qf_prev = qf
        if k + 1 == n:
            break
        # -- the carriage over the period: u(k-1) until the delay, then u(k) ---------
        for seg in range(2):
            length = delay if seg == 0 else Ts - delay
            if length <= 1e-12 * Ts:
                continue
            Fm = gtau * (u_prev if seg == 0 else u)
            m = max(1, int(math.ceil(nsub * length / Ts - 1e-9)))
            h = length / m
            t2[1] = h
            for _ in range(m):
                k1 = (Fm - F) / M
                qp = q + h * v
                vp = v + h * k1
                v2[0] = v
                v2[1] = vp
                x2[0] = q
                x2[1] = qp
                a2[0] = k1
                a2[1] = k1
                Fp, _ = kern(t2, v2, a2, load0, x2, theta, method, z)
                k2 = (Fm - Fp[1]) / M
                vn = v + 0.5 * h * (k1 + k2)
                qn = q + 0.5 * h * (v + vp)
                acc = 0.5 * (k1 + k2)
                v2[1] = vn
                x2[1] = qn
                a2[0] = acc
                a2[1] = acc
                Fn, S = kern(t2, v2, a2, load0, x2, theta, method, z)
                for j in range(z.size):
                    z[j] = S[1, j]
                F = Fn[1]
                q = qn
                v = vn
        u_prev = u
    return z
