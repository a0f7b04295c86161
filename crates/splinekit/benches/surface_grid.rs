//! A bicubic B-spline surface (100 × 100 control points) and a NURBS surface (the exact
//! torus) on a 1000 × 1000 grid with first partials and unit normals, one core.

use criterion::{Criterion, criterion_group, criterion_main};
use splinekit::Point;
use splinekit::surface::{BSplineSurface, NurbsSurface, Surface, unit_normal};
use std::hint::black_box;

/// Grid values (points, S_u, S_v) plus unit normals; returns a checksum.
fn points_partials_normals<S: Surface<3>>(
    s: &S,
    us: &[f64],
    vs: &[f64],
    values: &mut [Point<3>],
    normals: &mut [Point<3>],
) -> f64 {
    s.eval_grid(us, vs, 1, 1, values);
    for (n, v) in normals.iter_mut().zip(values.chunks_exact(4)) {
        *n = unit_normal(&v[2], &v[1]).unwrap_or_else(Point::<3>::zeros);
    }
    normals[normals.len() / 2][0]
}

fn bench(c: &mut Criterion) {
    let net: Vec<Vec<Point<3>>> = (0..100)
        .map(|i| {
            (0..100)
                .map(|j| Point::<3>::new(i as f64, j as f64, ((i as f64) * 0.3).sin() * ((j as f64) * 0.2).cos()))
                .collect()
        })
        .collect();
    let s = BSplineSurface::clamped_uniform((3, 3), net).unwrap();
    let torus = NurbsSurface::torus(3.0, 1.0).unwrap();
    let n = 1000;
    let us: Vec<f64> = (0..n).map(|i| i as f64 / (n - 1) as f64).collect();
    let mut values = vec![Point::<3>::zeros(); n * n * 4];
    let mut normals = vec![Point::<3>::zeros(); n * n];
    let mut g = c.benchmark_group("surface 1000x1000 grid, first partials + normals");
    g.sample_size(10);
    g.bench_function("bicubic B-spline, 100x100 control points", |b| {
        b.iter(|| points_partials_normals(&s, black_box(&us), &us, &mut values, &mut normals))
    });
    g.bench_function("NURBS torus (degree 2x2, 9x9 control points)", |b| {
        b.iter(|| points_partials_normals(&torus, black_box(&us), &us, &mut values, &mut normals))
    });
    let mut points = vec![Point::<3>::zeros(); n * n];
    g.bench_function("bicubic B-spline: eval_grid_with_normals", |b| {
        b.iter(|| {
            s.eval_grid_with_normals(black_box(&us), &us, &mut points, &mut normals);
            normals[n * n / 2][0]
        })
    });
    g.bench_function("NURBS torus: eval_grid_with_normals", |b| {
        b.iter(|| {
            torus.eval_grid_with_normals(black_box(&us), &us, &mut points, &mut normals);
            normals[n * n / 2][0]
        })
    });
    #[cfg(feature = "parallel")]
    g.bench_function("bicubic B-spline: eval_grid_with_normals, all cores (rayon)", |b| {
        b.iter(|| {
            splinekit::surface::parallel::eval_grid_with_normals(&s, black_box(&us), &us, &mut points, &mut normals);
            normals[n * n / 2][0]
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
