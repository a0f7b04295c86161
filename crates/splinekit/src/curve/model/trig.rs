//! Curves whose coordinates are finite trigonometric series plus a linear term:
//! x_j(t) = c_j + l_j t + Σ_m a_m cos(ω_m t + φ_m).
//!
//! Derivatives of any order are exact: d^k/dt^k a cos(ωt + φ) = a ω^k cos(ωt + φ + kπ/2).

use smallvec::SmallVec;

use crate::Point;
use crate::curve::Interval;

/// One term a cos(ω t + φ) or a sin(ω t + φ). Sines are evaluated as sines (not as
/// shifted cosines), so sin 0 is exactly 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Term {
    /// Amplitude a.
    pub amplitude: f64,
    /// Angular frequency ω.
    pub frequency: f64,
    /// Phase φ.
    pub phase: f64,
    /// Sine instead of cosine.
    pub sine: bool,
}

impl Term {
    /// a cos(ω t).
    pub const fn cos(amplitude: f64, frequency: f64) -> Self {
        Term { amplitude, frequency, phase: 0.0, sine: false }
    }
    /// a sin(ω t).
    pub const fn sin(amplitude: f64, frequency: f64) -> Self {
        Term { amplitude, frequency, phase: 0.0, sine: true }
    }
}

/// One coordinate: constant + linear·t + Σ terms.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TrigSeries {
    /// Constant part.
    pub constant: f64,
    /// Coefficient of t.
    pub linear: f64,
    /// The cosine terms.
    pub terms: SmallVec<[Term; 4]>,
}

impl TrigSeries {
    /// A series of the given terms.
    pub fn of(terms: &[Term]) -> Self {
        TrigSeries { constant: 0.0, linear: 0.0, terms: SmallVec::from_slice(terms) }
    }
    /// The constant c.
    pub fn constant(c: f64) -> Self {
        TrigSeries { constant: c, ..Default::default() }
    }

    /// The k-th derivative at t.
    #[inline]
    pub fn derivative(&self, t: f64, k: usize) -> f64 {
        let mut v = match k {
            0 => self.constant + self.linear * t,
            1 => self.linear,
            _ => 0.0,
        };
        for term in &self.terms {
            let (s, c) = (term.frequency * t + term.phase).sin_cos();
            // d/dx cycles cos → −sin → −cos → sin and sin → cos → −sin → −cos.
            let base = match (term.sine, k % 4) {
                (false, 0) | (true, 1) => c,
                (false, 1) | (true, 2) => -s,
                (false, 2) | (true, 3) => -c,
                _ => s,
            };
            v += term.amplitude * term.frequency.powi(k as i32) * base;
        }
        v
    }

    /// The derivatives of orders 0, 1, …, `out.len()` − 1 at t into `out` (the values of
    /// [`TrigSeries::derivative`]), with one sine and cosine per term for all orders.
    #[inline]
    pub fn derivatives(&self, t: f64, out: &mut [f64]) {
        self.derivatives_cached(t, out, &mut SinCosCache::default());
    }

    /// [`TrigSeries::derivatives`] that looks up and keeps the sines and cosines in `cache`
    /// (a surface's terms share their angles: the torus has seven trigonometric factors
    /// and two angles).
    #[inline]
    pub fn derivatives_cached(&self, t: f64, out: &mut [f64], cache: &mut SinCosCache) {
        for (k, o) in out.iter_mut().enumerate() {
            *o = match k {
                0 => self.constant + self.linear * t,
                1 => self.linear,
                _ => 0.0,
            };
        }
        for term in &self.terms {
            let (s, c) = cache.sin_cos(term.frequency * t + term.phase);
            let mut power = 1.0;
            for (k, o) in out.iter_mut().enumerate() {
                let base = match (term.sine, k % 4) {
                    (false, 0) | (true, 1) => c,
                    (false, 1) | (true, 2) => -s,
                    (false, 2) | (true, 3) => -c,
                    _ => s,
                };
                *o += term.amplitude * power * base;
                power *= term.frequency;
            }
        }
    }
}

/// The last few angles whose sine and cosine were computed, with them.
#[derive(Debug, Clone, Default)]
pub struct SinCosCache {
    entries: SmallVec<[(f64, f64, f64); 8]>,
}

impl SinCosCache {
    /// (sin x, cos x), computed once per distinct x while the cache has room.
    #[inline]
    pub fn sin_cos(&mut self, x: f64) -> (f64, f64) {
        if let Some(&(_, s, c)) = self.entries.iter().find(|e| e.0.to_bits() == x.to_bits()) {
            return (s, c);
        }
        let (s, c) = x.sin_cos();
        if self.entries.len() < 8 {
            self.entries.push((x, s, c));
        }
        (s, c)
    }
}

/// A 3-D curve with trigonometric-series coordinates on a domain.
#[derive(Debug, Clone, PartialEq)]
pub struct TrigCurve {
    /// x, y, z.
    pub coordinates: [TrigSeries; 3],
    /// Parameter domain.
    pub domain: Interval,
    /// Whether the curve is closed (periodic over the domain).
    pub closed: bool,
}

impl TrigCurve {
    /// The curve with these coordinates over one turn, t ∈ [0, 2π], closed there when
    /// `closed` (every frequency an integer) and open otherwise.
    pub(crate) fn one_turn(coordinates: [TrigSeries; 3], closed: bool) -> Self {
        TrigCurve { coordinates, domain: Interval::new(0.0, std::f64::consts::TAU), closed }
    }

    /// Writes the position and derivatives.
    #[inline]
    pub fn eval_into(&self, t: f64, out: &mut [Point<3>]) {
        let t =
            if self.closed { self.domain.wrap_periodic(t, crate::basis::Side::Right) } else { self.domain.clamp(t) };
        for (k, o) in out.iter_mut().enumerate() {
            for j in 0..3 {
                o[j] = self.coordinates[j].derivative(t, k);
            }
        }
    }
}

/// Implements `Curve<3>` for a model-curve struct with a `curve: TrigCurve` field.
macro_rules! trig_model_curve {
    ($ty:ty) => {
        impl $crate::curve::Curve<3> for $ty {
            fn domain(&self) -> $crate::curve::Interval {
                self.curve.domain
            }
            fn is_closed(&self) -> bool {
                self.curve.closed
            }
            #[inline]
            fn eval_side(&self, t: f64, _side: $crate::basis::Side, out: &mut [$crate::Point<3>]) {
                self.curve.eval_into(t, out)
            }
        }
    };
}
pub(crate) use trig_model_curve;

/// Checks a parameter is finite and positive.
pub(crate) fn positive(field: &str, v: f64) -> crate::Result<f64> {
    if v > 0.0 && v.is_finite() {
        Ok(v)
    } else {
        Err(crate::Error::invalid(field, format!("must be positive and finite, got {v}")))
    }
}

/// Checks a parameter is finite.
pub(crate) fn finite(field: &str, v: f64) -> crate::Result<f64> {
    if v.is_finite() { Ok(v) } else { Err(crate::Error::invalid(field, format!("must be finite, got {v}"))) }
}
