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
    "fit_many",
    "evaluate_many",
    "_restore",
    "_FIELDS_CLASSES",
    "HAS_RENDER",
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

@final
class Scene(_Document):
    @property
    def objects(self) -> list: ...
    @property
    def animated(self) -> bool: ...

HAS_RENDER: bool

def render(obj: Any, path: Union[str, "PathLike[str]"], size: Tuple[int, int] = (800, 600), time: Optional[float] = None) -> None: ...
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
