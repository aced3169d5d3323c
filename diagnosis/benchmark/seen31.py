"""The thirty-first seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-12-01 (session 35) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 36 (2026-12-01) on the code of df1f691 (the
diagnosis code of 8f48865): 176 cases, 0 skipped, 890 s wall on 2 workers (CI ran beside
it). Top-1 59.7 % (105; 62.5 % of the 168 detectable; of the 8 undetectable, 6 are delays
below their practical size (5 of them named unexplained, 1 none), 2 stribeck_shape cases
(none)); mean |shrink error| 0.242 (0.246 over the detectable, 0.160 over the right ones);
wrong names on 21 (11.9 %): asymmetry -> stribeck_shape 4, drift -> load 4,
acceleration -> position 4, backlash -> gms 3, gms -> delay 2, load -> delay 2,
load -> gms 2. By form: load/wheel_sinkage 16/20 (delay 2, gms 2), asymmetry/cup_paddle
16/20 (stribeck_shape 4), drift/frost_layer 16/20 (load 4), gms/band_brake 8/12
(unexplained 2, delay 2), acceleration/slack_belt 12/20 (unexplained 4, position 4),
inertia/magnet_spring 12/20 (unexplained 5, none 3), delay/disturbance_observer 11/20
(unexplained 8, none 1), position/rack_mesh 8/16 (unexplained 8),
stribeck_shape/measuring_wheel 4/16 (none 8, unexplained 4), backlash/warming_fit 2/12
(unexplained 7, gms 3). By plant: valve 77.5 %, XML-350 72.5 %, damping rig 50.0 %,
isolator 50.0 %, forging press 39.3 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen30` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen30`,
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
acceleration       ``slack_belt``: the carriage is driven by a pretensioned belt; the
                   belt's two strands share the drive force while both are taut, and
                   the pulleys' bearings carry a constant load, but beyond twice the
                   pretension the slack strand goes slack and the hub load grows with
                   the force: levels that rise with hard accelerations past a knee
load               ``wheel_sinkage``: the carriage rides on wheels on a soft, plastically
                   compacting track; the compaction resistance of a sinking wheel grows
                   as a power 3/2 of its load (Bekker): levels that follow the load
                   more than in proportion
asymmetry          ``cup_paddle``: an arm of the carriage drags a cup-shaped paddle (a
                   level sensor's float cup, a coolant scoop) through a liquid: its
                   drag coefficient is that of a hollow cup one way (concave side
                   first) and of a round back the other, a quadratic drag that differs
                   by direction
stribeck_shape     ``measuring_wheel``: a rubber-tyred measuring wheel pressed on the
                   carriage drives a tachogenerator; the generator's drag grows with the
                   wheel's speed until the tyre's creep force saturates at its
                   adhesion limit (Carter's creep curve): an added friction that grows
                   with the speed and levels off, rounded by the creep
position           ``rack_mesh``: the axis is driven by a rack and pinion; the flanks'
                   sliding grows with the contact's distance from the pitch point, and
                   the load passes between one and two pairs of teeth: a mesh friction
                   that repeats with each tooth of the rack along the stroke
inertia            ``magnet_spring``: the carriage carries a payload levitated between
                   repelling permanent magnets and damped by eddy currents in a copper
                   plate: a hardening inverse-square spring that transmits the payload's
                   inertia with a lag and a swing
delay              ``disturbance_observer``: the force is not measured but estimated
                   from the drive's current and the motion by a disturbance observer
                   whose Q-filter is a third-order binomial low-pass: the estimate lags
                   the force by the Q-filter's group delay
drift              ``frost_layer``: the contact runs cold in humid air; frost deposits
                   on its faces and thickens as the root of the time (diffusion-limited
                   growth), and its crystals, crushed and ploughed in the contact, raise
                   the friction as it grows
backlash           ``warming_fit``: a gear play that shrinks as the gears warm with the
                   friction power faster than the housing that sets their centres:
                   across the play the contact stands still, and the play closes by a
                   lag of the dissipated power
gms                ``band_brake``: part of the friction is carried by a band wrapped
                   round a drum beside the contact; before the band slips as a whole its
                   slip arc spreads from the tight end (Euler-Eytelwein with the band's
                   elasticity): a presliding force of the root of the displacement at
                   first, reversed by Masing's rule; at ``s`` = 0 the base
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``measuring_wheel``
needs a Stribeck curve (not the isolator's mre_lugre), ``rack_mesh`` a record that
revisits its positions (not the press), ``wheel_sinkage`` a load that changes,
``warming_fit`` and ``band_brake`` a classic LuGre base (valve, damping rig, XML-350);
each raises a ``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.shapes import SHAPES

from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _lag, _level,
                     _light_contact_step, _lugre_params, _motion_time, _presliding_path,
                     _smooth_max0, _substeps, has_stribeck_curve, level_inside,
                     lugre_with_curve, on_fine_grid)

__all__ = ["FORMS", "slack_belt_truth", "wheel_sinkage_truth", "cup_paddle_truth",
           "measuring_wheel_truth", "rack_mesh_truth", "magnet_spring_truth",
           "disturbance_observer_truth", "frost_layer_truth", "warming_fit_truth",
           "band_brake_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "slack_belt", "load": "wheel_sinkage",
         "asymmetry": "cup_paddle", "stribeck_shape": "measuring_wheel",
         "position": "rack_mesh", "inertia": "magnet_spring",
         "delay": "disturbance_observer", "drift": "frost_layer",
         "backlash": "warming_fit", "gms": "band_brake"}


# -- acceleration ----------------------------------------------------------------------------
#: ``slack_belt``'s rise of the levels per unit of the hub's extra load over its 99th
#: percentile along the record, at strength 1 [-]; the quantile of the record's |a| at
#: which the slack strand goes slack (twice the pretension) [-]; the rounding of the
#: strand's going slack and the drive's peak force (its current limit), x the inertial
#: force at the top acceleration [-]
BELT_RISE, BELT_KNEE, BELT_ROUND, BELT_PEAK = 0.5, 0.7, 0.03, 1.5


def _hub_extra(u, pre, rnd):
    """The pulleys' extra hub load [-] (over the inertial force at the top acceleration) at
    the drive forces ``u`` [-] (the same scale): while both strands are taut they carry
    ``pre`` + u / 2 and ``pre`` - u / 2, whose sum is constant; once |u| exceeds 2 ``pre``
    the slack strand carries nothing and the tight one |u|, so the hub carries
    |u| - 2 ``pre`` more, rounded over ``rnd`` (the strand's sag)."""
    return _smooth_max0(np.abs(np.asarray(u, float)) - 2.0 * pre, rnd)


@on_fine_grid
def slack_belt_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage is driven by a pretensioned belt (a toothed or flat belt over two
    pulleys, as on linear belt axes and gantries). The belt's force is the carriage's inertial
    force (m a; the friction's share is small next to it at hard accelerations). While
    both strands are taut they share it about the pretension (half the inertial force at
    the record's :data:`BELT_KNEE` quantile of |a|) and the pulleys' bearings carry a
    constant load; past twice the pretension the slack strand goes slack and the hub
    load grows with the force (:func:`_hub_extra`), and with it the friction of the
    pulleys' bearings and of the belt's wrap; the belt never carries more than the
    drive's peak force, :data:`BELT_PEAK` x the inertial force at the top acceleration
    (its current limit: the press's impacts are taken by its frame, not its drive). The
    Coulomb and Stribeck levels are the base's times 1 + ``s`` :data:`BELT_RISE` x that
    extra load over its 99th percentile along the record, inside the bristle dynamics;
    the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the bearings' friction per unit of hub load, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Belt drives' strand tensions, the slack side's going slack and the shaft (hub) load
    (Johnson 1985, Contact Mechanics, ch. on belts; Childs 2014, Mechanical Design
    Engineering Handbook, ch. on belt and chain drives: initial tension and shaft load;
    Harris and Kotzalas 2007, Rolling Bearing Analysis, ch. on the load-dependent friction
    torque). The candidate raises the levels with |a|, lagged, tilts them with a and adds a
    force odd in a; the open forms lag, age, heat, skid, load, press, attract, squeeze,
    transfer weight, slosh, dilate, wedge, spring a gib, soften rubber, swing arms, unload
    by the jerk, tilt pads, push ball trains, ripple the current, slide rack flanks, set a
    shoe, shut a damper's bypass, creep a belt, rack a gantry, tighten a band, surge a feed
    line, load a traction drive, heat a winding, unload a counterweight's rope or pump oil.
    Here a belt's strand goes slack: nothing until the force passes twice the pretension,
    then a hub load that grows with it.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    u = np.clip(np.asarray(kin.a, float) / a99, -BELT_PEAK, BELT_PEAK)
    pre = 0.5 * float(np.quantile(np.abs(u), BELT_KNEE))
    e = _hub_extra(u, pre, BELT_ROUND)
    e = e / max(float(np.percentile(e, 99)), 1e-12)
    lev = 1.0 + float(s) * BELT_RISE * e
    return level_inside(kin, lev, np.ones_like(lev))


# -- load ------------------------------------------------------------------------------------
#: ``wheel_sinkage``'s change of the levels per unit of the compaction's excess over the
#: proportional, at strength 1 [-]; the track's sinkage exponent n (Bekker's) [-]
SINK_RISE, SINK_N = 0.6, 0.5


def _compaction(w, n):
    """A rigid wheel's compaction resistance [-] at the loads ``w`` [-] (over the mean):
    Bekker's w^((2n + 2) / (2n + 1)) on a track whose pressure grows as the sinkage^n."""
    return np.abs(np.asarray(w, float)) ** ((2.0 * n + 2.0) / (2.0 * n + 1.0))


@on_fine_grid
def wheel_sinkage_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage rides on rigid wheels over a soft track that the wheels compact
    plastically (a test carriage on a sand or cinder bed, a trolley on a soft polymer or
    a felt-lined track). A wheel sinks until the track's pressure, growing as a power
    :data:`SINK_N` of the sinkage, carries its load, and the work of compacting the rut
    is a rolling resistance of the power (2n + 2) / (2n + 1) of the load (3/2 for n =
    1/2; :func:`_compaction`). The Coulomb and Stribeck levels are the base's times 1 +
    ``s`` :data:`SINK_RISE` x (that resistance - the load), both over their means along
    the record, inside the bristle dynamics: the part that grows more than in proportion
    to the load; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (load [N]) and its base law.
    s : float
        Amplitude factor [-]: the compaction's share in the friction, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Terramechanics: pressure-sinkage and the compaction resistance of rigid wheels (Bekker
    1969, Introduction to Terrain-Vehicle Systems, ch. on the motion resistance of rigid
    wheels; Wong 2008, Theory of Ground Vehicles, ch. on the mechanics of vehicle-terrain
    interaction). The candidate makes the levels affine in the load, with a memory over the
    travel; the open forms scale the friction with a Hertz contact's area, a seal's, a
    film's, a junction's, a pivot's, an adhesive contact's or a pin's arc, break, squeeze
    or desorb films, plough, creep, vibrate, overload or feed a constant flow to a pad,
    heal scuffs, relieve a preload, roll on a lossy track, slip differentially, spin
    balls, press a disc spring, skid lightly loaded rollers, bed a rail, heat a liner by
    PV, shear a soft film under pressure, pass the load through a clamp's seal or load
    crowned rollers' ends. Here a wheel sinks into a plastically compacting track.
    """
    L = np.abs(np.asarray(kin.load, float))
    Lm = float(np.mean(L)) or 1.0
    if not np.ptp(L) > 1e-9 * Lm:
        raise ValueError(f"load (wheel_sinkage): the {kin.plant} record's load does not "
                         f"change")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    w = L / Lm
    c = _compaction(w, SINK_N)
    e = c / float(np.mean(c)) - w
    e = e / max(float(np.max(np.abs(e))), 1e-12)
    lev = np.maximum(1.0 + float(s) * SINK_RISE * e, 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``cup_paddle``'s drag at the top speed, concave side first, x the friction level, at
#: strength 1 [-]; the cup's drag coefficients concave side first and round back first [-]
CUP_FORCE, CUP_CD_OPEN, CUP_CD_BACK = 0.5, 1.42, 0.38


def _cup_drag(u, cd_open, cd_back):
    """The cup's drag [-] (over its value at the top speed, open side first) at the speeds
    ``u`` [-] (over the top speed): a quadratic drag, u |u|, whose coefficient is
    ``cd_open`` moving +x (the hollow meets the liquid) and ``cd_back`` moving -x."""
    u = np.asarray(u, float)
    return np.where(u >= 0.0, cd_open, cd_back) * u * np.abs(u) / cd_open


@on_fine_grid
def cup_paddle_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """An arm of the carriage drags a hemispherical cup (a float cup of a level switch, a
    coolant scoop, a stirring cup) through a liquid. Its drag is quadratic in the speed,
    with the coefficient of a hollow hemisphere, :data:`CUP_CD_OPEN`, when its open side
    leads (+x) and of a round back, :data:`CUP_CD_BACK`, the other way (the cup
    anemometer's principle; :func:`_cup_drag`). The truth adds ``s`` :data:`CUP_FORCE` x
    the friction level x that drag (1 at the top speed moving +x) to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the cup's area x the liquid's density, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Drag of hollow and solid hemispheres by their orientation (Hoerner 1965, Fluid-Dynamic
    Drag, ch. on three-dimensional bodies; White 2011, Fluid Mechanics, table of drag
    coefficients; the cup anemometer, Robinson 1846 and Kristensen 1998, Cup anemometer
    behavior in turbulent environments, J. Atmos. Ocean. Technol. 15). The candidate gives
    each direction its levels and an offset; the open forms twin the levels, the curves or
    the viscous term, bend a curve, roll a lip, load a thrust bearing, film a rod seal,
    texture a ratchet, return a spring, tilt a pad, strut a sprag, throttle a meter-out,
    differ a cylinder's areas, groove chevrons, buckle a helix, scrape chips, commutate,
    idle a belt, free a roller, wick a felt, run a belt, lean a brush, band a seal,
    counterbalance a valve, vibrate elliptically, diode a flow, pitch pads, skew rollers,
    lift through a screw, turn the frame, angle a pull, adhere by wedges or charge through
    a diode. Here a body's shape makes an outer flow's drag differ by direction.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    d = _cup_drag(np.asarray(kin.v, float) / v99, CUP_CD_OPEN, CUP_CD_BACK)
    return F + float(s) * CUP_FORCE * _level(kin) * d


# -- stribeck_shape --------------------------------------------------------------------------
#: ``measuring_wheel``'s creep force at the tyre's adhesion limit, x the Coulomb level, at
#: strength 1 [-]; the speed at which the generator's drag reaches that limit with no
#: creep, x the top speed [-]; the creepage at which the tyre slides as a whole [-]
WHEEL_LIMIT, WHEEL_SPEED, WHEEL_CREEP = 0.5, 0.3, 0.3


def _creep_force(b, creep):
    """The wheel's creep force [-] (over the adhesion limit) at the drags ``b`` [-] (the
    generator's drag at no creep over the adhesion limit, ~ the speed): Carter's creep
    curve f = 2 y - y^2 (y the creepage over ``creep``, the creepage at full slip) balances
    the generator's drag at the wheel's speed, b (1 - ``creep`` y), so y is the smaller
    root of y^2 - (2 + b ``creep``) y + b = 0; past y = 1 the tyre slides, f = 1."""
    b = np.abs(np.asarray(b, float))
    p = 2.0 + b * creep
    disc = np.maximum(p * p - 4.0 * b, 0.0)
    y = np.minimum(0.5 * (p - np.sqrt(disc)), 1.0)
    y = np.where(b * (1.0 - creep) >= 1.0, 1.0, y)
    return 2.0 * y - y * y


@on_fine_grid
def measuring_wheel_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A rubber-tyred measuring wheel is pressed on the carriage (a length-measuring wheel
    or a speed pick-up wheel) and drives a tachogenerator, whose drag grows in proportion
    to the wheel's speed. The tyre passes that drag on by creep: its tangential force
    follows Carter's creep curve of the creepage (:func:`_creep_force`), so the wheel turns
    a little slower than the carriage, and beyond the tyre's adhesion limit it slides as a
    whole. The carriage feels the drag: it grows with the speed at low speeds and levels
    off at the limit (``s`` :data:`WHEEL_LIMIT` x the Coulomb level), the corner rounded by
    the creep; reached at about :data:`WHEEL_SPEED` x the top speed. The truth's Stribeck
    curve is the base's plus that drag, inside the bristle dynamics.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (with a Stribeck curve).
    s : float
        Amplitude factor [-]: the wheel's pressing force, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Rolling contact creep and its saturation (Carter 1926, On the action of a locomotive
    driving wheel, Proc. R. Soc. A 112; Johnson 1985, Contact Mechanics, ch. on rolling
    contact of elastic bodies; Kalker 1990, Three-Dimensional Elastic Bodies in Rolling
    Contact) and the drag of a tachogenerator (Hughes and Drury 2013, Electric Motors and
    Drives, ch. on d.c. machines). The candidate's curve is Gaussian, Lorentzian or an
    exponential tail; the open forms add tails, rationals, films that lift, spikes,
    bimodal roughness, logs, Eyring, starvation, rubber hysteresis, resonances, dither,
    melting, grains, readsorption, thermoviscous, turbulent and thixotropic films,
    churning, core losses, breathing bellows, eddy brakes, shear thinning, flying pads,
    wiping menisci, journals, wall slip, a closing clearance, a dwell's squeeze, a
    pocket's suction, condensing menisci, flash heating or a peeled adhesion. Here a
    rolling tyre's creep passes on a drag that grows with the speed until the tyre slides.
    """
    law = kin.base
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (measuring_wheel): the mre_lugre base has no "
                         "Stribeck curve")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    vw = WHEEL_SPEED * max(kin.scales["v99"], 1e-12)
    add = float(s) * WHEEL_LIMIT * _level(kin)
    return lugre_with_curve(kin, lambda vv: law.g(vv) + add * _creep_force(vv / vw,
                                                                            WHEEL_CREEP))


# -- position --------------------------------------------------------------------------------
#: ``rack_mesh``'s largest change of the levels through a tooth's mesh, at strength 1 [-];
#: the rack's pitch, x the visited stroke [-]; the mesh's contact ratio [-]
RACK_RISE, RACK_PITCH, RACK_RATIO = 0.25, 0.08, 1.6


def _mesh_sliding(phase, ratio):
    """The mesh's sliding friction [-] (1 at a tooth's entry or exit alone) at the mesh
    phases ``phase`` [-] (in pitches): each pair of teeth is in mesh over ``ratio``
    pitches, its flanks sliding in proportion to the contact's distance from the pitch
    point, |psi - ratio / 2| / (ratio / 2); where two pairs mesh they share the load."""
    ph = np.mod(np.asarray(phase, float), 1.0)
    half = 0.5 * ratio
    first = np.abs(ph - half) / half                 # the pair that entered at phase 0
    second = np.abs(ph + 1.0 - half) / half          # the one that entered a pitch before
    two = ph + 1.0 < ratio
    return np.where(two, 0.5 * (first + second), first)


@on_fine_grid
def rack_mesh_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The axis is driven by a rack and pinion. Through each tooth's mesh the flanks roll
    at the pitch point and slide elsewhere, the sliding growing with the contact's distance
    from it, and the load passes between one pair of teeth and two (a contact ratio of
    :data:`RACK_RATIO`; :func:`_mesh_sliding`): the mesh's friction repeats with each of
    the rack's teeth (a pitch of :data:`RACK_PITCH` x the visited stroke). The Coulomb and
    Stribeck levels are the base's times 1 + ``s`` :data:`RACK_RISE` x that friction's
    departure from its mean over a pitch, over its largest, inside the bristle dynamics;
    the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the flanks' friction coefficient, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Sliding between gear flanks along the line of action, the load sharing of the contact
    ratio and the mesh's friction losses (Buckingham 1949, Analytical Mechanics of Gears,
    ch. on sliding and efficiency; Niemann and Winter 1983, Maschinenelemente II, ch. on
    gear losses; Velex and Ville 2009, An analytical approach to tooth friction losses in
    spur and helical gears, J. Mech. Des. 131). The candidate scales the friction along the
    stroke and adds a force of the position; the open forms put defects, waviness, wear,
    runout, bends, films, cogging, tapers, pockets, cushions, covers, springs, holes,
    plungers, sags, festoons, curves, chains, cams, heat, dents, joints, misalignment, flow
    forces, cranks, overhangs, a track's end, a reel, a way's flatness, conductive strips,
    a guide's ball passage, a steel insert or a screw's lead error on the stroke. Here the
    teeth's flanks slide through each mesh and the load passes between pairs.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (rack_mesh): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    span = max(sc["x_hi"] - sc["x_lo"], 1e-12)
    xr = (np.asarray(kin.x, float) - sc["x_lo"]) / span
    f = _mesh_sliding(xr / RACK_PITCH, RACK_RATIO)
    p = f - float(np.mean(_mesh_sliding(np.linspace(0.0, 1.0, 1001), RACK_RATIO)))
    p = p / max(float(np.max(np.abs(p))), 1e-12)
    lev = np.maximum(1.0 + float(s) * RACK_RISE * p, 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- inertia ---------------------------------------------------------------------------------
#: ``magnet_spring``'s payload mass at strength 1, x the friction level / a99 [kg per N
#: s^2/m]; the payload's period on the magnets' small-motion stiffness, x the motion's time
#: scale [-]; the eddy currents' damping ratio [-]; the magnets' gap, x a99 / omega^2 [-]
MS_MASS, MS_PERIOD, MS_DAMP, MS_GAP = 0.5, 1.5, 0.15, 1.2


@njit(cache=True)
def _magnet_gap_force(q):
    """The repelling magnets' restoring force [-] at the payload's offset ``q`` [-] (over
    the gap at rest): two opposed pairs each repelling as the inverse square of their gap,
    (1 / (1 - q)^2 - 1 / (1 + q)^2) / 4, of unit slope at q = 0 and hardening towards the
    magnets (the offset kept within 0.95 of the gap)."""
    qq = min(max(q, -0.95), 0.95)
    return 0.25 * (1.0 / (1.0 - qq) ** 2 - 1.0 / (1.0 + qq) ** 2)


@njit(cache=True)
def _levitated_payload(t, a, omega, zeta, gap):
    """The acceleration [m/s^2] of a payload relative to the carriage, which accelerates by
    ``a`` [m/s^2] at the times ``t`` [s] (uniform), from rest: u'' = -a - omega^2 ``gap``
    f(u / ``gap``) - 2 ``zeta`` omega u' (:func:`_magnet_gap_force`, the eddy currents'
    damping); semi-implicit Euler on sub-steps of at most 0.02 / omega, the carriage's
    acceleration held over each."""
    n = t.size
    out = np.empty(n)
    dt = t[1] - t[0] if n > 1 else 0.0
    n_sub = max(1, int(math.ceil(omega * dt / 0.02)))
    h = dt / n_sub
    u = 0.0
    w = 0.0
    for k in range(n):
        out[k] = -a[k] - omega * omega * gap * _magnet_gap_force(u / gap) \
            - 2.0 * zeta * omega * w
        if k + 1 < n:
            am = 0.5 * (a[k] + a[k + 1])
            for _ in range(n_sub):
                w = w + h * (-am - omega * omega * gap * _magnet_gap_force(u / gap)
                             - 2.0 * zeta * omega * w)
                u = u + h * w
    return out


@on_fine_grid
def magnet_spring_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage carries a payload levitated between repelling permanent magnets (a
    magnetic spring, as in magnetic vibration isolators and levitated sensor masses) and
    damped by the eddy currents a magnet induces in a copper plate. Each opposed pair
    repels as the inverse square of its gap, so the spring hardens as the payload nears a
    magnet (:func:`_magnet_gap_force`; the gap :data:`MS_GAP` x a99 / omega^2, the
    small-motion period :data:`MS_PERIOD` x the motion's time scale, a damping ratio
    :data:`MS_DAMP`; :func:`_levitated_payload`). The carriage pushes the payload through
    the spring and the damper: the truth adds the payload's mass (``s`` :data:`MS_MASS` x
    the friction level / a99) times its own acceleration, the carriage's plus its relative
    one, to the base.

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
    Forces between permanent magnets and magnetic springs (Furlani 2001, Permanent Magnet
    and Electromechanical Devices, ch. on the force between magnets; Robertson, Cazzolato
    and Zander 2011, A multipole array magnetic spring, IEEE Trans. Magn. 41) and eddy
    current damping (Sodano, Bae, Inman and Belvin 2006, Improved concept and model of
    eddy current damper, J. Vib. Acoust. 128). The candidate misses a constant mass; the
    open forms filter it, reflect it through gearing, a chain, a pinion or a screw, hang it
    on a spring, a cable, a fluid, a clutch, a coupling, a flyweight, a friction-damped,
    quasi-zero-stiffness, hose's or elastomer mount, surge a spring, add a fluid's mass,
    pick, drop, empty, slide, rattle, telescope, roll or rock it, recoil a frame, saturate
    a motor, lead a feedforward, pitch a scale, radiate waves, swing it on a rod, slide it
    in a dish or swing a liquid in a tube. Here it floats on the repulsion of magnets, a
    spring that hardens as the inverse square of the gap.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    m = float(s) * MS_MASS * _level(kin) / a99
    omega = 2.0 * math.pi / (MS_PERIOD * max(_motion_time(kin), 1e-12))
    gap = MS_GAP * a99 / (omega * omega)
    a = np.asarray(kin.a, float)
    ur = _levitated_payload(np.asarray(kin.t, float), a, omega, MS_DAMP, gap)
    return F + m * (a + ur)


# -- delay -----------------------------------------------------------------------------------
#: ``disturbance_observer``'s Q-filter group delay at strength 1 [data samples]; its order
#: (a binomial low-pass) [-]
DOB_SAMPLES, DOB_ORDER = 2.0, 3


def _binomial_q(t, u, tau, order):
    """The Q-filter 1 / (tau s + 1)^``order`` of a disturbance observer applied to ``u``
    [N] at the times ``t`` [s] (uniform): ``order`` first-order lags of ``tau`` [s] in
    cascade (each exact for a piecewise-linear input), from rest at the first value."""
    y = np.asarray(u, float)
    for _ in range(int(order)):
        y = _lag(t, y, tau)
    return y


@on_fine_grid
def disturbance_observer_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is not measured but estimated, as in sensorless drives: a disturbance
    observer takes the drive's force (its current times the force constant) less the
    nominal mass times the acceleration and passes the difference through its Q-filter, a
    binomial low-pass of order :data:`DOB_ORDER` whose time constant sets a group delay of
    ``s`` :data:`DOB_SAMPLES` data samples (:func:`_binomial_q`). With the nominal model
    right, the estimate is the friction force through the Q-filter: it lags the force,
    rounds its steps and settles on them. The motion channels are on time.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the Q-filter's time constant, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Disturbance observers and their Q-filters (Ohnishi, Shibata and Murakami 1996, Motion
    control for advanced mechatronics, IEEE/ASME Trans. Mechatronics 1; Umeno and Hori
    1991, Robust speed control of DC servomotors using modern two degrees-of-freedom
    controller design, IEEE Trans. Ind. Electron. 38; Sariyildiz, Oboe and Ohnishi 2020,
    Disturbance observer-based robust control and its applications: 35th anniversary
    overview, IEEE Trans. Ind. Electron. 67) and friction estimated by them. The candidate
    shifts the force in time or lags it through a first-order filter; the open forms
    delay, filter, average, stamp, decimate, hold, skew, jitter, limit the slew, pipe, take
    medians, report on a dead band, sample positions, run a belt, aerate, drop telegrams,
    leak, creep, notch, track, snub, time a waveguide's pulse, diffuse eddy currents, count
    a resonator, sweep a grating, restore a force by a servo, interleave converters,
    balance a pneumatic cell, count out a dual slope, adapt a filter's time constant, round
    in integer arithmetic or fit a polynomial. Here no sensor reads the force: an observer
    estimates it from the drive and the motion.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    tau = float(s) * DOB_SAMPLES * kin.sample_dt / DOB_ORDER
    return _binomial_q(np.asarray(kin.t, float), F, tau, DOB_ORDER)


# -- drift -----------------------------------------------------------------------------------
#: ``frost_layer``'s rise of the levels with the frost of the record's end, at strength 1 [-]
FROST_RISE = 0.4


def _frost_thickness(tr):
    """The frost's thickness [-] (over that at the record's end) at the times ``tr`` [-]
    (over the record's): diffusion-limited deposition on a cold face, tr^(1/2)."""
    return np.sqrt(np.maximum(np.asarray(tr, float), 0.0))


@on_fine_grid
def frost_layer_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The contact runs below the dew and freezing points in humid air (a cold stage, a
    freezer's conveyor, a refrigerated test rig). Water vapour diffuses to the cold faces
    and deposits as frost, whose layer thickens as the square root of the time
    (:func:`_frost_thickness`); its crystals, crushed and ploughed between the sliding
    faces, raise the friction as the layer grows. The Coulomb and Stribeck levels are the
    base's times 1 + ``s`` :data:`FROST_RISE` x the thickness over the record's end's,
    inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the air's humidity, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Frost formation on cold surfaces and its growth (Hayashi, Aoki, Adachi and Hori 1977,
    Study of frost properties correlating with frost formation types, J. Heat Transfer 99;
    Iragorry, Tao and Jia 2004, A critical review of properties and models for frost
    formation analysis, HVAC&R Res. 10) and the friction of snow and frost layers (Colbeck
    1992, A review of the processes that control snow friction, CRREL Monograph 92-2). The
    candidate is a trend, a saturating change, a step, a cycle, a resetting change or the
    friction power's heat; the open forms warm up, wear in, change, heat, wear, follow the
    humidity, grind, relubricate, relax, oxidise, deplete, wear through, swell, build
    films, take in particles, expand, shear down, heat magnets, charge, creep, loosen,
    dewet, channel, drain, spall, evaporate, pump down, settle an additive, crystallise
    wax, bleed a grease's oil, cycle a thermostat, glaze a lining or form a tribolayer.
    Here a deposit from the air grows on the cold faces as the root of the time.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    tr = (t - t[0]) / max(float(t[-1] - t[0]), 1e-300)
    lev = 1.0 + float(s) * FROST_RISE * _frost_thickness(tr)
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: ``warming_fit``'s cold play at strength 1, as a share of the stroke (its full width) [-];
#: the share of the play the warm gears close at the record's largest heat [-]; the gears'
#: warming time over the housing's, x the record's duration [-]
WARM_CLEAR, WARM_CLOSE, WARM_TIME = 0.005, 0.6, 0.3


def _closure(t, power, tau):
    """The share [-] of its largest along the record by which the gears' warming closes
    the play at the times ``t`` [s]: the friction power ``power`` [W] through a first-order
    thermal lag of ``tau`` [s] (the gears' heat capacity over their cooling), from cold."""
    from scipy.signal import lfilter
    t = np.asarray(t, float)
    e = math.exp(-float(t[1] - t[0]) / tau)
    w = lfilter([1.0 - e], [1.0, -e], np.asarray(power, float))   # from cold: no heat yet
    return np.maximum(w, 0.0) / max(float(np.max(w)), 1e-300)


@njit(cache=True)
def _warming_contact(h, xd, half, kh, ch, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a light contact of mass ``m`` [kg] driven by the drive positions
    ``xd`` [m] (steps ``h`` [s]) through a play of half-width ``half`` [m] (an array, one a
    step) closed at the flanks by a spring ``kh`` [N/m] and damper ``ch`` [N s/m]
    (compressive only), nothing across it; from rest, the drive in the play's middle.
    Semi-implicit Euler of the contact, its bristle exact."""
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
        if e > half[j]:
            f2 = kh * (e - half[j]) + ch * ed
            if f2 > 0.0:
                fc = f2
        elif e < -half[j]:
            f2 = kh * (e + half[j]) + ch * ed
            if f2 < 0.0:
                fc = f2
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha,
                                         shape)
        x = x + h * v
    return F


@on_fine_grid
def warming_fit_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact are joined by a gear pair whose play, cold ``s``^2
    :data:`WARM_CLEAR` x the stroke, closes as the gears warm: the mesh's and the
    bearings' friction power heats the gears faster than the housing that sets their
    centre distance, and the teeth's expansion takes up part of the play. The closure
    follows the base's friction power |F v| through the gears' thermal lag
    (:data:`WARM_TIME` x the record's duration), and closes :data:`WARM_CLOSE` of the
    play at its largest along the record (:func:`_closure`). Across the play nothing
    drives the contact, which stands still; the flanks then take the drive up
    (:func:`_warming_contact`). The contact is light (its inertial force at the top
    acceleration 1 % of the Coulomb level) with the base's LuGre friction.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m], v [m/s]) and its base law (a classic
        LuGre).
    s : float
        Amplitude factor [-]: the square root of the cold play's width (as the open
        plays'), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Operating backlash and its loss to the gears' thermal expansion (AGMA 2002-B88, Tooth
    thickness specification and measurement, the operating backlash; Dudley 1984, Handbook
    of Practical Gear Design, ch. on backlash and the temperature difference between gears
    and housing) and lost motion in mechanisms (Nordin and Gutman 2002, Controlling
    mechanical systems with backlash - a survey, Automatica 38). The candidate holds or
    frees the contact across a rigid play; the open forms take it up rigidly, compliantly,
    by impact, against a spring, eccentrically, through oil, worn, with a dragging idler,
    biased, slack, magnetic, preloaded, through a flexspline, a rope, a spider, a fluid
    link, a cable, a clutch, a varying mesh, a polymer gear, grease, a wedge, an overlapped
    spool, a side loaded pin, a toggle spring, graded pins, an adhesive flank, packed
    powder, a floating part between two plays, trapped air, a ball detent or magnets on
    the flanks. Here the play narrows with the heat the friction puts into the gears.
    """
    p = _lugre_params(kin, "backlash (warming_fit)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    half0 = 0.5 * float(s) ** 2 * WARM_CLEAR * float(np.ptp(kin.x))
    tau = WARM_TIME * max(float(t[-1] - t[0]), 1e-12)
    c = _closure(t, np.abs(F * np.asarray(kin.v, float)), tau)
    m, kh, ch = _contact_constants(kin, p)
    rate = max(math.sqrt(kh / m), (float(p.sigma1) + float(p.sigma2) + ch) / m)
    h, xd, n_sub = _substeps(kin, rate)
    t2 = t[0] + h * np.arange(xd.size)
    half = half0 * (1.0 - WARM_CLOSE * np.interp(t2, t, c))
    Fr = _warming_contact(h, xd, half, kh, ch, m,
                          float(p.sigma0), float(p.sigma1), float(p.sigma2), float(p.Fc),
                          float(p.Fs), float(p.vs), float(p.alpha), SHAPES[p.shape])
    return Fr[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: ``band_brake``'s share of the friction the band carries, at strength 1 (at most 0.95)
#: [-]; its slip displacement beyond the base bristle's Fs / sigma0, at strength 1, x the
#: stroke / 3 [-]; the band's friction coefficient times its wrap angle [-]
BAND_SHARE, BAND_PATH, BAND_MU_WRAP = 0.4, 0.1, 1.0


def _band_backbone(n=401, mu_wrap=BAND_MU_WRAP):
    """The band's first loading curve as a table: (displacements [-], forces [-]), both
    over their values at gross slip. With the tension ratio r from 1 to e^``mu_wrap``
    (Euler-Eytelwein over the slip arc), the force is (r - 1) / (e^mu_wrap - 1) and the
    band's elastic stretch over the slip arc (r - 1 - ln r) / (e^mu_wrap - 1 - mu_wrap)."""
    rmax = math.exp(mu_wrap)
    r = 1.0 + (rmax - 1.0) * np.linspace(0.0, 1.0, n) ** 2
    x = (r - 1.0 - np.log(r)) / (rmax - 1.0 - mu_wrap)
    f = (r - 1.0) / (rmax - 1.0)
    return x, f


@njit(cache=True)
def _masing_band(x, x_ref, tab_x, tab_f):
    """The band's force [-] (+-1 at gross slip) along the positions ``x`` [m], from rest:
    the first loading follows the backbone h (the table ``tab_x``, ``tab_f``) of the
    displacement d from the start over ``x_ref`` [m], sign(d) h(|d| / ``x_ref``); after
    each reversal (at (x_r, f_r)) the branch is Masing's, f = f_r + 2 h((x - x_r) /
    2) (the backbone doubled), capped at gross slip (+-1)."""
    n = x.size
    out = np.empty(n)
    f = 0.0
    fr = 0.0
    xr = x[0] if n > 0 else 0.0
    d = 0.0
    first = True
    for k in range(n):
        if k > 0:
            dx = x[k] - x[k - 1]
            if dx != 0.0:
                sg = 1.0 if dx > 0.0 else -1.0
                if sg != d:
                    if d != 0.0:
                        first = False
                    xr = x[k - 1]
                    fr = f
                    d = sg
                if first:
                    u = (x[k] - x[0]) / x_ref
                    hh = np.interp(min(abs(u), 1.0), tab_x, tab_f)
                    f = hh if u >= 0.0 else -hh
                else:
                    u = 0.5 * (x[k] - xr) / x_ref
                    hh = np.interp(min(abs(u), 1.0), tab_x, tab_f)
                    f = fr + 2.0 * (hh if u >= 0.0 else -hh)
                    f = min(max(f, -1.0), 1.0)
        out[k] = f
    return out


@on_fine_grid
def band_brake_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Part of the contact's friction is carried by a band wrapped round a drum beside it
    (a band brake or a strap holding a drum, a wrapped rope's drag). Loaded, the band does
    not slip as a whole at once: its tension falls along the wrap by Euler-Eytelwein's law
    over an arc of slip that spreads from the tight end while the rest sticks, and the
    band's elastic stretch over that arc is the presliding displacement, so the force grows
    first as the root of the displacement and reaches gross slip (the whole wrap,
    e^:data:`BAND_MU_WRAP`) over a path of the base bristle's Fs / sigma0 plus ``s``
    :data:`BAND_PATH` x the stroke / 3 (:func:`_band_backbone`). After each reversal the
    force returns along Masing's rule, the first loading curve doubled
    (:func:`_masing_band`). The band carries the share w = ``s`` :data:`BAND_SHARE` of the
    Coulomb level, w Fc f; the contact the rest, the base's LuGre with its curve less w Fc
    (its viscous term whole). At ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the band's share of the friction (up to ``s`` = 0.95 /
        :data:`BAND_SHARE`) and its slip path (as the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Belt and band creep over a drum, the spreading slip arc and the elastic stretch over it
    (Reynolds 1874, On the efficiency of belts or straps as communicators of work, The
    Engineer 38; Johnson 1985, Contact Mechanics, ch. on belt drives and creep; Euler 1762,
    Remarques sur l'effet du frottement dans l'equilibre, Mem. Acad. Sci. Berlin) and
    Masing's rule for reversals (Masing 1926, Eigenspannungen und Verfestigung beim
    Messing, Proc. 2nd Int. Congr. Appl. Mech.), which the band follows approximately. The
    candidate's presliding is a generalized Maxwell-slip (GMS) element set; the open forms
    are Maxwell-slip sets, Dahl, elasto-plastic, Bliman-Sorine, Bouc-Wen, Zener junctions,
    Mindlin contacts, rate-and-state, Tomlinson asperities, bond rupture, gouge, kinematic
    hardening, interlocking, capillary bridges, cyclic hardening, peeling, unloading
    microslip, a power-law joint, junction growth, avalanches, slip weakening, a microslip
    bar, contact renewal, grease's yield, a superelastic flexure, an Eyring film, a
    viscoplastic layer, a poroelastic one, a confined film that melts, a hysteresis brake
    or a fibre wiper, each beside the contact, or a stiffening wire mesh in series with it.
    Here a wrapped band's slip arc spreads by the capstan law.
    """
    _lugre_params(kin, "gms (band_brake)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    law = kin.base
    w = min(float(s) * BAND_SHARE, 0.95)
    wf = w * _level(kin)
    e0, extra = _presliding_path(kin, s, BAND_PATH)
    tab_x, tab_f = _band_backbone()
    f = _masing_band(np.asarray(kin.x, float), e0 + extra, tab_x, tab_f)
    rest = lugre_with_curve(kin, lambda vv: law.g(vv) - wf)
    return rest + wf * f
