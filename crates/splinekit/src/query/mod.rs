//! Geometric queries: projection of points onto curves and surfaces (point inversion).
//!
//! Every query searches a cover of the shape by cubic Hermite pieces (curves,
//! [`curve_cover`]) whose bounding boxes carry an error radius; the pieces are split where
//! the boxes cannot decide, and the answers are polished by Newton's method to full
//! precision. Batch queries build the cover once ([`CurveProjector`]).

pub mod bernstein_product;
pub mod bounds;
pub mod curve_cover;
pub mod project_curve;
pub mod slope;

pub use bounds::Aabb;
pub use project_curve::{CurveProjector, Nearest};
