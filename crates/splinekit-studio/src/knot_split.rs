//! Splitting a knot of a blending-spline curve from the window: with a local curve of the
//! selected blending spline selected, its knot splits at once; otherwise the next click on
//! the curve splits the interior knot nearest the clicked parameter (one not already
//! double). One undoable edit of the object's whole `shape`, made by the scene's
//! [`split_local_curve`] (the kernel's split: the knot doubled, the local copied, the
//! curve unchanged).
//!
//! The two copies' handles then sit on their own local curves a third (the first copy)
//! and half (the second) of the way from the joint to the neighbouring knots
//! ([`crate::handles`]), and a drag turns and scales the
//! copy about the joint ([`crate::gesture`]), so the curve keeps its point there: a
//! corner, C⁰.
//!
//! The clicked parameter comes from the same samples as knot insertion's
//! ([`crate::knot_edit::parameter_at`]).

use splinekit_scene::blending::{BlendingSplineDoc, knot_to_split, split_local_curve};
use splinekit_scene::{CurveDocument, ShapeDocument};

use crate::edit::Edit;
use crate::error::StudioError;

/// What Split knot says when the selection is not a blending-spline curve.
pub const SELECT_A_BLENDING_CURVE: &str = "split knot: select a blending-spline curve first";

/// The blending-spline curve document of `shape`, or the message saying what to select.
fn blending_curve(shape: &ShapeDocument) -> Result<&BlendingSplineDoc, StudioError> {
    match shape {
        ShapeDocument::Curve(CurveDocument::BlendingSpline(doc)) => Ok(doc),
        _ => Err(SELECT_A_BLENDING_CURVE.into()),
    }
}

/// Whether `shape` is a blending-spline curve (whose knots split).
pub fn splits(shape: &ShapeDocument) -> bool {
    blending_curve(shape).is_ok()
}

/// The edit splitting knot `k` of object `object`'s blending-spline curve (local k is
/// copied to k + 1).
pub fn split_local(shape: &ShapeDocument, object: usize, k: usize) -> Result<Edit, StudioError> {
    let out = split_local_curve(blending_curve(shape)?, k).map_err(|e| StudioError::from(e).of_action("split knot"))?;
    Ok(Edit::Set { object, pointer: "/shape".into(), value: Some(CurveDocument::BlendingSpline(out).to_value()) })
}

/// The edit splitting the interior knot nearest the parameter `t` (not already double) of
/// object `object`'s blending-spline curve, and that knot's index.
pub fn split_near(shape: &ShapeDocument, object: usize, t: f64) -> Result<(Edit, usize), StudioError> {
    let k = knot_to_split(blending_curve(shape)?, t).map_err(|e| StudioError::from(e).of_action("split knot"))?;
    Ok((split_local(shape, object, k)?, k))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_blending_curves_split_and_the_edit_is_the_whole_shape() {
        let heart = ShapeDocument::from_value(
            serde_json::json!({"type": "blending_spline", "model": {"type": "heart"}, "local_curves": 8}),
        )
        .expect("valid");
        assert!(splits(&heart));
        let step = std::f64::consts::TAU / 8.0;
        let (Edit::Set { pointer, value: Some(v), .. }, k) = split_near(&heart, 2, 2.9 * step).expect("splits") else {
            panic!("a set")
        };
        assert_eq!((pointer.as_str(), k, &v["local_curves"]), ("/shape", 3, &serde_json::json!(9)));
        assert_eq!(v["knots"][3], v["knots"][4]);
        let e = split_local(&heart, 2, 0).expect_err("knot 0 is an end").to_string();
        assert!(e.starts_with("split knot: k:") && e.contains("got 0"), "{e}");
        let line = ShapeDocument::from_value(serde_json::json!({"type": "line", "from": [0, 0], "to": [1, 0]}))
            .expect("valid");
        assert!(!splits(&line));
        assert!(split_near(&line, 0, 0.5).is_err());
    }
}
