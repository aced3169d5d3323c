"""Truth forces of the benchmark: the base law plus a withheld effect, along a motion.

Each effect's truth forms are functions here that its record names
(:attr:`diagnosis.effects.Effect.truths`, ``generic_truth``, ``truth_applies``): per plant
``truth(kin, s) -> F`` [N] along a plant's motion (:class:`.kinematics.PlantKinematics`, its
``base`` law) with an amplitude factor ``s`` (:func:`.cases.make_plant_case` calibrates it
to the requested strength), generic ``truth(s, t, x, v, a) -> (F, load)`` on the mass-like
axis of :func:`.cases.make_case` with the LuGre law :data:`BASE`. Each differs in form from
the candidate that should name it (:mod:`diagnosis.candidates`); see the table in
:mod:`diagnosis.benchmark`. The benchmark's own cases without an effect, ``clean`` and
``outside``, are :data:`BENCH_CASES`.
"""
from __future__ import annotations

import functools
import math

import numpy as np
from numba import njit

from friction import make_model
from friction.lugre import bristle_update
from friction.shapes import SHAPES, stribeck_g
from friction.steps import split_at_reversals

from .kinematics import PlantKinematics, fine_kinematics

__all__ = ["BASE", "MAX_DELAY_SAMPLES", "STRIBECK_TAIL", "FIT_FRACTION", "BENCH_CASES",
           "BENCH_GENERIC", "on_fine_grid", "lugre_with_curve", "level_inside", "base_force",
           "sampled_base_force"]

BASE = dict(sigma0=2e4, sigma1=150.0, sigma2=8.0, Fc=2.0, Fs=2.8, vs=5e-3)
#: longest force-channel delay of the ``delay`` truth [samples] (the candidate reaches 25)
MAX_DELAY_SAMPLES = 20.0
#: speed scale of the extra low-speed tail of the ``stribeck_shape`` truth, x v99 [-]
STRIBECK_TAIL = 0.05


# -- generic cases (historical): a multi-sine motion of a mass-like axis -----------------------
def _generic_base():
    return make_model("lugre", **BASE)


def acceleration_generic(s, t, x, v, a):
    """Modified LuGre (seed 000) with its lagged acceleration part."""
    truth = make_model("modified_lugre", sigma0=BASE["sigma0"], sigma1=BASE["sigma1"],
                       sigma2=BASE["sigma2"], Fc=BASE["Fc"], Fs=BASE["Fs"], vs=BASE["vs"])
    truth = truth.with_values(f_a=1.5 * s, a_s=0.3, v_c=0.04, tau=0.01)
    return truth.simulate(t, v, a=a), None


def load_generic(s, t, x, v, a):
    """Levels linear in a varying normal load (seed 004 style)."""
    load = 100.0 + 60.0 * np.sin(2 * np.pi * 0.05 * t) ** 2 + 20 * (t / t[-1])
    levels = 1.0 + 0.6 * s * (load - 100.0) / 100.0
    return _generic_base().simulate(t, v) * levels, load


def asymmetry_generic(s, t, x, v, a):
    """Direction twins of the levels and the viscous slope."""
    F = _generic_base().with_values(Fc_neg=BASE["Fc"] * (1 + 0.5 * s),
                                    Fs_neg=BASE["Fs"] * (1 + 0.5 * s),
                                    sigma2_neg=BASE["sigma2"] * (1 + 0.6 * s)).simulate(t, v)
    return F, None


def stribeck_shape_generic(s, t, x, v, a):
    """A long Lorentzian tail: the Gaussian base cannot bend like it."""
    F = _generic_base().with_values(shape="lorentzian", Fc=BASE["Fc"] * 0.6,
                                    Fs=BASE["Fs"] * (1 + 1.5 * s),
                                    vs=BASE["vs"] * 3).simulate(t, v)
    return F, None


def position_generic(s, t, x, v, a):
    """A half-cosine level change along the stroke."""
    span = np.ptp(x)
    F = _generic_base().simulate(t, v) + 0.8 * s * np.cos(np.pi * (x - x.min()) / span) \
        * np.tanh(v / 2e-3)
    return F, None


def inertia_generic(s, t, x, v, a):
    """A 1.2 kg (x s) mass error in the inverse dynamics."""
    return _generic_base().simulate(t, v) + 1.2 * s * a, None


def delay_generic(s, t, x, v, a):
    """The force channel 4.5 s samples late (linear interpolation)."""
    dt = t[1] - t[0]
    return np.interp(t - 4.5 * s * dt, t, _generic_base().simulate(t, v)), None


def drift_generic(s, t, x, v, a):
    """A saturating warm-up of the levels."""
    warm = 1.0 + 0.5 * s * (1.0 - np.exp(-t / (0.6 * t[-1])))
    return _generic_base().simulate(t, v) * warm, None


def clean_generic(s, t, x, v, a):
    """The base law itself."""
    return _generic_base().simulate(t, v), None


def outside_generic(s, t, x, v, a):
    """An electrical ripple at 13 Hz, unrelated to motion: no candidate can express it."""
    return _generic_base().simulate(t, v) + 0.6 * s * np.sin(2 * np.pi * 13.0 * t), None


#: generic truths of the cases that are no effect of the library
BENCH_GENERIC = {"clean": clean_generic, "outside": outside_generic}


# -- per-plant cases: along a plant's simulated motion ----------------------------------------
def on_fine_grid(fn):
    """A per-plant truth ``fn(kin, s) -> F`` computed along the plant's continuous motion on
    the grid :data:`.kinematics.FINE` x finer than the data (:func:`.kinematics.
    fine_kinematics`: ``kin.dt`` is the fine step there, ``kin.sample_dt`` the data's) and
    returned at the data's sample instants."""
    @functools.wraps(fn)
    def truth(kin: PlantKinematics, s: float) -> np.ndarray:
        fk = fine_kinematics(kin)
        return np.asarray(fn(fk, s), float)[::fk.step]
    truth.fine_grid = True
    return truth


def _setting(kin: PlantKinematics):
    # what most truths start from: base force, its friction part, friction level, scales
    F, Ff = _base_parts(kin)
    return F, Ff, _level(kin), kin.scales


@on_fine_grid
def clean_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The base law itself (expected verdict ``none``)."""
    return _base_parts(kin)[0]


@on_fine_grid
def outside_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """An electrical ripple at 0.0537 x the sample rate, unrelated to the motion."""
    F, _, Fk, _ = _setting(kin)
    fr = 0.0537 / kin.sample_dt
    return F + 0.25 * s * Fk * np.sin(2 * np.pi * fr * kin.t + 0.3)


#: per-plant truths of the cases that are no effect of the library
BENCH_CASES = {"clean": clean_truth, "outside": outside_truth}


@on_fine_grid
def acceleration_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Modified LuGre (seed 000) with a lagged F_d; isolator: a first-order-lagged
    a/sqrt(a^2+a_s^2) fading as 1/(1+(v/v_c)^2)."""
    t, v, a, law, dt = kin.t, kin.v, kin.a, kin.base, kin.sample_dt
    F, _, Fk, sc = _setting(kin)
    if law.name != "mre_lugre":
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


@on_fine_grid
def load_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Seed-004 levels affine in the load inside the bristle dynamics (``load_lugre``; the
    press: the seed's own Table 3 coefficients x ``s``)."""
    t, v, L, law = kin.t, kin.v, kin.load, kin.base
    if kin.plant == "forging_press":
        q = kin.seed_law.params
        tru = kin.seed_law.with_values(**{k: getattr(q, k) * s for k in
                                          ("k1_low", "k2_low", "k3_low", "k1_high",
                                           "k2_high", "k3_high")})
        return tru.simulate(t, v, load=L)
    if law.name != "mre_lugre":
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
    F, Ff = _base_parts(kin)
    rel = (L - np.mean(L)) / np.mean(L)
    return F + Ff * 0.6 * s * rel


@on_fine_grid
def asymmetry_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Direction twins Fc_neg, Fs_neg, sigma2_neg (isolator: hysteretic part scaled on
    v < 0)."""
    law = kin.base
    if law.name != "mre_lugre":
        p = law.params
        return law.with_values(Fc_neg=p.Fc * (1 + 0.4 * s), Fs_neg=p.Fs * (1 + 0.4 * s),
                               sigma2_neg=p.sigma2 * (1 + 0.5 * s)).simulate(kin.t, kin.v)
    F, Ff, _, sc = _setting(kin)
    neg = 0.5 * (1 - np.tanh(kin.v / (0.01 * sc["v99"])))
    return F + Ff * 0.4 * s * neg


def has_stribeck_curve(kin: PlantKinematics) -> bool:
    """Whether the plant's base law has a Stribeck curve (not the isolator's mre_lugre)."""
    return kin.base.name != "mre_lugre"


@on_fine_grid
def stribeck_shape_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """LuGre whose Stribeck curve has an extra exponential low-speed tail (neither
    Gaussian-alpha nor Lorentzian)."""
    law = kin.base
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape: the mre_lugre base has no Stribeck curve")
    p = law.params
    tail = 0.4 * s * p.Fc
    vt = STRIBECK_TAIL * kin.scales["v99"]
    return lugre_with_curve(kin, lambda vv: law.g(vv) + tail * np.exp(-np.abs(vv) / vt))


def revisits_positions(kin: PlantKinematics) -> bool:
    """Whether the held-out part of the record revisits the fit part's positions
    (:func:`_bump_centre`; not the press's one-way stroke)."""
    return _bump_centre(kin) is not None


@on_fine_grid
def position_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A local defect: friction raised by a Gaussian bump along the stroke, centred where
    fit and held-out parts both pass."""
    F, Ff, _, sc = _setting(kin)
    span = sc["x_hi"] - sc["x_lo"] or 1.0
    xc = _bump_centre(kin)
    if xc is None:
        raise ValueError(f"position: the held-out part of the {kin.plant} record never "
                         f"revisits the positions of its fit part")
    bump = np.exp(-0.5 * ((kin.x - xc) / (0.08 * span)) ** 2)
    return F + Ff * 0.6 * s * bump


@on_fine_grid
def inertia_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A mass error times the *filtered* acceleration of the inverse dynamics."""
    from scipy.signal import butter, filtfilt
    F, _, Fk, sc = _setting(kin)
    fs = 1.0 / kin.dt
    fs_data = 1.0 / kin.sample_dt
    cut = min(0.2 * fs_data, 100.0 * max(1.0, fs_data / 1000.0))
    b, aa = butter(2, cut / (0.5 * fs))
    af = filtfilt(b, aa, kin.a)
    dm = 0.3 * s * Fk / sc["a99"]
    return F + dm * af


@on_fine_grid
def delay_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """An acquisition pipeline: transport delay of the force channel (cubic-spline
    fractional shift of ``s`` samples, at most :data:`MAX_DELAY_SAMPLES`) followed by a
    half-sample first-order anti-alias lag."""
    from scipy.interpolate import CubicSpline
    t, dt = kin.t, kin.sample_dt
    F = _base_parts(kin)[0]
    d = min(s, MAX_DELAY_SAMPLES) * dt
    Fd = CubicSpline(t, F)(np.clip(t - d, t[0], None))
    return _lag(t, Fd, 0.5 * dt)


@on_fine_grid
def drift_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A saturating warm-up of the friction level (time constant: the record)."""
    F, Ff = _base_parts(kin)
    t = kin.t
    T = t[-1] - t[0]
    return F + Ff * 0.4 * s * (1.0 - np.exp(-(t - t[0]) / T))


@njit(cache=True)
def _lugre_run(t, v, g, g_mid, s0, s1, visc):
    """LuGre force [N] along (t, v) with its Stribeck curve given as values, ``g`` [N] at
    the grid points and ``g_mid`` [N] at the step midpoints, and its viscous force ``visc``
    [N] given at the grid points (levels may vary along the grid inside the bristle
    dynamics); the bristle advances by the friction package's exact step
    (:func:`friction.lugre.bristle_update`, every LuGre kernel's)."""
    n = t.size
    F = np.empty(n)
    z = 0.0
    for k in range(n):
        zd = v[k] - s0 * abs(v[k]) * z / g[k]
        F[k] = s0 * z + s1 * zd + visc[k]
        if k + 1 < n:
            vm = 0.5 * (v[k] + v[k + 1])
            z = bristle_update(z, vm, s0 * abs(vm) / g_mid[k], t[k + 1] - t[k], 0)
    return F


def lugre_with_curve(kin: PlantKinematics, g, level=None, visc_level=None) -> np.ndarray:
    """The LuGre base of ``kin`` along its grid with the Stribeck curve ``g(v)`` [N] and
    relative levels ``level`` [-] of that curve and ``visc_level`` [-] of the viscous term
    (arrays on the grid, default 1) acting *inside* the bristle dynamics.

    Parameters
    ----------
    kin : PlantKinematics
        The motion (a LuGre base: ``sigma0``, ``sigma1``, ``sigma2``).
    g : callable
        Stribeck curve ``g(v)`` [N] of velocity [m/s] (``kin.base.g`` for the base's own).
    level, visc_level : ndarray, optional
        Relative level of the curve and of the viscous term at the grid points [-].

    Returns
    -------
    ndarray
        Force [N] at the grid points.
    """
    p = kin.base.params
    v = kin.v
    lev = np.ones_like(v) if level is None else np.asarray(level, float)
    vl = lev if visc_level is None else np.asarray(visc_level, float)
    vm = 0.5 * (v[1:] + v[:-1])
    return _lugre_run(kin.t, v, lev * g(v), 0.5 * (lev[1:] + lev[:-1]) * g(vm),
                      float(p.sigma0), float(p.sigma1), float(p.sigma2) * vl * v)


def level_inside(kin: PlantKinematics, level, visc_level=None) -> np.ndarray:
    """The base law with its friction levels scaled by ``level`` [-] (arrays on ``kin``'s
    grid): inside the bristle dynamics for a LuGre base (:func:`lugre_with_curve`), on the
    friction part of the force for the isolator's mre_lugre (no Stribeck curve)."""
    if kin.base.name == "mre_lugre":
        F, Ff = _base_parts(kin)
        return F + Ff * (np.asarray(level, float) - 1.0)
    return lugre_with_curve(kin, kin.base.g, level, visc_level)


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
    """(F_base, F_friction_part): the force of the base law along ``kin``'s grid and the part
    effects act on."""
    law, t, v, x = kin.base, kin.t, kin.v, kin.x
    if law.name == "mre_lugre":
        p = law.params
        F = law.simulate(t, v, x=x)
        return F, F - p.k0 * x - p.f0  # the spring and offset carry no friction
    F = law.simulate(t, v)
    return F, F


def base_force(kin: PlantKinematics) -> np.ndarray:
    """The base law's force [N] at the data's samples, integrated along the continuous
    motion on the truths' grid (what a case without effect measures, noise-free)."""
    fk = fine_kinematics(kin)
    return _base_parts(fk)[0][::fk.step]


def sampled_base_force(kin: PlantKinematics) -> np.ndarray:
    """The base law's force [N] simulated at the data's sample rate along the exact sampled
    motion (what the diagnosis' own law computes): :func:`base_force` minus this is the
    base's discretisation at the data rate, which no candidate is asked to explain."""
    law = kin.base
    # as the diagnosis simulates every model: a sample added at each reversal in a step
    # (diagnosis.composite.simulate_split)
    if law.name == "mre_lugre":
        fk = fine_kinematics(kin)
        t, v, (x,), idx = split_at_reversals(kin.t, kin.v, fk.x[::fk.step])
        F = law.simulate(t, v, x=x)
    else:
        t, v, _, idx = split_at_reversals(kin.t, kin.v)
        F = law.simulate(t, v)
    return F if idx is None else F[idx]


def _level(kin: PlantKinematics) -> float:
    """Friction level of the base law [N] (Coulomb level or saturated hysteretic force)."""
    p = kin.base.params
    if kin.base.name == "mre_lugre":
        return float(p.beta / p.alpha)
    return float(p.Fc)


def _motion_time(kin: PlantKinematics) -> float:
    """A time scale of the motion [s]: top speed over top acceleration."""
    sc = kin.scales
    return sc["v99"] / max(sc["a99"], 1e-12)


def _span(kin: PlantKinematics) -> float:
    """The stroke the record visits [m]."""
    sc = kin.scales
    return (sc["x_hi"] - sc["x_lo"]) or 1.0


def _lugre_params(kin: PlantKinematics, form: str):
    """Parameters of ``kin``'s base law, which the truth ``form`` (``"effect (form)"``) needs
    to be a classic LuGre (its bristle, damping, curve and viscous term); ValueError
    naming the form and the plant's base otherwise."""
    if kin.base.name != "lugre":
        raise ValueError(f"{form}: needs a classic LuGre base, the {kin.plant} base is "
                         f"{kin.base.name}")
    return kin.base.params


def _presliding_path(kin: PlantKinematics, s: float, share: float) -> tuple[float, float]:
    """The base bristle's presliding path ``Fs / sigma0`` [m] and the path a presliding
    truth adds at amplitude ``s``: ``s`` x ``share`` x the stroke / 3 [m] (``s`` < 0: 0)."""
    p = kin.base.params
    return (float(p.Fs) / float(p.sigma0),
            max(float(s), 0.0) * share * float(np.ptp(kin.x)) / 3.0)


def _smooth_max0(u, eps):
    """max(u, 0), rounded over ``eps`` (measured signals never switch in one sample)."""
    return 0.5 * (u + np.sqrt(u * u + eps * eps))


#: what bridges the play of :func:`_driven_contact`: a spring (``g1`` its stiffness [N/m]),
#: a squeeze film (``g1`` its drag c0 [N s/m], ``g2`` the floor of its gap factor [-]) or a
#: friction drag (``g1`` its Coulomb force [N], ``g2`` the slip speed it is rounded over
#: [m/s])
GAP_SPRING, GAP_SQUEEZE, GAP_DRAG, GAP_BIAS = 0, 1, 2, 3


@njit(cache=True)
def _driven_contact(h, xd, half, gap_kind, g1, g2, m, kh, ch, s0, s1, s2, Fc, Fs, vs, alpha,
                    shape):
    """LuGre friction [N] of a contact of mass ``m`` [kg] driven by the drive positions
    ``xd`` [m] (grid step ``h`` [s]) across a play of half-width ``half`` [m], the flanks a
    spring ``kh`` [N/m] and damper ``ch`` [N s/m] (compressive only). Inside the play
    (``gap_kind``): :data:`GAP_SPRING`, a spring ``g1`` bridging it (its force at the flank
    g1 half); :data:`GAP_SQUEEZE`, the oil squeezed between the flanks drags the contact,
    g1 (vd - v) / (1 - (e / half)^2 + g2)^1.5; :data:`GAP_DRAG`, a friction-loaded idler
    drags the contact, g1 tanh((vd - v) / g2); :data:`GAP_BIAS`, a constant force g1 [N]
    acts on the contact (a weight or a spring) and nothing bridges the play. Semi-implicit
    Euler of the mass, exact bristle update at the contact's velocity."""
    n = xd.size
    F = np.empty(n)
    x = xd[0]
    v = 0.0
    z = 0.0
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        e = xd[j] - x
        ed = vd - v
        if gap_kind == GAP_SPRING:
            fc = g1 * min(max(e, -half), half)
        elif gap_kind == GAP_DRAG:
            fc = g1 * math.tanh(ed / g2)
        elif gap_kind == GAP_BIAS:
            fc = g1
        else:
            fc = 0.0
            if half > 0.0 and abs(e) < half:
                q = 1.0 - (e / half) ** 2 + g2
                fc = g1 * ed / q ** 1.5
        if e > half:
            f2 = kh * (e - half) + ch * ed
            if f2 > 0.0:
                fc += f2
        elif e < -half:
            f2 = kh * (-e - half) - ch * ed
            if f2 > 0.0:
                fc -= f2
        g = stribeck_g(v, Fc, Fs, vs, alpha, shape)
        zd = v - s0 * abs(v) * z / g
        ff = s0 * z + s1 * zd + s2 * v
        F[j] = ff
        v = v + h * (fc - ff) / m
        if v != 0.0:
            gv = stribeck_g(v, Fc, Fs, vs, alpha, shape)
            zss = math.copysign(gv / s0, v)
            z = zss + (z - zss) * math.exp(-h * s0 * abs(v) / gv)
        x = x + h * v
    return F


def _contact_constants(kin: PlantKinematics, p):
    """(m [kg], kh [N/m], ch [N s/m]) of the light contact behind a play
    (:func:`_driven_contact`): its inertial force at the top acceleration 1 % of the
    Coulomb level, the flanks a coupling 100 x stiffer than the bristle, damping ratio 0.5."""
    m = 0.01 * float(p.Fc) / max(kin.scales["a99"], 1e-12)
    kh = 100.0 * float(p.sigma0)
    return m, kh, 2.0 * 0.5 * math.sqrt(kh * m)


@njit(cache=True)
def _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """One step ``h`` [s] of a light contact of mass ``m`` [kg] with LuGre friction
    (``s0`` [N/m], ``s1``, ``s2`` [N s/m], the curve ``Fc``, ``Fs`` [N], ``vs`` [m/s],
    ``alpha``, ``shape``) under the coupling force ``fc`` [N] from the velocity ``v``
    [m/s] and bristle ``z`` [m]: (its friction [N] at the step's start, the velocity and
    bristle after it); semi-implicit Euler of the mass, the bristle advanced exactly at
    the new velocity (:func:`friction.lugre.bristle_update`)."""
    g = stribeck_g(v, Fc, Fs, vs, alpha, shape)
    ff = s0 * z + s1 * (v - s0 * abs(v) * z / g) + s2 * v
    v = v + h * (fc - ff) / m
    z = bristle_update(z, v, s0 * abs(v) / stribeck_g(v, Fc, Fs, vs, alpha, shape), h, 0)
    return ff, v, z


def _substeps(kin: PlantKinematics, rate: float):
    """(step [s], drive positions [m], sub-steps per grid step) of sub-steps of ``kin``'s
    grid that resolve a light contact's motion whose fastest rate is ``rate`` [1/s] (at
    most 0.3 / ``rate``; 4 to 400 per grid step), the drive's positions interpolated."""
    n_sub = int(min(max(math.ceil(rate * kin.dt / 0.3), 4), 400))
    t2 = kin.t[0] + (kin.dt / n_sub) * np.arange((kin.t.size - 1) * n_sub + 1)
    return kin.dt / n_sub, np.interp(t2, kin.t, kin.x), n_sub


def _run_driven_contact(kin: PlantKinematics, p, half, gap_kind, g1, g2, m, kh, ch,
                        c_gap=0.0):
    """:func:`_driven_contact` along ``kin``'s motion with the base LuGre ``p``, on
    sub-steps that resolve the contact's stiffest and most damped motion (``c_gap``
    [N s/m]: the largest damping the play adds), sampled back on ``kin``'s grid [N]."""
    rate = max(math.sqrt(kh / m), (float(p.sigma1) + float(p.sigma2) + ch + c_gap) / m)
    h, xd, n_sub = _substeps(kin, rate)
    F = _driven_contact(h, xd, half, gap_kind, g1, g2, m, kh, ch,
                        float(p.sigma0), float(p.sigma1), float(p.sigma2), float(p.Fc),
                        float(p.Fs), float(p.vs), float(p.alpha), SHAPES[p.shape])
    return F[::n_sub]
