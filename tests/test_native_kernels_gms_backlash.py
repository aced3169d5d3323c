"""The C laws gms and backlash_lugre (fmus/native/csrc/laws) equal their numba kernels.

As tests/test_native_kernels_lugre.py (whose strategies are reused): hypothesis draws
parameter sets inside each parameter's search range (log scale where the law says so; every
option value; backlash twins set or None and delta = 0 now and then) and prescribed motions
(non-uniform steps of 1e-6..1e-2 s; sinusoids, plateaus, exact zeros, ramps through zero,
random reversals), then compares the C ``pack`` with ``model.theta``, the C ``kernel``
(exact and Euler, nonzero initial state: deflections up to twice the saturation, the play
anywhere in the gap or outside it) with ``model._kernel`` to 1e-10 relative, and the C
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
from hypothesis import given, note
from hypothesis import strategies as st

from friction.backlash import BacklashLuGre
from friction.gms import GMS
from fmus.native import ckernels
from fmus.native.ckernels import CLaw, NativeBuildError, param_vector
from test_native_kernels_lugre import (SETTINGS, _bounded_prefix, assert_close, motions,
                                       params_of)

OWN_SOURCES = ("gms.c", "backlash_lugre.c")
MODELS = {"gms": GMS, "backlash_lugre": BacklashLuGre}
RTOL = 1e-10      # kernels (they agree bit for bit so far)
RTOL_CT = 1e-12   # continuous-time derivatives / force (numpy's exp and pow vs libm's)
EMPTY = np.zeros(0)
_CLAWS: dict = {}


def _own_library() -> ctypes.CDLL:
    """This file's laws compiled alone (when another law's source does not build)."""
    out = pathlib.Path(tempfile.mkdtemp(prefix="fl_gms_")) / "libfl_gms.so"
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
    """-Wall -Wextra -pedantic clean; the only exported symbol is the fl_law_ definition."""
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
    assert d.inputs == 0
    assert not d.regimes
    assert d.derivatives and d.force


# -- cases --------------------------------------------------------------------------------
@st.composite
def cases(draw, name):
    Model = MODELS[name]
    params = draw(params_of(Model.Params))
    if name == "backlash_lugre" and draw(st.integers(0, 4)) == 0:
        params = params.replace(delta=0.0)
    model = Model(params)
    t, v, _ = draw(motions())
    scales = model.state_scales()
    state0 = np.array([draw(st.floats(-2.0, 2.0)) for _ in scales]) * scales
    if draw(st.booleans()):
        state0[:] = 0.0
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1)))
    points = []
    picks = list(rng.choice(v.size, size=min(6, v.size), replace=False))
    for vk in [v[k] for k in picks] + [0.0, -v[0], 3 * model.params.vs]:
        state = rng.uniform(-1.5, 1.5, scales.size) * scales
        if name == "backlash_lugre" and rng.random() < 0.5:  # on a flank
            state[1] = rng.choice([-1.0, 1.0]) * model.params.delta
        points.append((state, float(vk)))
    return model, t, v, state0, points


def compare_kernel(name, model, t, v, state0):
    law = claw(name)
    theta = law.pack(model.params)
    np.testing.assert_array_equal(theta, model.theta)
    p = model.params
    vmax = float(np.max(np.abs(v)))
    phys = max(p.Fc, p.Fs, getattr(p, "Fc_neg", None) or 0.0, getattr(p, "Fs_neg", None) or 0.0) \
        + max(p.sigma2, p.resolved("sigma2", -1)) * vmax + abs(p.b) \
        + getattr(p, "sigma1", 0.0) * vmax + 1.0
    for method in (0, 1):
        Fp, Sp = model._kernel(t, v, EMPTY, EMPTY, EMPTY, model.theta, method, state0)
        Fc, Sc = law.kernel(t, v, theta, method=method, state0=state0)
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
    p = model.params
    gmax = max(p.Fc, p.Fs, getattr(p, "Fc_neg", None) or 0.0, getattr(p, "Fs_neg", None) or 0.0)
    gmin = min(x for x in (p.Fc, p.Fs, getattr(p, "Fc_neg", None), getattr(p, "Fs_neg", None))
               if x is not None)
    scales = model.state_scales()
    for state, v in points:
        dc = law.derivatives(theta, state, v)
        dp = np.asarray(model.derivatives(state, v), float)
        # a rate scale per state: |v| and the relaxation rates times the deflections
        if name == "gms":
            rate = abs(v) + p.C / gmin * (np.abs(state) + scales)
        else:
            rate = np.full(2, abs(v) * (1.0 + p.sigma0 * abs(state[0]) / gmin))
        for j in range(law.n_states):
            assert abs(dc[j] - dp[j]) <= RTOL_CT * rate[j] + 1e-300, \
                f"{name} derivative {j} at v={v!r}: {dc[j]!r} != {dp[j]!r}"
        fc = law.force(theta, state, v)
        fp = model.force(state, v)
        elastic = state if name == "gms" else state[:1]  # the deflections sigma0 acts on
        fscale = p.sigma0 * float(np.sum(np.abs(elastic))) \
            + getattr(p, "sigma1", 0.0) * rate[0] + gmax + abs(p.b) \
            + max(p.sigma2, p.resolved("sigma2", -1)) * abs(v)
        assert abs(fc - fp) <= RTOL_CT * fscale, f"{name} force at v={v!r}: {fc!r} != {fp!r}"


@pytest.mark.parametrize("name", sorted(MODELS))
def test_c_kernel_equals_numba(name):
    @SETTINGS
    @given(cases(name))
    def check(case):
        model, t, v, state0, points = case
        note(repr(model.params))
        compare_kernel(name, model, t, v, state0)
        compare_continuous(name, model, points)

    check()


def test_reversal_inside_a_step_engagement_and_the_limits_bit_for_bit():
    """Reversals inside steps, an engagement inside a step, a huge attraction rate, a gap
    of zero and forces across the play: the C kernels equal numba to the bit."""
    t = np.concatenate((np.arange(400) * 5e-5, 0.02 + np.cumsum(np.full(300, 1.3e-4))))
    v = 2e-3 * np.sin(2 * np.pi * 40 * t) + 1e-4
    v[100:130] = 0.0
    cases_ = [GMS(), GMS(GMS.Params(C=1e12, spread=1.0)), GMS(GMS.Params(C=1.0, alpha=0.5)),
              # unequal break-away shares (the softest block a twentieth of the stiffest's)
              GMS(GMS.Params(spread=1e4, tilt=0.05, sigma1=30.0)),
              # LuGre bristles in place of slip-blocks, damped, unequal shares
              GMS(GMS.Params(spread=30.0, tilt=0.3, sigma1=30.0, element="bristle")),
              BacklashLuGre(), BacklashLuGre(BacklashLuGre.Params(delta=0.0)),
              BacklashLuGre(BacklashLuGre.Params(delta=3e-6, gap="free", Fc_neg=2.0)),
              # what bridges the play: a bias, an anti-backlash spring and a drag
              BacklashLuGre(BacklashLuGre.Params(delta=3e-6, gap="free", gap_bias=0.1,
                                                 gap_stiffness=2e4, gap_drag=0.3)),
              BacklashLuGre(BacklashLuGre.Params(delta=3e-6, gap_bias=-0.2,
                                                 gap_stiffness=5e4, gap_drag=0.1))]
    for m in cases_:
        law = claw(m.name)
        for method in (0, 1):
            s0 = m.steady_state_state(-1e-3)
            Fp, Sp = m._kernel(t, v, EMPTY, EMPTY, EMPTY, m.theta, method, s0)
            Fc, Sc = law.kernel(t, v, m.theta, method=method, state0=s0)
            np.testing.assert_array_equal(Fc, Fp)
            np.testing.assert_array_equal(Sc, Sp)


# -- pack refusals ------------------------------------------------------------------------
def _pack_raw(monkeypatch, name, p):
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


def test_backlash_pack_twins_resolve_to_plus_values():
    Params = BacklashLuGre.Params
    twins = {i.name: 1.2345 * (i.default if i.default else 1.0) for i in Params.info()
             if i.name.endswith("_neg")}
    for kw in ({}, twins):
        model = BacklashLuGre(Params(**kw))
        np.testing.assert_array_equal(claw("backlash_lugre").pack(model.params), model.theta)
