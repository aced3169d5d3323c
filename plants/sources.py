"""Trajectory generators (the ``Sources`` role): sine, triangle, trapezoidal velocity
plateaus, PRBS, low-pass coloured noise (8th-order Chebyshev I, seed 003) and the S-curve
point-to-point move (seed 003).

Every generator is a callable ``traj(t) -> (s, v, a)`` [m, m/s, m/s^2] that accepts a
scalar or an array of times. Signals that are generated on a grid (PRBS, coloured noise)
are held (PRBS) or linearly interpolated between grid points. Only numpy at import time:
the coloured-noise filter design imports scipy when it is built (offline, never in FMUs).
"""
from __future__ import annotations

import bisect
import math

import numpy as np

__all__ = ["Sine", "Triangle", "VelocityPlateaus", "PRBS", "ColoredNoise", "SCurve",
           "Sampled", "prbs_sequence"]


def _as(t):
    return np.asarray(t, dtype=float)


def _out(s, v, a, t):
    if np.ndim(t) == 0:
        return float(s), float(v), float(a)
    return s, v, a


class Sine:
    """Position sine ``s = offset + amplitude sin(2 pi f t + phase)``.

    Parameters
    ----------
    amplitude : float
        Amplitude [m].
    frequency : float
        Frequency [Hz] (> 0).
    offset : float
        Offset [m].
    phase : float
        Phase [rad].
    """

    def __init__(self, amplitude: float, frequency: float, offset: float = 0.0,
                 phase: float = 0.0):
        if not frequency > 0:
            raise ValueError(f"frequency = {frequency!r} is out of bounds: must be > 0 [Hz]")
        self.amplitude, self.frequency = float(amplitude), float(frequency)
        self.offset, self.phase = float(offset), float(phase)

    def __call__(self, t):
        t = _as(t)
        w = 2 * np.pi * self.frequency
        arg = w * t + self.phase
        return _out(self.offset + self.amplitude * np.sin(arg),
                    self.amplitude * w * np.cos(arg),
                    -self.amplitude * w * w * np.sin(arg), t)


class Triangle:
    """Position triangle wave of ``amplitude`` [m] and ``frequency`` [Hz]: constant speed
    ``4 A f`` alternating in sign (acceleration zero between the reversals).

    Starts at 0 moving in +s (like a sine), peaks at ``A`` at a quarter period.

    Parameters
    ----------
    amplitude : float
        Peak position [m].
    frequency : float
        Frequency [Hz] (> 0).
    """

    def __init__(self, amplitude: float, frequency: float):
        if not frequency > 0:
            raise ValueError(f"frequency = {frequency!r} is out of bounds: must be > 0 [Hz]")
        self.amplitude, self.frequency = float(amplitude), float(frequency)

    def __call__(self, t):
        t = _as(t)
        A, f = self.amplitude, self.frequency
        ph = np.mod(t * f + 0.25, 1.0)          # 0..1, position = A at ph = 0.5
        s = A * (1.0 - 4.0 * np.abs(ph - 0.5))
        v = np.where(ph < 0.5, 4 * A * f, -4 * A * f)
        return _out(s, v, np.zeros_like(s), t)


class VelocityPlateaus:
    """Trapezoidal velocity profile: constant-velocity plateaus joined by constant-acceleration
    ramps (Stribeck-curve protocols: seed 000's 48 speeds, seed 003's +-30 mm/s).

    Parameters
    ----------
    speeds : sequence of float
        Plateau velocities [m/s], visited in order, starting from rest.
    accel : float
        Ramp acceleration magnitude [m/s^2] (> 0).
    plateau : float
        Duration of each plateau [s] (> 0).
    rest : float
        Duration at rest before the first ramp and after the last [s].
    return_to_zero : bool
        Ramp to 0 between plateaus (each plateau starts from rest, like trapezoids).
    """

    def __init__(self, speeds, accel: float, plateau: float, rest: float = 0.0,
                 return_to_zero: bool = True):
        speeds = np.asarray(speeds, dtype=float).ravel()
        if speeds.size == 0:
            raise ValueError("speeds: need at least one plateau velocity")
        if not accel > 0:
            raise ValueError(f"accel = {accel!r} is out of bounds: must be > 0 [m/s^2]")
        if not plateau > 0:
            raise ValueError(f"plateau = {plateau!r} is out of bounds: must be > 0 [s]")
        # knots of the piecewise-linear velocity
        tk, vk = [0.0], [0.0]
        if rest > 0:
            tk.append(rest)
            vk.append(0.0)
        self.windows = []  # (t_begin, t_end, speed) of each plateau
        for sp in speeds:
            if return_to_zero and vk[-1] != 0.0:
                tk.append(tk[-1] + abs(vk[-1]) / accel)
                vk.append(0.0)
            tk.append(tk[-1] + abs(sp - vk[-1]) / accel)
            vk.append(sp)
            tk.append(tk[-1] + plateau)
            vk.append(sp)
            self.windows.append((tk[-2], tk[-1], float(sp)))
        tk.append(tk[-1] + abs(vk[-1]) / accel)
        vk.append(0.0)
        if rest > 0:
            tk.append(tk[-1] + rest)
            vk.append(0.0)
        self.tk, self.vk = np.array(tk), np.array(vk)
        # position at the knots: exact integral of the piecewise-linear velocity
        self.sk = np.concatenate(([0.0], np.cumsum(0.5 * (self.vk[1:] + self.vk[:-1])
                                                   * np.diff(self.tk))))
        self.duration = float(self.tk[-1])

    def __call__(self, t):
        t = _as(t)
        tc = np.clip(t, self.tk[0], self.tk[-1])
        i = np.clip(np.searchsorted(self.tk, tc, side="right") - 1, 0, self.tk.size - 2)
        dt = np.diff(self.tk)[i]
        slope = np.where(dt > 0, (self.vk[i + 1] - self.vk[i]) / np.where(dt > 0, dt, 1), 0.0)
        tau = tc - self.tk[i]
        v = self.vk[i] + slope * tau
        s = self.sk[i] + self.vk[i] * tau + 0.5 * slope * tau ** 2
        return _out(s, v, slope, t)


def prbs_sequence(n: int, order: int = 11, seed: int = 1) -> np.ndarray:
    """Maximum-length binary sequence (+-1) of ``n`` chips from a Fibonacci LFSR.

    ``order`` in 5..16 selects the feedback taps (period 2^order - 1); ``seed`` the start
    register (non-zero).
    """
    taps = {5: (5, 3), 6: (6, 5), 7: (7, 6), 8: (8, 6, 5, 4), 9: (9, 5), 10: (10, 7),
            11: (11, 9), 12: (12, 11, 10, 4), 13: (13, 12, 11, 8), 14: (14, 13, 12, 2),
            15: (15, 14), 16: (16, 15, 13, 4)}
    if order not in taps:
        raise ValueError(f"order = {order!r}: must be one of {sorted(taps)}")
    reg = (int(seed) % (2 ** order - 1)) + 1
    out = np.empty(int(n))
    for k in range(int(n)):
        bit = 0
        for tp in taps[order]:
            bit ^= (reg >> (tp - 1)) & 1
        out[k] = 1.0 if reg & 1 else -1.0
        reg = ((reg << 1) | bit) & ((1 << order) - 1)
    return out


class PRBS:
    """Pseudo-random binary ACCELERATION signal (seed 003's pre-sliding excitation).

    A maximum-length sequence of +-``rms`` [m/s^2] (a binary signal's RMS is its level)
    with a chip rate of ``f_max / 0.443`` so its spectrum is flat (-3 dB) up to ``f_max``
    [Hz]; held between chips. Position and velocity are the exact integrals (zero start).

    Parameters
    ----------
    rms : float
        Level = RMS of the acceleration [m/s^2] (seed 003: 5 mm/s^2).
    f_max : float
        Bandwidth [Hz] (seed 003: 500 Hz).
    duration : float
        Length [s].
    seed : int
        LFSR start register.
    order : int
        Length of the LFSR register (period ``2**order - 1`` bits).
    """

    def __init__(self, rms: float = 5e-3, f_max: float = 500.0, duration: float = 2.0,
                 seed: int = 1, order: int = 11):
        if not rms > 0:
            raise ValueError(f"rms = {rms!r} is out of bounds: must be > 0 [m/s^2]")
        if not f_max > 0:
            raise ValueError(f"f_max = {f_max!r} is out of bounds: must be > 0 [Hz]")
        self.chip = 0.443 / f_max
        n = int(math.ceil(duration / self.chip)) + 1
        self.levels = rms * prbs_sequence(n, order, seed)
        self.levels -= self.levels.mean()  # no net drift of the velocity
        self.rms, self.f_max, self.duration = float(rms), float(f_max), float(duration)
        tk = self.chip * np.arange(n + 1)
        vk = np.concatenate(([0.0], np.cumsum(self.levels * self.chip)))
        sk = np.concatenate(([0.0], np.cumsum(vk[:-1] * self.chip
                                              + 0.5 * self.levels * self.chip ** 2)))
        self.tk, self.vk, self.sk = tk, vk, sk

    def __call__(self, t):
        t = _as(t)
        i = np.clip((t / self.chip).astype(int), 0, self.levels.size - 1)
        tau = t - self.tk[i]
        a = self.levels[i]
        v = self.vk[i] + a * tau
        s = self.sk[i] + self.vk[i] * tau + 0.5 * a * tau ** 2
        return _out(s, v, a, t)


class ColoredNoise:
    """Low-pass coloured-noise VELOCITY reference (seed 003 refinement step).

    Zero-mean unit-variance Gaussian white noise, filtered by an ``order``-th order
    Chebyshev type I low-pass (cut-off ``cutoff`` [Hz], pass-band ripple ``ripple`` [dB]),
    scaled to the velocity RMS ``rms`` [m/s]; position is its integral (trapezoid) and
    acceleration its derivative, on a grid of ``rate`` [Hz], interpolated linearly.

    Parameters
    ----------
    rms : float
        Velocity RMS [m/s].
    cutoff : float
        Cut-off frequency [Hz] (seed 003: 10 Hz).
    duration : float
        Length [s].
    seed : int
        Noise realisation (seed 003 uses two: identification and validation).
    order : int
        Filter order (seed 003: 8).
    ripple : float
        Pass-band ripple [dB].
    rate : float
        Generation grid [Hz].
    """

    def __init__(self, rms: float = 5e-3, cutoff: float = 10.0, duration: float = 14.0,
                 seed: int = 0, order: int = 8, ripple: float = 0.5, rate: float = 1000.0):
        from scipy import signal  # offline design; never needed inside an FMU

        if not 0 < cutoff < rate / 2:
            raise ValueError(f"cutoff = {cutoff!r} is out of bounds: must be in (0, "
                             f"{rate / 2:g}) [Hz] for rate = {rate:g} Hz")
        n = int(round(duration * rate)) + 1
        rng = np.random.default_rng(seed)
        sos = signal.cheby1(order, ripple, cutoff, btype="low", fs=rate, output="sos")
        # settle the filter on a lead-in, then fade in so the stage starts from rest
        lead = int(5 * rate / cutoff)
        w = signal.sosfilt(sos, rng.standard_normal(n + lead))[lead:]
        w *= rms / np.std(w)
        fade = np.clip(np.arange(n) / (0.5 * rate / cutoff), 0, 1)
        v = w * fade * fade[::-1]
        self.t = np.arange(n) / rate
        self.v = v
        self.s = np.concatenate(([0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) / rate)))
        self.a = np.gradient(v, self.t, edge_order=2)
        self.duration = float(self.t[-1])

    def __call__(self, t):
        t = _as(t)
        return _out(np.interp(t, self.t, self.s), np.interp(t, self.t, self.v),
                    np.interp(t, self.t, self.a), t)


class SCurve:
    """Jerk-limited (7-segment) point-to-point move: the S-curve profile of seed 003.

    Constant-jerk segments; for short moves the peak acceleration and velocity are
    reduced so the profile still reaches ``distance`` exactly at rest.

    Parameters
    ----------
    distance : float
        Move length [m] (sign gives the direction).
    vmax : float
        Velocity limit [m/s] (seed 003: 0.25).
    amax : float
        Acceleration limit [m/s^2] (seed 003: 4.0).
    jerk : float
        Jerk limit [m/s^3]. Default ``amax / 5 ms`` (a 5 ms jerk time, the XPS default
        minimum jerk time; seed 003 does not print it).
    t0 : float
        Start time [s].
    x0 : float
        Start position [m].
    """

    def __init__(self, distance: float, vmax: float = 0.25, amax: float = 4.0,
                 jerk: float | None = None, t0: float = 0.0, x0: float = 0.0):
        for name, val in (("vmax", vmax), ("amax", amax)):
            if not val > 0:
                raise ValueError(f"{name} = {val!r} is out of bounds: must be > 0")
        J = amax / 5e-3 if jerk is None else float(jerk)
        if not J > 0:
            raise ValueError(f"jerk = {jerk!r} is out of bounds: must be > 0 [m/s^3]")
        d = abs(float(distance))
        self.sign = 1.0 if distance >= 0 else -1.0
        self.distance, self.t0, self.x0 = float(distance), float(t0), float(x0)
        V, A = float(vmax), float(amax)
        if d == 0:
            self.peaks = (0.0, 0.0)
            self._build(0.0, 0.0, 0.0, J)
            return
        # velocity reached with jerk-limited ramps: is A reached before V?
        if V * J < A * A:
            A = math.sqrt(V * J)
        Tj = A / J
        Ta = Tj + V / A          # duration of the acceleration phase
        if V * Ta > d:           # V not reached: find the peak velocity
            v = 0.5 * A * (-Tj + math.sqrt(Tj * Tj + 4 * d / A))
            if v * J < A * A:    # A not reached either: pure jerk ramps
                v = (d * math.sqrt(J) / 2.0) ** (2.0 / 3.0)
                A = math.sqrt(v * J)
                Tj = A / J
            V = v
            Ta = Tj + V / A
        Tv = max(0.0, d / V - Ta)
        self.peaks = (V, A)
        self._build(Tj, Ta - 2 * Tj, Tv, J)

    def _build(self, Tj, Tc, Tv, J):
        # segment durations and jerks: +J, 0, -J, 0 (cruise), -J, 0, +J
        durs = [Tj, max(Tc, 0.0), Tj, Tv, Tj, max(Tc, 0.0), Tj]
        jerks = [J, 0.0, -J, 0.0, -J, 0.0, J]
        tk, st = [0.0], [(0.0, 0.0, 0.0)]
        for T, j in zip(durs, jerks):
            s, v, a = st[-1]
            st.append((s + v * T + a * T * T / 2 + j * T ** 3 / 6, v + a * T + j * T * T / 2,
                       a + j * T))
            tk.append(tk[-1] + T)
        self.tk = np.array(tk)
        self.state = np.array(st)
        self.jerks = np.array(jerks + [0.0])
        self.duration = float(self.tk[-1])
        # the end state is (d, 0, 0) up to rounding: store the exact target
        self.state[-1] = (abs(self.distance), 0.0, 0.0)
        self._tk_list = self.tk.tolist()
        self._state_list = [tuple(r) for r in self.state.tolist()]
        self._jerk_list = self.jerks.tolist()

    @property
    def end_time(self) -> float:
        """Time the move ends [s] (``t0 + duration``)."""
        return self.t0 + self.duration

    @property
    def target(self) -> float:
        """Final position [m]."""
        return self.x0 + self.distance

    def __call__(self, t):
        if np.ndim(t) == 0:  # scalar fast path (called at every controller sample)
            tau = min(max(float(t) - self.t0, 0.0), self.duration)
            i = min(bisect.bisect_right(self._tk_list, tau) - 1, len(self._tk_list) - 1)
            dt = tau - self._tk_list[i]
            s0, v0, a0 = self._state_list[i]
            j = self._jerk_list[i]
            sg = self.sign
            return (self.x0 + sg * (s0 + v0 * dt + a0 * dt * dt / 2 + j * dt ** 3 / 6),
                    sg * (v0 + a0 * dt + j * dt * dt / 2), sg * (a0 + j * dt))
        t = _as(t)
        tau = np.clip(t - self.t0, 0.0, self.duration)
        i = np.clip(np.searchsorted(self.tk, tau, side="right") - 1, 0, self.tk.size - 1)
        dt = tau - self.tk[i]
        s0, v0, a0 = self.state[i, 0], self.state[i, 1], self.state[i, 2]
        j = self.jerks[i]
        s = s0 + v0 * dt + a0 * dt ** 2 / 2 + j * dt ** 3 / 6
        v = v0 + a0 * dt + j * dt ** 2 / 2
        a = a0 + j * dt
        return _out(self.x0 + self.sign * s, self.sign * v, self.sign * a, t)


class Sampled:
    """A trajectory given by samples ``(t, s, v, a)``, interpolated linearly.

    Parameters
    ----------
    t : array_like
        Sample times [s] (increasing).
    s : array_like
        Position samples [m].
    v : array_like, optional
        Velocity samples [m/s] (default: the gradient of ``s``).
    a : array_like, optional
        Acceleration samples [m/s^2] (default: the gradient of ``v``).
    """

    def __init__(self, t, s, v=None, a=None):
        self.t = np.asarray(t, float)
        self.s = np.asarray(s, float)
        self.v = np.gradient(self.s, self.t) if v is None else np.asarray(v, float)
        self.a = np.gradient(self.v, self.t) if a is None else np.asarray(a, float)

    def __call__(self, t):
        t = _as(t)
        return _out(np.interp(t, self.t, self.s), np.interp(t, self.t, self.v),
                    np.interp(t, self.t, self.a), t)
