//! Piecewise cubic Hermite curves through points with given tangents.

use crate::Point;
use crate::basis::Side;
use crate::curve::bezier::bezier_derivatives;
use crate::curve::{Curve, Interval};
use crate::error::{Error, Result, check_finite, check_points_finite};

/// A C¹ piecewise cubic through P_0 … P_{n−1} with tangents (first derivatives) M_i at
/// parameters t_0 < … < t_{n−1}. On [t_i, t_{i+1}] with h = t_{i+1} − t_i and
/// s = (t − t_i)/h:
///
/// c(t) = h₀₀(s) P_i + h₁₀(s) h M_i + h₀₁(s) P_{i+1} + h₁₁(s) h M_{i+1},
///
/// h₀₀ = 2s³ − 3s² + 1, h₁₀ = s³ − 2s² + s, h₀₁ = −2s³ + 3s², h₁₁ = s³ − s². Each segment is
/// stored as the Bézier cubic P_i, P_i + hM_i/3, P_{i+1} − hM_{i+1}/3, P_{i+1}; derivatives
/// are with respect to t (the k-th scaled by h^{−k}).
#[derive(Debug, Clone, PartialEq)]
pub struct HermiteCurve<const D: usize> {
    params: Vec<f64>,
    points: Vec<Point<D>>,
    tangents: Vec<Point<D>>,
    segments: Vec<[Point<D>; 4]>,
    closed: bool,
}

impl<const D: usize> HermiteCurve<D> {
    /// From points, tangents and optional strictly increasing parameters (default 0, 1, …).
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::{Curve, HermiteCurve};
    /// let p = |x, y| Point::<2>::new(x, y);
    /// let c = HermiteCurve::new(
    ///     vec![p(0.0, 0.0), p(2.0, 1.0), p(4.0, 0.0)],
    ///     vec![p(1.0, 1.0), p(1.0, 0.0), p(1.0, -1.0)],
    ///     Some(vec![0.0, 1.0, 3.0]),
    /// )
    /// .unwrap();
    /// // Through each point at its parameter, with the given tangent there.
    /// assert_eq!(c.point(1.0), p(2.0, 1.0));
    /// assert!((c.derivative(1.0, 1) - p(1.0, 0.0)).norm() < 1e-15);
    /// assert!((c.derivative(3.0, 1) - p(1.0, -1.0)).norm() < 1e-15);
    /// ```
    pub fn new(points: Vec<Point<D>>, tangents: Vec<Point<D>>, params: Option<Vec<f64>>) -> Result<Self> {
        Self::build(points, tangents, params, false)
    }

    pub(crate) fn build(
        points: Vec<Point<D>>,
        tangents: Vec<Point<D>>,
        params: Option<Vec<f64>>,
        closed: bool,
    ) -> Result<Self> {
        check_points_finite("points", &points)?;
        check_points_finite("tangents", &tangents)?;
        if points.len() < 2 {
            return Err(Error::count("points", "at least 2 points", points.len()));
        }
        if tangents.len() != points.len() {
            return Err(Error::count("tangents", format!("{} tangents, one per point", points.len()), tangents.len()));
        }
        let params = params.unwrap_or_else(|| (0..points.len()).map(|i| i as f64).collect());
        if params.len() != points.len() {
            return Err(Error::count("params", format!("{} values, one per point", points.len()), params.len()));
        }
        check_finite("params", &params)?;
        for i in 1..params.len() {
            if params[i] <= params[i - 1] {
                return Err(Error::invalid(
                    "params",
                    format!(
                        "must be strictly increasing, but params[{i}] = {} ≤ params[{}] = {}",
                        params[i],
                        i - 1,
                        params[i - 1]
                    ),
                ));
            }
        }
        let segments = (0..points.len() - 1)
            .map(|i| {
                let h = params[i + 1] - params[i];
                [
                    points[i],
                    points[i] + tangents[i] * (h / 3.0),
                    points[i + 1] - tangents[i + 1] * (h / 3.0),
                    points[i + 1],
                ]
            })
            .collect();
        Ok(HermiteCurve { params, points, tangents, segments, closed })
    }

    /// The interpolated points.
    pub fn points(&self) -> &[Point<D>] {
        &self.points
    }
    /// The tangents at the points.
    pub fn tangents(&self) -> &[Point<D>] {
        &self.tangents
    }
    /// The parameters of the points.
    pub fn params(&self) -> &[f64] {
        &self.params
    }
    /// The Bézier control points of segment i (on [t_i, t_{i+1}]).
    pub fn segment(&self, i: usize) -> &[Point<D>; 4] {
        &self.segments[i]
    }
}

impl<const D: usize> Curve<D> for HermiteCurve<D> {
    fn domain(&self) -> Interval {
        Interval::new(self.params[0], *self.params.last().unwrap())
    }
    fn is_closed(&self) -> bool {
        self.closed
    }
    fn eval_side(&self, t: f64, side: Side, out: &mut [Point<D>]) {
        let d = self.domain();
        let t = if self.closed { d.wrap_periodic(t, side) } else { d.clamp(t) };
        let inner = &self.params[1..self.params.len() - 1];
        let i = match side {
            Side::Right => inner.partition_point(|&k| k <= t),
            Side::Left => inner.partition_point(|&k| k < t),
        };
        let h = self.params[i + 1] - self.params[i];
        bezier_derivatives(&self.segments[i], (t - self.params[i]) / h, out);
        let mut scale = 1.0;
        for o in out.iter_mut().skip(1) {
            scale /= h;
            *o *= scale;
        }
    }
    fn breakpoints(&self) -> Vec<f64> {
        self.params.clone()
    }
}
