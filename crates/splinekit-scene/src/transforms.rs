//! Transforms of local pieces: `{"translate":[..], "rotate":{"axis":[..],"angle":a}, "scale":s}`,
//! applied in the local piece's frame about its origin: scale, then rotate, then translate.

use serde::{Deserialize, Serialize};
use splinekit::Point;
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
    /// The affine map translate ∘ rotate ∘ scale in dimension D.
    pub fn build<const D: usize>(&self, field: &str) -> Result<Affine<D>> {
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
            let rot = match D {
                2 => {
                    let (s, c) = r.angle.sin_cos();
                    let mut m = nalgebra::SMatrix::<f64, D, D>::identity();
                    m[(0, 0)] = c;
                    m[(0, 1)] = -s;
                    m[(1, 0)] = s;
                    m[(1, 1)] = c;
                    Affine { linear: m, translation: Point::<D>::zeros() }
                }
                3 => {
                    let axis = r.axis.as_ref().ok_or_else(|| {
                        DocumentError::new(format!("{field}.rotate.axis"), "missing (3-D rotations need an axis)")
                    })?;
                    let axis = crate::points::to_point::<3>(&format!("{field}.rotate.axis"), axis)?;
                    let r3 = Affine::rotation(axis, r.angle)
                        .map_err(|e| DocumentError::new(format!("{field}.rotate"), e.to_string()))?;
                    let mut m = nalgebra::SMatrix::<f64, D, D>::identity();
                    for i in 0..3 {
                        for j in 0..3 {
                            m[(i, j)] = r3.linear[(i, j)];
                        }
                    }
                    Affine { linear: m, translation: Point::<D>::zeros() }
                }
                _ => {
                    return Err(DocumentError::new(
                        format!("{field}.rotate"),
                        format!("rotations are defined for 2-D and 3-D, not {D}-D"),
                    ));
                }
            };
            a = rot.after(&a);
        }
        if let Some(t) = &self.translate {
            a = Affine::translation(crate::points::to_point::<D>(&format!("{field}.translate"), t)?).after(&a);
        }
        Ok(a)
    }
}
