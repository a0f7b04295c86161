"""SubdivisionSurface: closed forms of the Catmull–Clark cube, agreement with
``splinekit subdivide-surface`` (``--at`` JSON and ``--limit`` OBJ, bit for bit), pickling
and the command line's error messages."""

import copy
import json
import math
import os
import pathlib
import pickle
import subprocess

import numpy as np
import pytest

import splinekit as sk

ROOT = pathlib.Path(__file__).resolve().parents[3]
CLI = pathlib.Path(os.environ.get("SPLINEKIT_CLI", ROOT / "target" / "debug" / "splinekit"))
MESHES = ROOT / "examples" / "meshes"
needs_cli = pytest.mark.skipif(not CLI.exists(), reason="the splinekit binary is not built (cargo build -p splinekit-cli)")


def read_obj(path):
    """Vertices, faces (0-based) and `t crease 2/1 A B S` creases of an OBJ cage."""
    vertices, faces, creases = [], [], []
    for line in pathlib.Path(path).read_text().splitlines():
        w = line.split()
        if not w:
            continue
        if w[0] == "v":
            vertices.append([float(x) for x in w[1:4]])
        elif w[0] == "f":
            faces.append([int(x.split("/")[0]) - 1 for x in w[1:]])
        elif w[0] == "t" and w[1] == "crease":
            creases.append((int(w[3]), int(w[4]), float(w[5])))
    return vertices, faces, creases


def surface(name, **kw):
    v, f, c = read_obj(MESHES / name)
    return sk.SubdivisionSurface(v, f, creases=c, **kw)


def cli(*args):
    r = subprocess.run([str(CLI), "subdivide-surface", *map(str, args)], capture_output=True, text=True)
    return r


def test_cube_limit_in_closed_form():
    # The cube [-1, 1]³: the corner's limit is (½, ½, ½) with normal (1, 1, 1)/√3, the
    # face centre's (0, 0, 68/81) (the kernel tests derive both).
    s = surface("cube.obj")
    p = s.limit_points()
    n = s.limit_normals()
    assert p.shape == (8, 3) and n.shape == (8, 3) and p.dtype == np.float64
    v = np.asarray(s.vertices)
    np.testing.assert_allclose(p, v / 2, atol=1e-15)
    np.testing.assert_allclose(n, v / math.sqrt(3), atol=1e-15)
    top = s.evaluate(1, 0.5, 0.5)
    np.testing.assert_allclose(top["position"], [0, 0, 68 / 81], atol=1e-15)
    np.testing.assert_allclose(top["normal"], [0, 0, 1], atol=1e-15)
    assert set(top["partials"]) == {"du", "dv", "duu", "duv", "dvv"}
    corner = s.evaluate(1, 0.0, 0.0)
    np.testing.assert_allclose(corner["position"], [-0.5, -0.5, 0.5], atol=1e-15)
    assert corner["partials"] is None


def test_partials_match_finite_differences():
    s = surface("creased_cube.obj")
    u, v, h = 0.3, 0.6, 1e-5
    e = s.evaluate(2, u, v)
    pos = lambda a, b: s.evaluate(2, a, b)["position"]  # noqa: E731
    np.testing.assert_allclose(e["partials"]["du"], (pos(u + h, v) - pos(u - h, v)) / (2 * h), atol=1e-8)
    np.testing.assert_allclose(e["partials"]["dv"], (pos(u, v + h) - pos(u, v - h)) / (2 * h), atol=1e-8)
    cross = np.cross(e["partials"]["du"], e["partials"]["dv"])
    np.testing.assert_allclose(e["normal"], cross / np.linalg.norm(cross), atol=1e-14)


def test_subdivide_keeps_vertex_order_and_converges():
    s = surface("cube.obj")
    one = s.subdivide(1)
    assert isinstance(one, sk.SubdivisionSurface)
    assert one.vertices.shape == (26, 3) and len(one.faces) == 24 and one.scheme == "catmull-clark"
    # Vertex i stays vertex i; its limit does not move under refinement.
    np.testing.assert_allclose(one.limit_points()[:8], s.limit_points(), atol=1e-14)
    deep = s.subdivide(6).vertices[7]
    assert 0 < np.linalg.norm(deep - [0.5, 0.5, 0.5]) < 1e-3
    # Semi-sharp creases decay by one a step.
    c = surface("creased_cube.obj")
    assert (0, 1, 2.5) in c.creases
    assert any(k[2] == 1.5 for k in c.subdivide(1).creases)


def test_bilinear_is_the_bilinear_patch():
    s = surface("cube.obj", scheme="bilinear")
    np.testing.assert_array_equal(s.limit_points(), s.vertices)
    f = s.faces[1]
    c = s.vertices[f]
    u, v = 0.25, 0.75
    want = (1 - u) * (1 - v) * c[0] + u * (1 - v) * c[1] + u * v * c[2] + (1 - u) * v * c[3]
    np.testing.assert_allclose(s.evaluate(1, u, v)["position"], want, atol=1e-15)


def test_loop_triangulates_on_request():
    with pytest.raises(ValueError, match=r"^faces\[0\]: Loop subdivision takes triangles"):
        surface("cube.obj", scheme="loop")
    s = surface("cube.obj", scheme="loop", triangulate=True)
    assert len(s.faces) == 12 and all(len(f) == 3 for f in s.faces)
    e = s.evaluate(0, 1 / 3, 1 / 3)
    assert np.all(np.isfinite(e["position"])) and abs(np.linalg.norm(e["normal"]) - 1) < 1e-14


@needs_cli
@pytest.mark.parametrize("name,scheme", [("cube.obj", "catmull-clark"), ("creased_cube.obj", "catmull-clark"),
                                         ("creased_cube.obj", "bilinear")])
def test_evaluate_is_the_cli_at_json(name, scheme):
    s = surface(name, scheme=scheme)
    at = [(0, 0.0, 0.0), (1, 0.5, 0.25), (2, 0.3, 0.6), (4, 1.0, 1.0), (5, 0.125, 0.875)]
    r = cli(MESHES / name, "--scheme", scheme, *[a for f, u, v in at for a in ("--at", f"{f},{u!r},{v!r}")])
    assert r.returncode == 0, r.stderr
    for (f, u, v), want in zip(at, json.loads(r.stdout)):
        got = s.evaluate(f, u, v)
        assert got["position"].tolist() == want["position"]
        assert got["normal"].tolist() == want["normal"]
        if want["partials"] is None:
            assert got["partials"] is None
        else:
            assert {k: a.tolist() for k, a in got["partials"].items()} == want["partials"]


def read_limit_obj(text):
    v = [[float(x) for x in line.split()[1:]] for line in text.splitlines() if line.startswith("v ")]
    n = [[float(x) for x in line.split()[1:]] for line in text.splitlines() if line.startswith("vn ")]
    return np.array(v), np.array(n)


@needs_cli
@pytest.mark.parametrize("name", ["cube.obj", "creased_cube.obj"])
@pytest.mark.parametrize("steps", [0, 2])
def test_limit_is_the_cli_limit_obj(name, steps, tmp_path):
    out = tmp_path / "limit.obj"
    r = cli(MESHES / name, "--scheme", "catmull-clark", "--steps", steps, "--limit", "-o", out)
    assert r.returncode == 0, r.stderr
    pos, normals = read_limit_obj(out.read_text())
    s = surface(name).subdivide(steps)
    np.testing.assert_array_equal(s.limit_points(), pos)
    np.testing.assert_array_equal(s.limit_normals(), normals[: len(pos)])
    mesh = surface(name).to_mesh(steps)
    assert isinstance(mesh, sk.Mesh)
    np.testing.assert_array_equal(mesh.vertices[: len(pos)], pos)
    np.testing.assert_array_equal(mesh.normals[: len(pos)], normals[: len(pos)])
    # Extra vertices are limit points repeated for the far side of a sharp crease.
    extra = mesh.vertices[len(pos):]
    assert all(any((p == q).all() for q in pos) for p in extra)
    assert len(mesh.faces) == 2 * len(s.faces)
    assert mesh.faces.max() < len(mesh.vertices)


def test_to_mesh_without_limit_is_the_refined_cage():
    s = surface("cube.obj")
    m = s.to_mesh(2, limit=False)
    np.testing.assert_array_equal(m.vertices, s.subdivide(2).vertices)
    assert len(m.faces) == 2 * 96


def test_pickle_copy_and_equality_are_exact():
    s = surface("creased_cube.obj", boundary="edge-and-corner").subdivide(1)
    for proto in range(2, pickle.HIGHEST_PROTOCOL + 1):
        t = pickle.loads(pickle.dumps(s, protocol=proto))
        assert t == s
        assert t.vertices.tobytes() == s.vertices.tobytes()
        assert t.faces == s.faces and t.creases == s.creases and t.boundary == "edge-and-corner"
        assert t.limit_points().tobytes() == s.limit_points().tobytes()
        for k in ("position", "normal"):
            assert t.evaluate(3, 0.3, 0.7)[k].tobytes() == s.evaluate(3, 0.3, 0.7)[k].tobytes()
    assert copy.copy(s) == s and copy.deepcopy(s) == s
    assert s != surface("creased_cube.obj").subdivide(1)
    assert s != surface("creased_cube.obj", boundary="edge-and-corner", scheme="bilinear").subdivide(1)
    # Loop cages travel as their triangles.
    loop = surface("cube.obj", scheme="loop", triangulate=True)
    assert pickle.loads(pickle.dumps(loop)) == loop


@needs_cli
def test_errors_are_the_cli_messages(tmp_path):
    v, f, _ = read_obj(MESHES / "cube.obj")
    bad = tmp_path / "bad.obj"
    bad.write_text((MESHES / "cube.obj").read_text() + "t crease 2/1 0 7 1\n")
    r = cli(bad, "--scheme", "catmull-clark", "-o", tmp_path / "out.obj")
    assert r.returncode == 2
    with pytest.raises(ValueError) as e:
        sk.SubdivisionSurface(v, f, creases=[(0, 7, 1.0)])
    assert r.stderr.strip() == f"error: mesh: {e.value}"
    assert "creases[0]" in str(e.value)
    s = sk.SubdivisionSurface(v, f)
    for at, args in [("9,0.5,0.5", (9, 0.5, 0.5)), ("0,1.5,0.5", (0, 1.5, 0.5))]:
        r = cli(MESHES / "cube.obj", "--scheme", "catmull-clark", "--at", at)
        with pytest.raises(ValueError) as e:
            s.evaluate(*args)
        assert r.stderr.strip() == f"error: --at[0]: {e.value}"


def test_bad_arguments_name_the_field():
    v, f, _ = read_obj(MESHES / "cube.obj")
    with pytest.raises(ValueError, match=r'^scheme: expected "catmull-clark", "loop" or "bilinear", got "doo-sabin"$'):
        sk.SubdivisionSurface(v, f, scheme="doo-sabin")
    with pytest.raises(ValueError, match=r'^boundary: expected "edge-only" or "edge-and-corner", got "none"$'):
        sk.SubdivisionSurface(v, f, boundary="none")
    with pytest.raises(ValueError, match=r"^faces\[2\]: a vertex index must be ≥ 0 and below 2³², got -1$"):
        sk.SubdivisionSurface(v, [f[0], f[1], [-1, 1, 2]])
    with pytest.raises(ValueError, match=r"^faces\[0\]: vertex 8 does not exist \(there are 8\)$"):
        sk.SubdivisionSurface(v, [[0, 1, 8]])
    with pytest.raises(ValueError, match=r"^vertices: expected 3 coordinates per vertex, got 2$"):
        sk.SubdivisionSurface([[0, 0], [1, 0], [0, 1]], [[0, 1, 2]])
    with pytest.raises(ValueError, match=r"^vertices\[1\]: coordinates must be finite$"):
        sk.SubdivisionSurface([[0, 0, 0], [np.nan, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    with pytest.raises(ValueError, match=r"^steps: "):
        sk.SubdivisionSurface(v, f).subdivide(12)


def test_the_shape_document_is_the_exact_limit(tmp_path):
    """``load`` of a ``subdivision_surface`` document (the cage from an OBJ file beside it,
    creases from its tags): chart c + u, v is face c at (u, v), bit for bit the kernel's
    evaluation; ``tessellate`` puts the cage's vertices at their limit points first."""
    (tmp_path / "cage.obj").write_text((MESHES / "creased_cube.obj").read_text())
    (tmp_path / "doc.json").write_text(json.dumps({"type": "subdivision_surface", "obj": "cage.obj"}))
    doc = sk.load(tmp_path / "doc.json")
    s = surface("creased_cube.obj")
    for face, u, w in [(0, 0.5, 0.5), (3, 0.25, 0.75), (5, 0.875, 0.125)]:
        got = np.asarray(doc(face + u, w, grid=False)).reshape(-1)
        np.testing.assert_array_equal(got, np.asarray(s.evaluate(face, u, w)["position"]))
    mesh = doc.tessellate(tolerance=1e-2)
    limit = np.asarray(s.limit_points())
    np.testing.assert_allclose(mesh.vertices[: len(limit)], limit, rtol=0, atol=1e-14)
    # The same document inline, and round trips through its dict.
    inline = sk.load(doc.to_dict())
    assert inline.to_dict() == doc.to_dict() and "obj" not in doc.to_dict()
    with pytest.raises(ValueError, match=r"^obj: cannot read the cage file"):
        sk.load({"type": "subdivision_surface", "obj": str(tmp_path / "missing.obj")})
    with pytest.raises(ValueError, match=r"^faces\[0\]: vertex 7 does not exist"):
        sk.load({"type": "subdivision_surface", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "faces": [[0, 1, 7]]})
