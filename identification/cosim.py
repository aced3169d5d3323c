"""Co-simulation objectives: every evaluation runs the friction-law FMU (and, closed loop, the
mass FMU) through the project's master (:class:`fmus.master.Master`).

Two experiments:

* ``"prescribed"`` (:class:`CoSimObjective`): the law FMU is driven by the measured velocity.
  Communication points are the data samples; the output ``F`` is read with the input at the
  sample's velocity, and each step is taken with the input held at the step's midpoint
  velocity, which is exactly the in-process kernel's update. So on a prescribed-motion
  dataset the co-simulated force equals the numba kernel's to rounding, and both objectives
  give the same cost for the same parameters.
* ``"closed_loop"`` (:class:`ClosedLoopCoSimObjective`): mass FMU (``m dv/dt = u(t) - F``,
  ``u = u0 + u_amp sin(2 pi u_freq t)``) coupled with the law FMU by
  :meth:`Master.simulate`; the simulated friction force at the data instants is compared with
  the measured one. The friction then acts on the motion it produces (what a plant test
  measures), e.g. seed 001's open-loop drive ``u = 1.1 sin 5t``.

FMUs are built once per process (:func:`fmus.testing.built_fmus`) unless a folder is given;
one master stays open per objective (and per worker process) and is reset between runs.
"""
from __future__ import annotations

import os

import numpy as np

from friction.base import FrictionModel
from friction.dataset import Dataset

from .objectives import Objective, check_data

__all__ = ["CoSimObjective", "ClosedLoopCoSimObjective", "fmu_dir_for"]


def fmu_dir_for(laws, fmu_dir=None, native: bool = False) -> str:
    """Folder holding ``<law>.fmu`` (and ``mass.fmu``), or with ``native`` the native C FMUs
    ``<law>_native.fmu`` (``mass_native.fmu``): the given one, or built once per process."""
    from fmus.master import fmu_file
    if fmu_dir is not None:
        for law in laws:
            path = fmu_file(fmu_dir, law, native)
            if not os.path.exists(path):
                raise FileNotFoundError(f"{os.path.basename(path)} not found in {fmu_dir}; "
                                        f"build it with frictionlab build-fmus --out {fmu_dir}")
        return str(fmu_dir)
    names = tuple(sorted(set(laws)))
    if native:
        from fmus.testing import built_native_fmus
        return str(built_native_fmus(names))
    from fmus.testing import built_fmus
    return str(built_fmus(names))


def _fixed_parameters(model: FrictionModel, names) -> dict:
    """The model's parameters that are not identified, as Python values (options by name,
    unset twins ``None``); the master sets them in either FMU kind
    (:func:`fmus.master.fmu_values`)."""
    from fmus.master import law_parameters
    return law_parameters(model, exclude=set(names))


class _MasterHolder:
    """Lazily opened master; not pickled (each worker process opens its own)."""

    def __getstate__(self):
        d = dict(self.__dict__)
        d["_master"] = None
        for k in [k for k in d if k.startswith("_") and k not in ("_master",)]:
            del d[k]  # ctypes buffers and FMU handles belong to this process
        d["n_runs"] = 0
        return d

    def close(self):
        if getattr(self, "_master", None) is not None:
            self._master.close()
            self._master = None

    def __del__(self):  # pragma: no cover - best effort
        try:
            self.close()
        except Exception:
            pass


class CoSimObjective(_MasterHolder, Objective):
    """Prescribed-motion objective through the law FMU (see the module docstring).

    Parameters
    ----------
    model : FrictionModel
    data : Dataset
    names : list of str
    fmu_dir : path, optional
        Folder with ``<law>.fmu`` (``<law>_native.fmu`` with ``native``); default: built once
        per process.
    native : bool
        Run the native C FMU of the law (:mod:`fmus.native`) instead of the pythonfmu one:
        the same cost, without Python inside the FMU.
    """
    parallel_inside = False

    def __init__(self, model: FrictionModel, data: Dataset, names, fmu_dir=None,
                 native: bool = False):
        self.model = model
        self.data = check_data(data)
        self.names = list(names)
        self.native = bool(native)
        # resolved (built) here, once, so worker processes receive a ready folder
        self.fmu_dir = fmu_dir_for([model.name], fmu_dir, self.native)
        self._master = None
        self.n_runs = 0

    def _open(self):
        if self._master is None:
            from fmus.master import Master, fmu_file
            d = fmu_dir_for([self.model.name], self.fmu_dir, self.native)
            self._master = Master({"friction": fmu_file(d, self.model.name, self.native)}, [])
            inst = self._master.instances["friction"]
            self._inst = inst
            self._slave = inst.slave
            ins = ["v"] + [n for n in ("a", "load", "x") if n in self.model.extra_inputs]
            self._in_names = ins
            import ctypes
            self._in_vr = (ctypes.c_uint * len(ins))(*[inst.vars[n].valueReference for n in ins])
            self._in_buf = (ctypes.c_double * len(ins))()
            self._F_vr = (ctypes.c_uint * 1)(inst.vars["F"].valueReference)
            self._F_buf = (ctypes.c_double * 1)()
            self._loop = self._c_loop(inst)
        return self._master

    def _c_loop(self, inst):
        """The compiled drive of :mod:`fmus.master_loop` over this instance's buffers (the
        same calls as the Python loop of :meth:`_run`), or None (Python loop)."""
        from fmus import master_loop
        if self._master.loop == "python" or master_loop.library() is None:
            return None

        from types import SimpleNamespace
        # the instance's handle and functions, with the objective's buffers
        drive = SimpleNamespace(cv=inst.cv, raw_set=inst.raw_set, raw_step=inst.raw_step,
                                raw_get=inst.raw_get, in_vr=self._in_vr, in_buf=self._in_buf,
                                n_in=len(self._in_names), out_vr=self._F_vr,
                                out_buf=self._F_buf, n_out=1, gather=())
        return master_loop.CLoop([drive])

    def _run(self, x) -> np.ndarray:
        from fmus.master import FMUError
        self._open()
        inst, s = self._inst, self._slave
        d = self.data
        t = d.t
        cols = [d.v] + [getattr(d, n) for n in self._in_names[1:]]
        if any(c is None for c in cols):
            raise ValueError(f"{self.model.name} needs inputs {self._in_names} in the data")
        U = np.column_stack(cols)
        Um = 0.5 * (U[1:] + U[:-1])  # the kernel's midpoint inputs
        params = _fixed_parameters(self.model, self.names)
        params.update({n: float(v) for n, v in zip(self.names, x)})
        if self.n_runs:
            self._master._call(inst, "fmi2Reset", t[0], s.reset)
        self.n_runs += 1
        self._master._call(inst, "fmi2SetupExperiment", t[0], s.setupExperiment, None, t[0])
        self._master._set_values(inst, params, t[0])
        self._master._call(inst, "fmi2EnterInitializationMode", t[0], s.enterInitializationMode)
        self._master._call(inst, "fmi2ExitInitializationMode", t[0], s.exitInitializationMode)
        F = np.empty(t.size)
        if self._loop is not None:
            tc = np.ascontiguousarray(t, dtype=np.float64)
            Uc = np.ascontiguousarray(U, dtype=np.float64)
            Umc = np.ascontiguousarray(Um if Um.size else np.zeros((1, U.shape[1])),
                                       dtype=np.float64)
            if self._loop.prescribed(tc, Uc, Umc, F) >= 0:
                _, call, status, tk = self._loop.error()
                raise FMUError("friction", call, tk, status,
                               self._master.log.get("friction", ()))
            return F
        f_set, f_get, f_step, c = inst.f_set, inst.f_get, inst.f_step, inst.c
        n_in = len(self._in_names)
        ib, ivr, Fb, Fvr = self._in_buf, self._in_vr, self._F_buf, self._F_vr
        for k in range(t.size):
            for j in range(n_in):
                ib[j] = U[k, j]
            if f_set(c, ivr, n_in, ib) > 1:
                raise FMUError("friction", "fmi2SetReal", t[k], 3)
            if f_get(c, Fvr, 1, Fb) > 1:
                raise FMUError("friction", "fmi2GetReal", t[k], 3)
            F[k] = Fb[0]
            if k + 1 < t.size:
                for j in range(n_in):
                    ib[j] = Um[k, j]
                f_set(c, ivr, n_in, ib)
                st = f_step(c, t[k], t[k + 1] - t[k], 1)
                if st > 1:
                    raise FMUError("friction", "fmi2DoStep", t[k], st,
                                   self._master.log.get("friction", ()))
        return F

    def predict(self, X) -> np.ndarray:
        X = np.atleast_2d(np.asarray(X, float))
        out = np.empty((X.shape[0], len(self.data)))
        for i, x in enumerate(X):
            try:
                out[i] = self._run(x)
            except Exception:  # an FMU refusing a parameter set: infinite cost, not a crash
                out[i] = np.nan
                self.close()
        return out


class ClosedLoopCoSimObjective(_MasterHolder, Objective):
    """Closed-loop objective: mass FMU + law FMU co-simulated with :meth:`Master.simulate`.

    Parameters
    ----------
    model : FrictionModel
    data : Dataset
        Measured ``t`` (uniform, starting at 0), ``v`` and friction force ``F`` of the loop.
    names : list of str
    mass, u0, u_amp, u_freq, v0 : float
        The loop: mass [kg], drive ``u0 + u_amp sin(2 pi u_freq t)`` [N, Hz], initial speed.
    step : float, optional
        Communication step [s] (default: the data interval; must divide it).
    fmu_dir : path, optional
    native : bool
        Run the native C FMUs (``mass_native.fmu``, ``<law>_native.fmu``).
    """
    parallel_inside = False

    def __init__(self, model, data, names, *, mass, u_amp, u_freq, u0=0.0, v0=0.0, step=None,
                 fmu_dir=None, native: bool = False):
        self.model, self.data, self.names = model, check_data(data), list(names)
        self.native = bool(native)
        self.loop = dict(m=float(mass), u0=float(u0), u_amp=float(u_amp),
                         u_freq=float(u_freq), v0=float(v0))
        dt = np.diff(data.t)
        if not np.allclose(dt, dt[0], rtol=1e-9, atol=0) or abs(data.t[0]) > 1e-12:
            raise ValueError("closed-loop data must be uniformly sampled from t = 0")
        self.dt = float(dt[0])
        self.step = self.dt if step is None else float(step)
        ratio = self.dt / self.step
        if abs(ratio - round(ratio)) > 1e-9:
            raise ValueError(f"step = {self.step!r} must divide the data interval {self.dt!r}")
        self.every = int(round(ratio))
        self.fmu_dir = fmu_dir_for([model.name, "mass"], fmu_dir, self.native)
        self._master = None

    def _open(self):
        if self._master is None:
            from fmus.master import Master, fmu_file
            from fmus.proof import mass_connections
            d = fmu_dir_for([self.model.name, "mass"], self.fmu_dir, self.native)
            fm = {"mass": fmu_file(d, "mass", self.native),
                  "friction": fmu_file(d, self.model.name, self.native)}
            self._master = Master(fm, mass_connections(self.model.name),
                                  parameters={"mass": dict(self.loop), "friction": {}},
                                  record=["mass.v", "friction.F"])
        return self._master

    def predict(self, X) -> np.ndarray:
        X = np.atleast_2d(np.asarray(X, float))
        stop = float(self.data.t[-1])
        n_steps = int(round(stop / self.step))
        out = np.empty((X.shape[0], len(self.data)))
        for i, x in enumerate(X):
            try:
                m = self._open()
                params = _fixed_parameters(self.model, self.names)
                params.update({n: float(v) for n, v in zip(self.names, x)})
                m.parameters["friction"] = params
                res = m.simulate(stop_time=n_steps * self.step, step_size=self.step,
                                 progress=False)
                out[i] = res["friction.F"][::self.every][:len(self.data)]
            except Exception:
                out[i] = np.nan
                self.close()
        return out

    def simulate_loop(self, x) -> np.ndarray:
        """The co-simulated result array for one parameter vector (for plots/tests)."""
        m = self._open()
        params = _fixed_parameters(self.model, self.names)
        params.update({n: float(v) for n, v in zip(self.names, np.asarray(x, float))})
        m.parameters["friction"] = params
        n_steps = int(round(float(self.data.t[-1]) / self.step))
        return m.simulate(stop_time=n_steps * self.step, step_size=self.step, progress=False)
