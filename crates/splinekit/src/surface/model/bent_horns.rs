//! Bent horns (Paul Bourke's geometry pages, a surface by Roger Bagula): with φ = 2π/3,
//! ((2 + cos u)(v/3 − sin v), (2 + cos(u − φ))(cos v − 1), (2 + cos(u + φ))(cos v − 1)),
//! u ∈ [−π, π] closed, v ∈ [−2π, 2π]: two horns meeting in a cusp at v = 0.

use super::separable::{Factor as F, SeparableSurface, positive, separable_model_surface, term};
use crate::curve::Interval;
use crate::curve::model::{Term, TrigSeries};
use crate::error::Result;
use std::f64::consts::{PI, TAU};

/// Bent horns scaled by `scale` (documents: `bent_horns`).
#[derive(Debug, Clone, PartialEq)]
pub struct BentHorns {
    surface: SeparableSurface,
}
separable_model_surface!(BentHorns);

impl BentHorns {
    /// The horns scaled by `scale` > 0.
    pub fn new(scale: f64) -> Result<Self> {
        let s = positive("scale", scale)?;
        let phi = TAU / 3.0;
        let ring = |phase: f64| F::trig(2.0, &[Term { amplitude: 1.0, frequency: 1.0, phase, sine: false }]);
        let bend = F::Series(TrigSeries {
            constant: 0.0,
            linear: 1.0 / 3.0,
            terms: smallvec::smallvec![Term::sin(-1.0, 1.0)],
        });
        let fall = || F::trig(-1.0, &[Term::cos(1.0, 1.0)]);
        Ok(BentHorns {
            surface: SeparableSurface {
                coordinates: [
                    vec![term(s, ring(0.0), bend)],
                    vec![term(s, ring(-phi), fall())],
                    vec![term(s, ring(phi), fall())],
                ],
                domain_u: Interval::new(-PI, PI),
                domain_v: Interval::new(-2.0 * PI, 2.0 * PI),
                closed_u: true,
                closed_v: false,
            },
        })
    }
}
