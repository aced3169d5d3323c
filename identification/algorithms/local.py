"""Gradient-based least squares (scipy.optimize.least_squares) and its multistart variant.

The residual is the simulated minus measured force, scaled so that ``sum r^2 = nrmse^2``.
Where the objective has an analytic Jacobian (the classic LuGre: forward sensitivities of
the bristle state, :func:`friction.lugre.lugre_normal_equations`) the default algorithm
never forms the N x D Jacobian: one pass gives ``r.r``, ``J^T r`` and ``J^T J``, and
scipy's trust region runs on an equivalent residual of length D + 1
(:func:`compress_normal_equations`), so an iteration costs one pass and D x D algebra
whatever the record's length. Otherwise the Jacobian is analytic (``problem.jacobian``) or
a forward difference whose D perturbed parameter sets run as one population through the
numba kernel. Confidence intervals follow from the final Jacobian (Gauss-Newton
covariance).
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit
from scipy.optimize import least_squares

from ..problem import BudgetExhausted
from .base import Algorithm, latin_hypercube
from .trf import trf_exact

__all__ = ["LeastSquares", "MultistartLeastSquares", "run_least_squares",
           "compress_normal_equations", "forward_difference_normal_equations"]


def run_least_squares(problem, u0, *, method="trf", max_nfev=None, ftol=1e-10, xtol=1e-10,
                      gtol=1e-10, diff_step=1e-6, tr_solver="lsmr", solver="scipy",
                      x_scale="jac"):
    """Trust-region reflective least squares from ``u0`` inside the unit cube.

    ``tr_solver="lsmr"`` (default) solves the trust-region subproblems with products of the
    Jacobian only. The ``"exact"`` solver takes a dense SVD of the tall N x D Jacobian each
    iteration, which multithreaded OpenBLAS makes up to ~70 times slower on a loaded
    2-core machine (measured: 0.17 s instead of 2.4 ms for 4000 x 9).

    ``solver="normal"``: on a problem with an analytic Jacobian, the compressed run of
    :func:`compress_normal_equations` (the same trust-region model, one sensitivity pass
    per point, memory O(D^2)); otherwise (``"scipy"``) the N-long residual vector with the
    problem's Jacobian (analytic where it has one). ``x_scale``: scipy's variable scaling
    (``"jac"``: by the Jacobian's column norms).

    Returns the scipy result (``x``, ``jac``, ``fun``) or ``None`` if the budget ran out
    before the first iteration finished.

    With a checkpoint (``problem.log``) the run is one logged block: its Jacobians (D x N
    each) are too big to log, so a resume skips a finished run (result and evaluation count
    from the log, ``jac`` recomputed at ``x`` on first use: the same numbers) and reruns an
    interrupted one from ``u0``.
    """
    lm = solver == "normal" and getattr(problem, "has_analytic_jacobian", False)

    def go():
        if lm:
            return _run_normal_least_squares(problem, u0, method=method, max_nfev=max_nfev,
                                             ftol=ftol, xtol=xtol, gtol=gtol,
                                             tr_solver=tr_solver, x_scale=x_scale)
        return _run_least_squares(problem, u0, method=method, max_nfev=max_nfev, ftol=ftol,
                                  xtol=xtol, gtol=gtol, diff_step=diff_step,
                                  tr_solver=tr_solver, x_scale=x_scale)

    if getattr(problem, "log", None) is None:
        return go()
    u0 = np.asarray(u0, float)
    key = {"u0": u0, "x0": problem.space.to_physical(np.clip(u0, 0.0, 1.0)),
           "lower": problem.space.lower, "upper": problem.space.upper, "method": method,
           "max_nfev": max_nfev, "ftol": ftol, "xtol": xtol, "gtol": gtol,
           "diff_step": diff_step, "tr_solver": tr_solver}
    if x_scale != "jac":
        key["x_scale"] = x_scale
    if lm:
        key["solver"] = "normal_equations"
    live = {}

    def compute():
        res = live["res"] = go()
        if res is None:
            return {"none": True}
        return {"x": res.x, "cost": float(res.cost), "message": str(res.message),
                "status": int(res.status), "nfev": int(res.nfev),
                "success": bool(res.success)}

    out = problem.run_unit("least_squares", key, compute)
    if "res" in live:
        return live["res"]
    return None if out.get("none") else _ReplayedLeastSquares(problem, out, diff_step)


class _ReplayedLeastSquares:
    """A finished least-squares run read from a checkpoint: ``x``, ``cost``, ``message``,
    ``status``, ``nfev``, ``success`` as logged; ``jac`` recomputed at ``x`` when asked."""

    def __init__(self, problem, out, diff_step):
        self._problem, self._step = problem, diff_step
        self.x = np.asarray(out["x"], float)
        self.cost = float(out["cost"])
        self.message, self.status = out["message"], out["status"]
        self.nfev, self.success = out["nfev"], out["success"]
        self._jac = None

    @property
    def jac(self):
        if self._jac is None:
            self._jac = self._problem.jacobian_uncounted(self.x, step=self._step)
        return self._jac


def compress_normal_equations(c2, g, H):
    """A residual vector of length D + 1 and its D + 1 x D Jacobian with the same
    Gauss-Newton model as a long residual ``r`` (length N) with Jacobian ``J``, from
    ``c2 = r.r``, ``g = J^T r``, ``H = J^T J`` alone.

    With ``H = R^T R`` (eigen-decomposition of the column-scaled ``H``; directions of
    relative eigenvalue below 1e-14 dropped), ``Q = J R^-1`` spans the columns of ``J``:
    the short residual is ``[Q^T r, sqrt(c2 - |Q^T r|^2)]`` and its Jacobian ``[R; 0]``.
    Its squared norm is ``c2``, and ``R^T R = H``, ``[R; 0]^T [Q^T r, .] = g``: a
    trust-region method sees the same cost, gradient and quadratic model as on the long
    residual.
    """
    return _compress(float(c2), np.ascontiguousarray(g, float),
                     np.ascontiguousarray(H, float))


@njit(cache=True, nogil=True)
def _compress(c2, g, H):
    D = g.size
    d = np.empty(D)
    for i in range(D):
        d[i] = math.sqrt(H[i, i]) if H[i, i] > 0.0 else 1.0
    Hs = np.empty((D, D))
    for i in range(D):
        for j in range(D):
            Hs[i, j] = 0.5 * (H[i, j] + H[j, i]) / (d[i] * d[j])
    w, V = np.linalg.eigh(Hs)
    floor = max(w[D - 1], 0.0) * 1e-14
    f = np.empty(D + 1)
    Jc = np.zeros((D + 1, D))
    qq = 0.0
    for k in range(D):
        if w[k] > floor:
            sw = math.sqrt(w[k])
            a = 0.0
            for i in range(D):
                a += V[i, k] * g[i] / d[i]
            f[k] = a / sw
            qq += f[k] * f[k]
            for j in range(D):
                Jc[k, j] = sw * V[j, k] * d[j]
        else:
            f[k] = 0.0
    f[D] = math.sqrt(max(c2 - qq, 0.0))
    return f, Jc


def _run_normal_least_squares(problem, u0, *, method, max_nfev, ftol, xtol, gtol,
                              tr_solver="lsmr", x_scale="jac"):
    """``scipy.optimize.least_squares`` on the compressed residual of
    :func:`compress_normal_equations`: each point costs one forward-sensitivity pass
    (:meth:`identification.problem.Problem.normal_equations`, which gives the Jacobian too)
    and the trust-region algebra is D + 1 x D instead of N x D."""
    cache = {}
    n = len(problem.objective.data.F) if hasattr(problem.objective, "data") else 1

    def at(u):
        key = np.asarray(u, float).tobytes()
        if key not in cache:
            cache.clear()
            c2, g, H = problem.normal_equations(u)
            if not np.isfinite(c2):
                # as the long residual's 1e3 per non-finite sample: a huge cost
                f = np.zeros(g.size + 1)
                f[-1] = 1e3 * np.sqrt(n)
                cache[key] = (f, np.zeros((g.size + 1, g.size)))
            else:
                cache[key] = compress_normal_equations(c2, g, H)
        return cache[key]

    u0 = np.clip(np.asarray(u0, float), 1e-9, 1 - 1e-9)
    if u0.size == 1:
        tr_solver = "exact"  # scipy's lsmr subproblem indexes a 2-D subspace: one parameter fails
    try:
        if method == "trf" and tr_solver == "exact" and not isinstance(x_scale, str) \
                and np.all(np.asarray(x_scale) == 1.0):
            # scipy's algorithm with its D + 1 x D algebra compiled (the same iterates;
            # scipy's Python bookkeeping cost more than the sensitivity passes on 10,000
            # samples)
            ones = np.ones(u0.size)
            res = trf_exact(at, u0, 0.0 * ones, ones, ftol=ftol, xtol=xtol, gtol=gtol,
                            max_nfev=max_nfev, stop=_converged_within(n))
        else:
            res = least_squares(lambda u: at(u)[0], u0, jac=lambda u: at(u)[1],
                                bounds=(0.0, 1.0), method=method, x_scale=x_scale,
                                ftol=ftol, xtol=xtol, gtol=gtol, max_nfev=max_nfev,
                                tr_solver=tr_solver)
    except BudgetExhausted:
        return None
    return _NormalResult(problem, res)


#: a compressed run ends where the Gauss-Newton model of the long residual promises less
#: than this fraction of one parameter standard error's cost (``c2 / N``): the remaining
#: moves are below 1 % of a standard error (sqrt(1e-4)); scipy's own tests spend one or
#: two more sensitivity passes there
MODEL_REDUCTION_SE2 = 1e-4


def _converged_within(n):
    """The ``stop`` test of :func:`identification.algorithms.trf.trf_exact` on a
    compressed residual ``f = [Q^T r, rest]`` of an ``n``-sample record: the Gauss-Newton
    step's reduction of ``0.5 |r|^2`` is ``0.5 |Q^T r|^2`` (an upper bound of what the box
    allows); below :data:`MODEL_REDUCTION_SE2` / n of the cost the run has converged."""
    tol = MODEL_REDUCTION_SE2 / max(n, 1)

    def stop(f, J, cost):
        gain = 0.5 * float(np.dot(f[:-1], f[:-1]))
        if cost > 0 and gain <= tol * cost:
            return (f"the Gauss-Newton model promises {gain / cost:.1e} of the cost "
                    f"(< {MODEL_REDUCTION_SE2:g}/N: under 1 % of a standard error)")
        return None
    return stop


#: rows of a stored float32 Jacobian turned into float64 at a time for ``J^T J``
_NE_ROWS = 65536


def forward_difference_normal_equations(residual, u, r0=None, cols=None, step=1e-6,
                                        out=None):
    """``(r.r, J^T r, J^T J)`` of ``residual`` at ``u`` with ``J`` a forward difference
    over the coordinates ``cols`` (default all), held in float32 and reduced in float64
    blocks of rows: memory N x len(cols) x 4 bytes, not the several float64 copies a
    least-squares solver keeps of an N x D Jacobian.

    Parameters
    ----------
    residual : callable(u) -> ndarray, shape (N,)
        Residual vector (non-finite entries count as 0 in ``J``).
    u : ndarray, shape (D,)
        Point in the unit cube.
    r0 : ndarray, shape (N,), optional
        ``residual(u)`` if already computed.
    cols : sequence of int, optional
        Coordinates differentiated (the columns of ``J``, in this order).
    step : float
        Forward step in cube coordinates (inward at the upper face; scipy's 2-point
        ``diff_step`` rule for coordinates in [0, 1]).
    out : ndarray, shape (N, len(cols)), float32, optional
        Reused storage for ``J``.

    Returns
    -------
    (float, ndarray, ndarray, ndarray)
        ``r.r``, ``J^T r``, ``J^T J`` and the float32 ``J`` (for reuse as ``out``). The
        float32 entries carry the differences' own error (~1e-8 relative at this step),
        near float32's 6e-8: the Gauss-Newton model is unchanged for a trust region.
    """
    u = np.asarray(u, float)
    cols = list(range(u.size)) if cols is None else list(cols)
    r0 = np.asarray(residual(u) if r0 is None else r0, float)
    N, k = r0.size, len(cols)
    J = out if out is not None and out.shape == (N, k) else np.empty((N, k), np.float32)
    for c, j in enumerate(cols):
        h = step if u[j] + step <= 1.0 else -step
        uj = u.copy()
        uj[j] = u[j] + h
        h = uj[j] - u[j]  # the difference the floats represent
        J[:, c] = (np.asarray(residual(uj), float) - r0) / h
    r0f = np.where(np.isfinite(r0), r0, 0.0)
    g = np.zeros(k)
    H = np.zeros((k, k))
    for i in range(0, N, _NE_ROWS):
        Jb = J[i:i + _NE_ROWS].astype(np.float64)
        Jb[~np.isfinite(Jb)] = 0.0
        H += Jb.T @ Jb
        g += Jb.T @ r0f[i:i + _NE_ROWS]
    return float(np.dot(r0, r0)), g, H, J


def _jacobian_of(res):
    """``res.jac``, or a callable giving it where it is computed on demand (the analytic
    N x D Jacobian of a compressed run): the driver computes it only for intervals."""
    if isinstance(res, _NormalResult) and res._jac is None:
        return lambda: res.jac
    return res.jac


class _NormalResult:
    """scipy's result of a compressed run with the fields the algorithms read (``x``,
    ``cost``, ``nfev``, ``status``, ``message``, ``success``); ``jac`` is the long
    residual's N x D Jacobian (for intervals), computed analytically at ``x`` when first
    asked."""

    def __init__(self, problem, res):
        self._problem = problem
        self.x, self.cost, self.nfev = res.x, float(res.cost), int(res.nfev)
        self.status, self.message, self.success = int(res.status), res.message, res.success
        self._jac = None

    @property
    def jac(self):
        if self._jac is None:
            self._jac = self._problem.jacobian_uncounted(self.x)
        return self._jac


def _run_least_squares(problem, u0, *, method, max_nfev, ftol, xtol, gtol, diff_step,
                       tr_solver, x_scale="jac"):
    cache = {}

    def fun(u):
        r = problem.residuals(u)
        cache["u"], cache["r"] = np.array(u), r
        return r

    def jac(u):
        r0 = cache["r"] if "u" in cache and np.array_equal(cache["u"], u) else None
        return problem.jacobian(u, r0=r0, step=diff_step)

    u0 = np.clip(np.asarray(u0, float), 1e-9, 1 - 1e-9)
    if u0.size == 1:
        tr_solver = "exact"  # scipy's lsmr subproblem indexes a 2-D subspace: one parameter fails
    try:
        return least_squares(fun, u0, jac=jac, bounds=(0.0, 1.0), method=method,
                             x_scale=x_scale, ftol=ftol, xtol=xtol, gtol=gtol,
                             max_nfev=max_nfev, tr_solver=tr_solver)
    except BudgetExhausted:
        return None


def noise_level(F) -> float:
    """The white-noise RMS of a sampled signal relative to its standard deviation, from the
    median absolute deviation of its second differences (``F[k+1] - 2 F[k] + F[k-1]``
    carries 6 times the noise variance and little of a signal sampled faster than it
    changes; the median ignores the few samples of fast transients, such as reversals)."""
    F = np.ascontiguousarray(F, dtype=float)
    if F.size < 5:
        return np.nan
    return float(_noise_level(F))


@njit(cache=True, nogil=True)
def _noise_level(F):
    """:func:`noise_level` compiled (one pass for the second differences, two selections
    for the medians; numpy's calls cost more than the work on 10,000 samples)."""
    sd = np.std(F)
    if not sd > 0:
        return np.nan
    n = F.size - 2
    d2 = np.empty(n)
    for k in range(n):
        d2[k] = F[k + 2] - 2.0 * F[k + 1] + F[k]
    med = _median(d2)
    for k in range(n):
        d2[k] = abs(d2[k] - med)
    return 1.4826 * _median(d2) / math.sqrt(6.0) / sd


@njit(cache=True, nogil=True)
def _median(a):
    """``np.median`` of a finite 1-D array, exactly, by counting: a histogram of 2048
    bins over [min, max] (the bin index is monotone in the value, so the bins keep the
    order) finds the bin(s) holding the middle rank(s), and only their values are sorted.
    Two passes of arithmetic instead of a selection's data-dependent branches (0.13
    instead of 0.23 ms for the two medians of a 10,000-sample noise level)."""
    n = a.size
    lo = a.min()
    hi = a.max()
    if lo == hi:
        return lo
    nb = 2048
    sc = nb / (hi - lo)
    counts = np.zeros(nb, np.int64)
    for x in a:
        counts[min(int((x - lo) * sc), nb - 1)] += 1
    k1 = (n - 1) // 2
    k2 = n // 2
    c = 0
    b1 = -1
    b2 = -1
    below = 0
    for b in range(nb):
        if b1 < 0 and c + counts[b] > k1:
            b1 = b
            below = c
        if c + counts[b] > k2:
            b2 = b
            break
        c += counts[b]
    m = 0
    for b in range(b1, b2 + 1):
        m += counts[b]
    buf = np.empty(m)
    j = 0
    for x in a:
        b = min(int((x - lo) * sc), nb - 1)
        if b >= b1 and b <= b2:
            buf[j] = x
            j += 1
    buf.sort()
    return 0.5 * (buf[k1 - below] + buf[k2 - below])


def at_noise_floor(problem, cost):
    """A short reason if ``cost`` (NRMSE) equals the measured force's noise level
    (:func:`noise_level`) within the estimate's statistical spread (2.5/sqrt(N); at least
    2 %), else ``None``. Below the band the estimate is the signal's curvature, not noise
    (noise-free data): no conclusion."""
    data = getattr(problem.objective, "data", None)
    if data is None or not hasattr(data, "t"):
        return None  # not a time series (a steady-state map): no noise estimate
    F = np.asarray(data.F, float)
    level = noise_level(F)
    if not (np.isfinite(level) and level > 0 and np.isfinite(cost)):
        return None
    tol = max(0.02, 2.5 / np.sqrt(F.size))
    if abs(cost / level - 1.0) <= tol:
        return f"NRMSE {cost:.4g}, noise {level:.4g}"
    return None


#: above this size of the N x D Jacobian (8 bytes a number) the default runs every least
#: squares on the normal equations (scipy's trust region on the long residual holds several
#: copies of the Jacobian: about 1 GB at 2,000,000 samples and 8 parameters)
LONG_JACOBIAN_BYTES = 64 * 2**20


class LeastSquares(Algorithm):
    """``scipy.optimize.least_squares`` (trust-region reflective, bounded) from the model's
    current values. Fast and precise near the optimum; local."""
    name = "least_squares"
    kind = "local"
    steppable = False
    checkpointable = False
    no_checkpoint = ("it is one scipy least-squares run, which cannot be resumed part-way; "
                     "multistart_ls (the default) resumes after each of its starts")
    defaults = dict(max_nfev=200, ftol=1e-10, xtol=1e-10, gtol=1e-10, tr_solver="lsmr")
    source = "scipy.optimize.least_squares (Branch, Coleman, Li 1999 TRF)"

    def run(self, problem, rng, u0, progress=None):
        res = run_least_squares(problem, u0, max_nfev=self.max_nfev, ftol=self.ftol,
                                xtol=self.xtol, gtol=self.gtol, tr_solver=self.tr_solver)
        if progress is not None:
            progress(1, f"cost={problem.best_cost:.4g}")
        if res is None:
            return {"message": "evaluation budget exhausted"}
        return {"jac": res.jac, "u": res.x, "message": res.message, "history": [problem.best_cost]}


class MultistartLeastSquares(Algorithm):
    """Latin-hypercube screening in one population call, a full least-squares run from the
    best screened point (or the model's current values if better), then short runs from the
    next best starts; a start that beats the first is polished in full.

    Fast where one basin dominates (the first run converges and the trace reaches the optimum
    early) and robust where the LuGre family has a few basins (Stribeck velocity vs.
    stiffness trade-off): the extra starts check them.

    With an analytic Jacobian (the classic LuGre's forward sensitivities) the model's
    current values are tried first (``solver="auto"``): a run of at most ``probe_nfev``
    passes on the compressed normal equations (:func:`compress_normal_equations`: one
    sensitivity pass per point, D x D algebra, the exact trust-region subproblem in the unit
    cube's own scale). A run that converges to the data's noise level
    (:func:`at_noise_floor`; or below ``target``) with no parameter on a face of the box
    ends the search: no other basin can fit measurably better, so neither the screening nor
    the other starts run. Otherwise the search runs as above, its least squares on the
    N-long residual with the analytic Jacobian (the previous default's steps, without its
    finite differences). The noise-level test after the first full run skips the other
    starts too (``noise_stop=False``: never stop early). ``solver="normal"``: every run on
    the compressed normal equations (memory O(D^2) for any record length; its steps differ
    from the long residual's where scipy's iterative subproblem solver stops early);
    ``"scipy"``: no start from the guess, the long residual everywhere. A record whose
    N x D Jacobian exceeds :data:`LONG_JACOBIAN_BYTES` (1,000,000 samples at 8 parameters)
    runs as ``"normal"`` under ``"auto"``: its memory stays O(N), not O(N D) per copy.
    """
    name = "multistart_ls"
    kind = "local"
    steppable = False
    defaults = dict(n_screen=None, n_starts=3, max_nfev=15, ftol=1e-10, xtol=1e-10,
                    gtol=1e-10, polish_nfev=200, target=1e-9, tr_solver="lsmr",
                    solver="auto", noise_stop=True, probe_nfev=20)
    #: where each run's least squares works: (the start from the guess, the other runs)
    SOLVERS = {"auto": ("normal", "scipy"), "normal": ("normal", "normal"),
               "scipy": (None, "scipy")}
    source = ("Latin hypercube (scipy.stats.qmc) + scipy.optimize.least_squares (analytic "
              "LuGre Jacobian; its normal equations for the start from the guess)")

    def _ls(self, problem, u, nfev):
        return run_least_squares(problem, u, max_nfev=nfev, ftol=self.ftol, xtol=self.xtol,
                                 gtol=self.gtol, tr_solver=self.tr_solver,
                                 solver=self._solvers(problem)[1])

    def _solvers(self, problem):
        try:
            pair = self.SOLVERS[self.solver]
        except KeyError:
            raise ValueError(f"solver = {self.solver!r}: choose from "
                             f"{sorted(self.SOLVERS)}") from None
        if self.solver == "auto" and getattr(problem, "has_analytic_jacobian", False):
            data = getattr(problem.objective, "data", None)
            n = len(data.F) if data is not None else 0
            if 8 * n * problem.dim > LONG_JACOBIAN_BYTES:
                # a long record: the N x D Jacobian (and scipy's copies of it) would dominate
                # the memory; every run on the normal equations instead
                return self.SOLVERS["normal"]
        return pair

    def _settled(self, problem, res):
        """Why the search may stop at ``res`` (None: it may not)."""
        if problem.best_cost < self.target:
            return f"cost below {self.target:g}"
        if not self.noise_stop or res.status <= 0:
            return None
        x = np.asarray(res.x, float)
        if np.any((x <= 1e-6) | (x >= 1 - 1e-6)):
            return None  # a parameter on the box: the basin may be the box's, not the data's
        return at_noise_floor(problem, problem.best_cost)

    def run(self, problem, rng, u0, progress=None):
        D = problem.dim
        n_screen = self.n_screen or max(64, 16 * D)
        u0 = np.clip(np.asarray(u0, float), 0, 1)
        history = []
        if self.probe_nfev and self._solvers(problem)[0] \
                and getattr(problem, "has_analytic_jacobian", False):
            # the guess first, with the exact (D x D) trust-region subproblem (cheapest per
            # iteration) in the unit cube's own scale (x_scale=1: a trust region scaled by
            # the Jacobian's column norms would stretch along nearly flat directions and
            # carry such a parameter to the box); kept only if it settles (then no other
            # basin fits measurably better), otherwise the search below runs as it would
            # without it
            probe = run_least_squares(problem, u0, max_nfev=self.probe_nfev, ftol=self.ftol,
                                      xtol=self.xtol, gtol=self.gtol, tr_solver="exact",
                                      solver=self._solvers(problem)[0], x_scale=1.0)
            history.append(problem.best_cost)
            if probe is None:
                return {"message": "evaluation budget exhausted", "history": history}
            why = self._settled(problem, probe)
            if why is not None:
                if progress is not None:
                    progress(1, f"start from the guess cost={problem.best_cost:.4g} ({why}): "
                                f"done")
                return {"jac": _jacobian_of(probe), "u": probe.x, "history": history,
                        "message": f"{probe.message} Search ended after the start from the "
                                   f"guess: {why}."}
        U = np.vstack([u0[None, :], latin_hypercube(n_screen, D, rng)])
        try:
            c = problem.evaluate(U)
        except BudgetExhausted:
            return {"message": "evaluation budget exhausted during screening",
                    "history": history}
        history.append(problem.best_cost)
        order = [int(i) for i in np.argsort(c, kind="stable")]
        if 0 not in order[:self.n_starts + 1]:
            order = order[:self.n_starts] + [0]  # the user's guess is always tried
        best = self._ls(problem, U[order[0]], self.polish_nfev)
        history.append(problem.best_cost)
        n_total = len(order[:self.n_starts + 1])
        if progress is not None:
            progress(1, f"start 1/{n_total} cost={problem.best_cost:.4g}")
        if best is None:
            return {"message": "evaluation budget exhausted", "history": history}
        skip = self._settled(problem, best)
        for k, i in enumerate(order[1:self.n_starts + 1], start=2):
            if problem.best_cost < self.target or problem.exhausted:
                break  # exact fit already: the other starts add nothing
            if skip is not None:
                # the first run converged to the data's noise level: no other basin can
                # fit measurably better
                if progress is not None:
                    progress(1, f"other starts skipped: {skip}")
                break
            res = self._ls(problem, U[i], self.max_nfev)
            if res is not None and res.cost < best.cost * (1 - 1e-6):
                res = self._ls(problem, res.x, self.polish_nfev) or res  # a better basin
                if res.cost < best.cost:
                    best = res
            history.append(problem.best_cost)
            if progress is not None:
                progress(1, f"start {k}/{n_total} cost={problem.best_cost:.4g}")
        return {"jac": _jacobian_of(best), "u": best.x, "message": best.message,
                "history": history}
