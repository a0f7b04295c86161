//! Operations on curves: arc length, knot insertion and refinement, knot
//! removal, degree elevation, splitting and Bézier decomposition.

pub mod curve_ops;
pub mod decomposition;
pub mod degree_elevation;
pub mod homogeneous;
pub mod knot_insertion;
pub mod knot_removal;
pub mod length;
pub mod spline_data;

pub use decomposition::BezierSegment;
pub use homogeneous::Homogeneous;
pub use spline_data::SplineData;
