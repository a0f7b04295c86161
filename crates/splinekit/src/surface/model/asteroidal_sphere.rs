//! The asteroidal sphere (Gray's astroidal ellipsoid): the sphere with each coordinate
//! cubed, ((a cos u cos v)³, (b sin u cos v)³, (c sin v)³), u ∈ [0, 2π] closed,
//! v ∈ [−π/2, π/2]; on |x|^{2/3}/a² + |y|^{2/3}/b² + |z|^{2/3}/c² = 1, the 3-D astroid
//! (A. Gray, *Modern Differential Geometry of Curves and Surfaces with Mathematica*, 2nd
//! ed., the astroidal ellipsoid).
//!
//! Separable: cos³x = (3 cos x + cos 3x)/4 and sin³x = (3 sin x − sin 3x)/4.

use super::separable::{Factor as F, SeparableSurface, positive, separable_model_surface, term};
use crate::curve::Interval;
use crate::curve::model::Term;
use crate::error::Result;
use std::f64::consts::{FRAC_PI_2, TAU};

/// The asteroidal sphere of semi-axes a, b, c (documents: `asteroidal_sphere`, all 1 by
/// default).
#[derive(Debug, Clone, PartialEq)]
pub struct AsteroidalSphere {
    surface: SeparableSurface,
}
separable_model_surface!(AsteroidalSphere);

impl AsteroidalSphere {
    /// Semi-axes a, b, c > 0 (the points (±a³, 0, 0), (0, ±b³, 0), (0, 0, ±c³) are its tips).
    pub fn new(a: f64, b: f64, c: f64) -> Result<Self> {
        let (a, b, c) = (positive("a", a)?, positive("b", b)?, positive("c", c)?);
        let cube_cos = || F::trig(0.0, &[Term::cos(0.75, 1.0), Term::cos(0.25, 3.0)]);
        let cube_sin = || F::trig(0.0, &[Term::sin(0.75, 1.0), Term::sin(-0.25, 3.0)]);
        Ok(AsteroidalSphere {
            surface: SeparableSurface {
                coordinates: [
                    vec![term(a.powi(3), cube_cos(), cube_cos())],
                    vec![term(b.powi(3), cube_sin(), cube_cos())],
                    vec![term(c.powi(3), F::constant(1.0), cube_sin())],
                ],
                domain_u: Interval::new(0.0, TAU),
                domain_v: Interval::new(-FRAC_PI_2, FRAC_PI_2),
                closed_u: true,
                closed_v: false,
            },
        })
    }
}
