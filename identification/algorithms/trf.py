"""scipy's trust-region reflective least squares (``method="trf"``, ``tr_solver="exact"``,
``x_scale=1``, linear loss, finite box) with its small-matrix algebra compiled.

On a compressed residual of length D + 1 (:func:`identification.algorithms.local.
compress_normal_equations`) an iteration of :func:`scipy.optimize.least_squares` costs
about 0.25 ms of Python bookkeeping (its checks, the Coleman-Li scaling, an SVD through
``scipy.linalg``, the reflective step selection): 2.4 ms of the 6.6 ms default
identification of a 10,000-sample LuGre record, more than half of the 3.2 ms its nine
sensitivity passes cost. :func:`trf_exact` runs the same algorithm (scipy 1.17's
``trf_bounds``: the same trust-region radius, Levenberg-Marquardt parameter, reflected and
gradient steps, termination tests and status codes, so the same iterates to rounding) with
the algebra of an iteration in two compiled calls.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

__all__ = ["trf_exact", "TrfResult"]

_EPS = float(np.finfo(float).eps)

#: scipy.optimize.least_squares' messages by status
MESSAGES = {
    0: "The maximum number of function evaluations is exceeded.",
    1: "`gtol` termination condition is satisfied.",
    2: "`ftol` termination condition is satisfied.",
    3: "`xtol` termination condition is satisfied.",
    4: "Both `ftol` and `xtol` termination conditions are satisfied.",
}


class TrfResult:
    """What the algorithms read of a scipy ``OptimizeResult``: ``x``, ``cost``
    (half the sum of squares), ``fun``, ``jac``, ``grad``, ``optimality``, ``nfev``,
    ``njev``, ``status``, ``message``, ``success``."""

    def __init__(self, **kw):
        self.__dict__.update(kw)


@njit(cache=True, nogil=True)
def _strictly_feasible(x, lb, ub, rstep):
    """scipy's ``make_strictly_feasible``: a coordinate at (or within ``rstep`` relative
    of) a bound moves that far inside; ``rstep=0``: to the next float inside."""
    out = x.copy()
    for i in range(x.size):
        lo, hi = lb[i], ub[i]
        if rstep == 0.0:
            low = x[i] <= lo
            up = x[i] >= hi
        else:
            ld = x[i] - lo
            ud = hi - x[i]
            low = ld <= min(ud, rstep * max(1.0, abs(lo)))
            up = ud <= min(ld, rstep * max(1.0, abs(hi)))
        if up:  # scipy marks upper after lower: upper wins
            out[i] = np.nextafter(hi, lo) if rstep == 0.0 else hi - rstep * max(1.0, abs(hi))
        elif low:
            out[i] = np.nextafter(lo, hi) if rstep == 0.0 else lo + rstep * max(1.0, abs(lo))
        if out[i] < lo or out[i] > hi:
            out[i] = 0.5 * (lo + hi)
    return out


@njit(cache=True, nogil=True)
def _cl_scaling(x, g, lb, ub):
    """Coleman-Li scaling vector ``v`` and its derivative ``dv`` (finite bounds)."""
    n = x.size
    v = np.ones(n)
    dv = np.zeros(n)
    for i in range(n):
        if g[i] < 0.0:
            v[i] = ub[i] - x[i]
            dv[i] = -1.0
        if g[i] > 0.0:
            v[i] = x[i] - lb[i]
            dv[i] = 1.0
    return v, dv


@njit(cache=True, nogil=True)
def _setup(x, f, J, lb, ub):
    """One iteration's scaled problem: gradient, its scaled infinity norm, the scaling
    ``d``, ``diag_h``, ``g_h``, ``J_h`` and the SVD of the augmented ``[J_h; diag_h^.5]``
    (``uf = U^T [f; 0]``, singular values, ``V``)."""
    m, n = J.shape
    g = J.T @ f
    v, dv = _cl_scaling(x, g, lb, ub)
    gn = 0.0
    for i in range(n):
        gn = max(gn, abs(g[i] * v[i]))
    d = np.sqrt(v)
    diag_h = g * dv
    g_h = d * g
    Ja = np.zeros((m + n, n))
    for i in range(m):
        for j in range(n):
            Ja[i, j] = J[i, j] * d[j]
    for j in range(n):
        Ja[m + j, j] = math.sqrt(diag_h[j])
    U, s, Vt = np.linalg.svd(Ja, full_matrices=False)
    fa = np.zeros(m + n)
    fa[:m] = f
    uf = U.T @ fa
    return g, gn, d, diag_h, g_h, Ja[:m].copy(), uf, s, Vt.T.copy()


@njit(cache=True, nogil=True)
def _solve_tr(n, m, uf, s, V, Delta, alpha0, has_alpha):
    """scipy's ``solve_lsq_trust_region`` (More's method on one SVD; rtol 0.01, 10
    iterations)."""
    suf = s * uf
    full_rank = False
    if m >= n:
        full_rank = s[n - 1] > _EPS * m * s[0]
    if full_rank:
        p = -(V @ (uf / s))
        if np.linalg.norm(p) <= Delta:
            return p, 0.0
    alpha_upper = np.linalg.norm(suf) / Delta
    alpha_lower = 0.0
    if full_rank:
        denom = s ** 2
        pn = np.linalg.norm(suf / denom)
        phi = pn - Delta
        dphi = -np.sum(suf ** 2 / denom ** 3) / pn
        alpha_lower = -phi / dphi
    if (not has_alpha) or ((not full_rank) and alpha0 == 0.0):
        alpha = max(0.001 * alpha_upper, math.sqrt(alpha_lower * alpha_upper))
    else:
        alpha = alpha0
    for it in range(10):
        if alpha < alpha_lower or alpha > alpha_upper:
            alpha = max(0.001 * alpha_upper, math.sqrt(alpha_lower * alpha_upper))
        denom = s ** 2 + alpha
        pn = np.linalg.norm(suf / denom)
        phi = pn - Delta
        dphi = -np.sum(suf ** 2 / denom ** 3) / pn
        if phi < 0:
            alpha_upper = alpha
        ratio = phi / dphi
        alpha_lower = max(alpha_lower, alpha - ratio)
        alpha -= (phi + Delta) * ratio / Delta
        if abs(phi) < 0.01 * Delta:
            break
    p = -(V @ (suf / (s ** 2 + alpha)))
    p *= Delta / np.linalg.norm(p)
    return p, alpha


@njit(cache=True, nogil=True)
def _step_to_bound(x, s, lb, ub):
    """scipy's ``step_size_to_bound``: the step along ``s`` to the first face and which
    coordinates reach it (-1 lower, 1 upper, 0 none)."""
    n = x.size
    steps = np.full(n, np.inf)
    for i in range(n):
        if s[i] != 0.0:
            steps[i] = max((lb[i] - x[i]) / s[i], (ub[i] - x[i]) / s[i])
    mn = steps.min()
    hits = np.zeros(n)
    for i in range(n):
        if steps[i] == mn:
            hits[i] = np.sign(s[i])
    return mn, hits


@njit(cache=True, nogil=True)
def _quadratic(J, g, s, diag):
    Js = J @ s
    return 0.5 * (np.dot(Js, Js) + np.dot(s * diag, s)) + np.dot(s, g)


@njit(cache=True, nogil=True)
def _min_quad_1d(a, b, lo, hi, c):
    """scipy's ``minimize_quadratic_1d``: (t, value) at the best of lo, hi and the
    interior extremum."""
    best_t = lo
    best_y = lo * (a * lo + b) + c
    y = hi * (a * hi + b) + c
    if y < best_y:
        best_t, best_y = hi, y
    if a != 0.0:
        e = -0.5 * b / a
        if lo < e < hi:
            y = e * (a * e + b) + c
            if y < best_y:
                best_t, best_y = e, y
    return best_t, best_y


@njit(cache=True, nogil=True)
def _trial(x, J_h, diag_h, g_h, d, uf, s, V, Delta, alpha0, has_alpha, lb, ub, theta):
    """The trust-region step of one trial (scipy's ``solve_lsq_trust_region`` then
    ``select_step``: the interior step, its reflection at the first face, or the scaled
    gradient step, whichever the quadratic model prefers) and the strictly feasible new
    point. Returns (x_new, step, step_h, predicted reduction, alpha, |step|, |step_h|,
    |x|)."""
    m, n = J_h.shape
    p_h, alpha = _solve_tr(n, m, uf, s, V, Delta, alpha0, has_alpha)
    p = d * p_h
    xp = x + p
    inside = True
    for i in range(n):
        if xp[i] < lb[i] or xp[i] > ub[i]:
            inside = False
    if inside:
        step, step_h = p, p_h
        pred = -_quadratic(J_h, g_h, p_h, diag_h)
    else:
        p_stride, hits = _step_to_bound(x, p, lb, ub)
        r_h = p_h.copy()
        for i in range(n):
            if hits[i] != 0.0:
                r_h[i] = -r_h[i]
        r = d * r_h
        p = p * p_stride
        p_h = p_h * p_stride
        x_on = x + p
        # intersect_trust_region(p_h, r_h, Delta): the positive root
        a_ = np.dot(r_h, r_h)
        b_ = np.dot(p_h, r_h)
        c_ = np.dot(p_h, p_h) - Delta ** 2
        dd = math.sqrt(b_ * b_ - a_ * c_)
        q = -(b_ + math.copysign(dd, b_))
        t1 = q / a_
        t2 = c_ / q
        to_tr = max(t1, t2)
        to_bound, _ = _step_to_bound(x_on, r, lb, ub)
        r_stride = min(to_bound, to_tr)
        if r_stride > 0:
            r_l = (1 - theta) * p_stride / r_stride
            r_u = theta * to_bound if r_stride == to_bound else to_tr
        else:
            r_l = 0.0
            r_u = -1.0
        if r_l <= r_u:
            v_ = J_h @ r_h
            aq = 0.5 * (np.dot(v_, v_) + np.dot(r_h * diag_h, r_h))
            u_ = J_h @ p_h
            bq = np.dot(g_h, r_h) + np.dot(u_, v_) + np.dot(p_h * diag_h, r_h)
            cq = 0.5 * np.dot(u_, u_) + np.dot(g_h, p_h) + 0.5 * np.dot(p_h * diag_h, p_h)
            r_stride, r_value = _min_quad_1d(aq, bq, r_l, r_u, cq)
            r_h = r_h * r_stride + p_h
            r = r_h * d
        else:
            r_value = np.inf
        p = p * theta
        p_h = p_h * theta
        p_value = _quadratic(J_h, g_h, p_h, diag_h)
        ag_h = -g_h
        ag = d * ag_h
        to_tr = Delta / np.linalg.norm(ag_h)
        to_bound, _ = _step_to_bound(x, ag, lb, ub)
        ag_stride = theta * to_bound if to_bound < to_tr else to_tr
        v_ = J_h @ ag_h
        aq = 0.5 * (np.dot(v_, v_) + np.dot(ag_h * diag_h, ag_h))
        bq = np.dot(g_h, ag_h)
        ag_stride, ag_value = _min_quad_1d(aq, bq, 0.0, ag_stride, 0.0)
        ag_h = ag_h * ag_stride
        ag = ag * ag_stride
        if p_value < r_value and p_value < ag_value:
            step, step_h, pred = p, p_h, -p_value
        elif r_value < p_value and r_value < ag_value:
            step, step_h, pred = r, r_h, -r_value
        else:
            step, step_h, pred = ag, ag_h, -ag_value
    x_new = _strictly_feasible(x + step, lb, ub, 0.0)
    return (x_new, step, step_h, pred, alpha, np.linalg.norm(step), np.linalg.norm(step_h),
            np.linalg.norm(x))


def trf_exact(fun_jac, x0, lb, ub, *, ftol=1e-8, xtol=1e-8, gtol=1e-8, max_nfev=None,
              stop=None, cost_of=None):
    """Minimise ``0.5 |f(x)|^2`` in the box ``[lb, ub]`` as
    ``scipy.optimize.least_squares(fun, x0, jac=jac, bounds=(lb, ub), method="trf",
    tr_solver="exact", x_scale=1.0)`` does, for small problems.

    Parameters
    ----------
    fun_jac : callable(x) -> (f, J)
        Residual vector (length m) and its m x n Jacobian at ``x``; called once per point
        (scipy calls ``fun`` at every trial point and ``jac`` at the accepted ones: the
        same points, so a caller computing both at once loses nothing).
    x0 : ndarray, shape (n,)
        Start inside the box (moved strictly inside as scipy moves it).
    lb, ub : ndarray, shape (n,)
        Finite bounds, ``lb < ub``.
    ftol, xtol, gtol : float
        scipy's tolerances (cost change, step, scaled gradient).
    max_nfev : int, optional
        Most evaluations (default ``100 n``).
    cost_of : callable(x) -> float, optional
        Half the sum of squares at ``x`` alone, for the trial points (as scipy calls
        ``fun`` there): ``fun_jac`` then runs only where a trial is accepted (as scipy's
        ``jac``). For residuals whose Jacobian costs more than their value (finite
        differences).
    stop : callable(f, J, cost) -> str or None, optional
        Tested at every accepted point (the start included) after scipy's gradient test:
        a string ends the run there with status 2 and that message (e.g. the Gauss-Newton
        model promises no reduction worth a pass). Not in scipy.

    Returns
    -------
    TrfResult
        ``x``, ``cost`` (half the sum of squares), ``fun``, ``jac``, ``grad``,
        ``optimality``, ``nfev``, ``njev``, ``status`` (scipy's codes 0-4), ``message``,
        ``success`` (status > 0).

    Raises
    ------
    ValueError
        Non-finite residuals at the start (as scipy).
    """
    lb = np.asarray(lb, float)
    ub = np.asarray(ub, float)
    x = _strictly_feasible(np.asarray(x0, float), lb, ub, 1e-10)
    n = x.size
    if max_nfev is None:
        max_nfev = 100 * n
    f, J = fun_jac(x)
    if not np.all(np.isfinite(f)):
        raise ValueError("Residuals are not finite in the initial point.")
    nfev = njev = 1
    m = f.size
    cost = 0.5 * float(np.dot(f, f))
    g = J.T @ f
    v, dv = _cl_scaling(x, g, lb, ub)
    Delta = float(np.linalg.norm(x / v ** 0.5)) or 1.0
    alpha, has_alpha = 0.0, True
    status = None
    message = None
    g_norm = np.nan
    while True:
        g, g_norm, d, diag_h, g_h, J_h, uf, s, V = _setup(x, f, J, lb, ub)
        if g_norm < gtol:
            status = 1
        if status is None and stop is not None:
            why = stop(f, J, cost)
            if why:
                status, message = 2, why
        if status is not None or nfev == max_nfev:
            break
        theta = max(0.995, 1.0 - g_norm)
        actual = -1.0
        while actual <= 0 and nfev < max_nfev:
            x_new, step, step_h, pred, alpha, step_norm, step_h_norm, x_norm = _trial(
                x, J_h, diag_h, g_h, d, uf, s, V, Delta, alpha, has_alpha, lb, ub, theta)
            if cost_of is None:
                f_new, J_new = fun_jac(x_new)
                cost_new = 0.5 * float(np.dot(f_new, f_new)) \
                    if np.all(np.isfinite(f_new)) else math.nan
            else:
                cost_new = float(cost_of(x_new))
            nfev += 1
            if not math.isfinite(cost_new):
                Delta = 0.25 * step_h_norm
                continue
            actual = cost - cost_new
            # update_tr_radius
            if pred > 0:
                ratio = actual / pred
            elif pred == actual == 0:
                ratio = 1.0
            else:
                ratio = 0.0
            Delta_new = Delta
            if ratio < 0.25:
                Delta_new = 0.25 * step_h_norm
            elif ratio > 0.75 and step_h_norm > 0.95 * Delta:
                Delta_new = 2.0 * Delta
            # check_termination
            ftol_ok = actual < ftol * cost and ratio > 0.25
            xtol_ok = step_norm < xtol * (xtol + x_norm)
            if ftol_ok and xtol_ok:
                status = 4
            elif ftol_ok:
                status = 2
            elif xtol_ok:
                status = 3
            if status is not None:
                break
            alpha *= Delta / Delta_new
            Delta = Delta_new
        if actual > 0:
            if cost_of is not None:
                f_new, J_new = fun_jac(x_new)
            x, f, J, cost = x_new, f_new, J_new, cost_new
            njev += 1
    if status is None:
        status = 0
    return TrfResult(x=x, cost=cost, fun=f, jac=J, grad=g, optimality=g_norm, nfev=nfev,
                     njev=njev, status=status, message=message or MESSAGES[status],
                     success=status > 0)
