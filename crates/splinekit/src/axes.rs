//! Right-handed orthonormal axes from an axis and a reference direction: the frame of an
//! `AXIS2_PLACEMENT_3D` (ISO 10303-42 `build_axes`) and of a `placed` surface document.
//!
//! z = axis/|axis|; x is the part of the reference direction d orthogonal to z,
//! x = (d − (d·z) z)/|d − (d·z) z|; y = z × x. The reference direction need not be unit
//! nor orthogonal to the axis, only not parallel to it.

use crate::error::{Error, Result};

/// A right-handed orthonormal frame (x × y = z).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OrthonormalAxes {
    /// The reference direction made orthogonal to z and unit.
    pub x: [f64; 3],
    /// z × x.
    pub y: [f64; 3],
    /// The unit axis.
    pub z: [f64; 3],
}

/// v/|v|; an error naming `field` when v is zero or not finite.
pub fn unit_vector(v: [f64; 3], field: &str) -> Result<[f64; 3]> {
    let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if !(n.is_finite() && n > 0.0) {
        return Err(Error::invalid(field, format!("must be a non-zero vector, got {v:?}")));
    }
    Ok(v.map(|c| c / n))
}

impl OrthonormalAxes {
    /// The frame with z along `axis` and x along the part of `ref_direction` orthogonal to
    /// it (errors name `axis` or `ref_direction`).
    pub fn build(axis: [f64; 3], ref_direction: [f64; 3]) -> Result<Self> {
        let z = unit_vector(axis, "axis")?;
        let d = unit_vector(ref_direction, "ref_direction")?;
        let dz = d[0] * z[0] + d[1] * z[1] + d[2] * z[2];
        let x = unit_vector(std::array::from_fn(|k| d[k] - dz * z[k]), "ref_direction").map_err(|_| {
            Error::invalid("ref_direction", format!("must not be parallel to the axis {axis:?}, got {ref_direction:?}"))
        })?;
        let y = [z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]];
        Ok(OrthonormalAxes { x, y, z })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
        a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    }

    #[test]
    fn frame_is_orthonormal_and_right_handed_for_a_skew_reference() {
        let f = OrthonormalAxes::build([0.0, 0.6, 0.8], [1.0, 2.0, -0.5]).unwrap();
        for (a, b) in [(f.x, f.y), (f.y, f.z), (f.z, f.x)] {
            assert!(dot(a, b).abs() < 1e-15);
        }
        for v in [f.x, f.y, f.z] {
            assert!((dot(v, v) - 1.0).abs() < 1e-15);
        }
        // x × y = z, and x lies in the plane of z and the reference direction.
        let xy =
            [f.x[1] * f.y[2] - f.x[2] * f.y[1], f.x[2] * f.y[0] - f.x[0] * f.y[2], f.x[0] * f.y[1] - f.x[1] * f.y[0]];
        assert!((0..3).all(|k| (xy[k] - f.z[k]).abs() < 1e-15));
        assert!(dot(f.y, [1.0, 2.0, -0.5]).abs() < 1e-14);
    }

    #[test]
    fn zero_and_parallel_directions_are_refused_by_field() {
        let e = OrthonormalAxes::build([0.0; 3], [1.0, 0.0, 0.0]).unwrap_err().to_string();
        assert!(e.starts_with("axis:"), "{e}");
        let e = OrthonormalAxes::build([0.0, 0.0, 2.0], [0.0, 0.0, -3.0]).unwrap_err().to_string();
        assert!(e.starts_with("ref_direction:") && e.contains("parallel"), "{e}");
        let e = OrthonormalAxes::build([0.0, 0.0, 1.0], [f64::NAN, 0.0, 0.0]).unwrap_err().to_string();
        assert!(e.starts_with("ref_direction:"), "{e}");
    }
}
