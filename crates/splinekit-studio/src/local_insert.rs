//! Inserting a local piece into a blending spline from the window: a click on the selected
//! blending-spline curve inserts a local curve at the clicked parameter; on a blending
//! surface, a row of local patches along the u-isocurve through the click (Shift + click:
//! a column along the v-isocurve). One undoable edit of the object's whole `shape`, made by
//! the scene's [`insert_local_curve`] and [`insert_knot_line`] (the kernel's insertion:
//! the new local is the shape's Taylor-fitted Bézier there, so the shape changes only
//! between the neighbouring knots, within the bound the kernel states).
//!
//! The clicked parameters come from the same samples as knot insertion's
//! ([`crate::knot_edit::parameter_at`], [`crate::net_knot_edit::parameters_at`]).

use splinekit::surface::iso_curve::Direction;
use splinekit_scene::blending::{insert_knot_line, insert_local_curve};
use splinekit_scene::{CurveDocument, Decoration, ShapeDocument, SurfaceDocument};

use crate::edit::Edit;
use crate::error::StudioError;

/// Whether `shape` takes local insertions: a blending-spline curve or surface.
pub fn takes_locals(shape: &ShapeDocument) -> bool {
    match shape {
        ShapeDocument::Curve(c) => matches!(c.decoration(), Decoration::LocalCurves(_)),
        ShapeDocument::Surface(s) => matches!(s.decoration(), Decoration::LocalPatches(_)),
    }
}

fn whole_shape(object: usize, value: serde_json::Value) -> Edit {
    Edit::Set { object, pointer: "/shape".into(), value: Some(value) }
}

/// The edit inserting a local curve at `t` into object `object`'s blending spline.
pub fn insert_curve(shape: &ShapeDocument, object: usize, t: f64) -> Result<Edit, StudioError> {
    let ShapeDocument::Curve(CurveDocument::BlendingSpline(doc)) = shape else {
        return Err("insert local piece: select a blending spline (curve or surface)".into());
    };
    let (out, _) = insert_local_curve(doc, t).map_err(|e| StudioError::from(e).of_action("insert local piece"))?;
    Ok(whole_shape(object, CurveDocument::BlendingSpline(out).to_value()))
}

/// The edit inserting the knot line `direction` = `t` (a row of patches along the
/// u-isocurve for [`Direction::U`]) into object `object`'s blending surface.
pub fn insert_line(shape: &ShapeDocument, object: usize, direction: Direction, t: f64) -> Result<Edit, StudioError> {
    let ShapeDocument::Surface(SurfaceDocument::BlendingSplineSurface(doc)) = shape else {
        return Err("insert local piece: select a blending spline (curve or surface)".into());
    };
    let (out, _) =
        insert_knot_line(doc, direction, t).map_err(|e| StudioError::from(e).of_action("insert local piece"))?;
    Ok(whole_shape(object, SurfaceDocument::BlendingSplineSurface(out).to_value()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shape(json: serde_json::Value) -> ShapeDocument {
        ShapeDocument::from_value(json).expect("valid")
    }

    #[test]
    fn only_blending_splines_take_locals_and_the_edit_is_the_whole_shape() {
        let heart =
            shape(serde_json::json!({"type": "blending_spline", "model": {"type": "heart"}, "local_curves": 8}));
        assert!(takes_locals(&heart));
        let Edit::Set { pointer, value: Some(v), .. } = insert_curve(&heart, 2, 1.0).expect("inserts") else {
            panic!("a set")
        };
        assert_eq!((pointer.as_str(), &v["local_curves"]), ("/shape", &serde_json::json!(9)));
        let e = insert_curve(&heart, 2, 0.0).expect_err("on a knot").to_string();
        assert!(e.contains("insert local piece") && e.contains("got 0"), "{e}");
        let line = shape(serde_json::json!({"type": "line", "from": [0, 0], "to": [1, 0]}));
        assert!(!takes_locals(&line));
        assert!(insert_curve(&line, 0, 0.5).is_err());
        let torus = shape(serde_json::json!({"type": "blending_spline_surface", "model": {"type": "torus"},
            "local_surfaces": [4, 4]}));
        assert!(takes_locals(&torus));
        let Edit::Set { value: Some(v), .. } = insert_line(&torus, 0, Direction::V, 1.0).expect("inserts") else {
            panic!("a set")
        };
        assert_eq!(v["local_surfaces"], serde_json::json!([4, 5]));
        assert!(insert_line(&heart, 0, Direction::U, 1.0).is_err());
    }
}
