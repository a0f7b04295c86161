//! The help overlay (`?`): every action of the registry with its keys, and the keys held
//! during a drag in the 3-D view.

use crate::actions::{ACTIONS, HELD_KEYS, key_text};

/// The help window, shown while `open`; its close button clears `open`.
pub fn help_overlay(ctx: &egui::Context, open: &mut bool) {
    egui::Window::new("Keys and actions").open(open).collapsible(false).resizable(false).show(ctx, |ui| {
        egui::Grid::new("help").striped(true).show(ui, |ui| {
            for s in ACTIONS {
                let keys: Vec<String> = s.keys.iter().map(|&(m, k)| key_text(m, k)).collect();
                ui.label(keys.join(", "));
                ui.label(s.label);
                ui.label(if s.undoable { format!("{} (undoable)", s.help) } else { s.help.to_string() });
                ui.end_row();
            }
            for (keys, what) in HELD_KEYS {
                ui.label(*keys);
                ui.label("");
                ui.label(*what);
                ui.end_row();
            }
        });
    });
}
