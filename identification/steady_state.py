"""Steady-state friction maps and the seeds' two-step identification.

A **steady-state map** (:class:`friction.dataset.SteadyStateMap`) holds the friction force
``F`` [N] measured at constant velocity ``v`` [m/s], one row per plateau, with no time base:
the contract's map file (columns ``v, F`` and no ``t``), or the plateaus of a set of
constant-velocity runs (:func:`map_from_runs`). It pins the **static** parameters of a law,
those of its steady-state (Stribeck) curve ``F_ss(v) = g(v) sgn(v) + sigma2 v + b``:
``Fc, Fs, vs, alpha, sigma2, b`` and their direction twins (:data:`STATIC_NAMES`).

The **two-step method** of the seeds (and of most friction papers):

1. fit the static parameters to the map (:func:`identify_static`; per direction when the
   map covers both: the "-" twins become free and the offset ``b`` is held, since with a
   level per direction it is the same information - the reparameterisation is visible in
   the result's ``fixed``);
2. fit the dynamic ones (``sigma0, sigma1``: presliding, time series) with the static ones
   fixed (:func:`identify_two_step`; CLI ``--static-from STATIC.json`` or ``--fix``).

Also here: :func:`plateau` (the steady part of one constant-velocity run) and
:func:`breakaway` (the static friction of a force-ramp run: the force at which the joint
starts to slide).

Units: SI throughout (a rotary joint: rad, rad/s, N m).
"""
from __future__ import annotations

import math

import numpy as np

from friction import make_model
from friction.base import FrictionModel
from friction.dataset import Dataset, SteadyStateMap

from .objectives import Objective

__all__ = ["STATIC_NAMES", "static_names", "SteadyStateObjective", "check_map",
           "prepare_static", "identify_static", "identify_two_step", "static_values",
           "plateau", "map_from_runs", "breakaway"]

#: parameters of the steady-state (Stribeck) curve of the LuGre family and the static map
STATIC_NAMES = ("sigma2", "Fc", "Fs", "vs", "alpha", "b", "sigma2_neg", "Fc_neg", "Fs_neg",
                "vs_neg")
_STRIBECK_FIELDS = STATIC_NAMES + ("shape",)
#: fewest plateaus a map must have
MIN_PLATEAUS = 3


def static_names(model: FrictionModel) -> list[str]:
    """The law's free parameters that shape its steady-state curve (:data:`STATIC_NAMES`
    that are set; a twin left None is symmetric and not identified)."""
    return [n for n in model.free_names() if n in STATIC_NAMES]


def static_values(model: FrictionModel) -> dict:
    """The static parameter values of a law (twins left None omitted) [parameter units]."""
    out = {}
    for n in STATIC_NAMES:
        v = getattr(model.params, n, None)
        if v is not None:
            out[n] = float(v)
    return out


def check_map(smap, role: str = "fit") -> SteadyStateMap:
    """Validate a steady-state map for fitting or scoring (one-line errors)."""
    if not isinstance(smap, SteadyStateMap):
        raise TypeError(f"expected a SteadyStateMap, got {type(smap).__name__}")
    what = "steady-state map" if role == "fit" else "validation map"
    if len(smap) < MIN_PLATEAUS:
        raise ValueError(f"{what} {smap.name!r} has {len(smap)} plateaus: need at least "
                         f"{MIN_PLATEAUS}")
    if not np.std(smap.F) > 0:
        raise ValueError(f"{what} {smap.name!r}: F is constant, nothing to fit")
    if not np.any(smap.v != 0):
        raise ValueError(f"{what} {smap.name!r}: every plateau is at v = 0")
    return smap


class SteadyStateObjective(Objective):
    """NRMSE of the law's steady-state curve against a map.

    The classic LuGre and the static Stribeck law share the curve, evaluated for a whole
    population by the Stribeck numba kernel; any other law is evaluated row by row through
    its :meth:`friction.base.FrictionModel.steady_state` (slower, maps are short).

    Parameters
    ----------
    model : FrictionModel
        The law; its current values fix every parameter not in ``names``.
    smap : SteadyStateMap
        Plateau velocities [m/s] and forces [N].
    names : list of str
        Identified parameters (the columns of ``X``).
    """
    parallel_inside = True

    def __init__(self, model: FrictionModel, smap: SteadyStateMap, names):
        self.model = model
        self.data = smap
        self.names = list(names)
        self._fast = None
        if model.name in ("lugre", "stribeck") and set(self.names) <= set(STATIC_NAMES):
            kw = {k: getattr(model.params, k) for k in _STRIBECK_FIELDS}
            self._fast = make_model("stribeck", **kw)
            self._t = np.arange(len(smap), dtype=float)
            self._empty = np.zeros(0)

    def predict(self, X) -> np.ndarray:
        X = np.atleast_2d(np.asarray(X, float))
        v = self.data.v
        if self._fast is not None:
            Theta = self._fast.population_theta(self.names, X)
            return self._fast._population_kernel(self._t, v, self._empty, self._empty,
                                                 self._empty, np.ascontiguousarray(Theta), 0)
        out = np.full((X.shape[0], v.size), np.nan)
        for i, row in enumerate(X):
            try:
                m = self.model.with_values(**dict(zip(self.names, map(float, row))))
            except (ValueError, TypeError):
                continue  # inadmissible row: infinite cost
            out[i] = m.steady_state(v)
        return out


def _side_start(v, F):
    """Starting values (Fc, Fs, vs, sigma2) of one direction of a map from its plateaus:
    a line through the faster half, the excess of the slower plateaus over it."""
    s = np.abs(v)
    f = np.abs(F)
    order = np.argsort(s)
    s, f = s[order], f[order]
    half = max(2, s.size // 2)
    fast_s, fast_f = s[-half:], f[-half:]
    if np.ptp(fast_s) > 0:
        slope, icpt = np.polyfit(fast_s, fast_f, 1)
    else:
        slope, icpt = 0.0, float(np.median(fast_f))
    sigma2 = max(float(slope), 0.0)
    Fc = float(icpt) if icpt > 0 else float(np.median(f))
    excess = f - (Fc + sigma2 * s)
    Fs = max(Fc + float(np.max(excess[: max(1, s.size // 4)])), Fc * 1.001)
    big = excess > 0.37 * (Fs - Fc)
    vs = float(s[np.flatnonzero(big)[-1]]) if big.any() else float(np.median(s[:half]))
    return Fc, Fs, max(vs, float(s[s > 0].min()) if np.any(s > 0) else 1e-3), sigma2


def prepare_static(smap: SteadyStateMap, model, names=None, fixed=None,
                   per_direction="auto"):
    """The law, identified names and fixed values of a steady-state fit.

    Parameters
    ----------
    smap : SteadyStateMap
    model : str or FrictionModel
        A registry name starts from values read off the map (a line through the faster
        plateaus per direction, the excess of the slower ones); an instance keeps its
        values as the starting guess.
    names : list of str, optional
        Default: :func:`static_names` of the (possibly per-direction) law.
    fixed : dict, optional
        ``name -> value`` held.
    per_direction : "auto", bool
        Give each direction its own levels (``Fc_neg, Fs_neg, vs_neg, sigma2_neg`` free)
        when the map covers both. ``"auto"``: yes for a registry name, as the instance
        says otherwise. With a level per direction the offset ``b`` is the same information
        and is held at its value (0 by default) unless named or fixed explicitly.

    Returns
    -------
    (FrictionModel, list of str, dict fixed, list of str notes)
    """
    from_name = isinstance(model, str)
    if from_name:
        model = make_model(model)
    fixed = dict(fixed or {})
    notes = []
    both = (smap.v > 0).sum() >= 2 and (smap.v < 0).sum() >= 2
    if per_direction == "auto":
        per_direction = from_name
    twins = getattr(model, "twins", {})
    start = {}
    if from_name:
        for sign, suffix in ((1, ""), (-1, "_neg")):
            side = smap.v > 0 if sign > 0 else smap.v < 0
            if side.sum() < 2:
                continue
            Fc, Fs, vs, s2 = _side_start(smap.v[side], smap.F[side])
            if suffix and not (per_direction and both):
                continue
            for k, val in (("Fc", Fc), ("Fs", Fs), ("vs", vs), ("sigma2", s2)):
                if hasattr(model.params, k + suffix):
                    start[k + suffix] = val
        if not (smap.v > 0).sum() >= 2 and (smap.v < 0).sum() >= 2:
            # a map of v < 0 only: its levels are the "+" parameters of a symmetric law
            Fc, Fs, vs, s2 = _side_start(smap.v[smap.v < 0], smap.F[smap.v < 0])
            start.update(Fc=Fc, Fs=Fs, vs=vs, sigma2=s2)
    if per_direction and both and twins:
        for k, tw in twins.items():
            if getattr(model.params, tw, None) is None and hasattr(model.params, tw):
                start.setdefault(tw, start.get(k, getattr(model.params, k)))
        explicit_b = (names is not None and "b" in names) or "b" in fixed
        if not explicit_b and hasattr(model.params, "b"):
            fixed["b"] = float(model.params.b)
            notes.append(f"b held at {model.params.b:g}: with a level per direction the "
                         f"offset is carried by the levels (Fc+b, Fc_neg-b)")
    if start:
        try:
            model = model.with_values(**{k: v for k, v in start.items() if k not in fixed})
        except Exception:  # noqa: BLE001 - a start the law refuses: keep its defaults
            pass
    if names is None:
        names = [n for n in static_names(model) if n not in fixed]
    return model, list(names), fixed, notes


def identify_static(smap, model="lugre", *, per_direction="auto", **kwargs):
    """First step of the two-step method: the static parameters from a steady-state map.

    Parameters
    ----------
    smap : SteadyStateMap or path
        The map (or a map file: columns v, F and no t).
    model : str or FrictionModel
    per_direction : "auto", bool
        See :func:`prepare_static`.
    **kwargs
        As :func:`identification.identify` (``names``, ``bounds``, ``fixed``,
        ``algorithm``, ``seed``, ``max_evals``, ``progress``, ...).

    Returns
    -------
    IdentificationResult
        ``model`` carries the static values (and the law's defaults elsewhere), ``fixed``
        what was held (``b`` for a per-direction map), ``identifiability`` the report.
    """
    from .api import identify
    return identify(smap, model, per_direction=per_direction, **kwargs)


def identify_two_step(static_data, dynamic_data, model="lugre", *, static_names_=None,
                      dynamic_names=None, per_direction="auto", validation=None, seed=0,
                      algorithm=None, progress=None, static_kwargs=None,
                      dynamic_kwargs=None) -> dict:
    """The seeds' two-step protocol: static parameters first, then the dynamic ones with
    the static ones fixed.

    Parameters
    ----------
    static_data : SteadyStateMap, Dataset or path
        Step 1 data: a steady-state map (the protocol) or any record.
    dynamic_data : Dataset or path
        Step 2 data: presliding / time series (``t, v, F``).
    model : str or FrictionModel
    static_names_ : list of str, optional
        Step 1 names (default :func:`static_names`).
    dynamic_names : list of str, optional
        Step 2 names (default: the law's free parameters that are not static, e.g.
        ``sigma0, sigma1`` of the LuGre).
    per_direction : "auto", bool
        Step 1 per-direction levels (:func:`prepare_static`).
    validation : Dataset, optional
        Held-out record scored after step 2.
    seed, algorithm, progress
        As :func:`identification.identify` (both steps).
    static_kwargs, dynamic_kwargs : dict, optional
        Further keyword arguments of each step's :func:`identification.identify`.

    Returns
    -------
    dict
        ``static`` and ``dynamic`` (the two IdentificationResults) and ``model`` (the
        final law: static values from step 1, dynamic ones from step 2).
    """
    from .api import identify
    from .space import default_names
    r1 = identify(static_data, model, names=static_names_, seed=seed, algorithm=algorithm,
                  progress=progress, per_direction=per_direction, **(static_kwargs or {}))
    law = r1.model
    fixed = static_values(law)
    if dynamic_names is None:
        dynamic_names = [n for n in default_names(law) if n not in STATIC_NAMES]
    if not dynamic_names:
        raise ValueError(f"{law.name} has no dynamic parameters to identify in step 2")
    r2 = identify(dynamic_data, law, names=list(dynamic_names), fixed=fixed, seed=seed,
                  algorithm=algorithm, validation=validation, progress=progress,
                  **(dynamic_kwargs or {}))
    return {"static": r1, "dynamic": r2, "model": r2.model}


# ------------------------------------------------------------------------------ runs
def _moving_average(x, w):
    if w <= 1:
        return np.asarray(x, float)
    k = np.ones(w) / w
    pad = w // 2
    xp = np.concatenate([np.full(pad, x[0]), x, np.full(w - 1 - pad, x[-1])])
    return np.convolve(xp, k, mode="valid")


def plateau(run: Dataset, v_target=None, *, tolerance: float = 0.2, smooth: float = 0.3,
            exclude=None, min_samples: int = 10):
    """The constant-velocity part of one run and its friction level.

    The velocity is smoothed by a centred moving average over ``smooth`` seconds; the
    plateau is the longest stretch of samples within ``tolerance`` (relative) of
    ``v_target`` and not in ``exclude`` (e.g. samples at a torque limit). Its velocity is
    the mean slope of the position over the stretch (robust to the quantisation of a slow
    encoder), its force the median friction force.

    Parameters
    ----------
    run : Dataset
        One constant-velocity run (t [s], x [m], v [m/s], F [N]).
    v_target : float, optional
        Commanded velocity [m/s] (default: the median velocity of the run's second half).
    tolerance : float
        Relative band around ``v_target``.
    smooth : float
        Smoothing window [s].
    exclude : array of bool, optional
        Samples never part of a plateau.
    min_samples : int

    Returns
    -------
    dict or None
        ``v`` [m/s], ``F`` [N], ``F_spread`` (interquartile range / 1.35 [N]), ``t0``,
        ``t1`` [s], ``n``; None when no stretch of ``min_samples`` exists.
    """
    t, v = run.t, run.v
    if v_target is None:
        v_target = float(np.median(v[v.size // 2:]))
    if v_target == 0 or not math.isfinite(v_target):
        raise ValueError(f"v_target = {v_target!r}: a plateau needs a non-zero velocity")
    w = max(1, int(round(smooth / max(run.dt, 1e-12))))
    vs_ = _moving_average(v, w)
    ok = np.abs(vs_ - v_target) <= tolerance * abs(v_target)
    if exclude is not None:
        ok &= ~np.asarray(exclude, bool)
    if not ok.any():
        return None
    # longest run of True
    d = np.diff(np.concatenate([[0], ok.astype(int), [0]]))
    starts, ends = np.flatnonzero(d == 1), np.flatnonzero(d == -1)
    k = int(np.argmax(ends - starts))
    i0, i1 = int(starts[k]), int(ends[k])  # [i0, i1)
    if i1 - i0 < min_samples:
        return None
    sl = slice(i0, i1)
    dt_ = t[i1 - 1] - t[i0]
    vel = (run.x[i1 - 1] - run.x[i0]) / dt_ if "x" not in run.derived and dt_ > 0 \
        else float(np.mean(v[sl]))
    q25, q50, q75 = np.percentile(run.F[sl], [25, 50, 75])
    return {"v": float(vel), "F": float(q50), "F_spread": float((q75 - q25) / 1.349),
            "t0": float(t[i0]), "t1": float(t[i1 - 1]), "n": int(i1 - i0)}


def map_from_runs(runs, v_targets=None, *, name="steady state", **kwargs) -> SteadyStateMap:
    """A steady-state map from constant-velocity runs (one plateau per run, both
    directions).

    Parameters
    ----------
    runs : sequence of Dataset
        One run per commanded velocity.
    v_targets : sequence of float, optional
        Commanded velocities [m/s], one per run.
    **kwargs
        Passed to :func:`plateau` (``tolerance``, ``smooth``, ``exclude`` as one array per
        run is not supported here: give it through ``run.extra["exclude"]``).

    Returns
    -------
    SteadyStateMap
        ``extra``: ``F_spread``, ``t0``, ``t1``, ``n`` per plateau; runs without a plateau
        are skipped (their count is in ``notes``).
    """
    rows = []
    skipped = 0
    for i, run in enumerate(runs):
        vt = None if v_targets is None else v_targets[i]
        ex = run.extra.get("exclude")
        p = plateau(run, vt, exclude=None if ex is None else ex > 0, **kwargs)
        if p is None:
            skipped += 1
            continue
        rows.append(p)
    if len(rows) < 2:
        raise ValueError(f"only {len(rows)} of {len(runs)} runs have a plateau: no map")
    ex = {k: np.array([r[k] for r in rows], float) for k in ("F_spread", "t0", "t1", "n")}
    notes = (f"{skipped} run(s) without a plateau skipped",) if skipped else ()
    return SteadyStateMap(np.array([r["v"] for r in rows]), np.array([r["F"] for r in rows]),
                          name=name, extra=ex, notes=notes)


def breakaway(run: Dataset, v_threshold: float, *, start_fraction: float = 0.25):
    """Static (break-away) friction of a force-ramp run: the friction force at the first
    sample where the speed exceeds ``v_threshold`` in the direction of the ramp.

    The ramp's direction is the sign of the force where it first exceeds
    ``start_fraction`` of its largest magnitude (a controller's reaction after the slip,
    of the other sign, does not count).

    Parameters
    ----------
    run : Dataset
        Force ramp from rest: ``t`` [s], ``v`` [m/s], ``F`` [N] (friction force: below
        break-away it equals the applied force).
    v_threshold : float
        Speed [m/s] above which the joint counts as sliding (above the creep of the
        presliding regime, below the slowest sliding speed of interest).

    Returns
    -------
    dict or None
        ``F`` [N] (signed), ``t`` [s], ``index``; None if the run never slides.
    """
    if not v_threshold > 0:
        raise ValueError(f"v_threshold = {v_threshold!r}: must be > 0 [m/s]")
    F = np.asarray(run.F, float)
    big = np.abs(F) >= start_fraction * np.max(np.abs(F))
    k0 = int(np.argmax(big))
    sign = 1.0 if F[k0] > 0 else -1.0
    after = np.arange(F.size) >= k0
    hit = np.flatnonzero(after & (sign * run.v > v_threshold) & (sign * F > 0))
    if hit.size == 0:
        return None
    k = int(hit[0])
    return {"F": float(F[k]), "t": float(run.t[k]), "index": k}
