//! The Objects panel: the scene's objects with visibility and selection; add a shape of
//! any kind of the format (its example document), a blending spline of any model curve or
//! surface; duplicate and delete.

use serde_json::json;
use splinekit_scene::scenes::SceneObject;
use splinekit_scene::{CurveDocument, SurfaceDocument};

use super::context::PanelContext;
use super::fields::{read, write};
use crate::command::{Command, FieldEdit};
use crate::edit::Edit;
use crate::studio::Studio;

/// The Objects panel.
pub fn objects_panel(ui: &mut egui::Ui, studio: &mut Studio) {
    objects(ui, &mut PanelContext::of(studio));
}

/// The Objects panel.
fn objects(ui: &mut egui::Ui, cx: &mut PanelContext<'_>) {
    ui.heading("Objects");
    for i in 0..cx.scene.objects.len() {
        let ty = read(cx, i, "/shape/type").and_then(|v| v.as_str().map(String::from)).unwrap_or_default();
        ui.horizontal(|ui| {
            let hidden = read(cx, i, "/hidden").and_then(|v| v.as_bool()).unwrap_or(false);
            let mut visible = !hidden;
            if ui.checkbox(&mut visible, "").on_hover_text("visible").changed() {
                write(cx, i, "/hidden", Some((!visible).into()));
            }
            let label = ui.selectable_label(cx.selection.object == Some(i), format!("{i}: {ty}"));
            cx.widgets.push((format!("object {i}"), super::rect(&label)));
            if label.clicked() {
                cx.queue(Command::SelectObject(Some(i)));
            }
        });
    }
    ui.horizontal(|ui| {
        let selected = cx.selection.object.filter(|&i| i < cx.scene.objects.len());
        if ui.add_enabled(selected.is_some(), egui::Button::new("Duplicate")).clicked()
            && let Some(i) = selected
        {
            let object = Box::new(cx.scene.objects[i].clone());
            cx.queue(Command::Edit(FieldEdit::selecting(Edit::Insert { index: i + 1, object }, Some(i + 1))));
        }
        if ui.add_enabled(selected.is_some(), egui::Button::new("Delete")).clicked()
            && let Some(i) = selected
        {
            cx.queue(Command::Edit(FieldEdit::selecting(Edit::Remove { index: i }, None)));
        }
    });
    add_menu(ui, cx);
}

/// "Add": every curve and surface kind with its example, and blending splines of the
/// kinds that declare themselves models (`DocumentKind::BLENDING_MODEL`).
fn add_menu(ui: &mut egui::Ui, cx: &mut PanelContext<'_>) {
    ui.menu_button("Add…", |ui| {
        ui.menu_button("Curve", |ui| {
            for c in CurveDocument::examples() {
                if ui.button(c.type_name()).clicked() {
                    add(cx, c.to_value());
                }
            }
        });
        ui.menu_button("Surface", |ui| {
            for s in SurfaceDocument::examples() {
                if ui.button(s.type_name()).clicked() {
                    add(cx, s.to_value());
                }
            }
        });
        ui.menu_button("Blending spline of", |ui| {
            for m in CurveDocument::examples().into_iter().filter(CurveDocument::blending_model) {
                if ui.button(m.type_name()).clicked() {
                    add(cx, json!({"type": "blending_spline", "model": {"type": m.type_name()}, "local_curves": 8}));
                }
            }
            for m in SurfaceDocument::examples().into_iter().filter(SurfaceDocument::blending_model) {
                if ui.button(format!("{} (surface)", m.type_name())).clicked() {
                    let model = json!({"type": m.type_name()});
                    add(cx, json!({"type": "blending_spline_surface", "model": model, "local_surfaces": [4, 4]}));
                }
            }
        });
    });
}

fn add(cx: &mut PanelContext<'_>, shape: serde_json::Value) {
    let object = json!({"shape": shape, "local_pieces": true, "control_net": true});
    match SceneObject::from_value(object) {
        Ok(object) => {
            let index = cx.scene.objects.len();
            let edit = Edit::Insert { index, object: Box::new(object) };
            cx.queue(Command::Edit(FieldEdit::selecting(edit, Some(index))));
        }
        Err(e) => cx.status.message = Some(e.to_string()),
    }
}
