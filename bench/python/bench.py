"""splinekit for Python against scipy, splipy and geomdl: same process, same arrays,
timings including the numpy conversions (best of --repeat runs).

    python bench/python/bench.py [--repeat 3] [--quick]

Workloads (issues 12 and 20): a cubic 3-D B-spline with 1000 control points at 10⁶ sorted
parameters (points; points and 2 derivatives); points at random parameters (10⁶), and with
10⁵ control points at sorted (10⁶) and random (2·10⁴) parameters; the least-squares fit of 10⁶ samples with
1000 control points, and a bicubic 100 × 100 B-spline surface on a 1000 × 1000 grid with
unit normals. Each line prints the time per evaluation and the peer's time as a multiple of
splinekit's; results are checked to agree before they are timed.
"""

import argparse
import time

import numpy as np
import scipy
from scipy.interpolate import BSpline, bisplev, make_lsq_spline

import splinekit as sk

try:
    import splipy
except ImportError:  # splipy is optional
    splipy = None
try:
    from geomdl import BSpline as GeomdlBSpline
except ImportError:  # geomdl is optional
    GeomdlBSpline = None


def best(f, repeat):
    """Smallest wall time of `repeat` calls of f (fewer once 10 s are spent), and its last
    result."""
    times, out = [], None
    for _ in range(repeat):
        start = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - start)
        if sum(times) > 10.0:
            break
    return min(times), out


def report(name, count, ours, peers):
    line = f"{name:<44} splinekit {ours / count * 1e9:8.1f} ns"
    for peer, t in peers:
        line += f" | {peer} {t / count * 1e9:8.1f} ns ({t / ours:5.1f}x)"
    print(line, flush=True)


def clamped_uniform(n, p=3):
    return np.concatenate([[0.0] * p, np.linspace(0.0, 1.0, n - p + 1), [1.0] * p])


def curve_workloads(args):
    rng = np.random.default_rng(1)
    n, m = 1000, args.params
    knots, cp = clamped_uniform(n), rng.normal(size=(n, 3))
    t = np.linspace(0.0, 1.0, m)
    ours, ref = sk.BSpline(knots, cp, 3), BSpline(knots, cp, 3)
    np.testing.assert_allclose(ours(t), ref(t), atol=1e-10)
    t_ours, _ = best(lambda: ours(t), args.repeat)
    peers = [("scipy", best(lambda: ref(t), args.repeat)[0])]
    # splipy and geomdl take microseconds per parameter: timed on every 10th / 100th
    # parameter and scaled to all of them.
    some = t[:: max(1, m // 100_000)]
    if splipy is not None:
        basis = splipy.BSplineBasis(4, knots)
        curve = splipy.Curve(basis, cp)
        np.testing.assert_allclose(curve(some), ref(some), atol=1e-10)
        peers.append(("splipy (10⁵ params, scaled)", best(lambda: curve(some), args.repeat)[0] * m / some.size))
    if GeomdlBSpline is not None:
        g = GeomdlBSpline.Curve()
        g.degree, g.ctrlpts, g.knotvector = 3, cp.tolist(), knots.tolist()
        few = t[:: max(1, m // 10_000)]
        t_few, _ = best(lambda: g.evaluate_list(few.tolist()), 1)
        peers.append(("geomdl (10⁴ params, scaled)", t_few * m / few.size))
    report("curve points, 10⁶ sorted params", m, t_ours, peers)

    ders = ours.derivatives(t, 2)
    for k in range(3):
        np.testing.assert_allclose(ders[:, k], ref(t, k), atol=1e-8, rtol=1e-10)
    t_ours, _ = best(lambda: ours.derivatives(t, 2), args.repeat)
    peers = [("scipy", best(lambda: [ref(t, k) for k in range(3)], args.repeat)[0])]
    if splipy is not None:
        t_some = best(lambda: [curve.derivative(some, k) for k in range(3)], args.repeat)[0]
        peers.append(("splipy (10⁵ params, scaled)", t_some * m / some.size))
    report("curve points + 2 derivatives", m, t_ours, peers)

    # Any order of the parameters, and many control points (issue 20): span search must not
    # walk the knots.
    for n in (1000, 100_000):
        knots, cp = clamped_uniform(n), rng.normal(size=(n, 3))
        ours, ref = sk.BSpline(knots, cp, 3), BSpline(knots, cp, 3)
        for order in ("sorted", "random"):
            count = m if order == "sorted" or n <= 1000 else max(1, m // 50)
            t = np.linspace(0.0, 1.0, count) if order == "sorted" else rng.random(count)
            np.testing.assert_allclose(ours(t), ref(t), atol=1e-10)
            t_ours, _ = best(lambda: ours(t), args.repeat)
            t_ref, _ = best(lambda: ref(t), args.repeat)
            report(f"curve points, {n} cp, {count} {order} params", count, t_ours, [("scipy", t_ref)])


def fit_workload(args):
    rng = np.random.default_rng(2)
    m, n = args.samples, 1000
    x = np.linspace(0.0, 1.0, m)
    y = np.column_stack([np.sin(20 * x), np.cos(17 * x), x**3]) + 1e-3 * rng.normal(size=(m, 3))
    knots = clamped_uniform(n)
    ours = sk.fit(y, 3, params=x, knots=knots)
    ref = make_lsq_spline(x, y, knots, k=3)
    np.testing.assert_allclose(ours.control_points, ref.c, atol=1e-8)
    t_ours, _ = best(lambda: sk.fit(y, 3, params=x, knots=knots), args.repeat)
    t_ref, _ = best(lambda: make_lsq_spline(x, y, knots, k=3), args.repeat)
    report("LSQ fit, 10⁶ samples, 1000 control points", m, t_ours, [("scipy make_lsq_spline", t_ref)])
    t_named, _ = best(lambda: sk.fit(y, 3, n, params="chord", knots="averaged"), args.repeat)
    print(f"{'  (splinekit with chord params, averaged knots)':<44} {t_named * 1e3:8.1f} ms in all")


def surface_workload(args):
    rng = np.random.default_rng(3)
    n, g = 100, args.grid
    knots = clamped_uniform(n)
    cp = rng.normal(size=(n, n, 3))
    u = v = np.linspace(0.0, 1.0, g)
    s = sk.BSplineSurface(knots, knots, cp, 3, 3)

    def fitpack():
        tck = lambda j: (knots, knots, cp[:, :, j].ravel(), 3, 3)
        p = np.stack([bisplev(u, v, tck(j)) for j in range(3)], axis=-1)
        du = np.stack([bisplev(u, v, tck(j), dx=1) for j in range(3)], axis=-1)
        dv = np.stack([bisplev(u, v, tck(j), dy=1) for j in range(3)], axis=-1)
        normal = np.cross(du, dv)
        return p, normal / np.linalg.norm(normal, axis=-1, keepdims=True)

    points, normals = s.points_and_normals(u, v)
    p_ref, n_ref = fitpack()
    np.testing.assert_allclose(points, p_ref, atol=1e-10)
    np.testing.assert_allclose(normals, n_ref, atol=1e-8)
    t_ours, _ = best(lambda: s.points_and_normals(u, v), args.repeat)
    peers = [("scipy bisplev ×9 + numpy", best(fitpack, args.repeat)[0])]
    if splipy is not None:
        surf = splipy.Surface(splipy.BSplineBasis(4, knots), splipy.BSplineBasis(4, knots), cp.transpose(1, 0, 2).reshape(-1, 3))

        def splipy_normals():
            p = surf(u, v)
            normal = np.cross(surf.derivative(u, v, d=(1, 0)), surf.derivative(u, v, d=(0, 1)))
            return p, normal / np.linalg.norm(normal, axis=-1, keepdims=True)

        np.testing.assert_allclose(splipy_normals()[0], points, atol=1e-10)
        peers.append(("splipy", best(splipy_normals, args.repeat)[0]))
    report("surface grid 1000², points + unit normals", g * g, t_ours, peers)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--quick", action="store_true", help="10× smaller workloads (a smoke run)")
    args = ap.parse_args()
    scale = 10 if args.quick else 1
    args.params, args.samples, args.grid = 1_000_000 // scale, 1_000_000 // scale, 1000 // int(np.sqrt(scale))
    print(f"numpy {np.__version__}, scipy {scipy.__version__}, splipy {getattr(splipy, '__version__', '-')}; best of {args.repeat}")
    curve_workloads(args)
    fit_workload(args)
    surface_workload(args)


if __name__ == "__main__":
    main()
