"""The twenty-fifth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-30 (session 29) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 30 (2026-12-01) on the code of de40d49:
176 cases, 0 skipped, 443 s wall on 2 workers. Top-1 46.0 % (81;
48.5 % of the 167 detectable; of the 9 undetectable, 4 are stribeck_shape cases, 4 delays,
1 an inertia case, all with the verdict none); mean |shrink error| 0.294 (0.186 over the
right ones); wrong names on 26 (14.8 %): acceleration -> inertia 8, acceleration ->
asymmetry 4, drift -> load 3, position -> asymmetry 3, gms -> delay 3, position -> delay 2,
acceleration -> drift 2, asymmetry -> load 1. By form: load/constant_flow_pad 19/20,
inertia/oil_column 18/20, drift/additive_settling 17/20, position/cable_reel 9/16,
gms/viscoplastic_overstress 5/12, asymmetry/roller_skew 5/20, delay/interleaved_adc 4/20,
backlash/adhesive_flank 3/12, acceleration/band_capstan 1/20,
stribeck_shape/thermal_closure 0/16. By plant: isolator 53.6 %, valve 50.0 %, forging press
46.4 %, XML-350 42.5 %, damping rig 40.0 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen24` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen24`,
:mod:`diagnosis.effects_backlash`, :mod:`diagnosis.effects_gms`) and than the candidate's
formula (:mod:`diagnosis.candidates`, ``diagnosis.effects_<name>``), taken from the friction
literature or from real machines, integrated along the plant's continuous motion on the grid
:data:`.kinematics.FINE` x finer than the data (:func:`.truths.on_fine_grid`); level changes
act inside the bristle dynamics of a LuGre base (:func:`.truths.level_inside`). ``s`` scales
each effect's amplitude monotonically from the base law at ``s`` = 0 (its calibration,
:func:`.cases._calibrate`, sets the requested size).

=================  =====================================================================
effect             form
=================  =====================================================================
acceleration       ``band_capstan``: the carriage is pulled by a steel band wrapped over
                   a fixed guide shoe; the band also accelerates a driven mass behind
                   the shoe, so its tension there, and the shoe's capstan friction
                   (Euler-Eytelwein), rise when the motion speeds up and fall, down to a
                   slack band, when it slows
load               ``constant_flow_pad``: the carriage rides on hydrostatic pads fed a
                   constant flow each: the gap at which the flow carries the load
                   narrows as its cube root, and the film's shear drag grows with the
                   load as the gap narrows, with no solid contact
asymmetry          ``roller_skew``: the way's rollers skew in their cage as they roll,
                   towards an angle that differs by direction (a guiding flange on one
                   side); their skew slides them across the track: levels that settle
                   over a travel after each reversal to a different value each way
stribeck_shape     ``thermal_closure``: the carriage's plain bushings run with a small
                   clearance that their own viscous heat closes (the shaft expands more
                   than its housing): Petroff's drag over a clearance that shrinks with
                   the friction power, a rise steeper than linear with the speed
position           ``cable_reel``: a spring-driven reel keeps the carriage's cable taut;
                   its spiral spring's pull grows with the cable paid out along the stroke
                   and the reel's bearings drag in proportion to it
inertia            ``oil_column``: the carriage drags the oil column of a hydraulic hose
                   connected to it; the column rides on the hose wall's compliance and is
                   damped by the turbulent loss of its flow: a missed mass that follows
                   slow motions wholly and lags and rings in quick ones
delay              ``interleaved_adc``: the force is digitised by two time-interleaved
                   converters taking alternate samples; the second lane's clock is
                   skewed and its words misaligned in the merge: every other force
                   sample is read late
drift              ``additive_settling``: the way's lubricant carries a solid additive
                   that settles out of its reservoir (Stokes settling of a log-normal
                   size spread): the supply at the pick-up loses it as the settling
                   front passes, and the levels rise late and slowly
backlash           ``adhesive_flank``: drive and contact are joined across a play whose
                   flanks are lined with a tacky (adhesive) layer: after a reversal the
                   contact is held at the flank it last touched until the pull reaches
                   the layer's pull-off force, then it snaps free and crosses the play
gms                ``viscoplastic_overstress``: part of the contact is carried through a
                   soft interface layer that is viscoplastic (Perzyna): elastic with no
                   flow below its yield stress, and above it a flow growing as a power of
                   the overstress, so the sliding stress overshoots the yield the more the
                   faster it slides; at ``s`` = 0 the base itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``thermal_closure`` needs
a Stribeck curve (not the isolator's mre_lugre), ``cable_reel`` a record that revisits its
positions (not the press), ``constant_flow_pad`` a load that changes, ``adhesive_flank`` and
``viscoplastic_overstress`` a classic LuGre base (valve, damping rig, XML-350); each raises
a ``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit
from scipy.special import ndtr

from friction.shapes import SHAPES

from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _level,
                     _light_contact_step, _lugre_params, _motion_time, _presliding_path,
                     _smooth_max0, _substeps, has_stribeck_curve, level_inside, on_fine_grid)

__all__ = ["FORMS", "band_capstan_truth", "constant_flow_pad_truth", "roller_skew_truth",
           "thermal_closure_truth", "cable_reel_truth", "oil_column_truth",
           "interleaved_adc_truth", "additive_settling_truth", "adhesive_flank_truth",
           "viscoplastic_overstress_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "band_capstan", "load": "constant_flow_pad",
         "asymmetry": "roller_skew", "stribeck_shape": "thermal_closure",
         "position": "cable_reel", "inertia": "oil_column",
         "delay": "interleaved_adc", "drift": "additive_settling",
         "backlash": "adhesive_flank", "gms": "viscoplastic_overstress"}


# -- acceleration ----------------------------------------------------------------------------
#: ``band_capstan``'s rise of the levels per unit of the band's tension change (the driven
#: mass's inertial force at the top acceleration), at strength 1 [-]; the band's pretension
#: behind the shoe, in that unit [-]; the rounding of the slack band and of the direction,
#: in that unit and x the top speed [-]
BAND_RISE, BAND_PRE, BAND_ROUND = 0.4, 0.5, 0.05


def _band_tension(a, direction, pre, rounding):
    """The band's tension behind the guide shoe [-] (in the driven mass's inertial force at
    the top acceleration) at the accelerations ``a`` [-] (over the top acceleration) along
    the motion's ``direction`` [-] (+-1, rounded): the pretension ``pre`` plus the force
    that accelerates the driven mass along the motion, and never below a slack band's 0
    (rounded over ``rounding``)."""
    return _smooth_max0(pre + np.asarray(a, float) * np.asarray(direction, float), rounding)


@on_fine_grid
def band_capstan_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage is pulled by a steel band (a band or tape drive, as in plotters, pick
    and place heads and cable-driven devices) that wraps a fixed, lubricated guide shoe on
    its way to the drive drum; behind the shoe the band also pulls a driven mass (a
    counter-carriage, the tensioner's slide). By the capstan law the band slides over the
    shoe with a friction (e^(mu theta) - 1) T, T the tension behind the shoe: the
    pretension (:data:`BAND_PRE`) plus the driven mass's inertial force along the motion,
    never below zero, where the band goes slack (:func:`_band_tension`). The base law,
    identified at the steady pretension, carries its friction; the Coulomb and Stribeck
    levels are the base's times 1 + ``s`` :data:`BAND_RISE` (T - T_0), T_0 the steady
    pretension's (rounded), inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the shoe's capstan factor e^(mu theta) - 1 times the driven
        mass, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The capstan (Euler-Eytelwein) equation and band drives (Euler 1762; Eytelwein 1808;
    Johnson 1985, Contact Mechanics, ch. on belt friction; Jung, Pan and Kang 2008,
    Capstan equation including bending rigidity and non-linear frictional behavior, Mech.
    Mach. Theory 43). The candidate raises the levels with |a|, lagged, tilts them with a
    and adds a force odd in a; the open forms lag, age, heat, skid, load, press, attract,
    squeeze, transfer weight, slosh, dilate, wedge, spring a gib, soften rubber, swing
    arms, unload by the jerk, tilt pads, push ball trains, ripple the current, slide rack
    flanks, set a shoe by a ball in a cone, shut a damper's bypass, creep a belt or rack a
    gantry. Here a band slides over a fixed shoe: its friction follows the tension the
    acceleration puts in the band, up to where the band goes slack.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    v99 = max(kin.scales["v99"], 1e-12)
    direction = np.tanh(np.asarray(kin.v, float) / (BAND_ROUND * v99))
    T = _band_tension(np.asarray(kin.a, float) / a99, direction, BAND_PRE, BAND_ROUND)
    T0 = float(_band_tension(0.0, 1.0, BAND_PRE, BAND_ROUND))      # the steady pretension
    lev = np.maximum(1.0 + float(s) * BAND_RISE * (T - T0), 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- load ------------------------------------------------------------------------------------
#: ``constant_flow_pad``'s change of the drag at the top speed between the record's mean
#: load and its loads farthest from it (the 99th percentile of the change), x the friction
#: level, at strength 1 [-]; the floor of the load in the gap's law (the pad's lift limit),
#: x the mean load [-]
FLOW_DRAG, FLOW_FLOOR = 1.0, 0.05


def _pad_gap_drag(q, floor):
    """The pad's Couette drag per unit speed [-] (1 at the mean load) at the loads ``q``
    [-] (over the mean |load|): a pad fed a constant flow Q runs at the gap where Q
    passes its lands at the pressure that carries the load, Q ~ h^3 p, so h ~ (1 / W)^(1/3)
    and the drag ~ 1 / h ~ W^(1/3) (the load floored at ``floor``: the gap's limit)."""
    r = np.abs(np.asarray(q, float))
    return np.cbrt(np.sqrt(r * r + floor * floor))


@on_fine_grid
def constant_flow_pad_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage rides on hydrostatic pads each fed a constant flow (a pump per pad or a
    flow divider), not a constant pressure through a restrictor: the pad's pressure is the
    load over its effective area, and its gap settles where the constant flow passes its
    lands at that pressure, Q ~ h^3 p: h ~ W^(-1/3). The film's Couette (shear) drag
    ~ v / h therefore grows as the cube root of the load (:func:`_pad_gap_drag`), and it
    carries the load at every load without touching down. The base law, identified at the
    mean load, carries the drag there; the truth adds ``s`` :data:`FLOW_DRAG` x the friction
    level x v / v99 x the drag factor's change from the mean load (over its 99th percentile
    along the record) to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], load [N]) and its base law.
    s : float
        Amplitude factor [-]: the oil's viscosity times the pads' area over the gap at the
        mean load, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Constant-flow (pump-per-pad) hydrostatic bearings and their gap's law (Rowe 1983,
    Hydrostatic and Hybrid Bearing Design, ch. on constant-flow bearings; Stansfield 1970,
    Hydrostatic Bearings for Machine Tools; Bassani and Piccigallo 1992, Hydrostatic
    Lubrication). The candidate makes the levels affine in the load, with a memory over the
    travel; the open forms scale the friction with a Hertz contact's area, a seal's, a
    film's, a junction's, a pivot's, an adhesive contact's or a pin's arc, break, squeeze
    or desorb films, plough, creep, vibrate, overload a constant-pressure pad, heal
    scuffs, relieve a preload, roll on a lossy track, slip differentially in conforming
    grooves, spin balls, press a disc spring or skid lightly loaded rollers. Here no solid
    touches: the load sets the film's gap, and the gap the film's shear.
    """
    L = np.asarray(kin.load, float)
    Lm = float(np.mean(np.abs(L))) or 1.0
    if not np.ptp(L) > 1e-9 * Lm:
        raise ValueError(f"load (constant_flow_pad): the {kin.plant} record's load does "
                         f"not change")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    d = _pad_gap_drag(L / Lm, FLOW_FLOOR) - _pad_gap_drag(1.0, FLOW_FLOOR)
    d = d / max(float(np.percentile(np.abs(d), 99)), 1e-12)
    return F + float(s) * FLOW_DRAG * _level(kin) * np.asarray(kin.v, float) / v99 * d


# -- asymmetry -------------------------------------------------------------------------------
#: ``roller_skew``'s rise of the levels at the full skew, at strength 1 [-]; the skew's
#: equilibrium moving -x, x its equilibrium moving +x [-]; the travel the skew settles
#: over, x the stroke [-]; the direction's rounding, x the top speed [-]
SKEW_RISE, SKEW_BACK, SKEW_TRAVEL, SKEW_ROUND = 0.5, -0.25, 0.05, 0.02


@njit(cache=True)
def _skew(dx, direction, back, travel):
    """The rollers' skew angle [-] (1 the equilibrium moving +x) along the travel steps
    ``dx`` [m] with the motion's ``direction`` [-] (+-1, rounded): it settles towards 1
    moving +x and ``back`` moving -x over the travel ``travel`` [m] (first order in the
    distance rolled, exact on each step), from the +x equilibrium."""
    n = dx.size
    out = np.empty(n)
    psi = 1.0
    out[0] = psi
    for k in range(1, n):
        d = direction[k]
        eq = 0.5 * (1.0 + d) + 0.5 * (1.0 - d) * back
        e = math.exp(-abs(dx[k]) / travel)
        psi = eq + (psi - eq) * e
        out[k] = psi
    return out


@on_fine_grid
def roller_skew_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage runs on cylindrical rollers in a cage (a crossed-roller or flat roller
    way). Rolling, each roller skews about the load's axis until the moments of its end
    and flange friction balance: the skew angle settles over a travel of a few roller
    diameters (:data:`SKEW_TRAVEL` x the stroke) after each reversal, towards an angle that
    differs by direction, for the rollers are guided by a flange on one side of the track
    only (:data:`SKEW_BACK` of the +x skew moving -x; :func:`_skew`). A skewed roller
    slides across the track as it rolls, a friction ~ its skew: the Coulomb and Stribeck
    levels are the base's times 1 + ``s`` :data:`SKEW_RISE` |skew|, inside the bristle
    dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the friction coefficient of the rollers' cross sliding, /
        its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Roller skewing in roller bearings and ways (Harris and Kotzalas 2007, Advanced Concepts
    of Bearing Technology, ch. on roller skewing; Kalker 1990, Three-Dimensional Elastic
    Bodies in Rolling Contact, on the lateral creep of a yawed roller; Slocum 1992,
    Precision Machine Design, ch. 8 on roller ways). The candidate frees the levels (and
    the Stribeck velocity and viscous term) of each direction and an offset; the open
    forms twin levels, curves or viscous terms, roll lips, load thrust bearings, pump
    films, ratchet, spring back, tilt pads, strut, throttle with a check valve, differ in
    areas, pump along grooves, buckle, scrape chips, commutate, tension idlers,
    free-wheel, wick felts, run belts, lean brushes, pull sealing bands, hold by a
    counterbalance valve, vibrate the way, pass a fluidic diode or pitch unlike pads. Here
    the rollers steer themselves: each direction's level is reached over a travel.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    x = np.asarray(kin.x, float)
    dx = np.concatenate(([0.0], np.diff(x)))
    direction = np.tanh(np.asarray(kin.v, float) / (SKEW_ROUND * v99))
    span = max(float(np.ptp(x)), 1e-12)
    psi = _skew(dx, direction, SKEW_BACK, SKEW_TRAVEL * span)
    lev = 1.0 + float(s) * SKEW_RISE * np.abs(psi)
    return level_inside(kin, lev, np.ones_like(lev))


# -- stribeck_shape --------------------------------------------------------------------------
#: ``thermal_closure``'s drag at the top speed, x the friction level, at strength 1 [-]; the
#: clearance's closure at the top speed's friction power, as a share that closes the
#: clearance (4 kappa, at most 0.95 anywhere) [-]
CLOSE_DRAG, CLOSE_KAPPA = 0.5, 0.15


def _closure_drag(u, kappa):
    """The bushing's viscous drag [-] (1 at the top speed) at the speeds ``u`` [-] (over
    the top speed): Petroff's drag ~ u / c over the clearance c = 1 - kappa' D u closed by
    the friction power D u: D (1 - kappa D u) = u, the root that starts at D = u; odd in u
    (4 kappa u^2 held below 0.95)."""
    u = np.asarray(u, float)

    def drag(x):
        q = np.minimum(4.0 * kappa * x * x, 0.95)
        return 2.0 * x / (1.0 + np.sqrt(1.0 - q))
    return np.sign(u) * drag(np.abs(u)) / drag(1.0)


@on_fine_grid
def thermal_closure_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage's slide rods run in plain bushings of small clearance, filled with
    oil. Their viscous (Petroff) drag ~ v / c heats them, and the rod, hotter and of a
    larger expansion coefficient than its housing, expands into the clearance: in the
    steady state of each speed the clearance shrinks by ~ the friction power D v, so the
    drag solves D (1 - kappa D v) = v (:func:`_closure_drag`; :data:`CLOSE_KAPPA`): linear
    at low speed and steeper than linear towards the top speed. The truth adds ``s``
    :data:`CLOSE_DRAG` x the friction level x that drag (1 at the top speed) to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (with a Stribeck curve).
    s : float
        Amplitude factor [-]: the oil's viscosity over the clearance (its drag), / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Petroff's law of lightly loaded journal bearings and the thermal closure of their
    clearance, the route to thermal seizure (Petroff 1883; Khonsari and Booser 2017,
    Applied Tribology, 3rd ed., ch. on thermally induced seizure; Hazlett and Khonsari
    1992, Finite element model of journal bearings undergoing rapid thermally induced
    seizure, Tribol. Int. 25). The candidate reshapes the Stribeck curve; the open forms
    add a tail, a rational drop, a hydrodynamic rise, a spike, a lift-off, two roughness
    scales, a logarithmic or Eyring law, starve a film, add rubber hysteresis, resonate,
    dither, melt, flow grains, readsorb, heat the film, make it turbulent, thixotropic,
    churned or shear-thinning, add core losses, breathe a bellows, brake by eddy currents,
    fly a pad, wipe a meniscus, lift a journal or let the walls slip. Here the film's heat
    acts on the solids: the gap it shears closes as the speed rises.
    """
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (thermal_closure): the mre_lugre base has no "
                         "Stribeck curve")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    d = _closure_drag(np.asarray(kin.v, float) / v99, CLOSE_KAPPA)
    return F + float(s) * CLOSE_DRAG * _level(kin) * d


# -- position --------------------------------------------------------------------------------
#: ``cable_reel``'s spring pull at the far end of the stroke, x the friction level, at
#: strength 1 [-]; the reel bearings' drag, x the pull [-]; the direction's rounding, x the
#: top speed [-]
REEL_PULL, REEL_DRAG, REEL_ROUND = 0.4, 0.3, 0.02


def _reel_pull(xr):
    """The reel's pull [-] (1 at the stroke's far end) at the positions ``xr`` [-] (over
    the visited stroke, from its low end): a spiral spring wound by the cable paid out,
    its torque ~ the turns, so its pull ~ the payout; none at the low end (where the
    base law, fitted, takes up its pretension)."""
    return np.asarray(xr, float)


@on_fine_grid
def cable_reel_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage's cable (power, signal or a hose) is kept taut by a spring-driven reel
    fixed at the low end of the stroke: the cable pays out as the carriage moves away, and
    the reel's spiral spring winds up, its pull growing with the payout
    (:func:`_reel_pull`); the drive carries that pull, ``s`` :data:`REEL_PULL` x the
    friction level at the far end, the same in both directions. The reel's drum turns on
    bearings loaded by the cable's pull, whose friction (:data:`REEL_DRAG` x the pull)
    opposes the cable's motion, and so the carriage's: F = base + P (1 + REEL_DRAG
    sign(v)) (the direction rounded over :data:`REEL_ROUND` x the top speed).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the reel spring's rate, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Spring-driven cable reels (Wahl 1963, Mechanical Springs, 2nd ed., ch. on spiral
    springs; manufacturers' spring reel data, e.g. Conductix-Wampfler, the reel's pull
    rising with the cable paid out) and the friction of a drum's bearings under a rope's
    pull (Shigley, Mischke and Budynas 2004, Mechanical Engineering Design, ch. on rolling
    bearings' friction). The candidate scales the friction along the stroke and adds a
    force of the position; the open forms put a defect, a waviness, a worn section, runout,
    a bent rail, a transfer film, cogging, a taper, a pocket, a cushion, a cover, an air
    spring, bolt holes, a plunger, a sag, a festoon, a curve, a chain, a cam, a heated
    zone, brinelled dents, a rail joint, misaligned rails, a spool's flow force, a crank,
    an overhang or a track's end on the stroke. Here a wound spring pulls the carriage home
    and drags through its own reel, more the farther the carriage goes.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (cable_reel): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    span = max(sc["x_hi"] - sc["x_lo"], 1e-12)
    xr = np.clip((np.asarray(kin.x, float) - sc["x_lo"]) / span, 0.0, None)
    v99 = max(sc["v99"], 1e-12)
    P = float(s) * REEL_PULL * _level(kin) * _reel_pull(xr)
    return F + P * (1.0 + REEL_DRAG * np.tanh(np.asarray(kin.v, float) / (REEL_ROUND * v99)))


# -- inertia ---------------------------------------------------------------------------------
#: ``oil_column``'s column mass at strength 1, x the friction level / a99 [kg per N s^2/m];
#: the column's period on the hose's compliance, x the motion's time scale [-]; its
#: turbulent loss, as the damping ratio it gives at the top acceleration's deflection [-]
COLUMN_MASS, COLUMN_PERIOD, COLUMN_LOSS = 0.5, 0.3, 0.3


@njit(cache=True)
def _column_force(a, h, w, cq):
    """The force [N per kg] the oil column exerts on the carriage under its accelerations
    ``a`` [m/s^2] (steps ``h`` [s]): the column's displacement y from the carriage obeys
    y'' = -a - w^2 y - ``cq`` |y'| y' (the hose wall's compliance, mode ``w`` [rad/s], and a
    turbulent loss ~ the flow's square), the force -(w^2 y + cq |y'| y') = a + y''.
    Semi-implicit Euler on sub-steps of at most 0.05 / w, the acceleration interpolated,
    from rest."""
    n = a.size
    out = np.empty(n)
    m = max(1, int(math.ceil(w * h / 0.05)))
    hs = h / m
    y = 0.0
    yd = 0.0
    out[0] = 0.0
    for k in range(1, n):
        for i in range(m):
            u = a[k - 1] + (a[k] - a[k - 1]) * (i + 1.0) / m
            f = -(w * w * y + cq * abs(yd) * yd)
            yd += hs * (f - u)
            y += hs * yd
        out[k] = -(w * w * y + cq * abs(yd) * yd)
    return out


@on_fine_grid
def oil_column_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage carries a hydraulic actuator (a clamp, a tool's cylinder) fed by a
    hose; when it accelerates, it drags along the oil column in the hose, whose mass the
    inverse dynamics misses. The column rides on the compliance of the hose's wall (its
    mode of period :data:`COLUMN_PERIOD` x the motion's time scale) and is damped by its
    flow's turbulent loss, ~ the flow's square (:func:`_column_force`; the loss such that
    it damps the mode by :data:`COLUMN_LOSS` of critical at the top acceleration's
    deflection): the carriage carries the whole column in slow motions, and less, lagging
    and ringing, in quick ones. The truth adds ``s`` :data:`COLUMN_MASS` x the friction
    level / a99 x that force per unit mass to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the column's mass, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Fluid line dynamics: a line's inertance, its wall compliance and turbulent resistance
    (Merritt 1967, Hydraulic Control Systems, ch. on fluid lines; Watton 2009, Fundamentals
    of Fluid Power Control, ch. on line dynamics; Beater 2007, Pneumatic Drives, on the
    lumped line model). The candidate misses a constant mass; the open forms filter it,
    reflect it through gearing, a chain's polygon or a pinion, hang it on a spring, a
    cable, a fluid, a clutch, a coupling, a flyweight, a screw, a friction-damped mount, a
    surging spring or a quasi-zero-stiffness mount, add a fluid's mass around a body and
    its history, pick it up, drop it, empty it, slide it, rattle it, telescope it, roll it
    in a cradle, rock it on its edges, recoil the frame, saturate the motor, lead it by the
    feedforward or pitch the scale head. Here the mass is oil inside a hose: held by the
    hose's wall and damped by a loss that grows with its own flow's square.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    w = 2.0 * math.pi / (COLUMN_PERIOD * max(_motion_time(kin), 1e-12))
    y_top = a99 / (w * w)
    cq = 2.0 * COLUMN_LOSS / max(y_top, 1e-300)
    f = _column_force(np.ascontiguousarray(kin.a, dtype=float), float(kin.dt), w, cq)
    return F + float(s) * COLUMN_MASS * _level(kin) / a99 * f


# -- delay -----------------------------------------------------------------------------------
#: ``interleaved_adc``'s clock skew of the second converter at strength 1 [data samples]
SKEW_SAMPLES = 2.0


def _interleave(t, F, step, skew):
    """The force ``F`` [N] on the grid ``t`` [s] read by two interleaved converters: the
    data samples (every ``step`` th grid point, and the grid points around them) of even
    index on time, those of odd index ``skew`` [s] late (the force at t - skew,
    interpolated; the record's first force before it starts)."""
    t = np.asarray(t, float)
    F = np.asarray(F, float)
    j = np.rint(np.arange(t.size) / step).astype(np.int64)
    late = (j % 2) == 1
    out = F.copy()
    out[late] = np.interp(t[late] - skew, t, F)
    return out


@on_fine_grid
def interleaved_adc_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is digitised by a time-interleaved converter: two ADCs take alternate
    samples, each at half the data rate, on clocks half a sample period apart, and their
    words are merged into one stream. The second lane is late: its clock is skewed from
    its ideal phase (a trace length, a clock buffer's delay) and, where its pipeline is
    deeper than the first's, the merge aligns its words from earlier conversions (a lane
    misalignment): every other force sample is taken ``s`` :data:`SKEW_SAMPLES` data
    samples late (:func:`_interleave`), the others on time. The motion channels are on
    time.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]; ``step`` grid points per data sample) and its
        base law.
    s : float
        Amplitude factor [-]: the second converter's clock skew, / its value at strength
        1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Time-interleaved ADCs and their timing mismatch (Black and Hodges 1980, Time
    interleaved converter arrays, IEEE J. Solid-State Circuits 15; Kurosawa, Kobayashi,
    Maruyama, Sugawara and Kobayashi 2001, Explicit analysis of channel mismatch effects in
    time-interleaved ADC systems, IEEE Trans. Circuits Syst. I 48). The candidate shifts
    the force by a constant time, low-passes it, reads it through a transducer's
    resonance and leaks it; the open forms sample, filter, average, hold, skew, jitter,
    rate-limit, transmit, median, report by deadband, trigger on positions, run a belt,
    aerate, drop telegrams, leak, creep, notch, track, snub, time a waveguide's pulse,
    diffuse eddy currents, count a resonator's frequency over a gate, sweep a grating or
    restore a force by a servo. Here the sampling instants themselves alternate: half the
    samples are on time and half are late by the same skew.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    skew = float(s) * SKEW_SAMPLES * kin.sample_dt
    return _interleave(kin.t, F, int(kin.step), skew)


# -- drift -----------------------------------------------------------------------------------
#: ``additive_settling``'s rise of the levels by the record's end, at strength 1 [-]; the
#: median particle's settling time to the pick-up, x the record's length [-]; the log
#: standard deviation of the particles' diameters [-]
SETTLE_RISE, SETTLE_TIME, SETTLE_SPREAD = 0.4, 0.6, 0.35


def _suspended(tau, median, spread):
    """The additive's concentration at the pick-up [-] (1 at the start) at the times
    ``tau`` [-] (over the record's length): a particle of diameter d settles past it at
    time ~ 1 / d^2 (Stokes), so what remains at tau is the share of diameters below
    sqrt(``median`` / tau) x the median's, for log-normal diameters of log standard
    deviation ``spread``: Phi(ln(median / tau) / (2 spread))."""
    tau = np.maximum(np.asarray(tau, float), 1e-12)
    return ndtr(np.log(median / tau) / (2.0 * spread))


@on_fine_grid
def additive_settling_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The way's lubricant is an oil with a suspended solid additive (graphite, MoS2 or
    PTFE particles), fed from a reservoir left standing before the record: the particles
    settle by Stokes's law, a particle of diameter d in a time ~ 1 / d^2 past the pump's
    pick-up; their diameters spread log-normally (:data:`SETTLE_SPREAD`), the median's
    time :data:`SETTLE_TIME` x the record's length, so the supply loses its additive as
    the settling front passes (:func:`_suspended`), slowly and late. The contact's solid
    lubricant thins with its supply: the Coulomb and Stribeck levels are the base's times
    1 + ``s`` :data:`SETTLE_RISE` x the additive lost over its loss by the record's end,
    inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the friction without the additive over with it, less 1, / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Sedimentation of suspended particles (Stokes 1851; Richardson and Zaki 1954,
    Sedimentation and fluidisation, Trans. Inst. Chem. Eng. 32) and solid additives in
    lubricating oils and their settling (Bartz 1971, Solid lubricant additives - effect
    of concentration and other additives on anti-wear and extreme pressure performance,
    Wear 17; Mang and Dresel 2007, Lubricants and Lubrication, ch. on solid lubricants).
    The candidate is a trend, a saturating change, a step, a cycle, a resetting change or
    the friction power's heat; the open forms warm up, wear in, change the lubricant,
    heat, wear, follow the humidity, grind a third body, relubricate, relax a seal,
    oxidise, deplete, wear through, swell, build a tribofilm, take in particles, expand,
    shear down, heat magnets, charge, creep a cage, loosen a screw, dewet a film, channel
    grease, drain a receiver, grow a spall, evaporate an oil or pump a chamber down. Here
    the supply loses a suspension by gravity: a change that waits for its particles to
    fall.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    tau = (t - t[0]) / max(t[-1] - t[0], 1e-12)
    c = _suspended(tau, SETTLE_TIME, SETTLE_SPREAD)
    loss = max(float(c[0] - c[-1]), 1e-12)
    lev = 1.0 + float(s) * SETTLE_RISE * (c[0] - c) / loss
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: ``adhesive_flank``'s play at strength 1, as a share of the stroke (its full width, both
#: sides) [-]; the flanks' pull-off force, x the Coulomb level [-]
ADHESIVE_CLEAR, ADHESIVE_PULL = 0.01, 0.5


@njit(cache=True)
def _flank_force(e, ed, half, kh, ch, pull, held):
    """(force [N], the flank held after the step) of a play of half-width ``half`` [m]
    between drive and contact at the offset ``e`` [m] (drive minus contact) and its rate
    ``ed`` [m/s]: the flanks a spring ``kh`` [N/m] and damper ``ch`` [N s/m]; the flank
    ``held`` (+1, -1; 0 none) holds the contact by its adhesive layer, in tension up to
    ``pull`` [N], and lets it go past it; a flank the contact touches holds it."""
    if held == 0:
        if e > half:
            held = 1
        elif e < -half:
            held = -1
        else:
            return 0.0, 0
    if held == 1:
        f = kh * (e - half) + ch * ed
        if f < -pull:
            return 0.0, 0
        return f, 1
    f = kh * (e + half) + ch * ed
    if f > pull:
        return 0.0, 0
    return f, -1


@njit(cache=True)
def _adhesive_contact(h, xd, half, kh, ch, pull, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a light contact of mass ``m`` [kg] driven by the drive
    positions ``xd`` [m] (steps ``h`` [s]) across the adhesive play of
    :func:`_flank_force`, starting at rest against (and held by) the +x flank."""
    n = xd.size
    F = np.empty(n)
    x = xd[0] - half
    v = 0.0
    z = 0.0
    held = 1
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        fc, held = _flank_force(xd[j] - x, vd - v, half, kh, ch, pull, held)
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha,
                                         shape)
        x = x + h * v
    return F


@on_fine_grid
def adhesive_flank_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact are joined across a play (``s``^2 :data:`ADHESIVE_CLEAR` x the
    stroke wide) whose flanks are lined with a tacky layer (an elastomer's or a grease's
    adhesion, a damping pad's): a flank the contact touches holds it, in tension up to its
    pull-off force (:data:`ADHESIVE_PULL` x the Coulomb level, below the contact's
    friction, so it does not drag the contact back). After a reversal the drive first pulls
    the contact, held by the flank it left, up to the pull-off force, then the layer lets
    go and the drive crosses the play to the other flank (:func:`_flank_force`). The flanks
    and the light contact are the other plays' (:func:`.truths._contact_constants`; its
    inertial force at the top acceleration 1 % of the Coulomb level) with the base's LuGre
    friction (:func:`_adhesive_contact`).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the square root of the play, / its value at strength 1 (as
        the open plays').

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Adhesive contact and its pull-off force (Johnson, Kendall and Roberts 1971, Surface
    energy and the contact of elastic solids, Proc. R. Soc. Lond. A 324; Israelachvili
    2011, Intermolecular and Surface Forces, 3rd ed., ch. on adhesion) and the tacky
    damping pads of backlash stops. The candidate holds or frees the contact across a rigid
    play; the open forms take it up rigidly, compliantly, by impact, against a spring,
    eccentrically, through oil, worn, with a dragging idler, biased, slack, magnetic,
    preloaded, through a flexspline, a rope, a spider, a fluid link, a cable, a clutch, a
    varying mesh, a polymer gear, grease, a wedge, an overlapped spool, a side loaded pin,
    a toggle spring or graded pins. Here the flank the contact leaves pulls it back: the
    force turns over before the play opens.
    """
    p = _lugre_params(kin, "backlash (adhesive_flank)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    half = 0.5 * float(s) ** 2 * ADHESIVE_CLEAR * float(np.ptp(kin.x))
    m, kh, ch = _contact_constants(kin, p)
    pull = ADHESIVE_PULL * float(p.Fc)
    rate = max(math.sqrt(kh / m), (float(p.sigma1) + float(p.sigma2) + ch) / m)
    h, xd, n_sub = _substeps(kin, rate)
    Fr = _adhesive_contact(h, xd, half, kh, ch, pull, m, float(p.sigma0), float(p.sigma1),
                           float(p.sigma2), float(p.Fc), float(p.Fs), float(p.vs),
                           float(p.alpha), SHAPES[p.shape])
    return Fr[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: the layer's elastic path to its yield stress at strength 1, beyond the base bristle's
#: path, as a share of the stroke / 3 [-]; its share of the friction at strength 1 [-]; its
#: overstress at the top speed, over the yield stress [-]; the overstress law's exponent [-]
VP_PATH, VP_SHARE, VP_OVER, VP_EXPONENT = 0.1, 0.6, 0.3, 2.0


@njit(cache=True)
def _overstress_layer(t, v, path, v_top, over, expo):
    """The layer's shear stress u [-] (1 its yield stress) along the velocities ``v`` [m/s]
    at the times ``t`` [s]: elastic, du/dt = (v - v_p) / ``path`` [m], with no flow below
    the yield stress and above it Perzyna's viscoplastic flow v_p = ``v_top`` sgn(u)
    ((|u| - 1) / ``over``)^``expo`` (so a steady ``v_top`` holds u = 1 + ``over``);
    implicit Euler (Newton on each step, the velocity at the step's end), from no
    stress."""
    n = t.size
    out = np.zeros(n)
    u = 0.0
    for k in range(1, n):
        h = (t[k] - t[k - 1]) / path
        vk = v[k]
        x = u
        for _ in range(60):
            ex = abs(x) - 1.0
            if ex > 0.0:
                sg = 1.0 if x > 0.0 else -1.0
                phi = sg * v_top * (ex / over) ** expo
                dphi = v_top * expo * (ex / over) ** (expo - 1.0) / over
            else:
                phi = 0.0
                dphi = 0.0
            g = x - u - h * (vk - phi)
            dx = g / (1.0 + h * dphi)
            x -= dx
            if abs(dx) < 1e-12 * (1.0 + abs(x)):
                break
        u = x
        out[k] = u
    return out


@on_fine_grid
def viscoplastic_overstress_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Part of the contact is carried through a soft metallic (or polymer) interface layer
    whose shear is viscoplastic in Perzyna's sense: elastic below its yield stress, with
    no flow at all there (at rest the overstress relaxes to the yield stress, which then
    holds), and above it a flow whose rate grows as a power of the overstress
    (:func:`_overstress_layer`; the overstress :data:`VP_OVER` of the yield at the top
    speed, exponent :data:`VP_EXPONENT`). After a
    reversal the stress unloads elastically through zero to the other yield, and while
    sliding it overshoots the yield the more the faster it slides. Its elastic path is the
    base bristle's Fs / sigma0 plus ``s`` :data:`VP_PATH` x the stroke / 3; its share w =
    ``s`` :data:`VP_SHARE` (up to ``s`` = 1) of the friction is its stress over its value
    at the top speed times the Stribeck level, the viscous term the base's: F = (1 - w)
    F_lugre + w (g(v) u / (1 + VP_OVER) + sigma2 v). At ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the layer's share (up to ``s`` = 1) and its elastic path (as
        the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Overstress viscoplasticity (Perzyna 1966, Fundamental problems in viscoplasticity, Adv.
    Appl. Mech. 9; Lemaitre and Chaboche 1990, Mechanics of Solid Materials, ch. 6) and
    the shear of soft interface layers (Bowden and Tabor 1950, on thin metallic films on
    hard substrates). The candidate's presliding is a generalized Maxwell-slip (GMS)
    element set; the open forms are Maxwell-slip sets, Dahl, elasto-plastic,
    Bliman-Sorine, Bouc-Wen, Zener junctions, Mindlin contacts, rate-and-state, Tomlinson
    asperities, bond rupture, gouge, kinematic hardening, interlocking, capillary bridges,
    cyclic hardening, peeling, unloading microslip, a power-law joint, junction growth,
    avalanches, slip weakening, a microslip bar, contact renewal, a grease's yield, a
    superelastic flexure and an Eyring film. Here the presliding has a yield surface and
    a rate beyond it: nothing flows below the yield, and the overstress grows with the
    speed above it.
    """
    p = _lugre_params(kin, "gms (viscoplastic_overstress)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, VP_PATH)
    w = VP_SHARE * min(float(s), 1.0)
    v = np.ascontiguousarray(kin.v, dtype=float)
    v99 = max(kin.scales["v99"], 1e-12)
    u = _overstress_layer(np.ascontiguousarray(kin.t, dtype=float), v, e0 + extra, v99,
                          VP_OVER, VP_EXPONENT)
    return (1.0 - w) * F + w * (kin.base.g(v) * u / (1.0 + VP_OVER) + float(p.sigma2) * v)
