"""Forward sensitivities of the classic LuGre (friction.lugre): the analytic Jacobian equals
finite differences, the normal-equation pass equals J^T r / J^T J, the fused population
cost equals the forces' squared errors, and the identification problem uses them."""
import numpy as np
import pytest

from friction import make_model
from friction.dataset import Dataset
from friction.lugre import (_population_sse_kernel, lugre_normal_equations,
                            lugre_sensitivity_run)

ALL = ["sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs", "alpha", "b"]
ASYM = ["sigma0", "sigma1", "sigma2", "sigma2_neg", "Fc", "Fc_neg", "Fs", "Fs_neg", "vs",
        "vs_neg", "alpha", "b"]


def _motion(rng, n=1500):
    """Random multisine with a dwell at rest and non-uniform steps."""
    h = rng.uniform(0.5e-3, 1.5e-3, n - 1)
    t = np.concatenate(([0.0], np.cumsum(h)))
    v = np.zeros(n)
    for _ in range(3):
        v += rng.uniform(2e-3, 2e-2) * np.sin(2 * np.pi * rng.uniform(0.3, 6) * t
                                              + rng.uniform(0, 6))
    v[n // 3:n // 3 + 40] = 0.0  # sticking
    return t, v


def _model(rng, shape, asym, stiff=True):
    # explicit Euler is stable only while h sigma0 |v| / g < 2: a softer contact for it
    p = dict(sigma0=10 ** (rng.uniform(4, 6) if stiff else rng.uniform(3, 4)),
             sigma1=rng.uniform(10, 500),
             sigma2=rng.uniform(0.1, 5), Fc=rng.uniform(0.5, 2), vs=10 ** rng.uniform(-3.5, -2),
             alpha=rng.uniform(0.8, 3) if shape == "gaussian" else 2.0,
             b=rng.uniform(-0.2, 0.2), shape=shape)
    p["Fs"] = p["Fc"] * rng.uniform(1.1, 2.0)
    if asym:
        p.update(Fc_neg=rng.uniform(0.5, 2), sigma2_neg=rng.uniform(0.1, 5),
                 vs_neg=10 ** rng.uniform(-3.5, -2))
        p["Fs_neg"] = p["Fc_neg"] * rng.uniform(1.1, 2.0)
    return make_model("lugre", **p)


def _central_differences(m, t, v, names, method, rel=1e-6):
    cols = []
    for n in names:
        x = getattr(m.params, n)
        h = rel * max(abs(x), 1e-3)
        up = m.with_values(**{n: x + h}).simulate(t, v, method=method)
        dn = m.with_values(**{n: x - h}).simulate(t, v, method=method)
        cols.append((up - dn) / (2 * h))
    return np.array(cols).T


CASES = [(shape, asym, method, seed) for seed in range(3)
         for shape, asym, method in (("gaussian", False, "exact"), ("gaussian", True, "exact"),
                                     ("lorentzian", True, "exact"), ("gaussian", True, "euler"))]


@pytest.mark.parametrize("shape,asym,method,seed", CASES)
def test_analytic_jacobian_equals_finite_differences(shape, asym, method, seed):
    rng = np.random.default_rng(100 + seed)
    t, v = _motion(rng)
    m = _model(rng, shape, asym, stiff=method == "exact")
    names = [n for n in (ASYM if asym else ALL) if not (shape == "lorentzian" and n == "alpha")]
    F, J = m.force_jacobian(t, v, names, method=method)
    # the force is the simulation's (to rounding)
    F0 = m.simulate(t, v, method=method)
    assert np.max(np.abs(F - F0)) <= 1e-12 * np.max(np.abs(F0))
    Jfd = _central_differences(m, t, v, names, method)
    for j, n in enumerate(names):
        scale = np.max(np.abs(Jfd[:, j]))
        assert scale > 0, n
        err = np.max(np.abs(J[:, j] - Jfd[:, j])) / scale
        assert err < 1e-6, (n, err)


def test_symmetric_parameter_acts_on_both_directions():
    rng = np.random.default_rng(7)
    t, v = _motion(rng)
    m = _model(rng, "gaussian", False)  # Fc_neg etc. None: Fc sets both directions
    _, J = m.force_jacobian(t, v, ["Fc", "vs"])
    Jfd = _central_differences(m, t, v, ["Fc", "vs"], "exact")
    assert np.any(v < 0) and np.any(J[v < 0, 0] != 0)
    assert np.max(np.abs(J - Jfd)) / np.max(np.abs(Jfd)) < 1e-6


def test_normal_equations_and_population_costs():
    rng = np.random.default_rng(3)
    t, v = _motion(rng)
    m = _model(rng, "gaussian", True)
    Fm = m.simulate(t, v) + 0.05 * rng.standard_normal(t.size)
    names = ASYM
    F, J = m.force_jacobian(t, v, names)
    scale = 0.37
    D = len(names)
    H, G = np.zeros((D, D)), np.zeros(D)
    sse = lugre_normal_equations(t, v, m.theta, 0, 0.0, m.jacobian_columns(names), Fm, scale,
                                 H, G)
    r = (F - Fm) * scale
    Js = J * scale
    assert sse == pytest.approx(r @ r, rel=1e-12)
    assert np.allclose(G, Js.T @ r, rtol=1e-9, atol=1e-12 * np.abs(G).max())
    assert np.allclose(H, Js.T @ Js, rtol=1e-9, atol=1e-12 * np.abs(H).max())
    # the fused population cost: blocks of lugre_run with the state carried across
    X = np.array([[m.params.sigma0 * f, m.params.Fc * f] for f in (0.5, 1.0, 2.0)])
    Theta = m.population_theta(["sigma0", "Fc"], X)
    Fpop = m.simulate_population(t, v, ["sigma0", "Fc"], X)
    sse_pop = _population_sse_kernel(t, v, Theta, 0, Fm)
    assert np.allclose(sse_pop, np.sum((Fpop - Fm) ** 2, axis=1), rtol=1e-12)
    # a record of several of the kernel's blocks
    from friction import lugre
    t2 = np.arange(3 * lugre._SSE_BLOCK + 17) * 1e-3
    v2 = 0.01 * np.sin(3 * t2)
    Fm2 = m.simulate(t2, v2) * 1.01
    sse2 = _population_sse_kernel(t2, v2, m.theta[None, :], 0, Fm2)[0]
    assert sse2 == pytest.approx(np.sum((m.simulate(t2, v2) - Fm2) ** 2), rel=1e-12)


def test_identification_problem_uses_the_analytic_jacobian():
    """The unit-cube Jacobian of the problem (analytic) equals its finite differences, and
    the objective refuses it where the law is not the classic LuGre or the start depends on
    the parameters."""
    from identification.executors import InlineExecutor
    from identification.objectives import InProcessObjective
    from identification.problem import Problem
    from identification.space import ParameterSpace
    rng = np.random.default_rng(11)
    t, v = _motion(rng, 2000)
    m = _model(rng, "gaussian", False)
    data = Dataset.from_arrays(t, m.simulate(t, v) + 0.01 * rng.standard_normal(t.size), v=v,
                               check_units=False)
    space = ParameterSpace.build(m, ALL, None, data)
    obj = InProcessObjective(m, data, space.names)
    pr = Problem(obj, space, InlineExecutor())
    assert pr.has_analytic_jacobian
    u = np.clip(space.to_unit(np.array([getattr(m.params, n) for n in ALL])), 0.05, 0.95)
    Ja = pr.jacobian(u)
    assert pr.n_evals == 1  # one sensitivity pass
    pr._analytic = False  # the finite-difference path of the same problem
    Jfd = pr.jacobian(u, step=1e-7)
    for j, n in enumerate(ALL):
        s = np.max(np.abs(Ja[:, j]))
        assert np.max(np.abs(Ja[:, j] - Jfd[:, j])) <= 1e-4 * s, n
    # normal equations in cube coordinates: J^T J and J^T r of the same Jacobian
    pr._analytic = True
    c2, g, H = pr.normal_equations(u)
    r = obj.residuals(space.to_physical(u))
    assert c2 == pytest.approx(r @ r, rel=1e-12)
    assert np.allclose(H, Ja.T @ Ja, rtol=1e-8, atol=1e-10 * np.abs(H).max())
    assert np.allclose(g, Ja.T @ r, rtol=1e-8, atol=1e-10 * np.abs(g).max())
    # no analytic Jacobian: another law, a start from the record
    mod = make_model("modified_lugre")
    assert not InProcessObjective(mod, data, ["Fc"]).has_jacobian()
    held = InProcessObjective(m, data, ALL, start="record")
    assert not held.has_jacobian() and held.jacobian(np.ones(len(ALL))) is None


def test_compressed_residual_has_the_long_residuals_model():
    from identification.algorithms.local import compress_normal_equations
    rng = np.random.default_rng(5)
    J = rng.standard_normal((400, 5)) * np.array([1e-3, 1, 30, 1e2, 0.5])
    r = rng.standard_normal(400)
    f, Jc = compress_normal_equations(r @ r, J.T @ r, J.T @ J)
    assert f.shape == (6,) and Jc.shape == (6, 5)
    assert f @ f == pytest.approx(r @ r, rel=1e-12)
    assert np.allclose(Jc.T @ Jc, J.T @ J, rtol=1e-10)
    assert np.allclose(Jc.T @ f, J.T @ r, rtol=1e-8)


_FRESH_SCRIPT = """
import sys, numpy as np
from friction import make_model
from friction.lugre import lugre_normal_equations, lugre_sensitivity_run
d = np.load(sys.argv[1])
law = make_model("lugre")
t, v, th, cols, Fm = d["t"], d["v"], d["th"], d["cols"], d["Fm"]
# the sensitivity run compiled first, as identify's Jacobian does before its normal
# equations: the order in which the fast-math reductions once vectorised differently
F = np.empty(t.size); J = np.empty((t.size, int((cols >= 0).sum())))
lugre_sensitivity_run(t, v, th, 0, 0.0, cols, F, J)
H = np.zeros((J.shape[1],) * 2); G = np.zeros(J.shape[1])
sse = lugre_normal_equations(t, v, th, 0, 0.0, cols, Fm, 1.0, H, G)
np.savez(sys.argv[2], H=H, G=G, sse=np.array([sse]))
"""


@pytest.mark.slow  # compiles the sensitivity kernels afresh in a subprocess (~20 s)
def test_normal_equations_are_the_same_bits_fresh_or_cached(tmp_path):
    import os
    import subprocess
    import sys
    rng = np.random.default_rng(11)
    t, v = _motion(rng, 3000)
    law = _model(rng, "gaussian", False)
    names = ALL
    from friction.lugre import _LAYOUT
    cols = -np.ones(len(_LAYOUT), np.int64)
    for j, n in enumerate(names):
        cols[_LAYOUT.index(n)] = j
    Fm = law.simulate(t, v) + 0.01 * rng.standard_normal(t.size)
    np.savez(tmp_path / "in.npz", t=t, v=v, th=law.theta, cols=cols, Fm=Fm)
    H = np.zeros((len(names),) * 2)
    G = np.zeros(len(names))
    sse = lugre_normal_equations(t, v, law.theta, 0, 0.0, cols, Fm, 1.0, H, G)
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path / "numba")}  # nothing cached
    (tmp_path / "fresh.py").write_text(_FRESH_SCRIPT)
    subprocess.run([sys.executable, str(tmp_path / "fresh.py"), str(tmp_path / "in.npz"),
                    str(tmp_path / "out.npz")], check=True, env=env, timeout=600)
    out = np.load(tmp_path / "out.npz")
    assert np.array_equal(out["H"], H) and np.array_equal(out["G"], G)
    assert out["sse"][0] == sse
