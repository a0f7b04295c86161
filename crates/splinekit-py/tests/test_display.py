"""Notebook display (``_repr_mimebundle_``, ``show``, ``set_display``) and ``plot``."""

import base64
import json
import re
import sys

import numpy as np
import pytest

import splinekit as sk
from splinekit import _display


@pytest.fixture(autouse=True)
def fresh_session(monkeypatch):
    """Each test starts as a new session: the three.js bundle not sent yet."""
    monkeypatch.setattr(_display, "_three_sent", False)
    monkeypatch.setitem(_display._options, "png", False)


def glb_of(html):
    encoded = re.search(r'splinekitNotebook\.show\("[^"]+", "([A-Za-z0-9+/=]*)"', html).group(1)
    return base64.b64decode(encoded)


def gltf_json(glb):
    assert glb[:4] == b"glTF"
    return json.loads(glb[20 : 20 + int.from_bytes(glb[12:16], "little")])


SHAPES = [
    ("curve", lambda: sk.load({"type": "trefoil"})),
    ("plane curve", lambda: sk.Bezier([[0, 0], [1, 2], [2, 0]])),
    ("surface", lambda: sk.load({"type": "torus"})),
    ("blending spline", lambda: sk.blending_spline({"type": "heart"}, 8)),
    ("mesh", lambda: sk.load({"type": "sphere"}).tessellate(density=8)),
    ("subdivision surface", lambda: sk.SubdivisionSurface(
        [[x, y, z] for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)],
        [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]])),
    ("scene", lambda: sk.Scene([sk.load({"type": "torus"}), sk.load({"type": "trefoil"})])),
]


@pytest.mark.parametrize("name, make", SHAPES, ids=[s[0] for s in SHAPES])
def test_every_kind_of_object_shows_its_gltf(name, make):
    obj = make()
    bundle = obj._repr_mimebundle_()
    assert bundle["text/plain"] == repr(obj)
    html = bundle["text/html"]
    gltf = gltf_json(glb_of(html))
    assert gltf["meshes"], name
    assert "window.splinekitNotebook" in html and "var SplinekitThree=" in html
    assert ("image/svg+xml" in bundle) == (name == "plane curve")


def test_the_three_bundle_goes_once_a_session_and_has_no_closing_tag():
    bundle, licence = sk._splinekit._three_bundle()
    assert "</script" not in bundle.lower() and "MIT License" in licence
    first = sk.load({"type": "heart"})._repr_mimebundle_()["text/html"]
    second = sk.load({"type": "heart"})._repr_mimebundle_()["text/html"]
    assert "var SplinekitThree=" in first and "var SplinekitThree=" not in second
    assert len(second) < 100_000 < len(first)
    sk.set_display(embed_three="always")
    try:
        assert "var SplinekitThree=" in sk.load({"type": "heart"})._repr_mimebundle_()["text/html"]
    finally:
        sk.set_display(embed_three="once")


def test_animated_scenes_carry_their_animation_and_a_time_bar():
    heart = sk.load({"type": "blending_spline", "model": {"type": "heart"}, "local_curves": 10, "local": {"type": "sub_curve"},
                     "animation": [{"local": 1, "motions": [{"oscillate": {"direction": [1, 0, 0], "amplitude": 1.5}}]}]})
    scene = sk.Scene([heart], animation={"duration": 1, "fps": 8})
    html = scene._repr_mimebundle_()["text/html"]
    assert gltf_json(glb_of(html))["animations"]
    assert '"duration": 1.0' in html and "splinekit-timebar" in html and ">pause</button>" in html


def test_show_draws_several_objects_in_one_view_and_sizes():
    view = sk.show(sk.load({"type": "torus"}), sk.load({"type": "trefoil"}), sk.load({"type": "sphere"}).tessellate(density=6), width=300, height=200)
    html = view._repr_mimebundle_()["text/html"]
    gltf = gltf_json(glb_of(html))
    assert len(gltf["nodes"]) >= 3
    assert "width:300px;height:200px" in html
    page = view.html()
    assert page.startswith("<!DOCTYPE html>") and "var SplinekitThree=" in page
    with pytest.raises(ValueError):
        sk.show()
    with pytest.raises(TypeError):
        sk.show(42)
    with pytest.raises(ValueError, match="^width: "):
        sk.set_display(width=3)
    sk.set_display(width=640)


def test_include_and_exclude():
    c = sk.Bezier([[0, 0], [1, 1]])
    assert set(c._repr_mimebundle_(include={"text/plain", "image/svg+xml"})) == {"text/plain", "image/svg+xml"}
    assert "text/html" not in c._repr_mimebundle_(exclude={"text/html"})


@pytest.mark.skipif(not sk._splinekit.HAS_RENDER, reason="built without the render feature")
def test_png_fallback(monkeypatch):
    monkeypatch.setitem(_display._options, "png", True)
    png = sk.load({"type": "torus"})._repr_mimebundle_()["image/png"]
    assert png[:8] == b"\x89PNG\r\n\x1a\n"


def test_png_encoder_round_trips():
    image = np.zeros((3, 2, 4), dtype=np.uint8)
    image[1, 1] = [10, 20, 30, 255]
    png = _display._png_bytes(image)
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    pytest.importorskip("matplotlib")
    import io

    import matplotlib.image

    back = matplotlib.image.imread(io.BytesIO(png), format="png")
    np.testing.assert_allclose(back * 255, image, atol=0.5)


def test_plot_draws_curves_polygons_combs_and_bfunctions():
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    c = sk.BSpline([0, 0, 0, 0, 1, 2, 2, 2, 2], [[0, 0], [1, 2], [2, -1], [3, 3], [4, 0]], 3)
    ax = sk.plot(c, comb=True, samples=50)
    labels = [line.get_label() for line in ax.get_lines()]
    assert "control polygon" in labels and "curvature comb" in labels
    curve_line = ax.get_lines()[0].get_xydata()
    np.testing.assert_allclose(curve_line[0], [0, 0])
    ax = sk.plot(sk.bfunction("erbs"))
    x, y = ax.get_lines()[0].get_data()
    assert y[0] == 0 and y[-1] == pytest.approx(1)
    ax3 = sk.plot(sk.load({"type": "trefoil"}))
    assert ax3.name == "3d"
    sk.plot([sk.load({"type": "heart"}), sk.load({"type": "circle"})], ax=sk.plot(sk.load({"type": "torus"})))


def test_plot_without_matplotlib_says_so(monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    monkeypatch.setitem(sys.modules, "matplotlib.pyplot", None)
    with pytest.raises(ImportError, match="pip install matplotlib"):
        sk.plot(sk.load({"type": "heart"}))
