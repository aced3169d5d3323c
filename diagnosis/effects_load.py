"""The ``load`` candidate: friction levels affine in the normal load, on the law's output
(:class:`Load`) or inside a classic LuGre's bristle dynamics (:class:`LoadInside`)."""
from __future__ import annotations

import numpy as np

from .candidates import (Candidate, Extra, Fixed, _basis_rows, _lsq, _sig_neg, _subsample, _with,
                         inside_level, levels_inside)
from .effects_acceleration import slip_memory

__all__ = ["Load", "LoadInside"]


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
        if levels_inside(law):
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
        return inside_level(1.0 + self.slope_rel(p, data, ctx))

    def force_extras(self, ctx):
        k = self.extras(ctx)[0]
        return super().force_extras(ctx) + [Extra("k_Lo", 0.0, k.lo, k.hi, "1")]

    def apply(self, F, p, data, ctx):
        rel = (data.load - ctx.L0) / ctx.L0
        F = F * np.clip(1.0 + p.get("k_Lo", 0.0) * rel, 0.0, None)
        k_v = p.get("k_v", 0.0)
        return F + k_v * rel * data.v if k_v else F
