"""The seen family: one more mechanism per effect, now part of the open grid.

Written 2026-11-24 as the sealed family, seen at the end of session 7 and moved into the open
grid (each effect record's ``truths``, after its other open forms; the new sealed family is
:mod:`.sealed`). Its score when it was run sealed (146 cases, top-1 34.9 %) is in
``benchmarks/bench_diagnosis_forms.py``. Each is integrated along the plant's continuous
motion on the grid :data:`.kinematics.FINE` x finer than the data
(:func:`.truths.on_fine_grid`); level changes act inside the bristle dynamics of a LuGre
base (:func:`.truths.level_inside`).

=================  =====================================================================
effect             form (was sealed)
=================  =====================================================================
acceleration       ``film_dynamics``: the Stribeck curve follows a lubricant film whose
                   speed responds to the sliding speed as an underdamped second-order
                   system
load               ``squeeze_film``: Coulomb levels proportional to the load, the viscous
                   term growing as its square root (a film thinned by the load)
asymmetry          ``direction_curve``: a heavier low-speed tail in one direction only
stribeck_shape     ``stiction_spike``: a static peak narrower than the base's Stribeck
                   velocity
position           ``screw_runout``: a rectified-sine level along the stroke, period 5 %
                   of it
inertia            ``cable_chain``: a moving mass growing along the stroke
delay              ``encoder_latency``: the motion channels late, so the force leads
drift              ``thermal``: levels thinning with a temperature heated by the friction
                   power
=================  =====================================================================
"""
from __future__ import annotations

import numpy as np
from scipy.signal import lsim

from .kinematics import PlantKinematics
from .truths import _base_parts, _lag, _level, level_inside, on_fine_grid

__all__ = ["film_dynamics_truth", "squeeze_film_truth", "direction_curve_truth",
           "stiction_spike_truth", "screw_runout_truth", "cable_chain_truth",
           "encoder_latency_truth", "thermal_truth"]


@on_fine_grid
def film_dynamics_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The Stribeck curve evaluated at a film speed that follows |v| through an underdamped
    second-order system (natural frequency 3 / the motion's time scale, damping 0.4); the
    curves' ratio raised to the power ``s`` (positive at any strength)."""
    sc = kin.scales
    wn = 3.0 * sc["a99"] / max(sc["v99"], 1e-12)
    _, vf, _ = lsim(([wn * wn], [1.0, 0.8 * wn, wn * wn]), np.abs(kin.v), kin.t)
    if kin.base.name == "mre_lugre":
        return level_inside(kin, 1.0 + s * np.tanh((np.abs(kin.v) - vf) / (0.2 * sc["v99"])))
    g = kin.base.g
    return level_inside(kin, (g(np.abs(vf)) / g(kin.v)) ** s)


@on_fine_grid
def squeeze_film_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Levels proportional to the load, the viscous term as its square root."""
    L = np.clip(kin.load, 0.0, None)
    rel = L / max(float(np.mean(L)), 1e-12)
    lev = np.clip(1.0 + 0.8 * s * (rel - 1.0), 0.05, None)
    return level_inside(kin, lev, np.clip(1.0 + s * (np.sqrt(rel) - 1.0), 0.05, None))


@on_fine_grid
def direction_curve_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """In the negative direction only, the level gains a heavy low-speed tail
    1 / (1 + (v / 3 v_s)^2) (isolator: v_s a tenth of the top speed)."""
    neg = 0.5 * (1.0 - np.tanh(kin.v / (0.02 * kin.scales["v99"])))
    vs = 0.1 * kin.scales["v99"] if kin.base.name == "mre_lugre" else kin.base.params.vs
    return level_inside(kin, 1.0 + s * neg / (1.0 + (kin.v / (3.0 * vs)) ** 2))


@on_fine_grid
def stiction_spike_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A static peak narrower than the base's Stribeck velocity: the curve gains
    Fc exp(-(v / w)^2) x ``s``, w = 0.3 v_s but at least 2 % of the top speed (a peak no
    sample of the motion passes through would be no effect)."""
    p = kin.base.params
    g = kin.base.g
    v = kin.v
    w = max(0.3 * p.vs, 0.02 * kin.scales["v99"])
    extra = p.Fc * np.exp(-(v / w) ** 2)
    return level_inside(kin, 1.0 + s * extra / g(v), np.ones_like(v))


@on_fine_grid
def screw_runout_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A rectified-sine level of period 5 % of the stroke (a bent screw's runout)."""
    sc = kin.scales
    span = sc["x_hi"] - sc["x_lo"] or 1.0
    u = np.abs(np.sin(np.pi * (kin.x - sc["x_lo"]) / (0.05 * span))) - 2.0 / np.pi
    return level_inside(kin, 1.0 + s * u)


@on_fine_grid
def cable_chain_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A cable chain: the moving mass grows along the stroke, dm (0.5 + (x - x_lo)/span),
    times the true acceleration."""
    sc = kin.scales
    span = sc["x_hi"] - sc["x_lo"] or 1.0
    F, _ = _base_parts(kin)
    dm = s * _level(kin) / sc["a99"] * (0.5 + (kin.x - sc["x_lo"]) / span)
    return F + dm * kin.a


@on_fine_grid
def encoder_latency_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The motion channels ``s`` data samples late (at most 20; encoder latency): the
    force, on time, leads them."""
    from scipy.interpolate import CubicSpline
    F, _ = _base_parts(kin)
    d = min(max(s, 0.0), 20.0) * kin.sample_dt
    return CubicSpline(kin.t, F)(np.clip(kin.t + d, None, kin.t[-1]))


@on_fine_grid
def thermal_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Levels thinning with a temperature rise heated by the friction power |F v|
    (first-order, time constant a third of the record); the viscous term twice as much."""
    F, Ff = _base_parts(kin)
    T = kin.t[-1] - kin.t[0]
    theta = _lag(kin.t, np.abs(Ff * kin.v), T / 3.0)
    theta = theta / max(float(np.max(theta)), 1e-12)
    return level_inside(kin, np.clip(1.0 - s * theta, 0.05, None),
                        np.clip(1.0 - 2.0 * s * theta, 0.05, None))
