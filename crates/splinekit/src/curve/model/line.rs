//! The line segment c(t) = (1 − t) A + t B, t ∈ [0, 1].

use crate::Point;
use crate::basis::Side;
use crate::curve::{Curve, Interval};
use crate::error::{Result, check_points_finite};

/// Straight segment from `from` (t = 0) to `to` (t = 1), in any dimension.
#[derive(Debug, Clone, PartialEq)]
pub struct Line<const D: usize> {
    from: Point<D>,
    to: Point<D>,
}

impl<const D: usize> Line<D> {
    /// The segment between two finite points.
    pub fn new(from: Point<D>, to: Point<D>) -> Result<Self> {
        check_points_finite("from", &[from])?;
        check_points_finite("to", &[to])?;
        Ok(Line { from, to })
    }
}

impl<const D: usize> Curve<D> for Line<D> {
    fn domain(&self) -> Interval {
        Interval::new(0.0, 1.0)
    }
    fn eval_side(&self, t: f64, _side: Side, out: &mut [Point<D>]) {
        let t = t.clamp(0.0, 1.0);
        for (k, o) in out.iter_mut().enumerate() {
            *o = match k {
                0 => self.from + (self.to - self.from) * t,
                1 => self.to - self.from,
                _ => Point::<D>::zeros(),
            };
        }
    }
}
