//! The menu bar, drawn from the action registry ([`crate::actions::ACTIONS`]): File (the
//! open and export path fields, then its actions), Edit and View, each entry with its
//! shortcut.

use crate::actions::{ACTIONS, Action, Menu, menu_label};
use crate::command::Command;

/// The text fields of the File menu.
#[derive(Debug, Clone, Default)]
pub struct FileFields {
    /// File → Open's path.
    pub open: String,
    /// File → Export's path (its extension picks the format).
    pub export: String,
}

/// The registry's actions of `menu` as buttons (toggles in `on` as checkboxes showing
/// their state); the one clicked.
fn entries(ui: &mut egui::Ui, menu: Menu, on: &[(Action, bool)]) -> Option<Command> {
    let mut clicked = None;
    for s in ACTIONS.iter().filter(|s| s.menu == Some(menu)) {
        let response = match on.iter().find(|(a, _)| *a == s.action) {
            Some(&(_, mut state)) => ui.checkbox(&mut state, menu_label(s.action)),
            None => ui.button(menu_label(s.action)),
        };
        if response.on_hover_text(s.help).clicked() {
            clicked = Some(Command::Action(s.action));
        }
    }
    clicked
}

/// The menu bar; `files` holds File's path fields, `on` the state of toggled actions (the
/// frame-time overlay, …). Returns the command asked for.
pub fn menu_bar(ui: &mut egui::Ui, files: &mut FileFields, on: &[(Action, bool)]) -> Option<Command> {
    let mut command = None;
    egui::MenuBar::new().ui(ui, |ui| {
        ui.menu_button("File", |ui| {
            ui.label("Open a scene or shape document:");
            let field = ui.text_edit_singleline(&mut files.open);
            if ui.button("Open").clicked() || field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)) {
                command = Some(Command::Open(files.open.clone()));
            }
            ui.separator();
            ui.label("Export the selected object (.obj .stl .stla .ply .gltf .glb):");
            ui.text_edit_singleline(&mut files.export);
            if ui.button("Export").clicked() {
                command = Some(Command::Export(files.export.clone()));
            }
            ui.separator();
            command = entries(ui, Menu::File, on).or(command.take());
        });
        for (name, menu) in [("Edit", Menu::Edit), ("View", Menu::View)] {
            ui.menu_button(name, |ui| {
                command = entries(ui, menu, on).or(command.take());
            });
        }
    });
    command
}
