//! Selections of several handles without a window (issue 22): a box selects the handles
//! inside it, a drag of one moves all of them by the same displacement as one undo step,
//! turns and scalings go about the centroid, arrow-key nudges move by the snapping step,
//! and a snapped drag lands on the grid.

use serde_json::{Value, json};
use splinekit_render::RenderScene;
use splinekit_studio::actions::Action;
use splinekit_studio::gesture::GestureKind;
use splinekit_studio::handles::HandleKind;
use splinekit_studio::studio::Studio;
use splinekit_studio::view_camera::Projector;

const CURVE: &str = r#"{"type": "scene", "objects": [{"shape": {"type": "bspline", "degree": 2,
    "knots": [0, 0, 0, 1, 2, 3, 3, 3], "control_points": [[0, 0], [1, 2], [2, -1], [3, 2], [4, 0]]},
    "control_net": true}], "size": [600, 600]}"#;

fn studio() -> (Studio, Projector) {
    let mut studio = Studio::new(splinekit_studio::document::parse(CURVE).expect("valid"), None);
    let rs: RenderScene = studio.render_scene((600, 600), false).expect("composes");
    (studio, Projector::new(&rs, (600, 600)))
}

fn points(studio: &Studio) -> Vec<[f64; 2]> {
    serde_json::from_value(studio.document.scene().objects[0].to_value()["shape"]["control_points"].clone())
        .expect("points")
}

fn px(projector: &Projector, studio: &Studio, i: usize) -> [f64; 2] {
    let h =
        studio.view.handles.iter().find(|h| h.kind == HandleKind::ControlPoint(i, "control_points")).expect("shown");
    projector.project(h.position).expect("in view").0
}

/// The box around control points 1, 2 and 3 (not 0 and 4).
fn box_select_middle(studio: &mut Studio, projector: &Projector) {
    let (a, b) = (px(projector, studio, 1), px(projector, studio, 3));
    let c = px(projector, studio, 2);
    let lo = [a[0].min(c[0]) - 5.0, a[1].min(b[1]).min(c[1]) - 5.0];
    let hi = [b[0].max(c[0]) + 5.0, a[1].max(b[1]).max(c[1]) + 5.0];
    studio.box_select(projector, lo, hi, false);
    assert_eq!(studio.selection.handles.len(), 3, "{:?}", studio.selection.handles);
}

#[test]
fn a_boxed_selection_moves_together_in_one_undo_step() {
    let (mut studio, projector) = studio();
    let before = points(&studio);
    box_select_middle(&mut studio, &projector);
    let p = px(&projector, &studio, 2);
    assert!(studio.begin_drag(&projector, p, GestureKind::Move(None)));
    for k in 1..=5 {
        studio.drag_to(&projector, [p[0] + 6.0 * k as f64, p[1] - 4.0 * k as f64]);
    }
    studio.end_drag();
    let after = points(&studio);
    let d = [after[2][0] - before[2][0], after[2][1] - before[2][1]];
    assert!(d[0] > 0.1 && d[1] > 0.1, "{d:?}");
    for i in 1..=3 {
        assert!((after[i][0] - before[i][0] - d[0]).abs() < 1e-12 && (after[i][1] - before[i][1] - d[1]).abs() < 1e-12);
    }
    assert_eq!((after[0], after[4]), (before[0], before[4]), "the others stay");
    assert_eq!(studio.selection.handles.len(), 3, "still selected");
    studio.undo();
    assert_eq!(points(&studio), before, "one undo step");
}

#[test]
fn a_selection_turns_and_scales_about_its_centroid() {
    let (mut studio, projector) = studio();
    let before = points(&studio);
    box_select_middle(&mut studio, &projector);
    let centroid = |ps: &[[f64; 2]]| [0, 1].map(|k| (ps[1][k] + ps[2][k] + ps[3][k]) / 3.0);
    let c = studio.selection.centroid().expect("a centroid");
    let (cp, _) = projector.project(c).expect("in view");
    // Scale: grab point 3, move away from the centroid's screen position to twice the distance.
    let p = px(&projector, &studio, 3);
    assert!(studio.begin_drag(&projector, p, GestureKind::Scale));
    studio.drag_to(&projector, [cp[0] + 2.0 * (p[0] - cp[0]), cp[1] + 2.0 * (p[1] - cp[1])]);
    studio.end_drag();
    let scaled = points(&studio);
    let c0 = centroid(&before);
    assert!((0..2).all(|k| (centroid(&scaled)[k] - c0[k]).abs() < 1e-9), "the centroid stays");
    for i in 1..=3 {
        for k in 0..2 {
            let want = c0[k] + 2.0 * (before[i][k] - c0[k]);
            assert!((scaled[i][k] - want).abs() < 1e-6, "point {i}: {:?} vs {want}", scaled[i]);
        }
    }
    studio.undo();
    // A quarter turn about the centroid keeps the distances from it.
    let p = px(&projector, &studio, 3);
    assert!(studio.begin_drag(&projector, p, GestureKind::Rotate));
    let r = (p[0] - cp[0]).hypot(p[1] - cp[1]);
    let a = (p[1] - cp[1]).atan2(p[0] - cp[0]) - std::f64::consts::FRAC_PI_2;
    studio.drag_to(&projector, [cp[0] + r * a.cos(), cp[1] + r * a.sin()]);
    studio.end_drag();
    let turned = points(&studio);
    for i in 1..=3 {
        let d = |q: [f64; 2]| (q[0] - c0[0]).hypot(q[1] - c0[1]);
        assert!((d(turned[i]) - d(before[i])).abs() < 1e-6, "point {i}");
        let dot = (turned[i][0] - c0[0]) * (before[i][0] - c0[0]) + (turned[i][1] - c0[1]) * (before[i][1] - c0[1]);
        assert!(dot.abs() < 1e-6, "a quarter turn: point {i}");
    }
}

#[test]
fn shift_click_adds_and_removes_and_a_selects_all_and_escape_clears() {
    let (mut studio, projector) = studio();
    let pick = |s: &Studio, i| s.pick(&projector, px(&projector, s, i));
    studio.click(pick(&studio, 0), false);
    studio.click(pick(&studio, 4), true);
    assert_eq!(studio.selection.handles.len(), 2);
    studio.click(pick(&studio, 0), true);
    assert_eq!(studio.selection.handles.len(), 1);
    assert_eq!(studio.selection.handle.as_ref().map(|h| h.kind), Some(HandleKind::ControlPoint(4, "control_points")));
    studio.run_action(Action::SelectAll);
    assert_eq!(studio.selection.handles.len(), 5);
    studio.run_action(Action::ClearSelection);
    assert!(studio.selection.handles.is_empty() && studio.selection.handle.is_none());
}

#[test]
fn arrow_keys_nudge_by_the_step_and_a_snapped_drag_lands_on_the_grid() {
    let (mut studio, projector) = studio();
    let before = points(&studio);
    box_select_middle(&mut studio, &projector);
    studio.snapping.step = 0.25;
    studio.run_action(Action::Nudge(0, 1));
    studio.run_action(Action::Nudge(1, -10));
    let after = points(&studio);
    for i in 1..=3 {
        assert!((after[i][0] - before[i][0] - 0.25).abs() < 1e-12 && (after[i][1] - before[i][1] + 2.5).abs() < 1e-12);
    }
    studio.undo();
    studio.undo();
    assert_eq!(points(&studio), before, "each nudge one step");
    // One point dragged with the grid on lands on a multiple of the step.
    studio.snapping.grid = true;
    studio.snapping.step = 0.5;
    let p = px(&projector, &studio, 0);
    assert!(studio.begin_drag(&projector, p, GestureKind::Move(None)));
    studio.drag_to(&projector, [p[0] + 37.0, p[1] - 23.0]);
    studio.end_drag();
    let q = points(&studio)[0];
    for x in q {
        assert!((x / 0.5 - (x / 0.5).round()).abs() < 1e-9, "{q:?}");
    }
    assert_ne!(q, before[0]);
    let shape: Value = studio.document.scene().objects[0].to_value()["shape"].clone();
    assert_eq!(shape["control_points"][1], json!(before[1]), "only the dragged point moved");
}
