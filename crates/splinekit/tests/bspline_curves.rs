//! B-spline and NURBS curves: evaluation against independent algorithms, derivatives,
//! invariance under knot operations, periodic seams.

mod common;
use common::*;
use proptest::prelude::*;
use splinekit::Point;
use splinekit::basis::{Side, basis_derivatives, basis_function, basis_functions, find_span};
use splinekit::curve::{BSplineCurve, CircleFrame, Curve, CurveArcLength, NurbsCurve};

fn sample_curve(degree: usize, n: usize) -> BSplineCurve<3> {
    let pts = (0..n)
        .map(|i| {
            let x = i as f64;
            p3(x, (x * 1.3).sin() * 2.0, (x * 0.7).cos())
        })
        .collect();
    // Non-uniform clamped knots with one double interior knot.
    let mut knots = vec![0.0; degree + 1];
    let inner = n - degree - 1;
    for i in 1..=inner {
        let v = (i as f64 / (inner + 1) as f64).powf(1.3) * 4.0;
        knots.push(v);
    }
    if inner >= 3 && degree >= 2 {
        knots[degree + 2] = knots[degree + 1];
    }
    knots.extend(vec![4.0; degree + 1]);
    BSplineCurve::new(degree, knots, pts).unwrap()
}

#[test]
fn basis_matches_single_function_algorithm_and_sums_to_one() {
    let knots = [0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 2.0, 3.0, 3.0, 3.0, 3.0];
    let (p, n) = (3, 8);
    for i in 0..=300 {
        let t = 3.0 * i as f64 / 300.0;
        let span = find_span(&knots, p, n, t, Side::Right);
        let mut b = [0.0; 4];
        basis_functions(&knots, p, span, t, &mut b);
        let sum: f64 = b.iter().sum();
        assert!((sum - 1.0).abs() < 1e-15, "partition of unity at {t}: {sum}");
        for r in 0..=p {
            let single = basis_function(&knots, p, span - p + r, t);
            assert!((single - b[r]).abs() < 1e-14, "N_{} at {t}: {} vs {}", span - p + r, b[r], single);
            assert!(b[r] >= -1e-15);
        }
    }
}

#[test]
fn basis_derivatives_match_finite_differences() {
    let knots = [0.0, 0.0, 0.0, 0.0, 0.3, 0.7, 1.1, 2.0, 2.0, 2.0, 2.0];
    let (p, n) = (3, 7);
    for &t in &[0.1, 0.45, 0.9, 1.5, 1.99] {
        let span = find_span(&knots, p, n, t, Side::Right);
        let mut d = [0.0; 16];
        basis_derivatives(&knots, p, span, t, 3, &mut d);
        let h = 1e-5;
        for r in 0..=p {
            let f = |s: f64| basis_function(&knots, p, span - p + r, s);
            let fd = (f(t + h) - f(t - h)) / (2.0 * h);
            assert!((d[4 + r] - fd).abs() < 1e-6, "N'_{r} at {t}: {} vs {fd}", d[4 + r]);
        }
        let s0: f64 = d[..4].iter().sum();
        let s1: f64 = d[4..8].iter().sum();
        let s2: f64 = d[8..12].iter().sum();
        assert!((s0 - 1.0).abs() < 1e-15 && s1.abs() < 1e-12 && s2.abs() < 1e-10);
    }
}

#[test]
fn point_matches_de_boor() {
    for degree in 1..=5 {
        let c = sample_curve(degree, 9);
        for i in 0..=97 {
            let t = 4.0 * i as f64 / 97.0;
            let a = c.point(t);
            let b = de_boor(degree, c.knots(), c.control_points(), t);
            assert!((a - b).norm() < 1e-13, "degree {degree} at {t}: {a} vs {b}");
        }
    }
}

#[test]
fn clamped_curve_interpolates_end_points_and_batch_equals_single() {
    let c = sample_curve(3, 10);
    assert!((c.point(0.0) - c.control_points()[0]).norm() < 1e-15);
    assert!((c.point(4.0) - c.control_points()[9]).norm() < 1e-15);
    let params: Vec<f64> = (0..200).map(|i| ((i * 37) % 200) as f64 / 50.0).collect();
    let mut out = vec![Point::<3>::zeros(); params.len() * 3];
    c.eval_many(&params, 2, &mut out);
    for (i, &t) in params.iter().enumerate() {
        let mut single = [Point::<3>::zeros(); 3];
        c.eval(t, &mut single);
        for k in 0..3 {
            assert_eq!(out[i * 3 + k], single[k], "batch differs at t = {t}, order {k}");
        }
    }
}

#[test]
fn derivatives_match_finite_differences_and_vanish_above_degree() {
    let c = sample_curve(4, 9);
    for &t in &[0.3, 1.7, 2.2, 3.9] {
        let mut d = [Point::<3>::zeros(); 7];
        c.eval(t, &mut d);
        for k in 1..=4 {
            let fd = finite_difference(&c, t, k, 1e-4);
            let scale = d[k].norm().max(1.0);
            assert!((d[k] - fd).norm() < 1e-6 * scale, "order {k} at {t}: {} vs {}", d[k], fd);
        }
        assert_eq!(d[5], Point::<3>::zeros());
        assert_eq!(d[6], Point::<3>::zeros());
    }
}

#[test]
fn left_and_right_limits_differ_at_a_double_knot() {
    // Quadratic with a double interior knot: C⁰ there, the tangent jumps.
    let knots = vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0];
    let pts = vec![p2(0.0, 0.0), p2(1.0, 1.0), p2(2.0, 0.0), p2(3.0, 2.0), p2(4.0, 0.0)];
    let c = BSplineCurve::new(2, knots, pts).unwrap();
    let mut l = [Point::<2>::zeros(); 2];
    let mut r = [Point::<2>::zeros(); 2];
    c.eval_side(1.0, Side::Left, &mut l);
    c.eval_side(1.0, Side::Right, &mut r);
    assert!((l[0] - p2(2.0, 0.0)).norm() < 1e-15 && (r[0] - p2(2.0, 0.0)).norm() < 1e-15);
    assert!((l[1] - p2(2.0, -2.0)).norm() < 1e-13, "left tangent {}", l[1]);
    assert!((r[1] - p2(2.0, 4.0)).norm() < 1e-13, "right tangent {}", r[1]);
}

#[test]
fn bad_knot_vectors_are_rejected_with_the_numbers() {
    let pts = vec![p2(0.0, 0.0); 8];
    let e = BSplineCurve::new(3, vec![0.0; 11], pts.clone()).unwrap_err().to_string();
    assert_eq!(e, "knots: expected 12 values for 8 control points of degree 3, got 11");
    let e = BSplineCurve::new(3, vec![0., 0., 0., 0., 2., 1., 3., 4., 5., 5., 5., 5.], pts.clone())
        .unwrap_err()
        .to_string();
    assert!(e.contains("non-decreasing") && e.contains("knot 5"), "{e}");
    let e = BSplineCurve::new(3, vec![0., 0., 0., 0., 1., 1., 1., 1., 1., 5., 5., 5.], pts.clone())
        .unwrap_err()
        .to_string();
    assert!(e.contains("multiplicity 5"), "{e}");
    let e = BSplineCurve::new(3, vec![0., 0., 0., 0., f64::NAN, 1., 2., 3., 4., 5., 5., 5.], pts.clone())
        .unwrap_err()
        .to_string();
    assert!(e.contains("knots") && e.contains("not finite"), "{e}");
    let e = BSplineCurve::<2>::new(100000, vec![0.0; 10], vec![p2(0.0, 0.0); 3]).unwrap_err().to_string();
    assert!(e.contains("degree 100000"), "{e}");
}

#[test]
fn periodic_curve_closes_with_full_continuity() {
    for degree in 1..=5 {
        let n = 7;
        let pts: Vec<Point<2>> = (0..n)
            .map(|i| {
                let a = i as f64 * std::f64::consts::TAU / n as f64;
                p2(a.cos() * (1.0 + 0.3 * i as f64), a.sin())
            })
            .collect();
        // Non-uniform but periodic spacing.
        let gaps = [1.0, 0.5, 2.0, 1.0, 0.7, 1.3, 0.9];
        let mut knots = vec![0.0];
        for i in 0..n + degree {
            let v = knots[i] + gaps[i % n];
            knots.push(v);
        }
        let c = BSplineCurve::new_periodic(degree, knots, pts).unwrap();
        assert!(c.is_closed());
        let d = c.domain();
        let mut a = vec![Point::<2>::zeros(); degree];
        let mut b = vec![Point::<2>::zeros(); degree];
        c.eval_side(d.start, Side::Right, &mut a);
        c.eval_side(d.end, Side::Left, &mut b);
        for k in 0..degree {
            let scale = a[k].norm().max(1.0);
            assert!((a[k] - b[k]).norm() < 1e-11 * scale, "degree {degree}, derivative {k}: {} vs {}", a[k], b[k]);
        }
        // Wrapping outside the domain.
        let t = d.start + 0.3;
        assert!((c.point(t) - c.point(t + d.length())).norm() < 1e-12);
    }
}

#[test]
fn periodic_knots_must_repeat_their_spacing() {
    let pts = vec![p2(0.0, 0.0), p2(1.0, 0.0), p2(1.0, 1.0), p2(0.0, 1.0)];
    let e = BSplineCurve::new_periodic(2, vec![0., 1., 2., 3., 4., 5., 7.5], pts).unwrap_err().to_string();
    assert!(e.contains("periodic"), "{e}");
}

#[test]
fn nurbs_circle_is_exact() {
    let frame =
        CircleFrame { center: p3(1.0, -2.0, 0.5), x_axis: p3(1.0, 0.0, 0.0), y_axis: p3(0.0, 1.0, 0.0), radius: 2.5 };
    let c = NurbsCurve::circle(&frame).unwrap();
    for i in 0..=1000 {
        let t = i as f64 / 1000.0;
        let mut d = [Point::<3>::zeros(); 3];
        c.eval(t, &mut d);
        let r = (d[0] - p3(1.0, -2.0, 0.5)).norm();
        assert!((r - 2.5).abs() < 4e-16 * 2.5 * 4.0, "radius {r} at {t}");
        // Tangent ⟂ radius vector, curvature 1/r.
        assert!((d[0] - p3(1.0, -2.0, 0.5)).dot(&d[1]).abs() < 1e-12 * d[1].norm());
        assert!((c.curvature(t) - 0.4).abs() < 1e-12);
    }
    assert!((c.length(1e-12) - std::f64::consts::TAU * 2.5).abs() < 1e-10);
}

#[test]
fn nurbs_derivatives_match_finite_differences() {
    let c = NurbsCurve::arc(&CircleFrame::in_xy_plane(p2(0.0, 0.0), 1.0), 0.2, 4.0).unwrap();
    for &t in &[0.05, 0.33, 0.61, 0.9] {
        let mut d = [Point::<2>::zeros(); 4];
        c.eval(t, &mut d);
        for k in 1..=3 {
            let fd = finite_difference(&c, t, k, 1e-4);
            assert!((d[k] - fd).norm() < 1e-6 * d[k].norm().max(1.0), "order {k} at {t}: {} vs {}", d[k], fd);
        }
    }
}

fn check_same<const D: usize>(a: &impl Curve<D>, b: &impl Curve<D>, what: &str) {
    let dist = max_distance(a, b, 500);
    assert!(dist < 1e-12, "{what}: curves differ by {dist}");
}

#[test]
fn knot_insertion_refinement_and_removal_leave_the_curve_unchanged() {
    let c = sample_curve(3, 9);
    let c1 = c.insert_knot(1.234, 2).unwrap();
    assert_eq!(c1.control_points().len(), 11);
    check_same(&c, &c1, "insert");
    let c2 = c.refine(&[0.1, 0.2, 0.2, 3.5, 2.0]).unwrap();
    check_same(&c, &c2, "refine");
    let (c3, removed) = c1.remove_knot(1.234, 2, 1e-10).unwrap();
    assert_eq!(removed, 2);
    assert_eq!(c3.control_points().len(), 9);
    check_same(&c, &c3, "remove");
    for (a, b) in c3.control_points().iter().zip(c.control_points()) {
        assert!((a - b).norm() < 1e-11);
    }
    // A knot that carries shape cannot be removed within a tiny tolerance.
    let interior = c.knots()[5];
    let (_, r) = c.remove_knot(interior, 1, 1e-9).unwrap();
    assert_eq!(r, 0);
    assert!(c.insert_knot(1.0, 4).is_err());
    assert!(c.insert_knot(9.0, 1).is_err());
}

#[test]
fn degree_elevation_keeps_the_shape_and_continuity() {
    for degree in 1..=4 {
        let c = sample_curve(degree, 9);
        for t in 1..=2 {
            let e = c.elevate_degree(t).unwrap();
            assert_eq!(e.degree(), degree + t);
            check_same(&c, &e, &format!("elevate {degree} by {t}"));
            // Interior knot multiplicities grow by exactly t.
            let dom = c.domain();
            for &k in c.knots().iter().filter(|&&k| k > dom.start && k < dom.end) {
                let m0 = c.knots().iter().filter(|&&x| x == k).count();
                let m1 = e.knots().iter().filter(|&&x| x == k).count();
                assert_eq!(m1, m0 + t, "knot {k}");
            }
        }
    }
}

#[test]
fn split_and_bezier_decomposition_reproduce_the_curve() {
    let c = sample_curve(3, 9);
    let (l, r) = c.split(1.7).unwrap();
    let r = r.unwrap();
    assert_eq!(l.domain().end, 1.7);
    assert_eq!(r.domain().start, 1.7);
    for i in 0..=100 {
        let t = 1.7 * i as f64 / 100.0;
        assert!((l.point(t) - c.point(t)).norm() < 1e-12);
        let t = 1.7 + 2.3 * i as f64 / 100.0;
        assert!((r.point(t) - c.point(t)).norm() < 1e-12);
    }
    let segs = c.bezier_segments().unwrap();
    let distinct_spans = c.breakpoints().len() - 1;
    assert_eq!(segs.len(), distinct_spans);
    for (span, bez) in &segs {
        for i in 0..=20 {
            let s = i as f64 / 20.0;
            assert!((bez.point(s) - c.point(span.start + (span.end - span.start) * s)).norm() < 1e-12);
        }
    }
}

#[test]
fn unclamped_curves_can_be_clamped_without_change() {
    let pts: Vec<Point<2>> = (0..6).map(|i| p2(i as f64, (i % 2) as f64)).collect();
    let c = BSplineCurve::new(3, (0..10).map(|i| i as f64).collect(), pts).unwrap();
    let k = c.clamped().unwrap();
    check_same(&c, &k, "clamp");
    assert_eq!(&k.knots()[..4], &[3.0; 4]);
}

#[test]
fn periodic_operations_stay_periodic_and_unchanged() {
    let pts: Vec<Point<2>> = (0..6)
        .map(|i| {
            let a = i as f64 * std::f64::consts::TAU / 6.0;
            p2(a.cos() * (1.0 + 0.2 * (i % 2) as f64), a.sin())
        })
        .collect();
    let c = BSplineCurve::periodic_uniform(3, pts).unwrap();
    let i = c.insert_knot(0.3, 1).unwrap();
    assert!(i.is_periodic());
    assert_eq!(i.control_points().len(), 7);
    check_same(&c, &i, "periodic insert");
    let e = c.elevate_degree(1).unwrap();
    assert!(e.is_periodic() && e.degree() == 4);
    check_same(&c, &e, "periodic elevate");
    let (r, removed) = i.remove_knot(0.3, 1, 1e-10).unwrap();
    assert_eq!(removed, 1);
    check_same(&c, &r, "periodic remove");
    let (open, none) = c.split(0.4).unwrap();
    assert!(none.is_none() && !open.is_periodic());
    for j in 0..=50 {
        let t = 0.4 + j as f64 / 50.0;
        assert!((open.point(t) - c.point(t)).norm() < 1e-12);
    }
}

#[test]
fn nurbs_operations_leave_the_circle_unchanged() {
    let c = NurbsCurve::circle(&CircleFrame::in_xy_plane(p2(0.0, 0.0), 1.0)).unwrap();
    let r = c.refine(&[0.1, 0.6, 0.6]).unwrap();
    check_same(&c, &r, "nurbs refine");
    let e = c.elevate_degree(2).unwrap();
    check_same(&c, &e, "nurbs elevate");
    for i in 0..=200 {
        assert!((e.point(i as f64 / 200.0).norm() - 1.0).abs() < 1e-14);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn affine_invariance(
        coords in prop::collection::vec(-10.0f64..10.0, 18),
        a in prop::array::uniform9(-2.0f64..2.0),
        b in prop::array::uniform3(-5.0f64..5.0),
        t in 0.0f64..1.0,
    ) {
        let pts: Vec<Point<3>> = coords.chunks(3).map(|c| p3(c[0], c[1], c[2])).collect();
        let c = BSplineCurve::clamped_uniform(3, pts).unwrap();
        let m = nalgebra::Matrix3::from_row_slice(&a);
        let v = Point::<3>::from(b);
        let mapped = c.map_points(|p| m * p + v);
        let lhs = mapped.point(t);
        let rhs = m * c.point(t) + v;
        prop_assert!((lhs - rhs).norm() < 1e-12 * (1.0 + rhs.norm()));
    }

    #[test]
    fn convex_hull_of_the_active_control_points(
        coords in prop::collection::vec(-10.0f64..10.0, 14),
        t in 0.0f64..1.0,
    ) {
        // In 1-D the convex hull is the interval of the active control points.
        let pts: Vec<Point<2>> = coords.chunks(2).map(|c| p2(c[0], c[1])).collect();
        let c = BSplineCurve::clamped_uniform(3, pts.clone()).unwrap();
        let span = find_span(c.knots(), 3, pts.len(), t, Side::Right);
        let active = &pts[span - 3..=span];
        let v = c.point(t);
        for axis in 0..2 {
            let lo = active.iter().map(|p| p[axis]).fold(f64::INFINITY, f64::min);
            let hi = active.iter().map(|p| p[axis]).fold(f64::NEG_INFINITY, f64::max);
            prop_assert!(v[axis] >= lo - 1e-12 && v[axis] <= hi + 1e-12);
        }
    }

    #[test]
    fn insertion_leaves_curve_unchanged(
        coords in prop::collection::vec(-10.0f64..10.0, 16),
        u in 0.01f64..0.99,
        times in 1usize..3,
        degree in 1usize..5,
    ) {
        let pts: Vec<Point<2>> = coords.chunks(2).map(|c| p2(c[0], c[1])).collect();
        let c = BSplineCurve::clamped_uniform(degree, pts).unwrap();
        if let Ok(i) = c.insert_knot(u, times.min(degree)) {
            prop_assert!(max_distance(&c, &i, 100) < 1e-12);
        }
        let e = c.elevate_degree(1).unwrap();
        prop_assert!(max_distance(&c, &e, 100) < 1e-12);
    }
}

#[test]
fn bezier_span_fast_path_agrees_with_the_de_boor_kernel() {
    // Degrees 1 … 9 cover the Bézier-span path (≤ 7) and the fallback (8, 9).
    for degree in 1..=9 {
        let c = sample_curve(degree, degree + 8);
        let scale = c.control_points().iter().map(|p| p.norm()).fold(0.0, f64::max);
        let params: Vec<f64> = (0..=400).map(|i| 4.0 * i as f64 / 400.0).collect();
        let mut batch = vec![Point::<3>::zeros(); params.len() * (degree + 2)];
        c.eval_many(&params, degree + 1, &mut batch);
        for (i, &t) in params.iter().enumerate() {
            for side in [Side::Left, Side::Right] {
                let mut fast = vec![Point::<3>::zeros(); degree + 2];
                let mut reference = vec![Point::<3>::zeros(); degree + 2];
                c.eval_side(t, side, &mut fast);
                c.eval_de_boor(t, side, &mut reference);
                let mut h_scale = scale;
                for k in 0..=degree + 1 {
                    let err = (fast[k] - reference[k]).norm();
                    assert!(
                        err <= 1e-13 * h_scale.max(reference[k].norm()),
                        "degree {degree}, order {k}, t = {t}: {err}"
                    );
                    if side == Side::Right {
                        assert!((batch[i * (degree + 2) + k] - fast[k]).norm() <= 1e-13 * h_scale.max(fast[k].norm()));
                    }
                    h_scale *= 10.0;
                }
            }
        }
    }
}

#[test]
fn degree_zero_splines_take_new_knots() {
    let c = BSplineCurve::new(0, vec![0.0, 1.0, 2.0, 3.0], vec![p2(0.0, 0.0), p2(5.0, 1.0), p2(7.0, 2.0)]).unwrap();
    let r = c.insert_knot(1.5, 1).unwrap();
    assert_eq!(r.knots(), &[0.0, 1.0, 1.5, 2.0, 3.0]);
    check_same(&c, &r, "degree-0 insertion");
    assert!(c.insert_knot(1.0, 1).is_err());
    let (l, right) = c.split(1.5).unwrap();
    assert_eq!(l.point(1.2), p2(5.0, 1.0));
    assert_eq!(right.unwrap().point(1.7), p2(5.0, 1.0));
}
