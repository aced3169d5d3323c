"""Scoring of benchmark cases: verdict, localisation (:func:`localise`), shrink against the
truth (:func:`truth_shrink`), and the figures of a run (:func:`summarise`)."""
from __future__ import annotations

import numpy as np

from friction.dataset import Dataset
from friction.metrics import nrmse

# where each effect's gap should show: its record's families (one home for an effect)
from ..effects import EXPECTED_EVIDENCE, EXPECTED_FAMILIES
from ..regions import band_splits, regime_split
from .cases import expected

__all__ = ["EXPECTED_FAMILIES", "EXPECTED_EVIDENCE", "localise", "localise_gap",
           "truth_shift", "practical_size",
           "truth_shrink", "summarise"]



def _regime_families(where):
    """Marginal regions of the disjoint regimes: direction, accel/decel, pre-sliding."""
    tot = sum(w["samples"] for w in where) or 1
    fam = {"direction": {}, "accel/decel": {}, "pre-sliding": {}}
    for w in where:
        pre, acc, d = [s.strip() for s in w["label"].split(",")]
        for f, lab in (("direction", d), ("accel/decel", acc), ("pre-sliding", pre)):
            e = fam[f].setdefault(lab, [0.0, 0])
            e[0] += w["share"]
            e[1] += w["samples"]
    out = []
    for f, regs in fam.items():
        for lab, (share, n) in regs.items():
            out.append({"family": f, "label": lab, "share": share, "fraction": n / tot})
    return out


_BAND_FAMILY = {"|v|": "|v|", "|a|": "|a|", "x": "x", "t": "t", "load": "load"}


#: evidence feature of the report -> region family it points at
_EVIDENCE_FAMILY = {"corr_sign_v": "direction", "corr_v": "direction", "corr_a": "|a|",
                    "corr_x": "x", "corr_t": "t", "corr_load": "load", "corr_dFdt": "dF/dt",
                    "corr_level_x": "x", "corr_level_t": "t", "corr_level_load": "load"}


def localise(report, min_fraction: float = 0.05, method: str = "where") -> dict:
    """Where the report puts the gap.

    ``method="where"`` (the report's ``where`` sections): candidate regions are the
    marginals of the disjoint regimes (``where``: direction, accelerating/decelerating,
    pre-sliding/sliding) and the quantile bands (``where_bands``: |v|, |a|, x, t, load). A
    region's **lift** is its share of the residual energy over its share of the samples (its
    local mean-square error over the record's): 1 means no concentration. The top region is
    the one with the largest lift; regions holding fewer than ``min_fraction`` of the
    samples are ignored (a few samples at reversals would win by chance). Energy is blind
    to sign: a direction asymmetry that the base fit splits evenly between the directions
    shows no lift.

    ``method="evidence"``: the report's signed ``evidence`` correlations of the held-out
    residual with sign(v), v, a, x, t, load and dF/dt; the top family is that of the largest
    absolute correlation.

    Returns
    -------
    dict
        ``family`` and ``label`` of the top region, its ``lift`` (or |correlation|), and
        ``ranking`` (best value of each family, descending).
    """
    if method == "evidence":
        ev = report.get("evidence", {})
        best = {}
        for k, val in ev.items():
            fam = _EVIDENCE_FAMILY.get(k)
            if fam and (fam not in best or abs(val) > best[fam][1]):
                best[fam] = (k, abs(float(val)))
        ranking = sorted(best.items(), key=lambda kv: -kv[1][1])
        if not ranking:
            return {"family": "", "label": "", "lift": 0.0, "ranking": []}
        fam, (lab, val) = ranking[0]
        return {"family": fam, "label": lab, "lift": val,
                "ranking": [(f, k, round(v, 3)) for f, (k, v) in ranking]}
    if method != "where":
        raise ValueError(f"method must be 'where' or 'evidence', got {method!r}")
    regions = _regime_families(report["where"])
    for b in report.get("where_bands", []):
        regions.append({"family": _BAND_FAMILY.get(b.get("signal"), b.get("signal")),
                        "label": b["label"], "share": b["share"],
                        "fraction": b["fraction_of_samples"]})
    regions = [r for r in regions if r["fraction"] >= min_fraction]
    for r in regions:
        r["lift"] = r["share"] / r["fraction"]
    best = {}
    for r in regions:
        if r["family"] not in best or r["lift"] > best[r["family"]]["lift"]:
            best[r["family"]] = r
    ranking = sorted(best.values(), key=lambda r: -r["lift"])
    top = ranking[0] if ranking else {"family": "", "label": "", "lift": 0.0}
    return {"family": top["family"], "label": top["label"], "lift": top["lift"],
            "ranking": [(r["family"], r["label"], round(r["lift"], 3)) for r in ranking]}


def localise_gap(held: Dataset, gap: np.ndarray, min_fraction: float = 0.05) -> dict:
    """:func:`localise` (``where`` method) of a given held-out gap, e.g. the noise-free one
    ``truth - base fit``: the region a report of that gap would put on top."""
    pseudo = {"where": regime_split(held, gap), "where_bands": band_splits(held, gap)[:12]}
    return localise(pseudo, min_fraction=min_fraction)


def truth_shrink(data: Dataset, truth: np.ndarray, report, base_truth=None) -> dict:
    """The gap fraction the true model closes on the report's held-out part, vs the report.

    ``truth = 1 - val_err(truth law) / val_err(base fit)`` with both errors the pooled
    held-out NRMSE of :func:`diagnosis.diagnose` (chronological hold-out: the samples after
    ``timing.fit_samples``); ``reported`` is the verdict's ``gap_closed``.

    Returns
    -------
    dict with ``truth``, ``reported``, ``error`` (reported - truth) and ``val_truth``.
    """
    k = int(report["timing"]["fit_samples"])
    if k + int(report["timing"]["validation_samples"]) != len(data):
        raise ValueError("truth_shrink needs a report of a chronological hold-out of the same "
                         "data (validation=None)")
    val_truth = nrmse(data.F[k:], np.asarray(truth)[k:])
    before = float(report["baseline"]["validation"])
    tru = 1.0 - val_truth / before if before > 0 else 0.0
    rep = float(report["verdict"]["gap_closed"])
    return {"truth": tru, "reported": rep, "error": rep - tru, "val_truth": val_truth}


def truth_shift(t: np.ndarray, Fb: np.ndarray, F: np.ndarray,
                most: float = 25.0, left: bool = False):
    """The force channel's shift [samples] that best aligns the base force ``Fb`` [N] with
    the noise-free truth ``F`` [N] at the instants ``t`` [s] (> 0: the force lags; < 0: it
    leads, as when the motion channels are late): the oracle's size of a ``delay`` truth,
    whatever mechanism made it (a transport delay, a filter's group delay, a hold, an
    encoder's latency), in the unit of the delay candidate's practical-size rule
    (:attr:`diagnosis.effects_delay.Delay.MIN_SAMPLES`).

    Least squares over shifts of -``most`` to ``most`` samples of the cubic spline through
    ``Fb``: a grid of tenths of a sample, refined by a bounded scalar search. With ``left``,
    returns ``(shift, share)``: ``share`` [-] the part of the truth's squared departure from
    the base that the shift leaves (0: the truth is that shift; near 1: no shift draws it).
    """
    from scipy.interpolate import CubicSpline
    from scipy.optimize import minimize_scalar
    t, Fb, F = (np.asarray(a, float) for a in (t, Fb, F))
    if not (t.shape == Fb.shape == F.shape and t.ndim == 1 and t.size >= 4):
        raise ValueError(f"truth_shift needs t, Fb and F of one length (>= 4), got "
                         f"{t.size}, {Fb.size} and {F.size}")
    for name, a in (("t", t), ("Fb", Fb), ("F", F)):
        if not np.all(np.isfinite(a)):
            raise ValueError(f"{name}[{int(np.flatnonzero(~np.isfinite(a))[0])}] is not finite")
    if not np.all(np.diff(t) > 0):
        raise ValueError("t must increase strictly [s]")
    dt = float(np.median(np.diff(t)))
    spline = CubicSpline(t, Fb)

    def sse(d):
        r = F - spline(np.clip(t - d * dt, t[0], t[-1]))
        return float(r @ r)
    grid = np.linspace(-most, most, int(round(20 * most)) + 1)
    k = int(np.argmin([sse(d) for d in grid]))
    lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, grid.size - 1)]
    shift = float(grid[k]) if hi <= lo else float(minimize_scalar(
        sse, bounds=(lo, hi), method="bounded", options={"xatol": 1e-3}).x)
    if not left:
        return shift
    d = F - Fb
    dd = float(d @ d)
    return shift, (min(sse(shift) / dd, 1.0) if dd > 0 else 0.0)


#: largest share of a delay truth's squared departure from the base that its best shift may
#: leave for the truth to count as that shift [-]: the delay truths that are shifts (a
#: transport delay, a filter's group delay, a hold, a latency) leave 0-0.5 on the grid's
#: plants, those that are no shift (a charge amplifier's leak, a deadband's reports, lost
#: telegrams) 0.6-1.0
SHIFT_EXPLAINS = 0.5


def practical_size(case_effect: str, info: dict) -> str:
    """Why the truth of a case is below its effect's practical size, so that the issue's
    rule forbids naming it ('' when it is not). Such a case is not counted among the
    detectable ones: no verdict may name it.

    * Any effect: the truth's own held-out imprint (``info["truth_imprint"]``, NRMSE of
      the noise-free truth minus the base fit's prediction, :func:`truth_imprint`) is
      below what the verdict asks of a named candidate's (:func:`diagnosis.verdict.
      practical_size`): :data:`~diagnosis.verdict.IMPRINT_NOISE` x the noise floor
      ``info["floor"]`` or :data:`~diagnosis.verdict.IMPRINT_GAP` x the base's held-out
      NRMSE ``info["before"]``. Even the truth itself, offered as a candidate, would be
      refused: what the base absorbed of it leaves too little on the held-out record.
    * A ``delay`` truth whose shift (:func:`truth_shift`, ``info["truth_shift"]``) is below
      the candidate's :attr:`~diagnosis.effects_delay.Delay.MIN_SAMPLES` ("a shift smaller
      than a sample is not a delay"), where that shift draws the truth (it leaves at most
      :data:`SHIFT_EXPLAINS` of its departure from the base, ``info["shift_left"]``; a
      truth no shift draws, a sensor's leak, is judged by its size alone).
    """
    from ..effects_delay import Delay
    from ..verdict import imprint_shortfall
    imp = info.get("truth_imprint")
    if imp is not None:
        short = imprint_shortfall(imp, float(info.get("before") or 0.0),
                                  float(info.get("floor") or 0.0), "the truth's")
        if short:
            return short
    shift = info.get("truth_shift")
    left = info.get("shift_left", 0.0)
    if case_effect == "delay" and shift is not None and abs(shift) < Delay.MIN_SAMPLES \
            and left <= SHIFT_EXPLAINS:
        return (f"the truth shifts the force by {abs(shift):.2f} samples, below the "
                f"{Delay.MIN_SAMPLES:g} a delay needs")
    return ""


def truth_imprint(F_held, truth_held, base_held) -> float:
    """The truth's held-out imprint [-, NRMSE]: the RMS of the noise-free truth ``truth_held``
    [N] minus the base fit's prediction ``base_held`` [N] on the held-out samples, over the
    standard deviation of the measured held-out force ``F_held`` [N] (what a perfect
    candidate would change in the prediction; :func:`diagnosis.diagnose`'s ``imprint``)."""
    d = np.asarray(truth_held, float) - np.asarray(base_held, float)
    return float(np.sqrt(np.mean(d * d)) / (np.std(F_held) or 1.0))


def _score(case_effect, exp, rep, data, truth, seconds) -> dict:
    from ..verdict import decision_entries
    from ..significance import improvement_z, z_threshold
    from ..verdict import NOISE_RATIO
    cause = rep["verdict"]["cause"]
    loc = localise(rep)
    loc_ev = localise(rep, method="evidence")
    fams = EXPECTED_FAMILIES.get(case_effect)
    fams_ev = EXPECTED_EVIDENCE.get(case_effect)
    sh = truth_shrink(data, truth, rep)
    # detectable: an oracle that knows the truth tells it from the base fit by either path of
    # the verdict: the base fit's held-out error exceeds the truth's by the noise ratio, or
    # the truth's held-out improvement over it is significant at the diagnosis' level
    k = int(rep["timing"]["fit_samples"])
    base_pred = rep._models["base"].predict(data)[k:] if hasattr(rep, "_models") else None
    z_truth = (improvement_z(data.F[k:] - base_pred, data.F[k:] - np.asarray(truth)[k:])
               if base_pred is not None else 0.0)
    detectable = bool(rep["baseline"]["validation"] > NOISE_RATIO * sh["val_truth"]
                      or z_truth >= z_threshold(max(len(rep["effects"]), 1)))
    # ... and the truth has the practical size a name needs (a perfect candidate's imprint)
    imp = (truth_imprint(data.F[k:], np.asarray(truth)[k:], base_pred)
           if base_pred is not None else None)
    below = (practical_size(case_effect, {"truth_imprint": imp, "floor": rep["noise_floor"],
                                          "before": rep["baseline"]["validation"]})
             if imp is not None and case_effect not in ("clean", "outside") else "")
    if below:
        detectable = False
    # where the gap truly lies: the same sections on the noise-free gap (truth - base fit)
    loc_true = (localise_gap(data.select(slice(k, None)), np.asarray(truth)[k:] - base_pred)
                if base_pred is not None else {"family": "", "label": ""})
    return {"verdict": cause, "expected": exp, "correct": cause == exp,
            "gap_closed": rep["verdict"]["gap_closed"], "truth_shrink": sh["truth"],
            "shrink_error": sh["error"], "validation_before": rep["baseline"]["validation"],
            "validation_truth": sh["val_truth"], "noise_floor": rep["noise_floor"],
            "where_top": rep["where"][0]["label"] if rep["where"] else "",
            "loc_family": loc["family"], "loc_label": loc["label"], "loc_lift": loc["lift"],
            "loc_correct": (loc["family"] in fams) if fams else None,
            "loc_evidence_family": loc_ev["family"],
            "loc_evidence_correct": (loc_ev["family"] in fams_ev) if fams_ev else None,
            "loc_true_family": loc_true["family"], "loc_true_label": loc_true["label"],
            "loc_matches_truth": (loc["label"] == loc_true["label"]
                                  if case_effect not in ("clean", "outside") else None),
            "detectable": detectable if case_effect not in ("clean", "outside") else None,
            "truth_z": z_truth, "truth_imprint": imp,
            **({"below_practical": below} if below else {}),
            "runner_up": rep["verdict"].get("runner_up", ""),
            "ranking": [e["name"] for e in rep["effects"][:3]],
            **_expected_entry(exp, rep), "effects": decision_entries(rep["effects"]),
            "seconds": seconds}


def _expected_entry(exp, rep) -> dict:
    """How the expected effect's candidate fared (for reading a miss): the share of the
    excess above the noise floor it closes, its significance, and what kept it from a name
    ('' when nothing did: a miss is then a rival's rank)."""
    from ..verdict import MIN_EXCESS_CLOSED, practical_size
    e = next((e for e in rep["effects"] if e["name"] == exp), None)
    if e is None:
        return {"exp_excess": None, "exp_z": None,
                "exp_refusal": rep.get("skipped", {}).get(exp, "not scored")}
    why = practical_size(e, rep["baseline"]["validation"], rep["noise_floor"] or 0.0,
                         len(rep["effects"]))
    if not why and e["excess_closed"] < MIN_EXCESS_CLOSED:
        why = f"closes {e['excess_closed']:.2f} of the excess (< 1/3)"
    return {"exp_excess": e["excess_closed"], "exp_z": e.get("significance_z"),
            "exp_refusal": why}


_BASE_SECONDS: dict = {}


def _base_failed_row(case_effect, exc, seconds) -> dict:
    """Score row of a case whose diagnosis stopped with :class:`diagnosis.core.BaseFitError`."""
    exp = expected(case_effect)
    nan = float("nan")
    return {"verdict": "base_unfit", "expected": exp, "correct": False, "gap_closed": 0.0,
            "truth_shrink": nan, "shrink_error": nan, "validation_before": nan,
            "validation_truth": nan, "noise_floor": nan, "where_top": "", "loc_family": "",
            "loc_label": "", "loc_lift": 0.0, "loc_correct": None, "loc_evidence_family": "",
            "loc_evidence_correct": None, "loc_true_family": "", "loc_true_label": "",
            "loc_matches_truth": None,
            "detectable": True if case_effect not in ("clean", "outside") else None,
            "truth_z": nan, "runner_up": "", "ranking": [], "seconds": seconds,
            "base_fit_nrmse": exc.fit_nrmse}


def summarise(rows) -> dict:
    """Overall and per-plant figures of benchmark rows (see :func:`run_benchmark`)."""
    def figures(rs):
        if not rs:
            return {}
        lib = [r for r in rs if r["effect"] not in ("clean", "outside")]
        loc = [r for r in lib if r["loc_correct"] is not None]
        loc_ev = [r for r in lib if r["loc_evidence_correct"] is not None]
        loc_tr = [r for r in lib if r.get("loc_matches_truth") is not None]
        det = [r for r in rs if r["detectable"] is not False]
        # a case whose base did not fit (BaseFitError) has no shrink to compare
        sh = np.array([r["shrink_error"] for r in lib if np.isfinite(r["shrink_error"])])
        shc = np.array([r["shrink_error"] for r in lib if r["correct"]])
        out = {"cases": len(rs),
               "top1_accuracy": float(np.mean([r["correct"] for r in rs])),
               "clean_cases": sum(r["effect"] == "clean" for r in rs),
               "clean_false_attributions": sum(1 for r in rs if r["effect"] == "clean"
                                               and r["verdict"] != "none"),
               "outside_cases": sum(r["effect"] == "outside" for r in rs),
               "outside_named_wrongly": sum(1 for r in rs if r["effect"] == "outside"
                                            and r["verdict"] != "unexplained"),
               "library_accuracy": float(np.mean([r["correct"] for r in lib])) if lib else None,
               "top1_accuracy_detectable": float(np.mean([r["correct"] for r in det])),
               "undetectable_cases": len(rs) - len(det),
               # of those, the cases whose truth is below its effect's practical size
               # (practical_size: a delay of less than a sample)
               "below_practical_cases": sum(1 for r in rs if r.get("below_practical")),
               "localisation_accuracy": (float(np.mean([r["loc_correct"] for r in loc]))
                                         if loc else None),
               "localisation_evidence_accuracy": (
                   float(np.mean([r["loc_evidence_correct"] for r in loc_ev])) if loc_ev
                   else None),
               "localisation_truth_accuracy": (
                   float(np.mean([r["loc_matches_truth"] for r in loc_tr])) if loc_tr else None),
               "shrink_abs_error_mean": float(np.mean(np.abs(sh))) if sh.size else None,
               "shrink_abs_error_max": float(np.max(np.abs(sh))) if sh.size else None,
               "shrink_abs_error_mean_correct": (float(np.mean(np.abs(shc))) if shc.size
                                                 else None),
               "seconds_per_case": float(np.mean([r["seconds"] for r in rs])),
               "base_identification_seconds": float(np.mean([r["base_id_seconds"]
                                                             for r in rs]))}
        out["time_ratio"] = out["seconds_per_case"] / out["base_identification_seconds"]
        return out

    plants = sorted({r["plant"] for r in rows}, key=lambda p: (p != "generic", p))
    per_plant = {p: figures([r for r in rows if r["plant"] == p]) for p in plants}
    per_effect = {}
    for r in rows:
        e = per_effect.setdefault(r["effect"], {"cases": 0, "correct": 0, "loc_correct": 0,
                                                "loc_evidence_correct": 0, "loc_truth": 0,
                                                "undetectable": 0, "named": {}})
        e["cases"] += 1
        e["correct"] += bool(r["correct"])
        e["loc_correct"] += bool(r["loc_correct"])
        e["loc_evidence_correct"] += bool(r["loc_evidence_correct"])
        e["loc_truth"] += bool(r.get("loc_matches_truth"))
        e["undetectable"] += r["detectable"] is False
        if not r["correct"]:
            e["named"][r["verdict"]] = e["named"].get(r["verdict"], 0) + 1
    overall = figures(rows)
    return {"rows": rows, "top1_accuracy": overall["top1_accuracy"],
            "clean_false_attributions": overall["clean_false_attributions"],
            "outside_named_wrongly": overall["outside_named_wrongly"],
            "overall": overall, "per_plant": per_plant, "per_effect": per_effect,
            "per_form": _per_form(rows)}


def _per_form(rows) -> dict:
    """``effect/form`` -> cases, correct, correct among the detectable, mean |shrink error|
    and the wrong verdicts given (rows of the generalisation grid, which carry a form)."""
    out = {}
    for r in rows:
        if not r.get("form"):
            continue
        e = out.setdefault(f"{r['effect']}/{r['form']}",
                           {"cases": 0, "correct": 0, "detectable": 0,
                            "correct_detectable": 0, "shrink_errors": [], "named": {}})
        e["cases"] += 1
        e["correct"] += bool(r["correct"])
        if r["detectable"] is not False:
            e["detectable"] += 1
            e["correct_detectable"] += bool(r["correct"])
        if np.isfinite(r["shrink_error"]):
            e["shrink_errors"].append(abs(float(r["shrink_error"])))
        if not r["correct"]:
            e["named"][r["verdict"]] = e["named"].get(r["verdict"], 0) + 1
    for e in out.values():
        errs = e.pop("shrink_errors")
        e["shrink_abs_error_mean"] = float(np.mean(errs)) if errs else None
    return out
