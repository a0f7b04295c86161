//! Blending: two curves blended by a B-function, blending-spline curves and surfaces, and
//! B-functions seen as curves.

pub mod animation;
pub mod bfunction_curve;
pub mod blending_spline;
pub mod blending_surface;
mod curve_batch;
pub mod hermite;
pub mod knot_line;
pub mod knots;
pub mod leibniz;
pub mod osculating_arc;
pub mod presets;
pub mod two_curve;

pub use animation::{Motion, Track};
pub use bfunction_curve::BFunctionCurve;
pub use blending_spline::{BlendingCurveOptions, BlendingSplineCurve, KnotSpacing, LocalKind};
pub use blending_surface::{BlendingSplineSurface, BlendingSurfaceOptions, ParamRect, PatchKind};
pub use hermite::{IntervalBezier, hermite_bezier};
pub use knots::{BlendKnots, BlendSpan};
pub use osculating_arc::OsculatingArc;
pub use two_curve::{PlainBlend, TwoCurveBlend};
