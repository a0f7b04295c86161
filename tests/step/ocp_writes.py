"""STEP files that OpenCASCADE writes come back into splinekit with the same geometry.

OCP builds shapes — a B-spline curve and surface, rational ones (a NURBS circle, a NURBS
sphere patch), a surface of revolution, a surface of linear extrusion, a trimmed face (a
plate with a round hole), a box — and writes each with STEPControl_Writer. splinekit
converts every file to a JSON document (`splinekit convert F.step -o F.json`, which must
succeed with no entity left unread: no "not converted" warning), then evaluates each imported object at
parameters spread over OpenCASCADE's bounds of the matching edge or face. Every OCC edge
and face must be matched by one imported object whose points agree within 1e-9 of the
shape's size; trimmed faces must also agree with OCC's face classifier on which of the
sampled parameters lie inside the face, and the faces of AREA_CHECKED have OCC's area
(BRepGProp) within 1e-3 of splinekit's (its imported document's trimmed region
integrated with splinekit's own |S_u × S_v|; 400 rows are accurate to a few 1e-4 where a
loop has a vertical tangent).

usage: ocp_writes.py PATH/TO/splinekit WORKDIR
Prints one line per shape and 'N passed, M failed'; exit 1 on any failure.
"""
import json
import math
import os
import subprocess
import sys

from OCP.BRepAdaptor import BRepAdaptor_Curve, BRepAdaptor_Surface
from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakeFace
from OCP.BRepClass import BRepClass_FaceClassifier
from OCP.BRepPrimAPI import (BRepPrimAPI_MakeBox, BRepPrimAPI_MakeCone, BRepPrimAPI_MakeCylinder, BRepPrimAPI_MakeSphere,
                             BRepPrimAPI_MakeTorus)
from OCP.BRepGProp import BRepGProp
from OCP.GProp import GProp_GProps
from OCP.BRepTools import BRepTools
from OCP.GC import GC_MakeCircle
from OCP.Geom import Geom_SphericalSurface, Geom_SurfaceOfLinearExtrusion, Geom_SurfaceOfRevolution
from OCP.GeomAPI import GeomAPI_PointsToBSpline, GeomAPI_PointsToBSplineSurface
from OCP.GeomConvert import GeomConvert
from OCP.Geom import Geom_RectangularTrimmedSurface
from OCP.IFSelect import IFSelect_RetDone
from OCP.STEPControl import STEPControl_AsIs, STEPControl_Writer
from OCP.OCP.collections import Array1_gp_Pnt as TColgp_Array1OfPnt, Array2_gp_Pnt as TColgp_Array2OfPnt
from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE, TopAbs_IN, TopAbs_OUT
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS
from OCP.gp import gp_Ax1, gp_Ax2, gp_Ax3, gp_Dir, gp_Pnt, gp_Pnt2d

from face_checks import region_area
from verdicts import tally

SAMPLES = 12


def bspline_curve():
    pts = TColgp_Array1OfPnt(1, 7)
    for i in range(7):
        pts.SetValue(i + 1, gp_Pnt(i, math.sin(i), 0.3 * i * i))
    return GeomAPI_PointsToBSpline(pts).Curve()


def bspline_surface():
    net = TColgp_Array2OfPnt(1, 5, 1, 6)
    for i in range(5):
        for j in range(6):
            net.SetValue(i + 1, j + 1, gp_Pnt(i, j, math.sin(i) * math.cos(j)))
    return GeomAPI_PointsToBSplineSurface(net).Surface()


def shapes():
    """(name, TopoDS shape) pairs."""
    circle = GC_MakeCircle(gp_Ax2(gp_Pnt(1, 2, 3), gp_Dir(0, 0.6, 0.8)), 2.5).Value()
    nurbs_circle = GeomConvert.CurveToBSplineCurve_s(circle)
    sphere = Geom_SphericalSurface(gp_Ax3(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 2.0)
    patch = GeomConvert.SurfaceToBSplineSurface_s(Geom_RectangularTrimmedSurface(sphere, 0.2, 1.4, -0.5, 0.7))
    profile = bspline_curve()
    revolution = Geom_SurfaceOfRevolution(profile, gp_Ax1(gp_Pnt(0, 0, -1), gp_Dir(0, 0, 1)))
    extrusion = Geom_SurfaceOfLinearExtrusion(profile, gp_Dir(0.2, 0.3, 1.0))
    plate = BRepPrimAPI_MakeBox(4.0, 3.0, 0.5).Shape()
    hole = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(2, 1.5, -1), gp_Dir(0, 0, 1)), 0.8, 3.0).Shape()
    return [
        ("bspline_curve", BRepBuilderAPI_MakeEdge(bspline_curve()).Edge()),
        ("nurbs_circle", BRepBuilderAPI_MakeEdge(nurbs_circle).Edge()),
        ("bspline_surface", BRepBuilderAPI_MakeFace(bspline_surface(), 1e-7).Face()),
        ("nurbs_sphere_patch", BRepBuilderAPI_MakeFace(patch, 1e-7).Face()),
        ("revolution", BRepBuilderAPI_MakeFace(revolution, 0.0, 2.0 * math.pi, 0.0, 1.0, 1e-7).Face()),
        ("extrusion", BRepBuilderAPI_MakeFace(extrusion, 0.0, 1.0, -1.0, 2.0, 1e-7).Face()),
        ("plate_with_hole", BRepAlgoAPI_Cut(plate, hole).Shape()),
        ("box", BRepPrimAPI_MakeBox(gp_Pnt(-1, -2, 0.5), 1.0, 2.0, 3.0).Shape()),
        # Quadrics in a tilted placement, whole and in part (faces trimmed by angles; the
        # whole sphere is one face bounded by a vertex loop).
        ("sphere", BRepPrimAPI_MakeSphere(PLACEMENT, 1.5).Shape()),
        ("sphere_part", BRepPrimAPI_MakeSphere(PLACEMENT, 1.5, -0.4, 1.0, 4.0).Shape()),
        ("cone", BRepPrimAPI_MakeCone(PLACEMENT, 2.0, 0.5, 3.0, 5.0).Shape()),
        ("cone_to_apex", BRepPrimAPI_MakeCone(PLACEMENT, 1.2, 0.0, 2.0).Shape()),
        ("torus", BRepPrimAPI_MakeTorus(PLACEMENT, 3.0, 1.0).Shape()),
        ("torus_part", BRepPrimAPI_MakeTorus(PLACEMENT, 3.0, 1.0, 0.3, 2.0, 4.5).Shape()),
        # Around the tube from v = −0.6 to 0.9: the face's loops cross the seam v = 0.
        ("torus_across_seam", BRepPrimAPI_MakeTorus(PLACEMENT, 3.0, 1.0, -0.6, 0.9, 4.5).Shape()),
    ]


# The shapes whose faces' areas are compared (OCC's BRepGProp against splinekit's
# integration of its imported document).
AREA_CHECKED = ("sphere", "sphere_part", "cone", "cone_to_apex", "torus", "torus_part", "torus_across_seam",
                "plate_with_hole")

PLACEMENT = gp_Ax2(gp_Pnt(1, -2, 0.5), gp_Dir(0, 0.6, 0.8), gp_Dir(1, 0, 0))


def write(shape, path):
    w = STEPControl_Writer()
    w.Transfer(shape, STEPControl_AsIs)
    if w.Write(path) != IFSelect_RetDone:
        raise RuntimeError(f"OCC could not write {path}")


def run(binary, args, stdin=None):
    r = subprocess.run([binary] + args, capture_output=True, text=True, input=stdin)
    if r.returncode != 0:
        raise RuntimeError(f"splinekit {' '.join(args[:1])}: {r.stderr.strip()}")
    return r


# Samples of each pcurve piece where a brep face's loops become a trimmed face's polygons.
LOOP_SAMPLES = 400


def sampled_pcurves(binary, brep):
    """LOOP_SAMPLES + 1 points of every pcurve of the brep, by one `eval` of a scene of
    them all (one call per pcurve took minutes on a box in a debug build)."""
    pcurves = [use["pcurve"] for face in brep["faces"] for lp in face["loops"] for use in lp]
    if not pcurves:
        return []
    scene = {"type": "scene", "objects": [{"shape": c} for c in pcurves]}
    r = run(binary, ["eval", "-", "--samples", str(LOOP_SAMPLES + 1)], json.dumps(scene))
    return [o["points"] for o in json.loads(r.stdout)["objects"]]


def loop_polygon(sampled):
    """A brep face's loop (its pcurve pieces' samples, in order) as one closed degree-1
    B-spline through LOOP_SAMPLES points of each piece, within (size/LOOP_SAMPLES)² of the
    pcurves."""
    points = []
    for piece in sampled:
        points.extend(piece[:-1])
    points.append(points[0])
    n = len(points)
    knots = [0.0] + [float(k) for k in range(n)] + [float(n - 1)]
    return {"type": "bspline", "degree": 1, "knots": knots, "control_points": points}


def brep_faces(binary, brep):
    """A brep document's faces as trimmed documents, one per face (OpenCASCADE's explorer
    lists faces, splinekit reads a shell of them as one brep)."""
    sampled = iter(sampled_pcurves(binary, brep))
    faces = []
    for face in brep["faces"]:
        doc = {"type": "trimmed", "surface": face["surface"]}
        loops = [loop_polygon([next(sampled) for _ in lp]) for lp in face["loops"]]
        if loops:
            doc["outer"] = loops[0]
            if len(loops) > 1:
                doc["holes"] = loops[1:]
        faces.append(doc)
    return faces


def imported_objects(binary, step, out):
    r = run(binary, ["convert", step, "-o", out])
    doc = json.load(open(out))
    objects = doc["objects"] if doc.get("type") == "scene" else [{"shape": doc}]
    # A part used again (`instance_of`) is its first use's shape.
    shapes = [o["shape"] if "shape" in o else objects[o["instance_of"]]["shape"] for o in objects]
    expanded = []
    for s in shapes:
        expanded.extend(brep_faces(binary, s) if s.get("type") == "brep" else [s])
    return expanded, r.stderr


def occ_edges(shape):
    e = TopExp_Explorer(shape, TopAbs_EDGE)
    while e.More():
        yield TopoDS.Edge(e.Current())
        e.Next()


def occ_faces(shape):
    e = TopExp_Explorer(shape, TopAbs_FACE)
    while e.More():
        yield TopoDS.Face(e.Current())
        e.Next()


def edge_samples(edge):
    c = BRepAdaptor_Curve(edge)
    a, b = c.FirstParameter(), c.LastParameter()
    ts = [a + (b - a) * (k + 0.5) / SAMPLES for k in range(SAMPLES)]
    return ts, [tuple(c.Value(t).Coord()) for t in ts]


def face_samples(face):
    s = BRepAdaptor_Surface(face)
    u0, u1, v0, v1 = BRepTools.UVBounds_s(face)
    uv = [(u0 + (u1 - u0) * (i + 0.5) / SAMPLES, v0 + (v1 - v0) * (j + 0.5) / SAMPLES)
          for i in range(SAMPLES) for j in range(SAMPLES)]
    points = [tuple(s.Value(u, v).Coord()) for u, v in uv]
    classifier = BRepClass_FaceClassifier()
    inside = []
    for u, v in uv:
        classifier.Perform(face, gp_Pnt2d(u, v), 1e-9)
        state = classifier.State()
        inside.append(True if state == TopAbs_IN else False if state == TopAbs_OUT else None)
    return uv, points, inside


def evaluate(binary, doc, params):
    at = ",".join(f"{p[0]!r}:{p[1]!r}" if isinstance(p, tuple) else repr(p) for p in params)
    r = run(binary, ["eval", "-", "--at", at], stdin=json.dumps(doc))
    return json.loads(r.stdout)


def size_of(points):
    return max(1e-300, math.dist([min(p[k] for p in points) for k in range(3)], [max(p[k] for p in points) for k in range(3)]))


def pad3(p):
    return tuple(p) + (0.0,) * (3 - len(p))


def project(binary, workdir, doc, points):
    """splinekit's nearest points of `doc` to `points`: ((u, v), distance) each."""
    path = os.path.join(workdir, "points.json")
    json.dump([list(p) for p in points], open(path, "w"))
    r = run(binary, ["project", "-", "--points", path], stdin=json.dumps(doc))
    return [((q["nearest"]["u"], q["nearest"]["v"]), q["nearest"]["distance"]) for q in json.loads(r.stdout)["projections"]]


CURVE_TYPES = ("bezier", "rational_bezier", "bspline", "nurbs", "line", "circle", "ellipse")


def match_curve(binary, docs, used, params, points):
    """The unused curve document whose points at OCC's parameters are nearest (splinekit
    keeps the parameters of splines and lines)."""
    best = (math.inf, None, None)
    for i, doc in enumerate(docs):
        if i in used or doc["type"] not in CURVE_TYPES:
            continue
        got = evaluate(binary, doc, params)
        worst = max(math.dist(pad3(q), p) for q, p in zip(got["points"], points))
        best = min(best, (worst, i, None), key=lambda b: b[0])
    return best


def match_face(binary, workdir, docs, used, points, inside):
    """The unused surface document nearest to OCC's points inside the face, with the
    number of points whose inside/outside it disagrees on. Planes, cylinders and
    extrusions come back reparametrised, so points are compared through splinekit's
    projection: every point OCC finds inside the face must lie on the document and inside
    its trim; every point OCC finds outside but that lies on the document's surface must be
    outside its trim."""
    best = (math.inf, math.inf, None)
    limit = 1e-9 * size_of(points)
    # Both readers list a file's faces in much the same order: the documents are tried
    # from the one after the last matched, and the first that matches within the limit
    # with no disagreement is taken (each try is two debug-build CLI calls).
    start = max(used, default=-1) + 1
    for i in [(start + k) % len(docs) for k in range(len(docs))]:
        doc = docs[i]
        if i in used or doc["type"] in CURVE_TYPES:
            continue
        found = project(binary, workdir, doc, points)
        got = evaluate(binary, doc, [q for q, _ in found])
        flags = got.get("inside", [True] * len(found))
        worst = max((d for (_, d), occ in zip(found, inside) if occ), default=math.inf)
        wrong = sum(1 for (_, d), occ, ours in zip(found, inside, flags)
                    if occ is not None and (occ or d <= limit) and occ != ours)
        best = min(best, (worst, wrong, i))
        if worst <= limit and wrong == 0:
            break
    return best


def run_json(binary, args, doc):
    return json.loads(run(binary, args, stdin=json.dumps(doc)).stdout)


def splinekit_area(binary, doc):
    """The area of an imported surface document by splinekit's own evaluation: its
    trimmed region (the loops, 2048 points each by `splinekit eval`, inside the domain's
    rectangle when there is no outer loop) integrated by face_checks.region_area, with
    |S_u × S_v| from `splinekit eval --derivatives 1` (in batches of 2000 parameters)."""
    surface = doc["surface"] if doc["type"] == "trimmed" else doc
    loops = []
    if doc["type"] == "trimmed":
        for l in ([doc["outer"]] if "outer" in doc else []) + doc.get("holes", []):
            pts = run_json(binary, ["eval", "-", "--samples", "2049"], l)["points"][:-1]
            loops.append([tuple(p) for p in pts])
    if doc["type"] != "trimmed" or "outer" not in doc:
        corners = run_json(binary, ["eval", "-", "--grid", "2,2"], surface)["params"]
        (u0, v0), (u1, v1) = corners[0], corners[-1]
        loops.insert(0, [(u0, v0), (u1, v0), (u1, v1), (u0, v1)])

    def jacobians(nodes):
        out = []
        for k in range(0, len(nodes), 2000):
            batch = nodes[k:k + 2000]
            at = ",".join(f"{u!r}:{v!r}" for u, v in batch)
            got = run_json(binary, ["eval", "-", "--at", at, "--derivatives", "1"], surface)["partials"]
            for a, b in zip(got["u"], got["v"]):
                c = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
                out.append(math.sqrt(sum(x * x for x in c)))
        return out

    return region_area(jacobians, loops, rows=400)


def occ_area(face):
    props = GProp_GProps()
    BRepGProp.SurfaceProperties_s(face, props, 1e-10)
    return props.Mass()


def judge(binary, workdir, name, shape):
    step = os.path.join(workdir, f"{name}.step")
    write(shape, step)
    docs, notes = imported_objects(binary, step, os.path.join(workdir, f"{name}.json"))
    used, results = set(), []
    faces = list(occ_faces(shape))
    # Faces first; edges only of shapes without faces (a face's edges are its loops).
    items = [("face", f) for f in faces] or [("curve", e) for e in occ_edges(shape)]
    if len(docs) != len(items):
        return [(False, f"{name}: splinekit imported {len(docs)} objects for OCC's {len(items)} ({notes.strip()})")]
    if "not converted" in notes:
        # Every entity of these files is read: a warning is an entity left behind.
        return [(False, f"{name}: splinekit left entities unread: {notes.strip()}")]
    for kind, item in items:
        if kind == "curve":
            params, points = edge_samples(item)
            worst, index, _ = match_curve(binary, docs, used, params, points)
            wrong, note = 0, ""
        else:
            _, points, inside = face_samples(item)
            worst, wrong, index = match_face(binary, workdir, docs, used, points, inside)
            note = f", inside/outside disagreements {wrong} of {len(points)}"
            if index is not None and name in AREA_CHECKED:
                occ, ours = occ_area(item), splinekit_area(binary, docs[index])
                rel = abs(occ - ours) / occ
                note += f", area OCC {occ:.8g} splinekit {ours:.8g} (rel {rel:.1e}, limit 1e-3)"
                wrong += rel > 1e-3
        limit = 1e-9 * size_of(points)
        if index is None:
            results.append((False, f"{name}: no imported object matches an OCC {kind}"))
            continue
        used.add(index)
        results.append((worst <= limit and wrong == 0, f"{name}: {docs[index]['type']} vs OCC {kind}, {len(points)} "
                        f"points, max distance {worst:.2e} (limit {limit:.2e}){note}"))
    return results


def main(binary, workdir):
    os.makedirs(workdir, exist_ok=True)
    return tally((name, lambda name=name, shape=shape: judge(binary, workdir, name, shape)) for name, shape in shapes())


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
