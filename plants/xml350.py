"""XML-350 ultra-precision linear motor stage (seed 003) with its XPS-D position loop.

Plant (seed 003 Eq. 1): ``M x'' = f_e - f_r`` with ``M = 11.8 kg``, ``f_e = K_f i`` from
an ironless PMLSM (27.5 N/A) whose current loop is a 400 Hz first-order lag, and ``f_r``
the friction law (default: the paper's final LuGre of Table I, Lorentzian Stribeck curve,
offset ``b``). A 1 nm encoder quantises the measured position; the controller samples at
10 kHz and holds its output (ZOH).

Controller: the state-dependent PID of Eq. (15) (or the linear PID) in acceleration units
with acceleration feedforward, plus optionally the LuGre feedforward of Eq. (16),
``u_FF = LuGre_hat(v_d) / M``; current command ``i_cmd = M u / K_f``. The reference is
the S-curve point-to-point move of the paper (250 mm/s, 4000 mm/s^2; 100 um or 1 um).

The feedforward path is timed for the actuator (:class:`TrajectoryBlock`, default
``ff_mode="invert"``): the acceleration feedforward passes through the inverse of the
400 Hz current-loop lag and the ZOH's half sample, and the LuGre feedforward is evaluated
on the desired velocity ``Ts/2 + tau`` ahead. Without that (``ff_mode="none"``, the
literal Eqs. 14/16) the current loop's lag of the acceleration feedforward, not friction,
dominates the tracking error (jerk x tau ~ 0.3 m/s^2 vs ~0.08 m/s^2 of friction) and the
LuGre feedforward removes only a few percent of it - at odds with the paper's 92 %.

Two forms:

* :class:`XML350` - the closed loop as one plant (monolithic reference and fast stepper;
  a compiled kernel, :mod:`plants._xml350_kernel`, runs the same scheme for LuGre laws);
* :class:`XML350Mechanics` - the stage alone (input ``i_cmd`` [A], outputs position and
  velocity) so the loop can be assembled from separate steppers/FMUs with
  :class:`plants.controllers.StateDependentPID`, :class:`plants.controllers.LuGreFeedforward`,
  a :class:`TrajectoryBlock` and a friction component (:func:`loop_parts`);
  :func:`plants.studies.xml350.run_assembled` connects them with a Gauss-Seidel master
  and reproduces :class:`XML350` to round-off (friction inside the mechanics) or converges
  to it as the exchanges per control period grow (friction as its own component).

Stability note: with the nominal linear PID (Kp = 3e6 /s^2, Kd = 800 /s) the position
loop crosses over near 290 Hz with about 10 deg of phase margin before any lag; a
first-order 400 Hz current loop adds ~36 deg of lag there, so the LINEAR PID with a 400 Hz
current loop is unstable (discrete closed-loop spectral radius 1.02, see
:func:`plants.studies.xml350.loop_spectral_radius`). The paper's
compensation task uses the SD-PID, whose gains near the target (x0.34 Kp) keep the loop
stable with the 400 Hz current loop; this module uses it by default. The identification
experiments (linear PID) therefore run with a faster current loop (``f_current`` 2 kHz,
see :mod:`plants.experiments`), consistent with the paper's remark that the current
dynamics are negligible for the position loop.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from friction import make_model
from friction.base import FrictionModel, param

from .base import Experiment, Plant, PlantParams
from .components import Mass
from .controllers import (DiscreteBlock, DiscreteStepper, LuGreFeedforward, PID, PIDParams)
from .motor import LinearMotor
from .sensors import quantize
from .sources import SCurve

__all__ = ["XML350Params", "XML350", "XML350Mechanics", "TrajectoryBlock", "xml350_friction",
           "loop_parts"]



def xml350_friction(**overrides) -> FrictionModel:
    """The paper's final identified LuGre model of the XML-350 (Table I, refinement step,
    "Final" column): Fs = 1.1 N, Fc = 0.95 N, sigma2 = 15.62 kg/s, vs = 1e-5 m/s,
    sigma0 = 11.02e6 N/m, sigma1 = 1.46e3 kg/s, b = 0.01 N, Lorentzian Stribeck curve."""
    kw = dict(Fs=1.1, Fc=0.95, sigma2=15.62, vs=1e-5, sigma0=11.02e6, sigma1=1.46e3, b=0.01,
              shape="lorentzian")
    kw.update(overrides)
    return make_model("lugre", **kw)


@dataclass(frozen=True)
class XML350Params(PlantParams):
    """XML-350 stage and XPS-D controller parameters (seed 003 numbers as defaults)."""
    M: float = param(11.8, "kg", "moving mass", lower=0, lower_open=True)
    Kf: float = param(27.5, "N/A", "motor force constant", lower=0, lower_open=True)
    f_current: float = param(400.0, "Hz", "current-loop bandwidth", lower=0, lower_open=True)
    resolution: float = param(1e-9, "m", "encoder resolution (quantisation step)", lower=0)
    Ts: float = param(1e-4, "s", "controller sample time (10 kHz)", lower=0, lower_open=True)
    M_ctrl: float = param(11.8, "kg", "mass the controller uses to convert acceleration "
                          "to force (and in u_FF = f_r/M)", lower=0, lower_open=True)
    Kp: float = param(3e6, "1/s^2", "PID proportional gain (acceleration units)", lower=0)
    Ki: float = param(10e6, "1/s^3", "PID integral gain", lower=0)
    Kd: float = param(800.0, "1/s", "PID derivative gain", lower=0)
    alpha_p: float = param(-0.66, "1", "SD-PID factor of Kp (Eq. 15)", lower=-1)
    alpha_i: float = param(9.0, "1", "SD-PID factor of Ki (Eq. 15)", lower=-1)
    alpha_d: float = param(0.0, "1", "SD-PID factor of Kd (Eq. 15)", lower=-1)
    beta: float = param(4e-4, "m", "SD-PID distance scale (Eq. 15)", lower=0, lower_open=True)

    def motor(self) -> LinearMotor:
        """The PMLSM with its current loop."""
        return LinearMotor(Kf=self.Kf, f_current=self.f_current)

    def stage(self) -> Mass:
        """The moving mass ``M`` (Eq. 1: ``M x'' = f_e - f_r``)."""
        return Mass(m=self.M)

    def pid(self, state_dependent: bool = True) -> PID:
        a = (self.alpha_p, self.alpha_i, self.alpha_d) if state_dependent else (0.0, 0.0, 0.0)
        return PID(PIDParams(Kp=self.Kp, Ki=self.Ki, Kd=self.Kd, alpha_p=a[0], alpha_i=a[1],
                             alpha_d=a[2], beta=self.beta, Ts=self.Ts))


class TrajectoryBlock(DiscreteBlock):
    """Reference generator of the XPS-D as a discrete block.

    Outputs the reference ``x_d, v_d, a_d`` at the sample instant (for the feedback), the
    target ``x_f``, and the feedforward signals timed for the actuator (``ff_mode``):

    * ``"invert"`` (default): ``a_ff = a_d + tau da_d/dt`` at ``t + Ts/2`` (inverse of the
      first-order current loop, ``tau = 1 / (2 pi f_current)``, and of the ZOH's half
      sample); ``v_ff, x_ff`` (for the friction feedforward) at ``t + Ts/2 + tau``;
    * ``"lead"``: all feedforward signals at ``t + Ts/2 + tau`` (time advance);
    * ``"none"``: the literal Eqs. (14)/(16), everything at ``t``.

    Why: with a 400 Hz current loop the untimed acceleration feedforward lags by ~0.4 ms,
    an acceleration error of jerk x tau (~0.3 m/s^2 on the 100 um move), four times the
    friction disturbance (~0.08 m/s^2); the paper's 92 % reduction by friction
    compensation alone implies the XPS feedforward path does not suffer that lag.
    """
    output_names = ("x_d", "v_d", "a_d", "x_f", "x_ff", "v_ff", "a_ff")
    MODES = ("invert", "lead", "none")

    def __init__(self, traj=None, target: float | None = None, sample_time: float = 1e-4,
                 f_current: float = 400.0, ff_mode: str = "invert"):
        if ff_mode not in self.MODES:
            raise ValueError(f"ff_mode must be one of {self.MODES}, got {ff_mode!r}")
        self.traj = traj if traj is not None else SCurve(1e-4, t0=1e-3)
        if target is None:
            target = getattr(self.traj, "target", None)
            if target is None:
                target = float(self.traj(getattr(self.traj, "duration", 1e9))[0])
        self.target = float(target)
        self.sample_time = float(sample_time)
        self.tau = 1.0 / (2 * math.pi * f_current)
        self.ff_mode = ff_mode

    def step(self, t, state, inputs):
        x, v, a = self.traj(t)
        out = {"x_d": x, "v_d": v, "a_d": a, "x_f": self.target}
        if self.ff_mode == "none":
            out.update(x_ff=x, v_ff=v, a_ff=a)
            return state, out
        Ts, tau = self.sample_time, self.tau
        x_l, v_l, a_l = self.traj(t + 0.5 * Ts + tau)
        if self.ff_mode == "invert":
            th = t + 0.5 * Ts
            da = (self.traj(th + 0.5 * Ts)[2] - self.traj(th - 0.5 * Ts)[2]) / Ts
            a_l = self.traj(th)[2] + tau * da
        out.update(x_ff=x_l, v_ff=v_l, a_ff=a_l)
        return state, out

    def sample(self, times) -> np.ndarray:
        """Outputs at many instants at once: array (N, 7) in ``output_names`` order."""
        times = np.asarray(times, dtype=float)
        try:
            cols = self._sample_vectorised(times)
        except (TypeError, ValueError):  # a trajectory that only takes scalars
            rows = [self.step(float(t), None, {})[1] for t in times]
            cols = [np.array([r[n] for r in rows]) for n in self.output_names]
        return np.column_stack([np.broadcast_to(np.asarray(c, float), times.shape)
                                for c in cols])

    def _sample_vectorised(self, t):
        x, v, a = (np.asarray(c, float) for c in self.traj(t))
        if x.shape != t.shape:
            raise ValueError("trajectory is not vectorised")
        xf = np.full(t.shape, self.target)
        if self.ff_mode == "none":
            return [x, v, a, xf, x, v, a]
        Ts, tau = self.sample_time, self.tau
        x_l, v_l, a_l = self.traj(t + 0.5 * Ts + tau)
        if self.ff_mode == "invert":
            th = t + 0.5 * Ts
            da = (self.traj(th + 0.5 * Ts)[2] - self.traj(th - 0.5 * Ts)[2]) / Ts
            a_l = self.traj(th)[2] + tau * da
        return [x, v, a, xf, x_l, v_l, a_l]


_OPTIONS = dict(distance=1e-4, vmax=0.25, amax=4.0, jerk=None, t_move=1e-3,
                controller="sdpid", compensation=True, compensator=None, trajectory=None,
                open_loop=False, ff_mode="invert", engine="auto")


class _SubstepFromCurrentLoop:
    @property
    def max_substep(self) -> float:
        """2.5e-5 s, or less for a fast current loop (Heun is stable for h w_c < 2)."""
        return min(2.5e-5, 1.0 / (2 * math.pi * self.params.f_current))


class XML350(_SubstepFromCurrentLoop, Plant):
    """XML-350 stage in closed loop with the XPS-D SD-PID and the LuGre feedforward.

    Experiment options
    ------------------
    distance : float
        S-curve move length [m] (1e-4 or 1e-6 in the paper).
    vmax, amax, jerk : float
        S-curve limits [m/s, m/s^2, m/s^3] (jerk default: amax / 5 ms).
    t_move : float
        Start of the move [s].
    controller : {"sdpid", "pid"}
        State-dependent PID (Eq. 15) or the linear PID.
    compensation : bool
        Add the LuGre feedforward (Eq. 16).
    compensator : FrictionModel, optional
        The feedforward's friction law (default: a copy of the plant's law, i.e. a
        perfectly identified model).
    trajectory : callable, optional
        ``traj(t) -> (x, v, a)`` replacing the S-curve (e.g. :mod:`plants.sources`);
        target ``x_f`` = its ``target`` attribute or its final position.
    open_loop : bool
        No feedback: ``i_cmd = M a_ff / K_f`` (+ friction feedforward); seed 003's PRBS
        test (acceleration input).
    ff_mode : {"invert", "lead", "none"}
        Timing of the feedforward signals, see :class:`TrajectoryBlock`.
    engine : {"auto", "python", "numba"}
        Fast method's engine: ``numba`` runs the loop in one compiled kernel
        (:mod:`plants._xml350_kernel`; classic LuGre friction and compensator, output step
        = control period, no external inputs; same scheme and results to ~1e-13); ``auto``
        uses it when eligible (and the run has >= 100 samples); ``python`` is the generic
        stepper (what ``stepper()`` and the FMUs run).
    """
    name = "xml350"
    Params = XML350Params
    main_output = "x"
    data_rate = 10_000.0
    default_experiment = Experiment(start=0.0, stop=0.06, step=1e-4)
    state_names = ("x", "v", "i")
    state_scale = (1e-6, 1e-4, 1e-2)
    output_names = ("x", "v", "a", "x_meas", "x_d", "v_d", "a_d", "e", "i", "u", "u_ff")
    discrete_names = ("i_cmd", "u", "u_sd", "u_ff", "x_d", "v_d", "a_d", "x_meas")
    control_rate = 10_000.0
    options = _OPTIONS
    signals = {"x": ("m", "stage position"), "v": ("m/s", "stage velocity"),
               "a": ("m/s^2", "stage acceleration"), "x_meas": ("m", "encoder position"),
               "x_d": ("m", "desired position"), "v_d": ("m/s", "desired velocity"),
               "a_d": ("m/s^2", "desired acceleration"), "e": ("m", "tracking error x_d - x"),
               "i": ("A", "motor current"), "u": ("m/s^2", "acceleration command"),
               "u_ff": ("m/s^2", "LuGre feedforward"), "F": ("N", "friction force"),
               "F_friction": ("N", "friction force input (external friction)")}

    @classmethod
    def default_friction(cls) -> FrictionModel:
        return xml350_friction()

    # -- configuration of one run ---------------------------------------------------------------
    def _blocks(self):
        blocks = self.cache.get("blocks")
        if blocks is not None:
            return blocks
        o, p = self.opts, self.params
        if o["controller"] not in ("sdpid", "pid"):
            raise ValueError(f"controller must be 'sdpid' or 'pid', got {o['controller']!r}")
        traj = o["trajectory"]
        if traj is None:
            traj = SCurve(o["distance"], o["vmax"], o["amax"], o["jerk"], t0=o["t_move"])
        ref = TrajectoryBlock(traj, sample_time=p.Ts, f_current=p.f_current,
                              ff_mode=o["ff_mode"])
        pid = p.pid(state_dependent=o["controller"] == "sdpid")
        ff = None
        if o["compensation"]:
            law = o["compensator"]
            if law is None:
                law = self.friction if self.friction is not None else self.default_friction()
            ff = LuGreFeedforward(law, mass=p.M_ctrl, sample_time=p.Ts)
        blocks = dict(traj=traj, ref=ref, pid=pid, ff=ff, motor=p.motor(), stage=p.stage())
        self.cache["blocks"] = blocks
        return blocks

    def _layout(self):
        b = self._blocks()
        n0 = len(self.discrete_names)
        npid = len(b["pid"].state_names)
        nff = 0 if b["ff"] is None else len(b["ff"].state_names)
        return n0, npid, nff

    # -- plant contract ------------------------------------------------------------------------
    def initial_state(self):
        x0 = float(self._blocks()["traj"](0.0)[0]) if self.opts["trajectory"] is not None \
            else 0.0
        return np.array([x0, 0.0, 0.0])

    def initial_discrete(self):
        b = self._blocks()
        n0, npid, nff = self._layout()
        d = np.zeros(n0 + npid + nff)
        d[n0:n0 + npid] = b["pid"].initial_state()
        if b["ff"] is not None:
            d[n0 + npid:] = b["ff"].initial_state()
        return d

    def derivatives(self, t, s, d, F, u):
        b = self._blocks()
        motor = b["motor"]
        if self.external_friction:
            F = u["F_friction"]
        return np.array([s[1], b["stage"].acceleration(motor.force(s[2]) - F),
                         motor.current_derivative(s[2], d[0])])

    def contact(self, t, s, d, u):
        return s[0], s[1], None

    def discrete_update(self, t, s, d, u):
        b = self._blocks()
        p = self.params
        n0, npid, nff = self._layout()
        _, r = b["ref"].step(t, None, {})
        x_d, v_d, a_d = r["x_d"], r["v_d"], r["a_d"]
        x_meas = quantize(float(s[0]), p.resolution)
        new = d.copy()
        u_ff = 0.0
        if b["ff"] is not None:
            st, out = b["ff"].step(t, d[n0 + npid:], {"x_d": r["x_ff"], "v_d": r["v_ff"],
                                                      "a_d": r["a_ff"]})
            new[n0 + npid:] = st
            u_ff = out["u_ff"]
        if self.opts["open_loop"]:
            u_sd = r["a_ff"]
        else:
            st, out = b["pid"].step(t, d[n0:n0 + npid], {"x_d": x_d, "v_d": v_d,
                                                         "a_d": r["a_ff"], "x": x_meas,
                                                         "x_f": r["x_f"]})
            new[n0:n0 + npid] = st
            u_sd = out["u_sd"]
        u_tot = u_sd + u_ff
        new[:n0] = (p.M_ctrl * u_tot / p.Kf, u_tot, u_sd, u_ff, x_d, v_d, a_d, x_meas)
        return new

    def output(self, t, s, d, F, u):
        b = self._blocks()
        Fr = u["F_friction"] if self.external_friction else F
        return {"x": s[0], "v": s[1], "a": b["stage"].acceleration(b["motor"].force(s[2]) - Fr),
                "x_meas": d[7], "x_d": d[4], "v_d": d[5], "a_d": d[6], "e": d[4] - s[0], "i": s[2],
                "u": d[1], "u_ff": d[3]}

    # -- fast path ----------------------------------------------------------------------------
    def _numba_eligible(self, exp, inputs) -> str | None:
        """Why the compiled kernel cannot run this experiment (None: it can)."""
        from friction.lugre import LuGre
        if self.external_friction or inputs is not None:
            return "external inputs"
        if type(self.friction) is not LuGre:
            return f"friction law {type(self.friction).__name__} (kernel inlines LuGre)"
        ff = self._blocks()["ff"]
        if ff is not None and type(ff.law) is not LuGre:
            return f"compensator law {type(ff.law).__name__}"
        Ts = self.params.Ts
        if abs(exp.step - Ts) > 1e-9 * Ts:
            return "output step differs from the control period"
        return None

    def _simulate_fast(self, exp, progress, inputs, substep):
        engine = self.opts["engine"]
        if engine not in ("auto", "python", "numba"):
            raise ValueError(f"engine must be 'auto', 'python' or 'numba', got {engine!r}")
        times = exp.times()
        why = self._numba_eligible(exp, inputs) if engine != "python" else "python"
        if engine == "numba" and why is not None:
            raise ValueError(f"engine='numba' cannot run this experiment: {why}")
        if why is not None or (engine == "auto" and times.size < 100):
            return super()._simulate_fast(exp, progress, inputs, substep)
        from ._xml350_kernel import OUT_COLS, xml350_loop
        from .base import structured

        b, p = self._blocks(), self.params
        ref = b["ref"].sample(times)
        ff = b["ff"]
        pars = np.array([p.M, p.Kf, 2.0 * math.pi * p.f_current, p.resolution, p.Ts,
                         p.M_ctrl, b["pid"].params.Kp, b["pid"].params.Ki, b["pid"].params.Kd,
                         b["pid"].params.alpha_p, b["pid"].params.alpha_i,
                         b["pid"].params.alpha_d, b["pid"].params.beta,
                         float(bool(self.opts["open_loop"])), b["motor"].i_max,
                         float(ff is not None)])
        h = float(substep or self.max_substep)
        nsub = max(1, int(math.ceil(p.Ts / h - 1e-9)))
        out = np.empty((times.size, len(OUT_COLS)))
        theta_ff = ff.law.theta if ff is not None else self.friction.theta
        s0 = np.asarray(self.initial_state(), dtype=float)
        xml350_loop(times, ref, self.friction.theta, theta_ff, pars, nsub, s0, out)
        if not np.all(np.isfinite(out)):
            raise FloatingPointError(f"{self.name}: the fast integrator diverged "
                                     f"(substep {p.Ts / nsub:.3g} s)")
        if progress is not None:
            progress(times.size, "numba kernel")
        cols = dict(zip(OUT_COLS, out.T))
        return structured({"time": times, **{n: cols[n] for n in self.all_output_names}})

    # -- conveniences --------------------------------------------------------------------------
    def move_window(self) -> tuple[float, float]:
        """(start, end) of the S-curve move [s]."""
        tr = self._blocks()["traj"]
        t0 = getattr(tr, "t0", 0.0)
        return t0, t0 + getattr(tr, "duration", 0.0)


class XML350Mechanics(_SubstepFromCurrentLoop, Plant):
    """The XML-350 stage alone: motor with current loop, mass, friction, encoder.

    Input ``i_cmd`` [A] (current command); outputs ``x, x_meas, v, a, i`` and the thrust
    ``f_e`` [N]. With ``external_friction=True`` the friction force is the input
    ``F_friction``. Use with :func:`plants.studies.xml350.run_assembled` or as the stage FMU.
    """
    name = "xml350_mechanics"
    Params = XML350Params
    main_output = "x"
    data_rate = 10_000.0
    default_experiment = Experiment(start=0.0, stop=0.06, step=1e-4)
    state_names = ("x", "v", "i")
    state_scale = (1e-6, 1e-4, 1e-2)
    input_names = ("i_cmd",)
    output_names = ("x", "x_meas", "v", "a", "i", "f_e")
    signals = {**XML350.signals, "i_cmd": ("A", "current command"),
               "f_e": ("N", "motor thrust")}

    @classmethod
    def default_friction(cls) -> FrictionModel:
        return xml350_friction()

    def initial_state(self):
        return np.zeros(3)

    def build_parts(self) -> tuple[LinearMotor, Mass]:
        """(motor with its current loop, moving mass)."""
        return self.params.motor(), self.params.stage()

    def derivatives(self, t, s, d, F, u):
        motor, stage = self.parts
        if self.external_friction:
            F = u["F_friction"]
        return np.array([s[1], stage.acceleration(motor.force(s[2]) - F),
                         motor.current_derivative(s[2], u["i_cmd"])])

    def contact(self, t, s, d, u):
        return s[0], s[1], None

    def output(self, t, s, d, F, u):
        p = self.params
        f_e = p.Kf * s[2]
        Fr = u["F_friction"] if self.external_friction else F
        return {"x": s[0], "x_meas": quantize(float(s[0]), p.resolution), "v": s[1],
                "a": self.parts[1].acceleration(f_e - Fr), "i": s[2], "f_e": f_e}


def loop_parts(*, distance: float = 1e-4, compensation: bool = True,
               friction: FrictionModel | None = None, compensator: FrictionModel | None = None,
               params: XML350Params | None = None, controller: str = "sdpid",
               t_move: float = 1e-3, ff_mode: str = "invert",
               separate_friction: bool = False) -> dict:
    """The XML-350 loop's components as separate steppers (what the FMU build wraps).

    Returns
    -------
    dict
        ``"trajectory"``: :class:`TrajectoryBlock` stepper (outputs ``x_d, v_d, a_d, x_f,
        x_ff, v_ff, a_ff``); ``"controller"``: (SD-)PID stepper (inputs ``x_d, v_d, a_d,
        x, x_f, u_ff``; output ``u`` [m/s^2]); ``"feedforward"`` (when ``compensation``):
        LuGre feedforward stepper (inputs ``x_d, v_d, a_d``; output ``u_ff``);
        ``"mechanics"``: :class:`XML350Mechanics` stepper (input ``i_cmd`` [A], plus
        ``F_friction`` [N] when ``separate_friction``); ``"friction"`` (when
        ``separate_friction``): :class:`plants.law_stepper.FrictionComponent` (input ``v``,
        output ``F``); ``"params"``: the :class:`XML350Params` (``i_cmd = M_ctrl u / Kf``).
    """
    from .law_stepper import FrictionComponent

    p = params or XML350Params()
    law = friction or xml350_friction()
    Ts = p.Ts
    traj = TrajectoryBlock(SCurve(distance, t0=t_move), sample_time=Ts, f_current=p.f_current,
                           ff_mode=ff_mode)
    parts = {"trajectory": DiscreteStepper(traj),
             "controller": DiscreteStepper(p.pid(state_dependent=controller == "sdpid")),
             "params": p}
    if compensation:
        parts["feedforward"] = DiscreteStepper(LuGreFeedforward(compensator or law,
                                                                p.M_ctrl, Ts))
    if separate_friction:
        parts["mechanics"] = XML350Mechanics(external_friction=True, params=p).stepper()
        parts["friction"] = FrictionComponent(law)
    else:
        parts["mechanics"] = XML350Mechanics(law, params=p).stepper()
    return parts
