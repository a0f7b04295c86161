//! Offsets: planar curves at a signed distance d, c(t) + d·n(t), and surfaces,
//! S(u, v) + d·N(u, v), as B-splines within a tolerance of the exact offset.
//!
//! * [`planar_frame`]: the plane a curve is offset in (2-D curves, or 3-D curves in a plane
//!   with a given normal direction) and its in-plane coordinates.
//! * [`raw_curve`]: the exact raw offset of a plane curve and its derivative.
//! * [`hermite_fit`]: the adaptive cubic approximation of the raw offset.
//! * [`curve_offset`]: cusps and self-intersections of the raw offset trimmed away, the
//!   pieces of the true offset.
//! * [`surface_offset`]: tensor-product approximation of the offset surface.

pub mod curve_offset;
pub mod hermite_fit;
pub mod planar_frame;
pub mod raw_curve;
pub mod surface_offset;

pub use curve_offset::{CurveOffset, OffsetPiece, offset_curve};
pub use surface_offset::{SurfaceOffset, offset_surface};

use crate::error::{Error, Result};

/// Checks the distance (finite) and the tolerance (finite, > 0) of an offset.
pub(crate) fn check_arguments(distance: f64, tolerance: f64) -> Result<()> {
    if !distance.is_finite() {
        return Err(Error::invalid("distance", format!("must be finite, got {distance}")));
    }
    if !(tolerance > 0.0 && tolerance.is_finite()) {
        return Err(Error::invalid("tolerance", format!("must be finite and > 0, got {tolerance}")));
    }
    Ok(())
}

/// The smallest tolerance, relative to the size of the offset's coordinates: below it the
/// error measured is rounding.
pub const MIN_RELATIVE_TOLERANCE: f64 = 1e-13;

/// The most pieces one approximation may have, besides four per span of the curve.
pub const MAX_PIECES: usize = 10_000;

/// The most pieces all the approximations of one offset may have together (the whole raw
/// offset, its arcs between cusps, the pairs of arcs next to each cusp and the kept
/// stretches), so that an offset with many cusps cannot multiply the work of one
/// approximation by their number.
pub const MAX_TOTAL_PIECES: usize = 4 * MAX_PIECES;

/// Refuses a tolerance below what double precision resolves on coordinates up to `scale`.
pub(crate) fn check_resolvable(tolerance: f64, scale: f64) -> Result<()> {
    if tolerance < MIN_RELATIVE_TOLERANCE * scale || !scale.is_finite() {
        return Err(Error::invalid(
            "tolerance",
            format!(
                "{tolerance:e} is below what double precision resolves on an offset with coordinates up to {scale:e} (at least {:e})",
                MIN_RELATIVE_TOLERANCE * scale
            ),
        ));
    }
    Ok(())
}
