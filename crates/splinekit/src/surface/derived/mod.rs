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
use crate::curve::{Curve, Interval};
use smallvec::{SmallVec, smallvec};

/// c(a + t (b − a)) and its derivatives with respect to t ∈ [0, 1] (the k-th scaled by
/// (b − a)ᵏ): a curve reparametrised to the unit interval.
pub(crate) fn unit_derivatives<const D: usize>(c: &dyn Curve<D>, t: f64, order: usize) -> SmallVec<[Point<D>; 8]> {
    let d: Interval = c.domain();
    let mut out: SmallVec<[Point<D>; 8]> = smallvec![Point::<D>::zeros(); order + 1];
    c.eval(d.lerp(t.clamp(0.0, 1.0)), &mut out);
    let mut s = 1.0;
    for o in out.iter_mut().skip(1) {
        s *= d.length();
        *o *= s;
    }
    out
}
