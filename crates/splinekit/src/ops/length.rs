//! Arc length by adaptive Gauss–Legendre quadrature.
//!
//! L = ∫_a^b |c'(t)| dt. Each piece between breakpoints (knots, segment joins) is
//! integrated with the 10-point Gauss–Legendre rule ([`crate::quadrature`]) and compared
//! with the sum over its two halves; pieces whose estimates differ by more than their
//! share of the tolerance are bisected (to depth [`MAX_DEPTH`]). Nodes left of a piece's
//! midpoint take the right-hand limit and those right of it the left-hand one, so a piece
//! never sees the kink at the breakpoints that bound it.

use std::sync::OnceLock;

use crate::Interval;
use crate::Point;
use crate::basis::Side;
use crate::curve::Curve;
use crate::quadrature::GaussLegendre;

/// The arc length of a curve, a capability of every [`Curve`] (a blanket implementation):
/// `use splinekit::curve::CurveArcLength` to call it.
pub trait CurveArcLength<const D: usize>: Curve<D> {
    /// Arc length of the whole curve to the absolute tolerance `tolerance`
    /// (adaptive Gauss–Legendre, see [`crate::ops::length`]).
    ///
    /// ```
    /// use splinekit::curve::{Curve, CurveArcLength, model::Circle};
    /// let c = Circle::new(2.0).unwrap();
    /// assert!((c.length(1e-12) - 4.0 * std::f64::consts::PI).abs() < 1e-11);
    /// ```
    fn length(&self, tolerance: f64) -> f64 {
        arc_length(self, self.domain(), tolerance)
    }
}

impl<const D: usize, C: Curve<D> + ?Sized> CurveArcLength<D> for C {}

/// The smallest absolute tolerance honoured (below it, rounding dominates).
pub const MIN_TOLERANCE: f64 = 1e-15;

/// How many times a piece may be halved.
pub const MAX_DEPTH: u32 = 50;

fn ten_point_rule() -> &'static GaussLegendre {
    static RULE: OnceLock<GaussLegendre> = OnceLock::new();
    RULE.get_or_init(|| GaussLegendre::new(10))
}

/// ∫ |c'| over [a, b] by one 10-point rule.
fn gauss<const D: usize, C: Curve<D> + ?Sized>(curve: &C, a: f64, b: f64) -> f64 {
    let (m, h) = ((a + b) / 2.0, (b - a) / 2.0);
    let mut out = [Point::<D>::zeros(); 2];
    ten_point_rule().integrate_about(m, h, |t| {
        curve.eval_side(t, if t < m { Side::Right } else { Side::Left }, &mut out);
        out[1].norm()
    })
}

fn adaptive<const D: usize, C: Curve<D> + ?Sized>(curve: &C, a: f64, b: f64, whole: f64, tol: f64, depth: u32) -> f64 {
    let m = (a + b) / 2.0;
    let (l, r) = (gauss(curve, a, m), gauss(curve, m, b));
    if depth == 0 || (l + r - whole).abs() <= tol {
        return l + r;
    }
    adaptive(curve, a, m, l, tol / 2.0, depth - 1) + adaptive(curve, m, b, r, tol / 2.0, depth - 1)
}

/// Arc length of `curve` over the parameter interval `range` to about `tolerance`
/// (absolute, at least [`MIN_TOLERANCE`]).
///
/// # Examples
///
/// ```
/// use splinekit::curve::Interval;
/// use splinekit::curve::model::Circle;
/// use splinekit::ops::length::arc_length;
/// // A quarter of the circle of radius 2 is π long.
/// let c = Circle::new(2.0).unwrap();
/// let l = arc_length(&c, Interval::new(0.0, std::f64::consts::FRAC_PI_2), 1e-12);
/// assert!((l - std::f64::consts::PI).abs() < 1e-12);
/// ```
pub fn arc_length<const D: usize, C: Curve<D> + ?Sized>(curve: &C, range: Interval, tolerance: f64) -> f64 {
    let (a, b) = (range.start, range.end);
    let tol = tolerance.max(MIN_TOLERANCE);
    let mut cuts: Vec<f64> = curve.breakpoints().into_iter().filter(|&k| k > a && k < b).collect();
    cuts.insert(0, a);
    cuts.push(b);
    let pieces = (cuts.len() - 1) as f64;
    cuts.windows(2).map(|w| adaptive(curve, w[0], w[1], gauss(curve, w[0], w[1]), tol / pieces, MAX_DEPTH)).sum()
}
