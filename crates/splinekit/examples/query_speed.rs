//! The three query workloads of benches/queries.rs timed once each in a loop, printed as
//! one JSON line of median seconds, for bench/ocp/speed.py to set beside OpenCASCADE in
//! the same run: `cargo run --release -p splinekit --example query_speed [REPEATS]`.

use splinekit::query::{SurfaceProjector, intersect_curves, intersect_surfaces};
use std::hint::black_box;
use std::time::Instant;

#[path = "../benches/common/query_workloads.rs"]
mod query_workloads;
use query_workloads::{bicubic, query_points, torus_and_cylinder, wavy_curves};

/// The median of `repeats` timings of `f` (seconds) and its last result.
fn median<T>(repeats: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let start = Instant::now();
    let mut out = f();
    let mut times = vec![start.elapsed().as_secs_f64()];
    for _ in 1..repeats {
        let start = Instant::now();
        out = black_box(f());
        times.push(start.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (times[times.len() / 2], out)
}

fn main() {
    let repeats: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(11).max(1);
    // A second argument (project, curves or surfaces) runs that workload alone (the others once or on no points), for profiling.
    let only = std::env::args().nth(2);
    let skip = |name: &str| only.as_deref().is_some_and(|o| o != name);
    let repeats_of = |name: &str| if skip(name) { 1 } else { repeats };
    let surface = bicubic();
    let points = if skip("project") { Vec::new() } else { query_points() };
    let (project, total) = median(repeats_of("project"), || {
        let projector = SurfaceProjector::new(&surface);
        points.iter().map(|q| projector.nearest(black_box(q), 0.0).unwrap().distance).sum::<f64>()
    });
    let (ca, cb) = wavy_curves();
    let (curves, crossings) = median(repeats_of("curves"), || intersect_curves(&ca, &cb, 1e-9).unwrap().points.len());
    let (torus, cylinder) = torus_and_cylinder();
    let (surfaces, branches) =
        median(repeats_of("surfaces"), || intersect_surfaces(&torus, &cylinder, 1e-9, 1e-5).unwrap());
    let closed = branches.iter().filter(|b| b.closed).count();
    let points_on = branches.iter().map(|b| b.points.len()).sum::<usize>();
    println!(
        "{{\"project\": {project:e}, \"project_distance_sum\": {total}, \"curves\": {curves:e}, \
         \"crossings\": {crossings}, \"surfaces\": {surfaces:e}, \"branches\": {}, \"closed\": {closed}, \
         \"branch_points\": {points_on}}}",
        branches.len()
    );
}
