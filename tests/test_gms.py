"""The generalized Maxwell-slip law (friction/gms.py): presliding hysteresis with nonlocal
memory, the transition to the Stribeck curve, frictional lag, stable numerics and the
kernel against the continuous-time reference."""
from __future__ import annotations

import numpy as np
import pytest

from friction import MODELS, ParameterError, make_model
from friction.gms import GMS, GMSParams, N_ELEMENTS
from friction.reference import simulate_prescribed

#: rate-independent presliding: the attraction so fast that the corner rounding |v| g / C
#: is below rounding of the deflections
FAST = dict(C=1e12, sigma2=0.0)


def legs(points, unit, n_unit=80, V=1e-5):
    """A drive moving at speed V from point to point (positions [m], multiples of ``unit``),
    coming to rest for one sample at each turning point. ``n_unit`` steps per ``unit`` of
    travel. Returns t, v, the drive's displacement x (the trapezoid of v: the travel the
    kernel sees) and the sample indices of the turning points (v = 0 there)."""
    h = unit / (V * n_unit)
    v, turns = [0.0], []
    for a, b in zip(points[:-1], points[1:]):
        m = int(round(abs(b - a) / unit)) * n_unit  # travel m V h: 0 -> V, V ... V, V -> 0
        v += [float(np.sign(b - a)) * V] * m + [0.0]
        turns.append(len(v) - 1)
    v = np.asarray(v)
    t = h * np.arange(v.size)
    x = np.concatenate(([0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * h)))
    return t, v, x, turns


def test_registered_with_units_bounds_and_search_ranges():
    assert MODELS["gms"] is GMS
    m = make_model("gms")
    assert m.state_names == ("z1", "z2", "z3", "z4") and m.extra_inputs == ()
    for info in GMSParams.info():
        assert info.unit and info.description and info.search is not None, info.name
        assert info.admissible(getattr(m.params, info.name)), info.name
    k = m.element_stiffness()
    assert k.sum() == pytest.approx(m.params.sigma0, rel=1e-14)
    assert k[0] / k[-1] == pytest.approx(m.params.spread, rel=1e-12)
    assert np.all(np.diff(k) < 0)
    np.testing.assert_allclose(make_model("gms", spread=1.0).element_stiffness(),
                               np.full(N_ELEMENTS, 2.5e4), rtol=1e-14)


@pytest.mark.parametrize("kw", [{}, {"shape": "lorentzian"}, {"alpha": 0.8, "b": 0.3},
                                {"C": 50.0, "spread": 300.0}])
@pytest.mark.parametrize("speed", [2e-4, 1e-3, 5e-3, 0.1])
@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_sliding_at_a_constant_speed_settles_on_the_stribeck_curve(kw, speed, sign):
    m = make_model("gms", **kw)
    T = 30 * m.params.Fs / m.params.C + 20 * m.presliding_distance() / speed
    t = np.linspace(0.0, T, 4001)
    v = np.full(t.size, sign * speed)
    F, S = m.simulate(t, v, return_state=True)
    Fss = float(m.steady_state([sign * speed])[0])
    assert F[-1] == pytest.approx(Fss, rel=1e-9)
    np.testing.assert_allclose(S[-1], m.steady_state_state(sign * speed), rtol=1e-9)
    assert np.all(np.abs(m.derivatives(S[-1], sign * speed)) <= 1e-9 * speed)


def test_virgin_curve_and_the_transition_to_sliding():
    """A first loading from rest follows the virgin curve sum k_i clip(x, d_i) (every block
    elastic, then slipping one after the other: the stiffest first) and reaches the
    sliding force g at the presliding distance, Stribeck level at rest Fs."""
    m = make_model("gms", Fc=1.5, Fs=1.5, **FAST)
    d = m.presliding_distance()
    t, v, x, _ = legs([0.0, 1.5 * d], 1.5 * d, 600)
    F = m.simulate(t, v)
    np.testing.assert_allclose(F, m.virgin_force(x), rtol=0, atol=1e-12)
    k = m.element_stiffness()
    # slope sigma0 at the start, falling by k_i as each block breaks away
    assert (F[1] - F[0]) / (x[1] - x[0]) == pytest.approx(m.params.sigma0, rel=1e-9)
    assert F[-1] == pytest.approx(1.5, rel=1e-12)
    brk = 1.5 / (N_ELEMENTS * k)
    np.testing.assert_allclose(brk[-1], d, rtol=1e-14)
    inside = x < 0.999 * brk[0]
    np.testing.assert_allclose(F[inside], m.params.sigma0 * x[inside], rtol=1e-9)


def test_presliding_hysteresis_has_nonlocal_memory():
    """Outer loop +-A with inner loops: each inner loop closes where it left the outer one
    (return-point memory), the motion then continues on the outer branch as if the inner
    loop had not been (wiping-out), and every branch obeys Masing's rule
    F - F_r = +-2 F_v((x - x_r) / 2) from its reversal point (x_r, F_r)."""
    m = make_model("gms", Fc=1.0, Fs=1.0, spread=30.0, **FAST)
    A = 0.8 * m.presliding_distance(1.0)
    # outer loop, then a descending branch interrupted by two nested inner loops
    plain = [0.0, A, -A, A, -A]
    nested = [0.0, A, -A, A, 0.2 * A, 0.6 * A, 0.4 * A, 0.6 * A, 0.2 * A, A, -A]
    tp, vp, xp, turns_p = legs(plain, 0.2 * A)
    tn, vn, xn, turns_n = legs(nested, 0.2 * A)
    Fp, Sp = m.simulate(tp, vp, return_state=True)
    Fn, Sn = m.simulate(tn, vn, return_state=True)
    scale = np.max(np.abs(Sp), axis=0)
    # return points (turns_n[j] is where the drive stops at nested[j + 1]): the inner loop
    # 0.6A -> 0.4A -> 0.6A closes at 0.6A, the loop 0.2A -> ... -> 0.2A at 0.2A, and back
    # at A the state is the outer loop's at A
    for i, j in ((turns_n[4], turns_n[6]), (turns_n[3], turns_n[7]), (turns_n[2], turns_n[8])):
        assert xn[i] == pytest.approx(xn[j], abs=1e-15)
        np.testing.assert_allclose(Sn[i] / scale, Sn[j] / scale, rtol=0, atol=1e-12)
    # wiping-out: the last descending branch A -> -A equals the plain loop's
    last_n = slice(turns_n[8], turns_n[9] + 1)
    last_p = slice(turns_p[2], turns_p[3] + 1)
    np.testing.assert_allclose(Fn[last_n], Fp[last_p], rtol=0, atol=1e-12)
    # Masing: the descending branch from (A, F_A) is F_A - 2 F_v((A - x) / 2), the
    # ascending one from (-A, F_-A) is F_-A + 2 F_v((x + A) / 2); inner branches likewise
    for i0, i1 in zip(turns_n[1:-1], turns_n[2:]):
        seg = slice(i0, i1 + 1)
        xr, Fr = xn[i0], Fn[i0]
        sgn = np.sign(xn[i1] - xr)
        expect = Fr + sgn * 2.0 * m.virgin_force(np.abs(xn[seg] - xr) / 2.0, level=1.0)
        np.testing.assert_allclose(Fn[seg], expect, rtol=0, atol=1e-11)
    # the loop is a hysteresis: it encloses area (the energy dissipated, F along the motion
    # above F against it) and is point-symmetric
    assert np.trapezoid(Fp[turns_p[1]:turns_p[3] + 1], xp[turns_p[1]:turns_p[3] + 1]) > 0
    up = slice(turns_p[2], turns_p[3] + 1)
    down = slice(turns_p[1], turns_p[2] + 1)
    np.testing.assert_allclose(Fp[up], -Fp[down], rtol=0, atol=1e-12)


def test_presliding_is_rate_independent_in_the_limit_of_a_fast_attraction():
    """With a finite attraction rate a block starts slipping |v| g / C before its
    break-away deflection: the virgin curve is rounded at each break-away by at most
    sigma0 |v| g / C, which vanishes as the attraction gets faster (or the motion slower)."""
    devs = []
    for C in (1e3, 1e4, 1e5):
        m = make_model("gms", Fc=1.0, Fs=1.0, spread=30.0, C=C, sigma2=0.0)
        V = 1e-4
        d = m.presliding_distance()
        t, v, x, _ = legs([0.0, 1.5 * d], 1.5 * d, 1000, V=V)
        dev = np.max(np.abs(m.simulate(t, v) - m.virgin_force(x, level=1.0)))
        assert 0.0 < dev <= m.params.sigma0 * V * 1.0 / C
        devs.append(dev)
    assert devs[1] < 0.2 * devs[0] and devs[2] < 0.2 * devs[1], devs


def test_frictional_lag_above_the_curve_speeding_up_and_below_slowing_down():
    m = make_model("gms", C=200.0, vs=5e-3, shape="lorentzian")
    t = np.linspace(0.0, 0.2, 20001)
    v = 8e-3 * (1.2 - np.cos(2 * np.pi * 5 * t))  # always forward, speeding up and down
    F = m.simulate(t, v, state0=m.steady_state_state(v[0]))
    Fss = m.steady_state(v)
    acc = np.gradient(v, t)
    late = t > 0.05
    # the Stribeck curve falls with speed: speeding up the blocks lag above it, slowing
    # down below it
    assert np.all((F - Fss)[late & (acc > 0.3 * acc.max())] > 0)
    assert np.all((F - Fss)[late & (acc < 0.3 * acc.min())] < 0)
    lag = m.params.Fs / m.params.C
    assert 1e-3 < lag < 1e-2
    # a much faster attraction follows the curve
    fast = m.with_values(C=1e7).simulate(t, v, state0=m.steady_state_state(v[0]))
    assert np.max(np.abs(fast - Fss)[late]) < 2e-3 * np.max(np.abs(F - Fss)[late])


@pytest.mark.parametrize("h", [1e-6, 1e-4, 1e-2])
def test_exact_update_is_stable_at_any_step_and_stiffness(h):
    m = make_model("gms", sigma0=1e9, C=1e12, spread=1e6, Fc=0.1, Fs=5.0)
    t = h * np.arange(3000)
    rng = np.random.default_rng(0)
    v = np.repeat(rng.standard_normal(300), 10) * 10.0 ** rng.uniform(-6, 0, 3000)
    F, S = m.simulate(t, v, return_state=True)
    assert np.all(np.isfinite(F))
    dmax = max(m.params.Fc, m.params.Fs) / (N_ELEMENTS * m.element_stiffness())
    assert np.all(np.abs(S) <= dmax * (1 + 1e-12))
    assert np.max(np.abs(F)) <= m.params.Fs * (1 + 1e-9) + m.params.sigma2 * np.max(np.abs(v))
    # explicit Euler of the same equations overshoots the break-away and oscillates once
    # h C / g > 2 (the sticking rate |v| bounds it from below)
    t = 1e-3 * np.arange(200)
    m = make_model("gms", C=1e5)
    Fe = m.simulate(t, np.full(t.size, 1e-2), method="euler")
    assert np.max(np.abs(Fe)) > 10 * m.params.Fs
    F = m.simulate(t, np.full(t.size, 1e-2))
    assert np.max(np.abs(F)) <= m.params.Fs


@pytest.mark.parametrize("kw", [dict(C=2e3),
                                # LuGre bristles, damped, unequal shares
                                dict(element="bristle", spread=30.0, tilt=0.3, sigma1=20.0),
                                # a damped bristle with three slip-blocks beside it
                                dict(element="beside", spread=30.0, tilt=0.3, sigma1=20.0,
                                     C=2e3, share=0.4, sigma_b=2e3)])
def test_kernel_converges_to_the_continuous_time_reference(kw):
    """Max force error of the kernel against simulate_prescribed (Radau, rtol 1e-10) on a
    motion with reversals, presliding and sliding, Stribeck curve and lag on: second order
    in the step."""
    m = make_model("gms", **kw)
    T = 0.1
    tr = np.linspace(0.0, T, 201)
    vr = 3e-3 * np.sin(2 * np.pi * 20 * tr) + 1e-3 * np.sin(2 * np.pi * 73 * tr)
    Fr = simulate_prescribed(m, tr, vr, rtol=1e-10, atol=1e-10 * m.state_scales())
    errs = []
    for n in (201, 801, 3201):
        t = np.linspace(0.0, T, n)
        F = m.simulate(t, np.interp(t, tr, vr))[::(n - 1) // 200]
        errs.append(np.max(np.abs(F - Fr)))
    assert errs[-1] < 1e-4 * np.max(np.abs(Fr))
    assert errs[0] / errs[1] > 6 and errs[1] / errs[2] > 6, errs  # ~16: second order


def test_steady_start_and_the_force_family_of_a_record_start():
    m = make_model("gms")
    for v0 in (3e-2, -1e-3):
        s = m.steady_state_state(v0)
        np.testing.assert_allclose(s, np.sign(v0) * m.saturation(v0), rtol=1e-15)
        assert np.all(m.derivatives(s, v0) == 0.0)
        assert m.force(s, v0) == pytest.approx(float(m.steady_state([v0])[0]), rel=1e-14)
    assert np.all(m.steady_state_state(0.0) == 0.0)
    # a record cut in the presliding after a reversal from sliding (rate-independent
    # limit: the reversal family holds exactly) and cut in sliding
    m = make_model("gms", Fc=1.2, Fs=1.2, **FAST)
    t = np.linspace(0.0, 0.2, 4001)
    v = 2e-2 * np.sin(2 * np.pi * 7.0 * t + 0.3)  # strokes 10 x the presliding distance
    F, S = m.simulate(t, v, return_state=True)
    rev = int(np.flatnonzero(np.diff(np.sign(v)) != 0)[0]) + 1
    for k in (rev + 3, rev + 100, rev + 300, 300, 1500):
        s = m.record_start_state(t[k:], v[k:], F=F[k:])
        np.testing.assert_allclose(s, S[k], rtol=0, atol=1e-9 * m.z_max())
    # at rest under a load: the first loading from rest, within the law's reach
    s = m.record_start_state(t[:50], np.zeros(50), F=np.full(50, 0.3))
    assert m.force(s, 0.0) == pytest.approx(0.3, rel=1e-12)
    s = m.record_start_state(t[:50], np.zeros(50), F=np.full(50, 1e9))
    np.testing.assert_allclose(s, m.params.Fs / (N_ELEMENTS * m.element_stiffness()))
    # with the micro-damping, in motion: the compiled bisection still meets the first force
    # within the family's reach (at 2e-2 m/s the sticking blocks' damping, sigma1 v = 2 N,
    # lifts its whole range to [1.0, g(v0)]: its end is the start)
    m = make_model("gms", sigma1=float(m.params.sigma0) * 1e-3, **FAST)
    s = m.record_start_state(t[:50], np.full(50, 2e-2), F=np.full(50, 0.4))
    assert m.force(s, 2e-2) == pytest.approx(1.0, rel=1e-9)
    for v0, F0 in ((-1e-3, -0.7), (5e-3, -0.2)):
        s = m.record_start_state(t[:50], np.full(50, v0), F=np.full(50, F0))
        assert m.force(s, v0) == pytest.approx(F0, rel=1e-9)


def test_micro_damping_is_lugres_sigma1_after_a_reversal_and_vanishes_in_sliding():
    """sigma1 (the blocks' micro-damping, proportional to their stiffness) adds exactly
    sigma1 v while every block sticks (right after a reversal), nothing once they slip at a
    steady speed, and leaves the deflections alone; the kernel's force equals the law's
    continuous-time force at the states it reports, and sigma1 = 0 is the undamped law bit
    for bit."""
    kw = dict(sigma0=1e5, spread=10.0, C=1e4, Fc=1.0, Fs=1.5, vs=1e-3)
    m0, m1 = make_model("gms", **kw), make_model("gms", sigma1=50.0, **kw)
    i = list(m0.theta_layout).index("sigma1")
    assert np.array_equal(np.delete(m0.theta, i), np.delete(m1.theta, i))
    assert m0.params.sigma1 == 0.0
    t = np.linspace(0.0, 2.0, 20001)
    v = 2e-3 * np.sin(2 * np.pi * t)
    F0, S0 = m0.simulate(t, v, return_state=True)
    F1, S1 = m1.simulate(t, v, return_state=True)
    np.testing.assert_array_equal(S0, S1)  # an output term: the states do not see it
    after = np.searchsorted(t, 0.5) + 5     # every block sticking after the reversal at 0.5 s
    assert F1[after] - F0[after] == pytest.approx(50.0 * v[after], rel=1e-9)
    sliding = np.searchsorted(t, 0.25)      # top speed, every block slipping at d_i(v)
    assert abs(F1[sliding] - F0[sliding]) < 1e-3 * 50.0 * abs(v[sliding])
    for k in (after, sliding, 12345):
        assert F1[k] == pytest.approx(m1.force(S1[k], v[k]), rel=1e-12, abs=1e-12)
    with pytest.raises(ValueError, match="sigma1"):
        make_model("gms", sigma1=-1.0, **kw)


def test_tilted_shares_keep_the_steady_curve_and_move_the_presliding():
    """Unequal break-away shares (``tilt``): the shares sum to 1, so the steady-state
    force is still the Stribeck curve; the presliding distance is the softest block's
    share of Fs over its stiffness, and ``tilt`` = 1 is the equal split bit for bit."""
    kw = dict(sigma0=1e5, spread=100.0, C=1e6, Fc=1.0, Fs=1.5, vs=1e-3, sigma2=0.0)
    eq, tl = make_model("gms", **kw), make_model("gms", tilt=0.1, **kw)
    w = tl.element_shares()
    assert w.sum() == pytest.approx(1.0) and w[-1] / w[0] == pytest.approx(0.1)
    np.testing.assert_array_equal(eq.element_shares(), np.full(4, 0.25))
    k = tl.element_stiffness()
    assert tl.presliding_distance() == pytest.approx(1.5 * w[-1] / k[-1])
    # a slow constant-speed stroke ends on the curve for both splits
    t = np.linspace(0.0, 2.0, 4001)
    v = np.full_like(t, 2e-2)
    for m in (eq, tl):
        assert m.simulate(t, v)[-1] == pytest.approx(float(m.steady_state([2e-2])[0]), rel=1e-6)
    # the virgin presliding curve at 8 um: equal shares, the stiffest block has broken
    # away at 0.375 N / 6.9e4 N/m = 5.4 um; tilted, it carries 0.46 of the level and still
    # sticks (10 um), so every block is elastic: F = sigma0 x 8 um = 0.8 N
    ts = np.linspace(0.0, 0.1, 2001)
    vs = np.full_like(ts, 1e-4)
    Fe, Ft = eq.simulate(ts, vs), tl.simulate(ts, vs)
    assert Ft[1600] == pytest.approx(0.8, rel=1e-3) and Fe[1600] < 0.6
    bad = dict(kw, tilt=0.0)
    with pytest.raises(ParameterError, match="tilt"):
        make_model("gms", **bad)


# -- bristle elements (friction.gms.ELEMENTS) -------------------------------------------------
#: a heavily damped contact like the damping rig's (its base LuGre values)
RIG = dict(sigma0=4458.0, sigma1=138.8, sigma2=48.5, Fc=5.27, Fs=34.4, vs=0.021, alpha=2.0)


def _rig_motion():
    """Sinusoids with a square wave on top: velocity jumps through zero inside samples."""
    t = np.arange(0.0, 2.0, 1e-3)
    v = 0.05 * np.sin(2 * np.pi * 1.3 * t) + 0.02 * np.sign(np.sin(2 * np.pi * 0.7 * t))
    return t, v


def test_four_equal_bristles_are_the_lugre_law():
    """element = "bristle" with spread and tilt 1: four equal LuGre bristles, the LuGre law
    itself (its start from a measured first force included); only the steps that straddle a
    reversal differ (cut at the reversal here, LuGre's midpoint speed there), and what they
    leave decays: < 2e-5 of the force's spread."""
    t, v = _rig_motion()
    lugre = make_model("lugre", **RIG)
    four = make_model("gms", spread=1.0, tilt=1.0, element="bristle", C=1.0, **RIG)
    F0 = np.full(t.size, 3.0)
    s_l = lugre.record_start_state(t, v, F=F0)
    s_g = four.record_start_state(t, v, F=F0)
    np.testing.assert_allclose(s_g, np.full(N_ELEMENTS, s_l[0]), rtol=1e-12)
    Fl, Fg = lugre.simulate(t, v, state0=s_l), four.simulate(t, v, state0=s_g)
    assert Fg[0] == pytest.approx(3.0, rel=1e-12)
    first = int(np.flatnonzero(np.sign(v[1:]) != np.sign(v[:-1]))[0]) + 1
    np.testing.assert_allclose(Fg[:first], Fl[:first], rtol=1e-12, atol=1e-12 * np.ptp(Fl))
    assert np.max(np.abs(Fg - Fl)) < 2e-5 * np.ptp(Fl)
    # slip-blocks with the same values cannot draw it: sticking blocks give sigma1 |v|
    # right after a reversal where the bristle gives up to 2 sigma1 |v|
    slip = four.with_values(element="slip", C=1e6)
    Fs = slip.simulate(t, v, state0=slip.record_start_state(t, v, F=F0))
    assert np.sqrt(np.mean((Fs - Fl) ** 2)) > 50 * np.sqrt(np.mean((Fg - Fl) ** 2))


def test_a_bristle_with_nothing_beside_it_is_the_lugre_law():
    """element = "beside" at share 0: the contact's bristle alone (the blocks beside it
    carry nothing and stay undeflected), the LuGre law as four equal bristles are, its
    start from a measured first force included; with a share the blocks carry it: sliding
    far, every element at its share, the force is the Stribeck curve, and the blocks'
    virgin presliding reaches share x Fs at their break-away deflections."""
    t, v = _rig_motion()
    lugre = make_model("lugre", **RIG)
    four = make_model("gms", spread=1.0, tilt=1.0, element="bristle", C=1.0, **RIG)
    alone = make_model("gms", element="beside", share=0.0, spread=20.0, tilt=3.0,
                       sigma_b=50.0, **RIG)
    F0 = np.full(t.size, 3.0)
    s_b = alone.record_start_state(t, v, F=F0)
    s_l = lugre.record_start_state(t, v, F=F0)
    assert s_b[0] == pytest.approx(s_l[0], rel=1e-12) and not np.any(s_b[1:])
    Fb, S = alone.simulate(t, v, state0=s_b, return_state=True)
    Ff = four.simulate(t, v, state0=four.record_start_state(t, v, F=F0))
    assert not np.any(S[:, 1:])
    np.testing.assert_allclose(Fb, Ff, rtol=1e-12, atol=1e-12 * np.ptp(Ff))
    assert np.max(np.abs(Fb - lugre.simulate(t, v, state0=s_l))) < 2e-5 * np.ptp(Fb)
    # with a share: the elements' layout, the steady state, the blocks' reach
    m = alone.with_values(share=0.3, sigma_b=5e3)
    k, w = m.element_stiffness(), m.element_shares()
    assert k[0] == RIG["sigma0"] and w[0] == pytest.approx(0.7)
    assert np.sum(k[1:]) == pytest.approx(5e3) and k[1] / k[3] == pytest.approx(20.0)
    assert np.sum(w[1:]) == pytest.approx(0.3) and w[3] / w[1] == pytest.approx(3.0)
    tt = np.linspace(0.0, 2.0, 4001)
    F = m.simulate(tt, np.full(tt.size, 0.05))
    assert F[-1] == pytest.approx(float(m.steady_state([0.05])[0]), rel=1e-6)
    assert m.presliding_distance() == pytest.approx(RIG["Fs"] * w[3] / k[3], rel=1e-12)


def test_bristle_virgin_curve_is_a_sum_of_exponentials():
    """From rest without history at a constant level (Fc = Fs), each bristle approaches its
    break-away deflection d_i exponentially over the travel: F(x) = sum_i k_i d_i
    (1 - exp(-x / d_i)); the attraction rate C plays no part."""
    kw = dict(sigma0=1e5, spread=100.0, tilt=0.3, Fc=1.0, Fs=1.0, sigma2=0.0,
              element="bristle")
    m = make_model("gms", C=1e4, **kw)
    V = 1e-4
    t = np.linspace(0.0, 0.5, 5001)
    F = m.simulate(t, np.full(t.size, V))
    x = V * t
    k = m.element_stiffness()
    d = 1.0 * m.element_shares() / k
    want = np.sum(k * d * (1.0 - np.exp(-x[:, None] / d)), axis=1)
    np.testing.assert_allclose(F, want, rtol=1e-9, atol=1e-12)
    np.testing.assert_array_equal(F, make_model("gms", C=3.0, **kw).simulate(t, np.full(t.size, V)))


def test_bristle_exact_update_is_stable_at_any_step():
    """Stiff bristles (sigma0 1e7 N/m) at steps up to 0.1 s: the deflections stay within
    their saturation and the force within the curve's reach; explicit Euler blows up."""
    m = make_model("gms", element="bristle", sigma0=1e7, spread=10.0, sigma1=0.0)
    t = np.arange(0.0, 5.0, 0.1)
    v = 0.05 * np.sin(2 * np.pi * 0.3 * t)
    F, S = m.simulate(t, v, return_state=True)
    assert np.all(np.abs(S) <= m.state_scales() * (1 + 1e-12))
    assert np.all(np.abs(F) <= max(m.params.Fc, m.params.Fs) + m.params.sigma2 * 0.05 + 1e-9)
    Fe = m.simulate(t, v, method="euler")
    assert not np.all(np.isfinite(Fe)) or np.max(np.abs(Fe)) > 1e3 * np.max(np.abs(F))


def test_unknown_element_is_refused_by_name():
    with pytest.raises(ParameterError, match=r"element = 'brush'.*bristle.*slip"):
        make_model("gms", element="brush")
