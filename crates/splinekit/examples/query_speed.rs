//! The three query workloads of benches/queries.rs timed once each in a loop, printed as
//! one JSON line of median seconds, for bench/ocp/speed.py to set beside OpenCASCADE in
//! the same run: `cargo run --release -p splinekit --example query_speed [REPEATS]`.

use splinekit::Point;
use splinekit::curve::BSplineCurve;
use splinekit::curve::model::Line;
use splinekit::query::{SurfaceProjector, intersect_curves, intersect_surfaces};
use splinekit::surface::BSplineSurface;
use splinekit::surface::derived::RevolvedSurface;
use splinekit::surface::model::Torus;
use std::hint::black_box;
use std::time::Instant;

fn bicubic() -> BSplineSurface<3> {
    let net: Vec<Vec<Point<3>>> = (0..8)
        .map(|i| (0..8).map(|j| Point::<3>::new(i as f64, j as f64, (i as f64).sin() * (j as f64).cos())).collect())
        .collect();
    BSplineSurface::clamped_uniform((3, 3), net).unwrap()
}

fn query_points() -> Vec<Point<3>> {
    let side = 100;
    let mut pts = Vec::with_capacity(side * side);
    for a in 0..side {
        for b in 0..side {
            let x = -1.0 + 9.0 * (a as f64 + 0.5) / side as f64;
            let y = -1.0 + 9.0 * (b as f64 + 0.5) / side as f64;
            pts.push(Point::<3>::new(x, y, -2.0 + 4.0 * (3.0 * a as f64 + 7.0 * b as f64).sin().powi(2)));
        }
    }
    pts
}

fn wavy_curves() -> (BSplineCurve<2>, BSplineCurve<2>) {
    let a: Vec<Point<2>> = (0..100).map(|i| Point::<2>::new(0.1 * i as f64, (0.7 * i as f64).sin())).collect();
    let b: Vec<Point<2>> = (0..100).map(|i| Point::<2>::new(0.1 * i as f64, 0.8 * (0.45 * i as f64).cos())).collect();
    (BSplineCurve::clamped_uniform(3, a).unwrap(), BSplineCurve::clamped_uniform(3, b).unwrap())
}

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
    let torus = Torus::new(3.0, 1.0).unwrap();
    let line = Line::new(Point::<3>::new(3.5, 0.0, -2.0), Point::<3>::new(3.5, 0.0, 2.0)).unwrap();
    let cylinder = RevolvedSurface::new(
        Box::new(line),
        Point::<3>::new(3.0, 0.0, 0.0),
        Point::<3>::new(0.0, 0.0, 1.0),
        std::f64::consts::TAU,
    )
    .unwrap();
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
