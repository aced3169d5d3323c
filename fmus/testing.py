"""Helpers for tests and benchmarks: build the FMUs once per process; drive one FMU through
fmpy's low-level API with its log messages captured."""
from __future__ import annotations

import atexit
import functools
import pathlib
import shutil
import tempfile

__all__ = ["built_fmus", "built_native_fmus", "LoggedSlave"]


def _scratch(prefix: str) -> pathlib.Path:
    """A temporary folder removed when the process ends (each test process built its FMUs
    into a new one and left it: hundreds piled up in the temporary directory)."""
    out = pathlib.Path(tempfile.mkdtemp(prefix=prefix))
    atexit.register(shutil.rmtree, out, ignore_errors=True)
    return out


@functools.lru_cache(maxsize=None)
def built_fmus(only: tuple | None = None) -> pathlib.Path:
    """Build (and validate) the FMUs into a temporary folder once per process; returns it."""
    from .build import build_all
    out = _scratch("frictionlab_fmus_")
    build_all(out, only=list(only) if only else None, progress=False, kinds=("pythonfmu",))
    return out


@functools.lru_cache(maxsize=None)
def built_native_fmus(only: tuple | None = None) -> pathlib.Path:
    """Build every native FMU (or ``only`` those) into a temporary folder once per process;
    each is validated with fmpy. Returns the folder (``<name>_native.fmu`` files)."""
    from .native.build import build_native, native_catalogue
    from .build import validate
    out = _scratch("frictionlab_native_")
    for name in (only or tuple(native_catalogue())):
        path = build_native(name, out)
        problems = validate(path)
        if problems:
            raise RuntimeError(f"{path.name} fails fmpy validation: " + "; ".join(problems))
    return out


class LoggedSlave:
    """fmpy ``FMU2Slave`` of one FMU, with the log messages captured as (status, message).

    ``set``/``step`` return the FMI status instead of raising (fmpy raises above warning).
    """

    def __init__(self, path, name: str = "inst", logging_on: bool = True):
        """Load the FMU and instantiate it.

        Parameters
        ----------
        path : str or path
            The ``.fmu`` file.
        name : str
            Instance name.
        logging_on : bool
            Ask the FMU for its log messages.
        """
        import fmpy
        from fmpy.fmi2 import (FMU2Slave, calloc, fmi2CallbackAllocateMemoryTYPE,
                               fmi2CallbackFreeMemoryTYPE, fmi2CallbackFunctions,
                               fmi2CallbackLoggerTYPE, free)
        self.md = fmpy.read_model_description(str(path))
        self.dir = fmpy.extract(str(path))
        self.vr = {v.name: v.valueReference for v in self.md.modelVariables}
        self.types = {v.name: v.type for v in self.md.modelVariables}
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
        """Set one variable with the setter of its type; returns the FMI status.

        Parameters
        ----------
        name : str
            Variable name.
        value : float, int, bool or str
            The value.
        """
        from fmpy.fmi1 import FMICallException
        kind = self.types[name]
        try:
            if kind == "Boolean":
                self.s.setBoolean([self.vr[name]], [bool(value)])
            elif kind in ("Integer", "Enumeration"):
                self.s.setInteger([self.vr[name]], [int(value)])
            else:
                self.s.setReal([self.vr[name]], [value])
        except FMICallException as exc:
            return exc.status
        return 0

    def step(self, t, h) -> int:
        """fmi2DoStep; returns the FMI status.

        Parameters
        ----------
        t, h : float
            Communication point and step [s].
        """
        from fmpy.fmi1 import FMICallException
        try:
            self.s.doStep(t, h)
        except FMICallException as exc:
            return exc.status
        return 0

    def get(self, name) -> float:
        """Current value of a Real variable.

        Parameters
        ----------
        name : str
            Name of a Real variable.
        """
        return self.s.getReal([self.vr[name]])[0]

    def init(self, **values) -> None:
        """Set start values, then enter and exit initialization mode.

        Parameters
        ----------
        **values
            Start values by variable name; a name the FMU does not have is a TypeError.
        """
        unknown = sorted(set(values) - set(self.vr))
        if unknown:
            raise TypeError(f"{self.name}: the FMU has no variable(s) {unknown}")
        for k, v in values.items():
            self.set(k, v)
        self.s.enterInitializationMode()
        self.s.exitInitializationMode()

    def errors(self) -> list[str]:
        """Messages logged with fmi2Error (3) or worse."""
        return [m for st, m in self.messages if st >= 3]

    def close(self) -> None:
        from fmpy.fmi1 import FMICallException
        try:
            try:
                self.s.terminate()
            except FMICallException:
                pass  # e.g. never initialized: fmi2Terminate is not allowed there
            self.s.fmi2FreeInstance(self.s.component)
        finally:
            shutil.rmtree(self.dir, ignore_errors=True)
