"""Force extensions of a friction law: what the diagnosis' candidate effects add to a law.

``extension_force(F, v, a, x, load, t, e)`` takes a law's force ``F`` [N] and returns it with
the extensions switched on in the packed vector ``e`` (layout :data:`EXTENSION_PARAMS`),
applied in the order multiplicative then additive:

* ``load``         levels affine in the normal load (seed 004 Eqs. 9-11):
                   ``F (1 + k_L (load - L0) / L0)``, never of the opposite sign;
* ``drift``        levels changing over time, ``F (1 + d(t))`` (:func:`drift_change`):
                   a linear trend, a saturating change and a step,
                   ``d = k_drift (t - t0) / T + k_sat (1 - exp(-(t - t0) / tau_sat))
                   + k_step / (1 + exp(-(t - t_step) / w_step))`` (the saturating part 0
                   before ``t0``; ``tau_sat <= 0``: a step at ``t0``; ``w_step <= 0``: a
                   sharp step), plus a part that comes and goes with period ``P_cyc``
                   (two harmonics, ``k_c1 cos(psi) + k_s1 sin(psi) + k_c2 cos(2 psi) +
                   k_s2 sin(2 psi)``, ``psi = 2 pi (t - t0) / P_cyc``; ``P_cyc <= 0``:
                   none): an ambient that cycles under a thermostat or a dehumidifier, an
                   interval lubrication's shots; and a part that builds up and resets
                   with period ``P_rst``, ``k_r1 u + k_r2 u^2``, ``u = frac((t - t_rst) /
                   P_rst)`` (``P_rst <= 0``: none): a film that grows until it spalls (an
                   oxide at its critical thickness), debris that gathers until it is
                   purged, a lubricant that thins until the next shot;
* ``position``     levels along the stroke, ``F (1 + m(x))`` with ``m`` a friction map
                   (:func:`position_change`) of three parts: piecewise linear between
                   :data:`POSITION_KNOTS` equally spaced knots from ``x_lo`` to ``x_hi``
                   (values ``0, c_x1, ..., c_x11``: relative to the level at ``x_lo``,
                   whose change the base levels carry; constant beyond), a periodic
                   waviness of wavelength ``lambda_x`` with two harmonics
                   (``p_c1 cos(phi) + p_s1 sin(phi) + p_c2 cos(2 phi) + p_s2 sin(2 phi)``,
                   ``phi = 2 pi (x - x_lo) / lambda_x``; ``lambda_x <= 0``: none) and a
                   local defect ``d_x exp(-(x - x_d)^2 / (2 w_d^2))`` (``w_d <= 0``: none);
* ``acceleration`` the acceleration-dependent part of seed 000,
                   ``f_a tanh(a / a_s) w(|v| / v_c)``, with the velocity weight
                   ``w(u) = (u / m_a)^m_a exp(m_a - u)`` (:func:`acceleration_weight`):
                   ``m_a = 0`` is seed 000's ``exp(-|v| / v_c)``, largest at standstill;
                   ``m_a > 0`` peaks (at 1) at ``|v| = m_a v_c``, the shape of a Stribeck
                   curve's slope, where a frictional memory (Hess and Soom 1990) or a
                   rate-and-state friction acts most; and a level part even in the
                   acceleration, ``F (1 + f_e max(|a| - a_e, 0) + f_o a)``: levels raised by
                   what accelerating in either direction loads (rolling elements that skid, a
                   guide's moment load, a cylinder's pressurised seal), and by what the
                   signed acceleration moves (``f_o``: normal load pitched from one support
                   onto another of other friction, an iron-core motor's pull growing with
                   its thrust).

One formula serves the in-process diagnosis (:mod:`diagnosis.effects` evaluates the maps
with :func:`position_change` and :func:`drift_change`, :class:`diagnosis.effect_law.EffectLaw`
with :func:`extension_force`) and the ``friction_effects`` FMU block, so a candidate
re-simulated through FMUs is the same candidate: every form goes through the compiled
scalar functions ``_position_m`` and ``_drift_m``.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

__all__ = ["EXTENSIONS", "EXTENSION_PARAMS", "EXTENSION_INDEX", "POSITION_KNOTS", "POSITION_NAMES",
           "POSITION_FORM_NAMES", "DRIFT_NAMES", "DRIFT_CYCLE_NAMES", "DRIFT_RESET_NAMES",
           "DRIFT_SCALES", "drift_parts",
           "extension_force", "pack_extensions",
           "acceleration_weight",
           "position_map", "position_change", "drift_change"]

#: extension names, in the order of their switches in the packed vector
EXTENSIONS = ("acceleration", "position", "drift", "load")
#: knots of the position map along the stroke (the first pinned at 0); 12 resolve a local
#: defect a tenth of the stroke wide (93 % of a Gaussian bump of sigma 0.08 x stroke, where
#: the former 4th-order Legendre series caught 45-60 %); narrower features are the periodic
#: part's and the local defect's
POSITION_KNOTS = 12
#: names of the position map's free knot values (knot 0 is pinned at 0)
POSITION_NAMES = tuple(f"c_x{k}" for k in range(1, POSITION_KNOTS))
#: the position map's periodic part (wavelength [m], relative cosine/sine amplitudes of the
#: first two harmonics [-]) and local defect (relative height [-], centre [m], width [m])
POSITION_FORM_NAMES = ("lambda_x", "p_c1", "p_s1", "p_c2", "p_s2", "d_x", "x_d", "w_d")
#: the drift's parameters beyond t0 and T
#: the drift's periodic part (period [s], relative cosine/sine amplitudes of the first two
#: harmonics [-]); appended last in the packed layout, so earlier FMU value references stay
DRIFT_CYCLE_NAMES = ("P_cyc", "k_c1", "k_s1", "k_c2", "k_s2")
#: the drift's resetting part (period [s], a time it resets at [s], relative amplitudes of
#: the phase u and of u^2 [-]); appended last in the packed layout
DRIFT_RESET_NAMES = ("P_rst", "t_rst", "k_r1", "k_r2")
DRIFT_NAMES = ("k_drift", "k_sat", "tau_sat", "k_step", "t_step", "w_step") + DRIFT_CYCLE_NAMES \
    + DRIFT_RESET_NAMES

#: packed layout: (name, default, unit, description)
EXTENSION_PARAMS = (
    ("use_acc", 0.0, "1", "acceleration-dependent part on (1) or off (0)"),
    ("f_a", 0.0, "N", "amplitude of the acceleration-dependent part"),
    ("a_s", 1.0, "m/s^2", "acceleration scale of the acceleration-dependent part (> 0)"),
    ("v_c", 1.0, "m/s", "velocity over which the acceleration-dependent part fades (> 0)"),
    ("m_a", 0.0, "1", "exponent of the acceleration part's velocity weight (u / m_a)^m_a "
                      "exp(m_a - u), u = |v| / v_c: 0 fades from standstill, m_a > 0 peaks "
                      "at |v| = m_a v_c (>= 0)"),
    ("use_pos", 0.0, "1", "position-dependent levels on (1) or off (0)"),
    ("x_lo", 0.0, "m", "start of the stroke the position map refers to"),
    ("x_hi", 1.0, "m", "end of the stroke the position map refers to (> x_lo)"),
) + tuple(
    (n, 0.0, "1", f"relative level change at knot {k} of the stroke map (knot 0 at x_lo is "
                  f"0; knot {POSITION_KNOTS - 1} at x_hi)")
    for k, n in enumerate(POSITION_NAMES, 1)
) + (
    ("lambda_x", 0.0, "m", "wavelength of the periodic part of the stroke map (<= 0: none)"),
    ("p_c1", 0.0, "1", "relative amplitude of cos(phi) in the periodic part, "
                       "phi = 2 pi (x - x_lo) / lambda_x"),
    ("p_s1", 0.0, "1", "relative amplitude of sin(phi) in the periodic part"),
    ("p_c2", 0.0, "1", "relative amplitude of cos(2 phi) in the periodic part"),
    ("p_s2", 0.0, "1", "relative amplitude of sin(2 phi) in the periodic part"),
    ("d_x", 0.0, "1", "relative level change at the centre of a local defect"),
    ("x_d", 0.0, "m", "centre of the local defect"),
    ("w_d", 0.0, "m", "width (standard deviation) of the local defect (<= 0: none)"),
    ("use_drift", 0.0, "1", "level drift over time on (1) or off (0)"),
    ("k_drift", 0.0, "1", "relative level change per duration T (linear trend)"),
    ("t0", 0.0, "s", "time the drift starts from"),
    ("T", 1.0, "s", "duration the drift rate refers to (> 0)"),
    ("k_sat", 0.0, "1", "relative level change of the saturating part of the drift"),
    ("tau_sat", 1.0, "s", "time constant of the saturating part (<= 0: a step at t0)"),
    ("k_step", 0.0, "1", "relative level change of the step part of the drift"),
    ("t_step", 0.0, "s", "time of the step (midpoint)"),
    ("w_step", 0.0, "s", "time scale of the step's logistic rise (<= 0: sharp)"),
    ("use_load", 0.0, "1", "load-dependent levels on (1) or off (0)"),
    ("L0", 1.0, "N", "reference normal load (> 0)"),
    ("k_L", 0.0, "1", "relative level change per relative load change (1: Amontons)"),
    ("P_cyc", 0.0, "s", "period of the drift's periodic part (<= 0: none)"),
    ("k_c1", 0.0, "1", "relative amplitude of cos(psi) in the drift's periodic part, "
                       "psi = 2 pi (t - t0) / P_cyc"),
    ("k_s1", 0.0, "1", "relative amplitude of sin(psi) in the drift's periodic part"),
    ("k_c2", 0.0, "1", "relative amplitude of cos(2 psi) in the drift's periodic part"),
    ("k_s2", 0.0, "1", "relative amplitude of sin(2 psi) in the drift's periodic part"),
    ("f_e", 0.0, "s^2/m", "relative level change per m/s^2 of |a| above a_e (the "
                          "acceleration part's level part, even in a)"),
    ("a_e", 0.0, "m/s^2", "|a| from which the acceleration part's level part acts (>= 0)"),
    ("f_o", 0.0, "s^2/m", "relative level change per m/s^2 of the signed acceleration (the "
                          "acceleration part's level part, odd in a)"),
    ("P_rst", 0.0, "s", "period of the drift's resetting part (<= 0: none)"),
    ("t_rst", 0.0, "s", "a time at which the drift's resetting part resets"),
    ("k_r1", 0.0, "1", "relative level change of the resetting part per unit of its phase "
                       "u = frac((t - t_rst) / P_rst)"),
    ("k_r2", 0.0, "1", "relative level change of the resetting part per unit of u^2"),
)

#: index of each name in the packed vector
EXTENSION_INDEX = {p[0]: i for i, p in enumerate(EXTENSION_PARAMS)}
# indices for the compiled formula (module constants: numba freezes them)
_USE_ACC, _F_A, _A_S, _V_C, _M_A = (EXTENSION_INDEX[k] for k in
                                    ("use_acc", "f_a", "a_s", "v_c", "m_a"))
_USE_POS, _X_LO, _X_HI, _C_X1 = (EXTENSION_INDEX[k] for k in ("use_pos", "x_lo", "x_hi", "c_x1"))
_LAMBDA_X, _P_C1, _D_X, _X_D, _W_D = (EXTENSION_INDEX[k] for k in
                                      ("lambda_x", "p_c1", "d_x", "x_d", "w_d"))
_USE_DRIFT, _K_DRIFT, _T0, _T = (EXTENSION_INDEX[k] for k in ("use_drift", "k_drift", "t0", "T"))
_K_SAT, _TAU_SAT, _K_STEP, _T_STEP, _W_STEP = (EXTENSION_INDEX[k] for k in
                                              ("k_sat", "tau_sat", "k_step", "t_step", "w_step"))
_USE_LOAD, _L0, _K_L = (EXTENSION_INDEX[k] for k in ("use_load", "L0", "k_L"))
_P_CYC, _K_C1 = (EXTENSION_INDEX[k] for k in ("P_cyc", "k_c1"))
_P_RST, _T_RST, _K_R1, _K_R2 = (EXTENSION_INDEX[k] for k in ("P_rst", "t_rst", "k_r1", "k_r2"))
_F_E, _A_E, _F_O = (EXTENSION_INDEX[k] for k in ("f_e", "a_e", "f_o"))
_NK = POSITION_KNOTS
_TWO_PI = 2.0 * math.pi


@njit(cache=True, nogil=True)
def _acc_weight(u, m):
    """Velocity weight w(u) [-] of the acceleration part at u = |v| / v_c >= 0 and exponent
    m >= 0: exp(-u) at m = 0, else (u / m)^m exp(m - u), 1 at its peak u = m."""
    if m <= 0.0:
        return math.exp(-u)
    if u <= 0.0:
        return 0.0
    return math.exp(m * math.log(u / m) + m - u)


@njit(cache=True, nogil=True)
def _acc_weight_vec(u, m):
    out = np.empty(u.size)
    for i in range(u.size):
        out[i] = _acc_weight(u[i], m)
    return out


def acceleration_weight(v, v_c: float, m_a: float = 0.0) -> np.ndarray:
    """Velocity weight of the acceleration part at velocities ``v`` [m/s] (the formula of
    :func:`extension_force`): ``exp(-|v| / v_c)`` at ``m_a = 0``, else
    ``(u / m_a)^m_a exp(m_a - u)`` with ``u = |v| / v_c`` [-].

    Parameters
    ----------
    v : array_like
        Velocity [m/s].
    v_c : float
        Velocity scale [m/s] (> 0).
    m_a : float
        Exponent [-] (>= 0): the weight peaks at ``|v| = m_a v_c``.
    """
    if not v_c > 0:
        raise ValueError(f"v_c = {v_c!r} is out of bounds: must be > 0 [m/s]")
    if not m_a >= 0:
        raise ValueError(f"m_a = {m_a!r} is out of bounds: must be >= 0 [-]")
    u = np.abs(np.ascontiguousarray(np.atleast_1d(v), dtype=float)) / v_c
    w = _acc_weight_vec(u.ravel(), float(m_a))
    return float(w[0]) if np.ndim(v) == 0 else w.reshape(np.shape(v))


@njit(cache=True, nogil=True)
def _position_m(x, e):
    """Relative level change m(x) [-] of the stroke map in the packed vector ``e``."""
    span = e[_X_HI] - e[_X_LO]
    if span < 1e-12:
        span = 1e-12
    u = (x - e[_X_LO]) / span * (_NK - 1)
    if u <= 0.0:
        m = 0.0
    elif u >= _NK - 1:
        m = e[_C_X1 + _NK - 2]
    else:
        j = int(u)
        w = u - j
        lo = 0.0 if j == 0 else e[_C_X1 + j - 1]
        m = lo + w * (e[_C_X1 + j] - lo)
    if e[_LAMBDA_X] > 0.0:  # periodic waviness, two harmonics
        phi = _TWO_PI * (x - e[_X_LO]) / e[_LAMBDA_X]
        m += (e[_P_C1] * math.cos(phi) + e[_P_C1 + 1] * math.sin(phi)
              + e[_P_C1 + 2] * math.cos(2.0 * phi) + e[_P_C1 + 3] * math.sin(2.0 * phi))
    if e[_W_D] > 0.0:  # local defect
        q = (x - e[_X_D]) / e[_W_D]
        m += e[_D_X] * math.exp(-0.5 * q * q)
    return m


@njit(cache=True, nogil=True)
def _drift_scales(e, every):
    """The drift's time scales in ``e``, for :func:`_drift_parts`, and whether its rise and
    step are wanted: all with ``every``, else only where their amplitude is not 0 (the
    scalar formula's work). Read once per record, as :func:`_drift_amps`."""
    return (e[_T0], every or e[_K_SAT] != 0.0, e[_TAU_SAT], every or e[_K_STEP] != 0.0,
            e[_T_STEP], e[_W_STEP], e[_P_CYC], e[_T_RST], e[_P_RST])


@njit(cache=True, nogil=True)
def _drift_parts(t, sc):
    """The parts of the drift's d(t) at time ``t`` [s] that depend on its time scales ``sc``
    (:func:`_drift_scales`) only, not on its amplitudes: the saturating change's rise, the
    step's ``1 + tanh``, the periodic part's two harmonics and the resetting part's
    phase."""
    t0, want_sat, tau_sat, want_step, t_step, w_step, P_cyc, t_rst, P_rst = sc
    s = t - t0
    sat = 0.0
    if want_sat and s > 0.0:
        sat = 1.0 - math.exp(-s / tau_sat) if tau_sat > 0.0 else 1.0
    step = 0.0
    if want_step:
        if w_step > 0.0:
            step = 1.0 + math.tanh(0.5 * (t - t_step) / w_step)
        elif t >= t_step:
            step = 2.0  # a sharp step: k 0.5 x 2 = k in _drift_sum
    c1 = s1 = c2 = s2 = 0.0
    if P_cyc > 0.0:
        psi = _TWO_PI * s / P_cyc
        c1, s1, c2, s2 = math.cos(psi), math.sin(psi), math.cos(2.0 * psi), math.sin(2.0 * psi)
    u = 0.0
    if P_rst > 0.0:
        u = (t - t_rst) / P_rst
        u -= math.floor(u)
    return sat, step, c1, s1, c2, s2, u


@njit(cache=True, nogil=True)
def _drift_amps(e):
    """The drift's amplitudes and switches in ``e``, for :func:`_drift_sum` (read once per
    record: inside a loop over samples, reads of ``e`` made it 30 x slower)."""
    return (e[_K_DRIFT], e[_T], e[_K_SAT], e[_K_STEP], e[_K_C1], e[_K_C1 + 1], e[_K_C1 + 2],
            e[_K_C1 + 3], e[_P_CYC], e[_K_R1], e[_K_R2], e[_P_RST])


@njit(cache=True, nogil=True)
def _drift_sum(s, a, sat, step, c1, s1, c2, s2, u):
    """d(t) [-] at ``s = t - t0`` [s] from the parts of :func:`_drift_parts` and the
    amplitudes ``a`` of :func:`_drift_amps`."""
    k_drift, T, k_sat, k_step, k_c1, k_s1, k_c2, k_s2, P_cyc, k_r1, k_r2, P_rst = a
    d = k_drift * s / T
    if k_sat != 0.0 and s > 0.0:
        d += k_sat * sat
    if k_step != 0.0:
        d += k_step * 0.5 * step
    if P_cyc > 0.0:  # periodic part, two harmonics
        d += k_c1 * c1 + k_s1 * s1 + k_c2 * c2 + k_s2 * s2
    if P_rst > 0.0:  # resetting part: builds up over each period from 0
        d += (k_r1 + k_r2 * u) * u
    return d


@njit(cache=True, nogil=True)
def _drift_m(t, e):
    """Relative level change d(t) [-] of the drift in the packed vector ``e``."""
    sat, step, c1, s1, c2, s2, u = _drift_parts(t, _drift_scales(e, False))
    return _drift_sum(t - e[_T0], _drift_amps(e), sat, step, c1, s1, c2, s2, u)


@njit(cache=True, nogil=True)
def _position_vec(x, e):
    out = np.empty(x.size)
    for i in range(x.size):
        out[i] = _position_m(x[i], e)
    return out


@njit(cache=True, nogil=True)
def _drift_vec(t, e):
    out = np.empty(t.size)
    a, sc = _drift_amps(e), _drift_scales(e, False)
    for i in range(t.size):
        sat, step, c1, s1, c2, s2, u = _drift_parts(t[i], sc)
        out[i] = _drift_sum(t[i] - sc[0], a, sat, step, c1, s1, c2, s2, u)
    return out


@njit(cache=True, nogil=True)
def _drift_parts_vec(t, e):
    out = np.empty((7, t.size))
    sc = _drift_scales(e, True)
    for i in range(t.size):
        (out[0, i], out[1, i], out[2, i], out[3, i], out[4, i], out[5, i],
         out[6, i]) = _drift_parts(t[i], sc)
    return out


@njit(cache=True, nogil=True)
def _drift_sum_vec(t, e, parts):
    out = np.empty(t.size)
    a, t0 = _drift_amps(e), e[_T0]
    for i in range(t.size):
        out[i] = _drift_sum(t[i] - t0, a, parts[0, i], parts[1, i], parts[2, i], parts[3, i],
                            parts[4, i], parts[5, i], parts[6, i])
    return out


def position_change(x, e) -> np.ndarray:
    """Relative level change ``m(x)`` [-] of the stroke map of the packed vector ``e``
    (:func:`pack_extensions`) at positions ``x`` [m]: the formula of
    :func:`extension_force`."""
    return _position_vec(np.ascontiguousarray(np.atleast_1d(x), dtype=float),
                         np.asarray(e, float))


def drift_change(t, e, parts=None) -> np.ndarray:
    """Relative level change ``d(t)`` [-] of the drift of the packed vector ``e``
    (:func:`pack_extensions`) at times ``t`` [s]: the formula of :func:`extension_force`.
    ``parts``, the :func:`drift_parts` of the same times and time scales, spares their
    transcendental functions (the same bits): a fit's Jacobian moves the amplitudes alone
    in most of its columns."""
    t = np.ascontiguousarray(np.atleast_1d(t), dtype=float)
    e = np.asarray(e, float)
    if parts is None:
        return _drift_vec(t, e)
    if parts.shape != (7, t.size):
        raise ValueError(f"parts has shape {parts.shape}, expected (7, {t.size}) (drift_parts "
                         f"of the same times)")
    return _drift_sum_vec(t, e, parts)


#: entries of the packed vector the drift's parts depend on (its time scales)
DRIFT_SCALES = tuple(EXTENSION_INDEX[k] for k in
                     ("t0", "tau_sat", "t_step", "w_step", "P_cyc", "P_rst", "t_rst"))


def drift_parts(t, e) -> np.ndarray:
    """The drift's parts that depend on its time scales only (:data:`DRIFT_SCALES`) at times
    ``t`` [s], for :func:`drift_change`: a 7 x N array [-]."""
    return _drift_parts_vec(np.ascontiguousarray(np.atleast_1d(t), dtype=float),
                            np.asarray(e, float))


def position_map(x, x_lo: float, x_hi: float, c, **form) -> np.ndarray:
    """Relative level change ``m(x)`` [-] of the position map at positions ``x`` [m]: linear
    between the knots ``x_lo + k (x_hi - x_lo) / (POSITION_KNOTS - 1)`` with values
    ``0, c[0], ..., c[-1]``, constant beyond the stroke, plus the periodic part and the local
    defect given by name in ``form`` (:data:`POSITION_FORM_NAMES`; absent: none)."""
    c = np.asarray(c, float)
    if c.size != POSITION_KNOTS - 1:
        raise ValueError(f"the position map takes {POSITION_KNOTS - 1} knot values, "
                         f"got {c.size}")
    if not x_hi > x_lo:
        raise ValueError(f"x_hi = {x_hi!r} is out of bounds: must be > x_lo = {x_lo!r} [m]")
    bad = np.flatnonzero(~np.isfinite(c))
    if bad.size:
        raise ValueError(f"{POSITION_NAMES[bad[0]]} = {c[bad[0]]!r} is not a finite number")
    p = {n: float(v) for n, v in zip(POSITION_NAMES, c)}
    p.update(form)
    m = position_change(x, pack_extensions({"position": p}, x_lo=x_lo, x_hi=x_hi))
    return float(m[0]) if np.ndim(x) == 0 else m.reshape(np.shape(x))


@njit(cache=True, nogil=True)
def extension_force(F, v, a, x, load, t, e):
    """Law force ``F`` [N] with the extensions of the packed vector ``e`` at velocity ``v``
    [m/s], acceleration ``a`` [m/s^2], position ``x`` [m], normal load ``load`` [N] and
    time ``t`` [s]."""
    if e[_USE_LOAD] > 0.5:  # load: levels affine in the normal load, never of opposite sign
        r = 1.0 + e[_K_L] * (load - e[_L0]) / e[_L0]
        F = F * max(r, 0.0)
    if e[_USE_DRIFT] > 0.5:  # drift: trend, saturating change, step
        F = F * (1.0 + _drift_m(t, e))
    if e[_USE_POS] > 0.5:  # position: knots, waviness, local defect
        F = F * (1.0 + _position_m(x, e))
    if e[_USE_ACC] > 0.5:  # acceleration: grows with |a|, weighted along |v|; a level part
        F = F * (1.0 + e[_F_E] * max(abs(a) - e[_A_E], 0.0) + e[_F_O] * a)
        F = F + e[_F_A] * math.tanh(a / e[_A_S]) * _acc_weight(abs(v) / e[_V_C], e[_M_A])
    return F


def pack_extensions(effects: dict, *, x_lo: float = 0.0, x_hi: float = 1.0, t0: float = 0.0,
                    T: float = 1.0, L0: float | None = None) -> np.ndarray:
    """Packed vector of :func:`extension_force`.

    Parameters
    ----------
    effects : dict
        Extension name (:data:`EXTENSIONS`) -> its parameters (``f_a`` [N], ``a_s``
        [m/s^2], ``v_c`` [m/s], ``m_a`` [-]; ``c_x1..c_x11`` [-], ``lambda_x`` [m],
        ``p_c1, p_s1, p_c2, p_s2`` [-], ``d_x`` [-], ``x_d`` [m], ``w_d`` [m]; ``k_drift`` [-], ``k_sat`` [-],
        ``tau_sat`` [s], ``k_step`` [-], ``t_step`` [s], ``w_step`` [s]; ``k_L`` [-]);
        parameters not given keep their defaults (a part whose amplitude is 0 is off).
    x_lo, x_hi : float
        Stroke the position map refers to [m].
    t0, T : float
        Start and duration the drift refers to [s].
    L0 : float
        Reference normal load [N] (needed by ``load``).
    """
    e = np.array([p[1] for p in EXTENSION_PARAMS], float)
    ix = EXTENSION_INDEX
    if "position" in effects and not x_hi > x_lo:
        raise ValueError(f"x_hi = {x_hi!r} is out of bounds: must be > x_lo = {x_lo!r} [m]")
    if "drift" in effects and not T > 0:
        raise ValueError(f"T = {T!r} is out of bounds: must be > 0 [s]")
    for name, p in effects.items():
        if name == "acceleration":
            e[ix["use_acc"]] = 1.0
            for k in ("a_s", "v_c"):
                if not p[k] > 0:
                    raise ValueError(f"{k} = {p[k]!r} is out of bounds: must be > 0 "
                                     f"[{'m/s^2' if k == 'a_s' else 'm/s'}]")
            if not p.get("m_a", 0.0) >= 0:
                raise ValueError(f"m_a = {p['m_a']!r} is out of bounds: must be >= 0 [-]")
            for k in ("f_a", "f_e", "f_o"):
                if not np.isfinite(p.get(k, 0.0)):
                    raise ValueError(f"{k} = {p[k]!r} is not a finite number")
            if not p.get("a_e", 0.0) >= 0:
                raise ValueError(f"a_e = {p['a_e']!r} is out of bounds: must be >= 0 "
                                 f"[m/s^2]")
            for k in ("f_a", "a_s", "v_c", "m_a", "f_e", "a_e", "f_o"):
                e[ix[k]] = p.get(k, e[ix[k]])
        elif name == "position":
            e[ix["use_pos"]] = 1.0
            e[ix["x_lo"]], e[ix["x_hi"]] = x_lo, x_hi
            for n in POSITION_NAMES + POSITION_FORM_NAMES:
                e[ix[n]] = p.get(n, 0.0)
                if not np.isfinite(e[ix[n]]):
                    raise ValueError(f"{n} = {e[ix[n]]!r} is not a finite number")
        elif name == "drift":
            e[ix["use_drift"]] = 1.0
            for n in DRIFT_NAMES:
                if n in p:
                    e[ix[n]] = p[n]
                if not np.isfinite(e[ix[n]]):
                    raise ValueError(f"{n} = {e[ix[n]]!r} is not a finite number")
            e[ix["t0"]], e[ix["T"]] = t0, T
        elif name == "load":
            if L0 is None or not L0 > 0:
                raise ValueError("the load extension needs a positive reference load L0 [N]")
            e[ix["use_load"]] = 1.0
            e[ix["L0"]], e[ix["k_L"]] = L0, p["k_L"]
        else:
            raise ValueError(f"{name!r} is not a force extension; choose from {EXTENSIONS}")
    return e
