//! STEP geometry → shape documents. Splines keep everything (knots, weights; a closed
//! spline whose last p points repeat its first p and whose knots repeat their spacing
//! becomes a periodic document, undoing the export). Lines, planes and swept surfaces keep
//! their parametrisation up to an affine map per direction; circles and ellipses at the
//! world frame stay `circle`/`ellipse`, elsewhere they become exact rational arcs (same
//! points, rational parametrisation); quadrics at the world frame with the export's
//! ranges stay model surfaces, placed spheres and tori over their whole domain become
//! `placed` ones, others exact revolutions. Faces on planes, splines, cylinders, cones,
//! spheres, tori, revolutions and extrusions become `trimmed` documents whose loops are
//! their pcurves joined into one exact B-spline (NURBS) loop each.

use splinekit::Point;
use splinekit::curve::{CircleFrame, Curve as KernelCurve, NurbsCurve};
use splinekit::query::Aabb;
use splinekit_scene::curves::{BSplineDoc, CircleDoc, EllipseDoc, LineDoc, NurbsDoc};
use splinekit_scene::placement::{PlacementDoc, RigidTransform};
use splinekit_scene::surfaces::{
    BSplineSurfaceDoc, CylinderDoc, ExtrusionDoc, NurbsSurfaceDoc, PlacedDoc, PlaneDoc, RevolutionDoc, SphereDoc,
    TorusDoc, TrimmedDoc,
};
use splinekit_scene::{CurveDocument, ShapeDocument, SurfaceDocument};
use std::f64::consts::{FRAC_PI_2, TAU};

use crate::error::{Result, StepError};
use crate::geometry::{Axes, Curve, Geometry, Item, SplineCurve, SplineSurface, Surface};
use crate::import::{Face, GeometryOrFace, Role, import, is_world, radial};
use crate::kernel::nurbs;
use crate::part21::StepFile;

/// Documents read from a STEP file.
#[derive(Debug, Clone, Default)]
pub struct ImportedDocuments {
    /// Each converted object.
    pub items: Vec<ImportedItem>,
    /// Entity types not converted, with counts (to report; nothing is dropped silently).
    pub not_understood: Vec<(String, usize)>,
}

/// Reads every curve, surface and face of the file as documents: the faces of solids and
/// of shells of several faces as one `brep` document each (`documents::solid`), other
/// faces as `trimmed` documents.
pub fn import_items(file: &StepFile) -> Result<ImportedDocuments> {
    let mut found = import(file)?;
    let mut out = ImportedDocuments::default();
    let breps = super::solid::brep_documents(&found, &crate::styles::read_styles(file))?;
    let mut skipped = std::mem::take(&mut found.not_understood);
    for (reason, count) in breps.left_out {
        *skipped.entry(reason).or_default() += count;
    }
    let in_brep: std::collections::HashSet<usize> = breps.faces_used.into_iter().collect();
    out.items = super::instances::place_breps(file, breps.documents, &mut skipped);
    for (name, g) in found.geometry.into_iter().enumerate().filter(|(k, _)| !in_brep.contains(k)).map(|(_, g)| g) {
        let label = if name.is_empty() { what(&g) } else { format!("'{name}' ({})", what(&g)) };
        let converted = match &g {
            GeometryOrFace::Curve(c) => curve_doc(c).map(|d| d.map(ShapeDocument::Curve)),
            GeometryOrFace::Surface(s) => surface_doc(s).map(|d| d.map(ShapeDocument::Surface)),
            GeometryOrFace::Face(f) => face_doc(f).map(|d| d.map(ShapeDocument::Surface)),
        }?;
        let geometry = match g {
            GeometryOrFace::Curve(c) => Some(Geometry::Curve(c)),
            GeometryOrFace::Surface(s) => Some(Geometry::Surface(s)),
            GeometryOrFace::Face(_) => None,
        };
        match (converted, geometry) {
            // Faces travel as their `trimmed` documents, and STEP → STEP writes those.
            (Some(document), geometry) => out.items.push(ImportedItem::new(name, geometry, document)),
            (None, _) => *skipped.entry(format!("{label} (no document form)")).or_default() += 1,
        }
    }
    out.not_understood = skipped.into_iter().filter(|(_, c)| *c > 0).collect();
    Ok(out)
}

/// One object read from a STEP file.
#[derive(Debug, Clone)]
pub struct ImportedItem {
    /// Its name in the file (the entity's `name`).
    pub name: String,
    /// Its STEP geometry, for STEP → STEP; `None` for a face, which travels as its
    /// `trimmed` document, exported by [`ImportedDocuments::step_items`] when asked.
    pub geometry: Option<Geometry>,
    /// Its document (an instance's too: the shape of the object it is an instance of).
    pub document: ShapeDocument,
    /// Where the product structure places it (part coordinates → the root's), unless that
    /// is the identity.
    pub placement: Option<RigidTransform>,
    /// The earlier item it is another use of (the same part, placed again).
    pub instance_of: Option<usize>,
}

impl ImportedItem {
    /// An item where the file put it, not an instance.
    pub fn new(name: String, geometry: Option<Geometry>, document: ShapeDocument) -> Self {
        ImportedItem { name, geometry, document, placement: None, instance_of: None }
    }
}

impl ImportedDocuments {
    /// The STEP items of every object (for STEP → STEP): the geometry read, and for a face
    /// the export of its `trimmed` document (named as the face), each moved by its
    /// placement.
    pub fn step_items(&self) -> Result<Vec<Item>> {
        self.items
            .iter()
            .map(|i| -> Result<Vec<Item>> {
                let mut items = match (&i.geometry, &i.document) {
                    (Some(geometry), _) => vec![Item { name: i.name.clone(), geometry: geometry.clone() }],
                    (None, ShapeDocument::Surface(SurfaceDocument::Brep(b))) => {
                        super::solid::brep_faces(b)?.iter().map(|f| face_item(&i.name, f)).collect::<Result<_>>()?
                    }
                    (None, doc) => vec![face_item(&i.name, doc)?],
                };
                if let Some(t) = &i.placement {
                    let p = crate::placement::Placement::of_transform(t);
                    items.iter_mut().for_each(|item| item.geometry = p.geometry(&item.geometry));
                }
                Ok(items)
            })
            .collect::<Result<Vec<_>>>()
            .map(|v| v.into_iter().flatten().collect())
    }

    /// The file as one document: its one object where that stands where the file put it,
    /// else a scene of them, each with its `name`, its `placement` where the product
    /// structure moves it, and a part's later uses as `instance_of` its first (the JSON
    /// `convert` writes and every command that takes a STEP file reads).
    pub fn to_value(&self) -> serde_json::Value {
        let shape_value = |doc: &ShapeDocument| match doc {
            ShapeDocument::Curve(c) => c.to_value(),
            ShapeDocument::Surface(s) => s.to_value(),
        };
        if let [item] = self.items.as_slice()
            && item.placement.is_none()
        {
            return shape_value(&item.document);
        }
        let objects: Vec<serde_json::Value> = self
            .items
            .iter()
            .map(|i| {
                let mut o = serde_json::Map::new();
                match i.instance_of {
                    Some(k) => o.insert("instance_of".into(), k.into()),
                    None => o.insert("shape".into(), shape_value(&i.document)),
                };
                if !i.name.is_empty() {
                    o.insert("name".into(), i.name.clone().into());
                }
                if let Some(t) = &i.placement {
                    o.insert("placement".into(), serde_json::to_value(PlacementDoc::of(t)).unwrap_or_default());
                }
                serde_json::Value::Object(o)
            })
            .collect();
        serde_json::json!({"type": "scene", "objects": objects})
    }
}

/// What a converted object is, for the list of those without a document form.
fn what(g: &GeometryOrFace) -> String {
    let surface = |s: &Surface| match s {
        Surface::Plane(_) => "plane",
        Surface::Cylinder { .. } => "cylinder",
        Surface::Cone { .. } => "cone",
        Surface::Sphere { .. } => "sphere",
        Surface::Torus { .. } => "torus",
        Surface::Spline(_) => "B-spline surface",
        Surface::Revolution { .. } => "surface of revolution",
        Surface::Extrusion { .. } => "surface of linear extrusion",
        Surface::Trimmed { .. } => "trimmed surface",
    };
    match g {
        GeometryOrFace::Curve(_) => "curve".to_string(),
        GeometryOrFace::Surface(s) => surface(s).to_string(),
        GeometryOrFace::Face(f) => format!("face on a {}", surface(&f.surface)),
    }
}

/// A face's STEP item for STEP → STEP: its `trimmed` document, exported as a face.
fn face_item(name: &str, doc: &ShapeDocument) -> Result<Item> {
    let ShapeDocument::Surface(s) = doc else { unreachable!("faces are trimmed surfaces") };
    Ok(crate::documents::export_surface(s, name, 1e-6)?.item)
}

fn v3(p: Point<3>) -> Vec<f64> {
    p.as_slice().to_vec()
}

fn pts_of<const D: usize>(c: &NurbsCurve<D>) -> Vec<Vec<f64>> {
    c.control_points().iter().map(|p| p.iter().copied().collect()).collect()
}

/// A kernel NURBS curve as a `bspline` (all weights 1) or `nurbs` document.
pub(crate) fn nurbs_doc<const D: usize>(c: &NurbsCurve<D>) -> CurveDocument {
    if c.weights().iter().all(|&w| w == 1.0) {
        CurveDocument::Bspline(BSplineDoc {
            degree: c.degree(),
            knots: c.knots().to_vec(),
            control_points: pts_of(c),
            periodic: false,
        })
    } else {
        CurveDocument::Nurbs(NurbsDoc {
            degree: c.degree(),
            knots: c.knots().to_vec(),
            control_points: pts_of(c),
            weights: c.weights().to_vec(),
            periodic: false,
        })
    }
}

/// The periodic form (n points, n + p + 1 knots) of a closed spline written unrolled, if
/// it is one.
fn periodic_form<T: PartialEq + Clone>(items: &[T], knots: &[f64], p: usize) -> Option<(Vec<T>, Vec<f64>)> {
    let total = items.len();
    if p == 0 || total < 2 * p + 1 {
        return None;
    }
    let n = total - p;
    if (0..p).any(|i| items[i] != items[i + n]) {
        return None;
    }
    let period = knots[n + p] - knots[p];
    let scale = knots[n + p].abs().max(knots[0].abs()).max(period);
    let tail_ok = (n + p + 1..knots.len()).all(|i| ((knots[i] - knots[i - n]) - period).abs() <= 1e-12 * scale);
    tail_ok.then(|| (items[..n].to_vec(), knots[..n + p + 1].to_vec()))
}

pub(crate) fn spline_curve_doc(s: &SplineCurve) -> CurveDocument {
    let p = s.degree;
    let periodic = if s.closed {
        let tagged: Vec<(Vec<f64>, Option<f64>)> =
            s.points.iter().enumerate().map(|(i, pt)| (pt.clone(), s.weights.as_ref().map(|w| w[i]))).collect();
        periodic_form(&tagged, &s.knots, p)
    } else {
        None
    };
    let (points, weights, knots, periodic) = match periodic {
        Some((items, knots)) => {
            let w: Option<Vec<f64>> = s.weights.as_ref().map(|_| items.iter().map(|(_, w)| w.unwrap_or(1.0)).collect());
            (items.into_iter().map(|(p, _)| p).collect(), w, knots, true)
        }
        None => (s.points.clone(), s.weights.clone(), s.knots.clone(), false),
    };
    let doc = match weights {
        None => CurveDocument::Bspline(BSplineDoc { degree: p, knots, control_points: points, periodic }),
        Some(weights) => CurveDocument::Nurbs(NurbsDoc { degree: p, knots, control_points: points, weights, periodic }),
    };
    if periodic && doc.build().is_err() {
        // The knots only almost repeat: keep the unrolled open form, which is exact.
        return spline_curve_doc(&SplineCurve { closed: false, ..s.clone() });
    }
    doc
}

/// An exact rational arc of an ellipse with semi-axes (a, b) in a placement, angles
/// [t0, t1].
pub(crate) fn conic_arc<const D: usize>(axes: &Axes, a: f64, b: f64, t0: f64, t1: f64) -> Result<NurbsCurve<D>> {
    let v = |p: Point<3>| Point::<D>::from_fn(|k, _| p[k]);
    let (x, y) = (axes.x.map(|c| c * a), axes.y().map(|c| c * b));
    let frame = CircleFrame { center: v(axes.origin), x_axis: v(x), y_axis: v(y), radius: 1.0 };
    NurbsCurve::arc(&frame, t0, t1).map_err(|e| StepError::plain(format!("arc: {e}")))
}

/// A piece [start, end] of a spline, by knot insertion (the whole curve when the range
/// is its domain).
pub(crate) fn spline_piece<const D: usize>(s: &SplineCurve, start: f64, end: f64) -> Result<NurbsCurve<D>> {
    let mut c = nurbs::<D>(s)?.clamped().map_err(|e| StepError::plain(format!("B-spline curve: {e}")))?;
    let d = c.domain();
    let err = |e: splinekit::Error| StepError::plain(format!("B-spline curve: {e}"));
    if start > d.start {
        c = c.split(start).map_err(err)?.1.ok_or_else(|| StepError::plain("cannot trim a B-spline curve"))?;
    }
    if end < d.end {
        c = c.split(end).map_err(err)?.0;
    }
    Ok(c)
}

/// A free 3-D curve as a document; `None` where no document form exists.
fn curve_doc(c: &Curve) -> Result<Option<CurveDocument>> {
    Ok(Some(match c {
        Curve::Spline(s) => spline_curve_doc(s),
        Curve::Line { origin, direction } => CurveDocument::Line(LineDoc {
            from: origin.clone(),
            to: origin.iter().zip(direction).map(|(o, d)| o + d).collect(),
        }),
        Curve::Circle { axes, radius } if is_world(axes) => CurveDocument::Circle(CircleDoc { radius: *radius }),
        Curve::Ellipse { axes, a, b } if is_world(axes) => CurveDocument::Ellipse(EllipseDoc { a: *a, b: *b }),
        Curve::Circle { axes, radius } => nurbs_doc(&conic_arc::<3>(axes, *radius, *radius, 0.0, TAU)?),
        Curve::Ellipse { axes, a, b } => nurbs_doc(&conic_arc::<3>(axes, *a, *b, 0.0, TAU)?),
        Curve::Trimmed { basis, start, end } => match basis.as_ref() {
            Curve::Line { origin, direction } => CurveDocument::Line(LineDoc {
                from: origin.iter().zip(direction).map(|(o, d)| o + start * d).collect(),
                to: origin.iter().zip(direction).map(|(o, d)| o + end * d).collect(),
            }),
            Curve::Circle { axes, radius } if is_world(axes) && *start == 0.0 && *end == TAU => {
                CurveDocument::Circle(CircleDoc { radius: *radius })
            }
            Curve::Circle { axes, radius } => nurbs_doc(&conic_arc::<3>(axes, *radius, *radius, *start, *end)?),
            Curve::Ellipse { axes, a, b } => nurbs_doc(&conic_arc::<3>(axes, *a, *b, *start, *end)?),
            Curve::Spline(s) => nurbs_doc(&spline_piece::<3>(s, *start, *end)?),
            Curve::Trimmed { .. } => return Ok(None),
        },
    }))
}

/// A row or column of a control net with its weights (rational nets).
type WeightedLine = (Vec<Vec<f64>>, Option<Vec<f64>>);

fn spline_surface_doc(s: &SplineSurface) -> SurfaceDocument {
    let (p, q) = s.degrees;
    let mut points = s.points.clone();
    let mut weights = s.weights.clone();
    let (mut ku, mut kv) = (s.knots_u.clone(), s.knots_v.clone());
    let mut periodic = (false, false);
    if s.closed.0 {
        let rows: Vec<WeightedLine> =
            points.iter().enumerate().map(|(i, r)| (r.clone(), weights.as_ref().map(|w| w[i].clone()))).collect();
        if let Some((rows, k)) = periodic_form(&rows, &ku, p) {
            weights = weights.as_ref().map(|_| rows.iter().map(|(_, w)| w.clone().unwrap_or_default()).collect());
            points = rows.into_iter().map(|(r, _)| r).collect();
            ku = k;
            periodic.0 = true;
        }
    }
    if s.closed.1 {
        let cols: Vec<WeightedLine> = (0..points[0].len())
            .map(|j| {
                (
                    points.iter().map(|r| r[j].clone()).collect(),
                    weights.as_ref().map(|w| w.iter().map(|r| r[j]).collect()),
                )
            })
            .collect();
        if let Some((cols, k)) = periodic_form(&cols, &kv, q) {
            points = (0..points.len()).map(|i| cols.iter().map(|(c, _)| c[i].clone()).collect()).collect();
            weights = weights.as_ref().map(|_| {
                (0..points.len())
                    .map(|i| cols.iter().map(|(_, w)| w.as_ref().map_or(1.0, |w| w[i])).collect())
                    .collect()
            });
            kv = k;
            periodic.1 = true;
        }
    }
    let doc = match &weights {
        None => SurfaceDocument::BsplineSurface(BSplineSurfaceDoc {
            degree_u: p,
            degree_v: q,
            knots_u: ku,
            knots_v: kv,
            control_points: points,
            periodic_u: periodic.0,
            periodic_v: periodic.1,
        }),
        Some(w) => SurfaceDocument::NurbsSurface(NurbsSurfaceDoc {
            degree_u: p,
            degree_v: q,
            knots_u: ku,
            knots_v: kv,
            control_points: points,
            weights: w.clone(),
            periodic_u: periodic.0,
            periodic_v: periodic.1,
        }),
    };
    if periodic != (false, false) && doc.build().is_err() {
        return spline_surface_doc(&SplineSurface { closed: (false, false), ..s.clone() });
    }
    doc
}

/// The revolution (about the placement's axis) of a profile curve document in the
/// half-plane at angle u₀, by the angle u₁ − u₀.
fn revolution(axes: &Axes, profile: CurveDocument, angle: f64) -> SurfaceDocument {
    SurfaceDocument::Revolution(RevolutionDoc {
        curve: Box::new(profile),
        axis_point: v3(axes.origin),
        axis: v3(axes.z),
        angle,
    })
}

/// A model surface (sphere, torus: the parametrisation of STEP's) in a placement.
fn placed(axes: &Axes, surface: SurfaceDocument) -> SurfaceDocument {
    SurfaceDocument::Placed(PlacedDoc {
        surface: Box::new(surface),
        origin: v3(axes.origin),
        axis: v3(axes.z),
        ref_direction: v3(axes.x),
    })
}

/// A bounded quadric as a document: the model surface when it sits where the export puts
/// it, a placed sphere or torus over its whole domain, else an exact revolution of its
/// profile (line or arc) starting at u₀.
fn quadric_doc(basis: &Surface, (u0, u1): (f64, f64), (v0, v1): (f64, f64)) -> Result<Option<SurfaceDocument>> {
    let full = u0 == 0.0 && u1 == TAU;
    Ok(Some(match basis {
        Surface::Cylinder { axes, radius } if is_world(axes) && full && v0 == 0.0 => {
            SurfaceDocument::Cylinder(CylinderDoc { radius: *radius, height: v1 })
        }
        Surface::Sphere { axes, radius } if is_world(axes) && full && (v0, v1) == (-FRAC_PI_2, FRAC_PI_2) => {
            SurfaceDocument::Sphere(SphereDoc { radius: *radius })
        }
        Surface::Torus { axes, major_radius, minor_radius } if is_world(axes) && full && (v0, v1) == (0.0, TAU) => {
            SurfaceDocument::Torus(TorusDoc { major_radius: *major_radius, minor_radius: *minor_radius })
        }
        Surface::Sphere { axes, radius } if full && (v0, v1) == (-FRAC_PI_2, FRAC_PI_2) => {
            placed(axes, SurfaceDocument::Sphere(SphereDoc { radius: *radius }))
        }
        Surface::Torus { axes, major_radius, minor_radius } if full && (v0, v1) == (0.0, TAU) => {
            placed(axes, SurfaceDocument::Torus(TorusDoc { major_radius: *major_radius, minor_radius: *minor_radius }))
        }
        Surface::Cylinder { axes, radius } | Surface::Cone { axes, radius, .. } => {
            let slope = if let Surface::Cone { semi_angle, .. } = basis { semi_angle.tan() } else { 0.0 };
            let e = radial(axes, u0);
            let at = |v: f64| -> Vec<f64> {
                (0..3).map(|k| axes.origin[k] + (radius + v * slope) * e[k] + v * axes.z[k]).collect()
            };
            revolution(axes, CurveDocument::Line(LineDoc { from: at(v0), to: at(v1) }), u1 - u0)
        }
        Surface::Sphere { axes, radius } => {
            let meridian = Axes { origin: axes.origin, z: radial(axes, u0).cross(&axes.z), x: radial(axes, u0) };
            let frame = CircleFrame { center: axes.origin, x_axis: meridian.x, y_axis: axes.z, radius: *radius };
            let arc = NurbsCurve::<3>::arc(&frame, v0, v1).map_err(|e| StepError::plain(format!("sphere: {e}")))?;
            revolution(axes, nurbs_doc(&arc), u1 - u0)
        }
        Surface::Torus { axes, major_radius, minor_radius } => {
            let e = radial(axes, u0);
            let centre = Point::<3>::from_fn(|k, _| axes.origin[k] + major_radius * e[k]);
            let frame = CircleFrame { center: centre, x_axis: e, y_axis: axes.z, radius: *minor_radius };
            let arc = NurbsCurve::<3>::arc(&frame, v0, v1).map_err(|e| StepError::plain(format!("torus: {e}")))?;
            revolution(axes, nurbs_doc(&arc), u1 - u0)
        }
        _ => return Ok(None),
    }))
}

/// A free surface as a document (bounded: splines, trimmed surfaces); `None` where no
/// document form exists (unbounded surfaces outside faces).
fn surface_doc(s: &Surface) -> Result<Option<SurfaceDocument>> {
    Ok(match s {
        Surface::Spline(b) => Some(spline_surface_doc(b)),
        Surface::Trimmed { basis, u, v } => match basis.as_ref() {
            Surface::Plane(a) => Some(plane_doc(a, *u, *v)),
            Surface::Spline(b) if *u == domain(&b.knots_u, b.degrees.0) && *v == domain(&b.knots_v, b.degrees.1) => {
                Some(spline_surface_doc(b))
            }
            Surface::Revolution { profile, axis_origin, axis } if u.0 == 0.0 => {
                let Some(c) = trimmed_profile(profile, *v)? else { return Ok(None) };
                Some(SurfaceDocument::Revolution(RevolutionDoc {
                    curve: Box::new(c),
                    axis_point: v3(*axis_origin),
                    axis: v3(*axis),
                    angle: u.1,
                }))
            }
            Surface::Extrusion { profile, direction } if v.0 == 0.0 => {
                let Some(c) = trimmed_profile(profile, *u)? else { return Ok(None) };
                Some(SurfaceDocument::Extrusion(ExtrusionDoc {
                    curve: Box::new(c),
                    direction: v3(direction.map(|d| d * v.1)),
                }))
            }
            other => quadric_doc(other, *u, *v)?,
        },
        _ => None,
    })
}

fn domain(knots: &[f64], p: usize) -> (f64, f64) {
    (knots[p], knots[knots.len() - 1 - p])
}

/// The profile curve's document on [a, b] of its parameter.
fn trimmed_profile(c: &Curve, (a, b): (f64, f64)) -> Result<Option<CurveDocument>> {
    match c {
        Curve::Spline(s) if (a, b) == domain(&s.knots, s.degree) => curve_doc(c),
        _ => curve_doc(&Curve::Trimmed { basis: Box::new(c.clone()), start: a, end: b }),
    }
}

fn plane_doc(a: &Axes, (u0, u1): (f64, f64), (v0, v1): (f64, f64)) -> SurfaceDocument {
    let y = a.y();
    SurfaceDocument::Plane(PlaneDoc {
        origin: v3(a.at(u0, v0, 0.0)),
        u_axis: v3(a.x.map(|c| c * (u1 - u0))),
        v_axis: v3(y.map(|c| c * (v1 - v0))),
    })
}

/// The same NURBS curve run backwards, c(a + b − t): points, weights and knots reversed.
fn reversed_nurbs(c: &NurbsCurve<2>) -> Result<NurbsCurve<2>> {
    let d = c.domain();
    let knots = c.knots().iter().rev().map(|k| d.start + d.end - k).collect();
    let points = c.control_points().iter().rev().copied().collect();
    let weights = c.weights().iter().rev().copied().collect();
    NurbsCurve::new(c.degree(), knots, points, weights).map_err(|e| StepError::plain(format!("loop: {e}")))
}

/// One piece of a parameter-space loop as a clamped 2-D NURBS curve (a piece trimmed with
/// `start > end` runs against its parameter).
fn loop_piece(c: &Curve) -> Result<Option<NurbsCurve<2>>> {
    let Curve::Trimmed { basis, start, end } = c else { return Ok(None) };
    if start > end {
        let forward = Curve::Trimmed { basis: basis.clone(), start: *end, end: *start };
        return loop_piece(&forward)?.map(|p| reversed_nurbs(&p)).transpose();
    }
    Ok(Some(match basis.as_ref() {
        Curve::Line { origin, direction } => {
            let at = |t: f64| Point::<2>::new(origin[0] + t * direction[0], origin[1] + t * direction[1]);
            NurbsCurve::new(1, vec![0.0, 0.0, 1.0, 1.0], vec![at(*start), at(*end)], vec![1.0, 1.0])
                .map_err(|e| StepError::plain(format!("loop: {e}")))?
        }
        Curve::Circle { axes, radius } => conic_arc::<2>(axes, *radius, *radius, *start, *end)?,
        Curve::Ellipse { axes, a, b } => conic_arc::<2>(axes, *a, *b, *start, *end)?,
        Curve::Spline(s) => spline_piece::<2>(s, *start, *end)?,
        Curve::Trimmed { .. } => return Ok(None),
    }))
}

/// A loop's pieces as clamped 2-D NURBS curves in the document's (u, v), each with what it
/// is: mapped by `map`, seam sides chosen, moved by whole periods to run on from one
/// another, and bridged where one does not start where the one before it ends (the
/// degenerate edge at a pole, which writers leave out: a [`Role::Pole`] piece). `None`
/// where a piece has no NURBS form.
pub(crate) fn loop_parts(
    pieces: &[Curve],
    seam_twins: &[Option<(u64, Curve)>],
    roles: &[Role],
    map: &dyn Fn(Point<2>) -> Point<2>,
    periodic: (bool, bool),
) -> Result<Option<Vec<(NurbsCurve<2>, Role)>>> {
    let mut parts = Vec::new();
    let mut twins = Vec::new();
    for (c, twin) in pieces.iter().zip(seam_twins) {
        let Some(p) = loop_piece(c)? else { return Ok(None) };
        parts.push(mapped(&p, map)?);
        twins.push(match twin {
            Some((edge, t)) => match loop_piece(t)? {
                Some(t) => Some((*edge, mapped(&t, map)?)),
                None => return Ok(None),
            },
            None => None,
        });
    }
    choose_seam_sides(&mut parts, twins);
    align_periods(&mut parts, periodic);
    Ok(Some(bridge_gaps(parts.into_iter().zip(roles.iter().copied()).collect())?))
}

/// The curve with its control points mapped by `map`; an error where the map gives a
/// point that is not finite (a face whose loops span no area).
fn mapped(c: &NurbsCurve<2>, map: &dyn Fn(Point<2>) -> Point<2>) -> Result<NurbsCurve<2>> {
    if c.control_points().iter().any(|q| !map(*q).iter().all(|x| x.is_finite())) {
        return Err(StepError::plain("a face's loops span no area of its surface"));
    }
    Ok(c.map_points(|q| map(*q)))
}

/// Parts end to end as one clamped NURBS loop: every part elevated to the highest degree,
/// its parameter mapped onto [k, k + 1], joints kept at multiplicity p (exact).
pub(crate) fn join_parts(parts: &[NurbsCurve<2>]) -> Result<NurbsCurve<2>> {
    let p = parts.iter().map(|c| c.degree()).max().unwrap_or(1);
    let err = |e: splinekit::Error| StepError::plain(format!("loop: {e}"));
    let mut knots = vec![0.0; p + 1];
    let (mut points, mut weights) = (Vec::new(), Vec::new());
    for (k, c) in parts.iter().enumerate() {
        let c = c.elevate_degree(p - c.degree()).map_err(err)?;
        let d = c.domain();
        let inner: Vec<f64> =
            c.knots()[p + 1..c.knots().len() - p - 1].iter().map(|t| k as f64 + (t - d.start) / d.length()).collect();
        knots.extend(inner);
        knots.extend(std::iter::repeat_n((k + 1) as f64, if k + 1 == parts.len() { p + 1 } else { p }));
        let skip = usize::from(k > 0);
        points.extend(c.control_points()[skip..].iter().copied());
        weights.extend_from_slice(&c.weights()[skip..]);
    }
    let first = points[0];
    let last = points.len() - 1;
    points[last] = first; // the loop closes; pieces meet at shared vertices
    NurbsCurve::new(p, knots, points, weights).map_err(err)
}

/// Loop pieces end to end as one clamped NURBS loop ([`loop_parts`], [`join_parts`]).
fn join_loop(
    pieces: &[Curve],
    seam_twins: &[Option<(u64, Curve)>],
    roles: &[Role],
    map: &dyn Fn(Point<2>) -> Point<2>,
    periodic: (bool, bool),
) -> Result<Option<CurveDocument>> {
    let Some(parts) = loop_parts(pieces, seam_twins, roles, map, periodic)? else { return Ok(None) };
    let parts: Vec<NurbsCurve<2>> = parts.into_iter().map(|(c, _)| c).collect();
    Ok(Some(nurbs_doc(&join_parts(&parts)?)))
}

/// The box of a face's loops in its (u, v) plane: the box of the loops' control points
/// (which hold the loops); `None` without points.
fn loops_box(f: &Face) -> Result<Option<Aabb<2>>> {
    let mut b = Aabb::<2>::empty();
    for c in f.loops.iter().flatten() {
        let Some(p) = loop_piece(c)? else { return Ok(None) };
        p.control_points().iter().for_each(|q| b.include(q));
    }
    Ok((!b.is_empty()).then_some(b))
}

/// Whether [`curve_doc`] keeps the curve's parameter (splines, lines, conics at the world
/// frame), so that a face's pcurves over a surface swept from it stay valid.
fn keeps_parameter(c: &Curve) -> bool {
    match c {
        Curve::Spline(_) | Curve::Line { .. } => true,
        Curve::Circle { axes, .. } | Curve::Ellipse { axes, .. } => is_world(axes),
        Curve::Trimmed { .. } => false,
    }
}

/// A curve document moved by `offset` (splines, Bézier curves and lines; `None` for the
/// model curves, which have no placement).
fn translated(doc: CurveDocument, offset: Point<3>) -> Option<CurveDocument> {
    let shift = |pts: &mut Vec<Vec<f64>>| {
        pts.iter_mut().for_each(|p| p.iter_mut().zip(offset.iter()).for_each(|(x, o)| *x += o))
    };
    Some(match doc {
        CurveDocument::Bspline(mut d) => {
            shift(&mut d.control_points);
            CurveDocument::Bspline(d)
        }
        CurveDocument::Nurbs(mut d) => {
            shift(&mut d.control_points);
            CurveDocument::Nurbs(d)
        }
        CurveDocument::Line(mut d) => {
            let mut ends = vec![d.from, d.to];
            shift(&mut ends);
            (d.from, d.to) = (ends[0].clone(), ends[1].clone());
            CurveDocument::Line(d)
        }
        _ => return None,
    })
}

/// A face's surface as a document and the map of its (u, v) onto the document's.
pub(crate) type FaceSurface = (SurfaceDocument, Box<dyn Fn(Point<2>) -> Point<2>>);

/// The document of a face's surface: splines and revolutions keep their parameters, and so
/// do spheres and tori (`placed` model surfaces, whose parametrisation is STEP's); a plane
/// spans the loops' box (loops map onto [0, 1]²); a cylinder or cone is the exact
/// revolution of its generatrix and an extrusion its profile moved to the loops' lowest v,
/// both spanning the loops' v range (v maps onto [0, 1]). `None` for other surfaces.
pub(crate) fn face_surface(f: &Face) -> Result<Option<FaceSurface>> {
    let identity = |q: Point<2>| q;
    let span_v = |b: Aabb<2>| {
        let (v0, dv) = (b.min[1], b.max[1] - b.min[1]);
        Box::new(move |q: Point<2>| Point::<2>::new(q[0], (q[1] - v0) / dv)) as Box<dyn Fn(Point<2>) -> Point<2>>
    };
    Ok(Some(match &f.surface {
        Surface::Spline(b) => (spline_surface_doc(b), Box::new(identity)),
        Surface::Plane(a) => {
            let Some(Aabb { min: lo, max: hi }) = loops_box(f)? else { return Ok(None) };
            let size = hi - lo;
            (plane_doc(a, (lo[0], hi[0]), (lo[1], hi[1])), Box::new(move |q: Point<2>| (q - lo).component_div(&size)))
        }
        Surface::Revolution { profile, axis_origin, axis } if keeps_parameter(profile) => {
            let Some(c) = curve_doc(profile)? else { return Ok(None) };
            let doc = RevolutionDoc { curve: Box::new(c), axis_point: v3(*axis_origin), axis: v3(*axis), angle: TAU };
            (SurfaceDocument::Revolution(doc), Box::new(identity))
        }
        Surface::Sphere { axes, radius } => {
            (placed(axes, SurfaceDocument::Sphere(SphereDoc { radius: *radius })), Box::new(identity))
        }
        Surface::Torus { axes, major_radius, minor_radius } => {
            let torus = TorusDoc { major_radius: *major_radius, minor_radius: *minor_radius };
            (placed(axes, SurfaceDocument::Torus(torus)), Box::new(identity))
        }
        Surface::Cylinder { axes, radius } | Surface::Cone { axes, radius, .. } => {
            let Some(b) = loops_box(f)? else { return Ok(None) };
            // The generatrix at u = 0: o + (r + v tan α) x + v z, v the height (ISO
            // 10303-42's CONICAL_SURFACE, in which OpenCASCADE writes its pcurves; α = 0
            // for the cylinder).
            let slope = if let Surface::Cone { semi_angle, .. } = &f.surface { semi_angle.tan() } else { 0.0 };
            let at = |v: f64| v3(axes.at(radius + v * slope, 0.0, v));
            let line = LineDoc { from: at(b.min[1]), to: at(b.max[1]) };
            let doc = RevolutionDoc {
                curve: Box::new(CurveDocument::Line(line)),
                axis_point: v3(axes.origin),
                axis: v3(axes.z),
                angle: TAU,
            };
            (SurfaceDocument::Revolution(doc), span_v(b))
        }
        Surface::Extrusion { profile, direction } if keeps_parameter(profile) => {
            let Some(b) = loops_box(f)? else { return Ok(None) };
            let (v0, dv) = (b.min[1], b.max[1] - b.min[1]);
            let Some(c) = curve_doc(profile)? else { return Ok(None) };
            let Some(c) = translated(c, direction.map(|d| d * v0)) else { return Ok(None) };
            let doc = ExtrusionDoc { curve: Box::new(c), direction: v3(direction.map(|d| d * dv)) };
            (SurfaceDocument::Extrusion(doc), span_v(b))
        }
        _ => return Ok(None),
    }))
}

/// Pieces with a straight segment (a [`Role::Pole`]) wherever one does not start where the
/// one before it ends (cyclically): a degenerate edge at a pole, which STEP writers leave
/// out, is a point in space but a segment of the parameter plane. The twins of cuts are
/// renumbered past the inserted segments.
fn bridge_gaps(parts: Vec<(NurbsCurve<2>, Role)>) -> Result<Vec<(NurbsCurve<2>, Role)>> {
    let start = |c: &NurbsCurve<2>| c.control_points()[0];
    let end = |c: &NurbsCurve<2>| c.control_points()[c.control_points().len() - 1];
    let scale = parts.iter().flat_map(|c| c.0.control_points()).fold(1.0_f64, |m, q| m.max(q.amax()));
    let n = parts.len();
    let mut out = Vec::with_capacity(n + 2);
    let mut index = Vec::with_capacity(n);
    for k in 0..n {
        let (a, b) = (end(&parts[k].0), start(&parts[(k + 1) % n].0));
        index.push(out.len());
        out.push(parts[k].clone());
        if (b - a).norm() > GAP_TOLERANCE * scale {
            let line = NurbsCurve::new(1, vec![0.0, 0.0, 1.0, 1.0], vec![a, b], vec![1.0, 1.0])
                .map_err(|e| StepError::plain(format!("loop: {e}")))?;
            out.push((line, Role::Pole));
        }
    }
    for (_, role) in &mut out {
        if let Role::Cut { twin } = role {
            *twin = index[*twin];
        }
    }
    Ok(out)
}

/// Each piece after the first moved by whole turns (2π, along the periodic angles) to start
/// where the one before it ends: a loop across a seam (around a torus' tube through v = 0)
/// has pieces whose parameters writers give on either side of it (OpenCASCADE: the tube
/// circles' arcs over [2π − 0.6, 2π + 0.9] beside u-circles at v = −0.6 and 0.9).
fn align_periods(parts: &mut [NurbsCurve<2>], periodic: (bool, bool)) {
    let start = |c: &NurbsCurve<2>| c.control_points()[0];
    let end = |c: &NurbsCurve<2>| c.control_points()[c.control_points().len() - 1];
    let turns = |gap: f64, on: bool| {
        let n = (gap / TAU).round();
        if on && n != 0.0 && (gap - n * TAU).abs() <= 1e-6 { n * TAU } else { 0.0 }
    };
    for k in 1..parts.len() {
        let gap = start(&parts[k]) - end(&parts[k - 1]);
        let shift = Point::<2>::new(turns(gap[0], periodic.0), turns(gap[1], periodic.1));
        if shift != Point::<2>::zeros() {
            parts[k] = parts[k].map_points(|q| q - shift);
        }
    }
}

/// Relative distance in the parameter plane below which consecutive loop pieces meet.
const GAP_TOLERANCE: f64 = 1e-9;

/// Most seam uses in one loop whose sides are chosen by trying every combination.
const MAX_SEAM_USES: usize = 10;

/// Each use of a seam edge runs along one of its two pcurves, and a loop that uses one
/// seam edge twice runs once along each: of the choices of sides that respect this, the
/// one that leaves the smallest total gap between consecutive pieces (cyclically). A loop
/// around a pole has a gap where the degenerate edge at the pole was left out, but the
/// right sides still leave the smallest. Every combination is tried (at most
/// 2^[`MAX_SEAM_USES`]; beyond that the first pcurves stay).
fn choose_seam_sides(parts: &mut [NurbsCurve<2>], twins: Vec<Option<(u64, NurbsCurve<2>)>>) {
    let seams: Vec<usize> = (0..parts.len()).filter(|&k| twins[k].is_some()).collect();
    if seams.is_empty() || seams.len() > MAX_SEAM_USES {
        return;
    }
    let edge = |k: usize| twins[k].as_ref().map(|t| t.0);
    let start = |c: &NurbsCurve<2>| c.control_points()[0];
    let end = |c: &NurbsCurve<2>| c.control_points()[c.control_points().len() - 1];
    let twin_taken = |bit: usize, mask: usize| mask >> bit & 1 == 1;
    let pick = |k: usize, mask: usize| -> &NurbsCurve<2> {
        match seams.iter().position(|&s| s == k) {
            Some(bit) if twin_taken(bit, mask) => &twins[k].as_ref().expect("a seam").1,
            _ => &parts[k],
        }
    };
    // Two uses of one edge take different sides.
    let respects_pairs = |mask: usize| {
        seams.iter().enumerate().all(|(a, &i)| {
            seams
                .iter()
                .enumerate()
                .skip(a + 1)
                .all(|(b, &j)| edge(i) != edge(j) || twin_taken(a, mask) != twin_taken(b, mask))
        })
    };
    let n = parts.len();
    let gap =
        |mask: usize| -> f64 { (0..n).map(|k| (start(pick((k + 1) % n, mask)) - end(pick(k, mask))).norm()).sum() };
    let best = (0..1usize << seams.len())
        .filter(|&m| respects_pairs(m))
        .min_by(|&a, &b| gap(a).total_cmp(&gap(b)))
        .unwrap_or(0);
    let chosen: Vec<NurbsCurve<2>> = (0..n).map(|k| pick(k, best).clone()).collect();
    parts.clone_from_slice(&chosen);
}

/// Which of a face surface's parameters are angles of period 2π (u around an axis, and v
/// around a torus' tube).
fn periodic_angles(s: &Surface) -> (bool, bool) {
    match s {
        Surface::Torus { .. } => (true, true),
        Surface::Sphere { .. } | Surface::Cylinder { .. } | Surface::Cone { .. } | Surface::Revolution { .. } => {
            (true, false)
        }
        _ => (false, false),
    }
}

/// The periodic angles along which a loop's pieces are aligned by whole turns: those of
/// surfaces without poles (tori, cylinders). On a sphere, a cone or a revolution a gap of a
/// whole turn in u is the degenerate edge at a pole or apex, which writers leave out and
/// the loop bridges.
pub(crate) fn seam_crossings(s: &Surface) -> (bool, bool) {
    match s {
        Surface::Torus { .. } => (true, true),
        Surface::Cylinder { .. } => (true, false),
        _ => (false, false),
    }
}

/// The map of a face's (u, v) followed by the shift of a whole number of turns that brings
/// its loops' lowest u (and v, around a torus' tube) into [0, 2π) where the document's
/// angle is periodic: STEP writers place faces at any angle (OpenCASCADE's cones run over
/// u ∈ [−α, 0]), the documents' domains start at 0. Loops across the seam stay as they are.
pub(crate) fn into_domain(
    f: &Face,
    map: Box<dyn Fn(Point<2>) -> Point<2>>,
) -> Result<Box<dyn Fn(Point<2>) -> Point<2>>> {
    let periodic = periodic_angles(&f.surface);
    let Some(b) = loops_box(f)? else { return Ok(map) };
    let low = map(b.min);
    let turns = |x: f64, on: bool| if on { -((x + 1e-9) / TAU).floor() * TAU } else { 0.0 };
    let shift = Point::<2>::new(turns(low[0], periodic.0), turns(low[1], periodic.1));
    if shift == Point::<2>::zeros() {
        return Ok(map);
    }
    Ok(Box::new(move |q| map(q) + shift))
}

/// A face as a `trimmed` document; a face without edge loops (a whole sphere, bounded by
/// a vertex loop at a pole) or bounded by seams alone (a whole torus) as its surface's
/// document.
fn face_doc(f: &Face) -> Result<Option<SurfaceDocument>> {
    let Some((surface, map)) = face_surface(f)? else { return Ok(None) };
    // No edge loop, or one made of seam edges only (a whole torus: its two seams, each
    // used both ways): the face is the whole domain.
    let only_seams = f.loops.len() == 1 && f.seam_twins[0].iter().all(Option::is_some);
    if f.loops.is_empty() || only_seams {
        return Ok(Some(surface));
    }
    let map = into_domain(f, map)?;
    let mut outer = None;
    let mut holes = Vec::new();
    for (i, l) in f.loops.iter().enumerate() {
        let Some(doc) = join_loop(l, &f.seam_twins[i], &f.roles[i], map.as_ref(), seam_crossings(&f.surface))? else {
            return Ok(None);
        };
        if Some(i) == f.outer || (f.outer.is_none() && i == 0) {
            outer = Some(Box::new(doc));
        } else {
            holes.push(doc);
        }
    }
    Ok(Some(SurfaceDocument::Trimmed(TrimmedDoc { surface: Box::new(surface), outer, holes })))
}
