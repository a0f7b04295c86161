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
//! are evaluated by de Casteljau with derivatives. ERBS values come from a table of
//! cumulative cell integrals (20-point Gauss–Legendre per cell, compensated sums, shared
//! between all users of the same parameters) plus an 8-point Gauss–Legendre integral
//! inside the cell, taken from the nearer end; derivatives B^{(k)} = φ^{(k−1)}/S are
//! exact, from Taylor jets of φ = exp(g).

use std::f64::consts::{PI, TAU};
use std::sync::{Arc, Mutex, OnceLock};

use smallvec::{SmallVec, smallvec};

use crate::curve::bezier::bezier_derivatives;
use crate::error::{Error, Result};
use crate::taylor;

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

    /// B(t).
    pub fn value(&self, t: f64) -> f64 {
        let mut o = [0.0];
        self.eval(t, &mut o);
        o[0]
    }
}

/// The ERBS kernel parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kernel {
    /// α.
    pub alpha: f64,
    /// β.
    pub beta: f64,
    /// γ.
    pub gamma: f64,
    /// λ.
    pub lambda: f64,
}

impl Kernel {
    /// g(s) = ln φ(s) = −β |s − λ|^{α(1+γ)} / (s (1 − s)^γ)^α.
    fn log_phi(&self, s: f64) -> f64 {
        if self.alpha == 1.0 && self.gamma == 1.0 {
            // The common case: a rational function, no powf.
            let u = s - self.lambda;
            return -self.beta * u * u / (s * (1.0 - s));
        }
        -self.beta * (s - self.lambda).abs().powf(self.alpha * (1.0 + self.gamma))
            / (s * (1.0 - s).powf(self.gamma)).powf(self.alpha)
    }
    fn phi(&self, s: f64) -> f64 {
        if s <= 0.0 || s >= 1.0 { 0.0 } else { self.log_phi(s).exp() }
    }
    /// Normalised Taylor coefficients φ_k = φ^{(k)}(s)/k!, k < out.len().
    fn phi_jet(&self, s: f64, out: &mut [f64]) {
        let n = out.len();
        out.iter_mut().for_each(|o| *o = 0.0);
        if s <= 0.0 || s >= 1.0 || n == 0 {
            return;
        }
        let g0 = self.log_phi(s);
        if g0 < -700.0 {
            // φ and every derivative are below 1e-280 here.
            return;
        }
        // Work on at least two coefficients (the linear parts below), return the first n.
        let m = n.max(2);
        let mut buf: Vec<SmallVec<[f64; 8]>> = (0..7).map(|_| smallvec![0.0; m]).collect();
        let [u, ua, one_minus, om_g, v, w, g] = &mut buf[..] else { unreachable!("seven buffers") };
        let du = s - self.lambda;
        let a = self.alpha * (1.0 + self.gamma);
        // |u|^a: for u < 0 use (−u)^a, whose jet is that of (λ − s).
        let sign = if du < 0.0 { -1.0 } else { 1.0 };
        u[0] = du.abs();
        u[1] = sign;
        if u[0] == 0.0 {
            // At s = λ the jet of |u|^a is u^a's (a ≥ 1 integer-like for the usual parameters);
            // use the binomial series of (s − λ)^a with integer a, else step off λ slightly.
            let ai = a.round();
            if (a - ai).abs() < 1e-12 && ai >= 0.0 && (ai as usize) < m {
                ua[ai as usize] = 1.0;
            } else {
                return self.phi_jet(s + 1e-15, out);
            }
        } else {
            taylor::powf(&u[..m], a, &mut ua[..m]);
        }
        one_minus[0] = 1.0 - s;
        one_minus[1] = -1.0;
        taylor::powf(&one_minus[..m], self.gamma, &mut om_g[..m]);
        let mut sj: SmallVec<[f64; 8]> = smallvec![0.0; m.max(2)];
        sj[0] = s;
        sj[1] = 1.0;
        taylor::mul(&sj[..m], &om_g[..m], &mut v[..m]);
        taylor::powf(&v[..m], -self.alpha, &mut w[..m]);
        taylor::mul(&ua[..m], &w[..m], &mut g[..m]);
        for x in g[..m].iter_mut() {
            *x *= -self.beta;
        }
        let mut e: SmallVec<[f64; 8]> = smallvec![0.0; m];
        taylor::exp(&g[..m], &mut e);
        out.copy_from_slice(&e[..n]);
    }
}

/// Cells of the ERBS table.
const CELLS: usize = 512;

/// Gauss–Legendre nodes and weights on [−1, 1] (Newton on the Legendre recurrence).
fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    // P_n(z) and P_n'(z) by the three-term recurrence.
    let legendre = |z: f64| {
        let (mut p0, mut p1) = (1.0, z);
        for k in 2..=n {
            let p2 = ((2 * k - 1) as f64 * z * p1 - (k - 1) as f64 * p0) / k as f64;
            p0 = p1;
            p1 = p2;
        }
        (p1, n as f64 * (z * p1 - p0) / (z * z - 1.0))
    };
    let mut x = vec![0.0; n];
    let mut w = vec![0.0; n];
    for i in 0..n {
        let mut z = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        for _ in 0..100 {
            let (p, dp) = legendre(z);
            let dz = p / dp;
            z -= dz;
            if dz.abs() <= 1e-16 * z.abs().max(1e-3) {
                break;
            }
        }
        let (_, dp) = legendre(z);
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
    (x, w)
}

/// Cumulative integrals of φ at the cell boundaries, shared per parameter set.
#[derive(Debug)]
pub struct ErbsTable {
    kernel: Kernel,
    /// ∫₀^{x_i} φ at x_i = i/CELLS.
    head: Vec<f64>,
    /// ∫_{x_i}^1 φ.
    tail: Vec<f64>,
    /// S = ∫₀¹ φ.
    total: f64,
    nodes: (Vec<f64>, Vec<f64>),
}

impl PartialEq for ErbsTable {
    fn eq(&self, other: &Self) -> bool {
        self.kernel == other.kernel
    }
}

impl ErbsTable {
    fn build(kernel: Kernel) -> Self {
        let (x20, w20) = gauss_legendre(20);
        let h = 1.0 / CELLS as f64;
        let cell: Vec<f64> = (0..CELLS)
            .map(|i| {
                let m = (i as f64 + 0.5) * h;
                x20.iter().zip(&w20).map(|(x, w)| w * kernel.phi(m + 0.5 * h * x)).sum::<f64>() * 0.5 * h
            })
            .collect();
        // Compensated (Neumaier) prefix sums from both ends.
        let prefix = |vals: &mut dyn Iterator<Item = f64>| {
            let (mut sum, mut comp) = (0.0f64, 0.0f64);
            let mut out = vec![0.0];
            for v in vals {
                let t = sum + v;
                comp += if sum.abs() >= v.abs() { (sum - t) + v } else { (v - t) + sum };
                sum = t;
                out.push(sum + comp);
            }
            out
        };
        let head = prefix(&mut cell.iter().copied());
        let mut tail = prefix(&mut cell.iter().rev().copied());
        tail.reverse();
        let total = head[CELLS];
        ErbsTable { kernel, head, tail, total, nodes: gauss_legendre(8) }
    }

    /// The table for these parameters, built on first use and shared afterwards.
    pub fn shared(kernel: Kernel) -> Arc<ErbsTable> {
        static CACHE: OnceLock<Mutex<Vec<Arc<ErbsTable>>>> = OnceLock::new();
        let cache = CACHE.get_or_init(|| Mutex::new(Vec::new()));
        let mut list = cache.lock().unwrap_or_else(|p| p.into_inner());
        if let Some(t) = list.iter().find(|t| t.kernel == kernel) {
            return t.clone();
        }
        let t = Arc::new(ErbsTable::build(kernel));
        list.push(t.clone());
        t
    }

    /// S = ∫₀¹ φ.
    pub fn normaliser(&self) -> f64 {
        self.total
    }

    /// ∫_a^b φ by 8-point Gauss–Legendre (a, b in one cell).
    fn partial(&self, a: f64, b: f64) -> f64 {
        let (m, r) = (0.5 * (a + b), 0.5 * (b - a));
        self.nodes.0.iter().zip(&self.nodes.1).map(|(x, w)| w * self.kernel.phi(m + r * x)).sum::<f64>() * r
    }

    fn eval(&self, t: f64, out: &mut [f64]) {
        if out.is_empty() {
            return;
        }
        let h = 1.0 / CELLS as f64;
        let i = ((t * CELLS as f64) as usize).min(CELLS - 1);
        let (a, b) = (i as f64 * h, (i + 1) as f64 * h);
        // Integrate from the nearer table end of the cell; below λ from 0, above from 1.
        out[0] = if t <= self.kernel.lambda {
            let left =
                if t - a <= b - t { self.head[i] + self.partial(a, t) } else { self.head[i + 1] - self.partial(t, b) };
            left / self.total
        } else {
            let right =
                if b - t <= t - a { self.tail[i + 1] + self.partial(t, b) } else { self.tail[i] - self.partial(a, t) };
            1.0 - right / self.total
        };
        if out.len() > 1 {
            let k = out.len() - 1;
            let mut jet: SmallVec<[f64; 8]> = smallvec![0.0; k];
            self.kernel.phi_jet(t, &mut jet);
            let mut fact = 1.0;
            for (j, o) in out.iter_mut().skip(1).enumerate() {
                if j > 0 {
                    fact *= j as f64;
                }
                *o = jet[j] * fact / self.total;
            }
        }
    }
}
