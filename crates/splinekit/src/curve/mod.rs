//! Curves: the [`Curve`] trait and every curve kind, one file each.

pub mod bezier;
pub mod bezier_spans;
pub mod bspline;
pub mod catmull_rom;
pub mod circle_frame;
pub(crate) mod control_box;
pub mod hermite;
pub mod model;
pub mod nurbs;
pub mod output_slot;
#[cfg(feature = "parallel")]
pub mod parallel;
pub mod rational;
pub mod rational_bezier;
pub mod reparametrized;
pub mod samples;
pub mod span_kernel;
pub mod traits;

pub use crate::Interval;
pub use crate::ops::length::CurveArcLength;
pub use crate::query::extent::CurveExtent;
pub use crate::query::project_curve::CurveNearest;
pub use bezier::BezierCurve;
pub use bspline::BSplineCurve;
pub use catmull_rom::CatmullRomCurve;
pub use circle_frame::CircleFrame;
pub use hermite::HermiteCurve;
pub use nurbs::NurbsCurve;
pub use rational_bezier::RationalBezierCurve;
pub use reparametrized::Reparametrized;
pub use samples::CurveSamples;
pub use traits::{Curve, FrenetFrame, curvature_from};
