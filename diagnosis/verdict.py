"""The verdict both diagnosis levels share: noise floor, practical size, ranking, decision.

The force level (:func:`diagnosis.core.diagnose`) and the trajectory level
(:func:`diagnosis.trajectory.diagnose_trajectory`) score their candidates differently (one
on the friction force, the other on a re-simulated plant) but name the cause by the same
rules, kept here so neither level imports the other:

* :func:`noise_floor` - the white measurement noise of a residual, as NRMSE;
* :func:`rank` - candidates best first, near-ties (:data:`TIE`) to the simpler one;
* :func:`practical_size` - why a candidate that closes the gap may still not be named;
* :func:`decide` - ``none``, the named effect, or ``unexplained``
  (:data:`MIN_EXCESS_CLOSED`, :data:`NOISE_RATIO`, :data:`IMPRINT_NOISE`,
  :data:`IMPRINT_GAP`).

No name without practical size
------------------------------
A name needs the effect to *matter*, not only to be detectable (:func:`practical_size`).
Besides closing a third of the held-out gap above the noise floor, the named candidate must

* improve on the base significantly on the held-out samples (the paired
  forecast-encompassing statistic, :func:`.significance.encompassing_z`: its change of the
  prediction follows the base's held-out residual, at a family-wise 1 %) - on every path of
  the verdict. Where the held-out gap is at least :data:`EVENT_RATIO` x the noise floor,
  the same projection against the floor's white noise (:func:`.significance.noise_z`)
  may carry it instead: a gap made of a few events (a mass error in the forging press's
  two held-out acceleration events) is resolved by its samples there, not by its events;
  so is a gap the candidate closes to the floor (:func:`resolved`: most of the excess,
  with an imprint of a noise floor at least): what it leaves is the floor's noise;
* leave an **imprint** - the RMS of the difference between its and the base's held-out
  predictions, as NRMSE - of at least :data:`IMPRINT_NOISE` x the noise floor and
  :data:`IMPRINT_GAP` x the base's held-out NRMSE (the total gap): an effect that moves
  the prediction by less than half the noise, or by a sliver of what is wrong with
  it, is no practical part of the model (issue 15's clean record named ``delay``: imprint
  about 0.18 x the gap);
* have fitted parameters of a physical size of its own (:meth:`.effects.Candidate.
  practical`): a ``delay`` shorter than :attr:`.effects.Delay.MIN_SAMPLES` samples is what
  sampling and differentiation make (an integrating converter and backward differences
  each shift a record by half a sample), not a delay of the force channel;
* not be a simpler candidate in disguise (:meth:`.candidates.Candidate.defers`): an
  acceleration part that is linear in a and flat in v is a mass error - it ranks behind
  ``inertia`` (:func:`rank`) and is not named.

A candidate that fails is not named; the best one that passes is, if it closes a third of
the gap above the floor; otherwise the verdict is ``unexplained`` (a structured gap) or
``none`` (within the noise).
"""
from __future__ import annotations

import numpy as np

from .significance import z_threshold

__all__ = ["decide", "rank", "overrule_deferrals", "noise_floor", "practical_size",
           "imprint_shortfall", "decision_entries", "DEFER_SHARE",
           "MIN_EXCESS_CLOSED", "DOMINANT_EXCESS", "DOMINANCE", "dominant", "TIE", "TIE_REL",
           "EVENT_RATIO", "RESOLVED_EXCESS",
           "RESOLVED_IMPRINT", "resolved",
           "NOISE_RATIO", "NOISE_CLIP", "IMPRINT_NOISE", "IMPRINT_GAP"]

#: a candidate must close at least this share of the held-out gap *above the noise floor*
#: to be named. Right-family candidates whose form differs from the truth's close 0.38-0.95
#: of it in the withheld-effect benchmark, effects outside the library at most 0.07 (an
#: electrical ripple 0.001, a slower current loop at the trajectory level 0.064): a third
#: keeps a 5x margin above the latter; the report gives the part left unexplained.
#: Re-decided offline in session 23 (the rows carry every ranked candidate's decision
#: entries; exact: 0 of 272 grid and 0 of 500 clean verdicts differ when re-decided as they
#: are) on a uniform random 272 cases of the open grid and the 500 clean records: 0.3 names
#: 1 more right and 2 more wrong; 0.25 4 more right, 5 more wrong; 0.2 6 more right, 11
#: more wrong and 8 clean records; 0.15 11 more right, 14 more wrong and 14 clean records.
#: Where the right candidate misses, it mostly closes far less than a third (its form does
#: not reach the truth), so the share is not the lever
MIN_EXCESS_CLOSED = 1.0 / 3.0
#: ... or at least this share where it closes :data:`DOMINANCE` x what every other candidate
#: closes (at least :data:`DOMINANCE_FLOOR` of the excess) and the gap is beyond the noise
#: ratio: one candidate's form the only one to follow the gap at all, as far as it reaches
#: (a lubrication port's wake on the XML-350 closed 0.29-0.30 by the position map, nothing
#: else above 0.01). Decided offline in session 33 on session 32's 271 sample cases and 500
#: clean records (exact re-decision): 4 more right, 1 more wrong, 0 clean names; without the
#: dominance, 0.25 gave 7 more right, 5 more wrong; 0.2 with it named 8 clean records.
#: Out of sample, on another 272 cases of the open grid (``--sample 272 --sample-seed 2``):
#: 3 more right (a coating's wear-through drift, a waviness and the port's wake), 1 more
#: wrong (a fluidic diode's asymmetry named acceleration), where 147 were right and 25 wrong
DOMINANT_EXCESS = 0.25
DOMINANCE = 3.0
DOMINANCE_FLOOR = 0.02
#: candidates within this much closed excess of the best count as tied: the one with fewer
#: parameters is named (an acceleration term can mimic a mass error, not the reverse)
TIE = 0.02
#: ... or within this share of the best one's closed excess, when that is more [-]: what a
#: candidate with more parameters catches of a gap by its flexibility alone grows with the
#: gap (the grid's mass errors behind a filter or a flexible load: the 5-parameter
#: acceleration term closed 0.02-0.05 more than the mass error's 3 parameters, 7 wrong names)
TIE_REL = 0.05
#: (Re-ranked offline in session 23 on the same 272 grid cases and 500 clean records: the
#: best closed excess winning outright instead of the simplest tied candidate: 3 gained, 3
#: lost; the tied candidate of the highest paired z: 2 gained, 3 lost; no clean name either
#: way. The press's load, drift and direction truths, which move together there, trade
#: places)
#: base residual within this factor of the noise floor counts as noise
NOISE_RATIO = 1.2
#: second differences of the residual beyond this many robust standard deviations are
#: jumps of the residual (structure), not noise, in :func:`noise_floor`
NOISE_CLIP = 5.0


#: held-out gap, x the noise floor, from which the significance may be tested against the
#: floor's white noise (:func:`.significance.noise_z`) rather than against the residual's
#: own spread [-]. Re-deciding session 12's 1596-case grid offline: 3: 33 more right
#: verdicts (19 of them the press's mass errors), 3 more wrong names; 2: 40 more, 5 more
#: wrong; on 500 clean records (white and coloured noise) no name at 2 or 3
EVENT_RATIO = 3.0

#: a candidate that closes at least this share of the held-out gap above the floor [-] ...
RESOLVED_EXCESS = 0.7
#: ... and moves the prediction by at least this many noise floors (its imprint) [-] leaves
#: the floor's white noise behind: its significance may then be tested against that noise
#: (:func:`.significance.noise_z`) whatever the gap's size. The HAC statistic counts a
#: gap's independent stretches; a short record's few strokes (the valve's held-out part)
#: hold too few of them for even the truth to reach the quantile (the grid's filter,
#: latency and hold delays there: truth z 2.7-3.1 against 3.09, closing 0.8-1.0 of the
#: excess)
RESOLVED_IMPRINT = 1.0

#: smallest held-out imprint of a named effect, as a share of the noise floor [-]: the RMS
#: of what the effect changes in the prediction must reach half the noise's. At a third,
#: 2 of 224 clean records would have been named (drift, imprints 0.37 and 0.45 x the
#: floor, z 3.0 and 3.5); a Lorentzian curve under a Gaussian base that frees its exponent
#: (0.39 x the floor, z 8.8) is detected but not named
IMPRINT_NOISE = 0.5
#: smallest held-out imprint of a named effect, as a share of the base's held-out NRMSE
#: (the total gap) [-]
IMPRINT_GAP = 0.25


def resolved(effect: dict, floor: float) -> bool:
    """Whether ``effect`` (a ranked entry) leaves the noise floor's white noise behind:
    it closes :data:`RESOLVED_EXCESS` of the held-out gap above the floor ``floor``
    [-, NRMSE] with an imprint of :data:`RESOLVED_IMPRINT` x the floor at least, so what
    is left of the held-out residual is the floor's noise and its significance may be
    tested against that noise (:func:`practical_size`)."""
    return (effect.get("excess_closed", 0.0) >= RESOLVED_EXCESS
            and effect.get("imprint", 0.0) >= RESOLVED_IMPRINT * floor)


def imprint_shortfall(imp: float, before: float, floor: float, whose: str = "its") -> str:
    """Why a held-out imprint ``imp`` [-, NRMSE] is too small for a name ('' when it is
    not): below :data:`IMPRINT_NOISE` x the noise floor ``floor`` or :data:`IMPRINT_GAP` x
    the base's held-out NRMSE ``before`` [-]. ``whose`` starts the sentence (a candidate's
    imprint, or the benchmark's truth's: :func:`diagnosis.benchmark.scoring.
    practical_size`)."""
    if imp < IMPRINT_NOISE * floor:
        return (f"{whose} held-out imprint (NRMSE {imp:.3g}) is below {IMPRINT_NOISE:g} x the "
                f"noise floor {floor:.3g}")
    if imp < IMPRINT_GAP * before:
        return (f"{whose} held-out imprint (NRMSE {imp:.3g}) is below {IMPRINT_GAP:g} x the "
                f"held-out gap {before:.3g}")
    return ""


def practical_size(effect: dict, before: float, floor: float, n_tests: int) -> str:
    """Why ``effect`` (a ranked entry of :func:`diagnose`) may not be named whatever share of
    the gap it closes; '' when it may.

    Only the top-ranked candidate, or one within :data:`TIE` of it, can be named (see
    :func:`decide`). Checks, where the entry carries the figures (the trajectory level and
    transfer scores have none and keep the share rule alone): the paired (encompassing)
    statistic ``significance_z`` reaches the one-sided quantile of
    :data:`~diagnosis.significance.FAMILY_LEVEL` split over ``n_tests`` candidates (or,
    where ``before`` is at least :data:`EVENT_RATIO` x ``floor`` or the candidate leaves
    the floor's noise behind (:func:`resolved`), the statistic against the floor's noise
    ``noise_z`` does); the held-out ``imprint`` (NRMSE of the candidate's minus the base's prediction) reaches :data:`IMPRINT_NOISE` x ``floor`` and
    :data:`IMPRINT_GAP` x ``before``; the candidate's own ``size_reason`` (its fitted
    parameters below a physical size, :meth:`diagnosis.effects.Candidate.practical`) is
    empty.
    """
    if effect.get("defers_to"):
        return effect.get("defer_reason") or f"its fitted form is {effect['defers_to']}'s"
    if "significance_z" in effect:
        z_need = z_threshold(max(int(n_tests), 1))
        far = "noise_z" in effect and (before >= EVENT_RATIO * floor or resolved(effect, floor))
        if not (effect["significance_z"] >= z_need
                or (far and effect["noise_z"] >= z_need)):
            against = (f", {effect['noise_z']:.1f} against the noise floor" if far else "")
            return (f"its held-out improvement is not significant (paired z = "
                    f"{effect['significance_z']:.1f}{against} < {z_need:.2f})")
    if "imprint" in effect:
        short = imprint_shortfall(effect["imprint"], before, floor)
        if short:
            return short
    if effect.get("size_reason"):
        return effect["size_reason"]
    return ""



#: the keys of a ranked candidate entry :func:`decide` reads
DECISION_KEYS = ("name", "excess_closed", "gap_closed", "significance_z", "noise_z", "imprint",
                 "size_reason", "defers_to", "defer_reason")


def decision_entries(effects: list) -> list:
    """The ranked candidate entries reduced to what :func:`decide` reads
    (:data:`DECISION_KEYS`), for benchmark rows: a run's verdicts can be decided again
    under other rules without running the diagnosis again."""
    return [{k: e[k] for k in DECISION_KEYS if k in e} for e in effects]


def noise_floor(data, r) -> float:
    """Measurement-noise level of a residual, as NRMSE [-].

    Second differences cancel any smooth (modelled or unmodelled) structure, so
    std(diff2(r)) / sqrt(6) estimates white noise. The few second differences that straddle a
    jump of the residual (a velocity reversal under a stiff bristle, a stick-slip transition)
    are structure, not noise, and would dominate a plain std; so the differences are
    winsorised at :data:`NOISE_CLIP` robust (MAD) standard deviations first. Gaussian noise
    keeps its std (a 5-sigma clip changes it by < 1e-5); heavy-tailed measurement noise keeps
    most of its tails, unlike a pure MAD estimate.

    Parameters
    ----------
    data : Dataset
        The record (the spread of its force F [N] scales the NRMSE).
    r : ndarray
        Residual F_model - F_measured [N].
    """
    sd = float(np.std(data.F)) or 1.0
    d2 = np.diff(np.asarray(r, float), 2)
    if d2.size < 3:
        return 0.0
    centred = d2 - np.median(d2)
    robust = 1.4826 * float(np.median(np.abs(centred)))
    if robust > 0:
        centred = np.clip(centred, -NOISE_CLIP * robust, NOISE_CLIP * robust)
    est = float(np.std(centred)) / np.sqrt(6.0)
    return est / sd


#: a candidate defers to the simpler one its fitted form reduces to (``defers_to``) only
#: where that one closes at least this share of what it closes of the held-out gap above
#: the floor [-]: the fit record says the forms look alike, the held-out record whether
#: they act alike. An acceleration part 92-99 % of which follows a mass term on the fit
#: record closed 0.79-0.93 of belt-creep gaps (seen23) where the mass error closed
#: 0.47-0.82. Re-decided offline in session 28 on 272 grid cases, the seen families
#: 17-23's 1232 cases and 500 clean records (the deferring candidate moved to the top
#: where it closes more than the top by the tie margin): 0.5 1 more right, 0.6 4 (0
#: lost), 0.7 7 and 1 lost (a mass error named acceleration), 0.9 fewer; 0 clean names
#: throughout
DEFER_SHARE = 0.6


def overrule_deferrals(effects: list) -> None:
    """Drop, in place, the ``defers_to`` of the candidates whose simpler form closes less
    than :data:`DEFER_SHARE` of their closed excess on the held-out records; the reason is
    kept as ``deferral_overruled``.

    Parameters
    ----------
    effects : list of dict
        Scored candidates with ``name``, ``excess_closed`` [-] and, where a candidate's
        fitted form is a simpler one's, ``defers_to`` and ``defer_reason``.
    """
    closed = {e["name"]: e["excess_closed"] for e in effects}
    for e in effects:
        to = e.get("defers_to")
        # (a candidate that closes nothing has nothing for its simpler form to fall short of)
        if (not to or to not in closed or e["excess_closed"] <= 0.0
                or closed[to] >= DEFER_SHARE * e["excess_closed"]):
            continue
        why = e.get("defer_reason") or f"its fitted form is {to}'s"
        e["deferral_overruled"] = (
            f"{why}; but {to} closes {100 * closed[to]:.0f} % of the gap above the floor "
            f"against its {100 * e['excess_closed']:.0f} % (< {DEFER_SHARE:g} of it)")
        e.pop("defers_to")
        e.pop("defer_reason", None)


def rank(effects: list, floor: float = 0.0, tie_floor: float = 0.0) -> list:
    """Sort ``effects`` in place best first; near-ties go to the simpler candidate.

    Parameters
    ----------
    effects : list of dict
        Scored candidates, each with ``gap_closed``, ``excess_closed`` [-],
        ``validation_after`` [-] (held-out NRMSE) and ``n_params``.
    floor : float
        Noise floor [-] (NRMSE), for ``tie_floor``.
    tie_floor : float
        Candidates whose held-out NRMSE is within ``tie_floor x floor`` of the best one's,
        and which close :data:`MIN_EXCESS_CLOSED` of the gap above the floor, are tied with
        it too [-] (the trajectory level, where a gap barely above the floor makes excess
        fractions differ by noise alone); 0: ties by :data:`TIE` of closed excess only.

    Returns
    -------
    list of str
        Names of the candidates tied with the one moved to the top (the one with fewest
        parameters among those within :data:`TIE`, or :data:`TIE_REL` of it, of the best
        closed excess).

    Notes
    -----
    A candidate whose fitted form is a simpler candidate's (``defers_to``, :meth:`diagnosis.
    candidates.Candidate.defers`: an acceleration part that is a mass term) ranks right
    behind that one, whatever it closes: what it closes beyond it is flexibility, not an
    effect - unless that one closes less than :data:`DEFER_SHARE` of it on the held-out
    records (:func:`overrule_deferrals`): then it ranks by what it closes.
    """
    effects.sort(key=lambda e: -e["gap_closed"])
    present = {e["name"] for e in effects}
    overrule_deferrals(effects)
    deferring = [e for e in effects if e.get("defers_to") in present - {e["name"]}]
    for e in deferring:
        effects.remove(e)
    tied = _rank_ties(effects, floor, tie_floor)
    for e in deferring:
        at = next(k for k, o in enumerate(effects) if o["name"] == e["defers_to"])
        effects.insert(at + 1, e)
    return tied


def _rank_ties(effects, floor, tie_floor):
    """:func:`rank` on candidates none of which defers: the simplest of the near-ties to
    the top; the names of the others tied with it."""
    if not effects:
        return []
    top = effects[0]["excess_closed"]
    top_after = effects[0]["validation_after"]
    margin = max(TIE, TIE_REL * top)
    tied = [effects[0]] + [e for e in effects[1:] if e["excess_closed"] >= top - margin or (
        tie_floor > 0 and e["validation_after"] <= top_after + tie_floor * floor
        and e["excess_closed"] >= MIN_EXCESS_CLOSED)]
    simplest = min(tied, key=lambda e: e["n_params"])
    effects.remove(simplest)
    effects.insert(0, simplest)
    return [e["name"] for e in tied if e is not simplest]


def dominant(effects: list[dict]) -> bool:
    """Whether the candidate that closes the most of the gap above the floor closes at
    least :data:`DOMINANT_EXCESS` of it and :data:`DOMINANCE` x what each other one closes
    (taken as at least :data:`DOMINANCE_FLOOR`).

    Parameters
    ----------
    effects : list of dict
        Scored candidates with ``excess_closed`` [-].
    """
    shares = sorted((e.get("excess_closed", 0.0) for e in effects), reverse=True)
    if not shares or shares[0] < DOMINANT_EXCESS:
        return False
    other = shares[1] if len(shares) > 1 else 0.0
    return shares[0] >= DOMINANCE * max(other, DOMINANCE_FLOOR)


def decide(effects: list[dict], before: float, floor: float, noise_abs: float = 1e-6) -> dict:
    """The verdict from held-out scores (shared by the force and trajectory levels).

    ``none`` when the base's held-out NRMSE ``before`` is below ``noise_abs``, or within
    :data:`NOISE_RATIO` of the noise ``floor`` and no candidate is named. Otherwise the
    first of ``effects`` (ranked, dicts with ``name``, ``gap_closed``, ``excess_closed``)
    that closes at least :data:`MIN_EXCESS_CLOSED` of the gap above the floor (or, beyond
    the noise ratio, where none does, the one that dominates: :func:`dominant`), lies within
    :data:`TIE` of the best one's share *and* has practical size (:func:`practical_size`: a
    significant paired improvement, an imprint of half the noise and a quarter of the gap,
    a physical size of its own); ``unexplained`` when none does and the gap exceeds the
    noise ratio.

    Within the noise ratio a candidate can still be named: a long record resolves an effect
    below the noise's RMS, so the paired statistic and the imprint decide there (effects
    without the statistic, transfer scores and the trajectory level, are never named within
    the noise ratio).
    """
    if before < noise_abs:
        return {"cause": "none", "gap_closed": 0.0,
                "reason": f"held-out residual NRMSE {before:.3g} is below {noise_abs:.3g}"}
    n = len(effects)
    within = before <= NOISE_RATIO * floor
    closing = [e for e in effects if e.get("excess_closed", 0.0) >= MIN_EXCESS_CLOSED]
    if not closing and not within and dominant(effects):
        closing = [max(effects, key=lambda e: e.get("excess_closed", 0.0))]
    why = {e["name"]: practical_size(e, before, floor, n) for e in closing}
    if within:
        # the statistic is needed to name anything inside the noise ratio
        why.update({e["name"]: why[e["name"]] or "no paired statistic"
                    for e in closing if "significance_z" not in e})
    # only the best explanation (or one tied with it, :data:`TIE`) can be named: when it
    # lacks practical size, a weaker candidate that partly mimics it is not the cause (a
    # velocity differentiated half a sample late is delay-like, and on a sinusoidal stroke
    # a position map follows it too)
    best = effects[0]["excess_closed"] if effects else 0.0
    named = [e for e in closing if not why[e["name"]] and e["excess_closed"] >= best - TIE]
    refused = "; ".join(f"{e['name']} closes {100 * e['excess_closed']:.0f} % of the gap above "
                        f"the floor, but {why[e['name']]}" for e in closing if why[e["name"]])
    if not named:
        if within:
            return {"cause": "none", "gap_closed": 0.0,
                    "reason": f"held-out residual NRMSE {before:.3g} is within {NOISE_RATIO} x "
                              f"the noise floor {floor:.3g}, and no candidate has a "
                              f"significant held-out improvement of practical size"
                              + (f" ({refused})" if refused else "")}
        return {"cause": "unexplained",
                "gap_closed": effects[0]["gap_closed"] if effects else 0.0,
                "reason": ("no candidate closes a third of the held-out gap above the noise "
                           "floor" if not closing else
                           f"no candidate that closes a third of the held-out gap above the "
                           f"noise floor has practical size ({refused})")}
    top = named[0]
    verdict = {"cause": top["name"], "gap_closed": top["gap_closed"],
               "excess_closed": top["excess_closed"]}
    for k in ("significance_z", "imprint"):
        if k in top:
            verdict[k] = top[k]
    if within:
        verdict["reason"] = (f"held-out residual NRMSE {before:.3g} is within {NOISE_RATIO} x the "
                             f"noise floor {floor:.3g}, but {top['name']} closes "
                             f"{100 * top['excess_closed']:.0f} % of the gap above it with a "
                             f"significant held-out improvement (paired z = "
                             f"{top['significance_z']:.1f} >= {z_threshold(max(n, 1)):.2f}) of "
                             f"practical size (imprint {top.get('imprint', float('nan')):.3g}): "
                             f"a small real effect")
    elif top["excess_closed"] < MIN_EXCESS_CLOSED:
        verdict["reason"] = (f"{top['name']} closes {100 * top['excess_closed']:.0f} % of the "
                             f"gap above the floor, less than a third, but at least "
                             f"{DOMINANCE:g} x what any other candidate closes: the only "
                             f"form that follows the gap, as far as it reaches")
    elif refused:
        verdict["reason"] = f"named the best candidate of practical size ({refused})"
    others = [e for e in effects if e is not top]
    if others and others[0]["excess_closed"] >= top["excess_closed"] - 0.1:
        verdict["runner_up"] = others[0]["name"]
    return verdict

