//! Geometric queries: 10⁴ projections onto a bicubic surface, all intersections of two
//! cubic B-spline curves with 100 control points each, the intersection curve of a torus
//! and a cylinder through its tube (the shapes of bench/ocp/queries.py, which times
//! OpenCASCADE on the same work).

use criterion::{Criterion, criterion_group, criterion_main};
use splinekit::Point;
use splinekit::curve::BSplineCurve;
use splinekit::curve::model::Line;
use splinekit::query::{SurfaceProjector, intersect_curves, intersect_surfaces, self_intersections};
use splinekit::surface::BSplineSurface;
use splinekit::surface::derived::RevolvedSurface;
use splinekit::surface::model::Torus;
use std::hint::black_box;

fn bicubic() -> BSplineSurface<3> {
    let net: Vec<Vec<Point<3>>> = (0..8)
        .map(|i| (0..8).map(|j| Point::<3>::new(i as f64, j as f64, (i as f64).sin() * (j as f64).cos())).collect())
        .collect();
    BSplineSurface::clamped_uniform((3, 3), net).unwrap()
}

/// The query points of bench/ocp/queries.py: a 100 × 100 grid over [−1, 8]² at heights
/// −2 + 4 sin²(3a + 7b).
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

/// The two curves of bench/ocp/queries.py.
pub fn wavy_curves() -> (BSplineCurve<2>, BSplineCurve<2>) {
    let a: Vec<Point<2>> = (0..100).map(|i| Point::<2>::new(0.1 * i as f64, (0.7 * i as f64).sin())).collect();
    let b: Vec<Point<2>> = (0..100).map(|i| Point::<2>::new(0.1 * i as f64, 0.8 * (0.45 * i as f64).cos())).collect();
    (BSplineCurve::clamped_uniform(3, a).unwrap(), BSplineCurve::clamped_uniform(3, b).unwrap())
}

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
    let torus = Torus::new(3.0, 1.0).unwrap();
    let line = Line::new(Point::<3>::new(3.5, 0.0, -2.0), Point::<3>::new(3.5, 0.0, 2.0)).unwrap();
    let axis = (Point::<3>::new(3.0, 0.0, 0.0), Point::<3>::new(0.0, 0.0, 1.0));
    let cylinder = RevolvedSurface::new(Box::new(line), axis.0, axis.1, std::f64::consts::TAU).unwrap();
    g.bench_function("torus-cylinder intersection curve (two loops, chord 1e-5)", |b| {
        b.iter(|| intersect_surfaces(black_box(&torus), black_box(&cylinder), 1e-9, 1e-5).unwrap().len())
    });
    let windings = 32;
    let n = 16 * windings;
    let pts: Vec<Point<2>> = (0..n)
        .map(|i| {
            let t = i as f64 / (n - 1) as f64 * std::f64::consts::TAU;
            let w = windings as f64 * t;
            Point::<2>::new(w.cos() + 0.3 * t.cos(), w.sin() + 0.3 * t.sin())
        })
        .collect();
    let winding = BSplineCurve::clamped_uniform(3, pts).unwrap();
    g.bench_function("self-intersections of a cubic B-spline winding 32 times (962 crossings)", |b| {
        b.iter(|| self_intersections(black_box(&winding), 1e-9).unwrap().points.len())
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
