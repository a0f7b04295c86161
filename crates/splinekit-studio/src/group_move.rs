//! Moving several handles as one: a map of world points (a translation, a turn about the
//! selection's centroid, a scaling about it) becomes one edit of every selected value
//! ([`GroupStart::edit`], one undo step).
//!
//! Each handle moves by the map's displacement of its own position: a control point's
//! coordinates by q − p, a local piece's translation by q − p (its frame keeps its
//! orientation), a local Bézier's control point in its rest frame by the inverse of its
//! frame's linear part applied to q − p (all the points of one local in one value).

use serde_json::Value;
use splinekit_scene::scenes::SceneDocument;
use splinekit_scene::transforms::TransformDoc;

use crate::edit::{Edit, EditError};
use crate::handles::{Handle, coordinates_of, local_points_of, transform_of};
use crate::transform_edit::translated;

/// A map of world points that moves a selection as one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GroupMove {
    /// p + d.
    Translate([f64; 3]),
    /// A turn by `angle` radians about the unit `axis` through `center` (Rodrigues).
    Rotate {
        /// A point of the axis (the centroid).
        center: [f64; 3],
        /// The unit axis.
        axis: [f64; 3],
        /// Radians, counter-clockwise looking down the axis.
        angle: f64,
    },
    /// c + s (p − c).
    Scale {
        /// The fixed point (the centroid).
        center: [f64; 3],
        /// The factor.
        factor: f64,
    },
}

impl GroupMove {
    /// Where the map takes `p`.
    pub fn apply(&self, p: [f64; 3]) -> [f64; 3] {
        match *self {
            GroupMove::Translate(d) => [p[0] + d[0], p[1] + d[1], p[2] + d[2]],
            GroupMove::Rotate { center: c, axis: k, angle } => {
                let v = [p[0] - c[0], p[1] - c[1], p[2] - c[2]];
                let (s, co) = angle.sin_cos();
                let kxv = [k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]];
                let kv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
                [0, 1, 2].map(|i| c[i] + v[i] * co + kxv[i] * s + k[i] * kv * (1.0 - co))
            }
            GroupMove::Scale { center: c, factor } => [0, 1, 2].map(|i| c[i] + factor * (p[i] - c[i])),
        }
    }
}

/// One selected handle's value when the move started.
#[derive(Debug, Clone)]
enum Start {
    Transform(TransformDoc),
    Coordinates(Vec<f64>),
    /// A local Bézier's point: where it sits in the local's value (shared with the other
    /// selected points of that local: index into [`GroupStart::locals`]).
    LocalPoint {
        local: usize,
        path: Vec<usize>,
    },
}

/// The values of a selection when a move started, from which every step of the move is
/// computed afresh (a drag's edits replace each other).
#[derive(Debug, Clone)]
pub struct GroupStart {
    items: Vec<(Handle, Start)>,
    /// Per local Bézier touched: object, pointer, rest points, inverse of its frame's
    /// linear part.
    locals: Vec<(usize, String, Value, [[f64; 3]; 3])>,
}

impl GroupStart {
    /// Reads the selected handles' values from `scene` posed at `time`; `None` when one
    /// cannot be read.
    pub fn read(scene: &SceneDocument, time: Option<f64>, handles: &[Handle]) -> Option<GroupStart> {
        let mut items = Vec::new();
        let mut locals: Vec<(usize, String, Value, [[f64; 3]; 3])> = Vec::new();
        for h in handles {
            let start = if h.kind.is_local() {
                Start::Transform(transform_of(scene, h))
            } else if let Some(path) = h.kind.point_path() {
                let pointer = h.kind.pointer();
                let local = match locals.iter().position(|(o, p, _, _)| *o == h.object && *p == pointer) {
                    Some(i) => i,
                    None => {
                        let (rest, inverse) = local_points_of(scene, h, time)?;
                        locals.push((h.object, pointer, rest, inverse));
                        locals.len() - 1
                    }
                };
                Start::LocalPoint { local, path }
            } else {
                Start::Coordinates(coordinates_of(scene, h)?)
            };
            items.push((h.clone(), start));
        }
        Some(GroupStart { items, locals })
    }

    /// The handles moved.
    pub fn handles(&self) -> impl Iterator<Item = &Handle> {
        self.items.iter().map(|(h, _)| h)
    }

    /// The edit that moves every handle from its start by `map`: one [`Edit::Batch`].
    pub fn edit(&self, map: &GroupMove) -> Result<Edit, EditError> {
        let mut edits = Vec::new();
        let mut locals: Vec<Value> = self.locals.iter().map(|(_, _, rest, _)| rest.clone()).collect();
        for (h, start) in &self.items {
            let q = map.apply(h.position);
            let mut d = [q[0] - h.position[0], q[1] - h.position[1], q[2] - h.position[2]];
            if h.dimension == 2 {
                d[2] = 0.0;
            }
            let value = match start {
                Start::Transform(t) => serde_json::to_value(translated(t, &d, h.dimension)).unwrap_or(Value::Null),
                Start::Coordinates(c) => {
                    let moved: Vec<f64> =
                        c.iter().enumerate().map(|(i, x)| x + if i < h.dimension { d[i] } else { 0.0 }).collect();
                    Value::from(moved)
                }
                Start::LocalPoint { local, path } => {
                    let inverse = self.locals[*local].3;
                    let dq = inverse.map(|row| row[0] * d[0] + row[1] * d[1] + row[2] * d[2]);
                    let point =
                        path.iter().try_fold(&mut locals[*local], |v, &i| v.get_mut(i)).and_then(Value::as_array_mut);
                    let Some(point) = point else {
                        return Err(EditError::Missing(format!("{}: no such control point", h.kind.field())));
                    };
                    for (x, dx) in point.iter_mut().zip(dq).take(h.dimension) {
                        *x = Value::from(x.as_f64().unwrap_or(0.0) + dx);
                    }
                    continue;
                }
            };
            edits.push(Edit::Set { object: h.object, pointer: h.kind.pointer(), value: Some(value) });
        }
        for ((object, pointer, _, _), value) in self.locals.iter().zip(locals) {
            edits.push(Edit::Set { object: *object, pointer: pointer.clone(), value: Some(value) });
        }
        Ok(Edit::Batch(edits))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: [f64; 3], b: [f64; 3]) -> bool {
        (0..3).all(|i| (a[i] - b[i]).abs() < 1e-12)
    }

    #[test]
    fn group_maps_translate_turn_and_scale_about_the_centre() {
        let c = [1.0, 1.0, 0.0];
        let turn = GroupMove::Rotate { center: c, axis: [0.0, 0.0, 1.0], angle: std::f64::consts::FRAC_PI_2 };
        assert!(close(turn.apply([2.0, 1.0, 0.0]), [1.0, 2.0, 0.0]));
        assert!(close(turn.apply(c), c));
        let scale = GroupMove::Scale { center: c, factor: 2.0 };
        assert!(close(scale.apply([2.0, 0.0, 1.0]), [3.0, -1.0, 2.0]));
        assert!(close(GroupMove::Translate([1.0, 2.0, 3.0]).apply([0.0; 3]), [1.0, 2.0, 3.0]));
    }
}
