//! STEP spline data → splinekit kernel curves, for the geometric work import needs
//! (closest points, splitting, degree elevation of parameter-space loops).

use splinekit::Point;
use splinekit::curve::{CurveNearest, NurbsCurve};

use crate::error::{Result, StepError};
use crate::geometry::SplineCurve;

/// The spline as a kernel NURBS curve in D dimensions (weights 1 when not rational; the
/// STEP form is an open spline over its full knot vector, closed or not).
pub fn nurbs<const D: usize>(s: &SplineCurve) -> Result<NurbsCurve<D>> {
    let pts: Vec<Point<D>> =
        s.points.iter().map(|p| Point::<D>::from_fn(|k, _| p.get(k).copied().unwrap_or(0.0))).collect();
    let w = s.weights.clone().unwrap_or_else(|| vec![1.0; pts.len()]);
    NurbsCurve::new(s.degree, s.knots.clone(), pts, w).map_err(|e| StepError::plain(format!("B-spline curve: {e}")))
}

/// The parameter of the point of the spline closest to `p`.
pub fn closest_parameter(s: &SplineCurve, p: Point<3>) -> Result<f64> {
    let c = nurbs::<3>(s)?;
    let scale = s.points.iter().flatten().fold(1.0f64, |m, x| m.max(x.abs()));
    c.closest_point(&p, 1e-12 * scale).map(|n| n.t).map_err(|e| StepError::plain(format!("closest point: {e}")))
}
