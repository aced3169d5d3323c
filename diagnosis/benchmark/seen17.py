"""The seventeenth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-29 (session 22) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 23's work on the code of 5f0e273:
176 cases, 0 skipped, 490 s wall on 2 workers (nothing else running). Top-1 47.2 %
(83; 49.4 % of the 168 detectable; the other 8: 4 delays below a sample, 4 Stribeck
shapes an oracle cannot tell from the base); mean |shrink error| 0.365; wrong names on 16 (9.1 %):
acceleration -> position 4, drift -> position 4, drift -> load 2, gms -> acceleration 2,
and four single ones. By form: load/preload_relief 20/20, position/heated_zone 15/16,
acceleration/aerostatic_tilt 13/20, delay/alpha_beta_tracker 9/20, inertia/screw_stiffness
8/20, asymmetry/felt_lubricator 6/20, gms/junction_growth 6/12, stribeck_shape/
core_loss_drag 3/16, drift/cage_creep 3/20, backlash/mesh_stiffness 0/12. By plant: press
71.4 %, isolator 53.6 %, valve 42.5 %, XML-350 42.5 %, damping rig 35.0 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen16` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen16`,
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
acceleration       ``aerostatic_tilt``: the carriage floats on externally pressurised
                   (aerostatic or hydrostatic) pads; the acceleration's pitching moment
                   tilts them on their films' stiffness, and the film's shear drag,
                   ~ the mean of 1 / h over the tilted pad (Petroff's drag with a
                   linear gap), grows as atanh(d) / d of the tilt d (Powell 1970; Rowe
                   1983): a viscous drag that rises with a^2, felt only while the
                   carriage both moves and accelerates
load               ``preload_relief``: a preloaded rolling guide with opposed Hertzian
                   rows (Q ~ deflection^1.5): the load adds to the lower rows and relieves
                   the upper ones until they lift off (the preloaded pair of Harris and
                   Kotzalas 2007): the rows' summed load, and the levels, are nearly flat
                   in the load about the preload and follow it one for one past the
                   upper rows' lift-off
asymmetry          ``felt_lubricator``: an oil-soaked felt lubricator on one end of the
                   carriage (a linear guide's lubrication unit): leading, it lays a fresh
                   film just ahead of the contact; trailing, the contact runs on the film
                   it laid on the last pass the other way, which has drained off the
                   track since (a thin-film drainage in time): the levels fall in one
                   direction at once and in the other by the age of the film at each
                   position
stribeck_shape     ``core_loss_drag``: the drive's iron core losses per unit of travel
                   (the loss separation of Bertotti 1988: hysteresis ~ f, eddy ~ f^2,
                   excess ~ f^1.5 of the magnetic frequency f ~ v): a drag constant in
                   the speed (hysteresis) plus one rising as sqrt(|v|) (the excess,
                   domain-wall, loss) beside the friction's curve
position           ``heated_zone``: a heat source (a motor, a spindle, a hydraulic unit)
                   beside the rail where fit and held-out parts both pass warms it; the
                   rail's temperature falls off along it as a cooled fin's
                   (exp(-|x - x_h| / l), Incropera and DeWitt 2002), and the oil's
                   viscosity falls exponentially with the temperature (Reynolds 1886):
                   the film's drag falls and the boundary levels rise in a zone of the
                   stroke
inertia            ``screw_stiffness``: the carriage is driven by a ball screw fixed at one
                   end, whose axial stiffness ~ 1 / the screw's length between the fixed
                   bearing and the nut (Altintas 2012; Okwudire and Altintas 2009): the
                   carriage on that spring follows the drive's acceleration through a
                   lightly damped mode whose frequency falls along the stroke, and the
                   inverse dynamics misses the carriage's mass times the difference
delay              ``alpha_beta_tracker``: the logger smooths the force with an
                   alpha-beta (steady-state constant-velocity Kalman) tracking filter
                   (Benedict and Bordner 1962; Kalata 1984): a type-2 loop that follows
                   a steadily changing force without lag but lags the force's changes
                   of slope and overshoots them, more the lower its bandwidth
drift              ``cage_creep``: the rollers of a caged (non-recirculating) guide are
                   held in a cage that should move at half the carriage's speed but
                   creeps a little each stroke, more one way (cage creep; the makers'
                   anti-creep cages): once it reaches the carriage's end rollers leave
                   the loaded length (the others carry more), later the cage hits its stop
                   and the rollers skid: the levels rise along the net travel, then step
backlash           ``mesh_stiffness``: drive and contact joined by a gear (a rack and
                   pinion) with play whose mesh stiffness alternates between single- and
                   double-tooth contact along each tooth pitch (contact ratio 1.6;
                   Kahraman and Singh 1990; ISO 6336-1): after each reversal the play is
                   crossed and the force built through a compliance that depends on
                   where in the mesh the flank lands, and while sliding the mesh's
                   stiffness changes kick the contact
gms                ``junction_growth``: the presliding junctions beside the bristle grow
                   under the tangential force (Tabor's junction growth, 1959; McFarlane
                   and Tabor 1950): their contact radii, and their tangential stiffness
                   (Mindlin's 8 G a), rise with the force they carry, so each loads
                   *stiffening* up to its slip and unloads soft through zero: an S-shaped
                   loop, not the softening (Masing) loops of every other form; at ``s``
                   = 0 the base itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``core_loss_drag`` needs
a Stribeck curve (not the isolator's mre_lugre), ``heated_zone`` a record that revisits its
positions (not the press), ``preload_relief`` a load that changes, ``mesh_stiffness`` and
``junction_growth`` a classic LuGre base (valve, damping rig, XML-350); each raises a
``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.shapes import SHAPES

from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _level,
                     _light_contact_step, _lugre_params, _motion_time, _presliding_path,
                     _span, _substeps, has_stribeck_curve, level_inside, lugre_with_curve,
                     on_fine_grid)

__all__ = ["FORMS", "aerostatic_tilt_truth", "preload_relief_truth", "felt_lubricator_truth",
           "core_loss_drag_truth", "heated_zone_truth", "screw_stiffness_truth",
           "alpha_beta_tracker_truth", "cage_creep_truth", "mesh_stiffness_truth",
           "junction_growth_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "aerostatic_tilt", "load": "preload_relief",
         "asymmetry": "felt_lubricator", "stribeck_shape": "core_loss_drag",
         "position": "heated_zone", "inertia": "screw_stiffness",
         "delay": "alpha_beta_tracker", "drift": "cage_creep",
         "backlash": "mesh_stiffness", "gms": "junction_growth"}


# -- acceleration ----------------------------------------------------------------------------
#: ``aerostatic_tilt``'s acceleration at which the tilted pads would touch down, x the top
#: acceleration a99 [-]; the largest tilt reached, as a share of the film's mean gap (the
#: pads' restrictors stiffen the film as it closes) [-]; the pads' film drag at the top
#: speed, x the friction level, at strength 1 [-]
TILT_TOUCH, TILT_MAX, FILM_DRAG = 1.0, 0.9, 4.5


def _tilted_gap_drag(a, a_touch, d_max):
    """The shear drag of a pad tilted by the acceleration ``a`` [m/s^2] over its untilted
    drag [-]: the mean of h0 / h over a pad whose gap varies linearly by +-d h0 along it,
    atanh(d) / d, d = min(|a| / ``a_touch``, ``d_max``) (1 at d = 0)."""
    d = np.minimum(np.abs(np.asarray(a, float)) / a_touch, d_max)
    out = np.ones_like(d)
    big = d > 1e-4
    out[big] = np.arctanh(d[big]) / d[big]
    out[~big] = 1.0 + d[~big] ** 2 / 3.0          # the series of atanh(d) / d
    return out


@on_fine_grid
def aerostatic_tilt_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage floats on externally pressurised pads (aerostatic or hydrostatic) at
    both ends; the acceleration's pitching moment tilts it on the films' stiffness, in
    proportion to a (the films held by their restrictors), so each pad's gap varies
    linearly along it by +- d of its mean, d = |a| / (:data:`TILT_TOUCH` a99) (at most
    :data:`TILT_MAX`). The film's shear drag, eta v times the integral of 1 / h over the
    pad, grows as atanh(d) / d (:func:`_tilted_gap_drag`): the truth adds ``s``
    :data:`FILM_DRAG` F_level (v / v99) (atanh(d) / d - 1) to the base (the untilted
    film's drag is in the base's viscous term). The levels are the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the films' drag (their viscosity over their gap), / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Externally pressurised bearings and their tilt stiffness (Powell 1970, Design of
    Aerostatic Bearings; Rowe 1983, Hydrostatic and Hybrid Bearing Design; Slocum 1992,
    Precision Machine Design); the shear (Couette) drag of a film of varying gap (Petroff
    1883; Hamrock, Schmid and Jacobson 2004). The candidate raises the levels with |a|,
    lagged, tilts them with a and adds a force odd in a; the open forms lag the velocity,
    a film or a contact state, heat the contact, skid rolling elements, move load between
    rows or supports, press seals, pull with the thrust, squeeze or starve films, dilate,
    lift on a wedge, shift a gib, soften an elastomer, swing a roller arm or unload by
    the jerk's vibration. Here nothing touches: the acceleration closes one end of each
    film and the viscous drag, not the levels, grows with a^2, and only while the
    carriage moves.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    g = _tilted_gap_drag(kin.a, TILT_TOUCH * max(sc["a99"], 1e-12), TILT_MAX)
    c = float(s) * FILM_DRAG * _level(kin) / max(sc["v99"], 1e-12)
    return F + c * np.asarray(kin.v, float) * (g - 1.0)


# -- load ------------------------------------------------------------------------------------
#: ``preload_relief``'s rows' preload, x the record's mean load [-] (the upper rows lift off
#: at 2^1.5 x the preload, inside the records' load ranges); the rows' share of the friction
#: at strength 1 (the rest, seals and wipers, does not follow the load) [-]; the lowest
#: relative level [-]
ROW_PRELOAD, ROW_SHARE, ROW_FLOOR = 0.35, 1.0, 0.05


def _row_sum(load_over_preload):
    """The summed load [-] (over the preload) of two opposed Hertzian rows (Q ~ delta^1.5)
    preloaded against each other, under the external loads ``load_over_preload`` [-]
    (>= 0) pressing one of them: (1 + u)^1.5 - (1 - u)^1.5 = L / P solved for the
    deflection u (over the preload's), the sum (1 + u)^1.5 + (1 - u)^1.5; past the other
    row's lift-off (u >= 1, L / P >= 2^1.5) the loaded row carries L alone."""
    r = np.abs(np.asarray(load_over_preload, float))
    u = np.linspace(0.0, 1.0, 2001)
    diff = (1.0 + u) ** 1.5 - (1.0 - u) ** 1.5         # rises monotonically to 2^1.5
    tot = (1.0 + u) ** 1.5 + (1.0 - u) ** 1.5
    return np.where(r < diff[-1], np.interp(r, diff, tot), r)


@on_fine_grid
def preload_relief_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The contact is a preloaded rolling guide with opposed rows (upper and lower ball
    rows, preloaded against each other by :data:`ROW_PRELOAD` x the record's mean load):
    the normal load adds to the lower rows' load and relieves the upper ones (Hertz: each
    row's load ~ its deflection^1.5), until the upper rows lift off (:func:`_row_sum`).
    The rows' rolling friction follows their summed load S(L), which hardly changes while
    both rows carry and follows the load one for one once the upper ones are free. The
    Coulomb and Stribeck levels are the base's times 1 + ``s`` :data:`ROW_SHARE`
    (S(L) / S(mean L) - 1) (at least :data:`ROW_FLOOR`), inside the bristle dynamics; the
    viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (load [N]) and its base law.
    s : float
        Amplitude factor [-]: the rows' share of the friction, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Preloaded pairs of rolling bearings and guides and their lift-off (Harris and Kotzalas
    2007, Rolling Bearing Analysis, the preloaded duplex pair; Palmgren 1959, rolling
    friction ~ load; the makers' preload classes, e.g. THK's and Schaeffler's linear guide
    catalogues). The candidate's levels are affine in the load (two regimes); the open
    forms scale them with a power of the load, in one direction, through the Stribeck
    velocity, a film, a step, a creep, a rate, a lever's play, a plastic area, a hinge, a
    cavitating film, a pressure-viscous film, an erf area, a flash temperature, a relay,
    a renewal over the slip, an adhesive area or the position of the load. Here the load
    is shared with a preload: little of a light load's change reaches the friction, all
    of a heavy one's does, with the kink at the lift-off.
    """
    L = np.asarray(kin.load, float)
    if not np.ptp(L) > 1e-9 * max(float(np.mean(np.abs(L))), 1e-300):
        raise ValueError(f"load (preload_relief): the {kin.plant} record's load does not "
                         f"change")
    if s <= 0.0:
        return _base_parts(kin)[0]
    P = ROW_PRELOAD * max(float(np.mean(np.abs(L))), 1e-300)
    rows = _row_sum(L / P) / float(_row_sum(np.array([float(np.mean(np.abs(L))) / P]))[0])
    lev = np.clip(1.0 + float(s) * ROW_SHARE * (rows - 1.0), ROW_FLOOR, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``felt_lubricator``'s fall of the levels on a fresh film at strength 1 [-]; the film's
#: drainage time, x the record's length [-]; the track's cells, per the stroke the record
#: visits [-]; the lowest relative level [-]
FELT_DROP, FELT_DRAIN, FELT_CELLS, FELT_FLOOR = 0.4, 0.15, 400, 0.05


@njit(cache=True)
def _film_share(t, x, v, x_lo, cell, n_cells, tau):
    """The share [-] of a fresh film under the contact along the times ``t`` [s], positions
    ``x`` [m] and velocities ``v`` [m/s]: 1 while moving in the positive direction (the
    felt leads and oils the track just ahead); moving the other way, exp(-age / ``tau``)
    of the film the felt laid at that position (the track cut in ``n_cells`` cells of
    ``cell`` [m] from ``x_lo`` [m]) on its last positive pass, 0 where it never passed."""
    n = t.size
    laid = np.full(n_cells, -1e300)
    out = np.empty(n)
    for k in range(n):
        j = int((x[k] - x_lo) / cell)
        j = min(max(j, 0), n_cells - 1)
        if v[k] > 0.0:
            laid[j] = t[k]
            out[k] = 1.0
        elif laid[j] > -1e299:
            out[k] = math.exp(-(t[k] - laid[j]) / tau)
        else:
            out[k] = 0.0
    return out


@on_fine_grid
def felt_lubricator_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """An oil-soaked felt lubricator is fitted at the carriage's positive end (a linear
    guide's lubrication unit). Moving in the positive direction it leads and lays a fresh
    film just ahead of the contact; moving back it trails, and the contact runs on the
    film the felt laid at each position on its last positive pass, which has drained off
    the track since with the time constant :data:`FELT_DRAIN` x the record
    (:func:`_film_share`; none where the felt never passed). The Coulomb and Stribeck
    levels are the base's times 1 - ``s`` :data:`FELT_DROP` x the fresh film's share (at
    least :data:`FELT_FLOOR`), inside the bristle dynamics; the viscous term is the
    base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the film's lubricity (the levels' fall on it), / its value
        at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Lubrication units of linear guides (felt or fibre-net applicators on the carriage's
    end caps, e.g. THK's QZ and Bosch Rexroth's front lube units); the drainage and
    spreading of a thin oil film on a surface (Reynolds' thin-film flow; Oron, Davis and
    Bankoff 1997, Long-scale evolution of thin liquid films, Rev. Mod. Phys. 69). The
    candidate's twins and offset are the same everywhere and always; the open forms
    change with the direction through twin levels, curves or a viscous slope, roll a
    lip, load a thrust bearing, wipe a rod's film, climb a texture, compress a spring,
    wedge a pad or a sprag, throttle an exhaust, meter a cylinder, pump through grooves,
    buckle a cable, bulldoze chips, commutate late, tension an idler or lock a roller's
    clutch. Here the direction decides which film the contact meets: a fresh one, or
    one that has aged since the last pass, so the negative direction's levels depend on
    the time and place of the last positive pass.
    """
    if s <= 0.0:
        return _base_parts(kin)[0]
    t = np.asarray(kin.t, float)
    x = np.ascontiguousarray(kin.x, dtype=float)
    x_lo = float(np.min(x))
    cell = max(float(np.ptp(x)), 1e-12) / FELT_CELLS
    tau = FELT_DRAIN * max(float(t[-1] - t[0]), 1e-12)
    share = _film_share(t, x, np.ascontiguousarray(kin.v, dtype=float), x_lo, cell,
                        FELT_CELLS + 1, tau)
    lev = np.clip(1.0 - float(s) * FELT_DROP * share, FELT_FLOOR, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- stribeck_shape --------------------------------------------------------------------------
#: ``core_loss_drag``'s excess-loss drag at the top speed, x the Coulomb level, at strength
#: 1 [-]; the hysteresis-loss drag, x the excess loss's at the top speed [-]
EXCESS_DRAG, HYSTERESIS_SHARE = 0.4, 0.25


def _core_loss(u, hysteresis):
    """The iron core's loss drag [-] (over the excess loss's at ``u`` = 1) at the relative
    speeds ``u`` = |v| / v99 [-]: ``hysteresis`` (the hysteresis loss ~ f: a constant
    drag) plus sqrt(u) (the excess loss ~ f^1.5: a drag ~ f^0.5); the classical eddy loss
    (~ f^2: a drag ~ v) is a viscous term, the base's."""
    return hysteresis + np.sqrt(np.abs(np.asarray(u, float)))


@on_fine_grid
def core_loss_drag_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The drive's iron core (a linear motor's back iron, a rotary motor's stator) is
    magnetised at a frequency proportional to the speed; its losses per unit of travel
    are a drag on the axis (:func:`_core_loss`): the hysteresis loss, constant per cycle,
    a constant drag; the excess (domain-wall) loss, ~ f^1.5, a drag ~ sqrt(|v|). It acts
    as a curve beside the friction's (carried through the bristle at rest): the Stribeck
    curve is the base's plus ``s`` :data:`EXCESS_DRAG` Fc (:data:`HYSTERESIS_SHARE` +
    sqrt(|v| / v99)); the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (with a Stribeck curve).
    s : float
        Amplitude factor [-]: the core's losses (its induction squared), / their value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The separation of iron losses into hysteresis, classical eddy-current and excess
    losses (Bertotti 1988, General properties of power losses in soft ferromagnetic
    materials, IEEE Trans. Magn. 24; Steinmetz 1892) and the drag they put on motors
    (Gieras and Piech 2000, Linear Synchronous Motors). The open forms take other tails,
    lift-offs, peaks, roughness, rate-and-state, Eyring films, starvation, rubber
    hysteresis, resonances, dither, melt films, granular flow, readsorption, thermal,
    turbulent, thixotropic films or churning, each a property of the contact or its
    lubricant. Here the curve's new part comes from the drive's magnetics: a drag with
    a step at rest and a square-root rise, however the contact is lubricated.
    """
    law = kin.base
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (core_loss_drag): the mre_lugre base has no "
                         "Stribeck curve")
    if s <= 0.0:
        return _base_parts(kin)[0]
    drag = float(s) * EXCESS_DRAG * float(law.params.Fc)
    v99 = max(kin.scales["v99"], 1e-12)
    return lugre_with_curve(kin, lambda vv: law.g(vv) + drag * _core_loss(vv / v99,
                                                                          HYSTERESIS_SHARE))


# -- position --------------------------------------------------------------------------------
#: ``heated_zone``'s fin length of the rail's temperature, x the stroke [-]; the fall of the
#: log viscosity at the heat source at strength 1 (Reynolds' beta x the temperature rise)
#: [-]; the rise of the boundary levels as the film's viscosity falls to nothing [-]; the
#: film's drag at the top speed, x the friction level [-]
ZONE_LENGTH, ZONE_HEAT, ZONE_MIXED, ZONE_DRAG = 0.2, 0.8, 1.5, 1.5


def _fin_profile(x, centre, length):
    """The rail's temperature rise [-] (1 at the heat source at ``centre`` [m]) along the
    positions ``x`` [m]: a long cooled fin's exp(-|x - centre| / ``length``)."""
    return np.exp(-np.abs(np.asarray(x, float) - centre) / length)


@on_fine_grid
def heated_zone_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A heat source beside the rail (a motor, a spindle housing, a hydraulic unit) sits
    where fit and held-out parts both pass; the rail conducts its heat and loses it to the
    air, so its temperature rise falls off along it as a cooled fin's
    (:func:`_fin_profile`, length :data:`ZONE_LENGTH` x the stroke). The oil on the rail
    thins as exp(-``s`` :data:`ZONE_HEAT` theta(x)) of the temperature rise theta
    (Reynolds' law): its film's drag, ZONE_DRAG F_level v / v99 at the cold viscosity,
    falls with it, and the thinner film lets the asperities carry more: the Coulomb and
    Stribeck levels are the base's times 1 + :data:`ZONE_MIXED` (1 - eta / eta0), inside
    the bristle dynamics. At ``s`` = 0 the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the source's temperature rise at the rail, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Heat conduction along a cooled fin (Incropera and DeWitt 2002, Fundamentals of Heat
    and Mass Transfer, ch. 3); thermal errors and hot spots of machine tools (Bryan 1990,
    International status of thermal error research, CIRP Ann. 39); the viscosity's
    exponential fall with the temperature (Reynolds 1886). The open forms raise the
    levels by a bump, a wave, a worn stretch, a runout, a bent rail, a transfer film, a
    cogging force, a taper, an oil port's wake, a cushion, a cover, an air spring, bolt
    holes, an immersed plunger, a sagging beam, a festoon, a curved track, a gliding
    chain or a cam. Here the stroke's property is a temperature: the viscous drag falls
    and the boundary levels rise together, over a zone whose width the rail's conduction
    sets, both ways.
    """
    xc = _bump_centre(kin)
    if xc is None:
        raise ValueError(f"position (heated_zone): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    theta = _fin_profile(kin.x, xc, ZONE_LENGTH * _span(kin))
    thin = np.exp(-float(s) * ZONE_HEAT * theta)         # eta / eta0
    lev = 1.0 + ZONE_MIXED * (1.0 - thin)
    c = ZONE_DRAG * _level(kin) / max(kin.scales["v99"], 1e-12)
    return level_inside(kin, lev, np.ones_like(lev)) + c * np.asarray(kin.v, float) * (thin
                                                                                     - 1.0)


# -- inertia ---------------------------------------------------------------------------------
#: ``screw_stiffness``'s carriage mass at strength 1, x the friction level / a99 [-]; the
#: axial mode's angular frequency with the nut at the stroke's far end, x 1 / the motion's
#: time scale [-]; the screw's length from its fixed bearing to the stroke's near end, x
#: the stroke [-]; the mode's damping ratio [-]
SCREW_MASS, SCREW_FREQUENCY, SCREW_LEAD_IN, SCREW_DAMPING = 1.0, 4.0, 0.3, 0.08


@njit(cache=True)
def _screw_mode(t, a, omega, zeta):
    """The carriage's lag e [m] behind the drive along the times ``t`` [s] (uniform): e'' +
    2 ``zeta`` w e' + w^2 e = ``a`` (the drive's acceleration [m/s^2]) with the angular
    frequencies ``omega`` [1/s] at each instant (the screw's stiffness at the nut's
    position); semi-implicit Euler from rest. Returns (e, e'') [m, m/s^2]."""
    n = t.size
    e = np.empty(n)
    edd = np.empty(n)
    y = 0.0
    yd = 0.0
    for k in range(n):
        w = omega[k]
        acc = a[k] - 2.0 * zeta * w * yd - w * w * y
        e[k] = y
        edd[k] = acc
        if k + 1 < n:
            h = t[k + 1] - t[k]
            yd = yd + h * acc
            y = y + h * yd
    return e, edd


@on_fine_grid
def screw_stiffness_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage is driven by a ball screw fixed at one end (the stroke's lower end)
    and free at the other; its axial stiffness, EA / the screw's length between the fixed
    bearing and the nut, falls along the stroke, so the carriage on that spring is a mode
    whose angular frequency is :data:`SCREW_FREQUENCY` / the motion's time scale with the
    nut at the far end, higher nearer the bearing (~ 1 / sqrt(length), the length from
    :data:`SCREW_LEAD_IN` x the stroke), damping ratio :data:`SCREW_DAMPING`
    (:func:`_screw_mode`). The encoder is on the motor: the carriage's acceleration is
    a - e'', and the inverse dynamics misses m e'', m a99 = ``s`` :data:`SCREW_MASS` x the
    friction level: the measured force is the base's minus m e''.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the carriage's mass, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The axial stiffness of ball-screw feed drives and its dependence on the nut's position
    (Altintas 2012, Manufacturing Automation, ch. 6; Okwudire and Altintas 2009, Hybrid
    modeling of ball screw drives with coupled axial, torsional, and lateral dynamics,
    J. Mech. Des. 131; Varanasi and Nayfeh 2004). The candidate misses a constant mass;
    the open forms filter it, reflect it through gearing, a chain's polygon or a
    pinion, hang it on a spring, a cable, a fluid, a clutch, a coupling or a flyweight,
    pick it up, drop it, empty it, rattle it, recoil the frame or saturate the motor.
    Here the missed part is the carriage's own motion on the drive's compliance, whose
    mode's frequency changes with where the carriage is.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    T = max(_motion_time(kin), 1e-12)
    span = _span(kin)
    x = np.asarray(kin.x, float)
    length = SCREW_LEAD_IN * span + np.clip(x - float(np.min(x)), 0.0, None)
    far = SCREW_LEAD_IN * span + float(np.ptp(x))
    omega = (SCREW_FREQUENCY / T) * np.sqrt(far / length)
    _, edd = _screw_mode(np.asarray(kin.t, float), np.ascontiguousarray(kin.a, dtype=float),
                         np.ascontiguousarray(omega), SCREW_DAMPING)
    m = float(s) * SCREW_MASS * _level(kin) / max(kin.scales["a99"], 1e-12)
    return F - m * edd


# -- delay -----------------------------------------------------------------------------------
#: ``alpha_beta_tracker``'s time constant 1 / omega of its loop at strength 1, in data
#: samples [-]; its damping ratio (the alpha-beta gains of Kalata's tracking index near the
#: critically damped pair) [-]
TRACK_SAMPLES, TRACK_DAMPING = 3.5, 0.7


def _tracker(t, F, omega, zeta):
    """``F`` [N] along the times ``t`` [s] (uniform) through the type-2 tracking loop
    y' = w + 2 ``zeta`` ``omega`` (F - y), w' = ``omega``^2 (F - y) (the steady-state
    alpha-beta filter in continuous time: (2 zeta omega s + omega^2) / (s^2 + 2 zeta
    omega s + omega^2)), discretised by the bilinear transform, from steady state at the
    first value (no rate)."""
    from scipy.signal import bilinear, lfilter, lfilter_zi
    fs = 1.0 / float(t[1] - t[0])
    b, a = bilinear([2.0 * zeta * omega, omega * omega],
                    [1.0, 2.0 * zeta * omega, omega * omega], fs)
    F = np.asarray(F, float)
    return lfilter(b, a, F, zi=lfilter_zi(b, a) * F[0])[0]


@on_fine_grid
def alpha_beta_tracker_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The logger smooths the force with an alpha-beta tracking filter (the steady-state
    Kalman filter of a constant-rate model) of bandwidth omega = 1 / (``s``
    :data:`TRACK_SAMPLES` data samples) and damping :data:`TRACK_DAMPING`
    (:func:`_tracker`; no cap at :data:`.truths.MAX_DELAY_SAMPLES`: on a smooth force a
    slow tracker is all but exact, so the plants whose force turns gently need a long
    one to reach the requested size): it estimates the
    force's level and its rate, so a force that changes at a steady rate is followed
    without lag; a change of the rate (a reversal's turn, a plateau's start) is followed
    late and overshot.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the tracker's time constant, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The alpha-beta tracker (Sklansky 1957; Benedict and Bordner 1962, Synthesis of an
    optimal set of radar track-while-scan smoothing equations, IRE Trans. Autom. Control
    7; Kalata 1984, The tracking index, IEEE Trans. Aerosp. Electron. Syst. 20), used to
    smooth noisy sensor channels in loggers and drives. The open forms delay by one
    amount, filter by a low-pass, linearly or by rank, hold at a fieldbus's clock, let
    the delay drift, wander or follow the force's rate, level or slowness, the motion's
    speed or the position, hold stale values over lost telegrams, lead through a leaking
    charge, creep, or take out the mains' band. Here a filter with a rate state: no lag
    on ramps, a lag and an overshoot where the force's slope changes.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    tau = float(s) * TRACK_SAMPLES * float(kin.sample_dt)
    return _tracker(np.asarray(kin.t, float), F, 1.0 / tau, TRACK_DAMPING)


# -- drift -----------------------------------------------------------------------------------
#: ``cage_creep``'s creep the other way, as a share of the creep in the positive direction
#: per unit travel [-]; the net creep (over the record's) at which rollers begin to leave the
#: loaded length, and at which the cage reaches its stop [-]; the levels' rise as the rollers
#: leave, and their step when they skid, at strength 1 [-]; the skid's onset, as a share
#: of the net creep [-]
CREEP_BACK, CREEP_LEAVE, CREEP_STOP, CREEP_RISE, CREEP_SKID, CREEP_ONSET = (
    0.6, 0.3, 0.75, 0.25, 0.35, 0.03)


def _cage_offset(t, v, back):
    """The cage's creep [-] (over its largest value in the record) along the times ``t``
    [s] and velocities ``v`` [m/s]: the travel integrated with weight 1 in the positive
    direction and -``back`` in the other (a net creep one way)."""
    u = np.asarray(v, float)
    rate = np.where(u > 0.0, u, back * u)
    c = np.concatenate(([0.0], np.cumsum(0.5 * (rate[1:] + rate[:-1]) * np.diff(t))))
    return c / max(float(np.max(np.abs(c))), 1e-300)


@on_fine_grid
def cage_creep_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The contact's rollers run in a cage (a crossed-roller or caged ball slide, not
    recirculating) that should move at half the carriage's speed but slips a little on
    every stroke, more in the positive direction (an inclined axis, an offset load), so
    it creeps (:func:`_cage_offset`, the net creep over the record's largest). From
    :data:`CREEP_LEAVE` of it the cage's end passes the carriage's: rollers leave the
    loaded length one after the other and the rest carry more (the levels rise linearly
    by ``s`` :data:`CREEP_RISE` up to :data:`CREEP_STOP`); there the cage hits its stop,
    is dragged and the rollers skid (a step of ``s`` :data:`CREEP_SKID`, rounded over
    :data:`CREEP_ONSET` of the creep). Inside the bristle dynamics; the viscous term is
    the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the friction's rise (the rollers' overload and skid), / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Cage creep (cage slippage, retainer migration) in non-recirculating linear rolling
    guides and its remedies (rack-and-pinion anti-creep cages: IKO's and Schneeberger's
    catalogues; Harris and Kotzalas 2007 on cage slip); skidding of unloaded rollers
    (Harris 1966). The candidate is a trend, a saturating change, a step, a cycle, an
    accelerating part and a part that builds up and resets, in time; the open forms warm
    up, wear in, step, cycle, rise and fall with debris, drop with grease shots, relax,
    oxidise, wear through, swell, grow a tribofilm, take in particles, expand, shear the
    oil, heat the magnets or charge the surfaces. Here the drift follows the net travel
    one way, not the clock or the total travel: a ramp once the creep passes a margin,
    then a step at the stop.
    """
    if s <= 0.0:
        return _base_parts(kin)[0]
    c = _cage_offset(np.asarray(kin.t, float), kin.v, CREEP_BACK)
    leave = np.clip((c - CREEP_LEAVE) / (CREEP_STOP - CREEP_LEAVE), 0.0, 1.0)
    skid = 0.5 * (1.0 + np.tanh((c - CREEP_STOP) / CREEP_ONSET))
    lev = 1.0 + float(s) * (CREEP_RISE * leave + CREEP_SKID * skid)
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: ``mesh_stiffness``'s play at strength 1, as a share of the stroke [-]; the single-tooth
#: mesh's deflection at the Coulomb level at strength 1, as a share of the stroke [-]; the
#: double-tooth mesh's stiffness over the single's [-]; the contact ratio [-]; the tooth
#: pitch, as a share of the stroke [-]
MESH_PLAY, MESH_COMPLIANCE, MESH_DOUBLE, MESH_RATIO, MESH_PITCH = 0.007, 0.003, 1.8, 1.6, 0.07


def _mesh_factor(x, pitch, ratio, double):
    """The mesh's stiffness [-] over the single-tooth one along the drive positions ``x``
    [m]: ``double`` over the share ``ratio`` - 1 of each ``pitch`` [m] where two tooth
    pairs mesh, 1 over the rest, the changes rounded over 2 % of the pitch."""
    ph = np.mod(np.asarray(x, float) / pitch, 1.0)
    w = 0.02
    on = 0.5 * (np.tanh(ph / w) - np.tanh((ph - (ratio - 1.0)) / w)) \
        + 0.5 * (1.0 + np.tanh((ph - 1.0) / w))
    return 1.0 + (double - 1.0) * np.clip(on, 0.0, 1.0)


@njit(cache=True)
def _meshed_contact(h, xd, kfac, half, k1, c1, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a contact of mass ``m`` [kg] driven by the drive positions
    ``xd`` [m] (step ``h`` [s]) across a play of half-width ``half`` [m], the flank a
    mesh of stiffness ``k1`` ``kfac`` [N/m] (``kfac`` [-] at each drive position) and
    damping ``c1`` [N s/m], compressive only. Semi-implicit Euler of the mass
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
        k = k1 * kfac[j]
        fc = 0.0
        if e > half:
            f2 = k * (e - half) + c1 * ed
            if f2 > 0.0:
                fc = f2
        elif e < -half:
            f2 = k * (e + half) + c1 * ed
            if f2 < 0.0:
                fc = f2
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha, shape)
        x = x + h * v
    return F


@on_fine_grid
def mesh_stiffness_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact joined by a gear mesh (a rack and pinion) with play, half-width
    ``s``^2 :data:`MESH_PLAY` / 2 x the stroke, whose flank stiffness alternates along
    each tooth pitch (:data:`MESH_PITCH` x the stroke) between the single-tooth mesh's and
    :data:`MESH_DOUBLE` times it where two pairs mesh (the share :data:`MESH_RATIO` - 1 of
    the pitch; :func:`_mesh_factor`); the single-tooth mesh deflects by ``s``^2
    :data:`MESH_COMPLIANCE` x the stroke at the Coulomb level (:func:`_meshed_contact`).
    After each reversal the play is crossed and the force built through the mesh's
    compliance, which depends on where in the pitch the flank lands; while sliding, each
    change of the mesh's stiffness moves the contact against the held force and kicks
    it. The contact is light (:func:`.truths._contact_constants`), with the base's LuGre
    friction; the measured force is its friction. At ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the square root of the play and the mesh's compliance, /
        their values at strength 1 (as the open plays').

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Gear pairs with backlash and a time-varying mesh stiffness (Kahraman and Singh 1990,
    Non-linear dynamics of a spur gear pair, J. Sound Vib. 142; ISO 6336-1, the mesh
    stiffness c_gamma and the transverse contact ratio; Ozguven and Houser 1988). The
    candidate holds or frees the force across a play, with a bias, a spring or a drag
    across it; the open forms couple rigidly, compliantly, by impacts, springs, oil in
    the play, an idler, a bias, chains, magnets, a preload, a hardening gear, a slipping
    rope, a rubber spider, an oil column, a cable in a sheath or a clutch, with a play
    varying with the position or the travel. Here the coupling's stiffness changes with
    the tooth in mesh: the force's build-up after a reversal differs from one reversal to
    the next, and the sliding force ripples at the tooth pitch.
    """
    p = _lugre_params(kin, "backlash (mesh_stiffness)")
    if s <= 0.0:
        return _base_parts(kin)[0]
    m, kh, _ = _contact_constants(kin, p)
    stroke = float(np.ptp(kin.x))
    Fc = float(p.Fc)
    half = 0.5 * float(s) ** 2 * MESH_PLAY * stroke
    k1 = Fc / max(float(s) ** 2 * MESH_COMPLIANCE * stroke, 1e-300)
    k1 = min(k1, kh)                      # never stiffer than the other forms' flanks
    c1 = 2.0 * 0.5 * math.sqrt(k1 * m)
    kmax = MESH_DOUBLE * k1
    h, xd, n_sub = _substeps(kin, max(math.sqrt((kmax + float(p.sigma0)) / m),
                                      (float(p.sigma1) + float(p.sigma2) + c1) / m))
    kfac = _mesh_factor(xd, MESH_PITCH * _span(kin), MESH_RATIO, MESH_DOUBLE)
    F = _meshed_contact(h, xd, kfac, half, k1, c1, m, float(p.sigma0), float(p.sigma1),
                        float(p.sigma2), Fc, float(p.Fs), float(p.vs), float(p.alpha),
                        SHAPES[p.shape])
    return F[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: the junctions' travel to slip at strength 1, beyond the base bristle's path, as a share
#: of the stroke / 3 [-]; their share of the friction at strength 1 [-]; Tabor's growth
#: coefficient (alpha mu^2 of (A / A0)^2 = 1 + alpha (F / W)^2, with the force over its slip
#: value) [-]; the junctions (Iwan elements, slip strengths from 0.55 to 1 of the largest)
#: [-]
GROWTH_SLIP, GROWTH_SHARE, GROWTH_ALPHA, GROWTH_JUNCTIONS = 0.1, 0.7, 15.0, 8


def _growth_integral(alpha):
    """The travel to slip [-] of a junction of unit initial stiffness over unit slip force:
    the integral of (1 + ``alpha`` r^2)^-1/4 over r in [0, 1]."""
    r = np.linspace(0.0, 1.0, 4001)
    y = (1.0 + alpha * r * r) ** -0.25
    return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(r)))


@njit(cache=True)
def _growing_junctions(x, caps, kappa, alpha):
    """The junctions' force f [-] (1 when all slip) along the positions ``x`` [m]: junction
    j carries r_j ``caps``[j] with r_j in [-1, 1] (slipping at +-1), dr_j = ``kappa``[j]
    (1 + ``alpha`` r_j^2)^(1/4) dx (its stiffness ~ its contact radius, which grows with
    the force it carries). Starts unloaded."""
    n = x.size
    m = caps.size
    r = np.zeros(m)
    out = np.empty(n)
    out[0] = 0.0
    full = np.sum(caps)
    for k in range(1, n):
        dx = x[k] - x[k - 1]
        tot = 0.0
        for j in range(m):
            rj = r[j]
            # the midpoint's stiffness (the step is small against the travel to slip)
            half = rj + 0.5 * kappa[j] * (1.0 + alpha * rj * rj) ** 0.25 * dx
            rj = rj + kappa[j] * (1.0 + alpha * half * half) ** 0.25 * dx
            if rj > 1.0:
                rj = 1.0
            elif rj < -1.0:
                rj = -1.0
            r[j] = rj
            tot += rj * caps[j]
        out[k] = tot / full
    return out


@on_fine_grid
def junction_growth_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The presliding junctions beside the bristle grow under the tangential force
    (Tabor's junction growth: (A / A0)^2 = 1 + alpha (F / W)^2): each junction's contact
    radius, and with it its tangential stiffness (Mindlin's 8 G* a), rises as (1 +
    :data:`GROWTH_ALPHA` r^2)^(1/4) of its force over its slip force r
    (:func:`_growing_junctions`; :data:`GROWTH_JUNCTIONS` Iwan elements of slip strengths
    0.55 to 1, travel to slip in proportion). Loaded from rest a junction stiffens up to
    its slip; unloaded from slip it is stiff at first, soft through zero force and stiff
    again towards the other slip: the loops are S-shaped. The largest travel to slip is
    the base bristle's path Fs / sigma0 plus ``s`` :data:`GROWTH_SLIP` x the stroke / 3;
    a share w = :data:`GROWTH_SHARE` min(``s``, 1) of the friction is the junctions'
    (their sliding force the Stribeck level, the viscous term the base's): F = (1 - w)
    F_lugre + w (g(v) f + sigma2 v). At ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the junctions' share (up to ``s`` = 1) and their travel to
        slip (as the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Junction growth under combined normal and tangential loading (McFarlane and Tabor
    1950, Relation between friction and adhesion, Proc. R. Soc. A 202; Tabor 1959,
    Junction growth in metallic friction, Proc. R. Soc. A 251; Johnson 1985, Contact
    Mechanics, ch. 7, for the stiffness ~ the contact radius). Maxwell-slip (the
    candidate) and the open forms use equal, geometric or power-law strengths, path laws,
    an elastic range, rate-dependent creep, Mindlin's 3/2 law, multistable tips, bonds, a
    fabric, a back-stress, a climb out of a nest, capillary bridges, a hardening yield,
    peeling junctions or load-dependent microslip, each softening as it loads. Here each
    junction stiffens as it loads: the virgin curve is convex up to the slips and the
    loops are pinched, the reverse of Masing's.
    """
    p = _lugre_params(kin, "gms (junction_growth)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, GROWTH_SLIP)
    w = GROWTH_SHARE * min(float(s), 1.0)
    v = np.asarray(kin.v, float)
    caps = np.linspace(0.55, 1.0, GROWTH_JUNCTIONS)
    # travel to slip in proportion to the strength (equal initial stiffness per strength)
    kappa = _growth_integral(GROWTH_ALPHA) / ((e0 + extra) * caps)
    f = _growing_junctions(np.ascontiguousarray(kin.x, dtype=float), caps, kappa,
                           GROWTH_ALPHA)
    return (1.0 - w) * F + w * (kin.base.g(v) * f + float(p.sigma2) * v)
