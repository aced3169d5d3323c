"""The second seen truth family (diagnosis.benchmark.seen2, sealed in session 8, now open):
each form builds a finite case of the requested size on a plant's motion and grows with its
amplitude factor."""
import numpy as np
import pytest

from diagnosis.benchmark import plant_kinematics

#: the family's form of each effect
FORM = {"acceleration": "contact_aging", "load": "load_stribeck", "asymmetry": "lip_roll",
        "stribeck_shape": "film_liftoff", "position": "bent_rail", "inertia": "geared_inertia",
        "delay": "sigma_delta", "drift": "archard_wear", "backlash": "spring_loaded",
        "gms": "bliman_sorine"}
#: a plant each form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s; the load form's Stribeck region is too narrow there, the
#: isolator's low-speed excess carries it)
PLANT = {"acceleration": "xml350", "load": "mre_isolator", "asymmetry": "xml350",
         "stribeck_shape": "xml350", "position": "xml350", "inertia": "xml350",
         "delay": "xml350", "drift": "xml350", "backlash": "xml350", "gms": "xml350"}


def test_seen2_forms_refuse_plants_they_do_not_apply_to():
    from diagnosis.benchmark.seen2 import bliman_sorine_truth, film_liftoff_truth
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        film_liftoff_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        bliman_sorine_truth(iso, 1.0)
    # a one-way stroke (the press's) never revisits a position: no rail defect to learn
    import dataclasses
    from diagnosis.benchmark.kinematics import fine_kinematics
    from diagnosis.benchmark.seen2 import bent_rail_truth
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        bent_rail_truth.__wrapped__(one_way, 1.0)
