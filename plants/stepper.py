"""The fast integrator of the plants: :class:`PlantStepper`, the step-by-step object an
FMU's ``doStep`` calls and ``Plant.simulate(method="fast")`` runs (numpy/numba only).

Heun's method (second order) on the plant states; the friction law's states advance with
the law's own numba kernel (:class:`plants.law_stepper.FrictionStep`; for LuGre the exact
exponential bristle update, stable at any step and stiffness), called over the substep with
the velocity at both ends. The friction force entering the derivatives is the kernel's
output at the step ends, so the stiff bristle never sees an explicit update. Discrete
updates run eagerly when time reaches a sample instant, so outputs at an instant show the
controller output computed from it.

A law whose coefficients jump at |v| = vc (:func:`friction.regimes.regime_split`) is
stepped regime by regime: each substep holds one regime, a substep crossing vc is cut at
the crossing, and the motion slides along |v| = vc (Filippov) where both regimes push onto
it, with the rules on the surface of :mod:`friction.regimes` that the reference integrator
(:mod:`plants.reference`) applies with located events.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from friction.regimes import filippov, regime_split, side, surface_regime
from friction.coupling import MEAN_INPUT, PLANT_INPUTS, SHARE_INPUT

from .law_stepper import FrictionStep

if TYPE_CHECKING:
    from .base import Plant

__all__ = ["PlantStepper"]


class PlantStepper:
    """Step-by-step simulation of a plant (what an FMU's ``doStep`` calls).

    Attributes
    ----------
    input_names, output_names, parameter_names : tuple of str
    time : float
        Current time [s].

    Notes
    -----
    ``do_step(t, h)`` integrates ``[t, t+h]`` with internal substeps no longer than
    ``substep``; discrete updates run at every sample instant ``start + k / control_rate``
    reached on the way (including ``t+h`` itself). External inputs are held over the step.

    Linearly implicit coupling (external friction only): the optional inputs
    ``coupling_names`` = ``("dF_dx", "dF_dv", "dF_dt", "d2F_dt2", "t_kink", "dF_dt_kink")``
    [N/m, N.s/m, N/s, N/s^2, s, N/s] are the friction law's local linearisation over the
    coming step. The step then integrates with

        F(t) = F_friction + dF_dx (x(t) - x_k) + dF_dv (v(t) - v_k)
               + dF_dt (t - t_k) + d2F_dt2 (t - t_k)^2 / 2
               + dF_dt_kink max(0, t - t_k - t_kink)

    where ``x_k, v_k`` is the contact motion at the start of the step, so the stiff part of
    the contact (bristle spring, damping) is resolved inside the plant's own substeps instead
    of being held over the communication step; the substep shrinks so that the explicit
    integrator stays stable against that stiffness. All default to 0 (force held).

    The output ``v_mean`` [m/s] (travel over the last step / step) lets the law FMU advance
    its state with the plant's real travel instead of the end-point velocities (which alias
    the contact's fast motion inside a long step).

    A law whose coefficients jump at |v| = ``v_switch`` [m/s] (``load_lugre``) adds the
    other side's linearisation: where |v(t)| lies on the other side of ``v_switch`` than
    ``v_k``, ``F`` gains ``dF_switch + dF_dx_switch (x - x_k) + dF_dv_switch (v - v_k)``
    [N, N/m, N.s/m]. The substeps then treat the switch like the internal law's (below), and
    the output ``low_share`` [1] tells the law FMU which share of the step its state spent on
    the low side.

    Regime switches. For a law with a :func:`friction.regimes.regime_split` (internal, or
    through ``v_switch``) each substep holds one regime (both Heun stages and the law's state
    update), so the regime that drives the motion is the one that drives the law's state; a
    substep that crosses |v| = vc is cut at the crossing (linear interpolation), and where
    both regimes push the velocity onto the surface the motion slides along it: the Filippov
    combination ``alpha low + (1 - alpha) high`` of the whole field (force and law state),
    with alpha keeping d|v|/dt = 0, until one side stops pushing. This converges to the
    reference integrator's Filippov solution as the substep shrinks; switching regimes
    sample by sample (chattering) does not.
    """

    #: inputs of the linearly implicit coupling (external friction mode; the port names of
    #: friction.coupling, shared with the law FMUs and the master)
    COUPLING_INPUTS = PLANT_INPUTS
    #: output of the coupling (external friction mode): share of the last step spent on the
    #: low side of |v| = v_switch (a sliding stretch counts with its Filippov weight)
    SHARE_OUTPUT = SHARE_INPUT
    #: output of the coupling (external friction mode): mean contact velocity over the last
    #: step, travel / step [m/s] (the law advances its state with the plant's real travel)
    MEAN_OUTPUT = MEAN_INPUT

    def __init__(self, plant: Plant, *, substep: float | None = None, start: float = 0.0,
                 friction_method: str = "exact"):
        """

        Parameters
        ----------
        plant : Plant
            The plant to step (internal or external friction).
        substep : float, optional
            Internal step [s] (default ``plant.max_substep``).
        start : float
            Start time [s].
        friction_method : {"exact", "euler"}
            Bristle update of the internal law.
        """
        self.plant = plant
        self.coupling_names = self.COUPLING_INPUTS if plant.external_friction else ()
        self.input_names = plant.all_input_names
        self.output_names = plant.all_output_names + (
            (self.SHARE_OUTPUT, self.MEAN_OUTPUT) if plant.external_friction else ())
        self.parameter_names = plant.parameter_names
        self.substep = float(substep or plant.max_substep)
        if not self.substep > 0:
            raise ValueError(f"substep = {substep!r} is out of bounds: must be > 0 [s]")
        self.start = float(start)
        self.fric = None if plant.external_friction else FrictionStep(plant.friction,
                                                                      friction_method)
        self._sides = None   # internal law with a regime split: (vc, {side: FrictionStep})
        if self.fric is not None:
            split = regime_split(plant.friction)
            if split is not None:
                self._sides = (split.vc, {"low": FrictionStep(split.low, friction_method),
                                          "high": FrictionStep(split.high, friction_method)})
        self.reset()

    # -- public API -------------------------------------------------------------------------
    def reset(self, start: float | None = None) -> None:
        """Back to the initial state at time ``start`` (default: the stepper's start).

        Parameters
        ----------
        start : float, optional
            New start time [s].
        """
        if start is not None:
            self.start = float(start)
        p = self.plant
        self.time = self.start
        self.s = np.asarray(p.initial_state(), dtype=float).copy()
        self.d = np.asarray(p.initial_discrete(), dtype=float).copy()
        self.u = p._u(None)
        self.z = None if self.fric is None else p.friction.initial_state().astype(float)
        self._a = 0.0
        # coupling: dF_dx [N/m], dF_dv [N.s/m], dF_dt [N/s], d2F_dt2 [N/s^2], t_kink [s],
        # dF_dt_kink [N/s]
        self._lin = [0.0] * len(self.COUPLING_INPUTS)
        self._lin_ref = None    # (F_k, x_k, v_k, substep) of the current step when linearised
        self._mode = None       # regime held by the substeps: "low", "high" or "slide"
        self._low_share = 0.0   # share of the last step on the low side (Filippov weighted)
        self._v_mean = 0.0      # travel / step of the last step [m/s]
        self._carry = None      # (side, force at the end of the last substep on that side)
        Ts = p._sample_period()
        self._Ts = Ts
        self._k = 0  # index of the next sample instant
        self._F = self._friction_now()
        self._sample_due(self.time)

    def set_inputs(self, values: dict) -> None:
        """Set external inputs (held until changed); unknown names raise ``KeyError``.

        Parameters
        ----------
        values : dict
            Input values by name (``input_names`` and, in external-friction mode, the coupling
            inputs), SI units.
        """
        for k, val in values.items():
            if k in self.coupling_names:
                self._lin[self.coupling_names.index(k)] = float(val)
                continue
            if k not in self.u:
                raise KeyError(f"{self.plant.name}: unknown input {k!r}; inputs are "
                               f"{list(self.u) + list(self.coupling_names)}")
            self.u[k] = float(val)
        if self.fric is None:
            self._F = self.u["F_friction"]

    def set_parameters(self, **values) -> None:
        """Change plant parameters (validated); call before ``reset`` for initial values.

        Parameters
        ----------
        **values
            Plant parameter values (SI units) by name.
        """
        self.plant = self.plant.with_params(**values)

    def outputs(self) -> dict[str, float]:
        """Current outputs (names ``output_names``)."""
        p = self.plant
        out = dict(p.output(self.time, self.s, self.d, self._F, self.u))
        if self.fric is not None:
            out["F"] = self._F
        else:
            out[self.SHARE_OUTPUT] = self._low_share
            out[self.MEAN_OUTPUT] = self._v_mean
        return out

    def do_step(self, t: float, h: float) -> bool:
        """Integrate from ``t`` to ``t + h`` [s]; returns True.

        Parameters
        ----------
        t : float
            Current time [s] (the stepper's time).
        h : float
            Step length [s] (> 0).
        """
        if abs(t - self.time) > 1e-9 * max(1.0, abs(t)):
            raise ValueError(f"do_step(t={t!r}) but the stepper is at time {self.time!r}")
        if not h > 0:
            raise ValueError(f"h = {h!r} is out of bounds: must be > 0 [s]")
        t_end = t + h
        tol = 1e-12 * max(1.0, abs(t_end))
        tc = self.time
        self._lin_ref = None
        self._t_low = 0.0
        x_start = self.plant.contact(tc, self.s, self.d, self.u)[0] if self.fric is None \
            else 0.0
        if self.fric is None and any(c != 0.0 for c in self._lin):
            x_k, v_k, _ = self.plant.contact(tc, self.s, self.d, self.u)
            self._lin_ref = (self.u["F_friction"], float(x_k), float(v_k),
                             self._coupled_substep(), tc)
        while tc < t_end - tol:
            t_next = t_end
            if self._Ts is not None:
                ts = self.start + self._k * self._Ts
                if ts < t_end - tol:
                    t_next = ts
            self._integrate(tc, t_next)
            tc = t_next
            self.time = tc
            self._sample_due(tc)
        self.time = t_end
        self._low_share = min(1.0, max(0.0, self._t_low / h))
        if self.fric is None:
            self._v_mean = (self.plant.contact(t_end, self.s, self.d, self.u)[0] - x_start) / h
        return True

    # -- internals ---------------------------------------------------------------------------
    def _sample_due(self, t: float) -> None:
        if self._Ts is None:
            return
        tol = 1e-9 * self._Ts
        while self.start + self._k * self._Ts <= t + tol:
            self.d = np.asarray(self.plant.discrete_update(t, self.s, self.d, self.u), float)
            self._k += 1

    def _kin(self, t, s, ds):
        x, v, load = self.plant.contact(t, s, self.d, self.u)
        a = self.plant.contact_acceleration(t, s, ds, self.d, self.u) if ds is not None \
            else self._a
        return (x, v, a, load)

    def _friction_now(self) -> float:
        if self.fric is None:
            return self.u["F_friction"]
        x, v, load = self.plant.contact(self.time, self.s, self.d, self.u)
        if self._sides is not None:
            vc, sides = self._sides
            self._mode = side(v, vc)
            return sides[self._mode].force(self.z, x, v, self._a, load)
        return self.fric.force(self.z, x, v, self._a, load)

    def _coupled_substep(self) -> float:
        """Largest stable substep [s] against the linearised friction (Heun: |h lambda| <= 1
        on the damping, omega h <= 0.2 on the spring, a margin on the imaginary axis); with
        a regime switch, against the stiffer of both sides."""
        p, t, s, d, u = self.plant, self.time, self.s, self.d, self.u
        F = self.u["F_friction"]
        ds0 = p.derivatives(t, s, d, F, u)
        dF = 1.0 + 1e-6 * abs(F)
        ds1 = p.derivatives(t, s, d, F + dF, u)
        # the contact's inverse mass: d(acceleration)/dF
        w = abs(p.contact_acceleration(t, s, ds1, d, u)
                - p.contact_acceleration(t, s, ds0, d, u)) / dF
        K, D = abs(self._lin[0]), abs(self._lin[1])
        if self._lin[6] > 0.0:
            K = max(K, abs(self._lin[0] + self._lin[8]))
            D = max(D, abs(self._lin[1] + self._lin[9]))
        h = self.substep
        if w * D > 0:
            h = min(h, 1.0 / (w * D))
        if w * K > 0:
            h = min(h, 0.2 / math.sqrt(w * K))
        return h

    def _coupled_force(self, t, s, regime=None) -> float:
        """Linearised friction at (t, s); ``regime`` ("low"/"high") forces a side of the
        switch (default: the side of the contact velocity)."""
        F_k, x_k, v_k, _, t_k = self._lin_ref
        x, v, _ = self.plant.contact(t, s, self.d, self.u)
        K, D, r, c, t_kink, r_kink, v_sw, J, dK, dD = self._lin
        tau = t - t_k
        F = F_k + K * (x - x_k) + D * (v - v_k) + (r + 0.5 * c * tau) * tau
        if r_kink != 0.0 and tau > t_kink:
            F += r_kink * (tau - t_kink)
        if v_sw > 0.0:
            low = (abs(v) < v_sw) if regime is None else regime == "low"
            if low != (abs(v_k) < v_sw):  # the other side of the switch than the law's
                F += J + dK * (x - x_k) + dD * (v - v_k)
        return F

    def _integrate_coupled(self, ta: float, tb: float) -> None:
        """Heun substeps with the linearised friction evaluated at every stage."""
        n = max(1, int(math.ceil((tb - ta) / self._lin_ref[3] - 1e-9)))
        h = (tb - ta) / n
        p, d, u = self.plant, self.d, self.u
        s = self.s
        if self._lin[6] > 0.0:   # a regime switch: substeps hold a regime, slide along it
            v_sw = self._lin[6]
            self._carry = None
            for i in range(n):
                s = self._regime_substep(ta + i * h, h, s, None, v_sw, self._coupled_side)[0]
            F = (self._filippov(tb, s, None, self._coupled_side)[1] if self._mode == "slide"
                 else self._coupled_force(tb, s))
        else:
            F = self._coupled_force(ta, s)
            for i in range(n):
                t0 = ta + i * h
                k1 = p.derivatives(t0, s, d, F, u)
                s_pred = s + h * k1
                k2 = p.derivatives(t0 + h, s_pred, d, self._coupled_force(t0 + h, s_pred), u)
                s = s + 0.5 * h * (k1 + k2)
                F = self._coupled_force(t0 + h, s)
        if not (np.all(np.isfinite(s)) and math.isfinite(F)):
            raise FloatingPointError(
                f"{p.name}: the fast integrator diverged between t={ta:.6g} s and {tb:.6g} s "
                f"(substep {h:.3g} s, coupling dF_dx = {self._lin[0]:g} N/m, dF_dv = "
                f"{self._lin[1]:g} N.s/m)")
        self.s, self._F = s, F

    # -- regime switches (friction.regimes) ---------------------------------------------------
    def _coupled_side(self, regime, t, s, z, h=0.0, kin0=None, kin1=None):
        """Linearised friction of one side (external friction): (F, state) - no law state."""
        return self._coupled_force(t, s, regime), None

    def _internal_side(self, regime, t, s, z, h=0.0, kin0=None, kin1=None):
        """Internal law of one side: force at (t, s) with state z, or, with ``h`` > 0, the
        state advanced over [t - h, t] from kin0 to kin1 and the force at its end."""
        f = self._sides[1][regime]
        if h > 0.0:
            z1, F = f.advance(z, h, kin0, kin1)
            return F, z1
        x, v, load = self.plant.contact(t, s, self.d, self.u)
        return f.force(z, x, v, self._a, load), z

    def _filippov(self, t, s, z, side_fn):
        """Filippov weight on |v| = v_switch at (t, s): ``(alpha, F_mix, g_low, g_high)``
        (:func:`friction.regimes.filippov` with each side's force)."""
        p, d, u = self.plant, self.d, self.u
        F_l = side_fn("low", t, s, z)[0]
        F_h = side_fn("high", t, s, z)[0]
        al, g_l, g_h = filippov(
            p.contact(t, s, d, u)[1],
            p.contact_acceleration(t, s, p.derivatives(t, s, d, F_l, u), d, u),
            p.contact_acceleration(t, s, p.derivatives(t, s, d, F_h, u), d, u))
        return al, al * F_l + (1.0 - al) * F_h, g_l, g_h

    def _classify(self, t, s, z, side_fn, prev):
        """Regime on the switching surface (:func:`friction.regimes.surface_regime`; a
        repulsive surface keeps ``prev``)."""
        _, _, g_l, g_h = self._filippov(t, s, z, side_fn)
        return surface_regime(g_l, g_h, prev)

    def _regime_substep(self, t0, h, s, z, v_sw, side_fn, split=True):
        """One Heun substep holding a regime (or sliding); returns (s, z) at t0 + h.

        A side substep that ends on the other side is cut at the crossing (linear in the
        states) and the rest of it runs in the regime the surface leads to.
        """
        p, d, u = self.plant, self.d, self.u
        v0 = p.contact(t0, s, d, u)[1]
        mode = self._mode
        if not split:
            pass   # the rest of a substep cut at a crossing: the regime the surface chose
        elif mode == "slide":
            mode = self._classify(t0, s, z, side_fn, side(v0, v_sw))
        elif mode is None or (mode == "low") != (abs(v0) < v_sw):
            mode = side(v0, v_sw)
        self._mode = mode
        internal = self.fric is not None
        if mode == "slide":
            al, F0, _, _ = self._filippov(t0, s, z, side_fn)
            k1 = p.derivatives(t0, s, d, F0, u)
            s_pred = s + h * k1
            z_pred = z
            if internal:
                kin0, kp = self._kin(t0, s, k1), self._kin(t0 + h, s_pred, k1)
                z_pred = (al * side_fn("low", t0 + h, s_pred, z, h, kin0, kp)[1]
                          + (1.0 - al) * side_fn("high", t0 + h, s_pred, z, h, kin0, kp)[1])
            al2, F2, _, _ = self._filippov(t0 + h, s_pred, z_pred, side_fn)
            k2 = p.derivatives(t0 + h, s_pred, d, F2, u)
            s1 = s + 0.5 * h * (k1 + k2)
            w = 0.5 * (al + al2)
            self._t_low += w * h
            if internal:
                ds_mean = 0.5 * (k1 + k2)
                kin1 = self._kin(t0 + h, s1, ds_mean)
                z = (w * side_fn("low", t0 + h, s1, z, h, kin0, kin1)[1]
                     + (1.0 - w) * side_fn("high", t0 + h, s1, z, h, kin0, kin1)[1])
                self._a = p.contact_acceleration(t0 + h, s1, ds_mean, d, u)
            return s1, z
        # one side held over both stages (and the law's state update); the force at the
        # start is the last substep's end force when it ran on the same side
        carry, self._carry = self._carry, None
        F0 = carry[1] if carry is not None and carry[0] == mode else side_fn(mode, t0, s, z)[0]
        k1 = p.derivatives(t0, s, d, F0, u)
        s_pred = s + h * k1
        if internal:
            kin0 = self._kin(t0, s, k1)
            F_pred = side_fn(mode, t0 + h, s_pred, z, h, kin0,
                             self._kin(t0 + h, s_pred, k1))[0]
        else:
            F_pred = side_fn(mode, t0 + h, s_pred, z)[0]
        k2 = p.derivatives(t0 + h, s_pred, d, F_pred, u)
        s1 = s + 0.5 * h * (k1 + k2)
        z1 = z
        F1 = None
        if internal:
            ds_mean = 0.5 * (k1 + k2)
            F1, z1 = side_fn(mode, t0 + h, s1, z, h, kin0, self._kin(t0 + h, s1, ds_mean))
            self._a = p.contact_acceleration(t0 + h, s1, ds_mean, d, u)
        a0, a1 = abs(v0), abs(p.contact(t0 + h, s1, d, u)[1])
        crossed = (a1 >= v_sw) if mode == "low" else (a1 < v_sw)
        if not (crossed and split) or a1 == a0:
            if mode == "low":
                self._t_low += h
            if not crossed and F1 is not None:
                self._carry = (mode, F1)
            return s1, z1
        th = min(1.0, max(0.0, (v_sw - a0) / (a1 - a0)))
        s_c = s + th * (s1 - s)
        z_c = None if z is None else z + th * (z1 - z)
        if mode == "low":
            self._t_low += th * h
        other = "high" if mode == "low" else "low"
        nxt = self._classify(t0 + th * h, s_c, z_c, side_fn, other)
        if nxt == mode or th >= 1.0:  # pushed back at once (discretisation): keep the end
            if mode == "low":
                self._t_low += (1.0 - th) * h
            self._mode = side(a1, v_sw)
            return s1, z1
        self._mode = nxt
        return self._regime_substep(t0 + th * h, (1.0 - th) * h, s_c, z_c, v_sw, side_fn,
                                    split=False)

    def _integrate(self, ta: float, tb: float) -> None:
        if self._lin_ref is not None:
            return self._integrate_coupled(ta, tb)
        n = max(1, int(math.ceil((tb - ta) / self.substep - 1e-9)))
        h = (tb - ta) / n
        p = self.plant
        d, u = self.d, self.u
        s, z, F = self.s, self.z, self._F
        if self._sides is not None:   # a regime switch: substeps hold a regime, slide along it
            vc = self._sides[0]
            self._carry = None
            for i in range(n):
                s, z = self._regime_substep(ta + i * h, h, s, z, vc, self._internal_side)
            if self._mode == "slide":
                F = self._filippov(tb, s, z, self._internal_side)[1]
            else:
                self._mode = side(p.contact(tb, s, d, u)[1], vc)
                F = self._internal_side(self._mode, tb, s, z)[0]
        else:
            for i in range(n):
                t0 = ta + i * h
                k1 = p.derivatives(t0, s, d, F, u)
                s_pred = s + h * k1
                if self.fric is None:
                    k2 = p.derivatives(t0 + h, s_pred, d, F, u)
                    s = s + 0.5 * h * (k1 + k2)
                    F = self.u["F_friction"]
                    continue
                kin0 = self._kin(t0, s, k1)
                _, F_pred = self.fric.advance(z, h, kin0, self._kin(t0 + h, s_pred, k1))
                k2 = p.derivatives(t0 + h, s_pred, d, F_pred, u)
                s = s + 0.5 * h * (k1 + k2)
                ds_mean = 0.5 * (k1 + k2)
                z, F = self.fric.advance(z, h, kin0, self._kin(t0 + h, s, ds_mean))
                self._a = p.contact_acceleration(t0 + h, s, ds_mean, d, u)
        if not (np.all(np.isfinite(s)) and math.isfinite(F)):
            raise FloatingPointError(
                f"{p.name}: the fast integrator diverged between t={ta:.6g} s and {tb:.6g} s "
                f"(substep {h:.3g} s); try a smaller substep= or check the parameters")
        self.s, self.z, self._F = s, z, F
