"""The eighteenth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-30 (session 23) by another hand, once, without running the diagnosis on it;
run once, sealed, at the start of session 24 on the code of ba95736 (session 23's last):
176 cases, 0 skipped, 562 s wall on 2 workers (beside a 1-process helper). Top-1 53.4 %
(94; 55.3 % of the 170 detectable; the other 6: 4 Stribeck shapes and 2 backlash cases an
oracle cannot tell from the base); mean |shrink error| 0.345; wrong names on 20 (11.4 %):
acceleration -> position 4 (the isolator's one-frequency stroke), load -> drift 4,
asymmetry -> stribeck_shape 4, gms -> acceleration 2, and six single ones. By form:
drift/screw_loosening 19/20, position/false_brinelling 16/16, load/ploughing_onset 16/20,
acceleration/ball_train 12/20, asymmetry/running_belt 12/20, inertia/feedforward_lead
12/20, gms/slip_avalanches 5/12, stribeck_shape/bellows_breathing 2/16,
delay/transducer_resonance 0/20, backlash/polymer_gear 0/12. By plant: damping rig 57.5 %,
isolator 57.1 %, XML-350 55.0 %, valve 52.5 %, press 42.9 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen17` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen17`,
:mod:`diagnosis.effects_backlash`, :mod:`diagnosis.effects_gms`) and than the candidate's
formula (:mod:`diagnosis.candidates`), taken from the friction literature or from real
machines, integrated along the plant's continuous motion on the grid :data:`.kinematics.FINE`
x finer than the data (:func:`.truths.on_fine_grid`); level changes act inside the bristle
dynamics of a LuGre base (:func:`.truths.level_inside`). ``s`` scales each effect's
amplitude monotonically from the base law at ``s`` = 0 (its calibration,
:func:`.cases._calibrate`, sets the requested size).

=================  =====================================================================
effect             form
=================  =====================================================================
acceleration       ``ball_train``: the balls of a recirculating guide's return channel
                   (or a ball nut's) are pushed as a train through the end cap's
                   turnaround by the balls leaving the loaded zone; speeding the carriage
                   up compresses the train, whose ball-to-ball and wall contacts slide
                   (Ohta and Tanaka 2010; the makers' ball spacers and retainers):
                   a drag with the speeding-up acceleration only; slowing down, the
                   train runs on by itself and opens
load               ``ploughing_onset``: beside the adhesive friction, the harder
                   surface's asperities (or embedded hard particles) plough grooves in
                   the softer one once the load passes the yield onset (Bowden and
                   Tabor 1950; Goddard and Wilman 1962; Suh and Sin 1981): a ploughing
                   force ~ (load - onset)^1.5 (a groove's section, ~ its width cubed)
                   above the onset, nothing below
asymmetry          ``running_belt``: a skid shoe of the carriage rests on a conveyor
                   belt running at a fixed speed in the positive direction (a shuttle
                   beside a running transfer belt): its friction follows the *relative*
                   velocity v - u_belt: the belt pulls the carriage forward at rest and
                   in the negative direction, and drags it only above the belt's speed
stribeck_shape     ``bellows_breathing``: the way's accordion bellows cover is
                   compressed and stretched by the carriage and breathes through its
                   vents: the orifice law (Delta p ~ rho (Q / A)^2) makes a drag ~ v^2,
                   which turns linear in v once the vents' flow chokes (the sonic
                   limit of compressible orifice flow, Saint-Venant and Wantzel 1839)
position           ``false_brinelling``: the carriage was parked where fit and held-out
                   parts both pass while the machine vibrated (transport, a nearby
                   press): its balls wore dents in the raceway at their pitch (false
                   brinelling, Almen 1937; Tallian 1992): rolling over them, the balls
                   drop into and climb out of the dents, most where all balls meet
                   dents at once: a pattern at the ball pitch whose envelope falls
                   linearly over the carriage's loaded length either side
inertia            ``feedforward_lead``: the force is read from the drive's force
                   command, which carries an acceleration feedforward of the *commanded*
                   trajectory with a mass setting off the true one (Tomizuka 1987;
                   Altintas 2012): the command leads the measured motion by the servo's
                   tracking lag, so the missed mass multiplies the acceleration of a
                   moment *later*
delay              ``transducer_resonance``: the force transducer with the mass mounted
                   on it is a lightly damped spring-mass system (the dynamic
                   calibration of force transducers, Kumme 1996; ISO 4965): its
                   reading follows the force through a second-order low-pass of low
                   damping: a lag on ramps and a ringing after each fast change
drift              ``screw_loosening``: the gib's (or the preloaded nut's) clamping
                   screw works loose by the transverse slip each reversal puts through
                   its joint (self-loosening, Junker 1969; DIN 65151): the preload, and
                   the levels, fall step by step at the reversals, a share of what is
                   left at each: a drift that follows the count of reversals, not the
                   clock or the travel
backlash           ``polymer_gear``: drive and contact joined by a plastic gear (POM,
                   PA) with play: the mesh's friction power warms the teeth, which swell
                   (the play closes) and soften (the flanks' compliance grows) with
                   their temperature (VDI 2736; the makers' backlash allowances for
                   plastic gears): the lost motion at the reversals shrinks over the
                   record while the force's build-up after them grows softer
gms                ``slip_avalanches``: the presliding junctions beside the bristle are
                   coupled to their neighbours through the elastic body between them
                   (the Burridge-Knopoff chain, 1967; Olami, Feder and Christensen
                   1992; Rubinstein, Cohen and Fineberg 2007's precursors): a junction
                   that slips loads its neighbours and may set off a slip avalanche, so
                   the presliding curve climbs in bursts of all sizes, not element by
                   element; at ``s`` = 0 the base itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``bellows_breathing``
needs a Stribeck curve (not the isolator's mre_lugre), ``false_brinelling`` a record that
revisits its positions (not the press), ``ploughing_onset`` a load that changes,
``polymer_gear`` and ``slip_avalanches`` a classic LuGre base (valve, damping rig,
XML-350); each raises a ``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.shapes import SHAPES

from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _level,
                     _light_contact_step, _lugre_params, _motion_time, _presliding_path,
                     _smooth_max0, _span, _substeps, has_stribeck_curve, level_inside,
                     on_fine_grid)

__all__ = ["FORMS", "ball_train_truth", "ploughing_onset_truth", "running_belt_truth",
           "bellows_breathing_truth", "false_brinelling_truth", "feedforward_lead_truth",
           "transducer_resonance_truth", "screw_loosening_truth", "polymer_gear_truth",
           "slip_avalanches_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "ball_train", "load": "ploughing_onset",
         "asymmetry": "running_belt", "stribeck_shape": "bellows_breathing",
         "position": "false_brinelling", "inertia": "feedforward_lead",
         "delay": "transducer_resonance", "drift": "screw_loosening",
         "backlash": "polymer_gear", "gms": "slip_avalanches"}


# -- acceleration ----------------------------------------------------------------------------
#: ``ball_train``'s drag at the top acceleration, x the friction level, at strength 1 [-];
#: the speed the train's motion is rounded over, x the top speed [-]
TRAIN_DRAG, TRAIN_ROUND = 0.5, 0.02


def _train_push(v, a, v_round):
    """The ball train's compression [-] (over the one at ``a`` = 1) along the velocities
    ``v`` [m/s] and accelerations ``a`` [m/s^2] and the direction of travel tanh(v /
    ``v_round``) it is pushed in: the speeding-up acceleration max(a sgn(v), 0);
    slowing down, nothing pushes the train (it runs on and opens). Returns
    (compression, direction)."""
    sgn = np.tanh(np.asarray(v, float) / v_round)
    return np.maximum(np.asarray(a, float) * sgn, 0.0), sgn


@on_fine_grid
def ball_train_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The contact is a recirculating ball guide (or a ball nut) without spacers: the
    balls leaving the loaded zone push the balls of the return channel as a train through
    the end cap's curved turnaround. Speeding the carriage up, the train must be
    accelerated too and is compressed from behind; its balls turn the same way, so their
    contacts with each other slide at twice their surface speed, and the turnaround's
    wall takes the compression round the bend: both drag in proportion to the
    compression (:func:`_train_push`). Slowing down, nothing pushes: the train runs on by
    its own momentum and opens. The truth adds ``s`` :data:`TRAIN_DRAG` F_level max(a
    sgn(v), 0) / a99 in the direction of travel to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the train's mass times its contacts' friction, / its value
        at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Ball-to-ball contact and ball circulation resistance in linear ball guides and ball
    screws (Ohta and Tanaka 2010, Effect of ball-to-ball contact on friction of linear
    ball guides, Tribol. Trans.; THK's caged-ball technology and the makers' ball
    spacers that prevent it). The candidate raises the levels with |a|, lagged, tilts them
    with a and adds a force odd in a; the open forms lag the velocity, a film or a
    contact state, heat the contact, skid rolling elements, move load between rows or
    supports, press seals, pull with the thrust, squeeze or starve films, dilate, lift on
    a wedge, shift a gib, soften an elastomer, swing a roller arm, unload by the jerk or
    tilt a pressurised film. Here the drag depends on whether the carriage speeds up or
    slows down: the product a v, not |a|, with nothing at all while it slows.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    a99 = max(sc["a99"], 1e-12)
    push, sgn = _train_push(kin.v, kin.a, TRAIN_ROUND * max(sc["v99"], 1e-12))
    return F + float(s) * TRAIN_DRAG * _level(kin) * (push / a99) * sgn


# -- load ------------------------------------------------------------------------------------
#: ``ploughing_onset``'s onset of the ploughing, as a percentile of the record's load [%];
#: the ploughing force at the record's top load (its 99th percentile), x the friction
#: level, at strength 1 [-]; the load the onset is rounded over, x the mean load [-]
PLOUGH_ONSET, PLOUGH_SHARE, PLOUGH_ROUND = 40.0, 0.8, 0.01


def _ploughing(load, onset, top, eps):
    """The ploughing force [-] (1 at the load ``top``) along the loads ``load`` [N]: the
    groove's section of a spherical asperity pressed past the yield onset ``onset`` [N],
    ~ (L - onset)^1.5 (its width ~ sqrt(L - onset) cubed over its radius), nothing below
    the onset (the excess rounded over ``eps`` [N])."""
    e = _smooth_max0(np.asarray(load, float) - onset, eps)
    ref = max(top - onset, eps)
    return (e / ref) ** 1.5


@on_fine_grid
def ploughing_onset_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Beside the adhesive friction (the base's, following its own law), the harder
    surface's asperities plough grooves in the softer surface once the load passes the
    yield onset (:data:`PLOUGH_ONSET` percentile of the record's load): a spherical
    asperity pressed in plastically makes a groove whose width grows as the square root
    of the excess load and whose section, which the ploughing force pushes aside, as its
    cube over the asperity's radius (:func:`_ploughing`). The Coulomb and Stribeck
    levels are the base's times 1 + ``s`` :data:`PLOUGH_SHARE` (L - L_onset)_+^1.5 /
    (L99 - L_onset)^1.5, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (load [N]) and its base law.
    s : float
        Amplitude factor [-]: the ploughing asperities' share (their number over their
        radius), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The ploughing term of friction (Bowden and Tabor 1950, The Friction and Lubrication
    of Solids, ch. 5; Goddard and Wilman 1962, A theory of friction and wear during the
    abrasion of metals, Wear 5; Suh and Sin 1981, The genesis of friction, Wear 69);
    the onset of yield under a sphere (Johnson 1985, Contact Mechanics, ch. 6). The
    candidate's levels are affine in the load (two regimes); the open forms scale them
    with a power of the load from zero, in one direction, through the Stribeck velocity,
    a film, a step, a creep, a rate, a lever's play, a plastic area, a hinge, a cavitating
    film, a pressure-viscous film, an erf area, a flash temperature, a relay, a renewal
    over the slip, an adhesive area, the position of the load or a preload's relief.
    Here a second term of other physics starts at a threshold and grows faster than the
    load above it: nothing below the onset, convex above.
    """
    L = np.asarray(kin.load, float)
    Lm = max(float(np.mean(np.abs(L))), 1e-300)
    if not np.ptp(L) > 1e-9 * Lm:
        raise ValueError(f"load (ploughing_onset): the {kin.plant} record's load does not "
                         f"change")
    if s <= 0.0:
        return _base_parts(kin)[0]
    onset = float(np.percentile(L, PLOUGH_ONSET))
    top = float(np.percentile(L, 99.0))
    lev = 1.0 + float(s) * PLOUGH_SHARE * _ploughing(L, onset, top, PLOUGH_ROUND * Lm)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``running_belt``'s belt speed, x the top speed [-]; the shoe's friction, x the friction
#: level, at strength 1 [-]; the relative speed the shoe's friction is rounded over, x the
#: top speed [-]
BELT_SPEED, BELT_SHOE, BELT_ROUND = 0.4, 0.4, 0.02


def _shoe_friction(v, u_belt, v_round):
    """The skid shoe's friction [-] (over its Coulomb force) at the carriage's velocities
    ``v`` [m/s] on a belt running at ``u_belt`` [m/s]: tanh((v - u_belt) / ``v_round``),
    the sign of the slip against the belt, rounded."""
    return np.tanh((np.asarray(v, float) - u_belt) / v_round)


@on_fine_grid
def running_belt_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A skid shoe of the carriage (a pusher's, a shuttle's) rests on a conveyor belt that
    runs beside the axis at the fixed speed u = :data:`BELT_SPEED` v99 in the positive
    direction. The shoe's friction follows the slip against the belt, v - u
    (:func:`_shoe_friction`): at rest and moving in the negative direction the belt
    pulls the carriage forward with the shoe's whole friction; moving in the positive
    direction it still pulls while the carriage is slower than the belt and drags once
    it is faster. The truth adds ``s`` :data:`BELT_SHOE` F_level tanh((v - u) / (
    :data:`BELT_ROUND` v99)) to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the shoe's friction (its spring's force), / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Sliding on a moving counter-surface, the friction along the relative velocity
    (Coulomb's law in the frame of the belt; belt conveyors' skid plates and pushers,
    CEMA 2014, Belt Conveyors for Bulk Materials; pallets and accumulation on a running
    belt). The candidate's twins and offset are the same at every speed; the open forms
    change with the direction through twin levels, curves or a viscous slope, roll a lip,
    load a thrust bearing, wipe a rod's film, climb a texture, compress a spring, wedge a
    pad or a sprag, throttle an exhaust, meter a cylinder, pump through grooves, buckle a
    cable, bulldoze chips, commutate late, tension an idler, lock a roller's clutch or
    lay an oil film ahead. Here the counter-surface itself moves: the direction that
    matters is the one of the slip against the belt, so the positive direction's force
    changes sign at the belt's speed.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    shoe = _shoe_friction(kin.v, BELT_SPEED * v99, BELT_ROUND * v99)
    return F + float(s) * BELT_SHOE * _level(kin) * shoe


# -- stribeck_shape --------------------------------------------------------------------------
#: ``bellows_breathing``'s drag at the top speed, x the Coulomb level, at strength 1 [-]; the
#: speed at which the vents' flow chokes, x the top speed [-]
BELLOWS_DRAG, BELLOWS_CHOKE = 0.5, 0.45


def _vent_drag(u, choke):
    """The bellows' pressure drag [-] at the relative speeds ``u`` = v / v99 [-]: the
    orifice law's u |u| at low flows, linear in u once the flow chokes at ``choke``
    [-]: u |u| / sqrt(1 + (u / choke)^2) (over its value at ``u`` = 1 times the same)."""
    u = np.asarray(u, float)
    return u * np.abs(u) / np.sqrt(1.0 + (u / choke) ** 2)


@on_fine_grid
def bellows_breathing_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The way is covered by an accordion bellows that the carriage compresses on one
    side and stretches on the other; the air it displaces (its section times v) breathes
    through the bellows' vents. Through an orifice the pressure difference grows with the
    square of the flow, so the drag on the carriage grows as v |v|; once the vents' flow
    chokes (the sonic limit of compressible orifice flow) the pressure ahead grows only in
    proportion to the flow, so the drag turns linear in v (:func:`_vent_drag`). The truth
    adds ``s`` :data:`BELLOWS_DRAG` Fc q(v / v99) / q(1) to the base, q the vent drag.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (with a Stribeck curve).
    s : float
        Amplitude factor [-]: the bellows' section over its vents' (squared), / its value
        at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Orifice flow and its choking (Saint-Venant and Wantzel 1839; ISO 6358 for pneumatic
    components' sonic conductance); way covers and bellows of machine tools (Weck and
    Brecher 2006, Werkzeugmaschinen 2). The open forms take other tails, lift-offs,
    peaks, roughness, rate-and-state, Eyring films, starvation, rubber hysteresis,
    resonances, dither, melt films, granular flow, readsorption, thermal, turbulent,
    thixotropic films, churning or the drive's core losses, each a property of the contact,
    its lubricant or the drive. Here the curve's new part is the air the cover pumps: a
    drag that starts quadratic from zero and straightens at the choke, with no level at
    rest.
    """
    law = kin.base
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (bellows_breathing): the mre_lugre base has no "
                         "Stribeck curve")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    q1 = float(_vent_drag(np.array([1.0]), BELLOWS_CHOKE)[0])
    drag = float(s) * BELLOWS_DRAG * float(law.params.Fc) / q1
    return F + drag * _vent_drag(np.asarray(kin.v, float) / v99, BELLOWS_CHOKE)


# -- position --------------------------------------------------------------------------------
#: ``false_brinelling``'s ball pitch, x the stroke [-]; the balls in a loaded row [-]; the
#: dents' width (their standard deviation), x the pitch [-]; the levels' rise with every
#: ball in a dent, at strength 1 [-]
DENT_PITCH, DENT_BALLS, DENT_WIDTH, DENT_RISE = 0.04, 8, 0.15, 0.8


def _dent_pattern(x, centre, pitch, balls, width):
    """The share [-] of a row's balls in a dent along the positions ``x`` [m] of a carriage
    parked at ``centre`` [m]: the dents sit at the parked balls' places, a ``pitch`` [m]
    apart; moved by k pitches, ``balls`` - |k| of the balls meet a dent at once (a
    triangle of half-width ``balls`` pitches), and each dent's depth profile is a
    Gaussian of ``width`` pitches."""
    d = (np.asarray(x, float) - centre) / pitch
    frac = d - np.round(d)
    dent = np.exp(-0.5 * (frac / width) ** 2)
    return np.clip(1.0 - np.abs(d) / balls, 0.0, None) * dent


@on_fine_grid
def false_brinelling_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage stood parked, while the machine vibrated, where fit and held-out parts
    both pass (:func:`.truths._bump_centre`): the balls of its loaded row
    (:data:`DENT_BALLS`, a pitch :data:`DENT_PITCH` x the stroke apart) wore shallow
    dents in the raceway where they stood. Rolling over them, a ball drops into a dent
    and climbs out of it: the rolling resistance rises while balls sit in dents, most
    where all of them meet their dents at once (the parked position, and every pitch
    from it with one ball fewer: :func:`_dent_pattern`). The Coulomb and Stribeck levels
    are the base's times 1 + ``s`` :data:`DENT_RISE` x the share of balls in a dent,
    inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the dents' depth, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    False brinelling (fretting wear of a standing rolling contact under vibration: Almen
    1937, Lubricants and false brinelling of ball and roller bearings, Mech. Eng. 59;
    Tallian 1992, Failure Atlas for Hertz Contact Machine Elements; the makers' transport
    locks for linear guides). The open forms raise the levels by a bump, a wave, a worn
    stretch, a runout, a bent rail, a transfer film, a cogging force, a taper, an oil
    port's wake, a cushion, a cover, an air spring, bolt holes, an immersed plunger, a
    sagging beam, a festoon, a curved track, a gliding chain, a cam or a heated zone.
    Here a short wave at the ball pitch, only around one place, with an envelope that
    falls linearly over the carriage's length: the mark of where the carriage once stood.
    """
    xc = _bump_centre(kin)
    if xc is None:
        raise ValueError(f"position (false_brinelling): the held-out part of the "
                         f"{kin.plant} record never revisits the positions of its fit part")
    if s <= 0.0:
        return _base_parts(kin)[0]
    share = _dent_pattern(kin.x, xc, DENT_PITCH * _span(kin), DENT_BALLS, DENT_WIDTH)
    lev = 1.0 + float(s) * DENT_RISE * share
    return level_inside(kin, lev, np.ones_like(lev))


# -- inertia ---------------------------------------------------------------------------------
#: ``feedforward_lead``'s mass error of the feedforward at strength 1, x the friction level /
#: a99 [-]; the servo's tracking lag, x the motion's time scale v99 / a99 [-]
FF_MASS, FF_LEAD = 0.6, 0.15


def _commanded(t, a, lead):
    """The commanded acceleration [m/s^2] along the times ``t`` [s]: the measured
    accelerations ``a`` [m/s^2] read ``lead`` [s] later (the command leads the motion by
    the servo's tracking lag; past the record's end its last value)."""
    return np.interp(np.asarray(t, float) + lead, t, a)


@on_fine_grid
def feedforward_lead_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is read from the drive's force command (its current set point), which is
    the position controller's output plus an acceleration feedforward of the commanded
    trajectory with a mass setting m off the carriage's. The measured motion follows the
    command with the servo's tracking lag (:data:`FF_LEAD` x the motion's time scale), so
    the commanded acceleration is the measured one read that much later
    (:func:`_commanded`): the truth adds m a(t + lag) to the base, m a99 = ``s``
    :data:`FF_MASS` x the friction level.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the feedforward's mass error, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Acceleration feedforward and tracking lag of feed drives (Tomizuka 1987, Zero phase
    error tracking algorithm for digital control, J. Dyn. Syst. Meas. Control 109;
    Altintas 2012, Manufacturing Automation, ch. 6). The candidate misses a constant
    mass; the open forms filter it, reflect it through gearing, a chain's polygon or a
    pinion, hang it on a spring, a cable, a fluid, a clutch, a coupling, a flyweight or a
    screw, pick it up, drop it, empty it, rattle it, recoil the frame or saturate the
    motor, each missing the acceleration now or in the past. Here the missed mass
    multiplies the acceleration a moment ahead: a lead, not a lag.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    lead = FF_LEAD * max(_motion_time(kin), 1e-12)
    m = float(s) * FF_MASS * _level(kin) / max(sc["a99"], 1e-12)
    return F + m * _commanded(kin.t, np.asarray(kin.a, float), lead)


# -- delay -----------------------------------------------------------------------------------
#: ``transducer_resonance``'s period of the transducer's resonance at strength 1, in data
#: samples / 2 pi (1 / omega_n) [-]; its damping ratio [-]
RES_SAMPLES, RES_DAMPING = 3.0, 0.12


def _resonance(t, F, omega, zeta):
    """``F`` [N] along the times ``t`` [s] (uniform) through the spring-mass transducer
    omega^2 / (s^2 + 2 ``zeta`` ``omega`` s + ``omega``^2) (its reading the spring's
    deflection), discretised by the bilinear transform, from rest at the first value."""
    from scipy.signal import bilinear, lfilter, lfilter_zi
    fs = 1.0 / float(t[1] - t[0])
    b, a = bilinear([omega * omega], [1.0, 2.0 * zeta * omega, omega * omega], fs)
    F = np.asarray(F, float)
    return lfilter(b, a, F, zi=lfilter_zi(b, a) * F[0])[0]


@on_fine_grid
def transducer_resonance_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force transducer carries the mass mounted on it (the contact's holder): with
    the transducer's spring it is a lightly damped spring-mass system of angular
    frequency omega_n = 1 / (``s`` :data:`RES_SAMPLES` data samples) and damping ratio
    :data:`RES_DAMPING`, and the reading is the spring's deflection
    (:func:`_resonance`): it follows a ramp late by 2 zeta / omega_n and rings at
    omega_n after each fast change of the force (a reversal, a breakaway). No cap at
    :data:`.truths.MAX_DELAY_SAMPLES`: the plants whose force turns gently need a slow
    resonance to reach the requested size.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the resonance's period, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The dynamic behaviour of force transducers and their mounted mass (Kumme 1996, Dynamic
    force measurement in practical applications, IMEKO; ISO 4965-1 for the dynamic
    calibration of testing machines; Link, Glockner and Kobusch 2010). The open forms delay
    by one amount, filter by a low-pass, linearly or by rank, hold at a fieldbus's clock,
    let the delay drift, wander or follow the force's rate, level or slowness, the
    motion's speed or the position, hold stale values over lost telegrams, lead through a
    leaking charge, creep, take out the mains' band or track with a rate state. Here a
    mechanical resonance of the sensor itself: little damping, so each fast change of the
    force rings on in the reading.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    tau = float(s) * RES_SAMPLES * float(kin.sample_dt)
    return _resonance(np.asarray(kin.t, float), F, 1.0 / tau, RES_DAMPING)


# -- drift -----------------------------------------------------------------------------------
#: ``screw_loosening``'s share of the remaining preload lost at each reversal [-]; the
#: levels' fall with the whole preload lost, at strength 1 [-]; the time each loosening
#: step is rounded over, x the record's length [-]; the speed the direction of travel is
#: told by (a hysteresis), x the top speed [-]; the lowest relative level [-]
LOOSEN_STEP, LOOSEN_DROP, LOOSEN_ROUND, LOOSEN_SPEED, LOOSEN_FLOOR = (
    0.06, 0.6, 0.004, 0.02, 0.05)


def _reversal_times(t, v, v_min):
    """The times [s] along ``t`` [s] at which the direction of travel changes (the
    velocities ``v`` [m/s] pass -``v_min`` and ``v_min`` [m/s] the other way, a
    hysteresis against the standstills' crawl), at the zero crossing before it."""
    v = np.asarray(v, float)
    out = []
    state = 0
    last_zero = 0
    for k in np.flatnonzero(np.abs(v) > v_min):
        d = 1 if v[k] > 0.0 else -1
        if state != 0 and d != state:
            # the last sign change before this sample
            seg = np.flatnonzero(np.sign(v[last_zero:k + 1]) != d)
            j = last_zero + (seg[-1] if seg.size else 0)
            out.append(float(t[j]))
        if d != state:
            state = d
        last_zero = k
    return np.asarray(out)


def _loosened(t, reversals, step, width):
    """The preload lost [-] (1 - the remaining share) along the times ``t`` [s] after the
    ``reversals`` [s]: each loses ``step`` of what is left, 1 - (1 - step)^n(t), the
    count n(t) of reversals rounded over ``width`` [s]."""
    t = np.asarray(t, float)
    n = np.zeros_like(t)
    for tr in reversals:
        n += 0.5 * (1.0 + np.tanh((t - tr) / width))
    return 1.0 - (1.0 - step) ** n


@on_fine_grid
def screw_loosening_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The contact's preload is set by a clamping screw (a gib's adjusting screw, a
    preloaded nut's lock) whose joint slips a little transversely at each reversal of the
    friction force: each slip turns the screw back a little (self-loosening), so at each
    reversal (:func:`_reversal_times`) the preload loses :data:`LOOSEN_STEP` of what is
    left (:func:`_loosened`). The Coulomb and Stribeck levels are the base's times 1 -
    ``s`` :data:`LOOSEN_DROP` x the preload lost (at least :data:`LOOSEN_FLOOR`), inside
    the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the preload's share of the friction, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Self-loosening of threaded fasteners under transverse slip (Junker 1969, New criteria
    for self-loosening of fasteners under vibration, SAE Trans. 78; DIN 65151, the
    Junker test; Yokoyama et al. 2012). The candidate is a trend, a saturating change, a
    step, a cycle, an accelerating part, a part that builds up and resets and a part that
    follows the friction's heating; the open forms warm up, wear in, step, cycle, rise
    and fall with debris, drop with grease shots, relax, oxidise, wear through, swell,
    grow a tribofilm, take in particles, expand, shear the oil, heat the magnets, charge
    the surfaces or creep a cage. Here the drift is counted in reversals: steps at each
    one, each a share of what is left, whatever the time or the distance between them.
    """
    if s <= 0.0:
        return _base_parts(kin)[0]
    t = np.asarray(kin.t, float)
    rev = _reversal_times(t, kin.v, LOOSEN_SPEED * max(kin.scales["v99"], 1e-12))
    lost = _loosened(t, rev, LOOSEN_STEP, LOOSEN_ROUND * max(float(t[-1] - t[0]), 1e-12))
    lev = np.clip(1.0 - float(s) * LOOSEN_DROP * lost, LOOSEN_FLOOR, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: ``polymer_gear``'s play at strength 1 when cold, as a share of the stroke [-]; the flank's
#: deflection at the Coulomb level when cold, at strength 1, as a share of the stroke [-];
#: the share of the play the warm teeth's swelling closes, and the share of the flanks'
#: stiffness their warming takes, at the record's warmest [-]; the teeth's thermal time
#: constant, x the record's length [-]
GEAR_PLAY, GEAR_COMPLIANCE, GEAR_CLOSE, GEAR_SOFT, GEAR_HEAT = 0.008, 0.003, 0.7, 0.5, 0.3


def _tooth_warming(t, F, v, tau):
    """The teeth's temperature rise [-] (1 at the record's warmest) along the times ``t``
    [s]: the first-order lag (``tau`` [s]) of the mesh's friction power |F v| [W] (the
    forces ``F`` [N] at the velocities ``v`` [m/s]), from cold."""
    from scipy.signal import lfilter
    p = np.abs(np.asarray(F, float) * np.asarray(v, float))
    e = math.exp(-float(t[1] - t[0]) / tau)
    th = lfilter([1.0 - e], [1.0, -e], p)              # from cold (zero initial state)
    return th / max(float(np.max(th)), 1e-300)


@njit(cache=True)
def _warm_mesh(h, xd, half, kflank, c1, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a contact of mass ``m`` [kg] driven by the drive positions
    ``xd`` [m] (step ``h`` [s]) across a play of half-width ``half`` [m] (at each step),
    the flank a spring ``kflank`` [N/m] (at each step) and a damper ``c1`` [N s/m],
    compressive only. Semi-implicit Euler of the mass
    (:func:`.truths._light_contact_step`). Starts at rest, centred in the play."""
    n = xd.size
    F = np.empty(n)
    v = 0.0
    z = 0.0
    x = xd[0]
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        e = xd[j] - x
        ed = vd - v
        k = kflank[j]
        hw = half[j]
        fc = 0.0
        if e > hw:
            f2 = k * (e - hw) + c1 * ed
            if f2 > 0.0:
                fc = f2
        elif e < -hw:
            f2 = k * (e + hw) + c1 * ed
            if f2 < 0.0:
                fc = f2
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha, shape)
        x = x + h * v
    return F


@on_fine_grid
def polymer_gear_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact joined by a plastic gear (POM, PA) with play, half-width ``s``^2
    :data:`GEAR_PLAY` / 2 x the stroke when cold, whose flank deflects by ``s``^2
    :data:`GEAR_COMPLIANCE` x the stroke at the Coulomb level when cold. The mesh's
    friction power (the base's |F v|) warms the teeth with the time constant
    :data:`GEAR_HEAT` x the record (:func:`_tooth_warming`); warm, they swell, closing up
    to :data:`GEAR_CLOSE` of the play, and soften, losing up to :data:`GEAR_SOFT` of the
    flanks' stiffness (:func:`_warm_mesh`). After each reversal the play is crossed and
    the force built through the flank (the teeth's compliance in series with the stiff
    flank of the other forms): a shorter crossing and a softer build-up as the record goes
    on. The contact is light (:func:`.truths._contact_constants`), with the
    base's LuGre friction; the measured force is its friction. At ``s`` = 0 the base
    itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m], v [m/s]) and its base law (a classic
        LuGre).
    s : float
        Amplitude factor [-]: the square root of the play and the flanks' compliance, /
        their values at strength 1 (as the open plays').

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Plastic gears' backlash allowance for thermal and moisture expansion and their
    temperature-dependent tooth stiffness (VDI 2736 Blatt 2, 2014, Thermoplastic gear
    wheels; Hooton 1969; Mao 2007, A new approach for polymer composite gear design,
    Wear 262). The candidate holds or frees the force across a play, with a bias, a
    spring or a drag across it; the open forms couple rigidly, compliantly, by impacts,
    springs, oil in the play, an idler, a bias, chains, magnets, a preload, a hardening
    gear, a slipping rope, a rubber spider, an oil column, a cable in a sheath, a clutch
    or a mesh of varying stiffness, with a play varying with the position or the travel.
    Here the play and the flank's stiffness follow the coupling's own heating: both
    change over the record with the power the motion has put through the mesh.
    """
    p = _lugre_params(kin, "backlash (polymer_gear)")
    if s <= 0.0:
        return _base_parts(kin)[0]
    m, kh, _ = _contact_constants(kin, p)
    stroke = float(np.ptp(kin.x))
    Fc = float(p.Fc)
    half0 = 0.5 * float(s) ** 2 * GEAR_PLAY * stroke
    # the teeth's compliance (cold) in series with the other forms' stiff flank
    comp = float(s) ** 2 * GEAR_COMPLIANCE * stroke / Fc
    k1 = 1.0 / (1.0 / kh + comp)
    c1 = 2.0 * 0.5 * math.sqrt(k1 * m)
    t = np.asarray(kin.t, float)
    F0 = _base_parts(kin)[0]
    th = _tooth_warming(t, F0, kin.v, GEAR_HEAT * max(float(t[-1] - t[0]), 1e-12))
    h, xd, n_sub = _substeps(kin, max(math.sqrt((k1 + float(p.sigma0)) / m),
                                      (float(p.sigma1) + float(p.sigma2) + c1) / m))
    th_sub = np.interp(t[0] + h * np.arange(xd.size), t, th)
    half = half0 * (1.0 - GEAR_CLOSE * th_sub)
    kflank = 1.0 / (1.0 / kh + comp / (1.0 - GEAR_SOFT * th_sub))
    F = _warm_mesh(h, xd, half, kflank, c1, m, float(p.sigma0), float(p.sigma1),
                   float(p.sigma2), Fc, float(p.Fs), float(p.vs), float(p.alpha),
                   SHAPES[p.shape])
    return F[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: the junctions' travel to slip at strength 1, beyond the base bristle's path, as a share of
#: the stroke / 3 [-]; their share of the friction at strength 1 [-]; the junctions in the
#: chain [-]; the coupling between neighbours, x a junction's own stiffness [-]; the force a
#: junction keeps after it slips, x its strength (the static-to-dynamic drop) [-]
AVAL_SLIP, AVAL_SHARE, AVAL_BLOCKS, AVAL_COUPLING, AVAL_DROP = 0.1, 0.7, 24, 3.0, 0.8


def _strengths(n):
    """The chain's junction strengths [-]: 0.6 to 1, spread along the chain by the golden
    ratio's sequence (no two neighbours alike, the same every time)."""
    g = (math.sqrt(5.0) - 1.0) / 2.0
    return 0.6 + 0.4 * np.mod(np.arange(n) * g, 1.0)


@njit(cache=True)
def _avalanche_chain(x, caps, kp, kc, drop):
    """The chain's force f [-] (over its summed strengths x (1 + ``drop``) / 2, about 1
    while it slides) along the positions ``x`` [m]: junction i sits at u_i [m], pulled by
    the moving body with ``kp`` (x - u_i) and by its neighbours with ``kc`` (u_(i-1) +
    u_(i+1) - 2 u_i) [-]; where that force passes its strength ``caps``[i] it slips until
    ``drop`` x its strength is left, which loads its neighbours; repeated until every
    junction holds (an avalanche). Starts unloaded."""
    n = x.size
    m = caps.size
    u = np.full(m, x[0])
    out = np.empty(n)
    out[0] = 0.0
    norm = np.sum(caps) * 0.5 * (1.0 + drop)
    for k in range(1, n):
        xk = x[k]
        for _ in range(50 * m):
            moved = False
            for i in range(m):
                f = kp * (xk - u[i])
                nb = 0.0
                if i > 0:
                    f += kc * (u[i - 1] - u[i])
                    nb += kc
                if i < m - 1:
                    f += kc * (u[i + 1] - u[i])
                    nb += kc
                if abs(f) > caps[i]:
                    target = drop * caps[i] if f > 0.0 else -drop * caps[i]
                    u[i] += (f - target) / (kp + nb)
                    moved = True
            if not moved:
                break
        tot = 0.0
        for i in range(m):
            tot += kp * (xk - u[i])
        out[k] = tot / norm
    return out


@on_fine_grid
def slip_avalanches_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The presliding junctions beside the bristle (:data:`AVAL_BLOCKS` of them, strengths
    0.6 to 1: :func:`_strengths`) are held to the moving body each by its own stiffness
    and to its neighbours by the elastic body between them (:data:`AVAL_COUPLING` x as
    stiff): a junction slips where its force passes its strength, keeps
    :data:`AVAL_DROP` of it and passes the rest on to its neighbours, which may slip in
    turn (:func:`_avalanche_chain`). The largest junction's travel to slip on its own is
    the base bristle's path Fs / sigma0 plus ``s`` :data:`AVAL_SLIP` x the stroke / 3; a
    share w = :data:`AVAL_SHARE` min(``s``, 1) of the friction is the chain's (its
    sliding force the Stribeck level, the viscous term the base's): F = (1 - w) F_lugre +
    w (g(v) f + sigma2 v). At ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the chain's share (up to ``s`` = 1) and its travel to slip
        (as the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The spring-block (Burridge and Knopoff 1967, Model and theoretical seismicity, Bull.
    Seismol. Soc. Am. 57) and Olami-Feder-Christensen (1992, Phys. Rev. Lett. 68) models;
    precursors of sliding as detachment fronts (Rubinstein, Cohen and Fineberg 2007,
    Phys. Rev. Lett. 98; Braun, Barel and Urbakh 2009). Maxwell-slip (the candidate) and
    the open forms use equal, geometric or power-law strengths, path laws, an elastic
    range, rate-dependent creep, Mindlin's 3/2 law, multistable tips, bonds, a fabric, a
    back-stress, a climb out of a nest, capillary bridges, a hardening yield, peeling,
    load-dependent microslip or growing junctions, each element on its own. Here the
    elements are coupled: one slip sets off others, so the presliding curve climbs in
    bursts and its steps, and the sliding force's flicker, come in avalanches.
    """
    p = _lugre_params(kin, "gms (slip_avalanches)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, AVAL_SLIP)
    w = AVAL_SHARE * min(float(s), 1.0)
    v = np.asarray(kin.v, float)
    caps = _strengths(AVAL_BLOCKS)
    kp = 1.0 / (e0 + extra)          # the strongest junction slips alone after e0 + extra
    f = _avalanche_chain(np.ascontiguousarray(kin.x, dtype=float), caps, kp,
                         AVAL_COUPLING * kp, AVAL_DROP)
    return (1.0 - w) * F + w * (kin.base.g(v) * f + float(p.sigma2) * v)
