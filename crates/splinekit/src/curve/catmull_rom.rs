//! Catmull–Rom splines with uniform, centripetal and chordal parametrisation.

use crate::Point;
use crate::basis::Side;
use crate::curve::{Curve, HermiteCurve, Interval};
use crate::error::{Error, Result, check_points_finite};

/// A Catmull–Rom spline: the C¹ piecewise cubic through P_0 … P_{n−1} with knots
/// t_{i+1} = t_i + |P_{i+1} − P_i|^α (α = 0 uniform, ½ centripetal, 1 chordal) and the
/// Barry–Goldman tangents
///
/// M_i = (P_i − P_{i−1})/(t_i − t_{i−1}) − (P_{i+1} − P_{i−1})/(t_{i+1} − t_{i−1}) + (P_{i+1} − P_i)/(t_{i+1} − t_i),
///
/// which for α = 0 reduce to the classic (P_{i+1} − P_{i−1})/2. Open curves get phantom
/// end points P_{−1} = 2P_0 − P_1 and P_n = 2P_{n−1} − P_{n−2}; closed curves wrap around
/// and also join P_{n−1} to P_0. Derivatives are with respect to the knot parameter.
#[derive(Debug, Clone, PartialEq)]
pub struct CatmullRomCurve<const D: usize> {
    alpha: f64,
    hermite: HermiteCurve<D>,
}

impl<const D: usize> CatmullRomCurve<D> {
    /// Builds the spline; `alpha` ∈ [0, 1]. Consecutive points must differ when α > 0.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::{CatmullRomCurve, Curve};
    /// let p = |x, y| Point::<2>::new(x, y);
    /// let pts = vec![p(0.0, 0.0), p(1.0, 1.0), p(3.0, 1.0), p(4.0, 0.0)];
    /// // Uniform (α = 0): knots 0, 1, 2, 3 and the classic tangents (P_{i+1} − P_{i−1})/2.
    /// let c = CatmullRomCurve::new(pts.clone(), 0.0, false).unwrap();
    /// assert_eq!(c.point(1.0), pts[1]);
    /// assert!((c.derivative(1.0, 1) - (pts[2] - pts[0]) / 2.0).norm() < 1e-15);
    /// ```
    pub fn new(points: Vec<Point<D>>, alpha: f64, closed: bool) -> Result<Self> {
        check_points_finite("points", &points)?;
        if !(0.0..=1.0).contains(&alpha) {
            return Err(Error::invalid("alpha", format!("must be in [0, 1], got {alpha}")));
        }
        let n = points.len();
        let min = if closed { 3 } else { 2 };
        if n < min {
            return Err(Error::count("points", format!("at least {min} points"), n));
        }
        // Extended point list with one neighbour on each side.
        let mut ext = Vec::with_capacity(n + 3);
        if closed {
            ext.push(points[n - 1]);
            ext.extend_from_slice(&points);
            ext.push(points[0]);
            ext.push(points[1]);
        } else {
            ext.push(points[0] * 2.0 - points[1]);
            ext.extend_from_slice(&points);
            ext.push(points[n - 1] * 2.0 - points[n - 2]);
        }
        let mut knots = vec![0.0; ext.len()];
        for i in 1..ext.len() {
            let d = (ext[i] - ext[i - 1]).norm();
            if alpha > 0.0 && d == 0.0 {
                return Err(Error::invalid(
                    "points",
                    format!(
                        "points {} and {} coincide, which α = {alpha} does not allow",
                        (i + n - 2) % n,
                        (i + n - 1) % n
                    ),
                ));
            }
            knots[i] = knots[i - 1] + if alpha == 0.0 { 1.0 } else { d.powf(alpha) };
        }
        let m = if closed { n + 1 } else { n };
        let mut pts = Vec::with_capacity(m);
        let mut tangents = Vec::with_capacity(m);
        let mut params = Vec::with_capacity(m);
        for i in 1..=m {
            let (p0, p1, p2) = (ext[i - 1], ext[i], ext[i + 1]);
            let (t0, t1, t2) = (knots[i - 1], knots[i], knots[i + 1]);
            let tan = (p1 - p0) / (t1 - t0) - (p2 - p0) / (t2 - t0) + (p2 - p1) / (t2 - t1);
            pts.push(p1);
            tangents.push(tan);
            params.push(t1 - knots[1]);
        }
        let hermite = HermiteCurve::build(pts, tangents, Some(params), closed)?;
        Ok(CatmullRomCurve { alpha, hermite })
    }

    /// The parametrisation exponent α.
    pub fn alpha(&self) -> f64 {
        self.alpha
    }
    /// The equivalent Hermite curve (points, tangents and knot parameters).
    pub fn as_hermite(&self) -> &HermiteCurve<D> {
        &self.hermite
    }
}

impl<const D: usize> Curve<D> for CatmullRomCurve<D> {
    fn domain(&self) -> Interval {
        self.hermite.domain()
    }
    fn is_closed(&self) -> bool {
        self.hermite.is_closed()
    }
    fn eval_side(&self, t: f64, side: Side, out: &mut [Point<D>]) {
        self.hermite.eval_side(t, side, out)
    }
    fn breakpoints(&self) -> Vec<f64> {
        self.hermite.breakpoints()
    }
}
