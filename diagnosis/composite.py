"""A base friction law plus a stack of candidate effects, fitted jointly by least squares.

The parameter vector is ``[base law parameters (unit cube, log where the law says so),
candidate extras (unit cube over their physical box)]``; the residual is
``(F_measured - F_model) / std(F_measured)``. The law is simulated with its compiled kernel
(one call per evaluation), so a 20,000-sample fit takes a fraction of a second.

The Jacobian of a fit with an effect that has exact derivative columns (the position map's
knot values and amplitudes) is assembled by :func:`_stacked_jacobian`:
the law's columns by forward differences of the law's force alone, carried through the
effects by their derivative with respect to the force (:meth:`diagnosis.candidates.
Candidate.jac`), the effects' own columns exact where the candidate gives them, else
differences of that effect alone on the law's force as simulated: the columns of scipy's
``"2-point"`` differences of the whole residual (to rounding), without a simulation of the
law for each of the effects' columns or the whole stack evaluated for each column.

An effect with an ``inside`` hook (``inside(p, data, ctx) -> level`` [-], e.g. the
``stribeck_shape`` speed map) scales the law's friction levels *inside* its bristle
dynamics (a LuGre law's :meth:`friction.lugre.LuGre.simulate_level`): its extras change the
law's simulation, so they are differenced with the law's parameters.
"""
from __future__ import annotations

import contextlib
import contextvars
import time
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import least_squares

from friction.base import FrictionModel
from friction.lugre import lugre_level_run
from friction.steps import split_at_reversals
from identification.space import ParameterSpace

from .candidates import Candidate, Context, Fixed

__all__ = ["Composite", "fit_composite", "law_space", "reporting", "simulate_split", "STATIC_LEVELS",
           "STATIC_LEVEL_SPAN", "LONG_JACOBIAN_BYTES", "STRUCTURED_JACOBIAN"]

_STAGE_ORDER = {"modify_law": 0, "multiplicative": 1, "additive": 2, "shift": 3}
#: stages that act on the law's force (a ``modify_law`` effect acts through the law)
_FORCE_STAGES = ("multiplicative", "additive", "shift")

#: relative step of the forward differences of a joint fit [-] (scipy's ``diff_step``)
DIFF_STEP = 1e-6
#: a joint fit with an effect that has exact columns (:attr:`diagnosis.candidates.
#: Candidate.exact_extras`: the position map) takes its Jacobian from
#: :func:`_stacked_jacobian` (False: scipy's "2-point" differences of the whole residual,
#: one evaluation a column; the same columns to ~1e-8, the position fit 1.6 x as slow)
STRUCTURED_JACOBIAN = True
#: the joint fits' stop on the cost's relative fall (scipy's ``ftol``), unless every effect
#: of a fit allows a looser one (a candidate's ``FTOL``: :class:`diagnosis.effects_drift.
#: Drift`)
FTOL = 1e-8

#: static (break-away) levels of the LuGre family and how far above the data's force scale
#: (99th percentile of |F|) their box reaches [-]. The identification box stops at 2 x that
#: scale, which assumes the data show the level; a record that sticks and creeps far below
#: vs (the forging press) never loads the bristles up to it, yet its held-out part depends
#: on it through the bristle rate sigma0 |v| / g(v)
STATIC_LEVELS = ("Fs", "Fs_neg", "Fs0")
STATIC_LEVEL_SPAN = 10.0


def law_space(law, names, fit) -> ParameterSpace:
    """Search box of the base law's parameters in a joint fit: the identification box with
    the static levels reaching :data:`STATIC_LEVEL_SPAN` x the force scale of ``fit``."""
    sF = float(np.percentile(np.abs(fit.F), 99))
    space = ParameterSpace.build(law, names, data=fit)
    for j, n in enumerate(names):
        if n in STATIC_LEVELS and sF > 0:
            space.upper[j] = max(space.upper[j], STATIC_LEVEL_SPAN * sF)
    return space


@dataclass
class Composite:
    """Base law + effects, with fitted values.

    Attributes
    ----------
    law : FrictionModel
        The (possibly modified) law with its fitted parameter values.
    effects : list of Candidate
    extras : dict
        Fitted extra parameters of the effects, by name.
    """
    law: object
    base_names: list
    effects: list = field(default_factory=list)
    extras: dict = field(default_factory=dict)
    ctx: Context | None = None

    def predict(self, data) -> np.ndarray:
        """Force [N] along ``data``, the law started from the state consistent with the
        record's first samples, its motion and its measured force
        (:meth:`friction.base.FrictionModel.record_start_state`)."""
        kw = _law_inputs(self.law, data)
        s0 = self.law.record_start_state(data.t, data.v, F=data.F, **kw)
        lev = _inside_level(self.effects, self.extras, data, self.ctx)
        F = simulate_split(self.law, data.t, data.v, kw, s0, lev)
        return _apply_effects(F, self.effects, self.extras, data, self.ctx, self.law)

    def describe(self) -> dict:
        """Law name, fitted law parameters ``params``, effect names, fitted ``extras`` and,
        for effects that change the law and declare their own parameters from it
        (``own_parameters(law) -> dict``, e.g. backlash's ``backlash_gap`` [m]), those as
        ``parameters``."""
        out = {"law": self.law.name,
               "params": {n: float(getattr(self.law.params, n)) for n in self.base_names},
               "effects": [e.name for e in self.effects],
               "extras": {k: float(v) for k, v in self.extras.items()}}
        own = {}
        for e in self.effects:
            if getattr(e, "own_parameters", None) is not None:
                own.update(e.own_parameters(self.law))
        if own:
            out["parameters"] = own
        return out


def simulate_split(law, t, v, inputs, state0, level=None) -> np.ndarray:
    """The law's force [N] at the samples ``t`` [s], simulated with a sample added at each
    velocity reversal inside a step (:func:`friction.steps.split_at_reversals`): each side
    of a reversal is a step of its own, as the diagnosis simulates every model.

    Parameters
    ----------
    law : FrictionModel
    t, v : ndarray
        Time [s] and velocity [m/s].
    inputs : dict
        The law's further inputs (:func:`_law_inputs`: ``a``, ``x``, ``load``).
    state0 : ndarray
        The state at ``t[0]``.
    level : ndarray, optional
        Relative level inside the bristle dynamics [-] (:meth:`friction.lugre.LuGre.
        simulate_level`).
    """
    names = list(inputs)
    chans = [inputs[n] for n in names] + ([level] if level is not None else [])
    tt, vv, cc, idx = split_at_reversals(np.asarray(t, float), np.asarray(v, float), *chans)
    kw = dict(zip(names, cc[:len(names)]))
    if level is None:
        F = law.simulate(tt, vv, state0=state0, **kw)
    else:
        F = law.simulate_level(tt, vv, cc[-1], state0=state0)
    return F if idx is None else F[idx]


def _law_inputs(law, data) -> dict:
    kw = {}
    if "a" in law.extra_inputs:
        kw["a"] = data.a
    if "x" in law.extra_inputs:
        kw["x"] = data.x
    if "load" in law.extra_inputs:
        if data.load is None:
            raise ValueError(f"{law.name} needs a load column in the data")
        kw["load"] = data.load
    return kw


def _inside(effects):
    """The effects that scale the law's levels inside its bristle dynamics (an ``inside``
    hook: ``inside(p, data, ctx) -> level`` [-])."""
    return [e for e in effects if getattr(e, "inside", None) is not None]


def _inside_level(effects, extras, data, ctx):
    """The product of the ``inside`` effects' relative levels along ``data`` [-], or
    ``None`` when there is none."""
    lev = None
    for eff in _inside(effects):
        lev_e = np.asarray(eff.inside(extras, data, ctx), float)
        lev = lev_e if lev is None else lev * lev_e
    return lev


def _staged(effects):
    """The effects that act on the law's force, in the order they are applied."""
    return [e for e in sorted(effects, key=lambda e: _STAGE_ORDER[e.stage])
            if e.stage in _FORCE_STAGES]


def _apply_effects(F, effects, extras, data, ctx, law=None):
    for eff in _staged(effects):
        if eff.stage == "multiplicative" and law is not None:
            # a friction-level effect scales the friction, not the law's spring and offset
            Fc = law.conservative_force(data.x)
            F = Fc + eff.apply(F - Fc, extras, data, ctx)
        else:
            F = eff.apply(F, extras, data, ctx)
    return F


#: step of the base's parameters, in their search box's unit space, of the columns of
#: :func:`base_basis` [-]
BASIS_STEP = 1e-3


def base_basis(law, base_names, fit, ctx: Context, F0=None) -> np.ndarray:
    """Orthonormal basis of the changes of the base law's force on ``fit`` its free
    parameters can make (one-sided differences in the search box's unit space,
    :func:`law_space`), N x k with k <= len(base_names).

    A candidate's data start (:attr:`diagnosis.candidates.Candidate.start`) chooses its
    time scales on what this basis cannot fit: a base identified
    without the effect has already absorbed what its levels can mimic (a lubricant step
    on the valve at the record's switch to its faster sinusoid reads as a viscous term),
    and a residual taken at face value hides the effect's timing.

    Parameters
    ----------
    law : FrictionModel
        The base law at its fitted values.
    base_names : list of str
        Its free parameters.
    fit : friction.dataset.Dataset
        The fit record.
    ctx : diagnosis.candidates.Context
        Scales of the fit record.
    F0 : ndarray, optional
        The law's force along ``fit`` at its values [N] (computed when not given).
    """
    if F0 is None:
        F0 = Composite(law, list(base_names), [], {}, ctx).predict(fit)
    space = law_space(law, base_names, fit)
    u0 = np.clip(space.to_unit(np.array([getattr(law.params, n) for n in base_names])),
                 0.0, 1.0)
    cols = []
    for j in range(len(base_names)):
        u = u0.copy()
        u[j] += BASIS_STEP if u[j] + BASIS_STEP <= 1.0 else -BASIS_STEP
        try:
            trial = law.with_values(**dict(zip(base_names, map(float,
                                                               space.to_physical(u)))))
        except (ValueError, TypeError):
            continue
        d = Composite(trial, list(base_names), [], {}, ctx).predict(fit) - F0
        if np.all(np.isfinite(d)) and np.any(d):
            cols.append(d / np.linalg.norm(d))
    if not cols:
        return np.zeros((fit.t.size, 0))
    # directions the parameters barely separate (sigma1 at its bound, two levels a
    # record does not tell apart) are dropped, not amplified
    u, sv, _ = np.linalg.svd(np.column_stack(cols), full_matrices=False)
    return u[:, sv > 1e-6 * sv[0]]


def _data_starts(law, base_names, effects, ex, x_ex0, extras0, fit, ctx):
    """Start values of the extras of effects with a ``start`` hook (their time scales,
    wavelengths and positions chosen on the data, :meth:`diagnosis.effects.Candidate.
    start`), from the residual of ``law`` at its current values with the other effects at
    their starts; extras given in ``extras0`` are kept. Returns a list of alternative
    starts, each the extras' start values and the names of the extras it pinned
    (:class:`diagnosis.candidates.Fixed`: the joint fit keeps them); a start hook that
    returns a list of dicts offers one alternative per dict (one start: a list of one)."""
    given = extras0 or {}
    starters = [eff for eff in effects if eff.start is not None
                and any(e.name not in given for e in eff.force_extras(ctx))]
    if not starters:
        return [(x_ex0, set())]
    names = [e.name for e in ex]
    Fl = Composite(law, list(base_names), [], {}, ctx).predict(fit)
    # what the base's own parameters can still absorb: the starts fit it beside their columns
    basis = base_basis(law, base_names, fit, ctx, Fl) if base_names else None
    Ff = Fl - law.conservative_force(fit.x)
    others = [eff for eff in effects if eff not in starters]
    F = _apply_effects(Fl, others, dict(zip(names, x_ex0)), fit, ctx, law)
    r = fit.F - F
    alts = [(x_ex0.copy(), set())]
    for eff in starters:
        got = eff.start(fit, Ff, r, ctx, basis=basis)
        # a start may offer alternatives (a list): the joint fit runs from each
        options = got if isinstance(got, list) else [got]
        grown = []
        for x0, pinned in alts:
            for opt in options:
                x1, p1 = x0.copy(), set(pinned)
                for k, val in opt.items():
                    if k in names and k not in given:
                        x1[names.index(k)] = val
                        if isinstance(val, Fixed):
                            p1.add(k)
                grown.append((x1, p1))
        alts = grown
    return alts


def fit_composite(law, base_names, effects: list[Candidate], fit, ctx: Context, *,
                  extras0: dict | None = None, max_nfev: int = 60,
                  progress=None) -> tuple[Composite, float]:
    """Jointly re-identify the base law's parameters and the effects' extras on ``fit``.

    Returns the fitted composite and its fit NRMSE. ``law``'s current values start the search.
    Every trial is simulated from its own state consistent with the record's first samples
    (its motion and measured force), as :meth:`Composite.predict` scores it.

    Parameters
    ----------
    law : FrictionModel
        Base law; its current values start the search.
    base_names : list of str
        The law's parameters re-identified with the effects' extras.
    effects : list of Candidate
        Effects stacked on the law.
    fit : Dataset
        Record fitted (t [s], v [m/s], F [N], ...).
    ctx : Context
        The diagnosis context the effects read.
    extras0 : dict, optional
        Start values of extras [their units] (default each extra's ``x0`` or data start,
        and the law's values from the ``start_law`` hook of an effect that has one; given,
        even empty, the law starts from its values as they are).
    max_nfev : int
        Most trial points of each least-squares run (scipy's ``max_nfev``).
    progress : callable(n, info), optional
        Ticked at most once a second with ``n`` residual evaluations (default: the
        :func:`reporting` context's, else silent).

    Notes
    -----
    A record whose N x D finite-difference Jacobian exceeds :data:`LONG_JACOBIAN_BYTES`
    is fitted by :func:`_solve_normal` (the same trust-region algorithm on the normal
    equations, a float32 Jacobian): memory O(N D / 2) instead of scipy's several N x D
    float64 copies.
    """
    # a candidate that changes the law (backlash's gap, gms's stiffness split) may start
    # its new parameters on the data, where a least squares from the base's values stays
    # (``start_law(law, names, fit, ctx) -> law``, :mod:`diagnosis.effects_backlash`); a
    # warm start (greedy stacking) keeps its values
    law_starts = []
    if extras0 is None:
        for eff in effects:
            start_law = getattr(eff, "start_law", None)
            if start_law is not None:
                started = start_law(law, base_names, fit, ctx)
                # ``(law, pinned)``: law parameters the start pinned (a part of the
                # candidate the data do not ask for) stay at their values, out of the
                # solved vector; a list: several starts, the joint fit runs from each
                # (their pins alike) and keeps the best on the fit record
                # (``(law, pinned, True)``: a fallback start, run only where it starts
                # below the best fit so far)
                starts = [(s + (False,))[:3] if isinstance(s, tuple) else (s, (), False)
                          for s in (started if isinstance(started, list) else [started])]
                if any(set(pin) != set(starts[0][1]) for _, pin, _ in starts):
                    raise ValueError(f"{eff.name}'s law starts pin different parameters")
                law, pinned, _ = starts[0]
                law_starts = [(s, fb) for s, _, fb in starts[1:]]
                base_names = [n for n in base_names if n not in pinned]
    nb = len(base_names)
    # no law parameter to fit (the transfer scores calibrate only a candidate's own): the
    # law stays at its values
    space = law_space(law, base_names, fit) if nb else None
    for other, _ in (law_starts if nb else ()):
        # the box holds every start (each widens its own to its values)
        alt = law_space(other, base_names, fit)
        space.lower = np.minimum(space.lower, alt.lower)
        space.upper = np.maximum(space.upper, alt.upper)
        space.log = space.log & alt.log & (space.lower > 0)

    def law_unit(start):
        return (np.clip(space.to_unit(np.array([getattr(start.params, n)
                                                for n in base_names])), 0.0, 1.0)
                if nb else np.zeros(0))
    u_law0 = law_unit(law)
    ex = [e for eff in effects for e in eff.force_extras(ctx)]
    lo = np.array([e.lo for e in ex])
    hi = np.array([e.hi for e in ex])
    x_ex0 = np.array([(extras0 or {}).get(e.name, e.x0) for e in ex])
    alts = _data_starts(law, base_names, effects, ex, x_ex0, extras0, fit, ctx)
    box = (lo.copy(), hi.copy())

    def start_point(x_ex0, pinned, u_law):
        # the box of this start (lo, hi are the closures' arrays, set in place): a part the
        # data start found unsupported stays at its value
        lo[:], hi[:] = box
        for j, e in enumerate(ex):
            if e.name in pinned:
                lo[j] = hi[j] = x_ex0[j]
        span = hi - lo
        u_ex0 = (np.divide(x_ex0 - lo, span, out=np.zeros_like(x_ex0), where=span > 0)
                 if ex else np.zeros(0))
        return np.concatenate([u_law, np.clip(u_ex0, 0.0, 1.0)])
    # kernel inputs validated once; each evaluation only repacks theta
    t, v, a, load, x = law._inputs(fit.t, fit.v, **_law_inputs(law, fit))
    # simulated with a sample at each reversal inside a step (as Composite.predict)
    t_r, v_r, (a_r, load_r, x_r), at_samples = split_at_reversals(t, v, a, load, x)
    kern = law._kernel
    sd = float(np.std(fit.F)) or 1.0
    F0 = float(fit.F[0])
    # laws with a spring/offset part (mre_lugre) need it at the trial values
    elastic = type(law).conservative_force is not FrictionModel.conservative_force and \
        any(e.stage == "multiplicative" for e in effects)

    def unpack(u):
        xl = space.to_physical(u[:nb]) if nb else np.zeros(0)
        extras = {e.name: lo[j] + (hi[j] - lo[j]) * u[nb + j] for j, e in enumerate(ex)}
        return xl, extras

    def trial_law(xl):
        try:
            return law.with_values(**dict(zip(base_names, map(float, xl))))
        except (ValueError, TypeError):  # values the law rejects (NaN cost below)
            return None

    # the law's force depends on the law's parameters (and the extras of effects acting
    # inside it) only: a step in another effect's extras (most columns of a finite-
    # difference Jacobian) reuses the last simulation
    memo = {}
    inside = _inside(effects)
    # (an effect may name the extras its level reads: ``inside_names``; else all of them)
    inside_names = [n for eff in inside for n in (
        getattr(eff, "inside_names", None) or [e.name for e in eff.force_extras(ctx)])]
    if inside and not hasattr(law, "simulate_level"):
        raise ValueError(f"{', '.join(e.name for e in inside)} scales the levels inside "
                         f"the law, which {law.name} cannot (a classic LuGre can)")

    def law_force(xl, extras=None):
        key = xl.tobytes() + (np.array([extras[n] for n in inside_names]).tobytes()
                              if inside else b"")
        if key not in memo:
            theta = law.population_theta(base_names, xl[None, :])[0]
            trial = trial_law(xl) if nb else law
            s0 = (law.initial_state() if trial is None
                  else trial._start_from(t, v, a, load, x, F0))
            if inside:
                lev = _inside_level(effects, extras, fit, ctx)
                if at_samples is not None:
                    lev = np.interp(t_r, t, lev)
                F = np.empty(t_r.size)
                lugre_level_run(t_r, v_r, theta, lev, float(s0[0]), F)
            else:
                F, _ = kern(t_r, v_r, a_r, load_r, x_r, theta, 0, s0)
            if at_samples is not None:
                F = F[at_samples]
            memo.clear()
            memo[key] = (F, trial)
        return memo[key]

    penalties = [eff.penalty for eff in effects if getattr(eff, "penalty", None) is not None]
    n_pen = sum(np.size(pen({e.name: e.x0 for e in ex}, ctx)) for pen in penalties)

    def residual(u):
        xl, extras = unpack(u)
        F, trial = law_force(xl, extras)
        F = _apply_effects(F, effects, extras, fit, ctx,
                           (trial or law.with_values(**dict(zip(base_names, xl))))
                           if elastic else None)
        r = (fit.F - F) / sd
        if not np.all(np.isfinite(r)):
            return np.full(r.size + n_pen, 1e3)
        if n_pen:
            r = np.concatenate([r, prior_rows(extras)])
        return r

    def prior_rows(extras):
        # an effect's prior on its own parameters (a smoothness of a map's knots), as rows
        # weighted by the record's length: it counts as a misfit of that size on every
        # sample
        return np.concatenate([np.sqrt(fit.F.size) * np.asarray(pen(extras, ctx), float)
                               for pen in penalties])

    def gridded(u0):
        # a time shift or a filter time constant is non-convex (or flat at 0): start from
        # the best point of a coarse grid
        for j, e in enumerate(ex):
            if e.grid:
                grid = np.linspace(0.0, 1.0, e.grid)
                costs = []
                for g in grid:
                    u = u0.copy()
                    u[nb + j] = g
                    costs.append(float(np.sum(residual(u) ** 2)))
                u0[nb + j] = grid[int(np.argmin(costs))]
        return u0

    n_par = nb + len(ex)
    long_record = n_par > 0 and 8 * fit.F.size * n_par > LONG_JACOBIAN_BYTES
    prog = progress if progress is not None else _PROGRESS.get()
    if prog is not None:
        residual = _counted(residual, prog, f"fit {'+'.join(e.name for e in effects) or 'base'}")

    jac = "2-point"
    # (not with an effect inside the law: its extras move the law's simulation)
    if STRUCTURED_JACOBIAN and not elastic and not inside and any(
            getattr(e, "exact_extras", ()) for e in _staged(effects)):
        # only where an effect has exact columns: elsewhere the structured columns save
        # little (an effect is cheap next to the law's simulations) and scipy's are kept
        # to the last bit, so are the fits (a fit stopping in a flat valley moves by up
        # to 1e-2 in gap_closed with the rounding of its columns); nor for an elastic law,
        # whose spring part moves with its parameters under a friction-level effect
        def jac(u):
            J = _stacked_jacobian(u, nb, lambda uj: law_force(unpack(uj)[0])[0], effects,
                                  unpack(u)[1], lambda uj: unpack(uj)[1],
                                  [e.name for e in ex], hi - lo, fit, ctx, sd, residual)
            if not n_pen or J.shape[0] == n_pen + fit.F.size:
                return J
            # a prior's rows (a drag's knots beside an effect with exact columns): they
            # read the extras alone, so their differences cost no simulation
            h, dx = _forward_steps(u, DIFF_STEP)
            p0 = prior_rows(unpack(u)[1])
            P = np.zeros((p0.size, u.size))
            for j in range(nb, u.size):
                uj = u.copy()
                uj[j] += h[j]
                P[:, j] = (prior_rows(unpack(uj)[1]) - p0) / dx[j]
            return np.vstack([J, P])

    # the relative fall of the cost at which a fit stops (scipy's ftol; the strictest of
    # the effects', each its ``FTOL`` or :data:`FTOL`)
    ftol = min((getattr(eff, "FTOL", FTOL) for eff in effects), default=FTOL)

    def solve(u):
        # the parts a data start pinned (no span) stay out of the solved vector: their zero
        # columns leave the float32 normal equations singular, and in scipy's trust region
        # they still count in the step's scaling: five pinned columns of the inertia
        # candidate's coupled part kept a geared-inertia fit on the valve in the base's
        # basin (gap closed 0.24 against 0.73 without them)
        free = np.concatenate([np.ones(nb, bool), hi > lo])
        if free.all():
            if long_record:
                return _solve_normal(residual, u, max_nfev, ftol=ftol)
            return least_squares(residual, u, jac=jac, bounds=(0.0, 1.0), x_scale=1.0,
                                 max_nfev=max_nfev, diff_step=DIFF_STEP, method="trf",
                                 ftol=ftol)

        def on_free(uf):
            full = u.copy()
            full[free] = uf
            return residual(full)
        if long_record:
            sol_f = _solve_normal(on_free, u[free], max_nfev, ftol=ftol)
        else:
            jac_f = jac if jac == "2-point" else (lambda uf: jac(np.where(
                free, 0.0, u) + _scatter(uf, free))[:, free])
            sol_f = least_squares(on_free, u[free], jac=jac_f, bounds=(0.0, 1.0),
                                  x_scale=1.0, max_nfev=max_nfev, diff_step=DIFF_STEP,
                                  method="trf", ftol=ftol)
        full = u.copy()
        full[free] = sol_f.x
        sol_f.x = full
        return sol_f

    # from each alternative start (most effects offer one), the best on the fit record: a
    # coupled part that fits the fit record's residual can hold the base's own parameters
    # in the basin where they absorbed the effect, which the plain form leaves
    sol, best_box = None, None
    for u_law, fallback in [(u_law0, False)] + [(law_unit(s), fb) for s, fb in law_starts]:
        for x_ex0, pinned in alts:
            u0 = gridded(start_point(x_ex0, pinned, u_law))
            if fallback and sol is not None and 0.5 * float(np.sum(residual(u0) ** 2)) \
                    >= sol.cost:
                continue
            sol_a = solve(u0)
            if sol is None or sol_a.cost < sol.cost:
                sol, best_box = sol_a, (lo.copy(), hi.copy())
    lo[:], hi[:] = best_box
    undo = [eff for eff in effects if eff.undo is not None]
    if undo and nb:
        # the base law identified on the record with the effect in it absorbed part of it (a
        # 15-sample delay on the press reads as an inverted Stribeck curve, a basin the joint
        # fit does not leave although it finds the delay): a second start re-identifies the
        # law on the record with the effect as fitted taken out
        from identification import identify
        _, extras1 = unpack(sol.x)
        data_u = fit
        for eff in undo:
            data_u = eff.undo(data_u, extras1, ctx)
        # (the fit record's channels are as the caller gave them: aligned by diagnose)
        law_u = identify(data_u, law, names=base_names, seed=0, align=False)["model"]
        u1 = sol.x.copy()
        u1[:nb] = np.clip(space.to_unit(np.array([getattr(law_u.params, n)
                                                   for n in base_names])), 0.0, 1.0)
        sol = min((sol, solve(u1)), key=lambda s: s.cost)
    xl, extras = unpack(sol.x)
    fitted = law.with_values(**{n: float(val) for n, val in zip(base_names, xl)})
    comp = Composite(fitted, list(base_names), list(effects), extras, ctx)
    if long_record and not n_pen:
        nr = float(np.sqrt(2.0 * sol.cost / fit.F.size))
    else:
        # the record's own misfit, without a prior's rows (the long records' solver keeps
        # no residual)
        r = residual(sol.x) if long_record else sol.fun
        nr = float(np.sqrt(np.mean(r[:fit.F.size] ** 2)))
    return comp, nr


def _scatter(uf, free):
    """``uf`` placed at the ``free`` entries of a vector of zeros (``free``'s length)."""
    out = np.zeros(free.size)
    out[free] = uf
    return out


def _forward_steps(u, rel_step=DIFF_STEP):
    """Forward-difference steps in the unit cube, as scipy's ``least_squares`` takes them
    (``jac="2-point"``, ``diff_step=rel_step``, bounds 0 and 1): ``rel_step |u|`` (the
    square root of the machine epsilon where that is lost on ``u``), reversed where it
    would leave the box.

    Parameters
    ----------
    u : ndarray
        The point [-], inside [0, 1].
    rel_step : float
        Relative step [-].

    Returns
    -------
    (ndarray, ndarray)
        The steps ``h`` and the differences ``(u + h) - u`` the columns are divided by.
    """
    sign = np.where(u >= 0, 1.0, -1.0)
    h = rel_step * sign * np.abs(u)
    h = np.where((u + h) - u == 0, np.sqrt(np.finfo(float).eps) * sign
                 * np.maximum(1.0, np.abs(u)), h)
    out = ((u + h) < 0.0) | ((u + h) > 1.0)
    h = np.where(out & (np.abs(h) <= np.maximum(u, 1.0 - u)), -h, h)
    return h, (u + h) - u


def _stacked_jacobian(u, nb, law_at, effects, extras, extras_at, ex_names, ex_span, fit,
                      ctx, sd, residual):
    """Jacobian of the joint fit's residual ``(F - stack(law force)) / sd`` at ``u``.

    The law's columns are forward differences of the law's force alone (one simulation a
    column) carried through each effect by its derivative with respect to the force; an
    effect's own columns are exact where its :meth:`~diagnosis.candidates.Candidate.jac`
    gives them, else forward differences of that effect alone. An effect whose ``jac`` is
    ``None`` carries the columns by differences along them. Steps are scipy's
    (:func:`_forward_steps`), so the columns are those of ``jac="2-point"`` up to rounding
    (and the differences' own error where a column is exact here).

    Parameters
    ----------
    u : ndarray
        The point in the unit cube, law parameters first [-].
    nb : int
        Number of law parameters.
    law_at : callable
        ``law_at(u) -> F`` the law's force [N] at a point.
    effects : list of Candidate
        The stacked effects.
    extras : dict
        The effects' extras at ``u`` [their units].
    extras_at : callable
        ``extras_at(u) -> dict`` the extras at a point.
    ex_names : list of str
        The extras in the order of ``u[nb:]``.
    ex_span : ndarray
        Width of each extra's box [its unit] (``d extra / d u``).
    fit : Dataset
        The fit record.
    ctx : Context
        The candidates' context.
    sd : float
        Scale of the residual [N].
    residual : callable
        The residual itself: scipy's differences of it where a column is not finite.

    Returns
    -------
    ndarray
        ``(N, len(u))`` Jacobian [1 / unit step].
    """
    h, dx = _forward_steps(u, DIFF_STEP)
    F = law_at(u)
    D = np.zeros((F.size, u.size))
    for j in range(nb):
        uj = u.copy()
        uj[j] += h[j]
        D[:, j] = (law_at(uj) - F) / dx[j]
    live = list(range(nb))
    pos = {n: nb + k for k, n in enumerate(ex_names)}
    for eff in _staged(effects):
        out = eff.apply(F, extras, fit, ctx)
        lin = eff.jac(F, extras, fit, ctx)
        if lin is not None:
            dF, exact = lin
            D[:, live] *= np.reshape(dF, (-1, 1))
        else:
            # differences along each column: exact for an effect linear in the force
            # (a time shift), scipy's columns for any other
            for j in live:
                D[:, j] = (eff.apply(F + dx[j] * D[:, j], extras, fit, ctx) - out) / dx[j]
            exact = {}
        for e in eff.force_extras(ctx):
            k = pos[e.name]
            if e.name in exact:
                D[:, k] = exact[e.name] * ex_span[k - nb]
            else:
                uk = u.copy()
                uk[k] += h[k]
                D[:, k] = (eff.apply(F, extras_at(uk), fit, ctx) - out) / dx[k]
            live.append(k)
        F = out
    J = D / -sd
    if np.all(np.isfinite(F)) and np.all(np.isfinite(J)):
        return J
    # a trial the law or an effect cannot evaluate (NaN cost): scipy's columns (a prior's
    # rows included)
    r0 = residual(u)
    J = np.empty((r0.size, u.size))
    for j in range(u.size):
        uj = u.copy()
        uj[j] += h[j]
        J[:, j] = (residual(uj) - r0) / dx[j]
    return J


#: above this size of the N x D finite-difference Jacobian (8 bytes a number) a joint fit
#: runs on the normal equations (:func:`_solve_normal`): scipy's trust region holds the
#: Jacobian several times over (its copy, the scaled and augmented matrix, the SVD's left
#: factor: 2.8 GB peak for a 2,000,000-row record's candidate fits)
LONG_JACOBIAN_BYTES = 64 * 2**20

#: the progress callable(n, info) of the fits in this context (:func:`reporting`)
_PROGRESS = contextvars.ContextVar("fit_composite_progress", default=None)


@contextlib.contextmanager
def reporting(progress):
    """Within the block, :func:`fit_composite` calls without their own ``progress=``
    report to ``progress`` (``callable(n, info)``, ``n`` residual evaluations; ``None``:
    silent): a command shows life during the fits of a diagnosis without every layer
    between it and the fits taking the argument."""
    token = _PROGRESS.set(progress)
    try:
        yield progress
    finally:
        _PROGRESS.reset(token)


#: seconds between the progress ticks of a joint fit
TICK_EVERY = 1.0


def _counted(residual, progress, label):
    """``residual`` ticking ``progress(n, label + cost)`` at most every
    :data:`TICK_EVERY` seconds with the evaluations since the previous tick."""
    state = {"n": 0, "t": time.perf_counter()}

    def wrapped(u):
        r = residual(u)
        state["n"] += 1
        now = time.perf_counter()
        if now - state["t"] >= TICK_EVERY:
            progress(state["n"], f"{label} cost={float(np.sqrt(np.mean(r * r))):.4g}")
            state["n"], state["t"] = 0, now
        return r
    return wrapped


def _solve_normal(residual, u0, max_nfev, diff_step=1e-6, ftol=1e-8):
    """``least_squares(residual, u0, bounds=(0, 1), x_scale=1.0, max_nfev=max_nfev,
    diff_step=diff_step, method="trf")`` (a 2-point Jacobian, the exact trust-region
    subproblem) without an N x D float64 Jacobian or scipy's copies of it.

    The forward-difference Jacobian is stored in float32 (its entries carry the
    differences' own error, ~1e-8 relative at this step, near float32's 6e-8; memory
    N x D x 4 bytes) and reduced to ``r.r``, ``J^T r``, ``J^T J`` in float64 blocks of rows;
    the trust region runs on the D + 1 residual with the same Gauss-Newton model
    (:func:`identification.algorithms.local.compress_normal_equations`,
    :func:`identification.algorithms.trf.trf_exact`: scipy's algorithm and tests, trial
    points costing one evaluation, a Jacobian D more where one is accepted).

    Returns
    -------
    TrfResult
        ``x``, ``cost`` (half the sum of squares of the long residual), ``nfev``,
        ``status``, ``message``.
    """
    from identification.algorithms.local import (compress_normal_equations,
                                                 forward_difference_normal_equations)
    from identification.algorithms.trf import trf_exact

    u0 = np.asarray(u0, float)
    last = {}

    def r_at(u):
        key = u.tobytes()
        if last.get("key") != key:
            last.clear()
            last["r"] = np.asarray(residual(u), float)
            last["key"] = key
        return last["r"]

    def cost_of(u):
        r = r_at(u)
        return 0.5 * float(np.dot(r, r))

    J = None

    def fun_jac(u):
        nonlocal J
        r0 = r_at(u).copy()
        c2, g, H, J = forward_difference_normal_equations(r_at, u, r0, step=diff_step,
                                                          out=J)
        last.clear()
        last["r"], last["key"] = r0, u.tobytes()
        return compress_normal_equations(c2, g, H)

    x0 = np.clip(u0, 0.0, 1.0)
    D = u0.size
    return trf_exact(fun_jac, x0, np.zeros(D), np.ones(D), ftol=ftol, xtol=1e-8,
                     gtol=1e-8, max_nfev=max_nfev, cost_of=cost_of)
