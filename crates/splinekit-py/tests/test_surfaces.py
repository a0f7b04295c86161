"""Surfaces against scipy (NdBSpline, bisplev as RectBivariateSpline evaluates) and
NURBS against geomdl."""

import numpy as np
import pytest
from geomdl import NURBS as GeomdlNURBS
from scipy.interpolate import NdBSpline, bisplev

import splinekit as sk


def random_surface(nu=8, nv=7, d=3, seed=2):
    rng = np.random.default_rng(seed)
    ku = np.concatenate([[0] * 4, np.sort(rng.uniform(0, 1, nu - 4)), [1] * 4])
    kv = np.concatenate([[0] * 4, np.sort(rng.uniform(0, 1, nv - 4)), [1] * 4])
    return ku, kv, rng.normal(size=(nu, nv, d))


def test_grid_values_and_partials_match_ndbspline():
    ku, kv, cp = random_surface()
    s = sk.BSplineSurface(ku, kv, cp, 3, 3)
    ref = NdBSpline((ku, kv), cp, 3)
    u, v = np.linspace(0, 1, 23), np.linspace(0, 1, 19)
    uu, vv = np.meshgrid(u, v, indexing="ij")
    xi = np.stack([uu.ravel(), vv.ravel()], axis=1)
    np.testing.assert_allclose(s(u, v), ref(xi).reshape(23, 19, 3), atol=1e-10)
    parts = s.partials(u, v, order=2)
    assert sorted(parts) == ["u", "uu", "uv", "v", "vv"]
    for key, nu in {"u": (1, 0), "v": (0, 1), "uu": (2, 0), "uv": (1, 1), "vv": (0, 2)}.items():
        np.testing.assert_allclose(parts[key], ref(xi, nu=nu).reshape(23, 19, 3), rtol=1e-10, atol=1e-8)


def test_scalar_surface_matches_bisplev():
    ku, kv, cp = random_surface(d=1)
    s = sk.BSplineSurface(ku, kv, cp, 3, 3)
    u, v = np.linspace(0, 1, 11), np.linspace(0, 1, 13)
    tck = (ku, kv, cp[:, :, 0].ravel(), 3, 3)
    np.testing.assert_allclose(s(u, v)[:, :, 0], bisplev(u, v, tck), atol=1e-10)
    np.testing.assert_allclose(s.partials(u, v)["u"][:, :, 0], bisplev(u, v, tck, dx=1), atol=1e-8)


def test_paired_evaluation_shapes_and_normals():
    ku, kv, cp = random_surface()
    s = sk.BSplineSurface(ku, kv, cp, 3, 3)
    u, v = np.linspace(0, 1, 9), np.linspace(0, 1, 9)[::-1]
    paired = s(u, v, grid=False)
    assert paired.shape == (9, 3)
    np.testing.assert_allclose(paired, [s(a, b) for a, b in zip(u, v)], atol=1e-14)
    assert s(0.5, 0.5).shape == (3,)
    n = s.normals(u, v, grid=False)
    p = s.partials(u, v, grid=False)
    cross = np.cross(p["u"], p["v"])
    np.testing.assert_allclose(n, cross / np.linalg.norm(cross, axis=1)[:, None], atol=1e-12)
    points, normals = s.points_and_normals(u, v)
    assert points.shape == normals.shape == (9, 9, 3)
    np.testing.assert_allclose(points, s(u, v), atol=1e-14)
    np.testing.assert_allclose(np.linalg.norm(normals, axis=2), 1.0, atol=1e-12)
    assert s.control_points.shape == (8, 7, 3) and s.degrees == (3, 3)
    assert s.weights.shape == (8, 7) and len(s.knots) == 2


def test_grid_normals_of_high_degrees_match_ndbspline():
    # Issue 20: degree 4 or 5 in v ended in "range end index 10 out of range for slice of
    # length 8" on the grid path of normals; every degree up to 7 each way against scipy.
    rng = np.random.default_rng(20)
    for p, q in [(3, 4), (3, 5), (5, 5), (2, 7), (7, 2)]:
        nu, nv = p + 3, q + 2
        ku = np.concatenate([[0] * (p + 1), np.sort(rng.uniform(0, 1, nu - p - 1)), [1] * (p + 1)])
        kv = np.concatenate([[0] * (q + 1), np.sort(rng.uniform(0, 1, nv - q - 1)), [1] * (q + 1)])
        cp = rng.normal(size=(nu, nv, 3))
        s = sk.BSplineSurface(ku, kv, cp, p, q)
        ref = NdBSpline((ku, kv), cp, (p, q))
        u, v = np.linspace(0, 1, 7), np.linspace(0, 1, 6)
        uu, vv = np.meshgrid(u, v, indexing="ij")
        xi = np.stack([uu.ravel(), vv.ravel()], axis=1)
        cross = np.cross(ref(xi, nu=(1, 0)), ref(xi, nu=(0, 1))).reshape(7, 6, 3)
        want = cross / np.linalg.norm(cross, axis=2)[:, :, None]
        points, normals = s.points_and_normals(u, v)
        np.testing.assert_allclose(points, ref(xi).reshape(7, 6, 3), atol=1e-10)
        np.testing.assert_allclose(normals, want, atol=1e-8)
        np.testing.assert_allclose(s.normals(u, v), want, atol=1e-8)


def test_bezier_surface_and_closest_point():
    cp = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]
    s = sk.BezierSurface(cp)
    np.testing.assert_allclose(s(0.5, 0.5), [0.5, 0.5, 0.25])
    u, v, p, d = s.closest_point([1, 1, 2])
    assert (u, v) == pytest.approx((1.0, 1.0), abs=1e-9) and abs(d - 1.0) < 1e-9


def test_model_surfaces_load_and_evaluate():
    sphere = sk.load({"type": "sphere", "radius": 2})
    assert isinstance(sphere, sk.Surface) and sphere.closed_u and not sphere.closed_v
    u = np.linspace(0, 2 * np.pi, 17)
    v = np.linspace(-1.2, 1.2, 9)
    np.testing.assert_allclose(np.linalg.norm(sphere(u, v), axis=2), 2.0, atol=1e-14)
    np.testing.assert_allclose(sphere.normals(u, v), sphere(u, v) / 2, atol=1e-14)


def test_nurbs_curve_matches_geomdl():
    rng = np.random.default_rng(4)
    cp = rng.normal(size=(9, 3))
    w = rng.uniform(0.5, 2.0, 9)
    knots = [0, 0, 0, 0, 0.2, 0.4, 0.5, 0.7, 0.9, 1, 1, 1, 1]
    g = GeomdlNURBS.Curve()
    g.degree = 3
    g.ctrlptsw = [list(p * wi) + [wi] for p, wi in zip(cp, w)]
    g.knotvector = knots
    c = sk.NURBS(knots, cp, w, 3)
    t = np.linspace(0, 1, 57)
    np.testing.assert_allclose(c(t), g.evaluate_list(t.tolist()), atol=1e-12)
    for ti in t[::7]:
        d = g.derivatives(ti, order=2)
        np.testing.assert_allclose(c.derivatives(ti, 2), d, atol=1e-9)


def test_nurbs_surface_matches_geomdl():
    rng = np.random.default_rng(6)
    ku, kv, cp = random_surface(6, 5)
    w = rng.uniform(0.5, 2.0, (6, 5))
    g = GeomdlNURBS.Surface()
    g.degree_u, g.degree_v = 3, 3
    g.ctrlpts_size_u, g.ctrlpts_size_v = 6, 5
    g.ctrlptsw = [list(cp[i, j] * w[i, j]) + [w[i, j]] for i in range(6) for j in range(5)]
    g.knotvector_u, g.knotvector_v = ku.tolist(), kv.tolist()
    s = sk.NURBSSurface(ku, kv, cp, w, 3, 3)
    u, v = np.linspace(0, 1, 7), np.linspace(0, 1, 6)
    ref = np.array([[g.evaluate_single((a, b)) for b in v] for a in u])
    np.testing.assert_allclose(s(u, v), ref, atol=1e-12)
    d = g.derivatives(0.3, 0.6, order=1)
    parts = s.partials(0.3, 0.6)
    np.testing.assert_allclose(parts["u"], d[1][0], atol=1e-9)
    np.testing.assert_allclose(parts["v"], d[0][1], atol=1e-9)
