"""Helpers for tests and benchmarks: build the FMUs once per process; drive one FMU through
fmpy's low-level API with its log messages captured."""
from __future__ import annotations

import functools
import pathlib
import shutil
import tempfile

__all__ = ["built_fmus", "LoggedSlave"]


@functools.lru_cache(maxsize=None)
def built_fmus(only: tuple | None = None) -> pathlib.Path:
    """Build (and validate) the FMUs into a temporary folder once per process; returns it."""
    from .build import build_all
    out = pathlib.Path(tempfile.mkdtemp(prefix="frictionlab_fmus_"))
    build_all(out, only=list(only) if only else None, progress=False)
    return out


class LoggedSlave:
    """fmpy ``FMU2Slave`` of one FMU, with the log messages captured as (status, message).

    ``set``/``step`` return the FMI status instead of raising (fmpy raises above warning).
    """

    def __init__(self, path, name: str = "inst", logging_on: bool = True):
        import fmpy
        from fmpy.fmi2 import (FMU2Slave, calloc, fmi2CallbackAllocateMemoryTYPE,
                               fmi2CallbackFreeMemoryTYPE, fmi2CallbackFunctions,
                               fmi2CallbackLoggerTYPE, free)
        self.md = fmpy.read_model_description(str(path))
        self.dir = fmpy.extract(str(path))
        self.vr = {v.name: v.valueReference for v in self.md.modelVariables}
        self.messages = []

        def logger(env, inst, status, cat, msg):
            self.messages.append((status, msg.decode()))
        cb = fmi2CallbackFunctions()
        cb.logger = fmi2CallbackLoggerTYPE(logger)
        cb.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        cb.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        self._cb = (cb, logger)  # the callbacks must outlive the instance
        self.s = FMU2Slave(guid=self.md.guid, unzipDirectory=self.dir,
                           modelIdentifier=self.md.coSimulation.modelIdentifier,
                           instanceName=name)
        self.s.instantiate(callbacks=cb, loggingOn=logging_on)
        self.s.setupExperiment(startTime=0.0)

    def set(self, name, value) -> int:
        """fmi2SetReal of one variable; returns the FMI status."""
        from fmpy.fmi1 import FMICallException
        try:
            self.s.setReal([self.vr[name]], [value])
        except FMICallException as exc:
            return exc.status
        return 0

    def step(self, t, h) -> int:
        """fmi2DoStep; returns the FMI status."""
        from fmpy.fmi1 import FMICallException
        try:
            self.s.doStep(t, h)
        except FMICallException as exc:
            return exc.status
        return 0

    def get(self, name) -> float:
        return self.s.getReal([self.vr[name]])[0]

    def init(self, **values) -> None:
        """Set start values, then enter and exit initialization mode."""
        types = {v.name: v.type for v in self.md.modelVariables}
        for k, v in values.items():
            if types[k] == "Boolean":
                self.s.setBoolean([self.vr[k]], [bool(v)])
            elif types[k] in ("Integer", "Enumeration"):
                self.s.setInteger([self.vr[k]], [int(v)])
            else:
                self.s.setReal([self.vr[k]], [v])
        self.s.enterInitializationMode()
        self.s.exitInitializationMode()

    def errors(self) -> list[str]:
        """Messages logged with fmi2Error (3) or worse."""
        return [m for st, m in self.messages if st >= 3]

    def close(self) -> None:
        try:
            self.s.terminate()
            self.s.fmi2FreeInstance(self.s.component)
        finally:
            shutil.rmtree(self.dir, ignore_errors=True)
