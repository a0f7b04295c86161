//! The Whitney umbrella (MathWorld, "Whitney Umbrella"): r·(u v, u, v²), u, v ∈ [−1, 1],
//! open; on x² = y² z at r = 1 (r x² = y² z for any r), with the handle (the z-axis,
//! y = 0) left out and a pinch point at the origin.

use super::separable::{Factor as F, SeparableSurface, positive, separable_model_surface, term};
use crate::curve::Interval;
use crate::error::Result;

/// The Whitney umbrella scaled by `scale` (documents: `whitney_umbrella`).
#[derive(Debug, Clone, PartialEq)]
pub struct WhitneyUmbrella {
    surface: SeparableSurface,
}
separable_model_surface!(WhitneyUmbrella);

impl WhitneyUmbrella {
    /// The surface scaled by `scale` > 0.
    pub fn new(scale: f64) -> Result<Self> {
        let r = positive("scale", scale)?;
        let p = |c: &[f64]| F::Polynomial(c.to_vec());
        Ok(WhitneyUmbrella {
            surface: SeparableSurface {
                coordinates: [
                    vec![term(r, p(&[0.0, 1.0]), p(&[0.0, 1.0]))],
                    vec![term(r, p(&[0.0, 1.0]), p(&[1.0]))],
                    vec![term(r, p(&[1.0]), p(&[0.0, 0.0, 1.0]))],
                ],
                domain_u: Interval::new(-1.0, 1.0),
                domain_v: Interval::new(-1.0, 1.0),
                closed_u: false,
                closed_v: false,
            },
        })
    }
}
