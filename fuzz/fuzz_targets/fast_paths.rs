//! Every fast evaluation path against plain Cox–de Boor, with arbitrary inputs: the
//! comparison of `crates/splinekit/tests/fast_paths.rs` (whose independent truth,
//! `tests/common/plain_spline.rs`, is included here by path). The bytes choose degrees
//! (1–12), control point counts, knot gaps (0 — a repeated knot — or 0.25 … 2.25),
//! periodicity, weights, coordinates and parameters (raw f64s, any finite value: inside,
//! outside and at the ends of the domain); a difference beyond rounding is a crash.
#![no_main]

#[path = "../../crates/splinekit/tests/common/plain_spline.rs"]
mod plain;

use libfuzzer_sys::fuzz_target;
use plain::{Limit, PlainAxis};
use splinekit::Point;
use splinekit::basis::Side;
use splinekit::curve::{BSplineCurve, Curve, NurbsCurve};
use splinekit::surface::{BSplineSurface, NurbsSurface, Surface};

/// Reads the input front to back; zeros once it runs out.
struct Bytes<'a>(&'a [u8]);
impl Bytes<'_> {
    fn byte(&mut self) -> u8 {
        let Some((&b, rest)) = self.0.split_first() else { return 0 };
        self.0 = rest;
        b
    }
    fn unit(&mut self) -> f64 {
        self.byte() as f64 / 255.0
    }
    fn f64(&mut self) -> f64 {
        let mut b = [0u8; 8];
        for x in &mut b {
            *x = self.byte();
        }
        f64::from_le_bytes(b)
    }
}

/// Knots for n control points of degree p: gaps 0 (a repeated knot; runs limited so the
/// knot vector is valid) or 0.25 … 2.25; periodic knots repeat n gaps.
fn knots(b: &mut Bytes, p: usize, n: usize, periodic: bool) -> Option<Vec<f64>> {
    let count = if periodic { n } else { n + p };
    let max_run = if periodic { p.saturating_sub(1) } else { p };
    let mut run = 0;
    let mut gaps: Vec<f64> = (0..count)
        .map(|_| {
            let x = b.byte();
            let zero = x < 64 && run < max_run;
            run = if zero { run + 1 } else { 0 };
            if zero { 0.0 } else { 0.25 + 2.0 * (x as f64 / 255.0) }
        })
        .collect();
    if periodic {
        gaps[0] = gaps[0].max(0.25);
        gaps[count - 1] = gaps[count - 1].max(0.25);
    }
    let mut k = vec![0.0];
    for i in 0..n + p {
        let next = k[i] + gaps[i % count];
        k.push(next);
    }
    // The validator has the last word (an empty domain is simply skipped).
    (k[p] < k[n]).then_some(k)
}

fn tolerance(p: usize, k: usize, rational: bool) -> f64 {
    let growth: f64 = (0..k.min(p)).map(|j| 8.0 * (p - j) as f64).product();
    let spread: f64 = if rational { 4.0f64.powi(k as i32 + 1) } else { 1.0 };
    4e-13 * growth.max(1.0) * spread * (p + 1) as f64
}

fn close<const D: usize>(got: &Point<D>, want: &[f64], tol: f64) -> bool {
    let scale = want.iter().fold(1.0f64, |m, x| m.max(x.abs()));
    (0..D).all(|c| (got[c] - want[c]).abs() <= tol * scale)
}

fn curve(b: &mut Bytes) {
    let p = 1 + b.byte() as usize % 12;
    let n = p + 1 + b.byte() as usize % 6;
    let flags = b.byte();
    let (periodic, rational, order) = (flags & 1 == 1, flags & 2 == 2, (flags >> 2) as usize % 5);
    let Some(kn) = knots(b, p, n, periodic) else { return };
    let points: Vec<Vec<f64>> = (0..n).map(|_| vec![4.0 * b.unit() - 2.0, 4.0 * b.unit() - 2.0]).collect();
    let weights: Vec<f64> = (0..n).map(|_| if rational { 0.5 + 1.5 * b.unit() } else { 1.0 }).collect();
    let pts: Vec<Point<2>> = points.iter().map(|c| Point::<2>::new(c[0], c[1])).collect();
    let built: splinekit::Result<Box<dyn Curve<2>>> = match (rational, periodic) {
        (false, false) => BSplineCurve::new(p, kn.clone(), pts).map(|c| Box::new(c) as Box<dyn Curve<2>>),
        (false, true) => BSplineCurve::new_periodic(p, kn.clone(), pts).map(|c| Box::new(c) as Box<dyn Curve<2>>),
        (true, false) => NurbsCurve::new(p, kn.clone(), pts, weights.clone()).map(|c| Box::new(c) as Box<dyn Curve<2>>),
        (true, true) => {
            NurbsCurve::new_periodic(p, kn.clone(), pts, weights.clone()).map(|c| Box::new(c) as Box<dyn Curve<2>>)
        }
    };
    let Ok(c) = built else { return };
    let axis = if periodic { PlainAxis::periodic(p, &kn) } else { PlainAxis::open(p, &kn) };
    let (a, e) = axis.domain();
    let mut params: Vec<f64> = (0..8).map(|_| b.f64()).filter(|t| t.is_finite() && t.abs() < 1e6).collect();
    params.extend(kn.iter().copied().filter(|&t| t >= a && t <= e));
    let w = rational.then_some(&weights[..]);
    let mut out = vec![Point::<2>::zeros(); order + 1];
    for &t in &params {
        for (side, limit) in [(Side::Right, Limit::Right), (Side::Left, Limit::Left)] {
            c.eval_side(t, side, &mut out);
            let want = plain::curve(&axis, &points, w, t, limit, order);
            for k in 0..=order {
                assert!(
                    close(&out[k], &want[k], tolerance(p, k, rational)),
                    "degree {p} knots {kn:?} at {t} {side:?} order {k}: {:?} vs {:?}",
                    out[k],
                    want[k]
                );
            }
        }
    }
    let mut many = vec![Point::<2>::zeros(); params.len() * (order + 1)];
    c.eval_many(&params, order, &mut many);
    for (i, &t) in params.iter().enumerate() {
        let want = plain::curve(&axis, &points, w, t, Limit::Right, order);
        for k in 0..=order {
            assert!(close(&many[i * (order + 1) + k], &want[k], tolerance(p, k, rational)), "eval_many #{i} at {t}");
        }
    }
}

fn surface(b: &mut Bytes) {
    let (p, q) = (1 + b.byte() as usize % 12, 1 + b.byte() as usize % 12);
    let (nu, nv) = (p + 1 + b.byte() as usize % 3, q + 1 + b.byte() as usize % 3);
    let flags = b.byte();
    let periodic = (flags & 1 == 1, flags & 2 == 2);
    let rational = flags & 4 == 4;
    let (du, dv) = ((flags >> 3) as usize % 3, (flags >> 5) as usize % 3);
    let (Some(ku), Some(kv)) = (knots(b, p, nu, periodic.0), knots(b, q, nv, periodic.1)) else { return };
    let net: Vec<Vec<Vec<f64>>> =
        (0..nu).map(|_| (0..nv).map(|_| (0..3).map(|_| 4.0 * b.unit() - 2.0).collect()).collect()).collect();
    let weights: Vec<Vec<f64>> =
        (0..nu).map(|_| (0..nv).map(|_| if rational { 0.5 + 1.5 * b.unit() } else { 1.0 }).collect()).collect();
    let pnet: Vec<Vec<Point<3>>> =
        net.iter().map(|r| r.iter().map(|c| Point::<3>::new(c[0], c[1], c[2])).collect()).collect();
    let built: splinekit::Result<Box<dyn Surface<3>>> = if rational {
        NurbsSurface::new((p, q), ku.clone(), kv.clone(), pnet, weights.clone(), periodic)
            .map(|s| Box::new(s) as Box<dyn Surface<3>>)
    } else {
        BSplineSurface::new((p, q), ku.clone(), kv.clone(), pnet, periodic).map(|s| Box::new(s) as Box<dyn Surface<3>>)
    };
    let Ok(s) = built else { return };
    let axis = |k: &[f64], d: usize, per: bool| if per { PlainAxis::periodic(d, k) } else { PlainAxis::open(d, k) };
    let (au, av) = (axis(&ku, p, periodic.0), axis(&kv, q, periodic.1));
    let pick = |b: &mut Bytes, ax: &PlainAxis| {
        let (a, e) = ax.domain();
        let t = b.f64();
        if t.is_finite() && t.abs() < 1e6 { t } else { a + (e - a) * b.unit() }
    };
    let us: Vec<f64> = (0..3).map(|_| pick(b, &au)).collect();
    let vs: Vec<f64> = (0..3).map(|_| pick(b, &av)).collect();
    let w = rational.then_some(&weights[..]);
    let block = (du + 1) * (dv + 1);
    let mut grid = vec![Point::<3>::zeros(); us.len() * vs.len() * block];
    s.eval_grid(&us, &vs, du, dv, &mut grid);
    let (mut points, mut normals) = (vec![Point::<3>::zeros(); 9], vec![Point::<3>::zeros(); 9]);
    s.eval_grid_with_normals(&us, &vs, &mut points, &mut normals);
    let mut out = vec![Point::<3>::zeros(); block];
    for (a, &u) in us.iter().enumerate() {
        for (c, &v) in vs.iter().enumerate() {
            let want = plain::surface(&au, &av, &net, w, u, v, du, dv);
            s.eval_partials(u, v, du, dv, &mut out);
            for i in 0..=du {
                for j in 0..=dv {
                    let k = i * (dv + 1) + j;
                    let tol = tolerance(p, i, rational) * tolerance(q, j, rational) / tolerance(0, 0, false);
                    let g = (a * vs.len() + c) * block + k;
                    assert!(close(&out[k], &want[k], tol), "eval_partials ({u}, {v}) ({i}, {j})");
                    assert!(close(&grid[g], &want[k], tol), "eval_grid ({u}, {v}) ({i}, {j})");
                }
            }
            assert!(close(&points[a * vs.len() + c], &want[0], tolerance(p, 0, rational)), "grid point ({u}, {v})");
        }
    }
}

fuzz_target!(|data: &[u8]| {
    let mut b = Bytes(data);
    if b.byte() % 2 == 0 { curve(&mut b) } else { surface(&mut b) }
});
