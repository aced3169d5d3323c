"""The thirty-seventh sealed truth family: one more mechanism per effect, out of all tuning.

Written 2026-12-02 (session 41) by another hand, once, without running the diagnosis on it;
sealed: not run. It is run only at the end of a piece of work and reported apart from the
open grid (each effect record's ``sealed``, :data:`diagnosis.effects.EFFECTS`; the family
sealed before it, session 40's other, was run once and is :mod:`.seen36`).
Once its results have been seen it joins the open grid, as :mod:`.seen` to :mod:`.seen36`
did. Each form is a mechanism of other physics than every form of its effect so far
(:mod:`.truths`, :mod:`.forms`, :mod:`.seen` to :mod:`.seen36`,
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
acceleration       ``lanchester_damper``: the drive carries a heavy ring coupled by a
                   slipping friction clutch: held, it follows as a mass; under a harder
                   acceleration the clutch slips and drags the lagging ring up to speed:
                   a force that follows the acceleration's sign, saturates and lingers
load               ``brush_pads``: part of the load rests on brush pads whose bristles slide
                   on their tips under a light load and are bent over onto their flanks,
                   which grip harder, under a heavy one: levels that rise faster than the
                   load
asymmetry          ``peeled_tape``: an adhesive tape is laid on the way by the carriage
                   moving towards -x and peeled off it moving towards +x, at a force that
                   grows as a power of the peel rate: a one-way force from nothing at
                   rest
stribeck_shape     ``contact_charging``: the sliding charges the surfaces by contact
                   electrification, more the faster (against the charge's leak, up to
                   the air's breakdown); the image charges' pull adds to the load: the
                   curve rises with the speed from nothing at rest
position           ``dimpled_band``: a laser-textured band of micro-dimples on the way lifts
                   the carriage hydrodynamically, the more the faster it slides over it:
                   the friction falls over the band, by a share that grows with the
                   speed
inertia            ``speed_variator``: a flywheel driven through a centrifugal variator
                   whose ratio falls with the speed: a reflected mass that falls steeply
                   from rest to the top speed
delay              ``pen_arc``: the force is read off a pen recorder's chart whose pen tip
                   swings on an arc: a mark lands late along the chart by R (1 - cos
                   theta), nothing at mid-scale and most at the extremes
drift              ``sma_preload``: the gib is preloaded by a shape-memory wire heated by a
                   current from the start: the preload stays put while it warms, rises
                   along the martensite's turn to austenite and settles once done
backlash           ``taut_string``: drive and contact are joined across the play by a taut
                   string pushed sideways at its middle: a pull by its pretension for a
                   small push, stiffening as the offset's cube towards the stops
gms                ``mullins_shoe``: part of the friction is carried by a shoe held by a
                   rubber block in shear that softens under each new largest strain (the
                   Mullins effect): stiff at first, softer on later, smaller excursions;
                   at ``s`` = 0 the base
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``contact_charging`` needs
a Stribeck curve (not the isolator's mre_lugre), ``dimpled_band`` a record that revisits its
positions (not the press), ``brush_pads`` a load that changes, ``taut_string`` and
``mullins_shoe`` a classic LuGre base (valve, damping rig, XML-350); each raises a
``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.shapes import SHAPES

from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _level,
                     _light_contact_step, _lugre_params, _presliding_path, _substeps,
                     has_stribeck_curve, level_inside, lugre_with_curve, on_fine_grid)

__all__ = ["FORMS", "lanchester_damper_truth", "brush_pads_truth", "peeled_tape_truth",
           "contact_charging_truth", "dimpled_band_truth", "speed_variator_truth",
           "pen_arc_truth", "sma_preload_truth", "taut_string_truth", "mullins_shoe_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "lanchester_damper", "load": "brush_pads",
         "asymmetry": "peeled_tape", "stribeck_shape": "contact_charging",
         "position": "dimpled_band", "inertia": "speed_variator",
         "delay": "pen_arc", "drift": "sma_preload",
         "backlash": "taut_string", "gms": "mullins_shoe"}


# -- acceleration ----------------------------------------------------------------------------
#: ``lanchester_damper``'s clutch slipping force at strength 1, x the Coulomb level [-]; the
#: ring's inertial force at the top acceleration, x the clutch's slipping force [-]
RING_SLIP, RING_MASS = 0.6, 2.0


@njit(cache=True)
def _ring_force(t, v, mass, slip):
    """The force [N] a friction-coupled ring of mass ``mass`` [kg] (its inertia reflected
    to the carriage) puts on the carriage moving at ``v`` [m/s] at the times ``t`` [s]:
    the ring's clutch holds it to the drive while its inertial force stays below the
    slipping force ``slip`` [N]; beyond, the clutch slips and drags the ring towards the
    drive's speed at ``slip`` / ``mass``, and the carriage feels ``slip`` towards the ring's
    side. From rest with the drive."""
    n = v.size
    F = np.zeros(n)
    u = v[0]
    for k in range(1, n):
        h = t[k] - t[k - 1]
        need = mass * (v[k] - u) / h       # force to bring the ring to the drive's speed
        if abs(need) <= slip:
            F[k] = need
            u = v[k]
        else:
            f = slip if need > 0.0 else -slip
            F[k] = f
            u = u + h * f / mass
    return F


@on_fine_grid
def lanchester_damper_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The drive carries a Lanchester damper (a heavy ring on the motor's shaft, coupled to
    it by a spring-loaded friction clutch, as damps a drive's torsional vibrations): while
    the ring's inertial force stays below the clutch's slipping force the ring follows the
    drive as a mass; under a harder acceleration the clutch slips, and the drive feels the
    clutch's friction, pulling the lagging ring up to speed, until the ring catches up
    (:func:`_ring_force`): a force that follows the acceleration's sign and saturates, and
    lingers after it ends. The clutch slips at ``s`` :data:`RING_SLIP` x the Coulomb
    level; the ring's inertial force at the top acceleration is :data:`RING_MASS` x that.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the ring's inertia and its clutch's torque, / their values
        at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The Lanchester (friction) torsional vibration damper, a flywheel ring coupled by a
    slipping friction clutch, and its stick-slip under the drive's angular acceleration
    (Den Hartog 1956, Mechanical Vibrations, ch. on the Lanchester damper; Nestorides 1958,
    A Handbook on Torsional Vibration; Wilson 1956, Practical Solution of Torsional
    Vibration Problems). The candidate raises the levels with |a|, lagged, tilts them with
    a and adds a force odd in a; the open forms lag, age, heat, skid, load, press, slosh,
    wedge, couple through fluids, belts, meshes, seals and bands. Here a ring held by a
    slipping clutch is dragged up to the drive's speed.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    slip = float(s) * RING_SLIP * _level(kin)
    mass = RING_MASS * RING_SLIP * _level(kin) / max(kin.scales["a99"], 1e-12)
    mass = float(s) * mass
    return F + _ring_force(np.asarray(kin.t, float), np.asarray(kin.v, float), mass, slip)


# -- load ------------------------------------------------------------------------------------
#: ``brush_pads``' largest change of the levels with the brushes' friction, at strength 1
#: [-]; the load the pads carry at no normal load, x the largest load [-]; the load that
#: bends the bristles half over, x the largest load [-]; the friction coefficients of the
#: bristles' tips and of their flanks, laid on the way [-]
BRUSH_RISE, BRUSH_REST, BRUSH_BEND, BRUSH_MUT, BRUSH_MUS = 0.5, 0.1, 0.6, 0.1, 0.6


def _brush_friction(w, rest, bend, mut, mus):
    """The brush pads' friction [-] (over its value at the largest load) at the loads ``w``
    [-] (x the largest; the pads carry ``w`` + ``rest``): each bristle, a cantilever pressed
    on the way at its tip, bends over as the load grows, its tip angle's tangent growing as
    the load over the bending stiffness; the share of its length laid flat on the way,
    q = (load / (load + ``bend``))^2, slides on its flank at ``mus``, its tip at ``mut``."""
    q = (np.abs(np.asarray(w, float)) + float(rest)) / (1.0 + float(rest))

    def mu(load):
        lay = (load / (load + float(bend))) ** 2
        return float(mut) + (float(mus) - float(mut)) * lay
    return q * mu(q) / mu(np.array(1.0))


@on_fine_grid
def brush_pads_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Part of the carriage's load rests on brush pads (dense strips of nylon bristles, as
    guide and wipe the carriage of some conveyors and cover plates): a light load bends the
    bristles little and they slide on their tips, a heavy one bends them over until they
    lie on the way along their flanks, which grip it many times harder
    (:func:`_brush_friction`): the friction grows faster than the load. The Coulomb and
    Stribeck levels are the base's times 1 + ``s`` :data:`BRUSH_RISE` x the friction's
    departure from its mean along the record, over its largest, inside the bristle
    dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid and its base law, with the normal load [N].
    s : float
        Amplitude factor [-]: the brushes' share of the friction, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Raises
    ------
    ValueError
        When the record's load does not change.

    Notes
    -----
    The bending of a brush's bristles as elastic cantilevers under a tip load and their
    contact with the counterface along the tip or the flank (Timoshenko and Gere 1961,
    Theory of Elastic Stability, the elastica; Chew and Hogg 1997, Porosity modeling of
    brush seals, J. Tribol. 119, on bristle bending and friction in brush seals). The
    candidate makes the levels affine in the load, with a memory over the travel; the open
    forms scale the friction with contacts, films, junctions, pivots, seals, rolling
    elements, pores, clamps or magnets, none with a contact that lays over. Here the load
    lays bristles flat on the way.
    """
    L = np.abs(np.asarray(kin.load, float))
    Lmax = float(np.max(L)) or 1.0
    if not np.ptp(L) > 1e-9 * Lmax:
        raise ValueError(f"load (brush_pads): the {kin.plant} record's load does not "
                         f"change")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    g = _brush_friction(L / Lmax, BRUSH_REST, BRUSH_BEND, BRUSH_MUT, BRUSH_MUS)
    e = g - float(np.mean(g))
    e = e / max(float(np.max(np.abs(e))), 1e-12)
    lev = np.maximum(1.0 + float(s) * BRUSH_RISE * e, 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``peeled_tape``'s peel force at the top speed, at strength 1, x the Coulomb level [-];
#: the exponent of the adhesive's rate dependence [-]
TAPE_PULL, TAPE_RATE = 0.6, 0.3


def _peel_force(w, rate):
    """The tape's peel force [-] (x its value at the top speed, w = 1) at the speeds ``w``
    [-] (x the top speed): moving towards +x the carriage peels the tape at the speed w, and
    the adhesive's fracture energy grows as the peel rate's power ``rate`` (viscoelastic
    loss at the peel front), the force being G / (1 - cos theta) per unit width at the
    fixed peel angle theta (Rivlin's and Kendall's peel); moving towards -x the tape is
    laid back without a force."""
    w = np.maximum(np.asarray(w, float), 0.0)
    return w ** float(rate)


@on_fine_grid
def peeled_tape_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A pressure-sensitive adhesive tape (a protective band over the way, as keeps chips
    out of a slot) is laid on the way by a roller on the carriage moving towards -x and
    peeled off it by the carriage moving towards +x: laying it back costs nothing, peeling
    it costs the adhesive's fracture energy, which grows with the peel rate as a power
    (the viscoelastic loss at the peel front; :func:`_peel_force`). The peel force, ``s``
    :data:`TAPE_PULL` x the Coulomb level at the top speed, opposes the motion towards +x
    only, and grows from nothing at rest as the speed's power :data:`TAPE_RATE`.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the tape's width, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The peel test's force per unit width G / (1 - cos theta) (Rivlin 1944, The effective
    work of adhesion, Paint Technol. 9; Kendall 1975, Thin-film peeling - the elastic term,
    J. Phys. D 8) and the rate dependence of a viscoelastic adhesive's fracture energy,
    G = G0 (1 + (v / v*)^n) (Gent and Petrich 1969, Adhesion of viscoelastic materials to
    rigid substrates, Proc. R. Soc. A 310; Maugis and Barquins 1978, Fracture mechanics and
    the adherence of viscoelastic bodies, J. Phys. D 11). The candidate gives each
    direction its levels and an offset; the open forms twin levels, curves or viscous
    terms, roll lips, tilt pads, strut sprags, throttle, groove, scrape, pump, drag a cup
    or a hose, flush a stream or pull by a travelling field, none an adhesive's fracture.
    Here the carriage peels a tape one way and lays it back the other.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    w = np.asarray(kin.v, float) / v99
    return F + float(s) * TAPE_PULL * _level(kin) * _peel_force(w, TAPE_RATE)


# -- stribeck_shape --------------------------------------------------------------------------
#: ``contact_charging``'s rise of the Stribeck curve once the charge reaches the air's
#: breakdown, at strength 1, x the Coulomb level [-]; the speed at which the charge is half
#: its limit, x the top speed [-]
CHARGE_RISE, CHARGE_SPEED = 0.6, 0.25


def _contact_charge(w, speed):
    """The sliding surfaces' charge [-] (x the air's breakdown limit) at the speeds ``w``
    [-] (x the top speed): contact electrification separates charge at a rate proportional
    to the area swept, |w|, and the charge leaks through the surfaces' resistance at a rate
    proportional to itself, and is capped by the air's breakdown: at steady state
    q = |w| / (|w| + ``speed``)."""
    aw = np.abs(np.asarray(w, float))
    return aw / (aw + float(speed))


@on_fine_grid
def contact_charging_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage's polymer liner slides on the way and charges it by contact
    electrification: the charge separated grows with the area swept per unit time, that is
    with the speed, and leaks away through the surfaces' resistance, so the charge the
    surfaces hold grows with the speed, towards the limit the air's breakdown sets
    (:func:`_contact_charge`); the image charges pull the surfaces together with a pressure
    that grows as the charge's square, and the friction grows with that pull. The Stribeck
    curve is the base's plus ``s`` :data:`CHARGE_RISE` x the Coulomb level x the charge's
    square, inside the LuGre dynamics: nothing at rest, rising with the speed.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the electrostatic pull at the breakdown limit, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Raises
    ------
    ValueError
        On the isolator's mre_lugre base (no Stribeck curve).

    Notes
    -----
    Contact electrification (triboelectric charging) of sliding polymer-metal pairs, its
    growth with the rubbed area and its decay by surface conduction, the charge density's
    limit by the air's breakdown (Paschen's law), and the electrostatic pressure
    sigma^2 / (2 epsilon0) adding to the normal load (Harper 1967, Contact and Frictional
    Electrification; Lowell and Rose-Innes 1980, Contact electrification, Adv. Phys. 29;
    Budakian and Putterman 2000, Correlation between charge transfer and stick-slip
    friction at a metal-insulator interface, Phys. Rev. Lett. 85). The candidate's curve
    is Gaussian, Lorentzian or an exponential tail; the open forms add tails, films,
    melting, heating, churning, eddies, menisci, adhesion applied by an electrode and
    others, none a charge the sliding makes itself. Here the sliding charges the surfaces,
    the more the faster.
    """
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (contact_charging): the mre_lugre base has no "
                         "Stribeck curve")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    law = kin.base
    v99 = max(kin.scales["v99"], 1e-12)
    add = float(s) * CHARGE_RISE * _level(kin)
    return lugre_with_curve(kin, lambda vv: law.g(vv) + add * _contact_charge(
        vv / v99, CHARGE_SPEED) ** 2)


# -- position --------------------------------------------------------------------------------
#: ``dimpled_band``'s largest fall of the levels over the textured band at the top speed, at
#: strength 1 [-]; the band's half width and its edge's width, x the stroke [-]; the speed
#: at which the dimples' lift carries half its largest share, x the top speed [-]
DIMPLE_FALL, DIMPLE_HALF, DIMPLE_EDGE, DIMPLE_SPEED = 0.6, 0.15, 0.02, 0.3


def _dimple_lift(d, w, half, edge, speed):
    """The dimples' share of the load [-] at the distances ``d`` [-] (x the stroke) from the
    band's centre and the speeds ``w`` [-] (x the top speed): the band's cover (a logistic
    edge of width ``edge`` at the half width ``half``) times the micro-hydrodynamic lift of
    each dimple, which grows with the speed as |w| / (|w| + ``speed``) (the pressure a
    converging wedge builds, proportional to the viscosity and the speed, against the
    asperities' share at low speeds)."""
    d = np.abs(np.asarray(d, float))
    cover = 1.0 / (1.0 + np.exp((d - float(half)) / float(edge)))
    aw = np.abs(np.asarray(w, float))
    return cover * aw / (aw + float(speed))


@on_fine_grid
def dimpled_band_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A band of the way was laser-textured with shallow micro-dimples (a repair or a
    trial of surface texturing): each dimple is a small hydrodynamic bearing whose
    converging side builds a pressure that grows with the sliding speed, and a reservoir
    of oil, so over the band the film carries a share of the load that grows with the
    speed and the asperities' friction falls (:func:`_dimple_lift`); off the band the way
    is the plain ground one. The Coulomb and Stribeck levels are the base's times 1 -
    ``s`` :data:`DIMPLE_FALL` x that share, inside the bristle dynamics; the viscous term
    is the base's. The band is centred where both the fit and the held-out part of the
    record pass (:func:`.truths._bump_centre`).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the dimples' lift, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Raises
    ------
    ValueError
        When the held-out part never revisits the fit part's positions (the press).

    Notes
    -----
    Laser surface texturing, whose micro-dimples act as micro-hydrodynamic bearings and
    lubricant reservoirs and lower the friction of lubricated sliding, the more the faster
    it slides (Etsion 2005, State of the art in laser surface texturing, J. Tribol. 127;
    Ryk, Kligerman and Etsion 2002, Experimental investigation of laser surface texturing
    for reciprocating automotive components, Tribol. Trans. 45; Hamilton, Walowit and
    Allen 1966, A theory of lubrication by microirregularities, J. Basic Eng. 88). The
    candidate scales the friction along the stroke and adds a force of the position; the
    open forms put defects, waviness, wear, films, grit, rust or water on it, none of
    them a lift that grows with the speed. Here a textured band lifts the carriage the
    more, the faster it slides over it.
    """
    c = _bump_centre(kin)
    if c is None:
        raise ValueError(f"position (dimpled_band): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    span = max(sc["x_hi"] - sc["x_lo"], 1e-12)
    w = np.asarray(kin.v, float) / max(sc["v99"], 1e-12)
    lift = _dimple_lift((np.asarray(kin.x, float) - c) / span, w, DIMPLE_HALF, DIMPLE_EDGE,
                        DIMPLE_SPEED)
    lev = np.maximum(1.0 - float(s) * DIMPLE_FALL * lift, 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- inertia ---------------------------------------------------------------------------------
#: ``speed_variator``'s reflected mass at rest, at strength 1, x the friction level / a99
#: [kg per N s^2/m]; the variator's shift of its ratio at the top speed (i = i0 / (1 + c
#: w^2)) [-]; the largest speed the shift follows, x the top speed [-]
VARIATOR_MASS, VARIATOR_SHIFT, VARIATOR_TOP = 0.5, 0.5, 1.2


def _variator_mass(w, shift, top):
    """The variator's reflected mass [-] (x its value at rest) at the speeds ``w`` [-] (x
    the top speed): the flywheel turns at i(w) v, the ratio i = 1 / (1 + ``shift`` w^2)
    falling as the variator's flyweights open its sheaves; its torque J d(i v)/dt, passed
    back through the ratio i, is a force J i (i + w i'(w)) a = J a (1 - c w^2) / (1 + c
    w^2)^3, c ``shift`` (speeds beyond ``top`` held at ``top``)."""
    c = float(shift)
    w2 = np.minimum(np.asarray(w, float) ** 2, float(top) ** 2)
    return (1.0 - c * w2) / (1.0 + c * w2) ** 3


@on_fine_grid
def speed_variator_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The axis' drive turns a flywheel (a machine's heavy pulley or a tool's spindle mass)
    through a speed-dependent variator (a centrifugal variator, as shifts a scooter's belt
    drive): as the speed grows its flyweights open the sheaves and the ratio falls, so the
    flywheel is reflected to the carriage with a mass that falls with the speed, and the
    ratio's own change with the speed takes part of the flywheel's torque
    (:func:`_variator_mass`): an inertial force m(v) a with a mass that falls steeply from
    rest to the top speed. The mass at rest is ``s`` :data:`VARIATOR_MASS` x the friction
    level / the top acceleration.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the flywheel's inertia, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The reflected inertia J i^2 of a flywheel behind a transmission of ratio i, and of a
    continuously variable one whose ratio is set by the speed (a centrifugally shifted
    V-belt variator), J i (i + v di/dv) (Srivastava and Haque 2009, A review on belt and
    chain continuously variable transmissions (CVT): dynamics and control, Mech. Mach.
    Theory 44; Doughty 1988, Mechanics of Machines, the equivalent mass of a drive). The
    candidate misses a constant mass; the open forms filter it, gear it, hang, slide,
    roll, rock, swing or pick it, reflect it through linkages, yokes, winches or scissors,
    none through a ratio the speed sets. Here a variator's ratio falls with the speed.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    w = np.asarray(kin.v, float) / max(sc["v99"], 1e-12)
    M = float(s) * VARIATOR_MASS * _level(kin) / max(sc["a99"], 1e-12)
    return F + M * _variator_mass(w, VARIATOR_SHIFT, VARIATOR_TOP) * np.asarray(kin.a, float)


# -- delay -----------------------------------------------------------------------------------
#: ``pen_arc``'s lag of the pen's mark at its largest swing, at strength 1 [data samples];
#: the pen arm's largest swing [rad]
PEN_SPAN, PEN_SWING = 3.0, 0.7


def _arc_lag(y, swing):
    """The lag [-] (x its value at the largest swing) of a pen's mark along the chart at the
    pen's deflections ``y`` [-] (x the largest, across the chart): the pen on an arm of
    length R swings by theta, sin theta = y sin(``swing``), and its tip trails along the
    chart by R (1 - cos theta) behind where a straight pen would write."""
    q = np.clip(np.asarray(y, float), -1.0, 1.0) * math.sin(float(swing))
    return (1.0 - np.sqrt(1.0 - q * q)) / (1.0 - math.cos(float(swing)))


@on_fine_grid
def pen_arc_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is written by a pen recorder (a galvanometric chart recorder) and read off
    the chart as if its trace were drawn on straight lines across it: the pen's arm swings
    about a pivot, so its tip writes on an arc, and a mark far from the chart's middle
    lands further along the chart than a straight pen would put it - read, the force comes
    late by a time that grows with its deflection from the chart's middle
    (:func:`_arc_lag`), nothing at mid-scale. The pen is centred on the middle of the
    force's range along the record and swings by :data:`PEN_SWING` at its ends; the lag
    there is ``s`` :data:`PEN_SPAN` data samples. The force read at ``t`` is the base
    law's at ``t`` - tau, tau the lag at the deflection read there (the lag changes little
    over one lag).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the chart's time per unit of length, / its value at strength
        1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The curvilinear recording of galvanometric and potentiometric pen recorders, whose
    pen tip moves on an arc and displaces a mark along the time axis by R (1 - cos theta)
    (Doebelin 2004, Measurement Systems: Application and Design, ch. on graphic recorders;
    Bentley 2005, Principles of Measurement Systems; Webster 1998, Medical Instrumentation,
    on curvilinear strip-chart recorders). The candidate shifts the force in time or lags
    it through a first-order filter; the open forms delay, filter, average, stamp,
    decimate, hold, skew, pipe, transmit, observe, fuse, buffer or read a rolling shutter,
    none a pen's arc. Here the force's own deflection sets how late its mark lands.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    lo, hi = float(np.min(F)), float(np.max(F))
    y = (2.0 * F - lo - hi) / max(hi - lo, 1e-300)
    tau = float(s) * PEN_SPAN * kin.sample_dt * _arc_lag(y, PEN_SWING)
    return np.interp(t - tau, t, F, left=F[0])


# -- drift -----------------------------------------------------------------------------------
#: ``sma_preload``'s rise of the levels once the wire is wholly austenite, at strength 1
#: [-]; the wire's heating time constant, x the record's duration [-]; its steady
#: temperature rise and its austenite start and finish temperatures, x that rise [-]
SMA_RISE, SMA_TAU, SMA_AS, SMA_AF = 0.5, 0.35, 0.3, 0.85


def _austenite_share(tr, tau, a_s, a_f):
    """The shape-memory wire's austenite share [-] at the times ``tr`` [-] (x the record's
    duration): heated from the start by a constant current, its temperature rises as 1 -
    exp(-``tr`` / ``tau``) (x its steady rise; Newton's cooling), and the martensite turns
    to austenite between ``a_s`` and ``a_f`` of that rise along Liang and Rogers' cosine,
    0.5 (1 - cos(pi (T - As) / (Af - As)))."""
    T = 1.0 - np.exp(-np.asarray(tr, float) / float(tau))
    q = np.clip((T - float(a_s)) / (float(a_f) - float(a_s)), 0.0, 1.0)
    return 0.5 * (1.0 - np.cos(math.pi * q))


@on_fine_grid
def sma_preload_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The gib is preloaded by a shape-memory alloy (nickel-titanium) wire actuator,
    switched on with the axis: the current heats the wire towards a steady temperature,
    and between its austenite start and finish temperatures its martensite turns to
    austenite, recovering the wire's strain against the gib's spring - the preload stays
    put while the wire warms, then rises along the transformation and settles once it is
    complete (:func:`_austenite_share`). The Coulomb and Stribeck levels are the base's
    times 1 + ``s`` :data:`SMA_RISE` x the austenite share, inside the bristle dynamics;
    the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the wire's share of the preload, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The shape-memory effect and the recovery stress of a heated, prestrained NiTi wire,
    with the martensite-austenite share along Liang and Rogers' cosine law (Liang and
    Rogers 1990, One-dimensional thermomechanical constitutive relations for shape memory
    materials, J. Intell. Mater. Syst. Struct. 1; Otsuka and Wayman 1998, Shape Memory
    Materials; Lagoudas 2008, Shape Memory Alloys), the wire's Joule heating against
    Newton's cooling. The candidate is a trend, a saturating change, a step, a cycle, a
    resetting change or the friction power's heat; the open forms warm, wear, age, swell,
    charge, creep, relax, leak, discharge or evaporate, none of them a solid-state phase
    change. Here a wire's martensite turns to austenite under its heating current.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    tr = (t - t[0]) / max(float(t[-1] - t[0]), 1e-300)
    xi = _austenite_share(tr, SMA_TAU, SMA_AS, SMA_AF)
    lev = 1.0 + float(s) * SMA_RISE * xi
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: ``taut_string``'s play at strength 1, as a share of the stroke (its full width between
#: the stops) [-]; the string's pull at the stops, x the Coulomb level [-]; its
#: pretension's share of that pull [-]; each half's length, x the play's half width [-]
STRING_CLEAR, STRING_PULL, STRING_PRE, STRING_LEN = 0.0003, 0.6, 0.05, 1.0


@njit(cache=True)
def _string_force(e, half, pull, pre, length):
    """The taut string's pull [N] at the offset ``e`` [m] of the drive from the contact
    inside the play of half-width ``half`` [m]: a string anchored on the contact at both
    ends, each half ``length`` x ``half`` long, is pushed sideways at its middle by the
    drive; each half stretches to sqrt(l^2 + e^2), its tension the pretension plus the
    stretch's elastic force, and the two halves pull back by 2 T e / sqrt(l^2 + e^2):
    nearly nothing for a small push, stiffening as the cube of the offset (the string's
    geometric stiffening), ``pull`` [N] at the stops, ``pre`` of it from the pretension."""
    l = length * half
    r = math.sqrt(l * l + half * half)
    # tension at the stops from the pull there, of which the pretension's share
    t_stop = pull * r / (2.0 * half)
    t0 = pre * t_stop
    k = (t_stop - t0) / (r - l)
    d = math.sqrt(l * l + e * e)
    return 2.0 * (t0 + k * (d - l)) * e / d


@njit(cache=True)
def _string_contact(h, xd, half, pull, pre, length, kh, ch, m, s0, s1, s2, Fc, Fs, vs, alpha,
                    shape):
    """LuGre friction [N] of a light contact of mass ``m`` [kg] driven by the drive positions
    ``xd`` [m] (steps ``h`` [s]) through a play of half-width ``half`` [m] between rigid
    stops (a spring ``kh`` [N/m] and damper ``ch`` [N s/m], compressive only), across which
    a taut string pulls the contact towards the drive (:func:`_string_force`). From rest,
    the drive in the play's middle. Semi-implicit Euler of the contact, its bristle
    exact."""
    nn = xd.size
    F = np.empty(nn)
    x = xd[0]
    v = 0.0
    z = 0.0
    for j in range(nn):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        e = xd[j] - x
        ed = vd - v
        fc = _string_force(e, half, pull, pre, length)
        if e > half:
            f2 = kh * (e - half) + ch * ed
            if f2 > 0.0:
                fc += f2
        elif e < -half:
            f2 = kh * (-e - half) - ch * ed
            if f2 > 0.0:
                fc -= f2
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha,
                                         shape)
        x = x + h * v
    return F


@on_fine_grid
def taut_string_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact are joined across a play of width ``s``^2 :data:`STRING_CLEAR` x
    the stroke by a taut string (a steel wire anchored on the contact at both ends and
    pushed sideways at its middle by a pin on the drive, as some instruments' and models'
    anti-rattle strings are): a small push barely stretches it and it pulls back by its
    pretension's share only; a larger one stretches both halves and the pull stiffens as
    the offset's cube (:func:`_string_force`, :data:`STRING_PULL` x the Coulomb level at
    the stops; :func:`_string_contact`): the lost motion is taken up by a pull that
    stiffens across the play, nothing like a spring's linear one.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid and its base law.
    s : float
        Amplitude factor [-]: the play's width, / its square root at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Raises
    ------
    ValueError
        On a base other than a classic LuGre (the isolator's mre_lugre).

    Notes
    -----
    The transverse force of a pretensioned elastic string pushed at its middle, 2 T sin
    theta with the tension growing with the stretch, linear for small offsets under its
    pretension and cubic beyond (geometric nonlinearity; Timoshenko and Gere 1961, Theory
    of Elastic Stability; Nayfeh and Mook 1979, Nonlinear Oscillations, the string's
    cubic stiffness), and lost motion in mechanisms (Nordin and Gutman 2002, Controlling
    mechanical systems with backlash - a survey, Automatica 38). The candidate holds or
    frees the contact across a rigid play; the open forms take it up rigidly,
    compliantly, by impact, against springs, through oil, rope, cable, grease, air,
    foam, liquid bridges, magnets, detents or a swinging link. Here a string stretched
    across the play pulls back as it is pushed sideways.
    """
    p = _lugre_params(kin, "backlash (taut_string)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    half = 0.5 * float(s) ** 2 * STRING_CLEAR * float(np.ptp(kin.x))
    pull = STRING_PULL * float(p.Fc)
    m, kh, ch = _contact_constants(kin, p)
    rate = max(math.sqrt(kh / m), (float(p.sigma1) + float(p.sigma2) + ch) / m)
    h, xd, n_sub = _substeps(kin, rate)
    Fr = _string_contact(h, xd, half, pull, STRING_PRE, STRING_LEN, kh, ch, m,
                         float(p.sigma0), float(p.sigma1), float(p.sigma2), float(p.Fc),
                         float(p.Fs), float(p.vs), float(p.alpha), SHAPES[p.shape])
    return Fr[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: ``mullins_shoe``'s share of the Coulomb level the shoe carries at strength 1 [-]; its
#: slip travel in the virgin rubber at strength 1, beyond the base bristle's, as a share of
#: the stroke / 3 [-]; the rubber's largest loss of stiffness to the Mullins softening [-]
MULLINS_SHARE, MULLINS_PATH, MULLINS_LOSS = 0.3, 0.1, 0.6


@njit(cache=True)
def _mullins_pull(x, x_ref, loss):
    """The rubber's pull [-] (over the shoe's sliding force) along the carriage's positions
    ``x`` [m]: the shoe is held by a rubber block in shear, of stiffness 1 / ``x_ref`` in
    the virgin state (the shoe slides at an offset ``x_ref`` [m]), softened by the largest
    offset it has seen, m, to (1 - ``loss`` m / (m + ``x_ref``)) of that (the Mullins
    effect: softer on reloading below the largest strain, virgin stiffness beyond it). The
    shoe sticks while the pull stays below 1 and slides at the pull 1."""
    n = x.size
    out = np.empty(n)
    shoe = x[0] if n > 0 else 0.0
    mx = 0.0
    for j in range(n):
        e = x[j] - shoe
        if abs(e) > mx:
            mx = abs(e)
        k = (1.0 - loss * mx / (mx + x_ref)) / x_ref
        f = k * e
        if f > 1.0:
            f = 1.0
            shoe = x[j] - 1.0 / k
        elif f < -1.0:
            f = -1.0
            shoe = x[j] + 1.0 / k
        out[j] = f
    return out


@on_fine_grid
def mullins_shoe_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Part of the contact's friction is carried by a shoe held to the carriage by a block
    of filled rubber in shear (a rubber-mounted wiper or damping shoe): the rubber softens
    under its first loading to each new largest strain and stays softer on reloading below
    it (the Mullins effect, the filler network's damage), so the shoe's presliding path is
    stiff at first, softer on every later, smaller excursion, and the softened rubber lets
    the carriage travel further before the shoe slides (:func:`_mullins_pull`); a reversal
    below the largest strain unloads along the softened stiffness, no loss until the shoe
    slides. The shoe carries ``s`` :data:`MULLINS_SHARE` (at most 0.95) of the Coulomb
    level; its slip travel in the virgin rubber is the base bristle's Fs / sigma0 plus
    ``s`` :data:`MULLINS_PATH` x the stroke / 3; the rest stays the base law with its level
    lowered by as much; at ``s`` = 0 the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the shoe's share of the friction (up to ``s`` = 0.95 /
        :data:`MULLINS_SHARE`) and its slip travel, / their values at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Raises
    ------
    ValueError
        On a base other than a classic LuGre (the isolator's mre_lugre).

    Notes
    -----
    The Mullins effect, the stress softening of filled rubbers after loading to a new
    largest strain (Mullins 1948, Effect of stretching on the properties of rubber, Rubber
    Chem. Technol. 21; Diani, Fayolle and Gilormini 2009, A review on the Mullins effect,
    Eur. Polym. J. 45; Ogden and Roxburgh 1999, A pseudo-elastic model for the Mullins
    effect in filled rubber, Proc. R. Soc. A 455), carrying a sticking and sliding shoe, a
    presliding element of its own law (Al-Bender, Lampaert and Swevers 2005, The
    generalized Maxwell-slip model, IEEE Trans. Autom. Control 50, for the element set it
    departs from). The candidate's presliding is a generalized Maxwell-slip (GMS) element
    set; the open forms are Maxwell-slip sets, Dahl, elasto-plastic, Bouc-Wen, contacts,
    films, layers, flexures, brakes, bands, leaves, struts, couplings and a hanging shoe,
    none whose stiffness remembers its largest strain. Here a rubber block softens under
    each new largest strain.
    """
    _lugre_params(kin, "gms (mullins_shoe)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    law = kin.base
    w = min(float(s) * MULLINS_SHARE, 0.95)
    wf = w * _level(kin)
    e0, extra = _presliding_path(kin, s, MULLINS_PATH)
    f = _mullins_pull(np.asarray(kin.x, float), e0 + extra, MULLINS_LOSS)
    rest = lugre_with_curve(kin, lambda vv: law.g(vv) - wf)
    return rest + wf * f
