//! What the surface–surface intersection hands between its stages: a branch of the
//! intersection curve ([`IntersectionBranch`], [`EarlyStop`]), the test whether a point lies
//! near a branch already traced ([`near_polyline`]), and the error for coinciding surfaces
//! ([`coincidence`]). A leaf: the seeding, marching and touching stages all use it, and it
//! uses none of them.

use crate::Point;
use crate::error::Error;
use crate::query::bounds::Aabb;

/// Why a branch stopped before it closed or left through a boundary.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EarlyStop {
    /// The surfaces' normals became parallel (they touch).
    Tangential,
    /// No step down to the halving limit met the chord error.
    StepLimit,
    /// The branch reached [`crate::query::surface_intersection::MAX_POINTS`] points.
    PointLimit,
}

/// One branch of the intersection curve: a polyline in 3-D and in both parameter planes.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct IntersectionBranch {
    /// Points on both surfaces (within the tolerance), the chord error from the curve.
    pub points: Vec<Point<3>>,
    /// (u, v) on the first surface at each point.
    pub params_a: Vec<[f64; 2]>,
    /// (u, v) on the second surface at each point.
    pub params_b: Vec<[f64; 2]>,
    /// Whether the branch is a closed loop (its last point repeats the first).
    pub closed: bool,
    /// Why marching stopped early, in either direction, if it did.
    pub early_stop: Option<EarlyStop>,
    /// Whether the surfaces touch along the branch (their normals are parallel at every
    /// point) rather than cross.
    pub tangent: bool,
}

/// Whether `q` lies within `reach` of a segment of the polyline (runs of 16 segments whose
/// box is farther are skipped).
pub(crate) fn near_polyline(points: &[Point<3>], q: &Point<3>, reach: f64) -> bool {
    if points.len() == 1 {
        return (points[0] - q).norm() <= reach;
    }
    let mut start = 0;
    while start + 1 < points.len() {
        let end = (start + 17).min(points.len());
        let run = &points[start..end];
        if Aabb::around(run, 0.0).distance_to(q) <= reach
            && run.windows(2).any(|w| segment_distance(&w[0], &w[1], q) <= reach)
        {
            return true;
        }
        start = end - 1;
    }
    false
}

/// The distance from `q` to the segment from `p` to `r`.
pub(crate) fn segment_distance(p: &Point<3>, r: &Point<3>, q: &Point<3>) -> f64 {
    let d = r - p;
    let s = if d.norm_squared() > 0.0 { ((q - p).dot(&d) / d.norm_squared()).clamp(0.0, 1.0) } else { 0.0 };
    (p + d * s - q).norm()
}

/// The error for surfaces that coincide over a region around (u, v) on the first.
pub fn coincidence(u: f64, v: f64) -> Error {
    Error::numerical(
        "surface intersection",
        format!("the surfaces coincide over a region (about ({u:.6}, {v:.6}) on the first)"),
    )
}
