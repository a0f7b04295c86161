//! One parameter direction of a tensor-product spline: degree, knots, periodic unrolling
//! and span search.

use crate::basis::{KnotVector, Side, advance_span, advance_span_side};
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
    guide: SpanGuide,
}

/// Where a span search starts: the domain [t_p, t_N] cut into B = N − p equal buckets,
/// bucket b = ⌊(t − t_p)·B/(t_N − t_p)⌋. For uniform knots bucket b is span p + b (direct
/// arithmetic); otherwise a table holds the span of each bucket's start. Either way the
/// guess is then verified exactly against the knots by [`advance_span`] (galloping), so the
/// guide affects speed only: O(1) for knots spread about evenly, O(log N) at worst.
#[derive(Debug, Clone, PartialEq)]
struct SpanGuide {
    start: f64,
    buckets_per_unit: f64,
    /// B − 1, the last bucket (the guess clamps to it after truncating).
    last_bucket: i64,
    uniform: bool,
    /// The span of the start of each bucket; empty for uniform knots (and for more than
    /// 2³² spans, where the arithmetic guess p + b is only a starting point).
    table: Vec<u32>,
}

impl SpanGuide {
    /// Detects uniform knots (every knot of the domain within h/4 of t_p + (i − p)h, so the
    /// arithmetic guess is at most one span off) or tabulates the buckets' spans.
    fn new(knots: &[f64], p: usize, n: usize) -> Self {
        let (a, b) = (knots[p], knots[n]);
        let buckets = n - p;
        let h = (b - a) / buckets as f64;
        let mut guide = SpanGuide {
            start: a,
            buckets_per_unit: 1.0 / h,
            last_bucket: (buckets - 1) as i64,
            uniform: false,
            table: Vec::new(),
        };
        guide.uniform = (p..=n).all(|i| (knots[i] - (a + (i - p) as f64 * h)).abs() <= 0.25 * h);
        if guide.uniform || u32::try_from(n).is_err() {
            return guide;
        }
        let mut span = p;
        guide.table = (0..buckets)
            .map(|k| {
                span = advance_span(knots, p, n, span, a + k as f64 * h);
                span as u32
            })
            .collect();
        guide
    }

    /// The guessed span of t (any t; NaN guesses the first span).
    #[inline(always)]
    fn guess(&self, t: f64, p: usize) -> usize {
        // The bucket truncated, then clamped into [0, B − 1] as an integer (two conditional
        // moves, shorter on the way from t to the span's data than clamping the float).
        let k = truncate((t - self.start) * self.buckets_per_unit);
        let k = if k > 0 { k } else { 0 };
        let k = (if k < self.last_bucket { k } else { self.last_bucket }) as usize;
        match self.table.get(k) {
            Some(&s) => s as usize,
            None => p + k,
        }
    }
}

/// x truncated toward zero, any integer where x is NaN or out of the i64 range (a guess
/// only: the caller clamps it). On x86-64 one `cvttsd2si`, whose answer there is i64::MIN;
/// elsewhere the saturating `as`.
#[inline(always)]
fn truncate(x: f64) -> i64 {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_mm_cvttsd_si64, _mm_set_sd};
        // SAFETY: SSE2, all these need, is part of every x86-64 target.
        #[allow(unused_unsafe)]
        unsafe {
            _mm_cvttsd_si64(_mm_set_sd(x))
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        x as i64
    }
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
        let guide = SpanGuide::new(&eval_knots, p, n_eval);
        Ok(SplineAxis { degree, knots, count, periodic, eval_knots, inv, guide })
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
    /// t_s < t ≤ t_{s+1} (`Left`). Guessed by arithmetic (uniform knots) or a bucket table,
    /// then verified against the knots by galloping search: O(1) for evenly spread knots,
    /// O(log N) at worst.
    ///
    /// Always inlined, with the check that the guess is already the span (two knot
    /// comparisons, the common case); the search behind a wrong guess is out of line. A
    /// span whose ends bracket t is the answer, and non-empty, so the check returns what the
    /// search would.
    #[inline(always)]
    pub fn span_side(&self, t: f64, side: Side) -> usize {
        self.span_side_guessed(t, t, side)
    }
    /// Any parameter brought into the domain ([`SplineAxis::normalise_side`]) and its span
    /// ([`SplineAxis::span_side`]). On an open axis the span is guessed from the parameter
    /// as given, which the guess clamps into the domain's buckets anyway: the guess need not
    /// wait for the clamp, which shortens the chain of latencies from t to the span's data
    /// (a point at random parameters, whose loop is bound by that chain: 9.3 → 8.3 ns).
    #[inline(always)]
    pub fn locate_side(&self, t: f64, side: Side) -> (f64, usize) {
        if self.periodic {
            let t = self.domain().wrap_periodic(t, side);
            (t, self.span_side_guessed(t, t, side))
        } else {
            let clamped = self.domain().clamp(t);
            (clamped, self.span_side_guessed(t, clamped, side))
        }
    }
    /// [`SplineAxis::span_side`] of `t`, the guess taken from `guess_from` (any number: the
    /// guess is only where the verification starts).
    #[inline(always)]
    fn span_side_guessed(&self, guess_from: f64, t: f64, side: Side) -> usize {
        let (p, n) = (self.degree, self.eval_count());
        let guess = self.guide.guess(guess_from, p);
        if guess >= p && guess < n {
            if let (Some(&a), Some(&b)) = (self.eval_knots.get(guess), self.eval_knots.get(guess + 1)) {
                let inside = match side {
                    Side::Right => a <= t && t < b,
                    Side::Left => a < t && t <= b,
                };
                if inside {
                    return guess;
                }
            }
        }
        self.searched_span(guess, t, side)
    }
    /// [`SplineAxis::span_side`] when the guess is not the span: galloping from it.
    #[inline(never)]
    fn searched_span(&self, guess: usize, t: f64, side: Side) -> usize {
        advance_span_side(&self.eval_knots, self.degree, self.eval_count(), guess, t, side)
    }
    /// Whether the knots of the domain are uniform (each within a quarter span of t_p + i·h),
    /// detected once at construction: spans are then guessed by arithmetic.
    pub fn is_uniform(&self) -> bool {
        self.guide.uniform
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::basis::find_span;

    #[test]
    fn guided_spans_are_the_binary_search_spans() {
        // Uniform (as i/N, inexact in floating point, for large N), clustered, and with
        // repeated knots; clamped, unclamped and periodic.
        let mut cases: Vec<(usize, Vec<f64>, usize, bool)> = Vec::new();
        for n in [4, 10, 1000, 100_000] {
            let p = 3;
            let mut k = vec![0.0; p + 1];
            k.extend((1..n - p).map(|i| i as f64 / (n - p) as f64));
            k.extend([1.0; 4]);
            cases.push((p, k, n, false));
        }
        let clustered: Vec<f64> = (0..60).map(|i| if i < 50 { i as f64 * 1e-9 } else { (i - 49) as f64 }).collect();
        cases.push((2, clustered, 57, false));
        cases.push((2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 3.0, 3.0, 3.0, 4.0, 4.0, 4.0], 9, false));
        // Unclamped, with the domain's end knots repeated inside it (t_p = t_{p+1},
        // t_{n−1} = t_n): empty first and last spans, where the inline check of the guess
        // must leave the answer to the search.
        cases.push((2, vec![0.0, 1.0, 2.0, 2.0, 3.0, 4.0, 4.0, 5.0, 6.0], 6, false));
        let gaps = [1.0, 5.0, 0.5, 2.0, 9.0, 1.0, 0.25, 3.0, 1.5];
        let periodic: Vec<f64> = (0..12).scan(0.0, |x, i| Some(std::mem::replace(x, *x + gaps[i % 9]))).collect();
        cases.push((2, periodic, 9, true));
        for (p, k, n, periodic) in cases {
            let axis = SplineAxis::new(p, k, n, periodic, "knots").unwrap();
            let (ek, ne) = (axis.eval_knots(), axis.eval_count());
            let d = axis.domain();
            let mut ts: Vec<f64> = ek[p..=ne].to_vec();
            ts.extend((0..2000).map(|i| d.start + (d.end - d.start) * ((i * 7919) % 2000) as f64 / 1999.0));
            ts.extend(ek[p..=ne].iter().map(|&x| x.next_up().min(d.end)));
            ts.extend(ek[p..=ne].iter().map(|&x| x.next_down().max(d.start)));
            // Outside the domain and not numbers: the guess stays a valid index.
            ts.extend([f64::NAN, f64::NEG_INFINITY, f64::INFINITY, d.start - 1.0, d.end + 1.0, -1e300, 1e300]);
            ts.extend([d.start - 1e-300, d.end + 1e-9, d.end * 1e17 + 1e17, -(d.end * 1e17 + 1e17)]);
            for &t in &ts {
                for side in [Side::Right, Side::Left] {
                    assert_eq!(axis.span_side(t, side), find_span(ek, p, ne, t, side), "n {n} t {t} {side:?}");
                    // Located from t as given (guessed before the clamp on open axes): the
                    // parameter normalised and that parameter's span, bit for bit.
                    let (located, span) = axis.locate_side(t, side);
                    let normalised = axis.normalise_side(t, side);
                    assert_eq!(located.to_bits(), normalised.to_bits(), "n {n} t {t} {side:?}");
                    assert_eq!(span, find_span(ek, p, ne, normalised, side), "n {n} t {t} {side:?}");
                }
            }
        }
        let uniform = SplineAxis::new(3, (0..20).map(|i| i as f64 / 3.0).collect(), 16, false, "knots").unwrap();
        assert!(uniform.is_uniform());
        let squares = SplineAxis::new(3, (0..20).map(|i| (i * i) as f64).collect(), 16, false, "knots").unwrap();
        assert!(!squares.is_uniform());
    }
}
