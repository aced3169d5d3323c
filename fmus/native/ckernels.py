"""The friction laws' C sources, compiled into one shared library and called through ctypes.

Used by the tests that prove the C equations equal to the numba kernels, and by the
benchmarks. The library is compiled with the system C compiler on first use and cached under
``~/.cache/frictionlab`` (keyed by a hash of the sources).

>>> from fmus.native.ckernels import CLaw       # doctest: +SKIP
>>> law = CLaw("lugre")                          # doctest: +SKIP
>>> F, S = law.kernel(t, v, theta=law.pack(params))   # doctest: +SKIP
"""
from __future__ import annotations

import ctypes
import dataclasses
import hashlib
import math
import os
import pathlib
import shutil
import subprocess

import numpy as np

__all__ = ["CSRC", "law_sources", "compiler", "library", "param_vector", "CLaw",
           "NativeBuildError"]

#: folder of the C sources that travel into every native FMU's ``sources/``
CSRC = pathlib.Path(__file__).resolve().parent / "csrc"


class NativeBuildError(RuntimeError):
    """The C sources could not be compiled (no compiler, or a compile error)."""


def law_sources() -> list[pathlib.Path]:
    """The laws' C files present in ``csrc/laws`` (one per law, plus shared helpers)."""
    return sorted((CSRC / "laws").glob("*.c"))


def compiler() -> str:
    """Path of the system C compiler (``$CC``, ``cc``, ``gcc`` or ``clang``)."""
    for name in (os.environ.get("CC"), "cc", "gcc", "clang"):
        if name and shutil.which(name):
            return shutil.which(name)
    raise NativeBuildError("no C compiler found: install one (Debian: apt-get install gcc) "
                           "or set CC")


def _cache_dir() -> pathlib.Path:
    root = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    d = pathlib.Path(root) / "frictionlab" / "native"
    d.mkdir(parents=True, exist_ok=True)
    return d


_LIB = None


def library() -> ctypes.CDLL:
    """The compiled laws (one shared library with every ``fl_law_<name>`` definition)."""
    global _LIB
    if _LIB is not None:
        return _LIB
    srcs = law_sources()
    headers = sorted(CSRC.glob("*.h")) + sorted((CSRC / "laws").glob("*.h"))
    digest = hashlib.sha256()
    for p in srcs + headers:
        digest.update(p.name.encode())
        digest.update(p.read_bytes())
    out = _cache_dir() / f"libfl_laws_{digest.hexdigest()[:16]}.so"
    if not out.exists():
        tmp = out.with_suffix(f".{os.getpid()}.tmp")
        cmd = [compiler(), "-std=c99", "-O2", "-fPIC", "-shared", "-Wall", "-Wextra",
               "-Werror=implicit-function-declaration", f"-I{CSRC}",
               *map(str, srcs), "-o", str(tmp), "-lm"]
        res = subprocess.run(cmd, capture_output=True, text=True)
        if res.returncode != 0:
            raise NativeBuildError("compiling the laws' C sources failed:\n" + res.stderr)
        os.replace(tmp, out)
    _LIB = ctypes.CDLL(str(out))
    return _LIB


_D = ctypes.POINTER(ctypes.c_double)
_PACK = ctypes.CFUNCTYPE(ctypes.c_int, _D, _D, ctypes.c_char_p, ctypes.c_size_t)
_KERNEL = ctypes.CFUNCTYPE(None, ctypes.c_int, _D, _D, _D, _D, _D, _D, ctypes.c_int, _D, _D, _D)
_REGIMES = ctypes.CFUNCTYPE(ctypes.c_int, _D, _D, _D, _D)
_DERIV = ctypes.CFUNCTYPE(None, _D, _D, ctypes.c_double, ctypes.c_double, ctypes.c_double,
                          ctypes.c_double, _D)
_FORCE = ctypes.CFUNCTYPE(ctypes.c_double, _D, _D, ctypes.c_double, ctypes.c_double,
                          ctypes.c_double, ctypes.c_double)


class _LawDef(ctypes.Structure):
    _fields_ = [("name", ctypes.c_char_p), ("n_params", ctypes.c_int),
                ("n_theta", ctypes.c_int), ("n_states", ctypes.c_int),
                ("inputs", ctypes.c_int), ("pack", _PACK), ("kernel", _KERNEL),
                ("regimes", _REGIMES), ("derivatives", _DERIV), ("force", _FORCE)]


def param_vector(params) -> np.ndarray:
    """The ``p[]`` vector of ``csrc/fl_law.h`` for a parameter dataclass instance: fields in
    declaration order, None -> NaN, bool -> 0/1, an option -> its code in ``OPTIONS``."""
    options = getattr(type(params), "OPTIONS", {})
    out = []
    for f in dataclasses.fields(params):
        value = getattr(params, f.name)
        if value is None:
            out.append(math.nan)
        elif isinstance(value, str):
            out.append(float(options[f.name][value]))
        else:
            out.append(float(value))
    return np.asarray(out, dtype=np.float64)


def _ptr(a):
    return None if a is None else a.ctypes.data_as(_D)


def _arr(a, n=None):
    if a is None:
        return None
    a = np.ascontiguousarray(a, dtype=np.float64)
    if n is not None and a.size != n:
        raise ValueError(f"expected {n} values, got {a.size}")
    return a


class CLaw:
    """One law's C functions (``fl_law_<name>``) called from Python.

    Parameters
    ----------
    name : str
        Registry name (``friction.MODELS``).
    """

    def __init__(self, name: str):
        self.name = name
        try:
            self.d = _LawDef.in_dll(library(), f"fl_law_{name}")
        except ValueError:
            raise NotImplementedError(f"no C source defines fl_law_{name}") from None
        self.n_theta, self.n_states = self.d.n_theta, self.d.n_states

    def pack(self, params) -> np.ndarray:
        """Packed theta of a parameter dataclass instance (the C ``pack``).

        Raises
        ------
        ValueError
            The C side refused the parameters (its message).
        """
        p = param_vector(params)
        if p.size != self.d.n_params:
            raise ValueError(f"{self.name}: {p.size} parameters for n_params = "
                             f"{self.d.n_params}")
        theta = np.zeros(self.n_theta)
        msg = ctypes.create_string_buffer(512)
        if self.d.pack(_ptr(p), _ptr(theta), msg, 512):
            raise ValueError(msg.value.decode())
        return theta

    def kernel(self, t, v, theta, *, a=None, load=None, x=None, method: int = 0, state0=None):
        """``(F, S)`` along ``t, v`` (and ``a``, ``load``, ``x``) as the law's ``_kernel``."""
        t = _arr(t)
        n = t.size
        v, a, load, x = _arr(v, n), _arr(a, n), _arr(load, n), _arr(x, n)
        theta = _arr(theta, self.n_theta)
        s0 = np.zeros(self.n_states) if state0 is None else _arr(state0, self.n_states)
        if s0.size == 0:
            s0 = np.zeros(1)
        F = np.empty(n)
        S = np.empty(max(n * self.n_states, 1))
        self.d.kernel(n, _ptr(t), _ptr(v), _ptr(a), _ptr(load), _ptr(x), _ptr(theta), method,
                      _ptr(s0), _ptr(F), _ptr(S))
        return F, S[:n * self.n_states].reshape(n, self.n_states)

    def regimes(self, theta):
        """``(vc, theta_low, theta_high)`` or None for a smooth law."""
        if not self.d.regimes:
            return None
        theta = _arr(theta, self.n_theta)
        vc = np.zeros(1)
        lo, hi = np.zeros(self.n_theta), np.zeros(self.n_theta)
        if self.d.regimes(_ptr(theta), _ptr(vc), _ptr(lo), _ptr(hi)):
            raise ValueError(f"{self.name}: regime split failed")
        return float(vc[0]), lo, hi

    def derivatives(self, theta, state, v, a=0.0, load=0.0, x=0.0) -> np.ndarray:
        theta, state = _arr(theta, self.n_theta), _arr(state, self.n_states)
        out = np.zeros(self.n_states)
        self.d.derivatives(_ptr(theta), _ptr(state), v, a, load, x, _ptr(out))
        return out

    def force(self, theta, state, v, a=0.0, load=0.0, x=0.0) -> float:
        theta = _arr(theta, self.n_theta)
        state = _arr(state, self.n_states) if self.n_states else np.zeros(1)
        return float(self.d.force(_ptr(theta), _ptr(state), v, a, load, x))
