"""The ``backlash`` and ``gms`` diagnosis candidates (issue 15 item 3): their laws, starts,
truth forms and FMU route (the native law FMUs ``backlash_lugre`` and ``gms``, not the
stateless ``friction_effects`` block), and what the force-level diagnosis names on records
whose truth carries lost motion, Maxwell-slip presliding, or neither."""
from __future__ import annotations

import numpy as np
import pytest

from diagnosis import effects_backlash as eb
from diagnosis import effects_gms as eg
from diagnosis.effects import CANDIDATES, EFFECTS, make_context
from friction.gms import beside_layout
from friction import make_model
from friction.dataset import Dataset
from friction.metrics import nrmse
from diagnosis.benchmark import BASE, _motion as benchmark_motion
from diagnosis.candidates import Fallback, Fixed

BACKLASH = CANDIDATES["backlash"]
GMS = CANDIDATES["gms"]


def _motion(n, dt, seed):
    """The benchmark's multi-sine drive (both directions, ~16 reversals in 8.4 s) and the
    generator that drew it (for the noise)."""
    rng = np.random.default_rng(seed)
    t, x, v, _ = benchmark_motion(n, dt, rng)
    return t, x, v, rng


def _record(F0, t, x, v, rng, noise=0.02, name="rec"):
    F = F0 + noise * float(np.std(F0)) * rng.standard_normal(t.size)
    return Dataset.from_arrays(t, F, x=x, v=v, a=np.gradient(v, t), name=name,
                               check_units=False)


# -- candidate laws --------------------------------------------------------------------------
def test_backlash_candidate_is_the_base_behind_a_play_and_reports_the_lost_motion():
    base = make_model("lugre", **BASE, alpha=1.5, b=0.1)
    law = BACKLASH.law_for(base, 1e-3)
    assert law.name == "backlash_lugre" and law.params.gap == "hold"
    for n in ("sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs", "alpha", "b"):
        assert getattr(law.params, n) == getattr(base.params, n)
    assert BACKLASH.own_parameters(law) == {"backlash_gap": pytest.approx(2e-3),
                                            "gap_bias": 0.0, "gap_stiffness": 0.0,
                                            "gap_drag": 0.0}
    (var, names), = BACKLASH.modify_law(base, ["sigma0", "Fc"], _ctx())
    assert names == ["sigma0", "Fc", "delta", "gap_bias", "gap_stiffness", "gap_drag"]
    assert var.name == "backlash_lugre"
    # a gap of 0 is the base law bit for bit (the play operator cuts nothing)
    t, x, v, _ = _motion(3000, 1e-3, 0)
    np.testing.assert_array_equal(BACKLASH.law_for(base, 0.0).simulate(t, v),
                                  base.simulate(t, v))
    ok, why = BACKLASH.applicable(make_model("stribeck"), None, None)
    assert not ok and "stribeck" in why


def _ctx():
    t, x, v, rng = _motion(2000, 1e-3, 0)
    return make_context(_record(make_model("lugre", **BASE).simulate(t, v), t, x, v, rng))


def test_blocks_beside_the_contact_that_reach_past_half_the_stroke_are_a_spring():
    """The beside variant's blocks must slip within the record: reaching beyond
    ``SPRING_STROKE`` x the stroke before they slip, they are a spring to the record's start
    (what a position map draws). The rule reads the beside blocks alone (not the contact's
    bristle), and the other variants have no such rule."""
    ctx = _ctx()
    stroke = ctx.x_hi - ctx.x_lo
    vals = dict(sigma0=BASE["sigma0"], spread=10.0, tilt=1.0, Fs=BASE["Fs"], share=0.3)
    k, w = np.empty(4), np.empty(4)
    beside_layout(vals["sigma0"], 10.0, 1.0, 0.3, 1.0, k, w)
    per_unit = vals["Fs"] * w[3] / k[3]        # the softest block's reach at sigma_b = 1 N/m
    spring = dict(vals, sigma_b=per_unit / (0.6 * stroke))   # reach 0.6 x the stroke
    why = GMS.practical(spring, ctx)
    assert "spring" in why and "stroke" in why
    assert GMS.practical(dict(vals, sigma_b=per_unit / (0.4 * stroke)), ctx) == ""
    slip = {n: spring[n] for n in ("sigma0", "spread", "tilt", "Fs")}
    assert GMS.practical(slip, ctx) == ""


def test_the_blocks_reach_is_read_at_the_sliding_level_not_a_static_peak():
    """The blocks beside the contact slip while it slides, at their share of the sliding
    level ``Fc``: a static level far above it (the damping rig's fitted ``Fs`` runs to its
    box, 290-580 N against ``Fc`` 5 N) holds only at rest and does not make them a spring.
    Beyond half the stroke at ``Fc`` they still are one."""
    ctx = _ctx()
    stroke = ctx.x_hi - ctx.x_lo
    Fc = 1.0
    vals = dict(sigma0=BASE["sigma0"], spread=10.0, tilt=1.0, Fc=Fc, Fs=20.0 * Fc, share=0.3)
    k, w = np.empty(4), np.empty(4)
    beside_layout(vals["sigma0"], 10.0, 1.0, 0.3, 1.0, k, w)
    per_unit = Fc * w[3] / k[3]          # the softest block's reach at Fc, sigma_b = 1 N/m
    # reach 0.2 x the stroke at Fc, 4 x at Fs: blocks that slip within the record
    assert GMS.practical(dict(vals, sigma_b=per_unit / (0.2 * stroke)), ctx) == ""
    # reach 0.6 x the stroke at Fc: a spring
    assert "spring" in GMS.practical(dict(vals, sigma_b=per_unit / (0.6 * stroke)), ctx)
    # the short-presliding floor still reads the static level: slip-blocks reaching 4 x
    # the floor at Fs (0.2 x at Fc) are not refused, nor at 0.8 x the floor at Fs
    from diagnosis.effects_backlash import reversal_travel_floor
    from friction.gms import element_shares, element_stiffness
    floor = reversal_travel_floor(ctx, GMS.MIN_SAMPLES)
    element_stiffness(1.0, 10.0, k)
    element_shares(1.0, w)
    reach = vals["Fs"] * float(np.max(w / k))           # at sigma0 = 1 N/m
    slip = {n: vals[n] for n in ("spread", "tilt", "Fs", "Fc")}
    assert GMS.practical(dict(slip, sigma0=reach / (4.0 * floor)), ctx) == ""
    assert "crossed within" in GMS.practical(dict(slip, sigma0=reach / (0.8 * floor)), ctx)


def test_the_best_fitting_variant_of_practical_size_is_kept():
    """Of a candidate's law variants, the best fit whose fitted size is practical is kept
    (``best_variant``), not a better one its practical rule refuses; where every variant is
    refused, the best fit (whose refusal the verdict then reads). A variant that asks for a
    gain (gms's beside blocks) is kept only where it fits below that share of the best
    other variant's NRMSE."""
    from diagnosis.candidates import best_variant

    class Form:
        def __init__(self, why, gain):
            self.why, self.gain = why, gain

        def practical(self, p, ctx):
            return self.why if p["tag"] else ""

        def variant_gain(self, law):
            return self.gain

    class Fit:
        def __init__(self, tag, why="", gain=1.0):
            self.effects = [Form(why, gain)]
            self.extras = {}
            self.tag = tag
            self.law = None

        def describe(self):
            return {"params": {"tag": self.tag}}

    refused, kept = Fit(1, "too small"), Fit(0)
    assert best_variant([(refused, 0.01), (kept, 0.02)], None)[0] is kept
    assert best_variant([(kept, 0.03), (refused, 0.01)], None) == (kept, 0.03)
    other = Fit(1, "too small")
    assert best_variant([(other, 0.05), (refused, 0.01)], None)[0] is refused
    assert best_variant([], None) is None
    # a flexible variant (gain 0.85) competes only below 0.85 x the best plain one's misfit
    flexible = Fit(0, gain=0.85)
    assert best_variant([(flexible, 0.018), (kept, 0.02)], None)[0] is kept
    assert best_variant([(flexible, 0.016), (kept, 0.02)], None)[0] is flexible


def test_backlash_practical_size_is_a_play_crossed_within_a_sample_and_a_half():
    ctx = _ctx()
    floor = 0.5 * ctx.sa * (1.5 * ctx.dt) ** 2        # travel 1.5 samples after a reversal
    assert eb.reversal_travel_floor(ctx, 1.5) == pytest.approx(floor)
    assert "samples of a reversal" in BACKLASH.practical({"delta": 0.4 * floor}, ctx)
    assert BACKLASH.practical({"backlash_gap": 1.1 * floor}, ctx) == ""
    assert BACKLASH.practical({"sigma0": 1.0}, ctx) == ""


def test_gms_candidate_shares_the_base_curve_and_stiffness():
    base = make_model("lugre", **BASE, alpha=1.5, b=0.1)
    law = GMS.law_for(base, spread=20.0, C=3e3)
    assert law.name == "gms"
    for n in ("sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs", "alpha", "b"):
        assert getattr(law.params, n) == getattr(base.params, n)
    k = law.element_stiffness()
    assert k.sum() == pytest.approx(BASE["sigma0"]) and k[0] / k[-1] == pytest.approx(20.0)
    names = GMS.names_for(["sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs",
                                        "alpha", "b"])
    # the base's bristle damping is the blocks' micro-damping
    assert names == ["sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs", "alpha", "b", "spread",
                     "C", "tilt"]
    par = GMS.own_parameters(law)
    assert par["spread"] == 20.0 and par["C"] == 3e3
    # equal break-away shares unless the fit tilts them
    assert par["tilt"] == 1.0 and [par[f"w{i}"] for i in range(1, 5)] == [0.25] * 4
    assert par["presliding"] == pytest.approx(BASE["Fs"] / 4 / k[-1])
    # the steady state is the base's Stribeck curve
    vv = np.array([-0.05, -1e-3, 2e-3, 0.04])
    np.testing.assert_allclose(law.steady_state(vv), base.steady_state(vv), rtol=1e-12)
    twin = base.with_values(Fc_neg=1.5)
    ok, why = GMS.applicable(twin, None, None)
    assert not ok and "Fc_neg" in why


def test_gms_bristle_variant_nests_the_base_and_reaches_a_tail_beside_a_damped_bristle():
    """The candidate's second law variant, four LuGre bristles (``element`` "bristle"): the
    base itself at spread and tilt 1, without the unused attraction rate; its third, the
    base's bristle with three slip-blocks beside it (``element`` "beside"), finds the
    tail's share and stiffness and fits at under half the bristles' misfit. Beside a damped
    bristle (the base's sigma1 150 N s/m) a soft elasto-plastic tail carrying a fifth of
    the level (integrated 10 x finer than sampled, 1 % noise): slip-blocks in place of the
    bristle fit the record at half the base's NRMSE, the bristles at under a third of it
    and 0.7 of the slip-blocks' (0.091, 0.047, 0.028 when written), and the softest of
    them carries the tail (a small share on a far softer element)."""
    from diagnosis.candidates import law_variants
    from diagnosis.composite import fit_composite
    from diagnosis.core import fit_base
    base = make_model("lugre", **BASE)
    (slip, n_slip), (bristle, n_bristle), (beside, n_beside) = GMS.modify_law(
        base, list(BASE), _ctx())
    assert (slip.params.element, bristle.params.element) == ("slip", "bristle")
    assert beside.params.element == "beside" and n_beside == n_bristle + ["share", "sigma_b"]
    assert n_slip == n_bristle[:-1] + ["C", "tilt"] and "C" not in n_bristle
    assert "C" not in GMS.own_parameters(bristle) and "C" in GMS.own_parameters(slip)
    t, x, v, _ = _motion(3000, 1e-3, 4)
    ref = base.simulate(t, v)
    # (the steps across a reversal differ: cut there, LuGre's midpoint speed in the base)
    np.testing.assert_allclose(bristle.with_values(spread=1.0).simulate(t, v), ref, rtol=0,
                               atol=1e-3 * np.ptp(ref))
    rng = np.random.default_rng(3)
    n, dt, fine = 4000, 2e-3, 10
    tf, xf, vf, _ = benchmark_motion(n * fine, dt / fine, rng)
    tail = make_model("gms", sigma0=300.0, spread=1.0, C=1e6, Fc=0.2 * BASE["Fc"],
                      Fs=0.2 * BASE["Fs"], vs=BASE["vs"], sigma2=0.0)
    F0 = (0.8 * base.simulate(tf, vf) + tail.simulate(tf, vf))[::fine]
    rec = _record(F0, tf[::fine], xf[::fine], vf[::fine], rng, noise=0.01)
    ctx = make_context(rec)
    fitted, names, base_cost = fit_base(rec, make_model("lugre", **BASE), ctx)
    costs = {}
    for law_v, names_v, form in law_variants(GMS.specialise(fitted.law), fitted.law, names, ctx):
        comp, cost = fit_composite(law_v, names_v, [form], rec, ctx)
        costs[law_v.params.element] = cost
        if law_v.params.element == "beside":
            # the tail is what the blocks beside the bristle carry: its share of the level
            # and its stiffness (the truth's 0.2 and 300 N/m; 0.225 and 303 N/m when
            # written)
            own = comp.describe()["parameters"]
            assert 0.15 < own["share"] < 0.3
            assert 150.0 < own["k4"] < 600.0 and own["w4"] > 0.5 * own["share"]
        if law_v.params.element == "bristle":
            w, k = comp.law.element_shares(), comp.law.element_stiffness()
            assert w[-1] < 0.25 and k[-1] < k[0] / 100
    assert costs["slip"] < 0.6 * base_cost
    assert costs["bristle"] < 0.35 * base_cost and costs["bristle"] < 0.7 * costs["slip"]
    # the third variant, the base's bristle and slip-blocks beside it: under half the
    # bristles' misfit (0.010 against 0.028 when written)
    assert costs["beside"] < 0.5 * costs["bristle"]


# -- starts on the data ----------------------------------------------------------------------
@pytest.mark.parametrize("form", eb.TRUTHS)
def test_reversal_travels_measure_the_lost_motion_without_a_model(form):
    t, x, v, rng = _motion(12000, 1e-3, 0)
    data = _record(eb.backlash_truth(form, t, v, 2e-3, BASE), t, x, v, rng)
    tr = eb.reversal_travels(data, make_context(data))
    assert tr.size >= 10
    # the play plus the contact's presliding travel (~0.1 mm)
    assert 2e-3 <= np.median(tr) < 2.25e-3
    clean = _record(make_model("lugre", **BASE).simulate(t, v), t, x, v, rng)
    assert np.median(eb.reversal_travels(clean, make_context(clean))) < 2e-4


def test_reversal_travels_refuse_a_share_outside_0_1():
    t, x, v, rng = _motion(2000, 1e-3, 0)
    data = _record(make_model("lugre", **BASE).simulate(t, v), t, x, v, rng)
    with pytest.raises(ValueError, match="share = 1.0 is out of bounds"):
        eb.reversal_travels(data, make_context(data), 1.0)


@pytest.mark.parametrize("form", ["maxwell10", "dahl"])
def test_gms_start_reaches_a_long_presliding_tail_of_a_stiff_contact(form, monkeypatch):
    """A stiff contact (sigma0 2e6 N/m: one bristle deflects 1.4 um) whose presliding runs
    over 0.2 mm: the second start sets the presliding distance from the record's travel to
    90 % of the force swing after its reversals; the first (the stiffness scaled around the
    base's) stays below a quarter of the truth's and fits the record far worse."""
    t, x, v, rng = _motion(8000, 1e-3, 3)
    stiff = dict(BASE, sigma0=2e6)
    data = _record(eg.gms_truth(form, t, v, stiff, 2e-4), t, x, v, rng, noise=0.01)
    ctx = make_context(data)
    law = GMS.law_for(make_model("lugre", **stiff))
    names = GMS.names_for(["sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs", "b"])

    def run(vals):
        trial = law.with_values(**vals)
        F = trial.simulate(t, v, state0=trial.record_start_state(t, v, F=data.F))
        return float(np.sum((data.F - F) ** 2)), trial.presliding_distance()

    grid, tail = eg.gms_start(law, names, data, ctx)
    sse, pre = run(tail)
    assert 1e-4 <= pre <= 4e-4
    sse_grid, pre_grid = run(grid)
    assert pre_grid < 5e-5 and sse < 0.2 * sse_grid
    # without reversals to measure, the first grid's start alone
    monkeypatch.setattr(eb, "reversal_travels", lambda *a, **k: np.zeros(0))
    assert eg.gms_start(law, names, data, ctx) == [grid]


def test_joint_fit_runs_from_each_law_start_and_keeps_the_best():
    """A law candidate whose start gives two starts (a play of a fifth of the truth's, and
    the truth's): the joint fit is the better of the fits from each alone."""
    from diagnosis.composite import fit_composite
    t, x, v, rng = _motion(6000, 1e-3, 2)
    data = _record(eb.backlash_truth("rigid", t, v, 2e-3, BASE), t, x, v, rng)
    ctx = make_context(data)
    (law, names), = BACKLASH.modify_law(make_model("lugre", **BASE), ["Fc", "sigma0"], ctx)
    off = {n: Fixed(0.0) for n in eb.ACROSS}

    def fitted(*deltas):
        class Starts(type(BACKLASH)):
            def start_values(self, law, names, fit, ctx):
                return [{"delta": d, **off} for d in deltas]
        cand = Starts(BACKLASH.name, BACKLASH.description, BACKLASH.stage, BACKLASH.tags)
        comp, nr = fit_composite(law, names, [cand], data, ctx, max_nfev=8)
        return nr, 2.0 * comp.law.params.delta

    short, right = fitted(2e-4), fitted(1e-3)
    assert right[0] < 0.5 * short[0]
    assert fitted(2e-4, 1e-3) == right and fitted(1e-3, 2e-4) == right


def test_every_law_start_lies_inside_the_joint_fits_box():
    """A second start far below the first's box (a play of 1 nm beside one of 1 mm, on a
    record without play): the box is widened to it, not the start clipped, so the joint
    fit from both is the fit from the tiny play alone."""
    from diagnosis.composite import fit_composite, law_space
    t, x, v, rng = _motion(4000, 1e-3, 4)
    data = _record(make_model("lugre", **BASE).simulate(t, v), t, x, v, rng)
    ctx = make_context(data)
    (law, names), = BACKLASH.modify_law(make_model("lugre", **BASE), ["Fc", "sigma0"], ctx)
    off = {n: Fixed(0.0) for n in eb.ACROSS}
    box = law_space(law.with_values(delta=1e-3), ["Fc", "sigma0", "delta"], data)
    assert box.lower[2] > 1e-8              # the first start's box alone would clip 1 nm

    def fitted(*deltas):
        class Starts(type(BACKLASH)):
            def start_values(self, law, names, fit, ctx):
                return [{"delta": d, **off} for d in deltas]
        cand = Starts(BACKLASH.name, BACKLASH.description, BACKLASH.stage, BACKLASH.tags)
        comp, nr = fit_composite(law, names, [cand], data, ctx, max_nfev=8)
        return nr, comp.law.params.delta

    tiny = fitted(1e-9)
    assert tiny[1] < 1e-8 and tiny[0] < fitted(1e-3)[0]
    assert fitted(1e-3, 1e-9) == tiny


def test_a_fallback_law_start_runs_only_where_it_starts_below_the_best_fit(monkeypatch):
    """The base-like fallback start (a play of 1 nm) after a start at the true play of a
    rigid-play record is skipped (one least squares); after a 1 mm play on a record
    without play it is run and kept."""
    import diagnosis.composite as comp_mod
    from diagnosis.composite import fit_composite
    runs = []
    real = comp_mod.least_squares
    monkeypatch.setattr(comp_mod, "least_squares",
                        lambda *a, **k: runs.append(1) or real(*a, **k))
    t, x, v, rng = _motion(4000, 1e-3, 4)
    off = {n: Fixed(0.0) for n in eb.ACROSS}

    def fitted(data, first, fallback):
        ctx = make_context(data)
        (law, names), = BACKLASH.modify_law(make_model("lugre", **BASE), ["Fc", "sigma0"],
                                            ctx)

        class Starts(type(BACKLASH)):
            def start_values(self, law, names, fit, ctx):
                return [{"delta": first, **off}, Fallback(delta=fallback, **off)]
        cand = Starts(BACKLASH.name, BACKLASH.description, BACKLASH.stage, BACKLASH.tags)
        runs.clear()
        comp, _ = fit_composite(law, names, [cand], data, ctx, max_nfev=8)
        return len(runs), comp.law.params.delta

    rigid = _record(eb.backlash_truth("rigid", t, v, 2e-3, BASE), t, x, v, rng)
    n, delta = fitted(rigid, 1e-3, 1e-9)
    assert n == 1 and delta > 5e-4
    clean = _record(make_model("lugre", **BASE).simulate(t, v), t, x, v, rng)
    n, delta = fitted(clean, 1e-3, 1e-9)
    assert n == 2 and delta < 1e-8


def test_law_starts_that_pin_different_parameters_are_refused():
    from diagnosis.composite import fit_composite
    t, x, v, rng = _motion(2000, 1e-3, 0)
    data = _record(make_model("lugre", **BASE).simulate(t, v), t, x, v, rng)
    ctx = make_context(data)
    (law, names), = BACKLASH.modify_law(make_model("lugre", **BASE), ["Fc"], ctx)

    class TwoStarts(type(BACKLASH)):
        def start_values(self, law, names, fit, ctx):
            return [{"delta": 1e-4}, {"delta": 2e-4, "gap_bias": Fixed(0.0)}]
    two = TwoStarts(BACKLASH.name, BACKLASH.description, BACKLASH.stage, BACKLASH.tags)
    with pytest.raises(ValueError, match="law starts pin different parameters"):
        fit_composite(law, names, [two], data, ctx, max_nfev=2)


def test_contact_record_takes_the_play_out():
    t, x, v, rng = _motion(4000, 1e-3, 1)
    data = _record(np.zeros(t.size) + 1.0, t, x, v, rng)
    rec = eb.contact_record(data, 1e-3)
    assert np.all(np.abs(rec.x - data.x) <= 1e-3 + 1e-15)
    crossing = rec.v == 0.0
    assert 0.05 < crossing.mean() < 0.5            # the drive crosses the play after turns
    assert np.array_equal(rec.v[~crossing], data.v[~crossing])


# -- truth forms -----------------------------------------------------------------------------
def test_backlash_truths_lag_by_the_gap_and_differ_from_the_candidate():
    t, x, v, _ = _motion(6000, 1e-3, 0)
    lugre = make_model("lugre", **BASE).simulate(t, v)
    hold = make_model("backlash_lugre", delta=1e-3, **BASE).simulate(t, v)
    # a mass pushed through a coupling has no force jump sigma1 v at the engagement
    free = make_model("backlash_lugre", delta=1e-3, gap="free",
                      **dict(BASE, sigma1=0.0)).simulate(t, v)
    for form in eb.TRUTHS:
        F = eb.backlash_truth(form, t, v, 2e-3, BASE)
        assert np.all(np.isfinite(F))
        # far from the base law, nearer to the candidate of its kind, yet not its copy
        near = nrmse(F, hold if form == "rigid" else free)
        assert near < 0.5 * nrmse(F, lugre), form
        assert near > 1e-3, form
    with pytest.raises(ValueError, match="unknown backlash truth"):
        eb.backlash_truth("elastic", t, v, 1e-3, BASE)


@pytest.mark.parametrize("form", eg.TRUTHS)
def test_presliding_truths_settle_on_the_curve_and_have_hysteresis(form):
    dt = 1e-3
    t = np.arange(4000) * dt
    v = np.where(t < 2.0, 0.02, -0.02) * np.minimum(1.0, t / 0.2)
    F = eg.gms_truth(form, t, v, BASE, 1e-3)
    g = BASE["Fc"] + (BASE["Fs"] - BASE["Fc"]) * np.exp(-(0.02 / BASE["vs"]) ** 2)
    ss = g + BASE["sigma2"] * 0.02
    assert F[1900] == pytest.approx(ss, rel=0.02)         # sliding: the Stribeck curve
    assert F[-1] == pytest.approx(-ss, rel=0.02)
    # presliding: after the reversal the force takes more than one sample of travel (20 um)
    # to swing across, and less than twice the presliding distance of 1 mm (100 samples)
    k = np.flatnonzero(F[2000:] < 0.0)[0]
    assert 1 < k < 120, k


# -- the FMU route: the candidates' laws in their law FMUs ------------------------------------
_PYTHONFMU = []


def _pythonfmu_dir():
    """The pythonfmu FMUs of both candidate laws, built once per test process."""
    from fmus.testing import built_fmus
    if not _PYTHONFMU:
        _PYTHONFMU.append(built_fmus(("backlash_lugre", "gms")))
    return _PYTHONFMU[0]


# the pythonfmu build of both laws costs 15-30 s: slow
@pytest.mark.parametrize("kind", ["native", pytest.param("pythonfmu", marks=pytest.mark.slow)])
@pytest.mark.parametrize("which", ["backlash", "gms", "gms_bristle", "gms_beside"])
def test_candidate_law_runs_in_its_law_fmu_to_1e_10(which, kind):
    """The friction_effects block is a stateless map of the law's output; these candidates
    change the law's state, so they run in the law FMUs (C and pythonfmu). With the inputs
    set at the end of each step (first-order hold, ``inputs_at_step_end``) the FMU's steps
    are the kernel's."""
    from fmus.master import fmu_values, law_parameters
    from fmus.native.build import SUFFIX
    from fmus.testing import LoggedSlave, built_native_fmus
    base = make_model("lugre", **BASE, alpha=1.7, b=0.05)
    # backlash with forces across the play (a bias, a spring, a drag): the FMU carries them
    law = (BACKLASH.law_for(base, 4e-4).with_values(gap="free", gap_bias=0.05,
                                                    gap_stiffness=2e3, gap_drag=0.2)
           if which == "backlash" else GMS.law_for(base, spread=30.0, C=4e3))
    if which == "gms_bristle":  # the candidate's second variant, four LuGre bristles
        law = law.with_values(element="bristle", tilt=0.3)
    if which == "gms_beside":  # its third, the base's bristle and blocks beside it
        law = law.with_values(element="beside", tilt=0.3, share=0.3, sigma_b=400.0)
    path = (built_native_fmus((law.name,)) / f"{law.name}{SUFFIX}.fmu" if kind == "native"
            else _pythonfmu_dir() / f"{law.name}.fmu")
    t, x, v, _ = _motion(3000, 1e-3, 2)
    ref = law.simulate(t, v)
    s = LoggedSlave(path)
    try:
        vals = fmu_values({n: s.md.modelVariables[i] for i, n in
                           enumerate(v_.name for v_ in s.md.modelVariables)},
                          law_parameters(law))
        assert s.set("v", float(v[0])) == 0
        s.init(**vals, inputs_at_step_end=True)
        F = np.empty(t.size)
        F[0] = s.get("F")
        for k in range(t.size - 1):
            assert s.set("v", float(v[k + 1])) == 0
            assert s.step(t[k], t[k + 1] - t[k]) == 0
            F[k + 1] = s.get("F")
        assert not s.errors()
        # a parameter outside its bounds answers fmi2Error naming it
        for bad in (("delta", "gap_stiffness", "gap_drag") if which == "backlash"
                    else ("spread", "share", "sigma_b") if which == "gms_beside"
                    else ("spread",)):
            assert s.set(bad, -1.0) >= 3
            assert any(bad in m for m in s.errors())
    finally:
        s.close()
    assert np.max(np.abs(F - ref)) <= 1e-10 * np.max(np.abs(ref))


def test_joint_fit_starts_the_gap_on_the_data_and_finds_it():
    """fit_composite runs the candidate's start_law (a base fitted without the play absorbs
    it: a soft bristle; from its values no gap improves the fit) and recovers 2 mm of lost
    motion within 5 %; a warm start (extras0 given) keeps the law's values."""
    from diagnosis.composite import fit_composite
    from diagnosis.core import fit_base
    t, x, v, rng = _motion(6000, 1e-3, 3)
    data = _record(eb.backlash_truth("rigid", t, v, 2e-3, BASE), t, x, v, rng)
    ctx = make_context(data)
    base, names, base_nrmse = fit_base(data, "lugre", ctx)
    (law, nm), = BACKLASH.modify_law(base.law, names, ctx)
    comp, nr = fit_composite(law, nm, [BACKLASH], data, ctx)
    assert BACKLASH.own_parameters(comp.law)["backlash_gap"] == pytest.approx(2e-3, rel=0.05)
    assert nr < 0.6 * base_nrmse
    warm, _ = fit_composite(law, nm, [BACKLASH], data, ctx, extras0={}, max_nfev=1)
    assert warm.law.params.delta == pytest.approx(law.params.delta, rel=1e-3)


def test_gms_practical_size_is_a_presliding_distance_crossed_within_a_sample_and_a_half():
    ctx = _ctx()
    floor = eb.reversal_travel_floor(ctx, 1.5)
    law = GMS.law_for(make_model("lugre", **BASE), spread=10.0)
    p = {"sigma0": BASE["sigma0"], "spread": 10.0, "Fs": BASE["Fs"]}
    assert law.presliding_distance() > 5 * floor and GMS.practical(p, ctx) == ""
    # spread 10: the softest block carries Fs / 4 at 4.45 Fs / sigma0
    stiff = dict(p, sigma0=4.45 * BASE["Fs"] / (0.6 * floor))
    assert "samples of a reversal" in GMS.practical(stiff, ctx)
    soft = dict(p, sigma0=4.45 * BASE["Fs"] / (1.4 * floor))
    assert GMS.practical(soft, ctx) == ""
    assert GMS.practical({"spread": 3.0}, ctx) == ""


# -- what the force-level diagnosis names -----------------------------------------------------
def _diagnose(F0, t, x, v, rng, candidates):
    from diagnosis import diagnose
    return diagnose(_record(F0, t, x, v, rng), "lugre", candidates=candidates)


def test_lost_motion_of_2_mm_is_named_backlash_with_its_gap():
    # issue 15: a device whose force lags by a constant displacement at every reversal
    t, x, v, rng = _motion(8000, 1e-3, 5)
    rep = _diagnose(eb.backlash_truth("rigid", t, v, 2e-3, BASE), t, x, v, rng,
                    ["backlash", "gms", "delay"])
    assert rep["verdict"]["cause"] == "backlash", rep.summary()
    gap = 2.0 * rep["effect_details"]["backlash"]["params"]["delta"]
    assert gap == pytest.approx(2e-3, rel=0.2)
    assert rep["effect_details"]["backlash"]["parameters"]["backlash_gap"] == gap


def test_maxwell_slip_presliding_is_named_gms():
    t, x, v, rng = _motion(12000, 1e-3, 0)
    rep = _diagnose(eg.gms_truth("maxwell10", t, v, BASE, 1e-3), t, x, v, rng,
                    ["gms", "backlash", "acceleration"])
    assert rep["verdict"]["cause"] == "gms", rep.summary()
    par = rep["effect_details"]["gms"]["parameters"]
    # either variant may fit it best: slip-blocks (with their attraction rate C) or the
    # four bristles (no C); both spread their stiffness over a presliding of their own
    assert par["spread"] > 2.0 and par["presliding"] > 0 and par.get("C", 1.0) > 0


def test_a_clean_record_names_neither():
    t, x, v, rng = _motion(8000, 1e-3, 6)
    rep = _diagnose(make_model("lugre", **BASE).simulate(t, v), t, x, v, rng,
                    ["backlash", "gms"])
    assert rep["verdict"]["cause"] not in ("backlash", "gms"), rep.summary()


@pytest.mark.slow
@pytest.mark.parametrize("gap", [1e-3, 3e-3])
def test_backlash_among_every_candidate(gap):
    from diagnosis.effects import EFFECT_NAMES
    t, x, v, rng = _motion(12000, 1e-3, 0)
    rep = _diagnose(eb.backlash_truth("rigid", t, v, gap, BASE), t, x, v, rng,
                    list(EFFECT_NAMES))
    assert rep["verdict"]["cause"] == "backlash", rep.summary()
    assert 2.0 * rep["effect_details"]["backlash"]["params"]["delta"] == pytest.approx(
        gap, rel=0.2)


@pytest.mark.slow
def test_clean_record_among_every_candidate_names_neither():
    from diagnosis.effects import EFFECT_NAMES
    t, x, v, rng = _motion(12000, 1e-3, 0)
    rep = _diagnose(make_model("lugre", **BASE).simulate(t, v), t, x, v, rng,
                    list(EFFECT_NAMES))
    assert rep["verdict"]["cause"] == "none", rep.summary()


def test_the_records_list_parameters_truths_localisation_and_fmu():
    from diagnosis.effects import FMU_EFFECTS
    from fmus.native.build import native_catalogue
    from diagnosis.benchmark import CASES
    ctx = _ctx()
    for name, law, own in (("backlash", "backlash_lugre", {"delta": "m", "gap_bias": "N",
                                                          "gap_stiffness": "N/m",
                                                          "gap_drag": "N"}),
                           ("gms", "gms", {"spread": "1", "C": "N/s", "tilt": "1", "share": "1",
                                            "sigma_b": "N/m"})):
        e = EFFECTS[name]
        assert e.plant_entry == "law" and e.fmu and name in FMU_EFFECTS
        assert law in native_catalogue()          # the FMU that carries it
        assert {p.name: p.unit for p in e.parameters(ctx)} == own
        assert len(e.truths) >= 3 and "pre-sliding" in e.families and name in CASES
        t, x, v, _ = _motion(3000, 1e-3, 0)
        F, load = resolve_generic(e)(1.0, t, x, v, np.gradient(v, t))
        assert load is None and np.all(np.isfinite(F))


def resolve_generic(e):
    from diagnosis.effects import resolve
    return resolve(e.generic_truth)


def test_the_start_keeps_what_bridges_the_play_only_where_the_data_ask():
    """The forces across the play (bias, anti-backlash spring, drag) are solved by least
    squares for each trial gap: on a rigid play (no force across it) the start pins all
    three at 0, out of the joint fit; on a play bridged by a spring and a drag, read at the
    motor, it keeps them near their values and picks ``free``."""
    from diagnosis.candidates import Fixed
    t, x, v, rng = _motion(6000, 1e-3, 3)
    base = make_model("lugre", **BASE)
    (law, names), = BACKLASH.modify_law(base, ["Fc", "Fs", "sigma2"], _ctx())
    rigid = _record(eb.backlash_truth("rigid", t, v, 2e-3, BASE), t, x, v, rng)
    p, null = eb.gap_start(law, names, rigid, make_context(rigid))
    assert all(isinstance(p[n], Fixed) and p[n] == 0.0 for n in eb.ACROSS)
    assert p["delta"] == pytest.approx(1e-3, rel=0.25)
    # the second start: the base behind a play of a thousandth of its bristle's deflection
    assert null["delta"] == pytest.approx(1e-3 * BASE["Fs"] / BASE["sigma0"])
    assert {n: null[n] for n in ("Fc", "Fs", "sigma2")} == {
        n: getattr(law.params, n) for n in ("Fc", "Fs", "sigma2")}
    assert all(null[n] is p[n] for n in eb.ACROSS) and null["gap"] == p["gap"]
    assert isinstance(null, Fallback)
    first, second = BACKLASH.start_law(law, names, rigid, make_context(rigid))
    assert set(first[1]) == set(eb.ACROSS) and len(first) == 2
    # the base-like start is a fallback, run only where it starts below the first's fit
    assert set(second[1]) == set(eb.ACROSS) and second[2] is True
    truth = BACKLASH.law_for(base, 1e-3).with_values(gap="free", gap_stiffness=400.0,
                                                    gap_drag=0.3)
    bridged = _record(truth.simulate(t, v), t, x, v, rng, noise=0.01)
    p, null = eb.gap_start(law, names, bridged, make_context(bridged))
    assert p["gap"] == "free" and p["delta"] == pytest.approx(1e-3, rel=0.25)
    assert all(null[n] == 0.0 and not isinstance(null[n], Fixed) for n in eb.ACROSS)
    assert not isinstance(p["gap_drag"], Fixed)
    assert p["gap_drag"] == pytest.approx(0.3, rel=0.3)
    assert p["gap_stiffness"] == pytest.approx(400.0, rel=0.3)


def test_forces_across_the_play_beyond_the_break_away_are_no_play():
    """A fit whose forces across the play exceed the contact's break-away draws a
    presliding spring in a tiny gap (a harmonic drive's compliance on the XML-350: a gap of
    2.5 um, a spring of 7.5e5 N/m, 1.6 N across against Fc 0.95 N): not named; within the
    break-away it is."""
    ctx = _ctx()
    ok = {"delta": 2e-3, "Fc": 2.0, "Fs": 2.8, "gap_bias": 0.2, "gap_stiffness": 300.0,
          "gap_drag": 0.5}
    assert eb.across_force(ok) == pytest.approx(0.2 + 0.6 + 0.5)
    assert BACKLASH.practical(ok, ctx) == ""
    stiff = dict(ok, gap_stiffness=2000.0)          # 4 N across a 2.8 N break-away
    why = BACKLASH.practical(stiff, ctx)
    assert "break-away" in why and "4.7 N" in why
    law = BACKLASH.law_for(make_model("lugre", **BASE), 2e-3).with_values(gap_stiffness=2e3)
    assert eb.across_force(law.params) == pytest.approx(4.0)


def test_a_spring_across_the_play_stiffer_than_the_bristles_is_no_play():
    """A spring across the play pushes the standing contact, whose bristle deflects by
    gap_stiffness p / sigma0: stiffer than the bristles, the contact follows the drive and
    nothing is lost (a clean damping-rig record, LuGre truth sampled as each interval's mean,
    drew a free play of 6 counts with 28 x sigma0 across it). Not named; the start's least
    squares keeps the spring within sigma0."""
    ctx = _ctx()
    ok = {"delta": 2e-3, "Fc": 2.0, "Fs": 2.8, "gap_stiffness": 300.0, "sigma0": 1e4}
    assert BACKLASH.practical(ok, ctx) == ""
    # within the break-away (0.6 N across 2.8 N) but 1.5 x the bristles' stiffness
    stiff = dict(ok, delta=2e-5, gap_stiffness=1.5e4)
    assert eb.across_force(stiff) < eb._break_away(stiff)
    why = BACKLASH.practical(stiff, ctx)
    assert "stiffer than the contact's bristles" in why and "1e+04 N/m" in why
    assert BACKLASH.practical(dict(stiff, gap_stiffness=0.9e4), ctx) == ""
    # the start's fit of the forces across the play: a residual that ramps across the play
    # at 5e4 N/m is met at the cap (sigma0) when one is given, in full without it
    t = np.linspace(0.0, 1.0, 401)
    fit = Dataset.from_arrays(t, np.zeros_like(t), x=np.sin(2 * np.pi * t),
                              v=np.cos(2 * np.pi * t))
    delta = 1e-3
    p = 0.9 * delta * np.sin(6 * np.pi * t)  # inside the flanks: the forces act in full
    r = 5e4 * p
    _, free = eb._across_fit(fit, p, delta, r, ["gap_stiffness"], 1e3)
    _, capped = eb._across_fit(fit, p, delta, r, ["gap_stiffness"], 1e3, 1e4)
    assert free[0] == pytest.approx(5e4, rel=1e-6)
    assert capped[0] == pytest.approx(1e4, rel=1e-6)


def test_grease_presliding_beside_a_stiff_contact_is_named_gms_not_delay():
    """Seen family 22's grease layer yielding beside the XML-350's stiff contact (strength
    0.5, 1 % noise, positions quantised and differentiated): on ee79bf5, before the beside
    variant, ``delay`` (0.60 of the excess closed; ``gms`` 0.26); now ``gms``, closing the
    whole excess (1.03 when written), ``delay`` far behind."""
    from diagnosis import diagnose
    from diagnosis.benchmark.cases import make_plant_case
    from diagnosis.benchmark.runner import MEASURED
    case = make_plant_case("xml350", "gms", 0.5, 0.01, seed=60850, quick=True,
                           form="grease_yield", measured=MEASURED[3])
    rep = diagnose(case.data, case.base, seed=0)
    assert rep["verdict"]["cause"] == "gms"
    closed = {e["name"]: e["excess_closed"] for e in rep["effects"]}
    assert closed["gms"] > 0.8 and closed["gms"] > closed["delay"] + 0.2
