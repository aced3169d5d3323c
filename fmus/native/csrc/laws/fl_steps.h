/* frictionlab native FMUs: a sample step cut where the velocity changes sign
 * (friction/steps.py split_step), for the laws whose state depends on the path of the
 * displacement (gms, backlash_lugre). Same arithmetic as the numba helper. */
#ifndef FL_STEPS_H
#define FL_STEPS_H

/* The step [0, h] with end velocities v0, v1 as one or two pieces of one velocity sign:
 * durations T[0], T[1] (T[1] = 0: one piece, the whole step) and end velocities
 * a[j] -> b[j] of piece j (across a reversal v0 -> 0 and 0 -> v1). */
static inline void fl_split_step(double v0, double v1, double h, double T[2], double a[2],
                                 double b[2])
{
    if (v0 * v1 < 0.0) {
        const double tr = h * (v0 / (v0 - v1));
        T[0] = tr;
        a[0] = v0;
        b[0] = 0.0;
        T[1] = h - tr;
        a[1] = 0.0;
        b[1] = v1;
    } else {
        T[0] = h;
        a[0] = v0;
        b[0] = v1;
        T[1] = 0.0;
        a[1] = 0.0;
        b[1] = 0.0;
    }
}

#endif
