//! Splitting a knot of a blending-spline document: the document written back builds
//! exactly the curve the kernel's split makes, which is the curve before (moved, edited
//! and animated locals included, posed at a time too), reads back as itself, and stays
//! continuous at the doubled knot when one copy is turned and scaled about its origin.

use splinekit::basis::Side;
use splinekit::curve::Curve;
use splinekit::{Interval, Point};
use splinekit_scene::DocumentKind;
use splinekit_scene::blending::{BlendingSplineDoc, knot_to_split, split_local_curve};

#[path = "common/edited_heart.rs"]
mod edited_heart;
use edited_heart::{HEART, curve_doc, curve_value};

fn assert_same(a: &dyn Curve<3>, b: &dyn Curve<3>, domain: Interval, what: &str) {
    for i in 0..=2000 {
        let t = domain.lerp(i as f64 / 2000.0);
        let (p, q) = (a.point(t), b.point(t));
        assert!((p - q).norm() < 1e-12, "{what}: at {t} {p} vs {q}");
    }
}

#[test]
fn the_split_document_builds_the_kernels_split_which_is_the_curve_before() {
    let doc = curve_doc(HEART);
    let before = doc.curve::<3>().unwrap();
    for k in [1, 4, 6, 7, 9] {
        let after = split_local_curve(&doc, k).unwrap();
        let mut kernel = before.clone();
        kernel.split_knot(k).unwrap();
        let built = after.curve::<3>().unwrap();
        assert_eq!(built.local_count(), 11);
        assert_eq!(after.knots.as_deref(), Some(kernel.knots().values()));
        assert_eq!(after.knots.as_ref().map(|c| c[k] == c[k + 1]), Some(true), "knot {k} twice");
        assert_same(&built, &kernel, before.domain(), &format!("k = {k}: the kernel's split"));
        assert_same(&built, &before, before.domain(), &format!("k = {k}: the curve before"));
        // Posed at a time: the copy of an animated local moves with it.
        let (mut a, mut b) = (after.clone(), doc.clone());
        a.set_time(0.3);
        b.set_time(0.3);
        assert_same(&a.curve::<3>().unwrap(), &b.curve::<3>().unwrap(), before.domain(), &format!("k = {k} at 0.3"));
        // The document reads back as itself, through JSON text.
        let text = serde_json::to_string(&curve_value(&after)).unwrap();
        let back = curve_doc(&text);
        assert_eq!(back, after, "k = {k}: the round trip");
        assert_same(&back.curve::<3>().unwrap(), &built, before.domain(), "read back");
        let indices = |d: &BlendingSplineDoc| d.transforms.iter().map(|(i, _)| *i).collect::<Vec<_>>();
        let expected: Vec<usize> = match k {
            1 => vec![1, 2, 5],
            4 => vec![4, 5, 1],
            _ => vec![if k < 4 { 5 } else { 4 }, 1],
        };
        let mut got = indices(&after);
        let mut want = expected;
        got.sort_unstable();
        want.sort_unstable();
        assert_eq!(got, want, "k = {k}: transforms");
    }
    // The edited local 7, split: both copies carry its polynomial on their supports.
    let after = split_local_curve(&doc, 7).unwrap();
    assert_eq!(after.local_control_points.iter().map(|(i, _)| *i).collect::<Vec<_>>(), [7, 8]);
    assert_ne!(after.local_control_points[0].1, after.local_control_points[1].1, "different supports");
    // The animated local 6, split: the copy has its track.
    let after = split_local_curve(&doc, 6).unwrap();
    assert_eq!(after.animation.iter().map(|t| t.local).collect::<Vec<_>>(), [6, 7]);
}

#[test]
fn turning_one_copy_keeps_the_curve_continuous_at_the_split_knot() {
    let doc = curve_doc(r#"{"type": "blending_spline", "model": {"type": "heart"}, "local_curves": 10}"#);
    let split = split_local_curve(&doc, 3).unwrap();
    let t = split.knots.as_ref().unwrap()[3];
    let mut turned = curve_value(&split);
    turned["transforms"] = serde_json::json!({"4": {"rotate": {"axis": [0, 0, 1], "angle": 0.6}, "scale": 1.4}});
    let turned = curve_doc(&turned.to_string());
    let c = turned.curve::<3>().unwrap();
    let side = |s| {
        let mut out = [Point::<3>::zeros(); 2];
        c.eval_side(t, s, &mut out);
        out
    };
    let (left, right) = (side(Side::Left), side(Side::Right));
    assert!((left[0] - right[0]).norm() < 1e-12, "C0: {} vs {}", left[0], right[0]);
    assert!((left[0] - doc.curve::<3>().unwrap().point(t)).norm() < 1e-12, "the joint stays");
    let angle = (left[1].normalize().dot(&right[1].normalize())).clamp(-1.0, 1.0).acos();
    assert!(angle > 0.3, "a corner of {angle} rad");
}

#[test]
fn splits_are_refused_by_field_and_the_nearest_single_knot_is_found() {
    let doc = curve_doc(HEART);
    let e = split_local_curve(&doc, 0).unwrap_err().to_string();
    assert!(e.starts_with("k: ") && e.contains("1..=9") && e.contains("got 0"), "{e}");
    let after = split_local_curve(&doc, 4).unwrap();
    let e = split_local_curve(&after, 4).unwrap_err().to_string();
    assert!(e.contains("already double"), "{e}");
    let knots = after.knots.clone().unwrap();
    // Near the doubled knot the next single one is taken; near the seam, knot 10's copy
    // of knot 0 does not split, the next interior one does.
    assert_eq!(knot_to_split(&after, knots[4] - 0.01).unwrap(), 3);
    assert_eq!(knot_to_split(&after, knots[5] + 0.01).unwrap(), 6);
    assert_eq!(knot_to_split(&after, knots[11] - 0.01).unwrap(), 10);
    let explicit = curve_doc(
        r#"{"type": "blending_spline", "knots": [0, 1, 2],
            "local_curves": [{"type": "line", "from": [0, 0], "to": [1, 0]},
                             {"type": "line", "from": [0, 1], "to": [1, 1]},
                             {"type": "line", "from": [0, 2], "to": [1, 2]}]}"#,
    );
    let refusal = "local_curves: a knot is split only in a blending spline built from a model (explicit local \
                   curves are mapped onto their supports, which a split halves)";
    assert_eq!(split_local_curve(&explicit, 1).unwrap_err().to_string(), refusal);
    assert_eq!(knot_to_split(&explicit, 1.0).unwrap_err().to_string(), refusal);
}
