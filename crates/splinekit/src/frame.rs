//! Affine frames: x ↦ A x + b, with A any invertible linear map (rotation, uniform or
//! non-uniform scale, shear). Positions transform as points, derivatives as vectors
//! (A v, no translation).

use nalgebra::{SMatrix, Unit, Vector3};

use crate::Point;
use crate::error::{Error, Result};

/// An affine map x ↦ linear · x + translation in ℝᴰ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Affine<const D: usize> {
    /// The linear part A.
    pub linear: SMatrix<f64, D, D>,
    /// The translation b.
    pub translation: Point<D>,
}

impl<const D: usize> Default for Affine<D> {
    fn default() -> Self {
        Self::identity()
    }
}

impl<const D: usize> Affine<D> {
    /// The identity map.
    pub fn identity() -> Self {
        Affine { linear: SMatrix::identity(), translation: Point::<D>::zeros() }
    }
    /// x ↦ x + v.
    pub fn translation(v: Point<D>) -> Self {
        Affine { linear: SMatrix::identity(), translation: v }
    }
    /// x ↦ s x (about the origin).
    pub fn uniform_scale(s: f64) -> Self {
        Affine { linear: SMatrix::identity() * s, translation: Point::<D>::zeros() }
    }
    /// x ↦ diag(s) x (about the origin).
    pub fn scale(s: Point<D>) -> Self {
        Affine { linear: SMatrix::from_diagonal(&s), translation: Point::<D>::zeros() }
    }
    /// The map `self` applied after `first`: x ↦ self(first(x)).
    pub fn after(&self, first: &Affine<D>) -> Self {
        Affine { linear: self.linear * first.linear, translation: self.linear * first.translation + self.translation }
    }
    /// The same linear map acting about `center` instead of the origin:
    /// x ↦ A (x − c) + c + b.
    pub fn about(&self, center: &Point<D>) -> Self {
        Affine { linear: self.linear, translation: center - self.linear * center + self.translation }
    }
    /// Maps a position: A x + b.
    #[inline]
    pub fn apply_point(&self, p: &Point<D>) -> Point<D> {
        self.linear * p + self.translation
    }
    /// Maps a vector (a derivative): A v.
    #[inline]
    pub fn apply_vector(&self, v: &Point<D>) -> Point<D> {
        self.linear * v
    }
    /// Maps a position in the frame of a local piece with origin o: o + T(p − o), the map
    /// acting about o instead of the world origin.
    #[inline]
    pub fn apply_point_about(&self, origin: &Point<D>, p: &Point<D>) -> Point<D> {
        origin + self.apply_point(&(p - origin))
    }
    /// Maps `[c, c', c'', …]` about `origin`: the first entry as a point
    /// ([`Self::apply_point_about`]), the derivatives as vectors (A v) — the frame of a
    /// local piece applied to its values.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::frame::Affine;
    /// // A quarter turn about o = (1, 0): the point (2, 0) goes to (1, 1), the velocity
    /// // (0, 1) to (−1, 0).
    /// let turn = Affine::rotation_2d(std::f64::consts::FRAC_PI_2);
    /// let mut jet = [Point::<2>::new(2.0, 0.0), Point::<2>::new(0.0, 1.0)];
    /// turn.apply_derivatives_about(&Point::<2>::new(1.0, 0.0), &mut jet);
    /// assert!((jet[0] - Point::<2>::new(1.0, 1.0)).norm() < 1e-15);
    /// assert!((jet[1] - Point::<2>::new(-1.0, 0.0)).norm() < 1e-15);
    /// ```
    #[inline]
    pub fn apply_derivatives_about(&self, origin: &Point<D>, values: &mut [Point<D>]) {
        if let Some((first, rest)) = values.split_first_mut() {
            *first = self.apply_point_about(origin, first);
            for v in rest {
                *v = self.apply_vector(v);
            }
        }
    }
    /// The inverse map, if A is invertible.
    pub fn inverse(&self) -> Result<Self> {
        let inv =
            self.linear.try_inverse().ok_or_else(|| Error::invalid("transform", "the linear part is singular"))?;
        Ok(Affine { linear: inv, translation: -(inv * self.translation) })
    }
}

impl<const D: usize> Affine<D> {
    /// A rotation by `angle` radians in dimension D: in 2-D about the origin (no axis, or
    /// the z axis), in 3-D about `axis` through the origin. Other dimensions are an error.
    pub fn rotation_in(axis: Option<&[f64]>, angle: f64) -> Result<Self> {
        if !angle.is_finite() {
            return Err(Error::invalid("rotate.angle", format!("must be finite, got {angle}")));
        }
        let mut m = SMatrix::<f64, D, D>::identity();
        match D {
            2 => {
                let flip = match axis {
                    None => 1.0,
                    Some([x, y, z]) if *x == 0.0 && *y == 0.0 && *z != 0.0 => z.signum(),
                    Some(a) => {
                        return Err(Error::invalid(
                            "rotate.axis",
                            format!("2-D rotations turn about z, got axis {a:?}"),
                        ));
                    }
                };
                let (s, c) = (flip * angle).sin_cos();
                m[(0, 0)] = c;
                m[(0, 1)] = -s;
                m[(1, 0)] = s;
                m[(1, 1)] = c;
            }
            3 => {
                let a = axis.ok_or_else(|| Error::invalid("rotate.axis", "missing (3-D rotations need an axis)"))?;
                if a.len() != 3 {
                    return Err(Error::invalid("rotate.axis", format!("expected 3 coordinates, got {}", a.len())));
                }
                let r = Affine::<3>::rotation(Point::<3>::new(a[0], a[1], a[2]), angle)?;
                for i in 0..3 {
                    for j in 0..3 {
                        m[(i, j)] = r.linear[(i, j)];
                    }
                }
            }
            _ => return Err(Error::invalid("rotate", format!("rotations are defined in 2-D and 3-D, not {D}-D"))),
        }
        Ok(Affine { linear: m, translation: Point::<D>::zeros() })
    }
}

impl Affine<3> {
    /// Rotation by `angle` radians about `axis` through the origin (right-hand rule).
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::frame::Affine;
    /// // A quarter turn about z takes x to y; about a point, that point stays put.
    /// let turn = Affine::rotation(Point::<3>::z(), std::f64::consts::FRAC_PI_2).unwrap();
    /// assert!((turn.apply_point(&Point::<3>::x()) - Point::<3>::y()).norm() < 1e-16);
    /// let c = Point::<3>::new(1.0, 2.0, 3.0);
    /// assert!((turn.about(&c).apply_point(&c) - c).norm() < 1e-15);
    /// assert!(Affine::rotation(Point::<3>::zeros(), 1.0).is_err());
    /// ```
    pub fn rotation(axis: Point<3>, angle: f64) -> Result<Self> {
        let n = axis.norm();
        if !(n > 0.0 && n.is_finite() && angle.is_finite()) {
            return Err(Error::invalid(
                "rotate",
                format!("axis must be non-zero and finite, angle finite; got axis norm {n}, angle {angle}"),
            ));
        }
        let r = nalgebra::Rotation3::from_axis_angle(&Unit::new_normalize(Vector3::from(axis)), angle);
        Ok(Affine { linear: *r.matrix(), translation: Point::<3>::zeros() })
    }
}

impl Affine<2> {
    /// Rotation by `angle` radians about the origin (counter-clockwise).
    pub fn rotation_2d(angle: f64) -> Self {
        let (s, c) = angle.sin_cos();
        Affine { linear: SMatrix::<f64, 2, 2>::new(c, -s, s, c), translation: Point::<2>::zeros() }
    }
}
