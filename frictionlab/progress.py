"""Progress reporting for long runs (stderr, throttled, no dependency).

Usage::

    with Progress(total=n, label="identify") as p:
        for i in range(n):
            ...
            p.update(1, info=f"cost={c:.3g}")

Library code takes an optional ``progress`` callable; ``Progress`` is one, so is ``None``
(silent). Output is throttled to one line per ``interval`` seconds.
"""
from __future__ import annotations

import sys
import time

__all__ = ["Progress", "report"]


class Progress:
    def __init__(self, total: int | None = None, label: str = "", interval: float = 1.0,
                 stream=None, enabled: bool = True):
        self.total, self.label, self.interval = total, label, interval
        self.stream = stream if stream is not None else sys.stderr
        self.enabled = enabled
        self.count = 0
        self._t0 = time.monotonic()
        self._last = -1e9

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __call__(self, n: int = 1, info: str = "") -> None:
        self.update(n, info)

    def update(self, n: int = 1, info: str = "") -> None:
        self.count += n
        now = time.monotonic()
        if self.enabled and (now - self._last >= self.interval
                             or (self.total and self.count >= self.total)):
            self._last = now
            self._write(info)

    def _write(self, info: str) -> None:
        el = time.monotonic() - self._t0
        if self.total:
            pct = 100.0 * self.count / self.total
            msg = f"[{self.label}] {self.count}/{self.total} ({pct:5.1f} %) {el:6.1f} s"
        else:
            msg = f"[{self.label}] {self.count} {el:6.1f} s"
        if info:
            msg += f"  {info}"
        print(msg, file=self.stream, flush=True)

    def close(self) -> None:
        pass


def report(message: str, enabled: bool = True) -> None:
    """One progress line on stderr."""
    if enabled:
        print(message, file=sys.stderr, flush=True)
