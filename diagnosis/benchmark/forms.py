"""More truth forms per effect: the generalisation benchmark's mechanisms.

Each effect's first truth form (:mod:`.truths`) is joined here by two more, each from other
physics than the first and than the candidate's formula (:mod:`diagnosis.candidates`), each
integrated along the plant's continuous motion on the grid :data:`.kinematics.FINE` x finer
than the data (:func:`.truths.on_fine_grid`). Friction-level changes act *inside* the
bristle dynamics of a LuGre base (:func:`.truths.level_inside`), not on its output force as
the candidates do. The effect records (:data:`diagnosis.effects.EFFECTS`) name them.

=================  =====================================================================
effect             forms here
=================  =====================================================================
acceleration       ``frictional_memory``: the Stribeck curve of a velocity lagged by a
                   memory time (Hess and Soom 1990); ``slip_memory``: a state that relaxes
                   to its steady value over a slip distance (rate-and-state friction)
load               ``hertz_contact``: levels as the load to the power 2/3 (Hertzian
                   contact); ``one_sided_seal``: levels grow with the load in one direction
                   of motion only (a seal pressurised from one side)
asymmetry          ``stribeck_twins``: breakaway level and Stribeck velocity differ with
                   the direction; ``viscous_twin``: the viscous slope alone differs (a worn
                   ball screw, EMPS)
stribeck_shape     ``rational``: a Stribeck drop 1 / (1 + |v/v_r|^1.5); ``hydrodynamic``:
                   a viscous term growing as sqrt(|v|) (full-film lubrication)
position           ``waviness``: a periodic level of period 7 % of the stroke (guide
                   waviness, screw pitch); ``worn_section``: a smooth level step along the
                   stroke
inertia            ``raw_acceleration``: a mass error times the true, unfiltered
                   acceleration; ``flexible_load``: a second mass on a spring-damper
                   behind the force sensor
delay              ``antialias_filter``: a fourth-order Bessel low-pass of the force
                   channel (group delay of ``s`` samples); ``moving_average``: an
                   integrating converter averaging over 2 ``s`` samples
drift              ``linear_wear_in``: levels falling linearly in time; ``lubricant_step``:
                   a level step at 40 % of the record
=================  =====================================================================
"""
from __future__ import annotations

import numpy as np
from numba import njit

from .kinematics import PlantKinematics
from .truths import _base_parts, _bump_centre, _lag, _level, level_inside, on_fine_grid

__all__ = ["frictional_memory_truth", "slip_memory_truth", "hertz_contact_truth",
           "one_sided_seal_truth", "stribeck_twins_truth", "viscous_twin_truth",
           "rational_truth", "hydrodynamic_truth", "waviness_truth", "worn_section_truth",
           "raw_acceleration_truth", "flexible_load_truth", "antialias_filter_truth",
           "moving_average_truth", "linear_wear_in_truth", "lubricant_step_truth",
           "WAVE_SHARE"]

#: wavelength of the ``waviness`` truth, as a share of the stroke [-] (the issue's case)
WAVE_SHARE = 0.07


def _motion_time(kin: PlantKinematics) -> float:
    """A time scale of the motion [s]: top speed over top acceleration."""
    sc = kin.scales
    return sc["v99"] / max(sc["a99"], 1e-12)


def _smooth_positive(v, kin):
    # smooth indicator of v > 0 (measured data never switches in one sample)
    return 0.5 * (1.0 + np.tanh(v / (0.02 * kin.scales["v99"])))


# -- acceleration ---------------------------------------------------------------------------
@on_fine_grid
def frictional_memory_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The Stribeck curve follows a velocity lagged by a memory time of a fifth of the
    motion's time scale (Hess and Soom 1990): friction stays high while the speed rises,
    low while it falls; ``s`` is the power of the curves' ratio (1: the lagged curve; the
    level stays positive at any strength). Isolator: its friction part
    scaled by the same sign of (|v| - |v_lagged|)."""
    tau = 0.2 * _motion_time(kin)
    vm = _lag(kin.t, kin.v, tau)
    if kin.base.name == "mre_lugre":
        u = (np.abs(kin.v) - np.abs(vm)) / (0.2 * kin.scales["v99"])
        return level_inside(kin, 1.0 + s * np.tanh(u))
    g = kin.base.g
    return level_inside(kin, (g(vm) / g(kin.v)) ** s)


@njit(cache=True)
def _slip_state(v, h, Dc, v_ref):
    # phi relaxes to 1 / (1 + |v| / v_ref) over the slip distance Dc (exact per step)
    n = v.size
    phi = np.empty(n)
    p = 1.0 / (1.0 + abs(v[0]) / v_ref)
    for k in range(n):
        ss = 1.0 / (1.0 + abs(v[k]) / v_ref)
        p = ss + (p - ss) * np.exp(-abs(v[k]) * h / Dc)
        phi[k] = p - ss
    return phi


@on_fine_grid
def slip_memory_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A state that relaxes to its speed's steady value over a slip distance (rate-and-state
    friction, Ruina's slip law): the level departs from the steady curve only while the
    speed changes; slip distance a tenth of top speed x the motion's time scale; the level
    is exp(4 ``s`` phi), positive at any strength."""
    sc = kin.scales
    Dc = 0.1 * sc["v99"] * _motion_time(kin)
    phi = _slip_state(kin.v, kin.dt, Dc, 0.3 * sc["v99"])
    return level_inside(kin, np.exp(4.0 * s * phi))


# -- load -------------------------------------------------------------------------------------
def _relative_load(kin):
    L = np.clip(kin.load, 0.0, None)
    return L / max(float(np.mean(L)), 1e-12)


@on_fine_grid
def hertz_contact_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Friction levels as the normal load to the power 2/3 (Hertzian contact: the real
    contact area), inside the bristle dynamics; the viscous term unchanged."""
    lev = 1.0 + s * (_relative_load(kin) ** (2.0 / 3.0) - 1.0)
    return level_inside(kin, np.clip(lev, 0.05, None), np.ones_like(kin.v))


@on_fine_grid
def one_sided_seal_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A seal pressurised from one side: its levels grow with the load while moving in the
    positive direction and hardly in the other."""
    rel = _relative_load(kin) - 1.0
    lev = 1.0 + s * rel * (0.1 + 0.9 * _smooth_positive(kin.v, kin))
    return level_inside(kin, np.clip(lev, 0.05, None))


# -- asymmetry -------------------------------------------------------------------------------
@on_fine_grid
def stribeck_twins_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Breakaway level and Stribeck velocity differ with the direction (``Fs_neg``,
    ``vs_neg`` twins); isolator: its friction part raised at low speed for v < 0."""
    law = kin.base
    if law.name == "mre_lugre":
        neg = 1.0 - _smooth_positive(kin.v, kin)
        low = np.exp(-np.abs(kin.v) / (0.3 * kin.scales["v99"]))
        return level_inside(kin, 1.0 + s * neg * low)
    p = law.params
    return law.with_values(Fs_neg=p.Fs * (1.0 + 0.8 * s),
                           vs_neg=p.vs * (1.0 + 1.5 * s)).simulate(kin.t, kin.v)


@on_fine_grid
def viscous_twin_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The viscous slope alone differs with the direction (a worn ball screw: EMPS's
    Fv+ 167 vs Fv- 240 N s/m); isolator: its friction part grows with speed for v < 0."""
    law = kin.base
    if law.name == "mre_lugre":
        neg = 1.0 - _smooth_positive(kin.v, kin)
        return level_inside(kin, 1.0 + s * neg * np.abs(kin.v) / kin.scales["v99"])
    p = law.params
    if p.sigma2 <= 0.0:  # a base without viscous slope: the twin is the whole term
        F, _ = _base_parts(kin)
        neg = 1.0 - _smooth_positive(kin.v, kin)
        return F + s * _level(kin) * neg * kin.v / kin.scales["v99"]
    return law.with_values(sigma2_neg=p.sigma2 * (1.0 + s)).simulate(kin.t, kin.v)


# -- stribeck_shape --------------------------------------------------------------------------
@on_fine_grid
def rational_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A Stribeck drop of rational form, Fc + (Fs - Fc) / (1 + |v / v_r|^1.5) with v_r twice
    the base's Stribeck velocity, its ratio to the base's curve raised to the power ``s``
    (neither the Gaussian-alpha family nor the Lorentzian)."""
    p = kin.base.params
    g = kin.base.g

    def rational(v):
        return p.Fc + (p.Fs - p.Fc) / (1.0 + np.abs(v / (2.0 * p.vs)) ** 1.5)
    v = kin.v
    return level_inside(kin, (rational(v) / g(v)) ** s, np.ones_like(v))


@on_fine_grid
def hydrodynamic_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Full-film lubrication: a viscous term growing as sqrt(|v|) (equal to the base's
    linear one at the top speed) blended in by ``s``: the steady-state curve bends where
    the linear term cannot."""
    F = level_inside(kin, np.ones_like(kin.v))
    p = kin.base.params
    v99 = kin.scales["v99"]
    c = max(float(p.sigma2) * v99, 0.3 * _level(kin))
    return F + s * c * (np.sign(kin.v) * np.sqrt(np.abs(kin.v) / v99) - kin.v / v99)


# -- position --------------------------------------------------------------------------------
@on_fine_grid
def waviness_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Guide waviness or screw pitch: a periodic level of wavelength :data:`WAVE_SHARE` of
    the stroke, inside the bristle dynamics."""
    sc = kin.scales
    span = sc["x_hi"] - sc["x_lo"] or 1.0
    ph = 2.0 * np.pi * (kin.x - sc["x_lo"]) / (WAVE_SHARE * span)
    return level_inside(kin, 1.0 + s * np.sin(ph + 0.4))


@on_fine_grid
def worn_section_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A worn section: the level steps smoothly (over a twentieth of the stroke) where fit
    and held-out parts both pass, inside the bristle dynamics."""
    sc = kin.scales
    span = sc["x_hi"] - sc["x_lo"] or 1.0
    xc = _bump_centre(kin)
    if xc is None:
        raise ValueError(f"position: the held-out part of the {kin.plant} record never "
                         f"revisits the positions of its fit part")
    return level_inside(kin, 1.0 + s * np.tanh((kin.x - xc) / (0.05 * span)))


# -- inertia ---------------------------------------------------------------------------------
@on_fine_grid
def raw_acceleration_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A mass error times the true acceleration of the continuous motion (the data's ``a``
    is differentiated from positions, noisier and later)."""
    F, _ = _base_parts(kin)
    return F + s * _level(kin) / kin.scales["a99"] * kin.a


@on_fine_grid
def flexible_load_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A second mass behind the force sensor on a spring-damper (natural frequency 8 x the
    motion's, damping ratio 0.3): the sensor reads its inertial force too."""
    from scipy.signal import lsim
    F, _ = _base_parts(kin)
    wn = 8.0 / _motion_time(kin)
    z = 0.3
    # acceleration of the second mass: the base's acceleration through (2 z wn s + wn^2) /
    # (s^2 + 2 z wn s + wn^2)
    _, a2, _ = lsim(([2 * z * wn, wn * wn], [1.0, 2 * z * wn, wn * wn]), kin.a, kin.t)
    return F + s * _level(kin) / kin.scales["a99"] * a2


# -- delay -----------------------------------------------------------------------------------
@on_fine_grid
def antialias_filter_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force channel through a fourth-order Bessel low-pass (maximally flat delay) whose
    group delay is ``s`` data samples (at most 20)."""
    from scipy.signal import bessel, sosfilt, sosfilt_zi
    F, _ = _base_parts(kin)
    d = min(max(s, 0.05), 20.0) * kin.sample_dt
    # with fs given, the "delay" normalisation's group delay is 1 / (2 pi Wn)
    sos = bessel(4, 1.0 / (2.0 * np.pi * d), norm="delay", output="sos", fs=1.0 / kin.dt)
    y, _ = sosfilt(sos, F, zi=sosfilt_zi(sos) * F[0])
    return y


@on_fine_grid
def moving_average_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """An integrating converter: the force averaged over the last 2 ``s`` data samples
    (delay ``s`` samples, at most 20)."""
    F, _ = _base_parts(kin)
    n = max(1, int(round(2.0 * min(max(s, 0.0), 20.0) * kin.step)))
    c = np.concatenate([[0.0], np.cumsum(F)])
    k = np.arange(F.size)
    lo = np.maximum(k + 1 - n, 0)
    return (c[k + 1] - c[lo]) / (k + 1 - lo)


# -- drift -----------------------------------------------------------------------------------
@on_fine_grid
def linear_wear_in_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Running-in: every level (Stribeck curve and viscous term) falls linearly in time,
    inside the bristle dynamics."""
    u = (kin.t - kin.t[0]) / (kin.t[-1] - kin.t[0])
    return level_inside(kin, np.clip(1.0 - s * u, 0.05, None))


@on_fine_grid
def lubricant_step_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A lubricant change or a regulated heater switching: the levels step (over 1 % of
    the record) at 40 % of it, inside the bristle dynamics."""
    T = kin.t[-1] - kin.t[0]
    step = 0.5 * (1.0 + np.tanh((kin.t - kin.t[0] - 0.4 * T) / (0.01 * T)))
    return level_inside(kin, np.clip(1.0 + s * step, 0.05, None))
