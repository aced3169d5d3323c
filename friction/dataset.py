"""Measurement datasets: the CSV contract (``t, x, v, a, F[, load]``), ``.mat`` files with an
explicit column mapping, and the checks that keep bad files from producing silent nonsense.

A :class:`Dataset` holds SI arrays. ``to_structured()`` returns the fmpy-style structured
array with ``time`` first, the layout used by simulations and FMU runs alike.
"""
from __future__ import annotations

import csv
import os
from dataclasses import dataclass, field

import numpy as np

from ._validation import as_float_array, check_finite, check_same_length, check_time

__all__ = ["Dataset", "load_dataset", "load_csv", "load_mat", "parse_mapping"]

COLUMNS = ("t", "x", "v", "a", "F", "load")


@dataclass
class Dataset:
    """One experiment in SI units.

    Attributes
    ----------
    t : ndarray
        Time [s], strictly increasing.
    x, v, a : ndarray
        Position [m], velocity [m/s], acceleration [m/s^2]. Missing ones are derived
        (v from x by central differences, a from v), which ``derived`` records.
    F : ndarray
        Measured friction force [N].
    load : ndarray or None
        Normal/deformation load [N].
    extra : dict
        Extra columns, kept and ignored.
    """
    t: np.ndarray
    x: np.ndarray
    v: np.ndarray
    a: np.ndarray
    F: np.ndarray
    load: np.ndarray | None = None
    extra: dict = field(default_factory=dict)
    name: str = "data"
    derived: tuple = ()

    def __post_init__(self):
        # every dataset is checked however it was built (from_arrays, a file, or the
        # constructor), so a NaN or a wrong length is named here, not deep in a fit
        self.t = as_float_array("t", self.t)
        check_time(self.t)
        n = self.t.size
        for key in ("x", "v", "a", "F", "load"):
            arr = getattr(self, key)
            if arr is None and key == "load":
                continue
            arr = as_float_array(key, arr)
            check_same_length("t", n, **{key: arr})
            check_finite(key, arr)
            setattr(self, key, arr)

    @classmethod
    def from_arrays(cls, t, F, *, x=None, v=None, a=None, load=None, name="data",
                    extra=None, check_units: bool = True) -> "Dataset":
        """Build and validate a dataset; derives missing x, v, a."""
        t = as_float_array("t", t)
        check_time(t)
        n = t.size
        F = as_float_array("F", F)
        arrays = {"F": F}
        for key, val in (("x", x), ("v", v), ("a", a), ("load", load)):
            if val is not None:
                arrays[key] = as_float_array(key, val)
        check_same_length("t", n, **arrays)
        for key, arr in arrays.items():
            check_finite(key, arr)
        if "x" not in arrays and "v" not in arrays:
            raise ValueError("dataset needs a position column 'x' [m] or a velocity column "
                             "'v' [m/s] (or map yours with mapping=)")
        derived = []
        if "v" not in arrays:
            arrays["v"] = np.gradient(arrays["x"], t)
            derived.append("v")
        if "x" not in arrays:
            v_ = arrays["v"]
            arrays["x"] = np.concatenate(([0.0], np.cumsum(0.5 * (v_[1:] + v_[:-1]) * np.diff(t))))
            derived.append("x")
        if "a" not in arrays:
            arrays["a"] = np.gradient(arrays["v"], t)
            derived.append("a")
        ds = cls(t=t, x=arrays["x"], v=arrays["v"], a=arrays["a"], F=F,
                 load=arrays.get("load"), extra=dict(extra or {}), name=name,
                 derived=tuple(derived))
        if check_units:
            ds.check_units()
        return ds

    def __len__(self) -> int:
        return self.t.size

    @property
    def dt(self) -> float:
        return float(np.median(np.diff(self.t)))

    def check_units(self) -> None:
        """Catch the common factor-1000 slips (mm for m, ms for s) before they cost a fit."""
        if "v" not in self.derived and "x" not in self.derived:
            dxdt = np.gradient(self.x, self.t)
            moving = np.abs(self.v) > 0.05 * np.max(np.abs(self.v)) if np.any(self.v) else None
            if moving is not None and moving.sum() > 10:
                ratio = np.median(np.abs(dxdt[moving]) / np.abs(self.v[moving]))
                for factor, unit in ((1e3, "x looks like millimetres or v like m/s*1e-3"),
                                     (1e-3, "v looks like mm/s or x like km")):
                    if 0.3 * factor < ratio < 3 * factor:
                        raise ValueError(
                            f"units off by 1000: d(x)/dt is {ratio:.3g} times v ({unit}); "
                            f"columns must be SI (m, m/s). Rescale with scale={{'x': 1e-3}} "
                            f"or --scale x=1e-3")
        xr = float(np.ptp(self.x))
        if xr > 20.0:
            raise ValueError(f"x spans {xr:g} m: this looks like millimetres; columns must be "
                             f"SI (m). Rescale with scale={{'x': 1e-3}} or --scale x=1e-3")
        vmax = float(np.max(np.abs(self.v)))
        if vmax > 100.0:
            raise ValueError(f"|v| reaches {vmax:g} m/s: this looks like mm/s; columns must be "
                             f"SI (m/s). Rescale with scale={{'v': 1e-3}} or --scale v=1e-3")
        dt = self.dt
        if dt >= 0.5 and self.t.size > 200 and (self.t[-1] - self.t[0]) > 3600 * 24:
            raise ValueError(f"t steps by {dt:g} over {self.t[-1] - self.t[0]:g}: this looks "
                             f"like milliseconds; t must be in s (--scale t=1e-3)")

    def to_structured(self) -> np.ndarray:
        """Structured array with ``time`` first (fmpy convention)."""
        cols = [("time", self.t), ("x", self.x), ("v", self.v), ("a", self.a), ("F", self.F)]
        if self.load is not None:
            cols.append(("load", self.load))
        out = np.empty(self.t.size, dtype=[(n, "f8") for n, _ in cols])
        for n, arr in cols:
            out[n] = arr
        return out

    def select(self, index) -> "Dataset":
        """Sub-dataset of the samples in ``index`` (slice or boolean/int array)."""
        sub = lambda arr: None if arr is None else arr[index]
        return Dataset(t=self.t[index], x=self.x[index], v=self.v[index], a=self.a[index],
                       F=self.F[index], load=sub(self.load),
                       extra={k: val[index] for k, val in self.extra.items()},
                       name=self.name, derived=self.derived)

    def split(self, fraction: float = 0.7) -> tuple["Dataset", "Dataset"]:
        """Chronological split into a fit part and a held-out part."""
        if not 0 < fraction < 1:
            raise ValueError(f"fraction = {fraction!r} is out of bounds: must be in (0, 1)")
        k = int(round(fraction * len(self)))
        if k < 2 or len(self) - k < 2:
            raise ValueError(f"dataset of {len(self)} samples is too short to split")
        return self.select(slice(0, k)), self.select(slice(k, None))

    def to_csv(self, path) -> None:
        """Write the contract CSV (header row, SI units)."""
        s = self.to_structured()
        names = ["t" if n == "time" else n for n in s.dtype.names]
        with open(path, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(names)
            for row in s:
                w.writerow([repr(float(val)) for val in row])


def parse_mapping(text: str | None) -> dict[str, str]:
    """Parse ``"t=time,x=pos"`` into ``{"t": "time", "x": "pos"}`` (CLI helper)."""
    if not text:
        return {}
    out = {}
    for item in text.split(","):
        if "=" not in item:
            raise ValueError(f"bad mapping item {item!r}: expected NAME=COLUMN")
        k, v = item.split("=", 1)
        out[k.strip()] = v.strip()
    return out


def _apply(columns: dict[str, np.ndarray], mapping, scale, name, check_units) -> Dataset:
    mapping = dict(mapping or {})
    unknown = set(mapping) - set(COLUMNS)
    if unknown:
        raise ValueError(f"mapping keys {sorted(unknown)} are not dataset columns {COLUMNS}")
    picked = {}
    for col in COLUMNS:
        src = mapping.get(col, col)
        if src in columns:
            picked[col] = np.asarray(columns[src], dtype=float).ravel()
        elif col in mapping:
            raise ValueError(f"column {src!r} (mapped to {col!r}) not found; available: "
                             f"{sorted(columns)}")
    for col, factor in (scale or {}).items():
        if col not in picked:
            raise ValueError(f"scale given for {col!r}, which is not in the data")
        picked[col] = picked[col] * float(factor)
    if "t" not in picked:
        raise ValueError(f"no time column 't' (available: {sorted(columns)}); map it with "
                         f"mapping={{'t': 'yourname'}}")
    if "F" not in picked:
        raise ValueError(f"no friction-force column 'F' (available: {sorted(columns)}); map it "
                         f"with mapping={{'F': 'yourname'}}")
    used = {mapping.get(c, c) for c in picked}
    extra = {k: v for k, v in columns.items() if k not in used}
    return Dataset.from_arrays(picked.pop("t"), picked.pop("F"), name=name, extra=extra,
                               check_units=check_units, **picked)


def load_csv(path, mapping=None, scale=None, check_units: bool = True) -> Dataset:
    """Load a contract CSV (header row, comma separated, SI units)."""
    path = os.fspath(path)
    if not os.path.exists(path):
        raise FileNotFoundError(f"no such data file: {path}")
    with open(path, newline="") as fh:
        reader = csv.reader(fh)
        try:
            header = [h.strip() for h in next(reader)]
        except StopIteration:
            raise ValueError(f"{path}: empty file") from None
        rows = [r for r in reader if r and any(c.strip() for c in r)]
    if not rows:
        raise ValueError(f"{path}: header but no data rows")
    cols: dict[str, list] = {h: [] for h in header}
    for lineno, r in enumerate(rows, start=2):
        if len(r) != len(header):
            raise ValueError(f"{path}:{lineno}: {len(r)} fields, header has {len(header)}")
        for h, cell in zip(header, r):
            cols[h].append(cell)
    arrays = {}
    for h, cells in cols.items():
        try:
            arrays[h] = np.array([float(c) if c.strip() else np.nan for c in cells])
        except ValueError:
            if h in COLUMNS or h in (mapping or {}).values():
                bad = next(c for c in cells if not _isfloat(c))
                raise ValueError(f"{path}: column {h!r} has a non-numeric value {bad!r}") from None
            continue  # non-numeric extra column: kept out
    return _apply(arrays, mapping, scale, os.path.basename(path), check_units)


def _isfloat(c: str) -> bool:
    try:
        float(c)
        return True
    except ValueError:
        return False


def load_mat(path, mapping=None, scale=None, check_units: bool = True) -> Dataset:
    """Load a MATLAB ``.mat`` file; ``mapping`` names which variables are t, x, v, a, F, load."""
    from scipy.io import loadmat
    path = os.fspath(path)
    if not os.path.exists(path):
        raise FileNotFoundError(f"no such data file: {path}")
    raw = loadmat(path)
    arrays = {k: np.asarray(v, dtype=float).ravel() for k, v in raw.items()
              if not k.startswith("__") and np.asarray(v).dtype.kind in "fiu"
              and np.asarray(v).size > 1}
    return _apply(arrays, mapping, scale, os.path.basename(path), check_units)


def load_dataset(path, mapping=None, scale=None, check_units: bool = True) -> Dataset:
    """Load CSV or ``.mat`` by extension."""
    if os.fspath(path).lower().endswith(".mat"):
        return load_mat(path, mapping, scale, check_units)
    return load_csv(path, mapping, scale, check_units)
