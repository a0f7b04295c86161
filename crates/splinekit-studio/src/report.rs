//! The handle report (`--report-handles FILE`): each handle's object, kind, index, world
//! position and pixel position in the window (physical pixels from the window's top-left
//! corner), for a script that moves the mouse onto one; and the named panel widgets of the
//! last frame with their centres, for a script that clicks one.

use serde_json::{Value, json};

use crate::handles::{Handle, HandleKind};
use crate::view_camera::Projector;

/// The report of `handles` drawn by `projector` in a view whose top-left corner is at
/// `origin` window pixels.
pub fn handle_report(handles: &[Handle], projector: &Projector, origin: [u32; 2], view_size: [u32; 2]) -> Value {
    let list: Vec<Value> = handles
        .iter()
        .filter_map(|h| {
            let (p, _) = projector.project(h.position)?;
            let (kind, index) = match h.kind {
                HandleKind::LocalCurve(k) => ("local_curve", json!(k)),
                HandleKind::LocalPatch(k, l) => ("local_patch", json!([k, l])),
                HandleKind::ControlPoint(i, _) => ("control_point", json!(i)),
                HandleKind::NetPoint(i, j) => ("net_point", json!([i, j])),
                HandleKind::LocalCurvePoint(k, i) => ("local_curve_point", json!([k, i])),
                HandleKind::LocalPatchPoint(k, l, a, b) => ("local_patch_point", json!([k, l, a, b])),
                HandleKind::LocalTriangle(k) => ("local_triangle", json!(k)),
            };
            Some(json!({
                "object": h.object, "kind": kind, "index": index, "world": h.position,
                "x": p[0] + f64::from(origin[0]), "y": p[1] + f64::from(origin[1]),
            }))
        })
        .collect();
    json!({"view": {"left": origin[0], "top": origin[1], "width": view_size[0], "height": view_size[1]}, "handles": list})
}

/// The named widgets (rectangles in egui points) as `[{"name", "x", "y"}]`, their centres
/// in window pixels at `pixels_per_point`.
pub fn widget_report(widgets: &[(String, [f32; 4])], pixels_per_point: f32) -> Value {
    let list: Vec<Value> = widgets
        .iter()
        .map(|(name, r)| {
            let (x, y) = (0.5 * (r[0] + r[2]) * pixels_per_point, 0.5 * (r[1] + r[3]) * pixels_per_point);
            json!({"name": name, "x": x, "y": y})
        })
        .collect();
    Value::Array(list)
}
