//! Self-intersections of a B-spline that winds many times (timing, for profiling):
//! `cargo run --release -p splinekit --example self_cross_speed [WINDINGS]`.

use splinekit::query::self_intersections;
use std::time::Instant;

#[path = "../benches/common/query_workloads.rs"]
mod query_workloads;

fn main() {
    let windings: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(32);
    let curve = query_workloads::winding_curve(windings);
    let start = Instant::now();
    let r = self_intersections(&curve, 1e-9).unwrap();
    println!(
        "{windings} windings: {} crossings, {} overlaps, {:.3} s",
        r.points.len(),
        r.overlaps.len(),
        start.elapsed().as_secs_f64()
    );
}
