"""Truth forces of the benchmark cases: the base law plus a withheld effect, along a motion.

Each truth differs in form from the candidate that should name it (:mod:`diagnosis.effects`);
see the table in :mod:`diagnosis.benchmark`.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from friction import make_model
from friction.lugre import bristle_update


from .kinematics import FINE, PlantKinematics, fine_motion

__all__ = ["BASE", "MAX_DELAY_SAMPLES", "STRIBECK_TAIL", "FIT_FRACTION"]

BASE = dict(sigma0=2e4, sigma1=150.0, sigma2=8.0, Fc=2.0, Fs=2.8, vs=5e-3)
#: longest force-channel delay of the ``delay`` truth [samples] (the candidate reaches 25)
MAX_DELAY_SAMPLES = 20.0
#: speed scale of the extra low-speed tail of the ``stribeck_shape`` truth, x v99 [-]
STRIBECK_TAIL = 0.05


def _generic_truth(effect, s, t, x, v, a):
    """Noise-free truth force and load of a generic case."""
    load = None
    base = make_model("lugre", **BASE)
    dt = t[1] - t[0]
    if effect == "acceleration":
        truth = make_model("modified_lugre", sigma0=BASE["sigma0"], sigma1=BASE["sigma1"],
                           sigma2=BASE["sigma2"], Fc=BASE["Fc"], Fs=BASE["Fs"], vs=BASE["vs"])
        truth = truth.with_values(f_a=1.5 * s, a_s=0.3, v_c=0.04, tau=0.01)
        F = truth.simulate(t, v, a=a)
    elif effect == "load":
        load = 100.0 + 60.0 * np.sin(2 * np.pi * 0.05 * t) ** 2 + 20 * (t / t[-1])
        levels = 1.0 + 0.6 * s * (load - 100.0) / 100.0  # seed-004 style: levels linear in load
        F = base.simulate(t, v) * levels
    elif effect == "asymmetry":
        F = base.with_values(Fc_neg=BASE["Fc"] * (1 + 0.5 * s), Fs_neg=BASE["Fs"] * (1 + 0.5 * s),
                             sigma2_neg=BASE["sigma2"] * (1 + 0.6 * s)).simulate(t, v)
    elif effect == "stribeck_shape":
        # a long Lorentzian tail: the Gaussian base cannot bend like it
        F = base.with_values(shape="lorentzian", Fc=BASE["Fc"] * 0.6,
                             Fs=BASE["Fs"] * (1 + 1.5 * s), vs=BASE["vs"] * 3).simulate(t, v)
    elif effect == "position":
        span = np.ptp(x)
        F = base.simulate(t, v) + 0.8 * s * np.cos(np.pi * (x - x.min()) / span) * np.tanh(v / 2e-3)
    elif effect == "inertia":
        F = base.simulate(t, v) + 1.2 * s * a  # 1.2 kg mass error in the inverse dynamics
    elif effect == "delay":
        F0 = base.simulate(t, v)
        F = np.interp(t - 4.5 * s * dt, t, F0)
    elif effect == "drift":
        warm = 1.0 + 0.5 * s * (1.0 - np.exp(-t / (0.6 * t[-1])))  # saturating warm-up
        F = base.simulate(t, v) * warm
    elif effect == "clean":
        F = base.simulate(t, v)
    elif effect == "outside":
        # an electrical ripple at 13 Hz, unrelated to motion: no candidate can express it
        F = base.simulate(t, v) + 0.6 * s * np.sin(2 * np.pi * 13.0 * t)
    else:
        raise ValueError(f"unknown benchmark effect {effect!r}; the benchmark's cases are diagnosis.benchmark.CASES")
    return F, load


@njit(cache=True)
def _lugre_curve_run(t, v, g, g_mid, s0, s1, s2):
    """LuGre force [N] along (t, v) with its Stribeck curve given as values, ``g`` [N] at
    the samples and ``g_mid`` [N] at the step midpoints; the bristle advances by the friction
    package's exact step (:func:`friction.lugre.bristle_update`, every LuGre kernel's)."""
    n = t.size
    F = np.empty(n)
    z = 0.0
    for k in range(n):
        zd = v[k] - s0 * abs(v[k]) * z / g[k]
        F[k] = s0 * z + s1 * zd + s2 * v[k]
        if k + 1 < n:
            vm = 0.5 * (v[k] + v[k + 1])
            z = bristle_update(z, vm, s0 * abs(vm) / g_mid[k], t[k + 1] - t[k], 0)
    return F


def _lugre_curve(kin: PlantKinematics, g, s0, s1, s2) -> np.ndarray:
    """LuGre force [N] at the samples of ``kin`` with the Stribeck curve ``g(v)`` [N],
    integrated along the continuous motion on the grid :data:`.kinematics.FINE` x finer
    than the data (:func:`.kinematics.fine_motion`, the benchmark's one definition of the
    motion between samples)."""
    t_f, _, v_f, _ = fine_motion(kin)
    F_f = _lugre_curve_run(t_f, v_f, g(v_f), g(0.5 * (v_f[1:] + v_f[:-1])), s0, s1, s2)
    return F_f[::FINE]


def _lag(t, u, tau):
    """Causal first-order lag tau dy/dt + y = u (exact for a piecewise-linear input)."""
    from scipy.signal import lfilter
    dt = float(t[1] - t[0])
    e = np.exp(-dt / tau)
    y = lfilter([1.0 - e], [1.0, -e], u, zi=[u[0] * e])[0]
    return y


#: share of the record :func:`diagnosis.diagnose` fits on by default (the rest is held out)
FIT_FRACTION = 0.7


def _bump_centre(kin: PlantKinematics, min_overlap: float = 0.2):
    """Centre [m] of the ``position`` defect: the median held-out position among those the
    fit part also visits, so the defect is seen in both parts; ``None`` if fewer than
    ``min_overlap`` of the held-out samples lie within the fit part's range (a one-way
    stroke, e.g. the press: nothing to learn the defect from)."""
    m = int(round(FIT_FRACTION * kin.x.size))
    xf, xh = kin.x[:m], kin.x[m:]
    inside = (xh >= xf.min()) & (xh <= xf.max())
    if inside.mean() < min_overlap:
        return None
    return float(np.median(xh[inside]))


def _base_parts(kin: PlantKinematics):
    """(F_base, F_friction_part): the force of the base law and the part effects act on."""
    law, t, v, x = kin.base, kin.t, kin.v, kin.x
    if law.name == "mre_lugre":
        p = law.params
        F = law.simulate(t, v, x=x)
        return F, F - p.k0 * x - p.f0  # the spring and offset carry no friction
    F = law.simulate(t, v)
    return F, F


def _level(kin: PlantKinematics) -> float:
    """Friction level of the base law [N] (Coulomb level or saturated hysteretic force)."""
    p = kin.base.params
    if kin.base.name == "mre_lugre":
        return float(p.beta / p.alpha)
    return float(p.Fc)


def _truth(kin: PlantKinematics, effect: str, s: float) -> np.ndarray:
    """Noise-free truth force [N] of ``effect`` with amplitude factor ``s`` along the motion
    (:func:`make_plant_case` calibrates ``s`` to the requested strength)."""
    t, x, v, a, L = kin.t, kin.x, kin.v, kin.a, kin.load
    law = kin.base
    mre = law.name == "mre_lugre"
    F, Ff = _base_parts(kin)
    Fk = _level(kin)
    sc = kin.scales
    dt = kin.dt
    if effect == "clean":
        return F
    if effect == "outside":
        fr = 0.0537 / dt  # electrical ripple, unrelated to the motion
        return F + 0.25 * s * Fk * np.sin(2 * np.pi * fr * t + 0.3)
    if effect == "acceleration":
        if not mre:
            p = law.params
            tru = make_model("modified_lugre", sigma0=p.sigma0, sigma1=p.sigma1, sigma2=p.sigma2,
                             Fc=p.Fc, Fs=p.Fs, vs=p.vs, alpha=p.alpha, shape=p.shape,
                             v1=1e3 * sc["v99"], v2=2e3 * sc["v99"],
                             f_a=0.5 * s * Fk, a_s=0.1 * sc["a99"], v_c=0.2 * sc["v99"],
                             beta=1.0, gamma=1.0, tau=3 * dt)
            return tru.simulate(t, v, a=a)
        a_s = 0.1 * sc["a99"]
        u = a / np.sqrt(a * a + a_s * a_s) / (1.0 + (v / (0.2 * sc["v99"])) ** 2)
        return F + 0.5 * s * Fk * _lag(t, u, 3 * dt)
    if effect == "load":
        if kin.plant == "forging_press":
            # the seed's own load law, its Table 3 coefficients scaled by the strength
            q = kin.seed_law.params
            tru = kin.seed_law.with_values(**{k: getattr(q, k) * s for k in
                                              ("k1_low", "k2_low", "k3_low", "k1_high",
                                               "k2_high", "k3_high")})
            return tru.simulate(t, v, load=L)
        if not mre:
            p = law.params
            L0 = float(np.mean(L))
            # levels change by 0.4 s x the relative load change (s <= 2.4: Fc0 stays > 0)
            k = 0.4 * min(s, 2.4) / L0
            tru = make_model("load_lugre", sigma0=p.sigma0, sigma1=p.sigma1,
                             Fc0=p.Fc * (1 - k * L0), Fs0=p.Fs * (1 - k * L0), vs=p.vs,
                             sigma20=p.sigma2 * (1 - k * L0),
                             k1_low=k * p.Fc, k2_low=k * p.Fs, k3_low=k * p.sigma2,
                             k1_high=k * p.Fc, k2_high=k * p.Fs, k3_high=k * p.sigma2)
            return tru.simulate(t, v, load=L)
        rel = (L - np.mean(L)) / np.mean(L)
        return F + Ff * 0.6 * s * rel
    if effect == "asymmetry":
        if not mre:
            p = law.params
            return law.with_values(Fc_neg=p.Fc * (1 + 0.4 * s), Fs_neg=p.Fs * (1 + 0.4 * s),
                                   sigma2_neg=p.sigma2 * (1 + 0.5 * s)).simulate(t, v)
        neg = 0.5 * (1 - np.tanh(v / (0.01 * sc["v99"])))
        return F + Ff * 0.4 * s * neg
    if effect == "stribeck_shape":
        if mre:
            raise ValueError("stribeck_shape: the mre_lugre base has no Stribeck curve")
        p = law.params
        tail = 0.4 * s * p.Fc
        vt = STRIBECK_TAIL * sc["v99"]

        def g(vv):
            return law.g(vv) + tail * np.exp(-np.abs(vv) / vt)
        return _lugre_curve(kin, g, p.sigma0, p.sigma1, p.sigma2)
    if effect == "position":
        span = sc["x_hi"] - sc["x_lo"] or 1.0
        xc = _bump_centre(kin)
        if xc is None:
            raise ValueError(f"position: the held-out part of the {kin.plant} record never "
                             f"revisits the positions of its fit part")
        bump = np.exp(-0.5 * ((x - xc) / (0.08 * span)) ** 2)
        return F + Ff * 0.6 * s * bump
    if effect == "inertia":
        from scipy.signal import butter, filtfilt
        fs = 1.0 / dt
        b, aa = butter(2, min(0.2 * fs, 100.0 * max(1.0, fs / 1000.0)) / (0.5 * fs))
        af = filtfilt(b, aa, a)
        dm = 0.3 * s * Fk / sc["a99"]
        return F + dm * af
    if effect == "delay":
        # an acquisition pipeline: transport delay of the force channel (cubic-spline
        # fractional shift) followed by a half-sample first-order anti-alias lag
        from scipy.interpolate import CubicSpline
        d = min(s, MAX_DELAY_SAMPLES) * dt
        Fd = CubicSpline(t, F)(np.clip(t - d, t[0], None))
        return _lag(t, Fd, 0.5 * dt)
    if effect == "drift":
        T = t[-1] - t[0]
        return F + Ff * 0.4 * s * (1.0 - np.exp(-(t - t[0]) / T))
    raise ValueError(f"unknown benchmark effect {effect!r}; the benchmark's cases are diagnosis.benchmark.CASES")
