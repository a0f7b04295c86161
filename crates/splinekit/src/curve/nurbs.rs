//! NURBS curves: C(t) = Σ N_{i,p}(t) w_i P_i / Σ N_{i,p}(t) w_i.

use smallvec::{SmallVec, smallvec};

use crate::Point;
use crate::basis::Side;
use crate::curve::bezier_spans::BezierSpans;
use crate::curve::rational::rational_derivatives;
use crate::curve::span_kernel::eval_on_span;
use crate::curve::{BSplineCurve, CircleFrame, Curve};
use crate::error::{Error, Result, check_finite};
use crate::ops::homogeneous::Homogeneous;
use crate::tolerance::ANGLE_SLACK;

/// A non-uniform rational B-spline curve: a [`BSplineCurve`] whose control points carry
/// positive weights. Clamped, unclamped and periodic knot vectors work as for B-splines.
///
/// Internally the weighted points w_i P_i form a B-spline A(t) and the weights a scalar
/// B-spline w(t) on the same basis; derivatives of any order follow from
/// [`rational_derivatives`].
#[derive(Debug, Clone, PartialEq)]
pub struct NurbsCurve<const D: usize> {
    weighted: BSplineCurve<D>,
    points: Vec<Point<D>>,
    weights: Vec<f64>,
    /// (w_i P_i, w_i) in evaluation order (unrolled for periodic curves).
    homogeneous: Vec<Homogeneous<D>>,
    /// Bézier form of the homogeneous spline per span (degrees 1 … 7).
    spans: Option<BezierSpans<Homogeneous<D>>>,
}

impl<const D: usize> NurbsCurve<D> {
    /// A NURBS curve from degree, knots, control points and weights (all > 0).
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::{Curve, NurbsCurve};
    /// // A quarter of the unit circle: the middle weight √2/2 makes every point lie on it.
    /// let p = |x, y| Point::<2>::new(x, y);
    /// let w = std::f64::consts::FRAC_1_SQRT_2;
    /// let arc = NurbsCurve::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0], vec![p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)], vec![1.0, w, 1.0])
    ///     .unwrap();
    /// for i in 0..=10 {
    ///     assert!((arc.point(i as f64 / 10.0).norm() - 1.0).abs() < 1e-15);
    /// }
    /// ```
    pub fn new(degree: usize, knots: Vec<f64>, control_points: Vec<Point<D>>, weights: Vec<f64>) -> Result<Self> {
        Self::build(degree, knots, control_points, weights, false)
    }

    /// A periodic (closed) NURBS curve; knots as for [`BSplineCurve::new_periodic`].
    pub fn new_periodic(
        degree: usize,
        knots: Vec<f64>,
        control_points: Vec<Point<D>>,
        weights: Vec<f64>,
    ) -> Result<Self> {
        Self::build(degree, knots, control_points, weights, true)
    }

    fn build(degree: usize, knots: Vec<f64>, points: Vec<Point<D>>, weights: Vec<f64>, periodic: bool) -> Result<Self> {
        check_weights(&weights, points.len())?;
        let weighted_pts: Vec<Point<D>> = points.iter().zip(&weights).map(|(p, w)| p * *w).collect();
        let weighted = if periodic {
            BSplineCurve::new_periodic(degree, knots, weighted_pts)?
        } else {
            BSplineCurve::new(degree, knots, weighted_pts)?
        };
        let n = points.len();
        let count = if periodic { n + degree } else { n };
        let homogeneous: Vec<Homogeneous<D>> =
            (0..count).map(|i| Homogeneous::lift(&points[i % n], weights[i % n])).collect();
        let spans = BezierSpans::new(
            weighted.evaluation_data().0,
            weighted.reciprocal_knot_differences(),
            &homogeneous,
            degree,
        );
        Ok(NurbsCurve { weighted, points, weights, homogeneous, spans })
    }

    /// The exact full circle: 9 control points, degree 2, weights 1, √2/2 alternating,
    /// knots {0,0,0,¼,¼,½,½,¾,¾,1,1,1}. The parametrisation is not by arc length.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::{CircleFrame, Curve, NurbsCurve};
    /// let frame = CircleFrame::in_xy_plane(Point::<2>::new(1.0, 1.0), 2.0);
    /// let c = NurbsCurve::circle(&frame).unwrap();
    /// for i in 0..=16 {
    ///     let p = c.point(i as f64 / 16.0);
    ///     assert!(((p - frame.center).norm() - 2.0).abs() < 1e-14);
    /// }
    /// ```
    pub fn circle(frame: &CircleFrame<D>) -> Result<Self> {
        Self::arc(frame, 0.0, 2.0 * std::f64::consts::PI)
    }

    /// The exact circular arc of `frame` from angle `start` to `end` (radians,
    /// |end − start| ≤ 2π), using one rational quadratic segment per quarter turn or less
    /// (NURBS Book A7.1); the middle control point of a segment of sweep θ has weight
    /// cos(θ/2).
    pub fn arc(frame: &CircleFrame<D>, start: f64, end: f64) -> Result<Self> {
        frame.check()?;
        let radius = frame.radius;
        let sweep = end - start;
        if !(sweep.is_finite() && sweep.abs() > 0.0 && sweep.abs() <= 2.0 * std::f64::consts::PI + ANGLE_SLACK) {
            return Err(Error::invalid("angle", format!("sweep must be in (0, 2π], got {sweep}")));
        }
        let segments = ((sweep.abs() / (std::f64::consts::FRAC_PI_2)) - ANGLE_SLACK).ceil().max(1.0) as usize;
        let dtheta = sweep / segments as f64;
        let w1 = (dtheta / 2.0).cos();
        let (at, tangent) = (|a| frame.point(a), |a| frame.unit_tangent(a));
        let mut pts = vec![at(start)];
        let mut ws = vec![1.0];
        let mut knots = vec![0.0; 3];
        for s in 0..segments {
            let a0 = start + dtheta * s as f64;
            let a1 = a0 + dtheta;
            // Intersection of the end tangents: at(a0) + r tan(θ/2) T(a0).
            let p1 = at(a0) + tangent(a0) * (radius * (dtheta / 2.0).tan());
            pts.push(p1);
            ws.push(w1);
            pts.push(at(a1));
            ws.push(1.0);
            if s + 1 < segments {
                let k = (s + 1) as f64 / segments as f64;
                knots.push(k);
                knots.push(k);
            }
        }
        knots.extend([1.0; 3]);
        Self::new(2, knots, pts, ws)
    }

    /// The degree p.
    pub fn degree(&self) -> usize {
        self.weighted.degree()
    }
    /// The knots as given.
    pub fn knots(&self) -> &[f64] {
        self.weighted.knots()
    }
    /// The control points (not weighted).
    pub fn control_points(&self) -> &[Point<D>] {
        &self.points
    }
    /// The weights.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }
    /// Whether the curve is periodic.
    pub fn is_periodic(&self) -> bool {
        self.weighted.is_periodic()
    }
    /// The B-spline of weighted points w_i P_i (the numerator A(t)).
    pub fn weighted_curve(&self) -> &BSplineCurve<D> {
        &self.weighted
    }

    /// The same curve with every control point mapped by `f` (weights kept). Affine maps
    /// give the mapped curve exactly.
    pub fn map_points(&self, f: impl Fn(&Point<D>) -> Point<D>) -> Self {
        let pts = self.points.iter().map(f).collect();
        Self::build(self.degree(), self.knots().to_vec(), pts, self.weights.clone(), self.is_periodic())
            .expect("same knots and weights")
    }
}

pub(crate) fn check_weights(weights: &[f64], n: usize) -> Result<()> {
    if weights.len() != n {
        return Err(Error::count("weights", format!("{n} values, one per control point"), weights.len()));
    }
    check_finite("weights", weights)?;
    if let Some((i, w)) = weights.iter().enumerate().find(|(_, w)| **w <= 0.0) {
        return Err(Error::invalid("weights", format!("weight {i} is {w}, but weights must be > 0")));
    }
    Ok(())
}

impl<const D: usize> Curve<D> for NurbsCurve<D> {
    crate::curve::control_box::control_point_box!("a NURBS curve (weights > 0)");
    crate::curve::bspline::spline_curve_knots!(weighted);
    fn eval_side(&self, t: f64, side: Side, out: &mut [Point<D>]) {
        let (t, span) = self.weighted.locate(t, side);
        let knots = self.weighted.evaluation_data().0;
        let mut h: SmallVec<[Homogeneous<D>; 8]> = smallvec![Homogeneous::lift(&Point::<D>::zeros(), 0.0); out.len()];
        match &self.spans {
            Some(b) => b.eval(span, t, &mut h),
            None => eval_on_span(
                knots,
                self.weighted.reciprocal_knot_differences(),
                &self.homogeneous,
                self.degree(),
                span,
                t,
                &mut h,
            ),
        }
        let mut w: SmallVec<[f64; 8]> = smallvec![0.0; out.len()];
        for (k, hk) in h.iter().enumerate() {
            out[k] = hk.weighted;
            w[k] = hk.weight;
        }
        rational_derivatives(out, &w);
    }
}
