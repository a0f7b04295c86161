//! The panels driven through egui's own test harness (egui_kittest): clicks on the
//! Properties and Objects panels become edits of the document, undoable like any other.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use splinekit_scene::ShapeDocument;
use splinekit_studio::panels::{objects_panel, properties_panel};
use splinekit_studio::studio::Studio;

/// A harness frame: the panel drawn, then the commands it queued run (as the window does).
fn panel(draw: fn(&mut egui::Ui, &mut Studio)) -> impl FnMut(&mut egui::Ui, &mut Studio) {
    move |ui, s| {
        draw(ui, s);
        assert!(s.run_commands().is_empty(), "panels ask for no window actions");
    }
}

/// Clicks the widget labelled `label` and runs the frame that follows.
fn click(h: &mut Harness<'_, Studio>, label: &str) {
    h.get_by_label(label).click();
    h.run();
}

fn heart() -> Studio {
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/scenes/heart_local_curves.json"))
            .expect("the example");
    let mut studio = Studio::new(splinekit_studio::document::parse(&text).expect("valid"), None);
    studio.selection.object = Some(0);
    studio
}

fn bfunction(studio: &Studio) -> String {
    let ShapeDocument::Curve(c) = &studio.document.scene().objects[0].shape else { panic!("a curve") };
    c.to_value()["bfunction"]["type"].as_str().unwrap_or("erbs (default)").to_string()
}

#[test]
fn properties_toggle_styles_and_switch_the_bfunction_and_back() {
    let mut h = Harness::new_ui_state(panel(properties_panel), heart());
    h.run();
    click(&mut h, "control polygon / net");
    assert!(h.state().document.scene().objects[0].style.control_net);
    assert_eq!(bfunction(h.state()), "erbs (default)");
    click(&mut h, "B-function");
    click(&mut h, "trigonometric");
    assert_eq!(bfunction(h.state()), "trigonometric");
    // The ERBS parameters are gone from the panel; undo brings ERBS back.
    assert!(h.query_by_label("alpha").is_none());
    h.state_mut().undo();
    h.run();
    assert_eq!(bfunction(h.state()), "erbs (default)");
    assert!(h.query_by_label("alpha").is_some());
}

#[test]
fn objects_are_duplicated_and_deleted_from_the_panel() {
    let mut h = Harness::new_ui_state(panel(objects_panel), heart());
    h.run();
    click(&mut h, "Duplicate");
    assert_eq!(h.state().document.scene().objects.len(), 2);
    assert_eq!(h.state().selection.object, Some(1));
    click(&mut h, "Delete");
    assert_eq!(h.state().document.scene().objects.len(), 1);
    // The last object cannot go: the library's message, the document unchanged.
    h.state_mut().selection.object = Some(0);
    h.run();
    click(&mut h, "Delete");
    assert_eq!(h.state().document.scene().objects.len(), 1);
    let message = h.state().status.message.clone().unwrap_or_default();
    assert!(message.contains("objects"), "{message}");
}

#[test]
fn the_knot_style_switches_at_once_and_undoes_in_one_step() {
    let text = r#"{"type": "bspline", "degree": 2, "knots": [0, 0, 0, 1, 2, 2, 2],
        "control_points": [[0, 0], [1, 1], [2, 0], [3, 1]]}"#;
    let mut studio = Studio::new(splinekit_studio::document::parse(text).expect("valid"), None);
    studio.selection.object = Some(0);
    let mut h = Harness::new_ui_state(panel(properties_panel), studio);
    h.run();
    let shape = |s: &Studio| s.document.scene().objects[0].to_value()["shape"].clone();
    click(&mut h, "knots");
    click(&mut h, "periodic");
    assert_eq!(shape(h.state())["periodic"], serde_json::json!(true));
    assert_eq!(shape(h.state())["knots"].as_array().map(Vec::len), Some(7));
    click(&mut h, "knots");
    click(&mut h, "clamped");
    assert!(shape(h.state()).get("periodic").is_none());
    h.state_mut().undo();
    h.run();
    assert_eq!(shape(h.state())["periodic"], serde_json::json!(true));
}
