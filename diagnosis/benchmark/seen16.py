"""The sixteenth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-29 (session 21) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 22's work on the code of 93064fe:
176 cases, 0 skipped, 518 s wall on 2 workers (beside a 1-process helper). Top-1 31.8 %
(56; 32.2 % of the 174 detectable); mean |shrink error| 0.380; wrong names on 26 (14.8 %):
acceleration -> delay 4, acceleration -> asymmetry 4, load -> asymmetry 4, drift -> load 3,
load -> position 2, gms -> acceleration 2, and six single ones. By form:
position/cam_plunger 15/16, asymmetry/freewheel_roller 11/20, delay/mains_notch 9/20,
load/overhung_load 8/20, gms/power_law_joint 5/12, stribeck_shape/churning_drag 4/16,
drift/tribocharging 3/20, acceleration/jerk_unloading 1/20, inertia/chordal_action 0/20,
backlash/reversing_clutch 0/12. By plant: isolator 50.0 %, press 39.3 %, valve 30.0 %,
XML-350 25.0 %, damping rig 22.5 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen15` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen15`,
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
acceleration       ``jerk_unloading``: each change of the acceleration (the jerk) knocks
                   the carriage into vibration normal to its guides, which decays with
                   the contacts' damping; while the carriage vibrates, the mean
                   friction falls (dynamic unloading: Tolstoi 1967; Hess and Soom
                   1991): the levels fall with the decaying envelope of |jerk|, not
                   with the acceleration itself
load               ``overhung_load``: the load acts at a fixed point of the frame on a
                   carriage with two supports of different friction (a sliding pad and
                   a rolling block) that moves under it: the lever arms, and the
                   reactions' shares, change with the position (statics of a beam on
                   two supports): the load's effect on the levels is stronger at one
                   end of the stroke than at the other
asymmetry          ``freewheel_roller``: a pressure roller runs on a one-way (sprag)
                   clutch bearing: it rolls freely one way; the other way the clutch
                   locks, after a short engagement travel, and the roller slides with
                   its own friction (Orthwein 1986; anti-rollback rollers): extra
                   friction in one direction only, building up over a travel after
                   each reversal into it
stribeck_shape     ``churning_drag``: the recirculating rolling elements' lubricant
                   churning (Palmgren's load-independent bearing torque, M0 ~ (nu n)^(2/3)
                   above a speed, constant below; Palmgren 1959; Harris and Kotzalas
                   2007): a drag flat at low speeds rising as |v|^(2/3) above a knee
position           ``cam_plunger``: a spring plunger on the carriage runs over a cam bar
                   (a lobe: a ramp up, a dwell, a ramp down) fixed where fit and
                   held-out parts both pass: the compressed spring presses the plunger
                   harder (the levels rise over the lobe) and the ramps push back on the
                   way up and forward on the way down (a force of the position whose
                   sign changes between the two ramps)
inertia            ``chordal_action``: the carriage is pulled by a roller chain from a
                   sprocket whose shaft carries the encoder: the chain's speed pulses
                   with the sprocket's polygon (chordal action, Binder 1956; ISO 10823),
                   so the carriage's acceleration differs from the measured one by a
                   share of a and a term in v^2 periodic in the position, which the
                   inverse dynamics misses times the carriage's mass
delay              ``mains_notch``: the force amplifier carries a second-order notch
                   filter against the mains hum (at a twentieth of the data rate, the
                   50 Hz of a 1 kHz logger): below the notch its phase lags as
                   1 / (Q omega0), above it it leads; a wider notch (a lower Q), a
                   larger lag
drift              ``tribocharging``: the sliding charges the insulating surfaces
                   (contact electrification, Harper 1967; Lowell and Rose-Innes 1980),
                   the charge leaking away through the surfaces' resistance: the
                   electrostatic attraction ~ charge^2 presses the contact and the
                   levels rise as the charge builds up with the travel, more after fast
                   strokes, less after dwells
backlash           ``reversing_clutch``: drive and contact coupled through the
                   electromagnetic clutch of a reversing drive (one clutch per
                   direction): at each reversal the other clutch's torque builds up over
                   its engagement time (the coil's current rise, Warner Electric;
                   Schuler 1998): the contact follows only once the clutch transmits
                   its friction: a lost motion of time, not of travel
gms                ``power_law_joint``: presliding in a bolted lap joint (Segalman's
                   four-parameter Iwan model, 2005): a power-law density of the
                   junctions' slip strengths plus a share that slips at once (the
                   macro-slip), so the tangential stiffness softens as a power of the
                   travel and the loops' dissipation grows as a power of their
                   amplitude other than Masing's and Mindlin's; at ``s`` = 0 the base
                   itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``churning_drag`` needs a
Stribeck curve (not the isolator's mre_lugre), ``cam_plunger`` a record that revisits its
positions (not the press), ``overhung_load`` a load that changes,
``reversing_clutch`` and ``power_law_joint`` a classic LuGre base (valve, damping rig,
XML-350); each raises a ``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.shapes import SHAPES

from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _level,
                     _light_contact_step, _lugre_params, _lugre_run, _motion_time,
                     _presliding_path, _span, _substeps, level_inside, on_fine_grid)

__all__ = ["FORMS", "jerk_unloading_truth", "overhung_load_truth", "freewheel_roller_truth",
           "churning_drag_truth", "cam_plunger_truth", "chordal_action_truth",
           "mains_notch_truth", "tribocharging_truth", "reversing_clutch_truth",
           "power_law_joint_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "jerk_unloading", "load": "overhung_load",
         "asymmetry": "freewheel_roller", "stribeck_shape": "churning_drag",
         "position": "cam_plunger", "inertia": "chordal_action",
         "delay": "mains_notch", "drift": "tribocharging",
         "backlash": "reversing_clutch", "gms": "power_law_joint"}


def _from_cold(t, u, tau):
    """First-order lag tau dy/dt + y = ``u`` along the times ``t`` [s] (uniform), starting
    from y = 0 (not from the first input, as :func:`.truths._lag`)."""
    from scipy.signal import lfilter
    e = math.exp(-float(t[1] - t[0]) / tau)
    return lfilter([1.0 - e], [1.0, -e], np.asarray(u, float))


# -- acceleration ----------------------------------------------------------------------------
#: ``jerk_unloading``'s decay time of the carriage's normal vibration, x the motion's time
#: scale [-]; the levels' largest fall (the vibration's envelope E, |jerk| / its 99th
#: percentile, lagged, acting as E / (1 + E)) at strength 1 [-]; the lowest relative
#: level [-]
JERK_DECAY, JERK_DROP, JERK_FLOOR = 0.5, 0.5, 0.05


def _vibration_envelope(t, a, tau):
    """The envelope [-] of the normal vibration the jerk excites along the times ``t`` [s]
    of the accelerations ``a`` [m/s^2]: |da/dt| over its 99th percentile, through a
    first-order decay of time constant ``tau`` [s] (the contacts' damping), from rest."""
    j = np.abs(np.gradient(np.asarray(a, float), np.asarray(t, float)))
    j99 = float(np.percentile(j, 99.0))
    return _from_cold(t, j / max(j99, 1e-300), tau)


@on_fine_grid
def jerk_unloading_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Each change of the carriage's acceleration (its jerk) is an impulse of the drive's
    force that knocks the carriage into vibration normal to its guides (on the contacts'
    stiffness); the vibration decays with the contacts' damping (its envelope,
    :func:`_vibration_envelope`, with the decay time :data:`JERK_DECAY` x the motion's
    time scale). While the contact vibrates normally the mean friction falls (the contact
    is partly unloaded over each cycle). The Coulomb and Stribeck levels are the base's
    times 1 - ``s`` :data:`JERK_DROP` x E / (1 + E), E the envelope (the unloading
    saturates as the contact begins to lose touch; at least :data:`JERK_FLOOR`), inside
    the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the friction's sensitivity to the vibration (the contacts'
        compliance), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Normal vibrations and the fall of the mean friction (Tolstoi 1967, Significance of the
    normal degree of freedom and natural normal vibrations in contact friction, Wear 10;
    Hess and Soom 1991, Normal vibrations and friction under harmonic loads, J. Tribol.
    113). The candidate raises the levels with |a|,
    lagged, tilts them with a and adds a force odd in a; the open forms lag the velocity,
    a film or a contact state, heat the contact, skid rolling elements, move load between
    rows or supports, press seals, pull with the thrust, squeeze or starve films, dilate,
    lift on a wedge, shift a gib, soften an elastomer or swing a roller arm. Here the
    levels follow the rate of change of the acceleration, through a decaying memory:
    they fall after each jerk, whatever the acceleration is then.
    """
    if s <= 0.0:
        return _base_parts(kin)[0]
    T = max(_motion_time(kin), 1e-12)
    env = _vibration_envelope(kin.t, kin.a, JERK_DECAY * T)
    lev = np.clip(1.0 - float(s) * JERK_DROP * env / (1.0 + env), JERK_FLOOR, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- load ------------------------------------------------------------------------------------
#: ``overhung_load``'s supports' friction coefficients, the sliding pad's over the rolling
#: block's, less 1 [-]; the carriage's wheelbase over the stroke the record visits [-]; the
#: supports' share of the friction (the rest, the seals' and wipers', does not follow the
#: load) at strength 1 [-]; the lowest relative level [-]
PAD_EXCESS, WHEELBASE, SUPPORT_SHARE, OVERHUNG_FLOOR = 1.5, 1.5, 0.5, 0.05


def _pad_share(x, centre, span, base):
    """The share [-] of a load acting at ``centre`` [m] that the front support (the sliding
    pad) of a carriage at the positions ``x`` [m] carries: the supports sit ``base`` x
    ``span`` [m] apart, centred on the carriage (a beam on two supports: the share is the
    load's lever arm to the rear support over the wheelbase, in [0, 1])."""
    arm = 0.5 + (centre - np.asarray(x, float)) / (base * span)
    return np.clip(arm, 0.0, 1.0)


@on_fine_grid
def overhung_load_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The normal load acts at a fixed point of the frame (the mean position of the
    record) on a carriage with two supports :data:`WHEELBASE` x the stroke apart: a
    sliding pad in front and a rolling block behind, the pad's friction coefficient
    1 + :data:`PAD_EXCESS` times the block's. As the carriage moves under the load the
    reactions' shares change (:func:`_pad_share`), so the supports' friction is
    mu_b L (1 + :data:`PAD_EXCESS` share(x)), relative to its value at the record's mean
    load with the carriage centred under it: S(x, L). The supports carry a share ``s``
    :data:`SUPPORT_SHARE` of the friction (the rest, seals and wipers, does not follow the
    load): the Coulomb and Stribeck levels are the base's times 1 + ``s``
    :data:`SUPPORT_SHARE` (S - 1) (at least :data:`OVERHUNG_FLOOR`), inside the bristle
    dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], load [N]) and its base law.
    s : float
        Amplitude factor [-]: the supports' share of the friction, / its value at strength
        1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The statics of a beam on two supports and the load sharing of hybrid guideways (a
    sliding and a rolling support: Slocum 1992, Precision Machine Design; Weck and
    Brecher 2006, Werkzeugmaschinen 2). The candidate's levels are affine in the
    load (two regimes); the open forms scale them with a power of the load, in one
    direction, through the Stribeck velocity, a film, a step, a creep, a rate, a lever's
    play, a plastic area, a hinge, a cavitating film, a pressure-viscous film, an erf
    area, a flash temperature, a relay, a renewal over the slip or an adhesive area,
    each the same all along the stroke. Here the load's effect on the levels depends on
    where the carriage is: the same load change counts more at one end of the stroke.
    """
    L = np.asarray(kin.load, float)
    if not np.ptp(L) > 1e-9 * max(float(np.mean(np.abs(L))), 1e-300):
        raise ValueError(f"load (overhung_load): the {kin.plant} record's load does not "
                         f"change")
    if s <= 0.0:
        return _base_parts(kin)[0]
    x = np.asarray(kin.x, float)
    centre = float(np.mean(x))
    share = _pad_share(x, centre, _span(kin), WHEELBASE)
    r = L / max(float(np.mean(L)), 1e-300)
    supports = r * (1.0 + PAD_EXCESS * share) / (1.0 + 0.5 * PAD_EXCESS)
    lev = np.clip(1.0 + float(s) * SUPPORT_SHARE * (supports - 1.0), OVERHUNG_FLOOR, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``freewheel_roller``'s sliding roller's friction, x the base's friction levels, at
#: strength 1 [-]; the clutch's engagement travel, x the stroke the record visits [-]
ROLLER_FRICTION, ENGAGE_SHARE = 0.4, 0.02


@njit(cache=True)
def _engagement(x, travel):
    """The sprag clutch's engagement [-] (0 free, 1 locked) along the positions ``x`` [m]:
    moving in the positive direction it overruns (0 at once), moving in the negative one
    it engages linearly over the travel ``travel`` [m]. Starts free."""
    n = x.size
    out = np.empty(n)
    e = 0.0
    out[0] = e
    for k in range(1, n):
        dx = x[k] - x[k - 1]
        if dx > 0.0:
            e = 0.0
        elif dx < 0.0:
            e = min(e - dx / travel, 1.0)
        out[k] = e
    return out


@on_fine_grid
def freewheel_roller_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A pressure (hold-down) roller bears on the carriage through a one-way clutch
    bearing (a sprag freewheel in its hub): in the positive direction the clutch
    overruns and the roller rolls freely; in the negative one its sprags wedge after an
    engagement travel (:data:`ENGAGE_SHARE` x the stroke, :func:`_engagement`) and the
    locked roller slides on the carriage with its own friction, ``s``
    :data:`ROLLER_FRICTION` x the base's levels. The Coulomb and Stribeck levels are the
    base's times 1 + ``s`` :data:`ROLLER_FRICTION` x the engagement, inside the bristle
    dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the roller's pressing force (its sliding friction), / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Sprag and roller one-way clutches and their engagement (Orthwein 1986, Clutches and
    Brakes: Design and Selection); one-way (anti-rollback) rollers in conveyors and sheet
    feeders. The candidate shifts a direction's levels and
    viscous slope (and an offset); the open forms keep a direction's share, its Stribeck
    velocity, viscous slope or tail, roll a lip, follow a thrust, a film laid by the
    outstroke, a texture, a return spring, a wedge film, a strut, a throttle, a
    cylinder's areas, pumping grooves, a buckling cable, a scraper's pile, a commutation
    angle or an idler's tight span. Here one direction's extra friction is not there at
    once after a reversal into it: it builds up over a short travel, as the sprags
    wedge.
    """
    if s <= 0.0:
        return _base_parts(kin)[0]
    travel = max(ENGAGE_SHARE * _span(kin), 1e-12)
    e = _engagement(np.ascontiguousarray(kin.x, dtype=float), travel)
    lev = 1.0 + float(s) * ROLLER_FRICTION * e
    return level_inside(kin, lev, np.ones_like(lev))


# -- stribeck_shape --------------------------------------------------------------------------
#: ``churning_drag``'s drag at the knee at strength 1, x the friction level [-]; the knee's
#: speed (nu n = 2000 in Palmgren's rule), x v99 [-]
CHURN_DRAG, CHURN_KNEE = 0.15, 0.1


def _churning(u, knee):
    """Palmgren's churning law [-] at the relative speeds ``u`` [-] (>= 0): 1 below the knee
    ``knee`` [-] and (u / knee)^(2/3) above it, joined smoothly, (1 + (u / knee)^3)^(2/9)."""
    return (1.0 + (np.asarray(u, float) / knee) ** 3) ** (2.0 / 9.0)


@on_fine_grid
def churning_drag_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage's recirculating rolling elements run in grease or oil, which they
    churn: Palmgren's load-independent friction torque of rolling bearings, constant
    below a speed and growing as (nu n)^(2/3) above it (:func:`_churning`, the knee at
    :data:`CHURN_KNEE` x v99). That drag, ``s`` :data:`CHURN_DRAG` x the friction level x
    the law, adds to the Stribeck curve inside the bristle dynamics: a rise of the
    steady-state curve that bends the other way than a viscous term (sub-linear) and
    levels off at low speeds.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (a Stribeck curve).
    s : float
        Amplitude factor [-]: the lubricant's quantity and viscosity (Palmgren's f0), /
        its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The load-independent friction torque of rolling bearings, M0 = 1e-7 f0 (nu n)^(2/3)
    dm^3 for nu n >= 2000, 160e-7 f0 dm^3 below (Palmgren 1959, Ball and Roller Bearing
    Engineering; Harris and Kotzalas 2007, Rolling Bearing Analysis, ch. 9); the same
    law applied to the recirculating balls of linear guides (their makers' catalogues
    on the seal and lubricant drag). The candidate bends the base's drop (an exponent, the
    Lorentzian, a log-speed map); the open forms add tails, drops, a spike, a lift-off,
    a second drop, logarithmic weakening, Eyring strengthening, a rise at the top speed,
    a hump, a notch, a dither, a melt, a granular rise, re-adsorption, thermal thinning,
    a turbulent film and a thixotropic drag. Here the added drag is a two-thirds power of
    the speed above a knee and flat below it.
    """
    if kin.base.name == "mre_lugre":
        raise ValueError("stribeck_shape (churning_drag): the mre_lugre base has no "
                         "Stribeck curve")
    if s <= 0.0:
        return _base_parts(kin)[0]
    p = kin.base.params
    t = np.asarray(kin.t, float)
    v = np.asarray(kin.v, float)
    v99 = max(kin.scales["v99"], 1e-12)
    c = float(s) * CHURN_DRAG * _level(kin)
    vm = 0.5 * (v[1:] + v[:-1])
    g = kin.base.g(v) + c * _churning(np.abs(v) / v99, CHURN_KNEE)
    g_mid = kin.base.g(vm) + c * _churning(np.abs(vm) / v99, CHURN_KNEE)
    return _lugre_run(t, v, g, g_mid, float(p.sigma0), float(p.sigma1),
                      float(p.sigma2) * v)


# -- position --------------------------------------------------------------------------------
#: ``cam_plunger``'s lobe: its dwell's half-length and its ramps' length, x the stroke the
#: record visits [-]; the plunger's friction added on the dwell at strength 1, x the
#: friction level [-]; the ramps' force at their steepest at strength 1, x the friction
#: level [-]; the spring's preload, x its extra force on the dwell [-]
LOBE_HALF, LOBE_RAMP, CAM_FRICTION, CAM_FORCE, CAM_PRELOAD = 0.12, 0.06, 0.6, 0.6, 1.0


def _lobe(x, centre, half, ramp):
    """The cam's rise [-] (0 off the lobe, 1 on its dwell) at the positions ``x`` [m], and
    its slope [1/m]: a dwell of half-length ``half`` [m] around ``centre`` [m] between two
    ramps of length scale ``ramp`` [m] (tanh flanks)."""
    x = np.asarray(x, float)
    up = np.tanh((x - (centre - half)) / ramp)
    down = np.tanh((x - (centre + half)) / ramp)
    h = 0.5 * (up - down)
    dh = 0.5 * ((1.0 - up * up) - (1.0 - down * down)) / ramp
    return h, dh


@on_fine_grid
def cam_plunger_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A spring plunger (a ball or roller plunger, an indexing or limit-switch follower) on
    the carriage runs over a cam bar fixed on the frame where fit and held-out parts both
    pass (:func:`.truths._bump_centre`): a ramp up, a dwell :data:`LOBE_HALF` x the stroke
    either side, a ramp down (:func:`_lobe`). Over the lobe the plunger's spring is
    compressed: its normal force, and its sliding friction, rise (the levels are the
    base's times 1 + ``s`` :data:`CAM_FRICTION` h, inside the bristle dynamics, the
    viscous term the base's); on the ramps the cam's slope turns the spring's force into a
    force along the axis, ``s`` :data:`CAM_FORCE` x the friction level x (preload + h) x
    the ramp's slope (against the motion onto the lobe, with it off the lobe, whatever
    the direction).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the plunger spring's rate times the lobe's height, / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Cam-follower forces and the pressure angle (Norton 2009, Cam Design and Manufacturing
    Handbook); spring and indexing plungers (their makers' catalogues). The candidate scales the friction along the stroke and adds
    a periodic and a smooth force of x; the open forms are level maps, a periodic
    detent force, a cushion's drag, a cover's staircase, a gas spring, bolt holes, a
    plunger's drag in oil, a sagging beam's pull, a festoon's tension, a curve's
    centripetal load and a chain's gliding. Here one stretch of the stroke has both: a
    plateau of raised levels and, on its flanks, a conservative force that pushes back
    on the rise and forward on the fall.
    """
    xc = _bump_centre(kin)
    if xc is None:
        raise ValueError(f"position (cam_plunger): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    span = _span(kin)
    ramp = LOBE_RAMP * span
    h, dh = _lobe(kin.x, xc, LOBE_HALF * span, ramp)
    lev = 1.0 + float(s) * CAM_FRICTION * h
    Fl = _level(kin)
    # the cam's slope (ramp x dh / dx, at most 1/2) turns the spring's force along the axis
    along = float(s) * CAM_FORCE * Fl * (CAM_PRELOAD + h) * ramp * dh
    return level_inside(kin, lev, np.ones_like(lev)) + along


# -- inertia ---------------------------------------------------------------------------------
#: ``chordal_action``'s carriage mass, its inertial force at a99 x the friction level, at
#: strength 1 [-]; the sprocket's teeth [-]; the chain's pitch, x the stroke the record
#: visits [-]
CHAIN_MASS, SPROCKET_TEETH, CHAIN_PITCH = 1.0, 8, 0.2


def _chordal(x, pitch, teeth):
    """The chain's speed ratio kappa [-] (its mean 1) and its derivative along the
    sprocket's travel d kappa / dx [1/m] at the sprocket positions ``x`` [m]: the chain
    leaves a polygon of ``teeth`` sides, kappa ~ cos theta, theta running from -pi /
    ``teeth`` to pi / ``teeth`` over each ``pitch`` [m] and jumping back as the next tooth
    engages."""
    x = np.asarray(x, float)
    half = math.pi / teeth
    frac = np.mod(x / pitch, 1.0)
    theta = half * (2.0 * frac - 1.0)
    mean_cos = math.sin(half) / half
    kappa = np.cos(theta) / mean_cos
    dkappa = -np.sin(theta) / mean_cos * (2.0 * half / pitch)
    return kappa, dkappa


@on_fine_grid
def chordal_action_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage is pulled by a roller chain from a sprocket of
    :data:`SPROCKET_TEETH` teeth whose shaft carries the encoder (the record's motion is
    the sprocket's, scaled by its mean radius). The chain leaves the sprocket as from a
    polygon, so its speed is the sprocket's times kappa(x) ~ cos theta, pulsing once per
    pitch (:data:`CHAIN_PITCH` x the stroke, :func:`_chordal`): the carriage's acceleration
    is a kappa + v^2 d kappa / dx, not the measured a. The inverse dynamics subtracts
    m a; the record keeps m (a (kappa - 1) + v^2 d kappa / dx), m a99 = ``s``
    :data:`CHAIN_MASS` x the friction level.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the carriage's mass, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The polygonal (chordal) action of roller chain drives and its speed fluctuation
    1 - cos(pi / z) (Binder 1956, Mechanics of the Roller Chain Drive; ISO 10823:2004,
    Guidance on the selection of roller chain drives). The candidate's mass is constant, varies in time, along the stroke or with
    the squared speed, or holds a coupled part that slips; the open forms filter, flex
    behind the sensor, gear, lose, add fluid mass, dispense, slide a payload, rattle a
    part, freewheel, carry a payload between zones, couple through eddies, flyweights or
    a fluid, pick up a stage, stand on a recoiling frame or saturate the motor. Here the
    missed force is the carriage's mass times an acceleration the encoder never sees: a
    sawtooth of the position in v^2 plus a ripple of a.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    m = float(s) * CHAIN_MASS * _level(kin) / max(kin.scales["a99"], 1e-12)
    kappa, dkappa = _chordal(kin.x, CHAIN_PITCH * _span(kin), SPROCKET_TEETH)
    v = np.asarray(kin.v, float)
    return F + m * (np.asarray(kin.a, float) * (kappa - 1.0) + v * v * dkappa)


# -- delay -----------------------------------------------------------------------------------
#: ``mains_notch``'s notch frequency, x the data's sample rate [-]; the notch's width (1 /
#: its quality factor Q) at strength 1 [-]
NOTCH_SHARE, NOTCH_WIDTH = 0.05, 1.0


def _notch(t, F, f0, width):
    """``F`` [N] along the times ``t`` [s] (uniform) through the analogue notch
    (s^2 + w0^2) / (s^2 + ``width`` w0 s + w0^2), w0 = 2 pi ``f0`` [Hz], discretised by the
    bilinear transform (unit gain at zero frequency), from steady state at the first
    value."""
    from scipy.signal import bilinear, lfilter, lfilter_zi
    w0 = 2.0 * math.pi * f0
    fs = 1.0 / float(t[1] - t[0])
    b, a = bilinear([1.0, 0.0, w0 * w0], [1.0, width * w0, w0 * w0], fs)
    F = np.asarray(F, float)
    return lfilter(b, a, F, zi=lfilter_zi(b, a) * F[0])[0]


@on_fine_grid
def mains_notch_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force amplifier carries a second-order notch filter against the mains hum
    (:func:`_notch`), tuned to :data:`NOTCH_SHARE` x the data's sample rate (the 50 Hz of a
    1 kHz logger), its width 1 / Q = ``s`` :data:`NOTCH_WIDTH`: well below the notch the
    force passes with a phase lag of about omega / (Q omega0) (a delay of 1 / (Q omega0)),
    near it it is removed, above it it leads.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the notch's width (1 / Q), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Notch filters against power-line interference in strain-gauge and load-cell signal
    conditioning (Hoffmann 1989, An Introduction to Measurements using Strain Gages;
    Pallas-Areny and Webster 2001, Sensors and Signal Conditioning; the second-order
    notch, Oppenheim and Schafer 1989, Discrete-Time Signal Processing). The open forms delay by one amount,
    filter by a low-pass, linearly or by rank, hold at a fieldbus's clock, let the delay
    drift, wander or follow the force's rate, level or slowness, the motion's speed or
    the position, hold stale values over lost telegrams, lead through a leaking charge,
    creep, or shift the motion. Here the filter passes the steady force and the fast
    edges and takes out a band between them: a lag at the motion's frequencies that
    turns into a lead above the notch.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    f0 = NOTCH_SHARE / float(kin.sample_dt)
    return _notch(np.asarray(kin.t, float), F, f0, float(s) * NOTCH_WIDTH)


# -- drift -----------------------------------------------------------------------------------
#: ``tribocharging``'s charge's leakage time, x the record's length [-]; the levels' rise
#: at the charge of steady sliding at the record's mean speed, at strength 1 [-]
LEAK_TIME, CHARGE_RISE = 0.3, 0.4


@on_fine_grid
def tribocharging_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The sliding electrifies the insulating surfaces (a polymer liner, an anodised or
    coated rail): charge is separated at a rate ~ the sliding speed and leaks away
    through the surfaces' resistance with the time constant :data:`LEAK_TIME` x the
    record (from uncharged at its start, :func:`_from_cold`). The charges attract the
    surfaces with a pressure ~ the charge density squared (sigma^2 / (2 epsilon0)), an
    extra normal load: the Coulomb and Stribeck levels are the base's times 1 + ``s``
    :data:`CHARGE_RISE` (q / q_mean)^2, q_mean the charge of steady sliding at the
    record's mean speed, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the surfaces' charging (their triboelectric difference over
        their separation), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Contact and frictional electrification (Harper 1967, Contact and Frictional
    Electrification; Lowell and Rose-Innes 1980, Contact electrification, Adv. Phys. 29)
    and the electrostatic attraction it adds to the normal load (Johnsen and Rahbek 1923;
    Budakian and Putterman 2000, Correlation between charge transfer and stick-slip
    friction at a metal-insulator interface, Phys. Rev. Lett. 85). The candidate is a
    trend, a saturating change, a step, a cycle, an accelerating part and a part that
    builds up and resets, in time; the open forms warm up, wear in, step, cycle, rise and
    fall with debris, drop with grease shots, relax, oxidise, wear through, swell, grow a
    tribofilm, take in particles, expand, shear the oil or heat the magnets. Here the
    level follows the square of a quantity that builds with the sliding and leaks in
    time: up in busy stretches, down over dwells.
    """
    if s <= 0.0:
        return _base_parts(kin)[0]
    t = np.asarray(kin.t, float)
    u = np.abs(np.asarray(kin.v, float))
    u = u / max(float(np.mean(u)), 1e-300)
    q = _from_cold(t, u, LEAK_TIME * max(float(t[-1] - t[0]), 1e-12))
    lev = 1.0 + float(s) * CHARGE_RISE * q * q
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: ``reversing_clutch``'s engagement time constant at strength 1, x the motion's time scale
#: [-]; the engaged clutch's capacity, x the largest force of the base [-]
CLUTCH_TIME, CLUTCH_CAPACITY = 1.0, 3.0


@njit(cache=True)
def _reversing_clutch(h, xd, tau, cap_max, kh, ch, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a contact of mass ``m`` [kg] driven by the drive positions
    ``xd`` [m] (step ``h`` [s]) through a stiff coupling ``kh`` [N/m], ``ch`` [N s/m] and a
    clutch: after each reversal of the drive its capacity builds up as ``cap_max`` (1 -
    exp(-t / ``tau``)) [N]; while the coupling's spring force exceeds it the clutch slips
    (the spring's anchor follows, its force the capacity), otherwise it holds. Semi-implicit
    Euler of the mass (:func:`.truths._light_contact_step`). Starts at rest, engaged."""
    n = xd.size
    F = np.empty(n)
    v = 0.0
    z = 0.0
    xc = xd[0]
    off = 0.0
    d_last = 0.0
    since = 1e300
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        if vd != 0.0:
            d = 1.0 if vd > 0.0 else -1.0
            if d_last != 0.0 and d != d_last:
                since = 0.0
            d_last = d
        cap = cap_max * (1.0 - math.exp(-since / tau))
        fs_ = kh * (xd[j] - xc - off)
        if fs_ >= cap:
            off = xd[j] - xc - cap / kh
            fc = cap
        elif fs_ <= -cap:
            off = xd[j] - xc + cap / kh
            fc = -cap
        else:
            fc = fs_ + ch * (vd - v)
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha, shape)
        xc = xc + h * v
        since += h
    return F


@on_fine_grid
def reversing_clutch_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact coupled through the electromagnetic clutches of a reversing drive
    (one clutch per direction, :func:`_reversing_clutch`): at each reversal of the drive
    the released clutch lets go and the other's torque builds up with its coil's current,
    capacity :data:`CLUTCH_CAPACITY` x the base's largest force x (1 - exp(-t / tau)),
    tau = ``s``^3 :data:`CLUTCH_TIME` x the motion's time scale; until it transmits the contact's
    friction the clutch slips and the contact stands: a lost motion set by a time, so
    longer the faster the drive leaves the reversal. Engaged, the coupling is the stiff
    one of the other forms (:func:`.truths._contact_constants`). The contact is light,
    with the base's LuGre friction; the measured force is its friction. At ``s`` = 0 the
    base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the cube root of the clutch's engagement time, / its value
        at strength 1 (the lost motion's share of the record grows slowly with it).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Electromagnetic clutches' torque build-up after switching (the coil's L / R and the
    armature's pull-in; Orthwein 1986, Clutches and Brakes; the engagement times of
    makers' catalogues, e.g. Warner Electric's); reversing clutch drives of presses and
    machine tools (Schuler 1998, Metal Forming Handbook). The candidate holds
    or frees the force across a play, with a bias, a spring or a drag across it; the open
    forms couple rigidly, compliantly, by impacts, springs, oil in the play, an idler, a
    bias, chains, magnets, a preload, a hardening gear, a slipping rope, a rubber spider,
    an oil column or a cable in a sheath, with a play varying with the position or the
    travel. Here the lost motion is not a distance: the drive runs free for a time after
    each reversal and the contact follows once the clutch holds.
    """
    p = _lugre_params(kin, "backlash (reversing_clutch)")
    if s <= 0.0:
        return _base_parts(kin)[0]
    m, kh, ch = _contact_constants(kin, p)
    tau = float(s) ** 3 * CLUTCH_TIME * max(_motion_time(kin), 1e-12)
    # the engaged clutch holds the largest force the base's contact asks for
    cap_max = CLUTCH_CAPACITY * float(np.max(np.abs(_base_parts(kin)[0])))
    h, xd, n_sub = _substeps(kin, max(math.sqrt((kh + float(p.sigma0)) / m),
                                      (float(p.sigma1) + float(p.sigma2) + ch) / m))
    F = _reversing_clutch(h, xd, tau, cap_max, kh, ch, m,
                          float(p.sigma0), float(p.sigma1), float(p.sigma2), float(p.Fc),
                          float(p.Fs), float(p.vs), float(p.alpha), SHAPES[p.shape])
    return F[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: the joint's travel to macro-slip at strength 1, beyond the base bristle's path, as a
#: share of the stroke / 3 [-]; its share of the friction at strength 1 [-]; Segalman's
#: exponent chi of the slip-strength density [-]; the share of the joint slipping at once
#: at macro-slip [-]; the Iwan elements of the density's power-law part [-]
JOINT_SLIP, JOINT_SHARE, JOINT_CHI, MACRO_SHARE, JOINT_ELEMENTS = 0.1, 0.7, -0.5, 0.3, 24


def _slip_strengths(chi, macro, n_el):
    """The slip strengths [-] (over the macro-slip one) of an Iwan joint and their weights
    [-] (summing to 1): Segalman's density R phi^chi on (0, 1] at ``n_el`` mid-quantiles,
    weight 1 - ``macro``, and the macro-slip strength 1 with weight ``macro``."""
    u = (np.arange(n_el) + 0.5) / n_el
    phi = np.append(u ** (1.0 / (chi + 1.0)), 1.0)
    w = np.append(np.full(n_el, (1.0 - macro) / n_el), macro)
    return phi, w


@njit(cache=True)
def _iwan(x, phi, w, ud):
    """The Iwan joint's force f [-] (1 at macro-slip) along the positions ``x`` [m]: element
    j of weight ``w``[j] has stiffness ``w``[j] / ``ud`` and slips at the force ``w``[j]
    ``phi``[j] (at the travel ``phi``[j] ``ud`` [m]); all elements slip at the travel
    ``ud``. Starts unloaded."""
    n = x.size
    m = phi.size
    q = np.zeros(m)
    out = np.empty(n)
    out[0] = 0.0
    full = max(np.sum(w * phi), 1e-300)
    for k in range(1, n):
        dx = x[k] - x[k - 1]
        tot = 0.0
        for j in range(m):
            cap = w[j] * phi[j]
            qj = q[j] + w[j] * dx / ud
            if qj > cap:
                qj = cap
            elif qj < -cap:
                qj = -cap
            q[j] = qj
            tot += qj
        out[k] = tot / full
    return out


@on_fine_grid
def power_law_joint_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The presliding junctions beside the bristle behave as a bolted lap joint:
    Segalman's four-parameter Iwan model, a density of slip strengths R phi^chi (chi =
    :data:`JOINT_CHI`) up to the macro-slip strength plus a share :data:`MACRO_SHARE` that
    slips only there (:func:`_slip_strengths`, discretised in :data:`JOINT_ELEMENTS`
    elements, :func:`_iwan`). Loaded from a reversal its stiffness softens as the travel
    to the power chi + 1 and its loops dissipate as their amplitude to the power 3 + chi
    (Masing's rule of the parallel elements). The travel to macro-slip is the base
    bristle's path Fs / sigma0 plus ``s`` :data:`JOINT_SLIP` x the stroke / 3; a share w
    = :data:`JOINT_SHARE` min(``s``, 1) of the friction is the joint's (its sliding force
    the Stribeck level, the viscous term the base's): F = (1 - w) F_lugre + w (g(v) f +
    sigma2 v). At ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the joint's share (up to ``s`` = 1) and its travel to
        macro-slip (as the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Segalman 2005, A four-parameter Iwan model for lap-type joints, J. Appl. Mech. 72;
    Iwan 1966, A distributed-element model for hysteresis, J. Appl. Mech. 33; the power
    law of the dissipation in bolted joints (Smallwood, Gregory and Coleman 2000, Damping
    investigations of a simplified frictional shear joint; Ungar 1973). Maxwell-slip (the
    candidate) and the open forms use equal or geometric strengths, path laws, an
    elastic range, rate-dependent creep, Mindlin's 3/2 law, multistable tips, bonds, a
    fabric, a back-stress, a climb out of a nest, capillary bridges, a hardening yield,
    peeling junctions or load-dependent microslip; here the strengths follow a singular
    power-law density with a lump at macro-slip: the loop's tip is softer at once, its
    dissipation grows as the amplitude to the 2.5, and it ends in a kink.
    """
    p = _lugre_params(kin, "gms (power_law_joint)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, JOINT_SLIP)
    w = JOINT_SHARE * min(float(s), 1.0)
    v = np.asarray(kin.v, float)
    phi, wt = _slip_strengths(JOINT_CHI, MACRO_SHARE, JOINT_ELEMENTS)
    f = _iwan(np.ascontiguousarray(kin.x, dtype=float), phi, wt, e0 + extra)
    return (1.0 - w) * F + w * (kin.base.g(v) * f + float(p.sigma2) * v)
