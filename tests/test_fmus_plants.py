"""Plant and XML-350 part FMUs: validation, model structure, co-simulation vs reference."""
from __future__ import annotations

import numpy as np
import pytest

import plants
from friction.metrics import nrmse
from fmus.build import catalogue, validate
from fmus.testing import built_fmus

PARTS = ("xml350_mechanics", "sdpid", "lugre_feedforward", "xml350_trajectory")


@pytest.fixture(scope="session")
def plant_fmu_dir():
    import friction
    names = tuple(sorted(set(plants.PLANTS) | set(PARTS) | set(friction.MODELS) | {"mass"}))
    return built_fmus(names)


def test_catalogue_has_every_plant_and_the_loop_parts():
    cat = catalogue()
    assert set(plants.PLANTS) <= set(cat)
    assert set(PARTS) <= set(cat)


@pytest.mark.slow
def test_plant_and_part_fmus_validate_and_declare_feedthrough(plant_fmu_dir):
    import fmpy
    for name in list(plants.PLANTS) + list(PARTS):
        path = plant_fmu_dir / f"{name}.fmu"
        assert validate(path) == [], name
        md = fmpy.read_model_description(str(path))
        deps = {u.variable.name: [d.name for d in u.dependencies] for u in md.outputs}
        if name in plants.PLANTS:
            # positions and velocities are states: no direct dependence on the friction input
            assert deps["x"] == [] and deps["v"] == [], (name, deps)
            assert md.defaultExperiment.stepSize is not None


@pytest.mark.slow
@pytest.mark.parametrize("plant", ["xml350", "valve"])
def test_plant_cosimulation_matches_the_reference(plant_fmu_dir, plant):
    from fmus.plant_fmus import plant_laws, plant_proof
    cls = plants.PLANTS[plant]
    stop = min(float(cls.default_experiment.stop), 600.0 / cls.data_rate)
    for law in plant_laws(cls).values():
        r = plant_proof(plant_fmu_dir, plant, law, stop=stop, refinements=2)
        assert r["nrmse"] <= 1e-3, (plant, law.name, r)
        if r["errors"][0] > 2e-5:  # below: the fixed-step floor (valve + lugre: 3.5e-6)
            assert r["errors"][1] < r["errors"][0], (plant, law.name, r)


@pytest.mark.slow
def test_xml350_loop_from_part_fmus_matches_the_reference(plant_fmu_dir):
    from plants.studies.xml350 import run_assembled
    from plants.xml350 import XML350, xml350_friction
    from fmus.plant_fmus import xml350_loop_master
    with xml350_loop_master(plant_fmu_dir) as m:
        res = m.simulate(stop_time=0.03, step_size=1e-4)
    ref = XML350(friction=xml350_friction()).simulate(0.03, method="reference")
    assert nrmse(ref["x"], res["mechanics.x"]) < 1e-3
    # the same loop assembled in-process from the plants' steppers
    asm = run_assembled(0.03, separate_friction=True)
    assert nrmse(asm["x"], res["mechanics.x"]) < 1e-3
    assert np.ptp(res["mechanics.x"]) > 0.5 * 1e-4 * 0.1  # the stage did move


@pytest.mark.slow
def test_examples_run():
    import importlib.util
    import pathlib
    root = pathlib.Path(__file__).resolve().parents[1] / "examples"
    spec = importlib.util.spec_from_file_location("cosim_mass_friction",
                                                  root / "cosim_mass_friction.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    r = mod.run_cosim_mass_friction(show_plot=False, stop=0.3)
    assert r["nrmse"] < 1e-3
