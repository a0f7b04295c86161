//! The selection: several handles at once (Shift+click adds or removes one, a box drawn
//! with Ctrl on empty space selects the handles inside it, A selects every shown handle of
//! the object, Escape clears), and moving them together: a map of world points (a
//! translation, a turn about the selection's centroid, a scaling about it) becomes one edit
//! of every selected value ([`GroupStart::edit`], one undo step).
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
use crate::view_camera::Projector;

/// The selected handles, in the order they were selected.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Selection {
    /// The handles.
    pub handles: Vec<Handle>,
}

fn same(a: &Handle, b: &Handle) -> bool {
    a.object == b.object && a.kind == b.kind
}

impl Selection {
    /// Whether `h` is selected.
    pub fn contains(&self, h: &Handle) -> bool {
        self.handles.iter().any(|s| same(s, h))
    }

    /// Adds `h`, or removes it when it was selected; `true` when it is now selected.
    pub fn toggle(&mut self, h: Handle) -> bool {
        match self.handles.iter().position(|s| same(s, &h)) {
            Some(i) => {
                self.handles.remove(i);
                false
            }
            None => {
                self.handles.push(h);
                true
            }
        }
    }

    /// Adds the handles not yet selected.
    pub fn extend(&mut self, hs: impl IntoIterator<Item = Handle>) {
        for h in hs {
            if !self.contains(&h) {
                self.handles.push(h);
            }
        }
    }

    /// The mean of the selected handles' positions.
    pub fn centroid(&self) -> Option<[f64; 3]> {
        centroid(&self.handles)
    }

    /// Moves the selected handles to where `now` has them; those gone are dropped.
    pub fn follow(&mut self, now: &[Handle]) {
        self.handles = self.handles.iter().filter_map(|h| now.iter().find(|n| same(n, h)).cloned()).collect();
    }
}

/// The mean of the handles' positions (`None` for none).
pub fn centroid(handles: &[Handle]) -> Option<[f64; 3]> {
    if handles.is_empty() {
        return None;
    }
    let n = handles.len() as f64;
    Some([0, 1, 2].map(|i| handles.iter().map(|h| h.position[i]).sum::<f64>() / n))
}

/// The handles whose projection lies in the box with corners `a` and `b` (view pixels).
pub fn in_box<'a>(
    handles: impl IntoIterator<Item = &'a Handle>,
    projector: &Projector,
    a: [f64; 2],
    b: [f64; 2],
) -> Vec<Handle> {
    let (lo, hi) = ([a[0].min(b[0]), a[1].min(b[1])], [a[0].max(b[0]), a[1].max(b[1])]);
    handles
        .into_iter()
        .filter(|h| {
            projector
                .project(h.position)
                .is_some_and(|(p, _)| (lo[0]..=hi[0]).contains(&p[0]) && (lo[1]..=hi[1]).contains(&p[1]))
        })
        .cloned()
        .collect()
}

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

    #[test]
    fn toggling_adds_and_removes() {
        let h = |i| Handle {
            object: 0,
            kind: crate::handles::HandleKind::ControlPoint(i, "control_points"),
            position: [i as f64, 0.0, 0.0],
            origin: [i as f64, 0.0, 0.0],
            dimension: 2,
        };
        let mut s = Selection::default();
        assert!(s.toggle(h(0)));
        assert!(s.toggle(h(2)));
        assert_eq!(s.centroid(), Some([1.0, 0.0, 0.0]));
        assert!(!s.toggle(h(0)));
        assert_eq!(s.handles, [h(2)]);
        s.extend([h(2), h(3)]);
        assert_eq!(s.handles.len(), 2);
        s.follow(&[h(3)]);
        assert_eq!(s.handles, [h(3)]);
    }
}
