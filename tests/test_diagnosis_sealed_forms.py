"""The sealed truth family (diagnosis.benchmark.sealed): each form builds a finite case of
the requested size on a plant's motion and grows with its amplitude factor. No diagnosis is
run on these forms: the family stays unseen until the end of a piece of work."""
import numpy as np
import pytest

from diagnosis.benchmark import EFFECT_SIZE, make_plant_case, plant_kinematics
from diagnosis.benchmark.runner import MIN_SIZE
from diagnosis.benchmark.truths import base_force
from diagnosis.effects import EFFECTS

#: a plant each sealed form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s; the load form's Stribeck region is too narrow there, the
#: isolator's low-speed excess carries it)
PLANT = {"acceleration": "xml350", "load": "mre_isolator", "asymmetry": "xml350",
         "stribeck_shape": "xml350", "position": "xml350", "inertia": "xml350",
         "delay": "xml350", "drift": "xml350", "backlash": "xml350", "gms": "xml350"}


def test_every_effect_with_truths_has_its_sealed_form_here():
    assert set(PLANT) == {n for n, e in EFFECTS.items() if e.truths}


@pytest.mark.parametrize("effect", sorted(PLANT))
def test_sealed_form_builds_a_case_and_grows_with_its_amplitude(effect):
    (form,) = EFFECTS[effect].forms("sealed")
    plant = PLANT[effect]
    case = make_plant_case(plant, effect, 1.0, 0.01, form=form, quick=True)
    assert np.all(np.isfinite(case.data.F)) and np.all(np.isfinite(case.truth))
    # a case the benchmark runs (the runner skips a form below MIN_SIZE of the size)
    assert case.effect_rms >= MIN_SIZE * EFFECT_SIZE, (effect, form, case.effect_rms)
    kin = plant_kinematics(plant, quick=True)
    Fb = base_force(kin)
    truth = EFFECTS[effect].truth(form)
    size = [np.sqrt(np.mean((truth(kin, s) - Fb) ** 2)) for s in (0.5, 1.0)]
    assert 0.0 < size[0] < size[1], (effect, form, size)


def test_sealed_forms_refuse_plants_they_do_not_apply_to():
    from diagnosis.benchmark.sealed import bliman_sorine_truth, film_liftoff_truth
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        film_liftoff_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        bliman_sorine_truth(iso, 1.0)
    # a one-way stroke (the press's) never revisits a position: no rail defect to learn
    import dataclasses
    from diagnosis.benchmark.kinematics import fine_kinematics
    from diagnosis.benchmark.sealed import bent_rail_truth
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        bent_rail_truth.__wrapped__(one_way, 1.0)
