"""A Model Exchange master: the continuous states of several FMUs integrated together.

fmpy's ``simulate_fmu`` integrates one Model Exchange FMU and holds its inputs over each
output interval; it cannot couple two. :class:`MEMaster` couples several ME FMUs (a plant or
mass and a friction law) by connections, as the co-simulation :class:`fmus.master.Master`
does, but hands all their states to one implicit solver (``scipy.integrate.solve_ivp``,
Radau by default): the stiff bristle state is integrated with the plant's motion, so no
communication step holds a stiff force (what Jacobi co-simulation hosts cannot avoid).

At every right-hand-side evaluation the master sets the time and the states of every FMU,
the external inputs (functions of time, e.g. a measured velocity interpolated linearly),
then propagates the connections (as many passes as there are FMUs, enough for any
feedthrough chain without an algebraic loop) and reads the derivatives. Event indicators
(``load_lugre``'s |v| - vc) end an integration segment where they change sign; the FMUs go
through event mode and the solver restarts there, so no step straddles the jump.

>>> from fmus.me_master import MEMaster                                  # doctest: +SKIP
>>> m = MEMaster({"mass": "mass_native.fmu", "law": "lugre_native.fmu"},
...              [("mass.v", "law.v"), ("law.F", "mass.F_friction")],
...              parameters={"mass": {"m": 1.0, "u_amp": 2.0}})          # doctest: +SKIP
>>> res = m.simulate(np.linspace(0, 1, 1001))                          # doctest: +SKIP
"""
from __future__ import annotations

import ctypes
import shutil
from typing import Callable, Iterable, Mapping

import numpy as np

__all__ = ["MEMaster"]


class _Unit:
    """One ME FMU instance: fmpy ``FMU2Model`` with its value references and buffers."""

    def __init__(self, name: str, path: str, logger):
        import fmpy
        from fmpy.fmi2 import FMU2Model
        self.name = name
        self.md = fmpy.read_model_description(str(path))
        if self.md.modelExchange is None:
            raise ValueError(f"{name}: {path} has no Model Exchange interface")
        self.dir = fmpy.extract(str(path))
        self.vars = {v.name: v for v in self.md.modelVariables}
        self.fmu = FMU2Model(guid=self.md.guid, unzipDirectory=self.dir,
                             modelIdentifier=self.md.modelExchange.modelIdentifier,
                             instanceName=name)
        self.fmu.instantiate(callbacks=logger, loggingOn=False)
        self.nx = len(self.md.derivatives)
        self.nz = int(self.md.numberOfEventIndicators or 0)
        self.x = (ctypes.c_double * max(self.nx, 1))()
        self.dx = (ctypes.c_double * max(self.nx, 1))()
        self.z = (ctypes.c_double * max(self.nz, 1))()

    def vr(self, var: str) -> int:
        try:
            return self.vars[var].valueReference
        except KeyError:
            raise KeyError(f"{self.name} has no variable {var!r}") from None

    def set_start(self, var: str, value) -> None:
        v = self.vars.get(var)
        if v is None:
            raise KeyError(f"{self.name} has no variable {var!r}")
        if v.type == "Boolean":
            self.fmu.setBoolean([v.valueReference], [bool(value)])
        elif v.type in ("Integer", "Enumeration"):
            self.fmu.setInteger([v.valueReference], [int(value)])
        else:
            self.fmu.setReal([v.valueReference], [float(value)])

    def close(self) -> None:
        try:
            self.fmu.terminate()
        except Exception:  # noqa: BLE001 - closing after a failure: free regardless
            pass
        self.fmu.freeInstance()
        shutil.rmtree(self.dir, ignore_errors=True)


class MEMaster:
    """Couple Model Exchange FMUs and integrate their states with one implicit solver.

    Parameters
    ----------
    fmus : mapping
        Instance name -> FMU path (each with a Model Exchange interface).
    connections : iterable of (str, str)
        ``("src.output", "dst.input")`` pairs, propagated in this order.
    parameters : mapping, optional
        Instance name -> {variable: start value} (Booleans and Enumerations by their type).
    inputs : mapping, optional
        ``"inst.input"`` -> function of time [s] giving the input's value.
    """

    def __init__(self, fmus: Mapping[str, str], connections: Iterable = (), *,
                 parameters: Mapping[str, Mapping] | None = None,
                 inputs: Mapping[str, Callable[[float], float]] | None = None):
        from fmpy.fmi2 import (fmi2CallbackFunctions, fmi2CallbackLoggerTYPE,
                               fmi2CallbackAllocateMemoryTYPE, fmi2CallbackFreeMemoryTYPE,
                               calloc, free)
        self.messages: list[tuple[str, int, str]] = []

        def logger(env, inst, status, cat, msg):
            self.messages.append((inst.decode(), status, msg.decode()))
        cb = fmi2CallbackFunctions()
        cb.logger = fmi2CallbackLoggerTYPE(logger)
        cb.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        cb.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        self._cb = (cb, logger)
        self.units: dict[str, _Unit] = {}
        try:
            for name, path in fmus.items():
                self.units[name] = _Unit(name, path, cb)
            self.links = []
            for src, dst in connections:
                (si, sv), (di, dv) = src.split(".", 1), dst.split(".", 1)
                s, d = self.units[si], self.units[di]
                if d.vars[dv].causality != "input":
                    raise ValueError(f"{dst} is not an input")
                self.links.append((s.fmu, s.vr(sv), d.fmu, d.vr(dv)))
            self.inputs = []
            for ref, fn in (inputs or {}).items():
                inst, var = ref.split(".", 1)
                u = self.units[inst]
                self.inputs.append((u.fmu, u.vr(var), fn))
            for name, u in self.units.items():
                u.fmu.setupExperiment(startTime=0.0)
                for var, value in (parameters or {}).get(name, {}).items():
                    u.set_start(var, value)
            self.passes = max(1, len(self.units))
        except Exception:
            self.close()
            raise

    # -- the coupled system ----------------------------------------------------------------
    def _apply(self, t: float) -> None:
        for fmu, vr, fn in self.inputs:
            fmu.setReal([vr], [float(fn(t))])
        for _ in range(self.passes):
            for sf, svr, df, dvr in self.links:
                df.setReal([dvr], sf.getReal([svr]))

    def _set_states(self, t: float, y) -> None:
        k = 0
        for u in self.units.values():
            u.fmu.setTime(t)
            if u.nx:
                for j in range(u.nx):
                    u.x[j] = y[k + j]
                u.fmu.setContinuousStates(u.x, u.nx)
                k += u.nx
        self._apply(t)

    def _rhs(self, t, y):
        self._set_states(t, y)
        out = np.empty(self.nx)
        k = 0
        for u in self.units.values():
            if u.nx:
                u.fmu.getDerivatives(u.dx, u.nx)
                out[k:k + u.nx] = u.dx[:u.nx]
                k += u.nx
        return out

    def _indicators(self, t, y) -> np.ndarray:
        self._set_states(t, y)
        out = []
        for u in self.units.values():
            if u.nz:
                u.fmu.getEventIndicators(u.z, u.nz)
                out += list(u.z[:u.nz])
        return np.asarray(out)

    def _event_mode(self) -> None:
        for u in self.units.values():
            u.fmu.enterEventMode()
            u.fmu.newDiscreteStates()
            u.fmu.enterContinuousTimeMode()

    def simulate(self, t_eval, *, record: Iterable[str] = (), rtol: float = 1e-8,
                 method: str = "Radau", max_step: float | None = None,
                 max_events: int = 10000) -> dict:
        """Integrate from ``t_eval[0]`` to ``t_eval[-1]``; returns ``{"time": t_eval,
        "inst.var": values at t_eval}`` for the ``record`` variables.

        Parameters
        ----------
        t_eval : array_like
            Output times [s], increasing.
        record : iterable of str
            ``"inst.var"`` names to record.
        rtol : float
            Relative tolerance; the absolute tolerance of each state is ``rtol`` times its
            nominal (``fmi2GetNominalsOfContinuousStates``).
        method : str
            ``solve_ivp`` method (an implicit one for stiff friction: Radau, BDF, LSODA).
        max_step : float, optional
            Largest solver step [s] (e.g. the sample interval of interpolated inputs).
        max_events : int
            Most state events before the run is stopped: a motion that slides along an
            event surface (|v| = vc held by both regimes, a Filippov sliding motion) would
            otherwise restart the solver for ever.

        Raises
        ------
        RuntimeError
            The solver failed, or the events exceed ``max_events`` (the message gives the
            time: the motion slides along a switching surface there).
        """
        from scipy.integrate import solve_ivp
        t_eval = np.asarray(t_eval, dtype=float).ravel()
        if t_eval.size < 2 or not np.all(np.isfinite(t_eval)):
            raise ValueError("t_eval: need at least 2 finite output times [s]")
        if np.any(np.diff(t_eval) <= 0):
            i = int(np.argmax(np.diff(t_eval) <= 0))
            raise ValueError(f"t_eval must be strictly increasing: t_eval[{i + 1}] = "
                             f"{t_eval[i + 1]!r} <= t_eval[{i}] = {t_eval[i]!r}")
        for u in self.units.values():
            u.fmu.setTime(float(t_eval[0]))
            u.fmu.enterInitializationMode()
        self._apply(float(t_eval[0]))
        for u in self.units.values():
            u.fmu.exitInitializationMode()
        self._event_mode()
        y0, nominal = [], []
        for u in self.units.values():
            if u.nx:
                u.fmu.getContinuousStates(u.x, u.nx)
                y0 += list(u.x[:u.nx])
                nom = (ctypes.c_double * u.nx)()
                u.fmu.getNominalsOfContinuousStates(nom, u.nx)
                nominal += list(nom)
        self.nx = len(y0)
        rec = [(r, self.units[r.split(".", 1)[0]], r.split(".", 1)[1]) for r in record]
        out = {r: np.empty(t_eval.size) for r, _, _ in rec}
        atol = rtol * np.asarray(nominal, dtype=float)
        nz = sum(u.nz for u in self.units.values())
        events = []
        for j in range(nz):
            def ev(t, y, j=j):
                return self._indicators(t, y)[j]
            ev.terminal = True
            events.append(ev)
        y = np.asarray(y0, dtype=float)
        t0, k, n_events = float(t_eval[0]), 0, 0
        kw = {} if max_step is None else {"max_step": max_step}
        while True:
            pending = t_eval[k:]
            sol = solve_ivp(self._rhs, (t0, float(t_eval[-1])), y, method=method,
                            t_eval=pending, rtol=rtol, atol=atol, events=events or None,
                            dense_output=False, **kw)
            if sol.status == -1:
                raise RuntimeError(f"the Model Exchange integration failed at t = {t0:g} s: "
                                   f"{sol.message}")
            for i, ti in enumerate(sol.t):
                self._set_states(float(ti), sol.y[:, i])
                for r, u, var in rec:
                    out[r][k + i] = u.fmu.getReal([u.vr(var)])[0]
            k += len(sol.t)
            if sol.status == 0 or k >= t_eval.size:
                break
            # an event: restart just past it, after the FMUs' event mode
            t_ev = min(float(te[0]) for te in sol.t_events if len(te))
            n_events += 1
            if n_events > max_events:
                raise RuntimeError(
                    f"{n_events} state events by t = {t_ev:.9g} s: the motion slides along a "
                    f"switching surface (e.g. |v| = vc); this master does not follow sliding "
                    f"motions - use the co-simulation master or the plant's reference")
            y = sol.y_events[[len(te) > 0 for te in sol.t_events].index(True)][0]
            # restart just past the root: where the indicators' signs have changed (they may
            # depend on time through the inputs only), else a hair past the root
            before = np.sign(self._indicators(t_ev - 1e-9 * max(1.0, abs(t_ev)), y))
            eps = 1e-12 * max(1.0, abs(t_ev))
            t0 = t_ev + eps
            while eps < 1e-6 * max(1.0, abs(t_ev)):
                if np.any(np.sign(self._indicators(t_ev + eps, y)) != before):
                    t0 = t_ev + eps
                    break
                eps *= 2.0
            self._set_states(t0, y)
            self._event_mode()
            while k < t_eval.size and t_eval[k] <= t0:
                self._set_states(float(t_eval[k]), y)
                for r, u, var in rec:
                    out[r][k] = u.fmu.getReal([u.vr(var)])[0]
                k += 1
            if k >= t_eval.size:
                break
        return {"time": t_eval, **out}

    def close(self) -> None:
        for u in self.units.values():
            u.close()
        self.units = {}

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
