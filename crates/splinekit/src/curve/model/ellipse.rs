//! The ellipse (a cos t, b sin t, 0), t ∈ [0, 2π], closed.

use super::trig::{Term, TrigCurve, TrigSeries, positive, trig_model_curve};

/// Axis-aligned ellipse with semi-axes a (along x) and b (along y).
#[derive(Debug, Clone, PartialEq)]
pub struct Ellipse {
    curve: TrigCurve,
}

impl Ellipse {
    /// Semi-axes a, b > 0.
    pub fn new(a: f64, b: f64) -> crate::Result<Self> {
        let (a, b) = (positive("a", a)?, positive("b", b)?);
        let curve = TrigCurve::one_turn(
            [TrigSeries::of(&[Term::cos(a, 1.0)]), TrigSeries::of(&[Term::sin(b, 1.0)]), TrigSeries::default()],
            true,
        );
        Ok(Ellipse { curve })
    }
}

trig_model_curve!(Ellipse);
