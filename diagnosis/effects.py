"""The library of named effects: **one record per effect** (:class:`Effect`, :data:`EFFECTS`).

A record gathers everything the library knows about an effect, so adding one touches one
place. Every list the rest of the package uses is derived from :data:`EFFECTS`:

==================================  ============================================================
derived name                        what it is
==================================  ============================================================
:data:`EFFECT_NAMES`                the candidates, in the order they are tried
:data:`CANDIDATES`                  name -> candidate builder (:class:`.candidates.Candidate`)
:data:`FORCE_EFFECTS`               effects evaluated on the law's output force
                                    (:class:`.effect_law.EffectLaw`, ``friction_effects`` block)
:data:`FMU_EFFECTS`                 effects the trajectory level's FMU engine can express
:data:`LEVELS`, :data:`INPUTS`      force effects -> parameters whose zero switches them off,
                                    signals their formula reads
:data:`EXPECTED_FAMILIES`           region families the gap of each effect concentrates in
                                    (benchmark localisation)
:data:`EXPECTED_EVIDENCE`           evidence families of each effect (benchmark)
``diagnosis.benchmark.CASES``       effects with truth forms, plus ``clean`` and ``outside``
==================================  ============================================================

How to add an effect
--------------------
1. Write its candidate in a module of its own, ``diagnosis/effects_<name>.py``: a subclass of
   :class:`diagnosis.candidates.Candidate` (import it from :mod:`diagnosis.candidates`, never
   from this module, which imports yours) with
   ``extras(ctx)`` (its parameters: name, start, box from the fit data's scales, unit),
   ``apply(F, p, data, ctx)`` (its formula on the base law's force) or ``modify_law`` (a law
   of the friction package with more free parameters), and where needed ``force_extras``,
   ``start``, ``practical``, ``applicable``, ``held_out_reason``, ``specialise``,
   ``own_law_names``, ``inside`` (a relative level the force level applies inside a classic
   LuGre's bristle dynamics: ``stribeck_shape`` and ``load`` specialise to such forms
   there). Its truth forms may live beside it (``diagnosis/effects_backlash.py``).
2. Write its truth forms for the benchmark: functions ``truth(kin, s) -> F`` [N] (``kin`` a
   :class:`diagnosis.benchmark.PlantKinematics`: the plant's ``t, x, v, a, load`` and its
   ``base`` law; ``s`` an amplitude factor the benchmark calibrates to the requested
   strength), each a mechanism of different physics from the candidate's formula,
   integrated on a grid finer than the data (:data:`diagnosis.benchmark.kinematics.FINE`,
   :func:`~diagnosis.benchmark.kinematics.fine_motion`); optionally a generic truth
   ``truth(s, t, x, v, a) -> (F, load)`` on the mass-like axis of
   :func:`diagnosis.benchmark.make_case`, and ``applies(kin) -> bool`` for plants it does
   not apply to.
3. Add one :class:`Effect` to :data:`EFFECTS` below (its position is the order candidates
   are tried and benchmark cases are run), giving

   * ``candidate``: the builder, constructed with the effect's ``name``, a one-line
     ``description`` and its ``stage`` (``modify_law``, ``multiplicative``, ``additive``,
     ``shift``: the order effects compose in);
   * ``plant_entry``: how the trajectory level puts it into a simulated plant - ``"law"``
     (the candidate's ``modify_law``: a law of the friction package, so the friction FMU of
     that law carries it), ``"twins"`` (the law's direction twins and offset), ``"force"``
     (its formula on the law's output, inside :class:`.effect_law.EffectLaw`; needs the
     formula in :func:`friction.extensions.extension_force`), ``"mass"`` (the plant's
     moving mass), ``"delay"`` (a time shift of the output) or ``""`` (force level only);
   * ``fmu``: whether the trajectory level's FMU engine can express it (a ``"force"``
     entry only when :data:`friction.extensions.EXTENSIONS` has it: the ``friction_effects``
     block runs that formula; a ``"law"`` entry when its law has an FMU);
   * ``levels`` and ``inputs`` (``"force"`` entries): the parameters whose zero switches it
     off, and the signals its formula reads besides ``v`` (``a``, ``x``, ``load``);
   * ``families`` / ``evidence``: where its gap should show (region families of
     :func:`diagnosis.benchmark.localise`: ``direction``, ``accel/decel``, ``pre-sliding``,
     ``|v|``, ``|a|``, ``x``, ``t``, ``load``, ``frequency``; evidence families add
     ``dF/dt``);
   * ``truths``: form name -> ``"module:function"`` (or the function) of step 2, the first
     the benchmark's default, all of them in its generalisation grid (at least three, from
     different physics); ``sealed``: one more form written once and kept out of all tuning
     (:mod:`diagnosis.benchmark.sealed`; once its results have been seen it joins
     ``truths``, as :mod:`diagnosis.benchmark.seen` to :mod:`diagnosis.benchmark.seen36`
     did, and a new one is written);
     ``generic_truth`` and ``truth_applies`` likewise.

   Its parameters, units and bounds are the candidate's (:meth:`Effect.parameters`).
4. Nothing else: the force level, the trajectory level, the FMU engine, the report and the
   benchmark read the record. ``tests/test_diagnosis_layout.py`` checks every record
   (truths resolve, force entries are extensions, FMU claims hold).
"""
from __future__ import annotations

import importlib
from dataclasses import dataclass, field
from typing import Callable, Mapping, Union

from friction.extensions import EXTENSIONS, POSITION_NAMES

# the candidate builders, and what the rest of the package has always imported from here
from .candidates import (Candidate, Context, Extra,  # noqa: F401
                         MAX_FILTER_SAMPLES, Presliding, make_context)
# candidates in modules of their own (backlash's and gms's with their truth forms)
from .effects_acceleration import Acceleration
from .effects_asymmetry import Asymmetry, AsymmetryTwins
from .effects_backlash import Backlash
from .effects_delay import Delay
from .effects_drift import Drift
from .effects_gms import GMSCandidate
from .effects_inertia import Inertia
from .effects_load import Load
from .effects_position import Position
from .effects_stribeck import StribeckShape

__all__ = ["Effect", "EFFECTS", "EFFECT_NAMES", "CANDIDATES", "FORCE_EFFECTS", "FMU_EFFECTS",
           "LEVELS", "INPUTS", "EXPECTED_FAMILIES", "EXPECTED_EVIDENCE", "PLANT_ENTRIES", "Candidate",
           "Context", "Extra", "make_context", "Acceleration", "Load", "Drift", "Asymmetry",
           "AsymmetryTwins", "Position", "Inertia", "Delay", "StribeckShape", "Presliding",
           "MAX_FILTER_SAMPLES", "resolve"]

#: how an effect enters a simulated plant (the trajectory level), see :class:`Effect`
PLANT_ENTRIES = ("law", "twins", "force", "mass", "delay", "")

#: a function, or where to find it: ``"package.module:function"`` (imported when first used,
#: so a record can name a benchmark truth without importing the benchmark)
Ref = Union[str, Callable, None]


def resolve(ref: Ref):
    """The function a :data:`Ref` names (``None`` stays ``None``)."""
    if ref is None or callable(ref):
        return ref
    module, _, name = ref.partition(":")
    return getattr(importlib.import_module(module), name)


@dataclass(frozen=True)
class Effect:
    """Everything about one named effect (see the module docstring for how to add one).

    Parameters
    ----------
    candidate : Candidate
        The builder of the diagnosis' candidate (name, description, stage, parameters,
        formula or law).
    plant_entry : str
        How the trajectory level puts it into a plant: one of :data:`PLANT_ENTRIES`.
    fmu : bool
        The trajectory level's FMU engine can express it.
    levels : tuple of str
        ``"force"`` entries: parameters whose zero switches the effect off.
    inputs : tuple of str
        ``"force"`` entries: signals the formula reads besides the velocity (``"a"``,
        ``"x"``, ``"load"``; time is the law's own state).
    families : tuple of str
        Region families its held-out gap concentrates in (benchmark localisation).
    evidence : tuple of str
        Families of the residual's evidence correlations it points at (benchmark).
    truths : mapping
        Truth form name -> ``truth(kin, s) -> F`` [N] (or its ``"module:function"``); the
        first is the benchmark's default, all run in its generalisation grid.
    sealed : mapping
        Truth forms of the sealed family, as ``truths``: written once, kept out of all
        tuning, run only at the end of a piece of work and reported separately
        (:mod:`diagnosis.benchmark.sealed`).
    generic_truth : str or callable, optional
        ``truth(s, t, x, v, a) -> (F, load)`` of the generic benchmark.
    truth_applies : str or callable, optional
        ``applies(kin) -> bool``: whether the truths exist for a plant (default: always).
    """
    candidate: Candidate
    plant_entry: str = ""
    fmu: bool = False
    levels: tuple = ()
    inputs: tuple = ()
    families: tuple = ()
    evidence: tuple = ()
    truths: Mapping[str, Ref] = field(default_factory=dict)
    sealed: Mapping[str, Ref] = field(default_factory=dict)
    generic_truth: Ref = None
    truth_applies: Ref = None

    def __post_init__(self):
        if self.plant_entry not in PLANT_ENTRIES:
            raise ValueError(f"plant_entry = {self.plant_entry!r} is out of bounds: choose "
                             f"from {PLANT_ENTRIES}")
        if self.plant_entry == "force" and not self.levels:
            raise ValueError(f"effect {self.name!r}: a force entry needs its levels")

    @property
    def name(self) -> str:
        """The effect's name (the candidate's)."""
        return self.candidate.name

    @property
    def description(self) -> str:
        """One line on what the effect is."""
        return self.candidate.description

    def parameters(self, ctx: Context, level: str = "force") -> list:
        """The effect's parameters with their units and bounds for the fit data ``ctx``.

        Parameters
        ----------
        ctx : Context
            Scales of the fit data (:func:`make_context`).
        level : {"force", "trajectory", "formula"}
            Those fitted at the friction-force level (:meth:`Candidate.force_extras`), at
            the trajectory level (:meth:`Candidate.trajectory_extras`) or the formula's own
            (:meth:`Candidate.extras`).

        Returns
        -------
        list of Extra
            Name, start, lower and upper bound (physical units) and unit of each.
        """
        get = {"force": self.candidate.force_extras, "formula": self.candidate.extras,
               "trajectory": self.candidate.trajectory_extras}
        if level not in get:
            raise ValueError(f"level must be one of {sorted(get)}, got {level!r}")
        # a law-changing candidate's own parameters are law parameters (backlash's gap)
        own = getattr(self.candidate, "law_extras", None)
        return get[level](ctx) + (own(ctx) if own is not None else [])

    def truth(self, form: str | None = None) -> Callable:
        """The truth form ``form`` (default: the first; sealed forms included) as a function
        ``(kin, s) -> F``."""
        if not self.truths:
            raise ValueError(f"effect {self.name!r} has no truth forms")
        form = next(iter(self.truths)) if form is None else form
        every = {**self.truths, **self.sealed}
        if form not in every:
            raise ValueError(f"unknown truth form {form!r} of {self.name!r}; choose from "
                             f"{list(every)}")
        return resolve(every[form])

    def forms(self, family: str = "all") -> tuple:
        """Names of the truth forms of ``family``: ``"first"`` (the default form),
        ``"all"`` (every open form) or ``"sealed"``."""
        if family not in ("first", "all", "sealed"):
            raise ValueError(f"family must be 'first', 'all' or 'sealed', got {family!r}")
        if family == "sealed":
            return tuple(self.sealed)
        return tuple(self.truths)[:1] if family == "first" else tuple(self.truths)

    def applies(self, kin) -> bool:
        """Whether the truth forms exist for the plant motion ``kin``."""
        fn = resolve(self.truth_applies)
        return True if fn is None else bool(fn(kin))


_T = "diagnosis.benchmark.truths:"
_F = "diagnosis.benchmark.forms:"
_O = "diagnosis.benchmark.seen:"
_S = "diagnosis.benchmark.sealed:"
_S2 = "diagnosis.benchmark.seen2:"
_S3 = "diagnosis.benchmark.seen3:"
_S4 = "diagnosis.benchmark.seen4:"
_S5 = "diagnosis.benchmark.seen5:"
_S6 = "diagnosis.benchmark.seen6:"
_S7 = "diagnosis.benchmark.seen7:"
_S8 = "diagnosis.benchmark.seen8:"
_S9 = "diagnosis.benchmark.seen9:"
_S10 = "diagnosis.benchmark.seen10:"
_S11 = "diagnosis.benchmark.seen11:"
_S12 = "diagnosis.benchmark.seen12:"
_S13 = "diagnosis.benchmark.seen13:"
_S14 = "diagnosis.benchmark.seen14:"
_S15 = "diagnosis.benchmark.seen15:"
_S16 = "diagnosis.benchmark.seen16:"
_S17 = "diagnosis.benchmark.seen17:"
_S18 = "diagnosis.benchmark.seen18:"
_S19 = "diagnosis.benchmark.seen19:"
_S20 = "diagnosis.benchmark.seen20:"
_S21 = "diagnosis.benchmark.seen21:"
_S22 = "diagnosis.benchmark.seen22:"
_S23 = "diagnosis.benchmark.seen23:"
_S24 = "diagnosis.benchmark.seen24:"
_S25 = "diagnosis.benchmark.seen25:"
_S26 = "diagnosis.benchmark.seen26:"
_S27 = "diagnosis.benchmark.seen27:"
_S28 = "diagnosis.benchmark.seen28:"
_S29 = "diagnosis.benchmark.seen29:"
_S30 = "diagnosis.benchmark.seen30:"
_S31 = "diagnosis.benchmark.seen31:"
_S32 = "diagnosis.benchmark.seen32:"
_S33 = "diagnosis.benchmark.seen33:"
_S34 = "diagnosis.benchmark.seen34:"
_S35 = "diagnosis.benchmark.seen35:"
_S36 = "diagnosis.benchmark.seen36:"
_B = "diagnosis.effects_backlash:"
_G = "diagnosis.effects_gms:"


class _SealedForm(Mapping):
    """The sealed family's form of one effect as an effect record's ``sealed`` mapping
    (``{form: ref}``), read from :data:`diagnosis.benchmark.sealed.FORMS` when first asked
    for: the family is written by another hand and its forms are named only there."""

    def __init__(self, effect: str):
        self._effect = effect

    def _forms(self) -> dict:
        form = importlib.import_module("diagnosis.benchmark.sealed").FORMS[self._effect]
        return {form: _S + f"{form}_truth"}

    def __getitem__(self, form: str) -> Ref:
        return self._forms()[form]

    def __iter__(self):
        return iter(self._forms())

    def __len__(self) -> int:
        return 1

    def __repr__(self) -> str:
        return f"_SealedForm({self._effect!r})"


#: every named effect, in the order the candidates are tried
EFFECTS: dict[str, Effect] = {e.name: e for e in (
    Effect(Acceleration("acceleration", "acceleration-dependent part / frictional lag "
                        "(seed 000), levels raised by |a|", "additive"),
           plant_entry="force", fmu=True, levels=("f_a", "f_e", "f_o"), inputs=("a",),
           families=("accel/decel", "|a|"), evidence=("|a|",),
           truths={"lagged_fd": _T + "acceleration_truth",
                   "frictional_memory": _F + "frictional_memory_truth",
                   "slip_memory": _F + "slip_memory_truth",
                   "film_dynamics": _O + "film_dynamics_truth",
                   "contact_aging": _S2 + "contact_aging_truth",
                   "flash_temperature": _S3 + "flash_temperature_truth",
                   "rolling_skid": _S4 + "rolling_skid_truth",
                   "moment_load": _S5 + "moment_load_truth",
                   "cylinder_pressure": _S6 + "cylinder_pressure_truth",
                   "motor_attraction": _S7 + "motor_attraction_truth",
                   "pitch_squeeze": _S8 + "pitch_squeeze_truth",
                   "weight_transfer": _S9 + "weight_transfer_truth",
                   "oil_slosh": _S10 + "oil_slosh_truth",
                   "dilatancy_hardening": _S11 + "dilatancy_hardening_truth",
                   "tilt_wedge": _S12 + "tilt_wedge_truth",
                   "sprung_gib": _S13 + "sprung_gib_truth",
                   "payne_softening": _S14 + "payne_softening_truth",
                   "swing_arm_roller": _S15 + "swing_arm_roller_truth",
                   "jerk_unloading": _S16 + "jerk_unloading_truth",
                   "aerostatic_tilt": _S17 + "aerostatic_tilt_truth",
                   "ball_train": _S18 + "ball_train_truth",
                   "current_ripple": _S19 + "current_ripple_truth",
                   "rack_flank_sliding": _S20 + "rack_flank_sliding_truth",
                   "cone_sensor_brake": _S21 + "cone_sensor_brake_truth",
                   "inertia_valve_damper": _S22 + "inertia_valve_damper_truth",
                   "belt_creep": _S23 + "belt_creep_truth",
                   "gantry_racking": _S24 + "gantry_racking_truth",
                   "band_capstan": _S25 + "band_capstan_truth",
                   "feed_line_surge": _S26 + "feed_line_surge_truth",
                   "self_loading_drive": _S27 + "self_loading_drive_truth",
                   "winding_heat": _S28 + "winding_heat_truth",
                   "elastic_counterweight": _S29 + "elastic_counterweight_truth",
                   "inertia_lubricator": _S30 + "inertia_lubricator_truth",
                   "slack_belt": _S31 + "slack_belt_truth",
                   "nut_liftoff": _S32 + "nut_liftoff_truth",
                   "bowed_screw": _S33 + "bowed_screw_truth",
                   "energised_seals": _S34 + "energised_seals_truth",
                   "worm_mesh": _S35 + "worm_mesh_truth",
                   "slip_coupling": _S36 + "slip_coupling_truth"},
           sealed=_SealedForm("acceleration"),
           generic_truth=_T + "acceleration_generic"),
    Effect(Load("load", "friction levels depend on the normal load (seed 004)",
                "multiplicative"),
           plant_entry="force", fmu=True, levels=("k_L",), inputs=("load",),
           families=("load",), evidence=("load",),
           truths={"load_lugre": _T + "load_truth", "hertz_contact": _F + "hertz_contact_truth",
                   "one_sided_seal": _F + "one_sided_seal_truth",
                   "squeeze_film": _O + "squeeze_film_truth",
                   "load_stribeck": _S2 + "load_stribeck_truth",
                   "film_breakdown": _S3 + "film_breakdown_truth",
                   "junction_creep": _S4 + "junction_creep_truth",
                   "normal_vibration": _S5 + "normal_vibration_truth",
                   "pivot_lever": _S6 + "pivot_lever_truth",
                   "plastic_junctions": _S7 + "plastic_junctions_truth",
                   "hydrostatic_overload": _S8 + "hydrostatic_overload_truth",
                   "squeeze_cavitation": _S9 + "squeeze_cavitation_truth",
                   "piezoviscous_film": _S10 + "piezoviscous_film_truth",
                   "full_contact": _S11 + "full_contact_truth",
                   "flash_desorption": _S12 + "flash_desorption_truth",
                   "scuffing_healing": _S13 + "scuffing_healing_truth",
                   "normal_stress_memory": _S14 + "normal_stress_memory_truth",
                   "jkr_adhesion": _S15 + "jkr_adhesion_truth",
                   "overhung_load": _S16 + "overhung_load_truth",
                   "preload_relief": _S17 + "preload_relief_truth",
                   "ploughing_onset": _S18 + "ploughing_onset_truth",
                   "viscoelastic_rolling": _S19 + "viscoelastic_rolling_truth",
                   "heathcote_slip": _S20 + "heathcote_slip_truth",
                   "pin_in_bore": _S21 + "pin_in_bore_truth",
                   "ball_spin": _S22 + "ball_spin_truth",
                   "disc_spring_pad": _S23 + "disc_spring_pad_truth",
                   "light_load_skid": _S24 + "light_load_skid_truth",
                   "constant_flow_pad": _S25 + "constant_flow_pad_truth",
                   "bedded_rail": _S26 + "bedded_rail_truth",
                   "pv_heated_liner": _S27 + "pv_heated_liner_truth",
                   "soft_film_pressure": _S28 + "soft_film_pressure_truth",
                   "clamping_cylinder": _S29 + "clamping_cylinder_truth",
                   "crowned_rollers": _S30 + "crowned_rollers_truth",
                   "wheel_sinkage": _S31 + "wheel_sinkage_truth",
                   "sinking_wiper": _S32 + "sinking_wiper_truth",
                   "magnet_preload": _S33 + "magnet_preload_truth",
                   "toggle_clamp": _S34 + "toggle_clamp_truth",
                   "ball_hysteresis": _S35 + "ball_hysteresis_truth",
                   "porous_bushing": _S36 + "porous_bushing_truth"},
           sealed=_SealedForm("load"),
           generic_truth=_T + "load_generic"),
    Effect(Asymmetry("asymmetry", "direction-dependent levels and offset (seeds 000, 003), or "
                     "a drag of each direction beside the contact",
                     "additive"),
           plant_entry="twins", fmu=True, families=("direction",), evidence=("direction",),
           truths={"twins": _T + "asymmetry_truth",
                   "stribeck_twins": _F + "stribeck_twins_truth",
                   "viscous_twin": _F + "viscous_twin_truth",
                   "direction_curve": _O + "direction_curve_truth",
                   "lip_roll": _S2 + "lip_roll_truth",
                   "thrust_bearing": _S3 + "thrust_bearing_truth",
                   "rod_seal_film": _S4 + "rod_seal_film_truth",
                   "ratchet_texture": _S5 + "ratchet_texture_truth",
                   "spring_return": _S6 + "spring_return_truth",
                   "tilted_pad": _S7 + "tilted_pad_truth",
                   "sprag_strut": _S8 + "sprag_strut_truth",
                   "meter_out_throttle": _S9 + "meter_out_throttle_truth",
                   "differential_cylinder": _S10 + "differential_cylinder_truth",
                   "chevron_grooves": _S11 + "chevron_grooves_truth",
                   "helical_buckling": _S12 + "helical_buckling_truth",
                   "chip_scraper": _S13 + "chip_scraper_truth",
                   "hall_commutation": _S14 + "hall_commutation_truth",
                   "belt_idler": _S15 + "belt_idler_truth",
                   "freewheel_roller": _S16 + "freewheel_roller_truth",
                   "felt_lubricator": _S17 + "felt_lubricator_truth",
                   "running_belt": _S18 + "running_belt_truth",
                   "leaning_brush": _S19 + "leaning_brush_truth",
                   "sealing_band": _S20 + "sealing_band_truth",
                   "counterbalance_valve": _S21 + "counterbalance_valve_truth",
                   "elliptic_vibration": _S22 + "elliptic_vibration_truth",
                   "fluidic_diode": _S23 + "fluidic_diode_truth",
                   "pitching_pads": _S24 + "pitching_pads_truth",
                   "roller_skew": _S25 + "roller_skew_truth",
                   "lifting_screw": _S26 + "lifting_screw_truth",
                   "coriolis_slide": _S27 + "coriolis_slide_truth",
                   "angled_pull": _S28 + "angled_pull_truth",
                   "gecko_wedges": _S29 + "gecko_wedges_truth",
                   "charging_generator": _S30 + "charging_generator_truth",
                   "cup_paddle": _S31 + "cup_paddle_truth",
                   "coolant_stream": _S32 + "coolant_stream_truth",
                   "clapper_tool": _S33 + "clapper_tool_truth",
                   "plunger_pump": _S34 + "plunger_pump_truth",
                   "trailing_hose": _S35 + "trailing_hose_truth",
                   "magnetic_conveyor": _S36 + "magnetic_conveyor_truth"},
           sealed=_SealedForm("asymmetry"),
           generic_truth=_T + "asymmetry_generic"),
    Effect(StribeckShape("stribeck_shape",
                         "Stribeck curve shape: exponent, Lorentzian, a speed map, a drag beside "
                         "the contact",
                         "modify_law"),
           plant_entry="law", fmu=True, families=("|v|", "pre-sliding"),
           truths={"exponential_tail": _T + "stribeck_shape_truth",
                   "rational": _F + "rational_truth", "hydrodynamic": _F + "hydrodynamic_truth",
                   "stiction_spike": _O + "stiction_spike_truth",
                   "film_liftoff": _S2 + "film_liftoff_truth",
                   "bimodal_roughness": _S3 + "bimodal_roughness_truth",
                   "log_weakening": _S4 + "log_weakening_truth",
                   "eyring_boundary": _S5 + "eyring_boundary_truth",
                   "starved_film": _S6 + "starved_film_truth",
                   "rubber_hysteresis": _S7 + "rubber_hysteresis_truth",
                   "contact_resonance": _S8 + "contact_resonance_truth",
                   "dither_averaging": _S9 + "dither_averaging_truth",
                   "melt_lubrication": _S10 + "melt_lubrication_truth",
                   "granular_flow": _S11 + "granular_flow_truth",
                   "readsorption": _S12 + "readsorption_truth",
                   "thermoviscous_film": _S13 + "thermoviscous_film_truth",
                   "turbulent_film": _S14 + "turbulent_film_truth",
                   "thixotropic_grease": _S15 + "thixotropic_grease_truth",
                   "churning_drag": _S16 + "churning_drag_truth",
                   "core_loss_drag": _S17 + "core_loss_drag_truth",
                   "bellows_breathing": _S18 + "bellows_breathing_truth",
                   "eddy_brake": _S19 + "eddy_brake_truth",
                   "shear_thinning_oil": _S20 + "shear_thinning_oil_truth",
                   "flying_pad": _S21 + "flying_pad_truth",
                   "wiping_meniscus": _S22 + "wiping_meniscus_truth",
                   "sommerfeld_journal": _S23 + "sommerfeld_journal_truth",
                   "wall_slip": _S24 + "wall_slip_truth",
                   "thermal_closure": _S25 + "thermal_closure_truth",
                   "dwell_squeeze": _S26 + "dwell_squeeze_truth",
                   "suction_pocket": _S27 + "suction_pocket_truth",
                   "capillary_condensation": _S28 + "capillary_condensation_truth",
                   "flash_weakening": _S29 + "flash_weakening_truth",
                   "peel_adhesion": _S30 + "peel_adhesion_truth",
                   "measuring_wheel": _S31 + "measuring_wheel_truth",
                   "governor_shoes": _S32 + "governor_shoes_truth",
                   "battery_dynamo": _S33 + "battery_dynamo_truth",
                   "floating_pawl": _S34 + "floating_pawl_truth",
                   "dielectric_pad": _S35 + "dielectric_pad_truth",
                   "spin_off": _S36 + "spin_off_truth"},
           sealed=_SealedForm("stribeck_shape"),
           generic_truth=_T + "stribeck_shape_generic",
           truth_applies=_T + "has_stribeck_curve"),
    Effect(Presliding("presliding", "bristle dynamics missing from a static map",
                      "modify_law"),
           plant_entry="law", fmu=True, families=("pre-sliding",)),
    Effect(Position("position", "friction level varying along the stroke (and a force of "
                             "the position)", "multiplicative"),
           plant_entry="force", fmu=True, levels=POSITION_NAMES, inputs=("x",),
           families=("x",), evidence=("x",),
           truths={"local_defect": _T + "position_truth", "waviness": _F + "waviness_truth",
                   "worn_section": _F + "worn_section_truth",
                   "screw_runout": _O + "screw_runout_truth",
                   "bent_rail": _S2 + "bent_rail_truth",
                   "transfer_film": _S3 + "transfer_film_truth",
                   "cogging": _S4 + "cogging_truth",
                   "preload_taper": _S5 + "preload_taper_truth",
                   "oil_pocket": _S6 + "oil_pocket_truth",
                   "end_cushion": _S7 + "end_cushion_truth",
                   "telescopic_cover": _S8 + "telescopic_cover_truth",
                   "air_spring": _S9 + "air_spring_truth",
                   "bolt_holes": _S10 + "bolt_holes_truth",
                   "immersed_plunger": _S11 + "immersed_plunger_truth",
                   "beam_sag": _S12 + "beam_sag_truth",
                   "festoon_cable": _S13 + "festoon_cable_truth",
                   "curved_guide": _S14 + "curved_guide_truth",
                   "gliding_chain": _S15 + "gliding_chain_truth",
                   "cam_plunger": _S16 + "cam_plunger_truth",
                   "heated_zone": _S17 + "heated_zone_truth",
                   "false_brinelling": _S18 + "false_brinelling_truth",
                   "rail_joint": _S19 + "rail_joint_truth",
                   "rail_misalignment": _S20 + "rail_misalignment_truth",
                   "spool_flow_force": _S21 + "spool_flow_force_truth",
                   "crank_transmission": _S22 + "crank_transmission_truth",
                   "drawer_overhang": _S23 + "drawer_overhang_truth",
                   "track_end": _S24 + "track_end_truth",
                   "cable_reel": _S25 + "cable_reel_truth",
                   "air_film_flatness": _S26 + "air_film_flatness_truth",
                   "conductive_strips": _S27 + "conductive_strips_truth",
                   "ball_passage": _S28 + "ball_passage_truth",
                   "ferrous_insert": _S29 + "ferrous_insert_truth",
                   "lead_preload": _S30 + "lead_preload_truth",
                   "rack_mesh": _S31 + "rack_mesh_truth",
                   "draining_film": _S32 + "draining_film_truth",
                   "hardened_zones": _S33 + "hardened_zones_truth",
                   "grit_band": _S34 + "grit_band_truth",
                   "wet_patch": _S35 + "wet_patch_truth",
                   "rust_stain": _S36 + "rust_stain_truth"},
           sealed=_SealedForm("position"),
           generic_truth=_T + "position_generic", truth_applies=_T + "revisits_positions"),
    Effect(Inertia("inertia", "mass error in the inverse dynamics", "additive"),
           plant_entry="mass", fmu=True, families=("|a|", "accel/decel"), evidence=("|a|",),
           truths={"filtered_acceleration": _T + "inertia_truth",
                   "raw_acceleration": _F + "raw_acceleration_truth",
                   "flexible_load": _F + "flexible_load_truth",
                   "cable_chain": _O + "cable_chain_truth",
                   "geared_inertia": _S2 + "geared_inertia_truth",
                   "lossy_gearing": _S3 + "lossy_gearing_truth",
                   "basset_added_mass": _S4 + "basset_added_mass_truth",
                   "dispensing_mass": _S5 + "dispensing_mass_truth",
                   "sliding_payload": _S6 + "sliding_payload_truth",
                   "rattling_mass": _S7 + "rattling_mass_truth",
                   "freewheel_flywheel": _S8 + "freewheel_flywheel_truth",
                   "pick_and_place": _S9 + "pick_and_place_truth",
                   "eddy_coupling": _S10 + "eddy_coupling_truth",
                   "centrifugal_flyweights": _S11 + "centrifugal_flyweights_truth",
                   "fluid_coupling": _S12 + "fluid_coupling_truth",
                   "telescopic_stage": _S13 + "telescopic_stage_truth",
                   "frame_recoil": _S14 + "frame_recoil_truth",
                   "force_saturation": _S15 + "force_saturation_truth",
                   "chordal_action": _S16 + "chordal_action_truth",
                   "screw_stiffness": _S17 + "screw_stiffness_truth",
                   "feedforward_lead": _S18 + "feedforward_lead_truth",
                   "abbe_pitch": _S19 + "abbe_pitch_truth",
                   "friction_damped_mount": _S20 + "friction_damped_mount_truth",
                   "spring_surge": _S21 + "spring_surge_truth",
                   "rolling_payload": _S22 + "rolling_payload_truth",
                   "rocking_block": _S23 + "rocking_block_truth",
                   "qzs_isolator": _S24 + "qzs_isolator_truth",
                   "oil_column": _S25 + "oil_column_truth",
                   "elastomer_mount": _S26 + "elastomer_mount_truth",
                   "wave_radiation": _S27 + "wave_radiation_truth",
                   "hanging_pendulum": _S28 + "hanging_pendulum_truth",
                   "friction_pendulum": _S29 + "friction_pendulum_truth",
                   "liquid_column": _S30 + "liquid_column_truth",
                   "magnet_spring": _S31 + "magnet_spring_truth",
                   "fluid_inerter": _S32 + "fluid_inerter_truth",
                   "shunted_coil": _S33 + "shunted_coil_truth",
                   "yoke_flywheel": _S34 + "yoke_flywheel_truth",
                   "winch_layers": _S35 + "winch_layers_truth",
                   "scissor_links": _S36 + "scissor_links_truth"},
           sealed=_SealedForm("inertia"),
           generic_truth=_T + "inertia_generic"),
    Effect(Delay("delay", "time shift between force and motion channels, or the force "
                       "sensor's own dynamics (a charge leak, a load cell's creep, the "
                       "transducer's resonance with its mounted mass)",
                 "shift"),
           plant_entry="delay", fmu=True, families=("|a|", "frequency", "accel/decel"),
           evidence=("dF/dt", "|a|"),
           truths={"acquisition": _T + "delay_truth",
                   "antialias_filter": _F + "antialias_filter_truth",
                   "moving_average": _F + "moving_average_truth",
                   "encoder_latency": _O + "encoder_latency_truth",
                   "sigma_delta": _S2 + "sigma_delta_truth",
                   "fieldbus_hold": _S3 + "fieldbus_hold_truth",
                   "clock_skew": _S4 + "clock_skew_truth",
                   "timing_jitter": _S5 + "timing_jitter_truth",
                   "slew_limit": _S6 + "slew_limit_truth",
                   "pressure_line": _S7 + "pressure_line_truth",
                   "running_median": _S8 + "running_median_truth",
                   "deadband_reporting": _S9 + "deadband_reporting_truth",
                   "spatial_sampling": _S10 + "spatial_sampling_truth",
                   "belt_transit": _S11 + "belt_transit_truth",
                   "aerated_load_cell": _S12 + "aerated_load_cell_truth",
                   "lossy_telemetry": _S13 + "lossy_telemetry_truth",
                   "charge_leakage": _S14 + "charge_leakage_truth",
                   "load_cell_creep": _S15 + "load_cell_creep_truth",
                   "mains_notch": _S16 + "mains_notch_truth",
                   "alpha_beta_tracker": _S17 + "alpha_beta_tracker_truth",
                   "transducer_resonance": _S18 + "transducer_resonance_truth",
                   "gauge_snubber": _S19 + "gauge_snubber_truth",
                   "magnetostrictive_wire": _S20 + "magnetostrictive_wire_truth",
                   "magnetoelastic_cell": _S21 + "magnetoelastic_cell_truth",
                   "quartz_counter": _S22 + "quartz_counter_truth",
                   "swept_grating": _S23 + "swept_grating_truth",
                   "force_restoration": _S24 + "force_restoration_truth",
                   "interleaved_adc": _S25 + "interleaved_adc_truth",
                   "pneumatic_balance": _S26 + "pneumatic_balance_truth",
                   "dual_slope_adc": _S27 + "dual_slope_adc_truth",
                   "adaptive_filter": _S28 + "adaptive_filter_truth",
                   "fixed_point_filter": _S29 + "fixed_point_filter_truth",
                   "polynomial_smoother": _S30 + "polynomial_smoother_truth",
                   "disturbance_observer": _S31 + "disturbance_observer_truth",
                   "pulsation_comb": _S32 + "pulsation_comb_truth",
                   "complementary_fusion": _S33 + "complementary_fusion_truth",
                   "acoustic_link": _S34 + "acoustic_link_truth",
                   "bucket_brigade": _S35 + "bucket_brigade_truth",
                   "rolling_shutter": _S36 + "rolling_shutter_truth"},
           sealed=_SealedForm("delay"),
           generic_truth=_T + "delay_generic"),
    Effect(Drift("drift", "friction level changing over time (e.g. warming)",
                 "multiplicative"),
           plant_entry="force", fmu=True, levels=("k_drift",), families=("t",),
           evidence=("t",),
           truths={"saturating_warm_up": _T + "drift_truth",
                   "linear_wear_in": _F + "linear_wear_in_truth",
                   "lubricant_step": _F + "lubricant_step_truth",
                   "thermal": _O + "thermal_truth",
                   "archard_wear": _S2 + "archard_wear_truth",
                   "humidity_cycle": _S3 + "humidity_cycle_truth",
                   "third_body": _S4 + "third_body_truth",
                   "interval_lubrication": _S5 + "interval_lubrication_truth",
                   "seal_relaxation": _S6 + "seal_relaxation_truth",
                   "tribo_oxide": _S7 + "tribo_oxide_truth",
                   "antioxidant_depletion": _S8 + "antioxidant_depletion_truth",
                   "coating_wear_through": _S9 + "coating_wear_through_truth",
                   "polymer_swelling": _S10 + "polymer_swelling_truth",
                   "zddp_tribofilm": _S11 + "zddp_tribofilm_truth",
                   "particle_ingress": _S12 + "particle_ingress_truth",
                   "differential_expansion": _S13 + "differential_expansion_truth",
                   "shear_degradation": _S14 + "shear_degradation_truth",
                   "magnet_heating": _S15 + "magnet_heating_truth",
                   "tribocharging": _S16 + "tribocharging_truth",
                   "cage_creep": _S17 + "cage_creep_truth",
                   "screw_loosening": _S18 + "screw_loosening_truth",
                   "film_dewetting": _S19 + "film_dewetting_truth",
                   "grease_channelling": _S20 + "grease_channelling_truth",
                   "receiver_pressure": _S21 + "receiver_pressure_truth",
                   "spall_growth": _S22 + "spall_growth_truth",
                   "oil_evaporation": _S23 + "oil_evaporation_truth",
                   "pump_down": _S24 + "pump_down_truth",
                   "additive_settling": _S25 + "additive_settling_truth",
                   "wax_crystallisation": _S26 + "wax_crystallisation_truth",
                   "grease_oil_bleed": _S27 + "grease_oil_bleed_truth",
                   "thermostat_cycling": _S28 + "thermostat_cycling_truth",
                   "lining_glazing": _S29 + "lining_glazing_truth",
                   "carbon_tribolayer": _S30 + "carbon_tribolayer_truth",
                   "frost_layer": _S31 + "frost_layer_truth",
                   "jr_clamp": _S32 + "jr_clamp_truth",
                   "solenoid_coil": _S33 + "solenoid_coil_truth",
                   "magnetic_aftereffect": _S34 + "magnetic_aftereffect_truth",
                   "leaking_bladder": _S35 + "leaking_bladder_truth",
                   "battery_magnet": _S36 + "battery_magnet_truth"},
           sealed=_SealedForm("drift"),
           generic_truth=_T + "drift_generic"),
    Effect(Backlash("backlash", "lost motion at the reversals between drive and contact",
                    "modify_law"),
           plant_entry="law", fmu=True, families=("pre-sliding", "|v|", "accel/decel"),
           truths={"rigid": _B + "backlash_rigid_truth",
                   "compliant": _B + "backlash_compliant_truth",
                   "impact": _B + "backlash_impact_truth",
                   "spring_loaded": _S2 + "spring_loaded_truth",
                   "eccentric_gear": _S3 + "eccentric_gear_truth",
                   "oil_filled_gap": _S4 + "oil_filled_gap_truth",
                   "worn_gap": _S5 + "worn_gap_truth",
                   "drag_idler": _S6 + "drag_idler_truth",
                   "biased_play": _S7 + "biased_play_truth",
                   "slack_chain": _S8 + "slack_chain_truth",
                   "magnetic_coupling": _S9 + "magnetic_coupling_truth",
                   "preloaded_nut": _S10 + "preloaded_nut_truth",
                   "harmonic_drive": _S11 + "harmonic_drive_truth",
                   "wire_rope": _S12 + "wire_rope_truth",
                   "jaw_coupling": _S13 + "jaw_coupling_truth",
                   "hydraulic_link": _S14 + "hydraulic_link_truth",
                   "bowden_cable": _S15 + "bowden_cable_truth",
                   "reversing_clutch": _S16 + "reversing_clutch_truth",
                   "mesh_stiffness": _S17 + "mesh_stiffness_truth",
                   "polymer_gear": _S18 + "polymer_gear_truth",
                   "grease_packed_gap": _S19 + "grease_packed_gap_truth",
                   "wedge_flank": _S20 + "wedge_flank_truth",
                   "overlapped_servo": _S21 + "overlapped_servo_truth",
                   "side_loaded_pin": _S22 + "side_loaded_pin_truth",
                   "toggle_spring": _S23 + "toggle_spring_truth",
                   "graded_clearance": _S24 + "graded_clearance_truth",
                   "adhesive_flank": _S25 + "adhesive_flank_truth",
                   "powder_packed_gap": _S26 + "powder_packed_gap_truth",
                   "floating_coupling": _S27 + "floating_coupling_truth",
                   "air_cushion_gap": _S28 + "air_cushion_gap_truth",
                   "detent_ball": _S29 + "detent_ball_truth",
                   "magnet_latch": _S30 + "magnet_latch_truth",
                   "warming_fit": _S31 + "warming_fit_truth",
                   "dilatant_gap": _S32 + "dilatant_gap_truth",
                   "eddy_gap": _S33 + "eddy_gap_truth",
                   "foam_pads": _S34 + "foam_pads_truth",
                   "liquid_bridge": _S35 + "liquid_bridge_truth",
                   "swing_shackle": _S36 + "swing_shackle_truth"},
           sealed=_SealedForm("backlash"),
           generic_truth=_B + "backlash_rigid_generic", truth_applies=_B + "truth_applies"),
    Effect(GMSCandidate("gms", "multi-element presliding hysteresis (generalized "
                        "Maxwell-slip)", "modify_law"),
           plant_entry="law", fmu=True, families=("pre-sliding", "|v|"),
           truths={"maxwell10": _G + "gms_maxwell10_truth",
                   "maxwell4": _G + "gms_maxwell4_truth", "dahl": _G + "gms_dahl_truth",
                   "elastoplastic": _G + "gms_elastoplastic_truth",
                   "bliman_sorine": _S2 + "bliman_sorine_truth",
                   "bouc_wen": _S3 + "bouc_wen_truth",
                   "zener_junction": _S4 + "zener_junction_truth",
                   "mindlin_contacts": _S5 + "mindlin_contacts_truth",
                   "rate_state_presliding": _S6 + "rate_state_presliding_truth",
                   "tomlinson_asperities": _S7 + "tomlinson_asperities_truth",
                   "bond_rupture": _S8 + "bond_rupture_truth",
                   "gouge_fabric": _S9 + "gouge_fabric_truth",
                   "kinematic_hardening": _S10 + "kinematic_hardening_truth",
                   "asperity_interlocking": _S11 + "asperity_interlocking_truth",
                   "capillary_bridges": _S12 + "capillary_bridges_truth",
                   "cyclic_hardening": _S13 + "cyclic_hardening_truth",
                   "junction_peeling": _S14 + "junction_peeling_truth",
                   "unloading_microslip": _S15 + "unloading_microslip_truth",
                   "power_law_joint": _S16 + "power_law_joint_truth",
                   "junction_growth": _S17 + "junction_growth_truth",
                   "slip_avalanches": _S18 + "slip_avalanches_truth",
                   "slip_weakening": _S19 + "slip_weakening_truth",
                   "microslip_bar": _S20 + "microslip_bar_truth",
                   "contact_renewal": _S21 + "contact_renewal_truth",
                   "grease_yield": _S22 + "grease_yield_truth",
                   "superelastic_flexure": _S23 + "superelastic_flexure_truth",
                   "eyring_film": _S24 + "eyring_film_truth",
                   "viscoplastic_overstress": _S25 + "viscoplastic_overstress_truth",
                   "poroelastic_layer": _S26 + "poroelastic_layer_truth",
                   "wire_mesh_backing": _S27 + "wire_mesh_backing_truth",
                   "shear_melting_film": _S28 + "shear_melting_film_truth",
                   "hysteresis_brake": _S29 + "hysteresis_brake_truth",
                   "fibre_wiper": _S30 + "fibre_wiper_truth",
                   "band_brake": _S31 + "band_brake_truth",
                   "leaf_pack": _S32 + "leaf_pack_truth",
                   "air_shoe": _S33 + "air_shoe_truth",
                   "buckling_strut": _S34 + "buckling_strut_truth",
                   "magnet_coupling": _S35 + "magnet_coupling_truth",
                   "hanging_shoe": _S36 + "hanging_shoe_truth"},
           sealed=_SealedForm("gms"),
           generic_truth=_G + "gms_maxwell10_generic", truth_applies=_G + "truth_applies"),
)}

#: names of the candidate effects, in the order they are tried
EFFECT_NAMES = tuple(EFFECTS)
#: name -> candidate builder
CANDIDATES: dict[str, Candidate] = {n: e.candidate for n, e in EFFECTS.items()}
#: effects evaluated on the law's output force (in the packed order of
#: :data:`friction.extensions.EXTENSIONS`, the ``friction_effects`` block's)
FORCE_EFFECTS = tuple(sorted((n for n, e in EFFECTS.items() if e.plant_entry == "force"),
                             key=lambda n: EXTENSIONS.index(n) if n in EXTENSIONS
                             else len(EXTENSIONS)))
#: effects the trajectory level's FMU engine can express: law, plant and shift entries, then
#: the force effects of the ``friction_effects`` block
FMU_EFFECTS = tuple(n for n, e in EFFECTS.items() if e.fmu and e.plant_entry != "force") \
    + tuple(n for n in FORCE_EFFECTS if EFFECTS[n].fmu)
#: force effects -> the parameters whose zero makes them vanish
LEVELS = {n: EFFECTS[n].levels for n in FORCE_EFFECTS}
#: force effects -> the signals their formula reads besides the velocity
INPUTS = {n: EFFECTS[n].inputs for n in FORCE_EFFECTS}
#: region families where each effect should concentrate the held-out gap
EXPECTED_FAMILIES = {n: e.families for n, e in EFFECTS.items() if e.families}
#: families each effect should point at by the signed evidence correlations
EXPECTED_EVIDENCE = {n: e.evidence for n, e in EFFECTS.items() if e.evidence}
