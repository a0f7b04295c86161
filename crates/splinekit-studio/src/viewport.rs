//! The 3-D view inside the egui layout: shows the rendered image and turns the mouse and
//! keys into studio actions. Left drag on a handle moves it (held X/Y/Z: along that axis;
//! held R: rotates, S: scales about the local origin; W: changes a control point's
//! weight); left drag elsewhere orbits, middle or Shift+left drag pans, the wheel zooms; a
//! click selects the handle under the cursor (with a knot tool armed: edits the knots there)
//! (Shift+click adds or removes it), Ctrl+drag on empty space selects the handles in a box
//! (Ctrl+Shift: adds them). A drag of a handle of a selection of several moves them all.

use crate::gesture::GestureKind;
use crate::studio::Studio;
use crate::view_camera::Projector;

/// What the view reports back to the window after the frame's input.
#[derive(Debug, Clone, Copy, Default)]
pub struct ViewFrame {
    /// The view's rectangle in physical pixels: left, top, width, height.
    pub rect_px: [u32; 4],
}

/// What the 3-D view needs from the last frame drawn.
pub struct ViewInput<'a> {
    /// The 3-D view has been drawn (not before the first frame).
    pub drawn: bool,
    /// The projector of the scene as last drawn.
    pub projector: Option<&'a Projector>,
    /// Frame-time overlay text, when shown.
    pub overlay: Option<String>,
}

/// Lays out the view in `ui`'s remaining space, never under the right panel (a panel
/// whose content overflows must not move the view), and handles its input.
pub fn view(ui: &mut egui::Ui, studio: &mut Studio, input: ViewInput<'_>) -> ViewFrame {
    let mut rect = ui.available_rect_before_wrap();
    rect.max.x = rect.max.x.min(ui.ctx().content_rect().max.x - crate::panels::SIDE_WIDTH);
    let response = ui.allocate_rect(rect, egui::Sense::click_and_drag());
    let ppp = ui.ctx().pixels_per_point();
    if input.drawn {
        crate::view_blit::paint_view(ui.painter(), rect);
    }
    if let Some(text) = &input.overlay {
        let at = rect.left_top() + egui::vec2(8.0, 8.0);
        ui.painter().text(at, egui::Align2::LEFT_TOP, text, egui::FontId::monospace(13.0), egui::Color32::DARK_GRAY);
    }
    if let Some(projector) = input.projector {
        mouse(ui, studio, &response, projector, rect, ppp);
    }
    ViewFrame {
        rect_px: [
            (rect.left() * ppp).round() as u32,
            (rect.top() * ppp).round() as u32,
            (rect.width() * ppp).round().max(1.0) as u32,
            (rect.height() * ppp).round().max(1.0) as u32,
        ],
    }
}

/// The gesture a drag starts with, from the keys held.
fn gesture_kind(ui: &egui::Ui) -> GestureKind {
    ui.input(|i| {
        let held = |k| i.key_down(k);
        if held(egui::Key::W) {
            GestureKind::Weight
        } else if held(egui::Key::R) {
            GestureKind::Rotate
        } else if held(egui::Key::S) && !i.modifiers.command {
            GestureKind::Scale
        } else if held(egui::Key::X) {
            GestureKind::Move(Some(0))
        } else if held(egui::Key::Y) {
            GestureKind::Move(Some(1))
        } else if held(egui::Key::Z) && !i.modifiers.command {
            GestureKind::Move(Some(2))
        } else {
            GestureKind::Move(None)
        }
    })
}

fn mouse(
    ui: &egui::Ui,
    studio: &mut Studio,
    response: &egui::Response,
    projector: &Projector,
    rect: egui::Rect,
    ppp: f32,
) {
    let to_px = |p: egui::Pos2| [f64::from((p.x - rect.left()) * ppp), f64::from((p.y - rect.top()) * ppp)];
    let cursor = response.hover_pos().map(to_px);
    if studio.gesture.is_none() {
        studio.view.hovered = cursor.and_then(|c| studio.pick(projector, c));
    }
    let (ctrl, shift) = ui.input(|i| (i.modifiers.command, i.modifiers.shift));
    let panning = !ctrl && shift || response.dragged_by(egui::PointerButton::Middle);
    let band_id = response.id.with("box select");
    if response.drag_started_by(egui::PointerButton::Primary)
        && !panning
        && let Some(start) = ui.input(|i| i.pointer.press_origin())
    {
        let started = studio.begin_drag(projector, to_px(start), gesture_kind(ui));
        if !started && ctrl {
            ui.data_mut(|d| d.insert_temp(band_id, to_px(start)));
        }
    }
    let band: Option<[f64; 2]> = ui.data(|d| d.get_temp(band_id));
    if let Some(a) = band {
        if let Some(b) = ui.input(|i| i.pointer.latest_pos()) {
            let from = egui::pos2(a[0] as f32 / ppp + rect.left(), a[1] as f32 / ppp + rect.top());
            let stroke = egui::Stroke::new(1.0, egui::Color32::from_rgb(230, 120, 0));
            ui.painter().rect_stroke(egui::Rect::from_two_pos(from, b), 0.0, stroke, egui::StrokeKind::Inside);
            if response.drag_stopped() {
                studio.box_select(projector, a, to_px(b), shift);
            }
        }
        if response.drag_stopped() || !response.dragged() {
            ui.data_mut(|d| d.remove::<[f64; 2]>(band_id));
        }
    }
    if response.dragged() && band.is_none() {
        let delta = response.drag_delta() * ppp;
        match (&studio.gesture, studio.camera.as_mut()) {
            (Some(_), _) => {
                if let Some(p) = response.interact_pointer_pos() {
                    studio.drag_to(projector, to_px(p));
                }
            }
            (None, Some(camera)) if panning => camera.pan(delta.x, delta.y, rect.height() * ppp),
            (None, Some(camera)) => camera.orbit(0.01 * delta.x, 0.01 * delta.y),
            (None, None) => {}
        }
    }
    if response.drag_stopped() {
        // The button may come up in a frame with more motion: finish where it was released.
        if studio.gesture.is_some()
            && let Some(p) = ui.input(|i| i.pointer.latest_pos())
        {
            studio.drag_to(projector, to_px(p));
        }
        studio.end_drag();
    }
    if response.clicked() {
        match (studio.knot_tool, cursor) {
            (Some(tool), Some(c)) => studio.knot_click(tool, projector, c, shift),
            _ => {
                let picked = cursor.and_then(|c| studio.pick(projector, c));
                studio.click(picked, shift);
            }
        }
    }
    let scroll = ui.input(|i| i.smooth_scroll_delta.y);
    if response.hovered()
        && scroll != 0.0
        && let Some(camera) = studio.camera.as_mut()
    {
        camera.zoom(0.999f32.powf(scroll));
    }
}
