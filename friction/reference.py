"""Reference integrator: the monolithic ODE solved by ``scipy.integrate.solve_ivp``.

This is the yardstick the discrete updates, the plants and the FMU co-simulations are
compared against. It is slow on purpose (tight tolerances, stiff solver); do not use it in
identification loops.

Two problems are covered here:

* :func:`simulate_prescribed` - friction along a prescribed motion v(t) (linear
  interpolation between samples; the law's ``derivatives``/``force`` in continuous time);
* :func:`simulate_mass` - a mass driven by a force u(t) against the friction law,
  ``m dv/dt = u(t) - F``; states ``[x, v, *law states]``.

The plant library adds its own monolithic ODEs on the same pattern.

Laws whose coefficients jump (``load_lugre``: Table 3 switches at |v| = vc) are not smooth
ODEs; :func:`regime_split` gives the smooth law of each regime, so a reference integrator
can hold the regime fixed inside a segment, locate the crossing of |v| = vc as an event and
follow a sliding motion along the switching surface (Filippov) where both regimes push the
velocity towards it (see ``plants.base.Plant.simulate(method="reference")``).
"""
from __future__ import annotations

from typing import Callable

import numpy as np
from scipy.integrate import solve_ivp

from ._validation import as_float_array, check_signals, check_time
from .base import FrictionModel
from .regimes import RegimeSplit, regime_split  # re-exported (scipy-free home)

__all__ = ["simulate_prescribed", "simulate_mass", "DEFAULT_RTOL", "RegimeSplit",
           "regime_split"]

DEFAULT_RTOL = 1e-10


def _interp(t, y):
    def f(tq):
        return float(np.interp(tq, t, y))
    return f


def simulate_prescribed(model: FrictionModel, t, v, *, a=None, load=None, x=None,
                        rtol: float = DEFAULT_RTOL, atol: float | None = None,
                        method: str = "Radau") -> np.ndarray:
    """Friction force along a prescribed, linearly interpolated motion (reference).

    Parameters
    ----------
    model : FrictionModel
    t, v : array_like, shape (N,)
        Time [s] and velocity [m/s] samples.
    a, load, x : array_like, optional
        Acceleration [m/s^2], load [N], displacement [m] samples (interpolated linearly).
    rtol, atol : float
        Tolerances; ``atol`` defaults to 1e-6 of the bristle scale.

    Returns
    -------
    F : ndarray, shape (N,)
        Friction force [N] at the sample times.
    """
    t, v, extra = check_signals(t, v, a=a, load=load, x=x)
    if "a" in model.extra_inputs and extra["a"] is None:
        extra["a"] = np.gradient(v, t)
    if "x" in model.extra_inputs and extra["x"] is None:
        extra["x"] = np.concatenate(([0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(t))))
    fun = {k: _interp(t, arr) for k, arr in extra.items() if arr is not None}
    vf = _interp(t, v)
    s0 = model.initial_state()
    if s0.size == 0:
        return np.array([model.force(s0, vk, **{k: float(arr[i]) for k, arr in extra.items()
                                                if arr is not None})
                         for i, vk in enumerate(v)])
    scale = _state_scale(model)
    if atol is None:
        atol = 1e-6 * scale

    def rhs(tq, s):
        return model.derivatives(s, vf(tq), **{k: f(tq) for k, f in fun.items()})

    # max_step = sample interval: the interpolated input has a kink at every sample
    sol = solve_ivp(rhs, (t[0], t[-1]), s0, method=method, t_eval=t, rtol=rtol, atol=atol,
                    max_step=float(np.min(np.diff(t))))
    if not sol.success:
        raise RuntimeError(f"reference integrator failed: {sol.message}")
    S = sol.y.T
    return np.array([model.force(S[i], v[i], **{k: float(arr[i]) for k, arr in extra.items()
                                                if arr is not None})
                     for i in range(t.size)])


def _state_scale(model: FrictionModel) -> np.ndarray:
    """Typical magnitude of each state (the bristle deflection is ~Fc/sigma0, tiny): the
    law's ``state_scales()`` where it has one (several small states: the GMS blocks, the
    backlash gap), else ``z_max()`` for the first state and 1 for the others."""
    scales = getattr(model, "state_scales", None)
    if callable(scales):
        return np.asarray(scales(), dtype=float)
    zmax = getattr(model, "z_max", None)
    z = zmax() if callable(zmax) else 1e-5
    sc = np.full(len(model.state_names), 1.0)
    if sc.size:  # stateless laws (static Stribeck map) have nothing to scale
        sc[0] = z
    return sc


def simulate_mass(model: FrictionModel, mass: float, t, u: Callable[[float], float] | np.ndarray,
                  *, x0: float = 0.0, v0: float = 0.0, load: Callable[[float], float] | None = None,
                  rtol: float = DEFAULT_RTOL, atol: float | None = None,
                  method: str = "Radau") -> dict[str, np.ndarray]:
    """Mass on a friction contact driven by a force: ``m dv/dt = u(t) - F``.

    Parameters
    ----------
    model : FrictionModel
    mass : float
        Moving mass [kg] (> 0).
    t : array_like
        Output times [s].
    u : callable or array_like
        Driving force [N] as a function of time, or samples at ``t`` (linearly interpolated).
    x0, v0 : float
        Initial position [m] and velocity [m/s].
    load : callable, optional
        Normal/deformation load [N] as a function of time (load-dependent laws).

    Returns
    -------
    dict with ``t, x, v, a, F`` and one entry per law state.
    """
    if not mass > 0:
        raise ValueError(f"mass = {mass!r} is out of bounds: must be > 0 [kg]")
    t = as_float_array("t", t)
    check_time(t)
    uf = u if callable(u) else _interp(t, as_float_array("u", u))
    nz = len(model.state_names)
    s0 = np.concatenate(([x0, v0], model.initial_state()))
    needs_a = "a" in model.extra_inputs

    def inputs(tq, s):
        kw = {}
        if "x" in model.extra_inputs:
            kw["x"] = s[0]
        if "load" in model.extra_inputs:
            if load is None:
                raise ValueError(f"{model.name} needs load=")
            kw["load"] = load(tq)
        return kw

    def parts(tq, s):
        kw = inputs(tq, s)
        F = model.force(s[2:], s[1], **kw)
        acc = (uf(tq) - F) / mass
        if needs_a:
            kw["a"] = acc
        return F, acc, kw

    def rhs(tq, s):
        F, acc, kw = parts(tq, s)
        return np.concatenate(([s[1], acc], model.derivatives(s[2:], s[1], **kw)))

    scale = np.concatenate(([1e-6, 1e-6], _state_scale(model)))
    if atol is None:
        atol = 1e-6 * scale
    sol = solve_ivp(rhs, (t[0], t[-1]), s0, method=method, t_eval=t, rtol=rtol, atol=atol,
                    max_step=float(np.min(np.diff(t))))
    if not sol.success:
        raise RuntimeError(f"reference integrator failed: {sol.message}")
    S = sol.y.T
    Fs, accs = np.empty(t.size), np.empty(t.size)
    for i in range(t.size):
        Fs[i], accs[i], _ = parts(t[i], S[i])
    out = {"t": t, "x": S[:, 0], "v": S[:, 1], "a": accs, "F": Fs}
    for j, name in enumerate(model.state_names):
        out[name] = S[:, 2 + j]
    return out
