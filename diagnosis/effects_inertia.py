"""The ``inertia`` candidate: a mass the base model lacks, and a part coupled to the axis
through friction of its own (:class:`Inertia`, :func:`coupled_part`)."""
from __future__ import annotations

import numpy as np
from numba import njit

from .candidates import (MAX_FILTER_SAMPLES, Candidate, Extra, Fixed, _basis_rows, _lsq,
                         _subsample, _with, _zero_phase)

__all__ = ["Inertia", "coupled_part"]


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
