//! The sine surface (MathWorld, "Sine Surface"): r·(sin u, sin v, sin(u + v)),
//! u, v ∈ [0, 2π], closed both ways; sin(u + v) = sin u cos v + cos u sin v makes it
//! separable.

use super::separable::{Factor as F, SeparableSurface, positive, separable_model_surface, term};
use crate::curve::Interval;
use crate::error::Result;
use std::f64::consts::TAU;

/// The sine surface scaled by `scale` (documents: `sine_surface`).
#[derive(Debug, Clone, PartialEq)]
pub struct SineSurface {
    surface: SeparableSurface,
}
separable_model_surface!(SineSurface);

impl SineSurface {
    /// The surface scaled by `scale` > 0.
    pub fn new(scale: f64) -> Result<Self> {
        let r = positive("scale", scale)?;
        let one = || F::constant(1.0);
        Ok(SineSurface {
            surface: SeparableSurface {
                coordinates: [
                    vec![term(r, F::sin(1.0, 1.0), one())],
                    vec![term(r, one(), F::sin(1.0, 1.0))],
                    vec![term(r, F::sin(1.0, 1.0), F::cos(1.0, 1.0)), term(r, F::cos(1.0, 1.0), F::sin(1.0, 1.0))],
                ],
                domain_u: Interval::new(0.0, TAU),
                domain_v: Interval::new(0.0, TAU),
                closed_u: true,
                closed_v: true,
            },
        })
    }
}
