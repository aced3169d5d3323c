"""The seen truth families (diagnosis.benchmark.seen2 to seen36: each written once by
another hand, sealed, run once at the end of a session's work, then opened) checked in one
place: each sits in the effect records' truths in the order the families were opened, after
the forms before them and outside the sealed one, each form is integrated on the fine grid
and builds a case on a plant's motion that grows with its amplitude factor. Each family's own file
(``tests/test_diagnosis_seenN_forms.py``) holds its tables (``FORM``: the form of each
effect; ``PLANT``: a plant it reaches the requested size on) and the tests of its forms'
mechanisms. A family opened later is appended to :data:`FAMILIES`."""
import importlib

import pytest

from diagnosis.benchmark import EFFECT_SIZE, make_plant_case
from diagnosis.effects import EFFECTS
from truth_form_checks import (assert_builds_and_grows, assert_finite_and_grow_on_every_plant,
                               assert_zero_amplitude_is_the_base)

#: the seen families, in the order they were opened
FAMILIES = tuple(f"seen{k}" for k in range(2, 37))
#: each family's test module (its FORM and PLANT tables)
TABLES = {name: importlib.import_module(f"test_diagnosis_{name}_forms") for name in FAMILIES}
#: the families whose forms are checked on every plant and at zero amplitude (from the
#: fourth on; the second and third have checks of their own), and those whose calibration
#: is checked on two plants (from the eleventh on; each family's slow test checks every
#: plant)
ON_EVERY_PLANT = FAMILIES[FAMILIES.index("seen4"):]
SIZED_ON_TWO_PLANTS = FAMILIES[FAMILIES.index("seen11"):]
#: families checked in the default run; the older ones' truths and calibration run with
#: ``-m slow`` (the default run's 10-minute budget: CI's pytest took 552-579 s in session 25,
#: CI 611 s in session 27; the three most recent, 9 s of wall time each on 2 workers)
RECENT = FAMILIES[-3:]


def _recent_first(names):
    """``names`` as parameters, those not in :data:`RECENT` marked slow."""
    return [n if n in RECENT else pytest.param(n, marks=pytest.mark.slow) for n in names]


@pytest.mark.parametrize("name", FAMILIES)
def test_the_family_is_in_the_open_grid_in_the_order_opened(name):
    tables = TABLES[name]
    module = importlib.import_module(f"diagnosis.benchmark.{name}")
    assert set(tables.PLANT) == set(tables.FORM) == {n for n, e in EFFECTS.items()
                                                     if e.truths}
    if hasattr(module, "FORMS"):
        assert module.FORMS == tables.FORM
    later = len(FAMILIES) - FAMILIES.index(name) - 1
    for effect, form in tables.FORM.items():
        # the families opened after it follow it; the sealed one is not in the grid
        assert EFFECTS[effect].forms("all")[-1 - later] == form, effect
        assert form not in EFFECTS[effect].forms("sealed"), effect
        truth = EFFECTS[effect].truth(form)
        assert truth is getattr(module, f"{form}_truth"), effect
        assert truth.__module__ == module.__name__, effect


@pytest.mark.parametrize("name", FAMILIES)
def test_the_family_forms_are_integrated_on_the_fine_grid(name):
    for effect, form in TABLES[name].FORM.items():
        assert getattr(EFFECTS[effect].truth(form), "fine_grid", False), form


@pytest.mark.parametrize("name,effect", [
    (n, e) if n in RECENT else pytest.param(n, e, marks=pytest.mark.slow)
    for n in FAMILIES for e in sorted(TABLES[n].PLANT)])
def test_the_form_builds_a_case_and_grows_with_its_amplitude(name, effect):
    tables = TABLES[name]
    assert_builds_and_grows(effect, tables.FORM[effect], tables.PLANT[effect])


@pytest.mark.parametrize("name", _recent_first(ON_EVERY_PLANT))
def test_the_forms_are_finite_and_grow_on_every_plant_they_apply_to(name):
    # no diagnosis: only the truths, on each plant's quick motion
    assert_finite_and_grow_on_every_plant(TABLES[name].FORM)


@pytest.mark.parametrize("plant", ["xml350", "valve"])
@pytest.mark.parametrize("name", ON_EVERY_PLANT)
def test_the_forms_at_zero_amplitude_are_the_base(name, plant):
    # s scales the effect from nothing: at s = 0 each form is the base law (up to its own
    # integration on the fine grid: the stiff couplings of the backlash forms)
    assert_zero_amplitude_is_the_base(TABLES[name].FORM, plant)


@pytest.mark.parametrize("plant", ["xml350", "valve"])
@pytest.mark.parametrize("name", _recent_first(SIZED_ON_TWO_PLANTS))
def test_the_forms_reach_their_size_on_two_plants(name, plant):
    # the calibration of the grid's cases: 0.95 to 1.05 of the requested size at strengths
    # 0.5 and 1 (quick protocols)
    for effect, form in TABLES[name].FORM.items():
        for strength in (0.5, 1.0):
            case = make_plant_case(plant, effect, strength, 0.01, form=form, quick=True)
            share = case.effect_rms / (strength * EFFECT_SIZE)
            assert 0.95 <= share <= 1.05, (plant, effect, form, strength, share)
