//! Bézier pieces from Hermite data: the Bézier of degree d on a parameter interval
//! [a, a + h] whose value and first d derivatives (with respect to the global parameter)
//! at a + u₀h are given. With H the (d+1)×(d+1) matrix whose row j holds the j-th
//! derivatives of the Bernstein polynomials at u₀ times h^{−j}, the control points are
//! P = H⁻¹ c (and a surface patch's net is H_u⁻¹ C H_v⁻ᵀ).

use nalgebra::DMatrix;

use smallvec::{SmallVec, smallvec};

use crate::Point;
use crate::basis::Side;
use crate::basis::bernstein_derivatives;
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
    /// Σ_i B_{i,d}^{(k)}(u) P_i / h^k with the Bernstein derivatives computed once.
    fn eval_side(&self, t: f64, _side: Side, out: &mut [Point<D>]) {
        let n = self.points.len();
        let order = out.len() - 1;
        let mut basis: SmallVec<[f64; 64]> = smallvec![0.0; (order + 1) * n];
        bernstein_derivatives(n - 1, (t - self.start) / self.length, order, &mut basis);
        let mut s = 1.0;
        for (k, o) in out.iter_mut().enumerate() {
            let row = &basis[k * n..(k + 1) * n];
            let mut acc = Point::<D>::zeros();
            for (p, b) in self.points.iter().zip(row) {
                acc += p * *b;
            }
            *o = acc * s;
            s /= self.length;
        }
    }
}
