//! The query benchmarks of issue 14 that curvo 0.3 can also answer, splinekit and curvo
//! side by side in one process, on the shapes of crates/splinekit/benches/common/
//! query_workloads.rs (the shapes bench/ocp/speed.py times against OpenCASCADE):
//!
//! - all intersections of the two wavy cubic B-splines with 100 control points each
//!   (`splinekit::query::intersect_curves` at tolerance 1e-9 against curvo's
//!   `find_intersection` with its default `CurveIntersectionSolverOptions`), time per call;
//! - 10⁴ projections onto the bicubic 8 × 8 patch (`SurfaceProjector::nearest` against
//!   `NurbsSurface3D::find_closest_point` without a hint), time for all 10⁴ (curvo, which
//!   tessellates the surface for each call, on every 100th point, times 100);
//! - 10⁴ projections onto the first wavy curve (`CurveProjector::nearest` against
//!   `NurbsCurve2D::find_closest_point`), time for all 10⁴.
//!
//! Each time is the median of REPEATS runs (first argument, default 11), the same count for
//! both libraries; splinekit's projectors are built inside the timed run. curvo has no
//! surface–surface intersection, so the torus–cylinder workload is splinekit and
//! OpenCASCADE only.
//!
//! The answers are checked, not only timed: curvo's curves are built from splinekit's
//! control points and knots, and their points must agree at a few parameters; the crossing
//! counts must agree and every curvo crossing must lie within 1e-6 of one of splinekit's;
//! a projection whose distance is more than 1e-6 above the other library's counts as a
//! miss of that library (a local minimum, or Newton not converged). Any disagreement is
//! printed loudly with the distance between the two curves at the reported parameters.
//! Prints a table in ms and the ratio curvo / splinekit (> 1: splinekit is faster).
//!
//! `cargo run --release --bin queries [REPEATS]` (bench/peers/run.sh runs it).

use std::hint::black_box;
use std::time::Instant;

use curvo::prelude::{HasIntersection, Intersects, NurbsCurve2D, NurbsSurface3D};
use nalgebra::{Point2, Point3, Point4};
use splinekit::Point;
use splinekit::curve::{BSplineCurve, Curve};
use splinekit::query::{CurveProjector, SurfaceProjector, intersect_curves};
use splinekit::surface::{BSplineSurface, Surface};

#[path = "../../../../crates/splinekit/benches/common/query_workloads.rs"]
mod query_workloads;
use query_workloads::{bicubic, curve_query_points, query_points, wavy_curves};

/// curvo's surface projections are timed on every `CURVO_SURFACE_STRIDE`-th query point.
const CURVO_SURFACE_STRIDE: usize = 100;

/// The median of `repeats` timings of `f` (seconds) and its last result.
fn median<T>(repeats: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let start = Instant::now();
    let mut out = black_box(f());
    let mut times = vec![start.elapsed().as_secs_f64()];
    for _ in 1..repeats {
        let start = Instant::now();
        out = black_box(f());
        times.push(start.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (times[times.len() / 2], out)
}

/// curvo's copy of a splinekit B-spline curve: the same degree, knots and control points
/// (weight 1).
fn curvo_curve(c: &BSplineCurve<2>) -> Result<NurbsCurve2D<f64>, String> {
    let pts = c.control_points().iter().map(|p| Point3::new(p[0], p[1], 1.0)).collect();
    NurbsCurve2D::try_new(c.degree(), pts, c.knots().to_vec()).map_err(|e| e.to_string())
}

/// curvo's copy of a splinekit B-spline surface (net[i][j], i along u).
fn curvo_surface(s: &BSplineSurface<3>) -> NurbsSurface3D<f64> {
    let (p, q) = s.degrees();
    let (ku, kv) = s.knots();
    let net =
        s.control_points().iter().map(|row| row.iter().map(|c| Point4::new(c[0], c[1], c[2], 1.0)).collect()).collect();
    NurbsSurface3D::new(p, q, ku.to_vec(), kv.to_vec(), net)
}

/// The clamped uniform cubic knots on [0, 1] for n control points, written out here, to
/// check that splinekit's `clamped_uniform` means the same knots.
fn clamped_uniform_knots(n: usize) -> Vec<f64> {
    let mut k = vec![0.0; 4];
    k.extend((1..n - 3).map(|i| i as f64 / (n - 3) as f64));
    k.extend([1.0; 4]);
    k
}

/// The largest distance between the two libraries' points of a curve at 101 parameters.
fn curve_gap(ours: &BSplineCurve<2>, theirs: &NurbsCurve2D<f64>) -> f64 {
    (0..=100)
        .map(|i| {
            let t = i as f64 / 100.0;
            let (a, b) = (ours.point(t), theirs.point_at(t));
            ((a[0] - b.x).powi(2) + (a[1] - b.y).powi(2)).sqrt()
        })
        .fold(0.0, f64::max)
}

struct Row {
    name: &'static str,
    ours: f64,
    theirs: f64,
    note: String,
}

fn main() {
    let repeats: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(11).max(1);
    let mut rows = Vec::new();
    let mut disagreements = 0usize;

    // Curve–curve intersection.
    let (ca, cb) = wavy_curves();
    let (va, vb) = match (curvo_curve(&ca), curvo_curve(&cb)) {
        (Ok(a), Ok(b)) => (a, b),
        (a, b) => {
            eprintln!("curvo refused the wavy curves: {:?} {:?}", a.err(), b.err());
            std::process::exit(1);
        }
    };
    let knots_agree = ca.knots() == clamped_uniform_knots(100).as_slice() && cb.knots() == ca.knots();
    let gap = curve_gap(&ca, &va).max(curve_gap(&cb, &vb));
    println!("wavy curves: knots are clamped uniform: {knots_agree}; largest point gap splinekit vs curvo: {gap:.1e}");
    if !knots_agree || gap > 1e-12 {
        println!("!!! DISAGREEMENT: the two libraries' copies of the wavy curves differ");
        disagreements += 1;
    }
    let (ours, ours_x) = median(repeats, || intersect_curves(&ca, &cb, 1e-9).map(|x| x.points));
    let (theirs, theirs_x) = median(repeats, || va.find_intersection(&vb, None));
    let ours_x = ours_x.unwrap_or_else(|e| {
        println!("!!! splinekit failed: {e}");
        Vec::new()
    });
    let theirs_x: Vec<(f64, f64)> = match theirs_x {
        Ok(x) => x.iter().map(|i| (i.a().1, i.b().1)).collect(),
        Err(e) => {
            println!("!!! curvo failed: {e}");
            Vec::new()
        }
    };
    // The distance between the two curves at a pair of parameters: 0 at a true crossing.
    let miss = |ta: f64, tb: f64| (ca.point(ta) - cb.point(tb)).norm();
    let mut worst = 0.0f64;
    for &(ta, tb) in &theirs_x {
        let p = ca.point(ta);
        let near = ours_x.iter().map(|x| (x.point - p).norm()).fold(f64::INFINITY, f64::min);
        worst = worst.max(near);
        if near > 1e-6 {
            disagreements += 1;
            println!(
                "!!! DISAGREEMENT: curvo crossing at t_a {ta:.12}, t_b {tb:.12} is {near:.1e} from every splinekit \
                 crossing; |a(t_a) - b(t_b)| = {:.1e}",
                miss(ta, tb)
            );
        }
    }
    for x in &ours_x {
        let near = theirs_x.iter().map(|&(ta, _)| (ca.point(ta) - x.point).norm()).fold(f64::INFINITY, f64::min);
        if near > 1e-6 {
            disagreements += 1;
            println!(
                "!!! DISAGREEMENT: splinekit crossing at t_a {:.12}, t_b {:.12} is {near:.1e} from every curvo \
                 crossing; |a(t_a) - b(t_b)| = {:.1e}",
                x.t_a,
                x.t_b,
                miss(x.t_a, x.t_b)
            );
        }
    }
    if ours_x.len() != theirs_x.len() || ours_x.len() != 22 {
        disagreements += 1;
        println!("!!! DISAGREEMENT: {} crossings (splinekit) vs {} (curvo), 22 expected", ours_x.len(), theirs_x.len());
    }
    let residual = |xs: &mut dyn Iterator<Item = (f64, f64)>| xs.map(|(a, b)| miss(a, b)).fold(0.0, f64::max);
    rows.push(Row {
        name: "all intersections of two cubic B-splines (100 control points each)",
        ours,
        theirs,
        note: format!(
            "{} vs {} crossings, farthest curvo crossing from splinekit's {worst:.1e}, largest |a-b| {:.1e} vs {:.1e}",
            ours_x.len(),
            theirs_x.len(),
            residual(&mut ours_x.iter().map(|x| (x.t_a, x.t_b))),
            residual(&mut theirs_x.iter().copied()),
        ),
    });

    // Projections onto the bicubic patch.
    let surface = bicubic();
    let vs = curvo_surface(&surface);
    let surface_gap = (0..=10)
        .flat_map(|i| (0..=10).map(move |j| (i as f64 / 10.0, j as f64 / 10.0)))
        .map(|(u, v)| {
            let (a, b) = (surface.point(u, v), vs.point_at(u, v));
            (a - Point::<3>::new(b.x, b.y, b.z)).norm()
        })
        .fold(0.0, f64::max);
    println!("bicubic patch: largest point gap splinekit vs curvo: {surface_gap:.1e}");
    if surface_gap > 1e-12 {
        println!("!!! DISAGREEMENT: the two libraries' copies of the bicubic patch differ");
        disagreements += 1;
    }
    let points = query_points();
    let (ours, ours_d) = median(repeats, || {
        let projector = SurfaceProjector::new(&surface);
        points.iter().map(|q| projector.nearest(q, 0.0).map(|n| n.distance).unwrap_or(f64::NAN)).collect::<Vec<_>>()
    });
    // curvo tessellates the surface afresh for every projection without a hint (tens of ms
    // each), so it is timed on every 100th query point and scaled to 10^4.
    let sample: Vec<usize> = (0..points.len()).step_by(CURVO_SURFACE_STRIDE).collect();
    let (theirs, theirs_d) = median(repeats, || {
        sample
            .iter()
            .map(|&i| {
                let q = &points[i];
                let q3 = Point3::new(q[0], q[1], q[2]);
                vs.find_closest_point(&q3, None).map(|p| (p - q3).norm()).unwrap_or(f64::NAN)
            })
            .collect::<Vec<_>>()
    });
    let ours_sampled: Vec<f64> = sample.iter().map(|&i| ours_d[i]).collect();
    let theirs = theirs * CURVO_SURFACE_STRIDE as f64;
    rows.push(compare_projections(
        "10^4 projections onto a bicubic 8x8 surface (curvo: 10^2, x100)",
        (ours, theirs),
        &ours_sampled,
        &theirs_d,
        &mut disagreements,
    ));

    // Projections onto the first wavy curve.
    let points = curve_query_points();
    let (ours, ours_d) = median(repeats, || {
        let projector = CurveProjector::new(&ca);
        points.iter().map(|q| projector.nearest(q, 0.0).map(|n| n.distance).unwrap_or(f64::NAN)).collect::<Vec<_>>()
    });
    let (theirs, theirs_d) = median(repeats, || {
        points
            .iter()
            .map(|q| {
                let q2 = Point2::new(q[0], q[1]);
                va.find_closest_point(&q2).map(|p| (p - q2).norm()).unwrap_or(f64::NAN)
            })
            .collect::<Vec<_>>()
    });
    rows.push(compare_projections(
        "10^4 projections onto a wavy cubic (100 control points)",
        (ours, theirs),
        &ours_d,
        &theirs_d,
        &mut disagreements,
    ));

    println!("{:<68} {:>11} {:>11} {:>13}", "workload", "splinekit", "curvo 0.3", "curvo/ours");
    for r in &rows {
        println!(
            "{:<68} {:>8.3} ms {:>8.3} ms {:>12.2}x  {}",
            r.name,
            r.ours * 1e3,
            r.theirs * 1e3,
            r.theirs / r.ours,
            r.note
        );
    }
    println!(
        "(medians of {repeats} runs each; curvo/ours > 1 means splinekit is faster; curvo has no surface-surface intersection)"
    );
    if disagreements > 0 {
        println!("!!! {disagreements} disagreement(s) between splinekit and curvo, see above");
    } else {
        println!("answers agree");
    }
}

/// A table row for a projection workload, with the two libraries' distances compared: a
/// distance more than 1e-6 above the other's is a miss (not the nearest point).
fn compare_projections(
    name: &'static str,
    (ours, theirs): (f64, f64),
    ours_d: &[f64],
    theirs_d: &[f64],
    disagreements: &mut usize,
) -> Row {
    let ours_misses = ours_d.iter().zip(theirs_d).filter(|(a, b)| !(**a <= **b + 1e-6)).count();
    let theirs_misses = ours_d.iter().zip(theirs_d).filter(|(a, b)| !(**b <= **a + 1e-6)).count();
    let worst = ours_d.iter().zip(theirs_d).map(|(a, b)| b - a).filter(|d| d.is_finite()).fold(0.0, f64::max);
    if ours_misses > 0 {
        *disagreements += 1;
        println!("!!! DISAGREEMENT: {name}: splinekit's distance exceeds curvo's by > 1e-6 at {ours_misses} points");
    }
    if theirs_misses > 0 {
        *disagreements += 1;
        println!(
            "!!! DISAGREEMENT: {name}: curvo's distance exceeds splinekit's by > 1e-6 at {theirs_misses} points \
             (up to {worst:.1e}): curvo did not find the nearest point there"
        );
    }
    Row {
        name,
        ours,
        theirs,
        note: format!(
            "splinekit misses {ours_misses}, curvo misses {theirs_misses} of {} (curvo farther by up to {worst:.1e})",
            ours_d.len()
        ),
    }
}
