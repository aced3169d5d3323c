"""Runs the benchmark's cases (in parallel, resumable) and scores them."""
from __future__ import annotations

import time

import numpy as np

from friction.progress import status_lines

from ..core import BaseFitError, diagnose
from ..effects import EFFECTS
from .cases import CASES, EFFECT_SIZE, applicable, expected, make_case, make_plant_case
from .kinematics import _KIN_CACHE, PLANT_NAMES, _init_worker, plant_kinematics
from .scoring import _base_failed_row, _score, practical_size, summarise, truth_shift

__all__ = ["run_benchmark", "load_checkpoint"]

#: seconds of one base identification per (plant, quick), the time baseline of each worker
_BASE_SECONDS: dict = {}


#: motion channels of the generalisation grid (``measured=True``), taken in turn: encoder
#: counts per sample at the top speed and how the velocity is differentiated
MEASURED = ({"counts": 200.0, "velocity": "gradient"}, {"counts": 1000.0, "velocity": "backward"},
            {"counts": 50.0, "velocity": "lowpass"}, {"counts": 1000.0, "velocity": "gradient"},
            {"counts": 200.0, "velocity": "backward"}, {"counts": 50.0, "velocity": "gradient"})


#: smallest share of the requested effect size a truth form must reach on a plant's motion
#: to make a case
MIN_SIZE = 0.7


def _run_one(job):
    plant, eff, s, nz, seed, quick, dseed, form, meas = job
    key = (plant, quick)
    if key not in _BASE_SECONDS:
        # the time baseline, measured where and while the cases run (same load, same process)
        _BASE_SECONDS[key] = _base_identification_seconds(plant, quick, dseed)
    if plant is None:
        data, truth = make_case(eff, s, nz, seed=seed, return_truth=True)
        model, erms = "lugre", None
    else:
        case = make_plant_case(plant, eff, s, nz, seed=seed, quick=quick, form=form,
                               measured=None if meas is None else MEASURED[meas])
        data, model, erms = case.data, case.base, case.effect_rms
        # the oracle's truth: the effect as the data-rate law carries it (the base's own
        # discretisation is no effect: a clean record's fine truth closes up to 23 % of the
        # XML-350's gap by it alone)
        truth = case.truth - case.info["discretisation"]
        if eff != "clean" and erms < MIN_SIZE * s * EFFECT_SIZE:
            # the truth form cannot make the requested size on this motion (a stiction
            # peak the motion never dwells in): no case, said so
            return {"plant": plant, "effect": eff, "strength": s, "noise": nz,
                    "form": form or "", "effect_rms": erms, "_job": job,
                    "skipped": f"the truth reaches {erms / (s * EFFECT_SIZE):.2f} of the "
                               f"requested size on this motion"}
    t0 = time.perf_counter()
    row = {"plant": plant or "generic", "effect": eff, "strength": s, "noise": nz,
           "form": form or "", "measured": "" if meas is None else
           "{velocity}/{counts:g}".format(**MEASURED[meas]),
           "samples": len(data), "effect_rms": erms, "base_id_seconds": _BASE_SECONDS[key],
           "_job": job}
    try:
        rep = diagnose(data, model, seed=dseed)
    except BaseFitError as exc:
        # the diagnosis stopped on a base that fits worse than a constant: a miss of the
        # case (never a name), scored as such instead of ending the benchmark
        row.update(_base_failed_row(eff, exc, time.perf_counter() - t0))
        return row
    dt = time.perf_counter() - t0
    row.update(_score(eff, expected(eff), rep, data, truth, dt))
    if plant is not None and eff == "delay":
        # the rule: a shift below a sample is no delay, so a truth that small is
        # no case any verdict may name (counted apart from the detectable ones)
        case.info["truth_shift"], case.info["shift_left"] = truth_shift(
            data.t, case.info["base_force"], case.truth, left=True)
        row["truth_shift"], row["shift_left"] = case.info["truth_shift"], case.info["shift_left"]
        reason = practical_size(eff, case.info)
        if reason:
            row["detectable"], row["below_practical"] = False, reason
    return row


def _forms(eff, family, plant):
    """Truth forms of ``eff`` a run of ``family`` covers (``None``: the default form)."""
    if plant is None or family == "first" or eff not in EFFECTS:
        return [] if family == "sealed" else [None]
    return list(EFFECTS[eff].forms(family))


def _stable(*parts) -> int:
    """A number [0, 2**32) fixed by ``parts`` alone (CRC-32 of their text): a case's noise
    seed and its form's first measurement protocol in the generalisation grid."""
    import zlib
    return zlib.crc32("|".join(repr(p) for p in parts).encode())


def _base_identification_seconds(plant, quick, seed):
    """Wall time of one base identification on the plant's clean case (the time baseline)."""
    from identification import identify
    from ..core import _base_law
    if plant is None:
        data = make_case("clean", 1.0, 0.02, seed=seed)
        model = "lugre"
    else:
        case = make_plant_case(plant, "clean", 1.0, 0.02, seed=seed, quick=quick)
        data, model = case.data, case.base
    fit, _ = data.split(0.7)
    law, names = _base_law(model, fit)
    t0 = time.perf_counter()
    identify(fit, law, names=names, seed=seed)
    return time.perf_counter() - t0


def _job_key(job) -> str:
    plant, eff, s, nz, seed, quick, dseed, form, meas = job
    key = f"{plant}|{eff}|{s!r}|{nz!r}|{seed}|{int(bool(quick))}|{dseed}"
    # the default grid keeps its historical keys (checkpoints stay readable)
    return key if form is None and meas is None else f"{key}|{form}|{meas}"


def load_checkpoint(path, keys) -> dict:
    """Rows already scored in a checkpoint file (one JSON object per line, with its job
    ``key``); a truncated last line (a run killed while writing) is ignored.

    Parameters
    ----------
    path : str or None
        The checkpoint file (None, or a file that does not exist: nothing done yet).
    keys : set of str
        Keys of the jobs of this run; rows of other jobs are left out.

    Returns
    -------
    dict
        Job key -> its row.
    """
    import json
    import os
    done = {}
    if path is None or not os.path.exists(path):
        return done
    with open(path) as fh:
        for line in fh:
            try:
                row = json.loads(line)
            except json.JSONDecodeError:
                continue
            if isinstance(row, dict) and row.get("key") in keys:
                done[row["key"]] = row
    return done


def grid_jobs(plist, effects, forms, strengths, noises, clean_repeats, measured, quick,
              seed) -> list:
    """The benchmark's cases as jobs ``(plant, effect, strength, noise, noise seed, quick,
    diagnosis seed, form, measurement protocol)``, in order (arguments as
    :func:`run_benchmark`'s; ``plist`` the plants, ``[None]`` for the generic cases)."""
    jobs = []
    for plant in plist:
        for eff in effects:
            if plant is not None and not applicable(plant, eff, quick):
                continue
            reps = clean_repeats if eff == "clean" else 1
            for form in _forms(eff, forms, plant):
                # measured cases: each case's noise seed and each form's protocols follow
                # from the case itself, not from its place in the list, so that a family
                # added to the grid leaves every other case as it was (paired comparisons)
                offset = _stable(plant, eff, form) % len(MEASURED)
                i = 0
                for s in strengths:
                    for nz in noises:
                        for r in range(reps):
                            if measured and plant is not None:
                                meas = (offset + i) % len(MEASURED)
                                nseed = seed + 1 + _stable(plant, eff, form, s, nz, r) % 10**6
                            else:
                                meas, nseed = None, seed + len(jobs) + 1
                            i += 1
                            jobs.append((plant, eff, s, nz, nseed, quick, seed, form, meas))
    return jobs


def sample_jobs(jobs, n, seed=0) -> list:
    """A uniform random ``n`` of ``jobs`` (all of them if fewer), drawn with ``seed``, in
    the grid's order.

    Raises
    ------
    ValueError
        ``n`` is not a positive whole number.
    """
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
        raise ValueError(f"sample = {n!r}: the number of cases to draw must be a whole "
                         f"number >= 1")
    if n >= len(jobs):
        return list(jobs)
    pick = np.random.default_rng(seed).choice(len(jobs), size=int(n), replace=False)
    return [jobs[i] for i in sorted(pick)]


def select_jobs(jobs, keys) -> list:
    """The ``jobs`` whose keys (:func:`_job_key`) are in ``keys``, in the grid's order.

    Raises
    ------
    ValueError
        A key names no case of the grid (another grid's options, or a typing error), or
        ``keys`` is empty.
    """
    want = set(keys)
    if not want:
        raise ValueError("keys: no case key given")
    out = [j for j in jobs if _job_key(j) in want]
    missing = want - {_job_key(j) for j in out}
    if missing:
        raise ValueError(f"keys: {len(missing)} of {len(want)} keys name no case of this "
                         f"grid (its plants, effects, strengths, noises and protocols), "
                         f"e.g. {sorted(missing)[0]!r}")
    return out


def read_keys(path) -> list:
    """Case keys from ``path``: a checkpoint (JSON lines with a ``key``) or one key a
    line; blank lines and a checkpoint's truncated last line are skipped."""
    import json
    out = []
    with open(path) as fh:
        for line in fh:
            line = line.strip()
            if not line:
                continue
            if line.startswith("{"):
                try:
                    row = json.loads(line)
                except ValueError:
                    continue            # a run killed while writing its last line
                if "key" in row:
                    out.append(row["key"])
            else:
                out.append(line)
    return out


def run_benchmark(effects=CASES, strengths=(0.5, 1.0), noises=(0.01, 0.03), seed=0,
                  progress=None, plants=None, quick: bool = False, workers: int = 1,
                  clean_repeats: int = 1, checkpoint=None, forms: str = "first",
                  measured: bool = False, sample: int | None = None,
                  sample_seed: int = 0, keys=None) -> dict:
    """Run every case and score it.

    Parameters
    ----------
    effects : sequence of str
        Effects to withhold (``clean`` and ``outside`` included by default).
    strengths, noises : sequence of float
        Effect strengths [-] and noise levels (fraction of std(F)) [-].
    seed : int
        Base seed (noise seeds are ``seed + case number``, with ``measured`` ``seed + 1 +``
        a number fixed by the case's plant, effect, form, strength and noise; the diagnosis
        uses ``seed``).
    progress : None, bool, tqdm or callable(n, info), optional
        As :mod:`friction.progress` says: one status line per case (``n`` = 0); ``True``:
        lines on stderr.
    plants : None, "all" or sequence of str
        ``None``: the generic mass-like benchmark (historical); ``"all"``: every plant of
        :data:`PLANT_NAMES`; or a list of plant names.
    quick : bool
        Short plant protocols (tests).
    workers : int
        Processes running cases in parallel (1: in this process).
    clean_repeats : int
        Clean cases per (noise, strength) with different noise seeds.
    checkpoint : str or path, optional
        File the scored rows are appended to as they finish (JSON lines); a run started
        again with the same file and grid skips the cases already in it (resume after an
        interruption).
    forms : {"first", "all", "sealed"}
        Per-plant truth forms of each effect (:meth:`diagnosis.effects.Effect.forms`): its
        default form, every open form (the generalisation grid), or the sealed family only
        (no ``clean``/``outside`` cases then).
    measured : bool
        Per-plant cases with the motion channels a user records (positions quantised and
        differentiated, :data:`MEASURED` in turn) instead of the exact sampled motion.
    sample : int, optional
        Run a uniform random ``sample`` of the grid's cases only, drawn with
        ``sample_seed`` (:func:`sample_jobs`: the same cases for the same grid and seed, so
        two versions of the code are compared case by case).
    sample_seed : int
        Seed of the draw.
    keys : iterable of str, optional
        Run only the grid's cases with these job keys (:func:`select_jobs`: a checkpoint's
        cases again, after a family joined the grid and changed what ``sample`` draws).

    Returns
    -------
    dict
        ``rows`` (one per case), ``skipped`` (truth forms that cannot make the requested
        size on a plant's motion, :data:`MIN_SIZE`, with the reason), ``top1_accuracy``,
        ``clean_false_attributions``,
        ``outside_named_wrongly``, and (see :func:`summarise`) ``overall``, ``per_plant``
        and ``per_effect`` figures: localisation accuracy, shrink error, seconds per case
        and, as the time baseline, one base identification of the plant's clean case timed
        in the same process as its cases (``time_ratio`` = seconds per case / baseline).
    """
    if plants == "all":
        plants = PLANT_NAMES
    plist = [None] if plants is None else list(plants)
    for plant in plist:  # simulate each plant once here; workers get the kinematics
        if plant is not None:
            plant_kinematics(plant, quick)
    jobs = grid_jobs(plist, effects, forms, strengths, noises, clean_repeats, measured,
                     quick, seed)
    if sample is not None:
        jobs = sample_jobs(jobs, sample, sample_seed)
    if keys is not None:
        jobs = select_jobs(jobs, keys)
    say = status_lines(progress)
    rows, skipped = [], []
    keys = [_job_key(j) for j in jobs]
    resumed = load_checkpoint(checkpoint, set(keys))
    if resumed:
        say(f"[benchmark] resuming: {len(resumed)} of {len(jobs)} cases read from {checkpoint}")
        for k in keys:
            if k in resumed:
                (skipped if resumed[k].get("skipped") else rows).append(resumed[k])
    todo = [j for j, k in zip(jobs, keys) if k not in resumed]
    if checkpoint is not None and resumed:
        with open(checkpoint, "rb+") as fh:  # a line cut by the interruption: end it
            fh.seek(0, 2)
            if fh.tell() > 0:
                fh.seek(-1, 2)
                if fh.read(1) != b"\n":
                    fh.write(b"\n")

    def done(row, k):
        if checkpoint is not None:
            import json
            row["key"] = _job_key(row.pop("_job"))
            with open(checkpoint, "a") as fh:
                fh.write(json.dumps(row, default=float) + "\n")
        else:
            row.pop("_job", None)
        k += len(resumed)
        if row.get("skipped"):
            skipped.append(row)
            say(f"[benchmark {k}/{len(jobs)}] {row['plant']} {row['effect']} {row['form']} "
                f"s={row['strength']}: skipped, {row['skipped']}")
            return
        rows.append(row)
        lc = row["loc_correct"]
        lc = "-" if lc is None else "ok" if lc else "miss"
        say(f"[benchmark {k}/{len(jobs)}] {row['plant']} {row['effect']} s={row['strength']} "
            f"noise={row['noise']}: {row['verdict']} "
            f"({'ok' if row['correct'] else 'WRONG, expected ' + row['expected']}); where "
            f"{row['loc_family']} ({lc}); "
            f"shrink {row['gap_closed']:.2f} vs truth {row['truth_shrink']:.2f}; "
            f"{row['seconds']:.1f} s")

    if workers > 1 and len(todo) > 1:
        import multiprocessing as mp
        from concurrent.futures import ProcessPoolExecutor
        with ProcessPoolExecutor(max_workers=workers, mp_context=mp.get_context("spawn"),
                                 initializer=_init_worker, initargs=(dict(_KIN_CACHE),)) as ex:
            for k, row in enumerate(ex.map(_run_one, todo), 1):
                done(row, k)
    else:
        for k, job in enumerate(todo, 1):
            done(_run_one(job), k)
    if checkpoint is not None:  # the grid's order, resumed or not
        order = {k: i for i, k in enumerate(keys)}
        rows.sort(key=lambda r: order[r["key"]])
    out = summarise(rows)
    out["skipped"] = skipped
    return out
