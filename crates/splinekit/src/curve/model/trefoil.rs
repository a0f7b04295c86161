//! The trefoil knot (sin t + 2 sin 2t, cos t − 2 cos 2t, −sin 3t), t ∈ [0, 2π], closed.

use super::trig::{Term, TrigCurve, TrigSeries, positive, trig_model_curve};

/// Trefoil knot scaled by `scale`.
#[derive(Debug, Clone, PartialEq)]
pub struct Trefoil {
    curve: TrigCurve,
}

impl Trefoil {
    /// The knot scaled by `scale` > 0.
    pub fn new(scale: f64) -> crate::Result<Self> {
        let s = positive("scale", scale)?;
        let curve = TrigCurve::one_turn(
            [
                TrigSeries::of(&[Term::sin(s, 1.0), Term::sin(2.0 * s, 2.0)]),
                TrigSeries::of(&[Term::cos(s, 1.0), Term::cos(-2.0 * s, 2.0)]),
                TrigSeries::of(&[Term::sin(-s, 3.0)]),
            ],
            true,
        );
        Ok(Trefoil { curve })
    }
}

trig_model_curve!(Trefoil);
