//! Extrusions S(u, v) = c(u) + v·d, u in the curve's domain, v ∈ [0, 1].

use crate::Point;
use crate::curve::{Curve, Interval};
use crate::error::{Error, Result, check_points_finite};
use crate::surface::Surface;
use smallvec::{SmallVec, smallvec};

/// A curve swept along a straight direction.
pub struct Extrusion<const D: usize> {
    curve: Box<dyn Curve<D>>,
    direction: Point<D>,
}

impl<const D: usize> Extrusion<D> {
    /// Extrudes `curve` by the vector `direction` (non-zero).
    pub fn new(curve: Box<dyn Curve<D>>, direction: Point<D>) -> Result<Self> {
        check_points_finite("direction", &[direction])?;
        if direction.norm() == 0.0 {
            return Err(Error::invalid("direction", "must not be the zero vector"));
        }
        Ok(Extrusion { curve, direction })
    }
}

impl<const D: usize> Surface<D> for Extrusion<D> {
    fn domain_u(&self) -> Interval {
        self.curve.domain()
    }
    fn domain_v(&self) -> Interval {
        Interval::new(0.0, 1.0)
    }
    fn is_closed_u(&self) -> bool {
        self.curve.is_closed()
    }
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        let v = v.clamp(0.0, 1.0);
        let mut c: SmallVec<[Point<D>; 8]> = smallvec![Point::<D>::zeros(); du + 1];
        self.curve.eval(u, &mut c);
        for i in 0..=du {
            for j in 0..=dv {
                out[i * (dv + 1) + j] = match (i, j) {
                    (0, 0) => c[0] + self.direction * v,
                    (0, 1) => self.direction,
                    (_, 0) => c[i],
                    _ => Point::<D>::zeros(),
                };
            }
        }
    }
}
