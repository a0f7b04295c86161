//! `trochoid` documents: the default spirograph, explicit turns, and the fields' errors.

use serde_json::json;
use splinekit::curve::Curve;
use splinekit_scene::{CurveDocument, Curves, DimensionVisitor};

/// The domain's end and whether the curve is closed.
struct Extent;

impl DimensionVisitor<Curves> for Extent {
    type Output = (f64, bool);
    fn visit<const D: usize>(self, c: &dyn Curve<D>) -> (f64, bool) {
        (c.domain().end, c.is_closed())
    }
}

fn extent(doc: serde_json::Value) -> Result<(f64, bool), String> {
    let doc = CurveDocument::parse(&doc).map_err(|e| e.to_string())?;
    Ok(doc.build().map_err(|e| e.to_string())?.visit(Extent))
}

#[test]
fn the_domain_is_the_period_unless_turns_are_given() {
    let tau = std::f64::consts::TAU;
    // R/r = 5/3: three turns of the rolling circle's centre.
    assert_eq!(extent(json!({"type": "trochoid"})), Ok((3.0 * tau, true)));
    assert_eq!(extent(json!({"type": "trochoid", "rolling": "outside", "rolling_radius": 2})), Ok((2.0 * tau, true)));
    assert_eq!(extent(json!({"type": "trochoid", "turns": 6})), Ok((6.0 * tau, true)));
    assert_eq!(extent(json!({"type": "trochoid", "turns": 2})), Ok((2.0 * tau, false)));
    assert_eq!(
        extent(json!({"type": "trochoid", "fixed_radius": std::f64::consts::PI, "turns": 4.5})),
        Ok((4.5 * tau, false))
    );
}

#[test]
fn bad_fields_are_named() {
    let err = |doc| extent(doc).unwrap_err();
    assert!(err(json!({"type": "trochoid", "fixed_radius": std::f64::consts::PI})).starts_with("rolling_radius:"));
    assert!(err(json!({"type": "trochoid", "rolling": "sideways"})).starts_with("rolling: unknown variant `sideways`"));
    assert!(err(json!({"type": "trochoid", "rolling_radius": 5})).starts_with("rolling_radius:"));
    assert!(err(json!({"type": "trochoid", "distance": -1, "turns": 0})).starts_with("turns:"));
    assert!(err(json!({"type": "trochoid", "R": 5})).starts_with("R: unknown field"));
}
