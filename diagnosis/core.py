"""Sim-to-real gap diagnosis: where the gap lies, which unmodelled effect causes it, and how
much of it adding that effect closes on held-out data.

Procedure
---------
1. Fit the base law on the fit data (:func:`identification.identify`), score it on the
   held-out data (``validation_before``).
2. Where: split the held-out residual by regime, band and frequency (:mod:`.regions`).
3. Which: for every applicable candidate (:mod:`.effects`) re-identify base + effect jointly
   on the fit data, score on held-out data (``validation_after``, ``gap_closed``).
4. How far: greedy stacking of the effects that keep closing the gap; the part left
   unexplained; a noise floor estimated from the data.
5. Verdict: ``none`` if the base residual is consistent with the noise floor; the best effect
   if it closes a clear share of the gap; ``unexplained`` if a structured gap stays.

Verdict
-------
The rules that name a cause (noise floor, ranking, practical size, the decision) are
shared with the trajectory level and live in :mod:`.verdict`; the report's shape in
:mod:`.report`. Both are re-exported here.
"""
from __future__ import annotations

import time

import numpy as np

from friction import FrictionModel, make_model
from friction.alignment import align_motion, velocity_scale
from friction.dataset import Dataset, load_dataset
from friction.metrics import nrmse
from friction.progress import status_lines

from .candidates import best_variant, law_variants, missing_columns as _missing_columns
from .composite import Composite, fit_composite
from .effects import CANDIDATES, EFFECT_NAMES, make_context
from .regions import band_splits, frequency_split, regime_split
from .report import DiagnosisReport, report_sections
from .significance import encompassing_z, improvement_z, noise_z
from .transfer import transfer_applicable, transfer_scores
# the verdict rules both levels share, re-exported (their public names were this module's)
from .verdict import (IMPRINT_GAP, IMPRINT_NOISE, MIN_EXCESS_CLOSED, NOISE_RATIO,  # noqa: F401
                      TIE, decide, noise_floor, practical_size, rank)

__all__ = ["diagnose", "DiagnosisReport", "noise_floor", "extrapolation", "decide",
           "report_sections", "BaseFitError", "BASE_FIT_LIMIT", "base_free_names", "warm_up",
           "MIN_SCORED_SAMPLES", "practical_size", "IMPRINT_NOISE", "IMPRINT_GAP",
           "confounding", "CONFOUND_CORR"]

#: a base whose NRMSE on its own fit record reaches this (worse than the record's mean
#: force, NRMSE 1) stops the diagnosis: effects scored against it would be credited with
#: what the base itself lacks (Franka case 4: the constant torque offset read as
#: ``asymmetry``)
BASE_FIT_LIMIT = 1.0
#: fewest scored samples a held-out record must keep (after its warm-up, :func:`warm_up`)
MIN_SCORED_SAMPLES = 10
#: warm-up of a held-out record that starts at rest: this share of its samples, at most
#: :data:`WARM_UP_MAX`, is not scored
WARM_UP_SHARE = 1.0 / 50.0
WARM_UP_MAX = 200


class BaseFitError(ValueError):
    """The base law fits its own fit record worse than a constant (NRMSE >=
    :data:`BASE_FIT_LIMIT`): no effect can be named on top of it. ``fit_nrmse`` holds the
    figure."""

    def __init__(self, message: str, fit_nrmse: float):
        super().__init__(message)
        self.fit_nrmse = float(fit_nrmse)


def warm_up(record) -> int:
    """Samples at the start of a separate held-out record that are not scored.

    None for a record that starts in motion: the law starts from its steady state at the
    first velocity (:meth:`friction.base.FrictionModel.record_start_state`), the state
    consistent with the first samples, so there is no start-up transient to hide (from an
    undeflected bristle the rack-and-pinion's held-out stroke spiked by 760 N). A record
    that starts at rest (``v[0] = 0``) starts the law at rest, while the real contact may
    hold a deflection from before: its first :data:`WARM_UP_SHARE` (at most
    :data:`WARM_UP_MAX` samples) are a warm-up.
    """
    if len(record) == 0 or record.v[0] != 0.0:
        return 0
    return min(WARM_UP_MAX, int(len(record) * WARM_UP_SHARE))


def _as_dataset(d, mapping=None, scale=None):
    if isinstance(d, Dataset):
        return d
    return load_dataset(d, mapping=mapping, scale=scale)


def base_free_names(law: FrictionModel) -> list[str]:
    """Free parameters of the diagnosis' base law: those ``frictionlab identify`` fits by
    default (:func:`identification.space.default_names`, one definition for both
    commands). For the classic LuGre: sigma0, sigma1, sigma2, Fc, Fs, vs, the Stribeck
    exponent alpha and the offset b (direction twins left ``None`` stay symmetric;
    candidates add what the base lacks)."""
    from identification.space import default_names
    return default_names(law)


def _base_law(model, fit, names=None) -> tuple[FrictionModel, list[str]]:
    law = make_model(model) if isinstance(model, str) else model
    return law, list(base_free_names(law) if names is None else names)


def _deferral(cand, values, fit, ctx) -> dict:
    """``{"defers_to": name, "defer_reason": why}`` when the candidate at its fitted
    ``values`` (the law's and its own) reduces to a simpler candidate's form on ``fit``
    (:meth:`diagnosis.candidates.Candidate.defers`), else ``{}``."""
    to, why = cand.defers(values, fit, ctx)
    return {"defers_to": to, "defer_reason": why} if to else {}


def fit_base(fit, model, ctx=None, seed: int = 0, names=None, check: bool = True,
             align: bool = True):
    """The diagnosis' base fit: ``model`` identified on ``fit``, then polished as a composite
    with no effect (the same least squares every candidate is fitted with).

    Parameters
    ----------
    fit : Dataset
        The fit record.
    model : str or FrictionModel
        Base law (registry name, or an instance whose values start the fit).
    ctx : Context, optional
        Scales of ``fit`` (:func:`diagnosis.effects.make_context`).
    seed : int
        Seed of the identification.
    names : list of str, optional
        Free parameters (default :func:`base_free_names`, identify's default set).
    check : bool
        Raise :class:`BaseFitError` when the fit NRMSE reaches :data:`BASE_FIT_LIMIT`.
    align : bool
        Bring the motion channels onto one time base first (:func:`friction.alignment.
        align_motion`); ``False`` for a record the caller aligned (:func:`diagnose`).

    Returns
    -------
    (Composite, list of str, float)
        The fitted base, the names of its free parameters and its fit NRMSE [-].
    """
    from identification import identify
    # the motion channels as identify and diagnose have them
    if align:
        fit = align_motion(fit)[0]
    ctx = ctx or make_context(fit)
    law0, names = _base_law(model, fit, names)
    res = identify(fit, law0, names=names, seed=seed, align=False)
    base, base_fit = fit_composite(res["model"], names, [], fit, ctx)
    if check and not base_fit < BASE_FIT_LIMIT:
        raise BaseFitError(
            f"the base {base.law.name} fits its own fit record {fit.name!r} at NRMSE "
            f"{base_fit:.3g} >= {BASE_FIT_LIMIT:g}, worse than the record's mean force: no "
            f"effect is named on a base that does not fit (check the force's sign, units "
            f"and offset, or choose another base law)", base_fit)
    return base, names, base_fit


def _evidence(data, r) -> dict:
    """Correlations and lags that support (never replace) the held-out ranking."""
    def corr(s):
        s = np.asarray(s, float)
        if np.std(s) == 0 or np.std(r) == 0:
            return 0.0
        return float(np.corrcoef(s, r)[0, 1])
    ev = {"corr_a": corr(data.a), "corr_sign_v": corr(np.sign(data.v)), "corr_v": corr(data.v),
          "corr_x": corr(data.x), "corr_t": corr(data.t)}
    if data.load is not None:
        ev["corr_load"] = corr(data.load)
    # a friction-level effect (load, position, drift) makes r proportional to F g(s): its
    # correlation shows with r sgn(F), not with r
    rf = r * np.sign(data.F)
    for key, s in (("x", data.x), ("t", data.t), ("load", data.load)):
        if s is not None and np.std(s) > 0 and np.std(rf) > 0:
            ev[f"corr_level_{key}"] = float(np.corrcoef(s, rf)[0, 1])
    # lag of the residual against the measured force's rate: a delay shows as a peak here
    dF = np.gradient(data.F, data.t)
    ev["corr_dFdt"] = corr(dF)
    return ev


#: a held-out covariate counts as extrapolated when this share of its samples lies outside the
#: fit data's central 99 % range widened by its own width
EXTRAPOLATION_SHARE = 0.5

_COVARIATES = {"v": "m/s", "a": "m/s^2", "x": "m", "load": "N"}


def extrapolation(fit, val_sets) -> dict:
    """Covariates whose held-out values lie mostly outside the range seen in the fit data.

    An effect of such a covariate cannot be identified on the fit data (seed 004 needs tests
    at several loads to solve Eq. (18) for its load coefficients); the diagnosis says so
    instead of guessing.

    Returns
    -------
    dict
        ``{name: {"fit_range": [lo, hi], "validation_range": [lo, hi], "outside_share": s,
        "unit": u}}`` for each covariate with ``s >= EXTRAPOLATION_SHARE``.
    """
    out = {}
    for key, unit in _COVARIATES.items():
        f = getattr(fit, key)
        vals = [getattr(v, key) for v in val_sets]
        if f is None or any(v is None for v in vals):
            continue
        lo, hi = np.percentile(f, [0.5, 99.5])
        pad = 0.5 * (hi - lo)
        allv = np.concatenate(vals)
        share = float(np.mean((allv < lo - pad) | (allv > hi + pad)))
        if share >= EXTRAPOLATION_SHARE:
            out[key] = {"fit_range": [float(lo), float(hi)],
                        "validation_range": [float(np.min(allv)), float(np.max(allv))],
                        "outside_share": share, "unit": unit}
    return out


#: |correlation| from which two covariates of named effects count as confounded [-]
CONFOUND_CORR = 0.7
#: the effects told apart by the acceleration covariate ``a`` in :func:`confounding`: on a
#: stroke at one frequency a = -omega^2 x, and a position map draws what they draw (the
#: benchmark's isolator: a against x, R^2 0.84 on its fit part and 1.000 on its held-out
#: part; the seventeenth sealed family, run at the end of session 23, named all 8 of its
#: acceleration and drift cases there position, and 1 of its 4 inertia cases)
ACCELERATION_EFFECTS = ("acceleration", "inertia")


def confounding(records) -> list:
    """Pairs of covariates that stand in for each other on ``records`` (fit and held-out).

    An effect is told from another by where its gap lies: ``asymmetry`` by the direction of
    motion, ``load`` by the normal load, ``drift`` by time, ``position`` by the position
    (their region families, :data:`diagnosis.effects.EXPECTED_FAMILIES`), ``acceleration``
    and ``inertia`` by the acceleration ``a`` (:data:`ACCELERATION_EFFECTS`). Where two of
    these covariates move together (the press: a high forging load on the way down, a low
    one on the way up; a stroke at one frequency, where a = -omega^2 x), their effects can
    mimic each other and the data cannot tell them apart.

    Parameters
    ----------
    records : list of friction.dataset.Dataset
        The fit and held-out records (t [s], x [m], v [m/s], load [N]).

    Returns
    -------
    list of dict
        ``{"covariates": [a, b], "corr": r}`` for every pair with ``|r| >=``
        :data:`CONFOUND_CORR` (Pearson, over the pooled samples), strongest first.
    """
    cols = {"direction": [np.sign(r.v) for r in records], "t": [r.t for r in records],
            "x": [r.x for r in records], "a": [r.a for r in records]}
    if all(r.load is not None for r in records):
        cols["load"] = [r.load for r in records]
    cols = {k: np.concatenate(v).astype(float) for k, v in cols.items()}
    cols = {k: c for k, c in cols.items() if np.std(c) > 0}
    names = sorted(cols)
    out = []
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            r = float(np.corrcoef(cols[a], cols[b])[0, 1])
            if np.isfinite(r) and abs(r) >= CONFOUND_CORR:
                out.append({"covariates": [a, b], "corr": r})
    return sorted(out, key=lambda c: -abs(c["corr"]))


def _note_confounding(verdict: dict, effects: list, records) -> None:
    """Add to a named ``verdict`` the effects whose covariate is confounded with its own on
    ``records`` (:func:`confounding`) and that close a gap of their own; the name stays."""
    from .effects import EXPECTED_FAMILIES
    def covariates(name):
        own = set(EXPECTED_FAMILIES.get(name, ())) & {"direction", "t", "x", "load"}
        return own | ({"a"} if name in ACCELERATION_EFFECTS else set())
    cause = verdict.get("cause")
    own = covariates(cause)
    if not own:
        return
    closed = {e["name"]: e["gap_closed"] for e in effects}
    found = []
    for pair in confounding(records):
        a, b = pair["covariates"]
        if (a in own) == (b in own):
            continue
        other = b if a in own else a
        for name in EXPECTED_FAMILIES:
            if name != cause and other in covariates(name) and closed.get(name, 0.0) > 0.0:
                found.append({"effect": name, "covariates": pair["covariates"],
                              "corr": pair["corr"], "gap_closed": closed[name]})
    if found:
        verdict["confounded"] = found
        verdict["reason"] = (verdict.get("reason", "") + ("; " if verdict.get("reason") else "")
                             + "; ".join(
            f"on this data {f['covariates'][0]} and {f['covariates'][1]} move together "
            f"(correlation {f['corr']:+.2f}), so an effect of one can show as an effect of "
            f"the other ({f['effect']} closes {100 * f['gap_closed']:.0f} % here): a record "
            f"that varies them apart tells {cause} from {f['effect']}" for f in found))


def diagnose(fit_data, model="lugre", validation=None, candidates=None, *, seed: int = 0,
             fit_fraction: float = 0.7, greedy: bool = True, progress=None,
             mapping=None, scale=None, noise_level: float | None = None,
             base_names: list | None = None, executor=None,
             threads: int | None = None) -> DiagnosisReport:
    """Locate and name the sim-to-real gap of a friction model.

    Parameters
    ----------
    fit_data : Dataset or path
        Measurement the model is fitted on.
    model : str or FrictionModel
        Base law (registry name, or an instance whose values start the fit).
    validation : Dataset, path, or list of them, optional
        Held-out data. Default: the last ``1 - fit_fraction`` of ``fit_data`` (chronological).
    candidates : list of str, optional
        Effect names to try (default: all of :data:`diagnosis.effects.EFFECT_NAMES`).
    seed : int
        Seed of the base identification.
    greedy : bool
        Stack further effects while each closes more of the remaining gap.
    progress : None, bool, tqdm or callable(n, info), optional
        As :mod:`friction.progress` says: one-line status messages (``n`` = 0); ``True``:
        lines on stderr.
    noise_level : float, optional
        RMS of the force measurement's noise [N], e.g. the standard deviation of the force
        channel in a standstill record. Default: estimated from the held-out residual's
        second differences, which reads white noise right but under-reads noise a filter
        has coloured (the gap then reads as structure: ``unexplained``, never a name).
    base_names : list of str, optional
        Free parameters of the base law. Default: those ``identify`` fits by default
        (:func:`base_free_names`), so both commands fit the same law.
    executor : None or dask.distributed.Client
        Where the candidates' joint fits run: in this process (default), or mapped over a
        dask cluster, one task per candidate, the fit record scattered once
        (:mod:`diagnosis.cluster`); the report is the same.
    threads : int, optional
        Workers the candidates' fits run on when no ``executor`` is given: processes
        forked from this one on Linux, else threads of this process
        (:func:`diagnosis.cluster.local_fits`; default :data:`diagnosis.cluster.THREADS`:
        the machine's cores, at most 4; 1: one after the other); the report is the same.

    Every record is simulated from the law's steady state at its first velocity (a record
    that starts in motion), a separate held-out record that starts at rest after an
    unscored warm-up (:func:`warm_up`); one too short to score is refused.
    fit_fraction : float
        Share of ``fit_data`` fitted when no validation is given (the rest is held out).
    mapping : dict, optional
        Column mapping of files given by path (:func:`friction.dataset.load_dataset`).
    scale : dict, optional
        Unit factors of files given by path.

    Raises
    ------
    BaseFitError
        When the base fits its own fit record at NRMSE >= :data:`BASE_FIT_LIMIT` (worse
        than the record's mean): the diagnosis stops instead of naming effects.
    ValueError
        On bad input, e.g. a held-out record with fewer than :data:`MIN_SCORED_SAMPLES`
        samples to score.

    Returns
    -------
    DiagnosisReport
        ``baseline``, ``where``, ``effects``, ``verdict`` (the contract) plus ``where_bands``,
        ``where_frequency``, ``greedy``, ``noise_floor``, ``evidence``, ``skipped``, ``timing``.
    """
    t_start = time.perf_counter()
    if executor is None:
        from .cluster import thread_count
        thread_count(threads)  # a bad count is refused before any fit
    say = status_lines(progress)
    fit = _as_dataset(fit_data, mapping, scale)
    # one time base for the motion channels: a velocity that lags its position (backward
    # differences) is advanced by its measured lag (the held-out part of a split record
    # with it, a held-out file by its own)
    fit, v_lag = align_motion(fit)
    full = None
    if validation is None:
        # chronological hold-out: predicted as the continuation of the whole record, so the
        # held-out part starts from the model's own state, not from rest
        full = fit
        fit, held = fit.split(fit_fraction)
        val_sets = [held]
    else:
        vals = validation if isinstance(validation, (list, tuple)) else [validation]
        # each held-out file by its own measured lag (Franka case 3's records: 0.45, 0.75
        # and 1.08 samples at its three speeds)
        val_sets = [align_motion(_as_dataset(v, mapping, scale))[0] for v in vals]
    # held-out records that start at rest keep an unscored warm-up; the chronological
    # hold-out continues the fit part's simulation and needs none
    skip = [0] if full is not None else [warm_up(v) for v in val_sets]
    _check_scorable(val_sets, skip, chronological=full is not None)
    if noise_level is not None:
        _check_noise_level(noise_level, val_sets)
    names = list(candidates) if candidates is not None else list(EFFECT_NAMES)
    unknown = [n for n in names if n not in CANDIDATES]
    if unknown:
        raise ValueError(f"unknown candidate effect(s) {unknown}; choose from {list(EFFECT_NAMES)}")
    ctx = make_context(fit)

    # 1. base fit
    say(f"[diagnose] fitting base {model if isinstance(model, str) else model.name} on "
        f"{len(fit)} samples")
    # aligned above, with the held-out part of a split record
    base, base_names, base_fit = fit_base(fit, model, ctx, seed=seed, names=base_names,
                                          align=False)

    def predict_val(comp: Composite) -> list[np.ndarray]:
        if full is not None:
            return [comp.predict(full)[len(fit):]]
        return [comp.predict(v) for v in val_sets]

    F_all = np.concatenate([v.F[k:] for v, k in zip(val_sets, skip)])
    held_residuals = {}  # pooled held-out residuals of each scored model, for the paired test

    def val_score(comp: Composite, key: str | None = None) -> float:
        # pooled NRMSE over all held-out sets: RMS of all residuals / std of all measured F
        P = predict_val(comp)
        P_all = np.concatenate([p[k:] for p, k in zip(P, skip)])
        if key is not None:
            held_residuals[key] = F_all - P_all
        return nrmse(F_all, P_all)

    before = val_score(base, "base")
    r_val = [v.F - p for v, p in zip(val_sets, predict_val(base))]
    r_val = [r if k == 0 else np.concatenate([np.zeros(k), r[k:]]) for r, k in zip(r_val, skip)]
    val_cat = val_sets[0] if len(val_sets) == 1 else _concat(val_sets)
    r_cat = np.concatenate(r_val)
    sd_val = float(np.std(np.concatenate([v.F for v in val_sets])))
    if noise_level is None:
        floor = float(np.mean([noise_floor(v, r) * np.std(v.F) for v, r in zip(val_sets, r_val)])
                      / sd_val)
    else:
        # the user's own figure (a standstill record, a datasheet): also right for coloured
        # noise, which the second differences of the residual under-read
        floor = float(noise_level) / sd_val

    # 2. where
    where = regime_split(val_cat, r_cat)
    bands = band_splits(val_cat, r_cat)
    freq = frequency_split(val_sets[0], r_val[0])

    # 3. which
    effects, skipped, fitted = [], {}, {}
    from .cluster import as_client, candidate_fits, local_fits  # the fits at once
    remote = candidate_fits(executor, names, base.law, base_names, fit, ctx, val_sets)
    if as_client(executor) is None:
        remote = local_fits(names, base.law, base_names, fit, ctx, val_sets, threads)
    for k, name in enumerate(names, 1):
        cand = CANDIDATES[name].specialise(base.law)
        ok, why = cand.applicable(base.law, fit, ctx)
        why = why if not ok else _missing_columns(cand, val_sets, ctx)
        if why:
            skipped[name] = why
            continue
        say(f"[diagnose] candidate {k}/{len(names)}: {name}")
        best = remote.get(name) or best_variant(
            [fit_composite(law_v, names_v, [form], fit, ctx)
             for law_v, names_v, form in law_variants(cand, base.law, base_names, ctx)], ctx)
        comp, cost = best
        # the form that fitted best (a variant may carry its own: law_variants)
        cand = comp.effects[0] if comp.effects else cand
        after = val_score(comp, name)
        fitted[name] = comp
        # the law's fitted values too: a law-changing candidate's size is a law parameter
        # (backlash's gap)
        values = {**comp.describe()["params"], **comp.extras}
        effects.append({"name": name, "validation_before": before, "validation_after": after,
                        "gap_closed": (before - after) / before if before > 0 else 0.0,
                        "excess_closed": (before - after) / max(before - floor, 1e-12),
                        # does the change follow the held-out residual (the verdict's
                        # test), and is the squared error smaller (reported beside it)
                        "significance_z": float(encompassing_z(held_residuals["base"],
                                                               held_residuals[name])),
                        "improvement_z": float(improvement_z(held_residuals["base"],
                                                             held_residuals[name])),
                        # the same projection against the noise floor's white noise (the
                        # verdict's test where the gap is far above it)
                        "noise_z": float(noise_z(held_residuals["base"], held_residuals[name],
                                                 floor * sd_val)),
                        # what the candidate changes in the held-out prediction (NRMSE)
                        "imprint": float(np.sqrt(np.mean((held_residuals["base"]
                                                          - held_residuals[name]) ** 2))
                                         / (np.std(F_all) or 1.0)),
                        "size_reason": cand.practical(values, ctx),
                        # the fitted form may be a simpler candidate's (a mass-like
                        # acceleration part): then that one is the effect
                        **_deferral(cand, values, fit, ctx),
                        "n_params": len(cand.force_extras(ctx)) + max(len(comp.base_names)
                                                                 - len(base_names), 0),
                        "fit_before": base_fit, "fit_after": cost,
                        "fitted": comp.describe()})
    rank(effects)

    # 3b. held-out records at conditions the fit record never saw: transfer scores
    shift = extrapolation(fit, val_sets) if full is None else {}
    transfer = None
    if transfer_applicable(val_sets, shift):
        say("[diagnose] held-out conditions outside the fit range: transfer scores")
        wide = _concat([fit] + list(val_sets))
        ctx_wide = make_context(wide)
        cands = {}
        for name in names:
            cand = CANDIDATES[name].specialise(base.law)
            if not _missing_columns(cand, val_sets) and (
                    cand.applicable(base.law, fit, ctx)[0]
                    or cand.applicable(base.law, wide, ctx_wide)[0]):
                cands[name] = cand
                skipped.pop(name, None)
        tr = transfer_scores(base, base_names, cands, val_sets, ctx, skip)
        one_shot = {e["name"]: e for e in effects}
        before = tr["before"]
        effects = []
        for name, after in tr["after"].items():
            e1 = one_shot.get(name, {})
            effects.append({"name": name, "validation_before": before, "validation_after": after,
                            "gap_closed": (before - after) / before if before > 0 else 0.0,
                            "excess_closed": (before - after) / max(before - floor, 1e-12),
                            "n_params": tr["n_params"][name], "protocol": "transfer",
                            "fit_record_validation_after": e1.get("validation_after"),
                            "fitted": {"transfer_params": tr["params"][name],
                                       **e1.get("fitted", {})}})
        rank(effects)
        transfer = {"covariates": sorted(shift), "folds": tr["folds"],
                    "explanation": TRANSFER_NOTE}

    # 4. greedy stacking (at the fit-record protocol; a transfer verdict reports its top)
    sequence = []
    if transfer is not None:
        top_ok = effects and effects[0]["excess_closed"] >= MIN_EXCESS_CLOSED
        sequence = ([{"add": effects[0]["name"], "validation": effects[0]["validation_after"]}]
                    if top_ok else [])
        final_val = effects[0]["validation_after"] if top_ok else before
    elif greedy and decide(effects, before, floor)["cause"] in fitted:
        # stacking starts from the effect the verdict names (the best of practical size)
        first = next(e for e in effects
                     if e["name"] == decide(effects, before, floor)["cause"])
        current = fitted[first["name"]]
        cur_val = first["validation_after"]
        sequence.append({"add": first["name"], "validation": cur_val})
        used = {first["name"]}
        for e in [e for e in effects if e is not first][:3]:
            if e["gap_closed"] < 0.05 or e["name"] in used:
                continue
            # the form for the law it is stacked on (a backlash law carries no level inside)
            cand = CANDIDATES[e["name"]].specialise(current.law)
            if cand.stage == "modify_law" and any(c.stage == "modify_law" for c in current.effects):
                continue
            law_v, names_v, cand = law_variants(cand, current.law, current.base_names, ctx)[0]
            if not hasattr(law_v, "simulate_level") and any(
                    getattr(c, "inside", None) is not None for c in current.effects + [cand]):
                continue  # an effect inside the law, on a law that cannot carry it
            comp, _ = fit_composite(law_v, names_v, current.effects + [cand], fit, ctx,
                                    extras0=current.extras)
            v_after = val_score(comp)
            if v_after < cur_val * 0.97:  # keep only effects that close a further 3 %
                current, cur_val = comp, v_after
                used.add(e["name"])
                sequence.append({"add": e["name"], "validation": v_after})
        final_val = cur_val
    else:
        final_val = before

    # 5. verdict
    verdict = decide(effects, before, floor, noise_abs=1e-6)
    if transfer is not None:
        verdict["protocol"] = "transfer"
        verdict["reason"] = (verdict.get("reason", "") + ("; " if verdict.get("reason") else "")
                             + f"held-out {', '.join(transfer['covariates'])} outside the fit "
                             f"range: each candidate calibrated on one held-out record, scored "
                             f"on the others, the base as fitted")
    elif verdict["cause"] == "unexplained":
        for key, e in shift.items():
            verdict["reason"] += (
                f"; the held-out {key} ({e['validation_range'][0]:.4g} to "
                f"{e['validation_range'][1]:.4g} {e['unit']}) lies outside the fit range "
                f"({e['fit_range'][0]:.4g} to {e['fit_range'][1]:.4g} {e['unit']}) for "
                f"{100 * e['outside_share']:.0f} % of its samples, so an effect of {key} "
                f"cannot be identified from the fit data: fit on data that spans it")
    _note_confounding(verdict, effects, [fit] + list(val_sets))
    report = DiagnosisReport(
        baseline={"model": base.law.name, "metric": "nrmse", "fit": base_fit, "validation": before},
        **report_sections(where, bands, freq, effects, verdict, sequence, before, final_val,
                          floor),
        evidence=_evidence(val_cat, r_cat),
        noise_source="given" if noise_level is not None else "estimated",
        extrapolation=shift,
        transfer=transfer,
        effect_details={e["name"]: e["fitted"] for e in effects},
        base=base.describe(),
        skipped=skipped,
        velocity_alignment={"lag_samples": v_lag, "applied": bool(v_lag),
                            "velocity_scale": velocity_scale(fit)},
        timing={"seconds": time.perf_counter() - t_start, "fit_samples": len(fit),
                "validation_samples": int(sum(len(v) for v in val_sets))},
    )
    report._models = {"base": base, **fitted}  # for plots; not serialised
    report._data = {"fit": fit, "validation": val_sets}
    return report


TRANSFER_NOTE = ("the held-out records lie outside the fit record's range of a covariate, "
                 "so no candidate of it can be identified on the fit record: the base stays "
                 "as fitted, each candidate's own parameters are calibrated on one held-out "
                 "record and it is scored on the others (each in turn)")


def _check_noise_level(noise_level, val_sets) -> None:
    """A given noise RMS must be positive, finite and below the spread of the force."""
    try:
        nl = float(noise_level)
    except (TypeError, ValueError):
        raise ValueError(f"noise_level must be a number [N], got {noise_level!r}") from None
    if not (np.isfinite(nl) and nl > 0):
        raise ValueError(f"noise_level = {noise_level!r} is out of bounds: must be > 0 [N]")
    sd = float(np.std(np.concatenate([v.F for v in val_sets])))
    if nl >= sd:
        raise ValueError(f"noise_level = {nl:.4g} N is out of bounds: must be below the spread "
                         f"of the measured force (std {sd:.4g} N); check its unit (N, not mN)")


def _check_scorable(val_sets, skip, chronological: bool) -> None:
    """Refuse a held-out record with fewer than :data:`MIN_SCORED_SAMPLES` samples left to
    score after its warm-up, naming it, in one line."""
    for v, k in zip(val_sets, skip):
        n = len(v) - k
        if n < MIN_SCORED_SAMPLES:
            what = ("the held-out part of the record" if chronological
                    else f"held-out record {v.name!r}")
            warm = f" after its {k}-sample warm-up" if k else ""
            raise ValueError(f"{what} has {n} samples to score{warm}: too short to score "
                             f"(need >= {MIN_SCORED_SAMPLES})")
    sd = float(np.std(np.concatenate([v.F[k:] for v, k in zip(val_sets, skip)])))
    if not sd > 0:
        raise ValueError("the held-out measured force is constant: its NRMSE is undefined "
                         "(std(F) = 0)")


def _concat(sets) -> Dataset:
    cat = lambda key: np.concatenate([getattr(s, key) for s in sets])
    load = cat("load") if all(s.load is not None for s in sets) else None
    # time made monotonic across files (only used for labelling regions)
    t = np.concatenate([s.t - s.t[0] + (k * 0.0) for k, s in enumerate(sets)])
    t = np.arange(t.size) * sets[0].dt
    return Dataset(t=t, x=cat("x"), v=cat("v"), a=cat("a"), F=cat("F"), load=load,
                   name="+".join(s.name for s in sets))


