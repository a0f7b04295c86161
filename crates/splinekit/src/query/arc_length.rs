//! Arc length as a parameter: the parameter at a given length (inverse arc length), equal-
//! length sampling, and the arc-length reparametrised curve.
//!
//! The table: the curve's breakpoint pieces, each cut into at least [`TABLE_PIECES`] in
//! all, with the length of every piece by adaptive Gauss–Legendre quadrature
//! ([`crate::ops::length::arc_length`]) and their running sums. The parameter t at length
//! s is the root of L(t) = s_k + ∫_{t_k}^t |c′| − s on the table piece [t_k, t_{k+1}] that
//! holds s, found by Newton's method (L′ = |c′|) safeguarded by bisection.
//!
//! What is guaranteed (where the quadrature meets its tolerance): the returned t satisfies
//! |length(a, t) − s| ≤ `accuracy`, the table's lengths and the final integral each being
//! computed to a share of it. Where the speed |c′| vanishes on a stretch, the length does
//! not grow there and the smallest parameter of that length is returned.

use crate::Interval;
use crate::Point;
use crate::curve::Curve;
use crate::error::{Error, Result};
use crate::ops::length::arc_length;
use crate::taylor;

/// The fewest pieces the length table has.
pub const TABLE_PIECES: usize = 64;

/// Newton/bisection steps allowed for one inversion.
const MAX_STEPS: usize = 100;

/// The highest derivative order [`ArcLengthCurve`] computes.
pub const MAX_ORDER: usize = 16;

/// A table of running arc lengths of a curve, for inverting arc length many times.
#[derive(Debug, Clone)]
pub struct ArcLengthTable<'c, C: ?Sized> {
    curve: &'c C,
    params: Vec<f64>,
    lengths: Vec<f64>,
    accuracy: f64,
}

impl<'c, C: ?Sized> ArcLengthTable<'c, C> {
    /// The whole length L of the curve.
    pub fn total(&self) -> f64 {
        *self.lengths.last().unwrap()
    }
}

impl<'c, C: ?Sized> ArcLengthTable<'c, C> {
    /// Builds the table of `curve` for inversions to `accuracy` (absolute, > 0).
    pub fn new<const D: usize>(curve: &'c C, accuracy: f64) -> Result<Self>
    where
        C: Curve<D>,
    {
        if !(accuracy > 0.0 && accuracy.is_finite()) {
            return Err(Error::invalid("accuracy", format!("must be finite and > 0, got {accuracy}")));
        }
        let dom = curve.domain();
        let mut breaks: Vec<f64> =
            curve.breakpoints().into_iter().filter(|&t| t >= dom.start && t <= dom.end).collect();
        breaks.dedup();
        if breaks.len() < 2 {
            breaks = vec![dom.start, dom.end];
        }
        let per = TABLE_PIECES.div_ceil(breaks.len() - 1);
        let mut params = Vec::new();
        for w in breaks.windows(2).filter(|w| w[1] > w[0]) {
            params.extend((0..per).map(|i| w[0] + (w[1] - w[0]) * i as f64 / per as f64));
        }
        params.push(dom.end);
        let share = accuracy / (4.0 * params.len() as f64);
        let mut lengths = vec![0.0];
        for w in params.windows(2) {
            let last = *lengths.last().unwrap();
            lengths.push(last + arc_length(curve, Interval::new(w[0], w[1]), share));
        }
        Ok(ArcLengthTable { curve, params, lengths, accuracy })
    }

    /// The parameter t with length(a, t) = `s` (0 ≤ s ≤ L, within the accuracy); see the
    /// module documentation.
    pub fn parameter_at<const D: usize>(&self, s: f64) -> Result<f64>
    where
        C: Curve<D>,
    {
        let total = self.total();
        if !(s >= -self.accuracy && s <= total + self.accuracy) {
            return Err(Error::invalid("length", format!("{s} is outside [0, {total}]")));
        }
        let s = s.clamp(0.0, total);
        let k = self.lengths.partition_point(|&l| l < s).clamp(1, self.params.len() - 1) - 1;
        let (mut lo, mut hi) = (self.params[k], self.params[k + 1]);
        let base = self.lengths[k];
        let start = lo;
        let tol = self.accuracy / 4.0;
        let mut t = if self.lengths[k + 1] > base {
            lo + (hi - lo) * (s - base) / (self.lengths[k + 1] - base)
        } else {
            return Ok(lo);
        };
        for _ in 0..MAX_STEPS {
            let f = base + arc_length(self.curve, Interval::new(start, t), tol) - s;
            if f.abs() <= tol {
                return Ok(t);
            }
            if f < 0.0 {
                lo = t;
            } else {
                hi = t;
            }
            let speed = self.curve.derivative(t, 1).norm();
            let newton = t - f / speed;
            t = if speed > 0.0 && newton > lo && newton < hi { newton } else { 0.5 * (lo + hi) };
            if hi - lo <= crate::query::newton::ROUNDING_STEP * t.abs().max(1.0) {
                return Ok(t);
            }
        }
        Ok(t)
    }

    /// `n` ≥ 2 parameters at equal arc-length spacing L/(n − 1), both ends included.
    pub fn equal_length_parameters<const D: usize>(&self, n: usize) -> Result<Vec<f64>>
    where
        C: Curve<D>,
    {
        if n < 2 {
            return Err(Error::invalid("samples", format!("need at least 2, got {n}")));
        }
        let total = self.total();
        let d = self.curve.domain();
        (0..n)
            .map(|i| match i {
                0 => Ok(d.start),
                _ if i + 1 == n => Ok(d.end),
                _ => self.parameter_at(total * i as f64 / (n - 1) as f64),
            })
            .collect()
    }
}

/// The curve reparametrised by arc length, s ∈ [0, L]: b(s) = c(t(s)) with |b′| = 1.
///
/// Derivatives of every order (up to [`MAX_ORDER`]) come from Taylor jets: the jet of
/// σ(τ) = length(t, t + τ) (the integral of the speed jet √(c′·c′)) is reverted into the
/// jet of τ(σ), and c's jet is composed with it.
#[derive(Debug, Clone)]
pub struct ArcLengthCurve<'c, C: ?Sized> {
    table: ArcLengthTable<'c, C>,
}

impl<'c, C: ?Sized> ArcLengthCurve<'c, C> {
    /// The arc-length parametrisation of `curve`, inverted to `accuracy` (see
    /// [`ArcLengthTable`]).
    pub fn new<const D: usize>(curve: &'c C, accuracy: f64) -> Result<Self>
    where
        C: Curve<D>,
    {
        Ok(ArcLengthCurve { table: ArcLengthTable::new(curve, accuracy)? })
    }

    /// The table used for the inversions.
    pub fn table(&self) -> &ArcLengthTable<'c, C> {
        &self.table
    }
}

impl<const D: usize, C: Curve<D> + ?Sized> Curve<D> for ArcLengthCurve<'_, C> {
    fn domain(&self) -> Interval {
        Interval::new(0.0, self.table.total())
    }

    fn is_closed(&self) -> bool {
        self.table.curve.is_closed()
    }

    fn eval_side(&self, s: f64, side: crate::basis::Side, out: &mut [Point<D>]) {
        let total = self.table.total();
        let s = if self.is_closed() { self.domain().wrap(s) } else { s.clamp(0.0, total) };
        let t = self.table.parameter_at(s).unwrap_or(self.table.curve.domain().start);
        let k = (out.len() - 1).min(MAX_ORDER);
        let mut c = vec![Point::<D>::zeros(); k + 2];
        self.table.curve.eval_side(t, side, &mut c);
        compose_by_arc_length(&c, &mut out[..=k]);
        for o in out.iter_mut().skip(k + 1) {
            *o = Point::<D>::zeros();
        }
    }

    fn breakpoints(&self) -> Vec<f64> {
        let mut b: Vec<f64> = self
            .table
            .curve
            .breakpoints()
            .into_iter()
            .filter_map(|t| {
                let k = self.table.params.iter().position(|&p| p == t)?;
                Some(self.table.lengths[k])
            })
            .collect();
        b.dedup();
        b
    }
}

/// Given c, c′, …, c^{(k+1)} at t, writes b, b′, …, b^{(k)} of b(s) = c(t(s)) at the same
/// point, where s is arc length (see [`ArcLengthCurve`]).
fn compose_by_arc_length<const D: usize>(c: &[Point<D>], out: &mut [Point<D>]) {
    let k = out.len() - 1;
    let fact = |n: usize| (1..=n).map(|x| x as f64).product::<f64>();
    // The jet of q(τ) = c′(t+τ)·c′(t+τ), then of the speed √q, then σ = ∫ speed.
    let d1: Vec<Point<D>> = (0..=k).map(|j| c[j + 1] / fact(j)).collect();
    let q: Vec<f64> = (0..=k).map(|m| (0..=m).map(|j| d1[j].dot(&d1[m - j])).sum()).collect();
    let mut speed = vec![0.0; k + 1];
    taylor::powf(&q, 0.5, &mut speed);
    let sigma: Vec<f64> = (0..=k).map(|j| if j == 0 { 0.0 } else { speed[j - 1] / j as f64 }).collect();
    out[0] = c[0];
    if k == 0 {
        return;
    }
    if speed[0] == 0.0 {
        for o in out.iter_mut().skip(1) {
            *o = Point::<D>::zeros();
        }
        return;
    }
    // Revert σ(τ) into τ(x) = Σ τ_m x^m: τ_m makes the x^m coefficient of σ(τ(x)) vanish.
    let mut tau = vec![0.0; k + 1];
    tau[1] = 1.0 / sigma[1];
    for m in 2..=k {
        let composed = compose(&sigma, &tau);
        tau[m] = -composed[m] / sigma[1];
    }
    // b(x) = Σ_j c_j τ(x)^j, c_j = c^{(j)}/j!.
    let mut power = vec![0.0; k + 1];
    power[0] = 1.0;
    let mut jet = vec![Point::<D>::zeros(); k + 1];
    for j in 0..=k {
        let cj = c[j] / fact(j);
        for m in 0..=k {
            jet[m] += cj * power[m];
        }
        let mut next = vec![0.0; k + 1];
        taylor::mul(&power, &tau, &mut next);
        power = next;
    }
    for m in 1..=k {
        out[m] = jet[m] * fact(m);
    }
}

/// The jet of f(g(x)) for jets f and g with g₀ = 0.
fn compose(f: &[f64], g: &[f64]) -> Vec<f64> {
    let n = g.len();
    let mut out = vec![0.0; n];
    let mut power = vec![0.0; n];
    power[0] = 1.0;
    for fj in f.iter().take(n) {
        for m in 0..n {
            out[m] += fj * power[m];
        }
        let mut next = vec![0.0; n];
        taylor::mul(&power, g, &mut next);
        power = next;
    }
    out
}
