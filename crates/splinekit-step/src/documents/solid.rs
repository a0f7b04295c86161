//! STEP topology ↔ `brep` documents.
//!
//! Reading: the faces of each solid (its outer shell and voids), and of each shell that no
//! solid holds, become one `brep` document whose faces share their edges and vertices as
//! the file's do. Vertices are the file's `VERTEX_POINT`s; each edge's curve is its 3-D
//! curve between its two vertices (lines as `line`, arcs and splines as exact NURBS), run
//! from its start vertex to its end; each face is its surface's document (as a `trimmed`
//! face's is, `documents::import`) with its loops kept piece by piece: the pcurve of each
//! edge use mapped into the document's (u, v), the poles' lines and the cuts that close
//! loops around periodic surfaces as uses without an edge.
//!
//! Writing (until solids are written as `MANIFOLD_SOLID_BREP`): each face as a `trimmed`
//! surface whose loops are its uses joined end to end.

use std::collections::{BTreeMap, HashMap};

use splinekit::Point;
use splinekit::curve::{Curve as _, NurbsCurve};
use splinekit_scene::curves::{BSplineDoc, LineDoc, NurbsDoc};
use splinekit_scene::surfaces::{
    BrepDoc, BrepEdgeDoc, BrepFaceDoc, BrepShellDoc, BrepSolidDoc, BrepUseDoc, SurfaceDocument, TrimmedDoc,
};
use splinekit_scene::{CurveDocument, SceneDocument, SceneObject, SceneOrShape, ShapeDocument};

use super::import::{
    conic_arc, face_surface, into_domain, join_parts, loop_parts, nurbs_doc, seam_crossings, spline_piece,
};
use crate::error::{Result, StepError};
use crate::geometry::Curve;
use crate::import::{EdgeRead, Face, GeometryOrFace, Imported, Role};
use crate::styles::{Rgba, Styles};

/// An edge's curve from its start vertex to its end as a 3-D document: a line, or an exact
/// NURBS arc or spline piece.
fn edge_curve(e: &EdgeRead) -> Result<CurveDocument> {
    let (lo, hi) = e.range;
    let point = |t: f64| -> Option<Vec<f64>> {
        let c = crate::evaluate::CurveEval::new(&e.curve).ok()?;
        Some(c.point(t).as_slice().to_vec())
    };
    let nurbs: NurbsCurve<3> = match &e.curve {
        Curve::Line { .. } => {
            let (a, b) = (point(lo), point(hi));
            let (Some(a), Some(b)) = (a, b) else { return Err(StepError::plain("an edge's line")) };
            let (from, to) = if e.same_sense { (a, b) } else { (b, a) };
            return Ok(CurveDocument::Line(LineDoc { from, to }));
        }
        Curve::Circle { axes, radius } => conic_arc::<3>(axes, *radius, *radius, lo, hi)?,
        Curve::Ellipse { axes, a, b } => conic_arc::<3>(axes, *a, *b, lo, hi)?,
        Curve::Spline(s) => spline_piece::<3>(s, lo, hi)?,
        Curve::Trimmed { basis, .. } => {
            return edge_curve(&EdgeRead { curve: (**basis).clone(), ..e.clone() });
        }
    };
    let nurbs = if e.same_sense { nurbs } else { reversed(&nurbs)? };
    Ok(nurbs_doc(&nurbs))
}

/// The same NURBS curve run backwards.
fn reversed<const D: usize>(c: &NurbsCurve<D>) -> Result<NurbsCurve<D>> {
    let d = c.domain();
    let knots = c.knots().iter().rev().map(|k| d.start + d.end - k).collect();
    let points = c.control_points().iter().rev().copied().collect();
    let weights = c.weights().iter().rev().copied().collect();
    NurbsCurve::new(c.degree(), knots, points, weights).map_err(|e| StepError::plain(format!("edge: {e}")))
}

/// Collects the vertices and edges of the faces it is given, numbering them in order.
#[derive(Default)]
struct Numbering {
    vertices: Vec<Vec<f64>>,
    vertex_index: HashMap<u64, usize>,
    edges: Vec<BrepEdgeDoc>,
    edge_index: HashMap<u64, usize>,
}

impl Numbering {
    fn vertex(&mut self, id: u64, found: &Imported) -> Result<usize> {
        if let Some(&k) = self.vertex_index.get(&id) {
            return Ok(k);
        }
        let p = found.vertices.get(&id).ok_or_else(|| StepError::plain(format!("#{id}: a vertex not read")))?;
        self.vertices.push(p.as_slice().to_vec());
        self.vertex_index.insert(id, self.vertices.len() - 1);
        Ok(self.vertices.len() - 1)
    }

    fn edge(&mut self, id: u64, found: &Imported) -> Result<usize> {
        if let Some(&k) = self.edge_index.get(&id) {
            return Ok(k);
        }
        let e = found.edges.get(&id).ok_or_else(|| StepError::plain(format!("#{id}: an edge not read")))?;
        let curve = edge_curve(e).map_err(|err| StepError::plain(format!("edge #{id}: {}", err.message)))?;
        let vertices = [self.vertex(e.vertices[0], found)?, self.vertex(e.vertices[1], found)?];
        self.edges.push(BrepEdgeDoc { curve, vertices });
        self.edge_index.insert(id, self.edges.len() - 1);
        Ok(self.edges.len() - 1)
    }
}

/// A 2-D NURBS piece as a document: a line where it is one segment of degree 1, else a
/// B-spline or NURBS curve.
fn pcurve_doc(c: &NurbsCurve<2>) -> CurveDocument {
    let pts = c.control_points();
    if c.degree() == 1 && pts.len() == 2 {
        return CurveDocument::Line(LineDoc { from: pts[0].as_slice().to_vec(), to: pts[1].as_slice().to_vec() });
    }
    nurbs_doc(c)
}

/// A face with its loops piece by piece (see the module); `None` where its surface or a
/// loop has no document form.
fn brep_face(
    f: &Face,
    numbering: &mut Numbering,
    found: &Imported,
    color: Option<[f32; 4]>,
) -> Result<Option<BrepFaceDoc>> {
    let Some((surface, map)) = face_surface(f)? else { return Ok(None) };
    let only_seams = f.loops.len() == 1 && f.seam_twins[0].iter().all(Option::is_some);
    let map = into_domain(f, map)?;
    let mut loops = Vec::with_capacity(f.loops.len());
    let outer = f.outer.unwrap_or(0);
    // A face bounded only by a vertex loop (a whole sphere) has no loop: its whole surface.
    let order: Vec<usize> = if f.loops.is_empty() {
        Vec::new()
    } else {
        std::iter::once(outer).chain((0..f.loops.len()).filter(|&i| i != outer)).collect()
    };
    for &i in order.iter().filter(|_| !only_seams) {
        let Some(parts) =
            loop_parts(&f.loops[i], &f.seam_twins[i], &f.roles[i], map.as_ref(), seam_crossings(&f.surface))?
        else {
            return Ok(None);
        };
        let mut uses = Vec::with_capacity(parts.len());
        for (c, role) in parts {
            let (edge, forward, twin) = match role {
                Role::Edge { id, forward } => (Some(numbering.edge(id, found)?), forward, None),
                Role::Cut { twin } => (None, true, Some(twin)),
                Role::Pole => (None, true, None),
            };
            uses.push(BrepUseDoc { pcurve: pcurve_doc(&c), edge, forward, twin });
        }
        loops.push(uses);
    }
    Ok(Some(BrepFaceDoc { name: f.name.clone(), surface, reversed: !f.same_sense, loops, color }))
}

/// One solid or loose shell read as a `brep` document.
pub struct BrepRead {
    /// The solid's name in the file.
    pub name: String,
    /// The document.
    pub document: BrepDoc,
    /// The `#id` of the solid (`MANIFOLD_SOLID_BREP`, `BREP_WITH_VOIDS`, …) or of the
    /// shell, by which the product structure places it.
    pub source: u64,
}

/// What [`brep_documents`] made: the documents, and the faces that stayed out (their
/// `#id`s are in the import's list of what was not converted).
pub struct BrepDocuments {
    /// Each solid's or loose shell's document.
    pub documents: Vec<BrepRead>,
    /// The indices in the import's geometry of the faces they hold.
    pub faces_used: Vec<usize>,
    /// Faces without a document form, by reason.
    pub left_out: BTreeMap<String, usize>,
}

/// The `brep` documents of the solids and shells read (see the module): one per solid,
/// and one per shell that no solid holds and that has more than one face or is closed.
/// Faces and solids take the colours `styles` give them (a face its own, else its shell's,
/// else its solid's; COLOUR_RGB components as written, which CAD systems mean as sRGB).
pub fn brep_documents(found: &Imported, styles: &Styles) -> Result<BrepDocuments> {
    // (name, shells and whether each is used reversed, the solid's #id, the source #id)
    type Group = (String, Vec<(usize, bool)>, Option<u64>, u64);
    let mut groups: Vec<Group> = Vec::new();
    let mut in_solid = vec![false; found.shells.len()];
    for s in &found.solids {
        s.shells.iter().for_each(|&k| in_solid[k] = true);
        let shells = s.shells.iter().zip(&s.reversed).map(|(&k, &r)| (k, r)).collect();
        groups.push((s.name.clone(), shells, Some(s.id), s.id));
    }
    for (k, shell) in found.shells.iter().enumerate() {
        if !in_solid[k] && (shell.closed || shell.faces.len() + shell.missing > 1) {
            groups.push((String::new(), vec![(k, false)], None, shell.id));
        }
    }
    let srgb = |c: Rgba| c.to_array().map(|x| x as f32);
    let mut out = BrepDocuments { documents: Vec::new(), faces_used: Vec::new(), left_out: BTreeMap::new() };
    for (name, shells, solid_id, source) in groups {
        let mut numbering = Numbering::default();
        let mut faces = Vec::new();
        let mut shell_docs = Vec::new();
        for &(k, shell_reversed) in &shells {
            let shell = &found.shells[k];
            let mut members = Vec::new();
            for &g in &shell.faces {
                let GeometryOrFace::Face(f) = &found.geometry[g].1 else { continue };
                let color = styles.effective(&[f.id, shell.id, solid_id.unwrap_or(u64::MAX)]).map(srgb);
                match brep_face(f, &mut numbering, found, color)? {
                    Some(mut face) => {
                        face.reversed ^= shell_reversed;
                        members.push(faces.len());
                        faces.push(face);
                        out.faces_used.push(g);
                    }
                    None => *out.left_out.entry("face (no document form)".into()).or_default() += 1,
                }
            }
            shell_docs.push(BrepShellDoc { faces: members, closed: shell.closed && shell.missing == 0 });
        }
        if faces.is_empty() {
            continue;
        }
        let solids = if name.is_empty() && shells.len() == 1 && !found.shells[shells[0].0].closed {
            Vec::new()
        } else {
            let color = solid_id.and_then(|id| styles.colour(id)).map(srgb);
            vec![BrepSolidDoc { name: name.clone(), shells: (0..shells.len()).collect(), color }]
        };
        let doc = BrepDoc {
            source_unit: found.source_unit.clone(),
            vertices: numbering.vertices,
            edges: numbering.edges,
            faces,
            shells: shell_docs,
            solids,
        };
        out.documents.push(BrepRead { name, document: doc, source });
    }
    Ok(out)
}

/// A 2-D pcurve document as a clamped NURBS curve (the kinds reading writes: lines,
/// B-splines, NURBS curves).
fn pcurve_nurbs(doc: &CurveDocument) -> Result<NurbsCurve<2>> {
    let pt = |v: &[f64]| Point::<2>::new(v.first().copied().unwrap_or(0.0), v.get(1).copied().unwrap_or(0.0));
    let err = |e: splinekit::Error| StepError::plain(format!("pcurve: {e}"));
    match doc {
        CurveDocument::Line(l) => {
            NurbsCurve::new(1, vec![0.0, 0.0, 1.0, 1.0], vec![pt(&l.from), pt(&l.to)], vec![1.0, 1.0]).map_err(err)
        }
        CurveDocument::Bspline(BSplineDoc { degree, knots, control_points, periodic: false }) => {
            let n = control_points.len();
            NurbsCurve::new(*degree, knots.clone(), control_points.iter().map(|p| pt(p)).collect(), vec![1.0; n])
                .map_err(err)
        }
        CurveDocument::Nurbs(NurbsDoc { degree, knots, control_points, weights, periodic: false }) => {
            NurbsCurve::new(*degree, knots.clone(), control_points.iter().map(|p| pt(p)).collect(), weights.clone())
                .map_err(err)
        }
        other => Err(StepError::plain(format!("pcurve: a {} is not written yet", other.type_name()))),
    }
}

/// A B-rep's faces as `trimmed` surfaces, each loop its uses joined end to end (what STEP
/// writes of a B-rep until solids are written with their shared edges).
pub fn brep_faces(doc: &BrepDoc) -> Result<Vec<ShapeDocument>> {
    doc.faces
        .iter()
        .enumerate()
        .map(|(f, face)| {
            let within = |e: StepError| StepError::plain(format!("faces[{f}]: {}", e.message));
            let mut loops = Vec::with_capacity(face.loops.len());
            for lp in &face.loops {
                let parts = lp.iter().map(|u| pcurve_nurbs(&u.pcurve)).collect::<Result<Vec<_>>>().map_err(within)?;
                loops.push(nurbs_doc(&join_parts(&parts).map_err(within)?));
            }
            let mut loops = loops.into_iter();
            let outer = loops.next().map(Box::new);
            let surface = Box::new(face.surface.clone());
            Ok(ShapeDocument::Surface(SurfaceDocument::Trimmed(TrimmedDoc { surface, outer, holes: loops.collect() })))
        })
        .collect()
}

/// The document with every `brep` (a shape, or a scene's object) replaced by its faces
/// ([`brep_faces`]), objects keeping their style; other documents as they are.
pub fn expand_breps(doc: &SceneOrShape) -> Result<SceneOrShape> {
    Ok(match doc {
        SceneOrShape::Shape(ShapeDocument::Surface(SurfaceDocument::Brep(b))) => {
            let mut scene = SceneDocument::of_shape(ShapeDocument::Surface(SurfaceDocument::Brep(b.clone())));
            scene.objects = brep_faces(b)?
                .into_iter()
                .map(|shape| SceneObject { shape, instance_of: None, ..scene.objects[0].clone() })
                .collect();
            SceneOrShape::Scene(scene)
        }
        SceneOrShape::Scene(scene) => {
            let mut out = scene.clone();
            out.objects.clear();
            for (i, o) in scene.objects.iter().enumerate() {
                match &o.shape {
                    ShapeDocument::Surface(SurfaceDocument::Brep(b)) => {
                        let faces =
                            brep_faces(b).map_err(|e| StepError::plain(format!("objects[{i}]: {}", e.message)))?;
                        out.objects.extend(faces.into_iter().map(|shape| SceneObject {
                            shape,
                            instance_of: None,
                            ..o.clone()
                        }));
                    }
                    _ => out.objects.push(o.clone()),
                }
            }
            SceneOrShape::Scene(out)
        }
        other => other.clone(),
    })
}
