"""Property tests (hypothesis) over every registered friction law.

Each law in ``friction.MODELS`` gets a small adapter below: how to draw admissible inputs,
which state is the bristle-like deflection, and (where the law has one) its Dahl-type
pre-sliding limit and bristle energy. A law registered later without an adapter is still
covered by the generic checks (finite output, parameters drawn from its search ranges).

Properties:

* no NaN/inf for admissible parameters and inputs, steps up to 1 ms, |v| up to 1 m/s;
* the bristle deflection stays within its bound (|z| <= max g / sigma0 from z = 0) with the
  exact update;
* dissipativity where Olsson's condition sigma1 |v| < 4 g(v) holds: along a closed cycle
  from rest the energy put into the bristle, W(t) = int F_b v dt, never falls below the
  stored energy sigma0 z^2 / 2 (the dissipation inequality on every prefix);
* pre-sliding: with a constant Stribeck level the bristle is a Dahl element, whose periodic
  loop F(x) of amplitude A is known in closed form: tip deflection z_A = zs tanh(A/zs),
  secant stiffness at the tips S zs tanh(A/zs)/A (-> S for A -> 0, decreasing in A) and
  loop area 2 S [2 A zs - zs (zs + z_A)(1 - exp(-2 A/zs))].
"""
from __future__ import annotations

import inspect
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, note, settings
from hypothesis import strategies as st
from scipy.integrate import cumulative_trapezoid

from friction import MODELS, ParameterError, make_model

SETTINGS = settings(max_examples=30, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
LAWS = sorted(MODELS)
STATEFUL = [n for n in LAWS if MODELS[n].state_names]


# -- drawing admissible parameters from each law's own metadata ---------------------------
def _draw_value(draw, info):
    lo, hi = info.search
    if info.log and lo > 0:
        return float(10 ** draw(st.floats(math.log10(lo), math.log10(hi))))
    return float(draw(st.floats(lo, hi, allow_subnormal=False)))


@st.composite
def admissible_model(draw, name, **fixed):
    """A model of law ``name`` with every searchable parameter drawn from its search range."""
    cls = MODELS[name]
    kw = {}
    for info in cls.Params.info():
        if info.name in fixed or info.search is None:
            continue
        if info.default is None and not draw(st.booleans()):
            continue  # leave a direction-dependent twin unset half of the time
        kw[info.name] = _draw_value(draw, info)
    kw.update(fixed)
    note(f"{name} parameters: {kw}")
    try:
        return make_model(name, **kw)
    except ParameterError:
        assume(False)  # a cross-parameter relation failed: not an admissible set


def _load_range(model):
    # admissible deformation loads: keep every Stribeck level positive
    return 0.0, 2e5


def inputs_for(model, draw, t, v):
    """Extra keyword inputs a law needs, drawn admissibly."""
    kw = {}
    if "a" in model.extra_inputs and draw(st.booleans()):
        # an arbitrary (not necessarily consistent) finite acceleration record
        amp = draw(st.floats(0.0, 1e3))
        kw["a"] = amp * np.sin(2 * np.pi * draw(st.floats(0.1, 50.0)) * t + 0.3)
    if "load" in model.extra_inputs:
        lo, hi = _load_range(model)
        base = draw(st.floats(lo, hi))
        kw["load"] = base + 0.5 * min(base - lo, hi - base) * np.sin(2 * np.pi * 3 * t)
    return kw


def _simulate_or_reject(model, t, v, kw, **opts):
    try:
        return model.simulate(t, v, **kw, **opts)
    except ValueError as exc:
        if "load" in str(exc):  # this load makes a level of the law inadmissible
            assume(False)
        raise


@st.composite
def motion(draw):
    """A record with step h <= 1 ms, |v| <= 1 m/s: two sines plus a hold and a jump."""
    h = 10 ** draw(st.floats(-6.0, -3.0))
    n = draw(st.integers(50, 400))
    t = np.arange(n) * h
    vmax = 10 ** draw(st.floats(-6.0, 0.0))
    f1 = draw(st.floats(0.1, 1.0)) / (n * h)
    r = draw(st.floats(0.0, 1.0))
    v = np.sin(2 * np.pi * f1 * t) + r * np.sin(2 * np.pi * 7.3 * f1 * t + 1.0)
    v[n // 3: n // 2] = draw(st.floats(-1.0, 1.0))  # hold and velocity jumps
    v = vmax * v / max(np.max(np.abs(v)), 1e-300)
    return t, v


# -- 1. no NaN / inf ------------------------------------------------------------------------
@pytest.mark.parametrize("name", LAWS)
@SETTINGS
@given(data=st.data())
def test_finite_for_admissible_parameters_and_steps(name, data):
    model = data.draw(admissible_model(name))
    t, v = data.draw(motion())
    kw = inputs_for(model, data.draw, t, v)
    for method in ("exact",):
        F = _simulate_or_reject(model, t, v, kw, method=method, return_state=True)
        assert np.all(np.isfinite(F[0])), (model, F[0])
        assert np.all(np.isfinite(F[1]))
    # the population kernel agrees with single runs for the same parameter set
    names = [n for n in model.free_names() if n in model.theta_layout][:2]
    if names:
        X = np.array([[getattr(model.params, n) for n in names]])
        P = model.simulate_population(t, v, names, X, **kw)
        np.testing.assert_allclose(P[0], F[0], rtol=1e-12, atol=1e-12 * np.max(np.abs(F[0])))


def test_sigma0_1e7_at_1ms_and_1mps_is_finite():
    """The corner of the stated range for every law with a bristle stiffness sigma0."""
    t = np.arange(2000) * 1e-3
    v = np.sin(2 * np.pi * 2 * t)
    for name in LAWS:
        cls = MODELS[name]
        if "sigma0" not in cls.Params.numeric_names():
            continue
        m = make_model(name, sigma0=1e7)
        kw = {"load": np.full(t.size, 1e3)} if "load" in cls.extra_inputs else {}
        F, S = m.simulate(t, v, return_state=True, **kw)
        assert np.all(np.isfinite(F)) and np.all(np.isfinite(S)), name


# -- 2. bristle bound -----------------------------------------------------------------------
def _z_bound(model, kw):
    zmax = model.z_max
    if "load" in inspect.signature(zmax).parameters and "load" in kw:
        # the levels are affine in the load: the bound is reached at an extreme load
        return max(zmax(load=float(np.min(kw["load"]))), zmax(load=float(np.max(kw["load"]))))
    return zmax()


@pytest.mark.parametrize("name", [n for n in STATEFUL if hasattr(MODELS[n], "z_max")])
@SETTINGS
@given(data=st.data())
def test_bristle_deflection_stays_within_bound(name, data):
    model = data.draw(admissible_model(name))
    t, v = data.draw(motion())
    kw = inputs_for(model, data.draw, t, v)
    _, S = _simulate_or_reject(model, t, v, kw, return_state=True)
    bound = _z_bound(model, kw)
    assert np.max(np.abs(S[:, 0])) <= bound * (1 + 1e-9), (np.max(np.abs(S[:, 0])), bound)


# -- 3. dissipativity (Olsson) --------------------------------------------------------------
def _lugre_like(model, z, v, kw):
    """(S, D, zdot, g) of the bristle force F_b = S z + D dz/dt for LuGre-type laws."""
    p = model.params
    if model.name == "mre_lugre":
        zs = 1.0 / p.decay
        zd = v - p.decay * np.abs(v) * z
        return p.beta, p.ydot_gain, zd, np.full(v.shape, p.beta * zs)
    if model.name == "load_lugre":
        g = model.g(v, kw["load"])
    else:
        g = model.g(v)
    zd = v - p.sigma0 * np.abs(v) / g * z
    if model.name == "modified_lugre":
        zd = model.gamma_switch(v) * zd
    return p.sigma0, p.sigma1, zd, g


DISSIPATIVE = {
    "lugre": {},
    # Gamma-B is exactly 1 below v1: there the law is the classic one
    "modified_lugre": {"gamma_form": "cosine", "f_a": 0.0},
    "load_lugre": {},
    "mre_lugre": {"swap_alpha_eps": False},
}


@pytest.mark.parametrize("name", list(DISSIPATIVE))
@SETTINGS
@given(data=st.data())
def test_bristle_is_dissipative_under_olsson_condition(name, data):
    model = data.draw(admissible_model(name, **DISSIPATIVE[name]))
    if name == "mre_lugre":
        assume(model.params.alpha > 0 and model.params.beta > 0)
    zmax = model.z_max() if name != "load_lugre" else None
    n = 6000
    cycles = data.draw(st.floats(0.3, 3.0))
    t = np.linspace(0.0, 1.0, n)
    kw = {}
    if name == "load_lugre":
        kw["load"] = np.full(n, data.draw(st.floats(0.0, 2e5)))
        zmax = _z_bound(model, kw)
    # a closed displacement cycle from rest: x = X (1 - cos(2 pi t)) / 2 plus a ripple
    X = zmax * 10 ** data.draw(st.floats(-2.0, 1.5))
    ripple = data.draw(st.floats(0.0, 0.3))
    w = 2 * np.pi * cycles
    v = X / 2 * (2 * np.pi * np.sin(2 * np.pi * t) + ripple * w * np.sin(w * t))
    vmax = np.max(np.abs(v))
    if name == "modified_lugre":
        assume(vmax <= model.params.v1)
    F, S = _simulate_or_reject(model, t, v, kw, return_state=True)
    z = S[:, 0]
    Sg, D, zd, g = _lugre_like(model, z, v, kw)
    assume(np.all(D * np.abs(v) < 4 * g))  # Olsson's condition along the motion
    Fb = Sg * z + D * zd
    W = cumulative_trapezoid(Fb * v, t, initial=0.0)
    V = 0.5 * Sg * z ** 2
    scale = np.trapezoid(np.abs(Fb * v), t) + 1e-300
    assert np.min(W - V) >= -1e-4 * scale, (np.min(W - V), scale)


# -- 4. pre-sliding: the Dahl loop ----------------------------------------------------------
def dahl_setup(name, data):
    """Model with a constant Stribeck level and no rate terms: (model, S, zs, k_lin, kw)."""
    S = 10 ** data.draw(st.floats(3.0, 7.0))
    level = 10 ** data.draw(st.floats(-2.0, 1.5))
    kw = {}
    if name == "lugre":
        m = make_model(name, sigma0=S, sigma1=0.0, sigma2=0.0, Fc=level, Fs=level)
    elif name == "modified_lugre":
        m = make_model(name, sigma0=S, sigma1=0.0, sigma2=0.0, Fc=level, Fs=level, f_a=0.0,
                       gamma_form="cosine")
    elif name == "load_lugre":
        k = data.draw(st.floats(0.0, 1.0))
        load = data.draw(st.floats(0.0, 1e3))
        m = make_model(name, sigma0=S, sigma1=0.0, sigma20=0.0, Fc0=level, Fs0=level,
                       k1_low=k, k2_low=k, k1_high=k, k2_high=k, k3_low=0.0, k3_high=0.0,
                       vc=1e-4)
        level = level + k * load
        kw["load"] = load
    elif name == "mre_lugre":
        alpha = S / level  # saturation 1/alpha plays level/sigma0
        k0 = data.draw(st.floats(0.0, 1e4))
        m = make_model(name, beta=S, alpha=alpha, eps=0.0, c0=0.0, k0=k0, f0=0.0)
        return m, S, 1.0 / alpha, k0, kw
    else:
        return None
    return m, S, level / S, 0.0, kw


def dahl_loop(m, zs, A, kw, n=4001):
    """One periodic loop x = A cos(w t) started on the orbit (tip deflection z_A)."""
    t = np.linspace(0.0, 1.0, n)
    w = 2 * np.pi
    # slow enough for the Gamma switch (< v1) and the Stribeck part: A w << 1e-4 m/s
    scale = 1e-5 / (A * w)
    t = t / scale
    x = A * np.cos(w * scale * t)
    v = -A * w * scale * np.sin(w * scale * t)
    zA = zs * math.tanh(A / zs)
    extra = {k: np.full(n, val) for k, val in kw.items()}
    if m.name == "mre_lugre":
        extra["x"] = x
    F = m.simulate(t, v, state0=np.r_[zA, np.zeros(len(m.state_names) - 1)], **extra)
    return x, F


DAHL = ["lugre", "modified_lugre", "load_lugre", "mre_lugre"]


@pytest.mark.parametrize("name", DAHL)
@SETTINGS
@given(data=st.data())
def test_presliding_loop_is_the_dahl_hysteresis(name, data):
    m, S, zs, k_lin, kw = dahl_setup(name, data)
    ratios = sorted(data.draw(st.lists(st.floats(1e-3, 5.0), min_size=2, max_size=3,
                                       unique=True)))
    secants = []
    for r in ratios:
        A = r * zs
        x, F = dahl_loop(m, zs, A, kw)
        zA = zs * math.tanh(A / zs)
        k_sec = (F[0] - F[x.size // 2]) / (x[0] - x[x.size // 2])
        assert k_sec == pytest.approx(S * zA / A + k_lin, rel=1e-6)
        area = np.trapezoid(F, x)  # = int F v dt over the cycle: dissipated energy
        E = math.exp(-2 * A / zs)
        expected = 2 * S * (2 * A * zs - zs * (zs + zA) * (1 - E))
        assert area > 0
        assert area == pytest.approx(expected, rel=2e-3, abs=1e-9 * S * A * A)
        secants.append(k_sec)
    assert np.all(np.diff(secants) < 0)  # stiffness softens with amplitude
    if ratios[0] < 1e-2:
        assert secants[0] == pytest.approx(S + k_lin, rel=1e-2)  # F = sigma0 x


@pytest.mark.parametrize("name", [n for n in DAHL if n != "mre_lugre"])
def test_small_displacement_gives_sigma0_x(name):
    """Deep in pre-sliding the friction law is a spring of stiffness sigma0."""
    m = make_model(name, sigma1=0.0)
    kw = {}
    if "load" in m.extra_inputs:
        kw["load"] = np.full(20001, 1e3)
        zmax = _z_bound(m, kw)
    else:
        zmax = m.z_max()
    A = 1e-4 * zmax
    t = np.linspace(0, 1, 20001)
    x = A * np.sin(2 * np.pi * t)
    v = A * 2 * np.pi * np.cos(2 * np.pi * t)
    F = m.simulate(t, v, **kw)
    # F = sigma0 x + sigma2 v (+ offset): least squares on (x, v, 1)
    coef = np.linalg.lstsq(np.c_[x, v, np.ones_like(x)], F, rcond=None)[0]
    assert coef[0] == pytest.approx(m.params.sigma0, rel=1e-3)
