//! Shared helpers for the integration tests.
#![allow(dead_code)]

pub mod cages;

use splinekit::Point;
use splinekit::curve::Curve;

/// Textbook de Boor (NURBS Book A3.1-style triangle on raw knots), independent of the
/// crate's basis code: the point of Σ N_{i,p} P_i at t in span k.
pub fn de_boor<const D: usize>(p: usize, knots: &[f64], pts: &[Point<D>], t: f64) -> Point<D> {
    let n = pts.len();
    let mut k = p;
    while k + 1 < n && knots[k + 1] <= t {
        k += 1;
    }
    let mut d: Vec<Point<D>> = (0..=p).map(|j| pts[j + k - p]).collect();
    for r in 1..=p {
        for j in (r..=p).rev() {
            let i = j + k - p;
            let alpha = (t - knots[i]) / (knots[i + 1 + p - r] - knots[i]);
            d[j] = d[j - 1] * (1.0 - alpha) + d[j] * alpha;
        }
    }
    d[p]
}

/// Derivative of order `k` by central differences of order `k − 1` derivatives
/// (fourth-order stencil), with step h.
pub fn finite_difference<const D: usize, C: Curve<D> + ?Sized>(c: &C, t: f64, k: usize, h: f64) -> Point<D> {
    let f = |s: f64| c.derivative(s, k - 1);
    (f(t - 2.0 * h) - f(t + 2.0 * h) + (f(t + h) - f(t - h)) * 8.0) / (12.0 * h)
}

/// Max distance between two curves over `samples` parameters of the first's domain.
pub fn max_distance<const D: usize, A: Curve<D> + ?Sized, B: Curve<D> + ?Sized>(a: &A, b: &B, samples: usize) -> f64 {
    let d = a.domain();
    (0..=samples)
        .map(|i| (a.point(d.lerp(i as f64 / samples as f64)) - b.point(d.lerp(i as f64 / samples as f64))).norm())
        .fold(0.0, f64::max)
}

/// Asserts that two lists of derivatives (orders 0, 1, …) agree order by order within
/// `rel` relative to the second (reference) list, at least 1 in size:
/// |a_k − b_k| < rel · max(|b_k|, 1); a failure names `what`, the order and both values.
pub fn assert_orders_close<const D: usize>(a: &[Point<D>], b: &[Point<D>], rel: f64, what: &str) {
    assert_eq!(a.len(), b.len(), "{what}: as many orders on both sides");
    for (k, (x, y)) in a.iter().zip(b).enumerate() {
        assert!((x - y).norm() < rel * y.norm().max(1.0), "{what}: order {k}: {x} vs {y}");
    }
}

pub fn p2(x: f64, y: f64) -> Point<2> {
    Point::<2>::new(x, y)
}
pub fn p3(x: f64, y: f64, z: f64) -> Point<3> {
    Point::<3>::new(x, y, z)
}
