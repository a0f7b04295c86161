//! Bézier, rational Bézier, Hermite, Catmull–Rom and model curves: closed forms,
//! derivatives against finite differences, seams of closed curves, frames, length,
//! closest point.

mod common;
use common::*;
use splinekit::Point;
use splinekit::basis::Side;
use splinekit::curve::bezier::{CUBIC_BEZIER_MATRIX, CUBIC_BSPLINE_MATRIX, CUBIC_HERMITE_MATRIX, cubic_matrix_form};
use splinekit::curve::model::*;
use splinekit::curve::*;
use splinekit::frame::Affine;
use std::f64::consts::{PI, TAU};

fn check_derivatives<const D: usize>(c: &dyn Curve<D>, name: &str, max_order: usize) {
    let dom = c.domain();
    let h = 1e-4 * dom.length().min(10.0) / 10.0;
    for i in 1..8 {
        let t = dom.lerp(i as f64 / 8.0 + 0.013);
        let mut out = vec![Point::<D>::zeros(); max_order + 1];
        c.eval(t, &mut out);
        for k in 1..=max_order {
            let fd = finite_difference(c, t, k, h);
            let scale = out[k].norm().max(out[k - 1].norm()).max(1.0);
            assert!((out[k] - fd).norm() < 2e-6 * scale, "{name}: order {k} at {t}: {} vs {}", out[k], fd);
        }
    }
}

fn check_closed_seam<const D: usize>(c: &dyn Curve<D>, name: &str, orders: usize) {
    assert!(c.is_closed(), "{name} should be closed");
    let d = c.domain();
    let mut a = vec![Point::<D>::zeros(); orders + 1];
    let mut b = vec![Point::<D>::zeros(); orders + 1];
    c.eval_side(d.start, Side::Right, &mut a);
    c.eval_side(d.end, Side::Left, &mut b);
    assert_orders_close(&b, &a, 1e-9, &format!("{name}: at the seam"));
}

#[test]
fn bezier_de_casteljau_bernstein_and_matrix_forms_agree() {
    let pts = vec![p2(0.0, 0.0), p2(1.0, 3.0), p2(3.0, 3.0), p2(4.0, 0.0)];
    let b = BezierCurve::new(pts.clone()).unwrap();
    let g = [pts[0], pts[1], pts[2], pts[3]];
    for i in 0..=50 {
        let t = i as f64 / 50.0;
        let a = b.point(t);
        assert!((a - b.point_bernstein(t)).norm() < 1e-14);
        assert!((a - cubic_matrix_form(&CUBIC_BEZIER_MATRIX, &g, t)).norm() < 1e-13);
    }
    check_derivatives(&b, "bezier", 3);
    assert_eq!(b.derivative(0.3, 4), p2(0.0, 0.0));
    // c'(0) = n (P1 − P0).
    assert!((b.derivative(0.0, 1) - (pts[1] - pts[0]) * 3.0).norm() < 1e-14);
    // Hodograph, split, elevation.
    let hod = b.hodograph();
    let (l, r) = b.split(0.4);
    let e = b.elevate().elevate();
    for i in 0..=20 {
        let t = i as f64 / 20.0;
        assert!((hod.point(t) - b.derivative(t, 1)).norm() < 1e-13);
        assert!((l.point(t) - b.point(0.4 * t)).norm() < 1e-14);
        assert!((r.point(t) - b.point(0.4 + 0.6 * t)).norm() < 1e-14);
        assert!((e.point(t) - b.point(t)).norm() < 1e-14);
    }
    // The Hermite and uniform B-spline matrix forms agree with the curve classes.
    let h = HermiteCurve::new(vec![pts[0], pts[3]], vec![p2(3.0, 9.0), p2(3.0, -9.0)], None).unwrap();
    let s = BSplineCurve::new(3, (0..8).map(|i| i as f64).collect(), pts.clone()).unwrap();
    for i in 0..=10 {
        let t = i as f64 / 10.0;
        let hm = cubic_matrix_form(&CUBIC_HERMITE_MATRIX, &[pts[0], pts[3], p2(3.0, 9.0), p2(3.0, -9.0)], t);
        assert!((hm - h.point(t)).norm() < 1e-13);
        assert!((hm - b.point(t)).norm() < 1e-13, "Hermite with tangents 3(P1−P0), 3(P3−P2) is the Bézier");
        let sm = cubic_matrix_form(&CUBIC_BSPLINE_MATRIX, &g, t);
        assert!((sm - s.point(3.0 + t)).norm() < 1e-13);
    }
}

#[test]
fn rational_bezier_conics_are_exact() {
    let frame = CircleFrame { center: p2(1.0, 1.0), x_axis: p2(1.0, 0.0), y_axis: p2(0.0, 1.0), radius: 3.0 };
    let arc = RationalBezierCurve::circular_arc(&frame, 0.3, 2.0).unwrap();
    for i in 0..=100 {
        let t = i as f64 / 100.0;
        assert!(((arc.point(t) - p2(1.0, 1.0)).norm() - 3.0).abs() < 1e-14);
    }
    assert!((arc.point(1.0) - p2(1.0 + 3.0 * 2.3f64.cos(), 1.0 + 3.0 * 2.3f64.sin())).norm() < 1e-14);
    assert!((arc.length(1e-13) - 6.0).abs() < 1e-11);
    check_derivatives(&arc, "rational arc", 3);
    // Weight 1 gives the ordinary Bézier (a parabola).
    let para = RationalBezierCurve::conic(p2(0.0, 0.0), p2(1.0, 2.0), p2(2.0, 0.0), 1.0).unwrap();
    let poly = BezierCurve::new(vec![p2(0.0, 0.0), p2(1.0, 2.0), p2(2.0, 0.0)]).unwrap();
    assert!(max_distance(&para, &poly, 50) < 1e-15);
    assert!(RationalBezierCurve::new(vec![p2(0.0, 0.0), p2(1.0, 1.0)], vec![1.0, 0.0]).is_err());
}

#[test]
fn hermite_interpolates_points_and_tangents() {
    let pts = vec![p3(0.0, 0.0, 0.0), p3(1.0, 2.0, 0.0), p3(3.0, 1.0, 1.0), p3(4.0, -1.0, 0.0)];
    let tans = vec![p3(1.0, 0.0, 0.0), p3(1.0, 1.0, 0.0), p3(0.0, -1.0, 0.5), p3(2.0, 0.0, 0.0)];
    let params = vec![0.0, 0.5, 2.0, 2.5];
    let h = HermiteCurve::new(pts.clone(), tans.clone(), Some(params.clone())).unwrap();
    for i in 0..4 {
        let mut l = [Point::<3>::zeros(); 2];
        let mut r = [Point::<3>::zeros(); 2];
        h.eval_side(params[i], Side::Left, &mut l);
        h.eval_side(params[i], Side::Right, &mut r);
        for v in [l, r] {
            assert!((v[0] - pts[i]).norm() < 1e-14);
            assert!((v[1] - tans[i]).norm() < 1e-13, "tangent {i}: {} vs {}", v[1], tans[i]);
        }
    }
    check_derivatives(&h, "hermite", 3);
    assert!(HermiteCurve::new(pts.clone(), tans.clone(), Some(vec![0.0, 1.0, 1.0, 2.0])).is_err());
    assert!(HermiteCurve::new(pts, tans[..3].to_vec(), None).is_err());
}

#[test]
fn catmull_rom_interpolates_with_continuous_tangents() {
    let pts = vec![p2(0.0, 0.0), p2(1.0, 1.0), p2(1.1, 1.05), p2(3.0, 0.0), p2(4.0, 2.0)];
    for alpha in [0.0, 0.5, 1.0] {
        for closed in [false, true] {
            let c = CatmullRomCurve::new(pts.clone(), alpha, closed).unwrap();
            let knots = c.breakpoints();
            let expect = if closed { pts.len() + 1 } else { pts.len() };
            assert_eq!(knots.len(), expect);
            for (i, &k) in knots.iter().enumerate() {
                assert!((c.point(k) - pts[i % pts.len()]).norm() < 1e-14);
                let mut l = [Point::<2>::zeros(); 2];
                let mut r = [Point::<2>::zeros(); 2];
                c.eval_side(k, Side::Left, &mut l);
                c.eval_side(k, Side::Right, &mut r);
                if i > 0 && i + 1 < knots.len() {
                    assert!((l[1] - r[1]).norm() < 1e-12, "C¹ at knot {i}");
                }
            }
            if closed {
                check_closed_seam(&c, "closed catmull-rom", 1);
            }
            check_derivatives(&c, "catmull-rom", 3);
        }
    }
    // Uniform Catmull–Rom has the classic tangents (P_{i+1} − P_{i−1})/2.
    let c = CatmullRomCurve::new(pts.clone(), 0.0, false).unwrap();
    assert!((c.derivative(2.0, 1) - (pts[3] - pts[1]) * 0.5).norm() < 1e-14);
    // Centripetal parametrisation: knot gaps are √|ΔP|.
    let c = CatmullRomCurve::new(pts.clone(), 0.5, false).unwrap();
    let k = c.breakpoints();
    assert!((k[1] - k[0] - 2f64.sqrt().sqrt()).abs() < 1e-14);
    assert!(CatmullRomCurve::new(vec![p2(0.0, 0.0), p2(0.0, 0.0), p2(1.0, 0.0)], 0.5, false).is_err());
}

#[test]
fn model_curves_match_their_formulas() {
    let heart = Heart::new(1.0).unwrap();
    let rose = Rose::new(1.5, 4.0, false).unwrap();
    let trefoil = Trefoil::new(1.0).unwrap();
    let circle = Circle::new(2.0).unwrap();
    for i in 0..=60 {
        let t = TAU * i as f64 / 60.0;
        let h = p3(
            16.0 * t.sin().powi(3),
            13.0 * t.cos() - 5.0 * (2.0 * t).cos() - 2.0 * (3.0 * t).cos() - (4.0 * t).cos(),
            0.0,
        );
        assert!((heart.point(t) - h).norm() < 1e-13);
        let r = p3(1.5 * (4.0 * t).cos() * t.cos(), 1.5 * (4.0 * t).cos() * t.sin(), 1.5 * (4.0 * t).sin());
        assert!((rose.point(t) - r).norm() < 1e-14);
        let k = p3(t.sin() + 2.0 * (2.0 * t).sin(), t.cos() - 2.0 * (2.0 * t).cos(), -(3.0 * t).sin());
        assert!((trefoil.point(t) - k).norm() < 1e-14);
        assert!((circle.point(t) - p3(2.0 * t.cos(), 2.0 * t.sin(), 0.0)).norm() < 1e-15);
    }
    let butterfly = Butterfly::new(1.0).unwrap();
    for i in 0..=60 {
        let t = 24.0 * PI * i as f64 / 60.0;
        let r = t.cos().exp() - 2.0 * (4.0 * t).cos() - (t / 12.0).sin().powi(5);
        assert!((butterfly.point(t) - p3(t.sin() * r, t.cos() * r, 0.0)).norm() < 1e-13);
    }
}

#[test]
fn model_curve_derivatives_and_seams() {
    let curves: Vec<(&str, Box<dyn Curve<3>>)> = vec![
        ("circle", Box::new(Circle::new(1.0).unwrap())),
        ("ellipse", Box::new(Ellipse::new(2.0, 1.0).unwrap())),
        ("heart", Box::new(Heart::new(1.0).unwrap())),
        ("rose", Box::new(Rose::new(1.0, 4.0, false).unwrap())),
        ("lissajous", Box::new(Lissajous::new([1.0, 1.0, 0.5], [3.0, 2.0, 5.0], PI / 2.0).unwrap())),
        ("trefoil", Box::new(Trefoil::new(1.0).unwrap())),
        ("butterfly", Box::new(Butterfly::new(1.0).unwrap())),
    ];
    for (name, c) in &curves {
        check_derivatives(c.as_ref(), name, 4);
        check_closed_seam(c.as_ref(), name, 6);
    }
    let helix = Helix::new(2.0, 1.0, 3.0).unwrap();
    check_derivatives(&helix, "helix", 4);
    assert!(!helix.is_closed());
    // Helix curvature r/(r² + c²), c = pitch/2π.
    let c = 1.0 / TAU;
    assert!((helix.curvature(1.0) - 2.0 / (4.0 + c * c)).abs() < 1e-14);
    let f = helix.frame(1.0).unwrap();
    assert!((f.tangent.norm() - 1.0).abs() < 1e-15);
    let n = f.normal.unwrap();
    let b = f.binormal.unwrap();
    assert!(f.tangent.dot(&n).abs() < 1e-14 && f.tangent.dot(&b).abs() < 1e-14 && n.dot(&b).abs() < 1e-14);
    // The helix normal points to the axis.
    assert!((n - p3(-(1.0f64).cos(), -(1.0f64).sin(), 0.0)).norm() < 1e-14);
    // Ellipse length against the complete elliptic integral value (a = 2, b = 1).
    let e = Ellipse::new(2.0, 1.0).unwrap();
    assert!((e.length(1e-13) - 9.688448220547675).abs() < 1e-11);
}

#[test]
fn closest_point_is_found_on_closed_and_open_curves() {
    let circle = Circle::new(1.0).unwrap();
    // Near the seam: the answer is just before 2π.
    let a = -0.05f64;
    let q = p3(2.0 * a.cos(), 2.0 * a.sin(), 0.3);
    let near = circle.closest_point(&q, 0.0).unwrap();
    let (t, p) = (near.t, near.point);
    assert!((t - (TAU + a)).abs() < 1e-12, "t = {t}");
    assert!((p - p3(a.cos(), a.sin(), 0.0)).norm() < 1e-12);
    let pts = vec![p2(0.0, 0.0), p2(1.0, 2.0), p2(2.0, -1.0), p2(3.0, 1.0), p2(4.0, 0.0)];
    let c = BSplineCurve::clamped_uniform(3, pts).unwrap();
    for i in 1..20 {
        let t0 = i as f64 / 20.0;
        let mut d = [Point::<2>::zeros(); 2];
        c.eval(t0, &mut d);
        let normal = p2(-d[1][1], d[1][0]).normalize();
        let q = d[0] + normal * 0.01;
        let t = c.closest_point(&q, 0.0).unwrap().t;
        assert!((t - t0).abs() < 1e-9, "expected {t0}, got {t}");
    }
    // Beyond the end: the end point.
    assert_eq!(c.closest_point(&p2(10.0, 0.0), 0.0).unwrap().t, 1.0);
}

#[test]
fn affine_frames_map_points_and_vectors() {
    let r = Affine::rotation(p3(0.0, 0.0, 1.0), PI / 2.0).unwrap();
    let m = Affine::translation(p3(1.0, 2.0, 3.0)).after(&r);
    assert!((m.apply_point(&p3(1.0, 0.0, 0.0)) - p3(1.0, 3.0, 3.0)).norm() < 1e-15);
    assert!((m.apply_vector(&p3(1.0, 0.0, 0.0)) - p3(0.0, 1.0, 0.0)).norm() < 1e-15);
    let about = Affine::<3>::uniform_scale(2.0).about(&p3(1.0, 1.0, 1.0));
    assert!((about.apply_point(&p3(1.0, 1.0, 1.0)) - p3(1.0, 1.0, 1.0)).norm() < 1e-15);
    let inv = m.inverse().unwrap();
    assert!((inv.apply_point(&m.apply_point(&p3(0.3, -2.0, 5.0))) - p3(0.3, -2.0, 5.0)).norm() < 1e-14);
    assert!(Affine::<3>::scale(p3(1.0, 0.0, 1.0)).inverse().is_err());
    let mut d = [p3(1.0, 0.0, 0.0), p3(1.0, 0.0, 0.0)];
    m.apply_derivatives_about(&Point::<3>::zeros(), &mut d);
    assert!((d[0] - p3(1.0, 3.0, 3.0)).norm() < 1e-15 && (d[1] - p3(0.0, 1.0, 0.0)).norm() < 1e-15);
}
