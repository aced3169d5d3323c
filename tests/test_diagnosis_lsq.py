"""The data starts' linear least squares (:func:`diagnosis.candidates._lsq`): the normal
equations where the columns are well conditioned, LAPACK's SVD solve elsewhere; both give
what ``numpy.linalg.lstsq`` gives."""
import numpy as np
import pytest

from diagnosis.candidates import NORMAL_EQ_RATIO, _lsq


def _reference(A, b):
    c, *_ = np.linalg.lstsq(A, b, rcond=1e-10)
    r = b - A @ c
    return float(r @ r), c


@pytest.mark.parametrize("scales", [(1.0, 1.0, 1.0), (0.1, 1.0, 30.0)])
def test_tall_well_conditioned_columns_solve_as_lstsq(scales):
    rng = np.random.default_rng(3)
    t = np.linspace(0.0, 1.0, 6000)
    # a trend, a cycle and noise
    A = np.column_stack([t, np.sin(9.0 * t), rng.standard_normal(t.size)]) * scales
    b = A @ (np.array([2.0, -1.0, 0.5]) / np.array(scales)) + 0.1 * rng.standard_normal(t.size)
    sse, c = _lsq(A, b)
    sse0, c0 = _reference(A, b)
    np.testing.assert_allclose(c, c0, rtol=1e-9)
    assert sse == pytest.approx(sse0, rel=1e-12)


def test_ill_conditioned_or_degenerate_columns_fall_back_to_the_svd_solve():
    rng = np.random.default_rng(4)
    x = rng.standard_normal(4000)
    b = rng.standard_normal(4000)
    cases = {
        "collinear": np.column_stack([x, 2.0 * x, rng.standard_normal(4000)]),
        "nearly collinear": np.column_stack([x, x + 1e-7 * rng.standard_normal(4000)]),
        "a zero column": np.column_stack([x, np.zeros(4000)]),
        # scaled 12 decades apart: the SVD solve drops the small column's direction
        "badly scaled": np.column_stack([1e-6 * x, 1e6 * rng.standard_normal(4000)]),
        "short and wide": rng.standard_normal((6, 3)),
    }
    for name, A in cases.items():
        bb = b[:A.shape[0]]
        if name in ("collinear", "nearly collinear", "badly scaled"):
            w = np.linalg.eigvalsh(A.T @ A)
            assert w[0] <= NORMAL_EQ_RATIO * w[-1], name  # outside the direct solve
        sse, c = _lsq(A, bb)
        sse0, c0 = _reference(A, bb)
        np.testing.assert_array_equal(c, c0, err_msg=name)  # the same LAPACK call
        assert sse == sse0, name


def test_a_column_with_nan_raises_as_the_svd_solve_does():
    A = np.random.default_rng(5).random((100, 3))
    A[5, 1] = np.nan
    with pytest.raises(np.linalg.LinAlgError, match="SVD did not converge"):
        _lsq(A, np.ones(100))
