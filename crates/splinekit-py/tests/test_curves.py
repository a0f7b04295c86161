"""Curve evaluation against scipy.interpolate.BSpline, shapes, dtypes and operations."""

import numpy as np
import pytest
from scipy.interpolate import BSpline as ScipyBSpline

import splinekit as sk


def random_cubic(n=40, d=3, seed=1):
    rng = np.random.default_rng(seed)
    interior = np.sort(rng.uniform(0.0, 1.0, n - 4))
    knots = np.concatenate([[0.0] * 4, interior, [1.0] * 4])
    return knots, rng.normal(size=(n, d))


@pytest.mark.parametrize("d", [1, 2, 3])
def test_points_and_derivatives_match_scipy(d):
    knots, cp = random_cubic(d=d)
    c = sk.BSpline(knots, cp, 3)
    ref = ScipyBSpline(knots, cp, 3)
    t = np.linspace(0.0, 1.0, 1001)
    np.testing.assert_allclose(c(t), ref(t), rtol=0, atol=1e-10)
    for nu in (1, 2, 3):
        np.testing.assert_allclose(c(t, nu), ref(t, nu), rtol=1e-10, atol=1e-9)
    ders = c.derivatives(t, 2)
    assert ders.shape == (t.size, 3, d)
    for k in range(3):
        np.testing.assert_allclose(ders[:, k], ref(t, k), rtol=1e-10, atol=1e-9)


def test_unsorted_parameters_match_scipy():
    knots, cp = random_cubic()
    t = np.random.default_rng(5).uniform(0, 1, 500)
    np.testing.assert_allclose(sk.BSpline(knots, cp, 3)(t, 1), ScipyBSpline(knots, cp, 3)(t, 1), atol=1e-9)


def test_shapes_and_dtypes():
    knots, cp = random_cubic(d=2)
    c = sk.BSpline(knots, cp, 3)
    assert c(0.5).shape == (2,)
    assert c([0.1, 0.5]).shape == (2, 2)
    assert c.derivatives(0.5, 3).shape == (4, 2)
    assert c.derivatives([0.5], 0).shape == (1, 1, 2)
    assert c(np.empty(0)).shape == (0, 2)
    for out in (c(0.3), c([0.3]), c([0.3], 2), c.derivatives([0.3], 1)):
        assert out.dtype == np.float64 and out.flags["C_CONTIGUOUS"]
    assert c.knots.dtype == np.float64 and c.control_points.shape == (40, 2)
    assert c.degree == 3 and c.domain == (0.0, 1.0) and not c.closed and c.dimension == 2
    np.testing.assert_array_equal(c.weights, np.ones(40))


def test_accepts_lists_tuples_float32_and_strided_arrays():
    knots, cp = random_cubic(d=3)
    c = sk.BSpline(tuple(knots), cp.tolist(), 3)
    t = np.linspace(0, 1, 21)
    expected = c(t)
    np.testing.assert_array_equal(c(t.tolist()), expected)
    np.testing.assert_array_equal(c(tuple(t)), expected)
    np.testing.assert_allclose(c(t.astype(np.float32)), c(t.astype(np.float32).astype(np.float64)))
    strided = np.linspace(0, 1, 41)[::2]
    assert not strided.flags["C_CONTIGUOUS"]
    np.testing.assert_array_equal(c(strided), expected)
    np.testing.assert_allclose(sk.BSpline(knots, np.asfortranarray(cp), 3)(t), expected)
    np.testing.assert_array_equal(c(np.float32(0.5)), c(0.5))


def test_python_numbers_are_read_as_numpy_reads_them():
    # Python floats and ints skip numpy's conversion; the values, shapes and errors are
    # those of the 0-d array numpy makes of them.
    c = sk.BSpline([0, 0, 0, 0, 2**60, 2**61, 2**61, 2**61, 2**61], np.arange(15.0).reshape(5, 3), 3)
    class Half(float):
        pass
    for x in (0.5, np.float64(0.5), Half(0.5), 1, 2**53 + 1, 2**60 + 3, True, np.int64(7), np.float32(0.25), -0.0):
        ours = c(x)
        assert ours.shape == (3,) and ours.dtype == np.float64
        np.testing.assert_array_equal(ours, c(np.asarray(x, dtype=np.float64)))
        np.testing.assert_array_equal(ours, c([x])[0])
        np.testing.assert_array_equal(c(x, 1), c(np.asarray(x, dtype=np.float64), 1))
    for x, message in ((2**62, r"^t: parameter 4611686018427388000 is outside the domain"),
                       (-10**7, r"^t: parameter -10000000 is outside the domain"),
                       (float("nan"), r"^t\[0\]: value is not finite \(NaN\)$"),
                       (np.float64("inf"), r"^t\[0\]: value is not finite \(inf\)$")):
        with pytest.raises(ValueError, match=message):
            c(x)
    with pytest.raises(OverflowError):
        np.asarray(10**400, dtype=np.float64)
    with pytest.raises(OverflowError):
        c(10**400)


def test_bezier_rational_hermite_catmull_rom():
    b = sk.Bezier([[0, 0], [1, 2], [3, 2], [4, 0]])
    np.testing.assert_allclose(b(0.5), [2.0, 1.5])
    assert b.degree == 3
    w = np.sqrt(0.5)
    arc = sk.RationalBezier([[1, 0], [1, 1], [0, 1]], [1, w, 1])
    np.testing.assert_allclose(np.linalg.norm(arc(np.linspace(0, 1, 11)), axis=1), 1.0, atol=1e-15)
    h = sk.Hermite([[0, 0], [1, 0]], [[1, 1], [1, -1]])
    np.testing.assert_allclose(h(0.0, 1), [1, 1])
    np.testing.assert_allclose(h(1.0), [1, 0])
    cr = sk.CatmullRom([[0, 0], [1, 0], [1, 1], [0, 1]], alpha=0.5, closed=True)
    assert cr.closed
    np.testing.assert_allclose(cr(cr.domain[0]), [0, 0], atol=1e-15)
    np.testing.assert_allclose(cr(cr.domain[1]), [0, 0], atol=1e-15)


def test_nurbs_circle_length_curvature_frame_closest_point():
    w = np.sqrt(0.5)
    cp = [[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0], [-1, -1], [0, -1], [1, -1], [1, 0]]
    knots = [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1]
    c = sk.NURBS(knots, np.array(cp, float) * 2, [1, w, 1, w, 1, w, 1, w, 1], 2)
    assert isinstance(c, sk.Curve)
    np.testing.assert_allclose(np.linalg.norm(c(np.linspace(0, 1, 101)), axis=1), 2.0, atol=1e-14)
    assert abs(c.length() - 4 * np.pi) < 1e-9
    np.testing.assert_allclose(c.curvature([0.1, 0.6]), 0.5, atol=1e-12)
    assert isinstance(c.curvature(0.1), float)
    f = c.frame(0.0)
    np.testing.assert_allclose(f["tangent"], [0, 1], atol=1e-15)
    np.testing.assert_allclose(f["normal"], [-1, 0], atol=1e-15)
    assert f["binormal"] is None
    t, p, dist = c.closest_point([3.0, 0.0])
    np.testing.assert_allclose(p, [2.0, 0.0], atol=1e-12)
    assert abs(dist - 1.0) < 1e-12 and t in (0.0, 1.0)


def test_knot_operations_keep_the_curve():
    knots, cp = random_cubic(n=12, d=3)
    c = sk.BSpline(knots, cp, 3)
    t = np.linspace(0, 1, 201)
    refined = c.insert_knot(0.37, times=2)
    assert len(refined.knots) == len(knots) + 2
    np.testing.assert_allclose(refined(t), c(t), atol=1e-13)
    elevated = c.elevate_degree(2)
    assert elevated.degree == 5
    np.testing.assert_allclose(elevated(t), c(t), atol=1e-12)
    back = refined.remove_knot(0.37, tolerance=1e-9, times=2)
    assert len(back.knots) == len(knots)
    np.testing.assert_allclose(back(t), c(t), atol=1e-9)
    left, right = c.split(0.4)
    assert left.domain == (0.0, 0.4) and right.domain == (0.4, 1.0)
    np.testing.assert_allclose(left(t[t <= 0.4]), c(t[t <= 0.4]), atol=1e-13)
    np.testing.assert_allclose(right(t[t >= 0.4]), c(t[t >= 0.4]), atol=1e-13)
    pieces = c.to_bezier()
    assert len(pieces) == len(np.unique(knots)) - 1
    assert all(isinstance(p, sk.Bezier) and p.degree == 3 for p in pieces)
    np.testing.assert_allclose(pieces[0](0.0), c(0.0), atol=1e-14)
    np.testing.assert_allclose(pieces[-1](1.0), c(1.0), atol=1e-14)


def test_periodic_bspline_is_closed_and_split_cuts_it_open():
    square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    knots = [(i - 2) / 4 for i in range(7)]
    c = sk.BSpline(knots, square, 2, periodic=True)
    assert c.closed
    np.testing.assert_allclose(c(0.0), [0.5, 0.0], atol=1e-15)
    np.testing.assert_allclose(c(1.25), c(0.25), atol=1e-15)
    opened, none = c.split(0.1)
    assert none is None and not opened.closed
    np.testing.assert_allclose(opened(0.3), c(0.3), atol=1e-14)


def test_rational_operations_stay_rational():
    w = np.sqrt(0.5)
    arc = sk.RationalBezier([[1, 0], [1, 1], [0, 1]], [1, w, 1])
    n = arc.insert_knot(0.5)
    assert isinstance(n, sk.NURBS)
    np.testing.assert_allclose(np.linalg.norm(n(np.linspace(0, 1, 11)), axis=1), 1, atol=1e-15)
    pieces = n.to_bezier()
    assert len(pieces) == 2 and all(isinstance(p, sk.RationalBezier) for p in pieces)
    assert isinstance(arc.elevate_degree(), sk.RationalBezier)


def test_threads_evaluate_in_parallel_with_the_same_results():
    from concurrent.futures import ThreadPoolExecutor

    knots, cp = random_cubic(n=200)
    c = sk.BSpline(knots, cp, 3)
    t = np.linspace(0, 1, 200_000)
    expected = c(t)
    with ThreadPoolExecutor(4) as pool:
        for out in pool.map(lambda _: c(t), range(8)):
            np.testing.assert_array_equal(out, expected)


def test_contiguous_float64_parameters_are_read_in_place():
    import tracemalloc

    c = sk.BSpline([0, 0, 1, 1], [[0.0], [1.0]], 1)
    t = np.linspace(0, 1, 1_000_000)
    tracemalloc.start()
    c(t)  # the (N, 1) output: 8 MB
    contiguous = tracemalloc.get_traced_memory()[1]
    tracemalloc.reset_peak()
    c(t[::-1][::-1].astype(np.float32))  # a converted copy on top: 8 MB more
    converted = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert contiguous < 9_000_000 < 15_000_000 < converted


def test_derivatives_above_the_degree_are_zero():
    knots, cp = random_cubic(n=10, d=2)
    for c in (sk.BSpline(knots, cp, 3), sk.NURBS(knots, cp, np.ones(10), 3), sk.Bezier(cp[:3])):
        ders = c.derivatives(np.linspace(0, 1, 50), 6)
        np.testing.assert_array_equal(ders[:, c.degree + 1 :], 0.0)
