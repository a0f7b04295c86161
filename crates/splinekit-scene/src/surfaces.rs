//! Surface shape documents: the registry of surface kinds, and the model surfaces'
//! documents. The first index of a control net runs along u.
//!
//! Adding a surface kind is a document struct with its
//! [`DocumentKind`](crate::registry::DocumentKind) (for a model surface, one `model_document!`
//! declaration below) and one line in the list (see CONTRIBUTING.md); the compiler asks for
//! everything else.

mod from_curves;
mod nets;
mod placed;
mod subdivision;
mod trimmed;

use serde_json::Value;
use splinekit::surface::model::{
    Apple, Cone, Cylinder, Enneper, HeartSurface, Helicoid, KleinBottle, MobiusStrip, Plane, Seashell, Sphere, Torus,
};

pub use crate::blending::{BlendingSplineSurfaceDoc, LocalPatchDoc};
pub use from_curves::{CoonsBlendDoc, CoonsDoc, ExtrusionDoc, RevolutionDoc, RuledDoc, SweepDoc};
pub use nets::{BSplineSurfaceDoc, BezierSurfaceDoc, NurbsSurfaceDoc};
pub use placed::PlacedDoc;
pub use subdivision::{BoundaryDoc, CreaseDoc, SchemeDoc, SubdivisionSurfaceDoc};
pub use trimmed::TrimmedDoc;

use crate::dimension::Surfaces;
use crate::error::{DocumentError, Result};
use crate::json::split_type;
use crate::points::to_point;
use crate::registry::{document_kinds, model_document};

document_kinds! {
    /// A surface shape document: `{"type": "…", …fields…}`.
    pub enum SurfaceDocument of Surfaces {
        /// Tensor-product Bézier surface.
        BezierSurface(BezierSurfaceDoc) = "bezier_surface",
        /// Tensor-product B-spline surface.
        BsplineSurface(BSplineSurfaceDoc) = "bspline_surface",
        /// NURBS surface.
        NurbsSurface(NurbsSurfaceDoc) = "nurbs_surface",
        /// Plane.
        Plane(PlaneDoc) = "plane",
        /// Cylinder.
        Cylinder(CylinderDoc) = "cylinder",
        /// Cone.
        Cone(ConeDoc) = "cone",
        /// Sphere.
        Sphere(SphereDoc) = "sphere",
        /// Torus.
        Torus(TorusDoc) = "torus",
        /// Möbius strip.
        Mobius(MobiusDoc) = "mobius",
        /// Figure-8 Klein bottle.
        KleinBottle(KleinBottleDoc) = "klein_bottle",
        /// Enneper's minimal surface.
        Enneper(EnneperDoc) = "enneper",
        /// Helicoid.
        Helicoid(HelicoidDoc) = "helicoid",
        /// Seashell.
        Seashell(SeashellDoc) = "seashell",
        /// Apple.
        Apple(AppleDoc) = "apple",
        /// The heart curve turned about its axis.
        HeartSurface(HeartSurfaceDoc) = "heart_surface",
        /// Surface of revolution.
        Revolution(RevolutionDoc) = "revolution",
        /// Ruled surface between two curves.
        Ruled(RuledDoc) = "ruled",
        /// Extrusion of a curve.
        Extrusion(ExtrusionDoc) = "extrusion",
        /// Coons patch of four boundary curves.
        Coons(CoonsDoc) = "coons",
        /// Sweep of a profile along a path.
        Sweep(SweepDoc) = "sweep",
        /// Trimmed surface.
        Trimmed(TrimmedDoc) = "trimmed",
        /// A surface moved rigidly into a frame.
        Placed(PlacedDoc) = "placed",
        /// Blending-spline surface.
        BlendingSplineSurface(BlendingSplineSurfaceDoc) = "blending_spline_surface",
        /// The limit surface of a subdivision cage.
        SubdivisionSurface(SubdivisionSurfaceDoc) = "subdivision_surface",
    }
}

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

model_document! {
    /// `{"type":"plane","origin":[0,0,0],"u_axis":[1,0,0],"v_axis":[0,1,0]}`
    pub struct PlaneDoc in Surfaces {
        /// S(0, 0) (default the origin).
        pub origin: Vec<f64> = vec![0.0, 0.0, 0.0],
        /// ∂S/∂u (default x).
        pub u_axis: Vec<f64> = vec![1.0, 0.0, 0.0],
        /// ∂S/∂v (default y).
        pub v_axis: Vec<f64> = vec![0.0, 1.0, 0.0],
    }
    build(|d| Plane::new(to_point("origin", &d.origin)?, to_point("u_axis", &d.u_axis)?, to_point("v_axis", &d.v_axis)?))
}

model_document! {
    /// `{"type":"cylinder","radius":1,"height":1}`
    pub struct CylinderDoc in Surfaces {
        /// Radius (default 1).
        pub radius: f64 = 1.0,
        /// Height (default 1).
        pub height: f64 = 1.0,
    }
    build(|d| Cylinder::new(d.radius, d.height))
}

model_document! {
    /// `{"type":"cone","radius":1,"height":2}`
    pub struct ConeDoc in Surfaces {
        /// Base radius (default 1).
        pub radius: f64 = 1.0,
        /// Height (default 2).
        pub height: f64 = 2.0,
    }
    build(|d| Cone::new(d.radius, d.height))
}

model_document! {
    /// `{"type":"sphere","radius":1}`
    pub struct SphereDoc in Surfaces {
        /// Radius (default 1).
        pub radius: f64 = 1.0,
    }
    build(|d| Sphere::new(d.radius))
}

model_document! {
    /// `{"type":"torus","major_radius":3,"minor_radius":1}`
    pub struct TorusDoc in Surfaces {
        /// R (default 3).
        pub major_radius: f64 = 3.0,
        /// r (default 1).
        pub minor_radius: f64 = 1.0,
    }
    build(|d| Torus::new(d.major_radius, d.minor_radius))
}

model_document! {
    /// `{"type":"mobius","radius":1,"half_width":0.5}`
    pub struct MobiusDoc in Surfaces {
        /// Centre radius (default 1).
        pub radius: f64 = 1.0,
        /// Half-width (default 0.5).
        pub half_width: f64 = 0.5,
    }
    build(|d| MobiusStrip::new(d.radius, d.half_width))
}

model_document! {
    /// `{"type":"klein_bottle","radius":3}`
    pub struct KleinBottleDoc in Surfaces {
        /// Radius R (default 3).
        pub radius: f64 = 3.0,
    }
    build(|d| KleinBottle::new(d.radius))
}

model_document! {
    /// `{"type":"enneper","extent":2}`
    pub struct EnneperDoc in Surfaces {
        /// Half-extent of the square domain (default 2).
        pub extent: f64 = 2.0,
    }
    build(|d| Enneper::new(d.extent))
}

model_document! {
    /// `{"type":"helicoid","radius":1,"pitch":1,"turns":2}`
    pub struct HelicoidDoc in Surfaces {
        /// Radius (default 1).
        pub radius: f64 = 1.0,
        /// Rise per turn (default 1).
        pub pitch: f64 = 1.0,
        /// Turns (default 2).
        pub turns: f64 = 2.0,
    }
    build(|d| Helicoid::new(d.radius, d.pitch, d.turns))
}

model_document! {
    /// `{"type":"seashell","a":1,"b":2,"c":0.1,"turns":2}`
    pub struct SeashellDoc in Surfaces {
        /// Tube radius (default 1).
        pub a: f64 = 1.0,
        /// Height (default 2).
        pub b: f64 = 2.0,
        /// Inner radius (default 0.1).
        pub c: f64 = 0.1,
        /// Turns (default 2).
        pub turns: f64 = 2.0,
    }
    build(|d| Seashell::new(d.a, d.b, d.c, d.turns))
}

model_document! {
    /// `{"type":"apple","scale":1}`
    pub struct AppleDoc in Surfaces {
        /// Uniform scale (default 1).
        pub scale: f64 = 1.0,
    }
    build(|d| Apple::new(d.scale))
}

model_document! {
    /// `{"type":"heart_surface","scale":1}`
    pub struct HeartSurfaceDoc in Surfaces {
        /// Uniform scale (default 1).
        pub scale: f64 = 1.0,
    }
    build(|d| HeartSurface::new(d.scale))
}
