//! Blending-spline curves: the Hermite property at the knots, exact reproduction with
//! sub-curve locals, seams of closed curves, locality of local frames, affine invariance,
//! derivatives, convergence.

mod common;
use common::*;
use splinekit::Point;
use splinekit::basis::{BFunction, Side};
use splinekit::blend::{BlendingSplineCurve, LocalKind};
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
                LocalKind::Bezier(d),
                BFunction::erbs_default(),
                closed,
            )
            .unwrap();
            for k in 0..c.local_count() {
                let t = c.centre(k);
                let mut got = vec![Point::<3>::zeros(); d + 1];
                let mut want = vec![Point::<3>::zeros(); d + 1];
                c.eval_side(t, Side::Right, &mut got);
                model.eval(t, &mut want);
                for j in 0..=d {
                    assert!(
                        (got[j] - want[j]).norm() < 1e-10 * want[j].norm().max(1.0),
                        "d = {d}, knot {k}, order {j}: {} vs {}",
                        got[j],
                        want[j]
                    );
                }
            }
        }
    }
    // With 3t² − 2t³ only the value and the first derivative are reproduced.
    let c = BlendingSplineCurve::from_model(heart(), 10, LocalKind::Bezier(3), BFunction::polynomial(1).unwrap(), true)
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
    let c = BlendingSplineCurve::from_model(heart(), 10, LocalKind::SubCurve, BFunction::erbs_default(), true).unwrap();
    assert!(max_distance(&c, heart().as_ref(), 400) < 1e-13);
    let b = BlendingSplineCurve::from_model(heart(), 7, LocalKind::Bezier(2), BFunction::Trigonometric, true).unwrap();
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
    let mut c =
        BlendingSplineCurve::from_model(heart(), 10, LocalKind::Bezier(3), BFunction::erbs_default(), true).unwrap();
    let before: Vec<(f64, Point<3>)> = (0..=500)
        .map(|i| {
            let t = c.domain().lerp(i as f64 / 500.0);
            (t, c.point(t))
        })
        .collect();
    let rot = Affine::rotation(p3(0.0, 0.0, 1.0), 0.4).unwrap().after(&Affine::uniform_scale(1.3));
    let ranges = c.set_transform(0, Affine::translation(p3(0.5, 1.0, 0.0)).after(&rot));
    assert_eq!(ranges.len(), 2, "local 0 of a closed curve straddles the seam");
    let inside = |t: f64| ranges.iter().any(|&(a, b)| t >= a && t <= b);
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
    let plain =
        BlendingSplineCurve::from_model(heart(), 8, LocalKind::Bezier(2), BFunction::erbs_default(), true).unwrap();
    let mut mapped =
        BlendingSplineCurve::from_model(heart(), 8, LocalKind::Bezier(2), BFunction::erbs_default(), true).unwrap();
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
        let c =
            BlendingSplineCurve::from_model(circle.clone(), n, LocalKind::Bezier(2), BFunction::erbs_default(), true)
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
    assert!(BlendingSplineCurve::from_model(circle, 2, LocalKind::Bezier(2), BFunction::Linear, true).is_err());
}
