"""Every error path raises a ``splinekit.SplinekitError`` with the command line's one-line
message, of the class of its kind, each still the built-in class raised before (a
``ValueError``, ``OSError`` or ``RuntimeError``)."""

import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import splinekit as sk

ROOT = pathlib.Path(__file__).resolve().parents[3]
CLI = pathlib.Path(os.environ.get("SPLINEKIT_CLI", ROOT / "target" / "debug" / "splinekit"))

QUAD = dict(knots=[0, 0, 0, 1, 2, 2, 2], control_points=[[0, 0], [1, 2], [3, 2], [4, 0]], degree=2)

BAD_DOCUMENTS = [
    {"type": "bspline", "degree": 3, "knots": [0] * 4 + [1] * 7, "control_points": [[0, 0]] * 8},
    {"type": "bspline", "degree": 2, "knots": [0, 0, 0, 2, 1, 1, 1], "control_points": [[0, 0]] * 4},
    {"type": "nurbs", "degree": 1, "knots": [0, 0, 1, 1], "control_points": [[0, 0], [1, 1]], "weights": [1, -1]},
    {"type": "bezier", "control_points": [[0, 0], [1, 2, 3]]},
    {"type": "bezier", "control_points": []},
    {"type": "bezier", "control_points": [[0, 0]], "colour": "red"},
    {"type": "spline"},
    {"type": "circle", "radius": -1},
    {"type": "bspline_surface", "degree_u": 1, "degree_v": 1, "knots_u": [0, 0, 1, 1], "knots_v": [0, 1, 1], "control_points": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]},
    {"type": "blend", "first": {"type": "line", "from": [0, 0, 0], "to": [1, 0, 0]}, "second": {"type": "bezier", "control_points": [[0, 0], [1, 1, 1]]}, "overlap": 0.5, "bfunction": {"type": "erbs"}},
]


def cli_message(doc, tmp_path):
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(doc))
    at = "0:0" if doc["type"].endswith("surface") else "0"
    r = subprocess.run([str(CLI), "eval", str(path), "--at", at], capture_output=True, text=True)
    assert r.returncode == 2, r.stderr
    line = r.stderr.strip()
    assert line.startswith("error: ") and "\n" not in line
    return line[len("error: "):]


@pytest.mark.skipif(not CLI.exists(), reason="the splinekit binary is not built (cargo build -p splinekit-cli)")
@pytest.mark.parametrize("doc", BAD_DOCUMENTS, ids=lambda d: d["type"])
def test_load_raises_the_cli_message(doc, tmp_path):
    with pytest.raises(ValueError) as e:
        sk.load(doc)
    assert str(e.value) == cli_message(doc, tmp_path)


def test_constructor_messages_name_the_field_and_numbers():
    with pytest.raises(ValueError, match=r"^knots: expected 7 values for 4 control points of degree 2, got 6$"):
        sk.BSpline([0, 0, 1, 2, 2, 2], QUAD["control_points"], 2)
    with pytest.raises(ValueError, match=r"^weights: weight 1 is -1, but weights must be > 0$"):
        sk.NURBS([0, 0, 1, 1], [[0, 0], [1, 1]], [1, -1], 1)
    with pytest.raises(ValueError, match=r"^control_points\[1\]\[0\]: value is not finite \(NaN\)$"):
        sk.Bezier([[0, 0], [np.nan, 1]])
    with pytest.raises(ValueError, match=r"^degree: "):
        sk.BSpline(QUAD["knots"], QUAD["control_points"], -1)
    with pytest.raises(ValueError, match=r"^control_points\[1\]: expected 2 coordinates like the first point, got 3$"):
        sk.Bezier([[0, 0], [1, 2, 3]])
    with pytest.raises(ValueError, match=r"points of dimension 5 are not supported"):
        sk.Bezier(np.zeros((3, 5)))
    with pytest.raises(ValueError, match=r"^knots_v: "):
        sk.BSplineSurface([0, 0, 1, 1], [0, 1, 1], np.zeros((2, 2, 3)), 1, 1)


def test_evaluation_errors():
    c = sk.BSpline(**QUAD)
    with pytest.raises(ValueError, match=r"^t: parameter 2.5 is outside the domain \[0, 2\] of this open curve$"):
        c([0.5, 2.5])
    with pytest.raises(ValueError, match=r"^t\[1\]: value is not finite \(NaN\)$"):
        c([0.5, np.nan])
    with pytest.raises(ValueError, match=r"^t: expected a number or a 1-D array, got an array of shape \[2, 2\]$"):
        c(np.zeros((2, 2)))
    # Long batches are checked chunk by chunk as they are evaluated; the message is still
    # that of a check of all the parameters first: the first non-finite value wherever it
    # is, else the first parameter outside the domain, in any chunk.
    t = np.linspace(0.0, 2.0, 20_000)
    t[100], t[15_000] = 2.5, np.inf
    for nu in (0, 1):
        with pytest.raises(ValueError, match=r"^t\[15000\]: value is not finite \(inf\)$"):
            c(t, nu)
    t[15_000] = 1.0
    with pytest.raises(ValueError, match=r"^t: parameter 2.5 is outside the domain \[0, 2\] of this open curve$"):
        c(t)
    t[100], t[19_999] = 1.0, -0.75
    with pytest.raises(ValueError, match=r"^t: parameter -0.75 is outside the domain \[0, 2\] of this open curve$"):
        c(t)
    with pytest.raises(ValueError, match=r"^t: parameter -0.75 is outside the domain \[0, 2\] of this open curve$"):
        c.derivatives(t, 2)
    t[19_999] = 2.0
    np.testing.assert_array_equal(c(t), np.array([c(x) for x in t]))
    # The vectorised check sees a bad value in every lane, in the remainder after its
    # blocks of eight, and in the second chunk of a batch.
    for n in (1, 7, 8, 9, 17, 4100):
        for i in sorted({0, n // 2, n - 1, min(n - 1, 8), min(n - 1, 2048)}):
            for bad, message in ((np.nan, rf"^t\[{i}\]: value is not finite \(NaN\)$"),
                                 (np.inf, rf"^t\[{i}\]: value is not finite \(inf\)$"),
                                 (-np.inf, rf"^t\[{i}\]: value is not finite \(-inf\)$"),
                                 (2.5, r"^t: parameter 2.5 is outside the domain \[0, 2\] of this open curve$"),
                                 (-0.5, r"^t: parameter -0.5 is outside the domain \[0, 2\] of this open curve$")):
                t = np.full(n, 1.0)
                t[i] = bad
                with pytest.raises(ValueError, match=message):
                    c(t)
    with pytest.raises(ValueError, match=r"^order: 65 is more than the limit of 64$"):
        c.derivatives(0.5, 65)
    with pytest.raises(ValueError, match=r"^p: expected 2 coordinates like the curve's points, got 3$"):
        c.closest_point([1, 2, 3])
    with pytest.raises(ValueError, match=r"^tolerance: must be finite and > 0, got 0$"):
        c.length(0.0)
    with pytest.raises(ValueError, match=r"^t: parameter 3 is outside"):
        c.split(3.0)
    with pytest.raises(ValueError, match=r"^tolerance: must be finite and ≥ 0, got -1$"):
        c.remove_knot(1.0, -1.0)
    with pytest.raises(ValueError, match=r"^type: refine works on bezier, rational_bezier, bspline and nurbs documents, not heart$"):
        sk.load({"type": "heart"}).insert_knot(0.5)
    with pytest.raises(ValueError, match=r"^type: this works on bezier, rational_bezier, bspline and nurbs curves, not circle$"):
        sk.load({"type": "circle"}).to_bezier()


def test_surface_errors():
    s = sk.BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    with pytest.raises(ValueError, match=r"^v: parameter 2 is outside the domain \[0, 1\] of this open direction$"):
        s([0.5], [2.0])
    with pytest.raises(ValueError, match=r"^v: with grid=False u and v are paired and need the same length, got 2 and 3$"):
        s([0, 1], [0, 0.5, 1], grid=False)
    with pytest.raises(ValueError, match=r"^order: 17 is more than the limit of 16 for surfaces$"):
        s.partials(0.5, 0.5, order=17)
    with pytest.raises(ValueError, match=r"^p: expected 3 coordinates"):
        s.closest_point([0, 0])


def test_fit_errors():
    pts = np.random.default_rng(0).normal(size=(50, 2))
    with pytest.raises(ValueError, match=r"^degree: must be between 1 and 64, got 0$"):
        sk.fit(pts, 0, 10)
    with pytest.raises(ValueError, match=r"^n_control_points: degree 3 needs at least 4 control points, got 2$"):
        sk.fit(pts, 3, 2)
    with pytest.raises(ValueError, match=r"^n_control_points: 60 control points need at least 60 data points, got 50$"):
        sk.fit(pts, 3, 60)
    with pytest.raises(ValueError, match=r'^params: expected "uniform", "chord", "centripetal" or an array of parameters, got "arc"$'):
        sk.fit(pts, 3, 10, params="arc")
    with pytest.raises(ValueError, match=r'^knots: expected "uniform", "averaged" or an array of knots, got "even"$'):
        sk.fit(pts, 3, 10, knots="even")
    with pytest.raises(ValueError, match=r"^n_control_points: give a number of control points or an array of knots$"):
        sk.fit(pts, 3)
    with pytest.raises(ValueError, match=r"^params: expected 50 values, one per point, got 3$"):
        sk.fit(pts, 3, params=[0, 0.5, 1], knots=[0, 0, 0, 0, 1, 1, 1, 1])
    # Parameters given as numbers: counted before knots are averaged from them (a single
    # number once reached the knot placement and panicked).
    with pytest.raises(ValueError, match=r"^params: expected 50 values, one per point, got 1$"):
        sk.fit(pts, 2, 4, params=3)
    for closed in (False, True):
        with pytest.raises(ValueError, match=r"^n_control_points: degree 3 needs at least 4 control points, got 2$"):
            sk.fit(pts, 3, 2, params=np.linspace(0, 0.98, 50), closed=closed)
    with pytest.raises(ValueError, match=r"^n_control_points: 5 does not match the 8 knots of degree 3, which give 4 control points$"):
        sk.fit(pts, 3, 5, params=np.linspace(0, 1, 50), knots=[0, 0, 0, 0, 1, 1, 1, 1])
    with pytest.raises(ValueError, match=r"^points: expected an array of points of shape \(n, d\), got shape \[50\]$"):
        sk.fit(pts[:, 0], 3, 10)
    with pytest.raises(ValueError, match=r"^weights\[0\]: value is not finite \(inf\)$"):
        sk.fit(pts, 3, 10, weights=np.full(50, np.inf))
    with pytest.raises(ValueError, match=r"^end_derivatives: expected 2 coordinates like the points, got 3 and 2$"):
        sk.interpolate(pts, 3, end_derivatives=([1, 0, 0], [1, 0]))


def test_load_errors():
    with pytest.raises(ValueError, match=r"^document: cannot read 'no/such/file.json': "):
        sk.load("no/such/file.json")
    with pytest.raises(ValueError, match=r"^document: invalid JSON: "):
        sk.load("{not json")
    with pytest.raises(ValueError, match=r'^type: missing \(every shape document needs a "type"\)$'):
        sk.load({})
    with pytest.raises(ValueError, match=r"^control_points\[0\]\[1\]: value is not finite \(inf\)$"):
        sk.load({"type": "bezier", "control_points": [[0, float("inf")]]})
    with pytest.raises(ValueError, match=r"^objects: a scene needs at least one object$"):
        sk.load({"type": "scene", "objects": []})
    with pytest.raises(ValueError, match=r"cannot be written as JSON"):
        sk.load({"type": "bezier", "control_points": object()})


# The command line's flag for each argument of fit() / interpolate() its messages name.
FIT_FLAGS = {"n_control_points": "--control-points", "degree": "--degree"}


@pytest.mark.skipif(not CLI.exists(), reason="the splinekit binary is not built (cargo build -p splinekit-cli)")
@pytest.mark.parametrize(
    "degree, n, closed",
    [(0, 10, False), (65, 10, False), (3, 2, False), (3, 60, False), (3, 3, True), (2, 51, True)],
)
def test_fit_errors_are_the_cli_lines_with_the_argument_named(degree, n, closed, tmp_path):
    pts = np.random.default_rng(0).normal(size=(50, 2))
    path = tmp_path / "points.csv"
    np.savetxt(path, pts, delimiter=",", fmt="%.17g")
    args = [str(CLI), "fit", str(path), "--degree", str(degree), "--control-points", str(n)] + (["--closed"] if closed else [])
    r = subprocess.run(args, capture_output=True, text=True)
    assert r.returncode == 2 and r.stderr.startswith("error: "), r.stderr
    flag, cli_rest = r.stderr.strip()[len("error: "):].split(": ", 1)
    with pytest.raises(ValueError) as e:
        sk.fit(pts, degree, n, closed=closed)
    field, rest = str(e.value).split(": ", 1)
    assert "\n" not in str(e.value)
    assert FIT_FLAGS[field] == flag and rest == cli_rest


def test_the_exception_classes_form_one_hierarchy():
    for cls in (sk.DocumentError, sk.NumericalError, sk.BudgetError, sk.FileError, sk.RenderError):
        assert issubclass(cls, sk.SplinekitError) and cls.__module__ == "splinekit"
    for cls in (sk.DocumentError, sk.NumericalError, sk.BudgetError, sk.FileError):
        assert issubclass(cls, ValueError), cls
    assert issubclass(sk.FileError, OSError) and issubclass(sk.RenderError, RuntimeError)
    assert not issubclass(sk.DocumentError, sk.NumericalError) and not issubclass(sk.BudgetError, sk.DocumentError)
    import pickle

    e = pickle.loads(pickle.dumps(sk.FileError("path: cannot write 'x'")))
    assert type(e) is sk.FileError and str(e) == "path: cannot write 'x'"


def raised(f):
    with pytest.raises(sk.SplinekitError) as e:
        f()
    return e.value


def test_bad_documents_and_arguments_are_document_errors(tmp_path):
    for doc in BAD_DOCUMENTS:
        e = raised(lambda: sk.load(doc))
        assert type(e) is sk.DocumentError and isinstance(e, ValueError), doc
    assert type(raised(lambda: sk.BSpline(**{**QUAD, "degree": 0}))) is sk.DocumentError
    circle = sk.load({"type": "circle"})
    assert type(raised(lambda: circle.tessellate(density=0))) is sk.DocumentError
    assert type(raised(lambda: sk.intersect(circle, circle, tolerance=0))) is sk.DocumentError
    assert type(raised(lambda: sk.save(circle, tmp_path / "c.stl"))) is sk.DocumentError
    assert type(raised(lambda: sk.fit_many([[[0, 0], [1, 1]]], 3, 8))) is sk.DocumentError
    assert type(raised(lambda: sk.set_display(embed_three="never"))) is sk.DocumentError
    (tmp_path / "bad.step").write_text("ISO-10303-21;\nnot step at all\n")
    assert type(raised(lambda: sk.read_step(tmp_path / "bad.step"))) is sk.DocumentError


def test_numerical_failures_are_numerical_errors():
    points = [[0, 0], [1, 1], [2, 0], [3, 3]]
    e = raised(lambda: sk.fit(points, 3, 4, params=[0, 0, 0, 0], knots="uniform"))
    assert type(e) is sk.NumericalError and isinstance(e, ValueError)
    assert str(e).startswith("fit: control point 1 of 4 is not determined by the data")
    # In a batch the class stays, the message gets the index.
    e = raised(lambda: sk.fit_many([points, points], 3, 4, params=[0, 0, 0, 0], knots="uniform"))
    assert type(e) is sk.NumericalError and str(e).startswith("point_sets[0]: fit: control point 1")


def test_requests_over_the_budget_are_budget_errors(monkeypatch):
    monkeypatch.setenv("SPLINEKIT_MAX_MEMORY", "10M")
    torus = sk.load({"type": "torus"})
    e = raised(lambda: torus.tessellate(density=2048))
    assert type(e) is sk.BudgetError and isinstance(e, ValueError)
    assert str(e).startswith("density: a mesh of 2048×2048 cells would need about 1.2 GB of memory")
    assert type(raised(lambda: sk.load({"type": "sphere"}).offset(0.3))) is sk.BudgetError


def test_files_that_cannot_be_read_or_written_are_file_errors(tmp_path):
    missing = tmp_path / "missing" / "x"
    for f in (
        lambda: sk.load(tmp_path / "missing.json"),
        lambda: sk.load({"type": "torus"}).save(f"{missing}.stl"),
        lambda: sk.save(sk.Scene([sk.load({"type": "torus"})]), f"{missing}.obj"),
        lambda: sk.read_step(tmp_path / "missing.step"),
    ):
        e = raised(f)
        assert type(e) is sk.FileError and isinstance(e, OSError) and isinstance(e, ValueError), e
    assert str(raised(lambda: sk.load(tmp_path / "missing.json"))).startswith("document: cannot read '")
