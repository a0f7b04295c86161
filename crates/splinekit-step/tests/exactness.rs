//! `exports_exactly` says, without fitting anything, what the export then reports: every
//! object of the exact-forms scene leaves exactly, and shapes without an exact STEP form are
//! approximated.

use splinekit_scene::{SceneOrShape, ShapeDocument};
use splinekit_step::documents::{Form, export_shape, exports_exactly};

fn shapes(json: &str) -> Vec<ShapeDocument> {
    match SceneOrShape::from_json(json).unwrap() {
        SceneOrShape::Scene(s) => s.objects.into_iter().map(|o| o.shape).collect(),
        SceneOrShape::Shape(s) => vec![s],
    }
}

#[test]
fn exports_exactly_agrees_with_the_export() {
    let mut docs = shapes(include_str!("../../../tests/step/shapes/exact_forms.json"));
    for json in [
        r#"{"type":"heart"}"#,
        r#"{"type":"helix"}"#,
        r#"{"type":"catmull_rom","points":[[0,0],[1,1],[2,0],[3,1]]}"#,
        r#"{"type":"revolution","curve":{"type":"heart","scale":0.1}}"#,
        r#"{"type":"mobius"}"#,
        r#"{"type":"blending_spline","model":{"type":"circle"},"local_curves":6}"#,
    ] {
        docs.extend(shapes(json));
    }
    let (mut exact, mut approximated) = (0, 0);
    for doc in &docs {
        let form = export_shape(doc, "x", 1e-4).unwrap().form;
        let said = exports_exactly(doc);
        assert_eq!(said, form != Form::Approximated, "{doc:?}: exports_exactly says {said}, the export {form:?}");
        if said { exact += 1 } else { approximated += 1 }
    }
    assert!(exact >= 14 && approximated >= 6, "{exact} exact, {approximated} approximated");
}
