"""The twenty-second seen truth family (diagnosis.benchmark.seen22, sealed in session 26, run
once on 72892bf, 48.9 % top-1, now open): each form builds a finite case of the requested
size on every plant it applies to, is the base law at s = 0, grows with its amplitude factor
and refuses the plants it does not apply to."""
import dataclasses

import numpy as np
import pytest

from diagnosis.benchmark import EFFECT_SIZE, PLANT_NAMES, make_plant_case, plant_kinematics
from diagnosis.benchmark import seen22 as family
from diagnosis.benchmark.kinematics import FINE, PlantKinematics, fine_kinematics
from diagnosis.benchmark.runner import MIN_SIZE
from diagnosis.benchmark.truths import base_force

#: the family's form of each effect
FORM = {"acceleration": "inertia_valve_damper", "load": "ball_spin",
        "asymmetry": "elliptic_vibration", "stribeck_shape": "wiping_meniscus",
        "position": "crank_transmission", "inertia": "rolling_payload",
        "delay": "quartz_counter", "drift": "spall_growth",
        "backlash": "side_loaded_pin", "gms": "grease_yield"}
#: a plant each form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s)
PLANT = {effect: "xml350" for effect in FORM}


def test_seen22_forms_refuse_plants_they_do_not_apply_to():
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        family.wiping_meniscus_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.grease_yield_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.side_loaded_pin_truth(iso, 1.0)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    # a one-way stroke (the press's) never comes back over the positions the fit part saw
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        family.crank_transmission_truth.__wrapped__(one_way, 1.0)
    # a load that never changes cannot show the drag's growth with the load
    still = dataclasses.replace(fk, load=np.full(fk.t.size, 100.0))
    with pytest.raises(ValueError, match="does not change"):
        family.ball_spin_truth.__wrapped__(still, 1.0)


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


def test_the_poppet_moves_only_past_its_preload_and_the_damper_drags_then():
    h, n = 1e-3, 20001
    below = family._poppet(np.full(n, 0.3), h, 0.5, 10.0, 0.7)
    assert np.all(below == 0.0)
    above = family._poppet(np.full(n, 2.0), h, 0.5, 10.0, 0.7)
    assert np.isclose(above[-1], 1.5, rtol=1e-3)                       # beyond the preload
    assert np.allclose(family._poppet(-np.full(n, 2.0), h, 0.5, 10.0, 0.7), -above)
    kin = _triangle()
    F = family.inertia_valve_damper_truth.__wrapped__(kin, 1.0)
    F0 = family.inertia_valve_damper_truth.__wrapped__(kin, 0.0)
    Fc = float(kin.base.params.Fc)
    steady = (kin.t > 0.1) & (kin.t < 0.19)                            # the valve open again
    assert np.max(np.abs(F[steady] - F0[steady])) < 1e-6 * Fc
    assert np.all((F - F0) * kin.v >= -1e-12 * Fc)                     # a drag
    assert np.max(np.abs(F - F0)) > 0.01 * Fc


def test_the_spin_drag_grows_faster_than_the_load_to_the_4_3():
    d = family._spin_drag(np.array([0.5, 1.0, -1.0, 0.0]), 1.0)
    assert np.isclose(d[1], 1.0) and d[2] == d[1] and d[3] == 0.0
    assert d[1] / d[0] > 2.0 ** (4.0 / 3.0)                            # the angle opens
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    F = family.ball_spin_truth.__wrapped__(fk, 1.0)
    F0 = family.ball_spin_truth.__wrapped__(fk, 0.0)
    assert np.all(np.isfinite(F)) and np.max(np.abs(F - F0)) > 0.0


def test_the_vibrated_way_drives_the_carriage_one_way_below_its_speed():
    u = np.array([-2.0, -0.5, 0.0, 0.5, 2.0])
    f = family._vibrated_friction(u, 0.8, 60.0)
    assert f[0] == -1.0 and f[4] == 1.0                                # above it: none
    assert abs(f[2]) > 0.05                                            # pushes at rest
    assert not np.isclose(f[3], -f[1], rtol=0.05)                      # uneven
    assert np.allclose(family._vibrated_friction(u, 0.0, 60.0)[1:4],
                       [-1.0 / 3.0, 0.0, 1.0 / 3.0], atol=2e-3)        # no swing: even
    kin = plant_kinematics("valve", quick=True)
    d = family.elliptic_vibration_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.max(np.abs(d)) > 0.0
    fast = np.abs(kin.v) > 2.0 * family.VIB_SPEED * kin.scales["v99"]
    assert np.max(np.abs(d[fast])) < 1e-6 * float(kin.base.params.Fc)


def test_the_meniscus_drag_grows_as_the_speed_to_the_2_3():
    u = np.array([0.1, 0.8, 1.0, -1.0, 0.0])
    d = family._meniscus_drag(u, 1e-5)
    assert np.isclose(d[2], 1.0) and d[3] == -d[2] and d[4] == 0.0
    assert np.isclose(d[1] / d[0], 4.0, rtol=2e-3)                     # 8^(2/3)
    kin = plant_kinematics("valve", quick=True)
    d = family.wiping_meniscus_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.all(d * kin.v >= 0.0)
    assert np.max(np.abs(d)) > 0.0


def test_the_crank_passes_less_travel_per_angle_towards_its_dead_centres():
    r = 1.0
    x = np.array([-0.9, -0.5, 0.0, 0.5, 0.9])
    lever = family._crank_lever(x, r, 0.3)
    assert lever[0] < lever[1] < lever[2] and lever[4] < lever[3] < lever[2]
    assert not np.isclose(lever[0], lever[4], rtol=1e-2)               # the rod's obliquity
    assert 0.9 < lever[2] < 1.1                                        # about r per radian
    kin = plant_kinematics("valve", quick=True)
    d = family.crank_transmission_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.all(d * kin.v >= 0.0) and np.max(np.abs(d)) > 0.0


def test_the_rolling_payload_is_whole_when_slow_and_a_third_when_fast():
    h, n, w = 1e-4, 400001, 2.0 * np.pi
    slow = family._rolling_force(np.full(n, 1.0), h, w, 0.15)
    assert np.isclose(slow[-1], 1.0, rtol=1e-3)                        # the whole mass
    t = h * np.arange(n)
    fast = family._rolling_force(np.sin(2.0 * np.pi * 30.0 * t), h, w, 0.15)
    assert np.isclose(np.max(np.abs(fast[n // 2:])), 1.0 / 3.0, rtol=0.03)
    kin = plant_kinematics("xml350", quick=True)
    d = family.rolling_payload_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.max(np.abs(d)) > 0.0


def test_the_counter_reports_the_gate_mean_at_the_gates_end():
    t = np.linspace(0.0, 1.0, 1001)
    m = family._gate_mean(t, 2.0 * t, 0.1)
    late = t >= 0.1
    assert np.allclose(m[late], 2.0 * (t[late] - 0.05))                # half a gate late
    assert m[0] == 0.0
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    F0 = family.quartz_counter_truth.__wrapped__(fk, 0.0)
    F = family.quartz_counter_truth.__wrapped__(fk, 1.0)
    assert np.all(np.isfinite(F)) and np.max(np.abs(F - F0)) > 0.0
    # a steady force reads true: the conversion inverts the resonator's law
    still = dataclasses.replace(fk, v=np.zeros_like(fk.v))
    Fs = family.quartz_counter_truth.__wrapped__(still, 1.0)
    Fs0 = family.quartz_counter_truth.__wrapped__(still, 0.0)
    assert np.allclose(Fs, Fs0, atol=1e-9 * (np.max(np.abs(Fs0)) + 1.0))


def test_the_spall_grows_ever_faster_with_the_overrollings():
    n = np.linspace(0.0, 1.0, 101)
    a = family._spall_area(n, 6.0)
    assert a[0] == 1.0 and np.isclose(a[-1], 6.0)
    assert np.all(np.diff(a) > 0.0) and np.all(np.diff(a, 2) > 0.0)    # accelerating
    kin = _triangle()
    F = family.spall_growth_truth.__wrapped__(kin, 1.0)
    F0 = family.spall_growth_truth.__wrapped__(kin, 0.0)
    Fc = float(kin.base.params.Fc)
    end = (kin.t > 0.37) & (kin.t < 0.39)
    rise = np.abs(F[end]) - np.abs(F0[end])
    assert np.all(rise > 0.0) and np.all(rise <= family.SPALL_RISE * 1.05 * float(
        kin.base.params.Fs))
    assert np.max(np.abs(F[kin.t < 0.01] - F0[kin.t < 0.01])) < 0.05 * Fc


def test_the_pin_takes_up_the_play_later_the_wider_and_the_lighter_it_is(monkeypatch):
    kin = _triangle()
    Fc = float(kin.base.params.Fc)

    def turn(s):
        F = family.side_loaded_pin_truth.__wrapped__(kin, s)
        assert np.all(np.isfinite(F))
        after = np.flatnonzero((kin.t > 0.2) & (F < -0.9 * Fc))
        return kin.t[after[0]]
    times = [turn(s) for s in (0.0, 1.0, 2.0)]
    assert times[0] < times[1] < times[2]
    monkeypatch.setattr(family, "PIN_WEIGHT", 0.5 * family.PIN_WEIGHT)
    assert turn(2.0) > times[2]                                        # rolls further


def test_the_grease_holds_below_its_yield_and_flows_as_a_power_above_it():
    path, y, n_index = 1e-4, 0.7, 0.5
    t = np.linspace(0.0, 2.0, 20001)
    v = np.where(t < 1.0, 1.0, 0.0)
    u = family._grease_layer(t, v, path, 1.0, y, n_index)
    assert np.isclose(u[9999], 1.0, rtol=1e-3)                         # steady at v_top
    rest = u[10001:]
    assert np.all(rest >= y - 1e-9) and np.all(np.diff(rest) <= 1e-12)  # flows off to y
    v2 = np.where(t < 1.0, 0.25, 0.0)
    u2 = family._grease_layer(t, v2, path, 1.0, y, n_index)
    assert np.isclose(u2[9999], y + (1.0 - y) * 0.25 ** n_index, rtol=1e-3)
    # a small stroke below the yield is elastic: back to where it started
    x = np.concatenate([np.linspace(0, 0.3 * path, 1001), np.linspace(0.3 * path, 0, 1001)[1:]])
    tt = np.linspace(0.0, 1.0, x.size)
    g = family._grease_layer(tt, np.gradient(x, tt), path, 1.0, y, n_index)
    assert np.isclose(np.max(g), 0.3, rtol=1e-2) and abs(g[-1]) < 1e-2
    # and a stress below the yield, held at rest, stays: no creep
    x = np.concatenate([np.linspace(0, 0.3 * path, 1001), np.full(1000, 0.3 * path)])
    g = family._grease_layer(tt, np.gradient(x, tt), path, 1.0, y, n_index)
    assert np.ptp(g[1010:]) < 1e-9 and np.isclose(g[-1], 0.3, rtol=1e-2)
    kin = plant_kinematics("valve", quick=True)
    assert np.all(np.isfinite(family.grease_yield_truth(kin, 1.0)))


@pytest.mark.slow
def test_seen22_forms_reach_their_size_on_every_plant():
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
