//! Transforms of local pieces: `{"translate":[..], "rotate":{"axis":[..],"angle":a}, "scale":s}`,
//! applied in the local piece's frame about its origin: scale, then rotate, then translate.

use serde::{Deserialize, Serialize};
use splinekit::frame::Affine;

use crate::error::{DocumentError, Result};

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
