//! The circle (r cos t, r sin t, 0), t ∈ [0, 2π], closed.

use super::trig::{Term, TrigCurve, TrigSeries, positive, trig_model_curve};

/// Circle of radius r in the xy-plane about the origin; c^{(k)} has length r.
#[derive(Debug, Clone, PartialEq)]
pub struct Circle {
    radius: f64,
    curve: TrigCurve,
}

impl Circle {
    /// The circle of the given radius (> 0).
    pub fn new(radius: f64) -> crate::Result<Self> {
        let r = positive("radius", radius)?;
        let curve = TrigCurve::one_turn(
            [TrigSeries::of(&[Term::cos(r, 1.0)]), TrigSeries::of(&[Term::sin(r, 1.0)]), TrigSeries::default()],
            true,
        );
        Ok(Circle { radius, curve })
    }
    /// The radius.
    pub fn radius(&self) -> f64 {
        self.radius
    }
}

trig_model_curve!(Circle);
