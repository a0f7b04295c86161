"""OpenCASCADE judges the STEP files splinekit writes.

For each STEP file given with its `splinekit convert --report` JSON: OCP's
STEPControl_Reader must read it and transfer every root with no failed entity; then
each named item's transferred geometry is evaluated at the report's STEP parameters and
compared with splinekit's points there: within 1e-9 (relative to the object's size) for
exact forms, within the reported tolerance (plus 1e-9) for approximations.

usage: ocp_judge.py FILE.step REPORT.json [FILE.step REPORT.json ...]
Prints one line per item and 'N passed, M failed' at the end; exit 1 on any failure.
"""
import json
import math
import sys

from OCP.BRep import BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Curve
from OCP.IFSelect import IFSelect_RetDone
from OCP.STEPControl import STEPControl_Reader
from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS, TopoDS_Iterator

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


def evaluator(shape, kind):
    """A function (u, v) -> point of the one face or edge of a transferred item."""
    if kind == "surface":
        e = TopExp_Explorer(shape, TopAbs_FACE)
        surf = BRep_Tool.Surface_s(TopoDS.Face(e.Current()))
        return lambda u, v: surf.Value(u, v)
    e = TopExp_Explorer(shape, TopAbs_EDGE)
    curve = BRepAdaptor_Curve(TopoDS.Edge(e.Current()))
    return lambda t, _v: curve.Value(t)


def judge(path, report_path):
    report = json.load(open(report_path))
    reader, _, _ = transferred(path)
    # The geometric set's elements transfer in order, one sub-shape each.
    shapes = []
    it = TopoDS_Iterator(reader.OneShape())
    while it.More():
        shapes.append(it.Value())
        it.Next()
    if len(shapes) == 1 and len(report["items"]) == 1:
        pass
    elif len(shapes) != len(report["items"]):
        return [(False, f"{path}: {len(shapes)} shapes transferred for {len(report['items'])} items")]
    named = {item["name"]: shape for item, shape in zip(report["items"], shapes)}
    results = []
    for item in report["items"]:
        pts = item["points"]
        size = max(1e-300, math.dist([min(p[k] for p in pts) for k in range(3)], [max(p[k] for p in pts) for k in range(3)]))
        limit = 1e-9 * size if item["form"] != "approximated" else item["tolerance"] + 1e-9 * size
        if item["name"] not in named:
            results.append((False, f"{path}: {item['name']}: no transferred shape of that name"))
            continue
        f = evaluator(named[item["name"]], item["kind"])
        worst = 0.0
        for (u, v), p in zip(item["step_params"], pts):
            q = f(u, v)
            worst = max(worst, math.dist((q.X(), q.Y(), q.Z()), p))
        ok = worst <= limit
        results.append((ok, f"{path}: {item['name']} ({item['form']}): {len(pts)} parameters, max |OCC − splinekit| = {worst:.2e} (limit {limit:.2e})"))
    return results


def main(args):
    return tally(("", lambda path=path, report=report: judge(path, report)) for path, report in zip(args[::2], args[1::2]))


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
