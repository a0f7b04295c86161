"""fit and interpolate against scipy's make_lsq_spline and make_interp_spline."""

import numpy as np
import pytest
from scipy.interpolate import make_interp_spline, make_lsq_spline

import splinekit as sk


def samples(m=400, seed=3):
    x = np.linspace(0.0, 1.0, m)
    rng = np.random.default_rng(seed)
    y = np.column_stack([np.sin(6 * x), np.cos(5 * x), x**2]) + 0.01 * rng.normal(size=(m, 3))
    return x, y


def test_lsq_fit_matches_make_lsq_spline():
    x, y = samples()
    knots = np.concatenate([[0] * 4, np.linspace(0, 1, 12)[1:-1], [1] * 4])
    c = sk.fit(y, 3, params=x, knots=knots)
    ref = make_lsq_spline(x, y, knots, k=3)
    np.testing.assert_allclose(c.control_points, ref.c, atol=1e-10)
    np.testing.assert_allclose(c(x), ref(x), atol=1e-10)
    r = c.fit_report
    residual = np.linalg.norm(ref(x) - y, axis=1)
    assert abs(r.rms_error - np.sqrt(np.mean(residual**2))) < 1e-10
    assert abs(r.max_error - residual.max()) < 1e-10
    assert r.condition_estimate >= 1.0
    np.testing.assert_array_equal(r.params, x)


def test_weighted_fit_matches_make_lsq_spline():
    x, y = samples()
    w = np.linspace(0.5, 2.0, x.size)
    knots = np.concatenate([[0] * 4, np.linspace(0, 1, 9)[1:-1], [1] * 4])
    c = sk.fit(y, 3, params=x, knots=knots, weights=w)
    np.testing.assert_allclose(c.control_points, make_lsq_spline(x, y, knots, k=3, w=w).c, atol=1e-10)


def test_named_parametrisations_match_the_same_problem_in_scipy():
    _, y = samples()
    c = sk.fit(y, 3, 20, params="uniform", knots="uniform")
    x = np.linspace(0, 1, len(y))
    knots = np.concatenate([[0] * 4, np.linspace(0, 1, 18)[1:-1], [1] * 4])
    np.testing.assert_allclose(c.knots, knots, atol=1e-15)
    np.testing.assert_allclose(c.control_points, make_lsq_spline(x, y, knots, k=3).c, atol=1e-10)
    assert str(c.fit_report).startswith("fit: rms error ")


def test_fit_options():
    _, y = samples()
    ends = sk.fit(y, 3, 12, fix_ends=True)
    np.testing.assert_allclose(ends(0.0), y[0], atol=1e-14)
    np.testing.assert_allclose(ends(1.0), y[-1], atol=1e-14)
    theta = np.linspace(0, 2 * np.pi, 200, endpoint=False)
    closed = sk.fit(np.column_stack([np.cos(theta), np.sin(theta)]), 3, 16, closed=True)
    assert closed.closed and closed.fit_report.max_error < 1e-4


def test_interpolation_matches_make_interp_spline():
    rng = np.random.default_rng(7)
    y = rng.normal(size=(15, 2))
    c = sk.interpolate(y, 3)
    chord = np.concatenate([[0], np.cumsum(np.linalg.norm(np.diff(y, axis=0), axis=1))])
    x = chord / chord[-1]
    ref = make_interp_spline(x, y, k=3, t=c.knots)
    np.testing.assert_allclose(c.control_points, ref.c, atol=1e-10)
    np.testing.assert_allclose(c(x), y, atol=1e-12)


def test_interpolation_with_end_derivatives_and_closed():
    y = np.array([[0.0, 0], [1, 2], [2, 1], [3, 3], [4, 0]])
    c = sk.interpolate(y, 3, params="uniform", end_derivatives=([1, 0], [0, -1]))
    np.testing.assert_allclose(c(0.0, 1), [1, 0], atol=1e-12)
    np.testing.assert_allclose(c(1.0, 1), [0, -1], atol=1e-12)
    np.testing.assert_allclose(c(np.linspace(0, 1, 5)), y, atol=1e-12)
    closed = sk.interpolate(y, 3, closed=True)
    assert closed.closed
    assert c.fit_report is None


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_fit_accepts_float32_and_lists(dtype):
    _, y = samples(100)
    a = sk.fit(y.astype(dtype), 3, 10)
    b = sk.fit(y.astype(dtype).astype(np.float64).tolist(), 3, 10)
    np.testing.assert_array_equal(a.control_points, b.control_points)
