//! The cross-cap, a model of the projective plane: the image of the sphere
//! p = (cos u sin v, sin u sin v, cos v) under p ↦ (p₂p₃, 2p₁p₂, p₁² − p₂²),
//! r·(½ sin u sin 2v, sin 2u sin²v, cos 2u sin²v), u ∈ [0, 2π] closed, v ∈ [0, π/2]
//! (the upper hemisphere covers it: antipodes have one image). On the quartic
//! 4x²(x² + y² + z² + z) + y²(y² + z² − 1) = 0 at r = 1 (MathWorld, "Cross-Cap"; Gray,
//! *Modern Differential Geometry of Curves and Surfaces*, the cross-cap).

use super::separable::{Factor as F, SeparableSurface, positive, separable_model_surface, term};
use crate::curve::Interval;
use crate::curve::model::Term;
use crate::error::Result;
use std::f64::consts::{FRAC_PI_2, TAU};

/// The cross-cap scaled by `scale` (documents: `cross_cap`).
#[derive(Debug, Clone, PartialEq)]
pub struct CrossCap {
    surface: SeparableSurface,
}
separable_model_surface!(CrossCap);

impl CrossCap {
    /// The cross-cap scaled by `scale` > 0.
    pub fn new(scale: f64) -> Result<Self> {
        let r = positive("scale", scale)?;
        // sin²v = (1 − cos 2v)/2.
        let sin2 = || F::trig(0.5, &[Term::cos(-0.5, 2.0)]);
        Ok(CrossCap {
            surface: SeparableSurface {
                coordinates: [
                    vec![term(0.5 * r, F::sin(1.0, 1.0), F::sin(1.0, 2.0))],
                    vec![term(r, F::sin(1.0, 2.0), sin2())],
                    vec![term(r, F::cos(1.0, 2.0), sin2())],
                ],
                domain_u: Interval::new(0.0, TAU),
                domain_v: Interval::new(0.0, FRAC_PI_2),
                closed_u: true,
                closed_v: false,
            },
        })
    }
}
