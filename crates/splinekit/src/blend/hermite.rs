//! Bézier pieces from Hermite data: the Bézier of degree d on a parameter interval
//! [a, a + h] whose value and first d derivatives (with respect to the global parameter)
//! at a + u₀h are given. With H the (d+1)×(d+1) matrix whose row j holds the j-th
//! derivatives of the Bernstein polynomials at u₀ times h^{−j}, the control points are
//! P = H⁻¹ c (and a surface patch's net is H_u⁻¹ C H_v⁻ᵀ).

use nalgebra::DMatrix;

use smallvec::SmallVec;

use crate::Point;
use crate::basis::Side;
use crate::curve::bezier::bezier_derivatives;
use crate::curve::{Curve, Interval};
use crate::error::{Error, Result};

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

/// A Bézier curve on [start, start + length], with derivatives with respect to that
/// parameter (defined, as a polynomial, for every t).
#[derive(Debug, Clone)]
pub struct IntervalBezier<const D: usize> {
    /// Control points.
    pub points: Vec<Point<D>>,
    /// Parameter of the first control point.
    pub start: f64,
    /// Parameter length of the piece.
    pub length: f64,
}

impl<const D: usize> IntervalBezier<D> {
    /// The degree-(target.len() − 1) Bézier on [a, a + h] matching `target` (value and
    /// derivatives) at a + u₀h.
    pub fn hermite(target: &[Point<D>], a: f64, h: f64, u0: f64) -> Result<Self> {
        let d = target.len() - 1;
        let inv = inverse_hermite_matrix(d, u0, h)?;
        let points =
            (0..=d).map(|i| (0..=d).fold(Point::<D>::zeros(), |acc, j| acc + target[j] * inv[(i, j)])).collect();
        Ok(IntervalBezier { points, start: a, length: h })
    }
}

impl<const D: usize> Curve<D> for IntervalBezier<D> {
    fn domain(&self) -> Interval {
        Interval::new(self.start, self.start + self.length)
    }
    fn is_closed(&self) -> bool {
        false
    }
    /// de Casteljau down to level d − m, then for k = m, m − 1, …, 0: the k-th derivative is
    /// d!/(d − k)! Δᵏ of the k + 1 points at level d − k, divided by hᵏ, followed by one more
    /// de Casteljau step.
    fn eval_side(&self, t: f64, _side: Side, out: &mut [Point<D>]) {
        let d = self.points.len() - 1;
        let u = (t - self.start) / self.length;
        if d < 8 {
            let mut b = [Point::<D>::zeros(); 8];
            b[..=d].copy_from_slice(&self.points);
            return derivatives_by_de_casteljau(&mut b, d, u, self.length, out);
        }
        let mut b: SmallVec<[Point<D>; 16]> = SmallVec::from_slice(&self.points);
        derivatives_by_de_casteljau(&mut b, d, u, self.length, out)
    }
}

/// The de Casteljau derivative scheme on the control points `b[..=d]` (overwritten).
#[inline]
fn derivatives_by_de_casteljau<const D: usize>(
    b: &mut [Point<D>],
    d: usize,
    u: f64,
    length: f64,
    out: &mut [Point<D>],
) {
    let m = (out.len() - 1).min(d);
    for level in 0..d - m {
        for i in 0..d - level {
            b[i] = b[i] * (1.0 - u) + b[i + 1] * u;
        }
    }
    for o in out.iter_mut().skip(m + 1) {
        *o = Point::<D>::zeros();
    }
    for k in (0..=m).rev() {
        // b[0..=k] are the points at level d − k; Δᵏb₀ = Σ_j (−1)^{k−j} C(k, j) b_j.
        let mut delta = Point::<D>::zeros();
        let mut choose = 1.0;
        for j in (0..=k).rev() {
            let sign = if (k - j) % 2 == 0 { 1.0 } else { -1.0 };
            delta += b[j] * (sign * choose);
            choose = choose * j as f64 / (k - j + 1) as f64;
        }
        let falling: f64 = ((d - k + 1)..=d).map(|x| x as f64).product();
        out[k] = delta * (falling / length.powi(k as i32));
        if k > 0 {
            for i in 0..k {
                b[i] = b[i] * (1.0 - u) + b[i + 1] * u;
            }
        }
    }
}
