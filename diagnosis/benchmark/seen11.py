"""The eleventh seen truth family: one more mechanism per effect, sealed until run once.

Written 2026-11-29 (session 16) by another hand, once, without running the diagnosis on it;
run once, sealed, at the end of session 17's work on the code of e33ce5f:
176 cases, 0 skipped, 401 s wall on 2 workers (beside a helper's truth sizing). Top-1 47.7 %
(84; 51.5 % of the 163 detectable; 6 delay cases below a sample); mean |shrink error| 0.300;
wrong names on 26 (14.8 %): inertia -> acceleration 13, drift -> load 4, position -> drift 2.
By form: load/full_contact 19/20, asymmetry/chevron_grooves 19/20, drift/zddp_tribofilm
15/20, acceleration/dilatancy_hardening 10/20, position/immersed_plunger 9/16,
inertia/centrifugal_flyweights 4/20, delay/belt_transit 4/20, stribeck_shape/granular_flow
3/16, backlash/harmonic_drive 1/12, gms/asperity_interlocking 0/12. By plant: press 57.1 %,
damping rig 52.5 %, valve 47.5 %, isolator 42.9 %, XML-350 40.0 %. Since (bd055cd, the
inertia candidate's mass growing with the speed) the flyweights are named in 15 of 20.
Seen since, it is part of the open grid, as :mod:`.seen` to :mod:`.seen10` before it
(figures in ``benchmarks/bench_diagnosis_forms.py``). Each form is a
mechanism of other physics than every open form of its effect before it (:mod:`.truths`,
:mod:`.forms`, :mod:`.seen` to :mod:`.seen10`,
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
acceleration       ``dilatancy_hardening``: a lubricant-filled rough (or debris-laden)
                   interface dilates with the log of the slip speed (Marone, Raleigh and
                   Scholz 1990); while it dilates faster than the oil can flow into its
                   pores the pore pressure falls and the effective normal stress, and
                   the levels, rise; compacting, they fall (dilatancy hardening,
                   Segall and Rice 1995): the levels follow the undrained part of
                   ln(1 + |v| / v*), up while the speed rises, down while it falls
load               ``full_contact``: a soft seal whose real contact area approaches full
                   contact at high pressure (Persson 2001): the area, and the levels,
                   follow erf(L / (sqrt(2) sigma_p)) of the load: nearly proportional at
                   low loads, saturating at high ones
asymmetry          ``chevron_grooves``: a plain slideway with lubrication grooves
                   inclined to the sliding direction (a chevron pattern): the grooves
                   pump oil into the contact one way and out of it the other (viscous
                   pumping, Whipple 1951): the levels fall with the speed in the
                   pumping direction and rise with it in the other, the same amount,
                   saturating at speed
stribeck_shape     ``granular_flow``: the contact is lubricated by a dry powder or wear
                   debris (a third body, Godet 1984) sheared as a dense granular flow,
                   whose friction coefficient rises with the inertial number I ~ |v|
                   as mu_s + (mu_2 - mu_s) I / (I_0 + I) (GDR MiDi 2004; Jop, Forterre
                   and Pouliquen 2006): the levels rise with the speed and saturate
position           ``immersed_plunger``: a plunger entering an oil-filled bore part of
                   the way along the stroke: the oil's Couette shear over the immersed
                   length (Newton; Petroff 1883) adds a drag proportional to the
                   immersion and to the velocity, nothing outside the bore, nothing at
                   rest
inertia            ``centrifugal_flyweights``: a centrifugal governor (or clutch) on the
                   drive's rotating shaft whose flyweights move out on their springs as
                   the speed rises (Maxwell 1868): its inertia, and the torque
                   d(J omega) / dt it takes, grow with the speed: a missed mass that is
                   small at rest and several times larger at speed
delay              ``belt_transit``: the force is measured at the drive of a belt loop
                   (a torque sensor, the motor current): the carriage's force reaches it
                   through the belt's two spans, each with its share (its stiffness,
                   ~ 1 / its length) after its transit time (length / wave speed,
                   Kolsky 1953): two echoes whose delays and weights follow the
                   carriage's position; the mean delay grows along the stroke
drift              ``zddp_tribofilm``: a zinc dialkyldithiophosphate (ZDDP) antiwear
                   tribofilm grows on the rubbed track at a rate that is stress-activated,
                   exponential in the contact pressure (Gosvami et al. 2015), and
                   saturates; the film raises the boundary levels (Taylor and Spikes
                   2003): a rise along the travel weighted by exp(beta p) of the load
backlash           ``harmonic_drive``: drive and contact joined by a strain-wave
                   (harmonic drive) gear: no play, but a torsional stiffness that is soft
                   near zero load and hardens with it (the cubic law of Tuttle and
                   Seering 1996; Taghirad and Belanger 1998): after each reversal the
                   force turns slowly through zero and faster beyond
gms                ``asperity_interlocking``: the surfaces' asperities interlock where
                   the contact last came to rest (the roughness theory of friction,
                   Coulomb 1785; Patton 1966's sawtooth): after a reversal the contact
                   first slides down into the nest (the levels below the base's), then
                   climbs out of it on the other side (above), then rides the worn tips
                   (the base's) (Plesha 1987); at ``s`` = 0 the base itself
=================  =====================================================================

Where a form applies: as its effect's record (``truth_applies``); ``granular_flow`` needs a
Stribeck curve (not the isolator's mre_lugre), ``immersed_plunger`` a record that revisits
its positions (not the press), ``full_contact`` a load that changes, ``harmonic_drive`` and
``asperity_interlocking`` a classic LuGre base (valve, damping rig, XML-350); each raises a
``ValueError`` elsewhere. :data:`FORMS` names each effect's form.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit
from scipy.special import erf

from friction.lugre import bristle_update
from friction.shapes import SHAPES, stribeck_g

from ..effects_backlash import PLANT_GAP_SHARE
from .kinematics import PlantKinematics
from .truths import (_base_parts, _bump_centre, _contact_constants, _lag, _level,
                     _lugre_params, _motion_time, _presliding_path, _smooth_max0, _span,
                     level_inside, on_fine_grid)

__all__ = ["FORMS", "dilatancy_hardening_truth", "full_contact_truth",
           "chevron_grooves_truth", "granular_flow_truth", "immersed_plunger_truth",
           "centrifugal_flyweights_truth", "belt_transit_truth", "zddp_tribofilm_truth",
           "harmonic_drive_truth", "asperity_interlocking_truth"]

#: the family's form of each effect (its function is ``<form>_truth`` here)
FORMS = {"acceleration": "dilatancy_hardening", "load": "full_contact",
         "asymmetry": "chevron_grooves", "stribeck_shape": "granular_flow",
         "position": "immersed_plunger", "inertia": "centrifugal_flyweights",
         "delay": "belt_transit", "drift": "zddp_tribofilm",
         "backlash": "harmonic_drive", "gms": "asperity_interlocking"}


def _direction(kin: PlantKinematics) -> np.ndarray:
    """The direction of motion [-], -1 to 1, rounded over 2 % of v99 (measured signals
    never switch in one sample)."""
    return np.tanh(np.asarray(kin.v, float) / (0.02 * max(kin.scales["v99"], 1e-12)))


# -- acceleration ---------------------------------------------------------------------------
#: ``dilatancy_hardening``'s speed scale of the dilatancy, x v99 [-]; the pores' drainage
#: time, x the motion's time scale [-]; the levels' change per unit of the undrained
#: dilatancy at strength 1 [-]; the lowest relative level compaction leaves [-]
DILATANCY_SPEED, DRAINAGE_TIME, DILATANT_HARDENING, COMPACTION_FLOOR = 0.05, 0.5, 0.6, 0.05


def _undrained(t, phi, tau):
    """The undrained part [-] of a dilatancy ``phi`` [-] along the times ``t`` [s] whose pore
    pressure drains with the time constant ``tau`` [s]: u' = phi' - u / tau (Segall and
    Rice's pore-pressure balance, a first-order high-pass of ``phi``), u = ``phi`` - its
    first-order lag (:func:`.truths._lag`). Starts drained (u = 0)."""
    return np.asarray(phi, float) - _lag(t, phi, tau)


@on_fine_grid
def dilatancy_hardening_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A lubricant-filled rough (or debris-laden) interface that dilates with the slip
    speed: its porosity grows as phi = eps ln(1 + |v| / v*) (v* = :data:`DILATANCY_SPEED`
    v99), and the oil must flow into the new pore space. While the layer dilates faster
    than the oil can follow, the pore pressure falls below its drained value by u / beta,
    u' = phi' - u / tau_d (:func:`_undrained`; tau_d = :data:`DRAINAGE_TIME` x the motion's
    time scale), and the effective normal stress rises by as much; compacting (the speed
    falling) it rises and unloads the contact. The Coulomb and Stribeck levels are the
    base's times 1 + ``s`` :data:`DILATANT_HARDENING` u (u with eps = 1; at least
    :data:`COMPACTION_FLOOR`), inside the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the dilatancy eps over the pore fluid's compressibility beta
        and the effective normal stress, / :data:`DILATANT_HARDENING`.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Dilatancy of a sheared granular or rough layer with the log of the slip rate (Marone,
    Raleigh and Scholz 1990, Frictional behavior and constitutive modeling of simulated
    fault gouge, J. Geophys. Res. 95); dilatant hardening by the pore pressure it draws
    down (Rudnicki and Chen 1988, Stabilization of frictional slip on a weakening fault by
    dilatant hardening, J. Geophys. Res. 93; Segall and Rice 1995, Dilatancy, compaction,
    and slip instability of a fluid-infiltrated fault, J. Geophys. Res. 100). The candidate
    adds a force odd in a and raises the levels with |a|, lagged; the open forms lag the
    velocity, a film's speed or a contact state, heat the contact, skid rolling elements,
    move load between ball rows or supports, press a seal with a lagged pressure, pull the
    carriage with the thrust, relieve it by a squeeze film or starve it by a sloshing bath.
    Here the levels follow the rate of change of the log of the speed through a drainage
    time: steepest where the speed changes by a large factor (leaving and approaching
    rest), up speeding up, down slowing down, and back to the base's while the speed holds.
    """
    v = np.asarray(kin.v, float)
    vstar = DILATANCY_SPEED * max(kin.scales["v99"], 1e-12)
    phi = np.log1p(np.abs(v) / vstar)
    u = _undrained(kin.t, phi, DRAINAGE_TIME * max(_motion_time(kin), 1e-12))
    lev = 1.0 + max(float(s), 0.0) * DILATANT_HARDENING * u
    return level_inside(kin, np.clip(lev, COMPACTION_FLOOR, None), np.ones_like(lev))


# -- load -------------------------------------------------------------------------------------
#: ``full_contact``'s spread of the contact pressure over the nominal area, x the mean
#: load's pressure [-] (Persson's sigma_p: full contact well above it)
CONTACT_SPREAD = 0.7


def _contact_area(L, spread):
    """Persson's real contact area [-], relative to the nominal one, of a soft body pressed
    by the loads ``L`` [-] (relative to the mean load) onto a rough surface whose full-
    contact pressure spread is ``spread`` [-] (same unit): erf(L / (sqrt(2) spread))."""
    return erf(np.clip(np.asarray(L, float), 0.0, None) / (math.sqrt(2.0) * spread))


@on_fine_grid
def full_contact_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A soft (elastomer or polymer) seal pressed onto a rough counterface: its real
    contact area A(L) follows Persson's theory, A / A_0 = erf(p / (sqrt(2) sigma_p))
    (:func:`_contact_area`; p the nominal pressure, proportional to the load L, sigma_p =
    :data:`CONTACT_SPREAD` x the mean load's pressure): proportional to the load while
    the contact is sparse, saturating as it approaches full contact. The adhesive friction
    follows the area: the Coulomb and Stribeck levels are the base's times 1 + ``s`` (A(L)
    / A(mean L) - 1) (at least 0.05), inside the bristle dynamics; the viscous term is the
    base's. ValueError if the load does not change.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (load [N]) and its base law.
    s : float
        Amplitude factor [-]: the share of the levels that follows the real contact area.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Persson 2001, Theory of rubber friction and contact mechanics, J. Chem. Phys. 115 (the
    contact area's diffusion in pressure: A / A_0 = erf(p / (2 sqrt(G))), here sigma_p^2 =
    2 G); friction proportional to the real area of contact (Bowden and Tabor 1950, The
    Friction and Lubrication of Solids). The candidate's levels are affine in the load
    (with a direction's slope, a viscous slope and a memory over the travel); the open
    forms are a power 2/3 (Hertz), one direction, a square-root viscous term, the Stribeck
    velocity, a logistic step, a creep in time, the load's rate, a play, a ratchet with
    the travel, a hinge at a capacity, a lag while it rises and an exponential viscous
    term. Here the levels saturate: a load above the full-contact pressure adds almost
    nothing, a falling load takes area away fast.
    """
    L = np.asarray(kin.load, float)
    L0 = max(float(np.mean(np.abs(L))), 1e-12)
    # a change below 1e-6 of the mean load over the record is round-off, not a change
    if float(np.ptp(L)) <= 1e-6 * L0:
        raise ValueError(f"load (full_contact): the {kin.plant} record's load does not "
                         f"change")
    A = _contact_area(L / L0, CONTACT_SPREAD)
    A0 = float(_contact_area(1.0, CONTACT_SPREAD))
    lev = 1.0 + max(float(s), 0.0) * (A / A0 - 1.0)
    return level_inside(kin, np.clip(lev, 0.05, None), np.ones_like(lev))


# -- asymmetry -------------------------------------------------------------------------------
#: ``chevron_grooves``' relative change of the levels at full pumping at strength 1 [-];
#: the speed over which the pumped film builds up, x v99 [-]
PUMPING, PUMPING_SPEED = 0.4, 0.3


@on_fine_grid
def chevron_grooves_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A plain slideway whose lubrication grooves are inclined to the sliding direction (a
    chevron pattern, apex towards +x): sliding in +x the grooves drag oil towards their
    apex and build pressure in the contact, which carries part of the load and unloads
    the asperities; sliding in -x they pump the oil out of the contact, which runs short
    of oil and loads them more. The pumped pressure grows with the speed (Whipple's viscous
    pumping, ~ eta v) until the film carries what the grooves can feed: the Coulomb and
    Stribeck levels are the base's times 1 - ``s`` :data:`PUMPING` tanh(v / v_p) (v_p =
    :data:`PUMPING_SPEED` v99; at least 0.05), inside the bristle dynamics; the viscous
    term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the grooves' pumping at saturation relative to
        :data:`PUMPING` x the levels.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Viscous pumping by grooves inclined to the sliding direction (Whipple 1951, The inclined
    groove bearing, AERE Harwell report; Muijderman 1966, Spiral Groove Bearings, Philips
    Technical Library), as in the herringbone and spiral-groove bearings that pump one way
    only; lubrication grooves of slideways cut in a V or chevron pattern. The candidate
    shifts a direction's levels and viscous slope (and an offset); the open forms keep a
    direction's share, move its Stribeck velocity, viscous slope or tail, roll a lip, follow
    a thrust, a film laid by the outstroke, a texture, a return spring, a wedge film that
    lifts one way, a strut, a throttle's v^2 or a cylinder's unequal areas. Here the
    direction's levels are the mirror of each other about the base's and their gap grows
    with the speed: none at rest, the same share up one way as down the other at speed.
    """
    v = np.asarray(kin.v, float)
    vp = PUMPING_SPEED * max(kin.scales["v99"], 1e-12)
    lev = 1.0 - max(float(s), 0.0) * PUMPING * np.tanh(v / vp)
    return level_inside(kin, np.clip(lev, 0.05, None), np.ones_like(lev))


# -- stribeck_shape --------------------------------------------------------------------------
#: ``granular_flow``'s speed of the inertial number I_0 (where the rise is half done), x v99
#: [-]; the relative rise of the levels from the quasi-static to the inertial regime at
#: strength 1, (mu_2 - mu_s) / mu_s [-]
GRANULAR_SPEED, GRANULAR_RISE = 0.2, 0.5


@on_fine_grid
def granular_flow_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A contact lubricated by a granular third body (a dry powder lubricant, or wear
    debris) sheared as a dense granular flow: its friction coefficient follows the mu(I)
    rheology, mu = mu_s + (mu_2 - mu_s) I / (I_0 + I), of the inertial number I = gamma'
    d / sqrt(P / rho), proportional to the sliding speed (the layer's shear rate |v| / h):
    the Stribeck curve is the base's times 1 + ``s`` :data:`GRANULAR_RISE` |v| / (v_I +
    |v|), v_I = :data:`GRANULAR_SPEED` v99 the speed of I_0, inside the bristle dynamics;
    the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s]) and its base law (a Stribeck curve).
    s : float
        Amplitude factor [-]: (mu_2 - mu_s) / mu_s, / :data:`GRANULAR_RISE`.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The mu(I) law of dense granular flows (GDR MiDi 2004, On dense granular flows, Eur.
    Phys. J. E 14; Jop, Forterre and Pouliquen 2006, A constitutive law for dense granular
    flows, Nature 441); third bodies in the contact (Godet 1984, The third-body approach: a
    mechanical view of wear, Wear 100). The candidate bends the base's drop (an exponent,
    the Lorentzian, a log-speed map over 2.5 decades); the open forms add tails, drops, a
    spike, a lift-off, a second drop, a logarithmic weakening, an Eyring strengthening
    without bound, a rise at the top speed, a hump, a notch, a dither's loss of stiction or
    a melt's fall. Here the levels strengthen from rest, linearly at first, and level off
    at (1 + ``s`` :data:`GRANULAR_RISE`) x the base's: a bounded, rational rise.
    """
    if kin.base.name == "mre_lugre":
        raise ValueError("stribeck_shape (granular_flow): the mre_lugre base has no "
                         "Stribeck curve")
    v = np.abs(np.asarray(kin.v, float))
    vI = GRANULAR_SPEED * max(kin.scales["v99"], 1e-12)
    lev = 1.0 + max(float(s), 0.0) * GRANULAR_RISE * v / (vI + v)
    return level_inside(kin, lev, np.ones_like(lev))


# -- position --------------------------------------------------------------------------------
#: ``immersed_plunger``'s drag at strength 1, fully immersed (the stroke the record visits)
#: and at v99, x the friction level [-]; the immersion's rounding at the bore's mouth, x
#: the stroke [-]
PLUNGER_DRAG, MOUTH_ROUNDING = 3.0, 0.02


@on_fine_grid
def immersed_plunger_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A plunger (a rod, a ram) entering an oil-filled bore as the carriage moves up: the
    bore's mouth sits at the median held-out position the fit part also visits
    (:func:`.truths._bump_centre`), and the immersed length is l(x) = max(x - x_m, 0)
    (rounded over :data:`MOUTH_ROUNDING` x the stroke). The oil in the annular clearance h
    is sheared by the plunger (Couette: the stress eta v / h over the wetted area 2 pi r
    l): a drag c' l(x) v added to the base's force, c' such that at ``s`` = 1 the drag at
    full immersion (the stroke the record visits) and v99 is :data:`PLUNGER_DRAG` x the
    friction level. Nothing outside the bore and nothing at rest; the contact's friction is
    the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law.
    s : float
        Amplitude factor [-]: the drag per immersed length and speed (eta 2 pi r / h),
        relative to its value at strength 1.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Newton's law of viscosity in a thin film and its bearing form (Petroff 1883, Friction
    in machines and the effect of the lubricant; the Couette drag eta U A / h), over a
    wetted area that grows with the insertion, as in dashpot plungers and rams running in
    an oil-filled guide bush. The candidate scales the friction along the stroke (a map, a
    waviness of two harmonics, a defect) and adds a periodic force of x; the open forms are
    level maps (a defect, waviness, a worn section, runout, a bow, a transfer film, a
    taper, a port's wake), a periodic detent force, a cushion's orifice drag in one zone
    and direction, a cover's staircase, a trapped gas spring and a seal's climbs over bolt
    holes. Here a viscous drag whose coefficient ramps with the position: proportional to
    the speed (not a level, which would not vanish at low speed), the same both ways, zero
    over the part of the stroke outside the bore.
    """
    xm = _bump_centre(kin)
    if xm is None:
        raise ValueError(f"position (immersed_plunger): the held-out part of the {kin.plant} "
                         f"record never revisits the positions of its fit part")
    F, _ = _base_parts(kin)
    span = _span(kin)
    x = np.asarray(kin.x, float)
    depth = _smooth_max0(x - xm, MOUTH_ROUNDING * span)
    c = PLUNGER_DRAG * _level(kin) / (max(kin.scales["v99"], 1e-12) * span)
    return F + max(float(s), 0.0) * c * depth * np.asarray(kin.v, float)


# -- inertia ---------------------------------------------------------------------------------
#: ``centrifugal_flyweights``' mass at strength 1 (the flyweights' inertia at rest reflected
#: to the axis), x the friction level / a99 [kg per N s^2/m]; the flyweights' own speed
#: (sqrt(k / m_w) in axis speed, where they would fly out), x the record's top speed [-]
FLY_MASS, FLY_SPEED = 0.3, 1.5


def _flyweight_mass(u):
    """The flyweights' effective mass [-], relative to their mass at rest, at the relative
    speeds ``u`` [-] (the axis speed over the flyweights' own speed, |u| < 1): their radius
    r / r_0 = rho = 1 / (1 - u^2) (centrifugal force m r omega^2 against the springs k (r -
    r_0)), their inertia J ~ rho^2, and the torque d(J omega) / dt = (J + omega dJ / domega)
    omega' they take: rho^2 + 4 rho^3 u^2."""
    u2 = np.minimum(np.asarray(u, float) ** 2, 0.99)
    rho = 1.0 / (1.0 - u2)
    return rho * rho + 4.0 * rho ** 3 * u2


@on_fine_grid
def centrifugal_flyweights_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A centrifugal governor, brake or clutch on the drive's rotating shaft (a screw, a
    drum): its flyweights, held in by springs, move out as the shaft speeds up, so its
    inertia grows with the speed, and accelerating it takes d(J omega) / dt (the weights'
    outward motion adds omega dJ / domega). Reflected to the axis, the inverse dynamics
    misses m(v) a, m(v) = m_0 (rho^2 + 4 rho^3 u^2), rho = 1 / (1 - u^2), u = v / v_n
    (:func:`_flyweight_mass`): m_0 = ``s`` :data:`FLY_MASS` x the friction level / a99 the
    flyweights' mass at rest, v_n = :data:`FLY_SPEED` x the record's top speed their own
    speed (the governor never trips within the record). The measured force is the base's
    plus m(v) a.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (v [m/s], a [m/s^2]) and its base law.
    s : float
        Amplitude factor [-]: the flyweights' mass relative to :data:`FLY_MASS` x level /
        a99.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Centrifugal governors (Maxwell 1868, On governors, Proc. R. Soc. Lond. 16) and
    centrifugal clutches and brakes, whose shoes or weights move out against springs with
    the speed; the torque on a rotor of varying inertia, d(J omega) / dt (Lagrange). The
    candidate and the open forms are masses (constant, filtered, along the stroke, through
    a ratio or a lossy gear, in time, behind a spring, in a fluid), a payload held by
    Coulomb friction or carried between two zones, a part rattling in a pocket, a flywheel
    through a freewheel and a part behind a slip coupling; here a mass that depends on the
    speed: the same acceleration takes several times more force at speed than near rest.
    """
    F, _ = _base_parts(kin)
    v = np.asarray(kin.v, float)
    vmax = max(float(np.max(np.abs(v))), 1e-12)
    m0 = max(float(s), 0.0) * FLY_MASS * _level(kin) / max(kin.scales["a99"], 1e-12)
    return F + m0 * _flyweight_mass(v / (FLY_SPEED * vmax)) * np.asarray(kin.a, float)


# -- delay -----------------------------------------------------------------------------------
#: ``belt_transit``'s transit time of the whole loop at strength 1 [data samples]; the
#: margin of the drive pulley below, and of the idler above, the stroke the record visits,
#: x that stroke [-]
LOOP_TRANSIT, PULLEY_MARGIN = 8.0, 0.05


def _two_spans(t, F, l1, loop, transit):
    """What the drive of a belt loop reads [N] at the times ``t`` [s] of the carriage's
    force ``F`` [N]: each span's share of it, in proportion to its stiffness (~ 1 / its
    length), late by its transit time: (l2 F(t - T l1 / L) + l1 F(t - T l2 / L)) / L, span
    1 of length ``l1`` [m] (an array on ``t``), span 2 the rest of the ``loop`` L [m], T =
    ``transit`` [s] the loop's (linear interpolation; the first force before the start)."""
    t = np.asarray(t, float)
    F = np.asarray(F, float)
    l1 = np.clip(np.asarray(l1, float), 0.0, loop)
    l2 = loop - l1

    def late(d):
        return np.interp(np.clip(t - d, t[0], None), t, F)
    return (l2 * late(transit * l1 / loop) + l1 * late(transit * l2 / loop)) / loop


@on_fine_grid
def belt_transit_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A belt-driven axis whose force is measured at the drive pulley (a torque sensor on
    its shaft, or the motor's current): the belt loop runs from the drive pulley
    (:data:`PULLEY_MARGIN` x the stroke below the visited stroke) to the carriage (span 1,
    length l_1 = x - x_d) and on round an idler (as far above it) back to the drive (span
    2, l_2 = L - l_1, L the loop). A change of the carriage's force travels along each
    span as a longitudinal wave, l_j / c late, and is shared between the spans in
    proportion to their stiffness, ~ 1 / l_j: the drive reads (l_2 F(t - l_1 / c) + l_1 F(t
    - l_2 / c)) / L (:func:`_two_spans`), L / c = ``s`` :data:`LOOP_TRANSIT` data samples.
    Its mean delay, 2 l_1 l_2 / (L c), is short with the carriage near
    the drive and grows along the stroke. At ``s`` = 0 the force itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], x [m]) and its base law.
    s : float
        Amplitude factor [-]: the loop's transit time L / c, / :data:`LOOP_TRANSIT` data
        samples (the belt's wave speed c = sqrt(E A / mu) is 1 / ``s`` times its value at
        strength 1).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Longitudinal (extensional) waves along an elastic strip, speed sqrt(E / rho) (Kolsky
    1953, Stress Waves in Solids), here a belt's spans of changing length; the spans of a
    belt or cable loop share a force at the carriage as springs in parallel (stiffness E A
    / l). The open forms delay by one amount (a shift, a hold, a transport), filter
    linearly (a lag, Bessel, a moving average, a converter's FIR, a line's echoes) or by
    rank (a running median), let the delay drift, wander or grow with the force's rate or
    its slowness, with the motion's slowness (position-triggered capture) or shift the
    motion; here the delay is set by the carriage's position, and it is two delays at once:
    one echo for each span, of weights that move with the carriage.
    """
    F, _ = _base_parts(kin)
    if s <= 0.0:
        return F
    span = _span(kin)
    xd = kin.scales["x_lo"] - PULLEY_MARGIN * span
    loop = 2.0 * (kin.scales["x_hi"] + PULLEY_MARGIN * span - xd)
    return _two_spans(kin.t, F, np.asarray(kin.x, float) - xd, loop,
                      float(s) * LOOP_TRANSIT * kin.sample_dt)


# -- drift -----------------------------------------------------------------------------------
#: ``zddp_tribofilm``'s stress activation beta p_mean (the activation volume x the mean
#: contact pressure / kT) [-]; the largest exponent it reaches (against overflow) [-]; the
#: film's saturation, x the record's load-weighted travel [-]; the levels' rise at the
#: saturated film at strength 1 [-]
ZDDP_ACTIVATION, ZDDP_CAP, ZDDP_SATURATION, ZDDP_RISE = 6.0, 8.0, 0.5, 0.5


def _tribofilm(t, v, L, beta, sat, cap):
    """The share [-] of its saturated thickness a stress-activated tribofilm has grown to
    along the times ``t`` [s], speeds ``v`` [m/s] and loads ``L`` [-] (relative to the
    mean): its growth per travel is exp(``beta`` (L^(1/3) - 1)) (the Hertzian contact
    pressure ~ L^(1/3); the exponent at most ``cap``) x (1 - h / h_max), removal balancing
    formation at h_max, so h / h_max = 1 - exp(-tau / ``sat``), tau the load-weighted
    travel over its value at the record's end. Starts bare."""
    w = np.abs(np.asarray(v, float)) * np.exp(
        np.minimum(beta * (np.cbrt(np.clip(np.asarray(L, float), 0.0, None)) - 1.0), cap))
    tau = np.concatenate(([0.0], np.cumsum(0.5 * (w[1:] + w[:-1]) * np.diff(t))))
    return 1.0 - np.exp(-tau / (sat * max(float(tau[-1]), 1e-300)))


@on_fine_grid
def zddp_tribofilm_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """A zinc dialkyldithiophosphate (ZDDP) antiwear tribofilm growing on the rubbed track
    from the record's start: its growth per unit of sliding is stress-activated,
    exponential in the contact pressure p ~ L^(1/3) (beta p_mean =
    :data:`ZDDP_ACTIVATION`), and it saturates where its removal balances its formation
    (:func:`_tribofilm`; half the record's load-weighted travel, :data:`ZDDP_SATURATION`,
    is its saturation scale). The film raises the boundary friction: the Coulomb
    and Stribeck levels are the base's times 1 + ``s`` :data:`ZDDP_RISE` h / h_max, inside
    the bristle dynamics; the viscous term is the base's.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (t [s], v [m/s], load [N]) and its base law.
    s : float
        Amplitude factor [-]: the levels' rise at the saturated film, / :data:`ZDDP_RISE`.

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    Stress-promoted, thermally activated growth of ZDDP tribofilms (Gosvami, Bares,
    Mangolini, Konicek, Yablon and Carpick 2015, Mechanisms of antiwear tribofilm growth
    revealed in situ by single-asperity sliding contacts, Science 348: the growth rate
    exponential in the contact stress); their growth to a limiting thickness with rubbing
    (Fujita and Spikes 2004, The formation of zinc dithiophosphate antiwear films, Proc.
    IMechE J 218) and the friction they add in mixed lubrication (Taylor and Spikes 2003,
    Friction-enhancing properties of ZDDP antiwear additive, Tribol. Trans. 46). The
    candidate is a trend, a saturating change, a step and a cycle in time; the open forms
    warm up, wear in (in time, with the load and travel), step, heat, cycle, rise and fall
    with debris, drop with grease shots, relax in log time, grow an oxide and spall,
    oxidise after an induction, wear a coating through or swell as sqrt(t). Here the
    levels rise along a clock that runs with the sliding and many times faster under the
    higher loads: stalled at rest and under light load, quickest in the heavily loaded
    strokes, saturating.
    """
    L = np.asarray(kin.load, float)
    L0 = max(float(np.mean(np.abs(L))), 1e-12)
    h = _tribofilm(kin.t, kin.v, L / L0, ZDDP_ACTIVATION, ZDDP_SATURATION, ZDDP_CAP)
    lev = 1.0 + max(float(s), 0.0) * ZDDP_RISE * h
    return level_inside(kin, lev, np.ones_like(lev))


# -- backlash --------------------------------------------------------------------------------
#: the lost motion of ``harmonic_drive`` at strength 1 (the deflection between the Coulomb
#: levels either way, beyond the stiff coupling's), as a share of the stroke [-] (the open
#: backlash forms' play); the share of the Coulomb level the linear term of the stiffness
#: carries at that deflection [-]
GAP_SHARE, LINEAR_SHARE = PLANT_GAP_SHARE, 0.2


@njit(cache=True)
def _hardening_spring(e, k1, k3, kh):
    """(force [N], tangent stiffness [N/m]) of a torsional stiffness that hardens with the
    deflection ``e`` [m]: k1 e + k3 e^3 while its tangent k1 + 3 k3 e^2 stays below the
    stiff coupling's ``kh`` [N/m], then on with slope ``kh``; ``kh`` throughout where ``k1``
    >= ``kh``."""
    if k1 >= kh:
        return kh * e, kh
    ek = math.sqrt((kh - k1) / (3.0 * k3))
    a = abs(e)
    if a <= ek:
        f = k1 * a + k3 * a * a * a
        kt = k1 + 3.0 * k3 * a * a
    else:
        f = k1 * ek + k3 * ek * ek * ek + kh * (a - ek)
        kt = kh
    return math.copysign(f, e), kt


@njit(cache=True)
def _strain_wave_contact(h, xd, k1, k3, kh, zeta, m, s0, s1, s2, Fc, Fs, vs, alpha, shape):
    """LuGre friction [N] of a contact of mass ``m`` [kg] pulled by the drive positions
    ``xd`` [m] (grid step ``h`` [s]) through a hardening stiffness
    (:func:`_hardening_spring` of the deflection e = drive - contact) damped at the ratio
    ``zeta`` [-] of its tangent stiffness. Semi-implicit Euler of the mass, the bristle
    advanced exactly at the contact's velocity (:func:`friction.lugre.bristle_update`).
    Starts at rest, undeflected, its bristle unloaded."""
    n = xd.size
    F = np.empty(n)
    x = xd[0]
    v = 0.0
    z = 0.0
    for j in range(n):
        vd = (xd[j] - xd[j - 1]) / h if j > 0 else 0.0
        fs, kt = _hardening_spring(xd[j] - x, k1, k3, kh)
        fc = fs + 2.0 * zeta * math.sqrt(kt * m) * (vd - v)
        g = stribeck_g(v, Fc, Fs, vs, alpha, shape)
        zd = v - s0 * abs(v) * z / g
        ff = s0 * z + s1 * zd + s2 * v
        F[j] = ff
        v = v + h * (fc - ff) / m
        z = bristle_update(z, v, s0 * abs(v) / stribeck_g(v, Fc, Fs, vs, alpha, shape), h, 0)
        x = x + h * v
    return F


@on_fine_grid
def harmonic_drive_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Drive and contact joined by a strain-wave (harmonic drive) gear: no play, but a
    torsional stiffness that is soft near zero load and hardens with it, the cubic k1 e +
    k3 e^3 of the deflection e (up to the stiff coupling of the other forms, 100 x the
    bristle's stiffness, :func:`.truths._contact_constants`, which it then follows;
    :func:`_hardening_spring`), damped at the ratio 0.5 of its tangent stiffness
    (:func:`_strain_wave_contact`). The deflection between the Coulomb levels either way,
    the lost motion of a reversal, is about 2 e_c, e_c = ``s``^2 :data:`GAP_SHARE` x the
    stroke / 2 + :data:`LINEAR_SHARE` Fc / kh: k1 = :data:`LINEAR_SHARE` Fc / e_c, k3 = (1
    - :data:`LINEAR_SHARE`) Fc / e_c^3. The contact is light, with the base's LuGre
    friction; the measured force is its friction. At ``s`` = 0 k1 is the stiff coupling's
    (the base, up to it).

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
    The flexspline's and the teeth's compliance of strain-wave gearing, soft at low
    torque and hardening (Tuttle and Seering 1996, A nonlinear model of a harmonic drive
    gear transmission, IEEE Trans. Robot. Autom. 12: a cubic; Taghirad and Belanger 1998,
    Modeling and parameter identification of harmonic drive systems, J. Dyn. Syst. Meas.
    Control 120); the makers' "lost motion" (the torsion at a few per cent of the rated
    torque either way), which this is, with no backlash. The candidate holds or frees the
    force across a play; the open forms couple it rigidly, compliantly, by impacts (a
    stiffness e^1.5 beyond a play), a linear spring, an oil film, an idler's drag, a bias,
    slack chain strands, a magnetic pull that softens towards its peak or a spring
    preload on one side, with a play varying with the position or the travel; here
    there is no play and the coupling is softest at zero force: after either reversal the
    force turns slowly through zero and faster as it grows, the opposite of the magnetic
    coupling.
    """
    p = _lugre_params(kin, "backlash (harmonic_drive)")
    m, kh, ch = _contact_constants(kin, p)
    Fc = float(p.Fc)
    lost = max(float(s), 0.0) ** 2 * GAP_SHARE * float(np.ptp(kin.x))
    # at s = 0 the linear term is the stiff coupling itself
    ec = 0.5 * lost + LINEAR_SHARE * Fc / kh
    k1 = LINEAR_SHARE * Fc / ec
    k3 = (1.0 - LINEAR_SHARE) * Fc / ec ** 3
    zeta = ch / (2.0 * math.sqrt(kh * m))
    rate = max(math.sqrt((kh + float(p.sigma0)) / m),
               (float(p.sigma1) + float(p.sigma2) + ch) / m)
    n_sub = int(min(max(math.ceil(rate * kin.dt / 0.3), 4), 400))
    t2 = kin.t[0] + (kin.dt / n_sub) * np.arange((kin.t.size - 1) * n_sub + 1)
    xd = np.interp(t2, kin.t, kin.x)
    F = _strain_wave_contact(kin.dt / n_sub, xd, k1, k3, kh, zeta, m, float(p.sigma0),
                             float(p.sigma1), float(p.sigma2), Fc, float(p.Fs),
                             float(p.vs), float(p.alpha), SHAPES[p.shape])
    return F[::n_sub]


# -- gms -------------------------------------------------------------------------------------
#: the interlocking asperities' half-wavelength (the travel from the nest to a tip) at
#: strength 1, beyond the base bristle's path, as a share of the stroke / 3 [-]; the
#: levels' largest relative change on an asperity's flank at strength 1 (its slope tan i
#: over the friction coefficient) [-] and at any strength [-]
PRESLIDING_SHARE, INTERLOCK, INTERLOCK_MAX = 0.1, 0.5, 0.9


@njit(cache=True)
def _nest_offset(x, half):
    """The contact's offset [m] from the nest where its asperities interlock, along the
    positions ``x`` [m]: it follows the travel but stays within +-``half`` [m] (beyond a tip
    the asperities are ridden over and the nest is dragged along: a play operator).
    Starts in the nest."""
    n = x.size
    out = np.empty(n)
    u = 0.0
    out[0] = 0.0
    for k in range(1, n):
        u = min(max(u + x[k] - x[k - 1], -half), half)
        out[k] = u
    return out


@on_fine_grid
def asperity_interlocking_truth(kin: PlantKinematics, s: float) -> np.ndarray:
    """Presliding across interlocking asperities: where the contact comes to rest its
    asperities nest in the counterface's; moving it by u from the nest makes it ride up an
    asperity flank of profile z(u) ~ 1 - cos(pi u / lambda) and so of slope tan i ~ sin(pi
    u / lambda), up to the tips at +-lambda, beyond which the tips are ridden over and the
    nest is dragged along (u stays at +-lambda, :func:`_nest_offset`). Climbing a flank
    takes more force, sliding down one less (Patton's mu = tan(phi + i)): the Coulomb and
    Stribeck levels are the base's times 1 + k sin(pi u / lambda) sgn(v) (the direction
    rounded over 2 % of v99), k = min(``s`` :data:`INTERLOCK`, :data:`INTERLOCK_MAX`),
    inside the bristle dynamics; the viscous term is the base's. lambda = the base
    bristle's path Fs / sigma0 plus ``s`` :data:`PRESLIDING_SHARE` x the stroke / 3. After
    a reversal from sliding the contact slides down into the nest (the levels below the
    base's), climbs the other flank (above) and rides the tips again after 2 lambda. At
    ``s`` = 0 the base itself.

    Parameters
    ----------
    kin : PlantKinematics
        The motion on the fine grid (x [m], v [m/s]) and its base law (a classic LuGre).
    s : float
        Amplitude factor [-]: the asperities' slope (/ :data:`INTERLOCK`) and their
        half-wavelength (as the open presliding forms' path).

    Returns
    -------
    ndarray
        Force [N] on ``kin``'s grid.

    Notes
    -----
    The roughness (interlocking) theory of friction (Coulomb 1785, Theorie des machines
    simples); the sawtooth asperities of rock joints, mu = tan(phi_b + i) (Patton 1966,
    Multiple modes of shear failure in rock, Proc. 1st Congr. ISRM), and their reversed
    shear, which first descends the asperities climbed (Plesha 1987, Constitutive models
    for rock discontinuities with dilatancy and surface degradation, Int. J. Numer. Anal.
    Methods Geomech. 11). Maxwell-slip (the candidate, ``maxwell4``, ``maxwell10``) and
    the Mindlin contacts follow Masing's rule, Dahl, Bouc-Wen and Bliman-Sorine path laws,
    elasto-plastic an elastic range, the Zener junction and the rate-and-state interface
    rate-dependent creep, the Tomlinson contacts multistable tips, the bonds elements born
    and broken, the gouge a fabric turned over and the kinematic hardening a back-stress;
    all reach the new sliding level from below, monotonically or with an overshoot at
    once. Here the level first falls below the base's sliding level after a reversal and
    overshoots it only later, half a wavelength on: a dip, then a bump, at a fixed travel.
    """
    _lugre_params(kin, "gms (asperity_interlocking)")
    if s <= 0.0:
        return _base_parts(kin)[0]
    e0, extra = _presliding_path(kin, s, PRESLIDING_SHARE)
    lam = e0 + extra
    k = min(INTERLOCK * float(s), INTERLOCK_MAX)
    u = _nest_offset(np.ascontiguousarray(kin.x, dtype=float), lam)
    lev = 1.0 + k * np.sin(np.pi * u / lam) * _direction(kin)
    return level_inside(kin, lev, np.ones_like(lev))
