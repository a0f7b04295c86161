//! Blending: two curves blended by a B-function, and B-functions seen as curves.

pub mod bfunction_curve;
pub mod blending_spline;
pub mod two_curve;

pub use bfunction_curve::BFunctionCurve;
pub use blending_spline::{BlendingSplineCurve, LocalKind};
pub use two_curve::{PlainBlend, TwoCurveBlend};
