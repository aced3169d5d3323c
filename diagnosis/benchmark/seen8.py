"""The eighth seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-28 (session 13), once, without running the diagnosis on it; run once,
sealed, at the end of session 14's work on the code of a2ccae2: 176 cases, top-1 40.3 %
(71; 41.0 % of the detectable), mean |shrink error| 0.324, wrong names on 29 (16.5 %).
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen7` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen7`,
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
acceleration       ``pitch_squeeze``: a carriage on oil-lubricated plain slideways tilts
                   on its films under the acceleration's moment, the films' squeeze
                   damping making the tilt lag (Reynolds 1886, the squeeze term): while
                   the tilt changes, the closing film's squeeze pressure carries part of
                   the load off the asperities: the levels fall with the tilt's rate,
                   even in a, most where the acceleration changes
load               ``hydrostatic_overload``: a hydrostatic pad carries the load on its
                   film up to its capacity (supply pressure x effective area, Rowe 1983);
                   above it the pad touches down and only the excess is carried by
                   asperities with boundary friction: the levels follow max(L - W_c, 0),
                   a hinge at the capacity
asymmetry          ``sprag_strut``: the contact is pressed by an inclined strut (Spurr's
                   sprag, 1961): the friction force drags the strut steeper one way
                   (self-energising) and flatter the other: the levels are the base's
                   / (1 - c F_f / F99), amplified where the friction is positive, more at
                   its peaks, reduced where it is negative
stribeck_shape     ``contact_resonance``: the surface's roughness (one wavelength)
                   excites the slider's normal contact resonance at v / lambda (Tolstoi
                   1967; Budanov, Kudinov and Tolstoi 1980): the normal vibration relieves
                   the contact, most at the resonance speed: a notch in the curve with a
                   shallower plateau beyond, nothing at rest
position           ``telescopic_cover``: a telescopic way cover's sections are pulled out
                   and pushed in one after the other, each adding its wipers' drag: the
                   cover's drag is a staircase along the stroke that depends on the
                   direction and on which sections the last travel moved
inertia            ``freewheel_flywheel``: a rotating part driven through an overrunning
                   (one-way) clutch: it is a missed mass only while the drive pushes it
                   in the positive direction; when the drive slows faster than the part
                   coasts, or reverses, the clutch overruns and the part spins down on
                   its own bearing
delay              ``running_median``: the force transmitter's causal running median over
                   the last ``s`` samples (a spike filter, Tukey 1977): monotone stretches
                   come ``s`` / 2 samples late, steps keep their edges, peaks are clipped
drift              ``antioxidant_depletion``: the oil's antioxidant is consumed over an
                   induction period, after which the oil oxidises autocatalytically
                   (Denisov; Rasberger 1997; the RPVOT induction time of ASTM D2272): the
                   levels and the viscous term stay, then rise exponentially in time
backlash           ``slack_chain``: drive and contact joined by a chain loop whose slack
                   strands sag as catenaries (Irvine 1981): across the slack the contact
                   is pulled by the difference of the two strands' catenary tensions,
                   ~ 1 / sqrt(slack), which rises steeply as a strand goes taut
gms                ``bond_rupture``: adhesive contacts that bond unstretched, stretch
                   elastically with the sliding and rupture at their own critical stretch
                   (Schallamach 1963; Filippov, Klafter and Urbakh 2004) beside the LuGre
                   bristle: a bond drops its force when it breaks and bonds again,
                   unstretched, a moment later; at ``s`` = 0 the base itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``contact_resonance``
needs a Stribeck curve (not the isolator's mre_lugre), ``telescopic_cover`` a record that
revisits its positions (not the press), ``hydrostatic_overload`` a load that changes,
``slack_chain`` and ``bond_rupture`` a classic LuGre base (valve, damping rig, XML-350);
each raises a ``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from friction.lugre import bristle_update
from friction.shapes import SHAPES, stribeck_g

from ..effects_backlash import PLANT_GAP_SHARE
from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _lag, _level,
                     _lugre_params, _motion_time, _presliding_path, _smooth_max0, _span,
                     level_inside, on_fine_grid)

__all__ = ["FORMS", "pitch_squeeze_truth", "hydrostatic_overload_truth", "sprag_strut_truth",
           "contact_resonance_truth", "telescopic_cover_truth", "freewheel_flywheel_truth",
           "running_median_truth", "antioxidant_depletion_truth", "slack_chain_truth",
           "bond_rupture_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "pitch_squeeze", "load": "hydrostatic_overload",
         "asymmetry": "sprag_strut", "stribeck_shape": "contact_resonance",
         "position": "telescopic_cover", "inertia": "freewheel_flywheel",
         "delay": "running_median", "drift": "antioxidant_depletion",
         "backlash": "slack_chain", "gms": "bond_rupture"}


# -- acceleration ---------------------------------------------------------------------------
#: time constant of ``pitch_squeeze``'s tilt (the films' squeeze damping over their
#: stiffness), x the motion's time scale [-]; the levels' relief per unit of the squeeze
#: film's load share at strength 1 [-]
SQUEEZE_TIME, SQUEEZE_RELIEF = 0.3, 0.5


@on_fine_grid
def pitch_squeeze_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Squeeze films of a tilting carriage on oil-lubricated plain slideways: the
    acceleration's moment tilts the carriage on its films, and their squeeze damping makes
    the tilt theta (in units of the acceleration) follow a through a first-order lag of
    time constant tau = :data:`SQUEEZE_TIME` x the motion's time scale (v99 / a99). While
    the tilt changes, the closing end's film carries a share u / (1 + u) of the load by its
    squeeze pressure, u = |theta'| / q99 (theta' = (a - theta) / tau the tilt's rate, q99
    its 99th percentile over the record), and unloads the asperities: the Coulomb and
    Stribeck levels are the base's times 1 - ``s`` :data:`SQUEEZE_RELIEF` u / (1 + u)
    (floored at 0.05), inside the bristle dynamics; the viscous term (the films' shear) is
    the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the levels' relief per unit of the squeeze's load share, /
        :data:`SQUEEZE_RELIEF`.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Reynolds 1886 (the squeeze term of the film equation: a closing film carries load
    ~ eta dh/dt / h^3); Hamrock, Schmid and Jacobson 2004 (squeeze-film bearings); the
    relief of asperity contacts by a film's load share (Johnson, Greenwood and Poon 1972).
    The candidate is an odd, lagged function of a; the open forms lag the velocity or a
    state, heat the contact, skid rolling elements, move load between ball rows
    (``moment_load``: the same moment, through the rows' Hertzian loads, a function of |a|
    itself), press a seal with a lagged |a| or pull the carriage with the thrust; here the
    levels fall with the *rate* at which the tilt changes: not while a is large and steady,
    but where it rises or falls, in acceleration and braking alike.
    """
    a = np.asarray(kin.a, float)
    tau = SQUEEZE_TIME * _motion_time(kin)
    rate = np.abs(a - _lag(np.asarray(kin.t, float), a, tau)) / tau
    u = rate / max(float(np.percentile(rate, 99)), 1e-300)
    lev = np.clip(1.0 - s * SQUEEZE_RELIEF * u / (1.0 + u), 0.05, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- load -------------------------------------------------------------------------------------
#: the pad's load capacity, as this percentile of the record's load [%]; the rounding of
#: its touch-down, x the mean load [-]; the levels' slope in the asperities' load,
#: relative to the mean load, at strength 1 [-]
CAPACITY_PERCENTILE, TOUCHDOWN_ROUNDING, OVERLOAD_SLOPE = 40.0, 0.05, 0.8


@on_fine_grid
def hydrostatic_overload_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A hydrostatic pad overloaded: its film carries the normal load L up to its capacity
    W_c (the supply pressure times the pad's effective area; here the
    :data:`CAPACITY_PERCENTILE` th percentile of the record's load), without boundary
    friction; above it the pad touches down and the excess L - W_c is carried by the
    asperities (rounded over :data:`TOUCHDOWN_ROUNDING` x the mean load: the pad's tilt).
    The Coulomb and Stribeck levels are the base's times 1 + ``s``
    :data:`OVERLOAD_SLOPE` (E - mean E) / mean |L|, E = max(L - W_c, 0) rounded (floored
    at 0.05), inside the bristle dynamics; the viscous term is the base's. ValueError if
    the load does not change.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (load [N]) and its base law.
    s : float
        Amplitude factor [-]: the levels' slope in the asperities' load relative to the
        mean load, / :data:`OVERLOAD_SLOPE`.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Hydrostatic bearings: load capacity = recess pressure x effective area, limited by the
    supply pressure (Rowe 1983, Hydrostatic and Hybrid Bearing Design); load sharing
    between a film and asperity contacts (Johnson, Greenwood and Poon 1972). The candidate
    and the open forms are laws of the load (affine, a power, one direction, the Stribeck
    velocity, a logistic step where a boundary film breaks down), of its rate, of its
    history or of the load through a play; here nothing of the load reaches the boundary
    friction up to the capacity, and every newton above it does: a hinge, not a step.
    """
    L = np.asarray(kin.load, float)
    L0 = max(float(np.mean(np.abs(L))), 1e-12)
    # a change below 1e-6 of the mean load over the record is round-off, not a change
    if float(np.ptp(L)) <= 1e-6 * L0:
        raise ValueError(f"load (hydrostatic_overload): the {kin.plant} record's load does "
                         f"not change")
    Wc = float(np.percentile(L, CAPACITY_PERCENTILE))
    E = _smooth_max0(L - Wc, TOUCHDOWN_ROUNDING * L0)
    lev = np.clip(1.0 + s * OVERLOAD_SLOPE * (E - float(np.mean(E))) / L0, 0.05, None)
    return level_inside(kin, lev, np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``sprag_strut``'s self-energising gain c per unit strength at small strengths [-], and
#: the gain it approaches (below 1: the strut never locks) [-]
SPRAG_GAIN, SPRAG_LOCK = 0.3, 0.95


@on_fine_grid
def sprag_strut_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A contact pressed by an inclined strut (a sprag): the friction force F_f acts on the
    strut and, sliding one way, drags it steeper and raises the normal force, the other way
    flattens it: N / N0 = 1 / (1 - c F_f / F99) (quasi-static, F_f the base's friction at
    N0, F99 the 99th percentile of |F_f|, F_f / F99 clipped to +-1), c = :data:`SPRAG_LOCK`
    (1 - exp(-``s`` :data:`SPRAG_GAIN` / :data:`SPRAG_LOCK`)) < 1. The Coulomb and Stribeck
    levels are the base's times N / N0, inside the bristle dynamics; the viscous term is
    the base's. At ``s`` = 0 the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid and its base law.
    s : float
        Amplitude factor [-]: the strut's self-energising gain, c ~ ``s``
        :data:`SPRAG_GAIN` at small strengths.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Spurr 1961 (the sprag-slip model of brake squeal: F = mu L / (1 - mu tan theta) for a
    strut at angle theta); self-energising wedge and drum brakes (Roberts et al. 2003, the
    electronic wedge brake). The candidate shifts a direction's levels and viscous slope
    (and an offset); the open forms keep a direction's share at all speeds or move its
    Stribeck velocity, viscous slope or low-speed tail, follow a lip, a thrust, a film, a
    texture, a spring or a lifting wedge film; here the normal force follows the friction
    force itself: one direction is amplified, more at the breakaway peak than in sliding,
    the other is relieved, and presliding forces are amplified by their own sign.
    """
    _, Ff = _base_parts(kin)
    F99 = max(float(np.percentile(np.abs(Ff), 99)), 1e-300)
    c = SPRAG_LOCK * (1.0 - math.exp(-max(float(s), 0.0) * SPRAG_GAIN / SPRAG_LOCK))
    lev = 1.0 / (1.0 - c * np.clip(Ff / F99, -1.0, 1.0))
    return level_inside(kin, lev, np.ones_like(lev))


# -- stribeck_shape --------------------------------------------------------------------------
#: ``contact_resonance``'s resonance speed (the roughness wavelength x the contact's
#: normal natural frequency), x v99 [-]; the resonance's damping ratio [-]; the levels'
#: relief at the resonance at strength 1 [-]
RESONANCE_SPEED, RESONANCE_DAMPING, RESONANCE_RELIEF = 0.25, 0.15, 0.4


def _transmissibility(r, zeta):
    """The normal contact force's fluctuation [-] of a slider on a spring-damper contact
    (damping ratio ``zeta``) following a harmonic roughness at the frequency ratio ``r``
    [-], r^2 / sqrt((1 - r^2)^2 + (2 zeta r)^2), relative to its value at r = 1: 0 at rest,
    about 1 at the resonance, 2 zeta far above it."""
    r2 = r * r
    return 2.0 * zeta * r2 / np.sqrt((1.0 - r2) ** 2 + (2.0 * zeta * r) ** 2)


@on_fine_grid
def contact_resonance_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A normal contact resonance excited by the roughness: the slider rides a roughness of
    one dominant wavelength lambda on the normal stiffness and damping of its contact, so
    the sliding excites its normal mode at v / lambda, resonant at v_r =
    :data:`RESONANCE_SPEED` v99 (damping ratio :data:`RESONANCE_DAMPING`); the normal
    force's fluctuation (the slider's inertia, relative to its value at the resonance,
    :func:`_transmissibility`) relieves the contact's mean friction: the Stribeck curve is
    the base's times 1 - ``s`` :data:`RESONANCE_RELIEF` T(|v| / v_r) (floored at 0.05),
    inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (a Stribeck curve).
    s : float
        Amplitude factor [-]: the relief at the resonance, / :data:`RESONANCE_RELIEF`.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Tolstoi 1967 (significance of the normal degree of freedom and natural normal
    vibrations in contact friction); Budanov, Kudinov and Tolstoi 1980 (interaction of
    friction and vibration); base excitation of a single-degree-of-freedom system (the
    transmitted force). The candidate bends the base's drop (an exponent, the Lorentzian,
    a log-speed map); the open forms add tails, drops, a spike, a lift-off, a second drop,
    a logarithmic weakening, an Eyring strengthening, a rise at the top speed or a hump of
    rubber hysteresis; this one is a notch at one speed, sharp by the resonance's damping,
    and a shallower plateau beyond it, with nothing at rest.
    """
    if kin.base.name == "mre_lugre":
        raise ValueError("stribeck_shape (contact_resonance): the mre_lugre base has no "
                         "Stribeck curve")
    v = np.asarray(kin.v, float)
    r = np.abs(v) / (RESONANCE_SPEED * max(kin.scales["v99"], 1e-12))
    lev = np.clip(1.0 - s * RESONANCE_RELIEF * _transmissibility(r, RESONANCE_DAMPING),
                  0.05, None)
    return level_inside(kin, lev, np.ones_like(v))


# -- position --------------------------------------------------------------------------------
#: ``telescopic_cover``'s sections (each covering a share 1 / COVER_SECTIONS of the stroke
#: the record visits) [-]; one section's drag at strength 1, x the friction level [-]; the
#: travel over which a stop's buffer hands the motion on to the next section, x a
#: section's travel [-]
COVER_SECTIONS, COVER_DRAG, COVER_BUFFER = 5, 0.1, 0.05


@njit(cache=True)
def _cover(x, lo, ell, n_sec, buf):
    """Sections of a telescopic cover (``n_sec`` of travel ``ell`` [m] each, collapsed at
    ``lo`` [m]) moving along the carriage's positions ``x`` [m]: extending, section 1 (on the
    carriage) slides out until its stop, then drags section 2, ...; retracting, section 1
    is pushed in until it nests, then pushes section 2, .... Returns the count of sections
    moving if the carriage extends and if it retracts [-] at each point (each next
    section's share rounded over the last ``buf`` x ``ell`` of the one before: its stop's
    buffer). Starts as if extended from the collapsed end."""
    n = x.size
    e = np.zeros(n_sec)
    d = x[0] - lo
    for i in range(n_sec):
        take = min(max(d, 0.0), ell)
        e[i] = take
        d -= take
    out_ext = np.empty(n)
    out_ret = np.empty(n)
    w = max(buf * ell, 1e-300)
    for k in range(n):
        if k > 0:
            d = x[k] - x[k - 1]
            if d > 0.0:
                for i in range(n_sec):
                    take = min(ell - e[i], d)
                    e[i] += take
                    d -= take
                    if d <= 0.0:
                        break
            elif d < 0.0:
                d = -d
                for i in range(n_sec):
                    take = min(e[i], d)
                    e[i] -= take
                    d -= take
                    if d <= 0.0:
                        break
        ce, cr = 0.0, 0.0
        pe, pr = 1.0, 1.0
        for i in range(n_sec):
            ce += pe
            cr += pr
            # the next section moves once this one is (nearly) at its stop
            pe *= min(max((e[i] - (ell - w)) / w, 0.0), 1.0)
            pr *= min(max((w - e[i]) / w, 0.0), 1.0)
        out_ext[k] = ce
        out_ret[k] = cr
    return out_ext, out_ret


@on_fine_grid
def telescopic_cover_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A telescopic way cover over the stroke the record visits: :data:`COVER_SECTIONS`
    nested sections, each of a 1 / :data:`COVER_SECTIONS` share of the stroke, collapsed at
    its lower end. Extending, the carriage pulls the first section out to its stop, which
    then drags the second, ...; retracting, it pushes the first in until it nests, which
    then pushes the second, ... (:func:`_cover`). Each moving section's wipers add a drag
    ``s`` :data:`COVER_DRAG` x the friction level against the motion (its direction
    rounded over 2 % of v99), added to the base's force.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: one section's drag relative to :data:`COVER_DRAG` x the level.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Telescopic steel way covers of machine tools (sections pulled out and pushed in by
    each other's stops, each with its wipers on the next: a cover's drag of a few percent
    of the axis' friction to several times it, makers' data sheets, e.g. Hennig, Arno
    Arnold); Weck and Brecher 2006 (Werkzeugmaschinen 2, guideway covers). The candidate
    scales the friction along the stroke (a map, a waviness, a defect) and adds a
    periodic force of x; the open forms are level maps (a defect, waviness, a worn section,
    runout, a bow, a transfer film, a taper, a port's wake), a detent force or a cushion's
    drag in one zone; here the drag steps up along the stroke as sections join in, the
    other way round when the carriage comes back, and after a reversal it starts again
    from one section: it depends on where the last travel left the sections, not on x
    alone.
    """
    if _bump_centre(kin) is None:
        raise ValueError(f"position (telescopic_cover): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    x = np.ascontiguousarray(kin.x, dtype=float)
    ell = _span(kin) / COVER_SECTIONS
    ext, ret = _cover(x, kin.scales["x_lo"], ell, COVER_SECTIONS, COVER_BUFFER)
    d = np.tanh(np.asarray(kin.v, float) / (0.02 * max(kin.scales["v99"], 1e-12)))
    count = np.where(d > 0.0, ext, ret)
    F, _ = _base_parts(kin)
    return F + s * COVER_DRAG * _level(kin) * count * d


# -- inertia ---------------------------------------------------------------------------------
#: ``freewheel_flywheel``'s mass at strength 1, x the friction level / a99 [kg per N s^2/m];
#: its coast-down time constant on its own bearing, x the motion's time scale [-]
FLYWHEEL_MASS, FLYWHEEL_COAST = 0.3, 3.0


@njit(cache=True)
def _freewheel(t, v, a, tau):
    """Force per unit mass [m/s^2] a drive moving at the velocities ``v`` [m/s] with the
    accelerations ``a`` [m/s^2] (times ``t`` [s]) exerts on a part it drives through an
    overrunning clutch in the positive direction only: while the drive is not slower than
    the part's speed w (which coasts down as exp(-t / ``tau``) when free), the clutch
    engages, w = v and the drive supplies a + w / tau (the part's acceleration and its
    bearing drag, never negative); otherwise the clutch overruns and it supplies nothing.
    Starts engaged at the drive's speed (or at rest)."""
    n = t.size
    f = np.empty(n)
    w = max(v[0], 0.0)
    f[0] = max(a[0] + w / tau, 0.0) if v[0] >= 0.0 else 0.0
    for k in range(1, n):
        wc = w * math.exp(-(t[k] - t[k - 1]) / tau)
        if v[k] >= wc and a[k] + v[k] / tau > 0.0:
            w = v[k]
            f[k] = a[k] + w / tau
        else:
            w = wc
            f[k] = 0.0
    return f


@on_fine_grid
def freewheel_flywheel_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A rotating part (a roller, a fan, a flywheel; its mass reflected to the axis m =
    ``s`` :data:`FLYWHEEL_MASS` x the friction level / a99) driven through an overrunning
    clutch (a sprag freewheel) in the positive direction only. While the drive is as fast
    as the part and pushes it, the clutch engages: the drive supplies m (a + w / tau), the
    part's inertia and its bearing drag (coast-down time constant tau =
    :data:`FLYWHEEL_COAST` x the motion's time scale), which the inverse dynamics misses;
    when the drive slows faster than the part coasts, or moves back, the clutch overruns
    and the part spins down on its own (:func:`_freewheel`). The measured force is the
    base's plus the drive's force on the part. At ``s`` = 0 the base.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the part's mass relative to :data:`FLYWHEEL_MASS` x level /
        a99.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Overrunning (freewheel, sprag) clutches transmit torque one way only (Orthwein 2004,
    Clutches and Brakes; Chesney and Kremer 1998 on sprag clutches). The candidate and the
    open forms are masses (constant, filtered, along the stroke, through a ratio or a
    lossy gear, in time, behind a spring, in a fluid), a payload held by friction or a
    part rattling in a pocket: all of them follow the motion both ways. Here the part is
    felt only while the drive accelerates it (or holds its speed against its drag) in the
    positive direction, it re-engages with a jolt where the drive catches up with it, and
    braking and negative travel miss nothing.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    m = s * FLYWHEEL_MASS * _level(kin) / max(kin.scales["a99"], 1e-12)
    f = _freewheel(np.ascontiguousarray(kin.t, dtype=float),
                   np.ascontiguousarray(kin.v, dtype=float),
                   np.ascontiguousarray(kin.a, dtype=float), FLYWHEEL_COAST * _motion_time(kin))
    return F + m * f


# -- delay -----------------------------------------------------------------------------------
#: longest window of ``running_median`` [samples]: a delay of 25 samples, the candidate's
#: reach (:attr:`diagnosis.effects_delay.Delay.MAX_SAMPLES`; the open forms stop at
#: :data:`.truths.MAX_DELAY_SAMPLES`, 20, but a median, which cuts the reversals' peaks
#: that a shift keeps, needs a delay of 22 samples for the full size on the valve's 20 kHz
#: record)
MEDIAN_MAX_WINDOW = 50.0


def _causal_median(F, half: int) -> np.ndarray:
    """The causal running median of ``F`` over its last 2 ``half`` + 1 values (the first
    value held before the start): ramps come ``half`` points late; ``half`` <= 0: ``F``."""
    from scipy.ndimage import median_filter
    if half <= 0:
        return np.asarray(F, float)
    # origin = half puts the window on the last values (output k: inputs k - 2 half .. k)
    return median_filter(np.asarray(F, float), size=2 * half + 1, origin=half,
                         mode="nearest")


@on_fine_grid
def running_median_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """The force channel through a causal running median (a spike filter in the force
    transmitter): each output is the median of the continuous force over the last ``s``
    data samples (at most :data:`MEDIAN_MAX_WINDOW`; on the fine grid, to a tenth of a
    sample, the window's points an odd count). Monotone stretches come ``s`` / 2 samples
    late, as through a shift; steps keep their sharp edges (``s`` / 2 late); peaks and
    short spikes, shorter than ``s`` / 2, are cut off. At ``s`` = 0 the force itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (its step ``kin.step`` per data sample) and its base law.
    s : float
        Amplitude factor [-]: the window's length [data samples], twice the delay of
        monotone stretches.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Running medians (Tukey 1977, Exploratory Data Analysis; Gallagher and Wise 1981, the
    root signals of median filters), the spike and impulse filters of weighing and force
    transmitters, set by their window's length. The open forms delay by one amount (a
    shift, held samples), filter linearly (a lag, Bessel, a moving average, a converter's
    FIR, a line's echoes), let the delay drift, wander or grow with the rate, or shift the
    motion; this one is a non-linear, rank-order filter: its delay is exact on ramps, it
    keeps edges that every linear filter rounds, and it flattens the force's reversal
    peaks.
    """
    F, _ = _base_parts(kin)
    return _causal_median(F, int(round(0.5 * min(max(float(s), 0.0), MEDIAN_MAX_WINDOW)
                                       * kin.step)))


# -- drift -----------------------------------------------------------------------------------
#: ``antioxidant_depletion``'s induction period, x the record [-]; the oxidation's
#: e-folding time after it, x the record [-]; the levels' rise at the record's end at
#: strength 1 [-]
INDUCTION, OXIDATION_TIME, OXIDATION_RISE = 0.35, 0.15, 0.4


@on_fine_grid
def antioxidant_depletion_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Antioxidant depletion: the oil's antioxidant is consumed over an induction period
    (:data:`INDUCTION` x the record T); after it the oil oxidises autocatalytically, its
    oxidation products (the radical chain's) growing exponentially with an e-folding time
    of :data:`OXIDATION_TIME` T, thickening the oil and taking the boundary additives: the
    Coulomb and Stribeck levels and the viscous term are the base's times 1 + ``s``
    :data:`OXIDATION_RISE` y, y = (exp(tau / tau_o) - 1) / (exp(tau_end / tau_o) - 1) of
    the time tau since the induction ended (0 before it, 1 at the record's end), inside
    the bristle dynamics.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s]) and its base law.
    s : float
        Amplitude factor [-]: the levels' relative rise at the record's end, /
        :data:`OXIDATION_RISE`.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Autoxidation of hydrocarbons: an induction period while inhibitors last, then an
    autocatalytic, accelerating oxidation (Denisov and Afanas'ev 2005, Oxidation and
    Antioxidants in Organic Chemistry and Biology; Rasberger 1997, oxidative degradation
    and stabilisation of mineral oil based lubricants; the induction time of the RPVOT,
    ASTM D2272); oxidised oil thickens and loses its boundary additives. The candidate is
    a trend, a saturating change and a step; the open forms warm up, wear in, step, heat,
    cycle, rise and fall with debris, drop with grease shots, relax in log time or grow
    an oxide as sqrt(t) and spall; here nothing changes for a third of the record, then
    the levels rise ever faster: a convex, accelerating drift.
    """
    t = np.asarray(kin.t, float)
    T = float(t[-1] - t[0]) or 1.0
    tau = np.clip(t - t[0] - INDUCTION * T, 0.0, None) / (OXIDATION_TIME * T)
    y = np.expm1(tau) / math.expm1((1.0 - INDUCTION) / OXIDATION_TIME)
    lev = 1.0 + max(float(s), 0.0) * OXIDATION_RISE * y
    return level_inside(kin, lev, lev)


# -- backlash --------------------------------------------------------------------------------
#: the slack (the loop's excess length) of ``slack_chain`` at strength 1, as a share of the
#: stroke [-] (the open backlash forms' play); the strands' catenary tension at mid-slack
#: at strength 1, x the contact's static level Fs [-]; the excess length below which a
#: strand is taut (its elastic stretch), x the slack [-]
GAP_SHARE, CHAIN_TENSION, CHAIN_TAUT = PLANT_GAP_SHARE, 0.5, 0.02


@njit(cache=True)
def _strand(e, ed, C, e_min, kh, ch):
    """Tension [N] of a chain strand with excess length ``e`` [m] (its rate ``ed`` [m/s]):
    a catenary C / sqrt(e) (``C`` [N m^0.5]) while slack, taut below ``e_min`` [m] where its
    elastic stretch adds kh (e_min - e) + ch (-ed) (``kh`` [N/m], ``ch`` [N s/m]); never
    negative."""
    if e >= e_min:
        return C / math.sqrt(e)
    T = C / math.sqrt(e_min) + kh * (e_min - e) - ch * ed
    return T if T > 0.0 else 0.0


@njit(cache=True)
def _chain_contact(h, xd, half, C, e_min, m, kh, ch, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a contact of mass ``m`` [kg] pulled through a chain loop by the
    drive positions ``xd`` [m] (grid step ``h`` [s]): the strand ahead and the strand
    behind share the slack 2 ``half`` [m], excess lengths half - u and half + u (u = drive
    - contact), each pulling with its catenary tension (:func:`_strand`). Semi-implicit
    Euler of the mass, the bristle advanced exactly at the contact's velocity
    (:func:`friction.lugre.bristle_update`). Starts centred, at rest, its bristle
    unloaded."""
    n = xd.size
    F = np.empty(n)
    x = xd[0]
    v = 0.0
    z = 0.0
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        u = xd[j] - x
        ud = vd - v
        fc = (_strand(half - u, -ud, C, e_min, kh, ch)
              - _strand(half + u, ud, C, e_min, kh, ch))
        g = stribeck_g(v, Fc, Fs, vs, alpha, shape)
        zd = v - s0 * abs(v) * z / g
        ff = s0 * z + s1 * zd + s2 * v
        F[j] = ff
        v = v + h * (fc - ff) / m
        z = bristle_update(z, v, s0 * abs(v) / stribeck_g(v, Fc, Fs, vs, alpha, shape), h, 0)
        x = x + h * v
    return F


@on_fine_grid
def slack_chain_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact joined by a chain loop with slack: the loop's excess length 2
    ``half``, half = ``s``^2 :data:`GAP_SHARE` / 2 x the stroke, is shared by the strand
    ahead and the strand behind the contact; each sags as a catenary whose tension is C /
    sqrt(its excess length) (C fixed by the chain's weight and span: :data:`CHAIN_TENSION`
    Fs at mid-slack at ``s`` = 1), and goes taut below :data:`CHAIN_TAUT` x the slack (or
    where the catenary would be stiffer than the taut strand; then a coupling 100 x stiffer
    than the bristle, damping ratio 0.5). The
    contact is light, with the base's LuGre friction (:func:`.truths._contact_constants`);
    across the slack it is pulled by the difference of the two tensions, which rises
    steeply as the strand ahead straightens (:func:`_chain_contact`). The measured force is
    the contact's friction. At ``s`` = 0 the chain is taut both ways (the base, up to the
    stiff coupling).

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the square root of the slack relative to :data:`GAP_SHARE` x
        the stroke (a smaller slack also tightens the strands: the catenary's C is fixed;
        on the XML-350's many small reversals the size grows about as the slack's cube
        root, too weakly in the slack itself to be calibrated).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Catenary of a slack strand (a parabola for small sag: tension w l^2 / (8 sag), excess
    length 8 sag^2 / (3 l); Irvine 1981, Cable Structures); slack and sag of roller-chain
    drives (Binder 1956, Mechanics of the Roller Chain Drive). The candidate holds or frees
    the force across the play; the open forms couple it rigidly, compliantly, by impacts,
    a linear spring, an oil film, an idler's drag or a bias, with a play varying with the
    position or growing with the travel; here the bridge across the slack is a pull that
    is weak at mid-slack and hardens as 1 / sqrt of the slack left, so the contact starts
    before the strand is straight, later the more slack there is.
    """
    p = _lugre_params(kin, "backlash (slack_chain)")
    stroke = float(np.ptp(kin.x))
    half1 = 0.5 * GAP_SHARE * stroke
    half = max(float(s), 0.0) ** 2 * half1
    C = CHAIN_TENSION * float(p.Fs) * math.sqrt(half1)
    m, kh, ch = _contact_constants(kin, p)
    # taut below a share of the slack, or where the catenary's stiffness C / (2 e^1.5)
    # would exceed the taut strand's
    e_min = max(CHAIN_TAUT * half, (0.5 * C / kh) ** (2.0 / 3.0))
    rate = max(math.sqrt(2.0 * kh / m),
               (float(p.sigma1) + float(p.sigma2) + 2.0 * ch) / m)
    n_sub = int(min(max(math.ceil(rate * kin.dt / 0.3), 4), 400))
    t2 = kin.t[0] + (kin.dt / n_sub) * np.arange((kin.t.size - 1) * n_sub + 1)
    xd = np.interp(t2, kin.t, kin.x)
    F = _chain_contact(kin.dt / n_sub, xd, half, C, e_min, m, kh, ch, float(p.sigma0),
                       float(p.sigma1), float(p.sigma2), float(p.Fc), float(p.Fs),
                       float(p.vs), float(p.alpha), SHAPES[p.shape])
    return F[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: mean rupture stretch of ``bond_rupture``'s bonds beyond the base bristle's path, as a
#: share of the stroke / 3 [-]; the spread of the contacts' rupture stretches, +- this share
#: of the mean [-]; the bonds' share of the friction at strength 1 [-]; a broken contact's
#: time to bond again, x the mean rupture stretch / v99 [-]; the contacts [-]; the slip
#: over which the bonds' strength follows the Stribeck level, x the mean rupture stretch
#: [-]
PRESLIDING_SHARE, BOND_SPREAD, BOND_SHARE = 0.05, 0.5, 0.5
BOND_WAIT, BOND_CONTACTS, BOND_STRENGTH_RUN = 0.02, 256, 0.1


@njit(cache=True)
def _bonds(t, x, g, thr, wait, run):
    """Mean relative force [-] of adhesive contacts along the positions ``x`` [m] (times
    ``t`` [s]) and their strength [N]: each contact, bonded, pulls with its stretch x -
    anchor (elastic; the anchor where it bonded) and breaks when |stretch| reaches its own
    rupture stretch (``thr`` [m], one per contact); broken, it bonds again, unstretched at
    the current position, ``wait`` [s] later. The force is the bonded contacts' summed
    stretch / (count x mean(thr) / 2) (1 in slow steady sliding); the motion is sub-stepped
    to a 32nd of the mean rupture stretch. The strength follows the Stribeck levels ``g``
    [N] over the slip ``run`` [m]. Starts all bonded, unstretched, at the first level."""
    n = x.size
    nc = thr.size
    lc = np.mean(thr)
    anchor = np.full(nc, x[0])
    bonded = np.ones(nc, dtype=np.bool_)
    broke = np.zeros(nc)
    f = np.zeros(n)
    G = np.empty(n)
    G[0] = g[0]
    for k in range(1, n):
        dx = x[k] - x[k - 1]
        m = max(1, int(math.ceil(32.0 * abs(dx) / lc)))
        for j in range(1, m + 1):
            xc = x[k - 1] + dx * j / m
            tc = t[k - 1] + (t[k] - t[k - 1]) * j / m
            for i in range(nc):
                if bonded[i]:
                    if abs(xc - anchor[i]) >= thr[i]:
                        bonded[i] = False
                        broke[i] = tc
                elif tc - broke[i] >= wait:
                    bonded[i] = True
                    anchor[i] = xc
        acc = 0.0
        for i in range(nc):
            if bonded[i]:
                acc += x[k] - anchor[i]
        f[k] = acc / (0.5 * nc * lc)
        G[k] = g[k] + (G[k - 1] - g[k]) * math.exp(-abs(dx) / run)
    return f, G


@on_fine_grid
def bond_rupture_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Presliding by the kinetics of adhesive bonds beside the bristle: a share w =
    min(:data:`BOND_SHARE` ``s``, 1) of the friction is carried by :data:`BOND_CONTACTS`
    contacts that bond to the counter-surface, unstretched where they bond, stretch
    elastically with the sliding and rupture when their stretch reaches their own rupture
    stretch (spread evenly over 1 +- :data:`BOND_SPREAD` times the mean l_c = the base
    bristle's path Fs / sigma0 plus :data:`PRESLIDING_SHARE` x the stroke / 3); a broken
    contact bonds again after :data:`BOND_WAIT` l_c / v99 (:func:`_bonds`). Their summed
    stretch, over its value in slow steady sliding, is scaled by their strength G, which
    follows the base's Stribeck level g(v) over a slip of :data:`BOND_STRENGTH_RUN` l_c,
    plus the viscous term; the rest by the base's LuGre: F = (1 - w) F_lugre + w (G f +
    sigma2 v). At ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m], v [m/s]) and its base law (a classic
        LuGre).
    s : float
        Amplitude factor [-]: the bonds' share of the friction, / :data:`BOND_SHARE` (all
        of it from ``s`` = 1 / :data:`BOND_SHARE` on).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Schallamach 1963 (a theory of dynamic rubber friction: bonds that form, stretch and
    break); Chernyak and Leonov 1986; Filippov, Klafter and Urbakh 2004 (friction through
    the dynamical formation and rupture of molecular bonds, with a spread of the bonds'
    strengths). Maxwell-slip (the candidate, ``maxwell4``, ``maxwell10``) and the Mindlin
    contacts are elements that slip holding their force, Dahl, Bouc-Wen and Bliman-Sorine
    path laws, elasto-plastic an elastic range, the Zener junction and the rate-and-state
    interface rate-dependent creep, the Tomlinson contacts multistable tips in a fixed
    potential; here the elements are born and die: a bond drops its whole force when it
    ruptures, in either direction, and is replaced by an unstretched one a moment later, so
    after a reversal the contacts unload along their own stretch and break again only
    beyond the opposite rupture stretch.
    """
    p = _lugre_params(kin, "gms (bond_rupture)")
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    # the bonds are what they are at any strength: ``s`` sets their share
    e0, extra = _presliding_path(kin, 1.0, PRESLIDING_SHARE)
    lc = e0 + extra
    thr = lc * (1.0 + BOND_SPREAD * (2.0 * (np.arange(BOND_CONTACTS) + 0.5) / BOND_CONTACTS
                                     - 1.0))
    w = min(BOND_SHARE * float(s), 1.0)
    v = np.ascontiguousarray(kin.v, dtype=float)
    f, G = _bonds(np.ascontiguousarray(kin.t, dtype=float),
                  np.ascontiguousarray(kin.x, dtype=float), kin.base.g(v), thr,
                  BOND_WAIT * lc / max(kin.scales["v99"], 1e-12), BOND_STRENGTH_RUN * lc)
    return (1.0 - w) * F + w * (G * f + float(p.sigma2) * v)
