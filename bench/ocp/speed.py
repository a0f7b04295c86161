"""The three query benchmarks of issue 14 side by side in one run: splinekit (in process,
the example crates/splinekit/examples/query_speed.rs built with --release) and
OpenCASCADE (through OCP), medians of the same number of repeats, and their ratios.

Usage: python speed.py PATH/TO/query_speed [--repeats N]
Run with the venv of .ci/install-ocp.sh. The shapes are those of queries.py and
benches/queries.rs: 10⁴ projections onto the wavy bicubic 8 × 8 patch, all intersections
of two cubic B-splines with 100 control points each, torus (R 3, r 1) ∩ cylinder (radius
0.5 about x = 3). OpenCASCADE's projections run in a Python loop over one initialised
GeomAPI_ProjectPointOnSurf (the loop's own cost is measured and subtracted).

The curvo ratios of the same shapes (curve-curve intersection and the projections; curvo
has no surface-surface intersection) come from bench/peers/run.sh, whose src/bin/queries.rs
times splinekit beside curvo 0.3 in one process; bench/peers is a separate cargo project so
that curvo's dependencies stay out of the workspace and CI.
"""

import json
import subprocess
import sys
import time

from OCP.gp import gp_Ax3, gp_Dir, gp_Pnt
from OCP.Geom import Geom_CylindricalSurface, Geom_ToroidalSurface
from OCP.Geom2dAPI import Geom2dAPI_InterCurveCurve
from OCP.GeomAPI import GeomAPI_IntSS, GeomAPI_ProjectPointOnSurf

from queries import bicubic_surface, query_points, wavy_curves


def median(repeats, f):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    times.sort()
    return times[len(times) // 2]


def main():
    binary = sys.argv[1]
    repeats = int(sys.argv[sys.argv.index("--repeats") + 1]) if "--repeats" in sys.argv else 11
    ours = json.loads(subprocess.run([binary, str(repeats)], capture_output=True, text=True, check=True).stdout)

    _, surface = bicubic_surface()
    pts = [gp_Pnt(*p) for p in query_points(10_000, (-1.0, -1.0, -2.0), (8.0, 8.0, 2.0))]
    projector = GeomAPI_ProjectPointOnSurf()
    u0, u1, v0, v1 = surface.Bounds()

    def project():
        projector.Init(surface, u0, u1, v0, v1)
        for p in pts:
            projector.Perform(p)
            projector.NbPoints()

    def loop_only():
        for p in pts:
            p.X()
            p.Y()

    occ_project = max(median(repeats, project) - median(repeats, loop_only), 1e-9)

    (_, ca), (_, cb) = wavy_curves()
    found = []
    occ_curves = median(repeats, lambda: found.append(Geom2dAPI_InterCurveCurve(ca, cb, 1e-9).NbPoints()))

    z = gp_Dir(0, 0, 1)
    torus = Geom_ToroidalSurface(gp_Ax3(gp_Pnt(0, 0, 0), z), 3.0, 1.0)
    cylinder = Geom_CylindricalSurface(gp_Ax3(gp_Pnt(3, 0, 0), z), 0.5)
    lines = []
    occ_surfaces = median(repeats, lambda: lines.append(GeomAPI_IntSS(torus, cylinder, 1e-7).NbLines()))

    rows = [
        ("10^4 projections onto a bicubic 8x8 surface", ours["project"], occ_project, ""),
        ("all intersections of two cubic B-splines (100 control points each)", ours["curves"], occ_curves,
         f"{ours['crossings']} vs {found[-1]} points"),
        ("torus-cylinder intersection curve (chord 1e-5 / tolerance 1e-7)", ours["surfaces"], occ_surfaces,
         f"{ours['branches']} branches ({ours['closed']} closed, {ours['branch_points']} points) vs {lines[-1]} lines"),
    ]
    print(f"{'workload':<72} {'splinekit':>11} {'OpenCASCADE':>12} {'OCC/ours':>9}")
    for name, a, b, note in rows:
        print(f"{name:<72} {a * 1e3:>8.2f} ms {b * 1e3:>9.2f} ms {b / a:>8.2f}x  {note}")
    print(f"(medians of {repeats} runs; OCC/ours > 1 means splinekit is faster)")


if __name__ == "__main__":
    main()
