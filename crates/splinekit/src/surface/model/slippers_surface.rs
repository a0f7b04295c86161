//! The slippers surface (Paul Bourke's geometry pages, a surface by Roger Bagula): with
//! φ = 2π/3,
//! ((2 + cos u) cos³v sin v, (2 + cos(u + φ)) cos²(v + φ) sin²(v + φ),
//! −(2 + cos(u − φ)) cos²(φ − v) sin³(φ − v)), u, v ∈ [0, 2π], closed both ways.
//!
//! Separable, each v-factor a product of shifted cosines and sines (Leibniz rule).

use super::separable::{Factor as F, SeparableSurface, positive, separable_model_surface, term};
use crate::curve::Interval;
use crate::curve::model::Term;
use crate::error::Result;
use std::f64::consts::TAU;

/// The slippers surface scaled by `scale` (documents: `slippers_surface`).
#[derive(Debug, Clone, PartialEq)]
pub struct SlippersSurface {
    surface: SeparableSurface,
}
separable_model_surface!(SlippersSurface);

/// a cos(ω t + φ) (or a sin) as a factor.
fn wave(sine: bool, frequency: f64, phase: f64) -> F {
    F::trig(0.0, &[Term { amplitude: 1.0, frequency, phase, sine }])
}

/// The product of `n` copies of `f`.
fn power(f: &F, n: usize) -> F {
    (1..n).fold(f.clone(), |p, _| p.times(f.clone()))
}

impl SlippersSurface {
    /// The surface scaled by `scale` > 0.
    pub fn new(scale: f64) -> Result<Self> {
        let s = positive("scale", scale)?;
        let phi = TAU / 3.0;
        let ring = |phase: f64| F::trig(2.0, &[Term { amplitude: 1.0, frequency: 1.0, phase, sine: false }]);
        let x_v = power(&wave(false, 1.0, 0.0), 3).times(wave(true, 1.0, 0.0));
        let y_v = power(&wave(false, 1.0, phi), 2).times(power(&wave(true, 1.0, phi), 2));
        let z_v = power(&wave(false, -1.0, phi), 2).times(power(&wave(true, -1.0, phi), 3));
        Ok(SlippersSurface {
            surface: SeparableSurface {
                coordinates: [
                    vec![term(s, ring(0.0), x_v)],
                    vec![term(s, ring(phi), y_v)],
                    vec![term(-s, ring(-phi), z_v)],
                ],
                domain_u: Interval::new(0.0, TAU),
                domain_v: Interval::new(0.0, TAU),
                closed_u: true,
                closed_v: true,
            },
        })
    }
}
