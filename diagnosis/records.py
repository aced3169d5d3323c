"""Measured trajectory records of a plant (positions only) for the trajectory-level
diagnosis: :class:`TrajectoryRecord`, from a simulation result, a CSV or a ``.mat`` file."""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from friction._validation import as_float_array, check_finite, check_same_length, check_time

__all__ = ["TrajectoryRecord", "record_from_result", "load_record", "parse_experiment"]


# -- measured records ---------------------------------------------------------------------
@dataclass
class TrajectoryRecord:
    """One measured run of a plant: time, measured position and the experiment behind it.

    Attributes
    ----------
    t : ndarray
        Sample times [s], strictly increasing, from the start of the experiment (the plant
        simulation starts at ``t = 0`` at rest).
    y : ndarray
        Measured output [m] (the plant's ``signal``, by default its main output, e.g. the
        XML-350 stage position or the valve lift).
    options : dict
        Experiment options of :meth:`plants.base.Plant.simulate` that reproduce the run
        (trajectory, distance, controller, ...).
    name : str
    signal : str, optional
        Plant output compared with ``y`` (default: the plant's ``main_output``).
    t_start : float
        Absolute time of the record's start [s] (only the ``drift`` candidate uses it: a
        friction level that changes over the session).
    """
    t: np.ndarray
    y: np.ndarray
    options: dict = field(default_factory=dict)
    name: str = "trajectory"
    signal: str | None = None
    t_start: float = 0.0

    def __post_init__(self):
        try:  # the project's own checks, with the record named
            self.t = as_float_array("t", np.ravel(self.t))
            self.y = as_float_array("y", np.ravel(self.y))
            check_same_length("t", self.t.size, y=self.y)
            if self.t.size < 10:
                raise ValueError(f"need at least 10 samples, got {self.t.size}")
            check_finite("y", self.y)
            check_time(self.t)
        except ValueError as exc:
            raise ValueError(f"record {self.name!r}: {exc}") from None
        if self.t[0] < 0:
            raise ValueError(f"record {self.name!r}: t starts at {float(self.t[0])!r} < 0; times "
                             f"count from the experiment's start [s]")
        if np.max(np.abs(self.y)) > 10.0:
            raise ValueError(f"record {self.name!r}: |y| reaches {np.max(np.abs(self.y)):.4g}"
                             f" - positions are in m (a value in mm or um needs scaling)")
        self.options = dict(self.options)

    @property
    def dt(self) -> float:
        return float(np.median(np.diff(self.t)))


def record_from_result(result, options: dict | None = None, *, signal: str = "x",
                       noise: float = 0.0, seed: int = 0, name: str = "trajectory",
                       t_start: float = 0.0) -> TrajectoryRecord:
    """A :class:`TrajectoryRecord` from a plant result array (synthetic measurements).

    Parameters
    ----------
    result : structured ndarray
        Output of :meth:`plants.base.Plant.simulate` (``time`` first).
    options : dict, optional
        The experiment options that produced it.
    signal : str
        Output taken as the measurement (``"x"``, or ``"x_meas"`` for the quantised encoder).
    noise : float
        Standard deviation of white measurement noise added [m].
    seed : int
        Seed of the noise.
    name : str
        Name of the record.
    t_start : float
        Absolute time of the record's start [s] (the ``drift`` candidate uses it).
    """
    y = np.array(result[signal], dtype=float)
    if noise > 0:
        y = y + np.random.default_rng(seed).normal(0.0, noise, y.size)
    return TrajectoryRecord(result["time"], y, dict(options or {}), name=name, signal=None,
                            t_start=t_start)


def parse_experiment(text: str | None) -> dict:
    """Experiment options from ``"KEY=VALUE,..."`` (CLI helper).

    Values become bool (``true``/``false``), float, or str. ``trajectory=sine:A:f`` is the
    position sine ``A (1 - cos 2 pi f t)`` [m, Hz] that starts at rest
    (:class:`plants.sources.Sine`); ``trajectory=triangle:A:f`` a triangle wave.
    """
    out = {}
    if not text:
        return out
    for item in text.split(","):
        if "=" not in item:
            raise ValueError(f"bad experiment item {item!r}: expected KEY=VALUE")
        k, v = (x.strip() for x in item.split("=", 1))
        if k == "trajectory":
            from plants.sources import Sine, Triangle
            kind, *nums = v.split(":")
            try:
                A, f = (float(x) for x in nums)
            except ValueError:
                raise ValueError(f"trajectory={v!r}: expected sine:AMPLITUDE:FREQUENCY or "
                                 f"triangle:AMPLITUDE:FREQUENCY [m, Hz]") from None
            if kind == "sine":
                out[k] = Sine(A, f, offset=A, phase=-0.5 * math.pi)
            elif kind == "triangle":
                out[k] = Triangle(A, f)
            else:
                raise ValueError(f"trajectory kind {kind!r}: choose sine or triangle")
        elif v.lower() in ("true", "false"):
            out[k] = v.lower() == "true"
        else:
            try:
                out[k] = float(v)
            except ValueError:
                out[k] = v
    return out


def load_record(path, options: dict | None = None, *, mapping: dict | None = None,
                scale: dict | None = None, signal: str = "x") -> TrajectoryRecord:
    """A measured trajectory from CSV (header row) or ``.mat``: columns ``t`` [s] and the
    measured output ``x`` [m] (other names through ``mapping``, e.g. ``{"x": "pos"}``;
    unit factors through ``scale``, e.g. ``{"x": 1e-6}`` for micrometres)."""
    import csv
    import os
    path = os.fspath(path)
    if not os.path.exists(path):
        raise FileNotFoundError(f"no such data file: {path}")
    mapping = dict(mapping or {})
    unknown = set(mapping) - {"t", signal}
    if unknown:
        raise ValueError(f"mapping keys {sorted(unknown)}: a trajectory record has only "
                         f"'t' and {signal!r}")
    if path.lower().endswith(".mat"):
        from scipy.io import loadmat
        raw = loadmat(path)
        cols = {k: np.asarray(v, dtype=float).ravel() for k, v in raw.items()
                if not k.startswith("__") and np.asarray(v).dtype.kind in "fiu"}
    else:
        with open(path, newline="") as fh:
            rows = [r for r in csv.reader(fh) if r and any(c.strip() for c in r)]
        if len(rows) < 2:
            raise ValueError(f"{path}: need a header row and data rows")
        header = [h.strip() for h in rows[0]]
        cols = {}
        for j, h in enumerate(header):
            vals = []
            for lineno, r in enumerate(rows[1:], start=2):
                try:
                    vals.append(float(r[j]))
                except (ValueError, IndexError):
                    raise ValueError(f"{path}: line {lineno}, column {h!r}: not a number "
                                     f"({r[j] if j < len(r) else 'missing'!r})") from None
            cols[h] = np.array(vals)
    picked = {}
    for key in ("t", signal):
        src = mapping.get(key, key)
        if src not in cols:
            raise ValueError(f"{path}: column {src!r} (for {key!r}) not found; available: "
                             f"{sorted(cols)}")
        picked[key] = cols[src] * float((scale or {}).get(key, 1.0))
    return TrajectoryRecord(picked["t"], picked[signal], dict(options or {}),
                            name=os.path.basename(path))
