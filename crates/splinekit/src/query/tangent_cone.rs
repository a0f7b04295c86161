//! Cones that hold every tangent direction of a cover piece.
//!
//! The s-derivative of a piece's Hermite cubic is Σ 3(b_{j+1} − b_j) B_{j,2}(s), so it lies
//! in the convex cone of the three control legs; the curve's own derivative differs from it
//! by at most the piece's `slope_radius`, which widens the cone by
//! asin(slope_radius / shortest leg). Two pieces whose cones share no line direction meet
//! at most once: two meetings would give a chord whose direction lies in both cones
//! (mean value theorem).

use crate::Point;
use crate::query::curve_cover::CurvePiece;

/// A circular cone of directions: unit axis and half-angle (radians, π when unknown).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TangentCone<const D: usize> {
    /// Unit axis (zero when the half-angle is π).
    pub axis: Point<D>,
    /// Half-angle.
    pub half_angle: f64,
}

impl<const D: usize> TangentCone<D> {
    /// The cone of the tangent directions of `piece`.
    pub fn of(piece: &CurvePiece<D>) -> Self {
        let b = &piece.control;
        let legs = [(b[1] - b[0]) * 3.0, (b[2] - b[1]) * 3.0, (b[3] - b[2]) * 3.0];
        Self::of_legs(&legs, piece.slope_radius)
    }

    /// The cone holding every vector w + e with w in the convex cone of `legs` and
    /// |e| ≤ `slack`: the cone of the legs' directions widened by asin(slack / shortest leg)
    /// (π when a leg is shorter than `slack` or the legs cancel).
    pub fn of_legs(legs: &[Point<D>], slack: f64) -> Self {
        let all = TangentCone { axis: Point::<D>::zeros(), half_angle: std::f64::consts::PI };
        let shortest = legs.iter().map(|l| l.norm()).fold(f64::INFINITY, f64::min);
        let chord = legs.iter().fold(Point::<D>::zeros(), |s, l| s + l / l.norm().max(f64::MIN_POSITIVE));
        if legs.is_empty() || shortest <= slack || chord.norm() == 0.0 {
            return all;
        }
        let axis = chord.normalize();
        // The angle grows with the chord |axis − l̂|, so one arcsine of the longest chord.
        let far = legs.iter().map(|l| (axis - l.normalize()).norm()).fold(0.0f64, f64::max);
        let spread = 2.0 * (far / 2.0).min(1.0).asin();
        let widen = (slack / shortest).min(1.0).asin();
        TangentCone { axis, half_angle: (spread + widen).min(std::f64::consts::PI) }
    }

    /// Whether no line direction (a direction or its opposite) lies in both cones.
    pub fn separated_lines(&self, other: &Self) -> bool {
        if self.half_angle + other.half_angle >= std::f64::consts::FRAC_PI_2 {
            return false;
        }
        let between = angle(&self.axis, &other.axis);
        let undirected = between.min(std::f64::consts::PI - between);
        undirected > self.half_angle + other.half_angle
    }

    /// The smallest cone holding both.
    pub fn union(&self, other: &Self) -> Self {
        if self.half_angle >= std::f64::consts::PI || other.half_angle >= std::f64::consts::PI {
            return TangentCone { axis: Point::<D>::zeros(), half_angle: std::f64::consts::PI };
        }
        let between = angle(&self.axis, &other.axis);
        // About the bisector of the axes, each cone lies within half the angle between
        // the axes plus its own half-angle.
        let half = between / 2.0 + self.half_angle.max(other.half_angle);
        let sum = self.axis + other.axis;
        if sum.norm() == 0.0 || half >= std::f64::consts::PI {
            return TangentCone { axis: Point::<D>::zeros(), half_angle: std::f64::consts::PI };
        }
        TangentCone { axis: sum.normalize(), half_angle: half }
    }
}

/// The angle between two unit vectors, accurate for small angles.
pub fn angle<const D: usize>(a: &Point<D>, b: &Point<D>) -> f64 {
    2.0 * ((a - b).norm() / 2.0).min(1.0).asin()
}
