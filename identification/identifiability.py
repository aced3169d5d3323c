"""What an identification result can be trusted for: bounds, degenerate combinations, honest
intervals and the experiment that would pin what the data leave open.

:func:`assess_identifiability` runs after every fit (:func:`identification.identify` calls
it) and returns the ``identifiability`` report and the confidence intervals ``ci``:

* **at bound** - a parameter whose value sits within :data:`NEAR_BOUND` (a fraction of its
  search range, on the log scale for log-searched parameters) of an edge of the search box,
  and whether that edge is the law's admissible limit (``sigma2 >= 0``) or only the edge of
  the search box (then the optimum may lie beyond it).
* **structurally degenerate combinations**, detected from the law and the data and
  confirmed on the residual Jacobian (the contributions of the members cancel):

  - the offset ``b`` with the direction levels: ``F = g(v) sgn(v) + sigma2 v + b`` on each
    side of v = 0 only sees ``Fc + b`` (v > 0) and ``Fc_neg - b`` (v < 0); with independent
    levels per direction, or data in one direction only, ``b`` and the levels are one
    combination too many. Reported as the combination ``"b+Fc+Fs+..."`` with the
    combinations that *are* identified (``Fc+b``, ``Fc_neg-b``, ...), their values and
    intervals (the visible reparameterisation).
  - the Stribeck velocity ``vs`` (and the exponent ``alpha``) when ``|Fs - Fc|`` is below
    the residual noise: there is no visible dip to place.
  - the bristle parameters ``sigma0``/``sigma1`` when the bristle settles within one sample
    step everywhere (the data never stick, or the step is coarse against the bristle time
    constant ``g(v) / (sigma0 |v|)``).

* **intervals that respect the parameter's domain**: Gauss-Newton on the log of a
  parameter that must be positive (``lower >= 0``), on the value otherwise; the Jacobian's
  near-null directions get an infinite variance (a pseudo-inverse would report them as
  exactly known). Where Gauss-Newton is not trustworthy - a parameter at a bound, an
  infinite or huge variance, or a cost that does not rise as the quadratic model predicts
  at the interval's ends - the interval is a **profile likelihood**: the parameter is
  stepped away from the estimate, the others re-fitted at each step, until the cost rises
  by the same amount a Gauss-Newton interval of the same level allows,
  ``SSR <= SSR_min (1 + z^2 / (N - D))``. A side where the cost stays below that up to the
  search box is reported *open* (the box edge is shown, the parameter is unidentified
  there). Each interval says which method gave it.
* **excitation advice**: one sentence per open question, naming the experiment that
  answers it (small-amplitude presliding, reversals, slower plateaus, longer sticking).

Everything is in the units of each parameter's metadata (SI: N, m/s, N/m, N.s/m).
Statistical assumption of both interval methods: white residuals; coloured residuals (real
records) make every interval optimistic.
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["assess_identifiability", "NEAR_BOUND", "CANCELLATION", "PROFILE_BUDGET",
           "domain_is_positive"]

#: a parameter is "at a bound" within this fraction of its search range (cube coordinate)
NEAR_BOUND = 5e-3
#: a parameter this close to an edge (cube coordinate) is on it
ON_BOUND = 1e-6
#: the members of a candidate combination are degenerate when their joint move (a tenth of
#: the level they share) changes the residual by less than this fraction of their separate
#: moves (root of the ratio of the cost increases: they cancel)
CANCELLATION = 0.1
#: a parameter takes part in a null direction of the Jacobian with at least this loading
NULL_LOADING = 0.05
#: simulations the profile likelihoods of one result may spend at most
PROFILE_BUDGET = 20000
#: a positive parameter whose interval spans more than this factor is not identified
SPAN_UNIDENTIFIED = 1e3
#: a parameter on a search-box edge whose interval is open toward that edge and covers
#: at least this share of the box (search coordinates: log for positive parameters) is not
#: identified [-]: the data bound it on one side only, and the estimate is the box's edge
#: (sigma0 of LuGre sampled once a second: from 3.8e4 N/m to the edge, 62 % of the box)
BOX_SHARE_UNIDENTIFIED = 0.5
#: Gauss-Newton is trusted where the cost at its interval's ends rises by this range of
#: multiples of what the quadratic model predicts
TRUST = (0.5, 2.0)
_JAC_STEP = 1e-6
_MAX_POINTS = 12


def domain_is_positive(info) -> bool:
    """Whether a parameter's admissible domain is ``>= 0`` (its interval is built on the
    log scale, so it never goes negative)."""
    return info.lower >= 0.0


class _Fit:
    """The objective seen from the unit cube, with an evaluation counter."""

    def __init__(self, objective, space, u, cost):
        self.obj = objective
        self.space = space
        self.u = np.clip(np.asarray(u, float), 0.0, 1.0)
        self.Fd = np.asarray(objective.data.F, float)
        self.rs = float(objective._rscale)
        self.N = self.Fd.size
        self.D = space.dim
        self.n_evals = 0
        r0 = self.residuals(self.u[None, :])[0]
        self.r0 = r0
        self.cost2 = float(np.sum(r0 * r0)) if np.all(np.isfinite(r0)) else float(cost) ** 2

    def residuals(self, U) -> np.ndarray:
        U = np.clip(np.atleast_2d(np.asarray(U, float)), 0.0, 1.0)
        X = self.space.to_physical(U)
        P = np.asarray(self.obj.predict(X), float)
        self.n_evals += U.shape[0]
        R = np.subtract(P, self.Fd[None, :])  # one k x N array, not two (long records)
        R *= self.rs
        return R

    def cost2_of(self, U) -> np.ndarray:
        R = self.residuals(U)
        c = np.sum(R * R, axis=1)
        return np.where(np.isfinite(c), c, np.inf)


def _jacobian(fit, u, r0, cols=None) -> np.ndarray:
    """Forward differences in cube coordinates (inward at the upper face), N x len(cols)."""
    cols = list(range(fit.D)) if cols is None else list(cols)
    h = np.array([-_JAC_STEP if u[j] + _JAC_STEP > 1.0 else _JAC_STEP for j in cols])
    U = np.repeat(u[None, :], len(cols), axis=0)
    U[np.arange(len(cols)), cols] += h
    J = fit.residuals(U)  # the same numbers as before, worked out in place
    J -= r0[None, :]
    J /= h[:, None]
    J[~np.isfinite(J)] = 0.0
    return J.T


# ------------------------------------------------------------------------------ profile
def _refit(fit, u_start, j, uj, max_nfev=20):
    """Minimise the cost over every coordinate but ``j`` (held at ``uj``) from ``u_start``.
    Returns (u, cost^2)."""
    from scipy.optimize import least_squares
    free = [k for k in range(fit.D) if k != j]
    base = np.array(u_start, float)
    base[j] = uj
    if not free:
        return base, float(fit.cost2_of(base[None, :])[0])
    cache = {}

    def full(x):
        u = base.copy()
        u[free] = x
        return u

    def fun(x):
        r = fit.residuals(full(x)[None, :])[0]
        r = np.where(np.isfinite(r), r, 1e3)
        cache["x"], cache["r"] = np.array(x), r
        return r

    def jac(x):
        r = cache["r"] if "x" in cache and np.array_equal(cache["x"], x) else fun(x)
        return _jacobian(fit, full(x), r, free)

    x0 = np.clip(base[free], 1e-9, 1 - 1e-9)
    if 8 * fit.N * fit.D > LONG_JACOBIAN_BYTES:
        return _refit_normal(fit, base, free, x0, max_nfev)
    try:
        res = least_squares(fun, x0, jac=jac, bounds=(0.0, 1.0), method="trf",
                            x_scale="jac", ftol=1e-7, xtol=1e-7, gtol=1e-7,
                            max_nfev=max_nfev,
                            tr_solver="lsmr" if len(free) > 1 else "exact")
    except (ValueError, np.linalg.LinAlgError):
        return base, float(fit.cost2_of(base[None, :])[0])
    u = full(res.x)
    return u, float(2.0 * res.cost)


#: above this size of the N x D Jacobian (8 bytes a number) a profile refit works on the
#: normal equations (:func:`_refit_normal`): scipy's trust region on the long residual holds
#: the Jacobian and its scaled copies (the peak of a 2,000,000-row report, 1.45 GB)
LONG_JACOBIAN_BYTES = 64 * 2**20


def _normal_at(fit, u, free):
    """``(r.r, J^T r, J^T J)`` of the scaled residual over the coordinates ``free`` at
    ``u`` (cube coordinates): from the objective's analytic sensitivity pass where it has
    one (:meth:`identification.objectives.InProcessObjective.normal_equations`, one
    evaluation, memory O(D^2)), else forward differences stored in float32
    (:func:`identification.algorithms.local.forward_difference_normal_equations`)."""
    has = getattr(fit.obj, "has_jacobian", None)
    if callable(has) and has():
        x = fit.space.to_physical(u)
        out = fit.obj.normal_equations(x)
        if out is not None:
            fit.n_evals += 1
            c2, g, H = out
            lo, hi = fit.space._ends()
            s = np.where(fit.space.log, x * (hi - lo), hi - lo)  # dx/du
            g = np.asarray(g) * s
            H = np.asarray(H) * np.outer(s, s)
            return float(c2), g[free], H[np.ix_(free, free)]
    from .algorithms.local import forward_difference_normal_equations

    def residual(v):
        return fit.residuals(v[None, :])[0]
    c2, g, H, _ = forward_difference_normal_equations(residual, u, cols=free, step=_JAC_STEP)
    return c2, g, H


def _refit_normal(fit, base, free, x0, max_nfev):
    """:func:`_refit`'s least squares (the same scipy options) on the compressed residual of
    the normal equations (:func:`identification.algorithms.local.
    compress_normal_equations`: the long residual's Gauss-Newton model in D + 1 numbers):
    no N x D Jacobian is held. Returns (u, cost^2)."""
    from scipy.optimize import least_squares

    from .algorithms.local import compress_normal_equations
    cache = {}

    def full(x):
        u = base.copy()
        u[free] = x
        return u

    def at(x):
        key = np.asarray(x, float).tobytes()
        if key not in cache:
            cache.clear()
            c2, g, H = _normal_at(fit, full(x), free)
            if not (np.isfinite(c2) and np.all(np.isfinite(H)) and np.all(np.isfinite(g))):
                f = np.zeros(len(free) + 1)
                f[-1] = 1e3 * np.sqrt(fit.N)  # as 1e3 per non-finite sample: a huge cost
                cache[key] = (f, np.zeros((len(free) + 1, len(free))))
            else:
                cache[key] = compress_normal_equations(c2, g, H)
        return cache[key]

    try:
        res = least_squares(lambda x: at(x)[0], x0, jac=lambda x: at(x)[1],
                            bounds=(0.0, 1.0), method="trf", x_scale="jac", ftol=1e-7,
                            xtol=1e-7, gtol=1e-7, max_nfev=max_nfev,
                            tr_solver="lsmr" if len(free) > 1 else "exact")
    except (ValueError, np.linalg.LinAlgError):
        return base, float(fit.cost2_of(base[None, :])[0])
    return full(res.x), float(2.0 * res.cost)


def _unit(space, j, x, value) -> float:
    """Parameter ``j`` at ``value`` (physical units) in its search box's coordinates [-]
    (0 and 1 the box's edges; log scale for positive parameters); ``x`` the estimate, the
    other parameters' values."""
    return float(space.to_unit(np.where(np.arange(len(x)) == j, value, x))[j])


def _box_share(space, j, x, low, high) -> float:
    """Share of parameter ``j``'s search box [-] (in its search coordinates) that the
    interval ``[low, high]`` covers; ``x`` the estimate (the other parameters' values)."""
    return abs(_unit(space, j, x, high) - _unit(space, j, x, low))


def _profile_side(fit, j, sgn, thresh2, step0, budget_left):
    """Walk coordinate ``j`` away from the estimate (``sgn`` = +1 up, -1 down), re-fitting
    the others, until the cost crosses ``thresh2`` (closed side: the crossing, found by two
    bisections and linear interpolation) or the box edge is reached (open side).

    Returns (u_j at the end, open?, (lowest cost^2 met, u of that point), stopped?):
    ``stopped`` when a point beats the estimate by more than the interval's own cost rise
    (the fit has not converged: the walk ends there)."""
    u_prev = fit.u.copy()
    c_prev = fit.cost2
    step = step0
    best = (fit.cost2, fit.u.copy())
    n0 = fit.n_evals
    floor = fit.cost2 - (thresh2 - fit.cost2)
    for _ in range(_MAX_POINTS):
        target = float(np.clip(u_prev[j] + sgn * step, 0.0, 1.0))
        if target == u_prev[j]:
            return target, True, best, False
        u_new, c2 = _refit(fit, u_prev, j, target)
        if c2 < best[0]:
            best = (c2, u_new)
        if c2 < floor:
            return target, True, best, True
        if c2 > thresh2:
            lo, hi, c_lo, c_hi, u_lo = u_prev[j], target, c_prev, c2, u_prev
            for _ in range(2):
                mid = 0.5 * (lo + hi)
                um, cm = _refit(fit, u_lo, j, mid)
                if cm < best[0]:
                    best = (cm, um)
                if cm > thresh2:
                    hi, c_hi = mid, cm
                else:
                    lo, c_lo, u_lo = mid, cm, um
            w = (thresh2 - c_lo) / (c_hi - c_lo) if c_hi > c_lo else 0.5
            return lo + float(np.clip(w, 0.0, 1.0)) * (hi - lo), False, best, False
        u_prev, c_prev = u_new, c2
        if target in (0.0, 1.0):
            return target, True, best, False
        if fit.n_evals - n0 > budget_left:
            return target, True, best, False  # not crossed within the budget: open
        step *= 2.0
    return float(u_prev[j]), True, best, False


def _singular(Jn):
    """Singular values and right singular vectors of a tall N x k matrix, from the SVD of
    its k x k triangular factor (QR): the same numbers without the N x k left factor and
    its workspace (a long record's Jacobian would be held twice more)."""
    if Jn.shape[0] > Jn.shape[1]:
        Jn = np.linalg.qr(Jn, mode="r")
    _, S, Vt = np.linalg.svd(Jn, full_matrices=False)
    return S, Vt


def _gn_covariance(Jth, cols, s2, names):
    """Gauss-Newton covariance of the columns ``cols`` (bool mask) of the Jacobian in
    domain coordinates, by SVD of the column-normalised matrix: singular values below
    1e-7 of the largest are null directions, whose members (loading above
    :data:`NULL_LOADING`) get an infinite variance. Returns (var (D,), cov (D, D) with NaN
    outside ``cols``, null vectors as dicts)."""
    D = Jth.shape[1]
    var = np.full(D, np.inf)
    cov = np.full((D, D), np.nan)
    nulls = []
    if not cols.any():
        return var, cov, nulls
    cn = np.linalg.norm(Jth, axis=0)
    idx = np.flatnonzero(cols)
    Jn = Jth[:, idx] / cn[idx]
    S, Vt = _singular(Jn)
    tol = S[0] * 1e-7 if S.size and S[0] > 0 else np.inf
    keep = S > tol
    Vk = Vt[keep]
    covn = (Vk.T / S[keep] ** 2) @ Vk
    c = s2 * covn / np.outer(cn[idx], cn[idx])
    v = np.diag(c).copy()
    for i in np.flatnonzero(~keep):
        nulls.append({names[idx[k]]: float(Vt[i, k]) for k in range(idx.size)})
        v[np.abs(Vt[i]) > NULL_LOADING] = np.inf
    var[idx] = v
    cov[np.ix_(idx, idx)] = c
    return var, cov, nulls


# ------------------------------------------------------------------------------ helpers
def _is_limit(info, side, bound) -> bool:
    """Whether a box edge is the parameter's admissible limit (not just the search box)."""
    return info is not None and bound == (info.lower if side == "lower" else info.upper)


def _fmt(x, unit=""):
    if x is None or not np.isfinite(x):
        return "unbounded"
    return f"{x:.4g}{(' ' + unit) if unit else ''}"


def _sides(v, share=0.01):
    """Directions of motion the record covers: '+' / '-' with more than ``share`` of the
    moving samples."""
    v = np.asarray(v, float)
    moving = v != 0
    n = max(int(moving.sum()), 1)
    out = []
    if (v > 0).sum() > share * n:
        out.append("+")
    if (v < 0).sum() > share * n:
        out.append("-")
    return out


def _twin_free(model, names, n):
    """The "-" twin of ``n`` is set independently and identified."""
    twin = getattr(model, "twins", {}).get(n)
    return twin is not None and twin in names and getattr(model.params, twin, None) is not None


def _offset_candidate(model, names, v):
    """Null direction (physical units) of the offset b with the direction levels, or None."""
    if "b" not in names or not hasattr(model.params, "Fc"):
        return None
    sides = _sides(v)
    if not sides:
        return None
    levels = [n for n in ("Fc", "Fs") if n in names]
    delta = {"b": 1.0}
    if sides == ["+"]:
        for n in levels:
            delta[n] = -1.0
    elif sides == ["-"]:
        for n in levels:
            tw = model.twins.get(n)
            if _twin_free(model, names, n):
                delta[tw] = 1.0
            elif tw is None or getattr(model.params, tw, None) is None:
                delta[n] = 1.0  # a symmetric level acts on the "-" side
    else:
        # both directions: degenerate only with independent levels on each side
        if not (levels and all(_twin_free(model, names, n) for n in levels)):
            return None
        for n in levels:
            delta[n] = -1.0
            delta[model.twins[n]] = 1.0
    return delta if len(delta) > 1 else None


def _combo_label(delta):
    return "+".join(delta)


def _g_of(model, v):
    try:
        return np.abs(np.asarray(model.g(v), float))
    except Exception:  # a law without a Stribeck curve
        return None


def _bristle_informative(model, data):
    """Samples in which the bristle has not settled within one step (exponent
    ``h sigma0 |v| / g(v)`` below 3, v != 0), the median exponent over moving samples and
    the median bristle time constant ``g / (sigma0 |v|)`` [s]."""
    s0 = getattr(model.params, "sigma0", None)
    if s0 is None or not s0 > 0:
        return None
    t, v = np.asarray(data.t, float), np.asarray(data.v, float)
    if t.size < 3:
        return None
    vm = 0.5 * (v[1:] + v[:-1])
    h = np.diff(t)
    g = _g_of(model, vm)
    if g is None:
        return None
    moving = vm != 0
    if not moving.any():
        return {"n_informative": 0, "median_exponent": math.inf, "tau": math.inf, "dt": float(np.median(h))}
    with np.errstate(divide="ignore", invalid="ignore"):
        s = h * s0 * np.abs(vm) / np.where(g > 0, g, np.nan)
        tau = np.where(moving, g / (s0 * np.abs(vm)), np.nan)
    inf = int(np.sum(moving & (s < 3.0)))
    return {"n_informative": inf, "median_exponent": float(np.nanmedian(s[moving])),
            "tau": float(np.nanmedian(tau[moving])), "dt": float(np.median(h)),
            "z_ss": float(np.nanmedian(g[moving])) / s0}


def _finite_cancellation(fit, space, names, val, delta, frac=0.1):
    """sqrt(cost increase of the joint move / sum of the members' separate increases) for
    a move of ``frac`` x the shared level along ``delta``, in the feasible direction with
    the smaller joint increase (halved up to three times if neither is feasible).
    Returns (ratio or None, move [N])."""
    member = next(n for n in delta if n != "b")
    level = abs(val[member] - delta[member] * val["b"])
    step = frac * max(level, 1e-12)
    idx = {n: names.index(n) for n in delta}
    x0 = np.array([val[n] for n in names])
    for _ in range(4):
        best = None
        for sgn in (1.0, -1.0):
            xs = [x0.copy()]
            for n, c in delta.items():
                xs[0][idx[n]] += sgn * c * step
            for n, c in delta.items():
                xi = x0.copy()
                xi[idx[n]] += sgn * c * step
                xs.append(xi)
            U = space.to_unit(np.array(xs))
            if not np.all((U[0] >= 0) & (U[0] <= 1)):
                continue
            c2 = fit.cost2_of(np.clip(U, 0.0, 1.0)) - fit.cost2
            sep = float(np.sum(np.clip(c2[1:], 0.0, None)))
            if not np.isfinite(c2[0]) or not sep > 0:
                continue
            r = math.sqrt(max(float(c2[0]), 0.0) / sep)
            if best is None or r < best:
                best = r
        if best is not None:
            return best, step
        step /= 2.0
    return None, step


def _offset_combination(fit, names, val, units, delta, Jph, s2, z, v_data, ratio, dmove,
                        advice):
    """The combination entry of the offset b with the levels, its identified
    reparameterisation (level +- b with Gauss-Newton intervals, b held) and the advice."""
    D = len(names)
    idx = {n: names.index(n) for n in delta}
    keep = [k for k in range(D) if names[k] != "b"]
    Jk = Jph[:, keep]
    try:
        ck = s2 * np.linalg.pinv(Jk.T @ Jk)
    except np.linalg.LinAlgError:
        ck = np.full((len(keep), len(keep)), np.nan)
    identified = {}
    for n, c in delta.items():
        if n == "b":
            continue
        lab = f"{n}+b" if c < 0 else f"{n}-b"
        value = val[n] + val["b"] if c < 0 else val[n] - val["b"]
        sdk = math.sqrt(max(float(ck[keep.index(idx[n]), keep.index(idx[n])]), 0.0))
        identified[lab] = {"value": value, "ci": [value - z * sdk, value + z * sdk],
                           "unit": units[n], "method": "gauss-newton with b held"}
    sides = _sides(v_data)
    members = ", ".join(n for n in delta if n != "b")
    if len(sides) == 1:
        why = (f"the record moves in one direction only (v {'>' if sides == ['+'] else '<'} "
               f"0): the offset b and the levels {members} shift the force alike")
    else:
        why = ("with independent levels per direction, b shifts the sliding force of both "
               "directions exactly as raising one side's levels and lowering the other's")
    why += (f"; only the bristle transients could split them, and moving the split by "
            f"{_fmt(dmove, 'N')} costs {ratio:.2g} of what the members' separate moves cost "
            f"(root of the cost increases)")
    shown = ", ".join(f"{k} = {_fmt(q['value'], q['unit'])}" for k, q in identified.items())
    if len(sides) == 1:
        advice.append(
            f"Only {shown} are identified ({why}). Record reversals (motion in both "
            f"directions) to separate b from the levels, or fix b (--fix b=0).")
    else:
        advice.append(
            f"Only {shown} are identified ({why}). Fix one of them (--fix b=0, or b at an "
            f"offset measured at standstill, e.g. gravity) or make the levels symmetric; "
            f"read alone, Fc, Fc_neg and b mean nothing physically.")
    return {"label": _combo_label(delta), "names": list(delta), "direction": delta,
            "cancellation": float(ratio), "move": float(dmove), "reason": why,
            "identified": identified}


# ------------------------------------------------------------------------------ main
def assess_identifiability(objective, space, u, cost, *, model, data, jac=None,
                           level: float = 0.95, profile: bool = True,
                           budget: int = PROFILE_BUDGET, progress=None):
    """Identifiability report and confidence intervals of an identification result.

    Parameters
    ----------
    objective : identification.objectives.Objective
        The cost the result minimised (``predict(X)``, ``data.F``, ``_rscale``).
    space : identification.space.ParameterSpace
        Names, search box [units of each parameter] and scaling.
    u : array_like, shape (D,)
        The estimate in unit-cube coordinates.
    cost : float
        Its cost (NRMSE).
    model : friction.base.FrictionModel
        The fitted law (the estimate's values set).
    data : Dataset or SteadyStateMap
        The fitted record (``t, v`` for a time series; ``v`` for a map).
    jac : ndarray, shape (N, D), optional
        Residual Jacobian at ``u`` in cube coordinates (computed if not given: D + 1
        simulations).
    level : float
        Confidence level of the intervals.
    profile : bool
        Compute profile likelihoods where Gauss-Newton is not trustworthy (False:
        Gauss-Newton only, said so in each interval's method).
    budget : int
        Simulations the profiles may spend (an interval left when it is spent keeps its
        Gauss-Newton value and says so).
    progress : callable(n, info), optional

    Returns
    -------
    report : dict
        ``at_bound`` (names), ``unidentified`` (names and ``"a+b"`` combinations),
        ``advice`` (sentences), and the details: ``bounds`` (per flagged name: side,
        value, bound, kind), ``combinations`` (label, members, reason, identified
        combinations with values and intervals), ``relations`` (e.g. ``Fs<Fc``),
        ``intervals`` (per name: estimate, low, high, unit, method, open sides),
        ``reasons`` (per unidentified entry), ``level``, ``notes``, ``noise_rms`` (the
        residual RMS [N]), ``evaluations`` (simulations spent), ``trust_ratio`` (per
        parameter checked: the cost rise at the Gauss-Newton interval's ends over the
        rise the quadratic model predicts; Gauss-Newton is kept within
        :data:`TRUST`).
    ci : dict
        ``name -> (low, high)`` at ``level`` [parameter units]; an open side shows the
        search-box edge.
    """
    from scipy.stats import norm
    z = float(norm.ppf(0.5 + level / 2))
    fit = _Fit(objective, space, u, cost)
    N, D = fit.N, fit.D
    names = list(space.names)
    infos = {i.name: i for i in model.Params.info()}
    units = {n: infos[n].unit if n in infos else "" for n in names}
    x = space.to_physical(fit.u)
    val = dict(zip(names, map(float, x)))
    lo_box, hi_box = np.asarray(space.lower, float), np.asarray(space.upper, float)
    dof = max(N - D, 1)
    s2 = fit.cost2 / dof
    thresh2 = fit.cost2 * (1.0 + z * z / dof)
    noise_force = math.sqrt(fit.cost2) * float(np.std(fit.Fd))  # residual RMS [N]

    if jac is None or np.shape(jac) != (N, D):
        J = _jacobian(fit, fit.u, fit.r0)
    else:
        J = np.asarray(jac, float)

    # -- coordinates: physical slope dp/du, domain coordinate theta (log for positive)
    span = np.where(space.log, np.log(np.where(space.log, hi_box / np.where(lo_box > 0, lo_box, 1.0), 1.0)),
                    hi_box - lo_box)
    dpdu = np.where(space.log, x * span, span)
    positive = np.array([domain_is_positive(infos[n]) if n in infos else False for n in names])
    logc = positive & (x > 0)
    dthdu = np.where(logc, dpdu / np.where(x > 0, x, 1.0), dpdu)
    with np.errstate(divide="ignore", invalid="ignore"):
        Jth = np.where(dthdu != 0, J / dthdu[None, :], 0.0)
        Jph = np.where(dpdu != 0, J / dpdu[None, :], 0.0)

    # -- Gauss-Newton covariance in theta with near-null directions at infinite variance.
    # A parameter on an edge of the box is an active constraint, held there; so is a
    # parameter the first pass finds not identified (infinite variance, or a 95 % interval
    # wider than half its search range): the others' covariance is computed with those
    # held, so a flat direction does not drag every other interval with it (the held ones
    # get profiles, which re-fit everything else)
    on_edge = (fit.u <= ON_BOUND) | (fit.u >= 1 - ON_BOUND)
    cn = np.linalg.norm(Jth, axis=0)
    act = (cn > 0) & ~on_edge
    var, cov, null_vectors = _gn_covariance(Jth, act, s2, names)
    with np.errstate(invalid="ignore"):
        weak = ~act | ~np.isfinite(var) | (z * np.sqrt(var) / np.abs(dthdu) > 0.5)
    held = weak & act
    if held.any() and (act & ~weak).any():
        var2, cov2, _ = _gn_covariance(Jth, act & ~weak, s2, names)
        rest = act & ~weak
        var[rest] = var2[rest]
        cov = np.where(np.outer(rest, rest), cov2, np.nan)
        for j in np.flatnonzero(held):
            cov[j, j] = var[j]
    sd = np.sqrt(var)

    report = {"at_bound": [], "unidentified": [], "advice": [], "bounds": {},
              "combinations": [], "relations": [], "intervals": {}, "reasons": {},
              "level": level, "notes": [], "noise_rms": noise_force}
    advice = report["advice"]

    # -- bounds: on an edge, or near one with the edge inside the Gauss-Newton interval
    at_side = {}
    with np.errstate(divide="ignore", invalid="ignore"):
        sd_u = np.where(np.isfinite(sd) & (dthdu != 0), sd / np.abs(dthdu), np.inf)
    for j, n in enumerate(names):
        uj = fit.u[j]
        side = None
        if uj <= ON_BOUND or (uj <= NEAR_BOUND and uj - z * sd_u[j] <= 0.0):
            side = "lower"
        elif uj >= 1 - ON_BOUND or (uj >= 1 - NEAR_BOUND and uj + z * sd_u[j] >= 1.0):
            side = "upper"
        if side is None:
            continue
        bound = float(lo_box[j] if side == "lower" else hi_box[j])
        limit = _is_limit(infos.get(n), side, bound)
        at_side[j] = (side, limit)
        report["at_bound"].append(n)
        report["bounds"][n] = {"side": side, "value": val[n], "bound": bound,
                               "kind": "admissible limit" if limit else "search box"}

    # -- structural combination: offset b with the direction levels. Exact in sliding
    # (the steady-state curve); only bristle transients can split it. Confirmed by finite
    # moves of a tenth of the level: the joint move must cost far less than the members'
    # separate moves (an infinitesimal test fails where a level sits on its bound, whose
    # sensitivities blow up)
    combos = []
    v_data = np.asarray(getattr(data, "v"), float)
    delta = _offset_candidate(model, names, v_data)
    if delta is not None:
        ratio, dmove = _finite_cancellation(fit, space, names, val, delta)
        if ratio is not None and ratio < CANCELLATION:
            combos.append(_offset_combination(fit, names, val, units, delta, Jph, s2, z,
                                              v_data, ratio, dmove, advice))
    report["combinations"] = combos
    in_combo = {n for c in combos for n in c["names"]}

    # -- relations of the Stribeck levels
    p = model.params
    for fs, fc, tag in (("Fs", "Fc", ""), ("Fs_neg", "Fc_neg", " (v < 0)")):
        Fs_, Fc_ = getattr(p, fs, None), getattr(p, fc, None)
        if Fs_ is None or Fc_ is None or (fs not in names and fc not in names):
            continue
        if Fs_ < Fc_ - max(noise_force, 1e-12):
            report["relations"].append({"label": f"{fs}<{fc}", "values": [Fs_, Fc_]})
            if fs not in names:  # a break-away level given, not fitted
                advice.append(
                    f"{fs} < {fc}{tag} (given {_fmt(Fs_, units.get(fs, 'N'))} < fitted "
                    f"{_fmt(Fc_, units.get(fc, 'N'))}): this contact breaks away below its "
                    f"sliding level, so friction rises with speed from break-away (no "
                    f"Stribeck dip); the Stribeck velocity and exponent only shape that "
                    f"rise.")
                continue
            if not hasattr(data, "t"):  # a steady-state map
                sgn = 1.0 if fs == "Fs" else -1.0
                side = sgn * v_data > 0
                lvl = np.abs(np.asarray(data.F, float)[side] - getattr(p, "b", 0.0))
                above = np.abs(v_data[side])[lvl >= 0.98 * Fc_]
                vmin = f" (here about {_fmt(float(above.min()), 'm/s')})" if above.size else ""
                advice.append(
                    f"{fs} < {fc}{tag} ({_fmt(Fs_, units.get(fs, 'N'))} < "
                    f"{_fmt(Fc_, units.get(fc, 'N'))}): the slowest rows of the map sit below "
                    f"the sliding level - presliding creep, not sliding plateaus - and no "
                    f"Stribeck curve describes them. Drop them (--min-speed, the speed where "
                    f"|F| first reaches the sliding level{vmin}) and fit the dip on the "
                    f"sliding rows; identify the presliding from a time series (two-step).")
                continue
            advice.append(
                f"{fs} < {fc}{tag} ({_fmt(Fs_, units.get(fs, 'N'))} < {_fmt(Fc_, units.get(fc, 'N'))}): "
                f"the break-away level is below the sliding level, no Stribeck dip; the "
                f"Stribeck terms are fitting something else (a transient, an acceleration- or "
                f"rate-dependent effect). Identify the static curve from constant-velocity "
                f"plateaus first (frictionlab identify MAP.csv, then --static-from) and check "
                f"the rest with frictionlab diagnose.")

    # -- rule reasons (advice attached when the verdict confirms them)
    reasons = {}
    for side_tag, fs, fc, vsn in (("", "Fs", "Fc", "vs"), (" (v < 0)", "Fs_neg", "Fc_neg", "vs_neg")):
        Fs_, Fc_ = getattr(p, fs, None), getattr(p, fc, None)
        if Fs_ is None or Fc_ is None:
            continue
        bump = abs(Fs_ - Fc_)
        if bump < 2.0 * noise_force:
            for n in (vsn, "alpha"):
                if n in names:
                    reasons.setdefault(n, f"|{fs} - {fc}|{side_tag} = {_fmt(bump, 'N')} is below "
                                       f"twice the residual noise ({_fmt(noise_force, 'N')}): no "
                                       f"visible Stribeck dip to place")
    bi = None
    if "sigma0" in names or "sigma1" in names:
        if hasattr(data, "t"):
            try:
                bi = _bristle_informative(model, data)
            except Exception:
                bi = None
        if bi is not None and bi["n_informative"] < 5:
            why = (f"the bristle settles within one sample step everywhere (step "
                   f"{_fmt(bi['dt'], 's')}, bristle time constant g/(sigma0 |v|) about "
                   f"{_fmt(bi['tau'], 's')} at the record's median speed; "
                   f"{bi['n_informative']} samples inside a transient)")
            for n in ("sigma0", "sigma1"):
                if n in names:
                    reasons.setdefault(n, why)

    # -- intervals: Gauss-Newton in the domain coordinate, checked; profiles where not
    ci = {}
    gn = {}
    for j, n in enumerate(names):
        if np.isfinite(sd[j]):
            th = math.log(x[j]) if logc[j] else x[j]
            a, b = th - z * sd[j], th + z * sd[j]
            if logc[j]:
                with np.errstate(over="ignore"):
                    a, b = math.exp(a), math.exp(min(b, 700.0))
            info = infos.get(n)
            if info is not None:
                a, b = max(a, info.lower), min(b, info.upper)
            gn[j] = (float(a), float(b))
    # the quadratic model checked at each interval's ends along the Gauss-Newton direction
    trust = {}
    trust_ratio = {}
    checks = []
    for j in gn:
        if j in at_side or names[j] in in_combo or not np.isfinite(cov[j, j]) \
                or not cov[j, j] > 0:
            continue
        step = np.where(np.isfinite(cov[:, j]), z * cov[:, j] / math.sqrt(cov[j, j]), 0.0)
        for sgn in (1.0, -1.0):
            th = np.where(logc, np.log(np.where(logc, x, 1.0)), x) + sgn * step
            xp = np.where(logc, np.exp(np.clip(th, -700, 700)), th)
            up = space.to_unit(xp)
            checks.append((j, up))
    if checks:
        U = np.array([c[1] for c in checks])
        # the parameter's own end must lie in the box; others leaving it are held at it
        own = np.array([0.0 <= c[1][c[0]] <= 1.0 for c in checks])
        c2 = fit.cost2_of(np.clip(U, 0, 1))
        pred = z * z * s2
        for (j, _), ok_in, cc in zip(checks, own, c2):
            r = (cc - fit.cost2) / pred if pred > 0 else 1.0
            good = bool(ok_in) and TRUST[0] <= r <= TRUST[1]
            trust[j] = trust.get(j, True) and good
            trust_ratio.setdefault(j, []).append(float(r))
    spent = 0
    unconverged = False
    order = []
    for j, n in enumerate(names):
        if n in in_combo:
            continue
        if j in at_side or j not in gn or not trust.get(j, False):
            order.append(j)
        elif logc[j] and gn[j][1] / max(gn[j][0], 1e-300) > SPAN_UNIDENTIFIED:
            order.append(j)
    for j, n in enumerate(names):
        unit = units[n]
        entry = {"estimate": val[n], "unit": unit, "open": []}
        if n in in_combo:
            entry.update(low=float(lo_box[j]), high=float(hi_box[j]), open=["lower", "upper"],
                         method="not identified alone (only a combination is: see "
                                "combinations)")
        elif j not in order:
            entry.update(low=gn[j][0], high=gn[j][1],
                         method="gauss-newton (log scale)" if logc[j] else "gauss-newton")
        elif not profile or spent >= budget or unconverged:
            why = ("profile not computed" if not profile else
                   "the fit has not converged" if unconverged else "profile budget spent")
            if j in gn:
                entry.update(low=gn[j][0], high=gn[j][1],
                             method=f"gauss-newton{' (log scale)' if logc[j] else ''}, not "
                                    f"trustworthy here ({why})")
            else:
                entry.update(low=float(lo_box[j]), high=float(hi_box[j]),
                             open=["lower", "upper"],
                             method=f"flat direction of the Jacobian ({why})")
        else:
            sdu = sd[j] * abs(dthdu[j]) ** -1 if np.isfinite(sd[j]) and dthdu[j] != 0 else np.nan
            step0 = float(np.clip(0.5 * z * sdu, 2e-3, 0.1)) if np.isfinite(sdu) else 0.02
            ends = {}
            for sgn, side in ((-1.0, "lower"), (1.0, "upper")):
                limit = _is_limit(infos.get(n), side, float(lo_box[j] if side == "lower"
                                                            else hi_box[j]))
                if on_edge[j] and j in at_side and at_side[j][0] == side:
                    ends[side] = (fit.u[j], not limit)  # open unless a physical limit
                    continue
                n0 = fit.n_evals
                uj, is_open, best, stopped = _profile_side(fit, j, sgn, thresh2, step0,
                                                           budget - spent)
                spent += fit.n_evals - n0
                if best[0] < fit.cost2 * (1 - 1e-6):
                    report["notes"].append(
                        f"the profile of {n} met a lower cost ({math.sqrt(best[0]):.5g} < "
                        f"{math.sqrt(fit.cost2):.5g}) at {n} = "
                        f"{_fmt(float(space.to_physical(best[1])[j]), unit)}: the optimiser "
                        f"stopped short; rerun with more starts or a larger budget")
                if stopped:
                    unconverged = True
                    break
                if is_open and limit and uj in (0.0, 1.0):
                    is_open = False  # the cost stays flat down to the law's own limit
                ends[side] = (uj, is_open)
            if unconverged:
                why = "the fit has not converged"
                if j in gn:
                    entry.update(low=gn[j][0], high=gn[j][1],
                                 method=f"gauss-newton{' (log scale)' if logc[j] else ''}, "
                                        f"not trustworthy here ({why})")
                else:
                    entry.update(low=float(lo_box[j]), high=float(hi_box[j]),
                                 open=["lower", "upper"],
                                 method=f"flat direction of the Jacobian ({why})")
                report["intervals"][n] = entry
                ci[n] = (float(entry["low"]), float(entry["high"]))
                continue
            lo_u, hi_u = ends["lower"][0], ends["upper"][0]
            uu = np.array(fit.u)
            lo_p = float(space.to_physical(np.where(np.arange(D) == j, lo_u, uu))[j])
            hi_p = float(space.to_physical(np.where(np.arange(D) == j, hi_u, uu))[j])
            entry.update(low=min(lo_p, val[n]), high=max(hi_p, val[n]),
                         open=[s for s in ("lower", "upper") if ends[s][1]],
                         method="profile likelihood")
        report["intervals"][n] = entry
        ci[n] = (float(entry["low"]), float(entry["high"]))
        if progress is not None:
            progress(0, f"identifiability: {n} [{entry['method']}]")

    # a parameter flagged near a bound whose profile stops short of it is not at it
    for j in list(at_side):
        n = names[j]
        e = report["intervals"][n]
        side = at_side[j][0]
        if on_edge[j] or "profile" not in e["method"] or side in e["open"]:
            continue
        end = e["low"] if side == "lower" else e["high"]
        if abs(fit.u[j] - (0.0 if side == "lower" else 1.0)) > 0 and \
                abs(_unit(space, j, x, end) - (0.0 if side == "lower" else 1.0)) > ON_BOUND:
            del at_side[j]
            report["at_bound"].remove(n)
            del report["bounds"][n]

    # -- verdicts
    unident = []
    for c in combos:
        unident.append(c["label"])
        report["reasons"][c["label"]] = c["reason"]
    for j, n in enumerate(names):
        if n in in_combo:
            continue
        e = report["intervals"][n]
        own = at_side.get(j, (None,))[0]
        open_away = [s for s in e["open"] if s != own]
        wide = (logc[j] and own != "lower" and e["low"] > 0
                and e["high"] / e["low"] > SPAN_UNIDENTIFIED)
        one_sided = (own in e["open"] and not at_side[j][1]
                     and _box_share(space, j, x, e["low"], e["high"]) >= BOX_SHARE_UNIDENTIFIED)
        if open_away or wide or one_sided or (not np.isfinite(sd[j])
                                              and "profile" not in e["method"]):
            unident.append(n)
            why = reasons.get(n)
            if why is None:
                if open_away:
                    why = (f"the cost stays within the {int(round(level * 100))} % threshold "
                           f"from the estimate to the search box's {' and '.join(open_away)} "
                           f"edge")
                elif wide:
                    why = (f"the {int(round(level * 100))} % interval spans a factor "
                           f"{e['high'] / e['low']:.3g}")
                elif one_sided:
                    why = (f"the cost stays within the {int(round(level * 100))} % threshold "
                           f"from {e['low'] if own == 'upper' else e['high']:.4g} to the "
                           f"search box's {own} edge, where the estimate sits: the data "
                           f"bound it on one side only")
                else:
                    why = "the residual does not depend on it (flat direction of the Jacobian)"
            report["reasons"][n] = why
    # generic near-collinear combinations not named above: a direction of the Jacobian
    # along which the 95 % region moves at least two members by more than their own size
    # (a factor e for a log-scale parameter)
    live = act & ~np.array([n in in_combo for n in names])
    if live.sum() >= 2:
        idx = np.flatnonzero(live)
        Jn = Jth[:, idx] / cn[idx]
        S, Vt = _singular(Jn)
        th0 = np.where(logc, np.log(np.where(logc, x, 1.0)), x)
        for i in range(S.size - 1, -1, -1):  # the flattest direction first
            if S[0] == 0:
                break
            reach = z * math.sqrt(s2) / S[i] if S[i] > 0 else np.inf
            move = np.abs(Vt[i]) * reach / cn[idx]
            rel = np.where(logc[idx], move, move / np.maximum(np.abs(th0[idx]), 1e-300))
            members = [names[idx[k]] for k in np.argsort(-np.abs(Vt[i]))
                       if rel[k] > 1.0 and abs(Vt[i, k]) > 0.2]
            covered = set(unident) | {m for u_ in unident for m in u_.split("+")}
            if len(members) < 2 or set(members) <= covered:
                continue
            lab = "+".join(members)
            if lab not in unident:
                unident.append(lab)
                report["reasons"][lab] = (
                    f"their effects on the residual nearly cancel (relative singular value "
                    f"{S[i] / S[0]:.2g}): within the {int(round(level * 100))} % region they "
                    f"move together by more than their own size")
    report["unidentified"] = unident

    # -- advice for what is open
    def has(n):
        return n in unident or any(n in u.split("+") for u in unident if "+" in u)

    if has("sigma0") or has("sigma1"):
        which = " and ".join(n for n in ("sigma0", "sigma1") if has(n))
        extra = ""
        if bi is not None and np.isfinite(bi.get("tau", np.inf)):
            extra = (f" The bristle deflection is about {_fmt(bi.get('z_ss'), 'm')} (g/sigma0); "
                     f"sample at least every {_fmt(bi['tau'] / 10, 's')} (a tenth of the "
                     f"bristle time constant) through the transients.")
        advice.append(
            f"{which} {'is' if ' and ' not in which else 'are'} not pinned by this record "
            f"({report['reasons'].get('sigma0') or report['reasons'].get('sigma1')}). Record "
            f"small-amplitude presliding: a force ramp below break-away or a displacement "
            f"sine smaller than the bristle deflection, with reversals, sampled fast; or "
            f"longer sticking phases with slow reversals.{extra}")
    if has("vs") or has("vs_neg") or has("alpha") or has("Fs") or has("Fs_neg"):
        which = [n for n in ("Fs", "Fs_neg", "vs", "vs_neg", "alpha") if has(n)]
        vs_ = getattr(p, "vs_neg" if has("vs_neg") and not has("vs") else "vs", None)
        rng = (f" (about {_fmt(vs_ / 10, 'm/s')} to {_fmt(3 * vs_, 'm/s')})") if vs_ else ""
        stick = (", and longer sticking before a slow force ramp to break-away for "
                 + " and ".join(n for n in which if n.startswith("Fs"))
                 if any(n.startswith("Fs") for n in which) else "")
        advice.append(
            f"{', '.join(which)} {'is' if len(which) == 1 else 'are'} not pinned: record "
            f"slower constant-velocity plateaus in each direction, from a tenth of the "
            f"Stribeck velocity to three times it{rng}{stick}.")
    specific = {"sigma0", "sigma1", "vs", "vs_neg", "alpha", "Fs", "Fs_neg"} | in_combo
    rest = [n for n in names if has(n) and n not in specific]
    if rest:
        what = "; ".join(f"{n}: {infos[n].description}" for n in rest if n in infos)
        advice.append(
            f"{', '.join(rest)} {'is' if len(rest) == 1 else 'are'} not pinned by this "
            f"record: fix {'it' if len(rest) == 1 else 'them'} at known values (--fix) or "
            f"record an experiment that varies what {'it acts' if len(rest) == 1 else 'they act'}"
            f" on ({what}).")
    for j, n in enumerate(names):
        if n not in report["bounds"]:
            continue
        bd = report["bounds"][n]
        if bd["kind"] == "search box":
            lo_s = f"{lo_box[j]:.4g}" if bd["side"] == "upper" else f"{lo_box[j] / 10:.4g}"
            hi_s = f"{hi_box[j] * 10:.4g}" if bd["side"] == "upper" else f"{hi_box[j]:.4g}"
            advice.append(
                f"{n} = {_fmt(val[n], units[n])} sits on the {bd['side']} edge of the search box "
                f"({_fmt(bd['bound'], units[n])}), not on a physical limit: widen the box "
                f"(--bounds {n}={lo_s}:{hi_s}) or suspect it compensates an effect the law "
                f"lacks (frictionlab diagnose).")
        else:
            hint = {"sigma2": "faster constant-velocity plateaus (a wider speed range) show "
                              "the viscous slope",
                    "sigma2_neg": "faster plateaus for v < 0 show the viscous slope",
                    "sigma1": "small-amplitude presliding shows the bristle damping"}.get(
                n, "a record that excites it")
            advice.append(
                f"{n} = {_fmt(val[n], units[n])} is at its admissible {bd['side']} limit "
                f"{_fmt(bd['bound'], units[n])}: the data ask for no more of it; fix it there "
                f"(--fix {n}={bd['bound']:g}) or record {hint}.")
    if unconverged:
        report["converged"] = False
        advice.insert(0, "The fit has not converged: a profile found a clearly lower cost "
                         "(see notes). Rerun with the default algorithm, more evaluations or "
                         "more starts; until then the flags and intervals here are "
                         "provisional.")
    else:
        report["converged"] = True
    report["evaluations"] = fit.n_evals
    report["trust_ratio"] = {names[j]: r for j, r in trust_ratio.items()}
    return report, ci
