//! The trianguloid trefoil (Paul Bourke's geometry pages, "Tranguloid Trefoil", a surface
//! by Roger Bagula): with φ = 2π/3,
//! (2 sin 3u / (2 + cos v), 2 (sin u + 2 sin 2u) / (2 + cos(v + φ)),
//! (cos u − 2 cos 2u)(2 + cos v)(2 + cos(v + φ)) / 4), u, v ∈ [−π, π], closed both ways.
//!
//! Rational-separable ([`super::rational`]; the denominators are at least 1).

use super::rational::{RationalCoordinate, RationalSurface};
use super::separable::{Factor as F, positive, separable_model_surface, term};
use crate::curve::Interval;
use crate::curve::model::Term;
use crate::error::Result;
use std::f64::consts::{PI, TAU};

/// The trianguloid trefoil scaled by `scale` (documents: `trianguloid_trefoil`).
#[derive(Debug, Clone, PartialEq)]
pub struct TrianguloidTrefoil {
    surface: RationalSurface,
}
separable_model_surface!(TrianguloidTrefoil);

impl TrianguloidTrefoil {
    /// The surface scaled by `scale` > 0.
    pub fn new(scale: f64) -> Result<Self> {
        let s = positive("scale", scale)?;
        let phi = TAU / 3.0;
        let one = || F::constant(1.0);
        let ring = |phase: f64| F::trig(2.0, &[Term { amplitude: 1.0, frequency: 1.0, phase, sine: false }]);
        Ok(TrianguloidTrefoil {
            surface: RationalSurface {
                coordinates: [
                    RationalCoordinate {
                        plus: vec![],
                        numerator: vec![term(2.0 * s, F::sin(1.0, 3.0), one())],
                        denominator: vec![term(1.0, one(), ring(0.0))],
                    },
                    RationalCoordinate {
                        plus: vec![],
                        numerator: vec![term(
                            2.0 * s,
                            F::trig(0.0, &[Term::sin(1.0, 1.0), Term::sin(2.0, 2.0)]),
                            one(),
                        )],
                        denominator: vec![term(1.0, one(), ring(phi))],
                    },
                    RationalCoordinate {
                        plus: vec![term(
                            0.25 * s,
                            F::trig(0.0, &[Term::cos(1.0, 1.0), Term::cos(-2.0, 2.0)]),
                            ring(0.0).times(ring(phi)),
                        )],
                        ..Default::default()
                    },
                ],
                domain_u: Interval::new(-PI, PI),
                domain_v: Interval::new(-PI, PI),
                closed_u: true,
                closed_v: true,
            },
        })
    }
}
