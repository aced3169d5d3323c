"""The C laws lugre, stribeck and modified_lugre (fmus/native/csrc/laws) equal their numba
kernels.

Hypothesis draws parameter sets inside each parameter's search range (log scale where the
law says so; twins set or None; every option value; for modified_lugre v2 > v1 and tau = 0 or
> 0) and prescribed motions (non-uniform steps of 1e-6..1e-2 s, uniform and jittered runs;
sinusoids, plateaus, exact zeros, ramps through zero, random reversals; the acceleration
np.gradient(v) or independent of v), then compares the C ``pack`` with ``model.theta``, the C
``kernel`` (exact and Euler, nonzero initial state) with ``model._kernel``, and the C
``derivatives``/``force`` with the Python methods.
"""
from __future__ import annotations

import ctypes
import dataclasses
import math
import pathlib
import subprocess
import tempfile

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, note, settings
from hypothesis import strategies as st

from fmus.native import ckernels
from fmus.native.ckernels import CLaw, NativeBuildError, param_vector
from friction.lugre import LuGre, LuGreParams
from friction.modified_lugre import ModifiedLuGre, ModifiedLuGreParams
from friction.stribeck import StaticStribeck, StribeckParams, stribeck_force

SETTINGS = settings(max_examples=50, deadline=None, database=None,
                    suppress_health_check=[HealthCheck.too_slow,
                                           HealthCheck.data_too_large])
OWN_SOURCES = ("lugre.c", "stribeck.c", "modified_lugre.c")
MODELS = {"lugre": LuGre, "stribeck": StaticStribeck, "modified_lugre": ModifiedLuGre}
RTOL = 1e-10      # kernels (the brief's bound; so far they agree bit for bit)
RTOL_CT = 1e-12   # continuous-time derivatives / force
EMPTY = np.zeros(0)


# -- the C laws ---------------------------------------------------------------------------
_CLAWS: dict = {}


def _own_library() -> ctypes.CDLL:
    """This file's three laws compiled alone (when the shared library does not build because
    another law's source is half-written)."""
    out = pathlib.Path(tempfile.mkdtemp(prefix="fl_lugre_")) / "libfl_lugre.so"
    srcs = [str(ckernels.CSRC / "laws" / s) for s in OWN_SOURCES]
    cmd = [ckernels.compiler(), "-std=c99", "-O2", "-fPIC", "-shared", "-Wall", "-Wextra",
           "-Werror", f"-I{ckernels.CSRC}", *srcs, "-o", str(out), "-lm"]
    res = subprocess.run(cmd, capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
    return ctypes.CDLL(str(out))


def claw(name: str) -> CLaw:
    if name in _CLAWS:
        return _CLAWS[name]
    try:
        law = CLaw(name)
    except NativeBuildError:
        lib = _own_library()
        law = CLaw.__new__(CLaw)
        law.name = name
        law.d = ckernels._LawDef.in_dll(lib, f"fl_law_{name}")
        law.n_theta, law.n_states = law.d.n_theta, law.d.n_states
        law._lib = lib
    _CLAWS[name] = law
    return law


def test_sources_compile_warning_free(tmp_path):
    """-Wall -Wextra -pedantic clean; the only exported symbols are the fl_law_ definitions."""
    for src in OWN_SOURCES:
        obj = tmp_path / (src + ".o")
        cmd = [ckernels.compiler(), "-std=c99", "-O2", "-fPIC", "-Wall", "-Wextra",
               "-pedantic", "-Werror", f"-I{ckernels.CSRC}", "-c",
               str(ckernels.CSRC / "laws" / src), "-o", str(obj)]
        res = subprocess.run(cmd, capture_output=True, text=True)
        assert res.returncode == 0, res.stderr
        nm = subprocess.run(["nm", "-g", "--defined-only", str(obj)], capture_output=True,
                            text=True)
        if nm.returncode == 0:
            syms = [line.split()[-1] for line in nm.stdout.splitlines() if line.strip()]
            assert syms == [f"fl_law_{src[:-2]}"], syms


@pytest.mark.parametrize("name", sorted(MODELS))
def test_law_definition(name):
    law, model = claw(name), MODELS[name]()
    d = law.d
    assert d.name.decode() == name
    assert d.n_params == len(dataclasses.fields(model.Params))
    assert d.n_theta == len(model.theta_layout) == model.theta.size
    assert d.n_states == len(model.state_names)
    assert d.inputs == (1 if "a" in model.extra_inputs else 0)  # FL_IN_A of fl_law.h
    assert not d.regimes
    assert bool(d.derivatives) == (d.n_states > 0)
    assert d.force


# -- strategies ---------------------------------------------------------------------------
def _number(info):
    lo, hi = info.search
    if info.log:
        return st.floats(math.log(lo), math.log(hi)).map(math.exp)
    return st.floats(lo, hi)


def _value(draw, info):
    """A value of one numeric parameter inside its search range (special values too)."""
    if info.name == "alpha":
        return draw(st.one_of(st.just(2.0), _number(info)))
    if info.name in ("beta", "gamma"):
        return draw(st.one_of(st.sampled_from([1.0, 2.0]), _number(info)))
    if info.name == "tau":
        return draw(st.one_of(st.just(0.0), _number(info),
                              st.floats(math.log(1e-7), math.log(0.05)).map(math.exp)))
    return draw(_number(info))


@st.composite
def params_of(draw, Params):
    kw = {}
    infos = {i.name: i for i in Params.info()}
    for info in Params.info():
        if info.search is None:
            continue
        if info.default is None:  # direction twin: None or a value
            kw[info.name] = _value(draw, info) if draw(st.booleans()) else None
        else:
            kw[info.name] = _value(draw, info)
    # no Stribeck bump at all (the cut-off's d == 0 branch) now and then
    if "Fs" in kw and draw(st.integers(0, 5)) == 0:
        kw["Fs"] = kw["Fc"]
        if kw.get("Fc_neg") is not None:
            kw["Fs_neg"] = kw["Fc_neg"]
    if "v1" in infos:  # preset switch band, v2 > v1
        v1 = math.exp(draw(st.floats(math.log(1e-4), math.log(0.5))))
        kw["v1"] = v1
        kw["v2"] = v1 * (1.0 + math.exp(draw(st.floats(math.log(1e-3), math.log(10.0)))))
    for name, choices in Params.OPTIONS.items():
        kw[name] = draw(st.sampled_from(sorted(choices)))
    return Params(**kw)


_SEG_KINDS = ("sin", "plateau", "zero", "ramp", "noise")
_DT_MODES = ("uniform", "jitter", "random")


@st.composite
def motions(draw, with_a=False):
    """(t, v, a): non-uniform steps 1e-6..1e-2 s and a velocity mixing sinusoids, plateaus,
    exact zeros, ramps through zero and random reversals."""
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1)))
    segs = draw(st.lists(st.tuples(st.sampled_from(_SEG_KINDS), st.integers(1, 60),
                                   st.floats(-6.0, 0.0), st.sampled_from(_DT_MODES),
                                   st.floats(-6.0, -2.0), st.sampled_from([-1.0, 1.0])),
                         min_size=1, max_size=8))
    dts, vs = [], []
    for kind, n, amp_log, dt_mode, dt_log, sign in segs:
        A = 10.0 ** amp_log
        if dt_mode == "uniform":
            dt = np.full(n, 10.0 ** dt_log)
        elif dt_mode == "jitter":  # below the lag cache's 1e-9 relative tolerance
            dt = 10.0 ** dt_log * (1.0 + 1e-12 * rng.standard_normal(n))
        else:
            dt = 10.0 ** rng.uniform(-6.0, -2.0, n)
        tl = np.cumsum(dt)
        if kind == "sin":
            f = 10.0 ** rng.uniform(0.0, 3.0)
            v = sign * A * np.sin(2 * np.pi * f * tl + rng.uniform(0, 2 * np.pi)) \
                + rng.choice([0.0, 0.5 * A * sign])
        elif kind == "plateau":
            v = np.full(n, sign * A)
        elif kind == "zero":
            v = np.zeros(n)
        elif kind == "ramp":
            v = np.linspace(sign * A, -sign * A, n)
        else:
            v = A * rng.standard_normal(n)
        dts.append(dt)
        vs.append(v)
    dt = np.concatenate(dts)
    v = np.concatenate(vs)
    if v.size < 2:
        dt, v = np.append(dt, dt), np.append(v, -v)
    t = draw(st.floats(-1.0, 10.0)) + np.concatenate(([0.0], np.cumsum(dt[1:])))
    assert np.all(np.diff(t) > 0)
    a = None
    if with_a:
        mode = draw(st.sampled_from(["gradient", "independent", "zero"]))
        if mode == "gradient":
            a = np.gradient(v, t)
        elif mode == "independent":
            a = 10.0 ** rng.uniform(-2.0, 3.0) * rng.standard_normal(v.size)
            a[rng.random(v.size) < 0.2] = 0.0
        else:
            a = np.zeros(v.size)
    return t, v, a


# -- comparisons --------------------------------------------------------------------------
def assert_close(c, p, rtol, what, floor=1e-300):
    """|c - p| <= rtol * max|p| (+ a tiny floor), both finite at the same samples."""
    c, p = np.asarray(c, float), np.asarray(p, float)
    assert c.shape == p.shape, what
    fin = np.isfinite(p)
    assert np.array_equal(np.isfinite(c), fin), f"{what}: finiteness differs"
    if not fin.any():
        return 0.0
    scale = np.max(np.abs(p[fin]))
    err = np.max(np.abs(c[fin] - p[fin]))
    assert err <= rtol * scale + floor, f"{what}: |diff| {err:.3g} > {rtol:g} * {scale:.3g}"
    return err / max(scale, floor)


def _bounded_prefix(F, limit):
    """Samples before explicit Euler blows up (|F| above limit, or not finite)."""
    bad = ~np.isfinite(F) | (np.abs(F) > limit)
    return int(np.argmax(bad)) if bad.any() else F.size


def compare_kernel(name, model, t, v, a, state0):
    law = claw(name)
    theta = law.pack(model.params)
    np.testing.assert_array_equal(theta, model.theta)
    p = model.params
    # a physical force scale: the Stribeck levels, viscous force, offset and F_d levels
    vmax = float(np.max(np.abs(v)))
    levels = [getattr(p, n) or 0.0 for n in ("Fc", "Fs", "Fc_neg", "Fs_neg", "f_a", "f_a_neg")
              if hasattr(p, n)]
    visc = max(p.sigma2, p.resolved("sigma2", -1)) * vmax
    s1 = getattr(p, "sigma1", 0.0) * vmax
    phys = max(levels) + visc + abs(p.b) + s1 + 1.0
    if state0 is not None and state0.size:
        phys += abs(getattr(p, "sigma0", 0.0) * state0[0]) + abs(state0[-1])
    a_py = a if a is not None else EMPTY
    s0_py = state0 if state0 is not None and state0.size else np.zeros(1)
    for method in (0, 1):
        Fp, Sp = model._kernel(t, v, a_py, EMPTY, EMPTY, model.theta, method, s0_py)
        Fc, Sc = law.kernel(t, v, theta, a=a, method=method,
                            state0=state0 if state0 is not None and state0.size else None)
        Sp = np.asarray(Sp)
        assert Sp.shape == Sc.shape == (Fp.size, law.n_states)
        m = Fp.size if method == 0 else _bounded_prefix(Fp, 1e6 * phys)
        note(f"method {method}: {m} of {Fp.size} samples compared")
        if method == 0:
            assert np.all(np.isfinite(Fp)), "exact update must stay finite"
        if m == 0:
            continue
        assert_close(Fc[:m], Fp[:m], RTOL, f"{name} F (method {method})")
        for j in range(law.n_states):
            assert_close(Sc[:m, j], Sp[:m, j], RTOL, f"{name} state {j} (method {method})")


def compare_continuous(name, model, points):
    law = claw(name)
    theta = law.pack(model.params)
    for state, v, a in points:
        kw = {"a": a} if "a" in model.extra_inputs else {}
        with np.errstate(all="ignore"):  # tau down to subnormal: a derivative of +-inf
            _compare_point(law, theta, model, name, state, v, a, kw)


def _compare_point(law, theta, model, name, state, v, a, kw):
    """C and Python derivatives/force at one point, to RTOL_CT of the sum of the magnitudes
    of their terms (the terms can cancel; numpy's exp is not glibc's to the last bit)."""
    p = model.params
    fc = law.force(theta, state, v, a=a)
    fp = model.force(state, v, **kw)
    twins = [getattr(p, n, None) for n in ("Fc", "Fs", "Fc_neg", "Fs_neg")]
    gmin = min(x for x in twins if x is not None)
    fa = max(getattr(p, "f_a", 0.0), getattr(p, "f_a_neg", None) or 0.0)
    zd_scale = 0.0
    if law.n_states:
        dc = law.derivatives(theta, state, v, a=a)
        dp = np.asarray(model.derivatives(state, v, **kw), float)
        zd_scale = abs(v) * (1.0 + p.sigma0 * abs(state[0]) / gmin)
        scales = [zd_scale]
        if law.n_states > 1:
            scales.append((abs(a) + fa + abs(state[1])) / p.tau if p.tau > 0 else 0.0)
        for j, sc in enumerate(scales):
            if np.isinf(dp[j]):
                assert dc[j] == dp[j], f"{name} derivative {j}: {dc[j]!r} != {dp[j]!r}"
                continue
            assert abs(dc[j] - dp[j]) <= RTOL_CT * sc + 1e-300, \
                f"{name} derivative {j} at v={v!r}, a={a!r}: {dc[j]!r} != {dp[j]!r}"
    scale = (abs(getattr(p, "sigma0", 0.0) * state[0]) if law.n_states else 0.0) \
        + getattr(p, "sigma1", 0.0) * zd_scale + max(p.Fs, p.Fc, *[x for x in twins if x]) \
        + max(p.sigma2, p.resolved("sigma2", -1)) * abs(v) + abs(p.b) + fa \
        + (abs(state[1]) if law.n_states > 1 else 0.0)
    assert abs(fc - fp) <= RTOL_CT * scale, f"{name} force at v={v!r}: {fc!r} != {fp!r}"


def _points(draw, model, v, a):
    """Random (state, v, a) around the motion's samples, with v = 0 and both signs."""
    p = model.params
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1)))
    n_states = len(model.state_names)
    zmax = model.z_max() if hasattr(model, "z_max") else 0.0
    out = []
    picks = list(rng.choice(v.size, size=min(6, v.size), replace=False))
    for k, vk in [(k, v[k]) for k in picks] + [(0, 0.0), (0, -v[0]), (0, 3 * p.vs)]:
        ak = float(a[k]) if a is not None else float(rng.standard_normal())
        state = np.array([rng.uniform(-2, 2) * zmax, 10.0 ** rng.uniform(-2, 2)
                          * rng.standard_normal()][:n_states])
        out.append((state, float(vk), ak))
    return out


# -- the proofs ---------------------------------------------------------------------------
@st.composite
def cases(draw, Model):
    params = draw(params_of(Model.Params))
    model = Model(params)
    t, v, a = draw(motions(with_a="a" in Model.extra_inputs))
    n = len(model.state_names)
    state0 = None
    if n:
        zmax = model.z_max()
        state0 = np.array([draw(st.floats(-2.0, 2.0)) * zmax,
                           draw(st.floats(-20.0, 20.0))][:n])
        if draw(st.booleans()):
            state0[0] = 0.0
    points = _points(draw, model, v, a)
    return model, t, v, a, state0, points


@pytest.mark.parametrize("name", ["lugre", "stribeck", "modified_lugre"])
def test_c_kernel_equals_numba(name):
    @SETTINGS
    @given(cases(MODELS[name]))
    def check(case):
        model, t, v, a, state0, points = case
        note(repr(model.params))
        compare_kernel(name, model, t, v, a, state0)
        compare_continuous(name, model, points)

    check()


def test_stribeck_force_equals_numba_map():
    """The stribeck FMU's force is the numba one-sample map stribeck_force, bit for bit."""
    rng = np.random.default_rng(3)
    law = claw("stribeck")
    for shape in ("gaussian", "lorentzian"):
        for alpha in (2.0, 0.7):
            m = StaticStribeck(StribeckParams(Fc=1.1, Fs=1.7, vs=2e-3, alpha=alpha, sigma2=0.3,
                                              b=-0.2, Fc_neg=0.9, vs_neg=3e-3, shape=shape))
            th = law.pack(m.params)
            for v in np.concatenate((rng.standard_normal(50) * 10.0 ** rng.uniform(-6, 0, 50),
                                     [0.0, -0.0, 1e-300, -1e-300])):
                assert law.force(th, np.zeros(0), float(v)) == stribeck_force(float(v), th)


def test_modified_lugre_lag_cache_reused_on_uniform_and_jittered_steps():
    """Long uniform and jittered runs (the lag factors' cache) and a reversal inside a step
    with every option, including tau = 0, agree to the bit with numba."""
    t = np.concatenate((np.arange(400) * 5e-5, 0.02 + np.cumsum(
        5e-5 * (1 + 1e-12 * np.sin(np.arange(300))))))
    v = 0.3 * np.sin(2 * np.pi * 20 * t)
    v[100:130] = 0.0
    for a in (np.gradient(v, t), np.cos(np.arange(t.size)) * 40.0):
        for shape in ("gaussian", "lorentzian"):
            for gf in ("logistic", "cosine"):
                for fd in ("lag", "filtered_acceleration"):
                    for tau in (0.0, 1e-6, 2e-3):
                        m = ModifiedLuGre(ModifiedLuGreParams(
                            shape=shape, gamma_form=gf, fd_form=fd, tau=tau, f_a_neg=3.0,
                            a_s_neg=5.0, Fc_neg=5.0, beta=1.7, gamma=2.0))
                        for method in (0, 1):
                            s0 = np.array([3e-6, 0.4])
                            Fp, Sp = m._kernel(t, v, a, EMPTY, EMPTY, m.theta, method, s0)
                            Fc, Sc = claw("modified_lugre").kernel(
                                t, v, m.theta, a=a, method=method, state0=s0)
                            np.testing.assert_array_equal(Fc, Fp)
                            np.testing.assert_array_equal(Sc, Sp)


# -- pack refusals ------------------------------------------------------------------------
def _pack_raw(monkeypatch, name, p):
    """CLaw.pack on a hand-made p[] (a code the Python dataclass could not hold)."""
    monkeypatch.setattr(ckernels, "param_vector", lambda params: np.asarray(p, float))
    return claw(name).pack(MODELS[name]().params)


@pytest.mark.parametrize("name", sorted(MODELS))
def test_pack_refuses_bad_option_codes(monkeypatch, name):
    Params = MODELS[name].Params
    names = [f.name for f in dataclasses.fields(Params)]
    p0 = param_vector(Params())
    np.testing.assert_array_equal(_pack_raw(monkeypatch, name, p0), MODELS[name]().theta)
    for option, choices in Params.OPTIONS.items():
        for bad in (len(choices), -1.0, 0.5, math.nan, math.inf):
            p = p0.copy()
            p[names.index(option)] = bad
            with pytest.raises(ValueError, match=rf"^{option} = .*must be one of") as exc:
                _pack_raw(monkeypatch, name, p)
            for code, choice in enumerate(sorted(choices, key=choices.get)):
                assert f"{code} ({choice})" in str(exc.value)


@pytest.mark.parametrize("v1, v2", [(0.2, 0.1), (0.15, 0.15), (0.3, 1e-3), (1e-5, 2.5e-6)])
def test_modified_lugre_pack_refuses_v2_not_above_v1(v1, v2):
    with pytest.raises(ValueError) as py:
        ModifiedLuGreParams(v1=v1, v2=v2)
    params = ModifiedLuGreParams()
    object.__setattr__(params, "v1", v1)  # bypass the Python check to reach the C one
    object.__setattr__(params, "v2", v2)
    with pytest.raises(ValueError) as c:
        claw("modified_lugre").pack(params)
    assert str(c.value) == str(py.value)
    assert str(c.value).startswith(f"v2 = {v2!r} must be > v1 = {v1!r} [m/s]")


def test_pack_twins_resolve_to_plus_values():
    for name, Params in (("lugre", LuGreParams), ("stribeck", StribeckParams),
                         ("modified_lugre", ModifiedLuGreParams)):
        twins = {i.name: 1.2345 * (i.default if i.default else 1.0) for i in Params.info()
                 if i.name.endswith("_neg")}
        for kw in ({}, twins):
            model = MODELS[name](Params(**kw))
            np.testing.assert_array_equal(claw(name).pack(model.params), model.theta)


@settings(max_examples=100, deadline=None, database=None)
@given(st.floats(5e-324, 1e300), st.floats(0.0, 1.0))
@example(v1=2.0 ** -24, frac=0.0)   # repr's 16 digits are not printf's nearest 16
@example(v1=100.0, frac=0.0)        # "100.0", not "1e+02"
@example(v1=1e16, frac=0.5)
@example(v1=5e-324, frac=0.0)
def test_modified_lugre_relation_message_is_the_python_one(v1, frac):
    """Any v2 <= v1: the C message is the Python ParameterError text, the values written as
    Python's repr writes them."""
    v2 = v1 * frac
    if not v2 > 0.0:
        v2 = v1
    with pytest.raises(ValueError) as py:
        ModifiedLuGreParams(v1=v1, v2=v2)
    params = ModifiedLuGreParams()
    object.__setattr__(params, "v1", v1)
    object.__setattr__(params, "v2", v2)
    with pytest.raises(ValueError) as c:
        claw("modified_lugre").pack(params)
    assert str(c.value) == str(py.value)
