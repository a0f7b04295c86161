//! # splinekit-scene
//!
//! Shape documents (JSON, see `docs/format.md`) ↔ splinekit kernel objects: parsing with
//! errors that name the offending field, building curves in the dimension their points
//! ask for, and document-level operations such as refinement.

#![warn(missing_docs)]

pub mod answers;
pub mod bfunctions;
pub mod blending;
pub mod budget;
pub mod cage_file;
pub mod curves;
pub mod decoration;
mod defaults;
pub mod dimension;
pub mod error;
pub mod json;
mod keyed;
pub mod output_file;
pub mod placement;
pub mod points;
pub mod refine;
pub mod refine_net;
pub mod registry;
pub mod scenes;
pub mod surfaces;
pub mod transforms;
pub mod views;

pub use curves::{AnyCurve, CurveDecoration, CurveDocument, CurveForm, Curves};
pub use decoration::Decoration;
pub use dimension::{AnyDimension, DimensionVisitor};
pub use error::{DocumentError, ErrorKind, Result};
pub use output_file::{OutputFile, write_file};
pub use registry::DocumentKind;
pub use scenes::{SceneDocument, SceneObject, SceneOrShape, StyleDoc};
pub use surfaces::{AnySurface, SurfaceDecoration, SurfaceDocument, SurfaceForm, Surfaces};
pub use views::{NetView, SplineView};

use serde_json::Value;

/// Any shape document.
#[derive(Debug, Clone, PartialEq)]
pub enum ShapeDocument {
    /// A curve.
    Curve(CurveDocument),
    /// A surface.
    Surface(SurfaceDocument),
}

impl ShapeDocument {
    /// Parses a shape document from JSON text.
    pub fn from_json(text: &str) -> Result<Self> {
        let value = crate::json::parse_text(text)?;
        Self::from_value(value)
    }

    /// Poses every animated blending spline in the document at `time` (seconds).
    pub fn set_time(&mut self, time: f64) {
        match self {
            ShapeDocument::Curve(c) => c.set_time(time),
            ShapeDocument::Surface(s) => s.set_time(time),
        }
    }

    /// What building and evaluating the shape cost (see [`budget`]).
    pub fn cost(&self) -> budget::ShapeCost {
        match self {
            ShapeDocument::Curve(c) => c.cost(),
            ShapeDocument::Surface(s) => s.cost(),
        }
    }

    /// Parses a shape document.
    pub fn parse(value: &Value) -> Result<Self> {
        Self::from_value(value.clone())
    }

    /// Parses a shape document, taking the JSON value (a large document is not copied).
    pub fn from_value(value: Value) -> Result<Self> {
        let (ty, rest) = json::split_type(value)?;
        if CurveDocument::TYPES.contains(&ty.as_str()) {
            return CurveDocument::parse_fields(&ty, rest).expect("a curve type").map(ShapeDocument::Curve);
        }
        if let Some(s) = SurfaceDocument::parse_fields(&ty, rest) {
            return s.map(ShapeDocument::Surface);
        }
        Err(DocumentError::new(
            "type",
            format!(
                "unknown shape type \"{ty}\" (curves: {}; surfaces: {})",
                CurveDocument::TYPES.join(", "),
                SurfaceDocument::TYPES.join(", ")
            ),
        ))
    }
}
