/* frictionlab native FMUs: the interface every friction law's C source fills in.
 *
 * One law = one file laws/<name>.c defining `const fl_law_def fl_law_<name>`. The equations
 * are the same as the numba kernels of the Python package `friction` (friction/<name>.py);
 * tests prove them equal to 1e-10 relative. Plain C99 and libm only: the FMU needs nothing
 * else at run time.
 *
 * Parameter vector p[] (n_params entries): the fields of the law's Python parameter
 * dataclass in declaration order; a numeric field is its value, an unset optional field
 * (Python None, e.g. a direction twin) is NAN, a Boolean is 0 or 1, an option (a String
 * field such as `shape`) is the integer code of its choice (Params.OPTIONS[name]). Every
 * numeric field has passed its own bound check before pack() is called.
 */
#ifndef FL_LAW_H
#define FL_LAW_H

#include <stddef.h>

/* bit mask of the inputs a law takes besides the velocity v */
#define FL_IN_A 1
#define FL_IN_LOAD 2
#define FL_IN_X 4

/* p -> packed theta (the layout of the Python law's theta_layout). Checks the relations
 * between parameters (the Python _check_relations); on failure returns nonzero and writes a
 * one-line message naming the parameter and its bound into msg. */
typedef int (*fl_pack_fn)(const double *p, double *theta, char *msg, size_t msglen);

/* Prescribed-motion simulation over n samples, as the Python law's _kernel:
 * t, v [n]; a, load, x [n] or NULL when the law does not take them; method 0 exact, 1 euler;
 * state0 [n_states]; writes F [n] and S [n * n_states] (row-major: S[k*n_states + j]). */
typedef void (*fl_kernel_fn)(int n, const double *t, const double *v, const double *a,
                             const double *load, const double *x, const double *theta,
                             int method, const double *state0, double *F, double *S);

/* Laws whose coefficients jump at |v| = vc (load_lugre): vc and the packed theta of the
 * law with the coefficients of |v| < vc (low) and |v| >= vc (high) everywhere, as the
 * Python regimes(). NULL for smooth laws. Returns nonzero on failure. */
typedef int (*fl_regimes_fn)(const double *theta, double *vc, double *theta_low,
                             double *theta_high);

/* Continuous time (Model Exchange, reference integrator): d(state)/dt and the force at a
 * state and inputs, as the Python derivatives(state, v, ...) and force(state, v, ...). */
typedef void (*fl_deriv_fn)(const double *theta, const double *state, double v, double a,
                            double load, double x, double *dstate);
typedef double (*fl_force_fn)(const double *theta, const double *state, double v, double a,
                              double load, double x);

typedef struct fl_law_def {
    const char *name;        /* registry name, friction.MODELS key */
    int n_params;            /* entries of p[] */
    int n_theta;             /* entries of theta */
    int n_states;            /* continuous states (0: a static map) */
    int inputs;              /* FL_IN_* mask */
    fl_pack_fn pack;
    fl_kernel_fn kernel;
    fl_regimes_fn regimes;   /* NULL: smooth */
    fl_deriv_fn derivatives; /* NULL when n_states == 0 */
    fl_force_fn force;
} fl_law_def;

extern const fl_law_def fl_law_lugre;
extern const fl_law_def fl_law_stribeck;
extern const fl_law_def fl_law_modified_lugre;
extern const fl_law_def fl_law_load_lugre;
extern const fl_law_def fl_law_mre_lugre;
extern const fl_law_def fl_law_gms;
extern const fl_law_def fl_law_backlash_lugre;

#endif
