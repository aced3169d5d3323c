"""The thirtieth seen truth family (diagnosis.benchmark.seen30, sealed in session 34, run
once on fe2a59f, 59.7 % top-1, now open): each form builds a finite case of the requested
size on every plant it applies to, is the base law at s = 0, grows with its amplitude factor
and refuses the plants it does not apply to."""
import dataclasses

import numpy as np
import pytest

from diagnosis.benchmark import EFFECT_SIZE, PLANT_NAMES, make_plant_case, plant_kinematics
from diagnosis.benchmark import seen30 as family
from diagnosis.benchmark.kinematics import fine_kinematics
from diagnosis.benchmark.runner import MIN_SIZE

#: the family's form of each effect
FORM = {"acceleration": "inertia_lubricator", "load": "crowned_rollers",
        "asymmetry": "charging_generator", "stribeck_shape": "peel_adhesion",
        "position": "lead_preload", "inertia": "liquid_column",
        "delay": "polynomial_smoother", "drift": "carbon_tribolayer",
        "backlash": "magnet_latch", "gms": "fibre_wiper"}
#: a plant each form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s)
PLANT = {effect: "xml350" for effect in FORM}


def test_seen30_forms_refuse_plants_they_do_not_apply_to():
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        family.peel_adhesion_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.fibre_wiper_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.magnet_latch_truth(iso, 1.0)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    # a one-way stroke (the press's) never comes back over the positions the fit part saw
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        family.lead_preload_truth.__wrapped__(one_way, 1.0)
    # a load that never changes never reaches the rollers' ends differently
    still = dataclasses.replace(fk, load=np.full(fk.t.size, 100.0))
    with pytest.raises(ValueError, match="does not change"):
        family.crowned_rollers_truth.__wrapped__(still, 1.0)


# -- the mechanisms themselves (no case, no diagnosis) ---------------------------------------
def test_the_pump_delivers_beyond_its_preload_and_the_film_is_used_up():
    q = family._pump_delivery(np.array([0.0, 0.4, -0.7, 1.0]), 0.4)
    assert np.allclose(q, [0.0, 0.0, 0.5, 1.0])
    t = np.linspace(0.0, 20.0, 2001)
    h = family._oil_film(t, np.r_[np.ones(1000), np.zeros(1001)], 1.0)
    assert h[0] == 0.0 and np.isclose(h[999], 0.5, rtol=1e-3)   # q / (1 + q)
    assert h[-1] < 1e-3                                           # used up without supply


def test_the_rollers_load_their_ends_past_the_knee():
    e = family._edge_load(np.array([0.0, 0.5, 1.0, 2.0, 5.0]))
    assert np.allclose(e, [0.0, 0.0, 0.0, 1.0, 8.0])


def test_the_generator_charges_one_way_above_its_knee():
    i = family._charge_current(np.array([-1.0, 0.0, 0.3, 1.0]), 0.3, 1e-9)
    assert np.allclose(i, [0.0, 0.0, 0.0, 1.0], atol=1e-8)


def test_the_tearing_share_rises_and_levels_off():
    f = family._tearing_share(np.array([0.0, 1.0, -1.0, 1e6]), 0.6)
    assert np.allclose(f, [0.0, 0.5, 0.5, 1.0], atol=1e-3)


def test_the_preload_follows_the_lead_error_over_the_spacer():
    xr = np.linspace(0.0, 1.0, 101)
    p = family._preload_change(xr, 0.15)
    assert np.isclose(p[50], 0.0) and np.ptp(p) > 0.1
    assert np.allclose(family._preload_change(xr, 0.0), 0.0)   # no spacer, no change


def test_the_column_swings_and_settles_back():
    t = np.linspace(0.0, 40.0, 40001)
    acc = family._column_swing(t, np.r_[np.full(5500, 1.0), np.zeros(34501)],
                               2.0 * np.pi, 0.7, 1.0)
    assert np.isclose(acc[0], -0.7)                  # the limb's share, the column at rest
    free = family._column_swing(t, np.r_[np.full(5500, 1.0), np.zeros(34501)],
                                2.0 * np.pi, 0.7, 0.0)
    # the orifice's loss takes the swing down; without it the column swings on
    assert 0.0 < np.abs(acc[-5000:]).max() < 0.5 * np.abs(free[-5000:]).max()
    assert np.allclose(family._column_swing(t, np.zeros(t.size), 2.0 * np.pi, 0.7, 1.0),
                       0.0)


def test_the_smoother_passes_its_polynomials_and_lags_at_a_bend():
    w = family._endpoint_weights(9, 2)
    k = np.arange(9.0)
    assert np.isclose(w.sum(), 1.0) and np.isclose(w @ (k ** 2), 64.0)
    u = np.r_[np.zeros(20), np.arange(1.0, 21.0)]
    y = family._fir_causal(u, w)
    assert np.allclose(y[:20], 0.0) and np.allclose(y[-5:], u[-5:])
    assert not np.allclose(y[20:28], u[20:28])       # at the bend


def test_the_tribolayer_follows_the_distance():
    c = family._covered(np.array([0.0, 0.4, 1e3]), 0.4, 3.0)
    assert np.allclose(c, [0.0, 0.5, 1.0])


def test_the_latch_pulls_towards_the_nearer_flank():
    f = [family._latch_force(e, 1.0, 1.0, 0.5) for e in (0.0, 0.5, -0.5, 1.0, 3.0)]
    assert f[0] == 0.0 and 0.0 < f[1] < 1.0 and np.isclose(f[2], -f[1])
    assert np.isclose(f[3], 1.0) and np.isclose(f[4], 1.0)
    kin = plant_kinematics("valve", quick=True)
    assert np.all(np.isfinite(family.magnet_latch_truth(kin, 1.0)))


def test_the_wiper_follows_a_hyperbola_and_masings_rule():
    x = np.array([0.0, 1.0, 3.0, 1.0, -1.0])
    f = family._masing_hyperbola(x, 1.0)
    assert np.allclose(f[:3], [0.0, 0.5, 0.75])
    assert np.isclose(f[3], 0.75 - 1.0) and np.isclose(f[4], 0.75 - 2.0 * 2.0 / 3.0)
    kin = plant_kinematics("valve", quick=True)
    assert np.all(np.isfinite(family.fibre_wiper_truth(kin, 1.0)))


@pytest.mark.slow
def test_seen30_forms_reach_their_size_on_every_plant():
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
