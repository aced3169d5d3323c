"""The motion channels brought onto one time base before a fit (``identify``, ``diagnose``).

A velocity differentiated backward from encoder counts is the mean velocity of the last
sample interval: it lags the position by half a sample, and an acceleration differentiated
from it lags by as much again. A LuGre bristle integrates the velocity, so a lag of half a
sample is a wrong deflection at every reversal: on the XML-350's clean records (stiff
presliding, 1 % noise) the base fitted to backward differences misses the held-out force by
4.7 x the noise floor, and by 1.9 x once the velocity is advanced by its measured lag (the
same as central differences of the same counts). The lag is measured against the position
(:func:`velocity_lag`), so only a channel that lags its own position is moved, by what it
lags: central differences and zero-phase filters are left as they are.

:func:`align_motion` returns the record with the velocity (and an acceleration that lags it
alike) advanced by the measured lag, and says so in the record's ``notes``; both commands
apply it to the fit and held-out records (:func:`identification.identify`,
:func:`diagnosis.core.diagnose`), so they fit the same base law.
"""
from __future__ import annotations

import dataclasses

import numpy as np

__all__ = ["velocity_lag", "velocity_scale", "channel_lag", "align_motion", "MIN_ALIGN_SAMPLES",
           "SCALE_TOLERANCE"]

#: smallest measured lag [samples] that is moved: below it the estimate is within what
#: quantisation of the position alone makes it read (central differences of 50 counts a
#: sample at the top speed read 0.00-0.03 in the benchmark)
MIN_ALIGN_SAMPLES = 0.2
#: largest relative disagreement of the velocity's scale with the position's derivative at
#: which the lag between them is measured [-] (the benchmark's quantised channels: within
#: 0.04 %; Franka case 3: 0.3-0.4 %)
SCALE_TOLERANCE = 0.05
#: largest spread of the sample interval, relative to its median, at which a lag in samples
#: is measured [-]
UNEVEN_TOLERANCE = 0.01
#: how a moved record's ``notes`` say so (a record moved once is not moved again)
NOTE = "velocity advanced by"
#: samples of the centred mean :func:`channel_lag` smooths its regressor with
SMOOTH_SAMPLES = 9
#: largest lag [samples] the alignment moves: beyond it the velocity is filtered so much
#: that shifting it does not restore it (a zero-phase filter reads 0, a causal one of a few
#: samples 1-3), and a larger reading is more likely a channel of its own
MAX_ALIGN_SAMPLES = 3.0


def channel_lag(ref, ch, t) -> float:
    """How many samples the channel ``ch`` lags the derivative of ``ref`` [samples].

    ``ch(t) ~ ref'(t - d dt)`` to first order is ``ref' - ch ~ d dt ch'``, solved for ``d``
    by least squares, both sides first smoothed alike without a shift (a centred mean of
    :data:`SMOOTH_SAMPLES`; a lag between two channels survives any filter both pass):
    noise in the regressor biases ``d`` towards 0, and noise the regressand shares with
    it anywhere (an acceleration differenced twice from counts read 0.08 samples for 1
    unsmoothed, -1.2 with the regressor alone smoothed). The ends, where differences are
    one-sided or the mean is cut short, are left out.

    Parameters
    ----------
    ref : ndarray
        The channel ``ch`` is the derivative of (position [m] for a velocity).
    ch : ndarray
        The derivative channel (velocity [m/s]).
    t : ndarray
        Time [s], evenly sampled.

    Returns
    -------
    float
        The lag [samples]; 0 when ``ch`` does not change.
    """
    t = np.asarray(t, float)
    if t.size < 3 * SMOOTH_SAMPLES:
        return 0.0
    dt = float(t[1] - t[0])
    box = np.full(SMOOTH_SAMPLES, 1.0 / SMOOTH_SAMPLES)
    rd = np.convolve(np.gradient(np.asarray(ref, float), t), box, mode="same")
    c = np.convolve(np.asarray(ch, float), box, mode="same")
    k = SMOOTH_SAMPLES
    dc = (np.gradient(c, t) * dt)[k:-k]
    rd, c = rd[k:-k], c[k:-k]
    den = float(dc @ dc)
    if not den > 0:
        return 0.0
    d = float((rd - c) @ dc / den)
    return d if np.isfinite(d) else 0.0


def velocity_scale(data) -> float:
    """The velocity channel's scale against the position's central differences [-]: the
    least-squares slope of ``x'`` on ``v`` (1 when the two channels and the time column
    agree; Franka case 4's files read 0.50, their time column running twice as long as the
    velocity implies). NaN when either channel is derived from the other or ``v`` is 0.

    Parameters
    ----------
    data : friction.dataset.Dataset
        The record (t [s], x [m], v [m/s]).
    """
    if {"x", "v"} & set(getattr(data, "derived", ()) or ()) or len(data) < 5:
        return float("nan")
    v = np.asarray(data.v, float)
    vv = float(v @ v)
    if not vv > 0:
        return float("nan")
    return float(np.gradient(np.asarray(data.x, float), np.asarray(data.t, float)) @ v / vv)


def velocity_lag(data) -> float:
    """How many samples the velocity channel lags the position channel [samples].

    The velocity is compared with the central differences of the position (no lag)
    (:func:`channel_lag`). Backward differences of encoder counts give 0.5, ``np.gradient``
    and zero-phase filters 0. 0 when either channel is derived from the other
    (``data.derived``), the motion has no acceleration, the two channels disagree in
    scale by more than :data:`SCALE_TOLERANCE` (:func:`velocity_scale`: then the lag is
    not what the difference of the two measures), or the sample interval varies by more
    than :data:`UNEVEN_TOLERANCE`.

    Parameters
    ----------
    data : friction.dataset.Dataset
        The record (t [s], x [m], v [m/s]).
    """
    if {"x", "v"} & set(getattr(data, "derived", ()) or ()) or len(data) < 5:
        return 0.0
    if not abs(velocity_scale(data) - 1.0) <= SCALE_TOLERANCE:
        return 0.0
    h = np.diff(np.asarray(data.t, float))
    if np.ptp(h) > UNEVEN_TOLERANCE * np.median(h):
        # a lag in samples needs one sample interval (an uneven record's backward
        # differences read 0.37 samples of a lag that varies along it)
        return 0.0
    return channel_lag(data.x, data.v, data.t)


def _advance(u, t, d):
    """``u`` read ``d`` samples later (linear interpolation; the last value held)."""
    dt = float(t[1] - t[0])
    return np.interp(t + d * dt, t, u)


def align_motion(data, lag: float | None = None):
    """The record with its velocity advanced by the lag it has behind its position.

    Parameters
    ----------
    data : friction.dataset.Dataset
        The record (t [s], x [m], v [m/s], a [m/s^2]).
    lag : float, optional
        The velocity's lag [samples] (default :func:`velocity_lag` of ``data``): give the fit
        record's to every record of one instrument chain.

    Returns
    -------
    (Dataset, float)
        The record (``data`` itself when nothing is moved) and the lag moved [samples] (0
        when below :data:`MIN_ALIGN_SAMPLES`, above :data:`MAX_ALIGN_SAMPLES`, when the
        velocity is derived from the position or the position from it, or when the
        record was moved already: its ``notes`` say so). An acceleration
        derived from the velocity (by the Dataset, or central differences of it to 1 %) is
        derived again from the moved one; another one is moved by its own lag behind the
        moved velocity where that lag is as large.
    """
    if {"x", "v"} & set(getattr(data, "derived", ()) or ()) or len(data) < 5:
        return data, 0.0
    if any(n.startswith(NOTE) for n in getattr(data, "notes", ()) or ()):
        # moved once already (diagnose, then the identify inside it): a velocity that is
        # filtered rather than delayed reads a lag again after each move (Franka case 3:
        # 0.45, then 0.39, then 0.31 samples), so the move is made once
        return data, 0.0
    d = velocity_lag(data) if lag is None else float(lag)
    if not MIN_ALIGN_SAMPLES <= abs(d) <= MAX_ALIGN_SAMPLES:
        return data, 0.0
    t = np.asarray(data.t, float)
    v = _advance(np.asarray(data.v, float), t, d)
    a0 = np.asarray(data.a, float)
    grad = np.gradient(np.asarray(data.v, float), t)
    if "a" in data.derived or np.sqrt(np.mean((a0 - grad) ** 2)) <= 0.01 * np.sqrt(
            np.mean(grad ** 2)):
        # differentiated from the velocity (central differences): again, from the moved one
        a = np.gradient(v, t)
    else:
        # an acceleration differentiated from the lagging velocity lags it as much again
        d_a = channel_lag(v, data.a, t)
        a = (_advance(np.asarray(data.a, float), t, d_a)
             if MIN_ALIGN_SAMPLES <= abs(d_a) <= MAX_ALIGN_SAMPLES else data.a)
    note = f"{NOTE} {d:.2f} samples (its measured lag behind the position)"
    return dataclasses.replace(data, v=v, a=a, notes=tuple(data.notes) + (note,)), d
