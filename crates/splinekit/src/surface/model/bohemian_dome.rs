//! The Bohemian dome (MathWorld, "Bohemian Dome"): a circle of radius a in the xy-plane
//! moved along the ellipse (0, b cos v, c sin v) in the yz-plane,
//! (a cos u, a sin u + b cos v, c sin v), u, v ∈ [0, 2π], closed both ways; on the quartic
//! (x² + y² + b²(1 − z²/c²) − a²)² = 4 b² y² (1 − z²/c²).

use super::separable::{Factor as F, SeparableSurface, positive, separable_model_surface, term};
use crate::curve::Interval;
use crate::error::Result;
use std::f64::consts::TAU;

/// The Bohemian dome of radii a, b, c (documents: `bohemian_dome`, a = b = c = 1 by
/// default).
#[derive(Debug, Clone, PartialEq)]
pub struct BohemianDome {
    surface: SeparableSurface,
}
separable_model_surface!(BohemianDome);

impl BohemianDome {
    /// The moving circle's radius a > 0 and the semi-axes b, c > 0 of the path it moves on.
    pub fn new(a: f64, b: f64, c: f64) -> Result<Self> {
        let (a, b, c) = (positive("a", a)?, positive("b", b)?, positive("c", c)?);
        let one = || F::constant(1.0);
        Ok(BohemianDome {
            surface: SeparableSurface {
                coordinates: [
                    vec![term(a, F::cos(1.0, 1.0), one())],
                    vec![term(a, F::sin(1.0, 1.0), one()), term(b, one(), F::cos(1.0, 1.0))],
                    vec![term(c, one(), F::sin(1.0, 1.0))],
                ],
                domain_u: Interval::new(0.0, TAU),
                domain_v: Interval::new(0.0, TAU),
                closed_u: true,
                closed_v: true,
            },
        })
    }
}
