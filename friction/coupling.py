"""The law-plant coupling of the co-simulation: port names, units and the law's linearisation.

One home for what a friction-law FMU (either kind), a plant FMU (``plants`` stepper in
external-friction mode), the master (:mod:`fmus.master`, :mod:`fmus.plant_fmus`) and the
variable lists (:mod:`fmus.variables`, :mod:`fmus.native.variables`) must agree on:

* the law's kinematic inputs and their units (:data:`INPUT_INFO`);
* the coupling ports: the law's outputs :data:`COUPLING_OUTPUTS` (and
  :data:`SWITCH_OUTPUTS` for a law whose coefficients jump at a speed) go to the plant's
  inputs of the same names; the plant's outputs :data:`MEAN_INPUT` and :data:`SHARE_INPUT`
  go to the law's inputs of the same names (:data:`PLANT_INPUTS`, :data:`PLANT_OUTPUTS`);
  each port's unit and description on either side (:data:`LAW_PORTS`, :data:`PLANT_PORTS`);
* one spelling of units in every model description (:func:`fmi_unit`: ``m/s2``, not
  ``m/s^2``);
* the numerics of the linearly implicit coupling (:func:`law_linearisation`,
  :func:`switch_linearisation`), which the law FMUs run and the plant integrates.

It sits in ``friction`` (below ``plants``, whose stepper takes its port names from it, and
below ``fmus``, where :mod:`fmus.coupling` re-exports it). It imports nothing from the
project and needs numpy only: :mod:`fmus.build` carries a copy into every pythonfmu FMU as
the slave runtime's ``coupling`` module.
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["INPUT_INFO", "COUPLING_OUTPUTS", "SWITCH_OUTPUTS", "SHARE_INPUT", "MEAN_INPUT",
           "PLANT_INPUTS", "PLANT_OUTPUTS", "LAW_PORTS", "PLANT_PORTS", "fmi_unit", "law_inputs",
           "has_switch", "law_linearisation", "switch_linearisation"]


def fmi_unit(unit: str) -> str:
    """The one spelling of a unit in the FMUs' model descriptions: exponents without ``^``
    (``m/s^2`` -> ``m/s2``, ``m^3/s`` -> ``m3/s``).

    Parameters
    ----------
    unit : str
        A unit as the library spells it (``m/s^2``).
    """
    return unit.replace("^", "")


#: unit and description of the kinematic inputs a law may take, in this order after ``v``
INPUT_INFO = {
    "v": ("m/s", "sliding velocity"),
    "a": ("m/s2", "acceleration"),
    "load": ("N", "normal / deformation load"),
    "x": ("m", "displacement"),
}


def law_inputs(model_cls) -> list[str]:
    """Kinematic inputs of a law's FMU: ``v`` and whichever of ``a``, ``load``, ``x``.

    Parameters
    ----------
    model_cls : type
        A friction-law class (``friction.MODELS`` value).
    """
    return ["v"] + [n for n in ("a", "load", "x") if n in model_cls.extra_inputs]


#: outputs of a law FMU for the linearly implicit coupling (see :func:`law_linearisation`),
#: inputs of the same names of a plant FMU
COUPLING_OUTPUTS = ("dF_dx", "dF_dv", "dF_dt", "d2F_dt2", "t_kink", "dF_dt_kink")
#: extra coupling outputs of a law whose coefficients jump at |v| = v_switch
#: (:func:`switch_linearisation`)
SWITCH_OUTPUTS = ("v_switch", "dF_switch", "dF_dx_switch", "dF_dv_switch")
#: plant output / law input: share of the last step the plant spent below v_switch
SHARE_INPUT = "low_share"
#: plant output / law input: mean velocity over the last step (the plant's travel / step)
MEAN_INPUT = "v_mean"
#: a plant's coupling inputs (external-friction mode), in the order its stepper takes them
PLANT_INPUTS = COUPLING_OUTPUTS + SWITCH_OUTPUTS
#: a plant's coupling outputs that go back to the law
PLANT_OUTPUTS = (SHARE_INPUT, MEAN_INPUT)

#: the law side of each coupling port: name -> (unit, description)
LAW_PORTS = {
    "v_switch": ("m/s", "speed |v| at which the law's coefficients jump (0: none)"),
    "dF_switch": ("N", "force of the other side of v_switch minus this side's, at the current "
                       "state and inputs"),
    "dF_dx_switch": ("N/m", "dF_dx of the other side of v_switch minus this side's"),
    "dF_dv_switch": ("N.s/m", "dF_dv of the other side of v_switch minus this side's"),
    "dF_dx": ("N/m", "slope of F against the travel over the coming step (h_lin)"),
    "dF_dv": ("N.s/m", "slope of F against the end velocity of the coming step (h_lin)"),
    "dF_dt": ("N/s", "rate of F over the coming step (h_lin) along the motion extrapolated "
                     "from the last two input samples, beyond dF_dx and dF_dv"),
    "d2F_dt2": ("N/s2", "curvature of that rate over the coming step (h_lin)"),
    "t_kink": ("s", "time into the coming step at which the extrapolated velocity reverses "
                    "(0: no reversal)"),
    "dF_dt_kink": ("N/s", "change of dF_dt at t_kink (the force's kink where |v| turns)"),
    MEAN_INPUT: ("m/s", "mean velocity over the last step, travel / step (connect "
                        "plant.v_mean; used with use_v_mean)"),
    SHARE_INPUT: ("1", "share of the last step the plant spent below v_switch (connect "
                       "plant.low_share; used with use_low_share and inputs_at_step_end)"),
}

#: the plant side of each coupling port: name -> (unit, description)
PLANT_PORTS = {
    "dF_dx": ("N/m", "friction law's slope against the travel over the step (connect "
                     "friction.dF_dx; 0: friction held over the step)"),
    "dF_dv": ("N.s/m", "friction law's slope against the velocity over the step (connect "
                       "friction.dF_dv; 0: friction held over the step)"),
    "dF_dt": ("N/s", "friction law's rate over the step beyond the slopes (connect "
                     "friction.dF_dt; 0: none)"),
    "d2F_dt2": ("N/s2", "friction law's curvature of that rate over the step (connect "
                        "friction.d2F_dt2; 0: none)"),
    "t_kink": ("s", "time into the step at which the friction law's extrapolated velocity "
                    "reverses (connect friction.t_kink)"),
    "dF_dt_kink": ("N/s", "friction law's change of rate at t_kink (connect "
                          "friction.dF_dt_kink; 0: none)"),
    "v_switch": ("m/s", "speed at which the friction law's coefficients jump (connect "
                        "friction.v_switch; 0: none)"),
    "dF_switch": ("N", "friction law's force jump to the other side of v_switch (connect "
                       "friction.dF_switch)"),
    "dF_dx_switch": ("N/m", "change of dF_dx on the other side of v_switch (connect "
                            "friction.dF_dx_switch)"),
    "dF_dv_switch": ("N.s/m", "change of dF_dv on the other side of v_switch (connect "
                              "friction.dF_dv_switch)"),
    SHARE_INPUT: ("1", "share of the last communication step spent below the friction law's "
                       "v_switch (a sliding stretch with its Filippov weight; connect to "
                       "friction.low_share)"),
    MEAN_INPUT: ("m/s", "mean contact velocity over the last communication step, travel / "
                        "step (connect to friction.v_mean)"),
}


def has_switch(model_cls) -> bool:
    """Whether the law's coefficients jump at a switching speed (``regimes()``).

    Parameters
    ----------
    model_cls : type
        A friction-law class.
    """
    return callable(getattr(model_cls, "regimes", None))


def law_linearisation(kernel, theta, state, inputs: dict, h: float,
                      dv_dt: float | None = None, d2v_dt2: float = 0.0) -> tuple:
    """Local linearisation ``(dF_dx, dF_dv[, dF_dt, d2F_dt2])`` of a law over a step ``h`` [s].

    The law's own step map (its kernel over ``[0, h]``: state update with the velocity at
    both ends, force at the end) is differentiated by finite differences around the nominal
    step (velocity ``v`` held, or ``v -> v + dv_dt h`` when ``dv_dt`` is given; other inputs
    held): ``dF_dv`` shifts the end velocity at equal travel, ``dF_dx`` the travel (both
    velocities shifted). A plant that
    integrates its step with ``F(t) = F_k + dF_dx (x(t) - x_k) + dF_dv (v(t) - v_k)
    + dF_dt (t - t_k)`` then sees the law's stiffness (sticking: about ``sigma0`` and
    ``sigma1 + sigma2``; sliding: the relaxed bristle and the viscous slope) inside its own
    integrator. Where the law is not differentiable (``|v|`` at rest, a regime switch), the
    one-sided pair of smaller size is taken (a jump is not a slope).

    With ``dv_dt`` [m/s^2] (the motion's expected acceleration) the residual ``R(t)`` of
    the slopes along the extrapolated motion ``v(t) = v + dv_dt t`` is returned too: the
    step map gives the force at ``h/2`` and ``h``, ``R = F - F_0 - dF_dx dx - dF_dv dv``
    (``F_0``: the force now) there, and ``R(t) = dF_dt t + d2F_dt2 t^2 / 2`` through both
    points carries what the slopes miss, e.g. the velocity reversing inside the step.

    Parameters
    ----------
    kernel : callable
        The law's ``_kernel(t, v, a, load, x, theta, method, state0)``.
    theta, state : ndarray
        Packed parameters and current state.
    inputs : dict
        Current inputs ``v`` and whichever of ``a``, ``load``, ``x`` the law takes.
    h : float
        Horizon [s] (> 0).
    dv_dt : float, optional
        Expected acceleration over the step [m/s^2].
    d2v_dt2 : float
        Expected rate of change of the acceleration over the step [m/s^3].
    """
    v = float(inputs["v"])
    x = float(inputs.get("x", 0.0))
    t2 = np.array([0.0, h])
    empty = np.zeros(0)
    a2 = np.full(2, float(inputs["a"])) if "a" in inputs else empty
    l2 = np.full(2, float(inputs["load"])) if "load" in inputs else empty

    def f_end(v0, v1, x1):
        x2 = np.array([x, x1]) if "x" in inputs else empty
        F, _ = kernel(t2, np.array([v0, v1]), a2, l2, x2, theta, 0, state)
        return float(F[1])

    # nominal step: velocity v -> v1 (held, or along the extrapolated motion)
    v1 = v if dv_dt is None else v + (dv_dt + 0.5 * d2v_dt2 * h) * h
    trav = 0.5 * (v + v1) * h
    dv = 1e-6 * max(abs(v), abs(v1)) + 1e-9
    F0 = f_end(v, v1, x + trav)
    best = None
    for d in (dv, -dv):
        D = (f_end(v - d, v1 + d, x + trav) - F0) / d          # end velocity, same travel
        K = (f_end(v + d, v1 + d, x + trav + d * h) - F0 - D * d) / (d * h)   # travel
        size = abs(K) * h + abs(D)
        if best is None or size < best[0]:
            best = (size, K, D)
    K, D = best[1], best[2]
    if dv_dt is None:
        return K, D
    one = np.zeros(1)
    F_now, _ = kernel(one, np.array([v]), a2[:1], l2[:1],
                      np.array([x]) if "x" in inputs else empty, theta, 0, state)
    F_now = float(F_now[0])

    def v_at(tau):
        return v + (dv_dt + 0.5 * d2v_dt2 * tau) * tau

    def residual(tau):
        vt = v_at(tau)
        travel = 0.5 * (v + vt) * tau
        t2[1] = tau
        return f_end(v, vt, x + travel) - F_now - K * travel - D * (vt - v)

    t_kink = _reversal_time(v, dv_dt, d2v_dt2, h)
    if t_kink is not None:
        # the velocity reverses inside the step: |v| kinks the force there, so the
        # residual is piecewise linear through 0, t_kink and h
        r_k, r_end = residual(t_kink), residual(h)
        t2[1] = h
        s1 = r_k / t_kink
        s2 = (r_end - r_k) / (h - t_kink)
        return K, D, s1, 0.0, t_kink, s2 - s1
    r_mid, r_end = residual(0.5 * h), residual(h)
    t2[1] = h
    curv = 4.0 * (r_end - 2.0 * r_mid) / (h * h)       # R'' (R quadratic through 0, mid, end)
    return K, D, (r_end - 0.5 * curv * h * h) / h, curv, 0.0, 0.0


def _reversal_time(v, a, b, h):
    """First time in (0.02 h, 0.98 h) at which v + a t + b t^2 / 2 changes sign, or None."""
    if v == 0.0:
        return None
    roots = []
    if b == 0.0:
        if a != 0.0:
            roots.append(-v / a)
    else:
        disc = a * a - 2.0 * b * v
        if disc >= 0.0:
            q = math.sqrt(disc)
            roots += [(-a - q) / b, (-a + q) / b]
    inside = [t for t in roots if 0.02 * h < t < 0.98 * h]
    return min(inside) if inside else None


def switch_linearisation(kernel, thetas: dict, vc: float, state, inputs: dict, h: float,
                         dv_dt: float | None = None, d2v_dt2: float = 0.0) -> tuple:
    """Coupling outputs of a law whose coefficients jump at |v| = ``vc`` [m/s].

    Each side of the switch is a smooth law (``thetas["low"]``, ``thetas["high"]``: the
    packed parameters of :func:`friction.regimes.regime_split`). The side of the current
    velocity gives :func:`law_linearisation` (so no finite difference straddles the jump);
    the other side adds ``(vc, dF_switch, dF_dx_switch, dF_dv_switch)``: its force at the
    current state and inputs minus this side's, and the differences of its slopes. A plant
    that holds the side of its own velocity in each substep then sees the jump where it
    happens inside the step (``plants.base.PlantStepper``).

    Parameters
    ----------
    kernel : callable
        The law's ``_kernel(t, v, a, load, x, theta, method, state0)``.
    thetas : dict
        Packed parameters of each side, ``{"low": ..., "high": ...}``.
    vc : float
        Switching speed [m/s].
    state : ndarray
        Current state.
    inputs : dict
        Current inputs ``v`` and whichever of ``a``, ``load``, ``x`` the law takes.
    h : float
        Communication step [s].
    dv_dt : float, optional
        Velocity slope over the step [m/s^2], as for :func:`law_linearisation`.
    d2v_dt2 : float
        Its rate of change [m/s^3], as for :func:`law_linearisation`.
    """
    side = "low" if abs(float(inputs["v"])) < vc else "high"
    other = "high" if side == "low" else "low"
    lin = law_linearisation(kernel, thetas[side], state, inputs, h, dv_dt, d2v_dt2)
    K2, D2 = law_linearisation(kernel, thetas[other], state, inputs, h)[:2] if dv_dt is None \
        else law_linearisation(kernel, thetas[other], state, inputs, h, dv_dt, d2v_dt2)[:2]
    empty = np.zeros(0)
    one = np.zeros(1)
    args = [np.array([float(inputs[n])]) if n in inputs else empty
            for n in ("v", "a", "load", "x")]
    F_side = float(kernel(one, *args, thetas[side], 0, state)[0][0])
    F_other = float(kernel(one, *args, thetas[other], 0, state)[0][0])
    return tuple(lin) + (vc, F_other - F_side, K2 - lin[0], D2 - lin[1])
