//! Blending-spline curves: the Hermite property at the knots, exact reproduction with
//! sub-curve locals, seams of closed curves, locality of local frames, affine invariance,
//! derivatives, convergence.

mod common;
use common::*;
use splinekit::Point;
use splinekit::basis::{BFunction, Side};
use splinekit::blend::{BlendKnots, BlendingCurveOptions, BlendingSplineCurve, LocalKind};
use splinekit::curve::Curve;
use splinekit::curve::model::{Circle, Heart, Helix};
use splinekit::frame::Affine;
use std::sync::Arc;

fn heart() -> Arc<dyn Curve<3>> {
    Arc::new(Heart::new(1.0).unwrap())
}

#[test]
fn erbs_with_bezier_locals_reproduces_the_model_derivatives_at_every_knot() {
    for (model, closed) in [(heart(), true), (Arc::new(Helix::new(2.0, 1.0, 2.0).unwrap()) as Arc<dyn Curve<3>>, false)]
    {
        for d in 1..=4 {
            let c = BlendingSplineCurve::from_model(
                model.clone(),
                10,
                &BlendingCurveOptions { local: LocalKind::Bezier(d), closed: Some(closed), ..Default::default() },
            )
            .unwrap();
            for k in 0..c.local_count() {
                let t = c.centre(k);
                let mut got = vec![Point::<3>::zeros(); d + 1];
                let mut want = vec![Point::<3>::zeros(); d + 1];
                c.eval_side(t, Side::Right, &mut got);
                model.eval(t, &mut want);
                assert_orders_close(&got, &want, 1e-10, &format!("d = {d}, knot {k}"));
            }
        }
    }
    // With 3t² − 2t³ only the value and the first derivative are reproduced.
    let c = BlendingSplineCurve::from_model(
        heart(),
        10,
        &BlendingCurveOptions {
            local: LocalKind::Bezier(3),
            bfunction: BFunction::polynomial(1).unwrap(),
            closed: Some(true),
            ..Default::default()
        },
    )
    .unwrap();
    let t = c.centre(4) + 0.0;
    let (mut got, mut want) = ([Point::<3>::zeros(); 3], [Point::<3>::zeros(); 3]);
    c.eval(t, &mut got);
    heart().eval(t, &mut want);
    assert!((got[0] - want[0]).norm() < 1e-12 && (got[1] - want[1]).norm() < 1e-10);
    assert!((got[2] - want[2]).norm() > 1e-3, "B''(0) = 6 ≠ 0 changes the second derivative");
}

#[test]
fn sub_curve_locals_give_back_the_model_and_closed_curves_close() {
    let c = BlendingSplineCurve::from_model(
        heart(),
        10,
        &BlendingCurveOptions { local: LocalKind::SubCurve, closed: Some(true), ..Default::default() },
    )
    .unwrap();
    assert!(max_distance(&c, heart().as_ref(), 400) < 1e-13);
    let b = BlendingSplineCurve::from_model(
        heart(),
        7,
        &BlendingCurveOptions {
            local: LocalKind::Bezier(2),
            bfunction: BFunction::Trigonometric,
            closed: Some(true),
            ..Default::default()
        },
    )
    .unwrap();
    let d = b.domain();
    let (mut l, mut r) = ([Point::<3>::zeros(); 3], [Point::<3>::zeros(); 3]);
    b.eval_side(d.end, Side::Left, &mut l);
    b.eval_side(d.start, Side::Right, &mut r);
    for k in 0..3 {
        assert!((l[k] - r[k]).norm() < 1e-9 * l[k].norm().max(1.0), "order {k} at the seam");
    }
    for &t in &[0.3, 1.7, 3.9, 6.1] {
        let mut o = [Point::<3>::zeros(); 4];
        b.eval(t, &mut o);
        for k in 1..=3 {
            let f = finite_difference(&b, t, k, 1e-4);
            assert!((o[k] - f).norm() < 1e-5 * o[k].norm().max(1.0), "order {k} at {t}");
        }
    }
}

#[test]
fn moving_a_local_changes_only_its_support_and_frames_are_affine() {
    let mut c = BlendingSplineCurve::from_model(
        heart(),
        10,
        &BlendingCurveOptions { local: LocalKind::Bezier(3), closed: Some(true), ..Default::default() },
    )
    .unwrap();
    let before: Vec<(f64, Point<3>)> = (0..=500)
        .map(|i| {
            let t = c.domain().lerp(i as f64 / 500.0);
            (t, c.point(t))
        })
        .collect();
    let rot = Affine::rotation(p3(0.0, 0.0, 1.0), 0.4).unwrap().after(&Affine::uniform_scale(1.3));
    let ranges = c.set_transform(0, Affine::translation(p3(0.5, 1.0, 0.0)).after(&rot));
    assert_eq!(ranges.len(), 2, "local 0 of a closed curve straddles the seam");
    let inside = |t: f64| ranges.iter().any(|r| t >= r.start && t <= r.end);
    let mut changed = 0;
    for (t, p) in &before {
        let q = c.point(*t);
        if inside(*t) {
            changed += usize::from((q - p).norm() > 1e-9);
        } else {
            assert_eq!(q, *p, "t = {t} is outside the support but moved");
        }
    }
    assert!(changed > 50);
    // The local's own knot moves exactly as its frame says (ERBS: only local 0 acts there).
    let o = c.origin(0);
    assert!(
        (c.point(c.centre(0))
            - (o + Affine::translation(p3(0.5, 1.0, 0.0)).after(&rot).apply_point(&(heart().point(0.0) - o))))
        .norm()
            < 1e-12
    );

    // One affine map M applied through every frame equals M applied to the curve.
    let m = Affine::rotation(p3(1.0, 2.0, 0.5), 0.7).unwrap().after(&Affine::scale(p3(1.0, 2.0, 0.5)));
    let m = Affine::translation(p3(3.0, -1.0, 2.0)).after(&m);
    let plain = BlendingSplineCurve::from_model(
        heart(),
        8,
        &BlendingCurveOptions { local: LocalKind::Bezier(2), closed: Some(true), ..Default::default() },
    )
    .unwrap();
    let mut mapped = BlendingSplineCurve::from_model(
        heart(),
        8,
        &BlendingCurveOptions { local: LocalKind::Bezier(2), closed: Some(true), ..Default::default() },
    )
    .unwrap();
    for k in 0..8 {
        let o = mapped.origin(k);
        let frame = Affine { linear: m.linear, translation: m.apply_point(&o) - o };
        mapped.set_transform(k, frame);
    }
    for i in 0..=100 {
        let t = plain.domain().lerp(i as f64 / 100.0);
        assert!((mapped.point(t) - m.apply_point(&plain.point(t))).norm() < 1e-12);
    }
}

#[test]
fn bezier_locals_converge_to_the_circle() {
    let circle: Arc<dyn Curve<3>> = Arc::new(Circle::new(1.0).unwrap());
    let mut last = f64::INFINITY;
    let mut rates = Vec::new();
    for n in [4, 8, 16, 32] {
        let c = BlendingSplineCurve::from_model(
            circle.clone(),
            n,
            &BlendingCurveOptions { local: LocalKind::Bezier(2), closed: Some(true), ..Default::default() },
        )
        .unwrap();
        let err = (0..2000)
            .map(|i| (c.point(std::f64::consts::TAU * i as f64 / 2000.0).norm() - 1.0).abs())
            .fold(0.0, f64::max);
        if last.is_finite() {
            rates.push((last / err).log2());
        }
        assert!(err < last, "n = {n}: {err} ≥ {last}");
        last = err;
    }
    eprintln!("blending spline of the circle, Bézier degree 2 locals, n = 4→8→16→32: rates {rates:?}");
    assert!(rates.iter().all(|&r| r > 2.5), "convergence rates {rates:?}");
    assert!(
        BlendingSplineCurve::from_model(
            circle,
            2,
            &BlendingCurveOptions {
                local: LocalKind::Bezier(2),
                bfunction: BFunction::Linear,
                closed: Some(true),
                ..Default::default()
            }
        )
        .is_err()
    );
}

#[test]
fn osculating_arc_locals_match_position_tangent_and_curvature_and_give_the_circle_back() {
    let circle: Arc<dyn Curve<3>> = Arc::new(Circle::new(2.0).unwrap());
    let c = BlendingSplineCurve::from_model(
        circle.clone(),
        5,
        &BlendingCurveOptions { local: LocalKind::Arc, closed: Some(true), ..Default::default() },
    )
    .unwrap();
    for i in 0..=200 {
        let t = i as f64 * std::f64::consts::TAU / 200.0;
        assert!((c.point(t) - circle.point(t)).norm() < 1e-13, "t = {t}");
    }
    let h: Arc<dyn Curve<3>> = Arc::new(splinekit::curve::model::Ellipse::new(3.0, 1.0).unwrap());
    let c = BlendingSplineCurve::from_model(
        h.clone(),
        12,
        &BlendingCurveOptions { local: LocalKind::Arc, closed: Some(true), ..Default::default() },
    )
    .unwrap();
    for k in 0..12 {
        let t = c.centre(k);
        let (mut got, mut want) = ([Point::<3>::zeros(); 3], [Point::<3>::zeros(); 3]);
        c.eval(t, &mut got);
        h.eval(t, &mut want);
        assert!((got[0] - want[0]).norm() < 1e-12 && (got[1] - want[1]).norm() < 1e-11);
        let (kg, kw) = (c.curvature(t), h.curvature(t));
        assert!((kg - kw).abs() < 1e-10 * kw.max(1.0), "knot {k}: curvature {kg} vs {kw}");
    }
    // The heart has no tangent at its cusp (t = 0): arcs are refused there, with a reason.
    let e = BlendingSplineCurve::from_model(
        heart(),
        12,
        &BlendingCurveOptions { local: LocalKind::Arc, closed: Some(true), ..Default::default() },
    );
    assert!(e.err().unwrap().to_string().contains("no tangent"));
}

#[test]
fn chord_length_knots_space_the_locals_evenly_along_the_model() {
    use splinekit::blend::KnotSpacing;
    use splinekit::ops::length::arc_length;
    let h = heart();
    let c = BlendingSplineCurve::from_model(
        h.clone(),
        10,
        &BlendingCurveOptions {
            local: LocalKind::Bezier(3),
            bfunction: BFunction::erbs_default(),
            closed: Some(true),
            spacing: KnotSpacing::ChordLength,
        },
    )
    .unwrap();
    let knots = c.knots().values();
    let lengths: Vec<f64> =
        knots.windows(2).map(|w| arc_length(h.as_ref(), splinekit::Interval::new(w[0], w[1]), 1e-10)).collect();
    let mean = lengths.iter().sum::<f64>() / lengths.len() as f64;
    for l in &lengths {
        assert!((l - mean).abs() < 1e-4 * mean, "{lengths:?}");
    }
    // Still Hermite at the (non-uniform) knots.
    for k in 0..10 {
        let t = c.centre(k);
        let (mut got, mut want) = ([Point::<3>::zeros(); 4], [Point::<3>::zeros(); 4]);
        c.eval(t, &mut got);
        h.eval(t, &mut want);
        assert_orders_close(&got, &want, 1e-9, &format!("knot {k}"));
    }
}

#[test]
fn explicit_locals_are_mapped_onto_their_supports() {
    use splinekit::curve::BezierCurve;
    // Three straight locals; the curve passes through each local's point at its knot.
    let line = |a: [f64; 2], b: [f64; 2]| -> Arc<dyn Curve<2>> {
        Arc::new(BezierCurve::new(vec![Point::<2>::from(a), Point::<2>::from(b)]).unwrap())
    };
    let locals = vec![line([-1.0, 0.0], [1.0, 0.0]), line([0.0, 0.0], [2.0, 2.0]), line([1.0, 1.0], [3.0, 1.0])];
    let c = BlendingSplineCurve::from_locals(
        BlendKnots::new(vec![0.0, 1.0, 3.0], false).unwrap(),
        locals,
        BFunction::erbs_default(),
    )
    .unwrap();
    // Local k's [0,1] spans [c_{k−1}, c_{k+1}]; its midpoint ... at the knot it is at u = (c_k − c_{k−1})/(c_{k+1} − c_{k−1}).
    assert!((c.point(0.0) - Point::<2>::new(0.0, 0.0)).norm() < 1e-15);
    assert!((c.point(1.0) - Point::<2>::new(2.0 / 3.0, 2.0 / 3.0)).norm() < 1e-15);
    assert!((c.point(3.0) - Point::<2>::new(2.0, 1.0)).norm() < 1e-15);
    // The derivative at a knot is the local's, scaled by the map: local 1 spans 3 units.
    let mut d = [Point::<2>::zeros(); 2];
    c.eval(1.0, &mut d);
    assert!((d[1] - Point::<2>::new(2.0 / 3.0, 2.0 / 3.0)).norm() < 1e-14);
    check_derivatives_by_finite_differences(&c, &[0.3, 1.7, 2.5]);
    let two_knots = BlendKnots::new(vec![0.0, 1.0], false).unwrap();
    let bad = BlendingSplineCurve::<2>::from_locals(two_knots, vec![], BFunction::erbs_default());
    assert!(bad.err().unwrap().to_string().contains("local_curves"));
}

fn check_derivatives_by_finite_differences<C: Curve<D>, const D: usize>(c: &C, ts: &[f64]) {
    for &t in ts {
        let h = 1e-6;
        let (mut a, mut b, mut m) = ([Point::<D>::zeros(); 3], [Point::<D>::zeros(); 3], [Point::<D>::zeros(); 3]);
        c.eval(t - h, &mut a);
        c.eval(t + h, &mut b);
        c.eval(t, &mut m);
        for j in 0..2 {
            let fd = (b[j] - a[j]) / (2.0 * h);
            assert!((fd - m[j + 1]).norm() < 1e-6 * m[j + 1].norm().max(1.0), "t = {t}, order {}", j + 1);
        }
    }
}

#[test]
fn inserting_a_local_keeps_the_curve_outside_its_interval_and_still_interpolates() {
    let h = heart();
    let mut c = BlendingSplineCurve::from_model(
        h.clone(),
        8,
        &BlendingCurveOptions { local: LocalKind::Bezier(2), closed: Some(true), ..Default::default() },
    )
    .unwrap();
    let before = c.clone();
    let (lo, hi) = (c.centre(2), c.centre(3));
    let t_new = 0.5 * (lo + hi) + 0.1;
    let k = c.insert_local(t_new).unwrap();
    assert_eq!((k, c.local_count()), (3, 9));
    for i in 0..=400 {
        let t = i as f64 * std::f64::consts::TAU / 400.0;
        // The neighbours are re-expressed on their shrunk supports: the same
        // polynomials, up to rounding.
        if t <= lo || t >= hi {
            assert!((c.point(t) - before.point(t)).norm() < 1e-12, "t = {t} outside the split interval moved");
        }
    }
    // The old knots keep the model's derivatives; the new one the previous curve's (its
    // local is the curve's Taylor polynomial there, tests/blending_insertion.rs).
    for k in 0..c.local_count() {
        let t = c.centre(k);
        let (mut got, mut want) = ([Point::<3>::zeros(); 3], [Point::<3>::zeros(); 3]);
        c.eval(t, &mut got);
        if k == 3 {
            before.eval(t, &mut want)
        } else {
            h.eval(t, &mut want)
        }
        assert_orders_close(&got, &want, 1e-9, &format!("knot {k}"));
    }
    assert!(c.insert_local(t_new).is_err(), "a knot cannot be inserted twice");
    assert!(c.insert_local(100.0).is_err());
}

#[test]
fn splitting_a_knot_gives_a_c0_joint_that_survives_rotating_one_copy() {
    let mut c = BlendingSplineCurve::from_model(
        heart(),
        8,
        &BlendingCurveOptions { local: LocalKind::Bezier(3), closed: Some(true), ..Default::default() },
    )
    .unwrap();
    let before = c.clone();
    c.split_knot(3).unwrap();
    assert_eq!(c.local_count(), 9);
    for i in 0..=100 {
        let t = i as f64 * std::f64::consts::TAU / 100.0;
        assert!((c.point(t) - before.point(t)).norm() < 1e-12);
    }
    let t = c.centre(3);
    c.set_transform(4, Affine::rotation(Point::<3>::new(0.0, 0.0, 1.0), 0.7).unwrap());
    let (mut l, mut r) = ([Point::<3>::zeros(); 2], [Point::<3>::zeros(); 2]);
    c.eval_side(t, Side::Left, &mut l);
    c.eval_side(t, Side::Right, &mut r);
    assert!((l[0] - r[0]).norm() < 1e-12, "C⁰ at the double knot");
    assert!((l[1] - r[1]).norm() > 1.0, "a corner after rotating one copy");
    assert!((r[1] - Affine::rotation(Point::<3>::new(0.0, 0.0, 1.0), 0.7).unwrap().apply_vector(&l[1])).norm() < 1e-9);
}

#[test]
fn rebuilding_changes_count_degree_and_bfunction_and_refresh_only_touches_the_affected_range() {
    use splinekit::curve::CurveSamples;
    let c = BlendingSplineCurve::from_model(
        heart(),
        6,
        &BlendingCurveOptions { local: LocalKind::Bezier(2), closed: Some(true), ..Default::default() },
    )
    .unwrap();
    let finer = c.rebuilt(24, LocalKind::Bezier(4)).unwrap();
    assert_eq!(finer.local_count(), 24);
    let err = |c: &BlendingSplineCurve<3>| {
        (0..500).map(|i| (c.point(i as f64 * 0.0125) - heart().point(i as f64 * 0.0125)).norm()).fold(0.0, f64::max)
    };
    assert!(err(&finer) < err(&c) / 100.0);
    let mut poly = c.clone();
    poly.set_bfunction(BFunction::polynomial(2).unwrap());
    assert!(err(&poly) != err(&c));

    let mut c = finer;
    let mut samples = CurveSamples::uniform(&c, 2001, 2).unwrap();
    let ranges = c.set_transform(5, Affine::uniform_scale(1.5));
    let touched = samples.refresh(&c, &ranges);
    assert!(touched > 100 && touched < 200, "{touched} samples re-evaluated");
    let fresh = CurveSamples::uniform(&c, 2001, 2).unwrap();
    for i in 0..2001 {
        assert_eq!(samples.at(i), fresh.at(i), "sample {i}");
    }
    // Local 0 of the closed curve touches both ends of the domain.
    let ranges = c.set_transform(0, Affine::translation(Point::<3>::new(0.0, 1.0, 0.0)));
    assert_eq!(ranges.len(), 2);
    samples.refresh(&c, &ranges);
    let fresh = CurveSamples::uniform(&c, 2001, 2).unwrap();
    assert!((0..2001).all(|i| samples.at(i) == fresh.at(i)));
}

#[test]
fn arc_length_knots_are_where_the_spirals_closed_form_length_is_k_l_over_n() {
    use splinekit::blend::KnotSpacing;
    use splinekit::curve::model::LogarithmicSpiral;
    // r = a e^{bt}: length from 0 to t is a√(1 + b²)(e^{bt} − 1)/b, so the knot of
    // length k L/(n − 1) is t_k = ln(1 + k(e^{bT} − 1)/(n − 1))/b, T = 2π·turns.
    let (a, b, turns) = (0.5, 0.2, 3.0);
    let spiral: Arc<dyn Curve<3>> = Arc::new(LogarithmicSpiral::new(a, b, turns).unwrap());
    let n = 12;
    let options = BlendingCurveOptions { spacing: KnotSpacing::ArcLength, closed: Some(false), ..Default::default() };
    let c = BlendingSplineCurve::from_model(spiral.clone(), n, &options).unwrap();
    let end = (b * std::f64::consts::TAU * turns).exp();
    for k in 0..n {
        let want = (1.0 + k as f64 * (end - 1.0) / (n - 1) as f64).ln() / b;
        assert!((c.centre(k) - want).abs() < 1e-9, "knot {k}: {} vs {want}", c.centre(k));
    }
    // The polyline spacing is close but an order of magnitude and more less accurate.
    let chord = BlendingCurveOptions { spacing: KnotSpacing::ChordLength, ..options.clone() };
    let rough = BlendingSplineCurve::from_model(spiral.clone(), n, &chord).unwrap();
    let worst = (1..n - 1).map(|k| (rough.centre(k) - c.centre(k)).abs()).fold(0.0, f64::max);
    assert!(worst > 1e-8 && worst < 1e-3, "{worst:e}");
    // Still Hermite at the uneven knots.
    for k in 0..n {
        let t = c.centre(k);
        let (mut got, mut want) = ([Point::<3>::zeros(); 4], [Point::<3>::zeros(); 4]);
        c.eval(t, &mut got);
        spiral.eval(t, &mut want);
        assert_orders_close(&got, &want, 1e-10, &format!("knot {k}"));
    }
}
