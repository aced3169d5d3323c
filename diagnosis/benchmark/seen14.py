"""The fourteenth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-29 (session 19) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 20's work on the code of 0487306:
176 cases, 0 skipped, 758 s wall on 1 worker (beside a 2-worker grid run). Top-1 36.4 % (64;
40.5 % of the 158 detectable; 14 delay cases below a sample); mean |shrink error| 0.341;
wrong names on 31 (17.6 %): delay -> inertia 7, delay -> position 4, acceleration ->
asymmetry 4, drift -> load 3, acceleration -> position 3, asymmetry -> acceleration 2,
gms -> acceleration 2. By form: load/normal_stress_memory 20/20,
asymmetry/hall_commutation 12/20, drift/shear_degradation 12/20,
stribeck_shape/turbulent_film 7/16, inertia/frame_recoil 7/20,
acceleration/payne_softening 4/20, gms/junction_peeling 2/12, position/curved_guide 0/16,
delay/charge_leakage 0/20, backlash/hydraulic_link 0/12. By plant: XML-350 45.0 %, press
42.9 %, isolator 39.3 %, valve 32.5 %, damping rig 25.0 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen13` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen13`,
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
acceleration       ``payne_softening``: the guide's bushings sit in filled-elastomer
                   O-rings whose squeeze sets their preload; the carriage's inertial
                   force shears them, and the filled rubber's stiffness falls with the
                   strain amplitude (the filler network breaks: Payne 1962; Kraus 1984)
                   and recovers as the network re-forms: the levels fall with the
                   envelope of |a| (fast attack, slow recovery), not with |a| itself
load               ``normal_stress_memory``: the friction follows the normal load
                   (Amontons), but the contact's state responds to a change of the load
                   only in part at once and renews over a slip distance (Linker and
                   Dieterich 1992; Prakash 1998): after each change of the load the
                   levels lag its share alpha / mu, paced by the travel, both ways
asymmetry          ``hall_commutation``: the force is read from the motor current of a
                   brushless drive commutated by Hall sensors; their mounting offset, the
                   latches' hysteresis and their delay shift the commutation angle in
                   the direction of travel (Krishnan 2010), so the force per ampere
                   differs with the direction: friction and the inverse dynamics'
                   inertial force are scaled by cos d0 / cos(d0 + d(v))
stribeck_shape     ``turbulent_film``: a low-viscosity (water, coolant) film beside the
                   contact whose Couette flow turns turbulent above a critical Reynolds
                   number (Taylor 1923; Smith and Fuller 1956): its shear, laminar ~ v
                   below, grows as Re^0.75 beyond (Constantinescu 1959; Hirs 1973): a
                   drag whose slope steepens at a speed, v^1.75 at the top
position           ``curved_guide``: the track has a curved segment (an arc between two
                   clothoids) where the carriage's centripetal force m v^2 / R presses
                   its rollers onto the outer rail: the levels rise in the curve with the
                   curvature and the squared speed, nothing on the straights or at rest
inertia            ``frame_recoil``: the axis' frame stands on soft mounts and the
                   encoder reads the carriage against it: the drive's reaction makes the
                   frame recoil (a mass on its isolators, lightly damped), and the
                   inverse dynamics misses the carriage's mass times the frame's
                   acceleration: no error at low frequencies, ringing at the frame's
                   mode, a negative mass error above it
delay              ``charge_leakage``: the force read by a piezoelectric sensor through a
                   charge amplifier whose feedback resistor lets the charge leak (the
                   time constant R C, Gautschi 2002): a first-order high-pass from the
                   reset at the record's start: held forces droop and the force leads the
                   motion (a high-pass's phase, the opposite of a delay), more the slower
                   the motion
drift              ``shear_degradation``: the lubricant's polymer viscosity improver is
                   broken by the contact's shear (mechanical scission, Covitch 1998;
                   Bartz 2000): the viscosity falls with the shear-weighted travel towards
                   the base oil's, the film thins, the boundary levels rise and the
                   viscous term falls: a drift of the travel and the speed, two ways at
                   once
backlash           ``hydraulic_link``: drive and contact joined by an oil column (a
                   master-slave cylinder pair, a hydrostatic transmission): the oil's
                   compressibility (a damped spring) in series with the leakage past the
                   pistons (a dashpot, Merritt 1967): after each reversal the force
                   builds through the oil, and a held force leaks away: the contact
                   creeps behind the drive and stalls where the drive is slower than the
                   leak
gms                ``junction_peeling``: adhesive asperity junctions beside the bristle
                   whose real contact area shrinks under the shear force (Savkoor and
                   Briggs 1977; Sahli et al. 2018) and re-adheres only as the force
                   falls back (adhesion hysteresis, Chaudhury and Whitesides 1991): the
                   stiffness follows the area: loading softens, unloading is stiff and
                   linear down to the re-adhesion, not Masing's doubled curve; at ``s``
                   = 0 the base itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``turbulent_film`` needs a
Stribeck curve (not the isolator's mre_lugre), ``curved_guide`` a record that revisits its
positions (not the press), ``normal_stress_memory`` a load that changes,
``hydraulic_link`` and ``junction_peeling`` a classic LuGre base (valve, damping rig,
XML-350); each raises a ``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.shapes import SHAPES

from ..effects_backlash import PLANT_GAP_SHARE
from .kinematics import PlantKinematics
from .seen11 import _direction
from .seen13 import _travel
from .truths import (_base_parts, _bump_centre, _contact_constants, _lag, _level,
                     _light_contact_step, _lugre_params, _motion_time, _presliding_path,
                     _span, _substeps, level_inside, on_fine_grid)

__all__ = ["FORMS", "payne_softening_truth", "normal_stress_memory_truth",
           "hall_commutation_truth", "turbulent_film_truth", "curved_guide_truth",
           "frame_recoil_truth", "charge_leakage_truth", "shear_degradation_truth",
           "hydraulic_link_truth", "junction_peeling_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "payne_softening", "load": "normal_stress_memory",
         "asymmetry": "hall_commutation", "stribeck_shape": "turbulent_film",
         "position": "curved_guide", "inertia": "frame_recoil",
         "delay": "charge_leakage", "drift": "shear_degradation",
         "backlash": "hydraulic_link", "gms": "junction_peeling"}


# -- acceleration ---------------------------------------------------------------------------
#: ``payne_softening``'s critical strain amplitude of the filler network, as a share of the
#: O-rings' shear at a99 [-]; Kraus's exponent [-]; the network's re-forming time, x the
#: motion's time scale [-]; the levels' fall with the network fully broken at strength 1
#: [-]; the lowest relative level [-]
PAYNE_STRAIN, KRAUS_EXPONENT, PAYNE_RECOVERY, PAYNE_DROP, PAYNE_FLOOR = \
    0.3, 0.6, 2.0, 0.6, 0.05


@njit(cache=True)
def _strain_envelope(t, u, tau):
    """The strain amplitude [-] the filler network has seen along the times ``t`` [s] of the
    relative strains ``u`` [-] (>= 0): it breaks at once up to a new amplitude and re-forms
    with the time constant ``tau`` [s] (a peak detector with exponential release). Starts
    at the first strain."""
    n = u.size
    out = np.empty(n)
    e = u[0]
    out[0] = e
    for k in range(1, n):
        e = e * math.exp(-(t[k] - t[k - 1]) / tau)
        if u[k] > e:
            e = u[k]
        out[k] = e
    return out


def _payne_loss(e, critical, m):
    """The share [-] of the filled rubber's stiffness the filler network has lost at the
    strain amplitudes ``e`` [-] (Kraus 1984: G = G_inf + (G_0 - G_inf) / (1 + (e / e_c)^2m),
    the loss of the network's part x / (1 + x), x = (``e`` / ``critical``)^(2 ``m``))."""
    x = (np.asarray(e, float) / critical) ** (2.0 * m)
    return x / (1.0 + x)


@on_fine_grid
def payne_softening_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The guide's plain bushings are mounted in filled-elastomer O-rings (self-aligning
    mounts) whose squeeze sets the bushings' preload on their shafts. The carriage's
    inertial force passes through the O-rings and shears them, with an amplitude ~ |a|:
    the carbon-black network of the filled rubber breaks at once as the amplitude grows
    and re-forms over :data:`PAYNE_RECOVERY` x the motion's time scale
    (:func:`_strain_envelope` of |a| / a99), and the rubber's stiffness falls with that
    amplitude (the Payne effect, :func:`_payne_loss`, critical amplitude
    :data:`PAYNE_STRAIN`). The squeeze is fixed, so the preload, and the Coulomb and
    Stribeck levels, are the base's times 1 - ``s`` :data:`PAYNE_DROP` x the stiffness lost
    (at least :data:`PAYNE_FLOOR`), inside the bristle dynamics; the viscous term is the
    base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the filler network's share of the O-rings' stiffness
        (their preload lost when it is broken), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The strain-amplitude dependence of filled rubber (Payne 1962, The dynamic properties
    of carbon black-loaded natural rubber vulcanizates, J. Appl. Polym. Sci. 6; Kraus 1984,
    Mechanical losses in carbon-black-filled rubbers, J. Appl. Polym. Sci. Appl. Polym.
    Symp. 39); elastomer O-ring mounts of self-aligning linear bushings. The candidate adds
    a force odd in a fading with the speed and raises the levels with |a|, lagged; the
    open forms lag the velocity, a film or a contact state, heat the contact, skid rolling
    elements, move load between rows or supports, press seals, pull with the thrust,
    squeeze films, starve the contact, dilate it, lift it on a wedge or shift a gib. Here
    the levels follow the largest acceleration of the recent past: down at once with a
    new peak, back slowly, the same at a's zero crossings as at its peaks.
    """
    t = np.ascontiguousarray(kin.t, dtype=float)
    u = np.ascontiguousarray(np.abs(np.asarray(kin.a, float)) /
                             max(kin.scales["a99"], 1e-12))
    e = _strain_envelope(t, u, PAYNE_RECOVERY * max(_motion_time(kin), 1e-12))
    lev = 1.0 - max(float(s), 0.0) * PAYNE_DROP * _payne_loss(e, PAYNE_STRAIN,
                                                              KRAUS_EXPONENT)
    return level_inside(kin, np.clip(lev, PAYNE_FLOOR, None), np.ones_like(lev))


# -- load -------------------------------------------------------------------------------------
#: ``normal_stress_memory``'s share alpha / mu of a change of the (log) load the contact's
#: state does not follow at once [-]; the slip distance over which it renews, x the
#: record's travel [-]; the least load the state's logarithm reads, x the mean load [-];
#: the lowest relative level [-]
STATE_SHARE, RENEWAL_PATH, LOAD_FLOOR, STRESS_FLOOR = 0.4, 0.03, 0.05, 0.05


@njit(cache=True)
def _renewal(path, lnL, dc):
    """The contact state's deviation psi [-] (b ln(theta / theta_ss) / alpha) along the
    sliding ``path`` [m] and log loads ``lnL`` [-]: a change of ``lnL`` moves it by as
    much at once, against its sign, and it relaxes to 0 over the slip distance ``dc`` [m]
    (Linker and Dieterich's normal-stress term in the aging law, linearised at steady
    sliding), psi = - (``lnL`` high-passed in the slip). Starts at 0."""
    n = lnL.size
    out = np.empty(n)
    psi = 0.0
    out[0] = 0.0
    for k in range(1, n):
        psi = psi - (lnL[k] - lnL[k - 1])
        psi = psi * math.exp(-(path[k] - path[k - 1]) / dc)
        out[k] = psi
    return out


@on_fine_grid
def normal_stress_memory_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Friction proportional to the normal load (Amontons: tau = mu sigma) whose coefficient
    carries the contact's state: a change of the load changes the state at once by
    - alpha / b x its log change, and the state then renews over the slip distance D_c
    (Linker and Dieterich 1992; :func:`_renewal`). The friction follows L / L0 x (1 +
    :data:`STATE_SHARE` psi), L0 the mean load, psi the state's deviation (the log load
    high-passed in the slip, :data:`RENEWAL_PATH` x the record's travel; the log reads at
    least :data:`LOAD_FLOOR` x L0): at once by 1 - :data:`STATE_SHARE` of a change, the rest
    over D_c. The Coulomb and Stribeck levels are the base's times 1 + ``s`` (L / L0 (1 +
    :data:`STATE_SHARE` psi) - 1) (at least :data:`STRESS_FLOOR`), inside the bristle
    dynamics; the viscous term is the base's. ValueError if the load does not change.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s], load [N]) and its base law.
    s : float
        Amplitude factor [-]: the load-proportional share of the friction, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Rate-and-state friction under variable normal stress (Linker and Dieterich 1992,
    Effects of variable normal stress on rock friction, J. Geophys. Res. 97; Prakash 1998,
    Frictional response of sliding interfaces subjected to time varying normal pressures,
    J. Tribol. 120; Richardson and Marone 1999). The candidate's levels are affine in the
    load; the open forms are powers, one direction, square-root and exponential viscous
    terms, the Stribeck velocity, a logistic step, a creep in time, the load's rate, a
    play, a ratchet with the travel, a hinge, a lag while it rises, a saturating area, a
    flash temperature and a relay. Here the load acts at once in part and the rest over a
    slip distance, rising and falling alike, paced by the travel, not the clock.
    """
    L = np.asarray(kin.load, float)
    L0 = float(np.mean(np.abs(L)))
    # a change below 1e-6 of the mean load over the record is round-off, not a change
    if L0 <= 0.0 or float(np.ptp(L)) <= 1e-6 * L0:
        raise ValueError(f"load (normal_stress_memory): the {kin.plant} record's load does "
                         f"not change")
    path = _travel(kin)
    rel = np.maximum(L, 0.0) / L0
    lnL = np.log(np.maximum(rel, LOAD_FLOOR))
    psi = _renewal(path, np.ascontiguousarray(lnL),
                   RENEWAL_PATH * max(float(path[-1]), 1e-300))
    lev = 1.0 + max(float(s), 0.0) * (rel * (1.0 + STATE_SHARE * psi) - 1.0)
    return level_inside(kin, np.clip(lev, STRESS_FLOOR, None), np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``hall_commutation``'s Hall board mounting offset [rad, electrical]; the latches'
#: hysteresis and delay at low speed, and the delay's extra lag at v99, at strength 1 [rad,
#: electrical]; the moving mass's inertial force at a99, x the friction level [-]; the
#: largest commutation angle [rad]
HALL_OFFSET, HALL_HYSTERESIS, HALL_LAG, HALL_INERTIA, HALL_LIMIT = \
    math.radians(20.0), math.radians(11.0), math.radians(8.0), 1.0, math.radians(80.0)


def _force_per_ampere(angle, offset):
    """The drive's force per ampere [-] at the commutation angles ``angle`` [rad], over its
    value at the mounting offset ``offset`` [rad] (where it was calibrated): cos(angle) /
    cos(offset), the torque of block currents against a sinusoidal back-EMF whose
    commutation is off by ``angle``."""
    return np.cos(np.asarray(angle, float)) / math.cos(offset)


@on_fine_grid
def hall_commutation_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is read as the motor current of a brushless drive times its calibrated
    force constant, and the inverse dynamics subtracts the known inertial force m a. The
    motor is commutated by Hall sensors: mounted :data:`HALL_OFFSET` off, their latches
    switch late in the direction of travel (their magnetic hysteresis and delay, ``s``
    :data:`HALL_HYSTERESIS` either way, the direction rounded over 2 % of v99) and later
    still with the speed (the delay's angle, ``s`` :data:`HALL_LAG` at v99), within
    +-:data:`HALL_LIMIT`. The force per ampere is c = cos of that angle over its calibrated
    value (:func:`_force_per_ampere`), so the current of the true drive force F + m a reads
    as (F + m a) / c: the record's force is (F + m a) / c - m a, with m a99 =
    :data:`HALL_INERTIA` x the friction level.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the Hall latches' angle errors (hysteresis and delay), / their
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Hall-sensor commutation of brushless motors and its angle errors (Krishnan 2010,
    Permanent Magnet Synchronous and Brushless DC Motor Drives; the Hall latches' operate
    and release points); force estimated from the motor current in identification (the EMPS
    benchmark's force, its motor current times a gain). The candidate shifts a direction's
    levels and viscous slope (and an offset); the open forms keep a direction's share, its
    Stribeck velocity, viscous slope or tail, roll a lip, follow a thrust, a film laid by
    the outstroke, a texture, a return spring, a wedge film, a strut, a throttle, a
    cylinder's areas, pumping grooves, a buckling cable or a scraper's pile. Here the
    measurement's scale differs with the direction: the friction and the inertial force
    alike, more with the speed one way, less the other.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    m = HALL_INERTIA * _level(kin) / max(kin.scales["a99"], 1e-12)
    angle = HALL_OFFSET + float(s) * (HALL_HYSTERESIS * _direction(kin)
                                      + HALL_LAG * np.asarray(kin.v, float) / v99)
    c = _force_per_ampere(np.clip(angle, -HALL_LIMIT, HALL_LIMIT), HALL_OFFSET)
    ma = m * np.asarray(kin.a, float)
    return (F + ma) / c - ma


# -- stribeck_shape --------------------------------------------------------------------------
#: ``turbulent_film``'s laminar drag at v99 at strength 1, x the friction level [-]; the
#: speed where the film turns turbulent (its critical Reynolds number), x v99 [-]; the
#: turbulent shear's exponent of the Reynolds number [-]; the sharpness of the transition
#: [-]
TURB_DRAG, TURB_ONSET, TURB_EXPONENT, TURB_SHARPNESS = 0.3, 0.3, 0.75, 4.0


def _turbulent_shear(u, onset, exponent, sharpness):
    """The film's Couette shear [-] at the relative speeds ``u`` [-] (over v99), over its
    laminar shear at v99: laminar u below the critical speed ``onset`` [-], u (|u| /
    ``onset``)^``exponent`` beyond (the turbulent shear factor ~ Re^``exponent``), joined
    by a p-norm of sharpness ``sharpness``; odd in ``u``."""
    u = np.asarray(u, float)
    r = np.abs(u) / onset
    return u * (1.0 + r ** (exponent * sharpness)) ** (1.0 / sharpness)


@on_fine_grid
def turbulent_film_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A film of a low-viscosity lubricant (water, a coolant) between the carriage and a
    second surface beside its contact (a water-lubricated slideway pad): its Couette shear
    is laminar, ~ v, up to the critical Reynolds number, at :data:`TURB_ONSET` x v99, and
    turbulent beyond, the shear factor growing as Re^:data:`TURB_EXPONENT`
    (:func:`_turbulent_shear`). The film's drag is added to the base's force, ``s``
    :data:`TURB_DRAG` x the friction level at v99 were it laminar there.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (a Stribeck curve).
    s : float
        Amplitude factor [-]: the film's wetted area (its laminar drag), / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The onset of Taylor vortices and turbulence in a sheared film (Taylor 1923, Stability
    of a viscous liquid contained between two rotating cylinders, Phil. Trans. R. Soc. A
    223; Smith and Fuller 1956, Journal-bearing operation at superlaminar speeds, Trans.
    ASME 78); turbulent lubrication (Constantinescu 1959, On turbulent lubrication, Proc.
    Inst. Mech. Eng. 173; Hirs 1973, A bulk-flow theory for turbulence in lubricant
    films, J. Lubr. Technol. 95). The candidate bends the base's drop (an exponent, the
    Lorentzian, a log-speed map); the open forms add tails, drops, a spike, a lift-off, a
    second drop, logarithmic weakening, Eyring strengthening, a rise at the top speed, a
    hump, a notch, a dither, a melt, a granular rise, re-adsorption and thermal thinning.
    Here a viscous drag whose slope steepens at a speed: a change of the flow's regime,
    not of the contact's.
    """
    if kin.base.name == "mre_lugre":
        raise ValueError("stribeck_shape (turbulent_film): the mre_lugre base has no "
                         "Stribeck curve")
    F, _ = _base_parts(kin)
    u = np.asarray(kin.v, float) / max(kin.scales["v99"], 1e-12)
    drag = _turbulent_shear(u, TURB_ONSET, TURB_EXPONENT, TURB_SHARPNESS)
    return F + max(float(s), 0.0) * TURB_DRAG * _level(kin) * drag


# -- position --------------------------------------------------------------------------------
#: ``curved_guide``'s arc of constant curvature and each clothoid leading into it, x the
#: stroke the record visits [-]; the normal load the centripetal force adds at v99 on the
#: arc at strength 1, x the load on the straights [-]
ARC_SHARE, CLOTHOID_SHARE, CURVE_LOAD = 0.2, 0.1, 1.0


def _curvature(x, centre, arc, clothoid):
    """The track's curvature [-] at the positions ``x`` [m], over the arc's: 1 on the arc of
    length ``arc`` [m] around ``centre`` [m], rising linearly with the length along each
    clothoid of ``clothoid`` [m] before and after it (a clothoid's curvature is linear in
    its length), 0 on the straights."""
    d = np.abs(np.asarray(x, float) - centre) - 0.5 * arc
    return np.clip(1.0 - d / clothoid, 0.0, 1.0)


@on_fine_grid
def curved_guide_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage runs on a track with a curved segment (a transport system's track, a
    curved profile rail): an arc of :data:`ARC_SHARE` x the stroke the record visits,
    centred where fit and held-out parts both pass (:func:`.truths._bump_centre`), between
    clothoids of :data:`CLOTHOID_SHARE` x the stroke each (:func:`_curvature`). Along the
    curve the carriage's centripetal force m v^2 / R presses its rollers onto the outer
    rail: their normal load, and with it the Coulomb and Stribeck levels, are the base's
    times 1 + ``s`` :data:`CURVE_LOAD` x the relative curvature x (v / v99)^2, inside the
    bristle dynamics; the viscous term is the base's. Nothing on the straights, nothing
    at rest.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the carriage's mass over the arc's radius (its centripetal
        load at v99), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Centripetal loads of vehicles on curved tracks and their transition curves (the
    clothoid, Euler's spiral, of railway alignment); curved profile-rail guides, ring slides
    and the track systems of linear transport, whose rollers carry the centripetal force.
    The candidate scales the friction along the stroke and adds a periodic and a smooth
    force of x; the open forms are level maps, a periodic detent force, a cushion's drag, a
    cover's staircase, a gas spring, bolt holes, a plunger's drag, a sagging beam's pull and
    a festoon's tension. Here the levels depend on the position and the squared speed
    together: a bump along the stroke that is there only in fast passes.
    """
    xc = _bump_centre(kin)
    if xc is None:
        raise ValueError(f"position (curved_guide): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    span = _span(kin)
    kappa = _curvature(kin.x, xc, ARC_SHARE * span, CLOTHOID_SHARE * span)
    u = np.asarray(kin.v, float) / max(kin.scales["v99"], 1e-12)
    lev = 1.0 + max(float(s), 0.0) * CURVE_LOAD * kappa * u * u
    return level_inside(kin, lev, np.ones_like(lev))


# -- inertia ---------------------------------------------------------------------------------
#: ``frame_recoil``'s carriage mass at strength 1, x the friction level / a99 [kg per N
#: s^2/m]; the carriage's share of the mass the frame's isolators carry, m / (M + m) [-];
#: the frame's natural angular frequency on its isolators, x 1 / the motion's time scale
#: [-]; its damping ratio [-]
FRAME_CARRIAGE, FRAME_SHARE, FRAME_FREQUENCY, FRAME_DAMPING = 3.0, 0.4, 3.0, 0.05


def _frame_acceleration(t, a, share, wn, zeta):
    """The frame's acceleration [m/s^2] along the times ``t`` [s] when the carriage's
    relative accelerations ``a`` [m/s^2] drive it through the reaction: x_f'' + 2 ``zeta``
    ``wn`` x_f' + ``wn``^2 x_f = -``share`` a (the frame and the carriage on the
    isolators, the drive's force between them); linear in ``a``, from rest."""
    from scipy.signal import lsim
    _, y, _ = lsim(([-share, 0.0, 0.0], [1.0, 2.0 * zeta * wn, wn * wn]),
                   np.asarray(a, float), np.asarray(t, float))
    return np.asarray(y, float)


@on_fine_grid
def frame_recoil_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The axis' frame (its base with the stator and the encoder's scale) stands on soft
    isolators, and the motion is read relative to it. The drive's force acts between the
    carriage (mass m) and the frame: the frame recoils, a mass on its isolators (natural
    frequency :data:`FRAME_FREQUENCY` / the motion's time scale, damping ratio
    :data:`FRAME_DAMPING`), driven by the reaction with the carriage's share m / (M + m)
    = :data:`FRAME_SHARE` (:func:`_frame_acceleration`). The carriage's absolute
    acceleration is the measured one plus the frame's, so the inverse dynamics, which
    takes m times the measured, misses m x_f'': added to the base's force, m = ``s``
    :data:`FRAME_CARRIAGE` x the friction level / a99.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the carriage's mass (the frame's in proportion), / its value
        at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Reaction forces of high-acceleration stages on their machine frames and their
    isolation (Butler 2011, Position control in lithographic equipment, IEEE Control
    Syst. Mag. 31; Rivin 2003, Passive Vibration Isolation); relative position
    measurement against a moving base. The candidate's mass is constant, varies in time,
    along the stroke or with the squared speed, or holds a coupled part that slips; the
    open forms filter, flex behind the sensor, gear, lose, add fluid mass, dispense, slide
    a payload, rattle a part, freewheel, carry a payload between zones, couple through
    eddies, flyweights or a fluid, or pick up a stage. Here the missed force comes from
    the motion of what the measurement stands on: nothing at low frequencies, the frame's
    ringing, and a *negative* mass above its mode.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    T = max(_motion_time(kin), 1e-12)
    m = float(s) * FRAME_CARRIAGE * _level(kin) / max(kin.scales["a99"], 1e-12)
    af = _frame_acceleration(kin.t, kin.a, FRAME_SHARE, FRAME_FREQUENCY / T, FRAME_DAMPING)
    return F + m * af


# -- delay -----------------------------------------------------------------------------------
#: ``charge_leakage``'s charge amplifier time constant at strength 1, x the record's length
#: [-]
LEAK_TIME = 0.4


@on_fine_grid
def charge_leakage_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force read by a piezoelectric force sensor through a charge amplifier: its
    feedback resistor lets the charge leak with the time constant tau = R C, a first-order
    high-pass of the force's change since the amplifier was reset, at the record's start
    (the reading referred to the force there): F(t0) + (F - F(t0)) - its first-order lag
    (:func:`.truths._lag`). tau = :data:`LEAK_TIME` x the record's length / ``s`` (an
    amplifier in its long mode, its time constant a fraction of the record): at ``s`` = 0
    the force itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the leak's rate (1 / (R C)), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Piezoelectric force measurement and the charge amplifier's time constant, which limits
    quasi-static measurement (Gautschi 2002, Piezoelectric Sensorics; the charge amplifiers'
    short and long time-constant modes). The open forms delay by one amount, filter by a
    low-pass, linearly or by rank, hold at a fieldbus's clock, let the delay drift, wander
    or follow the force's rate, level or slowness, the motion's speed or the position, hold
    stale values over lost telegrams, or shift the motion: every one of them lags. Here the
    force leads the motion (a high-pass's phase), and what it holds, it loses.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    t = np.asarray(kin.t, float)
    tau = LEAK_TIME * max(float(t[-1] - t[0]), 1e-12) / float(s)
    return F - _lag(t, F - F[0], tau)


# -- drift -----------------------------------------------------------------------------------
#: ``shear_degradation``'s shear-weighted travel over which the polymer is broken, x the
#: record's [-]; the log viscosity lost when it is broken at strength 1 [-]; the boundary
#: levels' exponent of the viscosity lost (the film's ~ eta^0.7) [-]
SHEAR_LIFE, SHEAR_LOSS, FILM_EXPONENT = 0.35, 0.5, 0.7


def _sheared(t, v, v99):
    """The shear-weighted travel [m] along the times ``t`` [s] and velocities ``v`` [m/s]:
    the passes through the contact (|v| dt) weighted by the shear rate (|v| / ``v99``),
    from 0."""
    w = np.asarray(v, float) ** 2 / v99
    return np.concatenate(([0.0], np.cumsum(0.5 * (w[1:] + w[:-1]) * np.diff(t))))


@on_fine_grid
def shear_degradation_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A lubricant thickened by a polymer viscosity improver whose chains the contact's
    shear breaks: the polymer's degradation D = 1 - exp(-W / W_c), W the shear-weighted
    travel (:func:`_sheared`), W_c = :data:`SHEAR_LIFE` x its value over the record. The
    viscosity falls as eta / eta_0 = exp(-``s`` :data:`SHEAR_LOSS` D) towards the base
    oil's; the film thins with it (~ eta^:data:`FILM_EXPONENT`) and the asperities carry
    more: the Coulomb and Stribeck levels are the base's times (eta_0 /
    eta)^:data:`FILM_EXPONENT`, the viscous term the base's times eta / eta_0, inside the
    bristle dynamics.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the polymer's share of the viscosity (its log, lost when
        broken), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Permanent viscosity loss of polymer-thickened oils by mechanical scission (Covitch
    1998, How polymer architecture affects permanent viscosity loss of multigrade
    lubricants, SAE 982638; Bartz 2000, Influence of viscosity index improver, molecular
    weight, and base oil on thickening, shear stability, and evaporation losses of
    multigrade oils, Lubr. Sci. 12; the KRL shear test, CEC L-45). The candidate is a
    trend, a saturating change, a step and a cycle in time; the open forms warm up, wear
    in, step, cycle, rise and fall with debris, drop with grease shots, relax, oxidise,
    wear through, swell, grow a tribofilm, take in particles or expand. Here the levels
    rise and the viscous term falls together, as the fast travel, not the clock, breaks
    the oil.
    """
    t = np.asarray(kin.t, float)
    W = _sheared(t, kin.v, max(kin.scales["v99"], 1e-12))
    D = 1.0 - np.exp(-W / (SHEAR_LIFE * max(float(W[-1]), 1e-300)))
    loss = max(float(s), 0.0) * SHEAR_LOSS * D
    return level_inside(kin, np.exp(FILM_EXPONENT * loss), np.exp(-loss))


# -- backlash --------------------------------------------------------------------------------
#: the oil column's compression between the Coulomb levels either way in ``hydraulic_link``
#: at strength 1, as a share of the stroke [-] (a fifth of the open backlash forms' play);
#: the pistons' leakage speed at the Coulomb level at strength 1, x v99 [-]; the column's
#: stiffness at ``s`` = 0, x the stiff coupling's of the other forms [-]
COMPRESSION_SHARE, LEAK_SPEED, LINK_STIFF = 0.2 * PLANT_GAP_SHARE, 0.1, 10.0


@njit(cache=True)
def _oil_link(h, xd, k, c, cl, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a contact of mass ``m`` [kg] driven by the drive positions
    ``xd`` [m] (step ``h`` [s]) through an oil column: its compression d (a spring ``k``
    [N/m] damped by ``c`` [N s/m]) in series with the leakage past the pistons (a dashpot
    ``cl`` [N s/m]): the force F = (k d + c (vd - v)) / (1 + c / ``cl``), d' = vd - v - F /
    ``cl``; tension and compression alike (a double-acting pair). Semi-implicit Euler of
    the mass (:func:`.truths._light_contact_step`). Starts at rest, unloaded."""
    n = xd.size
    F = np.empty(n)
    v = 0.0
    z = 0.0
    d = 0.0
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        fc = (k * d + c * (vd - v)) / (1.0 + c / cl)
        d = d + h * (vd - v - fc / cl)
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha, shape)
    return F


@on_fine_grid
def hydraulic_link_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact joined by an oil column (a master-slave cylinder pair, a
    hydrostatic transmission; :func:`_oil_link`): the oil's compressibility is a spring,
    damped at the ratio 0.5, in series with the leakage past the pistons, a dashpot: the
    contact creeps behind the drive at the leakage speed F / c_l, ``s``^2
    :data:`LEAK_SPEED` x v99 at the Coulomb level, and stalls where the drive is slower
    than that. The compression between the Coulomb levels either way is ``s``^2
    :data:`COMPRESSION_SHARE` x the stroke (plus Fc / (:data:`LINK_STIFF` kh), kh the stiff
    coupling of the other forms, :func:`.truths._contact_constants`). The contact is light,
    with the base's LuGre friction; the measured force is its friction. At ``s`` = 0 the
    base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the square root of the oil's compression relative to
        :data:`COMPRESSION_SHARE` x the stroke (as the open plays'), and of the leakage.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The hydraulic spring of an oil column and the leakage of a cylinder or a hydrostatic
    transmission (Merritt 1967, Hydraulic Control Systems); master-slave cylinders of remote
    actuation. The candidate holds or frees the force across a play, with a bias, a spring
    or a drag across it; the open forms couple rigidly, compliantly (a linear
    spring-damper), by impacts, springs, oil in the play, an idler, a bias, chains, magnets,
    a preload, a hardening gear, a slipping rope or a rubber spider, with a play varying
    with the position or the travel. Here no play, but a coupling that cannot hold a force:
    the lost motion at a reversal grows with the time the force takes to turn, and the
    contact stands while a slow drive's flow leaks away.
    """
    p = _lugre_params(kin, "backlash (hydraulic_link)")
    if s <= 0.0:
        return _base_parts(kin)[0]
    m, kh, _ = _contact_constants(kin, p)
    Fc = float(p.Fc)
    lost = float(s) ** 2 * COMPRESSION_SHARE * float(np.ptp(kin.x))
    k = Fc / (0.5 * lost + Fc / (LINK_STIFF * kh))
    c = 2.0 * 0.5 * math.sqrt(k * m)
    cl = Fc / (float(s) ** 2 * LEAK_SPEED * max(kin.scales["v99"], 1e-12))
    h, xd, n_sub = _substeps(kin, max(math.sqrt((k + float(p.sigma0)) / m),
                                      (float(p.sigma1) + float(p.sigma2) + c) / m))
    F = _oil_link(h, xd, k, c, cl, m, float(p.sigma0), float(p.sigma1), float(p.sigma2), Fc,
                  float(p.Fs), float(p.vs), float(p.alpha), SHAPES[p.shape])
    return F[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: the junctions' elastic travel at full contact at strength 1, beyond the base bristle's
#: path, as a share of the stroke / 3 [-]; their share of the friction at strength 1 [-];
#: the real contact area's loss at the sliding force, A / A0 = 1 - beta f^2 [-]; the
#: re-adhesion's force over the peeling's at a given area (adhesion hysteresis) [-]
PRESLIDING_SHARE, JUNCTION_SHARE, PEEL_AREA, READHESION = 0.05, 0.7, 0.5, 0.4


@njit(cache=True)
def _peeling_junctions(x, ud, beta, rho):
    """The junctions' force f [-] (over the sliding level) along the positions ``x`` [m]:
    an elastic layer whose stiffness is its contact size c (the radius, ~ sqrt of the
    area; travel ``ud`` [m] to the sliding force at c = 1), df = c dx / ``ud``, |f| <= 1
    (sliding). The area peels as the force grows, c <= sqrt(1 - ``beta`` f^2) (receding),
    and re-adheres only once the force has fallen, c >= sqrt(1 - ``beta`` (f /
    ``rho``)^2) (advancing, ``rho`` < 1). Starts in full contact, unloaded."""
    n = x.size
    out = np.empty(n)
    f = 0.0
    c = 1.0
    out[0] = 0.0
    for k in range(1, n):
        f = f + c * (x[k] - x[k - 1]) / ud
        if f > 1.0:
            f = 1.0
        elif f < -1.0:
            f = -1.0
        cr = math.sqrt(max(1.0 - beta * f * f, 0.0))
        ca = math.sqrt(max(1.0 - beta * (f / rho) ** 2, 0.0))
        if c > cr:
            c = cr
        if c < ca:
            c = ca
        out[k] = f
    return out


@on_fine_grid
def junction_peeling_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Adhesive asperity junctions beside the bristle whose real contact area shrinks
    under the shear force: the interfacial crack (mode II) advances from the edges, A / A0
    = 1 - :data:`PEEL_AREA` f^2 at the force f (over the sliding level), and closes again
    only at a lower force (adhesion hysteresis: re-adhering at :data:`READHESION` x the
    force that peels the same area). Their tangential stiffness follows the contact's
    size (Mindlin's ~ radius): loading, the junctions soften as they peel; unloading, they
    stay at their smallest area, stiff and linear, until they re-adhere near zero force
    (:func:`_peeling_junctions`). The elastic travel at full contact is the base bristle's
    path Fs / sigma0 plus ``s`` :data:`PRESLIDING_SHARE` x the stroke / 3; a share w =
    :data:`JUNCTION_SHARE` min(``s``, 1) of the friction is the junctions' (their sliding
    force at the Stribeck level, the viscous term the base's): F = (1 - w) F_lugre + w
    (g(v) f + sigma2 v). At ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the junctions' share (up to ``s`` = 1) and their elastic
        travel (as the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The reduction of the contact area of an adhesive contact by a tangential force
    (Savkoor and Briggs 1977, The effect of tangential force on the contact of elastic
    solids in adhesion, Proc. R. Soc. A 356; Waters and Guduru 2010, Proc. R. Soc. A 466;
    Sahli et al. 2018, Evolution of real contact area under shear and the value of static
    friction of soft materials, PNAS 115) and adhesion hysteresis (Chaudhury and
    Whitesides 1991, Langmuir 7). Maxwell-slip (the candidate) and the open forms follow
    Masing's rule, path laws, an elastic range, rate-dependent creep, multistable tips,
    bonds, a fabric, a back-stress, a climb out of a nest, capillary bridges or a
    hardening yield; here the stiffness depends on how hard the junctions have been
    sheared since they last re-adhered: soft loading, stiff unloading, non-Masing loops.
    """
    p = _lugre_params(kin, "gms (junction_peeling)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, PRESLIDING_SHARE)
    w = JUNCTION_SHARE * min(float(s), 1.0)
    v = np.asarray(kin.v, float)
    f = _peeling_junctions(np.ascontiguousarray(kin.x, dtype=float), e0 + extra, PEEL_AREA,
                           READHESION)
    return (1.0 - w) * F + w * (kin.base.g(v) * f + float(p.sigma2) * v)
