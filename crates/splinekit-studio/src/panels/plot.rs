//! A small live plot of the B-function B(t) and its derivative B′(t) on [0, 1]
//! (B′ scaled to the plot's height by its maximum).

use splinekit::basis::BFunction;

/// Draws B (solid) and B′ (orange) of `b` in a box `size` points wide.
pub fn bfunction_plot(ui: &mut egui::Ui, b: &BFunction, size: egui::Vec2) {
    let (rect, _) = ui.allocate_exact_size(size, egui::Sense::hover());
    let painter = ui.painter_at(rect);
    painter.rect_stroke(rect, 2.0, egui::Stroke::new(1.0, egui::Color32::GRAY), egui::StrokeKind::Inside);
    let samples: Vec<(f64, f64, f64)> = (0..=64)
        .map(|i| {
            let t = i as f64 / 64.0;
            let mut v = [0.0; 2];
            b.eval(t, &mut v);
            (t, v[0], v[1])
        })
        .collect();
    let slope = samples.iter().map(|s| s.2.abs()).fold(1e-12, f64::max);
    let at = |t: f64, y: f64| {
        egui::pos2(
            rect.left() + 4.0 + (rect.width() - 8.0) * t as f32,
            rect.bottom() - 4.0 - (rect.height() - 8.0) * y as f32,
        )
    };
    let value: Vec<egui::Pos2> = samples.iter().map(|s| at(s.0, s.1)).collect();
    let derivative: Vec<egui::Pos2> = samples.iter().map(|s| at(s.0, s.2 / slope)).collect();
    painter.add(egui::Shape::line(value, egui::Stroke::new(1.5, ui.visuals().text_color())));
    painter.add(egui::Shape::line(derivative, egui::Stroke::new(1.5, egui::Color32::from_rgb(230, 120, 20))));
}
