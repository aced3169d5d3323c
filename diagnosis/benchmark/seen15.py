"""The fifteenth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-29 (session 20) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 21's work on the code of ca024ab:
176 cases, 0 skipped, 1306 s wall on 1 worker (beside a 2-worker grid run, a 1-worker
clean run and a helper). Top-1 35.8 % (63; 35.6 % of the 174 detectable); mean |shrink
error| 0.318; wrong names on 48 (27.3 %): inertia -> acceleration 8, acceleration ->
asymmetry 8, delay -> acceleration 7, gms -> acceleration 5, drift -> inertia 5, gms -> load
4, stribeck_shape -> acceleration 2, delay -> gms 2, backlash -> delay 2, asymmetry ->
inertia 2. By form: load/jkr_adhesion 19/20, position/gliding_chain 16/16,
asymmetry/belt_idler 10/20, acceleration/swing_arm_roller 7/20,
backlash/bowden_cable 4/12, drift/magnet_heating 4/20, inertia/force_saturation 2/20,
stribeck_shape/thixotropic_grease 1/16, delay/load_cell_creep 0/20,
gms/unloading_microslip 0/12. By plant: valve 45.0 %, damping rig 42.5 %, isolator 39.3 %,
XML-350 35.0 %, press 10.7 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen14` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen14`,
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
acceleration       ``swing_arm_roller``: the guide's rollers are pressed onto the rail
                   by springs through pivoted, inclined arms (an elevator's roller
                   guide shoes, a follower arm): the carriage's acceleration rocks each
                   arm's mass about its pivot against its spring, a lightly damped
                   oscillator: the rollers' load, and the levels, follow its swing -
                   the acceleration filtered by a resonance, ringing after each change
load               ``jkr_adhesion``: a soft, smooth contact (an elastomer pad or roller)
                   whose friction is a shear strength times the real contact area, that
                   area held by the surfaces' adhesion as well as the load (Johnson,
                   Kendall and Roberts 1971): the levels follow the JKR area, nonzero at
                   no load, steep at light loads and flat at heavy ones
asymmetry          ``belt_idler``: a belt-driven axis with a tension idler (a guide
                   roller) on one span only: its bearing's drag grows with that span's
                   tension, which carries the drive force when it pulls one way and
                   goes slack when it pulls the other (Palmgren's load-dependent
                   bearing torque): the levels follow the positive part of the drive
                   force (friction plus inertial force), not the direction of motion
stribeck_shape     ``thixotropic_grease``: a grease beside the contact whose structure
                   the shear breaks down and which rebuilds at rest (thixotropy, Moore
                   1959; Barnes 1997): its drag, viscous at the structure's viscosity,
                   thins as it is sheared: a drag rising with the speed and bending
                   over, fresh after a rest, thinned after fast travel
position           ``gliding_chain``: a long-travel energy chain whose upper run glides
                   on its lower run from the fixed point on, and on the trough's glide
                   bars past it: the gliding lengths change with the position, chain on
                   chain and chain on bars at their own friction: the levels change
                   linearly along the stroke with a kink at the chain's fixed point
inertia            ``force_saturation``: the force is read as the motor current times its
                   nominal force constant, and the iron saturates at high currents
                   (the force constant falls, Gieras and Piech 2000): the reading of
                   friction plus inertial force grows faster than the force, and the
                   inverse dynamics leaves an error ~ (m a)^3 at the acceleration peaks
delay              ``load_cell_creep``: the force read by a strain-gauge load cell whose
                   spring element creeps anelastically (Zener 1948; the creep test of
                   OIML R60): a share of each change of the force appears at once, the
                   rest follows with the creep's time constant: a partial lag
drift              ``magnet_heating``: the force is read as the motor current times the
                   cold force constant; the copper losses (~ the drive force squared)
                   warm the magnets and their remanence falls (NdFeB, about -0.1 %/K):
                   the reading of friction and inertial force alike grows with the
                   lagged mean square drive force
backlash           ``bowden_cable``: drive and contact joined by a push-pull cable in a
                   curved sheath (a Bowden cable, a tendon-sheath drive): the cable's
                   elasticity and the capstan friction along the sheath (Kaneko et al.
                   1991): after each reversal the cable's strain must unwind against the
                   sheath before the contact turns, more the higher the force
gms                ``unloading_microslip``: the presliding junctions are Hertzian
                   micro-contacts whose slip limits follow the normal load (Mindlin and
                   Deresiewicz 1953): a falling load makes them slip where they stand
                   and lose the force they held, a rising one does not give it back;
                   at ``s`` = 0 the base itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``thixotropic_grease``
needs a Stribeck curve (not the isolator's mre_lugre), ``gliding_chain`` a record that
revisits its positions (not the press), ``jkr_adhesion`` a load that changes,
``bowden_cable`` and ``unloading_microslip`` a classic LuGre base (valve, damping rig,
XML-350); each raises a ``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.shapes import SHAPES

from ..effects_backlash import PLANT_GAP_SHARE
from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _lag, _level,
                     _light_contact_step, _lugre_params, _lugre_run, _motion_time,
                     _presliding_path, _smooth_max0, _span, _substeps, level_inside,
                     on_fine_grid)

__all__ = ["FORMS", "swing_arm_roller_truth", "jkr_adhesion_truth", "belt_idler_truth",
           "thixotropic_grease_truth", "gliding_chain_truth", "force_saturation_truth",
           "load_cell_creep_truth", "magnet_heating_truth", "bowden_cable_truth",
           "unloading_microslip_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "swing_arm_roller", "load": "jkr_adhesion",
         "asymmetry": "belt_idler", "stribeck_shape": "thixotropic_grease",
         "position": "gliding_chain", "inertia": "force_saturation",
         "delay": "load_cell_creep", "drift": "magnet_heating",
         "backlash": "bowden_cable", "gms": "unloading_microslip"}


def _drive_force(kin: PlantKinematics, F, inertia: float) -> np.ndarray:
    """The drive's force [N] along ``kin``'s grid: the force ``F`` [N] plus the carriage's
    inertial force m a, m a99 = ``inertia`` x the friction level."""
    m = inertia * _level(kin) / max(kin.scales["a99"], 1e-12)
    return np.asarray(F, float) + m * np.asarray(kin.a, float), m


# -- acceleration ---------------------------------------------------------------------------
#: ``swing_arm_roller``'s arms' natural angular frequency on their springs, x 1 / the
#: motion's time scale [-]; their damping ratio [-]; the rollers' load change per unit of
#: the arms' static swing at a99 at strength 1 [-]; the lowest relative level (the rollers
#: lift off) [-]
ARM_FREQUENCY, ARM_DAMPING, ARM_LOAD, ARM_FLOOR = 2.0, 0.12, 0.6, 0.05


def _arm_swing(t, u, wn, zeta):
    """The arms' swing [-] along the times ``t`` [s] under the relative accelerations ``u``
    [-]: q'' + 2 ``zeta`` ``wn`` q' + ``wn``^2 q = ``wn``^2 u (a pivoted mass on its
    spring, rocked by the carriage's acceleration; static gain 1), from rest."""
    from scipy.signal import lsim
    _, y, _ = lsim(([wn * wn], [1.0, 2.0 * zeta * wn, wn * wn]), np.asarray(u, float),
                   np.asarray(t, float))
    return np.asarray(y, float)


@on_fine_grid
def swing_arm_roller_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage is guided by rollers, each pressed onto its rail by a spring through a
    pivoted arm inclined to the rail (roller guide shoes; spring-loaded follower arms).
    The carriage's acceleration swings each arm's mass about its pivot against its
    spring: a lightly damped oscillator (natural frequency :data:`ARM_FREQUENCY` / the
    motion's time scale, damping ratio :data:`ARM_DAMPING`) driven by a / a99
    (:func:`_arm_swing`). The inclination turns the swing into the rollers' pressing
    force: the Coulomb and Stribeck levels are the base's times 1 + ``s``
    :data:`ARM_LOAD` x the swing (at least :data:`ARM_FLOOR`: the rollers lift off),
    inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the arms' mass moment over their springs' preload, / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Spring-loaded roller guide shoes of elevator cars and their dynamics (Strakosch 1998,
    The Vertical Transportation Handbook; Janovsky 1999, Elevator Mechanical Design);
    follower arms held by springs (Norton 2002, Cam Design and Manufacturing Handbook, on
    follower jump). The candidate raises the levels with |a|, lagged, tilts them with a,
    and adds a force odd in a; the open forms lag the velocity, a film or a contact state,
    heat the contact, skid rolling elements, move load between rows or supports, press
    seals, pull with the thrust, squeeze films, starve the contact, dilate it, lift it on
    a wedge, shift a gib or soften an elastomer mount. Here the levels follow a resonant
    response of the acceleration: in phase at slow changes, ringing at the arms' own
    frequency after each jerk, whatever the acceleration does then.
    """
    if s <= 0.0:
        return _base_parts(kin)[0]
    T = max(_motion_time(kin), 1e-12)
    u = np.asarray(kin.a, float) / max(kin.scales["a99"], 1e-12)
    q = _arm_swing(kin.t, u, ARM_FREQUENCY / T, ARM_DAMPING)
    lev = np.clip(1.0 + float(s) * ARM_LOAD * q, ARM_FLOOR, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- load ------------------------------------------------------------------------------------
#: ``jkr_adhesion``'s pull-off force of the contact, x the record's mean load [-]; the levels'
#: change per unit of the relative contact area's change at strength 1 [-]; the lowest
#: relative level [-]
PULL_OFF, AREA_GAIN, ADHESION_FLOOR = 0.4, 1.0, 0.05


def _jkr_area(r, c):
    """The contact area [-] of an adhesive elastic contact at the relative loads ``r`` [-],
    over its value at r = 1 (Johnson, Kendall and Roberts 1971: a^3 ~ P + 2 P_c + 2 sqrt(P_c
    P + P_c^2), P_c = ``c`` the pull-off force [-]; the area ~ a^2)."""
    r = np.maximum(np.asarray(r, float), 0.0)

    def area(p):
        return (p + 2.0 * c + 2.0 * np.sqrt(c * p + c * c)) ** (2.0 / 3.0)
    return area(r) / area(1.0)


@on_fine_grid
def jkr_adhesion_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A soft, smooth contact (an elastomer pad or roller on a clean, smooth counterface)
    whose friction is an interfacial shear strength times the real contact area (Bowden and
    Tabor), that area set by the load *and* the surfaces' adhesion: the contact of
    Johnson, Kendall and Roberts (:func:`_jkr_area`), whose pull-off force is
    :data:`PULL_OFF` x the record's mean load. The Coulomb and Stribeck levels are the
    base's times 1 + ``s`` :data:`AREA_GAIN` x (A / A(mean load) - 1) (at least
    :data:`ADHESION_FLOOR`), inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (load [N]) and its base law.
    s : float
        Amplitude factor [-]: the share of the friction the adhesive area carries, / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Surface energy and the contact of elastic solids (Johnson, Kendall and Roberts 1971,
    Proc. R. Soc. A 324); friction proportional to the adhesive contact area (Carpick,
    Agrait, Ogletree and Salmeron 1996, J. Vac. Sci. Technol. B 14; Homola et al. 1990 for
    mica). The candidate's levels are affine in the load (two regimes); the open forms
    scale them with a power of the load (Hertz), in one direction, with the Stribeck
    velocity, a film that breaks, creeps, squeezes, desorbs, scuffs, cavitates, a lever's
    play, a plastic area, a pressure-viscous film, an erf area, a load's rate or its
    renewal over the slip. Here the friction does not vanish with the load: the adhesion
    holds an area at no load, and the levels rise steeply at light loads and slowly at
    heavy ones.
    """
    L = np.asarray(kin.load, float)
    if not np.ptp(L) > 1e-9 * max(float(np.mean(np.abs(L))), 1e-300):
        raise ValueError(f"load (jkr_adhesion): the {kin.plant} record's load does not "
                         f"change")
    if s <= 0.0:
        return _base_parts(kin)[0]
    r = L / max(float(np.mean(L)), 1e-300)
    lev = np.clip(1.0 + float(s) * AREA_GAIN * (_jkr_area(r, PULL_OFF) - 1.0),
                  ADHESION_FLOOR, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``belt_idler``'s idler bearing drag per unit of its span's tension, at strength 1 [-];
#: the carriage's inertial force at a99, x the friction level [-]; the span's tension
#: rounded over this share of the friction level (it never goes slack at once) [-]
IDLER_DRAG, IDLER_INERTIA, IDLER_ROUNDING = 0.4, 1.0, 0.05


@on_fine_grid
def belt_idler_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A belt-driven axis whose belt runs over a tension idler (a guide roller) on one
    span only. The drive's force F_d = friction + m a (m a99 = :data:`IDLER_INERTIA` x the
    friction level, :func:`_drive_force`) is carried by the span that pulls: the idler's
    span when F_d > 0, the other when F_d < 0, the idler's span then slack. The idler's
    bearing drag grows with its load, the span's tension: the Coulomb and Stribeck levels
    are the base's times 1 + ``s`` :data:`IDLER_DRAG` x max(F_d, 0) / the friction level
    (rounded over :data:`IDLER_ROUNDING` of it), inside the bristle dynamics; the viscous
    term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the idler bearing's drag per unit of its load, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The load-dependent friction torque of rolling bearings (Palmgren 1959, Ball and Roller
    Bearing Engineering: M1 = f1 P dm; Harris and Kotzalas 2007, Rolling Bearing
    Analysis); tight and slack spans of belt drives (Childs 2004, Mechanical Design, ch.
    10). The candidate shifts a direction's levels and viscous slope (and an offset); the
    open forms keep a direction's share, its Stribeck velocity, viscous slope or tail,
    roll a lip, follow a thrust, a film laid by the outstroke, a texture, a return spring,
    a wedge film, a strut, a throttle, a cylinder's areas, pumping grooves, a buckling
    cable, a scraper's pile or a commutation angle. Here the asymmetry follows the sign of
    the drive's force, not of the velocity: a braking stroke the one way looks like the
    other way.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    Fd, _ = _drive_force(kin, F, IDLER_INERTIA)
    Fl = _level(kin)
    tight = _smooth_max0(Fd / Fl, IDLER_ROUNDING)
    lev = 1.0 + float(s) * IDLER_DRAG * tight
    return level_inside(kin, lev, np.ones_like(lev))


# -- stribeck_shape --------------------------------------------------------------------------
#: ``thixotropic_grease``'s drag at v99 with its structure intact, at strength 1, x the
#: friction level [-]; the broken structure's viscosity over the intact one's [-]; the
#: structure's rebuilding time, x the record's length [-]; its breakdown at v99 over its
#: rebuilding (the steady structure at v99 is 1 / (1 + this)) [-]
GREASE_DRAG, GREASE_FLOOR, REBUILD_SHARE, BREAKDOWN = 0.5, 0.15, 0.05, 8.0


@njit(cache=True)
def _structure(t, u, tau, k):
    """The grease's structure parameter [-] (1 intact, 0 broken down) along the times ``t``
    [s] and relative shear rates ``u`` [-] (>= 0): d lambda / dt = (1 - lambda) / ``tau``
    - ``k`` u lambda / ``tau`` (Moore's kinetics), exact for the step's midpoint rate.
    Starts intact (the grease has rested)."""
    n = t.size
    out = np.empty(n)
    lam = 1.0
    out[0] = lam
    for j in range(1, n):
        um = 0.5 * (u[j] + u[j - 1])
        rate = (1.0 + k * um) / tau
        eq = 1.0 / (1.0 + k * um)
        lam = eq + (lam - eq) * math.exp(-(t[j] - t[j - 1]) * rate)
        out[j] = lam
    return out


@on_fine_grid
def thixotropic_grease_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A grease (a thixotropic gel) fills a gap beside the contact (a greased labyrinth,
    the space between a carriage's seals and its rail): its shear breaks its structure
    down and it rebuilds at rest (Moore's kinetics, :func:`_structure`: rebuilding time
    :data:`REBUILD_SHARE` x the record, breakdown at v99 :data:`BREAKDOWN` x the
    rebuilding). Its viscosity is the broken-down one plus the structure's share,
    eta / eta_0 = :data:`GREASE_FLOOR` + (1 - :data:`GREASE_FLOOR`) lambda, and its drag,
    ``s`` :data:`GREASE_DRAG` x the friction level x |v| / v99 x eta / eta_0, adds to the
    Stribeck curve inside the bristle dynamics: a rising, bending drag in steady sliding
    (its steady structure falls with the speed), higher after a rest, lower after fast
    travel.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law (a Stribeck curve).
    s : float
        Amplitude factor [-]: the grease's wetted area (its drag), / its value at strength
        1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Thixotropy and its structural kinetics (Moore 1959, The rheology of ceramic slips and
    bodies, Trans. Br. Ceram. Soc. 58; Barnes 1997, Thixotropy - a review, J.
    Non-Newtonian Fluid Mech. 70); the shear degradation and recovery of lubricating
    greases (Delgado et al. 2005, Tribol. Lett. 18). The candidate bends the base's drop
    (an exponent, the Lorentzian, a log-speed map); the open forms add tails, drops, a
    spike, a lift-off, a second drop, logarithmic weakening, Eyring strengthening, a rise
    at the top speed, a hump, a notch, a dither, a melt, a granular rise, re-adsorption,
    thermal thinning and a turbulent film. Here the speed dependence has a memory of the
    shearing: the same speed drags more after a rest than after a fast stroke.
    """
    if kin.base.name == "mre_lugre":
        raise ValueError("stribeck_shape (thixotropic_grease): the mre_lugre base has no "
                         "Stribeck curve")
    if s <= 0.0:
        return _base_parts(kin)[0]
    p = kin.base.params
    t = np.asarray(kin.t, float)
    v = np.asarray(kin.v, float)
    u = np.abs(v) / max(kin.scales["v99"], 1e-12)
    tau = REBUILD_SHARE * max(float(t[-1] - t[0]), 1e-12)
    lam = _structure(t, np.ascontiguousarray(u), tau, BREAKDOWN)
    drag = float(s) * GREASE_DRAG * _level(kin) * u * (GREASE_FLOOR +
                                                       (1.0 - GREASE_FLOOR) * lam)
    vm = 0.5 * (v[1:] + v[:-1])
    g = kin.base.g(v) + drag
    g_mid = kin.base.g(vm) + 0.5 * (drag[1:] + drag[:-1])
    return _lugre_run(t, v, g, g_mid, float(p.sigma0), float(p.sigma1),
                      float(p.sigma2) * v)


# -- position --------------------------------------------------------------------------------
#: ``gliding_chain``'s chain-on-chain and chain-on-bars friction, per unit of the gliding
#: length over the stroke the record visits, at strength 1, x the friction level [-]; the
#: chain's bend radius (the kink's rounding), x the stroke [-]
CHAIN_ON_CHAIN, CHAIN_ON_BARS, CHAIN_BEND = 1.2, 0.5, 0.03


def _gliding(x, fixed, bend, on_chain, on_bars):
    """The chain's gliding friction [-] at the positions ``x`` [m] less its value at the
    fixed point ``fixed`` [m]: its upper run glides on its lower run over l - |d| / 2 (d
    = x - ``fixed``, l half the chain) at ``on_chain`` per unit length and, behind the fixed
    point, on the trough's glide bars over -d at ``on_bars``; |d| and max(-d, 0) rounded
    over the bend ``bend`` [m]."""
    d = np.asarray(x, float) - fixed
    ad = np.sqrt(d * d + bend * bend) - bend
    return -0.5 * on_chain * ad + on_bars * _smooth_max0(-d, bend)


@on_fine_grid
def gliding_chain_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage drags a long-travel energy chain (a cable carrier) whose fixed end is at
    mid-travel, where fit and held-out parts both pass (:func:`.truths._bump_centre`): the
    chain runs from there along the trough, turns and comes back on top to the carriage.
    Its upper run glides on its lower run over l - |d| / 2 (d the carriage's distance from
    the fixed point, l half the chain's length) and, on the side where the carriage is
    behind the fixed point, on the trough's glide bars over |d| (:func:`_gliding`), each
    at its own friction (:data:`CHAIN_ON_CHAIN`, :data:`CHAIN_ON_BARS` per unit of the
    gliding length over the stroke, x the friction level, the base's levels holding the
    chain's drag at the fixed point). The Coulomb and Stribeck levels are the base's
    times 1 + ``s`` x that change, inside the bristle dynamics; the viscous term is the
    base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the chain's weight per unit length (its gliding friction), /
        its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Gliding applications of long-travel energy chains, the upper run sliding on the lower
    run in a guide trough with glide bars (igus 2020, e-chain systems, gliding
    applications; Tsubaki Kabelschlepp, cable carriers for long travel lengths). The
    candidate scales the friction along the stroke and adds a periodic and a smooth force
    of x; the open forms are level maps, a periodic detent force, a cushion's drag, a
    cover's staircase, a gas spring, bolt holes, a plunger's drag, a sagging beam's pull,
    a festoon's tension and a curve's centripetal load. Here the levels fall linearly away
    from one point of the stroke on one side and change at another slope on the other: a
    kinked ramp whose kink is the chain's fixed end.
    """
    xc = _bump_centre(kin)
    if xc is None:
        raise ValueError(f"position (gliding_chain): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    if s <= 0.0:
        return _base_parts(kin)[0]
    span = _span(kin)
    g = _gliding(np.asarray(kin.x, float) / span, xc / span, CHAIN_BEND, CHAIN_ON_CHAIN,
                 CHAIN_ON_BARS)
    lev = np.clip(1.0 + float(s) * g, 0.05, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- inertia ---------------------------------------------------------------------------------
#: ``force_saturation``'s carriage mass, its inertial force at a99 x the friction level
#: [-]; the saturation's force scale at strength 1, x that inertial force [-]
SATURATION_INERTIA, SATURATION_FORCE = 3.0, 1.0


@on_fine_grid
def force_saturation_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is read as the motor current times the motor's nominal force constant,
    and the inverse dynamics subtracts the known inertial force m a (m a99 =
    :data:`SATURATION_INERTIA` x the friction level). At high currents the motor's iron
    saturates and its force constant falls: the current for the drive force F_d = F + m a
    reads as F_d sqrt(1 + ``s`` (F_d / F_sat)^2), F_sat = :data:`SATURATION_FORCE` x m a99.
    The record's force is that reading less m a.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the saturation's strength (the squared ratio of m a99 to the
        saturating force), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Magnetic saturation of linear and rotary permanent-magnet motors and the fall of their
    force (torque) constant at high currents (Gieras and Piech 2000, Linear Synchronous
    Motors, ch. 5; Hendershot and Miller 2010, Design of Brushless Permanent-Magnet
    Machines); force estimated from the motor current in identification. The candidate's
    mass is constant, varies in time, along the stroke or with the squared speed, or holds
    a coupled part that slips; the open forms filter, flex behind the sensor, gear, lose,
    add fluid mass, dispense, slide a payload, rattle a part, freewheel, carry a payload
    between zones, couple through eddies, flyweights or a fluid, pick up a stage or stand
    on a recoiling frame. Here the missed force grows with the cube of the drive force:
    no error at gentle accelerations, a large one at the peaks.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    Fd, m = _drive_force(kin, F, SATURATION_INERTIA)
    Fsat = SATURATION_FORCE * m * max(kin.scales["a99"], 1e-12)
    return F + Fd * (np.sqrt(1.0 + float(s) * (Fd / Fsat) ** 2) - 1.0)


# -- delay -----------------------------------------------------------------------------------
#: ``load_cell_creep``'s creep (the reading's change under a held force, over its share at
#: once) at strength 1 [-]; its time constant, x the motion's time scale [-]
CREEP, CREEP_TIME = 0.5, 1.0


@on_fine_grid
def load_cell_creep_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force read by a strain-gauge load cell whose spring element creeps
    anelastically (a standard anelastic solid): under a held force its reading rises by
    ``s`` :data:`CREEP` x what appeared at once, with the time constant tau =
    :data:`CREEP_TIME` x the motion's time scale; the cell is calibrated statically (after
    the creep). The reading is (F + c lag(F)) / (1 + c), c = ``s`` :data:`CREEP`
    (:func:`.truths._lag`): a share 1 / (1 + c) of each change of the force at once, the
    rest lagged.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the creep, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Anelasticity of metals (Zener 1948, Elasticity and Anelasticity of Metals); the creep
    of load cells and its test (OIML R60, Metrological regulation for load cells, creep
    and minimum dead load output return; Stefanescu 2011, Handbook of Force Transducers,
    ch. 2). The open forms delay by one amount, filter by a low-pass, linearly or by
    rank, hold at a fieldbus's clock, let the delay drift, wander or follow the force's
    rate, level or slowness, the motion's speed or the position, hold stale values over
    lost telegrams, lead through a leaking charge or shift the motion. Here the force
    arrives in two parts: a share at once, the rest late, so that its edges are sharp and
    its levels late.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    c = float(s) * CREEP
    tau = CREEP_TIME * max(_motion_time(kin), 1e-12)
    return (F + c * _lag(np.asarray(kin.t, float), F, tau)) / (1.0 + c)


# -- drift -----------------------------------------------------------------------------------
#: ``magnet_heating``'s carriage mass, its inertial force at a99 x the friction level [-];
#: the magnets' thermal time constant, x the record's length [-]; the reading's rise at
#: the record's mean square drive force, warmed through, at strength 1 [-]
HEAT_INERTIA, HEAT_TIME, HEAT_GAIN = 2.0, 0.4, 0.3


def _warming(t, P, tau):
    """The magnets' temperature rise [-] along the times ``t`` [s] under the losses ``P``
    [-]: tau dT/dt + T = P, from cold (0)."""
    from scipy.signal import lfilter
    e = math.exp(-float(t[1] - t[0]) / tau)
    return lfilter([1.0 - e], [1.0, -e], np.asarray(P, float))


@on_fine_grid
def magnet_heating_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is read as the motor current times the motor's force constant measured
    cold, and the inverse dynamics subtracts the known inertial force m a (m a99 =
    :data:`HEAT_INERTIA` x the friction level). The copper losses, ~ the drive force
    squared, F_d = F + m a (:func:`_drive_force`), warm the motor and its magnets (a first
    order lag of :data:`HEAT_TIME` x the record, from cold, :func:`_warming`); the magnets'
    remanence, and the force constant, fall with their temperature, so the current reads
    the drive force as F_d (1 + ``s`` :data:`HEAT_GAIN` x the temperature over its value
    for the record's mean square drive force). The record's force is that reading less
    m a: the friction and the inertial force alike drift up.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the magnets' temperature coefficient times the motor's
        thermal resistance, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The reversible temperature coefficient of NdFeB remanence (about -0.1 %/K; Campbell
    1994, Permanent Magnet Materials and their Application) and the thermal models of
    motors (Gieras and Piech 2000, Linear Synchronous Motors; a first-order thermal
    network). The candidate is a trend, a saturating change, a step, a cycle, an
    accelerating part and a part that builds up and resets, in time; the open forms warm
    up, wear in, step, cycle, rise and fall with debris, drop with grease shots, relax,
    oxidise, wear through, swell, grow a tribofilm, take in particles, expand or shear
    the oil. Here the measurement drifts, not the friction: paced by the drive's own
    losses, and scaling the inertial force as much as the friction.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    Fd, _ = _drive_force(kin, F, HEAT_INERTIA)
    P = Fd * Fd
    t = np.asarray(kin.t, float)
    theta = _warming(t, P, HEAT_TIME * max(float(t[-1] - t[0]), 1e-12))
    return F + float(s) * HEAT_GAIN * theta / max(float(np.mean(P)), 1e-300) * Fd


# -- backlash --------------------------------------------------------------------------------
#: ``bowden_cable``'s cable stretch between the Coulomb levels either way at strength 1, as
#: a share of the stroke [-] (a fifth of the open backlash forms' play); the friction of the
#: sheath over its whole wrap, mu Theta [-]; the cable's nodes [-]; its stiffness at
#: ``s`` = 0, x the stiff coupling's of the other forms [-]
CABLE_SHARE, CABLE_WRAP, CABLE_NODES, CABLE_STIFF = 0.2 * PLANT_GAP_SHARE, 1.2, 12, 10.0


@njit(cache=True)
def _bowden(h, xd, ks, c, mu, n_nodes, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a contact of mass ``m`` [kg] driven by the drive positions
    ``xd`` [m] (step ``h`` [s]) through a cable of ``n_nodes`` massless nodes in a sheath:
    ``n_nodes`` + 1 springs ``ks`` [N/m] (the last damped by ``c`` [N s/m]), each node held
    by the sheath's capstan friction, ``mu`` / ``n_nodes`` x its tension (push or pull),
    quasi-static: a node moves only as far as its springs' imbalance exceeds its friction
    (a play operator, one Gauss-Seidel sweep per step from the drive on). Semi-implicit
    Euler of the mass (:func:`.truths._light_contact_step`). Starts at rest, unloaded."""
    n = xd.size
    F = np.empty(n)
    y = np.zeros(n_nodes + 2)
    y[:] = xd[0]
    v = 0.0
    z = 0.0
    xc = xd[0]
    y_end = xd[0]
    share = mu / n_nodes
    for j in range(n):
        y[0] = xd[j]
        y[n_nodes + 1] = xc
        for i in range(1, n_nodes + 1):
            mid = 0.5 * (y[i - 1] + y[i + 1])
            tol = 0.5 * share * abs(0.5 * (y[i - 1] - y[i + 1]))
            if y[i] > mid + tol:
                y[i] = mid + tol
            elif y[i] < mid - tol:
                y[i] = mid - tol
        fc = ks * (y[n_nodes] - xc) + c * ((y[n_nodes] - y_end) / h - v)
        y_end = y[n_nodes]
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha, shape)
        xc = xc + h * v
    return F


@on_fine_grid
def bowden_cable_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact joined by a push-pull cable in a curved sheath (a Bowden cable, a
    tendon-sheath drive; :func:`_bowden`): the cable is elastic and the sheath holds it by
    capstan friction, mu Theta = :data:`CABLE_WRAP` over the whole wrap, spread over
    :data:`CABLE_NODES` nodes, each node's friction its share of mu Theta times its
    tension. Pulling (or pushing), the tension falls along the sheath towards the contact;
    after a reversal the cable's strain must unwind against the sheath's friction before
    the contact's end turns: a lost motion that grows with the force the cable held. The
    cable's stretch between the Coulomb levels either way is ``s``^2
    :data:`CABLE_SHARE` x the stroke (plus Fc / (:data:`CABLE_STIFF` kh), kh the stiff
    coupling of the other forms, :func:`.truths._contact_constants`). The contact is
    light, with the base's LuGre friction; the measured force is its friction. At ``s`` =
    0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the square root of the cable's stretch relative to
        :data:`CABLE_SHARE` x the stroke (as the open plays').

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Tendon-sheath (Bowden cable) transmission and its friction hysteresis and backlash
    (Kaneko, Yamashita and Tanie 1991, Basic considerations on transmission
    characteristics for tendon drive robots, ICAR; Agrawal et al. 2010, Modeling of
    transmission characteristics across a cable-conduit system, IEEE Trans. Robot. 26);
    the capstan equation (Euler 1762; Eytelwein). The candidate holds or frees the force
    across a play, with a bias, a spring or a drag across it; the open forms couple
    rigidly, compliantly, by impacts, springs, oil in the play, an idler, a bias, chains,
    magnets, a preload, a hardening gear, a slipping rope, a rubber spider or an oil
    column, with a play varying with the position or the travel. Here the lost motion is
    made by friction spread along the link: the drive's end turns at once, the contact's
    only once the whole cable has unwound, and the dead travel scales with the force.
    """
    p = _lugre_params(kin, "backlash (bowden_cable)")
    if s <= 0.0:
        return _base_parts(kin)[0]
    m, kh, _ = _contact_constants(kin, p)
    Fc = float(p.Fc)
    lost = float(s) ** 2 * CABLE_SHARE * float(np.ptp(kin.x))
    k = Fc / (0.5 * lost + Fc / (CABLE_STIFF * kh))       # the whole cable's stiffness
    ks = (CABLE_NODES + 1) * k
    c = 2.0 * 0.5 * math.sqrt(ks * m)
    h, xd, n_sub = _substeps(kin, max(math.sqrt((ks + float(p.sigma0)) / m),
                                      (float(p.sigma1) + float(p.sigma2) + c) / m))
    F = _bowden(h, xd, ks, c, CABLE_WRAP, CABLE_NODES, m, float(p.sigma0), float(p.sigma1),
                float(p.sigma2), Fc, float(p.Fs), float(p.vs), float(p.alpha),
                SHAPES[p.shape])
    return F[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: the micro-contacts' elastic travel to full slip at the mean load at strength 1, beyond
#: the base bristle's path, as a share of the stroke / 3 [-]; their share of the friction
#: at strength 1 [-]; the micro-contacts (Iwan elements) [-]
MICROSLIP_SHARE, CONTACT_SHARE, MICRO_CONTACTS = 0.1, 0.7, 12


@njit(cache=True)
def _microslip(x, r, ud, n_el):
    """The micro-contacts' force f [-] (over their sliding level at the mean load) along the
    positions ``x`` [m] and relative normal loads ``r`` [-] (>= 0): ``n_el`` elements,
    element j (1 to ``n_el``) slipping at the force r / ``n_el`` after the travel ``ud`` j
    / ``n_el`` at r = 1 [m]; their tangential stiffness ~ r^(1/3) (Hertz-Mindlin); each
    element's force changes with the stiffness times the travel and is clipped to its
    present slip limit, so a falling load makes it slip where it stands. Starts
    unloaded."""
    n = x.size
    q = np.zeros(n_el)
    out = np.empty(n)
    out[0] = 0.0
    for k in range(1, n):
        rk = max(r[k], 0.0)
        cap = rk / n_el
        stiff = rk ** (1.0 / 3.0) * (x[k] - x[k - 1])
        tot = 0.0
        for j in range(n_el):
            qj = q[j] + stiff / (ud * (j + 1.0))
            if qj > cap:
                qj = cap
            elif qj < -cap:
                qj = -cap
            q[j] = qj
            tot += qj
        out[k] = tot
    return out


@on_fine_grid
def unloading_microslip_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The presliding junctions beside the bristle are Hertzian micro-contacts in partial
    slip whose slip limits follow the normal load: a discrete Iwan set of
    :data:`MICRO_CONTACTS` elements (:func:`_microslip`) whose slip forces are the relative
    load r = L / mean(L) times their share and whose stiffness is ~ r^(1/3). When the load
    falls at a standing position the elements at their limit slip and lose the force
    they held; when it rises again they do not get it back until the travel reloads them
    (Mindlin and Deresiewicz's dependence on the loading path). The elastic travel to
    full slip at the mean load is the base bristle's path Fs / sigma0 plus ``s``
    :data:`MICROSLIP_SHARE` x the stroke / 3; a share w = :data:`CONTACT_SHARE` min(``s``,
    1) of the friction is theirs (their sliding force the Stribeck level times r, the
    viscous term the base's): F = (1 - w) F_lugre + w (g(v) f + sigma2 v). At ``s`` = 0 the
    base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s], load [N]) and its base law (a classic
        LuGre).
    s : float
        Amplitude factor [-]: the micro-contacts' share (up to ``s`` = 1) and their elastic
        travel (as the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Elastic spheres in contact under varying oblique forces (Mindlin and Deresiewicz 1953,
    J. Appl. Mech. 20; Johnson 1985, Contact Mechanics, ch. 7); microslip of joints under
    varying clamping (Iwan 1966, A distributed-element model for hysteresis, J. Appl.
    Mech. 33; Segalman 2005). Maxwell-slip (the candidate) and the open forms follow
    Masing's rule, path laws, an elastic range, rate-dependent creep, multistable tips,
    bonds, a fabric, a back-stress, a climb out of a nest, capillary bridges, a hardening
    yield or peeling junctions, all at a fixed normal load; here the presliding state is
    erased by the normal load's falls, not only by the travel.
    """
    p = _lugre_params(kin, "gms (unloading_microslip)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, MICROSLIP_SHARE)
    w = CONTACT_SHARE * min(float(s), 1.0)
    v = np.asarray(kin.v, float)
    L = np.asarray(kin.load, float)
    r = L / max(float(np.mean(L)), 1e-300)
    f = _microslip(np.ascontiguousarray(kin.x, dtype=float), np.ascontiguousarray(r),
                   e0 + extra, MICRO_CONTACTS)
    return (1.0 - w) * F + w * (kin.base.g(v) * f + float(p.sigma2) * v)
