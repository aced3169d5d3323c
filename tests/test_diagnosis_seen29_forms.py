"""The twenty-ninth seen truth family (diagnosis.benchmark.seen29, sealed in session 33, run
once on f2c371c, 62.5 % top-1, now open): each form builds a finite case of the requested
size on every plant it applies to, is the base law at s = 0, grows with its amplitude factor
and refuses the plants it does not apply to."""
import dataclasses

import numpy as np
import pytest

from diagnosis.benchmark import EFFECT_SIZE, PLANT_NAMES, make_plant_case, plant_kinematics
from diagnosis.benchmark import seen29 as family
from diagnosis.benchmark.kinematics import fine_kinematics
from diagnosis.benchmark.runner import MIN_SIZE

#: the family's form of each effect
FORM = {"acceleration": "elastic_counterweight", "load": "clamping_cylinder",
        "asymmetry": "gecko_wedges", "stribeck_shape": "flash_weakening",
        "position": "ferrous_insert", "inertia": "friction_pendulum",
        "delay": "fixed_point_filter", "drift": "lining_glazing",
        "backlash": "detent_ball", "gms": "hysteresis_brake"}
#: a plant each form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s)
PLANT = {effect: "xml350" for effect in FORM}


def test_seen29_forms_refuse_plants_they_do_not_apply_to():
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        family.flash_weakening_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.hysteresis_brake_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.detent_ball_truth(iso, 1.0)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    # a one-way stroke (the press's) never comes back over the positions the fit part saw
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        family.ferrous_insert_truth.__wrapped__(one_way, 1.0)
    # a load that never changes is passed on as the base law's
    still = dataclasses.replace(fk, load=np.full(fk.t.size, 100.0))
    with pytest.raises(ValueError, match="does not change"):
        family.clamping_cylinder_truth.__wrapped__(still, 1.0)


# -- the mechanisms themselves (no case, no diagnosis) ---------------------------------------
def test_the_weight_bounces_on_its_rope_and_then_follows():
    t = np.linspace(0.0, 40.0, 40001)
    aw = family._rope_bounce(t, np.full(t.size, 2.0), 2.0 * np.pi, 0.3)
    assert aw[0] == 0.0 and np.isclose(aw[-1], 2.0, rtol=1e-3)
    assert aw.max() > 2.5                                   # it overshot on the rope
    assert np.allclose(family._rope_bounce(t, np.zeros(t.size), 2.0 * np.pi, 0.3), 0.0)


def test_the_seal_passes_the_load_on_through_a_play():
    y = family._seal_play(np.array([0.0, 1.0, 0.5, 0.2, 1.0]), 0.2)
    assert np.allclose(y, [0.0, 0.8, 0.7, 0.4, 0.8])
    assert np.allclose(family._seal_play(np.array([0.0, 1.0, 0.9, 0.7]), 0.2),
                       [0.0, 0.8, 0.8, 0.8])                 # held while it turns back


def test_the_wedges_adhere_one_way_and_less_at_speed():
    a = family._wedge_adhesion(np.array([1.0, -1.0, 1.0]), np.array([0.0, 0.0, 1.0]))
    assert np.allclose(a, [1.0, 0.0, 0.5])


def test_the_asperities_weaken_above_the_weakening_speed():
    f = family._flash_factor(np.array([0.0, 0.5, 1.0, 2.0, -4.0]), 0.5)
    assert np.allclose(f, [1.0, 1.0, 1.0, 0.75, 0.625])


def test_the_insert_attracts_over_its_length_and_pulls_at_its_edges():
    xr = np.linspace(0.0, 1.0, 1001)
    w, dw = family._insert_field(xr, 0.5, 0.3, 0.03)
    assert np.isclose(w[500], 1.0, atol=1e-3) and w[0] < 1e-6 and w[-1] < 1e-6
    assert np.isclose(dw[350], 0.5) and np.isclose(dw[650], -0.5)
    assert np.allclose(w, w[::-1]) and np.allclose(dw, -dw[::-1])


def test_the_payload_slides_in_its_dish_and_sticks_again():
    t = np.linspace(0.0, 40.0, 40001)
    acc = family._pendulum_slider(t, np.full(t.size, 2.0), 2.0 * np.pi, 0.5)
    assert acc[0] == 0.5                 # sliding, the slider passes its friction only
    assert acc[-1] == 2.0                # stuck again, carried whole
    held = family._pendulum_slider(t, np.full(t.size, 0.3), 2.0 * np.pi, 0.5)
    assert np.allclose(held, 0.3)        # within the friction: never slides
    assert np.allclose(family._pendulum_slider(t, np.zeros(t.size), 2.0 * np.pi, 0.5), 0.0)


def test_the_integer_filter_stops_short_of_a_rising_force():
    u = np.r_[np.zeros(10), np.ones(200), np.zeros(200)]
    y = family._integer_lowpass(u, 0.5, 0.01)
    assert np.allclose(y[10:14], [0.5, 0.75, 0.87, 0.93])
    assert np.isclose(y[209], 0.99)      # within count / gain below the input, held there
    assert abs(y[-1]) < 1e-12            # falling, the floor takes it all the way
    c = family._integer_lowpass(np.full(20, 1.0), 0.5, 2.0 ** -4)
    assert np.allclose(c, 1.0)


def test_the_glaze_grows_with_the_work_and_saturates():
    g = family._glaze(np.array([0.0, 0.5, 50.0]), 0.5)
    assert np.allclose(g, [0.0, 1.0 - np.exp(-1.0), 1.0])


def test_the_detent_pulls_inside_its_notch_only():
    f = [family._detent_force(e, 1.0, 1.0, 0.1) for e in (0.0, 0.5, -0.5, 2.0)]
    assert f[0] == 0.0 and 0.9 < f[1] < 1.0 and np.isclose(f[2], -f[1]) and abs(f[3]) < 1e-6
    kin = plant_kinematics("valve", quick=True)
    assert np.all(np.isfinite(family.detent_ball_truth(kin, 1.0)))


def test_the_brake_follows_rayleigh_branches():
    m = family._rayleigh_loop(np.array([0.0, 0.5, 1.0, 2.0, 1.0, 0.0, -1.0]), 1.0)
    assert np.allclose(m, [0.0, 0.75, 1.0, 1.0, -0.5, -1.0, -1.0])
    kin = plant_kinematics("valve", quick=True)
    assert np.all(np.isfinite(family.hysteresis_brake_truth(kin, 1.0)))


@pytest.mark.slow
def test_seen29_forms_reach_their_size_on_every_plant():
    # the sizing check: every form reaches 0.95 to 1.05 of the requested size at strengths
    # 0.5 and 1 on every plant it applies to (quick protocols), so the open grid's count of its
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
