"""The twentieth seen truth family (diagnosis.benchmark.seen20, sealed in session 24, run
once on 5ac3afd, 50.0 % top-1, now open): each form builds a finite case of the requested
size on every plant it applies to, is the base law at s = 0, grows with its amplitude factor
and refuses the plants it does not apply to."""
import dataclasses

import numpy as np
import pytest

from diagnosis.benchmark import EFFECT_SIZE, PLANT_NAMES, make_plant_case, plant_kinematics
from diagnosis.benchmark import seen20 as family
from diagnosis.benchmark.kinematics import FINE, PlantKinematics, fine_kinematics
from diagnosis.benchmark.runner import MIN_SIZE
from diagnosis.benchmark.truths import base_force

#: the family's form of each effect
FORM = {"acceleration": "rack_flank_sliding", "load": "heathcote_slip",
        "asymmetry": "sealing_band", "stribeck_shape": "shear_thinning_oil",
        "position": "rail_misalignment", "inertia": "friction_damped_mount",
        "delay": "magnetostrictive_wire", "drift": "grease_channelling",
        "backlash": "wedge_flank", "gms": "microslip_bar"}
#: a plant each form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s)
PLANT = {effect: "xml350" for effect in FORM}
def test_seen20_forms_refuse_plants_they_do_not_apply_to():
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        family.shear_thinning_oil_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.microslip_bar_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.wedge_flank_truth(iso, 1.0)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    # a one-way stroke (the press's) never comes back over the positions the fit part saw
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        family.rail_misalignment_truth.__wrapped__(one_way, 1.0)
    # a load that never changes cannot show the drag's growth with the load
    still = dataclasses.replace(fk, load=np.full(fk.t.size, 100.0))
    with pytest.raises(ValueError, match="does not change"):
        family.heathcote_slip_truth.__wrapped__(still, 1.0)


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




def test_the_flanks_slide_most_at_the_ends_of_the_path_of_contact_under_acceleration():
    x = np.array([0.0, 0.25, 0.5, 1.0, 1.5, 2.25])
    r = family._sliding_ratio(x, 1.0, 0.0)
    assert np.allclose(r, [0.0, 0.5, 1.0, 0.0, 1.0, 0.5])             # 0 at the pitch point
    kin = _triangle()
    F = family.rack_flank_sliding_truth.__wrapped__(kin, 1.0)
    F0 = family.rack_flank_sliding_truth.__wrapped__(kin, 0.0)
    Fc = float(kin.base.params.Fc)
    steady = (kin.t > 0.05) & (kin.t < 0.15)                           # no acceleration
    assert np.max(np.abs(F[steady] - F0[steady])) < 1e-6 * Fc
    # speeding up from the start: the levels are higher, never lower
    start = (kin.t > 0.001) & (kin.t < 0.01)
    assert np.all(np.abs(F[start]) >= np.abs(F0[start]) - 1e-9 * Fc)
    assert np.max(np.abs(F[start]) - np.abs(F0[start])) > 0.05 * Fc


def test_the_differential_slip_drag_grows_as_the_load_to_the_5_3():
    d = family._heathcote_drag(np.array([1.0, 2.0, -2.0, 4.0]), 4.0)
    assert np.isclose(d[1] / d[0], 2.0 ** (5.0 / 3.0)) and d[2] == d[1] and d[3] == 1.0
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    F = family.heathcote_slip_truth.__wrapped__(fk, 1.0)
    F0 = family.heathcote_slip_truth.__wrapped__(fk, 0.0)
    assert np.all(np.isfinite(F)) and np.max(np.abs(F - F0)) > 0.0


def test_the_band_pulls_harder_away_from_its_spring_than_towards_it():
    v = np.array([0.0, 1.0, -1.0, 1e-3, -1e-3])
    r = family._band_tension(v, 0.5, 0.6, 0.05, 1e-5)
    assert r[0] == 1.0
    assert np.isclose(r[1], np.exp(0.5)) and np.isclose(r[2], np.exp(-0.5))
    # slow sliding: the band's static friction, a larger ratio both ways
    assert np.isclose(r[3], np.exp(0.5 * 1.6), rtol=1e-3)
    assert np.isclose(r[4], np.exp(-0.5 * 1.6), rtol=1e-3)
    kin = _triangle()
    d = family.sealing_band_truth.__wrapped__(kin, 1.0) - \
        family.sealing_band_truth.__wrapped__(kin, 0.0)
    T0 = family.BAND_TENSION * float(kin.base.params.Fc)
    up, down = (kin.t > 0.1) & (kin.t < 0.19), (kin.t > 0.3) & (kin.t < 0.39)
    assert np.allclose(d[up], T0 * np.exp(family.BAND_WRAP), rtol=1e-6)
    assert np.allclose(d[down], T0 * np.exp(-family.BAND_WRAP), rtol=1e-6)


def test_the_thinning_film_is_viscous_at_low_speed_and_bends_over_above_it():
    u = np.array([0.0, 1e-6, 2e-6, 1e3, 2e3])
    q = family._cross_drag(u, 1.0, 0.8, 0.15)
    assert q[0] == 0.0 and np.isclose(q[2] / q[1], 2.0, rtol=1e-4)     # viscous at rest
    assert np.isclose((q[4] - q[3]) / 1e3, 0.15, rtol=0.05)            # the thinned slope
    assert np.allclose(family._cross_drag(-u, 1.0, 0.8, 0.15), -q)
    assert np.all(np.diff(family._cross_drag(np.linspace(0, 50, 501), 1.0, 0.8, 0.15)) > 0)
    kin = plant_kinematics("valve", quick=True)
    d = family.shear_thinning_oil_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.max(np.abs(d)) > 0.0
    assert np.all(d * kin.v >= 0.0)                                    # a drag


def test_the_misfit_starts_at_the_fitting_point_and_grows_linearly():
    x = np.linspace(-1.0, 3.0, 4001)
    m = family._misfit(x, 0.0, 2.0, 1e-6)
    assert np.allclose(m[x < -0.01], 0.0, atol=1e-6)
    assert np.allclose(m[x > 0.01], x[x > 0.01] / 2.0, atol=1e-6)
    kin = plant_kinematics("valve", quick=True)
    d = family.rail_misalignment_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.max(np.abs(d)) > 0.0


def test_the_mount_carries_the_payload_whole_until_its_damper_slips():
    m, T = 2.0, 1.0
    h, n = 1e-3, 20001
    w_pad = 25.0 / T
    args = (m, m * (2.0 / T) ** 2, m * w_pad ** 2, 2.0 * 0.05 * m * w_pad, 1.0)
    # a steady acceleration the damper holds: the whole mass, m a
    a = np.full(n, 0.3)
    out = family._mount_force(a, h, 4, *args)
    assert np.isclose(out[-1], m * 0.3, rtol=1e-3)
    # one it cannot: the pad slips, the force lags m a before the spring takes it up
    a = np.full(n, 2.0)
    out = family._mount_force(a, h, 4, *args)
    k = int(0.2 / h)
    assert out[k] < 0.8 * m * 2.0 and np.isclose(out[-1], m * 2.0, rtol=1e-3)
    kin = plant_kinematics("xml350", quick=True)
    d = family.friction_damped_mount_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.max(np.abs(d)) > 0.0


def test_the_wire_delays_the_motion_by_the_magnets_distance_from_the_head():
    tau = family._flight_time(np.array([0.0, 0.5, 1.0, 2.0]), 0.0, 2.0, 4e-3)
    assert np.allclose(tau, [0.0, 1e-3, 2e-3, 4e-3])
    from scipy.interpolate import CubicSpline
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    F = family.magnetostrictive_wire_truth.__wrapped__(fk, 1.0)
    F0 = family.magnetostrictive_wire_truth.__wrapped__(fk, 0.0)
    sc = fk.scales
    tau = family._flight_time(fk.x, sc["x_lo"], sc["x_hi"] - sc["x_lo"],
                              family.WIRE_SAMPLES * fk.sample_dt)
    assert np.allclose(F, CubicSpline(fk.t, F0)(np.clip(fk.t + tau, None, fk.t[-1])))
    head = np.abs(fk.x - sc["x_lo"]) < 1e-12 * (sc["x_hi"] - sc["x_lo"])
    assert np.allclose(F[head], F0[head])                              # no lag at the head


def test_the_grease_is_channelled_at_each_reversal():
    v = np.array([0.0, 1.0, 1.0, 1e-4, -1e-4, -1.0, -1.0, 0.0, 1.0, 1.0])
    assert np.array_equal(family._reversal_count(v, 1e-3),
                          [0, 0, 0, 0, 0, 1, 1, 1, 2, 2])
    t = np.linspace(0.0, 1.0, 1001)
    count = np.where(t < 0.5, 0.0, 1.0)
    share = family._starved_share(t, count, 2.0, 1.5, 1e-3)
    assert np.all(share[t < 0.5] == 0.0)
    assert np.isclose(share[-1], 1.0 - np.exp(-0.75), rtol=1e-6)
    kin = _triangle()
    F = family.grease_channelling_truth.__wrapped__(kin, 1.0)
    F0 = family.grease_channelling_truth.__wrapped__(kin, 0.0)
    Fc = float(kin.base.params.Fc)
    before = kin.t < 0.2                                               # no reversal yet
    assert np.max(np.abs(F[before] - F0[before])) < 1e-9 * Fc
    late = (kin.t > 0.3) & (kin.t < 0.39)                              # one of one: 1 - e^-1.5
    rise = np.abs(F[late]) - np.abs(F0[late])
    assert np.allclose(rise, family.CHANNEL_RISE * (1.0 - np.exp(-family.CHANNEL_FOLDS)) * Fc,
                       rtol=0.02)


def test_the_wedge_takes_up_the_play_later_the_wider_it_is(monkeypatch):
    kin = _triangle()
    Fc = float(kin.base.params.Fc)
    turn = []
    for s in (0.0, 1.0, 2.0):
        F = family.wedge_flank_truth.__wrapped__(kin, s)
        assert np.all(np.isfinite(F))
        after = np.flatnonzero((kin.t > 0.2) & (F < -0.9 * Fc))
        turn.append(kin.t[after[0]])
    assert turn[0] < turn[1] < turn[2]
    # the flank friction changes the take-up
    F1 = family.wedge_flank_truth.__wrapped__(kin, 2.0)
    monkeypatch.setattr(family, "WEDGE_FRICTION", 0.0)
    F2 = family.wedge_flank_truth.__wrapped__(kin, 2.0)
    assert np.max(np.abs(F1 - F2)) > 1e-3 * Fc


def test_the_bar_slips_as_the_square_root_of_its_travel_and_unloads_by_masing():
    x = np.concatenate([np.linspace(0.0, 2.0, 20001), np.linspace(2.0, -2.0, 40001)[1:]])
    f = family._microslip(x, 1.0)
    assert f[0] == 0.0
    assert np.isclose(f[2500], 0.5) and np.isclose(f[10000], 1.0)      # sqrt(x): 0.25 -> 0.5
    assert np.all(f[10000:20001] == 1.0)                               # full slip
    back = f[20001:]
    # from full slip, back along twice the backbone: 1 - 2 sqrt(d / 2)
    k = 5000                                                           # 0.5 of travel back
    assert np.isclose(back[k - 1], 1.0 - 2.0 * np.sqrt(0.25), rtol=1e-3)
    assert np.isclose(f[-1], -1.0) and np.all(np.diff(back) <= 0.0)
    kin = plant_kinematics("valve", quick=True)
    assert np.all(np.isfinite(family.microslip_bar_truth(kin, 1.0)))


@pytest.mark.slow
def test_seen20_forms_reach_their_size_on_every_plant():
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
