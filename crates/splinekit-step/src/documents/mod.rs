//! The thin layer between splinekit's JSON documents and STEP geometry: export of shape
//! and scene documents, import of STEP items as shape documents.

pub mod curve_export;
pub mod export;
pub mod exported;
pub mod faces;
pub mod subdivision;

pub use curve_export::export_curve;
pub use export::{Sample, export_shape, export_surface, export_triangles, exports_exactly, samples};
pub use exported::{Exported, Form, ParamMap};

use splinekit_scene::placement::PlacementDoc;
use splinekit_scene::{SceneOrShape, ShapeDocument, SurfaceForm};

use crate::placement::Placement;

use crate::error::{Result, StepError};
use crate::export::write_step;
use crate::part21::writer::HeaderInfo;

/// The name of a scene's object `index` (1-based in the name) of a shape type.
pub fn object_name(index: usize, shape: &ShapeDocument) -> String {
    let ty = match shape {
        ShapeDocument::Curve(c) => c.type_name().to_string(),
        ShapeDocument::Surface(s) => s.to_value()["type"].as_str().unwrap_or("surface").to_string(),
    };
    format!("object {} ({ty})", index + 1)
}

/// One piece of an exported document: the shape whose parameters the items' `domain` and
/// `map` refer to (after subdivision surfaces and breps are expanded), and the STEP items it
/// left — one for most shapes, one per triangle for surfaces made of triangles.
#[derive(Debug, Clone)]
pub struct ExportedPiece {
    /// The expanded shape document the items were written from.
    pub shape: ShapeDocument,
    /// What was written for it, in file order (moved by `placement`).
    pub items: Vec<Exported>,
    /// The scene object's placement, which moved the items: `shape`'s points are where
    /// the placement takes them.
    pub placement: Option<Placement>,
}

/// Exports a scene (one piece per object, named after it) or a single shape (named
/// `name`) piece by piece: subdivision surfaces are first replaced by their patches
/// ([`subdivision::expand_subdivision_surfaces`]) and breps by their faces
/// ([`solid::expand_breps`]), one piece each; a surface made of triangles leaves one item
/// per triangle. A report or a judge pairs each item with `piece.shape`.
pub fn export_pieces(doc: &SceneOrShape, name: &str, relative_tolerance: f64) -> Result<Vec<ExportedPiece>> {
    let expanded = solid::expand_breps(&subdivision::expand_subdivision_surfaces(doc, relative_tolerance)?)?;
    let piece = |shape: &ShapeDocument, name: &str, placement: Option<&PlacementDoc>| -> Result<ExportedPiece> {
        let mut items = match shape {
            ShapeDocument::Surface(s) if matches!(s.exact_form(), Ok(SurfaceForm::Triangles)) => {
                export_triangles(s, name, relative_tolerance)?
            }
            _ => vec![export_shape(shape, name, relative_tolerance)?],
        };
        let placement = placement
            .map(|p| p.transform().map(|t| Placement::of_transform(&t)))
            .transpose()
            .map_err(|e| StepError::plain(format!("placement: {e}")))?;
        if let Some(p) = &placement {
            for e in &mut items {
                e.item.geometry = p.geometry(&e.item.geometry);
            }
        }
        Ok(ExportedPiece { shape: shape.clone(), items, placement })
    };
    match &expanded {
        SceneOrShape::Shape(shape) => Ok(vec![piece(shape, name, None)?]),
        SceneOrShape::Scene(scene) => scene
            .objects
            .iter()
            .enumerate()
            .map(|(i, o)| {
                piece(&o.shape, &object_name(i, &o.shape), o.placement.as_ref())
                    .map_err(|e| StepError::plain(format!("objects[{i}]: {}", e.message)))
            })
            .collect(),
    }
}

/// Exports a document as one STEP file ([`export_pieces`], flattened): returns the text
/// and what was measured per item.
pub fn export_document(
    doc: &SceneOrShape,
    name: &str,
    relative_tolerance: f64,
    header: &HeaderInfo,
) -> Result<(String, Vec<Exported>)> {
    let exported: Vec<Exported> =
        export_pieces(doc, name, relative_tolerance)?.into_iter().flat_map(|piece| piece.items).collect();
    let items: Vec<_> = exported.iter().map(|e| e.item.clone()).collect();
    Ok((write_step(&items, name, header), exported))
}

pub mod import;
pub mod instances;
pub mod solid;
pub use import::{ImportedDocuments, ImportedItem, import_items};
