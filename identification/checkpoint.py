"""Checkpoints of an identification: a replayable evaluation log in JSON lines.

Why a log and not a snapshot of the algorithm's state: the state of scipy's and cma's
optimisers lives in objects that only ``pickle`` could store, and loading a pickle runs any
code inside it (a checkpoint someone sent you could do anything). The log holds numbers and
strings only, and ``json`` cannot execute anything on load.

How a resume reproduces the uninterrupted run: the algorithm starts again from the same
seed, so it asks for the same parameter sets in the same order. While the requested set
``x`` equals the next logged one, the logged cost is returned instead of simulating; at the
end of the log (or at the first difference, e.g. changed options) the run continues live and
appends to the same file.

File layout (one JSON object per line)::

    {"format": "frictionlab-checkpoint", "version": 2, "fingerprint": ..., ...}   # header
    {"k": "costs", "X": [[...], ...], "c": [...], "s": 1.25}     # one population evaluation
    {"k": "unit", "kind": "least_squares", "key": {...}, "out": {...},
     "after": {...}, "s": 2.5}                                    # one deterministic block

``X`` are physical parameter rows [SI units of each parameter], ``c`` their costs (NRMSE),
``s`` the seconds since the start of the original run when the record was written. A
``unit`` is a deterministic block whose inside is too big to log (one scipy least-squares
run of the default algorithm: its Jacobians are D x N; one alternation of
``alternating_ls``); its inputs (``key``), outputs (``out``) and the problem's bookkeeping
after it (``after``: evaluations, best point, trace) are logged instead, so a resume skips
finished blocks and reruns an interrupted one from its start.

A last line cut short by an interrupted write is ignored (and cut off before appending); any
other malformed content refuses the file with a one-line message.
"""
from __future__ import annotations

import hashlib
import json
import math
import os

import numpy as np

__all__ = ["CHECKPOINT_FORMAT", "CHECKPOINT_VERSION", "EvaluationLog", "fingerprint",
           "plain"]

CHECKPOINT_FORMAT = "frictionlab-checkpoint"
#: 1 was a pickle of the algorithm's state (never loaded any more: it could run code)
CHECKPOINT_VERSION = 2


def plain(obj):
    """Numbers, arrays and containers -> JSON-able Python objects (floats kept exact:
    ``json`` writes ``repr(float)``, which reads back to the same bits)."""
    if isinstance(obj, dict):
        return {str(k): plain(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [plain(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return plain(obj.tolist())
    if isinstance(obj, (bool, np.bool_)):
        return bool(obj)
    if isinstance(obj, (np.integer,)):
        return int(obj)
    if isinstance(obj, (np.floating, float)):
        return float(obj)
    return obj


def _canon(obj) -> str:
    return json.dumps(plain(obj), sort_keys=True)


def fingerprint(data, model, names, algorithm: str, seed, extra=()) -> str:
    """SHA-1 of what makes the logged costs valid: every data column, every value of the law
    (fixed ones too), the identified names, algorithm, seed and ``extra`` (objective kind,
    bristle update). Options and budget are not in it: a change there makes the replay
    diverge at the first differing request and the run continue live."""
    h = hashlib.sha1()
    for key in ("t", "x", "v", "a", "F", "load"):
        arr = getattr(data, key, None)
        h.update(key.encode())
        if arr is not None:
            h.update(np.ascontiguousarray(arr, dtype=float).tobytes())
    params = model.params.as_dict() if hasattr(model.params, "as_dict") else vars(model.params)
    h.update(_canon({"model": model.name, "params": {k: repr(v) for k, v in params.items()},
                     "names": list(names), "algorithm": algorithm, "seed": repr(seed),
                     "extra": [repr(e) for e in extra]}).encode())
    return h.hexdigest()


def _refuse(path, why: str):
    raise ValueError(f"checkpoint {path} {why}; it was not loaded (delete it or choose "
                     f"another file)")


class EvaluationLog:
    """Append-only evaluation log bound to one file; replays what the file already holds.

    Parameters
    ----------
    path : path
        The checkpoint file. Created (header first, atomically) if absent or empty.
    header : dict
        ``fingerprint`` plus descriptive fields (algorithm, names, seed) for the header.
    sync_every : int
        ``os.fsync`` every this many records (each record is flushed to the OS at once, so
        an interrupted process loses nothing; the fsync guards against a power cut).

    Attributes
    ----------
    n_logged : int
        Records found in the file when it was opened.
    n_replayed : int
        Records replayed so far.
    diverged : int or None
        Index of the first record the run asked differently for (then the rest of the log
        was dropped and the run continued live), else None.
    """

    def __init__(self, path, header: dict, sync_every: int = 5):
        self.path = os.fspath(path)
        self.sync_every = max(int(sync_every), 1)
        self.header = {"format": CHECKPOINT_FORMAT, "version": CHECKPOINT_VERSION,
                       **plain(header)}
        self.records: list[dict] = []
        self._ends: list[int] = []  # byte offset after each record line
        self.pos = 0
        self.diverged = None
        self.n_replayed = 0
        self._fh = None
        self._unsynced = 0
        self._head_end = 0
        end = self._read()
        self.n_logged = len(self.records)
        if end is None:  # absent or empty: a fresh log
            tmp = f"{self.path}.tmp"
            with open(tmp, "w", encoding="utf-8") as fh:
                fh.write(json.dumps(self.header) + "\n")
            os.replace(tmp, self.path)  # a crash never leaves a headless file behind
            end = self._head_end = os.path.getsize(self.path)
        self._fh = open(self.path, "r+b")
        self._fh.truncate(end)  # drop a line cut by an interrupted write
        self._fh.seek(end)

    # -- reading ----------------------------------------------------------------------
    def _read(self):
        """Parse the file; return the byte offset after the last complete record, or None
        if there is no file (or an empty one)."""
        if not os.path.exists(self.path):
            return None
        with open(self.path, "rb") as fh:
            raw = fh.read()
        if not raw:
            return None
        lines = raw.split(b"\n")
        complete = lines[:-1]  # the piece after the last newline is cut (or empty)
        head = lines[0]
        try:
            first = json.loads(head.decode("utf-8"))
        except (UnicodeDecodeError, ValueError):
            first = None
        if not isinstance(first, dict) or first.get("format") != CHECKPOINT_FORMAT:
            hint = (" (an old pickle checkpoint? those are never loaded: they could run code)"
                    if raw[:1] == b"\x80" else "")
            _refuse(self.path, f"is not a frictionlab checkpoint (JSON lines with a "
                               f"'{CHECKPOINT_FORMAT}' header){hint}")
        if not complete:  # header without its newline: our header is written atomically
            _refuse(self.path, "has a truncated header")
        if first.get("version") != CHECKPOINT_VERSION:
            _refuse(self.path, f"has version {first.get('version')!r}, this frictionlab "
                               f"reads version {CHECKPOINT_VERSION}")
        if first.get("fingerprint") != self.header.get("fingerprint"):
            _refuse(self.path, "belongs to another run (different data, model values, "
                               "parameters, algorithm or seed)")
        offset = len(head) + 1
        self._head_end = offset
        for i, line in enumerate(complete[1:], start=2):
            try:
                rec = json.loads(line.decode("utf-8"))
                if not isinstance(rec, dict) or rec.get("k") not in ("costs", "unit"):
                    raise ValueError("not a record")
            except (UnicodeDecodeError, ValueError):
                _refuse(self.path, f"is corrupt at line {i}")
            offset += len(line) + 1
            self.records.append(rec)
            self._ends.append(offset)
        return offset

    # -- replay -----------------------------------------------------------------------
    @property
    def replaying(self) -> bool:
        return self.pos < len(self.records)

    def _next(self, kind: str):
        if not self.replaying:
            return None
        rec = self.records[self.pos]
        return rec if rec.get("k") == kind else None

    def _diverge(self) -> None:
        """The run asked for something else: drop the rest of the log, continue live."""
        self.diverged = self.pos
        end = self._ends[self.pos - 1] if self.pos > 0 else self._head_end
        del self.records[self.pos:]
        del self._ends[self.pos:]
        self._fh.truncate(end)
        self._fh.seek(end)

    def replay_costs(self, X):
        """Logged costs of the rows ``X`` if they are the next record, else None (and the
        log switches to live mode if it had records left)."""
        if not self.replaying:
            return None
        rec = self._next("costs")
        if rec is not None:
            Xl = np.asarray(rec["X"], float)
            if Xl.shape == np.shape(X) and np.array_equal(Xl, X, equal_nan=True):
                self.pos += 1
                self.n_replayed += 1
                return rec
        self._diverge()
        return None

    def replay_unit(self, kind: str, key: dict):
        """The logged record of this unit if it is next with the same key, else None."""
        if not self.replaying:
            return None
        rec = self._next("unit")
        if rec is not None and rec.get("kind") == kind and _canon(rec.get("key")) == _canon(key):
            self.pos += 1
            self.n_replayed += 1
            return rec
        self._diverge()
        return None

    # -- writing ----------------------------------------------------------------------
    def append(self, record: dict) -> None:
        line = (json.dumps(plain(record)) + "\n").encode("utf-8")
        self._fh.write(line)
        self._fh.flush()  # in the OS now: a killed process loses nothing written
        self._unsynced += 1
        if self._unsynced >= self.sync_every:
            os.fsync(self._fh.fileno())
            self._unsynced = 0
        # live records are not kept: only a replay needs them

    def close(self) -> None:
        if self._fh is not None:
            try:
                self._fh.flush()
                os.fsync(self._fh.fileno())
            finally:
                self._fh.close()
                self._fh = None


def finite_or_none(c: float):
    """JSON has no inf: a failed simulation's cost is logged as null."""
    return float(c) if math.isfinite(c) else None
