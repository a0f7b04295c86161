"""``splinekit.plot``: curves, control polygons, curvature combs and B-functions drawn
with matplotlib (an optional dependency: ``pip install matplotlib``)."""

from __future__ import annotations

from typing import Any, Optional

import numpy as np

from . import _splinekit as _native
from ._bfunction import BFunction


def _pyplot() -> Any:
    try:
        import matplotlib.pyplot as plt
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError(
            "splinekit.plot draws with matplotlib, which is not installed: pip install matplotlib "
            "(or show the object in a notebook, which needs no matplotlib)"
        ) from e
    return plt


def _comb(curve: Any, ax: Any, samples: int, scale: Optional[float], three_d: bool) -> None:
    """The curvature comb: at each sample the normal scaled by −κ (pointing away from the
    centre of curvature), its tips joined."""
    a, b = curve.domain
    t = np.linspace(a, b, samples)
    d1 = curve(t, 1)
    d2 = curve(t, 2)
    k = curve.curvature(t)
    speed = np.linalg.norm(d1, axis=1)
    tangent = d1 / np.where(speed > 0, speed, 1)[:, None]
    normal = d2 - (np.sum(d2 * tangent, axis=1))[:, None] * tangent
    size = np.linalg.norm(normal, axis=1)
    normal = normal / np.where(size > 0, size, 1)[:, None]
    p = curve(t)
    if scale is None:
        extent = np.ptp(p, axis=0).max() if len(p) else 1.0
        scale = 0.2 * extent / max(float(np.max(np.abs(k))), 1e-300)
    tips = p - scale * k[:, None] * normal
    pts = p if three_d else p[:, :2]
    tips = tips if three_d else tips[:, :2]
    for q, r in zip(pts, tips):
        ax.plot(*np.stack([q, r]).T, color="0.6", linewidth=0.6)
    ax.plot(*tips.T, color="0.4", linewidth=0.8, label="curvature comb")


def plot(
    obj: Any,
    ax: Any = None,
    *,
    control_polygon: bool = True,
    comb: bool = False,
    comb_scale: Optional[float] = None,
    samples: int = 200,
    **style: Any,
) -> Any:
    """Draws ``obj`` with matplotlib into ``ax`` (default: a new figure's axes, 3-D for
    3-D shapes) and returns the axes.

    * a curve: its polyline (``style`` goes to ``ax.plot``: ``color``, ``linewidth``,
      ``label`` …), its control polygon (B-spline, NURBS, Bézier kinds; ``control_polygon``)
      and, with ``comb=True``, its curvature comb: the normal scaled by the curvature at
      ``samples`` parameters (``comb_scale``: length per unit curvature, default a fifth of
      the curve's extent at the largest curvature);
    * a ``BFunction``: B(t) on [0, 1];
    * a surface: its mesh (``plot_trisurf``); a ``Mesh`` likewise;
    * a list or tuple: each item into the same axes.

    2-D curves are drawn with equal axes. Raises ``ImportError`` naming matplotlib when it
    is not installed."""
    plt = _pyplot()
    if isinstance(obj, (list, tuple)):
        for item in obj:
            ax = plot(item, ax, control_polygon=control_polygon, comb=comb, comb_scale=comb_scale, samples=samples, **style)
        return ax
    if isinstance(obj, BFunction):
        if ax is None:
            ax = plt.figure().add_subplot()
        t = np.linspace(0.0, 1.0, samples)
        ax.plot(t, obj(t), label=style.pop("label", obj.document.get("type")), **style)
        ax.set_xlabel("t")
        ax.set_ylabel("B(t)")
        return ax
    if isinstance(obj, (_native.Surface, _native.Mesh)):
        mesh = obj.tessellate(density=32) if isinstance(obj, _native.Surface) else obj
        if ax is None:
            ax = plt.figure().add_subplot(projection="3d")
        v = mesh.vertices
        ax.plot_trisurf(v[:, 0], v[:, 1], v[:, 2], triangles=mesh.faces, **({"color": "#4c8cd9"} | style))
        return ax
    if not isinstance(obj, _native.Curve):
        raise TypeError(f"plot draws curves, surfaces, meshes and B-functions, not {type(obj).__name__}")
    three_d = obj.dimension >= 3
    if ax is None:
        ax = plt.figure().add_subplot(projection="3d") if three_d else plt.figure().add_subplot()
    points = obj.tessellate()
    if obj.closed:
        points = np.vstack([points, points[:1]])
    if obj.dimension == 1:
        t = np.linspace(*obj.domain, len(points))
        ax.plot(t, points[:, 0], **style)
        return ax
    coords = points if three_d else points[:, :2]
    ax.plot(*coords[:, : (3 if three_d else 2)].T, **style)
    if control_polygon:
        try:
            cp = obj.control_points
        except AttributeError:
            cp = None
        if cp is not None:
            cp = cp[:, : (3 if three_d else 2)]
            ax.plot(*cp.T, "o--", color="0.5", linewidth=0.8, markersize=3, label="control polygon")
    if comb:
        _comb(obj, ax, samples, comb_scale, three_d)
    if not three_d:
        ax.set_aspect("equal", adjustable="datalim")
    return ax
