"""The thirteenth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-29 (session 18) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 19's work on the code of 18bfa60:
176 cases, 0 skipped, 274 s wall on 2 workers (nothing else running). Top-1 17.0 % (30;
18.5 % of the 162 detectable; 12 delay cases below a sample); mean |shrink error| 0.440;
wrong names on 32 (18.2 %): asymmetry -> position 4, load -> asymmetry 4, drift ->
asymmetry 4, acceleration -> asymmetry 4, asymmetry -> load 3, position -> inertia 3,
stribeck_shape -> asymmetry 2, inertia -> asymmetry 2, gms -> acceleration 2. By form:
position/festoon_cable 13/16, acceleration/sprung_gib 4/20, drift/differential_expansion
4/20, load/scuffing_healing 3/20, stribeck_shape/thermoviscous_film 3/16,
gms/cyclic_hardening 3/12, asymmetry/chip_scraper 0/20, inertia/telescopic_stage 0/20,
delay/lossy_telemetry 0/20, backlash/jaw_coupling 0/12. By plant: XML-350 25.0 %, isolator
17.9 %, valve 17.5 %, damping rig 17.5 %, press 3.6 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen12` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen12`,
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
acceleration       ``sprung_gib``: a tapered gib strip (the slideway's adjusting wedge)
                   centred by a spring and held in its pocket by the friction of its
                   faces: once its inertial force passes that holding force it shifts
                   along the taper and changes the preload (a play operator of the
                   acceleration, Prandtl 1928 / Krasnosel'skii and Pokrovskii 1989;
                   gibs, Slocum 1992): the levels follow the acceleration's play
load               ``scuffing_healing``: the boundary film fails above a critical load
                   (scuffing, Dyson 1975) and heals only below a lower one (boundary
                   film re-formation, Bowden and Tabor 1950), each transition completed
                   over a sliding distance: the levels follow a relay (Schmitt trigger)
                   of the load, paced by the travel
asymmetry          ``chip_scraper``: a way scraper (wiper blade) angled to bulldoze chips
                   and coolant ahead of it one way and ride over them the other: the
                   pile it pushes grows with the travel since the last reversal and
                   saturates as it spills round the blade (the bulldozing resistance of
                   a blade, Reece 1964; McKyes 1985); dropped at each reversal
stribeck_shape     ``thermoviscous_film``: a full film whose viscous shear heats it
                   (Nahme-Griffith number ~ v^2): its viscosity falls exponentially
                   with the temperature (Reynolds' law), so the film's drag ~ v e^-W(N v^2)
                   rises, peaks and falls at speed (thermal thinning; Crook 1961;
                   Johnson and Greenwood 1980)
position           ``festoon_cable``: a cable hanging in a catenary from an anchor below
                   the stroke to the carriage (a festoon): its horizontal tension, from
                   sinh(beta) / beta = length / span (Irvine 1981), pulls the carriage
                   towards the anchor and rises steeply as the cable nears taut: a
                   force of the position alone, both ways
inertia            ``telescopic_stage``: a second (outer) stage of a telescopic axis
                   carried between two end stops: the carriage runs free inside it,
                   entrains it at each stop (a damped impact, vibro-impact, Babitsky
                   1998) and leaves it behind where its own guide friction stops it: a
                   mass picked up and dropped by the travel's history
delay              ``lossy_telemetry``: the force sent over a radio telemetry link that
                   loses telegrams in bursts (the Gilbert-Elliott channel, Gilbert
                   1960; Elliott 1963); the logger holds the last value received: stale
                   stretches of random lengths at a sequence fixed by its seed
drift              ``differential_expansion``: the carriage warms with the friction
                   power faster than the rail it heats in turn: their temperature
                   difference closes the preload (thermal errors of machines, Bryan
                   1990): the levels rise with the difference of two lags of the power,
                   up while the carriage leads and back as the rail catches up
backlash           ``jaw_coupling``: drive and contact joined by an elastomer-spider jaw
                   coupling with clearance: across the clearance nothing, then the
                   spider's rubber, stiff at once and relaxing (a standard linear solid,
                   Zener 1948): after each reversal the force overshoots and sags back
                   as the rubber creeps, more the slower the drive
gms                ``cyclic_hardening``: asperity junctions beside the bristle whose
                   yield hardens isotropically with the accumulated slip path (Voce 1948)
                   and recovers statically in time at rest (Chaboche 1989): after a rest
                   the presliding layer yields low and hardens over a path; through
                   quick reversals it stays hard; at ``s`` = 0 the base itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``thermoviscous_film``
needs a Stribeck curve (not the isolator's mre_lugre), ``festoon_cable`` a record that
revisits its positions (not the press), ``scuffing_healing`` a load that changes,
``jaw_coupling`` and ``cyclic_hardening`` a classic LuGre base (valve, damping rig, XML-350);
each raises a ``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit
from scipy.special import lambertw

from friction.shapes import SHAPES

from ..effects_backlash import PLANT_GAP_SHARE
from .kinematics import PlantKinematics
from .seen11 import _direction, _nest_offset
from .truths import (_base_parts, _bump_centre, _contact_constants, _lag, _level,
                     _light_contact_step, _lugre_params, _motion_time, _presliding_path,
                     _span, _substeps, level_inside, on_fine_grid)

__all__ = ["FORMS", "sprung_gib_truth", "scuffing_healing_truth", "chip_scraper_truth",
           "thermoviscous_film_truth", "festoon_cable_truth", "telescopic_stage_truth",
           "lossy_telemetry_truth", "differential_expansion_truth", "jaw_coupling_truth",
           "cyclic_hardening_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "sprung_gib", "load": "scuffing_healing",
         "asymmetry": "chip_scraper", "stribeck_shape": "thermoviscous_film",
         "position": "festoon_cable", "inertia": "telescopic_stage",
         "delay": "lossy_telemetry", "drift": "differential_expansion",
         "backlash": "jaw_coupling", "gms": "cyclic_hardening"}


def _travel(kin: PlantKinematics) -> np.ndarray:
    """The sliding path [m] along ``kin``'s grid (the integral of |v|), from 0."""
    v = np.abs(np.asarray(kin.v, float))
    return np.concatenate(([0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(kin.t))))


# -- acceleration ---------------------------------------------------------------------------
#: ``sprung_gib``'s holding force of the gib's faces, over its inertial force at a99 [-]
#: (the play's half-width in a / a99); the levels' change per unit of the gib's shift (in
#: a / a99) at strength 1 [-]; the lowest relative level [-]
GIB_HOLD, GIB_PRELOAD, GIB_FLOOR = 0.35, 0.8, 0.05
#: the gib's travel in its pocket either way from centre (in the units of its shift) [-]
GIB_TRAVEL = 1.0


def _gib_shift(a, hold, travel):
    """The gib's shift [-] (in units of its inertial force at a99 over its spring's
    stiffness) along the relative accelerations ``a`` [-]: quasi-static, k g + m a is
    held within +-H by the faces' friction, so g follows the play operator of ``a`` of
    half-width ``hold`` [-] (``a`` less its stop operator, :func:`.seen11._nest_offset`),
    within its pocket's ends +-``travel`` [-]; starts centred on the first acceleration's
    play."""
    a = np.ascontiguousarray(a, dtype=float)
    return np.clip(a - _nest_offset(a, hold) - a[0], -travel, travel)


@on_fine_grid
def sprung_gib_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A slideway whose preload is set by a tapered gib strip, centred by a spring and held
    in its pocket by the friction of its faces: its inertial force m_g a, with the
    spring's k g, must pass the holding force H before it shifts along the taper; then
    it moves until they balance again. Quasi-static (the gib is light and stiffly
    sprung), its shift is the play operator of a / a99 of half-width :data:`GIB_HOLD`
    (:func:`_gib_shift`), up to the ends of its pocket, :data:`GIB_TRAVEL` either way.
    Shifted into the taper it tightens the slideway, out of it it
    loosens it: the Coulomb and Stribeck levels are the base's times 1 + ``s``
    :data:`GIB_PRELOAD` x the shift (at least :data:`GIB_FLOOR`), inside the bristle
    dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the taper's preload per unit of the gib's shift, / its value
        at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The play (backlash) operator of hysteresis (Prandtl 1928; Krasnosel'skii and
    Pokrovskii 1989, Systems with Hysteresis); tapered gibs setting a slideway's preload
    (Slocum 1992, Precision Machine Design, ch. 8). The candidate adds a force odd in a
    fading with the speed and raises the levels with |a|, lagged; the open forms lag the
    velocity, a film or a contact state, heat the contact, skid rolling elements, move load
    between rows or supports, press seals, pull with the thrust, squeeze films, starve the
    contact, dilate it or lift it on a wedge. Here the levels keep what the last hard
    acceleration left them: a memory of the signed acceleration with a dead band, up
    after a hard push one way, down after one the other way, unchanged in between.
    """
    shift = _gib_shift(np.asarray(kin.a, float) / max(kin.scales["a99"], 1e-12), GIB_HOLD,
                       GIB_TRAVEL)
    lev = 1.0 + max(float(s), 0.0) * GIB_PRELOAD * shift
    return level_inside(kin, np.clip(lev, GIB_FLOOR, None), np.ones_like(lev))


# -- load -------------------------------------------------------------------------------------
#: ``scuffing_healing``'s critical loads where the film fails and heals, as shares of the
#: load's range [-]; the sliding distance a transition takes, x the record's travel [-];
#: the levels' rise where the film has failed at strength 1 [-]
SCUFF_AT, HEAL_AT, SCUFF_PATH, SCUFF_RISE = 0.65, 0.35, 0.02, 0.6


@njit(cache=True)
def _scuffed(path, L, hi, lo, ell):
    """The failed share [-] of the boundary film along the sliding ``path`` [m] and loads
    ``L`` [N]: above ``hi`` [N] it fails, below ``lo`` [N] it heals, each towards its end
    exponentially over the path ``ell`` [m]; in between it keeps its state (a relay of the
    load). Starts intact."""
    n = L.size
    out = np.empty(n)
    phi = 0.0
    out[0] = 0.0
    for k in range(1, n):
        e = math.exp(-(path[k] - path[k - 1]) / ell)
        if L[k] >= hi:
            phi = 1.0 + (phi - 1.0) * e
        elif L[k] <= lo:
            phi = phi * e
        out[k] = phi
    return out


@on_fine_grid
def scuffing_healing_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A boundary film that fails where the load passes a critical value (scuffing: the
    adsorbed film and then the oxide break through) and re-forms only where the load has
    fallen below a lower one (the film heals once the contact is light enough): the
    critical loads are :data:`SCUFF_AT` and :data:`HEAL_AT` of the load's range above its
    least, each transition completed over the sliding distance :data:`SCUFF_PATH` x the
    record's travel (:func:`_scuffed`). Where it has failed the metal touches: the
    Coulomb and Stribeck levels are the base's times 1 + ``s`` :data:`SCUFF_RISE` x the
    failed share, inside the bristle dynamics; the viscous term is the base's. ValueError
    if the load does not change.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s], load [N]) and its base law.
    s : float
        Amplitude factor [-]: the bare contact's friction over the film's, minus 1, /
        :data:`SCUFF_RISE`.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Scuffing as the failure of the boundary film at a critical load (Dyson 1975, Scuffing -
    a review, Tribology 8; the IRG transition diagrams, de Gee, Begelinger and Salomon
    1985); the healing of boundary films (Bowden and Tabor 1950, The Friction and
    Lubrication of Solids). The candidate's levels are affine in the load; the open forms
    are powers, one direction, square-root and exponential viscous terms, the Stribeck
    velocity, a logistic step, a creep in time, the load's rate, a play, a ratchet with
    the travel, a hinge, a lag while it rises, a saturating area and a flash temperature.
    Here a relay: between the two critical loads the levels are those of the last one
    passed, and they change with the travel, not at once.
    """
    L = np.asarray(kin.load, float)
    L0 = max(float(np.mean(np.abs(L))), 1e-12)
    # a change below 1e-6 of the mean load over the record is round-off, not a change
    if float(np.ptp(L)) <= 1e-6 * L0:
        raise ValueError(f"load (scuffing_healing): the {kin.plant} record's load does not "
                         f"change")
    path = _travel(kin)
    lo, span = float(np.min(L)), float(np.ptp(L))
    phi = _scuffed(path, np.ascontiguousarray(L), lo + SCUFF_AT * span, lo + HEAL_AT * span,
                   SCUFF_PATH * max(float(path[-1]), 1e-300))
    lev = 1.0 + max(float(s), 0.0) * SCUFF_RISE * phi
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``chip_scraper``'s travel over which the pile fills (spills round the blade), and over
#: which it is dropped after a reversal, x the stroke the record visits [-]; the full
#: pile's drag at strength 1, x the friction level [-]
PILE_FILL, PILE_DROP, PILE_DRAG = 0.3, 0.01, 0.6


@njit(cache=True)
def _pile(t, v_push, v_back, fill, drop):
    """The pile [-] (over the full one) a scraper pushes along the times ``t`` [s]: it
    gathers at the pushing speeds ``v_push`` [m/s] (>= 0) as p' = v_push (1 - p) / ``fill``
    (the film's chips per travel, spilling round the blade as it fills) and is left
    behind at the return speeds ``v_back`` [m/s] (>= 0) as p' = -v_back p / ``drop``; each
    step exact at its start's rates. Starts empty."""
    n = t.size
    out = np.empty(n)
    p = 0.0
    out[0] = 0.0
    for k in range(1, n):
        h = t[k] - t[k - 1]
        up = v_push[k - 1] / fill
        rate = up + v_back[k - 1] / drop
        if rate > 0.0:
            target = up / rate
            p = target + (p - target) * math.exp(-rate * h)
        out[k] = p
    return out


@on_fine_grid
def chip_scraper_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A way scraper (a wiper blade) on the carriage, angled so that moving up (v > 0) it
    bulldozes the chips and coolant lying on the way ahead of it, while moving down it
    rides over them and leaves its pile behind: the pile gathers with the travel since the
    last reversal and spills round the blade as it fills, over :data:`PILE_FILL` x the
    stroke; it is dropped over :data:`PILE_DROP` x the stroke after a reversal
    (:func:`_pile`; the direction rounded over 2 % of v99). Pushing it takes a drag in
    proportion to it (a blade's bulldozing resistance, ~ the pile's weight), ``s``
    :data:`PILE_DRAG` x the friction level when full, added to the base's force.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the chips per travel lying on the way (the full pile's
        weight), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The fundamental earthmoving equation of a blade's resistance (Reece 1964, Proc. Inst.
    Mech. Eng. 179; McKyes 1985, Soil Cutting and Tillage); way wipers and scrapers of
    machine tools pushing chips. The candidate shifts a direction's levels and viscous
    slope (and an offset); the open forms keep a direction's share, its Stribeck velocity,
    viscous slope or tail, roll a lip, follow a thrust, a film laid by the outstroke, a
    texture, a return spring, a wedge film, a strut, a throttle, a cylinder's areas,
    pumping grooves or a buckling cable. Here the direction pushing drags more the farther
    it has gone since the reversal, the same wherever along the stroke it turned.
    """
    F, _ = _base_parts(kin)
    d = _direction(kin)
    v = np.asarray(kin.v, float)
    span = _span(kin)
    p = _pile(np.ascontiguousarray(kin.t, dtype=float),
              np.ascontiguousarray(0.5 * (1.0 + d) * np.maximum(v, 0.0)),
              np.ascontiguousarray(0.5 * (1.0 - d) * np.maximum(-v, 0.0)),
              PILE_FILL * span, PILE_DROP * span)
    return F + max(float(s), 0.0) * PILE_DRAG * _level(kin) * p * 0.5 * (1.0 + d)


# -- stribeck_shape --------------------------------------------------------------------------
#: ``thermoviscous_film``'s Nahme-Griffith number at v99 (the viscous heating's rise of
#: beta T) [-]; the film's drag at v99 without heating at strength 1, x the friction
#: level [-]
NAHME_AT_TOP, THERMO_DRAG = 4.0, 0.8


def _thermal_thinning(u, nahme):
    """The film's drag [-] at the relative speeds ``u`` [-] (over v99), over its unheated
    drag at v99: u exp(-x), the viscosity's thinning x = beta dT solving x = N u^2 exp(-x)
    (the heat of the shear at that viscosity, Nahme-Griffith number ``nahme`` [-] at v99),
    i.e. x = W(N u^2) (Lambert's W)."""
    u = np.asarray(u, float)
    x = np.real(lambertw(nahme * u * u))
    return u * np.exp(-x)


@on_fine_grid
def thermoviscous_film_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A full lubricant film in the contact beside its asperities whose shear heats it:
    its viscosity falls as exp(-beta dT) (Reynolds' viscosity law) with the temperature
    rise dT the shear's heat eta v^2 makes through the film, so beta dT = x solves x = N
    u^2 exp(-x) (u = v / v99, N = :data:`NAHME_AT_TOP` the Nahme-Griffith number at v99):
    the film's drag ~ u exp(-W(N u^2)) (:func:`_thermal_thinning`) rises linearly, peaks
    and falls at speed. It is added to the base's force, ``s`` :data:`THERMO_DRAG` x the
    friction level at v99 without heating.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (a Stribeck curve).
    s : float
        Amplitude factor [-]: the film's unheated viscosity (its area over its
        thickness), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Viscous heating and thermal thinning of lubricant films (the Nahme-Griffith number,
    Nahme 1940, Ing.-Arch. 11; Crook 1961, The lubrication of rollers III, Phil. Trans. R.
    Soc. A 254; Johnson and Greenwood 1980, Thermal analysis of an Eyring fluid in
    elastohydrodynamic traction, Wear 61). The candidate bends the base's drop (an
    exponent, the Lorentzian, a log-speed map); the open forms add tails, drops, a spike,
    a lift-off, a second drop, logarithmic weakening, Eyring strengthening, a rise at the
    top speed, a hump, a notch, a dither, a melt, a granular rise and re-adsorption. Here
    a viscous drag that is linear at low speed and falls beyond its peak: thermal
    runaway of the film, not a boundary level.
    """
    if kin.base.name == "mre_lugre":
        raise ValueError("stribeck_shape (thermoviscous_film): the mre_lugre base has no "
                         "Stribeck curve")
    F, _ = _base_parts(kin)
    u = np.asarray(kin.v, float) / max(kin.scales["v99"], 1e-12)
    drag = _thermal_thinning(u, NAHME_AT_TOP)
    return F + max(float(s), 0.0) * THERMO_DRAG * _level(kin) * drag


# -- position --------------------------------------------------------------------------------
#: ``festoon_cable``'s anchor below the stroke the record visits, x that stroke [-]; the
#: cable's length over its span at the stroke's far end [-]; the tension's change over the
#: stroke at strength 1, x the friction level [-]
FESTOON_ANCHOR, FESTOON_SLACK, FESTOON_FORCE = 0.5, 1.05, 0.8


def _catenary_tension(d, length):
    """The horizontal tension [-] (x the cable's weight per length times its length) of a
    cable of ``length`` [m] hung between two points ``d`` [m] apart at one height: beta =
    w d / (2 H) solves sinh(beta) / beta = r = length / d (Newton's iteration from the
    shallow cable's sqrt(6 (r - 1)), damped), H / (w length) = d / (2 beta length)."""
    r = length / np.asarray(d, float)
    beta = np.sqrt(6.0 * (r - 1.0)) / (1.0 + 0.1 * np.sqrt(6.0 * (r - 1.0)))
    for _ in range(60):
        f = np.sinh(beta) / beta - r
        df = (beta * np.cosh(beta) - np.sinh(beta)) / (beta * beta)
        beta = np.maximum(beta - f / df, 1e-6)
    return np.asarray(d, float) / (2.0 * beta * length)


@on_fine_grid
def festoon_cable_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A cable (a festoon: a power cable, a hose) hanging in a catenary from an anchor
    :data:`FESTOON_ANCHOR` x the stroke below the stroke the record visits to the carriage,
    :data:`FESTOON_SLACK` x the span at the stroke's far end long: its horizontal tension H,
    from sinh(beta) / beta = length / span, beta = w span / (2 H)
    (:func:`_catenary_tension`), pulls the carriage towards the anchor, slack near it and
    rising steeply as the cable nears taut. The drive's force is the base's plus H (its
    least over the stroke taken off: the cable's pull at the near end is an offset no
    mechanism of the friction explains), scaled so that its change over the stroke is
    ``s`` :data:`FESTOON_FORCE` x the friction level, whatever the direction and at rest
    alike. The contact's friction is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the cable's weight per length, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The elastic catenary (Irvine 1981, Cable Structures); festoon cable systems of cranes
    and gantries. The candidate scales the friction along the stroke and adds a periodic
    force of x; the open forms are level maps, a periodic detent force, a cushion's
    drag, a cover's staircase, a gas spring, bolt holes, a plunger's drag and a sagging
    beam's pull towards its middle. Here one force of the position alone, monotonic over
    the stroke and steepening towards its far end as the cable's sag vanishes.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (festoon_cable): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    F, _ = _base_parts(kin)
    span = _span(kin)
    anchor = kin.scales["x_lo"] - FESTOON_ANCHOR * span
    length = FESTOON_SLACK * (1.0 + FESTOON_ANCHOR) * span
    d = np.clip(np.asarray(kin.x, float) - anchor, 1e-3 * span, None)
    H = _catenary_tension(d, length)
    lo = float(_catenary_tension(FESTOON_ANCHOR * span, length))
    hi = float(_catenary_tension((1.0 + FESTOON_ANCHOR) * span, length))
    return F + max(float(s), 0.0) * FESTOON_FORCE * _level(kin) * (H - lo) / (hi - lo)


# -- inertia ---------------------------------------------------------------------------------
#: ``telescopic_stage``'s mass at strength 1, x the friction level / a99 [kg per N s^2/m];
#: the carriage's free travel inside it, x the stroke the record visits [-]; its own guide
#: friction, x its inertial force at a99 [-]; the stops' contact period, x the motion's
#: time scale [-]
STAGE_MASS, STAGE_PLAY, STAGE_FRICTION, STOP_PERIOD = 1.0, 0.3, 0.1, 0.1


@njit(cache=True)
def _stage_force(h, xd, half, m, fs, k, c):
    """The force [N] the carriage at the drive positions ``xd`` [m] (step ``h`` [s]) exerts
    on a stage of mass ``m`` [kg] it runs inside with a free travel of +-``half`` [m]: at
    either stop a spring ``k`` [N/m] and damper ``c`` [N s/m] (compressive only); the stage
    slides on its guides with the Coulomb force ``fs`` [N] and sticks where that holds it.
    Semi-implicit Euler of the stage. Starts centred, at rest."""
    n = xd.size
    out = np.empty(n)
    y = xd[0]
    w = 0.0
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        e = xd[j] - y
        f = 0.0
        if e > half:
            f = max(k * (e - half) + c * (vd - w), 0.0)
        elif e < -half:
            f = min(k * (e + half) + c * (vd - w), 0.0)
        out[j] = f
        if w != 0.0:
            wn = w + h * (f - fs * (1.0 if w > 0.0 else -1.0)) / m
            w = 0.0 if wn * w < 0.0 else wn
        elif abs(f) > fs:
            w = h * (f - fs * (1.0 if f > 0.0 else -1.0)) / m
        y = y + h * w
    return out


@on_fine_grid
def telescopic_stage_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage runs inside a second (outer) stage of a telescopic axis with a free
    travel of :data:`STAGE_PLAY` x the stroke between two end stops: inside it the stage
    stays where it was left, held by its own guides' Coulomb friction (a deceleration of
    :data:`STAGE_FRICTION` a99); at a stop the carriage entrains it through the stop's
    damped spring (rubber buffers: a contact period :data:`STOP_PERIOD` x the motion's time
    scale, critically damped) and pushes or pulls it along until it slows faster than the stage's
    friction stops it (:func:`_stage_force`, on sub-steps). The inverse dynamics misses
    the stage: its force is added to the base's; the stage's mass is ``s``
    :data:`STAGE_MASS` x the friction level / a99.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law.
    s : float
        Amplitude factor [-]: the stage's mass (its guides' friction in proportion), /
        its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Vibro-impact systems (Babitsky 1998, Theory of Vibro-Impact Systems and
    Applications); multi-stage telescopic slides and telescopic forks, whose outer stages
    are picked up at the inner stage's stops. The candidate's mass is constant, varies in
    time, along the stroke or with the squared speed, or holds a coupled part that slips;
    the open forms filter, flex, gear, lose, add fluid mass, dispense, slide a payload,
    rattle a part across a small pocket, freewheel, carry a payload between zones or
    couple through eddies, flyweights or a fluid coupling. Here the stage is picked up
    only after the carriage has run through a third of the stroke from where it turned,
    and left behind where the carriage slows: the mass depends on the travel's history.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    T = max(_motion_time(kin), 1e-12)
    a99 = max(kin.scales["a99"], 1e-12)
    m = float(s) * STAGE_MASS * _level(kin) / a99
    omega = 2.0 * math.pi / (STOP_PERIOD * T)
    k = m * omega * omega
    c = 2.0 * math.sqrt(k * m)
    h, xd, n_sub = _substeps(kin, omega)
    f = _stage_force(h, xd, 0.5 * STAGE_PLAY * _span(kin), m, STAGE_FRICTION * m * a99, k,
                     c)
    return F + f[::n_sub]


# -- delay -----------------------------------------------------------------------------------
#: ``lossy_telemetry``'s bursts of lost telegrams over the record [-]; their seed [-]; their
#: mean length at strength 1 [data samples]
BURSTS, BURST_SEED, BURST_LENGTH = 150, 1963, 3.0


def _held(t, F, starts, lengths):
    """The force [N] a logger holds at the times ``t`` [s] when the telegrams of ``F`` [N]
    are lost from ``starts`` [s] for ``lengths`` [s] (overlapping losses merged): within a
    loss the value received last, at its start; elsewhere the force."""
    order = np.argsort(starts)
    a, b = np.asarray(starts, float)[order], np.asarray(starts, float)[order] + \
        np.asarray(lengths, float)[order]
    out = np.array(F, float)
    k = 0
    while k < a.size:
        end = b[k]
        j = k + 1
        while j < a.size and a[j] <= end:
            end = max(end, b[j])
            j += 1
        i0, i1 = np.searchsorted(t, a[k]), np.searchsorted(t, end)
        if i0 < t.size:
            out[i0:i1] = F[i0]
        k = j
    return out


@on_fine_grid
def lossy_telemetry_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force sent from the carriage over a radio telemetry link that loses telegrams
    in bursts (a Gilbert-Elliott channel: fading and interference come and go): the
    logger holds the last value received until the link recovers. :data:`BURSTS` bursts
    over the record, at times and of relative lengths (exponentially distributed) fixed
    by :data:`BURST_SEED`, of mean length ``s`` :data:`BURST_LENGTH` data samples
    (:func:`_held`). At ``s`` = 0 the force itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the bursts' mean length, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Burst-error channels (Gilbert 1960, Capacity of a burst-noise channel, Bell Syst. Tech.
    J. 39; Elliott 1963, Estimates of error rates for codes on burst-noise channels, Bell
    Syst. Tech. J. 42); wireless torque and force telemetry on moving parts. The open
    forms delay by one amount, filter linearly or by rank, hold at a fieldbus's clock,
    let the delay drift, wander or follow the force's rate, level or slowness, the
    motion's speed or the position, or shift the motion; here the force is held stale
    over random stretches and exact between them.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    rng = np.random.default_rng(BURST_SEED)
    starts = t[0] + (t[-1] - t[0]) * np.sort(rng.uniform(0.02, 0.98, BURSTS))
    lengths = float(s) * BURST_LENGTH * kin.sample_dt * rng.exponential(1.0, BURSTS)
    return _held(t, F, starts, lengths)


# -- drift -----------------------------------------------------------------------------------
#: ``differential_expansion``'s carriage and rail heating times, x the record's length [-];
#: the levels' rise per unit of the temperature difference (in units of the mean friction
#: power's steady heating) at strength 1 [-]
CARRIAGE_HEATING, RAIL_HEATING, EXPANSION_RISE = 0.05, 0.3, 1.0


@on_fine_grid
def differential_expansion_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage is heated by the friction power |F_f v| (over its mean) and warms
    with the time constant :data:`CARRIAGE_HEATING` x the record; the rail is heated by the
    carriage and follows it with :data:`RAIL_HEATING` x the record (two first-order lags,
    :func:`.truths._lag`). Their temperature difference expands the carriage against the
    rail and closes the preload: the Coulomb and Stribeck levels are the base's times 1 +
    ``s`` :data:`EXPANSION_RISE` x (T_carriage - T_rail), inside the bristle dynamics; the
    viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the preload per unit of the temperature difference (the
        carriage's expansion coefficient and the guide's stiffness), / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Thermal errors of machine tools (Bryan 1990, International status of thermal error
    research, CIRP Annals 39; Mayr et al. 2012, Thermal issues in machine tools, CIRP
    Annals 61); the preload of linear guides rising as the carriage warms. The candidate is
    a trend, a saturating change, a step and a cycle in time; the open forms warm up (the
    oil thinning), wear in, step, cycle, rise and fall with debris, drop with grease
    shots, relax, oxidise, wear through, swell, grow a tribofilm or take in particles.
    Here the levels follow the difference of two lags of the friction power: up while
    the carriage leads, back as the rail catches up, up again when the power rises.
    """
    F, Ff = _base_parts(kin)
    t = np.asarray(kin.t, float)
    power = np.abs(Ff * np.asarray(kin.v, float))
    power = power / max(float(np.mean(power)), 1e-300)
    T = float(t[-1] - t[0])
    carriage = _lag(t, power - power[0], CARRIAGE_HEATING * T)
    diff = carriage - _lag(t, carriage, RAIL_HEATING * T)
    lev = 1.0 + max(float(s), 0.0) * EXPANSION_RISE * diff
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: the lost motion of ``jaw_coupling`` at strength 1 (the clearance plus the spider's relaxed
#: deflection between the Coulomb levels either way), as a share of the stroke [-] (the
#: open backlash forms' play); the clearance's share of it [-]; the rubber's instant
#: stiffness over its relaxed one [-]; its relaxation time, x the motion's time scale [-];
#: the spider's stiffness at ``s`` = 0, x the stiff coupling's of the other forms [-]
GAP_SHARE, CLEARANCE_SHARE, RUBBER_STIFFENING, RUBBER_RELAXATION, SPIDER_STIFF = \
    PLANT_GAP_SHARE, 0.4, 5.0, 0.1, 10.0


@njit(cache=True)
def _jaw_contact(h, xd, half, k0, km, tau, c, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a contact of mass ``m`` [kg] driven by the drive positions
    ``xd`` [m] (step ``h`` [s]) through a jaw coupling's clearance +-``half`` [m] and its
    elastomer spider, a standard linear solid in compression: the relaxed spring ``k0``
    [N/m] beside a Maxwell arm (spring ``km`` [N/m], relaxation time ``tau`` [s]) whose
    force q follows q' = km d' - q / tau of the compression d (relaxing freely out of
    contact), damped by ``c`` [N s/m]; no tension. Semi-implicit Euler of the mass
    (:func:`.truths._light_contact_step`). Starts at rest, centred."""
    n = xd.size
    F = np.empty(n)
    x = xd[0]
    v = 0.0
    z = 0.0
    q = 0.0
    d_old = 0.0
    decay = math.exp(-h / tau)
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        e = xd[j] - x
        d = max(abs(e) - half, 0.0)
        q = q * decay + km * (d - d_old)
        d_old = d
        fc = 0.0
        if d > 0.0:
            side = 1.0 if e > 0.0 else -1.0
            fc = side * max(k0 * d + q + c * side * (vd - v), 0.0)
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha, shape)
        x = x + h * v
    return F


@on_fine_grid
def jaw_coupling_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact joined by a jaw coupling with an elastomer spider and clearance
    (:func:`_jaw_contact`): across the clearance (:data:`CLEARANCE_SHARE` of the lost
    motion) nothing holds the contact; then the spider's rubber is compressed, a standard
    linear solid :data:`RUBBER_STIFFENING` x stiffer at once than relaxed, relaxing over
    :data:`RUBBER_RELAXATION` x the motion's time scale, damped at the ratio 0.5 of its
    instant stiffness. The lost motion of a reversal at the Coulomb level is ``s``^2
    :data:`GAP_SHARE` x the stroke (the rest of it the relaxed spider's deflection, plus
    Fc / (:data:`SPIDER_STIFF` kh), kh the stiff coupling of the other forms,
    :func:`.truths._contact_constants`). The contact is light, with the base's LuGre
    friction; the measured force is its friction. At ``s`` = 0 the base itself.

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
    The standard linear solid (Zener 1948, Elasticity and Anelasticity of Metals);
    elastomer jaw (spider) couplings, their clearance and the rubber's dynamic stiffness
    (Gent 2001, Engineering with Rubber). The candidate holds or frees the force across a
    play, with a bias, a spring or a drag across it; the open forms couple rigidly,
    compliantly (a linear spring-damper), by impacts, springs, oil, an idler, a bias,
    chains, magnets, a preload, a hardening gear or a slipping rope, with a play varying
    with the position or the travel. Here a play and then a coupling whose stiffness
    depends on the rate: the force overshoots as the drive takes up the spider fast and
    sags back as the rubber creeps.
    """
    p = _lugre_params(kin, "backlash (jaw_coupling)")
    if s <= 0.0:
        return _base_parts(kin)[0]
    m, kh, _ = _contact_constants(kin, p)
    Fc = float(p.Fc)
    lost = float(s) ** 2 * GAP_SHARE * float(np.ptp(kin.x))
    half = 0.5 * CLEARANCE_SHARE * lost
    k0 = Fc / (0.5 * (1.0 - CLEARANCE_SHARE) * lost + Fc / (SPIDER_STIFF * kh))
    km = (RUBBER_STIFFENING - 1.0) * k0
    c = 2.0 * 0.5 * math.sqrt((k0 + km) * m)
    h, xd, n_sub = _substeps(kin, max(math.sqrt((k0 + km + float(p.sigma0)) / m),
                                      (float(p.sigma1) + float(p.sigma2) + c) / m))
    F = _jaw_contact(h, xd, half, k0, km, RUBBER_RELAXATION * max(_motion_time(kin), 1e-12),
                     c, m, float(p.sigma0), float(p.sigma1), float(p.sigma2), Fc,
                     float(p.Fs), float(p.vs), float(p.alpha), SHAPES[p.shape])
    return F[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: the junctions' elastic travel at strength 1, beyond the base bristle's path, as a share
#: of the stroke / 3 [-]; their share of the friction at strength 1 [-]; the yield's share
#: lost when fully recovered [-]; the slip path that hardens them, x their elastic travel
#: [-]; their static recovery time, x the motion's time scale [-]
PRESLIDING_SHARE, JUNCTION_SHARE, SOFTENING, HARDENING_PATH, RECOVERY_TIME = \
    0.05, 0.7, 0.6, 3.0, 2.0


@njit(cache=True)
def _hardening_junctions(t, x, ud, soft, path, tau):
    """The junctions' force [-] (over the sliding level) along the positions ``x`` [m] at
    the times ``t`` [s]: elastic over the travel ``ud`` [m] at full hardness, yielding at
    1 - ``soft`` exp(-p / ``path``) of the sliding level, p the accumulated slip path [m]
    (Voce's isotropic hardening), which recovers at rest as p' = -p / ``tau`` [s] (static
    recovery). Starts recovered, unloaded."""
    n = x.size
    out = np.empty(n)
    u = 0.0
    p = 0.0
    out[0] = 0.0
    for k in range(1, n):
        p = p * math.exp(-(t[k] - t[k - 1]) / tau)
        u = u + (x[k] - x[k - 1]) / ud
        y = 1.0 - soft * math.exp(-p / path)
        if abs(u) > y:
            p = p + (abs(u) - y) * ud
            y = 1.0 - soft * math.exp(-p / path)
            u = y if u > 0.0 else -y
        out[k] = u
    return out


@on_fine_grid
def cyclic_hardening_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Asperity junctions beside the bristle that harden isotropically with the slip: an
    elastic layer over the travel u_d at full hardness that yields at 1 - :data:`SOFTENING`
    exp(-p / p_h) of the Stribeck level (Voce's law; p the accumulated slip path, p_h =
    :data:`HARDENING_PATH` u_d), the hardening recovering in time, p' = -p / tau (static
    recovery, tau = :data:`RECOVERY_TIME` x the motion's time scale)
    (:func:`_hardening_junctions`). u_d is the base bristle's path Fs / sigma0 plus ``s``
    :data:`PRESLIDING_SHARE` x the stroke / 3; a share w = :data:`JUNCTION_SHARE` min(``s``,
    1) of the friction is the junctions' (their yield at the Stribeck level, the viscous
    term the base's): F = (1 - w) F_lugre + w (g(v) f + sigma2 v). At ``s`` = 0 the base
    itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m], v [m/s]) and its base law (a classic
        LuGre).
    s : float
        Amplitude factor [-]: the junctions' share (up to ``s`` = 1) and their elastic
        travel (as the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Isotropic (Voce) hardening (Voce 1948, The relationship between stress and strain for
    homogeneous deformation, J. Inst. Met. 74) and static recovery (Chaboche 1989,
    Constitutive equations for cyclic plasticity and cyclic viscoplasticity, Int. J.
    Plast. 5); work-hardening of asperity junctions (Bowden and Tabor 1950). Maxwell-slip
    (the candidate) and the open forms follow Masing's rule, path laws, an elastic range,
    rate-dependent creep, multistable tips, bonds, a fabric, a back-stress, a climb out
    of a nest or capillary bridges; here the junctions' yield depends on how far they
    have slipped since they last rested: soft after a stop, hard through quick reversals.
    """
    p = _lugre_params(kin, "gms (cyclic_hardening)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, PRESLIDING_SHARE)
    ud = e0 + extra
    w = JUNCTION_SHARE * min(float(s), 1.0)
    v = np.asarray(kin.v, float)
    f = _hardening_junctions(np.ascontiguousarray(kin.t, dtype=float),
                             np.ascontiguousarray(kin.x, dtype=float), ud, SOFTENING,
                             HARDENING_PATH * ud, RECOVERY_TIME * max(_motion_time(kin), 1e-12))
    return (1.0 - w) * F + w * (kin.base.g(v) * f + float(p.sigma2) * v)
