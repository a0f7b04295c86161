//! Self-intersections of a B-spline that winds many times (timing, for profiling):
//! `cargo run --release -p splinekit --example self_cross_speed [WINDINGS]`.

use splinekit::Point;
use splinekit::curve::BSplineCurve;
use splinekit::query::self_intersections;
use std::time::Instant;

fn main() {
    let windings: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(32);
    // A circle of radius 1 whose centre drifts along a circle of radius 0.3 once while it
    // winds `windings` times: every winding crosses every other one twice.
    let n = 16 * windings;
    let pts: Vec<Point<2>> = (0..n)
        .map(|i| {
            let t = i as f64 / (n - 1) as f64 * std::f64::consts::TAU;
            let w = windings as f64 * t;
            Point::<2>::new(w.cos() + 0.3 * t.cos(), w.sin() + 0.3 * t.sin())
        })
        .collect();
    let curve = BSplineCurve::clamped_uniform(3, pts).unwrap();
    let start = Instant::now();
    let r = self_intersections(&curve, 1e-9).unwrap();
    println!(
        "{windings} windings: {} crossings, {} overlaps, {:.3} s",
        r.points.len(),
        r.overlaps.len(),
        start.elapsed().as_secs_f64()
    );
}
