"""splinekit: curves and surfaces from numpy.

Bézier, rational Bézier, B-spline, NURBS, Hermite and Catmull–Rom curves, B-spline,
NURBS and Bézier surfaces, Catmull–Clark, Loop and bilinear subdivision surfaces,
least-squares fitting and interpolation, and every shape and
scene document of the ``splinekit`` command line (docs/format.md), evaluated by the
splinekit kernel (Rust). Every command of the command line has its function here
(intersections, sections, projections, offsets, arc length, STEP, scenes, rendering);
shapes and scenes show themselves in notebooks. Arrays in, float64 C-contiguous arrays out; errors are
``SplinekitError``s with the command line's one-line message: ``DocumentError`` (bad input),
``NumericalError``, ``BudgetError`` (each also a ``ValueError``), ``FileError`` (also an
``OSError``) and ``RenderError`` (also a ``RuntimeError``).
"""

import os as _os


def _quiet_headless_vulkan() -> None:
    """Turn Mesa's Vulkan device-selection layer off where no Wayland session is reachable.

    Without it the layer makes libwayland print ``error: XDG_RUNTIME_DIR is invalid or not
    set in the environment.`` at every render on machines with Mesa's Vulkan driver and no
    desktop session (servers, containers, CI). The same rule as the command line's
    (``splinekit_render::backends``): only when neither ``WAYLAND_SOCKET``, an absolute
    ``WAYLAND_DISPLAY`` nor an absolute ``XDG_RUNTIME_DIR`` is set, and the user has not
    chosen a device (``NODEVICE_SELECT``, ``MESA_VK_DEVICE_SELECT``, ``DRI_PRIME``).
    """
    env = _os.environ
    if any(name in env for name in ("NODEVICE_SELECT", "MESA_VK_DEVICE_SELECT", "DRI_PRIME")):
        return
    absolute = lambda name: env.get(name, "").startswith("/")  # noqa: E731
    if "WAYLAND_SOCKET" in env or absolute("WAYLAND_DISPLAY") or absolute("XDG_RUNTIME_DIR"):
        return
    env["NODEVICE_SELECT"] = "1"


_quiet_headless_vulkan()

from ._errors import BudgetError, DocumentError, FileError, NumericalError, RenderError, SplinekitError
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
    animate,
    fit,
    fit_many,
    interpolate,
    load,
    render,
    subdivide,
)
from ._queries import (
    blend,
    blending_spline,
    blending_spline_surface,
    intersect,
    offset,
    project,
    measure,
    read_step,
    save,
    section,
    write_step,
)
from ._display import View, set_display, show
from ._plot import plot

__all__ = [
    "SplinekitError",
    "DocumentError",
    "NumericalError",
    "BudgetError",
    "FileError",
    "RenderError",
    "BFunction",
    "View",
    "animate",
    "blend",
    "blending_spline",
    "blending_spline_surface",
    "intersect",
    "offset",
    "plot",
    "project",
    "measure",
    "read_step",
    "save",
    "section",
    "set_display",
    "show",
    "subdivide",
    "write_step",
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
