"""The nineteenth seen truth family (diagnosis.benchmark.seen19, sealed in session 24, run
once at the end of session 24 on 3cef9aa, 43.8 % top-1, now open): each form builds a finite
case of the requested size on every plant it applies to, is the base law at s = 0, grows with
its amplitude factor and refuses the plants it does not apply to."""
import dataclasses

import numpy as np
import pytest

from diagnosis.benchmark import EFFECT_SIZE, PLANT_NAMES, make_plant_case, plant_kinematics
from diagnosis.benchmark import seen19 as family
from diagnosis.benchmark.kinematics import FINE, PlantKinematics, fine_kinematics
from diagnosis.benchmark.runner import MIN_SIZE
from diagnosis.benchmark.truths import base_force

#: the family's form of each effect
FORM = {"acceleration": "current_ripple", "load": "viscoelastic_rolling",
        "asymmetry": "leaning_brush", "stribeck_shape": "eddy_brake",
        "position": "rail_joint", "inertia": "abbe_pitch",
        "delay": "gauge_snubber", "drift": "film_dewetting",
        "backlash": "grease_packed_gap", "gms": "slip_weakening"}
#: a plant each form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s)
PLANT = {effect: "xml350" for effect in FORM}
def test_seen19_forms_refuse_plants_they_do_not_apply_to():
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        family.eddy_brake_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.slip_weakening_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.grease_packed_gap_truth(iso, 1.0)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    # a one-way stroke (the press's) never comes back over the positions the fit part saw
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        family.rail_joint_truth.__wrapped__(one_way, 1.0)
    # a load that never changes cannot show the rolling resistance's load
    still = dataclasses.replace(fk, load=np.full(fk.t.size, 100.0))
    with pytest.raises(ValueError, match="does not change"):
        family.viscoelastic_rolling_truth.__wrapped__(still, 1.0)


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


def test_the_current_ripple_averages_the_friction_at_low_speed_under_acceleration():
    v = np.array([0.0, 0.5, 1.0, 2.0, 0.3])
    share = family._dither_share(v, np.array([1.0, 1.0, 1.0, 1.0, 0.0]), 1e-12)
    assert np.isclose(share[0], 0.0, atol=1e-9) and np.isclose(share[1], 1.0 / 3.0)
    assert share[2] == 1.0 and share[3] == 1.0 and share[4] == 1.0     # no ripple: whole
    kin = _triangle()
    F = family.current_ripple_truth.__wrapped__(kin, 1.0)
    F0 = family.current_ripple_truth.__wrapped__(kin, 0.0)
    Fc = float(kin.base.params.Fc)
    steady = (kin.t > 0.05) & (kin.t < 0.15)                           # no acceleration
    assert np.max(np.abs(F[steady] - F0[steady])) < 1e-9 * Fc
    # slowing down to the reversal (low speed, strong deceleration) the friction is smaller
    turn = (kin.t > 0.197) & (kin.t < 0.1995)
    assert np.all(np.abs(F[turn]) <= np.abs(F0[turn]) + 1e-9 * Fc)
    assert np.max(np.abs(F0[turn]) - np.abs(F[turn])) > 0.05 * Fc


def test_the_rolling_resistance_grows_as_the_load_to_the_4_3_and_its_peak_moves_up():
    L = np.array([1.0, 2.0])
    # at a speed far below the peak the loss is linear in u ~ v L^(-1/3): F ~ L^(4/3 - 1/3)
    low = family._rolling_loss(np.array([1e-6, 1e-6]), L, 1.0, 1.0, 2.0)
    assert np.isclose(low[1] / low[0], 2.0, rtol=1e-6)
    # the peak loss (u = 1) sits at v = v_peak (L / L_mean)^(1/3): higher under more load
    v = np.linspace(1e-3, 5.0, 50001)
    peak = [v[np.argmax(family._rolling_loss(v, np.full(v.size, Li), 1.0, 1.0, 2.0))]
            for Li in L]
    assert np.isclose(peak[0], 1.0, rtol=1e-3) and np.isclose(peak[1], 2.0 ** (1 / 3), rtol=1e-3)
    top = family._rolling_loss(np.array([2.0 ** (1 / 3)]), np.array([2.0]), 1.0, 1.0, 2.0)
    assert np.isclose(top[0], 1.0)
    assert np.allclose(family._rolling_loss(-v[:5], np.full(5, 1.0), 1.0, 1.0, 2.0),
                       -family._rolling_loss(v[:5], np.full(5, 1.0), 1.0, 1.0, 2.0))
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    d = family.viscoelastic_rolling_truth.__wrapped__(fk, 1.0) - \
        family.viscoelastic_rolling_truth.__wrapped__(fk, 0.0)
    assert np.all(np.isfinite(d)) and np.all(d * fk.v >= 0.0)          # a drag


def test_the_brush_is_soft_and_low_with_its_lean_and_stiff_and_high_against_it():
    x = np.concatenate([np.linspace(0.0, 1.0, 10001), np.linspace(1.0, 0.0, 10001)[1:]])
    f = family._brush(x, 1.0, 3.0, 0.1, 0.01)
    assert f[0] == 0.0
    assert np.isclose(f[1000], 1.0 - np.exp(-1.0), rtol=1e-6)         # 0.1 of travel: one path
    assert np.isclose(f[10000], 1.0 - np.exp(-10.0), rtol=1e-6)
    assert np.isclose(f[-1], -3.0, rtol=1e-6)
    # back against the lean: from +1 to -3 within a few short paths
    k = 10000 + 300                                                    # 0.03 of travel back
    assert np.isclose(f[k], -3.0 + 4.0 * np.exp(-3.0), rtol=1e-6)
    kin = _triangle()
    d = family.leaning_brush_truth.__wrapped__(kin, 1.0) - \
        family.leaning_brush_truth.__wrapped__(kin, 0.0)
    Fc = float(kin.base.params.Fc)
    up, down = (kin.t > 0.15) & (kin.t < 0.19), (kin.t > 0.35) & (kin.t < 0.39)
    assert np.allclose(d[up], family.BRUSH_WITH * Fc, rtol=0.05)
    assert np.allclose(d[down], -family.BRUSH_AGAINST * Fc, rtol=0.01)


def test_the_eddy_drag_rises_then_falls_past_the_critical_speed():
    u = np.array([0.0, 0.01, 0.02, 1.0, 10.0, 20.0])
    q = family._eddy_drag(u)
    assert q[0] == 0.0 and np.isclose(q[2] / q[1], 2.0, rtol=1e-3)     # viscous below
    assert np.isclose(q[3], 1.0) and np.isclose(q[4] / q[5], 2.0, rtol=1e-2)   # ~ 1 / u above
    assert np.allclose(family._eddy_drag(-u), -q)
    kin = plant_kinematics("valve", quick=True)
    d = family.eddy_brake_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.max(np.abs(d)) > 0.0
    still = np.abs(kin.v) < 1e-9
    assert np.all(np.abs(d[still]) < 1e-9 * float(kin.base.params.Fc))


def test_the_joint_raises_the_levels_across_one_carriage_length_and_pushes_back():
    x = np.linspace(-2.0, 2.0, 40001)
    share, ds = family._straddle(x, 0.0, 1.0, 1e-4)
    assert np.allclose(share[x < -0.6], 0.0, atol=1e-6) and np.allclose(share[x > 0.6], 1.0)
    mid = np.abs(x) < 0.4
    assert np.allclose(share[mid], x[mid] + 0.5, atol=1e-6) and np.allclose(ds[mid], 1.0)
    assert np.isclose(np.trapezoid(ds, x), 1.0, rtol=1e-4)
    kin = plant_kinematics("valve", quick=True)
    d = family.rail_joint_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.max(np.abs(d)) > 0.0


def test_the_scale_head_misses_only_the_changes_of_the_acceleration():
    t = np.linspace(0.0, 40.0, 400001)
    a = np.where(t < 1.0, 0.0, 1.0)
    hp = family._pitch_highpass(t, a, 2.0, 0.15)
    assert np.allclose(hp[t < 1.0], 0.0)
    k = np.searchsorted(t, 1.0)
    assert np.isclose(hp[k + 1], 1.0, atol=0.02)                       # a step passes at once
    assert abs(hp[-1]) < 1e-4                                          # and dies out
    assert hp[k:].min() < -0.3                                         # after a swing back
    assert np.allclose(family._pitch_highpass(t, np.full(t.size, 3.0), 2.0, 0.15), 0.0)
    kin = plant_kinematics("xml350", quick=True)
    d = family.abbe_pitch_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.max(np.abs(d)) > 0.0


def test_the_snubber_lags_a_ramp_by_a_time_that_grows_with_its_rate():
    h = 1e-3
    t = h * np.arange(20001)
    for rate in (1.0, 4.0):
        y = family._snubbed(rate * t, h, 0.05, 0.02)
        lag = (rate * t[-1] - y[-1]) / rate
        assert np.isclose(lag, 0.05 + 0.02 * rate, rtol=2e-2)
    assert np.allclose(family._snubbed(np.full(100, 2.0), h, 0.05, 0.02), 2.0)
    step = np.where(t < 1.0, 0.0, 1.0)
    ys = family._snubbed(step, h, 0.05, 0.02)
    assert np.all(np.diff(ys) >= 0.0) and ys.max() <= 1.0 + 1e-12      # no overshoot
    kin = plant_kinematics("valve", quick=True)
    d = family.gauge_snubber_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.max(np.abs(d)) > 0.0


def test_the_film_dewets_after_an_incubation_along_avrami_kinetics():
    t = np.linspace(0.0, 10.0, 1001)
    bare = family._bare_share(t, 1.0, 4.0, 3.0)
    assert np.all(bare[t <= 1.0] == 0.0) and np.all(np.diff(bare) >= 0.0)
    k = np.searchsorted(t, 5.0)
    assert np.isclose(bare[k], 1.0 - np.exp(-1.0))
    kin = _triangle()
    F = family.film_dewetting_truth.__wrapped__(kin, 1.0)
    F0 = family.film_dewetting_truth.__wrapped__(kin, 0.0)
    Fc = float(kin.base.params.Fc)
    early = kin.t < family.DEWET_ONSET * 0.4
    assert np.max(np.abs(F[early] - F0[early])) < 1e-9 * Fc
    late = (kin.t > 0.35) & (kin.t < 0.39)
    share = family._bare_share(kin.t[late], family.DEWET_ONSET * 0.4, family.DEWET_TIME * 0.4,
                               family.DEWET_ORDER)
    rise = np.abs(F[late]) - np.abs(F0[late])
    assert np.allclose(rise, family.DEWET_RISE * share * Fc, rtol=0.05, atol=1e-3 * Fc)


def test_the_grease_takes_up_the_play_before_the_flanks_meet(monkeypatch):
    kin = _triangle()
    Fc = float(kin.base.params.Fc)
    turn = []
    for s in (0.0, 1.0, 2.0):
        F = family.grease_packed_gap_truth.__wrapped__(kin, s)
        assert np.all(np.isfinite(F))
        after = np.flatnonzero((kin.t > 0.2) & (F < -0.9 * Fc))
        turn.append(kin.t[after[0]])
    # the play delays the contact's turn, more the wider it is
    assert turn[0] < turn[1] < turn[2]
    # without the grease the same play delays it more: the grease drags the contact along
    monkeypatch.setattr(family, "GREASE_YIELD", 1e-9)
    F = family.grease_packed_gap_truth.__wrapped__(kin, 2.0)
    after = np.flatnonzero((kin.t > 0.2) & (F < -0.9 * Fc))
    assert kin.t[after[0]] > turn[2]


def test_the_junctions_peak_after_each_reversal_and_weaken_over_their_slip():
    caps = np.array([1.0])
    kp = 1.0
    x = np.concatenate([np.linspace(0.0, 6.0, 60001), np.linspace(6.0, -6.0, 120001)[1:]])
    f = family._weakening_junctions(x, caps, kp, 0.7, 2.0)
    assert f[0] == 0.0
    # loading from rest: elastic up to the peak (1 / 0.7 of the sliding value) at x = 1
    k1 = np.searchsorted(x[:60001], 1.0)
    assert np.isclose(f[k1], 1.0 / 0.7, rtol=1e-3) and np.isclose(f[500], 0.05 / 0.7)
    # then weakening over the slip distance to the residual, 1
    assert np.isclose(f[60000], 1.0) and np.all(np.diff(f[k1 + 10:k1 + 20000]) <= 1e-12)
    # after the reversal it heals: the same peak the other way, then the residual again
    back = f[60001:]
    assert np.isclose(back.min(), -1.0 / 0.7, rtol=1e-3) and np.isclose(f[-1], -1.0)
    kin = plant_kinematics("valve", quick=True)
    assert np.all(np.isfinite(family.slip_weakening_truth(kin, 1.0)))


@pytest.mark.slow
def test_seen19_forms_reach_their_size_on_every_plant():
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
