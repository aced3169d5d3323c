"""Library of named candidate effects: real extensions of a base friction law.

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
from friction.dataset import Dataset
from friction.extensions import POSITION_NAMES, position_map

__all__ = ["Candidate", "CANDIDATES", "EFFECT_NAMES", "Context", "make_context"]

EFFECT_NAMES = ("acceleration", "load", "asymmetry", "stribeck_shape", "presliding",
                "position", "inertia", "delay", "drift")


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


def make_context(fit) -> Context:
    sF = float(np.percentile(np.abs(fit.F), 99)) or 1.0
    sv = float(np.percentile(np.abs(fit.v), 99)) or 1e-3
    sa = float(np.percentile(np.abs(fit.a), 99)) or 1e-3
    L0 = float(np.mean(fit.load)) if fit.load is not None else None
    L_span = float(np.ptp(fit.load)) if fit.load is not None else 0.0
    L_hi = float(np.max(fit.load)) if fit.load is not None else 0.0
    return Context(sF, sv, sa, float(np.min(fit.x)), float(np.max(fit.x)), float(fit.t[0]),
                   float(fit.t[-1] - fit.t[0]), fit.dt, L0, L_span, L_hi)


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

    def applicable(self, law, fit, ctx: Context) -> tuple[bool, str]:
        return True, ""

    def modify_law(self, law, base_names, ctx: Context):
        """Return the list of (law, base_names) variants to try (best on fit is kept)."""
        return [(law, list(base_names))]

    def extras(self, ctx: Context) -> list[Extra]:
        """Parameters of the effect's formula at every level (the trajectory level's
        :class:`diagnosis.effect_law.EffectLaw` implements exactly these)."""
        return []

    def force_extras(self, ctx: Context) -> list[Extra]:
        """All parameters fitted at the force level: :meth:`extras` plus those only measured
        friction data need (their zero, the default of :meth:`apply`, is the plain formula)."""
        return self.extras(ctx)

    def apply(self, F, p: dict, data, ctx: Context) -> np.ndarray:
        return F

    #: ``undo(data, p, ctx) -> Dataset``: the data with the effect at ``p`` taken out, for
    #: effects the base fit absorbs in a distorted way (see :func:`diagnosis.composite.
    #: fit_composite`); ``None``: no such start
    undo = None

    def specialise(self, law) -> "Candidate":
        """The form of this effect for ``law`` (default: the same for every law)."""
        return self

    def own_law_names(self, law) -> tuple:
        """Parameters of the law itself that belong to this effect, whether or not the base
        already frees them (the transfer scores calibrate them with the effect's own; by
        default only the names :meth:`modify_law` adds to the base's)."""
        return ()


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
    def extras(self, ctx):
        return [Extra("f_a", 0.0, -ctx.sF, ctx.sF, "N"),
                Extra("a_s", 0.3 * ctx.sa, 0.02 * ctx.sa, 3 * ctx.sa, "m/s^2"),
                Extra("v_c", ctx.sv, 0.05 * ctx.sv, 20 * ctx.sv, "m/s")]

    def force_extras(self, ctx):
        # the frictional lag of seed 000 (Eq. 11, its "lag" form: tau dF_d/dt + F_d =
        # F_d^ss(v, a)); started at one sample (at 0 the residual is flat in it)
        lag = Extra("tau_lag", ctx.dt, 0.0, MAX_FILTER_SAMPLES * ctx.dt, "s")
        return self.extras(ctx) + [lag]

    def apply(self, F, p, data, ctx):
        # acceleration-dependent part (seed 000): grows with |a|, fades with |v|, zero at a = 0,
        # and lags behind them as a whole. (Lagging the acceleration alone, the form before,
        # closed 0.57-0.60 of held-out gaps that the truth closes 0.83-0.92 on the rig, the
        # press and the isolator; lagging the part, 0.81-0.84.)
        Fd = p["f_a"] * np.tanh(data.a / p["a_s"]) * np.exp(-np.abs(data.v) / p["v_c"])
        return F + _first_order(Fd, data.dt, p.get("tau_lag", 0.0))


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

    def force_extras(self, ctx):
        # seed 004 gives the viscous coefficient its own load slope (k3 of Eq. 11; on the
        # press it is most of the load effect), so the level factor alone cannot carry it
        # a seal pressurised from one side (the pneumatic cylinder's O-ring) grows with the
        # load in one direction of motion and hardly in the other: k_L_neg is the level
        # slope for v < 0 (k_L then holds for v > 0)
        s = 2.0 * ctx.sF / ctx.sv
        k = self.extras(ctx)[0]
        return [k, Extra("k_L_neg", 0.0, k.lo, k.hi, "1"), Extra("k_v", 0.0, -s, s, "N.s/m")]

    def apply(self, F, p, data, ctx):
        # friction levels affine in the normal load (seed 004 Eqs. 9-11), relative to the
        # fit data's mean load: F (1 + k_L (L - L0) / L0), never of the opposite sign, with
        # its own slope k_L_neg for v < 0 where fitted, plus a viscous part k_v v (L - L0) / L0
        rel = (data.load - ctx.L0) / ctx.L0
        k = p["k_L"]
        if "k_L_neg" in p:
            s = _sig_neg(data.v, ctx)
            k = k * (1.0 - s) + p["k_L_neg"] * s
        F = F * np.clip(1.0 + k * rel, 0.0, None)
        k_v = p.get("k_v", 0.0)
        return F + k_v * rel * data.v if k_v else F


class Drift(Candidate):
    def extras(self, ctx):
        return [Extra("k_drift", 0.0, -2.0, 2.0, "1")]

    def apply(self, F, p, data, ctx):
        # friction level changing over time (warming): relative change per fit duration
        return F * (1.0 + p["k_drift"] * (data.t - ctx.t0) / ctx.T)


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
    """``asymmetry`` for laws with direction twins: Fc, Fs, sigma2 for v < 0 and the offset
    b become free parameters of the law itself."""
    TWINS = ("Fc", "Fs", "sigma2")

    def modify_law(self, law, base_names, ctx):
        p = law.params
        start = {law.twins[n]: float(getattr(p, n)) for n in self.TWINS}
        names = list(base_names) + [law.twins[n] for n in self.TWINS if law.twins[n]
                                    not in base_names]
        if "b" not in names:
            names.append("b")
        return [(law.with_values(**start), names)]

    def own_law_names(self, law):
        # the offset is this effect's too: identify's default base frees it on the fit
        # record, but a held-out condition with its own offset is the asymmetry's to carry
        return tuple(law.twins[n] for n in self.TWINS) + ("b",)


class Position(Candidate):
    stage_doc = "friction level scaled along the stroke"
    NAMES = POSITION_NAMES

    def extras(self, ctx):
        return [Extra(n, 0.0, -1.0, 1.0, "1") for n in self.NAMES]

    def apply(self, F, p, data, ctx):
        # friction level varying along the stroke: a friction map, linear between equally
        # spaced knots over the fit record's stroke (a local defect, a worn section)
        span_hi = max(ctx.x_hi, ctx.x_lo + 1e-12)
        return F * (1.0 + position_map(data.x, ctx.x_lo, span_hi,
                                       [p.get(n, 0.0) for n in self.NAMES]))


class Inertia(Candidate):
    def extras(self, ctx):
        m = ctx.sF / ctx.sa
        return [Extra("dm", 0.0, -m, m, "kg")]

    def force_extras(self, ctx):
        # the inverse dynamics smooths the acceleration it uses offline (zero phase), the a
        # column of the data may not be; started at one sample (at 0 the residual is flat)
        smooth = Extra("tau_af", ctx.dt, 0.0, MAX_FILTER_SAMPLES * ctx.dt, "s")
        return self.extras(ctx) + [smooth]

    def apply(self, F, p, data, ctx):
        # mass error of the inverse dynamics leaks dm * a into the "measured" friction
        return F + p["dm"] * _zero_phase(data.a, data.dt, p.get("tau_af", 0.0))


class Delay(Candidate):
    MAX_SAMPLES = 25

    def extras(self, ctx):
        d = self.MAX_SAMPLES * ctx.dt
        return [Extra("delay", 0.0, -d, d, "s", grid=51)]

    def apply(self, F, p, data, ctx):
        # the force channel lags (delay > 0) the motion channels
        return np.interp(data.t - p["delay"], data.t, F)

    def undo(self, data, p, ctx):
        """``data`` with its force channel shifted back by ``p["delay"]`` (for a
        re-identification of the base law without the shift)."""
        F = np.interp(data.t + p["delay"], data.t, data.F)
        return Dataset(t=data.t, x=data.x, v=data.v, a=data.a, F=F, load=data.load,
                       name=data.name)


class StribeckShape(Candidate):
    def applicable(self, law, fit, ctx):
        if not hasattr(law.params, "shape") or not hasattr(law.params, "alpha"):
            return False, f"{law.name} has no Stribeck-shape parameters"
        return True, ""

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


CANDIDATES: dict[str, Candidate] = {
    "acceleration": Acceleration("acceleration", "acceleration-dependent part / frictional lag "
                                 "(seed 000)", "additive"),
    "load": Load("load", "friction levels depend on the normal load (seed 004)",
                 "multiplicative"),
    "asymmetry": Asymmetry("asymmetry", "direction-dependent levels and offset (seeds 000, 003)",
                           "additive"),
    "stribeck_shape": StribeckShape("stribeck_shape", "Stribeck exponent / Lorentzian shape",
                                    "modify_law"),
    "presliding": Presliding("presliding", "bristle dynamics missing from a static map",
                             "modify_law"),
    "position": Position("position", "friction level varying along the stroke",
                         "multiplicative"),
    "inertia": Inertia("inertia", "mass error in the inverse dynamics", "additive"),
    "delay": Delay("delay", "time shift between force and motion channels", "shift"),
    "drift": Drift("drift", "friction level changing over time (e.g. warming)",
                   "multiplicative"),
}
