//! B-spline curves of any degree: c(t) = Σ_i N_{i,p}(t) P_i on [t_p, t_n].

use smallvec::{SmallVec, smallvec};

use crate::Point;
use crate::basis::bspline_basis::INLINE;
use crate::basis::{KnotVector, Side, advance_span, basis_derivatives, basis_functions, find_span};
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
}

impl<const D: usize> BSplineCurve<D> {
    /// A B-spline from degree, n + p + 1 knots and n control points (open: clamped or not).
    pub fn new(degree: usize, knots: Vec<f64>, control_points: Vec<Point<D>>) -> Result<Self> {
        check_points_finite("control_points", &control_points)?;
        let knots = KnotVector::for_spline(knots, degree, control_points.len())?;
        Ok(BSplineCurve { degree, knots, control_points, periodic: false, unrolled: None })
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
        Ok(BSplineCurve { degree, knots, control_points, periodic: true, unrolled: Some((ext, pts)) })
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

    /// Maps a parameter into the domain: clamped (open) or wrapped (periodic).
    #[inline]
    pub(crate) fn normalise(&self, t: f64, side: Side) -> f64 {
        let d = self.domain();
        if self.periodic { d.wrap_periodic(t, side) } else { d.clamp(t) }
    }

    /// Span index and basis derivatives `ders[k*(p+1)+r]` for k = 0 … order at `t`
    /// (already in the domain), on the evaluation data.
    #[inline]
    pub(crate) fn basis_at(&self, t: f64, side: Side, order: usize, ders: &mut SmallVec<[f64; 4 * INLINE]>) -> usize {
        let (knots, pts) = self.evaluation_data();
        let p = self.degree;
        let span = find_span(knots, p, pts.len(), t, side);
        ders.resize((order + 1) * (p + 1), 0.0);
        if order == 0 {
            basis_functions(knots, p, span, t, ders);
        } else {
            basis_derivatives(knots, p, span, t, order, ders);
        }
        span
    }
}

/// out[k] = Σ_r ders[k][r] · pts[span − p + r].
#[inline]
fn combine<const D: usize>(pts: &[Point<D>], p: usize, span: usize, ders: &[f64], out: &mut [Point<D>]) {
    let w = p + 1;
    let base = &pts[span - p..=span];
    for (k, o) in out.iter_mut().enumerate() {
        if k > p {
            *o = Point::<D>::zeros();
            continue;
        }
        let row = &ders[k * w..(k + 1) * w];
        let mut acc = Point::<D>::zeros();
        for (b, q) in row.iter().zip(base) {
            acc += q * *b;
        }
        *o = acc;
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
        let order = out.len().saturating_sub(1);
        let mut ders: SmallVec<[f64; 4 * INLINE]> = SmallVec::new();
        let span = self.basis_at(t, side, order.min(self.degree), &mut ders);
        combine(self.evaluation_data().1, self.degree, span, &ders, out);
    }

    fn eval_many(&self, params: &[f64], order: usize, out: &mut [Point<D>]) {
        let (knots, pts) = self.evaluation_data();
        let p = self.degree;
        let n = pts.len();
        let w = order + 1;
        let o = order.min(p);
        let mut ders: SmallVec<[f64; 4 * INLINE]> = smallvec![0.0; (o + 1) * (p + 1)];
        let mut span = p;
        for (i, &t) in params.iter().enumerate() {
            let t = self.normalise(t, Side::Right);
            span = advance_span(knots, p, n, span, t);
            if o == 0 {
                basis_functions(knots, p, span, t, &mut ders);
            } else {
                basis_derivatives(knots, p, span, t, o, &mut ders);
            }
            combine(pts, p, span, &ders, &mut out[i * w..(i + 1) * w]);
        }
    }

    fn breakpoints(&self) -> Vec<f64> {
        let (k, pts) = self.evaluation_data();
        KnotVector::new(k.to_vec()).expect("valid").breakpoints(self.degree, pts.len())
    }
}
