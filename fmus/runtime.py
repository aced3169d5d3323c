"""FMU-side runtime: the ``Fmi2Slave`` classes that every frictionlab FMU runs.

This module travels inside each FMU (vendored under a unique name such as
``_fl_lugre_runtime``); it needs only ``pythonfmu`` (bundled by the builder), numpy, and the
vendored ``friction`` / ``plants`` copies whose module names the generated slave script
passes in. It must not import frictionlab, scipy or matplotlib.

Three slave kinds share one base:

* :class:`LawSlave` - a friction law from ``friction.MODELS``. Inputs ``v`` [m/s] (and
  ``a``, ``load``, ``x`` when the law needs them), outputs ``F`` [N] (direct feedthrough
  of the inputs) and the law's states. Parameters come from the law's ``Params`` metadata.
* :class:`MassSlave` - a rigid mass driven by a built-in force signal plus the inputs
  ``F_ext`` and ``F_friction`` (the mass+friction proof loop).
* :class:`StepperSlave` - a plant of the ``plants`` package in external-friction mode through
  its ``stepper()`` (numpy/numba only);
* :class:`BlockSlave` - a discrete block of the XML-350 loop (state-dependent PID, LuGre
  feedforward, S-curve trajectory) through ``plants.controllers.DiscreteStepper``.

The variable list of a slave (:func:`law_variables`, :func:`mass_variables`, ...) is the single
source for both the runtime and the ``modelDescription.xml`` written by ``fmus.build``: the
value reference of a variable is its index in that list.

Bad input: a NaN/inf on any input or parameter, or a parameter outside its bounds, is never
stored: ``set_real`` logs it at error level naming the variable and its bound and keeps the
previous value, so ``fmi2SetReal`` returns ``fmi2Error`` and the instance keeps working. The
status comes from the FMU's status shim (``fmus/shim``, in front of pythonfmu's binary on
linux64 and win64): a call during which the slave logged an error returns ``fmi2Error``. The
slaves never raise, because pythonfmu 0.7 turns an exception into ``fmi2Fatal`` and destroys
the instance (and leaves the embedding interpreter corrupt: a later garbage collection
segfaults). An inadmissible parameter combination (found when the model is built), a failed
output evaluation or a step that would produce a non-finite output is logged at error level by
the call that finds it, and every later ``fmi2DoStep`` is refused (``do_step`` returns False)
with the message again; these give ``fmi2Error`` too. Without the shim (an FMU built without
a C compiler for linux64 or without MinGW-w64 for win64) the statuses are pythonfmu's: the
call that logs answers ``fmi2OK``, so a rejected value also refuses the next ``fmi2DoStep``,
with ``fmi2Discard``.
"""
from __future__ import annotations

import dataclasses
import importlib
import math
import operator
import os
import sys

import numpy as np
from pythonfmu import Fmi2Causality, Fmi2Slave, Fmi2Variability
from pythonfmu.enums import Fmi2Status
from pythonfmu.variables import Boolean, Integer, Real, String

__all__ = ["Var", "law_variables", "mass_variables", "plant_variables", "block_variables",
           "SlaveBase", "LawSlave", "MassSlave", "StepperSlave", "BlockSlave", "INPUT_INFO",
           "behind_status_shim",
           "BLOCKS"]

#: unit and description of the kinematic inputs a law may need
INPUT_INFO = {
    "v": ("m/s", "sliding velocity"),
    "a": ("m/s2", "acceleration"),
    "load": ("N", "normal / deformation load"),
    "x": ("m", "displacement"),
}


@dataclasses.dataclass
class Var:
    """One FMU variable (what the model description lists and the runtime stores)."""
    name: str
    causality: str                  # "parameter" | "input" | "output"
    type: str = "Real"              # "Real" | "Integer" | "Boolean" | "String"
    start: object = 0.0
    unit: str = ""
    description: str = ""
    lower: float = -math.inf
    upper: float = math.inf
    lower_open: bool = False
    upper_open: bool = False
    #: optional parameter (Python ``None``): this start value stands for "unset"
    unset: float | None = None
    #: outputs: names of the inputs they depend on directly (feedthrough)
    depends: tuple = ()

    def bound_text(self) -> str:
        parts = []
        if self.lower > -math.inf:
            parts.append(f"{'>' if self.lower_open else '>='} {self.lower:g}")
        if self.upper < math.inf:
            parts.append(f"{'<' if self.upper_open else '<='} {self.upper:g}")
        return " and ".join(parts) or "finite"

    def admissible(self, value: float) -> bool:
        if self.unset is not None and value == self.unset:
            return True
        if not math.isfinite(value):
            return False
        if value < self.lower or (self.lower_open and value == self.lower):
            return False
        if value > self.upper or (self.upper_open and value == self.upper):
            return False
        return True


# -- variable lists ------------------------------------------------------------------------

def _param_vars(params_cls) -> list[Var]:
    """FMU parameters from a frozen parameter dataclass (``friction.base.param`` metadata)."""
    out = []
    for f in dataclasses.fields(params_cls):
        if f.name.startswith("_"):
            continue
        md = f.metadata
        default = f.default
        if default is dataclasses.MISSING:
            if f.default_factory is not dataclasses.MISSING:  # type: ignore[misc]
                default = f.default_factory()  # type: ignore[misc]
            else:
                continue
        desc = md.get("description", f"{f.name} (see {params_cls.__name__})")
        unit = md.get("unit", "")
        if isinstance(default, bool):
            out.append(Var(f.name, "parameter", "Boolean", bool(default), "", desc))
            continue
        if isinstance(default, str):
            out.append(Var(f.name, "parameter", "String", default, "", desc))
            continue
        if isinstance(default, int) and not md:
            out.append(Var(f.name, "parameter", "Integer", int(default), "", desc))
            continue
        if default is not None and not isinstance(default, (int, float)):
            continue  # arrays, nested objects: not an FMU scalar
        lower, upper = md.get("lower", -math.inf), md.get("upper", math.inf)
        v = Var(f.name, "parameter", "Real", None, unit, desc, lower, upper,
                md.get("lower_open", False), md.get("upper_open", False))
        if default is None:
            # optional value (e.g. a direction-dependent twin): a start value outside the
            # admissible range stands for Python None
            v.unset = (lower - 1.0) if math.isfinite(lower) else (upper + 1.0 if math.isfinite(upper) else 0.0)
            v.start = v.unset
            v.description = f"{desc} [FMU: {v.unset:g} = None]"
        else:
            v.start = float(default)
        if unit and "[" not in v.description:
            v.description = f"{v.description} [{unit}]"
        v.description += f" ({v.bound_text()})" if v.bound_text() != "finite" else ""
        out.append(v)
    return out


#: probe point of the feedthrough test (typical magnitudes; perturbed by 10 % each)
_PROBE = {"v": 1e-3, "a": 0.5, "load": 1e3, "x": 1e-4}


def law_feedthrough(model_cls, inputs) -> tuple:
    """Inputs the force output depends on directly, probed at the default parameters.

    ``F`` is evaluated by the law's ``force(state, v, **inputs)`` at a probe point and with
    each input perturbed; an input that changes ``F`` is a direct dependency. (A law whose
    structure changes with a parameter, e.g. modified LuGre with tau = 0 where F_d becomes
    algebraic in ``a``, is described at its defaults.)
    """
    try:
        model = model_cls()
        state = np.asarray(model.initial_state(), dtype=float)
        base = {n: _PROBE[n] for n in inputs}

        def F(vals):
            kw = {k: vals[k] for k in inputs if k != "v"}
            return float(model.force(state, vals["v"], **kw))

        f0 = F(base)
        deps = []
        for n in inputs:
            pert = dict(base)
            pert[n] = base[n] * 1.1 + 1e-9
            if abs(F(pert) - f0) > 1e-12 * (1.0 + abs(f0)):
                deps.append(n)
        return tuple(deps)
    except Exception:  # noqa: BLE001 - cannot probe: declare every input (safe side)
        return tuple(inputs)


def law_variables(model_cls, probe: bool = False) -> list[Var]:
    """Parameters, inputs and outputs of the FMU of a friction law class.

    ``probe=True`` (build time) narrows the declared dependencies of ``F`` to the inputs
    it really depends on (:func:`law_feedthrough`); otherwise all inputs are declared.
    """
    vs = _param_vars(model_cls.Params)
    inputs = ["v"] + [n for n in ("a", "load", "x") if n in model_cls.extra_inputs]
    for n in inputs:
        unit, desc = INPUT_INFO[n]
        vs.append(Var(n, "input", "Real", 0.0, unit, f"{desc} [{unit}]"))
    switching = has_switch(model_cls)
    if model_cls.state_names:
        vs.append(Var(MEAN_INPUT, "input", "Real", 0.0, "m/s",
                      "mean velocity over the last step, travel / step (connect plant.v_mean; "
                      "used with use_v_mean) [m/s]"))
        vs.append(Var("use_v_mean", "parameter", "Boolean", False, "",
                      "advance the state over a step with the input v_mean (the plant's "
                      "travel) instead of the velocities at both ends"))
    if switching:
        vs.append(Var(SHARE_INPUT, "input", "Real", -1.0, "1",
                      "share of the last step the plant spent below v_switch (connect "
                      "plant.low_share; with inputs_at_step_end the bristle state advances "
                      "with that mix of both regimes; negative: not connected, the regime of "
                      "the mid-step velocity) [1] (<= 1)", upper=1.0))
    deps = law_feedthrough(model_cls, inputs) if probe else tuple(inputs)
    vs.append(Var("F", "output", "Real", None, "N", "friction force [N]", depends=deps))
    vs += coupling_variables(inputs, switching)
    units = getattr(model_cls, "state_units", None)
    for j, s in enumerate(model_cls.state_names):
        unit = units[j] if units else ("m" if j == 0 else "N" if s.startswith("F") else "")
        desc = "bristle deflection" if j == 0 else f"internal state {s}"
        vs.append(Var(s, "output", "Real", None, unit,
                      f"{desc}" + (f" [{unit}]" if unit else ""), depends=()))
    return vs


#: outputs of a law FMU for the linearly implicit coupling (see :func:`law_linearisation`)
COUPLING_OUTPUTS = ("dF_dx", "dF_dv", "dF_dt", "d2F_dt2", "t_kink", "dF_dt_kink")
#: extra coupling outputs of a law whose coefficients jump at |v| = v_switch
#: (:func:`switch_linearisation`), and the plant output / law input of the share of a step
#: spent below it
SWITCH_OUTPUTS = ("v_switch", "dF_switch", "dF_dx_switch", "dF_dv_switch")
SHARE_INPUT = "low_share"
#: law input / plant output: mean velocity over the last step (the plant's travel / step)
MEAN_INPUT = "v_mean"


def has_switch(model_cls) -> bool:
    """Whether the law's coefficients jump at a switching speed (``regimes()``)."""
    return callable(getattr(model_cls, "regimes", None))


def coupling_variables(inputs, switching: bool = False) -> list[Var]:
    """Parameters ``h_lin``, ``inputs_at_step_end`` and outputs ``dF_dx``, ``dF_dv``,
    ``dF_dt``, ``d2F_dt2`` of a law FMU: the local linearisation of the law over the coming
    step (computed from the current inputs, so they depend directly on every input); with
    ``switching`` also ``v_switch``, ``dF_switch``, ``dF_dx_switch``, ``dF_dv_switch``."""
    def out(name, unit, description):
        return Var(name, "output", "Real", None, unit, f"{description} [{unit}]",
                   depends=tuple(inputs))

    extra = [] if not switching else [
        out("v_switch", "m/s", "speed |v| at which the law's coefficients jump (0: none)"),
        out("dF_switch", "N", "force of the other side of v_switch minus this side's, at "
                              "the current state and inputs"),
        out("dF_dx_switch", "N/m", "dF_dx of the other side of v_switch minus this side's"),
        out("dF_dv_switch", "N.s/m", "dF_dv of the other side of v_switch minus this side's"),
    ]
    return extra + [
        Var("h_lin", "parameter", "Real", 0.0, "s",
            "horizon of the coupling linearisation dF_dx, dF_dv, dF_dt, normally the "
            "communication step [s] (0: not computed, the outputs stay 0) (>= 0)", 0.0),
        Var("inputs_at_step_end", "parameter", "Boolean", False, "",
            "the inputs set before fmi2DoStep are the values at the end of the step "
            "(Gauss-Seidel after the plant): the state advances with the inputs at both "
            "ends (first-order hold) instead of holding them"),
        out("dF_dx", "N/m", "slope of F against the travel over the coming step (h_lin)"),
        out("dF_dv", "N.s/m", "slope of F against the end velocity of the coming step (h_lin)"),
        out("dF_dt", "N/s", "rate of F over the coming step (h_lin) along the motion "
                            "extrapolated from the last two input samples, beyond dF_dx and "
                            "dF_dv"),
        out("d2F_dt2", "N/s2", "curvature of that rate over the coming step (h_lin)"),
        out("t_kink", "s", "time into the coming step at which the extrapolated velocity "
                           "reverses (0: no reversal)"),
        out("dF_dt_kink", "N/s", "change of dF_dt at t_kink (the force's kink where |v| "
                                 "turns)"),
    ]


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


__all__ += ["COUPLING_OUTPUTS", "SWITCH_OUTPUTS", "SHARE_INPUT", "MEAN_INPUT", "has_switch",
            "coupling_variables", "law_linearisation", "switch_linearisation",
            "plant_coupling_inputs"]


def mass_variables() -> list[Var]:
    """A rigid mass on a line, driven by u(t) = u0 + u_amp sin(2 pi u_freq t) + F_ext - F_friction."""
    return [
        Var("m", "parameter", "Real", 1.0, "kg", "moving mass [kg] (> 0)", 0.0, math.inf, True),
        Var("x0", "parameter", "Real", 0.0, "m", "initial position [m]"),
        Var("v0", "parameter", "Real", 0.0, "m/s", "initial velocity [m/s]"),
        Var("u0", "parameter", "Real", 0.0, "N", "constant drive force [N]"),
        Var("u_amp", "parameter", "Real", 2.0, "N", "amplitude of the sinusoidal drive force [N]"),
        Var("u_freq", "parameter", "Real", 1.0, "Hz", "frequency of the drive force [Hz] (>= 0)",
            0.0),
        Var("F_friction", "input", "Real", 0.0, "N", "friction force opposing the motion [N]"),
        Var("F_ext", "input", "Real", 0.0, "N", "additional external force along +x [N]"),
        Var("x", "output", "Real", None, "m", "position [m]"),
        Var("v", "output", "Real", None, "m/s", "velocity [m/s]"),
        Var("a", "output", "Real", None, "m/s2", "acceleration [m/s2]",
            depends=("F_friction", "F_ext")),
    ]


def _option_vars(options: dict) -> list[Var]:
    """Scalar experiment options of a plant as FMU parameters (None/tuples are not exposed)."""
    out = []
    for k, v in options.items():
        desc = f"experiment option {k} (see the plant's options)"
        if isinstance(v, bool):
            out.append(Var(k, "parameter", "Boolean", v, "", desc))
        elif isinstance(v, str):
            out.append(Var(k, "parameter", "String", v, "", desc))
        elif isinstance(v, (int, float)):
            out.append(Var(k, "parameter", "Real", float(v), "", desc))
    return out


def plant_feedthrough(plant_cls) -> dict:
    """Outputs of the external-friction plant that change at once with ``F_friction``."""
    try:
        st = plant_cls(external_friction=True).stepper()
        st.set_inputs({"F_friction": 0.0})
        o0 = st.outputs()
        st.set_inputs({"F_friction": 1.0})
        o1 = st.outputs()
        return {n: ("F_friction",) for n in st.output_names
                if abs(o1[n] - o0[n]) > 1e-12 * (1.0 + abs(o0[n]))}
    except Exception:  # noqa: BLE001 - cannot probe: every output depends (safe side)
        return {n: tuple(plant_cls(external_friction=True).all_input_names)
                for n in plant_cls(external_friction=True).all_output_names}


def plant_variables(plant_cls, probe: bool = False) -> list[Var]:
    """Parameters (plant ``Params`` and scalar options), inputs and outputs of the FMU of a
    plant in external-friction mode (input ``F_friction``)."""
    plant = plant_cls(external_friction=True)
    numeric = set(plant.parameter_names)
    vs = [v for v in _param_vars(plant_cls.Params) if v.name in numeric or v.type != "Real"]
    names = {v.name for v in vs}
    vs += [v for v in _option_vars(dict(plant_cls.options)) if v.name not in names]
    signals = dict(getattr(plant_cls, "signals", {}) or {})
    signals.setdefault("F_friction", ("N", "friction force on the contact, opposing the "
                                             "sliding velocity"))
    deps = plant_feedthrough(plant_cls) if probe else \
        {n: tuple(plant.all_input_names) for n in plant.all_output_names}
    for n in plant.all_input_names:
        unit, desc = signals.get(n, ("", n))
        vs.append(Var(n, "input", "Real", 0.0, unit, desc + (f" [{unit}]" if unit else "")))
    vs += plant_coupling_inputs(plant)
    signals.setdefault(SHARE_INPUT, ("1", "share of the last communication step spent below "
                                          "the friction law's v_switch (a sliding stretch "
                                          "with its Filippov weight; connect to "
                                          "friction.low_share)"))
    signals.setdefault(MEAN_INPUT, ("m/s", "mean contact velocity over the last communication "
                                          "step, travel / step (connect to friction.v_mean)"))
    outs = plant.all_output_names + tuple(
        n for n in getattr(plant.stepper(), "output_names", ()) if n in (SHARE_INPUT,
                                                                         MEAN_INPUT))
    for n in outs:
        unit, desc = signals.get(n, ("", n))
        vs.append(Var(n, "output", "Real", None, unit, desc + (f" [{unit}]" if unit else ""),
                      depends=tuple(deps.get(n, ()))))
    return vs


#: unit and description of a plant FMU's coupling inputs (``PlantStepper.coupling_names``)
_COUPLING_INPUT_INFO = {
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
}


def plant_coupling_inputs(plant) -> list[Var]:
    """Inputs ``dF_dx``, ``dF_dv`` of a plant FMU in external-friction mode (the linearly
    implicit coupling of ``PlantStepper``); none if its stepper does not take them."""
    names = getattr(plant.stepper(), "coupling_names", ()) if plant.external_friction else ()
    out = []
    for n in names:
        unit, desc = _COUPLING_INPUT_INFO[n]
        out.append(Var(n, "input", "Real", 0.0, unit, f"{desc} [{unit}]"))
    return out


# -- slaves ---------------------------------------------------------------------------------

#: binaries folder and file name suffix of pythonfmu's library behind the status shim
#: (fmus.status_shim), by host platform
_SHIM_INNER = {"linux": ("linux64", "_pythonfmu.so"), "win32": ("win64", "_pythonfmu.dll")}


def behind_status_shim(resources, model_identifier: str) -> bool:
    """True when this FMU runs its linux64 or win64 binary and that binary is the status shim
    (which turns error-level log messages into ``fmi2Error``)."""
    key = "linux" if sys.platform.startswith("linux") else sys.platform
    if key not in _SHIM_INNER or not resources:
        return False
    folder, suffix = _SHIM_INNER[key]
    return os.path.isfile(os.path.join(resources, os.pardir, "binaries", folder,
                                       model_identifier + suffix))


_CAUS = {"parameter": Fmi2Causality.parameter, "input": Fmi2Causality.input,
         "output": Fmi2Causality.output}
_TYPES = {"Real": Real, "Integer": Integer, "Boolean": Boolean, "String": String}


class SlaveBase(Fmi2Slave):
    """Value store, bound checks and error reporting shared by all frictionlab slaves.

    Subclasses set ``model_identifier`` and implement ``make_variables``, ``rebuild``
    (parameters changed), ``compute_outputs`` (fill output values from state + inputs) and
    ``advance(t, h)``.
    """
    model_identifier = "frictionlab"
    fmu_description = ""

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.modelName = self.model_identifier
        self.description = self.fmu_description
        self.variables = self.make_variables()
        self.values = [v.start for v in self.variables]
        self.index = {v.name: i for i, v in enumerate(self.variables)}
        self.roles = [v.causality for v in self.variables]
        self.output_idx = [i for i, r in enumerate(self.roles) if r == "output"]
        #: the output values as a tuple (one C call: do_step's finiteness test)
        idx = self.output_idx
        self.output_values = operator.itemgetter(*idx) if len(idx) > 1 else \
            (lambda vals, i=idx[0]: (vals[i],)) if idx else (lambda vals: ())
        #: per value reference: a Real input (set_real's fast path)
        self.fast_input = [v.causality == "input" and v.type == "Real" for v in self.variables]
        for i, v in enumerate(self.variables):
            var_cls = _TYPES[v.type]
            variability = (Fmi2Variability.tunable if v.causality == "parameter"
                           else Fmi2Variability.continuous if v.type == "Real"
                           else Fmi2Variability.discrete)
            self.register_variable(var_cls(
                v.name, causality=_CAUS[v.causality], variability=variability,
                description=v.description,
                getter=(lambda i=i: self.values[i]),
                setter=(lambda value, i=i: self.values.__setitem__(i, value))),
                nested=False)
        self.params_dirty = True
        self.outputs_dirty = True
        #: failures that refuse every step until fixed: "parameters" (model cannot be
        #: built), "outputs" (evaluation failed), "step" (a step failed; until reset)
        self.failed: dict[str, str] = {}
        #: without the status shim only: rejected values, refusing the next step
        self.pending: dict[str, str] = {}
        self.status_shim = behind_status_shim(self.resources, self.model_identifier)
        self.time = 0.0

    # subclasses ---------------------------------------------------------------------------
    def make_variables(self) -> list[Var]:  # pragma: no cover - abstract
        raise NotImplementedError

    def rebuild(self, initial: bool) -> None:  # pragma: no cover - abstract
        raise NotImplementedError

    def compute_outputs(self) -> None:  # pragma: no cover - abstract
        raise NotImplementedError

    def advance(self, t: float, h: float) -> bool:  # pragma: no cover - abstract
        """Integrate [t, t+h] with the inputs held; return True if the outputs at t+h were
        set as well (otherwise ``compute_outputs`` runs)."""
        raise NotImplementedError

    # helpers ------------------------------------------------------------------------------
    def log(self, msg, status=Fmi2Status.ok, category=None, debug=None):
        # pythonfmu hands the message to the FMI logger as a printf format without
        # arguments: a literal '%' (e.g. "about 2 %" in a description) is doubled, or a
        # formatting logger (fmpy's default one uses vsnprintf) reads past its arguments
        super().log(msg.replace("%", "%%"), status, category)

    def reject(self, key: str, message: str) -> None:
        """Log a rejected value at error level (the call returns ``fmi2Error`` behind the
        status shim); without the shim the next step is refused as well (``fmi2Discard``).
        """
        msg = f"{self.instance_name}: {message}"
        self.log(msg, Fmi2Status.error)
        if not self.status_shim:
            self.pending[key] = msg

    def fail(self, key: str, message: str) -> None:
        """Record a failure that refuses every step until cleared (see ``failed``); the
        FMI call that found it reports it with :meth:`report`."""
        self.failed[key] = f"{self.instance_name}: {message}"

    def report(self, what: str) -> None:
        """Log every recorded failure at error level, saying what it prevents."""
        for msg in self.failed.values():
            self.log(f"{msg} ({what})", Fmi2Status.error)

    def param_values(self) -> dict:
        out = {}
        for v, value in zip(self.variables, self.values):
            if v.causality != "parameter":
                continue
            out[v.name] = None if (v.unset is not None and value == v.unset) else value
        return out

    def value(self, name: str):
        return self.values[self.index[name]]

    def _ensure_model(self, initial: bool = False) -> bool:
        if self.params_dirty:
            try:
                self.rebuild(initial)
            except Exception as exc:  # noqa: BLE001 - ParameterError names the parameter
                self.fail("parameters", f"invalid parameters: {type(exc).__name__}: {exc}")
                return False
            self.failed.pop("parameters", None)
            self.params_dirty = False
            self.outputs_dirty = True
        return "parameters" not in self.failed

    def _update_outputs(self) -> bool:
        if not self._ensure_model():
            return False
        try:
            self.compute_outputs()
        except Exception as exc:  # noqa: BLE001
            self.fail("outputs", f"output evaluation failed: {type(exc).__name__}: {exc}")
            return False
        self.failed.pop("outputs", None)
        self.outputs_dirty = False
        return True

    # FMI ----------------------------------------------------------------------------------
    def setup_experiment(self, start_time, stop_time=None, tolerance=None):
        self.time = float(start_time)

    def exit_initialization_mode(self):
        self._ensure_model(initial=True)
        if self.failed:
            self.report("initialization")

    def do_step(self, current_time, step_size):
        if self.failed or self.pending or (self.params_dirty and not self._ensure_model()):
            what = f"step at t = {current_time:g} refused"
            self.report(what)
            for msg in self.pending.values():
                self.log(f"{msg} ({what})", Fmi2Status.error)
            return False
        try:
            done = self.advance(current_time, step_size)
        except Exception as exc:  # noqa: BLE001 - never let an exception become fmi2Fatal
            self.fail("step", f"step [{current_time:g}, +{step_size:g}] failed: "
                              f"{type(exc).__name__}: {exc}")
            self.report("the instance refuses further steps")
            return False
        self.time = current_time + step_size
        if done:  # advance() already set the outputs for the held inputs
            self.outputs_dirty = False
        elif not self._update_outputs():
            self.report(f"step to t = {self.time:g}")
            return False
        values = self.values
        total = sum(self.output_values(values))  # inf/NaN if an output is (or on overflow)
        if total - total != 0.0:
            for i in self.output_idx:
                if not math.isfinite(values[i]):
                    self.fail("step", f"output {self.variables[i].name} = {values[i]!r} is "
                                      f"not finite after the step to t = {self.time:g}")
                    self.report("the instance refuses further steps")
                    return False
        return True

    def _check_set(self, vr, value):
        v = self.variables[vr]
        role = self.roles[vr]
        if role == "output":
            self.reject(v.name, f"{v.name} is an output and cannot be set; {value!r} ignored")
            return
        if v.type == "Real":
            value = float(value)
            if not math.isfinite(value):
                self.reject(v.name, f"{role} {v.name} = {value!r} is not finite "
                                    f"({v.description}); value rejected, {v.name} keeps "
                                    f"{self.values[vr]!r}")
                return
            if role == "parameter" and not v.admissible(value):
                self.reject(v.name, f"parameter {v.name} = {value!r} is out of bounds: must be "
                                    f"{v.bound_text()} [{v.unit}] ({v.description}); value "
                                    f"rejected, {v.name} keeps {self.values[vr]!r}")
                return
        self.pending.pop(v.name, None)
        self.values[vr] = value
        if role == "parameter":
            self.params_dirty = True
        self.outputs_dirty = True

    # An exception escaping to pythonfmu 0.7 gives fmi2Fatal and leaves the embedding
    # interpreter corrupt (a later garbage collection segfaults), so even an invalid value
    # reference is caught here and logged as an error (fmi2Error behind the status shim).
    def _bad_call(self, call, vrs, exc):
        self.log(f"{self.instance_name}: {call} with value references {list(vrs)} failed "
                 f"(valid: 0..{len(self.variables) - 1}): {type(exc).__name__}: {exc}",
                 Fmi2Status.error)

    def set_values(self, vrs, values):
        """Set any variables, each checked by ``_check_set``."""
        try:
            for vr, value in zip(vrs, values):
                self._check_set(vr, value)
        except (IndexError, TypeError, ValueError) as exc:
            self._bad_call("set", vrs, exc)

    def set_real(self, vrs, values):
        # fast path for finite Real inputs (every communication step); everything else,
        # and every value while a refusal is pending, goes through _check_set
        if self.pending:
            self.set_values(vrs, values)
            return
        fast, vals = self.fast_input, self.values
        try:
            for vr, value in zip(vrs, values):
                if fast[vr] and value - value == 0.0:  # 0.0 exactly when value is finite
                    vals[vr] = value
                else:
                    self._check_set(vr, value)
        except (IndexError, TypeError, ValueError) as exc:
            self._bad_call("fmi2SetReal", vrs, exc)
        self.outputs_dirty = True

    set_integer = set_values
    set_boolean = set_values
    set_string = set_values

    def get_real(self, vrs):
        if self.outputs_dirty:
            self._update_outputs()
        if self.failed:  # the values may be stale or non-finite: say so (fmi2Error)
            self.report("values read by fmi2GetReal are not valid")
        values = self.values
        try:
            return [float(values[vr]) for vr in vrs]
        except (IndexError, TypeError, ValueError) as exc:
            self._bad_call("fmi2GetReal", vrs, exc)
            return [math.nan] * len(vrs)

    def _get_as(self, call, kind, vrs, bad):
        try:
            return [kind(self.values[vr]) for vr in vrs]
        except (IndexError, TypeError, ValueError) as exc:
            self._bad_call(call, vrs, exc)
            return [bad] * len(vrs)

    def get_integer(self, vrs):
        return self._get_as("fmi2GetInteger", int, vrs, 0)

    def get_boolean(self, vrs):
        return self._get_as("fmi2GetBoolean", bool, vrs, False)

    def get_string(self, vrs):
        return self._get_as("fmi2GetString", str, vrs, "")


class LawSlave(SlaveBase):
    """FMU of one friction law (``law`` = registry name in ``<friction_package>.MODELS``).

    Inputs are held constant over a communication step (zero-order hold; with the
    parameter ``inputs_at_step_end`` the step runs from the previous inputs to the current
    ones, first-order hold); the state is advanced by the law's own stable kernel (exact
    exponential bristle update), so any step size is stable. ``F`` is evaluated from the
    current state and the current inputs (direct feedthrough), as the law's ``simulate``
    does at a sample. With ``h_lin > 0`` the outputs ``dF_dx, dF_dv, dF_dt, d2F_dt2`` give
    the law's linearisation over the coming step (:func:`law_linearisation`) for a plant
    that integrates the stiff contact itself (``plants.base.PlantStepper``).
    """
    law = "lugre"
    friction_package = "friction"

    @classmethod
    def model_class(cls):
        return importlib.import_module(cls.friction_package).MODELS[cls.law]

    def make_variables(self):
        return law_variables(self.model_class())

    def rebuild(self, initial):
        cls = self.model_class()
        values = self.param_values()
        for name in ("h_lin", "inputs_at_step_end", "use_v_mean"):  # the coupling's
            values.pop(name, None)
        model = cls(cls.Params(**values))
        self.model = model
        self.theta = np.ascontiguousarray(model.theta, dtype=np.float64)
        self.kernel = model._kernel
        if initial or not hasattr(self, "state"):
            self.state = np.asarray(model.initial_state(), dtype=np.float64).copy()
        ins = ["v"] + [n for n in ("a", "load", "x") if n in cls.extra_inputs]
        self.in_idx = [self.index[n] for n in ins]
        self.F_idx = self.index["F"]
        self.state_idx = [self.index[s] for s in cls.state_names]
        empty = np.zeros(0)
        self.t1 = np.zeros(1)
        self.t2 = np.zeros(2)
        self.buf1 = {n: (np.zeros(1) if n in ins else empty) for n in ("v", "a", "load", "x")}
        self.buf2 = {n: (np.zeros(2) if n in ins else empty) for n in ("v", "a", "load", "x")}
        self.names = ins
        # per step: (buffer, value index) pairs to fill and the kernel's leading arguments
        self.fill1 = [(self.buf1[n], i) for n, i in zip(ins, self.in_idx)]
        self.fill2 = [(self.buf2[n], i) for n, i in zip(ins, self.in_idx)]
        self.args1 = (self.t1,) + tuple(self.buf1[n] for n in ("v", "a", "load", "x"))
        self.args2 = (self.t2,) + tuple(self.buf2[n] for n in ("v", "a", "load", "x"))
        self.lin_idx = [self.index[n] for n in COUPLING_OUTPUTS]
        self.switch = None       # a regime switch: (vc, {"low": theta, "high": theta})
        if has_switch(cls):
            split = model.regimes()
            self.switch = (float(split.vc),
                           {r: np.ascontiguousarray(getattr(split, r).theta, dtype=np.float64)
                            for r in ("low", "high")})
            self.lin_idx += [self.index[n] for n in SWITCH_OUTPUTS]
            self.share_idx = self.index[SHARE_INPUT]
        self.lin_zeroed = False  # h_lin = 0: the coupling outputs are written once
        self.h_lin = float(self.values[self.index["h_lin"]])
        self.foh = bool(self.values[self.index["inputs_at_step_end"]])
        self.mean_idx = (self.index[MEAN_INPUT]
                         if cls.state_names and self.values[self.index["use_v_mean"]] else None)
        if initial or not hasattr(self, "last_in"):
            self.last_in = None    # inputs at the last communication point
            self.slope_v = 0.0     # dv/dt at the last input sample [m/s^2]
            self.curv_v = 0.0      # d2v/dt2 of the last three input samples [m/s^3]
            self.dv_last = None    # last backward difference of v [m/s]
            self.stepped = False

    def _inputs(self) -> list:
        vals = self.values
        return [vals[i] for i in self.in_idx]

    def _linearise(self):
        """Coupling outputs at the current state and inputs (0 if h_lin = 0)."""
        if self.h_lin > 0.0:
            inputs = dict(zip(self.names, self._inputs()))
            if self.switch is not None:
                lin = switch_linearisation(self.kernel, self.switch[1], self.switch[0],
                                           self.state, inputs, self.h_lin, self.slope_v,
                                           self.curv_v)
            else:
                lin = law_linearisation(self.kernel, self.theta, self.state, inputs,
                                        self.h_lin, self.slope_v, self.curv_v)
        elif self.lin_zeroed:
            return  # constant zeros, already written (per-step cost of the plain loops)
        else:
            lin = (0.0,) * len(self.lin_idx)
            self.lin_zeroed = True
        for i, val in zip(self.lin_idx, lin):
            self.values[i] = float(val)

    def _fill(self, pairs):
        vals = self.values
        for buf, i in pairs:
            buf.fill(vals[i])

    def compute_outputs(self):
        self._fill(self.fill1)
        F, _ = self.kernel(*self.args1, self.theta, 0, self.state)
        vals = self.values
        vals[self.F_idx] = F.item(0)
        for i, z in zip(self.state_idx, self.state.tolist()):
            vals[i] = z
        if not self.stepped:
            self.last_in = self._inputs()  # the start of the first step
        self._linearise()

    def advance(self, t, h):
        if self.state.size == 0:
            return False  # a static map: nothing to integrate
        self._fill(self.fill2)
        if self.h_lin > 0.0 or self.foh:
            now = self._inputs()
            if self.last_in is not None:
                # Newton backward polynomial through the last three samples of v
                d1 = now[0] - self.last_in[0]
                d2 = 0.0 if self.dv_last is None else d1 - self.dv_last
                self.slope_v = (d1 + 0.5 * d2) / h
                self.curv_v = d2 / (h * h)
                self.dv_last = d1
                if self.foh:  # first-order hold: the step starts at the last inputs
                    for n, v0 in zip(self.names, self.last_in):
                        self.buf2[n][0] = v0
            self.last_in = now
        self.stepped = True
        self.t2[1] = h
        v_end = None
        if self.mean_idx is not None:
            # the state follows the plant's travel over the step (mean velocity held); the
            # force at the end still sees the velocity at the end
            vbuf = self.buf2["v"]
            v_end = vbuf[1]
            vbuf.fill(self.values[self.mean_idx])
        # the plant's low_share describes this step only when it stepped first (Gauss-Seidel)
        share = self.values[self.share_idx] if self.switch is not None and self.foh else -1.0
        if share >= 0.0:
            # the plant says which share of the step lay below v_switch (sliding along it
            # with its Filippov weight): the state advances with that mix of both regimes
            thetas = self.switch[1]
            S = (share * self.kernel(*self.args2, thetas["low"], 0, self.state)[1]
                 + (1.0 - share) * self.kernel(*self.args2, thetas["high"], 0, self.state)[1])
            self._fill(self.fill1)
            F = np.array([0.0, self.kernel(*self.args1, self.theta, 0, S[1])[0].item(0)])
        else:
            F, S = self.kernel(*self.args2, self.theta, 0, self.state)
            if v_end is not None:
                self._fill(self.fill1)
                F = np.array([0.0, self.kernel(*self.args1, self.theta, 0, S[1])[0].item(0)])
        new = S[1].tolist()
        for j, zj in enumerate(new):
            if zj - zj != 0.0:  # inf or NaN: the state is kept as it was
                raise ValueError(f"state {self.model.state_names[j]} = {zj!r} became non-finite")
        vals, state = self.values, self.state
        for j, (i, zj) in enumerate(zip(self.state_idx, new)):
            vals[i] = zj
            state[j] = zj  # in place: no array per step
        # the kernel's force at the second sample: new state, inputs at the step's end
        vals[self.F_idx] = F.item(1)
        self._linearise()
        return True


class MassSlave(SlaveBase):
    """A rigid mass, m dv/dt = u0 + u_amp sin(2 pi u_freq t) + F_ext - F_friction.

    The inputs are held over the step and the sinusoid is integrated in closed form, so the
    step is exact for held inputs; ``a`` is the acceleration at the current time with the
    current inputs (direct feedthrough of ``F_friction`` and ``F_ext``).
    """
    model_identifier = "fl_mass"
    fmu_description = "Rigid mass driven by a sinusoidal force against an external friction force"

    def make_variables(self):
        return mass_variables()

    def rebuild(self, initial):
        p = self.param_values()
        if not p["m"] > 0:
            raise ValueError(f"m = {p['m']!r} is out of bounds: must be > 0 [kg]")
        self.p = p
        # per step: plain attributes and value slots instead of dict look-ups
        self.m, self.u0, self.u_amp = p["m"], p["u0"], p["u_amp"]
        self.w = 2.0 * math.pi * p["u_freq"]
        ix = self.index
        self.slots = (ix["x"], ix["v"], ix["a"], ix["F_ext"], ix["F_friction"])
        if initial or not hasattr(self, "x"):
            self.x, self.v = float(p["x0"]), float(p["v0"])

    def drive(self, t):
        return self.u0 + self.u_amp * math.sin(self.w * t)

    def compute_outputs(self):
        vals = self.values
        i_x, i_v, i_a, i_ext, i_fr = self.slots
        vals[i_x] = self.x
        vals[i_v] = self.v
        vals[i_a] = (self.drive(self.time) + vals[i_ext] - vals[i_fr]) / self.m

    def advance(self, t, h):
        vals = self.values
        _, _, _, i_ext, i_fr = self.slots
        held = self.u0 + vals[i_ext] - vals[i_fr]
        w = self.w
        if w > 0.0:
            c0, c1 = math.cos(w * t), math.cos(w * (t + h))
            s0, s1 = math.sin(w * t), math.sin(w * (t + h))
            i1 = self.u_amp * (c0 - c1) / w                           # int sin
            i2 = self.u_amp * (h * c0 / w - (s1 - s0) / (w * w))       # double integral
        else:
            i1 = i2 = 0.0
        m = self.m
        self.x = self.x + self.v * h + (0.5 * held * h * h + i2) / m
        self.v = self.v + (held * h + i1) / m
        self.time = t + h
        self.compute_outputs()
        return True


class StepperSlave(SlaveBase):
    """FMU of a plant of the ``plants`` package (external friction: input ``F_friction``)
    through its ``stepper()``; parameters are the plant's ``Params`` and scalar options.

    Parameters are structural for a plant (they shape its state and controllers): changes
    after initialization are applied by rebuilding the stepper only before the first step.
    """
    plant = "xml350"
    plants_package = "plants"

    @classmethod
    def plant_class(cls):
        if ":" in cls.plant:  # a plant outside the registry, e.g. "xml350:XML350Mechanics"
            mod, _, name = cls.plant.partition(":")
            return getattr(importlib.import_module(f"{cls.plants_package}.{mod}"), name)
        return importlib.import_module(cls.plants_package).PLANTS[cls.plant]

    def make_variables(self):
        return plant_variables(self.plant_class())

    def rebuild(self, initial):
        if not initial and getattr(self, "stepped", False):
            raise ValueError("plant parameters cannot change after the first step")
        cls = self.plant_class()
        values = self.param_values()
        pnames = {f.name for f in dataclasses.fields(cls.Params)}
        params = {k: v for k, v in values.items() if k in pnames}
        options = {k: v for k, v in values.items() if k not in pnames and k in cls.options}
        plant = cls(external_friction=True, **params)
        self.stepper = plant.stepper(**options)
        self.stepper.reset(self.time)
        self.in_names = list(self.stepper.input_names) + [
            n for n in getattr(self.stepper, "coupling_names", ()) if n in self.index]
        self.out_names = list(self.stepper.output_names)
        self.in_idx = [self.index[n] for n in self.in_names]
        self.out_idx = [self.index[n] for n in self.out_names]
        self.stepped = False

    def _push_inputs(self):
        self.stepper.set_inputs({n: self.values[i] for n, i in zip(self.in_names, self.in_idx)})

    def compute_outputs(self):
        self._push_inputs()
        out = self.stepper.outputs()
        for n, i in zip(self.out_names, self.out_idx):
            self.values[i] = float(out[n])

    def advance(self, t, h):
        self._push_inputs()
        self.stepper.do_step(t, h)
        self.stepped = True
        return False


# -- discrete blocks of the XML-350 loop (controllers, feedforward, trajectory) -------------

#: units of the loop signals (those not in the plant's ``signals``)
_LOOP_UNITS = {"x_d": ("m", "desired position"), "v_d": ("m/s", "desired velocity"),
               "a_d": ("m/s^2", "desired acceleration"), "x": ("m", "measured position"),
               "x_f": ("m", "target position of the move"),
               "u_ff": ("m/s^2", "friction feedforward (acceleration)"),
               "u": ("m/s^2", "acceleration command"),
               "u_sd": ("m/s^2", "feedback + acceleration feedforward"),
               "e": ("m", "position error x_d - x"), "i_cmd": ("A", "current command M_ctrl u / Kf"),
               "F_ff": ("N", "feedforward friction force estimate"),
               "x_ff": ("m", "feedforward position"), "v_ff": ("m/s", "feedforward velocity"),
               "a_ff": ("m/s^2", "feedforward acceleration")}

BLOCKS = ("sdpid", "pid", "lugre_feedforward", "xml350_trajectory")


def _block_parts(kind: str, plants_package: str):
    """(parameter Var list, input names, output names) of a loop block."""
    xml = importlib.import_module(f"{plants_package}.xml350")
    ctrl = importlib.import_module(f"{plants_package}.controllers")
    P = xml.XML350Params()
    if kind in ("sdpid", "pid"):
        pid = P.pid(state_dependent=kind == "sdpid")
        pv = _param_vars(ctrl.PIDParams)
        for v in pv:
            v.start = float(getattr(pid.params, v.name))
        pv += [Var("M_ctrl", "parameter", "Real", P.M_ctrl, "kg",
                   "mass converting acceleration to force in i_cmd [kg] (> 0)", 0.0, math.inf,
                   True),
               Var("Kf", "parameter", "Real", P.Kf, "N/A",
                   "motor force constant converting force to current in i_cmd [N/A] (> 0)",
                   0.0, math.inf, True)]
        return pv, list(ctrl.PID.input_names), list(ctrl.PID.output_names) + ["i_cmd"]
    if kind == "lugre_feedforward":
        law = xml.xml350_friction()
        pv = _param_vars(type(law.params))
        for v in pv:
            val = getattr(law.params, v.name)
            v.start = v.unset if val is None else val
        pv += [Var("mass", "parameter", "Real", P.M_ctrl, "kg",
                   "mass converting the friction force to acceleration [kg] (> 0)", 0.0,
                   math.inf, True),
               Var("Ts", "parameter", "Real", P.Ts, "s", "sample time [s] (> 0)", 0.0,
                   math.inf, True)]
        return pv, list(ctrl.LuGreFeedforward.input_names), \
            list(ctrl.LuGreFeedforward.output_names)
    if kind == "xml350_trajectory":
        pv = [Var("distance", "parameter", "Real", 1e-4, "m", "S-curve move distance [m]"),
              Var("t_move", "parameter", "Real", 1e-3, "s", "start time of the move [s] (>= 0)",
                  0.0),
              Var("Ts", "parameter", "Real", P.Ts, "s", "sample time [s] (> 0)", 0.0,
                  math.inf, True),
              Var("f_current", "parameter", "Real", P.f_current, "Hz",
                  "current-loop bandwidth used to time the feedforward [Hz] (> 0)", 0.0,
                  math.inf, True),
              Var("ff_mode", "parameter", "String", "invert", "",
                  "feedforward timing: invert, lead or none")]
        return pv, [], list(xml.TrajectoryBlock.output_names)
    raise ValueError(f"unknown block {kind!r}; choose from {BLOCKS}")


def block_variables(kind: str, plants_package: str = "plants") -> list[Var]:
    """Variables of a loop block FMU; outputs depend directly on every input (a block
    samples at the communication point with the inputs just set)."""
    pv, ins, outs = _block_parts(kind, plants_package)
    vs = list(pv)
    for n in ins:
        unit, desc = _LOOP_UNITS.get(n, ("", n))
        vs.append(Var(n, "input", "Real", 0.0, unit, desc + (f" [{unit}]" if unit else "")))
    for n in outs:
        unit, desc = _LOOP_UNITS.get(n, ("", n))
        vs.append(Var(n, "output", "Real", None, unit, desc + (f" [{unit}]" if unit else ""),
                      depends=tuple(ins)))
    return vs


class BlockSlave(SlaveBase):
    """FMU of a discrete block of the XML-350 loop (state-dependent PID of seed 003 Eq. 15,
    LuGre feedforward Eq. 16, S-curve trajectory) through ``plants.controllers
    .DiscreteStepper``: the block samples at ``start + k Ts``; reading the outputs at a
    sample instant runs that sample with the inputs just set (direct feedthrough), a step
    runs the samples inside it with the inputs held."""
    block = "sdpid"
    plants_package = "plants"

    def make_variables(self):
        return block_variables(self.block, self.plants_package)

    def exit_initialization_mode(self):
        # outputs read during initialization may have run the sample at t0 before the
        # inputs were connected: start from a fresh block so t0 samples the final inputs
        self.params_dirty = True
        super().exit_initialization_mode()

    def rebuild(self, initial):
        if not initial and getattr(self, "stepped", False):
            raise ValueError("block parameters cannot change after the first step")
        pk = self.plants_package
        xml = importlib.import_module(f"{pk}.xml350")
        ctrl = importlib.import_module(f"{pk}.controllers")
        vals = self.param_values()
        self.gain = None
        if self.block in ("sdpid", "pid"):
            names = {f.name for f in dataclasses.fields(ctrl.PIDParams)}
            blk = ctrl.PID(ctrl.PIDParams(**{k: v for k, v in vals.items() if k in names}))
            self.gain = vals["M_ctrl"] / vals["Kf"]
        elif self.block == "lugre_feedforward":
            fr = importlib.import_module(pk.replace("_plants", "_friction")
                                         if pk.endswith("_plants") else "friction")
            names = {f.name for f in dataclasses.fields(fr.LuGreParams)}
            law = fr.LuGre(fr.LuGreParams(**{k: v for k, v in vals.items() if k in names}))
            blk = ctrl.LuGreFeedforward(law, vals["mass"], vals["Ts"])
        else:
            src = importlib.import_module(f"{pk}.sources")
            blk = xml.TrajectoryBlock(src.SCurve(vals["distance"], t0=vals["t_move"]),
                                      sample_time=vals["Ts"], f_current=vals["f_current"],
                                      ff_mode=vals["ff_mode"])
        self.stepper = ctrl.DiscreteStepper(blk, start=self.time)
        self.in_names = list(self.stepper.input_names)
        self.in_idx = [self.index[n] for n in self.in_names]
        self.out_names = list(self.stepper.output_names)
        self.out_idx = [self.index[n] for n in self.out_names]
        self.stepped = False

    def _push_inputs(self):
        if self.in_names:
            self.stepper.set_inputs({n: self.values[i]
                                     for n, i in zip(self.in_names, self.in_idx)})

    def compute_outputs(self):
        self._push_inputs()
        out = self.stepper.outputs()
        for n, i in zip(self.out_names, self.out_idx):
            self.values[i] = float(out[n])
        if self.gain is not None:
            self.values[self.index["i_cmd"]] = self.gain * self.values[self.index["u"]]

    def advance(self, t, h):
        self._push_inputs()
        self.stepper.do_step(t, h)
        self.stepped = True
        return False


# -- friction effects block ------------------------------------------------------------------
#: inputs of the friction_effects block: (name, unit, description)
EFFECTS_INPUTS = (("F_law", "N", "friction force of the law FMU"),
                  ("v", "m/s", "sliding velocity"),
                  ("a", "m/s2", "acceleration"),
                  ("x", "m", "position"),
                  ("load", "N", "normal load"))
#: parameters that must be > 0
_EFFECTS_POSITIVE = ("a_s", "v_c", "T", "L0")


def effects_variables(friction_package: str = "friction") -> list[Var]:
    """Variables of the ``friction_effects`` block: the law's force in, the force with the
    extensions of ``friction.extensions`` out (switches ``use_*`` = 0 or 1)."""
    ext = importlib.import_module(f"{friction_package}.extensions")
    vs = []
    for name, start, unit, desc in ext.EXTENSION_PARAMS:
        if name.startswith("use_"):
            vs.append(Var(name, "parameter", "Real", start, unit, f"{desc} [-] (0 or 1)",
                          0.0, 1.0))
        elif name in _EFFECTS_POSITIVE:
            vs.append(Var(name, "parameter", "Real", start, unit, f"{desc} [{unit}]", 0.0,
                          math.inf, True))
        else:
            vs.append(Var(name, "parameter", "Real", start, unit, f"{desc} [{unit}]"))
    ins = tuple(n for n, _, _ in EFFECTS_INPUTS)
    for name, unit, desc in EFFECTS_INPUTS:
        vs.append(Var(name, "input", "Real", 1.0 if name == "load" else 0.0, unit,
                      f"{desc} [{unit}]"))
    vs.append(Var("F", "output", "Real", None, "N",
                  "friction force with the switched-on extensions [N]", depends=ins))
    return vs


class EffectsSlave(SlaveBase):
    """FMU block between a friction-law FMU and a plant FMU: ``F = extension_force(F_law, v,
    a, x, load, t, e)`` (``friction.extensions``: the diagnosis' acceleration, load, position
    and drift candidates), evaluated at the communication points; no state but the time."""
    friction_package = "friction"

    def make_variables(self):
        return effects_variables(self.friction_package)

    def rebuild(self, initial):
        ext = importlib.import_module(f"{self.friction_package}.extensions")
        p = self.param_values()
        if p["use_pos"] > 0.5 and not p["x_hi"] > p["x_lo"]:
            raise ValueError(f"x_hi = {p['x_hi']!r} must be > x_lo = {p['x_lo']!r} [m]")
        self.e = np.array([float(p[n]) for n, _, _, _ in ext.EXTENSION_PARAMS])
        self.kernel = ext.extension_force
        self.in_idx = [self.index[n] for n, _, _ in EFFECTS_INPUTS]
        self.out_i = self.index["F"]

    def compute_outputs(self):
        vals = self.values
        F, v, a, x, load = (vals[i] for i in self.in_idx)
        vals[self.out_i] = float(self.kernel(F, v, a, x, load, self.time, self.e))

    def advance(self, t, h):
        self.time = t + h
        return False
