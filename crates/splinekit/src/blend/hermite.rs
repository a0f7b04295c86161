//! Bézier pieces from Hermite data: the Bézier of degree d on a parameter interval
//! [a, a + h] whose value and first d derivatives (with respect to the global parameter)
//! at a + u₀h are given. With H the (d+1)×(d+1) matrix whose row j holds the j-th
//! derivatives of the Bernstein polynomials at u₀ times h^{−j}, the control points are
//! P = H⁻¹ c (and a surface patch's net is H_u⁻¹ C H_v⁻ᵀ).
//!
//! A piece is a [`BezierCurve`] on [0, 1] reparametrised onto [a, a + h]
//! ([`Reparametrized`]), so it is evaluated by the one Bézier derivative routine,
//! [`crate::curve::bezier::bezier_derivatives`], with the chain rule's h^{−j}.
//!
//! A piece moved onto another interval ([`rebased`], used when a knot inserted next to a
//! local changes its support) keeps its polynomial: with s = α + βs′ the affine map from
//! the new unit parameter to the old one, the new control points are the blossom values
//! Q_i = b(α, …, α, α + β, …, α + β) (d − i copies of α, i of α + β), computed by de
//! Casteljau steps with one parameter per level ([`rebased_points`]).

use nalgebra::DMatrix;

use crate::curve::bezier::bezier_derivatives;
use crate::curve::{BezierCurve, Curve, Reparametrized};
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

/// The control points on the interval `to` of the degree-d polynomial whose Bézier control
/// points on `from` are `points` (the same polynomial of the global parameter): the
/// blossom values Q_i = b(α^{d−i}, (α + β)^i) with α and α + β the old unit parameters of
/// `to`'s ends. Exact up to rounding for any two non-empty intervals.
///
/// # Examples
///
/// ```
/// use splinekit::{Interval, Point};
/// use splinekit::blend::hermite::rebased_points;
/// // The parabola t² on [0, 1] (points 0, 0, 1) seen on [1, 2]: points 1, 2, 4.
/// let p = [0.0, 0.0, 1.0].map(|y| Point::<1>::new(y));
/// let q = rebased_points(&p, Interval::new(0.0, 1.0), Interval::new(1.0, 2.0));
/// assert_eq!(q, vec![Point::<1>::new(1.0), Point::<1>::new(2.0), Point::<1>::new(4.0)]);
/// ```
pub fn rebased_points<const D: usize>(points: &[Point<D>], from: Interval, to: Interval) -> Vec<Point<D>> {
    let d = points.len().saturating_sub(1);
    let a = (to.start - from.start) / from.length();
    let b = (to.end - from.start) / from.length();
    let mut work = points.to_vec();
    (0..=d)
        .map(|i| {
            work.copy_from_slice(points);
            // Level r uses b for the first i levels, a for the rest (the blossom is symmetric).
            for r in 1..=d {
                let x = if r <= i { b } else { a };
                for j in 0..=d - r {
                    work[j] = work[j] * (1.0 - x) + work[j + 1] * x;
                }
            }
            work[0]
        })
        .collect()
}

/// `piece` (a Bézier on its interval) as the same polynomial on `support`: the control
/// points of [`rebased_points`] on the new interval.
pub fn rebased<const D: usize>(piece: &IntervalBezier<D>, support: Interval) -> Result<IntervalBezier<D>> {
    let points = rebased_points(piece.curve().control_points(), piece.domain(), support);
    Reparametrized::new(BezierCurve::new(points)?, support)
}
