//! One parameter direction of a tensor-product spline: degree, knots, periodic unrolling
//! and span search.

use crate::basis::{KnotVector, Side, advance_span, advance_span_side, find_span};
use crate::curve::Interval;
use crate::curve::span_kernel::ReciprocalKnotDifferences;
use crate::error::{Error, Result};
use crate::tolerance::PARAMETER_RELATIVE;

/// The knot data of one parameter direction of a spline: of a B-spline curve, or of the
/// u or v direction of a spline surface.
///
/// Periodic directions follow [`crate::curve::BSplineCurve::new_periodic`]: n control
/// points and n + p + 1 knots repeating their spacing every n knots; evaluation uses the
/// unrolled n + p coefficients and n + 2p + 1 knots.
#[derive(Debug, Clone, PartialEq)]
pub struct SplineAxis {
    degree: usize,
    knots: Vec<f64>,
    count: usize,
    periodic: bool,
    eval_knots: Vec<f64>,
    inv: ReciprocalKnotDifferences,
    uniform: Option<(f64, f64)>,
}

impl SplineAxis {
    /// Validates `knots` for `count` control points of `degree`; `field` names the knot
    /// field in errors (`knots_u`, `knots_v`).
    pub fn new(degree: usize, knots: Vec<f64>, count: usize, periodic: bool, field: &str) -> Result<Self> {
        let rename = |e: Error| match e {
            Error::Count { expected, got, .. } => Error::Count { field: field.to_string(), expected, got },
            Error::Invalid { field: f, message } if f == "knots" => {
                Error::Invalid { field: field.to_string(), message }
            }
            Error::NotFinite { index, value, .. } => Error::NotFinite { field: field.to_string(), index, value },
            other => other,
        };
        let kv = KnotVector::for_spline(knots, degree, count).map_err(rename)?;
        let knots = kv.into_vec();
        let p = degree;
        let eval_knots = if periodic {
            let n = count;
            let period = knots[n + p] - knots[p];
            let scale = knots[n + p].abs().max(knots[0].abs()).max(period);
            for j in 0..=p {
                let d = knots[j + n] - knots[j];
                if (d - period).abs() > PARAMETER_RELATIVE * scale {
                    return Err(Error::invalid(
                        field,
                        format!(
                            "a periodic knot vector must repeat its spacing every {n} knots: t_{} − t_{j} = {d}, but the period is {period}",
                            j + n
                        ),
                    ));
                }
            }
            let mut ext = knots.clone();
            for i in n + p + 1..n + 2 * p + 1 {
                let v = ext[i - n] + period;
                ext.push(v);
            }
            ext
        } else {
            knots.clone()
        };
        let n_eval = if periodic { count + p } else { count };
        let inv = ReciprocalKnotDifferences::new(&eval_knots, p);
        let h = (eval_knots[n_eval] - eval_knots[p]) / (n_eval - p) as f64;
        let uniform = (p..n_eval)
            .all(|i| ((eval_knots[i + 1] - eval_knots[i]) - h).abs() <= PARAMETER_RELATIVE * h)
            .then(|| (eval_knots[p], 1.0 / h));
        Ok(SplineAxis { degree, knots, count, periodic, eval_knots, inv, uniform })
    }

    /// Degree p.
    pub fn degree(&self) -> usize {
        self.degree
    }
    /// The knots as given.
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }
    /// Number of control points n in this direction.
    pub fn count(&self) -> usize {
        self.count
    }
    /// Number of coefficients used for evaluation (n + p when periodic).
    pub fn eval_count(&self) -> usize {
        if self.periodic { self.count + self.degree } else { self.count }
    }
    /// Whether the direction is periodic.
    pub fn is_periodic(&self) -> bool {
        self.periodic
    }
    /// Knots used for evaluation.
    pub fn eval_knots(&self) -> &[f64] {
        &self.eval_knots
    }
    /// Reciprocal knot differences of the evaluation knots.
    pub fn reciprocals(&self) -> &ReciprocalKnotDifferences {
        &self.inv
    }
    /// The parameter domain.
    pub fn domain(&self) -> Interval {
        Interval::new(self.eval_knots[self.degree], self.eval_knots[self.eval_count()])
    }
    /// Clamps (open) or wraps (periodic) a parameter into the domain.
    #[inline]
    pub fn normalise(&self, t: f64) -> f64 {
        self.normalise_side(t, Side::Right)
    }
    /// As [`SplineAxis::normalise`]; on a periodic axis the left limit at the start is
    /// taken at the end of the domain and the right limit at the end at its start.
    #[inline]
    pub fn normalise_side(&self, t: f64, side: Side) -> f64 {
        let d = self.domain();
        if self.periodic { d.wrap_periodic(t, side) } else { d.clamp(t) }
    }
    /// The span s with t_s ≤ t < t_{s+1} (t in the domain).
    #[inline]
    pub fn span(&self, t: f64) -> usize {
        self.span_side(t, Side::Right)
    }
    /// The span s ∈ [p, N − 1] of `t` (in the domain): t_s ≤ t < t_{s+1} (`Right`) or
    /// t_s < t ≤ t_{s+1} (`Left`). O(1) for uniform knots, binary search otherwise.
    #[inline]
    pub fn span_side(&self, t: f64, side: Side) -> usize {
        let (p, n) = (self.degree, self.eval_count());
        match self.uniform {
            Some(_) => advance_span_side(&self.eval_knots, p, n, self.uniform_estimate(t), t, side),
            None => find_span(&self.eval_knots, p, n, t, side),
        }
    }
    /// The span of `t` (right limit) searched from `hint`, the span of an earlier parameter
    /// of a batch: for uniform knots from the direct estimate p + ⌊(t − t_p)/h⌋ instead
    /// (then O(1)), otherwise by galloping from the hint ([`advance_span`]), O(1) for sorted
    /// batches and O(log n) in any order. The estimate is only a starting point: the span
    /// returned satisfies t_s ≤ t < t_{s+1} by exact comparison with the knots.
    #[inline]
    pub fn span_from(&self, hint: usize, t: f64) -> usize {
        let hint = if self.uniform.is_some() { self.uniform_estimate(t) } else { hint };
        advance_span(&self.eval_knots, self.degree, self.eval_count(), hint, t)
    }
    /// Whether the knots of the domain are uniform (to [`PARAMETER_RELATIVE`]), detected
    /// once at construction; spans are then located by arithmetic.
    pub fn is_uniform(&self) -> bool {
        self.uniform.is_some()
    }
    /// p + ⌊(t − t_p)/h⌋ clamped to [p, N − 1] for uniform knots of spacing h (p otherwise).
    #[inline(always)]
    fn uniform_estimate(&self, t: f64) -> usize {
        let (p, n) = (self.degree, self.eval_count());
        match self.uniform {
            // `as usize` saturates: NaN and negative values give 0.
            Some((a, inv_h)) => p + ((t - a) * inv_h).min((n - 1 - p) as f64) as usize,
            None => p,
        }
    }
    /// Distinct knots of the domain, both ends included.
    pub fn breakpoints(&self) -> Vec<f64> {
        let mut out: Vec<f64> = self.eval_knots[self.degree..=self.eval_count()].to_vec();
        out.dedup();
        out
    }
    /// Index of the given control point for evaluation coefficient `i`.
    #[inline]
    pub fn wrap_index(&self, i: usize) -> usize {
        i % self.count
    }
}
