"""Candidate builders: the diagnosis' effects as real extensions of a base friction law.

Each named effect is one record of :mod:`diagnosis.effects` (:class:`diagnosis.effects.
Effect`), whose ``candidate`` is an instance of a class here (or of a subclass of
:class:`Candidate` in the effect's own module).

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

import threading
from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from numba import njit
from scipy.signal import cont2discrete, lfilter, lfilter_zi

from friction import make_model
from friction.alignment import velocity_lag
from friction.dataset import Dataset
from friction.extensions import (DRIFT_CYCLE_NAMES, DRIFT_NAMES, DRIFT_RESET_NAMES,
                                 DRIFT_SCALES, POSITION_FORM_NAMES, POSITION_NAMES,
                                 acceleration_weight, drift_change, drift_parts,
                                 pack_extensions, position_change)

__all__ = ["Candidate", "LawCandidate", "Context", "Extra", "make_context", "velocity_lag",
           "Fixed", "Acceleration", "Load", "Drift", "Asymmetry", "AsymmetryTwins", "Position",
           "Inertia", "coupled_part", "Delay", "sensed", "unsensed", "resonant", "unresonant",
           "StribeckShape",
           "friction_heat",
           "Presliding", "MAX_FILTER_SAMPLES", "missing_columns"]



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
    return Context(sF, sv, sa, float(np.min(fit.x)), float(np.max(fit.x)), float(fit.t[0]),
                   float(fit.t[-1] - fit.t[0]), fit.dt, L0, L_span, L_hi, velocity_lag(fit),
                   position_quantum(fit.x), power)


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

    def applicable(self, law, fit, ctx: Context) -> tuple[bool, str]:
        return True, ""

    def modify_law(self, law, base_names, ctx: Context):
        """Return the list of (law, base_names) variants to try (best on fit is kept)."""
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

    def start_values(self, law, names, fit, ctx: Context) -> dict:
        """Start values of the variant ``law`` chosen on the fit record (see
        :meth:`start_law`)."""
        raise NotImplementedError

    def start_law(self, law, names, fit, ctx: Context):
        """``law`` (a :meth:`modify_law` variant) started on the data (:meth:`start_values`);
        ``(law, pinned)`` when the start pinned some of its values (:class:`Fixed`: the
        joint fit keeps them).

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
        pinned = tuple(n for n, x in vals.items() if isinstance(x, Fixed))
        law = law.with_values(**vals)
        # values the start pinned (:class:`Fixed`) stay out of the joint fit
        return (law, pinned) if pinned else law

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

def _over_onset(a, a_e):
    """The level part's drive ``max(|a| - a_e, 0)`` [m/s^2] of :class:`Acceleration`
    (:func:`friction.extensions.extension_force`'s formula)."""
    return np.maximum(np.abs(a) - a_e, 0.0)


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


class Acceleration(Candidate):
    """Seed 000's acceleration-dependent part ``f_a tanh(a / a_s) w(v)`` and a level part
    even and odd in the acceleration, ``F (1 + f_e max(|a| - a_e, 0) + f_o a)``, lagged as a
    whole (:meth:`apply`); a fitted part that is a mass term defers to ``inertia``
    (:meth:`defers`).

    The level part: accelerating either way loads the contact - rolling elements that
    must be spun up skid, a guide's moment load moves between its ball rows, the chamber
    pressure that accelerates a cylinder presses its seal. The odd part changes sign with
    ``a`` (it lowers friction while braking), so such truths were beyond it: on the grid's
    rolling-skid, moment-load and cylinder-pressure forms 1 of 60 cases was named.

    The odd level part ``f_o a``: what the signed acceleration moves onto the contact. A
    carriage whose centre of mass sits above its drive line pitches, and moves normal load
    from one support onto another of other friction; an iron-core linear motor's pull grows
    with its thrust ``m a + F`` (its cross term); a screw's thrust presses its nut. The
    additive odd part cannot draw it (it does not follow the direction of sliding), nor the
    even one (it does not change sign with ``a``): the grid's weight-transfer form was named
    in 0 of 20 cases, the motor-attraction form in 4.

    Tried in session 11 and not kept: a frictional memory *inside* the bristle dynamics
    (Hess and Soom: the level ``(g(v_lagged) / g(v))^k``, ``k`` and the memory time
    started on a grid). On the damping rig's frictional-memory truth the base fitted
    without it had absorbed the memory as a Stribeck spike ten times the true ``Fs``, and
    the joint fit stayed in that basin (held-out gap unchanged, ``k`` back to 0); with the
    base at its true values the same form closed 0.4 of the gap, not the truth's 0.9.
    """
    #: largest exponent of the velocity weight [-]: the weight peaks at |v| = m_a v_c, and
    #: its width relative to the peak speed narrows as 1 / sqrt(m_a)
    MAX_M = 4.0

    def extras(self, ctx):
        # m_a: where along |v| the part acts (friction.extensions.acceleration_weight). 0
        # (seed 000) is largest at standstill; a frictional memory of the Stribeck curve
        # (Hess and Soom) or a rate-and-state level acts as the curve's slope, most at a
        # speed near the Stribeck velocity and not at all at standstill. With the weight
        # fixed at exp(-|v| / v_c) those truths closed 0.02-0.28 of gaps their own form
        # closes 0.6-0.9 (issue 15); with the exponent, slip memory is named in 6 of 20
        # grid cases (was 3), frictional memory still in 3: its lag is a fifth of the
        # motion's time scale, beyond any first-order form in the acceleration
        return [Extra("f_a", 0.0, -ctx.sF, ctx.sF, "N"),
                Extra("a_s", 0.3 * ctx.sa, 0.02 * ctx.sa, 3 * ctx.sa, "m/s^2"),
                Extra("v_c", ctx.sv, 0.05 * ctx.sv, 20 * ctx.sv, "m/s"),
                Extra("m_a", 0.0, 0.0, self.MAX_M, "1"),
                # the level part, even in a: what accelerating either way loads (skidding
                # rolling elements, a guide's moment load, a cylinder's pressurised seal)
                # raises the levels whatever the sign of a; the odd part above cannot: it
                # changes sign with a, so it lowers friction when braking
                Extra("f_e", 0.0, -1.0 / ctx.sa, 1.0 / ctx.sa, "s^2/m"),
                Extra("a_e", 0.0, 0.0, 0.9 * ctx.sa, "m/s^2"),
                # the level part odd in a: what the signed acceleration moves onto the
                # contact (a pitching carriage's load transfer, a motor's thrust pull)
                Extra("f_o", 0.0, -1.0 / ctx.sa, 1.0 / ctx.sa, "s^2/m")]

    #: onsets of the level part tried by the start, x the acceleration scale [-], and the
    #: share of the odd part's squared residual below which the start keeps it [-]
    LEVEL_ONSETS, LEVEL_GAIN = (0.0, 0.5), 0.7
    #: smallest share of the fit record the friction force must spend in either direction
    #: for the odd level part to be tried [-]: with the force of one sign (the press's
    #: working stroke) F f_o a is a mass error scaled by the level, and it took 5 of the
    #: grid's inertia truths there by ties of < 1 % of the gap
    ODD_LEVEL_BOTH_WAYS = 0.2

    def force_extras(self, ctx):
        # the frictional lag of seed 000 (Eq. 11, its "lag" form: tau dF_d/dt + F_d =
        # F_d^ss(v, a)); started at one sample (at 0 the residual is flat in it)
        lag = Extra("tau_lag", ctx.dt, 0.0, MAX_FILTER_SAMPLES * ctx.dt, "s")
        return self.extras(ctx) + [lag]

    def start(self, fit, Ff, r, ctx, basis=None) -> dict:
        """Start values from the base's fit residual ``r`` [N]: the part is linear in
        ``f_a``, ``f_e`` and ``f_o``, so every point of a grid of ``a_s``, ``v_c``, ``m_a``,
        the even level part's onset :attr:`LEVEL_ONSETS` (and the lag, where fitted) is
        solved by least squares and the best one starts the fit (from ``f_a = 0`` the
        residual is flat in the others, and the weight's peak is not convex). The level
        parts are added greedily, the better of the even and the odd one first, each kept
        only where it leaves less than :attr:`LEVEL_GAIN` of the squared residual before
        it, else pinned off (:class:`Fixed`). The changes the base's own parameters can
        make (``basis``, :func:`diagnosis.composite.base_basis`) are fitted beside each
        point: a base identified without the part has absorbed what its Stribeck curve can
        mimic of it."""
        sub = _subsample(fit.t.size)
        B = _basis_rows(basis, sub)
        a, v, rr = fit.a, fit.v, r
        ex = {e.name: e for e in self.extras(ctx)}
        lags = [0.0, ctx.dt, 3.0 * ctx.dt] if "tau_lag" in {
            e.name for e in self.force_extras(ctx)} else [0.0]
        # the level parts' columns at each onset and lag (beside every point of the grid)
        evens = {(a_e, lag): _first_order(_over_onset(a, a_e * ctx.sa), fit.dt, lag)[sub]
                 * Ff[sub]
                 for a_e in self.LEVEL_ONSETS for lag in lags}
        odds = {lag: _first_order(a, fit.dt, lag)[sub] * Ff[sub] for lag in lags}
        # the odd level part only where the friction acts both ways (else a mass term)
        both_ways = min(np.mean(Ff > 0), np.mean(Ff < 0)) >= self.ODD_LEVEL_BOTH_WAYS
        raw = float(rr[sub] @ rr[sub])
        # best start without a level part, with the even, the odd and both level parts
        best = {k: (raw, {}) for k in ("", "e", "o", "eo")}
        off = {"f_e": Fixed(0.0), "a_e": Fixed(0.0), "f_o": Fixed(0.0)}

        def scan(kinds):
            # every point of the grid, the level parts of ``kinds`` beside its part
            for a_s in (0.1 * ctx.sa, 0.3 * ctx.sa, ctx.sa):
                ta = np.tanh(a / a_s)
                for v_c in np.geomspace(ex["v_c"].lo, ex["v_c"].hi, 7):
                    for m in (0.0, 1.0, 2.0, self.MAX_M):
                        b0 = ta * acceleration_weight(v, v_c, m)
                        for lag in lags:
                            b = _first_order(b0, fit.dt, lag)[sub]
                            odd = {"a_s": a_s, "v_c": float(v_c), "m_a": m, "tau_lag": lag}
                            # (kind, level columns beside the part, their names, onset)
                            trials = [("", [], (), 0.0), ("o", [odds[lag]], ("f_o",), 0.0)]
                            for a_e in self.LEVEL_ONSETS:
                                ev = evens[(a_e, lag)]
                                trials += [("e", [ev], ("f_e",), a_e * ctx.sa),
                                           ("eo", [ev, odds[lag]], ("f_e", "f_o"),
                                            a_e * ctx.sa)]
                            for kind, cols, put, a_e in trials:
                                if kind not in kinds:
                                    continue
                                sse, c = _lsq(_with(np.column_stack([b] + cols), B),
                                              rr[sub])
                                if sse < best[kind][0]:
                                    vals = {**odd, **off, "f_a": c[0]}
                                    vals.update({k: c[j] for j, k in enumerate(put, 1)})
                                    if "f_e" in put:
                                        vals["a_e"] = a_e
                                    best[kind] = (sse, vals)
        singles = ("e", "o") if both_ways else ("e",)
        scan(("",) + singles)
        # the level parts only where they change the fit: fitted beside a part that is
        # enough, the even one followed the fit record's noise (the damping rig's short
        # records: 4 of its named memory, aging and flash-temperature truths lost, the level
        # part's start 0.82-0.98 of the odd part's squared residual; the skid and
        # moment-load truths it reaches on the valve, 0.42-0.45); both together only
        # where one is kept (so their grid is scanned only then)
        kind = ""
        one = min(singles, key=lambda k: best[k][0])
        if best[one][0] < self.LEVEL_GAIN * best[""][0]:
            kind = one
            if both_ways:
                scan(("eo",))
                if best["eo"][0] < self.LEVEL_GAIN * best[one][0]:
                    kind = "eo"
        p = best[kind][1]
        for k in ("f_a", "f_e", "f_o"):
            if k in p and not isinstance(p[k], Fixed):
                p[k] = float(np.clip(p[k], ex[k].lo, ex[k].hi))
        return p

    #: share of its fitted part's energy on the fit record a mass term ``dm a`` explains
    #: (R^2) from which the part *is* a mass error [-]: fitted to the grid's mass-error
    #: truths (filtered, flexible, geared, added-mass) the part reached R^2 0.97-0.999 on
    #: the valve and the XML-350 (a_s at its top, v_c 3-20 x the top speed: linear in a,
    #: flat in v) and named `acceleration` where it closed a few % more than `inertia`;
    #: fitted to the acceleration truths of other physics (memory, aging, flash
    #: temperature, skid, lagged differences) on the valve, damping rig and XML-350 it
    #: stayed at 0.13-0.82
    MASS_LIKE_R2 = 0.9
    #: smallest share of the whole part's energy on the fit record that its odd part must
    #: carry for a mass-like odd part to make the candidate a mass error [-]
    MASS_SHARE = 0.5

    def defers(self, p, fit, ctx):
        """``("inertia", why)`` when the fitted part is a mass term on ``fit``: at least
        :attr:`MASS_LIKE_R2` of its odd part's energy follows ``dm a`` (an
        acceleration-proportional force that does not depend on the speed is the inverse
        dynamics' mass error, whatever its size), and the odd part carries at least
        :attr:`MASS_SHARE` of the energy of the whole part (the level part on the measured
        force: a level raised by |a| follows the direction of sliding, not the sign of a, so
        it is no mass term; a gear stage's losses on its reflected inertia add one of a
        third of the mass term's size, which stays the mass error's). The odd part is
        tested whole and as its two terms, the additive one and the odd level part ``F f_o
        a`` (a mass term on a one-way stroke), each carrying at least that share.
        Parameters as :meth:`Candidate.defers`."""
        if not p["a_s"] > 0:
            raise ValueError(f"a_s = {p['a_s']!r} is out of bounds: the acceleration scale "
                             f"must be > 0 [m/s^2]")
        a = np.asarray(fit.a, float)
        F = np.asarray(fit.F, float)
        # the odd parts: the additive one and the odd level part (on a one-way stroke, the
        # press's, the level times a is a mass term: beside a small additive part that is
        # not, the sum was not, and 5 of the grid's inertia truths there went to this part)
        odd = p["f_a"] * np.tanh(a / p["a_s"]) * acceleration_weight(fit.v, p["v_c"],
                                                                     p.get("m_a", 0.0))
        odd_level = F * p.get("f_o", 0.0) * a
        lev = F * p.get("f_e", 0.0) * _over_onset(a, p.get("a_e", 0.0))
        aa = float(a @ a)
        whole = float((odd + odd_level) @ (odd + odd_level)) + float(lev @ lev)
        r2 = 0.0
        for part in (odd + odd_level, odd, odd_level):
            ee = float(part @ part)
            if not (aa > 0 and ee > 0) or ee < self.MASS_SHARE * whole:
                continue
            r2 = max(r2, float(a @ part) ** 2 / (aa * ee))
        if r2 < self.MASS_LIKE_R2:
            return "", ""
        return "inertia", (f"its fitted part is a mass term ({100 * r2:.0f} % of it follows "
                           f"dm a on the fit record, >= {100 * self.MASS_LIKE_R2:.0f} %): "
                           f"a mass error, the inertia candidate's form")

    def apply(self, F, p, data, ctx):
        # acceleration-dependent part (seed 000): grows with |a|, fades with |v|, zero at a = 0,
        # and lags behind them as a whole. (Lagging the acceleration alone, the form before,
        # closed 0.57-0.60 of held-out gaps that the truth closes 0.83-0.92 on the rig, the
        # press and the isolator; lagging the part, 0.81-0.84.)
        Fd = p["f_a"] * np.tanh(data.a / p["a_s"]) * acceleration_weight(
            data.v, p["v_c"], p.get("m_a", 0.0))
        lag = p.get("tau_lag", 0.0)
        # the level part (even in a), lagged as the rest: a cylinder's pressure follows
        # the force demand through the oil's compliance
        lev = p.get("f_e", 0.0) * _over_onset(data.a, p.get("a_e", 0.0)) \
            + p.get("f_o", 0.0) * data.a
        return F * (1.0 + _first_order(lev, data.dt, lag)) + _first_order(Fd, data.dt, lag)


@njit(cache=True, nogil=True)
def _slip_memory(u, x, D):
    out = np.empty(u.size)
    y = u[0]
    for k in range(u.size):
        step = abs(x[k] - x[k - 1]) if k > 0 else 0.0
        y = u[k] + (y - u[k]) * np.exp(-step / D)
        out[k] = y
    return out


def slip_memory(u, x, D) -> np.ndarray:
    """``u`` remembered over the travel: ``dy/ds = (u - y) / D`` along the slid distance
    ``s`` (exact per sample, started at ``u[0]``); ``D <= 0``: ``u`` itself.

    Parameters
    ----------
    u : array_like
        The signal remembered (e.g. the relative load) [any unit].
    x : array_like
        Position [m] at the same samples.
    D : float
        Memory travel [m] (finite; ValueError otherwise, and for ``u`` and ``x`` of
        different lengths).
    """
    u = np.ascontiguousarray(u, dtype=float)
    x = np.ascontiguousarray(x, dtype=float)
    if u.shape != x.shape:
        raise ValueError(f"slip_memory needs u and x of one length, got {u.size} and {x.size}")
    if not np.isfinite(D):
        raise ValueError(f"D = {D!r} is not finite: the memory travel must be a number [m]")
    if not D > 0.0:
        return u
    return _slip_memory(u, x, float(D))


class Load(Candidate):
    needs = ("load",)

    def applicable(self, law, fit, ctx):
        if fit.load is None:
            return False, "the data has no load column"
        if ctx.L0 is None or not ctx.L0 > 0 or ctx.L_span <= 1e-9 * abs(ctx.L0):
            return False, "the load does not vary in the fit data"
        return True, ""

    def extras(self, ctx):
        # k_L = 1: friction proportional to the load (Amontons); 0: independent of it. Seed
        # 004's levels are affine in the load (Fc = Fc0 + k1 F_sigma, k1 < 0 at low speed),
        # so k_L may be negative down to where the level would vanish at the largest load
        k_lo = -min(1.0, 0.9 * ctx.L0 / max(ctx.L_hi - ctx.L0, 1e-12 * ctx.L0))
        return [Extra("k_L", 0.0, k_lo, 1.0, "1")]

    #: memory travels the start tries, x the fit record's stroke [-], and the share of the
    #: instantaneous form's squared residual below which it keeps the memory [-]
    MEMORY_TRAVELS, MEMORY_GAIN = (0.03, 0.1, 0.3, 1.0), 0.7

    def force_extras(self, ctx):
        # seed 004 gives the viscous coefficient its own load slope (k3 of Eq. 11; on the
        # press it is most of the load effect), so the level factor alone cannot carry it
        # a seal pressurised from one side (the pneumatic cylinder's O-ring) grows with the
        # load in one direction of motion and hardly in the other: k_L_neg is the level
        # slope for v < 0 (k_L then holds for v > 0)
        s = 2.0 * ctx.sF / ctx.sv
        k = self.extras(ctx)[0]
        # a memory of the load over the travel (D_L [m], its slope k_Lm): after a change of
        # the normal load the contact's junctions are renewed only by sliding, so the
        # levels follow it over a slip distance (Linker and Dieterich 1992; Bowden and
        # Tabor's junctions). D_L = 0: none
        stroke = max(ctx.x_hi - ctx.x_lo, 1e-12)
        return [k, Extra("k_L_neg", 0.0, k.lo, k.hi, "1"), Extra("k_v", 0.0, -s, s, "N.s/m"),
                Extra("k_Lm", 0.0, k.lo, k.hi, "1"), Extra("D_L", 0.0, 0.0, 3.0 * stroke, "m")]

    def slope_rel(self, p, data, ctx):
        """The level's relative change ``k (L - L0) / L0 + k_Lm (L_m - L0) / L0`` [-] along
        ``data``: the load's slope (``k_L``, ``k_L_neg`` for v < 0 where fitted) and its
        memory over the travel ``D_L`` [m] (:func:`slip_memory`)."""
        rel = (data.load - ctx.L0) / ctx.L0
        k = p["k_L"]
        if "k_L_neg" in p:
            s = _sig_neg(data.v, ctx)
            k = k * (1.0 - s) + p["k_L_neg"] * s
        out = k * rel
        if p.get("k_Lm", 0.0) and p.get("D_L", 0.0) > 0.0:
            out = out + p["k_Lm"] * slip_memory(rel, data.x, p["D_L"])
        return out

    def start(self, fit, Ff, r, ctx, basis=None) -> dict:
        """The load's memory started on the data: at each travel of
        :attr:`MEMORY_TRAVELS` the level columns (slopes and memory) are solved by least
        squares beside the base's own changes (``basis``); the memory is kept where it
        leaves less than :attr:`MEMORY_GAIN` of the instantaneous form's squared residual,
        else pinned off (:class:`Fixed`). Parameters as :attr:`Candidate.start`."""
        sub = _subsample(fit.t.size)
        B = _basis_rows(basis, sub)
        rel = (fit.load - ctx.L0) / ctx.L0
        s = _sig_neg(fit.v, ctx)
        inst = np.column_stack([Ff * rel * (1.0 - s), Ff * rel * s, rel * fit.v])[sub]
        sse0, _ = _lsq(_with(inst, B), r[sub])
        stroke = max(ctx.x_hi - ctx.x_lo, 1e-12)
        best = (sse0, None)
        for f in self.MEMORY_TRAVELS:
            mem = (Ff * slip_memory(rel, fit.x, f * stroke))[sub]
            sse, c = _lsq(_with(np.column_stack([inst, mem]), B), r[sub])
            if sse < best[0]:
                best = (sse, (f * stroke, float(c[3])))
        if best[1] is None or not best[0] < self.MEMORY_GAIN * sse0:
            return {"k_Lm": Fixed(0.0), "D_L": Fixed(0.0)}
        ex = {e.name: e for e in self.force_extras(ctx)}
        return {"D_L": best[1][0], "k_Lm": float(np.clip(best[1][1], ex["k_Lm"].lo,
                                                          ex["k_Lm"].hi))}

    def apply(self, F, p, data, ctx):
        # friction levels affine in the normal load (seed 004 Eqs. 9-11), relative to the
        # fit data's mean load: F (1 + k_L (L - L0) / L0), never of the opposite sign, with
        # its own slope k_L_neg for v < 0 where fitted and the load's memory over the
        # travel, plus a viscous part k_v v (L - L0) / L0
        rel = (data.load - ctx.L0) / ctx.L0
        F = F * np.clip(1.0 + self.slope_rel(p, data, ctx), 0.0, None)
        k_v = p.get("k_v", 0.0)
        return F + k_v * rel * data.v if k_v else F

    def specialise(self, law):
        # a classic LuGre carries the load's levels inside its bristle dynamics
        if type(law).__name__ == "LuGre" and hasattr(law, "simulate_level"):
            return LoadInside(self.name, self.description, self.stage, self.tags)
        return self


class LoadInside(Load):
    """``load`` of a classic LuGre law at the force level: the levels affine in the load
    (``k_L``, ``k_L_neg``) scale the Stribeck curve and viscous term *inside* the bristle
    dynamics, as seed 004 writes them (Eqs. 9-11); the viscous slope ``k_v`` acts on the
    output, and so does a level slope ``k_Lo`` of its own (a load-dependent force that does
    not pass through the contact's bristle: with the inside slope alone the pneumatic
    O-ring's load closed 66 % of its held-out gap, the output form 75 %, both 79 %). On
    the forging press the output form closed 0.10-0.38 of load truths of other physics
    (Hertzian L^(2/3), a one-sided seal, a squeeze film) and ``asymmetry`` took their
    names (load and direction move together there); inside, 0.72-0.99. The trajectory
    level and the ``friction_effects`` FMU block keep the output form (:class:`Load`)."""

    def inside(self, p, data, ctx):
        return np.clip(1.0 + self.slope_rel(p, data, ctx), 0.05, None)

    def force_extras(self, ctx):
        k = self.extras(ctx)[0]
        return super().force_extras(ctx) + [Extra("k_Lo", 0.0, k.lo, k.hi, "1")]

    def apply(self, F, p, data, ctx):
        rel = (data.load - ctx.L0) / ctx.L0
        F = F * np.clip(1.0 + p.get("k_Lo", 0.0) * rel, 0.0, None)
        k_v = p.get("k_v", 0.0)
        return F + k_v * rel * data.v if k_v else F


class Drift(Candidate):
    """Friction level changing over time: ``F (1 + d(t))`` with ``d`` a linear trend, a
    saturating change of time constant ``tau_sat`` and a step at ``t_step``
    (:func:`friction.extensions.drift_change`). A warm-up that levels off within the record
    is the saturating part (the linear form alone closed 23 % of a +60 % warm-up of time
    constant T/3: it cannot bend), a change of lubricant or a regulated temperature is the
    step; a level that comes and goes with the ambient is the periodic part (two
    harmonics), one that builds up and drops back at once (an oxide film spalling at its
    critical thickness, debris purged) the resetting part ``k_r1 u + k_r2 u^2`` of the
    phase ``u`` since the last reset; their time scales are chosen on the data
    (:meth:`start`).

    At the force level a further part follows the contact's heating by its own friction
    power: ``k_heat h(t)``, ``h`` the first-order lag (time constant ``tau_heat``) of the
    measured |F v| over its mean on the fit record, from cold at its start
    (:func:`friction_heat`; thermal drift is the commonest of real drives, Bhushan 2013,
    Introduction to Tribology, ch. 5). It rises in busy stretches and falls back over
    dwells, which no function of time alone forecasts: on the open grid's isolator a
    thermal drift (time constant a third of the record) was closed -0.10 by the parts in
    time, 0.97 with it. It reads the measured force, so the trajectory level and the FMU
    blocks keep the parts in time.

    Tried in session 19 and not kept: a change that accelerates, ``k_run (exp((t - t0) /
    tau_run) - 1) / (exp(T / tau_run) - 1)`` (oil that oxidises autocatalytically once its
    antioxidant is spent), a third form the start's forecast chose among. On the grid's 300
    drift cases (the eleventh and twelfth families' included), same seeds: 196 -> 189 named
    (thermal drift 7 -> 9, a humidity cycle 18 -> 12: the accelerating form fitted part of
    its cycle, and the periodic form no longer beat it by the margin it needs; Archard
    wear, seal relaxation and a ZDDP tribofilm one fewer each); the antioxidant form stayed
    8 of 20, its runaway still within the noise at the end of the fit record.

    Tried in session 10 and not kept: the same levels inside a classic LuGre's bristle
    dynamics (as :class:`LoadInside`): on the valve and the damping rig 1 drift case
    gained, 6 lost; on the forging press no change."""

    def extras(self, ctx):
        T = ctx.T or 1.0
        return [Extra("k_drift", 0.0, -2.0, 2.0, "1"),
                Extra("k_sat", 0.0, -2.0, 2.0, "1"),
                # a saturating change over the fit record, not a start-up transient of its
                # first samples (which would free the level of the record's start)
                Extra("tau_sat", 0.3 * T, self.STEP_MARGIN / 3.0 * T, 3.0 * T, "s"),
                Extra("k_step", 0.0, -1.0, 1.0, "1"),
                # a step is seen on both sides within the fit record: one at its very end
                # would only set a free level for whatever follows (the held-out part)
                Extra("t_step", ctx.t0 + 0.5 * T, ctx.t0 + self.STEP_MARGIN * T,
                      ctx.t0 + (1.0 - self.STEP_MARGIN) * T, "s"),
                Extra("w_step", 0.01 * T, max(ctx.dt, 1e-4 * T), 0.1 * T, "s"),
                # a level that comes and goes: seen at least CYCLES_SEEN times in the fit
                # record, so what repeats is told from a change that happens once
                Extra("P_cyc", 0.5 * T, self.CYCLE_MIN * T, T / self.CYCLES_SEEN, "s"),
                Extra("k_c1", 0.0, -1.0, 1.0, "1"), Extra("k_s1", 0.0, -1.0, 1.0, "1"),
                Extra("k_c2", 0.0, -1.0, 1.0, "1"), Extra("k_s2", 0.0, -1.0, 1.0, "1"),
                # a level that builds up and resets, with the periodic part's periods; its
                # period and reset time are chosen on the data and kept (:meth:`start`)
                Extra("P_rst", 0.5 * T, self.CYCLE_MIN * T, T / self.CYCLES_SEEN, "s"),
                Extra("t_rst", ctx.t0 + 0.5 * T, ctx.t0, ctx.t0 + T, "s"),
                Extra("k_r1", 0.0, -2.0, 2.0, "1"), Extra("k_r2", 0.0, -2.0, 2.0, "1")]

    #: shortest share of the fit record on either side of the step, and over which the
    #: saturating part may complete 95 % of its change (tau_sat >= STEP_MARGIN / 3 x T) [-]
    STEP_MARGIN = 0.15
    #: fewest periods of the periodic part in the fit record [-], and its shortest period as
    #: a share of the fit record [-]: a level cycling over a few motion cycles is an ambient
    #: or a maintenance interval, not the motion's own periodicity
    CYCLES_SEEN, CYCLE_MIN = 1.25, 0.15

    def trajectory_extras(self, ctx):
        # the saturating, step and periodic parts start from a force-level residual
        # (:meth:`start`); the trajectory level keeps the linear trend
        return self.extras(ctx)[:1]

    def force_extras(self, ctx):
        # the heating part reads the record's measured friction power (:func:`friction_heat`)
        T = ctx.T or 1.0
        return self.extras(ctx) + [
            Extra("k_heat", 0.0, -2.0, 2.0, "1"),
            Extra("tau_heat", 0.3 * T, self.HEAT_TAUS[0] * T, self.HEAT_TAUS[-1] * T, "s")]

    def _packed(self, p, ctx):
        return pack_extensions({"drift": {n: p[n] for n in DRIFT_NAMES if n in p}},
                               t0=ctx.t0, T=ctx.T or 1.0)

    def apply(self, F, p, data, ctx):
        # friction level changing over time (warming, running-in, a lubricant change, an
        # ambient that cycles), and with the contact's heating by its own friction power
        e = self._packed(p, ctx)
        d = 1.0 + drift_change(data.t, e, self._parts(data.t, e))
        if p.get("k_heat", 0.0) != 0.0:
            d = d + p["k_heat"] * friction_heat(data, p["tau_heat"], ctx)
        return F * d

    #: the last time scales' parts, per thread (:meth:`_parts`), and how many are kept: a
    #: Jacobian's columns that move a time scale (the step's time and width) come back to
    #: the point's own scales
    _last, PARTS_KEPT = threading.local(), 4

    def _parts(self, t, e):
        """The drift's time-scale parts (:func:`friction.extensions.drift_parts`) at times
        ``t`` [s], kept for the next calls with the same array and time scales: a fit's
        Jacobian moves the amplitudes alone in most columns, and the parts' exp, tanh and
        cos cost most of the drift's share of an evaluation (the same bits)."""
        key = e[list(DRIFT_SCALES)].tobytes()
        kept = getattr(self._last, "entries", None)
        if kept is None:
            kept = self._last.entries = []
        for entry in kept:
            if entry[0] is t and entry[1] == key:
                return entry[2]
        parts = drift_parts(t, e)
        kept.insert(0, (t, key, parts))
        del kept[self.PARTS_KEPT:]
        return parts


    #: share of the fit record the forms are fitted on when the start chooses among them;
    #: the rest is forecast, as the held-out part will be
    FORECAST_SPLIT = 0.8
    #: the forms the start chooses among by forecasting (parts of the formula switched on):
    #: with or without the linear trend, the one part that grows without bound beyond the
    #: record. (Choosing among every single part and pair too follows the noise of the
    #: record's last fifth: of the grid's 100 drift cases 65 named, 63 before, 12 gained and
    #: 10 lost; adding the trend alone to the two: 63; the trend question alone: 72)
    FORMS = (("sat", "step"), ("lin", "sat", "step"))
    #: the form of a level that comes and goes, and the share of the chosen form's squared
    #: residual on the whole fit record below which it is taken instead [-]. (Not by
    #: forecasting the last fifth: an interval lubrication's shots leave it quiet, and every
    #: form that forecasts nothing wins there; the periodic part fitted 0.52 of the
    #: once-only forms' squared residual of such a valve record, found the shots' period
    #: within 6 % and forecast only the quiet fifth worse)
    CYCLE_FORM, CYCLE_GAIN = ("cyc",), 0.8
    #: the resetting part is also taken where the chosen once-only form explains at least
    #: REPEAT_EXPLAINS of what the base's own changes leave [-], and the resetting part at
    #: least REPEAT_SHARE of what that form explains [-]: an oxide film that grows and
    #: spalls once inside the fit record is drawn nearly as well by a trend, a saturating
    #: change and a step, which forecast no next spall. (Not the harmonics: with this rule
    #: they took 2 particle-ingress cases on the press and a thermal drift on the damping
    #: rig from a saturating change and a step, and forecast them worse than nothing)
    REPEAT_EXPLAINS, REPEAT_SHARE = 0.3, 0.95
    #: correlation of the velocity with itself one period later from which the motion
    #: repeats with that period [-]: a level cycling with the motion's own period (or a
    #: multiple of it) cannot be told from an effect of the motion, so such periods are not
    #: tried (EMPS's periodic excitation, held out on a second record of it: the periodic
    #: part took 10 % of the gap from the direction twins)
    MOTION_REPEAT = 0.8
    #: each part's parameters (pinned where the chosen form leaves the part out) and the
    #: value that switches it off
    PARTS = {"lin": ("k_drift",), "sat": ("k_sat", "tau_sat"),
             "step": ("k_step", "t_step", "w_step"), "cyc": DRIFT_CYCLE_NAMES,
             "rst": DRIFT_RESET_NAMES, "heat": ("k_heat", "tau_heat")}
    #: the periodic part's amplitudes, in the order of its regressors
    CYCLE_AMPS = DRIFT_CYCLE_NAMES[1:]
    #: the resetting part's form, and the reset phases tried at each period [-]: a level
    #: that builds up and drops back at once (an oxide film that spalls at its critical
    #: thickness, debris purged) forecasts its next reset; two harmonics round it off (of
    #: a film growing as sqrt(t) and spalling every 0.45 T, fitted on the first 0.7 T, two
    #: harmonics forecast 49 % of the rest's variance, three 70 %, u and u^2 93 %)
    RESET_FORM, RESET_PHASES = ("rst",), 16
    #: the heating part's form (forecast beside :attr:`FORMS`: a level that follows the
    #: contact's temperature, heated by the friction power and cooling with the time
    #: constant ``tau_heat``, rises in busy stretches and falls back over dwells, which no
    #: function of time alone forecasts); its time constants, x the fit record [-]
    HEAT_FORM = ("heat",)
    HEAT_TAUS = tuple(np.geomspace(0.05, 3.0, 16))

    def start(self, fit, Ff, r, ctx, basis=None) -> dict:
        """Start values from the base's fit residual ``r`` [N] against its friction part
        ``Ff`` [N]: ``r ~ Ff d(t)`` is linear in the amplitudes; the saturation time
        constant, the step's time and width and the period are chosen on grids by least
        squares, with the changes the base's own parameters can make (``basis``,
        :func:`diagnosis.composite.base_basis`) fitted beside them: a base identified
        without the drift has absorbed what its levels can of it (a step where the
        protocol changes speed reads as a viscous term), so the residual alone does not
        show when the change happened.

        Whether the change has the linear trend (:attr:`FORMS`) is chosen by forecasting:
        each form is fitted on the first :attr:`FORECAST_SPLIT` of the fit record and scored
        on the rest, the question the held-out part asks; a part left out is pinned off
        (:class:`Fixed`), and without the trend the saturating part's time constant is
        chosen at most T/3 and kept. Fitted together, a trend and a saturating change of
        opposite signs cancel inside the record and part outside it (a lubricant step on
        the valve: fit NRMSE 0.064 -> 0.021, held out 0.103 -> 0.163). A level that comes
        and goes (:attr:`CYCLE_FORM`, alone) or builds up and resets (:attr:`RESET_FORM`,
        alone, where it leaves less than :attr:`CYCLE_GAIN` of the former's squared residual)
        replaces the chosen form where it leaves less than :attr:`CYCLE_GAIN` of its squared
        residual on the whole fit record; the resetting part also where it explains nearly
        as much of a large change (:attr:`REPEAT_EXPLAINS`, :attr:`REPEAT_SHARE`). A reset
        is seen inside the fit record, at least :attr:`STEP_MARGIN` T from its ends; the
        period and the reset time are kept as chosen (the formula jumps there: no gradient
        moves them). The heating part (:attr:`HEAT_FORM`, alone; a force-level extra) is
        forecast beside the forms in time and taken where it forecasts best and also
        draws the whole fit record better than the best of them."""
        T = ctx.T or 1.0
        sub = _subsample(fit.t.size)
        t, f, rr = fit.t[sub], Ff[sub], r[sub]
        B = _basis_rows(basis, sub)
        ex = {e.name: e for e in self.extras(ctx)}
        early = t < ctx.t0 + self.FORECAST_SPLIT * T
        best = (np.inf, None)
        heats, fc = {}, {}

        def heat(tau, tq):
            # the heat state on the whole fit record, read at the times ``tq``
            if tau not in heats:
                heats[tau] = friction_heat(fit, tau, ctx)
            return np.interp(tq, fit.t, heats[tau])
        for form in self.FORMS + ((self.HEAT_FORM,) if ctx.power else ()):
            if early.sum() < 10 or (~early).sum() < 5:  # too short to forecast
                best = (0.0, self.FORMS[1])
                break
            # the step's time inside the early part, with the start's margin
            ts_hi = ctx.t0 + (self.FORECAST_SPLIT - self.STEP_MARGIN) * T
            # (on the residual as it is: with the base's changes beside them, the forms
            # forecast alike and the choice follows the noise)
            cols, scales = self._form_columns(form, t[early], f[early], rr[early], ctx, ex,
                                              ts_hi, heat=heat)
            c = _lsq(cols, rr[early])[1]
            late, _ = self._form_columns(form, t[~early], f[~early], None, ctx, ex, ts_hi,
                                         fixed=scales, heat=heat)
            miss = rr[~early] - late @ c
            sse = float(miss @ miss)
            fc[form] = sse
            if sse < best[0]:
                best = (sse, form)
        form = best[1]
        if form == self.HEAT_FORM:
            # the heating part only where it also draws the whole fit record better than
            # the best form in time: over one record the work done and the time run nearly
            # together, and the last fifth alone let it take a lubricant step on the press
            # (held-out excess closed 1.0 -> -1.2)
            timed = min((f0 for f0 in fc if f0 != self.HEAT_FORM), key=fc.get)
            full = {frm: _lsq(_with(self._form_columns(frm, t, f, rr, ctx, ex, ex["t_step"].hi,
                                                       nuis=B, heat=heat)[0], B), rr)[0]
                    for frm in (timed, self.HEAT_FORM)}
            if not full[self.HEAT_FORM] < full[timed]:
                form = timed
        periods = [P for P in np.geomspace(ex["P_cyc"].lo, ex["P_cyc"].hi, 40)
                   if not _repeats(fit.t, fit.v, P, self.MOTION_REPEAT)]
        chosen = []
        for frm in (form,) + ((self.CYCLE_FORM, self.RESET_FORM) if periods else ()):
            cols, grid = self._form_columns(frm, t, f, rr, ctx, ex, ex["t_step"].hi,
                                            nuis=B, periods=periods, heat=heat)
            if cols.shape[1]:
                chosen.append((*_lsq(_with(cols, B), rr), frm, grid))
        sse, c, form, grid = chosen[0]
        if len(chosen) > 1:
            # the resetting part only where it leaves clearly less than the harmonics (a
            # sawtooth draws a sine's rise, and its reset then forecasts a drop that never
            # comes)
            alt = chosen[1]
            if len(chosen) > 2 and chosen[2][0] < self.CYCLE_GAIN * alt[0]:
                alt = chosen[2]
            # what the base's own changes leave, the forms' common reference
            sse0 = _sse_beside(B, rr)
            if alt[0] < self.CYCLE_GAIN * sse or (
                    alt[2] == self.RESET_FORM and sse0 - sse >= self.REPEAT_EXPLAINS * sse0
                    and sse0 - alt[0] >= self.REPEAT_SHARE * (sse0 - sse)):
                _, c, form, grid = alt
        amp = dict(zip(self._amplitudes(form), c))
        out = {"k_drift": amp.get("k_drift", 0.0), "k_sat": amp.get("k_sat", 0.0),
               "tau_sat": grid.get("tau", ex["tau_sat"].x0), "k_step": amp.get("k_step", 0.0),
               "t_step": grid.get("ts", ex["t_step"].x0), "w_step": grid.get("w", ex["w_step"].x0),
               "P_cyc": grid.get("P", ex["P_cyc"].x0),
               **{k: amp.get(k, 0.0) for k in self.CYCLE_AMPS},
               "P_rst": grid.get("Pr", ex["P_rst"].x0), "t_rst": grid.get("tr", ex["t_rst"].x0),
               "k_r1": amp.get("k_r1", 0.0), "k_r2": amp.get("k_r2", 0.0)}
        if ctx.power:
            ex.update({e.name: e for e in self.force_extras(ctx)})
            out.update({"k_heat": amp.get("k_heat", 0.0),
                        "tau_heat": grid.get("th", ex["tau_heat"].x0)})
        out = {k: float(np.clip(v, ex[k].lo, ex[k].hi)) for k, v in out.items()}
        for part, names in self.PARTS.items():
            if part not in form:
                for n in names:
                    if n in out:
                        out[n] = Fixed(out[n])
        if "cyc" not in form:
            out["P_cyc"] = Fixed(0.0)  # the periodic part off
        if "rst" not in form:
            out["P_rst"] = Fixed(0.0)  # the resetting part off
        else:
            out["P_rst"], out["t_rst"] = Fixed(out["P_rst"]), Fixed(out["t_rst"])
        if "lin" not in form:
            # its time constant stays where it levels off inside the record (a clean
            # damping-rig record took tau_sat = 2.1 T and was named drift for a 2 % rise)
            out["tau_sat"] = Fixed(out["tau_sat"])
        return out

    def _amplitudes(self, form):
        """The amplitude names of the regressors of ``form``, in :meth:`_form_columns`'
        order."""
        names = {"lin": ("k_drift",), "sat": ("k_sat",), "step": ("k_step",),
                 "cyc": self.CYCLE_AMPS, "rst": ("k_r1", "k_r2"), "heat": ("k_heat",)}
        return [n for part in ("lin", "cyc", "rst", "sat", "step", "heat") if part in form
                for n in names[part]]

    def _reset_grid(self, periods, ctx):
        """The (period [s], reset time [s]) pairs the start tries: :attr:`RESET_PHASES`
        reset times per period, each pair with a reset at least :attr:`STEP_MARGIN` of the
        fit record from its ends."""
        T = ctx.T or 1.0
        lo, hi = ctx.t0 + self.STEP_MARGIN * T, ctx.t0 + (1.0 - self.STEP_MARGIN) * T
        out = []
        for P in periods:
            for tr in ctx.t0 + P * np.arange(self.RESET_PHASES) / self.RESET_PHASES:
                k = np.ceil((lo - tr) / P)  # the first reset from lo on
                if tr + k * P <= hi:
                    out.append((float(P), float(tr)))
        return out

    @staticmethod
    def _reset_columns(t, f, P, tr):
        u = _reset_phase(t, P, tr)
        return [f * u, f * u * u]

    def _form_columns(self, form, t, f, rr, ctx, ex, ts_hi, fixed=None, nuis=None,
                      periods=(), heat=None):
        """Regressors of the parts ``form`` of ``Ff d(t)`` at times ``t`` [s], their time
        scales chosen on ``rr`` by least squares over grids (or taken from ``fixed``), with
        the columns ``nuis`` fitted beside them; the periodic part's period chosen from
        ``periods`` [s]; the heating part's state ``heat(tau, t)`` [-]; the columns and the
        chosen ``{"tau", "ts", "w", "P", "Pr", "tr", "th"}``."""
        T = ctx.T or 1.0
        lin = f * (t - ctx.t0) / T

        def sat(tau):
            return f * (1.0 - np.exp(-np.clip(t - ctx.t0, 0.0, None) / tau))

        def step(ts, w):
            return f * 0.5 * (1.0 + np.tanh(0.5 * (t - ts) / w))

        def cyc(P):
            psi = 2.0 * np.pi * (t - ctx.t0) / P
            return [f * np.cos(psi), f * np.sin(psi), f * np.cos(2 * psi), f * np.sin(2 * psi)]
        grid = dict(fixed or {})
        base = [lin] if "lin" in form else []
        if "cyc" in form:
            if "P" not in grid:
                grid["P"] = min(periods, key=lambda P: _lsq(
                    _with(np.column_stack(base + cyc(P)), nuis), rr)[0])
            base = base + cyc(grid["P"])
        if "rst" in form:
            if "Pr" not in grid:
                resets = self._reset_grid(periods, ctx)
                if not resets:
                    return np.empty((t.size, 0)), grid

                sse = _residual_after(base, nuis, rr,
                                      lambda pt: self._reset_columns(t, f, *pt))
                P, tr = min(resets, key=sse)
                # refined twice between the grid's neighbours, each time 4 x finer: the
                # squared residual drops sharply where the resets line up, and a
                # forecast's resets drift by the period's error once per period
                dlog = np.log((periods[-1] / periods[0]) ** (1.0 / max(len(periods) - 1, 1)))
                shift = 1.0 / self.RESET_PHASES
                for _ in range(2):
                    P, tr = min(((float(P * np.exp(k * dlog)), float(tr + j * shift * P))
                                 for k in np.linspace(-1, 1, 9) for j in np.linspace(-1, 1, 9)),
                                key=sse)
                    dlog, shift = dlog / 4.0, shift / 4.0
                # the same resets, from the first one at or after t0 (the box of t_rst)
                grid["Pr"], grid["tr"] = P, ctx.t0 + (tr - ctx.t0) % P
            base = base + self._reset_columns(t, f, grid["Pr"], grid["tr"])
        if "sat" in form:
            if "tau" not in grid:
                # without the trend, a saturating change levels off inside the record
                # (95 % by its end): one slower is a trend in disguise
                hi = ex["tau_sat"].hi if "lin" in form else max(T / 3.0, ex["tau_sat"].lo)
                taus = np.geomspace(ex["tau_sat"].lo, hi, 24)
                grid["tau"] = min(taus, key=lambda tau: _lsq(
                    _with(np.column_stack(base + [sat(tau)]), nuis), rr)[0])
            base = base + [sat(grid["tau"])]
        if "step" in form:
            if "ts" not in grid:
                if nuis is None:
                    # after the smooth parts: a step is what they leave
                    r1 = rr - np.column_stack(base) @ _lsq(np.column_stack(base), rr)[1] \
                        if base else rr
                    lead = []
                else:
                    # the smooth parts and the base's changes are fitted with each step,
                    # not before it (they would take the step's share first)
                    r1, lead = rr, base
                tss = np.linspace(ex["t_step"].lo, max(ts_hi, ex["t_step"].lo), 49)
                ws = [float(np.clip(w, ex["w_step"].lo, ex["w_step"].hi))
                      for w in (ex["w_step"].lo, 0.01 * T, 0.05 * T)]
                grid["ts"], grid["w"] = min(
                    ((ts, w) for w in ws for ts in tss),
                    key=lambda p: _lsq(_with(np.column_stack(lead + [step(*p)]), nuis),
                                       r1)[0])
            base = base + [step(grid["ts"], grid["w"])]
        if "heat" in form:
            if "th" not in grid:
                grid["th"] = min((k * T for k in self.HEAT_TAUS), key=lambda tau: _lsq(
                    _with(np.column_stack(base + [f * heat(tau, t)]), nuis), rr)[0])
            base = base + [f * heat(grid["th"], t)]
        return np.column_stack(base), grid


def _reset_phase(t, P, tr):
    """Phase u in [0, 1) [-] at times ``t`` [s] of a part that resets every ``P`` [s], once
    at ``tr`` [s]."""
    u = (t - tr) / P
    return u - np.floor(u)


def _repeats(t, v, lag, level) -> bool:
    """Whether the motion ``v`` [m/s] at times ``t`` [s] repeats itself after ``lag`` [s]:
    the correlation of v(t) with v(t + lag), over the times where both are recorded,
    reaches ``level`` [-]."""
    later = t + lag <= t[-1]
    if later.sum() < 10:
        return False
    a, b = v[later], np.interp(t[later] + lag, t, v)
    if not (np.std(a) > 0 and np.std(b) > 0):
        return False
    return float(np.corrcoef(a, b)[0, 1]) >= level


def _subsample(n, most: int = 6000) -> np.ndarray:
    """Evenly spaced indices of at most ``most`` of ``n`` samples (for start grids)."""
    return np.arange(0, n, max(1, -(-n // most)))


def _lsq(A, b):
    """Least squares of ``A c ~ b``: (sum of squared residuals, c)."""
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


class Asymmetry(Candidate):
    def extras(self, ctx):
        return [Extra("b", 0.0, -ctx.sF, ctx.sF, "N"),
                Extra("dF_neg", 0.0, -ctx.sF, ctx.sF, "N"),
                Extra("dsigma2_neg", 0.0, -2 * ctx.sF / ctx.sv, 2 * ctx.sF / ctx.sv, "N.s/m")]

    def apply(self, F, p, data, ctx):
        # direction-dependent levels and an offset (seeds 000, 003)
        s = _sig_neg(data.v, ctx)
        return F + p["b"] - p["dF_neg"] * s + p["dsigma2_neg"] * data.v * s

    def specialise(self, law):
        # a law with direction twins carries the asymmetry inside itself, so the levels act
        # through the bristle state in sticking and crawling too (the additive form only
        # sees the sign of v, which is undecided near rest)
        if set(law.twins) >= {"Fc", "Fs", "sigma2"} and hasattr(law.params, "b"):
            return AsymmetryTwins(self.name, self.description, "modify_law", self.tags)
        return self


class AsymmetryTwins(Candidate):
    """``asymmetry`` for laws with direction twins: Fc, Fs, sigma2 (and vs, where the law
    has its twin) for v < 0 and the offset b become free parameters of the law itself."""
    TWINS = ("Fc", "Fs", "sigma2")
    #: twins freed where the law has them: a Stribeck velocity of its own for v < 0 (a
    #: breakaway that differs with the direction rarely keeps its Stribeck velocity; with
    #: Fs_neg alone the candidate closed 0.0-0.3 of such gaps, issue 15)
    OPTIONAL = ("vs",)

    def _twins(self, law):
        return self.TWINS + tuple(n for n in self.OPTIONAL if law.twins.get(n))

    def modify_law(self, law, base_names, ctx):
        p = law.params
        twins = self._twins(law)
        start = {law.twins[n]: float(getattr(p, n)) for n in twins}
        names = list(base_names) + [law.twins[n] for n in twins if law.twins[n]
                                    not in base_names]
        if "b" not in names:
            names.append("b")
        return [(law.with_values(**start), names)]

    def own_law_names(self, law):
        # the offset is this effect's too: identify's default base frees it on the fit
        # record, but a held-out condition with its own offset is the asymmetry's to carry
        return tuple(law.twins[n] for n in self._twins(law)) + ("b",)


class Position(Candidate):
    """Friction level varying along the stroke, ``F (1 + m(x))``
    (:func:`friction.extensions.position_change`): a 12-knot map for trends and defects a
    tenth of the stroke wide, a periodic waviness (two harmonics) whose wavelength is chosen
    on the data, and a local defect whose centre and width are chosen on the data
    (:meth:`start`). The 12-knot map alone closed 1 % of a waviness of period 7 % of the
    stroke: its knots are 9 % apart.

    At the force level the waviness has an *additive* twin of the same wavelength,
    ``g(x)`` [N] (:data:`ADD_NAMES`): a force of the position alone, the same in both
    directions of motion - a linear motor's detent (cogging) force, a spring or cable
    along the stroke - which a level scale, changing sign with the velocity, cannot make
    (the grid's cogging truth: 0 of 16 named with the scale alone), and its smooth course
    over the stroke (:attr:`POLY_NAMES`: a spring, counterweight or cable along the stroke,
    a carriage on a sagging beam). The trajectory level and the FMU blocks keep the scaled
    map."""
    stage_doc = "friction level scaled along the stroke, and a force of the position"
    NAMES = POSITION_NAMES + POSITION_FORM_NAMES
    #: amplitudes of the additive periodic force [N] (cosine, sine; first and second
    #: harmonic of the waviness' wavelength ``lambda_x``), fitted at the force level only
    ADD_NAMES = ("q_c1", "q_s1", "q_c2", "q_s2")
    #: amplitudes of the additive force's smooth course over the stroke [N] (Legendre
    #: polynomials of degree 1-3 of the position across the fit record's stroke, constant
    #: beyond it): a spring, a counterweight or a cable along the stroke, a carriage on a
    #: sagging beam, gravity along an axis whose tilt changes with the position
    POLY_NAMES = ("q_x1", "q_x2", "q_x3")
    #: shortest wavelength and narrowest defect, in samples of travel at the top speed:
    #: finer than this along the motion the data cannot tell a map from noise
    MIN_SAMPLES = 8.0

    #: smallest share of the held-out samples at positions inside the fit record's stroke
    #: [-]: beyond it the map is constant by construction, so on held-out positions the fit
    #: never passed it is a level change of the whole held-out part - a drift in disguise
    #: (the press's one-way strokes: 0 % inside; its drift truths were named `position`
    #: in 5 grid and 4 sealed cases)
    MIN_REVISIT = 0.5

    def held_out_reason(self, val_sets, ctx):
        x = np.concatenate([np.asarray(v.x, float) for v in val_sets])
        inside = float(np.mean((x >= ctx.x_lo) & (x <= ctx.x_hi))) if x.size else 0.0
        if inside < self.MIN_REVISIT:
            return (f"only {100 * inside:.0f} % of the held-out positions lie inside the fit "
                    f"record's stroke [{ctx.x_lo:.4g}, {ctx.x_hi:.4g}] m (needs "
                    f"{100 * self.MIN_REVISIT:.0f} %): a map along the stroke learned there "
                    f"is not tested")
        return ""

    def _span(self, ctx):
        return max(ctx.x_hi - ctx.x_lo, 1e-12)

    def extras(self, ctx):
        span = self._span(ctx)
        step = self.MIN_SAMPLES * ctx.sv * ctx.dt
        lam_lo = min(max(0.01 * span, step), 0.25 * span)
        w_lo = min(max(0.004 * span, 0.5 * step), 0.05 * span)
        return ([Extra(n, 0.0, -1.0, 1.0, "1") for n in POSITION_NAMES]
                + [Extra("lambda_x", 0.1 * span, lam_lo, 0.5 * span, "m")]
                + [Extra(n, 0.0, -1.0, 1.0, "1") for n in ("p_c1", "p_s1", "p_c2", "p_s2")]
                + [Extra("d_x", 0.0, -1.0, 1.0, "1"),
                   Extra("x_d", 0.5 * (ctx.x_lo + ctx.x_hi), ctx.x_lo, ctx.x_lo + span, "m"),
                   Extra("w_d", 0.05 * span, w_lo, 0.2 * span, "m")])

    def trajectory_extras(self, ctx):
        # the waviness and the local defect start from a force-level residual
        # (:meth:`start`); the trajectory level keeps the knot map
        return self.extras(ctx)[:len(POSITION_NAMES)]

    def force_extras(self, ctx):
        return self.extras(ctx) + [Extra(n, 0.0, -ctx.sF, ctx.sF, "N")
                                   for n in self.ADD_NAMES + self.POLY_NAMES]

    def _poly(self, x, ctx):
        """The smooth additive force's columns at positions ``x`` [m]: P1, P2, P3 of the
        position mapped onto [-1, 1] across the fit record's stroke (clipped beyond)."""
        u = np.clip(2.0 * (np.asarray(x, float) - ctx.x_lo) / self._span(ctx) - 1.0,
                    -1.0, 1.0)
        return u, 0.5 * (3.0 * u * u - 1.0), 0.5 * (5.0 * u ** 3 - 3.0 * u)

    def _packed(self, p, ctx):
        return pack_extensions({"position": {n: p[n] for n in self.NAMES if n in p}},
                               x_lo=ctx.x_lo, x_hi=ctx.x_lo + self._span(ctx))

    @staticmethod
    def _harmonics(x, x_lo, lam):
        """cos, sin of the waviness' phase and of twice it at positions ``x`` [m]."""
        ph = 2.0 * np.pi * (x - x_lo) / lam
        return np.cos(ph), np.sin(ph), np.cos(2.0 * ph), np.sin(2.0 * ph)

    def _additive(self, p, x, ctx):
        """The force of the position alone [N] (zero without its amplitudes): periodic and
        smooth along the stroke."""
        out = 0.0
        if any(p.get(n, 0.0) for n in self.POLY_NAMES):
            out = sum(p.get(n, 0.0) * c for n, c in zip(self.POLY_NAMES, self._poly(x, ctx)))
        if not any(p.get(n, 0.0) for n in self.ADD_NAMES):
            return out
        if not (np.isfinite(p["lambda_x"]) and p["lambda_x"] > 0):
            raise ValueError(f"lambda_x = {p['lambda_x']!r} is out of bounds: the wavelength "
                             f"of the force of the position must be > 0 [m]")
        return out + sum(p[n] * h for n, h in zip(self.ADD_NAMES,
                                                  self._harmonics(x, ctx.x_lo, p["lambda_x"])))

    def apply(self, F, p, data, ctx):
        # friction level varying along the stroke: a friction map over the fit record's
        # stroke (a worn section, guide waviness or screw pitch, a local defect); and a
        # force of the position alone (cogging), the same in both directions
        return (F * (1.0 + position_change(data.x, self._packed(p, ctx)))
                + self._additive(p, data.x, ctx))

    #: the map is linear in the knot values, the waviness' amplitudes and the defect's
    #: height, the additive force in its amplitudes
    exact_extras = (POSITION_NAMES + ("p_c1", "p_s1", "p_c2", "p_s2", "d_x") + ADD_NAMES
                    + POLY_NAMES)

    def jac(self, F, p, data, ctx):
        """``d apply / dF = 1 + m(x)``; the columns of :attr:`exact_extras` exactly, ``F``
        times the part of the map they scale (the others are differenced). Parameters as
        :meth:`Candidate.jac`."""
        span = self._span(ctx)
        x = data.x
        # the map is linear in these: piecewise-linear hats between the knots (constant
        # beyond the stroke), the harmonics, the defect's bump
        knots = np.linspace(ctx.x_lo, ctx.x_lo + span, len(POSITION_NAMES) + 1)
        eye = np.eye(knots.size)
        cols = {n: F * np.interp(x, knots, eye[k]) for k, n in enumerate(POSITION_NAMES, 1)}
        harm = self._harmonics(x, ctx.x_lo, p["lambda_x"])
        cols.update({n: F * h for n, h in zip(("p_c1", "p_s1", "p_c2", "p_s2"), harm)})
        cols.update({n: h for n, h in zip(self.ADD_NAMES, harm)})
        cols.update({n: c for n, c in zip(self.POLY_NAMES, self._poly(x, ctx))})
        cols["d_x"] = F * np.exp(-0.5 * ((x - p["x_d"]) / p["w_d"]) ** 2)
        return 1.0 + position_change(x, self._packed(p, ctx)), cols

    def start(self, fit, Ff, r, ctx, basis=None) -> dict:
        """Start values from the base's fit residual ``r`` [N] against its friction part
        ``Ff`` [N]: ``r ~ Ff m(x)`` is linear in the knot values and amplitudes; the
        wavelength is chosen on a grid even in wavenumber (a quarter period of slip over the
        stroke between neighbours), the defect's centre and width on a grid, each by least
        squares on what the parts before it leave, with the changes the base's own
        parameters can make (``basis``, :func:`diagnosis.composite.base_basis`) fitted
        beside every part."""
        span = self._span(ctx)
        ex = {e.name: e for e in self.extras(ctx)}
        sub = _subsample(fit.t.size)
        x, f, rr = fit.x[sub], Ff[sub], r[sub]
        B = _basis_rows(basis, sub)
        knots = np.linspace(ctx.x_lo, ctx.x_lo + span, len(POSITION_NAMES) + 1)
        H = np.column_stack([np.interp(x, knots, np.eye(knots.size)[k])
                             for k in range(1, knots.size)]) * f[:, None]
        _, c = _lsq(_with(H, B), rr)
        r1 = rr - _with(H, B) @ c

        def periodic(lam):
            # the waviness scales the level; its additive twin is a force of x alone
            harm = np.column_stack(self._harmonics(x, ctx.x_lo, lam))
            return np.column_stack([harm * f[:, None], harm])
        k_lo, k_hi = 1.0 / ex["lambda_x"].hi, 1.0 / ex["lambda_x"].lo
        waves = np.arange(k_lo, k_hi, 0.25 / span)
        sse = [_lsq(_with(periodic(1.0 / k), B), r1)[0] for k in waves]
        lam = float(1.0 / waves[int(np.argmin(sse))])
        P = periodic(lam)
        _, pc = _lsq(_with(P, B), r1)
        r2 = r1 - _with(P, B) @ pc
        best = (np.inf, None, None)
        for w in np.geomspace(ex["w_d"].lo, ex["w_d"].hi, 8):
            for xd in np.linspace(ctx.x_lo, ctx.x_lo + span, 61):
                g = f * np.exp(-0.5 * ((x - xd) / w) ** 2)
                e, _ = _lsq(_with(g[:, None], B), r2)
                if e < best[0]:
                    best = (e, xd, w)
        _, xd, w = best
        G = (f * np.exp(-0.5 * ((x - xd) / w) ** 2))[:, None]
        Q = np.column_stack(self._poly(x, ctx))
        HPG = np.column_stack([H, P, G, Q])
        _, allc = _lsq(_with(HPG, B), rr)
        allc = allc[:HPG.shape[1]]
        nk, nq = len(POSITION_NAMES), len(self.POLY_NAMES)
        out = dict(zip(POSITION_NAMES, allc[:nk]))
        out.update(zip(("p_c1", "p_s1", "p_c2", "p_s2") + self.ADD_NAMES,
                       allc[nk:-1 - nq]))
        out.update(zip(self.POLY_NAMES, allc[-nq:]))
        out.update(lambda_x=lam, d_x=allc[-1 - nq], x_d=xd, w_d=w)
        ex.update({e.name: e for e in self.force_extras(ctx)})
        return {k: float(np.clip(v, ex[k].lo, ex[k].hi)) for k, v in out.items()}


@njit(cache=True, nogil=True)
def _coupled_part(v, dt, tau, g_up, g_dn):
    out = np.empty(v.size)
    vp = v[0]  # the part moves with the axis at the start
    for k in range(v.size):
        # exact over the sample with the axis speed held: slipping at the grip while the
        # speed difference needs more, then relaxing to the axis's speed through the lag
        d = v[k] - vp
        d0 = d
        rest = dt
        if d > g_up * tau:
            t1 = (d - g_up * tau) / g_up if g_up > 0.0 else np.inf
            if t1 >= dt:
                d -= g_up * dt
                rest = 0.0
            else:
                d = g_up * tau
                rest = dt - t1
        elif d < -g_dn * tau:
            t1 = (-d - g_dn * tau) / g_dn if g_dn > 0.0 else np.inf
            if t1 >= dt:
                d += g_dn * dt
                rest = 0.0
            else:
                d = -g_dn * tau
                rest = dt - t1
        if rest > 0.0:
            d *= np.exp(-rest / tau)
        out[k] = (d0 - d) / dt  # (the part's change of speed, without v's rounding)
        vp += d0 - d
    return out


def coupled_part(v, dt, tau, g_up, g_dn) -> np.ndarray:
    """Acceleration [m/s^2] of a part coupled to the axis: its speed follows the axis's
    ``v`` through a lag ``tau`` [s] while the coupling holds, and its acceleration is
    capped at ``g_up`` forward and ``g_dn`` backward [m/s^2] where the coupling slips (a
    payload on its friction, a slipping or one-way clutch, an induction coupling past its
    pull-out); exact steps (stable at any ``dt``), the part starts at the axis's speed.
    The force the axis spends on a part of mass m is m times it.

    Parameters
    ----------
    v : array_like
        Axis velocity [m/s] at the samples.
    dt : float
        Sample interval [s] (> 0).
    tau : float
        Coupling time constant [s] (> 0).
    g_up, g_dn : float
        Largest forward and backward acceleration the coupling gives the part [m/s^2]
        (>= 0; 0: a one-way coupling; inf: it never slips).
    """
    v = np.ascontiguousarray(v, dtype=float)
    bad = np.flatnonzero(~np.isfinite(v))
    if bad.size:
        raise ValueError(f"v[{bad[0]}] = {float(v[bad[0]])!r} is not finite: the axis velocity must "
                         f"be a number at every sample [m/s]")
    for name, val in (("dt", dt), ("tau", tau)):
        if not (np.isfinite(val) and val > 0):
            raise ValueError(f"{name} = {val!r} is out of bounds: must be > 0 [s]")
    for name, val in (("g_up", g_up), ("g_dn", g_dn)):
        if not val >= 0:  # inf: a coupling that never slips
            raise ValueError(f"{name} = {val!r} is out of bounds: must be >= 0 [m/s^2]")
    return _coupled_part(v, float(dt), float(tau), float(g_up), float(g_dn))


class Inertia(Candidate):
    """A mass the inverse dynamics misses: ``dm`` rigidly on the axis (its acceleration
    smoothed by ``tau_af`` as the data's may be), a trend of it over the record (``dm_t``:
    a tank that empties, material taken on), its change along the stroke (``dm_x``: a cable
    chain, a linkage or arm whose reflected inertia depends on the configuration) and with
    the speed (``dm_v``, times (v / sv)^2: flyweights or clutch shoes that move out as a
    shaft speeds up), and a part of mass ``m_p`` *coupled* to the axis
    (:func:`coupled_part`: through a lag ``tau_p``, slipping beyond the accelerations
    ``g_up`` / ``g_dn`` the coupling can give it).

    The coupled part: a flywheel behind a freewheel, a payload held by its friction, a roll
    behind an induction coupling, a loose part in a pocket - each is a mass the axis
    accelerates only as far as its coupling lets it. The rigid ``dm a`` alone reached 2-7 of
    20 grid cases of those forms (freewheel, rattling, sliding payload). The coupled part and
    the variations are measured-force extras (:meth:`force_extras`, zero: the plain mass error);
    the trajectory level changes the plant's mass by ``dm``.
    """
    #: coupling time constants the start tries, x the sample interval [-], and the grips,
    #: x the acceleration scale [-] (inf: the coupling never slips)
    START_TAUS = (3.0, 10.0, 30.0, 100.0)
    START_GRIPS = (0.1, 0.3, 0.6, np.inf)
    #: share of the rigid mass's squared residual below which the start keeps the part, and
    #: the constant mass's below which it keeps the trend [-]
    PART_GAIN = 0.8

    def extras(self, ctx):
        m = ctx.sF / ctx.sa
        return [Extra("dm", 0.0, -m, m, "kg")]

    def force_extras(self, ctx):
        m = ctx.sF / ctx.sa
        # the inverse dynamics smooths the acceleration it uses offline (zero phase), the a
        # column of the data may not be; started at one sample (at 0 the residual is flat)
        smooth = Extra("tau_af", ctx.dt, 0.0, MAX_FILTER_SAMPLES * ctx.dt, "s")
        return self.extras(ctx) + [
            smooth, Extra("dm_t", 0.0, -m, m, "kg"),
            # the mass across the fit record's stroke, and at its top speed over at rest: a
            # speed-dependent inertia grows several-fold (flyweights flying out)
            Extra("dm_x", 0.0, -m, m, "kg"), Extra("dm_v", 0.0, -m, 10.0 * m, "kg"),
            # a part the coupling lets slip takes less than the axis's acceleration, so
            # its mass may be many times what the force scale gives a rigid one
            Extra("m_p", 0.0, 0.0, 20.0 * m, "kg"),
            Extra("tau_p", 10.0 * ctx.dt, ctx.dt, max(0.5 * ctx.T, 2.0 * ctx.dt), "s"),
            Extra("g_up", 3.0 * ctx.sa, 0.0, 3.0 * ctx.sa, "m/s^2"),
            Extra("g_dn", 3.0 * ctx.sa, 0.0, 3.0 * ctx.sa, "m/s^2")]

    #: the mass's optional variations: their names, in the order the start tries them
    VARIATIONS = ("dm_t", "dm_x", "dm_v")

    def _columns(self, data, p, ctx):
        """The smoothed acceleration [m/s^2] and the columns of :attr:`VARIATIONS` (a times
        the record's time, position and squared speed, each scaled to about +-0.5 or 0..1
        on the fit record)."""
        a = _zero_phase(data.a, data.dt, p.get("tau_af", 0.0))
        tt = (np.asarray(data.t, float) - (ctx.t0 + 0.5 * ctx.T)) / max(ctx.T, data.dt)
        xx = ((np.asarray(data.x, float) - 0.5 * (ctx.x_lo + ctx.x_hi))
              / max(ctx.x_hi - ctx.x_lo, 1e-12))
        vv = (np.asarray(data.v, float) / ctx.sv) ** 2
        return a, {"dm_t": a * tt, "dm_x": a * xx, "dm_v": a * vv}

    def start(self, fit, Ff, r, ctx, basis=None) -> dict:
        """Start values of the coupled part and the mass's variations from the base's fit
        residual ``r`` [N]: linear in the masses. The variations (:attr:`VARIATIONS`) are
        added one at a time, the best first, each kept where it leaves less than
        :attr:`PART_GAIN` of the squared residual without it (else pinned off); then each
        coupling (lag :attr:`START_TAUS`, grips :attr:`START_GRIPS` each way) is solved by
        least squares beside the rigid mass, the kept variations and ``basis`` (the base's
        own changes, :func:`diagnosis.composite.base_basis`); the part is kept where it
        leaves less than :attr:`PART_GAIN` of the rigid mass's squared residual, else pinned
        off (:class:`Fixed`). Where it is kept the rigid form (part off) is offered beside
        it as a second start (a list of two: the joint fit keeps the better on the fit
        record)."""
        sub = _subsample(fit.t.size)
        B = _basis_rows(basis, sub)
        ex = {e.name: e for e in self.force_extras(ctx)}
        a, var = self._columns(fit, {"tau_af": ctx.dt}, ctx)
        # each variation only where the data ask for it, added greedily: fitted beside a
        # constant mass it follows the base's misfit, and a trend extrapolates into every
        # later record
        kept = []
        sse0, c0 = _lsq(_with(a[sub, None], B), r[sub])
        while True:
            trials = [(_lsq(_with(np.column_stack([a[sub]] + [var[k][sub] for k in kept + [n]]),
                                  B), r[sub]), n)
                      for n in self.VARIATIONS if n not in kept]
            if not trials:
                break
            (sse_n, c_n), n = min(trials, key=lambda tr: tr[0][0])
            if not sse_n < self.PART_GAIN * sse0:
                break
            kept.append(n)
            sse0, c0 = sse_n, c_n
        rigid = np.column_stack([a[sub]] + [var[k][sub] for k in kept])
        varied = {n: (0.0 if n in kept else Fixed(0.0)) for n in self.VARIATIONS}
        part_off = {"m_p": Fixed(0.0), "tau_p": Fixed(ex["tau_p"].x0),
                    "g_up": Fixed(ex["g_up"].hi), "g_dn": Fixed(ex["g_dn"].hi)}
        best = (sse0, {"dm": c0[0], **varied, **part_off})
        for k in self.START_TAUS:
            tau = float(np.clip(k * ctx.dt, ex["tau_p"].lo, ex["tau_p"].hi))
            for gu in self.START_GRIPS:
                for gd in self.START_GRIPS:
                    g_up = min(gu * ctx.sa, ex["g_up"].hi)
                    g_dn = min(gd * ctx.sa, ex["g_dn"].hi)
                    col = coupled_part(fit.v, fit.dt, tau, g_up, g_dn)[sub]
                    sse, c = _lsq(_with(np.column_stack([rigid, col]), B), r[sub])
                    if sse < best[0] and sse < self.PART_GAIN * sse0:
                        best = (sse, {"dm": c[0], **varied, "m_p": c[rigid.shape[1]],
                                      "tau_p": tau, "g_up": g_up, "g_dn": g_dn})
        p = best[1]
        # the rigid mass and its variations start at 0 (their residual is linear in them):
        # the least-squares mass fitted beside the base's changes started the joint fit in a
        # worse basin (a raw-acceleration truth on the valve closed 0.24 of the gap, not 0.75)
        del p["dm"]
        if isinstance(p["m_p"], Fixed):
            return p
        p["m_p"] = float(np.clip(p["m_p"], ex["m_p"].lo, ex["m_p"].hi))
        # and the rigid form beside it (the joint fit keeps the better on the fit record):
        # a part that fits the base's residual can hold the base's parameters where they
        # absorbed a mass error (a cable chain on the valve: Fc stayed at 3 x its value)
        return [p, {**varied, **part_off}]

    def apply(self, F, p, data, ctx):
        # mass error of the inverse dynamics leaks dm * a into the "measured" friction
        a, var = self._columns(data, p, ctx)
        out = F + p["dm"] * a
        for n in self.VARIATIONS:
            if p.get(n, 0.0) != 0.0:
                out = out + p[n] * var[n]
        if p.get("m_p", 0.0) != 0.0:
            out = out + p["m_p"] * coupled_part(data.v, data.dt, p["tau_p"], p["g_up"],
                                                p["g_dn"])
        return out


class Delay(Candidate):
    """The force channel's dynamics against the motion channels: a time shift ``delay``
    [s] (> 0: the force lags), and at the force level the force sensor's own first-order
    dynamics from the record's start (:func:`sensed`): the reading ``F + g lag(F - F(t0))``
    with the gain ``sensor_gain`` = g [-] and the rate ``sensor_rate`` [1/s] (1 / the time
    constant).

    Two sensors' physics in one formula:

    - g = -1: a piezoelectric sensor read through a charge amplifier whose feedback
      resistor lets the charge leak (time constant R C, Gautschi 2002): a first-order
      high-pass; a held force droops, and the force leads the motion, the more the slower
      the motion;
    - g > 0: a strain-gauge load cell whose spring element creeps anelastically (Zener's
      standard anelastic solid; OIML R60's creep test): a share of each change of the force
      at once, the rest late (a cell calibrated statically reads ``(F + g lag(F)) / (1 +
      g)``; the scale 1 / (1 + g) is the base's levels').

    The shift alone draws neither (a lag of the whole force): on the fourteenth family's
    charge-amplifier truth it closed -0.1-0.13 of the excess and the verdict named
    `inertia` or `position` in 11 of 20 cases; with the leak alone (g = -1), none of the
    fifteenth family's 20 creeping-load-cell cases was named.

    Then the transducer's own resonance (:func:`resonant`): a force transducer carries the
    mass mounted on it, and with its spring that is a lightly damped spring-mass system of
    natural period ``sensor_period`` [s] and damping ratio ``sensor_zeta`` [-] (Kumme 1996,
    dynamic force measurement): the reading follows a ramp late by 2 zeta / w and rings
    after each fast change of the force (a reversal, a breakaway). A first-order lag does
    not ring, and the shift draws only the lag: on the eighteenth family's mounted-mass
    truth (sealed, run once on ba95736) none of 20 cases was named; with the resonance, 13
    (valve 4, press 4, isolator 3, damping rig 2), the fitted natural period within 1 % of
    the truth's on the valve and the isolator; the XML-350's 4 stay unnamed (2 with fitted
    periods of 3.4-3.6 samples, under :attr:`PERIOD_SAMPLES`' four, 2 where the start
    keeps none). On a uniform random 272 cases of the open grid no verdict changed. The trajectory level and the FMU blocks keep the shift (a sensor's dynamics
    act on the reading, not on the plant).
    """
    MAX_SAMPLES = 25
    #: shortest shift of the force channel named ``delay`` [samples] (issue 15: "a shift
    #: smaller than a sample is not a delay"). Sampling and differentiation alone shift a
    #: record by a fraction of a sample: an integrating converter averages the force over
    #: the sample period (half a sample late), the base law's update at the sample rate
    #: differs from the continuous contact by less. The velocity channel's own lag behind
    #: the position (backward differences: half a sample, :func:`velocity_lag`) is measured
    #: on the record and added back first: the fitted shift is the force's against the
    #: velocity's. On 500 clean records (session 9) the fitted shifts reach 0.80 samples,
    #: 0.62 where the rest of the verdict would name them; 1.5 (sessions 8-9) refused 14
    #: real delays of 1.0-1.4 samples on the grid
    MIN_SAMPLES = 1.0
    #: fastest sensor rate, x 1 / the fit record's duration [-], and at most this share of
    #: the sample rate [-]: faster, the sensor's lag is a shift of a few samples
    MAX_RATE, MAX_RATE_SAMPLES = 300.0, 0.25
    #: smallest part of a held force the sensor's dynamics move over the fit record for
    #: them to be named on their own [-] (|g| (1 - exp(-rate T))): a charge leak that lets
    #: a held force droop by 5 %, a load cell that creeps by 5 %; smaller, a slow offset any
    #: drift draws, or the base's own levels
    MIN_SENSOR = 0.05
    #: fastest leak (a negative gain), x 1 / the fit record's duration [-]. Faster than a
    #: few times 1 / the record, a partial leak reads ``(1 + g) F - g / rate dF/dt``: a
    #: scale the base's levels take and a lead, the shift's work; what it draws beyond is
    #: presliding hysteresis. On session 21's grid the wrong `delay` names with a leak had
    #: 13-220 / T and g of -0.1 to -0.5; the charge-amplifier truths 0.07-15 / T (a
    #: quasi-static amplifier's time constant is seconds to hours)
    MAX_LEAK_RATE = 20.0

    def extras(self, ctx):
        d = self.MAX_SAMPLES * ctx.dt
        return [Extra("delay", 0.0, -d, d, "s", grid=51)]

    def _max_rate(self, ctx):
        return min(self.MAX_RATE / max(ctx.T, 1e-12), self.MAX_RATE_SAMPLES / ctx.dt)

    def force_extras(self, ctx):
        # the sensor's dynamics start on the data (:meth:`start`): at a zero gain the
        # residual is flat in the rate, at a zero period in the damping
        return self.extras(ctx) + [
            Extra("sensor_rate", 0.0, 0.0, self._max_rate(ctx), "1/s"),
            Extra("sensor_gain", 0.0, -1.0, 1.0, "1"),
            Extra("sensor_period", 0.0, 0.0, self.PERIOD_SAMPLES[1] * ctx.dt, "s"),
            Extra("sensor_zeta", 0.5, self.ZETA[0], self.ZETA[1], "1")]

    #: the transducer resonance's natural periods the start tries, in samples [-]: from
    #: four to 400 (the box's top: a lightly damped one lags by 2 zeta / w, 13 samples at
    #: zeta 0.1). A resonance of a shorter period has no practical size of its own
    #: (:meth:`practical`): near the Nyquist period it rings between samples, and a fit
    #: draws with it what averaging the force over the sample period makes (an integrating
    #: converter: before this bound, 6 of the first 127 clean records, 5 of the isolator
    #: and 1 of the press, were named `delay` for fitted periods of 2.0-2.9 samples,
    #: damping 0.11-0.79); from four samples on every resonance has a size of its own, by
    #: its lag or its ringing. Its damping ratios [-] (above 1 it is two lags, no ringing)
    PERIOD_SAMPLES = (4.0, 400.0)
    ZETA = (0.02, 1.0)

    def apply(self, F, p, data, ctx):
        # the force channel lags (delay > 0) the motion channels; the sensor's own dynamics:
        # its first-order leak or creep, then the transducer's resonance
        out = np.interp(data.t - p["delay"], data.t, F)
        out = sensed(out, data.dt, p.get("sensor_rate", 0.0), p.get("sensor_gain", 0.0))
        return resonant(out, data.dt, p.get("sensor_period", 0.0), p.get("sensor_zeta", 0.5))

    #: rates the start tries, x 1 / the fit record's duration [-] (those above the
    #: largest rate dropped); share of the squared residual without the sensor's dynamics
    #: below which the best of them is kept [-] (else they stay off, :class:`Fixed`): on
    #: the grid's charge-amplifier truths the start left 0.07-0.27 of it; on a clean record
    #: of the isolator whose reference truth the base cannot draw, 0.98, and the joint fit,
    #: started there, spent the leak on the fit record's misfit (held-out excess closed
    #: 0.91 -> 0.12)
    RATE_GRID = tuple(np.geomspace(MIN_SENSOR, MAX_RATE, 31))
    SENSOR_GAIN = 0.7
    #: damping ratios the start tries for the transducer's resonance [-]
    ZETA_GRID = (0.05, 0.1, 0.2, 0.4, 0.7, 1.0)

    def start(self, fit, Ff, r, ctx, basis=None) -> dict:
        """The sensor's start from the base's fit residual ``r`` [N]: for each rate of
        :attr:`RATE_GRID`, the gain that best draws ``r`` with the lag of the base's force
        ``fit.F - r`` (least squares, clipped to [-1, 1]; to [0, 1] at rates above
        :attr:`MAX_LEAK_RATE`), the changes the base's own
        parameters can make (``basis``, :func:`diagnosis.composite.base_basis`) fitted
        beside: a base identified on a sensor's reading has absorbed much of it (on the
        grid's valve truth, the charge leak added to the fitted base alone raised the
        squared residual at every rate). The best pair is kept only where it leaves less
        than :attr:`SENSOR_GAIN` of the squared residual without it, else pinned off
        (:class:`Fixed`). The shift is then gridded (:attr:`Extra.grid`)."""
        sub = _subsample(fit.t.size)
        B = _basis_rows(basis, sub)
        Fm = np.asarray(fit.F, float) - r
        rr = r[sub]
        sse0 = _sse_beside(B, rr)
        best = (sse0, 0.0, 0.0)
        top = self._max_rate(ctx)
        for k in self.RATE_GRID:
            rate = k / max(ctx.T, 1e-12)
            if rate > top:
                break
            col = sensed(Fm, fit.dt, rate, 1.0)[sub] - Fm[sub]
            sse, c = _lsq(_with(col[:, None], B), rr)
            g = float(c[0])
            lo = -1.0 if rate * ctx.T <= self.MAX_LEAK_RATE else 0.0
            if not lo <= g <= 1.0:
                g = float(np.clip(g, lo, 1.0))
                rg = rr - g * col
                sse = _sse_beside(B, rg)
            if sse < best[0]:
                best = (sse, rate, g)
        if not best[0] < self.SENSOR_GAIN * sse0:
            out = {"sensor_rate": Fixed(0.0), "sensor_gain": Fixed(0.0)}
            rate, g = 0.0, 0.0
        else:
            out = {"sensor_rate": best[1], "sensor_gain": best[2]}
            sse0, rate, g = best
        # then the transducer's resonance, on what the leak or creep leaves: for each
        # period and damping of the grid, the base's force read through it
        Fs = sensed(Fm, fit.dt, rate, g)
        rr = np.asarray(fit.F, float)[sub] - Fs[sub]
        best_res = (_sse_beside(B, rr), 0.0, 0.5)
        for P in np.geomspace(*self.PERIOD_SAMPLES, 16):
            for zeta in self.ZETA_GRID:
                col = resonant(Fs, fit.dt, P * fit.dt, zeta)[sub] - Fs[sub]
                sse = _sse_beside(B, rr - col)
                if sse < best_res[0]:
                    best_res = (sse, P * fit.dt, zeta)
        if best_res[1] > 0.0 and best_res[0] < self.SENSOR_GAIN * sse0:
            out.update({"sensor_period": best_res[1], "sensor_zeta": best_res[2]})
        else:
            out.update({"sensor_period": Fixed(0.0), "sensor_zeta": Fixed(0.5)})
        return out

    def practical(self, p, ctx) -> str:
        """Why the fitted shift and sensor dynamics are too small to name ('' when either
        is large enough)."""
        fitted = p["delay"] / ctx.dt
        n = abs(fitted + ctx.v_lag)
        rate, g = p.get("sensor_rate", 0.0), p.get("sensor_gain", 0.0)
        # a fast leak is a lead and a scale (:attr:`MAX_LEAK_RATE`): not a sensor's own size
        moved = (0.0 if g < 0.0 and rate * ctx.T > self.MAX_LEAK_RATE
                 else abs(g) * (1.0 - np.exp(-rate * ctx.T)))
        if n >= self.MIN_SAMPLES or moved >= self.MIN_SENSOR:
            return ""
        # a transducer's resonance: its lag 2 zeta / w, in samples, adds to the shift's (a
        # lag is the force channel's whatever draws it: an anti-alias filter's of a sample
        # is a delay, though a fit may give a few % of it to a fast resonance); its
        # overshoot on a step counts as a held force's move (a ringing of 5 % is a sensor's
        # own), but not within PERIOD_SAMPLES[0] samples a period (what sampling makes)
        period, zeta = p.get("sensor_period", 0.0), p.get("sensor_zeta", 0.5)
        if period > 0.0:
            r_lag = 2.0 * zeta * period / (2.0 * np.pi) / ctx.dt
            over = (float(np.exp(-zeta * np.pi / np.sqrt(1.0 - zeta * zeta)))
                    if zeta < 1 and period >= self.PERIOD_SAMPLES[0] * ctx.dt else 0.0)
            if r_lag + n >= self.MIN_SAMPLES or over >= self.MIN_SENSOR:
                return ""
        lag = (f" ({fitted:.2f} against the velocity, which lags the position by "
               f"{ctx.v_lag:.2f})" if abs(ctx.v_lag) >= 0.05 else "")
        sensor = (f", and the sensor's dynamics move a held force by {100 * moved:.1f} % "
                  f"over the fit record (< {100 * self.MIN_SENSOR:g} %)" if moved > 0 else "")
        if period > 0.0:
            sensor += (f", with its transducer resonance's lag of {r_lag:.2f} samples; the "
                       f"resonance's period of {period / ctx.dt:.1f} samples is under "
                       f"{self.PERIOD_SAMPLES[0]:g}, what averaging over the sample period "
                       f"makes" if period < self.PERIOD_SAMPLES[0] * ctx.dt else
                       f", with its transducer resonance's lag of {r_lag:.2f} samples and an "
                       f"overshoot of {100 * over:.1f} % (< {100 * self.MIN_SENSOR:g} %)")
        return (f"its shift of {n:.2f} samples{lag} is below {self.MIN_SAMPLES:g} "
                f"samples, what sampling and differentiation alone make{sensor}")

    def undo(self, data, p, ctx):
        """``data`` with its force channel's sensor dynamics undone and shifted back by
        ``p["delay"]`` (for a re-identification of the base law without them)."""
        F = unresonant(data.F, data.dt, p.get("sensor_period", 0.0), p.get("sensor_zeta", 0.5))
        F = unsensed(F, data.dt, p.get("sensor_rate", 0.0), p.get("sensor_gain", 0.0))
        F = np.interp(data.t + p["delay"], data.t, F)
        return Dataset(t=data.t, x=data.x, v=data.v, a=data.a, F=F, load=data.load,
                       name=data.name)


def _sensor_check(rate, gain):
    if not (np.isfinite(rate) and rate >= 0.0):
        raise ValueError(f"sensor_rate = {rate!r} is out of bounds: the force sensor's rate "
                         f"must be >= 0 [1/s]")
    if not (np.isfinite(gain) and -1.0 <= gain <= 1.0):
        raise ValueError(f"sensor_gain = {gain!r} is out of bounds: the force sensor's gain "
                         f"must be in [-1, 1] [-]")


def sensed(F, dt, rate, gain):
    """The force ``F`` [N] read by a sensor with first-order dynamics from its first
    sample: ``F + gain y``, ``y`` the step-invariant lag (time constant 1 / ``rate``) of
    ``F - F[0]`` from 0. ``gain`` = -1: a charge amplifier's leak (a high-pass);
    ``gain`` > 0: a load cell's creep.

    Parameters
    ----------
    F : ndarray
        The force [N], at the sample interval ``dt`` [s].
    dt : float
        Sample interval [s].
    rate : float
        1 / the time constant [1/s] (>= 0; 0: ``F`` itself).
    gain : float
        The lagged part's gain [-], in [-1, 1].

    Returns
    -------
    ndarray
        The reading [N].
    """
    _sensor_check(rate, gain)
    F = np.asarray(F, float)
    if rate == 0.0 or gain == 0.0 or F.size == 0:
        return F
    e = np.exp(-dt * rate)
    return F + gain * lfilter([1.0 - e], [1.0, -e], F - F[0])


def unsensed(R, dt, rate, gain):
    """The force whose reading through :func:`sensed` is ``R`` [N] (its exact inverse: the
    lag's state from the reading alone, ``y_n = (e y_(n-1) + (1 - e) (R_n - R_0)) / (1 +
    (1 - e) gain)``). Parameters as :func:`sensed`."""
    _sensor_check(rate, gain)
    R = np.asarray(R, float)
    if rate == 0.0 or gain == 0.0 or R.size == 0:
        return R
    e = np.exp(-dt * rate)
    d = 1.0 + (1.0 - e) * gain
    return R - gain * lfilter([(1.0 - e) / d], [1.0, -e / d], R - R[0])


def _resonance_check(period, zeta):
    if not (np.isfinite(period) and period >= 0.0):
        raise ValueError(f"sensor_period = {period!r} is out of bounds: the force transducer's "
                         f"natural period must be >= 0 [s]")
    if not (np.isfinite(zeta) and zeta > 0.0):
        raise ValueError(f"sensor_zeta = {zeta!r} is out of bounds: the force transducer's "
                         f"damping ratio must be > 0 [-]")


def resonant(F, dt, period, zeta):
    """The force ``F`` [N] read by a transducer that is a spring-mass system: the reading
    ``y`` follows ``y'' + 2 zeta w y' + w^2 y = w^2 F`` (w = 2 pi / ``period``), settled at
    ``F[0]`` at the first sample; ``F`` taken as linear between samples (first-order
    hold, exact for such an input). A lightly damped transducer follows a ramp late by
    2 zeta / w and rings with its natural period after each fast change of the force (a
    reversal, a breakaway).

    Parameters
    ----------
    F : ndarray
        The force [N], at the sample interval ``dt`` [s].
    dt : float
        Sample interval [s].
    period : float
        Natural period [s] (>= 0; 0: ``F`` itself, a rigid transducer; below a thousandth
        of ``dt`` read as rigid).
    zeta : float
        Damping ratio [-] (> 0).

    Returns
    -------
    ndarray
        The reading [N].
    """
    _resonance_check(period, zeta)
    F = np.asarray(F, float)
    if period < 1e-3 * dt or F.size == 0:
        return F
    w = 2.0 * np.pi / period
    b, a, _ = cont2discrete(([w * w], [1.0, 2.0 * zeta * w, w * w]), dt, method="foh")
    b = np.ravel(b)
    return lfilter(b, a, F, zi=lfilter_zi(b, a) * F[0])[0]


def unresonant(R, dt, period, zeta):
    """A force whose reading through :func:`resonant` is about ``R`` [N]: the transducer's
    equation solved for its input, ``R + 2 zeta / w R' + R'' / w^2`` (derivatives by
    central differences; a start for a re-identification, not an exact inverse: it
    amplifies the noise at the highest frequencies). Parameters as :func:`resonant`."""
    _resonance_check(period, zeta)
    R = np.asarray(R, float)
    if period < 1e-3 * dt or R.size < 3:
        return R
    w = 2.0 * np.pi / period
    d1 = np.gradient(R, dt)
    return R + 2.0 * zeta / w * d1 + np.gradient(d1, dt) / (w * w)


class StribeckShape(Candidate):
    """The law's Stribeck curve in another shape of its family: a free exponent ``alpha``
    (Gaussian) or the other shape (Lorentzian).

    Its reach ends there: a rational drop, a hydrodynamic rise bending as sqrt(|v|), a
    stiction spike or a lift-off kink lie outside the family (grid: 2 of 74). Tried in
    session 9 and not kept: a speed map on the law's output, ``F (1 + m(|v|))`` with ``m``
    piecewise linear in log |v| on 8 knots over two decades below the top speed, beside
    these variants. It named 7 of 45 detectable Stribeck cases (was 0), most refused for
    significance (z 1.6-2.9): the map acts on the output, the truths' curves inside the
    bristle dynamics (the XML-350's gap lies in its presliding transitions). On a classic
    LuGre the force level now puts the map there (:class:`StribeckMap`, :meth:`specialise`);
    this family stays the form of the trajectory level and the FMUs, and of the other
    laws.
    """

    def applicable(self, law, fit, ctx):
        if not hasattr(law.params, "shape") or not hasattr(law.params, "alpha"):
            return False, f"{law.name} has no Stribeck-shape parameters"
        return True, ""

    def specialise(self, law):
        # a classic LuGre carries a speed map inside its bristle dynamics
        if type(law).__name__ == "LuGre" and hasattr(law, "simulate_level"):
            return StribeckMap(self.name, self.description, self.stage, self.tags)
        return self

    def modify_law(self, law, base_names, ctx):
        names = list(base_names)
        with_alpha = names + ([] if "alpha" in names else ["alpha"])
        if law.params.shape == "gaussian":
            # a base that already fits its exponent (identify's default set) has only the
            # other shape left to try
            variants = [] if "alpha" in names else [(law, with_alpha)]
            return variants + [(law.with_values(shape="lorentzian"), names)]
        # the exponent acts on the gaussian form only: a lorentzian base gets the gaussian
        # family with a free exponent, started at alpha = 1 (an exponential tail, closest
        # to the lorentzian's heavy one) and at 2 (was: the gaussian at alpha = 2 only, so
        # a lorentzian base could never change its Stribeck exponent)
        return [(law.with_values(shape="gaussian", alpha=1.0), with_alpha),
                (law.with_values(shape="gaussian", alpha=2.0), with_alpha)]


def speed_map(speed, v_hi, knots, decades) -> np.ndarray:
    """Relative level change ``m(|v|)`` [-] of :class:`StribeckMap`: piecewise linear in
    ``log |v|`` through ``0, knots...`` at speeds spaced evenly in ``log |v|`` from
    ``v_hi / 10^decades`` to ``v_hi``; 0 below, the last knot's value above.

    Parameters
    ----------
    speed : ndarray
        |v| [m/s].
    v_hi : float
        Top knot speed [m/s].
    knots : sequence of float
        Values at the inner knots [-].
    decades : float
        Span of the knots [decades of speed].
    """
    vals = np.concatenate([[0.0], np.asarray(knots, float)])
    u = np.log10(np.maximum(speed, 1e-300) / v_hi) + decades
    return np.interp(u, np.linspace(0.0, decades, vals.size), vals, left=0.0)


class StribeckMap(StribeckShape):
    """``stribeck_shape`` of a classic LuGre law at the force level: the base's curve bent
    by a speed map *inside* the bristle dynamics - its levels (Stribeck curve and viscous
    term) times ``1 + m(|v|)``, ``m`` piecewise linear in ``log |v|`` (:func:`speed_map`)
    on :attr:`KNOTS` knots over :attr:`DECADES` decades below the fit record's top speed,
    the lowest pinned at 0 (the breakaway stays the law's ``Fs``). The law's curve
    parameters (:attr:`CURVE`) keep the base's values; its bristle, damping, viscous and
    offset parameters are re-identified with the map.

    A rational or exponential drop, a hydrodynamic rise bending as sqrt(|v|), a
    lift-off kink lie outside the Gaussian-alpha/Lorentzian family (session 9: the
    family reached 2 of 74 grid cases). The same map on the law's *output* closed
    0.3-0.6 of such truths with the base at its true values, inside 0.8-1.0 (valve,
    damping rig, press): the curve acts through the bristle's steady deflection and
    rate, so the map belongs there. The trajectory level and the FMUs keep the family
    variants of :class:`StribeckShape` (:meth:`extras` is empty): the map's knots are
    fitted on measured friction only (:meth:`force_extras`).
    """
    #: knots of the speed map (the lowest pinned at 0: the breakaway is the law's ``Fs``)
    KNOTS = 9
    #: span of the knots below the top speed [decades]
    DECADES = 2.5
    #: the law's curve parameters the map bends: kept at the base's values (freed with the
    #: map they trade against it - on the damping rig the map ran to its bounds while the
    #: law's Fc and vs moved the other way; started from the family's own fit instead, the
    #: map closed less: 1 of 18 grid cases named where the base's values named 3)
    CURVE = ("Fc", "Fs", "vs", "alpha", "Fc_neg", "Fs_neg", "vs_neg")

    def modify_law(self, law, base_names, ctx):
        return [(law, [n for n in base_names if n not in self.CURVE])]

    def _names(self):
        return [f"c_s{k}" for k in range(1, self.KNOTS)]

    def force_extras(self, ctx):
        return [Extra(n, 0.0, -0.9, 3.0, "1") for n in self._names()]

    def inside(self, p, data, ctx):
        knots = [p[n] for n in self._names()]
        return np.clip(1.0 + speed_map(np.abs(data.v), ctx.sv, knots, self.DECADES),
                       0.05, None)


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

