//! The eight surface (MathWorld, "Eight Surface"): the figure eight (sin 2v, sin v) turned
//! about the z-axis, r·(cos u sin 2v, sin u sin 2v, sin v), u ∈ [0, 2π] closed,
//! v ∈ [−π/2, π/2]; on x² + y² = 4z²(1 − z²) at r = 1.

use super::separable::{Factor as F, SeparableSurface, positive, separable_model_surface, term};
use crate::curve::Interval;
use crate::error::Result;
use std::f64::consts::{FRAC_PI_2, TAU};

/// The eight surface scaled by `scale` (documents: `eight_surface`).
#[derive(Debug, Clone, PartialEq)]
pub struct EightSurface {
    surface: SeparableSurface,
}
separable_model_surface!(EightSurface);

impl EightSurface {
    /// The surface scaled by `scale` > 0.
    pub fn new(scale: f64) -> Result<Self> {
        let r = positive("scale", scale)?;
        Ok(EightSurface {
            surface: SeparableSurface {
                coordinates: [
                    vec![term(r, F::cos(1.0, 1.0), F::sin(1.0, 2.0))],
                    vec![term(r, F::sin(1.0, 1.0), F::sin(1.0, 2.0))],
                    vec![term(r, F::constant(1.0), F::sin(1.0, 1.0))],
                ],
                domain_u: Interval::new(0.0, TAU),
                domain_v: Interval::new(-FRAC_PI_2, FRAC_PI_2),
                closed_u: true,
                closed_v: false,
            },
        })
    }
}
