//! What the tests of the knot tools armed from the window share (local insertion, knot
//! split): the example scenes opened in a studio, the view's projector, a harness frame as
//! the window runs it, and the checks that a key and the Edit menu arm a tool.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use splinekit_render::RenderScene;
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

/// With object 0 of `examples/scenes/{scene}` selected, the Edit menu's entry `label` arms
/// `tool`.
pub fn assert_edit_menu_arms(scene: &str, label: &str, tool: KnotTool) {
    let mut studio = open(scene);
    studio.selection.object = Some(0);
    let mut h = Harness::new_ui_state(
        |ui, state: &mut (Studio, FileFields)| {
            let (studio, files) = state;
            if let Some(command) = menu_bar(ui, files, &[]) {
                studio.queue(command);
            }
            studio.run_commands();
        },
        (studio, FileFields::default()),
    );
    h.run();
    h.get_by_label("Edit").click();
    h.run();
    h.get_by_label(label).click();
    h.run();
    assert_eq!(h.state().0.knot_tool, Some(tool));
}

/// The key `key` arms `tool` in the harness, and the Edit menu lists `action` as `label`
/// (with that key).
pub fn assert_key_arms(h: &mut Harness<'_, Studio>, key: egui::Key, tool: KnotTool, action: Action, label: &str) {
    h.key_press(key);
    h.run();
    assert_eq!(h.state().knot_tool, Some(tool));
    assert_eq!(menu_label(action), label);
}
