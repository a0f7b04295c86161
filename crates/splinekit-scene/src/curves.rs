//! Curve shape documents: the curve family — the registry of its kinds, its marker
//! [`Curves`], and what its kinds declare of themselves, [`CurveForm`] and
//! [`CurveDecoration`]. Those name kinds (a blending spline's form is the document) while
//! the kinds, declared in this module's files, produce them: the family is one module.
//!
//! Adding a curve kind is a document struct with its
//! [`DocumentKind`](crate::registry::DocumentKind) (for a model curve, one
//! `model_document!` declaration in `models.rs`) and one line in the list (see
//! CONTRIBUTING.md); the compiler asks for everything else.

mod blending;
mod composite;
mod models;
mod on_surface;
mod splines;

use serde_json::Value;
use splinekit::curve::Curve;

pub use blending::{BlendingSource, BlendingSplineDoc, KnotSpacingDoc, LocalCurves, LocalDoc};
pub use composite::{BFunctionShapeDoc, BlendDoc};
// Every document that `models.rs` declares, so that a model kind is its declaration and
// its line in the list below.
pub use models::*;
pub use on_surface::CurveOnSurfaceDoc;
pub use splines::{BSplineDoc, BezierDoc, CatmullRomDoc, HermiteDoc, LineDoc, NurbsDoc, RationalBezierDoc};

use crate::dimension::{AnyDimension, ShapeFamily};
use crate::error::{DocumentError, Result};
use crate::json::split_type;
use crate::registry::ModelFamily;
use crate::views::SplineView;

/// The registry of curve kinds: `curve_kinds!(callback)` calls the macro `callback` with the
/// list, in the syntax of `document_kinds!` (see [`crate::registry`]). This crate makes
/// the document enum of it; front ends make their per-kind code of it (the Python
/// classes), so that every kind appears in each of them.
///
/// Each line is `Variant(Doc) = "type", python(CLASS),` where CLASS is the kind's Python
/// class: `base` (the plain `Curve`), `own` (splinekit-py's hand-written class named
/// after the variant) or `fields "Name"` (a class `Name` whose constructor takes the
/// document's fields as keyword arguments).
#[macro_export]
macro_rules! curve_kinds {
    ($callback:path) => {
        $callback! {
            /// A curve shape document: `{"type": "…", …fields…}`.
            pub enum CurveDocument of Curves {
                /// Bézier curve.
                Bezier(BezierDoc) = "bezier", python(own),
                /// Rational Bézier curve.
                RationalBezier(RationalBezierDoc) = "rational_bezier", python(own),
                /// B-spline curve.
                Bspline(BSplineDoc) = "bspline", python(own),
                /// NURBS curve.
                Nurbs(NurbsDoc) = "nurbs", python(own),
                /// Cubic Hermite spline.
                Hermite(HermiteDoc) = "hermite", python(own),
                /// Catmull–Rom spline.
                CatmullRom(CatmullRomDoc) = "catmull_rom", python(own),
                /// Line segment.
                Line(LineDoc) = "line", python(base),
                /// Circle.
                Circle(CircleDoc) = "circle", python(base),
                /// Ellipse.
                Ellipse(EllipseDoc) = "ellipse", python(base),
                /// Circular helix.
                Helix(HelixDoc) = "helix", python(base),
                /// Heart curve.
                Heart(HeartDoc) = "heart", python(base),
                /// Rose curve.
                Rose(RoseDoc) = "rose", python(base),
                /// Lissajous figure.
                Lissajous(LissajousDoc) = "lissajous", python(base),
                /// Trefoil knot.
                Trefoil(TrefoilDoc) = "trefoil", python(base),
                /// Butterfly curve.
                Butterfly(ButterflyDoc) = "butterfly", python(base),
                /// Hypotrochoid or epitrochoid (spirograph curve).
                Trochoid(TrochoidDoc) = "trochoid", python(base),
                /// Logarithmic spiral.
                LogarithmicSpiral(LogarithmicSpiralDoc) = "logarithmic_spiral", python(fields "LogarithmicSpiral"),
                /// Chrysanthemum curve.
                Chrysanthemum(ChrysanthemumDoc) = "chrysanthemum", python(fields "Chrysanthemum"),
                /// A B-function as a 1-D curve.
                Bfunction(BFunctionShapeDoc) = "bfunction", python(base),
                /// Blend of two curves.
                Blend(BlendDoc) = "blend", python(base),
                /// A 2-D curve in a surface's (u, v) domain, on the surface.
                CurveOnSurface(CurveOnSurfaceDoc) = "curve_on_surface", python(base),
                /// Blending-spline curve.
                BlendingSpline(BlendingSplineDoc) = "blending_spline", python(base),
            }
        }
    };
}
crate::curve_kinds!(crate::registry::document_kinds);

/// The curve `type` names, for messages.
pub const CURVE_TYPES: &[&str] = CurveDocument::TYPES;

impl CurveDocument {
    /// Parses a curve document, taking the JSON value.
    pub fn from_value(value: Value) -> Result<Self> {
        let (ty, rest) = split_type(value)?;
        Self::parse_fields(&ty, rest).unwrap_or_else(|| {
            Err(DocumentError::new(
                "type",
                format!("unknown curve type \"{ty}\" (expected one of {})", CURVE_TYPES.join(", ")),
            ))
        })
    }
}

/// Curves: `dyn Curve<D>`.
#[derive(Debug)]
pub enum Curves {}

impl ShapeFamily for Curves {
    type Shape<const D: usize> = dyn Curve<D>;
    type Spline<'a> = SplineView<'a>;
    type Form<'a> = CurveForm<'a>;
    type Decoration<'a> = CurveDecoration<'a>;
}

/// A curve of a dimension known only at run time.
pub type AnyCurve = AnyDimension<Curves>;

impl ModelFamily for Curves {
    fn not_3d(name: &str) -> DocumentError {
        DocumentError::new("type", format!("{name} is a 3-D model curve"))
    }
}

/// The exact form of a curve document: what it is in the classical vocabulary of geometry
/// (a spline, a line, a conic), declared by its kind in
/// [`DocumentKind::exact_form`](crate::registry::DocumentKind::exact_form).
///
/// Exporters write the form's own entity (STEP: `B_SPLINE_CURVE_WITH_KNOTS`, `CIRCLE`,
/// `TOROIDAL_SURFACE`, …) and approximate only `Approximate`; a new kind chooses among
/// these forms, so an exporter needs no edit for it. Every form has the document's
/// parametrisation up to the affine maps the exporter names.
#[derive(Debug, Clone)]
pub enum CurveForm<'a> {
    /// A B-spline, NURBS or (rational) Bézier curve with these points, knots and weights.
    Spline(SplineView<'a>),
    /// The segment from + t (to − from), t ∈ [0, 1].
    Line {
        /// c(0).
        from: &'a [f64],
        /// c(1).
        to: &'a [f64],
    },
    /// (r cos t, r sin t, 0), t ∈ [0, 2π].
    Circle {
        /// r.
        radius: f64,
    },
    /// (a cos t, b sin t, 0), t ∈ [0, 2π].
    Ellipse {
        /// Semi-axis along x.
        a: f64,
        /// Semi-axis along y.
        b: f64,
    },
    /// A blending spline: a piecewise polynomial (a B-spline) when its locals are Bézier
    /// curves or lines and its B-function is a polynomial, else approximated.
    BlendingSpline(&'a BlendingSplineDoc),
    /// No exact form: exporters approximate the curve within a tolerance.
    Approximate,
}

/// What a scene draws besides a curve when its style asks for control nets (`control_net`)
/// or local pieces (`local_pieces`); scenes read it as a [`Decoration`](crate::Decoration).
#[derive(Debug, Clone, Copy, Default)]
pub enum CurveDecoration<'a> {
    /// Nothing besides the curve.
    #[default]
    None,
    /// A control polygon (curves from control points or interpolated points).
    ControlPolygon {
        /// The points, each of 1 to 4 coordinates.
        points: &'a [Vec<f64>],
        /// The document field that holds them (`control_points`, or `points` of
        /// interpolating kinds), for editors that move them.
        field: &'static str,
        /// Whether the last point joins the first.
        closed: bool,
    },
    /// The local curves of a blending-spline curve.
    LocalCurves(&'a BlendingSplineDoc),
}
