//! The same workloads in splinekit, curvo and truck-geometry: a clamped uniform cubic 3-D
//! B-spline with 1000 control points, evaluated at 10⁶ parameters (random order and
//! sorted), points and first derivatives; the same curve with 10⁵ control points at 2·10⁴
//! random parameters; a bicubic surface grid. splinekit alone: its batch call on random
//! parameters, the parallel batch (feature `parallel`), a blending-spline curve batch with
//! two derivatives. And the floor: the time to write the output arrays to memory (the
//! least any library can take). Best of 5 runs; prints ns per evaluation.

use std::hint::black_box;
use std::time::Instant;

mod workload;

use workload::{M, N, N_LARGE, control, knots, params};

/// Random parameters of the large curve.
const M_LARGE: usize = 20_000;

/// Surface workload: a bicubic B-spline surface with 100 × 100 control points, points and
/// unit normals on a G × G grid (G = 300), best of 5, ns per grid point.
const G: usize = 300;

fn surface_net(i: usize, j: usize) -> [f64; 3] {
    [i as f64, j as f64, ((i as f64) * 0.3).sin() * ((j as f64) * 0.2).cos()]
}

fn surfaces(rows: &mut Vec<(String, String, f64, f64)>) {
    let k: Vec<f64> = {
        let mut k = vec![0.0; 4];
        for i in 1..97 {
            k.push(i as f64 / 97.0);
        }
        k.extend([1.0; 4]);
        k
    };
    let g: Vec<f64> = (0..G).map(|i| i as f64 / (G - 1) as f64).collect();
    let what = "surface grid: points + normals".to_string();
    {
        use splinekit::Point;
        use splinekit::surface::{BSplineSurface, Surface};
        let net = (0..100).map(|i| (0..100).map(|j| Point::<3>::from(surface_net(i, j))).collect()).collect();
        let s = BSplineSurface::new((3, 3), k.clone(), k.clone(), net, (false, false)).unwrap();
        let mut pn = vec![Point::<3>::zeros(); 2 * G * G];
        let r = time_batch(
            G * G,
            &mut pn,
            &mut |pn| {
                let (p, n) = pn.split_at_mut(G * G);
                s.eval_grid_with_normals(&g, &g, p, n)
            },
            &|pn| pn.iter().map(|q| q[2]).sum(),
        );
        rows.push(("splinekit".into(), what.clone(), r.0, r.1));
    }
    {
        use curvo::prelude::NurbsSurface3D;
        use nalgebra::Point4;
        let net = (0..100)
            .map(|i| {
                (0..100)
                    .map(|j| {
                        let c = surface_net(i, j);
                        Point4::new(c[0], c[1], c[2], 1.0)
                    })
                    .collect()
            })
            .collect();
        let s = NurbsSurface3D::<f64>::new(3, 3, k.clone(), k.clone(), net);
        let r = time_per(G * G, &mut || {
            let mut sum = 0.0;
            for &u in &g {
                for &v in &g {
                    sum += s.point_at(u, v).z + s.normal_at(u, v).normalize().z;
                }
            }
            sum
        });
        rows.push(("curvo 0.3".into(), what.clone(), r.0, r.1));
    }
    // The floor: writing the 2·G² output points (24 bytes each) to memory.
    let mut p = vec![[0.0f64; 3]; 2 * G * G];
    let r = time_per(G * G, &mut || {
        for (i, q) in p.iter_mut().enumerate() {
            *q = [i as f64; 3];
        }
        black_box(&mut p);
        p[G][2]
    });
    rows.push(("floor (write output)".into(), what, r.0, r.1));
}

/// Best of 5 runs of the batch call `run`, which writes the array `out`, in ns per element for
/// `count` elements; the checksum `check` of `out` is taken once afterwards. Summing the
/// array is no part of the call timed: its serial additions alone cost about 1.3 ns an
/// element, more than half of a sorted batch (the output is written to memory and read by
/// the checksum, so nothing is optimised away).
fn time_batch<T>(
    count: usize,
    out: &mut [T],
    run: &mut dyn FnMut(&mut [T]),
    check: &dyn Fn(&[T]) -> f64,
) -> (f64, f64) {
    let mut best = f64::INFINITY;
    for _ in 0..5 {
        let t = Instant::now();
        run(out);
        black_box(&mut *out);
        best = best.min(t.elapsed().as_secs_f64());
    }
    (best * 1e9 / count as f64, check(out))
}

/// Best-of-5 time per element in ns; `f` returns a checksum so nothing is optimised away.
fn time(f: &mut dyn FnMut() -> f64) -> (f64, f64) {
    time_per(M, f)
}

/// Best of 5 runs of `f`, in ns per element for `count` elements, with f's checksum.
fn time_per(count: usize, f: &mut dyn FnMut() -> f64) -> (f64, f64) {
    let mut best = f64::INFINITY;
    let mut sum = 0.0;
    for _ in 0..5 {
        let t = Instant::now();
        sum = black_box(f());
        best = best.min(t.elapsed().as_secs_f64());
    }
    (best * 1e9 / count as f64, sum)
}

fn main() {
    let (random, sorted) = params();
    let k = knots(N);
    let k_large = knots(N_LARGE);
    let random_large = &random[..M_LARGE];
    let mut rows: Vec<(String, String, f64, f64)> = Vec::new();

    // splinekit
    {
        use splinekit::Point;
        use splinekit::curve::{BSplineCurve, Curve};
        let c = BSplineCurve::new(3, k.clone(), (0..N).map(|i| Point::<3>::from(control(i))).collect()).unwrap();
        let mut out = vec![Point::<3>::zeros(); 2 * M];
        rows.push(("splinekit".into(), "point, random order".into(), 0.0, 0.0));
        let r = time(&mut || random.iter().map(|&t| c.point(t).sum()).sum());
        rows.last_mut().unwrap().2 = r.0;
        rows.last_mut().unwrap().3 = r.1;
        let r = time_batch(M, &mut out[..M], &mut |o| c.eval_many(&sorted, 0, o), &|o| o.iter().map(|p| p.sum()).sum());
        rows.push(("splinekit".into(), "point, sorted batch".into(), r.0, r.1));
        let r = time_batch(M, &mut out, &mut |o| c.eval_many(&sorted, 1, o), &|o| {
            o.iter().skip(1).step_by(2).map(|p| p[1]).sum()
        });
        rows.push(("splinekit".into(), "first derivative, sorted".into(), r.0, r.1));
        let r = time_batch(M, &mut out[..M], &mut |o| c.eval_many(&random, 0, o), &|o| o.iter().map(|p| p.sum()).sum());
        rows.push(("splinekit".into(), "point, random order (batch)".into(), r.0, r.1));
        {
            let r =
                time_batch(M, &mut out[..M], &mut |o| splinekit::curve::parallel::eval_many(&c, &sorted, 0, o), &|o| {
                    o.iter().map(|p| p.sum()).sum()
                });
            rows.push(("splinekit (parallel)".into(), "point, sorted batch".into(), r.0, r.1));
            let r =
                time_batch(M, &mut out[..M], &mut |o| splinekit::curve::parallel::eval_many(&c, &random, 0, o), &|o| {
                    o.iter().map(|p| p.sum()).sum()
                });
            rows.push(("splinekit (parallel)".into(), "point, random order (batch)".into(), r.0, r.1));
        }
        let large = BSplineCurve::new(3, k_large.clone(), (0..N_LARGE).map(|i| Point::<3>::from(control(i))).collect())
            .unwrap();
        let r = time_per(M_LARGE, &mut || random_large.iter().map(|&t| large.point(t).sum()).sum());
        rows.push(("splinekit".into(), "point, random, 10^5 cp".into(), r.0, r.1));
        let r = time_batch(M_LARGE, &mut out[..M_LARGE], &mut |o| large.eval_many(random_large, 0, o), &|o| {
            o.iter().map(|p| p.sum()).sum()
        });
        rows.push(("splinekit".into(), "point, random, 10^5 cp (batch)".into(), r.0, r.1));

        // A closed blending-spline curve (the heart, 10 cubic Bézier locals, ERBS) at 10⁶
        // parameters with two derivatives.
        use splinekit::blend::{BlendingCurveOptions, BlendingSplineCurve, LocalKind};
        let heart = BlendingSplineCurve::from_model(
            std::sync::Arc::new(splinekit::curve::model::Heart::new(1.0).unwrap()),
            10,
            &BlendingCurveOptions { local: LocalKind::Bezier(3), closed: Some(true), ..Default::default() },
        )
        .unwrap();
        let ts: Vec<f64> = sorted.iter().map(|t| t * std::f64::consts::TAU).collect();
        let mut out3 = vec![Point::<3>::zeros(); 3 * M];
        let r = time_batch(M, &mut out3, &mut |o| heart.eval_many(&ts, 2, o), &|o| {
            o.iter().skip(2).step_by(3).map(|p| p[1]).sum()
        });
        rows.push(("splinekit".into(), "blending curve, 2 derivatives".into(), r.0, r.1));
    }

    // The floor: writing 10⁶ points (24 MB) to memory, and 2·10⁶ for the first derivative.
    {
        let mut out = vec![[0.0f64; 3]; 2 * M];
        let r = time(&mut || {
            for (i, q) in out[..M].iter_mut().enumerate() {
                *q = [i as f64; 3];
            }
            black_box(&mut out);
            out[M / 2][1]
        });
        rows.push(("floor (write output)".into(), "point, sorted batch".into(), r.0, r.1));
        let r = time(&mut || {
            for (i, q) in out.iter_mut().enumerate() {
                *q = [i as f64; 3];
            }
            black_box(&mut out);
            out[M / 2][1]
        });
        rows.push(("floor (write output)".into(), "first derivative, sorted".into(), r.0, r.1));
        let mut out3 = vec![[0.0f64; 3]; 3 * M];
        let r = time(&mut || {
            for (i, q) in out3.iter_mut().enumerate() {
                *q = [i as f64; 3];
            }
            black_box(&mut out3);
            out3[M / 2][1]
        });
        rows.push(("floor (write output)".into(), "blending curve, 2 derivatives".into(), r.0, r.1));
    }

    // curvo (homogeneous control points (x, y, z, w))
    {
        use curvo::prelude::NurbsCurve3D;
        use nalgebra::Point4;
        let pts = (0..N)
            .map(|i| {
                let c = control(i);
                Point4::new(c[0], c[1], c[2], 1.0)
            })
            .collect();
        let c = NurbsCurve3D::<f64>::try_new(3, pts, k.clone()).unwrap();
        let r = time(&mut || random.iter().map(|&t| c.point_at(t).coords.sum()).sum());
        rows.push(("curvo 0.3".into(), "point, random order".into(), r.0, r.1));
        let r = time(&mut || sorted.iter().map(|&t| c.point_at(t).coords.sum()).sum());
        rows.push(("curvo 0.3".into(), "point, sorted batch".into(), r.0, r.1));
        let r = time(&mut || sorted.iter().map(|&t| c.rational_derivatives(t, 1)[1].y).sum());
        rows.push(("curvo 0.3".into(), "first derivative, sorted".into(), r.0, r.1));
        let pts = (0..N_LARGE)
            .map(|i| {
                let c = control(i);
                Point4::new(c[0], c[1], c[2], 1.0)
            })
            .collect();
        let large = NurbsCurve3D::<f64>::try_new(3, pts, k_large.clone()).unwrap();
        let r = time_per(M_LARGE, &mut || random_large.iter().map(|&t| large.point_at(t).coords.sum()).sum());
        rows.push(("curvo 0.3".into(), "point, random, 10^5 cp".into(), r.0, r.1));
    }

    // truck-geometry
    {
        use truck_geometry::prelude::*;
        let c = BSplineCurve::new(KnotVec::from(k.clone()), (0..N).map(|i| Point3::from(control(i))).collect());
        // Every coordinate, as the other libraries' loops.
        let coordinate_sum = |p: Point3| p.x + p.y + p.z;
        let r = time(&mut || random.iter().map(|&t| coordinate_sum(c.subs(t))).sum());
        rows.push(("truck-geometry 0.5".into(), "point, random order".into(), r.0, r.1));
        let r = time(&mut || sorted.iter().map(|&t| coordinate_sum(c.subs(t))).sum());
        rows.push(("truck-geometry 0.5".into(), "point, sorted batch".into(), r.0, r.1));
        let r = time(&mut || sorted.iter().map(|&t| c.der(t).y).sum());
        rows.push(("truck-geometry 0.5".into(), "first derivative, sorted".into(), r.0, r.1));
        let large =
            BSplineCurve::new(KnotVec::from(k_large.clone()), (0..N_LARGE).map(|i| Point3::from(control(i))).collect());
        let r = time_per(M_LARGE, &mut || random_large.iter().map(|&t| coordinate_sum(large.subs(t))).sum());
        rows.push(("truck-geometry 0.5".into(), "point, random, 10^5 cp".into(), r.0, r.1));
    }

    surfaces(&mut rows);

    for (lib, what, ns, check) in &rows {
        println!("{lib}\t{what}\t{ns:.2}\t{check:.9e}");
    }
}
