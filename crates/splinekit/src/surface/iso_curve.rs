//! Isoparametric curves of a surface as [`Curve`]s.

use crate::Point;
use crate::basis::Side;
use crate::curve::{Curve, Interval};
use crate::surface::Surface;

/// Which parameter an isocurve keeps fixed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// u = const; the curve runs along v.
    U,
    /// v = const; the curve runs along u.
    V,
}

/// The curve v ↦ S(u₀, v) (`Direction::U`) or u ↦ S(u, v₀) (`Direction::V`).
pub struct IsoCurve<'a, S: ?Sized> {
    surface: &'a S,
    fixed: f64,
    direction: Direction,
}

impl<'a, S: ?Sized> IsoCurve<'a, S> {
    /// The isocurve of `surface` with the `direction` parameter fixed at `value`.
    pub fn new(surface: &'a S, direction: Direction, value: f64) -> Self {
        IsoCurve { surface, fixed: value, direction }
    }
}

impl<const D: usize, S: Surface<D> + ?Sized> Curve<D> for IsoCurve<'_, S> {
    fn domain(&self) -> Interval {
        match self.direction {
            Direction::U => self.surface.domain_v(),
            Direction::V => self.surface.domain_u(),
        }
    }
    fn is_closed(&self) -> bool {
        match self.direction {
            Direction::U => self.surface.is_closed_v(),
            Direction::V => self.surface.is_closed_u(),
        }
    }
    fn breakpoints(&self) -> Vec<f64> {
        match self.direction {
            Direction::U => self.surface.breakpoints_v(),
            Direction::V => self.surface.breakpoints_u(),
        }
    }
    fn eval_side(&self, t: f64, _side: Side, out: &mut [Point<D>]) {
        let k = out.len() - 1;
        match self.direction {
            // (0, j) partials are out[j] when du = 0.
            Direction::U => self.surface.eval_partials(self.fixed, t, 0, k, out),
            // (i, 0) partials are out[i] when dv = 0.
            Direction::V => self.surface.eval_partials(t, self.fixed, k, 0, out),
        }
    }
}
