"""The thirty-second seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-12-01 (session 36) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 37 (2026-12-01) on the code of 1264221 (the
diagnosis code of b5696a1): 176 cases, 0 skipped, 539 s wall on 2 workers (alone).
Top-1 74.4 % (131; 75.7 % of the 169 detectable; of the 7 undetectable, 6 are delays below
their practical size (3 of them named delay, 2 unexplained, 1 none), 1 an inertia case
(none)); mean |shrink error| 0.188 (0.189 over the detectable, 0.152 over the right ones);
wrong names on 17 (9.7 %): acceleration -> position 4, inertia -> acceleration 3,
drift -> load 3, asymmetry -> stribeck_shape 2, delay -> gms 1, stribeck_shape -> inertia 1,
stribeck_shape -> acceleration 1, gms -> delay 1, load -> delay 1. By form:
position/draining_film 16/16, load/sinking_wiper 19/20 (delay 1), drift/jr_clamp 17/20
(load 3), delay/pulsation_comb 16/20 (unexplained 2, gms 1, none 1),
asymmetry/coolant_stream 15/20 (unexplained 2, stribeck_shape 2, none 1),
inertia/fluid_inerter 14/20 (acceleration 3, none 2, unexplained 1), gms/leaf_pack 8/12
(unexplained 2, none 1, delay 1), acceleration/nut_liftoff 12/20 (unexplained 4,
position 4), stribeck_shape/governor_shoes 8/16 (none 5, inertia 1, acceleration 1,
unexplained 1), backlash/dilatant_gap 6/12 (unexplained 6). By plant: XML-350 87.5 %,
valve 80.0 %, isolator 71.4 %, forging press 67.9 %, damping rig 62.5 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen31` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen31`,
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
acceleration       ``nut_liftoff``: the axis is driven by a ball screw with a preloaded
                   double nut; the carriage's inertial thrust loads one half of the nut
                   and unloads the other (Hertz's 3/2 law of the balls' contacts), and
                   past 2^(3/2) times the preload the unloaded half lifts off: the
                   balls' summed contact load, and with it the nut's friction, rises
                   with the thrust, slowly at first and in proportion once the half
                   lifts off
load               ``sinking_wiper``: the carriage's ball rows deflect under the load
                   (Hertz's 2/3 power) and the carriage sinks on them; its lower wiper
                   seal, fixed to the carriage, meets the rail beyond a free clearance
                   and is pressed harder as it sinks: a seal drag that sets in past a
                   load and grows as the sinkage does
asymmetry          ``coolant_stream``: the carriage runs in a stream of coolant flushed
                   along the axis towards -x (chip flushing); its drag is quadratic in
                   the speed relative to the stream: it pushes the carriage at rest and
                   resists more against the stream than with it
stribeck_shape     ``governor_shoes``: a drum geared to the carriage carries spring-
                   pressed friction shoes on centrifugal flyweights; as the drum speeds
                   up the flyweights pull the shoes off (a centrifugally released
                   brake): an added drag that falls as the square of the speed and is
                   gone above the lift-off speed
position           ``draining_film``: the axis is inclined; the oil film on its way
                   drains down the slope (Jeffreys' draining film), thicker downhill as
                   the root of the distance from the way's top, and the asperities'
                   share of the load falls with the film: levels that fall along the
                   stroke
inertia            ``fluid_inerter``: the carriage drives the piston of a fluid inerter
                   fixed to the frame (oil pushed round a helical channel): a force of
                   the channel's oil's amplified mass times the acceleration, with the
                   channel's viscous and its entry and exit losses beside it
delay              ``pulsation_comb``: the force channel carries a hydraulic unit's
                   pulsation of known period, cancelled by averaging each reading with
                   the one half a period earlier (a two-tap comb filter): every change
                   of the force reaches the record in two halves, the second late by
                   that half period
drift              ``jr_clamp``: the carriage's pads are pressed on the way by an
                   electrostatic (Johnsen-Rahbek) clamp switched on at the record's
                   start; charge migrates through the dielectric's bulk, the gap's
                   voltage rises with its RC time and the attraction with its square:
                   levels that rise slowly, then faster, then level off
backlash           ``dilatant_gap``: the play between drive and contact is packed with a
                   shear-thickening fluid (a dense suspension): across the play the
                   fluid's drag, quadratic in the shear rate until the suspension jams,
                   drags the contact when the drive reverses fast and hardly when
                   slowly
gms                ``leaf_pack``: part of the friction is carried by a shoe on a multi-leaf
                   spring whose leaves rub on each other; the pack's force approaches
                   the envelopes of its stiffness plus or minus the interleaf friction
                   exponentially (Fancher's leaf-spring model) until the shoe slides; at
                   ``s`` = 0 the base
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``governor_shoes``
needs a Stribeck curve (not the isolator's mre_lugre), ``draining_film`` a record that
revisits its positions (not the press), ``sinking_wiper`` a load that changes,
``dilatant_gap`` and ``leaf_pack`` a classic LuGre base (valve, damping rig, XML-350);
each raises a ``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.shapes import SHAPES

from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _level,
                     _light_contact_step, _lugre_params, _presliding_path, _smooth_max0,
                     _substeps, has_stribeck_curve, level_inside, lugre_with_curve,
                     on_fine_grid)

__all__ = ["FORMS", "nut_liftoff_truth", "sinking_wiper_truth", "coolant_stream_truth",
           "governor_shoes_truth", "draining_film_truth", "fluid_inerter_truth",
           "pulsation_comb_truth", "jr_clamp_truth", "dilatant_gap_truth",
           "leaf_pack_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "nut_liftoff", "load": "sinking_wiper",
         "asymmetry": "coolant_stream", "stribeck_shape": "governor_shoes",
         "position": "draining_film", "inertia": "fluid_inerter",
         "delay": "pulsation_comb", "drift": "jr_clamp",
         "backlash": "dilatant_gap", "gms": "leaf_pack"}


# -- acceleration ----------------------------------------------------------------------------
#: ``nut_liftoff``'s rise of the levels per unit of the balls' extra contact load over its
#: 99th percentile along the record, at strength 1 [-]; the quantile of the record's |a| at
#: which the unloaded half lifts off [-]; the drive's peak thrust (its current limit), x
#: the inertial force at the top acceleration [-]
NUT_RISE, NUT_LIFT, NUT_PEAK = 0.5, 0.8, 1.5
#: the thrust at which the unloaded half of the nut lifts off, x the preload: 2^(3/2) [-]
NUT_LIFTOFF = 2.0 ** 1.5


def _nut_loads(u, n=2001):
    """The two halves' summed contact load [-] (over the preload) at the axial thrusts ``u``
    [-] (over the preload): with Hertz's law each half carries (1 +- d)^(3/2) at the
    axial deflection d (over the preload's), their difference the thrust; once |u|
    reaches :data:`NUT_LIFTOFF` (d = 1) the unloaded half carries nothing and the loaded
    one |u|. 2 at no thrust."""
    d = np.linspace(0.0, 1.0, n)
    ut = (1.0 + d) ** 1.5 - (1.0 - d) ** 1.5
    st = (1.0 + d) ** 1.5 + (1.0 - d) ** 1.5
    au = np.abs(np.asarray(u, float))
    return np.where(au < NUT_LIFTOFF, np.interp(au, ut, st), au)


@on_fine_grid
def nut_liftoff_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The axis is driven by a ball screw whose nut is a preloaded double nut (two halves
    pressed apart by a spacer, as on machine tools' feed drives). The carriage's
    inertial force (m a; the friction's share is small next to it at hard accelerations)
    is the nut's axial thrust: it loads one half and unloads the other, each half's balls
    following Hertz's law, load ~ deflection^(3/2), so the summed contact load grows
    with the thrust, slowly at first; at :data:`NUT_LIFTOFF` x the preload the unloaded
    half lifts off and the loaded one carries the whole thrust (:func:`_nut_loads`). The
    preload is set so the half lifts off at the record's :data:`NUT_LIFT` quantile of
    |a|, and the thrust never exceeds the drive's peak force, :data:`NUT_PEAK` x the
    inertial force at the top acceleration (its current limit). The Coulomb and Stribeck
    levels are the base's times 1 + ``s`` :data:`NUT_RISE` x the summed load's excess
    over the preloaded nut's, over its 99th percentile along the record, inside the
    bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the nut's share of the friction per unit of contact load, /
        its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Preloaded double nuts of ball screws, the halves' load under an axial force and the
    lift-off at 2^(3/2) x the preload (Harris and Kotzalas 2007, Rolling Bearing Analysis,
    ch. on preloading; THK and NSK ball screw technical notes on the preload's lift-off
    load; Wei and Lin 2003, Kinematic analysis of the ball screw mechanism considering
    variable contact angles and elastic deformations, J. Mech. Des. 125) and the
    load-dependent friction torque of preloaded nuts (Olaru, Puiu, Balan and Puiu 2005, A
    new model to estimate friction torque in a ball screw system, Product Engineering).
    The candidate raises the levels with |a|, lagged, tilts them with a and adds a force
    odd in a; the open forms lag, age, heat, skid, load, press, attract, squeeze, transfer
    weight, slosh, dilate, wedge, spring a gib, soften rubber, swing arms, unload by the
    jerk, tilt pads, push ball trains, ripple the current, slide rack flanks, set a shoe,
    shut a damper's bypass, creep a belt, rack a gantry, tighten a band, surge a feed line,
    load a traction drive, heat a winding, unload a counterweight's rope, pump oil or
    slacken a belt's strand. Here the thrust shifts a preloaded nut's load between its
    halves until one lifts off.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    u = np.clip(np.asarray(kin.a, float) / a99, -NUT_PEAK, NUT_PEAK)
    pre = max(float(np.quantile(np.abs(u), NUT_LIFT)), 1e-9) / NUT_LIFTOFF
    e = _nut_loads(u / pre) - 2.0
    e = e / max(float(np.percentile(e, 99)), 1e-12)
    lev = 1.0 + float(s) * NUT_RISE * e
    return level_inside(kin, lev, np.ones_like(lev))


# -- load ------------------------------------------------------------------------------------
#: ``sinking_wiper``'s largest change of the levels with the wiper's drag, at strength 1
#: [-]; the lip's free clearance, x the carriage's sinkage at the mean load [-]; its
#: rounding (the lip's compliance), the same scale [-]
WIPER_RISE, WIPER_FREE, WIPER_ROUND = 0.5, 0.8, 0.03


def _lip_press(w, free, rnd):
    """The lower wiper lip's interference [-] (over the carriage's sinkage at the mean
    load) at the loads ``w`` [-] (over the mean): the ball rows' Hertzian sinkage
    |w|^(2/3) less the lip's free clearance ``free``, nothing before the lip touches,
    rounded over ``rnd``."""
    return _smooth_max0(np.abs(np.asarray(w, float)) ** (2.0 / 3.0) - free, rnd)


@on_fine_grid
def sinking_wiper_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage runs on rows of balls (a profile rail guide) that deflect under its
    normal load by Hertz's law, the sinkage growing as the load^(2/3). Its lower wiper
    seal (an end seal's or a bottom seal's lip, fixed to the carriage) stands off the rail
    by a free clearance of :data:`WIPER_FREE` x the sinkage at the mean load; as the
    carriage sinks the lip meets the rail and is pressed on it in proportion to its
    interference (:func:`_lip_press`), and its drag follows. The Coulomb and Stribeck
    levels are the base's times 1 + ``s`` :data:`WIPER_RISE` x the interference's
    departure from its mean along the record, over its largest (the base's level holds
    the wiper's mean drag), inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (load [N]) and its base law.
    s : float
        Amplitude factor [-]: the lip's friction per unit of interference, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The deflection of ball rows under load (Hertz 1882, Ueber die Beruehrung fester
    elastischer Koerper, J. reine angew. Math. 92; Harris and Kotzalas 2007, Rolling
    Bearing Analysis, ch. on contact deformation) and the friction of linear guides'
    seals and wipers (the guide makers' technical documentation, THK's and Bosch
    Rexroth's, on the seals' resistance; Mueller and Nau 1998, Fluid Sealing Technology,
    ch. on wipers and lip seals). The
    candidate makes the levels affine in the load, with a memory over the travel; the
    open forms scale the friction with a Hertz contact's area, a seal's, a film's, a
    junction's, a pivot's, an adhesive contact's or a pin's arc, break, squeeze or desorb
    films, plough, creep, vibrate, overload or feed a constant flow to a pad, heal scuffs,
    relieve a preload, roll on a lossy track, slip differentially, spin balls, press a
    disc spring, skid lightly loaded rollers, bed a rail, heat a liner by PV, shear a soft
    film under pressure, pass the load through a clamp's seal, load crowned rollers' ends
    or sink wheels into a compacting track. Here the load lowers the carriage onto a
    wiper that it carries itself.
    """
    L = np.abs(np.asarray(kin.load, float))
    Lm = float(np.mean(L)) or 1.0
    if not np.ptp(L) > 1e-9 * Lm:
        raise ValueError(f"load (sinking_wiper): the {kin.plant} record's load does not "
                         f"change")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    d = _lip_press(L / Lm, WIPER_FREE, WIPER_ROUND)
    e = d - float(np.mean(d))
    e = e / max(float(np.max(np.abs(e))), 1e-12)
    lev = np.maximum(1.0 + float(s) * WIPER_RISE * e, 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``coolant_stream``'s drag at the top speed in still coolant, x the friction level, at
#: strength 1 [-]; the stream's speed along -x, x the top speed [-]
STREAM_FORCE, STREAM_SPEED = 0.5, 0.4


def _stream_drag(u, w):
    """The stream's drag [-] (over the still-coolant drag at the top speed) at the speeds
    ``u`` [-] (over the top speed) in a stream moving at ``w`` [-] (the same scale,
    signed): quadratic in the speed relative to the stream, (u - w) |u - w|."""
    r = np.asarray(u, float) - float(w)
    return r * np.abs(r)


@on_fine_grid
def coolant_stream_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage (its saddle and a bulky fixture) runs in a stream of coolant flushed
    along the axis, as the chip flushing of machine tools' beds: the stream flows towards
    -x at :data:`STREAM_SPEED` x the top speed and drags the carriage quadratically in its
    speed relative to the stream (:func:`_stream_drag`, a bluff body's drag at high
    Reynolds numbers). At rest the stream pushes the carriage towards -x; moving with it
    the carriage meets less drag, against it more. The truth adds ``s``
    :data:`STREAM_FORCE` x the friction level x that drag (1 at the top speed in still
    coolant) to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the fixture's frontal area x the coolant's density, / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The drag of bluff bodies in a flow, quadratic in the relative speed (Hoerner 1965,
    Fluid-Dynamic Drag, ch. on the drag of bodies in a stream; White 2011, Fluid
    Mechanics, ch. on flow past immersed bodies) and machine tools' coolant and chip
    flushing (Brinksmeier, Heinzel and Wittmann 1999, Friction, cooling and lubrication
    in grinding, CIRP Annals 48). The candidate gives each direction its levels and an
    offset; the open forms twin the levels, the curves or the viscous term, bend a curve,
    roll a lip, load a thrust bearing, film a rod seal, texture a ratchet, return a
    spring, tilt a pad, strut a sprag, throttle a meter-out, differ a cylinder's areas,
    groove chevrons, buckle a helix, scrape chips, commutate, idle a belt, free a roller,
    wick a felt, run a belt, lean a brush, band a seal, counterbalance a valve, vibrate
    elliptically, diode a flow, pitch pads, skew rollers, lift through a screw, turn the
    frame, angle a pull, adhere by wedges, charge through a diode or drag a cup. Here the
    medium itself moves along the axis.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    d = _stream_drag(np.asarray(kin.v, float) / v99, -STREAM_SPEED)
    return F + float(s) * STREAM_FORCE * _level(kin) * d


# -- stribeck_shape --------------------------------------------------------------------------
#: ``governor_shoes``' drag at rest, x the Coulomb level, at strength 1 [-]; the lift-off
#: speed, x the top speed [-]; the rounding of the shoes' landing (their lining's
#: compliance), of the squared speed ratio [-]
SHOE_DRAG, SHOE_LIFT, SHOE_ROUND = 0.5, 0.4, 0.05


def _shoe_press(u, rnd):
    """The shoes' pressing force [-] (over the springs' at rest) at the speeds ``u`` [-]
    (over the lift-off speed): the springs' force less the flyweights' centrifugal pull,
    which grows as the drum's speed squared, 1 - u^2, nothing once they lift off, rounded
    over ``rnd``."""
    u = np.asarray(u, float)
    return _smooth_max0(1.0 - u * u, rnd) / _smooth_max0(1.0, rnd)


@on_fine_grid
def governor_shoes_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A drum geared to the carriage (through a pinion on its rack or a belt) carries
    friction shoes pressed on a fixed ring by springs and mounted on centrifugal
    flyweights, as a centrifugally released holding brake or a lift-off sprag: as the
    drum speeds up the flyweights pull the shoes off against their springs, the pressing
    force falls as the square of the speed and is gone at the lift-off speed
    (:data:`SHOE_LIFT` x the top speed; :func:`_shoe_press`). The shoes' drag, ``s``
    :data:`SHOE_DRAG` x the Coulomb level at rest, is added to the base's Stribeck curve,
    inside the bristle dynamics.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (with a Stribeck curve).
    s : float
        Amplitude factor [-]: the springs' force, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Centrifugal clutches and brakes, the shoes' force as the centrifugal pull less the
    springs' (Shigley, Mischke and Budynas 2004, Mechanical Engineering Design, ch. on
    clutches and brakes: centrifugal clutches; Juvinall and Marshek 2012, Fundamentals of
    Machine Component Design, ch. on brakes and clutches) and centrifugal lift-off of
    freewheels' sprags (Stoelzle and Hart 1961, Freilaufkupplungen, Springer). The
    candidate's curve is Gaussian, Lorentzian or an exponential tail; the open forms add
    tails, rationals, films that lift, spikes, bimodal roughness, logs, Eyring,
    starvation, rubber hysteresis, resonances, dither, melting, grains, readsorption,
    thermoviscous, turbulent and thixotropic films, churning, core losses, breathing
    bellows, eddy brakes, shear thinning, flying pads, wiping menisci, journals, wall
    slip, a closing clearance, a dwell's squeeze, a pocket's suction, condensing menisci,
    flash heating, a peeled adhesion or a measuring wheel's creep. Here a body's
    centrifugal pull unloads a rubbing shoe as the speed rises.
    """
    law = kin.base
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (governor_shoes): the mre_lugre base has no "
                         "Stribeck curve")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    vl = SHOE_LIFT * max(kin.scales["v99"], 1e-12)
    add = float(s) * SHOE_DRAG * _level(kin)
    return lugre_with_curve(kin, lambda vv: law.g(vv) + add * _shoe_press(vv / vl,
                                                                           SHOE_ROUND))


# -- position --------------------------------------------------------------------------------
#: ``draining_film``'s largest change of the levels along the record, at strength 1 [-];
#: the film parameter (film over roughness) at the stroke's low end [-]; the oiled way's
#: top (where the oil is fed) above the stroke's top, x the stroke [-]
DRAIN_RISE, DRAIN_FILM, DRAIN_TOP = 0.5, 2.5, 0.25


def _asperity_share(xr, film, top):
    """The asperities' share of the load [-] at the positions ``xr`` [-] (over the visited
    stroke, 0 at its top): the draining film thickens downhill as the root of the distance
    from the way's top, ``top`` above the stroke's (Jeffreys), to the film parameter
    ``film`` at the stroke's low end, and the asperities carry exp(-film parameter) of
    the load."""
    xr = np.clip(np.asarray(xr, float), 0.0, 1.0)
    return np.exp(-float(film) * np.sqrt((xr + top) / (1.0 + top)))


@on_fine_grid
def draining_film_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The axis is inclined (an inclined bed, a column's vertical way) and its way is oiled
    from above; between lubrications the oil drains down the slope as a viscous film
    under gravity, whose thickness, Jeffreys' draining film, grows as the root of the
    distance from the way's top (where the oil is fed, :data:`DRAIN_TOP` x the stroke
    above the stroke's top), to :data:`DRAIN_FILM` x the roughness at the stroke's low
    end. Where the film is thin the asperities carry more of the load
    (:func:`_asperity_share`): the Coulomb and Stribeck levels are the base's times 1 +
    ``s`` :data:`DRAIN_RISE` x that share's departure from its mean along the record, over
    its largest, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the boundary friction's share in the friction, / its value
        at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The drainage of a viscous film down an inclined wall (Jeffreys 1930, The draining of a
    vertical plate, Proc. Camb. Phil. Soc. 26; Bird, Stewart and Lightfoot 2002, Transport
    Phenomena, ch. on falling films) and the load sharing of mixed lubrication by the film
    parameter (Johnson, Greenwood and Poon 1972, A simple theory of asperity contact in
    elastohydrodynamic lubrication, Wear 19; Hamrock, Schmid and Jacobson 2004,
    Fundamentals of Machine Elements, ch. on the film parameter). The candidate scales the
    friction along the stroke and adds a force of the position; the open forms put
    defects, waviness, wear, runout, bends, films, cogging, tapers, pockets, cushions,
    covers, springs, holes, plungers, sags, festoons, curves, chains, cams, heat, dents,
    joints, misalignment, flow forces, cranks, overhangs, a track's end, a reel, a way's
    flatness, conductive strips, a guide's ball passage, a steel insert, a screw's lead
    error or a rack's mesh on the stroke. Here gravity spreads the oil unevenly along an
    inclined way.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (draining_film): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    span = max(sc["x_hi"] - sc["x_lo"], 1e-12)
    xr = (np.asarray(kin.x, float) - sc["x_lo"]) / span
    b = _asperity_share(xr, DRAIN_FILM, DRAIN_TOP)
    p = b - float(np.mean(b))
    p = p / max(float(np.max(np.abs(p))), 1e-12)
    lev = np.maximum(1.0 + float(s) * DRAIN_RISE * p, 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- inertia ---------------------------------------------------------------------------------
#: ``fluid_inerter``'s inertance at strength 1, x the friction level / a99 [kg per N
#: s^2/m]; the channel's viscous loss at the top speed and its entry and exit losses at
#: the top speed, each x the inertance's force at the top acceleration [-]
INERTER_MASS, INERTER_VISCOUS, INERTER_ENDS = 0.5, 0.15, 0.1


def _inerter_force(a, v, b, c, d):
    """A fluid inerter's force [N] at the accelerations ``a`` [m/s^2] and speeds ``v``
    [m/s]: its inertance ``b`` [kg] (the channel's oil's mass x the area ratio squared)
    times the acceleration, the channel's viscous loss ``c`` [N s/m] times the speed and
    its entry and exit losses ``d`` [N s^2/m^2] times v |v|."""
    a = np.asarray(a, float)
    v = np.asarray(v, float)
    return b * a + c * v + d * v * np.abs(v)


@on_fine_grid
def fluid_inerter_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage drives the piston of a fluid inerter whose cylinder is fixed to the
    frame (a vibration suppressor: the oil the piston displaces flows round a long helical
    channel outside the cylinder). The channel's oil, accelerated by the area ratio
    squared, acts as a mass (the inertance, ``s`` :data:`INERTER_MASS` x the friction
    level / a99) that the inverse dynamics misses; the channel's Poiseuille flow adds a
    viscous loss, and its entry and exit a loss quadratic in the speed (at the top speed
    and acceleration :data:`INERTER_VISCOUS` and :data:`INERTER_ENDS` x the inertance's
    force; :func:`_inerter_force`). The truth adds that force to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the inerter's bore (its inertance and losses), / its value
        at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The inerter (Smith 2002, Synthesis of mechanical networks: the inerter, IEEE Trans.
    Autom. Control 47) and the fluid inerter with a helical channel and its parasitic
    losses (Swift, Smith, Glover, Papageorgiou, Gartner and Houghton 2013, Design and
    modelling of a fluid inerter, Int. J. Control 86; Liu, Jiang, Titurus and Harrison
    2018, Model identification methodology for fluid-based inerters, Mech. Syst. Signal
    Process. 106). The candidate misses a constant mass; the open forms filter it, reflect
    it through gearing, a chain, a pinion or a screw, hang it on a spring, a cable, a
    fluid, a clutch, a coupling, a flyweight, a friction-damped, quasi-zero-stiffness,
    hose's, elastomer or magnetic mount, surge a spring, add a fluid's mass, pick, drop,
    empty, slide, rattle, telescope, roll or rock it, recoil a frame, saturate a motor,
    lead a feedforward, pitch a scale, radiate waves, swing it on a rod, slide it in a
    dish or swing a liquid in a tube. Here a mass that the frame holds, amplified by a
    fluid's flow, comes with the flow's losses.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    v99 = max(kin.scales["v99"], 1e-12)
    b = float(s) * INERTER_MASS * _level(kin) / a99
    c = INERTER_VISCOUS * b * a99 / v99
    d = INERTER_ENDS * b * a99 / (v99 * v99)
    return F + _inerter_force(kin.a, kin.v, b, c, d)


# -- delay -----------------------------------------------------------------------------------
#: ``pulsation_comb``'s spacing of the two taps (the pulsation's half period) at strength 1
#: [data samples]
COMB_SAMPLES = 4.0


def _comb(t, u, lag):
    """The two-tap comb (u(t) + u(t - ``lag``)) / 2 of ``u`` [N] at the times ``t`` [s]
    (linear between them; before the record's start its first value), ``lag`` [s]."""
    t = np.asarray(t, float)
    u = np.asarray(u, float)
    late = np.interp(t - float(lag), t, u, left=u[0])
    return 0.5 * (u + late)


@on_fine_grid
def pulsation_comb_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force sensor sits on an axis whose hydraulic unit (a piston pump) puts a
    pulsation of known period on its signal; the acquisition cancels it by averaging each
    reading with the one half a pulsation period earlier (``s`` :data:`COMB_SAMPLES` data
    samples; a two-tap comb filter, which takes out the pulsation's fundamental and its
    odd harmonics; :func:`_comb`). The pulsation is cancelled and left out here; the
    force reaches the record in two halves, the second late by the half period. The
    motion channels are on time.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the pulsation's half period, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Comb filters for periodic disturbances (Smith 2007, Introduction to Digital Filters,
    ch. on comb filters; Oppenheim and Schafer 2010, Discrete-Time Signal Processing, ch.
    on linear-phase FIR systems) and pump pulsation in hydraulic systems (Edge and Johnston
    1990, The secondary source method for the measurement of pump pressure ripple
    characteristics, Proc. IMechE A 204). The candidate shifts the force in time or lags
    it through a first-order filter; the open forms delay, filter, average, stamp,
    decimate, hold, skew, jitter, limit the slew, pipe, take medians, report on a dead
    band, sample positions, run a belt, aerate, drop telegrams, leak, creep, notch, track,
    snub, time a waveguide's pulse, diffuse eddy currents, count a resonator, sweep a
    grating, restore a force by a servo, interleave converters, balance a pneumatic cell,
    count out a dual slope, adapt a filter's time constant, round in integer arithmetic,
    fit a polynomial or observe a disturbance. Here two readings far apart are averaged:
    the force arrives in two steps.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    return _comb(kin.t, F, float(s) * COMB_SAMPLES * kin.sample_dt)


# -- drift -----------------------------------------------------------------------------------
#: ``jr_clamp``'s rise of the levels with the clamp's force at the record's end, at
#: strength 1 [-]; the dielectric's charging time (its RC), x the record's duration [-]
JR_RISE, JR_TIME = 0.4, 0.4


def _clamp_force(tr, tau):
    """The clamp's attraction [-] (over its full value) at the times ``tr`` [-] (over the
    record's) from switching on: the interface's voltage rises as 1 - exp(-tr / ``tau``)
    as charge migrates through the dielectric's bulk, the attraction as its square."""
    tr = np.maximum(np.asarray(tr, float), 0.0)
    return (1.0 - np.exp(-tr / float(tau))) ** 2


@on_fine_grid
def jr_clamp_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage's pads are pressed on the way by an electrostatic clamp of the
    Johnsen-Rahbek kind (a semiconducting dielectric between electrode and way, as on
    electrostatic chucks and electroadhesive holding pads), switched on as the record
    starts. Charge migrates through the dielectric's bulk to the interface, so the voltage
    across the thin gap there rises with the layer's RC time (:data:`JR_TIME` x the
    record's duration) and the attraction, growing as its square, rises slowly at first,
    then faster, then levels off (:func:`_clamp_force`). The Coulomb and Stribeck levels
    are the base's times 1 + ``s`` :data:`JR_RISE` x the attraction over its value at the
    record's end, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the clamp's voltage squared, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The Johnsen-Rahbek effect and the time dependence of its clamping force (Johnsen and
    Rahbek 1923, A physical phenomenon and its applications to telegraphy, telephony,
    etc., J. IEE 61; Watanabe, Kitabayashi and Nakayama 1993, Relationship between
    electrical resistivity and electrostatic force of alumina electrostatic chuck, Jpn.
    J. Appl. Phys. 32; Kanno and Usui 2003, Generation mechanism of residual clamping force
    in a bipolar electrostatic chuck, J. Vac. Sci. Technol. B 21). The candidate is a
    trend, a saturating change, a step, a cycle, a resetting change or the friction
    power's heat; the open forms warm up, wear in, change, heat, wear, follow the humidity,
    grind, relubricate, relax, oxidise, deplete, wear through, swell, build films, take in
    particles, expand, shear down, heat magnets, charge, creep, loosen, dewet, channel,
    drain, spall, evaporate, pump down, settle an additive, crystallise wax, bleed a
    grease's oil, cycle a thermostat, glaze a lining, form a tribolayer or grow frost.
    Here a clamp's charge migrates through a dielectric and its pull grows with it.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    tr = (t - t[0]) / max(float(t[-1] - t[0]), 1e-300)
    lev = 1.0 + float(s) * JR_RISE * _clamp_force(tr, JR_TIME) / float(
        _clamp_force(1.0, JR_TIME))
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: ``dilatant_gap``'s play at strength 1, as a share of the stroke (its full width) [-];
#: the fluid's drag at the play's crossing speed (the drive's from rest across the play at
#: the top acceleration), x the Coulomb level [-]; the drag's bound once the suspension
#: jams (the confining stress), x the Coulomb level [-]
DIL_CLEAR, DIL_DRAG, DIL_JAM = 0.005, 0.5, 1.0


@njit(cache=True)
def _dilatant_drag(ed, c, jam):
    """The shear-thickening fluid's drag [N] on the contact at the drive's speed relative
    to it ``ed`` [m/s]: quadratic in the shear rate, q = ``c`` ed |ed| (``c`` [N s^2/m^2]),
    bounded by the confining stress's ``jam`` [N] once the suspension jams, q / (1 + |q| /
    ``jam``)."""
    q = c * ed * abs(ed)
    return q / (1.0 + abs(q) / jam)


@njit(cache=True)
def _dilatant_contact(h, xd, half, c, jam, kh, ch, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a light contact of mass ``m`` [kg] driven by the drive positions
    ``xd`` [m] (steps ``h`` [s]) through a play of half-width ``half`` [m] closed at the
    flanks by a spring ``kh`` [N/m] and damper ``ch`` [N s/m] (compressive only); across
    the play the fluid's drag :func:`_dilatant_drag` acts; from rest, the drive in the
    play's middle. Semi-implicit Euler of the contact, its bristle exact."""
    nn = xd.size
    F = np.empty(nn)
    x = xd[0]
    v = 0.0
    z = 0.0
    for j in range(nn):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        e = xd[j] - x
        ed = vd - v
        fc = 0.0
        if e > half:
            f2 = kh * (e - half) + ch * ed
            if f2 > 0.0:
                fc = f2
        elif e < -half:
            f2 = kh * (e + half) + ch * ed
            if f2 < 0.0:
                fc = f2
        else:
            fc = _dilatant_drag(ed, c, jam)
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha,
                                         shape)
        x = x + h * v
    return F


@on_fine_grid
def dilatant_gap_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact are joined across a play of width ``s``^2 :data:`DIL_CLEAR` x the
    stroke packed with a shear-thickening fluid (a dense suspension of particles, as in
    shear-thickening dampers and lock-up couplings): across the play the fluid is
    sheared between the flanks and drags the contact with a force quadratic in the shear
    rate (:data:`DIL_DRAG` x the Coulomb level at the play's crossing speed, the drive's
    from rest across the play at the top acceleration), bounded by the confining stress
    once the suspension jams (:data:`DIL_JAM` x the Coulomb level;
    :func:`_dilatant_drag`). A slow reversal crosses the play with the contact standing
    still; a fast one drags it along before the flanks meet. The flanks then take the
    drive up (:func:`_dilatant_contact`). The contact is light (its inertial force at the
    top acceleration 1 % of the Coulomb level) with the base's LuGre friction.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the square root of the play's width (as the open plays'),
        / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Shear-thickening suspensions and their rheology (Barnes 1989, Shear-thickening
    ("dilatancy") in suspensions of nonaggregating solid particles dispersed in Newtonian
    liquids, J. Rheol. 33; Brown and Jaeger 2014, Shear thickening in concentrated
    suspensions, Rep. Prog. Phys. 77), dampers filled with them (Zhang, Li and Gong 2008,
    The rheology of shear thickening fluid (STF) and the dynamic performance of an
    STF-filled damper, Smart Mater. Struct. 17) and lost motion in
    mechanisms (Nordin and Gutman 2002, Controlling mechanical systems with backlash - a
    survey, Automatica 38). The candidate holds or frees the contact across a rigid play;
    the open forms take it up rigidly, compliantly, by impact, against a spring,
    eccentrically, through oil, worn, with a dragging idler, biased, slack, magnetic,
    preloaded, through a flexspline, a rope, a spider, a fluid link, a cable, a clutch, a
    varying mesh, a polymer gear, grease, a wedge, an overlapped spool, a side loaded pin,
    a toggle spring, graded pins, an adhesive flank, packed powder, a floating part
    between two plays, trapped air, a ball detent, magnets on the flanks or a play that
    warms shut. Here the play is filled with a fluid that stiffens with its shear rate.
    """
    p = _lugre_params(kin, "backlash (dilatant_gap)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    half = 0.5 * float(s) ** 2 * DIL_CLEAR * float(np.ptp(kin.x))
    vc2 = 4.0 * max(kin.scales["a99"], 1e-12) * max(half, 1e-300)
    c = DIL_DRAG * float(p.Fc) / vc2
    jam = DIL_JAM * float(p.Fc)
    m, kh, ch = _contact_constants(kin, p)
    rate = max(math.sqrt(kh / m), (float(p.sigma1) + float(p.sigma2) + ch
                                   + math.sqrt(c * jam)) / m)
    h, xd, n_sub = _substeps(kin, rate)
    Fr = _dilatant_contact(h, xd, half, c, jam, kh, ch, m,
                           float(p.sigma0), float(p.sigma1), float(p.sigma2), float(p.Fc),
                           float(p.Fs), float(p.vs), float(p.alpha), SHAPES[p.shape])
    return Fr[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: ``leaf_pack``'s share of the friction the shoe carries, at strength 1 (at most 0.95)
#: [-]; its slip path beyond the base bristle's Fs / sigma0, at strength 1, x the stroke /
#: 3 [-]; the interleaf friction's half-width of the envelopes, x the shoe's sliding force
#: [-]; the length over which the pack's force approaches an envelope, x the path [-]
LEAF_SHARE, LEAF_PATH, LEAF_FRICTION, LEAF_DECAY = 0.4, 0.1, 0.3, 0.15


@njit(cache=True)
def _leaf_pack(x, x_ref, eta, beta):
    """The leaf pack's force [-] (+-1 when the shoe slides) along the positions ``x`` [m],
    from rest: moving, it approaches the envelope u + ``eta`` sign(dx) (u the bending
    displacement over ``x_ref`` [m], ``eta`` the interleaf friction) exponentially over
    ``beta`` x ``x_ref`` of travel (Fancher's model); where it reaches +-1 the shoe slides
    and the pack's bending stays at that force."""
    n = x.size
    out = np.empty(n)
    f = 0.0
    anchor = x[0] if n > 0 else 0.0
    for k in range(n):
        if k > 0:
            dx = x[k] - x[k - 1]
            if dx != 0.0:
                sg = 1.0 if dx > 0.0 else -1.0
                target = (x[k] - anchor) / x_ref + eta * sg
                f = target + (f - target) * math.exp(-abs(dx) / (beta * x_ref))
                if f > 1.0:
                    f = 1.0
                    anchor = x[k] - (1.0 - eta * sg) * x_ref
                elif f < -1.0:
                    f = -1.0
                    anchor = x[k] - (-1.0 - eta * sg) * x_ref
        out[k] = f
    return out


@on_fine_grid
def leaf_pack_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Part of the contact's friction is carried by a shoe mounted on a multi-leaf spring
    (a laminated spring pack, as in leaf-sprung shoes and vehicle suspensions) whose leaves
    rub on each other. The shoe sticks on the way and the pack bends; its force is bounded
    by two envelopes, the pack's stiffness line plus and minus the interleaf friction
    (:data:`LEAF_FRICTION` x the shoe's sliding force), and approaches the one of the
    direction of bending exponentially (over :data:`LEAF_DECAY` x the path; Fancher's
    model), so a reversal first crosses the band between them; where the force reaches
    the shoe's sliding force the shoe slides (:func:`_leaf_pack`), over a path of the base
    bristle's Fs / sigma0 plus ``s`` :data:`LEAF_PATH` x the stroke / 3. The shoe carries
    the share w = ``s`` :data:`LEAF_SHARE` of the Coulomb level, w Fc f; the contact the
    rest, the base's LuGre with its curve less w Fc (its viscous term whole). At ``s`` = 0
    the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the shoe's share of the friction (up to ``s`` = 0.95 /
        :data:`LEAF_SHARE`) and its slip path (as the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Leaf springs' interleaf friction and its hysteresis (Fancher, Ervin, MacAdam and
    Winkler 1980, Measurement and representation of the mechanical properties of truck
    leaf springs, SAE 800905; Cebon 1986, Interaction between heavy vehicles and roads,
    SAE 861973, the leaf spring's envelopes and exponential decay; SAE HS-788 2008, Spring
    Design Manual, ch. on leaf springs). The candidate's presliding is a generalized
    Maxwell-slip (GMS) element set; the open forms are Maxwell-slip sets, Dahl,
    elasto-plastic, Bliman-Sorine, Bouc-Wen, Zener junctions, Mindlin contacts,
    rate-and-state, Tomlinson asperities, bond rupture, gouge, kinematic hardening,
    interlocking, capillary bridges, cyclic hardening, peeling, unloading microslip, a
    power-law joint, junction growth, avalanches, slip weakening, a microslip bar, contact
    renewal, grease's yield, a superelastic flexure, an Eyring film, a viscoplastic layer,
    a poroelastic one, a confined film that melts, a hysteresis brake, a fibre wiper or a
    band on a drum, each beside the contact, or a stiffening wire mesh in series with it.
    Here a spring's leaves rub on each other as it bends.
    """
    _lugre_params(kin, "gms (leaf_pack)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    law = kin.base
    w = min(float(s) * LEAF_SHARE, 0.95)
    wf = w * _level(kin)
    e0, extra = _presliding_path(kin, s, LEAF_PATH)
    f = _leaf_pack(np.asarray(kin.x, float), e0 + extra, LEAF_FRICTION, LEAF_DECAY)
    rest = lugre_with_curve(kin, lambda vv: law.g(vv) - wf)
    return rest + wf * f
