"""Where the diagnosis' candidate fits run: worker processes forked from this one, threads
of this process, or a ``dask.distributed`` cluster (force level and trajectory level).

In-process, the force level's candidate fits run on :data:`THREADS` workers
(:func:`local_fits`): they are independent of each other. On Linux
the workers are processes forked from this one (:func:`process_fits`): the fit record, the
base law and the compiled kernels are already in them, and each fit's Python parts (scipy's
trust region, each trial's start state) run beside the other's. Elsewhere, or inside a
daemonic process, they are threads (:func:`thread_fits`), which gain less: the laws'
kernels (``nogil``) and LAPACK release the interpreter lock, the Python parts do not
(20,000 samples, every candidate, session 25: one thread 7.3 s, two threads 6.5 s, two
forked processes 4.6 s; ``benchmarks/bench_diagnosis.py --speed-only``). Each worker runs
exactly the fit the serial loop runs; the report is the same.

Every candidate effect is re-identified jointly with the base law on the fit record
(:func:`diagnosis.composite.fit_composite`), independently of the others: they are mapped
over the workers, one task per candidate, with the fit record, its context and the base law
scattered to every worker once. Each task runs exactly what :func:`diagnosis.diagnose` runs
in-process, so the report is the same; scoring on the held-out records, the greedy stacking
and the verdict stay in the client.

At the trajectory level (:func:`diagnosis.trajectory.diagnose_trajectory`, the user's plant
FMU included) each candidate's fit is a series of plant simulations; the procedure's own
fit function (a closure over the plant, its engine and the records) is shipped by value
(:class:`identification.cluster.ShippedCall`: ``cloudpickle``, the plant FMU, the law FMUs and
the connection's further FMUs as bytes, written once per machine), once per worker, and
called once per candidate.

>>> from identification.cluster import connect                      # doctest: +SKIP
>>> rep = diagnose("fit.csv", "lugre", executor=connect("tcp://10.0.0.5:8786"))
"""
from __future__ import annotations

__all__ = ["candidate_fits", "applicable", "as_client", "trajectory_fits", "thread_fits",
           "process_fits", "local_fits", "can_fork", "costliest_first", "THREADS",
           "PROCESSES"]

import contextvars
import functools
import multiprocessing
import os
import sys
import threading
import warnings
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, ThreadPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool

from threadpoolctl import threadpool_limits

#: workers (forked processes or threads, :func:`local_fits`) the force level's candidate
#: fits run on when no cluster is given: ``None`` the environment's ``FRICTIONLAB_THREADS``,
#: else the machine's cores (at most :data:`MAX_THREADS`); 1 one after the other (a process
#: pool that already keeps every core busy sets ``FRICTIONLAB_THREADS=1`` in its workers)
THREADS = None
MAX_THREADS = 4
#: the in-process workers are processes forked from this one on Linux
#: (False: always threads)
PROCESSES = True


def as_client(executor):
    """The ``dask.distributed.Client`` behind ``executor`` (a client, or a
    :class:`identification.executors.DaskExecutor`), else ``None`` (fits run in-process).

    Parameters
    ----------
    executor : None, str, dask.distributed.Client or DaskExecutor
        ``None``, ``"inline"`` or ``"auto"``: in this process.

    Returns
    -------
    dask.distributed.Client or None
    """
    if executor is None or executor in ("inline", "auto"):
        return None
    client = getattr(executor, "client", executor)
    try:
        from dask.distributed import Client
    except ImportError:  # pragma: no cover
        Client = None
    if Client is not None and isinstance(client, Client):
        return client
    raise ValueError(f"executor = {executor!r}: the diagnosis runs its candidate fits "
                     f"in-process (None) or on a dask.distributed.Client")


def _fit_one(name, *, law, base_names, fit, ctx):
    """Best (composite, fit NRMSE) of candidate ``name`` over its law variants
    (:func:`diagnosis.candidates.best_variant`), or None when it does not apply (the client
    decides what to report)."""
    from .candidates import best_variant, law_variants
    from .composite import fit_composite
    from .effects import CANDIDATES  # the registry diagnose() uses
    cand = CANDIDATES[name].specialise(law)
    return best_variant([fit_composite(law_v, names_v, [form], fit, ctx)
                         for law_v, names_v, form in law_variants(cand, law, base_names, ctx)],
                        ctx)


def applicable(names, law, fit, ctx, val_sets) -> list:
    """The candidates of ``names`` that :func:`diagnosis.diagnose` fits: those that apply
    to ``law`` on ``fit`` and whose columns every held-out record has.

    Parameters
    ----------
    names : list of str
    law : FrictionModel
    fit : friction.dataset.Dataset
    ctx : diagnosis.effects.Context
    val_sets : list of friction.dataset.Dataset

    Returns
    -------
    list of str
    """
    from .candidates import missing_columns as _missing_columns
    from .effects import CANDIDATES
    out = []
    for n in names:
        cand = CANDIDATES[n].specialise(law)
        ok, _ = cand.applicable(law, fit, ctx)
        if ok and not _missing_columns(cand, val_sets, ctx):
            out.append(n)
    return out


def candidate_fits(executor, names, law, base_names, fit, ctx, val_sets=()) -> dict:
    """The candidates' joint fits on the cluster behind ``executor``.

    Parameters
    ----------
    executor : None, dask.distributed.Client or DaskExecutor
        ``None``: nothing runs here (``{}``; the caller fits in-process).
    names : list of str
        Candidate effects; those that do not apply (:func:`applicable`) are left out.
    law : FrictionModel
        The fitted base law (the candidates' start).
    base_names : list of str
        Its free parameters.
    fit : friction.dataset.Dataset
        The fit record [SI units].
    ctx : diagnosis.effects.Context
        Its scales.
    val_sets : list of friction.dataset.Dataset
        The held-out records (a candidate needs its columns in them).

    Returns
    -------
    dict
        ``name -> (Composite, fit NRMSE)``, the same as the in-process loop gives.
    """
    client = as_client(executor)
    if client is None:
        return {}
    names = applicable(names, law, fit, ctx, val_sets)
    if not names:
        return {}
    import functools
    from identification.cluster import ShippedCall, run_shipped
    # the fit record, its context and the base law go to each worker once, with the call
    call = ShippedCall(functools.partial(_fit_one, law=law, base_names=list(base_names),
                                         fit=fit, ctx=ctx))
    return dict(zip(names, run_shipped(client, call, list(names))))


def thread_count(threads=None) -> int:
    """Threads the candidate fits run on: ``threads``, else :data:`THREADS`, else the
    environment's ``FRICTIONLAB_THREADS``, else the machine's cores (at most
    :data:`MAX_THREADS`)."""
    n = threads if threads is not None else THREADS
    if n is None:
        env = os.environ.get("FRICTIONLAB_THREADS", "").strip()
        try:
            n = int(env) if env else min(os.cpu_count() or 1, MAX_THREADS)
        except ValueError:
            raise ValueError(f"FRICTIONLAB_THREADS = {env!r}: give a whole number of "
                             f"threads >= 1") from None
    n = int(n)
    if n < 1:
        raise ValueError(f"threads = {n}: at least 1")
    return n


def _side_by_side(names, law, fit, ctx, val_sets, threads) -> tuple:
    """``(workers, candidates to fit side by side)``: none (the caller's loop fits them)
    with one worker or fewer than two candidates that apply."""
    n = thread_count(threads)
    names = applicable(names, law, fit, ctx, val_sets) if n > 1 else []
    return n, (names if len(names) >= 2 else [])


def _bound_fit(law, base_names, fit, ctx):
    """:func:`_fit_one` with the base law, its free parameters, the record and its
    context bound: ``one(name) -> (Composite, fit NRMSE)``."""
    return functools.partial(_fit_one, law=law, base_names=list(base_names), fit=fit, ctx=ctx)


def costliest_first(names, law, base_names, ctx) -> list:
    """``names`` with the costliest fits first, so that no long one starts last and runs
    alone: by the candidates' measured :attr:`~diagnosis.candidates.Candidate.fit_cost`,
    then (unmeasured ones) by their Jacobian's width (most columns first). The width alone
    put the GMS fit, the costliest, last: on the speed case of
    ``benchmarks/bench_diagnosis.py`` it ran alone for its last 0.6 s."""
    from .candidates import law_variants
    from .effects import CANDIDATES
    key = {}
    for name in names:
        cand = CANDIDATES[name].specialise(law)
        width = max((len(form.force_extras(ctx)) + len(nv) for _, nv, form
                     in law_variants(cand, law, base_names, ctx)), default=0)
        key[name] = (-float(cand.fit_cost), -width)
    return sorted(names, key=lambda nm: key[nm])


def thread_fits(names, law, base_names, fit, ctx, val_sets=(), threads=None) -> dict:
    """The candidates' joint fits on threads of this process.

    Parameters
    ----------
    names : list of str
        Candidate effects; those that do not apply (:func:`applicable`) are left out.
    law : FrictionModel
        The fitted base law (the candidates' start).
    base_names : list of str
        Its free parameters.
    fit : friction.dataset.Dataset
        The fit record [SI units].
    ctx : diagnosis.effects.Context
        Its scales.
    val_sets : list of friction.dataset.Dataset
        The held-out records (a candidate needs its columns in them).
    threads : int, optional
        Threads (default :func:`thread_count`); 1: ``{}`` (the caller's loop fits).

    Returns
    -------
    dict
        ``name -> (Composite, fit NRMSE)``, the same as the serial loop gives.
    """
    n, names = _side_by_side(names, law, fit, ctx, val_sets, threads)
    if not names:
        return {}
    one = _bound_fit(law, base_names, fit, ctx)
    order = costliest_first(names, law, base_names, ctx)
    # one BLAS thread per fit while they run side by side: each fit's trust-region steps
    # take SVDs of its Jacobian, and two fits whose BLAS spawns a thread per core each
    # oversubscribe the cores (OpenBLAS's threads spin while they wait; measured below)
    with threadpool_limits(limits=1, user_api="blas"), \
            ThreadPoolExecutor(max_workers=min(n, len(names))) as pool:
        # each fit in a copy of the caller's context (its progress reporter)
        futures = {name: pool.submit(contextvars.copy_context().run, one, name)
                   for name in order}
        return {name: futures[name].result() for name in names}


def can_fork() -> bool:
    """Whether :func:`local_fits` may fork its workers: :data:`PROCESSES` is on, this is
    Linux (macOS forks, but a child of a process that used Apple's frameworks, numpy's
    Accelerate among them, may crash: Python's own default there is to spawn), and this
    process is not daemonic (those may not have children)."""
    return (PROCESSES and sys.platform.startswith("linux")
            and "fork" in multiprocessing.get_all_start_methods()
            and not multiprocessing.current_process().daemon)


#: the forked workers' job, set before the fork (the children read their copy): the fit
#: function with the record, the law and the context bound, and the progress queue; one
#: caller's pool at a time holds it (:data:`_JOB_LOCK`: diagnoses run from two threads)
_JOB = {}
_JOB_LOCK = threading.Lock()


def _worker_start():
    """A forked worker's start: population simulations row by row (the parent's numba may
    run GNU OpenMP, whose parallel kernels abort a forked child)."""
    from friction import base
    base.SERIAL_POPULATIONS = True


def _forked_fit(name):
    """One candidate's fit in a forked worker, its progress ticks sent to the parent."""
    from .composite import reporting
    ticks = _JOB.get("ticks")
    send = (lambda n, info: ticks.put((n, info))) if ticks is not None else None
    with reporting(send):
        best = _JOB["one"](name)
    if best is not None:
        best[0].ctx = None  # the parent has it: not pickled back (the record's size)
    return best


def process_fits(names, law, base_names, fit, ctx, val_sets=(), threads=None) -> dict:
    """The candidates' joint fits in worker processes forked from this one.

    The workers inherit the fit record, the base law and the compiled kernels (nothing is
    sent but each candidate's name; each result comes back pickled). A fit that raises
    raises here; a worker that dies leaves its candidates out of the result, for the
    caller's loop to fit.

    Parameters
    ----------
    names, law, base_names, fit, ctx, val_sets
        As :func:`thread_fits`.
    threads : int, optional
        Worker processes (default :func:`thread_count`); 1: ``{}`` (the caller's loop
        fits).

    Returns
    -------
    dict
        ``name -> (Composite, fit NRMSE)``, the same as the serial loop gives.
    """
    n, names = _side_by_side(names, law, fit, ctx, val_sets, threads)
    if not names:
        return {}
    from .composite import _PROGRESS
    progress = _PROGRESS.get()
    mp = multiprocessing.get_context("fork")
    out = {}
    with _JOB_LOCK:
        _JOB["one"] = _bound_fit(law, base_names, fit, ctx)
        _JOB["ticks"] = mp.SimpleQueue() if progress is not None else None
        _run_pool(names, law, base_names, ctx, n, mp, progress, out)
    return {name: out[name] for name in names if name in out}


def _run_pool(names, law, base_names, ctx, n, mp, progress, out):
    """The pool of :func:`process_fits`: its results into ``out`` as they come."""
    try:
        # one BLAS thread in each worker (inherited through the fork), as in thread_fits
        with threadpool_limits(limits=1, user_api="blas"), \
                ProcessPoolExecutor(max_workers=min(n, len(names)), mp_context=mp,
                                    initializer=_worker_start) as pool, \
                warnings.catch_warnings():
            # Python 3.12+ warns on a fork of a process with threads (numba's, OpenBLAS's):
            # the children run only the fits, not the threads' work
            warnings.simplefilter("ignore", DeprecationWarning)
            futures = {pool.submit(_forked_fit, name): name
                       for name in costliest_first(names, law, base_names, ctx)}
            pending = set(futures)
            while pending:
                done, pending = wait(pending, timeout=0.25, return_when=FIRST_COMPLETED)
                _relay(_JOB["ticks"], progress)
                for fut in done:
                    try:
                        best = fut.result()
                    except BrokenProcessPool:
                        continue  # the caller's loop fits it
                    if best is not None:
                        best[0].ctx = ctx
                    out[futures[fut]] = best
            _relay(_JOB["ticks"], progress)
    finally:
        _JOB.clear()


def _relay(ticks, progress):
    """The workers' progress ticks so far, to the caller's reporter."""
    while ticks is not None and not ticks.empty():
        progress(*ticks.get())


def local_fits(names, law, base_names, fit, ctx, val_sets=(), threads=None) -> dict:
    """The candidates' joint fits in this machine's workers: forked processes where
    :func:`can_fork`, else threads.

    Parameters
    ----------
    names, law, base_names, fit, ctx, val_sets, threads
        As :func:`thread_fits` (``threads``: the workers, processes or threads).

    Returns
    -------
    dict
        ``name -> (Composite, fit NRMSE)``, the same as the serial loop gives.
    """
    run = process_fits if can_fork() else thread_fits
    return run(names, law, base_names, fit, ctx, val_sets, threads)


def trajectory_fits(executor, names, run_one, tm, engine) -> dict:
    """The trajectory level's candidate fits on the cluster behind ``executor``.

    Parameters
    ----------
    executor : None, dask.distributed.Client or DaskExecutor
        ``None``: nothing runs here (``{}``).
    names : list of str
        Candidates to fit (those that apply).
    run_one : callable
        ``run_one(name) -> result``: the procedure's fit of one candidate (a closure).
    tm : diagnosis.trajectory.TrajectoryModel
        Its plant runner (the plant whose FMU files travel; its progress bar stays here).
    engine : object
        The simulation engine (its open FMU instances are closed before shipping and
        reopened here when next used).

    Returns
    -------
    dict
        ``name -> run_one(name)`` as the workers computed it.
    """
    client = as_client(executor)
    if client is None or not names:
        return {}
    from identification.cluster import ShippedCall, run_shipped
    if hasattr(engine, "close"):
        engine.close()  # FMU instances belong to this process; the workers open their own
    progress, tm.progress = tm.progress, None  # a terminal bar does not travel
    try:
        call = ShippedCall(run_one, [tm.plant, getattr(engine, "plant", None)])
    finally:
        tm.progress = progress
    return dict(zip(names, run_shipped(client, call, list(names))))
