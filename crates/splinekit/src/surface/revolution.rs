//! Exact NURBS surfaces of revolution about the z-axis (NURBS Book A8.1), and the exact
//! sphere, cylinder and torus built from them.

use crate::Point;
use crate::curve::{CircleFrame, NurbsCurve};
use crate::error::{Error, Result};
use crate::surface::NurbsSurface;
use std::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2, FRAC_PI_4};

impl NurbsSurface<3> {
    /// The full revolution of `profile` about the z-axis: u runs once around (degree 2,
    /// 9 control points per circle, knots {0,0,0,¼,¼,½,½,¾,¾,1,1,1}), v along the profile.
    /// Every control point P_j of the profile turns on the circle of radius
    /// √(x_j² + y_j²) at height z_j; corner points lie at radius/cos(π/4) with weight
    /// w_j·√2/2.
    pub fn revolve_z(profile: &NurbsCurve<3>) -> Result<Self> {
        if profile.is_periodic() {
            return Err(Error::invalid("profile", "revolve a clamped or open profile (periodic ones: clamp first)"));
        }
        let pts = profile.control_points();
        let ws = profile.weights();
        let mut net = Vec::with_capacity(9);
        let mut weights = Vec::with_capacity(9);
        for k in 0..9 {
            let corner = k % 2 == 1;
            let mut row = Vec::with_capacity(pts.len());
            let mut wrow = Vec::with_capacity(pts.len());
            for (p, w) in pts.iter().zip(ws) {
                let rho = p[0].hypot(p[1]);
                let phi = p[1].atan2(p[0]) + k as f64 * FRAC_PI_4;
                let r = if corner { rho / FRAC_1_SQRT_2 } else { rho };
                row.push(Point::<3>::new(r * phi.cos(), r * phi.sin(), p[2]));
                wrow.push(if corner { w * FRAC_1_SQRT_2 } else { *w });
            }
            net.push(row);
            weights.push(wrow);
        }
        let knots_u = vec![0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0];
        NurbsSurface::new((2, profile.degree()), knots_u, profile.knots().to_vec(), net, weights, (false, false))
    }

    /// The exact sphere of `radius` about the origin (revolved half circle; v from the
    /// south to the north pole).
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::surface::{NurbsSurface, Surface};
    /// let s = NurbsSurface::sphere(2.0).unwrap();
    /// for (u, v) in [(0.1, 0.2), (0.5, 0.5), (0.9, 0.7)] {
    ///     assert!((s.point(u, v).norm() - 2.0).abs() < 1e-14);
    /// }
    /// ```
    pub fn sphere(radius: f64) -> Result<Self> {
        let arc = NurbsCurve::arc(
            &CircleFrame { center: Point::<3>::zeros(), x_axis: Point::<3>::x(), y_axis: Point::<3>::z(), radius },
            -FRAC_PI_2,
            FRAC_PI_2,
        )?;
        Self::revolve_z(&arc)
    }

    /// The exact cylinder x² + y² = r², 0 ≤ z ≤ height (degree (2, 1)).
    pub fn cylinder(radius: f64, height: f64) -> Result<Self> {
        if !(height > 0.0 && height.is_finite()) {
            return Err(Error::invalid("height", format!("must be positive and finite, got {height}")));
        }
        let line = NurbsCurve::new(
            1,
            vec![0.0, 0.0, 1.0, 1.0],
            vec![Point::<3>::new(radius, 0.0, 0.0), Point::<3>::new(radius, 0.0, height)],
            vec![1.0, 1.0],
        )?;
        if !(radius > 0.0 && radius.is_finite()) {
            return Err(Error::invalid("radius", format!("must be positive and finite, got {radius}")));
        }
        Self::revolve_z(&line)
    }

    /// The exact torus with major radius R (centre circle in z = 0) and minor radius r < R.
    pub fn torus(major_radius: f64, minor_radius: f64) -> Result<Self> {
        if !(minor_radius > 0.0 && major_radius > minor_radius && major_radius.is_finite()) {
            return Err(Error::invalid(
                "minor_radius",
                format!("need 0 < minor_radius < major_radius, got {minor_radius} and {major_radius}"),
            ));
        }
        let tube = NurbsCurve::circle(&CircleFrame {
            center: Point::<3>::new(major_radius, 0.0, 0.0),
            x_axis: Point::<3>::x(),
            y_axis: Point::<3>::z(),
            radius: minor_radius,
        })?;
        Self::revolve_z(&tube)
    }
}
