//! Rational Bézier curves c(t) = Σ w_i P_i B_{i,n}(t) / Σ w_i B_{i,n}(t) on [0, 1].

use smallvec::{SmallVec, smallvec};

use crate::Point;
use crate::basis::Side;
use crate::curve::bezier::bezier_derivatives;
use crate::curve::nurbs::check_weights;
use crate::curve::rational::rational_derivatives;
use crate::curve::{CircleFrame, Curve, Interval};
use crate::error::{Error, Result, check_points_finite};

/// A rational Bézier curve with positive weights.
///
/// Numerator A(t) = Σ w_i P_i B_{i,n}(t) and denominator w(t) = Σ w_i B_{i,n}(t) are
/// evaluated by de Casteljau with derivatives; c^{(k)} follows by the quotient rule.
#[derive(Debug, Clone, PartialEq)]
pub struct RationalBezierCurve<const D: usize> {
    points: Vec<Point<D>>,
    weights: Vec<f64>,
    weighted: Vec<Point<D>>,
}

impl<const D: usize> RationalBezierCurve<D> {
    /// A rational Bézier curve from control points and weights (> 0, one per point).
    pub fn new(control_points: Vec<Point<D>>, weights: Vec<f64>) -> Result<Self> {
        if control_points.is_empty() {
            return Err(Error::count("control_points", "at least 1 point", 0));
        }
        check_points_finite("control_points", &control_points)?;
        check_weights(&weights, control_points.len())?;
        let weighted = control_points.iter().zip(&weights).map(|(p, w)| p * *w).collect();
        Ok(RationalBezierCurve { points: control_points, weights, weighted })
    }

    /// The conic arc from `p0` to `p2` with tangent-intersection point `p1` and middle
    /// weight `w` (ellipse for w < 1, parabola for w = 1, hyperbola for w > 1).
    pub fn conic(p0: Point<D>, p1: Point<D>, p2: Point<D>, w: f64) -> Result<Self> {
        Self::new(vec![p0, p1, p2], vec![1.0, w, 1.0])
    }

    /// The exact circular arc of `frame` from angle `start` over `sweep` radians
    /// (0 < |sweep| < π): a quadratic with middle weight cos(sweep/2) whose middle control
    /// point is where the end tangents meet.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::{CircleFrame, Curve, RationalBezierCurve};
    /// // A quarter of the unit circle: every point is at distance 1 from the centre.
    /// let frame = CircleFrame::in_xy_plane(Point::<2>::zeros(), 1.0);
    /// let arc = RationalBezierCurve::circular_arc(&frame, 0.0, std::f64::consts::FRAC_PI_2).unwrap();
    /// assert!((arc.point(0.37).norm() - 1.0).abs() < 1e-15);
    /// assert!((arc.point(1.0) - Point::<2>::new(0.0, 1.0)).norm() < 1e-15);
    /// ```
    pub fn circular_arc(frame: &CircleFrame<D>, start: f64, sweep: f64) -> Result<Self> {
        if !(sweep.abs() > 0.0 && sweep.abs() < std::f64::consts::PI) {
            return Err(Error::invalid("sweep", format!("must satisfy 0 < |sweep| < π, got {sweep}")));
        }
        frame.check()?;
        let p1 = frame.point(start) + frame.unit_tangent(start) * (frame.radius * (sweep / 2.0).tan());
        Self::conic(frame.point(start), p1, frame.point(start + sweep), (sweep / 2.0).cos())
    }

    /// The control points.
    pub fn control_points(&self) -> &[Point<D>] {
        &self.points
    }
    /// The weights.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }
    /// The degree n.
    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }
}

impl<const D: usize> Curve<D> for RationalBezierCurve<D> {
    crate::curve::control_box::control_point_box!("a rational Bézier curve (weights > 0)");
    fn domain(&self) -> Interval {
        Interval::new(0.0, 1.0)
    }
    fn eval_side(&self, t: f64, _side: Side, out: &mut [Point<D>]) {
        let t = t.clamp(0.0, 1.0);
        let mut w: SmallVec<[f64; 8]> = smallvec![0.0; out.len()];
        bezier_derivatives(&self.weighted, t, out);
        bezier_derivatives(&self.weights, t, &mut w);
        rational_derivatives(out, &w);
    }
}
