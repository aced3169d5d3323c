"""Sensors and signal conditioning: quantised position encoder, velocity/acceleration
sensors, additive measurement noise, zero-phase Butterworth filtering and second-order
finite differences (the processing chain of seeds 000 and 003).

Sensors are small objects with ``measure(value)`` for one sample (used inside plants and
FMUs, numpy only) and vectorised helpers for whole records (offline, scipy imported when
called).
"""
from __future__ import annotations

import numpy as np

__all__ = ["PositionSensor", "VelocitySensor", "AccelerationSensor", "add_noise",
           "quantize", "zero_phase_lowpass", "differentiate"]


def quantize(x, resolution: float):
    """Round to the encoder grid ``resolution`` [m] (``0``: no quantisation)."""
    if resolution < 0:
        raise ValueError(f"resolution = {resolution!r} is out of bounds: must be >= 0")
    if resolution == 0:
        return x
    return np.round(np.asarray(x, dtype=float) / resolution) * resolution if np.ndim(x) \
        else float(round(x / resolution) * resolution)


class PositionSensor:
    """Incremental encoder: position quantised to ``resolution`` [m] (seed 003: 1 nm),
    optional white noise of standard deviation ``noise`` [m].

    Parameters
    ----------
    resolution : float
        Quantisation step [m] (>= 0; 0: none).
    noise : float
        Standard deviation of the white noise [m] (>= 0).
    seed : int
        Seed of the noise generator.
    """

    def __init__(self, resolution: float = 1e-9, noise: float = 0.0, seed: int = 0):
        if resolution < 0:
            raise ValueError(f"resolution = {resolution!r} is out of bounds: must be >= 0 [m]")
        if noise < 0:
            raise ValueError(f"noise = {noise!r} is out of bounds: must be >= 0 [m]")
        self.resolution, self.noise = float(resolution), float(noise)
        self._rng = np.random.default_rng(seed)

    def measure(self, x):
        """Measured position [m] of the true position ``x`` (scalar or array).

        Parameters
        ----------
        x : float or array_like
            True position [m].
        """
        if self.noise > 0:
            x = x + self.noise * self._rng.standard_normal(np.shape(x))
        return quantize(x, self.resolution)


class VelocitySensor:
    """Velocity measurement: the true value plus white noise ``noise`` [m/s].

    Parameters
    ----------
    noise : float
        Standard deviation of the white noise [m/s] (>= 0).
    seed : int
        Seed of the noise generator.
    """

    def __init__(self, noise: float = 0.0, seed: int = 0):
        if noise < 0:
            raise ValueError(f"noise = {noise!r} is out of bounds: must be >= 0 [m/s]")
        self.noise = float(noise)
        self._rng = np.random.default_rng(seed)

    def measure(self, v):
        """

        Parameters
        ----------
        v : float or array_like
            True velocity [m/s].
        """
        return v + self.noise * self._rng.standard_normal(np.shape(v)) if self.noise else v


class AccelerationSensor(VelocitySensor):
    """Acceleration measurement: the true value plus white noise ``noise`` [m/s^2]."""


def add_noise(x, std: float, seed: int = 0) -> np.ndarray:
    """``x`` plus Gaussian white noise of standard deviation ``std`` (same unit as x)."""
    if std < 0:
        raise ValueError(f"std = {std!r} is out of bounds: must be >= 0")
    x = np.asarray(x, dtype=float)
    return x + std * np.random.default_rng(seed).standard_normal(x.shape)


def zero_phase_lowpass(x, fs: float, cutoff: float, order: int = 2) -> np.ndarray:
    """Zero-phase Butterworth low-pass (forward-backward; seed 003: 2nd order, 100 Hz).

    Parameters
    ----------
    x : array_like
        Samples.
    fs : float
        Sample rate [Hz].
    cutoff : float
        Cut-off [Hz], below ``fs / 2``.
    order : int
        Butterworth order (the forward-backward pass doubles the attenuation).
    """
    from scipy import signal

    if not 0 < cutoff < fs / 2:
        raise ValueError(f"cutoff = {cutoff!r} is out of bounds: must be in (0, {fs / 2:g}) "
                         f"[Hz] for fs = {fs:g} Hz")
    sos = signal.butter(order, cutoff, btype="low", fs=fs, output="sos")
    return signal.sosfiltfilt(sos, np.asarray(x, dtype=float))


def differentiate(x, t) -> np.ndarray:
    """Second-order finite-difference derivative of ``x`` over ``t`` (central inside,
    one-sided second-order at the ends)."""
    return np.gradient(np.asarray(x, dtype=float), np.asarray(t, dtype=float), edge_order=2)
