"""The twenty-third seen truth family (diagnosis.benchmark.seen23, sealed in session 27, run
once on 25e7bb5, 51.7 % top-1, now open): each form builds a finite case of the requested
size on every plant it applies to, is the base law at s = 0, grows with its amplitude factor
and refuses the plants it does not apply to."""
import dataclasses

import numpy as np
import pytest

from diagnosis.benchmark import EFFECT_SIZE, PLANT_NAMES, make_plant_case, plant_kinematics
from diagnosis.benchmark import seen23 as family
from diagnosis.benchmark.kinematics import FINE, PlantKinematics, fine_kinematics
from diagnosis.benchmark.runner import MIN_SIZE
from diagnosis.benchmark.truths import base_force

#: the family's form of each effect
FORM = {"acceleration": "belt_creep", "load": "disc_spring_pad",
        "asymmetry": "fluidic_diode", "stribeck_shape": "sommerfeld_journal",
        "position": "drawer_overhang", "inertia": "rocking_block",
        "delay": "swept_grating", "drift": "oil_evaporation",
        "backlash": "toggle_spring", "gms": "superelastic_flexure"}
#: a plant each form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s)
PLANT = {effect: "xml350" for effect in FORM}


def test_seen23_forms_refuse_plants_they_do_not_apply_to():
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        family.sommerfeld_journal_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.superelastic_flexure_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.toggle_spring_truth(iso, 1.0)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    # a one-way stroke (the press's) never comes back over the positions the fit part saw
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        family.drawer_overhang_truth.__wrapped__(one_way, 1.0)
    # a load that never changes does not move the disc spring along its characteristic
    still = dataclasses.replace(fk, load=np.full(fk.t.size, 100.0))
    with pytest.raises(ValueError, match="does not change"):
        family.disc_spring_pad_truth.__wrapped__(still, 1.0)


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


def test_the_belts_creep_drag_grows_as_the_square_of_the_drive_force():
    q = np.array([-2.0, -1.0, 0.0, 0.5, 1.0, 2.0])
    d = family._creep_loss(q)
    assert np.allclose(d, q * q) and np.all(d >= 0.0)                  # even in the force
    assert np.isclose(family._creep_loss(2.0 * q)[4], 4.0 * d[4])
    kin = _triangle()
    F = family.belt_creep_truth.__wrapped__(kin, 1.0)
    F0 = family.belt_creep_truth.__wrapped__(kin, 0.0)
    Fc = float(kin.base.params.Fc)
    assert np.all((F - F0) * kin.v >= -1e-12 * Fc) and np.max(np.abs(F - F0)) > 0.0  # a drag
    # the reversal's deceleration carries the drive force far past the friction: more drag
    turn = np.abs(kin.t - 0.2) < 0.004
    steady = (kin.t > 0.1) & (kin.t < 0.19)
    assert np.max(np.abs(F - F0)[steady]) > 0.0
    assert np.max(np.abs(F - F0)[turn & (np.abs(kin.v) > 0.5e-2)]) > \
        np.max(np.abs(F - F0)[steady])


def test_the_disc_spring_rises_flattens_and_falls_past_its_top():
    f = np.linspace(0.0, 2.8, 281)
    P = family._disc_force(f, 2.0)
    assert P[0] == 0.0 and np.isclose(np.max(P), 1.0, rtol=1e-3)
    top = int(np.argmax(P))
    assert 1.0 < f[top] < 1.4
    assert np.all(np.diff(P[:top]) > 0.0) and np.all(np.diff(P[top + 5:]) < 0.0)
    # the visited deflections run across the top: the pad's force is not monotone in the load
    visited = family._disc_force(np.linspace(family.DISC_SET, family.DISC_SET
                                             + family.DISC_SPAN, 101), family.DISC_HEIGHT)
    assert np.argmax(visited) not in (0, 100)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    F = family.disc_spring_pad_truth.__wrapped__(fk, 1.0)
    F0 = family.disc_spring_pad_truth.__wrapped__(fk, 0.0)
    assert np.all(np.isfinite(F)) and np.max(np.abs(F - F0)) > 0.0


def test_the_diode_is_even_at_low_speed_and_favours_one_way_at_speed():
    u = np.array([-1.0, -0.01, 0.01, 1.0])
    d = family._diode_drag(u, 0.3, 3.0, 0.3)
    assert np.isclose(d[3], 1.0)
    assert np.isclose(-d[1], d[2], rtol=0.05)                          # laminar: even
    assert np.isclose(-d[0] / d[3], 0.3 + 0.7 * (1.0 + 2.0 / 1.3), rtol=1e-9)
    ratio = [-family._diode_drag(-x, 0.3, 3.0, 0.3) / family._diode_drag(x, 0.3, 3.0, 0.3)
             for x in (0.1, 0.3, 1.0, 3.0)]
    assert np.all(np.diff(ratio) > 0.0)                                # grows with Re
    kin = plant_kinematics("valve", quick=True)
    d = family.fluidic_diode_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.all(d * kin.v >= 0.0) and np.max(np.abs(d)) > 0.0


def test_the_journals_friction_dips_below_its_boundary_value_then_rises_as_petroff():
    f = family._journal_friction(np.array([1e-9, 0.25, 1.0, 4.0, 8.0]), 0.25)
    assert np.isclose(f[0], 1.0, atol=1e-3)                            # the shaft on its seat
    assert np.isclose(f[1], 2.0 * np.sqrt(2.0) / 3.0, rtol=1e-3)       # least, e = 1 / sqrt 2
    assert f[1] < f[0] < f[2] < f[3]
    assert np.isclose(f[4] / f[3], 2.0, rtol=0.03)                     # Petroff: linear
    e = family._journal_eccentricity(np.array([0.1, 1.0, 10.0, 100.0]))
    assert np.all(np.diff(e) > 0.0) and 0.0 < e[0] and e[-1] < 1.0
    kin = plant_kinematics("valve", quick=True)
    d = family.sommerfeld_journal_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.all(d * kin.v >= 0.0) and np.max(np.abs(d)) > 0.0


def test_the_rams_reactions_grow_hyperbolically_as_it_runs_out():
    e = np.array([0.0, 0.1, 0.4, 0.7, 0.9])
    r = family._drawer_reactions(e)
    assert r[0] == 1.0 and np.all(np.diff(r) > 0.0) and np.all(np.diff(r, 2) > 0.0)
    assert np.isclose(r[4], 19.0)
    kin = plant_kinematics("valve", quick=True)
    d = family.drawer_overhang_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.all(d * kin.v >= 0.0)
    sc = kin.scales
    moving = np.abs(kin.v) > 0.5 * sc["v99"]
    out = moving & (kin.x > sc["x_lo"] + 0.8 * (sc["x_hi"] - sc["x_lo"]))
    inn = moving & (kin.x < sc["x_lo"] + 0.2 * (sc["x_hi"] - sc["x_lo"]))
    assert np.median(np.abs(d[out])) > 2.0 * np.median(np.abs(d[inn]))


def test_the_block_stands_below_its_tipping_acceleration_and_rocks_above_it():
    h, n, R, alpha = 1e-4, 100001, 0.05, 0.2
    tip = 9.81 * np.tan(alpha)
    slow = family._rocking_force(np.full(n, 0.8 * tip), h, R, alpha, 9.81, 0.1)
    assert np.allclose(slow[1:], 0.8 * tip)                            # stands: whole mass
    t = h * np.arange(n)
    pulse = np.where(t < 0.05, 3.0 * tip, 0.0)
    f = family._rocking_force(pulse, h, R, alpha, 9.81, 0.1)
    rocking = (t > 0.01) & (t < 0.05)
    assert np.all(np.abs(f[rocking]) < 3.0 * tip)                      # less than its mass
    assert np.min(f[rocking]) < 0.9 * 3.0 * tip
    assert np.allclose(f[-100:], 0.0, atol=1e-9 * tip)                 # landed, at rest
    # mirrored accelerations rock it on the other edge
    assert np.allclose(family._rocking_force(-pulse, h, R, alpha, 9.81, 0.1), -f)
    kin = plant_kinematics("xml350", quick=True)
    d = family.rocking_block_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.max(np.abs(d)) > 0.0


def test_the_sweep_samples_where_the_force_meets_it_and_holds_to_its_end():
    t = np.linspace(0.0, 1.0, 10001)
    F = t.copy()
    out = family._sweep_readings(t, F, np.full(t.size, 0.5), 0.1)
    assert np.all(out[t < 0.1] == 0.0)                                 # before the first report
    for k in range(1, 9):
        held = (t >= 0.1 * k + 1e-9) & (t < 0.1 * (k + 1) - 1e-9)
        assert np.allclose(out[held], 0.1 * (k - 1) + 0.05, atol=2e-4)  # mid-sweep, a sweep on
    # the force sets the sampling instant: later in the sweep, a later sample
    late = family._sweep_readings(t, F, np.full(t.size, 0.9), 0.1)
    held = (t >= 0.5 + 1e-9) & (t < 0.6 - 1e-9)
    assert np.allclose(late[held] - out[held], 0.04, atol=2e-4)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    F0 = family.swept_grating_truth.__wrapped__(fk, 0.0)
    F1 = family.swept_grating_truth.__wrapped__(fk, 1.0)
    assert np.all(np.isfinite(F1)) and np.max(np.abs(F1 - F0)) > 0.0
    # a steady force reads true
    still = dataclasses.replace(fk, v=np.zeros_like(fk.v))
    Fs = family.swept_grating_truth.__wrapped__(still, 1.0)
    Fs0 = family.swept_grating_truth.__wrapped__(still, 0.0)
    assert np.allclose(Fs, Fs0, atol=1e-9 * (np.max(np.abs(Fs0)) + 1.0))


def test_the_film_evaporates_to_its_heavy_fraction_and_the_asperities_take_over_late():
    tau = np.linspace(0.0, 1.0, 101)
    h = family._film(tau, 0.25, 0.5)
    assert h[0] == 1.0 and np.all(np.diff(h) < 0.0) and h[-1] > 0.25
    assert np.isclose(family._film(50.0, 0.25, 0.5), 0.25)
    share = family._asperity_share(3.0 * h)
    assert np.all(np.diff(share) > 0.0)
    assert share[50] - share[0] < 0.5 * (share[100] - share[0])       # a delayed onset
    kin = _triangle()
    F = family.oil_evaporation_truth.__wrapped__(kin, 1.0)
    F0 = family.oil_evaporation_truth.__wrapped__(kin, 0.0)
    Fs = float(kin.base.params.Fs)
    end = (kin.t > 0.37) & (kin.t < 0.39)
    rise = np.abs(F[end]) - np.abs(F0[end])
    assert np.all(rise > 0.0) and np.all(rise <= family.EVAP_RISE * 1.05 * Fs)
    first = (kin.t > 0.05) & (kin.t < 0.1)
    assert np.max(np.abs(F[first] - F0[first])) < 0.2 * np.min(rise)


def test_the_toggle_pushes_away_from_the_centre_and_turns_over_in_the_play():
    half, push = 1e-3, 2.0
    e = np.linspace(-2e-3, 2e-3, 401)
    f = np.array([family._toggle_push(x, half, push, 1.0, 2.8) for x in e])
    assert np.isclose(family._toggle_push(0.0, half, push, 1.0, 2.8), 0.0)
    assert np.isclose(family._toggle_push(half, half, push, 1.0, 2.8), -push)
    assert np.allclose(f, -f[::-1])                                   # odd
    inside = np.abs(e) <= half
    assert np.all(np.diff(f[inside]) < 0.0)                           # a negative stiffness
    assert np.allclose(f[e > half], -push) and np.allclose(f[e < -half], push)
    kin = _triangle()
    Fc = float(kin.base.params.Fc)
    F = family.toggle_spring_truth.__wrapped__(kin, 1.0)
    assert np.all(np.isfinite(F))
    # after the reversal (the drive going down), before the flank takes the contact up:
    # first the toggle pulls it back after the drive, then, past the centre, pushes it
    # towards the coming flank: the force turns over inside the play
    after = kin.t > 0.2
    taken = np.flatnonzero(after & (F < -0.9 * Fc))[0]
    window = F[np.flatnonzero(after)[0]:taken]
    low = np.flatnonzero(window < -0.5 * family.TOGGLE_PUSH * Fc)
    assert low.size and np.max(window[low[0]:]) > 0.5 * family.TOGGLE_PUSH * Fc


def test_the_flexure_loops_as_a_flag_and_returns_without_residual_deflection():
    path = 1.0
    D = np.concatenate([np.linspace(0.0, 1.0, 1001), np.linspace(1.0, 0.0, 1001)[1:]])
    u = family._flag(D, path, 0.5, 0.2, 0.1, 1.0)
    a = 0.5 / 1.1
    assert np.isclose(u[500], 0.5, atol=1e-9)                          # elastic to the plateau
    assert np.isclose(u[1000], 0.5 + 0.1 * a, atol=1e-9)               # on the forward one
    assert np.isclose(u[1500], 0.2 + 0.1 * (0.3 / 1.1), atol=1e-9)     # on the reverse one
    assert abs(u[-1]) < 1e-9                                           # no residual deflection
    # the other way alike, and beyond the transformation the contact slips at 1
    far = np.concatenate([np.linspace(0.0, -4.0, 2001), np.full(500, -4.0)])
    g = family._flag(far, path, 0.5, 0.2, 0.1, 1.0)
    assert np.isclose(np.min(g), -1.0) and np.ptp(g[-500:]) == 0.0     # held, no creep
    assert np.allclose(family._flag(-D, path, 0.5, 0.2, 0.1, 1.0), -u)
    kin = plant_kinematics("valve", quick=True)
    assert np.all(np.isfinite(family.superelastic_flexure_truth(kin, 1.0)))


@pytest.mark.slow
def test_seen23_forms_reach_their_size_on_every_plant():
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
