"""The thirty-fourth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-12-01 (session 39) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 39 (2026-12-02) on the code of d7e0374 (the
diagnosis code of 606791c): 176 cases, 0 skipped, 680 s wall on 2 workers (alone).
Top-1 64.8 % (114; 69.2 % of the 159 detectable; of the 17 undetectable, 9 are below their
practical size by the truth's own imprint (valve stribeck_shape 3, valve asymmetry 2,
forging press asymmetry 1, forging press stribeck_shape 1, isolator inertia 1, isolator
drift 1; all named none but one valve stribeck_shape, named stribeck_shape), 8 delays
shifted by less than a sample (XML-350 4: 2 named delay, 2 unexplained; damping rig 2: 1
named delay, 1 unexplained; isolator 2: 1 unexplained, 1 none); 4 of the 17 named their
effect and count among the 114); mean |shrink error| 0.212 (0.220 over the detectable, 0.140
over the right ones); wrong names on 16 (9.1 %): asymmetry -> stribeck_shape 5,
acceleration -> position 4, inertia -> acceleration 2, inertia -> position 2,
load -> delay 1, drift -> load 1, backlash -> gms 1.
By form: position/grit_band 16/16, load/toggle_clamp 19/20 (delay 1),
delay/acoustic_link 15/20 (unexplained 4, none 1),
drift/magnetic_aftereffect 15/20 (none 2, unexplained 2, load 1),
gms/buckling_strut 8/12 (unexplained 4),
stribeck_shape/floating_pawl 10/16 (none 4, unexplained 2),
acceleration/energised_seals 12/20 (unexplained 4, position 4),
inertia/yoke_flywheel 11/20 (unexplained 4, acceleration 2, position 2, none 1),
asymmetry/plunger_pump 5/20 (none 6, stribeck_shape 5, unexplained 4),
backlash/foam_pads 3/12 (unexplained 8, gms 1). By plant: valve 80.0 %, XML-350 67.5 %,
forging press 60.7 %, isolator 60.7 %, damping rig 52.5 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen33` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen33`,
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
acceleration       ``energised_seals``: the axis is driven by a double-acting hydraulic
                   cylinder held at a mean pressure; its seals' friction grows with the
                   pressure they hold, and once the thrust (m a) has emptied one chamber
                   to the tank's pressure the other's alone rises: levels that hold at
                   gentle accelerations and rise with |a| past a threshold
load               ``toggle_clamp``: the normal load bears on the knee of a toggle that
                   presses a gib on the way; the links' spring yields, the links
                   straighten and the toggle's gain 1 / (2 tan theta) rises: levels that
                   rise ever faster with the load
asymmetry          ``plunger_pump``: the carriage works a single-acting plunger pump:
                   towards +x it delivers against its relief valve's cracking pressure
                   and the delivery's orifice loss (~ v^2); towards -x it only draws oil
                   in through its inlet check valve, bounded by cavitation
stribeck_shape     ``floating_pawl``: a spring-loaded pawl rides over a toothed rack:
                   at low speeds it drops into every root, a drag independent of the
                   speed; above its float speed it is still in flight at the next tooth
                   and the drag falls as the speed's inverse square
position           ``grit_band``: a band of the way beside the work is covered with loose
                   abrasive grit, thinning beyond the band where the wipers carried it:
                   three-body abrasion raises the levels over that band
inertia            ``yoke_flywheel``: a flywheel turned by a Scotch yoke on the
                   carriage: its inertia reflected as the mass J (dtheta/dx)^2, growing
                   towards the stroke's ends, with Lagrange's m'(x) v^2 / 2 beside it
delay              ``acoustic_link``: the force measured on the carriage is sent by an
                   ultrasonic link to a receiver beyond the stroke's end: each reading
                   arrives after its flight time, which grows with the distance along
                   the stroke (and stretches or compresses the record, the Doppler
                   effect)
drift              ``magnetic_aftereffect``: the pads are pressed by a permanent-magnet
                   clamp magnetised by a pulse at the record's start; its magnetisation
                   decays by magnetic viscosity as the logarithm of the time and the pull
                   as its square: levels that fall fast at first, then ever slower
backlash           ``foam_pads``: the play's flanks are lined with elastomeric foam:
                   elastic, then a collapse plateau below the contact's friction, then
                   densification: the contact is pushed once the pad has densified
gms                ``buckling_strut``: part of the friction is carried by a shoe pushed
                   and pulled by a slender strut: stiff while straight, soft once
                   buckled, until the shoe slides; it unloads along the same elastic
                   path; at ``s`` = 0 the base
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``floating_pawl``
needs a Stribeck curve (not the isolator's mre_lugre), ``grit_band`` a record that
revisits its positions (not the press), ``toggle_clamp`` a load that changes,
``foam_pads`` and ``buckling_strut`` a classic LuGre base (valve, damping rig, XML-350);
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

__all__ = ["FORMS", "energised_seals_truth", "toggle_clamp_truth", "plunger_pump_truth",
           "floating_pawl_truth", "grit_band_truth", "yoke_flywheel_truth",
           "acoustic_link_truth", "magnetic_aftereffect_truth", "foam_pads_truth",
           "buckling_strut_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "energised_seals", "load": "toggle_clamp",
         "asymmetry": "plunger_pump", "stribeck_shape": "floating_pawl",
         "position": "grit_band", "inertia": "yoke_flywheel",
         "delay": "acoustic_link", "drift": "magnetic_aftereffect",
         "backlash": "foam_pads", "gms": "buckling_strut"}


# -- acceleration ----------------------------------------------------------------------------
#: ``energised_seals``' rise of the levels per unit of the seals' extra pressure over its
#: 99th percentile along the record, at strength 1 [-]; the chambers' mean pressure, x the
#: pressure difference that drives the top acceleration [-]; the drive's peak thrust (its
#: relief valve), x the inertial force at the top acceleration [-]; the rounding of a
#: chamber's pressure at the tank's (its cavitation), the same scale [-]
SEAL_RISE, SEAL_MEAN, SEAL_PEAK, SEAL_ROUND = 1.0, 0.1, 1.5, 0.02


def _chamber_pressures(u, mean, rnd):
    """The two chambers' pressures [-] (over the pressure difference at the top
    acceleration) of a double-acting cylinder held at the mean pressure ``mean`` and driven
    by the pressure difference ``u`` [-] (its thrust over the top acceleration's): mean +-
    u / 2, neither below the tank's (0; a chamber that reaches it cavitates and the other
    alone carries the thrust), rounded over ``rnd``."""
    u = np.asarray(u, float)
    p1 = _smooth_max0(mean + 0.5 * u, rnd)
    p2 = _smooth_max0(mean - 0.5 * u, rnd)
    return p1, p2


@on_fine_grid
def energised_seals_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The axis is driven by a double-acting hydraulic cylinder whose servo valve holds
    both chambers at a mean pressure (:data:`SEAL_MEAN` x the pressure difference that
    drives the top acceleration) and adds the difference its thrust needs: the carriage's
    inertial force m a (its friction's share is small next to it at hard accelerations),
    bounded by the relief valve (:data:`SEAL_PEAK` x the force at the top acceleration).
    The piston's and the rod's elastomer seals are energised by the pressure they hold: a
    seal's friction is its fitted interference's plus a coefficient times the pressure
    times its area. While both chambers stay above the tank's pressure, one gains what
    the other loses and the seals' summed friction holds; past the thrust at which one
    chamber reaches the tank's pressure (it cannot go below: it cavitates), the other's
    pressure alone rises with the thrust (:func:`_chamber_pressures`). The Coulomb and
    Stribeck levels are the base's times 1 + ``s`` :data:`SEAL_RISE` x the summed
    pressure's excess over its value at rest, over its 99th percentile along the record,
    inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the seals' friction per unit of pressure, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The friction of pressure-energised elastomer seals, a fitted part plus a coefficient
    times the pressure and the seal's projected area (the Parker O-Ring Handbook, ORD 5700,
    ch. on dynamic seals and their friction; Mueller and Nau 1998, Fluid Sealing
    Technology, ch. on reciprocating seals) and the chambers' pressures of a servo-driven
    cylinder, held at a mean and bounded below by the tank's pressure or cavitation (Merritt
    1967, Hydraulic Control Systems, ch. on valve-controlled pistons). The candidate raises
    the levels with |a|, lagged, tilts them with a and adds a force odd in a; the open forms
    lag, age, heat, skid, load, press, attract, squeeze, transfer weight, slosh, dilate,
    wedge, spring a gib, soften rubber, swing arms, unload by the jerk, tilt pads, push ball
    trains, ripple the current, slide rack flanks, set a shoe, shut a damper's bypass, creep
    a belt, rack a gantry, tighten a band, surge a feed line, load a traction drive, heat a
    winding, unload a counterweight's rope, pump oil, slacken a belt's strand, lift a
    preloaded nut's half off or bend a bowed screw. Here the thrust's pressure presses the
    drive's own seals, once it has emptied one chamber.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    u = np.clip(np.asarray(kin.a, float) / a99, -SEAL_PEAK, SEAL_PEAK)
    p1, p2 = _chamber_pressures(u, SEAL_MEAN, SEAL_ROUND)
    q0 = sum(_chamber_pressures(0.0, SEAL_MEAN, SEAL_ROUND))
    e = p1 + p2 - float(q0)
    e = e / max(float(np.percentile(np.abs(e), 99)), 1e-12)
    lev = np.maximum(1.0 + float(s) * SEAL_RISE * e, 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- load ------------------------------------------------------------------------------------
#: ``toggle_clamp``'s largest change of the levels with the toggle's amplification, at
#: strength 1 [-]; the links' angle to the line of thrust at no load [rad]; the share of
#: that angle the links' spring lets them straighten by at the largest load [-]
TOG_RISE, TOG_ANGLE, TOG_GIVE = 0.5, 0.35, 0.5


def _toggle_gain(w, angle, give):
    """A toggle's (knuckle joint's) normal force [-] on its pad per unit of the thrust on
    its knee, over its value at no load, at the loads ``w`` [-] (x the largest): each link
    at the angle theta to the pad's surface turns the knee's thrust W into W / (2 tan
    theta); the links' spring yields in proportion to the load and the links straighten,
    theta = ``angle`` (1 - ``give`` |w|), so the gain rises ever faster with the load."""
    w = np.abs(np.asarray(w, float))
    return math.tan(float(angle)) / np.tan(float(angle) * (1.0 - float(give) * w))


@on_fine_grid
def toggle_clamp_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage's gib (or a guide's clamping pad) is pressed on the way through a
    toggle (a knuckle joint) on which the normal load bears: the load pushes on the knee of
    two links that make an angle theta (:data:`TOG_ANGLE` at no load) with the pad's
    surface, and each link presses the pad with W / (2 tan theta). The links sit on a
    spring that yields under the load, so the knee sinks and the links straighten
    (theta falls by :data:`TOG_GIVE` of its value at the largest load), and the gain of
    the toggle rises ever faster with the load (:func:`_toggle_gain`). The Coulomb and
    Stribeck levels are the base's times 1 + ``s`` :data:`TOG_RISE` x the gain's
    departure from its mean along the record, over its largest (the base's level holds
    the mean gain), inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (load [N]) and its base law.
    s : float
        Amplitude factor [-]: the toggle-pressed pad's share of the friction, / its value
        at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The toggle (knuckle-joint) mechanism and its mechanical advantage 1 / (2 tan theta), which
    grows without bound as the links straighten (Reuleaux 1876, The Kinematics of Machinery;
    Shigley and Uicker 1980, Theory of Machines and Mechanisms, ch. on mechanical advantage;
    the toggle clamps of fixtures and the knuckle-joint presses). The candidate makes the
    levels affine in the load, with a memory over the travel; the open forms scale the
    friction with a Hertz contact's area, a seal's, a film's, a junction's, a pivot's, an
    adhesive contact's or a pin's arc, break, squeeze or desorb films, plough, creep,
    vibrate, overload or feed a constant flow to a pad, heal scuffs, relieve a preload, roll
    on a lossy track, slip differentially, spin balls, press a disc spring, skid lightly
    loaded rollers, bed a rail, heat a liner by PV, shear a soft film under pressure, pass
    the load through a clamp's seal, load crowned rollers' ends, sink wheels into a
    compacting track, sink a carriage onto its own wiper or close a magnet's gap. Here a
    linkage's geometry amplifies the load it passes to a pad, the more the harder it is
    pressed.
    """
    L = np.abs(np.asarray(kin.load, float))
    Lmax = float(np.max(L)) or 1.0
    if not np.ptp(L) > 1e-9 * Lmax:
        raise ValueError(f"load (toggle_clamp): the {kin.plant} record's load does not "
                         f"change")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    g = _toggle_gain(L / Lmax, TOG_ANGLE, TOG_GIVE)
    e = g - float(np.mean(g))
    e = e / max(float(np.max(np.abs(e))), 1e-12)
    lev = np.maximum(1.0 + float(s) * TOG_RISE * e, 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``plunger_pump``'s delivery force at the top speed, x the friction level, at strength 1
#: [-]; the delivery's relief (cracking) pressure, x the delivery pressure at the top speed
#: [-]; the suction's inlet check valve's cracking pressure, x the same [-], its inlet's
#: orifice loss at the top speed over that cracking pressure [-] and the suction's bound
#: (the vapour pressure: the plunger cavitates), x the same [-]; the speed over which the
#: check valves change over, x the top speed [-]
PUMP_FORCE, PUMP_CRACK, PUMP_INLET, PUMP_INLOSS, PUMP_CAV, PUMP_SWITCH = (
    0.5, 0.6, 0.05, 4.0, 0.2, 0.02)


def _pump_pressure(u, crack, inlet, inloss, cav):
    """The plunger's pressure [-] (over the delivery pressure at the top speed; the
    plunger moving towards +x delivers, towards -x draws in) at the speeds ``u`` [-]
    (over the top speed): delivering, the relief valve's cracking pressure ``crack`` plus
    the delivery line's orifice loss, growing as u^2 (``crack`` + (1 - ``crack``) u^2);
    drawing in, minus the inlet check valve's cracking pressure ``inlet`` plus its
    orifice loss (``inlet`` (1 + ``inloss`` u^2)), bounded by the vapour pressure ``cav``
    (y / (1 + y / ``cav``)). Each branch for its own sign of ``u``."""
    u = np.asarray(u, float)
    out = float(crack) + (1.0 - float(crack)) * u * u
    y = float(inlet) * (1.0 + float(inloss) * u * u)
    return out, -y / (1.0 + y / float(cav))


@on_fine_grid
def plunger_pump_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage drives the plunger of a single-acting piston pump (a way-lubrication or
    a coolant pump worked by the axis, as on shapers, planers and older grinders) through
    two check valves. Moving towards +x the plunger delivers: the outlet valve opens and
    the plunger pushes against the relief valve's cracking pressure (:data:`PUMP_CRACK` x
    the delivery pressure at the top speed) plus the delivery line's orifice loss, which
    grows as the flow squared; moving towards -x it draws oil in through the inlet check
    valve against that valve's small cracking pressure (:data:`PUMP_INLET`) and the inlet's
    orifice loss, bounded by the oil's vapour pressure, at which the plunger cavitates
    (:data:`PUMP_CAV`; :func:`_pump_pressure`). The valves change over within
    :data:`PUMP_SWITCH` x the top speed (tanh). The truth adds ``s`` :data:`PUMP_FORCE` x
    the friction level x that pressure (1 when delivering at the top speed) to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the plunger's area, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Reciprocating plunger pumps with suction and delivery check valves, their relief
    valve's cracking pressure and the orifice loss of the delivery, dp ~ Q^2, and
    cavitation at the vapour pressure on the suction stroke (Karassik, Messina, Cooper and
    Heald 2008, Pump Handbook, ch. on reciprocating pumps; Merritt 1967, Hydraulic Control
    Systems, ch. on orifice flow), as machine tools' axis-driven lubricating pumps (Chapman
    1972, Workshop Technology, part 2, on the lubrication of shapers and planers). The
    candidate gives each direction its levels and an offset; the open forms twin the levels,
    the curves or the viscous term, bend a curve, roll a lip, load a thrust bearing, film a
    rod seal, texture a ratchet, return a spring, tilt a pad, strut a sprag, throttle a
    meter-out, differ a cylinder's areas, groove chevrons, buckle a helix, scrape chips,
    commutate, idle a belt, free a roller, wick a felt, run a belt, lean a brush, band a
    seal, counterbalance a valve, vibrate elliptically, diode a flow, pitch pads, skew
    rollers, lift through a screw, turn the frame, angle a pull, adhere by wedges, charge
    through a diode, drag a cup, flush coolant along the axis or cut one way with a clapper
    tool. Here a pump works one stroke against its delivery and the other only draws in.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    u = np.asarray(kin.v, float) / v99
    fwd = 0.5 * (1.0 + np.tanh(u / PUMP_SWITCH))
    out, back = _pump_pressure(u, PUMP_CRACK, PUMP_INLET, PUMP_INLOSS, PUMP_CAV)
    return F + float(s) * PUMP_FORCE * _level(kin) * (fwd * out + (1.0 - fwd) * back)


# -- stribeck_shape --------------------------------------------------------------------------
#: ``floating_pawl``'s drag at rest, x the Coulomb level, at strength 1 [-]; the pawl's
#: float speed (where it no longer falls back to a tooth's root before the next tooth),
#: x the top speed [-]
PAWL_DRAG, PAWL_FLOAT = 0.5, 0.3


def _pawl_drag(u, ufloat):
    """The pawl's mean drag [-] (over its value at low speeds) at the speeds ``u`` [-]
    (over the top speed): below the float speed ``ufloat`` it drops into every tooth's
    root and the tooth's flank lifts it again, an energy per tooth, a drag independent of
    the speed; above it the pawl, thrown off a crest, is still in flight when the next
    tooth passes and strikes ever fewer and lower, the drag falling as (``ufloat`` /
    u)^2: 1 / sqrt(1 + (u / ``ufloat``)^4)."""
    r = np.abs(np.asarray(u, float)) / float(ufloat)
    return 1.0 / np.sqrt(1.0 + r ** 4)


@on_fine_grid
def floating_pawl_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage carries a spring-loaded pawl that rides over a toothed rack along the
    way (a safety catch of a vertical axis, or an indexing detent left engaged): each tooth
    lifts the pawl against its spring and the pawl drops into the next root, a loss of
    energy per tooth and so a drag independent of the speed at low speeds. The pawl falls
    back under its spring in a fixed time; once a tooth passes sooner (above the float
    speed, :data:`PAWL_FLOAT` x the top speed) the pawl, thrown off a crest, is still in
    flight at the next tooth and strikes ever fewer and lower, and the drag falls as the
    speed's inverse square (:func:`_pawl_drag`). That drag, ``s`` :data:`PAWL_DRAG` x the
    Coulomb level at rest, is added to the base's Stribeck curve, inside the bristle
    dynamics.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (with a Stribeck curve).
    s : float
        Amplitude factor [-]: the pawl's spring force, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Follower jump and float, where a spring-returned follower (an engine's valve, a cam's
    follower, a pawl) no longer keeps to its track once its return time exceeds the time
    the track allows (Norton 2009, Cam Design and Manufacturing Handbook, ch. on follower
    jump; Rothbart 2004, Cam Design Handbook), and ratchets' and detents' losses per tooth
    (Shigley and Mischke 2001, Mechanical Engineering Design, on ratchets and pawls). The
    candidate's curve is Gaussian, Lorentzian or an exponential tail; the open forms add
    tails, rationals, films that lift, spikes, bimodal roughness, logs, Eyring, starvation,
    rubber hysteresis, resonances, dither, melting, grains, readsorption, thermoviscous,
    turbulent and thixotropic films, churning, core losses, breathing bellows, eddy brakes,
    shear thinning, flying pads, wiping menisci, journals, wall slip, a closing clearance, a
    dwell's squeeze, a pocket's suction, condensing menisci, flash heating, a peeled
    adhesion, a measuring wheel's creep, a governor's shoes or a battery's dynamo. Here a
    pawl's flight time sets the speed above which it stops dragging.
    """
    law = kin.base
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (floating_pawl): the mre_lugre base has no "
                         "Stribeck curve")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    add = float(s) * PAWL_DRAG * _level(kin)
    return lugre_with_curve(kin, lambda vv: law.g(vv) + add * _pawl_drag(vv / v99,
                                                                         PAWL_FLOAT))


# -- position --------------------------------------------------------------------------------
#: ``grit_band``'s rise of the levels where the grit lies thickest, at strength 1 [-]; the
#: band's half-width where it lies evenly, x the stroke [-]; the length over which the
#: wipers have thinned it beyond the band, x the stroke [-]
GRIT_RISE, GRIT_HALF, GRIT_TAIL = 0.5, 0.08, 0.05


def _grit_cover(d, half, tail):
    """The grit's cover of the way [-] (1 in the band) at the distances ``d`` [-] from the
    band's centre (over the stroke): even over ``half`` either side, thinning beyond as
    exp(-(|d| - ``half``) / ``tail``), as the wipers have carried it along and shed it."""
    d = np.abs(np.asarray(d, float))
    return np.exp(-np.maximum(d - float(half), 0.0) / float(tail))


@on_fine_grid
def grit_band_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A band of the way beside the work (where a grinding wheel's or a saw's fall-out
    settles) is covered with hard abrasive grit, even over :data:`GRIT_HALF` x the stroke
    either side of its centre (the middle of the positions both parts of the record
    visit) and thinning beyond it over :data:`GRIT_TAIL` x the stroke, where the wipers
    have carried it along (:func:`_grit_cover`). Loose hard particles between the
    carriage's pads and the way roll and slide between them and plough grooves in both
    (three-body abrasion), adding a ploughing share to the adhesive friction: the Coulomb
    and Stribeck levels are the base's times 1 + ``s`` :data:`GRIT_RISE` x the cover less
    its mean along the record, over its largest, inside the bristle dynamics; the viscous
    term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the friction's rise where the grit lies thickest, / its value
        at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Three-body abrasion by loose hard particles, which roll and slide between two surfaces
    and plough both, and the ploughing share it adds to the friction (Rabinowicz 1995,
    Friction and Wear of Materials, ch. on abrasive wear; Hutchings 1992, Tribology:
    Friction and Wear of Engineering Materials, ch. on abrasive wear; Suh and Sin 1981, The
    genesis of friction, Wear 69). The candidate scales the friction along the stroke and
    adds a force of the position; the open forms put defects, waviness, wear, runout, bends,
    films, cogging, tapers, pockets, cushions, covers, springs, holes, plungers, sags,
    festoons, curves, chains, cams, heat, dents, joints, misalignment, flow forces, cranks,
    overhangs, a track's end, a reel, a way's flatness, conductive strips, a guide's ball
    passage, a steel insert, a screw's lead error, a rack's mesh, a draining film or
    hardened zones on the stroke. Here loose particles lie on a band of the way.
    """
    c = _bump_centre(kin)
    if c is None:
        raise ValueError(f"position (grit_band): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    span = max(sc["x_hi"] - sc["x_lo"], 1e-12)
    b = _grit_cover((np.asarray(kin.x, float) - c) / span, GRIT_HALF, GRIT_TAIL)
    p = b - float(np.mean(b))
    p = p / max(float(np.max(np.abs(p))), 1e-12)
    lev = np.maximum(1.0 + float(s) * GRIT_RISE * p, 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- inertia ---------------------------------------------------------------------------------
#: ``yoke_flywheel``'s mass reflected to the axis with the crank square to the slot (J / R^2)
#: at strength 1, x the friction level / a99 [kg per N s^2/m]; the crank's radius, x half
#: the visited stroke (above 1: the crank never reaches its dead centres) [-]
YOKE_MASS, YOKE_CRANK = 0.5, 1.25


def _yoke_mass(d, crank):
    """The flywheel's mass [-] reflected to the carriage through a Scotch yoke (over its
    value with the crank square to the slot) at the offsets ``d`` [-] (over the crank's
    radius ``crank``; the yoke's x = R sin theta, so dtheta/dx = 1 / sqrt(R^2 - x^2)):
    J (dtheta/dx)^2 = 1 / (1 - (d / ``crank``)^2), and its derivative along the offset
    [-] (over the crank's radius)."""
    q = np.asarray(d, float) / float(crank)
    m = 1.0 / (1.0 - q * q)
    return m, 2.0 * q * m * m / float(crank)


@on_fine_grid
def yoke_flywheel_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage's slot is the yoke of a Scotch yoke: a crank pin running in it turns a
    flywheel (a crank-driven rotary part, as a shaper's or a pump's, left coupled to the
    axis), so the flywheel's angle follows the carriage's position, x = R sin theta, with
    the crank's radius R :data:`YOKE_CRANK` x half the visited stroke (it never reaches its
    dead centres). The flywheel's inertia J is seen at the carriage as the mass J
    (dtheta/dx)^2, J / R^2 (``s`` :data:`YOKE_MASS` x the friction level / a99) with the
    crank square to the slot and growing towards the stroke's ends as 1 / (1 - (x /
    R)^2) (:func:`_yoke_mass`); by Lagrange's equation the force is that mass times the
    acceleration plus half its gradient along x times the speed squared. The inverse
    dynamics misses it; the truth adds it to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the flywheel's moment of inertia, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The Scotch yoke's kinematics, x = R sin theta (Shigley and Uicker 1980, Theory of
    Machines and Mechanisms, ch. on linkages; Norton 2008, Design of Machinery, ch. on the
    dynamics of crank mechanisms) and a mechanism's inertia reduced to one coordinate, a
    mass that depends on the configuration, whose generalised force by Lagrange's equation
    is m(x) a + m'(x) v^2 / 2 (Meriam and Kraige, Engineering Mechanics: Dynamics, on
    variable-ratio drives; Wittenburg 2008, Dynamics of Multibody Systems). The candidate
    misses a constant mass; the open forms filter it, reflect it through gearing, a chain, a
    pinion or a screw, hang it on a spring, a cable, a fluid, a clutch, a coupling, a
    flyweight, a friction-damped, quasi-zero-stiffness, hose's, elastomer or magnetic mount,
    surge a spring, add a fluid's mass, pick, drop, empty, slide, rattle, telescope, roll or
    rock it, recoil a frame, saturate a motor, lead a feedforward, pitch a scale, radiate
    waves, swing it on a rod, slide it in a dish, swing a liquid in a tube, amplify a
    fluid's mass in an inerter or store it as a shunted coil's charge. Here a crank's
    changing ratio makes the reflected mass a function of the position.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    a99 = max(sc["a99"], 1e-12)
    mid = 0.5 * (sc["x_hi"] + sc["x_lo"])
    half = max(0.5 * (sc["x_hi"] - sc["x_lo"]), 1e-12)
    d = (np.asarray(kin.x, float) - mid) / half
    m, dm = _yoke_mass(d, YOKE_CRANK)
    M = float(s) * YOKE_MASS * _level(kin) / a99
    v = np.asarray(kin.v, float)
    return F + M * (m * np.asarray(kin.a, float) + 0.5 * dm / half * v * v)


# -- delay -----------------------------------------------------------------------------------
#: ``acoustic_link``'s flight time from the stroke's far end at strength 1 [data samples];
#: the receiver's distance beyond the stroke's near (-x) end, x the stroke [-]
LINK_SAMPLES, LINK_NEAR = 4.0, 0.5


def _acoustic_record(t, u, flight):
    """The record [N] at the times ``t`` [s] of readings ``u`` [N] sent at ``t`` and heard
    ``flight`` [s] later (the path's length over the speed of sound, at each sending): at
    each time the latest reading heard (linear between the readings; before the first
    arrives, the first), its arrival times kept in order (a reading overtaken by a later
    one is never the latest: the carriage never outruns the sound). With no flight time,
    ``u`` itself."""
    t = np.asarray(t, float)
    u = np.asarray(u, float)
    arrive = np.maximum.accumulate(t + np.asarray(flight, float))
    return np.interp(t, arrive, u, left=u[0])


@on_fine_grid
def acoustic_link_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is measured on the carriage and sent to the acquisition by an ultrasonic
    link (a transmitter on the carriage, a receiver fixed beyond the stroke's -x end, as
    where a cable or a radio link cannot be used): each reading reaches the receiver after
    its flight over the distance between them at the speed of sound, longer the further
    the carriage is from the receiver (the receiver :data:`LINK_NEAR` x the stroke beyond
    the near end; ``s`` :data:`LINK_SAMPLES` data samples of flight from the far end,
    in proportion to the distance). The acquisition records the latest reading heard
    (:func:`_acoustic_record`): the force's changes reach the record late by a time that
    grows along the stroke, and the record is stretched while the carriage moves away and
    compressed while it comes back (the Doppler effect). The motion channels are on time.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law.
    s : float
        Amplitude factor [-]: the flight time per unit of distance (the inverse of the
        speed of sound in the axis's enclosure, or the path's folding), / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The propagation of sound in air at c = 331 sqrt(T / 273 K) m/s and the time of flight
    and Doppler shift of a moving source (Kinsler, Frey, Coppens and Sanders 2000,
    Fundamentals of Acoustics, ch. on plane waves and the Doppler effect) and ultrasonic
    data links and ranging, whose arrival time is the path's length over c (Lynnworth 1989,
    Ultrasonic Measurements for Process Control, ch. on transit time). The candidate shifts
    the force in time or lags it through a first-order filter; the open forms delay, filter,
    average, stamp, decimate, hold, skew, jitter, limit the slew, pipe, take medians, report
    on a dead band, sample positions, run a belt, aerate, drop telegrams, leak, creep,
    notch, track, snub, time a waveguide's pulse, diffuse eddy currents, count a resonator,
    sweep a grating, restore a force by a servo, interleave converters, balance a pneumatic
    cell, count out a dual slope, adapt a filter's time constant, round in integer
    arithmetic, fit a polynomial, observe a disturbance, average two taps half a period
    apart or fuse a late fine channel with a fast coarse one. Here the delay is a flight
    time that follows the carriage along the stroke.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    span = max(sc["x_hi"] - sc["x_lo"], 1e-12)
    dist = (LINK_NEAR + (np.asarray(kin.x, float) - sc["x_lo"]) / span) / (LINK_NEAR + 1.0)
    flight = float(s) * LINK_SAMPLES * kin.sample_dt * dist
    return _acoustic_record(kin.t, F, flight)


# -- drift -----------------------------------------------------------------------------------
#: ``magnetic_aftereffect``'s fall of the levels at the record's end, at strength 1 [-]; the
#: magnetisation's time origin after the magnetising pulse, x the record's duration [-];
#: the magnet's viscosity coefficient, the magnetisation's loss per e-fold of the time
#: (over the magnetisation just after the pulse) [-]
AFTER_FALL, AFTER_T0, AFTER_S = 0.4, 0.01, 0.02


def _aftereffect_pull(tr, t0, visc):
    """A permanent-magnet clamp's pull [-] (over its pull just after the magnetising
    pulse) at the record's relative times ``tr`` [-]: the magnetisation decays by magnetic
    viscosity as the logarithm of the time, M = 1 - ``visc`` ln(1 + tr / ``t0``), and the
    pull across the clamp's fixed gap as M^2."""
    tr = np.maximum(np.asarray(tr, float), 0.0)
    m = 1.0 - float(visc) * np.log1p(tr / float(t0))
    return m * m


@on_fine_grid
def magnetic_aftereffect_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage's pads are pressed on the way by a permanent-magnet clamp (an
    electro-permanent clamp, its magnets magnetised by a current pulse just before the
    record's start). At a constant temperature and field the magnets' magnetisation
    decays after the pulse by magnetic viscosity, the thermally activated reversal of
    domains over their energy barriers: in proportion to the logarithm of the time since
    the pulse (its time origin :data:`AFTER_T0` x the record, its coefficient
    :data:`AFTER_S` per e-fold), and the clamp's pull across its fixed gap falls as the
    magnetisation squared (:func:`_aftereffect_pull`). The Coulomb and Stribeck levels
    are the base's times 1 - ``s`` :data:`AFTER_FALL` x the pull's loss since the start
    over its loss at the record's end, inside the bristle dynamics; the viscous term is
    the base's: a fall fast at first and ever slower, never levelling off.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the clamp's share of the friction, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Magnetic viscosity (the magnetic after-effect), the decay of a magnet's magnetisation as
    S ln(t) after a change of the field, from the thermal activation of irreversible
    reversals (Street and Woolley 1949, A study of magnetic viscosity, Proc. Phys. Soc. A
    62; Chikazumi 1997, Physics of Ferromagnetism, ch. on magnetic after-effect), the pull
    of a magnet ~ B^2 across a gap (Furlani 2001, Permanent Magnet and Electromechanical
    Devices) and electro-permanent magnetic clamps and chucks, magnetised by a pulse. The
    candidate is a trend, a saturating change, a step, a cycle, a resetting change or the
    friction power's heat; the open forms warm up, wear in, change, heat, wear, follow the
    humidity, grind, relubricate, relax, oxidise, deplete, wear through, swell, build films,
    take in particles, expand, shear down, heat magnets, charge, creep, loosen, dewet,
    channel, drain, spall, evaporate, pump down, settle an additive, crystallise wax, bleed
    a grease's oil, cycle a thermostat, glaze a lining, form a tribolayer, grow frost,
    charge an electrostatic clamp or warm a solenoid's coil. Here a magnet's own domains
    relax after it was magnetised, at a constant temperature.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    tr = (t - t[0]) / max(float(t[-1] - t[0]), 1e-300)
    loss = 1.0 - _aftereffect_pull(tr, AFTER_T0, AFTER_S)
    lev = np.maximum(1.0 - float(s) * AFTER_FALL * loss / max(float(loss[-1]), 1e-12), 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: ``foam_pads``' play at strength 1, as a share of the stroke (its full width between the
#: rigid flanks) [-]; each foam pad's thickness, x half the play [-]; the foam's plateau
#: (collapse) force, x the Coulomb level [-]; its strain at the plateau's start (the cell
#: walls' elastic limit) [-] and at densification [-]; the plateau's rise to
#: densification, x the plateau force [-]; the strain the densification is followed to
#: (the pad then bottoms on the flank) [-]
FOAM_CLEAR, FOAM_THICK, FOAM_PLAT = 0.0004, 0.5, 0.3
FOAM_YIELD, FOAM_DENSE, FOAM_HARD, FOAM_BOTTOM = 0.05, 0.6, 0.2, 0.95


@njit(cache=True)
def _foam_stress(eps, yld, dense, hard, bottom):
    """An elastomeric open-cell foam's compressive force [-] (over its plateau force) at the
    strains ``eps`` [-] (0 to 1): linear elastic up to ``yld`` (the cell walls bend),
    a plateau rising by ``hard`` to the densification strain ``dense`` (the cell walls
    buckle), then steeply, ((1 - ``dense``) / (1 - eps))^2, as the collapsed cells touch,
    followed up to ``bottom`` (held there beyond). 0 at no strain."""
    if eps <= 0.0:
        return 0.0
    if eps < yld:
        return eps / yld
    if eps < dense:
        return 1.0 + hard * (eps - yld) / (dense - yld)
    e = eps if eps < bottom else bottom
    r = (1.0 - dense) / (1.0 - e)
    return (1.0 + hard) * r * r


@njit(cache=True)
def _foam_contact(h, xd, half, tf, plat, kh, ch, m, s0, s1, s2, Fc, Fs, vs, alpha, shape,
                  yld, dense, hard, bottom):
    """LuGre friction [N] of a light contact of mass ``m`` [kg] driven by the drive positions
    ``xd`` [m] (steps ``h`` [s]) through a play of half-width ``half`` [m] whose flanks
    carry foam pads ``tf`` [m] thick (:func:`_foam_stress`, its plateau ``plat`` [N];
    compressive only) and are rigid beyond them (a spring ``kh`` [N/m] and damper ``ch``
    [N s/m], compressive only, the pad fully compressed between); from rest, the drive
    in the play's middle. Semi-implicit Euler of the contact, its bristle exact."""
    nn = xd.size
    F = np.empty(nn)
    x = xd[0]
    v = 0.0
    z = 0.0
    free = half - tf
    for j in range(nn):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        e = xd[j] - x
        ed = vd - v
        fc = 0.0
        ae = e if e > 0.0 else -e
        if ae > free:
            fc = plat * _foam_stress((ae - free) / tf, yld, dense, hard, bottom)
            if ae > half:
                f2 = kh * (ae - half) + (ch * ed if e > 0.0 else -ch * ed)
                if f2 > 0.0:
                    fc += f2
            if e < 0.0:
                fc = -fc
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha,
                                         shape)
        x = x + h * v
    return F


@on_fine_grid
def foam_pads_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact are joined across a play of width ``s``^2 :data:`FOAM_CLEAR` x the
    stroke whose flanks are lined with pads of an elastomeric open-cell foam (a noise- and
    shock-damping liner), each :data:`FOAM_THICK` x half the play thick. Across the
    play's middle the contact is free; the drive then meets a pad, which resists
    elastically while its cell walls bend, then collapses at a nearly constant force
    (its plateau, :data:`FOAM_PLAT` x the Coulomb level, rising slowly as the cell walls
    buckle) and stiffens steeply once the collapsed cells touch (densification;
    :func:`_foam_stress`), until the pad bottoms on the rigid flank
    (:func:`_foam_contact`). The plateau holds less than the contact's friction: a
    reversal pushes the contact only once the pad is densified, at a take-up that depends
    on how hard the contact sticks. The contact is light (its inertial force at the top
    acceleration 1 % of the Coulomb level) with the base's LuGre friction; the foam's
    unloading hysteresis is left out.

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
    The compression of cellular solids, linear elastic, then a plateau as the cell walls
    buckle or collapse, then densification (Gibson and Ashby 1997, Cellular Solids:
    Structure and Properties, ch. 5 on elastomeric foams; Mills 2007, Polymer Foams
    Handbook, ch. on compressive behaviour) and lost motion in mechanisms (Nordin and Gutman
    2002, Controlling mechanical systems with backlash - a survey, Automatica 38). The
    candidate holds or frees the contact across a rigid play; the open forms take it up
    rigidly, compliantly, by impact, against a spring, eccentrically, through oil, worn,
    with a dragging idler, biased, slack, magnetic, preloaded, through a flexspline, a rope,
    a spider, a fluid link, a cable, a clutch, a varying mesh, a polymer gear, grease, a
    wedge, an overlapped spool, a side loaded pin, a toggle spring, graded pins, an adhesive
    flank, packed powder, a floating part between two plays, trapped air, a ball detent,
    magnets on the flanks, a play that warms shut, a shear-thickening fluid or an
    eddy-current damper. Here the flanks are lined with a foam that collapses at a plateau
    before it stiffens.
    """
    p = _lugre_params(kin, "backlash (foam_pads)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    half = 0.5 * float(s) ** 2 * FOAM_CLEAR * float(np.ptp(kin.x))
    tf = FOAM_THICK * half
    plat = FOAM_PLAT * float(p.Fc)
    m, kh, ch = _contact_constants(kin, p)
    # the densified pad's steepest stiffness at the bottom strain [N/m]
    kf = plat * (1.0 + FOAM_HARD) * 2.0 * (1.0 - FOAM_DENSE) ** 2 / (
        (1.0 - FOAM_BOTTOM) ** 3 * max(tf, 1e-300))
    rate = max(math.sqrt(max(kh, kf) / m), (float(p.sigma1) + float(p.sigma2) + ch) / m)
    h, xd, n_sub = _substeps(kin, rate)
    Fr = _foam_contact(h, xd, half, tf, plat, kh, ch, m,
                       float(p.sigma0), float(p.sigma1), float(p.sigma2), float(p.Fc),
                       float(p.Fs), float(p.vs), float(p.alpha), SHAPES[p.shape],
                       FOAM_YIELD, FOAM_DENSE, FOAM_HARD, FOAM_BOTTOM)
    return Fr[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: ``buckling_strut``'s share of the friction the shoe carries, at strength 1 (at most 0.95)
#: [-]; its slip travel beyond the base bristle's Fs / sigma0, at strength 1, x the stroke /
#: 3 [-]; the strut's buckling load, x the shoe's sliding force [-], and the travel at
#: which it buckles, x the slip travel [-]
STRUT_SHARE, STRUT_PATH, STRUT_PCR, STRUT_BUCKLE = 0.3, 0.1, 0.7, 0.2


def _strut_force(r, pcr, rb):
    """A slender strut's axial force [-] (over the shoe's sliding force) at the end
    shortenings ``r`` [-] (over the slip travel; its sign the force's): straight, in
    proportion up to its buckling load ``pcr`` at the travel ``rb``; buckled, it carries
    little more as it shortens (its stable post-buckling branch, P = P_cr (1 + D / 2L) in
    the end shortening D beyond buckling, steepened here so the force reaches the shoe's
    sliding force, 1, at the slip travel): elastic both ways, it unloads along the same
    path."""
    r = np.asarray(r, float)
    a = np.abs(r)
    post = pcr + (1.0 - pcr) * (a - rb) / (1.0 - rb)
    return np.sign(r) * np.where(a < rb, pcr * a / rb, post)


@njit(cache=True)
def _strut_travel(x, x_ref):
    """The strut's end shortening [-] (over the slip travel ``x_ref`` [m]) along the
    carriage's positions ``x`` [m], from rest and unstressed: the shoe sticks on the way,
    so the strut is loaded by the carriage's travel, until that travel reaches the slip
    travel (+-1: the strut's force the shoe's sliding force); then the shoe slides and the
    strut stays loaded there."""
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
def buckling_strut_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Part of the contact's friction is carried by a shoe that rides on the way and is
    pushed and pulled along by a slender strut (a thin flexure rod between carriage and
    shoe, pinned at both ends). The shoe sticks on the way and the carriage's travel
    loads the strut: straight, it is stiff; at its buckling load (:data:`STRUT_PCR` x the
    shoe's sliding force, reached at :data:`STRUT_BUCKLE` x the slip travel) it bows
    sideways and carries little more as it shortens further (its post-buckling branch),
    until its force reaches the shoe's sliding force and the shoe slides, at a travel of
    the base bristle's Fs / sigma0 plus ``s`` :data:`STRUT_PATH` x the stroke / 3
    (:func:`_strut_travel`). A reversal unloads the strut along the same elastic path,
    soft first, stiff once straight again (:func:`_strut_force`; a pinned strut buckles
    the same way under tension's opposite, so the law is odd). The shoe carries the share
    w = ``s`` :data:`STRUT_SHARE` of the Coulomb level, w Fc f; the contact the rest, the
    base's LuGre with its curve less w Fc (its viscous term whole). At ``s`` = 0 the base
    itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the shoe's share of the friction (up to ``s`` = 0.95 /
        :data:`STRUT_SHARE`) and its slip travel (as the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The Euler buckling of a pinned strut and its stable post-buckling branch, on which the
    load rises only slowly with the end shortening (Timoshenko and Gere 1961, Theory of
    Elastic Stability, ch. 2 on the elastica; Bazant and Cedolin 1991, Stability of
    Structures, ch. on post-critical behaviour), as used in buckled-beam force limiters and
    constant-force mechanisms, and friction shoes held on flexures beside a contact. The
    candidate's presliding is a generalized Maxwell-slip (GMS) element set; the open forms
    are Maxwell-slip sets, Dahl, elasto-plastic, Bliman-Sorine, Bouc-Wen, Zener junctions,
    Mindlin contacts, rate-and-state, Tomlinson asperities, bond rupture, gouge, kinematic
    hardening, interlocking, capillary bridges, cyclic hardening, peeling, unloading
    microslip, a power-law joint, junction growth, avalanches, slip weakening, a microslip
    bar, contact renewal, grease's yield, a superelastic flexure, an Eyring film, a
    viscoplastic layer, a poroelastic one, a confined film that melts, a hysteresis brake, a
    fibre wiper, a band on a drum, a spring's rubbing leaves or an air cylinder's spring,
    each beside the contact, or a stiffening wire mesh in series with it. Here the spring
    that holds a sticking shoe softens where it buckles, and recovers elastically.
    """
    _lugre_params(kin, "gms (buckling_strut)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    law = kin.base
    w = min(float(s) * STRUT_SHARE, 0.95)
    wf = w * _level(kin)
    e0, extra = _presliding_path(kin, s, STRUT_PATH)
    r = _strut_travel(np.asarray(kin.x, float), e0 + extra)
    f = _strut_force(r, STRUT_PCR, STRUT_BUCKLE)
    rest = lugre_with_curve(kin, lambda vv: law.g(vv) - wf)
    return rest + wf * f
