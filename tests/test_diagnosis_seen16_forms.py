"""The sixteenth seen truth family (diagnosis.benchmark.seen16, sealed in session 21, run
once at the end of session 22 on 93064fe, 31.8 % top-1, now open): each form builds a finite
case of the requested size on every plant it applies to, is the base law at s = 0, grows with
its amplitude factor and refuses the plants it does not apply to."""
import dataclasses

import numpy as np
import pytest

from diagnosis.benchmark import EFFECT_SIZE, PLANT_NAMES, make_plant_case, plant_kinematics
from diagnosis.benchmark import seen16 as family
from diagnosis.benchmark.kinematics import FINE, PlantKinematics, fine_kinematics
from diagnosis.benchmark.runner import MIN_SIZE
from diagnosis.benchmark.truths import base_force

#: the family's form of each effect
FORM = {"acceleration": "jerk_unloading", "load": "overhung_load",
        "asymmetry": "freewheel_roller", "stribeck_shape": "churning_drag",
        "position": "cam_plunger", "inertia": "chordal_action",
        "delay": "mains_notch", "drift": "tribocharging",
        "backlash": "reversing_clutch", "gms": "power_law_joint"}
#: a plant each form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s)
PLANT = {effect: "xml350" for effect in FORM}


def test_seen16_forms_refuse_plants_they_do_not_apply_to():
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        family.churning_drag_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.power_law_joint_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.reversing_clutch_truth(iso, 1.0)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    # a one-way stroke (the press's) never comes back over the positions the fit part saw
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        family.cam_plunger_truth.__wrapped__(one_way, 1.0)
    # a load that never changes leaves the supports' shares nothing to act on
    still = dataclasses.replace(fk, load=np.full(fk.t.size, 100.0))
    with pytest.raises(ValueError, match="does not change"):
        family.overhung_load_truth.__wrapped__(still, 1.0)


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


def test_the_vibration_follows_the_jerk_and_decays():
    t = np.linspace(0.0, 10.0, 10001)
    a = np.clip(t - 1.0, 0.0, 1.0)            # a ramp of the acceleration over 1 s, then held
    env = family._vibration_envelope(t, a, 0.5)
    assert env[500] == 0.0                    # no jerk yet: no vibration
    assert env[1990] > 0.8                    # excited by the jerk
    # once the acceleration is held it decays with the contacts' damping, whatever a is
    assert np.isclose(env[3000] / env[2500], np.exp(-1.0), rtol=1e-2)
    kin = plant_kinematics("valve", quick=True)
    d = family.jerk_unloading_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.max(np.abs(d)) > 0.0


def test_the_supports_share_the_load_by_their_lever_arms():
    x = np.array([-1.0, -0.5, 0.0, 0.5, 1.0])
    share = family._pad_share(x, 0.0, 1.0, 2.0)
    # centred under the load each support takes half; the pad's share falls as the
    # carriage moves on, and it takes nothing once the load is over the rear support
    assert np.allclose(share, [1.0, 0.75, 0.5, 0.25, 0.0])
    # so a given change of the load counts more at one end of the stroke than at the other
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    lev = 1.0 + family.PAD_EXCESS * family._pad_share(fk.x, float(np.mean(fk.x)),
                                                       float(np.ptp(fk.x)), family.WHEELBASE)
    assert np.ptp(lev) > 0.5


def test_the_roller_slides_one_way_after_its_engagement_travel():
    x = np.concatenate([np.linspace(0.0, 1.0, 101), np.linspace(1.0, 0.0, 101)[1:]])
    e = family._engagement(x, 0.2)
    assert np.all(e[:101] == 0.0)                                      # overrunning
    assert np.isclose(e[110], 0.5) and np.isclose(e[120], 1.0)         # engaging, locked
    assert np.allclose(e[120:], 1.0) and np.all(e[125:] == 1.0)
    kin = _triangle()
    F = family.freewheel_roller_truth.__wrapped__(kin, 1.0)
    F0 = family.freewheel_roller_truth.__wrapped__(kin, 0.0)
    Fc = float(kin.base.params.Fc)
    down = (kin.t > 0.3) & (kin.t < 0.35)
    # the locked roller's sliding adds its friction against the motion, the negative way
    assert np.median(F[down] - F0[down]) < -0.5 * family.ROLLER_FRICTION * Fc


def test_the_churning_drag_is_flat_below_its_knee_and_a_two_thirds_power_above():
    u = np.array([0.0, 1e-3, 10.0, 100.0])
    c = family._churning(u, 0.1)
    assert np.isclose(c[0], 1.0) and np.isclose(c[1], 1.0)
    assert np.isclose(c[3] / c[2], 10.0 ** (2.0 / 3.0), rtol=1e-3)


def test_the_cam_lobe_rises_dwells_and_falls():
    x = np.linspace(-5.0, 5.0, 100001)
    h, dh = family._lobe(x, 0.0, 1.0, 0.1)
    assert np.isclose(h[50000], 1.0, atol=1e-6) and h[0] < 1e-6 and h[-1] < 1e-6
    assert np.allclose(dh[1:-1], np.gradient(h, x)[1:-1], atol=1e-3)
    # the ramps push back on the way up and forward on the way down
    assert dh[np.argmin(np.abs(x + 1.0))] > 0.0 > dh[np.argmin(np.abs(x - 1.0))]


def test_the_chain_speed_pulses_with_the_sprocket_polygon():
    pitch, teeth = 1.0, 8
    x = np.linspace(0.0, 4.0, 400001)
    kappa, dkappa = family._chordal(x, pitch, teeth)
    assert np.isclose(np.mean(kappa), 1.0, rtol=1e-4)                  # the mean speed
    assert np.isclose(np.ptp(kappa) / kappa.max(), 1.0 - np.cos(np.pi / teeth), rtol=1e-3)
    inside = (np.mod(x, pitch) > 0.01) & (np.mod(x, pitch) < 0.99)
    assert np.allclose(dkappa[inside], np.gradient(kappa, x)[inside], atol=1e-3)


def test_the_notch_passes_the_steady_force_and_removes_its_band():
    t = np.arange(200001) * 1e-4
    f0 = 5.0
    steady = family._notch(t, np.full(t.size, 3.0), f0, 1.0)
    assert np.allclose(steady, 3.0)
    hum = family._notch(t, np.sin(2.0 * np.pi * f0 * t), f0, 1.0)
    assert np.max(np.abs(hum[-20000:])) < 0.01
    # well below the notch the force is late by about width / omega0
    slow = np.sin(2.0 * np.pi * 0.05 * t)
    out = family._notch(t, slow, f0, 1.0)
    lag = np.arange(0, 1000)
    err = [np.mean((out[100000:] - np.sin(2.0 * np.pi * 0.05 * (t[100000:] - k * 1e-4))) ** 2)
           for k in lag]
    assert abs(lag[int(np.argmin(err))] * 1e-4 - 1.0 / (2.0 * np.pi * f0)) < 2e-3


def test_the_charge_builds_with_the_sliding_and_leaks():
    t = np.linspace(0.0, 5.0, 5001)
    q = family._from_cold(t, np.ones_like(t), 1.0)
    assert q[0] == pytest.approx(1.0 - np.exp(-1e-3), rel=1e-6)
    assert np.allclose(q, 1.0 - np.exp(-(t + 1e-3)), atol=1e-3)
    kin = _triangle()
    F = family.tribocharging_truth.__wrapped__(kin, 1.0)
    F0 = family.tribocharging_truth.__wrapped__(kin, 0.0)
    # the levels rise as the charge builds up: more at the end than at the start
    early = (kin.t > 0.02) & (kin.t < 0.05)
    late = (kin.t > 0.35) & (kin.t < 0.38)
    assert np.median(np.abs(F[late]) - np.abs(F0[late])) > \
        np.median(np.abs(F[early]) - np.abs(F0[early])) > 0.0


def test_the_clutch_lets_the_drive_run_free_for_a_time_after_each_reversal():
    kin = _triangle()
    Fc = float(kin.base.params.Fc)
    turn = []
    for s in (0.0, 2.0, 3.0):
        F = family.reversing_clutch_truth.__wrapped__(kin, s)
        assert np.all(np.isfinite(F))
        # released at the reversal, the contact's friction builds up only with the
        # engaging clutch's capacity
        after = np.flatnonzero((kin.t > 0.2) & (F < -0.9 * Fc))
        turn.append(kin.t[after[0]])
    # the longer the engagement, the later the contact's friction has turned
    assert turn[0] < turn[1] < turn[2]
    assert turn[2] - turn[0] > 0.02


def test_the_joint_softens_as_a_power_and_follows_masing():
    ud = 1.0
    phi, w = family._slip_strengths(-0.5, 0.3, 24)
    assert np.isclose(np.sum(w), 1.0) and phi[-1] == 1.0 and np.isclose(w[-1], 0.3)
    x = np.concatenate([np.linspace(0.0, 2.0, 2001), np.linspace(2.0, -2.0, 4001)[1:]])
    f = family._iwan(x, phi, w, ud)
    full = np.sum(w * phi)
    # stiff at first: every element sticks (the weakest slips after phi_min ud)
    x0 = np.linspace(0.0, 0.5 * phi[0] * ud, 11)
    f0 = family._iwan(x0, phi, w, ud)
    assert np.isclose((f0[1] - f0[0]) / (x0[1] - x0[0]), 1.0 / (ud * full), rtol=1e-9)
    assert np.isclose(f[1000], 1.0) and np.isclose(f[2000], 1.0)       # macro-slip at ud
    assert f[250] < 0.25 / full                                         # it has softened
    # unloading from the tip: Masing's rule, twice the backbone at half the travel back
    for k in (100, 400, 800):
        assert np.isclose(f[2000 + k], 1.0 - 2.0 * f[k // 2], atol=1e-9)
    assert np.isclose(f[-1], -1.0)
    kin = plant_kinematics("valve", quick=True)
    assert np.all(np.isfinite(family.power_law_joint_truth(kin, 1.0)))


@pytest.mark.slow
def test_seen16_forms_reach_their_size_on_every_plant():
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
