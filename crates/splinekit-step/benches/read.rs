//! Reading 10⁵ entity instances (points, directions, placements and B-spline curves over
//! them, as CAD files hold them): scan, index and reference check, from memory and from a
//! file on disk.

use criterion::{Criterion, criterion_group, criterion_main};
use splinekit_step::part21::writer::{HeaderInfo, Part21Writer};
use splinekit_step::part21::{Param, StepFile};
use std::hint::black_box;

/// A file of `n` instances: per group of 10, eight points, a direction and a curve over
/// the points.
fn synthetic(n: usize) -> String {
    let mut w = Part21Writer::new(&HeaderInfo::default());
    let mut count = 0;
    while count + 10 <= n {
        let pts: Vec<Param> = (0..8)
            .map(|i| {
                let x = (count + i) as f64 * 0.37;
                w.add(
                    "CARTESIAN_POINT",
                    vec![
                        Param::String(String::new()),
                        Param::List(vec![Param::Real(x), Param::Real(x.sin()), Param::Real(1.25)]),
                    ],
                )
            })
            .map(Param::Reference)
            .collect();
        w.add(
            "DIRECTION",
            vec![Param::String(String::new()), Param::List(vec![Param::Real(0.0), Param::Real(0.0), Param::Real(1.0)])],
        );
        w.add(
            "B_SPLINE_CURVE_WITH_KNOTS",
            vec![
                Param::String(String::new()),
                Param::Integer(3),
                Param::List(pts),
                Param::Enumeration("UNSPECIFIED".into()),
                Param::Enumeration("F".into()),
                Param::Enumeration("F".into()),
                Param::List(vec![
                    Param::Integer(4),
                    Param::Integer(1),
                    Param::Integer(1),
                    Param::Integer(1),
                    Param::Integer(1),
                    Param::Integer(4),
                ]),
                Param::List((0..6).map(|k| Param::Real(k as f64)).collect()),
                Param::Enumeration("UNSPECIFIED".into()),
            ],
        );
        count += 10;
    }
    w.finish()
}

fn bench(c: &mut Criterion) {
    let text = synthetic(100_000);
    let path = std::env::temp_dir().join(format!("splinekit-step-bench-{}.step", std::process::id()));
    std::fs::write(&path, &text).unwrap();
    let mut g = c.benchmark_group(format!("read 10^5 instances ({:.1} MB)", text.len() as f64 / 1e6));
    g.sample_size(10);
    g.bench_function("from memory", |b| b.iter(|| StepFile::from_bytes(black_box(text.as_bytes().to_vec())).unwrap()));
    g.bench_function("from a file (streamed)", |b| b.iter(|| StepFile::open(black_box(&path)).unwrap()));
    g.finish();
    let _ = std::fs::remove_file(&path);
}

criterion_group!(benches, bench);
criterion_main!(benches);
