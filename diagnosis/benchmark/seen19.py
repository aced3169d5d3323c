"""The nineteenth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-30 (session 24) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 24's work on the code of 3cef9aa:
176 cases, 0 skipped, 977 s wall on 2 workers (beside the README's first command in a
fresh clone and the real-data examples). Top-1 43.8 % (77; 45.2 % of the 168 detectable;
the other 8: 6 delays below a sample, 2 Stribeck shapes an oracle cannot tell from the
base); mean |shrink error| 0.328; wrong names on 35 (19.9 %): acceleration -> asymmetry 4,
load -> inertia 4, delay -> position 4, asymmetry -> delay 4, asymmetry -> position 3,
gms -> acceleration 3, load -> stribeck_shape 3, backlash -> gms 2, acceleration -> delay
2, and five single ones; of the 7 wrong `delay` names, 6 are the code's before the
transducer resonance (308ab2d gives the same), 1 (a backlash case of the damping rig,
`unexplained` before) is the resonance's. By form: drift/film_dewetting 20/20,
position/rail_joint 16/16, delay/gauge_snubber 12/20, load/viscoelastic_rolling 8/20,
inertia/abbe_pitch 8/20, asymmetry/leaning_brush 4/20, gms/slip_weakening 3/12,
acceleration/current_ripple 2/20, stribeck_shape/eddy_brake 2/16,
backlash/grease_packed_gap 2/12. By plant: press 57.1 %, XML-350 50.0 %, valve 42.5 %,
isolator 35.7 %, damping rig 35.0 %.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen18` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen18`,
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
acceleration       ``current_ripple``: the drive's current controller is a hysteresis
                   (bang-bang) controller whose band is a share of the current command
                   (Bose 1990's adaptive band): its high-frequency force ripple, and the
                   contact's tangential velocity ripple, grow with the thrust, i.e.
                   with |a|; a fast tangential vibration averages the friction's sign
                   (dither), so the friction falls where the speed is below the ripple's
                   velocity amplitude: at low speed under a strong acceleration
load               ``viscoelastic_rolling``: a hard support roller of the carriage runs
                   on a viscoelastic (polyurethane-coated) track: its hysteresis rolling
                   resistance ~ L^(4/3) tan(delta) (Greenwood, Minshall and Tabor 1961),
                   the track's loss factor (a standard linear solid) taken at the
                   excitation rate v / a, a the contact's half-width ~ L^(1/3): a drag
                   that grows faster than the load and whose speed of peak loss moves
                   up with the load
asymmetry          ``leaning_brush``: a strip brush (a way wiper's bristles) fixed to the
                   carriage with its bristles leaning towards +x: moving with the lean
                   the bristles bend over, a low force built over a long, soft path;
                   moving against it they stand up and dig in, a high force built over a
                   short, stiff path (brush seal hysteresis, Chupp and Dowler 1993):
                   direction-dependent levels *and* presliding paths
stribeck_shape     ``eddy_brake``: a conductive fin of the carriage runs between
                   permanent magnets (an eddy-current brake, a magnetic damper): its drag
                   rises linearly with the speed and falls beyond the critical speed at
                   which the eddy currents' own field expels the magnets' (the skin
                   effect; Wouterse 1991): 2 F_max u / (1 + u^2), u = v / v_crit
position           ``rail_joint``: the rail is butt-jointed from two pieces where fit and
                   held-out parts both pass, the piece on the +x side a little higher:
                   while the carriage straddles the joint the share of its rolling
                   elements on the high piece carries more preload (levels up with that
                   share, which grows linearly across the carriage's loaded length) and
                   the extra elastic energy pushes it back towards -x (a conservative
                   force while it straddles)
inertia            ``abbe_pitch``: the linear scale is read at a height off the
                   carriage's centre of mass (an Abbe offset) and the carriage pitches on
                   its guides' compliance under the acceleration's moment (a pitch mode):
                   the read acceleration carries the scale head's pitch motion, so the
                   inverse dynamics misses the mass times a high-passed acceleration
                   (s^2 / (s^2 + 2 zeta omega s + omega^2) of a)
delay              ``gauge_snubber``: the force read as a pressure through a gauge
                   snubber (an orifice restrictor) into the transducer's volume: the
                   flow through it has a laminar and a turbulent part (Delta p = R_l Q +
                   R_t Q |Q|), so the reading lags the force by a time that grows with
                   the force's rate of change
drift              ``film_dewetting``: the thin lubricant film on the track dewets:
                   holes nucleate after an incubation time and grow at a constant speed
                   (Reiter 1992), so the bare share of the track follows Avrami's
                   kinetics 1 - exp(-(t / t_d)^3) and the boundary levels rise with it
backlash           ``grease_packed_gap``: drive and contact joined across a play packed
                   with grease (a Bingham plastic, yield stress tau_y): the grease
                   squeezed out of the closing side resists as ~ tau_y / h (a Bingham
                   squeeze film, Covey and Stanmore 1981), so the contact is dragged
                   along before the flanks meet once the thinning gap's force passes its
                   friction: a gradual take-up of the play
gms                ``slip_weakening``: the presliding junctions beside the bristle weaken
                   with their own slip: each one's strength falls linearly from its peak
                   to a residual over a critical slip distance (Rabinowicz 1951; Palmer
                   and Rice 1973) and heals when its slip reverses, so every reversal's
                   presliding curve climbs to a peak and falls back to the sliding level
                   over the slip distance, whatever the speed; at ``s`` = 0 the base
                   itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``eddy_brake`` needs a
Stribeck curve (not the isolator's mre_lugre), ``rail_joint`` a record that revisits its
positions (not the press), ``viscoelastic_rolling`` a load that changes,
``grease_packed_gap`` and ``slip_weakening`` a classic LuGre base (valve, damping rig,
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

__all__ = ["FORMS", "current_ripple_truth", "viscoelastic_rolling_truth",
           "leaning_brush_truth", "eddy_brake_truth", "rail_joint_truth",
           "abbe_pitch_truth", "gauge_snubber_truth", "film_dewetting_truth",
           "grease_packed_gap_truth", "slip_weakening_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "current_ripple", "load": "viscoelastic_rolling",
         "asymmetry": "leaning_brush", "stribeck_shape": "eddy_brake",
         "position": "rail_joint", "inertia": "abbe_pitch",
         "delay": "gauge_snubber", "drift": "film_dewetting",
         "backlash": "grease_packed_gap", "gms": "slip_weakening"}


# -- acceleration ----------------------------------------------------------------------------
#: ``current_ripple``'s velocity amplitude of the contact's ripple at the top acceleration,
#: x the top speed, at strength 1 [-]; the lowest relative level the averaging leaves [-];
#: the speed the averaging is rounded over, x the top speed [-]
RIPPLE_SPEED, RIPPLE_FLOOR, RIPPLE_ROUND = 0.3, 0.05, 1e-4


def _dither_share(v, v_ripple, eps):
    """The friction's share [-] left by averaging its sign over a fast sinusoidal velocity
    ripple of amplitude ``v_ripple`` [m/s] about the velocities ``v`` [m/s]: (2 / pi)
    asin(|v| / v_ripple) below the ripple's amplitude, 1 above (the speeds rounded by
    ``eps`` [m/s], so that no ripple leaves the friction whole)."""
    u = (np.abs(np.asarray(v, float)) + eps) / (np.asarray(v_ripple, float) + eps)
    return np.where(u < 1.0, (2.0 / np.pi) * np.arcsin(np.minimum(u, 1.0)), 1.0)


@on_fine_grid
def current_ripple_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The drive's current controller is a hysteresis (bang-bang) controller whose band
    is a fixed share of the current command: the current, and the drive's force, ripple
    at a high frequency with an amplitude proportional to the thrust, which the inertial
    force m a dominates. The ripple shakes the contact tangentially with a velocity
    amplitude v_r = ``s`` :data:`RIPPLE_SPEED` v99 |a| / a99, and the friction, whose sign
    follows v + v_r sin(omega t), averages over a period to (2 / pi) asin(|v| / v_r) of
    itself where |v| < v_r (:func:`_dither_share`). The Coulomb and Stribeck levels are
    the base's times that share (at least :data:`RIPPLE_FLOOR`), inside the bristle
    dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the controller's relative band (the ripple per unit of
        current), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Hysteresis current control with a band proportional to the command (Bose 1990, An
    adaptive hysteresis-band current control technique of a voltage-fed PWM inverter for
    machine drive system, IEEE Trans. Ind. Electron. 37); friction averaged by a fast
    tangential vibration (Thomsen 1999, Using fast vibrations to quench friction-induced
    oscillations, J. Sound Vib. 228; Armstrong-Helouvry, Dupont and Canudas de Wit 1994).
    The candidate raises the levels with |a|, lagged, tilts them with a and adds a force
    odd in a; the open forms lag the velocity, a film or a contact state, heat the
    contact, skid or push rolling elements, move load between rows or supports, press
    seals, pull with the thrust, squeeze or starve films, dilate, lift on a wedge, shift a
    gib, soften an elastomer, swing a roller arm, unload by the jerk or tilt a pressurised
    film. Here the acceleration *lowers* the friction, and only where the speed is low
    against the ripple it sets: most at the reversals of a strong acceleration.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    v99 = max(sc["v99"], 1e-12)
    a99 = max(sc["a99"], 1e-12)
    v_r = float(s) * RIPPLE_SPEED * v99 * np.abs(np.asarray(kin.a, float)) / a99
    share = _dither_share(kin.v, v_r, RIPPLE_ROUND * v99)
    lev = np.maximum(share, RIPPLE_FLOOR)
    return level_inside(kin, lev, np.ones_like(lev))


# -- load ------------------------------------------------------------------------------------
#: ``viscoelastic_rolling``'s rolling resistance at the record's top load (its 99th
#: percentile) and the track's peak loss, x the friction level, at strength 1 [-]; the
#: speed of peak loss at the record's mean load, x the top speed [-]
ROLL_SHARE, ROLL_PEAK = 0.6, 0.3


def _rolling_loss(v, load, v_peak, mean_load, top_load):
    """The roller's hysteresis rolling resistance [-] (1 at the load ``top_load`` [N] and
    the peak loss) at the velocities ``v`` [m/s] and loads ``load`` [N]: (L / L_top)^(4/3)
    x 2 u / (1 + u^2), the standard linear solid's loss factor over its peak at the rate u
    = (v / ``v_peak``) (L / ``mean_load``)^(-1/3) (the contact's half-width ~ L^(1/3)
    sets the excitation rate v / a); odd in v, nothing at rest."""
    L = np.maximum(np.abs(np.asarray(load, float)), 1e-9 * mean_load)
    u = (np.asarray(v, float) / v_peak) * (mean_load / L) ** (1.0 / 3.0)
    return (L / top_load) ** (4.0 / 3.0) * 2.0 * u / (1.0 + u * u)


@on_fine_grid
def viscoelastic_rolling_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A hard support roller of the carriage (a cam follower, a guide wheel) runs under the
    normal load on a viscoelastic track (a polyurethane-coated rail, a polymer liner).
    The track is deformed ahead of the contact and recovers late behind it, so its
    pressure is asymmetric and resists the rolling: the hysteresis rolling resistance
    F_r = alpha (3 / 16) L a / R, a ~ (L R / E*)^(1/3) the contact's half-width, so F_r ~
    L^(4/3), with alpha the track's loss at the excitation rate v / a (a standard linear
    solid's 2 u / (1 + u^2), u = v tau / a; :func:`_rolling_loss`). The truth adds ``s``
    :data:`ROLL_SHARE` F_level x that loss (1 at the record's top load and the peak loss,
    the peak at :data:`ROLL_PEAK` v99 at the mean load) to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], load [N]) and its base law.
    s : float
        Amplitude factor [-]: the track's loss modulus over its stiffness (the roller's
        share of the load), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Hysteresis rolling resistance (Greenwood, Minshall and Tabor 1961, Hysteresis losses
    in rolling and sliding friction, Proc. R. Soc. A 259; Johnson 1985, Contact Mechanics,
    ch. 8; Persson 2010, Rolling friction for hard cylinder and sphere on viscoelastic
    solids, Eur. Phys. J. E 33). The candidate's levels are affine in the load (two
    regimes); the open forms scale them with a power of the load from zero, in one
    direction, through the Stribeck velocity, a film, a step, a creep, a rate, a lever's
    play, a plastic area, a hinge, a cavitating film, a pressure-viscous film, an erf
    area, a flash temperature, a relay, a renewal over the slip, an adhesive area, the
    position of the load, a preload's relief or a ploughing onset. Here a drag of its own
    beside the friction, nothing at rest, whose speed of peak loss moves with the load:
    load and speed enter together.
    """
    L = np.asarray(kin.load, float)
    Lm = max(float(np.mean(np.abs(L))), 1e-300)
    if not np.ptp(L) > 1e-9 * Lm:
        raise ValueError(f"load (viscoelastic_rolling): the {kin.plant} record's load does "
                         f"not change")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    top = max(float(np.percentile(np.abs(L), 99.0)), 1e-300)
    v_peak = ROLL_PEAK * max(kin.scales["v99"], 1e-12)
    loss = _rolling_loss(kin.v, L, v_peak, Lm, top)
    return F + float(s) * ROLL_SHARE * _level(kin) * loss


# -- asymmetry -------------------------------------------------------------------------------
#: ``leaning_brush``'s sliding force moving with the bristles' lean (+x) and against it
#: (-x), x the friction level, at strength 1 [-]; the travel over which each builds up, x
#: the stroke [-]
BRUSH_WITH, BRUSH_AGAINST, BRUSH_PATH_WITH, BRUSH_PATH_AGAINST = 0.25, 0.8, 0.03, 0.004


@njit(cache=True)
def _brush(x, f_with, f_against, p_with, p_against):
    """The brush's force [N] along the positions ``x`` [m]: moving in +x (with the lean)
    it approaches ``f_with`` [N] exponentially over the travel ``p_with`` [m], moving in
    -x (against it) -``f_against`` [N] over ``p_against`` [m] (a Dahl law of each
    direction's own level and path, exact for a piecewise-linear path). Starts unloaded."""
    n = x.size
    out = np.empty(n)
    f = 0.0
    out[0] = 0.0
    for k in range(1, n):
        dx = x[k] - x[k - 1]
        if dx > 0.0:
            f = f_with + (f - f_with) * math.exp(-dx / p_with)
        elif dx < 0.0:
            f = -f_against + (f + f_against) * math.exp(dx / p_against)
        out[k] = f
    return out


@on_fine_grid
def leaning_brush_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A strip brush on the carriage (a way wiper's bristles, a brush seal) sweeps the way
    with its bristles leaning towards +x. Moving with the lean (v > 0) the bristles bend
    further over and their tips slide after a long, soft deflection: the force builds
    over :data:`BRUSH_PATH_WITH` x the stroke to ``s`` :data:`BRUSH_WITH` F_level. Moving
    against it (v < 0) they stand up, stiffen and dig their tips in: the force builds over
    the short :data:`BRUSH_PATH_AGAINST` x the stroke to ``s`` :data:`BRUSH_AGAINST`
    F_level (:func:`_brush`). The truth adds the brush's force to the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the brush's bristle density (its force per unit of
        deflection and its sliding force), / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The frictional hysteresis of inclined bristle packs (Chupp and Dowler 1993,
    Performance characteristics of brush seals for limited-life engines, J. Eng. Gas
    Turbines Power 115; Demiroglu, Gursoy and Tichy 2004; the anisotropic friction of
    inclined fibres, Tramsen et al. 2018). The candidate changes the levels and offsets
    with the direction; the open forms twin levels, curves or slopes, add a tail, roll a
    lip, take the thrust on other bearings, drag a seal's film, climb a texture, hold a
    spring, wedge a pad, a sprag or grooves, throttle an exhaust, unbalance a cylinder's
    areas, buckle a cable, bulldoze chips, shift the commutation, bend a belt over an
    idler, lock a freewheel, oil ahead of the carriage or ride a running belt. Here the
    two directions differ in their presliding too: after each reversal the force turns
    over a path ten times shorter one way than the other.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    stroke = max(float(np.ptp(kin.x)), 1e-12)
    lev = _level(kin)
    f = _brush(np.ascontiguousarray(kin.x, dtype=float), float(s) * BRUSH_WITH * lev,
               float(s) * BRUSH_AGAINST * lev, BRUSH_PATH_WITH * stroke,
               BRUSH_PATH_AGAINST * stroke)
    return F + f


# -- stribeck_shape --------------------------------------------------------------------------
#: ``eddy_brake``'s peak drag (at the critical speed), x the Coulomb level, at strength 1
#: [-]; the critical speed, x the top speed [-]
EDDY_DRAG, EDDY_CRIT = 0.4, 0.35


def _eddy_drag(u):
    """The eddy-current brake's drag [-] (1 at its peak) at the relative speeds ``u`` =
    v / v_crit [-]: 2 u / (1 + u^2), linear below the critical speed, falling as 2 / u
    above it (the eddy currents' field expels the magnets'); odd in ``u``."""
    u = np.asarray(u, float)
    return 2.0 * u / (1.0 + u * u)


@on_fine_grid
def eddy_brake_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A conductive fin (a copper or aluminium plate) on the carriage runs through the gap
    of permanent magnets on the frame (an eddy-current brake, a magnetic damper). The
    moving conductor carries eddy currents whose force on it opposes the motion: at low
    speeds in proportion to the speed (a viscous drag); at higher speeds the eddy
    currents' own field cancels the magnets' in the plate (the magnetic Reynolds number
    passes 1) and the drag falls: 2 F_max u / (1 + u^2), u = v / v_crit
    (:func:`_eddy_drag`). The truth adds ``s`` :data:`EDDY_DRAG` F_c x that to the base,
    v_crit = :data:`EDDY_CRIT` v99.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (with a Stribeck curve).
    s : float
        Amplitude factor [-]: the magnets' flux squared times the fin's conductivity, /
        its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The eddy-current brake's speed-drag characteristic with its critical speed (Wouterse
    1991, Critical torque and speed of eddy current brake with widely separated soft iron
    poles, IEE Proc. B 138; Heald 1988, Magnetic braking: improved theory, Am. J. Phys.
    56). The candidate reshapes the Stribeck curve; the open forms add a tail, a rational
    drop, a film's root, a spike, a lift-off, two roughness scales, a log weakening, an
    Eyring film, starvation, an elastomer's loss, a resonance, a dither, a melt, a
    granular flow, a readsorption, a heated film, a turbulent film, a thixotropic
    grease, a churning drag, core losses or a bellows' breathing. Here a drag beside the
    friction that rises and then falls with the speed: highest at a speed of its own,
    far above the Stribeck velocity.
    """
    law = kin.base
    if not has_stribeck_curve(kin):
        raise ValueError("stribeck_shape (eddy_brake): the mre_lugre base has no Stribeck "
                         "curve")
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    v_crit = EDDY_CRIT * max(kin.scales["v99"], 1e-12)
    return F + float(s) * EDDY_DRAG * float(law.params.Fc) * _eddy_drag(kin.v / v_crit)


# -- position --------------------------------------------------------------------------------
#: ``rail_joint``'s loaded length of the carriage, x the stroke [-]; the levels' rise with
#: the whole loaded length on the high piece, at strength 1 [-]; the push back while the
#: carriage straddles the joint, x the friction level, at strength 1 [-]; the share of the
#: loaded length the straddle's ends are rounded over [-]
JOINT_LENGTH, JOINT_RISE, JOINT_PUSH, JOINT_ROUND = 0.15, 0.5, 0.3, 0.05


def _straddle(x, joint, length, rounding):
    """The share [-] of the carriage's loaded length ``length`` [m] past the joint at
    ``joint`` [m] along the carriage's (centre) positions ``x`` [m], and its derivative
    [1/m]: 0 before, rising linearly across the joint, 1 after (the ends rounded over
    ``rounding`` x the length). Returns (share, d share / dx)."""
    u = (np.asarray(x, float) - joint) / length + 0.5
    e = rounding
    share = _smooth_max0(u, e) - _smooth_max0(u - 1.0, e)
    du = 0.5 * (u / np.sqrt(u * u + e * e) - (u - 1.0) / np.sqrt((u - 1.0) ** 2 + e * e))
    return share, du / length


@on_fine_grid
def rail_joint_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The guide rail is butt-jointed from two pieces, the joint where fit and held-out
    parts both pass (:func:`.truths._bump_centre`), the piece on the +x side a little
    higher. While the carriage (its loaded length :data:`JOINT_LENGTH` x the stroke)
    straddles the joint, the share of its rolling elements on the high piece
    (:func:`_straddle`) is compressed further: the Coulomb and Stribeck levels are the
    base's times 1 + ``s`` :data:`JOINT_RISE` x that share (inside the bristle dynamics;
    the viscous term is the base's), and the elastic energy the step stores, which grows
    with the share, pushes the carriage back towards -x: a conservative force ``s``
    :data:`JOINT_PUSH` F_level x length x d share / dx, whatever the direction of travel.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m]) and its base law.
    s : float
        Amplitude factor [-]: the step's height, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Butt-jointed rails of linear guides and the makers' allowance for the step at their
    joints (THK and HIWIN catalogues: butt-jointed rails, matched joint marks; the preload
    of a rolling element ~ its interference^1.5, Harris and Kotzalas 2007). The candidate
    maps the levels over the position; the open forms bump, wave, step, rectify, bow,
    coat, cog, taper, oil, cushion, cover, spring, drill, immerse, sag, hang, curve,
    drag a chain, cam, heat or dent the stroke. Here a level that ramps across one
    carriage length at the joint, with a force that pushes one way on that ramp in both
    directions of travel.
    """
    centre = _bump_centre(kin)
    if centre is None:
        raise ValueError(f"position (rail_joint): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    if s <= 0.0:
        return _base_parts(kin)[0]
    length = JOINT_LENGTH * max(float(np.ptp(kin.x)), 1e-12)
    share, dshare = _straddle(kin.x, centre, length, JOINT_ROUND)
    lev = 1.0 + float(s) * JOINT_RISE * share
    F = level_inside(kin, lev, np.ones_like(lev))
    return F + float(s) * JOINT_PUSH * _level(kin) * length * dshare


# -- inertia ---------------------------------------------------------------------------------
#: ``abbe_pitch``'s mass x the scale's pitch response, x the friction level / a99, at
#: strength 1 [-]; the pitch mode's angular frequency, x 1 / the motion's time scale v99 /
#: a99 [-]; its damping ratio [-]
PITCH_MASS, PITCH_FREQ, PITCH_DAMPING = 1.0, 4.0, 0.15


def _pitch_highpass(t, a, omega, zeta):
    """The acceleration ``a`` [m/s^2] along the times ``t`` [s] (uniform) through the
    scale head's pitch response s^2 / (s^2 + 2 ``zeta`` ``omega`` s + ``omega``^2) [-]
    (the pitch follows the acceleration through the pitch mode; the head reads its second
    derivative), discretised by the bilinear transform, from rest at the first value."""
    from scipy.signal import bilinear, lfilter, lfilter_zi
    fs = 1.0 / float(t[1] - t[0])
    b, den = bilinear([1.0, 0.0, 0.0], [1.0, 2.0 * zeta * omega, omega * omega], fs)
    a = np.asarray(a, float)
    return lfilter(b, den, a, zi=lfilter_zi(b, den) * a[0])[0]


@on_fine_grid
def abbe_pitch_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The motion is read by a linear scale whose head sits at a height h off the
    carriage's centre of mass (an Abbe offset), and the carriage pitches on its guides'
    compliance: the acceleration's moment tilts it through a pitch mode of angular
    frequency :data:`PITCH_FREQ` / (v99 / a99) and damping ratio :data:`PITCH_DAMPING`.
    The head reads the centre's travel plus h theta, so the recorded acceleration carries
    h theta'' and the inverse dynamics, which subtracts the mass times the recorded
    acceleration, misses m h theta'': the mass times the acceleration through the
    high-pass s^2 / (s^2 + 2 zeta omega s + omega^2) (:func:`_pitch_highpass`), m a99 =
    ``s`` :data:`PITCH_MASS` x the friction level. The truth adds that to the base (the
    friction at the centre's speed, which differs from the read one by h theta', is taken
    as the read one's).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the mass times the Abbe offset over the pitch stiffness, /
        its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The Abbe principle and the Abbe error of an offset scale (Abbe 1890; Bryan 1979, The
    Abbe principle revisited, Precis. Eng. 1); carriage pitch on the guides' compliance
    under acceleration in machine tool axes (Altintas 2012, Manufacturing Automation, ch.
    6; Okwudire and Altintas 2009). The candidate is a mass error times the acceleration;
    the open forms filter it, take it raw, add a second mass, a chain, a geared or lossy
    inertia, an added mass, a dispensing tank, a sliding payload, a rattling part, a
    flywheel, a pick, eddy or fluid couplings, flyweights, a stage, a recoiling frame, a
    saturating motor, a sprocket, a screw's spring or a feedforward's lead. Here the
    missed force is high-passed: the acceleration's slow part is read right and only its
    changes, seen through the pitch mode, are missed.
    """
    F = _base_parts(kin)[0]
    if s <= 0.0:
        return F
    sc = kin.scales
    omega = PITCH_FREQ / max(_motion_time(kin), 1e-12)
    hp = _pitch_highpass(np.asarray(kin.t, float), kin.a, omega, PITCH_DAMPING)
    m = float(s) * PITCH_MASS * _level(kin) / max(sc["a99"], 1e-12)
    return F + m * hp


# -- delay -----------------------------------------------------------------------------------
#: ``gauge_snubber``'s lag of the reading at the force's top rate (its 99th percentile), in
#: data samples, at strength 1 [-]; the laminar part of that lag [-]
SNUB_SAMPLES, SNUB_LAMINAR = 3.0, 0.2


@njit(cache=True)
def _snubbed(F, h, lam, turb):
    """The reading [N] of the force ``F`` [N] (steps ``h`` [s]) behind an orifice
    snubber: the reading's rate Q [N/s] and the difference e = F - reading [N] obey |e| =
    ``lam`` |Q| + ``turb`` Q^2 (the restrictor's laminar ``lam`` [s] and turbulent
    ``turb`` [s^2/N] parts), integrated by backward Euler (exact root of the step's
    quadratic). Starts at the first value."""
    n = F.size
    y = np.empty(n)
    y[0] = F[0]
    c1 = lam / h + 1.0
    c2 = turb / (h * h)
    for k in range(1, n):
        e0 = F[k] - y[k - 1]
        E = abs(e0)
        q = 2.0 * E / (c1 + math.sqrt(c1 * c1 + 4.0 * c2 * E))
        y[k] = y[k - 1] + (q if e0 >= 0.0 else -q)
    return y


@on_fine_grid
def gauge_snubber_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force is read as a pressure (a hydraulic cylinder's, a hydraulic load cell's)
    whose transducer sits behind a gauge snubber, a restrictor that protects it from
    pressure spikes: the oil flows through the restrictor into the transducer's volume,
    laminar and turbulent, Delta p = R_l Q + R_t Q |Q|, and the transducer's pressure
    rises with the volume that has flowed in. In force units the reading's rate Q and
    the difference e = F - reading obey |e| = lam |Q| + turb Q^2 (:func:`_snubbed`): it
    follows a ramp of rate R late by lam + turb R, a lag that grows with the force's rate.
    At the force's top rate R99 the lag is ``s`` :data:`SNUB_SAMPLES` data samples, of
    which :data:`SNUB_LAMINAR` laminar. No cap at :data:`.truths.MAX_DELAY_SAMPLES`: the
    plants whose force turns gently need a slow snubber to reach the requested size.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the restrictor's resistance, / its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Pressure gauge snubbers and restrictors (ASME B40.100, Pressure gauges and gauge
    attachments; Doebelin 2004, Measurement Systems, ch. 6, the dynamics of pressure
    measuring systems); orifice flow's square law (Merritt 1967, Hydraulic Control
    Systems, ch. 3). The open forms delay by one amount, filter by a low-pass, linearly or
    by rank, hold at a fieldbus's clock, let the delay drift, wander or follow the force's
    rate, level or slowness, the motion's speed or the position, hold stale values over
    lost telegrams, lead through a leaking charge, creep, take out the mains' band, track
    with a rate state or ring in a resonance. Here a restriction with a square law: no
    hard limit to the reading's rate, but a lag that grows smoothly and without bound
    with the force's rate of change.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    F = np.asarray(F, float)
    rate = np.abs(np.gradient(F, float(kin.dt)))
    r99 = max(float(np.percentile(rate, 99.0)), 1e-300)
    lag = float(s) * SNUB_SAMPLES * float(kin.sample_dt)
    lam = SNUB_LAMINAR * lag
    turb = (1.0 - SNUB_LAMINAR) * lag / r99
    return _snubbed(F, float(kin.dt), lam, turb)


# -- drift -----------------------------------------------------------------------------------
#: ``film_dewetting``'s rise of the levels with the whole track bare, at strength 1 [-]; the
#: incubation time, x the record's length [-]; the Avrami time, x the record's length [-];
#: Avrami's exponent (constant nucleation, two-dimensional growth) [-]
DEWET_RISE, DEWET_ONSET, DEWET_TIME, DEWET_ORDER = 0.6, 0.15, 0.6, 3.0


def _bare_share(t, onset, t_d, order):
    """The bare share of the track [-] along the times ``t`` [s]: Avrami's 1 - exp(-((t -
    ``onset``)_+ / ``t_d``)^``order``) (holes nucleating at a steady rate after the
    incubation ``onset`` [s] and growing at a constant speed; ``t_d`` [s])."""
    u = np.maximum(np.asarray(t, float) - onset, 0.0) / t_d
    return 1.0 - np.exp(-u ** order)


@on_fine_grid
def film_dewetting_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The track carries a thin lubricant film (a light oil, a fluorinated or silicone
    film) on a surface it does not wet well: the film is unstable and dewets. After an
    incubation time of :data:`DEWET_ONSET` x the record, holes nucleate at a steady rate
    and grow at a constant speed (a dry hole's rim advances at the dewetting speed), so
    the bare share follows Avrami's kinetics 1 - exp(-(t / t_d)^3) with t_d =
    :data:`DEWET_TIME` x the record (:func:`_bare_share`). The boundary friction on the
    bare track is higher: the Coulomb and Stribeck levels are the base's times 1 + ``s``
    :data:`DEWET_RISE` x the bare share, inside the bristle dynamics; the viscous term is
    the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the bare track's friction over the wetted one's, less 1, /
        its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Dewetting of thin films by nucleated holes (Reiter 1992, Dewetting of thin polymer
    films, Phys. Rev. Lett. 68; Redon, Brochard-Wyart and Rondelez 1991, Dynamics of
    dewetting, Phys. Rev. Lett. 66); the kinetics of nucleation and growth (Avrami 1939,
    J. Chem. Phys. 7). The candidate is a trend, a saturating change, a step, a cycle, an
    accelerating part, a part that builds up and resets and a part that follows the
    friction's heating; the open forms warm up, wear in, step, cycle, rise and fall with
    debris, drop with grease shots, relax, oxidise, wear through, swell, grow a
    tribofilm, take in particles, expand, shear the oil, heat the magnets, charge the
    surfaces, creep a cage or loosen a screw. Here nothing happens for a while, then the
    levels rise along a cubic-exponential sigmoid of the clock, neither the travel nor
    the friction's work.
    """
    if s <= 0.0:
        return _base_parts(kin)[0]
    t = np.asarray(kin.t, float)
    T = max(float(t[-1] - t[0]), 1e-12)
    bare = _bare_share(t - t[0], DEWET_ONSET * T, DEWET_TIME * T, DEWET_ORDER)
    lev = 1.0 + float(s) * DEWET_RISE * bare
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: ``grease_packed_gap``'s play at strength 1, as a share of the stroke [-]; the grease's
#: squeeze force with the contact in the middle of the play, x the Coulomb level [-]; the
#: thinnest gap the grease is squeezed to, x the half play [-]; the relative speed the
#: grease's yield is rounded over, x the top speed [-]
GREASE_PLAY, GREASE_YIELD, GREASE_FLOOR, GREASE_ROUND = 0.008, 0.3, 0.05, 0.02


@njit(cache=True)
def _greased_play(h, xd, half, g_yield, floor, v_round, kh, ch, m, s0, s1, s2, Fc, Fs, vs,
                  alpha, shape):
    """LuGre friction [N] of a contact of mass ``m`` [kg] driven by the drive positions
    ``xd`` [m] (step ``h`` [s]) across a play of half-width ``half`` [m] packed with grease:
    inside the play the grease squeezed out of the closing side pushes with its yield
    force ``g_yield`` [N] x ``half`` / the closing gap (at least ``floor`` x ``half``),
    tanh-rounded over the relative speed ``v_round`` [m/s] (a Bingham squeeze film); at the
    flanks a spring ``kh`` [N/m] and damper ``ch`` [N s/m], compressive only. Semi-implicit
    Euler of the mass (:func:`.truths._light_contact_step`). Starts at rest, centred."""
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
            f2 = kh * (e - half) + ch * ed
            if f2 > 0.0:
                fc = f2
        elif e < -half:
            f2 = kh * (e + half) + ch * ed
            if f2 < 0.0:
                fc = f2
        else:
            # the closing side: ahead of the drive's relative motion
            gap = half - e if ed >= 0.0 else half + e
            gap = max(gap, floor * half)
            fc = g_yield * (half / gap) * math.tanh(ed / v_round)
        F[j], v, z = _light_contact_step(v, z, fc, h, m, s0, s1, s2, Fc, Fs, vs, alpha, shape)
        x = x + h * v
    return F


@on_fine_grid
def grease_packed_gap_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact joined across a play of half-width ``s``^2 :data:`GREASE_PLAY` /
    2 x the stroke that is packed with grease (a greased gear mesh or keyway). Grease is a
    Bingham plastic: squeezed between the closing flanks it flows only past its yield
    stress, and a plate squeezing a Bingham layer of thickness h feels ~ tau_y / h. So
    as the drive crosses the play after a reversal the grease on the closing side pushes
    the contact with :data:`GREASE_YIELD` F_c x half / h (h the closing gap, at least
    :data:`GREASE_FLOOR` x half; :func:`_greased_play`): with the gap thinning it passes
    the contact's friction and drags the contact along before the flanks meet. The
    contact is light (:func:`.truths._contact_constants`), with the base's LuGre
    friction; the measured force is its friction. At ``s`` = 0 the base itself.

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
    Squeeze films of Bingham plastics (Covey and Stanmore 1981, Use of the parallel-plate
    plastometer for the characterisation of viscous fluids with a yield stress, J.
    Non-Newtonian Fluid Mech. 8); greases as Bingham (Herschel-Bulkley) fluids (Lugt
    2013, Grease Lubrication in Rolling Bearings, ch. 6). The candidate holds or frees the
    force across a play, with a bias, a spring or a drag across it; the open forms couple
    rigidly, compliantly, by impacts, springs, oil in the play, an idler, a bias, chains,
    magnets, a preload, a hardening gear, a slipping rope, a rubber spider, an oil column,
    a cable in a sheath, a clutch, a mesh of varying stiffness or a warming plastic gear,
    with a play varying with the position or the travel. Here a plastic, not a viscous,
    medium fills the play: a force that does not vanish with the relative speed and grows
    as the gap closes, so the play is taken up gradually at a gap set by the friction.
    """
    p = _lugre_params(kin, "backlash (grease_packed_gap)")
    if s <= 0.0:
        return _base_parts(kin)[0]
    m, kh, ch = _contact_constants(kin, p)
    stroke = float(np.ptp(kin.x))
    Fc = float(p.Fc)
    half = 0.5 * float(s) ** 2 * GREASE_PLAY * stroke
    g_yield = GREASE_YIELD * Fc
    v_round = GREASE_ROUND * max(kin.scales["v99"], 1e-12)
    # the grease's stiffest drag: its yield force at the thinnest gap over the rounding
    c_grease = g_yield / GREASE_FLOOR / v_round
    h, xd, n_sub = _substeps(kin, max(math.sqrt((kh + float(p.sigma0)) / m),
                                      (float(p.sigma1) + float(p.sigma2) + ch + c_grease) / m))
    F = _greased_play(h, xd, half, g_yield, GREASE_FLOOR, v_round, kh, ch, m,
                      float(p.sigma0), float(p.sigma1), float(p.sigma2), Fc, float(p.Fs),
                      float(p.vs), float(p.alpha), SHAPES[p.shape])
    return F[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: the junctions' travel to their peak at strength 1, beyond the base bristle's path, as a
#: share of the stroke / 3 [-]; their share of the friction at strength 1 [-]; the
#: junctions [-]; the residual strength over the peak [-]; the critical slip distance, x the
#: strongest junction's elastic travel [-]
WEAK_SLIP, WEAK_SHARE, WEAK_BLOCKS, WEAK_RESIDUAL, WEAK_DIST = 0.1, 0.6, 10, 0.7, 2.0


@njit(cache=True)
def _weakening_junctions(x, caps, kp, residual, dc):
    """The junctions' force f [-] (over their summed residual strengths: 1 while they all
    slide) along the positions ``x`` [m]: junction i sits at u_i [m], pulled by ``kp`` (x -
    u_i); its strength falls linearly from ``caps``[i] to ``residual`` x ``caps``[i] over
    the slip ``dc`` [m] it has made since its slip last changed direction (it heals at
    once when its slip reverses); where the pull passes the strength it slips to the
    force its weakened strength allows (a linear equation on the weakening branch, the
    residual beyond it). Starts unloaded."""
    n = x.size
    m = caps.size
    u = np.full(m, x[0])
    slip = np.zeros(m)
    last = np.zeros(m)
    out = np.empty(n)
    out[0] = 0.0
    norm = residual * np.sum(caps)
    for k in range(1, n):
        xk = x[k]
        tot = 0.0
        for i in range(m):
            f = kp * (xk - u[i])
            sg = 1.0 if f > 0.0 else -1.0
            d = slip[i] if sg == last[i] else 0.0
            c = caps[i]
            cap = c * (residual + (1.0 - residual) * max(0.0, 1.0 - d / dc))
            if abs(f) > cap:
                e0 = abs(f) / kp
                w = c * (1.0 - residual) / dc
                dl = (kp * e0 - c + w * d) / (kp - w)
                if d + dl > dc:
                    dl = e0 - c * residual / kp
                dl = max(dl, 0.0)
                u[i] += sg * dl
                slip[i] = d + dl
                last[i] = sg
            tot += kp * (xk - u[i])
        out[k] = tot / norm
    return out


@on_fine_grid
def slip_weakening_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The presliding junctions beside the bristle (:data:`WEAK_BLOCKS` of them, peak
    strengths 0.5 to 1, all of the same stiffness) weaken with their own slip: once a
    junction slips its strength falls linearly from its peak to :data:`WEAK_RESIDUAL` of
    it over a critical slip distance (:data:`WEAK_DIST` x the strongest one's elastic
    travel), and it heals to its peak when its slip reverses (:func:`_weakening_junctions`).
    The strongest junction's travel to its peak is the base bristle's path Fs / sigma0
    plus ``s`` :data:`WEAK_SLIP` x the stroke / 3; a share w = :data:`WEAK_SHARE` min(``s``,
    1) of the friction is the junctions' (their sliding force the Stribeck level, the
    viscous term the base's): F = (1 - w) F_lugre + w (g(v) f + sigma2 v). At ``s`` = 0
    the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the junctions' share (up to ``s`` = 1) and their travel to
        the peak (as the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The static-to-kinetic transition over a critical slip distance (Rabinowicz 1951, The
    nature of the static and kinetic coefficients of friction, J. Appl. Phys. 22) and the
    linear slip-weakening law (Ida 1972; Palmer and Rice 1973, Proc. R. Soc. A 332).
    Maxwell-slip (the candidate) and the open forms use equal, geometric or power-law
    strengths, path laws, an elastic range, rate-dependent creep, Mindlin's 3/2 law,
    multistable tips, bonds, a fabric, a back-stress, a climb out of a nest, capillary
    bridges, a hardening yield, peeling, load-dependent microslip, growing junctions or a
    coupled chain's avalanches. Here each junction's strength is a function of its own
    slip since its last reversal: the presliding curve overshoots the sliding level and
    falls back to it over a distance, not a speed.
    """
    p = _lugre_params(kin, "gms (slip_weakening)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    e0, extra = _presliding_path(kin, s, WEAK_SLIP)
    w = WEAK_SHARE * min(float(s), 1.0)
    v = np.asarray(kin.v, float)
    caps = np.linspace(0.5, 1.0, WEAK_BLOCKS)
    kp = 1.0 / (e0 + extra)          # the strongest junction reaches its peak after e0 + extra
    f = _weakening_junctions(np.ascontiguousarray(kin.x, dtype=float), caps, kp,
                             WEAK_RESIDUAL, WEAK_DIST / kp)
    return (1.0 - w) * F + w * (kin.base.g(v) * f + float(p.sigma2) * v)
