//! Operations on curves: arc length, closest point, knot insertion and refinement, knot
//! removal, degree elevation, splitting and Bézier decomposition.

pub mod closest_point;
pub mod length;
