"""The command line's queries, files and constructions for Python.

Each function runs the kernel calls of its ``splinekit`` command (in the extension
module) and turns the command's JSON answer into numpy arrays and splinekit objects:
``intersect`` (``splinekit intersect``), ``section`` (``section``), ``project``
(``project``), ``offset`` (``offset``), ``read_step``/``write_step`` (``convert``),
``save`` (``tessellate``), ``subdivide`` (``subdivide``) and the documents of blending
splines and blends. Errors are ``SplinekitError``s (``DocumentError`` for bad arguments, a ``ValueError``) with the command's message, its flags named
as the arguments here (``tolerance: expected one number > 0, got '0.0'``).
"""

from __future__ import annotations

import os
import warnings
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union, cast

import numpy as np

from . import _splinekit as _native
from ._errors import DocumentError
from ._splinekit import Curve, Scene, Surface, load

Shape = Union[Curve, Surface]
PathLike = Union[str, "os.PathLike[str]"]


def _array(x: Any) -> np.ndarray:
    return np.asarray(x, dtype=np.float64)


def _bspline(doc: Optional[dict]) -> Any:
    return None if doc is None else load(doc)


def _branch(c: dict, params_key: Sequence[str]) -> Dict[str, Any]:
    out: Dict[str, Any] = {"points": _array(c["points"]).reshape(-1, 3)}
    for key in params_key:
        out[key] = _array(c[key]).reshape(-1, 2)
    out.update(
        closed=c["closed"],
        tangent=c["tangent"],
        early_stop=c["early_stop"],
        bspline=_bspline(c["bspline"]),
        fit_error=c["fit_error"],
    )
    return out


def intersect(a: Any, b: Any = None, tolerance: float = 1e-9, chord: float = 1e-4) -> Dict[str, list]:
    """Where two shapes meet, or where one curve crosses itself (``b`` None): ``splinekit
    intersect A [B] --tolerance E --chord C`` as a dict of three lists.

    * ``points``: isolated intersections, each ``{"params": array, "point": array,
      "kind": "crossing" | "tangent"}``; ``params`` is (t_a, t_b) for two curves (or one
      curve with itself, t_a < t_b) and (t, u, v) for a curve and a surface (the curve's
      parameter first, whichever order they were given in);
    * ``overlaps``: stretches where two curves coincide within ``tolerance``, each
      ``{"params_a": (a0, a1), "params_b": (b0, b1)}`` (b0 > b1 when they run opposite ways);
    * ``curves``: the intersection curves of two 3-D surfaces, each ``{"points": (N, 3),
      "params_a": (N, 2), "params_b": (N, 2), "closed", "tangent", "early_stop",
      "bspline": BSpline | None, "fit_error"}`` — polylines within ``chord`` of the curve
      and a cubic B-spline fitted to them.

    ``a`` and ``b`` are curves, surfaces or documents ``load`` reads.
    """
    r = _native._intersect(a, b, tolerance, chord)
    points = [{"params": _array(p["params"]), "point": _array(p["point"]), "kind": p["kind"]} for p in r["points"]]
    overlaps = [{"params_a": tuple(o["params_a"]), "params_b": tuple(o["params_b"])} for o in r["overlaps"]]
    curves = [_branch(c, ("params_a", "params_b")) for c in r["curves"]]
    return {"points": points, "overlaps": overlaps, "curves": curves}


def section(
    surface: Any,
    origin: Any,
    normal: Any,
    levels: int = 1,
    tolerance: float = 1e-9,
    chord: float = 1e-4,
) -> List[Dict[str, Any]]:
    """Plane sections (contours) of a 3-D surface: ``splinekit section SURFACE --plane
    O/N --levels L``. With ``levels`` 1 the plane through ``origin`` with ``normal``; with
    L > 1 the L parallel planes at the middles of L equal slabs of the surface's extent
    along the normal. One dict per plane: ``origin`` (the plane's point nearest to the
    given origin), unit ``normal`` and ``curves``, each as ``intersect``'s curves with
    ``params`` (N, 2) on the surface."""
    r = _native._section(surface, origin, normal, levels, tolerance, chord)
    return [
        {"origin": _array(s["origin"]), "normal": _array(s["normal"]), "curves": [_branch(c, ("params",)) for c in s["curves"]]}
        for s in r["sections"]
    ]


def project(shape: Any, points: Any, all: bool = False, accuracy: float = 0.0) -> Any:
    """Nearest points of a curve or surface to many points at once (one bounding hierarchy
    for all): ``splinekit project SHAPE --points FILE [--all] [--accuracy E]``.

    ``points`` is (N, D), or one point (D,). Returns ``(params, points, distances)``:
    params (N,) for a curve, (N, 2) for a surface ((u, v)), the nearest points (N, D) and
    their distances (N,); for one point (D,) the first axis is dropped. With ``all=True``
    every local minimum of the distance instead: per query point a list of dicts ``t``
    (or ``u``, ``v``), ``point``, ``distance`` in increasing parameter order. ``accuracy``
    bounds how far a nearest distance may be above the true minimum (0: exact to
    rounding)."""
    p = np.asarray(points, dtype=np.float64)
    single = p.ndim == 1
    r = _native._project(shape, p.reshape(1, -1) if single else p, all, accuracy)
    if all:
        out = [[{k: (_array(v) if k == "point" else v) for k, v in m.items()} for m in minima] for minima in r]
        return out[0] if single else out
    params, near, dist = r
    if single:
        return (params[0] if params.ndim == 2 else float(params[0]), near[0], float(dist[0]))
    return params, near, dist


def offset(shape: Any, distance: float, tolerance: float = 1e-6, normal: Any = None, report: bool = False) -> Any:
    """The offset at signed ``distance`` as B-splines within ``tolerance`` of the exact
    offset: ``splinekit offset SHAPE --distance D [--tolerance E] [--normal N]``.

    A plane curve (2-D, or 3-D in the plane with ``normal``, default (0, 0, 1)) gives the
    list of its offset's pieces, cubic ``BSpline`` curves in parameter order (one piece
    usually; several where cusps and self-intersections were trimmed; none when the offset
    vanishes); c(t) + d·n(t) with n the right-hand normal, so d > 0 is outwards for a
    counter-clockwise curve. A 3-D surface gives one bicubic ``BSplineSurface``,
    S + d·N. With ``report=True`` also the line the command prints on standard error
    (pieces, achieved error, what was trimmed), as ``(result, report)``."""
    docs, line = _native._offset(shape, distance, tolerance, normal)
    result = [load(d) for d in docs] if isinstance(docs, list) else load(docs)
    return (result, line) if report else result


def read_step(path: PathLike, names: bool = False, scene: bool = False) -> Any:
    """The curves, surfaces and faces of a STEP file (any CAD system's AP203/AP214/AP242
    geometry, in millimetres and radians), as ``splinekit convert FILE.step -o OUT.json``
    reads them: a list of curves and surfaces (solids are ``brep`` surfaces, loose faces
    ``trimmed`` ones), each in its part's own coordinates. With ``names=True`` a list of
    ``(name, shape)`` pairs, the names of the file. With ``scene=True`` the file as one
    document, exactly as ``convert`` writes it: an assembly's parts as a ``Scene`` whose
    objects carry their ``name``, their ``placement`` and, for a part used again,
    ``instance_of`` its first use (a file of one object at its place: that shape).
    Entities splinekit does not read are reported by a ``UserWarning`` (as the command's
    ``warning:`` lines)."""
    items, skipped, document = _native._read_step(os.fspath(path))
    for entity, count in skipped:
        warnings.warn(f"{count} × {entity} not converted (no splinekit equivalent yet)", stacklevel=2)
    if scene:
        return load(document)
    shapes = [(name, load(doc)) for name, doc in items]
    return shapes if names else [s for _, s in shapes]


def measure(shape: Any, tolerance: Optional[float] = None) -> Dict[str, Any]:
    """What a solid or surface measures: ``splinekit measure SHAPE [--tolerance T]``.

    ``shape`` is a surface, a ``brep`` solid (as ``read_step`` returns the solids of a
    CAD file), a ``Scene``, or the path of a STEP file (read as ``read_step`` reads it: one
    object, or a scene of them). A solid gives its ``faces``, ``edges``, ``vertices``,
    ``shells``, ``closed_shells``, ``solids`` (each with its ``volume``), the ``area`` and
    ``volume`` integrated over the exact trimmed faces, and ``mesh``: its watertight mesh's
    ``tolerance`` (default 10⁻³ of the box diagonal), ``triangles``, ``area``, ``volume``,
    ``open_edges`` and ``box``. Another surface gives only ``mesh``; a scene
    ``{"objects": […]}``."""
    if isinstance(shape, (str, os.PathLike)):
        path = os.fspath(shape)
        if not path.lower().endswith((".step", ".stp")):
            raise DocumentError(f"shape: measure reads STEP files (.step, .stp) by path, not '{path}'; load() a document")
        shape = read_step(path, scene=True)
    return cast(Dict[str, Any], _native._measure(shape, tolerance))


def write_step(objects: Any, path: PathLike, tolerance: float = 1e-6) -> List[Dict[str, Any]]:
    """Writes exact geometry as STEP AP214 in millimetres: ``splinekit convert IN.json -o
    OUT.step``. ``objects`` is a shape, a ``Scene`` or a list of shapes (one item each);
    shapes without an exact STEP form are approximated by B-splines within ``tolerance``
    of their size. Returns per item ``name``, ``form`` (``"exact"``,
    ``"exact_polynomial"``, ``"approximated"``), ``max_deviation`` and ``tolerance``."""
    if isinstance(objects, (list, tuple)):
        objects = Scene(objects)
    return _native._write_step(objects, os.fspath(path), tolerance)


def save(
    obj: Any,
    path: PathLike,
    density: Optional[int] = None,
    tolerance: Optional[float] = None,
    time: Optional[float] = None,
) -> None:
    """Writes a shape or scene to a file, the extension picking the format, as ``splinekit
    tessellate SHAPE -o FILE`` (and ``.json``: the document). Curves: .svg, .obj, .gltf,
    .glb; surfaces: .obj, .stl, .stla, .ply, .gltf, .glb; scenes: .obj (a group per
    object), .stl, .stla (every surface in one mesh; curves are refused), .ply (one mesh,
    curves as edges), .gltf, .glb (an animation as morph targets); .step and .stp as
    ``write_step``. ``density`` segments or cells per direction, or adaptive to
    ``tolerance`` (shapes; a scene's objects keep their own ``density``); ``time`` poses an
    animation (a scene's glTF carries the whole animation)."""
    if isinstance(obj, (list, tuple)):
        obj = Scene(obj)
    _native._save(obj, os.fspath(path), density, tolerance, time)


def _bfunction_doc(bfunction: Any) -> Any:
    if bfunction is None:
        return None
    if isinstance(bfunction, str):
        return {"type": bfunction}
    return bfunction  # a BFunction (its to_dict) or a dict


def _drop_none(doc: Dict[str, Any]) -> Dict[str, Any]:
    return {k: v for k, v in doc.items() if v is not None}


def blending_spline(
    model: Any = None,
    local_curves: Any = None,
    *,
    local: str = "bezier",
    degree: int = 3,
    bfunction: Any = "erbs",
    knots: Any = None,
    knot_spacing: Optional[str] = None,
    closed: Optional[bool] = None,
    transforms: Any = None,
    animation: Any = None,
) -> Curve:
    """A blending-spline curve (docs/format.md, ``blending_spline``) c(t) = Σ B∘w_k(t) ℓ_k(t).

    From a ``model`` curve: ``local_curves`` n local curves at knots over its domain,
    ``local`` ``"bezier"`` (of ``degree``, fitted to the model's value and first d
    derivatives at each knot), ``"sub_curve"`` or ``"arc"``; ``knot_spacing``
    ``"uniform"`` or ``"chord_length"``, or the ``knots`` themselves. From explicit locals:
    ``local_curves`` a list of curves and ``knots`` one per local (closed: one more).
    ``bfunction`` is a ``BFunction``, a kind (``"erbs"``, ``"polynomial"``, …) or its
    document; ``transforms`` and ``animation`` as in the document."""
    doc: Dict[str, Any] = {"type": "blending_spline"}
    if model is not None:
        doc.update(model=model, local_curves=local_curves)
        doc["local"] = {"type": local, "degree": degree} if local == "bezier" else {"type": local}
    else:
        if local_curves is None or isinstance(local_curves, int):
            raise DocumentError("local_curves: without a model, give the local curves themselves (a list) and their knots")
        doc["local_curves"] = list(local_curves)
    doc.update(
        _drop_none(
            dict(
                knots=None if knots is None else np.asarray(knots, dtype=float).tolist(),
                knot_spacing=knot_spacing,
                bfunction=_bfunction_doc(bfunction),
                closed=closed,
                transforms=transforms,
                animation=animation,
            )
        )
    )
    return cast(Curve, load(doc))


def blending_spline_surface(
    model: Any,
    local_surfaces: Tuple[int, int],
    *,
    local: str = "bezier",
    degree: Tuple[int, int] = (3, 3),
    bfunction: Any = "erbs",
    closed_u: Optional[bool] = None,
    closed_v: Optional[bool] = None,
    transforms: Any = None,
    animation: Any = None,
) -> Surface:
    """A blending-spline surface of a ``model`` surface (docs/format.md,
    ``blending_spline_surface``): ``local_surfaces`` (nu, nv) local patches, ``local``
    ``"bezier"`` (of ``degree`` (du, dv), fitted to the model's mixed partials at the
    knots) or ``"sub_surface"``, blended by ``bfunction`` in both directions."""
    doc: Dict[str, Any] = {
        "type": "blending_spline_surface",
        "model": model,
        "local_surfaces": list(local_surfaces),
        "local": {"type": local, "degree": list(degree)} if local == "bezier" else {"type": local},
    }
    doc.update(
        _drop_none(
            dict(
                bfunction=_bfunction_doc(bfunction),
                closed_u=closed_u,
                closed_v=closed_v,
                transforms=transforms,
                animation=animation,
            )
        )
    )
    return cast(Surface, load(doc))


def blend(first: Any, second: Any, overlap: float = 0.5, bfunction: Any = "polynomial") -> Curve:
    """The two-curve blend on [0, 1 + x] (docs/format.md, ``blend``): ``first`` on [0, x),
    first + B((t − x)/(1 − x))(second(t − x) − first) on [x, 1), ``second`` on [1, 1 + x],
    each curve reparametrised to [0, 1], x = ``overlap``."""
    return cast(Curve, load({"type": "blend", "first": first, "second": second, "overlap": overlap, "bfunction": _bfunction_doc(bfunction)}))
