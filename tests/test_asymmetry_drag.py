"""The ``asymmetry`` candidate's second variant on a classic LuGre, a drag beside the contact
with a curve for each direction (:class:`diagnosis.effects_asymmetry.AsymmetryDrag`): its
formula, the variant protocol that carries it beside the twins, and what it is chosen for on
truths integrated finer than sampled, with noise, scored on a motion not fitted - a pump
worked one way by the axis (a force of another mechanism than the candidate's knots), and a
film drag alike in both directions, which is no asymmetry."""
import numpy as np
import pytest

from diagnosis.candidates import best_variant, law_variants, make_context
from diagnosis.composite import fit_composite
from diagnosis.effects import CANDIDATES
from diagnosis.effects_asymmetry import AsymmetryDrag, AsymmetryTwins
from diagnosis.effects_stribeck import StribeckMap, speed_map
from friction import make_model
from friction.dataset import Dataset

NAMES = ["sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs", "b"]


def _law():
    return make_model("lugre", sigma0=1e5, sigma1=300.0, sigma2=40.0, Fc=10.0, Fs=15.0,
                      vs=5e-3)


def _motion(n, T=2.0, amp=0.05, switch=None):
    """A two-tone velocity [m/s] of amplitude ``amp``, 0.6 ``amp`` after ``switch`` [s]."""
    t = np.linspace(0.0, T, n)
    a = amp if switch is None else np.where(t < switch, amp, 0.6 * amp)
    return t, a * (np.sin(2 * np.pi * 1.5 * t) + 0.2 * np.sin(2 * np.pi * 6.5 * t))


def _pump(v, crack=4.0, k=4e3, v_open=2e-3):
    """A plunger pump the axis works towards +x only, through check valves: delivering, it
    pushes against its relief valve's cracking force plus an orifice loss quadratic in the
    flow [N]; drawing in (v < 0) it meets nothing. The valve opens over ``v_open``."""
    on = 0.5 * (1.0 + np.tanh(v / v_open))
    return on * (crack + k * v ** 2)


def _cross_film(v, eta=200.0, v_c=0.01, n=0.8):
    """A shear-thinning film in parallel with the contact, alike in both directions [N]."""
    return eta * v / (1.0 + (np.abs(v) / v_c) ** n)


def _record(extra, n=2001, fine=8, noise=0.005, seed=0, **motion):
    """The LuGre contact plus ``extra(v)`` on a grid ``fine`` x finer than the samples, then
    sampled, with white noise of ``noise`` x the force's standard deviation."""
    tf, vf = _motion((n - 1) * fine + 1, **motion)
    Ff = _law().simulate(tf, vf) + extra(vf)
    t, v = tf[::fine], vf[::fine]
    rng = np.random.default_rng(seed)
    F = Ff[::fine] + noise * np.std(Ff) * rng.standard_normal(t.size)
    return Dataset.from_arrays(t, F, v=v)


def _fits(law, data):
    """The candidate's two variants fitted on ``data``: ``[(form, composite, fit NRMSE)]``."""
    ctx = make_context(data)
    spec = CANDIDATES["asymmetry"].specialise(law)
    return [(form, *fit_composite(lv, nv, [form], data, ctx))
            for lv, nv, form in law_variants(spec, law, NAMES, ctx)]


def _nrmse(comp, held):
    return float(np.sqrt(np.mean((comp.predict(held) - held.F) ** 2)) / np.std(held.F))


def test_the_twins_and_a_drag_for_each_direction_are_the_two_variants():
    law = _law()
    t, v = _motion(500)
    ctx = make_context(Dataset.from_arrays(t, law.simulate(t, v), v=v))
    spec = CANDIDATES["asymmetry"].specialise(law)
    assert isinstance(spec, AsymmetryTwins)
    (l1, n1, f1), (l2, n2, f2) = law_variants(spec, law, NAMES, ctx)
    assert f1 is spec and {"Fc_neg", "Fs_neg", "sigma2_neg", "b"} <= set(n1)
    assert isinstance(f2, AsymmetryDrag) and f2.name == "asymmetry"
    assert l2 is law and n2 == NAMES
    # a base without its offset free gets it freed with the drag
    assert law_variants(spec, law, NAMES[:-1], ctx)[1][1] == NAMES
    # fitted at the force level only: two curves of KNOTS - 1 knots [N] and a quadratic
    # drag coefficient each [N s^2/m^2]
    ex = f2.force_extras(ctx)
    assert f2.extras(ctx) == [] and len(ex) == 2 * StribeckMap.KNOTS
    assert len({e.name for e in ex}) == len(ex)
    knots = [e for e in ex if e.unit == "N"]
    assert len(knots) == 2 * (StribeckMap.KNOTS - 1)
    assert all(e.lo == -ctx.sF and e.hi == ctx.sF for e in knots)
    quad = [e for e in ex if e.unit == "N.s2/m2"]
    assert [e.name for e in quad] == ["qp_a", "qn_a"]
    assert all(e.hi == -e.lo == pytest.approx(2 * ctx.sF / ctx.sv ** 2) for e in quad)
    assert f2.variant_gain(law) == AsymmetryDrag.GAIN < 1.0


def test_each_curve_acts_on_its_own_direction_and_zero_knots_add_nothing():
    law = _law()
    t, v = _motion(801)
    data = Dataset.from_arrays(t, law.simulate(t, v), v=v)
    ctx = make_context(data)
    drag = AsymmetryDrag("asymmetry", "", "additive")
    F = law.simulate(t, v)
    zero = {e.name: 0.0 for e in drag.force_extras(ctx)}
    assert np.array_equal(drag.apply(F, zero, data, ctx), F)
    # the quadratic drag of each direction
    q = drag.apply(F, dict(zero, qp_a=2.0), data, ctx) - F
    clear = np.abs(v) > 0.1 * ctx.sv       # beyond the indicator's blend (0.02 sv)
    np.testing.assert_allclose(q[clear & (v > 0)], 2.0 * v[clear & (v > 0)] ** 2, rtol=1e-4)
    assert np.all(np.abs(q[clear & (v < 0)]) < 1e-4 * np.abs(q).max())
    knots = [float(k) for k in range(1, StribeckMap.KNOTS)]
    neg_only = dict(zero, **dict(zip(drag._names("n"), knots)))
    added = drag.apply(F, neg_only, data, ctx) - F
    want = -speed_map(np.abs(v), ctx.sv, knots, StribeckMap.DECADES)
    # (the indicator's tanh leaves 1e-4 of the other direction's curve at 0.1 sv)
    np.testing.assert_allclose(added[clear & (v < 0)], want[clear & (v < 0)], rtol=1e-4)
    assert np.all(np.abs(added[clear & (v > 0)]) < 1e-4 * np.abs(want).max())
    # equal curves are the symmetric drag sgn(v) h(|v|)
    both = dict(neg_only, **dict(zip(drag._names("p"), knots)))
    sym = np.sign(v) * speed_map(np.abs(v), ctx.sv, knots, StribeckMap.DECADES)
    np.testing.assert_allclose(drag.apply(F, both, data, ctx) - F, sym, rtol=0, atol=1e-9)
    assert drag.jac(F, both, data, ctx)[0] == 1.0       # an additive form


def test_a_pump_worked_one_way_is_fitted_by_the_drag_and_carries_to_another_motion():
    law = _law()
    fit = _record(_pump)
    held = _record(_pump, n=1001, T=1.0, amp=0.03, seed=1)
    ctx = make_context(fit)
    base, base_nr = fit_composite(law, NAMES, [], fit, ctx)
    (twins, c_tw, nr_tw), (drag, c_dr, nr_dr) = _fits(law, fit)
    assert isinstance(drag, AsymmetryDrag)
    # the fit record chooses the drag: below GAIN x the twins' NRMSE, near the noise (0.5 %)
    assert nr_dr < AsymmetryDrag.GAIN * nr_tw and nr_dr < 0.0065, (base_nr, nr_tw, nr_dr)
    assert best_variant([(c_tw, nr_tw), (c_dr, nr_dr)], ctx)[0] is c_dr
    # and forecasts the held-out motion better than the base and the twins
    scores = [_nrmse(c, held) for c in (base, c_tw, c_dr)]
    assert scores[2] < 0.7 * scores[1] and scores[2] < 0.5 * scores[0], scores
    # the curve for v < 0 stays near nothing beside the one for v > 0
    h_p, h_n = drag.curves(c_dr.extras, np.array([0.5 * ctx.sv]), ctx)
    assert abs(h_n[0]) < 0.25 * abs(h_p[0]), (h_p, h_n)


def test_a_record_the_twins_fit_as_well_keeps_the_twins():
    law = _law()
    twin = law.with_values(Fc_neg=13.0, Fs_neg=18.0)
    t, v = _motion(2001)
    rng = np.random.default_rng(3)
    F = twin.simulate(t, v)
    data = Dataset.from_arrays(t, F + 0.005 * np.std(F) * rng.standard_normal(t.size), v=v)
    ctx = make_context(data)
    (twins, c_tw, nr_tw), (drag, c_dr, nr_dr) = _fits(law, data)
    assert nr_tw < 0.006 and nr_dr > AsymmetryDrag.GAIN * nr_tw, (nr_tw, nr_dr)
    assert best_variant([(c_tw, nr_tw), (c_dr, nr_dr)], ctx)[0] is c_tw


@pytest.mark.parametrize("extra, named", [(_pump, "asymmetry"),
                                          (_cross_film, "stribeck_shape")])
def test_the_diagnosis_names_a_one_way_pump_and_not_a_film_alike_both_ways(extra, named):
    from diagnosis import diagnose
    # fitted on one amplitude, held out (the last 30 % of the record) on a smaller one
    data = _record(extra, n=3001, T=3.0, noise=0.01, switch=2.0)
    rep = diagnose(data, _law(), candidates=["asymmetry", "stribeck_shape", "load"],
                   greedy=False, threads=1)
    eff = {e["name"]: e for e in rep["effects"]}
    assert rep["verdict"]["cause"] == named, (rep["verdict"], eff)
    assert eff[named]["excess_closed"] > 0.7


def test_a_drag_alike_both_ways_is_no_practical_asymmetry():
    law = _law()
    t, v = _motion(801)
    ctx = make_context(Dataset.from_arrays(t, law.simulate(t, v), v=v))
    # the fit record's speeds, where the share is weighed
    assert len(ctx.speeds) == 50 and ctx.speeds[-1] <= np.abs(v).max()
    assert np.all(np.diff(ctx.speeds) >= 0)
    drag = AsymmetryDrag("asymmetry", "", "additive")
    zero = {e.name: 0.0 for e in drag.force_extras(ctx)}
    knots = [float(k) for k in range(1, StribeckMap.KNOTS)]
    alike = dict(zero, qp_a=3.0, qn_a=3.0, **dict(zip(drag._names("p"), knots)),
                 **dict(zip(drag._names("n"), knots)))
    one_way = dict(zero, qp_a=3.0, **dict(zip(drag._names("p"), knots)))
    assert drag.direction_share(zero, ctx) == 0.0
    assert drag.direction_share(alike, ctx) == pytest.approx(0.0, abs=1e-12)
    # one curve and none: half of it differs, half is alike, sqrt(1/2) of the RMS
    assert drag.direction_share(one_way, ctx) == pytest.approx(np.sqrt(0.5))
    assert "alike both ways" in drag.practical(alike, ctx)
    assert drag.practical(one_way, ctx) == ""
    # the twins variant is kept where the drag's best fit is no practical asymmetry
    fit = _record(_cross_film)
    ctx = make_context(fit)
    (twins, c_tw, nr_tw), (drag, c_dr, nr_dr) = _fits(law, fit)
    assert nr_dr < AsymmetryDrag.GAIN * nr_tw, (nr_tw, nr_dr)
    assert drag.direction_share(c_dr.extras, ctx) < AsymmetryDrag.MIN_SHARE
    assert best_variant([(c_tw, nr_tw), (c_dr, nr_dr)], ctx)[0] is c_tw
