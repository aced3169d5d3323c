"""The twenty-fifth seen truth family (diagnosis.benchmark.seen25, sealed in session 29, run
once on de40d49, 46.0 % top-1, now open): each form builds a finite case of the requested
size on every plant it applies to, is the base law at s = 0, grows with its amplitude factor
and refuses the plants it does not apply to."""
import dataclasses

import numpy as np
import pytest

from diagnosis.benchmark import EFFECT_SIZE, PLANT_NAMES, make_plant_case, plant_kinematics
from diagnosis.benchmark import seen25 as family
from diagnosis.benchmark.kinematics import FINE, PlantKinematics, fine_kinematics
from diagnosis.benchmark.runner import MIN_SIZE
from diagnosis.benchmark.truths import base_force

#: the family's form of each effect
FORM = {"acceleration": "band_capstan", "load": "constant_flow_pad",
        "asymmetry": "roller_skew", "stribeck_shape": "thermal_closure",
        "position": "cable_reel", "inertia": "oil_column",
        "delay": "interleaved_adc", "drift": "additive_settling",
        "backlash": "adhesive_flank", "gms": "viscoplastic_overstress"}
#: a plant each form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s)
PLANT = {effect: "xml350" for effect in FORM}


def test_seen25_forms_refuse_plants_they_do_not_apply_to():
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        family.thermal_closure_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.viscoplastic_overstress_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.adhesive_flank_truth(iso, 1.0)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    # a one-way stroke (the press's) never comes back over the positions the fit part saw
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        family.cable_reel_truth.__wrapped__(one_way, 1.0)
    # a load that never changes never moves the pads' gap
    still = dataclasses.replace(fk, load=np.full(fk.t.size, 100.0))
    with pytest.raises(ValueError, match="does not change"):
        family.constant_flow_pad_truth.__wrapped__(still, 1.0)


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


def test_the_band_tightens_with_the_acceleration_along_the_motion_and_goes_slack():
    T = family._band_tension(np.array([0.0, 1.0, -1.0, -1.0]),
                             np.array([1.0, 1.0, 1.0, -1.0]), 0.5, 1e-6)
    assert np.allclose(T, [0.5, 1.5, 0.0, 1.5], atol=1e-5)         # slack, then both ways
    kin = _triangle()
    F = family.band_capstan_truth.__wrapped__(kin, 1.0)
    F0 = family.band_capstan_truth.__wrapped__(kin, 0.0)
    steady = (kin.t > 0.1) & (kin.t < 0.18)                          # no acceleration
    assert np.allclose(F[steady], F0[steady], rtol=1e-6, atol=1e-9)
    assert np.all(np.isfinite(F)) and np.max(np.abs(F - F0)) > 0.0


def test_the_pads_drag_grows_as_the_cube_root_of_the_load():
    d = family._pad_gap_drag(np.array([1.0, 8.0, -8.0, 0.0]), 1e-9)
    assert np.allclose(d[:3], [1.0, 2.0, 2.0]) and d[3] < 1e-2
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    F = family.constant_flow_pad_truth.__wrapped__(fk, 1.0)
    F0 = family.constant_flow_pad_truth.__wrapped__(fk, 0.0)
    d = F - F0
    assert np.all(np.isfinite(F)) and np.max(np.abs(d)) > 0.0
    # a drag: along the motion above the mean load, against it below
    Lm = np.mean(np.abs(fk.load))
    moving = np.abs(fk.v) > 0.3 * fk.scales["v99"]
    heavy = moving & (np.abs(fk.load) > 1.2 * Lm)
    light = moving & (np.abs(fk.load) < 0.8 * Lm)
    assert np.all(d[heavy] * fk.v[heavy] > 0.0) and np.all(d[light] * fk.v[light] < 0.0)


def test_the_rollers_settle_to_a_skew_that_differs_by_direction():
    n = 2001
    dx = np.full(n, 1e-3)
    up = family._skew(dx, np.ones(n), -0.25, 0.05)
    down = family._skew(dx, -np.ones(n), -0.25, 0.05)
    assert np.allclose(up, 1.0) and np.isclose(down[-1], -0.25)
    assert np.isclose(down[50], -0.25 + 1.25 * np.exp(-1.0), rtol=1e-6)   # over the travel
    kin = _triangle()
    F = family.roller_skew_truth.__wrapped__(kin, 1.0)
    F0 = family.roller_skew_truth.__wrapped__(kin, 0.0)
    up_t = (kin.t > 0.15) & (kin.t < 0.19)
    down_t = (kin.t > 0.35) & (kin.t < 0.39)
    r_up = np.median(np.abs(F[up_t]) / np.abs(F0[up_t]))
    r_down = np.median(np.abs(F[down_t]) / np.abs(F0[down_t]))
    assert r_up > r_down > 1.0


def test_the_bushings_drag_grows_faster_than_linear_with_the_speed():
    u = np.array([-1.0, 0.0, 0.1, 0.5, 1.0])
    d = family._closure_drag(u, 0.15)
    assert d[4] == 1.0 and d[0] == -1.0 and d[1] == 0.0
    assert d[3] / d[2] > 5.0 and d[4] / d[3] > 2.0                   # steeper than linear
    kin = plant_kinematics("valve", quick=True)
    d = family.thermal_closure_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.all(d * kin.v >= -1e-12) and np.max(np.abs(d)) > 0.0


def test_the_reel_pulls_more_and_drags_more_as_the_cable_pays_out():
    kin = plant_kinematics("valve", quick=True)
    d = family.cable_reel_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d))
    sc = kin.scales
    xr = (kin.x - sc["x_lo"]) / (sc["x_hi"] - sc["x_lo"])
    moving = np.abs(kin.v) > 0.5 * sc["v99"]
    near, far = moving & (xr < 0.2), moving & (xr > 0.8)
    assert np.median(np.abs(d[near])) < np.median(np.abs(d[far]))
    # pulled home in both directions, more while paying out (moving +x)
    assert np.all(d[far] > 0.0)
    assert np.median(d[far & (kin.v > 0)]) > np.median(d[far & (kin.v < 0)])


def test_the_oil_column_is_carried_whole_in_slow_motion_and_lags_in_quick():
    h, n = 1e-3, 40001
    t = h * np.arange(n)
    w = 10.0
    steady = family._column_force(np.full(n, 1.0), h, w, 2.0 * 0.3 * w * w)
    assert np.isclose(steady[-1], 1.0, rtol=2e-2)                     # the whole column
    quick = family._column_force(np.sin(2.0 * np.pi * 10.0 * w * t), h, w, 0.6 * w * w)
    assert np.max(np.abs(quick[n // 2:])) < 0.1                       # hardly any of it
    assert np.allclose(family._column_force(-np.full(n, 1.0), h, w, 0.6 * w * w), -steady)
    kin = plant_kinematics("xml350", quick=True)
    d = family.oil_column_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.max(np.abs(d)) > 0.0


def test_every_other_sample_is_read_late():
    t = np.arange(101) * 0.1
    F = t.copy()
    out = family._interleave(t, F, 10, 0.25)
    samples = out[::10]
    assert np.allclose(samples[0::2], t[::10][0::2])                 # even ones on time
    assert np.allclose(samples[1::2], t[::10][1::2] - 0.25)          # odd ones late
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    F0 = family.interleaved_adc_truth.__wrapped__(fk, 0.0)
    F1 = family.interleaved_adc_truth.__wrapped__(fk, 1.0)
    d = (F1 - F0)[::fk.step]
    assert np.all(d[0::2] == 0.0) and np.max(np.abs(d[1::2])) > 0.0


def test_the_additive_settles_out_late_and_slowly():
    tau = np.linspace(0.0, 1.0, 10001)
    c = family._suspended(tau, 0.6, 0.35)
    assert np.isclose(c[0], 1.0) and np.all(np.diff(c) <= 0.0)
    assert c[1000] > 0.99 and np.isclose(c[6000], 0.5, atol=1e-3)    # a late onset
    kin = _triangle()
    F = family.additive_settling_truth.__wrapped__(kin, 1.0)
    F0 = family.additive_settling_truth.__wrapped__(kin, 0.0)
    Fs = float(kin.base.params.Fs)
    end = (kin.t > 0.37) & (kin.t < 0.39)
    rise = np.abs(F[end]) - np.abs(F0[end])
    assert np.all(rise > 0.0) and np.all(rise <= family.SETTLE_RISE * 1.05 * Fs)
    first = (kin.t > 0.05) & (kin.t < 0.08)
    assert np.max(np.abs(F[first] - F0[first])) < 0.1 * np.min(rise)


def test_the_flank_holds_the_contact_up_to_its_pull_off():
    f = family._flank_force
    assert f(0.0, 0.0, 1.0, 10.0, 0.0, 2.0, 0) == (0.0, 0)           # free in the play
    assert f(1.5, 0.0, 1.0, 10.0, 0.0, 2.0, 0) == (5.0, 1)           # touches, is held
    assert f(0.9, 0.0, 1.0, 10.0, 0.0, 2.0, 1) == (pytest.approx(-1.0), 1)   # pulled, held
    assert f(0.7, 0.0, 1.0, 10.0, 0.0, 2.0, 1) == (0.0, 0)           # past the pull-off
    assert f(-0.9, 0.0, 1.0, 10.0, 0.0, 2.0, -1) == (pytest.approx(1.0), -1)
    kin = _triangle()
    Fc = float(kin.base.params.Fc)
    F1 = family.adhesive_flank_truth.__wrapped__(kin, 1.0)
    F0 = family.adhesive_flank_truth.__wrapped__(kin, 0.0)
    assert np.all(np.isfinite(F1))
    # after the reversal the force turns over later than the base's, the play to cross

    def turn(F):
        return kin.t[np.flatnonzero((kin.t > 0.2) & (F < -0.9 * Fc))[0]]
    assert turn(F0) < turn(F1)


def test_the_layer_does_not_flow_below_its_yield_and_overshoots_it_with_the_speed():
    h, n = 1e-3, 20001
    t = h * np.arange(n)
    u = family._overstress_layer(t, np.where(t < 10.0, 1.0, 0.0), 1e-3, 1.0, 0.3, 2.0)
    assert np.isclose(u[9999], 1.3, rtol=1e-6)                        # steady at v_top
    rest = u[10001:]                                                  # at rest: relaxes
    assert np.all(np.diff(rest) <= 0.0) and np.all(rest >= 1.0) and rest[-1] < 1.0 + 1e-4
    slow = family._overstress_layer(t, np.where(t < 10.0, 0.25, 0.0), 1e-3, 1.0, 0.3, 2.0)
    assert np.isclose(slow[9999], 1.0 + 0.3 * 0.5, rtol=1e-6)         # (v / v_top)^(1/2)
    # below the yield the layer is elastic: its slope the path's
    x = np.concatenate([np.full(1000, 1.0), np.full(1000, -1.0)])
    tt = 1e-6 * np.arange(x.size)
    w = family._overstress_layer(tt, x, 1.0, 1.0, 0.3, 2.0)
    assert np.allclose(np.diff(w[:999]), 1e-6, rtol=1e-6)
    assert np.isclose(w[1001] - w[1000], -1e-6, rtol=1e-6)
    kin = plant_kinematics("valve", quick=True)
    assert np.all(np.isfinite(family.viscoplastic_overstress_truth(kin, 1.0)))


@pytest.mark.slow
def test_seen25_forms_reach_their_size_on_every_plant():
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
