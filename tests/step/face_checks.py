"""OpenCASCADE's checks of a face splinekit wrote for a `trimmed` document.

For a transferred face and its report item (the document's loops in the STEP surface's
(u, v), sampled by splinekit from the document's own loop curves):
- BRepCheck_Analyzer finds the face valid;
- its area (BRepGProp.SurfaceProperties, adaptive to 1e-10) agrees with the area of the
  document's trimmed region, integrated here independently: ∫∫ |S_u × S_v| du dv over the
  region inside the outer loop (or the domain) and outside every hole, by rows in v (4000
  midpoints) crossing the loop polygons, Gauss–Legendre along each inside stretch of a
  row, with S_u, S_v from the surface OCC read (whose points the judge has already compared
  with splinekit's); within 1e-5 relative, and within 1e-7 of the closed form where the test
  knows one (CLOSED_FORMS);
- BRepClass_FaceClassifier says IN at every sampled parameter of the report that lies in
  the document's region, OUT at every one outside (parameters within 1e-3 of a loop are
  skipped), and at the named points of CLOSED_FORMS.
"""
import math

from OCP.BRep import BRep_Tool
from OCP.BRepCheck import BRepCheck_Analyzer
from OCP.BRepClass import BRepClass_FaceClassifier
from OCP.BRepGProp import BRepGProp
from OCP.GProp import GProp_GProps
from OCP.TopAbs import TopAbs_IN, TopAbs_OUT
from OCP.gp import gp_Pnt, gp_Pnt2d, gp_Vec

def bessel_j1(x):
    """J₁(x) = Σ (−1)^k (x/2)^(2k+1) / (k! (k+1)!), to full precision for |x| ≤ 2."""
    return sum((-1) ** k * (x / 2) ** (2 * k + 1) / (math.factorial(k) * math.factorial(k + 1)) for k in range(20))


# file stem → item name → (closed-form area, document (u, v) inside, document (u, v) outside)
CLOSED_FORMS = {
    "trimmed_faces": {
        # A 2 × 1 plane without a circular hole of radius 0.25 in (u, v): an ellipse of
        # semi-axes 0.5, 0.25 in space.
        "object 1 (trimmed)": (2.0 - math.pi / 8.0, [(0.1, 0.1), (0.9, 0.5)], [(0.5, 0.5), (0.6, 0.55)]),
        # Cylinder r = 2, h = 3: |S_u × S_v| = r h = 6; (u, v) rectangle [1, 4] × [0.2, 0.8]
        # without a circle of radius 0.2.
        "object 2 (trimmed)": (6.0 * (3.0 * 0.6 - math.pi * 0.04), [(1.5, 0.5), (3.5, 0.3)],
                               [(2.5, 0.5), (0.5, 0.5), (4.5, 0.5)]),
        # Sphere r = 1.5: |S_u × S_v| = r² cos v; [0.5, 2.5] × [−0.6, 0.9] without
        # [1, 1.5] × [0, 0.3].
        "object 3 (trimmed)": (2.25 * (2.0 * (math.sin(0.9) + math.sin(0.6)) - 0.5 * math.sin(0.3)),
                               [(0.7, 0.0), (2.0, 0.5)], [(1.25, 0.15), (3.0, 0.0), (1.0, 1.2)]),
        # Cone r = 1.5, h = 2 ((r (1 − v) cos u, r (1 − v) sin u, h v)): |S_u × S_v| =
        # r L (1 − v), L = √(r² + h²) = 2.5; [1, 4] × [0.2, 0.6] without a circle of radius
        # 0.1 about (2.5, 0.4): r L (3 ∫(1 − v) dv − π 0.1² (1 − 0.4)).
        "object 4 (trimmed)": (1.5 * 2.5 * (3.0 * 0.24 - math.pi * 0.01 * 0.6), [(1.5, 0.3), (3.5, 0.5)],
                               [(2.5, 0.4), (0.5, 0.4), (2.0, 0.7)]),
    },
    # Whole closed surfaces bounded by their seams (no outer loop).
    "natural_bounds": {
        "object 1 (trimmed)": (2.0 * math.pi * 2.0 * 3.0, [(1.0, 0.5), (6.0, 0.1)], []),
        "object 2 (trimmed)": (4.0 * math.pi * 1.5 ** 2, [(1.0, 0.0), (5.0, -1.2)], []),
        "object 3 (trimmed)": (4.0 * math.pi ** 2 * 3.0 * 1.0, [(1.0, 1.0), (6.0, 6.0)], []),
        # π r L, L = √(1.5² + 2²) = 2.5
        "object 4 (trimmed)": (math.pi * 1.5 * 2.5, [(1.0, 0.5), (6.0, 0.1)], []),
        # the cylinder without a circle of radius 0.2 about (2.5, 0.5)
        "object 5 (trimmed)": (6.0 * (2.0 * math.pi - math.pi * 0.04), [(1.0, 0.5)], [(2.5, 0.5), (2.6, 0.45)]),
    },
    # Loops across seams (tests/step/shapes/seam_faces.json). On the torus (R = 3, r = 1,
    # |S_u × S_v| = r (R + r cos v)) a disc of radius ρ about (u₀, v₀) has the area
    # r R π ρ² + r² cos v₀ · 2π ρ J₁(ρ).
    "seam_faces": {
        # about (1, 0): across the tube's seam v = 0
        "object 1 (trimmed)": (3.0 * math.pi * 0.25 + 2.0 * math.pi * 0.5 * bessel_j1(0.5),
                               [(1.0, 6.1), (1.2, 0.2)], [(1.0, 0.7), (1.0, 5.5)]),
        # about (0, 2): across the seam u = 0
        "object 2 (trimmed)": (3.0 * math.pi * 0.25 + math.cos(2.0) * 2.0 * math.pi * 0.5 * bessel_j1(0.5),
                               [(6.1, 2.0), (0.2, 2.1)], [(5.6, 2.0), (0.0, 2.7)]),
        # cylinder r = 2, h = 3: [−1, 1] × [0.2, 0.8] without a circle of radius 0.1 about
        # (0, 0.5), both across the seam u = 0
        "object 3 (trimmed)": (6.0 * (1.2 - math.pi * 0.01), [(6.0, 0.5), (0.5, 0.3)],
                               [(0.0, 0.5), (6.2, 0.5), (1.5, 0.5)]),
    },
    "trimmed_surface": {
        "object 1 (trimmed)": (None, [(0.5, 0.2), (0.2, 0.5)], [(0.5, 0.45), (0.02, 0.5)]),
    },
}

GAUSS = [(-0.9602898564975363, 0.1012285362903763), (-0.7966664774136267, 0.2223810344533745),
         (-0.5255324099163290, 0.3137066458778873), (-0.1834346424956498, 0.3626837833783620),
         (0.1834346424956498, 0.3626837833783620), (0.5255324099163290, 0.3137066458778873),
         (0.7966664774136267, 0.2223810344533745), (0.9602898564975363, 0.1012285362903763)]


def jacobian(surface, u, v):
    p, du, dv = gp_Pnt(), gp_Vec(), gp_Vec()
    surface.D1(u, v, p, du, dv)
    return du.Crossed(dv).Magnitude()


def polygons(item):
    """The region's loops as closed polygons in STEP (u, v); the domain's rectangle (from
    the sampled grid's corners) when the document has no outer loop."""
    loops = [list(map(tuple, l)) for l in item["loops"]]
    if not item["has_outer"]:
        us = [p[0] for p in item["step_params"]]
        vs = [p[1] for p in item["step_params"]]
        loops.insert(0, [(min(us), min(vs)), (max(us), min(vs)), (max(us), max(vs)), (min(us), max(vs))])
    return loops


def crossings(loops, v):
    xs = []
    for poly in loops:
        n = len(poly)
        for k in range(n):
            (u0, v0), (u1, v1) = poly[k], poly[(k + 1) % n]
            if (v0 <= v < v1) or (v1 <= v < v0):
                xs.append(u0 + (v - v0) * (u1 - u0) / (v1 - v0))
    return sorted(xs)


def inside(loops, u, v):
    """Even–odd rule: inside the outer loop and outside every hole."""
    return sum(1 for x in crossings(loops, v) if x < u) % 2 == 1


def distance_to_loops(loops, u, v):
    best = math.inf
    for poly in loops:
        n = len(poly)
        for k in range(n):
            (a, b), (c, d) = poly[k], poly[(k + 1) % n]
            ex, ey = c - a, d - b
            t = max(0.0, min(1.0, ((u - a) * ex + (v - b) * ey) / max(1e-300, ex * ex + ey * ey)))
            best = min(best, math.hypot(u - a - t * ex, v - b - t * ey))
    return best


def region_area(jacobians, loops, rows=4000):
    """∫∫ J du dv over the even–odd region of `loops` (closed polygons in (u, v)): midpoint
    rows in v, 8-point Gauss–Legendre along each inside stretch; `jacobians` maps a list of
    (u, v) to the list of |S_u × S_v| there (evaluated in one batch)."""
    vs = [p[1] for poly in loops for p in poly]
    v0, v1 = min(vs), max(vs)
    h = (v1 - v0) / rows
    # Each polygon edge adds its crossing to the rows whose midpoint it spans.
    row_crossings = [[] for _ in range(rows)]
    for poly in loops:
        n = len(poly)
        for k in range(n):
            (a0, b0), (a1, b1) = poly[k], poly[(k + 1) % n]
            lo, hi = min(b0, b1), max(b0, b1)
            first = max(0, math.floor((lo - v0) / h - 0.5))
            for j in range(first, rows):
                v = v0 + (j + 0.5) * h
                if v >= hi:
                    break
                if v >= lo:
                    row_crossings[j].append(a0 + (v - b0) * (a1 - a0) / (b1 - b0))
    nodes, weights = [], []
    for j, xs in enumerate(row_crossings):
        v = v0 + (j + 0.5) * h
        xs.sort()
        for a, b in zip(xs[::2], xs[1::2]):
            pieces = max(1, math.ceil((b - a) / ((v1 - v0) / 8)))
            w = (b - a) / pieces
            for k in range(pieces):
                mid = a + (k + 0.5) * w
                for x, c in GAUSS:
                    nodes.append((mid + 0.5 * w * x, v))
                    weights.append(c * 0.5 * w * h)
    return sum(w * j for w, j in zip(weights, jacobians(nodes)))


def copies(item, u, v):
    """(u, v) and, along each periodic direction of the surface (the report's periods in
    STEP parameters), its copies one period to either side: loops may cross a seam."""
    periods = item.get("periods") or [None, None]
    shifts = [[0.0] + ([-t, t] if t else []) for t in periods]
    return [(u + a, v + b) for a in shifts[0] for b in shifts[1]]


def inside_somewhere(item, loops, u, v):
    return any(inside(loops, *c) for c in copies(item, u, v))


def occ_inside(item, face, u, v):
    """OCC's classifier finds (u, v), or a copy of it a period away, IN the face (its
    pcurves may lie across the seam, where the classifier does not wrap)."""
    return any(state(face, *c) == TopAbs_IN for c in copies(item, u, v))


def state(face, u, v):
    c = BRepClass_FaceClassifier()
    c.Perform(face, gp_Pnt2d(u, v), 1e-9)
    return c.State()


def check_face(stem, item, face):
    """[(ok, line), ...] for one face."""
    name, out = item["name"], []
    out.append((BRepCheck_Analyzer(face).IsValid(), f"{stem}: {name}: BRepCheck_Analyzer finds the face valid"))
    props = GProp_GProps()
    BRepGProp.SurfaceProperties_s(face, props, 1e-10)
    occ = props.Mass()
    surface = BRep_Tool.Surface_s(face)
    loops = polygons(item)
    ours = region_area(lambda nodes: [jacobian(surface, u, v) for u, v in nodes], loops)
    closed, ins, outs = CLOSED_FORMS.get(stem, {}).get(name, (None, [], []))
    rel = abs(occ - ours) / max(abs(ours), 1e-300)
    line = f"{stem}: {name}: area OCC {occ:.10g}, integrated over the document's region {ours:.10g} (rel {rel:.1e}, limit 1e-5)"
    ok = rel <= 1e-5
    if closed is not None:
        rel_closed = abs(occ - closed) / closed
        line += f", closed form {closed:.10g} (rel {rel_closed:.1e}, limit 1e-7)"
        ok = ok and rel_closed <= 1e-7
    out.append((ok, line))
    m = item["map"]
    step = lambda p: (m["u"][0] * p[0] + m["u"][1], m["v"][0] * p[1] + m["v"][1])
    wrong, checked = [], 0
    for uv, expected in [(step(p), True) for p in ins] + [(step(p), False) for p in outs]:
        checked += 1
        if occ_inside(item, face, *uv) != expected:
            wrong.append((uv, expected))
    span = max(max(p[0] for p in item["step_params"]) - min(p[0] for p in item["step_params"]),
               max(p[1] for p in item["step_params"]) - min(p[1] for p in item["step_params"]))
    for uv in map(tuple, item["step_params"]):
        if min(distance_to_loops(loops, *c) for c in copies(item, *uv)) < 1e-3 * span:
            continue
        expected = inside_somewhere(item, loops, *uv)
        checked += 1
        if occ_inside(item, face, *uv) != expected:
            wrong.append((uv, expected))
    out.append((not wrong, f"{stem}: {name}: BRepClass_FaceClassifier agrees with the document's region at "
                f"{checked - len(wrong)} of {checked} parameters{'' if not wrong else f' (first wrong: {wrong[0]})'}"))
    return out
