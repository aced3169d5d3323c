"""The seventeenth seen truth family (diagnosis.benchmark.seen17, sealed in session 22, run
once at the end of session 23 on 5f0e273, 47.2 % top-1, now open): each form builds a finite
case of the requested size on every plant it applies to, is the base law at s = 0, grows with
its amplitude factor and refuses the plants it does not apply to."""
import dataclasses

import numpy as np
import pytest

from diagnosis.benchmark import EFFECT_SIZE, PLANT_NAMES, make_plant_case, plant_kinematics
from diagnosis.benchmark import seen17 as family
from diagnosis.benchmark.kinematics import FINE, PlantKinematics, fine_kinematics
from diagnosis.benchmark.runner import MIN_SIZE
from diagnosis.benchmark.truths import base_force

#: the family's form of each effect
FORM = {"acceleration": "aerostatic_tilt", "load": "preload_relief",
        "asymmetry": "felt_lubricator", "stribeck_shape": "core_loss_drag",
        "position": "heated_zone", "inertia": "screw_stiffness",
        "delay": "alpha_beta_tracker", "drift": "cage_creep",
        "backlash": "mesh_stiffness", "gms": "junction_growth"}
#: a plant each form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s)
PLANT = {effect: "xml350" for effect in FORM}
def test_seen17_forms_refuse_plants_they_do_not_apply_to():
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        family.core_loss_drag_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.junction_growth_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.mesh_stiffness_truth(iso, 1.0)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    # a one-way stroke (the press's) never comes back over the positions the fit part saw
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        family.heated_zone_truth.__wrapped__(one_way, 1.0)
    # a load that never changes leaves the rows' shares where they are
    still = dataclasses.replace(fk, load=np.full(fk.t.size, 100.0))
    with pytest.raises(ValueError, match="does not change"):
        family.preload_relief_truth.__wrapped__(still, 1.0)


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


def test_the_tilted_films_drag_grows_with_the_acceleration_squared():
    a = np.array([-2.0, -0.5, 0.0, 1e-6, 0.5, 2.0])
    g = family._tilted_gap_drag(a, 1.0, 0.9)
    assert g[2] == 1.0 and np.isclose(g[3], 1.0)
    assert np.isclose(g[4], np.arctanh(0.5) / 0.5) and np.isclose(g[1], g[4])   # even in a
    assert np.isclose(g[5], np.arctanh(0.9) / 0.9) and g[0] == g[5]             # capped
    small = family._tilted_gap_drag(np.array([0.01, 0.02]), 1.0, 0.9) - 1.0
    assert np.isclose(small[1] / small[0], 4.0, rtol=1e-3)                      # ~ a^2
    # nothing while the carriage stands or runs at a steady speed: the film only drags
    kin = _triangle()
    d = family.aerostatic_tilt_truth.__wrapped__(kin, 1.0) - \
        family.aerostatic_tilt_truth.__wrapped__(kin, 0.0)
    steady = (kin.t > 0.05) & (kin.t < 0.15)
    assert np.max(np.abs(d[steady])) < 1e-9 * float(kin.base.params.Fc)
    assert np.max(np.abs(d)) > 0.0


def test_the_preloaded_rows_share_the_load_until_one_lifts_off():
    r = np.array([0.0, 0.2, 0.5, 2.0 ** 1.5, 4.0, 8.0])
    S = family._row_sum(r)
    assert np.isclose(S[0], 2.0)                                       # both at the preload
    assert np.isclose(S[3], 2.0 ** 1.5, rtol=1e-4)                     # the upper rows free
    assert np.allclose(S[4:], r[4:])                                   # the lower carry all
    assert np.all(np.diff(S) >= 0.0)
    # a light load hardly changes the sum (it is even in the deflection), a heavy one does
    assert S[1] - S[0] < 0.05 * (r[1] - r[0])
    assert np.isclose(S[5] - S[4], r[5] - r[4])


def test_the_felt_oils_ahead_one_way_and_the_film_ages_the_other():
    t = np.linspace(0.0, 4.0, 4001)
    v = np.where(t < 2.0, 1.0, -1.0)
    x = np.where(t < 2.0, t, 4.0 - t)
    share = family._film_share(t, x, v, 0.0, 0.01, 201, 1.0)
    assert np.all(share[t < 2.0] == 1.0)                               # leading: fresh
    # trailing, at x = 1 (oiled at t = 1, met again at t = 3): two drainage times old
    k = np.argmin(np.abs(t - 3.0))
    assert np.isclose(share[k], np.exp(-2.0), rtol=2e-2)
    # and older the further back it goes
    back = t > 2.01
    assert np.all(np.diff(share[back]) <= 1e-12)
    kin = _triangle()
    F = family.felt_lubricator_truth.__wrapped__(kin, 1.0)
    F0 = family.felt_lubricator_truth.__wrapped__(kin, 0.0)
    up = (kin.t > 0.05) & (kin.t < 0.15)
    Fc = float(kin.base.params.Fc)
    assert np.median(F0[up] - F[up]) > 0.5 * family.FELT_DROP * Fc     # lower on the film


def test_the_core_losses_are_a_constant_and_a_square_root_drag():
    u = np.array([0.0, 1.0, 4.0, 16.0])
    c = family._core_loss(u, 0.25)
    assert np.isclose(c[0], 0.25) and np.allclose(np.diff(c[1:]), [1.0, 2.0])
    assert np.allclose(family._core_loss(-u, 0.25), c)                 # a drag either way
    kin = plant_kinematics("valve", quick=True)
    d = family.core_loss_drag_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.max(np.abs(d)) > 0.0


def test_the_rail_is_warmest_at_the_source_and_cools_along_it():
    x = np.array([-2.0, -1.0, 0.0, 1.0, 2.0])
    th = family._fin_profile(x, 0.0, 1.0)
    assert np.isclose(th[2], 1.0) and np.allclose(th[[1, 3]], np.exp(-1.0))
    assert np.allclose(th, th[::-1])
    kin = plant_kinematics("valve", quick=True)
    d = family.heated_zone_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.max(np.abs(d)) > 0.0


def test_the_carriage_rings_on_the_screw_and_settles_at_its_static_lag():
    h, w, zeta = 2e-4, 10.0, 0.1
    t = h * np.arange(60001)
    e, edd = family._screw_mode(t, np.ones_like(t), np.full(t.size, w), zeta)
    # a step of the acceleration: the lag overshoots the static a / w^2 by the mode's
    # ratio and settles there, so the carriage's acceleration error dies out
    assert np.isclose(e.max() * w * w, 1.0 + np.exp(-np.pi * zeta / np.sqrt(1.0 - zeta ** 2)),
                      rtol=1e-2)
    assert np.isclose(e[-1] * w * w, 1.0, rtol=1e-3) and abs(edd[-1]) < 1e-3
    # the mode is stiffer near the fixed bearing: a faster ring there
    kin = plant_kinematics("xml350", quick=True)
    d = family.screw_stiffness_truth(kin, 1.0) - base_force(kin)
    assert np.all(np.isfinite(d)) and np.max(np.abs(d)) > 0.0


def test_the_tracker_follows_a_ramp_without_lag_and_overshoots_a_turn():
    t = np.linspace(0.0, 10.0, 100001)
    ramp = 3.0 + 2.0 * t
    y = family._tracker(t, ramp, 5.0, 0.7)
    assert np.allclose(y[50000:], ramp[50000:], atol=1e-6)            # type 2: no ramp lag
    assert np.allclose(family._tracker(t, np.full(t.size, 3.0), 5.0, 0.7), 3.0)
    step = np.where(t < 1.0, 0.0, 1.0)
    ys = family._tracker(t, step, 5.0, 0.7)
    assert ys.max() > 1.05 and np.isclose(ys[-1], 1.0, atol=1e-6)     # the rate overshoots
    # a turn of the slope (a reversal's) is followed late: the rate's estimate runs on
    vee = np.abs(t - 5.0)
    yv = family._tracker(t, vee, 5.0, 0.7)
    assert np.isclose(yv[50000], vee[50000], atol=1e-6)
    assert yv[52000] < vee[52000] - 0.05


def test_the_cage_creeps_one_way_and_the_levels_step_at_its_stop():
    t = np.linspace(0.0, 4.0, 4001)
    v = np.where(np.mod(t, 1.0) < 0.5, 1.0, -1.0)                      # equal strokes
    c = family._cage_offset(t, v, 0.6)
    assert np.isclose(c.max(), 1.0)
    per_cycle = c[np.searchsorted(t, [1.0, 2.0, 3.0, 4.0]) - 1]
    assert np.all(np.diff(per_cycle) > 0.0)                            # a net creep
    kin = _triangle()
    F = family.cage_creep_truth.__wrapped__(kin, 1.0)
    F0 = family.cage_creep_truth.__wrapped__(kin, 0.0)
    Fc = float(kin.base.params.Fc)
    early = (kin.t > 0.02) & (kin.t < 0.05)
    assert np.max(np.abs(F[early] - F0[early])) < 1e-9 * Fc             # not yet at the end
    late = (kin.t > 0.17) & (kin.t < 0.19)                             # past the stop
    assert np.median(F[late] - F0[late]) > 0.9 * (family.CREEP_RISE + family.CREEP_SKID) * Fc


def test_the_mesh_stiffens_where_two_tooth_pairs_mesh():
    x = np.linspace(0.0, 10.0, 100001)
    k = family._mesh_factor(x, 1.0, 1.6, 1.8)
    assert np.isclose(k.min(), 1.0) and np.isclose(k.max(), 1.8)
    assert np.isclose(np.mean(k > 1.4), 0.6, atol=0.01)                # the contact ratio
    kin = _triangle()
    Fc = float(kin.base.params.Fc)
    turn = []
    for s in (0.0, 1.0, 2.0):
        F = family.mesh_stiffness_truth.__wrapped__(kin, s)
        assert np.all(np.isfinite(F))
        after = np.flatnonzero((kin.t > 0.2) & (F < -0.9 * Fc))
        turn.append(kin.t[after[0]])
    # the play and the mesh's compliance delay the contact's turn
    assert turn[0] < turn[1] < turn[2]


def test_the_junctions_stiffen_as_they_grow_and_the_loops_are_pinched():
    caps = np.array([1.0])
    alpha = 15.0
    ud = 1.0
    kappa = np.array([family._growth_integral(alpha) / ud])
    x = np.concatenate([np.linspace(0.0, 2.0, 20001), np.linspace(2.0, -2.0, 40001)[1:]])
    f = family._growing_junctions(x, caps, kappa, alpha)
    # loading from rest: the start's stiffness kappa, (1 + alpha r^2)^(1/4) times it later
    slope = np.diff(f) / np.diff(x)                                    # over each step
    assert np.isclose(slope[0], kappa[0], rtol=1e-3)
    assert slope[8000] > 1.5 * slope[0]                                # convex: stiffening
    assert np.isclose(f[10000], 1.0, atol=2e-3) and f[20000] == 1.0    # slips at ud
    # unloading from the slip: stiff first, soft through zero force (pinched, not Masing)
    back = slope[20000:]
    fb = f[20001:]
    near_tip = back[fb > 0.95][:50]
    near_zero = back[np.abs(fb) < 0.05]
    assert np.all(np.abs(near_tip) > 1.5 * np.max(np.abs(near_zero)))
    assert np.isclose(f[-1], -1.0)
    kin = plant_kinematics("valve", quick=True)
    assert np.all(np.isfinite(family.junction_growth_truth(kin, 1.0)))


@pytest.mark.slow
def test_seen17_forms_reach_their_size_on_every_plant():
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
