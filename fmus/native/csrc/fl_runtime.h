/* frictionlab native FMUs: the variable table the generator (fmus/native/build.py) writes
 * into fl_model.h, and the roles that tell the runtime (fl_fmi2.c) what each variable is. */
#ifndef FL_RUNTIME_H
#define FL_RUNTIME_H

#define FL_REAL 0
#define FL_INTEGER 1
#define FL_BOOLEAN 2
#define FL_ENUM 3

#define FL_PARAMETER 0
#define FL_INPUT 1
#define FL_OUTPUT 2
#define FL_LOCAL 3

/* roles; idx says which entry (law parameter p[idx], state idx, coupling output idx ...) */
enum {
    FL_R_PARAM,        /* law parameter p[idx] (Real, Boolean or Enumeration code) */
    FL_R_TWIN_FLAG,    /* Boolean: law parameter p[idx] is given (false: NAN, "same as +") */
    FL_R_IN_V, FL_R_IN_A, FL_R_IN_LOAD, FL_R_IN_X, FL_R_IN_F,
    FL_R_IN_VMEAN, FL_R_IN_SHARE,
    FL_R_H_LIN, FL_R_FOH, FL_R_USE_VMEAN, FL_R_USE_SHARE,
    FL_R_OUT_F,        /* the force */
    FL_R_OUT_LIN,      /* coupling output idx (dF_dx ... dF_dt_kink, then switch outputs) */
    FL_R_STATE,        /* continuous state idx (an output) */
    FL_R_DER,          /* derivative of state idx (Model Exchange) */
    FL_R_EXT,          /* effects block: packed extension entry e[idx] */
    FL_R_MASS_PARAM,   /* mass: parameter idx (m, x0, v0, u0, u_amp, u_freq) */
    FL_R_IN_FEXT, FL_R_IN_FFRIC,
    FL_R_OUT_X, FL_R_OUT_V, FL_R_OUT_A,
    FL_R_EMPS_PARAM,   /* EMPS axis / controller: parameter FL_EP_<idx> of fl_model.h */
    FL_R_IN_U, FL_R_IN_QG, FL_R_IN_PULSE, FL_R_OUT_U, FL_R_OUT_FMOTOR
};

typedef struct fl_var {
    const char *name;
    int type, causality, role, idx;
    double start, lo, hi;   /* Real bounds (Integer/Enumeration: 1..n items) */
    int lo_open, hi_open;   /* the bound itself excluded */
    const char *unit;
} fl_var;

#define FL_KIND_LAW 1
#define FL_KIND_EFFECTS 2
#define FL_KIND_MASS 3
#define FL_KIND_EMPS_AXIS 4
#define FL_KIND_EMPS_CTRL 5

/* largest EMPS parameter index + 1 (FL_EP_* of fl_model.h) */
#define FL_EP_MAX 16

#endif
