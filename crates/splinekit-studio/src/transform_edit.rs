//! Hand gestures on a local piece's transform document, composed exactly as the document
//! applies it (`x ↦ o + t + R·s·(x − o)` about the piece's origin o; scale, then rotate,
//! then translate): moving adds to `translate`, rotating about the moved origin composes
//! the rotation after `rotate` (axis–angle through unit quaternions in 3-D, added angles in
//! 2-D), scaling multiplies `scale`.

use nalgebra::{Unit, UnitQuaternion, Vector3};
use splinekit_scene::DocumentError;
use splinekit_scene::transforms::{RotateDoc, TransformDoc};

/// `t` moved by `delta` (world units, `dim` coordinates).
pub fn translated(t: &TransformDoc, delta: &[f64], dim: usize) -> TransformDoc {
    let mut out = t.clone();
    let mut v = t.translate.clone().unwrap_or_else(|| vec![0.0; dim]);
    v.resize(dim, 0.0);
    for (x, d) in v.iter_mut().zip(delta) {
        *x += d;
    }
    out.translate = Some(v);
    out
}

/// `t` followed by a rotation by `angle` radians about `axis` (3-D; ignored in 2-D) through
/// the moved origin. A transform rotating about a `pivot` is refused: composing about two
/// centres is not one `rotate` of the format.
pub fn rotated(
    t: &TransformDoc,
    field: &str,
    axis: [f64; 3],
    angle: f64,
    dim: usize,
) -> Result<TransformDoc, DocumentError> {
    let mut out = t.clone();
    let (old_axis, old_angle) = match &t.rotate {
        Some(r) if r.pivot.is_some() => {
            return Err(DocumentError::new(
                format!("{field}.rotate.pivot"),
                "rotating by hand turns about the local origin; remove the pivot first",
            ));
        }
        Some(r) => (r.axis.clone(), r.angle),
        None => (None, 0.0),
    };
    out.rotate = Some(if dim == 2 {
        RotateDoc { axis: None, angle: old_angle + angle, pivot: None }
    } else {
        let old = match old_axis.as_deref() {
            Some([x, y, z]) => rotation(Vector3::new(*x, *y, *z), old_angle),
            _ => UnitQuaternion::identity(),
        };
        let new = rotation(Vector3::new(axis[0], axis[1], axis[2]), angle) * old;
        let (axis, angle) = new.axis_angle().map_or(([0.0, 0.0, 1.0], 0.0), |(a, angle)| ([a.x, a.y, a.z], angle));
        RotateDoc { axis: Some(axis.to_vec()), angle, pivot: None }
    });
    Ok(out)
}

/// `t` scaled by `factor` about the moved origin.
pub fn scaled(t: &TransformDoc, factor: f64) -> TransformDoc {
    let mut out = t.clone();
    out.scale = Some(t.scale.unwrap_or(1.0) * factor);
    out
}

fn rotation(axis: Vector3<f64>, angle: f64) -> UnitQuaternion<f64> {
    if axis.norm() == 0.0 {
        return UnitQuaternion::identity();
    }
    UnitQuaternion::from_axis_angle(&Unit::new_normalize(axis), angle)
}

#[cfg(test)]
mod tests {
    use super::*;
    use splinekit::Point;

    fn apply(t: &TransformDoc, origin: Point<3>, x: Point<3>) -> Point<3> {
        t.build::<3>("t", &origin).expect("valid").apply_point_about(&origin, &x)
    }

    #[test]
    fn a_rotation_about_the_moved_origin_keeps_the_translation_and_turns_the_piece() {
        let o = Point::<3>::new(1.0, 2.0, 0.0);
        let t = translated(&TransformDoc::default(), &[0.5, 0.0, 0.0], 3);
        let r = rotated(&t, "t", [0.0, 0.0, 1.0], std::f64::consts::FRAC_PI_2, 3).expect("no pivot");
        // The origin stays at o + t; a point one unit along x from o turns to +y.
        assert!((apply(&r, o, o) - Point::<3>::new(1.5, 2.0, 0.0)).norm() < 1e-12);
        assert!((apply(&r, o, o + Point::<3>::x()) - Point::<3>::new(1.5, 3.0, 0.0)).norm() < 1e-12);
        // Two quarter turns compose to a half turn.
        let rr = rotated(&r, "t", [0.0, 0.0, 1.0], std::f64::consts::FRAC_PI_2, 3).expect("no pivot");
        assert!((apply(&rr, o, o + Point::<3>::x()) - Point::<3>::new(0.5, 2.0, 0.0)).norm() < 1e-12);
    }

    #[test]
    fn scaling_multiplies_and_a_pivot_is_refused_by_name() {
        let s = scaled(&scaled(&TransformDoc::default(), 2.0), 1.5);
        assert_eq!(s.scale, Some(3.0));
        let pivoted = TransformDoc {
            rotate: Some(RotateDoc { axis: None, angle: 0.1, pivot: Some(vec![0.0, 0.0]) }),
            ..Default::default()
        };
        let e = rotated(&pivoted, "transforms[3]", [0.0, 0.0, 1.0], 0.2, 2).expect_err("pivot");
        assert!(e.to_string().contains("transforms[3].rotate.pivot"), "{e}");
        let two_d = rotated(&TransformDoc::default(), "t", [0.0; 3], 0.25, 2).expect("2-D");
        assert_eq!(two_d.rotate.map(|r| r.angle), Some(0.25));
    }
}
