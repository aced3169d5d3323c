"""The seeds' experimental protocols as reusable definitions that produce
:class:`friction.dataset.Dataset` records (CSV contract ``t, x, v, a, F[, load]``).

Protocol definitions (pure: they return trajectories or grids)

* :func:`sinusoid_grid` - seed 000: 1/5/10/20 Hz x 2/4/6/8 mm position sinusoids;
* :func:`stribeck_speeds` / :func:`stribeck_plateaus` - constant-velocity plateaus for
  Stribeck curves (seed 000: 48 speeds in +-0.02 m/s; seed 003: trapezoids within
  +-30 mm/s; seed 004: constant speeds);
* :func:`prbs_excitation` - seed 003: PRBS acceleration up to 500 Hz at 5 mm/s^2 RMS;
* :func:`refinement_reference` - seed 003: coloured noise, 8th-order Chebyshev I, 10 Hz;
* :data:`SCURVE_MOVES` - seed 003: S-curve moves of 100 um and 1 um.

Measurement chain (seed 003 Sec. V-B): :func:`measured_dataset` adds sensor noise, filters
position and force with a zero-phase 2nd-order Butterworth (100 Hz), differentiates with
second-order finite differences, recovers friction from the inertial model
``f_r = f_e - M a`` and decimates (10 kHz -> 1 kHz). :func:`steady_state_points` averages
plateaus; :func:`frf` and :func:`fit_presliding` do the pre-sliding frequency-domain step.

XML-350 runs: :func:`xml350_stribeck`, :func:`xml350_prbs`, :func:`xml350_refinement`,
:func:`xml350_scurve` simulate the stage (:mod:`plants.xml350`) under the protocols and
return datasets. Identification runs use the linear PID with acceleration feedforward as
the paper does; since that PID is unstable with a 400 Hz first-order current loop (see
:mod:`plants.xml350`), they use a 2 kHz current loop (``IDENTIFICATION_F_CURRENT``).
"""
from __future__ import annotations

import numpy as np

from friction.dataset import Dataset

from .sensors import add_noise, differentiate, zero_phase_lowpass
from .sources import PRBS, ColoredNoise, SCurve, Sine, VelocityPlateaus

__all__ = ["sinusoid_grid", "stribeck_speeds", "stribeck_plateaus", "prbs_excitation",
           "refinement_reference", "SCURVE_MOVES", "PRESS_SPEEDS", "measured_dataset", "steady_state_points",
           "dataset_from_result", "frf", "fit_presliding", "xml350_stribeck", "xml350_prbs",
           "xml350_refinement", "xml350_scurve", "IDENTIFICATION_F_CURRENT",
           "identification_stage"]

#: current-loop bandwidth [Hz] used with the linear PID in identification runs
IDENTIFICATION_F_CURRENT = 2000.0

#: seed 003 point-to-point moves [m]
SCURVE_MOVES = {"100um": 1e-4, "1um": 1e-6}

#: seed 004 Table 1: constant ram speeds of the isothermal forging rule [m/s]
PRESS_SPEEDS = (1.2e-3, 0.1e-3, 0.05e-3, 0.002e-3)


# -- protocol definitions ---------------------------------------------------------------------
def sinusoid_grid(frequencies=(1.0, 5.0, 10.0, 20.0), amplitudes=(2e-3, 4e-3, 6e-3, 8e-3),
                  periods: float = 3.0) -> list[dict]:
    """Seed 000's grid of position sinusoids.

    Returns
    -------
    list of dict
        ``{"frequency" [Hz], "amplitude" [m], "source": Sine, "duration" [s]}``, one per
        (frequency, amplitude) pair; ``duration`` covers ``periods`` periods.
    """
    out = []
    for f in frequencies:
        for A in amplitudes:
            if not A > 0:
                raise ValueError(f"amplitude = {A!r} is out of bounds: must be > 0 [m]")
            out.append({"frequency": float(f), "amplitude": float(A), "source": Sine(A, f),
                        "duration": periods / float(f)})
    return out


def stribeck_speeds(n: int = 48, vmax: float = 0.02, vmin: float | None = None) -> np.ndarray:
    """``n`` plateau speeds [m/s], half positive and half negative, log-spaced in
    ``[vmin, vmax]`` (seed 000: 48 speeds in +-0.02 m/s; seed 003: +-30 mm/s).

    ``vmin`` defaults to ``vmax / 500``.
    """
    if n < 2 or n % 2:
        raise ValueError(f"n = {n!r}: need an even number >= 2 of speeds (+ and -)")
    if not vmax > 0:
        raise ValueError(f"vmax = {vmax!r} is out of bounds: must be > 0 [m/s]")
    vmin = vmax / 500.0 if vmin is None else float(vmin)
    if not 0 < vmin < vmax:
        raise ValueError(f"vmin = {vmin!r} is out of bounds: must be in (0, vmax)")
    pos = np.geomspace(vmin, vmax, n // 2)
    return np.concatenate((pos, -pos))


def stribeck_plateaus(speeds, accel: float = 0.2, plateau: float = 0.2,
                      rest: float = 0.02) -> VelocityPlateaus:
    """Trapezoidal velocity reference visiting each speed from rest (seed 003 Sec. V-A)."""
    return VelocityPlateaus(speeds, accel=accel, plateau=plateau, rest=rest,
                            return_to_zero=True)


def prbs_excitation(rms: float = 5e-3, f_max: float = 500.0, duration: float = 2.0,
                    seed: int = 1) -> PRBS:
    """Seed 003's pre-sliding excitation: PRBS acceleration, ``f_max`` 500 Hz, 5 mm/s^2 RMS."""
    return PRBS(rms=rms, f_max=f_max, duration=duration, seed=seed)


def refinement_reference(rms: float = 5e-3, seed: int = 0, duration: float = 14.0,
                         cutoff: float = 10.0, order: int = 8) -> ColoredNoise:
    """Seed 003's refinement velocity reference: Gaussian noise through an 8th-order
    Chebyshev I low-pass at 10 Hz (two realisations: identification and validation)."""
    return ColoredNoise(rms=rms, cutoff=cutoff, duration=duration, seed=seed, order=order)


# -- measurement chain ------------------------------------------------------------------------
def measured_dataset(t, x, f_e, mass: float, *, load=None, noise_x: float = 0.0,
                     noise_f: float = 0.0, cutoff: float | None = 100.0, order: int = 2,
                     decimate: int = 1, seed: int = 0, name: str = "measured") -> Dataset:
    """Friction "measured" the way seed 003 does it: ``f_r = f_e - M a`` from filtered
    position and force.

    Parameters
    ----------
    t : array_like
        Uniform time samples [s].
    x : array_like
        Measured position [m].
    f_e : array_like
        Applied (motor) force [N].
    mass : float
        Moving mass M [kg] of the inertial model.
    load : array_like, optional
        Normal load [N], carried along.
    noise_x, noise_f : float
        Standard deviation of white noise added to x [m] and f_e [N].
    cutoff : float or None
        Zero-phase Butterworth cut-off [Hz] (``None``: no filter).
    order : int
        Butterworth order (seed 003: 2).
    decimate : int
        Keep every ``decimate``-th sample after filtering (seed 003: 10 -> 1 kHz).
    """
    t = np.asarray(t, float)
    x = add_noise(x, noise_x, seed) if noise_x else np.asarray(x, float)
    f = add_noise(f_e, noise_f, seed + 1) if noise_f else np.asarray(f_e, float)
    if not mass > 0:
        raise ValueError(f"mass = {mass!r} is out of bounds: must be > 0 [kg]")
    if cutoff is not None:
        fs = 1.0 / float(np.median(np.diff(t)))
        x = zero_phase_lowpass(x, fs, cutoff, order)
        f = zero_phase_lowpass(f, fs, cutoff, order)
    v = differentiate(x, t)
    a = differentiate(v, t)
    F = f - mass * a
    k = max(1, int(decimate))
    sel = slice(None, None, k)
    return Dataset.from_arrays(t[sel], F[sel], x=x[sel], v=v[sel], a=a[sel],
                               load=None if load is None else np.asarray(load)[sel], name=name)


def dataset_from_result(result: np.ndarray, *, F: str = "F", x: str = "x", v: str | None = "v",
                        a: str | None = None, load: str | None = None,
                        name: str = "simulated") -> Dataset:
    """A dataset straight from named columns of a simulation result (no processing)."""
    cols = result.dtype.names
    for key in (F, x, v, a, load):
        if key is not None and key not in cols:
            raise KeyError(f"result has no column {key!r}; columns are {cols}")
    return Dataset.from_arrays(result["time"], result[F], x=result[x],
                               v=None if v is None else result[v],
                               a=None if a is None else result[a],
                               load=None if load is None else result[load], name=name)


def steady_state_points(ds: Dataset, windows, trim: float = 0.3) -> tuple[np.ndarray, np.ndarray]:
    """Mean velocity and friction on each plateau ``(t_begin, t_end, speed)``; the first
    ``trim`` fraction of each plateau (transient) is dropped."""
    vs, Fs = [], []
    for t0, t1, _ in windows:
        sel = (ds.t >= t0 + trim * (t1 - t0)) & (ds.t <= t1)
        if sel.sum() < 3:
            raise ValueError(f"plateau [{t0:g}, {t1:g}] s has fewer than 3 samples")
        vs.append(float(np.mean(ds.v[sel])))
        Fs.append(float(np.mean(ds.F[sel])))
    return np.array(vs), np.array(Fs)


def frf(t, force, x, nperseg: int | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """H1 estimate of the frequency response ``X/F`` [m/N] (Welch averaging).

    Returns
    -------
    freq [Hz], G (complex), coherence
    """
    from scipy import signal

    t = np.asarray(t, float)
    fs = 1.0 / float(np.median(np.diff(t)))
    force = np.asarray(force, float) - np.mean(force)
    x = np.asarray(x, float) - np.mean(x)
    nperseg = nperseg or min(len(t) // 4, int(fs // 2))
    f, Pff = signal.welch(force, fs, nperseg=nperseg)
    _, Pfx = signal.csd(force, x, fs, nperseg=nperseg)
    _, coh = signal.coherence(force, x, fs, nperseg=nperseg)
    with np.errstate(divide="ignore", invalid="ignore"):
        G = Pfx / Pff
    return f, G, coh


def fit_presliding(freq, G, mass: float, band=(10.0, 400.0), coherence=None) -> dict:
    """Fit the pre-sliding model ``X/F = 1 / (M s^2 + sigma1 s + sigma0)`` (seed 003 Eq. 13).

    ``1/G = sigma0 - M w^2 + j sigma1 w`` is linear in (sigma0, sigma1): least squares on
    the band, weighted by the coherence when given.

    Returns
    -------
    dict with ``sigma0`` [N/m], ``sigma1`` [N.s/m], ``wn`` [rad/s], ``zeta``.
    """
    freq = np.asarray(freq, float)
    sel = (freq >= band[0]) & (freq <= band[1]) & np.isfinite(G) & (np.abs(G) > 0)
    if sel.sum() < 3:
        raise ValueError(f"fewer than 3 frequency points in the band {band} Hz")
    w = 2 * np.pi * freq[sel]
    H = 1.0 / G[sel]
    wt = np.ones(w.size) if coherence is None else np.asarray(coherence)[sel]
    sigma0 = float(np.sum(wt * (H.real + mass * w ** 2)) / np.sum(wt))
    sigma1 = float(np.sum(wt * H.imag * w) / np.sum(wt * w ** 2))
    wn = float(np.sqrt(max(sigma0, 0.0) / mass))
    return {"sigma0": sigma0, "sigma1": sigma1, "wn": wn,
            "zeta": sigma1 / (2 * mass * wn) if wn > 0 else float("nan")}


# -- XML-350 runs -------------------------------------------------------------------------------
def identification_stage(friction=None, **params):
    """The XML-350 in the identification configuration (linear PID; faster current loop)."""
    from .xml350 import XML350
    params.setdefault("f_current", IDENTIFICATION_F_CURRENT)
    return XML350(friction, **params)


def _xml_force(res, stage) -> np.ndarray:
    return stage.params.Kf * res["i"]


def xml350_stribeck(speeds=None, *, plateau: float = 0.2, accel: float = 0.2,
                    friction=None, noise_x: float = 0.0, substep: float | None = None,
                    progress=None) -> tuple[Dataset, np.ndarray, np.ndarray]:
    """Seed 003's static step: trapezoidal plateaus within +-30 mm/s tracked by the linear
    PID; returns the processed dataset and the steady-state points (v [m/s], F [N])."""
    if speeds is None:
        speeds = stribeck_speeds(16, 0.03, 2e-4)
    prof = stribeck_plateaus(speeds, accel=accel, plateau=plateau)
    stage = identification_stage(friction)
    res = stage.simulate(prof.duration, controller="pid", compensation=False,
                         trajectory=prof, substep=substep, progress=progress)
    ds = measured_dataset(res["time"], res["x_meas"], _xml_force(res, stage), stage.params.M,
                          noise_x=noise_x, name="xml350_stribeck")
    v, F = steady_state_points(ds, prof.windows)
    return ds, v, F


def xml350_prbs(*, rms: float = 5e-3, f_max: float = 500.0, duration: float = 2.0,
                seed: int = 1, friction=None, substep: float | None = None) -> dict:
    """Seed 003's dynamic step: open-loop PRBS acceleration in pre-sliding; returns
    ``{"result", "freq", "G", "coherence", "fit"}`` with the fitted sigma0, sigma1."""
    from .xml350 import XML350
    stage = XML350(friction)
    prbs = prbs_excitation(rms, f_max, duration, seed)
    res = stage.simulate(duration, open_loop=True, compensation=False, ff_mode="none",
                         trajectory=prbs, substep=substep)
    f_e = _xml_force(res, stage)
    skip = res["time"] >= 0.1  # drop the start transient
    freq, G, coh = frf(res["time"][skip], f_e[skip], res["x"][skip])
    fit = fit_presliding(freq, G, stage.params.M, band=(20.0, min(f_max, 400.0)),
                         coherence=coh)
    return {"result": res, "freq": freq, "G": G, "coherence": coh, "fit": fit,
            "force_peak": float(np.max(np.abs(f_e)))}


def xml350_refinement(seed: int = 0, *, duration: float = 14.0, rms: float = 5e-3,
                      friction=None, noise_x: float = 0.0, substep: float | None = None,
                      progress=None) -> Dataset:
    """Seed 003's refinement data: coloured-noise velocity reference tracked by the linear
    PID, processed to 1 kHz (N = 1000 * duration samples; the paper: 14000 and 10000)."""
    ref = refinement_reference(rms=rms, seed=seed, duration=duration)
    stage = identification_stage(friction)
    res = stage.simulate(duration, controller="pid", compensation=False, trajectory=ref,
                         substep=substep, progress=progress)
    return measured_dataset(res["time"], res["x_meas"], _xml_force(res, stage),
                            stage.params.M, noise_x=noise_x, decimate=10,
                            name=f"xml350_refinement_{seed}")


def xml350_scurve(distance: float = 1e-4, *, compensation: bool = True, friction=None,
                  compensator=None, stop_time: float | None = None) -> np.ndarray:
    """One S-curve point-to-point move of seed 003 (250 mm/s, 4000 mm/s^2) under the SD-PID;
    returns the stage's result array (``e`` is the tracking error)."""
    from .xml350 import XML350
    return XML350(friction).simulate(stop_time, distance=distance, compensation=compensation,
                                     compensator=compensator)


# an S-curve generator with the seed's limits, for users who want the reference alone
def scurve(distance: float, t0: float = 0.0) -> SCurve:
    """Seed 003's S-curve move of ``distance`` [m] (250 mm/s, 4000 mm/s^2)."""
    return SCurve(distance, vmax=0.25, amax=4.0, t0=t0)
