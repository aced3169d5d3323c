"""The twentieth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-30 (session 24) by another hand, once, without running the diagnosis on it;
run once, sealed, at the start of session 25 on the code of 5ac3afd (the forked fit
workers; the benchmark's workers fit one after the other, so its verdicts are 4ea8e8e's):
176 cases, 0 skipped, 565 s wall on 2 workers (nothing else running). Top-1 50.0 % (88;
54.7 % of the 161 detectable; the other 15: 8 delays below a sample, 5 Stribeck shapes and 2
asymmetries an oracle cannot tell from the base); mean |shrink error| 0.303; wrong names on 16
(9.1 %): delay -> position 4, delay -> inertia 4, acceleration -> position 4 (the isolator's
one-frequency stroke), gms -> delay 2, gms -> acceleration 1, drift -> load 1. By form:
load/heathcote_slip 18/20, drift/grease_channelling 17/20, position/rail_misalignment 16/16,
inertia/friction_damped_mount 15/20, acceleration/rack_flank_sliding 8/20, gms/microslip_bar
6/12, asymmetry/sealing_band 4/20, backlash/wedge_flank 3/12, delay/magnetostrictive_wire 1/20,
stribeck_shape/shear_thinning_oil 0/16. By plant: isolator 60.7 %, valve 60.0 %, XML-350
57.5 %, press 35.7 %, damping rig 35.0 %. Run in a fresh worktree with 5ac3afd's fast-math
normal equations, whose last bits depended on the compile (0a12cc6 made them the same bits).
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen19` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen19`,
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
acceleration       ``rack_flank_sliding``: the carriage is driven by a rack and pinion
                   whose tooth flanks slide on each other with a speed that grows with
                   the distance of the contact from the pitch point (zero there, largest
                   at the ends of the path of contact; Buckingham 1949): the flanks'
                   friction loss, carried by the carriage, is the thrust through the
                   mesh (~ m |a|) times that sliding ratio: levels that rise with |a|,
                   modulated along each tooth pitch
load               ``heathcote_slip``: the rolling elements run in close-conforming
                   (gothic-arch) grooves: across the contact ellipse's width the groove's
                   radius, and so the rolling speed, varies, and the differential
                   (Heathcote) slip about two rolling lines dissipates a rolling drag
                   ~ mu L (b / R)^2, b ~ L^(1/3): a drag ~ L^(5/3)
asymmetry          ``sealing_band``: the steel sealing band of a slotted (rodless)
                   cylinder or a way cover, held by a constant-force spring at one end,
                   is pulled by the carriage over a fixed guide radius: the band's
                   tension at the carriage is the spring's times exp(+mu theta) moving
                   away from the spring and exp(-mu theta) towards it (Euler-Eytelwein),
                   mu with the band's own static and kinetic values: an offset and
                   levels, and speed dependences, that differ with the direction
stribeck_shape     ``shear_thinning_oil``: a polymer-thickened (multigrade) oil film
                   beside the contact whose viscosity thins with the shear rate (Cross
                   1965): the film's drag is viscous at low speed and bends over to a
                   lower slope above the thinning speed
position           ``rail_misalignment``: the two rails of the axis are not parallel:
                   beyond the point of the stroke where their spacing fits the carriages,
                   the misfit grows linearly and is taken up elastically by the
                   carriages' preload: the levels rise with it, and the stored elastic
                   energy pushes the carriage back towards the fitting point
inertia            ``friction_damped_mount``: a payload rides on the carriage on a spring
                   mount with a friction damper (a wire-mesh or friction-pad isolator):
                   it moves rigidly while the damper holds, and on its spring, with a
                   dry friction slip, where its inertial force passes the damper's slip
                   force: the mass the inverse dynamics misses is whole at low
                   acceleration and springs and slips at the peaks
delay              ``magnetostrictive_wire``: the position is read by a magnetostrictive
                   sensor (a waveguide wire, the Wiedemann effect): the torsional strain
                   pulse travels from the position magnet to the head at the wire's
                   sound speed, so the motion channels are late by a time that grows
                   with the magnet's distance from the head: a delay that varies along
                   the stroke
drift              ``grease_channelling``: the grease of the guide is pushed aside at each
                   reversal of the motion into ridges beside the track (channelling,
                   Lugt 2013): the share of the track left starved grows by a fixed
                   fraction of what remains at every reversal, and the levels rise with
                   it: a drift counted in reversals, not in time or travel
backlash           ``wedge_flank``: drive and contact meet across their play on inclined
                   flanks (a thread or a gear flank) that slide on one another as the
                   contact deflects: the flank friction stiffens the coupling while it
                   loads and softens it while it unloads (the wedge's tan(phi + rho)
                   against tan(phi - rho)): a compliant take-up of the play with a
                   hysteresis of its own
gms                ``microslip_bar``: presliding of a slender part clamped along its
                   length on a friction bed (a rod in its bore, a lap joint's strip;
                   Menq, Bielak and Griffin 1986): the slip front advances from the
                   loaded end, so the force grows as the square root of the
                   displacement up to full slip, and unloading follows Masing's rule; at
                   ``s`` = 0 the base itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``shear_thinning_oil``
needs a Stribeck curve (not the isolator's mre_lugre), ``rail_misalignment`` a record that
revisits its positions (not the press), ``heathcote_slip`` a load that changes,
``wedge_flank`` and ``microslip_bar`` a classic LuGre base (valve, damping rig,
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
                     _smooth_max0, _substeps, has_stribeck_curve, level_inside, on_fine_grid)

__all__ = ["FORMS", "rack_flank_sliding_truth", "heathcote_slip_truth",
           "sealing_band_truth", "shear_thinning_oil_truth", "rail_misalignment_truth",
           "friction_damped_mount_truth", "magnetostrictive_wire_truth",
           "grease_channelling_truth", "wedge_flank_truth", "microslip_bar_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "rack_flank_sliding", "load": "heathcote_slip",
         "asymmetry": "sealing_band", "stribeck_shape": "shear_thinning_oil",
         "position": "rail_misalignment", "inertia": "friction_damped_mount",
         "delay": "magnetostrictive_wire", "drift": "grease_channelling",
         "backlash": "wedge_flank", "gms": "microslip_bar"}


# -- acceleration ----------------------------------------------------------------------------
#: ``rack_flank_sliding``'s flank friction at the top acceleration and the end of the path of
#: contact, x the friction level, at strength 1 [-]; the rack's tooth pitch, x the stroke the
#: record visits [-]
RACK_SHARE, RACK_PITCH = 0.8, 0.06


def _sliding_ratio(x, pitch, x0):
    """The flanks' sliding speed over the pitch-line speed [-] (1 at the ends of the path of
    contact) along the positions ``x`` [m] of a rack of tooth pitch ``pitch`` [m] whose
    pitch point is passed at ``x0`` [m]: |2 u - 1|, u the mesh's phase in [0, 1) - the
    sliding speed grows linearly with the contact's distance from the pitch point (a
    single pair in mesh)."""
    u = np.mod((np.asarray(x, float) - x0) / pitch + 0.5, 1.0)
    return np.abs(2.0 * u - 1.0)


@on_fine_grid
def rack_flank_sliding_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The carriage is driven by a rack and pinion. The thrust through the mesh is, above
    all, the inertial force m a that accelerates the carriage; its flanks slide on each
    other with a speed proportional to the contact's distance from the pitch point (zero
    there, largest at the ends of the path of contact; :func:`_sliding_ratio`), and the
    flank friction mu N v_slide, over the carriage's speed, is a drag ~ |m a| x the
    sliding ratio. The Coulomb and Stribeck levels are the base's times 1 + ``s``
    :data:`RACK_SHARE` (|a| / a99) x the sliding ratio (tooth pitch :data:`RACK_PITCH` x
    the stroke), inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the flanks' friction coefficient times the carriage's mass,
        / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Sliding velocity along the path of contact and the resulting tooth friction loss
    (Buckingham 1949, Analytical Mechanics of Gears, ch. 14; Niemann and Winter 1983,
    Maschinenelemente II; ISO/TR 14179-2 on gear power losses); rack-and-pinion drives of
    long axes. The candidate raises the levels with |a|, lagged, tilts them with a and
    adds a force odd in a; the open forms lag the velocity, a film or a contact state,
    heat the contact, skid or push rolling elements, move load between rows or supports,
    press seals, pull with the thrust, squeeze or starve films, dilate, lift on a wedge,
    shift a gib, soften an elastomer, swing a roller arm, unload by the jerk, tilt a
    pressurised film or shake the contact with a current ripple. Here the acceleration's
    friction is a loss of the mesh: it vanishes each time the contact passes the pitch
    point and is largest between, once per tooth along the stroke.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    a99 = max(sc["a99"], 1e-12)
    stroke = (sc["x_hi"] - sc["x_lo"]) or 1.0
    ratio = _sliding_ratio(kin.x, RACK_PITCH * stroke, sc["x_lo"])
    lev = 1.0 + float(s) * RACK_SHARE * np.abs(np.asarray(kin.a, float)) / a99 * ratio
    return level_inside(kin, lev, np.ones_like(lev))


# -- load ------------------------------------------------------------------------------------
#: ``heathcote_slip``'s rolling drag at the record's top load (its 99th percentile), x the
#: friction level, at strength 1 [-]; the exponent of the load (the drag mu L (b / R)^2,
#: b ~ L^(1/3)) [-]
HEATH_SHARE, HEATH_POWER = 0.5, 5.0 / 3.0


def _heathcote_drag(load, top_load):
    """The differential-slip drag [-] (1 at the load ``top_load`` [N]) at the loads
    ``load`` [N]: (|L| / L_top)^(5/3) (:data:`HEATH_POWER`)."""
    return (np.abs(np.asarray(load, float)) / top_load) ** HEATH_POWER


@on_fine_grid
def heathcote_slip_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The rolling elements of the guide run in close-conforming (gothic-arch) grooves.
    Across the width 2b of the contact ellipse the groove's radius, and with it the
    element's rolling speed, varies: the element rolls without slip on two lines only and
    slips forwards between and backwards outside them (Heathcote slip), which dissipates
    a rolling drag mu L (b / R)^2 with the contact's half-width b ~ (L R / E*)^(1/3): a
    drag ~ L^(5/3) (:func:`_heathcote_drag`). The Coulomb and Stribeck levels are the
    base's times 1 + ``s`` :data:`HEATH_SHARE` x that drag (1 at the record's top load),
    inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (load [N]) and its base law.
    s : float
        Amplitude factor [-]: the slip's friction coefficient times the grooves'
        conformity, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Differential slip in conforming grooves (Heathcote 1921, The ball bearing: in the
    making, under test and on service, Proc. Inst. Automob. Eng. 15; Johnson 1985, Contact
    Mechanics, ch. 8.4; Harris and Kotzalas 2007, ch. 7). The candidate makes the levels
    affine in the load, with a memory over the travel; the open forms scale the friction
    with the load, as a Hertz contact's area, a seal's, a film's, a junction's, a pivot's
    or an adhesive contact's, break or squeeze films, plough, creep, roll on a lossy track
    and more. Here the drag grows faster than the load, as its 5/3 power: a rolling loss
    that is nearly nothing at light loads.
    """
    L = np.asarray(kin.load, float)
    Lm = float(np.mean(np.abs(L))) or 1.0
    if not np.ptp(L) > 1e-9 * Lm:
        raise ValueError(f"load (heathcote_slip): the {kin.plant} record's load does not "
                         f"change")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    top = max(float(np.percentile(np.abs(L), 99)), 1e-12 * Lm)
    lev = 1.0 + float(s) * HEATH_SHARE * _heathcote_drag(L, top)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``sealing_band``'s spring tension, x the friction level, at strength 1 [-]; the wrap's
#: mu theta at the band's kinetic friction [-]; its static excess over the kinetic [-]; the
#: speed the band's friction falls to the kinetic over, x the top speed [-]; the speed its
#: sign is rounded over, x the top speed [-]
BAND_TENSION, BAND_WRAP, BAND_STATIC, BAND_SPEED, BAND_ROUND = 0.3, 0.6, 0.6, 0.05, 2e-3


def _band_tension(v, wrap, static, v_fall, v_round):
    """The band's tension at the carriage over the spring's [-] at the velocities ``v``
    [m/s]: exp(mu theta(v) r(v)), mu theta(v) = ``wrap`` (1 + ``static`` exp(-(v /
    ``v_fall``)^2)) and r(v) = tanh(v / ``v_round``) the sliding direction over the guide
    radius (Euler-Eytelwein: the tight side's tension is the slack side's times exp(mu
    theta)); 1 at rest."""
    v = np.asarray(v, float)
    mu = wrap * (1.0 + static * np.exp(-(v / v_fall) ** 2))
    return np.exp(mu * np.tanh(v / v_round))


@on_fine_grid
def sealing_band_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A steel sealing band (the slot cover of a rodless cylinder, a way cover's band) is
    held at its far end by a constant-force spring of tension T0 = ``s``
    :data:`BAND_TENSION` x the friction level and runs to the carriage over a fixed guide
    radius that it wraps by theta. Moving away from the spring (+x) the carriage pulls the
    band over the guide against its friction, and the tension it feels is T0 exp(mu
    theta); moving towards it the spring pulls the band back over the guide, and the
    friction holds the tension at the carriage down to T0 exp(-mu theta) (Euler-Eytelwein,
    :func:`_band_tension`), mu falling from its static to its kinetic value over
    :data:`BAND_SPEED` x the top speed. The truth adds that tension (towards -x) to the
    base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the spring's tension, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Belt friction (Euler 1762; Eytelwein 1808; Johnson 1985, Contact Mechanics, ch. 8);
    sealing bands of slotted rodless cylinders (Festo's and Parker's catalogues; Beater
    2007, Pneumatic Drives, ch. 6). The candidate frees the levels (and the Stribeck
    velocity and viscous term) of each direction and an offset; the open forms twin the
    levels, curves or viscous terms, roll lips, load thrust bearings, pump films, ratchet,
    spring back, tilt pads, strut, throttle, differ in areas, pump along grooves, buckle,
    scrape chips, commutate, tension idlers, free-wheel, wick felts, run belts or lean
    brushes. Here the direction multiplies an offset: the two directions' levels are in
    the ratio exp(2 mu theta), and their static peaks in a larger one.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    ratio = _band_tension(kin.v, BAND_WRAP, BAND_STATIC, BAND_SPEED * v99, BAND_ROUND * v99)
    return F + float(s) * BAND_TENSION * _level(kin) * ratio


# -- stribeck_shape --------------------------------------------------------------------------
#: ``shear_thinning_oil``'s film drag at the top speed, x the Coulomb level, at strength 1
#: [-]; the thinning speed (the Cross model's 1 / lambda x the film's thickness), x the top
#: speed [-]; the Cross exponent [-]; the thinned viscosity over the rest viscosity [-]
THIN_DRAG, THIN_SPEED, THIN_EXPONENT, THIN_FLOOR = 0.4, 0.04, 0.8, 0.15


def _cross_drag(v, v_thin, exponent, floor):
    """The shear-thinning film's drag [-] at the velocities ``v`` [m/s], over its drag at
    ``v`` = ``v_thin`` [m/s] without thinning: (v / v_thin) eta(v) / eta_0 with the Cross
    model eta / eta_0 = ``floor`` + (1 - ``floor``) / (1 + |v / v_thin|^``exponent``);
    odd in ``v``."""
    u = np.asarray(v, float) / v_thin
    return u * (floor + (1.0 - floor) / (1.0 + np.abs(u) ** exponent))


@on_fine_grid
def shear_thinning_oil_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Beside the contact a film of a polymer-thickened (multigrade) oil is sheared between
    the carriage and the way. Its viscosity thins with the shear rate v / h along the Cross
    model eta = eta_inf + (eta_0 - eta_inf) / (1 + (lambda v / h)^m) (:func:`_cross_drag`;
    thinning speed :data:`THIN_SPEED` x the top speed, m = :data:`THIN_EXPONENT`, eta_inf =
    :data:`THIN_FLOOR` eta_0): its drag eta v A / h is viscous at low speed and bends over
    to a lower slope above the thinning speed. The truth adds that drag, ``s``
    :data:`THIN_DRAG` x the Coulomb level at the top speed, to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (with a Stribeck curve).
    s : float
        Amplitude factor [-]: the film's area over its thickness times its rest viscosity,
        / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Shear thinning of polymer-containing oils (Cross 1965, Rheology of non-Newtonian
    fluids: a new flow equation for pseudoplastic systems, J. Colloid Sci. 20; Bair 2007,
    High Pressure Rheology for Quantitative Elastohydrodynamics, ch. 4; temporary
    viscosity loss of multigrade oils, ASTM D6616). The candidate reshapes the Stribeck
    curve; the open forms add a tail, a rational drop, a hydrodynamic rise, a spike, a
    lift-off, two roughness scales, a logarithmic or Eyring law, starve a film, add rubber
    hysteresis, resonate, dither, melt, flow grains, readsorb, heat the film, make it
    turbulent, thixotropic or churned, add core losses, breathe a bellows or brake by
    eddy currents. Here a film drag rises steeply from rest and bends to a lower slope at
    speed: a viscous term whose coefficient falls with the speed.
    """
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (shear_thinning_oil): the mre_lugre base has no "
                         "Stribeck curve")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    v_thin = THIN_SPEED * v99
    top = float(_cross_drag(np.array([v99]), v_thin, THIN_EXPONENT, THIN_FLOOR)[0])
    drag = _cross_drag(kin.v, v_thin, THIN_EXPONENT, THIN_FLOOR) / top
    return F + float(s) * THIN_DRAG * float(kin.base.params.Fc) * drag


# -- position --------------------------------------------------------------------------------
#: ``rail_misalignment``'s rise of the levels at the far end of the stroke from the fitting
#: point, at strength 1 [-]; the push back there, x the friction level, at strength 1 [-];
#: the travel the misfit's onset is rounded over, x the stroke [-]
MISFIT_RISE, MISFIT_PUSH, MISFIT_ROUND = 0.5, 0.3, 0.03


def _misfit(x, x_fit, far, rounding):
    """The rails' misfit [-] along the positions ``x`` [m] (1 at ``x_fit`` + ``far``):
    nothing before the fitting point ``x_fit`` [m], where the rails' spacing fits the
    carriages (there they have play), then growing linearly with the distance past it
    (the onset rounded over ``rounding`` [m])."""
    return _smooth_max0(np.asarray(x, float) - x_fit, rounding) / far


@on_fine_grid
def rail_misalignment_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The two rails of the axis are mounted at a small angle to each other (not
    parallel): up to a point of the stroke their spacing leaves the carriages their play,
    past it the misfit grows linearly with the travel (:func:`_misfit`) and is taken up
    elastically by the carriages' rolling elements as extra preload. The levels rise with
    that preload, 1 + ``s`` :data:`MISFIT_RISE` x the misfit (1 at the far end of the
    stroke), inside the bristle dynamics, and the elastic energy stored, ~ misfit^2, pushes
    the carriage back towards the fitting point: a force ``s`` :data:`MISFIT_PUSH` x the
    friction level x the misfit, whatever the direction of travel. The fitting point is
    where fit and held-out parts both pass.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the rails' angle, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Parallelism of the rails of linear guides and the resulting rise of the running
    resistance (THK's and Bosch Rexroth's catalogues: permissible parallelism error and
    its load; Slocum 1992, Precision Machine Design, ch. 8). The candidate scales the
    friction along the stroke and adds a force of the position; the open forms put a
    defect, a waviness, a worn section, runout, a bent rail, a transfer film, cogging, a
    taper, a pocket, a cushion, a cover, an air spring, bolt holes, a plunger, a sag, a
    festoon, a curve, a chain, a cam, a heated zone, brinelled dents or a rail joint on
    the stroke. Here the levels and a spring-like push both start at one point and grow
    linearly from it: a kink in the middle of the visited stroke.
    """
    x_fit = _bump_centre(kin)
    if x_fit is None:
        raise ValueError(f"position (rail_misalignment): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    if s <= 0.0:
        return _base_parts(kin)[0]
    sc = kin.scales
    stroke = (sc["x_hi"] - sc["x_lo"]) or 1.0
    far = max(sc["x_hi"] - x_fit, 0.05 * stroke)
    m = _misfit(kin.x, x_fit, far, MISFIT_ROUND * stroke)
    lev = 1.0 + float(s) * MISFIT_RISE * m
    return level_inside(kin, lev, np.ones_like(lev)) + float(s) * MISFIT_PUSH * _level(kin) * m


# -- inertia ---------------------------------------------------------------------------------
#: ``friction_damped_mount``'s payload mass x the top acceleration, x the friction level, at
#: strength 1 [-]; the damper's slip force, x the payload's inertial force at the top
#: acceleration [-]; the mount spring's angular frequency and the damper pad's (stuck), x
#: 1 / the motion's time scale v99 / a99 [-]; the mount's damping ratio at the pad's
#: frequency [-]
MOUNT_MASS, MOUNT_SLIP, MOUNT_SPRING, MOUNT_PAD, MOUNT_DAMPING = 1.0, 0.35, 2.0, 25.0, 0.05


@njit(cache=True)
def _mount_force(a, h, n_sub, m, k, k_pad, c, slip):
    """The force [N] the payload of mass ``m`` [kg] exerts back on the carriage, whose
    accelerations ``a`` [m/s^2] come in steps ``h`` [s] (each taken in ``n_sub`` sub-steps):
    the payload's displacement u [m] on the carriage obeys m (a + u'') = -(k u + f + c u'),
    ``k`` [N/m] the mount's spring, ``c`` [N s/m] its damping and f [N] the friction
    damper's force, a stiff pad ``k_pad`` [N/m] that slips at ``slip`` [N] (an elastic-
    perfectly plastic element). Semi-implicit Euler; starts at rest, unloaded. The drive
    supplies m (a + u'') = -(k u + f + c u')."""
    n = a.size
    out = np.empty(n)
    hs = h / n_sub
    u = 0.0
    w = 0.0
    f = 0.0
    for j in range(n):
        out[j] = -(k * u + f + c * w)
        for _ in range(n_sub):
            w = (w + hs * (-a[j] - (k * u + f) / m)) / (1.0 + hs * c / m)
            du = hs * w
            u += du
            f = min(max(f + k_pad * du, -slip), slip)
    return out


@on_fine_grid
def friction_damped_mount_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A payload rides on the carriage on a spring mount with a dry friction damper (a
    wire-mesh or friction-pad isolator), mass m with m a99 = ``s`` :data:`MOUNT_MASS` x
    the friction level. While the damper's pad holds (its slip force :data:`MOUNT_SLIP`
    x m a99) the payload moves with the carriage on the pad's stiffness (a fast mode,
    :data:`MOUNT_PAD` / the motion's time scale); where its inertial force passes the slip
    force the pad slips and the payload swings on the mount's soft spring
    (:data:`MOUNT_SPRING` / the motion's time scale), lightly damped, until the pad holds
    again (:func:`_mount_force`). The truth adds the force the payload takes from the
    carriage, m (a + u''), to the base (the inverse dynamics' mass is the carriage's
    alone).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the payload's mass (its damper's slip force with it), / its
        value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Friction-damped isolators and mounts (Den Hartog 1931, Forced vibrations with combined
    Coulomb and viscous friction, Trans. ASME 53; Harris and Piersol 2002, Shock and
    Vibration Handbook, ch. 32 on wire-rope and friction isolators). The candidate misses
    a constant mass; the open forms filter it, reflect it through gearing, a chain's
    polygon or a pinion, hang it on a spring, a cable, a fluid, a clutch, a coupling, a
    flyweight or a screw, pick it up, drop it, empty it, slide it, rattle it, recoil the
    frame, saturate the motor, lead it by the feedforward or pitch the scale head. Here
    the payload is whole while the damper holds and springs away where the acceleration
    peaks: a mass error that depends on the size of the acceleration and on its history.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    T = max(_motion_time(kin), 1e-12)
    a99 = max(kin.scales["a99"], 1e-12)
    m = float(s) * MOUNT_MASS * _level(kin) / a99
    w_pad = MOUNT_PAD / T
    k_pad = m * w_pad ** 2
    k = m * (MOUNT_SPRING / T) ** 2
    c = 2.0 * MOUNT_DAMPING * m * w_pad
    h = float(kin.t[1] - kin.t[0])
    n_sub = max(1, int(math.ceil(h * w_pad / 0.05)))
    extra = _mount_force(np.ascontiguousarray(kin.a, dtype=float), h, n_sub, m, k, k_pad, c,
                         MOUNT_SLIP * m * a99)
    return F + extra


# -- delay -----------------------------------------------------------------------------------
#: ``magnetostrictive_wire``'s time of flight of the strain pulse from the far end of the
#: stroke to the head, in data samples, at strength 1 [-]
WIRE_SAMPLES = 2.0


def _flight_time(x, x_head, length, t_full):
    """The strain pulse's time of flight [s] from the magnet at the positions ``x`` [m] to
    the head at ``x_head`` [m] along the waveguide: ``t_full`` [s] over the length
    ``length`` [m], in proportion to the distance (the wire's constant sound speed)."""
    return t_full * np.abs(np.asarray(x, float) - x_head) / length


@on_fine_grid
def magnetostrictive_wire_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The motion is read by a magnetostrictive position sensor: a current pulse in the
    waveguide wire meets the position magnet's field, the Wiedemann effect launches a
    torsional strain pulse there, and the head times its arrival. The pulse travels at the
    wire's sound speed, so the position is that of the moment the pulse left the magnet,
    late by the time of flight, which grows with the magnet's distance from the head (at
    the stroke's low end): ``s`` :data:`WIRE_SAMPLES` data samples at the far end
    (:func:`_flight_time`). The force, on time, leads the motion channels by that
    position-dependent time.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law.
    s : float
        Amplitude factor [-]: the waveguide's length over its sound speed, / its value at
        strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Magnetostrictive displacement sensors (Wiedemann 1862; Tumanski 2011, Handbook of
    Magnetic Measurements, ch. 6; Seco et al. 2009, Improving the accuracy of
    magnetostrictive linear position sensors, IEEE Trans. Instrum. Meas. 58; MTS
    Temposonics data sheets: torsional wave speed ~2800 m/s). The candidate shifts the
    force by a constant time, low-passes it, reads it through a transducer's resonance and
    leaks it; the open forms sample, filter, average, hold, skew, jitter, rate-limit,
    transmit, median, report by deadband, trigger on positions, run a belt, aerate, drop
    telegrams, leak, creep, notch, track or snub it. Here the lag is the motion's and
    changes along the stroke: none at the head, largest at the far end.
    """
    from scipy.interpolate import CubicSpline
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    length = (sc["x_hi"] - sc["x_lo"]) or 1.0
    tau = _flight_time(kin.x, sc["x_lo"], length, float(s) * WIRE_SAMPLES * kin.sample_dt)
    return CubicSpline(kin.t, F)(np.clip(kin.t + tau, None, kin.t[-1]))


# -- drift -----------------------------------------------------------------------------------
#: ``grease_channelling``'s rise of the levels with the whole track starved, at strength 1
#: [-]; the e-folds of the grease's share left on the track over all the record's reversals
#: [-]; the time the pushed grease settles in, x the record's length [-]; the speed below
#: which no reversal is counted, x the top speed [-]
CHANNEL_RISE, CHANNEL_FOLDS, CHANNEL_SETTLE, CHANNEL_DEAD = 0.6, 1.5, 0.01, 0.02


def _reversal_count(v, dead):
    """The number of reversals of the motion [-] made up to each of the velocities ``v``
    [m/s]: changes of the direction of travel, speeds below ``dead`` [m/s] keeping the
    last direction."""
    v = np.asarray(v, float)
    d = np.where(np.abs(v) > dead, np.sign(v), 0.0)
    idx = np.where(d != 0.0, np.arange(v.size), 0)
    np.maximum.accumulate(idx, out=idx)
    held = d[idx]
    turns = np.concatenate(([0.0], (held[1:] * held[:-1] < 0.0).astype(float)))
    return np.cumsum(turns)


def _starved_share(t, count, total, folds, settle):
    """The starved share of the track [-] along the times ``t`` [s] after ``count``
    reversals of ``total`` in the record: 1 - exp(-``folds`` count / total), each
    reversal pushing the same fraction of what grease is left aside, settling over the
    first-order lag ``settle`` [s]."""
    from scipy.signal import lfilter
    target = 1.0 - np.exp(-folds * np.asarray(count, float) / max(total, 1.0))
    dt = float(t[1] - t[0])
    e = math.exp(-dt / settle)
    return lfilter([1.0 - e], [1.0, -e], target, zi=[target[0] * e])[0]


@on_fine_grid
def grease_channelling_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The guide is greased. At every reversal of the motion the rolling elements push a
    part of the grease left on the track aside into ridges beside it (channelling), where
    it no longer takes part; the contact runs on what the ridges bleed back and is
    progressively starved. The starved share of the track after N reversals is 1 -
    exp(-:data:`CHANNEL_FOLDS` N / N_total), N_total the record's reversals
    (:func:`_reversal_count`, :func:`_starved_share`; each settling over
    :data:`CHANNEL_SETTLE` x the record). The Coulomb and Stribeck levels are the base's
    times 1 + ``s`` :data:`CHANNEL_RISE` x that share, inside the bristle dynamics; the
    viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the starved track's friction over the greased one's, less
        1, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Grease channelling and starvation in rolling contacts (Lugt 2013, Grease Lubrication
    in Rolling Bearings, ch. 6 and 9; Cann 1996, Starved grease lubrication of rolling
    contacts, Tribol. Trans. 42; short-stroke reciprocation in linear guides, THK's
    lubrication notes). The candidate is a trend, a saturating change, a step, a cycle, a
    resetting change or the friction power's heat; the open forms warm up, wear in, change
    the lubricant, heat, wear, follow the humidity, grind a third body, relubricate,
    relax a seal, oxidise, deplete, wear through, swell, build a tribofilm, take in
    particles, expand, shear down, heat magnets, charge, creep a cage, loosen a screw or
    dewet a film. Here the friction changes at the reversals only, and so with the
    motion's count of them, not with the time or the travel.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v99 = max(kin.scales["v99"], 1e-12)
    count = _reversal_count(kin.v, CHANNEL_DEAD * v99)
    T = float(kin.t[-1] - kin.t[0]) or 1.0
    share = _starved_share(kin.t, count, float(count[-1]), CHANNEL_FOLDS, CHANNEL_SETTLE * T)
    lev = 1.0 + float(s) * CHANNEL_RISE * share
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: ``wedge_flank``'s play at strength 1, as a share of the stroke [-]; the flanks' friction
#: over their inclination, tan(rho) / tan(phi), which stiffens the loading coupling by 1 +
#: it and softens the unloading one by 1 - it [-]; the relative speed the change between
#: them is rounded over, x the top speed [-]
WEDGE_PLAY, WEDGE_FRICTION, WEDGE_ROUND = 0.008, 0.5, 0.01


@njit(cache=True)
def _wedged_play(h, xd, half, eta, v_round, kh, ch, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a contact of mass ``m`` [kg] driven by the drive positions
    ``xd`` [m] (step ``h`` [s]) across a play of half-width ``half`` [m] whose flanks meet
    on a wedge: in contact the coupling is ``kh`` [N/m] x the penetration x (1 + ``eta``
    tanh(r / ``v_round``)), r [m/s] the penetration's rate (loading: stiffer, unloading:
    softer), plus the damping ``ch`` [N s/m]; it only pushes. Euler of the mass
    (:func:`.truths._light_contact_step`). Starts at rest, centred."""
    n = xd.size
    F = np.empty(n)
    v = 0.0
    z = 0.0
    x = xd[0]
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        e = xd[j] - x
        ed = vd - v
        fc = 0.0
        if e > half:
            f2 = kh * (e - half) * (1.0 + eta * math.tanh(ed / v_round)) + ch * ed
            if f2 > 0.0:
                fc = f2
        elif e < -half:
            f2 = kh * (e + half) * (1.0 - eta * math.tanh(ed / v_round)) + ch * ed
            if f2 < 0.0:
                fc = f2
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha, shape)
        x = x + h * v
    return F


@on_fine_grid
def wedge_flank_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact joined across a play of half-width ``s``^2 :data:`WEDGE_PLAY` / 2
    x the stroke whose flanks meet at an inclination (a thread's flank, a gear's pressure
    angle) and slide on one another as the contact deflects. The flank friction (angle
    rho) adds to the wedge's angle phi while the coupling loads and subtracts from it
    while it unloads: the coupling's stiffness is tan(phi + rho) / tan(phi) times its
    nominal one on loading and tan(phi - rho) / tan(phi) on unloading, ~ 1 +- tan(rho) /
    tan(phi) = 1 +- :data:`WEDGE_FRICTION` (rounded over :data:`WEDGE_ROUND` x the top
    speed of the penetration's rate; :func:`_wedged_play`). The light contact behind it
    carries the base's LuGre friction (:func:`.truths._contact_constants`).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the square root of the play, / its value at strength 1 (as
        the open plays').

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Friction on inclined flanks and the hysteresis of a wedge's stiffness (the screw's
    efficiency tan(phi) / tan(phi + rho), and tan(phi - rho) / tan(phi) back-driven:
    Shigley and Mischke 2001, Mechanical Engineering Design, ch. 8; Johnson 1985,
    Contact Mechanics, ch. 7 on tangential loading with friction). The candidate holds or
    frees the contact across a rigid play; the open forms take it up rigidly, compliantly,
    by impact, against a spring, eccentrically, through oil, worn, with a dragging idler,
    biased, slack, magnetic, preloaded, through a flexspline, a rope, a spider, a fluid
    link, a cable, a clutch, a varying mesh, a polymer gear or grease. Here the take-up
    has a hysteresis of its own: the coupling is stiffer while it closes than while it
    opens.
    """
    p = _lugre_params(kin, "backlash (wedge_flank)")
    if s <= 0.0:
        return _base_parts(kin)[0]
    m, kh, ch = _contact_constants(kin, p)
    stroke = float(np.ptp(kin.x))
    half = 0.5 * float(s) ** 2 * WEDGE_PLAY * stroke
    v_round = WEDGE_ROUND * max(kin.scales["v99"], 1e-12)
    h, xd, n_sub = _substeps(kin, max(math.sqrt(((1.0 + WEDGE_FRICTION) * kh
                                                 + float(p.sigma0)) / m),
                                      (float(p.sigma1) + float(p.sigma2) + ch) / m))
    F = _wedged_play(h, xd, half, WEDGE_FRICTION, v_round, kh, ch, m,
                     float(p.sigma0), float(p.sigma1), float(p.sigma2), float(p.Fc),
                     float(p.Fs), float(p.vs), float(p.alpha), SHAPES[p.shape])
    return F[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: the bar's travel to full slip at strength 1, beyond the base bristle's path, as a share
#: of the stroke / 3 [-]; its share of the friction at strength 1 [-]
BAR_SLIP, BAR_SHARE = 0.1, 0.6


@njit(cache=True)
def _microslip(x, d_full):
    """The bar's force f [-] (1 at full slip) along the positions ``x`` [m] of its loaded
    end: from rest the backbone sqrt(|x - x0| / ``d_full``) (the slip front's length grows
    as the square root of the end's travel) up to 1; after each reversal at (x_r, f_r)
    Masing's branch f_r -+ 2 sqrt(|x - x_r| / (2 ``d_full``)), within [-1, 1]."""
    n = x.size
    out = np.empty(n)
    out[0] = 0.0
    xr = x[0]
    fr = 0.0
    direction = 0.0
    virgin = True
    f = 0.0
    for k in range(1, n):
        dx = x[k] - x[k - 1]
        if dx != 0.0:
            d = 1.0 if dx > 0.0 else -1.0
            if direction != 0.0 and d != direction:
                xr = x[k - 1]
                fr = f
                virgin = False
            direction = d
        if direction != 0.0:
            dist = abs(x[k] - xr)
            if virgin:
                f = direction * min(math.sqrt(dist / d_full), 1.0)
            else:
                f = fr + direction * 2.0 * math.sqrt(0.5 * dist / d_full)
                f = min(max(f, -1.0), 1.0)
        out[k] = f
    return out


@on_fine_grid
def microslip_bar_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Beside the bristle, part of the contact is a slender part clamped along its length
    on a friction bed (a rod in its bore, the strip of a lap joint): pushed at one end it
    slips first there, and the slip front advances along it as the force grows, F =
    sqrt(2 EA q delta) for the end's travel delta, up to full slip F = q L at delta_full
    = q L^2 / (2 EA) (:func:`_microslip`); unloading and reloading follow Masing's rule
    (twice the backbone from the last reversal). delta_full is the base bristle's path Fs
    / sigma0 plus ``s`` :data:`BAR_SLIP` x the stroke / 3; the bar's share w = ``s``
    :data:`BAR_SHARE` (up to ``s`` = 1) of the friction is its force times the Stribeck
    level, the viscous term the base's: F = (1 - w) F_lugre + w (g(v) f + sigma2 v). At
    ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the bar's share (up to ``s`` = 1) and its travel to full
        slip (as the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The microslip bar (Menq, Bielak and Griffin 1986, The influence of microslip on
    vibratory response, part I: a new microslip model, J. Sound Vib. 107; Csaba 1998 on
    shear-lag in friction dampers; Masing 1926). The candidate's presliding is a
    generalized Maxwell-slip (GMS) element set; the open forms are Maxwell-slip sets, Dahl,
    elasto-plastic, Bliman-Sorine, Bouc-Wen, Zener junctions, Mindlin contacts,
    rate-and-state, Tomlinson asperities, bond rupture, gouge, kinematic hardening,
    interlocking, capillary bridges, cyclic hardening, peeling, unloading microslip, a
    power-law joint, junction growth, avalanches and slip weakening. Here the presliding
    stiffness is infinite at each reversal and falls as one over the square root of the
    travel since it.
    """
    p = _lugre_params(kin, "gms (microslip_bar)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, BAR_SLIP)
    w = BAR_SHARE * min(float(s), 1.0)
    v = np.asarray(kin.v, float)
    f = _microslip(np.ascontiguousarray(kin.x, dtype=float), e0 + extra)
    return (1.0 - w) * F + w * (kin.base.g(v) * f + float(p.sigma2) * v)
