"""B-functions, blending splines (frames, animation, local pieces) and meshes."""

import pathlib

import numpy as np
import pytest

import splinekit as sk

ROOT = pathlib.Path(__file__).resolve().parents[3]


def test_bfunctions():
    smooth = sk.bfunction("polynomial", smoothness=1)
    t = np.linspace(0, 1, 11)
    np.testing.assert_allclose(smooth(t), 3 * t**2 - 2 * t**3, atol=1e-15)
    np.testing.assert_allclose(smooth(t, 1), 6 * t - 6 * t**2, atol=1e-14)
    assert isinstance(smooth(0.5), float)
    erbs = sk.bfunction()
    assert erbs(0.0) == 0.0 and erbs(1.0) == 1.0 and abs(erbs(0.5) - 0.5) < 1e-15
    h = 1e-5
    assert abs(erbs(0.3, 1) - (erbs(0.3 + h) - erbs(0.3 - h)) / (2 * h)) < 1e-8
    skewed = sk.bfunction("erbs", **{"lambda": 0.3})
    assert skewed(0.3) < 0.5
    trig = sk.bfunction("trigonometric")
    np.testing.assert_allclose(trig(t), t - np.sin(2 * np.pi * t) / (2 * np.pi), atol=1e-15)
    with pytest.raises(ValueError, match=r"^bfunction"):
        sk.bfunction("erbs", alpha=-1)
    with pytest.raises(ValueError, match=r"^bfunction\.type: "):
        sk.bfunction("sigmoid")


def test_set_transform_moves_only_its_local_curve_in_place(heart):
    c = sk.load(heart)
    a, b = c.domain
    t = np.linspace(a, b, 400, endpoint=False)
    before = c(t)
    support = c.local_pieces()[2]["support"]
    centre = c.local_pieces()[2]["origin"]
    knot = (support[0] + support[1]) / 2  # uniform knots: the local's own knot is mid-support
    assert np.allclose(centre, c(knot), atol=1e-12)  # the curve passes through the local's origin there
    assert c.set_transform(2, translate=[0, 0, 1]) is None  # changes c itself, as list.sort does
    assert np.allclose(c(knot), np.asarray(centre) + [0, 0, 1], atol=1e-12)  # only local 2 counts at its knot
    assert c.to_dict()["transforms"] == {"2": {"translate": [0, 0, 1]}}
    dz = c(t)[:, 2] - before[:, 2]
    inside = (t > support[0]) & (t < support[1])
    assert np.all(dz[inside] > 0) and np.all(np.abs(dz[~inside]) < 1e-12)
    # A second call replaces the frame of that piece; other pieces keep theirs.
    c.set_transform(5, scale=0.5)
    c.set_transform(2, rotate={"axis": [0, 0, 1], "angle": 0.5}, scale=2.0)
    assert c.to_dict()["transforms"] == {"5": {"scale": 0.5}, "2": {"rotate": {"axis": [0, 0, 1], "angle": 0.5}, "scale": 2.0}}
    assert sk.load(c.to_json()).to_dict() == c.to_dict()
    # A refused frame leaves the curve as it was.
    kept = c.to_dict()
    with pytest.raises(ValueError, match=r"^transforms\[2\]\.translate: expected 3 coordinates, got 2$"):
        c.set_transform(2, translate=[0, 1])
    assert c.to_dict() == kept
    with pytest.raises(ValueError, match=r"^type: set_transform works on blending_spline curves, not heart$"):
        sk.load({"type": "heart"}).set_transform(0, scale=2.0)


def test_set_transform_is_seen_by_every_reference(heart):
    c = sk.load(heart)
    same = c
    c.set_transform(0, translate=[1, 0, 0])
    assert same.to_dict()["transforms"] == {"0": {"translate": [1, 0, 0]}}


def test_local_pieces_reproduce_the_spline_at_the_knots(heart):
    c = sk.load(heart)
    pieces = c.local_pieces(samples=9)
    assert len(pieces) == 8
    for p in pieces:
        assert p["points"].shape == (9, 3)
        lo, hi = p["support"]
        np.testing.assert_allclose(p["points"][4], c((lo + hi) / 2 % c.domain[1]), atol=1e-9)


def test_at_time_poses_the_animation():
    beating = sk.load(ROOT / "examples" / "shapes" / "beating_heart.json")
    rest = beating(np.pi)
    posed = beating.at_time(0.25)
    np.testing.assert_allclose(posed(np.pi), [0.0, -18.5, 0.0], atol=1e-9)
    assert not np.allclose(rest, posed(np.pi))


def test_surface_tessellation_and_saving(tmp_path):
    sphere = sk.load({"type": "sphere"})
    mesh = sphere.tessellate(density=16)
    assert mesh.vertices.shape[1] == 3 and mesh.faces.shape[1] == 3
    assert mesh.faces.dtype == np.int32 and mesh.faces.max() < len(mesh.vertices)
    np.testing.assert_allclose(np.linalg.norm(mesh.vertices, axis=1), 1.0, atol=1e-14)
    np.testing.assert_allclose(np.linalg.norm(mesh.normals, axis=1), 1.0, atol=1e-12)
    assert mesh.uv.shape == (len(mesh.vertices), 2) and mesh.uv.min() >= 0 and mesh.uv.max() <= 1
    a, b, c = (mesh.vertices[mesh.faces[:, k]] for k in range(3))
    volume = np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6
    assert abs(volume / (4 / 3 * np.pi) - 1) < 0.05  # 16 × 16 cells: 3.5 % short
    for ext in ("obj", "stl", "stla", "ply", "gltf", "glb"):
        path = tmp_path / f"sphere.{ext}"
        mesh.save(path)
        assert path.stat().st_size > 100
    assert (tmp_path / "sphere.obj").read_text().count("\nf ") == len(mesh.faces)
    with pytest.raises(ValueError, match=r"^path: meshes are written as .obj, .stl, .stla, .ply, .gltf or .glb, not"):
        mesh.save(tmp_path / "sphere.svg")
    fine = sphere.tessellate(tolerance=1e-3)
    assert len(fine.faces) > len(mesh.faces)
    with pytest.raises(ValueError, match=r"^density: between 1 and 2048 cells per direction, got 0$"):
        sphere.tessellate(density=0)


def test_curve_polylines():
    circle = sk.load({"type": "circle"})
    line = circle.tessellate(density=16)
    assert line.shape == (16, 3)
    np.testing.assert_allclose(np.linalg.norm(line, axis=1), 1.0, atol=1e-15)
    adaptive = circle.tessellate(tolerance=1e-4)
    angle = 2 * np.arccos(1 - 1e-4)
    assert len(adaptive) >= 2 * np.pi / angle
    c = sk.BSpline([0, 0, 1, 1], [[0, 0], [1, 1]], 1)
    assert c.tessellate(density=4).shape == (5, 2)


def test_blending_surface_pieces_and_frames():
    torus = sk.load(ROOT / "examples" / "shapes" / "animated_torus.json")
    pieces = torus.local_pieces(samples=3)
    assert pieces and pieces[0]["points"].shape == (3, 3, 3) and pieces[0]["index"] == (0, 0)
    u = np.linspace(*torus.domain_u, 7)
    v = np.linspace(*torus.domain_v, 5)
    before = torus(u, v)
    assert torus.set_transform((0, 0), translate=[0, 0, 0.5]) is None
    assert "0,0" in torus.to_dict()["transforms"]
    moved = torus(u, v)
    assert not np.allclose(moved, before)
    posed = torus.at_time(0.5)  # a new object; the original keeps its pose
    assert isinstance(posed, sk.Surface) and posed is not torus
    np.testing.assert_array_equal(torus(u, v), moved)


def test_render_writes_a_png_or_says_why_not(tmp_path):
    path = tmp_path / "torus.png"
    torus = sk.load({"type": "torus"})
    with pytest.raises(ValueError, match=r"^path: render writes .png files, not"):
        sk.render(torus, tmp_path / "torus.jpg")
    if not sk._splinekit.HAS_RENDER:
        with pytest.raises(RuntimeError, match=r"^render: this build of splinekit has no renderer"):
            sk.render(torus, path)
        return
    try:
        sk.render(torus, path, size=(64, 48))
    except RuntimeError as e:  # no graphics adapter on this machine: the message says so
        assert str(e).startswith("render: no graphics adapter found")
        return
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def _heart_formula(t):
    """The heart curve in closed form (docs/format.md), the truth for sub-curve locals."""
    return np.stack(
        [16 * np.sin(t) ** 3, 13 * np.cos(t) - 5 * np.cos(2 * t) - 2 * np.cos(3 * t) - np.cos(4 * t), 0 * t], axis=-1
    )


def test_insert_local_returns_a_new_curve_that_keeps_an_untransformed_sub_curve_spline():
    c = sk.load({"type": "blending_spline", "model": {"type": "heart"}, "local_curves": 8, "local": {"type": "sub_curve"}})
    t = np.linspace(0, 2 * np.pi, 401)
    np.testing.assert_allclose(c(t), _heart_formula(t), atol=1e-12)
    d, k = c.insert_local(1.0)
    assert k == 2 and len(d.local_pieces()) == 9 and len(c.local_pieces()) == 8  # a new object
    assert d.to_dict()["knots"][k] == 1.0
    np.testing.assert_allclose(d(t), _heart_formula(t), atol=1e-12)


def test_insert_local_on_bezier_locals_keeps_the_curve_outside_the_split_interval(heart):
    c = sk.load(heart)
    step = 2 * np.pi / 8
    d, k = c.insert_local(2.5 * step)
    assert k == 3
    t = np.linspace(0, 2 * np.pi, 801)
    outside = (t <= 2 * step) | (t >= 3 * step)
    np.testing.assert_allclose(d(t[outside]), c(t[outside]), atol=1e-12)
    np.testing.assert_allclose(d(2.5 * step), c(2.5 * step), atol=1e-12)  # and at the new knot


def test_split_knot_keeps_the_curve_and_a_turned_copy_makes_a_corner(heart):
    c = sk.load(heart)
    d = c.split_knot(3)
    knots = d.to_dict()["knots"]
    assert knots[3] == knots[4] and len(knots) == 10 and len(d.local_pieces()) == 9
    t = np.linspace(0, 2 * np.pi, 801)
    np.testing.assert_allclose(d(t), c(t), atol=1e-12)
    assert sk.load(d.to_json()) == d  # the document reads back as itself
    d.set_transform(4, rotate={"axis": [0, 0, 1], "angle": 0.5}, scale=1.3)
    joint, h = knots[3], 1e-7
    left, right = d(joint - h), d(joint + h)
    assert np.linalg.norm(left - right) < 1e-4, "continuous at the joint"
    np.testing.assert_allclose(d(joint), c(joint), atol=1e-12)
    tangents = d(np.array([joint - h, joint + h]), 1)
    cosine = tangents[0] @ tangents[1] / np.linalg.norm(tangents[0]) / np.linalg.norm(tangents[1])
    assert cosine < np.cos(0.3), "a corner"


def test_insert_local_and_split_knot_errors_name_the_field(heart):
    c = sk.load(heart)
    with pytest.raises(ValueError, match=r"^k: only interior knots 1\.\.=7 can be split, got 0$"):
        c.split_knot(0)
    with pytest.raises(ValueError, match=r"^k: knot 3 is already double$"):
        c.split_knot(3).split_knot(3)
    with pytest.raises(ValueError, match=r"^t: a new knot must lie strictly inside the domain"):
        c.insert_local(0.0)
    with pytest.raises(ValueError, match=r"^type: insert_local works on blending_spline curves, not heart$"):
        sk.load({"type": "heart"}).insert_local(1.0)
    with pytest.raises(ValueError, match=r"^type: split_knot works on blending_spline curves, not heart$"):
        sk.load({"type": "heart"}).split_knot(1)


def test_hermite_data_curve_reproduces_its_data_and_opens_and_closes():
    data = [[[0, 0], [1, 1], [0, -2]], [[1, 1], [1, 0], [0.5, 0]], [[2, 0.5], [0, -1], [1, 1]], [[3, 0], [1, 0.2], [0, 0]]]
    knots = [0, 1, 2.5, 3]
    c = sk.load({"type": "blending_spline", "knots": knots, "hermite": data})
    for k, t in enumerate(knots):
        for j in range(3):
            np.testing.assert_allclose(c(t, j), data[k][j], atol=1e-12)
    closed = c.set_closed(True)  # the ends differ: every datum kept, one bridging interval
    assert closed.to_dict()["knots"] == [0, 1, 2.5, 3, 3.5] and len(closed.local_pieces()) == 4
    t = np.linspace(0, 3, 301)
    np.testing.assert_allclose(closed(t), c(t), atol=1e-12)
    np.testing.assert_allclose(closed(3.5 - 1e-12), c(0.0), atol=1e-9)
    with pytest.raises(ValueError, match=r"^hermite\[1\]: expected 3 values"):
        sk.load({"type": "blending_spline", "knots": knots, "hermite": [data[0], data[1][:2], data[2], data[3]]})


def test_hermite_data_surface_and_knot_lines():
    two = lambda z: [[[0, 0, z], [0, 1, 0]], [[1, 0, 0], [0, 0, 0]]]  # noqa: E731
    s = sk.load({"type": "blending_spline_surface", "knots_u": [0, 1, 2], "knots_v": [0, 1],
                 "hermite": [[two(0), two(1)], [two(2), two(0)], [two(1), two(1)]]})
    np.testing.assert_allclose(s(1.0, 1.0, grid=False), [0, 0, 0], atol=1e-12)
    np.testing.assert_allclose(s(1.0, 0.0, grid=False), [0, 0, 2], atol=1e-12)
    split = s.split_knot_line("u", 1)
    assert len(split.to_dict()["hermite"]) == 4
    u, v = np.linspace(0, 2, 21), np.linspace(0, 1, 11)
    np.testing.assert_allclose(split(u, v), s(u, v), atol=1e-12)
    inserted, k = s.insert_knot_line("v", 0.5)
    assert k == 1 and len(inserted.to_dict()["hermite"][0]) == 3
    with pytest.raises(ValueError, match=r'^direction: must be "u" or "v", got "w"$'):
        s.split_knot_line("w", 1)
