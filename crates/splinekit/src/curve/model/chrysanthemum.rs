//! The chrysanthemum curve, a relative of Temple Fay's butterfly: in polar form
//! r = 5 (1 + sin(11t/5)) − 4 sin⁴(17t/3) sin⁸(2 cos 3t − 28t), the point
//! s·r(t)(cos t, sin t, 0), t ∈ [0, 21π], open (MathWorld, "Chrysanthemum Curve";
//! T. H. Fay, "A Study of Butterfly Curves", 1997).
//!
//! Derivatives of every order: sin⁴x = (3 − 4 cos 2x + cos 4x)/8 is a trigonometric
//! polynomial; sin⁸ g with g = 2 cos 3t − 28t is differentiated in Taylor mode (the jet of
//! g, then sin g by [`crate::taylor::sin_cos`] and its eighth power by Cauchy products);
//! the coordinates follow by Leibniz.

use smallvec::{SmallVec, smallvec};

use super::trig::{Term, TrigSeries, positive};
use crate::Point;
use crate::basis::{Side, binomial};
use crate::curve::{Curve, Interval};
use crate::taylor;
use std::f64::consts::PI;

type Jet = SmallVec<[f64; 8]>;

/// The chrysanthemum curve scaled by `scale` (documents: `chrysanthemum`).
#[derive(Debug, Clone, PartialEq)]
pub struct Chrysanthemum {
    scale: f64,
    /// 5 (1 + sin(11t/5)).
    petals: TrigSeries,
    /// 4 sin⁴(17t/3).
    fourth: TrigSeries,
    /// 2 cos 3t − 28t, the angle of the eighth power.
    angle: TrigSeries,
}

impl Chrysanthemum {
    /// The curve scaled by `scale` > 0.
    pub fn new(scale: f64) -> crate::Result<Self> {
        let scale = positive("scale", scale)?;
        let w = 17.0 / 3.0;
        Ok(Chrysanthemum {
            scale,
            petals: TrigSeries { constant: 5.0, linear: 0.0, terms: smallvec![Term::sin(5.0, 11.0 / 5.0)] },
            fourth: TrigSeries {
                constant: 1.5,
                linear: 0.0,
                terms: smallvec![Term::cos(-2.0, 2.0 * w), Term::cos(0.5, 4.0 * w)],
            },
            angle: TrigSeries { constant: 0.0, linear: -28.0, terms: smallvec![Term::cos(2.0, 3.0)] },
        })
    }

    /// r^{(k)}(t) for k = 0 … out.len() − 1.
    fn radius_derivatives(&self, t: f64, out: &mut [f64]) {
        let n = out.len();
        let factorials: Jet = (0..n)
            .scan(1.0, |f, k| {
                if k > 0 {
                    *f *= k as f64;
                }
                Some(*f)
            })
            .collect();
        let jet_of = |series: &TrigSeries| -> Jet {
            let mut d: Jet = smallvec![0.0; n];
            series.derivatives(t, &mut d);
            d.iter().zip(&factorials).map(|(d, f)| d / f).collect()
        };
        let (g, fourth) = (jet_of(&self.angle), jet_of(&self.fourth));
        let (mut s, mut c): (Jet, Jet) = (smallvec![0.0; n], smallvec![0.0; n]);
        taylor::sin_cos(&g, &mut s, &mut c);
        // sin⁸ = ((sin²)²)².
        let square = |x: &Jet| -> Jet {
            let mut y: Jet = smallvec![0.0; n];
            taylor::mul(x, x, &mut y);
            y
        };
        let eighth = square(&square(&square(&s)));
        let mut product: Jet = smallvec![0.0; n];
        taylor::mul(&fourth, &eighth, &mut product);
        let mut petals: Jet = smallvec![0.0; n];
        self.petals.derivatives(t, &mut petals);
        for (k, o) in out.iter_mut().enumerate() {
            *o = petals[k] - product[k] * factorials[k];
        }
    }
}

impl Curve<3> for Chrysanthemum {
    fn domain(&self) -> Interval {
        Interval::new(0.0, 21.0 * PI)
    }
    fn is_closed(&self) -> bool {
        false
    }
    fn eval_side(&self, t: f64, _side: Side, out: &mut [Point<3>]) {
        let t = self.domain().clamp(t);
        let n = out.len();
        let mut r: Jet = smallvec![0.0; n];
        self.radius_derivatives(t, &mut r);
        let (s, c) = t.sin_cos();
        let cos_d = |k: usize| [c, -s, -c, s][k % 4];
        let sin_d = |k: usize| [s, c, -s, -c][k % 4];
        for (k, o) in out.iter_mut().enumerate() {
            let (mut x, mut y) = (0.0, 0.0);
            for j in 0..=k {
                let b = binomial(k, j) * r[k - j];
                x += b * cos_d(j);
                y += b * sin_d(j);
            }
            *o = Point::<3>::new(self.scale * x, self.scale * y, 0.0);
        }
    }
}
