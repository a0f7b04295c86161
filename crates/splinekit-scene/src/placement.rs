//! Where a scene object stands: a rigid motion of its shape (how an assembly places each
//! part, and a part used several times is placed once per use).
//!
//! A scene object's `"placement": {"origin": o, "axis": a, "ref_direction": d}` is the
//! frame of an `AXIS2_PLACEMENT_3D` (ISO 10303-42 `build_axes`, [`OrthonormalAxes`]):
//! z = a/|a|, x = d made orthogonal to z and unit, y = z × x, and the object's point p is
//! drawn at o + p₁x + p₂y + p₃z. Rigid motions keep lengths, areas, volumes and chord
//! heights, so a shape is meshed and measured in its own frame and its mesh moved.

use serde::{Deserialize, Serialize};
use splinekit::axes::OrthonormalAxes;

use crate::defaults::{origin, x_axis, z_axis};
use crate::error::{DocumentError, Result};

/// A rigid motion p ↦ R p + t of 3-D space, in millimetres.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidTransform {
    /// The rotation R, row by row (`rotation[i][j]` = Rᵢⱼ; its columns are the images of
    /// the x, y and z axes).
    pub rotation: [[f64; 3]; 3],
    /// The translation t, in millimetres.
    pub translation: [f64; 3],
}

impl RigidTransform {
    /// The identity.
    pub const IDENTITY: RigidTransform =
        RigidTransform { rotation: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], translation: [0.0; 3] };

    /// The frame with origin `o` and unit axes `x`, `y`, `z` as a map from frame
    /// coordinates: p ↦ o + p₁x + p₂y + p₃z.
    pub fn frame(o: [f64; 3], x: [f64; 3], y: [f64; 3], z: [f64; 3]) -> RigidTransform {
        RigidTransform { rotation: std::array::from_fn(|i| [x[i], y[i], z[i]]), translation: o }
    }

    /// R p + t.
    pub fn apply(&self, p: [f64; 3]) -> [f64; 3] {
        std::array::from_fn(|i| self.rotation[i].iter().zip(p).map(|(r, c)| r * c).sum::<f64>() + self.translation[i])
    }

    /// R v (a direction).
    pub fn apply_vector(&self, v: [f64; 3]) -> [f64; 3] {
        std::array::from_fn(|i| self.rotation[i].iter().zip(v).map(|(r, c)| r * c).sum())
    }

    /// self ∘ inner: first `inner`, then `self` (p ↦ R(R′p + t′) + t).
    pub fn compose(&self, inner: &RigidTransform) -> RigidTransform {
        let rotation = std::array::from_fn(|i| {
            std::array::from_fn(|j| (0..3).map(|k| self.rotation[i][k] * inner.rotation[k][j]).sum())
        });
        RigidTransform { rotation, translation: self.apply(inner.translation) }
    }

    /// The inverse p ↦ Rᵀ(p − t) (R is orthonormal).
    pub fn inverse(&self) -> RigidTransform {
        let rotation: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| self.rotation[j][i]));
        let t = RigidTransform { rotation, translation: [0.0; 3] }.apply(self.translation);
        RigidTransform { rotation, translation: t.map(|c| -c) }
    }
}

/// `"placement"` of a scene object (see the module).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlacementDoc {
    /// Where the shape's origin goes (default the origin).
    #[serde(default = "origin")]
    pub origin: Vec<f64>,
    /// Where its z axis goes (default z).
    #[serde(default = "z_axis")]
    pub axis: Vec<f64>,
    /// Where its x axis goes, up to the part along `axis` (default x).
    #[serde(default = "x_axis")]
    pub ref_direction: Vec<f64>,
}

fn three(field: &str, v: &[f64]) -> Result<[f64; 3]> {
    match v {
        [x, y, z] if v.iter().all(|c| c.is_finite()) => Ok([*x, *y, *z]),
        _ => Err(DocumentError::new(field, format!("expected 3 finite coordinates, got {v:?}"))),
    }
}

impl PlacementDoc {
    /// The rigid motion (errors name `origin`, `axis` or `ref_direction`).
    pub fn transform(&self) -> Result<RigidTransform> {
        let o = three("origin", &self.origin)?;
        let (axis, reference) = (three("axis", &self.axis)?, three("ref_direction", &self.ref_direction)?);
        let OrthonormalAxes { x, y, z } = OrthonormalAxes::build(axis, reference)?;
        Ok(RigidTransform::frame(o, x, y, z))
    }

    /// The placement of a rigid motion: its translation, and the images of z and x.
    pub fn of(t: &RigidTransform) -> PlacementDoc {
        let column = |j: usize| (0..3).map(|i| t.rotation[i][j]).collect::<Vec<f64>>();
        PlacementDoc { origin: t.translation.to_vec(), axis: column(2), ref_direction: column(0) }
    }
}
