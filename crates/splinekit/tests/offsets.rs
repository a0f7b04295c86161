//! Offsets of curves and surfaces against closed forms and projection: circles offset to
//! circles, spheres to spheres, sampled offset points at distance |d| from the shape,
//! trimmed cusps of an ellipse's inner offset.

mod common;
use common::*;
use splinekit::Point;
use splinekit::curve::model::{Circle, Ellipse, Helix};
use splinekit::curve::{BSplineCurve, Curve};
use splinekit::query::{
    CurveProjector, SurfaceProjector, intersect_curves, offset_curve, offset_surface, self_intersections,
};
use splinekit::surface::model::{Cone, Sphere};
use splinekit::surface::{BSplineSurface, Surface};

const SAMPLES: usize = 1000;

fn wavy() -> BSplineCurve<2> {
    let pts = vec![p2(0.0, 0.0), p2(1.0, 2.0), p2(2.0, -1.0), p2(3.0, 1.5), p2(4.0, 0.0), p2(5.0, 2.0), p2(6.0, -0.5)];
    BSplineCurve::clamped_uniform(3, pts).unwrap()
}

/// Parameters spread over a piece's domain, ends included.
fn params(c: &BSplineCurve<3>) -> impl Iterator<Item = f64> + '_ {
    (0..SAMPLES).map(move |k| c.domain().lerp(k as f64 / (SAMPLES - 1) as f64))
}

#[test]
fn offsets_of_a_circle_are_circles_of_radius_r_plus_d() {
    let c = Circle::new(2.0).unwrap();
    for (d, tol) in [(0.5, 1e-7), (-0.5, 1e-7), (1.75, 1e-9), (-1.9, 1e-6)] {
        let off = offset_curve(&c, d, Some(Point::<3>::z()), tol).unwrap();
        assert_eq!(off.pieces.len(), 1, "d = {d}");
        assert!(off.cusps.is_empty() && off.max_error <= tol, "d = {d}: {off:?}");
        let piece = &off.pieces[0].curve;
        assert!(piece.is_closed(), "d = {d}");
        let worst = params(piece).map(|t| (piece.point(t).norm() - (2.0 + d)).abs()).fold(0.0, f64::max);
        assert!(worst <= tol, "d = {d}: radius off by {worst:e}");
        // The parameter is the circle's: the offset point at t is on the ray through c(t).
        let t = 1.234;
        assert!((piece.point(t) - c.point(t) * ((2.0 + d) / 2.0)).norm() <= tol);
    }
}

#[test]
fn an_offset_deeper_than_the_radius_of_a_circle_is_empty() {
    let off = offset_curve(&Circle::new(2.0).unwrap(), -3.0, Some(Point::<3>::z()), 1e-6).unwrap();
    assert!(off.pieces.is_empty(), "{} pieces", off.pieces.len());
}

#[test]
fn offset_points_of_a_spline_are_at_distance_d() {
    let c = wavy();
    let projector = CurveProjector::new(&c);
    for (d, tol) in [(0.2, 1e-6), (-0.3, 1e-8)] {
        let off = offset_curve(&c, d, None, tol).unwrap();
        assert!(!off.pieces.is_empty() && off.max_error <= tol);
        for piece in &off.pieces {
            let p = &piece.curve;
            for k in 0..SAMPLES {
                let q = p.point(p.domain().lerp(k as f64 / (SAMPLES - 1) as f64));
                let near = projector.nearest(&q, 0.0).unwrap();
                assert!((near.distance - d.abs()).abs() <= tol, "d = {d}: distance {} at {q:?}", near.distance);
            }
        }
    }
}

#[test]
fn a_3d_plane_curve_is_offset_along_t_cross_v() {
    // The circle of radius 2 turned into the plane x = 1 (normal +x): c(t) = (1, 2 cos t, 2 sin t)
    // runs counter-clockwise about +x, so T × x points outwards.
    let ctrl: Vec<Point<3>> = (0..12)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / 12.0;
            p3(1.0, 2.0 * a.cos(), 2.0 * a.sin())
        })
        .collect();
    let c = BSplineCurve::periodic_uniform(3, ctrl).unwrap();
    let projector = CurveProjector::new(&c);
    let off = offset_curve(&c, 0.25, Some(p3(2.0, 0.0, 0.0)), 1e-8).unwrap();
    assert_eq!(off.pieces.len(), 1);
    let p = &off.pieces[0].curve;
    assert!(p.is_closed());
    for t in params(p) {
        let q = p.point(t);
        assert!((q.x - 1.0).abs() <= 1e-12, "leaves the plane: {q:?}");
        let near = projector.nearest(&q, 0.0).unwrap();
        assert!((near.distance - 0.25).abs() <= 1e-8);
        // Outwards: farther from the axis than the curve.
        assert!(q.yz().norm() > near.point.yz().norm());
    }
}

#[test]
fn the_inner_offset_of_an_ellipse_has_its_cusps_trimmed_and_no_self_intersections() {
    // Semi-axes 3 and 1: the smallest radius of curvature is b²/a = 1/3, so at d = −0.6
    // (inwards) the raw offset has four cusps and two swallowtails, one at each end.
    let e = Ellipse::new(3.0, 1.0).unwrap();
    let tol = 1e-7;
    let off = offset_curve(&e, -0.6, Some(Point::<3>::z()), tol).unwrap();
    assert_eq!(off.cusps.len(), 4, "cusps {:?}", off.cusps);
    assert!(off.crossings.len() >= 2, "crossings {:?}", off.crossings);
    // What is left: the upper and the lower arc, meeting at the two crossings.
    assert_eq!(off.pieces.len(), 2, "{:?}", off.pieces.iter().map(|p| p.params).collect::<Vec<_>>());
    let projector = CurveProjector::new(&e);
    for piece in &off.pieces {
        let p = &piece.curve;
        assert!(self_intersections(p, 1e-9).unwrap().points.is_empty());
        for t in params(p) {
            let near = projector.nearest(&p.point(t), 0.0).unwrap();
            assert!((near.distance - 0.6).abs() <= tol, "distance {} at t = {t}", near.distance);
        }
    }
    // The two arcs meet only at their ends (the corners of the trimmed offset).
    let (a, b) = (&off.pieces[0].curve, &off.pieces[1].curve);
    let meet = intersect_curves(a, b, 1e-7).unwrap();
    assert_eq!(meet.points.len(), 2, "{:?}", meet.points);
    for m in &meet.points {
        let ends = [a.domain().start, a.domain().end];
        assert!(ends.iter().any(|&t| (t - m.t_a).abs() <= 1e-6), "crossing inside a piece: {m:?}");
    }
}

#[test]
fn bad_curve_offsets_are_refused_with_the_field_named() {
    let c = Circle::new(1.0).unwrap();
    let z = Some(Point::<3>::z());
    let msg = |r: splinekit::Result<_>| r.map(|_: splinekit::query::CurveOffset<3>| ()).unwrap_err().to_string();
    assert!(msg(offset_curve(&c, f64::NAN, z, 1e-6)).starts_with("distance:"));
    assert!(msg(offset_curve(&c, 0.1, z, 0.0)).starts_with("tolerance:"));
    assert!(msg(offset_curve(&c, 0.1, None, 1e-6)).starts_with("normal:"));
    assert!(msg(offset_curve(&c, 0.1, Some(Point::<3>::zeros()), 1e-6)).starts_with("normal:"));
    // A helix is in no plane.
    let h = Helix::new(1.0, 1.0, 2.0).unwrap();
    let e = offset_curve(&h, 0.1, z, 1e-6).map(|_| ()).unwrap_err().to_string();
    assert!(e.starts_with("normal:") && e.contains("not in a plane"), "{e}");
    // A tolerance that cannot be reached is an error, not a hang.
    let e = offset_curve(&c, 0.1, z, 1e-300).map(|_| ()).unwrap_err().to_string();
    assert!(e.starts_with("tolerance:"), "{e}");
}

#[test]
fn the_offset_of_a_sphere_is_a_sphere() {
    let s = Sphere::new(2.0).unwrap();
    for (d, tol) in [(0.5, 1e-5), (-0.5, 1e-6)] {
        let off = offset_surface(&s, d, tol).unwrap();
        assert!(off.max_error <= tol, "d = {d}: {}", off.max_error);
        let (du, dv) = (s.domain_u(), s.domain_v());
        for k in 0..SAMPLES {
            let (u, v) = (du.lerp((k as f64 * 0.618_034).fract()), dv.lerp(k as f64 / (SAMPLES - 1) as f64));
            let r = off.surface.point(u, v).norm();
            assert!((r - (2.0 + d)).abs() <= tol, "d = {d}: radius {r} at ({u}, {v})");
        }
    }
    // Through the centre: the offset would fold.
    let e = offset_surface(&s, -2.5, 1e-5).unwrap_err().to_string();
    assert!(e.starts_with("distance:") && e.contains("folds"), "{e}");
}

#[test]
fn offset_points_of_a_bspline_surface_are_at_distance_d() {
    let net: Vec<Vec<Point<3>>> = (0..5)
        .map(|i| (0..5).map(|j| p3(i as f64, j as f64, 0.6 * ((i * j) % 3) as f64 - 0.4 * (i % 2) as f64)).collect())
        .collect();
    let s = BSplineSurface::clamped_uniform((3, 3), net).unwrap();
    let projector = SurfaceProjector::new(&s);
    let (d, tol) = (0.3, 1e-5);
    let off = offset_surface(&s, d, tol).unwrap();
    assert!(off.max_error <= tol);
    let (du, dv) = (s.domain_u(), s.domain_v());
    for k in 0..SAMPLES {
        let (u, v) = (du.lerp((k as f64 * 0.618_034).fract()), dv.lerp((k as f64 * 0.414_214).fract()));
        let q = off.surface.point(u, v);
        let near = projector.nearest(&q, 0.0).unwrap();
        assert!((near.distance - d).abs() <= tol, "distance {} at ({u}, {v})", near.distance);
        // On the side of S_u × S_v.
        assert!((q - s.point(u, v)).dot(&s.normal(u, v).unwrap()) > 0.0);
    }
}

#[test]
fn a_cone_apex_has_no_offset() {
    let e = offset_surface(&Cone::new(1.0, 2.0).unwrap(), 0.1, 1e-4).unwrap_err().to_string();
    assert!(e.starts_with("surface:") && e.contains("apex"), "{e}");
    let e = offset_surface(&Sphere::new(1.0).unwrap(), f64::INFINITY, 1e-4).unwrap_err().to_string();
    assert!(e.starts_with("distance:"), "{e}");
}

#[test]
fn the_heart_is_offset_piecewise_between_its_corners() {
    // The heart curve's tangent vanishes at its top (the seam) and its bottom: the normal
    // flips there, so the offset is cut at both; every point kept is at distance |d|.
    let heart = splinekit::curve::model::Heart::new(1.0).unwrap();
    let projector = CurveProjector::new(&heart);
    for d in [0.8, -0.8] {
        let off = offset_curve(&heart, d, Some(Point::<3>::z()), 1e-6).unwrap();
        assert!(off.pieces.len() >= 2 && off.max_error <= 1e-6, "d = {d}: {} pieces", off.pieces.len());
        for piece in &off.pieces {
            for t in params(&piece.curve).step_by(4) {
                let near = projector.nearest(&piece.curve.point(t), 0.0).unwrap();
                assert!((near.distance - 0.8).abs() <= 1e-6, "d = {d}: distance {} at t = {t}", near.distance);
            }
        }
    }
}
