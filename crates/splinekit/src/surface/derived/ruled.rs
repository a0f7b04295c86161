//! Ruled surfaces S(u, v) = (1 − v) c₁(u) + v c₂(u), each curve reparametrised to
//! u ∈ [0, 1], v ∈ [0, 1].

use smallvec::{SmallVec, smallvec};

use crate::Point;
use crate::curve::{Curve, Reparametrized};
use crate::error::{Error, Result};
use crate::surface::Surface;

/// The straight lines between corresponding points of two curves.
pub struct RuledSurface<const D: usize> {
    first: Reparametrized<Box<dyn Curve<D>>>,
    second: Reparametrized<Box<dyn Curve<D>>>,
}

impl<const D: usize> RuledSurface<D> {
    /// The ruled surface between two curves (both reparametrised to [0, 1]).
    pub fn new(first: Box<dyn Curve<D>>, second: Box<dyn Curve<D>>) -> Result<Self> {
        if first.is_closed() != second.is_closed() {
            return Err(Error::invalid("second", "both curves must be open or both closed"));
        }
        Ok(RuledSurface { first: Reparametrized::unit(first)?, second: Reparametrized::unit(second)? })
    }
}

impl<const D: usize> Surface<D> for RuledSurface<D> {
    crate::surface::unit_square::unit_square_domains!();
    fn is_closed_u(&self) -> bool {
        self.first.is_closed()
    }
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        let u = if self.is_closed_u() { self.domain_u().wrap(u) } else { u.clamp(0.0, 1.0) };
        let v = v.clamp(0.0, 1.0);
        let mut a: SmallVec<[Point<D>; 8]> = smallvec![Point::<D>::zeros(); du + 1];
        let mut b: SmallVec<[Point<D>; 8]> = smallvec![Point::<D>::zeros(); du + 1];
        self.first.eval(u, &mut a);
        self.second.eval(u, &mut b);
        for i in 0..=du {
            for j in 0..=dv {
                out[i * (dv + 1) + j] = match j {
                    0 => a[i] * (1.0 - v) + b[i] * v,
                    1 => b[i] - a[i],
                    _ => Point::<D>::zeros(),
                };
            }
        }
    }
}
