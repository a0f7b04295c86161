//! B-function evaluation: B and three derivatives at 1024 parameters in (0, 1).

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use splinekit::basis::BFunction;
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let ts: Vec<f64> = (0..1024).map(|i| (i as f64 + 0.5) / 1024.0).collect();
    let mut g = c.benchmark_group("B-function with 3 derivatives");
    g.throughput(Throughput::Elements(ts.len() as u64));
    for (name, b) in [
        ("ERBS (default)", BFunction::erbs_default()),
        ("ERBS value only", BFunction::erbs_default()),
        ("polynomial k=2", BFunction::polynomial(2).unwrap()),
        ("trigonometric", BFunction::Trigonometric),
    ] {
        let k = if name.contains("value only") { 0 } else { 3 };
        g.bench_function(name, |bench| {
            bench.iter(|| {
                let mut out = [0.0; 4];
                let mut acc = 0.0;
                for &t in &ts {
                    b.eval(black_box(t), &mut out[..=k]);
                    acc += out[k];
                }
                acc
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
