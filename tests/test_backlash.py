"""Backlash in front of a LuGre contact (friction/backlash.py): lost motion 2 delta at each
reversal, LuGre without a gap, stable numerics and the kernel against the reference."""
from __future__ import annotations

import numpy as np
import pytest

from friction import MODELS, make_model
from friction.backlash import ENGAGE_BAND, BacklashLuGre, BacklashLuGreParams
from friction.reference import simulate_prescribed


def triangle(X, periods=2.0, n=8001, T=1.0):
    """Drive displacement x = X tri(t) (speed 4 X / T, reversals at the tips), sampled so
    that each tip is a sample with v = 0: (t, v, x, tips)."""
    t = np.linspace(0.0, periods * T, n)
    ph = (t / T) % 1.0
    v = np.where(ph < 0.25, 1.0, np.where(ph < 0.75, -1.0, 1.0)) * 4 * X / T
    tips = np.flatnonzero(np.isclose(ph, 0.25) | np.isclose(ph, 0.75))
    v[tips] = 0.0
    x = np.concatenate(([0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(t))))
    return t, v, x, tips


def test_registered_with_units_bounds_and_search_ranges():
    assert MODELS["backlash_lugre"] is BacklashLuGre
    m = make_model("backlash_lugre")
    assert m.state_names == ("z", "p") and m.extra_inputs == ()
    info = {i.name: i for i in BacklashLuGreParams.info()}
    assert info["delta"].unit == "m" and info["delta"].admissible(0.0)
    assert not info["delta"].admissible(-1e-9)
    assert set(BacklashLuGreParams.OPTIONS) == {"shape", "gap"}
    with pytest.raises(ValueError, match="gap"):
        make_model("backlash_lugre", gap="loose")


@pytest.mark.parametrize("kw", [{}, {"Fc_neg": 2.0, "sigma2_neg": 1.0, "shape": "lorentzian"},
                                {"alpha": 0.7, "b": 0.2, "gap": "free"}])
def test_no_gap_is_the_lugre_law_bit_for_bit(kw):
    rng = np.random.default_rng(4)
    t = np.cumsum(10.0 ** rng.uniform(-6, -2, 4000))
    v = 3e-3 * np.sin(2 * np.pi * 3 * t) + 1e-3 * rng.standard_normal(t.size)
    v[500:600] = 0.0
    lug = {k: val for k, val in kw.items() if k != "gap"}
    m = make_model("backlash_lugre", delta=0.0, **kw)
    lg = make_model("lugre", **lug)
    for method in ("exact", "euler"):
        F, S = m.simulate(t, v, method=method, state0=[2e-6, 0.0], return_state=True)
        Fl, Sl = lg.simulate(t, v, method=method, state0=[2e-6], return_state=True)
        np.testing.assert_array_equal(F, Fl)
        np.testing.assert_array_equal(S[:, 0], Sl[:, 0])
        assert np.all(S[:, 1] == 0.0)
    P = m.simulate_population(t, v, ["sigma0", "Fc"], [[1e5, 1.0], [3e4, 2.0]])
    Pl = lg.simulate_population(t, v, ["sigma0", "Fc"], [[1e5, 1.0], [3e4, 2.0]])
    np.testing.assert_array_equal(P, Pl)
    # and continuous time
    for s, vv in (([1e-6, 0.0], 1e-3), ([-3e-6, 0.0], -2e-3), ([1e-6, 0.0], 0.0)):
        assert m.force(s, vv) == lg.force(s[:1], vv)
        assert m.derivatives(s, vv)[0] == lg.derivatives(s[:1], vv)[0]


@pytest.mark.parametrize("delta", [1e-4, 3e-4])
def test_each_reversal_has_a_flat_segment_of_width_two_delta(delta):
    """F(x) of a triangular drive: after each reversal the force holds its value (gap
    "hold") while the drive crosses the gap, over 2 delta of travel (less the stiff flank's
    band), then the contact follows; with gap "free" it is the offset b there."""
    X = 1e-3
    t, v, x, tips = triangle(X)
    for gap in ("hold", "free"):
        m = make_model("backlash_lugre", delta=delta, gap=gap, b=0.05)
        F, S = m.simulate(t, v, return_state=True)
        dx = np.max(np.abs(np.diff(x)))
        for k in tips:
            sgn = -np.sign(v[k - 1])  # direction after the reversal
            after = np.arange(k + 1, t.size)
            travel = sgn * (x[after] - x[k])
            crossed = np.flatnonzero(travel >= (2 - ENGAGE_BAND) * delta - 1e-12)
            inside = after[:crossed[0]] if crossed.size else after
            held = F[k] if gap == "hold" else m.params.b
            if gap == "hold":
                assert abs(F[k] - m.params.b) > 0.5  # the contact held a sliding force
            np.testing.assert_array_equal(F[inside], held)
            # the contact stands still: its bristle is frozen
            assert np.all(S[inside, 0] == S[k, 0])
            # once the drive has crossed the gap, the contact follows
            beyond = after[(travel > 2 * delta + dx) & (travel < 2 * delta + 20 * dx)]
            assert np.all(F[beyond] != held)
            np.testing.assert_allclose(np.abs(S[beyond, 1]), delta, rtol=0,
                                       atol=ENGAGE_BAND * delta)


def test_force_is_the_lugre_force_of_the_contact_shifted_by_delta():
    """With a constant level and no rate terms the LuGre bristle is a Dahl element whose
    branch from a reversal (x_r, z_r) is z = s zs + (z_r - s zs) exp(-s (x - x_r) / zs),
    zs = g / sigma0. Behind the gap the contact reverses where the drive did, offset by
    delta, and follows it at x - p (x - s delta once the flank's band is closed): F(x) is
    that branch of the contact's position."""
    delta, sigma0 = 2e-4, 1e5
    m = make_model("backlash_lugre", delta=delta, sigma0=sigma0, sigma1=0.0, sigma2=0.0,
                   Fs=1.0, Fc=1.0)
    zs = 1.0 / sigma0
    t, v, x, tips = triangle(1e-3, n=16001)
    F, S = m.simulate(t, v, return_state=True)
    checked = 0
    for k, k_next in zip(tips, list(tips[1:]) + [t.size - 1]):
        s = -np.sign(v[k - 1])
        seg = np.arange(k + 1, k_next)
        seg = seg[s * (x[seg] - x[k]) > 2 * delta + 1e-9]  # engaged
        xc = x[seg] - S[seg, 1]                     # the contact's position
        xcr = x[k] - S[k, 1]                        # where the contact reversed
        assert S[k, 1] == -s * delta
        z = s * zs + (S[k, 0] - s * zs) * np.exp(-s * (xc - xcr) / zs)
        np.testing.assert_allclose(F[seg], sigma0 * z, rtol=1e-9, atol=1e-12)
        np.testing.assert_allclose(xc, x[seg] - s * delta, rtol=0, atol=ENGAGE_BAND * delta)
        checked += seg.size
    assert checked > t.size // 2


def test_steady_state_is_the_stribeck_curve_on_the_leading_flank():
    m = make_model("backlash_lugre", delta=5e-4, Fc_neg=1.3)
    for v0 in (2e-3, -5e-2):
        t = np.linspace(0.0, 0.5, 5001)
        F, S = m.simulate(t, np.full(t.size, v0), return_state=True)
        assert F[-1] == pytest.approx(float(m.steady_state([v0])[0]), rel=1e-9)
        np.testing.assert_allclose(S[-1], m.steady_state_state(v0), rtol=1e-9)
        # the first 5e-4 m of travel (less the flank's band) only cross half the gap: no
        # force but the bristle's
        n_gap = int((1 - 2 * ENGAGE_BAND) * 5e-4 / abs(v0) / (t[1] - t[0]))
        assert np.all(F[:n_gap] == 0.0)
    s = m.steady_state_state(1e-2)
    assert np.all(m.derivatives(s, 1e-2) == 0.0)
    assert np.all(m.steady_state_state(0.0) == 0.0)


@pytest.mark.parametrize("h", [1e-6, 1e-4, 1e-2])
def test_exact_update_is_stable_at_any_step_and_stiffness(h):
    m = make_model("backlash_lugre", sigma0=1e9, sigma1=0.0, delta=1e-6, Fc=0.1, Fs=5.0)
    t = h * np.arange(3000)
    rng = np.random.default_rng(1)
    v = np.repeat(rng.standard_normal(300), 10) * 10.0 ** rng.uniform(-6, 0, 3000)
    F, S = m.simulate(t, v, return_state=True)
    assert np.all(np.isfinite(F))
    assert np.all(np.abs(S[:, 0]) <= m.z_max() * (1 + 1e-12))
    assert np.all(np.abs(S[:, 1]) <= 1e-6)


def test_kernel_converges_to_the_continuous_time_reference():
    """Max force error of the kernel against simulate_prescribed (Radau, rtol 1e-10) on a
    motion with reversals inside steps, engagements and sliding: second order in the step."""
    m = make_model("backlash_lugre", delta=1e-5)
    T = 0.2
    tr = np.linspace(0.0, T, 201)
    vr = 3e-3 * np.sin(2 * np.pi * 10 * tr + 0.2) + 1e-3 * np.sin(2 * np.pi * 47 * tr)
    Fr = simulate_prescribed(m, tr, vr, rtol=1e-10, atol=1e-10 * m.state_scales())
    errs = []
    for n in (201, 801, 3201):
        t = np.linspace(0.0, T, n)
        F = m.simulate(t, np.interp(t, tr, vr))[::(n - 1) // 200]
        errs.append(np.max(np.abs(F - Fr)))
    assert errs[-1] < 1e-4 * np.max(np.abs(Fr))
    assert errs[0] / errs[1] > 6 and errs[1] / errs[2] > 6, errs  # ~16: second order


def test_a_record_cut_while_the_drive_crosses_the_gap_starts_there():
    """The measured first force opposing the motion: the drive has just reversed and is
    crossing the gap; the state taken from the record's first samples is the one the whole
    record had there (travel since the reversal from the first acceleration)."""
    m = make_model("backlash_lugre", delta=1e-4)
    t = np.linspace(0.0, 0.2, 20001)
    v = 0.05 * np.sin(2 * np.pi * 7.0 * t + 0.3)
    F, S = m.simulate(t, v, return_state=True)
    rev = int(np.flatnonzero(np.diff(np.sign(v)) != 0)[0]) + 1
    for k in (rev + 2, rev + 20, rev + 60):
        assert abs(S[k, 1]) < 1e-4  # inside the gap
        s = m.record_start_state(t[k:], v[k:], F=F[k:])
        assert s[0] == pytest.approx(S[k, 0], rel=1e-12)
        assert s[1] == pytest.approx(S[k, 1], abs=1e-3 * 1e-4)
        Fk = m.simulate(t[k:], v[k:], state0=s)
        assert np.max(np.abs(Fk - F[k:])) < 1e-2 * np.max(np.abs(F))
    # sliding: the leading flank and the steady bristle
    k = 3000
    s = m.record_start_state(t[k:], v[k:], F=F[k:])
    np.testing.assert_allclose(s, S[k], rtol=1e-9)


def test_native_fmu_reproduces_the_law_first_order_in_step():
    """The native FMU holds its inputs over a step, the law interpolates them: with no rate
    terms at the contact (sigma1 = sigma2 = 0, F continuous in time) the two agree to O(h).
    With sigma1 or sigma2 > 0 the force jumps by (sigma1 + sigma2) v when the contact
    engages, and a held input moves that instant by up to a step: the error at the jump
    does not shrink with the step (tests/test_fmus.py's first-order check cannot apply)."""
    from fmus.native.build import SUFFIX
    from fmus.testing import LoggedSlave, built_native_fmus
    from friction.metrics import nrmse
    path = built_native_fmus(("backlash_lugre",)) / f"backlash_lugre{SUFFIX}.fmu"
    params = dict(sigma1=0.0, sigma2=0.0, delta=2e-5)
    law = make_model("backlash_lugre", **params)
    errs = []
    for h in (2e-4, 1e-4, 5e-5):
        t = h * np.arange(int(round(0.1 / h)) + 1)
        v = 2e-3 * np.sin(2 * np.pi * 10 * t) + 5e-4
        s = LoggedSlave(path)
        try:
            s.init(**params)
            F = np.empty(t.size)
            for k in range(t.size):
                s.set("v", float(v[k]))
                F[k] = s.get("F")
                if k + 1 < t.size:
                    assert s.step(t[k], h) == 0
        finally:
            s.close()
        errs.append(nrmse(law.simulate(t, v), F))
    assert errs[-1] < 2e-2, errs
    assert errs[0] / errs[1] > 1.6 and errs[1] / errs[2] > 1.6, errs
