"""The Python class of a kind comes from its line in splinekit-scene's registry:
hand-written classes (``own``), the plain bases (``base``) and classes made from a kind's
document fields (``fields "Name"``: the Dupin cyclide)."""

import pickle

import numpy as np
import pytest

import splinekit as sk


def test_a_kind_declared_with_its_fields_is_a_class_made_from_them():
    s = sk.DupinCyclide(a=3, c=1, mu=2)
    assert type(s) is sk.DupinCyclide and isinstance(s, sk.Surface)
    assert type(s).__module__ == "splinekit" and s.kind == "dupin_cyclide"
    loaded = sk.load({"type": "dupin_cyclide", "a": 3, "c": 1, "mu": 2})
    assert type(loaded) is sk.DupinCyclide
    u = np.linspace(0.0, 2.0 * np.pi, 7)
    np.testing.assert_array_equal(s(u, u), loaded(u, u))
    back = pickle.loads(pickle.dumps(s))
    assert type(back) is sk.DupinCyclide
    np.testing.assert_array_equal(back(u, u), s(u, u))
    # The defaults are a = 3, c = 1, μ = 2: at (0, 0) the point (μ(c − a) + b²)/(a − c) = 2 on x.
    np.testing.assert_allclose(sk.DupinCyclide()(0.0, 0.0), [2.0, 0.0, 0.0], atol=1e-15)
    # Every point on the quartic (x² + y² + z² − μ² + b²)² = 4(ax − cμ)² + 4b²y².
    x, y, z = s(u, u).reshape(-1, 3).T
    a, c, mu, b2 = 3.0, 1.0, 2.0, 8.0
    lhs = (x * x + y * y + z * z - mu * mu + b2) ** 2
    np.testing.assert_allclose(lhs, 4 * (a * x - c * mu) ** 2 + 4 * b2 * y * y, rtol=1e-12)


def test_bad_fields_raise_the_command_lines_message():
    with pytest.raises(ValueError, match="a: must be greater than c = 2, got 1"):
        sk.DupinCyclide(a=1, c=2)
    with pytest.raises(ValueError, match="radius"):
        sk.DupinCyclide(radius=1)


def test_other_kinds_keep_their_classes():
    assert type(sk.load({"type": "torus"})) is sk.Surface
    assert type(sk.load({"type": "circle"})) is sk.Curve
    assert type(sk.load({"type": "bezier", "control_points": [[0, 0], [1, 1]]})) is sk.Bezier
    net = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]
    assert type(sk.load({"type": "bezier_surface", "control_points": net})) is sk.BezierSurface


def test_triangle_kinds_are_classes_made_from_their_fields():
    # A flat Bézier triangle: its atlas chart (s, t) is (u, v, w) = (s(1 − t), s t, 1 − s).
    t = sk.BezierTriangle(control_points=[[1, 0, 0], [0, 1, 0], [0, 0, 0]])
    assert type(t) is sk.BezierTriangle and t.kind == "bezier_triangle"
    np.testing.assert_allclose(t(0.5, 0.25), [0.375, 0.125, 0.0], atol=1e-15)
    back = pickle.loads(pickle.dumps(t))
    assert type(back) is sk.BezierTriangle
    with pytest.raises(ValueError, match="control_points"):
        sk.BezierTriangle(control_points=[[0, 0, 0]] * 4)
    # A triangle of the unit sphere stays on it.
    s = sk.SubTriangle(surface={"type": "sphere"}, corners=[[0.3, 0.2], [1.4, 0.3], [0.8, 1.1]])
    np.testing.assert_allclose(np.linalg.norm(s(0.4, 0.6)), 1.0, atol=1e-14)
    g = sk.GerbsTriangle(model=s.to_dict(), degree=3)
    assert type(g) is sk.GerbsTriangle
    # At its corner w (s = 0) the GERBS triangle has the model's value.
    np.testing.assert_allclose(g(0.0, 0.5), s(0.0, 0.5), atol=1e-14)
    h = sk.Triangulation(points=[[0, 0, 1], [1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]])
    assert type(h) is sk.Triangulation
    # The pyramid's first triangle at its corner w: a vertex with its height.
    assert h(0.0, 0.0)[2] in (0.0, 1.0)
    b = sk.BlendingTriangulation(mesh={"type": "icosphere", "subdivisions": 1})
    assert type(b) is sk.BlendingTriangulation
    assert b.tessellate(tolerance=1e-2).faces.shape[1] == 3
