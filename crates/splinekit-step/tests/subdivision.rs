//! `subdivision_surface` documents in STEP: exact bicubic (Catmull–Clark) and (4, 4)
//! (Loop) patches on regular faces, bilinear
//! stand-ins within the tolerance around extraordinary vertices, the faces there refined
//! locally as deep as the tolerance needs (up to 30 levels).

use splinekit::subdivision::surface::bezier_patches::{LimitPatches, limit_patches};
use splinekit_scene::surfaces::{SchemeDoc, SubdivisionSurfaceDoc};
use splinekit_scene::{SceneOrShape, ShapeDocument, SurfaceDocument};
use splinekit_step::documents::export_document;
use splinekit_step::documents::subdivision::{MAX_DEPTH, subdivision_patches};
use splinekit_step::part21::writer::HeaderInfo;

fn shape(doc: SubdivisionSurfaceDoc) -> SceneOrShape {
    SceneOrShape::Shape(ShapeDocument::Surface(SurfaceDocument::SubdivisionSurface(doc)))
}

/// The patches of `doc` within `relative` × 2√3 (the diagonal of the cube [−1, 1]³): within it, with bilinear stand-ins
/// around the extraordinary vertices, and one level less is not within it; with `export`
/// also written as STEP, one lossless item per patch (`exact` counts the exact ones).
fn check_patches(
    name: &str,
    doc: &SubdivisionSurfaceDoc,
    relative: f64,
    export: bool,
    exact: fn(&LimitPatches) -> usize,
) -> LimitPatches {
    let size = 2.0 * 3f64.sqrt();
    let (patches, depth) = subdivision_patches(doc, relative).unwrap();
    assert!(patches.max_deviation <= relative * size && !patches.bilinear.is_empty());
    let s = doc.subdivision_surface().unwrap();
    assert!(limit_patches(&s, depth - 1).unwrap().max_deviation > relative * size, "{name}: depth {depth}");
    if export {
        let (text, exported) = export_document(&shape(doc.clone()), name, relative, &HeaderInfo::default()).unwrap();
        assert_eq!(exported.len(), exact(&patches) + patches.bilinear.len());
        assert!(exported.iter().all(|e| e.max_deviation == 0.0));
        assert!(text.matches("B_SPLINE_SURFACE").count() >= exported.len());
    }
    eprintln!(
        "{name} within {relative:e}: depth {depth}, {} exact + {} bilinear patches, deviation {:.2e}",
        exact(&patches),
        patches.bilinear.len(),
        patches.max_deviation / size
    );
    patches
}

/// `examples/meshes/creased_cube.obj` as a document (its sharp top ring and semi-sharp
/// bottom edge as the document's creases).
fn creased_cube() -> SubdivisionSurfaceDoc {
    let folder = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/meshes"));
    let doc =
        SceneOrShape::from_json_in(r#"{"type": "subdivision_surface", "obj": "creased_cube.obj"}"#, folder).unwrap();
    match doc {
        SceneOrShape::Shape(ShapeDocument::Surface(SurfaceDocument::SubdivisionSurface(d))) => d,
        other => panic!("not a subdivision surface: {other:?}"),
    }
}

/// The cube [−1, 1]³ and the creased cube (size 2√3) at the default tolerance 10⁻⁶, the
/// cube also at 10⁻⁸ (the creased cube's is in splinekit's tests): the fewest levels whose stand-ins are within the tolerance, and one level
/// less does not meet it; the cube at 10⁻⁶ as one STEP item per patch (all exact).
#[test]
fn cubes_export_as_their_patches_within_the_tolerance() {
    for (name, doc, tolerances) in
        [("cube", SubdivisionSurfaceDoc::cube(), &[1e-6, 1e-8][..]), ("creased cube", creased_cube(), &[1e-6][..])]
    {
        assert!(!doc.creases.is_empty() || name == "cube");
        for &relative in tolerances {
            // Written at the default tolerance, the cube's (the creased cube's through
            // `subdivide-surface --tolerance 1e-6` in splinekit-cli; writing a thousand
            // patches takes long in a debug build).
            let export = relative == 1e-6 && name == "cube";
            check_patches(name, &doc, relative, export, |p| p.bicubic.len());
        }
    }
}

/// A tolerance that 30 levels do not reach is refused naming it and the one they reach,
/// and asking for that one succeeds.
#[test]
fn an_unreachable_tolerance_names_the_reachable_one() {
    let doc = SubdivisionSurfaceDoc::cube();
    let err = subdivision_patches(&doc, 1e-15).unwrap_err().to_string();
    assert!(err.contains("tolerance") && err.contains(&format!("after {MAX_DEPTH} levels")), "{err}");
    assert!(err.contains("relative 1.0e-15"), "{err}");
    let reachable: f64 = err.rsplit("at least ").next().unwrap().trim().parse().unwrap();
    assert!(reachable > 1e-15 && reachable < 1e-11, "{err}");
    let (patches, depth) = subdivision_patches(&doc, reachable).unwrap();
    assert!(depth <= MAX_DEPTH && patches.max_deviation <= reachable * 2.0 * 3f64.sqrt());
    for bad in [0.0, -1e-3, f64::NAN] {
        let err = subdivision_patches(&doc, bad).unwrap_err().to_string();
        assert!(err.starts_with("tolerance:"), "{err}");
    }
}

/// The cube's cage under Loop (its faces split into fans: corners of valence 3 to 6) at
/// relative 10⁻⁴ and 10⁻⁶: the fewest levels meeting the tolerance, one level less not;
/// at 10⁻⁴ as one STEP item per patch, the exact (4, 4) patches with a collapsed edge
/// and the flat triangles written without loss.
#[test]
fn loop_surfaces_export_within_the_tolerance() {
    let mut doc = SubdivisionSurfaceDoc::cube();
    doc.scheme = SchemeDoc::Loop;
    doc.triangulate = true;
    for relative in [1e-4, 1e-6] {
        let patches = check_patches("loop cube", &doc, relative, relative == 1e-4, |p| p.quartic.len());
        assert!(patches.bicubic.is_empty() && !patches.quartic.is_empty());
    }
}

/// The bilinear limit is its faces: the cube as 6 exact bilinear patches.
#[test]
fn bilinear_exports_its_faces() {
    let mut doc = SubdivisionSurfaceDoc::cube();
    doc.scheme = SchemeDoc::Bilinear;
    let (patches, depth) = subdivision_patches(&doc, 1e-6).unwrap();
    assert_eq!((patches.bilinear.len(), patches.max_deviation, depth), (6, 0.0, 0));
    let (text, exported) = export_document(&shape(doc), "x", 1e-6, &HeaderInfo::default()).unwrap();
    assert_eq!(exported.len(), 6);
    assert_eq!(text.matches("B_SPLINE_SURFACE_WITH_KNOTS(").count(), 6);
}
