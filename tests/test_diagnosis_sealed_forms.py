"""The thirty-seventh sealed truth family (diagnosis.benchmark.sealed, written in session 41
by another hand, sealed: not run): each form builds a finite case of the requested size on every
plant it applies to, is the base law at s = 0, grows with its amplitude factor and refuses
the plants it does not apply to. No diagnosis is run on these forms: the family stays unseen
until the end of a piece of work. Each effect record of :data:`diagnosis.effects.EFFECTS`
names it as its ``sealed`` form (the thirty-sixth family, sealed before it, is
:mod:`diagnosis.benchmark.seen36` since its run)."""
import dataclasses
import importlib

import numpy as np
import pytest

from diagnosis.benchmark import EFFECT_SIZE, PLANT_NAMES, make_plant_case, plant_kinematics
from diagnosis.benchmark import sealed as family
from diagnosis.benchmark.kinematics import fine_kinematics
from diagnosis.benchmark.runner import MIN_SIZE
from diagnosis.effects import EFFECTS
from truth_form_checks import (assert_builds_and_grows, assert_finite_and_grow_on_every_plant,
                               assert_zero_amplitude_is_the_base)

#: the family's form of each effect
FORM = {"acceleration": "lanchester_damper", "load": "brush_pads",
        "asymmetry": "peeled_tape", "stribeck_shape": "contact_charging",
        "position": "dimpled_band", "inertia": "speed_variator",
        "delay": "pen_arc", "drift": "sma_preload",
        "backlash": "taut_string", "gms": "mullins_shoe"}
#: a plant each form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s)
PLANT = {effect: "xml350" for effect in FORM}
#: the modules of truth forms: every form name any of them uses
_FORM_MODULES = ("diagnosis.benchmark.truths", "diagnosis.benchmark.forms",
                 "diagnosis.benchmark.seen", "diagnosis.benchmark.seen2",
                 "diagnosis.benchmark.seen3", "diagnosis.benchmark.seen4",
                 "diagnosis.benchmark.seen5", "diagnosis.benchmark.seen6",
                 "diagnosis.benchmark.seen7", "diagnosis.benchmark.seen8",
                 "diagnosis.benchmark.seen9", "diagnosis.benchmark.seen10",
                 "diagnosis.benchmark.seen11", "diagnosis.benchmark.seen12",
                 "diagnosis.benchmark.seen13", "diagnosis.benchmark.seen14",
                 "diagnosis.benchmark.seen15", "diagnosis.benchmark.seen16",
                 "diagnosis.benchmark.seen17", "diagnosis.benchmark.seen18",
                 "diagnosis.benchmark.seen19", "diagnosis.benchmark.seen20",
                 "diagnosis.benchmark.seen21", "diagnosis.benchmark.seen22",
                 "diagnosis.benchmark.seen23", "diagnosis.benchmark.seen24",
                 "diagnosis.benchmark.seen25", "diagnosis.benchmark.seen26",
                 "diagnosis.benchmark.seen27", "diagnosis.benchmark.seen28",
                 "diagnosis.benchmark.seen29", "diagnosis.benchmark.seen30",
                 "diagnosis.benchmark.seen31", "diagnosis.benchmark.seen32",
                 "diagnosis.benchmark.seen33", "diagnosis.benchmark.seen34",
                 "diagnosis.benchmark.seen35", "diagnosis.benchmark.seen36",
                 "diagnosis.benchmark.sealed", "diagnosis.effects_backlash",
                 "diagnosis.effects_gms")


def test_the_family_has_one_new_form_per_effect():
    assert family.FORMS == FORM
    assert set(PLANT) == set(FORM) == {n for n, e in EFFECTS.items() if e.truths}
    every = {f for e in EFFECTS.values() for f in e.forms("all")}
    for effect, form in FORM.items():
        assert form not in every, (effect, form)
        fn = getattr(family, f"{form}_truth")
        assert fn.__module__ == "diagnosis.benchmark.sealed"
        assert getattr(fn, "fine_grid", False), form   # integrated on the fine grid
        assert f"{form}_truth" in family.__all__
    # no function of that name, nor a form of that name, anywhere else
    names = {f"{f}_truth" for f in FORM.values()}
    for name in _FORM_MODULES:
        mod = importlib.import_module(name)
        if mod is family:
            continue
        assert not names & set(vars(mod)), name
        assert not set(FORM.values()) & set(getattr(mod, "FORMS", {}).values()), name
    doc = family.__doc__
    assert doc.startswith("The thirty-seventh sealed truth family")
    assert "sealed: not run" in doc and "2026-12-02 (session 41)" in doc
    assert "session 40's other, was run once and is :mod:`.seen36`" in doc


def test_registered_forms_resolve():
    # the effect records name this family's forms as their sealed ones
    for effect, form in FORM.items():
        assert EFFECTS[effect].forms("sealed") == (form,)
        assert EFFECTS[effect].truth(form) is getattr(family, f"{form}_truth")


@pytest.mark.parametrize("effect", sorted(PLANT))
def test_sealed_form_builds_a_case_and_grows_with_its_amplitude(effect):
    assert_builds_and_grows(effect, FORM[effect], PLANT[effect])


@pytest.mark.slow
def test_sealed_forms_are_finite_and_grow_on_every_plant_they_apply_to():
    # no diagnosis: only the truths, on each plant's quick motion
    assert_finite_and_grow_on_every_plant(FORM)


@pytest.mark.parametrize("plant", ["xml350", "valve"])
def test_sealed_forms_at_zero_amplitude_are_the_base(plant):
    # s scales the effect from nothing: at s = 0 each form is the base law
    assert_zero_amplitude_is_the_base(FORM, plant)


@pytest.mark.parametrize("plant", ["xml350", "valve"])
def test_sealed_forms_reach_their_size_on_two_plants(plant):
    # the calibration of the grid's cases: 0.95 to 1.05 of the requested size at strengths
    # 0.5 and 1 (quick protocols; every plant: the slow test below)
    for effect, form in FORM.items():
        for strength in (0.5, 1.0):
            case = make_plant_case(plant, effect, strength, 0.01, form=form, quick=True)
            share = case.effect_rms / (strength * EFFECT_SIZE)
            assert 0.95 <= share <= 1.05, (plant, effect, form, strength, share)


def test_sealed_forms_refuse_plants_they_do_not_apply_to():
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        family.contact_charging_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.taut_string_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.mullins_shoe_truth(iso, 1.0)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    # a one-way stroke (the press's) never comes back over the positions the fit part saw
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        family.dimpled_band_truth.__wrapped__(one_way, 1.0)
    # a load that never changes never changes the film
    still = dataclasses.replace(fk, load=np.full(fk.t.size, 100.0))
    with pytest.raises(ValueError, match="does not change"):
        family.brush_pads_truth.__wrapped__(still, 1.0)


# -- the mechanisms themselves (no case, no diagnosis) ---------------------------------------
def test_the_ring_follows_as_a_mass_then_slips_at_its_clutch():
    t = np.linspace(0.0, 1.0, 1001)
    v = 0.1 * t                          # a = 0.1
    F = family._ring_force(t, v, 1.0, 1.0)
    assert np.allclose(F[1:], 0.1)       # held: m a
    F = family._ring_force(t, 5.0 * t, 1.0, 1.0)
    assert np.allclose(F[1:], 1.0)       # slips at its clutch's force
    v = np.where(t < 0.5, 5.0 * t, 2.5)  # stops accelerating: the ring still catches up
    F = family._ring_force(t, v, 1.0, 1.0)
    assert F[600] == 1.0 and np.all(np.abs(F) <= 1.0 + 1e-12)


def test_the_bristles_lay_over_and_grip_more_than_the_load():
    w = np.array([0.0, 0.25, 0.5, 1.0])
    g = family._brush_friction(w, 0.1, 0.6, 0.1, 0.6)
    assert np.isclose(g[-1], 1.0) and np.all(np.diff(g) > 0.0)
    # faster than the load: the friction per unit load grows
    q = (w + 0.1) / 1.1
    assert np.all(np.diff(g / q) > 0.0)


def test_the_tape_costs_a_force_peeled_and_none_laid_back():
    p = family._peel_force(np.array([-1.0, 0.0, 0.1, 1.0, 2.0]), 0.3)
    assert p[0] == 0.0 and p[1] == 0.0 and np.isclose(p[3], 1.0)
    assert 0.0 < p[2] < p[3] < p[4] and np.isclose(p[4], 2.0 ** 0.3)


def test_the_charge_grows_with_the_speed_to_its_limit():
    q = family._contact_charge(np.array([0.0, 0.25, 1.0, -1.0, 100.0]), 0.25)
    assert q[0] == 0.0 and np.isclose(q[1], 0.5) and q[2] == q[3] and 0.99 < q[4] < 1.0


def test_the_dimples_lift_more_the_faster_and_only_on_the_band():
    d = np.array([0.0, 0.0, 0.0, 0.5])
    w = np.array([0.0, 0.3, 1.0, 1.0])
    lift = family._dimple_lift(d, w, 0.15, 0.02, 0.3)
    assert lift[0] == 0.0 and 0.0 < lift[1] < lift[2] < 1.0
    assert lift[3] < 1e-6
    assert np.isclose(lift[1], 0.5, atol=1e-3)


def test_the_variator_reflects_less_mass_the_faster():
    m = family._variator_mass(np.array([0.0, 0.5, 1.0, -1.0, 2.0]), 0.5, 1.2)
    assert m[0] == 1.0 and 1.0 > m[1] > m[2] > 0.0 and m[2] == m[3]
    assert np.isclose(m[4], family._variator_mass(np.array([1.2]), 0.5, 1.2)[0])


def test_the_pen_lags_by_its_arc_nothing_at_mid_scale():
    lag = family._arc_lag(np.array([0.0, 0.5, -0.5, 1.0, -1.0]), 0.7)
    assert lag[0] == 0.0 and lag[1] == lag[2] and 0.0 < lag[1] < 0.5
    assert np.allclose(lag[3:], 1.0)


def test_the_wire_turns_to_austenite_between_its_temperatures():
    tr = np.linspace(0.0, 1.0, 201)
    xi = family._austenite_share(tr, 0.35, 0.3, 0.85)
    assert xi[0] == 0.0 and np.all(np.diff(xi) >= 0.0)
    T = 1.0 - np.exp(-tr / 0.35)
    assert np.all(xi[T <= 0.3] == 0.0) and 0.9 < xi[-1] <= 1.0


def test_the_string_pulls_back_stiffening_to_its_pull_at_the_stops():
    f = [family._string_force(e, 1.0, 0.6, 0.05, 1.0) for e in (0.0, 0.1, 0.5, 1.0, -1.0)]
    assert f[0] == 0.0 and np.isclose(f[3], 0.6) and np.isclose(f[4], -0.6)
    # stiffening: the secant stiffness grows with the offset
    assert f[1] / 0.1 < f[2] / 0.5 < f[3] / 1.0


def test_the_rubber_softens_under_its_largest_strain_and_slides_at_one():
    up = np.linspace(0.0, 0.5, 51)
    f = family._mullins_pull(np.concatenate([up, up[::-1]]), 1.0, 0.6)
    assert np.all(np.abs(f) <= 1.0)
    assert np.isclose(f[50], 0.5 * (1.0 - 0.6 * 0.5 / 1.5))
    # back at 0.41, below the largest strain: softer than on the first loading there
    assert np.isclose(up[41], up[::-1][9]) and f[60] < f[41]
    x = np.linspace(0.0, 5.0, 501)
    assert np.isclose(family._mullins_pull(x, 1.0, 0.6)[-1], 1.0)


@pytest.mark.slow
def test_sealed_forms_reach_their_size_on_every_plant():
    # the sizing check: every form reaches 0.95 to 1.05 of the requested size at strengths
    # 0.5 and 1 on every plant it applies to (quick protocols), so the grid's count of its
    # cases (2 strengths x 2 noise levels x plants, 0.7 of the size at least) is 176
    from diagnosis.benchmark import applicable
    cases = 0
    for plant in PLANT_NAMES:
        for effect, form in FORM.items():
            if not applicable(plant, effect, quick=True):
                continue
            for strength in (0.5, 1.0):
                case = make_plant_case(plant, effect, strength, 0.01, form=form, quick=True)
                share = case.effect_rms / (strength * EFFECT_SIZE)
                assert np.all(np.isfinite(case.truth))
                assert 0.95 <= share <= 1.05, (plant, effect, form, strength, share)
                cases += 2 * (share >= MIN_SIZE)
    assert cases == 176
