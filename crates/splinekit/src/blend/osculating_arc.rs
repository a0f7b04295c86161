//! The osculating circle arc of a curve at a parameter, as a local curve in the global
//! parameter: with s₀ = |c′(t₀)|, unit tangent x = c′/s₀, curvature κ and unit normal y,
//!
//! a(t) = c(t₀) + x sin θ/κ + y · 2 sin²(θ/2)/κ,  θ = κ s₀ (t − t₀),
//!
//! which matches c's position, velocity and curvature at t₀ (and is the tangent line
//! c(t₀) + s₀(t − t₀)x where κ = 0). Derivatives: a^{(m)} = (κs₀)^m/κ (x sin^{(m)}θ − y cos^{(m)}θ).

use crate::Point;
use crate::basis::Side;
use crate::curve::{Curve, Interval};
use crate::error::{Error, Result};

/// A circle arc (or line) through a point with given velocity and curvature.
#[derive(Debug, Clone)]
pub struct OsculatingArc<const D: usize> {
    centre_parameter: f64,
    point: Point<D>,
    tangent: Point<D>,
    normal: Point<D>,
    speed: f64,
    curvature: f64,
}

impl<const D: usize> OsculatingArc<D> {
    /// The osculating arc of `curve` at `t0`; an error where the curve is not regular.
    pub fn of<C: Curve<D> + ?Sized>(curve: &C, t0: f64) -> Result<Self> {
        let mut d = [Point::<D>::zeros(); 3];
        curve.eval(t0, &mut d);
        let speed = d[1].norm();
        if !(speed > 0.0 && speed.is_finite()) {
            return Err(Error::numerical("osculating arc", format!("the model has no tangent at t = {t0}")));
        }
        let tangent = d[1] / speed;
        let normal_part = d[2] - tangent * tangent.dot(&d[2]);
        let n = normal_part.norm();
        let curvature = n / (speed * speed);
        let normal = if curvature > 0.0 { normal_part / n } else { Point::<D>::zeros() };
        Ok(OsculatingArc { centre_parameter: t0, point: d[0], tangent, normal, speed, curvature })
    }
    /// The curvature κ of the arc.
    pub fn curvature(&self) -> f64 {
        self.curvature
    }
}

impl<const D: usize> Curve<D> for OsculatingArc<D> {
    fn domain(&self) -> Interval {
        Interval::new(f64::NEG_INFINITY, f64::INFINITY)
    }
    fn eval_side(&self, t: f64, _side: Side, out: &mut [Point<D>]) {
        let tau = t - self.centre_parameter;
        let (k, s) = (self.curvature, self.speed);
        if k == 0.0 {
            out[0] = self.point + self.tangent * (s * tau);
            if out.len() > 1 {
                out[1] = self.tangent * s;
            }
            for o in out.iter_mut().skip(2) {
                *o = Point::<D>::zeros();
            }
            return;
        }
        let theta = k * s * tau;
        let (sin, cos) = theta.sin_cos();
        let half = (0.5 * theta).sin();
        out[0] = self.point + self.tangent * (sin / k) + self.normal * (2.0 * half * half / k);
        // d^m/dθ^m of (sin θ, −cos θ) cycles through (cos, sin), (−sin, cos), (−cos, −sin), (sin, −cos).
        let mut factor = 1.0 / k;
        for (m, o) in out.iter_mut().enumerate().skip(1) {
            factor *= k * s;
            let (a, b) = match m % 4 {
                1 => (cos, sin),
                2 => (-sin, cos),
                3 => (-cos, -sin),
                _ => (sin, -cos),
            };
            *o = (self.tangent * a + self.normal * b) * factor;
        }
    }
}
