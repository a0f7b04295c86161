//! The shapes of the query benchmarks, shared by `benches/queries.rs` (criterion), the
//! example `query_speed` (timed beside OpenCASCADE by bench/ocp/speed.py, which builds the
//! same shapes in OCP), the example `self_cross_speed` and bench/peers/src/bin/queries.rs
//! (timed beside curvo); each uses a part of it.

#![allow(dead_code)]

use splinekit::Point;
use splinekit::curve::BSplineCurve;
use splinekit::curve::model::Line;
use splinekit::surface::BSplineSurface;
use splinekit::surface::derived::RevolvedSurface;
use splinekit::surface::model::Torus;

/// The bicubic 8 × 8 patch z = sin(i) cos(j) over the integer grid [0, 7]².
pub fn bicubic() -> BSplineSurface<3> {
    let net: Vec<Vec<Point<3>>> = (0..8)
        .map(|i| (0..8).map(|j| Point::<3>::new(i as f64, j as f64, (i as f64).sin() * (j as f64).cos())).collect())
        .collect();
    BSplineSurface::clamped_uniform((3, 3), net).unwrap()
}

/// The query points of bench/ocp/queries.py: a 100 × 100 grid over [−1, 8]² at heights
/// −2 + 4 sin²(3a + 7b).
pub fn query_points() -> Vec<Point<3>> {
    cell_centres((-1.0, 9.0), (-1.0, 9.0), |a, b, x, y| {
        Point::<3>::new(x, y, -2.0 + 4.0 * (3.0 * a as f64 + 7.0 * b as f64).sin().powi(2))
    })
}

/// `point(a, b, x, y)` at the centres (x, y) of the cells (a, b) of a 100 × 100 grid over
/// [x₀, x₀ + w] × [y₀, y₀ + h] (`x` = (x₀, w), `y` = (y₀, h)), rows of a first.
fn cell_centres<P>(x: (f64, f64), y: (f64, f64), point: impl Fn(usize, usize, f64, f64) -> P) -> Vec<P> {
    let side = 100;
    let mut pts = Vec::with_capacity(side * side);
    for a in 0..side {
        for b in 0..side {
            let px = x.0 + x.1 * (a as f64 + 0.5) / side as f64;
            let py = y.0 + y.1 * (b as f64 + 0.5) / side as f64;
            pts.push(point(a, b, px, py));
        }
    }
    pts
}

/// Query points for projections onto the first of the [`wavy_curves`] (bench/peers, beside
/// curvo): a 100 × 100 grid over [−0.5, 10.4] × [−2, 2], the curve's box widened by 0.5
/// and 1.
pub fn curve_query_points() -> Vec<Point<2>> {
    cell_centres((-0.5, 10.9), (-2.0, 4.0), |_, _, x, y| Point::<2>::new(x, y))
}

/// The two cubic curves with 100 control points each of bench/ocp/queries.py (22 crossings).
pub fn wavy_curves() -> (BSplineCurve<2>, BSplineCurve<2>) {
    let a: Vec<Point<2>> = (0..100).map(|i| Point::<2>::new(0.1 * i as f64, (0.7 * i as f64).sin())).collect();
    let b: Vec<Point<2>> = (0..100).map(|i| Point::<2>::new(0.1 * i as f64, 0.8 * (0.45 * i as f64).cos())).collect();
    (BSplineCurve::clamped_uniform(3, a).unwrap(), BSplineCurve::clamped_uniform(3, b).unwrap())
}

/// The torus (R = 3, r = 1) and the cylinder of radius 1/2 through its tube about the
/// vertical line through (3, 0): two intersection loops.
pub fn torus_and_cylinder() -> (Torus, RevolvedSurface) {
    let torus = Torus::new(3.0, 1.0).unwrap();
    let line = Line::new(Point::<3>::new(3.5, 0.0, -2.0), Point::<3>::new(3.5, 0.0, 2.0)).unwrap();
    let axis = (Point::<3>::new(3.0, 0.0, 0.0), Point::<3>::new(0.0, 0.0, 1.0));
    let cylinder = RevolvedSurface::new(Box::new(line), axis.0, axis.1, std::f64::consts::TAU).unwrap();
    (torus, cylinder)
}

/// A cubic B-spline through 16 points a winding: a circle of radius 1 whose centre drifts
/// once along a circle of radius 0.3 while it winds `windings` times, so that every
/// winding crosses every other one twice (32 windings: 962 crossings).
pub fn winding_curve(windings: usize) -> BSplineCurve<2> {
    let n = 16 * windings;
    let pts: Vec<Point<2>> = (0..n)
        .map(|i| {
            let t = i as f64 / (n - 1) as f64 * std::f64::consts::TAU;
            let w = windings as f64 * t;
            Point::<2>::new(w.cos() + 0.3 * t.cos(), w.sin() + 0.3 * t.sin())
        })
        .collect();
    BSplineCurve::clamped_uniform(3, pts).unwrap()
}
