//! Inserting local curves into blending-spline curves and knot lines (rows of local
//! patches) into blending-spline surfaces: what the method promises (nothing moves outside
//! the split interval or strip; at the old knots and the new one the derivatives are kept;
//! inside, the change is within the pointwise bound |ℓ* − c| + |c − ℓ_neighbour|), checked
//! against the spline before the insertion, with edited and moved neighbours.

use splinekit::basis::Side;
use splinekit::blend::hermite::{IntervalBezier, rebased, rebased_points};
use splinekit::blend::{
    BlendingCurveOptions, BlendingSplineCurve, BlendingSplineSurface, BlendingSurfaceOptions, LocalKind, PatchKind,
};
use splinekit::curve::model::Heart;
use splinekit::curve::{BezierCurve, Curve, Reparametrized};
use splinekit::frame::Affine;
use splinekit::surface::model::Torus;
use splinekit::surface::{Direction, Surface, SurfaceGridSamples};
use splinekit::{Interval, Point};
use std::sync::Arc;

fn heart_spline(local: LocalKind) -> BlendingSplineCurve<3> {
    let heart: Arc<dyn Curve<3>> = Arc::new(Heart::new(1.0).unwrap());
    let options = BlendingCurveOptions { local, closed: Some(true), ..Default::default() };
    BlendingSplineCurve::from_model(heart, 10, &options).unwrap()
}

/// The heart's spline with local 3's control points pulled and local 4 turned and moved:
/// the two neighbours of the interval [c₃, c₄] are edited.
fn edited_heart(d: usize) -> BlendingSplineCurve<3> {
    let mut c = heart_spline(LocalKind::Bezier(d));
    let mut p = c.local_bezier_points(3).unwrap().to_vec();
    p[1] += Point::<3>::new(0.8, -0.5, 0.3);
    c.set_local_bezier_points(3, p).unwrap();
    let turn = Affine::rotation(Point::<3>::new(0.0, 0.0, 1.0), 0.2).unwrap();
    c.set_transform(4, Affine::translation(Point::<3>::new(0.4, 0.2, 0.0)).after(&turn));
    c
}

fn derivatives(c: &BlendingSplineCurve<3>, t: f64, n: usize, side: Side) -> Vec<Point<3>> {
    let mut out = vec![Point::<3>::zeros(); n + 1];
    c.eval_side(t, side, &mut out);
    out
}

/// The Bernstein sum Σ C(d, i) s^i (1 − s)^{d−i} P_i at any s (no clamping): the
/// polynomial of a Bézier's points, extended past [0, 1].
fn bernstein_sum(points: &[Point<3>], s: f64) -> Point<3> {
    let d = points.len() - 1;
    let mut binomial = 1.0;
    let mut sum = Point::<3>::zeros();
    for (i, p) in points.iter().enumerate() {
        sum += p * (binomial * s.powi(i as i32) * (1.0 - s).powi((d - i) as i32));
        binomial = binomial * (d - i) as f64 / (i + 1) as f64;
    }
    sum
}

#[test]
fn rebasing_a_bezier_keeps_its_polynomial() {
    let points: Vec<Point<3>> = (0..5)
        .map(|i| {
            let x = i as f64;
            Point::<3>::new(x.sin() * 3.0, (1.7 * x).cos(), x * x - 2.0)
        })
        .collect();
    let from = Interval::new(0.3, 1.1);
    let piece: IntervalBezier<3> = Reparametrized::new(BezierCurve::new(points.clone()).unwrap(), from).unwrap();
    for to in [Interval::new(-0.5, 2.0), Interval::new(0.5, 0.7), Interval::new(1.2, 4.0)] {
        let moved = rebased(&piece, to).unwrap();
        assert_eq!(moved.domain(), to);
        for i in 0..=20 {
            let t = to.lerp(i as f64 / 20.0);
            let want = bernstein_sum(&points, (t - from.start) / from.length());
            let got = moved.point(t);
            assert!((got - want).norm() < 1e-11 * want.norm().max(1.0), "{got} vs {want} at {t} on {to:?}");
        }
    }
    // On its own interval the points are the same.
    let same = rebased_points(&points, from, from);
    for (a, b) in points.iter().zip(&same) {
        assert!((a - b).norm() < 1e-14 * a.norm().max(1.0));
    }
}

#[test]
fn an_inserted_local_curve_keeps_the_curve_within_the_promised_bound() {
    for (d, edited) in [(2, false), (3, false), (5, false), (2, true), (3, true), (5, true)] {
        let mut c = if edited { edited_heart(d) } else { heart_spline(LocalKind::Bezier(d)) };
        let before = c.clone();
        let (lo, hi) = (c.centre(3), c.centre(4));
        let t_new = lo + 0.37 * (hi - lo);
        let k = c.insert_local(t_new).unwrap();
        assert_eq!((k, c.local_count(), c.centre(k)), (4, 11, t_new));
        assert_eq!(c.local_bezier_points(k).unwrap().len(), d + 1, "a Bézier local of the neighbours' degree");
        let mut worst: f64 = 0.0;
        for i in 0..=3000 {
            let t = c.domain().lerp(i as f64 / 3000.0);
            let (now, was) = (c.point(t), before.point(t));
            let change = (now - was).norm();
            if t <= lo || t >= hi {
                assert!(change < 1e-12, "degree {d}: t = {t} outside [{lo}, {hi}] moved by {change}");
                continue;
            }
            let neighbour = if t <= t_new { k - 1 } else { k + 1 };
            let (mut new_local, mut side) = ([Point::<3>::zeros()], [Point::<3>::zeros()]);
            c.eval_local(k, t, &mut new_local);
            c.eval_local(neighbour, t, &mut side);
            let bound = (new_local[0] - was).norm() + (was - side[0]).norm();
            assert!(change <= bound + 1e-12, "degree {d}: at {t} the change {change} exceeds the bound {bound}");
            worst = worst.max(change);
        }
        // The heart is about 33 across. Fitted to it, the locals are close to the curve
        // and the change stays under 1 % of its size; with edited neighbours it is as
        // large as their distance from the curve (the bound's second term).
        eprintln!("degree {d}, edited {edited}: largest change {worst:.3e}");
        assert!(worst > 0.0 && (edited || worst < 0.33), "degree {d}: {worst}");
        for (t, orders, tol) in [(lo, d, 1e-9), (t_new, d, 1e-8), (hi, d, 1e-9)] {
            for side in [Side::Left, Side::Right] {
                let (a, b) = (derivatives(&c, t, orders, side), derivatives(&before, t, orders, side));
                for j in 0..=orders {
                    let err = (a[j] - b[j]).norm();
                    assert!(err < tol * b[j].norm().max(1.0), "degree {d}: order {j} at {t}: {err}");
                }
            }
        }
    }
}

#[test]
fn inserting_in_the_seam_interval_of_a_closed_curve_rebases_local_zero() {
    let mut c = edited_heart(3);
    let mut p = c.local_bezier_points(0).unwrap().to_vec();
    p[2] += Point::<3>::new(-0.6, 0.4, 0.0);
    c.set_local_bezier_points(0, p).unwrap();
    let before = c.clone();
    let (lo, hi) = (c.centre(9), c.domain().end);
    let t_new = lo + 0.5 * (hi - lo);
    assert_eq!(c.insert_local(t_new).unwrap(), 10);
    assert_eq!(c.knots().values().len(), 12);
    for i in 0..=1000 {
        let t = c.domain().lerp(i as f64 / 1000.0);
        if t <= lo {
            assert!((c.point(t) - before.point(t)).norm() < 1e-12, "t = {t} moved");
        }
    }
    let (a, b) = (derivatives(&c, t_new, 3, Side::Right), derivatives(&before, t_new, 3, Side::Right));
    for j in 0..=3 {
        assert!((a[j] - b[j]).norm() < 1e-8 * b[j].norm().max(1.0), "order {j} at the new knot");
    }
}

#[test]
fn sub_curve_locals_of_an_unmoved_spline_do_not_change_at_all() {
    let mut c = heart_spline(LocalKind::SubCurve);
    let before = c.clone();
    c.insert_local(1.234).unwrap();
    for i in 0..=500 {
        let t = c.domain().lerp(i as f64 / 500.0);
        assert!((c.point(t) - before.point(t)).norm() < 1e-14);
    }
}

#[test]
fn bad_insertion_parameters_are_refused_with_the_field_and_numbers() {
    let mut c = heart_spline(LocalKind::Bezier(3));
    let knot = c.centre(2);
    for t in [knot, -1.0, 100.0, f64::NAN] {
        let e = c.insert_local(t).unwrap_err().to_string();
        assert!(e.starts_with("t: ") && e.contains("strictly inside the domain [0, 6.28"), "{e}");
    }
    let mut s = torus_spline(PatchKind::Bezier(3, 3));
    let e = s.insert_knot_line(Direction::U, 7.0).unwrap_err().to_string();
    assert!(e.starts_with("u: "), "{e}");
    assert!(e.contains("got 7"), "{e}");
    let v = s.knots().1.centre(1);
    let e = s.insert_knot_line(Direction::V, v).unwrap_err().to_string();
    assert!(e.starts_with("v: ") && e.contains("not on a knot"), "{e}");
    assert_eq!(s.local_count(), (8, 6), "a refused insertion changes nothing");
}

fn torus_spline(kind: PatchKind) -> BlendingSplineSurface<3> {
    let torus: Arc<dyn Surface<3>> = Arc::new(Torus::new(3.0, 1.0).unwrap());
    let options = BlendingSurfaceOptions { local: kind, ..Default::default() };
    BlendingSplineSurface::from_model(torus, (8, 6), &options).unwrap()
}

/// The torus's 8 × 6 bicubic surface with patch (2, 1)'s net pulled and patch (3, 2)
/// scaled: both next to the strip between u-knots 2 and 3 (and v-knots 1 and 2).
fn edited_torus() -> BlendingSplineSurface<3> {
    let mut s = torus_spline(PatchKind::Bezier(3, 3));
    let (net, _) = s.bezier_rest_net(2, 1).unwrap();
    let mut net = net.to_vec();
    net[5] += Point::<3>::new(0.0, 0.0, 0.7);
    net[10] += Point::<3>::new(0.3, -0.2, 0.0);
    s.set_bezier_net(2, 1, net).unwrap();
    s.set_transform(3, 2, Affine::uniform_scale(1.3));
    s
}

/// B(w) and 1 − B(w) of the surface's B-function.
fn weights(s: &BlendingSplineSurface<3>, w: f64) -> [f64; 2] {
    let mut b = [0.0];
    s.bfunction().eval(w, &mut b);
    [1.0 - b[0], b[0]]
}

/// The bound of the module documentation at (x, y) for a line inserted across
/// `direction`: per active row b of the other direction (weight γ_b), the new row's and
/// the neighbouring row's distance from the old row blend C_b.
fn surface_bound(s: &BlendingSplineSurface<3>, direction: Direction, k: usize, t_new: f64, (u, v): (f64, f64)) -> f64 {
    let along_u = direction == Direction::U;
    let (knots, others) = if along_u { (s.knots().0, s.knots().1) } else { (s.knots().1, s.knots().0) };
    let (x, y) = if along_u { (u, v) } else { (v, u) };
    let other = others.locate(y, Side::Right);
    let gamma = weights(s, other.w);
    let (left, right) = (knots.centre(k - 1), knots.centre(k + 1));
    let beta = weights(s, (x - left) / (right - left));
    let neighbour = if x <= t_new { k - 1 } else { k + 1 };
    let local = |a: usize, b: usize, y: f64| {
        let mut out = [Point::<3>::zeros()];
        let (pair, at) = if along_u { ((a, b), (x, y)) } else { ((b, a), (y, x)) };
        s.eval_local(pair, at, 0, 0, &mut out);
        out[0]
    };
    [(other.first, other.t), (other.second, other.t + other.second_shift)]
        .into_iter()
        .zip(gamma)
        .map(|((b, y), g)| {
            let row = beta[0] * local(k - 1, b, y) + beta[1] * local(k + 1, b, y);
            g * ((local(k, b, y) - row).norm() + (row - local(neighbour, b, y)).norm())
        })
        .sum()
}

#[test]
fn an_inserted_knot_line_keeps_the_surface_within_the_promised_bound() {
    for direction in [Direction::U, Direction::V] {
        let mut s = edited_torus();
        let before = s.clone();
        let along_u = direction == Direction::U;
        let (knots, counts) = if along_u { (s.knots().0.clone(), (9, 6)) } else { (s.knots().1.clone(), (8, 7)) };
        let (lo, hi) = (knots.centre(if along_u { 2 } else { 1 }), knots.centre(if along_u { 3 } else { 2 }));
        let t_new = lo + 0.6 * (hi - lo);
        let k = s.insert_knot_line(direction, t_new).unwrap();
        assert_eq!(s.local_count(), counts);
        let new_knots = if along_u { s.knots().0 } else { s.knots().1 };
        assert_eq!(new_knots.centre(k), t_new);
        assert_eq!(new_knots.values().len(), knots.values().len() + 1);
        let (du, dv) = (s.domain_u(), s.domain_v());
        let mut worst: f64 = 0.0;
        for i in 0..=80 {
            for j in 0..=80 {
                let (u, v) = (du.lerp(i as f64 / 80.0), dv.lerp(j as f64 / 80.0));
                let change = (s.point(u, v) - before.point(u, v)).norm();
                let x = if along_u { u } else { v };
                if x <= lo || x >= hi {
                    assert!(change < 1e-12, "{direction:?}: ({u}, {v}) outside the strip moved by {change}");
                    continue;
                }
                let bound = surface_bound(&s, direction, k, t_new, (u, v));
                assert!(change <= bound + 1e-12, "{direction:?}: at ({u}, {v}) {change} exceeds the bound {bound}");
                worst = worst.max(change);
            }
        }
        eprintln!("{direction:?}: largest change {worst:.3e}");
        assert!(worst > 0.0 && worst < 0.05, "{direction:?}: {worst}");
        // The renderer's grid path (Bernstein bases from the knots' supports) agrees with
        // pointwise evaluation: the rebased neighbours live on their new supports.
        let g = SurfaceGridSamples::uniform(&s, 41, 33).unwrap();
        for (a, &u) in g.us().iter().enumerate() {
            for (b, &v) in g.vs().iter().enumerate() {
                let p = g.points()[a * 33 + b];
                assert!((p - s.point(u, v)).norm() < 1e-12, "{direction:?}: the grid path at ({u}, {v})");
            }
        }
        // At every knot pair on the new line the partials up to (3, 3) are kept.
        let others = if along_u { s.knots().1.clone() } else { s.knots().0.clone() };
        for l in 0..others.count() {
            let (u, v) = if along_u { (t_new, others.centre(l)) } else { (others.centre(l), t_new) };
            let (mut a, mut b) = ([Point::<3>::zeros(); 16], [Point::<3>::zeros(); 16]);
            s.eval_partials(u, v, 3, 3, &mut a);
            before.eval_partials(u, v, 3, 3, &mut b);
            for (i, (p, q)) in a.iter().zip(&b).enumerate() {
                assert!((p - q).norm() < 1e-8 * q.norm().max(1.0), "{direction:?}: partial {i} at ({u}, {v})");
            }
        }
    }
}

#[test]
fn sub_surface_patches_of_an_unmoved_surface_do_not_change() {
    let mut s = torus_spline(PatchKind::SubSurface);
    let before = s.clone();
    s.insert_knot_line(Direction::V, 2.0).unwrap();
    s.insert_knot_line(Direction::U, 6.0).unwrap();
    assert_eq!(s.local_count(), (9, 7));
    for i in 0..=30 {
        for j in 0..=30 {
            let (u, v) = (s.domain_u().lerp(i as f64 / 30.0), s.domain_v().lerp(j as f64 / 30.0));
            assert!((s.point(u, v) - before.point(u, v)).norm() < 1e-14);
        }
    }
}
