"""Running on a ``dask.distributed`` cluster: connect to a scheduler, and ship an objective
(its FMU files and its data) to the workers once.

A worker may sit on another machine with no shared file system, so a co-simulation
objective cannot be sent with the paths of its FMUs. :func:`ship` wraps it in a
:class:`ShippedObjective` that carries the FMU files' bytes (:class:`FileBundle`) beside the
objective and its measured data. :class:`identification.executors.DaskExecutor` scatters
that wrapper to every worker once per identification (``client.scatter(...,
broadcast=True)``); after that only parameter rows travel. On a worker the bundle is written
once per machine into ``<tempdir>/frictionlab-shipped-<uid>/<sha256>/`` (private to the user;
a second worker process on the same machine, or a second identification with the same FMUs,
finds it there after checking the files' hashes) and the objective's paths are pointed at
it. Each worker thread evaluates on its own copy of the
objective (an FMU instance is not thread-safe).

>>> from identification.cluster import connect                        # doctest: +SKIP
>>> client = connect("tcp://10.0.0.5:8786")
>>> res = identify_plant_fmu("run.csv", "rig.fmu", "rig.toml", executor=client)

A dask scheduler runs whatever code its clients send: keep it on a private network (bind it
to 127.0.0.1 or a private interface) or behind dask's TLS settings (see the README).
"""
from __future__ import annotations

import dataclasses
import hashlib
import os
import pickle
import tempfile
import threading

__all__ = ["connect", "SchedulerError", "FileBundle", "ShippedObjective", "ship",
           "ShippedCall", "run_shipped", "worker_stats", "CONNECT_TIMEOUT"]

#: seconds to wait for the scheduler to answer (and again for its first worker) [s]
CONNECT_TIMEOUT = 5.0


class SchedulerError(ConnectionError):
    """The dask scheduler cannot be reached, has no workers, or was lost during a run."""


def _first_line(exc) -> str:
    text = str(exc).strip()
    return text.splitlines()[0] if text else type(exc).__name__


def connect(address: str, timeout: float | None = None, *, workers: int = 1, security=None):
    """A ``dask.distributed.Client`` connected to the scheduler at ``address``.

    Parameters
    ----------
    address : str
        Scheduler address, e.g. ``"tcp://127.0.0.1:8786"`` (``tls://...`` with dask's TLS
        settings in its configuration).
    timeout : float, optional
        Seconds to wait for the scheduler to answer, then as long again for ``workers``
        workers to be connected to it [s] (default :data:`CONNECT_TIMEOUT`).
    workers : int
        Workers the scheduler must have before the run starts (a scheduler without
        workers would leave the run waiting for ever).
    security : distributed.security.Security, optional
        TLS settings for a ``tls://`` address (default: dask's configuration,
        ``distributed.comm.tls.*``).

    Returns
    -------
    dask.distributed.Client

    Raises
    ------
    SchedulerError
        One line naming the address: unreachable within ``timeout``, a malformed address,
        or no worker connected.
    ImportError
        When ``dask.distributed`` is not installed.
    """
    try:
        from dask.distributed import Client
    except ImportError:  # pragma: no cover - dask is a dependency of the test extra
        raise ImportError("--scheduler needs dask.distributed: pip install "
                          "'dask[distributed]'") from None
    if not isinstance(address, str) or not address.strip():
        raise SchedulerError(f"dask scheduler address {address!r}: expected e.g. "
                             f"tcp://127.0.0.1:8786")
    address = address.strip()
    timeout = float(CONNECT_TIMEOUT if timeout is None else timeout)
    try:
        client = Client(address, timeout=timeout, set_as_default=False,
                        **({} if security is None else {"security": security}))
    except Exception as exc:  # noqa: BLE001 - OSError, TimeoutError, ValueError (bad URI)
        raise SchedulerError(f"cannot reach the dask scheduler at {address} within "
                             f"{timeout:g} s: {_first_line(exc)}") from None
    try:
        client.wait_for_workers(workers, timeout=timeout)
    except Exception:  # noqa: BLE001 - dask raises TimeoutError
        client.close()
        raise SchedulerError(f"the dask scheduler at {address} has no worker after "
                             f"{timeout:g} s: start some with 'dask worker {address}'") \
            from None
    return client


# -- files shipped by value ----------------------------------------------------------------------
#: per worker process: bundle digest -> folder it was written to
_EXTRACTED: dict = {}
_LOCK = threading.Lock()
#: per worker process: what this process did (for tests and diagnostics)
_STATS = {"chunks": 0, "rows": 0, "predicted": 0, "extracted": 0, "reused": 0,
          "objectives": 0, "candidates": 0, "folders": []}


def _root() -> str:
    """This user's folder for shipped files: ``<tmp>/frictionlab-shipped`` (``-<uid>`` on
    POSIX), private (0700) and owned by this user; anything else is refused (a folder
    another user controls could swap the FMUs this process loads)."""
    uid = getattr(os, "getuid", lambda: None)()
    root = os.path.join(tempfile.gettempdir(),
                        "frictionlab-shipped" + ("" if uid is None else f"-{uid}"))
    os.makedirs(root, mode=0o700, exist_ok=True)
    if uid is not None:
        st = os.stat(root)
        if st.st_uid != uid or st.st_mode & 0o022:
            raise PermissionError(f"{root} is not a private folder of this user: remove it "
                                  f"or set TMPDIR elsewhere")
    return root


class FileBundle:
    """Files carried by value (their bytes), written once per machine where they are used.

    Parameters
    ----------
    paths : dict
        ``key -> local file path``; each file keeps its base name in the folder it is
        written to, so a folder of FMUs (``<law>_native.fmu``) stays a valid folder.

    Attributes
    ----------
    digest : str
        SHA-256 over the names and contents: the folder's name on the workers.
    nbytes : int
        Total size of the files [bytes].
    """

    def __init__(self, paths: dict):
        self.files = {}
        self._sha = {}
        h = hashlib.sha256()
        for key in sorted(paths):
            path = os.fspath(paths[key])
            with open(path, "rb") as fh:
                data = fh.read()
            name = os.path.basename(path)
            if any(n == name and k != key for k, (n, _) in self.files.items()):
                raise ValueError(f"two shipped files are named {name!r}: rename one")
            self.files[key] = (name, data)
            self._sha[name] = hashlib.sha256(data).digest()
            h.update(key.encode() + b"\0" + name.encode() + b"\0")
            h.update(self._sha[name])
        self.digest = h.hexdigest()
        self.nbytes = sum(len(d) for _, d in self.files.values())

    def folder(self) -> str:
        """The folder holding the files on this machine, written on first use (atomic:
        written into a private folder, then renamed; a concurrent writer's copy wins)."""
        with _LOCK:
            hit = _EXTRACTED.get(self.digest)
            if hit is not None and self._complete(hit):
                _STATS["reused"] += 1
                return hit
            root = _root()
            final = os.path.join(root, self.digest)
            if not self._complete(final, verify=True):
                if os.path.isdir(final):  # a broken or altered copy: replaced
                    import shutil
                    shutil.rmtree(final, ignore_errors=True)
                tmp = tempfile.mkdtemp(prefix=f".{self.digest[:12]}-", dir=root)
                for name, data in self.files.values():
                    with open(os.path.join(tmp, name), "wb") as fh:
                        fh.write(data)
                try:
                    os.rename(tmp, final)
                    _STATS["extracted"] += 1
                except OSError:  # another process wrote it first
                    import shutil
                    shutil.rmtree(tmp, ignore_errors=True)
                    if not self._complete(final, verify=True):
                        raise
                    _STATS["reused"] += 1
            else:
                _STATS["reused"] += 1
            _EXTRACTED[self.digest] = final
            _STATS["folders"].append(final)
            return final

    def _complete(self, folder, verify: bool = False) -> bool:
        """Whether ``folder`` holds every file at its size (and, with ``verify``, its
        SHA-256: a copy found on disk is checked once before this process loads it)."""
        if not os.path.isdir(folder):
            return False
        for n, d in self.files.values():
            path = os.path.join(folder, n)
            if not os.path.isfile(path) or os.path.getsize(path) != len(d):
                return False
            if verify:
                with open(path, "rb") as fh:
                    if hashlib.sha256(fh.read()).digest() != self._sha[n]:
                        return False
        return True

    def paths(self) -> dict:
        """``key -> path`` of the files on this machine (written on first use)."""
        d = self.folder()
        return {k: os.path.join(d, n) for k, (n, _) in self.files.items()}


def _law_fmus(obj) -> list:
    """Law FMU names an object opens from its ``fmu_dir``: a co-simulation objective its
    law's (and the closed loop's ``mass``), the user's plant as the trajectory diagnosis'
    plant (:class:`diagnosis.plant_fmu.FMUPlantModel`) its base law's, ``lugre`` and the
    ``friction_effects`` block."""
    if getattr(obj, "model", None) is not None:
        names = [obj.model.name]
        if type(obj).__name__ == "ClosedLoopCoSimObjective":
            names.append("mass")
        return names
    return sorted({obj.friction.name, "lugre", "friction_effects"})


def _files_of(obj) -> dict:
    """``key -> path`` of the FMU files ``obj`` opens: its plant FMU, the further plant-side
    FMUs of its connection, the law FMU(s) of its ``fmu_dir``; ``{}`` for an objective
    without FMUs (the in-process one)."""
    files = {}
    if getattr(obj, "plant_fmu", None):
        files["plant"] = obj.plant_fmu
    conn = getattr(obj, "conn", None)
    for inst, path in (getattr(conn, "fmus", None) or {}).items():
        files[f"conn:{inst}"] = path
    if getattr(obj, "fmu_dir", None) and (getattr(obj, "model", None) is not None
                                          or getattr(obj, "friction", None) is not None):
        from fmus.master import fmu_file
        for law in _law_fmus(obj):
            path = fmu_file(obj.fmu_dir, law, getattr(obj, "native", False))
            if os.path.isfile(path):
                files[f"law:{law}"] = path
    return files


def _repoint(obj, paths: dict) -> None:
    """Point ``obj``'s FMU paths at ``paths`` (the bundle's files on this machine)."""
    if "plant" in paths:
        obj.plant_fmu = paths["plant"]
    conn = getattr(obj, "conn", None)
    if conn is not None and getattr(conn, "fmus", None):
        fmus = {inst: paths.get(f"conn:{inst}", p) for inst, p in conn.fmus.items()}
        obj.conn = dataclasses.replace(conn, fmus=fmus)
    laws = [k for k in paths if k.startswith("law:")]
    if laws:
        obj.fmu_dir = os.path.dirname(paths[laws[0]])


class ShippedObjective:
    """An objective with its FMU files by value, for workers without the client's files.

    Parameters
    ----------
    objective : identification.objectives.Objective
        Pickled with its data (an FMU objective drops its open instances when pickled).

    Notes
    -----
    Where it is unpickled (a worker), the bundle's files are written once per machine and
    the objective's paths repointed; :meth:`costs` then evaluates on a per-thread copy.
    Where it was made (the client), it is the objective itself with its own paths.
    """

    def __init__(self, objective):
        self.objective = objective
        files = _files_of(objective)
        self.bundle = FileBundle(files) if files else None
        self._copies = {}

    # what the scatter sends: the objective (its own __getstate__) and the bundle
    def __getstate__(self):
        return {"objective": pickle.dumps(self.objective, protocol=pickle.HIGHEST_PROTOCOL),
                "bundle": self.bundle}

    def __setstate__(self, state):
        self.bundle = state["bundle"]
        self.objective = pickle.loads(state["objective"])
        self._blob = state["objective"]
        if self.bundle is not None:
            _repoint(self.objective, self.bundle.paths())
        self._copies = {}
        _STATS["objectives"] += 1

    @property
    def parallel_inside(self) -> bool:
        return bool(getattr(self.objective, "parallel_inside", False))

    def _mine(self):
        """This thread's objective (the first thread uses the received one)."""
        tid = threading.get_ident()
        obj = self._copies.get(tid)
        if obj is None:
            with _LOCK:
                if not self._copies:
                    obj = self.objective
                else:
                    blob = getattr(self, "_blob", None) or pickle.dumps(self.objective)
                    obj = pickle.loads(blob)
                    if self.bundle is not None:
                        _repoint(obj, self.bundle.paths())
                self._copies[tid] = obj
        return obj

    def costs(self, X):
        """Costs of the parameter rows ``X[n, D]`` (physical values) on this worker.

        Parameters
        ----------
        X : ndarray
            Parameter rows in the objective's units.

        Returns
        -------
        ndarray
            One cost per row (NRMSE; ``inf`` for a failed co-simulation).
        """
        c = self._mine().costs(X)
        _STATS["chunks"] += 1
        _STATS["rows"] += int(len(X))
        return c


    def predict(self, X):
        """Simulated outputs of the parameter rows ``X[n, D]`` on this worker (the
        objective's ``predict``).

        Parameters
        ----------
        X : ndarray
            Parameter rows in the objective's units.

        Returns
        -------
        ndarray
            ``[n, len(data)]``; NaN rows for failed co-simulations.
        """
        F = self._mine().predict(X)
        _STATS["chunks"] += 1
        _STATS["predicted"] += int(len(X))
        return F


class ShippedCall:
    """A function (a closure, with everything it captures) shipped by value, with the FMU
    files of the objects it opens them through, for workers without the client's files.

    Parameters
    ----------
    fn : callable
        Pickled with ``cloudpickle`` together with ``holders`` (shared references stay
        shared: a holder captured by ``fn`` is the one repointed on the worker).
    holders : sequence
        Objects with FMU paths (``plant_fmu``, ``conn.fmus``, ``fmu_dir``; see
        :func:`ship`) that ``fn`` reaches; their files travel as one :class:`FileBundle`.

    Notes
    -----
    On a worker each thread calls its own copy (unpickled from the same bytes), so FMU
    instances opened by ``fn`` are never shared between threads.
    """

    def __init__(self, fn, holders=()):
        import cloudpickle
        holders = list({id(h): h for h in holders if h is not None}.values())
        files = {}
        for i, h in enumerate(holders):
            files.update({f"{i}:{k}": p for k, p in _files_of(h).items()})
        self.bundle = FileBundle(files) if files else None
        self.n_holders = len(holders)
        self.payload = cloudpickle.dumps((fn, holders))
        self._copies = {}

    def __getstate__(self):
        return {"payload": self.payload, "bundle": self.bundle, "n_holders": self.n_holders}

    def __setstate__(self, state):
        self.__dict__.update(state)
        self._copies = {}
        self._remote = True

    def _mine(self):
        tid = threading.get_ident()
        fn = self._copies.get(tid)
        if fn is None:
            import cloudpickle
            fn, holders = cloudpickle.loads(self.payload)
            if self.bundle is not None and getattr(self, "_remote", False):
                paths = self.bundle.paths()
                for i, h in enumerate(holders):
                    mine = {k.split(":", 1)[1]: p for k, p in paths.items()
                            if k.split(":", 1)[0] == str(i)}
                    _repoint(h, mine)
            self._copies[tid] = fn
        return fn

    def __call__(self, *args, **kwargs):
        """``fn(*args, **kwargs)`` on this thread's copy."""
        _STATS["candidates"] += 1
        return self._mine()(*args, **kwargs)


def run_shipped(client, call: ShippedCall, args: list) -> list:
    """``call(a)`` for every ``a`` of ``args`` on the workers of ``client``: ``call`` (its
    bytes and files) sent to each worker once, the tasks placed round the workers' threads;
    results in the order of ``args``.

    Parameters
    ----------
    client : dask.distributed.Client
    call : ShippedCall
    args : list
        One argument per task.

    Returns
    -------
    list

    Raises
    ------
    SchedulerError
        When the scheduler or every worker is lost (a lost worker's tasks run again on
        the workers left).
    """
    from concurrent.futures import CancelledError
    from distributed.scheduler import KilledWorker
    address = getattr(client, "scheduler_address", None) or "the scheduler"
    lost = (OSError, CancelledError, TimeoutError, KilledWorker)
    placed = {}
    try:
        for attempt in range(3):
            try:
                nthreads = client.nthreads()
                for w in sorted(nthreads):
                    if w not in placed:
                        placed[w] = client.scatter(call, workers=[w], hash=False)
                slots = [w for w in sorted(nthreads) for _ in range(max(1, nthreads[w]))]
                if not slots:
                    raise OSError("no worker is connected")
                futures = [client.submit(_apply, placed[slots[i % len(slots)]], a,
                                         pure=False, workers=[slots[i % len(slots)]],
                                         allow_other_workers=True)
                           for i, a in enumerate(args)]
                return client.gather(futures)
            except lost as exc:
                # a worker lost: its copy is gone; the tasks run again on those left
                # (each is deterministic), twice at most
                try:
                    left = client.status == "running" and bool(client.nthreads())
                except Exception:  # noqa: BLE001 - the scheduler itself is gone
                    left = False
                if left and attempt < 2:
                    for f in placed.values():
                        f.release()
                    placed = {}
                    continue
                text = str(exc).strip().splitlines()
                raise SchedulerError(f"lost the dask cluster at {address} during the run: "
                                     f"{text[0] if text else type(exc).__name__}") from None
    finally:
        for f in placed.values():
            try:
                f.release()
            except Exception:  # noqa: BLE001
                pass


def _apply(call, arg):
    return call(arg)


def ship(objective) -> ShippedObjective:
    """:class:`ShippedObjective` of ``objective`` (FMU files by value, data inside).

    Parameters
    ----------
    objective : identification.objectives.Objective or ShippedObjective
        The FMU files it opens are found through its ``plant_fmu``, its connection's
        ``fmus`` and the law FMUs of its ``fmu_dir``; an objective without FMUs (the
        in-process one) travels with its data only. A shipped one is returned as it is.

    Returns
    -------
    ShippedObjective
    """
    return objective if isinstance(objective, ShippedObjective) else \
        ShippedObjective(objective)


def worker_stats() -> dict:
    """What this process did as a worker: ``chunks`` run, ``rows`` costed and rows
    ``predicted`` (finite-difference Jacobians), bundles ``extracted`` (written) or
    ``reused`` (found on disk or in memory), ``objectives`` received, diagnosis
    ``candidates`` fitted (:mod:`diagnosis.cluster`), ``folders`` used. Run it on every
    worker with ``client.run(worker_stats)``.

    Returns
    -------
    dict
        Counts since the process started (a copy).
    """
    return {k: (list(v) if isinstance(v, list) else v) for k, v in _STATS.items()}
