"""The twelfth seen truth family (diagnosis.benchmark.seen12, sealed at the end of session 17,
run once in session 18 on f5cb1e9, 29.5 % top-1, now open): each form builds a finite case
of the requested size on every plant it applies to, is the base law at s = 0, grows with
its amplitude factor and refuses the plants it does not apply to."""
import dataclasses

import numpy as np
import pytest

from diagnosis.benchmark import EFFECT_SIZE, PLANT_NAMES, make_plant_case, plant_kinematics
from diagnosis.benchmark import seen12 as family
from diagnosis.benchmark.kinematics import FINE, PlantKinematics
from diagnosis.benchmark.runner import MIN_SIZE
from diagnosis.benchmark.truths import base_force

#: the family's form of each effect
FORM = {"acceleration": "tilt_wedge", "load": "flash_desorption",
        "asymmetry": "helical_buckling", "stribeck_shape": "readsorption",
        "position": "beam_sag", "inertia": "fluid_coupling",
        "delay": "aerated_load_cell", "drift": "particle_ingress",
        "backlash": "wire_rope", "gms": "capillary_bridges"}
#: a plant each form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s)
PLANT = {effect: "xml350" for effect in FORM}


def test_seen12_forms_refuse_plants_they_do_not_apply_to():
    from diagnosis.benchmark.kinematics import fine_kinematics
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        family.readsorption_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.capillary_bridges_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.wire_rope_truth(iso, 1.0)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    # a one-way stroke (the press's) never comes back over the positions the fit part saw
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        family.beam_sag_truth.__wrapped__(one_way, 1.0)
    # a load that never changes heats no contact more than another
    still = dataclasses.replace(fk, load=np.full(fk.t.size, 100.0))
    with pytest.raises(ValueError, match="does not change"):
        family.flash_desorption_truth.__wrapped__(still, 1.0)


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


def test_inclined_pad_load_peaks_inside_and_starts_linear():
    K = np.array([0.0, 1e-4, 0.01, 0.5, 1.19, 2.0, 10.0])
    f = family._inclined_pad_load(K)
    assert f[0] == 0.0 and np.isclose(f[1], 0.5e-4, rtol=1e-3)
    assert np.isclose(f[2], 6.0 / 1e-4 * (np.log1p(0.01) - 0.02 / 2.01), rtol=1e-9)
    assert f[1] < f[2] < f[3] < f[4] and f[4] > f[5] > f[6] > 0.0      # best near 1.19
    assert np.isclose(family.PAD_LOAD_MAX, f[4], rtol=1e-3)


def test_tilt_wedge_lifts_speeding_up_only():
    kin = plant_kinematics("xml350", quick=True)
    d = np.abs(family.tilt_wedge_truth(kin, 1.0)) - np.abs(base_force(kin))
    v99, a99, Fc = kin.scales["v99"], kin.scales["a99"], float(kin.base.params.Fc)
    fast, rate = np.abs(kin.v) > 0.5 * v99, kin.v * kin.a
    assert np.median(d[fast & (rate > 0.2 * v99 * a99)]) < -0.1 * Fc   # speeding up
    assert abs(np.median(d[fast & (rate < -0.2 * v99 * a99)])) < 0.01 * Fc   # braking


def test_flash_temperature_desorbs_the_film_at_load_and_speed_together():
    phi = family._desorbed(np.array([1.0, 1.5, 0.5, 1.5, 5.0]),
                           np.array([1.0, 1.0, 1.0, 0.2, 0.0]), 1.0, 0.04)
    assert np.isclose(phi[0], 0.5)                                    # at the critical one
    assert phi[1] > 0.99 and phi[2] < 0.01                            # the load decides
    assert phi[3] < 0.01 and phi[4] < 1e-6                            # not when slow


def test_a_pushed_cable_drags_more_than_a_pulled_one_the_longer_it_is():
    ell = np.array([1.0, 2.0, 3.0])
    pull = family._cable_drag(ell, np.ones(3), 0.3)
    push = family._cable_drag(ell, -np.ones(3), 0.3)
    assert np.allclose(pull, 0.3 * ell) and np.allclose(push, np.tan(0.3 * ell))
    assert np.all(np.diff(push / pull) > 0.0)
    # near lock-up the drive's force limit caps it
    assert family._cable_drag(10.0, -1.0, 0.3) == np.tan(family.BUCKLING_MAX)
    kin = plant_kinematics("valve", quick=True)
    d = np.abs(family.helical_buckling_truth(kin, 1.0)) - np.abs(base_force(kin))
    v99 = kin.scales["v99"]
    assert np.median(d[kin.v < -0.5 * v99]) > 1.2 * np.median(d[kin.v > 0.5 * v99]) > 0.0


def test_readsorption_leaves_slow_sliding_covered():
    va = 0.1
    bare = family._uncovered(np.array([0.0, 0.005, 0.01, -0.1, 1.0]), va)
    assert bare[0] == 0.0 and bare[1] < 1e-8 and bare[2] < 1e-4
    assert np.isclose(bare[3], np.exp(-1.0)) and np.isclose(bare[4], np.exp(-0.1))
    kin = plant_kinematics("valve", quick=True)
    d = np.abs(family.readsorption_truth(kin, 1.0)) - np.abs(base_force(kin))
    v99, Fc = kin.scales["v99"], float(kin.base.params.Fc)
    slow = (np.abs(kin.v) > 0.01 * v99) & (np.abs(kin.v) < 0.05 * v99)
    assert np.median(d[np.abs(kin.v) > 0.8 * v99]) > 0.2 * Fc
    assert np.median(np.abs(d[slow])) < 1e-3 * Fc                    # (the bristle remembers)


def test_beam_slope_under_the_load_is_odd_about_midspan():
    u = np.array([0.0, 0.5 - np.sqrt(3.0) / 6.0, 0.3, 0.5, 0.7, 1.0])
    f = family._sag_pull(u)
    assert f[0] == 0.0 and f[3] == 0.0 and f[5] == 0.0
    assert np.isclose(f[1], 1.0) and np.isclose(f[2], -f[4]) and f[2] > 0.0
    # a force of the position alone: the same going up and down
    kin = _triangle()
    d = family.beam_sag_truth.__wrapped__(kin, 1.0) - family.beam_sag_truth.__wrapped__(kin,
                                                                                        0.0)
    up, down = slice(300, 1700), slice(2300, 3700)
    xs = np.linspace(kin.x[up].min(), kin.x[up].max(), 7)[1:-1]
    iu, idn = np.argsort(kin.x[up]), np.argsort(kin.x[down])
    assert np.allclose(np.interp(xs, kin.x[up][iu], d[up][iu]),
                       np.interp(xs, kin.x[down][idn], d[down][idn]), atol=1e-9)
    assert np.ptp(d) > 0.1 * float(kin.base.params.Fc)


def test_fluid_coupling_holds_at_speed_and_lets_go_near_rest():
    t = np.arange(20001) * 1e-4
    # w' = (v |v| - w |w|) / v_c: held at a steady speed, a step follows tanh
    assert np.allclose(family._fluid_part(t, np.full(t.size, 0.01), 0.2, 1e9), 0.01)
    w = family._fluid_part(t, np.where(t < 0.5, 0.01, 1.0), 0.2, 1e9)
    exact = np.tanh((t - 0.5) / 0.2 + np.arctanh(0.01))
    assert np.max(np.abs(w[5001:] - exact[5001:])) < 1e-3
    # the axis stopped, the coupling transmits ~ w^2 only: the part coasts on algebraically
    w = family._fluid_part(t, np.where(t < 1.0, 1.0, 0.0), 0.2, 1e9)
    assert np.isclose(w[-1], 1.0 / (1.0 + 1.0 / 0.2), rtol=1e-3)


def test_aerated_cell_lags_longer_at_low_pressure():
    t = np.arange(4001) * 1e-3
    up = family._aerated_lag(t, np.where(t >= 1.0, 1.0, 0.0), 0.1, 2.0)
    down = family._aerated_lag(t, np.where(t >= 1.0, -1.0, 0.0), 0.1, 2.0)
    # time to go 63 % of the way: the pressure rises to 1.5 p0 or falls to 0.5 p0
    k_up = np.argmax(up >= 1.0 - np.exp(-1.0))
    k_dn = np.argmax(down <= -(1.0 - np.exp(-1.0)))
    assert 1000 < k_up < k_dn and (k_dn - 1000) > 2.0 * (k_up - 1000)
    assert up[-1] > 0.999 and down[-1] < -0.999


def test_particles_enter_at_fixed_points_and_wear_off():
    tr = np.linspace(0.0, 1.0, 100001)
    r = family._particle_levels(tr, 2026, 8, 0.1, 0.005)
    again = family._particle_levels(tr, 2026, 8, 0.1, 0.005)
    assert np.array_equal(r, again) and r[0] == 0.0 and np.all(r >= 0.0)
    jumps = np.flatnonzero(np.diff(r) > 2e-4)                          # being pressed in
    assert 0.05 <= tr[jumps[0]] and tr[jumps[-1]] <= 0.96
    one = family._particle_levels(tr, 2026, 1, 0.1, 0.005)
    k = int(np.argmax(one))
    assert one[min(k + 20000, tr.size - 1)] < 0.2 * one[k]            # worn off over 0.2


def test_wire_rope_turns_the_force_fast_then_slowly():
    kin = _triangle()
    F = family.wire_rope_truth.__wrapped__(kin, 1.0)
    Fc = float(kin.base.params.Fc)
    rev = np.argmax(kin.t >= 0.2)
    after = F[rev:rev + 1500]
    # from the sliding level one way to the other after the reversal: the first 40 % of the
    # swing (the strands sticking) takes less drive travel than 55 to 95 % (the core alone)
    dx = kin.x[rev] - kin.x[rev:rev + 1500]
    swing = (after[0] - after) / (after[0] + Fc)

    def travel(share):
        return dx[np.argmax(swing >= share)]
    assert 0.0 < travel(0.4) < travel(0.95) - travel(0.55)
    assert abs(F[-1000] + Fc) < 0.2 * Fc                               # sliding again


def test_bridges_pull_back_as_sin_of_their_tilt_up_to_depinning():
    ud, tilt = 2.0, np.radians(60.0)
    f = family._bridge_force(np.array([0.0, 1e-6, ud, -ud]), ud, tilt)
    assert f[0] == 0.0 and np.isclose(f[2], 1.0) and np.isclose(f[3], -1.0)
    h = ud / np.tan(tilt)
    assert np.isclose(f[1], 1e-6 / h / np.sin(tilt), rtol=1e-6)       # linear at first
    # concave: the slope falls with the tilt
    u = np.linspace(0.0, ud, 101)
    assert np.all(np.diff(family._bridge_force(u, ud, tilt), 2) < 0.0)


@pytest.mark.slow
def test_seen12_forms_reach_their_size_on_every_plant():
    # the sizing check: every form reaches 0.95 to 1.05 of the requested size at strengths
    # 0.5 and 1 on every plant it applies to (quick protocols), so the open grid's count of
    # its cases (2 strengths x 2 noise levels x plants, 0.7 of the size at least) is 176
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
