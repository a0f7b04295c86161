"""Objects that travel: every object pickles (every protocol, 5 included), copies and
deep-copies into an equal object (``==``) that evaluates bit for bit as the original —
in this process and, unpickled, in another one."""

import copy
import pathlib
import pickle
import subprocess
import sys

import numpy as np
import pytest

import splinekit as sk

ROOT = pathlib.Path(__file__).resolve().parents[3]
EXAMPLES = sorted((ROOT / "examples" / "shapes").glob("*.json")) + sorted((ROOT / "examples" / "scenes").glob("*.json"))


def sample(obj):
    """What an object computes, as arrays: points (and a derivative) of curves and
    surfaces, the four arrays of meshes, values of B-functions, the numbers of reports."""
    if isinstance(obj, sk.Curve):
        a, b = obj.domain
        t = np.linspace(a, b, 23)
        return [obj(t), obj(t, 1)]
    if isinstance(obj, sk.Surface):
        (a, b), (c, d) = obj.domain_u, obj.domain_v
        u, v = np.linspace(a, b, 9), np.linspace(c, d, 7)
        return [obj(u, v), obj.partials(u, v)["v"]]
    if isinstance(obj, sk.Scene):
        return [array for shape in obj.objects for array in sample(shape)]
    if isinstance(obj, sk.Mesh):
        return [obj.vertices, obj.faces, obj.normals, obj.uv]
    if isinstance(obj, sk.BFunction):
        t = np.linspace(0, 1, 31)
        return [obj(t), obj(t, 1)]
    if isinstance(obj, sk.FitReport):
        return [np.array([obj.rms_error, obj.max_error, obj.condition_estimate]), obj.params]
    raise TypeError(obj)


def bits(arrays):
    """The exact bytes of every array (so 0.0 and −0.0, or two NaNs, are told apart)."""
    return [(a.dtype.str, a.shape, np.ascontiguousarray(a).tobytes()) for a in arrays]


def constructed():
    """One object of every kind with a constructor, plus fit, mesh and B-function."""
    rng = np.random.default_rng(21)
    data = rng.normal(size=(60, 3)).cumsum(axis=0)
    fitted = sk.fit(data, 3, 12)
    net = rng.normal(size=(4, 5, 3))
    surface = sk.BSplineSurface([0, 0, 0, 0.4, 1, 1, 1], [0, 0, 0, 0.3, 0.6, 1, 1, 1], net, 2, 2)
    return {
        "bspline": sk.BSpline([0, 0, 0, 0.25, 0.5, 1, 1, 1], rng.normal(size=(5, 2)), 2),
        "periodic_bspline": sk.BSpline(np.arange(-3.0, 9.0), rng.normal(size=(8, 3)), 3, periodic=True),
        "nurbs": sk.NURBS([0, 0, 0, 1, 1, 1], [[1, 0], [1, 1], [0, 1]], [1, np.sqrt(0.5), 1], 2),
        "bezier": sk.Bezier(rng.normal(size=(6, 4))),
        "rational_bezier": sk.RationalBezier([[1, 0, 0], [1, 1, 0], [0, 1, 1]], [1, 0.3, 2]),
        "hermite": sk.Hermite([[0, 0], [1, 1], [3, 0]], [[1, 0], [1, 1], [0, -1]], params=[0, 0.7, 2.1]),
        "catmull_rom": sk.CatmullRom(rng.normal(size=(7, 3)), alpha=0.5, closed=True),
        "fit": fitted,
        "fit_report": fitted.fit_report,
        "interpolation": sk.interpolate(data[:20], 3),
        "bspline_surface": surface,
        "nurbs_surface": sk.NURBSSurface(
            [0, 0, 1, 1], [0, 0, 1, 1], net[:2, :2], rng.uniform(0.5, 2, size=(2, 2)), 1, 1
        ),
        "bezier_surface": sk.BezierSurface(net),
        "mesh": surface.tessellate(density=6),
        "adaptive_mesh": sk.load({"type": "torus"}).tessellate(tolerance=0.05),
        "erbs": sk.bfunction("erbs", **{"lambda": 0.3}),
        "polynomial_bfunction": sk.bfunction("polynomial", smoothness=2),
    }


OBJECTS = constructed()


def check_travels(obj):
    expected = bits(sample(obj))
    for protocol in (0, 2, pickle.HIGHEST_PROTOCOL):
        again = pickle.loads(pickle.dumps(obj, protocol=protocol))
        assert type(again) is type(obj)
        assert again == obj and not (again != obj)
        assert bits(sample(again)) == expected
    for twin in (copy.copy(obj), copy.deepcopy(obj)):
        assert twin is not obj and type(twin) is type(obj)
        assert twin == obj
        assert bits(sample(twin)) == expected


@pytest.mark.parametrize("name", sorted(OBJECTS))
def test_constructed_objects_travel(name):
    check_travels(OBJECTS[name])


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_every_example_travels(path):
    obj = sk.load(path)
    check_travels(obj)
    if not isinstance(obj, sk.Scene):
        assert pickle.loads(pickle.dumps(obj, protocol=5)).to_dict() == obj.to_dict()


def test_a_fitted_curve_keeps_its_report():
    fitted = OBJECTS["fit"]
    again = pickle.loads(pickle.dumps(fitted, protocol=5))
    assert again.fit_report == fitted.fit_report
    assert str(again.fit_report) == str(fitted.fit_report)
    np.testing.assert_array_equal(again.fit_report.params, fitted.fit_report.params)
    assert sk.BSpline(fitted.knots, fitted.control_points, fitted.degree).fit_report is None


def test_a_fit_report_state_holds_its_parameters_as_exact_bytes():
    report = OBJECTS["fit"].fit_report
    restore, (tag, state, extra) = report.__reduce__()
    params = state[3]
    assert isinstance(params, bytes) and params == report.params.astype("<f8").tobytes()
    # A list of floats (the state pickles of 0.1.0 held) restores the same report.
    assert restore(tag, (*state[:3], report.params.tolist()), extra) == report
    with pytest.raises(ValueError, match="^state: the parameters take 12 bytes, not a whole number of doubles"):
        restore(tag, (*state[:3], bytes(12)), extra)


def test_a_transformed_blending_spline_travels_with_its_frames(heart):
    curve = sk.load(heart)
    before = pickle.dumps(curve, protocol=5)
    curve.set_transform(1, translate=[0.25, -0.5, 0.125], scale=1.5)
    again = pickle.loads(pickle.dumps(curve, protocol=5))
    assert again == curve
    assert bits(sample(again)) == bits(sample(curve))
    assert pickle.loads(before) != curve


def test_copies_are_independent(heart):
    curve = sk.load(heart)
    twin = copy.deepcopy(curve)
    twin.set_transform(0, translate=[1.0, 0.0, 0.0])
    assert twin != curve
    assert curve == sk.load(heart)


def test_equality_is_by_document():
    a = OBJECTS["bspline"]
    b = sk.BSpline(a.knots, a.control_points, a.degree)
    assert a == b
    moved = a.control_points.copy()
    moved[2, 1] = np.nextafter(moved[2, 1], np.inf)
    assert a != sk.BSpline(a.knots, moved, a.degree)
    assert a != OBJECTS["nurbs"] and a != "bspline" and a != a.to_dict()
    assert OBJECTS["mesh"] != OBJECTS["adaptive_mesh"]
    assert sk.bfunction("erbs") == sk.bfunction("erbs") != sk.bfunction("linear")
    with pytest.raises(TypeError):
        hash(a)


def test_exact_doubles_survive():
    # Numbers with no short decimal form, the extremes of a double, and −0.0.
    points = np.array([[0.1, 1 / 3], [np.pi, -0.0], [1e-300, 2.0**-1074], [9.999999999999999e149, 4.0]])
    curve = sk.Bezier(points)
    again = pickle.loads(pickle.dumps(curve, protocol=5))
    assert again.control_points.tobytes() == points.tobytes()


def test_restore_refuses_a_bad_state():
    with pytest.raises(ValueError, match="^control_points: expected at least 1 point, got 0$"):
        sk._splinekit._restore("curve", {"type": "bezier", "control_points": []}, None)
    with pytest.raises(ValueError, match="unknown object kind"):
        sk._splinekit._restore("teapot", {}, None)
    with pytest.raises(ValueError, match="triangles"):
        sk._splinekit._restore("mesh", (bytes(24), b"", b"", b"", np.array([0, 1, 5], "<u4").tobytes()), None)


CHILD = """
import pickle, sys
import numpy as np
objects, params = pickle.load(sys.stdin.buffer)
out = {}
for name, obj in objects.items():
    t = params[name]
    if isinstance(obj, tuple(getattr(__import__("splinekit"), k) for k in ("Curve", "BFunction"))):
        out[name] = [np.asarray(obj(t)), np.asarray(obj(t, 1))]
    else:
        out[name] = [obj(*t)]
sys.stdout.buffer.write(pickle.dumps(out, protocol=5))
"""


def test_unpickled_in_another_process_evaluates_bit_for_bit():
    objects, params = {}, {}
    for name, obj in OBJECTS.items():
        if isinstance(obj, (sk.Curve, sk.BFunction)):
            a, b = obj.domain if isinstance(obj, sk.Curve) else (0.0, 1.0)
            objects[name], params[name] = obj, np.random.default_rng(5).uniform(a, b, 1000)
        elif isinstance(obj, sk.Surface):
            (a, b), (c, d) = obj.domain_u, obj.domain_v
            objects[name], params[name] = obj, (np.linspace(a, b, 40), np.linspace(c, d, 30))
    for path in EXAMPLES[:40]:
        obj = sk.load(path)
        if isinstance(obj, sk.Curve):
            objects[path.name], params[path.name] = obj, np.linspace(*obj.domain, 500)
    child = subprocess.run(
        [sys.executable, "-c", CHILD],
        input=pickle.dumps((objects, params), protocol=5),
        capture_output=True,
        check=True,
    )
    theirs = pickle.loads(child.stdout)
    assert sorted(theirs) == sorted(objects)
    for name, obj in objects.items():
        t = params[name]
        ours = [np.asarray(obj(t)), np.asarray(obj(t, 1))] if not isinstance(obj, sk.Surface) else [obj(*t)]
        assert bits(theirs[name]) == bits(ours), name
