"""A check the tests of the benchmark's truth families share: a form builds a case of the
requested size on a plant's motion and grows with its amplitude factor."""
import numpy as np

from diagnosis.benchmark import EFFECT_SIZE, make_plant_case, plant_kinematics
from diagnosis.benchmark.runner import MIN_SIZE
from diagnosis.benchmark.truths import base_force
from diagnosis.effects import EFFECTS


def assert_builds_and_grows(effect: str, form: str, plant: str) -> None:
    """Assert that ``effect``'s truth ``form`` makes a finite case of at least
    ``MIN_SIZE x EFFECT_SIZE`` on ``plant`` (quick protocol; below it the runner skips the
    case) and that its RMS change of the base force grows from s = 0.5 to s = 1."""
    case = make_plant_case(plant, effect, 1.0, 0.01, form=form, quick=True)
    assert np.all(np.isfinite(case.data.F)) and np.all(np.isfinite(case.truth))
    assert case.effect_rms >= MIN_SIZE * EFFECT_SIZE, (effect, form, case.effect_rms)
    kin = plant_kinematics(plant, quick=True)
    Fb = base_force(kin)
    truth = EFFECTS[effect].truth(form)
    size = [np.sqrt(np.mean((truth(kin, s) - Fb) ** 2)) for s in (0.5, 1.0)]
    assert 0.0 < size[0] < size[1], (effect, form, size)


def assert_finite_and_grow_on_every_plant(forms: dict) -> None:
    """Assert that each truth form of ``forms`` (effect -> form) is finite on every plant
    it applies to (quick protocols) and that its RMS change of the base force grows from
    s = 0.5 to s = 1. No diagnosis: only the truths."""
    from diagnosis.benchmark import PLANT_NAMES
    for plant in PLANT_NAMES:
        kin = plant_kinematics(plant, quick=True)
        Fb = base_force(kin)
        for effect, form in forms.items():
            if not EFFECTS[effect].applies(kin):
                continue
            truth = EFFECTS[effect].truth(form)
            size = []
            for s in (0.5, 1.0):
                F = truth(kin, s)
                assert F.shape == Fb.shape and np.all(np.isfinite(F)), (plant, form)
                size.append(np.sqrt(np.mean((F - Fb) ** 2)))
            assert 0.0 < size[0] < size[1], (plant, effect, form, size)


def assert_zero_amplitude_is_the_base(forms: dict, plant: str, rel: float = 0.02) -> None:
    """Assert that at s = 0 each truth form of ``forms`` (effect -> form) that applies to
    ``plant`` is the base law, to ``rel`` of the base force's spread (the forms integrate
    on the fine grid, the base too, but a stiff contact coupling may differ a little)."""
    kin = plant_kinematics(plant, quick=True)
    Fb = base_force(kin)
    sd = float(np.std(Fb))
    for effect, form in forms.items():
        if not EFFECTS[effect].applies(kin):
            continue
        F0 = EFFECTS[effect].truth(form)(kin, 0.0)
        assert np.sqrt(np.mean((F0 - Fb) ** 2)) < rel * sd, (plant, effect, form)
