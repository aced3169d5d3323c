"""Friction levels scaled inside the LuGre bristle dynamics (``LuGre.simulate_level``) and the
``stribeck_shape`` speed map that uses them (:class:`diagnosis.effects_stribeck.StribeckMap`):
analytic limits, an independent reference integrator, bad input, and a fit that reaches a
Stribeck drop outside the Gaussian-alpha/Lorentzian family."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

from diagnosis.candidates import law_variants, make_context
from diagnosis.effects_stribeck import StribeckMap, StribeckShape, speed_map
from diagnosis.composite import fit_composite
from diagnosis.effects import CANDIDATES
from friction import make_model
from friction.dataset import Dataset


def _law():
    return make_model("lugre", sigma0=1e5, sigma1=300.0, sigma2=40.0, Fc=10.0, Fs=15.0,
                      vs=5e-3)


def _motion(n, T=1.0):
    t = np.linspace(0.0, T, n)
    return t, 0.05 * np.sin(2 * np.pi * 2 * t) + 0.01 * np.sin(2 * np.pi * 7 * t)


def test_unit_level_is_the_law_and_a_constant_level_scales_its_levels():
    law = _law()
    t, v = _motion(2001)
    assert np.array_equal(law.simulate_level(t, v, np.ones_like(t)), law.simulate(t, v))
    scaled = law.with_values(Fc=13.0, Fs=19.5, sigma2=52.0).simulate(t, v)
    np.testing.assert_allclose(law.simulate_level(t, v, np.full_like(t, 1.3)), scaled,
                               rtol=1e-12, atol=1e-10)


def _reference(law, t, v, lev):
    """Radau on the continuous problem (v and the level interpolated linearly)."""
    p = law.params

    def vi(s):
        return np.interp(s, t, v)

    def li(s):
        return np.interp(s, t, lev)

    def rhs(s, z):
        vv = vi(s)
        return [vv - p.sigma0 * abs(vv) / (li(s) * float(law.g(vv))) * z[0]]

    sol = solve_ivp(rhs, (t[0], t[-1]), [0.0], method="Radau", t_eval=t, rtol=1e-10,
                    atol=1e-14, max_step=(t[1] - t[0]))
    z = sol.y[0]
    zd = np.array([rhs(s, [zz])[0] for s, zz in zip(t, z)])
    return p.sigma0 * z + p.sigma1 * zd + lev * p.sigma2 * v + p.b


def test_time_varying_level_matches_reference_and_converges_second_order():
    law = _law()
    tf, vf = _motion(8001)
    levf = 1.0 + 0.4 * np.sin(2 * np.pi * 3 * tf)
    Fr = _reference(law, tf, vf, levf)
    errs = []
    for n in (251, 501, 1001):
        t, v = _motion(n)
        lev = 1.0 + 0.4 * np.sin(2 * np.pi * 3 * t)
        F = law.simulate_level(t, v, lev)
        errs.append(np.sqrt(np.mean((F - np.interp(t, tf, Fr)) ** 2)))
    order = np.log2(errs[0] / errs[1]), np.log2(errs[1] / errs[2])
    assert errs[-1] < 2e-3 * np.std(Fr), errs
    assert min(order) > 1.5, (errs, order)


@pytest.mark.parametrize("bad, what", [(np.nan, "level\\[7\\] = nan"),
                                       (-0.5, "level\\[7\\] = -0.5"),
                                       (0.0, "must be finite and > 0")])
def test_bad_level_is_refused_with_the_sample(bad, what):
    t, v = _motion(50)
    lev = np.ones_like(t)
    lev[7] = bad
    with pytest.raises(ValueError, match=what):
        _law().simulate_level(t, v, lev)


def test_level_of_wrong_length_is_refused():
    t, v = _motion(50)
    with pytest.raises(ValueError, match="level has 49 samples, the motion 50"):
        _law().simulate_level(t, v, np.ones(49))


def test_speed_map_interpolates_its_knots_in_log_speed_0_below_last_above():
    knots = [0.5, -0.2, 1.0, 0.6]
    # knots at 1e-3, 1e-2.5, 1e-2, 1e-1.5, 1e-1 (top 0.1, two decades)
    speeds = np.array([1e-4, 1e-3, 10 ** -2.5, 1e-2, 10 ** -1.5, 1e-1, 1.0,
                       10 ** -2.25])
    m = speed_map(speeds, 0.1, knots, 2.0)
    np.testing.assert_allclose(m, [0.0, 0.0, 0.5, -0.2, 1.0, 0.6, 0.6, 0.15], atol=1e-12)


def test_stribeck_shape_is_the_speed_map_on_a_classic_lugre_only():
    cand = CANDIDATES["stribeck_shape"]
    spec = cand.specialise(_law())
    assert isinstance(spec, StribeckMap)
    t, v = _motion(500)
    ctx = make_context(Dataset.from_arrays(t, _law().simulate(t, v), v=v))
    # the trajectory level and the FMUs keep the family variants: no knots there
    assert spec.extras(ctx) == [] and spec.trajectory_extras(ctx) == []
    assert len(spec.force_extras(ctx)) == StribeckMap.KNOTS - 1
    modified = make_model("modified_lugre")
    assert type(cand.specialise(modified)) is StribeckShape


def _hump(v, vs):
    # a mixed-lubrication hump: the curve rises by 40 % around 4 vs (0.3 decades wide),
    # a non-monotone shape no Gaussian-alpha or Lorentzian curve has
    return 1.0 + 0.4 * np.exp(-np.log10(np.maximum(np.abs(v), 1e-12) / (4 * vs)) ** 2
                              / (2 * 0.3 ** 2))


def test_speed_map_reaches_a_stribeck_curve_the_family_cannot():
    law = _law()
    vs = law.params.vs
    # truth: the hump inside the bristle dynamics, integrated on a grid 8 x finer than
    # the data, 0.5 % noise
    tf, vf = _motion(16001)
    Ff = law.simulate_level(tf, vf, _hump(vf, vs))
    t, v = tf[::8], vf[::8]
    rng = np.random.default_rng(0)
    F = Ff[::8] + 0.005 * np.std(Ff) * rng.standard_normal(t.size)
    data = Dataset.from_arrays(t, F, v=v)
    ctx = make_context(data)
    names = ["Fc", "Fs", "vs", "sigma2"]
    _, base_nr = fit_composite(law, names, [], data, ctx)
    spec = CANDIDATES["stribeck_shape"].specialise(law)
    fam_form = StribeckShape("stribeck_shape", "")
    family = [fit_composite(lv, nv, [fam_form], data, ctx)
              for lv, nv, _ in law_variants(fam_form, law, names, ctx)]
    # both forms of the map (inside the levels, and the drag beside the contact)
    mapped = [fit_composite(lv, nv, [form], data, ctx)
              for lv, nv, form in law_variants(spec, law, names, ctx)]
    fam, fam_nr = min(family, key=lambda r: r[1])
    comp, map_nr = min(mapped, key=lambda r: r[1])
    assert fam_nr > 0.6 * base_nr, (base_nr, fam_nr)   # the family hardly bends this way
    assert map_nr < 0.4 * fam_nr, (base_nr, fam_nr, map_nr)
    # and the map carries to a motion it was not fitted on
    t2 = np.linspace(0.0, 1.0, 2001)
    v2 = 0.04 * np.sin(2 * np.pi * 3 * t2)
    held = Dataset.from_arrays(t2, law.simulate_level(t2, v2, _hump(v2, vs)), v=v2)

    def nrmse(c):
        return np.sqrt(np.mean((c.predict(held) - held.F) ** 2)) / np.std(held.F)
    assert nrmse(comp) < 0.5 * nrmse(fam), (nrmse(comp), nrmse(fam))


# -- load and drift inside the bristle dynamics ------------------------------------------------
def test_load_specialises_to_its_inside_form_on_a_classic_lugre_only():
    from diagnosis.effects_load import LoadInside
    law = _law()
    assert isinstance(CANDIDATES["load"].specialise(law), LoadInside)
    backlash = make_model("backlash_lugre")
    assert type(CANDIDATES["load"].specialise(backlash)).__name__ == "Load"


def _load_record(law, inside):
    """A record whose levels grow with a load that changes with the direction of motion (a
    press: load and direction move together), levels affine in the load (seed 004) inside
    the bristle dynamics (or on the output), integrated 8 x finer than sampled, 0.5 %
    noise."""
    tf, vf = _motion(16001)
    load = 1000.0 * (1.0 + 0.6 * np.tanh(vf / 0.01)) + 200.0 * np.sin(2 * np.pi * 0.7 * tf)
    lev = 1.0 + 0.8 * (load / load.mean() - 1.0)
    Ff = law.simulate_level(tf, vf, lev) if inside else law.simulate(tf, vf) * lev
    rng = np.random.default_rng(1)
    F = Ff[::8] + 0.005 * np.std(Ff) * rng.standard_normal(Ff[::8].size)
    return Dataset.from_arrays(tf[::8], F, v=vf[::8], load=load[::8], check_units=False)


def test_load_inside_reaches_levels_that_act_through_the_bristle():
    from diagnosis.effects_load import Load
    law = _law()
    data = _load_record(law, inside=True)
    fit, held = data.split(0.7)
    ctx = make_context(fit)
    names = ["sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs"]

    def held_nrmse(cand):
        comp, _ = fit_composite(law, names, [cand], fit, ctx)
        return np.sqrt(np.mean((comp.predict(held) - held.F) ** 2)) / np.std(held.F)
    base, _ = fit_composite(law, names, [], fit, ctx)
    before = np.sqrt(np.mean((base.predict(held) - held.F) ** 2)) / np.std(held.F)
    out = held_nrmse(Load("load", ""))
    ins = held_nrmse(CANDIDATES["load"].specialise(law))
    assert ins < 0.03 and ins < 0.5 * out, (before, out, ins)


def test_greedy_stacking_skips_an_inside_effect_on_a_law_that_cannot_carry_it():
    # a load-inside first effect, then a backlash law to stack: skipped, not an error
    from diagnosis import diagnose
    law = _law()
    data = _load_record(law, inside=True)
    rep = diagnose(data, law, candidates=["load", "backlash", "drift"])
    assert rep["verdict"]["cause"] == "load", rep.summary()
    added = [s["add"] for s in rep["greedy"]["sequence"]]
    assert added[0] == "load" and "backlash" not in added


def _two_speed_record(law, rise, n_fine=24001, step=8):
    """A record that dwells at two speeds (a slow and a fast constant-speed stroke, both
    ways) and crosses the speeds between only while accelerating - the knots there are
    pinned by few samples - with a level that rises above 40 % of the top speed (a starved
    film), inside the bristle dynamics, integrated ``step`` x finer than sampled, 1 %
    noise."""
    tf = np.linspace(0.0, 3.0, n_fine)
    ph = 2 * np.pi * tf / 1.5
    # a trapezoid-like speed profile: flat tops at 0.05 and 0.4 m/s, fast ramps between
    v_slow = 0.05 * np.tanh(8 * np.sin(ph))
    v_fast = 0.4 * np.tanh(8 * np.sin(2 * ph))
    vf = np.where(tf < 1.5, v_slow, v_fast)
    q = np.clip((np.abs(vf) - 0.16) / 0.24, 0.0, None)
    Ff = law.simulate_level(tf, vf, 1.0 + rise * q ** 2)
    rng = np.random.default_rng(3)
    F = Ff[::step] + 0.01 * np.std(Ff) * rng.standard_normal(Ff[::step].size)
    return Dataset.from_arrays(tf[::step], F, v=vf[::step])


def test_the_knots_prior_keeps_the_map_smooth_and_is_not_counted_in_the_fit_score(monkeypatch):
    law = _law()
    data = _two_speed_record(law, 0.3)
    ctx = make_context(data)
    spec = CANDIDATES["stribeck_shape"].specialise(law)
    names = ["sigma0", "sigma1", "sigma2"]

    def fitted(smooth):
        monkeypatch.setattr(StribeckMap, "SMOOTH", smooth)
        comp, nr = fit_composite(law, names, [spec], data, ctx)
        knots = np.array([0.0] + [comp.extras[n] for n in spec._names()])
        return comp, nr, knots
    default = StribeckMap.SMOOTH
    assert default > 0.0
    comp, nr, knots = fitted(default)
    free_comp, free_nr, free_knots = fitted(0.0)
    # the score is the record's own misfit, the prior's rows left out
    own = np.sqrt(np.mean((comp.predict(data) - data.F) ** 2)) / np.std(data.F)
    assert nr == pytest.approx(own, rel=1e-6)
    assert nr >= free_nr * (1 - 1e-6)   # the prior costs fit, never gains it
    # the map's second differences: far smaller with the prior
    rough = np.sum(np.diff(knots, 2) ** 2)
    free_rough = np.sum(np.diff(free_knots, 2) ** 2)
    assert rough < 0.25 * free_rough, (knots, free_knots)
