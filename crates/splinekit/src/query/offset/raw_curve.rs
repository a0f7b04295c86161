//! The exact raw offset of a plane curve.
//!
//! For a regular plane curve c with unit tangent T = c′/|c′| and right-hand unit normal
//! n = (T_y, −T_x), the raw offset at signed distance d is o(t) = c(t) + d·n(t). Its signed
//! curvature κ = (c′ × c″)/|c′|³ (positive where c turns left) gives T′ = κ|c′|·(−T_y, T_x)
//! and n′ = κ|c′|·T (Frenet), so
//!
//! o′(t) = (1 + d·κ(t))·c′(t):
//!
//! the offset runs parallel to the curve where 1 + dκ > 0, backwards where 1 + dκ < 0, and
//! has a cusp where 1 + dκ changes sign (d = −1/κ, the curve's radius of curvature on the
//! side of the offset). A counter-clockwise circle of radius r has κ = 1/r and n pointing
//! outwards, so its offset is the circle of radius r + d.

use std::cell::Cell;

use crate::Point;
use crate::basis::Side;
use crate::curve::Curve;

/// Position, derivative and the speed factor 1 + dκ of the raw offset at one parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RawSample {
    /// Parameter t.
    pub t: f64,
    /// o(t).
    pub point: Point<2>,
    /// o′(t).
    pub derivative: Point<2>,
    /// 1 + d·κ(t).
    pub factor: f64,
}

/// The raw offset of a plane curve at signed distance `distance`.
pub struct RawOffset<'c, C: ?Sized> {
    /// The curve.
    pub curve: &'c C,
    /// d.
    pub distance: f64,
    /// Pieces its approximations may still use, all of them together (the whole offset,
    /// its arcs between cusps and its kept stretches): see
    /// [`MAX_TOTAL_PIECES`](crate::query::offset::MAX_TOTAL_PIECES).
    pub pieces_left: Cell<usize>,
}

impl<'c, C: ?Sized> RawOffset<'c, C> {
    /// The raw offset of `curve` at `distance`, its approximations allowed
    /// [`MAX_TOTAL_PIECES`](crate::query::offset::MAX_TOTAL_PIECES) pieces.
    pub fn new(curve: &'c C, distance: f64) -> Self {
        RawOffset { curve, distance, pieces_left: Cell::new(crate::query::offset::MAX_TOTAL_PIECES) }
    }
}

impl<C: Curve<2> + ?Sized> RawOffset<'_, C> {
    /// The raw offset at t (one-sided limit `side`); `None` where c′(t) = 0 (no normal).
    pub fn at(&self, t: f64, side: Side) -> Option<RawSample> {
        let mut out = [Point::<2>::zeros(); 3];
        self.curve.eval_side(t, side, &mut out);
        let (c, d1, d2) = (out[0], out[1], out[2]);
        let speed = d1.norm();
        if !(speed > 0.0 && speed.is_finite()) {
            return None;
        }
        let tangent = d1 / speed;
        let normal = Point::<2>::new(tangent.y, -tangent.x);
        let kappa = (d1.x * d2.y - d1.y * d2.x) / (speed * speed * speed);
        let factor = 1.0 + self.distance * kappa;
        Some(RawSample { t, point: c + normal * self.distance, derivative: d1 * factor, factor })
    }
}
