//! Splitting a surface's knot line and opening or closing a curve, as documents: the
//! document written back builds the shape before (moved, edited and animated pieces
//! included, posed at a time too), reads back as itself, and carries each copied piece's
//! entries.

use serde_json::json;
use splinekit::basis::Side;
use splinekit::curve::Curve;
use splinekit::surface::{Direction, Surface};
use splinekit::{Interval, Point};
use splinekit_scene::DocumentKind;
use splinekit_scene::SurfaceDocument;
use splinekit_scene::blending::{BlendingSplineSurfaceDoc, LocalCurves, set_closed, split_knot_line};

#[path = "common/edited_heart.rs"]
mod edited_heart;
use edited_heart::{HEART, curve_doc, curve_value};

fn surface_doc(value: serde_json::Value) -> BlendingSplineSurfaceDoc {
    match SurfaceDocument::from_value(value).unwrap() {
        SurfaceDocument::BlendingSplineSurface(d) => d,
        other => panic!("{other:?}"),
    }
}

fn same_surface(a: &dyn Surface<3>, b: &dyn Surface<3>, what: &str) {
    let (du, dv) = (b.domain_u(), b.domain_v());
    for i in 0..=41 {
        for j in 0..=23 {
            let (u, v) = (du.lerp(i as f64 / 41.0), dv.lerp(j as f64 / 23.0));
            let (p, q) = (a.point(u, v), b.point(u, v));
            assert!((p - q).norm() < 1e-11, "{what} at ({u}, {v}): {p} vs {q}");
        }
    }
}

#[test]
fn a_split_knot_line_document_builds_the_surface_before_with_its_entries_copied() {
    let doc = surface_doc(
        json!({"type": "blending_spline_surface", "model": {"type": "torus"}, "local_surfaces": [6, 5],
        "closed_v": false, "local": {"type": "bezier", "degree": [2, 3]},
        "transforms": {"2,1": {"translate": [0, 0, 0.5]}, "4,3": {"scale": 1.2}},
        "local_control_points": {"2,3": [[[4, 0, 1], [4, 1, 1], [3, 2, 1], [2, 3, 1]], [[4, 0, 0], [4, 1, 0], [3, 2, 0], [2, 3, 0]],
                                         [[4, 0, -1], [4, 1, -1], [3, 2, -1], [2, 3, -1]]]},
        "animation": [{"local": [2, 2], "motions": [{"pulse": {"amplitude": 0.2}}]}]}),
    );
    let before = doc.surface::<3>().unwrap();
    for (direction, k) in [(Direction::U, 2), (Direction::V, 3), (Direction::U, 5)] {
        let after = split_knot_line(&doc, direction, k).unwrap();
        let built = after.surface::<3>().unwrap();
        let mut kernel = before.clone();
        kernel.split_knot_line(direction, k).unwrap();
        assert_eq!(after.counts().unwrap(), [kernel.local_count().0, kernel.local_count().1]);
        same_surface(&built, &kernel, &format!("{direction:?} {k}: the kernel's split"));
        same_surface(&built, &before, &format!("{direction:?} {k}: the surface before"));
        let (mut a, mut b) = (after.clone(), doc.clone());
        a.set_time(0.3);
        b.set_time(0.3);
        same_surface(&a.surface::<3>().unwrap(), &b.surface::<3>().unwrap(), &format!("{direction:?} {k} at 0.3"));
        let back = surface_doc(SurfaceDocument::BlendingSplineSurface(after.clone()).to_value());
        assert_eq!(back, after, "{direction:?} {k}: the round trip");
    }
    // Row 2 split: the transform of (2, 1) and the edited net of (2, 3) are copied to row 3,
    // (4, 3) moves to (5, 3), the track of (2, 2) is copied to (3, 2).
    let after = split_knot_line(&doc, Direction::U, 2).unwrap();
    let mut t: Vec<_> = after.transforms.iter().map(|(i, _)| *i).collect();
    t.sort_unstable();
    assert_eq!(t, [(2, 1), (3, 1), (5, 3)]);
    let l: Vec<_> = after.local_control_points.iter().map(|(i, _)| *i).collect();
    assert_eq!(l, [(2, 3), (3, 3)]);
    let a: Vec<_> = after.animation.iter().map(|t| t.local).collect();
    assert_eq!(a, [(2, 2), (3, 2)]);
    let e = split_knot_line(&doc, Direction::V, 0).unwrap_err().to_string();
    assert!(e.starts_with("k: only interior knots"), "{e}");
}

#[test]
fn a_hermite_surface_splits_its_data() {
    let two = |z: f64| json!([[[0, 0, z], [0, 1, 0]], [[1, 0, 0], [0, 0, 0]]]);
    let doc = surface_doc(json!({"type": "blending_spline_surface", "knots_u": [0, 1, 2], "knots_v": [0, 1],
        "hermite": [[two(0.0), two(1.0)], [two(2.0), two(0.0)], [two(1.0), two(1.0)]]}));
    let before = doc.surface::<3>().unwrap();
    let after = split_knot_line(&doc, Direction::U, 1).unwrap();
    let data = after.hermite.as_ref().unwrap();
    assert_eq!((data.len(), &data[1]), (4, &data[2]));
    assert!(after.local_surfaces.is_none());
    same_surface(&after.surface::<3>().unwrap(), &before, "hermite split");
}

fn same_curve(a: &dyn Curve<3>, b: &dyn Curve<3>, range: Interval, what: &str) {
    for i in 0..=1500 {
        let t = range.lerp(i as f64 / 1500.0);
        let (p, q) = (a.point(t), b.point(t));
        assert!((p - q).norm() < 1e-11, "{what} at {t}: {p} vs {q}");
    }
}

#[test]
fn opening_and_closing_a_model_built_curve_document_keeps_the_curve() {
    let doc = curve_doc(HEART);
    let before = doc.curve::<3>().unwrap();
    let open = set_closed(&doc, false).unwrap();
    assert_eq!((open.closed, open.local_curves.clone()), (Some(false), Some(LocalCurves::Count(11))));
    assert_eq!(open.knots.as_deref(), Some(before.knots().values()));
    let built = open.curve::<3>().unwrap();
    assert!(!built.is_closed());
    same_curve(&built, &before, before.domain(), "opened");
    // Posed at a time as well (local 6's track stays with it).
    let (mut a, mut b) = (open.clone(), doc.clone());
    a.set_time(0.7);
    b.set_time(0.7);
    same_curve(&a.curve::<3>().unwrap(), &b.curve::<3>().unwrap(), before.domain(), "opened, at 0.7");
    let text = serde_json::to_string(&curve_value(&open)).unwrap();
    assert_eq!(curve_doc(&text), open);
    // Closing again: the heart's ends meet, the copy goes and the curve is the one before.
    let closed = set_closed(&open, true).unwrap();
    assert_eq!(closed.local_curves, Some(LocalCurves::Count(10)));
    same_curve(&closed.curve::<3>().unwrap(), &before, before.domain(), "closed again");
    // Local 0, moved? Not in HEART; move it and open: the copy carries the move.
    let mut moved = doc.clone();
    moved.transforms.push((0, serde_json::from_value(json!({"translate": [0, 2, 0]})).unwrap()));
    let open = set_closed(&moved, false).unwrap();
    assert!(open.transforms.iter().any(|(i, _)| *i == 10));
    same_curve(&open.curve::<3>().unwrap(), &moved.curve::<3>().unwrap(), before.domain(), "moved local 0, opened");
}

#[test]
fn hermite_curves_open_and_close_keeping_their_data_and_explicit_locals_refuse() {
    let doc = curve_doc(
        r#"{"type": "blending_spline", "knots": [0, 1, 2, 3],
            "hermite": [[[0, 0, 0], [1, 0, 0]], [[1, 1, 0], [0, 1, 0]], [[0, 2, 0], [-1, 0, 1]], [[-1, 1, 0], [0, -1, 0]]]}"#,
    );
    let before = doc.curve::<3>().unwrap();
    let closed = set_closed(&doc, true).unwrap();
    // The ends do not meet: every datum stays and a bridging knot is added.
    assert_eq!(
        (closed.hermite.as_ref().map(Vec::len), closed.knots.clone()),
        (Some(4), Some(vec![0.0, 1.0, 2.0, 3.0, 4.0]))
    );
    let c = closed.curve::<3>().unwrap();
    same_curve(&c, &before, Interval::new(0.0, 3.0), "closed with a bridge");
    let (mut end, mut start) = ([Point::<3>::zeros(); 2], [Point::<3>::zeros(); 2]);
    c.eval_side(4.0, Side::Left, &mut end);
    c.eval_side(0.0, Side::Right, &mut start);
    assert!((end[0] - start[0]).norm() < 1e-12 && (end[1] - start[1]).norm() < 1e-12);
    // Opened again: local 0's datum is copied to the end; the curve is the closed one.
    let open = set_closed(&closed, false).unwrap();
    assert_eq!(open.hermite.as_ref().map(Vec::len), Some(5));
    same_curve(&open.curve::<3>().unwrap(), &c, Interval::new(0.0, 4.0), "opened again");
    let explicit = curve_doc(
        r#"{"type": "blending_spline", "knots": [0, 1, 2, 3], "local_curves": [
            {"type": "line", "from": [0, 0], "to": [1, 0]}, {"type": "line", "from": [1, 0], "to": [1, 1]},
            {"type": "line", "from": [1, 1], "to": [0, 1]}, {"type": "line", "from": [0, 1], "to": [0, 0]}]}"#,
    );
    let e = set_closed(&explicit, true).unwrap_err().to_string();
    assert!(e.starts_with("local_curves: open or closed is set only for"), "{e}");
}
