"""The thirty-sixth sealed truth family (diagnosis.benchmark.sealed, written in session 40
by another hand, sealed: not run): each form builds a finite case of the requested size on every
plant it applies to, is the base law at s = 0, grows with its amplitude factor and refuses
the plants it does not apply to. No diagnosis is run on these forms: the family stays unseen
until the end of a piece of work. Each effect record of :data:`diagnosis.effects.EFFECTS`
names it as its ``sealed`` form (the thirty-fifth family, sealed before it, is
:mod:`diagnosis.benchmark.seen35` since its run)."""
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
FORM = {"acceleration": "slip_coupling", "load": "porous_bushing",
        "asymmetry": "magnetic_conveyor", "stribeck_shape": "spin_off",
        "position": "rust_stain", "inertia": "scissor_links",
        "delay": "rolling_shutter", "drift": "battery_magnet",
        "backlash": "swing_shackle", "gms": "hanging_shoe"}
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
                 "diagnosis.benchmark.seen35", "diagnosis.benchmark.sealed",
                 "diagnosis.effects_backlash", "diagnosis.effects_gms")


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
    assert doc.startswith("The thirty-sixth sealed truth family")
    assert "sealed: not run" in doc and "2026-12-02 (session 40)" in doc
    assert "session 40's first, was run once and is :mod:`.seen35`" in doc


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
        family.spin_off_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.swing_shackle_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.hanging_shoe_truth(iso, 1.0)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    # a one-way stroke (the press's) never comes back over the positions the fit part saw
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        family.rust_stain_truth.__wrapped__(one_way, 1.0)
    # a load that never changes never changes the film
    still = dataclasses.replace(fk, load=np.full(fk.t.size, 100.0))
    with pytest.raises(ValueError, match="does not change"):
        family.porous_bushing_truth.__wrapped__(still, 1.0)


# -- the mechanisms themselves (no case, no diagnosis) ---------------------------------------
def test_the_coupling_loses_more_with_the_thrust_and_less_as_it_speeds_up():
    slip, stall, thrust = 0.1, 0.3, 1.0
    loss = family._coupling_loss(np.array([0.0, 0.5, -0.5, 0.5, 0.5]),
                                 np.array([0.5, 0.5, 0.5, 1.0, -0.5]), slip, stall, thrust)
    d = 0.25 + 0.09
    assert loss[0] == 0.0
    assert np.isclose(loss[1], 1.5 * slip * 1.5 / d - slip / d)          # (1 + u)^2 - 1
    assert loss[2] < 0 < loss[3] < loss[1]                                # less at speed
    assert loss[4] < 0                                                    # braking a -x run
    stalled = family._coupling_loss(np.array([3.0]), np.array([0.01]), 1.0, stall, thrust)
    assert np.isclose(stalled[0], 4.0 - 1.0)                              # sigma capped at 1


def test_the_bushing_loses_its_film_into_the_pores_as_the_load_grows():
    g = family._bushing_friction(np.array([0.0, 0.5, 1.0]), 0.1, 3.0, 3.0, 0.15, 0.01)
    assert np.isclose(g[2], 1.0) and 0 < g[0] < g[1] < g[2]
    assert g[2] - g[1] > g[1] - g[0]                                      # ever faster
    # no drain: the film keeps its thickness and the friction is the load's
    flat = family._bushing_friction(np.array([0.0, 1.0]), 0.1, 3.0, 0.0, 0.15, 0.01)
    assert np.isclose(flat[0], 0.1 / 1.1)


def test_the_travelling_field_pulls_by_the_slip():
    p = family._induction_pull(np.array([1.5, 0.0, 1.05, -3.0]), 1.5, 0.3)
    assert p[0] == 0.0                                                    # moving with it
    assert np.isclose(p[2], 1.0)                                          # the breakdown
    assert np.isclose(p[1], 2.0 * 0.3 / (1.0 + 0.09)) and 0 < p[3] < p[1]
    assert np.isclose(family._induction_pull(3.0, 1.5, 0.3), -p[1])      # odd in the slip


def test_the_spinning_film_thins_with_the_speed():
    h = family._spun_film(np.array([0.0, 0.5, 1.0, -1.0]), 12.0)
    assert h[0] == 1.0 and 1.0 > h[1] > h[2] > 0 and h[2] == h[3]
    assert np.isclose(1.0 - h[2], 12.0 * h[2] ** 3)                       # its steady state


def test_the_rust_covers_the_stain_and_fades_at_its_edges():
    c = family._rust_cover(np.array([0.0, 0.12, -0.12, 0.5]), 0.12, 0.05)
    assert c[0] > 0.999 and np.isclose(c[1], 0.5) and c[1] == c[2] and c[3] < 1e-12


def test_the_scissor_reflects_ever_more_mass_as_it_stretches():
    m, dm = family._scissor_mass(np.array([0.0, 0.5, 1.0]), 6, 0.45, 0.92)
    assert np.isclose(m[1], 1.0) and m[0] < m[1] < m[2] and np.all(dm > 0)
    h = 1e-6
    slope = (family._scissor_mass(0.3 + h, 6, 0.45, 0.92)[0]
             - family._scissor_mass(0.3 - h, 6, 0.45, 0.92)[0]) / (2 * h)
    assert np.isclose(slope, family._scissor_mass(0.3, 6, 0.45, 0.92)[1])


def test_the_shutter_delays_by_the_row_the_force_falls_on():
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    F0 = family.rolling_shutter_truth.__wrapped__(fk, 0.0)
    F1 = family.rolling_shutter_truth.__wrapped__(fk, 1.0)
    assert np.all(np.isfinite(F1)) and not np.allclose(F0, F1)
    t = np.asarray(fk.t, float)
    # the force's top row is read last, its bottom row first
    for k, rows in ((int(np.argmax(F0)), family.SHUTTER_FIRST + family.SHUTTER_SPAN),
                    (int(np.argmin(F0)), family.SHUTTER_FIRST)):
        tau = rows * fk.sample_dt
        assert np.isclose(F1[k], np.interp(t[k] - tau, t, F0, left=F0[0]))


def test_the_battery_falls_quickly_then_slowly_then_at_its_knee():
    tr = np.linspace(0.0, 1.0, 101)
    u = family._battery_voltage(tr, 0.9, 0.04, 0.08, 30.0)
    assert u[0] == 1.0 and np.all(np.diff(u) < 0)
    d = -np.diff(u)
    assert d[0] > d[40] < d[-1]                                           # fast, slow, knee


def test_the_shackle_pulls_as_the_tangent_of_its_swing():
    half, pull, swing = 1e-3, 2.0, 1.0
    f = [family._shackle_force(e, half, pull, swing) for e in (0.0, 5e-4, 1e-3, 2e-3, -1e-3)]
    assert f[0] == 0.0 and np.isclose(f[2], pull) and f[3] == f[2] and f[4] == -f[2]
    assert 0 < f[1] < 0.5 * pull                                          # soft at first
    kin = plant_kinematics("valve", quick=True)
    assert np.all(np.isfinite(family.swing_shackle_truth(kin, 1.0)))


def test_the_hanger_holds_the_shoe_stiffening_towards_its_slip():
    f = family._hanger_pull(np.array([0.0, 0.5, 1.0, -1.0]), 1.1)
    assert f[0] == 0.0 and np.isclose(f[2], 1.0) and np.isclose(f[3], -1.0)
    assert f[1] < 0.5                                                     # soft first, stiffer
    path = np.r_[np.linspace(0.0, 3.0, 3001), np.linspace(3.0, -3.0, 6001)[1:]]
    r = family._hanger_offset(path, 1.0)
    assert r[0] == 0.0 and np.isclose(r[500], 0.5) and np.isclose(r[3000], 1.0)
    assert np.isclose(r[3000 + 1500], -0.5) and np.isclose(r[-1], -1.0)
    kin = plant_kinematics("valve", quick=True)
    assert np.all(np.isfinite(family.hanging_shoe_truth(kin, 1.0)))


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
