"""Transfer scoring: held-out records taken under conditions the fit record never saw.

A candidate effect of a covariate that the fit record holds (nearly) constant cannot be
identified from it: the pneumatic seal fitted at 1 bar sees 46-50 N of pressure load, its
held-out records 243-347 N; seed 004 needs constant-speed tests at three loads to solve its
Eq. (18) for the load coefficients. Fitting the candidate on the fit record and scoring it
on the held-out records then tests nothing but an unidentified slope.

When the held-out data come as two or more records and a covariate of theirs lies outside
the fit range (:func:`diagnosis.core.extrapolation`), every candidate is scored by
*transfer* as well:

* the base law stays as identified on the fit record (it describes the fit condition);
* the candidate's own parameters (its extras, or the law parameters it frees) are
  calibrated on one held-out record, with the base held fixed;
* the candidate predicts the *other* held-out records, never used in its calibration;
* each record is the calibration record in turn; the held-out NRMSE pools every
  prediction, and the base is scored on exactly the same samples.

A candidate that describes *how* the friction changes with the new condition (the load
sensitivity) carries over from one pressure to another; one that only re-levels the model
(an offset, a drift over the record) carries the calibration record's level to a condition
where it no longer holds. So the ranking stays a held-out ranking, on records taken at the
conditions the question is about.
"""
from __future__ import annotations

import numpy as np

from friction.metrics import nrmse

from .candidates import law_variants
from .composite import Composite, fit_composite

__all__ = ["transfer_applicable", "transfer_scores"]


def transfer_applicable(val_sets, shift: dict) -> bool:
    """Whether the transfer scores apply: two or more held-out records and a covariate of
    theirs outside the fit range (``shift`` from :func:`diagnosis.core.extrapolation`)."""
    return len(val_sets) >= 2 and bool(shift)


def transfer_scores(base: Composite, base_names, candidates: dict, val_sets, ctx,
                    skip) -> dict:
    """Held-out NRMSE of the base and of each candidate under transfer calibration.

    Parameters
    ----------
    base : Composite
        The base law fitted on the fit record (held fixed).
    base_names : list of str
        Its fitted parameter names (a ``modify_law`` candidate calibrates only the names it
        adds to these, and those it declares its own,
        :meth:`diagnosis.effects.Candidate.own_law_names`).
    candidates : dict
        ``{name: Candidate}`` (already specialised to the base law).
    val_sets : list of Dataset
        The held-out records (two or more).
    ctx : Context
        Scales of the fit record (the candidates' boxes and reference load).
    skip : list of int
        Start-up samples of each record left out of the scores.

    Returns
    -------
    dict
        ``{"before": nrmse, "after": {name: nrmse}, "folds": [{"calibrated_on": i,
        "scored_on": [j, ...], "before": nrmse, "after": {name: nrmse}}],
        "params": {name: [per-fold fitted extras]}, "n_params": {name: count}}`` (the count
        of calibrated parameters, for the tie rule).
    """
    n = len(val_sets)
    base_pred = [base.predict(v) for v in val_sets]
    meas, pb = [], []
    pc = {name: [] for name in candidates}
    folds, params, n_params = [], {name: [] for name in candidates}, {}
    for i in range(n):
        others = [j for j in range(n) if j != i]
        fold = {"calibrated_on": i, "scored_on": others, "after": {}}
        F_o = np.concatenate([val_sets[j].F[skip[j]:] for j in others])
        P_b = np.concatenate([base_pred[j][skip[j]:] for j in others])
        fold["before"] = nrmse(F_o, P_b)
        meas.append(F_o)
        pb.append(P_b)
        for name, cand in candidates.items():
            best = None
            own = cand.own_law_names(base.law)
            for law_v, names_v, form in law_variants(cand, base.law, base_names, ctx):
                new = [m for m in names_v if m not in base_names or m in own]
                comp, cost = fit_composite(law_v, new, [form], val_sets[i], ctx)
                if best is None or cost < best[1]:
                    best = (comp, cost, len(form.force_extras(ctx)) + len(new))
            comp = best[0]
            n_params[name] = best[2]
            P_c = np.concatenate([comp.predict(val_sets[j])[skip[j]:] for j in others])
            pc[name].append(P_c)
            fold["after"][name] = nrmse(F_o, P_c)
            desc = comp.describe()
            params[name].append({**desc["params"], **desc["extras"]})
        folds.append(fold)
    F_all = np.concatenate(meas)
    return {"before": nrmse(F_all, np.concatenate(pb)),
            "after": {name: nrmse(F_all, np.concatenate(p)) for name, p in pc.items()},
            "folds": folds, "params": params, "n_params": n_params}
