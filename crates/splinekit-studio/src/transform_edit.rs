//! Hand gestures on a local piece's transform document, composed exactly as the document
//! applies it (`x ↦ o + t + R·s·(x − o)` about the piece's origin o; scale, then rotate,
//! then translate): moving adds to `translate`, rotating about the moved origin composes
//! the rotation after `rotate` (axis–angle through unit quaternions in 3-D, added angles in
//! 2-D; a rotation `pivot` stays, `translate` keeping the moved origin in place), scaling
//! multiplies `scale`.

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
/// the moved origin, for the piece whose rest origin is `origin`. A transform rotating
/// about a `pivot` keeps its pivot: the rotation composes as without one, and `translate`
/// takes up the difference so that the moved origin stays where it was (both moved
/// origins computed by the format's own [`TransformDoc::build`] and
/// [`Affine::apply_point_about`](splinekit::frame::Affine::apply_point_about)). A pivot
/// the format refuses is refused with its message.
pub fn rotated(
    t: &TransformDoc,
    field: &str,
    axis: [f64; 3],
    angle: f64,
    dim: usize,
    origin: [f64; 3],
) -> Result<TransformDoc, DocumentError> {
    let mut out = t.clone();
    let (old_axis, old_angle, pivot) = match &t.rotate {
        Some(r) => (r.axis.clone(), r.angle, r.pivot.clone()),
        None => (None, 0.0, None),
    };
    let has_pivot = pivot.is_some();
    out.rotate = Some(if dim == 2 {
        RotateDoc { axis: None, angle: old_angle + angle, pivot }
    } else {
        let old = match old_axis.as_deref() {
            Some([x, y, z]) => rotation(Vector3::new(*x, *y, *z), old_angle),
            _ => UnitQuaternion::identity(),
        };
        let new = rotation(Vector3::new(axis[0], axis[1], axis[2]), angle) * old;
        let (axis, angle) = new.axis_angle().map_or(([0.0, 0.0, 1.0], 0.0), |(a, angle)| ([a.x, a.y, a.z], angle));
        RotateDoc { axis: Some(axis.to_vec()), angle, pivot }
    });
    if has_pivot {
        let before = moved_origin(t, field, origin, dim)?;
        let after = moved_origin(&out, field, origin, dim)?;
        let shift: Vec<f64> = before.iter().zip(&after).map(|(b, a)| b - a).collect();
        out = translated(&out, &shift, dim);
    }
    Ok(out)
}

/// Where `t` puts the rest origin `origin` (the first `dim` coordinates), as the format
/// builds it.
fn moved_origin(t: &TransformDoc, field: &str, origin: [f64; 3], dim: usize) -> Result<Vec<f64>, DocumentError> {
    fn moved<const D: usize>(t: &TransformDoc, field: &str, origin: [f64; 3]) -> Result<Vec<f64>, DocumentError> {
        let o = splinekit::Point::<D>::from_fn(|i, _| origin[i]);
        Ok(t.build::<D>(field, &o)?.apply_point_about(&o, &o).as_slice().to_vec())
    }
    match dim {
        2 => moved::<2>(t, field, origin),
        3 => moved::<3>(t, field, origin),
        other => Err(DocumentError::new(field, format!("rotating by hand works in 2-D and 3-D, not {other}-D"))),
    }
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
        let r = rotated(&t, "t", [0.0, 0.0, 1.0], std::f64::consts::FRAC_PI_2, 3, [1.0, 2.0, 0.0]).expect("no pivot");
        // The origin stays at o + t; a point one unit along x from o turns to +y.
        assert!((apply(&r, o, o) - Point::<3>::new(1.5, 2.0, 0.0)).norm() < 1e-12);
        assert!((apply(&r, o, o + Point::<3>::x()) - Point::<3>::new(1.5, 3.0, 0.0)).norm() < 1e-12);
        // Two quarter turns compose to a half turn.
        let rr = rotated(&r, "t", [0.0, 0.0, 1.0], std::f64::consts::FRAC_PI_2, 3, [1.0, 2.0, 0.0]).expect("no pivot");
        assert!((apply(&rr, o, o + Point::<3>::x()) - Point::<3>::new(0.5, 2.0, 0.0)).norm() < 1e-12);
    }

    #[test]
    fn scaling_multiplies() {
        let s = scaled(&scaled(&TransformDoc::default(), 2.0), 1.5);
        assert_eq!(s.scale, Some(3.0));
        let two_d = rotated(&TransformDoc::default(), "t", [0.0; 3], 0.25, 2, [0.0; 3]).expect("2-D");
        assert_eq!(two_d.rotate.map(|r| r.angle), Some(0.25));
    }

    /// A transform turning about a pivot, rotated by hand: the pivot stays, the moved
    /// origin stays put, and a point of the piece turns about the moved origin by the
    /// angle (the new map is the old one followed by that rotation about the moved origin).
    #[test]
    fn a_rotation_of_a_pivoted_transform_turns_about_the_moved_origin() {
        use std::f64::consts::FRAC_PI_2;
        let o = Point::<3>::new(1.0, 2.0, 0.0);
        let t = TransformDoc {
            translate: Some(vec![0.5, 0.0, 0.25]),
            rotate: Some(RotateDoc { axis: Some(vec![0.0, 0.0, 1.0]), angle: 0.3, pivot: Some(vec![3.0, 1.0, 0.0]) }),
            scale: Some(1.5),
        };
        let r = rotated(&t, "t", [1.0, 0.0, 0.0], FRAC_PI_2, 3, [1.0, 2.0, 0.0]).expect("pivot kept");
        assert_eq!(r.rotate.as_ref().and_then(|r| r.pivot.clone()), Some(vec![3.0, 1.0, 0.0]));
        let m = apply(&t, o, o);
        assert!((apply(&r, o, o) - m).norm() < 1e-12);
        let turn = nalgebra::Rotation3::from_axis_angle(&Vector3::x_axis(), FRAC_PI_2);
        for x in [o + Point::<3>::x(), o + Point::<3>::new(0.3, -0.7, 2.0)] {
            let expected = m + turn * (apply(&t, o, x) - m);
            assert!((apply(&r, o, x) - expected).norm() < 1e-12, "{x}");
        }
        // 2-D: the angle adds, the pivot stays, the moved origin stays.
        let t2 = TransformDoc {
            rotate: Some(RotateDoc { axis: None, angle: 0.2, pivot: Some(vec![0.0, 0.0]) }),
            ..Default::default()
        };
        let r2 = rotated(&t2, "transforms[3]", [0.0, 0.0, 1.0], 0.5, 2, [1.0, 2.0, 0.0]).expect("2-D pivot");
        let o2 = Point::<2>::new(1.0, 2.0);
        let at = |t: &TransformDoc| t.build::<2>("t", &o2).expect("valid").apply_point_about(&o2, &o2);
        assert!((at(&r2) - at(&t2)).norm() < 1e-12);
        assert!((r2.rotate.map(|r| r.angle).unwrap_or_default() - 0.7).abs() < 1e-15);
        // A pivot the format refuses is refused by name.
        let bad = TransformDoc {
            rotate: Some(RotateDoc { axis: None, angle: 0.2, pivot: Some(vec![0.0]) }),
            ..Default::default()
        };
        let e = rotated(&bad, "transforms[3]", [0.0, 0.0, 1.0], 0.5, 2, [0.0; 3]).expect_err("a 1-D pivot");
        assert!(e.to_string().contains("transforms[3].rotate.pivot"), "{e}");
    }
}
