//! Evaluation of a cubic 3-D B-spline with 1000 control points: single points at random
//! parameters (and on a curve of 100 control points, whose spans sit in L1), and sorted
//! batches of 10⁶ parameters with 0, 1 and 2 derivatives.

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use splinekit::Point;
use splinekit::curve::{BSplineCurve, Curve};
use std::hint::black_box;

fn curve(n: usize) -> BSplineCurve<3> {
    let pts = (0..n)
        .map(|i| {
            let x = i as f64;
            Point::<3>::new(x, (x * 0.37).sin(), (x * 0.11).cos())
        })
        .collect();
    BSplineCurve::clamped_uniform(3, pts).unwrap()
}

/// A deterministic pseudo-random sequence in [0, 1).
fn random_params(m: usize) -> Vec<f64> {
    let mut s = 0x9E3779B97F4A7C15u64;
    (0..m)
        .map(|_| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let curve = curve(1000);
    let random = random_params(4096);
    let mut g = c.benchmark_group("bspline cubic 3d, 1000 control points");
    g.throughput(Throughput::Elements(random.len() as u64));
    let small = self::curve(100);
    for (name, curve) in [("point at random parameters", &curve), ("point at random parameters, 100 cp", &small)] {
        g.bench_function(name, |b| {
            b.iter(|| {
                let mut acc = Point::<3>::zeros();
                for &t in &random {
                    acc += curve.point(black_box(t));
                }
                acc
            })
        });
    }
    g.bench_function("point + 2 derivatives at random parameters", |b| {
        b.iter(|| {
            let mut acc = Point::<3>::zeros();
            let mut out = [Point::<3>::zeros(); 3];
            for &t in &random {
                curve.eval(black_box(t), &mut out);
                acc += out[2];
            }
            acc
        })
    });
    g.finish();

    let m = 1_000_000;
    let sorted: Vec<f64> = (0..m).map(|i| i as f64 / (m - 1) as f64).collect();
    let mut g = c.benchmark_group("bspline cubic 3d, sorted batch of 10^6");
    g.throughput(Throughput::Elements(m as u64));
    g.sample_size(20);
    for order in 0..=2 {
        // One output buffer, touched before timing (a fresh one would time page faults).
        let mut out = vec![Point::<3>::zeros(); m * (order + 1)];
        curve.eval_many(&sorted, order, &mut out);
        g.bench_function(format!("eval_many, {order} derivatives"), |b| {
            b.iter(|| curve.eval_many(black_box(&sorted), order, &mut out))
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
