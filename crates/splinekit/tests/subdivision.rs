//! Subdivision schemes converge to their known limit curves.

mod common;
use common::*;
use splinekit::Point;
use splinekit::curve::{Curve, CurveNearest};
use splinekit::subdivision::{
    ChaikinOptions, FourPointOptions, chaikin, four_point, lane_riesenfeld, lane_riesenfeld_limit,
};

fn polygon() -> Vec<Point<2>> {
    vec![p2(0.0, 0.0), p2(2.0, 0.5), p2(3.0, 2.0), p2(1.5, 3.5), p2(-0.5, 2.5), p2(-1.0, 1.0)]
}

fn max_distance_to_curve(points: &[Point<2>], curve: &impl Curve<2>) -> f64 {
    points.iter().map(|q| curve.closest_point(q, 0.0).unwrap().distance).fold(0.0, f64::max)
}

#[test]
fn lane_riesenfeld_converges_to_the_uniform_bspline() {
    for degree in 1..=5 {
        for closed in [true, false] {
            let p = polygon();
            let limit = lane_riesenfeld_limit(&p, degree, closed).unwrap();
            let mut last = f64::INFINITY;
            for steps in 1..=5 {
                let q = lane_riesenfeld(&p, degree, steps, closed).unwrap();
                let expected = if closed { p.len() << steps } else { q.len() };
                assert_eq!(q.len(), expected);
                // The refined polygon is the control polygon of the same curve: with
                // half-spaced knots it reproduces the limit exactly.
                let n = q.len();
                let h = 1.0 / (1u64 << steps) as f64;
                let knots: Vec<f64> = (0..n + degree + 1).map(|i| i as f64 * h).collect();
                let refined = if closed {
                    splinekit::curve::BSplineCurve::new_periodic(degree, knots, q.clone()).unwrap()
                } else {
                    splinekit::curve::BSplineCurve::new(degree, knots, q.clone()).unwrap()
                };
                let d = refined.domain();
                let samples: Vec<Point<2>> = (0..=40).map(|i| refined.point(d.lerp(i as f64 / 40.0))).collect();
                let off = max_distance_to_curve(&samples, &limit);
                assert!(
                    off < 1e-9,
                    "degree {degree} closed {closed} step {steps}: refined curve leaves the limit by {off}"
                );
                // And the polygon itself approaches the curve.
                let dist = max_distance_to_curve(&q, &limit);
                if degree >= 2 {
                    assert!(dist < last, "degree {degree}: polygon distance {dist} did not decrease from {last}");
                }
                last = dist;
            }
        }
    }
}

#[test]
fn chaikin_is_lane_riesenfeld_of_degree_two() {
    let p = polygon();
    let a = chaikin(&p, 3, ChaikinOptions { closed: true, keep_ends: false }).unwrap();
    let b = lane_riesenfeld(&p, 2, 3, true).unwrap();
    assert_eq!(a.len(), b.len());
    // LR output is rotated by one relative to Chaikin's; compare as cyclic sequences.
    let shift = (0..b.len()).find(|&s| (b[s] - a[0]).norm() < 1e-12).expect("same points");
    for i in 0..a.len() {
        assert!((a[i] - b[(i + shift) % b.len()]).norm() < 1e-12);
    }
    let open = chaikin(&p, 2, ChaikinOptions { closed: false, keep_ends: true }).unwrap();
    assert_eq!(open[0], p[0]);
    assert_eq!(*open.last().unwrap(), p[5]);
}

#[test]
fn four_point_interpolates_and_reproduces_cubics() {
    let p = polygon();
    let q = four_point(&p, 2, FourPointOptions { closed: true, tension: 1.0 / 16.0 }).unwrap();
    for (i, v) in p.iter().enumerate() {
        assert_eq!(q[4 * i], *v, "old point {i} kept");
    }
    // Samples of a cubic stay on the cubic (inner points; the reflected ends only keep lines).
    let cubic = |t: f64| p2(t, t * t * t - 2.0 * t);
    let pts: Vec<Point<2>> = (0..8).map(|i| cubic(i as f64)).collect();
    let r = four_point(&pts, 1, FourPointOptions { closed: false, tension: 1.0 / 16.0 }).unwrap();
    for i in 1..6 {
        assert!((r[2 * i + 1] - cubic(i as f64 + 0.5)).norm() < 1e-12);
    }
}

#[test]
fn oversized_requests_are_refused() {
    let e = lane_riesenfeld(&polygon(), 3, 40, true).unwrap_err().to_string();
    assert!(e.starts_with("steps:"), "{e}");
}
