"""The FMI status shim on its own: a minimal pythonfmu slave that logs at each status level.

Checks the shim's contract independently of the frictionlab slaves: the call returns the
worst of the inner status and the statuses logged during that call (reset per call), the
importer's loggingOn / categories filter non-error messages, error messages always arrive,
and pythonfmu's own fmi2Discard for a refused step passes through unchanged.
"""
from __future__ import annotations

import shutil
import textwrap
import zipfile

import fmpy
import pytest
from fmpy.fmi1 import FMICallException

from fmus import status_shim

try:
    status_shim.shim_library()
except status_shim.ShimUnavailable as exc:  # pragma: no cover - no C compiler here
    pytest.skip(f"no status shim: {exc}", allow_module_level=True)

PROBE = textwrap.dedent('''
    from pythonfmu import Fmi2Causality, Fmi2Slave, Real
    from pythonfmu.enums import Fmi2Status

    # pythonfmu <= 0.7 (NTNU-IHB/PythonFMU#228): keep the module alive across instances
    _keep = globals().setdefault("_keep_refs", [])
    _keep.append(globals())


    class shimprobe(Fmi2Slave):
        """u selects what do_step does: 1 warns, 2 logs an error, 3 raises, 4 refuses."""

        def __init__(self, **kwargs):
            super().__init__(**kwargs)
            self.u = 0.0
            self.y = 0.0
            self.register_variable(Real("u", causality=Fmi2Causality.input))
            self.register_variable(Real("y", causality=Fmi2Causality.output))

        def do_step(self, current_time, step_size):
            if self.u == 1.0:
                self.log("probe warning", Fmi2Status.warning)
            elif self.u == 2.0:
                self.log("probe error", Fmi2Status.error)
            elif self.u == 3.0:
                raise RuntimeError("probe exception")
            elif self.u == 4.0:
                return False
            self.y = self.u
            return True
''')


@pytest.fixture(scope="module")
def probe_fmu(tmp_path_factory):
    from pythonfmu.builder import FmuBuilder
    d = tmp_path_factory.mktemp("shimprobe")
    script = d / "shimprobe.py"
    script.write_text(PROBE)
    fmu = FmuBuilder.build_FMU(script, dest=d)
    status_shim.install(fmu)
    return fmu


class Probe:
    def __init__(self, path, logging_on):
        from fmpy.fmi2 import FMU2Slave, fmi2CallbackFunctions, fmi2CallbackLoggerTYPE, \
            fmi2CallbackAllocateMemoryTYPE, fmi2CallbackFreeMemoryTYPE, calloc, free
        md = fmpy.read_model_description(str(path))
        self.dir = fmpy.extract(str(path))
        self.vr = {v.name: v.valueReference for v in md.modelVariables}
        self.messages = []

        def logger(env, inst, status, cat, msg):
            self.messages.append((status, (cat or b"").decode(), msg.decode()))
        cb = fmi2CallbackFunctions()
        cb.logger = fmi2CallbackLoggerTYPE(logger)
        cb.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        cb.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        self._cb = (cb, logger)
        self.s = FMU2Slave(guid=md.guid, unzipDirectory=self.dir,
                           modelIdentifier=md.coSimulation.modelIdentifier,
                           instanceName="probe")
        self.s.instantiate(callbacks=cb, loggingOn=logging_on)
        self.s.setupExperiment(startTime=0.0)
        self.s.enterInitializationMode()
        self.s.exitInitializationMode()
        self.t = 0.0

    def step(self, u):
        """Set u, step; returns the fmi2DoStep status."""
        self.s.setReal([self.vr["u"]], [u])
        try:
            status = self.s.fmi2DoStep(self.s.component, self.t, 0.1, 1)
        except FMICallException as exc:
            status = exc.status
        self.t += 0.1
        return status

    def close(self):
        try:
            self.s.fmi2FreeInstance(self.s.component)
        finally:
            shutil.rmtree(self.dir, ignore_errors=True)


def test_install_puts_the_shim_in_front(probe_fmu):
    with zipfile.ZipFile(probe_fmu) as z:
        names = set(z.namelist())
    assert {"binaries/linux64/shimprobe.so", "binaries/linux64/shimprobe_pythonfmu.so"} <= names
    try:  # win64 too when MinGW-w64 is installed (tests/test_fmu_shim_win64.py)
        win64 = status_shim.shim_library("win64").read_bytes()
    except status_shim.ShimUnavailable:
        assert "binaries/win64/shimprobe_pythonfmu.dll" not in names
    else:
        with zipfile.ZipFile(probe_fmu) as z:
            assert z.read("binaries/win64/shimprobe.dll") == win64
        assert "binaries/win64/shimprobe_pythonfmu.dll" in names
    with pytest.raises(ValueError, match="already"):
        status_shim.install(probe_fmu)


def test_call_status_is_the_worst_logged_during_that_call(probe_fmu):
    p = Probe(probe_fmu, logging_on=True)
    try:
        assert p.step(0.0) == 0
        assert p.step(1.0) == 1            # fmi2Warning: a warning was logged
        assert p.step(0.0) == 0            # reset per call
        assert p.step(2.0) == 3            # fmi2Error: an error was logged, do_step True
        assert p.step(0.0) == 0
        assert p.step(4.0) == 2            # pythonfmu's fmi2Discard passes through
        assert p.step(5.0) == 0 and p.s.getReal([p.vr["y"]]) == [5.0]
        assert [(st, m) for st, _, m in p.messages] == [(1, "probe warning"),
                                                         (3, "probe error")]
        # (u = 3, an exception, would give pythonfmu's fmi2Fatal, but pythonfmu 0.7 then
        # leaves the interpreter corrupt: a later garbage collection segfaults the test
        # process, with or without the shim. Hence our slaves never raise.)
    finally:
        p.close()


def test_logging_off_forwards_errors_only(probe_fmu):
    p = Probe(probe_fmu, logging_on=False)
    try:
        assert p.step(1.0) == 1            # the status is kept, the message is filtered
        assert p.step(2.0) == 3
        assert [(st, m) for st, _, m in p.messages] == [(3, "probe error")]
    finally:
        p.close()


def test_debug_logging_categories_filter_non_error_messages(probe_fmu):
    p = Probe(probe_fmu, logging_on=True)
    try:
        p.s.setDebugLogging(True, ["logStatusError"])
        assert p.step(1.0) == 1 and p.step(2.0) == 3
        assert [m for _, _, m in p.messages] == ["probe error"]
        p.s.setDebugLogging(True, ["logStatusWarning"])
        assert p.step(1.0) == 1
        assert p.messages[-1][1:] == ("logStatusWarning", "probe warning")
        p.s.setDebugLogging(False, [])
        assert p.step(1.0) == 1 and len(p.messages) == 2
    finally:
        p.close()
