/* The per-step loop of fmus.master.Master (and the prescribed-motion drive of
 * identification.cosim.CoSimObjective) in C: the same FMI calls, in the same order, on the
 * same buffers as the Python loop of fmus/master.py, without a Python round trip per call.
 *
 * Built by fmus/master_loop.py with the system C compiler (cached); the FMU functions are
 * called through the pointers the Python side took from each FMU's library. Nothing here
 * computes anything the Python loop does not: gathered inputs are copied times their
 * connection's factor, external inputs (measured signals) come from a table, the communication
 * time is t0 + (k - 1) h in double precision, and the fixed-point pass, its "only changed"
 * test and its relative tolerance are those of Master._settle. A call answering fmi2Discard
 * or worse stops the loop; the caller raises FMUError from the recorded instance, call,
 * status and time.
 */
#include <math.h>
#include <stddef.h>

#if defined(_WIN32)
#define FLM_EXPORT __declspec(dllexport)
#else
#define FLM_EXPORT __attribute__((visibility("default")))
#endif

typedef int (*flm_set_fn)(void *, const unsigned int *, size_t, const double *);
typedef int (*flm_get_fn)(void *, const unsigned int *, size_t, double *);
typedef int (*flm_step_fn)(void *, double, double, int);

/* one FMU instance (mirrors fmus.master_loop._Inst) */
typedef struct {
    void *c;
    flm_set_fn set;
    flm_step_fn step;
    flm_get_fn get;
    const unsigned int *in_vr;
    size_t n_in;
    double *in_buf;
    const unsigned int *out_vr;
    size_t n_out;
    double *out_buf;
    int n_gather;
    const int *g_slot;        /* input slot of each gathered value */
    double *const *g_src;     /* address of the source output value */
    const double *g_fac;      /* factor of each connection (1.0: the value as it is) */
} flm_inst;

/* the whole run (mirrors fmus.master_loop._Plan) */
typedef struct {
    int n_inst;
    flm_inst *inst;           /* in stepping order */
    int jacobi;
    int iterations;           /* fixed-point passes per communication point (0: none) */
    double tolerance;
    int n_ft;
    const int *ft;            /* feedthrough instances (indices into inst), in order */
    int n_conn;
    double *const *conn_src;  /* every connection's source value */
    double *prev, *cur;       /* scratch, n_conn each */
    int n_rec;
    double *const *rec_src;   /* recorded values */
    int n_tab;                /* external inputs (measured signals) */
    double *const *tab_dst;   /* where each goes (an input slot of an instance) */
    const double *tab;        /* row k - 1 (n_tab values) is written before step k */
    double t0, h;
    /* the failed call: instance index, call (0 set, 1 doStep, 2 get), status, time */
    int err_inst, err_call, err_status;
    double err_time;
} flm_plan;

enum { CALL_SET = 0, CALL_STEP = 1, CALL_GET = 2 };

static int fail(flm_plan *p, int i, int call, int status, double t)
{
    p->err_inst = i;
    p->err_call = call;
    p->err_status = status;
    p->err_time = t;
    return 1;
}

static void gather(flm_inst *s)
{
    int g;
    for (g = 0; g < s->n_gather; g++) s->in_buf[s->g_slot[g]] = s->g_fac[g] * *s->g_src[g];
}

/* Master._gather_set(only_changed=True): 1 when an input changed (and was set) */
static int gather_changed(flm_inst *s)
{
    int g, same = 1;
    for (g = 0; g < s->n_gather; g++) {
        double value = s->g_fac[g] * *s->g_src[g];
        if (s->in_buf[s->g_slot[g]] != value) {
            s->in_buf[s->g_slot[g]] = value;
            same = 0;
        }
    }
    return !same;
}

/* Master._settle(t, passes); 0, or 1 on a failed call */
static int settle(flm_plan *p, double t, int passes)
{
    int it, j, q, check = passes > 1;
    if (p->n_ft == 0) return 0;
    if (check)
        for (q = 0; q < p->n_conn; q++) p->prev[q] = *p->conn_src[q];
    for (it = 1; it <= passes; it++) {
        int changed = 0;
        for (j = 0; j < p->n_ft; j++) {
            int i = p->ft[j], st;
            flm_inst *s = &p->inst[i];
            if (!gather_changed(s)) continue;
            if (s->n_in) {
                st = s->set(s->c, s->in_vr, s->n_in, s->in_buf);
                if (st > 1) return fail(p, i, CALL_SET, st, t);
            }
            if (s->n_out) {
                st = s->get(s->c, s->out_vr, s->n_out, s->out_buf);
                if (st > 1) return fail(p, i, CALL_GET, st, t);
            }
            changed = 1;
        }
        if (!changed) return 0;
        if (check && it < passes) {
            int converged = 1;
            for (q = 0; q < p->n_conn; q++) {
                double cur = *p->conn_src[q];
                p->cur[q] = cur;
                if (!(fabs(cur - p->prev[q]) <= p->tolerance * (1.0 + fabs(cur)))) converged = 0;
            }
            if (converged) return 0;
            for (q = 0; q < p->n_conn; q++) p->prev[q] = p->cur[q];
        }
    }
    return 0;
}

/* Communication steps k = k_from .. k_to (1-based, t = t0 + (k - 1) h); the recorded values
 * after step k go to rec[(k - k_from) * n_rec ...]. Returns 0, or 1 when a call failed
 * (err_* say which; the steps before it are complete and recorded). */
FLM_EXPORT int flm_run(flm_plan *p, long k_from, long k_to, double *rec)
{
    long k;
    int i, j, st;
    double h = p->h;
    for (k = k_from; k <= k_to; k++) {
        double t = p->t0 + (double)(k - 1) * h;
        for (j = 0; j < p->n_tab; j++) *p->tab_dst[j] = p->tab[(k - 1) * p->n_tab + j];
        if (!p->jacobi) {
            for (i = 0; i < p->n_inst; i++) {
                flm_inst *s = &p->inst[i];
                if (s->n_in) {
                    gather(s);
                    st = s->set(s->c, s->in_vr, s->n_in, s->in_buf);
                    if (st > 1) return fail(p, i, CALL_SET, st, t);
                }
                st = s->step(s->c, t, h, 1);
                if (st > 1) return fail(p, i, CALL_STEP, st, t);
                if (s->n_out) {
                    st = s->get(s->c, s->out_vr, s->n_out, s->out_buf);
                    if (st > 1) return fail(p, i, CALL_GET, st, t + h);
                }
            }
        } else {
            for (i = 0; i < p->n_inst; i++) {
                flm_inst *s = &p->inst[i];
                gather(s);
                if (s->n_in) {
                    st = s->set(s->c, s->in_vr, s->n_in, s->in_buf);
                    if (st > 1) return fail(p, i, CALL_SET, st, t);
                }
            }
            for (i = 0; i < p->n_inst; i++) {
                flm_inst *s = &p->inst[i];
                st = s->step(s->c, t, h, 1);
                if (st > 1) return fail(p, i, CALL_STEP, st, t);
            }
            for (i = 0; i < p->n_inst; i++) {
                flm_inst *s = &p->inst[i];
                if (s->n_out) {
                    st = s->get(s->c, s->out_vr, s->n_out, s->out_buf);
                    if (st > 1) return fail(p, i, CALL_GET, st, t + h);
                }
            }
        }
        if (p->iterations && settle(p, t + h, p->iterations)) return 1;
        for (j = 0; j < p->n_rec; j++) rec[(k - k_from) * p->n_rec + j] = *p->rec_src[j];
    }
    return 0;
}

/* identification.cosim.CoSimObjective: at each sample k the inputs U[k] are set and F read;
 * then, before the next sample, the step [t_k, t_k+1] is taken with the midpoint inputs
 * Um[k] held. Returns -1 when done, else the sample whose call failed (err_* say which). */
FLM_EXPORT long flm_prescribed(flm_plan *p, long n, const double *t, const double *U,
                               const double *Um, double *F)
{
    flm_inst *s = &p->inst[0];
    size_t j, n_in = s->n_in;
    long k;
    int st;
    for (k = 0; k < n; k++) {
        for (j = 0; j < n_in; j++) s->in_buf[j] = U[k * (long)n_in + (long)j];
        st = s->set(s->c, s->in_vr, n_in, s->in_buf);
        if (st > 1) { fail(p, 0, CALL_SET, st, t[k]); return k; }
        st = s->get(s->c, s->out_vr, 1, s->out_buf);
        if (st > 1) { fail(p, 0, CALL_GET, st, t[k]); return k; }
        F[k] = s->out_buf[0];
        if (k + 1 < n) {
            for (j = 0; j < n_in; j++) s->in_buf[j] = Um[k * (long)n_in + (long)j];
            st = s->set(s->c, s->in_vr, n_in, s->in_buf);
            if (st > 1) { fail(p, 0, CALL_SET, st, t[k]); return k; }
            st = s->step(s->c, t[k], t[k + 1] - t[k], 1);
            if (st > 1) { fail(p, 0, CALL_STEP, st, t[k]); return k; }
        }
    }
    return -1;
}
