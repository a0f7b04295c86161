//! Blending splines: a closed curve of 10 cubic Bézier locals (ERBS) at 10⁶ parameters
//! with two derivatives; an 8×8 bicubic torus blending surface on a 256×256 grid with
//! normals, from scratch and refreshed after moving one patch or one control point of a
//! patch's Bézier net (the studio's drag of a local Bézier point, GMlib's updateCoeffs); the
//! heart's samples refreshed after moving one control point of a local.

use criterion::{Criterion, criterion_group, criterion_main};
use splinekit::Point;
use splinekit::basis::BFunction;
use splinekit::blend::{
    BlendingCurveOptions, BlendingSplineCurve, BlendingSplineSurface, BlendingSurfaceOptions, LocalKind, PatchKind,
};
use splinekit::curve::Curve;
use splinekit::curve::model::Heart;
use splinekit::frame::Affine;
use splinekit::surface::SurfaceGridSamples;
use splinekit::surface::model::Torus;
use std::hint::black_box;
use std::sync::Arc;

fn bench(c: &mut Criterion) {
    let curve = BlendingSplineCurve::from_model(
        Arc::new(Heart::new(1.0).unwrap()),
        10,
        &BlendingCurveOptions { local: LocalKind::Bezier(3), closed: Some(true), ..Default::default() },
    )
    .unwrap();
    let n = 1_000_000;
    let ts: Vec<f64> = (0..n).map(|i| std::f64::consts::TAU * i as f64 / n as f64).collect();
    let mut g = c.benchmark_group("blending spline");
    g.sample_size(10);
    g.bench_function("closed curve, 10 cubic locals, 10⁶ params + 2 derivatives", |b| {
        let mut out = vec![Point::<3>::zeros(); 3 * n];
        b.iter(|| {
            for (t, o) in ts.iter().zip(out.chunks_exact_mut(3)) {
                curve.eval(black_box(*t), o);
            }
            out[3 * n - 1]
        })
    });
    let torus = BlendingSplineSurface::from_model(
        Arc::new(Torus::new(3.0, 1.0).unwrap()),
        (8, 8),
        &BlendingSurfaceOptions {
            local: PatchKind::Bezier(3, 3),
            bfunction: BFunction::erbs_default(),
            closed_u: Some(true),
            closed_v: Some(true),
        },
    )
    .unwrap();
    g.bench_function("torus 8×8 bicubic, 256×256 grid with normals", |b| {
        b.iter(|| SurfaceGridSamples::uniform(black_box(&torus), 256, 256).unwrap())
    });
    let mut moved = torus.clone();
    let mut samples = SurfaceGridSamples::uniform(&moved, 256, 256).unwrap();
    let mut angle = 0.0;
    g.bench_function("torus: move one patch and refresh", |b| {
        b.iter(|| {
            angle += 0.01;
            let rects = moved.set_transform(3, 4, Affine::rotation(Point::<3>::new(0.0, 0.0, 1.0), angle).unwrap());
            samples.refresh(&moved, &rects)
        })
    });
    let mut edited = torus.clone();
    let mut samples = SurfaceGridSamples::uniform(&edited, 256, 256).unwrap();
    let net = edited.bezier_rest_net(3, 4).unwrap().0.to_vec();
    let mut lift = 0.0;
    g.bench_function("torus: move one control point of a patch and refresh", |b| {
        b.iter(|| {
            lift = if lift == 0.0 { 0.3 } else { 0.0 };
            let mut n = net.clone();
            n[5].z += lift;
            let rects = edited.set_bezier_net(3, 4, n).unwrap();
            samples.refresh(&edited, &rects)
        })
    });
    let mut heart = curve.clone();
    let mut curve_samples = splinekit::curve::CurveSamples::uniform(&heart, 2000, 0).unwrap();
    let points = heart.local_bezier_points(2).unwrap().to_vec();
    g.bench_function("heart, 2000 samples: move one control point of a local and refresh", |b| {
        b.iter(|| {
            lift = if lift == 0.0 { 0.5 } else { 0.0 };
            let mut p = points.clone();
            p[1].x += lift;
            let ranges = heart.set_local_bezier_points(2, p).unwrap();
            curve_samples.refresh(&heart, &ranges)
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
