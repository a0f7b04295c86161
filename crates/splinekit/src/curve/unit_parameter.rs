//! Curves reparametrised to the unit interval, as blends and derived surfaces use them.

use smallvec::{SmallVec, smallvec};

use crate::Point;
use crate::basis::Side;
use crate::curve::Curve;

/// c(a + s (b − a)) and its derivatives with respect to s ∈ [0, 1] (the k-th scaled by
/// (b − a)ᵏ), for the curve's domain [a, b].
pub fn unit_derivatives<const D: usize, C: Curve<D> + ?Sized>(
    c: &C,
    s: f64,
    side: Side,
    order: usize,
) -> SmallVec<[Point<D>; 8]> {
    let d = c.domain();
    let mut out: SmallVec<[Point<D>; 8]> = smallvec![Point::<D>::zeros(); order + 1];
    c.eval_side(d.lerp(s.clamp(0.0, 1.0)), side, &mut out);
    let mut f = 1.0;
    for o in out.iter_mut().skip(1) {
        f *= d.length();
        *o *= f;
    }
    out
}
