"""Every command of the command line has its Python counterpart, and each new function
answers as its command does: the same numbers as the command's JSON on the examples
(the CLI binary run beside), the same messages, and the right answers by independent
checks (both shapes evaluated at the returned parameters, arc length against scipy's
quad of |c'|, offsets against circles)."""

import json
import os
import pathlib
import re
import subprocess
import sys

import numpy as np
import pytest

import splinekit as sk

ROOT = pathlib.Path(__file__).resolve().parents[3]
CLI = pathlib.Path(os.environ.get("SPLINEKIT_CLI", ROOT / "target" / "debug" / "splinekit"))
needs_cli = pytest.mark.skipif(not CLI.exists(), reason="the splinekit binary is not built (cargo build -p splinekit-cli)")
needs_render = pytest.mark.skipif(not sk._splinekit.HAS_RENDER, reason="built without the render feature")

# Each command of `splinekit --help` and the Python names that do what it does (resolved
# against the package by the test), or why it has none.
PYTHON = {
    "eval": ["Curve.__call__", "Curve.derivatives", "Curve.arc_length_params", "Curve.at_time", "Surface.__call__", "Surface.partials"],
    "fit": ["fit"],
    "interpolate": ["interpolate"],
    "intersect": ["intersect", "Curve.intersect", "Surface.intersect"],
    "offset": ["offset", "Curve.offset", "Surface.offset"],
    "project": ["project", "Curve.project", "Surface.project"],
    "section": ["section", "Surface.section"],
    "refine": ["Curve.insert_knot", "Curve.elevate_degree", "Curve.remove_knot"],
    "subdivide": ["subdivide"],
    "subdivide-surface": ["SubdivisionSurface", "SubdivisionSurface.subdivide", "SubdivisionSurface.evaluate"],
    "tessellate": ["save", "Curve.save", "Surface.save", "Scene.save", "Curve.tessellate", "Surface.tessellate"],
    "render": ["render"],
    "animate": ["animate"],
    "convert": ["read_step", "write_step"],
    "measure": ["measure"],
}
CLI_ONLY = {
    "view": "an interactive window of its own (winit and egui); in a notebook every object is its own "
    "interactive view (_repr_mimebundle_, splinekit.show)",
    "gallery": "writes the project's showcase website, a fixed set of figures, not an operation on the user's shapes",
    "help": "clap's help",
}


def cli(*args, check=True):
    r = subprocess.run([str(CLI), *map(str, args)], capture_output=True, text=True)
    if check:
        assert r.returncode == 0, r.stderr
    return r


def cli_json(*args):
    return json.loads(cli(*args).stdout)


def cli_error(*args):
    r = cli(*args, check=False)
    assert r.returncode == 2, r.stderr
    line = r.stderr.strip()
    assert line.startswith("error: ") and "\n" not in line, line
    return line[len("error: "):]


def as_python_message(message):
    """The command's message as Python says it: flags named as the arguments, the
    shapes `A`/`B` as `a`/`b`."""
    message = re.sub(r"--([a-z]+)", r"\1", message)
    return re.sub(r"\b([AB])( is |: )", lambda m: m.group(1).lower() + m.group(2), message)


def write(tmp_path, name, doc):
    path = tmp_path / name
    path.write_text(json.dumps(doc.to_dict() if hasattr(doc, "to_dict") else doc))
    return path


def resolve(name):
    obj = sk
    for part in name.split("."):
        obj = getattr(obj, part)
    return obj


@needs_cli
def test_every_command_has_a_python_counterpart():
    text = cli("--help").stdout
    commands = re.findall(r"^  ([a-z][a-z-]*)\s", text.split("Commands:")[1].split("Options:")[0], re.M)
    assert len(commands) >= 16, text
    missing = [c for c in commands if c not in PYTHON and c not in CLI_ONLY]
    assert not missing, f"commands without a Python counterpart: {missing}"
    stale = [c for c in PYTHON if c not in commands]
    assert not stale, f"the table names commands the CLI no longer has: {stale}"
    for command, names in PYTHON.items():
        for name in names:
            assert callable(resolve(name)), (command, name)


def test_the_table_names_only_what_the_package_has():
    for names in PYTHON.values():
        for name in names:
            resolve(name)


# --- intersections -------------------------------------------------------------------

CIRCLE = {"type": "circle", "radius": 2}
LINE = {"type": "line", "from": [-3, 1, 0], "to": [3, 1, 0]}
TANGENT_LINE = {"type": "line", "from": [-3, 2, 0], "to": [3, 2, 0]}
LOOP = {"type": "bezier", "control_points": [[0, 0], [3, 3], [-1, 3], [2, 0]]}
SPHERE = {"type": "sphere", "radius": 1.5}
CROSSING_PLANE = {"type": "plane", "origin": [-3, -3, 0.5], "u_axis": [6, 0, 0], "v_axis": [0, 6, 0]}
AXIS_LINE = {"type": "line", "from": [0.2, 0.1, -3], "to": [0.2, 0.1, 3]}


def same_points(py, cli_points):
    assert len(py) == len(cli_points)
    for p, q in zip(py, cli_points):
        assert p["kind"] == q["kind"]
        np.testing.assert_array_equal(p["params"], q["params"])
        np.testing.assert_array_equal(p["point"], q["point"])


@needs_cli
@pytest.mark.parametrize(
    "a, b",
    [(CIRCLE, LINE), (CIRCLE, TANGENT_LINE), (LOOP, None), (CIRCLE, CIRCLE), (AXIS_LINE, SPHERE), (SPHERE, AXIS_LINE)],
    ids=["crossing", "tangent", "self", "overlap", "curve-surface", "surface-curve"],
)
def test_intersect_agrees_with_the_command(a, b, tmp_path):
    args = [write(tmp_path, "a.json", a)] + ([write(tmp_path, "b.json", b)] if b else [])
    expected = cli_json("intersect", *args)
    got = sk.intersect(sk.load(a), None if b is None else sk.load(b))
    same_points(got["points"], expected["points"])
    assert [(o["params_a"], o["params_b"]) for o in got["overlaps"]] == [
        (tuple(o["params_a"]), tuple(o["params_b"])) for o in expected["overlaps"]
    ]
    # Independent truth: both shapes at the returned parameters are the point.
    ca = sk.load(a)
    for p in got["points"]:
        if b is None:
            np.testing.assert_allclose(ca(p["params"][0]), ca(p["params"][1]), atol=1e-9)
        elif isinstance(ca, sk.Curve) and isinstance(sk.load(b), sk.Curve):
            np.testing.assert_allclose(ca(p["params"][0]), sk.load(b)(p["params"][1]), atol=1e-7)
        else:
            c, s = (ca, sk.load(b)) if isinstance(ca, sk.Curve) else (sk.load(b), ca)
            t, u, v = p["params"]
            np.testing.assert_allclose(c(t), s(u, v, grid=False)[0] if np.ndim(u) else s([u], [v], grid=False)[0], atol=1e-9)
            np.testing.assert_allclose(c(t), p["point"], atol=1e-12)


def test_intersection_kinds():
    c, line, touch = sk.load(CIRCLE), sk.load(LINE), sk.load(TANGENT_LINE)
    assert [p["kind"] for p in sk.intersect(c, line)["points"]] == ["crossing", "crossing"]
    assert [p["kind"] for p in c.intersect(touch)["points"]] == ["tangent"]
    overlap = sk.intersect(c, c)
    assert overlap["points"] == [] and len(overlap["overlaps"]) == 1
    assert [p["kind"] for p in sk.load(LOOP).intersect()["points"]] == ["crossing"]


@needs_cli
def test_surface_surface_intersection_agrees_and_lies_on_both(tmp_path):
    expected = cli_json("intersect", write(tmp_path, "a.json", SPHERE), write(tmp_path, "b.json", CROSSING_PLANE))
    sphere, plane = sk.load(SPHERE), sk.load(CROSSING_PLANE)
    got = sphere.intersect(plane)
    assert got["points"] == [] and len(got["curves"]) == len(expected["curves"]) == 1
    branch, cli_branch = got["curves"][0], expected["curves"][0]
    np.testing.assert_array_equal(branch["points"], cli_branch["points"])
    np.testing.assert_array_equal(branch["params_a"], cli_branch["params_a"])
    assert branch["closed"] is True and branch["tangent"] is False and branch["early_stop"] is None
    assert branch["bspline"] == sk.load(cli_branch["bspline"])
    # On the sphere (radius 1.5) and the plane z = 0.5, and on each surface at its (u, v).
    pts = branch["points"]
    np.testing.assert_allclose(np.linalg.norm(pts, axis=1), 1.5, atol=1e-8)
    np.testing.assert_allclose(pts[:, 2], 0.5, atol=1e-8)
    uv = branch["params_a"]
    np.testing.assert_allclose(sphere(uv[:, 0], uv[:, 1], grid=False), pts, atol=1e-8)
    uv = branch["params_b"]
    np.testing.assert_allclose(plane(uv[:, 0], uv[:, 1], grid=False), pts, atol=1e-8)
    assert branch["fit_error"] <= 1e-4


@needs_cli
def test_section_agrees_with_the_command(tmp_path):
    torus = {"type": "torus"}
    expected = cli_json("section", write(tmp_path, "t.json", torus), "--plane", "0,0,0/0,0,1", "--levels", "3")
    got = sk.section(sk.load(torus), [0, 0, 0], [0, 0, 1], levels=3)
    assert len(got) == len(expected["sections"]) == 3
    for g, e in zip(got, expected["sections"]):
        np.testing.assert_array_equal(g["origin"], e["origin"])
        assert len(g["curves"]) == len(e["curves"])
        for c, d in zip(g["curves"], e["curves"]):
            np.testing.assert_array_equal(c["points"], d["points"])
            np.testing.assert_array_equal(c["params"], d["params"])
            np.testing.assert_allclose(c["points"][:, 2], g["origin"][2], atol=1e-8)


@needs_cli
def test_errors_are_the_commands_messages(tmp_path):
    a, b = write(tmp_path, "a.json", CIRCLE), write(tmp_path, "b.json", {"type": "bezier", "control_points": [[0, 0], [1, 1]]})
    for args, call in [
        (["intersect", a, b, "--tolerance", "0"], lambda: sk.intersect(sk.load(CIRCLE), sk.load(LOOP), tolerance=0.0)),
        (["intersect", a, b], lambda: sk.intersect(sk.load(CIRCLE), sk.load({"type": "bezier", "control_points": [[0, 0], [1, 1]]}))),
        (["intersect", write(tmp_path, "s.json", SPHERE)], lambda: sk.intersect(sk.load(SPHERE))),
        (["section", write(tmp_path, "t.json", {"type": "torus"}), "--plane", "0,0,0/0,0,1", "--levels", "0"],
         lambda: sk.section(sk.load({"type": "torus"}), [0, 0, 0], [0, 0, 1], levels=0)),
    ]:
        with pytest.raises(ValueError) as e:
            call()
        assert str(e.value) == as_python_message(cli_error(*args))


# --- projection -------------------------------------------------------------------------


@needs_cli
@pytest.mark.parametrize("doc", [{"type": "trefoil"}, {"type": "torus"}], ids=["curve", "surface"])
def test_project_many_points_agrees_with_the_command(doc, tmp_path):
    rng = np.random.default_rng(1)
    points = rng.uniform(-4, 4, size=(25, 3))
    (tmp_path / "p.json").write_text(json.dumps(points.tolist()))
    expected = cli_json("project", write(tmp_path, "s.json", doc), "--points", tmp_path / "p.json")["projections"]
    shape = sk.load(doc)
    params, near, dist = shape.project(points)
    for i, e in enumerate(expected):
        n = e["nearest"]
        if "t" in n:
            assert params[i] == n["t"]
        else:
            assert tuple(params[i]) == (n["u"], n["v"])
        np.testing.assert_array_equal(near[i], n["point"])
        assert dist[i] == n["distance"]
    # Independent: no sample of the shape is nearer than the answer.
    if isinstance(shape, sk.Curve):
        samples = shape(np.linspace(*shape.domain, 4001))
        np.testing.assert_allclose(shape(params), near, atol=1e-12)
    else:
        samples = shape(np.linspace(*shape.domain_u, 201), np.linspace(*shape.domain_v, 201)).reshape(-1, 3)
    nearest_sample = np.min(np.linalg.norm(samples[None, :, :] - points[:, None, :], axis=2), axis=1)
    assert np.all(dist <= nearest_sample + 1e-12)
    np.testing.assert_allclose(np.linalg.norm(near - points, axis=1), dist, rtol=1e-12)


@needs_cli
def test_project_all_minima_agrees_with_the_command(tmp_path):
    doc = {"type": "circle", "radius": 2}
    expected = cli_json("project", write(tmp_path, "c.json", doc), "--point", "3,0.5,0", "--all")["minima"]
    got = sk.project(sk.load(doc), [3, 0.5, 0], all=True)
    assert [m["t"] for m in got] == [m["t"] for m in expected]
    t, p, d = sk.project(sk.load(doc), [3, 0.5, 0])
    assert isinstance(t, float) and p.shape == (3,) and d == pytest.approx(np.hypot(3, 0.5) - 2)


# --- offsets ----------------------------------------------------------------------------


@needs_cli
def test_curve_offset_agrees_with_the_command_and_is_the_bigger_circle(tmp_path):
    doc = {"type": "circle", "radius": 2}
    expected = cli_json("offset", write(tmp_path, "c.json", doc), "--distance", "0.5")
    pieces, report = sk.offset(sk.load(doc), 0.5, report=True)
    assert len(pieces) == 1 and pieces[0] == sk.load(expected)
    assert report.startswith("offset: 1 piece, max error")
    p = pieces[0](np.linspace(*pieces[0].domain, 500))
    np.testing.assert_allclose(np.linalg.norm(p[:, :2], axis=1), 2.5, atol=1e-6)


@needs_cli
def test_surface_offset_agrees_with_the_command(tmp_path):
    doc = {"type": "sphere", "radius": 1}
    expected = cli_json("offset", write(tmp_path, "s.json", doc), "--distance", "0.25", "--tolerance", "1e-4")
    got = sk.load(doc).offset(0.25, tolerance=1e-4)
    assert got == sk.load(expected)
    m = got.tessellate(density=16).vertices
    np.testing.assert_allclose(np.linalg.norm(m, axis=1), 1.25, atol=1e-4)


# --- arc length -------------------------------------------------------------------------


@needs_cli
def test_arc_length_params_are_those_of_eval_arc_length(tmp_path):
    doc = {"type": "heart"}
    expected = cli_json("eval", write(tmp_path, "h.json", doc), "--samples", "17", "--arc-length")["params"]
    np.testing.assert_array_equal(sk.load(doc).arc_length_params(17), expected)


def test_arc_length_and_its_inverse_against_scipy():
    from scipy.integrate import quad

    c = sk.BSpline([0, 0, 0, 0, 1, 2, 2, 2, 2], [[0, 0], [1, 2], [2, -1], [3, 3], [4, 0]], 3)
    speed = lambda t: float(np.linalg.norm(c(t, 1)))  # noqa: E731
    for t in (0.3, 1.0, 1.7, 2.0):
        exact = sum(quad(speed, a, b, epsabs=1e-13)[0] for a, b in [(0, min(t, 1.0)), (1.0, max(t, 1.0))])
        assert c.length_at(t) == pytest.approx(exact, abs=1e-9)
    lengths = c.length_at(np.array([0.3, 1.0, 1.7]))
    np.testing.assert_allclose(c.param_at_length(lengths), [0.3, 1.0, 1.7], atol=1e-9)
    assert c.length_at(2.0) == pytest.approx(c.length())
    even = c.arc_length_params(9)
    steps = np.diff(c.length_at(even))
    np.testing.assert_allclose(steps, c.length() / 8, rtol=1e-9)


# --- STEP, files, subdivision -------------------------------------------------------------


def without_timestamp(text):
    return re.sub(r"FILE_NAME\([^;]*;", "FILE_NAME(…);", text)


@needs_cli
def test_write_step_is_what_convert_writes(tmp_path):
    doc = {"type": "torus", "major_radius": 3, "minor_radius": 1}
    src = write(tmp_path, "torus.json", doc)
    cli("convert", src, "-o", tmp_path / "cli.step")
    report = sk.write_step(sk.load(doc), tmp_path / "torus.step")
    assert without_timestamp((tmp_path / "torus.step").read_text()) == without_timestamp((tmp_path / "cli.step").read_text())
    assert report[0]["form"] == "exact"


@needs_cli
def test_read_step_returns_the_objects_convert_reads(tmp_path):
    scene = sk.Scene([sk.load({"type": "torus"}), sk.load({"type": "circle", "radius": 2})])
    sk.write_step(scene, tmp_path / "two.step")
    expected = cli_json("convert", tmp_path / "two.step", "-o", "-")
    shapes = sk.read_step(tmp_path / "two.step")
    assert [s.to_dict() for s in shapes] == [o["shape"] for o in expected["objects"]]
    assert isinstance(shapes[0], sk.Surface) and isinstance(shapes[1], sk.Curve)
    # The torus read back is the torus: (ρ − 3)² + z² = 1, ρ the distance from the axis.
    torus = shapes[0]
    p = torus(np.linspace(*torus.domain_u, 7), np.linspace(*torus.domain_v, 5)).reshape(-1, 3)
    np.testing.assert_allclose((np.hypot(p[:, 0], p[:, 1]) - 3) ** 2 + p[:, 2] ** 2, 1, atol=1e-9)
    named = sk.read_step(tmp_path / "two.step", names=True)
    assert all(isinstance(n, str) for n, _ in named)
    with pytest.raises(ValueError, match="^path: "):
        sk.read_step(tmp_path / "missing.step")


@needs_cli
def test_read_step_scene_places_an_assemblys_parts_as_convert_does():
    # SolidWorks 2015's box: ten uses of six parts, each placed; the repeats are instances.
    part = ROOT / "tests" / "step" / "real" / "sw2015_box_sides_assembly_inch.stp"
    expected = cli_json("convert", part, "-o", "-")
    scene = sk.read_step(part, scene=True)
    assert isinstance(scene, sk.Scene)
    assert scene.to_dict() == expected
    objects = expected["objects"]
    assert len(objects) == 10 and sum("instance_of" in o for o in objects) == 4
    assert all("placement" in o and o["name"] for o in objects)


@needs_cli
@pytest.mark.parametrize("doc, ext", [({"type": "heart"}, "svg"), ({"type": "heart"}, "obj"), ({"type": "torus"}, "stl"), ({"type": "torus"}, "ply")])
def test_save_writes_what_tessellate_writes(doc, ext, tmp_path):
    cli("tessellate", write(tmp_path, "s.json", doc), "-o", tmp_path / f"cli.{ext}", "--density", "24")
    # The file name is the object's name in OBJ and PLY: the same stem gives the same bytes.
    (tmp_path / "py").mkdir()
    sk.save(sk.load(doc), tmp_path / "py" / f"cli.{ext}", density=24)
    assert (tmp_path / "py" / f"cli.{ext}").read_bytes() == (tmp_path / f"cli.{ext}").read_bytes()


@needs_cli
@pytest.mark.parametrize("ext", ["glb", "gltf", "obj", "stl", "stla", "ply"])
def test_scene_save_is_what_tessellate_writes(ext, tmp_path):
    path = ROOT / "examples" / "scenes" / "torus_animated.json"
    cli("tessellate", path, "-o", tmp_path / f"cli.{ext}")
    (tmp_path / "py").mkdir()
    sk.load(path).save(tmp_path / "py" / f"cli.{ext}")
    assert (tmp_path / "py" / f"cli.{ext}").read_bytes() == (tmp_path / f"cli.{ext}").read_bytes()


@needs_cli
def test_scene_save_refuses_what_tessellate_refuses(tmp_path):
    path = ROOT / "examples" / "scenes" / "torus_animated.json"
    with pytest.raises(sk.DocumentError) as e:
        sk.load(path).save(tmp_path / "scene.svg")
    assert str(e.value) == "path: " + cli_error("tessellate", path, "-o", tmp_path / "scene.svg").split(": ", 1)[1]
    # STL has no curves: the error names the object.
    hearts = ROOT / "examples" / "scenes" / "heart_transformed.json"
    with pytest.raises(sk.DocumentError) as e:
        sk.save(sk.load(hearts), tmp_path / "hearts.stl")
    assert str(e.value) == cli_error("tessellate", hearts, "-o", tmp_path / "hearts.stl")
    assert str(e.value).startswith("objects[0]: a curve (heart)")


@needs_cli
@pytest.mark.parametrize("scheme, extra", [("chaikin", []), ("lane_riesenfeld", ["--degree", "4"]), ("four_point", ["--closed"])])
def test_subdivide_agrees_with_the_command(scheme, extra, tmp_path):
    pts = [[0, 0], [1, 2], [3, 2.5], [4, 0], [2, -1]]
    (tmp_path / "p.json").write_text(json.dumps(pts))
    expected = cli_json("subdivide", tmp_path / "p.json", "--scheme", scheme, "--steps", "3", *extra)
    kwargs = {"degree": 4} if "--degree" in extra else {}
    got = sk.subdivide(pts, scheme, 3, closed="--closed" in extra, **kwargs)
    np.testing.assert_array_equal(got, expected)


# --- blending splines -------------------------------------------------------------------


def test_blending_splines_from_a_model_and_from_locals():
    heart = sk.load({"type": "heart"})
    b = sk.blending_spline(heart, 8, degree=3, bfunction=sk.bfunction("erbs"))
    assert b == sk.load({"type": "blending_spline", "model": {"type": "heart"}, "local_curves": 8,
                         "local": {"type": "bezier", "degree": 3}, "bfunction": {"type": "erbs"}})
    # ERBS with Bézier locals of degree 3 reproduces the model at the knots.
    knots = np.linspace(*heart.domain, 9)
    np.testing.assert_allclose(b(knots), heart(knots), atol=1e-9)
    for kind in ("polynomial", "trigonometric", "linear"):
        assert sk.blending_spline(heart, 6, local="sub_curve", bfunction=kind).closed
    locals_ = [sk.load({"type": "line", "from": [-1, 0], "to": [1, 0]}),
               sk.Bezier([[0, 0], [1, 2], [2, 0]]),
               sk.load({"type": "line", "from": [1, 0], "to": [3, 0]})]
    c = sk.blending_spline(local_curves=locals_, knots=[0, 1, 2])
    assert c.domain == (0.0, 2.0)
    np.testing.assert_allclose(c(1.0), [1, 1], atol=1e-12)  # local 1's point at its middle
    s = sk.blending_spline_surface({"type": "torus"}, (6, 4), degree=(2, 2))
    assert s.kind == "blending_spline_surface" and s.closed_u and s.closed_v
    x = sk.blend(sk.load({"type": "line", "from": [0, 0], "to": [1, 0]}), sk.load({"type": "line", "from": [0.5, 0], "to": [1.5, 1]}), 0.5, "trigonometric")
    assert x.domain == (0.0, 1.5)
    with pytest.raises(ValueError, match="^local_curves: "):
        sk.blending_spline(local_curves=3)


# --- scenes -------------------------------------------------------------------------------


def test_scenes_are_built_styled_animated_and_saved(tmp_path):
    heart = sk.load(ROOT / "examples" / "shapes" / "beating_heart.json")
    scene = sk.Scene([(heart, {"color": [0.8, 0.1, 0.2], "line_width": 3})], animation={"duration": 1, "fps": 10})
    scene = scene.add(sk.load({"type": "torus"}), wireframe=True, color=[0.3, 0.5, 0.9]).replace(size=[320, 240])
    assert len(scene) == 2 and scene.animated and scene.clock == (1.0, 10.0) and scene.size == (320, 240)
    doc = scene.to_dict()
    assert doc["objects"][1]["wireframe"] is True and doc["objects"][0]["shape"]["type"] == "blending_spline"
    scene.save(tmp_path / "s.json")
    assert sk.load(tmp_path / "s.json") == scene
    scene.save(tmp_path / "s.glb")
    data = (tmp_path / "s.glb").read_bytes()
    assert data[:4] == b"glTF"
    header = json.loads(data[20 : 20 + int.from_bytes(data[12:16], "little")])
    assert header.get("animations"), "the animated scene carries its frames"
    with pytest.raises(ValueError, match="^objects\\[0\\]"):
        sk.Scene([{"shape": {"type": "nope"}}])
    with pytest.raises(ValueError, match="^colour: not a scene field"):
        scene.replace(colour=1)


# --- rendering ------------------------------------------------------------------------------


@needs_render
def test_render_into_an_array_and_a_file(tmp_path):
    shape = sk.load({"type": "torus"})
    image = sk.render(shape, size=(96, 64))
    assert image.shape == (64, 96, 4) and image.dtype == np.uint8
    assert (image[..., :3] < 200).any(), "something is drawn on the white background"
    assert sk.render(shape, tmp_path / "t.png", size=(96, 64)) is None
    assert (tmp_path / "t.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    frames = sk.animate(ROOT / "examples" / "scenes" / "torus_animated.json", frames=3, size=(48, 32))
    assert frames.shape == (3, 32, 48, 4)
    sk.animate(ROOT / "examples" / "scenes" / "torus_animated.json", tmp_path / "a.gif", frames=2, size=(48, 32))
    assert (tmp_path / "a.gif").read_bytes()[:3] == b"GIF"
    with pytest.raises(ValueError, match="^path: render writes .png files"):
        sk.render(shape, tmp_path / "t.jpg")


@needs_render
@needs_cli
def test_render_array_is_the_commands_picture(tmp_path):
    doc = {"type": "sphere", "radius": 2}
    cli("render", write(tmp_path, "s.json", doc), "-o", tmp_path / "cli.png", "--size", "80x60")
    sk.render(sk.load(doc), tmp_path / "py.png", size=(80, 60))
    assert (tmp_path / "py.png").read_bytes() == (tmp_path / "cli.png").read_bytes()


@needs_render
def test_a_render_without_xdg_runtime_dir_prints_nothing(tmp_path):
    env = {k: v for k, v in os.environ.items() if k not in ("XDG_RUNTIME_DIR", "NODEVICE_SELECT", "WAYLAND_DISPLAY")}
    code = "import splinekit as sk; sk.render({'type': 'sphere', 'radius': 2}, %r, size=(64, 48))" % str(tmp_path / "q.png")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert r.returncode == 0, r.stderr
    assert r.stderr == "", r.stderr
    assert (tmp_path / "q.png").stat().st_size > 0


@needs_cli
def test_measure_agrees_with_the_command_on_a_real_part_and_a_surface(tmp_path):
    part = ROOT / "tests" / "step" / "real" / "fusion360_passive_horn_ap242.stp"
    expected = cli_json("measure", part)
    got = sk.measure(part)
    assert got == expected
    # The same solid through read_step, and OpenCASCADE's area (occ_reference.json).
    (solid,) = sk.read_step(part)
    assert sk.measure(solid) == expected
    occ = json.loads((part.parent / "occ_reference.json").read_text())[part.name]
    assert abs(got["area"] - occ["area"]) <= 1e-12 * occ["area"]
    assert got["mesh"]["open_edges"] == 0
    sphere = {"type": "sphere", "radius": 2}
    expected = cli_json("measure", write(tmp_path, "s.json", sphere), "--tolerance", "0.01")
    got = sk.measure(sk.load(sphere), tolerance=0.01)
    assert got == expected
    assert abs(got["mesh"]["area"] - 16 * np.pi) < 0.05 * 16 * np.pi
    with pytest.raises(ValueError, match="^shape: a heart is a curve"):
        sk.measure(sk.load({"type": "heart"}))
    with pytest.raises(ValueError, match="tolerance"):
        sk.measure(sk.load(sphere), tolerance=-1.0)
