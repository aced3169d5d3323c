"""Measurement datasets: the CSV contract (``t, x, v, a, F[, load]``), ``.mat`` files with an
explicit column mapping, and the checks that keep bad files from producing silent nonsense.

A :class:`Dataset` holds SI arrays. ``to_structured()`` returns the fmpy-style structured
array with ``time`` first, the layout used by simulations and FMU runs alike.

Files as they come from spreadsheets and loggers are read too: ``;``, tab, ``|`` or
whitespace separators, decimal commas, a UTF-8 (or UTF-16) byte-order mark; what was
detected is listed in ``Dataset.notes``. Errors about the data are :class:`DataError`, whose
message gives hints in Python syntax (``scale={'x': 0.001}``) and whose ``cli`` attribute
gives the same message with command-line hints (``--scale x=1e-3``), which the
``frictionlab`` command prints.
"""
from __future__ import annotations

import csv
import io
import math
import os
import re
from dataclasses import dataclass, field

import numpy as np

from ._validation import as_float_array, check_finite, check_same_length, check_time
from .progress import as_progress

__all__ = ["Dataset", "SteadyStateMap", "DataError", "load_dataset", "load_csv", "load_mat",
           "parse_mapping"]

COLUMNS = ("t", "x", "v", "a", "F", "load")

#: plausibility limits of the unit check (SI): a speed above V_MAX [m/s] (99.5th percentile
#: of |v|, measured or differentiated from x; friction rigs and robot joints stay well below:
#: the real records in ../shared/data/real reach 0.66 m/s), a measured position spanning more
#: than X_SPAN_MAX [m]. A column given an explicit scale (even 1) is not checked.
V_MAX = 5.0
X_SPAN_MAX = 20.0


class DataError(ValueError):
    """A problem with a data file or its columns.

    ``str(err)`` gives hints in Python syntax (for API users); ``err.cli`` the same message
    with ``frictionlab`` option syntax (``--map t=COLUMN``, ``--scale x=1e-3``).
    """

    def __init__(self, message: str, cli: str | None = None):
        super().__init__(message)
        self.cli = cli if cli is not None else message


def _num(f: float) -> str:
    """A scale factor as a user types it: 1e-3 rather than 0.001."""
    if f > 0 and abs(math.log10(f) - round(math.log10(f))) < 1e-12 and f != 1.0:
        return f"1e{round(math.log10(f))}"
    return repr(float(f))


def _scale_hint(factors: dict, syntax: str) -> str:
    if syntax == "cli":
        return "--scale " + ",".join(f"{k}={_num(f)}" for k, f in factors.items())
    return "scale={" + ", ".join(f"'{k}': {_num(f)}" for k, f in factors.items()) + "}"


def _map_hint(col: str, syntax: str) -> str:
    if syntax == "cli":
        return f"--map {col}=COLUMN"
    return f"mapping={{'{col}': 'COLUMN'}}"


def _data_error(make) -> DataError:
    """``make(syntax) -> message`` for ``syntax`` in ("python", "cli")."""
    return DataError(make("python"), cli=make("cli"))


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
    notes : tuple of str
        How the file was read when it was not the plain contract CSV (separator, decimal
        commas, byte-order mark).
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
    notes: tuple = ()

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
                    extra=None, check_units: bool = True, asserted_units=(),
                    notes=()) -> "Dataset":
        """Build and validate a dataset; derives missing x, v, a.

        Parameters
        ----------
        t : array
            Time [s], strictly increasing.
        F : array
            Measured friction force [N].
        x, v, a : array, optional
            Position [m], velocity [m/s], acceleration [m/s^2]; x or v is required, the
            others are derived (recorded in ``derived``).
        load : array, optional
            Normal/deformation load [N].
        check_units : bool
            Run :meth:`check_units` (catches mm for m, mm/s for m/s, degrees for rad).
        asserted_units : iterable of str
            Columns whose unit the caller vouches for (e.g. given an explicit scale): the
            unit check never blames them.
        notes : tuple of str
            How the source file was read (kept in ``notes``).
        name : str
            Name of the record (a file name, "data").
        extra : dict, optional
            Further named columns of the same length (kept in ``Dataset.extra``).
        """
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
            raise _data_error(lambda s: f"dataset needs a position column 'x' [m] or a "
                              f"velocity column 'v' [m/s] (map yours with "
                              f"{_map_hint('x', s)} or {_map_hint('v', s)})")
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
                 derived=tuple(derived), notes=tuple(notes))
        if check_units:
            ds.check_units(asserted_units)
        return ds

    def __len__(self) -> int:
        return self.t.size

    @property
    def dt(self) -> float:
        return float(np.median(np.diff(self.t)))

    def check_units(self, asserted=()) -> None:
        """Catch unit slips (mm for m, mm/s for m/s, degrees for rad, ms for s) before they
        cost a fit, naming the column that is off and the scale that fixes it.

        Only measured columns are blamed: a velocity differentiated from x points at x, and
        a position integrated from v is never checked (its span grows with any offset of v).

        * x and v both measured: ``d(x)/dt`` against v. A ratio near 1000 means x is in mm,
          near 0.001 that v is in mm/s (or t in ms), near 57.3 / 0.0175 degrees for rad.
        * a measured position spanning more than :data:`X_SPAN_MAX` [m], a speed above
          :data:`V_MAX` [m/s] (99.5th percentile of |v|, so one noisy difference does not
          count): blamed on v if v was measured (and on x too when both were: they agree),
          on x if v was differentiated from it.

        Parameters
        ----------
        asserted : iterable of str
            Columns whose unit the caller vouches for (an explicit ``scale`` entry, even
            ``1``): never blamed.

        Raises
        ------
        DataError
            With the column, what it looks like, and the ``scale`` (``--scale``) to use.
        """
        asserted = set(asserted)
        measured = {c for c in ("x", "v") if c not in self.derived}

        def fail(column_text, factors, extra=""):
            def make(syn):
                fix = _scale_hint(factors, syn)
                keep = ("--scale " + ",".join(f"{k}=1" for k in factors) if syn == "cli"
                        else "scale={" + ", ".join(f"'{k}': 1" for k in factors) + "}")
                return (f"{column_text}; columns must be SI (s, m, m/s). Rescale with {fix}"
                        f"{extra(syn) if extra else ''}; if the values are SI, say so with "
                        f"{keep}")
            raise _data_error(make)

        if measured == {"x", "v"} and not {"x", "v"} <= asserted:
            dxdt = np.gradient(self.x, self.t)
            vmax = float(np.max(np.abs(self.v)))
            moving = np.abs(self.v) > 0.05 * vmax if vmax > 0 else None
            if moving is not None and moving.sum() > 10:
                ratio = float(np.median(np.abs(dxdt[moving]) / np.abs(self.v[moving])))
                deg = 180.0 / np.pi
                known = [  # ratio, band, blamed column, what it looks like, factor
                    (1e3, 3.0, "x", "x looks like millimetres (v like m/s)", 1e-3),
                    (1e6, 3.0, "x", "x looks like micrometres (v like m/s)", 1e-6),
                    (deg, 1.5, "x", "x looks like degrees (v like rad/s)", 1.0 / deg),
                    (1e-3, 3.0, "v", "v looks like mm/s (x like m)", 1e-3),
                    (1e-6, 3.0, "v", "v looks like um/s (x like m)", 1e-6),
                    (1.0 / deg, 1.5, "v", "v looks like deg/s (x like rad)", 1.0 / deg)]
                for r0, band, col, what, factor in known:
                    if r0 / band < ratio < r0 * band:
                        if col in asserted:  # the other column of the pair is off
                            col, factor = ({"x": "v", "v": "x"}[col], 1.0 / factor)
                            what = f"{col} is off by {_num(factor)}"
                        also = ((lambda syn: " (or " + _scale_hint({"t": 1e-3}, syn)
                                 + " if t is in milliseconds)")
                                if col == "v" and r0 == 1e-3 and "t" not in asserted else "")
                        off = max(r0, 1.0 / r0)
                        off = "1000" if off == 1e3 else f"{off:.3g}"
                        fail(f"units off by {off}: d(x)/dt is {ratio:.3g} times v: {what}",
                             {col: factor}, also)
        span = float(np.ptp(self.x))
        v99 = float(np.percentile(np.abs(self.v), 99.5))
        # x and v both measured passed the ratio check: they share one unit, so a slip in
        # one is a slip in both
        both = [c for c in ("x", "v") if c in measured and c not in asserted]
        rad = np.pi / 180.0

        def degrees(cols):  # a rotary axis logged in degrees looks the same: say so
            return lambda syn: (" (or " + _scale_hint({c: rad for c in cols}, syn)
                                + " if in degrees)")

        if "x" in both and span > X_SPAN_MAX:
            fail(f"x spans {span:g} m: this looks like millimetres"
                 + (" (and v like mm/s)" if "v" in both else ""),
                 {c: 1e-3 for c in both}, degrees(both))
        if "v" in both and v99 > V_MAX:
            fail(f"|v| reaches {v99:g} m/s: this looks like mm/s"
                 + (" (and x like mm)" if "x" in both else ""),
                 {c: 1e-3 for c in both}, degrees(both))
        if "v" not in measured and "x" not in asserted and v99 > V_MAX:
            # v was differentiated from x: x is the measured column to blame
            fail(f"the velocity differentiated from x reaches {v99:g} m/s: x looks like "
                 f"millimetres", {"x": 1e-3}, degrees(["x"]))
        dt = self.dt
        if "t" not in asserted and dt >= 0.5 and self.t.size > 200 \
                and (self.t[-1] - self.t[0]) > 3600 * 24:
            fail(f"t steps by {dt:g} s over {self.t[-1] - self.t[0]:g} s: t looks like "
                 f"milliseconds", {"t": 1e-3})

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
        """Sub-dataset of the samples in ``index`` (slice or boolean/int array).

        Parameters
        ----------
        index : slice or array_like of bool or int
            The samples to keep.
        """
        sub = lambda arr: None if arr is None else arr[index]
        return Dataset(t=self.t[index], x=self.x[index], v=self.v[index], a=self.a[index],
                       F=self.F[index], load=sub(self.load),
                       extra={k: val[index] for k, val in self.extra.items()},
                       name=self.name, derived=self.derived, notes=self.notes)

    def split(self, fraction: float = 0.7) -> tuple["Dataset", "Dataset"]:
        """Chronological split into a fit part and a held-out part.

        Parameters
        ----------
        fraction : float
            Share of the samples, from the start, in the fit part (0 < fraction < 1).
        """
        if not 0 < fraction < 1:
            raise ValueError(f"fraction = {fraction!r} is out of bounds: must be in (0, 1)")
        k = int(round(fraction * len(self)))
        if k < 2 or len(self) - k < 2:
            raise ValueError(f"dataset of {len(self)} samples is too short to split")
        return self.select(slice(0, k)), self.select(slice(k, None))

    def to_csv(self, path) -> None:
        """Write the contract CSV (header row, SI units).

        Parameters
        ----------
        path : str or path
            The file to write.
        """
        s = self.to_structured()
        names = ["t" if n == "time" else n for n in s.dtype.names]
        with open(path, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(names)
            for row in s:
                w.writerow([repr(float(val)) for val in row])


@dataclass
class SteadyStateMap:
    """A steady-state friction map: the friction force ``F`` [N] measured at constant
    velocity ``v`` [m/s], one row per constant-velocity plateau, no time base.

    The contract's map file has columns ``v`` and ``F`` and no ``t``
    (:func:`load_dataset` returns this class for it). Identification fits the law's
    steady-state curve to it (the static parameters; the first step of the seeds' two-step
    method, :mod:`identification.steady_state`). Rows are kept sorted by velocity.

    Attributes
    ----------
    v : ndarray
        Plateau velocities [m/s] (rotary joints: rad/s), sorted.
    F : ndarray
        Friction force at each plateau [N] (rotary: N m).
    name : str
    extra : dict
        Other per-plateau columns (e.g. the spread of each plateau), in the same order.
    notes : tuple of str
        How the source was read.
    """
    v: np.ndarray
    F: np.ndarray
    name: str = "steady state"
    extra: dict = field(default_factory=dict)
    notes: tuple = ()

    def __post_init__(self):
        v = as_float_array("v", self.v)
        F = as_float_array("F", self.F)
        check_same_length("v", v.size, F=F)
        check_finite("v", v)
        check_finite("F", F)
        if v.size < 2:
            raise DataError(f"steady-state map {self.name!r} has {v.size} row(s): need at "
                            f"least 2 plateaus")
        order = np.argsort(v, kind="stable")
        self.v, self.F = v[order], F[order]
        self.extra = {k: np.asarray(a, float).ravel()[order] for k, a in self.extra.items()
                      if np.asarray(a).size == v.size}

    def __len__(self) -> int:
        return self.v.size

    def side(self, sign: int) -> "SteadyStateMap":
        """The plateaus of one direction (``sign`` > 0: v > 0; < 0: v < 0)."""
        keep = self.v > 0 if sign > 0 else self.v < 0
        return SteadyStateMap(self.v[keep], self.F[keep], name=f"{self.name} "
                              f"(v {'>' if sign > 0 else '<'} 0)",
                              extra={k: a[keep] for k, a in self.extra.items()},
                              notes=self.notes)

    def sliding(self, min_speed: float) -> "SteadyStateMap":
        """The plateaus at ``|v| >= min_speed`` [m/s]: drops rows of presliding creep (a
        force below the sliding level at a vanishing speed), which no steady-state
        (Stribeck) curve describes."""
        if not (math.isfinite(min_speed) and min_speed >= 0):
            raise ValueError(f"min_speed = {min_speed!r}: must be >= 0 [m/s]")
        keep = np.abs(self.v) >= min_speed
        return SteadyStateMap(self.v[keep], self.F[keep], name=self.name,
                              extra={k: a[keep] for k, a in self.extra.items()},
                              notes=self.notes + (f"plateaus with |v| < {min_speed:g} m/s "
                                                  f"dropped ({int((~keep).sum())})",))

    def as_dataset(self) -> Dataset:
        """The map as a quasi-static Dataset (``t`` = row index [s], a = 0): for code that
        needs a time series; identification takes the map itself."""
        t = np.arange(self.v.size, dtype=float)
        return Dataset.from_arrays(t, self.F, v=self.v, a=np.zeros_like(self.v),
                                   name=self.name, check_units=False)

    def to_csv(self, path) -> None:
        """Write the contract's map file (header ``v,F``, SI units)."""
        with open(path, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["v", "F"])
            for a, b in zip(self.v, self.F):
                w.writerow([repr(float(a)), repr(float(b))])


def parse_mapping(text: str | None) -> dict[str, str]:
    """Parse ``"t=time,x=pos"`` into ``{"t": "time", "x": "pos"}`` (CLI helper); a comma
    inside brackets belongs to a column pick (``v=log[:,1],F=log[:,0]``)."""
    if not text:
        return {}
    out = {}
    for item in re.split(r",(?![^\[]*\])", text):
        if "=" not in item:
            raise ValueError(f"bad mapping item {item!r}: expected NAME=COLUMN")
        k, v = item.split("=", 1)
        out[k.strip()] = v.strip()
    return out


def _apply(columns: dict[str, np.ndarray], mapping, scale, name, check_units,
           notes=()) -> Dataset:
    mapping = dict(mapping or {})
    unknown = set(mapping) - set(COLUMNS)
    if unknown:
        raise _data_error(lambda s: f"{'--map' if s == 'cli' else 'mapping'} keys "
                          f"{sorted(unknown)} are not dataset columns {COLUMNS}")
    picked = {}
    for col in COLUMNS:
        src = mapping.get(col, col)
        if src in columns:
            picked[col] = np.asarray(columns[src], dtype=float).ravel()
        elif col in mapping:
            raise DataError(f"column {src!r} (mapped to {col!r}) not found; available: "
                            f"{sorted(columns)}")
    for col, factor in (scale or {}).items():
        if col not in picked:
            raise _data_error(lambda s: f"{'--scale' if s == 'cli' else 'scale'} given for "
                              f"{col!r}, which is not in the data (columns: "
                              f"{sorted(picked)})")
        picked[col] = picked[col] * float(factor)
    if "t" not in picked and "v" in picked and "F" in picked and "x" not in picked:
        # the contract's steady-state map: one row per constant-velocity plateau
        return SteadyStateMap(picked["v"], picked["F"], name=name, notes=tuple(notes),
                              extra={k: np.asarray(a, float).ravel() for k, a in
                                     columns.items() if k not in (mapping.get("v", "v"),
                                                                  mapping.get("F", "F"))
                                     and np.asarray(a).size == picked["v"].size})
    if "t" not in picked:
        raise _data_error(lambda s: f"no time column 't' (available: {sorted(columns)}); "
                          f"map it with {_map_hint('t', s)} (a steady-state map needs "
                          f"columns v and F only)")
    if "F" not in picked:
        raise _data_error(lambda s: f"no friction-force column 'F' (available: "
                          f"{sorted(columns)}); map it with {_map_hint('F', s)}")
    used = {mapping.get(c, c) for c in picked}
    extra = {k: v for k, v in columns.items() if k not in used}
    return Dataset.from_arrays(picked.pop("t"), picked.pop("F"), name=name, extra=extra,
                               check_units=check_units, asserted_units=tuple(scale or ()),
                               notes=notes, **picked)


_DECIMAL_COMMA = re.compile(r"^\s*[+-]?(\d+,\d*|,\d+)([eE][+-]?\d+)?\s*$")


def _decode(raw: bytes) -> tuple[str, list[str]]:
    """Bytes -> text, honouring a byte-order mark (Excel writes one)."""
    if raw.startswith(b"\xef\xbb\xbf"):
        return raw[3:].decode("utf-8", errors="replace"), ["UTF-8 byte-order mark"]
    if raw.startswith((b"\xff\xfe", b"\xfe\xff")):
        return raw.decode("utf-16"), ["UTF-16 text"]
    try:
        return raw.decode("utf-8"), []
    except UnicodeDecodeError:  # a spreadsheet's legacy code page (a header with a degree sign)
        return raw.decode("latin-1"), ["latin-1 text"]


def _sniff(lines: list[str]) -> str | None:
    """The separator of a header line and the data lines after it: the candidate that splits
    the header in more than one field and every sampled data line the same way; ``None``
    for runs of whitespace."""
    head, sample = lines[0], lines[1:21]
    best = None
    for sep in (",", ";", "\t", "|"):
        n = len(next(csv.reader([head], delimiter=sep)))
        if n < 2:
            continue
        counts = [len(next(csv.reader([ln], delimiter=sep))) for ln in sample]
        if all(c == n for c in counts):
            return sep
        if best is None:
            best = sep
    if best is None and len(head.split()) > 1:
        return None
    return best if best is not None else ","


def _to_floats(cells: list[str], decimal_comma: bool) -> np.ndarray | None:
    """Cells -> floats (empty -> NaN); None if a cell is not a number."""
    out = np.empty(len(cells))
    try:
        for i, c in enumerate(cells):
            c = c.strip()
            if decimal_comma and "," in c:
                c = c.replace(",", ".", 1)
            out[i] = float(c) if c else np.nan
    except ValueError:
        return None
    return out


#: bytes read per block by the streaming CSV reader (:func:`_read_numeric_csv`)
CSV_BLOCK = 8 * 2**20


def _read_numeric_csv(path, progress=None):
    """A plain numeric CSV read in blocks without holding its text: ``(columns, notes)``,
    or ``None`` when the file needs the general reader (quotes, decimal commas, UTF-16,
    non-numeric or empty cells, ragged or blank-but-spaced lines: that reader reads them
    or names the problem).

    The separator and header come from the first lines as the general reader takes them
    (:func:`_sniff`); the body is parsed block by block (``numpy.loadtxt``: C speed, memory
    of one block plus the result), with ``progress(bytes, info)`` after each block of a file
    longer than one block (:mod:`friction.progress`).
    """
    size = os.path.getsize(path)
    with open(path, "rb") as fh:
        head = fh.read(min(size, 1 << 16))
        if head.startswith((b"\xff\xfe", b"\xfe\xff")) or b'"' in head:
            return None
        cut = head.rfind(b"\n")
        if cut < 0:
            return None
        text, notes = _decode(head[:cut + 1])
        if "latin-1 text" in notes:
            return None
        lines = [ln for ln in text.splitlines() if ln.strip()]
        if len(lines) < 2:
            return None
        sep = _sniff(lines)
        split = (lambda ln: ln.split()) if sep is None else \
            (lambda ln: next(csv.reader([ln], delimiter=sep)))
        header = [h.strip().strip('"').strip() for h in split(lines[0])]
        if all(_to_floats([h], True) is not None for h in header if h):
            return None  # no header: the general reader says so
        for ln in lines[1:21]:
            cells = split(ln)
            if len(cells) != len(header) or _to_floats(cells, False) is None \
                    or any(not c.strip() for c in cells):
                return None
        # the body starts after the header line (and a byte-order mark)
        start = head.index(b"\n") + 1
        while head[start:start + 1] in (b"\r", b"\n") and start < cut:
            start += 1
        fh.seek(start)
        with as_progress(progress if size > CSV_BLOCK else None,
                         f"load {os.path.basename(path)}", total=size - start, unit="B") as prog:
            return _read_blocks(fh, start, size, sep, header, notes, prog)


def _read_blocks(fh, start, size, sep, header, notes, progress):
    """The body of :func:`_read_numeric_csv` from byte ``start``; ``progress(bytes, info)``
    after each block."""
    blocks, rest, done = [], b"", start
    kw = dict(delimiter=sep, comments=None, ndmin=2, dtype=float, encoding="latin-1")
    while True:
        raw = fh.read(CSV_BLOCK)
        buf = rest + raw
        if raw:
            end = buf.rfind(b"\n")
            if end < 0:
                rest = buf
                continue
            chunk, rest = buf[:end + 1], buf[end + 1:]
        else:
            chunk, rest = buf, b""
        if chunk.strip():
            try:
                arr = np.loadtxt(io.BytesIO(chunk), **kw)
            except ValueError:
                return None
            if arr.shape[1] != len(header):
                return None
            blocks.append(arr)
        done += len(chunk)
        if chunk:
            rows = sum(b.shape[0] for b in blocks)
            progress(len(chunk), f"read {100.0 * done / max(size, 1):5.1f} % ({rows} rows)")
        if not raw:
            break
    if not blocks:
        return None
    data = np.concatenate(blocks).T.copy() if len(blocks) > 1 else blocks[0].T.copy()
    del blocks
    if sep is None:
        notes.append("whitespace-separated")
    elif sep != ",":
        notes.append({";": "';'-separated", "\t": "tab-separated", "|": "'|'-separated"}[sep])
    return {h: data[j] for j, h in enumerate(header)}, notes


def load_csv(path, mapping=None, scale=None, check_units: bool = True,
             progress=None) -> Dataset:
    """Load a measurement CSV (header row, SI units; the contract's is comma separated).

    Separators ``,``, ``;``, tab and ``|`` (or runs of whitespace) are detected from the
    header and the first data lines; decimal commas (``0,25`` in a ``;``- or tab-separated
    file, or quoted) and a UTF-8/UTF-16 byte-order mark are read correctly. What was
    detected is kept in ``Dataset.notes``.

    Parameters
    ----------
    path : path
        The file.
    mapping : dict, optional
        ``{contract column: file column}``, e.g. ``{"t": "time", "x": "pos"}``.
    scale : dict, optional
        ``{contract column: factor}`` to SI, e.g. ``{"x": 1e-3}`` for a position in mm; a
        column given a factor (even 1) is never blamed by the unit check.
    check_units : bool
        Run :meth:`Dataset.check_units`.
    progress : None, bool, tqdm or callable(n, info), optional
        Progress in bytes read (:mod:`friction.progress`), after each block of a file
        longer than one block (a plain numeric CSV is read in blocks of :data:`CSV_BLOCK`
        bytes: memory of one block plus the columns).
    """
    path = os.fspath(path)
    if not os.path.exists(path):
        raise FileNotFoundError(f"no such data file: {path}")
    fast = _read_numeric_csv(path, progress)
    if fast is not None:
        arrays, notes = fast
        return _apply(arrays, mapping, scale, os.path.basename(path), check_units,
                      tuple(notes))
    with open(path, "rb") as fh:
        text, notes = _decode(fh.read())
    lines = [ln for ln in text.splitlines() if ln.strip()]
    if not lines:
        raise DataError(f"{path}: empty file")
    if len(lines) < 2:
        raise DataError(f"{path}: header but no data rows")
    sep = _sniff(lines)
    if sep is None:
        rows = [ln.split() for ln in lines]
        notes.append("whitespace-separated")
    else:
        rows = list(csv.reader(lines, delimiter=sep))
        if sep != ",":
            notes.append({";": "';'-separated", "\t": "tab-separated",
                          "|": "'|'-separated"}[sep])
    header = [h.strip().strip('"').strip() for h in rows[0]]
    if all(_to_floats([h], True) is not None for h in header if h):
        raise DataError(f"{path}: the first line holds numbers, not column names: add a "
                        f"header row (t, x, v, F, ...) naming the columns")
    rows = rows[1:]
    for lineno, r in enumerate(rows, start=2):
        if len(r) != len(header):
            why = ""
            if sep == "," and len(r) > len(header) and any(
                    _DECIMAL_COMMA.match(f"{a},{b}") for a, b in zip(r, r[1:])):
                why = ("; decimal commas in a comma-separated file? Save it with ';' as the "
                       "separator (or with decimal points)")
            raise DataError(f"{path}:{lineno}: {len(r)} fields, header has "
                            f"{len(header)}{why}")
    cols = {h: [r[j] for r in rows] for j, h in enumerate(header)}
    wanted = set(COLUMNS) | set((mapping or {}).values())
    arrays = {}
    comma_cols = []
    for h, cells in cols.items():
        arr = _to_floats(cells, decimal_comma=False)
        if arr is None and any(_DECIMAL_COMMA.match(c) for c in cells) \
                and not any("." in c for c in cells):
            # a comma can only sit inside a field here (another separator, or quoted)
            arr = _to_floats(cells, decimal_comma=True)
            if arr is not None:
                comma_cols.append(h)
        if arr is None:
            if h in wanted:
                bad = next((c for c in cells if _to_floats([c], True) is None), None)
                if bad is None:  # every cell is a number with one decimal mark or the other
                    raise DataError(f"{path}: column {h!r} mixes decimal commas and decimal "
                                    f"points ({next(c for c in cells if ',' in c)!r}, "
                                    f"{next(c for c in cells if '.' in c)!r})")
                raise DataError(f"{path}: column {h!r} has a non-numeric value {bad!r}")
            continue  # non-numeric extra column: kept out
        arrays[h] = arr
    if comma_cols:
        notes.append("decimal commas")
    return _apply(arrays, mapping, scale, os.path.basename(path), check_units, tuple(notes))


def _isfloat(c: str) -> bool:
    try:
        float(c)
        return True
    except ValueError:
        return False


def load_mat(path, mapping=None, scale=None, check_units: bool = True):
    """Load a MATLAB ``.mat`` file; ``mapping`` names which variables are t, x, v, a, F, load.

    A mapping value ``NAME[:,j]`` takes column ``j`` of a 2-D variable (``NAME[i,:]`` row
    ``i``; indices from 0, negative from the end), e.g. ``{"v": "log[:,1]", "F":
    "log[:,0]"}`` (CLI ``--map v=log[:,1],F=log[:,0]``). Returns a :class:`Dataset`, or a
    :class:`SteadyStateMap` when v and F are given and no t.

    Parameters
    ----------
    path : str or path
        The ``.mat`` file.
    mapping : dict, optional
        ``{contract column: variable}``, e.g. ``{"t": "time", "F": "force[:,1]"}`` (a column
        or row of a 2-D variable by ``NAME[:,j]`` / ``NAME[i,:]``).
    scale : dict, optional
        ``{contract column: factor}`` to SI, e.g. ``{"x": 1e-3}`` for a position in mm.
    check_units : bool
        Run :meth:`Dataset.check_units`.
    """
    from scipy.io import loadmat
    path = os.fspath(path)
    if not os.path.exists(path):
        raise FileNotFoundError(f"no such data file: {path}")
    raw = {k: np.asarray(v) for k, v in loadmat(path).items() if not k.startswith("__")}
    numeric = {k: v for k, v in raw.items() if v.dtype.kind in "fiu" and v.size > 1}
    arrays = {}
    for k, v in numeric.items():
        if v.ndim == 2 and min(v.shape) > 1:
            continue  # a 2-D variable: only a column or row of it can be a signal
        arrays[k] = np.asarray(v, dtype=float).ravel()
    for col, src in (mapping or {}).items():
        if src in arrays:
            continue
        m = _MAT_COLUMN.match(src)
        if m is None:
            if src in numeric:
                shape = "x".join(map(str, numeric[src].shape))
                raise _data_error(lambda s, src=src, shape=shape, col=col: (
                    f"variable {src!r} is {shape}: pick one column or row of it, e.g. "
                    + (f"--map {col}={src}[:,0]" if s == "cli"
                       else f"mapping={{'{col}': '{src}[:,0]'}}")))
            continue  # _apply names the missing column
        var = m.group("var")
        if var not in numeric:
            raise DataError(f"{path}: no numeric variable {var!r} for {col}={src} "
                            f"(variables: {sorted(numeric)})")
        a = numeric[var]
        a2 = a.reshape(a.shape[0], -1) if a.ndim >= 2 else a.reshape(1, -1)
        axis = 1 if m.group("rows") is not None else 0
        i = int(m.group("rows") if axis == 1 else m.group("cols"))
        if not -a2.shape[axis] <= i < a2.shape[axis]:
            raise DataError(f"{path}: {src}: index {i} out of range for a variable of shape "
                            f"{'x'.join(map(str, a.shape))}")
        arrays[src] = np.asarray(a2[:, i] if axis == 1 else a2[i, :], dtype=float).ravel()
    return _apply(arrays, mapping, scale, os.path.basename(path), check_units)


#: ``NAME[:,j]`` (column j) or ``NAME[i,:]`` (row i) of a 2-D ``.mat`` variable in a mapping
_MAT_COLUMN = re.compile(r"^\s*(?P<var>\w+)\s*\[\s*(?::\s*,\s*(?P<rows>-?\d+)|"
                         r"(?P<cols>-?\d+)\s*,\s*:)\s*\]\s*$")


def load_dataset(path, mapping=None, scale=None, check_units: bool = True, progress=None):
    """Load CSV or ``.mat`` by extension: a :class:`Dataset`, or a :class:`SteadyStateMap`
    for a file with columns v and F and no t. ``progress``: bytes read while a long CSV is
    read (:func:`load_csv`, :mod:`friction.progress`).

    Parameters
    ----------
    path : str or path
        The file (``.mat`` or CSV).
    mapping : dict, optional
        ``{contract column: file column or variable}``.
    scale : dict, optional
        ``{contract column: factor}`` to SI.
    check_units : bool
        Run :meth:`Dataset.check_units`.
    progress : None, bool, tqdm or callable(n, info), optional
        Progress in bytes while a long CSV is read (:mod:`friction.progress`).
    """
    if os.fspath(path).lower().endswith(".mat"):
        return load_mat(path, mapping, scale, check_units)
    return load_csv(path, mapping, scale, check_units, progress=progress)
