//! Curve shape documents: the registry of curve kinds, and the model curves' documents.
//!
//! Adding a curve kind is a document struct with its [`DocumentKind`] and one line in the
//! list below (see CONTRIBUTING.md); the compiler asks for everything else.

mod composite;
mod splines;

use serde::{Deserialize, Serialize};
use serde_json::Value;
use splinekit::curve::Curve;
use splinekit::curve::model::{Butterfly, Circle, Ellipse, Heart, Helix, Lissajous, Rose, Trefoil};

pub use crate::blending::{BlendingSplineDoc, LocalDoc};
pub use composite::{BFunctionShapeDoc, BlendDoc};
pub use splines::{BSplineDoc, BezierDoc, CatmullRomDoc, HermiteDoc, LineDoc, NurbsDoc, RationalBezierDoc};

use crate::defaults::is_false;
use crate::dimension::{Curves, same_type};
use crate::error::{DocumentError, Result};
use crate::json::split_type;
use crate::registry::{Decoration, DocumentKind, KindName, document_kinds};

document_kinds! {
    /// A curve shape document: `{"type": "…", …fields…}`.
    pub enum CurveDocument of Curves {
        /// Bézier curve.
        Bezier(BezierDoc) = "bezier",
        /// Rational Bézier curve.
        RationalBezier(RationalBezierDoc) = "rational_bezier",
        /// B-spline curve.
        Bspline(BSplineDoc) = "bspline",
        /// NURBS curve.
        Nurbs(NurbsDoc) = "nurbs",
        /// Cubic Hermite spline.
        Hermite(HermiteDoc) = "hermite",
        /// Catmull–Rom spline.
        CatmullRom(CatmullRomDoc) = "catmull_rom",
        /// Line segment.
        Line(LineDoc) = "line",
        /// Circle.
        Circle(CircleDoc) = "circle",
        /// Ellipse.
        Ellipse(EllipseDoc) = "ellipse",
        /// Circular helix.
        Helix(HelixDoc) = "helix",
        /// Heart curve.
        Heart(HeartDoc) = "heart",
        /// Rose curve.
        Rose(RoseDoc) = "rose",
        /// Lissajous figure.
        Lissajous(LissajousDoc) = "lissajous",
        /// Trefoil knot.
        Trefoil(TrefoilDoc) = "trefoil",
        /// Butterfly curve.
        Butterfly(ButterflyDoc) = "butterfly",
        /// A B-function as a 1-D curve.
        Bfunction(BFunctionShapeDoc) = "bfunction",
        /// Blend of two curves.
        Blend(BlendDoc) = "blend",
        /// Blending-spline curve.
        BlendingSpline(BlendingSplineDoc) = "blending_spline",
    }
}

/// The curve `type` names, for messages.
pub const CURVE_TYPES: &[&str] = CurveDocument::TYPES;

impl CurveDocument {
    /// Parses a curve document.
    pub fn parse(value: &Value) -> Result<Self> {
        let (ty, rest) = split_type(value)?;
        Self::parse_fields(&ty, rest).unwrap_or_else(|| {
            Err(DocumentError::new(
                "type",
                format!("unknown curve type \"{ty}\" (expected one of {})", CURVE_TYPES.join(", ")),
            ))
        })
    }
}

/// A model curve in dimension D, which must be 3.
fn model_curve_in<const D: usize>(
    name: &str,
    build: impl FnOnce() -> Result<Box<dyn Curve<3>>>,
) -> Result<Box<dyn Curve<D>>> {
    let not_3d = || DocumentError::new("type", format!("{name} is a 3-D model curve"));
    if D != 3 {
        return Err(not_3d());
    }
    same_type(build()?).ok_or_else(not_3d)
}

/// Implements [`DocumentKind`] for a model curve's document `$doc`: 3-D, built as
/// `$build` from the document `$d`; its example is its default document, and it has
/// nothing to decorate or pose.
macro_rules! model_curve {
    ($doc:ty, |$d:ident| $build:expr) => {
        impl DocumentKind for $doc {
            type Family = Curves;
            fn dimension(&self) -> Result<usize> {
                Ok(3)
            }
            fn build_in<const D: usize>(&self) -> Result<Box<dyn Curve<D>>> {
                let $d = self;
                model_curve_in::<D>(Self::TYPE, || Ok(Box::new($build?)))
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

/// `{"type":"circle","radius":1}`: (r cos t, r sin t, 0), t ∈ [0, 2π].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct CircleDoc {
    /// Radius r (default 1).
    pub radius: f64,
}

impl Default for CircleDoc {
    fn default() -> Self {
        CircleDoc { radius: 1.0 }
    }
}

model_curve!(CircleDoc, |d| Circle::new(d.radius));

/// `{"type":"ellipse","a":2,"b":1}`: (a cos t, b sin t, 0), t ∈ [0, 2π].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct EllipseDoc {
    /// Semi-axis along x (default 2).
    pub a: f64,
    /// Semi-axis along y (default 1).
    pub b: f64,
}

impl Default for EllipseDoc {
    fn default() -> Self {
        EllipseDoc { a: 2.0, b: 1.0 }
    }
}

model_curve!(EllipseDoc, |d| Ellipse::new(d.a, d.b));

/// `{"type":"helix","radius":1,"pitch":1,"turns":3}`: (r cos t, r sin t, pitch·t/2π).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct HelixDoc {
    /// Radius (default 1).
    pub radius: f64,
    /// Rise per turn (default 1).
    pub pitch: f64,
    /// Number of turns; t ∈ [0, 2π·turns] (default 3).
    pub turns: f64,
}

impl Default for HelixDoc {
    fn default() -> Self {
        HelixDoc { radius: 1.0, pitch: 1.0, turns: 3.0 }
    }
}

model_curve!(HelixDoc, |d| Helix::new(d.radius, d.pitch, d.turns));

/// `{"type":"heart","scale":1}`: s·(16 sin³t, 13 cos t − 5 cos 2t − 2 cos 3t − cos 4t, 0).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct HeartDoc {
    /// Uniform scale (default 1).
    pub scale: f64,
}

impl Default for HeartDoc {
    fn default() -> Self {
        HeartDoc { scale: 1.0 }
    }
}

model_curve!(HeartDoc, |d| Heart::new(d.scale));

/// `{"type":"rose","radius":1,"n":4,"planar":false}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct RoseDoc {
    /// Radius r (default 1).
    pub radius: f64,
    /// Petal parameter n (default 4).
    pub n: f64,
    /// Drop z = r sin(nt) (default false: the 3-D rose).
    #[serde(skip_serializing_if = "is_false")]
    pub planar: bool,
}

impl Default for RoseDoc {
    fn default() -> Self {
        RoseDoc { radius: 1.0, n: 4.0, planar: false }
    }
}

model_curve!(RoseDoc, |d| Rose::new(d.radius, d.n, d.planar));

/// `{"type":"lissajous","amplitudes":[1,1,0],"frequencies":[3,2,0],"delta":π/2}`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct LissajousDoc {
    /// (A, B, C) (default [1, 1, 0]).
    pub amplitudes: [f64; 3],
    /// (a, b, c) (default [3, 2, 0]).
    pub frequencies: [f64; 3],
    /// Phase of x (default π/2).
    pub delta: f64,
}

impl Default for LissajousDoc {
    fn default() -> Self {
        LissajousDoc { amplitudes: [1.0, 1.0, 0.0], frequencies: [3.0, 2.0, 0.0], delta: std::f64::consts::FRAC_PI_2 }
    }
}

model_curve!(LissajousDoc, |d| Lissajous::new(d.amplitudes, d.frequencies, d.delta));

/// `{"type":"trefoil","scale":1}`: s·(sin t + 2 sin 2t, cos t − 2 cos 2t, −sin 3t).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct TrefoilDoc {
    /// Uniform scale (default 1).
    pub scale: f64,
}

impl Default for TrefoilDoc {
    fn default() -> Self {
        TrefoilDoc { scale: 1.0 }
    }
}

model_curve!(TrefoilDoc, |d| Trefoil::new(d.scale));

/// `{"type":"butterfly","scale":1}`: Fay's butterfly, t ∈ [0, 24π].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ButterflyDoc {
    /// Uniform scale (default 1).
    pub scale: f64,
}

impl Default for ButterflyDoc {
    fn default() -> Self {
        ButterflyDoc { scale: 1.0 }
    }
}

model_curve!(ButterflyDoc, |d| Butterfly::new(d.scale));
