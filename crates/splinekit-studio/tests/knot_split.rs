//! Splitting a knot of a blending-spline curve from the window, without a window (issue
//! 22): the Properties panel's, the Edit menu's and the key D's Split knot; with no local
//! selected the tool arms and a click on the heart (examples/scenes/heart_local_curves.json)
//! splits the knot nearest it, with a local curve selected its knot splits at once. The
//! document builds the kernel's split and the curve is unchanged; one undo gives the
//! document back exactly. The two copies have handles of their own, and dragging one turns
//! and scales it about the joint: the curve moves on that copy's side only and stays
//! continuous at the doubled knot.

use egui_kittest::Harness;
use serde_json::Value;
use splinekit::Point;
use splinekit::basis::Side;
use splinekit::blend::BlendingSplineCurve;
use splinekit::curve::Curve;
use splinekit_render::RenderScene;
use splinekit_studio::actions::Action;
use splinekit_studio::gesture::GestureKind;
use splinekit_studio::handles::HandleKind;
use splinekit_studio::knot_edit::{KnotTool, curve_samples};
use splinekit_studio::studio::Studio;
use splinekit_studio::view_camera::Projector;

#[path = "common/knot_tools.rs"]
mod knot_tools;
use knot_tools::{armed, assert_armed_from_the_window, blending_curve, frame, open, open_selected, projector};

fn shape(studio: &Studio) -> Value {
    studio.document.scene().objects[0].to_value()["shape"].clone()
}

fn knots(studio: &Studio) -> Vec<f64> {
    serde_json::from_value(shape(studio)["knots"].clone()).expect("explicit knots")
}

/// The curves agree at 601 samples of the domain and at `extra`, both sides, to 10⁻¹².
fn assert_same(a: &BlendingSplineCurve<3>, b: &BlendingSplineCurve<3>, extra: &[f64], what: &str) {
    let samples = (0..=600).map(|i| a.domain().lerp(i as f64 / 600.0));
    for t in samples.chain(extra.iter().copied()) {
        for side in [Side::Left, Side::Right] {
            let (mut p, mut q) = ([Point::<3>::zeros(); 1], [Point::<3>::zeros(); 1]);
            a.eval_side(t, side, &mut p);
            b.eval_side(t, side, &mut q);
            assert!((p[0] - q[0]).norm() < 1e-12, "{what}: at {t} {} vs {}", p[0], q[0]);
        }
    }
}

#[test]
fn a_click_near_a_knot_of_the_heart_splits_it_and_undo_takes_it_back() {
    let (mut studio, projector, original) = armed("heart_local_curves.json", Action::SplitKnot, KnotTool::SplitKnot);
    let original_curve = blending_curve(&studio, 0);
    let knot3 = original_curve.centre(3);
    let samples = curve_samples(&studio.document.scene().objects[0].shape, 600).expect("samples");
    // A click on the curve a little past knot 3 (0.63 from its neighbours).
    let (_, p) =
        *samples.iter().min_by(|a, b| (a.0 - knot3 - 0.1).abs().total_cmp(&(b.0 - knot3 - 0.1).abs())).unwrap();
    let (px, _) = projector.project(p).expect("in view");
    studio.knot_click(KnotTool::SplitKnot, &projector, px, false);
    assert_eq!(studio.knot_tool, None);
    let s = shape(&studio);
    assert_eq!(s["local_curves"], serde_json::json!(11), "one local more");
    let knots_now = knots(&studio);
    assert_eq!(knots_now.len(), 12, "closed: one knot more than locals");
    assert_eq!((knots_now[3], knots_now[4]), (knot3, knot3), "knot 3 twice");
    // What the document builds is the kernel's split, and the curve as it was.
    let mut expected = original_curve.clone();
    expected.split_knot(3).expect("splits");
    let now = blending_curve(&studio, 0);
    assert_same(&now, &expected, &[knot3], "the kernel's split");
    assert_same(&now, &original_curve, &[knot3], "the curve before");
    studio.undo();
    assert_eq!(studio.document.scene().to_value(), original, "one undo step gives the document back");
}

/// With local curve 3 selected, D splits knot 3 at once; the two copies' handles sit apart
/// with the joint as their pivot, and a drag of the right copy turns and scales it about
/// the joint: the curve is continuous there, unchanged left of it, and changed on the
/// copy's side; one undo step each.
#[test]
fn a_selected_local_splits_at_once_and_each_copy_turns_about_the_joint() {
    let mut studio = open("heart_local_curves.json");
    let mut projector = projector(&mut studio);
    let handle = studio.shown_handles().find(|h| h.kind == HandleKind::LocalCurve(3)).cloned().expect("local 3");
    assert_eq!(handle.pivot, None, "a single knot's handle is its origin");
    let (px, _) = projector.project(handle.position).expect("in view");
    studio.click(studio.pick(&projector, px), false);
    assert_eq!(studio.selection.handle.as_ref().map(|h| h.kind), Some(HandleKind::LocalCurve(3)));
    let original = studio.document.scene().to_value();
    let before = blending_curve(&studio, 0);
    let knot = before.centre(3);
    let mut h = Harness::new_ui_state(frame, studio);
    h.run();
    h.key_press(egui::Key::D);
    h.run();
    let studio = h.state_mut();
    assert_eq!(studio.knot_tool, None, "split at once");
    let split = studio.document.scene().to_value();
    assert_eq!((knots(studio)[3], knots(studio)[4]), (knot, knot));
    assert_same(&blending_curve(studio, 0), &before, &[knot], "the curve before");
    studio.undo();
    assert_eq!(studio.document.scene().to_value(), original, "one undo step");
    studio.redo();
    assert_eq!(studio.document.scene().to_value(), split);
    // The copies' handles: apart, on either side of the joint, the joint their pivot.
    projector = self::projector(studio);
    let copy = |studio: &Studio, k| studio.shown_handles().find(|h| h.kind == HandleKind::LocalCurve(k)).cloned();
    let (left, right) = (copy(studio, 3).expect("left copy"), copy(studio, 4).expect("right copy"));
    let joint = before.point(knot);
    for h in [&left, &right] {
        let pivot = h.pivot.expect("a copy turns about the joint");
        assert!((Point::<3>::from(pivot) - joint).norm() < 1e-12, "the joint");
    }
    let (lp, _) = projector.project(left.position).expect("in view");
    let (rp, _) = projector.project(right.position).expect("in view");
    assert!((lp[0] - rp[0]).hypot(lp[1] - rp[1]) > 10.0, "two handles to pick: {lp:?} {rp:?}");
    assert_eq!(studio.pick(&projector, rp).map(|h| h.kind), Some(HandleKind::LocalCurve(4)));
    // Drag the right copy 40 pixels across: it turns and scales about the joint.
    assert!(studio.begin_drag(&projector, rp, GestureKind::Move(None)));
    for k in 1..=10 {
        studio.drag_to(&projector, [rp[0] + 4.0 * k as f64, rp[1] - 2.0 * k as f64]);
    }
    studio.end_drag();
    let s = shape(studio);
    let transforms = s["transforms"].as_object().expect("a transform");
    assert_eq!(transforms.keys().collect::<Vec<_>>(), ["4"], "the right copy's only");
    assert!(transforms["4"].get("rotate").is_some() && transforms["4"].get("scale").is_some(), "{}", transforms["4"]);
    assert!(transforms["4"].get("translate").is_none(), "no move: {}", transforms["4"]);
    let now = blending_curve(studio, 0);
    let side = |t, s| {
        let mut out = [Point::<3>::zeros(); 1];
        now.eval_side(t, s, &mut out);
        out[0]
    };
    let gap = (side(knot, Side::Left) - side(knot, Side::Right)).norm();
    assert!(gap < 1e-12, "C0 at the split knot: a gap of {gap}");
    assert!((side(knot, Side::Right) - joint).norm() < 1e-12, "the joint stays");
    let (lo, hi) = (before.centre(2), before.centre(4));
    let mid = |a: f64, b: f64| 0.5 * (a + b);
    assert!((now.point(mid(lo, knot)) - before.point(mid(lo, knot))).norm() < 1e-12, "left of the joint: unchanged");
    assert!((now.point(mid(knot, hi)) - before.point(mid(knot, hi))).norm() > 1e-3, "the copy's side moved");
    // The handle followed the cursor (to a pixel or so: a turn in the view plane).
    let projector = self::projector(studio);
    let moved = copy(studio, 4).expect("right copy");
    let (mp, _) = projector.project(moved.position).expect("in view");
    assert!(
        (mp[0] - rp[0] - 40.0).hypot(mp[1] - rp[1] + 20.0) < 2.0,
        "the handle at {mp:?}, cursor at {:?}",
        [rp[0] + 40.0, rp[1] - 20.0]
    );
    studio.undo();
    assert_eq!(studio.document.scene().to_value(), split, "the drag is one undo step");
}

/// At the heart's bottom cusp (knot 5) the quadratic local is symmetric about its knot:
/// the copies' handles (a third and half of the way to the neighbouring knots) are still
/// apart, drawn with a line to the joint, and each is picked by a click on it.
#[test]
fn the_copies_at_a_cusp_are_picked_apart() {
    let mut studio = open_selected("heart_local_curves.json");
    let edit =
        splinekit_studio::knot_split::split_local(&studio.document.scene().objects[0].shape, 0, 5).expect("splits");
    assert!(studio.edit(edit, false));
    let rs: RenderScene = studio.render_scene((600, 600), true).expect("composes");
    let projector = Projector::new(&rs, (600, 600));
    for k in [5, 6] {
        let h = studio.shown_handles().find(|h| h.kind == HandleKind::LocalCurve(k)).cloned().expect("a copy");
        // Drawn (the renderer marks origins only), with a line to the joint.
        let f = |p: [f64; 3]| p.map(|x| x as f32);
        assert!(rs.points.iter().any(|p| p.position == f(h.position)), "copy {k}'s handle drawn");
        let joint = f(h.pivot.expect("a copy"));
        assert!(rs.lines.iter().any(|l| l.points == [joint, f(h.position)]), "copy {k}'s line to the joint");
        let (px, _) = projector.project(h.position).expect("in view");
        assert_eq!(studio.pick(&projector, px).map(|h| h.kind), Some(HandleKind::LocalCurve(k)), "copy {k} at {px:?}");
    }
}

#[test]
fn the_panel_the_key_and_the_edit_menu_arm_the_tool() {
    let (tool, action) = (KnotTool::SplitKnot, Action::SplitKnot);
    assert_armed_from_the_window("heart_local_curves.json", tool, action, egui::Key::D, "Split knot  D");
}
