//! Boy's surface, an immersion of the projective plane, in Apéry's parametrisation as
//! MathWorld ("Boy's Surface") and Paul Bourke give it (after Nordstrand): with
//! d = 2 − √2 sin 3u sin 2v,
//! ((√2 cos²v cos 2u + cos u sin 2v)/d, (√2 cos²v sin 2u − sin u sin 2v)/d, 3 cos²v/d),
//! u ∈ [−π/2, π/2], v ∈ [0, π]. Closed in v (period π); in u the ends meet with a flip,
//! S(u + π, v) = S(u, π − v). (2/3)·S lies on Apéry's sextic (F. Apéry, *Models of the Real
//! Projective Plane*, 1987).
//!
//! Rational-separable ([`super::rational`]): d ≥ 2 − √2 > 0.

use super::rational::{RationalCoordinate, RationalSurface};
use super::separable::{Factor as F, positive, separable_model_surface, term};
use crate::curve::Interval;
use crate::curve::model::Term;
use crate::error::Result;
use std::f64::consts::{FRAC_PI_2, PI, SQRT_2};

/// Boy's surface scaled by `scale` (documents: `boy_surface`).
#[derive(Debug, Clone, PartialEq)]
pub struct BoySurface {
    surface: RationalSurface,
}
separable_model_surface!(BoySurface);

impl BoySurface {
    /// The surface scaled by `scale` > 0.
    pub fn new(scale: f64) -> Result<Self> {
        let s = positive("scale", scale)?;
        // cos²v = (1 + cos 2v)/2.
        let cos2 = || F::trig(0.5, &[Term::cos(0.5, 2.0)]);
        let d =
            || vec![term(2.0, F::constant(1.0), F::constant(1.0)), term(-SQRT_2, F::sin(1.0, 3.0), F::sin(1.0, 2.0))];
        let quotient = |numerator| RationalCoordinate { plus: vec![], numerator, denominator: d() };
        Ok(BoySurface {
            surface: RationalSurface {
                coordinates: [
                    quotient(vec![
                        term(s * SQRT_2, F::cos(1.0, 2.0), cos2()),
                        term(s, F::cos(1.0, 1.0), F::sin(1.0, 2.0)),
                    ]),
                    quotient(vec![
                        term(s * SQRT_2, F::sin(1.0, 2.0), cos2()),
                        term(-s, F::sin(1.0, 1.0), F::sin(1.0, 2.0)),
                    ]),
                    quotient(vec![term(3.0 * s, F::constant(1.0), cos2())]),
                ],
                domain_u: Interval::new(-FRAC_PI_2, FRAC_PI_2),
                domain_v: Interval::new(0.0, PI),
                closed_u: false,
                closed_v: true,
            },
        })
    }
}
