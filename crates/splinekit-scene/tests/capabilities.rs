//! What every kind declares besides its kernel object, checked for every kind of the
//! registry: its exact form is its shape (the closed forms of `CurveForm` and `SurfaceForm`
//! evaluated here, or the form's spline built as a general NURBS, against the kind's own
//! kernel object), its spline view is its document's fields, and the kinds it offers as
//! blending-spline models make blending splines that build and evaluate.

use serde_json::json;
use splinekit::Point;
use splinekit::curve::bezier::bezier_knots;
use splinekit::curve::{Curve, NurbsCurve};
use splinekit::surface::{NurbsSurface, Surface};
use splinekit_scene::points::to_points;
use splinekit_scene::{
    CurveDocument, CurveForm, Curves, DimensionVisitor, ShapeDocument, SurfaceDocument, SurfaceForm, Surfaces,
};

/// Points of a curve at `count` parameters spread over its domain, as 3-D coordinates.
struct CurvePoints(usize);

impl DimensionVisitor<Curves> for CurvePoints {
    type Output = Vec<[f64; 3]>;
    fn visit<const D: usize>(self, c: &dyn Curve<D>) -> Vec<[f64; 3]> {
        let dom = c.domain();
        (0..self.0).map(|i| pad(c.point(dom.lerp(i as f64 / (self.0 - 1) as f64)).as_slice())).collect()
    }
}

/// Points of a surface on a `count` × `count` grid of its domain, with the parameters.
struct SurfacePoints(usize);

impl DimensionVisitor<Surfaces> for SurfacePoints {
    type Output = Vec<((f64, f64), [f64; 3])>;
    fn visit<const D: usize>(self, s: &dyn Surface<D>) -> Self::Output {
        let (du, dv) = (s.domain_u(), s.domain_v());
        let n = self.0;
        let mut out = Vec::new();
        for i in 0..n {
            for j in 0..n {
                let (u, v) = (du.lerp(i as f64 / (n - 1) as f64), dv.lerp(j as f64 / (n - 1) as f64));
                out.push(((u, v), pad(s.point(u, v).as_slice())));
            }
        }
        out
    }
}

fn pad(p: &[f64]) -> [f64; 3] {
    [p.first().copied().unwrap_or(0.0), p.get(1).copied().unwrap_or(0.0), p.get(2).copied().unwrap_or(0.0)]
}

fn close(a: [f64; 3], b: [f64; 3], scale: f64, what: &str) {
    let d = ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt();
    assert!(d <= 1e-12 * scale.max(1.0), "{what}: {a:?} ≠ {b:?} ({d:e})");
}

/// A curve form's point at the parameter t of its kind (`None` for forms of nested documents).
fn curve_form_point(form: &CurveForm<'_>, t: f64) -> Option<[f64; 3]> {
    Some(match form {
        CurveForm::Line { from, to } => {
            let (f, e) = (pad(from), pad(to));
            [f[0] + t * (e[0] - f[0]), f[1] + t * (e[1] - f[1]), f[2] + t * (e[2] - f[2])]
        }
        CurveForm::Circle { radius } => [radius * t.cos(), radius * t.sin(), 0.0],
        CurveForm::Ellipse { a, b } => [a * t.cos(), b * t.sin(), 0.0],
        CurveForm::Spline(_) | CurveForm::BlendingSpline(_) | CurveForm::Approximate => return None,
    })
}

/// The spline form as a general NURBS (knots of a Bézier: clamped on [0, 1]; weights 1 when
/// absent), in 3-D.
fn nurbs_of(view: &splinekit_scene::SplineView<'_>) -> NurbsCurve<3> {
    let points: Vec<Vec<f64>> = view.control_points.iter().map(|p| pad(p).to_vec()).collect();
    let n = points.len();
    let knots = view.knots.as_deref().map_or_else(|| bezier_knots(view.degree), <[f64]>::to_vec);
    let weights = view.weights.as_deref().map_or_else(|| vec![1.0; n], <[f64]>::to_vec);
    let points = to_points::<3>(&points);
    if view.periodic {
        NurbsCurve::new_periodic(view.degree, knots, points, weights).unwrap()
    } else {
        NurbsCurve::new(view.degree, knots, points, weights).unwrap()
    }
}

#[test]
fn every_curve_kinds_exact_form_is_its_shape() {
    for doc in CurveDocument::examples() {
        let name = doc.type_name();
        let built = doc.build().unwrap().visit(CurvePoints(17));
        let form = doc.exact_form().unwrap();
        let scale = built.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
        match &form {
            CurveForm::Spline(view) => {
                assert_eq!(doc.spline().as_ref(), Some(view), "{name}: the exact spline is the document's own");
                let nurbs = nurbs_of(view);
                let dom = nurbs.domain();
                for (i, p) in built.iter().enumerate() {
                    let q = nurbs.point(dom.lerp(i as f64 / 16.0));
                    close(*p, [q[0], q[1], q[2]], scale, name);
                }
            }
            CurveForm::Line { .. } | CurveForm::Circle { .. } | CurveForm::Ellipse { .. } => {
                let ShapeDocument::Curve(c) = ShapeDocument::parse(&doc.to_value()).unwrap() else { panic!() };
                let dom = c.build().unwrap().visit(Domain);
                for (i, p) in built.iter().enumerate() {
                    let t = dom.0 + (dom.1 - dom.0) * i as f64 / 16.0;
                    close(*p, curve_form_point(&form, t).unwrap(), scale, name);
                }
            }
            CurveForm::BlendingSpline(_) => assert!(matches!(doc, CurveDocument::BlendingSpline(_)), "{name}"),
            CurveForm::Approximate => assert!(doc.spline().is_none(), "{name}: a spline has an exact form"),
        }
    }
}

/// A curve's domain.
struct Domain;

impl DimensionVisitor<Curves> for Domain {
    type Output = (f64, f64);
    fn visit<const D: usize>(self, c: &dyn Curve<D>) -> (f64, f64) {
        (c.domain().start, c.domain().end)
    }
}

/// A surface form's point at (u, v) (`None` for forms of nested documents).
fn surface_form_point(form: &SurfaceForm<'_>, u: f64, v: f64) -> Option<[f64; 3]> {
    Some(match form {
        SurfaceForm::Plane { origin, u_axis, v_axis } => {
            let (o, a, b) = (pad(origin), pad(u_axis), pad(v_axis));
            [o[0] + u * a[0] + v * b[0], o[1] + u * a[1] + v * b[1], o[2] + u * a[2] + v * b[2]]
        }
        SurfaceForm::Cylinder { radius, height } => [radius * u.cos(), radius * u.sin(), height * v],
        SurfaceForm::Cone { radius, height } => {
            [radius * (1.0 - v) * u.cos(), radius * (1.0 - v) * u.sin(), height * v]
        }
        SurfaceForm::Sphere { radius } => [radius * v.cos() * u.cos(), radius * v.cos() * u.sin(), radius * v.sin()],
        SurfaceForm::Torus { major_radius: r0, minor_radius: r1 } => {
            [(r0 + r1 * v.cos()) * u.cos(), (r0 + r1 * v.cos()) * u.sin(), r1 * v.sin()]
        }
        _ => return None,
    })
}

#[test]
fn every_surface_kinds_exact_form_is_its_shape() {
    for doc in SurfaceDocument::examples() {
        let name = doc.type_name();
        let built = doc.build().unwrap().visit(SurfacePoints(9));
        let scale = built.iter().flat_map(|(_, p)| *p).fold(0.0f64, |m, x| m.max(x.abs()));
        let form = doc.exact_form().unwrap();
        match &form {
            SurfaceForm::Spline(view) => {
                let (p, q) = view.degrees;
                let net: Vec<Vec<Point<3>>> = view
                    .control_points
                    .iter()
                    .map(|row| row.iter().map(|x| Point::<3>::from(pad(x))).collect())
                    .collect();
                let (ku, kv) = match &view.knots {
                    Some((u, v)) => (u.to_vec(), v.to_vec()),
                    None => (bezier_knots(p), bezier_knots(q)),
                };
                let weights = view
                    .weights
                    .as_deref()
                    .map_or_else(|| net.iter().map(|row| vec![1.0; row.len()]).collect(), <[Vec<f64>]>::to_vec);
                let s = NurbsSurface::new((p, q), ku, kv, net, weights, view.periodic).unwrap();
                for ((u, v), point) in &built {
                    let r = s.point(*u, *v);
                    close(*point, [r[0], r[1], r[2]], scale, name);
                }
            }
            SurfaceForm::Plane { .. }
            | SurfaceForm::Cylinder { .. }
            | SurfaceForm::Cone { .. }
            | SurfaceForm::Sphere { .. }
            | SurfaceForm::Torus { .. } => {
                for ((u, v), point) in &built {
                    close(*point, surface_form_point(&form, *u, *v).unwrap(), scale, name);
                }
            }
            SurfaceForm::Revolution(_)
            | SurfaceForm::Extrusion(_)
            | SurfaceForm::Trimmed(_)
            | SurfaceForm::Placed(_)
            | SurfaceForm::BlendingSpline(_)
            | SurfaceForm::Brep(_)
            | SurfaceForm::Triangles
            | SurfaceForm::Approximate => assert!(doc.spline().is_none(), "{name}: a net has an exact form"),
        }
    }
}

#[test]
fn spline_views_are_the_documents_fields() {
    for doc in CurveDocument::examples() {
        let Some(view) = doc.spline() else { continue };
        let value = doc.to_value();
        assert_eq!(json!(view.control_points), value["control_points"], "{}", doc.type_name());
        assert_eq!(view.knots.map(|k| json!(k)), value.get("knots").cloned(), "{}", doc.type_name());
        assert_eq!(view.weights.map(|w| json!(w)), value.get("weights").cloned(), "{}", doc.type_name());
    }
    for doc in SurfaceDocument::examples() {
        let Some(view) = doc.spline() else { continue };
        let value = doc.to_value();
        assert_eq!(json!(view.control_points), value["control_points"], "{}", doc.type_name());
        assert_eq!(view.knots.map(|(u, _)| json!(u)), value.get("knots_u").cloned(), "{}", doc.type_name());
        assert_eq!(view.weights.map(|w| json!(w)), value.get("weights").cloned(), "{}", doc.type_name());
    }
}

#[test]
fn every_blending_model_makes_a_blending_spline() {
    let mut models = 0;
    for doc in CurveDocument::examples().into_iter().filter(CurveDocument::blending_model) {
        let b = json!({"type": "blending_spline", "model": {"type": doc.type_name()}, "local_curves": 8});
        let ShapeDocument::Curve(c) = ShapeDocument::parse(&b).unwrap() else { panic!("a curve") };
        let points = c.build().unwrap_or_else(|e| panic!("{}: {e}", doc.type_name())).visit(CurvePoints(5));
        assert!(points.iter().flatten().all(|x| x.is_finite()), "{}", doc.type_name());
        models += 1;
    }
    for doc in SurfaceDocument::examples().into_iter().filter(SurfaceDocument::blending_model) {
        let b =
            json!({"type": "blending_spline_surface", "model": {"type": doc.type_name()}, "local_surfaces": [4, 4]});
        let ShapeDocument::Surface(s) = ShapeDocument::parse(&b).unwrap() else { panic!("a surface") };
        let points = s.build().unwrap_or_else(|e| panic!("{}: {e}", doc.type_name())).visit(SurfacePoints(3));
        assert!(points.iter().all(|(_, p)| p.iter().all(|x| x.is_finite())), "{}", doc.type_name());
        models += 1;
    }
    assert!(models >= 20, "the model kinds offer blending splines ({models})");
    let trochoid = CurveDocument::examples().into_iter().find(|d| d.type_name() == "trochoid").unwrap();
    assert!(trochoid.blending_model());
}
