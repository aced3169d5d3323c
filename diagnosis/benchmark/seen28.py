"""The twenty-eighth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-12-01 (session 32) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 33 (2026-12-01) on the code of 9f8fda9:
176 cases, 0 skipped, 322 s wall on 2 workers. Top-1 52.8 % (93;
56.0 % of the 166 detectable; of the 10 undetectable, 6 are delays below their practical
size (3 of them named acceleration, 1 inertia, 2 unexplained), 4 stribeck_shape cases
(none)); mean |shrink error| 0.300 (0.163 over the right ones); wrong names on 19 (10.8 %):
acceleration -> drift 6, delay -> acceleration 5 (3 of them below their practical size),
gms -> delay 3, acceleration -> position 2, delay -> inertia 1, asymmetry -> load 1,
backlash -> gms 1. By form: load/soft_film_pressure 20/20, asymmetry/angled_pull 18/20
(none 1, load 1), drift/thermostat_cycling 15/20 (unexplained 5), inertia/hanging_pendulum
11/20 (unexplained 7, none 2), delay/adaptive_filter 9/20 (acceleration 5, unexplained 5,
inertia 1), position/ball_passage 8/16 (unexplained 8),
stribeck_shape/capillary_condensation 5/16 (none 7, unexplained 4), gms/shear_melting_film
4/12 (unexplained 5, delay 3), backlash/air_cushion_gap 3/12 (unexplained 7, none 1, gms 1),
acceleration/winding_heat 0/20 (unexplained 11, drift 6, position 2, none 1). By plant:
valve 70.0 %, XML-350 62.5 %, isolator 50.0 %, damping rig 42.5 %, forging press 32.1 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen27` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen27`,
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
acceleration       ``winding_heat``: the axis is driven by a linear motor whose winding
                   sits on the carriage over the bearings; its copper loss ~ the square
                   of the thrust, the friction plus the inertial force, heats the
                   carriage over its thermal time and the bearings' preload grows with
                   the expansion: levels that follow the lagged square of the drive's
                   force, up after speeding up, down after slowing and in dwells
load               ``soft_film_pressure``: the contact runs through a thin soft film
                   (a plated or sputtered soft metal, a polymer or a soap layer) on
                   hard bodies; the hard bodies set the contact area (~ the load^(2/3))
                   and the film's shear strength rises with the contact pressure
                   (tau0 + alpha p): a friction tau0 A + alpha W of the load
asymmetry          ``angled_pull``: the carriage is pulled each way by a cable or tape
                   whose two ends are anchored at different heights; the front pull
                   lifts the carriage off its ways, the rear pull presses it on: the
                   friction mu N / (1 + mu tan) one way and mu N / (1 - mu tan) the
                   other, with unequal angles
stribeck_shape     ``capillary_condensation``: in humid air water condenses into the
                   gaps around each junction while it lives; slower sliding lives
                   longer and fills more menisci, whose Laplace pressure adds to the
                   load: an extra friction ~ 1 - exp(-v_k / |v|), full at rest and
                   gone at speed
position           ``ball_passage``: the carriage's recirculating balls enter and leave
                   the loaded zone as it travels; each entry over the end seal's
                   crowning lifts the rolling resistance, a peaked ripple that repeats
                   every two ball pitches of travel, locked to the position
inertia            ``hanging_pendulum``: a payload hangs under the carriage on a rod (an
                   overhead conveyor's carrier, a gantry crane's hook, a probe on a
                   stem); it swings as a damped, nonlinear gravity pendulum and pulls on
                   the carriage with its own horizontal acceleration
delay              ``adaptive_filter``: the force is read by a weighing indicator with
                   an adaptive digital filter: a long time constant while the reading
                   stays near the input, shortened as the input leaves it: a lag that
                   changes with how fast the force changes
drift              ``thermostat_cycling``: the machine's oil (or its bed's coolant) is
                   held by an on-off chiller with a switching band: the temperature
                   rises and falls along exponential arcs between the band's edges, and
                   the levels and the viscous term fall and rise with it: a cycle with
                   no trend
backlash           ``air_cushion_gap``: the play is a closed chamber: the drive's piston
                   moves in a bore of the contact's link with air trapped on each side,
                   compressed polytropically as the play closes: a soft, then steeply
                   stiffening cushion, before the flank is reached
gms                ``shear_melting_film``: part of the contact is carried through a
                   confined lubricant film a few molecules thick, solid at rest (an
                   elastic layer that yields) and melted by its own slip; it freezes
                   again over a time when it stops: stiff presliding after a dwell,
                   a liquid's rounded one after a quick reversal
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``capillary_condensation``
needs a Stribeck curve (not the isolator's mre_lugre), ``ball_passage`` a record that
revisits its positions (not the press), ``soft_film_pressure`` a load that changes,
``air_cushion_gap`` and ``shear_melting_film`` a classic LuGre base (valve, damping rig,
XML-350); each raises a ``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.shapes import SHAPES

from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _lag, _level,
                     _light_contact_step, _lugre_params, _motion_time, _presliding_path,
                     _substeps, has_stribeck_curve, level_inside, lugre_with_curve,
                     on_fine_grid)

__all__ = ["FORMS", "winding_heat_truth", "soft_film_pressure_truth", "angled_pull_truth",
           "capillary_condensation_truth", "ball_passage_truth", "hanging_pendulum_truth",
           "adaptive_filter_truth", "thermostat_cycling_truth", "air_cushion_gap_truth",
           "shear_melting_film_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "winding_heat", "load": "soft_film_pressure",
         "asymmetry": "angled_pull", "stribeck_shape": "capillary_condensation",
         "position": "ball_passage", "inertia": "hanging_pendulum",
         "delay": "adaptive_filter", "drift": "thermostat_cycling",
         "backlash": "air_cushion_gap", "gms": "shear_melting_film"}


# -- acceleration ----------------------------------------------------------------------------
#: ``winding_heat``'s change of the levels at the record's largest excess of the winding's
#: heat over steady motion's (its 99th percentile), at strength 1 [-]; the carriage's
#: inertial force at the top acceleration, x the friction level [-]; the carriage's thermal
#: time, x the motion's time scale [-]; the rounding of the direction, x the top speed [-]
WIND_RISE, WIND_INERTIA, WIND_TIME, WIND_ROUND = 0.5, 1.0, 2.0, 0.05


def _copper_loss(a, direction, inertia):
    """The winding's copper loss [-] over its value in steady motion, less 1, at the
    accelerations ``a`` [-] (over the top acceleration) along the motion's ``direction``
    [-] (+-1, rounded): the square of the thrust, the friction (``direction``) plus the
    inertial force ``inertia`` a, less the steady motion's 1 (I^2 R with I ~ the
    thrust)."""
    q = np.asarray(direction, float) + inertia * np.asarray(a, float)
    return q * q - 1.0


@on_fine_grid
def winding_heat_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The axis is driven by an iron-core linear motor whose winding is fixed to the
    carriage, over its bearings (as in many machine-tool and pick-and-place axes). The
    winding's current follows the thrust, the friction plus the carriage's inertial force
    (at the top acceleration :data:`WIND_INERTIA` x the friction level), and its copper
    loss I^2 R the thrust's square (:func:`_copper_loss`). The heat warms the carriage
    over its thermal time (:data:`WIND_TIME` x the motion's time scale, a first-order
    lag), and the carriage's expansion across its bearing rows raises their preload: the
    Coulomb and Stribeck levels are the base's (at the heat of steady motion) times 1 +
    ``s`` :data:`WIND_RISE` x the lagged heat's excess over it (over its 99th percentile
    along the record), inside the bristle dynamics; the viscous term is the base's.
    Speeding up heats more than steady motion; slowing down (the friction helping) and
    dwells heat less.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the winding's resistance times the preload's change per
        degree, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Linear motors' copper losses and the thermal behaviour of their axes (Gieras, Piech
    and Tomczuk 2011, Linear Synchronous Motors, ch. on losses and heat transfer; Mayr et
    al. 2012, Thermal issues in machine tools, CIRP Ann. 61) and the thermally induced
    preload of rolling bearings (Harris and Kotzalas 2007, Rolling Bearing Analysis, ch.
    on preload and on thermal effects). The candidate raises the levels with |a|, lagged,
    tilts them with a and adds a force odd in a; the open forms lag, age, heat, skid,
    load, press, attract, squeeze, transfer weight, slosh, dilate, wedge, spring a gib,
    soften rubber, swing arms, unload by the jerk, tilt pads, push ball trains, ripple the
    current, slide rack flanks, set a shoe by a ball in a cone, shut a damper's bypass,
    creep a belt, rack a gantry, tighten a band, surge a feed line or load a traction
    drive's cam. Here the drive's own losses heat the carriage: the square of the thrust,
    integrated over a thermal time, expands it onto its bearings.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    v99 = max(kin.scales["v99"], 1e-12)
    direction = np.tanh(np.asarray(kin.v, float) / (WIND_ROUND * v99))
    P = _copper_loss(np.asarray(kin.a, float) / a99, direction, WIND_INERTIA)
    H = _lag(np.asarray(kin.t, float), P, WIND_TIME * max(_motion_time(kin), 1e-12))
    H = H / max(float(np.percentile(np.abs(H), 99)), 1e-12)
    lev = np.maximum(1.0 + float(s) * WIND_RISE * H, 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- load ------------------------------------------------------------------------------------
#: ``soft_film_pressure``'s rise of the levels per unit of the film's friction change from
#: the mean load's, at strength 1 [-]; the share of the film's friction at the mean load
#: that its pressure term (alpha W) makes [-]
SOFT_RISE, SOFT_PRESSURE = 1.0, 0.5


def _soft_film_friction(q, pressure):
    """The soft film's friction [-] (1 at the mean load) at the loads ``q`` [-] (over the
    mean |load|): tau0 A + alpha W with the hard bodies' Hertz area A ~ |q|^(2/3), the
    pressure term the share ``pressure`` of it at the mean load."""
    r = np.abs(np.asarray(q, float))
    return (1.0 - pressure) * r ** (2.0 / 3.0) + pressure * r


@on_fine_grid
def soft_film_pressure_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The contact runs through a thin soft film on hard bodies (a plated or sputtered
    soft metal, lead, indium, silver, a polymer or a metal soap layer, as on bearing
    shells, space mechanisms and drawing dies). The hard bodies carry the load and set
    the contact area, elastically ~ the load^(2/3) (Hertz); the film, too thin to add
    area, shears at its own strength, which rises with the contact pressure: tau = tau0 +
    alpha p. The friction is then tau0 A + alpha W (:func:`_soft_film_friction`; the
    pressure term :data:`SOFT_PRESSURE` of it at the mean load), a sum of a part that
    grows slower than the load and one that grows as the load. The base law, identified
    at the mean load, carries the film's friction there; the truth's Coulomb and Stribeck
    levels are the base's times 1 + ``s`` :data:`SOFT_RISE` x the film's friction's change
    from the mean load's, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], load [N]) and its base law.
    s : float
        Amplitude factor [-]: the share of the contact's friction the film carries, / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The pressure dependence of thin films' shear strength and the friction of soft films
    on hard substrates (Bowden and Tabor 1950, The Friction and Lubrication of Solids, ch.
    on thin metallic films; Briscoe and Tabor 1978, Shear properties of thin polymeric
    films, J. Adhes. 9; Bridgman 1935, Effects of high shearing stress combined with high
    hydrostatic pressure, Phys. Rev. 48). The candidate makes the levels affine in the
    load, with a memory over the travel; the open forms scale the friction with a Hertz
    contact's area, a seal's, a film's, a junction's, a pivot's, an adhesive contact's or
    a pin's arc, break, squeeze or desorb films, plough, creep, vibrate, overload or feed
    a constant flow to a pad, heal scuffs, relieve a preload, roll on a lossy track, slip
    differentially, spin balls, press a disc spring, skid lightly loaded rollers, bed a
    rail or heat a liner by PV. Here the interface's own shear strength depends on the
    pressure, beside an area that grows slower than the load.
    """
    L = np.asarray(kin.load, float)
    Lm = float(np.mean(np.abs(L))) or 1.0
    if not np.ptp(L) > 1e-9 * Lm:
        raise ValueError(f"load (soft_film_pressure): the {kin.plant} record's load does "
                         f"not change")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    g = _soft_film_friction(L / Lm, SOFT_PRESSURE)
    lev = np.maximum(1.0 + float(s) * SOFT_RISE * (g - 1.0), 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``angled_pull``'s mu tan(theta) of the front pull (lifting the carriage, moving +x) and
#: of the rear pull (pressing it on, moving -x), at strength 1 [-]; the rounding of the
#: direction, x the top speed [-]
PULL_FRONT, PULL_REAR, PULL_ROUND = 0.3, 0.15, 0.05


def _pull_levels(direction, front, rear):
    """The guides' friction factor [-] (1 with a level pull) along the motion's
    ``direction`` [-] (+-1, rounded): moving +x the front pull, rising at mu tan =
    ``front``, lifts the carriage: F = mu (N - F tan) = mu N / (1 + ``front``); moving -x
    the rear pull, falling at mu tan = ``rear`` (at most 0.9), presses it on: mu N / (1 -
    ``rear``)."""
    d = np.asarray(direction, float)
    up = 1.0 / (1.0 + front)
    down = 1.0 / (1.0 - min(rear, 0.9))
    return 0.5 * (1.0 + d) * up + 0.5 * (1.0 - d) * down


@on_fine_grid
def angled_pull_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage is pulled each way by a cable or a steel tape (a cable-driven stage, a
    plotter's or a sliding door's drive, a hoist's trolley) whose ends leave the carriage
    at angles to its ways: the front run rises to its pulley, the rear one falls to its
    own. The pull is the friction it overcomes; its component across the ways lifts the
    carriage moving +x, against its weight, and presses it on moving -x, so the friction
    is mu (N -+ F tan theta): mu N / (1 + mu tan theta1) one way and mu N / (1 - mu tan
    theta2) the other (:func:`_pull_levels`; mu tan theta ``s`` :data:`PULL_FRONT` and
    ``s`` :data:`PULL_REAR`). The Coulomb and Stribeck levels are the base's times that
    factor, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the tangents of the runs' angles, / their values at strength
        1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Friction with a pull inclined to the sliding plane (Meriam and Kraige 2012,
    Engineering Mechanics: Statics, ch. on friction; Beer and Johnston 2010, Vector
    Mechanics for Engineers, ch. on the angle of friction) and cable drives' geometry
    (Slocum 1992, Precision Machine Design, ch. on cable and belt drives). The candidate
    gives each direction its levels and an offset; the open forms twin the levels, the
    curves or the viscous term, bend a curve, roll a lip, load a thrust bearing, film a
    rod seal, texture a ratchet, return a spring, tilt a pad, strut a sprag, throttle a
    meter-out, differ a cylinder's areas, groove chevrons, buckle a helix, scrape chips,
    commutate, idle a belt, free a roller, wick a felt, run a belt, lean a brush, band a
    seal, counterbalance a valve, vibrate elliptically, diode a flow, pitch pads, skew
    rollers, lift through a screw or turn the frame. Here the drive's own line of pull
    sets the normal load: lifted one way, pressed the other.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    d = np.tanh(np.asarray(kin.v, float) / (PULL_ROUND * v99))
    lev = _pull_levels(d, float(s) * PULL_FRONT, float(s) * PULL_REAR)
    return level_inside(kin, lev, np.ones_like(lev))


# -- stribeck_shape --------------------------------------------------------------------------
#: ``capillary_condensation``'s meniscus force with every junction's gaps filled, x the
#: Stribeck curve, at strength 1 [-]; the speed at which a junction lives the condensation's
#: time, x the top speed [-]
CAP_RISE, CAP_SPEED = 0.5, 0.1


def _condensed(u):
    """The share of a junction's gaps filled by condensed water [-] at the speeds ``u`` [-]
    (over the speed at which the junction lives the condensation's time): first-order
    filling over the junction's lifetime, 1 - exp(-1 / |u|) (1 at rest)."""
    r = np.abs(np.asarray(u, float))
    return -np.expm1(-1.0 / np.maximum(r, 1e-12))


@on_fine_grid
def capillary_condensation_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The contact works in humid air (or a solvent's vapour) and its junctions are
    hydrophilic: while a junction lives, water condenses into the narrow gaps around it
    (Kelvin's equation) and the menisci's Laplace pressure pulls the surfaces together,
    adding to the load. A junction lives its size over the speed; the gaps fill over a
    condensation time, so the filled share is 1 - exp(-v_k / |v|) (:func:`_condensed`;
    v_k :data:`CAP_SPEED` x the top speed, the speed at which a junction lives that time).
    The truth's Stribeck curve is the base's times 1 + ``s`` :data:`CAP_RISE` x that
    share, inside the bristle dynamics: an extra friction that is whole at rest and
    fades, as exp(-v_k / v), with the speed; no film, no tail in log v.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (with a Stribeck curve).
    s : float
        Amplitude factor [-]: the relative humidity's share of the menisci's force, / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Capillary condensation in contacts and its kinetics in sliding friction (Bocquet,
    Charlaix, Ciliberto and Crassous 1998, Moisture-induced ageing in granular media and
    the kinetics of capillary condensation, Nature 396; Riedo, Levy and Brune 2002,
    Kinetics of capillary condensation in nanoscopic sliding friction, Phys. Rev. Lett.
    88; Israelachvili 2011, Intermolecular and Surface Forces, ch. on capillary forces).
    The candidate's curve is Gaussian, Lorentzian or an exponential tail; the open forms
    add tails, rationals, films that lift, spikes, bimodal roughness, logs, Eyring,
    starvation, rubber hysteresis, resonances, dither, melting, grains, readsorption,
    thermoviscous, turbulent and thixotropic films, churning, core losses, breathing
    bellows, eddy brakes, shear thinning, flying pads, wiping menisci, journals, wall
    slip, a closing clearance, a dwell's squeeze or a pocket's suction. Here water
    condenses out of the air into each junction for as long as it lives.
    """
    law = kin.base
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (capillary_condensation): the mre_lugre base has "
                         "no Stribeck curve")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    vk = CAP_SPEED * max(kin.scales["v99"], 1e-12)
    k = float(s) * CAP_RISE
    return lugre_with_curve(kin, lambda vv: law.g(vv) * (1.0 + k * _condensed(vv / vk)))


# -- position --------------------------------------------------------------------------------
#: ``ball_passage``'s rise of the levels at an entry's peak over the ripple's mean, at
#: strength 1 [-]; the ripple's period (two ball pitches of travel), x the visited stroke
#: [-]; the peak's sharpness (the seal's crowning over the pitch) [-]
BALL_RISE, BALL_PERIOD, BALL_PEAK = 0.5, 0.09, 3.0


def _ball_entry(xr, period, peak):
    """The rolling resistance's ripple [-] (0 on average over a period, 1 at its peak) at
    the positions ``xr`` [-] (over the visited stroke): a ball entering the loaded zone
    every ``period`` of travel, exp(``peak`` (cos(2 pi xr / period) - 1)), less its mean
    e^-peak I0(peak), over its peak's excess."""
    w = np.exp(peak * (np.cos(2.0 * np.pi * np.asarray(xr, float) / period) - 1.0))
    m = math.exp(-peak) * float(np.i0(peak))
    return (w - m) / (1.0 - m)


@on_fine_grid
def ball_passage_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage runs on a recirculating-ball linear guide: its balls roll through the
    loaded zone at half its speed and return through its end caps. Each ball entering the
    loaded zone is squeezed over the crowning at the zone's end, and its entry raises the
    rolling resistance; rolling without slip, the balls' places follow the travel, so the
    entries repeat every two ball pitches of the carriage's travel (:data:`BALL_PERIOD` x
    the visited stroke) at the same positions (:func:`_ball_entry`, a peaked ripple). The
    Coulomb and Stribeck levels are the base's times 1 + ``s`` :data:`BALL_RISE` x the
    ripple, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the balls' preload at the entry over their mean, / its value
        at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Ball passage in linear rolling guides and its friction and force ripple (Ohta and
    Tanaka 2010, Vibration characteristics of a linear guideway type recirculating ball
    bearing, J. Vib. Acoust. 132; Harris and Kotzalas 2007, Rolling Bearing Analysis, ch.
    on the load distribution among the rolling elements; Slocum 1992, Precision Machine
    Design, ch. on rolling element bearings). The candidate scales the friction
    along the stroke and adds a force of the position; the open forms put defects,
    waviness, wear, runout, bends, films, cogging, tapers, pockets, cushions, covers,
    springs, holes, plungers, sags, festoons, curves, chains, cams, heat, dents, joints,
    misalignment, flow forces, cranks, overhangs, a track's end, a reel, a way's flatness
    or conductive strips on the stroke. Here the bearing's own balls set the ripple, their
    places a function of the travel.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (ball_passage): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    span = max(sc["x_hi"] - sc["x_lo"], 1e-12)
    xr = (np.asarray(kin.x, float) - sc["x_lo"]) / span
    lev = np.maximum(1.0 + float(s) * BALL_RISE * _ball_entry(xr, BALL_PERIOD, BALL_PEAK),
                     0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- inertia ---------------------------------------------------------------------------------
#: ``hanging_pendulum``'s payload mass at strength 1, x the friction level / a99 [kg per
#: N s^2/m]; its small swings' period, x the motion's time scale [-]; their damping ratio
#: [-]; the gravity the payload hangs in [m/s^2]
PEND_MASS, PEND_PERIOD, PEND_DAMPING, PEND_G = 0.5, 1.5, 0.1, 9.81


@njit(cache=True)
def _pendulum(t, a, omega, zeta, g):
    """The horizontal acceleration [m/s^2] of a pendulum's bob hung from a pivot that
    accelerates by ``a`` [m/s^2] at the times ``t`` [s] (uniform), from rest hanging
    straight: its angle theta from the vertical follows theta'' = -omega^2 (sin theta +
    a cos theta / ``g``) - 2 ``zeta`` ``omega`` theta' (the length g / omega^2), and the
    bob's acceleration is a + L (theta'' cos theta - theta'^2 sin theta); semi-implicit
    Euler on sub-steps of at most 0.02 / omega, the pivot's acceleration held over each."""
    n = t.size
    out = np.empty(n)
    L = g / (omega * omega)
    dt = t[1] - t[0] if n > 1 else 0.0
    n_sub = max(1, int(math.ceil(omega * dt / 0.02)))
    h = dt / n_sub
    th = 0.0
    w = 0.0
    for k in range(n):
        acc = -omega * omega * (math.sin(th) + a[k] * math.cos(th) / g) - 2.0 * zeta * omega * w
        out[k] = a[k] + L * (acc * math.cos(th) - w * w * math.sin(th))
        if k + 1 < n:
            am = 0.5 * (a[k] + a[k + 1])
            for _ in range(n_sub):
                acc = (-omega * omega * (math.sin(th) + am * math.cos(th) / g)
                       - 2.0 * zeta * omega * w)
                w = w + h * acc
                th = th + h * w
    return out


@on_fine_grid
def hanging_pendulum_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A payload hangs under the carriage on a rod or a cable (an overhead conveyor's
    carrier, a gantry crane's hook and load, a probe or a tool on a long stem), which the
    inverse dynamics misses. It swings as a gravity pendulum (:func:`_pendulum`; its small
    swings' period :data:`PEND_PERIOD` x the motion's time scale, so its length is g /
    omega^2; damped at :data:`PEND_DAMPING` by its pivot and the air), large swings
    nonlinear (sin theta, the centripetal term), and it pulls on the carriage with its own
    horizontal acceleration: the truth adds its mass (``s`` :data:`PEND_MASS` x the
    friction level / a99) times that acceleration to the base. Slow motions carry it whole;
    quicker ones leave it behind, swinging.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the payload's mass, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The pendulum on an accelerating pivot and the sway of suspended loads (Abdel-Rahman,
    Nayfeh and Masoud 2003, Dynamics and control of cranes: a review, J. Vib. Control 9;
    Singhose, Porter, Kenison and Kriikku 2000, Effects of hoisting on the input shaping
    control of gantry cranes, Control Eng. Pract. 8; Thomson and Dahleh 1998, Theory of
    Vibration with Applications, ch. on nonlinear vibrations). The candidate misses a
    constant mass; the open forms filter it, reflect it through gearing, a chain, a pinion
    or a screw, hang it on a spring, a cable, a fluid, a clutch, a coupling, a flyweight, a
    friction-damped, quasi-zero-stiffness, hose's or elastomer mount, surge a spring, add a
    fluid's mass, pick, drop, empty, slide, rattle, telescope, roll or rock it, recoil a
    frame, saturate a motor, lead a feedforward, pitch a scale or radiate waves. Here
    gravity is the spring: the payload swings below its pivot, a pendulum, not a mount.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    m = float(s) * PEND_MASS * _level(kin) / a99
    omega = 2.0 * math.pi / (PEND_PERIOD * max(_motion_time(kin), 1e-12))
    bob = _pendulum(np.asarray(kin.t, float), np.asarray(kin.a, float), omega,
                    PEND_DAMPING, PEND_G)
    return F + m * bob


# -- delay -----------------------------------------------------------------------------------
#: ``adaptive_filter``'s time constant while the reading is steady, at strength 1 [data
#: samples]; the band the input may leave the reading by before the filter speeds up, x
#: the force's range [-]; the filter's speed-up far outside the band [-]
ADAPT_SAMPLES, ADAPT_BAND, ADAPT_FAST = 3.0, 0.05, 8.0


@njit(cache=True)
def _adaptive_lowpass(t, u, tau, band, fast):
    """The output [N] of an adaptive first-order low-pass of the input ``u`` [N] at the
    times ``t`` [s], from the first input: its time constant ``tau`` [s] while the input
    stays within ``band`` [N] of the output, shortened to tau / (1 + (``fast`` - 1) r^2 /
    (1 + r^2)) as it leaves it (r the departure over the band); each step exact for the
    step's mean input and its time constant at the step's start."""
    n = u.size
    y = np.empty(n)
    y[0] = u[0]
    for k in range(n - 1):
        um = 0.5 * (u[k] + u[k + 1])
        r = (um - y[k]) / band
        r2 = r * r
        tk = tau / (1.0 + (fast - 1.0) * r2 / (1.0 + r2))
        y[k + 1] = um + (y[k] - um) * math.exp(-(t[k + 1] - t[k]) / tk)
    return y


@on_fine_grid
def adaptive_filter_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is read by a weighing indicator (a load cell's digital amplifier) with an
    adaptive filter, as such indicators damp vibration yet settle quickly: a first-order
    digital low-pass whose time constant is long (``s`` :data:`ADAPT_SAMPLES` data samples)
    while the input stays within a band of the reading (:data:`ADAPT_BAND` x the force's
    range) and shortens, down to 1 / :data:`ADAPT_FAST` of it, as the input leaves the
    band (:func:`_adaptive_lowpass`). Its lag changes with the force's own changes: long
    where the force creeps, short where it jumps, as at a reversal. The motion channels
    are on time.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the filter's steady time constant, / its value at strength
        1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Adaptive and time-varying filters for load cells and weighing (Piskorowski and
    Barcinski 2008, Dynamic compensation of load cell response: a time-varying approach,
    Mech. Syst. Signal Process. 22; Shu 1993, Dynamic weighing under nonzero initial
    conditions, IEEE Trans. Instrum. Meas. 42; OIML R 76-1 2006, Non-automatic weighing
    instruments, on stability of equilibrium). The candidate shifts the force by a
    constant time, low-passes it, reads it through a transducer's resonance and leaks it;
    the open forms sample, filter, average, hold, skew, jitter, rate-limit, transmit,
    median, report by deadband, trigger on positions, run a belt, aerate, drop telegrams,
    leak, creep, notch, track, snub, time a waveguide's pulse, diffuse eddy currents,
    count a resonator, sweep a grating, restore a force by a servo, interleave converters,
    balance a pneumatic cell or count out a dual slope. Here the filter's own time
    constant follows the signal: the lag is set by how far the force runs from the
    reading.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    band = ADAPT_BAND * max(float(np.ptp(F)), 1e-12)
    tau = float(s) * ADAPT_SAMPLES * kin.sample_dt
    return _adaptive_lowpass(np.asarray(kin.t, float), np.asarray(F, float), tau, band,
                             ADAPT_FAST)


# -- drift -----------------------------------------------------------------------------------
#: ``thermostat_cycling``'s fall of the levels per unit of the band's half-width, at
#: strength 1 [-]; the viscous term's fall per unit of it [-]; the chiller's cycle, x the
#: record's length [-]; the temperatures it heats and cools towards, x the band's
#: half-width [-]
CHILL_LEVEL, CHILL_VISC, CHILL_PERIOD, CHILL_REACH = 0.15, 0.4, 0.4, 3.0


@njit(cache=True)
def _thermostat(tau, period, reach):
    """The oil's temperature [-] (over the band's half-width, from its middle) at the times
    ``tau`` [-] (over the record's length) under an on-off chiller: off, it rises towards
    ``reach`` and switches on at +1; on, it falls towards -``reach`` and switches off at
    -1; from -1, off. Exponential arcs with the time constant that makes a cycle
    ``period`` long."""
    n = tau.size
    out = np.empty(n)
    tc = 0.5 * period / math.log((reach + 1.0) / (reach - 1.0))
    T = -1.0
    on = False
    out[0] = T
    for k in range(1, n):
        target = -reach if on else reach
        T = target + (T - target) * math.exp(-(tau[k] - tau[k - 1]) / tc)
        if not on and T >= 1.0:
            on = True
        elif on and T <= -1.0:
            on = False
        out[k] = T
    return out


@on_fine_grid
def thermostat_cycling_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The machine's oil (or the coolant of its bed and ways) is held by an on-off chiller
    with a switching band, as the simplest oil coolers are: off, the machine's heat warms
    the oil towards its uncooled temperature until the band's top switches the chiller
    on; on, it cools towards the chiller's until the band's bottom switches it off
    (:func:`_thermostat`, a cycle of :data:`CHILL_PERIOD` x the record's length). The
    temperature runs along exponential arcs, a rounded sawtooth with no trend, and the
    oil's viscosity (exponential in the temperature over the band, Reynolds' law) and the
    boundary film's friction follow it: the Coulomb and Stribeck levels are the base's
    times exp(-``s`` :data:`CHILL_LEVEL` T), the viscous term exp(-``s``
    :data:`CHILL_VISC` T), T the temperature over the band's half-width, inside the
    bristle dynamics.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the band's width, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    On-off (relay) temperature control and its limit cycle (Seborg, Edgar, Mellichamp and
    Doyle 2011, Process Dynamics and Control, ch. on on-off control; Astrom and Murray
    2008, Feedback Systems, ch. on relay feedback), machine tools' oil and coolant
    temperature (Bryan 1990, International status of thermal error research, CIRP Ann.
    39) and the viscosity's dependence on the temperature (Reynolds 1886, On the theory of
    lubrication, Philos. Trans. R. Soc. 177). The candidate is a trend, a saturating
    change, a step, a cycle, a resetting change or the friction power's heat; the open
    forms warm up, wear in, change, heat, wear, follow the humidity, grind, relubricate,
    relax, oxidise, deplete, wear through, swell, build films, take in particles, expand,
    shear down, heat magnets, charge, creep, loosen, dewet, channel, drain, spall,
    evaporate, pump down, settle an additive, crystallise wax or bleed a grease's oil.
    Here a relay's limit cycle sets the temperature: arcs between two switching points.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    tau = (t - t[0]) / max(t[-1] - t[0], 1e-12)
    T = _thermostat(tau, CHILL_PERIOD, CHILL_REACH)
    lev = np.exp(-float(s) * CHILL_LEVEL * T)
    return level_inside(kin, lev, np.exp(-float(s) * CHILL_VISC * T))


# -- backlash --------------------------------------------------------------------------------
#: ``air_cushion_gap``'s play at strength 1, as a share of the stroke (its full width) [-];
#: the chambers' precharge pressure times the piston's area, x the Coulomb level [-]; the
#: chambers' ends beyond the flanks, x the play's half-width [-]; the polytropic index [-]
CUSH_CLEAR, CUSH_PRESS, CUSH_END, CUSH_INDEX = 0.01, 0.05, 0.15, 1.4


@njit(cache=True)
def _air_force(e, half, p, end, n):
    """The trapped air's force [N] on the piston at its offset ``e`` [m] from the play's
    middle (half-width ``half`` [m]): each chamber ``half`` (1 + ``end``) long at the
    middle, precharged to the force ``p`` [N], compressed polytropically (index ``n``):
    p ((L / (L - e))^n - (L / (L + e))^n); the offset held within the flanks' overshoot
    (half the ends)."""
    L = half * (1.0 + end)
    lim = half * (1.0 + 0.5 * end)
    ee = min(max(e, -lim), lim)
    return p * ((L / (L - ee)) ** n - (L / (L + ee)) ** n)


@njit(cache=True)
def _cushioned_contact(h, xd, half, p, end, n_idx, kh, ch, m, s0, s1, s2, Fc, Fs, vs,
                       alpha, shape):
    """LuGre friction [N] of a light contact of mass ``m`` [kg] driven by the drive positions
    ``xd`` [m] (steps ``h`` [s]) through a play of half-width ``half`` [m] closed at the
    flanks by a spring ``kh`` [N/m] and damper ``ch`` [N s/m] (compressive only) and
    bridged by the trapped air of :func:`_air_force`; from rest, the piston in the play's
    middle. Semi-implicit Euler of the contact, its bristle exact."""
    nn = xd.size
    F = np.empty(nn)
    x = xd[0]
    v = 0.0
    z = 0.0
    for j in range(nn):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        e = xd[j] - x
        ed = vd - v
        fc = _air_force(e, half, p, end, n_idx)
        if e > half:
            f2 = kh * (e - half) + ch * ed
            if f2 > 0.0:
                fc += f2
        elif e < -half:
            f2 = kh * (e + half) + ch * ed
            if f2 < 0.0:
                fc += f2
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha,
                                         shape)
        x = x + h * v
    return F


@on_fine_grid
def air_cushion_gap_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact are joined through a closed chamber: the drive's piston (a pin
    with a seal, a plunger) moves in a bore of the contact's link with a play of ``s``^2
    :data:`CUSH_CLEAR` x the stroke, and air is trapped on each side of it (a pneumatic
    lost-motion link, an air-cushioned stop). Crossing the play the piston compresses the
    air ahead and expands the air behind, polytropically (index :data:`CUSH_INDEX`):
    p ((L / (L - e))^n - (L / (L + e))^n) (:func:`_air_force`; precharged to
    :data:`CUSH_PRESS` x the Coulomb level, the chambers' ends :data:`CUSH_END` x the
    half-play beyond the flanks), soft in the play's middle and steeply stiffer towards
    its end, where the flanks (as the open plays') take the drive up
    (:func:`_cushioned_contact`). The contact is light (its inertial force at the top
    acceleration 1 % of the Coulomb level) with the base's LuGre friction.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the square root of the play's width, / its value at strength
        1 (as the open plays').

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Pneumatic cushioning and the polytropic compression of trapped air (Beater 2007,
    Pneumatic Drives, ch. on cylinders and end-position cushioning; Cengel and Boles 2015,
    Thermodynamics: An Engineering Approach, ch. on polytropic processes) and lost motion
    in mechanisms (Nordin and Gutman 2002, Controlling mechanical systems with backlash -
    a survey, Automatica 38). The candidate holds or frees the contact across a rigid play;
    the open forms take it up rigidly, compliantly, by impact, against a spring,
    eccentrically, through oil, worn, with a dragging idler, biased, slack, magnetic,
    preloaded, through a flexspline, a rope, a spider, a fluid link, a cable, a clutch, a
    varying mesh, a polymer gear, grease, a wedge, an overlapped spool, a side loaded pin,
    a toggle spring, graded pins, an adhesive flank, packed powder or a floating part
    between two plays. Here a gas bridges the play: a cushion that stiffens as it closes,
    with no leak and no drag.
    """
    p = _lugre_params(kin, "backlash (air_cushion_gap)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    half = 0.5 * float(s) ** 2 * CUSH_CLEAR * float(np.ptp(kin.x))
    m, kh, ch = _contact_constants(kin, p)
    pa = CUSH_PRESS * float(p.Fc)
    rate = max(math.sqrt(kh / m), (float(p.sigma1) + float(p.sigma2) + ch) / m)
    h, xd, n_sub = _substeps(kin, rate)
    Fr = _cushioned_contact(h, xd, half, pa, CUSH_END, CUSH_INDEX, kh, ch, m,
                            float(p.sigma0), float(p.sigma1), float(p.sigma2), float(p.Fc),
                            float(p.Fs), float(p.vs), float(p.alpha), SHAPES[p.shape])
    return Fr[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: ``shear_melting_film``'s share of the friction the film carries, at strength 1 (at most
#: 0.95) [-]; the solid film's path to its yield beyond the base bristle's Fs / sigma0, at
#: strength 1, x the stroke / 3 [-]; the slip that melts it, x that path [-]; its freezing
#: time, x the motion's time scale [-]; the melt's speed of full stress, x the top speed [-]
MELT_SHARE, MELT_PATH, MELT_SLIP, MELT_FREEZE, MELT_SPEED = 0.3, 0.1, 3.0, 1.0, 0.05


@njit(cache=True)
def _film_state(t, v, path, slip, freeze):
    """(elastic strain [m], solid share [-]) of a confined film along the velocities ``v``
    [m/s] at the times ``t`` [s], from rest, solid and unstrained: the solid strains with
    the motion up to its yield path ``path`` [m], beyond it slips; the slip melts it
    (the solid share times exp(-slip / ``slip``)), and it freezes again towards all solid
    over ``freeze`` [s]."""
    n = v.size
    z = np.empty(n)
    phi = np.empty(n)
    zz = 0.0
    ph = 1.0
    for k in range(n):
        z[k] = zz
        phi[k] = ph
        if k + 1 < n:
            dt = t[k + 1] - t[k]
            zt = zz + 0.5 * (v[k] + v[k + 1]) * dt
            sl = 0.0
            if zt > path:
                sl = zt - path
                zt = path
            elif zt < -path:
                sl = -path - zt
                zt = -path
            zz = zt
            ph = 1.0 - (1.0 - ph) * math.exp(-dt / freeze)
            ph = ph * math.exp(-sl / slip)
    return z, phi


@on_fine_grid
def shear_melting_film_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Part of the contact is carried through a confined lubricant film a few molecular
    layers thick (a boundary film of a long-chain or a near-spherical lubricant, as in
    precision slides' and surface-force apparatus' contacts). At rest the confined film is
    solid-like: it strains elastically, up to its yield path (the base bristle's Fs /
    sigma0 plus ``s`` :data:`MELT_PATH` x the stroke / 3), and then slips; its slip melts
    it (shear melting, over :data:`MELT_SLIP` x the path of slip), and at rest it freezes
    again over a time (:data:`MELT_FREEZE` x the motion's time scale;
    :func:`_film_state`). The solid part
    carries its elastic stress, the molten part a liquid's, tanh(v / v_m) (v_m
    :data:`MELT_SPEED` x the top speed), each times the Stribeck level: its share w = ``s``
    :data:`MELT_SHARE` of the friction is w g(v) (phi z / path + (1 - phi) tanh(v / v_m)),
    the rest the base's LuGre (its viscous term whole). After a dwell the presliding is a
    solid's, stiff; after a quick reversal a melt's, rounded; sliding, the base's. At
    ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the film's share of the contact (up to ``s`` = 0.95 /
        :data:`MELT_SHARE`) and its elastic path (as the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Shear melting and freezing of confined films (Thompson and Robbins 1990, Origin of
    stick-slip motion in boundary lubrication, Science 250; Yoshizawa and Israelachvili
    1993, Fundamental mechanisms of interfacial friction. 2. Stick-slip friction of
    spherical and chain molecules, J. Phys. Chem. 97; Persson 2000, Sliding Friction:
    Physical Principles and Applications, ch. on boundary lubrication). The candidate's
    presliding is a generalized Maxwell-slip (GMS) element set; the open forms are
    Maxwell-slip sets, Dahl, elasto-plastic, Bliman-Sorine, Bouc-Wen, Zener junctions,
    Mindlin contacts, rate-and-state, Tomlinson asperities, bond rupture, gouge, kinematic
    hardening, interlocking, capillary bridges, cyclic hardening, peeling, unloading
    microslip, a power-law joint, junction growth, avalanches, slip weakening, a microslip
    bar, contact renewal, grease's yield, a superelastic flexure, an Eyring film, a
    viscoplastic layer or a poroelastic one, each beside the contact, or a stiffening wire
    mesh in series with it. Here the film changes phase: solid after a dwell, melted by
    its own slip.
    """
    _lugre_params(kin, "gms (shear_melting_film)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    w = min(float(s) * MELT_SHARE, 0.95)
    t = np.asarray(kin.t, float)
    v = np.asarray(kin.v, float)
    e0, extra = _presliding_path(kin, s, MELT_PATH)
    path = e0 + extra
    z, phi = _film_state(t, v, path, MELT_SLIP * path,
                         MELT_FREEZE * max(_motion_time(kin), 1e-12))
    vm = MELT_SPEED * max(kin.scales["v99"], 1e-12)
    law = kin.base
    film = law.g(v) * (phi * z / path + (1.0 - phi) * np.tanh(v / vm))
    rest = lugre_with_curve(kin, law.g, np.full(v.size, 1.0 - w), np.ones(v.size))
    return rest + w * film
