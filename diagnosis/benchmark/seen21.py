"""The twenty-first seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-30 (session 25) by another hand, once, without running the diagnosis on it;
run once, sealed, at the start of session 26 on the code of cead57e:
176 cases, 0 skipped, 687 s wall on 2 workers (beside a helper's tests and other checks). Top-1 50.0 % (88;
51.2 % of the 168 detectable; the other 8: 6 delays below a sample, 1 load and 1 asymmetry an
oracle cannot tell from the base); mean |shrink error| 0.293; wrong names on 11 (6.3 %, the
fewest of any family): acceleration -> drift 4, gms -> acceleration 2, gms -> delay 2, drift ->
load 1, position -> inertia 1, position -> delay 1. By form: load/pin_in_bore 16/20,
inertia/spring_surge 15/20, delay/magnetoelastic_cell 14/20, position/spool_flow_force 10/16,
acceleration/cone_sensor_brake 9/20, drift/receiver_pressure 9/20, backlash/overlapped_servo
7/12, asymmetry/counterbalance_valve 5/20, gms/contact_renewal 2/12, stribeck_shape/flying_pad
1/16. By plant: valve 67.5 %, isolator 60.7 %, damping rig 45.0 %, press 39.3 %, XML-350
37.5 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen20` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen20`,
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
acceleration       ``cone_sensor_brake``: an inertia sensor on the carriage (a ball in
                   a conical seat, as in emergency-locking retractors and seismic
                   shut-off valves) rolls up its cone once the acceleration, either way,
                   passes its trip level and sets a drag shoe on the rail; the ball
                   rolls back only below a lower release level (its seat's lip): a dry
                   friction that follows a relay (with hysteresis) of |a|, paced by the
                   ball's roll time
load               ``pin_in_bore``: the load is carried by a pin (a guide rod, a pivot)
                   in a bore of nearly its size: the conforming contact's arc widens
                   with the load (Persson's pin in a hole), and the friction of a
                   cosine pressure over that arc is mu L times a factor that grows from
                   1 (a line contact) towards 4 / pi and beyond (Reye's worn-in
                   journal): levels that grow faster than the load
asymmetry          ``counterbalance_valve``: the axis is held by a pilot-operated
                   counterbalance (load-holding) valve: moving out the oil passes its
                   check valve at a small cracking pressure; moving in it must open the
                   valve's relief seat, a pressure setting that the pilot pressure of
                   the driving side lowers once it has built up (pilot ratio, a lag)
                   and that rises with the flow (the override): a direction-dependent
                   offset, high at first after each reversal into the valve
stribeck_shape     ``flying_pad``: a self-acting (aerodynamic or hydrodynamic) pad
                   beside the contact takes part of the load off it once the speed
                   passes its take-off speed, and lands again only below a lower
                   touch-down speed (the take-off / landing hysteresis of flying
                   sliders): the levels drop above a speed that depends on whether
                   the carriage is speeding up or slowing down
position           ``spool_flow_force``: the moving part is (or carries) a spool of a
                   supplied valve whose metering edges open past an overlap either side
                   of the null: the oil's jet through the opening pushes the spool back
                   towards the null (the steady-state flow force, ~ opening x pressure
                   drop x cos of the jet angle, which turns from about 21 to 69 degrees
                   as the opening grows past the radial clearance): a force of the
                   position alone, nothing within the overlap, stiff just past it and
                   softer further out
inertia            ``spring_surge``: the carriage pulls a long helical spring (a return
                   or counterbalance spring, its static force in the model) whose own
                   mass is distributed along its coils: the coils move as an elastic
                   rod fixed at one end and driven at the other (spring surge): the
                   inverse dynamics misses a third of the spring's mass at low
                   frequencies, and the surge modes ring after each change of the
                   acceleration
delay              ``magnetoelastic_cell``: the force is read by a magnetoelastic
                   (Villari-effect) transducer with a solid core: a change of stress
                   changes its magnetisation, and eddy currents in the core hold the
                   flux change back as it diffuses in from the surface: the reading is
                   the force through a diffusion lag (tanh(sqrt(s tau)) / sqrt(s tau)),
                   half-order at high frequencies
drift              ``receiver_pressure``: the pneumatic seals (or an air-bearing preload)
                   are fed straight from a receiver tank that a compressor refills
                   between its pressure switch's cut-in and cut-out pressures; the
                   axis' own air use, ~ its travel, drains the tank: the seals' levels
                   follow a sawtooth of the supply pressure, falling with the travel
                   and rising in time while the compressor runs
backlash           ``overlapped_servo``: the contact is moved by a hydraulic actuator
                   whose valve follows the drive's position error through an overlapped
                   spool: within the overlap no oil flows and the contact stands; past
                   it the contact's speed is proportional to the error beyond the
                   overlap (a flow-gain dead zone): a lost motion taken up at a rate, not
                   at a flank
gms                ``contact_renewal``: presliding of rolling contacts whose force is
                   carried by each contact's pressure distribution shifted against the
                   rolling: every strip of a contact takes its sense from the direction
                   of travel when it rolled in, so after a reversal the contact is
                   renewed only once it has rolled through its own width; the force is
                   the Hertz-weighted mean of the direction over the last renewal path
                   (a finite, local memory); at ``s`` = 0 the base itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``flying_pad`` needs a
Stribeck curve (not the isolator's mre_lugre), ``spool_flow_force`` a record that revisits
its positions (not the press), ``pin_in_bore`` a load that changes, ``overlapped_servo``
and ``contact_renewal`` a classic LuGre base (valve, damping rig, XML-350); each raises a
``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _lag, _level, _lugre_params, _motion_time,
                     _presliding_path, _smooth_max0, _substeps, has_stribeck_curve,
                     level_inside, on_fine_grid)

__all__ = ["FORMS", "cone_sensor_brake_truth", "pin_in_bore_truth",
           "counterbalance_valve_truth", "flying_pad_truth", "spool_flow_force_truth",
           "spring_surge_truth", "magnetoelastic_cell_truth", "receiver_pressure_truth",
           "overlapped_servo_truth", "contact_renewal_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "cone_sensor_brake", "load": "pin_in_bore",
         "asymmetry": "counterbalance_valve", "stribeck_shape": "flying_pad",
         "position": "spool_flow_force", "inertia": "spring_surge",
         "delay": "magnetoelastic_cell", "drift": "receiver_pressure",
         "backlash": "overlapped_servo", "gms": "contact_renewal"}


@njit(cache=True)
def _relay(u, on, off, start):
    """A relay (Schmitt trigger) of the values ``u``: 1 from where ``u`` passes ``on``, 0
    again from where it falls below ``off`` (< ``on``); ``start`` its state before the
    first value."""
    out = np.empty(u.size)
    state = start
    for k in range(u.size):
        if u[k] > on:
            state = 1.0
        elif u[k] < off:
            state = 0.0
        out[k] = state
    return out


# -- acceleration ----------------------------------------------------------------------------
#: ``cone_sensor_brake``'s trip and release accelerations, x the top acceleration [-]; the
#: drag shoe's friction, x the friction level, at strength 1 [-]; the ball's roll time up or
#: down its cone, x the motion's time scale v99 / a99 [-]; the speed the shoe's friction
#: turns over, x the top speed [-]
CONE_TRIP, CONE_RELEASE, CONE_DRAG, CONE_ROLL, CONE_ROUND = 0.6, 0.3, 0.5, 0.03, 2e-3


@on_fine_grid
def cone_sensor_brake_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """An inertia sensor rides on the carriage: a ball in a conical seat (half-angle alpha)
    stays seated while the horizontal acceleration |a| is below g tan(alpha) and rolls up
    the cone, either way, above it, lifting a lever that sets a drag shoe on the rail; a
    lip at the seat's rim holds the ball up until |a| has fallen below a lower level. The
    shoe is set while the ball is up: a relay of |a| (trip :data:`CONE_TRIP`, release
    :data:`CONE_RELEASE` x the top acceleration; :func:`_relay`), each change taking the
    ball's roll time (a first-order lag of :data:`CONE_ROLL` x the motion's time scale).
    The shoe is a contact of its own: the truth adds its dry friction, ``s``
    :data:`CONE_DRAG` x the friction level x the shoe's engagement, against the velocity
    (turning over :data:`CONE_ROUND` x the top speed), to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the shoe's spring force times its friction coefficient, / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Ball-in-cone acceleration sensors of vehicle-sensitive emergency-locking retractors
    (UN ECE Regulation No. 16, their locking and non-locking accelerations) and of
    seismic gas shut-off valves (a ball that leaves its seat above a set ground
    acceleration). The candidate raises the levels with |a|, lagged, tilts them with a and
    adds a force odd in a; the open forms lag, age, heat, skid, move load between rows,
    press seals, pull magnets, squeeze, transfer weight, slosh, dilate, lift on wedges,
    shift a gib, soften rubber, swing arms, unload by the jerk, tilt pads, push ball
    trains, ripple the current or slide rack flanks. Here the friction switches: up once
    |a| has passed one level, down only when it has fallen below a lower one.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    a99 = max(kin.scales["a99"], 1e-12)
    up = _relay(np.abs(np.asarray(kin.a, float)) / a99, CONE_TRIP, CONE_RELEASE, 0.0)
    shoe = _lag(kin.t, up, CONE_ROLL * max(_motion_time(kin), 1e-12))
    v99 = max(kin.scales["v99"], 1e-12)
    turn = np.tanh(np.asarray(kin.v, float) / (CONE_ROUND * v99))
    return F + float(s) * CONE_DRAG * _level(kin) * shoe * turn


# -- load ------------------------------------------------------------------------------------
#: ``pin_in_bore``'s rise of the levels at the record's top load (its 99th percentile), at
#: strength 1 [-]; the load L_c at which the contact arc reaches +-90 degrees, x the top
#: load [-]
BORE_SHARE, BORE_CONFORM = 0.5, 0.5


def _contact_arc(load, l_c):
    """The half-angle [rad] of the contact arc of a pin in a bore of nearly its size under
    the loads ``load`` [N]: tan^2(theta0 / 2) = |L| / ``l_c`` (``l_c`` [N] ~ E* times the
    clearance: Hertz's conforming contact, theta0^2 ~ L, at light loads; the arc widens
    towards the half circle as the load grows)."""
    return 2.0 * np.arctan(np.sqrt(np.abs(np.asarray(load, float)) / l_c))


def _arc_factor(theta0):
    """The friction of a cosine pressure p ~ cos(theta) - cos(theta0) over the arc
    |theta| < ``theta0`` [rad] over the friction of the same net load on a line [-]:
    integral of p over integral of p cos(theta), (sin t - t cos t) / (t / 2 - sin(2 t) / 4);
    1 + t^2 / 10 for small arcs, 4 / pi at a quarter circle each side, 2 at a full one."""
    t = np.asarray(theta0, float)
    small = t < 1e-2
    ts = np.where(small, 1.0, t)
    full = (np.sin(ts) - ts * np.cos(ts)) / (0.5 * ts - 0.25 * np.sin(2.0 * ts))
    return np.where(small, 1.0 + t * t / 10.0, full)


@on_fine_grid
def pin_in_bore_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The normal load reaches the contact through a pin (a guide rod, a pivot pin) in a
    bore of nearly its size. Lightly loaded the two touch along a line; as the load grows
    the conforming surfaces close over an arc of half-angle theta0 with tan^2(theta0 / 2)
    = L / L_c (:func:`_contact_arc`; L_c = :data:`BORE_CONFORM` x the record's top load).
    The sliding friction is mu times the integral of the pressure, which for a cosine
    distribution over the arc exceeds mu L by the factor :func:`_arc_factor` (1 on a line,
    4 / pi over a quarter circle either side: the worn-in journal's). The Coulomb and
    Stribeck levels are the base's times 1 + ``s`` :data:`BORE_SHARE` (L / L_top) x the
    factor / its value at the top load, inside the bristle dynamics; the viscous term is
    the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (load [N]) and its base law.
    s : float
        Amplitude factor [-]: the pin's friction coefficient times its share of the
        contact, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The pin in a hole (Persson 1964, On the stress distribution of cylindrical elastic
    bodies in contact, Chalmers; Johnson 1985, Contact Mechanics, ch. 5.3 on conforming
    cylinders) and the friction of a conforming journal (Reye's hypothesis of wear, the
    factor 4 / pi of a worn-in journal: Rabinowicz 1995, Friction and Wear of Materials;
    Hutchings 1992). The candidate makes the levels affine in the load, with a memory over
    the travel; the open forms scale the friction with the load as a Hertz contact's area,
    a seal's, a film's, a junction's, a pivot's or an adhesive contact's, break or squeeze
    films, plough, creep, relieve a preload, roll on a lossy track or slip in conforming
    grooves. Here the load changes the contact's geometry: the friction per unit load
    grows with the load as the arc widens.
    """
    L = np.asarray(kin.load, float)
    Lm = float(np.mean(np.abs(L))) or 1.0
    if not np.ptp(L) > 1e-9 * Lm:
        raise ValueError(f"load (pin_in_bore): the {kin.plant} record's load does not change")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    top = max(float(np.percentile(np.abs(L), 99)), 1e-12 * Lm)
    l_c = BORE_CONFORM * top
    rel = np.abs(L) / top * _arc_factor(_contact_arc(L, l_c)) \
        / float(_arc_factor(_contact_arc(np.array([top]), l_c))[0])
    lev = 1.0 + float(s) * BORE_SHARE * rel
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``counterbalance_valve``'s piloted holding resistance (the setting less the pilot's
#: share), x the friction level, at strength 1 [-]; the pilot ratio [-]; the check valve's
#: cracking resistance, x the holding resistance [-]; the override at the top speed [-];
#: the pilot's build-up time, x the motion's time scale [-]; the speed the valves' switching
#: is rounded over, x the top speed [-]
VALVE_HOLD, VALVE_PILOT, VALVE_CHECK, VALVE_OVERRIDE, VALVE_LAG, VALVE_ROUND = \
    0.4, 1.5, 0.15, 0.5, 0.05, 2e-3


def _valve_resistance(v, pilot, v99, pilot_ratio, check, override, v_round):
    """The valve's resistance [-] (1: the piloted holding resistance at rest) at the
    velocities ``v`` [m/s], signed as a friction: moving out (+x) the check valve's
    cracking ``check``; moving in (-x) the relief seat's setting, lowered by the pilot
    pressure ``pilot`` [-] (0 to 1) in the ratio (1 + ``pilot_ratio``) / (1 +
    ``pilot_ratio`` pilot), and raised by the flow, 1 + ``override`` |v| / ``v99``; the
    switch rounded over ``v_round`` [m/s]."""
    v = np.asarray(v, float)
    q = np.tanh(v / v_round)
    out_ = np.maximum(q, 0.0)
    in_ = np.maximum(-q, 0.0)
    hold = (1.0 + override * np.abs(v) / v99) * (1.0 + pilot_ratio) \
        / (1.0 + pilot_ratio * np.asarray(pilot, float))
    return check * out_ - in_ * hold


@on_fine_grid
def counterbalance_valve_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The axis' actuator is held by a pilot-operated counterbalance valve on its
    load-holding side. Moving out (+x) the oil flows in through the valve's check at its
    small cracking pressure (:data:`VALVE_CHECK` of the holding resistance). Moving in
    (-x) it must leave through the relief seat, which opens only at the valve's setting;
    the pressure of the driving side, fed to the pilot, helps to open it in the pilot
    ratio :data:`VALVE_PILOT` once it has built up (a first-order lag of
    :data:`VALVE_LAG` x the motion's time scale from each reversal into -x), and the
    pressure rises with the flow (the override, :data:`VALVE_OVERRIDE` at the top speed;
    :func:`_valve_resistance`). The truth adds ``s`` :data:`VALVE_HOLD` x the friction
    level x that resistance to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the valve's setting times the actuator's area, / its value
        at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Counterbalance (over-centre, load-holding) valves (Merritt 1967, Hydraulic Control
    Systems, ch. 4; Miyakawa 1978, Stability of a hydraulic circuit with a counter-balance
    valve, Bull. JSME 21; the makers' notes on pilot ratio and override). The candidate
    frees the levels (and the Stribeck velocity and viscous term) of each direction and an
    offset; the open forms twin the levels, curves or viscous terms, roll lips, load
    thrust bearings, pump films, ratchet, spring back, tilt pads, strut, throttle, differ
    in areas, pump along grooves, buckle, scrape chips, commutate, tension idlers,
    free-wheel, wick felts, run belts, lean brushes or pull sealing bands. Here one
    direction opens a pressure setting, high at first after each reversal into it and
    lower once the pilot has built up.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v = np.asarray(kin.v, float)
    v99 = max(kin.scales["v99"], 1e-12)
    v_round = VALVE_ROUND * v99
    inward = np.maximum(-np.tanh(v / v_round), 0.0)
    pilot = _lag(kin.t, inward, VALVE_LAG * max(_motion_time(kin), 1e-12))
    r = _valve_resistance(v, pilot, v99, VALVE_PILOT, VALVE_CHECK, VALVE_OVERRIDE, v_round)
    return F + float(s) * VALVE_HOLD * _level(kin) * r


# -- stribeck_shape --------------------------------------------------------------------------
#: ``flying_pad``'s take-off and touch-down speeds, x the top speed [-]; the share of the
#: contact's load it takes flying, at strength 1 [-]; the least share the contact keeps [-];
#: the time it takes to lift or land, x the motion's time scale [-]
PAD_TAKEOFF, PAD_TOUCHDOWN, PAD_SHARE, PAD_FLOOR, PAD_SETTLE = 0.5, 0.25, 0.4, 0.05, 0.02


@on_fine_grid
def flying_pad_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Beside the contact a self-acting pad (an aerodynamic slider, a hydrodynamic shoe)
    shares the carriage's load. At rest and at low speed it rests on the way and the
    contact carries the load; above its take-off speed its film carries the pad's share,
    and it lands again only when the speed has fallen below a lower touch-down speed
    (the adhesion of its meniscus and its film's stiffness make take-off and landing
    differ): a relay of |v| (:data:`PAD_TAKEOFF`, :data:`PAD_TOUCHDOWN` x the top speed;
    :func:`_relay`), each change over :data:`PAD_SETTLE` x the motion's time scale. The
    Coulomb and Stribeck levels are the base's times 1 - ``s`` :data:`PAD_SHARE` x the
    pad's lift (the contact's remaining load; at least :data:`PAD_FLOOR`), inside the
    bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law (with a Stribeck
        curve).
    s : float
        Amplitude factor [-]: the pad's share of the load, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Self-acting gas-film sliders and their take-off and landing (contact start-stop)
    speeds (Gross 1962, Gas Film Lubrication; Bhushan 1996, Tribology and Mechanics of
    Magnetic Storage Devices, ch. 8 on take-off velocity and stiction); hysteresis of
    flying height with speed (the slider's bistable flying states). The candidate reshapes
    the Stribeck curve; the open forms add a tail, a rational drop, a hydrodynamic rise, a
    spike, a lift-off, two roughness scales, a logarithmic or Eyring law, starve a film,
    add rubber hysteresis, resonate, dither, melt, flow grains, readsorb, heat the film,
    make it turbulent, thixotropic, churned or shear-thinning, add core losses, breathe a
    bellows or brake by eddy currents. Here the curve has two branches: the levels drop at
    one speed while the carriage speeds up and return at a lower one while it slows down.
    """
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (flying_pad): the mre_lugre base has no Stribeck "
                         "curve")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    up = _relay(np.abs(np.asarray(kin.v, float)) / v99, PAD_TAKEOFF, PAD_TOUCHDOWN, 0.0)
    lift = _lag(kin.t, up, PAD_SETTLE * max(_motion_time(kin), 1e-12))
    lev = np.maximum(1.0 - float(s) * PAD_SHARE * lift, PAD_FLOOR)
    return level_inside(kin, lev, np.ones_like(lev))


# -- position --------------------------------------------------------------------------------
#: ``spool_flow_force``'s flow force at the far end of the visited stroke, x the friction
#: level, at strength 1 [-]; the overlap of the metering edges either side of the null, x
#: the stroke [-]; the radial clearance the jet angle turns over, x the stroke [-]; the
#: travel the edges' opening is rounded over, x the stroke [-]; the jet angles at a closed
#: and a wide opening [deg] (von Mises' 69 degrees)
FLOW_PUSH, FLOW_LAP, FLOW_CLEAR, FLOW_ROUND = 0.25, 0.03, 0.05, 0.005
FLOW_ANGLE_CLOSED, FLOW_ANGLE_OPEN = 21.0, 69.0


def _jet_cosine(opening, clearance):
    """cos of the jet angle [-] at the metering edge's openings ``opening`` [m] (>= 0) of
    a spool with the radial clearance ``clearance`` [m]: the angle turns from
    :data:`FLOW_ANGLE_CLOSED` at openings small against the clearance to
    :data:`FLOW_ANGLE_OPEN` (the free streamline's) at wide ones, as 1 / (1 + y / c)."""
    y = np.asarray(opening, float)
    ang = FLOW_ANGLE_OPEN - (FLOW_ANGLE_OPEN - FLOW_ANGLE_CLOSED) / (1.0 + y / clearance)
    return np.cos(np.radians(ang))


@on_fine_grid
def spool_flow_force_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The moving part is (or carries) the spool of a valve under supply pressure, its
    null where fit and held-out parts both pass. Within the metering edges' overlap
    (:data:`FLOW_LAP` x the stroke either side of the null) no oil flows; past it the edge
    opens by y = |x - x0| - overlap (rounded over :data:`FLOW_ROUND` x the stroke) and the
    oil's jet through it pushes the spool back towards the null with the steady-state
    flow force 2 Cd Cv w y dp cos(theta), the jet angle theta turning from about 21 to 69
    degrees as the opening grows past the radial clearance (:data:`FLOW_CLEAR` x the
    stroke; :func:`_jet_cosine`). The truth adds that force, ``s`` :data:`FLOW_PUSH` x the
    friction level at the far end of the visited stroke, to the base, whatever the
    direction of motion.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the supply pressure drop times the edges' width, / its value
        at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Steady-state flow forces on spool valves (von Mises 1917, Berechnung von Ausfluss- und
    Ueberfallzahlen, Z. VDI 61: the free streamline's 69 degrees; Lee and Blackburn 1952,
    Contributions to hydraulic control 1: steady-state axial forces on control-valve
    pistons, Trans. ASME 74, the smaller angle at openings within the radial clearance;
    Merritt 1967, Hydraulic Control Systems, ch. 5). The candidate scales the friction
    along the stroke and adds a force of the position; the open forms put a defect, a
    waviness, a worn section, runout, a bent rail, a transfer film, cogging, a taper, a
    pocket, a cushion, a cover, an air spring, bolt holes, a plunger, a sag, a festoon, a
    curve, a chain, a cam, a heated zone, brinelled dents, a rail joint or misaligned rails
    on the stroke. Here a centring force with a dead band: none within the overlap, then
    one whose stiffness falls as the jet turns.
    """
    x0 = _bump_centre(kin)
    if x0 is None:
        raise ValueError(f"position (spool_flow_force): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    if s <= 0.0:
        return _base_parts(kin)[0]
    F = _base_parts(kin)[0]
    sc = kin.scales
    stroke = (sc["x_hi"] - sc["x_lo"]) or 1.0
    e = np.asarray(kin.x, float) - x0
    lap, clear = FLOW_LAP * stroke, FLOW_CLEAR * stroke
    y = _smooth_max0(np.abs(e) - lap, FLOW_ROUND * stroke)
    push = y * _jet_cosine(y, clear)
    far = max(sc["x_hi"] - x0, x0 - sc["x_lo"])
    y_far = float(_smooth_max0(np.array([far - lap]), FLOW_ROUND * stroke)[0])
    ref = max(y_far * float(_jet_cosine(np.array([y_far]), clear)[0]), 1e-12 * stroke)
    return F + float(s) * FLOW_PUSH * _level(kin) * np.sign(e) * push / ref


# -- inertia ---------------------------------------------------------------------------------
#: ``spring_surge``'s missed mass at low frequencies (a third of the spring's) x the top
#: acceleration, x the friction level, at strength 1 [-]; the first surge mode's angular
#: frequency, x 1 / the motion's time scale v99 / a99 [-]; the modes' damping ratio [-];
#: the number of modes kept [-]
SURGE_MASS, SURGE_FREQ, SURGE_DAMPING, SURGE_MODES = 0.8, 8.0, 0.05, 8


@njit(cache=True)
def _surge_force(a, h, n_sub, m_s, w1, zeta, n_modes):
    """The force [N] the distributed mass ``m_s`` [kg] of a spring (an elastic rod fixed at
    its far end, its near end moving with the carriage, whose accelerations ``a`` [m/s^2]
    come in steps ``h`` [s], each in ``n_sub`` sub-steps) takes from the carriage beyond
    its static force: the coils' motion relative to the static line is a sum of the rod's
    fixed-fixed modes q_n, q_n'' + 2 zeta w_n q_n' + w_n^2 q_n = 2 (-1)^n / (n pi) a,
    w_n = n ``w1`` [rad/s], and the force is k sum n pi (-1)^n q_n, k = m_s w1^2 / pi^2,
    plus the static share of the modes beyond ``n_modes`` (m_s (1/3 - sum 2 / (n pi)^2) a:
    m_s a / 3 in all at low frequencies). Semi-implicit Euler; starts at rest."""
    n = a.size
    out = np.empty(n)
    hs = h / n_sub
    q = np.zeros(n_modes)
    w = np.zeros(n_modes)
    k = m_s * w1 * w1 / (math.pi * math.pi)
    rest = 1.0 / 3.0
    for i in range(n_modes):
        rest -= 2.0 / ((i + 1) * math.pi) ** 2
    for j in range(n):
        f = m_s * rest * a[j]
        for i in range(n_modes):
            nn = i + 1
            f += k * nn * math.pi * (-1.0) ** nn * q[i]
        out[j] = f
        for _ in range(n_sub):
            for i in range(n_modes):
                nn = i + 1
                wn = nn * w1
                c = 2.0 * (-1.0) ** nn / (nn * math.pi)
                w[i] = (w[i] + hs * (c * a[j] - wn * wn * q[i])) / (1.0 + 2.0 * zeta * wn * hs)
                q[i] += hs * w[i]
    return out


@on_fine_grid
def spring_surge_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage pulls one end of a long helical spring (a return or counterbalance
    spring) whose other end is fixed; the spring's static force k x is in the model, its
    mass m_s is not. The coils do not follow the static line: they move as an elastic rod
    (the spring's surge, waves along its coils), the modes of a rod fixed at both ends
    driven by the carriage's acceleration (:func:`_surge_force`; first mode
    :data:`SURGE_FREQ` / the motion's time scale, :data:`SURGE_MODES` modes, damping ratio
    :data:`SURGE_DAMPING`). At low frequencies the force they take is m_s a / 3
    (Rayleigh's third of the spring's mass; m_s a99 / 3 = ``s`` :data:`SURGE_MASS` x the
    friction level), and each change of the acceleration sets the surge modes ringing.
    The truth adds that force to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the spring's mass, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Spring surge and the effective mass of a spring (Rayleigh 1877, The Theory of Sound,
    the third of the spring's mass; Wahl 1963, Mechanical Springs, ch. 25 on surge; Den
    Hartog 1956, Mechanical Vibrations, on valve-spring surge). The candidate misses a
    constant mass; the open forms filter it, reflect it through gearing, a chain's polygon
    or a pinion, hang it on a spring, a cable, a fluid, a clutch, a coupling, a flyweight,
    a screw or a friction-damped mount, pick it up, drop it, empty it, slide it, rattle it,
    recoil the frame, saturate the motor, lead it by the feedforward or pitch the scale
    head. Here the missed mass is distributed: a third of it at low frequencies, and a
    train of standing waves along the spring above.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    T = max(_motion_time(kin), 1e-12)
    a99 = max(kin.scales["a99"], 1e-12)
    m_s = 3.0 * float(s) * SURGE_MASS * _level(kin) / a99
    w1 = SURGE_FREQ / T
    h = float(kin.t[1] - kin.t[0])
    n_sub = max(1, int(math.ceil(h * SURGE_MODES * w1 / 0.05)))
    extra = _surge_force(np.ascontiguousarray(kin.a, dtype=float), h, n_sub, m_s, w1,
                         SURGE_DAMPING, SURGE_MODES)
    return F + extra


# -- delay -----------------------------------------------------------------------------------
#: ``magnetoelastic_cell``'s mean lag at low frequencies (a third of the core's diffusion
#: time), in data samples, at strength 1 [-]; the diffusion modes kept [-]
CELL_SAMPLES, CELL_MODES = 4.0, 60


def _diffusion_modes(tau, n_modes):
    """(weights [-], time constants [s]) of the core's flux diffusion
    tanh(sqrt(s ``tau``)) / sqrt(s ``tau``) (``tau`` [s] the diffusion time of the half
    thickness) as a sum of first-order lags: weights 8 / ((2k + 1) pi)^2 and time
    constants ``tau`` / ((2k + 1) pi / 2)^2, k < ``n_modes``; the weights sum to 1 over
    all k, their mean lag is ``tau`` / 3."""
    k = np.arange(n_modes)
    lam = ((2 * k + 1) * math.pi / 2.0) ** 2
    return 2.0 / lam, tau / lam


def _diffused(t, F, tau, n_modes):
    """The force ``F`` [N] on the uniform times ``t`` [s] read through the core's flux
    diffusion of diffusion time ``tau`` [s] (:func:`_diffusion_modes`): each mode a
    first-order lag (:func:`.truths._lag`), the modes much faster than the grid's step and
    those beyond ``n_modes`` passed through at once (their weights' rest)."""
    w, taus = _diffusion_modes(tau, n_modes)
    h = float(t[1] - t[0])
    out = np.zeros_like(F)
    direct = 1.0
    for wk, tk in zip(w, taus):
        if tk < 0.05 * h:
            break                                              # as good as instantaneous
        out += wk * _lag(t, F, tk)
        direct -= wk
    return out + direct * F


@on_fine_grid
def magnetoelastic_cell_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is read by a magnetoelastic (Villari-effect) transducer: the stress the
    force puts into a magnetised solid steel core changes its magnetisation, and a coil
    (or a field sensor) reads the flux. In the solid core a change of the flux induces
    eddy currents that oppose it, and it diffuses in from the surface: the reading follows
    the force through tanh(sqrt(s tau)) / sqrt(s tau) (:func:`_diffused`, a sum of
    :data:`CELL_MODES` first-order lags, the faster rest passed through), whose mean lag
    is tau / 3 = ``s`` :data:`CELL_SAMPLES` data samples and whose phase goes as the
    square root of the frequency above 1 / tau (a half-order lag, not a filter's). The
    motion channels are on time.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the core's diffusion time mu sigma d^2, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Magnetoelastic force and torque transducers (Bozorth 1951, Ferromagnetism, ch. 13 on
    the Villari effect; Garshelis 1992, A torque transducer utilizing a circularly
    polarized ring, IEEE Trans. Magn. 28) and eddy-current diffusion into a solid core
    (Lammeraner and Stafl 1964, Eddy Currents; Stoll 1974, The Analysis of Eddy
    Currents). The candidate shifts the force by a constant time, low-passes it, reads it
    through a transducer's resonance and leaks it; the open forms sample, filter, average,
    hold, skew, jitter, rate-limit, transmit, median, report by deadband, trigger on
    positions, run a belt, aerate, drop telegrams, leak, creep, notch, track, snub or time
    a waveguide's pulse. Here the lag is a diffusion's: short for the slow part of the
    force, a long tail for its fast changes.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    tau = 3.0 * float(s) * CELL_SAMPLES * kin.sample_dt
    return _diffused(np.asarray(kin.t, float), F, tau, CELL_MODES)


# -- drift -----------------------------------------------------------------------------------
#: ``receiver_pressure``'s rise of the levels from the cut-in to the cut-out pressure, at
#: strength 1 [-]; the tank's swings from cut-out to cut-in over the record's travel [-];
#: the compressor's refill time from cut-in to cut-out, x the record's length [-]
RECV_RISE, RECV_CYCLES, RECV_FILL = 0.5, 2.5, 0.08


@njit(cache=True)
def _receiver(t, speed, drain, fill):
    """The receiver's pressure [-] (0 at the cut-in, 1 at the cut-out pressure) along the
    times ``t`` [s]: it falls by ``drain`` [1/m] x the travel (the axis' air use, ~ its
    swept volume, at the speeds ``speed`` [m/s]) and, while the compressor runs, rises at
    ``fill`` [1/s]; the pressure switch starts the compressor at the cut-in and stops it
    at the cut-out. Starts full, the compressor stopped."""
    n = t.size
    out = np.empty(n)
    u = 1.0
    on = False
    out[0] = u
    for k in range(1, n):
        dt = t[k] - t[k - 1]
        u -= drain * 0.5 * (speed[k] + speed[k - 1]) * dt
        if on:
            u += fill * dt
        if u <= 0.0:
            u = 0.0
            on = True
        elif u >= 1.0:
            u = 1.0
            on = False
        out[k] = u
    return out


@on_fine_grid
def receiver_pressure_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The contact's pneumatic seals (or an air-bearing preload, or a pressure-energised
    clamp) are fed straight from a receiver tank, with no regulator between. The axis'
    air use, its swept volume, drains the tank in proportion to its travel
    (:data:`RECV_CYCLES` swings from the cut-out to the cut-in pressure over the record);
    the pressure switch starts the compressor at the cut-in pressure and stops it at the
    cut-out, refilling the tank in :data:`RECV_FILL` x the record (or twice as fast as the
    axis' top air use drains it; :func:`_receiver`). The seals' levels follow the supply
    pressure: the Coulomb and Stribeck levels are the base's times 1 + ``s``
    :data:`RECV_RISE` x the pressure above the cut-in, inside the bristle dynamics; the
    viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the switch's pressure band times the seals' pressure
        sensitivity, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Compressed-air supply by a receiver and a pressure switch (cut-in and cut-out
    pressures; Beater 2007, Pneumatic Drives, ch. 2; ISO 1217 on compressor duty) and the
    pressure dependence of pneumatic seal friction (Belforte, Mattiazzo, Mauro and
    Tokashiki 2003, Measurement of friction force in pneumatic cylinders, Tribotest 10).
    The candidate is a trend, a saturating change, a step, a cycle, a resetting change or
    the friction power's heat; the open forms warm up, wear in, change the lubricant,
    heat, wear, follow the humidity, grind a third body, relubricate, relax a seal,
    oxidise, deplete, wear through, swell, build a tribofilm, take in particles, expand,
    shear down, heat magnets, charge, creep a cage, loosen a screw, dewet a film or
    channel grease. Here the levels fall with the travel and rise with the time: a
    sawtooth whose falling flanks follow the motion and whose rising ones the clock.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    speed = np.abs(np.asarray(kin.v, float))
    T = float(t[-1] - t[0]) or 1.0
    travel = float(np.sum(0.5 * (speed[1:] + speed[:-1]) * np.diff(t))) or 1.0
    drain = RECV_CYCLES / travel
    fill = max(1.0 / (RECV_FILL * T), 2.0 * drain * float(np.max(speed)))
    p = _receiver(t, speed, drain, fill)
    lev = 1.0 + float(s) * RECV_RISE * p
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: ``overlapped_servo``'s overlap at strength 1, as a share of the stroke (its full width,
#: both sides) [-]; the servo's time constant 1 / K past the overlap, x the motion's time
#: scale [-]
SERVO_LAP, SERVO_LAG = 0.008, 0.01


@njit(cache=True)
def _overlapped_follower(xd, h, half, gain):
    """The velocities [m/s] of a contact whose speed follows the drive positions ``xd``
    [m] (steps ``h`` [s]) through a flow-gain dead zone: v = ``gain`` [1/s] x (e - clip(e,
    -``half``, ``half``)), e the drive's lead on the contact (an overlapped spool of
    half-overlap ``half`` [m] in a position loop). Explicit Euler; starts centred, at
    rest."""
    n = xd.size
    out = np.empty(n)
    x = xd[0]
    for j in range(n):
        e = xd[j] - x
        v = gain * (e - min(max(e, -half), half))
        out[j] = v
        x += h * v
    return out


@on_fine_grid
def overlapped_servo_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The contact (the carriage whose friction is measured) is moved by a hydraulic
    actuator in a position loop whose valve has an overlapped spool: while the drive's
    lead e on the contact is within the overlap (half-width ``s``^2 :data:`SERVO_LAP` / 2
    x the stroke) no oil flows and the contact stands; past it the flow, and the
    contact's speed, are K (e - overlap) (:func:`_overlapped_follower`; 1 / K =
    :data:`SERVO_LAG` x the motion's time scale): after each reversal the drive crosses
    the overlap with the contact at rest and the contact then takes up the lead
    exponentially in time, not at a flank. The force is the base's LuGre friction along
    the contact's motion (the actuator is stiff: no mass, no coupling spring).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the square root of the overlap, / its value at strength 1
        (as the open plays').

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Overlapped (closed-centre) spools and the flow-gain dead zone they put in a servo
    loop (Merritt 1967, Hydraulic Control Systems, ch. 5 on critically centred,
    overlapped and underlapped valves; Viersma 1980, Analysis, Synthesis and Design of
    Hydraulic Servosystems and Pipelines). The candidate holds or frees the contact across
    a rigid play; the open forms take it up rigidly, compliantly, by impact, against a
    spring, eccentrically, through oil, worn, with a dragging idler, biased, slack,
    magnetic, preloaded, through a flexspline, a rope, a spider, a fluid link, a cable, a
    clutch, a varying mesh, a polymer gear, grease or a wedge. Here the take-up is a rate:
    the contact's speed is proportional to how far the drive has gone past the overlap.
    """
    _lugre_params(kin, "backlash (overlapped_servo)")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    half = 0.5 * float(s) ** 2 * SERVO_LAP * float(np.ptp(kin.x))
    gain = 1.0 / (SERVO_LAG * max(_motion_time(kin), 1e-12))
    h, xd, n_sub = _substeps(kin, 1.5 * gain)
    vc = _overlapped_follower(xd, h, half, gain)[::n_sub]
    return np.asarray(kin.base.simulate(kin.t, vc), float)


# -- gms -------------------------------------------------------------------------------------
#: the contacts' renewal path at strength 1, beyond the base bristle's path, as a share of
#: the stroke / 3 [-]; their share of the friction at strength 1 [-]
RENEW_PATH, RENEW_SHARE = 0.1, 0.6


@njit(cache=True)
def _renewal_share(u):
    """The share [-] of a Hertzian (semi-elliptic) line contact's load on the strips within
    ``u`` x its width of its leading edge (0 <= u <= 1): a circular segment's area over the
    half disc's, (acos(1 - 2u) - (1 - 2u) sqrt(1 - (1 - 2u)^2)) / pi."""
    u = min(max(u, 0.0), 1.0)
    c = 1.0 - 2.0 * u
    return (math.acos(c) - c * math.sqrt(max(1.0 - c * c, 0.0))) / math.pi


@njit(cache=True)
def _renewed(x, width):
    """The contacts' force f [-] (+-1 once renewed) along the positions ``x`` [m]: the mean
    of the direction of travel over the last ``width`` [m] of travel, each strip weighted
    by its share of the Hertzian load (:func:`_renewal_share`); strips that rolled in
    before the motion started carry nothing."""
    n = x.size
    out = np.zeros(n)
    path = np.zeros(n)
    starts = np.zeros(n)                    # path at which each run of one direction began
    dirs = np.zeros(n)
    runs = 0
    direction = 0.0
    for k in range(1, n):
        dx = x[k] - x[k - 1]
        path[k] = path[k - 1] + abs(dx)
        if dx != 0.0:
            d = 1.0 if dx > 0.0 else -1.0
            if d != direction:
                starts[runs] = path[k - 1]
                dirs[runs] = d
                runs += 1
                direction = d
        f = 0.0
        end = path[k]
        for r in range(runs - 1, -1, -1):
            back_end = (path[k] - end) / width
            back_start = (path[k] - starts[r]) / width
            f += dirs[r] * (_renewal_share(back_start) - _renewal_share(back_end))
            end = starts[r]
            if back_start >= 1.0:
                break
        out[k] = f
    return out


@on_fine_grid
def contact_renewal_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Beside the bristle, part of the friction is the rolling resistance of rolling
    contacts (a guide's balls or rollers), carried by each contact's pressure distribution
    shifted against the rolling. Every strip of a contact takes the sense of its shift
    from the direction of rolling when it entered the contact, and keeps it while it rolls
    through: after a reversal the contact's force turns as the renewed strips' share of
    its Hertzian (semi-elliptic) load grows, and the contact is wholly renewed once it
    has rolled through its own width (:func:`_renewed`; the renewal path is the base
    bristle's Fs / sigma0 plus ``s`` :data:`RENEW_PATH` x the stroke / 3): a finite,
    local memory - the last renewal path decides, whatever came before. The contacts'
    share w = ``s`` :data:`RENEW_SHARE` (up to ``s`` = 1) of the friction is their force
    times the Stribeck level, the viscous term the base's: F = (1 - w) F_lugre + w (g(v)
    f + sigma2 v). At ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the contacts' share (up to ``s`` = 1) and their renewal path
        (as the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Rolling resistance as the contact's displaced pressure distribution and the renewal
    of a rolling contact over its width (Johnson 1985, Contact Mechanics, ch. 8 and 9;
    Carter 1926, On the action of a locomotive driving wheel, Proc. R. Soc. A 112); the
    presliding of rolling guideways over a rolling distance of the contacts' size
    (Al-Bender and Symens 2005, Characterization of frictional hysteresis in ball-bearing
    guideways, Wear 258). The candidate's presliding is a generalized Maxwell-slip (GMS)
    element set; the open forms are Maxwell-slip sets, Dahl, elasto-plastic,
    Bliman-Sorine, Bouc-Wen, Zener junctions, Mindlin contacts, rate-and-state, Tomlinson
    asperities, bond rupture, gouge, kinematic hardening, interlocking, capillary bridges,
    cyclic hardening, peeling, unloading microslip, a power-law joint, junction growth,
    avalanches, slip weakening and a microslip bar. Here the memory is a window of the
    travel: the force after a reversal reaches the full opposite level at a finite path
    and forgets everything rolled through before it.
    """
    p = _lugre_params(kin, "gms (contact_renewal)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, RENEW_PATH)
    w = RENEW_SHARE * min(float(s), 1.0)
    v = np.asarray(kin.v, float)
    f = _renewed(np.ascontiguousarray(kin.x, dtype=float), e0 + extra)
    return (1.0 - w) * F + w * (kin.base.g(v) * f + float(p.sigma2) * v)
