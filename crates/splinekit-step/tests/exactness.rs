//! `exports_exactly` says, without fitting anything, what the export then reports: every
//! object of the exact-forms scene leaves exactly, and shapes without an exact STEP form are
//! approximated.

use splinekit_scene::{SceneOrShape, ShapeDocument};
use splinekit_step::documents::{Form, export_document, export_shape, exports_exactly};
use splinekit_step::part21::writer::HeaderInfo;

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

/// Every kind of the registry: what its declared exact form promises, the export does (an
/// exact kind's example leaves exactly, measured at 0 deviation; the others are approximated
/// or, blending splines, exact as polynomials).
#[test]
fn every_kinds_example_exports_as_its_form_says() {
    use splinekit_scene::{CurveDocument, CurveForm, SurfaceDocument, SurfaceForm};
    // STEP geometry is 2-D or 3-D (a B-function is a 1-D curve).
    for doc in CurveDocument::examples().into_iter().filter(|d| matches!(d.dimension(), Ok(2 | 3))) {
        let promised = !matches!(doc.exact_form().unwrap(), CurveForm::Approximate | CurveForm::BlendingSpline(_));
        let e = export_shape(&ShapeDocument::Curve(doc.clone()), "x", 1e-4).unwrap();
        if promised {
            assert_eq!((e.form.clone(), e.max_deviation), (Form::Exact, 0.0), "{}", doc.type_name());
        }
    }
    for doc in SurfaceDocument::examples() {
        let form = doc.exact_form().unwrap();
        let promised = matches!(
            form,
            SurfaceForm::Spline(_)
                | SurfaceForm::Plane { .. }
                | SurfaceForm::Cylinder { .. }
                | SurfaceForm::Cone { .. }
                | SurfaceForm::Sphere { .. }
                | SurfaceForm::Torus { .. }
        );
        // Through the document export, which writes a subdivision surface as its patches.
        let shape = SceneOrShape::Shape(ShapeDocument::Surface(doc.clone()));
        let (_, items) = export_document(&shape, "x", 1e-4, &HeaderInfo::default()).unwrap();
        if promised {
            assert_eq!(items.len(), 1, "{}", doc.type_name());
            assert_eq!((items[0].form.clone(), items[0].max_deviation), (Form::Exact, 0.0), "{}", doc.type_name());
        }
        if matches!(form, SurfaceForm::Approximate) {
            // Approximated as one item, or as pieces each written exactly (a limit surface's
            // Bézier patches, the ones at extraordinary vertices standing in within the
            // tolerance).
            if items.len() == 1 {
                assert_eq!(items[0].form, Form::Approximated, "{}", doc.type_name());
            } else {
                assert!(items.iter().all(|e| e.form == Form::Exact), "{}", doc.type_name());
            }
        }
    }
}
