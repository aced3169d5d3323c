"""Structure-exploiting identification of the seeds 003 and 004.

* :class:`AlternatingLeastSquares` (seed 003, Eqs. 8-10): the LuGre force is linear in
  ``theta_L = [sigma0, sigma1, sigma2, b]`` once the bristle state is known, and the state
  depends only on ``theta_NL = [a1, a2, vs]`` (``a1 = Fc/sigma0``, ``a2 = (Fs - Fc)/sigma0``,
  deflection units). After a two-step initialisation (Stribeck fit + pre-sliding stiffness),
  ``k`` alternations of a bounded Levenberg-Marquardt step on ``theta_NL`` (theta_L fixed)
  and a constrained linear least squares on ``theta_L`` (state fixed) refine the model inside
  ``Theta(delta)``.
* :class:`StaticLeastSquares` (seed 004, Eqs. 14-18): the no-load Stribeck parameters
  ``Phi = [Fc0, Fs0, vs, sigma20]`` by nonlinear least squares on constant-speed no-load
  samples (Eq. 16), then the load coefficients ``K = [k1, k2, k3]`` per velocity regime from
  the linear system (Eq. 18) of the loaded constant-speed samples (least squares when there
  are more than three).
"""
from __future__ import annotations

import numpy as np
from scipy.optimize import least_squares, lsq_linear

from friction.shapes import stribeck_g_np

from .base import Algorithm

__all__ = ["AlternatingLeastSquares", "StaticLeastSquares", "stribeck_fit", "quasi_steady",
           "ALGORITHM_CLASSES"]


def quasi_steady(data, accel_tol: float | None = None, v_min: float | None = None):
    """Boolean mask of samples near constant speed (plateaus): small |a|, |v| away from 0."""
    a, v = np.abs(data.a), np.abs(data.v)
    if accel_tol is None:
        accel_tol = 0.05 * np.percentile(a, 99) + 1e-12
    if v_min is None:
        v_min = 0.02 * np.percentile(v, 99)
    return (a <= accel_tol) & (v >= v_min)


def stribeck_fit(v, F, shape: str = "gaussian", alpha: float = 2.0, x0=None,
                 offset: bool = True):
    """Nonlinear least-squares Stribeck fit ``F = g(v) sgn(v) + sigma2 v + b`` (seed 003 Eq. 6,
    seed 004 Eq. 8). Returns dict Fc, Fs, vs, sigma2, b.

    ``offset=False`` fixes ``b = 0`` (Eq. 8; also needed when all speeds have one sign, where
    b and Fc cannot be told apart)."""
    v, F = np.asarray(v, float), np.asarray(F, float)
    sv = max(np.percentile(np.abs(v), 95), 1e-12)
    sF = max(np.percentile(np.abs(F), 95), 1e-12)
    vmin = max(np.min(np.abs(v[v != 0])) if np.any(v != 0) else sv * 1e-3, sv * 1e-4)

    def model(p):
        Fc, dF, lvs, s2, b = p
        vs = np.exp(lvs)
        return stribeck_g_np(v, Fc, Fc + dF, vs, alpha, shape) * np.sign(v) + s2 * v + b

    if x0 is None:
        x0 = [0.5 * sF, 0.2 * sF, np.log(max(vmin * 3, sv * 0.05)), 0.3 * sF / sv, 0.0]
    lo = [0.0, 0.0, np.log(vmin * 0.1), 0.0, -sF]
    hi = [2 * sF, 2 * sF, np.log(sv * 2), 10 * sF / sv, sF]
    if not offset:  # b pinned at 0: an (almost) empty interval keeps the solver's shape
        x0 = list(x0)
        x0[4], lo[4], hi[4] = 0.0, -1e-12 * sF, 1e-12 * sF
    x0 = np.clip(x0, np.array(lo) + 1e-15 * sF, np.array(hi) - 1e-15 * sF)
    best = None
    for lvs0 in (x0[2], np.log(sv * 0.01), np.log(sv * 0.1), np.log(max(vmin, sv * 1e-3))):
        start = np.array(x0, float)
        start[2] = np.clip(lvs0, lo[2] + 1e-9, hi[2] - 1e-9)
        r = least_squares(lambda p: model(p) - F, start, bounds=(lo, hi), method="trf")
        if best is None or r.cost < best.cost:
            best = r
    Fc, dF, lvs, s2, b = best.x
    return {"Fc": float(Fc), "Fs": float(Fc + dF), "vs": float(np.exp(lvs)), "sigma2": float(s2),
            "b": float(b), "cost": float(best.cost)}


class AlternatingLeastSquares(Algorithm):
    """Seed 003: two-step initialisation, then ``k`` alternations of nonlinear (LM on
    ``[a1, a2, vs]``) and linear (bounded least squares on ``[sigma0, sigma1, sigma2, b]``)
    updates inside ``Theta(delta)``.

    Options
    -------
    k : int
        Number of alternations (paper: 5).
    delta : float
        Tolerance of ``Theta(delta)`` around the initial estimates (paper: 0.5).
    init : dict, optional
        Initial estimates (e.g. from the XML-350 protocol: Stribeck fit on trapezoid plateaus
        and sigma0/sigma1 from the PRBS transfer function). Missing entries: Stribeck
        parameters from the quasi-steady samples of the data, sigma0/sigma1 from the model.
    vs_range : (float, float)
        Fixed range of vs (paper: 1e-5 to 1e-2 m/s).
    """
    name = "alternating_ls"
    kind = "local"
    steppable = False
    defaults = dict(k=5, delta=0.5, init=None, vs_range=(1e-5, 1e-2), nl_max_nfev=50)
    source = "seed 003 Eqs. 8-10, Theta(delta); two-step initialisation of ref. [4]"
    required = ("sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs", "b")

    def _initial(self, model, data):
        p = model.params
        init = dict(self.init or {})
        if not {"Fc", "Fs", "vs", "sigma2"} <= set(init):
            m = quasi_steady(data)
            if m.sum() < 10:
                raise ValueError("alternating_ls: the data have fewer than 10 quasi-steady "
                                 "samples for the Stribeck initialisation; pass init={...}")
            fit = stribeck_fit(data.v[m], data.F[m], p.shape, p.alpha)
            for key in ("Fc", "Fs", "vs", "sigma2", "b"):
                init.setdefault(key, fit[key])
        init.setdefault("sigma0", p.sigma0)
        init.setdefault("sigma1", p.sigma1)
        init.setdefault("b", p.b)
        return init

    def run(self, problem, rng, u0, progress=None):
        obj = problem.objective
        model, data = obj.model, obj.data
        if model.name != "lugre" or any(getattr(model.params, n + "_neg", None) is not None
                                        for n in ("Fc", "Fs", "vs", "sigma2")):
            raise ValueError("alternating_ls needs the symmetric classic 'lugre' law")
        if set(problem.space.names) != set(self.required):
            raise ValueError(f"alternating_ls identifies exactly {list(self.required)}; "
                             f"call identify(..., names={list(self.required)})")
        p = model.params
        init = self._initial(model, data)
        d = self.delta
        s0, s1, s2, b = (init["sigma0"], init["sigma1"], init["sigma2"], init["b"])
        a1, a2 = init["Fc"] / s0, max(init["Fs"] - init["Fc"], 1e-9 * init["Fc"]) / s0
        vs = float(np.clip(init["vs"], *self.vs_range))
        box_L = (np.array([(1 - d) * s0, (1 - d) * max(s1, 1e-12), (1 - d) * s2,
                           -d * init["Fs"]]),
                 np.array([(1 + d) * s0, (1 + d) * max(s1, 1e-12), (1 + d) * max(s2, 1e-12),
                           d * init["Fs"]]))
        box_NL = (np.array([(1 - d) * a1, (1 - d) * a2, np.log(self.vs_range[0])]),
                  np.array([(1 + d) * a1, (1 + d) * a2, np.log(self.vs_range[1])]))
        names = ["sigma0", "sigma1", "sigma2", "b", "Fc", "Fs", "vs"]
        t, v, F = data.t, data.v, data.F
        counter = [0]

        def states(a1_, a2_, vs_):
            """Bristle state z [m] and dz/dt for the NL parameters (F = z with sigma0 = 1)."""
            X = np.array([[1.0, 0.0, 0.0, 0.0, a1_, a1_ + a2_, vs_]])
            z = model.simulate_population(t, v, names, X)[0]
            counter[0] += 1
            g = stribeck_g_np(v, a1_, a1_ + a2_, vs_, p.alpha, p.shape)
            return z, v - np.abs(v) / g * z

        def force(L, nl):
            z, zd = states(nl[0], nl[1], np.exp(nl[2]))
            return L[0] * z + L[1] * zd + L[2] * v + L[3]

        L = np.array([s0, s1, s2, b])
        nl = np.clip(np.array([a1, a2, np.log(vs)]), box_NL[0], box_NL[1])
        L = np.clip(L, box_L[0], box_L[1])
        history = []
        sd = np.std(F)

        def alternate(L, nl):
            counter[0] = 0
            # nonlinear step: theta_NL with theta_L fixed (bounded LM-type trust region)
            r = least_squares(lambda q: (force(L, q) - F) / sd, nl, bounds=box_NL,
                              method="trf", x_scale=np.maximum(np.abs(nl), 1e-12),
                              max_nfev=self.nl_max_nfev, diff_step=1e-6)
            nl = r.x
            # linear step: theta_L with the state fixed (constrained linear least squares)
            z, zd = states(nl[0], nl[1], np.exp(nl[2]))
            A = np.column_stack([z, zd, v, np.ones_like(v)])
            col = np.maximum(np.abs(A).max(axis=0), 1e-300)  # column scaling for conditioning
            sol = lsq_linear(A / col, F, bounds=(box_L[0] * col, box_L[1] * col))
            L = sol.x / col
            cost = float(np.sqrt(np.mean((A @ L - F) ** 2)) / sd)
            problem.n_evals += counter[0]
            return {"L": L, "nl": nl, "cost": cost}

        for i in range(self.k):
            # one alternation depends on (L, nl) only: the unit a checkpoint logs and skips
            out = problem.run_unit(
                "alternation", {"i": i, "L": L, "nl": nl, "box_L": box_L, "box_NL": box_NL},
                lambda: alternate(L, nl))
            L, nl = np.asarray(out["L"], float), np.asarray(out["nl"], float)
            cost = float(out["cost"])
            history.append(cost)
            if progress is not None:
                progress(1, f"alternation {i + 1}/{self.k} cost={cost:.4g}")
        s0f = L[0]
        final = {"sigma0": s0f, "sigma1": L[1], "sigma2": L[2], "b": L[3],
                 "Fc": nl[0] * s0f, "Fs": (nl[0] + nl[1]) * s0f, "vs": float(np.exp(nl[2]))}
        x = np.array([final[n] for n in problem.space.names])
        u = problem.space.to_unit(x)
        if np.any(u < -1e-9) or np.any(u > 1 + 1e-9):
            # Theta(delta) may leave the identify() box: widen the box to hold the result
            problem.space.lower = np.minimum(problem.space.lower, x)
            problem.space.upper = np.maximum(problem.space.upper, x * (1 + 1e-12) + 1e-300)
            u = problem.space.to_unit(x)
        problem.evaluate(u[None, :])
        return {"message": f"{self.k} alternations in Theta(delta={d})", "history": history,
                "init": init}


class StaticLeastSquares(Algorithm):
    """Seed 004: static parameters of the load-dependent LuGre from constant-speed samples.

    The no-load samples (``load <= load_tol``) give ``Phi = [Fc0, Fs0, vs, sigma20]`` by
    nonlinear least squares (Eq. 16); the loaded samples, split at the no-load critical
    velocity, give ``[k1, k2, k3]`` per regime by the linear system of Eq. 18
    (``(1 - xi) F_sigma k1 + xi F_sigma k2 + v F_sigma k3 = F - Fc0 (1 - xi) - Fs0 xi -
    sigma20 v`` with ``xi = exp(-(v/vs)^2)``). sigma0 and sigma1 stay at the model's values.
    """
    name = "static_ls"
    kind = "local"
    steppable = False
    checkpointable = False
    no_checkpoint = "it is one closed-form static fit (seconds), with nothing to resume"
    defaults = dict(load_tol=None, accel_tol=None)
    source = "seed 004 Eqs. 8, 14-18"

    def run(self, problem, rng, u0, progress=None):
        from friction.load_lugre import critical_velocity
        obj = problem.objective
        model, data = obj.model, obj.data
        if model.name != "load_lugre":
            raise ValueError("static_ls needs the 'load_lugre' law (seed 004)")
        if data.load is None:
            raise ValueError("static_ls needs a load column (deformation load F_sigma [N])")
        m = quasi_steady(data, accel_tol=self.accel_tol)
        v, F, Fl = np.abs(data.v[m]), np.abs(data.F[m]), data.load[m]
        tol = self.load_tol if self.load_tol is not None else 1e-6 * max(np.max(np.abs(Fl)), 1.0)
        free = np.abs(Fl) <= tol
        if free.sum() < 4:
            raise ValueError("static_ls: fewer than 4 no-load constant-speed samples for Phi")
        fit = stribeck_fit(v[free], F[free], offset=False)
        Fc0, Fs0, vs, s20 = fit["Fc"], fit["Fs"], fit["vs"], fit["sigma2"]
        out = {"Fc0": Fc0, "Fs0": Fs0, "vs": vs, "sigma20": s20}
        vc = critical_velocity(Fc0, Fs0, vs, s20)
        if not np.isfinite(vc):
            vc = np.inf
        loaded = ~free
        for regime, sel in (("low", loaded & (v < vc)), ("high", loaded & (v >= vc))):
            if sel.sum() < 3:
                continue
            xi = np.exp(-(v[sel] / vs) ** 2)
            Fs_ = Fl[sel]
            A = np.column_stack([(1 - xi) * Fs_, xi * Fs_, v[sel] * Fs_])  # Eq. 18
            rhs = F[sel] - Fc0 * (1 - xi) - Fs0 * xi - s20 * v[sel]
            K, *_ = np.linalg.lstsq(A, rhs, rcond=None)
            out.update({f"k1_{regime}": K[0], f"k2_{regime}": K[1], f"k3_{regime}": K[2]})
        names = problem.space.names
        x = np.array([out.get(n, getattr(model.params, n)) for n in names], float)
        problem.space.lower = np.minimum(problem.space.lower, x)
        problem.space.upper = np.maximum(problem.space.upper, x)
        problem.evaluate(problem.space.to_unit(x)[None, :])
        return {"message": f"static fit (Eq. 16) + linear system (Eq. 18); vc = {vc:.3g} m/s",
                "static": out, "vc": vc}


ALGORITHM_CLASSES = (AlternatingLeastSquares, StaticLeastSquares)
