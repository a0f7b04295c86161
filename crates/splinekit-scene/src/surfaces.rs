//! Surface shape documents: the registry of surface kinds, and the model surfaces'
//! documents. The first index of a control net runs along u.
//!
//! Adding a surface kind is a document struct with its [`DocumentKind`] and one line in
//! the list below (see CONTRIBUTING.md); the compiler asks for everything else.

mod from_curves;
mod nets;
mod trimmed;

use serde::{Deserialize, Serialize};
use serde_json::Value;
use splinekit::surface::Surface;
use splinekit::surface::model::{
    Apple, Cone, Cylinder, Enneper, HeartSurface, Helicoid, KleinBottle, MobiusStrip, Plane, Seashell, Sphere, Torus,
};

pub use crate::blending::{BlendingSplineSurfaceDoc, LocalPatchDoc};
pub use from_curves::{CoonsBlendDoc, CoonsDoc, ExtrusionDoc, RevolutionDoc, RuledDoc, SweepDoc};
pub use nets::{BSplineSurfaceDoc, BezierSurfaceDoc, NurbsSurfaceDoc};
pub use trimmed::TrimmedDoc;

use crate::dimension::{Surfaces, same_type};
use crate::error::{DocumentError, Result};
use crate::json::split_type;
use crate::points::to_point;
use crate::registry::{Decoration, DocumentKind, document_kinds};

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
        /// Blending-spline surface.
        BlendingSplineSurface(BlendingSplineSurfaceDoc) = "blending_spline_surface",
    }
}

/// The surface `type` names, for messages.
pub const SURFACE_TYPES: &[&str] = SurfaceDocument::TYPES;

impl SurfaceDocument {
    /// Parses a surface document.
    pub fn parse(value: &Value) -> Result<Self> {
        let (ty, rest) = split_type(value)?;
        Self::parse_fields(&ty, rest)
            .unwrap_or_else(|| Err(DocumentError::new("type", format!("expected a surface type, got \"{ty}\""))))
    }
}

/// A surface that exists in 3-D only, in dimension D (which must be 3).
fn surface_in_3d<const D: usize>(build: impl FnOnce() -> Result<Box<dyn Surface<3>>>) -> Result<Box<dyn Surface<D>>> {
    same_type(build()?).ok_or_else(|| DocumentError::new("type", "model surfaces are 3-D"))
}

/// Implements [`DocumentKind`] for a model surface's document `$doc`: 3-D, built as
/// `$build` from the document `$d`; its example is its default document, and it has
/// nothing to decorate or pose.
macro_rules! model_surface {
    ($doc:ty, |$d:ident| $build:expr) => {
        impl DocumentKind for $doc {
            type Family = Surfaces;
            fn dimension(&self) -> Result<usize> {
                Ok(3)
            }
            fn build_in<const D: usize>(&self) -> Result<Box<dyn Surface<D>>> {
                let $d = self;
                surface_in_3d::<D>(|| Ok(Box::new($build?)))
            }
            fn example() -> Self {
                Self::default()
            }
            fn decoration(&self) -> Decoration<'_> {
                Decoration::None
            }
            fn set_time(&mut self, _time: f64) {}
        }
    };
}

/// `{"type":"plane","origin":[0,0,0],"u_axis":[1,0,0],"v_axis":[0,1,0]}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct PlaneDoc {
    /// S(0, 0).
    pub origin: Vec<f64>,
    /// ∂S/∂u.
    pub u_axis: Vec<f64>,
    /// ∂S/∂v.
    pub v_axis: Vec<f64>,
}

impl Default for PlaneDoc {
    fn default() -> Self {
        PlaneDoc { origin: vec![0.0, 0.0, 0.0], u_axis: vec![1.0, 0.0, 0.0], v_axis: vec![0.0, 1.0, 0.0] }
    }
}

model_surface!(PlaneDoc, |d| Plane::new(
    to_point("origin", &d.origin)?,
    to_point("u_axis", &d.u_axis)?,
    to_point("v_axis", &d.v_axis)?
));

/// `{"type":"cylinder","radius":1,"height":1}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct CylinderDoc {
    /// Radius (default 1).
    pub radius: f64,
    /// Height (default 1).
    pub height: f64,
}

impl Default for CylinderDoc {
    fn default() -> Self {
        CylinderDoc { radius: 1.0, height: 1.0 }
    }
}

model_surface!(CylinderDoc, |d| Cylinder::new(d.radius, d.height));

/// `{"type":"cone","radius":1,"height":2}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ConeDoc {
    /// Base radius (default 1).
    pub radius: f64,
    /// Height (default 2).
    pub height: f64,
}

impl Default for ConeDoc {
    fn default() -> Self {
        ConeDoc { radius: 1.0, height: 2.0 }
    }
}

model_surface!(ConeDoc, |d| Cone::new(d.radius, d.height));

/// `{"type":"sphere","radius":1}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SphereDoc {
    /// Radius (default 1).
    pub radius: f64,
}

impl Default for SphereDoc {
    fn default() -> Self {
        SphereDoc { radius: 1.0 }
    }
}

model_surface!(SphereDoc, |d| Sphere::new(d.radius));

/// `{"type":"torus","major_radius":3,"minor_radius":1}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct TorusDoc {
    /// R (default 3).
    pub major_radius: f64,
    /// r (default 1).
    pub minor_radius: f64,
}

impl Default for TorusDoc {
    fn default() -> Self {
        TorusDoc { major_radius: 3.0, minor_radius: 1.0 }
    }
}

model_surface!(TorusDoc, |d| Torus::new(d.major_radius, d.minor_radius));

/// `{"type":"mobius","radius":1,"half_width":0.5}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct MobiusDoc {
    /// Centre radius (default 1).
    pub radius: f64,
    /// Half-width (default 0.5).
    pub half_width: f64,
}

impl Default for MobiusDoc {
    fn default() -> Self {
        MobiusDoc { radius: 1.0, half_width: 0.5 }
    }
}

model_surface!(MobiusDoc, |d| MobiusStrip::new(d.radius, d.half_width));

/// `{"type":"klein_bottle","radius":3}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct KleinBottleDoc {
    /// Radius R (default 3).
    pub radius: f64,
}

impl Default for KleinBottleDoc {
    fn default() -> Self {
        KleinBottleDoc { radius: 3.0 }
    }
}

model_surface!(KleinBottleDoc, |d| KleinBottle::new(d.radius));

/// `{"type":"enneper","extent":2}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct EnneperDoc {
    /// Half-extent of the square domain (default 2).
    pub extent: f64,
}

impl Default for EnneperDoc {
    fn default() -> Self {
        EnneperDoc { extent: 2.0 }
    }
}

model_surface!(EnneperDoc, |d| Enneper::new(d.extent));

/// `{"type":"helicoid","radius":1,"pitch":1,"turns":2}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct HelicoidDoc {
    /// Radius (default 1).
    pub radius: f64,
    /// Rise per turn (default 1).
    pub pitch: f64,
    /// Turns (default 2).
    pub turns: f64,
}

impl Default for HelicoidDoc {
    fn default() -> Self {
        HelicoidDoc { radius: 1.0, pitch: 1.0, turns: 2.0 }
    }
}

model_surface!(HelicoidDoc, |d| Helicoid::new(d.radius, d.pitch, d.turns));

/// `{"type":"seashell","a":1,"b":2,"c":0.1,"turns":2}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SeashellDoc {
    /// Tube radius (default 1).
    pub a: f64,
    /// Height (default 2).
    pub b: f64,
    /// Inner radius (default 0.1).
    pub c: f64,
    /// Turns (default 2).
    pub turns: f64,
}

impl Default for SeashellDoc {
    fn default() -> Self {
        SeashellDoc { a: 1.0, b: 2.0, c: 0.1, turns: 2.0 }
    }
}

model_surface!(SeashellDoc, |d| Seashell::new(d.a, d.b, d.c, d.turns));

/// `{"type":"apple","scale":1}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct AppleDoc {
    /// Uniform scale (default 1).
    pub scale: f64,
}

impl Default for AppleDoc {
    fn default() -> Self {
        AppleDoc { scale: 1.0 }
    }
}

model_surface!(AppleDoc, |d| Apple::new(d.scale));

/// `{"type":"heart_surface","scale":1}`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct HeartSurfaceDoc {
    /// Uniform scale (default 1).
    pub scale: f64,
}

impl Default for HeartSurfaceDoc {
    fn default() -> Self {
        HeartSurfaceDoc { scale: 1.0 }
    }
}

model_surface!(HeartSurfaceDoc, |d| HeartSurface::new(d.scale));
