//! Knot and weight edits from the window, without a window (issue 22): the Properties
//! panel's Insert knot arms the tool, a click on the curve inserts a knot there with the
//! curve unchanged (one undo step), E raises the degree, a W-drag changes one weight.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use serde_json::Value;
use splinekit_render::RenderScene;
use splinekit_studio::actions::Action;
use splinekit_studio::gesture::GestureKind;
use splinekit_studio::handles::HandleKind;
use splinekit_studio::knot_edit::{KnotTool, curve_samples};
use splinekit_studio::panels::properties_panel;
use splinekit_studio::studio::Studio;
use splinekit_studio::view_camera::Projector;

const NURBS: &str = r#"{"type": "scene", "objects": [{"shape": {"type": "nurbs", "degree": 2,
    "knots": [0, 0, 0, 1, 2, 2, 2], "control_points": [[0, 0], [1, 2], [3, -1], [4, 1]],
    "weights": [1, 0.7, 2, 1]}, "control_net": true}], "size": [600, 600]}"#;

/// The studio on the document `json` with its first object selected, and the projector
/// of its 600 × 600 view.
fn studio_on(json: &str) -> (Studio, Projector) {
    let mut studio = Studio::new(splinekit_studio::document::parse(json).expect("valid"), None);
    studio.selection.object = Some(0);
    let rs: RenderScene = studio.render_scene((600, 600), false).expect("composes");
    (studio, Projector::new(&rs, (600, 600)))
}

fn studio() -> (Studio, Projector) {
    studio_on(NURBS)
}

/// The Properties panel over `studio`, its commands run each frame, after a first frame.
fn panel(studio: Studio) -> Harness<'static, Studio> {
    let mut h = Harness::new_ui_state(
        |ui, s: &mut Studio| {
            properties_panel(ui, s);
            s.run_commands();
        },
        studio,
    );
    h.run();
    h
}

/// Clicks Insert knot in the panel: the tool is armed.
fn arm_insert(h: &mut Harness<'static, Studio>) {
    h.get_by_label("Insert knot").click();
    h.run();
    assert_eq!(h.state().knot_tool, Some(KnotTool::Insert));
}

fn shape(studio: &Studio) -> Value {
    studio.document.scene().objects[0].to_value()["shape"].clone()
}

fn samples(studio: &Studio) -> Vec<(f64, [f64; 3])> {
    curve_samples(&studio.document.scene().objects[0].shape, 300).expect("samples")
}

#[test]
fn the_panel_arms_the_tool_and_a_click_on_the_curve_inserts_a_knot_there() {
    let (studio, projector) = studio();
    let before = samples(&studio);
    let mut h = panel(studio);
    arm_insert(&mut h);
    let studio = h.state_mut();
    // A click off the curve keeps the tool; one on the curve at t ≈ 1.4 inserts there.
    studio.knot_click(KnotTool::Insert, &projector, [1.0, 1.0], false);
    assert_eq!(shape(studio)["knots"].as_array().map(Vec::len), Some(7));
    let (t, p) = before[210];
    let (px, _) = projector.project(p).expect("in view");
    studio.knot_click(KnotTool::Insert, &projector, px, false);
    let knots: Vec<f64> = serde_json::from_value(shape(studio)["knots"].clone()).expect("knots");
    assert_eq!(knots.len(), 8);
    assert!(knots.iter().any(|k| (k - t).abs() < 0.01), "{knots:?} has {t}");
    for ((_, a), (_, b)) in before.iter().zip(samples(studio)) {
        assert!((0..3).all(|k| (a[k] - b[k]).abs() < 1e-12), "the curve is unchanged");
    }
    studio.undo();
    assert_eq!(shape(studio)["knots"].as_array().map(Vec::len), Some(7), "one undo step");
    studio.run_action(Action::ElevateDegree);
    assert_eq!(shape(studio)["degree"], serde_json::json!(3));
    for ((_, a), (_, b)) in before.iter().zip(samples(studio)) {
        assert!((0..3).all(|k| (a[k] - b[k]).abs() < 1e-9), "the curve is unchanged");
    }
}

#[test]
fn a_w_drag_changes_one_weight_and_the_panel_shows_it() {
    let (mut studio, projector) = studio();
    let h =
        studio.view.handles.iter().find(|h| h.kind == HandleKind::ControlPoint(1, "control_points")).expect("shown");
    let (p, _) = projector.project(h.position).expect("in view");
    assert!(studio.begin_drag(&projector, p, GestureKind::Weight));
    studio.drag_to(&projector, [p[0], p[1] - 100.0]);
    studio.end_drag();
    let w: Vec<f64> = serde_json::from_value(shape(&studio)["weights"].clone()).expect("weights");
    assert!((w[1] - 0.7 * std::f64::consts::E).abs() < 1e-12, "{w:?}");
    assert_eq!((w[0], w[2], w[3]), (1.0, 2.0, 1.0));
    assert_eq!(shape(&studio)["control_points"][1], serde_json::json!([1.0, 2.0]), "the point stays");
    let mut h = Harness::new_ui_state(|ui, s: &mut Studio| properties_panel(ui, s), studio);
    h.run();
    assert!(h.query_by_label("weight").is_some());
}

const NET: &str = r#"{"type": "scene", "objects": [{"shape": {"type": "bspline_surface",
    "degree_u": 2, "degree_v": 3, "knots_u": [0, 0, 0, 1, 1, 1], "knots_v": [0, 0, 0, 0, 1, 1, 1, 1],
    "control_points": [[[0, 0, 0], [0, 1, 0.5], [0, 2, 0.5], [0, 3, 0]],
                       [[1, 0, 0.5], [1, 1, 2], [1, 2, 1.5], [1, 3, 0.5]],
                       [[2, 0, 0], [2, 1, 0.5], [2, 2, 0.5], [2, 3, 0]]]}, "control_net": true}],
    "size": [600, 600]}"#;

/// Rows of ((u, v), world point) samples.
type Grid = Vec<Vec<((f64, f64), [f64; 3])>>;

fn net_samples(studio: &Studio) -> Grid {
    splinekit_studio::net_knot_edit::surface_samples(&studio.document.scene().objects[0].shape, 40).expect("samples")
}

fn knots(studio: &Studio, field: &str) -> Vec<f64> {
    serde_json::from_value(shape(studio)[field].clone()).expect("knots")
}

#[test]
fn on_a_spline_surface_a_click_inserts_a_u_knot_and_a_shift_click_a_v_knot() {
    let (studio, projector) = studio_on(NET);
    let before = net_samples(&studio);
    let mut h = panel(studio);
    assert!(h.query_by_label("Remove knot").is_none(), "a surface offers insertion only");
    arm_insert(&mut h);
    let studio = h.state_mut();
    // Sample (14, 25) of the 40 × 40 grid: (u, v) = (0.35, 0.625).
    let ((u, v), p) = before[14][25];
    let (px, _) = projector.project(p).expect("in view");
    studio.knot_click(KnotTool::Insert, &projector, px, false);
    let ku = knots(studio, "knots_u");
    assert_eq!(ku.len(), 7, "{ku:?}");
    assert!(ku.iter().any(|k| (k - u).abs() < 0.01), "{ku:?} has {u}");
    assert_eq!(knots(studio, "knots_v").len(), 8, "v untouched");
    let same = |studio: &Studio| {
        for (ra, rb) in before.iter().zip(net_samples(studio)) {
            for ((_, a), (_, b)) in ra.iter().zip(rb) {
                assert!((0..3).all(|k| (a[k] - b[k]).abs() < 1e-12), "the surface is unchanged");
            }
        }
    };
    same(studio);
    studio.run_action(Action::InsertKnot);
    studio.knot_click(KnotTool::Insert, &projector, px, true);
    let kv = knots(studio, "knots_v");
    assert_eq!(kv.len(), 9, "{kv:?}");
    assert!(kv.iter().any(|k| (k - v).abs() < 0.01), "{kv:?} has {v}");
    same(studio);
    studio.undo();
    assert_eq!((knots(studio, "knots_u").len(), knots(studio, "knots_v").len()), (7, 8), "one undo step each");
    studio.run_action(Action::ElevateDegree);
    assert!(studio.status.message.as_deref().is_some_and(|m| m.contains("curves")), "{:?}", studio.status.message);
}
