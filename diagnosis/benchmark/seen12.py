"""The twelfth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-29 (early in session 18) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 18's work on the code of f5cb1e9:
176 cases, 0 skipped, 1093 s wall on 1 worker (beside two grid runs). Top-1 29.5 % (52;
30.6 % of the 170 detectable; 6 delay cases below a sample); mean |shrink error| 0.359;
wrong names on 28 (15.9 %): inertia -> acceleration 6, load -> asymmetry 5, position ->
acceleration 3, load -> acceleration 3, position -> inertia 2, backlash -> delay 2,
gms -> acceleration 2. By form: acceleration/tilt_wedge 13/20, delay/aerated_load_cell
11/20, inertia/fluid_coupling 9/20, stribeck_shape/readsorption 8/16,
gms/capillary_bridges 5/12, asymmetry/helical_buckling 4/20, drift/particle_ingress 2/20,
load/flash_desorption 0/20, position/beam_sag 0/16, backlash/wire_rope 0/12. By plant:
press 60.7 %, isolator 28.6 %, valve 30.0 %, XML-350 27.5 %, damping rig 10.0 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen11` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen11`,
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
acceleration       ``tilt_wedge``: the acceleration's moment pitches the carriage on its
                   compliant plain pads; speeding up, the leading edge rises and the
                   pads form converging wedges whose hydrodynamic lift (Reynolds 1886;
                   Michell's inclined pad, 1905) grows with the speed and, as the
                   inclined pad's load function, first with and then against the tilt:
                   the levels fall while the carriage speeds up, not while it brakes
load               ``flash_desorption``: the adsorbed boundary film desorbs where the
                   flash temperature of the asperity contacts (Blok 1937; Jaeger 1942;
                   at high Peclet number and Hertzian contacts ~ sqrt(load x speed),
                   Archard 1959) passes the film's critical temperature (Frewing 1944):
                   the levels step up in the heavily loaded fast strokes, not at rest
asymmetry          ``helical_buckling``: a cable (a hose, a push-pull rod) dragged in a
                   channel by the carriage: pulled, it slides with its weight's
                   friction; pushed, it buckles into a helix whose wall contact force
                   grows as the square of its compression (Lubinski 1962), and its
                   friction grows as tan of its length towards lock-up (Wu and
                   Juvkam-Wold 1995): one direction drags more, more along the stroke
stribeck_shape     ``readsorption``: the boundary lubricant re-adsorbs on a spot in the
                   time between two asperity encounters (Kingsbury 1960; Rowe 1966):
                   the faster the sliding, the less of the surface is covered at the
                   next encounter, and the levels rise towards the bare metal's as
                   exp(-v_a / |v|): flat at low speed, then a step up in log-speed
position           ``beam_sag``: the carriage runs on a beam (a gantry's cross-beam)
                   that sags under it: at every position it sits in its own deflection,
                   and moving on takes its weight times the slope there (a moving load
                   on an elastic beam, Timoshenko 1922): a force of the position alone,
                   drawing the carriage towards the middle of the span, both ways
inertia            ``fluid_coupling``: a rotating part driven through a hydrodynamic
                   (Foettinger) fluid coupling, whose torque follows the difference of
                   the two wheels' heads, ~ omega |omega|: at speed a tightly coupled,
                   lagged mass; near rest and through the reversals the coupling all but
                   lets go and the part coasts
delay              ``aerated_load_cell``: the force read as the pressure of a preloaded
                   hydraulic load cell through a damping restrictor, the transducer's
                   oil holding entrained air: the air's compliance ~ 1 / p^2 (Merritt
                   1967) makes the lag long at low pressure and short at high: a delay
                   set by the force's own level, longest at its most negative
drift              ``particle_ingress``: contaminant particles swept into the contact at
                   random points of the record's travel embed in the softer surface
                   and plough it until they are worn down or ejected over a tenth of
                   the travel (Nikas 2010): the levels jump up at each ingress and
                   decay with the sliding, in a sequence fixed by its seed
backlash           ``wire_rope``: drive and contact joined by a wire rope (a cable
                   drive) whose strands stick, then slip on each other as the load
                   changes (Costello 1997; Bouc-Wen for wire-rope elements, Demetriades,
                   Constantinou and Reinhorn 1993): after each reversal the force turns
                   fast while the strands stick and slowly once they slip: a lost motion
                   through a hysteretic, softening coupling
gms                ``capillary_bridges``: capillary bridges of condensed water around the
                   asperity contacts whose contact lines stay pinned (contact-angle
                   hysteresis, Furmidge 1962) until the bridges' tilt reaches the
                   advancing angle, then slide: beside the bristle, a presliding force
                   2 gamma w sin(theta) sin(phi) of the tilt phi, a play of the travel;
                   at ``s`` = 0 the base itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``readsorption`` needs a
Stribeck curve (not the isolator's mre_lugre), ``beam_sag`` a record that revisits its
positions (not the press), ``flash_desorption`` a load that changes, ``wire_rope`` and
``capillary_bridges`` a classic LuGre base (valve, damping rig, XML-350); each raises a
``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.shapes import SHAPES

from ..effects_backlash import PLANT_GAP_SHARE
from .kinematics import PlantKinematics
from .seen11 import _direction, _nest_offset
from .truths import (_base_parts, _bump_centre, _contact_constants, _level,
                     _light_contact_step, _lugre_params, _motion_time, _presliding_path,
                     _smooth_max0, _span, _substeps, level_inside, on_fine_grid)

__all__ = ["FORMS", "tilt_wedge_truth", "flash_desorption_truth", "helical_buckling_truth",
           "readsorption_truth", "beam_sag_truth", "fluid_coupling_truth",
           "aerated_load_cell_truth", "particle_ingress_truth", "wire_rope_truth",
           "capillary_bridges_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "tilt_wedge", "load": "flash_desorption",
         "asymmetry": "helical_buckling", "stribeck_shape": "readsorption",
         "position": "beam_sag", "inertia": "fluid_coupling",
         "delay": "aerated_load_cell", "drift": "particle_ingress",
         "backlash": "wire_rope", "gms": "capillary_bridges"}


# -- acceleration ---------------------------------------------------------------------------
#: ``tilt_wedge``'s convergence ratio K = (h_in - h_out) / h_out of the pads at a99 speeding
#: up [-] (beyond K = 1.19 the inclined pad's load falls again); the levels' fall at v99
#: and the load function's peak at strength 1 [-]; the lowest relative level [-]
TILT_CONVERGENCE, WEDGE_LIFT, WEDGE_FLOOR = 2.0, 0.6, 0.05


def _inclined_pad_load(K):
    """The load function [-] of Michell's inclined plane pad of convergence ratio ``K``
    [-] (>= 0; the gap falls from (1 + K) h_0 to h_0 in the sliding direction): W h_0^2 /
    (eta U B^2 L) = (6 / K^2) (ln(1 + K) - 2 K / (2 + K)); K / 2 - 3 K^2 / 4 below 1e-3
    (its series). 0 for a parallel gap, its largest (0.160) at K = 1.19."""
    K = np.maximum(np.asarray(K, float), 0.0)
    small = K < 1e-3
    Ks = np.where(small, 1.0, K)
    exact = 6.0 / (Ks * Ks) * (np.log1p(Ks) - 2.0 * Ks / (2.0 + Ks))
    return np.where(small, 0.5 * K - 0.75 * K * K, exact)


#: the inclined pad's largest load function value [-] (at K = 1.19)
PAD_LOAD_MAX = float(np.max(_inclined_pad_load(np.linspace(0.5, 2.5, 20001))))


@on_fine_grid
def tilt_wedge_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A carriage on oil-lubricated plain pads, pitched by the acceleration's moment on the
    pads' compliance (quasi-static: the pitch modes are far faster than the motion).
    Speeding up (a v > 0), the leading edge rises and each pad forms a converging wedge of
    convergence ratio K = :data:`TILT_CONVERGENCE` max(a sgn(v), 0) / a99 (the direction
    rounded over 2 % of v99, the hinge over 2 % of a99); braking, it diverges and lifts
    nothing (the film cavitates). The wedge's hydrodynamic load, eta U B^2 L f(K) / h_0^2
    (:func:`_inclined_pad_load`, h_0 set by the asperities), takes that much load off the
    asperities: the Coulomb and Stribeck levels are the base's times 1 - ``s``
    :data:`WEDGE_LIFT` (|v| / v99) f(K) / f_max (at least :data:`WEDGE_FLOOR`), inside the
    bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the pads' lift per unit of speed and load function (their
        width squared over the film's), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The wedge term of Reynolds' equation (Reynolds 1886, On the theory of lubrication,
    Phil. Trans. R. Soc. 177) and the inclined plane pad's load (Michell 1905, Z. Math.
    Phys. 52; Cameron 1981, Basic Lubrication Theory, ch. 4); the pitch of a carriage under
    its inertial moment. The candidate adds a force odd in a fading with the speed and
    raises the levels with |a|, lagged; the open forms lag the velocity, a film's speed or
    a contact state, heat the contact, skid rolling elements, move load between ball rows
    or supports, press a seal, pull the carriage with the thrust, squeeze the films by the
    tilt's rate, starve the contact by a sloshing bath or dilate its pores. Here the
    levels fall only while the carriage speeds up, in proportion to the speed, and not
    monotonically in |a|: a harder start tilts the pads past their best wedge.
    """
    v = np.asarray(kin.v, float)
    v99 = max(kin.scales["v99"], 1e-12)
    a99 = max(kin.scales["a99"], 1e-12)
    up = _smooth_max0(np.asarray(kin.a, float) * _direction(kin) / a99, 0.02)
    lift = np.abs(v) / v99 * _inclined_pad_load(TILT_CONVERGENCE * up) / PAD_LOAD_MAX
    lev = 1.0 - max(float(s), 0.0) * WEDGE_LIFT * lift
    return level_inside(kin, np.clip(lev, WEDGE_FLOOR, None), np.ones_like(lev))


# -- load -------------------------------------------------------------------------------------
#: ``flash_desorption``'s critical flash temperature, relative to that of the mean load at
#: v99 [-]; the width of the film's desorption in it [-]; the levels' rise where the film
#: has desorbed at strength 1 [-]
DESORPTION_AT, DESORPTION_WIDTH, DESORPTION_RISE = 1.0, 0.04, 0.8


def _desorbed(L, v, at, width):
    """The share [-] of the boundary film desorbed at the relative loads ``L`` [-] and
    speeds ``v`` [-] (over the mean load and v99): the flash temperature of Hertzian
    contacts at high Peclet number, ~ sqrt(L |v|) relative to that of the mean load at
    v99, against the film's critical temperature ``at`` [-], desorbing over ``width`` [-]
    as a Langmuir film's coverage, 1 / (1 + exp(-(T - T_c) / width))."""
    T = np.sqrt(np.clip(np.asarray(L, float), 0.0, None) * np.abs(np.asarray(v, float)))
    return 0.5 * (1.0 + np.tanh(0.5 * (T - at) / width))


@on_fine_grid
def flash_desorption_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """An adsorbed boundary film (a fatty acid, a friction modifier) that desorbs where the
    asperity contacts' flash temperature passes its critical temperature: the flash
    temperature of a moving heat source mu L v over Hertzian contacts (radius ~ L^(1/3)) at
    high Peclet number is ~ L^(1/2) |v|^(1/2), here relative to that of the mean load at
    v99; the film's critical temperature is :data:`DESORPTION_AT` of it, its desorption
    :data:`DESORPTION_WIDTH` wide (:func:`_desorbed`). Where it has desorbed the metal
    touches: the Coulomb and Stribeck levels are the base's times 1 + ``s``
    :data:`DESORPTION_RISE` x the desorbed share, inside the bristle dynamics; the
    viscous term is the base's. ValueError if the load does not change.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], load [N]) and its base law.
    s : float
        Amplitude factor [-]: the bare metal's friction over the film's, minus 1, /
        :data:`DESORPTION_RISE`.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Blok's critical temperature hypothesis (Blok 1937, Theoretical study of temperature
    rise at surfaces of actual contact under oiliness lubricating conditions, Proc. Inst.
    Mech. Eng. General Discussion on Lubrication 2); moving heat sources (Jaeger 1942,
    Proc. R. Soc. N.S.W. 76; Archard 1959, The temperature of rubbing surfaces, Wear 2);
    the desorption of boundary films at a critical temperature (Frewing 1944, Proc. R. Soc.
    A 182; Bowden and Tabor 1950, The Friction and Lubrication of Solids). The candidate's
    levels are affine in the load (with a direction's slope, a viscous slope and a memory
    over the travel); the open forms are powers, one direction, a square-root viscous term,
    the Stribeck velocity, a logistic step of the load, a creep in time, the load's rate,
    a play, a ratchet with the travel, a hinge at a capacity, a lag while it rises, an
    exponential viscous term and a saturating contact area. Here the load acts through the
    speed: at rest and in slow strokes it changes nothing, in fast ones it decides whether
    the film holds.
    """
    L = np.asarray(kin.load, float)
    L0 = max(float(np.mean(np.abs(L))), 1e-12)
    # a change below 1e-6 of the mean load over the record is round-off, not a change
    if float(np.ptp(L)) <= 1e-6 * L0:
        raise ValueError(f"load (flash_desorption): the {kin.plant} record's load does not "
                         f"change")
    v = np.asarray(kin.v, float) / max(kin.scales["v99"], 1e-12)
    phi = _desorbed(L / L0, v, DESORPTION_AT, DESORPTION_WIDTH)
    lev = 1.0 + max(float(s), 0.0) * DESORPTION_RISE * phi
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``helical_buckling``'s channel entry below the stroke the record visits, x that stroke
#: [-] (the cable's length in the channel runs from it to the carriage); the cable's
#: B l (its length over its lock-up length, x pi / 2) at the stroke's far end [-]; the
#: largest B l (the drive's force limit near lock-up) [-]; the pushed cable's drag at the
#: stroke's middle at strength 1, x the friction level [-]
CHANNEL_ENTRY, BUCKLING_REACH, BUCKLING_MAX, BUCKLING_DRAG = 4.0, 1.0, 1.45, 0.6


def _cable_drag(ell, direction, B):
    """The drag [-] (per unit of the cable's A = sqrt(4 E I w / r)) of a cable ``ell`` [m]
    long in its channel, moved along it: pulled (``direction`` 1), the friction of its
    weight, mu w l = A B l; pushed (-1), helically buckled: dF/dl = mu (w + r F^2 / (4 E
    I)), F = A tan(B l) (B = mu sqrt(w r / (4 E I)) [1/m], B l at most
    :data:`BUCKLING_MAX`); in between (a rounded direction) their blend. Positive: it
    opposes the motion."""
    Bl = np.minimum(B * np.asarray(ell, float), BUCKLING_MAX)
    d = np.asarray(direction, float)
    return 0.5 * (1.0 + d) * Bl + 0.5 * (1.0 - d) * np.tan(Bl)


@on_fine_grid
def helical_buckling_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A cable (a hose, a push-pull rod) fixed to the carriage and dragged in a channel
    whose entry lies :data:`CHANNEL_ENTRY` strokes below the stroke the record visits: the
    length in the channel is l = x - x_e. Moving up (v > 0) the carriage pulls it, and it
    slides with the friction of its weight; moving down it pushes it, the cable buckles
    into a helix against the channel's wall, and the wall's contact force, r F^2 / (4 E I)
    per length, makes the compression grow as tan(B l) (:func:`_cable_drag`), B set so
    that B l is :data:`BUCKLING_REACH` at the stroke's far end. The drag, opposing the
    motion (the direction rounded over 2 % of v99), is added to the base's force; at
    strength 1 the pushed cable's at the stroke's middle is :data:`BUCKLING_DRAG` x the
    friction level.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the cable's weight per length (its bending stiffness in
        proportion: its lock-up length fixed), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The wall contact force of a helically buckled tube (Lubinski, Althouse and Logan 1962,
    Helical buckling of tubing sealed in packers, J. Petrol. Technol. 14) and the lock-up
    of coiled tubing pushed along a horizontal well (Wu and Juvkam-Wold 1995, Coiled tubing
    buckling implication in drilling and completing horizontal wells, SPE Drilling and
    Completion 10); push-pull cables and hoses dragged along with a carriage. The
    candidate shifts a direction's levels and viscous slope (and an offset); the open forms
    keep a direction's share, move its Stribeck velocity, viscous slope or tail, roll a
    lip, follow a thrust, a film laid by the outstroke, a texture, a return spring, a wedge
    film, a strut, a throttle, a cylinder's areas or grooves that pump. Here the direction
    pushed drags more, the more the longer the cable pushed: tan of the length, near its
    lock-up.
    """
    F, _ = _base_parts(kin)
    span = _span(kin)
    ell = np.asarray(kin.x, float) - (kin.scales["x_lo"] - CHANNEL_ENTRY * span)
    B = BUCKLING_REACH / ((CHANNEL_ENTRY + 1.0) * span)
    A = BUCKLING_DRAG * _level(kin) / math.tan(B * (CHANNEL_ENTRY + 0.5) * span)
    drag = _cable_drag(ell, _direction(kin), B)
    return F + max(float(s), 0.0) * A * _direction(kin) * drag


# -- stribeck_shape --------------------------------------------------------------------------
#: ``readsorption``'s speed v_a = lambda / tau_a (the asperities' spacing over the
#: lubricant's adsorption time), x v99 [-]; the bare metal's levels over the covered
#: surface's, minus 1, at strength 1 [-]
READSORPTION_SPEED, BARE_RISE = 0.5, 0.6


def _uncovered(v, va):
    """The share [-] of the surface left bare at the next asperity encounter at the speeds
    ``v`` [m/s]: a spot exposed for t_e = lambda / |v| re-adsorbs the lubricant as 1 -
    exp(-t_e / tau_a) (first-order adsorption), so exp(-``va`` / |v|), ``va`` = lambda /
    tau_a [m/s]; 0 at rest."""
    a = np.abs(np.asarray(v, float))
    return np.exp(-va / np.maximum(a, 1e-300))


@on_fine_grid
def readsorption_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A boundary lubricant (an additive adsorbing from the oil) that the asperity
    encounters strip off and that re-adsorbs between two of them: a spot is exposed for
    the time lambda / |v| between encounters and is covered again as 1 - exp(-t / tau_a),
    so the share left bare at the next encounter is exp(-v_a / |v|) (:func:`_uncovered`;
    v_a = :data:`READSORPTION_SPEED` v99). The bare share rubs metal on metal: the Stribeck
    curve is the base's times 1 + ``s`` :data:`BARE_RISE` exp(-v_a / |v|), inside the
    bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (a Stribeck curve).
    s : float
        Amplitude factor [-]: the bare metal's levels over the covered surface's, minus 1,
        / :data:`BARE_RISE`.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The coverage of a boundary lubricant set by the time between asperity encounters and
    its adsorption rate (Kingsbury 1960, Heat of adsorption of a boundary lubricant, ASLE
    Trans. 3; Rowe 1966, Some aspects of the heat of adsorption in the function of a
    boundary lubricant, ASLE Trans. 9). The candidate bends the base's drop (an exponent,
    the Lorentzian, a log-speed map over 2.5 decades); the open forms add tails, drops, a
    spike, a lift-off, a second drop, a logarithmic weakening, an Eyring strengthening, a
    rise at the top speed, a hump, a notch, a dither's loss of stiction, a melt's fall
    and a granular layer's rational rise from rest. Here nothing changes at low speed
    (flat to all orders: exp(-v_a / |v|)), then the levels step up over a decade of speed
    towards the bare metal's.
    """
    if kin.base.name == "mre_lugre":
        raise ValueError("stribeck_shape (readsorption): the mre_lugre base has no "
                         "Stribeck curve")
    va = READSORPTION_SPEED * max(kin.scales["v99"], 1e-12)
    lev = 1.0 + max(float(s), 0.0) * BARE_RISE * _uncovered(kin.v, va)
    return level_inside(kin, lev, np.ones_like(lev))


# -- position --------------------------------------------------------------------------------
#: ``beam_sag``'s supports beyond the stroke the record visits, each x that stroke [-];
#: the largest force of the sag at strength 1 (the carriage's weight times the beam's
#: largest slope under it), x the friction level [-]
SUPPORT_MARGIN, SAG_FORCE = 0.1, 0.8


def _sag_pull(u):
    """The slope [-] of a simply supported beam under a point load at the share ``u`` [-]
    of its span, at the load, over its largest value: P a b (b - a) / (3 E I L) with a =
    u L, b = (1 - u) L, i.e. u (1 - u) (1 - 2 u) over its peak (at u = 1/2 - sqrt(3)/6);
    0 at the supports and at midspan, odd about midspan. The load sits in its own
    deflection, so moving it on takes P times this slope (the work into the beam)."""
    u = np.clip(np.asarray(u, float), 0.0, 1.0)
    peak = (0.5 - math.sqrt(3.0) / 6.0) * (0.5 + math.sqrt(3.0) / 6.0) * math.sqrt(3.0) / 3.0
    return u * (1.0 - u) * (1.0 - 2.0 * u) / peak


@on_fine_grid
def beam_sag_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage runs on a beam (a gantry's cross-beam, a bridge rail) simply supported
    :data:`SUPPORT_MARGIN` x the stroke beyond each end of the stroke the record visits,
    which sags under the carriage's weight P: at every position the carriage sits in its
    own deflection, whose slope under it is P a b (b - a) / (3 E I L) (:func:`_sag_pull`).
    Its potential energy falls towards midspan, so the beam draws it there with P times
    that slope: the drive's force is the base's minus that pull, whatever the direction of
    motion and at rest alike; its largest at strength 1 is :data:`SAG_FORCE` x the
    friction level. The contact's friction is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: P^2 L^2 / (E I), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The moving load on an elastic beam (Timoshenko 1922, On the forced vibrations of
    bridges, Phil. Mag. 43; Fryba 1972, Vibration of Solids and Structures under Moving
    Loads), here quasi-static; gantries and bridge cranes whose carriages run towards the
    middle of a sagging beam. The candidate scales the friction along the stroke (a map, a
    waviness of two harmonics, a defect) and adds a periodic force of x; the open forms are
    level maps (a defect, waviness, a worn section, runout, a bow, a transfer film, a
    taper, a port's wake), a periodic detent force, a cushion's orifice drag, a cover's
    staircase, a trapped gas spring, a seal over bolt holes and a plunger's Couette drag.
    Here one force of the position alone over the whole stroke, odd about the span's
    middle (the cubic of the beam's influence line), not periodic and not a level.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (beam_sag): the held-out part of the {kin.plant} record "
                         f"never revisits the positions of its fit part")
    F, _ = _base_parts(kin)
    span = _span(kin)
    lo = kin.scales["x_lo"] - SUPPORT_MARGIN * span
    u = (np.asarray(kin.x, float) - lo) / ((1.0 + 2.0 * SUPPORT_MARGIN) * span)
    return F - max(float(s), 0.0) * SAG_FORCE * _level(kin) * _sag_pull(u)


# -- inertia ---------------------------------------------------------------------------------
#: ``fluid_coupling``'s part mass at strength 1, x the friction level / a99 [kg per N s^2/m];
#: the coupling's lag at v99 (the part's mass over its torque's slope in the slip there), x
#: the motion's time scale [-]; the part's own spin-down time on its bearings, x the
#: motion's time scale [-]
FLUID_MASS, FLUID_LAG, SPIN_DOWN = 0.4, 0.2, 20.0


@njit(cache=True)
def _fluid_part(t, v, vc, tau_d):
    """The speed [m/s] of a part driven through a fluid coupling along the axis speeds
    ``v`` [m/s] at the times ``t`` [s]: w' = (v |v| - w |w|) / ``vc`` - w / ``tau_d``
    (``vc`` [m], the coupling's torque over the part's mass ~ the difference of the wheels'
    heads; ``tau_d`` [s] its spin-down on its bearings), the w |w| and w terms taken at the
    new step (stable at any step). Starts at the axis's speed."""
    n = t.size
    w = np.empty(n)
    w[0] = v[0]
    for k in range(1, n):
        h = t[k] - t[k - 1]
        w[k] = (w[k - 1] + h * v[k] * abs(v[k]) / vc) / (1.0 + h * abs(w[k - 1]) / vc
                                                          + h / tau_d)
    return w


@on_fine_grid
def fluid_coupling_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A rotating part (a drum, a roll) driven from the axis through a hydrodynamic fluid
    coupling: the torque is the difference of the wheels' heads, ~ omega_p |omega_p| -
    omega_t |omega_t| (Euler's turbine equation; the coupling's similarity law, T ~ rho
    omega^2 D^5 at a given slip), so in axis units the part's speed w follows w' = (v |v| -
    w |w|) / v_c (:func:`_fluid_part`; it spins down on its bearings over
    :data:`SPIN_DOWN` x the motion's time scale): linearised, a lag v_c / (2 |v|),
    :data:`FLUID_LAG` x the motion's time scale at v99, longer the slower the axis. The
    inverse dynamics misses the force the coupling takes, m (v |v| - w |w|) / v_c, m =
    ``s`` :data:`FLUID_MASS` x the friction level / a99; it is added to the base's force.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the part's mass (the coupling's size with it: its lag
        fixed), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Hydrodynamic couplings (Foettinger 1905, the fluid transmitter; its torque ~ rho omega^2
    D^5 lambda(slip)); conveyor and drum drives started through fluid couplings. The
    candidate and the open forms are masses (constant, filtered, along the stroke, through
    a ratio or a lossy gear, in time, behind a spring, in a fluid, with the speed), a
    payload held by Coulomb friction or carried between two zones, a part rattling in a
    pocket, a flywheel through a freewheel and a part behind an eddy-current coupling,
    whose force follows the slip speed whatever the speed; here the coupling's stiffness in
    the slip grows with the speed itself: at speed the part follows closely, near rest the
    coupling transmits almost nothing and through a reversal the part runs on.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    T = max(_motion_time(kin), 1e-12)
    v = np.ascontiguousarray(kin.v, dtype=float)
    vc = 2.0 * max(kin.scales["v99"], 1e-12) * FLUID_LAG * T
    w = _fluid_part(np.ascontiguousarray(kin.t, dtype=float), v, vc, SPIN_DOWN * T)
    m = float(s) * FLUID_MASS * _level(kin) / max(kin.scales["a99"], 1e-12)
    return F + m * (v * np.abs(v) - w * np.abs(w)) / vc


# -- delay -----------------------------------------------------------------------------------
#: ``aerated_load_cell``'s lag at the cell's preload pressure (zero force) at strength 1
#: [data samples]; the preload, x the record's largest |force| (the pressure is p_0 (1 +
#: F / F_p)) [-]
AIR_LAG, CELL_PRELOAD = 3.0, 2.5


@njit(cache=True)
def _aerated_lag(t, F, tau0, Fp):
    """What the transducer reads [N] of the force ``F`` [N] at the times ``t`` [s]: the
    pressure p = p_0 (1 + F / ``Fp``) reaches it through a restrictor into a volume whose
    entrained air's compliance is ~ (p_0 / p)^2 (isothermal gas), so its reading y lags by
    tau(y) = ``tau0`` / (1 + y / ``Fp``)^2 [s], exact for each step at that lag (the
    pressure at least 1e-3 p_0). Starts at the first force."""
    n = t.size
    y = np.empty(n)
    y[0] = F[0]
    for k in range(1, n):
        p = max(1.0 + y[k - 1] / Fp, 1e-3)
        e = math.exp(-(t[k] - t[k - 1]) * p * p / tau0)
        y[k] = F[k] + (y[k - 1] - F[k]) * e
    return y


@on_fine_grid
def aerated_load_cell_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force read as the pressure of a hydraulic load cell (a pressure capsule)
    preloaded to p_0, so that p = p_0 (1 + F / F_p) (F_p = :data:`CELL_PRELOAD` x the
    record's largest |force|) stays positive whatever the force's sign; the transducer
    sits behind a damping restrictor, and its oil holds entrained air whose compliance,
    isothermal, is ~ (p_0 / p)^2: the reading follows the pressure with the lag tau(p) =
    tau_0 (p_0 / p)^2 (:func:`_aerated_lag`), tau_0 = ``s`` :data:`AIR_LAG` data samples.
    At ``s`` = 0 the force itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the volume of air entrained (the lag at the preload), /
        its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The effective bulk modulus of oil with entrained air (Merritt 1967, Hydraulic Control
    Systems, ch. 2: the gas's compliance V_g p_0 / p^2), hydraulic load cells and the
    snubbers (restrictors) in front of pressure transducers. The open forms delay by one
    amount (a shift, a hold, a transport), filter linearly (a lag, Bessel, a moving average,
    a converter's FIR, a line's echoes) or by rank (a running median), let the delay drift,
    wander or grow with the force's rate or its slowness, with the motion's slowness or
    with the position, or shift the motion; here the lag is set by the force's own level:
    long where the force pulls (the capsule unloads), short where it pushes.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    Fp = CELL_PRELOAD * max(float(np.max(np.abs(F))), 1e-300)
    return _aerated_lag(np.ascontiguousarray(kin.t, dtype=float), np.ascontiguousarray(F),
                        float(s) * AIR_LAG * kin.sample_dt, Fp)


# -- drift -----------------------------------------------------------------------------------
#: ``particle_ingress``'s particles over the record [-]; their seed [-]; the travel over
#: which one is worn down or ejected, and over which it is pressed in, x the record's
#: travel [-]; the levels' rise of a particle of mean size at strength 1 [-]
PARTICLES, PARTICLE_SEED, PARTICLE_WEAR, PARTICLE_PRESS, PARTICLE_RISE = \
    8, 2026, 0.1, 0.005, 0.5


def _particle_levels(travel, seed, count, wear, press):
    """The levels' relative rise [-] of particles that enter the contact at ``count``
    random points of the relative travel ``travel`` [-] (0 to 1; uniform over 5-95 %,
    from ``seed``), of sizes 0.5 to 1.5 [-]: each is pressed in over the travel ``press``
    [-] and worn down or ejected over ``wear`` [-], (1 - exp(-d / press)) exp(-d / wear)
    of the travel d since it entered."""
    rng = np.random.default_rng(seed)
    at = np.sort(rng.uniform(0.05, 0.95, count))
    size = rng.uniform(0.5, 1.5, count)
    tr = np.asarray(travel, float)
    out = np.zeros_like(tr)
    for x0, a in zip(at, size):
        d = np.maximum(tr - x0, 0.0)
        out += a * -np.expm1(-d / press) * np.exp(-d / wear)
    return out


@on_fine_grid
def particle_ingress_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Contaminant particles (dust, chips, wear debris from elsewhere) swept into the
    contact by the sliding at :data:`PARTICLES` random points of the record's travel (a
    sequence fixed by :data:`PARTICLE_SEED`, the same share of the travel on every plant):
    each embeds in the softer surface and ploughs it, raising the levels by its size (0.5
    to 1.5 x ``s`` :data:`PARTICLE_RISE`) as it is pressed in, then less as it is worn down
    or ejected, over :data:`PARTICLE_WEAR` of the travel (:func:`_particle_levels`): the
    Coulomb and Stribeck levels are the base's times 1 + that rise, inside the bristle
    dynamics; the viscous term is the base's. Nothing changes at rest.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the particles' size (their ploughing), / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Hard particles entrained into lubricated contacts, their indentation, embedding and
    ploughing (Nikas 2010, A state-of-the-art review on the effects of particulate
    contamination and related topics in machine-element contacts, Proc. IMechE J 224);
    the ingress of chips and dust past a slideway's wipers. The candidate is a trend, a
    saturating change, a step and a cycle in time; the open forms warm up, wear in (in
    time, with the load and travel), step, heat, cycle, rise and fall with debris, drop
    with grease shots, relax in log time, grow an oxide and spall, oxidise after an
    induction, wear a coating through, swell as sqrt(t) or grow a tribofilm. Here a
    sequence of sudden rises at random points, each decaying with the sliding: the levels
    jump, creep back, and jump again when the next particle comes.
    """
    v = np.abs(np.asarray(kin.v, float))
    path = np.concatenate(([0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(kin.t))))
    travel = path / max(float(path[-1]), 1e-300)
    rise = _particle_levels(travel, PARTICLE_SEED, PARTICLES, PARTICLE_WEAR, PARTICLE_PRESS)
    lev = 1.0 + max(float(s), 0.0) * PARTICLE_RISE * rise
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: the lost motion of ``wire_rope`` at strength 1 (the deflection between the Coulomb levels
#: either way, beyond the stiff coupling's), as a share of the stroke [-] (the open
#: backlash forms' play); the share of the Coulomb level the strands carry by sticking
#: [-]; their slip deflection, x the rope's deflection at the Coulomb level [-]; the rope's
#: stiffness at ``s`` = 0, x the stiff coupling's of the other forms [-]
GAP_SHARE, STRAND_SHARE, STRAND_SLIP, ROPE_STIFF = PLANT_GAP_SHARE, 0.6, 0.15, 10.0


@njit(cache=True)
def _rope_contact(h, xd, ke, kz, zy, c, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a contact of mass ``m`` [kg] pulled by the drive positions
    ``xd`` [m] (grid step ``h`` [s]) through a wire rope: an elastic core ``ke`` [N/m] of
    the deflection e = drive - contact, and strands of stiffness ``kz`` [N/m] whose
    sticking deflection z slips beyond ``zy`` [m] (Bouc-Wen, exponent 1: z' = e' (1 - z /
    zy) while e' z > 0, e' otherwise; at most zy), damped by ``c`` [N s/m]. Semi-implicit
    Euler of the mass, the bristle advanced exactly at the contact's velocity
    (:func:`.truths._light_contact_step`). Starts at rest, undeflected."""
    n = xd.size
    F = np.empty(n)
    x = xd[0]
    v = 0.0
    z = 0.0
    zb = 0.0
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        de = h * (vd - v)
        if de * zb > 0.0:
            zb = zb + de * (1.0 - abs(zb) / zy)
        else:
            zb = zb + de
        zb = min(max(zb, -zy), zy)
        fc = ke * (xd[j] - x) + kz * zb + c * (vd - v)
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha, shape)
        x = x + h * v
    return F


@on_fine_grid
def wire_rope_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact joined by a wire rope (a cable drive): no play, but a coupling
    whose strands first stick (stiff) and then slip on each other as the load changes
    (:func:`_rope_contact`): an elastic core k_e and strands that carry up to
    :data:`STRAND_SHARE` of the Coulomb level by sticking, slipping beyond a deflection of
    :data:`STRAND_SLIP` x the rope's deflection e_c at the Coulomb level, damped at the
    ratio 0.5 of its initial stiffness. e_c = ``s``^2 :data:`GAP_SHARE` x the stroke / 2
    + Fc / (:data:`ROPE_STIFF` kh) (kh the stiff coupling of the other forms,
    :func:`.truths._contact_constants`), so the lost motion of a reversal is about 2 e_c.
    The contact is light, with the base's LuGre friction; the measured force is its
    friction. At ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the square root of the lost motion relative to
        :data:`GAP_SHARE` x the stroke (as the open plays').

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Wire ropes' hysteresis from the strands' and wires' friction (Costello 1997, Theory of
    Wire Rope); wire-rope elements modelled by Bouc-Wen's hysteresis (Demetriades,
    Constantinou and Reinhorn 1993, Study of wire rope systems for seismic protection of
    equipment in buildings, Eng. Struct. 15); capstan and cable drives. The candidate holds
    or frees the force across a play; the open forms couple it rigidly, compliantly, by
    impacts, a linear spring, an oil film, an idler's drag, a bias, slack chain strands, a
    magnetic pull, a spring preload on one side or a strain-wave gear that hardens, with a
    play varying with the position or the travel; here a dissipative coupling: after each
    reversal it is stiff until the strands slip, then soft: the force turns fast at first
    and slowly beyond, the opposite of the hardening gear.
    """
    p = _lugre_params(kin, "backlash (wire_rope)")
    if s <= 0.0:
        return _base_parts(kin)[0]
    m, kh, _ = _contact_constants(kin, p)
    Fc = float(p.Fc)
    ec = 0.5 * float(s) ** 2 * GAP_SHARE * float(np.ptp(kin.x)) + Fc / (ROPE_STIFF * kh)
    ke = (1.0 - STRAND_SHARE) * Fc / ec
    zy = STRAND_SLIP * ec
    kz = STRAND_SHARE * Fc / zy
    c = 2.0 * 0.5 * math.sqrt((ke + kz) * m)
    h, xd, n_sub = _substeps(kin, max(math.sqrt((ke + kz + float(p.sigma0)) / m),
                                      (float(p.sigma1) + float(p.sigma2) + c) / m))
    F = _rope_contact(h, xd, ke, kz, zy, c, m, float(p.sigma0), float(p.sigma1),
                      float(p.sigma2), Fc, float(p.Fs), float(p.vs), float(p.alpha),
                      SHAPES[p.shape])
    return F[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: the capillary bridges' depinning tilt travel at strength 1, beyond the base bristle's
#: path, as a share of the stroke / 3 [-]; their share of the friction at strength 1 [-];
#: the bridges' tilt at depinning (the advancing angle less the equilibrium one) [rad]
PRESLIDING_SHARE, CAPILLARY_SHARE, DEPINNING_TILT = 0.05, 0.5, math.radians(60.0)


def _bridge_force(u, ud, tilt):
    """The pinned bridges' force [-], relative to their retention force, at the tilt
    travels ``u`` [m] (within +-``ud`` [m], where they depin at the tilt ``tilt`` [rad]):
    2 gamma w sin(theta) sin(phi), tan(phi) = u / h, h = ``ud`` / tan(``tilt``) the
    bridges' height, over its value at ``ud``."""
    h = ud / math.tan(tilt)
    u = np.asarray(u, float)
    return u / np.sqrt(h * h + u * u) / math.sin(tilt)


@on_fine_grid
def capillary_bridges_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Capillary bridges of condensed water around the asperity contacts, beside the
    bristle: their contact lines stay pinned while the sliding tilts them (contact-angle
    hysteresis), each pulling back 2 gamma w sin(theta) sin(phi) at the tilt phi, tan(phi)
    = u / h (:func:`_bridge_force`); at the tilt :data:`DEPINNING_TILT` the contact line on
    the moving side depins and the bridge slides on with its retention force. The tilt
    travel u is thus a play of the travel within +-u_d (:func:`.seen11._nest_offset`), u_d
    the base bristle's path Fs / sigma0 plus ``s`` :data:`PRESLIDING_SHARE` x the stroke /
    3. A share w = :data:`CAPILLARY_SHARE` min(``s``, 1) of the friction is the bridges'
    (their retention at the Stribeck level, the viscous term the base's): F = (1 - w)
    F_lugre + w (g(v) f(u) + sigma2 v). At ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the bridges' share (up to ``s`` = 1) and their depinning
        travel (as the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The retention force of pinned drops and bridges, gamma w (cos theta_r - cos theta_a)
    (Furmidge 1962, Studies at phase interfaces I: the sliding of liquid drops on solid
    surfaces and a theory for spray retention, J. Colloid Sci. 17); capillary condensation
    at asperity contacts (Bocquet, Charlaix, Ciliberto and Crassous 1998, Moisture-induced
    ageing in granular media and the kinetics of capillary condensation, Nature 396).
    Maxwell-slip (the candidate, ``maxwell4``, ``maxwell10``) and the Mindlin contacts
    follow Masing's rule, Dahl, Bouc-Wen and Bliman-Sorine path laws, elasto-plastic an
    elastic range, the Zener junction and the rate-and-state interface rate-dependent
    creep, the Tomlinson contacts multistable tips, the bonds elements born and broken,
    the gouge a fabric turned over, the kinematic hardening a back-stress and the
    interlocking asperities a climb out of a nest; here a geometric capillary force of a
    play: after a reversal the bridges unbend slowly at first (the force's slope sin(phi)'
    is least at the largest tilt), fastest as they pass upright, and depin at a corner.
    """
    p = _lugre_params(kin, "gms (capillary_bridges)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, PRESLIDING_SHARE)
    ud = e0 + extra
    w = CAPILLARY_SHARE * min(float(s), 1.0)
    v = np.asarray(kin.v, float)
    u = _nest_offset(np.ascontiguousarray(kin.x, dtype=float), ud)
    Fb = kin.base.g(v) * _bridge_force(u, ud, DEPINNING_TILT) + float(p.sigma2) * v
    return (1.0 - w) * F + w * Fb
