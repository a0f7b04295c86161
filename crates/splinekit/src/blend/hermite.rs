//! Bézier pieces from Hermite data: the Bézier of degree d on a parameter interval
//! [a, a + h] whose value and first d derivatives (with respect to the global parameter)
//! at a + u₀h are given. With H the (d+1)×(d+1) matrix whose row j holds the j-th
//! derivatives of the Bernstein polynomials at u₀ times h^{−j}, the control points are
//! P = H⁻¹ c (and a surface patch's net is H_u⁻¹ C H_v⁻ᵀ).
//!
//! A piece is a [`BezierCurve`] on [0, 1] reparametrised onto [a, a + h]
//! ([`Reparametrized`]), so it is evaluated by the one Bézier derivative routine,
//! [`crate::curve::bezier::bezier_derivatives`], with the chain rule's h^{−j}.

use nalgebra::DMatrix;

use crate::curve::bezier::bezier_derivatives;
use crate::curve::{BezierCurve, Reparametrized};
use crate::error::{Error, Result};
use crate::{Interval, Point};

/// H⁻¹ for degree d, interpolation point u₀ ∈ [0, 1] and interval length h.
pub(crate) fn inverse_hermite_matrix(d: usize, u0: f64, h: f64) -> Result<DMatrix<f64>> {
    let mut m = DMatrix::<f64>::zeros(d + 1, d + 1);
    let mut unit = vec![0.0; d + 1];
    let mut ders = vec![0.0; d + 1];
    for i in 0..=d {
        unit.iter_mut().for_each(|x| *x = 0.0);
        unit[i] = 1.0;
        bezier_derivatives(&unit, u0, &mut ders);
        let mut s = 1.0;
        for j in 0..=d {
            m[(j, i)] = ders[j] * s;
            s /= h;
        }
    }
    m.try_inverse().ok_or_else(|| Error::numerical("local Bézier", "singular Hermite system"))
}

/// A Bézier curve on a parameter interval, with derivatives with respect to that
/// parameter: a local Bézier piece.
pub type IntervalBezier<const D: usize> = Reparametrized<BezierCurve<D>>;

/// The Bézier piece of degree d = `target.len() − 1` on `support` whose value and first
/// d derivatives at the parameter `at` are `target`.
///
/// # Examples
///
/// ```
/// use splinekit::{Interval, Point};
/// use splinekit::blend::hermite::hermite_bezier;
/// use splinekit::curve::Curve;
/// // The cubic on [0, 2] with c(1) = (1, 0), c′(1) = (1, 0), c″(1) = (0, 2), c‴(1) = 0:
/// // the parabola (t, (t − 1)²), whatever the support.
/// let target = [Point::<2>::new(1.0, 0.0), Point::<2>::new(1.0, 0.0), Point::<2>::new(0.0, 2.0), Point::<2>::zeros()];
/// let piece = hermite_bezier(&target, Interval::new(0.0, 2.0), 1.0).unwrap();
/// assert!((piece.point(0.5) - Point::<2>::new(0.5, 0.25)).norm() < 1e-15);
/// ```
pub fn hermite_bezier<const D: usize>(target: &[Point<D>], support: Interval, at: f64) -> Result<IntervalBezier<D>> {
    if let Some(j) = target.iter().position(|p| !p.iter().all(|x| x.is_finite())) {
        return Err(Error::numerical("local Bézier", format!("derivative {j} at t = {at} is not finite")));
    }
    let d = target.len() - 1;
    let (a, h) = (support.start, support.length());
    let inv = inverse_hermite_matrix(d, (at - a) / h, h)?;
    let points = (0..=d).map(|i| (0..=d).fold(Point::<D>::zeros(), |acc, j| acc + target[j] * inv[(i, j)])).collect();
    Reparametrized::new(BezierCurve::new(points)?, support)
}
