//! Curve–surface (and surface–surface) intersections against closed forms: every reported
//! point lies on both shapes, and every root of an independent one-variable equation is
//! found.

mod common;
use common::*;
use splinekit::Point;
use splinekit::basis::Side;
use splinekit::curve::model::Line;
use splinekit::curve::{Curve, Interval};
use splinekit::query::{IntersectionKind, intersect_curve_surface};
use splinekit::surface::Surface;
use splinekit::surface::model::{Cylinder, Sphere};

/// A helix about the x axis: (a·t − l, r cos t, r sin t), t ∈ [0, 6π].
struct XHelix {
    a: f64,
    l: f64,
    r: f64,
}

impl Curve<3> for XHelix {
    fn domain(&self) -> Interval {
        Interval::new(0.0, 6.0 * std::f64::consts::PI)
    }
    fn eval_side(&self, t: f64, _side: Side, out: &mut [Point<3>]) {
        for (k, o) in out.iter_mut().enumerate() {
            let x = match k {
                0 => self.a * t - self.l,
                1 => self.a,
                _ => 0.0,
            };
            // The k-th derivative of cos t is cos(t + kπ/2).
            let phase = t + k as f64 * std::f64::consts::FRAC_PI_2;
            *o = p3(x, self.r * phase.cos(), self.r * phase.sin());
        }
    }
}

/// Roots of g on [a, b] by sampling and bisection.
fn roots(g: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> Vec<f64> {
    let mut out = Vec::new();
    for i in 0..n {
        let (mut lo, mut hi) = (a + (b - a) * i as f64 / n as f64, a + (b - a) * (i + 1) as f64 / n as f64);
        if g(lo).signum() == g(hi).signum() {
            continue;
        }
        for _ in 0..200 {
            let m = 0.5 * (lo + hi);
            if g(m).signum() == g(lo).signum() { lo = m } else { hi = m }
        }
        out.push(0.5 * (lo + hi));
    }
    out
}

#[test]
fn lines_pierce_a_sphere_where_the_quadratic_says() {
    let sphere = Sphere::new(1.5).unwrap();
    for k in 0..12 {
        let f = k as f64;
        let from = p3(-3.0 + 0.1 * f, -2.0 + 0.3 * (f * 1.7).sin(), 0.2 * f - 1.0);
        let to = p3(2.5, 2.0 * (f * 0.9).cos(), 1.0 - 0.15 * f);
        let line = Line::new(from, to).unwrap();
        let d = to - from;
        // |from + t d|² = r²: a t² + b t + c = 0.
        let (a, b, c) = (d.dot(&d), 2.0 * from.dot(&d), from.dot(&from) - 2.25);
        let disc = b * b - 4.0 * a * c;
        let expected: Vec<f64> = if disc > 0.0 {
            [(-b - disc.sqrt()) / (2.0 * a), (-b + disc.sqrt()) / (2.0 * a)]
                .into_iter()
                .filter(|t| (0.0..=1.0).contains(t))
                .collect()
        } else {
            vec![]
        };
        let found = intersect_curve_surface(&line, &sphere, 1e-9).unwrap();
        assert_eq!(found.len(), expected.len(), "line {k}: {found:?} vs {expected:?}");
        for (p, t) in found.iter().zip(&expected) {
            assert!((p.t - t).abs() < 1e-12, "line {k}: t {} vs {t}", p.t);
            assert!((line.point(p.t) - sphere.point(p.u, p.v)).norm() < 1e-9);
            assert_eq!(p.kind, IntersectionKind::Crossing);
        }
    }
}

#[test]
fn a_helix_about_x_crosses_a_cylinder_about_z_at_every_root() {
    let (rho, h) = (0.9, 2.0);
    let cylinder = Cylinder::new(rho, h).unwrap();
    let helix = XHelix { a: 0.05, l: 0.47, r: 1.0 };
    let found = intersect_curve_surface(&helix, &cylinder, 1e-9).unwrap();
    // On the cylinder's side: x² + y² = ρ² with 0 ≤ z ≤ h.
    let g = |t: f64| {
        let p = helix.point(t);
        p.x * p.x + p.y * p.y - rho * rho
    };
    let expected: Vec<f64> = roots(g, 0.0, 6.0 * std::f64::consts::PI, 4000)
        .into_iter()
        .filter(|&t| (0.0..=h).contains(&helix.point(t).z))
        .collect();
    assert!(expected.len() >= 4, "the test needs crossings: {expected:?}");
    assert_eq!(found.len(), expected.len(), "{found:?} vs {expected:?}");
    for (p, t) in found.iter().zip(&expected) {
        assert!((p.t - t).abs() < 1e-10, "t {} vs {t}", p.t);
        assert!((helix.point(p.t) - cylinder.point(p.u, p.v)).norm() < 1e-9);
    }
}

use splinekit::curve::{CircleFrame, NurbsCurve};
use splinekit::query::{IntersectionBranch, intersect_surfaces};
use splinekit::surface::derived::Extrusion;
use splinekit::surface::model::{Plane, Torus};

/// Checks that every point of every branch lies on both surfaces within `tol`, and that
/// its parameters name it.
fn on_both<A: Surface<3>, B: Surface<3>>(a: &A, b: &B, branches: &[IntersectionBranch], tol: f64) {
    for br in branches {
        assert_eq!(br.points.len(), br.params_a.len());
        for ((p, pa), pb) in br.points.iter().zip(&br.params_a).zip(&br.params_b) {
            assert!((a.point(pa[0], pa[1]) - p).norm() <= tol, "{p:?} is not on A");
            assert!((b.point(pb[0], pb[1]) - p).norm() <= tol, "{p:?} is not on B");
        }
    }
}

#[test]
fn a_plane_cuts_a_sphere_in_one_closed_circle() {
    let sphere = Sphere::new(1.5).unwrap();
    let plane = Plane::new(p3(-3.0, -3.0, 0.5), p3(6.0, 0.0, 0.0), p3(0.0, 6.0, 0.0)).unwrap();
    let r = intersect_surfaces(&plane, &sphere, 1e-10, 1e-4).unwrap();
    assert_eq!(r.len(), 1, "{} branches", r.len());
    assert!(r[0].closed && r[0].early_stop.is_none() && r[0].points.len() > 20);
    on_both(&plane, &sphere, &r, 1e-10);
    let radius = 2.0f64.sqrt();
    for p in &r[0].points {
        assert!(((p.x * p.x + p.y * p.y).sqrt() - radius).abs() < 1e-9 && (p.z - 0.5).abs() < 1e-10, "{p:?}");
    }
    // The polyline's chords stay within the chord error of the circle: sagitta = l²/(8ρ).
    for w in r[0].points.windows(2) {
        assert!((w[1] - w[0]).norm_squared() / (8.0 * radius) <= 1e-4 * 1.01);
    }
}

#[test]
fn a_thin_cylinder_pierces_a_wide_one_in_two_loops() {
    let wide = Cylinder::new(1.0, 3.0).unwrap();
    let frame =
        CircleFrame { center: p3(-2.0, 0.0, 1.5), x_axis: p3(0.0, 1.0, 0.0), y_axis: p3(0.0, 0.0, 1.0), radius: 0.7 };
    let thin = Extrusion::new(Box::new(NurbsCurve::circle(&frame).unwrap()), p3(4.0, 0.0, 0.0)).unwrap();
    let r = intersect_surfaces(&wide, &thin, 1e-10, 1e-4).unwrap();
    assert_eq!(r.len(), 2, "{r:?}");
    on_both(&wide, &thin, &r, 1e-10);
    for br in &r {
        assert!(
            br.closed && br.early_stop.is_none(),
            "{:?} {} {:?} {:?}",
            br.early_stop,
            br.closed,
            br.params_b.first(),
            br.params_b.last()
        );
        for p in &br.points {
            assert!(
                (p.x * p.x + p.y * p.y - 1.0).abs() < 1e-9 && (p.y * p.y + (p.z - 1.5).powi(2) - 0.49).abs() < 1e-9
            );
        }
    }
    assert!(r[0].points[0].x * r[1].points[0].x < 0.0, "one loop on each side");
}

#[test]
fn the_bitangent_plane_cuts_a_torus_in_two_villarceau_circles() {
    let (big, small) = (3.0, 1.0);
    let torus = Torus::new(big, small).unwrap();
    let slope = small / (big * big - small * small).sqrt();
    let plane = Plane::new(p3(-5.0, -5.0, -5.0 * slope), p3(10.0, 0.0, 10.0 * slope), p3(0.0, 10.0, 0.0)).unwrap();
    let r = intersect_surfaces(&plane, &torus, 1e-10, 1e-4).unwrap();
    on_both(&plane, &torus, &r, 1e-10);
    // Two circles of radius R about (0, ±r, 0) in the plane; they cross where the plane
    // touches the torus, where marching stops.
    let mut length = 0.0;
    for br in &r {
        for p in &br.points {
            let d = |c: f64| (p - p3(0.0, c, 0.0)).norm() - big;
            assert!(d(small).abs().min(d(-small).abs()) < 1e-9, "{p:?} is on neither circle");
        }
        length += br.points.windows(2).map(|w| (w[1] - w[0]).norm()).sum::<f64>();
    }
    let full = 2.0 * 2.0 * std::f64::consts::PI * big;
    assert!(length > 0.98 * full && length < 1.001 * full, "traced {length} of {full}");
}

#[test]
fn coincident_shapes_are_refused_quickly() {
    let cylinder = Cylinder::new(1.0, 1.0).unwrap();
    let helix = splinekit::curve::model::Helix::new(1.0, 0.2, 2.0).unwrap();
    let e = intersect_curve_surface(&helix, &cylinder, 1e-9).unwrap_err().to_string();
    assert!(e.contains("runs inside the surface"), "{e}");
    let torus = Torus::new(3.0, 1.0).unwrap();
    let e = intersect_surfaces(&torus, &torus, 1e-9, 1e-4).unwrap_err().to_string();
    assert!(e.contains("coincide over a region"), "{e}");
}

/// A unit sphere cut by the plane n·x = cos θ, n the sphere's normal at (u, v) = (π/8, 0):
/// a circle of radius sin θ about n·cos θ. The loop lies between the sphere's isocurves at
/// u = 0, π/4 and v = ±π/14 and between the plane's, where seeding by eight isocurves per
/// direction did not look; subdivision until the patches' normals cannot be parallel must
/// find it, down to loops a few thousandths wide.
#[test]
fn small_loops_of_a_plane_near_a_sphere_are_found() {
    let sphere = Sphere::new(1.0).unwrap();
    let u = std::f64::consts::PI / 8.0;
    let n = p3(u.cos(), u.sin(), 0.0);
    let (e1, e2) = (p3(-u.sin(), u.cos(), 0.0), p3(0.0, 0.0, 1.0));
    for theta in [0.1f64, 0.02, 0.003] {
        let centre = n * theta.cos();
        let plane = Plane::new(centre - e1 * 1.75 - e2 * 1.75, e1 * 3.5, e2 * 3.5).unwrap();
        let radius = theta.sin();
        let chord = 1e-3 * radius;
        let r = intersect_surfaces(&plane, &sphere, 1e-12, chord).unwrap();
        assert_eq!(r.len(), 1, "θ = {theta}: {} branches", r.len());
        assert!(r[0].closed && r[0].early_stop.is_none(), "θ = {theta}: {:?}", r[0].early_stop);
        on_both(&plane, &sphere, &r, 1e-12);
        for p in &r[0].points {
            assert!(((p - centre).norm() - radius).abs() < 1e-11 && (p - centre).dot(&n).abs() < 1e-11, "{p:?}");
        }
        let length: f64 = r[0].points.windows(2).map(|w| (w[1] - w[0]).norm()).sum();
        let full = std::f64::consts::TAU * radius;
        assert!(length > (1.0 - 1e-2) * full && length <= full, "θ = {theta}: length {length} of {full}");
    }
}

/// Checks a touching branch: flagged tangent, every point on both surfaces within `tol`
/// with parallel normals there, and on the closed-form curve (`off` gives a point's
/// distance from it).
fn touching<A: Surface<3>, B: Surface<3>>(a: &A, b: &B, br: &IntersectionBranch, off: impl Fn(&Point<3>) -> f64) {
    assert!(br.tangent && br.early_stop.is_none(), "{:?} tangent {}", br.early_stop, br.tangent);
    on_both(a, b, std::slice::from_ref(br), 1e-10);
    for ((p, pa), pb) in br.points.iter().zip(&br.params_a).zip(&br.params_b) {
        assert!(off(p) < 1e-9, "{p:?} is {} off the touching curve", off(p));
        let (na, nb) = (a.normal(pa[0], pa[1]).unwrap(), b.normal(pb[0], pb[1]).unwrap());
        assert!(na.cross(&nb).norm() < 1e-6, "normals at {p:?} are not parallel");
    }
}

/// The polyline's length.
fn length(points: &[Point<3>]) -> f64 {
    points.windows(2).map(|w| (w[1] - w[0]).norm()).sum()
}

/// A unit cylinder about z from z = −1 to 1 (a NURBS circle extruded: its seam is a
/// boundary).
fn nurbs_cylinder(centre: Point<3>, height: f64) -> Extrusion<3> {
    let frame = CircleFrame { center: centre, x_axis: p3(1.0, 0.0, 0.0), y_axis: p3(0.0, 1.0, 0.0), radius: 1.0 };
    Extrusion::new(Box::new(NurbsCurve::circle(&frame).unwrap()), p3(0.0, 0.0, height)).unwrap()
}

#[test]
fn a_unit_sphere_touches_a_unit_cylinder_along_the_equator() {
    let sphere = Sphere::new(1.0).unwrap();
    let cylinder = nurbs_cylinder(p3(0.0, 0.0, -1.0), 2.0);
    for (first, r) in [
        (true, intersect_surfaces(&sphere, &cylinder, 1e-10, 1e-4).unwrap()),
        (false, intersect_surfaces(&cylinder, &sphere, 1e-10, 1e-4).unwrap()),
    ] {
        assert_eq!(r.len(), 1, "{r:?}");
        assert!(r[0].closed, "the equator is one loop");
        let off = |p: &Point<3>| p.z.abs().max(((p.x * p.x + p.y * p.y).sqrt() - 1.0).abs());
        if first {
            touching(&sphere, &cylinder, &r[0], off);
        } else {
            touching(&cylinder, &sphere, &r[0], off);
        }
        let full = std::f64::consts::TAU;
        assert!((length(&r[0].points) - full).abs() < 1e-3, "length {} of {full}", length(&r[0].points));
        let fitted = r[0].fit_bspline(1e-4).unwrap();
        assert!(fitted.max_error <= 1e-4 && fitted.curve.is_closed());
    }
}

/// The equator on the rim of the cylinder (0 ≤ z ≤ 1, a model cylinder and a NURBS one):
/// the touching curve lies in a domain boundary and is followed along it, one closed loop
/// (not a piece per step that leaves through the boundary).
#[test]
fn a_touching_curve_on_a_domain_boundary_is_one_loop() {
    let sphere = Sphere::new(1.0).unwrap();
    let off = |p: &Point<3>| p.z.abs().max(((p.x * p.x + p.y * p.y).sqrt() - 1.0).abs());
    let model = Cylinder::new(1.0, 1.0).unwrap();
    let r = intersect_surfaces(&sphere, &model, 1e-10, 1e-4).unwrap();
    assert_eq!(r.len(), 1, "{r:?}");
    assert!(r[0].closed, "one loop along the rim");
    touching(&sphere, &model, &r[0], off);
    let nurbs = nurbs_cylinder(p3(0.0, 0.0, 0.0), 1.0);
    let r = intersect_surfaces(&nurbs, &sphere, 1e-10, 1e-4).unwrap();
    assert_eq!(r.len(), 1, "{r:?}");
    touching(&nurbs, &sphere, &r[0], off);
    assert!((length(&r[0].points) - std::f64::consts::TAU).abs() < 1e-3, "length {}", length(&r[0].points));
}

#[test]
fn a_plane_touches_a_cylinder_along_a_line_and_two_cylinders_touch_side_by_side() {
    // The cylinder of radius 1 about z, 0 ≤ z ≤ 1, touches the plane x = 1 along the segment
    // x = 1, y = 0 and the same cylinder about x = 2 along it too; the segment ends on the
    // first cylinder's boundary circles.
    let cylinder = Cylinder::new(1.0, 1.0).unwrap();
    let plane = Plane::new(p3(1.0, -2.0, -0.5), p3(0.0, 4.0, 0.0), p3(0.0, 0.0, 2.0)).unwrap();
    let beside = nurbs_cylinder(p3(2.0, 0.0, -0.5), 2.0);
    let off = |p: &Point<3>| (p.x - 1.0).abs().max(p.y.abs()).max((p.z - p.z.clamp(0.0, 1.0)).abs());
    let r = intersect_surfaces(&cylinder, &plane, 1e-10, 1e-4).unwrap();
    assert_eq!(r.len(), 1, "{r:?}");
    touching(&cylinder, &plane, &r[0], off);
    let r2 = intersect_surfaces(&cylinder, &beside, 1e-10, 1e-4).unwrap();
    assert_eq!(r2.len(), 1, "{r2:?}");
    touching(&cylinder, &beside, &r2[0], off);
    for br in [&r[0], &r2[0]] {
        assert!(!br.closed);
        let (z0, z1) = (br.points[0].z, br.points[br.points.len() - 1].z);
        assert!((z0.min(z1)).abs() < 1e-12 && (z0.max(z1) - 1.0).abs() < 1e-12, "ends at z = {z0}, {z1}");
    }
}

#[test]
fn a_patch_of_a_plane_on_a_plane_is_refused() {
    let plane = Plane::new(p3(-1.0, -1.0, 0.0), p3(2.0, 0.0, 0.0), p3(0.0, 2.0, 0.0)).unwrap();
    let patch = Plane::new(p3(-0.3, -0.2, 0.0), p3(0.5, 0.1, 0.0), p3(-0.1, 0.6, 0.0)).unwrap();
    let e = intersect_surfaces(&plane, &patch, 1e-9, 1e-4).unwrap_err().to_string();
    assert!(e.contains("coincide over a region"), "{e}");
}

/// Against the touching case: a cylinder of radius 0.95 crosses the unit sphere in two
/// circles at z = ±√(1 − 0.95²), flat crossings that are no touching curve.
#[test]
fn a_slightly_thinner_cylinder_crosses_the_unit_sphere_in_two_circles() {
    let sphere = Sphere::new(1.0).unwrap();
    let frame =
        CircleFrame { center: p3(0.0, 0.0, -1.0), x_axis: p3(1.0, 0.0, 0.0), y_axis: p3(0.0, 1.0, 0.0), radius: 0.95 };
    let cylinder = Extrusion::new(Box::new(NurbsCurve::circle(&frame).unwrap()), p3(0.0, 0.0, 2.0)).unwrap();
    let r = intersect_surfaces(&sphere, &cylinder, 1e-10, 1e-4).unwrap();
    assert_eq!(r.len(), 2, "{r:?}");
    on_both(&sphere, &cylinder, &r, 1e-10);
    let h = (1.0f64 - 0.95 * 0.95).sqrt();
    for br in &r {
        assert!(!br.tangent && br.closed && br.early_stop.is_none(), "{:?}", br.early_stop);
        for p in &br.points {
            assert!((p.z.abs() - h).abs() < 1e-9 && ((p.x * p.x + p.y * p.y).sqrt() - 0.95).abs() < 1e-9, "{p:?}");
        }
    }
    assert!(r[0].points[0].z * r[1].points[0].z < 0.0, "one circle on each side of the equator");
}
