"""The thirty-third seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-12-01 (session 38) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 38 (2026-12-01) on the code of c6080f7:
176 cases, 0 skipped, 605 s wall on 2 workers (alone).
Top-1 59.7 % (105; 61.9 % of the 168 detectable; of the 8 undetectable, 6 are below their
practical size by the truth's own imprint (valve stribeck_shape 3, isolator inertia 2, valve
asymmetry 1, all named none), 2 isolator delays shifted by less than a sample (one named
delay, the other none)); mean |shrink error| 0.223 (0.231 over the detectable, 0.150 over the right
ones); wrong names on 35 (19.9 %): asymmetry -> stribeck_shape 7, inertia -> acceleration 4,
backlash -> gms 4, stribeck_shape -> acceleration 4, acceleration -> position 4,
delay -> acceleration 3, load -> delay 2, delay -> gms 2, delay -> inertia 1,
backlash -> delay 1, gms -> delay 1, acceleration -> asymmetry 1, acceleration -> load 1.
By form: position/hardened_zones 16/16, load/magnet_preload 18/20 (delay 2),
drift/solenoid_coil 17/20 (unexplained 3), gms/air_shoe 9/12 (unexplained 2, delay 1),
acceleration/bowed_screw 13/20 (position 4, unexplained 1, asymmetry 1, load 1),
delay/complementary_fusion 12/20 (acceleration 3, gms 2, unexplained 1, inertia 1, none 1),
inertia/shunted_coil 9/20 (unexplained 5, acceleration 4, none 2),
stribeck_shape/battery_dynamo 6/16 (none 4, acceleration 4, unexplained 2),
asymmetry/clapper_tool 5/20 (stribeck_shape 7, unexplained 5, none 3),
backlash/eddy_gap 0/12 (unexplained 7, gms 4, delay 1). By plant: isolator 67.9 %,
valve 62.5 %, XML-350 62.5 %, forging press 60.7 %, damping rig 47.5 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen32` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen32`,
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
acceleration       ``bowed_screw``: the axis is driven by a long lead screw with a slight
                   initial bow; the carriage's inertial force is the screw's axial load,
                   which grows the bow under compression by 1 / (1 - P / P_cr) and
                   shrinks it under tension (a beam-column); the bowed screw presses the
                   nut and the carriage sideways on their guides: levels that rise with
                   one sign of a, ever faster, and fall with the other
load               ``magnet_preload``: the carriage carries a permanent magnet facing a
                   steel strip (a magnetic preload); the load deflects the carriage's
                   bearing and closes the magnet's air gap, and the magnet's pull, the
                   gap's inverse square, adds to the normal force: levels that rise ever
                   faster with the load
asymmetry          ``clapper_tool``: the carriage carries a tool in a clapper box (a
                   shaper's ram): towards +x it cuts a chip, against a cutting force that
                   falls slowly with the cutting speed; towards -x the clapper lifts and
                   the tool only rubs lightly over the cut surface
stribeck_shape     ``battery_dynamo``: a dynamo geared to the carriage charges a battery
                   through a rectifier: below the cut-in speed (its EMF under the
                   battery's voltage) nothing flows; above it a braking force that grows
                   in proportion to the speed's excess
position           ``hardened_zones``: the way is induction-hardened in passes; where two
                   passes meet the second tempers the first's end and leaves a soft band,
                   where the junctions grow and plough more: levels that rise in bands
                   along the stroke
inertia            ``shunted_coil``: the carriage carries a voice coil in a fixed
                   magnet's gap, its terminals shunted by a capacitor: the charging
                   current's force is a mass (C Bl^2) seen through the coil's R C lag,
                   falling as the coil leaves the gap towards the stroke's ends
delay              ``complementary_fusion``: the force is read by a fast coarse channel
                   and a slow fine one whose result comes late, fused by a complementary
                   filter: the force's slow part reaches the record late, its fast part
                   on time
drift              ``solenoid_coil``: the carriage's pads are pressed by a solenoid fed at
                   a constant voltage; its coil warms under its own I^2 R, its resistance
                   rises, the current falls and the pull with its square: levels that
                   fall, first fast, then levelling off
backlash           ``eddy_gap``: the play between drive and contact is bridged by an
                   eddy-current damper (a magnet on the drive over a copper plate on the
                   contact): across the play the eddy drag, in proportion to the speed
                   at first and falling beyond its critical speed, drags the contact
gms                ``air_shoe``: part of the friction is carried by a shoe held to the
                   carriage by a closed double-acting air cylinder; the shoe sticks and
                   the cylinder's air, compressed on one side and expanded on the other
                   (Boyle's law), pushes back ever more stiffly until the shoe slides; at
                   ``s`` = 0 the base
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``battery_dynamo``
needs a Stribeck curve (not the isolator's mre_lugre), ``hardened_zones`` a record that
revisits its positions (not the press), ``magnet_preload`` a load that changes,
``eddy_gap`` and ``air_shoe`` a classic LuGre base (valve, damping rig, XML-350); each
raises a ``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.shapes import SHAPES

from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _lag, _level,
                     _light_contact_step, _lugre_params, _presliding_path, _smooth_max0,
                     _substeps, has_stribeck_curve, level_inside, lugre_with_curve,
                     on_fine_grid)

__all__ = ["FORMS", "bowed_screw_truth", "magnet_preload_truth", "clapper_tool_truth",
           "battery_dynamo_truth", "hardened_zones_truth", "shunted_coil_truth",
           "complementary_fusion_truth", "solenoid_coil_truth", "eddy_gap_truth",
           "air_shoe_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "bowed_screw", "load": "magnet_preload",
         "asymmetry": "clapper_tool", "stribeck_shape": "battery_dynamo",
         "position": "hardened_zones", "inertia": "shunted_coil",
         "delay": "complementary_fusion", "drift": "solenoid_coil",
         "backlash": "eddy_gap", "gms": "air_shoe"}


# -- acceleration ----------------------------------------------------------------------------
#: ``bowed_screw``'s change of the levels per unit of the bow's growth over its 99th
#: percentile along the record, at strength 1 [-]; the screw's buckling load, x the
#: inertial force at the top acceleration [-]; the drive's peak thrust (its current limit),
#: x the inertial force at the top acceleration [-]
BOW_RISE, BOW_CRIT, BOW_PEAK = 0.5, 2.0, 1.5


def _bow_growth(q):
    """The screw's bow [-] (over its initial bow) at the axial loads ``q`` [-] (over its
    buckling load, compression positive, |q| < 1): a beam-column's initial crookedness
    grows by 1 / (1 - q) under compression and shrinks by the same law, 1 / (1 + |q|),
    under tension."""
    q = np.asarray(q, float)
    return 1.0 / (1.0 - q)


@on_fine_grid
def bowed_screw_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The axis is driven by a long slender lead screw with a slight initial bow (its
    straightness tolerance), fixed at the motor's end and carried by the nut at the
    carriage. The carriage's inertial force (m a; the friction's share is small next to it
    at hard accelerations) is the screw's axial load between the two: accelerating one
    way compresses the screw, the other way pulls it. A beam-column's bow grows under a
    compressive load by 1 / (1 - P / P_cr) and shrinks under tension by 1 / (1 + |P| /
    P_cr) (:func:`_bow_growth`; the buckling load P_cr :data:`BOW_CRIT` x the inertial
    force at the top acceleration, the thrust bounded by the drive's peak force,
    :data:`BOW_PEAK` x that force). The bowed screw presses the nut, and the carriage
    with it, sideways on its guides in proportion to its bow. The Coulomb and Stribeck
    levels are the base's times 1 + ``s`` :data:`BOW_RISE` x the bow's change from its
    initial value, over its 99th percentile of |change| along the record, inside the
    bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the guides' friction per unit of the screw's bow, / its value
        at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The amplification of a beam-column's initial crookedness by its axial load, 1 / (1 - P /
    P_cr) (Timoshenko and Gere 1961, Theory of Elastic Stability, ch. on beam-columns; the
    Perry-Robertson formula of columns with initial imperfections) and the buckling load
    that limits ball and lead screws' axial load (the screw makers' technical notes, THK's
    and NSK's, on the permissible axial load; Slocum 1992, Precision Machine Design, ch. on
    screw drives). The candidate raises the levels with |a|, lagged, tilts them with a and
    adds a force odd in a; the open forms lag, age, heat, skid, load, press, attract,
    squeeze, transfer weight, slosh, dilate, wedge, spring a gib, soften rubber, swing arms,
    unload by the jerk, tilt pads, push ball trains, ripple the current, slide rack flanks,
    set a shoe, shut a damper's bypass, creep a belt, rack a gantry, tighten a band, surge a
    feed line, load a traction drive, heat a winding, unload a counterweight's rope, pump
    oil, slacken a belt's strand or lift a preloaded nut's half off. Here the thrust that
    accelerates the carriage bends its own screw further or straightens it.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    u = np.clip(np.asarray(kin.a, float) / a99, -BOW_PEAK, BOW_PEAK)
    e = _bow_growth(u / BOW_CRIT) - 1.0
    e = e / max(float(np.percentile(np.abs(e), 99)), 1e-12)
    lev = np.maximum(1.0 + float(s) * BOW_RISE * e, 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- load ------------------------------------------------------------------------------------
#: ``magnet_preload``'s largest change of the levels with the magnet's pull, at strength 1
#: [-]; the magnet's air gap at no load, x the bearing's deflection at the largest load [-]
MAG_RISE, MAG_GAP = 0.5, 2.0


def _magnet_pull(w, gap):
    """A permanent magnet's pull [-] (over that at no load) across its air gap, at the
    loads ``w`` [-] (x the largest): the bearing deflects in proportion to the load and
    the gap (``gap`` x that deflection at the largest load, unloaded) closes by it; the
    pull grows as the gap's inverse square."""
    w = np.abs(np.asarray(w, float))
    return (gap / (gap - w)) ** 2


@on_fine_grid
def magnet_preload_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage carries a permanent magnet facing a steel strip on the way (a magnetic
    preload, as on air-bearing stages and some linear guides), its pull added to the
    contact's normal force. The normal load deflects the carriage's bearing in proportion
    and closes the magnet's air gap (:data:`MAG_GAP` x that deflection at the largest
    load, unloaded) by as much; the pull grows as the inverse square of the gap
    (:func:`_magnet_pull`). The Coulomb and Stribeck levels are the base's times
    1 + ``s`` :data:`MAG_RISE` x the pull's departure from its mean along the record, over
    its largest (the base's level holds the mean pull), inside the bristle dynamics; the
    viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (load [N]) and its base law.
    s : float
        Amplitude factor [-]: the friction per unit of the magnet's pull, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The pull of a permanent magnet across an air gap, ~ 1 / gap^2 for gaps small next to the
    pole (Furlani 2001, Permanent Magnet and Electromechanical Devices, ch. on magnetic
    forces) and magnetically preloaded bearings and stages (Slocum 1992, Precision Machine
    Design, ch. on bearings' preload). The candidate makes the levels affine in the load,
    with a memory over the travel; the open forms scale the friction with a Hertz contact's
    area, a seal's, a film's, a junction's, a pivot's, an adhesive contact's or a pin's arc,
    break, squeeze or desorb films, plough, creep, vibrate, overload or feed a constant flow
    to a pad, heal scuffs, relieve a preload, roll on a lossy track, slip differentially,
    spin balls, press a disc spring, skid lightly loaded rollers, bed a rail, heat a liner
    by PV, shear a soft film under pressure, pass the load through a clamp's seal, load
    crowned rollers' ends, sink wheels into a compacting track or sink a carriage onto its
    own wiper. Here the load narrows a magnet's gap and the magnet adds its pull to the
    load.
    """
    L = np.abs(np.asarray(kin.load, float))
    Lmax = float(np.max(L)) or 1.0
    if not np.ptp(L) > 1e-9 * Lmax:
        raise ValueError(f"load (magnet_preload): the {kin.plant} record's load does not "
                         f"change")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    p = _magnet_pull(L / Lmax, MAG_GAP)
    e = p - float(np.mean(p))
    e = e / max(float(np.max(np.abs(e))), 1e-12)
    lev = np.maximum(1.0 + float(s) * MAG_RISE * e, 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``clapper_tool``'s cutting force at the top speed, x the friction level, at strength 1
#: [-]; the tool's drag on the return stroke (its clapper's weight), x that force [-]; the
#: cutting speed below which the specific cutting force rises, x the top speed [-], and the
#: exponent of its fall with the speed [-]; the speed over which the tool engages, x the top
#: speed [-]
CUT_FORCE, CUT_RETURN, CUT_V0, CUT_EXP, CUT_ENGAGE = 0.5, 0.15, 0.1, 0.2, 0.02


def _cutting_factor(u, v0, n):
    """The specific cutting force [-] (over its value at the top speed) at the cutting
    speeds ``u`` [-] (|u|, over the top speed): it falls with the speed as the shear zone
    heats and softens, ((|u| + ``v0``) / (1 + ``v0``))^(-``n``)."""
    return ((np.abs(np.asarray(u, float)) + float(v0)) / (1.0 + float(v0))) ** (-float(n))


@on_fine_grid
def clapper_tool_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage carries a single-point tool in a clapper box (as a shaper's or a
    planer's ram): moving towards +x the tool is held against the clapper's back and cuts
    a chip from a workpiece that spans the stroke, against a cutting force that falls
    slowly with the cutting speed (the shear zone's heating; :func:`_cutting_factor`);
    moving towards -x the clapper swings up on its hinge and the tool only rubs over the
    cut surface under the clapper's weight, a drag of :data:`CUT_RETURN` x the cutting
    force at the top speed. The tool engages over :data:`CUT_ENGAGE` x the top speed
    (tanh). The truth adds ``s`` :data:`CUT_FORCE` x the friction level x that force (1
    when cutting at the top speed) to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the chip's cross-section (the depth of cut x the feed), / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The mechanics of orthogonal cutting (Merchant 1945, Mechanics of the metal cutting
    process, J. Appl. Phys. 16), the specific cutting force and its fall with the cutting
    speed (Kienzle 1952, Die Bestimmung von Kraeften und Leistungen an spanenden Werkzeugen
    und Werkzeugmaschinen, VDI-Z 94; Shaw 2005, Metal Cutting Principles, ch. on cutting
    forces and temperatures) and the clapper box of shapers and planers, which lifts the
    tool on the return stroke (Chapman 1972, Workshop Technology, part 2, ch. on shaping and
    planing). The candidate gives each direction its levels and an offset; the open forms
    twin the levels, the curves or the viscous term, bend a curve, roll a lip, load a thrust
    bearing, film a rod seal, texture a ratchet, return a spring, tilt a pad, strut a sprag,
    throttle a meter-out, differ a cylinder's areas, groove chevrons, buckle a helix, scrape
    chips, commutate, idle a belt, free a roller, wick a felt, run a belt, lean a brush,
    band a seal, counterbalance a valve, vibrate elliptically, diode a flow, pitch pads,
    skew rollers, lift through a screw, turn the frame, angle a pull, adhere by wedges,
    charge through a diode, drag a cup or flush coolant along the axis. Here a tool that
    cuts one way and rides back the other.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    u = np.asarray(kin.v, float) / v99
    fwd = 0.5 * (1.0 + np.tanh(u / CUT_ENGAGE))
    d = fwd * _cutting_factor(u, CUT_V0, CUT_EXP) - (1.0 - fwd) * CUT_RETURN
    return F + float(s) * CUT_FORCE * _level(kin) * d


# -- stribeck_shape --------------------------------------------------------------------------
#: ``battery_dynamo``'s drag at the top speed, x the Coulomb level, at strength 1 [-]; the
#: cut-in speed (where the dynamo's EMF reaches the battery's voltage and the rectifier's
#: drops), x the top speed [-]; the rounding of the cut-in (the rectifier's diodes' soft
#: knee), the same scale [-]
DYNAMO_DRAG, DYNAMO_CUTIN, DYNAMO_KNEE = 0.5, 0.35, 0.03


def _charging_current(u, cutin, knee):
    """The dynamo's charging current [-] (over its value at the top speed) at the speeds
    ``u`` [-] (over the top speed): its EMF, in proportion to |u|, less the battery's
    voltage and the rectifier's drops (the EMF at the cut-in speed ``cutin``), over the
    circuit's resistance; none below the cut-in (the diodes block), rounded over
    ``knee``."""
    u = np.abs(np.asarray(u, float))
    top = _smooth_max0(1.0 - float(cutin), knee)
    return _smooth_max0(u - float(cutin), knee) / top


@on_fine_grid
def battery_dynamo_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A small permanent-magnet dynamo geared to the carriage (through a pinion on its rack
    or a belt) charges a battery through a bridge rectifier (an axis-driven supply of a
    sensor's or a display's battery). Its EMF grows in proportion to the speed; below the
    cut-in speed (:data:`DYNAMO_CUTIN` x the top speed, where the EMF reaches the
    battery's voltage plus the diodes' drops) the rectifier blocks and no current flows;
    above it the charging current, and the dynamo's braking force (the force factor times
    the current), grow in proportion to the speed's excess (:func:`_charging_current`,
    the diodes' knee rounded). That drag, ``s`` :data:`DYNAMO_DRAG` x the Coulomb level at
    the top speed, is added to the base's Stribeck curve, inside the bristle dynamics.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (with a Stribeck curve).
    s : float
        Amplitude factor [-]: the dynamo's force factor over the circuit's resistance, / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    DC generators charging a battery and their cut-in speed (Say 1983, Alternating Current
    Machines, and Hughes and Drury 2013, Electric Motors and Drives, ch. on DC machines: the
    EMF in proportion to the speed, the torque to the current), rectifiers' blocking below
    their forward voltage (Mohan, Undeland and Robbins 2003, Power Electronics, ch. on diode
    rectifiers) and regenerative braking's force in proportion to the current (the force
    factor Bl or K_t). The candidate's curve is Gaussian, Lorentzian or an exponential tail;
    the open forms add tails, rationals, films that lift, spikes, bimodal roughness, logs,
    Eyring, starvation, rubber hysteresis, resonances, dither, melting, grains,
    readsorption, thermoviscous, turbulent and thixotropic films, churning, core losses,
    breathing bellows, eddy brakes, shear thinning, flying pads, wiping menisci, journals,
    wall slip, a closing clearance, a dwell's squeeze, a pocket's suction, condensing
    menisci, flash heating, a peeled adhesion, a measuring wheel's creep or a governor's
    shoes. Here a battery's voltage sets a speed below which the generator does not brake.
    """
    law = kin.base
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (battery_dynamo): the mre_lugre base has no "
                         "Stribeck curve")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    add = float(s) * DYNAMO_DRAG * _level(kin)
    return lugre_with_curve(kin, lambda vv: law.g(vv) + add * _charging_current(
        vv / v99, DYNAMO_CUTIN, DYNAMO_KNEE))


# -- position --------------------------------------------------------------------------------
#: ``hardened_zones``' rise of the levels in a soft zone, at strength 1 [-]; the hardening
#: passes' length, x the stroke [-]; the soft band's width where two passes meet, x the
#: stroke [-]
HARD_RISE, HARD_PASS, HARD_BAND = 0.5, 0.4, 0.06


def _softness(xr, passes, band):
    """The way's relative softness [-] (0 hardened, 1 as annealed) at the stroke's
    positions ``xr`` [-] (0 to 1): induction-hardened in passes of ``passes`` x the
    stroke; where two passes meet the second tempers the first's end, a soft band of
    ``band`` x the stroke, Gaussian across it."""
    xr = np.asarray(xr, float)
    joints = np.arange(passes, 1.0, passes)
    soft = np.zeros_like(xr)
    for j in joints:
        soft = np.maximum(soft, np.exp(-0.5 * ((xr - j) / band) ** 2))
    return soft


@on_fine_grid
def hardened_zones_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The way is induction-hardened in passes of :data:`HARD_PASS` x the stroke; where two
    passes meet, the second tempers the end of the first and leaves a soft band
    (:data:`HARD_BAND` x the stroke; :func:`_softness`). The adhesive friction is the
    junctions' shear strength over the softer body's hardness times the load, and on a
    softer way the junctions grow and plough more: the Coulomb and Stribeck levels are the
    base's times 1 + ``s`` :data:`HARD_RISE` x the softness less its mean along the
    record, over its largest, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the friction's rise in a soft band, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Friction as the junctions' shear strength over the hardness (Bowden and Tabor 1950, The
    Friction and Lubrication of Solids, ch. 5) and the soft zones that scanning induction
    hardening leaves where passes overlap or end (Rudnev, Loveless and Cook 2017, Handbook
    of Induction Heating, ch. on scan hardening). The candidate scales the friction along
    the stroke and adds a force of the position; the open forms put defects, waviness, wear,
    runout, bends, films, cogging, tapers, pockets, cushions, covers, springs, holes,
    plungers, sags, festoons, curves, chains, cams, heat, dents, joints, misalignment, flow
    forces, cranks, overhangs, a track's end, a reel, a way's flatness, conductive strips, a
    guide's ball passage, a steel insert, a screw's lead error, a rack's mesh or a draining
    film on the stroke. Here the way's own hardness changes along the stroke.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (hardened_zones): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    span = max(sc["x_hi"] - sc["x_lo"], 1e-12)
    xr = (np.asarray(kin.x, float) - sc["x_lo"]) / span
    b = _softness(xr, HARD_PASS, HARD_BAND)
    p = b - float(np.mean(b))
    p = p / max(float(np.max(np.abs(p))), 1e-12)
    lev = np.maximum(1.0 + float(s) * HARD_RISE * p, 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- inertia ---------------------------------------------------------------------------------
#: ``shunted_coil``'s mass (the capacitor's C x Bl^2 in the gap's middle) at strength 1, x
#: the friction level / a99 [kg per N s^2/m]; the shunt's time constant R C, x the motion's
#: time (v99 / a99) [-]; the coupling's fall at the stroke's ends (the coil leaving the
#: magnet's gap), Bl's share [-]
COIL_MASS, COIL_TAU, COIL_EDGE = 0.5, 0.1, 0.3


def _coil_coupling(xr, edge):
    """The voice coil's force factor Bl [-] (over its value in the gap's middle) at the
    positions ``xr`` [-] (-1 to 1 across the visited stroke): it falls as the coil moves
    out of the magnet's gap, 1 - ``edge`` xr^2."""
    xr = np.clip(np.asarray(xr, float), -1.0, 1.0)
    return 1.0 - float(edge) * xr * xr


def _shunt_force(t, b, v, M, tau):
    """The force [N] of a moving coil shunted by a capacitor through the coil's resistance:
    the coil's EMF b v (``b`` [-] its force factor over the middle's, ``v`` [m/s]) charges
    the capacitor through R (time constant ``tau`` = R C [s]), the current C d(u_C)/dt
    flows through the coil and its force is Bl times it: ``M`` / ``tau`` x b (b v - the
    capacitor's voltage over Bl), ``M`` = C Bl^2 [kg]; from rest, the capacitor charged to
    the start's EMF. A mass ``M`` b^2 for motions slow next to ``tau``."""
    e = np.asarray(b, float) * np.asarray(v, float)
    return float(M) / float(tau) * np.asarray(b, float) * (e - _lag(np.asarray(t, float), e,
                                                                    float(tau)))


@on_fine_grid
def shunted_coil_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage carries the coil of a voice-coil transducer (a moving coil in a fixed
    magnet's gap, left on the axis as a sensor or a spare actuator) whose terminals are
    shunted by a capacitor. Moving, the coil's EMF Bl v charges the capacitor through the
    coil's resistance (time constant R C, :data:`COIL_TAU` x the motion's time); its
    charging current flows through the coil, whose force, Bl times the current, is that of
    a mass C Bl^2 (``s`` :data:`COIL_MASS` x the friction level / a99 in the gap's
    middle) seen through the R C lag (:func:`_shunt_force`); Bl falls as the coil leaves
    the magnet's gap towards the stroke's ends (:func:`_coil_coupling`), so the mass does
    too, with a force of the speed squared as it changes. The inverse dynamics misses it;
    the truth adds it to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the capacitor's capacitance, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The mobility analogy, in which a capacitor across a transducer's terminals is a mass
    (Firestone 1933, A new analogy between mechanical and electrical systems, J. Acoust.
    Soc. Am. 4), electromagnetic shunt damping of moving coils (Behrens, Fleming and
    Moheimani 2005, Passive vibration control via electromagnetic shunt damping, IEEE/ASME
    Trans. Mechatronics 10) and the force factor's fall as a voice coil leaves its gap
    (Klippel 2006, Tutorial: loudspeaker nonlinearities - causes, parameters, symptoms, J.
    Audio Eng. Soc. 54). The candidate misses a constant mass; the open forms filter it,
    reflect it through gearing, a chain, a pinion or a screw, hang it on a spring, a cable,
    a fluid, a clutch, a coupling, a flyweight, a friction-damped, quasi-zero-stiffness,
    hose's, elastomer or magnetic mount, surge a spring, add a fluid's mass, pick, drop,
    empty, slide, rattle, telescope, roll or rock it, recoil a frame, saturate a motor, lead
    a feedforward, pitch a scale, radiate waves, swing it on a rod, slide it in a dish,
    swing a liquid in a tube or amplify a fluid's mass in an inerter. Here an electric
    circuit stores the carriage's kinetic energy as charge.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    a99 = max(sc["a99"], 1e-12)
    tau = COIL_TAU * max(sc["v99"], 1e-12) / a99
    mid = 0.5 * (sc["x_hi"] + sc["x_lo"])
    half = max(0.5 * (sc["x_hi"] - sc["x_lo"]), 1e-12)
    b = _coil_coupling((np.asarray(kin.x, float) - mid) / half, COIL_EDGE)
    M = float(s) * COIL_MASS * _level(kin) / a99
    return F + _shunt_force(kin.t, b, kin.v, M, tau)


# -- delay -----------------------------------------------------------------------------------
#: ``complementary_fusion``'s latency of the slow, fine channel at strength 1 [data
#: samples]; the complementary filter's time constant (its crossover's 1 / (2 pi f_c))
#: [data samples]
FUSE_SAMPLES, FUSE_TAU = 4.0, 3.0


def _fuse(t, u, late, tau):
    """The complementary fusion of two readings of ``u`` [N] at the times ``t`` [s]: a slow
    channel that reports u late by ``late`` [s] (linear between the times; before the
    record's start its first value) through the low pass of time constant ``tau`` [s], and
    a fast one on time through the complementary high pass, u - its low pass. With no
    latency, u itself."""
    t = np.asarray(t, float)
    u = np.asarray(u, float)
    slow = np.interp(t - float(late), t, u, left=u[0])
    return _lag(t, slow, tau) + (u - _lag(t, u, tau))


@on_fine_grid
def complementary_fusion_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is read by two channels fused by a complementary filter: a fast, coarse
    one (a low-resolution converter on time) and a slow, fine one (a high-resolution
    converter whose result reaches the acquisition ``s`` :data:`FUSE_SAMPLES` data samples
    late: its conversion and transfer). The acquisition keeps the fine channel's slow part
    and the coarse channel's fast part: the fine channel through a first-order low pass of
    time constant :data:`FUSE_TAU` data samples, the coarse one through the complementary
    high pass (:func:`_fuse`), so that at no latency the sum is the force itself. The
    coarse channel's quantisation is left out here; the force's slow changes reach the
    record late, its fast ones on time. The motion channels are on time.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the fine channel's latency, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Complementary filters, which blend two sensors of one quantity through a low pass and
    its complement (Higgins 1975, A comparison of complementary and Kalman filtering, IEEE
    Trans. Aerosp. Electron. Syst. 11; Brown and Hwang 2012, Introduction to Random Signals
    and Applied Kalman Filtering, ch. on complementary filters), as used to fuse a fast
    coarse and a slow fine measurement of one signal. The candidate shifts the force in time
    or lags it through a first-order filter; the open forms delay, filter, average, stamp,
    decimate, hold, skew, jitter, limit the slew, pipe, take medians, report on a dead band,
    sample positions, run a belt, aerate, drop telegrams, leak, creep, notch, track, snub,
    time a waveguide's pulse, diffuse eddy currents, count a resonator, sweep a grating,
    restore a force by a servo, interleave converters, balance a pneumatic cell, count out a
    dual slope, adapt a filter's time constant, round in integer arithmetic, fit a
    polynomial, observe a disturbance or average two taps half a period apart. Here the slow
    channel's latency delays only the force's slow part.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    return _fuse(kin.t, F, float(s) * FUSE_SAMPLES * kin.sample_dt, FUSE_TAU * kin.sample_dt)


# -- drift -----------------------------------------------------------------------------------
#: ``solenoid_coil``'s fall of the levels once the coil is warm, at strength 1 [-]; the
#: coil's thermal time constant, x the record's duration [-]; its temperature rise at the
#: end of warming times copper's temperature coefficient (alpha dT_max) [-]
COIL_FALL, COIL_TIME, COIL_RISE = 0.4, 0.5, 0.4


def _coil_pull(tr, tau, rise):
    """A voltage-driven solenoid's pull [-] (over its cold pull) at the record's relative
    times ``tr`` [-]: the coil warms towards its steady temperature with the time constant
    ``tau`` (its own I^2 R), its resistance rises with copper's temperature coefficient
    (``rise`` = alpha dT at the steady temperature), the current falls as 1 / R and the
    pull, in a fixed air gap, as the current squared."""
    tr = np.maximum(np.asarray(tr, float), 0.0)
    r = 1.0 + float(rise) * (1.0 - np.exp(-tr / float(tau)))
    return 1.0 / (r * r)


@on_fine_grid
def solenoid_coil_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage's brake pads (or a guide's clamping shoe) are pressed on the way by a
    solenoid fed at a constant voltage, switched on at the record's start. The coil
    warms under its own I^2 R towards its steady temperature (a first-order rise, time
    :data:`COIL_TIME` x the record); copper's resistance rises with the temperature, so
    the current falls as 1 / R and the solenoid's pull, across its fixed air gap, as the
    current squared (:func:`_coil_pull`). The Coulomb and Stribeck levels are the base's
    times 1 - ``s`` :data:`COIL_FALL` x the pull's loss since the start over its loss at
    the record's end, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the solenoid's share of the friction, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The pull of a solenoid ~ (N I)^2 across a fixed gap (Roters 1941, Electromagnetic
    Devices, ch. on tractive magnets), copper's temperature coefficient of resistance (about
    0.0039 per K) and the coil's first-order heating (the self-heating of solenoid-applied
    brakes and clamps, whose makers derate the force when the coil is hot; Roters 1941, ch.
    on heating). The candidate is a trend, a saturating change, a step, a cycle, a resetting
    change or the friction power's heat; the open forms warm up, wear in, change, heat,
    wear, follow the humidity, grind, relubricate, relax, oxidise, deplete, wear through,
    swell, build films, take in particles, expand, shear down, heat magnets, charge, creep,
    loosen, dewet, channel, drain, spall, evaporate, pump down, settle an additive,
    crystallise wax, bleed a grease's oil, cycle a thermostat, glaze a lining, form a
    tribolayer, grow frost or charge an electrostatic clamp. Here a coil's own heating
    weakens the force that presses the contact.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    tr = (t - t[0]) / max(float(t[-1] - t[0]), 1e-300)
    loss = 1.0 - _coil_pull(tr, COIL_TIME, COIL_RISE)
    lev = np.maximum(1.0 - float(s) * COIL_FALL * loss / max(float(loss[-1]), 1e-12), 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: ``eddy_gap``'s play at strength 1, as a share of the stroke (its full width) [-]; the
#: eddy drag's peak, x the Coulomb level [-]; its critical speed (where the drag peaks), x
#: the play's crossing speed (the drive's from rest across the play at the top
#: acceleration) [-]
EDDY_CLEAR, EDDY_DRAG, EDDY_CRIT = 0.0004, 0.5, 0.5


@njit(cache=True)
def _eddy_drag(ed, peak, vc):
    """The eddy-current drag [N] of a magnet moving over a conducting plate at the speed
    ``ed`` [m/s] relative to it: ``peak`` [N] at the critical speed ``vc`` [m/s], 2 peak
    (ed / vc) / (1 + (ed / vc)^2): in proportion to the speed while the induced currents'
    own field is weak, falling beyond ``vc`` as it pushes the magnet's field out of the
    plate."""
    r = ed / vc
    return 2.0 * peak * r / (1.0 + r * r)


@njit(cache=True)
def _eddy_contact(h, xd, half, peak, vc, kh, ch, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a light contact of mass ``m`` [kg] driven by the drive positions
    ``xd`` [m] (steps ``h`` [s]) through a play of half-width ``half`` [m] closed at the
    flanks by a spring ``kh`` [N/m] and damper ``ch`` [N s/m] (compressive only); across
    the play the eddy drag :func:`_eddy_drag` acts; from rest, the drive in the play's
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
            fc = _eddy_drag(ed, peak, vc)
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha,
                                         shape)
        x = x + h * v
    return F


@on_fine_grid
def eddy_gap_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact are joined across a play of width ``s``^2 :data:`EDDY_CLEAR` x the
    stroke; the drive's side carries a permanent magnet facing a copper plate on the
    contact's side across the play (an eddy-current damper bridging it). Across the play
    the moving magnet induces eddy currents in the plate, and their drag pulls the
    contact along: in proportion to the drive's speed relative to the contact at first,
    peaking (:data:`EDDY_DRAG` x the Coulomb level) at the critical speed
    (:data:`EDDY_CRIT` x the play's crossing speed, the drive's from rest across the play
    at the top acceleration) and falling beyond it as the currents' own field pushes the
    magnet's out (:func:`_eddy_drag`). A slow reversal crosses the play with the contact
    hardly dragged; a fast one drags it less than a middling one. The flanks then take
    the drive up (:func:`_eddy_contact`). The contact is light (its inertial force at the
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
    Eddy-current drag and its peak at a critical speed (Wouterse 1991, Critical torque and
    speed of eddy current brake with widely separated soft iron poles, IEE Proc. B 138;
    Sodano, Bae, Inman and Belvin 2006, Improved concept and model of eddy current damper,
    J. Vib. Acoust. 128) and lost motion in mechanisms (Nordin and Gutman 2002, Controlling
    mechanical systems with backlash - a survey, Automatica 38). The candidate holds or
    frees the contact across a rigid play; the open forms take it up rigidly, compliantly,
    by impact, against a spring, eccentrically, through oil, worn, with a dragging idler,
    biased, slack, magnetic, preloaded, through a flexspline, a rope, a spider, a fluid
    link, a cable, a clutch, a varying mesh, a polymer gear, grease, a wedge, an overlapped
    spool, a side loaded pin, a toggle spring, graded pins, an adhesive flank, packed
    powder, a floating part between two plays, trapped air, a ball detent, magnets on the
    flanks, a play that warms shut or a shear-thickening fluid. Here the play is bridged by
    induced currents.
    """
    p = _lugre_params(kin, "backlash (eddy_gap)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    half = 0.5 * float(s) ** 2 * EDDY_CLEAR * float(np.ptp(kin.x))
    vc = EDDY_CRIT * math.sqrt(4.0 * max(kin.scales["a99"], 1e-12) * max(half, 1e-300))
    peak = EDDY_DRAG * float(p.Fc)
    m, kh, ch = _contact_constants(kin, p)
    rate = max(math.sqrt(kh / m), (float(p.sigma1) + float(p.sigma2) + ch
                                   + 2.0 * peak / vc) / m)
    h, xd, n_sub = _substeps(kin, rate)
    Fr = _eddy_contact(h, xd, half, peak, vc, kh, ch, m,
                       float(p.sigma0), float(p.sigma1), float(p.sigma2), float(p.Fc),
                       float(p.Fs), float(p.vs), float(p.alpha), SHAPES[p.shape])
    return Fr[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: ``air_shoe``'s share of the friction the shoe carries, at strength 1 (at most 0.95) [-];
#: its slip travel beyond the base bristle's Fs / sigma0, at strength 1, x the stroke / 3
#: [-]; each chamber's length with the piston centred, x the slip travel [-]; the air's
#: polytropic index (1: isothermal, the chambers small and their walls at the way's
#: temperature) [-]
AIR_SHARE, AIR_PATH, AIR_CHAMBER, AIR_INDEX = 0.3, 0.1, 1.5, 1.0


def _air_spring(r, chamber, index):
    """A closed double-acting cylinder's force [-] (over its force at the slip travel) at
    the piston's travels ``r`` [-] (over the slip travel, |r| < ``chamber``): each chamber
    of length ``chamber`` x the slip travel holds the same air at the centre; the piston
    compresses one and expands the other, their pressures following p V^``index`` =
    const (Boyle's law at 1): (c / (c - r))^n - (c / (c + r))^n. Stiffer the further it
    travels."""
    r = np.asarray(r, float)
    c, n = float(chamber), float(index)

    def f(q):
        return (c / (c - q)) ** n - (c / (c + q)) ** n
    return f(r) / f(1.0)


@njit(cache=True)
def _shoe_travel(x, x_ref):
    """The piston's travel [-] (over the slip travel ``x_ref`` [m]) along the carriage's
    positions ``x`` [m], from rest and centred: the shoe sticks on the way, so the
    piston travels with the carriage, until it reaches the slip travel (+-1: the air
    spring's force the shoe's sliding force); then the shoe slides and the piston stays
    there."""
    n = x.size
    out = np.empty(n)
    shoe = x[0] if n > 0 else 0.0
    for k in range(n):
        r = (x[k] - shoe) / x_ref
        if r > 1.0:
            shoe = x[k] - x_ref
            r = 1.0
        elif r < -1.0:
            shoe = x[k] + x_ref
            r = -1.0
        out[k] = r
    return out


@on_fine_grid
def air_shoe_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Part of the contact's friction is carried by a shoe that rides on the way and is
    held to the carriage by a closed double-acting air cylinder (a small pneumatic spring:
    the shoe on its rod, both chambers sealed with the same air charge, each
    :data:`AIR_CHAMBER` x the slip travel long with the piston centred). The shoe sticks
    on the way and the carriage moves the cylinder over the piston: one chamber is
    compressed, the other expanded, and their pressures follow Boyle's law (polytropic
    index :data:`AIR_INDEX`), so the spring stiffens the further the piston travels
    (:func:`_air_spring`); where its force reaches the shoe's sliding force the shoe
    slides, at a travel of the base bristle's Fs / sigma0 plus ``s`` :data:`AIR_PATH` x the
    stroke / 3 (:func:`_shoe_travel`). The shoe carries the share w = ``s``
    :data:`AIR_SHARE` of the Coulomb level, w Fc f; the contact the rest, the base's
    LuGre with its curve less w Fc (its viscous term whole). At ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the shoe's share of the friction (up to ``s`` = 0.95 /
        :data:`AIR_SHARE`) and its slip travel (as the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Gas springs and the stiffness of enclosed air, p V^n = const (Harris and Piersol 2002,
    Harris' Shock and Vibration Handbook, ch. on air springs; Beater 2007, Pneumatic Drives,
    ch. on the cylinder's chambers as springs) and friction shoes held on springs beside a
    contact (the guide makers' clamping and braking elements). The candidate's presliding is
    a generalized Maxwell-slip (GMS) element set; the open forms are Maxwell-slip sets,
    Dahl, elasto-plastic, Bliman-Sorine, Bouc-Wen, Zener junctions, Mindlin contacts,
    rate-and-state, Tomlinson asperities, bond rupture, gouge, kinematic hardening,
    interlocking, capillary bridges, cyclic hardening, peeling, unloading microslip, a
    power-law joint, junction growth, avalanches, slip weakening, a microslip bar, contact
    renewal, grease's yield, a superelastic flexure, an Eyring film, a viscoplastic layer, a
    poroelastic one, a confined film that melts, a hysteresis brake, a fibre wiper, a band
    on a drum or a spring's rubbing leaves, each beside the contact, or a stiffening wire
    mesh in series with it. Here the air in a closed cylinder is the spring that holds a
    sticking shoe.
    """
    _lugre_params(kin, "gms (air_shoe)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    law = kin.base
    w = min(float(s) * AIR_SHARE, 0.95)
    wf = w * _level(kin)
    e0, extra = _presliding_path(kin, s, AIR_PATH)
    r = _shoe_travel(np.asarray(kin.x, float), e0 + extra)
    f = _air_spring(r, AIR_CHAMBER, AIR_INDEX)
    rest = lugre_with_curve(kin, lambda vv: law.g(vv) - wf)
    return rest + wf * f
