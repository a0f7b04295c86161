"""Shapes that show themselves in notebooks (IPython's ``_repr_mimebundle_``).

Curves, surfaces, meshes, subdivision surfaces, blending splines and scenes give:

* ``text/html``: an interactive 3-D view of the object's glTF (three.js, the gallery's
  pinned bundle, inline so it works offline): drag to turn, wheel to zoom, right-drag to
  pan, double-click to go back; animated scenes play their morph targets with a
  play/pause button and a time slider. The three.js bundle (about 660 KiB) is embedded in
  the first view of a session only, and later views use it (``set_display(embed_three=
  "always")`` embeds it in every view, for notebooks whose outputs are shown one by one);
* ``image/svg+xml`` for plane curves (1-D and 2-D);
* ``image/png``, a picture by the renderer, for front ends that run no JavaScript
  (GitHub's notebook view, nbviewer) — when the package has the renderer
  (``splinekit._splinekit.HAS_RENDER``) and a graphics adapter is there;
* ``text/plain``: the ``repr``.

``show(a, b, …)`` draws several objects in one view; ``set_display`` sets the size and
which parts are made.
"""

from __future__ import annotations

import base64
import json
import struct
import uuid
import zlib
from importlib import resources
from typing import Any, Dict, List, Optional

from . import _splinekit as _native
from ._errors import DocumentError

_options: Dict[str, Any] = {"width": 640, "height": 420, "embed_three": "once", "png": True, "html": True}
_three_sent = False
_viewer_js: Optional[str] = None


def set_display(
    width: Optional[int] = None,
    height: Optional[int] = None,
    embed_three: Optional[str] = None,
    png: Optional[bool] = None,
    html: Optional[bool] = None,
) -> Dict[str, Any]:
    """Sets how objects show in notebooks and returns the settings: the view's ``width``
    and ``height`` in CSS pixels (default 640 × 420; also the PNG's size), ``embed_three``
    ``"once"`` (the three.js bundle in the first view of the session, the default) or
    ``"always"`` (in every view), ``png`` (make the PNG fallback) and ``html`` (make the
    interactive view)."""
    for key, value in (("width", width), ("height", height), ("png", png), ("html", html)):
        if value is not None:
            _options[key] = value
    if embed_three is not None:
        if embed_three not in ("once", "always"):
            raise DocumentError(f"embed_three: expected \"once\" or \"always\", got {embed_three!r}")
        _options["embed_three"] = embed_three
    for key in ("width", "height"):
        if not (isinstance(_options[key], int) and 16 <= _options[key] <= 8192):
            raise DocumentError(f"{key}: expected a whole number of pixels in 16 … 8192, got {_options[key]!r}")
    return dict(_options)


def _viewer() -> str:
    global _viewer_js
    if _viewer_js is None:
        _viewer_js = resources.files("splinekit").joinpath("_viewer.js").read_text(encoding="utf-8")
    return _viewer_js


def _three_script(force: bool) -> str:
    """The three.js bundle in a script tag, once a session unless ``force``."""
    global _three_sent
    if _three_sent and not force and _options["embed_three"] == "once":
        return ""
    _three_sent = True
    bundle, _licence = _native._three_bundle()
    # The bundle holds no "</script" (checked by the tests), so it can sit in a tag as is.
    return "<script>if(!window.SplinekitThree){" + bundle + "\nwindow.SplinekitThree=SplinekitThree;}</script>"


def _kind(obj: Any) -> str:
    if isinstance(obj, _native.Mesh):
        return "mesh"
    if isinstance(obj, (_native.Curve, _native.Surface, _native.Scene, _native.SubdivisionSurface)):
        return "document"
    raise TypeError(f"splinekit cannot show {type(obj).__name__} objects (curves, surfaces, meshes, subdivision surfaces and scenes)")


def _scene_of(objects: List[Any]) -> Optional[_native.Scene]:
    """One scene of every document object (scenes' objects flattened, the first scene's
    camera, background and clock kept); None when there are none."""
    entries: List[Any] = []
    options: Dict[str, Any] = {}
    for obj in objects:
        if isinstance(obj, _native.Scene):
            doc = obj.to_dict()
            entries.extend(doc.get("objects", []))
            for key in ("background", "animation", "lights", "axes"):
                if key in doc and key not in options:
                    options[key] = doc[key]
        elif _kind(obj) == "document":
            entries.append({"shape": obj})
    if not entries:
        return None
    return _native.Scene([_steady(e) for e in entries], **options)


def _steady(entry: Any) -> Any:
    """An animated object drawn at a fixed density, so that every frame has as many
    vertices and the glTF carries the motion as morph targets (adaptive polylines change
    their point count from frame to frame)."""
    shape = entry["shape"]
    doc = shape if isinstance(shape, dict) else shape.to_dict()
    if "animation" in doc and "density" not in entry:
        curve = isinstance(shape, _native.Curve) or doc.get("type") in ("blending_spline", "blend")
        return {**entry, "shape": doc, "density": 400 if curve else 48}
    return entry


def _glb(objects: List[Any]) -> "tuple[bytes, Optional[float], List[float]]":
    scene = _scene_of(objects)
    meshes = [o for o in objects if _kind(o) == "mesh"]
    data, period = _native._gltf(scene, meshes, True)
    background = [1.0, 1.0, 1.0]
    if scene is not None:
        background = list(scene.to_dict().get("background", background))
    return bytes(data), period, background


def _html(objects: List[Any], width: int, height: int, force_three: bool = False) -> str:
    data, period, background = _glb(objects)
    view_id = "splinekit-" + uuid.uuid4().hex
    spec = {"size": [width, height], "background": background, "duration": period}
    encoded = base64.b64encode(data).decode("ascii")
    bar = (
        '<div class="splinekit-timebar" style="display:none;gap:8px;align-items:center;font:13px sans-serif">'
        '<button type="button" aria-label="play or pause">pause</button>'
        '<input type="range" min="0" value="0" style="flex:1"><output>0.00 s</output></div>'
    )
    return (
        f'<div id="{view_id}" class="splinekit-view" style="width:{width}px">'
        f'<canvas style="width:{width}px;height:{height}px;display:block;touch-action:none;cursor:grab" '
        f'aria-label="3-D view: drag to turn, wheel to zoom, right-drag to pan"></canvas>{bar}</div>'
        + _three_script(force_three)
        + "<script>"
        + _viewer()
        + f"\nwindow.splinekitNotebook.show({json.dumps(view_id)}, {json.dumps(encoded)}, {json.dumps(spec)});</script>"
    )


def _png_bytes(image: Any) -> bytes:
    """PNG bytes of an (H, W, 4) uint8 array (zlib and struct: no imaging library)."""
    h, w, _ = image.shape
    raw = b"".join(b"\x00" + image[y].tobytes() for y in range(h))

    def chunk(tag: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b"")


def _png(objects: List[Any], width: int, height: int) -> Optional[bytes]:
    """A picture by the renderer, or None where there is none (no renderer in the build,
    no graphics adapter, only meshes)."""
    if not _native.HAS_RENDER:
        return None
    scene = _scene_of(objects)
    if scene is None:
        return None
    try:
        return _png_bytes(_native.render(scene, size=(width, height)))
    except RuntimeError:
        return None


def _svg(obj: Any) -> Optional[str]:
    if isinstance(obj, _native.Curve) and obj.dimension <= 2:
        return _native._svg(obj)
    return None


def _wanted(mime: str, include: Any, exclude: Any) -> bool:
    return (not include or mime in include) and not (exclude and mime in exclude)


def _bundle(objects: List[Any], text: str, width: int, height: int, include: Any = None, exclude: Any = None) -> Dict[str, Any]:
    out: Dict[str, Any] = {"text/plain": text}
    if len(objects) == 1 and _wanted("image/svg+xml", include, exclude):
        svg = _svg(objects[0])
        if svg is not None:
            out["image/svg+xml"] = svg
    if _options["png"] and _wanted("image/png", include, exclude):
        png = _png(objects, width, height)
        if png is not None:
            out["image/png"] = png
    if _options["html"] and _wanted("text/html", include, exclude):
        out["text/html"] = _html(objects, width, height)
    return out


def mimebundle(obj: Any, include: Any = None, exclude: Any = None) -> Dict[str, Any]:
    """What ``obj._repr_mimebundle_(include, exclude)`` returns (see the module)."""
    return _bundle([obj], repr(obj), _options["width"], _options["height"], include, exclude)


class View:
    """Several objects in one notebook view (``show(a, b, …)``); displays itself, and
    ``html()`` gives the view's HTML (with the three.js bundle) for a page of its own."""

    def __init__(self, objects: List[Any], width: Optional[int], height: Optional[int]):
        for o in objects:
            _kind(o)
        self.objects = list(objects)
        self.width = width or _options["width"]
        self.height = height or _options["height"]

    def _repr_mimebundle_(self, include: Any = None, exclude: Any = None, **kwargs: Any) -> Dict[str, Any]:
        return _bundle(self.objects, repr(self), self.width, self.height, include, exclude)

    def html(self) -> str:
        """A standalone HTML page of the view (three.js inline: works offline)."""
        body = _html(self.objects, self.width, self.height, force_three=True)
        return f'<!DOCTYPE html><html><head><meta charset="utf-8"><title>splinekit</title></head><body>{body}</body></html>'

    def __repr__(self) -> str:
        return f"<splinekit view of {len(self.objects)} objects, {self.width}×{self.height}>"


def show(*objects: Any, width: Optional[int] = None, height: Optional[int] = None) -> View:
    """One view of several objects (curves, surfaces, meshes, subdivision surfaces,
    scenes) drawn together, ``width`` × ``height`` CSS pixels (default: ``set_display``'s).
    Returned for the notebook to display (the last expression of a cell, or
    ``IPython.display.display(show(…))``)."""
    if not objects:
        raise DocumentError("objects: show needs at least one object")
    return View(list(objects), width, height)
