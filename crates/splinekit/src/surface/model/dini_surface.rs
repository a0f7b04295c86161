//! Dini's surface, a twisted pseudosphere of constant Gaussian curvature
//! K = −1/(a² + b²): (a cos u sin v, a sin u sin v, a (cos v + ln tan(v/2)) + b u),
//! u ∈ [0, 4π], v ∈ [0.1, 2], open (MathWorld, "Dini's Surface"; Wikipedia, "Dini's
//! surface", u ∈ [0, 4π], 0 < v ≤ 2, which this starts at v = 0.1, away from the axis
//! the surface winds towards as v → 0).
//!
//! Separable, with ln tan(v/2) differentiated to any order in Taylor mode
//! ([`super::separable::Factor::LogTanHalf`]).

use super::separable::{Factor as F, SeparableSurface, positive, separable_model_surface, term};
use crate::curve::Interval;
use crate::error::Result;
use std::f64::consts::PI;

/// Dini's surface of radius a and twist b (documents: `dini_surface`, a = 1, b = 0.2).
#[derive(Debug, Clone, PartialEq)]
pub struct DiniSurface {
    surface: SeparableSurface,
}
separable_model_surface!(DiniSurface);

impl DiniSurface {
    /// Radius a > 0 and twist b (finite; 0 gives the pseudosphere's tractrix turned about
    /// the axis, covered twice).
    pub fn new(a: f64, b: f64) -> Result<Self> {
        let a = positive("a", a)?;
        if !b.is_finite() {
            return Err(crate::Error::invalid("b", format!("must be finite, got {b}")));
        }
        let one = || F::constant(1.0);
        Ok(DiniSurface {
            surface: SeparableSurface {
                coordinates: [
                    vec![term(a, F::cos(1.0, 1.0), F::sin(1.0, 1.0))],
                    vec![term(a, F::sin(1.0, 1.0), F::sin(1.0, 1.0))],
                    vec![
                        term(a, one(), F::cos(1.0, 1.0)),
                        term(a, one(), F::LogTanHalf),
                        term(b, F::Polynomial(vec![0.0, 1.0]), one()),
                    ],
                ],
                domain_u: Interval::new(0.0, 4.0 * PI),
                domain_v: Interval::new(0.1, 2.0),
                closed_u: false,
                closed_v: false,
            },
        })
    }
}
