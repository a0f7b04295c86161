//! B-functions B: [0, 1] → [0, 1], B(0) = 0, B(1) = 1, monotone: the blending functions of
//! blending splines. Every kind returns derivatives of any order.
//!
//! | kind | B(t) |
//! | --- | --- |
//! | linear | t |
//! | polynomial, smoothness k | I_t(k+1, k+1) = Σ_{j=k+1}^{2k+1} C(2k+1, j) tʲ(1−t)^{2k+1−j} (k = 1: 3t² − 2t³) |
//! | beta (BFBS) a, b | I_t(a+1, b+1), the normalised ∫₀ᵗ sᵃ(1−s)ᵇ ds |
//! | trigonometric | t − sin(2πt)/(2π) |
//! | half-cosine | ½ − ½ cos πt |
//! | rational | t²/((1−t)² + t²) |
//! | ERBS α, β, γ, λ | ∫₀ᵗ φ / ∫₀¹ φ, φ(s) = exp(−β\|s−λ\|^{α(1+γ)} / (s(1−s)^γ)^α) |
//!
//! Polynomial and beta B-functions are Bernstein sums with coefficients 0 … 0, 1 … 1 and
//! are evaluated by de Casteljau with derivatives. ERBS values and derivatives come from
//! the tables of [`super::erbs`].

use std::f64::consts::{PI, TAU};
use std::sync::Arc;

use super::erbs::{ErbsTable, Kernel};
use crate::curve::bezier::bezier_derivatives;
use crate::error::{Error, Result};

/// A B-function.
#[derive(Debug, Clone, PartialEq)]
pub enum BFunction {
    /// B(t) = t.
    Linear,
    /// Bernstein sum of degree n with coefficients 0 for j ≤ a, 1 above: the polynomial
    /// B-function of smoothness k (a = k, n = 2k + 1) or the Beta-function B-spline
    /// (BFBS) with exponents a, b (n = a + b + 1).
    Bernstein {
        /// Exponent a of sᵃ in the kernel.
        a: usize,
        /// Degree n = a + b + 1.
        degree: usize,
    },
    /// t − sin(2πt)/(2π).
    Trigonometric,
    /// ½ − ½ cos πt.
    HalfCosine,
    /// t²/((1−t)² + t²).
    Rational,
    /// The expo-rational B-function.
    Erbs(Arc<ErbsTable>),
}

impl BFunction {
    /// The polynomial B-function of smoothness k ≥ 1 (k = 1: 3t² − 2t³, k = 2:
    /// 6t⁵ − 15t⁴ + 10t³): C^k blends.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::basis::BFunction;
    /// // k = 1 is 3t² − 2t³: at ½ the value ½, slope 3/2 and no curvature; flat at both ends.
    /// let b = BFunction::polynomial(1).unwrap();
    /// let mut d = [0.0; 3];
    /// b.eval(0.5, &mut d);
    /// assert_eq!(d, [0.5, 1.5, 0.0]);
    /// b.eval(1.0, &mut d);
    /// assert_eq!(d[..2], [1.0, 0.0]);
    /// ```
    pub fn polynomial(smoothness: usize) -> Result<Self> {
        if smoothness == 0 || smoothness > 30 {
            return Err(Error::invalid("smoothness", format!("must be between 1 and 30, got {smoothness}")));
        }
        Ok(BFunction::Bernstein { a: smoothness, degree: 2 * smoothness + 1 })
    }

    /// The Beta-function B-spline with kernel sᵃ(1−s)ᵇ (a = b = 1: 3t² − 2t³).
    pub fn beta(a: usize, b: usize) -> Result<Self> {
        if a + b > 60 {
            return Err(Error::invalid("beta", format!("a + b must be at most 60, got {a} + {b}")));
        }
        Ok(BFunction::Bernstein { a, degree: a + b + 1 })
    }

    /// The ERBS B-function with intrinsic parameters α, β, γ > 0 and λ ∈ (0, 1) (defaults
    /// 1, 1, 1, ½). Tables are built once per parameter set and shared.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::basis::BFunction;
    /// // The default ERBS (α = β = γ = 1, λ = ½) is symmetric: B(½) = ½, B(t) + B(1 − t) = 1,
    /// // and every derivative vanishes at the ends.
    /// let b = BFunction::erbs(1.0, 1.0, 1.0, 0.5).unwrap();
    /// assert!((b.value(0.5) - 0.5).abs() < 1e-16);
    /// assert!((b.value(0.2) + b.value(0.8) - 1.0).abs() < 1e-15);
    /// let mut d = [0.0; 4];
    /// b.eval(0.0, &mut d);
    /// assert_eq!(d, [0.0; 4]);
    /// assert!(BFunction::erbs(1.0, 1.0, 1.0, 1.5).is_err());
    /// ```
    pub fn erbs(alpha: f64, beta: f64, gamma: f64, lambda: f64) -> Result<Self> {
        for (name, v) in [("alpha", alpha), ("beta", beta), ("gamma", gamma)] {
            if !(v > 0.0 && v.is_finite() && v <= 100.0) {
                return Err(Error::invalid(name, format!("must be in (0, 100], got {v}")));
            }
        }
        if !(lambda > 0.0 && lambda < 1.0) {
            return Err(Error::invalid("lambda", format!("must be in (0, 1), got {lambda}")));
        }
        Ok(BFunction::Erbs(ErbsTable::shared(Kernel { alpha, beta, gamma, lambda })))
    }

    /// The default ERBS, φ(s) = exp(−(s − ½)²/(s(1 − s))).
    pub fn erbs_default() -> Self {
        BFunction::erbs(1.0, 1.0, 1.0, 0.5).expect("valid defaults")
    }

    /// Writes B(t), B'(t), …, B^{(k)}(t) into `out` (k = out.len() − 1); t is clamped to [0, 1].
    pub fn eval(&self, t: f64, out: &mut [f64]) {
        let t = t.clamp(0.0, 1.0);
        match self {
            BFunction::Linear => {
                for (k, o) in out.iter_mut().enumerate() {
                    *o = match k {
                        0 => t,
                        1 => 1.0,
                        _ => 0.0,
                    };
                }
            }
            BFunction::Bernstein { a, degree } => {
                let mut c = [0.0f64; 64];
                for (j, cj) in c.iter_mut().enumerate().take(degree + 1) {
                    *cj = if j > *a { 1.0 } else { 0.0 };
                }
                bezier_derivatives(&c[..=*degree], t, out);
            }
            BFunction::Trigonometric => {
                let (s, c) = (TAU * t).sin_cos();
                for (k, o) in out.iter_mut().enumerate() {
                    *o = match k {
                        0 => t - s / TAU,
                        _ => {
                            // d^k/dt^k of −sin(2πt)/(2π) = −(2π)^{k−1} sin(2πt + kπ/2).
                            let base = [s, c, -s, -c][k % 4];
                            (if k == 1 { 1.0 } else { 0.0 }) - TAU.powi(k as i32 - 1) * base
                        }
                    };
                }
            }
            BFunction::HalfCosine => {
                let (s, c) = (PI * t).sin_cos();
                for (k, o) in out.iter_mut().enumerate() {
                    // d^k/dt^k (−½ cos πt) = −½ π^k cos(πt + kπ/2).
                    let base = [c, -s, -c, s][k % 4];
                    *o = if k == 0 { 0.5 - 0.5 * c } else { -0.5 * PI.powi(k as i32) * base };
                }
            }
            BFunction::Rational => {
                // N = t², D = 2t² − 2t + 1; B^{(k)} = (N^{(k)} − Σ C(k,i) D^{(i)} B^{(k−i)})/D.
                let n = [t * t, 2.0 * t, 2.0];
                let d = [2.0 * t * t - 2.0 * t + 1.0, 4.0 * t - 2.0, 4.0];
                for k in 0..out.len() {
                    let mut v = if k < 3 { n[k] } else { 0.0 };
                    for i in 1..=k.min(2) {
                        v -= crate::basis::binomial(k, i) * d[i] * out[k - i];
                    }
                    out[k] = v / d[0];
                }
            }
            BFunction::Erbs(table) => table.eval(t, out),
        }
    }

    /// [`Self::eval`] into an array of K values (B, B′, …, B^{(K−1)}): the same values, with
    /// the ERBS table's fast polynomials unrolled for K (the batch paths of blending splines).
    #[inline]
    pub fn eval_array<const K: usize>(&self, t: f64, out: &mut [f64; K]) {
        match self {
            BFunction::Erbs(table) => table.eval_array(t.clamp(0.0, 1.0), out),
            _ => self.eval(t, out),
        }
    }

    /// The order k of flatness at both ends: the largest k with
    /// B^{(j)}(0) = B^{(j)}(1) = 0 for 1 ≤ j ≤ k, so that B − B(0) and B − B(1) vanish to
    /// order k + 1 there and blends are C^k. `None` for ERBS, flat to every order.
    ///
    /// | kind | k |
    /// | --- | --- |
    /// | linear | 0 |
    /// | polynomial of smoothness k, beta (a, b) | k, min(a, b) |
    /// | trigonometric | 2 |
    /// | half-cosine, rational | 1 |
    /// | ERBS | every order (`None`) |
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::basis::BFunction;
    /// assert_eq!(BFunction::polynomial(2).unwrap().flatness(), Some(2));
    /// assert_eq!(BFunction::beta(3, 1).unwrap().flatness(), Some(1));
    /// assert_eq!(BFunction::erbs_default().flatness(), None);
    /// ```
    pub fn flatness(&self) -> Option<usize> {
        match self {
            BFunction::Linear => Some(0),
            BFunction::Bernstein { a, degree } => Some((*a).min(degree - a - 1)),
            BFunction::Trigonometric => Some(2),
            BFunction::HalfCosine | BFunction::Rational => Some(1),
            BFunction::Erbs(_) => None,
        }
    }

    /// B(t).
    pub fn value(&self, t: f64) -> f64 {
        let mut o = [0.0];
        self.eval(t, &mut o);
        o[0]
    }
}
