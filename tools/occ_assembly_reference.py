#!/usr/bin/env python3
"""OpenCASCADE's reading of the product structure and colours of real STEP files.

For each STEP file it reads the file with STEPCAFControl_Reader (XCAF: names, colours,
assembly structure; B-rep only, `read.step.tessellated` = 0 as in /work/realstep's
occ_reference.py) and walks the assembly tree from each free shape. For every leaf
occurrence (a shape label that is not an assembly) it records:

  - path: the names of the labels from the free shape through each component to the part;
  - part: the name of the referred part label;
  - solids: how many solids the part's shape holds, vertices: how many distinct vertices
    (more than the file's VERTEX_POINTs where OCC's shape healing split edges);
  - rotation (row-major 3x3) and translation (mm) of the accumulated location;
  - vertex_box: the box of the part's vertices moved by that location (mm), which
    splinekit's placed VERTEX_POINT boxes are compared with.

and per file the box of all placed vertices, and the colours XCAF gives: the surface (or
generic) colour of each part label and how many of its faces carry a colour of their own,
in sRGB (OCC takes COLOUR_RGB's numbers as sRGB and stores them linear; Quantity_TOC_sRGB
gives the file's numbers back, rounded to 1e-9).

Writes crates/splinekit-step/tests/data/real/occ_assembly.json (keyed by file name).

Usage:  /work/ocpvenv/bin/python tools/occ_assembly_reference.py [--dir /work/realstep] [-o OUT]
Needs:  OCP (pip install cadquery-ocp-novtk==8.0.1.1.0).
"""
import argparse
import glob
import json
import os

from OCP.BRep import BRep_Tool
from OCP.Interface import Interface_Static
from OCP.Quantity import Quantity_Color, Quantity_TOC_sRGB
from OCP.STEPCAFControl import STEPCAFControl_Reader
from OCP.TCollection import TCollection_ExtendedString
from OCP.TDF import TDF_Label
from OCP.TDataStd import TDataStd_Name
from OCP.TDocStd import TDocStd_Document
from OCP.TopAbs import TopAbs_FACE, TopAbs_SOLID, TopAbs_VERTEX
from OCP.TopExp import TopExp, TopExp_Explorer
from OCP.TopLoc import TopLoc_Location
from OCP.TopoDS import TopoDS
from OCP.XCAFDoc import (XCAFDoc_ColorGen, XCAFDoc_ColorSurf, XCAFDoc_ColorTool, XCAFDoc_DocumentTool,
                         XCAFDoc_ShapeTool)
from OCP.collections import IndexedMap_TopoDS_Shape_TopTools_ShapeMapHasher as ShapeMap
from OCP.collections import Sequence_TDF_Label

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, 'crates', 'splinekit-step', 'tests', 'data', 'real', 'occ_assembly.json')
_vertex = getattr(TopoDS, 'Vertex_s', None) or TopoDS.Vertex


def name(label):
    n = TDataStd_Name()
    if label.FindAttribute(TDataStd_Name.GetID_s(), n):
        return n.Get().ToExtString()
    return ''


def explore(shape, kind):
    exp = TopExp_Explorer(shape, kind)
    while exp.More():
        yield exp.Current()
        exp.Next()


def rgb(c):
    r, g, b = c.Values(Quantity_TOC_sRGB)
    return [round(r, 9), round(g, 9), round(b, 9)]


def colour_of(ct, what):
    """The surface colour of a label or shape, else its generic colour."""
    for kind in (XCAFDoc_ColorSurf, XCAFDoc_ColorGen):
        c = Quantity_Color()
        found = (XCAFDoc_ColorTool.GetColor_s(what, kind, c) if isinstance(what, TDF_Label)
                 else ct.GetColor(what, kind, c))
        if found:
            return rgb(c)
    return None


def read(path):
    doc = TDocStd_Document(TCollection_ExtendedString('XmlOcaf'))
    reader = STEPCAFControl_Reader()
    reader.SetColorMode(True)
    reader.SetNameMode(True)
    Interface_Static.SetIVal_s('read.step.tessellated', 0)
    if reader.ReadFile(path) != 1:
        raise RuntimeError(f'{path}: not read')
    reader.Transfer(doc)
    st = XCAFDoc_DocumentTool.ShapeTool_s(doc.Main())
    ct = XCAFDoc_DocumentTool.ColorTool_s(doc.Main())
    instances, parts = [], {}
    lo, hi = [float('inf')] * 3, [float('-inf')] * 3

    def leaf(label, loc, path):
        shape = st.GetShape_s(label)
        key = name(label) + '@' + label.EntryDumpToString() if hasattr(label, 'EntryDumpToString') else name(label)
        if key not in parts:
            faces = list(explore(shape, TopAbs_FACE))
            face_colours = [colour_of(ct, f) for f in faces]
            parts[key] = {
                'name': name(label),
                'solids': sum(1 for _ in explore(shape, TopAbs_SOLID)),
                'faces': len(faces),
                'colour': colour_of(ct, label),
                'faces_coloured': sum(1 for c in face_colours if c is not None),
                'face_colours': sorted({tuple(c) for c in face_colours if c is not None}),
            }
        trsf = loc.Transformation()
        moved = shape.Moved(TopLoc_Location(trsf))
        vlo, vhi = [float('inf')] * 3, [float('-inf')] * 3
        vertices = ShapeMap()
        TopExp.MapShapes_s(moved, TopAbs_VERTEX, vertices)
        n_vertices = vertices.Extent()
        for v in explore(moved, TopAbs_VERTEX):
            p = BRep_Tool.Pnt_s(_vertex(v))
            for k, x in enumerate((p.X(), p.Y(), p.Z())):
                vlo[k], vhi[k] = min(vlo[k], x), max(vhi[k], x)
                lo[k], hi[k] = min(lo[k], x), max(hi[k], x)
        instances.append({
            'path': path,
            'part': name(label),
            'solids': parts[key]['solids'],
            'vertices': n_vertices,
            'rotation': [trsf.Value(i, j) for i in (1, 2, 3) for j in (1, 2, 3)],
            'translation': [trsf.Value(i, 4) for i in (1, 2, 3)],
            'vertex_box': {'min': vlo, 'max': vhi},
        })

    def walk(label, loc, path):
        if XCAFDoc_ShapeTool.IsAssembly_s(label):
            comps = Sequence_TDF_Label()
            XCAFDoc_ShapeTool.GetComponents_s(label, comps, False)
            for i in range(1, comps.Length() + 1):
                comp = comps.Value(i)
                ref = TDF_Label()
                XCAFDoc_ShapeTool.GetReferredShape_s(comp, ref)
                walk(ref, loc.Multiplied(XCAFDoc_ShapeTool.GetLocation_s(comp)), path + [name(comp)])
        else:
            leaf(label, loc, path)

    free = Sequence_TDF_Label()
    st.GetFreeShapes(free)
    for i in range(1, free.Length() + 1):
        label = free.Value(i)
        walk(label, TopLoc_Location(), [name(label)])
    return {
        'instances': instances,
        'parts': sorted(parts.values(), key=lambda p: p['name']),
        'solids': sum(i['solids'] for i in instances),
        'vertex_box': {'min': lo, 'max': hi},
    }


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--dir', default=os.environ.get('SPLINEKIT_REAL_STEP', '/work/realstep'))
    ap.add_argument('-o', '--out', default=OUT)
    args = ap.parse_args()
    out = {'_meta': {'made_by': 'tools/occ_assembly_reference.py', 'units': 'mm',
                     'reader': 'STEPCAFControl_Reader, read.step.tessellated = 0'}}
    for path in sorted(glob.glob(os.path.join(args.dir, '*.stp')) + glob.glob(os.path.join(args.dir, '*.step'))):
        out[os.path.basename(path)] = read(path)
        r = out[os.path.basename(path)]
        print(f"{os.path.basename(path)}: {len(r['instances'])} instances, {r['solids']} solids, {len(r['parts'])} parts")
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    with open(args.out, 'w') as f:
        json.dump(out, f, indent=1, sort_keys=True)
        f.write('\n')


if __name__ == '__main__':
    main()
