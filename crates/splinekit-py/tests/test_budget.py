"""The command line's resource budget in Python: calls whose allocations grow with their
arguments are estimated first and refused with the command line's line, naming the
argument, the estimate and the limit (SPLINEKIT_MAX_MEMORY / SPLINEKIT_MAX_WORK)."""

import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import splinekit as sk

ROOT = pathlib.Path(__file__).resolve().parents[3]
CLI = pathlib.Path(os.environ.get("SPLINEKIT_CLI", ROOT / "target" / "debug" / "splinekit"))

LIMIT = r"more than the limit of 1\.0 MB \(raise it with --max-memory or SPLINEKIT_MAX_MEMORY\)$"


def test_a_dense_mesh_is_refused_before_it_is_built(monkeypatch):
    sphere = sk.load({"type": "sphere"})
    monkeypatch.setenv("SPLINEKIT_MAX_MEMORY", "1M")
    with pytest.raises(ValueError, match=r"^density: a mesh of 2048×2048 cells would need about 1\.2 GB of memory, " + LIMIT):
        sphere.tessellate(density=2048)
    with pytest.raises(ValueError, match=r"^density: a mesh of 64×64 cells would need about"):
        sphere.tessellate()  # the default density counts too
    assert len(sphere.tessellate(density=8).faces) > 0
    monkeypatch.delenv("SPLINEKIT_MAX_MEMORY")
    assert len(sphere.tessellate(density=64).faces) > 0


def test_a_long_polyline_is_refused(monkeypatch):
    circle = sk.load({"type": "circle"})
    monkeypatch.setenv("SPLINEKIT_MAX_WORK", "1e5")
    msg = r"a polyline of up to 1000001 points would need about .* operations, more than the limit of 1\.0e5 "
    with pytest.raises(ValueError, match=r"^density: " + msg):
        circle.tessellate(density=10**6)
    with pytest.raises(ValueError, match=r"^tolerance: " + msg):
        circle.tessellate(tolerance=1e-9)
    assert circle.tessellate(density=100).shape == (100, 3)


@pytest.mark.skipif(not CLI.exists(), reason="the splinekit binary is not built (cargo build -p splinekit-cli)")
@pytest.mark.parametrize("density", [2048, 700])
def test_mesh_refusals_are_the_cli_lines(density, monkeypatch, tmp_path):
    doc = {"type": "sphere"}
    path = tmp_path / "sphere.json"
    path.write_text(json.dumps(doc))
    r = subprocess.run(
        [str(CLI), "--max-memory", "1M", "tessellate", str(path), "--density", str(density), "-o", str(tmp_path / "s.obj")],
        capture_output=True,
        text=True,
    )
    assert r.returncode == 2, r.stderr
    monkeypatch.setenv("SPLINEKIT_MAX_MEMORY", "1M")
    with pytest.raises(ValueError) as e:
        sk.load(doc).tessellate(density=density)
    assert "--" + str(e.value) == r.stderr.strip()[len("error: "):]


def test_adaptive_meshes_get_the_budget_as_a_cell_limit(monkeypatch):
    sphere = sk.load({"type": "sphere"})
    assert len(sphere.tessellate(tolerance=1e-4).faces) > 0
    monkeypatch.setenv("SPLINEKIT_MAX_WORK", "5e6")
    with pytest.raises(ValueError, match=r"^tolerance: 0\.0001 needs about .* cells \(.*\), more than the budget of \d+ cells of this mesh$"):
        sphere.tessellate(tolerance=1e-4)
    assert len(sphere.tessellate(tolerance=0.3).faces) > 0


def test_surface_grids_and_partials_are_budgeted(monkeypatch):
    s = sk.BezierSurface(np.random.default_rng(0).normal(size=(4, 4, 3)))
    u = np.linspace(0, 1, 1000)
    monkeypatch.setenv("SPLINEKIT_MAX_MEMORY", "1M")
    grid = r"^grid: a grid of 1000×1000 points with partials up to order {} \(.* operations each, driven by control_points\) would need about {} of memory, " + LIMIT
    with pytest.raises(ValueError, match=grid.format(0, r"24\.0 MB")):
        s(u, u)
    with pytest.raises(ValueError, match=grid.format(1, r"48\.0 MB")):
        s.normals(u, u)
    with pytest.raises(ValueError, match=r"^u: 1000 points with partials up to order 16 .* of memory, " + LIMIT):
        s.partials(u, u, order=16, grid=False)
    assert s(u[:100], u[:100]).shape == (100, 100, 3)  # 240 kB
    assert s(u, u, grid=False).shape == (1000, 3)  # paired arrays are the caller's


def test_local_pieces_are_budgeted(monkeypatch):
    torus = sk.load(ROOT / "examples" / "shapes" / "animated_torus.json")
    monkeypatch.setenv("SPLINEKIT_MAX_MEMORY", "1M")
    with pytest.raises(ValueError, match=r"^samples: \d+ local pieces of 100000000 points would need about .* of memory, " + LIMIT):
        torus.local_pieces(samples=10_000)
    assert torus.local_pieces(samples=3)


def test_a_malformed_limit_is_named(monkeypatch):
    monkeypatch.setenv("SPLINEKIT_MAX_MEMORY", "lots")
    with pytest.raises(ValueError, match=r"^SPLINEKIT_MAX_MEMORY: expected bytes like 4G, 512M or 2e9, got 'lots'$"):
        sk.load({"type": "sphere"}).tessellate(density=4)


def test_curve_points_and_derivatives_are_budgeted(monkeypatch):
    c = sk.BSpline([0, 0, 0, 0, 1, 1, 1, 1], np.eye(4, 3), 3)
    t = np.linspace(0, 1, 100_000)
    monkeypatch.setenv("SPLINEKIT_MAX_MEMORY", "1M")
    with pytest.raises(ValueError, match=r"^order: 100000 parameters with derivatives up to order 64 would need about 156\.0 MB of memory, " + LIMIT):
        c.derivatives(t, 64)
    with pytest.raises(ValueError, match=r"^nu: 100000 parameters with derivatives up to order 2 would need about 2\.4 MB of memory, " + LIMIT):
        c(t, nu=2)
    with pytest.raises(ValueError, match=r"^t: 100000 parameters with derivatives up to order 0 would need about 2\.4 MB"):
        c(t)
    assert c.derivatives(t[:1000], 2).shape == (1000, 3, 3)
    monkeypatch.delenv("SPLINEKIT_MAX_MEMORY")
    monkeypatch.setenv("SPLINEKIT_MAX_WORK", "1e6")
    with pytest.raises(ValueError, match=r"^order: 100000 parameters with derivatives up to order 64 would need about .* operations, more than the limit of 1\.0e6 "):
        c.derivatives(t, 64)


def test_a_fit_is_budgeted_before_it_solves(monkeypatch):
    x = np.linspace(0, 1, 20_000)
    points = np.column_stack([x, np.sin(6 * x)])
    monkeypatch.setenv("SPLINEKIT_MAX_WORK", "1e5")
    with pytest.raises(ValueError, match=r"^points: a degree-3 fit of 20000 points with 50 control points would need about .* operations, more than the limit of 1\.0e5 "):
        sk.fit(points, 3, 50)
    with pytest.raises(ValueError, match=r"^n_control_points: 30000 control points need at least 30000 data points, got 20000$"):
        sk.fit(points, 3, 30_000)  # the fit's own check comes first: nothing is allocated
    assert sk.fit(points[:500], 3, 50).fit_report.max_error < 1e-3


def test_a_render_is_budgeted_before_any_adapter_is_asked(monkeypatch, tmp_path):
    if not sk._splinekit.HAS_RENDER:
        pytest.skip("built without the render feature")
    dense = {"type": "scene", "objects": [{"shape": {"type": "sphere"}, "density": 2048}]}
    monkeypatch.setenv("SPLINEKIT_MAX_MEMORY", "100M")
    with pytest.raises(ValueError, match=r"^objects: drawing 1 objects would need about 1\.2 GB of memory, more than the limit of 104\.9 MB"):
        sk.render(dense, tmp_path / "dense.png")
    with pytest.raises(ValueError, match=r"^size: rendering 4000x3000 would need about 528\.0 MB of memory, more than the limit of 104\.9 MB"):
        sk.render({"type": "circle"}, tmp_path / "c.png", size=(4000, 3000))
