"""The ``stribeck_shape`` candidate's second form on a classic LuGre, a drag beside the contact
(:class:`diagnosis.effects_stribeck.StribeckDrag`), and the variant protocol that carries it
(:func:`diagnosis.candidates.law_variants`): which form the fit record chooses on truths of
either kind (a film drag in parallel with the contact, a level inside the bristle
dynamics), integrated finer than sampled, with noise, scored on a motion not fitted."""
import numpy as np
import pytest

from diagnosis.candidates import Candidate, law_variants, make_context
from diagnosis.composite import fit_composite
from diagnosis.effects import CANDIDATES
from diagnosis.effects_stribeck import StribeckDrag, StribeckMap, speed_map
from friction import make_model
from friction.dataset import Dataset

NAMES = ["sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs"]


def _law():
    return make_model("lugre", sigma0=1e5, sigma1=300.0, sigma2=40.0, Fc=10.0, Fs=15.0,
                      vs=5e-3)


def _motion(n, T=2.0, amp=0.05, switch=None):
    """A two-tone velocity [m/s] of amplitude ``amp``, 0.6 ``amp`` after ``switch`` [s]
    (a whole number of seconds: both tones pass zero there)."""
    t = np.linspace(0.0, T, n)
    a = amp if switch is None else np.where(t < switch, amp, 0.6 * amp)
    return t, a * (np.sin(2 * np.pi * 1.5 * t) + 0.2 * np.sin(2 * np.pi * 6.5 * t))


def _cross_film(v, eta=200.0, v_c=0.01, n=0.8):
    """A shear-thinning film in parallel with the contact (Cross's model): its drag
    eta v / (1 + (|v| / v_c)^n) [N] rises linearly, then bends well below linear."""
    return eta * v / (1.0 + (np.abs(v) / v_c) ** n)


def _hump(v, vs):
    # a mixed-lubrication hump of the level inside the bristle: +40 % around 4 vs
    return 1.0 + 0.4 * np.exp(-np.log10(np.maximum(np.abs(v), 1e-12) / (4 * vs)) ** 2
                              / (2 * 0.3 ** 2))


def _record(truth, n=2001, fine=8, noise=0.005, seed=0, **motion):
    """``truth(t, v)`` on a grid ``fine`` x finer than the samples, then sampled, with
    white noise of ``noise`` x the force's standard deviation."""
    tf, vf = _motion((n - 1) * fine + 1, **motion)
    Ff = truth(tf, vf)
    t, v = tf[::fine], vf[::fine]
    rng = np.random.default_rng(seed)
    F = Ff[::fine] + noise * np.std(Ff) * rng.standard_normal(t.size)
    return Dataset.from_arrays(t, F, v=v)


def _drag_truth(t, v):
    return _law().simulate(t, v) + _cross_film(v)


def _inside_truth(t, v):
    law = _law()
    return law.simulate_level(t, v, _hump(v, law.params.vs))


def _fits(law, data):
    """The candidate's two forms fitted on ``data``: ``[(form, composite, fit NRMSE)]``."""
    ctx = make_context(data)
    spec = CANDIDATES["stribeck_shape"].specialise(law)
    return [(form, *fit_composite(lv, nv, [form], data, ctx))
            for lv, nv, form in law_variants(spec, law, NAMES, ctx)]


def _nrmse(comp, held):
    return float(np.sqrt(np.mean((comp.predict(held) - held.F) ** 2)) / np.std(held.F))


def test_the_map_has_two_forms_the_curve_kept_inside_and_freed_beside():
    law = _law()
    t, v = _motion(500)
    ctx = make_context(Dataset.from_arrays(t, law.simulate(t, v), v=v))
    spec = CANDIDATES["stribeck_shape"].specialise(law)
    (l1, n1, f1), (l2, n2, f2) = law_variants(spec, law, NAMES + ["alpha", "b"], ctx)
    assert f1 is spec and isinstance(f1, StribeckMap)
    assert not set(n1) & set(StribeckMap.CURVE) and "sigma0" in n1
    assert isinstance(f2, StribeckDrag) and f2.name == "stribeck_shape"
    assert n2 == NAMES + ["alpha", "b"]
    # the drag is fitted at the force level only, in newtons, below the fit's top speed
    assert f2.extras(ctx) == [] and len(f2.force_extras(ctx)) == StribeckMap.KNOTS - 1
    assert all(e.unit == "N" and e.lo == -ctx.sF and e.hi == ctx.sF
               for e in f2.force_extras(ctx))
    # a candidate without forms of its own: each variant with the candidate itself
    plain = Candidate("x", "")
    assert law_variants(plain, law, NAMES, ctx) == [(law, NAMES, plain)]
    # a malformed variant is named, not unpacked into the wrong places
    bad = Candidate("bad", "")
    bad.modify_law = lambda law, names, ctx: [(law, names, "inside")]
    with pytest.raises(ValueError, match="bad.modify_law gave the variant"):
        law_variants(bad, law, NAMES, ctx)


def test_the_drag_is_odd_in_the_velocity_and_nothing_at_its_zero_knots():
    law = _law()
    t, v = _motion(801)
    data = Dataset.from_arrays(t, law.simulate(t, v), v=v)
    ctx = make_context(data)
    drag = StribeckDrag("stribeck_shape", "", "additive")
    zero = {n: 0.0 for n in drag._names()}
    F = law.simulate(t, v)
    assert np.array_equal(drag.apply(F, zero, data, ctx), F)
    knots = {n: float(k) for k, n in enumerate(drag._names(), 1)}
    added = drag.apply(F, knots, data, ctx) - F
    want = np.sign(v) * speed_map(np.abs(v), ctx.sv, list(knots.values()),
                                  StribeckMap.DECADES)
    np.testing.assert_allclose(added, want, rtol=0, atol=1e-12)
    # an additive form: d apply / dF = 1
    assert drag.jac(F, knots, data, ctx)[0] == 1.0


def test_a_film_drag_beside_the_contact_is_fitted_by_the_drag_and_carries_to_another_motion():
    law = _law()
    fit = _record(_drag_truth)
    held = _record(_drag_truth, n=1001, T=1.0, amp=0.03, seed=1)
    ctx = make_context(fit)
    _, base_nr = fit_composite(law, NAMES, [], fit, ctx)
    (inside, c_in, nr_in), (drag, c_dr, nr_dr) = _fits(law, fit)
    assert isinstance(drag, StribeckDrag)
    # the fit record chooses the drag: it fits it better than the map inside, to the
    # noise (0.5 %)
    assert nr_dr < 0.9 * nr_in and nr_dr < 0.0055, (base_nr, nr_in, nr_dr)
    # and the drag forecasts the held-out motion better than the base and the map inside
    # (on the noise again)
    scores = [_nrmse(c, held) for c in (fit_composite(law, NAMES, [], fit, ctx)[0], c_in,
                                         c_dr)]
    assert scores[2] < 0.8 * scores[1] and scores[2] < 0.4 * scores[0], scores
    assert scores[2] < 0.0065, scores
    # its curve stays a Stribeck drop (not bent to mimic the film)
    assert c_dr.law.params.Fs > c_dr.law.params.Fc


def test_a_level_inside_the_bristle_is_fitted_by_the_map_inside():
    law = _law()
    fit = _record(_inside_truth)
    (inside, c_in, nr_in), (drag, c_dr, nr_dr) = _fits(law, fit)
    assert isinstance(inside, StribeckMap)
    # the fit record chooses the map inside (the diagnosis keeps the lower fit NRMSE)
    assert nr_in < nr_dr, (nr_in, nr_dr)


def test_the_diagnosis_names_the_drag_and_reports_its_knots():
    from diagnosis import diagnose
    # fitted on one amplitude, held out (the last 30 % of the record) on a smaller one
    data = _record(_drag_truth, n=3001, T=3.0, noise=0.01, switch=2.0)
    rep = diagnose(data, _law(), candidates=["stribeck_shape", "load", "position"],
                   greedy=False, threads=1)
    eff = {e["name"]: e for e in rep["effects"]}
    assert rep["verdict"]["cause"] == "stribeck_shape", (rep["verdict"], eff)
    assert eff["stribeck_shape"]["excess_closed"] > 0.7
    extras = rep["effect_details"]["stribeck_shape"]["extras"]
    assert sorted(extras) == sorted(StribeckDrag("s", "")._names())


def test_the_drag_stacks_beside_an_effect_with_exact_columns(monkeypatch):
    """The drag's curvature prior adds rows to the joint fit's residual; beside an effect
    with exact derivative columns (``position``) the structured Jacobian carries them too
    (it raised a shape error: 980 rows for a residual of 987), and the fit ends where the
    fit with scipy's own differences ends."""
    import diagnosis.composite as composite
    law = _law()
    fit = _record(_drag_truth)
    ctx = make_context(fit)
    spec = CANDIDATES["stribeck_shape"].specialise(law)
    lv, nv, drag = law_variants(spec, law, NAMES, ctx)[1]
    assert isinstance(drag, StribeckDrag)
    pos = CANDIDATES["position"].specialise(law)
    assert pos.exact_extras
    comp, cost = fit_composite(lv, nv, [drag, pos], fit, ctx)
    monkeypatch.setattr(composite, "STRUCTURED_JACOBIAN", False)
    comp_ref, cost_ref = fit_composite(lv, nv, [drag, pos], fit, ctx)
    assert np.isfinite(cost) and cost == pytest.approx(cost_ref, rel=0.02)
    assert cost < 0.0055          # the film and the contact to the noise (0.5 %)
