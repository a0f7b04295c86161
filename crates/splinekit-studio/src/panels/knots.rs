//! The knot vector style of a B-spline or NURBS curve, or of one direction of a net:
//! clamped (p + 1 equal knots at each end, uniform between: the kernel's
//! [`KnotVector::clamped_uniform`]), uniform (equally spaced, unclamped:
//! [`KnotVector::uniform`]) or periodic (uniform knots with `periodic: true`), over the
//! parameter range of the current first and last knot. A switch rewrites the knots and the
//! `periodic` flag in one edit of the whole shape, so that it is one undo step and a
//! combination the library refuses leaves the document as it was.

use serde_json::Value;
use splinekit::Interval;
use splinekit::basis::KnotVector;
use splinekit_scene::DocumentError;

use super::context::PanelContext;
use super::fields::{error_label, read};
use crate::command::{Command, FieldEdit};
use crate::edit::Edit;

/// A style of knot vector.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KnotStyle {
    /// p + 1 equal knots at each end, uniform interior knots.
    Clamped,
    /// Equally spaced knots, unclamped.
    Uniform,
    /// Equally spaced knots, control points used cyclically (closed).
    Periodic,
}

impl KnotStyle {
    /// Every style, in the order the panel offers them.
    pub const ALL: [KnotStyle; 3] = [KnotStyle::Clamped, KnotStyle::Uniform, KnotStyle::Periodic];

    /// The name shown in the panel.
    pub fn name(self) -> &'static str {
        match self {
            KnotStyle::Clamped => "clamped",
            KnotStyle::Uniform => "uniform",
            KnotStyle::Periodic => "periodic",
        }
    }
}

/// The document fields of one knot direction: `degree`, `knots`, `periodic` (or their
/// `_u`/`_v` forms), and which index of `control_points` counts the points along it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct KnotAxis {
    /// The degree field.
    pub degree: &'static str,
    /// The knots field.
    pub knots: &'static str,
    /// The periodic field.
    pub periodic: &'static str,
    /// 0: the number of control points (curves) or rows (nets); 1: the length of a row.
    pub depth: usize,
}

/// The knot direction of a curve.
pub const CURVE: KnotAxis = KnotAxis { degree: "degree", knots: "knots", periodic: "periodic", depth: 0 };
/// The u direction of a net.
pub const NET_U: KnotAxis = KnotAxis { degree: "degree_u", knots: "knots_u", periodic: "periodic_u", depth: 0 };
/// The v direction of a net.
pub const NET_V: KnotAxis = KnotAxis { degree: "degree_v", knots: "knots_v", periodic: "periodic_v", depth: 1 };

/// The style of `knots` of degree `degree`; `None` when it is none of the three (custom
/// knots). Spacings count as equal within 10⁻⁹ of the range.
pub fn style_of(knots: &[f64], degree: usize, periodic: bool) -> Option<KnotStyle> {
    let (first, last) = (*knots.first()?, *knots.last()?);
    let tol = 1e-9 * (last - first).abs().max(1e-300);
    let equal_steps = |ks: &[f64]| ks.windows(3).all(|w| ((w[2] - w[1]) - (w[1] - w[0])).abs() <= tol);
    if equal_steps(knots) && knots.len() >= 2 && knots[1] > first {
        return Some(if periodic { KnotStyle::Periodic } else { KnotStyle::Uniform });
    }
    let p = degree + 1;
    let clamped = !periodic
        && knots.len() >= 2 * p
        && knots[..p].iter().all(|&k| k == first)
        && knots[knots.len() - p..].iter().all(|&k| k == last)
        && equal_steps(&knots[p - 1..knots.len() - p + 1]);
    clamped.then_some(KnotStyle::Clamped)
}

/// The n + p + 1 knots of `style` for n control points of degree p over `range` (the
/// kernel's constructors and their messages).
pub fn knots_for(style: KnotStyle, degree: usize, n: usize, range: Interval) -> Result<Vec<f64>, splinekit::Error> {
    match style {
        KnotStyle::Clamped => KnotVector::clamped_uniform(degree, n, range).map(KnotVector::into_vec),
        KnotStyle::Uniform | KnotStyle::Periodic => {
            let count = n + degree + 1;
            let step = (range.end - range.start) / (count - 1) as f64;
            KnotVector::uniform(count, range.start, step).map(KnotVector::into_vec)
        }
    }
}

/// The shape document `shape` with the knots of `axis` in `style` (and `periodic` set, or
/// removed for open styles). Errors name the field within the shape.
pub fn restyled(shape: &Value, axis: KnotAxis, style: KnotStyle) -> Result<Value, DocumentError> {
    let degree = shape.get(axis.degree).and_then(Value::as_u64).ok_or_else(|| missing(axis.degree))? as usize;
    let points = shape.get("control_points").and_then(Value::as_array).ok_or_else(|| missing("control_points"))?;
    let n = match axis.depth {
        0 => points.len(),
        _ => points.first().and_then(Value::as_array).map_or(0, Vec::len),
    };
    let knots: Vec<f64> = shape
        .get(axis.knots)
        .and_then(|k| serde_json::from_value(k.clone()).ok())
        .ok_or_else(|| missing(axis.knots))?;
    let range = match (knots.first(), knots.last()) {
        (Some(&a), Some(&b)) if a < b => Interval::new(a, b),
        _ => Interval::new(0.0, 1.0),
    };
    let new = knots_for(style, degree, n, range).map_err(DocumentError::from)?;
    let mut out = shape.clone();
    if let Some(map) = out.as_object_mut() {
        map.insert(axis.knots.into(), new.into());
        if style == KnotStyle::Periodic {
            map.insert(axis.periodic.into(), true.into());
        } else {
            map.remove(axis.periodic);
        }
    }
    Ok(out)
}

fn missing(field: &str) -> DocumentError {
    DocumentError::new(field, "missing")
}

/// The knot style chooser of one direction; a choice is applied at once (one edit), a
/// refused one shows the library's message under it.
pub fn knot_style(ui: &mut egui::Ui, cx: &mut PanelContext<'_>, object: usize, axis: KnotAxis, label: &str) {
    let Some(shape) = read(cx, object, "/shape") else { return };
    let knots: Vec<f64> =
        shape.get(axis.knots).and_then(|k| serde_json::from_value(k.clone()).ok()).unwrap_or_default();
    let degree = shape.get(axis.degree).and_then(Value::as_u64).unwrap_or(0) as usize;
    let periodic = shape.get(axis.periodic).and_then(Value::as_bool).unwrap_or(false);
    let current = style_of(&knots, degree, periodic);
    let mut chosen = current;
    let mut items = Vec::new();
    let combo =
        egui::ComboBox::from_label(label).selected_text(current.map_or("custom", KnotStyle::name)).show_ui(ui, |ui| {
            for s in KnotStyle::ALL {
                let item = ui.selectable_value(&mut chosen, Some(s), s.name());
                items.push((format!("{label}: {}", s.name()), super::rect(&item)));
            }
        });
    cx.widgets.push((label.to_string(), super::rect(&combo.response)));
    cx.widgets.extend(items);
    let key = format!("/shape/{}", axis.knots);
    if let Some(style) = chosen.filter(|_| chosen != current) {
        let within = format!("objects[{object}].shape");
        match restyled(&shape, axis, style) {
            Ok(value) => {
                let edit = Edit::Set { object, pointer: "/shape".into(), value: Some(value) };
                cx.queue(Command::Edit(FieldEdit::of_field(edit, &key)));
            }
            Err(e) => {
                let m = e.within(&within).to_string();
                cx.status.message = Some(m.clone());
                cx.status.field_error = Some((key.clone(), m));
            }
        }
    }
    error_label(ui, cx, &key);
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn styles_are_recognised_and_made() {
        let r = Interval::new(0.0, 5.0);
        let clamped = knots_for(KnotStyle::Clamped, 3, 8, r).expect("clamped");
        assert_eq!(clamped, [0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 5.0, 5.0, 5.0]);
        assert_eq!(style_of(&clamped, 3, false), Some(KnotStyle::Clamped));
        let uniform = knots_for(KnotStyle::Uniform, 3, 8, Interval::new(0.0, 11.0)).expect("uniform");
        assert_eq!(uniform, (0..12).map(f64::from).collect::<Vec<_>>());
        assert_eq!(style_of(&uniform, 3, false), Some(KnotStyle::Uniform));
        assert_eq!(style_of(&uniform, 3, true), Some(KnotStyle::Periodic));
        assert_eq!(style_of(&[0.0, 0.0, 0.0, 1.0, 3.0, 4.0, 4.0, 4.0], 2, false), None);
        // Too few points for a clamped cubic: the kernel's message.
        let e = knots_for(KnotStyle::Clamped, 3, 3, r).expect_err("three points");
        assert!(e.to_string().contains("control_points"), "{e}");
    }

    #[test]
    fn a_restyled_document_sets_knots_and_periodic_of_its_direction() {
        let shape = json!({"type": "bspline", "degree": 2, "knots": [0, 0, 0, 1, 2, 2, 2],
            "control_points": [[0, 0], [1, 1], [2, 0], [3, 1]]});
        let p = restyled(&shape, CURVE, KnotStyle::Periodic).expect("periodic");
        assert_eq!(p["periodic"], json!(true));
        assert_eq!(p["knots"].as_array().map(Vec::len), Some(7));
        let back = restyled(&p, CURVE, KnotStyle::Clamped).expect("clamped");
        assert!(back.get("periodic").is_none());
        assert_eq!(back["knots"], json!([0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0]));
        let net = json!({"type": "bspline_surface", "degree_u": 1, "degree_v": 1,
            "knots_u": [0, 0, 1, 1], "knots_v": [0, 0, 0.5, 1, 1],
            "control_points": [[[0, 0, 0], [0, 1, 0], [0, 2, 0]], [[1, 0, 0], [1, 1, 0], [1, 2, 1]]]});
        let v = restyled(&net, NET_V, KnotStyle::Uniform).expect("uniform v");
        assert_eq!(v["knots_v"], json!([0.0, 0.25, 0.5, 0.75, 1.0]));
        assert_eq!(v["knots_u"], net["knots_u"]);
    }
}
