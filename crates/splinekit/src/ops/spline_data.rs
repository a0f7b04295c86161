//! The raw form (degree, knots, coefficients) that knot operations transform, and the
//! conversions from and to curves. Periodic curves are unrolled over several periods,
//! transformed, and one period is cut from the middle (operations are local, so the
//! middle period is exactly the periodic result).

use crate::curve::{BSplineCurve, NurbsCurve};
use crate::error::{Error, Result};
use crate::ops::homogeneous::Homogeneous;
use crate::tolerance::PARAMETER_RELATIVE;
use crate::{Coefficient, Interval, Point};

/// A B-spline in raw form: Σ N_{i,p} c_i over `knots` (n + p + 1 of them).
#[derive(Debug, Clone, PartialEq)]
pub struct SplineData<T> {
    /// Degree p.
    pub degree: usize,
    /// Knots.
    pub knots: Vec<f64>,
    /// Coefficients c_i.
    pub coefficients: Vec<T>,
}

impl<T: Coefficient> SplineData<T> {
    /// Domain [t_p, t_n].
    pub fn domain(&self) -> Interval {
        Interval::new(self.knots[self.degree], self.knots[self.coefficients.len()])
    }

    /// Unrolls the periodic spline with base knots t_0 … t_{n+p} and n coefficients over
    /// `extra` periods on each side: coefficients c_{i mod n}, knots τ(i) = t_{i mod n} +
    /// ⌊i/n⌋ T. Returns the open spline and the index offset (extra·n).
    pub(crate) fn unroll_periodic(&self, extra: usize) -> (SplineData<T>, usize) {
        let n = self.coefficients.len();
        let p = self.degree;
        let period = self.knots[n + p] - self.knots[p];
        let tau = |i: isize| -> f64 {
            let r = i.rem_euclid(n as isize) as usize;
            let q = i.div_euclid(n as isize) as f64;
            self.knots[r] + q * period
        };
        let offset = (extra * n) as isize;
        let count = (2 * extra + 1) * n + p;
        let knots = (0..count + p + 1).map(|j| tau(j as isize - offset)).collect();
        let coefficients =
            (0..count).map(|j| self.coefficients[(j as isize - offset).rem_euclid(n as isize) as usize]).collect();
        (SplineData { degree: p, knots, coefficients }, extra * n)
    }

    /// Applies `op` to a periodic spline (see the module documentation) and returns the
    /// periodic result. `op` receives the unrolled open spline and the period T; it must
    /// treat every periodic image of a knot alike.
    pub fn map_periodic(&self, op: impl FnOnce(SplineData<T>, f64) -> Result<SplineData<T>>) -> Result<SplineData<T>> {
        let n = self.coefficients.len();
        let p = self.degree;
        let (a, b) = (self.knots[p], self.knots[n + p]);
        let period = b - a;
        let extra = (2 * p + 2).div_ceil(n) + 1;
        let (unrolled, _) = self.unroll_periodic(extra);
        let out = op(unrolled, period)?;
        let q = out.degree;
        // First knot index s with K[s] ≥ a, then one period: n' knots in [a, a + T).
        let tol = PARAMETER_RELATIVE * period.max(a.abs()).max(b.abs());
        let s = out.knots.partition_point(|&k| k < a - tol);
        let n_new = out.knots[s..].partition_point(|&k| k < b - tol);
        if s < q || s + n_new + 1 > out.knots.len() || s - q + n_new > out.coefficients.len() {
            return Err(Error::numerical("periodic operation", "not enough periods unrolled"));
        }
        Ok(SplineData {
            degree: q,
            knots: out.knots[s - q..=s + n_new].to_vec(),
            coefficients: out.coefficients[s - q..s - q + n_new].to_vec(),
        })
    }
}

impl<const D: usize> From<&BSplineCurve<D>> for SplineData<Point<D>> {
    fn from(c: &BSplineCurve<D>) -> Self {
        SplineData { degree: c.degree(), knots: c.knots().to_vec(), coefficients: c.control_points().to_vec() }
    }
}

impl<const D: usize> From<&NurbsCurve<D>> for SplineData<Homogeneous<D>> {
    fn from(c: &NurbsCurve<D>) -> Self {
        SplineData {
            degree: c.degree(),
            knots: c.knots().to_vec(),
            coefficients: c.control_points().iter().zip(c.weights()).map(|(p, w)| Homogeneous::lift(p, *w)).collect(),
        }
    }
}

/// Builds a B-spline curve from raw data (periodic or open).
pub fn to_bspline<const D: usize>(data: SplineData<Point<D>>, periodic: bool) -> Result<BSplineCurve<D>> {
    if periodic {
        BSplineCurve::new_periodic(data.degree, data.knots, data.coefficients)
    } else {
        BSplineCurve::new(data.degree, data.knots, data.coefficients)
    }
}

/// Builds a NURBS curve from raw homogeneous data (periodic or open).
pub fn to_nurbs<const D: usize>(data: SplineData<Homogeneous<D>>, periodic: bool) -> Result<NurbsCurve<D>> {
    let pts = data.coefficients.iter().map(|h| h.project()).collect();
    let ws = data.coefficients.iter().map(|h| h.weight).collect();
    if periodic {
        NurbsCurve::new_periodic(data.degree, data.knots, pts, ws)
    } else {
        NurbsCurve::new(data.degree, data.knots, pts, ws)
    }
}
