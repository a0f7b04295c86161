//! Transforms of local pieces: `{"translate":[..], "rotate":{"axis":[..],"angle":a}, "scale":s}`,
//! applied in the local piece's frame about its origin: scale, then rotate, then translate.

use serde::{Deserialize, Serialize};
use serde_json::Value;
use splinekit::frame::Affine;

use crate::error::{DocumentError, Result};
use crate::json::kind;
use crate::keyed;

/// A rotation: about `axis` (3-D) by `angle` radians; 2-D rotations give only the angle.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RotateDoc {
    /// Rotation axis (3-D only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axis: Option<Vec<f64>>,
    /// Angle in radians.
    pub angle: f64,
    /// A world point on the rotation axis (default: the local piece's origin).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pivot: Option<Vec<f64>>,
}

/// One transform.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct TransformDoc {
    /// Translation vector.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub translate: Option<Vec<f64>>,
    /// Rotation.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rotate: Option<RotateDoc>,
    /// Uniform scale factor.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scale: Option<f64>,
}

impl TransformDoc {
    /// The affine map translate ∘ rotate ∘ scale in dimension D, in coordinates centred on
    /// the local piece's `origin` (a rotation `pivot` is a world point).
    pub fn build<const D: usize>(&self, field: &str, origin: &splinekit::Point<D>) -> Result<Affine<D>> {
        let mut a = Affine::<D>::identity();
        if let Some(s) = self.scale {
            if !(s.is_finite() && s != 0.0) {
                return Err(DocumentError::new(
                    format!("{field}.scale"),
                    format!("must be finite and non-zero, got {s}"),
                ));
            }
            a = Affine::uniform_scale(s);
        }
        if let Some(r) = &self.rotate {
            if !r.angle.is_finite() {
                return Err(DocumentError::new(format!("{field}.rotate.angle"), "must be finite"));
            }
            if D == 3 && r.axis.is_none() {
                return Err(DocumentError::new(format!("{field}.rotate.axis"), "missing (3-D rotations need an axis)"));
            }
            let mut rot = Affine::<D>::rotation_in(r.axis.as_deref(), r.angle)
                .map_err(|e| DocumentError::new(format!("{field}.rotate"), e.to_string()))?;
            if let Some(p) = &r.pivot {
                let q = crate::points::to_point::<D>(&format!("{field}.rotate.pivot"), p)?;
                rot = rot.about(&(q - origin));
            }
            a = rot.after(&a);
        }
        if let Some(t) = &self.translate {
            a = Affine::translation(crate::points::to_point::<D>(&format!("{field}.translate"), t)?).after(&a);
        }
        Ok(a)
    }
}

/// Rest transforms of a blending-spline curve's locals, by local index.
pub type LocalTransforms = Vec<(usize, TransformDoc)>;

/// Rest transforms of a blending-spline surface's patches, by patch index (k, l).
pub type PatchTransforms = Vec<((usize, usize), TransformDoc)>;

/// Per-piece transforms as a document holds them: `null` (none), a list (read by `list`;
/// `what` names it in the message for other values) or an object keyed by the pieces'
/// indices (a key naming none is refused with `refusal`).
fn read<K: keyed::Key>(
    value: Value,
    what: &str,
    refusal: &str,
    list: impl FnOnce(&[Value]) -> Result<Vec<(K, TransformDoc)>>,
) -> Result<Vec<(K, TransformDoc)>> {
    match value {
        Value::Null => Ok(Vec::new()),
        Value::Array(items) => list(&items),
        Value::Object(map) => keyed::entries(map, refusal),
        other => Err(DocumentError::new("", format!("expected {what} or an object, got {}", kind(&other)))),
    }
}

/// Per-local transforms of a blending-spline curve (`with` module for serde): read from a
/// list (one per local, in order) or an object keyed by local index; written as the object.
pub mod by_index {
    use serde::Deserializer;

    use super::{LocalTransforms, read};
    use crate::json::{fields, nested};
    pub(crate) use crate::keyed::serialize;

    /// Reads `transforms`.
    pub fn deserialize<'de, D: Deserializer<'de>>(deserializer: D) -> std::result::Result<LocalTransforms, D::Error> {
        nested(deserializer, |value| {
            read(value, "a list", "keys must be local-curve indices", |list| {
                list.iter()
                    .enumerate()
                    .map(|(i, t)| Ok((i, fields(t.clone()).map_err(|e| e.within(&format!("[{i}]")))?)))
                    .collect()
            })
        })
    }
}

/// Per-patch transforms of a blending-spline surface (`with` module for serde): read from
/// rows (n_u lists of n_v transforms) or an object keyed by `"k,l"`; written as the object.
pub mod by_pair {
    use serde::Deserializer;
    use serde_json::Value;

    use super::{PatchTransforms, read};
    use crate::error::DocumentError;
    use crate::json::{fields, kind, nested};
    pub(crate) use crate::keyed::serialize;

    /// Reads `transforms`.
    pub fn deserialize<'de, D: Deserializer<'de>>(deserializer: D) -> std::result::Result<PatchTransforms, D::Error> {
        nested(deserializer, |value| {
            read(value, "a list of rows", "keys must be patch indices \"k,l\"", |rows| {
                let mut out = Vec::new();
                for (k, row) in rows.iter().enumerate() {
                    let Value::Array(row) = row else {
                        return Err(DocumentError::new(
                            format!("[{k}]"),
                            format!("expected a list of transforms (one row of patches), got {}", kind(row)),
                        ));
                    };
                    for (l, t) in row.iter().enumerate() {
                        out.push(((k, l), fields(t.clone()).map_err(|e| e.within(&format!("[{k}][{l}]")))?));
                    }
                }
                Ok(out)
            })
        })
    }
}
