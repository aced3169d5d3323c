"""Candidate builders: the diagnosis' effects as real extensions of a base friction law.

Each named effect is one record of :mod:`diagnosis.effects` (:class:`diagnosis.effects.
Effect`), whose ``candidate`` is an instance of a subclass of :class:`Candidate`. Here are
the base classes, the fit record's scales (:class:`Context`), the least squares the
candidates' start values share, and the smallest candidate (``presliding``); every other
candidate lives in its effect's own module, ``diagnosis/effects_<name>.py``
(``acceleration``, ``asymmetry``, ``load``, ``drift``, ``position``, ``inertia``, ``delay``,
``stribeck`` for ``stribeck_shape``, ``backlash``, ``gms``).

Every candidate changes the model in one of four ways, applied in this order:

1. ``modify_law``   - a different law or more free parameters of the law itself
                      (``stribeck_shape``: free exponent / Lorentzian; ``presliding``: bristle
                      dynamics added to a static map);
2. ``multiplicative`` - the law's force scaled (``load``: levels grow with the normal load;
                      ``drift``: levels change over time);
3. ``additive``     - a force term added (``acceleration``, ``asymmetry``, ``position``,
                      ``inertia``);
4. ``shift``        - the whole prediction shifted in time (``delay``).

so candidates compose: the greedy sequence of :mod:`diagnosis.core` stacks them.
Each candidate declares its own parameters with a physical box computed from the fit data
(``context``), so no candidate has a free scale an optimiser could abuse: ``extras`` are those
of the effect's formula at every level, ``force_extras`` add what measured friction data need
(the filter of a differentiated acceleration channel, the load slope of the viscous part).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from scipy.signal import lfilter

from friction import make_model
from friction.alignment import velocity_lag

__all__ = ["Candidate", "LawCandidate", "Context", "Extra", "make_context", "velocity_lag",
           "Fixed", "friction_heat", "position_quantum",
           "Presliding", "MAX_FILTER_SAMPLES", "missing_columns", "law_variants",
           "levels_inside", "with_inside_form", "inside_level"]



@dataclass
class Context:
    """Scales of the fit data that fix each candidate's parameter box."""
    sF: float       # force scale [N] (99th percentile of |F|)
    sv: float       # velocity scale [m/s]
    sa: float       # acceleration scale [m/s^2]
    x_lo: float
    x_hi: float     # position range of the fit data [m]
    t0: float
    T: float        # fit data start and duration [s]
    dt: float       # sample interval [s]
    L0: float | None  # mean load of the fit data [N]
    L_span: float   # load spread of the fit data [N]
    L_hi: float = 0.0  # largest load of the fit data [N]
    v_lag: float = 0.0  # lag of the velocity channel behind the position's [samples]
    x_q: float = 0.0  # position resolution of the fit data [m] (0: not quantised)
    #: the fit data's friction power |F v| over its mean [-], and that mean [W]
    #: (:func:`friction_heat`); empty where unknown
    power: tuple = ()
    #: the fit data's speeds |v| [m/s] at its 1st to 99th percentiles in steps of 2, where
    #: its motion is (the asymmetry drag's share, :class:`diagnosis.effects_asymmetry.
    #: AsymmetryDrag`); empty where unknown
    speeds: tuple = ()


def make_context(fit) -> Context:
    sF = float(np.percentile(np.abs(fit.F), 99)) or 1.0
    sv = float(np.percentile(np.abs(fit.v), 99)) or 1e-3
    sa = float(np.percentile(np.abs(fit.a), 99)) or 1e-3
    L0 = float(np.mean(fit.load)) if fit.load is not None else None
    L_span = float(np.ptp(fit.load)) if fit.load is not None else 0.0
    L_hi = float(np.max(fit.load)) if fit.load is not None else 0.0
    P = np.abs(np.asarray(fit.F, float) * np.asarray(fit.v, float))
    P_mean = float(np.mean(P)) if P.size else 0.0
    power = (P / P_mean, P_mean) if P_mean > 0.0 and np.isfinite(P_mean) else ()
    speeds = tuple(float(q) for q in np.percentile(np.abs(fit.v), np.arange(1, 100, 2)))
    return Context(sF, sv, sa, float(np.min(fit.x)), float(np.max(fit.x)), float(fit.t[0]),
                   float(fit.t[-1] - fit.t[0]), fit.dt, L0, L_span, L_hi, velocity_lag(fit),
                   position_quantum(fit.x), power, speeds)


def friction_heat(data, tau, ctx) -> np.ndarray:
    """The heating of the contact by its friction power [-]: the first-order lag (time
    constant ``tau`` [s], step-invariant at the sample interval) of the measured |F v| over
    its mean on the fit record (``ctx.power``). From 0 (cold) for a record that starts
    where the fit record starts (the fit record itself, or one on a clock reset likewise);
    a record that starts later (the held-out part of a split record, a record made after)
    from the fit record's final state, cooled over any pause between them; one that starts
    earlier (its own clock) from that final state.

    Parameters
    ----------
    data : friction.dataset.Dataset
        The record (t [s], v [m/s], F [N]).
    tau : float
        Time constant [s] (> 0).
    ctx : Context
        Scales of the fit record (:func:`make_context`).

    Returns
    -------
    ndarray
        The heat state [-] at ``data.t`` (1: the fit record's mean power, held long).
    """
    if not (np.isfinite(tau) and tau > 0.0):
        raise ValueError(f"tau_heat = {tau!r} is out of bounds: the heating's time constant "
                         f"must be > 0 [s]")
    t = np.asarray(data.t, float)
    if not ctx.power or t.size == 0:
        return np.zeros(t.size)
    u_fit, P_mean = ctx.power
    u = np.abs(np.asarray(data.F, float) * np.asarray(data.v, float)) / P_mean
    h0 = 0.0
    if t[0] > ctx.t0 + 0.5 * ctx.dt:
        e = np.exp(-ctx.dt / tau)
        h0 = float(lfilter([1.0 - e], [1.0, -e], u_fit)[-1])
        h0 *= np.exp(-max(t[0] - (ctx.t0 + ctx.T) - ctx.dt, 0.0) / tau)
    e = np.exp(-float(data.dt) / tau)
    return lfilter([1.0 - e], [1.0, -e], u, zi=[e * h0])[0]


def position_quantum(x) -> float:
    """The position channel's resolution [m]: the smallest step between its samples when
    every step is a whole number of it (an encoder's count, a file's last digit), else 0.

    Parameters
    ----------
    x : ndarray
        Positions [m].
    """
    d = np.abs(np.diff(np.asarray(x, float)))
    d = d[d > 0.0]
    if d.size < 10:
        return 0.0
    q = float(d.min())
    r = d / q
    # (to the rounding of stored positions: 1e-3 of a count)
    if np.mean(np.abs(r - np.round(r)) < 1e-3) < 0.99:
        return 0.0
    return q


class Fixed(float):
    """A start value (:attr:`Candidate.start`) the joint fit keeps: the data start found the
    part of the formula it belongs to unsupported (its amplitude 0 and its time scale, which
    then moves nothing, where it is)."""


class Fallback(dict):
    """Start values of a law candidate (:meth:`LawCandidate.start_values`, in a list after
    the first start) that the joint fit runs from only where they fit the record better
    than its best fit so far (:func:`diagnosis.composite.fit_composite`): a start that
    guards against a poor basin of the others (the base itself inside the candidate's law)
    costs one simulation where it is not needed."""


@dataclass
class Extra:
    """One extra parameter of a candidate: name, start value and box (physical units).

    ``grid`` > 0: the fit starts from the best of that many evenly spaced values over the box
    (for parameters the residual is not convex in, or whose gradient vanishes at the start,
    such as a time shift or a filter time constant at 0).
    """
    name: str
    x0: float
    lo: float
    hi: float
    unit: str = ""
    grid: int = 0


@dataclass
class Candidate:
    """A named effect. Subclasses override the hooks they need."""
    name: str
    description: str
    stage: str = "additive"   # modify_law | multiplicative | additive | shift
    tags: tuple = field(default_factory=tuple)
    #: optional data columns the effect reads (fit and held-out data must both have them)
    needs: ClassVar[tuple] = ()
    #: extras whose derivative :meth:`jac` gives exactly; a joint fit with such an effect
    #: takes its Jacobian from :func:`diagnosis.composite._stacked_jacobian`
    exact_extras: ClassVar[tuple] = ()
    #: seconds of its joint fit (starts included) on ``bench_diagnosis.py``'s speed case
    #: (20,000 samples, one thread, session 39): the side-by-side fits start with the
    #: costliest (:func:`diagnosis.cluster.costliest_first`); 0: unmeasured (ordered by
    #: its Jacobian's width after the measured ones)
    fit_cost: ClassVar[float] = 0.0

    def applicable(self, law, fit, ctx: Context) -> tuple[bool, str]:
        return True, ""

    def modify_law(self, law, base_names, ctx: Context):
        """Return the list of (law, base_names) variants to try (best on fit is kept); a
        variant may carry a third item, the form of the candidate fitted with it (a
        :class:`Candidate` of the same name; :func:`law_variants`)."""
        return [(law, list(base_names))]

    def extras(self, ctx: Context) -> list[Extra]:
        """Parameters of the effect's formula at every level (the trajectory level's
        :class:`diagnosis.effect_law.EffectLaw` implements exactly these)."""
        return []

    def trajectory_extras(self, ctx: Context) -> list[Extra]:
        """The parameters the trajectory level fits (each evaluation a plant simulation):
        :meth:`extras` by default; a candidate whose further forms need a start chosen on
        the data (:attr:`start`, a force-level residual) offers only its first form there."""
        return self.extras(ctx)

    def force_extras(self, ctx: Context) -> list[Extra]:
        """All parameters fitted at the force level: :meth:`extras` plus those only measured
        friction data need (their zero, the default of :meth:`apply`, is the plain formula)."""
        return self.extras(ctx)

    def apply(self, F, p: dict, data, ctx: Context) -> np.ndarray:
        return F

    def jac(self, F, p: dict, data, ctx: Context):
        """Derivatives of :meth:`apply` for a joint fit's Jacobian (:func:`diagnosis.
        composite._stacked_jacobian`), or ``None``: differences of :meth:`apply` along each
        column.

        By default from the stage: an ``additive`` effect adds a term (``d/dF = 1``), a
        ``multiplicative`` one scales the force by a factor (``apply(1) - apply(0)``, exact
        for a formula affine in the force); no extra is given exactly.

        Parameters
        ----------
        F : ndarray
            The force the effect acts on [N].
        p : dict
            The extras [their units].
        data : friction.dataset.Dataset
            The record (t [s], x [m], v [m/s], a [m/s^2], load [N]).
        ctx : Context
            Scales of the fit record.

        Returns
        -------
        None or (float or ndarray, dict)
            ``d apply / dF`` element by element [-], and ``d apply / d p[name]`` [N per
            unit of the extra] of the extras whose derivative is exact here (the others
            are differenced).
        """
        if self.stage == "additive":
            return 1.0, {}
        if self.stage == "multiplicative":
            one = np.ones_like(F)
            return self.apply(one, p, data, ctx) - self.apply(0.0 * one, p, data, ctx), {}
        return None

    #: ``start(fit, Ff, r, ctx, basis=None) -> dict``: start values of extras chosen on the
    #: data (time scales, wavelengths, positions a gradient cannot find from a zero
    #: amplitude), given the base's friction part ``Ff`` [N] and residual ``r`` [N] on the
    #: fit record (:func:`diagnosis.composite.fit_composite`) and ``basis``, the changes of
    #: the base's force its own parameters can make (:func:`diagnosis.composite.
    #: base_basis`), fitted beside the start's columns: what the base absorbed of the effect
    #: is not in ``r``; ``None``: the extras' ``x0``. It may return a list of such dicts:
    #: alternative starts, the joint fit runs from each and keeps the best on the fit record
    start = None

    #: ``inside(p, data, ctx) -> ndarray``: the relative level [-] at which the effect
    #: scales the law's friction levels *inside* its bristle dynamics along ``data``
    #: (:func:`diagnosis.composite.fit_composite`, a LuGre law's ``simulate_level``);
    #: ``None``: the effect acts on the law's output (:meth:`apply`) or through the law
    inside = None

    #: ``undo(data, p, ctx) -> Dataset``: the data with the effect at ``p`` taken out, for
    #: effects the base fit absorbs in a distorted way (see :func:`diagnosis.composite.
    #: fit_composite`); ``None``: no such start
    undo = None

    #: ``penalty(p, ctx) -> ndarray``: a prior on the effect's own extras ``p``, as rows [-]
    #: appended to the joint fit's residual (each weighted by the square root of the fit
    #: record's length, so a row of size ``e`` costs what a misfit of ``e`` standard
    #: deviations of the force on every sample does; :func:`diagnosis.composite.
    #: fit_composite`); the fit scores it reports leave the rows out. ``None``: no prior
    penalty = None

    def practical(self, p: dict, ctx: Context) -> str:
        """Why the fitted parameters ``p`` are too small to be this effect in practice,
        whatever the held-out scores ('' when they are not; see
        :func:`diagnosis.core.practical_size`)."""
        return ""

    def held_out_reason(self, val_sets, ctx: Context) -> str:
        """Why the held-out records ``val_sets`` cannot test what the fit record (scales
        ``ctx``) teaches this candidate ('' when they can; see :func:`missing_columns`)."""
        return ""

    def defers(self, p: dict, fit, ctx: Context) -> tuple[str, str]:
        """The simpler candidate whose form the fitted parameters ``p`` reduce to on the fit
        record ``fit``, and why: ``(name, reason)``, or ``("", "")`` when they do not. A
        candidate that defers is not named, and ranks behind the one it defers to
        (:func:`diagnosis.verdict.rank`): what its extra flexibility adds is no effect of
        its own."""
        return "", ""

    def specialise(self, law) -> "Candidate":
        """The form of this effect for ``law`` (default: the same for every law)."""
        return self

    def own_law_names(self, law) -> tuple:
        """Parameters of the law itself that belong to this effect, whether or not the base
        already frees them (the transfer scores calibrate them with the effect's own; by
        default only the names :meth:`modify_law` adds to the base's)."""
        return ()



class LawCandidate(Candidate):
    """A candidate that changes the law itself (its variant from :meth:`modify_law`) and has
    law parameters of its own, :attr:`OWN`, started on the data by :meth:`start_values`
    (the ``start_law`` hook of :func:`diagnosis.composite.fit_composite`)."""

    #: the law parameters that are this candidate's own
    OWN: ClassVar[tuple] = ()

    def start_values(self, law, names, fit, ctx: Context) -> dict | list:
        """Start values of the variant ``law`` chosen on the fit record, or a list of such
        starts (see :meth:`start_law`)."""
        raise NotImplementedError

    def start_law(self, law, names, fit, ctx: Context):
        """``law`` (a :meth:`modify_law` variant) started on the data (:meth:`start_values`);
        ``(law, pinned)`` when the start pinned some of its values (:class:`Fixed`: the
        joint fit keeps them); a list of them where :meth:`start_values` gives several
        starts (the joint fit runs from each and keeps the best on the fit record), a
        :class:`Fallback` start as ``(law, pinned, True)``.

        Parameters
        ----------
        law : FrictionModel
            The candidate's variant of the base law (:meth:`modify_law`).
        names : list of str
            The variant's free parameters (its own among them).
        fit : friction.dataset.Dataset
            The fit record (t [s], x [m], v [m/s], F [N]).
        ctx : diagnosis.candidates.Context
            Scales of the fit record (:func:`diagnosis.candidates.make_context`).
        """
        vals = self.start_values(law, names, fit, ctx)
        if isinstance(vals, list):
            # several starts: the joint fit runs from each (:func:`diagnosis.composite.
            # fit_composite`), from a Fallback only where it starts below the best fit
            return [(*self._started(law, v), True) if isinstance(v, Fallback)
                    else self._started(law, v) for v in vals]
        return self._started(law, vals)

    @staticmethod
    def _started(law, vals: dict):
        pinned = tuple(n for n, x in vals.items() if isinstance(x, Fixed))
        law = law.with_values(**vals)
        # values the start pinned (:class:`Fixed`) stay out of the joint fit
        return (law, pinned) if pinned or isinstance(vals, Fallback) else law

    def own_law_names(self, law):
        """The law parameters that are this candidate's own, :attr:`OWN` (a transfer
        calibration fits these alone).

        Parameters
        ----------
        law : FrictionModel
            The base law (a classic LuGre).
        """
        return tuple(self.OWN)

    def law_extras(self, ctx: Context) -> list:
        """The candidate's own parameters as the effect record lists them: name, start (the
        variant of a default LuGre), the joint fit's box without data
        (:func:`identification.space.default_bounds`) and unit.

        Parameters
        ----------
        ctx : diagnosis.candidates.Context
            Scales of the fit record (:func:`diagnosis.candidates.make_context`).
        """
        from identification.space import default_bounds
        law = self.modify_law(make_model("lugre"), [], ctx)[0][0]
        units = {i.name: i.unit for i in law.Params.info()}
        box = default_bounds(law, list(self.OWN))
        return [Extra(n, float(getattr(law.params, n)), *box[n], units[n]) for n in self.OWN]


def law_variants(cand: Candidate, law, base_names, ctx: Context) -> list:
    """``cand``'s law variants (:meth:`Candidate.modify_law`) as ``(law, names, form)``:
    ``form`` is the candidate fitted with that variant, ``cand`` itself unless the variant
    names another form of it (a speed map inside the law's levels with the curve kept, or
    one beside the law with the curve freed: :class:`diagnosis.effects_stribeck.
    StribeckMap`).

    Parameters
    ----------
    cand : Candidate
        The candidate (specialised to ``law``).
    law : FrictionModel
        The base law.
    base_names : list of str
        Its free parameters.
    ctx : Context
        Scales of the fit record.
    """
    out = []
    for v in cand.modify_law(law, base_names, ctx):
        if len(v) not in (2, 3) or (len(v) == 3 and not isinstance(v[2], Candidate)):
            raise ValueError(f"{cand.name}.modify_law gave the variant {v!r}: each must be "
                             f"(law, names) or (law, names, form), form a Candidate")
        out.append((v[0], v[1], v[2] if len(v) == 3 else cand))
    return out


def best_variant(fits, ctx: Context):
    """The fit of a candidate's law variants to keep: of the (composite, fit NRMSE) pairs
    ``fits``, the best-fitting one whose fitted size is practical (its form's
    ``practical`` on the law's values and extras is ''), else the best-fitting one (None
    for no fits). A variant whose form asks for a gain (``variant_gain(law)`` < 1, the
    more flexible form of a candidate) competes only where its NRMSE is below that share
    of the best of the others'. A variant that fits the record better with a presliding crossed within
    a sample or one that spans the stroke draws the base's own behaviour or a spring,
    not the effect; the candidate's practical variant is then its own form (session 36:
    an XML-350 junction-peeling record fitted best by blocks beside the bristle 0.25 um
    long, named ``gms`` through the slip-blocks before them).

    Parameters
    ----------
    fits : list of (Composite, float)
        Each law variant's joint fit and its fit NRMSE [-].
    ctx : Context
        Scales of the fit record (:func:`make_context`).
    """
    def nameable(comp) -> bool:
        form = comp.effects[0] if comp.effects else None
        if form is None:
            return True
        return not form.practical({**comp.describe()["params"], **comp.extras}, ctx)

    def gain(comp) -> float:
        form = comp.effects[0] if comp.effects else None
        return float(getattr(form, "variant_gain", lambda law: 1.0)(comp.law))
    fits = sorted(fits, key=lambda fc: fc[1])
    # a variant that asks for a gain (``variant_gain`` < 1: it is the more flexible form)
    # is kept only where it fits below that share of the best plain variant's NRMSE
    plain = [cost for comp, cost in fits if gain(comp) >= 1.0]
    fits = [(comp, cost) for comp, cost in fits
            if gain(comp) >= 1.0 or not plain or cost < gain(comp) * min(plain)]
    return next((fc for fc in fits if nameable(fc[0])), fits[0] if fits else None)


def levels_inside(law) -> bool:
    """Whether ``law`` can carry friction levels inside its bristle dynamics (a classic
    LuGre: :meth:`friction.lugre.LuGre.simulate_level`), where the ``inside`` forms of
    ``load``, ``stribeck_shape``, ``drift``, ``acceleration`` and ``position`` act."""
    return type(law).__name__ == "LuGre" and hasattr(law, "simulate_level")


#: smallest relative level an inside form passes to the bristle dynamics [-]: a fit can
#: then never reverse or null the friction, whatever its extras do
MIN_INSIDE_LEVEL = 0.05


def inside_level(level) -> np.ndarray:
    """A relative level [-] as an inside form gives it to the law (:meth:`friction.lugre.
    LuGre.simulate_level`): held at :data:`MIN_INSIDE_LEVEL` or above."""
    return np.clip(level, MIN_INSIDE_LEVEL, None)


def with_inside_form(cand: Candidate, law, base_names, form) -> list:
    """``cand``'s law variants (:meth:`Candidate.modify_law`) when it also has a form
    ``form`` (a :class:`Candidate` subclass) that scales its level inside the bristle
    dynamics: the output form, and where ``law`` can carry it (:func:`levels_inside`) the
    inside form beside it, the better on the fit record kept (:func:`law_variants`)."""
    out = [(law, list(base_names))]
    if levels_inside(law):
        out.append((law, list(base_names), form(cand.name, cand.description, cand.stage,
                                                cand.tags)))
    return out


def _sig_neg(v, ctx):
    # smooth indicator of the negative direction: a sign change is not a step in measured data
    return 0.5 * (1.0 - np.tanh(v / (0.02 * ctx.sv)))


#: longest time constant of the acceleration filters of ``acceleration`` and ``inertia``
#: [samples]: a measured acceleration is differentiated and filtered, and at a low sample
#: rate (the press's 100 Hz) it chatters from sample to sample during fast events
MAX_FILTER_SAMPLES = 8


def _first_order(u, dt, tau):
    """Causal first-order lag tau dy/dt + y = u (step-invariant, starts settled)."""
    if tau <= 0.0:
        return u
    e = np.exp(-dt / tau)
    return lfilter([1.0 - e], [1.0, -e], u, zi=[u[0] * e])[0]


def _zero_phase(u, dt, tau):
    """The first-order lag run forward and backward: smoothing without a time shift."""
    if tau <= 0.0:
        return u
    return _first_order(_first_order(u, dt, tau)[::-1], dt, tau)[::-1]


def _subsample(n, most: int = 6000) -> np.ndarray:
    """Evenly spaced indices of at most ``most`` of ``n`` samples (for start grids)."""
    return np.arange(0, n, max(1, -(-n // most)))


#: smallest eigenvalue ratio of the normal equations :func:`_lsq` solves directly: a
#: condition number of the columns below 1e5, far from where the SVD solve's ``rcond``
#: (1e-10 of the largest singular value) drops a direction, so both give the full solution
#: (the coefficients to about 1e-6, the sum of squares, flat there, far finer)
NORMAL_EQ_RATIO = 1e-10


def _lsq(A, b):
    """Least squares of ``A c ~ b``: (sum of squared residuals, c).

    The data starts solve thousands of these on tall, thin columns (14,000 x 3-12): the
    normal equations take a fifth to an eighth of the time of LAPACK's SVD solve
    (``gelsd``) and give its solution where the columns are well conditioned
    (:data:`NORMAL_EQ_RATIO`); elsewhere the SVD solve with ``rcond`` 1e-10 runs as
    before (it drops the directions below that)."""
    n, k = A.shape
    if n >= 4 * k and k:
        G = A.T @ A
        # (columns with a NaN or an inf take the SVD solve, and its error)
        w, V = np.linalg.eigh(G) if np.all(np.isfinite(G)) else (np.zeros(1), None)
        if w[0] > NORMAL_EQ_RATIO * w[-1]:
            c = V @ ((V.T @ (A.T @ b)) / w)
            res = b - A @ c
            return float(res @ res), c
    c, *_ = np.linalg.lstsq(A, b, rcond=1e-10)
    res = b - A @ c
    return float(res @ res), c


def _sse_beside(B, b):
    """Sum of squared residuals [N^2] of ``b`` once the columns ``B`` (the base's basis rows,
    or ``None``) have taken what they can of it."""
    return _lsq(B, b)[0] if B is not None else float(b @ b)


def _basis_rows(basis, rows):
    """The rows ``rows`` of a start's ``basis`` (:func:`diagnosis.composite.base_basis`), or
    ``None`` when there is none to fit beside."""
    return None if basis is None or basis.shape[1] == 0 else basis[rows]


def _residual_after(fixed, nuis, b, columns):
    """``sse(p)``: the sum of squared residuals of ``b`` fitted by ``columns(p)`` with the
    columns ``fixed`` (a list) and ``nuis`` (or None) beside them, as :func:`_lsq` gives it,
    with what ``fixed`` and ``nuis`` fit of everything taken out once (a grid over ``p``
    then solves only for the columns that change)."""
    A = [np.column_stack(fixed)] if fixed else []
    if nuis is not None:
        A.append(nuis)
    Q = None
    if A:
        u, sv, _ = np.linalg.svd(np.column_stack(A), full_matrices=False)
        Q = u[:, sv > 1e-10 * sv[0]]
    y = b - Q @ (Q.T @ b) if Q is not None else b

    def sse(p):
        X = np.column_stack(columns(p))
        if Q is not None:
            X = X - Q @ (Q.T @ X)
        return _lsq(X, y)[0]
    return sse


def _with(A, nuis):
    """The columns ``A`` with the columns ``nuis`` beside them (``nuis`` None: ``A``)."""
    return A if nuis is None else np.column_stack([A, nuis])


class Presliding(Candidate):
    def applicable(self, law, fit, ctx):
        if law.state_names:
            return False, f"{law.name} already has bristle dynamics"
        if law.name != "stribeck":
            return False, "presliding is added to the static Stribeck map only"
        return True, ""

    def modify_law(self, law, base_names, ctx):
        p = law.params
        lugre = make_model("lugre", sigma0=max(1e3, 1e3 * ctx.sF / max(ctx.sv, 1e-9) * 1e-1),
                           sigma1=0.0, sigma2=p.sigma2, Fc=p.Fc, Fs=p.Fs, vs=p.vs, alpha=p.alpha,
                           b=p.b, shape=p.shape, Fc_neg=p.Fc_neg, Fs_neg=p.Fs_neg,
                           vs_neg=p.vs_neg, sigma2_neg=p.sigma2_neg)
        return [(lugre, list(base_names) + ["sigma0", "sigma1"])]


def missing_columns(cand, val_sets, ctx: Context | None = None) -> str:
    """Why a candidate cannot be scored on the held-out sets ('' when it can).

    Parameters
    ----------
    cand : Candidate
        The candidate; its ``needs`` names the dataset columns its formula reads.
    val_sets : list of friction.dataset.Dataset
        The held-out records.
    ctx : Context, optional
        Scales of the fit record: given, the candidate's own
        :meth:`Candidate.held_out_reason` is asked too (whether the held-out records test
        what the fit record can teach it).

    Returns
    -------
    str
        The missing column and the records that lack it, the candidate's own reason, or
        ``''``.
    """
    for key in cand.needs:
        bad = [v.name for v in val_sets if getattr(v, key) is None]
        if bad:
            return f"the held-out data {bad} has no {key} column"
    return cand.held_out_reason(val_sets, ctx) if ctx is not None else ""

