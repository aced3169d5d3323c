"""The recipes of the pythonfmu FMUs: which FMUs exist, their slave class, variables, vendored
packages, description and default experiment (:func:`catalogue`); :mod:`fmus.build` builds them.
"""
from __future__ import annotations

import dataclasses
from typing import Callable

from . import variables

__all__ = ["FmuRecipe", "catalogue", "LAW_EXPERIMENT"]

#: default experiment of the friction-law and mass FMUs [s]
LAW_EXPERIMENT = {"startTime": 0.0, "stopTime": 1.0, "stepSize": 1e-4}


@dataclasses.dataclass
class FmuRecipe:
    """How to build one FMU.

    Attributes
    ----------
    name : str
        File stem (``<name>.fmu``) and the key used by ``build_all(only=...)``.
    base : str
        Slave base class in :mod:`fmus.runtime` (``LawSlave``, ``MassSlave``,
        ``StepperSlave``, ``BlockSlave``).
    variables : callable
        Returns the :class:`fmus.variables.Var` list (build-time, from the repository packages).
    attributes : dict
        Class attributes of the generated slave class; the string ``{pkg:friction}`` (or
        ``{pkg:plants}``) is replaced by the FMU's unique vendored package name.
    packages : tuple of str
        Repository packages to vendor.
    description : str
    default_experiment : dict
    """
    name: str
    base: str
    variables: Callable[[], list]
    attributes: dict
    packages: tuple = ("friction",)
    description: str = ""
    default_experiment: dict = dataclasses.field(default_factory=lambda: dict(LAW_EXPERIMENT))
    #: the slave saves and restores its state (``canGetAndSetFMUstate``,
    #: ``canSerializeFMUstate``; :attr:`fmus.runtime.SlaveBase.can_get_state`)
    state: bool = True

    @property
    def model_identifier(self) -> str:
        return f"fl_{self.name}"

    def package_name(self, pkg: str) -> str:
        """The vendored name of a repository package inside this FMU (``_fl_<fmu>_<pkg>``).

        Parameters
        ----------
        pkg : str
            A repository package (``friction``, ``plants``, ``fmus``).
        """
        return f"_fl_{self.name}_{pkg}"


def _law_recipes() -> list[FmuRecipe]:
    import friction
    out = []
    for name, cls in friction.MODELS.items():
        doc = (cls.__doc__ or name).strip().splitlines()[0]
        out.append(FmuRecipe(
            name=name, base="LawSlave",
            variables=(lambda cls=cls: variables.law_variables(cls, probe=True)),
            attributes=dict(law=name, friction_package="{pkg:friction}"),
            description=f"Friction law '{name}': {doc}"))
    return out


def _mass_recipe() -> FmuRecipe:
    return FmuRecipe(name="mass", base="MassSlave", variables=variables.mass_variables,
                     attributes={}, packages=(),
                     description="Rigid mass driven by a sinusoidal force against an "
                                 "external friction force (mass+friction proof loop)")


def _effects_recipe() -> FmuRecipe:
    return FmuRecipe(name="friction_effects", base="EffectsSlave",
                     variables=variables.effects_variables,
                     attributes=dict(friction_package="{pkg:friction}"),
                     description="Friction effects block between a law FMU and a plant FMU: "
                                 "acceleration-dependent part, load-, position- and "
                                 "time-dependent levels (friction.extensions)")


def _plant_recipes() -> list[FmuRecipe]:
    """Build recipes of the plant FMUs (one per registered plant) and the XML-350 parts."""
    try:
        import plants
    except ImportError:
        return []
    out = []
    for name, cls in plants.PLANTS.items():
        de = cls.default_experiment
        doc = (cls.__doc__ or name).strip().splitlines()[0]
        out.append(FmuRecipe(
            name=name, base="StepperSlave", state=False,
            variables=(lambda cls=cls: variables.plant_variables(cls, probe=True)),
            attributes=dict(plant=name, plants_package="{pkg:plants}"),
            packages=("friction", "plants"),
            description=f"Plant '{name}' with external friction (input F_friction): {doc}",
            default_experiment={"startTime": float(de.start), "stopTime": float(de.stop),
                                "stepSize": float(de.step)}))
    out += _xml350_part_recipes()
    return out


def _xml350_part_recipes():
    """The XML-350 loop from parts: stage mechanics, SD-PID, LuGre feedforward, trajectory."""
    try:
        from plants import xml350
    except ImportError:
        return []
    mech = xml350.XML350Mechanics
    de = {"startTime": 0.0, "stopTime": float(mech.default_experiment.stop),
          "stepSize": float(mech.default_experiment.step)}
    out = [FmuRecipe(
        name="xml350_mechanics", base="StepperSlave", state=False,
        variables=lambda: variables.plant_variables(mech, probe=True),
        attributes=dict(plant="xml350:XML350Mechanics", plants_package="{pkg:plants}"),
        packages=("friction", "plants"), default_experiment=dict(de),
        description="XML-350 stage mechanics (current loop, mass, encoder) with external "
                    "friction: inputs i_cmd [A], F_friction [N]")]
    descs = {"sdpid": "State-dependent PID of seed 003 Eq. (15) (acceleration units) with "
                      "current command output i_cmd = M_ctrl u / Kf",
             "lugre_feedforward": "LuGre friction feedforward of seed 003 Eq. (16)",
             "xml350_trajectory": "S-curve point-to-point trajectory of the XML-350 tests"}
    for kind, desc in descs.items():
        out.append(FmuRecipe(
            name=kind, base="BlockSlave", state=False,
            variables=(lambda kind=kind: variables.block_variables(kind, "plants")),
            attributes=dict(block=kind, plants_package="{pkg:plants}"),
            packages=("friction", "plants"), default_experiment=dict(de), description=desc))
    return out


def catalogue() -> dict[str, FmuRecipe]:
    """All FMUs this build knows, by name (laws, ``mass``, the effects block, then plants and
    controllers)."""
    recipes = _law_recipes() + [_mass_recipe(), _effects_recipe()] + _plant_recipes()
    return {r.name: r for r in recipes}
