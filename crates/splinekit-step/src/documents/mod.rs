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

use splinekit_scene::{SceneOrShape, ShapeDocument, SurfaceForm};

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

/// Exports a scene (one item per object, named after it) or a single shape (named
/// `name`) as one STEP file; returns the text and what was measured per item. Subdivision
/// surfaces are first replaced by their patches ([`subdivision::expand_subdivision_surfaces`]),
/// one item each.
pub fn export_document(
    doc: &SceneOrShape,
    name: &str,
    relative_tolerance: f64,
    header: &HeaderInfo,
) -> Result<(String, Vec<Exported>)> {
    let expanded = solid::expand_breps(&subdivision::expand_subdivision_surfaces(doc, relative_tolerance)?)?;
    // Documents of several triangles give one item per triangle.
    let items_of = |shape: &ShapeDocument, name: &str| -> Result<Vec<Exported>> {
        match shape {
            ShapeDocument::Surface(s) if matches!(s.exact_form(), Ok(SurfaceForm::Triangles)) => {
                export_triangles(s, name, relative_tolerance)
            }
            _ => Ok(vec![export_shape(shape, name, relative_tolerance)?]),
        }
    };
    let exported: Vec<Exported> = match &expanded {
        SceneOrShape::Shape(shape) => items_of(shape, name)?,
        SceneOrShape::Scene(scene) => {
            let mut all = Vec::new();
            for (i, o) in scene.objects.iter().enumerate() {
                let n = object_name(i, &o.shape);
                all.extend(
                    items_of(&o.shape, &n).map_err(|e| StepError::plain(format!("objects[{i}]: {}", e.message)))?,
                );
            }
            all
        }
    };
    let items: Vec<_> = exported.iter().map(|e| e.item.clone()).collect();
    Ok((write_step(&items, name, header), exported))
}

pub mod import;
pub mod solid;
pub use import::{ImportedDocuments, ImportedItem, import_items};
