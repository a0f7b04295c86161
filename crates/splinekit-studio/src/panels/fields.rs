//! Field widgets bound to a JSON pointer of the selected object's document: a change is
//! one edit (queued as a command); a refused change shows the library's message under the
//! field.

use serde_json::Value;

use super::context::PanelContext;
use crate::command::{Command, FieldEdit};
use crate::edit::Edit;

/// The value at `pointer` of object `object`'s document.
pub fn read(cx: &PanelContext<'_>, object: usize, pointer: &str) -> Option<Value> {
    cx.scene.objects.get(object)?.to_value().pointer(pointer).cloned()
}

/// Asks to set the value at `pointer` (a refusal's message is shown under that field).
pub fn write(cx: &mut PanelContext<'_>, object: usize, pointer: &str, value: Option<Value>) {
    let edit = Edit::Set { object, pointer: pointer.into(), value };
    cx.queue(Command::Edit(FieldEdit::of_field(edit, pointer)));
}

/// The message under a field, when its last change was refused.
pub fn error_label(ui: &mut egui::Ui, cx: &PanelContext<'_>, pointer: &str) {
    if let Some((p, m)) = &cx.status.field_error
        && p == pointer
    {
        ui.colored_label(egui::Color32::from_rgb(200, 40, 40), m);
    }
}

/// A checkbox for a boolean field (missing: `default`).
pub fn toggle(ui: &mut egui::Ui, cx: &mut PanelContext<'_>, object: usize, pointer: &str, label: &str, default: bool) {
    let mut on = read(cx, object, pointer).and_then(|v| v.as_bool()).unwrap_or(default);
    if ui.checkbox(&mut on, label).changed() {
        write(cx, object, pointer, Some(on.into()));
    }
    error_label(ui, cx, pointer);
}

/// A whole-number field; the value is applied when it changes.
pub fn count(ui: &mut egui::Ui, cx: &mut PanelContext<'_>, object: usize, pointer: &str, label: &str, default: u64) {
    let n = read(cx, object, pointer).and_then(|v| v.as_u64()).unwrap_or(default);
    drag_field(ui, cx, object, pointer, label, n, |drag| drag.range(0..=4096).speed(0.1));
}

/// A real-number field.
pub fn number(ui: &mut egui::Ui, cx: &mut PanelContext<'_>, object: usize, pointer: &str, label: &str, default: f64) {
    let x = read(cx, object, pointer).and_then(|v| v.as_f64()).unwrap_or(default);
    drag_field(ui, cx, object, pointer, label, x, |drag| drag.speed(0.01));
}

/// A labelled drag value showing `value`, set up by `drag` (range, speed); a change is
/// written to `pointer`, and a refused one's message shown under the field.
fn drag_field<T: egui::emath::Numeric + Into<Value>>(
    ui: &mut egui::Ui,
    cx: &mut PanelContext<'_>,
    object: usize,
    pointer: &str,
    label: &str,
    mut value: T,
    drag: impl FnOnce(egui::DragValue<'_>) -> egui::DragValue<'_>,
) {
    let changed = ui.horizontal(|ui| {
        let name = ui.label(label);
        ui.add(drag(egui::DragValue::new(&mut value))).labelled_by(name.id).changed()
    });
    if changed.inner {
        write(cx, object, pointer, Some(value.into()));
    }
    error_label(ui, cx, pointer);
}
