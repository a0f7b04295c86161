//! Surface shape documents: the registry of surface kinds. The first index of a control net runs along u.
//!
//! Adding a surface kind is a document struct with its
//! [`DocumentKind`](crate::registry::DocumentKind) (for a model surface, one `model_document!`
//! declaration in `models.rs`) and one line in the list (see CONTRIBUTING.md); the compiler asks for
//! everything else.

mod from_curves;
mod models;
mod nets;
mod placed;
mod subdivision;
mod trimmed;

use serde_json::Value;

pub use crate::blending::{BlendingSplineSurfaceDoc, LocalPatchDoc};
pub use from_curves::{CoonsBlendDoc, CoonsDoc, ExtrusionDoc, RevolutionDoc, RuledDoc, SweepDoc};
pub use models::{
    AppleDoc, ConeDoc, CylinderDoc, DupinCyclideDoc, EnneperDoc, HeartSurfaceDoc, HelicoidDoc, KleinBottleDoc,
    MobiusDoc, PlaneDoc, SeashellDoc, SphereDoc, TorusDoc,
};
pub use nets::{BSplineSurfaceDoc, BezierSurfaceDoc, NurbsSurfaceDoc};
pub use placed::PlacedDoc;
pub use subdivision::{BoundaryDoc, CreaseDoc, SchemeDoc, SubdivisionSurfaceDoc};
pub use trimmed::TrimmedDoc;

use crate::dimension::Surfaces;
use crate::error::{DocumentError, Result};
use crate::json::split_type;

/// The registry of surface kinds: `surface_kinds!(callback)` calls the macro `callback` with the
/// list, in the syntax of `document_kinds!` (see [`crate::registry`]). This crate makes
/// the document enum of it; front ends make their per-kind code of it (the Python
/// classes), so that every kind appears in each of them.
///
/// Each line is `Variant(Doc) = "type", python(CLASS),` where CLASS is the kind's Python
/// class: `base` (the plain `Surface`), `own` (splinekit-py's hand-written class named
/// after the variant) or `fields "Name"` (a class `Name` whose constructor takes the
/// document's fields as keyword arguments).
#[macro_export]
macro_rules! surface_kinds {
    ($callback:path) => {
        $callback! {
            /// A surface shape document: `{"type": "…", …fields…}`.
            pub enum SurfaceDocument of Surfaces {
                /// Tensor-product Bézier surface.
                BezierSurface(BezierSurfaceDoc) = "bezier_surface", python(own),
                /// Tensor-product B-spline surface.
                BsplineSurface(BSplineSurfaceDoc) = "bspline_surface", python(own),
                /// NURBS surface.
                NurbsSurface(NurbsSurfaceDoc) = "nurbs_surface", python(own),
                /// Plane.
                Plane(PlaneDoc) = "plane", python(base),
                /// Cylinder.
                Cylinder(CylinderDoc) = "cylinder", python(base),
                /// Cone.
                Cone(ConeDoc) = "cone", python(base),
                /// Sphere.
                Sphere(SphereDoc) = "sphere", python(base),
                /// Torus.
                Torus(TorusDoc) = "torus", python(base),
                /// Möbius strip.
                Mobius(MobiusDoc) = "mobius", python(base),
                /// Figure-8 Klein bottle.
                KleinBottle(KleinBottleDoc) = "klein_bottle", python(base),
                /// Enneper's minimal surface.
                Enneper(EnneperDoc) = "enneper", python(base),
                /// Helicoid.
                Helicoid(HelicoidDoc) = "helicoid", python(base),
                /// Seashell.
                Seashell(SeashellDoc) = "seashell", python(base),
                /// Apple.
                Apple(AppleDoc) = "apple", python(base),
                /// The heart curve turned about its axis.
                HeartSurface(HeartSurfaceDoc) = "heart_surface", python(base),
                /// Dupin cyclide.
                DupinCyclide(DupinCyclideDoc) = "dupin_cyclide", python(fields "DupinCyclide"),
                /// Surface of revolution.
                Revolution(RevolutionDoc) = "revolution", python(base),
                /// Ruled surface between two curves.
                Ruled(RuledDoc) = "ruled", python(base),
                /// Extrusion of a curve.
                Extrusion(ExtrusionDoc) = "extrusion", python(base),
                /// Coons patch of four boundary curves.
                Coons(CoonsDoc) = "coons", python(base),
                /// Sweep of a profile along a path.
                Sweep(SweepDoc) = "sweep", python(base),
                /// Trimmed surface.
                Trimmed(TrimmedDoc) = "trimmed", python(base),
                /// A surface moved rigidly into a frame.
                Placed(PlacedDoc) = "placed", python(base),
                /// Blending-spline surface.
                BlendingSplineSurface(BlendingSplineSurfaceDoc) = "blending_spline_surface", python(base),
                /// The limit surface of a subdivision cage.
                SubdivisionSurface(SubdivisionSurfaceDoc) = "subdivision_surface", python(base),
            }
        }
    };
}
crate::surface_kinds!(crate::registry::document_kinds);

/// The surface `type` names, for messages.
pub const SURFACE_TYPES: &[&str] = SurfaceDocument::TYPES;

impl SurfaceDocument {
    /// Parses a surface document.
    pub fn parse(value: &Value) -> Result<Self> {
        Self::from_value(value.clone())
    }

    /// Parses a surface document, taking the JSON value.
    pub fn from_value(value: Value) -> Result<Self> {
        let (ty, rest) = split_type(value)?;
        Self::parse_fields(&ty, rest)
            .unwrap_or_else(|| Err(DocumentError::new("type", format!("expected a surface type, got \"{ty}\""))))
    }
}
