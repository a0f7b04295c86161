//! Knot vectors of blending splines: one knot (centre) per local piece.
//!
//! Open: knots c₀ ≤ … ≤ c_{n−1}, domain [c₀, c_{n−1}], n − 1 intervals. Closed: the n
//! knots plus c_n = c₀ + P (P the period), domain [c₀, c_n], n intervals; local indices
//! wrap, and on the last interval local 0 is evaluated at t − P.
//!
//! Local k is centred at c_k and supported on [c_{k−1}, c_{k+1}]; on [c_k, c_{k+1}) the
//! locals k and k + 1 are blended with w = (t − c_k)/(c_{k+1} − c_k). A knot may be doubled
//! ([`BlendKnots::split`]): the zero-length interval is never active and the curve has a
//! C⁰ joint there.

use crate::basis::Side;
use crate::curve::Interval;
use crate::error::{Error, Result};

/// Largest number of local pieces along one direction.
pub const MAX_LOCALS: usize = 100_000;

/// The knots of a blending spline along one parameter direction.
#[derive(Debug, Clone, PartialEq)]
pub struct BlendKnots {
    /// c₀ … c_{n−1} (open) or c₀ … c_n with c_n = c₀ + P (closed).
    knots: Vec<f64>,
    closed: bool,
}

/// Where a parameter falls: locals `first` and `second` are blended with weight B(w) on
/// the interval [start, start + width); `second` is evaluated at t + `second_shift`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BlendSpan {
    /// The interval index k (also the first local).
    pub first: usize,
    /// The second local, k + 1 (mod n when closed).
    pub second: usize,
    /// −P when the second local is local 0 of a closed spline seen from the last interval.
    pub second_shift: f64,
    /// The wrapped or clamped parameter.
    pub t: f64,
    /// (t − c_k)/(c_{k+1} − c_k).
    pub w: f64,
    /// c_{k+1} − c_k.
    pub width: f64,
}

impl BlendKnots {
    /// n knots spaced evenly over `domain` (closed: n intervals, open: n − 1).
    pub fn uniform(domain: Interval, count: usize, closed: bool, field: &str) -> Result<Self> {
        check_count(count, closed, field)?;
        if !(domain.length() > 0.0 && domain.start.is_finite() && domain.end.is_finite()) {
            return Err(Error::invalid(
                field,
                format!("the domain [{}, {}] must be a finite, non-empty interval", domain.start, domain.end),
            ));
        }
        let intervals = if closed { count } else { count - 1 };
        let dt = domain.length() / intervals as f64;
        let mut knots: Vec<f64> = (0..=intervals).map(|k| domain.start + k as f64 * dt).collect();
        *knots.last_mut().unwrap() = domain.end;
        Ok(BlendKnots { knots, closed })
    }

    /// Explicit knots: n values for an open spline, n + 1 for a closed one (the last is
    /// c₀ + period). Non-decreasing; a knot may appear twice (a C⁰ joint) but not at the
    /// ends, and never three times.
    pub fn new(knots: Vec<f64>, closed: bool) -> Result<Self> {
        Self::new_as(knots, closed, "knots")
    }

    /// [`BlendKnots::new`] with errors naming `field` (e.g. `knots_u[2]`) instead of `knots`.
    pub fn new_as(knots: Vec<f64>, closed: bool, field: &str) -> Result<Self> {
        let count = if closed { knots.len().saturating_sub(1) } else { knots.len() };
        check_count(count, closed, field)?;
        if let Some(i) = knots.iter().position(|k| !k.is_finite()) {
            return Err(Error::invalid(format!("{field}[{i}]"), format!("must be finite, got {}", knots[i])));
        }
        for i in 1..knots.len() {
            if knots[i] < knots[i - 1] {
                return Err(Error::invalid(
                    format!("{field}[{i}]"),
                    format!("knots must not decrease: {} follows {}", knots[i], knots[i - 1]),
                ));
            }
            if i >= 2 && knots[i] == knots[i - 2] {
                return Err(Error::invalid(format!("{field}[{i}]"), format!("{} appears three times", knots[i])));
            }
        }
        let last = knots.len() - 1;
        if knots[1] == knots[0] || knots[last] == knots[last - 1] {
            return Err(Error::invalid(field, "the first and last intervals must not be empty"));
        }
        Ok(BlendKnots { knots, closed })
    }

    /// Number of local pieces n.
    pub fn count(&self) -> usize {
        if self.closed { self.knots.len() - 1 } else { self.knots.len() }
    }
    /// Whether the spline is closed in this direction.
    pub fn is_closed(&self) -> bool {
        self.closed
    }
    /// The knot values (closed: n + 1, the last being c₀ + P).
    pub fn values(&self) -> &[f64] {
        &self.knots
    }
    /// The distinct knot values in order: where the active locals change, the breakpoints
    /// of a blending spline curve or surface in this direction.
    pub(crate) fn breakpoints(&self) -> Vec<f64> {
        let mut b = self.knots.clone();
        b.dedup();
        b
    }
    /// The parameter domain.
    pub fn domain(&self) -> Interval {
        Interval::new(self.knots[0], *self.knots.last().unwrap())
    }
    /// The knot c_k of local k.
    pub fn centre(&self, k: usize) -> f64 {
        self.knots[k]
    }
    /// c_k for any integer k: closed splines continue periodically, open ones mirror the
    /// end spacing (c₋₁ = 2c₀ − c₁).
    pub fn extended(&self, k: isize) -> f64 {
        let n = self.count() as isize;
        if self.closed {
            let period = self.domain().length();
            let wraps = k.div_euclid(n);
            self.knots[k.rem_euclid(n) as usize] + wraps as f64 * period
        } else if k < 0 {
            2.0 * self.knots[0] - self.knots[(-k) as usize]
        } else if k >= n {
            let m = (2 * (n - 1) - k) as usize;
            2.0 * self.knots[n as usize - 1] - self.knots[m]
        } else {
            self.knots[k as usize]
        }
    }
    /// The support [c_{k−1}, c_{k+1}] of local k (extended past the ends).
    pub fn support(&self, k: usize) -> Interval {
        Interval::new(self.extended(k as isize - 1), self.extended(k as isize + 1))
    }

    /// The span containing `t` (clamped into an open domain, wrapped into a closed one). At
    /// a knot the left limit uses the interval that ends there.
    pub fn locate(&self, t: f64, side: Side) -> BlendSpan {
        let dom = self.domain();
        let t = if self.closed { dom.wrap_periodic(t, side) } else { dom.clamp(t) };
        let intervals = self.knots.len() - 1;
        let k = match side {
            Side::Right => self.knots.partition_point(|&c| c <= t),
            Side::Left => self.knots.partition_point(|&c| c < t),
        };
        let k = k.saturating_sub(1).min(intervals - 1);
        let n = self.count();
        let second = (k + 1) % n;
        let second_shift = if self.closed && second == 0 { -dom.length() } else { 0.0 };
        let width = self.knots[k + 1] - self.knots[k];
        BlendSpan { first: k, second, second_shift, t, w: (t - self.knots[k]) / width, width }
    }

    /// The parameter ranges where local k takes part, (c_{k−1}, c_{k+1}) clipped to the
    /// domain (split at the seam of a closed spline).
    pub fn affected_ranges(&self, k: usize) -> Vec<Interval> {
        let Interval { start: a, end: b } = self.support(k);
        let dom = self.domain();
        if !self.closed {
            return vec![Interval::new(a.max(dom.start), b.min(dom.end))];
        }
        let p = dom.length();
        if a < dom.start {
            vec![Interval::new(dom.start, b), Interval::new(a + p, dom.end)]
        } else if b > dom.end {
            vec![Interval::new(a, dom.end), Interval::new(dom.start, b - p)]
        } else {
            vec![Interval::new(a, b)]
        }
    }

    /// Inserts the knot `t` strictly inside a non-empty interval; returns its index.
    pub fn insert(&mut self, t: f64) -> Result<usize> {
        self.insert_as(t, "t")
    }

    /// [`Self::insert`], its errors naming `field` (the parameter's name where it came from).
    pub fn insert_as(&mut self, t: f64, field: &str) -> Result<usize> {
        let dom = self.domain();
        if !(t > dom.start && t < dom.end) || self.knots.contains(&t) {
            return Err(Error::invalid(
                field,
                format!(
                    "a new knot must lie strictly inside the domain [{}, {}] and not on a knot, got {t}",
                    dom.start, dom.end
                ),
            ));
        }
        if self.count() >= MAX_LOCALS {
            return Err(Error::invalid(field, format!("at most {MAX_LOCALS} local pieces")));
        }
        let k = self.knots.partition_point(|&c| c < t);
        self.knots.insert(k, t);
        Ok(k)
    }

    /// An error naming `field` unless the knots run from the start to the end of `domain`
    /// (to 10⁻¹² times max(its length, 1)): knots for locals made from a model on `domain`.
    pub fn check_spans(&self, domain: Interval, field: &str) -> Result<()> {
        let got = self.domain();
        let slack = 1e-12 * domain.length().abs().max(1.0);
        if (got.start - domain.start).abs() > slack || (got.end - domain.end).abs() > slack {
            return Err(Error::invalid(
                field,
                format!(
                    "the knots must span the model's domain [{}, {}], got [{}, {}]",
                    domain.start, domain.end, got.start, got.end
                ),
            ));
        }
        Ok(())
    }

    /// Doubles the interior knot k (a C⁰ joint); the copy gets index k + 1.
    pub fn split(&mut self, k: usize) -> Result<()> {
        let last = if self.closed { self.count() - 1 } else { self.count() - 2 };
        if k == 0 || k > last {
            return Err(Error::invalid("k", format!("only interior knots 1..={last} can be split, got {k}")));
        }
        if self.knots[k - 1] == self.knots[k] || self.knots[k + 1] == self.knots[k] {
            return Err(Error::invalid("k", format!("knot {k} is already double")));
        }
        self.knots.insert(k, self.knots[k]);
        Ok(())
    }
}

fn check_count(count: usize, closed: bool, field: &str) -> Result<()> {
    let min = if closed { 3 } else { 2 };
    if count < min || count > MAX_LOCALS {
        return Err(Error::invalid(
            field,
            format!("need {min} to {MAX_LOCALS} local pieces{}, got {count}", if closed { " when closed" } else { "" }),
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn locate_closed_wraps_and_shifts_local_zero() {
        let k = BlendKnots::uniform(Interval::new(0.0, 4.0), 4, true, "n").unwrap();
        let s = k.locate(3.5, Side::Right);
        assert_eq!((s.first, s.second, s.second_shift, s.w), (3, 0, -4.0, 0.5));
        let s = k.locate(4.0, Side::Right);
        assert_eq!((s.first, s.t), (0, 0.0));
        let s = k.locate(0.0, Side::Left);
        assert_eq!((s.first, s.t, s.w), (3, 4.0, 1.0));
        assert_eq!(k.support(0), Interval::new(-1.0, 1.0));
        assert_eq!(k.affected_ranges(0), vec![Interval::new(0.0, 1.0), Interval::new(3.0, 4.0)]);
    }

    #[test]
    fn open_ends_mirror_and_double_knots_are_skipped() {
        let mut k = BlendKnots::new(vec![0.0, 1.0, 3.0, 4.0], false).unwrap();
        assert_eq!(k.support(0), Interval::new(-1.0, 1.0));
        assert_eq!(k.support(3), Interval::new(3.0, 5.0));
        k.split(1).unwrap();
        assert_eq!(k.values(), &[0.0, 1.0, 1.0, 3.0, 4.0]);
        let r = k.locate(1.0, Side::Right);
        assert_eq!((r.first, r.w), (2, 0.0));
        let l = k.locate(1.0, Side::Left);
        assert_eq!((l.first, l.w), (0, 1.0));
        assert!(k.split(1).is_err());
        assert!(BlendKnots::new(vec![0.0, 1.0, 1.0, 1.0, 2.0], false).is_err());
        assert!(BlendKnots::new(vec![0.0, 2.0, 1.0], false).is_err());
    }
}
