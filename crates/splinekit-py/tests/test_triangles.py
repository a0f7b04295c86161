"""The triangle family's Python classes (issue 36) against formulas written here in numpy:
a Bézier triangle is the Bernstein sum Σ n!/(i! j! k!) uⁱ vʲ wᵏ P_ijk at the atlas point
(u, v, w) = (s(1 − t), s t, 1 − s) of its chart (s, t), rational with weights; its chart
partials are the derivatives of that sum; a GERBS local moved by Δ moves its corner by Δ and
the centroid by Δ/3; a linear height field reproduces a plane."""

from math import factorial

import numpy as np

import splinekit as sk


def storage(n):
    """(i, j, k) in storage order: b_n00 first, rows of falling i, each by falling j."""
    return [(i, j, n - i - j) for i in range(n, -1, -1) for j in range(n - i, -1, -1)]


def bernstein(points, weights, s, t):
    n = round((np.sqrt(8 * len(points) + 1) - 3) / 2)
    u, v, w = s * (1 - t), s * t, 1 - s
    num, den = np.zeros(s.shape + (points.shape[1],)), np.zeros(s.shape)
    for (i, j, k), p, wt in zip(storage(n), points, weights):
        b = factorial(n) / (factorial(i) * factorial(j) * factorial(k)) * u**i * v**j * w**k * wt
        num += b[..., None] * p
        den += b
    return num / den[..., None]


def test_storage_order_is_the_documented_index():
    for n in range(6):
        for at, (i, j, k) in enumerate(storage(n)):
            assert at == (j + k) * (j + k + 1) // 2 + k


def test_bezier_triangles_are_the_bernstein_sum_with_its_chart_partials():
    rng = np.random.default_rng(36)
    s, t = rng.random(200), rng.random(200)
    for n in (1, 2, 3, 5):
        points = rng.normal(size=((n + 1) * (n + 2) // 2, 3))
        for weights in (None, rng.uniform(0.5, 2.0, len(points))):
            fields = {"control_points": points.tolist()}
            if weights is not None:
                fields["weights"] = weights.tolist()
            tri = sk.BezierTriangle(**fields)
            w = np.ones(len(points)) if weights is None else weights
            np.testing.assert_allclose(tri(s, t, grid=False), bernstein(points, w, s, t), atol=1e-13)
            # The chart's first partials against central differences of the sum.
            inner = (s > 1e-3) & (s < 1 - 1e-3) & (t > 1e-3) & (t < 1 - 1e-3)
            si, ti, h = s[inner], t[inner], 1e-6
            parts = tri.partials(si, ti, order=1, grid=False)
            ds = (bernstein(points, w, si + h, ti) - bernstein(points, w, si - h, ti)) / (2 * h)
            dt = (bernstein(points, w, si, ti + h) - bernstein(points, w, si, ti - h)) / (2 * h)
            np.testing.assert_allclose(parts["u"], ds, atol=1e-7)
            np.testing.assert_allclose(parts["v"], dt, atol=1e-7)


def test_a_moved_gerbs_local_moves_its_corner_by_the_move_and_the_centroid_by_a_third():
    model = {"type": "sub_triangle", "surface": {"type": "sphere", "radius": 2}, "corners": [[0, 0], [1.3, 0.1], [0.5, 1.1]]}
    rest = sk.GerbsTriangle(model=model, degree=2)
    moved = sk.GerbsTriangle(model=model, degree=2, transforms={"1": {"translate": [0.1, -0.2, 0.3]}})
    delta = np.array([0.1, -0.2, 0.3])
    # Chart points (s, t) of the corners u (1, 0), v (1, 1), w (0, ·) and the centroid (2/3, 1/2).
    s = np.array([1.0, 1.0, 0.0, 2.0 / 3.0])
    t = np.array([0.0, 1.0, 0.5, 0.5])
    change = moved(s, t, grid=False) - rest(s, t, grid=False)
    np.testing.assert_allclose(change[0], 0.0, atol=1e-12)
    np.testing.assert_allclose(change[1], delta, atol=1e-12)
    np.testing.assert_allclose(change[2], 0.0, atol=1e-12)
    np.testing.assert_allclose(change[3], delta / 3, atol=1e-12)
    # The corners lie on the model's sphere of radius 2 (the Hermite locals interpolate it).
    np.testing.assert_allclose(np.linalg.norm(rest(s[:3], t[:3], grid=False), axis=1), 2.0, atol=1e-12)


def test_a_linear_height_field_reproduces_a_plane_and_clough_tocher_a_quadratic():
    rng = np.random.default_rng(7)
    xy = rng.uniform(-1, 1, size=(40, 2))
    plane = 2 * xy[:, 0] - xy[:, 1] + 1
    h = sk.Triangulation(points=np.column_stack([xy, plane]).tolist())
    v = h.tessellate(density=20).vertices
    np.testing.assert_allclose(v[:, 2], 2 * v[:, 0] - v[:, 1] + 1, atol=1e-13)
    # z = x² + x y − y²: its normals give the gradients, which Clough–Tocher reproduces.
    z = xy[:, 0] ** 2 + xy[:, 0] * xy[:, 1] - xy[:, 1] ** 2
    gx, gy = 2 * xy[:, 0] + xy[:, 1], xy[:, 0] - 2 * xy[:, 1]
    normals = np.column_stack([-gx, -gy, np.ones(len(xy))])
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    q = sk.Triangulation(
        points=np.column_stack([xy, z]).tolist(), interpolant="clough_tocher", normals=normals.tolist()
    )
    v = q.tessellate(density=20).vertices
    np.testing.assert_allclose(v[:, 2], v[:, 0] ** 2 + v[:, 0] * v[:, 1] - v[:, 1] ** 2, atol=1e-12)
