//! A cubic Bézier triangle's point (and first partials) against the same surface as the
//! degenerate bicubic tensor-product patch it converts to exactly: 1024 points of the
//! triangle, the patch evaluated at the matching (s, t).

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use splinekit::Point;
use splinekit::surface::Surface;
use splinekit::triangle::{BezierTriangle, Triangle, multi_indices};
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let t = BezierTriangle::from_fn(3, |(i, j, k)| {
        Point::<3>::new(i as f64 + 0.1 * (j * k) as f64, j as f64 - 0.2 * i as f64, (i * j + k) as f64 * 0.3)
    })
    .unwrap();
    assert_eq!(multi_indices(3).count(), 10);
    let patch = t.to_tensor_patch();
    // (s, t) on a 32×32 grid and the barycentric points they map to.
    let st: Vec<(f64, f64)> =
        (0..32).flat_map(|a| (0..32).map(move |b| ((a as f64 + 0.5) / 32.0, (b as f64 + 0.5) / 32.0))).collect();
    let uvw: Vec<[f64; 3]> = st.iter().map(|&(s, q)| splinekit::triangle::degenerate_patch_parameters(s, q)).collect();
    let mut g = c.benchmark_group("cubic triangle point");
    g.throughput(Throughput::Elements(st.len() as u64));
    g.bench_function("Bézier triangle, de Casteljau", |b| {
        b.iter(|| uvw.iter().fold(Point::<3>::zeros(), |acc, p| acc + t.point(black_box(p[0]), p[1], p[2])))
    });
    g.bench_function("Bézier triangle, Bernstein form", |b| {
        b.iter(|| uvw.iter().fold(Point::<3>::zeros(), |acc, p| acc + t.point_bernstein(black_box(p[0]), p[1], p[2])))
    });
    g.bench_function("bicubic tensor patch", |b| {
        b.iter(|| st.iter().fold(Point::<3>::zeros(), |acc, &(s, q)| acc + patch.point(black_box(s), q)))
    });
    g.finish();
    let mut g = c.benchmark_group("cubic triangle point and first partials");
    g.throughput(Throughput::Elements(st.len() as u64));
    g.bench_function("Bézier triangle, de Casteljau", |b| {
        b.iter(|| {
            let mut o = [Point::<3>::zeros(); 4];
            uvw.iter().fold(Point::<3>::zeros(), |acc, p| {
                t.eval_partials(black_box(p[0]), p[1], 1, 1, &mut o);
                acc + o[0] + o[1] + o[2]
            })
        })
    });
    g.bench_function("bicubic tensor patch", |b| {
        b.iter(|| {
            let mut o = [Point::<3>::zeros(); 4];
            st.iter().fold(Point::<3>::zeros(), |acc, &(s, q)| {
                patch.eval_partials(black_box(s), q, 1, 1, &mut o);
                acc + o[0] + o[1] + o[2]
            })
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
