//! What the tests of the knot tools armed from the window share (local insertion, knot
//! split): the example scenes opened in a studio, the view's projector, a harness frame as
//! the window runs it, the blending-spline curve a document builds, the check that the
//! Properties panel, a key and the Edit menu arm a tool, and a studio with a tool armed,
//! checked to stay armed after a click off the shape.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use serde_json::Value;
use splinekit::blend::BlendingSplineCurve;
use splinekit_render::RenderScene;
use splinekit_scene::{CurveDocument, ShapeDocument};
use splinekit_studio::actions::{self, Action, menu_label};
use splinekit_studio::knot_edit::KnotTool;
use splinekit_studio::panels::{FileFields, menu_bar, properties_panel};
use splinekit_studio::studio::Studio;
use splinekit_studio::view_camera::Projector;

/// A studio on `examples/scenes/{name}`.
pub fn open(name: &str) -> Studio {
    let path = format!("{}/../../examples/scenes/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(path).expect("the example");
    Studio::new(splinekit_studio::document::parse(&text).expect("valid"), None)
}

/// A studio on `examples/scenes/{name}` with object 0 selected.
pub fn open_selected(name: &str) -> Studio {
    let mut studio = open(name);
    studio.selection.object = Some(0);
    studio
}

/// The projector of a 600 × 600 view, the view caches (handles) composed afresh.
pub fn projector(studio: &mut Studio) -> Projector {
    let rs: RenderScene = studio.render_scene((600, 600), false).expect("composes");
    Projector::new(&rs, (600, 600))
}

/// A harness frame as the window runs it: the Properties panel, the shortcuts pressed, the
/// commands.
pub fn frame(ui: &mut egui::Ui, s: &mut Studio) {
    properties_panel(ui, s);
    for a in actions::pressed(ui.ctx()) {
        s.run_action(a);
    }
    s.run_commands();
}

/// The blending-spline curve that object `object` of the studio's document builds.
pub fn blending_curve(studio: &Studio, object: usize) -> BlendingSplineCurve<3> {
    match &studio.document.scene().objects[object].shape {
        ShapeDocument::Curve(CurveDocument::BlendingSpline(d)) => d.curve::<3>().expect("builds"),
        _ => panic!("a blending spline"),
    }
}

/// With object 0 of `examples/scenes/{scene}` selected (no handle), each way the window
/// offers arms `tool`: the Properties panel's button of `action`, the key `key`, and the
/// Edit menu's entry, which reads `menu` (the action's label and key).
pub fn assert_armed_from_the_window(scene: &str, tool: KnotTool, action: Action, key: egui::Key, menu: &str) {
    assert_eq!(menu_label(action), menu);
    let label = actions::spec(action).label;
    let mut h = Harness::new_ui_state(frame, open_selected(scene));
    h.run();
    h.get_by_label(label).click();
    h.run();
    assert_eq!(h.state().knot_tool, Some(tool), "the panel's {label}");
    let mut h = Harness::new_ui_state(frame, open_selected(scene));
    h.run();
    h.key_press(key);
    h.run();
    assert_eq!(h.state().knot_tool, Some(tool), "the key {key:?}");
    let mut h = Harness::new_ui_state(
        |ui, state: &mut (Studio, FileFields)| {
            let (studio, files) = state;
            if let Some(command) = menu_bar(ui, files, &[]) {
                studio.queue(command);
            }
            studio.run_commands();
        },
        (open_selected(scene), FileFields::default()),
    );
    h.run();
    h.get_by_label("Edit").click();
    h.run();
    h.get_by_label(menu).click();
    h.run();
    assert_eq!(h.state().0.knot_tool, Some(tool), "the Edit menu's {menu}");
}

/// A studio on `examples/scenes/{scene}` with object 0 selected (no handle) and `action`
/// run, which arms `tool`; a click off the shape (at pixel (1, 1)) keeps the tool armed and
/// the document as it was. Returns the studio, its view's projector and the document.
pub fn armed(scene: &str, action: Action, tool: KnotTool) -> (Studio, Projector, Value) {
    let mut studio = open_selected(scene);
    let projector = projector(&mut studio);
    let original = studio.document.scene().to_value();
    studio.run_action(action);
    assert_eq!(studio.knot_tool, Some(tool), "no handle selected: {action:?} arms the tool");
    studio.knot_click(tool, &projector, [1.0, 1.0], false);
    assert_eq!(studio.document.scene().to_value(), original, "a click off the shape keeps the document");
    assert_eq!(studio.knot_tool, Some(tool), "and the tool armed");
    (studio, projector, original)
}
