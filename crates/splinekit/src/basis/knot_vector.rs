//! Knot vectors: validation, span search and common constructions.

use crate::Interval;
use crate::error::{Error, Result, check_finite};

/// Which one-sided limit to take where a curve is evaluated exactly at a knot.
///
/// At a knot of multiplicity m the curve is only C^{p−m}; `Right` uses the span that starts
/// at the knot (the convention of Cox–de Boor with half-open intervals `[t_i, t_{i+1})`),
/// `Left` the span that ends there. At the end of the domain `Right` falls back to the last
/// span, at the start `Left` to the first.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Side {
    /// The limit from below, t → t_k⁻.
    Left,
    /// The limit from above, t → t_k⁺ (the default).
    #[default]
    Right,
}

/// A non-decreasing sequence of finite knots t_0 ≤ t_1 ≤ … ≤ t_{m−1}.
#[derive(Debug, Clone, PartialEq)]
pub struct KnotVector {
    knots: Vec<f64>,
}

impl KnotVector {
    /// Validates finiteness and monotonicity (the field is named `knots` in errors).
    pub fn new(knots: Vec<f64>) -> Result<Self> {
        check_finite("knots", &knots)?;
        if knots.len() < 2 {
            return Err(Error::count("knots", "at least 2 values", knots.len()));
        }
        for i in 1..knots.len() {
            if knots[i] < knots[i - 1] {
                return Err(Error::invalid(
                    "knots",
                    format!(
                        "must be non-decreasing, but knot {} ({}) < knot {} ({})",
                        i,
                        knots[i],
                        i - 1,
                        knots[i - 1]
                    ),
                ));
            }
        }
        Ok(KnotVector { knots })
    }

    /// Validates the knot vector for a B-spline of `degree` with `n` control points:
    /// n + p + 1 knots, no knot of multiplicity above p + 1, and a non-empty domain
    /// `[t_p, t_n]`.
    pub fn for_spline(knots: Vec<f64>, degree: usize, n: usize) -> Result<Self> {
        if n < degree + 1 {
            return Err(Error::invalid(
                "control_points",
                format!("degree {degree} needs at least {} control points, got {n}", degree + 1),
            ));
        }
        if knots.len() != n + degree + 1 {
            return Err(Error::count(
                "knots",
                format!("{} values for {n} control points of degree {degree}", n + degree + 1),
                knots.len(),
            ));
        }
        let kv = KnotVector::new(knots)?;
        let k = &kv.knots;
        let mut i = 0;
        while i < k.len() {
            let mut j = i;
            while j + 1 < k.len() && k[j + 1] == k[i] {
                j += 1;
            }
            let m = j - i + 1;
            if m > degree + 1 {
                return Err(Error::invalid(
                    "knots",
                    format!("knot {} has multiplicity {m}, more than degree + 1 = {}", k[i], degree + 1),
                ));
            }
            i = j + 1;
        }
        if k[degree] >= k[n] {
            return Err(Error::invalid(
                "knots",
                format!("the domain [t_{degree}, t_{n}] = [{}, {}] is empty", k[degree], k[n]),
            ));
        }
        Ok(kv)
    }

    /// Clamped (open) uniform knots for `n` control points of `degree` on `domain`:
    /// p + 1 copies of each end and n − p − 1 uniform interior knots.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Interval;
    /// use splinekit::basis::KnotVector;
    /// let k = KnotVector::clamped_uniform(2, 5, Interval::new(0.0, 3.0)).unwrap();
    /// assert_eq!(k.as_slice(), &[0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0]);
    /// ```
    pub fn clamped_uniform(degree: usize, n: usize, domain: Interval) -> Result<Self> {
        let Interval { start, end } = domain;
        if n < degree + 1 {
            return Err(Error::invalid(
                "control_points",
                format!("degree {degree} needs at least {} control points, got {n}", degree + 1),
            ));
        }
        check_interval(domain)?;
        let segments = n - degree;
        let mut knots = Vec::with_capacity(n + degree + 1);
        knots.extend(std::iter::repeat_n(start, degree + 1));
        for i in 1..segments {
            knots.push(start + (end - start) * i as f64 / segments as f64);
        }
        knots.extend(std::iter::repeat_n(end, degree + 1));
        Ok(KnotVector { knots })
    }

    /// Uniform, unclamped knots t_i = start + i·h, i = 0 … count − 1.
    pub fn uniform(count: usize, start: f64, step: f64) -> Result<Self> {
        if !(step > 0.0 && step.is_finite() && start.is_finite()) {
            return Err(Error::invalid("knots", format!("step must be positive and finite, got {step}")));
        }
        KnotVector::new((0..count).map(|i| start + step * i as f64).collect())
    }

    /// The knots.
    #[inline]
    pub fn as_slice(&self) -> &[f64] {
        &self.knots
    }

    /// Number of knots.
    #[inline]
    pub fn len(&self) -> usize {
        self.knots.len()
    }

    /// Always false: a knot vector has at least two knots.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.knots.is_empty()
    }

    /// Consumes the vector, returning the knots.
    pub fn into_vec(self) -> Vec<f64> {
        self.knots
    }

    /// Multiplicity of the value `t` among the knots (exact comparison).
    pub fn multiplicity(&self, t: f64) -> usize {
        self.knots.iter().filter(|&&k| k == t).count()
    }

    /// Distinct knot values in `[t_p, t_n]` (the breakpoints of the spline's domain).
    pub fn breakpoints(&self, degree: usize, n: usize) -> Vec<f64> {
        let mut out: Vec<f64> = Vec::new();
        for &k in &self.knots[degree..=n] {
            if out.last() != Some(&k) {
                out.push(k);
            }
        }
        out
    }

    /// The knot span index i ∈ [p, n − 1] with t_i ≤ t < t_{i+1} (`Side::Right`) or
    /// t_i < t ≤ t_{i+1} (`Side::Left`); `t` is clamped to the domain `[t_p, t_n]`.
    /// Binary search, O(log n).
    #[inline]
    pub fn span(&self, degree: usize, n: usize, t: f64, side: Side) -> usize {
        find_span(&self.knots, degree, n, t, side)
    }
}

/// Span search on a raw knot slice; see [`KnotVector::span`].
#[inline]
pub fn find_span(knots: &[f64], degree: usize, n: usize, t: f64, side: Side) -> usize {
    let interior = &knots[degree + 1..n];
    let mut span = degree
        + match side {
            Side::Right => interior.partition_point(|&k| k <= t),
            Side::Left => interior.partition_point(|&k| k < t),
        };
    // The search lands on an empty span only at an end of the domain whose knot is repeated
    // inside [t_p, t_n] (unclamped knots: t_{n−1} = t_n, or t_p = t_{p+1}); the limit there
    // is the last (first) non-empty span's.
    match side {
        Side::Right => {
            while span > degree && knots[span] >= knots[span + 1] {
                span -= 1;
            }
        }
        Side::Left => {
            while span + 1 < n && knots[span] >= knots[span + 1] {
                span += 1;
            }
        }
    }
    span
}

/// Advances a span found for an earlier parameter to the span of `t` (sorted batches);
/// falls back to binary search when `t` moved backwards.
#[inline]
pub fn advance_span(knots: &[f64], degree: usize, n: usize, mut span: usize, t: f64) -> usize {
    if t < knots[span] && span > degree {
        return find_span(knots, degree, n, t, Side::Right);
    }
    while span + 1 < n && knots[span + 1] <= t {
        span += 1;
    }
    // At the end of the domain the last span may be empty (t_{n−1} = t_n): step back to
    // the last non-empty one, as `find_span` does.
    while span > degree && knots[span] >= knots[span + 1] {
        span -= 1;
    }
    span
}

fn check_interval(Interval { start, end }: Interval) -> Result<()> {
    if !(start.is_finite() && end.is_finite() && start < end) {
        return Err(Error::invalid("domain", format!("expected finite start < end, got [{start}, {end}]")));
    }
    Ok(())
}
