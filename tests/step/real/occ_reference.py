#!/usr/bin/env python3
"""OpenCASCADE reference numbers for the real-CAD STEP test set (issue 35).

For each *.stp / *.step file beside this script (or the files given on the
command line) it reads the file with STEPControl_Reader (TransferRoots,
OneShape) and records:

  - the length unit the file declares and the unit OCC converted to
    (OCC converts lengths to millimetres by default; every number below is
    in that unit, mm, mm^2, mm^3);
  - counts: solids, shells (and how many are closed), faces, edges, vertices;
  - total face area (BRepGProp.SurfaceProperties_s);
  - volume of the solids (BRepGProp.VolumeProperties_s, summed per solid,
    and the signed total) -- only meaningful for closed solids;
  - the bounding box, both Bnd_Box via BRepBndLib.Add_s(useTriangulation=False)
    (OCC enlarges it by the shape's tolerances) and the optimal box
    BRepBndLib.AddOptimal_s(useTriangulation=False, useShapeTolerance=False);
  - BRepCheck_Analyzer validity;
  - timings: read (ReadFile) + transfer (TransferRoots/OneShape), and
    BRepMesh_IncrementalMesh at linear deflection 1e-3 x bbox diagonal and
    angular deflection 0.5 rad; plus the mesh's triangle/node counts and
    the mesh area/volume (from Poly_Triangulation), so a mesher can be
    compared with OCC's at the same deflection.

Writes occ_reference.json (keyed by file name) next to this script.

Usage:  python occ_reference.py [--repeat N] [files...]
Needs:  OCP (pip install cadquery-ocp-novtk==8.0.1.1.0, as .ci/install-ocp.sh).
"""
import argparse
import json
import math
import os
import re
import sys
import time

from OCP.BRep import BRep_Tool
from OCP.BRepBndLib import BRepBndLib
from OCP.BRepCheck import BRepCheck_Analyzer
from OCP.BRepGProp import BRepGProp
from OCP.BRepMesh import BRepMesh_IncrementalMesh
from OCP.Bnd import Bnd_Box
from OCP.GProp import GProp_GProps
from OCP.IFSelect import IFSelect_RetDone
from OCP.Interface import Interface_Static
from OCP.STEPControl import STEPControl_Reader
from OCP.TopAbs import (TopAbs_EDGE, TopAbs_FACE, TopAbs_REVERSED, TopAbs_SHELL,
                        TopAbs_SOLID, TopAbs_VERTEX)
from OCP.TopExp import TopExp, TopExp_Explorer
from OCP.TopLoc import TopLoc_Location
from OCP.collections import (IndexedMap_TopoDS_Shape_TopTools_ShapeMapHasher as ShapeMap,
                             Sequence_TCollection_AsciiString as AsciiSeq)
from OCP.TopoDS import TopoDS

_to_face = getattr(TopoDS, 'Face_s', None) or TopoDS.Face  # OCP 7.x vs 8.x
HERE = os.path.dirname(os.path.abspath(__file__))
LIN_REL = 1e-3   # linear deflection relative to the bbox diagonal
ANG = 0.5        # angular deflection, radians


def header_info(path):
    """FILE_NAME preprocessor/originating system, FILE_SCHEMA and the declared
    length unit, read from the text (OCC does not expose all of it)."""
    with open(path, 'rb') as f:
        raw = f.read()
    t = raw.decode('latin-1')
    data_at = t.find('DATA;')
    hdr = t[:data_at] if data_at >= 0 else t[:4000]
    hdr_nc = re.sub(r'/\*.*?\*/', '', hdr, flags=re.S)
    fn = re.search(r'FILE_NAME\s*\((.*?)\)\s*;', hdr_nc, re.S)
    strs = re.findall(r"'((?:[^']|'')*)'", fn.group(1)) if fn else []
    pre, orig = (strs[-3], strs[-2]) if len(strs) >= 3 else ('', '')
    fs = re.search(r"FILE_SCHEMA\s*\(\s*\((.*?)\)\s*\)", hdr_nc, re.S)
    schemas = re.findall(r"'([^']*)'", fs.group(1)) if fs else []
    body = t[data_at:] if data_at >= 0 else t
    conv = sorted(set(u.upper() for u in re.findall(
        r"CONVERSION_BASED_UNIT\s*\(\s*'([^']*)'", body)))
    si = sorted(set(re.findall(
        r"LENGTH_UNIT\s*\(\s*\)\s*NAMED_UNIT\s*\(\s*\*\s*\)\s*SI_UNIT\s*\(\s*([.A-Z$]*)\s*,\s*\.METRE\.",
        body)))

    def count(name):
        return len(re.findall(r'(?<![A-Z_])' + name + r'\s*\(', body))

    n_edge_curve = count('EDGE_CURVE')
    n_surface_curve = count('SURFACE_CURVE') + count('SEAM_CURVE')
    n_pcurve = count('PCURVE')
    return {
        'bytes': len(raw),
        'preprocessor_version': pre,
        'originating_system': orig,
        'file_schema': schemas,
        'declared_length_units': {'si_prefixes': si, 'conversion_based': conv},
        'entity_counts': {
            'MANIFOLD_SOLID_BREP': count('MANIFOLD_SOLID_BREP'),
            'BREP_WITH_VOIDS': count('BREP_WITH_VOIDS'),
            'CLOSED_SHELL': count('CLOSED_SHELL'),
            'OPEN_SHELL': count('OPEN_SHELL'),
            'SHELL_BASED_SURFACE_MODEL': count('SHELL_BASED_SURFACE_MODEL'),
            'ADVANCED_FACE': count('ADVANCED_FACE'),
            'EDGE_CURVE': n_edge_curve,
            'SURFACE_CURVE_or_SEAM_CURVE': n_surface_curve,
            'PCURVE': n_pcurve,
            'NEXT_ASSEMBLY_USAGE_OCCURRENCE': count('NEXT_ASSEMBLY_USAGE_OCCURRENCE'),
            'MAPPED_ITEM': count('MAPPED_ITEM'),
            'STYLED_ITEM': count('STYLED_ITEM'),
            'COLOUR_RGB': count('COLOUR_RGB'),
            'B_SPLINE_SURFACE_WITH_KNOTS': count('B_SPLINE_SURFACE_WITH_KNOTS'),
            'TESSELLATED_or_TRIANGULATED': len(re.findall(r'(?<![A-Z_])(?:TESSELLATED_SOLID|TESSELLATED_SHELL|TRIANGULATED_FACE|COMPLEX_TRIANGULATED_FACE|TRIANGULATED_SURFACE_SET|COMPLEX_TRIANGULATED_SURFACE_SET)\s*\(', body)),
        },
        'edges_have_pcurves': n_surface_curve > 0 or n_pcurve > 0,
        'bytes_after_end_iso': len(raw) - (raw.rfind(b'END-ISO-10303-21;') + len(b'END-ISO-10303-21;'))
        if b'END-ISO-10303-21;' in raw else None,
    }


def explore(shape, kind):
    out = []
    exp = TopExp_Explorer(shape, kind)
    while exp.More():
        out.append(exp.Current())
        exp.Next()
    return out


def unique_count(shape, kind):
    m = ShapeMap()
    TopExp.MapShapes_s(shape, kind, m)
    return m.Extent()


def mesh_stats(shape):
    """Triangles, nodes, area and signed volume of the triangulation that
    BRepMesh left on the faces (volume by the divergence theorem)."""
    tris = nodes = 0
    area = 0.0
    vol = 0.0
    missing = 0
    for f in explore(shape, TopAbs_FACE):
        face = _to_face(f)
        loc = TopLoc_Location()
        tri = BRep_Tool.Triangulation_s(face, loc)
        if tri is None:
            missing += 1
            continue
        trsf = loc.Transformation()
        rev = face.Orientation() == TopAbs_REVERSED
        pts = [tri.Node(i).Transformed(trsf) for i in range(1, tri.NbNodes() + 1)]
        nodes += tri.NbNodes()
        tris += tri.NbTriangles()
        for i in range(1, tri.NbTriangles() + 1):
            a, b, c = tri.Triangle(i).Get()
            p, q, r = pts[a - 1], pts[b - 1], pts[c - 1]
            if rev:
                q, r = r, q
            ux, uy, uz = q.X() - p.X(), q.Y() - p.Y(), q.Z() - p.Z()
            vx, vy, vz = r.X() - p.X(), r.Y() - p.Y(), r.Z() - p.Z()
            cx, cy, cz = uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx
            area += 0.5 * math.sqrt(cx * cx + cy * cy + cz * cz)
            vol += (p.X() * (q.Y() * r.Z() - q.Z() * r.Y())
                    - p.Y() * (q.X() * r.Z() - q.Z() * r.X())
                    + p.Z() * (q.X() * r.Y() - q.Y() * r.X())) / 6.0
    return {'triangles': tris, 'nodes': nodes, 'faces_without_triangulation': missing,
            'mesh_area': area, 'mesh_signed_volume_all_faces': vol}


def box_dict(box):
    if box.IsVoid():
        return None
    lo, hi = box.CornerMin(), box.CornerMax()
    xmin, ymin, zmin, xmax, ymax, zmax = lo.X(), lo.Y(), lo.Z(), hi.X(), hi.Y(), hi.Z()
    return {'min': [xmin, ymin, zmin], 'max': [xmax, ymax, zmax],
            'gap': box.GetGap(),
            'diagonal': math.sqrt((xmax - xmin) ** 2 + (ymax - ymin) ** 2 + (zmax - zmin) ** 2)}


def set_tessellated(mode):
    """read.step.tessellated: 0 = Off (B-rep only), 1 = On (OCC's default), 2 = OnNoBRep."""
    STEPControl_Reader()  # makes sure the STEP controller (and its parameters) exist
    Interface_Static.SetIVal_s('read.step.tessellated', mode)


def counts_with_tessellated(path):
    """Faces and solids as OCC's default reading (tessellated geometry On) gives them."""
    set_tessellated(1)
    try:
        r = STEPControl_Reader()
        if r.ReadFile(path) != IFSelect_RetDone:
            return None
        r.TransferRoots()
        s = r.OneShape()
        return {'faces': len(explore(s, TopAbs_FACE)), 'solids': len(explore(s, TopAbs_SOLID)),
                'brepcheck_valid': bool(BRepCheck_Analyzer(s).IsValid())}
    finally:
        set_tessellated(0)


def reference(path, repeat=1):
    res = {'header': header_info(path)}
    # The reference numbers are for the exact B-rep only: tessellated (AP242
    # TRIANGULATED_FACE / TESSELLATED_SOLID) geometry that some writers add
    # beside the B-rep is not read (read.step.tessellated = 0).
    set_tessellated(0)
    res['occ_read_step_tessellated'] = 'Off'
    # OCC converts every length to this unit (xstep.cascade.unit, default MM).
    res['occ_length_unit'] = Interface_Static.CVal_s('xstep.cascade.unit')

    best_read = best_transfer = None
    shape = None
    for _ in range(max(1, repeat)):
        reader = STEPControl_Reader()
        t0 = time.perf_counter()
        status = reader.ReadFile(path)
        t1 = time.perf_counter()
        if status != IFSelect_RetDone:
            return {**res, 'error': f'ReadFile status {status}'}
        nroots = reader.NbRootsForTransfer()
        reader.TransferRoots()
        shape = reader.OneShape()
        t2 = time.perf_counter()
        best_read = (t1 - t0) if best_read is None else min(best_read, t1 - t0)
        best_transfer = (t2 - t1) if best_transfer is None else min(best_transfer, t2 - t1)
    # Units as OCC understood them: the scale from file units to mm.
    try:
        lu, au, su = AsciiSeq(), AsciiSeq(), AsciiSeq()
        reader.FileUnits(lu, au, su)
        res['occ_file_length_units'] = sorted(set(x.ToCString() for x in lu))
        res['occ_system_length_unit'] = reader.SystemLengthUnit()  # OCC's target unit, in mm (1.0 = mm)
    except Exception as e:  # noqa: BLE001
        res['occ_file_length_units'] = f'unavailable: {e}'
    res['roots_for_transfer'] = nroots
    if shape is None or shape.IsNull():
        return {**res, 'error': 'null shape'}

    solids = explore(shape, TopAbs_SOLID)
    shells = explore(shape, TopAbs_SHELL)
    shells_closed = sum(1 for s in shells if BRep_Tool.IsClosed_s(s))
    res['counts'] = {
        'solids': len(solids),
        'shells': len(shells),
        'closed_shells': shells_closed,
        'faces': len(explore(shape, TopAbs_FACE)),
        'faces_unique': unique_count(shape, TopAbs_FACE),
        'edges_unique': unique_count(shape, TopAbs_EDGE),
        'vertices_unique': unique_count(shape, TopAbs_VERTEX),
    }

    g = GProp_GProps()
    BRepGProp.SurfaceProperties_s(shape, g)
    res['area'] = g.Mass()
    vols = []
    for s in solids:
        gv = GProp_GProps()
        BRepGProp.VolumeProperties_s(s, gv)
        vols.append(gv.Mass())
    res['volume_solids'] = vols
    res['volume_total'] = sum(vols)
    res['all_shells_closed'] = shells_closed == len(shells) and len(shells) > 0

    box = Bnd_Box()
    BRepBndLib.Add_s(shape, box, False)
    res['bbox'] = box_dict(box)
    obox = Bnd_Box()
    BRepBndLib.AddOptimal_s(shape, obox, False, False)
    res['bbox_optimal'] = box_dict(obox)

    ana = BRepCheck_Analyzer(shape)
    res['brepcheck_valid'] = bool(ana.IsValid())

    diag = res['bbox_optimal']['diagonal'] if res['bbox_optimal'] else 1.0
    lin = LIN_REL * diag
    best_mesh = None
    for _ in range(max(1, repeat)):
        # BRepMesh keeps its triangulation on the shape; re-read is too slow,
        # so clean it between repeats.
        from OCP.BRepTools import BRepTools
        BRepTools.Clean_s(shape)
        t0 = time.perf_counter()
        mesher = BRepMesh_IncrementalMesh(shape, lin, False, ANG, False)
        mesher.Perform()
        t1 = time.perf_counter()
        best_mesh = (t1 - t0) if best_mesh is None else min(best_mesh, t1 - t0)
    if res['header']['entity_counts']['TESSELLATED_or_TRIANGULATED']:
        res['occ_default_read_with_tessellated'] = counts_with_tessellated(path)
    res['mesh_params'] = {'linear_deflection': lin, 'relative_to_bbox_diagonal': LIN_REL,
                          'angular_deflection_rad': ANG, 'relative': False, 'parallel': False}
    res['mesh'] = mesh_stats(shape)
    res['times_s'] = {'read': best_read, 'transfer': best_transfer,
                      'read_plus_transfer': best_read + best_transfer,
                      'mesh': best_mesh, 'repeat': max(1, repeat)}
    return res


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('files', nargs='*')
    ap.add_argument('--repeat', type=int, default=3, help='take the best of N timings')
    ap.add_argument('-o', '--output', default=os.path.join(HERE, 'occ_reference.json'))
    a = ap.parse_args()
    files = a.files or sorted(os.path.join(HERE, f) for f in os.listdir(HERE)
                              if f.lower().endswith(('.stp', '.step')))
    out = {}
    for p in files:
        name = os.path.basename(p)
        t0 = time.perf_counter()
        try:
            out[name] = reference(p, a.repeat)
        except Exception as e:  # noqa: BLE001
            out[name] = {'error': repr(e)}
        r = out[name]
        c = r.get('counts', {})
        print(f"{name:48s} faces={c.get('faces')} solids={c.get('solids')} "
              f"shells={c.get('shells')}/{c.get('closed_shells')}closed "
              f"area={r.get('area', float('nan')):.6g} vol={r.get('volume_total', float('nan')):.6g} "
              f"valid={r.get('brepcheck_valid')} {r.get('error', '')} "
              f"[{time.perf_counter() - t0:.1f}s]", flush=True)
    import OCP
    meta = {'_meta': {'ocp_version': getattr(OCP, '__version__', 'cadquery-ocp-novtk 8.0.1.1.0'),
                      'python': sys.version.split()[0],
                      'units': 'lengths in mm (OCC xstep.cascade.unit), areas mm^2, volumes mm^3',
                      'mesh': f'BRepMesh_IncrementalMesh(lin={LIN_REL} x optimal-bbox diagonal, ang={ANG} rad)'}}
    with open(a.output, 'w') as f:
        json.dump({**meta, **out}, f, indent=1, sort_keys=False)
    print('wrote', a.output)


if __name__ == '__main__':
    main()
