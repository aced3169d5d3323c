"""The thirtieth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-12-01 (session 34) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 35 (2026-12-01) on the code of fe2a59f:
176 cases, 0 skipped, 420 s wall on 2 workers. Top-1 59.7 % (105;
60.8 % of the 171 detectable; the 5 undetectable are all stribeck_shape cases (4 of them
named none, 1 stribeck_shape)); mean |shrink error| 0.255 (0.183 over the right ones);
wrong names on 27 (15.3 %): acceleration -> asymmetry 5, gms -> delay 5, load -> drift 4,
gms -> position 3, acceleration -> drift 3, inertia -> acceleration 2, backlash -> gms 1,
delay -> stribeck_shape 1, acceleration -> load 1, asymmetry -> stribeck_shape 1,
drift -> position 1. By form: asymmetry/charging_generator 19/20 (stribeck_shape 1),
drift/carbon_tribolayer 19/20 (position 1), position/lead_preload 15/16 (unexplained 1),
load/crowned_rollers 16/20 (drift 4), inertia/liquid_column 15/20 (acceleration 2, none 2,
unexplained 1), delay/polynomial_smoother 12/20 (unexplained 7, stribeck_shape 1),
gms/fibre_wiper 4/12 (delay 5, position 3), backlash/magnet_latch 2/12 (unexplained 9,
gms 1), stribeck_shape/peel_adhesion 2/16 (none 10, unexplained 4),
acceleration/inertia_lubricator 1/20 (unexplained 9, asymmetry 5, drift 3, load 1, none 1).
By plant: forging press 71.4 %, isolator 71.4 %, valve 55.0 %, damping rig 55.0 %,
XML-350 52.5 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen29` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen29`,
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
acceleration       ``inertia_lubricator``: the ways are oiled by an inertia pump on the
                   carriage (a check-valved plunger thrown by the carriage's
                   acceleration beyond its spring's preload); the oil it delivers builds
                   a film that the contact consumes over a time: levels that fall after
                   hard accelerations and recover in gentle motion and dwells
load               ``crowned_rollers``: the guide's rollers are crowned; as the load
                   grows their contact lengthens until it spans the whole roller, and
                   beyond that load the pressure piles up at the roller's ends (edge
                   loading): the levels rise steeply with the load past a knee
asymmetry          ``charging_generator``: the carriage drives a linear generator that
                   charges a battery through a single diode: it conducts, and brakes the
                   carriage, only one way and only once its EMF exceeds the battery's
                   voltage and the diode's drop
stribeck_shape     ``peel_adhesion``: part of the contact is a soft polymer whose
                   adhesion is torn at the trailing edge of each junction; the tearing
                   energy of a viscoelastic crack grows with its speed as a power law and
                   saturates (Maugis and Barquins): an adhesive friction that rises and
                   levels off with the speed
position           ``lead_preload``: the axis is a ball screw with a double nut preloaded
                   by a spacer; the screw's lead deviates along the stroke, so the
                   difference of the deviation over the spacer's length changes the
                   preload, and the friction with it, at each position
inertia            ``liquid_column``: the carriage carries a U-tube of liquid (a tuned
                   liquid column damper, a coolant loop): the liquid moves with the
                   carriage and its column swings in the tube, against gravity and an
                   orifice's quadratic loss, pushing on the carriage with its own
                   acceleration
delay              ``polynomial_smoother``: the force is smoothed by a real-time
                   least-squares polynomial fit over a trailing window, read at its
                   newest point: a lag that is small on straight stretches and errs at
                   the force's bends, overshooting after them
drift              ``carbon_tribolayer``: the contact's coating is a hydrogenated
                   diamond-like carbon; after an incubating sliding distance a graphitic
                   tribolayer forms and spreads, and the friction falls to its level,
                   following the distance slid, not the time
backlash           ``magnet_latch``: drive and contact are joined across the play with
                   small permanent magnets on both flanks: across the play the contact is
                   drawn towards the nearer flank by an attraction of the inverse square
                   of the gap, which swells as the flank approaches
gms                ``fibre_wiper``: part of the friction is carried by a fibrous felt
                   wiper beside the contact; its fibres' mutual slipping gives a
                   hyperbolic force of the presliding displacement, reversed along
                   Masing's rule (the branch twice the size of the virgin curve); at
                   ``s`` = 0 the base
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``peel_adhesion``
needs a Stribeck curve (not the isolator's mre_lugre), ``lead_preload`` a record that
revisits its positions (not the press), ``crowned_rollers`` a load that changes,
``magnet_latch`` and ``fibre_wiper`` a classic LuGre base (valve, damping rig,
XML-350); each raises a ``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.shapes import SHAPES

from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _level,
                     _light_contact_step, _lugre_params, _motion_time, _presliding_path,
                     _substeps, has_stribeck_curve, level_inside, lugre_with_curve,
                     on_fine_grid)

__all__ = ["FORMS", "inertia_lubricator_truth", "crowned_rollers_truth",
           "charging_generator_truth", "peel_adhesion_truth", "lead_preload_truth",
           "liquid_column_truth", "polynomial_smoother_truth", "carbon_tribolayer_truth",
           "magnet_latch_truth", "fibre_wiper_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "inertia_lubricator", "load": "crowned_rollers",
         "asymmetry": "charging_generator", "stribeck_shape": "peel_adhesion",
         "position": "lead_preload", "inertia": "liquid_column",
         "delay": "polynomial_smoother", "drift": "carbon_tribolayer",
         "backlash": "magnet_latch", "gms": "fibre_wiper"}


# -- acceleration ----------------------------------------------------------------------------
#: ``inertia_lubricator``'s fall of the levels per unit of the oil film over its 99th
#: percentile along the record, at strength 1 [-]; the plunger spring's preload, x the top
#: acceleration [-]; the film's consumption time, x the motion's time scale [-]
LUB_DROP, LUB_CRACK, LUB_TIME = 0.4, 0.4, 3.0


@njit(cache=True)
def _oil_film(t, q, tau):
    """The oil film [-] an inertia pump builds at the deliveries ``q`` [-] (per time
    ``tau``) along the times ``t`` [s] (uniform), from none: tau dh/dt = q (1 - h) - h (the
    pump fills what is not yet wetted, the contact consumes the film over ``tau`` [s]),
    each step exact for the delivery held at its mean."""
    n = t.size
    out = np.empty(n)
    h = 0.0
    for k in range(n):
        out[k] = h
        if k + 1 < n:
            qm = 0.5 * (q[k] + q[k + 1])
            rate = (1.0 + qm) / tau
            target = qm / (1.0 + qm)
            h = target + (h - target) * math.exp(-rate * (t[k + 1] - t[k]))
    return out


def _pump_delivery(a, crack):
    """The inertia pump's delivery [-] at the accelerations ``a`` [-] (over the top
    acceleration): the plunger is thrown either way once |a| exceeds its spring's preload
    ``crack`` [-], and delivers with the excess, (|a| - ``crack``) / (1 - ``crack``)."""
    return np.maximum(np.abs(np.asarray(a, float)) - crack, 0.0) / (1.0 - crack)


@on_fine_grid
def inertia_lubricator_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The ways are oiled by an inertia lubricator on the carriage (as on reciprocating
    slides, shakers and some presses' gibs: a plunger on a spring, with check valves,
    pumps a dose of oil each time the carriage's acceleration throws it beyond the
    spring's preload, :data:`LUB_CRACK` x the top acceleration; :func:`_pump_delivery`).
    The oil it delivers builds a film on the ways, which the contact consumes (squeezes
    out, carries off) over :data:`LUB_TIME` x the motion's time scale
    (:func:`_oil_film`). The Coulomb and Stribeck levels are the base's times 1 - ``s``
    :data:`LUB_DROP` x the film over its 99th percentile along the record, inside the
    bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the film's share in the friction, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Inertia (acceleration-driven) lubricators and plunger pumps on reciprocating parts
    (Bisson and Anderson 1964, Advanced Bearing Technology, NASA SP-38, ch. on lubricant
    supply; Lansdown 1994, Lubrication and Lubricant Selection, ch. on lubricant
    application) and the fall of boundary friction with the lubricant's supply (Bowden and
    Tabor 1950, The Friction and Lubrication of Solids, ch. on boundary lubrication). The
    candidate raises the levels with |a|, lagged, tilts them with a and adds a force odd
    in a; the open forms lag, age, heat, skid, load, press, attract, squeeze, transfer
    weight, slosh, dilate, wedge, spring a gib, soften rubber, swing arms, unload by the
    jerk, tilt pads, push ball trains, ripple the current, slide rack flanks, set a shoe,
    shut a damper's bypass, creep a belt, rack a gantry, tighten a band, surge a feed
    line, load a traction drive, heat a winding or unload a counterweight's rope. Here the
    accelerations beyond a threshold pump oil that the contact then uses up.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    tau = LUB_TIME * max(_motion_time(kin), 1e-12)
    q = _pump_delivery(np.asarray(kin.a, float) / a99, LUB_CRACK)
    h = _oil_film(np.asarray(kin.t, float), q, tau)
    h = h / max(float(np.percentile(h, 99)), 1e-12)
    lev = np.maximum(1.0 - float(s) * LUB_DROP * h, 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- load ------------------------------------------------------------------------------------
#: ``crowned_rollers``' rise of the levels per unit of the edge load, at strength 1 [-]; the
#: load at which the contact spans the roller, as a quantile of the record's |load| [-]
CROWN_RISE, CROWN_KNEE = 0.6, 0.4


def _edge_load(w):
    """The rollers' edge loading [-] at the loads ``w`` [-] (over the load at which the
    contact spans the roller): none below, (w - 1)^1.5 above (the pressure the length can
    no longer spread piles up at the ends, as the truncated Hertz line contact's)."""
    return np.maximum(np.asarray(w, float) - 1.0, 0.0) ** 1.5


@on_fine_grid
def crowned_rollers_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The guide runs on crowned rollers (a roller guide's or a cam follower's, a
    crossed-roller way's). Their contact's length grows with the load until, at the
    record's :data:`CROWN_KNEE` quantile of the load, it spans the whole roller; beyond
    it the roller's ends take the load's rest as edge stresses, whose sliding at the
    roller's ends and the material's hysteresis under them lift the rolling friction
    (:func:`_edge_load`). The Coulomb and Stribeck levels are the base's times 1 + ``s``
    :data:`CROWN_RISE` x that edge loading over its 99th percentile along the record,
    inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], load [N]) and its base law.
    s : float
        Amplitude factor [-]: the edge loading's share in the friction, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Crowned rollers, their contact length and edge loading (Lundberg 1939, Elastische
    Beruehrung zweier Halbraeume, Forschung auf dem Gebiete des Ingenieurwesens 10;
    Johnson 1985, Contact Mechanics, ch. on line contacts of finite length; Harris and
    Kotzalas 2007, Rolling Bearing Analysis, ch. on roller profiles and edge loading).
    The candidate makes the levels affine in the load, with a memory over the travel; the
    open forms scale the friction with a Hertz contact's area, a seal's, a film's, a
    junction's, a pivot's, an adhesive contact's or a pin's arc, break, squeeze or desorb
    films, plough, creep, vibrate, overload or feed a constant flow to a pad, heal
    scuffs, relieve a preload, roll on a lossy track, slip differentially, spin balls,
    press a disc spring, skid lightly loaded rollers, bed a rail, heat a liner by PV,
    shear a soft film under pressure or pass the load through a clamp's seal. Here the
    contact runs out of length: past a knee the load goes to the rollers' ends.
    """
    L = np.abs(np.asarray(kin.load, float))
    Lm = float(np.mean(L)) or 1.0
    if not np.ptp(L) > 1e-9 * Lm:
        raise ValueError(f"load (crowned_rollers): the {kin.plant} record's load does not "
                         f"change")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    knee = max(float(np.quantile(L, CROWN_KNEE)), 1e-12)
    e = _edge_load(L / knee)
    e = e / max(float(np.percentile(e, 99)), 1e-12)
    lev = 1.0 + float(s) * CROWN_RISE * e
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``charging_generator``'s braking force at the top speed, x the friction level, at strength
#: 1 [-]; the speed at which the EMF reaches the battery's voltage and the diode's drop, x
#: the top speed [-]; the diode's rounding of the knee, x the top speed [-]
GEN_FORCE, GEN_KNEE, GEN_ROUND = 0.5, 0.3, 0.02


def _charge_current(u, knee, rnd):
    """The charging current [-] (over its value at the top speed) at the speeds ``u`` [-]
    (over the top speed): the diode conducts one way only, once the EMF ~ u exceeds the
    battery's voltage and its own drop, ~ ``knee``; the current is the excess over the
    circuit's resistance, rounded over ``rnd`` (the diode's exponential knee)."""
    x = np.asarray(u, float) - knee
    return 0.5 * (x + np.sqrt(x * x + rnd * rnd)) / (1.0 - knee)


@on_fine_grid
def charging_generator_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage drives a linear generator (a moving-magnet harvester, a regenerative
    damper) that charges a battery through a single diode, a half-wave rectifier. Its EMF
    is proportional to the speed; the diode conducts only with the EMF of one polarity
    (+x) and only once it exceeds the battery's voltage and the diode's drop, at
    :data:`GEN_KNEE` x the top speed; the charging current is then the excess over the
    circuit's resistance (:func:`_charge_current`), and its Lorentz force brakes the
    carriage: ``s`` :data:`GEN_FORCE` x the friction level at the top speed, nothing the
    other way and nothing slowly.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the generator's force constant squared over the circuit's
        resistance, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Electromagnetic energy harvesting and regenerative shock absorbers, the electrical
    damping of a generator charging a battery through a rectifier (Zuo and Zhang 2013,
    Energy harvesting, ride comfort and road handling of regenerative vehicle
    suspensions, J. Vib. Acoust. 135; Stephen 2006, On energy harvesting from ambient
    vibration, J. Sound Vib. 293; Sedra and Smith 2015, Microelectronic Circuits, ch. on
    rectifiers and battery chargers). The candidate gives each direction its levels and an
    offset; the open forms twin the levels, the curves or the viscous term, bend a curve,
    roll a lip, load a thrust bearing, film a rod seal, texture a ratchet, return a
    spring, tilt a pad, strut a sprag, throttle a meter-out, differ a cylinder's areas,
    groove chevrons, buckle a helix, scrape chips, commutate, idle a belt, free a roller,
    wick a felt, run a belt, lean a brush, band a seal, counterbalance a valve, vibrate
    elliptically, diode a flow, pitch pads, skew rollers, lift through a screw, turn the
    frame, angle a pull or adhere by wedges. Here an electrical diode and a battery's
    voltage make a braking force of one direction above a speed.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    i = _charge_current(np.asarray(kin.v, float) / v99, GEN_KNEE, GEN_ROUND)
    return F + float(s) * GEN_FORCE * _level(kin) * i


# -- stribeck_shape --------------------------------------------------------------------------
#: ``peel_adhesion``'s adhesive friction far above the peeling speed, x the Coulomb level, at
#: strength 1 [-]; the peeling speed, x the top speed [-]; the power of the tearing
#: energy's rise with the crack's speed [-]
PEEL_RISE, PEEL_SPEED, PEEL_POWER = 0.5, 0.3, 0.6


def _tearing_share(u, n):
    """The adhesive friction's share [-] of its high-speed value at the speeds ``u`` [-]
    (over the peeling speed): the viscoelastic tearing energy's rise G0 (1 + u^n), its
    loss part u^n / (1 + u^n) saturating as the polymer turns glassy."""
    r = np.abs(np.asarray(u, float)) ** n
    return r / (1.0 + r)


@on_fine_grid
def peel_adhesion_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Part of the contact is a soft polymer (an elastomer wiper's or a polyurethane
    roller's lip) that adheres to the counterface. Sliding, each junction's trailing edge
    is peeled off like a crack; a viscoelastic crack's tearing energy grows with its
    speed as a power of it (G = G0 (1 + (v / v_p)^n), n ~ 0.6) and levels off as the
    polymer turns glassy, and the energy lost per unit of sliding is an adhesive friction
    (:func:`_tearing_share`; v_p :data:`PEEL_SPEED` x the top speed). The truth's Stribeck
    curve is the base's plus ``s`` :data:`PEEL_RISE` x the Coulomb level x that share,
    inside the bristle dynamics: a friction that rises and levels off with the speed.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (with a Stribeck curve).
    s : float
        Amplitude factor [-]: the adhesive area's share, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Rate dependence of the adhesion and peeling of viscoelastic solids (Maugis and Barquins
    1978, Fracture mechanics and the adherence of viscoelastic bodies, J. Phys. D 11;
    Gent and Schultz 1972, Effect of wetting liquids on the strength of adhesion of
    viscoelastic materials, J. Adhesion 3; Persson 2000, Sliding Friction, ch. on rubber
    friction and crack propagation). The candidate's curve is Gaussian, Lorentzian or an
    exponential tail; the open forms add tails, rationals, films that lift, spikes,
    bimodal roughness, logs, Eyring, starvation, rubber hysteresis, resonances, dither,
    melting, grains, readsorption, thermoviscous, turbulent and thixotropic films,
    churning, core losses, breathing bellows, eddy brakes, shear thinning, flying pads,
    wiping menisci, journals, wall slip, a closing clearance, a dwell's squeeze, a
    pocket's suction, condensing menisci or flash heating. Here the adhesion is torn at
    each junction's trailing edge at a cost that grows with the tearing's speed.
    """
    law = kin.base
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (peel_adhesion): the mre_lugre base has no "
                         "Stribeck curve")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    vp = PEEL_SPEED * max(kin.scales["v99"], 1e-12)
    add = float(s) * PEEL_RISE * _level(kin)
    return lugre_with_curve(kin, lambda vv: law.g(vv) + add * _tearing_share(vv / vp,
                                                                              PEEL_POWER))


# -- position --------------------------------------------------------------------------------
#: ``lead_preload``'s largest change of the levels along the stroke, at strength 1 [-]; the
#: spacer between the two nuts, x the visited stroke [-]
LEAD_RISE, LEAD_SPACER = 0.4, 0.15


def _lead_deviation(xr):
    """A ball screw's cumulative lead deviation [-] along the positions ``xr`` [-] (over the
    visited stroke): a uniform lead error (the screw's mean lead off its nominal) and the
    slow wander of the grinding's lead along the screw, two long waves."""
    xr = np.asarray(xr, float)
    return (0.5 * xr + 0.3 * np.sin(2.0 * math.pi * xr / 0.55 + 0.4)
            + 0.15 * np.sin(2.0 * math.pi * xr / 0.23 + 1.3))


def _preload_change(xr, spacer):
    """The double nut's preload change [-] at the positions ``xr`` [-]: the lead
    deviation's difference over the ``spacer`` [-] between the nuts (what the spacer no
    longer matches), less its value at the stroke's middle."""
    d = _lead_deviation(xr + 0.5 * spacer) - _lead_deviation(xr - 0.5 * spacer)
    mid = _lead_deviation(np.array([0.5 + 0.5 * spacer]))[0] - \
        _lead_deviation(np.array([0.5 - 0.5 * spacer]))[0]
    return d - mid


@on_fine_grid
def lead_preload_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The axis is driven by a ball screw with a double nut preloaded by a spacer (two
    nuts pressed apart by a spacer of fixed length, :data:`LEAD_SPACER` x the visited
    stroke). The screw's lead deviates along its length (a uniform lead error and the
    grinding's slow wander, :func:`_lead_deviation`); where the deviation over the
    spacer's length differs, the spacer no longer matches the balls' grooves and the
    preload, and with it the nut's friction, changes (:func:`_preload_change`). The
    Coulomb and Stribeck levels are the base's times 1 + ``s`` :data:`LEAD_RISE` x that
    change over its largest along the record, inside the bristle dynamics; the viscous
    term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the lead deviation's size over the preload, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Lead accuracy of ball screws and the variation of a preloaded nut's drag torque along
    the stroke (ISO 3408-3, Ball screws - acceptance conditions and acceptance tests; JIS B
    1192, the preload drag torque's variation; Wei and Lin 2003, Kinematic analysis of the
    ball screw mechanism considering variable contact angles and elastic deformations, J.
    Mech. Des. 125). The candidate scales the friction along the stroke and adds a force of
    the position; the open forms put defects, waviness, wear, runout, bends, films,
    cogging, tapers, pockets, cushions, covers, springs, holes, plungers, sags, festoons,
    curves, chains, cams, heat, dents, joints, misalignment, flow forces, cranks,
    overhangs, a track's end, a reel, a way's flatness, conductive strips, a guide's ball
    passage or a steel insert on the stroke. Here the screw's lead error, differenced over
    the nuts' spacing, sets the preload along the stroke.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (lead_preload): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    span = max(sc["x_hi"] - sc["x_lo"], 1e-12)
    xr = (np.asarray(kin.x, float) - sc["x_lo"]) / span
    p = _preload_change(xr, LEAD_SPACER)
    p = p / max(float(np.max(np.abs(p))), 1e-12)
    lev = np.maximum(1.0 + float(s) * LEAD_RISE * p, 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- inertia ---------------------------------------------------------------------------------
#: ``liquid_column``'s liquid mass at strength 1, x the friction level / a99 [kg per N
#: s^2/m]; the horizontal share of the column's length [-]; the column's period, x the
#: motion's time scale [-]; the orifice's head loss, x omega^2 / (the share x a99) [1/m]
LC_MASS, LC_SHARE, LC_PERIOD, LC_LOSS = 0.5, 0.7, 2.0, 2.0


@njit(cache=True)
def _column_swing(t, a, omega, share, loss):
    """The acceleration [m/s^2] of a liquid column in a U-tube relative to the tube, whose
    tube accelerates by ``a`` [m/s^2] at the times ``t`` [s] (uniform), from rest: u'' =
    -``share`` a - omega^2 u - ``loss`` |u'| u' (gravity's restoring head, 2 g / L =
    omega^2, and the orifice's quadratic loss); semi-implicit Euler on sub-steps of at
    most 0.02 / omega, the tube's acceleration held over each."""
    n = t.size
    out = np.empty(n)
    dt = t[1] - t[0] if n > 1 else 0.0
    n_sub = max(1, int(math.ceil(omega * dt / 0.02)))
    h = dt / n_sub
    u = 0.0
    w = 0.0
    for k in range(n):
        out[k] = -share * a[k] - omega * omega * u - loss * abs(w) * w
        if k + 1 < n:
            am = 0.5 * (a[k] + a[k + 1])
            for _ in range(n_sub):
                w = w + h * (-share * am - omega * omega * u - loss * abs(w) * w)
                u = u + h * w
    return out


@on_fine_grid
def liquid_column_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage carries a U-tube of liquid (a tuned liquid column damper, a coolant or
    hydraulic loop with two risers), which the inverse dynamics misses. All of the liquid
    moves with the carriage; the column moreover swings in the tube, driven by the
    horizontal limb's share (:data:`LC_SHARE`) of the carriage's acceleration, restored by
    gravity on the risers' heads (a period of :data:`LC_PERIOD` x the motion's time scale)
    and damped by an orifice's quadratic head loss (:func:`_column_swing`). The liquid
    pushes on the carriage with its mass (``s`` :data:`LC_MASS` x the friction level /
    a99) times the carriage's acceleration plus the horizontal limb's share of the
    column's own: the truth adds that force to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the liquid's mass, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Tuned liquid column dampers and the U-tube's nonlinear equation of motion (Sakai, Takaeda
    and Tamaki 1989, Tuned liquid column damper - new type device for suppression of
    building vibrations, Proc. Int. Conf. on High-rise Buildings; Yalla and Kareem 2000,
    Optimum absorber parameters for tuned liquid column dampers, J. Struct. Eng. 126;
    Idelchik 1986, Handbook of Hydraulic Resistance, ch. on orifices). The candidate
    misses a constant mass; the open forms filter it, reflect it through gearing, a chain,
    a pinion or a screw, hang it on a spring, a cable, a fluid, a clutch, a coupling, a
    flyweight, a friction-damped, quasi-zero-stiffness, hose's or elastomer mount, surge a
    spring, add a fluid's mass, pick, drop, empty, slide, rattle, telescope, roll or rock
    it, recoil a frame, saturate a motor, lead a feedforward, pitch a scale, radiate
    waves, swing it on a rod or slide it in a dish. Here a liquid swings in a tube against
    gravity and a quadratic loss.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    m = float(s) * LC_MASS * _level(kin) / a99
    omega = 2.0 * math.pi / (LC_PERIOD * max(_motion_time(kin), 1e-12))
    a = np.asarray(kin.a, float)
    loss = LC_LOSS * omega * omega / (LC_SHARE * a99)
    ur = _column_swing(np.asarray(kin.t, float), a, omega, LC_SHARE, loss)
    return F + m * (a + LC_SHARE * ur)


# -- delay -----------------------------------------------------------------------------------
#: ``polynomial_smoother``'s window at strength 1 [data samples]; its polynomial's degree [-]
SMOOTH_SAMPLES, SMOOTH_DEGREE = 6.0, 2


def _endpoint_weights(m, degree):
    """The weights [-] (oldest first) of a least-squares polynomial of ``degree`` fitted to
    the ``m`` newest samples and read at the newest: a causal FIR filter that passes
    polynomials of that degree exactly (Savitzky and Golay's, at the window's end)."""
    m = int(m)
    deg = min(int(degree), m - 1)
    k = np.arange(m, dtype=float) - (m - 1)
    V = np.vander(k / max(m - 1, 1), deg + 1, increasing=True)
    # the fitted polynomial's value at k = 0 is the first row of (V^T V)^-1 V^T
    return np.linalg.pinv(V)[0]


def _fir_causal(u, w):
    """The causal FIR filter of the weights ``w`` (oldest first) on ``u`` [N], the first
    input held before the record (the logger starts on a full window of it)."""
    u = np.asarray(u, float)
    pad = np.concatenate((np.full(w.size - 1, u[0]), u))
    return np.convolve(pad, w[::-1], mode="valid")


@on_fine_grid
def polynomial_smoother_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is smoothed in real time by the data logger: a least-squares polynomial
    of degree :data:`SMOOTH_DEGREE` fitted over a trailing window (``s``
    :data:`SMOOTH_SAMPLES` data samples) and read at the window's newest point, updated at
    the converter's rate (the fine grid's; :func:`_endpoint_weights`, a causal
    Savitzky-Golay filter). A force that is a low polynomial over the window passes
    unchanged; at the force's bends (the reversals, the stick's onset) the reading lags
    and overshoots after them. The motion channels are on time.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the window's length, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Least-squares polynomial smoothing and its real-time (end-point) form (Savitzky and
    Golay 1964, Smoothing and differentiation of data by simplified least squares
    procedures, Anal. Chem. 36; Schafer 2011, What is a Savitzky-Golay filter?, IEEE
    Signal Process. Mag. 28). The candidate shifts the force in time or lags it through a
    first-order filter; the open forms delay, filter, average, stamp, decimate, hold,
    skew, jitter, limit the slew, pipe, take medians, report on a dead band, sample
    positions, run a belt, aerate, drop telegrams, leak, creep, notch, track, snub, time a
    waveguide's pulse, diffuse eddy currents, count a resonator, sweep a grating, restore
    a force by a servo, interleave converters, balance a pneumatic cell, count out a dual
    slope, adapt a filter's time constant or round in integer arithmetic. Here a fitted
    polynomial extrapolates the window to its end: exact on smooth stretches, late and
    overshooting at the bends.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    m = float(s) * SMOOTH_SAMPLES * kin.sample_dt / float(kin.t[1] - kin.t[0])
    lo = int(math.floor(m))
    if lo < SMOOTH_DEGREE + 1:
        # a window shorter than the polynomial's terms passes the force: blend towards
        # the shortest window that smooths, so the reading departs continuously from s = 0
        lo, frac = SMOOTH_DEGREE + 1, m / (SMOOTH_DEGREE + 1)
        y = _fir_causal(F, _endpoint_weights(lo, SMOOTH_DEGREE))
        return F + frac * (y - F)
    frac = m - lo
    y0 = _fir_causal(F, _endpoint_weights(lo, SMOOTH_DEGREE))
    y1 = _fir_causal(F, _endpoint_weights(lo + 1, SMOOTH_DEGREE))
    return y0 + frac * (y1 - y0)


# -- drift -----------------------------------------------------------------------------------
#: ``carbon_tribolayer``'s fall of the levels with the tribolayer complete, at strength 1
#: [-]; the sliding distance at which half the track is covered, x the record's [-]; the
#: covering's steepness (Hill's power) [-]
DLC_DROP, DLC_HALF, DLC_POWER = 0.35, 0.4, 3.0


def _covered(d, half, n):
    """The share of the track [-] a graphitic tribolayer covers after the sliding distance
    ``d`` [-] (over the record's): d^n / (d^n + ``half``^n), an incubation, then a
    spreading that saturates."""
    r = np.maximum(np.asarray(d, float), 0.0) ** n
    return r / (r + half ** n)


@on_fine_grid
def carbon_tribolayer_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The contact's surfaces are coated with a hydrogenated diamond-like carbon (a-C:H, as
    on precision slides, valve tappets and injection pumps). Run in, the coating's top
    rehybridises under the sliding's shear into a graphitic tribolayer that transfers to
    the counterface and carries a much lower friction; the layer nucleates after an
    incubating distance and spreads over the track (:func:`_covered`, half the track at
    :data:`DLC_HALF` x the record's sliding distance). It follows the distance slid, the
    integral of |v|: it holds in dwells and does not care for the friction's power. The
    Coulomb and Stribeck levels are the base's times 1 - ``s`` :data:`DLC_DROP` x the
    covered share, inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the tribolayer's fall of the friction, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Running-in of diamond-like carbon coatings and their graphitic transfer layers
    (Erdemir and Donnet 2006, Tribology of diamond-like carbon films: recent progress and
    future prospects, J. Phys. D 39; Liu, Erdemir and Meletis 1996, A study of the wear
    mechanism of diamond-like carbon films, Surf. Coat. Technol. 82; Sanchez-Lopez et al.
    2003, Friction-induced structural transformations of diamondlike carbon coatings
    under various atmospheres, Surf. Coat. Technol. 163). The candidate is a trend, a
    saturating change, a step, a cycle, a resetting change or the friction power's heat;
    the open forms warm up, wear in, change, heat, wear, follow the humidity, grind,
    relubricate, relax, oxidise, deplete, wear through, swell, build films, take in
    particles, expand, shear down, heat magnets, charge, creep, loosen, dewet, channel,
    drain, spall, evaporate, pump down, settle an additive, crystallise wax, bleed a
    grease's oil, cycle a thermostat or glaze a lining. Here the coating itself transforms
    under the sliding: a layer that forms after a distance and spreads.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    sp = np.abs(np.asarray(kin.v, float))
    d = np.concatenate(([0.0], np.cumsum(0.5 * (sp[1:] + sp[:-1]) * np.diff(t))))
    d = d / max(float(d[-1]), 1e-300)
    lev = np.maximum(1.0 - float(s) * DLC_DROP * _covered(d, DLC_HALF, DLC_POWER), 0.05)
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: ``magnet_latch``'s play at strength 1, as a share of the stroke (its full width) [-]; the
#: latch's pull at a flank at strength 1 (at most 0.9), x the Coulomb level [-]; the
#: magnets' effective distance at contact, x the play's half-width [-]
MAG_CLEAR, MAG_HOLD, MAG_STANDOFF = 0.005, 0.8, 0.5


@njit(cache=True)
def _latch_force(e, half, hold, d0):
    """The magnets' force [N] on the contact at the drive's offset ``e`` [m] from the
    play's middle (half-width ``half`` [m]): each flank's magnet attracts as the inverse
    square of its distance (the gap plus ``d0`` [m]), the two pulling opposite ways, scaled
    so the pull at a flank is ``hold`` [N]; beyond the flanks, the nearer one's at contact."""
    ee = min(max(e, -half), half)
    a = 1.0 / (half - ee + d0) ** 2 - 1.0 / (half + ee + d0) ** 2
    amax = 1.0 / d0 ** 2 - 1.0 / (2.0 * half + d0) ** 2
    return hold * a / amax


@njit(cache=True)
def _latch_contact(h, xd, half, hold, d0, kh, ch, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a light contact of mass ``m`` [kg] driven by the drive positions
    ``xd`` [m] (steps ``h`` [s]) through a play of half-width ``half`` [m] closed at the
    flanks by a spring ``kh`` [N/m] and damper ``ch`` [N s/m] (compressive only), with the
    magnets of :func:`_latch_force` across it; from rest, the drive in the play's middle.
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
        fc = _latch_force(e, half, hold, d0)
        if e > half:
            f2 = kh * (e - half) + ch * ed
            if f2 > 0.0:
                fc += f2
        elif e < -half:
            f2 = kh * (e + half) + ch * ed
            if f2 < 0.0:
                fc += f2
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha,
                                         shape)
        x = x + h * v
    return F


@on_fine_grid
def magnet_latch_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact are joined through a play of ``s``^2 :data:`MAG_CLEAR` x the
    stroke whose flanks carry small permanent magnets (a magnetic latch or a magnetic
    catch on a lost-motion link, a magnetically retained pawl). Across the play each
    flank's magnet attracts the contact as the inverse square of its distance (the gap
    plus :data:`MAG_STANDOFF` x the half-play, the magnets' effective distance at
    contact), the two opposite ways (:func:`_latch_force`): in the play's middle they
    cancel, and as the drive nears a flank the pull towards it swells, reaching ``s``
    :data:`MAG_HOLD` x the Coulomb level at the flank (at most 0.9 of it: less than the
    friction, so the contact does not follow); the flank then takes the drive up
    (:func:`_latch_contact`). The contact is light (its inertial force at the top
    acceleration 1 % of the Coulomb level) with the base's LuGre friction.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the square root of the play's width (as the open plays') and
        the magnets' pull, / their values at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The attraction of permanent magnets across an air gap and magnetic latches (Furlani
    2001, Permanent Magnet and Electromechanical Devices, ch. on the force between
    magnets; Campbell 1994, Permanent Magnet Materials and their Application, ch. on
    holding magnets) and lost motion in mechanisms (Nordin and Gutman 2002, Controlling
    mechanical systems with backlash - a survey, Automatica 38). The candidate holds or
    frees the contact across a rigid play; the open forms take it up rigidly, compliantly,
    by impact, against a spring, eccentrically, through oil, worn, with a dragging idler,
    biased, slack, magnetic, preloaded, through a flexspline, a rope, a spider, a fluid
    link, a cable, a clutch, a varying mesh, a polymer gear, grease, a wedge, an
    overlapped spool, a side loaded pin, a toggle spring, graded pins, an adhesive flank,
    packed powder, a floating part between two plays, trapped air or a ball detent. Here
    magnets on the flanks pull across the gap: an inverse-square tug that swells towards
    each flank.
    """
    p = _lugre_params(kin, "backlash (magnet_latch)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    half = 0.5 * float(s) ** 2 * MAG_CLEAR * float(np.ptp(kin.x))
    m, kh, ch = _contact_constants(kin, p)
    rate = max(math.sqrt(kh / m), (float(p.sigma1) + float(p.sigma2) + ch) / m)
    h, xd, n_sub = _substeps(kin, rate)
    hold = min(float(s) * MAG_HOLD, 0.9) * float(p.Fc)
    Fr = _latch_contact(h, xd, half, hold, MAG_STANDOFF * half, kh, ch, m,
                        float(p.sigma0), float(p.sigma1), float(p.sigma2), float(p.Fc),
                        float(p.Fs), float(p.vs), float(p.alpha), SHAPES[p.shape])
    return Fr[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: ``fibre_wiper``'s share of the friction the wiper carries, at strength 1 (at most 0.95)
#: [-]; its reference displacement beyond the base bristle's Fs / sigma0, at strength 1, x
#: the stroke / 3 [-]
FIBRE_SHARE, FIBRE_PATH = 0.4, 0.1


@njit(cache=True)
def _masing_hyperbola(x, xr_ref):
    """The wiper's force [-] (+-1 at full slip) along the positions ``x`` [m], from rest:
    the virgin curve is the hyperbola f = d / (``xr_ref`` + |d|) of the displacement d from
    the start; after each reversal (at (x_r, f_r)) the branch is Masing's, f = f_r + 2 h((x
    - x_r) / 2), the virgin curve doubled, capped at full slip (+-1)."""
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
                    u = x[k] - x[0]
                    f = u / (xr_ref + abs(u))
                else:
                    u = 0.5 * (x[k] - xr)
                    f = fr + 2.0 * u / (xr_ref + abs(u))
                    f = min(max(f, -1.0), 1.0)
        out[k] = f
    return out


@on_fine_grid
def fibre_wiper_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Part of the contact's friction is carried by a fibrous felt wiper beside it (a way
    wiper of wool or synthetic felt, pressed on the ways). Its fibres bend and slip on one
    another: the wiper's force is a hyperbola of the displacement, f = F_w d / (d_r + |d|)
    (the fibre network's tangent stiffness falling as its contacts slip, Kondner's and
    Hardin and Drnevich's form; d_r the base bristle's Fs / sigma0 plus ``s``
    :data:`FIBRE_PATH` x the stroke / 3), and after each reversal it returns along
    Masing's rule, the virgin hyperbola doubled in both scales (:func:`_masing_hyperbola`).
    The wiper carries the share w = ``s`` :data:`FIBRE_SHARE` of the Coulomb level, w Fc
    f; the contact the rest, the base's LuGre with its curve less w Fc (its viscous term
    whole). Sliding far, the sum approaches the base's; after a reversal the wiper's force
    turns over along the hyperbola's branch. At ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the wiper's share of the friction (up to ``s`` = 0.95 /
        :data:`FIBRE_SHARE`) and its reference displacement (as the open presliding
        forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Hyperbolic stress-strain laws with Masing's unloading rule (Kondner 1963, Hyperbolic
    stress-strain response: cohesive soils, J. Soil Mech. Found. Div. 89; Hardin and
    Drnevich 1972, Shear modulus and damping in soils: design equations and curves, J.
    Soil Mech. Found. Div. 98; Masing 1926, Eigenspannungen und Verfestigung beim Messing,
    Proc. 2nd Int. Congr. Appl. Mech.) and the friction of fibre assemblies (Carnaby and
    Pan 1989, Theory of the compression hysteresis of fibrous assemblies, Text. Res. J.
    59). The candidate's presliding is a generalized Maxwell-slip (GMS) element set; the
    open forms are Maxwell-slip sets, Dahl, elasto-plastic, Bliman-Sorine, Bouc-Wen, Zener
    junctions, Mindlin contacts, rate-and-state, Tomlinson asperities, bond rupture,
    gouge, kinematic hardening, interlocking, capillary bridges, cyclic hardening,
    peeling, unloading microslip, a power-law joint, junction growth, avalanches, slip
    weakening, a microslip bar, contact renewal, grease's yield, a superelastic flexure,
    an Eyring film, a viscoplastic layer, a poroelastic one, a confined film that melts or
    a hysteresis brake, each beside the contact, or a stiffening wire mesh in series with
    it. Here a fibre network's hyperbola, reversed by Masing's rule, beside the contact.
    """
    _lugre_params(kin, "gms (fibre_wiper)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    law = kin.base
    w = min(float(s) * FIBRE_SHARE, 0.95)
    wf = w * _level(kin)
    e0, extra = _presliding_path(kin, s, FIBRE_PATH)
    f = _masing_hyperbola(np.asarray(kin.x, float), e0 + extra)
    rest = lugre_with_curve(kin, lambda vv: law.g(vv) - wf)
    return rest + wf * f
