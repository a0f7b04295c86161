//! Surfaces of revolution: S(u, v) = a + R_k(u)(c(v) − a), the profile c turned by the
//! angle u ∈ [0, θ] about the axis through a with unit direction k.
//!
//! With x = c(v) − a, R_k(u)x = (k·x)k + cos u (x − (k·x)k) + sin u (k × x), so
//! ∂^{i+j}S/∂uⁱ∂vʲ = δ_{i0}(k·x_j)k + cos⁽ⁱ⁾(u)(x_j − (k·x_j)k) + sin⁽ⁱ⁾(u)(k × x_j)
//! with x_j = c⁽ʲ⁾(v) (and the translation a in the position only).

use crate::Point;
use crate::curve::{Curve, Interval};
use crate::error::{Error, Result, check_points_finite};
use crate::surface::Surface;
use crate::tolerance::PARAMETER_RELATIVE;
use smallvec::{SmallVec, smallvec};

/// A profile curve revolved about an axis.
pub struct RevolvedSurface {
    profile: Box<dyn Curve<3>>,
    origin: Point<3>,
    axis: Point<3>,
    angle: f64,
}

impl RevolvedSurface {
    /// Revolves `profile` about the axis through `origin` along `axis` by `angle`
    /// radians (0 < angle ≤ 2π; 2π closes the surface in u).
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::model::Line;
    /// use splinekit::surface::Surface;
    /// use splinekit::surface::derived::RevolvedSurface;
    /// // The segment x = 1, 0 ≤ z ≤ 2 turned a full turn about the z axis: the cylinder of radius 1.
    /// let profile = Line::new(Point::<3>::new(1.0, 0.0, 0.0), Point::<3>::new(1.0, 0.0, 2.0)).unwrap();
    /// let axis = Point::<3>::new(0.0, 0.0, 1.0);
    /// let s = RevolvedSurface::new(Box::new(profile), Point::<3>::zeros(), axis, std::f64::consts::TAU).unwrap();
    /// assert!(s.is_closed_u());
    /// let q = s.point(1.0, 0.5);
    /// assert!((q[0].hypot(q[1]) - 1.0).abs() < 1e-15 && (q[2] - 1.0).abs() < 1e-15);
    /// ```
    pub fn new(profile: Box<dyn Curve<3>>, origin: Point<3>, axis: Point<3>, angle: f64) -> Result<Self> {
        check_points_finite("axis_point", &[origin])?;
        check_points_finite("axis", &[axis])?;
        let n = axis.norm();
        if n == 0.0 {
            return Err(Error::invalid("axis", "must not be the zero vector"));
        }
        if !(angle > 0.0 && angle <= std::f64::consts::TAU * (1.0 + PARAMETER_RELATIVE)) {
            return Err(Error::invalid("angle", format!("must be in (0, 2π], got {angle}")));
        }
        Ok(RevolvedSurface { profile, origin, axis: axis / n, angle: angle.min(std::f64::consts::TAU) })
    }
}

fn cross(a: &Point<3>, b: &Point<3>) -> Point<3> {
    a.cross(b)
}

impl Surface<3> for RevolvedSurface {
    fn domain_u(&self) -> Interval {
        Interval::new(0.0, self.angle)
    }
    fn domain_v(&self) -> Interval {
        self.profile.domain()
    }
    fn is_closed_u(&self) -> bool {
        self.angle == std::f64::consts::TAU
    }
    fn is_closed_v(&self) -> bool {
        self.profile.is_closed()
    }
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<3>]) {
        let u = if self.is_closed_u() { self.domain_u().wrap(u) } else { self.domain_u().clamp(u) };
        let mut x: SmallVec<[Point<3>; 8]> = smallvec![Point::<3>::zeros(); dv + 1];
        self.profile.eval(v, &mut x);
        x[0] -= self.origin;
        let k = self.axis;
        let (s, c) = u.sin_cos();
        for i in 0..=du {
            let (ci, si) = match i % 4 {
                0 => (c, s),
                1 => (-s, c),
                2 => (-c, -s),
                _ => (s, -c),
            };
            for j in 0..=dv {
                let xj = x[j];
                let along = k * k.dot(&xj);
                let mut p = (xj - along) * ci + cross(&k, &xj) * si;
                if i == 0 {
                    p += along;
                    if j == 0 {
                        p += self.origin;
                    }
                }
                out[i * (dv + 1) + j] = p;
            }
        }
    }
}
