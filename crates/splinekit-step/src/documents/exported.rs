//! What exporting one shape document gives: the STEP item, whether it is exact, its
//! measured deviation and tolerance, and the affine map from the document's parameters to
//! the STEP entity's ([`ParamMap`]). Shared by the curve, surface and face exporters.

use splinekit::curve::Interval;

use crate::geometry::Item;

/// u' = a·u + b per direction: the STEP parameter of the document's parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParamMap {
    /// (a, b) of u (curves: of t).
    pub u: (f64, f64),
    /// (a, b) of v.
    pub v: (f64, f64),
}

impl ParamMap {
    /// The identity.
    pub const IDENTITY: ParamMap = ParamMap { u: (1.0, 0.0), v: (1.0, 0.0) };
}

/// How an object was written.
#[derive(Debug, Clone, PartialEq)]
pub enum Form {
    /// Its own STEP entity or an identical B-spline.
    Exact,
    /// A B-spline equal to it up to rounding, because the maths says it is one (a blending
    /// spline with Bézier locals and a polynomial B-function).
    ExactPolynomial {
        /// The degree of the pieces (per direction for surfaces).
        degree: (usize, usize),
    },
    /// A B-spline within the tolerance.
    Approximated,
}

/// One exported object with what the export measured.
#[derive(Debug, Clone)]
pub struct Exported {
    /// The STEP item.
    pub item: Item,
    /// How it was written.
    pub form: Form,
    /// max |STEP(map(t)) − document(t)| as measured (0 for exact forms, where no
    /// arithmetic but the file's decimal round trip lies between them).
    pub max_deviation: f64,
    /// The absolute tolerance used for approximations.
    pub tolerance: f64,
    /// Parameter map document → STEP.
    pub map: ParamMap,
    /// The document's domain (u, v; curves: v is unused).
    pub domain: (Interval, Interval),
}
