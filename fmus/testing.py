"""Helpers for tests and benchmarks: build the FMUs once per process."""
from __future__ import annotations

import functools
import pathlib
import tempfile

__all__ = ["built_fmus"]


@functools.lru_cache(maxsize=None)
def built_fmus(only: tuple | None = None) -> pathlib.Path:
    """Build (and validate) the FMUs into a temporary folder once per process; returns it."""
    from .build import build_all
    out = pathlib.Path(tempfile.mkdtemp(prefix="frictionlab_fmus_"))
    build_all(out, only=list(only) if only else None, progress=False)
    return out
