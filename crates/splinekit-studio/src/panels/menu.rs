//! The menu bar: File (open a path, save), Edit (undo, redo), View (standard views, home,
//! frame the selection, the frame-time overlay).

use crate::view_camera::StandardView;

/// What the menu asked for (carried out by the window, which owns the camera and files).
#[derive(Debug, Clone, PartialEq)]
pub enum MenuAction {
    /// Open the document at this path.
    Open(String),
    /// Save (Ctrl+S).
    Save,
    /// Export the selected object to this mesh file.
    Export(String),
    /// Undo (Ctrl+Z).
    Undo,
    /// Redo (Ctrl+Shift+Z).
    Redo,
    /// Look from a standard direction.
    Look(StandardView),
    /// Back to the first camera (Home).
    Home,
    /// Frame the selection (F).
    Frame,
    /// Save a screenshot of the 3-D view (F12).
    Screenshot,
    /// Close the window.
    Quit,
}

/// The text fields of the File menu.
#[derive(Debug, Clone, Default)]
pub struct FileFields {
    /// File → Open's path.
    pub open: String,
    /// File → Export's path (its extension picks the format).
    pub export: String,
}

/// The menu bar; `files` holds File's path fields, `overlay` the frame-time overlay toggle.
pub fn menu_bar(ui: &mut egui::Ui, files: &mut FileFields, overlay: &mut bool) -> Option<MenuAction> {
    let mut action = None;
    egui::MenuBar::new().ui(ui, |ui| {
        ui.menu_button("File", |ui| {
            ui.label("Open a scene or shape document:");
            let field = ui.text_edit_singleline(&mut files.open);
            if ui.button("Open").clicked() || field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)) {
                action = Some(MenuAction::Open(files.open.clone()));
            }
            ui.separator();
            ui.label("Export the selected object (.obj .stl .stla .ply .gltf .glb):");
            ui.text_edit_singleline(&mut files.export);
            if ui.button("Export").clicked() {
                action = Some(MenuAction::Export(files.export.clone()));
            }
            ui.separator();
            for (label, a) in [
                ("Save  Ctrl+S", MenuAction::Save),
                ("Screenshot  F12", MenuAction::Screenshot),
                ("Quit  Ctrl+Q", MenuAction::Quit),
            ] {
                if ui.button(label).clicked() {
                    action = Some(a);
                }
            }
        });
        ui.menu_button("Edit", |ui| {
            for (label, a) in [("Undo  Ctrl+Z", MenuAction::Undo), ("Redo  Ctrl+Shift+Z", MenuAction::Redo)] {
                if ui.button(label).clicked() {
                    action = Some(a);
                }
            }
        });
        ui.menu_button("View", |ui| {
            let views = [
                ("Top  7", MenuAction::Look(StandardView::Top)),
                ("Front  1", MenuAction::Look(StandardView::Front)),
                ("Side  3", MenuAction::Look(StandardView::Side)),
                ("Home", MenuAction::Home),
                ("Frame selection  F", MenuAction::Frame),
            ];
            for (label, a) in views {
                if ui.button(label).clicked() {
                    action = Some(a);
                }
            }
            ui.checkbox(overlay, "frame time");
        });
    });
    action
}
