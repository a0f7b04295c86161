//! splinekit's own evaluation workloads of `main.rs` alone, each beside its floor (writing
//! the same output array), best of `REPEATS` (default 15) runs: a quick check of one
//! kernel while tuning it. Usage: `kernels [WORKLOAD-SUBSTRING] [REPEATS]`.

use std::hint::black_box;
use std::time::Instant;

use splinekit::Point;
use splinekit::curve::{BSplineCurve, Curve};

#[path = "../workload.rs"]
mod workload;

use workload::{M, N, N_LARGE, control, knots, params};

const G: usize = 300;

fn best(repeats: usize, count: usize, f: &mut dyn FnMut() -> f64) -> f64 {
    let mut best = f64::INFINITY;
    for _ in 0..repeats {
        let t = Instant::now();
        black_box(f());
        best = best.min(t.elapsed().as_secs_f64());
    }
    best * 1e9 / count as f64
}

/// Writing `points` 3-D points per evaluation, `count` evaluations.
fn floor(repeats: usize, count: usize, points: usize) -> f64 {
    let mut out = vec![[0.0f64; 3]; count * points];
    best(repeats, count, &mut || {
        for (i, q) in out.iter_mut().enumerate() {
            *q = [i as f64; 3];
        }
        black_box(&mut out);
        out[count / 2][1]
    })
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let filter = args.get(1).cloned().unwrap_or_default();
    let repeats: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(15);
    let run = |name: &str| name.contains(&filter);
    let (random, sorted) = params();
    let curve =
        |n: usize| BSplineCurve::new(3, knots(n), (0..n).map(|i| Point::<3>::from(control(i))).collect()).unwrap();
    let report =
        |name: &str, ns: f64, fl: f64| println!("{name:<34} {ns:8.2} ns   floor {fl:6.2} ns   ×{:5.2}", ns / fl);

    let c = curve(N);
    let mut out = vec![Point::<3>::zeros(); 3 * M];
    if run("sorted points") {
        let ns = best(repeats, M, &mut || {
            c.eval_many(&sorted, 0, &mut out[..M]);
            out[M / 3][1]
        });
        report("sorted points", ns, floor(repeats, M, 1));
    }
    if run("lanes") {
        // The portable one-at-a-time points loop (`BezierSpans::eval_many`, order 0) beside
        // the blocked loop of `eval_many_points` (AVX2 where the CPU has it), alternating.
        use splinekit::basis::SplineAxis;
        use splinekit::curve::bezier_spans::BezierSpans;
        use splinekit::curve::span_kernel::ReciprocalKnotDifferences;
        let (knots, points) = c.evaluation_data();
        let inv = ReciprocalKnotDifferences::new(knots, 3);
        let spans = BezierSpans::new(knots, &inv, points, 3).unwrap();
        let axis = SplineAxis::new(3, knots.to_vec(), points.len(), false, "knots").unwrap();
        let (mut one, mut lanes) = (f64::INFINITY, f64::INFINITY);
        for _ in 0..repeats {
            one = one.min(best(1, M, &mut || {
                spans.eval_many(&sorted, 0, &mut out[..M], |t| t.clamp(0.0, 1.0), |_, t| axis.span(t));
                out[M / 3][1]
            }));
            lanes = lanes.min(best(1, M, &mut || {
                spans.eval_many_lanes(&sorted, 0, &mut out[..M], |t| t.clamp(0.0, 1.0), |_, t| axis.span(t));
                out[M / 3][1]
            }));
        }
        let fl = floor(repeats, M, 1);
        report("sorted points, one at a time", one, fl);
        report("sorted points, blocks of 4", lanes, fl);
    }
    if run("sorted points, 10⁵ control points") {
        // About ten parameters a span: blocks of four often straddle two spans.
        let big = curve(N_LARGE);
        let ns = best(repeats, M, &mut || {
            big.eval_many(&sorted, 0, &mut out[..M]);
            out[M / 3][1]
        });
        report("sorted points, 10⁵ control points", ns, floor(repeats, M, 1));
    }
    if run("sparse sorted") {
        // Sorted parameters about as many as the spans, or fewer (plotting a large curve):
        // blocks of four run over four spans or more.
        let big = curve(N_LARGE);
        for per_span in [1.0, 0.3] {
            let m = (N_LARGE as f64 * per_span) as usize;
            let ts: Vec<f64> = (0..m).map(|i| i as f64 / (m - 1) as f64).collect();
            let reps = repeats * (M / m);
            let ns = best(reps, m, &mut || {
                big.eval_many(&ts, 0, &mut out[..m]);
                out[m / 3][1]
            });
            let random: Vec<f64> = random[..m].to_vec();
            let nr = best(reps, m, &mut || {
                big.eval_many(&random, 0, &mut out[..m]);
                out[m / 3][1]
            });
            report(&format!("sparse sorted, {per_span} a span, 10⁵ cp"), ns, floor(reps, m, 1));
            report("  random parameters, as many", nr, floor(reps, m, 1));
        }
    }
    if run("random points") {
        // The peers' workload: point(t) one parameter at a time, random order, summed.
        let ns = best(repeats, M, &mut || random.iter().map(|&t| c.point(t).sum()).sum());
        report("random points, point(t)", ns, floor(repeats, M, 1));
    }
    if run("random batch") {
        // The same parameters in one call: at least as fast as the loop of point(t).
        let ns = best(repeats, M, &mut || {
            c.eval_many(&random, 0, &mut out[..M]);
            out[M / 3][1]
        });
        report("random batch, eval_many", ns, floor(repeats, M, 1));
    }
    if run("sorted first derivative") {
        let ns = best(repeats, M, &mut || {
            c.eval_many(&sorted, 1, &mut out[..2 * M]);
            out[M / 3][1]
        });
        report("sorted first derivative", ns, floor(repeats, M, 2));
    }
    if run("blending curve") {
        use splinekit::blend::{BlendingCurveOptions, BlendingSplineCurve, LocalKind};
        let heart = BlendingSplineCurve::from_model(
            std::sync::Arc::new(splinekit::curve::model::Heart::new(1.0).unwrap()),
            10,
            &BlendingCurveOptions { local: LocalKind::Bezier(3), closed: Some(true), ..Default::default() },
        )
        .unwrap();
        let ts: Vec<f64> = sorted.iter().map(|t| t * std::f64::consts::TAU).collect();
        let ns = best(repeats, M, &mut || {
            heart.eval_many(&ts, 2, &mut out);
            out[M / 3][1]
        });
        report("blending curve, 2 derivatives", ns, floor(repeats, M, 3));
    }
    if run("surface grid") {
        use splinekit::surface::{BSplineSurface, Surface};
        let mut k = vec![0.0; 4];
        k.extend((1..97).map(|i| i as f64 / 97.0));
        k.extend([1.0; 4]);
        let net = (0..100)
            .map(|i| {
                (0..100)
                    .map(|j| Point::<3>::new(i as f64, j as f64, ((i as f64) * 0.3).sin() * ((j as f64) * 0.2).cos()))
                    .collect()
            })
            .collect();
        let s = BSplineSurface::new((3, 3), k.clone(), k, net, (false, false)).unwrap();
        let g: Vec<f64> = (0..G).map(|i| i as f64 / (G - 1) as f64).collect();
        let (mut p, mut nn) = (vec![Point::<3>::zeros(); G * G], vec![Point::<3>::zeros(); G * G]);
        let ns = best(repeats, G * G, &mut || {
            s.eval_grid_with_normals(&g, &g, &mut p, &mut nn);
            p[G][2] + nn[G][2]
        });
        report("surface grid: points + normals", ns, floor(repeats, G * G, 2));
    }
}
