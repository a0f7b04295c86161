//! Direct manipulation: a drag on a handle becomes an edit. Moving follows the mouse in the
//! view plane through the handle (the world point under the cursor at the handle's depth),
//! optionally along one axis; rotating turns about the local origin by the angle the cursor
//! sweeps around the handle's screen position, about the axis towards the eye; scaling
//! multiplies by the ratio of the cursor's distances from the handle. A control point of a
//! local Bézier moves in the local's rest frame by the inverse of its frame's linear part
//! applied to the world displacement, so that its world position o + T(P − o) follows the
//! mouse (GMlib's `updateCoeffs`).

use serde_json::Value;
use splinekit_scene::scenes::SceneDocument;
use splinekit_scene::transforms::TransformDoc;

use crate::edit::{Edit, EditError};
use crate::handles::{Handle, coordinates_of, local_points_of, transform_of};
use crate::transform_edit::{rotated, scaled, translated};
use crate::view_camera::Projector;

/// What a drag does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GestureKind {
    /// Move in the view plane, or along world axis 0, 1 or 2 only.
    Move(Option<usize>),
    /// Rotate about the local origin (local pieces only).
    Rotate,
    /// Scale about the local origin (local pieces only).
    Scale,
}

/// The value a handle had when the drag started.
#[derive(Debug, Clone, PartialEq)]
enum Start {
    Transform(TransformDoc),
    Coordinates(Vec<f64>),
    /// A local Bézier's rest control points, where the dragged one sits among them, and the
    /// inverse of the linear part of the local's frame.
    LocalPoints {
        rest: Value,
        path: Vec<usize>,
        inverse: [[f64; 3]; 3],
    },
}

/// A drag in progress.
#[derive(Debug, Clone)]
pub struct Gesture {
    /// The handle dragged.
    pub handle: Handle,
    /// What the drag does.
    pub kind: GestureKind,
    start: Start,
    start_mouse: [f64; 2],
    handle_px: [f64; 2],
    depth: f64,
}

impl Gesture {
    /// Starts dragging `handle` from the cursor at `mouse` (view pixels); `None` when the
    /// handle is behind the eye or its value cannot be read.
    pub fn start(
        scene: &SceneDocument,
        projector: &Projector,
        handle: &Handle,
        kind: GestureKind,
        mouse: [f64; 2],
    ) -> Option<Gesture> {
        Gesture::start_at(scene, None, projector, handle, kind, mouse)
    }

    /// [`Gesture::start`] on the scene posed at `time` (a local Bézier's control point
    /// follows the mouse through the local's frame at that time).
    pub fn start_at(
        scene: &SceneDocument,
        time: Option<f64>,
        projector: &Projector,
        handle: &Handle,
        kind: GestureKind,
        mouse: [f64; 2],
    ) -> Option<Gesture> {
        let (handle_px, depth) = projector.project(handle.position)?;
        let start = if handle.kind.is_local() {
            Start::Transform(transform_of(scene, handle))
        } else if let Some(path) = handle.kind.point_path() {
            let (rest, inverse) = local_points_of(scene, handle, time)?;
            Start::LocalPoints { rest, path, inverse }
        } else {
            Start::Coordinates(coordinates_of(scene, handle)?)
        };
        let kind = if handle.kind.is_local() { kind } else { GestureKind::Move(move_axis(kind)) };
        Some(Gesture { handle: handle.clone(), kind, start, start_mouse: mouse, handle_px, depth })
    }

    /// The edit that puts the handle where the cursor at `mouse` says.
    pub fn edit_at(&self, projector: &Projector, mouse: [f64; 2]) -> Result<Edit, EditError> {
        let field = self.handle.kind.field();
        let dim = self.handle.dimension;
        let value = match (&self.start, self.kind) {
            (Start::Transform(t), GestureKind::Move(axis)) => {
                to_json(&translated(t, &self.delta(projector, mouse, axis), dim))
            }
            (Start::Transform(t), GestureKind::Rotate) => {
                let sweep = |m: [f64; 2]| (m[1] - self.handle_px[1]).atan2(m[0] - self.handle_px[0]);
                // Screen y points down: a clockwise sweep on screen is a negative turn about
                // the axis towards the eye.
                let angle = -(sweep(mouse) - sweep(self.start_mouse));
                let d = projector.view_direction();
                let axis = [-d[0], -d[1], -d[2]];
                let angle = if dim == 2 { angle * axis[2].signum() } else { angle };
                to_json(&rotated(t, &field, axis, angle, dim, self.handle.origin)?)
            }
            (Start::Transform(t), GestureKind::Scale) => {
                let dist = |m: [f64; 2]| (m[0] - self.handle_px[0]).hypot(m[1] - self.handle_px[1]);
                let factor = dist(mouse) / dist(self.start_mouse).max(1.0);
                to_json(&scaled(t, factor.max(1e-3)))
            }
            (Start::Coordinates(c), kind) => {
                let delta = self.delta(projector, mouse, move_axis(kind));
                let moved: Vec<f64> =
                    c.iter().enumerate().map(|(i, x)| x + if i < dim { delta[i] } else { 0.0 }).collect();
                Value::from(moved)
            }
            (Start::LocalPoints { rest, path, inverse }, kind) => {
                let d = self.delta(projector, mouse, move_axis(kind));
                let q = inverse.map(|row| row[0] * d[0] + row[1] * d[1] + row[2] * d[2]);
                let mut value = rest.clone();
                let point = path.iter().try_fold(&mut value, |v, &i| v.get_mut(i)).and_then(Value::as_array_mut);
                let Some(point) = point else {
                    return Err(EditError::Missing(format!("{field}: no such control point")));
                };
                for (x, dq) in point.iter_mut().zip(q).take(dim) {
                    *x = Value::from(x.as_f64().unwrap_or(0.0) + dq);
                }
                value
            }
        };
        Ok(Edit::Set { object: self.handle.object, pointer: self.handle.kind.pointer(), value: Some(value) })
    }

    /// The world displacement from the drag's start to `mouse` at the handle's depth, kept
    /// to one axis when asked.
    fn delta(&self, projector: &Projector, mouse: [f64; 2], axis: Option<usize>) -> [f64; 3] {
        let a = projector.unproject(self.start_mouse, self.depth);
        let b = projector.unproject(mouse, self.depth);
        let mut d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        if let Some(k) = axis {
            for (i, x) in d.iter_mut().enumerate() {
                if i != k {
                    *x = 0.0;
                }
            }
        }
        if self.handle.dimension == 2 {
            d[2] = 0.0;
        }
        d
    }
}

fn move_axis(kind: GestureKind) -> Option<usize> {
    match kind {
        GestureKind::Move(axis) => axis,
        _ => None,
    }
}

fn to_json(t: &TransformDoc) -> Value {
    serde_json::to_value(t).unwrap_or(Value::Null)
}
