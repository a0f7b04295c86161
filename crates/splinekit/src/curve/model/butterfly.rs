//! Fay's butterfly curve r(t)(sin t, cos t, 0), r = e^{cos t} − 2 cos 4t − sin⁵(t/12),
//! t ∈ [0, 24π], closed.

use smallvec::{SmallVec, smallvec};

use super::trig::{Term, TrigSeries, positive};
use crate::Point;
use crate::basis::{Side, binomial};
use crate::curve::{Curve, Interval};
use crate::taylor;

/// The butterfly curve scaled by `scale`. Derivatives of any order: the radius is
/// e^{cos t} (Taylor-mode differentiation) plus a trigonometric polynomial
/// (sin⁵x = (10 sin x − 5 sin 3x + sin 5x)/16), and the coordinates follow by Leibniz.
#[derive(Debug, Clone, PartialEq)]
pub struct Butterfly {
    scale: f64,
    trig_part: TrigSeries,
}

impl Butterfly {
    /// The butterfly scaled by `scale` > 0.
    pub fn new(scale: f64) -> crate::Result<Self> {
        let scale = positive("scale", scale)?;
        let w = 1.0 / 12.0;
        let trig_part = TrigSeries::of(&[
            Term::cos(-2.0, 4.0),
            Term::sin(-10.0 / 16.0, w),
            Term::sin(5.0 / 16.0, 3.0 * w),
            Term::sin(-1.0 / 16.0, 5.0 * w),
        ]);
        Ok(Butterfly { scale, trig_part })
    }

    /// r^{(k)}(t) for k = 0 … out.len() − 1.
    fn radius_derivatives(&self, t: f64, out: &mut [f64]) {
        let n = out.len();
        // Taylor coefficients of cos t about t, then of exp(cos t).
        let mut g: SmallVec<[f64; 8]> = smallvec![0.0; n];
        let (s, c) = t.sin_cos();
        let mut fact = 1.0;
        for (k, gk) in g.iter_mut().enumerate() {
            if k > 0 {
                fact *= k as f64;
            }
            *gk = [c, -s, -c, s][k % 4] / fact;
        }
        let mut e: SmallVec<[f64; 8]> = smallvec![0.0; n];
        taylor::exp(&g, &mut e);
        let mut fact = 1.0;
        for (k, o) in out.iter_mut().enumerate() {
            if k > 0 {
                fact *= k as f64;
            }
            *o = e[k] * fact + self.trig_part.derivative(t, k);
        }
    }
}

impl Curve<3> for Butterfly {
    fn domain(&self) -> Interval {
        Interval::new(0.0, 24.0 * std::f64::consts::PI)
    }
    fn is_closed(&self) -> bool {
        true
    }
    fn eval_side(&self, t: f64, _side: Side, out: &mut [Point<3>]) {
        let t = self.domain().wrap_periodic(t, Side::Right);
        let n = out.len();
        let mut r: SmallVec<[f64; 8]> = smallvec![0.0; n];
        self.radius_derivatives(t, &mut r);
        let (s, c) = t.sin_cos();
        let sin_d = |k: usize| [s, c, -s, -c][k % 4];
        let cos_d = |k: usize| [c, -s, -c, s][k % 4];
        for (k, o) in out.iter_mut().enumerate() {
            let (mut x, mut y) = (0.0, 0.0);
            for j in 0..=k {
                let b = binomial(k, j) * r[k - j];
                x += b * sin_d(j);
                y += b * cos_d(j);
            }
            *o = Point::<3>::new(self.scale * x, self.scale * y, 0.0);
        }
    }
}
