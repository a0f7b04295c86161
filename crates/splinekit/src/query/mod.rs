//! Geometric queries: projection of points onto curves and surfaces (point inversion),
//! intersections of curves with curves and with surfaces, offsets of curves and surfaces,
//! arc length as a parameter.
//!
//! Every query searches a cover of the shape by cubic Hermite pieces (curves,
//! [`curve_cover`]) or bicubic Hermite patches (surfaces, [`surface_cover`]) whose
//! bounding boxes carry an error radius; pieces are split where the boxes and the
//! Bernstein coefficients of the distance's derivatives cannot decide, and the answers are
//! polished by Newton's method to full precision. Batch queries build the cover once
//! ([`CurveProjector`], [`SurfaceProjector`]).

pub mod arc_length;
pub mod bernstein_product;
pub mod best_first;
pub mod bounds;
pub mod branch;
pub mod branch_fit;
pub mod curve_cover;
pub mod curve_intersection;
pub mod curve_surface;
pub mod extent;
pub mod march;
pub mod newton;
pub mod normal_cone;
pub mod offset;
pub(crate) mod pair_count;
pub mod project_curve;
pub mod project_surface;
pub mod slope;
pub mod surface_cover;
pub mod surface_intersection;
pub mod surface_pair;
pub mod surface_seeds;
pub mod surface_slope;
pub mod tangent_cone;
pub mod touching;

pub use arc_length::{ArcLengthCurve, ArcLengthTable};
pub use bounds::Aabb;
pub use curve_intersection::{
    CurveIntersection, CurveIntersections, CurveOverlap, IntersectionKind, intersect_curves, self_intersections,
};
pub use curve_surface::{CurveSurfaceIntersection, intersect_curve_surface};
pub use extent::{CurveExtent, SurfaceExtent};
pub use offset::{CurveOffset, OffsetPiece, SurfaceOffset, offset_curve, offset_surface};
pub use project_curve::{CurveNearest, CurveProjector, Nearest};
pub use project_surface::{NearestOnSurface, SurfaceNearest, SurfaceProjector};
pub use surface_intersection::{EarlyStop, IntersectionBranch, intersect_surfaces};
