"""The thirty-third seen truth family (diagnosis.benchmark.seen33, sealed in session 38, run
once on c6080f7, 59.7 % top-1, now open): each form builds a finite case of the requested
size on every plant it applies to, is the base law at s = 0, grows with its amplitude factor
and refuses the plants it does not apply to."""
import dataclasses

import numpy as np
import pytest

from diagnosis.benchmark import EFFECT_SIZE, PLANT_NAMES, make_plant_case, plant_kinematics
from diagnosis.benchmark import seen33 as family
from diagnosis.benchmark.kinematics import fine_kinematics
from diagnosis.benchmark.runner import MIN_SIZE

#: the family's form of each effect
FORM = {"acceleration": "bowed_screw", "load": "magnet_preload",
        "asymmetry": "clapper_tool", "stribeck_shape": "battery_dynamo",
        "position": "hardened_zones", "inertia": "shunted_coil",
        "delay": "complementary_fusion", "drift": "solenoid_coil",
        "backlash": "eddy_gap", "gms": "air_shoe"}
#: a plant each form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s)
PLANT = {effect: "xml350" for effect in FORM}


def test_seen33_forms_refuse_plants_they_do_not_apply_to():
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        family.battery_dynamo_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.air_shoe_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.eddy_gap_truth(iso, 1.0)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    # a one-way stroke (the press's) never comes back over the positions the fit part saw
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        family.hardened_zones_truth.__wrapped__(one_way, 1.0)
    # a load that never changes never moves the magnet's gap
    still = dataclasses.replace(fk, load=np.full(fk.t.size, 100.0))
    with pytest.raises(ValueError, match="does not change"):
        family.magnet_preload_truth.__wrapped__(still, 1.0)


# -- the mechanisms themselves (no case, no diagnosis) ---------------------------------------
def test_the_bow_grows_under_compression_and_shrinks_under_tension():
    b = family._bow_growth(np.array([0.0, 0.5, -0.5, 0.75]))
    assert np.allclose(b, [1.0, 2.0, 2.0 / 3.0, 4.0])
    kin = plant_kinematics("forging_press", quick=True)
    assert np.all(np.isfinite(family.bowed_screw_truth(kin, 1.0)))


def test_the_magnet_pulls_as_the_inverse_square_of_its_closing_gap():
    p = family._magnet_pull(np.array([0.0, 1.0, -1.0, 0.5]), 2.0)
    assert np.allclose(p, [1.0, 4.0, 4.0, (2.0 / 1.5) ** 2])


def test_the_cutting_force_falls_slowly_with_the_speed():
    c = family._cutting_factor(np.array([1.0, -1.0, 0.0, 0.5]), 0.1, 0.2)
    assert np.allclose(c[:2], 1.0) and np.isclose(c[2], 11.0 ** 0.2)
    assert c[2] > c[3] > c[0]


def test_the_dynamo_brakes_above_its_cut_in_speed():
    c = family._charging_current(np.array([0.0, 0.3, 1.0, -1.0, 0.675]), 0.35, 1e-9)
    assert np.allclose(c, [0.0, 0.0, 1.0, 1.0, 0.5], atol=1e-8)
    q = family._charging_current(np.linspace(0.0, 1.0, 101), 0.35, 0.03)
    assert np.all(np.diff(q) > 0.0) and q[0] < 0.01


def test_the_way_is_soft_where_two_passes_meet():
    b = family._softness(np.array([0.0, 0.4, 0.8, 0.46, 1.0]), 0.4, 0.06)
    assert np.isclose(b[0], 0.0, atol=1e-9) and np.allclose(b[1:3], 1.0)
    assert np.isclose(b[3], np.exp(-0.5)) and b[4] < 0.01


def test_the_shunted_coil_is_a_mass_seen_through_its_lag():
    t = np.linspace(0.0, 10.0, 100001)
    f = family._shunt_force(t, np.ones_like(t), 2.0 * t, 3.0, 0.5)
    assert np.allclose(f, 6.0 * (1.0 - np.exp(-t / 0.5)), atol=1e-3)   # M a, after the lag
    b = family._coil_coupling(np.array([0.0, 1.0, -1.0, 2.0]), 0.3)
    assert np.allclose(b, [1.0, 0.7, 0.7, 0.7])


def test_the_fusion_delays_only_the_slow_part():
    t = np.linspace(0.0, 10.0, 10001)
    u = (t >= 2.0).astype(float)
    assert np.allclose(family._fuse(t, np.full(t.size, 3.0), 1.0, 0.5), 3.0)
    assert np.allclose(family._fuse(t, u, 0.0, 0.5), u)
    y = family._fuse(t, u, 3.0, 0.5)
    assert np.allclose(y[:2000], 0.0)
    k = 2000 + np.arange(1, 3000, 500)                  # the fast part on time, then fading
    assert np.allclose(y[k], np.exp(-(t[k] - 2.0) / 0.5), atol=2e-3)
    assert np.isclose(y[-1], 1.0, atol=1e-3)            # the slow part, late


def test_the_warming_coil_pulls_less():
    p = family._coil_pull(np.array([0.0, 0.5, 1e3]), 0.5, 0.4)
    assert np.isclose(p[0], 1.0) and np.isclose(p[2], 1.0 / 1.4 ** 2)
    assert np.isclose(p[1], 1.0 / (1.0 + 0.4 * (1.0 - np.exp(-1.0))) ** 2)
    assert np.all(np.diff(family._coil_pull(np.linspace(0.0, 1.0, 101), 0.5, 0.4)) < 0.0)


def test_the_eddy_drag_peaks_at_its_critical_speed():
    d = [family._eddy_drag(e, 2.0, 0.5) for e in (0.0, 0.5, -0.5, 1e-4, 50.0)]
    assert d[0] == 0.0 and np.isclose(d[1], 2.0) and np.isclose(d[2], -2.0)
    assert np.isclose(d[3], 2.0 * 2.0 * 1e-4 / 0.5, rtol=1e-6)   # viscous when slow
    assert 0.0 < d[4] < 0.05                                    # pushed out when fast
    kin = plant_kinematics("valve", quick=True)
    assert np.all(np.isfinite(family.eddy_gap_truth(kin, 1.0)))


def test_the_air_spring_stiffens_and_the_shoe_slides():
    f = family._air_spring(np.array([0.0, 1.0, -1.0, 0.5]), 1.5, 1.0)
    assert np.isclose(f[0], 0.0) and np.isclose(f[1], 1.0) and np.isclose(f[2], -1.0)
    assert np.isclose(f[3], (1.5 / 1.0 - 1.5 / 2.0) / (1.5 / 0.5 - 1.5 / 2.5))
    assert f[3] < 0.5                                   # stiffer the further it travels
    path = np.r_[np.linspace(0.0, 3.0, 3001), np.linspace(3.0, -3.0, 6001)[1:]]
    r = family._shoe_travel(path, 1.0)
    assert r[0] == 0.0 and np.isclose(r[500], 0.5) and np.isclose(r[3000], 1.0)
    assert np.isclose(r[3000 + 1500], -0.5) and np.isclose(r[-1], -1.0)
    kin = plant_kinematics("valve", quick=True)
    assert np.all(np.isfinite(family.air_shoe_truth(kin, 1.0)))


@pytest.mark.slow
def test_seen33_forms_reach_their_size_on_every_plant():
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
