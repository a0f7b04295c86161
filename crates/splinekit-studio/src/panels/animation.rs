//! The Animation panel: play/pause, speed and a time slider over the scene's duration; in a
//! scene without animation, a beat for the selected blending spline ([`Studio::add_beat`]).

use crate::actions::Action;
use crate::command::Command;
use crate::studio::Studio;

/// The Animation panel (one row).
pub fn animation_panel(ui: &mut egui::Ui, studio: &mut Studio) {
    let duration = studio.scene.clock().duration;
    ui.horizontal(|ui| {
        if !studio.scene.is_animated() {
            ui.label("no animation in this scene");
            let beat = crate::actions::spec(Action::AddBeat);
            if studio.selected_object.is_some() && ui.button(beat.label).on_hover_text(beat.help).clicked() {
                studio.queue(Command::Action(Action::AddBeat));
            }
            return;
        }
        let label = if studio.clock.playing { "Pause" } else { "Play" };
        if ui.button(label).on_hover_text(crate::actions::menu_label(Action::TogglePlay)).clicked() {
            studio.queue(Command::Action(Action::TogglePlay));
        }
        let speed = ui.label("speed");
        ui.add(egui::DragValue::new(&mut studio.clock.speed).range(0.0..=10.0).speed(0.02)).labelled_by(speed.id);
        let time = ui.label("time");
        ui.add(egui::Slider::new(&mut studio.clock.time, 0.0..=duration).suffix(" s")).labelled_by(time.id);
    });
}
