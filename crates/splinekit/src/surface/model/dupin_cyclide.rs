//! The Dupin cyclide, the CAD blending surface: the envelope of the spheres touching three
//! fixed spheres, whose lines of curvature are all circles. With parameters a > c ≥ 0 and
//! μ, b² = a² − c², its standard parametrisation over angles (θ, ψ) is
//!
//! x = (μ (c − a cos θ cos ψ) + b² cos θ) / (a − c cos θ cos ψ),
//! y = b sin θ (a − μ cos ψ) / (a − c cos θ cos ψ),
//! z = b sin ψ (c cos θ − μ) / (a − c cos θ cos ψ),
//!
//! on the quartic (x² + y² + z² − μ² + b²)² = 4 (a x − c μ)² + 4 b² y² (a ring cyclide for
//! c < μ < a; spindle and horn cyclides otherwise).
//!
//! Exact rational biquadratic form. Write each angle's (cos, sin, 1) homogeneously as the
//! NURBS circle of nine control points (Cₖ, Sₖ, Wₖ) = wₖ (xₖ, yₖ, 1) on the corners and
//! mid-sides of the square [−1, 1]², weights 1 and √2/2 alternating, knots
//! 0, 0, 0, π/2, π/2, π, π, 3π/2, 3π/2, 2π, 2π, 2π (the parameter equals the angle at the
//! quarter points). The cyclide's homogeneous coordinates are bilinear in the two circles'
//! (C, S, W):
//!
//! W = a W_θ W_ψ − c C_θ C_ψ,
//! X = μ (c W_θ W_ψ − a C_θ C_ψ) + b² C_θ W_ψ,
//! Y = b S_θ (a W_ψ − μ C_ψ),
//! Z = b S_ψ (c C_θ − μ W_θ),
//!
//! so the tensor product of the circle's bases with control values (X, Y, Z, W)ᵢⱼ made of
//! the circles' control values by the same formulas is the cyclide exactly: a 9 × 9 NURBS
//! net of degree (2, 2), weight Wᵢⱼ = wᵢ wⱼ (a − c xᵢ xⱼ) ≥ wᵢ wⱼ (a − c) > 0 and control
//! point (X, Y, Z)ᵢⱼ / Wᵢⱼ. The point at parameters (s, t) is the closed form's at the
//! angles θ(s), ψ(t) of the circle's rational parametrisation.

use std::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2};

use crate::Point;
use crate::error::{Error, Result};
use crate::surface::NurbsSurface;

/// The homogeneous control values (C, S, W) = w (x, y, 1) of the nine-point NURBS circle,
/// counter-clockwise from (1, 0).
fn circle() -> [(f64, f64, f64); 9] {
    let corner = FRAC_1_SQRT_2;
    let xy = [
        (1.0, 0.0),
        (1.0, 1.0),
        (0.0, 1.0),
        (-1.0, 1.0),
        (-1.0, 0.0),
        (-1.0, -1.0),
        (0.0, -1.0),
        (1.0, -1.0),
        (1.0, 0.0),
    ];
    xy.map(|(x, y)| {
        let w = if x != 0.0 && y != 0.0 { corner } else { 1.0 };
        (w * x, w * y, w)
    })
}

/// The knots of the nine-point circle: breaks at the quarter angles, each doubled.
fn circle_knots() -> Vec<f64> {
    let q = FRAC_PI_2;
    vec![0.0, 0.0, 0.0, q, q, 2.0 * q, 2.0 * q, 3.0 * q, 3.0 * q, 4.0 * q, 4.0 * q, 4.0 * q]
}

/// The Dupin cyclide of parameters a > c ≥ 0 and μ as its exact biquadratic NURBS
/// surface on [0, 2π]² (see the module's documentation).
pub fn dupin_cyclide(a: f64, c: f64, mu: f64) -> Result<NurbsSurface<3>> {
    // Finite first, so that the comparisons below decide.
    for (field, value) in [("a", a), ("c", c), ("mu", mu)] {
        if !value.is_finite() {
            return Err(Error::invalid(field, format!("must be finite, got {value}")));
        }
    }
    if c < 0.0 {
        return Err(Error::invalid("c", format!("must be ≥ 0, got {c}")));
    }
    if a <= c {
        return Err(Error::invalid("a", format!("must be greater than c = {c}, got {a}")));
    }
    let b2 = (a - c) * (a + c);
    let b = b2.sqrt();
    let circle = circle();
    let mut net = Vec::with_capacity(9);
    let mut weights = Vec::with_capacity(9);
    for &(ci, si, wi) in &circle {
        let (mut row, mut row_weights) = (Vec::with_capacity(9), Vec::with_capacity(9));
        for &(cj, sj, wj) in &circle {
            let w = a * wi * wj - c * ci * cj;
            let x = mu * (c * wi * wj - a * ci * cj) + b2 * ci * wj;
            let y = b * si * (a * wj - mu * cj);
            let z = b * sj * (c * ci - mu * wi);
            row.push(Point::<3>::new(x / w, y / w, z / w));
            row_weights.push(w);
        }
        net.push(row);
        weights.push(row_weights);
    }
    NurbsSurface::new((2, 2), circle_knots(), circle_knots(), net, weights, (false, false))
}
