//! Circles in ℝᴰ: a centre, a radius and the orthonormal axes x, y of their plane, with
//! the point at angle θ at centre + r (cos θ x + sin θ y). The exact rational arcs
//! ([`crate::curve::NurbsCurve::arc`], [`crate::curve::RationalBezierCurve::circular_arc`])
//! are built on them.

use crate::Point;
use crate::error::{Error, Result};

/// A circle with its plane (see the module documentation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CircleFrame<const D: usize> {
    /// The centre.
    pub center: Point<D>,
    /// The unit vector towards angle 0.
    pub x_axis: Point<D>,
    /// The unit vector towards angle π/2, orthogonal to `x_axis`.
    pub y_axis: Point<D>,
    /// The radius r > 0.
    pub radius: f64,
}

impl<const D: usize> CircleFrame<D> {
    /// The circle of `radius` about `center` in the plane of the first two coordinates
    /// (D ≥ 2).
    pub fn in_xy_plane(center: Point<D>, radius: f64) -> Self {
        let mut x_axis = Point::<D>::zeros();
        let mut y_axis = Point::<D>::zeros();
        x_axis[0] = 1.0;
        y_axis[1] = 1.0;
        CircleFrame { center, x_axis, y_axis, radius }
    }
    /// Checks the radius (positive and finite).
    pub fn check(&self) -> Result<()> {
        if !(self.radius > 0.0 && self.radius.is_finite()) {
            return Err(Error::invalid("radius", format!("must be positive and finite, got {}", self.radius)));
        }
        Ok(())
    }
    /// The point at angle θ: centre + r cos θ x + r sin θ y.
    #[inline]
    pub fn point(&self, angle: f64) -> Point<D> {
        self.center + self.x_axis * (self.radius * angle.cos()) + self.y_axis * (self.radius * angle.sin())
    }
    /// The unit tangent at angle θ: −sin θ x + cos θ y.
    #[inline]
    pub fn unit_tangent(&self, angle: f64) -> Point<D> {
        -self.x_axis * angle.sin() + self.y_axis * angle.cos()
    }
}
