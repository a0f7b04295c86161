//! B-spline curves of any degree: c(t) = Σ_i N_{i,p}(t) P_i on [t_p, t_n].

use crate::Point;
use crate::basis::{KnotVector, Side, SplineAxis};
use crate::curve::bezier_spans::BezierSpans;
use crate::curve::output_slot::{Slot, zeroed};
use crate::curve::span_kernel::{ReciprocalKnotDifferences, eval_on_span};
use crate::curve::{Curve, Interval};
use crate::error::{Error, Result, check_points_finite};

/// A B-spline curve of degree p with n control points and n + p + 1 knots.
///
/// * **Clamped** (open) knot vectors repeat each end p + 1 times; the curve then starts at
///   P_0 and ends at P_{n−1}.
/// * **Unclamped** knot vectors give a curve on [t_p, t_n] that need not touch P_0.
/// * **Periodic** (closed) curves treat the control points cyclically: on the bi-infinite
///   knot sequence with t_{i+n} = t_i + T the curve is c(t) = Σ_i N_{i,p}(t) P_{i mod n},
///   periodic with period T = t_{n+p} − t_p, on the domain [t_p, t_{n+p}], and C^{p−m} at a
///   knot of multiplicity m — including the seam. The given n + p + 1 knots must repeat
///   their spacing with period n (t_{j+n} − t_j = T for j = 0 … p).
///
/// Evaluation finds the span (a guess by arithmetic for uniform knots or from a bucket table
/// otherwise, verified against the knots by galloping search: O(1) for evenly spread knots,
/// O(log n) at worst, in any order of the parameters) and evaluates the span's Bézier form (degrees 1 … 7)
/// or the p + 1 non-zero basis functions.
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineCurve<const D: usize> {
    /// Degree, knots, periodic unrolling and span search.
    axis: SplineAxis,
    control_points: Vec<Point<D>>,
    /// For periodic curves: the n + p wrapped control points used for evaluation.
    unrolled: Option<Vec<Point<D>>>,
    /// Bézier form of every span (degrees 1 … 7), the fast evaluation path.
    spans: Option<BezierSpans<Point<D>>>,
}

impl<const D: usize> BSplineCurve<D> {
    /// A B-spline from degree, n + p + 1 knots and n control points (open: clamped or not).
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::{BSplineCurve, Curve};
    /// let p = |x, y| Point::<2>::new(x, y);
    /// let points = vec![p(0.0, 0.0), p(1.0, 2.0), p(3.0, 2.0), p(4.0, 0.0)];
    /// let c = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0], points.clone()).unwrap();
    /// // Clamped: the curve starts at P0 and ends at P3; at the knot 1 it is (P1 + P2)/2.
    /// assert_eq!((c.point(0.0), c.point(2.0), c.point(1.0)), (p(0.0, 0.0), p(4.0, 0.0), p(2.0, 2.0)));
    /// assert_eq!(c.point(0.5), p(1.0, 1.5));
    /// // The knot count is checked, with the numbers in the message.
    /// let e = BSplineCurve::new(2, vec![0.0, 0.0, 1.0, 2.0, 2.0, 2.0], points).unwrap_err();
    /// assert_eq!(e.to_string(), "knots: expected 7 values for 4 control points of degree 2, got 6");
    /// ```
    pub fn new(degree: usize, knots: Vec<f64>, control_points: Vec<Point<D>>) -> Result<Self> {
        Self::build(degree, knots, control_points, false)
    }

    /// A periodic (closed) B-spline from degree, n + p + 1 knots and n control points;
    /// see the type documentation for the knot condition.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::curve::{BSplineCurve, Curve};
    /// // The uniform quadratic through the corners of the unit square, closed: at every knot it
    /// // passes through the midpoint of two neighbouring corners.
    /// let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]].map(|[x, y]| Point::<2>::new(x, y));
    /// let knots = (0..7).map(|i| (i as f64 - 2.0) / 4.0).collect();
    /// let c = BSplineCurve::new_periodic(2, knots, square.to_vec()).unwrap();
    /// assert!(c.is_closed());
    /// assert!((c.point(0.0) - Point::<2>::new(0.5, 0.0)).norm() < 1e-15);
    /// assert!((c.point(0.25) - Point::<2>::new(1.0, 0.5)).norm() < 1e-15);
    /// assert!((c.point(1.0) - c.point(0.0)).norm() < 1e-15);
    /// ```
    pub fn new_periodic(degree: usize, knots: Vec<f64>, control_points: Vec<Point<D>>) -> Result<Self> {
        Self::build(degree, knots, control_points, true)
    }

    fn build(degree: usize, knots: Vec<f64>, control_points: Vec<Point<D>>, periodic: bool) -> Result<Self> {
        check_points_finite("control_points", &control_points)?;
        let n = control_points.len();
        let axis = SplineAxis::new(degree, knots, n, periodic, "knots")?;
        let unrolled = periodic.then(|| (0..n + degree).map(|i| control_points[i % n]).collect::<Vec<_>>());
        let eval_points = unrolled.as_deref().unwrap_or(&control_points);
        let spans = BezierSpans::new(axis.eval_knots(), axis.reciprocals(), eval_points, degree);
        Ok(BSplineCurve { axis, control_points, unrolled, spans })
    }

    /// Clamped B-spline with uniform interior knots on [0, 1].
    pub fn clamped_uniform(degree: usize, control_points: Vec<Point<D>>) -> Result<Self> {
        let kv = KnotVector::clamped_uniform(degree, control_points.len(), Interval::new(0.0, 1.0))?;
        Self::new(degree, kv.into_vec(), control_points)
    }

    /// Periodic B-spline with uniform knots on [0, 1] (knot spacing 1/n).
    pub fn periodic_uniform(degree: usize, control_points: Vec<Point<D>>) -> Result<Self> {
        let n = control_points.len();
        if n == 0 {
            return Err(Error::count("control_points", "at least 1 point", 0));
        }
        let h = 1.0 / n as f64;
        let knots = (0..n + degree + 1).map(|i| (i as f64 - degree as f64) * h).collect();
        Self::new_periodic(degree, knots, control_points)
    }

    /// The degree p.
    #[inline]
    pub fn degree(&self) -> usize {
        self.axis.degree()
    }
    /// The n + p + 1 knots as given.
    #[inline]
    pub fn knots(&self) -> &[f64] {
        self.axis.knots()
    }
    /// The n control points as given (the control polygon).
    #[inline]
    pub fn control_points(&self) -> &[Point<D>] {
        &self.control_points
    }
    /// Whether the curve is periodic (closed).
    #[inline]
    pub fn is_periodic(&self) -> bool {
        self.axis.is_periodic()
    }

    /// Knots and control points used for evaluation (unrolled for periodic curves);
    /// the curve is Σ N_{i,p} Q_i over these with domain [t_p, t_{len(Q)}].
    #[inline]
    pub fn evaluation_data(&self) -> (&[f64], &[Point<D>]) {
        (self.axis.eval_knots(), self.unrolled.as_deref().unwrap_or(&self.control_points))
    }

    /// The same curve with every control point mapped by `f` (affine maps give the mapped
    /// curve exactly: B-splines are affinely invariant).
    pub fn map_points(&self, f: impl Fn(&Point<D>) -> Point<D>) -> Self {
        let pts: Vec<Point<D>> = self.control_points.iter().map(&f).collect();
        Self::build(self.degree(), self.knots().to_vec(), pts, self.is_periodic()).expect("same knots")
    }

    /// Evaluates on a known span: Bézier form when available, else the triangular kernel.
    /// Kept out of line: inlined into a caller's loop (the seven widths' derivative kernels
    /// with their runtime output count), a point with two derivatives took 29 ns at random
    /// parameters instead of 22; and [`Curve::point`], which calls it for the degrees
    /// without Bézier spans (0 and above 7), stays small enough to inline.
    #[inline(never)]
    fn eval_on(&self, span: usize, t: f64, out: &mut [Point<D>]) {
        match &self.spans {
            Some(b) => b.eval(span, t, out),
            None => {
                let (knots, pts) = self.evaluation_data();
                eval_on_span(knots, self.axis.reciprocals(), pts, self.degree(), span, t, out)
            }
        }
    }

    /// Evaluates with the triangular Cox–de Boor kernel, bypassing the Bézier spans
    /// (a reference for tests and benchmarks).
    pub fn eval_de_boor(&self, t: f64, side: Side, out: &mut [Point<D>]) {
        let (t, span) = self.locate(t, side);
        let (knots, pts) = self.evaluation_data();
        eval_on_span(knots, self.axis.reciprocals(), pts, self.degree(), span, t, out)
    }

    /// The tabulated reciprocal knot differences (shared with NURBS evaluation).
    #[inline]
    pub(crate) fn reciprocal_knot_differences(&self) -> &ReciprocalKnotDifferences {
        self.axis.reciprocals()
    }

    /// A parameter mapped into the domain (clamped when open, wrapped when periodic) and its
    /// span; see [`SplineAxis::locate_side`].
    #[inline(always)]
    pub(crate) fn locate(&self, t: f64, side: Side) -> (f64, usize) {
        self.axis.locate_side(t, side)
    }

    /// The batch by the Bézier spans into any [`Slot`]s (points, or memory not yet
    /// written): parameters clamped into the domain (wrapped when periodic), spans located
    /// by the axis in any order of the parameters.
    fn span_batch<O: Slot<Point<D>>>(
        &self,
        spans: &BezierSpans<Point<D>>,
        params: &[f64],
        order: usize,
        out: &mut [O],
    ) {
        let axis = &self.axis;
        // The domain and the kind of axis, read once for the batch.
        let (domain, periodic) = (axis.domain(), axis.is_periodic());
        let map = |t: f64| if periodic { domain.wrap_periodic(t, Side::Right) } else { domain.clamp(t) };
        let locate = |_: usize, t: f64| axis.span(t);
        let out = &mut out[..params.len() * (order + 1)];
        spans.eval_many_lanes(params, order, out, map, locate);
    }
}

/// Writes, inside an `impl Curve<D> for …` of a spline curve, the methods it takes from its
/// knots — `domain`, `is_closed` (periodic knots) and `breakpoints` — as those of the field
/// `$knots` (the `SplineAxis` of a B-spline curve, the B-spline curve a NURBS curve keeps).
macro_rules! spline_curve_knots {
    ($knots:ident) => {
        fn domain(&self) -> $crate::Interval {
            self.$knots.domain()
        }
        fn is_closed(&self) -> bool {
            self.$knots.is_periodic()
        }
        fn breakpoints(&self) -> Vec<f64> {
            self.$knots.breakpoints()
        }
    };
}
pub(crate) use spline_curve_knots;

impl<const D: usize> Curve<D> for BSplineCurve<D> {
    crate::curve::control_box::control_point_box!("a B-spline curve");
    spline_curve_knots!(axis);

    #[inline]
    fn eval_side(&self, t: f64, side: Side, out: &mut [Point<D>]) {
        let (t, span) = self.locate(t, side);
        self.eval_on(span, t, out);
    }

    /// c(t) alone: on the Bézier-span path the span's Bernstein sum without the derivative
    /// machinery of [`Curve::eval_side`] (the same value as its `out[0]`).
    ///
    /// Always inlined, with the span search and the Bernstein sum of each degree width, so
    /// that a caller's loop keeps the knots and the domain in registers and is unswitched
    /// on the degree (degrees 0 and 8+ are out of line). Left to the compiler, `point` was
    /// inlined or not depending on how many callers a binary had: 11 ns or 15 ns a point
    /// at random parameters.
    #[inline(always)]
    fn point(&self, t: f64) -> Point<D> {
        let (t, span) = self.locate(t, Side::Right);
        match &self.spans {
            Some(b) => b.point(span, t),
            None => {
                let mut out = [Point::<D>::zeros()];
                self.eval_on(span, t, &mut out);
                out[0]
            }
        }
    }

    fn eval_many(&self, params: &[f64], order: usize, out: &mut [Point<D>]) {
        if let Some(spans) = &self.spans {
            return self.span_batch(spans, params, order, out);
        }
        let w = order + 1;
        for (i, &t) in params.iter().enumerate() {
            let (t, span) = self.locate(t, Side::Right);
            self.eval_on(span, t, &mut out[i * w..(i + 1) * w]);
        }
    }

    fn eval_many_uninit(&self, params: &[f64], order: usize, out: &mut [std::mem::MaybeUninit<Point<D>>]) {
        match &self.spans {
            Some(spans) => self.span_batch(spans, params, order, out),
            None => self.eval_many(params, order, zeroed(out)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_stream::stream;

    /// Curves of degree p with n control points: clamped uniform, periodic uniform,
    /// non-uniform with repeated interior knots (clamped and unclamped), non-uniform
    /// periodic.
    fn curves(p: usize, n: usize, next: &mut impl FnMut() -> f64) -> Vec<(&'static str, BSplineCurve<3>)> {
        let pts: Vec<Point<3>> = (0..n).map(|_| Point::<3>::new(next() * 4.0 - 2.0, next(), next() * 10.0)).collect();
        let mut out = vec![("clamped uniform", BSplineCurve::clamped_uniform(p, pts.clone()).unwrap())];
        if p > 0 {
            out.push(("periodic uniform", BSplineCurve::periodic_uniform(p, pts.clone()).unwrap()));
        }
        // Interior knots with multiplicities up to p (a double knot at a third of the way).
        let mut k = vec![0.0; p + 1];
        let mut x = 0.0;
        while k.len() < n {
            x += 0.2 + next();
            let m = if k.len() == n / 3 { p.max(1) } else { 1 };
            for _ in 0..m.min(n - k.len()) {
                k.push(x);
            }
        }
        x += 0.2 + next();
        k.extend(std::iter::repeat_n(x, p + 1));
        out.push(("clamped non-uniform", BSplineCurve::new(p, k.clone(), pts.clone()).unwrap()));
        let unclamped: Vec<f64> = (0..n + p + 1).map(|i| i as f64 + 0.5 * next()).collect();
        out.push(("unclamped non-uniform", BSplineCurve::new(p, unclamped, pts.clone()).unwrap()));
        if p > 0 && n > p {
            // Periodic with spacing repeating every n knots.
            let gaps: Vec<f64> = (0..n).map(|_| 0.3 + next()).collect();
            let mut kp = vec![0.0];
            for i in 0..n + p {
                kp.push(kp[i] + gaps[i % n]);
            }
            out.push(("periodic non-uniform", BSplineCurve::new_periodic(p, kp, pts).unwrap()));
        }
        out
    }

    /// Parameter sets: sorted, reversed, random, repeated, knots and domain ends, outside.
    fn parameter_sets(c: &BSplineCurve<3>, next: &mut impl FnMut() -> f64) -> Vec<(&'static str, Vec<f64>)> {
        let d = c.domain();
        let len = d.end - d.start;
        let sorted: Vec<f64> = (0..=100).map(|i| d.start + len * i as f64 / 100.0).collect();
        let reversed: Vec<f64> = sorted.iter().rev().copied().collect();
        let random: Vec<f64> = (0..100).map(|_| d.start - 0.1 * len + 1.2 * len * next()).collect();
        let repeated: Vec<f64> = (0..20).flat_map(|_| [d.start + 0.3 * len, d.end, d.start + 0.7 * len]).collect();
        let mut knots: Vec<f64> = c.knots().to_vec();
        knots.extend([d.start, d.end, d.start - len, d.end + len]);
        let mut jumbled = knots.clone();
        jumbled.reverse();
        knots.extend(jumbled);
        // Sorted and sparser than the knots: the middle of every other span (blocks of four
        // over seven spans), then the end.
        let breaks = c.breakpoints();
        let mut sparse: Vec<f64> = breaks.windows(2).step_by(2).map(|w| 0.5 * (w[0] + w[1])).collect();
        sparse.push(d.end);
        vec![
            ("sorted", sorted),
            ("reversed", reversed),
            ("random", random),
            ("repeated", repeated),
            ("knots", knots),
            ("sparse", sparse),
        ]
    }

    /// The batch path (Bézier spans with a span cursor for degrees 1 … 7, the Cox–de Boor
    /// kernel above, uniform-knot arithmetic or galloping span search) against the plain
    /// de Boor evaluation at each parameter, degrees 0 … 12, derivative orders 0, 1 and 4.
    #[test]
    fn batches_in_any_order_match_de_boor() {
        let mut next = stream(0x9E3779B97F4A7C15);
        for p in 0..=12 {
            for n in [p + 1, 3 * p + 9] {
                for (kind, c) in curves(p, n, &mut next) {
                    let scale = c.control_points().iter().map(|q| q.norm()).fold(0.0, f64::max).max(1.0);
                    // |c⁽ᵏ⁾| ≤ Π_{j<k} 2(p − j)/h_min · max |P|: the scale of the k-th derivative.
                    let h_min = c.breakpoints().windows(2).map(|w| w[1] - w[0]).fold(f64::INFINITY, f64::min);
                    for (order_of_params, params) in parameter_sets(&c, &mut next) {
                        for order in [0, 1, 4] {
                            let w = order + 1;
                            let mut batch = vec![Point::<3>::zeros(); params.len() * w];
                            c.eval_many(&params, order, &mut batch);
                            let mut single = vec![Point::<3>::zeros(); w];
                            let mut reference = vec![Point::<3>::zeros(); w];
                            for (i, &t) in params.iter().enumerate() {
                                c.eval(t, &mut single);
                                c.eval_de_boor(t, Side::Right, &mut reference);
                                assert_eq!(c.point(t), single[0], "{kind} p {p}: point({t}) differs from eval");
                                let mut tol = 1e-13 * scale;
                                for k in 0..w {
                                    let r = reference[k];
                                    let (b, s) = (batch[i * w + k], single[k]);
                                    let what = format!("{kind} p {p} n {n} {order_of_params} t {t} order {k}");
                                    assert!(
                                        (b - r).norm() <= tol.max(1e-13 * r.norm()),
                                        "{what}: batch {b} vs de Boor {r}"
                                    );
                                    assert_eq!(b, s, "{what}: batch differs from the single evaluation");
                                    tol *= 2.0 * p.saturating_sub(k).max(1) as f64 / h_min;
                                }
                            }
                        }
                    }
                }
            }
        }
    }
}
