//! Geometric queries: 10⁴ projections onto a bicubic surface, all intersections of two
//! cubic B-spline curves with 100 control points each, the intersection curve of a torus
//! and a cylinder through its tube (the shapes of bench/ocp/queries.py, which times
//! OpenCASCADE on the same work).

use criterion::{Criterion, criterion_group, criterion_main};
use splinekit::query::{SurfaceProjector, intersect_curves, intersect_surfaces, self_intersections};
use std::hint::black_box;

#[path = "common/query_workloads.rs"]
mod query_workloads;
use query_workloads::{bicubic, query_points, torus_and_cylinder, wavy_curves, winding_curve};

fn bench(c: &mut Criterion) {
    let surface = bicubic();
    let points = query_points();
    let mut g = c.benchmark_group("queries");
    g.sample_size(10);
    g.bench_function("10^4 projections onto a bicubic 8x8 surface (projector built once)", |b| {
        b.iter(|| {
            let projector = SurfaceProjector::new(&surface);
            points.iter().map(|q| projector.nearest(black_box(q), 0.0).unwrap().distance).sum::<f64>()
        })
    });
    let (ca, cb) = wavy_curves();
    g.bench_function("all intersections of two cubic B-splines, 100 control points each", |b| {
        b.iter(|| intersect_curves(black_box(&ca), black_box(&cb), 1e-9).unwrap().points.len())
    });
    let (torus, cylinder) = torus_and_cylinder();
    g.bench_function("torus-cylinder intersection curve (two loops, chord 1e-5)", |b| {
        b.iter(|| intersect_surfaces(black_box(&torus), black_box(&cylinder), 1e-9, 1e-5).unwrap().len())
    });
    let winding = winding_curve(32);
    g.bench_function("self-intersections of a cubic B-spline winding 32 times (962 crossings)", |b| {
        b.iter(|| self_intersections(black_box(&winding), 1e-9).unwrap().points.len())
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
