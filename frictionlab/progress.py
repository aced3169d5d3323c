"""Progress reporting: re-exported from :mod:`friction.progress`, which owns the convention
(a library function's ``progress=`` argument; the CLI's ``--quiet``)."""
from friction.progress import LOG_INTERVAL, Progress, as_progress, report, status_lines

__all__ = ["Progress", "as_progress", "report", "status_lines", "LOG_INTERVAL"]
