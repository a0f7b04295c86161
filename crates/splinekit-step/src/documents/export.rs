//! Shape documents → STEP geometry: the exact entity where STEP has one, else a measured
//! B-spline form (see [`crate::approximate`]).
//!
//! Parametrisations. Splines, Bézier curves and surfaces, circles, ellipses, spheres,
//! tori and revolutions keep their parameters (the STEP object at t is the document's at
//! t). Others take an affine map per direction, listed in [`ParamMap`]: a line is a unit
//! `LINE` trimmed by length (t' = |to − from| t), an extrusion has a unit direction
//! (v' = |direction| v); a plane with orthogonal axes U, V is `PLANE` with u' = |U| u,
//! v' = |V| v (a plane with skew axes is its exact bilinear B-spline instead);
//! a cylinder of height h has v' = h v. A `placed` document is its surface's export moved
//! rigidly into the placement (see [`crate::placement`]). A cone of radius r and height h
//! is `CONICAL_SURFACE` placed at its base with its axis down, u' = 2π − u, v' = −h v (see
//! `cone_surface`). 2-D documents lie in the plane z = 0.

use splinekit::Point;
use splinekit::curve::bezier::bezier_knots;
use splinekit::curve::{Curve as KernelCurve, Interval};
use splinekit::query::extent::sampled_surface_box;
use splinekit::surface::Surface as KernelSurface;
use splinekit::triangle::{BezierTriangle, RationalBezierTriangle, TriangleAtlas};
use splinekit_scene::blending::LocalPatchDoc;
use splinekit_scene::{CurveDocument, ShapeDocument, SurfaceDocument, SurfaceForm};
use std::f64::consts::{FRAC_PI_2, TAU};

use super::curve_export::{
    bfunction_degree, curve_exports_exactly, export_curve, kernel_curve, p3, plain, unrolled_knots,
};
use super::exported::{Exported, Form, ParamMap};
use crate::approximate::{Fitted, hermite_surface, polynomial_surface, uniform_breaks};
use crate::error::{Result, StepError};
use crate::geometry::{Axes, Curve, Geometry, Item, SplineSurface, Surface};
use crate::placement::Placement;
use splinekit_scene::surfaces::PlacedDoc;

fn net3(net: &[Vec<Vec<f64>>]) -> Result<Vec<Vec<Vec<f64>>>> {
    net.iter().map(|row| row.iter().map(|p| p3(p)).collect()).collect()
}

/// Rows (or within each row, columns) of a periodic direction unrolled: index i % n.
fn unroll<T: Clone>(items: &[T], p: usize) -> Vec<T> {
    (0..items.len() + p).map(|i| items[i % items.len()].clone()).collect()
}

#[allow(clippy::too_many_arguments)]
fn spline_surface(
    (p, q): (usize, usize),
    knots_u: &[f64],
    knots_v: &[f64],
    net: &[Vec<Vec<f64>>],
    weights: Option<&[Vec<f64>]>,
    (pu, pv): (bool, bool),
) -> Result<SplineSurface> {
    let mut pts = net3(net)?;
    let mut w = weights.map(<[Vec<f64>]>::to_vec);
    let (nu, nv) = (pts.len(), pts.first().map_or(0, Vec::len));
    let (mut ku, mut kv) = (knots_u.to_vec(), knots_v.to_vec());
    if pu {
        pts = unroll(&pts, p);
        w = w.map(|w| unroll(&w, p));
        ku = unrolled_knots(knots_u, nu, p);
    }
    if pv {
        pts = pts.iter().map(|row| unroll(row, q)).collect();
        w = w.map(|w| w.iter().map(|row| unroll(row, q)).collect());
        kv = unrolled_knots(knots_v, nv, q);
    }
    Ok(SplineSurface { degrees: (p, q), knots_u: ku, knots_v: kv, points: pts, weights: w, closed: (pu, pv) })
}

pub(crate) fn kernel_surface(doc: &SurfaceDocument) -> Result<Box<dyn KernelSurface<3>>> {
    match doc.dimension().map_err(|e| plain("document", e))? {
        3 => doc.build_in::<3>().map_err(|e| plain("document", e)),
        d => Err(StepError::plain(format!("document: STEP surfaces are 3-D, got a {d}-D surface"))),
    }
}

/// The size a relative tolerance refers to: the diagonal of the box of the regular 33 × 33
/// grid of samples ([`sampled_surface_box`]).
fn surface_size(s: &dyn KernelSurface<3>) -> f64 {
    sampled_surface_box(s, 32).diagonal().max(f64::MIN_POSITIVE)
}

fn trimmed(basis: Surface, u: (f64, f64), v: (f64, f64)) -> Surface {
    Surface::Trimmed { basis: Box::new(basis), u, v }
}

/// A profile curve of a swept surface, exact or approximated (its deviation bounds the
/// surface's: revolutions and extrusions move it rigidly).
fn profile(doc: &CurveDocument, relative_tolerance: f64) -> Result<(Curve, Form, f64)> {
    let e = export_curve(doc, "", relative_tolerance)?;
    let Geometry::Curve(c) = e.item.geometry else { unreachable!("a curve exports as a curve") };
    Ok((c, e.form, e.max_deviation))
}

/// The exact STEP surface of a spline, Bézier, plane or quadric document and the map of
/// its parameters; `None` for the kinds without one of their own.
fn elementary_surface(doc: &SurfaceDocument) -> Result<Option<(Surface, ParamMap)>> {
    let id = ParamMap::IDENTITY;
    Ok(Some(match doc.exact_form().map_err(|e| plain("document", e))? {
        SurfaceForm::Spline(view) => {
            let (p, q) = view.degrees;
            let (ku, kv) = match &view.knots {
                Some((ku, kv)) => (ku.to_vec(), kv.to_vec()),
                None => (bezier_knots(p), bezier_knots(q)),
            };
            let weights = view.weights.as_deref();
            let net = spline_surface((p, q), &ku, &kv, &view.control_points, weights, view.periodic)?;
            (Surface::Spline(net), id)
        }
        SurfaceForm::Plane { origin, u_axis, v_axis } => plane_surface(origin, u_axis, v_axis)?,
        SurfaceForm::Cylinder { radius, height } => (
            trimmed(Surface::Cylinder { axes: Axes::WORLD, radius }, (0.0, TAU), (0.0, height)),
            ParamMap { u: (1.0, 0.0), v: (height, 0.0) },
        ),
        SurfaceForm::Cone { radius, height } => cone_surface(radius, height),
        SurfaceForm::Sphere { radius } => {
            (trimmed(Surface::Sphere { axes: Axes::WORLD, radius }, (0.0, TAU), (-FRAC_PI_2, FRAC_PI_2)), id)
        }
        SurfaceForm::Torus { major_radius, minor_radius } => {
            let torus = Surface::Torus { axes: Axes::WORLD, major_radius, minor_radius };
            (trimmed(torus, (0.0, TAU), (0.0, TAU)), id)
        }
        SurfaceForm::Revolution(_)
        | SurfaceForm::Extrusion(_)
        | SurfaceForm::Trimmed(_)
        | SurfaceForm::Placed(_)
        | SurfaceForm::BlendingSpline(_)
        | SurfaceForm::Brep(_)
        | SurfaceForm::Triangles
        | SurfaceForm::Approximate => return Ok(None),
    }))
}

/// A plane o + u U + v V: `PLANE` with u' = |U| u, v' = |V| v when U ⊥ V, else its exact
/// bilinear B-spline.
fn plane_surface(origin: &[f64], u_axis: &[f64], v_axis: &[f64]) -> Result<(Surface, ParamMap)> {
    let (o, u, v) = (p3(origin)?, p3(u_axis)?, p3(v_axis)?);
    let three = |p: Vec<f64>| Point::<3>::new(p[0], p[1], p[2]);
    let (o, u, v) = (three(o), three(u), three(v));
    let (lu, lv) = (u.norm(), v.norm());
    let dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    if dot.abs() <= 1e-14 * lu * lv {
        let x = u.map(|c| c / lu);
        let z = u.cross(&v).map(|c| c / (lu * lv));
        let axes = Axes { origin: o, z, x };
        Ok((trimmed(Surface::Plane(axes), (0.0, lu), (0.0, lv)), ParamMap { u: (lu, 0.0), v: (lv, 0.0) }))
    } else {
        let corner = |a: f64, b: f64| (0..3).map(|k| o[k] + a * u[k] + b * v[k]).collect::<Vec<f64>>();
        let net = vec![vec![corner(0.0, 0.0), corner(0.0, 1.0)], vec![corner(1.0, 0.0), corner(1.0, 1.0)]];
        let k = vec![0.0, 0.0, 1.0, 1.0];
        Ok((Surface::Spline(spline_surface((1, 1), &k, &k, &net, None, (false, false))?), ParamMap::IDENTITY))
    }
}

/// A cone (r (1 − v) cos u, r (1 − v) sin u, h v) as `CONICAL_SURFACE` of radius r and
/// semi-angle α = atan(r/h) > 0 (OpenCASCADE raises a negative one to 10⁻¹²), so that the
/// radius grows along its axis: the placement at the base with z = −Z, x = X, y = −Y,
/// where the point at u′, v′ (v′ the height along z, ISO 10303-42's parameter) is the
/// document's at u = 2π − u′, v = −v′/h (u′ over [0, 2π] as OpenCASCADE keeps it).
fn cone_surface(radius: f64, height: f64) -> (Surface, ParamMap) {
    let axes =
        Axes { origin: Point::<3>::zeros(), z: Point::<3>::new(0.0, 0.0, -1.0), x: Point::<3>::new(1.0, 0.0, 0.0) };
    let cone = Surface::Cone { axes, radius, semi_angle: (radius / height).atan() };
    (trimmed(cone, (0.0, TAU), (-height, 0.0)), ParamMap { u: (-1.0, TAU), v: (-height, 0.0) })
}

/// Revolutions and extrusions: the STEP swept surface of their profile's export (exact when
/// the profile is), with the profile's form and deviation; `None` for other kinds.
fn swept_surface(
    doc: &SurfaceDocument,
    domain: (Interval, Interval),
    relative_tolerance: f64,
) -> Result<Option<(Surface, Form, f64, ParamMap)>> {
    Ok(Some(match doc.exact_form().map_err(|e| plain("document", e))? {
        SurfaceForm::Revolution(d) => {
            let (c, form, dev) = profile(&d.curve, relative_tolerance)?;
            let axis = p3(&d.axis)?;
            let len = Point::<3>::new(axis[0], axis[1], axis[2]).norm();
            let o = p3(&d.axis_point)?;
            let rev = Surface::Revolution {
                profile: c,
                axis_origin: Point::<3>::new(o[0], o[1], o[2]),
                axis: Point::<3>::new(axis[0] / len, axis[1] / len, axis[2] / len),
            };
            (trimmed(rev, (0.0, d.angle), (domain.1.start, domain.1.end)), form, dev, ParamMap::IDENTITY)
        }
        SurfaceForm::Extrusion(d) => {
            let (c, form, dev) = profile(&d.curve, relative_tolerance)?;
            // Unit direction, v' = |direction| v (readers parametrise v by length).
            let dir = p3(&d.direction)?;
            let len = Point::<3>::new(dir[0], dir[1], dir[2]).norm();
            let ext =
                Surface::Extrusion { profile: c, direction: Point::<3>::new(dir[0] / len, dir[1] / len, dir[2] / len) };
            let map = ParamMap { u: (1.0, 0.0), v: (len, 0.0) };
            (trimmed(ext, (domain.0.start, domain.0.end), (0.0, len)), form, dev, map)
        }
        _ => return Ok(None),
    }))
}

/// The degrees (m_u, m_v) = (d_u + β, d_v + β) of the B-spline that a blending-spline surface
/// with Bézier locals of degrees (d_u, d_v) and a polynomial B-function of degree β is (its
/// knots are the blending spline's); `None` for other surfaces.
fn polynomial_blending_degrees(doc: &SurfaceDocument) -> Option<(usize, usize)> {
    let Ok(SurfaceForm::BlendingSpline(b)) = doc.exact_form() else { return None };
    let local = b.local.as_ref().unwrap_or(&LocalPatchDoc::Bezier { degree: [3, 3] });
    match (local, b.bfunction.as_ref().and_then(bfunction_degree)) {
        (LocalPatchDoc::Bezier { degree }, Some(beta)) => Some((degree[0] + beta, degree[1] + beta)),
        _ => None,
    }
}

/// The B-spline form of any other surface: exact for a blending spline with Bézier locals
/// and a polynomial B-function, else a biquintic Hermite approximation within `tolerance`
/// (blending splines on their own knots, the kernel surface's breakpoints; others on a
/// 4 × 4 start grid).
fn fitted_surface(
    doc: &SurfaceDocument,
    kernel: &dyn KernelSurface<3>,
    domain: (Interval, Interval),
    tolerance: f64,
) -> Result<(Fitted<SplineSurface>, Form)> {
    let knots = || (kernel.breakpoints_u(), kernel.breakpoints_v());
    if let Some(degrees) = polynomial_blending_degrees(doc) {
        let (bu, bv) = knots();
        let fitted = polynomial_surface(kernel, &bu, &bv, degrees)?;
        return Ok((fitted, Form::ExactPolynomial { degree: degrees }));
    }
    let (bu, bv) = match doc.exact_form() {
        Ok(SurfaceForm::BlendingSpline(_)) => knots(),
        _ => (uniform_breaks(domain.0, 4), uniform_breaks(domain.1, 4)),
    };
    Ok((hermite_surface(kernel, &bu, &bv, tolerance)?, Form::Approximated))
}

/// Exports a surface document; `relative_tolerance` scales with the surface's size.
pub fn export_surface(doc: &SurfaceDocument, name: &str, relative_tolerance: f64) -> Result<Exported> {
    if let SurfaceDocument::SubdivisionSurface(_) = doc {
        return Err(StepError::plain(
            "subdivision_surface: a limit surface is exported as its patches, one item each (export_document)",
        ));
    }
    let form = doc.exact_form().map_err(|e| plain("document", e))?;
    if let SurfaceForm::Brep(_) = form {
        return Err(StepError::plain("brep: a B-rep is exported face by face, one item each (export_document)"));
    }
    if let SurfaceForm::Triangles = form {
        let mut items = export_triangles(doc, name, relative_tolerance)?;
        if items.len() != 1 {
            return Err(StepError::plain(format!(
                "{}: {} triangles are exported one item each (export_document)",
                doc.type_name(),
                items.len()
            )));
        }
        return Ok(items.remove(0));
    }
    if let SurfaceForm::Trimmed(t) = form {
        let within = |e: StepError| StepError::plain(format!("surface: {}", e.message));
        let base = export_surface(&t.surface, name, relative_tolerance).map_err(within)?;
        let kernel = kernel_surface(&t.surface).map_err(within)?;
        return super::faces::export_trimmed(t, name, relative_tolerance, base, kernel.as_ref());
    }
    let kernel = kernel_surface(doc)?;
    if let SurfaceForm::Placed(p) = form {
        return placed_surface(p, name, relative_tolerance);
    }
    let tolerance = relative_tolerance * surface_size(kernel.as_ref());
    let domain = (kernel.domain_u(), kernel.domain_v());
    let make = |surface: Surface, form: Form, max_deviation: f64, map: ParamMap| Exported {
        item: Item { name: name.to_string(), geometry: Geometry::Surface(surface) },
        form,
        max_deviation,
        tolerance,
        map,
        domain,
    };
    if let Some((surface, map)) = elementary_surface(doc)? {
        return Ok(make(surface, Form::Exact, 0.0, map));
    }
    if let Some((surface, form, deviation, map)) = swept_surface(doc, domain, relative_tolerance)? {
        return Ok(make(surface, form, deviation, map));
    }
    let (fitted, form) = fitted_surface(doc, kernel.as_ref(), domain, tolerance)?;
    Ok(make(Surface::Spline(fitted.spline), form, fitted.max_deviation, ParamMap::IDENTITY))
}

/// A document of several triangles ([`SurfaceForm::Triangles`]) as one item per triangle,
/// named `name` and the triangle's number: chart c (u ∈ [c, c + 1], v ∈ [0, 1] of the
/// document, u' = u − c in STEP) is a Bézier triangle's exact degenerate tensor patch of
/// degree (n, n) (a rational one's NURBS patch), or for other triangles a biquintic Hermite
/// B-spline within the tolerance, relative to the whole surface's size.
pub fn export_triangles(doc: &SurfaceDocument, name: &str, relative_tolerance: f64) -> Result<Vec<Exported>> {
    let kernel = kernel_surface(doc)?;
    let Some(atlas) = kernel.triangle_atlas() else {
        return Err(StepError::plain(format!("{}: the surface is not made of triangles", doc.type_name())));
    };
    let tolerance = relative_tolerance * surface_size(kernel.as_ref());
    let unit = Interval::new(0.0, 1.0);
    let mut out = Vec::with_capacity(atlas.charts().len());
    for (c, chart) in atlas.charts().iter().enumerate() {
        let domain = (Interval::new(c as f64, c as f64 + 1.0), unit);
        let map = ParamMap { u: (1.0, -(c as f64)), v: (1.0, 0.0) };
        let exact = |surface: SplineSurface| (surface, Form::Exact, 0.0);
        let rows = |rows: &[Vec<Point<3>>]| -> Vec<Vec<Vec<f64>>> {
            rows.iter().map(|row| row.iter().map(|x| x.as_slice().to_vec()).collect()).collect()
        };
        let invalid = |e: splinekit::Error| StepError::plain(format!("{name} triangle {c}: {e}"));
        let (surface, form, max_deviation) = match chart.bezier_net() {
            Some(net) if net.weights.is_none() => {
                let patch = BezierTriangle::new(net.points.to_vec()).map_err(invalid)?.to_tensor_patch();
                let (p, q) = patch.degrees();
                let net = rows(patch.control_points());
                exact(spline_surface((p, q), &bezier_knots(p), &bezier_knots(q), &net, None, (false, false))?)
            }
            Some(net) => {
                let weights = net.weights.unwrap_or_default().to_vec();
                let patch =
                    RationalBezierTriangle::new(net.points.to_vec(), weights).map_err(invalid)?.to_tensor_patch();
                let (ku, kv) = patch.knots();
                let net = rows(patch.control_points());
                exact(spline_surface(patch.degrees(), ku, kv, &net, Some(patch.weights()), (false, false))?)
            }
            None => {
                let single = TriangleAtlas::single(chart.clone());
                let fitted = hermite_surface(&single, &uniform_breaks(unit, 4), &uniform_breaks(unit, 4), tolerance)?;
                (fitted.spline, Form::Approximated, fitted.max_deviation)
            }
        };
        out.push(Exported {
            item: Item { name: format!("{name} triangle {c}"), geometry: Geometry::Surface(Surface::Spline(surface)) },
            form,
            max_deviation,
            tolerance,
            map,
            domain,
        });
    }
    Ok(out)
}

/// A `placed` document: its surface's export carried rigidly into the placement (same
/// form, deviation and parameter map; the document has been built, so its frame is valid).
fn placed_surface(doc: &PlacedDoc, name: &str, relative_tolerance: f64) -> Result<Exported> {
    let within = |e: StepError| StepError::plain(format!("surface: {}", e.message));
    let inner = export_surface(&doc.surface, name, relative_tolerance).map_err(within)?;
    let Geometry::Surface(s) = &inner.item.geometry else {
        return Err(StepError::plain("surface: a trimmed surface cannot be placed (place its surface instead)"));
    };
    let placement = Placement::of_frame(&doc.origin, &doc.axis, &doc.ref_direction)?;
    let item = Item { name: name.to_string(), geometry: Geometry::Surface(placement.surface(s)) };
    Ok(Exported { item, ..inner })
}

/// Whether a document leaves exactly (its own STEP entity, or a B-spline equal to it):
/// what [`export_shape`] would report as [`Form::Exact`] or [`Form::ExactPolynomial`],
/// decided without fitting anything.
pub fn exports_exactly(doc: &ShapeDocument) -> bool {
    match doc {
        ShapeDocument::Curve(c) => curve_exports_exactly(c),
        ShapeDocument::Surface(s) => surface_exports_exactly(s),
    }
}

fn surface_exports_exactly(doc: &SurfaceDocument) -> bool {
    match doc.exact_form() {
        Err(_) | Ok(SurfaceForm::Approximate) => false,
        Ok(SurfaceForm::Brep(b)) => super::solid::brep_faces(b).is_ok_and(|faces| faces.iter().all(exports_exactly)),
        Ok(SurfaceForm::Triangles) => kernel_surface(doc)
            .is_ok_and(|k| k.triangle_atlas().is_some_and(|a| a.charts().iter().all(|c| c.bezier_net().is_some()))),
        Ok(SurfaceForm::Revolution(d)) => curve_exports_exactly(&d.curve),
        Ok(SurfaceForm::Extrusion(d)) => curve_exports_exactly(&d.curve),
        Ok(SurfaceForm::Trimmed(t)) => {
            super::faces::trimmed_exports_exactly(t, surface_exports_exactly(&t.surface), curve_exports_exactly)
        }
        Ok(SurfaceForm::Placed(p)) => {
            !matches!(p.surface.exact_form(), Ok(SurfaceForm::Trimmed(_))) && surface_exports_exactly(&p.surface)
        }
        Ok(SurfaceForm::BlendingSpline(_)) => polynomial_blending_degrees(doc).is_some(),
        Ok(
            SurfaceForm::Spline(_)
            | SurfaceForm::Plane { .. }
            | SurfaceForm::Cylinder { .. }
            | SurfaceForm::Cone { .. }
            | SurfaceForm::Sphere { .. }
            | SurfaceForm::Torus { .. },
        ) => matches!(elementary_surface(doc), Ok(Some(_))),
    }
}

/// Exports any shape document.
pub fn export_shape(doc: &ShapeDocument, name: &str, relative_tolerance: f64) -> Result<Exported> {
    match doc {
        ShapeDocument::Curve(c) => export_curve(c, name, relative_tolerance),
        ShapeDocument::Surface(s) => export_surface(s, name, relative_tolerance),
    }
}

/// A parameter of the document, the matching STEP parameter, and the document's point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// (u, v) of the document (curves: (t, 0)).
    pub param: (f64, f64),
    /// The STEP parameter map(param).
    pub step_param: (f64, f64),
    /// The document's point there, evaluated by splinekit.
    pub point: Point<3>,
}

/// `count` samples of a curve (uniform in t, ends included), or `count` × `count` of a
/// surface, of the document and the STEP parameters the export maps them to: what a
/// reader of the file should find there.
pub fn samples(doc: &ShapeDocument, exported: &Exported, count: usize) -> Result<Vec<Sample>> {
    let m = exported.map;
    let step = |(u, v): (f64, f64)| (m.u.0 * u + m.u.1, m.v.0 * v + m.v.1);
    let at = |d: Interval, i: usize| d.lerp(i as f64 / (count - 1).max(1) as f64);
    match doc {
        ShapeDocument::Curve(c) => {
            let k = kernel_curve(c)?;
            Ok((0..count)
                .map(|i| {
                    let t = at(exported.domain.0, i);
                    Sample { param: (t, 0.0), step_param: step((t, 0.0)), point: k.point(t) }
                })
                .collect())
        }
        ShapeDocument::Surface(s) => {
            let k = kernel_surface(s)?;
            // An item of one triangle (`export_triangles`: u ∈ [c, c + 1]) is sampled on
            // that triangle alone: the atlas gives u = c + 1 to triangle c + 1.
            if let Some(atlas) = k.triangle_atlas().filter(|a| a.charts().len() > 1) {
                let c = exported.domain.0.start.floor().max(0.0) as usize;
                let chart = atlas.charts()[c.min(atlas.charts().len() - 1)].clone();
                let shift = c as f64;
                let single = TriangleAtlas::single(chart);
                return Ok((0..count)
                    .flat_map(|i| (0..count).map(move |j| (i, j)))
                    .map(|(i, j)| {
                        let (u, v) = (at(exported.domain.0, i), at(exported.domain.1, j));
                        Sample { param: (u, v), step_param: step((u, v)), point: single.point(u - shift, v) }
                    })
                    .collect());
            }
            Ok((0..count)
                .flat_map(|i| (0..count).map(move |j| (i, j)))
                .map(|(i, j)| {
                    let (u, v) = (at(exported.domain.0, i), at(exported.domain.1, j));
                    Sample { param: (u, v), step_param: step((u, v)), point: k.point(u, v) }
                })
                .collect())
        }
    }
}
