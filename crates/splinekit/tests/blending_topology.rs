//! Knot edits that change the shape's topology without changing the shape: splitting a
//! surface's knot line along the other direction (GMlib's `splitKnotAlong`) and turning a
//! blending-spline curve open or closed (GMlib's `toggleClose`), checked against the spline
//! before at many parameters, derivatives included.

use std::sync::Arc;

use splinekit::basis::{BFunction, Side};
use splinekit::blend::{
    BlendKnots, BlendingCurveOptions, BlendingSplineCurve, BlendingSplineSurface, BlendingSurfaceOptions, LocalKind,
    PatchKind,
};
use splinekit::curve::Curve;
use splinekit::curve::model::{Circle, Heart, Helix};
use splinekit::frame::Affine;
use splinekit::surface::model::Torus;
use splinekit::surface::{Direction, Surface};
use splinekit::{Interval, Point};

fn same_surface(a: &dyn Surface<3>, b: &dyn Surface<3>, what: &str) {
    let (du, dv) = (b.domain_u(), b.domain_v());
    for i in 0..=37 {
        for j in 0..=29 {
            let (u, v) = (du.lerp(i as f64 / 37.0), dv.lerp(j as f64 / 29.0));
            let (mut p, mut q) = ([Point::<3>::zeros(); 4], [Point::<3>::zeros(); 4]);
            a.eval_partials(u, v, 1, 1, &mut p);
            b.eval_partials(u, v, 1, 1, &mut q);
            for (x, y) in p.iter().zip(&q) {
                assert!((x - y).norm() < 1e-11 * y.norm().max(1.0), "{what} at ({u}, {v}): {x} vs {y}");
            }
        }
    }
}

#[test]
fn splitting_a_knot_line_keeps_the_surface_and_lets_a_row_turn_into_a_crease_at_the_knot_pairs() {
    let torus = Arc::new(Torus::new(3.0, 1.0).unwrap());
    for kind in [PatchKind::Bezier(3, 3), PatchKind::Bezier(2, 4), PatchKind::SubSurface] {
        let options = BlendingSurfaceOptions { local: kind, closed_v: Some(false), ..Default::default() };
        let mut before = BlendingSplineSurface::from_model(torus.clone(), (7, 5), &options).unwrap();
        // An edited patch next to the split row, so the copies carry a transformed neighbour.
        before.set_transform(2, 1, Affine::translation(Point::<3>::new(0.0, 0.0, 0.4)));
        for (direction, k) in [(Direction::U, 3), (Direction::U, 6), (Direction::V, 1), (Direction::V, 3)] {
            let mut s = before.clone();
            s.split_knot_line(direction, k).unwrap();
            let (knots, count) = match direction {
                Direction::U => (s.knots().0.values().to_vec(), s.local_count().0),
                Direction::V => (s.knots().1.values().to_vec(), s.local_count().1),
            };
            assert_eq!(knots[k], knots[k + 1], "{kind:?} {direction:?} {k}");
            assert_eq!(count, if direction == Direction::U { 8 } else { 6 });
            same_surface(&s, &before, &format!("{kind:?} {direction:?} {k}"));
            // Turning the copies (row or column k + 1) about their origins: a crease at the knot.
            let t = knots[k];
            let others = if direction == Direction::U { 5 } else { 7 };
            for l in 0..others {
                let (a, b) = if direction == Direction::U { (k + 1, l) } else { (l, k + 1) };
                let turn = Affine::rotation(Point::<3>::new(0.3, 0.2, 1.0), 0.4).unwrap();
                s.set_transform(a, b, turn.after(s.transform(a, b)));
            }
            // At a knot pair of the line only the copy (from the right) or row k (from the
            // left) is active: both at their common origin.
            let other = if direction == Direction::U { s.knots().1.centre(2) } else { s.knots().0.centre(4) };
            let (u, v) = if direction == Direction::U { (t, other) } else { (other, t) };
            let (mut left, mut right) = ([Point::<3>::zeros(); 1], [Point::<3>::zeros(); 1]);
            // The left limit: just before the knot, where the copies take no part.
            let eps = 1e-9;
            let (ul, vl) = if direction == Direction::U { (u - eps, v) } else { (u, v - eps) };
            s.eval_partials(ul, vl, 0, 0, &mut left);
            s.eval_partials(u, v, 0, 0, &mut right);
            assert!((left[0] - right[0]).norm() < 1e-6, "C⁰ across the crease: {} vs {}", left[0], right[0]);
            // Between knot pairs the turned copies part from row k: two sheets.
            let mid = if direction == Direction::U { s.domain_v().lerp(0.37) } else { s.domain_u().lerp(0.61) };
            let (um, vm) = if direction == Direction::U { (t, mid) } else { (mid, t) };
            let (uml, vml) = if direction == Direction::U { (um - eps, vm) } else { (um, vm - eps) };
            let (mut l2, mut r2) = ([Point::<3>::zeros(); 1], [Point::<3>::zeros(); 1]);
            s.eval_partials(uml, vml, 0, 0, &mut l2);
            s.eval_partials(um, vm, 0, 0, &mut r2);
            assert!((l2[0] - r2[0]).norm() > 1e-4, "{kind:?} {direction:?}: sheets part between knot pairs");
            let across = |s: &BlendingSplineSurface<3>, at: (f64, f64)| {
                let mut p = [Point::<3>::zeros(); 4];
                s.eval_partials(at.0, at.1, 1, 1, &mut p);
                if direction == Direction::U { p[2] } else { p[1] }
            };
            let (d_left, d_right) = (across(&s, (ul, vl)), across(&s, (u, v)));
            assert!((d_left - d_right).norm() > 1e-2, "a crease: {d_left} vs {d_right}");
        }
    }
    let mut s = BlendingSplineSurface::from_model(torus, (6, 4), &BlendingSurfaceOptions::default()).unwrap();
    assert!(s.split_knot_line(Direction::U, 0).unwrap_err().to_string().contains("k: only interior knots 1..=5"));
    s.split_knot_line(Direction::U, 2).unwrap();
    assert!(s.split_knot_line(Direction::U, 3).unwrap_err().to_string().contains("already double"));
}

fn same_curve(a: &dyn Curve<3>, b: &dyn Curve<3>, range: Interval, what: &str) {
    for i in 0..=997 {
        let t = range.lerp(i as f64 / 997.0);
        for side in [Side::Left, Side::Right] {
            let (mut p, mut q) = ([Point::<3>::zeros(); 3], [Point::<3>::zeros(); 3]);
            a.eval_side(t, side, &mut p);
            b.eval_side(t, side, &mut q);
            for (j, (x, y)) in p.iter().zip(&q).enumerate() {
                assert!((x - y).norm() < 1e-10 * y.norm().max(1.0), "{what} at {t}, order {j}: {x} vs {y}");
            }
        }
    }
}

#[test]
fn opening_a_closed_spline_and_closing_it_again_keeps_the_curve_and_its_locals() {
    let heart: Arc<dyn Curve<3>> = Arc::new(Heart::new(1.0).unwrap());
    let circle: Arc<dyn Curve<3>> = Arc::new(Circle::new(2.0).unwrap());
    for model in [heart, circle] {
        for local in [LocalKind::Bezier(3), LocalKind::Bezier(5), LocalKind::SubCurve] {
            let options = BlendingCurveOptions { local, ..Default::default() };
            let mut closed = BlendingSplineCurve::from_model(model.clone(), 9, &options).unwrap();
            closed.set_transform(0, Affine::translation(Point::<3>::new(0.0, 0.3, 0.1)));
            closed.set_transform(4, Affine::uniform_scale(1.3));
            let mut c = closed.clone();
            c.set_closed(false).unwrap();
            assert_eq!((c.local_count(), c.is_closed(), c.domain()), (10, false, closed.domain()));
            // Local 9 is local 0 one period on, with its frame.
            assert_eq!(c.transform(9), closed.transform(0));
            same_curve(&c, &closed, closed.domain(), &format!("{local:?} opened"));
            c.set_closed(true).unwrap();
            assert_eq!((c.local_count(), c.is_closed()), (9, true), "{local:?}: the ends meet, the copy goes");
            same_curve(&c, &closed, closed.domain(), &format!("{local:?} closed again"));
            // Closing is idempotent.
            c.set_closed(true).unwrap();
            assert_eq!(c.local_count(), 9);
        }
    }
}

#[test]
fn closing_where_the_ends_do_not_meet_keeps_every_local_and_bridges_the_gap() {
    let helix: Arc<dyn Curve<3>> = Arc::new(Helix::new(1.0, 0.5, 2.0).unwrap());
    let open = BlendingSplineCurve::from_model(helix, 8, &BlendingCurveOptions::default()).unwrap();
    let knots = open.knots().values().to_vec();
    let mut c = open.clone();
    c.set_closed(true).unwrap();
    assert_eq!((c.local_count(), c.is_closed()), (8, true));
    let (last, end) = (knots[7], c.domain().end);
    assert!((end - (2.0 * knots[7] - knots[6])).abs() < 1e-12);
    // Unchanged up to the old end, where every derivative of the end local is kept.
    same_curve(&c, &open, Interval::new(knots[0], last), "up to the old end");
    // The bridge arrives at the start with local 0's derivatives (all of them: ERBS).
    let (mut at_end, mut at_start) = ([Point::<3>::zeros(); 4], [Point::<3>::zeros(); 4]);
    c.eval_side(end, Side::Left, &mut at_end);
    open.eval_side(knots[0], Side::Right, &mut at_start);
    for j in 0..4 {
        assert!((at_end[j] - at_start[j]).norm() < 1e-12, "order {j}: {} vs {}", at_end[j], at_start[j]);
    }
    // Hermite data whose ends differ: the same, every datum kept.
    let p = |x: f64, y: f64| Point::<3>::new(x, y, 0.0);
    let data = vec![vec![p(0.0, 0.0), p(1.0, 0.0)], vec![p(1.0, 1.0), p(0.0, 1.0)], vec![p(0.0, 2.0), p(-1.0, 0.0)]];
    let mut h = BlendingSplineCurve::from_hermite(
        BlendKnots::new(vec![0.0, 1.0, 2.0], false).unwrap(),
        data.clone(),
        BFunction::erbs_default(),
    )
    .unwrap();
    h.set_closed(true).unwrap();
    assert_eq!((h.local_count(), h.domain()), (3, Interval::new(0.0, 3.0)));
    for (k, t) in [0.0, 1.0, 2.0].into_iter().enumerate() {
        assert!((h.derivative(t, 1) - data[k][1]).norm() < 1e-12 && (h.point(t) - data[k][0]).norm() < 1e-12);
    }
    assert!((h.point(3.0) - data[0][0]).norm() < 1e-12);
    // Two locals cannot close.
    let two = vec![vec![p(0.0, 0.0), p(1.0, 0.0)], vec![p(1.0, 1.0), p(0.0, 1.0)]];
    let mut t = BlendingSplineCurve::from_hermite(
        BlendKnots::new(vec![0.0, 1.0], false).unwrap(),
        two,
        BFunction::erbs_default(),
    )
    .unwrap();
    let e = t.set_closed(true).unwrap_err().to_string();
    assert!(e.contains("closed") && e.contains("at least 3"), "{e}");
}
