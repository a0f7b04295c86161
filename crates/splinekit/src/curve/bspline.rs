//! B-spline curves of any degree: c(t) = Σ_i N_{i,p}(t) P_i on [t_p, t_n].

use crate::Point;
use crate::basis::{KnotVector, Side, advance_span, find_span};
use crate::curve::bezier_spans::BezierSpans;
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
/// Evaluation finds the span by binary search (or incrementally in sorted batches) and
/// evaluates only the p + 1 non-zero basis functions and their derivatives.
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineCurve<const D: usize> {
    degree: usize,
    knots: KnotVector,
    control_points: Vec<Point<D>>,
    periodic: bool,
    /// For periodic curves: n + 2p + 1 knots and n + p wrapped control points.
    unrolled: Option<(Vec<f64>, Vec<Point<D>>)>,
    /// (t_p, 1/h) when the domain's knots are uniformly spaced: O(1) span lookup.
    uniform: Option<(f64, f64)>,
    /// Reciprocal knot differences of the evaluation knots.
    inv: ReciprocalKnotDifferences,
    /// Bézier form of every span (degrees 1 … 7), the fast evaluation path.
    spans: Option<BezierSpans<Point<D>>>,
}

/// (t_p, 1/h) if the knots t_p … t_n are equally spaced (to 1e-12 relative).
fn uniform_spacing(knots: &[f64], p: usize, n: usize) -> Option<(f64, f64)> {
    let h = (knots[n] - knots[p]) / (n - p) as f64;
    let ok = (p..n).all(|i| ((knots[i + 1] - knots[i]) - h).abs() <= 1e-12 * h);
    ok.then(|| (knots[p], 1.0 / h))
}

impl<const D: usize> BSplineCurve<D> {
    /// A B-spline from degree, n + p + 1 knots and n control points (open: clamped or not).
    pub fn new(degree: usize, knots: Vec<f64>, control_points: Vec<Point<D>>) -> Result<Self> {
        check_points_finite("control_points", &control_points)?;
        let knots = KnotVector::for_spline(knots, degree, control_points.len())?;
        let uniform = uniform_spacing(knots.as_slice(), degree, control_points.len());
        let inv = ReciprocalKnotDifferences::new(knots.as_slice(), degree);
        let spans = BezierSpans::new(knots.as_slice(), &inv, &control_points, degree);
        Ok(BSplineCurve { degree, knots, control_points, periodic: false, unrolled: None, uniform, inv, spans })
    }

    /// A periodic (closed) B-spline from degree, n + p + 1 knots and n control points;
    /// see the type documentation for the knot condition.
    pub fn new_periodic(degree: usize, knots: Vec<f64>, control_points: Vec<Point<D>>) -> Result<Self> {
        check_points_finite("control_points", &control_points)?;
        let n = control_points.len();
        let knots = KnotVector::for_spline(knots, degree, n)?;
        let k = knots.as_slice();
        let p = degree;
        let period = k[n + p] - k[p];
        let scale = k[n + p].abs().max(k[0].abs()).max(period);
        for j in 0..=p {
            let d = k[j + n] - k[j];
            if (d - period).abs() > 1e-12 * scale {
                return Err(Error::invalid(
                    "knots",
                    format!(
                        "a periodic knot vector must repeat its spacing every {n} knots: \
                         t_{} − t_{j} = {d}, but the period t_{} − t_{p} = {period}",
                        j + n,
                        n + p
                    ),
                ));
            }
        }
        let mut ext = k.to_vec();
        for i in n + p + 1..n + 2 * p + 1 {
            let v = ext[i - n] + period;
            ext.push(v);
        }
        let mut pts = control_points.clone();
        for i in 0..p {
            pts.push(control_points[i % n]);
        }
        let uniform = uniform_spacing(&ext, p, n + p);
        let inv = ReciprocalKnotDifferences::new(&ext, p);
        let spans = BezierSpans::new(&ext, &inv, &pts, p);
        Ok(BSplineCurve {
            degree,
            knots,
            control_points,
            periodic: true,
            unrolled: Some((ext, pts)),
            uniform,
            inv,
            spans,
        })
    }

    /// Clamped B-spline with uniform interior knots on [0, 1].
    pub fn clamped_uniform(degree: usize, control_points: Vec<Point<D>>) -> Result<Self> {
        let kv = KnotVector::clamped_uniform(degree, control_points.len(), 0.0, 1.0)?;
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
        self.degree
    }
    /// The n + p + 1 knots as given.
    #[inline]
    pub fn knots(&self) -> &[f64] {
        self.knots.as_slice()
    }
    /// The n control points as given (the control polygon).
    #[inline]
    pub fn control_points(&self) -> &[Point<D>] {
        &self.control_points
    }
    /// Whether the curve is periodic (closed).
    #[inline]
    pub fn is_periodic(&self) -> bool {
        self.periodic
    }

    /// Knots and control points used for evaluation (unrolled for periodic curves);
    /// the curve is Σ N_{i,p} Q_i over these with domain [t_p, t_{len(Q)}].
    #[inline]
    pub fn evaluation_data(&self) -> (&[f64], &[Point<D>]) {
        match &self.unrolled {
            Some((k, p)) => (k, p),
            None => (self.knots.as_slice(), &self.control_points),
        }
    }

    /// The same curve with every control point mapped by `f` (affine maps give the mapped
    /// curve exactly: B-splines are affinely invariant).
    pub fn map_points(&self, f: impl Fn(&Point<D>) -> Point<D>) -> Self {
        let pts: Vec<Point<D>> = self.control_points.iter().map(&f).collect();
        if self.periodic {
            Self::new_periodic(self.degree, self.knots.as_slice().to_vec(), pts).expect("same knots")
        } else {
            Self::new(self.degree, self.knots.as_slice().to_vec(), pts).expect("same knots")
        }
    }

    /// Evaluates on a known span: Bézier form when available, else the triangular kernel.
    #[inline]
    fn eval_on(&self, span: usize, t: f64, out: &mut [Point<D>]) {
        match &self.spans {
            Some(b) => b.eval(span, t, out),
            None => {
                let (knots, pts) = self.evaluation_data();
                eval_on_span(knots, &self.inv, pts, self.degree, span, t, out)
            }
        }
    }

    /// Evaluates with the triangular Cox–de Boor kernel, bypassing the Bézier spans
    /// (a reference for tests and benchmarks).
    pub fn eval_de_boor(&self, t: f64, side: Side, out: &mut [Point<D>]) {
        let t = self.normalise(t, side);
        let span = self.span_of(t, side);
        let (knots, pts) = self.evaluation_data();
        eval_on_span(knots, &self.inv, pts, self.degree, span, t, out)
    }

    /// The tabulated reciprocal knot differences (shared with NURBS evaluation).
    #[inline]
    pub(crate) fn reciprocal_knot_differences(&self) -> &ReciprocalKnotDifferences {
        &self.inv
    }

    /// Maps a parameter into the domain: clamped (open) or wrapped (periodic).
    #[inline]
    pub(crate) fn normalise(&self, t: f64, side: Side) -> f64 {
        let d = self.domain();
        if self.periodic { d.wrap_periodic(t, side) } else { d.clamp(t) }
    }

    /// The span i ∈ [p, N − 1] of `t` (already in the domain) on the evaluation data:
    /// t_i ≤ t < t_{i+1} (`Right`) or t_i < t ≤ t_{i+1} (`Left`). O(1) for uniform knots,
    /// binary search otherwise.
    #[inline]
    pub(crate) fn span_of(&self, t: f64, side: Side) -> usize {
        let (knots, pts) = self.evaluation_data();
        let (p, n) = (self.degree, pts.len());
        let Some((a, inv_h)) = self.uniform else {
            return find_span(knots, p, n, t, side);
        };
        let guess = ((t - a) * inv_h).max(0.0) as usize;
        let mut s = (p + guess).min(n - 1);
        match side {
            Side::Right => {
                while s > p && knots[s] > t {
                    s -= 1;
                }
                while s + 1 < n && knots[s + 1] <= t {
                    s += 1;
                }
            }
            Side::Left => {
                while s > p && knots[s] >= t {
                    s -= 1;
                }
                while s + 1 < n && knots[s + 1] < t {
                    s += 1;
                }
            }
        }
        s
    }
}

impl<const D: usize> Curve<D> for BSplineCurve<D> {
    fn domain(&self) -> Interval {
        let (k, pts) = self.evaluation_data();
        Interval::new(k[self.degree], k[pts.len()])
    }

    fn is_closed(&self) -> bool {
        self.periodic
    }

    #[inline]
    fn eval_side(&self, t: f64, side: Side, out: &mut [Point<D>]) {
        let t = self.normalise(t, side);
        let span = self.span_of(t, side);
        self.eval_on(span, t, out);
    }

    fn eval_many(&self, params: &[f64], order: usize, out: &mut [Point<D>]) {
        let (knots, pts) = self.evaluation_data();
        if let Some(spans) = &self.spans {
            let dom = self.domain();
            let periodic = self.periodic;
            let map = |t: f64| if periodic { dom.wrap_periodic(t, Side::Right) } else { dom.clamp(t) };
            spans.eval_many(knots, params, order, &mut out[..params.len() * (order + 1)], map);
            return;
        }
        let (p, n, w) = (self.degree, pts.len(), order + 1);
        let mut span = p;
        for (i, &t) in params.iter().enumerate() {
            let t = self.normalise(t, Side::Right);
            span = advance_span(knots, p, n, span, t);
            self.eval_on(span, t, &mut out[i * w..(i + 1) * w]);
        }
    }

    fn breakpoints(&self) -> Vec<f64> {
        let (k, pts) = self.evaluation_data();
        KnotVector::new(k.to_vec()).expect("valid").breakpoints(self.degree, pts.len())
    }
}
