//! `subdivision_surface` documents in STEP: exact bicubic patches on regular faces, bilinear
//! stand-ins within the tolerance around extraordinary vertices.

use splinekit::subdivision::surface::bezier_patches::limit_patches;
use splinekit_scene::surfaces::{SchemeDoc, SubdivisionSurfaceDoc};
use splinekit_scene::{SceneOrShape, ShapeDocument, SurfaceDocument};
use splinekit_step::documents::export_document;
use splinekit_step::documents::subdivision::{MAX_DEPTH, subdivision_patches};
use splinekit_step::part21::writer::HeaderInfo;

fn shape(doc: SubdivisionSurfaceDoc) -> SceneOrShape {
    SceneOrShape::Shape(ShapeDocument::Surface(SurfaceDocument::SubdivisionSurface(doc)))
}

/// The cube [−1, 1]³ (size 2√3): the fewest levels whose stand-ins are within the
/// tolerance, one STEP item per patch, and the level before does not meet it.
#[test]
fn the_cube_exports_as_its_patches_within_the_tolerance() {
    let doc = SubdivisionSurfaceDoc::cube();
    let size = 2.0 * 3f64.sqrt();
    for relative in [1e-2, 1e-3] {
        let (patches, depth) = subdivision_patches(&doc, relative).unwrap();
        assert!(patches.max_deviation <= relative * size && !patches.bilinear.is_empty());
        let s = doc.subdivision_surface().unwrap();
        if depth > 1 {
            assert!(limit_patches(&s, depth - 1).unwrap().max_deviation > relative * size, "depth {depth}");
        }
        let (text, exported) = export_document(&shape(doc.clone()), "cube", relative, &HeaderInfo::default()).unwrap();
        assert_eq!(exported.len(), patches.bicubic.len() + patches.bilinear.len());
        assert!(text.matches("B_SPLINE_SURFACE").count() >= exported.len());
    }
    let err = subdivision_patches(&doc, 1e-12).unwrap_err().to_string();
    assert!(err.contains("tolerance") && err.contains(&format!("after {MAX_DEPTH} levels")), "{err}");
}

/// Loop and bilinear limits are refused, naming the scheme.
#[test]
fn only_catmull_clark_exports() {
    let mut doc = SubdivisionSurfaceDoc::cube();
    doc.scheme = SchemeDoc::Bilinear;
    let err = export_document(&shape(doc), "x", 1e-3, &HeaderInfo::default()).unwrap_err().to_string();
    assert!(err.contains("scheme") && err.contains("bilinear"), "{err}");
}
