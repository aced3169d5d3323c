"""The fourth seen truth family (diagnosis.benchmark.seen4, sealed in session 10, run once,
now open): each form builds a finite case of the requested size on every plant it applies
to, is the base law at s = 0 and grows with its amplitude factor."""
import dataclasses

import numpy as np
import pytest

from diagnosis.benchmark import plant_kinematics

#: the family's form of each effect
FORM = {"acceleration": "rolling_skid", "load": "junction_creep",
        "asymmetry": "rod_seal_film", "stribeck_shape": "log_weakening",
        "position": "cogging", "inertia": "basset_added_mass", "delay": "clock_skew",
        "drift": "third_body", "backlash": "oil_filled_gap", "gms": "zener_junction"}
#: a plant each form reaches the requested size on (quick protocols: the XML-350's
#: kinematics take 0.1 s)
PLANT = {"acceleration": "xml350", "load": "xml350", "asymmetry": "xml350",
         "stribeck_shape": "xml350", "position": "xml350", "inertia": "xml350",
         "delay": "xml350", "drift": "xml350", "backlash": "xml350", "gms": "xml350"}


def test_seen4_forms_refuse_plants_they_do_not_apply_to():
    from diagnosis.benchmark.kinematics import fine_kinematics
    from diagnosis.benchmark.seen4 import (cogging_truth, log_weakening_truth,
                                           oil_filled_gap_truth, zener_junction_truth)
    iso = plant_kinematics("mre_isolator", quick=True)
    with pytest.raises(ValueError, match="Stribeck"):
        log_weakening_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        zener_junction_truth(iso, 1.0)
    with pytest.raises(ValueError, match="LuGre"):
        oil_filled_gap_truth(iso, 1.0)
    # a one-way stroke (the press's) never revisits a position: no detent map to learn
    fk = fine_kinematics(plant_kinematics("xml350", quick=True))
    one_way = dataclasses.replace(fk, x=np.linspace(0.0, 1e-2, fk.t.size))
    with pytest.raises(ValueError, match="revisits"):
        cogging_truth.__wrapped__(one_way, 1.0)

