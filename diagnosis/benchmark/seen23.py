"""The twenty-third seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-30 (session 27) by another hand, once, without running the diagnosis on it;
run once, sealed, at the start of session 28 on the code of 25e7bb5:
176 cases, 0 skipped, 538 s wall on 2 workers. Top-1 51.7 % (91;
52.9 % of the 170 detectable; the other 6: delays below a sample); mean |shrink error|
0.296; wrong names on 24 (13.6 %): acceleration -> inertia 7, gms -> delay 5, position ->
asymmetry 4, drift -> load 3, inertia -> acceleration 2, asymmetry -> stribeck_shape 1,
acceleration -> position 1, acceleration -> delay 1. By form: drift/oil_evaporation 17/20,
inertia/rocking_block 14/20, delay/swept_grating 13/20, load/disc_spring_pad 11/20,
asymmetry/fluidic_diode 11/20, position/drawer_overhang 10/16, acceleration/belt_creep
5/20, backlash/toggle_spring 4/12, gms/superelastic_flexure 4/12,
stribeck_shape/sommerfeld_journal 2/16. By plant: valve 67.5 %, forging press 50.0 %,
damping rig 47.5 %, isolator 46.4 %, XML-350 45.0 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen22` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen22`,
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
acceleration       ``belt_creep``: the carriage is driven by a flat belt, which creeps
                   elastically over its pulleys (Reynolds): the creep's loss is the
                   transmitted force squared over the belt's stiffness, and the force
                   the belt carries is the carriage's friction plus the inertial force of
                   the driven mass: a drag that grows with the square of the drive force
load               ``disc_spring_pad``: a drag pad is pressed on the way by a disc
                   (Belleville) spring that the carriage's Hertzian approach under the
                   load compresses further: the pad's force follows the disc spring's
                   non-linear characteristic (Almen-Laszlo), rising and then falling
                   with the load past the spring's flat top
asymmetry          ``fluidic_diode``: a damper whose oil passes a valvular conduit
                   (Tesla's fluidic diode, no moving part): laminar and even at low
                   speed, and a resistance of the flow's inertia at speed whose
                   diodicity grows with the Reynolds number: the drag differs between
                   the directions only at speed
stribeck_shape     ``sommerfeld_journal``: the carriage runs on track rollers turning
                   on plain journal bearings: the journals' friction follows the
                   Sommerfeld number through the shaft's eccentricity (the full
                   Sommerfeld solution): a shallow dip from the boundary value at rest to
                   its least at moderate speed, then Petroff's linear rise
position           ``drawer_overhang``: the moving part is a ram that runs out of a
                   fixed sleeve with a weight at its nose (a drawer, a quill): its two
                   bearing reactions grow as the overhang grows and the engagement
                   shrinks (the drawer effect), a friction that rises hyperbolically
                   towards the extended end of the stroke
inertia            ``rocking_block``: a free-standing block on the carriage rocks on its
                   edges (Housner's rocking block) once the acceleration passes g times
                   its width over its height: a missed mass while it stands, less while
                   it rocks, with its impacts' energy loss when it lands
delay              ``swept_grating``: the force is read by a fibre Bragg grating
                   interrogated by a swept laser: each sweep finds the grating's
                   wavelength at the time within the sweep set by the force itself, and
                   the reading is held from the sweep's end: a force-dependent sampling
                   instant and a hold
drift              ``oil_evaporation``: the lubricant's volatile fraction evaporates
                   from the thin film on the way (Noack volatility): the film thins
                   towards the heavy fraction's and the asperities' share of the load
                   (the Gaussian tail of the film parameter) rises with a delayed
                   onset
backlash           ``toggle_spring``: drive and contact are joined across the play by an
                   over-centre (toggle) spring: a negative stiffness that holds the
                   contact at the flank it last touched and, past the centre, pushes it
                   towards the other: after a reversal the force the contact feels turns
                   over before the flank arrives
gms                ``superelastic_flexure``: part of the contact is carried through a
                   superelastic (NiTi) flexure: elastic, then a stress-induced
                   martensitic transformation on a plateau, and on unloading the reverse
                   transformation on a lower plateau back to no residual strain: a
                   flag-shaped presliding loop (Auricchio); at ``s`` = 0 the base
                   itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``sommerfeld_journal``
needs a Stribeck curve (not the isolator's mre_lugre), ``drawer_overhang`` a record that
revisits its positions (not the press), ``disc_spring_pad`` a load that changes,
``toggle_spring`` and ``superelastic_flexure`` a classic LuGre base (valve, damping rig,
XML-350); each raises a ``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit
from scipy.special import erfc

from friction.shapes import SHAPES

from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _level,
                     _light_contact_step, _lugre_params, _motion_time, _presliding_path,
                     _substeps, has_stribeck_curve, level_inside, on_fine_grid)

__all__ = ["FORMS", "belt_creep_truth", "disc_spring_pad_truth", "fluidic_diode_truth",
           "sommerfeld_journal_truth", "drawer_overhang_truth", "rocking_block_truth",
           "swept_grating_truth", "oil_evaporation_truth", "toggle_spring_truth",
           "superelastic_flexure_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "belt_creep", "load": "disc_spring_pad",
         "asymmetry": "fluidic_diode", "stribeck_shape": "sommerfeld_journal",
         "position": "drawer_overhang", "inertia": "rocking_block",
         "delay": "swept_grating", "drift": "oil_evaporation",
         "backlash": "toggle_spring", "gms": "superelastic_flexure"}

#: the acceleration of gravity [m/s^2]
GRAVITY = 9.81


# -- acceleration ----------------------------------------------------------------------------
#: ``belt_creep``'s creep drag at the record's top transmitted force, x the friction level,
#: at strength 1 [-]; the driven mass's inertial force at the top acceleration, x the
#: friction level [-]; the speed the drag turns over, x the top speed [-]
CREEP_DRAG, CREEP_MASS, CREEP_ROUND = 0.5, 2.0, 2e-3


def _creep_loss(tension):
    """The belt's creep loss force over its value at the unit transmitted force [-] at the
    transmitted forces ``tension`` [-]: the belt's strain drops by Delta T / (E A) across
    the pulley's slip arc, so it slides on the pulley at v Delta T / (E A) under the
    force Delta T: a loss power v Delta T^2 / (E A), a force Delta T^2 / (E A)."""
    q = np.asarray(tension, float)
    return q * q


@on_fine_grid
def belt_creep_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage is driven by a flat (friction) belt. Wrapped over its pulleys, the belt
    stretches by T / (E A) on the tight span and less on the slack one; over each pulley's
    slip arc it contracts or stretches from one to the other and so creeps on the pulley's
    rim (Reynolds' creep) at the speed v (T1 - T2) / (E A) against the rim's friction,
    which carries the transmitted force T1 - T2: a loss v (T1 - T2)^2 / (E A), a drag
    (T1 - T2)^2 / (E A) at the carriage (:func:`_creep_loss`). The belt transmits what the
    drive applies: the base force plus the inertial force of the driven mass
    (:data:`CREEP_MASS` x the friction level at the top acceleration). The truth adds
    ``s`` :data:`CREEP_DRAG` x the friction level x that force squared over its top value
    (99th percentile) squared, along the velocity, to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the belt's compliance 1 / (E A), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Elastic creep of belts (Reynolds 1874, On the efficiency of belts or straps as
    communicators of work, The Engineer 38; Swift 1928, Power transmission by belts, Proc.
    Inst. Mech. Eng. 2; Firbank 1970, Mechanics of the belt drive, Int. J. Mech. Sci. 12;
    Johnson 1985, Contact Mechanics, on creep in belt drives). The candidate raises the
    levels with |a|, lagged, tilts them with a and adds a force odd in a; the open forms
    lag, age, heat, skid, load, press, attract, squeeze, transfer weight, slosh, dilate,
    wedge, spring a gib, soften rubber, swing arms, unload by the jerk, tilt pads, push
    ball trains, ripple the current, slide rack flanks, set a shoe by a ball in a cone or
    shut a damper's bypass by an inertia valve. Here the drive's own elasticity slips: a
    drag of the square of the drive force, even in a.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    v99 = max(kin.scales["v99"], 1e-12)
    lev = _level(kin)
    T = F + CREEP_MASS * lev / a99 * np.asarray(kin.a, float)
    top = max(float(np.percentile(np.abs(T), 99)), 1e-12 * lev)
    turn = np.tanh(np.asarray(kin.v, float) / (CREEP_ROUND * v99))
    return F + float(s) * CREEP_DRAG * lev * _creep_loss(T / top) * turn


# -- load ------------------------------------------------------------------------------------
#: ``disc_spring_pad``'s rise of the levels at the disc spring's peak force, at strength 1
#: [-]; the disc's free cone height over its thickness [-]; its deflection at the record's
#: least load and what the carriage's approach from there to the top load adds, in disc
#: thicknesses [-]
PAD_SHARE, DISC_HEIGHT, DISC_SET, DISC_SPAN = 0.4, 2.0, 0.6, 2.2


def _disc_force(f, height):
    """A disc (Belleville) spring's force [-] at the deflections ``f`` [-] (in thicknesses)
    for the free cone height ``height`` [-] (in thicknesses), Almen and Laszlo's
    f ((height - f) (height - f / 2) + 1), over its top (its local peak, on 0 <= f <=
    height; past the flat the disc's force falls, and rises again only once it has passed
    through its plane)."""
    f = np.asarray(f, float)
    P = f * ((height - f) * (height - 0.5 * f) + 1.0)
    grid = np.linspace(0.0, height, 4001)
    peak = float(np.max(grid * ((height - grid) * (height - 0.5 * grid) + 1.0)))
    return P / peak


@on_fine_grid
def disc_spring_pad_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A drag pad (a clamping or damping pad) is pressed on the way by a disc (Belleville)
    spring seated in the carriage. The load presses the carriage onto its guide, whose
    Hertzian approach ~ load^(2/3) compresses the disc further: set to :data:`DISC_SET`
    thicknesses at the record's least load (1st percentile), the approach to its top load
    (99th percentile) adds :data:`DISC_SPAN`. The disc's force follows Almen and
    Laszlo's characteristic (:func:`_disc_force`, the cone's height :data:`DISC_HEIGHT`
    thicknesses): it rises, flattens over the disc's top and falls past it (the negative
    stiffness of a disc spring flattening towards its plane). The Coulomb and Stribeck
    levels are the base's times 1 + ``s`` :data:`PAD_SHARE` x that force over its peak,
    inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (load [N]) and its base law.
    s : float
        Amplitude factor [-]: the pad's friction coefficient times the disc's stiffness, /
        its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Disc springs (Almen and Laszlo 1936, The uniform-section disk spring, Trans. ASME 58;
    DIN EN 16983 / DIN 2092, disc springs' characteristics) and the Hertzian approach of a
    carriage on its guide (Johnson 1985, Contact Mechanics, ch. 4). The candidate makes
    the levels affine in the load, with a memory over the travel; the open forms scale the
    friction with a Hertz contact's area, a seal's, a film's, a junction's, a pivot's, an
    adhesive contact's or a pin's arc, break, squeeze or desorb films, plough, creep,
    vibrate, overload a pad, heal scuffs, relieve a preload, roll on a lossy track, slip
    differentially in conforming grooves or spin balls. Here a spring of negative
    stiffness past its top sets the friction: it grows with the load, then falls.
    """
    L = np.asarray(kin.load, float)
    Lm = float(np.mean(np.abs(L))) or 1.0
    if not np.ptp(L) > 1e-9 * Lm:
        raise ValueError(f"load (disc_spring_pad): the {kin.plant} record's load does not "
                         f"change")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    top = max(float(np.percentile(np.abs(L), 99)), 1e-12 * Lm)
    low = min(float(np.percentile(np.abs(L), 1)) / top, 1.0)
    q = np.abs(L) / top
    span = max(1.0 - low ** (2.0 / 3.0), 1e-9)
    f = DISC_SET + DISC_SPAN * (q ** (2.0 / 3.0) - low ** (2.0 / 3.0)) / span
    lev = 1.0 + float(s) * PAD_SHARE * _disc_force(np.maximum(f, 0.0), DISC_HEIGHT)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``fluidic_diode``'s drag at the top speed forwards, x the friction level, at strength 1
#: [-]; the laminar resistance's share of the forward drag at the top speed [-]; the
#: diodicity the conduit reaches at high Reynolds numbers [-]; the speed it reaches half of
#: its excess at, x the top speed [-]
DIODE_DRAG, DIODE_LAMINAR, DIODE_MAX, DIODE_ONSET = 0.5, 0.3, 3.0, 0.3


def _diode_drag(u, laminar, di_max, onset):
    """The fluidic diode's pressure drop [-] (1 forwards at u = 1) at the flows ``u`` [-]
    (over the top speed's): a laminar part ``laminar`` u, even, and an inertial part
    (1 - ``laminar``) K u |u|, K = 1 forwards (u > 0) and, backwards, 1 + (``di_max`` - 1)
    |u| / (|u| + ``onset``): the diodicity grows with the Reynolds number from 1."""
    u = np.asarray(u, float)
    au = np.abs(u)
    k = np.where(u < 0.0, 1.0 + (di_max - 1.0) * au / (au + onset), 1.0)
    return laminar * u + (1.0 - laminar) * k * u * au


@on_fine_grid
def fluidic_diode_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A damper on the carriage (a dashpot, a cylinder's bypass) passes its oil through a
    valvular conduit, Tesla's fluidic diode: loops that return part of the flow against
    itself in one direction and let it by in the other, with no moving part. At low flow
    (small Reynolds numbers) the flow is laminar and the resistance the same both ways;
    at speed the flow's inertia separates the jets and the backward flow loses several
    times the forward pressure (the diodicity, growing with the Reynolds number to
    :data:`DIODE_MAX`; :func:`_diode_drag`). The truth adds ``s`` :data:`DIODE_DRAG` x the
    friction level x that drop (1 forwards at the top speed) to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the damper's piston area squared times the conduit's
        resistance, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Tesla 1920, Valvular conduit, US patent 1,329,559; the diodicity of Tesla valves and
    its growth with the Reynolds number (Forster, Bardell, Afromowitz, Sharma and Blanchard
    1995, Design, fabrication and testing of fixed-valve micro-pumps, ASME FED 234; Bardell
    2000, The diodicity mechanism of Tesla-type no-moving-parts valves, PhD thesis, Univ.
    Washington; Nguyen, Lin, Sen and Liu 2021, J. Fluid Mech. 915 on the onset of
    diodicity). The candidate frees the levels (and the Stribeck velocity and viscous
    term) of each direction and an offset; the open forms twin levels, curves or viscous
    terms, roll lips, load thrust bearings, pump films, ratchet, spring back, tilt pads,
    strut, throttle with a check valve, differ in areas, pump along grooves, buckle,
    scrape chips, commutate, tension idlers, free-wheel, wick felts, run belts, lean
    brushes, pull sealing bands, hold by a counterbalance valve or vibrate the way. Here
    the asymmetry is the flow's inertia in a fixed geometry: none at low speed, growing
    with the speed.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    d = _diode_drag(np.asarray(kin.v, float) / v99, DIODE_LAMINAR, DIODE_MAX, DIODE_ONSET)
    return F + float(s) * DIODE_DRAG * _level(kin) * d


# -- stribeck_shape --------------------------------------------------------------------------
#: ``sommerfeld_journal``'s journal friction at rest, x the friction level, at strength 1
#: [-]; the speed (x the top speed) at which the journals' friction is least [-]; the speed
#: the friction turns over at rest, x the top speed [-]
JOURNAL_DRAG, JOURNAL_LEAST, JOURNAL_ROUND = 0.5, 0.25, 2e-3


def _journal_eccentricity(load_number):
    """The journal's eccentricity ratio [-] at the load numbers ``load_number`` [-] (W c^2
    / (eta U r^2 L) up to a constant): the inverse of the full Sommerfeld solution's
    6 e / ((2 + e^2) sqrt(1 - e^2)), increasing in e on (0, 1)."""
    e = np.concatenate((np.linspace(1e-6, 0.99, 2000), 1.0 - np.logspace(-2.0001, -12, 400)))
    w = 6.0 * e / ((2.0 + e * e) * np.sqrt(1.0 - e * e))
    return np.interp(np.asarray(load_number, float), w, e)


def _journal_friction(u, least):
    """The journal's friction coefficient over its boundary value c / r [-] at the speeds
    ``u`` [-] (over the top speed), full Sommerfeld: (1 + 2 e^2) / (3 e), e the
    eccentricity at the load number 2.4 ``least`` / |u| (so the least friction, at e =
    1 / sqrt(2), lies at |u| = ``least``); 1 at rest, Petroff's |u| / (2.4 ``least``) at
    speed."""
    au = np.maximum(np.abs(np.asarray(u, float)), 1e-12)
    e = _journal_eccentricity(2.4 * least / au)
    return (1.0 + 2.0 * e * e) / (3.0 * e)


@on_fine_grid
def sommerfeld_journal_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage runs on track rollers (cam followers) whose plain journal bearings
    turn with the carriage's speed under a fixed load. A hydrodynamic journal's
    eccentricity follows the Sommerfeld number (~ speed / load): at rest the shaft sits on
    the bearing (e -> 1) and the friction coefficient is c / r, as the speed grows the
    shaft lifts towards the centre and the friction (1 + 2 e^2) / (3 e) x c / r (the full
    Sommerfeld solution) dips to its least at e = 1 / sqrt(2) (at :data:`JOURNAL_LEAST` x
    the top speed), then rises as Petroff's viscous drag (:func:`_journal_friction`). The
    truth adds ``s`` :data:`JOURNAL_DRAG` x the friction level x that friction over its
    boundary value, along the velocity (rounded over :data:`JOURNAL_ROUND` x the top
    speed), to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (with a Stribeck curve).
    s : float
        Amplitude factor [-]: the rollers' load times their journals' clearance ratio, /
        its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The full Sommerfeld solution of the long journal bearing (Sommerfeld 1904, Zur
    hydrodynamischen Theorie der Schmiermittelreibung, Z. Math. Phys. 50; Hamrock, Schmid
    and Jacobson 2004, Fundamentals of Fluid Film Lubrication, ch. 10; Petroff 1883) and
    the friction of track rollers on plain bearings. The candidate reshapes the Stribeck
    curve; the open forms add a tail, a rational drop, a hydrodynamic rise, a spike, a
    lift-off, two roughness scales, a logarithmic or Eyring law, starve a film, add rubber
    hysteresis, resonate, dither, melt, flow grains, readsorb, heat the film, make it
    turbulent, thixotropic, churned or shear-thinning, add core losses, breathe a bellows,
    brake by eddy currents, fly a pad or wipe a meniscus. Here the journal's eccentricity:
    a shallow dip below the boundary value and a linear rise, from one formula.
    """
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (sommerfeld_journal): the mre_lugre base has no "
                         "Stribeck curve")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    u = np.asarray(kin.v, float) / v99
    d = _journal_friction(u, JOURNAL_LEAST) * np.tanh(u / JOURNAL_ROUND)
    return F + float(s) * JOURNAL_DRAG * _level(kin) * d


# -- position --------------------------------------------------------------------------------
#: ``drawer_overhang``'s friction at mid-stroke, x the friction level, at strength 1 [-];
#: the ram's overhang at the visited stroke's two ends, x its length [-]; the speed the
#: friction turns over, x the top speed [-]
DRAWER_DRAG, DRAWER_IN, DRAWER_OUT, DRAWER_ROUND = 0.4, 0.1, 0.7, 2e-3


def _drawer_reactions(overhang):
    """The sum of a ram's two bearing reactions over its nose load [-] at the overhangs
    ``overhang`` [-] (over the ram's length): the sleeve's mouth carries W / (1 - e), the
    ram's tail bushing, inside the sleeve, W e / (1 - e) (moments about each): (1 + e) /
    (1 - e)."""
    e = np.asarray(overhang, float)
    return (1.0 + e) / (1.0 - e)


@on_fine_grid
def drawer_overhang_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The moving part is a ram (a quill, a drawer, a telescopic arm) that runs out of a
    fixed sleeve and carries a weight at its nose: the sleeve's mouth and the ram's tail
    bushing, inside the sleeve, bear it. As the ram runs out its overhang e grows and its
    engagement 1 - e (both over the ram's length) shrinks, and the reactions, whose sum is
    W (1 + e) / (1 - e) (:func:`_drawer_reactions`), grow hyperbolically: the drawer
    effect. The visited stroke runs from the overhang :data:`DRAWER_IN` to
    :data:`DRAWER_OUT`. The truth adds ``s`` :data:`DRAWER_DRAG` x the friction level x
    the reactions over their value at mid-stroke, against the velocity, to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the bearings' friction coefficient times the nose weight,
        / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The drawer effect and the length-to-width rule of sliding bearings (Slocum 1992,
    Precision Machine Design, ch. 8 on sliding-contact bearings and the 'golden rule';
    Moore 1970, Foundations of Mechanical Accuracy; quills and rams of boring mills). The
    candidate scales the friction along the stroke and adds a force of the position; the
    open forms put a defect, a waviness, a worn section, runout, a bent rail, a transfer
    film, cogging, a taper, a pocket, a cushion, a cover, an air spring, bolt holes, a
    plunger, a sag, a festoon, a curve, a chain, a cam, a heated zone, brinelled dents, a
    rail joint, misaligned rails, a spool's flow force or a crank on the stroke. Here the
    bearing's span itself shrinks along the stroke: a friction rising hyperbolically
    towards one end.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (drawer_overhang): the held-out part of the "
                         f"{kin.plant} record never revisits the positions of its fit part")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    span = max(sc["x_hi"] - sc["x_lo"], 1e-12)
    e = DRAWER_IN + (DRAWER_OUT - DRAWER_IN) * (np.asarray(kin.x, float) - sc["x_lo"]) / span
    e = np.clip(e, 0.0, 0.95)
    mid = float(_drawer_reactions(0.5 * (DRAWER_IN + DRAWER_OUT)))
    v99 = max(sc["v99"], 1e-12)
    turn = np.tanh(np.asarray(kin.v, float) / (DRAWER_ROUND * v99))
    return F + float(s) * DRAWER_DRAG * _level(kin) * _drawer_reactions(e) / mid * turn


# -- inertia ---------------------------------------------------------------------------------
#: ``rocking_block``'s mass at strength 1, x the friction level / a99 [kg per N s^2/m]; the
#: acceleration it tips at, g x its width over its height, x the top acceleration [-]; the
#: period of its frequency parameter 2 pi / p (p^2 = 3 g / (4 R)), x the motion's time
#: scale [-]; the angle a retaining fence stops it at, x its slenderness angle [-]
ROCK_MASS, ROCK_TIP, ROCK_PERIOD, ROCK_FENCE = 0.4, 0.5, 0.5, 0.5


@njit(cache=True)
def _rocking_force(a, h, R, alpha, g, fence):
    """The horizontal force [N per kg] a rigid rectangular block (half-diagonal ``R`` [m],
    slenderness ``alpha`` [rad], tan(alpha) its width over its height) standing free on
    the carriage exerts under its accelerations ``a`` [m/s^2] (steps ``h`` [s]):
    a + the acceleration of its centre relative to the carriage. It stands while |a| <= g
    tan(alpha); beyond, it rocks on an edge (Housner): theta'' = -(3 / (4 R)) (a cos(alpha
    - |theta|) sign(theta) + g sin(alpha - |theta|)) sign(theta); landing (theta through
    0) it keeps 1 - 1.5 sin^2(alpha) of its angular velocity (and comes to rest if that is
    less than gravity takes in ten sub-steps); a fence stops it
    (inelastically) at ``fence`` [rad]. Semi-implicit Euler on sub-steps of at most
    0.02 / p (p^2 = 3 g / (4 R)), the acceleration interpolated, from rest."""
    n = a.size
    out = np.empty(n)
    c = 0.75 / R
    p = math.sqrt(c * g)
    m = max(1, int(math.ceil(p * h / 0.02)))
    hs = h / m
    r = 1.0 - 1.5 * math.sin(alpha) ** 2
    tip = g * math.tan(alpha)
    # the angular velocity gravity takes from it in ten sub-steps: slower after a landing,
    # the block's ever shorter rocks (Housner's, in finite time) end at once
    settle = 10.0 * hs * c * g * math.sin(alpha)
    th = 0.0
    thd = 0.0
    out[0] = a[0]
    for k in range(1, n):
        thdd = 0.0
        ak = a[k]
        for i in range(m):
            ak = a[k - 1] + (a[k] - a[k - 1]) * (i + 1.0) / m
            if th == 0.0 and thd == 0.0:
                if ak < -tip:
                    side = 1.0
                elif ak > tip:
                    side = -1.0
                else:
                    thdd = 0.0
                    continue
            elif th > 0.0 or (th == 0.0 and thd > 0.0):
                side = 1.0
            else:
                side = -1.0
            at = abs(th)
            thdd = -c * (side * ak * math.cos(alpha - at) + g * math.sin(alpha - at)) * side
            thd += hs * thdd
            new = th + hs * thd
            if side * new < 0.0:                      # lands: an impact on the other edge
                new = 0.0
                thd *= r
                if abs(thd) < settle:                 # too slow to lift it again
                    thd = 0.0
            if abs(new) > fence:                      # the fence holds it
                new = math.copysign(fence, new)
                thd = 0.0
                thdd = 0.0
            th = new
        if th == 0.0 and thd == 0.0:
            out[k] = ak
        else:
            side = 1.0 if (th > 0.0 or (th == 0.0 and thd > 0.0)) else -1.0
            at = abs(th)
            xdd = R * math.cos(alpha - at) * thdd + side * R * math.sin(alpha - at) * thd * thd
            out[k] = ak + xdd
    return out


@on_fine_grid
def rocking_block_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A rigid block (a casting, a cabinet) stands free on the carriage, and the inverse
    dynamics misses it. While the carriage's acceleration stays below g tan(alpha) (its
    width over its height; :data:`ROCK_TIP` x the top acceleration) it stands and moves
    with the carriage: its whole mass. Beyond, it tips onto an edge and rocks (Housner's
    rocking block, its frequency parameter p = sqrt(3 g / (4 R)) of period
    :data:`ROCK_PERIOD` x the motion's time scale): the carriage then carries the force
    that accelerates its centre, less than its mass times a, and when it lands again it
    loses part of its rocking (the impact's restitution 1 - 1.5 sin^2(alpha)); a fence
    stops it before it topples (:data:`ROCK_FENCE` x alpha). The truth adds ``s``
    :data:`ROCK_MASS` x the friction level / a99 x that force per unit mass
    (:func:`_rocking_force`) to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the block's mass, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The rocking of free-standing rigid blocks (Housner 1963, The behavior of inverted
    pendulum structures during earthquakes, Bull. Seismol. Soc. Am. 53; Yim, Chopra and
    Penzien 1980, Rocking response of rigid blocks to earthquakes, Earthquake Eng. Struct.
    Dyn. 8; Makris and Roussos 2000, Rocking response of rigid blocks under near-source
    ground motions, Geotechnique 50). The candidate misses a constant mass; the open forms
    filter it, reflect it through gearing, a chain's polygon or a pinion, hang it on a
    spring, a cable, a fluid, a clutch, a coupling, a flyweight, a screw, a friction-damped
    mount or a surging spring, add a fluid's mass and its history, pick it up, drop it,
    empty it, slide it, rattle it, telescope it, roll it in a cradle, recoil the frame,
    saturate the motor, lead it by the feedforward or pitch the scale head. Here the
    missed mass tips on its edge: whole while it stands, less while it rocks, set by its
    geometry and gravity.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    p = 2.0 * math.pi / (ROCK_PERIOD * max(_motion_time(kin), 1e-12))
    R = 0.75 * GRAVITY / (p * p)
    alpha = math.atan(ROCK_TIP * a99 / GRAVITY)
    f = _rocking_force(np.ascontiguousarray(kin.a, dtype=float), float(kin.dt), R, alpha,
                       GRAVITY, ROCK_FENCE * alpha)
    return F + float(s) * ROCK_MASS * _level(kin) / a99 * f


# -- delay -----------------------------------------------------------------------------------
#: ``swept_grating``'s sweep period at strength 1 [data samples]; the share of the sweep the
#: record's force range spans, and where in the sweep its least force lies [-]
SWEEP_SAMPLES, SWEEP_SPAN, SWEEP_START = 3.0, 0.8, 0.1


@njit(cache=True)
def _sweep_readings(t, F, q, period):
    """The interrogator's readings [N] along the times ``t`` [s] of the forces ``F`` [N]:
    the sweeps of ``period`` [s] from t[0] reach the grating's wavelength when their
    phase passes ``q`` [-] (the grating's place in the sweep, 0 to 1, at each time); the
    force then read is held from the sweep's end to the next sweep's end (before the first
    reading: the first force)."""
    n = t.size
    out = np.empty(n)
    held = F[0]
    pending = F[0]
    found = False
    k_now = 0
    for i in range(n):
        ph = (t[i] - t[0]) / period
        k = int(math.floor(ph))
        if k > k_now:
            held = pending if found else F[i - 1]
            found = False
            k_now = k
        if not found and ph - k >= q[i]:
            pending = F[i]
            found = True
        out[i] = held
    return out


@on_fine_grid
def swept_grating_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is read by a fibre Bragg grating on the force member, interrogated by a
    wavelength-swept laser: the grating's Bragg wavelength moves with the strain, so with
    the force (the record's force range spans :data:`SWEEP_SPAN` of the sweep from
    :data:`SWEEP_START`), and each sweep (``s`` :data:`SWEEP_SAMPLES` data samples long)
    finds the reflection peak at the instant its wavelength meets the grating's: the
    force is sampled at an instant within the sweep that the force itself sets. The
    interrogator reports that reading at the sweep's end, held until the next one
    (:func:`_sweep_readings`): a delay of one sweep or more, jittered by the force's
    place in the sweep. The motion channels are on time.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the sweep period, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Fibre Bragg grating sensors (Kersey, Davis, Patrick, LeBlanc, Koo, Askins, Putnam and
    Friebele 1997, Fiber grating sensors, J. Lightwave Technol. 15) read by swept lasers
    (Yun, Richardson and Kim 1998, Interrogation of fiber grating sensor arrays with a
    wavelength-swept fiber laser, Opt. Lett. 23). The candidate shifts the force by a
    constant time, low-passes it, reads it through a transducer's resonance and leaks it;
    the open forms sample, filter, average, hold, skew, jitter, rate-limit, transmit,
    median, report by deadband, trigger on positions, run a belt, aerate, drop telegrams,
    leak, creep, notch, track, snub, time a waveguide's pulse, diffuse eddy currents or
    count a resonator's frequency over a gate. Here the sampling instant is set by the
    measured force itself, within each sweep, then held.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.ascontiguousarray(kin.t, dtype=float)
    lo, hi = float(np.min(F)), float(np.max(F))
    q = SWEEP_START + SWEEP_SPAN * (F - lo) / max(hi - lo, 1e-12)
    period = float(s) * SWEEP_SAMPLES * kin.sample_dt
    return _sweep_readings(t, np.ascontiguousarray(F, dtype=float),
                           np.ascontiguousarray(q, dtype=float), period)


# -- drift -----------------------------------------------------------------------------------
#: ``oil_evaporation``'s rise of the levels at the record's end, at strength 1 [-]; the film
#: parameter (film over roughness) at the start [-]; the heavy fraction's share of the film
#: [-]; the volatile fraction's evaporation time, x the record's length [-]
EVAP_RISE, EVAP_LAMBDA, EVAP_HEAVY, EVAP_TIME = 0.5, 3.0, 0.25, 0.5


def _asperity_share(lam):
    """The asperities' share of the load [-] at the film parameters ``lam`` [-] (film
    thickness over the composite roughness): the Gaussian tail of the summit heights above
    the film, erfc(lam / sqrt 2) / 2."""
    return 0.5 * erfc(np.asarray(lam, float) / math.sqrt(2.0))


def _film(tau, heavy, time):
    """The film's thickness over its initial one [-] at the times ``tau`` [-] (over the
    record's length): the volatile fraction 1 - ``heavy`` evaporates as exp(-tau /
    ``time``) (a first-order loss at the oil's vapour pressure), the heavy fraction
    stays."""
    return heavy + (1.0 - heavy) * np.exp(-np.asarray(tau, float) / time)


@on_fine_grid
def oil_evaporation_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The way's lubricant is a blend whose volatile fraction evaporates from the thin film
    (an oil's Noack volatility, a solvent-thinned lubricant drying): the film thins as
    heavy + (1 - heavy) exp(-t / tau) (:func:`_film`; :data:`EVAP_HEAVY` of it stays,
    tau :data:`EVAP_TIME` x the record's length), and the film parameter falls from
    :data:`EVAP_LAMBDA`: the asperities, whose summits above the film follow a Gaussian
    tail (:func:`_asperity_share`), take a share of the load that grows slowly at first,
    faster as the film nears the roughness. The Coulomb and Stribeck levels are the base's
    times 1 + ``s`` :data:`EVAP_RISE` x that share's rise over its rise by the record's
    end, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the asperities' friction over the film's, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Evaporation losses of lubricants (Noack 1936; ASTM D5800 / CEC L-40, the Noack
    volatility) and mixed lubrication's load sharing by the film parameter (Patir and Cheng
    1978; Johnson, Greenwood and Poon 1972, A simple theory of asperity contact in
    elastohydrodynamic lubrication, Wear 19; Greenwood and Williamson 1966). The
    candidate is a trend, a saturating change, a step, a cycle, a resetting change or the
    friction power's heat; the open forms warm up, wear in, change the lubricant, heat,
    wear, follow the humidity, grind a third body, relubricate, relax a seal, oxidise,
    deplete, wear through, swell, build a tribofilm, take in particles, expand, shear down,
    heat magnets, charge, creep a cage, loosen a screw, dewet a film, channel grease, drain
    a receiver or grow a spall. Here the film evaporates in time: a change with a delayed
    onset that steepens as the film nears the roughness.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    tau = (t - t[0]) / max(t[-1] - t[0], 1e-12)
    share = _asperity_share(EVAP_LAMBDA * _film(tau, EVAP_HEAVY, EVAP_TIME))
    s0 = float(_asperity_share(EVAP_LAMBDA))
    s1 = float(_asperity_share(EVAP_LAMBDA * _film(1.0, EVAP_HEAVY, EVAP_TIME)))
    lev = 1.0 + float(s) * EVAP_RISE * (share - s0) / (s1 - s0)
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: ``toggle_spring``'s clearance at strength 1, as a share of the stroke (its full width,
#: both sides) [-]; the toggle's push at the flank, x the Coulomb level [-]; its pivot's
#: offset from the line of the play and its free length's reach along it, x the play's
#: half-width [-] (the reach such that its push grows all the way to the flank)
TOGGLE_CLEAR, TOGGLE_PUSH, TOGGLE_OFFSET, TOGGLE_REACH = 0.008, 0.3, 1.0, 2.8


@njit(cache=True)
def _toggle_push(e, half, push, offset, reach):
    """The over-centre spring's push [N] on the contact at the offset ``e`` [m] (drive
    minus contact, clipped to the play's half-width ``half`` [m]): a spring of free length
    L0 = sqrt(d^2 + (``reach`` half)^2) pivoted at d = ``offset`` half from the line of the
    play, compressed to sqrt(d^2 + e^2): its force along the play ~ e (L0 / sqrt(d^2 +
    e^2) - 1), pushing the contact away from the centre, ``push`` [N] at the flank."""
    d = offset * half
    L0 = math.sqrt(d * d + (reach * half) ** 2)
    ec = min(max(e, -half), half)
    at = half * (L0 / math.sqrt(d * d + half * half) - 1.0)
    return -push * ec * (L0 / math.sqrt(d * d + ec * ec) - 1.0) / at


@njit(cache=True)
def _toggle_contact(h, xd, half, push, offset, reach, m, kh, ch, s0, s1, s2, Fc, Fs, vs,
                    alpha, shape):
    """LuGre friction [N] of a light contact of mass ``m`` [kg] driven by the drive
    positions ``xd`` [m] (steps ``h`` [s]) across a play of half-width ``half`` [m]
    bridged by an over-centre spring (:func:`_toggle_push`); past the play the flank, a
    spring ``kh`` [N/m] and damper ``ch`` [N s/m], compressive only."""
    n = xd.size
    F = np.empty(n)
    x = xd[0] - half
    v = 0.0
    z = 0.0
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        e = xd[j] - x
        ed = vd - v
        fc = _toggle_push(e, half, push, offset, reach)
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
def toggle_spring_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact are joined across a play (radius ``s``^2 :data:`TOGGLE_CLEAR` / 2 x
    the stroke) by an over-centre (toggle) spring, as in snap-action switches and toggle
    clamps: a compressed spring pivoted off the line of the play (:func:`_toggle_push`),
    whose push along the play is zero at the centre and grows towards either flank
    (:data:`TOGGLE_PUSH` x the Coulomb level there): a negative stiffness that holds the
    contact against the flank it last touched. After a reversal the drive leaves that
    flank, the toggle keeps pushing the contact back towards it, less and less, turns
    over at the centre and pushes it towards the coming flank, which then takes it up.
    The contact is light (its inertial force at the top acceleration 1 % of the Coulomb
    level) with the base's LuGre friction (:func:`_toggle_contact`).

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
    Bistable (over-centre) mechanisms and their negative stiffness (Howell 2001, Compliant
    Mechanisms, ch. on bistable mechanisms; Jensen and Howell 2004, Bistable configurations
    of compliant mechanisms modeled using four links and translational joints, J. Mech.
    Des. 126; snap-action switches). The candidate holds or frees the contact across a
    rigid play; the open forms take it up rigidly, compliantly, by impact, against a
    spring, eccentrically, through oil, worn, with a dragging idler, biased, slack,
    magnetic, preloaded, through a flexspline, a rope, a spider, a fluid link, a cable, a
    clutch, a varying mesh, a polymer gear, grease, a wedge, an overlapped spool or a side
    loaded pin. Here the play is bridged by a negative stiffness: the force in the play
    turns over at its centre.
    """
    p = _lugre_params(kin, "backlash (toggle_spring)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    half = 0.5 * float(s) ** 2 * TOGGLE_CLEAR * float(np.ptp(kin.x))
    push = TOGGLE_PUSH * float(p.Fc)
    m, kh, ch = _contact_constants(kin, p)
    k_toggle = 4.0 * push / max(half, 1e-15)
    rate = max(math.sqrt(max(kh, k_toggle) / m), (float(p.sigma1) + float(p.sigma2) + ch) / m)
    h, xd, n_sub = _substeps(kin, rate)
    Fr = _toggle_contact(h, xd, half, push, TOGGLE_OFFSET, TOGGLE_REACH, m, kh, ch,
                         float(p.sigma0), float(p.sigma1), float(p.sigma2), float(p.Fc),
                         float(p.Fs), float(p.vs), float(p.alpha), SHAPES[p.shape])
    return Fr[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: the flexure's elastic path to the slip at strength 1, beyond the base bristle's path, as
#: a share of the stroke / 3 [-]; its share of the friction at strength 1 [-]; its forward
#: and reverse transformation stresses and their hardening, x the slip stress [-]; its
#: transformation path, x its elastic path [-]
SE_PATH, SE_SHARE, SE_FORWARD, SE_REVERSE, SE_HARDEN, SE_STRAIN = 0.1, 0.6, 0.5, 0.2, 0.1, 1.0


@njit(cache=True)
def _flag(x, path, fwd, rev, hard, strain):
    """The superelastic flexure's stress u [-] (1 at the contact's slip) along the
    positions ``x`` [m]: its deflection D = ``path`` u + ``strain`` ``path`` xi (elastic
    path ``path`` [m] to u = 1, martensite fraction xi, -1 to 1); forward transformation
    while |u| = ``fwd`` + ``hard`` |xi| and loading, reverse while |u| = ``rev`` + ``hard``
    |xi| and unloading, elastic between; past |u| = 1 the contact slips (D follows).
    Starts unstressed, austenite."""
    n = x.size
    out = np.zeros(n)
    eps = strain * path
    D = 0.0
    xi = 0.0
    for j in range(1, n):
        D += x[j] - x[j - 1]
        u = (D - eps * xi) / path
        if xi != 0.0:                                 # reverse transformation
            sg = 1.0 if xi > 0.0 else -1.0
            if u * sg < rev + hard * abs(xi):
                a = (D * sg - path * rev) / (path * hard + eps)
                if a <= 0.0:
                    xi = 0.0
                    u = D / path
                else:
                    xi = sg * a
                    u = sg * (rev + hard * a)
        if u != 0.0:                                  # forward transformation
            sg = 1.0 if u > 0.0 else -1.0
            if (xi == 0.0 or xi * sg > 0.0) and abs(xi) < 1.0 \
                    and u * sg > fwd + hard * abs(xi):
                a = (D * sg - path * fwd) / (path * hard + eps)
                if a >= 1.0:
                    xi = sg
                    u = (D - eps * xi) / path
                else:
                    xi = sg * a
                    u = sg * (fwd + hard * a)
        if abs(u) > 1.0:                              # the contact slips
            u = 1.0 if u > 0.0 else -1.0
            D = path * u + eps * xi
        out[j] = u
    return out


@on_fine_grid
def superelastic_flexure_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Part of the contact is carried through a superelastic (NiTi) flexure in series with
    it (a shape-memory alloy flexure, a pseudoelastic wire): elastic up to the forward
    transformation stress (:data:`SE_FORWARD` of the slip stress), then a stress-induced
    martensitic transformation on a plateau (hardening :data:`SE_HARDEN`; its path
    :data:`SE_STRAIN` x the elastic path), elastic again up to the slip; unloading, elastic
    down to the lower reverse plateau (:data:`SE_REVERSE`), on which the martensite
    reverts, then elastic through zero with no residual strain, and likewise the other way
    (:func:`_flag`; its elastic path the base bristle's Fs / sigma0 plus ``s``
    :data:`SE_PATH` x the stroke / 3): a flag-shaped loop, not a Masing one. Its share w
    = ``s`` :data:`SE_SHARE` (up to ``s`` = 1) of the friction is its stress times the
    Stribeck level, the viscous term the base's: F = (1 - w) F_lugre + w (g(v) u + sigma2
    v). At ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the flexure's share (up to ``s`` = 1) and its elastic path (as
        the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Superelasticity of shape-memory alloys and its one-dimensional models (Auricchio and
    Taylor 1997, Shape-memory alloys: modelling and numerical simulations of the finite-
    strain superelastic behavior, Comput. Methods Appl. Mech. Eng. 143; Brinson 1993, J.
    Intell. Mater. Syst. Struct. 4; Dolce, Cardone and Marnetto 2000, Implementation and
    testing of passive control devices based on shape memory alloys, Earthquake Eng.
    Struct. Dyn. 29). The candidate's presliding is a generalized Maxwell-slip (GMS)
    element set; the open forms are Maxwell-slip sets, Dahl, elasto-plastic,
    Bliman-Sorine, Bouc-Wen, Zener junctions, Mindlin contacts, rate-and-state, Tomlinson
    asperities, bond rupture, gouge, kinematic hardening, interlocking, capillary bridges,
    cyclic hardening, peeling, unloading microslip, a power-law joint, junction growth,
    avalanches, slip weakening, a microslip bar, contact renewal and a grease's yield.
    Here the presliding is a phase change's: two plateaus, and back to zero without a
    residual deflection.
    """
    p = _lugre_params(kin, "gms (superelastic_flexure)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, SE_PATH)
    w = SE_SHARE * min(float(s), 1.0)
    v = np.ascontiguousarray(kin.v, dtype=float)
    u = _flag(np.ascontiguousarray(kin.x, dtype=float), e0 + extra, SE_FORWARD, SE_REVERSE,
              SE_HARDEN, SE_STRAIN)
    return (1.0 - w) * F + w * (kin.base.g(v) * u + float(p.sigma2) * v)
