"""The seventh seen truth family (diagnosis.benchmark.seen7, sealed at the end of session 12,
run once in session 13 on d12174d, 25.0 % top-1, now open): each form builds a finite case of the
requested size on every plant it applies to, is the base law at s = 0 and grows with its
amplitude factor."""
import dataclasses

import numpy as np
import pytest

from diagnosis.benchmark import EFFECT_SIZE, PLANT_NAMES, make_plant_case, plant_kinematics
from diagnosis.benchmark import seen7 as family
from diagnosis.benchmark.runner import MIN_SIZE
from diagnosis.benchmark.truths import base_force

#: the family's form of each effect
FORM = {"acceleration": "motor_attraction", "load": "plastic_junctions",
        "asymmetry": "tilted_pad", "stribeck_shape": "rubber_hysteresis",
        "position": "end_cushion", "inertia": "rattling_mass", "delay": "pressure_line",
        "drift": "tribo_oxide", "backlash": "biased_play", "gms": "tomlinson_asperities"}
#: a plant each form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s)
PLANT = {effect: "xml350" for effect in FORM}


def test_seen7_forms_refuse_plants_they_do_not_apply_to():
    from diagnosis.benchmark.kinematics import fine_kinematics
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        family.rubber_hysteresis_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.tomlinson_asperities_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        family.biased_play_truth(iso, 1.0)
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    # a one-way stroke (the press's) never comes back into a cushion the fit part saw
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        family.end_cushion_truth.__wrapped__(one_way, 1.0)
    # a load that never changes forms no junctions to remember
    still = dataclasses.replace(fk, load=np.full(fk.t.size, 100.0))
    with pytest.raises(ValueError, match="does not change"):
        family.plastic_junctions_truth.__wrapped__(still, 1.0)


# -- the mechanisms themselves (no case, no diagnosis) ---------------------------------------


def test_tomlinson_contacts_slide_at_their_mean_and_reverse_symmetrically():
    # a slow ramp over many periods: the ensemble's force, divided by the steady mean the
    # truth normalises with, is 1 sliding forwards and -1 backwards (up to the ripple of
    # 256 evenly spread contacts)
    lam = 1.0
    qmax, table = family._tomlinson_branch(family.PT_ETA)
    x = np.concatenate((np.linspace(0.0, 20.0 * lam, 40001), np.linspace(20.0 * lam, 0.0,
                                                                          40001)[1:]))
    phases = lam * (np.arange(family.PT_CONTACTS) + 0.5) / family.PT_CONTACTS
    f = family._tomlinson(x, lam, phases, qmax, table) / family._tomlinson_sliding_mean(
        family.PT_ETA)
    fwd, back = f[10000:40000], f[50000:]
    assert abs(np.mean(fwd) - 1.0) < 0.01 and abs(np.mean(back) + 1.0) < 0.01
    assert np.ptp(fwd) < 0.05
    # presliding: right after the reversal the contacts unload elastically, the force
    # passes zero within a period of the corrugation and reaches the other side
    turn = f[40000:44001]
    cross = np.flatnonzero(turn < 0.0)[0]
    assert 0 < cross < 2000 and turn[-1] < -0.9


def test_rattling_part_is_a_mass_on_its_bumper_and_floats_across_the_clearance():
    # constant acceleration a0 from rest: the part lands on the rear bumper and is then
    # carried (force a0 per unit mass); when the acceleration changes sign it floats free
    t = np.linspace(0.0, 2.0, 20001)
    a0 = 1.0
    acc = np.where(t < 1.0, a0, -a0)
    v = np.concatenate(([0.0], np.cumsum(0.5 * (acc[1:] + acc[:-1]) * np.diff(t))))
    x = np.concatenate(([0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(t))))
    half = 0.01
    f = family._rattle(t, x, v, half, 200.0, 0.5, 4)
    assert np.all(np.abs(f[6000:10000] - a0) < 0.02 * a0)       # carried on the bumper
    # after the switch it crosses the 2 x 1 cm clearance in sqrt(4 half / a0) = 0.2 s
    assert np.all(f[10300:11800] == 0.0)
    assert np.all(np.abs(f[14000:] + a0) < 0.02 * a0)            # carried on the other one


def test_plastic_junctions_follow_the_load_up_and_down_only_with_the_travel():
    L = np.array([1.0, 2.0, 3.0, 1.0, 1.0, 1.0])
    still = family._junction_load(np.zeros(6), L, 1.0)
    assert list(still) == [1.0, 2.0, 3.0, 3.0, 3.0, 3.0]          # no sliding: no renewal
    moving = family._junction_load(np.arange(6.0), L, 1.0)
    assert moving[2] == 3.0 and 1.0 < moving[5] < moving[4] < moving[3] < 3.0


def test_tilted_pad_lifts_one_direction_only():
    kin = plant_kinematics("xml350", quick=True)
    dF = np.abs(family.tilted_pad_truth(kin, 1.0) - base_force(kin))
    v99 = kin.scales["v99"]
    fwd, back = dF[kin.v > 0.2 * v99], dF[kin.v < -0.2 * v99]
    assert np.median(fwd) > 20.0 * max(np.median(back), 1e-12)


def test_end_cushion_drags_only_into_the_end():
    kin = plant_kinematics("valve", quick=True)
    dF = family.end_cushion_truth(kin, 1.0) - base_force(kin)
    v99 = kin.scales["v99"]
    assert np.all(dF >= -1e-9)                                  # a drag against v > 0
    assert np.max(np.abs(dF[kin.v < -0.1 * v99])) < 1e-4 * np.max(dF)
    assert np.max(dF) > 0.0


@pytest.mark.slow
def test_seen7_forms_reach_their_size_on_every_plant():
    # the sizing check: every form reaches 0.96 of the requested size at strengths 0.5 and
    # 1 on every plant it applies to (quick protocols), so the open grid's count of its
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
                assert 0.96 <= share <= 1.06, (plant, effect, form, strength, share)
                cases += 2 * (share >= MIN_SIZE)
    assert cases == 176
