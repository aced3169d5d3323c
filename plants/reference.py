"""The plants' reference integrator: the monolithic ODE of plant + friction states with
``scipy.integrate.solve_ivp`` (Radau) between sample instants, discrete values held
(``Plant.simulate(method="reference")``).

A law whose coefficients jump at |v| = vc (:func:`friction.regimes.regime_split`) is
integrated regime by regime: ``"low"`` and ``"high"`` hold one smooth law each, the
crossings of |v| = vc end a segment as located events, and ``"slide"`` follows the Filippov
sliding motion along the surface while both regimes push the velocity onto it. The rules on
the surface (:func:`friction.regimes.filippov`, :func:`friction.regimes.surface_regime`)
are the ones the fast stepper (:mod:`plants.stepper`) applies.

scipy is imported here only: FMUs and the stepper must not need it.
"""
from __future__ import annotations

import math
import time as _time

import numpy as np

from friction.regimes import filippov, regime_split, surface_rate, surface_regime

from .base import Experiment, Plant, structured

__all__ = ["ReferenceIntegrator"]


class _Event:
    """A terminal ``solve_ivp`` event: ``fn(t, y, d, u)`` crossing zero in ``direction``."""
    terminal = True

    def __init__(self, fn, direction: float):
        self.fn, self.direction = fn, direction

    def __call__(self, t, y, d, u, mode):
        return self.fn(t, y, d, u)


class ReferenceIntegrator:
    """One reference run of ``plant`` over the experiment ``exp``.

    Parameters
    ----------
    plant : Plant
        A plant with an internal friction law.
    exp : Experiment
        Start, stop and output step.
    rtol : float
        Relative tolerance of Radau; the absolute tolerances are ``10 rtol`` times the
        plant's ``state_scale`` and the law's ``z_max()``.
    progress : callable(n, info), optional
        Progress in output samples (a :class:`friction.progress.Progress`).
    inputs : callable, optional
        ``inputs(t) -> dict`` of external inputs, held over each output interval.
    time_budget : float, optional
        Wall-clock budget [s]; ``TimeoutError`` once exceeded.

    Notes
    -----
    States ``y = [plant states, law states]``; a segment is an interval between breakpoints
    (sample instants of the discrete part, output instants when inputs are given, the stop)
    with the discrete values ``d`` and the inputs ``u`` held. ``mode`` is the regime held:
    ``"smooth"`` (a law without a switch), ``"low"``, ``"high"`` or ``"slide"``.
    """

    #: regime switches in one segment above which the motion is taken as Zeno
    MAX_EVENTS = 10_000

    def __init__(self, plant: Plant, exp: Experiment, rtol: float, progress=None,
                 inputs=None, time_budget: float | None = None):
        if plant.external_friction:
            raise ValueError("the reference integrator needs an internal friction law "
                             "(external_friction=False)")
        self.plant, self.exp, self.rtol = plant, exp, rtol
        self.progress, self.inputs, self.time_budget = progress, inputs, time_budget
        self.law = law = plant.friction
        self.ns = len(plant.state_names)
        nz = len(law.state_names)
        self.eps = 1e-12 * max(1.0, abs(exp.stop))
        scale = (np.ones(self.ns) if plant.state_scale is None
                 else np.asarray(plant.state_scale, float))
        zscale = np.full(nz, getattr(law, "z_max", lambda: 1e-5)())
        self.atol = rtol * np.concatenate((scale, zscale)) * 10.0
        self.deadline = None if time_budget is None else _time.monotonic() + float(time_budget)
        # one smooth law per regime ("low", "high"); "slide" mixes them along |v| = vc
        self.split = regime_split(law)
        self.laws = ({"smooth": law} if self.split is None
                     else {"low": self.split.low, "high": self.split.high})

    # -- the vector field ----------------------------------------------------------------------
    def _friction_force(self, t, y, d, u, law, a_guess=0.0):
        x, v, load = self.plant.contact(t, y[:self.ns], d, u)
        kw = {}
        if "x" in law.extra_inputs:
            kw["x"] = x
        if "load" in law.extra_inputs:
            kw["load"] = load
        if "a" in law.extra_inputs:
            kw["a"] = a_guess
        return law.force(y[self.ns:], v, **kw), v, kw

    def _smooth_parts(self, t, y, d, u, law):
        """(F, ds, dz) of one smooth law at (t, y)."""
        p, s = self.plant, y[:self.ns]
        F, v, kw = self._friction_force(t, y, d, u, law)
        ds = p.derivatives(t, s, d, F, u)
        if "a" in law.extra_inputs:  # acceleration-dependent law: fixed point on a
            for _ in range(4):
                a = p.contact_acceleration(t, s, ds, d, u)
                F, v, kw = self._friction_force(t, y, d, u, law, a)
                ds = p.derivatives(t, s, d, F, u)
        dz = law.derivatives(y[self.ns:], v, **kw)
        return F, ds, dz

    def _rates(self, t, y, d, u):
        """Filippov weight and d|v|/dt of both regimes, with their (F, ds, dz)."""
        p, s = self.plant, y[:self.ns]
        low = self._smooth_parts(t, y, d, u, self.laws["low"])
        high = self._smooth_parts(t, y, d, u, self.laws["high"])
        v = p.contact(t, s, d, u)[1]
        al, gl, gh = filippov(v, p.contact_acceleration(t, s, low[1], d, u),
                              p.contact_acceleration(t, s, high[1], d, u))
        return al, gl, gh, low, high

    def parts(self, t, y, d, u, mode):
        """(F, ds, dz) in regime ``mode``; the sliding field is the Filippov combination."""
        if self.deadline is not None and _time.monotonic() > self.deadline:
            raise TimeoutError(f"{self.plant.name}: reference integrator of {self.law.name} "
                               f"exceeded the time budget of {self.time_budget:g} s at "
                               f"t = {t:.6g} s")
        if mode == "slide":
            al, _, _, low, high = self._rates(t, y, d, u)
            return tuple(al * lo + (1 - al) * hi for lo, hi in zip(low, high))
        return self._smooth_parts(t, y, d, u, self.laws[mode])

    def _rhs(self, t, y, d, u, mode):
        _, ds, dz = self.parts(t, y, d, u, mode)
        return np.concatenate((ds, dz))

    # -- the switching surface |v| = vc -----------------------------------------------------------
    def _sigma(self, t, y, d, u):
        """Distance |v| - vc from the switching surface [m/s]."""
        return abs(self.plant.contact(t, y[:self.ns], d, u)[1]) - self.split.vc

    def _rate(self, t, y, d, u, regime):
        """d|v|/dt under one regime's field [m/s^2]."""
        p, s = self.plant, y[:self.ns]
        ds = self._smooth_parts(t, y, d, u, self.laws[regime])[1]
        return surface_rate(p.contact(t, s, d, u)[1], p.contact_acceleration(t, s, ds, d, u))

    def classify(self, t, y, d, u, prev):
        """Regime at (t, y): by the side of the surface, or on it by where the two fields
        push (:func:`friction.regimes.surface_regime`; a repulsive surface keeps the present
        side)."""
        if self.split is None:
            return "smooth"
        sg = self._sigma(t, y, d, u)
        if prev == "slide" or abs(sg) <= 1e-9 * self.split.vc:
            _, gl, gh, _, _ = self._rates(t, y, d, u)
            keep = prev if prev in ("low", "high") else ("low" if sg < 0 else "high")
            return surface_regime(gl, gh, keep)
        return "low" if sg < 0 else "high"

    def _events(self, mode):
        """Terminal events that end a segment held in ``mode``."""
        if mode in ("low", "high"):   # the crossing of the surface out of this side
            return [_Event(self._sigma, 1.0 if mode == "low" else -1.0)]
        if mode == "slide":
            # the low side stops pushing up: leave down; the high side stops pushing down:
            # leave up
            return [_Event(lambda t, y, d, u: self._rate(t, y, d, u, "low"), -1.0),
                    _Event(lambda t, y, d, u: self._rate(t, y, d, u, "high"), 1.0)]
        return None

    def _segment(self, ta, tb, y, d, u, t_eval, mode):
        """Integrate [ta, tb] with d, u held; returns ([(tk, yk, mode)], y(tb), mode)."""
        from scipy.integrate import solve_ivp  # reference only: FMUs must not need scipy

        eps = self.eps
        out = []
        t = ta
        n_events = 0
        t_ev = np.concatenate((t_eval, [tb])) if (
            t_eval.size == 0 or abs(t_eval[-1] - tb) > eps) else t_eval
        forced = None
        while True:
            mode = forced or self.classify(t, y, d, u, mode)
            forced = None
            te = t_ev[t_ev > t + eps]
            sol = solve_ivp(self._rhs, (t, tb), y, method="Radau", rtol=self.rtol,
                            atol=self.atol, args=(d, u, mode), first_step=min(tb - t, 1e-7),
                            t_eval=te, events=self._events(mode))
            if sol.status < 0:
                raise RuntimeError(f"{self.plant.name}: reference integrator failed at "
                                   f"t={t:.6g} s: {sol.message}")
            for k, tk in enumerate(sol.t):
                if abs(tk - tb) > eps:
                    out.append((tk, sol.y[:, k], mode))
            if sol.status == 0:
                return out, sol.y[:, -1], mode
            # an event: continue from it in the regime it leads to
            j = next(i for i, ev in enumerate(sol.t_events) if ev.size)
            t, y = float(sol.t_events[j][0]), sol.y_events[j][0]
            if mode == "slide":
                forced = "low" if j == 0 else "high"
            n_events += 1
            if n_events > self.MAX_EVENTS:
                raise RuntimeError(f"{self.plant.name}: more than {self.MAX_EVENTS} regime "
                                   f"switches of {self.law.name} in [{ta:.6g}, {tb:.6g}] s "
                                   "(Zeno)")
            if t >= tb - eps:
                return out, y, (forced or self.classify(t, y, d, u, mode))

    # -- the run ----------------------------------------------------------------------------------
    def _breakpoints(self, times):
        """Segment ends (sample instants of the discrete part, the stop time, and the output
        instants when inputs are given) and which of them are sample instants."""
        exp, eps = self.exp, self.eps
        Ts = self.plant._sample_period()
        if Ts is not None:
            nsamp = int(math.floor((exp.stop - exp.start) / Ts + 1e-9))
            samples = exp.start + Ts * np.arange(nsamp + 1)
        else:
            samples = np.array([exp.start])
        bps = np.union1d(samples, [times[-1]])
        if self.inputs is not None:
            bps = np.union1d(bps, times)
        bps = bps[np.concatenate(([True], np.diff(bps) > eps))]
        is_sample = np.zeros(bps.size, bool)
        is_sample[np.searchsorted(bps, samples - eps)] = True
        return bps, is_sample

    def run(self) -> np.ndarray:
        """Structured array, ``time`` first, then the plant's ``all_output_names``."""
        p, exp, eps, inputs = self.plant, self.exp, self.eps, self.inputs
        ns = self.ns
        times = exp.times()
        bps, is_sample = self._breakpoints(times)
        y = np.concatenate((np.asarray(p.initial_state(), float), self.law.initial_state()))
        d = np.asarray(p.initial_discrete(), float)
        u = p._u(inputs(exp.start) if inputs else None)
        cols = {n: np.empty(times.size) for n in p.all_output_names}
        ti = 0
        mode = self.classify(exp.start, y, d, u, "low")

        def record(t, y, d, u, mode):
            nonlocal ti
            F, _, _ = self.parts(t, y, d, u, mode)
            out = p.output(t, y[:ns], d, F, u)
            out["F"] = F
            for n in cols:
                cols[n][ti] = out[n]
            ti += 1
            if self.progress is not None and ti % 100 == 0:
                self.progress(100, f"t={t:.4g} s")

        if abs(times[0] - bps[0]) <= eps:  # the start instant
            if is_sample[0]:
                d = np.asarray(p.discrete_update(bps[0], y[:ns], d, u), float)
            record(bps[0], y, d, u, self.classify(bps[0], y, d, u, mode))
        for j in range(1, bps.size):
            ta, tb = bps[j - 1], bps[j]
            lo = np.searchsorted(times, ta + eps, side="left")
            hi = np.searchsorted(times, tb + eps, side="left")
            inner, y, mode = self._segment(ta, tb, y, d, u, times[lo:hi], mode)
            for tk, yk, mk in inner:
                record(tk, yk, d, u, mk)   # output inside the segment: d held
            if is_sample[j]:
                d = np.asarray(p.discrete_update(tb, y[:ns], d, u), float)
            if ti < times.size and abs(tb - times[ti]) <= eps:
                if inputs is not None:
                    u = p._u(inputs(tb))
                record(tb, y, d, u, self.classify(tb, y, d, u, mode))
        return structured({"time": times, **cols})
