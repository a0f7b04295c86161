//! Surfaces made from curves: revolution, ruled surfaces, extrusions and Coons patches.
//! Their partials of every order come from the curves' derivatives.

pub mod coons;
pub mod extrusion;
pub mod revolved;
pub mod ruled;
pub mod sweep;

pub use coons::{CoonsBlend, CoonsPatch};
pub use extrusion::Extrusion;
pub use revolved::RevolvedSurface;
pub use ruled::RuledSurface;
pub use sweep::SweepSurface;

use crate::Point;
use crate::basis::Side;
use crate::curve::Curve;
use smallvec::SmallVec;

/// A curve reparametrised to [0, 1], right-hand limits (see
/// [`crate::curve::unit_parameter::unit_derivatives`]).
pub(crate) fn unit_derivatives<const D: usize>(c: &dyn Curve<D>, t: f64, order: usize) -> SmallVec<[Point<D>; 8]> {
    crate::curve::unit_parameter::unit_derivatives(c, t, Side::Right, order)
}
