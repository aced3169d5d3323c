"""The master's per-step loop in C (``fmus/csrc/fl_master_loop.c``), called once per run.

From Python each FMI call through ctypes costs about 0.5-0.8 us whatever the FMU does, so a
mass + law loop (six calls per communication step) cannot get below about 4 us per step in a
Python loop, while a native FMU's ``fmi2DoStep`` takes a fraction of a microsecond. This
module compiles a small C loop that makes the same calls, in the same order, on the same
buffers as :meth:`fmus.master.Master.simulate` (Gauss-Seidel or Jacobi, the fixed-point pass,
the recording), through the function pointers taken from each FMU's library; the results are
those of the Python loop bit for bit (tests/test_native_master.py).

The library is built with the system C compiler on first use and cached under
``$FRICTIONLAB_CACHE/master_loop`` (default ``~/.cache/frictionlab``), keyed by a hash of the
source, compiler and flags. Without a compiler the master keeps its Python loop
(:func:`library` returns None and :data:`UNAVAILABLE` says why); ``FRICTIONLAB_MASTER_LOOP=
python`` forces the Python loop.
"""
from __future__ import annotations

import ctypes
import hashlib
import os
import pathlib
import shlex
import shutil
import subprocess
import sysconfig
import tempfile

__all__ = ["SOURCE", "library", "UNAVAILABLE", "CLoop", "function_address", "LOOPS"]

SOURCE = pathlib.Path(__file__).resolve().parent / "csrc" / "fl_master_loop.c"
#: ``Master(loop=...)``: the C loop when it can be built (``"auto"``), always (``"c"``), never
LOOPS = ("auto", "c", "python")
_FLAGS = ["-std=c99", "-O2", "-shared", "-fPIC", "-fvisibility=hidden", "-ffp-contract=off",
          "-Wall", "-Wextra"]
#: why the C loop is not available (None: it is, or it was not tried yet)
UNAVAILABLE: str | None = None
_LIB: ctypes.CDLL | None = None


def _compiler() -> list[str] | None:
    for cand in (os.environ.get("CC"), sysconfig.get_config_var("CC"), "cc", "gcc", "clang"):
        if not cand:
            continue
        argv = shlex.split(cand)
        if argv and shutil.which(argv[0]):
            return argv
    return None


def _cache_dirs() -> list[pathlib.Path]:
    base = os.environ.get("FRICTIONLAB_CACHE") or \
        os.path.join(os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"),
                     "frictionlab")
    return [pathlib.Path(base) / "master_loop",
            pathlib.Path(tempfile.gettempdir()) / "frictionlab_master_loop"]


def library() -> ctypes.CDLL | None:
    """The compiled loop (built on first use, then cached), or None when it cannot be built
    (:data:`UNAVAILABLE` gives the reason)."""
    global _LIB, UNAVAILABLE
    if _LIB is not None or UNAVAILABLE is not None:
        return _LIB
    cc = _compiler()
    if cc is None:
        UNAVAILABLE = "no C compiler found ($CC, Python's CC, cc, gcc, clang)"
        return None
    h = hashlib.sha256(SOURCE.read_bytes())
    h.update(" ".join(cc + _FLAGS).encode())
    name = f"fl_master_loop_{h.hexdigest()[:16]}.so"
    for cache in _cache_dirs():
        lib = cache / name
        if not lib.is_file():
            try:
                cache.mkdir(parents=True, exist_ok=True)
                tmpdir = tempfile.mkdtemp(dir=cache)
            except OSError:
                continue  # not writable: the next place
            try:
                tmp = os.path.join(tmpdir, name)
                proc = subprocess.run(cc + _FLAGS + [str(SOURCE), "-o", tmp, "-lm"],
                                      capture_output=True, text=True)
                if proc.returncode != 0:
                    UNAVAILABLE = f"compiling {SOURCE.name} failed: {proc.stderr.strip()[-800:]}"
                    return None
                os.replace(tmp, lib)  # atomic: a concurrent build sees a complete file
            finally:
                shutil.rmtree(tmpdir, ignore_errors=True)
        try:
            dll = ctypes.CDLL(str(lib))
        except OSError as exc:
            UNAVAILABLE = f"loading {lib} failed: {exc}"
            return None
        dll.flm_run.restype = ctypes.c_int
        dll.flm_run.argtypes = [ctypes.c_void_p, ctypes.c_long, ctypes.c_long, ctypes.c_void_p]
        dll.flm_prescribed.restype = ctypes.c_long
        dll.flm_prescribed.argtypes = [ctypes.c_void_p, ctypes.c_long, ctypes.c_void_p,
                                       ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p]
        _LIB = dll
        return dll
    UNAVAILABLE = "no writable cache folder for the compiled master loop"
    return None


def function_address(fn) -> int:
    """Address of a ctypes function pointer (the FMU library's function)."""
    return ctypes.cast(fn, ctypes.c_void_p).value


_P = ctypes.c_void_p


class _Inst(ctypes.Structure):
    _fields_ = [("c", _P), ("set", _P), ("step", _P), ("get", _P),
                ("in_vr", _P), ("n_in", ctypes.c_size_t), ("in_buf", _P),
                ("out_vr", _P), ("n_out", ctypes.c_size_t), ("out_buf", _P),
                ("n_gather", ctypes.c_int), ("g_slot", _P), ("g_src", _P), ("g_fac", _P)]


class _Plan(ctypes.Structure):
    _fields_ = [("n_inst", ctypes.c_int), ("inst", _P), ("jacobi", ctypes.c_int),
                ("iterations", ctypes.c_int), ("tolerance", ctypes.c_double),
                ("n_ft", ctypes.c_int), ("ft", _P),
                ("n_conn", ctypes.c_int), ("conn_src", _P), ("prev", _P), ("cur", _P),
                ("n_rec", ctypes.c_int), ("rec_src", _P),
                ("n_tab", ctypes.c_int), ("tab_dst", _P), ("tab", _P),
                ("t0", ctypes.c_double), ("h", ctypes.c_double),
                ("err_inst", ctypes.c_int), ("err_call", ctypes.c_int),
                ("err_status", ctypes.c_int), ("err_time", ctypes.c_double)]


CALLS = ("fmi2SetReal", "fmi2DoStep", "fmi2GetReal")


def _addr(buf, k: int = 0) -> int:
    return ctypes.addressof(buf) + k * ctypes.sizeof(ctypes.c_double)


class CLoop:
    """The C loop over instances (objects with the ``fmus.master._Instance`` buffers).

    Parameters
    ----------
    insts : list
        Instances in stepping order (``cv``, ``raw_set``/``raw_step``/``raw_get``, ``in_vr``,
        ``in_buf``, ``out_vr``, ``out_buf``, ``n_in``, ``n_out``, ``gather``).
    jacobi : bool
    iterations : int
    tolerance : float
    feedthrough : list
        The instances the fixed-point pass visits, in order.
    conn_src : list of (buffer, slot)
        Every connection's source value (the convergence test).
    rec_src : list of (buffer, slot)
        The recorded values.
    ext_dst : list of (buffer, slot)
        Where the external inputs' values go; :meth:`set_table` gives them, one row per
        communication step (row k - 1 written before step k).
    """

    def __init__(self, insts, *, jacobi=False, iterations=0, tolerance=1e-10, feedthrough=(),
                 conn_src=(), rec_src=(), ext_dst=()):
        self.lib = library()
        if self.lib is None:
            raise RuntimeError(f"the C master loop is not available: {UNAVAILABLE}")
        self.insts = list(insts)
        keep = []  # every array the C side points into
        arr = (_Inst * max(len(self.insts), 1))()
        for i, inst in enumerate(self.insts):
            gather = [g if len(g) == 4 else (*g, 1.0) for g in inst.gather]
            slots = (ctypes.c_int * max(len(gather), 1))(*[g[0] for g in gather])
            srcs = (_P * max(len(gather), 1))(*[_addr(g[1].out_buf, g[2]) for g in gather])
            facs = (ctypes.c_double * max(len(gather), 1))(*[float(g[3]) for g in gather])
            keep += [slots, srcs, facs]
            arr[i] = _Inst(inst.cv.value, function_address(inst.raw_set),
                           function_address(inst.raw_step), function_address(inst.raw_get),
                           ctypes.addressof(inst.in_vr), inst.n_in, _addr(inst.in_buf),
                           ctypes.addressof(inst.out_vr), inst.n_out, _addr(inst.out_buf),
                           len(gather), ctypes.addressof(slots), ctypes.addressof(srcs),
                           ctypes.addressof(facs))
        index = {id(inst): i for i, inst in enumerate(self.insts)}
        ft = (ctypes.c_int * max(len(feedthrough), 1))(*[index[id(f)] for f in feedthrough])
        conn = (_P * max(len(conn_src), 1))(*[_addr(b, j) for b, j in conn_src])
        prev = (ctypes.c_double * max(len(conn_src), 1))()
        cur = (ctypes.c_double * max(len(conn_src), 1))()
        rec = (_P * max(len(rec_src), 1))(*[_addr(b, j) for b, j in rec_src])
        ext = (_P * max(len(ext_dst), 1))(*[_addr(b, j) for b, j in ext_dst])
        keep += [arr, ft, conn, prev, cur, rec, ext]
        self._keep = keep
        self.n_tab = len(ext_dst)
        self._table = None
        self.plan = _Plan(len(self.insts), ctypes.addressof(arr), int(bool(jacobi)),
                          int(iterations), float(tolerance), len(feedthrough),
                          ctypes.addressof(ft), len(conn_src), ctypes.addressof(conn),
                          ctypes.addressof(prev), ctypes.addressof(cur), len(rec_src),
                          ctypes.addressof(rec), 0, ctypes.addressof(ext), None,
                          0.0, 0.0, -1, -1, 0, 0.0)
        self.n_rec = len(rec_src)
        self._plan_p = ctypes.addressof(self.plan)

    def error(self) -> tuple:
        """(instance, call name, status, time) of the failed call."""
        p = self.plan
        return self.insts[p.err_inst], CALLS[p.err_call], p.err_status, p.err_time

    def set_table(self, table) -> None:
        """The external inputs' values of the next runs: a C-contiguous float64 array of
        ``(steps, len(ext_dst))``; row ``k - 1`` is written before step ``k``."""
        import numpy as np
        table = np.ascontiguousarray(table, dtype=np.float64)
        if table.ndim != 2 or table.shape[1] != self.n_tab:
            raise ValueError(f"table of shape {table.shape}: need (steps, {self.n_tab})")
        self._table = table  # kept alive while the C side points into it
        self.plan.n_tab = self.n_tab
        self.plan.tab = table.ctypes.data

    def run(self, t0: float, h: float, k_from: int, k_to: int, rec_rows) -> bool:
        """Steps ``k_from..k_to``; ``rec_rows``: a C-contiguous float64 array of at least
        ``(k_to - k_from + 1) * n_rec`` values. Returns False when a call failed."""
        self.plan.t0, self.plan.h = t0, h
        return self.lib.flm_run(self._plan_p, k_from, k_to, rec_rows.ctypes.data) == 0

    def prescribed(self, t, U, Um, F) -> int:
        """The prescribed-motion drive of ``identification.cosim`` on the first instance
        (its ``out_vr[0]`` is the force): -1 when done, else the failed sample."""
        return self.lib.flm_prescribed(self._plan_p, t.size, t.ctypes.data, U.ctypes.data,
                                       Um.ctypes.data, F.ctypes.data)
