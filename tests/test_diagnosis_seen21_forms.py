"""The twenty-first seen truth family (diagnosis.benchmark.seen21, sealed in session 25, run
once on cead57e, 50.0 % top-1, now open): each form builds a finite case of the requested
size on every plant it applies to, is the base law at s = 0, grows with its amplitude factor
and refuses the plants it does not apply to."""
import dataclasses

import numpy as np
import pytest

from diagnosis.benchmark import EFFECT_SIZE, PLANT_NAMES, make_plant_case, plant_kinematics
from diagnosis.benchmark import seen21 as family
from diagnosis.benchmark.kinematics import FINE, PlantKinematics, fine_kinematics
from diagnosis.benchmark.runner import MIN_SIZE
from diagnosis.benchmark.truths import base_force

#: the family's form of each effect
FORM = {"acceleration": "cone_sensor_brake", "load": "pin_in_bore",
        "asymmetry": "counterbalance_valve", "stribeck_shape": "flying_pad",
        "position": "spool_flow_force", "inertia": "spring_surge",
        "delay": "magnetoelastic_cell", "drift": "receiver_pressure",
        "backlash": "overlapped_servo", "gms": "contact_renewal"}
#: a plant each form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s)
PLANT = {effect: "xml350" for effect in FORM}
def test_seen21_forms_refuse_plants_they_do_not_apply_to():
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        family.flying_pad_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.contact_renewal_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.overlapped_servo_truth(iso, 1.0)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    # a one-way stroke (the press's) never comes back over the positions the fit part saw
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        family.spool_flow_force_truth.__wrapped__(one_way, 1.0)
    # a load that never changes cannot show the contact arc's growth with the load
    still = dataclasses.replace(fk, load=np.full(fk.t.size, 100.0))
    with pytest.raises(ValueError, match="does not change"):
        family.pin_in_bore_truth.__wrapped__(still, 1.0)


# -- the mechanisms themselves (no case, no diagnosis) ---------------------------------------
def _triangle(plant="valve", n=4001, v=0.01):
    """A synthetic motion on the fine grid with ``plant``'s base law: up at ``v`` [m/s],
    then down, 0.2 s each."""
    kin = plant_kinematics(plant, quick=True)
    t = np.linspace(0.0, 0.4, n)
    vel = np.where(t < 0.2, v, -v) * np.tanh(np.minimum(t, 0.4 - t) / 0.005)
    vel = np.where(np.abs(t - 0.2) < 0.004, v * (0.2 - t) / 0.004, vel)
    x = np.concatenate(([0.0], np.cumsum(0.5 * (vel[1:] + vel[:-1]) * np.diff(t))))
    return PlantKinematics(plant, t, x, vel, np.gradient(vel, t), np.full(n, 100.0),
                           kin.base, kin.seed_law, "triangle", step=FINE)


def test_the_relay_switches_on_above_one_level_and_off_below_a_lower_one():
    u = np.array([0.0, 0.5, 0.7, 0.5, 0.4, 0.2, 0.5, 0.65])
    assert np.array_equal(family._relay(u, 0.6, 0.3, 0.0), [0, 0, 1, 1, 1, 0, 0, 1])
    assert np.array_equal(family._relay(u[3:5], 0.6, 0.3, 1.0), [1, 1])   # held from before


def test_the_cone_sensor_sets_its_shoe_only_while_the_acceleration_is_high():
    kin = _triangle()
    F = family.cone_sensor_brake_truth.__wrapped__(kin, 1.0)
    F0 = family.cone_sensor_brake_truth.__wrapped__(kin, 0.0)
    Fc = float(kin.base.params.Fc)
    d = F - F0
    assert np.all(np.isfinite(F)) and np.all(d * kin.v >= -1e-12 * Fc)  # a drag
    steady = (kin.t > 0.05) & (kin.t < 0.15)                           # no acceleration
    assert np.max(np.abs(d[steady])) < 1e-6 * Fc
    # braking into the reversal and speeding up out of it: the shoe is set
    turn = (kin.t > 0.19) & (kin.t < 0.21)
    assert np.max(np.abs(d[turn])) > 0.5 * family.CONE_DRAG * Fc


def test_the_pins_contact_arc_widens_with_the_load_and_its_friction_grows_faster():
    assert np.isclose(family._contact_arc(np.array([1.0]), 1.0)[0], np.pi / 2)
    f = family._arc_factor(np.array([0.0, 1e-3, 0.1, np.pi / 2, np.pi - 1e-9]))
    assert f[0] == 1.0 and np.isclose(f[1], 1.0) and np.isclose(f[2], 1.0 + 0.01 / 10.0,
                                                                 rtol=1e-4)
    assert np.isclose(f[3], 4.0 / np.pi) and np.isclose(f[4], 2.0, rtol=1e-6)
    # continuous where the series takes over
    assert np.isclose(family._arc_factor(np.array([0.0100001]))[0],
                      family._arc_factor(np.array([0.0099999]))[0], rtol=1e-7)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    F = family.pin_in_bore_truth.__wrapped__(fk, 1.0)
    F0 = family.pin_in_bore_truth.__wrapped__(fk, 0.0)
    assert np.all(np.isfinite(F)) and np.max(np.abs(F - F0)) > 0.0


def test_the_valve_resists_inward_at_its_setting_until_the_pilot_has_built_up():
    v = np.array([1.0, -1.0, -1.0, -0.5])
    r = family._valve_resistance(v, np.array([0.0, 0.0, 1.0, 1.0]), 1.0, 1.5, 0.15, 0.5, 1e-6)
    assert np.isclose(r[0], 0.15)                                      # the check's cracking
    assert np.isclose(r[1], -1.5 * 2.5) and np.isclose(r[2], -1.5)     # pilot: 2.5 x lower
    assert np.isclose(r[3], -1.25)                                     # the override
    kin = _triangle()
    d = family.counterbalance_valve_truth.__wrapped__(kin, 1.0) - \
        family.counterbalance_valve_truth.__wrapped__(kin, 0.0)
    hold = family.VALVE_HOLD * float(kin.base.params.Fc)
    up = (kin.t > 0.1) & (kin.t < 0.19)
    assert np.allclose(d[up], family.VALVE_CHECK * hold, rtol=1e-6)
    # moving in: the piloted holding resistance with its override, more just after the turn
    down = (kin.t > 0.3) & (kin.t < 0.35)
    assert np.allclose(d[down], -hold * (1.0 + family.VALVE_OVERRIDE), rtol=1e-3)
    # just after the turn (slow, the pilot not yet up) more than at full speed later
    early = (kin.t > 0.2) & (kin.t < 0.2003)
    assert d[early].min() < -1.02 * (1.0 + family.VALVE_OVERRIDE) * hold


def test_the_pad_takes_off_at_one_speed_and_lands_at_a_lower_one():
    t = np.linspace(0.0, 2.0, 2001)
    v = 0.01 * np.sin(np.pi * t / 2.0)                                 # up to 0.01, back to 0
    kin = _triangle()
    kin = PlantKinematics(kin.plant, t, np.cumsum(v) * 1e-3, v, np.gradient(v, t),
                          np.full(t.size, 100.0), kin.base, kin.seed_law, "arch", step=FINE)
    lift = family._relay(np.abs(v) / 0.01, family.PAD_TAKEOFF, family.PAD_TOUCHDOWN, 0.0)
    rising, falling = (t < 1.0) & (np.abs(v) > 0.3e-2) & (np.abs(v) < 0.45e-2), \
        (t > 1.0) & (np.abs(v) > 0.3e-2) & (np.abs(v) < 0.45e-2)
    assert np.all(lift[rising] == 0.0) and np.all(lift[falling] == 1.0)
    F = family.flying_pad_truth.__wrapped__(kin, 1.0)
    F0 = family.flying_pad_truth.__wrapped__(kin, 0.0)
    # at the same speeds: the base's levels speeding up, relieved slowing down
    assert np.all(np.isfinite(F))
    i, j = np.flatnonzero(rising)[-1], np.flatnonzero(falling)[0]
    assert abs(F[i] - F0[i]) < 1e-3 * abs(F0[i])
    assert F[j] < F0[j] - 0.5 * family.PAD_SHARE * float(kin.base.g(np.array([v[j]]))[0])


def test_the_flow_force_centres_the_spool_past_its_overlap():
    c = family._jet_cosine(np.array([0.0, 1e6]), 1.0)
    assert np.isclose(c[0], np.cos(np.radians(21.0))) and np.isclose(c[1], np.cos(np.radians(
        69.0)), rtol=1e-4)
    kin = plant_kinematics("valve", quick=True)
    fk = fine_kinematics(kin)
    d = family.spool_flow_force_truth.__wrapped__(fk, 1.0) - \
        family.spool_flow_force_truth.__wrapped__(fk, 0.0)
    from diagnosis.benchmark.truths import _bump_centre
    x0 = _bump_centre(fk)
    stroke = float(np.ptp(fk.x))
    e = fk.x - x0
    inside = np.abs(e) < (family.FLOW_LAP - 4 * family.FLOW_ROUND) * stroke
    outside = np.abs(e) > (family.FLOW_LAP + 4 * family.FLOW_ROUND) * stroke
    Fc = float(kin.base.params.Fc)
    assert inside.any() and outside.any()
    assert np.max(np.abs(d[inside])) < 1e-2 * family.FLOW_PUSH * Fc
    assert np.all(d[outside] * e[outside] > 0.0)                       # towards the null
    # a force of the position alone: the same at the same position both ways
    k = np.argsort(fk.x)
    assert np.all(np.diff(d[k]) >= -1e-9 * Fc)


def test_the_springs_coils_carry_a_third_of_its_mass_and_ring_after_a_step():
    m_s, w1, h = 3.0, 10.0, 1e-3
    a = np.concatenate([np.zeros(100), np.full(20000, 2.0)])
    out = family._surge_force(a, h, 4, m_s, w1, 0.05, 8)
    assert np.isclose(out[-1], m_s * 2.0 / 3.0, rtol=1e-3)            # Rayleigh's third
    assert out[:100].max() == 0.0
    assert out[100:1000].max() > 1.05 * m_s * 2.0 / 3.0                # ringing
    kin = plant_kinematics("xml350", quick=True)
    d = family.spring_surge_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.max(np.abs(d)) > 0.0


def test_the_core_lags_a_ramp_by_a_third_of_its_diffusion_time():
    w, taus = family._diffusion_modes(1.0, 2000)
    assert np.isclose(w.sum(), 1.0, atol=1e-3) and np.isclose(np.sum(w * taus), 1.0 / 3.0)
    t = np.linspace(0.0, 20.0, 200001)
    y = family._diffused(t, t.copy(), 0.9, family.CELL_MODES)
    assert np.isclose(t[-1] - y[-1], 0.3, rtol=2e-3)                   # tau / 3
    assert np.allclose(family._diffused(t, np.full(t.size, 2.0), 0.9, 60), 2.0)
    step = np.where(t < 1.0, 0.0, 1.0)
    ys = family._diffused(t, step, 0.9, family.CELL_MODES)
    assert np.all(np.diff(ys) >= -1e-12) and ys.max() <= 1.0 + 1e-9    # no overshoot
    kin = plant_kinematics("xml350", quick=True)
    d = family.magnetoelastic_cell_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.max(np.abs(d)) > 0.0


def test_the_receiver_drains_with_the_travel_and_refills_in_time():
    t = np.linspace(0.0, 3.0, 3001)
    p = family._receiver(t, np.ones(t.size), 1.0, 10.0)
    assert p[0] == 1.0 and np.isclose(p[500], 0.5)                     # drained by the travel
    k0 = int(np.argmax(p <= 0.0))
    assert np.isclose(t[k0], 1.0, atol=2e-3)                           # the cut-in
    assert np.isclose(p[k0 + 100], 0.9, atol=2e-2)                     # refilling at 10 - 1
    still = family._receiver(t, np.zeros(t.size), 1.0, 10.0)
    assert np.all(still == 1.0)                                        # no travel, no drain
    kin = _triangle()
    F = family.receiver_pressure_truth.__wrapped__(kin, 1.0)
    F0 = family.receiver_pressure_truth.__wrapped__(kin, 0.0)
    assert np.all(np.isfinite(F)) and np.max(np.abs(F - F0)) > 0.0


def test_the_overlapped_spool_takes_up_the_lead_at_a_rate():
    h = 1e-4
    t = h * np.arange(20001)
    xd = 0.01 * t                                                      # a ramp from rest
    v = family._overlapped_follower(xd, h, 1e-4, 50.0)
    assert np.all(v[t < 0.0099] == 0.0)                                # within the overlap
    assert np.isclose(v[-1], 0.01, rtol=1e-3)                          # following, lagged
    kin = _triangle()
    Fc = float(kin.base.params.Fc)
    turn = []
    for s in (0.0, 1.0, 2.0):
        F = family.overlapped_servo_truth.__wrapped__(kin, s)
        assert np.all(np.isfinite(F))
        after = np.flatnonzero((kin.t > 0.2) & (F < -0.9 * Fc))
        turn.append(kin.t[after[0]])
    assert turn[0] < turn[1] < turn[2]


def test_the_rolling_contacts_are_renewed_within_their_width():
    assert family._renewal_share(0.0) == 0.0 and np.isclose(family._renewal_share(1.0), 1.0)
    assert np.isclose(family._renewal_share(0.5), 0.5)
    x = np.concatenate([np.linspace(0.0, 2.0, 20001), np.linspace(2.0, 0.0, 20001)[1:]])
    f = family._renewed(x, 1.0)
    assert f[0] == 0.0 and np.isclose(f[5000], family._renewal_share(0.5))
    assert np.allclose(f[10000:20001], 1.0)                            # renewed
    assert np.isclose(f[20000 + 5000], 0.0, atol=1e-3)                 # half way back: 0
    assert np.allclose(f[30000:], -1.0)                                # and renewed again
    # a short stroke back is forgotten once the contact has rolled its width on
    y = np.concatenate([np.linspace(0.0, 2.0, 2001), np.linspace(2.0, 1.8, 201)[1:],
                        np.linspace(1.8, 3.0, 1201)[1:]])
    g = family._renewed(y, 1.0)
    assert np.isclose(g[2200], 1.0 - 2.0 * family._renewal_share(0.2), rtol=1e-3)
    assert np.isclose(g[-1], 1.0)
    kin = plant_kinematics("valve", quick=True)
    assert np.all(np.isfinite(family.contact_renewal_truth(kin, 1.0)))


@pytest.mark.slow
def test_seen21_forms_reach_their_size_on_every_plant():
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
