"""Documents: every example of examples/shapes and examples/scenes loads, round-trips
through to_dict / to_json, and evaluates the same after the round trip."""

import json
import pathlib

import numpy as np
import pytest

import splinekit as sk

ROOT = pathlib.Path(__file__).resolve().parents[3]
EXAMPLES = sorted((ROOT / "examples" / "shapes").glob("*.json")) + sorted((ROOT / "examples" / "scenes").glob("*.json"))


def test_there_are_examples():
    assert len(EXAMPLES) >= 20


def sample(obj):
    if isinstance(obj, sk.Curve):
        a, b = obj.domain
        return obj(np.linspace(a, b, 7))
    (a, b), (c, d) = obj.domain_u, obj.domain_v
    return obj(np.linspace(a, b, 5), np.linspace(c, d, 4))


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_example_round_trips(path):
    obj = sk.load(path)
    again = sk.load(obj.to_dict())
    assert again.to_dict() == obj.to_dict()
    assert sk.load(obj.to_json()).to_json() == obj.to_json()
    assert sk.load(str(path)).to_json() == obj.to_json()
    if isinstance(obj, sk.Scene):
        assert obj.to_dict() == json.loads(path.read_text())
        for shape, copy in zip(obj.objects, again.objects):
            np.testing.assert_array_equal(sample(shape), sample(copy))
    else:
        np.testing.assert_array_equal(sample(obj), sample(again))


def test_constructed_curves_round_trip_to_their_class():
    c = sk.BSpline([0, 0, 0, 1, 2, 2, 2], [[0, 0], [1, 2], [3, 2], [4, 0]], 2)
    d = c.to_dict()
    assert d == {"type": "bspline", "degree": 2, "knots": [0, 0, 0, 1, 2, 2, 2], "control_points": [[0, 0], [1, 2], [3, 2], [4, 0]]}
    assert isinstance(sk.load(d), sk.BSpline)
    for obj in [
        sk.NURBS([0, 0, 1, 1], [[0, 0], [1, 1]], [1, 2], 1),
        sk.Bezier([[0.0], [1.0]]),
        sk.RationalBezier([[0, 0, 0], [1, 1, 1]], [1, 3]),
        sk.Hermite([[0, 0], [1, 0]], [[1, 1], [1, -1]], params=[0, 2]),
        sk.CatmullRom([[0, 0], [1, 0], [1, 1]]),
        sk.BSplineSurface([0, 0, 1, 1], [0, 0, 1, 1], [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]], 1, 1),
        sk.NURBSSurface([0, 0, 1, 1], [0, 0, 1, 1], [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]], [[1, 1], [1, 2]], 1, 1),
        sk.BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]),
    ]:
        copy = sk.load(obj.to_json())
        assert type(copy) is type(obj) and copy.to_dict() == obj.to_dict()


def test_model_and_blending_documents_are_curves():
    heart = sk.load({"type": "heart"})
    assert type(heart) is sk.Curve and heart.kind == "heart" and heart.closed and heart.dimension == 3
    with pytest.raises(AttributeError, match="a heart curve has no knots"):
        heart.knots
    blend = sk.load({"type": "blending_spline", "model": {"type": "circle"}, "local_curves": 6, "local": {"type": "bezier", "degree": 3}, "bfunction": {"type": "erbs"}})
    np.testing.assert_allclose(np.linalg.norm(blend(np.linspace(0, 6.28, 50)), axis=1), 1.0, atol=5e-3)


def test_a_model_curve_is_fitted_through_its_samples():
    circle = sk.load({"type": "circle", "radius": 2})
    a, b = circle.domain
    points = circle(np.linspace(a, b, 200, endpoint=False))
    c = sk.fit(points, 3, 16, closed=True)
    assert c.fit_report.max_error < 1e-3
