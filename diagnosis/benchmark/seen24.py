"""The twenty-fourth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-30 (session 28) by another hand, once, without running the diagnosis on it;
run once, sealed, at the start of session 29 (2026-11-30) on the code of 3fa3016:
176 cases, 0 skipped, 459 s wall on 2 workers. Top-1 60.8 % (107;
61.3 % of the 173 detectable; of the 3 undetectable, 2 are delays below a sample, 1 a
stribeck_shape case); mean |shrink error| 0.279; wrong names on 15 (8.5 %): acceleration ->
position 4, stribeck_shape -> asymmetry 3, gms -> delay 3, delay -> inertia 1, drift ->
load 1, delay -> position 1, delay -> acceleration 1, gms -> acceleration 1. By form:
drift/pump_down 19/20, load/light_load_skid 18/20, asymmetry/pitching_pads 17/20,
position/track_end 16/16, inertia/qzs_isolator 11/20, delay/force_restoration 9/20,
acceleration/gantry_racking 8/20, gms/eyring_film 4/12, stribeck_shape/wall_slip 3/16,
backlash/graded_clearance 2/12. By plant: valve 85.0 %, XML-350 67.5 %, isolator 64.3 %,
damping rig 52.5 %, forging press 25.0 %.
Before the run, the session's engineer had read this family's form table (the module
docstring) while reading the benchmark package; no change to the diagnosis was made between
that reading and the run (the code run differs from 1c7014e only by two speed changes,
verdict-neutral on the 272-case grid).
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen23` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen23`,
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
acceleration       ``gantry_racking``: the axis is a gantry driven on both sides by
                   two servo loops of unequal bandwidth: each lags the command by its
                   type-2 loop's following error, ~ the acceleration over its
                   bandwidth squared, so the bridge racks by their difference and binds
                   in its guides: levels rising with the lagged |a|
load               ``light_load_skid``: the contact's rolling elements are driven by
                   their traction, ~ the load, against the drag of their cage and
                   lubricant: below the bearing's minimum load they skid, and the
                   sliding at the skid's speed adds a friction ~ W (1 - W / W_min),
                   greatest at half the minimum load and none above it
asymmetry          ``pitching_pads``: the carriage slides on a leading and a trailing
                   pad of different materials (a bronze falling with the speed, a
                   polymer rising with it); the friction's moment about the pads'
                   plane shifts the weight onto the leading pad: the levels differ by
                   direction, the one way at low speed and the other at speed
stribeck_shape     ``wall_slip``: a lubricant film that sticks to the walls below a
                   critical shear stress and slips along them above it (Navier slip):
                   a viscous drag that grows linearly up to the critical speed and far
                   more slowly beyond it
position           ``track_end``: an iron-core linear motor whose forcer runs off the
                   end of its magnet track within the stroke: its magnetic pull on the
                   guides, and their friction, fall with the overlap, and the track's
                   end pulls the forcer back (a reluctance force)
inertia            ``qzs_isolator``: a payload on a quasi-zero-stiffness isolator
                   (a spring balanced by negative-stiffness springs): a cubic spring and
                   a damper transmit its inertia, whole for large strokes and hardly at
                   all for small or slow relative motions
delay              ``force_restoration``: the force is read by an electromagnetic
                   force-restoration cell: a PID loop holds its lever at null with a
                   coil, and the coil's current is the reading: a lag set by the lever
                   pivot's stiffness over the loop's bandwidth, with the loop's overshoot
drift              ``pump_down``: the machine runs in a chamber being pumped down: the
                   adsorbed gas layer on the contact desorbs as the pressure falls
                   (Langmuir kinetics), and the bare surfaces' adhesion raises the
                   levels once the pressure passes the layer's: a late, sigmoid rise
backlash           ``graded_clearance``: drive and contact are joined by several pins
                   (a cycloid or pin-gear mesh) whose clearances are spread by the
                   machining tolerances: after a reversal one pin engages after the
                   other, and the stiffness of the take-up grows stepwise until all
                   carry
gms                ``eyring_film``: part of the contact is carried through an
                   elastohydrodynamic film that is an elastic solid for fast changes and
                   an Eyring fluid in steady shear (Johnson and Tevaarwerk): after a
                   reversal the stress unloads elastically, then flows at a rate
                   growing as sinh of the stress, and it relaxes at rest; at ``s`` = 0
                   the base itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``wall_slip`` needs a
Stribeck curve (not the isolator's mre_lugre), ``track_end`` a record that revisits its
positions (not the press), ``light_load_skid`` a load that changes, ``graded_clearance``
and ``eyring_film`` a classic LuGre base (valve, damping rig, XML-350); each raises a
``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit
from scipy.signal import cont2discrete, lfilter, lfilter_zi

from friction.shapes import SHAPES

from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _level,
                     _light_contact_step, _lugre_params, _motion_time, _presliding_path,
                     _smooth_max0, _substeps, has_stribeck_curve, level_inside, on_fine_grid)

__all__ = ["FORMS", "gantry_racking_truth", "light_load_skid_truth", "pitching_pads_truth",
           "wall_slip_truth", "track_end_truth", "qzs_isolator_truth",
           "force_restoration_truth", "pump_down_truth", "graded_clearance_truth",
           "eyring_film_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "gantry_racking", "load": "light_load_skid",
         "asymmetry": "pitching_pads", "stribeck_shape": "wall_slip",
         "position": "track_end", "inertia": "qzs_isolator",
         "delay": "force_restoration", "drift": "pump_down",
         "backlash": "graded_clearance", "gms": "eyring_film"}


# -- acceleration ----------------------------------------------------------------------------
#: ``gantry_racking``'s rise of the levels at the record's top racking, at strength 1 [-];
#: the slower side's closed-loop period, x the motion's time scale [-], the faster side's
#: bandwidth over it [-] and the loops' damping ratio [-]; the racking's rounding at zero,
#: x its top value [-]
RACK_RISE, RACK_PERIOD, RACK_RATIO, RACK_DAMPING, RACK_ROUND = 0.4, 0.4, 1.6, 0.7, 0.05


@njit(cache=True)
def _following_error(a, h, w, zeta):
    """The following error e [m] of a type-2 servo loop (closed loop (2 zeta w s + w^2) /
    (s^2 + 2 zeta w s + w^2)) along the commanded accelerations ``a`` [m/s^2] (steps ``h``
    [s]): e'' + 2 zeta w e' + w^2 e = a, from rest (its static value a / w^2).
    Semi-implicit Euler on sub-steps of at most 0.05 / ``w``, the acceleration
    interpolated."""
    n = a.size
    out = np.empty(n)
    m = max(1, int(math.ceil(w * h / 0.05)))
    hs = h / m
    e = 0.0
    ed = 0.0
    out[0] = 0.0
    for k in range(1, n):
        for i in range(m):
            u = a[k - 1] + (a[k] - a[k - 1]) * (i + 1.0) / m
            ed += hs * (u - 2.0 * zeta * w * ed - w * w * e)
            e += hs * ed
        out[k] = e
    return out


def _racking(a, h, w, ratio, zeta):
    """The gantry's racking [m] (the two sides' following errors' difference) along the
    accelerations ``a`` [m/s^2] (steps ``h`` [s]): the slow side's loop of bandwidth ``w``
    [rad/s], the fast side's ``ratio`` x ``w``, both of damping ``zeta``
    (:func:`_following_error`)."""
    a = np.ascontiguousarray(a, dtype=float)
    return _following_error(a, h, w, zeta) - _following_error(a, h, ratio * w, zeta)


@on_fine_grid
def gantry_racking_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The axis is a gantry (an H-frame) whose bridge is driven on both sides by its own
    motor and servo loop, the loops' bandwidths unequal (the sides' masses, the cable
    chain's side, the tuning): a type-2 loop follows a ramp without error but lags an
    acceleration by ~ a / w^2 (:func:`_following_error`), so the bridge racks by the two
    sides' difference (:func:`_racking`; the slow side's closed-loop period
    :data:`RACK_PERIOD` x the motion's time scale, the fast side :data:`RACK_RATIO` x
    quicker). The racked bridge is stiff in yaw and binds in its guides, pressing their
    carriages diagonally with a force ~ the racking: the Coulomb and Stribeck levels are
    the base's times 1 + ``s`` :data:`RACK_RISE` x |racking| over its top value (99th
    percentile; rounded at zero over :data:`RACK_ROUND` of it), inside the bristle
    dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the bridge's yaw stiffness times the guides' friction
        coefficient, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Dual-drive gantry stages and their racking (Teo, Tan, Lim, Huang and Tay 2007, Dynamic
    modeling and adaptive control of a H-type gantry stage, Mechatronics 17;
    Garcia-Herreros, Kestelyn, Gomand, Coleman and Barre 2013, Model-based decoupling
    control method for dual-drive gantry stages, Control Eng. Pract. 21) and the following
    error of type-2 servo loops (Ellis 2012, Control System Design Guide, 4th ed., ch. on
    following error). The candidate raises the levels with |a|, lagged, tilts them with a
    and adds a force odd in a; the open forms lag, age, heat, skid, load, press, attract,
    squeeze, transfer weight, slosh, dilate, wedge, spring a gib, soften rubber, swing
    arms, unload by the jerk, tilt pads, push ball trains, ripple the current, slide rack
    flanks, set a shoe by a ball in a cone, shut a damper's bypass by an inertia valve or
    creep a belt. Here the two drives' servo lags differ: the structure racks, and binds.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    w = 2.0 * math.pi / (RACK_PERIOD * max(_motion_time(kin), 1e-12))
    r = _racking(kin.a, float(kin.dt), w, RACK_RATIO, RACK_DAMPING)
    top = max(float(np.percentile(np.abs(r), 99)), 1e-300)
    eps = RACK_ROUND * top
    mag = (np.sqrt(r * r + eps * eps) - eps) / top
    lev = 1.0 + float(s) * RACK_RISE * mag
    return level_inside(kin, lev, np.ones_like(lev))


# -- load ------------------------------------------------------------------------------------
#: ``light_load_skid``'s rise of the levels at half the minimum load, at strength 1 [-]; the
#: bearing's minimum load as a quantile of the record's |load| [-]; the rounding of the
#: skid's end, x the minimum load [-]
SKID_RISE, SKID_QUANTILE, SKID_ROUND = 0.5, 70.0, 0.05


def _skid_drag(q, q_min, rounding):
    """The skidding elements' sliding friction [-] (1 at half the minimum load) at the loads
    ``q`` [-] for the minimum load ``q_min`` [-] (same unit): the traction that drives
    them, ~ q, falls short of their drag, ~ q_min, by 1 - q / q_min, their skid's share;
    the sliding it leaves, ~ traction x skid, is 4 (q / q_min) (1 - q / q_min), none above
    the minimum load (rounded over ``rounding`` of it)."""
    r = np.abs(np.asarray(q, float)) / q_min
    return 4.0 * r * _smooth_max0(1.0 - r, rounding)


@on_fine_grid
def light_load_skid_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The contact is a rolling guide (or a roller bearing) whose elements must be driven
    round by their traction at the raceways, ~ the load, against the drag of their cage,
    seals and lubricant. Above the bearing's minimum load the traction suffices and they
    roll; below it they skid, and a share 1 - W / W_min of their speed slides under the
    traction ~ W: a sliding friction ~ W (1 - W / W_min) (:func:`_skid_drag`), none at no
    load, greatest at half the minimum load and none above it (the minimum load the
    record's :data:`SKID_QUANTILE` th percentile of |load|). The Coulomb and Stribeck levels
    are the base's times 1 + ``s`` :data:`SKID_RISE` x that friction, inside the bristle
    dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (load [N]) and its base law.
    s : float
        Amplitude factor [-]: the elements' drag, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Skidding of lightly loaded rolling elements and the minimum load of rolling bearings
    (Harris and Kotzalas 2007, Rolling Bearing Analysis, ch. on high-speed operation and
    skidding; Palmgren 1959, Ball and Roller Bearing Engineering; SKF 2018, Rolling
    bearings catalogue, 'minimum load'; Selvaraj and Marappan 2011, Experimental analysis
    of factors influencing the cage slip in cylindrical roller bearing, Int. J. Adv.
    Manuf. Technol. 53). The candidate makes the levels affine in the load, with a memory
    over the travel; the open forms scale the friction with a Hertz contact's area, a
    seal's, a film's, a junction's, a pivot's, an adhesive contact's or a pin's arc, break,
    squeeze or desorb films, plough, creep, vibrate, overload a pad, heal scuffs, relieve a
    preload, roll on a lossy track, slip differentially in conforming grooves, spin balls
    or press a disc spring. Here the friction comes from too little load: it rises as the
    load falls below the minimum, then falls again towards no load.
    """
    L = np.asarray(kin.load, float)
    Lm = float(np.mean(np.abs(L))) or 1.0
    if not np.ptp(L) > 1e-9 * Lm:
        raise ValueError(f"load (light_load_skid): the {kin.plant} record's load does not "
                         f"change")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    q_min = max(float(np.percentile(np.abs(L), SKID_QUANTILE)), 1e-12 * Lm)
    lev = 1.0 + float(s) * SKID_RISE * _skid_drag(L, q_min, SKID_ROUND)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``pitching_pads``'s mean friction coefficient times the friction's height over the pads'
#: spacing, at strength 1 [-]; the bronze pad's friction at rest over its value at speed,
#: and the speed its excess falls over, x the top speed [-]; the polymer pad's friction at
#: rest and its rise to the top speed, x the bronze's at speed [-]; the direction's
#: rounding, x the top speed [-]
PAD_PITCH, BRONZE_REST, BRONZE_FALL = 0.4, 1.3, 0.1
POLYMER_REST, POLYMER_RISE, PAD_ROUND = 0.9, 0.8, 0.02


def _pad_difference(u):
    """The leading (bronze) pad's friction minus the trailing (polymer) pad's [-] at the
    speeds ``u`` [-] (over the top speed; in the bronze's friction at speed): the bronze's
    falls from :data:`BRONZE_REST` to 1 over :data:`BRONZE_FALL` (boundary to mixed
    lubrication), the polymer's rises linearly from :data:`POLYMER_REST` by
    :data:`POLYMER_RISE` at the top speed (a polymer's velocity strengthening)."""
    au = np.abs(np.asarray(u, float))
    bronze = 1.0 + (BRONZE_REST - 1.0) * np.exp(-au / BRONZE_FALL)
    polymer = POLYMER_REST + POLYMER_RISE * au
    return bronze - polymer


@on_fine_grid
def pitching_pads_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage slides on two pads, one before the other along the motion, of
    different materials: a bronze pad at the +x end, whose friction falls with the speed,
    and a filled-polymer pad at the -x end, whose friction rises with it
    (:func:`_pad_difference`). The friction acts in the pads' plane, the drive a height h
    above it: their moment pitches the carriage and shifts the weight onto the leading pad
    (N_lead = W / 2 + F h / l). Solved for the friction F = F_sym / (1 - (mu_lead -
    mu_trail) h / l): moving +x the bronze pad leads, moving -x the polymer one. The
    Coulomb and Stribeck levels are the base's times 1 / (1 - ``s`` :data:`PAD_PITCH` x
    d(v) x the direction), d the pads' difference (rounded over :data:`PAD_ROUND` x the top
    speed), inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the drive's height over the pads' spacing, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The friction moment's load transfer between the pads of a slider (the self-energising
    and de-energising shoes of drum brakes: Limpert 2011, Brake Design and Safety, 3rd ed.,
    ch. 2; Slocum 1992, Precision Machine Design, ch. 8 on the pitching of carriages by
    friction and drive height) and the opposite speed dependences of bronze and filled
    PTFE slideway linings (Bowden and Tabor 1950; Unal, Mimaroglu, Kadioglu and Ekiz 2004,
    Sliding friction and wear behaviour of polytetrafluoroethylene and its composites,
    Mater. Des. 25). The candidate frees the levels (and the Stribeck velocity and viscous
    term) of each direction and an offset; the open forms twin levels, curves or viscous
    terms, roll lips, load thrust bearings, pump films, ratchet, spring back, tilt pads,
    strut, throttle with a check valve, differ in areas, pump along grooves, buckle,
    scrape chips, commutate, tension idlers, free-wheel, wick felts, run belts, lean
    brushes, pull sealing bands, hold by a counterbalance valve, vibrate the way or pass a
    fluidic diode. Here the friction's own moment weighs two unlike pads: the asymmetry
    turns over with the speed.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    u = np.asarray(kin.v, float) / v99
    shift = float(s) * PAD_PITCH * _pad_difference(u) * np.tanh(u / PAD_ROUND)
    lev = 1.0 / (1.0 - np.clip(shift, -0.9, 0.9))
    return level_inside(kin, lev, np.ones_like(lev))


# -- stribeck_shape --------------------------------------------------------------------------
#: ``wall_slip``'s drag at the top speed, x the friction level, at strength 1 [-]; the speed
#: the wall shear reaches the critical stress at, x the top speed [-]; the film's share of
#: its shear above it, h / (h + b) (b the slip length) [-]; the kink's rounding, x the
#: critical speed [-]
SLIP_DRAG, SLIP_ONSET, SLIP_SHARE, SLIP_ROUND = 0.5, 0.25, 0.15, 0.1


def _slip_shear(u, onset, share, rounding):
    """The film's wall shear stress [-] (1 at the top speed) at the speeds ``u`` [-] (over
    the top speed): Couette flow, ~ u, below the critical stress (at ``onset``); above it
    the walls slip and only the film's ``share`` h / (h + b) of the further speed shears
    it (rounded over ``rounding`` x the critical speed, the rounding's offset at rest
    taken off); odd in u."""
    u = np.asarray(u, float)

    def tau(x):
        r = x / onset
        return r - (1.0 - share) * _smooth_max0(r - 1.0, rounding)
    t0 = tau(0.0)
    return np.sign(u) * (tau(np.abs(u)) - t0) / (tau(1.0) - t0)


@on_fine_grid
def wall_slip_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The way's lubricant film (a thin boundary-additive or polymer-thickened oil on a
    smooth, oleophobic coating) sticks to the walls below a critical wall shear stress and
    slips along them above it, with a slip length b several times the film's thickness h
    (Navier's partial slip, the 'half-slip' of smooth surfaces): its drag grows as
    Couette's, ~ v, up to the critical speed (:data:`SLIP_ONSET` x the top speed), and
    beyond it only h / (h + b) (:data:`SLIP_SHARE`) of the further speed shears the film
    (:func:`_slip_shear`). The truth adds ``s`` :data:`SLIP_DRAG` x the friction level x
    that drag (1 at the top speed) to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (with a Stribeck curve).
    s : float
        Amplitude factor [-]: the film's viscosity over its thickness (its drag), / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Boundary slip of liquids (Navier 1823; Spikes and Granick 2003, Equation for slip of
    simple liquids at smooth solid surfaces, Langmuir 19; Spikes 2003, The half-wetted
    bearing, Proc. Inst. Mech. Eng. J 217; Neto, Evans, Bonaccurso, Butt and Craig 2005,
    Boundary slip in Newtonian liquids: a review of experimental studies, Rep. Prog. Phys.
    68). The candidate reshapes the Stribeck curve; the open forms add a tail, a rational
    drop, a hydrodynamic rise, a spike, a lift-off, two roughness scales, a logarithmic or
    Eyring law, starve a film, add rubber hysteresis, resonate, dither, melt, flow grains,
    readsorb, heat the film, make it turbulent, thixotropic, churned or shear-thinning, add
    core losses, breathe a bellows, brake by eddy currents, fly a pad, wipe a meniscus or
    lift a journal. Here the film's bulk is Newtonian: its walls let go, and the drag
    bends at a critical stress.
    """
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (wall_slip): the mre_lugre base has no Stribeck "
                         "curve")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    d = _slip_shear(np.asarray(kin.v, float) / v99, SLIP_ONSET, SLIP_SHARE, SLIP_ROUND)
    return F + float(s) * SLIP_DRAG * _level(kin) * d


# -- position --------------------------------------------------------------------------------
#: ``track_end``'s drop of the levels with the forcer wholly off the track, at strength 1
#: [-]; the end's reluctance pull, x the friction level, at strength 1 [-]; the forcer's
#: length and where the track ends, x the visited stroke (from its low end) [-]; the
#: fringing field's reach, x the forcer's length [-]
TRACK_DROP, TRACK_PULL, FORCER_LENGTH, TRACK_END, TRACK_FRINGE = 0.4, 0.4, 0.4, 0.9, 0.08


def _overlap(x, length, end, fringe):
    """The forcer's overlap with the magnet track [-] (1 wholly over it) at the forcer's
    centres ``x`` [-] (over the stroke), the forcer ``length`` long, the track ending at
    ``end``: (end - (x - length / 2)) / length clipped to 0..1, its corners rounded over
    ``fringe`` x ``length`` (the fringing field)."""
    r = (end - (np.asarray(x, float) - 0.5 * length)) / length
    e = fringe
    lo = _smooth_max0(r, e)
    return lo - _smooth_max0(lo - 1.0, e)


@on_fine_grid
def track_end_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The axis is driven by an iron-core linear motor whose magnet track ends within the
    stroke (a short track, a gap between its plates): the forcer (:data:`FORCER_LENGTH` x
    the stroke long) runs off the track's end (at :data:`TRACK_END` of the stroke). Its
    magnetic pull on the guides is ~ its overlap with the track (:func:`_overlap`); the base
    law, identified over the track, carries the whole pull, and the Coulomb and Stribeck
    levels are the base's times 1 - ``s`` :data:`TRACK_DROP` (1 - overlap), inside the
    bristle dynamics. The magnetic energy ~ the overlap also pulls the forcer back onto the
    track along its run-off (a reluctance force ~ -d overlap / dx, :data:`TRACK_PULL` x the
    friction level x ``s`` there), which the drive carries: added to the force, the same
    in both directions.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the magnets' pull, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The normal (attraction) force of iron-core permanent-magnet linear motors and its end
    effects (Gieras, Piech and Tomczuk 2011, Linear Synchronous Motors, 2nd ed., ch. on
    forces and end effects; Boldea and Nasar 1997, Linear Electric Actuators and
    Generators). The candidate scales the friction along the stroke and adds a force of the
    position; the open forms put a defect, a waviness, a worn section, runout, a bent rail,
    a transfer film, cogging, a taper, a pocket, a cushion, a cover, an air spring, bolt
    holes, a plunger, a sag, a festoon, a curve, a chain, a cam, a heated zone, brinelled
    dents, a rail joint, misaligned rails, a spool's flow force, a crank or an overhang on
    the stroke. Here the preload itself ends with the magnets: the friction falls, and a
    pull appears, where the forcer leaves its track.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (track_end): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    span = max(sc["x_hi"] - sc["x_lo"], 1e-12)
    xr = (np.asarray(kin.x, float) - sc["x_lo"]) / span
    o = _overlap(xr, FORCER_LENGTH, TRACK_END, TRACK_FRINGE)
    h = 1e-4
    slope = (_overlap(xr + h, FORCER_LENGTH, TRACK_END, TRACK_FRINGE)
             - _overlap(xr - h, FORCER_LENGTH, TRACK_END, TRACK_FRINGE)) / (2.0 * h)
    lev = np.maximum(1.0 - float(s) * TRACK_DROP * (1.0 - o), 0.05)
    pull = -float(s) * TRACK_PULL * _level(kin) * slope * FORCER_LENGTH
    return level_inside(kin, lev, np.ones_like(lev)) + pull


# -- inertia ---------------------------------------------------------------------------------
#: ``qzs_isolator``'s payload mass at strength 1, x the friction level / a99 [kg per N s^2/m];
#: the period of its mode at the top acceleration's deflection, x the motion's time scale
#: [-]; the damper's ratio to that mode's critical damping [-]
QZS_MASS, QZS_PERIOD, QZS_DAMPING = 0.5, 0.5, 0.3


@njit(cache=True)
def _qzs_force(a, h, k3, c, w_top):
    """The force [N per kg] a payload on a quasi-zero-stiffness mount (a cubic spring
    ``k3`` y^3 [m/s^2 per m^3] and a damper ``c`` [1/s] in parallel, y the payload's
    deflection from the carriage) exerts on the carriage under its accelerations ``a``
    [m/s^2] (steps ``h`` [s]): y'' = -a - k3 y^3 - c y', the force -(k3 y^3 + c y') = a +
    y''. Semi-implicit Euler on sub-steps of at most 0.05 / (2 ``w_top``) (the mode's
    rate at twice the top acceleration's deflection), the acceleration interpolated, from
    rest."""
    n = a.size
    out = np.empty(n)
    m = max(1, int(math.ceil(2.0 * w_top * h / 0.05)), int(math.ceil(c * h / 0.5)))
    hs = h / m
    y = 0.0
    yd = 0.0
    out[0] = 0.0
    for k in range(1, n):
        f = 0.0
        for i in range(m):
            u = a[k - 1] + (a[k] - a[k - 1]) * (i + 1.0) / m
            f = -(k3 * y * y * y + c * yd)
            yd += hs * (f - u)
            y += hs * yd
        out[k] = -(k3 * y * y * y + c * yd)
    return out


@on_fine_grid
def qzs_isolator_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A payload (an instrument, an optical table top) rides on the carriage on a
    quasi-zero-stiffness isolator: a vertical spring balanced by oblique springs'
    negative stiffness about its working point, which leaves a cubic stiffness k3 y^3,
    in the direction of travel here, with a damper c y' in parallel. The inverse dynamics
    misses it. The carriage carries the force that accelerates it, k3 y^3 + c y'
    (:func:`_qzs_force`): for strokes that deflect the mount far it follows, its whole
    mass; for small or slow relative motions its spring hardly holds it and only the
    damper drags it along. The mount deflects by y_top under the top acceleration (its mode
    there of period :data:`QZS_PERIOD` x the motion's time scale, w_top^2 = 3 k3 y_top^2),
    the damper :data:`QZS_DAMPING` of that mode's critical. The truth adds ``s``
    :data:`QZS_MASS` x the friction level / a99 x that force per unit mass to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the payload's mass, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Quasi-zero-stiffness isolators (Alabuzhev, Gritchin, Kim, Migirenko, Chon and Stepanov
    1989, Vibration Protecting and Measuring Systems with Quasi-Zero Stiffness; Carrella,
    Brennan and Waters 2007, Static analysis of a passive vibration isolator with
    quasi-zero-stiffness characteristic, J. Sound Vib. 301; Kovacic, Brennan and Waters
    2008, A study of a nonlinear vibration isolator with a quasi-zero stiffness
    characteristic, J. Sound Vib. 315). The candidate misses a constant mass; the open
    forms filter it, reflect it through gearing, a chain's polygon or a pinion, hang it on
    a spring, a cable, a fluid, a clutch, a coupling, a flyweight, a screw, a
    friction-damped mount or a surging spring, add a fluid's mass and its history, pick it
    up, drop it, empty it, slide it, rattle it, telescope it, roll it in a cradle, rock it
    on its edges, recoil the frame, saturate the motor, lead it by the feedforward or pitch
    the scale head. Here the mass hangs on a spring with no linear stiffness: how much of
    it the carriage carries depends on how far the motion deflects its mount.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    w_top = 2.0 * math.pi / (QZS_PERIOD * max(_motion_time(kin), 1e-12))
    y_top = 3.0 * a99 / (w_top * w_top)
    k3 = a99 / y_top ** 3
    c = 2.0 * QZS_DAMPING * w_top
    f = _qzs_force(np.ascontiguousarray(kin.a, dtype=float), float(kin.dt), k3, c, w_top)
    return F + float(s) * QZS_MASS * _level(kin) / a99 * f


# -- delay -----------------------------------------------------------------------------------
#: ``force_restoration``'s lag (the lever pivot's stiffness over the loop's cube of
#: bandwidth) at strength 1 [data samples]; the pivot's stiffness over the square of the
#: loop's bandwidth (per unit lever mass) [-]
RESTORE_SAMPLES, PIVOT_SHARE = 5.0, 1.0


def _restoring_coefficients(kappa):
    """(numerator, denominator) of the coil's force over the applied force, per unit lever
    mass and in the loop's time unit 1 / w (S = s / w), for a PID loop that places the
    closed loop's three poles at S = -1 against a lever pivot of stiffness ``kappa`` w^2:
    (3 S^2 + (3 - kappa) S + 1) / (S + 1)^3; its static gain 1 and its low-frequency lag
    kappa / w."""
    return np.array([3.0, 3.0 - kappa, 1.0]), np.array([1.0, 3.0, 3.0, 1.0])


@on_fine_grid
def force_restoration_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is read by an electromagnetic force-restoration (force-compensation)
    cell, as in precision balances: the force acts on a lever on a flexure pivot, a
    position sensor sees its deflection, and a PID loop drives a coil in a magnet that
    pushes the lever back to its null; the coil's current, ~ its force, is the reading.
    While the loop works the lever's inertia and the pivot's spring take part of the
    force, so the coil's force lags it: the loop's poles placed at -w (a triple pole;
    :func:`_restoring_coefficients`), the pivot's stiffness :data:`PIVOT_SHARE` x w^2 per
    unit mass, the reading lags by PIVOT_SHARE / w = ``s`` :data:`RESTORE_SAMPLES` data
    samples at low frequencies and rings through the loop's zeros at high ones (the
    bilinear transform on the fine grid, from the record's first force). The motion
    channels are on time.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the loop's time constant 1 / w, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Electromagnetic force compensation (EMFC) weighing cells (Kochsiek and Glaser 2000,
    Comprehensive Mass Metrology, ch. on weighing cells; Diethold, Kuehnel, Hilbrunner,
    Froehlich and Manske 2014, Determination of force to displacement curves using a
    nanopositioning system based on electromagnetic force compensated balances,
    Measurement 51). The candidate shifts the force by a constant time, low-passes it,
    reads it through a transducer's resonance and leaks it; the open forms sample, filter,
    average, hold, skew, jitter, rate-limit, transmit, median, report by deadband, trigger
    on positions, run a belt, aerate, drop telegrams, leak, creep, notch, track, snub,
    time a waveguide's pulse, diffuse eddy currents, count a resonator's frequency over a
    gate or sweep a grating. Here the sensor is itself a servo: the reading is the force a
    loop needs to hold a sprung lever still.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    lag = float(s) * RESTORE_SAMPLES * kin.sample_dt
    w = PIVOT_SHARE / max(lag, 1e-300)
    num, den = _restoring_coefficients(PIVOT_SHARE)
    numd, dend, _ = cont2discrete((num, den), float(kin.dt) * w, method="bilinear")
    b = np.ravel(numd)
    zi = lfilter_zi(b, dend) * F[0]
    return lfilter(b, dend, F, zi=zi)[0]


# -- drift -----------------------------------------------------------------------------------
#: ``pump_down``'s rise of the levels by the record's end, at strength 1 [-]; the pressure's
#: e-folding time of the pump-down, x the record's length [-]; the layer's Langmuir
#: constant times the starting pressure [-]; the chamber's base pressure over the starting
#: one [-]; the layer's desorption rate, x 1 / the record's length [-]
PUMP_RISE, PUMP_TIME, PUMP_AFFINITY, PUMP_FLOOR, PUMP_DESORB = 0.4, 0.08, 1e3, 1e-5, 12.0


@njit(cache=True)
def _coverage(tau, pressure, affinity, rate):
    """The adsorbed layer's coverage theta [-] along the times ``tau`` [-] (over the
    record's length) at the pressures ``pressure`` [-] (over the starting one): Langmuir's
    kinetics d theta / d tau = ``rate`` (``affinity`` p (1 - theta) - theta), implicit
    Euler, from its equilibrium at the first pressure."""
    n = tau.size
    out = np.empty(n)
    th = affinity * pressure[0] / (1.0 + affinity * pressure[0])
    out[0] = th
    for k in range(1, n):
        h = (tau[k] - tau[k - 1]) * rate
        bp = affinity * pressure[k]
        th = (th + h * bp) / (1.0 + h * (bp + 1.0))
        out[k] = th
    return out


def _pressure(tau, time, floor):
    """The chamber's pressure over its starting one [-] at the times ``tau`` [-] (over the
    record's length): a pump-down exp(-tau / ``time``) to the base pressure ``floor``."""
    return np.exp(-np.asarray(tau, float) / time) + floor


@on_fine_grid
def pump_down_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The machine runs in a vacuum chamber being pumped down (a load lock, a coating or
    space-simulation chamber): the pressure falls as exp(-t / tau) (:data:`PUMP_TIME` x
    the record's length) to the base pressure :data:`PUMP_FLOOR` (:func:`_pressure`). The
    contact's surfaces carry an adsorbed gas layer (water, oxygen) that lubricates them;
    its coverage follows Langmuir's kinetics (:func:`_coverage`; affinity
    :data:`PUMP_AFFINITY` at the starting pressure, desorption rate :data:`PUMP_DESORB`
    per record): it hardly changes while b p >> 1, then desorbs, late and fast, as the
    pressure passes 1 / b, lagging it by its desorption time. As the layer goes, the bare
    surfaces' adhesion raises the friction: the Coulomb and Stribeck levels are the base's
    times 1 + ``s`` :data:`PUMP_RISE` x the coverage's loss over its loss by the record's
    end, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the bare surfaces' friction over the covered ones', / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Friction in vacuum and the loss of adsorbed films (Bowden and Tabor 1964, The Friction
    and Lubrication of Solids, part II, ch. on clean surfaces; Buckley 1981, Surface
    Effects in Adhesion, Friction, Wear and Lubrication, ch. 5; Langmuir 1918, The
    adsorption of gases on plane surfaces of glass, mica and platinum, J. Am. Chem. Soc.
    40; O'Hanlon 2003, A User's Guide to Vacuum Technology, ch. on pump-down). The
    candidate is a trend, a saturating change, a step, a cycle, a resetting change or the
    friction power's heat; the open forms warm up, wear in, change the lubricant, heat,
    wear, follow the humidity, grind a third body, relubricate, relax a seal, oxidise,
    deplete, wear through, swell, build a tribofilm, take in particles, expand, shear down,
    heat magnets, charge, creep a cage, loosen a screw, dewet a film, channel grease, drain
    a receiver, grow a spall or evaporate an oil. Here the ambient gas is taken away: a
    change that waits for the pressure to pass the layer's, then runs its course.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    tau = (t - t[0]) / max(t[-1] - t[0], 1e-12)
    th = _coverage(np.ascontiguousarray(tau), _pressure(tau, PUMP_TIME, PUMP_FLOOR),
                   PUMP_AFFINITY, PUMP_DESORB)
    loss = max(float(th[0] - th[-1]), 1e-12)
    lev = 1.0 + float(s) * PUMP_RISE * (th[0] - th) / loss
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: ``graded_clearance``'s play at strength 1, as a share of the stroke (its full width, both
#: sides, to the last pin) [-]; the number of pins [-]; the clearances' spread, x the play's
#: half-width (the first pin engages at 1 - that) [-]; the pins' force when the last one
#: engages, x the Coulomb level [-]
GRADED_CLEAR, GRADED_PINS, GRADED_SPREAD, GRADED_LOAD = 0.01, 8, 0.6, 1.5


@njit(cache=True)
def _pin_force(e, ed, first, step, pins, kp, m):
    """The pins' force [N] on the contact at the offset ``e`` [m] (drive minus contact) and
    its rate ``ed`` [m/s]: pin j (0 .. ``pins`` - 1) engages at |e| = ``first`` + j
    ``step`` [m] and pushes with its stiffness ``kp`` [N/m] (compressive only), damped at
    the ratio 0.5 of the engaged pins' stiffness for the contact's mass ``m`` [kg]."""
    ae = abs(e)
    f = 0.0
    n = 0
    for j in range(pins):
        d = ae - (first + j * step)
        if d > 0.0:
            f += kp * d
            n += 1
    if n == 0:
        return 0.0
    sg = 1.0 if e > 0.0 else -1.0
    c = 2.0 * 0.5 * math.sqrt(n * kp * m)
    f2 = f + c * ed * sg
    if f2 < 0.0:
        f2 = 0.0
    return sg * f2


@njit(cache=True)
def _pinned_contact(h, xd, first, step, pins, kp, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a light contact of mass ``m`` [kg] driven by the drive
    positions ``xd`` [m] (steps ``h`` [s]) through the pins of :func:`_pin_force`."""
    n = xd.size
    F = np.empty(n)
    x = xd[0] - first - (pins - 1) * step
    v = 0.0
    z = 0.0
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        fc = _pin_force(xd[j] - x, vd - v, first, step, pins, kp, m)
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha,
                                         shape)
        x = x + h * v
    return F


@on_fine_grid
def graded_clearance_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact are joined by :data:`GRADED_PINS` pins (a cycloid drive's ring
    pins, a pin gear, a multi-key coupling) whose clearances the machining tolerances
    spread: the play's half-width (``s``^2 :data:`GRADED_CLEAR` / 2 x the stroke) is the
    last pin's clearance, the first engages :data:`GRADED_SPREAD` of it earlier, the
    others evenly between. After a reversal the drive crosses the play, the first pin
    takes up the contact alone, then the next joins, and so on: a take-up whose stiffness
    grows stepwise with the number of pins carrying (each pin's stiffness such that the
    pins push with :data:`GRADED_LOAD` x the Coulomb level when the last engages; at most
    the flank stiffness of the other plays in all). The contact is light (its inertial
    force at the top acceleration 1 % of the Coulomb level) with the base's LuGre friction
    (:func:`_pinned_contact`).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the square root of the clearance, / its value at strength 1
        (as the open plays').

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Load sharing among the pins of cycloid drives with machining tolerances (Blanche and
    Yang 1989, Cycloid drives with machining tolerances, J. Mech. Transm. Autom. Des. 111;
    Gorla, Davoli, Rosa, Longoni, Chiozzi and Samarani 2008, Theoretical and experimental
    analysis of a cycloidal speed reducer, J. Mech. Des. 130; Li, Wu, Wang and Liu 2017 on
    lost motion of RV reducers). The candidate holds or frees the contact across a rigid
    play; the open forms take it up rigidly, compliantly, by impact, against a spring,
    eccentrically, through oil, worn, with a dragging idler, biased, slack, magnetic,
    preloaded, through a flexspline, a rope, a spider, a fluid link, a cable, a clutch, a
    varying mesh, a polymer gear, grease, a wedge, an overlapped spool, a side loaded pin
    or a toggle spring. Here the play ends not at one flank but at many, one after the
    other.
    """
    p = _lugre_params(kin, "backlash (graded_clearance)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    half = 0.5 * float(s) ** 2 * GRADED_CLEAR * float(np.ptp(kin.x))
    pins = int(GRADED_PINS)
    first = (1.0 - GRADED_SPREAD) * half
    step = GRADED_SPREAD * half / (pins - 1)
    m, kh, _ = _contact_constants(kin, p)
    kp = min(2.0 * GRADED_LOAD * float(p.Fc) / max(step * pins * (pins - 1), 1e-300),
             kh / pins)
    rate = max(math.sqrt(pins * kp / m), (float(p.sigma1) + float(p.sigma2)
                                           + math.sqrt(pins * kp * m)) / m)
    h, xd, n_sub = _substeps(kin, rate)
    Fr = _pinned_contact(h, xd, first, step, pins, kp, m, float(p.sigma0), float(p.sigma1),
                         float(p.sigma2), float(p.Fc), float(p.Fs), float(p.vs),
                         float(p.alpha), SHAPES[p.shape])
    return Fr[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: the film's elastic path to its stress at the top speed at strength 1, beyond the base
#: bristle's path, as a share of the stroke / 3 [-]; its share of the friction at strength
#: 1 [-]; its Eyring speed (where its flow turns from linear to exponential in the
#: stress), x the top speed [-]
EF_PATH, EF_SHARE, EF_EYRING = 0.1, 0.6, 1e-3


@njit(cache=True)
def _eyring_film(t, v, path, v_top, v_eyring):
    """The film's shear stress u [-] (1 in steady sliding at ``v_top`` [m/s]) along the
    velocities ``v`` [m/s] at the times ``t`` [s]: a nonlinear Maxwell element, its elastic
    path ``path`` [m] to u = 1, its flow speed v_E sinh(A u) (v_E = ``v_eyring``, A =
    asinh(v_top / v_E)): du/dt = (v - v_E sinh(A u)) / path, implicit Euler (Newton on
    each step, the velocity at the step's end), from no stress."""
    n = t.size
    out = np.zeros(n)
    A = math.asinh(v_top / v_eyring)
    u = 0.0
    for k in range(1, n):
        h = (t[k] - t[k - 1]) / path
        vk = v[k]
        x = u
        for _ in range(60):
            ax = min(max(A * x, -60.0), 60.0)
            g = x - u - h * (vk - v_eyring * math.sinh(ax))
            dg = 1.0 + h * v_eyring * A * math.cosh(ax)
            dx = g / dg
            x -= dx
            if abs(dx) < 1e-12 * (1.0 + abs(x)):
                break
        u = x
        out[k] = u
    return out


@on_fine_grid
def eyring_film_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Part of the contact is carried through an elastohydrodynamic film (a traction
    fluid's, a highly loaded rolling-sliding contact's), whose shear follows Johnson and
    Tevaarwerk's nonlinear Maxwell model: elastic (the film's shear modulus) for quick
    changes of strain and an Eyring fluid in steady shear, its flow rate ~ sinh of the
    stress: du/dt = (v - v_E sinh(A u)) / path (:func:`_eyring_film`; its elastic path the
    base bristle's Fs / sigma0 plus ``s`` :data:`EF_PATH` x the stroke / 3, v_E
    :data:`EF_EYRING` x the top speed, u = 1 in steady sliding at the top speed). After a
    reversal the stress unloads elastically and then flows, at rest it relaxes (no static
    hold), and in steady sliding it follows the speed logarithmically. Its share w = ``s``
    :data:`EF_SHARE` (up to ``s`` = 1) of the friction is its stress times the Stribeck
    level, the viscous term the base's: F = (1 - w) F_lugre + w (g(v) u + sigma2 v). At
    ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the film's share (up to ``s`` = 1) and its elastic path (as
        the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The viscoelastic shear of elastohydrodynamic films (Johnson and Tevaarwerk 1977, Shear
    behaviour of elastohydrodynamic oil films, Proc. R. Soc. Lond. A 356; Evans and Johnson
    1986, The rheological properties of elastohydrodynamic lubricants, Proc. Inst. Mech.
    Eng. C 200; Eyring 1936). The candidate's presliding is a generalized Maxwell-slip (GMS)
    element set; the open forms are Maxwell-slip sets, Dahl, elasto-plastic,
    Bliman-Sorine, Bouc-Wen, Zener junctions, Mindlin contacts, rate-and-state, Tomlinson
    asperities, bond rupture, gouge, kinematic hardening, interlocking, capillary bridges,
    cyclic hardening, peeling, unloading microslip, a power-law joint, junction growth,
    avalanches, slip weakening, a microslip bar, contact renewal, a grease's yield and a
    superelastic flexure. Here the presliding is a liquid's elasticity: no yield, no
    sticking, and a relaxation at rest.
    """
    p = _lugre_params(kin, "gms (eyring_film)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, EF_PATH)
    w = EF_SHARE * min(float(s), 1.0)
    v = np.ascontiguousarray(kin.v, dtype=float)
    v99 = max(kin.scales["v99"], 1e-12)
    u = _eyring_film(np.ascontiguousarray(kin.t, dtype=float), v, e0 + extra, v99,
                     EF_EYRING * v99)
    return (1.0 - w) * F + w * (kin.base.g(v) * u + float(p.sigma2) * v)
