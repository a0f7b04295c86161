//! Least-squares fit of 10⁶ samples with 1000 control points (cubic, 3-D).

use criterion::{Criterion, criterion_group, criterion_main};
use splinekit::Point;
use splinekit::fit::{FitOptions, FitWithKnotsOptions, KnotPlacement, Parametrization, fit, fit_knots, fit_with_knots};
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let m = 1_000_000;
    let params: Vec<f64> = (0..m).map(|i| i as f64 / (m - 1) as f64).collect();
    let points: Vec<Point<3>> = params
        .iter()
        .map(|&t| Point::<3>::new((40.0 * t).cos(), (40.0 * t).sin(), t + 0.1 * (7.0 * t).sin()))
        .collect();
    let knots = fit_knots(&params, 3, 1000, KnotPlacement::Uniform).expect("1000 control points for 10⁶ parameters");
    let mut g = c.benchmark_group("fit 10^6 samples, 1000 control points, cubic 3d");
    g.sample_size(10);
    g.bench_function("fit_with_knots (given params and knots)", |b| {
        b.iter(|| fit_with_knots(black_box(&points), &params, &FitWithKnotsOptions::new(3, knots.clone())).unwrap())
    });
    let mut o = FitOptions::new(3, 1000);
    o.params = Parametrization::ChordLength;
    o.knots = KnotPlacement::Averaged;
    g.bench_function("fit (chord-length params, averaged knots)", |b| b.iter(|| fit(black_box(&points), &o).unwrap()));
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
