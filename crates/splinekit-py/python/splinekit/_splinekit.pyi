"""Type stubs of the extension module (the docstrings at run time carry the math)."""

from os import PathLike
from typing import Any, Dict, Iterable, List, Optional, Sequence, Tuple, Union, final

from typing_extensions import disjoint_base

import numpy as np
from numpy.typing import ArrayLike, NDArray

_F64 = NDArray[np.float64]

__all__ = [
    "Curve",
    "BSpline",
    "NURBS",
    "Bezier",
    "RationalBezier",
    "Hermite",
    "CatmullRom",
    "Surface",
    "BSplineSurface",
    "NURBSSurface",
    "BezierSurface",
    "SubdivisionSurface",
    "DupinCyclide",
    "Chrysanthemum",
    "LogarithmicSpiral",
    "WhitneyUmbrella",
    "TrianguloidTrefoil",
    "Swallowtail",
    "RomanSurface",
    "SlippersSurface",
    "SineSurface",
    "KuenSurface",
    "InsideOutTorus",
    "EightSurface",
    "DiniSurface",
    "CrossCap",
    "BoySurface",
    "BohemianDome",
    "BentHorns",
    "AsteroidalSphere",
    "BezierTriangle",
    "SubTriangle",
    "GerbsTriangle",
    "Triangulation",
    "BlendingTriangulation",
    "Scene",
    "FitReport",
    "Mesh",
    "fit",
    "interpolate",
    "load",
    "render",
    "animate",
    "subdivide",
    "fit_many",
    "evaluate_many",
    "_restore",
    "_FIELDS_CLASSES",
    "HAS_RENDER",
    "_intersect",
    "_section",
    "_measure",
    "_project",
    "_offset",
    "_read_step",
    "_write_step",
    "_gltf",
    "_save",
    "_svg",
    "_three_bundle",
]

# Stub-only bases (absent at run time, where each class defines these methods itself):
# what the classes of the module have alike, written once here.
class _Pickled:
    """Pickles and copies (``__reduce__``) and compares its contents (``==``)."""
    def __reduce__(self) -> Tuple[Any, Tuple[Any, ...]]: ...
    def __eq__(self, value: object, /) -> bool: ...

class _Document(_Pickled):
    """An object whose state is a document (docs/format.md)."""
    def to_dict(self) -> dict: ...
    def to_json(self) -> str: ...

class _Shape(_Document):
    """A curve or surface of a shape document."""
    def _repr_mimebundle_(self, include: Any = None, exclude: Any = None, **_kwargs: Any) -> Dict[str, Any]: ...
    def save(
        self,
        path: Union[str, "PathLike[str]"],
        density: Optional[int] = None,
        tolerance: Optional[float] = None,
        time: Optional[float] = None,
    ) -> None: ...
    def intersect(self, other: Any = None, tolerance: float = 1e-9, chord: float = 1e-4) -> Dict[str, list]: ...
    def project(self, points: ArrayLike, all: bool = False, accuracy: float = 0.0) -> Any: ...
    def offset(self, distance: float, tolerance: float = 1e-6, normal: Optional[ArrayLike] = None, report: bool = False) -> Any: ...
    @property
    def dimension(self) -> int: ...
    @property
    def kind(self) -> str: ...
    @property
    def control_points(self) -> _F64: ...
    @property
    def weights(self) -> _F64: ...

@disjoint_base
class Curve(_Shape):
    """A parametric curve c: [a, b] → ℝᴰ of any shape-document kind."""
    def __call__(self, t: ArrayLike, nu: int = 0) -> _F64: ...
    def derivatives(self, t: ArrayLike, order: int) -> _F64: ...
    @property
    def domain(self) -> Tuple[float, float]: ...
    @property
    def closed(self) -> bool: ...
    @property
    def knots(self) -> _F64: ...
    @property
    def degree(self) -> int: ...
    def length(self, tolerance: float = 1e-10) -> float: ...
    def length_at(self, t: ArrayLike, tolerance: float = 1e-10) -> Union[float, _F64]: ...
    def param_at_length(self, s: ArrayLike, accuracy: Optional[float] = None) -> Union[float, _F64]: ...
    def arc_length_params(self, n: int) -> _F64: ...
    def closest_point(self, p: ArrayLike, accuracy: float = 1e-12) -> Tuple[float, _F64, float]: ...
    def curvature(self, t: ArrayLike) -> Union[float, _F64]: ...
    def frame(self, t: float) -> Optional[dict]: ...
    def insert_knot(self, t: float, times: int = 1) -> "Curve": ...
    def elevate_degree(self, times: int = 1) -> "Curve": ...
    def remove_knot(self, t: float, tolerance: float = 1e-9, times: int = 1) -> "Curve": ...
    def split(self, t: float) -> Tuple["Curve", Optional["Curve"]]: ...
    def to_bezier(self) -> list: ...
    def tessellate(self, density: Optional[int] = None, tolerance: Optional[float] = None) -> _F64: ...
    def set_transform(
        self, k: int, translate: Optional[ArrayLike] = None, rotate: Optional[dict] = None, scale: Optional[float] = None
    ) -> None: ...
    def at_time(self, t: float) -> "Curve": ...
    def local_pieces(self, samples: int = 97) -> list: ...
    def insert_local(self, t: float) -> Tuple["Curve", int]: ...
    def split_knot(self, k: int) -> "Curve": ...
    def set_closed(self, closed: bool) -> "Curve": ...

@final
class BSpline(Curve):
    def __new__(cls, knots: ArrayLike, control_points: ArrayLike, degree: int, periodic: bool = False) -> "BSpline": ...
    @property
    def fit_report(self) -> Optional["FitReport"]: ...

@final
class NURBS(Curve):
    def __new__(
        cls, knots: ArrayLike, control_points: ArrayLike, weights: ArrayLike, degree: int, periodic: bool = False
    ) -> "NURBS": ...

@final
class Bezier(Curve):
    def __new__(cls, control_points: ArrayLike) -> "Bezier": ...

@final
class RationalBezier(Curve):
    def __new__(cls, control_points: ArrayLike, weights: ArrayLike) -> "RationalBezier": ...

@final
class Hermite(Curve):
    def __new__(cls, points: ArrayLike, tangents: ArrayLike, params: Optional[ArrayLike] = None) -> "Hermite": ...

@final
class CatmullRom(Curve):
    def __new__(cls, points: ArrayLike, alpha: float = 0.0, closed: bool = False) -> "CatmullRom": ...

@final
class FitReport(_Pickled):
    @property
    def rms_error(self) -> float: ...
    @property
    def max_error(self) -> float: ...
    @property
    def condition_estimate(self) -> float: ...
    @property
    def params(self) -> _F64: ...

@disjoint_base
class Surface(_Shape):
    """A parametric surface S: [a, b] × [c, d] → ℝᴰ of any shape-document kind."""
    def __call__(self, u: ArrayLike, v: ArrayLike, grid: bool = True) -> _F64: ...
    def partials(self, u: ArrayLike, v: ArrayLike, order: int = 1, grid: bool = True) -> dict: ...
    def normals(self, u: ArrayLike, v: ArrayLike, grid: bool = True) -> _F64: ...
    def points_and_normals(self, u: ArrayLike, v: ArrayLike, grid: bool = True) -> Tuple[_F64, _F64]: ...
    def closest_point(self, p: ArrayLike, accuracy: float = 1e-12) -> Tuple[float, float, _F64, float]: ...
    @property
    def domain_u(self) -> Tuple[float, float]: ...
    @property
    def domain_v(self) -> Tuple[float, float]: ...
    @property
    def closed_u(self) -> bool: ...
    @property
    def closed_v(self) -> bool: ...
    @property
    def knots(self) -> Tuple[_F64, _F64]: ...
    @property
    def degrees(self) -> Tuple[int, int]: ...
    def tessellate(self, density: Optional[int] = None, tolerance: Optional[float] = None) -> "Mesh": ...
    def set_transform(
        self,
        k: Tuple[int, int],
        translate: Optional[ArrayLike] = None,
        rotate: Optional[dict] = None,
        scale: Optional[float] = None,
    ) -> None: ...
    def at_time(self, t: float) -> "Surface": ...
    def local_pieces(self, samples: int = 17) -> list: ...
    def insert_knot_line(self, direction: str, t: float) -> Tuple["Surface", int]: ...
    def split_knot_line(self, direction: str, k: int) -> "Surface": ...
    def section(
        self, origin: ArrayLike, normal: ArrayLike, levels: int = 1, tolerance: float = 1e-9, chord: float = 1e-4
    ) -> List[Dict[str, Any]]: ...

@final
class BSplineSurface(Surface):
    def __new__(
        cls,
        knots_u: ArrayLike,
        knots_v: ArrayLike,
        control_points: ArrayLike,
        degree_u: int,
        degree_v: int,
        periodic_u: bool = False,
        periodic_v: bool = False,
    ) -> "BSplineSurface": ...

@final
class NURBSSurface(Surface):
    def __new__(
        cls,
        knots_u: ArrayLike,
        knots_v: ArrayLike,
        control_points: ArrayLike,
        weights: ArrayLike,
        degree_u: int,
        degree_v: int,
        periodic_u: bool = False,
        periodic_v: bool = False,
    ) -> "NURBSSurface": ...

@final
class BezierSurface(Surface):
    def __new__(cls, control_points: ArrayLike) -> "BezierSurface": ...

# The classes made from a kind's document fields (a line `python(fields "Name")` in
# splinekit-scene's registry of kinds); their constructors take the fields as keyword
# arguments. tests/test_api.py checks that each has its stub here.
_FIELDS_CLASSES: List[str]

@final
class DupinCyclide(Surface):
    def __new__(cls, **fields: Any) -> "DupinCyclide": ...

@final
class Chrysanthemum(Curve):
    def __new__(cls, **fields: Any) -> "Chrysanthemum": ...

@final
class LogarithmicSpiral(Curve):
    def __new__(cls, **fields: Any) -> "LogarithmicSpiral": ...

@final
class WhitneyUmbrella(Surface):
    def __new__(cls, **fields: Any) -> "WhitneyUmbrella": ...

@final
class TrianguloidTrefoil(Surface):
    def __new__(cls, **fields: Any) -> "TrianguloidTrefoil": ...

@final
class Swallowtail(Surface):
    def __new__(cls, **fields: Any) -> "Swallowtail": ...

@final
class RomanSurface(Surface):
    def __new__(cls, **fields: Any) -> "RomanSurface": ...

@final
class SlippersSurface(Surface):
    def __new__(cls, **fields: Any) -> "SlippersSurface": ...

@final
class SineSurface(Surface):
    def __new__(cls, **fields: Any) -> "SineSurface": ...

@final
class KuenSurface(Surface):
    def __new__(cls, **fields: Any) -> "KuenSurface": ...

@final
class InsideOutTorus(Surface):
    def __new__(cls, **fields: Any) -> "InsideOutTorus": ...

@final
class EightSurface(Surface):
    def __new__(cls, **fields: Any) -> "EightSurface": ...

@final
class DiniSurface(Surface):
    def __new__(cls, **fields: Any) -> "DiniSurface": ...

@final
class CrossCap(Surface):
    def __new__(cls, **fields: Any) -> "CrossCap": ...

@final
class BoySurface(Surface):
    def __new__(cls, **fields: Any) -> "BoySurface": ...

@final
class BohemianDome(Surface):
    def __new__(cls, **fields: Any) -> "BohemianDome": ...

@final
class BentHorns(Surface):
    def __new__(cls, **fields: Any) -> "BentHorns": ...

@final
class AsteroidalSphere(Surface):
    def __new__(cls, **fields: Any) -> "AsteroidalSphere": ...

@final
class BezierTriangle(Surface):
    def __new__(cls, **fields: Any) -> "BezierTriangle": ...

@final
class SubTriangle(Surface):
    def __new__(cls, **fields: Any) -> "SubTriangle": ...

@final
class GerbsTriangle(Surface):
    def __new__(cls, **fields: Any) -> "GerbsTriangle": ...

@final
class Triangulation(Surface):
    def __new__(cls, **fields: Any) -> "Triangulation": ...

@final
class BlendingTriangulation(Surface):
    def __new__(cls, **fields: Any) -> "BlendingTriangulation": ...

@final
class Mesh(_Pickled):
    @property
    def vertices(self) -> _F64: ...
    @property
    def faces(self) -> NDArray[np.int32]: ...
    @property
    def normals(self) -> _F64: ...
    @property
    def uv(self) -> _F64: ...
    def save(self, path: Union[str, "PathLike[str]"]) -> None: ...
    def to_gltf(self, binary: bool = True) -> bytes: ...
    def _repr_mimebundle_(self, include: Any = None, exclude: Any = None, **_kwargs: Any) -> Dict[str, Any]: ...

@final
class SubdivisionSurface(_Pickled):
    def __new__(
        cls,
        vertices: ArrayLike,
        faces: Sequence[Sequence[int]],
        scheme: str = "catmull-clark",
        creases: Optional[Sequence[Tuple[int, int, float]]] = None,
        boundary: str = "edge-only",
        triangulate: bool = False,
    ) -> "SubdivisionSurface": ...
    @property
    def vertices(self) -> _F64: ...
    @property
    def faces(self) -> List[List[int]]: ...
    @property
    def creases(self) -> List[Tuple[int, int, float]]: ...
    @property
    def scheme(self) -> str: ...
    @property
    def boundary(self) -> str: ...
    def subdivide(self, steps: int) -> SubdivisionSurface: ...
    def limit_points(self) -> _F64: ...
    def limit_normals(self) -> _F64: ...
    def evaluate(self, face: int, u: float, v: float) -> Dict[str, Any]: ...
    def to_mesh(self, steps: int = 3, limit: bool = True) -> Mesh: ...
    def to_dict(self) -> dict: ...
    def _repr_mimebundle_(self, include: Any = None, exclude: Any = None, **_kwargs: Any) -> Dict[str, Any]: ...

@final
class Scene(_Document):
    def __new__(
        cls,
        objects: Optional[Iterable[Any]] = None,
        *,
        camera: Optional[dict] = None,
        lights: Optional[Sequence[dict]] = None,
        background: Optional[ArrayLike] = None,
        size: Optional[Tuple[int, int]] = None,
        axes: Optional[bool] = None,
        animation: Optional[dict] = None,
    ) -> "Scene": ...
    @property
    def objects(self) -> list: ...
    @property
    def animated(self) -> bool: ...
    @property
    def clock(self) -> Tuple[float, float]: ...
    @property
    def size(self) -> Tuple[int, int]: ...
    def add(self, shape: Any, **style: Any) -> "Scene": ...
    def replace(self, **fields: Any) -> "Scene": ...
    def save(self, path: Union[str, "PathLike[str]"]) -> None: ...
    def __len__(self) -> int: ...
    def _repr_mimebundle_(self, include: Any = None, exclude: Any = None, **_kwargs: Any) -> Dict[str, Any]: ...

HAS_RENDER: bool

def render(
    obj: Any,
    path: Optional[Union[str, "PathLike[str]"]] = None,
    size: Optional[Tuple[int, int]] = None,
    time: Optional[float] = None,
) -> Optional[NDArray[np.uint8]]: ...
def animate(
    obj: Any,
    path: Optional[Union[str, "PathLike[str]"]] = None,
    frames: Optional[int] = None,
    fps: Optional[float] = None,
    size: Optional[Tuple[int, int]] = None,
) -> Optional[NDArray[np.uint8]]: ...
def subdivide(
    points: ArrayLike,
    scheme: str,
    steps: int,
    degree: Optional[int] = None,
    closed: bool = False,
    keep_ends: bool = False,
    tension: float = 0.0625,
) -> _F64: ...
def _intersect(a: Any, b: Any = None, tolerance: float = 1e-9, chord: float = 1e-4) -> Dict[str, Any]: ...
def _section(
    surface: Any, origin: Any, normal: Any, levels: int = 1, tolerance: float = 1e-9, chord: float = 1e-4
) -> Dict[str, Any]: ...
def _measure(shape: Any, tolerance: Optional[float] = None) -> Dict[str, Any]: ...
def _project(shape: Any, points: Any, all: bool = False, accuracy: float = 0.0) -> Any: ...
def _offset(shape: Any, distance: float, tolerance: float = 1e-6, normal: Any = None) -> Tuple[Any, str]: ...
def _read_step(path: Union[str, "PathLike[str]"]) -> Tuple[List[Tuple[str, Any]], List[Tuple[str, int]], Any]: ...
def _write_step(doc: Any, path: Union[str, "PathLike[str]"], tolerance: float = 1e-6) -> List[Dict[str, Any]]: ...
def _gltf(doc: Any, meshes: Sequence[Mesh] = ..., binary: bool = True) -> Tuple[bytes, Optional[float]]: ...
def _save(
    doc: Any,
    path: Union[str, "PathLike[str]"],
    density: Optional[int] = None,
    tolerance: Optional[float] = None,
    time: Optional[float] = None,
) -> None: ...
def _svg(doc: Any) -> str: ...
def _three_bundle() -> Tuple[str, str]: ...
def load(doc: Any) -> Union[Curve, Surface, Scene]: ...
def fit(
    points: ArrayLike,
    degree: int,
    n_control_points: Optional[int] = None,
    params: Union[str, ArrayLike] = "chord",
    knots: Union[str, ArrayLike] = "averaged",
    closed: bool = False,
    weights: Optional[ArrayLike] = None,
    fix_ends: bool = False,
) -> BSpline: ...
def interpolate(
    points: ArrayLike,
    degree: int,
    params: str = "chord",
    closed: bool = False,
    end_derivatives: Optional[Tuple[ArrayLike, ArrayLike]] = None,
) -> BSpline: ...
def fit_many(
    point_sets: Iterable[ArrayLike],
    degree: int,
    n_control_points: Optional[int] = None,
    params: Union[str, ArrayLike] = "chord",
    knots: Union[str, ArrayLike] = "averaged",
    closed: bool = False,
    weights: Optional[ArrayLike] = None,
    fix_ends: bool = False,
    threads: Optional[int] = None,
) -> List[BSpline]: ...
def evaluate_many(
    shapes: Iterable[Union[Curve, Surface]],
    params: Iterable[Any],
    nu: int = 0,
    threads: Optional[int] = None,
) -> List[_F64]: ...
def _restore(tag: str, state: Any, extra: Any) -> Any: ...
