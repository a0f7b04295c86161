//! The inside-out torus: the torus of an elliptic tube,
//! ((a + b cos v) cos u, (a + b cos v) sin u, c sin v), u, v ∈ [0, 2π], closed both ways
//! (Gray, *Modern Differential Geometry of Curves and Surfaces*, the torus with
//! f(u, v) = ((a + b cos v) cos u, (a + b cos v) sin u, c sin v); GMlib's inside-out torus
//! takes the same wheel radius a and tube radii b, c). With b > a, as by default, the tube
//! passes through the axis and its inner half comes out on the other side: a spindle torus
//! turned inside out, on ((ρ − a)²/b² + z²/c² − 1)((ρ + a)²/b² + z²/c² − 1) = 0,
//! ρ = √(x² + y²).

use super::separable::{Factor as F, SeparableSurface, positive, separable_model_surface, term};
use crate::curve::Interval;
use crate::error::Result;
use std::f64::consts::TAU;

/// The torus of wheel radius a and elliptic tube b × c (documents: `inside_out_torus`,
/// a = 1, b = 2, c = 1.5).
#[derive(Debug, Clone, PartialEq)]
pub struct InsideOutTorus {
    surface: SeparableSurface,
}
separable_model_surface!(InsideOutTorus);

impl InsideOutTorus {
    /// Wheel radius a > 0, tube semi-axes b > 0 (radial) and c > 0 (axial).
    pub fn new(wheel_radius: f64, tube_radius_1: f64, tube_radius_2: f64) -> Result<Self> {
        let a = positive("wheel_radius", wheel_radius)?;
        let b = positive("tube_radius_1", tube_radius_1)?;
        let c = positive("tube_radius_2", tube_radius_2)?;
        let one = || F::constant(1.0);
        Ok(InsideOutTorus {
            surface: SeparableSurface {
                coordinates: [
                    vec![term(a, F::cos(1.0, 1.0), one()), term(b, F::cos(1.0, 1.0), F::cos(1.0, 1.0))],
                    vec![term(a, F::sin(1.0, 1.0), one()), term(b, F::sin(1.0, 1.0), F::cos(1.0, 1.0))],
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
