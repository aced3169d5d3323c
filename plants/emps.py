"""EMPS: the Electro-Mechanical Positioning System of the nonlinearbenchmark.org benchmark
(Janot, Gautier, Brunot), a prismatic axis (DC motor, ball screw, carriage) under its 1 kHz
position controller, with any friction law of :mod:`friction`.

Axis (:class:`EMPSAxis`)::

    M dv/dt = gtau u_applied - F_friction(v, z, x),     dq/dt = v

``gtau`` [N/V] turns the controller's voltage ``u`` (the benchmark's ``vir``) into motor
force; ``u_applied`` is the voltage of the last sample held, reaching the carriage ``delay``
seconds after that sample (``0 <= delay <= Ts``; the benchmark's Simulink model holds it one
whole sample, ``delay = Ts``).

Controller (:class:`EMPS`, the axis in its loop; numbers from the benchmark files)::

    qf(k)  = (qm(k) + qm(k-1)) / 2                       two-sample average
    dqf(k) = (qf(k) - qf(k-1)) / Ts                      backward difference
    u(k)   = kv (kp (qg(k) - e_pos(k)) - dqf(k)) + pulse_gain * pulse(k),  |u| <= u_max

with ``e_pos = qm`` (``position_feedback="sample"``, what the recorded ``vir`` obeys: the law
with ``qm`` reproduces the measured voltage to 0.004 V RMS, with ``qf`` it leaves 1.7 V, see
:func:`plants.studies.emps.controller_evidence`) or ``e_pos = qf``
(``position_feedback="average"``, the loop as the data README writes it, which its
published figures come from). ``pulse`` is the PULSES file's square wave: a voltage added at
the controller output (it is inside the recorded ``vir``), not a force on the carriage.

Both plants take their signals as arrays sampled at ``Ts`` from ``t = 0`` (experiment
options ``reference``, ``pulses``, ``voltage``) and an ``initial`` condition consistent with
a record that starts in motion (:func:`initial_from_record`). The fast method runs one
compiled loop (:mod:`plants._emps_kernel`, any law through its numba kernel); the generic
plant contract (reference integrator, :meth:`plants.base.Plant.stepper`) holds the same
equations.

The published inverse-dynamic-model baseline (IDIM-LS) is
``M ddq + Fv dq + Fc sign(dq) + OF = gtau vir``: :data:`IDIM_LS` and
:func:`idim_friction` (the static map of :mod:`friction.stribeck` with ``Fs = Fc``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from friction import make_model
from friction.base import METHODS, FrictionModel, param

from .base import Experiment, Plant, PlantParams, structured

__all__ = ["EMPSParams", "EMPS", "EMPSAxis", "IDIM_LS", "BENCHMARK_GAINS", "idim_friction",
           "initial_from_record", "law_start_state", "force_error", "position_metrics"]

#: the benchmark's drive gain and controller gains (DATA_EMPS.mat: gtau, kp, kv)
BENCHMARK_GAINS = {"gtau": 35.15065188248547, "kp": 160.18, "kv": 243.45}
#: published IDIM-LS parameters (data README): M [kg], Fv [N s/m], Fc [N], OF [N]
IDIM_LS = {"M": 95.1089, "Fv": 203.5034, "Fc": 20.3935, "OF": -3.1648}


def idim_friction(Fv: float = IDIM_LS["Fv"], Fc: float = IDIM_LS["Fc"],
                  OF: float = IDIM_LS["OF"]) -> FrictionModel:
    """The IDIM-LS friction ``Fv v + Fc sign(v) + OF`` as a law: the static Stribeck map
    with no Stribeck bump (``Fs = Fc``), viscous ``sigma2 = Fv`` and offset ``b = OF``."""
    return make_model("stribeck", Fc=Fc, Fs=Fc, sigma2=Fv, b=OF)


@dataclass(frozen=True)
class EMPSParams(PlantParams):
    """EMPS axis, drive and position controller (defaults: the benchmark's numbers, the
    IDIM-LS mass and the Simulink model's one sample of delay)."""
    M: float = param(IDIM_LS["M"], "kg", "moving mass (carriage, screw and rotor reflected "
                     "to the carriage)", lower=0, lower_open=True, search=(60.0, 130.0))
    gtau: float = param(BENCHMARK_GAINS["gtau"], "N/V", "drive gain: motor force per volt of "
                        "controller output", lower=0, lower_open=True)
    kp: float = param(BENCHMARK_GAINS["kp"], "1/s", "position-loop gain", lower=0)
    kv: float = param(BENCHMARK_GAINS["kv"], "V.s/m", "velocity-loop gain (volts per m/s of "
                      "velocity error; the benchmark lists it as 1/s)", lower=0)
    Ts: float = param(1e-3, "s", "controller sample time (1 kHz)", lower=0, lower_open=True)
    u_max: float = param(10.0, "V", "saturation of the controller output", lower=0,
                         lower_open=True)
    delay: float = param(1e-3, "s", "time from a position sample to the motor force of the "
                         "voltage computed from it (0 <= delay <= Ts)", lower=0,
                         search=(0.0, 1e-3))
    pulse_gain: float = param(1.0, "V", "voltage added at the controller output per unit of "
                              "the PULSES file's pulse signal", search=(0.9, 1.1))

    def _check_relations(self):
        from friction._validation import ParameterError
        if self.delay > self.Ts * (1 + 1e-12):
            raise ParameterError(f"delay = {self.delay!r} is out of bounds: must be <= Ts = "
                                 f"{self.Ts!r} [s]")


def initial_from_record(qm, u, Ts: float = 1e-3) -> np.ndarray:
    """Initial condition of a run that starts where a record starts (in motion):
    ``(q0, v0, q(-1), q(-2), u(-1))`` with ``v0`` the first backward difference of the
    measured position ``qm`` [m], the two earlier positions on that velocity, and the
    voltage before the first sample taken as the first recorded ``u`` [V]."""
    qm = np.asarray(qm, float)
    if qm.size < 2:
        raise ValueError(f"qm has {qm.size} samples: need at least 2 for an initial velocity")
    v0 = (qm[1] - qm[0]) / Ts
    return np.array([qm[0], v0, qm[0] - v0 * Ts, qm[0] - 2 * v0 * Ts, float(np.ravel(u)[0])])


def law_start_state(law: FrictionModel, v0: float) -> np.ndarray:
    """State of ``law`` sliding steadily at ``v0`` [m/s] (zeros at rest); an
    :class:`diagnosis.effect_law.EffectLaw` keeps its time state."""
    base = getattr(law, "base", None)
    if base is not None and hasattr(law, "time0"):
        return np.concatenate([law_start_state(base, v0), [law.time0]])
    if not law.state_names or v0 == 0.0:
        return np.asarray(law.initial_state(), float)
    try:
        s = np.asarray(law.steady_state_state(v0), float)
    except (NotImplementedError, AttributeError, ValueError, ArithmeticError):
        return np.asarray(law.initial_state(), float)
    return s if np.all(np.isfinite(s)) else np.asarray(law.initial_state(), float)


def force_error(F_sim, F_meas) -> float:
    """The benchmark's criterion: relative error ``||F_sim - F_meas|| / ||F_meas||`` [-]."""
    F_sim, F_meas = np.asarray(F_sim, float), np.asarray(F_meas, float)
    return float(np.linalg.norm(F_sim - F_meas) / np.linalg.norm(F_meas))


def position_metrics(q_sim, q_meas) -> dict:
    """Position RMSE [mm] and R^2 [-] of a simulated against a measured position [m]."""
    q_sim, q_meas = np.asarray(q_sim, float), np.asarray(q_meas, float)
    r = q_sim - q_meas
    sst = float(np.sum((q_meas - q_meas.mean()) ** 2))
    return {"rmse_mm": 1e3 * float(np.sqrt(np.mean(r ** 2))),
            "r2": 1.0 - float(np.sum(r ** 2)) / sst if sst > 0 else float("nan")}


_SIGNALS = {"x": ("m", "carriage position"), "v": ("m/s", "carriage velocity"),
            "a": ("m/s^2", "carriage acceleration"),
            "qg": ("m", "reference position"), "e": ("m", "tracking error qg - x"),
            "u": ("V", "controller output (voltage vir) computed at the sample"),
            "F_motor": ("N", "motor force gtau * u of the voltage computed at the sample"),
            "u_cmd": ("V", "voltage command (open loop)"),
            "qg_in": ("m", "reference position input (without the reference option)"),
            "pulse_in": ("", "pulse signal input (without the pulses option)"),
            "F": ("N", "friction force"),
            "F_friction": ("N", "friction force input (external friction)")}


class _EMPSBase(Plant):
    """What the closed loop and the axis share: parameters, law, kernel call."""
    Params = EMPSParams
    main_output = "x"
    data_rate = 1000.0
    default_experiment = Experiment(start=0.0, stop=1.0, step=1e-3)
    state_names = ("x", "v")
    state_scale = (1e-6, 1e-4)
    control_rate = 1000.0
    signals = _SIGNALS

    @classmethod
    def default_friction(cls) -> FrictionModel:
        return idim_friction()

    @property
    def max_substep(self) -> float:
        """A tenth of the sample time (the generic stepper; the kernel uses ``substeps``)."""
        return self.params.Ts / 10.0

    def _init(self) -> np.ndarray:
        init = self.opts.get("initial")
        if init is None:
            return np.array([self._x0(), 0.0, self._x0(), self._x0(), 0.0])
        init = np.asarray(init, float).ravel()
        if init.size != 5 or not np.all(np.isfinite(init)):
            raise ValueError("initial must be 5 finite numbers (q0 [m], v0 [m/s], q(-1), "
                             "q(-2) [m], u(-1) [V]); see plants.emps.initial_from_record")
        return init

    def _x0(self) -> float:
        return 0.0

    def _array(self, name, n=None, required=True):
        arr = self.opts.get(name)
        if arr is None:
            if required:
                raise ValueError(f"{self.name}: experiment option {name!r} (an array sampled "
                                 f"at Ts from t = 0) is required")
            return None
        arr = np.ascontiguousarray(np.asarray(arr, float).ravel())
        if n is not None and arr.size < n:
            raise ValueError(f"{self.name}: option {name!r} has {arr.size} samples, the run "
                             f"needs {n} (stop time / Ts + 1)")
        bad = np.flatnonzero(~np.isfinite(arr))
        if bad.size:
            raise ValueError(f"{self.name}: option {name!r}[{bad[0]}] is not finite")
        return arr

    @staticmethod
    def _at(arr, t, Ts) -> float:
        k = min(max(int(round(t / Ts)), 0), arr.size - 1)
        return float(arr[k])

    # -- plant contract (generic stepper and reference integrator) --------------------------
    def initial_state(self):
        init = self._init()
        return np.array([init[0], init[1]])

    def contact(self, t, s, d, u):
        return s[0], s[1], None

    def _applied(self, t, d) -> float:
        """Voltage acting at time t: the previous sample's until ``delay`` after a sample."""
        # d: [u, u_prev, x_prev, xf_prev, t_k, ...]; a whole sample of delay holds the
        # previous voltage up to and including the period's end
        p = self.params
        if p.delay >= p.Ts * (1 - 1e-9) or (t - d[4]) < p.delay * (1 - 1e-9):
            return d[1]
        return d[0]

    def derivatives(self, t, s, d, F, u):
        p = self.params
        if self.external_friction:
            F = u["F_friction"]
        return np.array([s[1], (p.gtau * self._applied(t, d) - F) / p.M])

    # -- fast path --------------------------------------------------------------------------
    def _kernel_inputs(self, n):  # pragma: no cover - per plant
        raise NotImplementedError

    def _simulate_fast(self, exp, progress, inputs, substep):
        p = self.params
        if self.external_friction or inputs is not None \
                or abs(exp.step - p.Ts) > 1e-9 * p.Ts or abs(exp.start) > 0:
            return super()._simulate_fast(exp, progress, inputs, substep)
        from ._emps_kernel import OUT_COLS, emps_loop
        times = exp.times()
        n = times.size
        closed, qg, u_in, pulse, err_avg = self._kernel_inputs(n)
        # the kernel runs qg.size periods: every array exactly n samples long
        qg, pulse = qg[:n].copy(), pulse[:n].copy()
        u_in = u_in[:n].copy() if not closed else np.zeros(n)
        init = self._init()
        law = self.friction
        nsub = int(self.opts.get("substeps") or 10)
        if substep:
            nsub = max(1, int(math.ceil(p.Ts / substep - 1e-9)))
        pars = np.array([p.M, p.gtau, p.kp, p.kv, p.Ts, p.u_max, p.delay, p.pulse_gain,
                         float(err_avg), float(closed)])
        z0 = law_start_state(law, float(init[1]))
        out = np.empty((n, len(OUT_COLS)))
        emps_loop(law._kernel, np.asarray(law.theta, float), METHODS["exact"],
                  np.ascontiguousarray(z0, dtype=np.float64), pars, qg, u_in, pulse, init,
                  nsub, out)
        if not np.all(np.isfinite(out)):
            raise FloatingPointError(f"{self.name}: the simulation diverged (substep "
                                     f"{p.Ts / nsub:.3g} s)")
        if progress is not None:
            progress(n, "numba kernel")
        cols = dict(zip(OUT_COLS, out.T))
        return structured({"time": times, **self._columns(cols, qg, n)})


_COMMON_OPTIONS = dict(initial=None, substeps=10)


class EMPS(_EMPSBase):
    """The EMPS axis in its 1 kHz position loop, driven by the reference position.

    Experiment options
    ------------------
    reference : array
        Reference position ``qg`` [m] at the control instants ``k Ts``; without it the
        inputs ``qg_in`` [m] and ``pulse_in`` [-] are sampled at each control instant (the
        plant FMU: a sample instant is reached at the end of the communication step that
        ends there, so the inputs held over that step are the sample's values).
    pulses : array, optional
        The PULSES file's pulse signal (0 or 5), added at the controller output as
        ``pulse_gain * pulse`` [V].
    position_feedback : {"sample", "average"}
        Position error on the sampled position ``qm(k)`` (what the recorded ``vir`` obeys)
        or on the two-sample average ``qf(k)`` (the data README's loop).
    initial : array of 5, optional
        ``(q0, v0, q(-1), q(-2), u(-1))`` (:func:`initial_from_record`); default: at rest
        on the first reference sample.
    substeps : int
        Heun substeps per control period of the fast method.

    Outputs ``x, v, a, qg, e, u, F_motor`` (and ``F``, the friction force); ``u`` and
    ``F_motor`` are the voltage and motor force computed at each sample (the benchmark's
    compared signal ``gtau * vir``).
    """
    name = "emps"
    #: the trajectory diagnosis may compare any output (the voltage ``u`` is the benchmark's
    #: criterion); the reference is named ``qg``, not ``x_ref``, so a compared channel is
    #: normalised by its own spread
    any_signal = True
    input_names = ("qg_in", "pulse_in")
    output_names = ("x", "v", "a", "qg", "e", "u", "F_motor")
    discrete_names = ("u", "u_prev", "x_prev", "xf_prev", "t_k", "qg")
    options = dict(reference=None, pulses=None, position_feedback="sample", **_COMMON_OPTIONS)

    def _x0(self) -> float:
        ref = self.opts.get("reference")
        return 0.0 if ref is None else float(np.ravel(ref)[0])

    def _simulate_fast(self, exp, progress, inputs, substep):
        if self.opts.get("reference") is None:  # driven through the inputs: generic stepper
            return Plant._simulate_fast(self, exp, progress, inputs, substep)
        return super()._simulate_fast(exp, progress, inputs, substep)

    def _feedback_average(self) -> bool:
        fb = self.opts["position_feedback"]
        if fb not in ("sample", "average"):
            raise ValueError(f"position_feedback must be 'sample' or 'average', got {fb!r}")
        return fb == "average"

    def _kernel_inputs(self, n):
        qg = self._array("reference", n)
        pulse = self._array("pulses", n, required=False)
        if pulse is None:
            pulse = np.zeros(n)
        return True, qg, np.zeros(1), pulse, self._feedback_average()

    def _columns(self, cols, qg, n):
        p = self.params
        return {"x": cols["q"], "v": cols["v"], "a": cols["a"], "qg": qg[:n],
                "e": qg[:n] - cols["q"], "u": cols["u"], "F_motor": p.gtau * cols["u"],
                **({} if self.external_friction else {"F": cols["F"]})}

    def initial_discrete(self):
        init = self._init()
        return np.array([init[4], init[4], init[2], 0.5 * (init[2] + init[3]), -1.0,
                         self._x0()])

    def discrete_update(self, t, s, d, u):
        p = self.params
        qg = self._array("reference", required=False)
        pulses = self._array("pulses", required=False)
        x = float(s[0])
        xf = 0.5 * (x + d[2])
        dxf = (xf - d[3]) / p.Ts
        # the arrays of an in-process run, else the inputs (a plant FMU)
        ref = self._at(qg, t, p.Ts) if qg is not None else float(u["qg_in"])
        e = ref - (xf if self._feedback_average() else x)
        v_out = p.kv * (p.kp * e - dxf)
        if pulses is not None:
            v_out += p.pulse_gain * self._at(pulses, t, p.Ts)
        elif qg is None:
            v_out += p.pulse_gain * float(u["pulse_in"])
        v_out = min(max(v_out, -p.u_max), p.u_max)
        return np.array([v_out, d[0], x, xf, t, ref])

    def output(self, t, s, d, F, u):
        p = self.params
        Fr = u["F_friction"] if self.external_friction else F
        return {"x": s[0], "v": s[1], "a": (p.gtau * self._applied(t, d) - Fr) / p.M,
                "qg": d[5], "e": d[5] - s[0], "u": d[0], "F_motor": p.gtau * d[0]}


class EMPSAxis(_EMPSBase):
    """The EMPS axis alone (open loop): the measured voltage in, the position out.

    Experiment options
    ------------------
    voltage : array, optional
        Voltage ``u`` [V] at the control instants (the recorded ``vir``, pulses included);
        without it the input ``u_cmd`` [V] is sampled at each control instant (the plant
        FMU: the value held over the communication step that ends at the sample instant).
    initial : array of 5, optional
        As :class:`EMPS` (default: at rest at 0).
    substeps : int
        Heun substeps per control period of the fast method.

    Outputs ``x, v, a, u, F_motor`` (and ``F``).
    """
    name = "emps_axis"
    input_names = ("u_cmd",)
    output_names = ("x", "v", "a", "u", "F_motor")
    discrete_names = ("u", "u_prev", "x_prev", "xf_prev", "t_k")
    options = dict(voltage=None, **_COMMON_OPTIONS)

    def _kernel_inputs(self, n):
        u_in = self._array("voltage", n)
        return False, np.zeros(n), u_in, np.zeros(n), False

    def _simulate_fast(self, exp, progress, inputs, substep):
        if self.opts.get("voltage") is None:  # driven through the input: generic stepper
            return Plant._simulate_fast(self, exp, progress, inputs, substep)
        return super()._simulate_fast(exp, progress, inputs, substep)

    def _columns(self, cols, qg, n):
        p = self.params
        return {"x": cols["q"], "v": cols["v"], "a": cols["a"], "u": cols["u"],
                "F_motor": p.gtau * cols["u"],
                **({} if self.external_friction else {"F": cols["F"]})}

    def initial_discrete(self):
        init = self._init()
        return np.array([init[4], init[4], init[2], 0.5 * (init[2] + init[3]), -1.0])

    def discrete_update(self, t, s, d, u):
        volt = self._array("voltage", required=False)
        val = self._at(volt, t, self.params.Ts) if volt is not None else float(u["u_cmd"])
        return np.array([val, d[0], float(s[0]), 0.0, t])

    def output(self, t, s, d, F, u):
        p = self.params
        Fr = u["F_friction"] if self.external_friction else F
        return {"x": s[0], "v": s[1], "a": (p.gtau * self._applied(t, d) - Fr) / p.M,
                "u": d[0], "F_motor": p.gtau * d[0]}
