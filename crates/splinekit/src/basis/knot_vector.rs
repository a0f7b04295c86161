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
    let span = degree
        + match side {
            Side::Right => interior.partition_point(|&k| k <= t),
            Side::Left => interior.partition_point(|&k| k < t),
        };
    non_empty_span(knots, degree, n, span, side)
}

/// The search lands on an empty span only at an end of the domain whose knot is repeated
/// inside [t_p, t_n] (unclamped knots: t_{n−1} = t_n for the right limit, t_p = t_{p+1}
/// for the left); the limit there is the last (first) non-empty span's. Elsewhere the
/// span is returned unchanged after one comparison.
#[inline(always)]
fn non_empty_span(knots: &[f64], degree: usize, n: usize, mut span: usize, side: Side) -> usize {
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

/// The span of `t` searched from a `hint` (the span of an earlier parameter, or an estimate):
/// the same index as [`find_span`] with `Side::Right`, s = max{i ∈ [p, n − 1] : t_i ≤ t}
/// (p when t < t_{p+1}), found by galloping (exponential) search.
///
/// From the hint the search steps 1, 2, 4, … knots towards `t` until it brackets it, then
/// bisects the bracket: O(log d) comparisons for a span d knots away, so a sorted batch
/// (d = 0 or 1) costs one or two comparisons and a random order O(log n) — never a walk.
///
/// # Examples
///
/// ```
/// use splinekit::basis::{Side, advance_span, find_span};
/// let k = [0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 3.0, 4.0, 5.0, 5.0, 5.0];
/// for hint in 2..8 {
///     for t in [0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 4.5, 5.0] {
///         assert_eq!(advance_span(&k, 2, 8, hint, t), find_span(&k, 2, 8, t, Side::Right));
///     }
/// }
/// ```
#[inline]
pub fn advance_span(knots: &[f64], degree: usize, n: usize, span: usize, t: f64) -> usize {
    let span = gallop_span(knots, degree, n, span, |k| k <= t);
    non_empty_span(knots, degree, n, span, Side::Right)
}

/// [`advance_span`] for either side: the index [`find_span`] gives for `side`, searched
/// from `hint` by galloping.
#[inline]
pub fn advance_span_side(knots: &[f64], degree: usize, n: usize, hint: usize, t: f64, side: Side) -> usize {
    let span = match side {
        Side::Right => gallop_span(knots, degree, n, hint, |k| k <= t),
        Side::Left => gallop_span(knots, degree, n, hint, |k| k < t),
    };
    non_empty_span(knots, degree, n, span, side)
}

/// The galloping search of [`advance_span`] for a predicate `below` that holds for a
/// prefix of the knots (k ≤ t for the right limit, k < t for the left): returns
/// max{i ∈ [p, n − 1] : below(t_i)}, or p when there is none.
#[inline(always)]
fn gallop_span(knots: &[f64], degree: usize, n: usize, hint: usize, below: impl Fn(f64) -> bool) -> usize {
    let (p, last) = (degree, n - 1);
    let hint = hint.clamp(p, last);
    // Invariant: below(knots[lo]) (or lo = p) and !below(knots[hi]) (or hi = n); the answer
    // lies in [lo, hi − 1].
    let (lo, hi) = if hint == p || below(knots[hint]) {
        // Forward: the common case of a sorted batch ends at the first test.
        if hint == last || !below(knots[hint + 1]) {
            return hint;
        }
        let (mut lo, mut step) = (hint + 1, 1);
        loop {
            let probe = lo + step;
            if probe > last {
                break (lo, n);
            }
            if !below(knots[probe]) {
                break (lo, probe);
            }
            lo = probe;
            step *= 2;
        }
    } else {
        let (mut hi, mut step) = (hint, 1);
        loop {
            let probe = hi.saturating_sub(step);
            if probe <= p {
                break (p, hi);
            }
            if below(knots[probe]) {
                break (probe, hi);
            }
            hi = probe;
            step *= 2;
        }
    };
    lo + knots[lo + 1..hi].partition_point(|&k| below(k))
}

fn check_interval(Interval { start, end }: Interval) -> Result<()> {
    if !(start.is_finite() && end.is_finite() && start < end) {
        return Err(Error::invalid("domain", format!("expected finite start < end, got [{start}, {end}]")));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_stream::stream;

    /// Random knot vectors (clamped or not, with repeated interior knots) for degree p and
    /// n control points.
    fn knots(p: usize, n: usize, next: &mut impl FnMut() -> f64, clamped: bool) -> Vec<f64> {
        let mut k: Vec<f64> = Vec::with_capacity(n + p + 1);
        let mut x = 0.0;
        while k.len() < n + p + 1 {
            // Now and then a knot of multiplicity up to p.
            let m = if next() < 0.2 { 1 + (next() * p as f64) as usize } else { 1 };
            for _ in 0..m.min(n + p + 1 - k.len()) {
                k.push(x);
            }
            x += 0.1 + next();
        }
        if clamped {
            let (a, b) = (k[p], k[n]);
            for v in &mut k[..=p] {
                *v = a;
            }
            for v in &mut k[n..] {
                *v = b;
            }
        }
        k
    }

    #[test]
    fn galloping_from_any_hint_finds_the_binary_search_span() {
        let mut next = stream(0x2545F4914F6CDD1D);
        for p in 0..=6 {
            for n in [p + 1, p + 2, p + 5, 40, 300] {
                if n < p + 1 {
                    continue;
                }
                for clamped in [false, true] {
                    let k = knots(p, n, &mut next, clamped);
                    if k[p] >= k[n] {
                        continue;
                    }
                    let (a, b) = (k[0] - 1.0, k[n + p] + 1.0);
                    // Every knot exactly, random parameters, beyond both ends.
                    let mut ts: Vec<f64> = k.clone();
                    ts.extend((0..200).map(|_| a + (b - a) * next()));
                    ts.extend([f64::NEG_INFINITY, a, b, f64::INFINITY]);
                    for &t in &ts {
                        for side in [Side::Right, Side::Left] {
                            let want = find_span(&k, p, n, t, side);
                            for hint in [0, p, (p + n) / 2, n - 1, n + 5, usize::MAX / 2] {
                                assert_eq!(
                                    advance_span_side(&k, p, n, hint, t, side),
                                    want,
                                    "p {p} n {n} t {t} hint {hint}"
                                );
                            }
                            // A hint a few spans off in either direction.
                            let near = want.saturating_sub(3).max(p);
                            assert_eq!(advance_span_side(&k, p, n, near, t, side), want);
                            assert_eq!(advance_span_side(&k, p, n, (want + 3).min(n - 1), t, side), want);
                        }
                        assert_eq!(advance_span(&k, p, n, p, t), find_span(&k, p, n, t, Side::Right));
                    }
                }
            }
        }
    }

    #[test]
    fn galloping_takes_logarithmically_many_probes() {
        // A jump across 10⁵ knots costs O(log n) comparisons: count them with a predicate.
        let n = 100_000;
        let k: Vec<f64> = (0..n + 4).map(|i| i as f64).collect();
        let count = std::cell::Cell::new(0);
        let t = 99_990.5;
        let s = gallop_span(&k, 3, n, 3, |x| {
            count.set(count.get() + 1);
            x <= t
        });
        assert_eq!(s, 99_990);
        assert!(count.get() <= 2 * 17 + 2, "{} comparisons", count.get());
        count.set(0);
        let s = gallop_span(&k, 3, n, n - 1, |x| {
            count.set(count.get() + 1);
            x <= 4.5
        });
        assert_eq!(s, 4);
        assert!(count.get() <= 2 * 17 + 2, "{} comparisons", count.get());
    }
}
