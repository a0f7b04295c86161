//! Direct manipulation: a drag on a handle becomes an edit. Moving follows the mouse in the
//! view plane through the handle (the world point under the cursor at the handle's depth),
//! optionally along one axis; rotating turns about the local origin by the angle the cursor
//! sweeps around the handle's screen position, about the axis towards the eye; scaling
//! multiplies by the ratio of the cursor's distances from the handle. A control point of a
//! local Bézier moves in the local's rest frame by the inverse of its frame's linear part
//! applied to the world displacement, so that its world position o + T(P − o) follows the
//! mouse (GMlib's `updateCoeffs`). A copy of a split knot (a handle with a pivot, the
//! joint) turns and scales about the joint instead of moving, so the curve stays continuous
//! there: a plain drag does both at once, the handle following the cursor.

use serde_json::Value;
use splinekit_scene::DocumentError;
use splinekit_scene::scenes::SceneDocument;
use splinekit_scene::transforms::TransformDoc;

use crate::edit::{Edit, EditError};
use crate::group_move::{GroupMove, GroupStart};
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
    /// Change the weight of a NURBS or rational Bézier control point (held W): dragging
    /// up multiplies it by e^(Δy/100) for Δy pixels, down divides.
    Weight,
    /// Turn and scale about the handle's pivot at once, by the angle the cursor sweeps
    /// around it and the ratio of its distances from it, so that the handle follows the
    /// cursor in the view plane: a plain drag of a copy of a split knot, whose joint (the
    /// pivot) stays put.
    TurnScale,
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
    /// A control point's weight and where it is in the document.
    Weight {
        pointer: String,
        w: f64,
    },
}

/// Where the weight of a control-point handle sits in its object's document, and its
/// value: `/shape/weights/i` of a NURBS or rational Bézier curve, `/shape/weights/i/j` of
/// a NURBS net. `None` for handles of shapes without weights.
pub fn weight_of(scene: &SceneDocument, handle: &Handle) -> Option<(String, f64)> {
    let pointer = match handle.kind {
        crate::handles::HandleKind::ControlPoint(i, "control_points") => format!("/shape/weights/{i}"),
        crate::handles::HandleKind::NetPoint(i, j) => format!("/shape/weights/{i}/{j}"),
        _ => return None,
    };
    let w = scene.objects.get(handle.object)?.to_value().pointer(&pointer)?.as_f64()?;
    Some((pointer, w))
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
    /// The pivot's screen position: the handle's, or the selection's centroid's.
    handle_px: [f64; 2],
    depth: f64,
    /// With several handles selected: their values when the drag started, and their
    /// centroid (the pivot of turns and scalings).
    group: Option<(GroupStart, [f64; 3])>,
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
        // A copy of a split knot turns and scales about its joint, whatever the drag.
        let pivot = handle.pivot.filter(|_| handle.kind.is_local() && kind != GestureKind::Weight);
        let (handle_px, kind) = match pivot {
            Some(p) => {
                let kind = if matches!(kind, GestureKind::Move(_)) { GestureKind::TurnScale } else { kind };
                (projector.project(p)?.0, kind)
            }
            None => (handle_px, kind),
        };
        let weight = (kind == GestureKind::Weight).then(|| weight_of(scene, handle)).flatten();
        let start = if let Some((pointer, w)) = weight {
            Start::Weight { pointer, w }
        } else if handle.kind.is_local() {
            Start::Transform(transform_of(scene, handle))
        } else if let Some(path) = handle.kind.point_path() {
            let (rest, inverse) = local_points_of(scene, handle, time)?;
            Start::LocalPoints { rest, path, inverse }
        } else {
            Start::Coordinates(coordinates_of(scene, handle)?)
        };
        let kind = match (&start, kind) {
            (Start::Weight { .. }, _) => GestureKind::Weight,
            (_, GestureKind::Weight) => GestureKind::Move(None),
            _ if handle.kind.is_local() => kind,
            _ => GestureKind::Move(move_axis(kind)),
        };
        Some(Gesture { handle: handle.clone(), kind, start, start_mouse: mouse, handle_px, depth, group: None })
    }

    /// A drag of `handle` that moves every handle of `group` (the selection, `handle`
    /// among them) with it: moving translates them all, rotating and scaling turn and
    /// scale their positions about their centroid ([`GroupMove`]). `None` when a value
    /// cannot be read or the centroid is behind the eye.
    pub fn start_group(
        scene: &SceneDocument,
        time: Option<f64>,
        projector: &Projector,
        handle: &Handle,
        group: &[Handle],
        kind: GestureKind,
        mouse: [f64; 2],
    ) -> Option<Gesture> {
        let (_, depth) = projector.project(handle.position)?;
        let centroid = crate::selection::centroid(group)?;
        let (handle_px, _) = projector.project(centroid)?;
        let values = GroupStart::read(scene, time, group)?;
        let start = Start::Coordinates(handle.position.to_vec());
        Some(Gesture {
            handle: handle.clone(),
            kind,
            start,
            start_mouse: mouse,
            handle_px,
            depth,
            group: Some((values, centroid)),
        })
    }

    /// Whether the drag moves a selection of several handles.
    pub fn is_group(&self) -> bool {
        self.group.is_some()
    }

    /// The edit that puts the handle where the cursor at `mouse` says.
    pub fn edit_at(&self, projector: &Projector, mouse: [f64; 2]) -> Result<Edit, EditError> {
        self.edit_snapped(projector, mouse, &|p| p)
    }

    /// The turn (radians about the axis towards the eye) the cursor at `mouse` has swept
    /// about the pivot since the drag started.
    fn angle(&self, mouse: [f64; 2]) -> f64 {
        let sweep = |m: [f64; 2]| (m[1] - self.handle_px[1]).atan2(m[0] - self.handle_px[0]);
        // Screen y points down: a clockwise sweep on screen is a negative turn about
        // the axis towards the eye.
        -(sweep(mouse) - sweep(self.start_mouse))
    }

    /// `t` turned about the axis towards the eye, through the handle's origin, by the angle
    /// the cursor swept ([`Self::angle`]; in the plane about z, with the view's sign).
    fn turned(&self, t: &TransformDoc, projector: &Projector, mouse: [f64; 2]) -> Result<TransformDoc, DocumentError> {
        let d = projector.view_direction();
        let axis = [-d[0], -d[1], -d[2]];
        let dim = self.handle.dimension;
        let angle = if dim == 2 { self.angle(mouse) * axis[2].signum() } else { self.angle(mouse) };
        rotated(t, &self.handle.kind.field(), axis, angle, dim, self.handle.origin)
    }

    /// The ratio of the cursor's distances from the pivot now and when the drag started.
    fn factor(&self, mouse: [f64; 2]) -> f64 {
        let dist = |m: [f64; 2]| (m[0] - self.handle_px[0]).hypot(m[1] - self.handle_px[1]);
        (dist(mouse) / dist(self.start_mouse).max(1.0)).max(1e-3)
    }

    /// [`Self::edit_at`], the dragged handle's new position passed through `snap` when
    /// moving (the others of a selection move with it by the same displacement).
    pub fn edit_snapped(
        &self,
        projector: &Projector,
        mouse: [f64; 2],
        snap: &dyn Fn([f64; 3]) -> [f64; 3],
    ) -> Result<Edit, EditError> {
        let field = self.handle.kind.field();
        let dim = self.handle.dimension;
        if let Some((group, center)) = &self.group {
            let d = projector.view_direction();
            let axis = if dim == 2 { [0.0, 0.0, -d[2].signum()] } else { [-d[0], -d[1], -d[2]] };
            let map = match self.kind {
                GestureKind::Move(axis) => GroupMove::Translate(self.delta(projector, mouse, axis, snap)),
                GestureKind::Rotate => GroupMove::Rotate { center: *center, axis, angle: self.angle(mouse) },
                GestureKind::Scale => GroupMove::Scale { center: *center, factor: self.factor(mouse) },
                // A weight drag changes one handle's weight, never a group's; a group is
                // never turned and scaled about a copy's joint.
                GestureKind::Weight | GestureKind::TurnScale => GroupMove::Translate([0.0; 3]),
            };
            return group.edit(&map);
        }
        let value = match (&self.start, self.kind) {
            (Start::Weight { pointer, w }, _) => {
                let w = w * ((self.start_mouse[1] - mouse[1]) / 100.0).exp();
                return Ok(Edit::Set { object: self.handle.object, pointer: pointer.clone(), value: Some(w.into()) });
            }
            (Start::Transform(t), GestureKind::Move(axis)) => {
                to_json(&translated(t, &self.delta(projector, mouse, axis, snap), dim))
            }
            (Start::Transform(t), GestureKind::Rotate) => to_json(&self.turned(t, projector, mouse)?),
            (Start::Transform(t), GestureKind::Scale | GestureKind::Weight) => to_json(&scaled(t, self.factor(mouse))),
            (Start::Transform(t), GestureKind::TurnScale) => {
                to_json(&scaled(&self.turned(t, projector, mouse)?, self.factor(mouse)))
            }
            (Start::Coordinates(c), kind) => {
                let delta = self.delta(projector, mouse, move_axis(kind), snap);
                let moved: Vec<f64> =
                    c.iter().enumerate().map(|(i, x)| x + if i < dim { delta[i] } else { 0.0 }).collect();
                Value::from(moved)
            }
            (Start::LocalPoints { rest, path, inverse }, kind) => {
                let d = self.delta(projector, mouse, move_axis(kind), snap);
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
    /// to one axis when asked, such that the handle lands where `snap` puts it.
    fn delta(
        &self,
        projector: &Projector,
        mouse: [f64; 2],
        axis: Option<usize>,
        snap: &dyn Fn([f64; 3]) -> [f64; 3],
    ) -> [f64; 3] {
        let a = projector.unproject(self.start_mouse, self.depth);
        let b = projector.unproject(mouse, self.depth);
        let keep = |mut d: [f64; 3]| {
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
        };
        let d = keep([b[0] - a[0], b[1] - a[1], b[2] - a[2]]);
        let p = self.handle.position;
        let q = snap([p[0] + d[0], p[1] + d[1], p[2] + d[2]]);
        keep([q[0] - p[0], q[1] - p[1], q[2] - p[2]])
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
