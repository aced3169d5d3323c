"""The studies' figure plumbing: pyplot on the file-only backend, the output folder, saving."""
from __future__ import annotations

import pathlib

__all__ = ["pyplot", "folder", "save"]


def pyplot():
    """``matplotlib.pyplot`` on the Agg backend (files only, no display needed)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def folder(out) -> pathlib.Path:
    """The output folder ``out`` as a path, created if missing."""
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    return out


def save(fig, path, dpi: int = 110):
    """Lay out ``fig``, write it to ``path`` at ``dpi`` and close it; returns ``path``."""
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    pyplot().close(fig)
    return path
