"""OpenCASCADE judges the STEP files splinekit writes.

For each STEP file given with its `splinekit convert --report` JSON: OCP's
STEPControl_Reader must read it and transfer every root with no failed entity; then
each named item's transferred geometry is evaluated at the report's STEP parameters and
compared with splinekit's points there: within 1e-9 (relative to the object's size) for
exact forms, within the reported tolerance (plus 1e-9) for approximations. Faces (trimmed
documents) are also checked for validity, area and inside/outside (face_checks.py).

usage: ocp_judge.py FILE.step REPORT.json [FILE.step REPORT.json ...]
Prints one line per item and 'N passed, M failed' at the end; exit 1 on any failure.
"""
import json
import math
import os
import sys

from OCP.BRep import BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Curve
from OCP.Geom import Geom_ConicalSurface, Geom_RectangularTrimmedSurface
from OCP.IFSelect import IFSelect_RetDone
from OCP.STEPControl import STEPControl_Reader
from OCP.TopAbs import TopAbs_COMPOUND, TopAbs_EDGE, TopAbs_FACE, TopAbs_SHELL
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS, TopoDS_Iterator

from face_checks import check_face
from verdicts import tally


def transferred(path):
    """Reader, model, transient process; fails on read or transfer errors."""
    r = STEPControl_Reader()
    if r.ReadFile(path) != IFSelect_RetDone:
        raise RuntimeError(f"{path}: STEPControl_Reader could not read the file")
    ws = r.WS()
    if not ws.ModelCheckList().IsEmpty(True):
        raise RuntimeError(f"{path}: the model has failed entities when loaded")
    if r.TransferRoots() == 0:
        raise RuntimeError(f"{path}: no root transferred")
    tp = ws.TransferReader().TransientProcess()
    if not tp.CheckList(False).IsEmpty(True):
        raise RuntimeError(f"{path}: failed entities in the transfer")
    return r, ws.Model(), ws.TransferReader()


def occ_v_scale(shape, kind):
    """OpenCASCADE's v per STEP v of an item's surface: 1 / cos α on a cone (OCC's
    Geom_ConicalSurface runs v along the generatrix where ISO 10303-42's CONICAL_SURFACE,
    and so the file's trims and pcurves, use the height; StepToGeom converts them), else 1."""
    if kind not in ("surface", "face"):
        return 1.0
    surf = BRep_Tool.Surface_s(TopoDS.Face(TopExp_Explorer(shape, TopAbs_FACE).Current()))
    while isinstance(surf, Geom_RectangularTrimmedSurface):
        surf = surf.BasisSurface()
    return 1.0 / math.cos(surf.SemiAngle()) if isinstance(surf, Geom_ConicalSurface) else 1.0


def in_occ_parameters(item, scale):
    """The report item with its STEP v (samples, loops, map) in OpenCASCADE's."""
    if scale == 1.0:
        return item
    item = dict(item)
    item["step_params"] = [[u, v * scale] for u, v in item["step_params"]]
    if "loops" in item:
        item["loops"] = [[[u, v * scale] for u, v in l] for l in item["loops"]]
    item["map"] = {"u": item["map"]["u"], "v": [c * scale for c in item["map"]["v"]]}
    return item


def evaluator(shape, kind):
    """A function (u, v) -> point of the one face or edge of a transferred item."""
    if kind in ("surface", "face"):
        e = TopExp_Explorer(shape, TopAbs_FACE)
        surf = BRep_Tool.Surface_s(TopoDS.Face(e.Current()))
        return lambda u, v: surf.Value(u, v)
    e = TopExp_Explorer(shape, TopAbs_EDGE)
    curve = BRepAdaptor_Curve(TopoDS.Edge(e.Current()))
    return lambda t, _v: curve.Value(t)


def items_of(shape):
    """The transferred items: the elements of the (nested) compounds, in order."""
    if shape.ShapeType() != TopAbs_COMPOUND:
        return [shape]
    out = []
    it = TopoDS_Iterator(shape)
    while it.More():
        out.extend(items_of(it.Value()))
        it.Next()
    return out


def judge(path, report_path):
    report = json.load(open(report_path))
    reader, _, _ = transferred(path)
    stem = os.path.basename(path).rsplit(".", 1)[0]
    # The geometric set's elements transfer in order, one sub-shape each (surfaces as
    # faces); faces of trimmed documents come as the shells of the surface model, in order.
    shapes = items_of(reader.OneShape())
    is_face = lambda s: s.ShapeType() == TopAbs_SHELL
    faces = [s for s in shapes if is_face(s)]
    others = [s for s in shapes if not is_face(s)]
    face_items = [i for i in report["items"] if i["kind"] == "face"]
    other_items = [i for i in report["items"] if i["kind"] != "face"]
    if len(faces) != len(face_items) or len(others) != len(other_items):
        return [(False, f"{path}: {len(faces)} faces and {len(others)} other shapes transferred for "
                 f"{len(face_items)} faces and {len(other_items)} other items")]
    named = {item["name"]: shape for item, shape in zip(face_items + other_items, faces + others)}
    results = []
    for item in report["items"]:
        pts = item["points"]
        size = max(1e-300, math.dist([min(p[k] for p in pts) for k in range(3)], [max(p[k] for p in pts) for k in range(3)]))
        limit = 1e-9 * size if item["form"] != "approximated" else item["tolerance"] + 1e-9 * size
        if item["name"] not in named:
            results.append((False, f"{path}: {item['name']}: no transferred shape of that name"))
            continue
        item = in_occ_parameters(item, occ_v_scale(named[item["name"]], item["kind"]))
        f = evaluator(named[item["name"]], item["kind"])
        worst = 0.0
        for (u, v), p in zip(item["step_params"], pts):
            q = f(u, v)
            worst = max(worst, math.dist((q.X(), q.Y(), q.Z()), p))
        ok = worst <= limit
        results.append((ok, f"{path}: {item['name']} ({item['form']}): {len(pts)} parameters, max |OCC − splinekit| = {worst:.2e} (limit {limit:.2e})"))
        if item["kind"] == "face":
            e = TopExp_Explorer(named[item["name"]], TopAbs_FACE)
            results.extend(check_face(stem, item, TopoDS.Face(e.Current())))
    return results


def main(args):
    return tally(("", lambda path=path, report=report: judge(path, report)) for path, report in zip(args[::2], args[1::2]))


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
