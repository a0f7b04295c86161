//! Kuen's surface, of constant Gaussian curvature K = −1/r²: with
//! d = 1 + u² sin²v, r·(2 (cos u + u sin u) sin v / d, 2 (sin u − u cos u) sin v / d,
//! ln tan(v/2) + 2 cos v / d), u ∈ [−4.5, 4.5], v ∈ [0.1, π − 0.1], open (MathWorld,
//! "Kuen Surface", u ∈ [−4.5, 4.5], v ∈ (0, π); the ends of v stop short of the spikes that
//! run off to z → ∓∞).
//!
//! Rational-separable ([`super::rational`], d ≥ 1) plus ln tan(v/2)
//! ([`super::separable::Factor::LogTanHalf`]).

use super::rational::{RationalCoordinate, RationalSurface};
use super::separable::{Factor as F, positive, separable_model_surface, term};
use crate::curve::Interval;
use crate::curve::model::Term;
use crate::error::Result;
use std::f64::consts::PI;

/// Kuen's surface scaled by `scale` (documents: `kuen_surface`).
#[derive(Debug, Clone, PartialEq)]
pub struct KuenSurface {
    surface: RationalSurface,
}
separable_model_surface!(KuenSurface);

impl KuenSurface {
    /// The surface scaled by `scale` > 0 (1: K = −1).
    pub fn new(scale: f64) -> Result<Self> {
        let r = positive("scale", scale)?;
        let one = || F::constant(1.0);
        let u = || F::Polynomial(vec![0.0, 1.0]);
        // d = 1 + u² sin²v, sin²v = (1 − cos 2v)/2.
        let d = || {
            vec![
                term(1.0, one(), one()),
                term(1.0, F::Polynomial(vec![0.0, 0.0, 1.0]), F::trig(0.5, &[Term::cos(-0.5, 2.0)])),
            ]
        };
        let sin_v = || F::sin(1.0, 1.0);
        Ok(KuenSurface {
            surface: RationalSurface {
                coordinates: [
                    RationalCoordinate {
                        plus: vec![],
                        numerator: vec![
                            term(2.0 * r, F::cos(1.0, 1.0), sin_v()),
                            term(2.0 * r, u().times(F::sin(1.0, 1.0)), sin_v()),
                        ],
                        denominator: d(),
                    },
                    RationalCoordinate {
                        plus: vec![],
                        numerator: vec![
                            term(2.0 * r, F::sin(1.0, 1.0), sin_v()),
                            term(-2.0 * r, u().times(F::cos(1.0, 1.0)), sin_v()),
                        ],
                        denominator: d(),
                    },
                    RationalCoordinate {
                        plus: vec![term(r, one(), F::LogTanHalf)],
                        numerator: vec![term(2.0 * r, one(), F::cos(1.0, 1.0))],
                        denominator: d(),
                    },
                ],
                domain_u: Interval::new(-4.5, 4.5),
                domain_v: Interval::new(0.1, PI - 0.1),
                closed_u: false,
                closed_v: false,
            },
        })
    }
}
