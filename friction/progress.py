"""One progress convention for the whole library, on tqdm.

What a library function accepts as ``progress=``
------------------------------------------------
``None`` or ``False``
    Silent (the default everywhere).
``True``
    A tqdm bar on stderr labelled ``[<run>]`` (``[identify cmaes]``, ``[cosim]``,
    ``[load data.csv]``): count and rate, and percentage and ETA when the run knows its
    length; the latest status text (``cost=0.012``) at its end. ``tqdm.auto`` picks a
    notebook widget in Jupyter.
a tqdm instance (``tqdm.tqdm``, ``tqdm.auto.tqdm``, ``tqdm.notebook.tqdm``, ...)
    Used as it is: advanced with ``update(n)``, its status set with
    ``set_postfix_str(info)``; the caller creates and closes it.
a callable
    Called as ``progress(n, info)``, both positional: ``n`` (int) units of work finished
    since the previous call, ``0`` for a status line that finishes none; ``info`` (str) a
    short status text or ``""``. The unit is the function's own (output samples,
    evaluations, co-simulation steps, FMUs, cases) and its docstring names it.

Library code turns the argument into a :class:`Progress` with :func:`as_progress` once per
run (``with as_progress(progress, "cosim", total=n, unit="step") as p: ... p(k, info)``);
it never prints progress itself. A :class:`Progress` is itself a valid ``progress=``
argument, so a run can hand its bar to the functions it calls.

Command line and logs
---------------------
The ``frictionlab`` commands pass ``progress=not args.quiet``: ``--quiet`` prints nothing.
When stderr is not a terminal (a log file, CI, a captured stream) a bar is not redrawn in
place: it writes a plain line when it starts, at most every :data:`LOG_INTERVAL` seconds
while it runs and once when it ends, so logs stay short. One-off status lines
(``[demo 1/5] friction ...``) go through :func:`report`, which does not tear a bar.
"""
from __future__ import annotations

import sys
import time

__all__ = ["Progress", "as_progress", "report", "status_lines", "LOG_INTERVAL"]

#: seconds between a bar's lines when stderr is not a terminal
LOG_INTERVAL = 10.0


def _isatty(stream) -> bool:
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):
        return False


class _LogLines:
    """A stream for a bar in a log: every redraw becomes one plain line."""

    def __init__(self, stream):
        self.stream = stream

    def write(self, s: str) -> None:
        for part in s.replace("\r", "\n").split("\n"):
            if part.strip():
                self.stream.write(part.rstrip() + "\n")

    def flush(self) -> None:
        getattr(self.stream, "flush", lambda: None)()


class Progress:
    """The ``progress(n, info)`` callable of this convention, on a tqdm bar.

    Parameters
    ----------
    total : int, optional
        Units of work in the run (percentage and ETA when given).
    label : str
        Name of the run, shown as ``[label]``.
    interval : float, optional
        Minimum seconds between redraws (default 0.1 on a terminal, :data:`LOG_INTERVAL`
        otherwise; 0 draws every call).
    stream : file-like, optional
        Where the bar goes (default ``sys.stderr``).
    enabled : bool
        False: a silent progress (every call does nothing).
    unit : str
        Name of one unit of work (``"it"``, ``"step"``, ``"eval"``).
    bar : tqdm or callable, optional
        Drive this caller-owned tqdm bar or ``callable(n, info)`` instead of creating a
        bar; :meth:`close` leaves it open.
    """

    def __init__(self, total: int | None = None, label: str = "", interval: float | None = None,
                 stream=None, enabled: bool = True, unit: str = "it", bar=None):
        self.total, self.label, self.count = total, label, 0
        self._own = False
        self._bar = self._fn = None
        if bar is not None:
            if hasattr(bar, "update") and hasattr(bar, "set_postfix_str"):
                self._bar = bar
            elif callable(bar):
                self._fn = bar
            else:
                raise TypeError(f"bar must be a tqdm instance or a callable(n, info), "
                                f"got {type(bar).__name__}")
        elif enabled:  # the bar is drawn from the first update: a run with none is silent
            self._new = dict(total=total, desc=f"[{label}]" if label else None, unit=unit,
                             stream=stream, interval=interval, t0=time.time())
            self._own = True

    def _start(self):
        from tqdm.auto import tqdm
        kw = self.__dict__.pop("_new")
        stream = sys.stderr if kw["stream"] is None else kw["stream"]
        tty = _isatty(stream)
        interval = kw["interval"]
        if interval is None:
            interval = 0.1 if tty else LOG_INTERVAL
        bar = tqdm(total=kw["total"], desc=kw["desc"], unit=kw["unit"], mininterval=interval,
                   file=stream if tty else _LogLines(stream), miniters=0, dynamic_ncols=tty,
                   leave=True, delay=0)
        bar.start_t = bar.last_print_t = kw["t0"]  # rate and ETA from the run's start
        self._bar = bar

    def __bool__(self) -> bool:
        return self._bar is not None or self._fn is not None or self._own

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __call__(self, n: int = 1, info: str = "") -> None:
        """``n`` units done since the last call (0: a status line only); ``info``: status."""
        self.update(n, info)

    def update(self, n: int = 1, info: str = "") -> None:
        """Same as calling the progress: ``n`` units done, ``info`` the status text."""
        self.count += n
        if self._fn is not None:
            self._fn(n, info)
        else:
            if self._bar is None:
                if not self._own:
                    return
                self._start()
            if info:
                self._bar.set_postfix_str(info, refresh=False)
            self._bar.update(n)

    def close(self) -> None:
        """End a bar this object created (its final line); a caller's bar stays open."""
        if self._own and self._bar is not None:
            self._bar.close()
            self._own = False


def as_progress(progress, label: str = "", total: int | None = None, unit: str = "it",
                interval: float | None = None) -> Progress:
    """The :class:`Progress` for a function's ``progress=`` argument (see the module).

    Parameters
    ----------
    progress : None, bool, tqdm, Progress or callable(n, info)
        The argument as the user gave it.
    label : str
        Name of the run for a bar created here (``progress=True``).
    total : int, optional
        Units of work in the run, for a bar created here.
    unit : str
        Name of one unit of work, for a bar created here.
    interval : float, optional
        Minimum seconds between the lines of a bar created here (see :class:`Progress`;
        0 for a few slow units, each worth its line).

    Returns
    -------
    Progress
        Silent for None/False, a new stderr bar for True, else a wrapper of the given bar or
        callable (not closed by :meth:`Progress.close`).
    """
    if isinstance(progress, Progress):
        return Progress(bar=progress) if progress else Progress(enabled=False)
    if progress is None or progress is False:
        return Progress(enabled=False)
    if progress is True:
        return Progress(total=total, label=label, unit=unit, interval=interval)
    if callable(progress) or hasattr(progress, "set_postfix_str"):
        return Progress(bar=progress)
    raise TypeError(f"progress must be None, a bool, a tqdm bar or a callable(n, info), got "
                    f"{type(progress).__name__}")


def report(message: str, enabled: bool = True) -> None:
    """One status line on stderr (through tqdm, so a running bar is not torn).

    Parameters
    ----------
    message : str
        The line.
    enabled : bool
        False: print nothing.
    """
    if enabled:
        from tqdm.auto import tqdm
        tqdm.write(message, file=sys.stderr)


def status_lines(progress):
    """``say(message)`` for a run's one-off status lines (``[diagnose] candidate 3/9``),
    from the same ``progress=`` argument as everything else (see the module).

    Parameters
    ----------
    progress : None, bool, tqdm, Progress or callable(n, info)
        The argument as the user gave it: None/False silent; True one line each on stderr
        (:func:`report`); a bar gets the message as its status, a callable ``(0, message)``.

    Returns
    -------
    callable
        ``say(message)``.
    """
    if progress is None or progress is False:
        return lambda message: None
    if progress is True:
        return report
    p = as_progress(progress)
    return lambda message: p(0, message)

