//! Small live plots: the B-function B(t) with its derivatives B′(t) and B″(t) on [0, 1]
//! (each derivative scaled to the plot's height by its maximum), and the blending basis of
//! a knot vector (the weight B∘w of each local over its two spans).

use splinekit::basis::BFunction;

/// A plot's box, framed, and the map from (x in [0, 1], y in [0, 1]) into it.
fn frame(ui: &mut egui::Ui, size: egui::Vec2) -> (egui::Painter, impl Fn(f64, f64) -> egui::Pos2) {
    let (rect, _) = ui.allocate_exact_size(size, egui::Sense::hover());
    let painter = ui.painter_at(rect);
    painter.rect_stroke(rect, 2.0, egui::Stroke::new(1.0, egui::Color32::GRAY), egui::StrokeKind::Inside);
    let at = move |x: f64, y: f64| {
        egui::pos2(
            rect.left() + 4.0 + (rect.width() - 8.0) * x as f32,
            rect.bottom() - 4.0 - (rect.height() - 8.0) * y as f32,
        )
    };
    (painter, at)
}

/// Draws B (text colour), B′ (orange, from the bottom) and B″ (blue, about the middle) of
/// `b` in a box `size` points wide.
pub fn bfunction_plot(ui: &mut egui::Ui, b: &BFunction, size: egui::Vec2) {
    let text = ui.visuals().text_color();
    let (painter, at) = frame(ui, size);
    let samples: Vec<[f64; 3]> = (0..=64)
        .map(|i| {
            let mut v = [0.0; 3];
            b.eval(i as f64 / 64.0, &mut v);
            v
        })
        .collect();
    let peak = |k: usize| samples.iter().map(|s| s[k].abs()).fold(1e-12, f64::max);
    let (slope, bend) = (peak(1), peak(2));
    let t = |i: usize| i as f64 / 64.0;
    let line = |f: &dyn Fn(&[f64; 3]) -> f64| -> Vec<egui::Pos2> {
        samples.iter().enumerate().map(|(i, s)| at(t(i), f(s))).collect()
    };
    painter.add(egui::Shape::dashed_line(
        &[at(0.0, 0.5), at(1.0, 0.5)],
        egui::Stroke::new(0.5, egui::Color32::GRAY),
        3.0,
        3.0,
    ));
    painter.add(egui::Shape::line(line(&|s| s[0]), egui::Stroke::new(1.5, text)));
    painter
        .add(egui::Shape::line(line(&|s| s[1] / slope), egui::Stroke::new(1.5, egui::Color32::from_rgb(230, 120, 20))));
    painter.add(egui::Shape::line(
        line(&|s| 0.5 + 0.5 * s[2] / bend),
        egui::Stroke::new(1.5, egui::Color32::from_rgb(40, 110, 220)),
    ));
}

/// Draws the blending basis of `knots` (increasing, at least 2) with `b`: local k weighs
/// B((t − t_{k−1})/(t_k − t_{k−1})) rising and 1 − B((t − t_k)/(t_{k+1} − t_k)) falling,
/// each local in its own hue, the knots as ticks.
pub fn blending_basis_plot(ui: &mut egui::Ui, b: &BFunction, knots: &[f64], size: egui::Vec2) {
    let (painter, at) = frame(ui, size);
    let n = knots.len();
    if n < 2 || knots.iter().any(|k| !k.is_finite()) || knots[n - 1] <= knots[0] {
        return;
    }
    let (a, span) = (knots[0], knots[n - 1] - knots[0]);
    let x = |t: f64| (t - a) / span;
    for k in 0..n {
        let hue = k as f32 / n.max(2) as f32;
        let color: egui::Color32 = egui::ecolor::Hsva::new(hue * 0.8, 0.8, 0.8, 1.0).into();
        let mut pts = Vec::new();
        if k > 0 {
            pts.extend((0..=32).map(|i| {
                let w = i as f64 / 32.0;
                at(x(knots[k - 1] + w * (knots[k] - knots[k - 1])), b.value(w))
            }));
        }
        if k + 1 < n {
            pts.extend((0..=32).map(|i| {
                let w = i as f64 / 32.0;
                at(x(knots[k] + w * (knots[k + 1] - knots[k])), 1.0 - b.value(w))
            }));
        }
        painter.add(egui::Shape::line(pts, egui::Stroke::new(1.5, color)));
    }
    for &t in knots {
        painter.line_segment([at(x(t), 0.0), at(x(t), 0.06)], egui::Stroke::new(1.0, egui::Color32::GRAY));
    }
}
