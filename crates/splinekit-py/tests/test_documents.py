"""Documents: every example of examples/shapes and examples/scenes loads, round-trips
through to_dict / to_json, and evaluates the same after the round trip."""

import json
import os
import pathlib
import subprocess

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


# Decimals that a fast but inexact float parser gets one ulp wrong, the extremes of the
# doubles, and random doubles of every magnitude a document may hold (up to ±1e150).
HARD_DECIMALS = [0.1, 2.675, 1e-7, 5e-324, 2.2250738585072014e-308, 2.225073858507201e-308, 9007199254740993.0,
                 0.30000000000000004, 1.0000000000000002, 123456789.12345679, 8.98846567431158e-150, 1e150]


def decimals_document():
    rng = np.random.default_rng(12)
    mantissas = rng.uniform(1.0, 10.0, 400)
    exponents = rng.integers(-320, 150, 400).astype(float)
    values = HARD_DECIMALS + [float(m * 10.0**e) for m, e in zip(mantissas, exponents) if 0 < m * 10.0**e <= 1e150]
    values += values[: len(values) % 2]
    points = [values[i : i + 2] for i in range(0, len(values), 2)]
    n = len(points)
    knots = [0.0] + [float(i) for i in range(n)] + [float(n - 1)]
    return {"type": "bspline", "degree": 1, "knots": knots, "control_points": points}


def bits(values):
    return np.asarray(values, dtype=np.float64).view(np.uint64)


def test_decimals_come_back_bit_exact_through_load_and_to_json(tmp_path):
    doc = decimals_document()
    text = json.dumps(doc)  # Python writes the shortest decimal that reads back exactly
    path = tmp_path / "decimals.json"
    path.write_text(text)
    for source in (text, str(path), path):
        obj = sk.load(source)
        np.testing.assert_array_equal(bits(obj.control_points), bits(doc["control_points"]))
        back = json.loads(obj.to_json())
        np.testing.assert_array_equal(bits(back["control_points"]), bits(doc["control_points"]))
        assert sk.load(obj.to_json()).to_json() == obj.to_json()
    assert json.loads(sk.load(text).to_json())["control_points"] == doc["control_points"]


def test_the_largest_double_is_refused_with_its_exact_digits(tmp_path):
    with pytest.raises(ValueError, match=r"^control_points\[0\]\[0\]: 1\.7976931348623157e308 is beyond ±1e150, "):
        sk.load('{"type": "bezier", "control_points": [[1.7976931348623157e308, 0], [1, 1]]}')


CLI = pathlib.Path(os.environ.get("SPLINEKIT_CLI", ROOT / "target" / "debug" / "splinekit"))


@pytest.mark.skipif(not CLI.exists(), reason="the splinekit binary is not built (cargo build -p splinekit-cli)")
def test_the_cli_reads_and_writes_the_same_decimals_bit_exact(tmp_path):
    doc = decimals_document()
    path = tmp_path / "decimals.json"
    path.write_text(json.dumps(doc))
    n = len(doc["control_points"])
    # A degree-1 B-spline passes through its control points at its knots exactly.
    at = ",".join(str(i) for i in range(n))
    r = subprocess.run([str(CLI), "eval", str(path), "--at", at], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    np.testing.assert_array_equal(bits(json.loads(r.stdout)["points"]), bits(doc["control_points"]))
    # Through Python and back through the CLI: the same points again.
    again = tmp_path / "again.json"
    again.write_text(sk.load(path).to_json())
    r2 = subprocess.run([str(CLI), "eval", str(again), "--at", at], capture_output=True, text=True)
    assert r2.stdout == r.stdout


def test_edited_local_control_points_load_evaluate_and_round_trip():
    # At knot c3 = 3·2π/10 the blend is local 3 alone: its edited quadratic Bézier at the
    # midpoint of its support, (P0 + 2 P1 + P2) / 4.
    points = [[10.0, 0.0, 0.0], [14.0, -4.0, 2.0], [12.0, -8.0, 0.0]]
    doc = {"type": "blending_spline", "model": {"type": "heart"}, "local_curves": 10,
           "local": {"type": "bezier", "degree": 2}, "local_control_points": {"3": points}}
    c = sk.load(doc)
    p = np.asarray(c(np.array([3 * 2 * np.pi / 10])))[0]
    np.testing.assert_allclose(p, (np.array(points[0]) + 2 * np.array(points[1]) + np.array(points[2])) / 4, atol=1e-12)
    assert c.to_dict()["local_control_points"] == {"3": points}
    plain = sk.load({k: v for k, v in doc.items() if k != "local_control_points"})
    t = np.linspace(0, 2 * np.pi, 201)
    outside = (t <= 2 * 2 * np.pi / 10) | (t >= 4 * 2 * np.pi / 10)
    np.testing.assert_array_equal(np.asarray(c(t))[outside], np.asarray(plain(t))[outside])
    with pytest.raises(ValueError, match=r"local_control_points\.3: expected 3 control points for a Bézier local of degree 2, got 2"):
        sk.load({**doc, "local_control_points": {"3": points[:2]}})
