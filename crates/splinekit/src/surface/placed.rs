//! Placed surfaces: a surface moved rigidly into a right-handed orthonormal frame, with its
//! parameters kept (the `AXIS2_PLACEMENT_3D` of STEP's elementary surfaces).
//!
//! With the frame's x, y, z ([`OrthonormalAxes`]: z along the axis, x the reference
//! direction made orthogonal to it, y = z × x), the placed surface is
//! P(u, v) = o + S₁(u, v) x + S₂(u, v) y + S₃(u, v) z, and every partial derivative is the
//! rotated partial of S: ∂^{i+j}P/∂uⁱ∂vʲ = R ∂^{i+j}S/∂uⁱ∂vʲ with R = [x y z] (i + j ≥ 1).

use crate::Point;
use crate::axes::OrthonormalAxes;
use crate::error::{Error, Result};
use crate::surface::Surface;

/// A surface in a placement (3-D frames; in D > 3 the frame acts on the first three
/// coordinates).
pub struct PlacedSurface<const D: usize> {
    surface: Box<dyn Surface<D>>,
    origin: Point<D>,
    /// Columns x, y, z of the rotation (the first three coordinates).
    frame: [[f64; 3]; 3],
}

impl<const D: usize> PlacedSurface<D> {
    /// `surface` placed at `origin` with its z along `axis` and its x along the part of
    /// `ref_direction` orthogonal to `axis` (errors name `axis` or `ref_direction`).
    pub fn new(
        surface: Box<dyn Surface<D>>,
        origin: [f64; 3],
        axis: [f64; 3],
        ref_direction: [f64; 3],
    ) -> Result<Self> {
        if D < 3 {
            return Err(Error::invalid("origin", format!("a placement needs 3 dimensions, got {D}")));
        }
        let OrthonormalAxes { x, y, z } = OrthonormalAxes::build(axis, ref_direction)?;
        let origin = Point::<D>::from_fn(|k, _| origin.get(k).copied().unwrap_or(0.0));
        Ok(PlacedSurface { surface, origin, frame: [x, y, z] })
    }

    /// R p: the frame applied to the first three coordinates.
    fn rotate(&self, p: &Point<D>) -> Point<D> {
        let [x, y, z] = &self.frame;
        let mut out = *p;
        for k in 0..3 {
            out[k] = p[0] * x[k] + p[1] * y[k] + p[2] * z[k];
        }
        out
    }
}

impl<const D: usize> Surface<D> for PlacedSurface<D> {
    crate::wrapped_surface_domains!(surface);
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        self.surface.eval_partials(u, v, du, dv, out);
        let n = (du + 1) * (dv + 1);
        for (i, o) in out[..n].iter_mut().enumerate() {
            *o = self.rotate(o);
            if i == 0 {
                *o += self.origin;
            }
        }
    }
    fn breakpoints_u(&self) -> Vec<f64> {
        self.surface.breakpoints_u()
    }
    fn breakpoints_v(&self) -> Vec<f64> {
        self.surface.breakpoints_v()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::model::Sphere;

    #[test]
    fn a_placed_sphere_is_the_sphere_in_its_frame_with_rotated_derivatives() {
        let s = PlacedSurface::<3>::new(
            Box::new(Sphere::new(2.0).unwrap()),
            [1.0, -2.0, 0.5],
            [0.0, 0.6, 0.8],
            [1.0, 0.3, 0.4],
        )
        .unwrap();
        // x is the reference direction without its part along z: (1, 0, 0) here.
        let (x, y, z) =
            (Point::<3>::new(1.0, 0.0, 0.0), Point::<3>::new(0.0, 0.8, -0.6), Point::<3>::new(0.0, 0.6, 0.8));
        let o = Point::<3>::new(1.0, -2.0, 0.5);
        for &(u, v) in &[(0.3f64, -0.4f64), (2.0, 1.1), (5.0, 0.0)] {
            let expect = o + (x * u.cos() + y * u.sin()) * (2.0 * v.cos()) + z * (2.0 * v.sin());
            assert!((s.point(u, v) - expect).norm() < 1e-14);
            let mut d = [Point::<3>::zeros(); 4];
            s.eval_partials(u, v, 1, 1, &mut d);
            let su = (-x * u.sin() + y * u.cos()) * (2.0 * v.cos());
            let sv = -(x * u.cos() + y * u.sin()) * (2.0 * v.sin()) + z * (2.0 * v.cos());
            assert!((d[2] - su).norm() < 1e-14 && (d[1] - sv).norm() < 1e-14);
        }
    }

    #[test]
    fn a_reference_direction_along_the_axis_is_refused() {
        let sphere = || Box::new(Sphere::new(1.0).unwrap()) as Box<dyn Surface<3>>;
        let e = PlacedSurface::<3>::new(sphere(), [0.0; 3], [0.0, 0.0, 2.0], [0.0, 0.0, -1.0]).err().unwrap();
        assert!(e.to_string().contains("ref_direction"), "{e}");
        let e = PlacedSurface::<3>::new(sphere(), [0.0; 3], [0.0; 3], [1.0, 0.0, 0.0]).err().unwrap();
        assert!(e.to_string().contains("axis"), "{e}");
    }
}
