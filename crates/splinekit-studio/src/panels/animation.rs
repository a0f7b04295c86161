//! The Animation panel: play/pause, speed and a time slider over the scene's duration; in a
//! scene without animation, a beat for the selected blending spline ([`Studio::add_beat`]).

use super::context::PanelContext;
use crate::actions::Action;
use crate::command::Command;
use crate::studio::Studio;

/// The Animation panel (one row).
pub fn animation_panel(ui: &mut egui::Ui, studio: &mut Studio) {
    animation(ui, &mut PanelContext::of(studio));
}

/// The Animation panel (one row).
fn animation(ui: &mut egui::Ui, cx: &mut PanelContext<'_>) {
    let duration = cx.scene.clock().duration;
    ui.horizontal(|ui| {
        if !cx.scene.is_animated() {
            ui.label("no animation in this scene");
            let beat = crate::actions::spec(Action::AddBeat);
            if cx.selection.object.is_some() && ui.button(beat.label).on_hover_text(beat.help).clicked() {
                cx.queue(Command::Action(Action::AddBeat));
            }
            return;
        }
        let label = if cx.clock.playing { "Pause" } else { "Play" };
        if ui.button(label).on_hover_text(crate::actions::menu_label(Action::TogglePlay)).clicked() {
            cx.queue(Command::Action(Action::TogglePlay));
        }
        let speed = ui.label("speed");
        ui.add(egui::DragValue::new(&mut cx.clock.speed).range(0.0..=10.0).speed(0.02)).labelled_by(speed.id);
        let time = ui.label("time");
        ui.add(egui::Slider::new(&mut cx.clock.time, 0.0..=duration).suffix(" s")).labelled_by(time.id);
    });
}
