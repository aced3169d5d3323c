"""Discrete controllers of seed 003: PID with acceleration feedforward, the state-dependent
PID of Eq. (15) and the LuGre friction feedforward of Eq. (16).

Each controller is a *pure* discrete block: ``step(t, state, inputs) -> (state, outputs)``
runs one sample, with all memory in the explicit ``state`` vector, so a plant can keep it
among its held discrete values (reference and fast integrators then agree exactly on the
discrete part). :class:`DiscreteStepper` wraps a block in the FMU-facing stepper interface
(``input_names``, ``output_names``, ``parameter_names``, ``reset``, ``set_inputs``,
``do_step``, ``outputs``) so the XML-350 loop can be assembled from separate FMUs.

Control law (seed 003 Eq. 14, acceleration units [m/s^2])::

    u_SD = k_i(x) I + k_p(x) (x_d - x) + k_d(x) (v_d - v) + a_d,   I = sum Ts (x_d - x)
    k_j(x) = (1 + alpha_j beta / (|x_f - x| + beta)) K_j,          j in {p, i, d}   (Eq. 15)
    u = u_SD + u_FF,   u_FF = f_r_hat / M,   f_r_hat = LuGre(v_d)                   (Eq. 16)

``v_d - v`` is the backward difference of the position error (encoder-based servo: the
measured velocity is a backward difference, and differencing the error keeps the reference
velocity on the same half-sample lag); the integral is the rectangle sum including the
current sample.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from friction.base import FrictionModel, FrictionParams, param

from .law_stepper import FrictionStep

__all__ = ["PIDParams", "PID", "StateDependentPID", "LuGreFeedforward", "DiscreteBlock",
           "DiscreteStepper"]


class DiscreteBlock:
    """Base of pure discrete blocks (see the module docstring).

    Subclasses set ``input_names``, ``output_names``, ``state_names``, ``sample_time``
    [s] and implement ``initial_state()`` and ``step(t, state, inputs)``.
    """
    input_names: tuple[str, ...] = ()
    output_names: tuple[str, ...] = ()
    state_names: tuple[str, ...] = ()
    sample_time: float = 1e-4

    def initial_state(self) -> np.ndarray:
        return np.zeros(len(self.state_names))

    def step(self, t: float, state: np.ndarray, inputs: dict) -> tuple[np.ndarray, dict]:
        """One sample: ``(new_state, outputs)``, the outputs a dict by ``output_names``.

        Parameters
        ----------
        t : float
            Sample time [s].
        state : ndarray
            The block's state before the sample (``state_names``).
        inputs : dict
            Input values by name (``input_names``), SI units.
        """
        raise NotImplementedError  # pragma: no cover - abstract

    @property
    def parameter_names(self) -> tuple[str, ...]:
        """Numeric parameters of the block (unset optional ones left out)."""
        p = getattr(self, "params", None)
        if p is None:
            return ()
        return tuple(n for n in p.numeric_names() if getattr(p, n) is not None)


@dataclass(frozen=True)
class PIDParams(FrictionParams):
    """Gains of the acceleration-unit PID and its state-dependent extension (seed 003)."""
    Kp: float = param(3e6, "1/s^2", "proportional gain (acceleration per position error)",
                      lower=0)
    Ki: float = param(10e6, "1/s^3", "integral gain", lower=0)
    Kd: float = param(800.0, "1/s", "derivative gain (acceleration per velocity error)",
                      lower=0)
    alpha_p: float = param(0.0, "1", "state-dependent factor of Kp (Eq. 15)", lower=-1)
    alpha_i: float = param(0.0, "1", "state-dependent factor of Ki (Eq. 15)", lower=-1)
    alpha_d: float = param(0.0, "1", "state-dependent factor of Kd (Eq. 15)", lower=-1)
    beta: float = param(4e-4, "m", "distance scale of the state-dependent gains (Eq. 15)",
                        lower=0, lower_open=True)
    accel_ff: float = param(1.0, "1", "weight of the acceleration feedforward a_d", lower=0,
                            upper=1)
    Ts: float = param(1e-4, "s", "sample time (seed 003: 10 kHz)", lower=0, lower_open=True)


class PID(DiscreteBlock):
    """Linear PID in acceleration units with acceleration feedforward (seed 003 Eq. 14,
    alpha_j = 0).

    Inputs: ``x_d, v_d, a_d`` (reference [m, m/s, m/s^2]), ``x`` (measured position [m]),
    ``x_f`` (target [m], used by the state-dependent gains), ``u_ff`` (added feedforward
    [m/s^2]). Outputs: ``u`` (total acceleration command [m/s^2]), ``u_sd`` (feedback +
    acceleration feedforward), ``e`` (position error [m]).

    Parameters
    ----------
    params : PIDParams, optional
        The gains and sample time; default their defaults.
    **gains
        Parameter values replacing those of ``params`` (validated; unknown: TypeError).
    """
    input_names = ("x_d", "v_d", "a_d", "x", "x_f", "u_ff")
    output_names = ("u", "u_sd", "e")
    state_names = ("integral", "e_prev", "started")

    def __init__(self, params: PIDParams | None = None, **gains):
        if params is None:
            params = PIDParams(**gains)
        elif gains:
            params = params.replace(**gains)
        self.params = params
        self.sample_time = params.Ts

    def gains(self, x, x_f) -> tuple[float, float, float]:
        """Gains (k_p, k_i, k_d) at measured position ``x`` and target ``x_f`` (Eq. 15).

        Parameters
        ----------
        x : float
            Measured position [m].
        x_f : float
            Target position of the move [m].
        """
        p = self.params
        w = p.beta / (abs(x_f - x) + p.beta)
        return ((1 + p.alpha_p * w) * p.Kp, (1 + p.alpha_i * w) * p.Ki,
                (1 + p.alpha_d * w) * p.Kd)

    def step(self, t, state, inputs):
        p = self.params
        x = inputs["x"]
        e = inputs["x_d"] - x
        integral = state[0] + p.Ts * e
        # velocity error (v_d - v) as the backward difference of the position error: the
        # encoder velocity and the reference velocity then carry the same half-sample lag
        de = (e - state[1]) / p.Ts if state[2] > 0 else inputs["v_d"]
        kp, ki, kd = self.gains(x, inputs.get("x_f", inputs["x_d"]))
        u_sd = ki * integral + kp * e + kd * de + p.accel_ff * inputs["a_d"]
        u = u_sd + inputs.get("u_ff", 0.0)
        return np.array([integral, e, 1.0]), {"u": u, "u_sd": u_sd, "e": e}


class StateDependentPID(PID):
    """State-dependent PID of seed 003 Eq. (15) with the paper's empirical factors:
    beta = 4e-4 m, alpha_p = -0.66, alpha_i = 9, alpha_d = 0 (gains x0.34, x10, x1 at the
    target).

    Parameters
    ----------
    params : PIDParams, optional
        The gains, their state-dependent factors and the sample time.
    **gains
        Parameter values replacing those of ``params`` (validated; unknown: TypeError).
    """

    def __init__(self, params: PIDParams | None = None, **gains):
        defaults = dict(alpha_p=-0.66, alpha_i=9.0, alpha_d=0.0, beta=4e-4)
        if params is None:
            params, gains = PIDParams(**{**defaults, **gains}), {}
        super().__init__(params, **gains)


class LuGreFeedforward(DiscreteBlock):
    """Friction feedforward of seed 003 Eq. (16): ``u_FF = f_r_hat / M`` with
    ``f_r_hat = law(v_d)`` simulated along the desired velocity.

    Parameters
    ----------
    law : FrictionModel
        The compensator's friction law (any law of :mod:`friction`; its parameters may
        differ from the plant's friction to study mismatch).
    mass : float
        Mass used to convert force to acceleration [kg] (seed 003: 11.8 kg).
    sample_time : float
        Sample time [s].

    Inputs ``v_d`` [m/s] (and ``x_d``, ``a_d`` for laws that need them); outputs ``u_ff``
    [m/s^2] and ``F_ff`` [N]. The law's state advances over each sample period with its
    stable exact update between the previous and the current desired velocity.
    """
    input_names = ("x_d", "v_d", "a_d")
    output_names = ("u_ff", "F_ff")

    def __init__(self, law: FrictionModel, mass: float = 11.8, sample_time: float = 1e-4):
        if not mass > 0:
            raise ValueError(f"mass = {mass!r} is out of bounds: must be > 0 [kg]")
        if not sample_time > 0:
            raise ValueError(f"sample_time = {sample_time!r} is out of bounds: must be > 0 [s]")
        self.law = law
        self.params = law.params
        self.mass = float(mass)
        self.sample_time = float(sample_time)
        self.fric = FrictionStep(law)
        nz = len(law.state_names)
        self.state_names = tuple(law.state_names) + ("x_prev", "v_prev", "a_prev", "started")
        self._nz = nz

    def initial_state(self):
        return np.concatenate((self.law.initial_state(), np.zeros(4)))

    def step(self, t, state, inputs):
        nz = self._nz
        z = state[:nz]
        x, v, a = inputs.get("x_d", 0.0), inputs["v_d"], inputs.get("a_d", 0.0)
        if state[nz + 3] > 0:
            z, F = self.fric.advance(z, self.sample_time,
                                     (state[nz], state[nz + 1], state[nz + 2], None),
                                     (x, v, a, None))
        else:
            F = self.fric.force(z, x, v, a)
        new = np.concatenate((z, [x, v, a, 1.0]))
        return new, {"u_ff": F / self.mass, "F_ff": F}


class DiscreteStepper:
    """FMU-facing wrapper of a :class:`DiscreteBlock` (same interface as
    :class:`plants.stepper.PlantStepper`).

    Semantics: the block samples at ``start + k * sample_time``. ``set_inputs`` stores
    inputs; ``outputs()`` first runs a sample that is due at the current time with the
    current inputs (direct feedthrough at sample instants, so a Gauss-Seidel master that
    sets inputs, reads outputs, then steps the plant reproduces the monolithic loop with
    no extra delay); ``do_step(t, h)`` runs samples due in ``[t, t+h)`` with the held
    inputs and leaves a sample at ``t+h`` pending. Outputs are held between samples.

    Parameters
    ----------
    block : DiscreteBlock
        The sampled block.
    start : float
        Start time [s].
    """

    def __init__(self, block: DiscreteBlock, start: float = 0.0):
        self.block = block
        self.input_names = tuple(block.input_names)
        self.output_names = tuple(block.output_names)
        self.parameter_names = block.parameter_names
        self.start = float(start)
        self.reset()

    def reset(self, start: float | None = None) -> None:
        """

        Parameters
        ----------
        start : float, optional
            New start time [s].
        """
        if start is not None:
            self.start = float(start)
        self.time = self.start
        self.state = self.block.initial_state()
        self.inputs = {n: 0.0 for n in self.input_names}
        self._k = 0
        self._out = {n: 0.0 for n in self.output_names}

    def set_inputs(self, values: dict) -> None:
        """

        Parameters
        ----------
        values : dict
            Input values by name (``input_names``), SI units.
        """
        for k, val in values.items():
            if k not in self.inputs:
                raise KeyError(f"unknown input {k!r}; inputs are {list(self.inputs)}")
            self.inputs[k] = float(val)

    def _run_due(self, t_limit: float, inclusive: bool) -> None:
        Ts = self.block.sample_time
        tol = 1e-9 * Ts
        while True:
            ts = self.start + self._k * Ts
            if ts < t_limit - tol or (inclusive and ts <= t_limit + tol):
                self.state, self._out = self.block.step(ts, self.state, self.inputs)
                self._k += 1
            else:
                break

    def outputs(self) -> dict[str, float]:
        self._run_due(self.time, inclusive=True)
        return dict(self._out)

    def do_step(self, t: float, h: float) -> bool:
        """

        Parameters
        ----------
        t : float
            Current time [s].
        h : float
            Step length [s].
        """
        if abs(t - self.time) > 1e-9 * max(1.0, abs(t)):
            raise ValueError(f"do_step(t={t!r}) but the stepper is at time {self.time!r}")
        if not h > 0:
            raise ValueError(f"h = {h!r} is out of bounds: must be > 0 [s]")
        self._run_due(t + h, inclusive=False)
        self.time = t + h
        return True
