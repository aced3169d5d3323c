"""identification.algorithms.trf.trf_exact runs scipy's trust-region reflective least
squares (tr_solver="exact", x_scale=1): the same iterates, evaluations and status."""
import numpy as np
import pytest
from scipy.optimize import least_squares

from identification.algorithms.trf import trf_exact


def _rosenbrock(x):
    f = np.array([10.0 * (x[1] - x[0] ** 2), 1.0 - x[0], 0.5 * (x[2] - x[1]) ** 2 + 0.1 * x[2]])
    J = np.array([[-20.0 * x[0], 10.0, 0.0], [-1.0, 0.0, 0.0],
                  [0.0, -(x[2] - x[1]), (x[2] - x[1]) + 0.1]])
    return f, J


def _exp_fit(x, t=np.linspace(0.0, 3.0, 40)):
    y = 2.0 * np.exp(-1.3 * t) + 0.4 + 0.01 * np.sin(7 * t)
    e = np.exp(-x[1] * t)
    f = x[0] * e + x[2] - y
    J = np.column_stack([e, -x[0] * t * e, np.ones_like(t)])
    return f, J


CASES = [  # (function, start, lower, upper): the optimum inside, on a face, from a corner
    (_rosenbrock, [-1.2, 1.0, 0.5], [-2.0, -2.0, -2.0], [2.0, 2.0, 2.0]),
    (_rosenbrock, [-1.2, 0.2, 0.5], [-2.0, -2.0, -2.0], [0.5, 0.3, 2.0]),
    (_exp_fit, [0.5, 0.1, 0.0], [0.0, 0.0, -1.0], [5.0, 5.0, 1.0]),
    (_exp_fit, [0.5, 0.1, 0.0], [0.0, 0.0, -1.0], [5.0, 1.0, 0.2]),
    (_exp_fit, [4.999, 4.9, 0.99], [0.0, 0.0, -1.0], [5.0, 5.0, 1.0]),
]


@pytest.mark.parametrize("case", range(len(CASES)))
@pytest.mark.parametrize("tol,max_nfev", [(1e-10, None), (1e-6, 7)])
def test_same_iterates_as_scipy(case, tol, max_nfev):
    fj, x0, lb, ub = CASES[case]
    seen_ours, seen_scipy = [], []

    def ours(x):
        seen_ours.append(np.array(x))
        return fj(x)

    a = least_squares(lambda x: (seen_scipy.append(np.array(x)), fj(x)[0])[1], x0,
                      jac=lambda x: fj(x)[1], bounds=(lb, ub), method="trf",
                      tr_solver="exact", x_scale=1.0, ftol=tol, xtol=tol, gtol=tol,
                      max_nfev=max_nfev)
    b = trf_exact(ours, np.array(x0, float), np.array(lb, float), np.array(ub, float),
                  ftol=tol, xtol=tol, gtol=tol, max_nfev=max_nfev)
    assert b.nfev == a.nfev and b.status == a.status and b.success == a.success
    assert len(seen_ours) == len(seen_scipy)
    np.testing.assert_allclose(np.array(seen_ours), np.array(seen_scipy), rtol=1e-9,
                               atol=1e-12)
    np.testing.assert_allclose(b.x, a.x, rtol=1e-9, atol=1e-12)
    assert b.cost == pytest.approx(a.cost, rel=1e-9, abs=1e-15)


def test_stop_hook_ends_the_run_with_its_message():
    fj, x0, lb, ub = CASES[2]
    calls = []

    def stop(f, J, cost):
        calls.append(cost)
        return "enough" if len(calls) == 3 else None

    r = trf_exact(fj, np.array(x0, float), np.array(lb, float), np.array(ub, float),
                  ftol=1e-12, xtol=1e-12, gtol=1e-12, stop=stop)
    full = trf_exact(fj, np.array(x0, float), np.array(lb, float), np.array(ub, float),
                     ftol=1e-12, xtol=1e-12, gtol=1e-12)
    assert r.status == 2 and r.message == "enough" and r.nfev < full.nfev
    assert r.cost == calls[-1]


def test_non_finite_start_refused():
    with pytest.raises(ValueError, match="not finite"):
        trf_exact(lambda x: (np.array([np.nan]), np.ones((1, 1))), np.array([0.5]),
                  np.zeros(1), np.ones(1))
