"""Where population evaluations run: in this process, in local worker processes, or on a
``dask.distributed`` cluster.

An executor has one method, ``costs(objective, X) -> cost[npop]``. The objective is shipped
to the workers once (process initializer / ``client.scatter``), then only parameter rows
travel. The numba in-process objective already runs its population on every core, so the
automatic choice keeps it inline and sends slow single-threaded objectives (co-simulation)
to a local process pool.
"""
from __future__ import annotations

import os

import numpy as np

__all__ = ["InlineExecutor", "ProcessExecutor", "DaskExecutor", "make_executor"]

_WORKER_OBJECTIVE = None


def _init_worker(objective):
    global _WORKER_OBJECTIVE
    _WORKER_OBJECTIVE = objective


def _worker_costs(X):
    return _WORKER_OBJECTIVE.costs(X)


def _dask_costs(objective, X):
    return objective.costs(X)


def _dask_predict(objective, X):
    return objective.predict(X)


def _chunks(X, n):
    n = max(1, min(n, len(X)))
    return [c for c in np.array_split(X, n) if len(c)]


class InlineExecutor:
    """Evaluate in this process (the objective may itself be parallel)."""
    name = "inline"

    def costs(self, objective, X):
        """Costs of the parameter rows ``X`` of ``objective``, in this process.

        Parameters
        ----------
        objective : Objective
            The objective.
        X : array_like, shape (npop, D)
            Parameter sets (physical values), one per row.
        """
        return objective.costs(X)

    def close(self):
        pass


class ProcessExecutor:
    """A pool of local worker processes; the population is split into one chunk per worker.

    Parameters
    ----------
    workers : int, optional
        Number of processes (default: CPU count).
    """
    name = "processes"

    def __init__(self, workers: int | None = None):
        self.workers = workers or os.cpu_count() or 1
        self._pool = None
        self._objective_id = None

    def _pool_for(self, objective):
        if self._pool is None or self._objective_id != id(objective):
            self.close()
            from concurrent.futures import ProcessPoolExecutor
            import multiprocessing as mp
            self._pool = ProcessPoolExecutor(self.workers, mp_context=mp.get_context("spawn"),
                                             initializer=_init_worker, initargs=(objective,))
            self._objective_id = id(objective)
        return self._pool

    def costs(self, objective, X):
        """Costs of the parameter rows ``X`` of ``objective``, split over the worker processes.

        Parameters
        ----------
        objective : Objective
            The objective (sent to each worker once).
        X : array_like, shape (npop, D)
            Parameter sets (physical values), one per row.
        """
        pool = self._pool_for(objective)
        parts = list(pool.map(_worker_costs, _chunks(np.asarray(X), self.workers)))
        return np.concatenate(parts)

    def close(self):
        if self._pool is not None:
            self._pool.shutdown(wait=True, cancel_futures=True)
            self._pool = None

    def __del__(self):  # pragma: no cover - best effort
        try:
            self.close()
        except Exception:
            pass


class DaskExecutor:
    """Evaluate on a ``dask.distributed`` cluster (for campaigns that outgrow one machine).

    The objective goes from here to every worker once per identification, with its data and
    its FMU files by value (:func:`identification.cluster.ship`: workers need no shared file
    system); then only parameter rows travel, one chunk per worker thread, each to the
    worker that holds its objective.

    Parameters
    ----------
    client : dask.distributed.Client
        A connected client (:func:`identification.cluster.connect`).
    chunks : int, optional
        Pieces per population (default: number of worker threads).
    """
    name = "dask"

    def __init__(self, client, chunks: int | None = None):
        self.client = client
        self.chunks = chunks
        self._shipped = None
        self._futures = {}  # worker address -> the shipped objective's future there
        self._objective_id = None
        self._closed = False
        #: the scheduler's address (for messages once it is gone)
        self.address = getattr(client, "scheduler_address", None) or "the scheduler"

    def _placed(self, objective) -> dict:
        """``worker -> future`` of the shipped objective on every current worker: sent
        from here once per worker (a worker that joins later gets it on the next call)."""
        from .cluster import ship
        if self._shipped is None or self._objective_id != id(objective):
            self._release()
            self._shipped = ship(objective)
            self._objective_id = id(objective)
        workers = sorted(self.client.nthreads())
        for w in [w for w in self._futures if w not in workers]:
            self._futures.pop(w).release()
        for w in workers:
            if w not in self._futures:
                self._futures[w] = self.client.scatter(self._shipped, workers=[w],
                                                       hash=False)
        return self._futures

    def costs(self, objective, X):
        """Costs of the parameter rows ``X[n, D]`` (physical values) of ``objective``.

        Parameters
        ----------
        objective : identification.objectives.Objective
        X : ndarray

        Returns
        -------
        ndarray
            One cost per row, in the order of ``X``.

        Raises
        ------
        identification.cluster.SchedulerError
            When the scheduler or a worker is lost during the evaluation.
        """
        return np.concatenate(self._map(_dask_costs, objective, X))

    def predict(self, objective, X):
        """Simulated outputs of the parameter rows ``X[n, D]`` (the objective's
        ``predict``: one row of ``len(objective.data)`` values per parameter row), e.g.
        the D perturbed sets of a finite-difference Jacobian
        (:meth:`identification.problem.Problem.jacobian`). After :meth:`close` (the search
        is over) they run here.

        Parameters
        ----------
        objective : identification.objectives.Objective
        X : ndarray

        Returns
        -------
        ndarray
            ``[n, len(objective.data)]``, in the order of ``X``.
        """
        if self._closed:
            return objective.predict(X)
        return np.concatenate(self._map(_dask_predict, objective, X), axis=0)

    def _map(self, fn, objective, X) -> list:
        """``fn(shipped objective, chunk)`` over the rows of ``X``, one chunk per worker
        thread, each on the worker that holds its objective; results in order. A worker
        lost meanwhile: the whole call runs again on the workers left (evaluations are
        deterministic, so nothing changes but the time); the scheduler lost, or no worker
        left: :class:`identification.cluster.SchedulerError`."""
        from concurrent.futures import CancelledError
        from distributed.scheduler import KilledWorker
        from .cluster import SchedulerError
        lost = (OSError, CancelledError, TimeoutError, KilledWorker)
        for attempt in range(3):
            try:
                placed = self._placed(objective)
                nthreads = self.client.nthreads()
                slots = [w for w in sorted(placed) for _ in range(max(1, nthreads.get(w, 1)))]
                if not slots:
                    raise OSError("no worker is connected")
                n = self.chunks or len(slots)
                futures = []
                for i, c in enumerate(_chunks(np.asarray(X), n)):
                    w = slots[i % len(slots)]
                    futures.append(self.client.submit(fn, placed[w], c, pure=False,
                                                      workers=[w], allow_other_workers=True))
                return self.client.gather(futures)
            except lost as exc:
                alive = self.client.status == "running" and self._workers_left()
                if alive and attempt < 2:
                    self._release()  # ship again to the workers that are left
                    self._objective_id = None
                    continue
                text = str(exc).strip().splitlines()
                raise SchedulerError(f"lost the dask cluster at {self.address} during the "
                                     f"run: {text[0] if text else type(exc).__name__} (a "
                                     f"--checkpoint keeps every finished evaluation)") \
                    from None

    def _workers_left(self) -> bool:
        try:
            return bool(self.client.nthreads())
        except Exception:  # noqa: BLE001 - the scheduler itself is gone
            return False

    def close(self):
        """Release the shipped objective on the workers (the client stays connected);
        later :meth:`predict` calls run here."""
        self._release()
        self._closed = True

    def _release(self):
        for f in self._futures.values():
            try:
                f.release()
            except Exception:  # noqa: BLE001 - a lost client has nothing to release
                pass
        self._futures = {}
        self._shipped = None
        self._objective_id = None


def make_executor(executor, objective):
    """Resolve ``executor`` (None/"auto", "inline", "processes", a dask Client, or an object
    with ``costs``) for ``objective``."""
    if executor is None or executor == "auto":
        return InlineExecutor() if objective.parallel_inside else ProcessExecutor()
    if executor == "inline":
        return InlineExecutor()
    if executor == "processes":
        return ProcessExecutor()
    if hasattr(executor, "costs"):
        return executor
    try:
        from dask.distributed import Client
    except ImportError:  # pragma: no cover
        Client = None
    if Client is not None and isinstance(executor, Client):
        return DaskExecutor(executor)
    raise ValueError(f"executor = {executor!r}: use 'auto', 'inline', 'processes', a "
                     f"dask.distributed.Client or an object with costs(objective, X)")
