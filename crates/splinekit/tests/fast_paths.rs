//! Differential property tests: every specialised evaluation path of the kernel against
//! the plain Cox–de Boor evaluation of `common/plain_spline.rs` (independent truth,
//! written from the definitions).
//!
//! Pinned paths (docs/fast-paths.md lists them with these tests):
//! * curves: the Bézier-span cache (`BezierSpans`, degrees 1–7) and its sorted-batch
//!   cursor (`eval_many`, points-only and derivative loops), the blocked batch of four
//!   parameters in step (`eval_many_lanes`, orders 0–2, AVX2 at run time; blocks in one
//!   span and blocks across a knot), the
//!   batch of blending-spline curves (`curve_batch`), the monomorphised triangular
//!   kernel (`span_kernel::eval_fixed`, W ≤ 8) and its dynamic fallback, uniform-knot span
//!   arithmetic, periodic unrolling, left and right limits, the rational (homogeneous)
//!   paths of NURBS curves, the array paths of `bezier_derivatives` (≤ 8 coefficients,
//!   ≤ 4 outputs) in Bézier and rational Bézier curves;
//! * surfaces: the tensor-product point path (`TensorSpline::eval_partials`), the grid
//!   path (`eval_grid`), the row path of grids with normals (`eval_grid_first`, unrolled
//!   W-term sums for W = 2…6 and the generic loop beyond; for B-spline surfaces
//!   `eval_grid_points_normals`, W = 2…8, AVX2 at run time), NURBS grids, Bézier patches,
//!   the parallel grids (feature `parallel`), and the Bézier grid path of blending-spline
//!   surfaces against their own general evaluation;
//! * degrees 1–12 in each direction, derivative orders 0–4, clamped, unclamped and
//!   periodic knots with repeated interior knots, 1–4 coordinates, rational and not,
//!   parameters sorted, reversed, random, repeated, at knots, at and past the ends.
//!
//! Case counts keep the file to a few seconds in a debug build.

#[path = "common/plain_spline.rs"]
mod plain;

use plain::{Limit, PlainAxis};
use proptest::prelude::*;
use splinekit::Point;
use splinekit::basis::Side;
use splinekit::curve::{BSplineCurve, BezierCurve, Curve, NurbsCurve, RationalBezierCurve};
use splinekit::surface::{BSplineSurface, BezierSurface, NurbsSurface, Surface};

/// splitmix64: coordinates, weights and parameters from one proptest seed (the structure
/// — degrees, counts, knot kinds, orders — comes from proptest, so it shrinks).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.next()
    }
    fn below(&mut self, n: usize) -> usize {
        ((self.next() * n as f64) as usize).min(n - 1)
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum KnotKind {
    Clamped,
    Unclamped,
    Periodic,
    /// Clamped with equal spacing (the O(1) span arithmetic).
    Uniform,
}

fn knot_kind() -> impl Strategy<Value = KnotKind> {
    prop_oneof![Just(KnotKind::Clamped), Just(KnotKind::Unclamped), Just(KnotKind::Periodic), Just(KnotKind::Uniform)]
}

/// Smallest non-zero knot gap the generator makes.
const MIN_GAP: f64 = 0.25;

/// `count` gaps, a quarter of them zero (repeated knots), no run of zeros longer than
/// `max_run`, and the gaps at the indices in `nonzero` non-zero.
fn gaps(rng: &mut Rng, count: usize, max_run: usize, nonzero: &[usize]) -> Vec<f64> {
    let mut run = 0;
    (0..count)
        .map(|i| {
            let zero = rng.next() < 0.25 && run < max_run && !nonzero.contains(&i);
            run = if zero { run + 1 } else { 0 };
            if zero { 0.0 } else { rng.range(MIN_GAP, 2.0) }
        })
        .collect()
}

/// A valid knot vector for n control points of degree p (n ≥ p + 1), with repeated
/// interior knots (multiplicity ≤ p; up to p + 1 in unclamped vectors, ends included).
fn knots(rng: &mut Rng, p: usize, n: usize, kind: KnotKind) -> Vec<f64> {
    let start = rng.range(-2.0, 2.0);
    let cumulative = |gaps: &[f64], len: usize| {
        let mut k = vec![start];
        for i in 0..len - 1 {
            let next = k[i] + gaps[i % gaps.len()];
            k.push(next);
        }
        k
    };
    match kind {
        KnotKind::Clamped => {
            // n − p interior gaps between the clamped ends; first and last non-zero.
            let g = gaps(rng, n - p, p.saturating_sub(1), &[0, n - p - 1]);
            let mut k = vec![start; p + 1];
            for x in g {
                let next = k[k.len() - 1] + x;
                k.push(next);
            }
            let end = k[k.len() - 1];
            k.extend(std::iter::repeat_n(end, p));
            k
        }
        KnotKind::Uniform => {
            let h = rng.range(MIN_GAP, 2.0);
            let mut k = vec![start; p + 1];
            k.extend((1..n - p).map(|i| start + i as f64 * h));
            k.extend(std::iter::repeat_n(start + (n - p) as f64 * h, p + 1));
            k
        }
        KnotKind::Unclamped => {
            // Any multiplicity up to p + 1, also at the ends of the domain [t_p, t_n].
            let mut g = gaps(rng, n + p, p, &[]);
            if g[p..n].iter().all(|&x| x == 0.0) {
                g[p] = 1.0;
            }
            cumulative(&g, n + p + 1)
        }
        KnotKind::Periodic => {
            // One period of n gaps repeated; multiplicity ≤ p, also across the seam.
            let g = gaps(rng, n, p.saturating_sub(1), &[0, n - 1]);
            cumulative(&g, n + p + 1)
        }
    }
}

fn plain_axis(p: usize, k: &[f64], kind: KnotKind) -> PlainAxis {
    if kind == KnotKind::Periodic { PlainAxis::periodic(p, k) } else { PlainAxis::open(p, k) }
}

/// How a batch of parameters is ordered.
#[derive(Debug, Clone, Copy)]
enum Order {
    Sorted,
    Reversed,
    Random,
    Repeated,
}

fn order_kind() -> impl Strategy<Value = Order> {
    prop_oneof![Just(Order::Sorted), Just(Order::Reversed), Just(Order::Random), Just(Order::Repeated)]
}

/// Parameters of a domain: random inside, every knot of the domain, both ends, past both
/// ends, arranged by `order`.
fn parameters(rng: &mut Rng, axis: &PlainAxis, random: usize, order: Order) -> Vec<f64> {
    let (a, b) = axis.domain();
    let mut t: Vec<f64> = (0..random).map(|_| rng.range(a, b)).collect();
    t.extend(axis.knots.iter().copied().filter(|&k| k >= a && k <= b));
    t.extend([a, b, a - 0.5, b + 0.75]);
    arrange(&mut t, order, rng);
    t
}

/// Sorts `t`, then arranges it by `order`: kept sorted, reversed, shuffled (Fisher–Yates
/// with `rng`), or each value three times in a row followed by the sorted values again.
fn arrange(t: &mut Vec<f64>, order: Order, rng: &mut Rng) {
    t.sort_by(f64::total_cmp);
    match order {
        Order::Sorted => {}
        Order::Reversed => t.reverse(),
        Order::Random => {
            for i in (1..t.len()).rev() {
                t.swap(i, rng.below(i + 1));
            }
        }
        Order::Repeated => *t = t.iter().flat_map(|&x| [x, x, x]).chain(t.clone()).collect(),
    }
}

fn coordinates(rng: &mut Rng, dim: usize) -> Vec<f64> {
    (0..dim).map(|_| rng.range(-2.0, 2.0)).collect()
}

fn point<const D: usize>(c: &[f64]) -> Point<D> {
    Point::<D>::from_fn(|i, _| c[i])
}

/// Allowed error of a k-th derivative of degree p: a few hundred ulps of the control
/// points, times the growth of k-th differences (2 (p − j)/h per order, h ≥ MIN_GAP), times
/// the spread of the weights for rational splines.
fn tolerance(p: usize, k: usize, weight_spread: f64) -> f64 {
    let growth: f64 = (0..k.min(p)).map(|j| 2.0 * (p - j) as f64 / MIN_GAP).product();
    2e-13 * 2.0 * growth.max(1.0) * weight_spread.powi(k as i32 + 1) * (p + 1) as f64
}

fn assert_close<const D: usize>(got: &Point<D>, want: &[f64], tol: f64, what: &dyn Fn() -> String) {
    let err = (0..D).map(|c| (got[c] - want[c]).abs()).fold(0.0, f64::max);
    let scale = want.iter().fold(1.0f64, |m, x| m.max(x.abs()));
    assert!(
        err <= tol * scale,
        "{}: got {:?}, want {want:?}, error {err:e} > {:e}",
        what(),
        got.as_slice(),
        tol * scale
    );
}

/// A spline curve case: degree, count, knots, order of derivatives, order of parameters.
#[derive(Debug, Clone)]
struct CurveCase {
    degree: usize,
    extra: usize,
    kind: KnotKind,
    order: usize,
    params: Order,
    dim: usize,
    rational: bool,
    seed: u64,
}

fn curve_case() -> impl Strategy<Value = CurveCase> {
    (1usize..=12, 0usize..=5, knot_kind(), 0usize..=4, order_kind(), 1usize..=4, any::<bool>(), any::<u64>()).prop_map(
        |(degree, extra, kind, order, params, dim, rational, seed)| CurveCase {
            degree,
            extra,
            kind,
            order,
            params,
            dim,
            rational,
            seed,
        },
    )
}

fn check_curve<const D: usize>(case: &CurveCase) {
    let mut rng = Rng(case.seed);
    let (p, k) = (case.degree, case.order);
    let n = p + 1 + case.extra;
    let kn = knots(&mut rng, p, n, case.kind);
    let points: Vec<Vec<f64>> = (0..n).map(|_| coordinates(&mut rng, D)).collect();
    let weights: Vec<f64> = (0..n).map(|_| if case.rational { rng.range(0.5, 2.0) } else { 1.0 }).collect();
    let axis = plain_axis(p, &kn, case.kind);
    let params = parameters(&mut rng, &axis, 7, case.params);
    let pts: Vec<Point<D>> = points.iter().map(|c| point::<D>(c)).collect();
    let periodic = case.kind == KnotKind::Periodic;
    let curve: Box<dyn Curve<D>> = match (case.rational, periodic) {
        (false, false) => Box::new(BSplineCurve::new(p, kn.clone(), pts).unwrap()),
        (false, true) => Box::new(BSplineCurve::new_periodic(p, kn.clone(), pts).unwrap()),
        (true, false) => Box::new(NurbsCurve::new(p, kn.clone(), pts, weights.clone()).unwrap()),
        (true, true) => Box::new(NurbsCurve::new_periodic(p, kn.clone(), pts, weights.clone()).unwrap()),
    };
    let w = case.rational.then_some(&weights[..]);
    let spread = if case.rational { 4.0 } else { 1.0 };
    let truth = |t: f64, side: Limit| plain::curve(&axis, &points, w, t, side, k);
    let mut out = vec![Point::<D>::zeros(); k + 1];
    for &t in &params {
        for (side, limit) in [(Side::Right, Limit::Right), (Side::Left, Limit::Left)] {
            curve.eval_side(t, side, &mut out);
            let want = truth(t, limit);
            for j in 0..=k {
                assert_close(&out[j], &want[j], tolerance(p, j, spread), &|| {
                    format!("{case:?} knots {kn:?}: eval_side({t}, {side:?}) order {j}")
                });
            }
        }
        let want = truth(t, Limit::Right);
        assert_close(&curve.point(t), &want[0], tolerance(p, 0, spread), &|| format!("{case:?}: point({t})"));
        if !case.rational {
            // point(t), the Bernstein sum alone, is the same span's sum as the right limit's
            // first output: the same bits.
            curve.eval_side(t, Side::Right, &mut out);
            assert_eq!(curve.point(t), out[0], "{case:?} knots {kn:?}: point({t}) differs from eval_side");
        }
        assert_close(&curve.derivative(t, k), &want[k], tolerance(p, k, spread), &|| {
            format!("{case:?} knots {kn:?}: derivative({t}, {k})")
        });
    }
    // The sorted-batch cursor (any order of parameters is correct, only slower).
    for order in [0, k] {
        let mut many = vec![Point::<D>::zeros(); params.len() * (order + 1)];
        curve.eval_many(&params, order, &mut many);
        for (i, &t) in params.iter().enumerate() {
            let want = plain::curve(&axis, &points, w, t, Limit::Right, order);
            for j in 0..=order {
                assert_close(&many[i * (order + 1) + j], &want[j], tolerance(p, j, spread), &|| {
                    format!("{case:?} knots {kn:?}: eval_many #{i} ({t}) order {j} of {order}")
                });
            }
        }
    }
    // The blocked batch of B-spline curves (`BezierSpans::eval_many_lanes`: four
    // parameters of one span in step, or of two neighbouring spans evaluated with both,
    // orders 0 … 2, AVX2 where the CPU has it): a dense batch (many parameters per span,
    // so that blocks inside a span and blocks across a knot occur in every order of
    // parameters but the random one) against the truth, and bit for bit against the
    // single evaluation at each parameter.
    let dense = parameters(&mut rng, &axis, 8 * n, case.params);
    for order in 0..=2 {
        let mut many = vec![Point::<D>::zeros(); dense.len() * (order + 1)];
        curve.eval_many(&dense, order, &mut many);
        let mut single = vec![Point::<D>::zeros(); order + 1];
        for (i, &t) in dense.iter().enumerate() {
            let want = plain::curve(&axis, &points, w, t, Limit::Right, order);
            curve.eval_side(t, Side::Right, &mut single);
            for j in 0..=order {
                let got = &many[i * (order + 1) + j];
                assert_close(got, &want[j], tolerance(p, j, spread), &|| {
                    format!("{case:?} knots {kn:?}: dense eval_many #{i} ({t}) order {j} of {order}")
                });
                if !case.rational {
                    assert_eq!(
                        *got, single[j],
                        "{case:?}: dense eval_many #{i} ({t}) order {j} differs from eval_side"
                    );
                }
            }
        }
    }
    // Into memory not yet written (`Curve::eval_many_uninit`, the slot-generic kernel
    // behind Python's arrays; orders past the lanes' zero the slots first): bit for bit
    // `eval_many`, and every slot written.
    for order in 0..=3 {
        let len = dense.len() * (order + 1);
        let mut many = vec![Point::<D>::zeros(); len];
        curve.eval_many(&dense, order, &mut many);
        let mut fresh: Vec<std::mem::MaybeUninit<Point<D>>> = Vec::with_capacity(len);
        // SAFETY: the capacity is `len`; `eval_many_uninit` writes every slot (checked
        // below only after it returned, as the contract promises).
        unsafe { fresh.set_len(len) };
        curve.eval_many_uninit(&dense, order, &mut fresh);
        // SAFETY: every slot written by `eval_many_uninit`.
        let fresh: Vec<Point<D>> = fresh.into_iter().map(|v| unsafe { v.assume_init() }).collect();
        for (i, (a, b)) in fresh.iter().zip(&many).enumerate() {
            assert!(
                a.iter().zip(b.iter()).all(|(x, y)| x.to_bits() == y.to_bits()),
                "{case:?}: eval_many_uninit value {i} of order {order}: {a:?} against eval_many's {b:?}"
            );
        }
    }
    // The triangular kernel behind B-spline curves (the Bézier spans bypassed).
    if !case.rational {
        let c = if periodic {
            BSplineCurve::<D>::new_periodic(p, kn.clone(), points.iter().map(|c| point::<D>(c)).collect())
        } else {
            BSplineCurve::<D>::new(p, kn.clone(), points.iter().map(|c| point::<D>(c)).collect())
        }
        .unwrap();
        for &t in &params {
            c.eval_de_boor(t, Side::Right, &mut out);
            let want = truth(t, Limit::Right);
            for j in 0..=k {
                assert_close(&out[j], &want[j], tolerance(p, j, spread), &|| {
                    format!("{case:?} knots {kn:?}: eval_de_boor({t}) order {j}")
                });
            }
        }
    }
}

/// Bézier and rational Bézier curves of degree 0–12: the array paths of
/// `bezier_derivatives` (≤ 8 coefficients, ≤ 4 outputs) and the buffer path beyond.
fn check_bezier_curve<const D: usize>(degree: usize, outputs: usize, rational: bool, seed: u64) {
    let mut rng = Rng(seed);
    let p = degree;
    let points: Vec<Vec<f64>> = (0..=p).map(|_| coordinates(&mut rng, D)).collect();
    let weights: Vec<f64> = (0..=p).map(|_| rng.range(0.5, 2.0)).collect();
    let mut kn = vec![0.0; p + 1];
    kn.extend(vec![1.0; p + 1]);
    let axis = PlainAxis::open(p, &kn);
    let pts: Vec<Point<D>> = points.iter().map(|c| point::<D>(c)).collect();
    let curve: Box<dyn Curve<D>> = if rational {
        Box::new(RationalBezierCurve::new(pts, weights.clone()).unwrap())
    } else {
        Box::new(BezierCurve::new(pts).unwrap())
    };
    let w = rational.then_some(&weights[..]);
    let spread = if rational { 4.0 } else { 1.0 };
    let mut out = vec![Point::<D>::zeros(); outputs];
    for t in [0.0, 1.0, 0.5, rng.next(), rng.next(), -0.25, 1.5] {
        curve.eval(t, &mut out);
        let want = plain::curve(&axis, &points, w, t, Limit::Right, outputs - 1);
        for j in 0..outputs {
            // The Bernstein form on [0, 1]: k-th differences grow like 2p per order.
            assert_close(&out[j], &want[j], tolerance(p, j, spread) * MIN_GAP.powi(j as i32), &|| {
                format!("Bézier degree {p} rational {rational} at {t}: order {j}")
            });
        }
    }
}

/// A tensor-product surface case.
#[derive(Debug, Clone)]
struct SurfaceCase {
    degrees: (usize, usize),
    extra: (usize, usize),
    kinds: (KnotKind, KnotKind),
    orders: (usize, usize),
    params: Order,
    dim: usize,
    rational: bool,
    seed: u64,
}

fn surface_case() -> impl Strategy<Value = SurfaceCase> {
    (
        (1usize..=12, 1usize..=12),
        (0usize..=3, 0usize..=3),
        (knot_kind(), knot_kind()),
        (0usize..=4, 0usize..=4),
        order_kind(),
        1usize..=4,
        any::<bool>(),
        any::<u64>(),
    )
        .prop_map(|(degrees, extra, kinds, orders, params, dim, rational, seed)| SurfaceCase {
            degrees,
            extra,
            kinds,
            orders,
            params,
            dim,
            rational,
            seed,
        })
}

fn check_surface<const D: usize>(case: &SurfaceCase) {
    let mut rng = Rng(case.seed);
    let ((p, q), (du, dv)) = (case.degrees, case.orders);
    let (nu, nv) = (p + 1 + case.extra.0, q + 1 + case.extra.1);
    let (ku, kv) = (knots(&mut rng, p, nu, case.kinds.0), knots(&mut rng, q, nv, case.kinds.1));
    let net: Vec<Vec<Vec<f64>>> = (0..nu).map(|_| (0..nv).map(|_| coordinates(&mut rng, D)).collect()).collect();
    let weights: Vec<Vec<f64>> =
        (0..nu).map(|_| (0..nv).map(|_| if case.rational { rng.range(0.5, 2.0) } else { 1.0 }).collect()).collect();
    let (au, av) = (plain_axis(p, &ku, case.kinds.0), plain_axis(q, &kv, case.kinds.1));
    let periodic = (case.kinds.0 == KnotKind::Periodic, case.kinds.1 == KnotKind::Periodic);
    let pnet: Vec<Vec<Point<D>>> = net.iter().map(|r| r.iter().map(|c| point::<D>(c)).collect()).collect();
    let surface: Box<dyn Surface<D>> = if case.rational {
        Box::new(NurbsSurface::new((p, q), ku.clone(), kv.clone(), pnet, weights.clone(), periodic).unwrap())
    } else {
        Box::new(BSplineSurface::new((p, q), ku.clone(), kv.clone(), pnet, periodic).unwrap())
    };
    let w = case.rational.then_some(&weights[..]);
    let spread = if case.rational { 4.0 } else { 1.0 };
    let tol = |i: usize, j: usize| tolerance(p, i, spread) * tolerance(q, j, spread) / tolerance(0, 0, 1.0);
    let truth = |u: f64, v: f64, du: usize, dv: usize| plain::surface(&au, &av, &net, w, u, v, du, dv);
    let what = |s: &str| format!("{case:?} knots {ku:?} × {kv:?}: {s}");
    check_surface_paths(&*surface, &mut rng, (&au, &av), case.params, (du, dv), &truth, &tol, &what);
}

/// Every evaluation path of one surface against `truth`: paired points, the grid, the
/// grid with normals, `normal`, and the parallel grids.
#[allow(clippy::too_many_arguments)]
fn check_surface_paths<const D: usize>(
    surface: &dyn Surface<D>,
    rng: &mut Rng,
    (au, av): (&PlainAxis, &PlainAxis),
    order: Order,
    (du, dv): (usize, usize),
    truth: &dyn Fn(f64, f64, usize, usize) -> Vec<Vec<f64>>,
    tol: &dyn Fn(usize, usize) -> f64,
    what: &dyn Fn(&str) -> String,
) {
    let w = (du + 1) * (dv + 1);
    // Paired parameters (u_i, v_i).
    let us = parameters(rng, au, 2, order);
    let vs = parameters(rng, av, 2, order);
    let mut out = vec![Point::<D>::zeros(); w];
    for (&u, &v) in us.iter().zip(vs.iter().rev()) {
        surface.eval_partials(u, v, du, dv, &mut out);
        let want = truth(u, v, du, dv);
        for i in 0..=du {
            for j in 0..=dv {
                let k = i * (dv + 1) + j;
                assert_close(&out[k], &want[k], tol(i, j), &|| what(&format!("eval_partials({u}, {v}) ({i}, {j})")));
            }
        }
        let n = surface.normal(u, v);
        check_normal(n, &want_partials_first(truth, u, v), &|| what(&format!("normal({u}, {v})")));
    }
    // A grid: a few of those parameters each way.
    let gu: Vec<f64> = us.iter().copied().step_by(3).take(5).collect();
    let gv: Vec<f64> = vs.iter().copied().step_by(2).take(6).collect();
    let mut grid = vec![Point::<D>::zeros(); gu.len() * gv.len() * w];
    surface.eval_grid(&gu, &gv, du, dv, &mut grid);
    let (mut points, mut normals) =
        (vec![Point::<D>::zeros(); gu.len() * gv.len()], vec![Point::<D>::zeros(); gu.len() * gv.len()]);
    surface.eval_grid_with_normals(&gu, &gv, &mut points, &mut normals);
    for (a, &u) in gu.iter().enumerate() {
        for (b, &v) in gv.iter().enumerate() {
            let g = a * gv.len() + b;
            let want = truth(u, v, du, dv);
            for i in 0..=du {
                for j in 0..=dv {
                    let k = i * (dv + 1) + j;
                    assert_close(&grid[g * w + k], &want[k], tol(i, j), &|| {
                        what(&format!("eval_grid at ({u}, {v}) ({i}, {j})"))
                    });
                }
            }
            let first = want_partials_first(truth, u, v);
            assert_close(&points[g], &first[0], tol(0, 0), &|| {
                what(&format!("eval_grid_with_normals point ({u}, {v})"))
            });
            let n = (normals[g] != Point::<D>::zeros()).then_some(normals[g]);
            check_normal(n, &first, &|| what(&format!("eval_grid_with_normals normal ({u}, {v})")));
        }
    }
    #[cfg(feature = "parallel")]
    {
        let mut par = vec![Point::<D>::zeros(); grid.len()];
        splinekit::surface::parallel::eval_grid(surface, &gu, &gv, du, dv, &mut par);
        assert_eq!(par, grid, "{}", what("parallel eval_grid"));
        let (mut pp, mut pn) = (vec![Point::<D>::zeros(); points.len()], vec![Point::<D>::zeros(); points.len()]);
        splinekit::surface::parallel::eval_grid_with_normals(surface, &gu, &gv, &mut pp, &mut pn);
        assert_eq!((pp, pn), (points, normals), "{}", what("parallel eval_grid_with_normals"));
    }
}

/// S, S_u, S_v from the truth.
fn want_partials_first(truth: &dyn Fn(f64, f64, usize, usize) -> Vec<Vec<f64>>, u: f64, v: f64) -> [Vec<f64>; 3] {
    let t = truth(u, v, 1, 1);
    [t[0].clone(), t[2].clone(), t[1].clone()]
}

/// The unit normal S_u × S_v / |S_u × S_v| in ℝ³ where the surface is clearly regular (the
/// sine of the angle between the partials above 10⁻⁴); no normal outside ℝ³.
fn check_normal<const D: usize>(got: Option<Point<D>>, first: &[Vec<f64>; 3], what: &dyn Fn() -> String) {
    if D != 3 {
        assert!(got.is_none(), "{}: a normal outside ℝ³", what());
        return;
    }
    let (a, b) = (&first[1], &first[2]);
    let n = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    let len = n.iter().map(|x| x * x).sum::<f64>().sqrt();
    let (la, lb) = (a.iter().map(|x| x * x).sum::<f64>().sqrt(), b.iter().map(|x| x * x).sum::<f64>().sqrt());
    if len <= 1e-4 * la * lb || len.is_nan() {
        return;
    }
    let got = got.unwrap_or_else(|| panic!("{}: no normal at a regular point", what()));
    let want: Vec<f64> = n.iter().map(|x| x / len).collect();
    // The normal's error is the partials' relative error over the sine of their angle.
    assert_close(&got, &want, 1e-7 * la * lb / len, what);
}

fn check_bezier_surface<const D: usize>(degrees: (usize, usize), orders: (usize, usize), seed: u64) {
    let mut rng = Rng(seed);
    let (p, q) = degrees;
    let net: Vec<Vec<Vec<f64>>> = (0..=p).map(|_| (0..=q).map(|_| coordinates(&mut rng, D)).collect()).collect();
    let bez = |p: usize| {
        let mut k = vec![0.0; p + 1];
        k.extend(vec![1.0; p + 1]);
        PlainAxis::open(p, &k)
    };
    let (au, av) = (bez(p), bez(q));
    let pnet: Vec<Vec<Point<D>>> = net.iter().map(|r| r.iter().map(|c| point::<D>(c)).collect()).collect();
    let surface = BezierSurface::new(pnet).unwrap();
    let truth = |u: f64, v: f64, du: usize, dv: usize| plain::surface(&au, &av, &net, None, u, v, du, dv);
    let tol = |i: usize, j: usize| {
        tolerance(p, i, 1.0) * tolerance(q, j, 1.0) / tolerance(0, 0, 1.0) * MIN_GAP.powi((i + j) as i32)
    };
    let what = |s: &str| format!("Bézier surface {degrees:?}: {s}");
    check_surface_paths(&surface, &mut rng, (&au, &av), Order::Random, orders, &truth, &tol, &what);
}

/// Proptest's settings: `base` cases, times `FAST_PATHS_SCALE` when set (a deeper local
/// hunt: `FAST_PATHS_SCALE=100 cargo test --release -p splinekit --test fast_paths`), and
/// no failure files.
fn config(base: u32) -> ProptestConfig {
    let cases = base * std::env::var("FAST_PATHS_SCALE").ok().and_then(|s| s.parse().ok()).unwrap_or(1);
    ProptestConfig { cases, failure_persistence: None, ..ProptestConfig::default() }
}

macro_rules! by_dimension {
    ($dim:expr, $f:ident, $($arg:expr),*) => {
        match $dim {
            1 => $f::<1>($($arg),*),
            2 => $f::<2>($($arg),*),
            3 => $f::<3>($($arg),*),
            _ => $f::<4>($($arg),*),
        }
    };
}

/// Cases the property tests found. Knots repeated at the end of an unclamped domain leave
/// the last span empty: the blocked batch once moved into it at the domain's end and
/// returned zeros (the end belongs to the last span that is not empty).
#[test]
fn found_cases_of_spline_curves() {
    for (degree, extra, order, params, dim, seed) in
        [(1, 5, 2, Order::Repeated, 3, 13262486668611229537), (6, 1, 1, Order::Random, 4, 6365972896449921215)]
    {
        let case = CurveCase { degree, extra, kind: KnotKind::Unclamped, order, params, dim, rational: false, seed };
        by_dimension!(dim, check_curve, &case);
    }
}

proptest! {
    #![proptest_config(config(64))]

    /// B-spline and NURBS curves, every path, against plain Cox–de Boor.
    #[test]
    fn spline_curves_match_plain_cox_de_boor(case in curve_case()) {
        by_dimension!(case.dim, check_curve, &case);
    }

    /// Bézier and rational Bézier curves, 1 to 5 outputs (array and buffer paths).
    #[test]
    fn bezier_curves_match_plain_bernstein(degree in 0usize..=12, outputs in 1usize..=5, dim in 1usize..=4, rational: bool, seed: u64) {
        by_dimension!(dim, check_bezier_curve, degree, outputs, rational, seed);
    }
}

proptest! {
    #![proptest_config(config(40))]

    /// B-spline and NURBS surfaces: points, partials, grids, grids with normals, normals.
    #[test]
    fn spline_surfaces_match_plain_cox_de_boor(case in surface_case()) {
        by_dimension!(case.dim, check_surface, &case);
    }

    /// Bézier surfaces of degrees 1–12 each way.
    #[test]
    fn bezier_surfaces_match_plain_bernstein(p in 1usize..=12, q in 1usize..=12, du in 0usize..=4, dv in 0usize..=4, dim in 1usize..=4, seed: u64) {
        by_dimension!(dim, check_bezier_surface, (p, q), (du, dv), seed);
    }
}

/// The row path of grids with normals at every unrolled width W = 2 … 6 and past it, in
/// each direction, with clamped, unclamped and periodic knots: the edge of issue 20 (a
/// degree-4 or 5 surface in v overran an 8-value scratch array) and its neighbours, all
/// deterministic so that the failure before the fix needs no luck.
#[test]
fn grid_normals_every_width_in_each_direction() {
    for p in [1, 4, 8] {
        for q in 1..=8 {
            for kinds in [
                (KnotKind::Clamped, KnotKind::Unclamped),
                (KnotKind::Periodic, KnotKind::Clamped),
                (KnotKind::Uniform, KnotKind::Periodic),
            ] {
                let case = SurfaceCase {
                    degrees: (p, q),
                    extra: (1, 2),
                    kinds,
                    orders: (1, 1),
                    params: Order::Sorted,
                    dim: 3,
                    rational: (p + q) % 2 == 0,
                    seed: (p * 31 + q) as u64,
                };
                check_surface::<3>(&case);
            }
        }
    }
}

/// Blending-spline surfaces: the Bézier grid path (`eval_grid_with_normals`: Bernstein
/// bases once per row and column, nets contracted once per column) against the surface's
/// general evaluation at each point (patches evaluated, then blended by the Leibniz rule),
/// open and closed, patch degrees 1–5 each way.
fn check_blending_grid(
    model: usize,
    counts: (usize, usize),
    degrees: (usize, usize),
    closed: (bool, bool),
    order: Order,
    seed: u64,
) {
    use splinekit::basis::BFunction;
    use splinekit::blend::{BlendingSplineSurface, BlendingSurfaceOptions, PatchKind};
    use splinekit::surface::model::{Plane, Sphere, Torus};
    use std::sync::Arc;
    let model: Arc<dyn Surface<3>> = match model {
        0 => Arc::new(Torus::new(3.0, 1.0).unwrap()),
        1 => Arc::new(Sphere::new(1.5).unwrap()),
        _ => Arc::new(
            Plane::new(Point::<3>::zeros(), Point::<3>::new(2.0, 0.0, 0.5), Point::<3>::new(0.0, 1.0, 0.0)).unwrap(),
        ),
    };
    let options = BlendingSurfaceOptions {
        local: PatchKind::Bezier(degrees.0, degrees.1),
        bfunction: BFunction::erbs_default(),
        closed_u: Some(closed.0),
        closed_v: Some(closed.1),
    };
    let s = BlendingSplineSurface::from_model(model, counts, &options).unwrap();
    let mut rng = Rng(seed);
    let axis = |d: splinekit::Interval| PlainAxis::open(1, &[d.start, d.end]);
    let us = parameters(&mut rng, &axis(s.domain_u()), 4, order);
    let vs = parameters(&mut rng, &axis(s.domain_v()), 3, order);
    let (mut points, mut normals) =
        (vec![Point::<3>::zeros(); us.len() * vs.len()], vec![Point::<3>::zeros(); us.len() * vs.len()]);
    s.eval_grid_with_normals(&us, &vs, &mut points, &mut normals);
    let mut out = [Point::<3>::zeros(); 4];
    for (a, &u) in us.iter().enumerate() {
        for (b, &v) in vs.iter().enumerate() {
            let k = a * vs.len() + b;
            s.eval_partials(u, v, 1, 1, &mut out);
            let c = |p: &Point<3>| vec![p[0], p[1], p[2]];
            let what = || format!("blending grid {counts:?} {degrees:?} closed {closed:?} at ({u}, {v})");
            assert_close(&points[k], &c(&out[0]), 1e-12, &what);
            let n = (normals[k] != Point::<3>::zeros()).then_some(normals[k]);
            check_normal(n, &[c(&out[0]), c(&out[2]), c(&out[1])], &what);
        }
    }
}

proptest! {
    #![proptest_config(config(6))]

    #[test]
    fn blending_surface_grids_match_their_general_evaluation(
        model in 0usize..3, nu in 3usize..=5, nv in 3usize..=5, du in 1usize..=5, dv in 1usize..=5,
        closed: (bool, bool), order in order_kind(), seed: u64,
    ) {
        check_blending_grid(model, (nu, nv), (du, dv), closed, order, seed);
    }
}

/// Blending-spline curves: the batch path (`BlendingSplineCurve::eval_many`: Bézier locals
/// of one degree ≤ 7, orders ≤ 4, each interval's locals prepared once per run of
/// parameters, Bernstein sums of scaled differences) against the curve's general
/// evaluation at each parameter (`eval_side`: de Casteljau on each local, then the Leibniz
/// blend), open and closed, local degrees 1–8 (8: the general path), orders 0–5 (5: the
/// general path), edited splines (a moved frame, edited control points, an inserted local)
/// and explicit non-Bézier locals, with several B-functions.
#[allow(clippy::too_many_arguments)]
fn check_blending_curve(
    model: usize,
    count: usize,
    degree: usize,
    order: usize,
    closed: bool,
    edit: usize,
    bfunction: usize,
    params: Order,
    seed: u64,
) {
    use splinekit::basis::BFunction;
    use splinekit::blend::{BlendingCurveOptions, BlendingSplineCurve, LocalKind};
    use splinekit::curve::model::{Heart, Helix, Lissajous};
    use splinekit::frame::Affine;
    use std::sync::Arc;
    let model: Arc<dyn Curve<3>> = match model {
        0 => Arc::new(Helix::new(1.0, 0.7, 2.0).unwrap()),
        1 => Arc::new(Heart::new(1.5).unwrap()),
        _ => Arc::new(Lissajous::new([1.0, 2.0, 0.5], [3.0, 2.0, 1.0], 0.3).unwrap()),
    };
    let bfunction = match bfunction {
        0 => BFunction::erbs_default(),
        1 => BFunction::polynomial(2).unwrap(),
        2 => BFunction::Trigonometric,
        _ => BFunction::Linear,
    };
    let options = BlendingCurveOptions {
        local: LocalKind::Bezier(degree),
        bfunction,
        closed: Some(closed),
        ..Default::default()
    };
    let mut rng = Rng(seed);
    let mut c = BlendingSplineCurve::from_model(model.clone(), count, &options).unwrap();
    match edit {
        0 => {}
        1 => {
            let k = rng.below(count);
            let frame = Affine::translation(Point::<3>::new(0.3, -0.2, 0.5)).after(&Affine::uniform_scale(1.3));
            c.set_transform(k, frame);
        }
        2 => {
            let k = rng.below(count);
            let mut p = c.local_bezier_points(k).unwrap().to_vec();
            for q in &mut p {
                *q += Point::<3>::new(rng.range(-0.5, 0.5), rng.range(-0.5, 0.5), rng.range(-0.5, 0.5));
            }
            c.set_local_bezier_points(k, p).unwrap();
        }
        3 => {
            let d = c.domain();
            c.insert_local(d.start + 0.37 * d.length()).unwrap();
        }
        _ => {
            // Explicit locals: the model itself on every support (no Bézier locals).
            let knots = c.knots().clone();
            let locals = (0..knots.count()).map(|_| model.clone()).collect();
            c = BlendingSplineCurve::from_locals(knots, locals, options.bfunction.clone()).unwrap();
        }
    }
    let d = c.domain();
    let mut t: Vec<f64> = (0..40).map(|_| rng.range(d.start, d.end)).collect();
    t.extend(c.knots().values());
    t.extend([d.start, d.end, d.start - 0.3 * d.length(), d.end + 0.6 * d.length()]);
    arrange(&mut t, params, &mut rng);
    let w = order + 1;
    let mut batch = vec![Point::<3>::zeros(); t.len() * w];
    c.eval_many(&t, order, &mut batch);
    let mut reference = vec![Point::<3>::zeros(); t.len() * w];
    for (&x, o) in t.iter().zip(reference.chunks_exact_mut(w)) {
        c.eval_side(x, Side::Right, o);
    }
    // Both paths round the locals' control points P to a few ulps (the batch restricts
    // each local to the interval, the general path runs de Casteljau on the whole local);
    // a j-th derivative multiplies such errors by the growth of j-th differences,
    // Π_{i<j} 2(d + 4 − i)/h on the narrowest interval h (d + 4 bounds the local's
    // degree and the B-function's share of the Leibniz sum).
    let points = (0..c.local_count())
        .filter_map(|k| c.local_bezier_world_points(k))
        .flatten()
        .map(|p| p.amax())
        .fold(1.0, f64::max);
    let h = c.knots().values().windows(2).map(|k| k[1] - k[0]).filter(|&g| g > 0.0).fold(f64::INFINITY, f64::min);
    let growth = |j: usize| (0..j).map(|i| 2.0 * (degree + 4 - i) as f64 / h).product::<f64>();
    let scale: Vec<f64> =
        (0..w).map(|j| reference.iter().skip(j).step_by(w).map(|p| p.amax()).fold(1.0, f64::max)).collect();
    let tol: Vec<f64> = (0..w).map(|j| 1e-12 * scale[j] + 64.0 * f64::EPSILON * points * growth(j)).collect();
    for (i, &x) in t.iter().enumerate() {
        for j in 0..w {
            let (got, want) = (batch[i * w + j], reference[i * w + j]);
            assert!(
                (got - want).amax() <= tol[j],
                "blending curve {count} locals of degree {degree}, closed {closed}, edit {edit}: order {j} at {x}: \
                 {got:?} vs {want:?} (tolerance {:e})",
                tol[j]
            );
        }
    }
}

proptest! {
    #![proptest_config(config(48))]

    #[test]
    fn blending_curve_batches_match_their_general_evaluation(
        model in 0usize..3, count in 3usize..=12, degree in 1usize..=8, order in 0usize..=5, closed: bool,
        edit in 0usize..5, bfunction in 0usize..4, params in order_kind(), seed: u64,
    ) {
        check_blending_curve(model, count, degree, order, closed, edit, bfunction, params, seed);
    }
}
