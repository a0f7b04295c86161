"""splinekit: curves and surfaces from numpy.

Bézier, rational Bézier, B-spline, NURBS, Hermite and Catmull–Rom curves, B-spline,
NURBS and Bézier surfaces, Catmull–Clark, Loop and bilinear subdivision surfaces,
least-squares fitting and interpolation, and every shape and
scene document of the ``splinekit`` command line (docs/format.md), evaluated by the
splinekit kernel (Rust). Arrays in, float64 C-contiguous arrays out; bad input raises
``ValueError`` with the command line's one-line message.
"""

from ._bfunction import BFunction, bfunction
from ._splinekit import (
    BSpline,
    BSplineSurface,
    Bezier,
    BezierSurface,
    CatmullRom,
    Curve,
    FitReport,
    Hermite,
    Mesh,
    NURBS,
    NURBSSurface,
    RationalBezier,
    Scene,
    SubdivisionSurface,
    Surface,
    evaluate_many,
    fit,
    fit_many,
    interpolate,
    load,
    render,
)

__all__ = [
    "BFunction",
    "BSpline",
    "BSplineSurface",
    "Bezier",
    "BezierSurface",
    "CatmullRom",
    "Curve",
    "FitReport",
    "Hermite",
    "Mesh",
    "NURBS",
    "NURBSSurface",
    "RationalBezier",
    "Scene",
    "SubdivisionSurface",
    "Surface",
    "bfunction",
    "evaluate_many",
    "fit",
    "fit_many",
    "interpolate",
    "load",
    "render",
]

# The classes the registry of kinds makes from a kind's document fields (a line
# `python(fields "Name")` in splinekit-scene's lists), e.g. ``splinekit.DupinCyclide``.
from . import _splinekit as _native  # noqa: E402

for _name in _native._FIELDS_CLASSES:
    globals()[_name] = getattr(_native, _name)
