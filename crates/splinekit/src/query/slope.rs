//! The sign of the distance function's slope on a cover piece.
//!
//! For f(t) = |c(t) − q|²/2 the slope is g = f′ = (c − q)·c′. On a piece, g in the piece
//! parameter s is approximated by G = (H − q)·H_s, a quintic whose Bernstein coefficients
//! [`bernstein_product`](crate::query::bernstein_product) computes exactly; G's end
//! coefficients are the true slopes at the ends (H interpolates c and c′ there). The
//! difference |g − G| ≤ |c − q|·|c_s − H_s| + |c − H|·|H_s| is bounded with the piece's
//! radii, so coefficients beyond that margin have the sign of g on their share of the piece
//! (a Bernstein polynomial lies between its extreme coefficients).

use crate::Point;
use crate::query::bernstein_product::product;
use crate::query::bounds::Aabb;
use crate::query::curve_cover::{CurvePiece, ROUNDING};

/// Two minima found closer than this (relative to the coordinates' size) are one: a shallow
/// minimum is located only to about √ε, so Newton iterations from two pieces may end this
/// far apart on it.
pub const DUPLICATE_DISTANCE: f64 = 1e-7;

/// Relative size below which a slope or a distance difference counts as zero (rounding).
pub const ZERO_SLOPE: f64 = 1e-11;

/// What a piece's slope coefficients say about the distance function on it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// f strictly increasing: no interior extremum.
    Increasing,
    /// f strictly decreasing: no interior extremum.
    Decreasing,
    /// f constant to rounding (a query at the centre of a circular arc).
    Flat,
    /// Exactly one sign change of the slope from − to +, bracketed by the ends: one
    /// interior minimum.
    OneMinimum,
    /// Exactly one sign change from + to −: one interior maximum, no interior minimum.
    OneMaximum,
    /// The coefficients cannot tell: split the piece.
    Unresolved,
}

/// The classification of one piece with respect to a query point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlopeSigns {
    /// The shape.
    pub shape: Shape,
    /// Direction of f leaving the start: the sign (−1, 0, +1) of the first slope
    /// coefficient beyond the margin.
    pub start: i8,
    /// Direction of f arriving at the end: the sign of the last coefficient beyond the margin.
    pub end: i8,
}

/// Classifies `piece` for the query point `q`. A piece whose box is at the rounding level
/// of the coordinates (such as the pole of a sphere, a circle of radius 10⁻¹⁶) is flat.
pub fn classify<const D: usize>(piece: &CurvePiece<D>, q: &Point<D>) -> SlopeSigns {
    if is_rounding_sized(&piece.bounds, q) {
        return SlopeSigns { shape: Shape::Flat, start: 0, end: 0 };
    }
    let b = &piece.control;
    let a: [Point<D>; 4] = [b[0] - q, b[1] - q, b[2] - q, b[3] - q];
    let e: [Point<D>; 3] = [(b[1] - b[0]) * 3.0, (b[2] - b[1]) * 3.0, (b[3] - b[2]) * 3.0];
    let mut g = [0.0; 6];
    product(&a, &e, |x, y| x.dot(y), &mut g);
    let big_a = a.iter().fold(0.0f64, |m, x| m.max(x.norm())) + piece.radius;
    let big_e = e.iter().fold(0.0f64, |m, x| m.max(x.norm())) + piece.slope_radius;
    let zero = ZERO_SLOPE * big_a * big_e;
    let margin = big_a * piece.slope_radius + piece.radius * big_e;
    // The end coefficients are exact slopes; the inner ones carry the margin.
    let tol = |k: usize| if k == 0 || k == 5 { zero } else { zero + margin };
    let sign = |k: usize| {
        if g[k] > tol(k) {
            1i8
        } else if g[k] < -tol(k) {
            -1
        } else {
            0
        }
    };
    let signs: [i8; 6] = std::array::from_fn(sign);
    let start = signs.iter().copied().find(|&s| s != 0).unwrap_or(0);
    let end = signs.iter().rev().copied().find(|&s| s != 0).unwrap_or(0);
    let shape = shape_of(piece, q, &signs, zero);
    SlopeSigns { shape, start, end }
}

/// Whether a box is no bigger than the rounding noise of coordinates as large as its own and
/// the query's.
pub fn is_rounding_sized<const D: usize>(bounds: &Aabb<D>, q: &Point<D>) -> bool {
    let scale = q.amax().max(bounds.min.amax()).max(bounds.max.amax());
    bounds.diagonal() <= 16.0 * ROUNDING * scale
}

fn shape_of<const D: usize>(piece: &CurvePiece<D>, q: &Point<D>, signs: &[i8; 6], zero: f64) -> Shape {
    // Zero end coefficients do not break monotonicity (an extremum exactly at an end).
    let inner = &signs[1..5];
    if inner.iter().all(|&s| s > 0) && signs[0] >= 0 && signs[5] >= 0 {
        return Shape::Increasing;
    }
    if inner.iter().all(|&s| s < 0) && signs[0] <= 0 && signs[5] <= 0 {
        return Shape::Decreasing;
    }
    if is_flat(piece, q, signs, zero) {
        return Shape::Flat;
    }
    if signs.iter().all(|&s| s != 0) {
        let changes = signs.windows(2).filter(|w| w[0] != w[1]).count();
        if changes == 1 {
            return if signs[0] < 0 { Shape::OneMinimum } else { Shape::OneMaximum };
        }
    }
    Shape::Unresolved
}

/// Flat: every coefficient within its margin, and the sampled slopes and distances at
/// start, middle and end equal to rounding.
fn is_flat<const D: usize>(piece: &CurvePiece<D>, q: &Point<D>, signs: &[i8; 6], zero: f64) -> bool {
    if signs.iter().any(|&s| s != 0) {
        return false;
    }
    let h = piece.end.t - piece.start.t;
    let samples = [&piece.start, &piece.mid, &piece.end];
    let slopes_vanish = samples.iter().all(|s| ((s.point - q).dot(&s.derivative) * h).abs() <= zero);
    let d: Vec<f64> = samples.iter().map(|s| (s.point - q).norm()).collect();
    let scale = d.iter().fold(0.0f64, |m, x| m.max(*x)) + piece.bounds.diagonal();
    slopes_vanish && (d[0] - d[1]).abs() <= ZERO_SLOPE * scale && (d[2] - d[1]).abs() <= ZERO_SLOPE * scale
}
