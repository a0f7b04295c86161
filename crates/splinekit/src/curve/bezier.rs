//! Bézier curves c(t) = Σ_{i=0}^{n} B_{i,n}(t) P_i on [0, 1].

use smallvec::SmallVec;

use crate::Coefficient;
use crate::Point;
use crate::basis::{Side, bernstein_all};
use crate::curve::{Curve, Interval};
use crate::error::{Error, Result, check_points_finite};

/// A Bézier curve of degree n = (number of control points − 1) on [0, 1].
///
/// Evaluated by de Casteljau's algorithm, which also yields the derivatives:
/// c^{(k)}(t) = n!/(n−k)! Σ_i Δ^k P_i B_{i,n−k}(t), and Δ^k of the k + 1 intermediate
/// points of level n − k is exactly that sum.
#[derive(Debug, Clone, PartialEq)]
pub struct BezierCurve<const D: usize> {
    control_points: Vec<Point<D>>,
}

/// The knots of a Bézier curve of degree p as a clamped B-spline over [0, 1]: p + 1 zeros
/// then p + 1 ones. A Bézier curve (rational or not, or each direction of a Bézier
/// surface) is the one-span B-spline (NURBS) on them with the same control points.
pub fn bezier_knots(degree: usize) -> Vec<f64> {
    [vec![0.0; degree + 1], vec![1.0; degree + 1]].concat()
}

impl<const D: usize> BezierCurve<D> {
    /// A Bézier curve through its control points (at least one).
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::{BezierCurve, Curve};
    /// // The quadratic with P0 = (0, 0), P1 = (1, 2), P2 = (2, 0): c(½) = (1, 1), c′(½) = (2, 0).
    /// let p = |x, y| Point::<2>::new(x, y);
    /// let c = BezierCurve::new(vec![p(0.0, 0.0), p(1.0, 2.0), p(2.0, 0.0)]).unwrap();
    /// assert_eq!(c.point(0.5), p(1.0, 1.0));
    /// assert_eq!(c.derivative(0.5, 1), p(2.0, 0.0));
    /// assert!(BezierCurve::<2>::new(vec![]).is_err());
    /// ```
    pub fn new(control_points: Vec<Point<D>>) -> Result<Self> {
        if control_points.is_empty() {
            return Err(Error::count("control_points", "at least 1 point", 0));
        }
        check_points_finite("control_points", &control_points)?;
        Ok(BezierCurve { control_points })
    }

    /// The degree n.
    pub fn degree(&self) -> usize {
        self.control_points.len() - 1
    }

    /// The control points.
    pub fn control_points(&self) -> &[Point<D>] {
        &self.control_points
    }

    /// c(t) = Σ B_{i,n}(t) P_i evaluated in Bernstein form (for comparison with de Casteljau).
    pub fn point_bernstein(&self, t: f64) -> Point<D> {
        let n = self.degree();
        let mut b: SmallVec<[f64; 16]> = SmallVec::from_elem(0.0, n + 1);
        bernstein_all(n, t, &mut b);
        self.control_points.iter().zip(&b).fold(Point::<D>::zeros(), |acc, (p, w)| acc + p * *w)
    }

    /// The intermediate points of de Casteljau's algorithm at t: level r holds the n − r + 1
    /// points b_i^r = (1−t) b_i^{r−1} + t b_{i+1}^{r−1}; level 0 is the control polygon.
    pub fn de_casteljau_levels(&self, t: f64) -> Vec<Vec<Point<D>>> {
        let mut levels = vec![self.control_points.clone()];
        while levels.last().unwrap().len() > 1 {
            let prev = levels.last().unwrap();
            let next = prev.windows(2).map(|w| w[0] * (1.0 - t) + w[1] * t).collect();
            levels.push(next);
        }
        levels
    }

    /// Splits at t into the Bézier curves on [0, t] and [t, 1] (each reparametrised to [0, 1]).
    pub fn split(&self, t: f64) -> (Self, Self) {
        let levels = self.de_casteljau_levels(t);
        let left = levels.iter().map(|l| l[0]).collect();
        let right = levels.iter().rev().map(|l| *l.last().unwrap()).collect();
        (BezierCurve { control_points: left }, BezierCurve { control_points: right })
    }

    /// The same curve as a Bézier curve of degree n + 1:
    /// Q_i = i/(n+1) P_{i−1} + (1 − i/(n+1)) P_i.
    pub fn elevate(&self) -> Self {
        let n = self.degree();
        let p = &self.control_points;
        let mut q = Vec::with_capacity(n + 2);
        q.push(p[0]);
        for i in 1..=n {
            let a = i as f64 / (n + 1) as f64;
            q.push(p[i - 1] * a + p[i] * (1.0 - a));
        }
        q.push(p[n]);
        BezierCurve { control_points: q }
    }

    /// The same curve with every control point mapped by `f` (affine maps give the mapped
    /// curve exactly: Bézier curves are affinely invariant).
    pub fn map_points(&self, f: impl Fn(&Point<D>) -> Point<D>) -> Self {
        BezierCurve { control_points: self.control_points.iter().map(f).collect() }
    }

    /// The hodograph c'(t) as a Bézier curve of degree n − 1: n (P_{i+1} − P_i).
    /// A degree-0 curve has the zero curve as hodograph.
    pub fn hodograph(&self) -> Self {
        let n = self.degree();
        if n == 0 {
            return BezierCurve { control_points: vec![Point::<D>::zeros()] };
        }
        let q = self.control_points.windows(2).map(|w| (w[1] - w[0]) * n as f64).collect();
        BezierCurve { control_points: q }
    }
}

/// The cubic Bézier basis matrix M_B of the lecture notes: c(t) = [1 t t² t³] M_B [P0 P1 P2 P3]ᵀ.
pub const CUBIC_BEZIER_MATRIX: [[f64; 4]; 4] =
    [[1.0, 0.0, 0.0, 0.0], [-3.0, 3.0, 0.0, 0.0], [3.0, -6.0, 3.0, 0.0], [-1.0, 3.0, -3.0, 1.0]];

/// The cubic Hermite basis matrix: c(t) = [1 t t² t³] M_H [P0 P1 T0 T1]ᵀ.
pub const CUBIC_HERMITE_MATRIX: [[f64; 4]; 4] =
    [[1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [-3.0, 3.0, -2.0, -1.0], [2.0, -2.0, 1.0, 1.0]];

/// The uniform cubic B-spline segment matrix: c(t) = [1 t t² t³] M_S [P0 P1 P2 P3]ᵀ.
pub const CUBIC_BSPLINE_MATRIX: [[f64; 4]; 4] = [
    [1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0, 0.0],
    [-3.0 / 6.0, 0.0, 3.0 / 6.0, 0.0],
    [3.0 / 6.0, -6.0 / 6.0, 3.0 / 6.0, 0.0],
    [-1.0 / 6.0, 3.0 / 6.0, -3.0 / 6.0, 1.0 / 6.0],
];

/// Evaluates the matrix form [1 t t² t³] M G for a 4×4 basis matrix M and geometry G.
pub fn cubic_matrix_form<const D: usize>(m: &[[f64; 4]; 4], geometry: &[Point<D>; 4], t: f64) -> Point<D> {
    let powers = [1.0, t, t * t, t * t * t];
    let mut out = Point::<D>::zeros();
    for (r, pw) in powers.iter().enumerate() {
        for c in 0..4 {
            out += geometry[c] * (pw * m[r][c]);
        }
    }
    out
}

/// De Casteljau with derivatives: writes c^{(k)}(t) for k = 0 … `out.len() − 1` of the
/// Bézier curve with coefficients `points` (any linear space), t ∈ [0, 1] (any t works:
/// the polynomial is continued).
///
/// Level r of the triangle holds n − r + 1 points; the derivative of order j = n − r is
/// n!/(n−j)! Δ^j of them. Cost O(n² + k³). Up to 8 coefficients (degree 7) and 4 outputs
/// the triangle lives in fixed-size arrays the compiler unrolls; otherwise in a stack
/// buffer up to 16 coefficients and on the heap beyond. This is the one home of Bézier derivatives: curves, rational
/// curves, Hermite segments, polynomial B-functions, Bézier surfaces and the local Bézier
/// pieces of blending splines all call it.
///
/// # Examples
///
/// ```
/// use splinekit::curve::bezier::bezier_derivatives;
/// // The cubic with coefficients 0, 0, 0, 1 is t³: at t = ½, (⅛, ¾, 3, 6).
/// let mut out = [0.0; 4];
/// bezier_derivatives(&[0.0, 0.0, 0.0, 1.0], 0.5, &mut out);
/// assert_eq!(out, [0.125, 0.75, 3.0, 6.0]);
/// ```
#[inline]
pub fn bezier_derivatives<T: Coefficient>(points: &[T], t: f64, out: &mut [T]) {
    /// Dispatches to the array path for W coefficients, by the number of outputs K.
    macro_rules! by_outputs {
        ($w:literal) => {
            match out.len() {
                1 => bezier_derivatives_fixed::<T, $w, 1>(points, t, out),
                2 => bezier_derivatives_fixed::<T, $w, 2>(points, t, out),
                3 => bezier_derivatives_fixed::<T, $w, 3>(points, t, out),
                4 => bezier_derivatives_fixed::<T, $w, 4>(points, t, out),
                _ => bezier_derivatives_slices(points, t, out),
            }
        };
    }
    match points.len() {
        1 => by_outputs!(1),
        2 => by_outputs!(2),
        3 => by_outputs!(3),
        4 => by_outputs!(4),
        5 => by_outputs!(5),
        6 => by_outputs!(6),
        7 => by_outputs!(7),
        8 => by_outputs!(8),
        _ => bezier_derivatives_slices(points, t, out),
    }
}

/// [`bezier_derivatives`] with W coefficients and K outputs in arrays: every loop has a
/// constant trip count, so the triangle stays in registers.
#[inline(always)]
fn bezier_derivatives_fixed<T: Coefficient, const W: usize, const K: usize>(points: &[T], t: f64, out: &mut [T]) {
    let mut b: [T; W] = points.try_into().expect("W coefficients");
    let mut diff = [T::zero(); W];
    let out: &mut [T; K] = out.try_into().expect("K outputs");
    de_casteljau_triangle(&mut b, &mut diff, t, out)
}

/// [`bezier_derivatives`] for any sizes, with stack buffers up to 16 coefficients.
fn bezier_derivatives_slices<T: Coefficient>(points: &[T], t: f64, out: &mut [T]) {
    let mut b: SmallVec<[T; 16]> = SmallVec::from_slice(points);
    let mut diff: SmallVec<[T; 16]> = SmallVec::from_elem(T::zero(), points.len());
    de_casteljau_triangle(&mut b, &mut diff, t, out)
}

/// The triangle of [`bezier_derivatives`] on the coefficients `b` (overwritten), with
/// `diff` (as long as `b`) as scratch for the differences; only the levels whose
/// derivative is asked for are differenced.
#[inline(always)]
fn de_casteljau_triangle<T: Coefficient>(b: &mut [T], diff: &mut [T], t: f64, out: &mut [T]) {
    let n = b.len() - 1;
    let k = out.len() - 1;
    for o in out.iter_mut().skip(n + 1) {
        *o = T::zero();
    }
    for r in 0..=n {
        let j = n - r;
        if j <= k {
            // Δ^j of b[..=j]: the first differences straight from b, then in place.
            let delta = if j == 0 {
                b[0]
            } else {
                for i in 0..j {
                    diff[i] = b[i + 1] - b[i];
                }
                for s in 1..j {
                    for i in 0..j - s {
                        diff[i] = diff[i + 1] - diff[i];
                    }
                }
                diff[0]
            };
            let falling = (0..j).fold(1.0, |acc, i| acc * (n - i) as f64);
            out[j] = delta * falling;
        }
        if r < n {
            for i in 0..n - r {
                b[i] = b[i] * (1.0 - t) + b[i + 1] * t;
            }
        }
    }
}

impl<const D: usize> Curve<D> for BezierCurve<D> {
    crate::curve::control_box::control_point_box!("a Bézier curve");
    fn domain(&self) -> Interval {
        Interval::new(0.0, 1.0)
    }
    fn eval_side(&self, t: f64, _side: Side, out: &mut [Point<D>]) {
        bezier_derivatives(&self.control_points, t.clamp(0.0, 1.0), out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The array paths (up to 8 coefficients and 4 outputs) and the buffer path are the same
    /// arithmetic, and both match the derivatives of the power form.
    #[test]
    fn every_path_of_bezier_derivatives_agrees_with_the_power_form() {
        for n in 0..=10usize {
            // t^m with m = n/2 in Bernstein form of degree n: b_i = C(i, m)/C(n, m).
            let m = n / 2;
            let coefficients: Vec<f64> =
                (0..=n).map(|i| crate::basis::binomial(i, m) / crate::basis::binomial(n, m)).collect();
            let t = 0.3;
            let mut long = vec![0.0; 7];
            bezier_derivatives(&coefficients, t, &mut long);
            for outputs in 1..=4 {
                let mut short = vec![0.0; outputs];
                bezier_derivatives(&coefficients, t, &mut short);
                assert_eq!(short[..], long[..outputs], "n = {n}, {outputs} outputs");
            }
            for (k, d) in long.iter().enumerate() {
                let falling: f64 = (0..k).map(|i| (m as f64) - i as f64).product();
                let want = if k <= m { falling * t.powi((m - k) as i32) } else { 0.0 };
                // Differences of order k of the coefficients carry n!/(n−k)! of their rounding.
                let scale: f64 = (0..k.min(n)).map(|i| (n - i) as f64).product();
                assert!((d - want).abs() < 1e-14 * scale.max(1.0), "n = {n}, t^{m}, order {k}: {d} vs {want}");
            }
        }
    }
}
