"""A friction law plus the force-level candidate effects, as one law a plant can take
(:class:`EffectLaw`; numba kernel wrapping the base law's kernel)."""
from __future__ import annotations

import functools

import numpy as np
from numba import njit

from friction import FrictionModel
from friction.extensions import extension_force, pack_extensions

from .effects import FORCE_EFFECTS, INPUTS, LEVELS, Context

__all__ = ["EffectLaw", "FORCE_EFFECTS"]

# FORCE_EFFECTS (re-exported): the candidates evaluated inside the friction law by
# :class:`EffectLaw`, the records of :mod:`diagnosis.effects` with ``plant_entry="force"``


# -- friction law + force effects -----------------------------------------------------------
# one formula for the in-process law and the friction_effects FMU block
_effect_force = extension_force


@functools.lru_cache(maxsize=None)
def _effect_kernel(base_kernel, nb: int, ns: int):
    """Numba kernel of base law + force effects; the extra last state is absolute time."""

    @njit
    def kern(t, v, a, load, x, theta, method, state0):
        th = theta[:nb].copy()
        s0 = state0[:ns].copy()
        F0, S0 = base_kernel(t, v, a, load, x, th, method, s0)
        n = t.size
        F = np.empty(n)
        S = np.empty((n, ns + 1))
        e = theta[nb:]
        tau0 = state0[ns]
        has_a, has_x, has_l = a.size == n, x.size == n, load.size == n
        for i in range(n):
            for j in range(ns):
                S[i, j] = S0[i, j]
            ti = tau0 + (t[i] - t[0])
            S[i, ns] = ti
            F[i] = _effect_force(F0[i], v[i], a[i] if has_a else 0.0, x[i] if has_x else 0.0,
                                 load[i] if has_l else 1.0, ti, e)
        return F, S

    return kern


#: parameters whose zero makes a force effect vanish (the records' ``levels``)
_LEVELS = LEVELS


def _pack_effects(effects: dict, ctx: Context) -> np.ndarray:
    return pack_extensions(effects, x_lo=ctx.x_lo, x_hi=ctx.x_hi, t0=ctx.t0, T=ctx.T,
                           L0=ctx.L0 if "load" in effects else None)


class EffectLaw(FrictionModel):
    """A friction law with candidate force effects, usable wherever a law is (plants,
    :class:`plants.base.FrictionComponent`, ``simulate``).

    Parameters
    ----------
    base : FrictionModel
        The base law (its kernel runs unchanged).
    effects : dict
        Effect name (:data:`FORCE_EFFECTS`) -> its parameters (the ``Extra`` names of
        :mod:`diagnosis.effects`, physical units: ``f_a`` [N], ``a_s`` [m/s^2], ``v_c``
        [m/s], ``c_x1..c_x11`` [-], ``k_drift`` [-], ``k_L`` [-]).
    ctx : Context
        Scales of the fit record (stroke ``x_lo, x_hi`` [m], start ``t0`` and duration ``T``
        [s], mean load ``L0`` [N]) that the effect formulas refer to.
    time0 : float
        Absolute time at the start of a run [s] (initial value of the time state).

    Notes
    -----
    The force is exactly ``Candidate.apply`` of :mod:`diagnosis.effects` applied to the base
    law's force, sample by sample; the state is the base law's plus the absolute time
    (``drift`` needs it: a plant's friction stepper only sees step lengths).
    """

    def __init__(self, base: FrictionModel, effects: dict, ctx: Context, time0: float = 0.0):
        if isinstance(base, EffectLaw):
            raise TypeError("EffectLaw wraps a plain friction law, not another EffectLaw")
        self.base = base
        self.effects = {k: dict(v) for k, v in effects.items()}
        self.ctx = ctx
        self.time0 = float(time0)
        self.name = base.name + "".join(f"+{k}" for k in self.effects)
        self.Params = base.Params
        self.params = base.params
        self.state_names = tuple(base.state_names) + ("t_abs",)
        needs = set(base.extra_inputs)
        for k in self.effects:
            needs.update(INPUTS[k])
        self.extra_inputs = tuple(n for n in ("a", "load", "x") if n in needs)
        self._e = _pack_effects(self.effects, ctx)
        self.theta = np.concatenate([np.asarray(base.theta, float), self._e])
        self._kernel = _effect_kernel(type(base)._kernel, int(base.theta.size),
                                      len(base.state_names))

    def __repr__(self) -> str:
        return f"EffectLaw({self.base!r}, {self.effects!r})"

    def initial_state(self) -> np.ndarray:
        return np.concatenate([self.base.initial_state(), [self.time0]])

    def with_time0(self, time0: float) -> "EffectLaw":
        """This law with the record's start at absolute time ``time0``.

        Parameters
        ----------
        time0 : float
            Absolute time [s] of the record's first sample (drift effects).
        """
        return EffectLaw(self.base, self.effects, self.ctx, time0)

    def with_values(self, **values) -> "EffectLaw":
        return EffectLaw(self.base.with_values(**values), self.effects, self.ctx, self.time0)

    def _split(self, inputs):
        return {k: v for k, v in inputs.items() if k in self.base.extra_inputs}

    def force(self, state, v, **inputs) -> float:
        ns = len(self.base.state_names)
        F = self.base.force(np.asarray(state[:ns], float), v, **self._split(inputs))
        ld = inputs.get("load")
        return float(_effect_force(float(F), float(v), float(inputs.get("a", 0.0) or 0.0),
                                   float(inputs.get("x", 0.0) or 0.0),
                                   1.0 if ld is None else float(ld), float(state[ns]), self._e))

    def derivatives(self, state, v, **inputs) -> np.ndarray:
        ns = len(self.base.state_names)
        ds = self.base.derivatives(np.asarray(state[:ns], float), v, **self._split(inputs))
        return np.concatenate([np.atleast_1d(ds), [1.0]])

    def steady_state(self, v, **inputs) -> np.ndarray:
        raise NotImplementedError("EffectLaw has no steady state of its own (the effects "
                                  "depend on acceleration, position or time)")

    def z_max(self) -> float:
        zm = getattr(self.base, "z_max", None)
        return zm() if zm else 1e-5
