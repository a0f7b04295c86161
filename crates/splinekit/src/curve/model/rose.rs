//! The rose curve r cos(nt)(cos t, sin t) with z = r sin(nt) (3-D) or z = 0 (planar).

use super::trig::{Term, TrigCurve, TrigSeries, positive, trig_model_curve};

/// Rose (rhodonea) curve, t ∈ [0, 2π]: (r cos(nt) cos t, r cos(nt) sin t, r sin(nt)).
///
/// With cos(nt) cos t = ½[cos((n+1)t) + cos((n−1)t)] and
/// cos(nt) sin t = ½[sin((n+1)t) − sin((n−1)t)] it is a trigonometric polynomial. It is
/// closed over [0, 2π] when n is an integer.
#[derive(Debug, Clone, PartialEq)]
pub struct Rose {
    curve: TrigCurve,
}

impl Rose {
    /// Radius r > 0, petal number n > 0, `planar` drops the z-coordinate.
    pub fn new(radius: f64, n: f64, planar: bool) -> crate::Result<Self> {
        let r = positive("radius", radius)?;
        let n = positive("n", n)?;
        let h = r / 2.0;
        let x = TrigSeries::of(&[Term::cos(h, n + 1.0), Term::cos(h, n - 1.0)]);
        let y = TrigSeries::of(&[Term::sin(h, n + 1.0), Term::sin(-h, n - 1.0)]);
        let z = if planar { TrigSeries::default() } else { TrigSeries::of(&[Term::sin(r, n)]) };
        let closed = n.fract() == 0.0;
        let curve = TrigCurve::one_turn([x, y, z], closed);
        Ok(Rose { curve })
    }
}

trig_model_curve!(Rose);
