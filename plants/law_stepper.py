"""A friction law stepped on its own, through its numba kernel (no scipy).

* :class:`FrictionStep` - the law's state advanced over a step with the motion at both
  ends, and its force at a state (what :class:`plants.stepper.PlantStepper` and
  :class:`plants.controllers.LuGreFeedforward` call);
* :class:`FrictionComponent` - the law as a stand-alone component with the stepper
  interface (the friction FMU of an assembled loop).
"""
from __future__ import annotations

import numpy as np

from friction.base import METHODS, FrictionModel

__all__ = ["FrictionStep", "FrictionComponent"]


class FrictionStep:
    """A friction law driven step by step through its numba kernel (no scipy).

    Parameters
    ----------
    law : FrictionModel
    method : {"exact", "euler"}
        Bristle update of the law's kernel (``exact`` is stable at any step).

    Notes
    -----
    The law's prescribed-motion kernel evaluated on a two-sample record ``[t, t+h]``
    advances the state over the step (velocity at both ends) and returns the force at both
    ends; a one-sample record gives the force at the current state.
    """

    def __init__(self, law: FrictionModel, method: str = "exact"):
        if method not in METHODS:
            raise ValueError(f"method must be one of {sorted(METHODS)}, got {method!r}")
        self.law = law
        self.method = METHODS[method]
        self.n_states = len(law.state_names)
        self.needs = law.extra_inputs
        self._t2 = np.zeros(2)
        self._empty = np.zeros(0)

    def _extra(self, key, values):
        return np.array(values) if key in self.needs else self._empty

    def force(self, state, x, v, a=0.0, load=None) -> float:
        """Friction force [N] at the given state and kinematics.

        Parameters
        ----------
        state : array_like
            The law's state (``state_names``).
        x : float
            Displacement [m].
        v : float
            Velocity [m/s].
        a : float
            Acceleration [m/s^2].
        load : float, optional
            Load [N].
        """
        one = np.zeros(1)
        F, _ = self.law._kernel(one, np.array([v]), self._extra("a", [a]),
                                self._extra("load", [load if load is not None else 0.0]),
                                self._extra("x", [x]), self.law.theta, self.method,
                                np.asarray(state, dtype=np.float64))
        return float(F[0])

    def advance(self, state, h, k0, k1):
        """Advance the state over a step of length ``h`` [s].

        ``k0``, ``k1`` are ``(x, v, a, load)`` at the start and the end. Returns
        ``(new_state, force_at_end)``.

        Parameters
        ----------
        state : ndarray
            The law's state at the start of the step.
        h : float
            Step length [s].
        k0, k1 : tuple of float
            ``(x, v, a, load)`` [m, m/s, m/s^2, N] at the start and at the end of the step.
        """
        t = self._t2
        t[1] = h
        F, S = self.law._kernel(
            t, np.array([k0[1], k1[1]]), self._extra("a", [k0[2], k1[2]]),
            self._extra("load", [k0[3] or 0.0, k1[3] or 0.0]), self._extra("x", [k0[0], k1[0]]),
            self.law.theta, self.method, np.asarray(state, dtype=np.float64))
        return S[1].copy(), float(F[1])



class FrictionComponent:
    """A friction law as a stand-alone stepper component (friction FMU of an assembled loop).

    Inputs ``v`` [m/s] and, if the law needs them, ``x`` [m], ``a`` [m/s^2], ``load`` [N];
    output ``F`` [N]. Same interface as :class:`PlantStepper`.

    Semantics: the state over ``[t, t+h]`` is advanced lazily, when the inputs at ``t+h``
    arrive (``set_inputs``) or the outputs are read, with the law's stable update between
    the inputs at both ends - exactly ``law.simulate`` on the sampled motion. ``F`` depends
    on the current inputs (direct feedthrough), so a Gauss-Seidel master reads it after
    setting ``v`` at each communication point.

    Parameters
    ----------
    law : FrictionModel
        The friction law.
    method : {"exact", "euler"}
        Bristle update.
    start : float
        Start time [s].
    """

    def __init__(self, law: FrictionModel, method: str = "exact", start: float = 0.0):
        self.law = law
        self.fric = FrictionStep(law, method)
        self.input_names = ("v",) + tuple(n for n in ("x", "a", "load")
                                          if n in law.extra_inputs)
        self.output_names = ("F",)
        self.parameter_names = tuple(n for n in law.Params.numeric_names()
                                     if getattr(law.params, n) is not None)
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
        self.z = self.law.initial_state().astype(float)
        self.inputs = {n: 0.0 for n in self.input_names}
        self._pending = 0.0

    def _kin(self, inp):
        return (inp.get("x", 0.0), inp["v"], inp.get("a", 0.0), inp.get("load"))

    def _advance(self, new_inputs) -> None:
        if self._pending > 0:
            self.z, _ = self.fric.advance(self.z, self._pending, self._kin(self.inputs),
                                          self._kin(new_inputs))
            self._pending = 0.0

    def set_inputs(self, values: dict) -> None:
        """

        Parameters
        ----------
        values : dict
            Input values by name (``v`` and the law's ``x``, ``a``, ``load``), SI units.
        """
        for k in values:
            if k not in self.inputs:
                raise KeyError(f"{self.law.name}: unknown input {k!r}; inputs are "
                               f"{list(self.inputs)}")
        new = {**self.inputs, **{k: float(v) for k, v in values.items()}}
        self._advance(new)
        self.inputs = new

    def outputs(self) -> dict[str, float]:
        self._advance(self.inputs)  # no new inputs arrived: held over the step
        i = self.inputs
        return {"F": self.fric.force(self.z, i.get("x", 0.0), i["v"], i.get("a", 0.0),
                                     i.get("load"))}

    def do_step(self, t: float, h: float) -> bool:
        """

        Parameters
        ----------
        t, h : float
            The component's current time and the step length [s].
        """
        if abs(t - self.time) > 1e-9 * max(1.0, abs(t)):
            raise ValueError(f"do_step(t={t!r}) but the component is at time {self.time!r}")
        if not h > 0:
            raise ValueError(f"h = {h!r} is out of bounds: must be > 0 [s]")
        self._pending += h
        self.time = t + h
        return True

