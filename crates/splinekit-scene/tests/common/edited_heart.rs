//! What the blending-spline edit tests (insertion, knot split) share: the heart document
//! with moved, edited and animated locals, and reading and writing curve documents.

use splinekit_scene::blending::BlendingSplineDoc;
use splinekit_scene::{CurveDocument, ShapeDocument};

/// The heart with quadratic locals as in examples/scenes/heart_local_curves.json, plus a
/// moved local 4, an edited local 7 and an animated local 6.
pub const HEART: &str = r#"{"type": "blending_spline", "model": {"type": "heart"}, "local_curves": 10,
    "local": {"type": "bezier", "degree": 2},
    "transforms": {"4": {"translate": [0.5, -0.3, 0], "scale": 1.1}, "1": {"translate": [0, 1, 0]}},
    "local_control_points": {"7": [[-11, -6, 0], [-13, -3, 0.5], [-14, 1, 0]]},
    "animation": [{"local": 6, "motions": [{"pulse": {"amplitude": 0.2}}]}]}"#;

/// The blending-spline curve document of `json`.
pub fn curve_doc(json: &str) -> BlendingSplineDoc {
    match ShapeDocument::from_json(json).unwrap() {
        ShapeDocument::Curve(CurveDocument::BlendingSpline(d)) => d,
        _ => panic!("a blending spline"),
    }
}

/// `d` as JSON.
pub fn curve_value(d: &BlendingSplineDoc) -> serde_json::Value {
    CurveDocument::BlendingSpline(d.clone()).to_value()
}
