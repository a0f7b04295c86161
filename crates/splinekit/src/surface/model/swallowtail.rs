//! The swallowtail (Paul Bourke's geometry pages; MathWorld, "Swallowtail Catastrophe"):
//! r·(u v² + 3 v⁴, −2 u v − 4 v³, u), u ∈ [−2, 2], v ∈ [−1, 1], open. At r = 1 it is the
//! discriminant of the quartic t⁴ + z t² + y t + x: the quartic has the double root t = v
//! at S(u, v).

use super::separable::{Factor as F, SeparableSurface, positive, separable_model_surface, term};
use crate::curve::Interval;
use crate::error::Result;

/// The swallowtail scaled by `scale` (documents: `swallowtail`).
#[derive(Debug, Clone, PartialEq)]
pub struct Swallowtail {
    surface: SeparableSurface,
}
separable_model_surface!(Swallowtail);

impl Swallowtail {
    /// The surface scaled by `scale` > 0.
    pub fn new(scale: f64) -> Result<Self> {
        let r = positive("scale", scale)?;
        let p = |c: &[f64]| F::Polynomial(c.to_vec());
        Ok(Swallowtail {
            surface: SeparableSurface {
                coordinates: [
                    vec![
                        term(r, p(&[0.0, 1.0]), p(&[0.0, 0.0, 1.0])),
                        term(3.0 * r, p(&[1.0]), p(&[0.0, 0.0, 0.0, 0.0, 1.0])),
                    ],
                    vec![
                        term(-2.0 * r, p(&[0.0, 1.0]), p(&[0.0, 1.0])),
                        term(-4.0 * r, p(&[1.0]), p(&[0.0, 0.0, 0.0, 1.0])),
                    ],
                    vec![term(r, p(&[0.0, 1.0]), p(&[1.0]))],
                ],
                domain_u: Interval::new(-2.0, 2.0),
                domain_v: Interval::new(-1.0, 1.0),
                closed_u: false,
                closed_v: false,
            },
        })
    }
}
