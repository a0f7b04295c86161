//! The heart curve (16 sin³t, 13 cos t − 5 cos 2t − 2 cos 3t − cos 4t, 0), t ∈ [0, 2π], closed.

use super::trig::{Term, TrigCurve, TrigSeries, positive, trig_model_curve};

/// The classic heart curve, scaled by `scale`. With sin³t = (3 sin t − sin 3t)/4 both
/// coordinates are trigonometric polynomials, so derivatives of every order are exact.
#[derive(Debug, Clone, PartialEq)]
pub struct Heart {
    curve: TrigCurve,
}

impl Heart {
    /// The heart scaled by `scale` > 0 (1 gives the contract's coordinates).
    pub fn new(scale: f64) -> crate::Result<Self> {
        let s = positive("scale", scale)?;
        let x = TrigSeries::of(&[Term::sin(12.0 * s, 1.0), Term::sin(-4.0 * s, 3.0)]);
        let y = TrigSeries::of(&[
            Term::cos(13.0 * s, 1.0),
            Term::cos(-5.0 * s, 2.0),
            Term::cos(-2.0 * s, 3.0),
            Term::cos(-s, 4.0),
        ]);
        let curve = TrigCurve::one_turn([x, y, TrigSeries::default()], true);
        Ok(Heart { curve })
    }
}

trig_model_curve!(Heart);
