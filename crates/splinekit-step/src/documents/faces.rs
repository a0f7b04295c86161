//! `trimmed` documents → STEP faces: the surface's own export (exact where it has one), and
//! per trimming loop one closed edge: its pcurve is the loop as a B-spline in the STEP
//! surface's (u, v) (the document's loop through the surface's affine [`ParamMap`], exact
//! for B-spline, NURBS, Bézier, line and conic loops, else a quintic Hermite B-spline within
//! the tolerance in (u, v)), its 3-D curve the quintic Hermite B-spline of S(c(t)) over the
//! same parameter t within the surface's tolerance, its one vertex S(c(t₀)) = S(c(t₁)).
//! Without an outer loop the face is bounded by the domain's rectangle: its natural bounds,
//! seams on closed surfaces, no edge where a side is one point (see `domain_rectangle`).
//! Bounds carry the orientation flag that puts the material on the left in (u, v): outer
//! loops counter-clockwise, holes clockwise, by the sign of the loop's area
//! ½∮(u dv − v du).

use splinekit::Point;
use splinekit::basis::Side;
use splinekit::curve::{CircleFrame, Curve as KernelCurve, Interval, NurbsCurve};
use splinekit::surface::Surface as KernelSurface;
use splinekit_scene::CurveDocument;
use splinekit_scene::surfaces::TrimmedDoc;
use std::f64::consts::TAU;

use super::curve_export::export_curve;
use super::exported::{Exported, Form, ParamMap};
use crate::approximate::hermite_curve;
use crate::error::{Result, StepError};
use crate::geometry::{Curve, FaceEdge, FaceGeometry, FaceLoop, Geometry, LoopEdge, SplineCurve, Surface};

/// Largest distance between an edge's 3-D curve and S(pcurve), relative to the size of
/// the surface (and never more than the surface's own tolerance).
pub const EDGE_TOLERANCE: f64 = 1e-10;

/// A loop c(t) in the document's (u, v) carried onto the surface: C(t) = S(c(t)), with
/// C' = S_u u' + S_v v' and C'' = S_uu u'² + 2 S_uv u'v' + S_vv v'² + S_u u'' + S_v v''
/// (derivatives up to the second; higher ones are not asked for by the fit).
struct OnSurface<'a> {
    surface: &'a dyn KernelSurface<3>,
    curve: &'a NurbsCurve<2>,
}

impl KernelCurve<3> for OnSurface<'_> {
    fn domain(&self) -> Interval {
        self.curve.domain()
    }
    fn eval_side(&self, t: f64, side: Side, out: &mut [Point<3>]) {
        let n = out.len().min(3);
        let mut c = [Point::<2>::zeros(); 3];
        self.curve.eval_side(t, side, &mut c[..n]);
        let mut s = [Point::<3>::zeros(); 9];
        self.surface.eval_partials(c[0][0], c[0][1], 2, 2, &mut s);
        let d = |i: usize, j: usize| s[i * 3 + j];
        let (u1, v1, u2, v2) = (c[1][0], c[1][1], c[2][0], c[2][1]);
        let values = [
            d(0, 0),
            d(1, 0) * u1 + d(0, 1) * v1,
            d(2, 0) * u1 * u1 + d(1, 1) * (2.0 * u1 * v1) + d(0, 2) * v1 * v1 + d(1, 0) * u2 + d(0, 1) * v2,
        ];
        out[..n].copy_from_slice(&values[..n]);
        out[n..].iter_mut().for_each(|o| *o = Point::<3>::zeros());
    }
    fn breakpoints(&self) -> Vec<f64> {
        self.curve.breakpoints()
    }
}

/// A trimming loop as a 2-D NURBS curve in the document's (u, v), and whether it had to be
/// approximated (loops without an exact B-spline form).
fn loop_curve(doc: &CurveDocument, field: &str, relative_tolerance: f64) -> Result<(NurbsCurve<2>, bool)> {
    let within = |e: StepError| StepError::plain(format!("{field}: {}", e.message));
    let exported = export_curve(doc, "", relative_tolerance).map_err(within)?;
    let approximated = exported.form == Form::Approximated;
    let Geometry::Curve(c) = exported.item.geometry else { unreachable!("a curve exports as a curve") };
    let err = |e: splinekit::Error| StepError::plain(format!("{field}: {e}"));
    let p2 = |p: &[f64]| Point::<2>::new(p[0], p[1]);
    let arc = |axes: &crate::geometry::Axes, a: f64, b: f64| {
        let frame = CircleFrame {
            center: p2(axes.origin.as_slice()),
            x_axis: p2(axes.x.map(|x| x * a).as_slice()),
            y_axis: p2(axes.y().map(|y| y * b).as_slice()),
            radius: 1.0,
        };
        NurbsCurve::arc(&frame, 0.0, TAU).map_err(err)
    };
    let curve = match &c {
        Curve::Spline(s) => crate::kernel::nurbs::<2>(s).map_err(within)?,
        Curve::Circle { axes, radius } => arc(axes, *radius, *radius)?,
        Curve::Ellipse { axes, a, b } => arc(axes, *a, *b)?,
        Curve::Trimmed { basis, start, end } => match basis.as_ref() {
            Curve::Line { origin, direction } => {
                let at = |t: f64| Point::<2>::new(origin[0] + t * direction[0], origin[1] + t * direction[1]);
                NurbsCurve::new(1, vec![0.0, 0.0, 1.0, 1.0], vec![at(*start), at(*end)], vec![1.0; 2]).map_err(err)?
            }
            _ => return Err(StepError::plain(format!("{field}: no B-spline form of this loop"))),
        },
        Curve::Line { .. } => return Err(StepError::plain(format!("{field}: a line is no closed loop"))),
    };
    Ok((curve, approximated))
}

/// ½∮(u dv − v du) of a closed 2-D curve by the shoelace formula on 1024 samples: positive
/// when it runs counter-clockwise.
fn signed_area(c: &NurbsCurve<2>) -> f64 {
    let d = c.domain();
    let pts: Vec<Point<2>> = (0..1024).map(|i| c.point(d.lerp(i as f64 / 1024.0))).collect();
    0.5 * (0..pts.len())
        .map(|i| {
            let (a, b) = (pts[i], pts[(i + 1) % pts.len()]);
            a[0] * b[1] - b[0] * a[1]
        })
        .sum::<f64>()
}

/// The 2-D spline data of a kernel curve with the STEP surface's map applied to its control
/// points (affine, so exact for rational curves too).
fn mapped_pcurve(c: &NurbsCurve<2>, map: &ParamMap) -> Curve {
    let rational = c.weights().iter().any(|&w| w != 1.0);
    Curve::Spline(SplineCurve {
        degree: c.degree(),
        knots: c.knots().to_vec(),
        points: c.control_points().iter().map(|p| vec![map.u.0 * p[0] + map.u.1, map.v.0 * p[1] + map.v.1]).collect(),
        weights: rational.then(|| c.weights().to_vec()),
        closed: false,
    })
}

/// The edge of a loop piece c: its pcurve through `map` and its fitted 3-D curve.
fn edge(
    surface: &dyn KernelSurface<3>,
    c: &NurbsCurve<2>,
    map: &ParamMap,
    tolerance: f64,
    (start, end): (usize, usize),
    field: &str,
) -> Result<FaceEdge> {
    let on = OnSurface { surface, curve: c };
    let fitted = hermite_curve(&on, tolerance).map_err(|e| StepError::plain(format!("{field}: {}", e.message)))?;
    Ok(FaceEdge { start, end, curve: Curve::Spline(fitted.spline), pcurve: mapped_pcurve(c, map), seam: None })
}

/// A straight segment a → b of the parameter plane on [0, 1].
fn segment(a: (f64, f64), b: (f64, f64)) -> Result<NurbsCurve<2>> {
    NurbsCurve::new(
        1,
        vec![0.0, 0.0, 1.0, 1.0],
        vec![Point::<2>::new(a.0, a.1), Point::<2>::new(b.0, b.1)],
        vec![1.0; 2],
    )
    .map_err(|e| StepError::plain(format!("outer: {e}")))
}

/// The face's bound along the rectangle of the domain, counter-clockwise (the natural
/// bounds, as CAD systems write a whole surface): sides bottom (v₀), right (u₁), top (v₁),
/// left (u₀). On a surface closed in u the right and left sides are one seam edge
/// (`SEAM_CURVE` with both pcurves), used up the right side and back down the left; closed
/// in v, bottom and top likewise. A side whose image is one point (a sphere's pole, a
/// cone's apex) has no edge, as STEP writers leave degenerate edges out. Corners that meet
/// in space share a vertex.
fn domain_rectangle(
    surface: &dyn KernelSurface<3>,
    map: &ParamMap,
    tolerance: f64,
    vertices: &mut Vec<Point<3>>,
) -> Result<FaceLoop> {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let (closed_u, closed_v) = (surface.is_closed_u(), surface.is_closed_v());
    let corners = [(du.start, dv.start), (du.end, dv.start), (du.end, dv.end), (du.start, dv.end)];
    let first = vertices.len();
    let mut corner_vertex = [0; 4];
    for (k, &(u, v)) in corners.iter().enumerate() {
        let p = surface.point(u, v);
        let near = |q: &Point<3>| (q - p).norm() <= tolerance;
        corner_vertex[k] = match vertices[first..].iter().position(near) {
            Some(i) => first + i,
            None => {
                vertices.push(p);
                vertices.len() - 1
            }
        };
    }
    let degenerate = |(a, b): ((f64, f64), (f64, f64))| {
        let start = surface.point(a.0, a.1);
        (1..=16).all(|i| {
            let t = i as f64 / 16.0;
            (surface.point(a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)) - start).norm() <= tolerance
        })
    };
    let side = |k: usize| (corners[k], corners[(k + 1) % 4]);
    let mut edges = Vec::with_capacity(4);
    // Which use (index in `edges`) wrote the edge of sides 0 (bottom) and 1 (right).
    let (mut bottom, mut right) = (None, None);
    for k in 0..4 {
        let (a, b) = side(k);
        if degenerate((a, b)) {
            continue;
        }
        let seam_again = match k {
            2 if closed_v => bottom,
            3 if closed_u => right,
            _ => None,
        };
        if let Some(again) = seam_again {
            edges.push(LoopEdge::Again(again));
            continue;
        }
        let line = segment(a, b)?;
        let mut e = edge(surface, &line, map, tolerance, (corner_vertex[k], corner_vertex[(k + 1) % 4]), "outer")?;
        // The seam's other pcurve runs along the opposite side in this edge's sense.
        let (c, d) = side((k + 2) % 4);
        e.seam = match k {
            0 if closed_v => Some(mapped_pcurve(&segment(d, c)?, map)),
            1 if closed_u => Some(mapped_pcurve(&segment(d, c)?, map)),
            _ => None,
        };
        match k {
            0 => bottom = Some(edges.len()),
            1 => right = Some(edges.len()),
            _ => {}
        }
        edges.push(LoopEdge::Edge(Box::new(e)));
    }
    if edges.is_empty() {
        return Err(StepError::plain(format!(
            "outer: the boundary of the domain [{}, {}] × [{}, {}] is a single point on the surface, no face bound",
            du.start, du.end, dv.start, dv.end
        )));
    }
    Ok(FaceLoop { outer: true, orientation: true, edges })
}

/// The surface a face lies on: a rectangular trimmed surface's basis (the face's bounds
/// take over its parameter range).
fn face_surface(s: Surface) -> Surface {
    match s {
        Surface::Trimmed { basis, .. } => *basis,
        other => other,
    }
}

/// Exports a `trimmed` document as a face; its form is the surface's, or
/// [`Form::Approximated`] when a loop had no exact B-spline form.
///
/// `base` is the export of the document's surface, `kernel` the surface itself (both made
/// by the caller, [`super::export::export_surface`], which dispatches here).
pub fn export_trimmed(
    doc: &TrimmedDoc,
    name: &str,
    relative_tolerance: f64,
    base: Exported,
    kernel: &dyn KernelSurface<3>,
) -> Result<Exported> {
    let Geometry::Surface(surface) = base.item.geometry.clone() else { unreachable!("a surface exports as a surface") };
    let edge_tolerance = base.tolerance.min(EDGE_TOLERANCE * base.tolerance / relative_tolerance);
    let mut vertices = Vec::new();
    let mut loops = Vec::new();
    let mut approximated = false;
    let named: Vec<(String, &CurveDocument, bool)> = doc
        .outer
        .iter()
        .map(|o| ("outer".to_string(), o.as_ref(), true))
        .chain(doc.holes.iter().enumerate().map(|(i, h)| (format!("holes[{i}]"), h, false)))
        .collect();
    if doc.outer.is_none() {
        loops.push(domain_rectangle(kernel, &base.map, edge_tolerance, &mut vertices)?);
    }
    for (field, loop_doc, outer) in named {
        let (c, approx) = loop_curve(loop_doc, &field, relative_tolerance)?;
        approximated |= approx;
        let d = c.domain();
        let (a, b) = (kernel.point(c.point(d.start)[0], c.point(d.start)[1]), {
            let q = c.point(d.end);
            kernel.point(q[0], q[1])
        });
        let gap = (a - b).norm();
        if gap > base.tolerance {
            return Err(StepError::plain(format!(
                "{field}: the loop is not closed on the surface (ends {gap:e} apart)"
            )));
        }
        let vertex = vertices.len();
        vertices.push(a);
        let counter_clockwise = signed_area(&c) > 0.0;
        let e = edge(kernel, &c, &base.map, edge_tolerance, (vertex, vertex), &field)?;
        loops.push(FaceLoop {
            outer,
            orientation: counter_clockwise == outer,
            edges: vec![LoopEdge::Edge(Box::new(e))],
        });
    }
    let face = FaceGeometry { surface: face_surface(surface), vertices, loops };
    Ok(Exported {
        item: crate::geometry::Item { name: name.to_string(), geometry: Geometry::Face(face) },
        form: if approximated { Form::Approximated } else { base.form },
        ..base
    })
}

/// Whether a `trimmed` document leaves exactly: its surface does, every loop is a
/// B-spline, NURBS, Bézier, line or conic (a missing outer loop is the domain's rectangle,
/// whose sides are straight).
pub fn trimmed_exports_exactly(
    doc: &TrimmedDoc,
    surface_exact: bool,
    loop_exact: impl Fn(&CurveDocument) -> bool,
) -> bool {
    surface_exact && doc.outer.as_deref().is_none_or(&loop_exact) && doc.holes.iter().all(loop_exact)
}

/// `count` points of each of a `trimmed` document's loops (outer first when it has one),
/// evaluated by splinekit from the document's own loop curves and carried into the STEP
/// surface's (u, v) by `map`: the region a reader of the face should find.
pub fn loop_samples(doc: &TrimmedDoc, map: &ParamMap, count: usize) -> Result<Vec<Vec<(f64, f64)>>> {
    let loops = doc.outer.iter().map(|o| ("outer".to_string(), o.as_ref()));
    let loops = loops.chain(doc.holes.iter().enumerate().map(|(i, h)| (format!("holes[{i}]"), h)));
    loops
        .map(|(field, c)| {
            let k = c.build_in::<2>().map_err(|e| StepError::plain(format!("{field}: {e}")))?;
            let d = k.domain();
            Ok((0..count)
                .map(|i| {
                    let q = k.point(d.lerp(i as f64 / count as f64));
                    (map.u.0 * q[0] + map.u.1, map.v.0 * q[1] + map.v.1)
                })
                .collect())
        })
        .collect()
}
