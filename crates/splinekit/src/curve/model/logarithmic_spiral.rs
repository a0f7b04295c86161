//! The logarithmic spiral r = a e^{bt}: (a e^{bt} cos t, a e^{bt} sin t, 0),
//! t ∈ [0, 2π·turns], open (MathWorld, "Logarithmic Spiral"). Its tangent makes the
//! constant angle ψ with the radius, cot ψ = b; its length from t₀ to t₁ is
//! a √(1 + b²) (e^{bt₁} − e^{bt₀}) / b, its curvature e^{−bt} / (a √(1 + b²)).
//!
//! Derivatives of every order in closed form: c(t) = a Re, Im e^{(b + i)t} and
//! b + i = ρ e^{iφ} with ρ = √(1 + b²), φ = atan2(1, b), so
//! c⁽ᵏ⁾(t) = a ρᵏ e^{bt} (cos(t + kφ), sin(t + kφ), 0).

use super::trig::{finite, positive};
use crate::Point;
use crate::basis::Side;
use crate::curve::{Curve, Interval};
use std::f64::consts::TAU;

/// The logarithmic spiral (documents: `logarithmic_spiral`, a = 1, b = 0.1, 4 turns).
#[derive(Debug, Clone, PartialEq)]
pub struct LogarithmicSpiral {
    a: f64,
    b: f64,
    domain: Interval,
}

impl LogarithmicSpiral {
    /// Radius a > 0 at t = 0, growth b (finite; negative winds inwards, 0 is the circle)
    /// and turns > 0.
    pub fn new(a: f64, b: f64, turns: f64) -> crate::Result<Self> {
        let (a, b, turns) = (positive("a", a)?, finite("b", b)?, positive("turns", turns)?);
        let end = TAU * turns;
        if !(b * end).exp().is_finite() || !(a * (b * end).exp()).is_finite() {
            return Err(crate::Error::invalid("b", format!("e^(b·2π·turns) overflows: b = {b}, turns = {turns}")));
        }
        Ok(LogarithmicSpiral { a, b, domain: Interval::new(0.0, end) })
    }
}

impl Curve<3> for LogarithmicSpiral {
    fn domain(&self) -> Interval {
        self.domain
    }
    fn is_closed(&self) -> bool {
        false
    }
    fn eval_side(&self, t: f64, _side: Side, out: &mut [Point<3>]) {
        let t = self.domain.clamp(t);
        let (rho, phi) = ((1.0 + self.b * self.b).sqrt(), 1f64.atan2(self.b));
        let mut scale = self.a * (self.b * t).exp();
        for (k, o) in out.iter_mut().enumerate() {
            let (s, c) = (t + k as f64 * phi).sin_cos();
            *o = Point::<3>::new(scale * c, scale * s, 0.0);
            scale *= rho;
        }
    }
}
