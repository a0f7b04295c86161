//! Steiner's Roman surface (MathWorld, "Roman Surface"): the sphere
//! p = (cos u cos v, sin u cos v, sin v) under p ↦ r²(p₁p₃, p₂p₃, p₁p₂),
//! r²·(cos u cos v sin v, sin u cos v sin v, cos u sin u cos²v), u ∈ [0, 2π],
//! v ∈ [−π/2, π/2], closed both ways (in v with period π: antipodes have one image, so it
//! is covered twice); on Steiner's quartic x²y² + y²z² + z²x² − r²xyz = 0.

use super::separable::{Factor as F, SeparableSurface, positive, separable_model_surface, term};
use crate::curve::Interval;
use crate::curve::model::Term;
use crate::error::Result;
use std::f64::consts::{FRAC_PI_2, TAU};

/// Steiner's Roman surface of radius r (documents: `roman_surface`).
#[derive(Debug, Clone, PartialEq)]
pub struct RomanSurface {
    surface: SeparableSurface,
}
separable_model_surface!(RomanSurface);

impl RomanSurface {
    /// The image of the sphere of radius r > 0 (the quartic's r).
    pub fn new(radius: f64) -> Result<Self> {
        let r = positive("radius", radius)?;
        let r2 = r * r;
        // cos v sin v = ½ sin 2v, cos²v = (1 + cos 2v)/2, cos u sin u = ½ sin 2u.
        Ok(RomanSurface {
            surface: SeparableSurface {
                coordinates: [
                    vec![term(0.5 * r2, F::cos(1.0, 1.0), F::sin(1.0, 2.0))],
                    vec![term(0.5 * r2, F::sin(1.0, 1.0), F::sin(1.0, 2.0))],
                    vec![term(0.5 * r2, F::sin(1.0, 2.0), F::trig(0.5, &[Term::cos(0.5, 2.0)]))],
                ],
                domain_u: Interval::new(0.0, TAU),
                domain_v: Interval::new(-FRAC_PI_2, FRAC_PI_2),
                closed_u: true,
                closed_v: true,
            },
        })
    }
}
