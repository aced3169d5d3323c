/* frictionlab native FMUs: the EMPS axis and its position controller (plants/emps.py,
 * nonlinearbenchmark.org EMPS), included by fl_fmi2.c for FL_KIND_EMPS_AXIS and
 * FL_KIND_EMPS_CTRL. The parameter indices FL_EP_* come from the generated fl_model.h.
 *
 * Axis (FL_KIND_EMPS_AXIS), states x [m], v [m/s]:
 *     M dv/dt = gtau u_applied(t) - F_friction,   dx/dt = v
 * The drive samples its voltage input u [V] at the instants t_k = start + k Ts, at the
 * beginning of the step from t_k (the input's value at t_k). The voltage sampled at t_k acts
 * from t_k + delay; before that the one sampled at t_(k-1) (before the first sample: u0).
 * delay = Ts is the benchmark's one sample of delay. With the friction force held over the
 * communication step the acceleration is piecewise constant, so each piece is integrated
 * in closed form (exact; the Heun substeps of plants.stepper give the same to rounding).
 *
 * Controller (FL_KIND_EMPS_CTRL), sampled at t_k = start + k Ts:
 *     qf(k)  = (x(k) + x(k-1)) / 2,   dqf(k) = (qf(k) - qf(k-1)) / Ts
 *     u(k)   = kv (kp (qg(k) - e_pos) - dqf(k)) + pulse_gain pulse(k),  |u| <= u_max
 * with e_pos = x(k) (position_feedback = sample) or qf(k) (average). The sample at the start
 * time is taken with the inputs at the start (re-taken when the outputs are read after an
 * input changed, until the first step; the two earlier positions lie on the velocity v0
 * before the start; a first step without any read before takes it); a later sample
 * t_k is taken at the end of the step that reaches it, with the inputs set for that step
 * (under Gauss-Seidel after the axis: the axis position at t_k). Outputs u and
 * F_motor = gtau u hold the last sample.
 */
#ifndef FL_EMPS_H
#define FL_EMPS_H

#define EP(c, k) ((c)->d.val[(c)->vr_ep[k]])

/* discrete state d.ds[]: shared slots */
#define DS_KNEXT 0   /* index of the next sample instant */
#define DS_START 1   /* start time [s] */
/* axis */
#define DS_UPREV 2   /* voltage sampled at the previous instant [V] */
#define DS_UCUR 3    /* voltage sampled at the last instant [V] */
#define DS_TLATCH 4  /* time of the last sample [s] (-inf before the first) */
/* controller */
#define DS_XPREV 2   /* position at the last sample [m] */
#define DS_XFPREV 3  /* two-sample average at the last sample [m] */
#define DS_U 4       /* voltage of the last sample [V] */
#define DS_T0 5      /* the start sample is taken (1) */

static int emps_check(fl_inst *c)
{
    double Ts = EP(c, FL_EP_TS);
#ifdef FL_EP_DELAY
    double delay = EP(c, FL_EP_DELAY);
    if (delay > Ts * (1.0 + 1e-12)) {
        c->d.failed |= FAIL_PARAMS;
        snprintf(c->d.fail_msg, sizeof c->d.fail_msg, "%s: invalid parameters: delay = %.17g "
                 "is out of bounds: must be <= Ts = %.17g [s]", c->name, delay, Ts);
        return 0;
    }
#endif
    (void)Ts;
    c->d.failed &= ~FAIL_PARAMS;
    return 1;
}

static int build_model(fl_inst *c)
{
    return emps_check(c);
}

static double sample_time(const fl_inst *c, double k)
{
    return c->d.ds[DS_START] + k * EP(c, FL_EP_TS);
}

#if FL_KIND == FL_KIND_EMPS_AXIS
static void emps_initial(fl_inst *c)
{
    c->d.state[0] = EP(c, FL_EP_X0);
    c->d.state[1] = EP(c, FL_EP_V0);
    c->d.ds[DS_UPREV] = c->d.ds[DS_UCUR] = EP(c, FL_EP_U0);
    c->d.ds[DS_TLATCH] = -INFINITY;
    c->d.ds[DS_KNEXT] = 0.0;
}

/* voltage acting at time t (right after t at a switch) */
static double axis_applied(const fl_inst *c, double t)
{
    double tsw = c->d.ds[DS_TLATCH] + EP(c, FL_EP_DELAY);
    return t < tsw - 1e-9 * EP(c, FL_EP_TS) ? c->d.ds[DS_UPREV] : c->d.ds[DS_UCUR];
}

static void emps_outputs(fl_inst *c)
{
    double *v = c->d.val;
    v[c->vr_x] = c->d.state[0];
    v[c->vr_v] = c->d.state[1];
    v[c->vr_a] = (EP(c, FL_EP_GTAU) * axis_applied(c, c->d.time) - v[c->vr_ffric])
                 / EP(c, FL_EP_M);
}

static void emps_advance(fl_inst *c, double t, double h)
{
    double Ts = EP(c, FL_EP_TS), M = EP(c, FL_EP_M), gtau = EP(c, FL_EP_GTAU);
    double delay = EP(c, FL_EP_DELAY), F = c->d.val[c->vr_ffric];
    double tol = 1e-9 * Ts, tau = t, t_end = t + h, x = c->d.state[0], v = c->d.state[1];
    while (tau < t_end - tol) {
        double next = t_end, ts = sample_time(c, c->d.ds[DS_KNEXT]), tsw, acc, dt;
        if (ts <= tau + tol) {           /* a sample instant: the drive takes its input */
            c->d.ds[DS_UPREV] = c->d.ds[DS_UCUR];
            c->d.ds[DS_UCUR] = c->d.val[c->vr_uin];
            c->d.ds[DS_TLATCH] = ts;
            c->d.ds[DS_KNEXT] += 1.0;
            continue;
        }
        if (ts < next) next = ts;
        tsw = c->d.ds[DS_TLATCH] + delay;  /* the new voltage reaches the carriage */
        if (tsw > tau + tol && tsw < next - tol) next = tsw;
        acc = (gtau * (0.5 * (tau + next) < tsw ? c->d.ds[DS_UPREV] : c->d.ds[DS_UCUR]) - F) / M;
        dt = next - tau;
        x = x + v * dt + 0.5 * acc * dt * dt;
        v = v + acc * dt;
        tau = next;
    }
    c->d.state[0] = x;
    c->d.state[1] = v;
}
#endif /* FL_KIND_EMPS_AXIS */

#if FL_KIND == FL_KIND_EMPS_CTRL
static void emps_initial(fl_inst *c)
{
    c->d.ds[DS_KNEXT] = 0.0;
    c->d.ds[DS_U] = 0.0;
    c->d.stepped = 0;
}

/* one sample with the current inputs; the history in ds[] */
static void ctrl_sample(fl_inst *c)
{
    double *v = c->d.val, Ts = EP(c, FL_EP_TS), umax = EP(c, FL_EP_U_MAX);
    double x = v[c->vr_in[3]], xf = 0.5 * (x + c->d.ds[DS_XPREV]);
    double dxf = (xf - c->d.ds[DS_XFPREV]) / Ts;
    int average = EP(c, FL_EP_POSITION_FEEDBACK) == 2.0;
    double e = v[c->vr_qg] - (average ? xf : x);
    double u = EP(c, FL_EP_KV) * (EP(c, FL_EP_KP) * e - dxf);
    u += EP(c, FL_EP_PULSE_GAIN) * v[c->vr_pulse];
    if (u > umax) u = umax;
    else if (u < -umax) u = -umax;
    c->d.ds[DS_XPREV] = x;
    c->d.ds[DS_XFPREV] = xf;
    c->d.ds[DS_U] = u;
    c->d.ds[DS_KNEXT] += 1.0;
}

static void ctrl_publish(fl_inst *c)
{
    c->d.val[c->vr_uout] = c->d.ds[DS_U];
    c->d.val[c->vr_fmotor] = EP(c, FL_EP_GTAU) * c->d.ds[DS_U];
}

static void emps_outputs(fl_inst *c)
{
    if (!c->d.stepped) {  /* the start sample, from the inputs at the start */
        double x = c->d.val[c->vr_in[3]], Ts = EP(c, FL_EP_TS), v0 = EP(c, FL_EP_V0);
        double xm1 = x - v0 * Ts, xm2 = x - 2.0 * v0 * Ts;
        c->d.ds[DS_XPREV] = xm1;
        c->d.ds[DS_XFPREV] = 0.5 * (xm1 + xm2);
        c->d.ds[DS_KNEXT] = 0.0;
        ctrl_sample(c);
        c->d.ds[DS_T0] = 1.0;
    }
    ctrl_publish(c);
}

static void emps_advance(fl_inst *c, double t, double h)
{
    double tol = 1e-9 * EP(c, FL_EP_TS);
    /* the start sample stays as last read (under Gauss-Seidel the inputs set before the
     * first step are already those of its end); never read: taken now */
    if (!c->d.stepped && c->d.ds[DS_T0] == 0.0) emps_outputs(c);
    c->d.stepped = 1;
    while (sample_time(c, c->d.ds[DS_KNEXT]) <= t + h + tol) ctrl_sample(c);
}
#endif /* FL_KIND_EMPS_CTRL */

#endif
