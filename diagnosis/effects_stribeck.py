"""The ``stribeck_shape`` candidate: the Stribeck curve's shape freed (:class:`StribeckShape`),
a map of the friction level over the speed's decades (:class:`StribeckMap`,
:func:`speed_map`) or a drag over the speed's decades beside the contact
(:class:`StribeckDrag`)."""
from __future__ import annotations

import numpy as np

from .candidates import Candidate, Extra, inside_level, levels_inside

__all__ = ["StribeckShape", "StribeckMap", "StribeckDrag", "speed_map"]


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
    LuGre the force level now puts the map there (:class:`StribeckMap`, :meth:`specialise`),
    or a drag over the speed's decades beside the contact (:class:`StribeckDrag`, its second
    form); this family stays the form of the trajectory level and the FMUs, and of the
    other laws.
    """
    #: seconds of its fit on the speed case (:attr:`Candidate.fit_cost`)
    fit_cost = 0.3

    def applicable(self, law, fit, ctx):
        if not hasattr(law.params, "shape") or not hasattr(law.params, "alpha"):
            return False, f"{law.name} has no Stribeck-shape parameters"
        return True, ""

    def specialise(self, law):
        # a classic LuGre carries a speed map inside its bristle dynamics
        if levels_inside(law):
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


def _curvature_rows(knots, smooth) -> np.ndarray:
    """The rows of a prior on a speed map's curvature [-]: ``sqrt(smooth)`` x the second
    differences of the knot values ``knots`` [-] after the pinned 0 (:func:`speed_map`)."""
    return np.sqrt(smooth) * np.diff(np.concatenate([[0.0], np.asarray(knots, float)]), 2)


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
    fitted on measured friction only (:meth:`force_extras`). A prior on the map's curvature
    (:attr:`SMOOTH`, :meth:`penalty`) keeps the knots a record pins poorly from zigzagging.

    A speed-dependent force that does not act through the bristle (a film's drag beside
    the contact) is this candidate's second form, :class:`StribeckDrag`, fitted beside
    this one (:meth:`modify_law`): the one that fits the fit record better is kept.
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
        # two forms, the one that fits the fit record best kept: this map inside the
        # law's levels with the curve kept, and a drag beside the contact with the curve
        # re-identified (:class:`StribeckDrag`)
        drag = StribeckDrag(self.name, self.description, "additive", self.tags)
        return [(law, [n for n in base_names if n not in self.CURVE]),
                (law, list(base_names), drag)]

    def _names(self):
        return [f"c_s{k}" for k in range(1, self.KNOTS)]

    def force_extras(self, ctx):
        return [Extra(n, 0.0, -0.9, 3.0, "1") for n in self._names()]

    #: weight of the prior on the map's curvature: its rows are ``sqrt(SMOOTH)`` x the
    #: knots' second differences (the pinned 0 included; :meth:`penalty`) [-]. Without it
    #: a record that pins few knots drew a map that zigzags between the bounds: on the
    #: damping rig's quick protocol (half the fit record at one speed, the speeds between
    #: crossed only while accelerating) the knots ran +3.0, -0.9, -0.9 and the held-out
    #: gap grew by 0.71 of its part above the floor where the truth closes 0.74 of it; 53
    #: of the 131 Stribeck-shape cases of the grid and the seen families 17-22 closed less
    #: than nothing (22 with it). Chosen on those cases alone (0.0003, 0.001, 0.003, 0.01,
    #: 0.1, 1: 32, 29, 23, 20, 14, 0 named, 27, 22, 21, 23, 23, 26 closing less than
    #: nothing); with every candidate the grid's 272 cases lost 2 (a press's contact
    #: resonance, a narrow bump the prior flattens), the seen families 17-22's 96
    #: Stribeck-shape cases gained 5 (8 -> 13), no other verdict changed
    SMOOTH = 0.001

    def penalty(self, p, ctx):
        return _curvature_rows([p[n] for n in self._names()], self.SMOOTH)

    def inside(self, p, data, ctx):
        knots = [p[n] for n in self._names()]
        return inside_level(1.0 + speed_map(np.abs(data.v), ctx.sv, knots, self.DECADES))


class StribeckDrag(StribeckShape):
    """``stribeck_shape`` of a classic LuGre law as a drag beside the contact: the law's
    force plus ``sgn(v) h(|v|)``, ``h`` piecewise linear in ``log |v|`` (:func:`speed_map`)
    on :attr:`StribeckMap.KNOTS` knots [N] over :attr:`StribeckMap.DECADES` decades below
    the fit record's top speed (the lowest pinned at 0), with every parameter of the law
    re-identified beside it (the curve's too). The second form of :class:`StribeckMap`
    (:meth:`StribeckMap.modify_law`; the one that fits the fit record better is kept).

    A speed-dependent force that does not pass through the contact's presliding: a
    lubricant film's shear (its walls slipping past a critical stress), a journal's
    Petroff drag, a meniscus wiped by the motion - the law's viscous term ``sigma2 v``
    bent over the speed's decades. Fitted by the map inside the levels, such a drag
    bends the bristle's transitions, which it does not. Session 31, on the Stribeck-shape
    cases of the 272-case grid and the twenty-second to twenty-fifth families (99), the
    candidate alone: 23 named with the map inside, 27 with this drag alone, 33 with the
    better fit of the two (the damping rig's Sommerfeld journal: 0.06 of the excess
    closed by the map inside, 0.54-0.90 by the drag). With every candidate, the grid
    went from 138 to 140 right (a hydrodynamic rise and two heated films on the press
    gained, a logarithmic weakening on the XML-350 lost to ``asymmetry``, a frictional
    memory there named ``stribeck_shape``); on 500 clean records still none named. With
    the curve kept at the base's values the drag closed less than the map inside on the
    press (its base had absorbed the drag in its curve): it frees the curve. A prior on
    the knots' curvature (:attr:`SMOOTH`) as for the map inside.
    """
    #: weight of the prior on the drag's curvature, its knots over the force scale [-]
    SMOOTH = StribeckMap.SMOOTH

    def modify_law(self, law, base_names, ctx):
        return [(law, list(base_names))]

    def _names(self):
        return [f"h_s{k}" for k in range(1, StribeckMap.KNOTS)]

    def force_extras(self, ctx):
        return [Extra(n, 0.0, -ctx.sF, ctx.sF, "N") for n in self._names()]

    def penalty(self, p, ctx):
        return _curvature_rows([p[n] / ctx.sF for n in self._names()], self.SMOOTH)

    def apply(self, F, p, data, ctx):
        knots = [p[n] for n in self._names()]
        return F + np.sign(data.v) * speed_map(np.abs(data.v), ctx.sv, knots,
                                               StribeckMap.DECADES)
