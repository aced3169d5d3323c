"""The thirty-fifth seen truth family (diagnosis.benchmark.seen35, sealed in session 40, run
once on ddc8eb5, 64.2 % top-1, now open): each form builds a finite case of the requested
size on every plant it applies to, is the base law at s = 0, grows with its amplitude factor
and refuses the plants it does not apply to."""
import dataclasses

import numpy as np
import pytest

from diagnosis.benchmark import EFFECT_SIZE, PLANT_NAMES, make_plant_case, plant_kinematics
from diagnosis.benchmark import seen35 as family
from diagnosis.benchmark.kinematics import fine_kinematics
from diagnosis.benchmark.runner import MIN_SIZE

#: the family's form of each effect
FORM = {"acceleration": "worm_mesh", "load": "ball_hysteresis",
        "asymmetry": "trailing_hose", "stribeck_shape": "dielectric_pad",
        "position": "wet_patch", "inertia": "winch_layers",
        "delay": "bucket_brigade", "drift": "leaking_bladder",
        "backlash": "liquid_bridge", "gms": "magnet_coupling"}
#: a plant each form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s)
PLANT = {effect: "xml350" for effect in FORM}


def test_seen35_forms_refuse_plants_they_do_not_apply_to():
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        family.dielectric_pad_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.liquid_bridge_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.magnet_coupling_truth(iso, 1.0)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    # a one-way stroke (the press's) never comes back over the positions the fit part saw
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        family.wet_patch_truth.__wrapped__(one_way, 1.0)
    # a load that never changes never changes the balls' loss
    still = dataclasses.replace(fk, load=np.full(fk.t.size, 100.0))
    with pytest.raises(ValueError, match="does not change"):
        family.ball_hysteresis_truth.__wrapped__(still, 1.0)


# -- the mechanisms themselves (no case, no diagnosis) ---------------------------------------
def test_the_worm_loses_more_driving_and_less_as_it_speeds_up():
    lead, mu0, mu1, fall, sw = 0.35, 0.15, 0.04, 0.2, 0.01
    loss = family._worm_loss(np.array([0.0, 1.0, -1.0, 1.0]), np.array([0.5, 0.5, 0.5, 5.0]),
                             lead, mu0, mu1, fall, sw)
    mu = mu1 + (mu0 - mu1) / (1.0 + 0.5 / fall)
    phi = np.arctan(mu)
    assert loss[0] == 0.0
    assert np.isclose(loss[1], np.tan(lead + phi) / np.tan(lead) - 1.0)     # driving
    assert np.isclose(loss[2], 1.0 - np.tan(lead - phi) / np.tan(lead))     # back-driven
    assert loss[1] > loss[2] > 0 and 0 < loss[3] < loss[1]


def test_the_balls_lose_as_the_load_to_the_four_thirds():
    g = family._rolling_hysteresis(np.array([0.0, 0.5, 1.0]), 0.1)
    assert np.isclose(g[2], 1.0) and np.isclose(g[0], (0.1 / 1.1) ** (4.0 / 3.0))
    assert g[2] - g[1] > g[1] - g[0] > 0                       # ever faster


def test_the_hose_drags_pulled_and_gives_up_its_slack_over_a_travel():
    x = np.r_[np.linspace(0.0, 0.1, 11), np.linspace(0.1, 0.0, 11)[1:],
              np.linspace(0.0, 0.2, 21)[1:]]
    p = family._hose_pull(x, 0.05)
    assert np.all(p[:11] == 1.0)                               # straight: all of it slides
    # pushed back 0.1, the loops hold 0.05 of slack, taken up over the next 0.05 of travel
    assert np.isclose(p[20 + 2], 0.4) and np.isclose(p[20 + 4], 0.8)
    assert np.all(p[20 + 5:] == 1.0)


def test_the_pad_pulls_fully_at_rest_and_fades_with_the_speed():
    q = family._pad_pull(np.array([0.0, 0.015, 0.15, 1.5, -1.5]), 0.15)
    assert q[0] == 1.0 and q[1] > 0.99 and np.isclose(q[2], (1.0 - np.exp(-1.0)) ** 2)
    assert np.isclose(q[3], (1.0 - np.exp(-0.1)) ** 2) and q[3] == q[4]
    assert np.isclose(q[3], 0.01, rtol=0.1)                    # ~ (0.15 / u)^2


def test_the_menisci_pull_hardest_where_the_film_is_thin():
    d = np.array([0.0, 0.1 * np.sqrt(np.log(3.0)), 0.5])
    b = family._meniscus_pull(d, 0.1, 3.0)
    assert np.isclose(b[0], 3.0 * np.exp(-2.0)) and np.isclose(b[1], 1.0) and b[2] < 1e-9
    assert b[1] > b[0] > b[2]                                  # a ring round a milder middle


def test_the_drum_reflects_less_mass_on_each_layer():
    m, dm = family._winch_mass(np.array([0.0, 0.5, 1.0]), 3, 0.25, 0.08)
    assert np.isclose(m[0], 1.0, atol=1e-6) and np.isclose(m[2], 1.0 / 1.5 ** 2, atol=1e-6)
    assert m[0] > m[1] > m[2] and np.all(dm <= 0.0)
    h = 1e-6
    q = 1.0 / 3.0 + 0.01                                       # on a cross-over
    slope = (family._winch_mass(q + h, 3, 0.25, 0.08)[0]
             - family._winch_mass(q - h, 3, 0.25, 0.08)[0]) / (2 * h)
    assert np.isclose(slope, family._winch_mass(q, 3, 0.25, 0.08)[1])


def test_the_brigade_delays_by_its_stages_and_smears():
    ks, ws = family._brigade_weights(16, 0.08)
    assert ks[0] == 16 and np.isclose(ws.sum(), 1.0)
    assert np.isclose(ws[0], 0.92 ** 16, rtol=1e-6)
    assert np.isclose(np.sum(ks * ws), 16 / 0.92, rtol=1e-4)  # the mean: stages / (1 - loss)
    assert np.allclose(family._brigade_weights(4, 0.0)[0], [4.0])   # no loss: a pure delay


def test_the_bladder_empties_choked_then_ever_more_slowly():
    tr = np.array([0.0, 0.1, 0.2, 0.5, 1.0])
    p = family._bladder_pressure(tr, 4.0, 1.0, 1.4)
    assert p[0] == 4.0 and np.all(np.diff(p) < 0) and p[-1] >= 1.0
    assert np.isclose(p[1], 4.0 * np.exp(-0.1), rtol=1e-3)   # choked: exponential
    # subsonic: the pressure falls slower than the choked exponential would go on
    late = family._bladder_pressure(np.array([0.9, 1.0]), 4.0, 1.0, 1.4)
    assert late[0] < 1.893 and (late[0] - late[1]) / late[0] < 1.0 - np.exp(-0.1)


def test_the_bridge_pulls_less_as_it_stretches_and_ruptures():
    f = [family._bridge_force(d, 2.0, 1e-3) for d in (-1e-4, 0.0, 5e-4, 1e-3, 2e-3)]
    assert f[0] == f[1] == 2.0 and np.isclose(f[2], 1.0) and f[3] == f[4] == 0.0
    kin = plant_kinematics("valve", quick=True)
    assert np.all(np.isfinite(family.liquid_bridge_truth(kin, 1.0)))


def test_the_magnet_holds_the_shoe_softening_towards_its_pull_out():
    f = family._coupling_pull(np.array([0.0, 0.5, 1.0, -1.0]), 1.2)
    assert f[0] == 0.0 and np.isclose(f[2], 1.0) and f[3] == -1.0
    assert f[1] > 0.5                                          # stiff first, then softer
    path = np.r_[np.linspace(0.0, 3.0, 3001), np.linspace(3.0, -3.0, 6001)[1:]]
    r = family._shoe_offset(path, 1.0)
    assert r[0] == 0.0 and np.isclose(r[500], 0.5) and np.isclose(r[3000], 1.0)
    assert np.isclose(r[3000 + 1500], -0.5) and np.isclose(r[-1], -1.0)
    kin = plant_kinematics("valve", quick=True)
    assert np.all(np.isfinite(family.magnet_coupling_truth(kin, 1.0)))


@pytest.mark.slow
def test_seen35_forms_reach_their_size_on_every_plant():
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
