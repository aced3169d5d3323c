"""The third seen truth family (diagnosis.benchmark.seen3, sealed in session 9, run once,
now open): each form builds a finite case of the requested size on a plant's motion and
grows with its amplitude factor."""
import dataclasses

import numpy as np
import pytest

from diagnosis.benchmark import plant_kinematics
from truth_form_checks import assert_zero_amplitude_is_the_base

#: the family's form of each effect
FORM = {"acceleration": "flash_temperature", "load": "film_breakdown",
        "asymmetry": "thrust_bearing", "stribeck_shape": "bimodal_roughness",
        "position": "transfer_film", "inertia": "lossy_gearing", "delay": "fieldbus_hold",
        "drift": "humidity_cycle", "backlash": "eccentric_gear", "gms": "bouc_wen"}
#: a plant each form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s)
PLANT = {"acceleration": "xml350", "load": "xml350", "asymmetry": "xml350",
         "stribeck_shape": "xml350", "position": "xml350", "inertia": "xml350",
         "delay": "xml350", "drift": "xml350", "backlash": "xml350", "gms": "xml350"}


def test_seen3_forms_refuse_plants_they_do_not_apply_to():
    from diagnosis.benchmark.kinematics import fine_kinematics
    from diagnosis.benchmark.seen3 import (bimodal_roughness_truth, bouc_wen_truth,
                                            eccentric_gear_truth, transfer_film_truth)
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        bimodal_roughness_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        bouc_wen_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        eccentric_gear_truth(iso, 1.0)
    # a one-way stroke (the press's) never revisits a position: no film pattern to learn
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        transfer_film_truth.__wrapped__(one_way, 1.0)


def test_seen3_forms_at_zero_amplitude_are_near_the_base():
    # s scales the effect from nothing: at s = 0 each form is the base law (up to its own
    # integration on the fine grid)
    assert_zero_amplitude_is_the_base(FORM, "xml350")
