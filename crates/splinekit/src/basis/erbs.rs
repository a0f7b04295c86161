//! The expo-rational B-function (ERBS): B(t) = ∫₀ᵗ φ / ∫₀¹ φ with the kernel
//! φ(s) = exp(−β |s − λ|^{α(1+γ)} / (s (1 − s)^γ)^α), and its tables.
//!
//! Values come from a table of cumulative cell integrals (20-point Gauss–Legendre per
//! cell, compensated sums, shared between all users of the same parameters) plus an
//! 8-point Gauss–Legendre integral inside the cell, taken from the nearer end;
//! derivatives B^{(k)} = φ^{(k−1)}/S are exact, from Taylor jets of φ = exp(g). For speed,
//! B and up to three derivatives come from per-cell Taylor polynomials of degree 12 about
//! 1024 cell centres (built from the exact path, and used only in cells where they
//! reproduce it: the value to 2⁻⁵², derivatives to 1e-14 of their size).

use std::sync::{Arc, Mutex, OnceLock};

use smallvec::{SmallVec, smallvec};

use crate::quadrature::GaussLegendre;
use crate::taylor;

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
        if g0 < NEGLIGIBLE_LOG_PHI {
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
            if (a - ai).abs() < INTEGER_EXPONENT && ai >= 0.0 && (ai as usize) < m {
                ua[ai as usize] = 1.0;
            } else {
                return self.phi_jet(s + STEP_OFF_LAMBDA, out);
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

/// Below this, ln φ makes φ and every derivative smaller than 1e-280: the jet is zero.
const NEGLIGIBLE_LOG_PHI: f64 = -700.0;

/// The exponent α(1 + γ) counts as an integer within this distance (then |s − λ|^a has an
/// exact binomial jet at s = λ).
const INTEGER_EXPONENT: f64 = 1e-12;

/// At s = λ with a non-integer exponent, the jet is taken this far to the right instead.
const STEP_OFF_LAMBDA: f64 = 1e-15;

/// A fast cell's B may differ from the exact path by this much (both are within about an
/// ulp of the truth).
const FAST_VALUE_TOLERANCE: f64 = 2.3e-16;

/// A fast cell's derivatives may differ from the exact ones by this fraction of their
/// value …
const FAST_DERIVATIVE_RELATIVE: f64 = 1e-14;

/// … plus this fraction of the derivative's largest size over [0, 1].
const FAST_DERIVATIVE_OF_SCALE: f64 = 1e-15;

/// Cells of the ERBS table.
const CELLS: usize = 512;
/// Cells of the fast polynomial table.
const FAST_CELLS: usize = 1024;
/// Degree of the per-cell polynomial for B.
const FAST_DEGREE: usize = 12; // `estrin` is written for 13 coefficients
/// Highest derivative order served by the fast table.
const FAST_ORDER: usize = 3;

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
    /// The 8-point rule for integrals inside a cell.
    rule8: GaussLegendre,
    /// Per fast cell, the polynomial p(x) = Σ_k c_k x^k in x = (t − m)/r about the cell
    /// centre m (r the half-width), from the Taylor series of B (or 1 − B, ln B, ln(1 − B))
    /// at m, followed by the coefficients of p′, p″, p‴.
    fast: Vec<[[f64; FAST_DEGREE + 1]; FAST_ORDER + 1]>,
    fast_mode: Vec<FastMode>,
}

/// How a fast cell's polynomial p gives B.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum FastMode {
    /// B = p.
    Poly,
    /// B = 1 − p.
    PolyTail,
    /// B = exp(p).
    LogHead,
    /// B = 1 − exp(p).
    LogTail,
    /// No polynomial: quadrature and jets.
    Exact,
}

/// Σ c_k x^k for the 13 coefficients of a fast cell, by Estrin's scheme.
#[inline(always)]
fn estrin(c: &[f64; FAST_DEGREE + 1], x: f64, x2: f64, x4: f64, x8: f64) -> f64 {
    let a = [c[0] + c[1] * x, c[2] + c[3] * x, c[4] + c[5] * x, c[6] + c[7] * x, c[8] + c[9] * x, c[10] + c[11] * x];
    let b0 = a[0] + a[1] * x2;
    let b1 = a[2] + a[3] * x2;
    let b2 = a[4] + a[5] * x2;
    (b0 + b1 * x4) + (b2 + c[12] * x4) * x8
}

/// Taylor coefficients of ln f from those of f (f₀ > 0):
/// L₀ = ln f₀, k L_k = (k f_k − Σ_{j=1}^{k−1} j L_j f_{k−j}) / f₀.
fn log_series(f: &[f64; FAST_DEGREE + 1]) -> [f64; FAST_DEGREE + 1] {
    let mut l = [0.0; FAST_DEGREE + 1];
    l[0] = f[0].ln();
    for k in 1..=FAST_DEGREE {
        let mut acc = k as f64 * f[k];
        for j in 1..k {
            acc -= j as f64 * l[j] * f[k - j];
        }
        l[k] = acc / (k as f64 * f[0]);
    }
    l
}

impl PartialEq for ErbsTable {
    fn eq(&self, other: &Self) -> bool {
        self.kernel == other.kernel
    }
}

impl ErbsTable {
    fn build(kernel: Kernel) -> Self {
        let rule20 = GaussLegendre::new(20);
        let h = 1.0 / CELLS as f64;
        let cell: Vec<f64> =
            (0..CELLS).map(|i| rule20.integrate_about((i as f64 + 0.5) * h, 0.5 * h, |s| kernel.phi(s))).collect();
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
        let mut table = ErbsTable {
            kernel,
            head,
            tail,
            total,
            rule8: GaussLegendre::new(8),
            fast: vec![[[0.0; FAST_DEGREE + 1]; FAST_ORDER + 1]; FAST_CELLS],
            fast_mode: vec![FastMode::Exact; FAST_CELLS],
        };
        table.build_fast();
        table
    }

    /// The per-cell polynomials of the fast path, each checked against the quadrature and
    /// jet path ([`Self::fast_cell_agrees`]). Where a polynomial for B
    /// fails (next to 0 and 1, where φ's essential singularity limits the Taylor series)
    /// the cell tries a polynomial for ln B (below λ) or ln(1 − B) (above λ), whose
    /// singularity is only a pole; cells that fail both keep the exact path.
    fn build_fast(&mut self) {
        let r = 0.5 / FAST_CELLS as f64;
        let n = FAST_DEGREE + 1;
        // The size of each derivative over [0, 1], for the absolute part of the check.
        let mut scale = [0.0f64; FAST_ORDER + 1];
        for j in 1..1000 {
            let mut e = [0.0; FAST_ORDER + 1];
            self.eval_exact(j as f64 / 1000.0, &mut e);
            for k in 0..=FAST_ORDER {
                scale[k] = scale[k].max(e[k].abs());
            }
        }
        for i in 0..FAST_CELLS {
            let m = (2 * i + 1) as f64 * r;
            // The Taylor series of B at m (coefficients B^{(k)}(m)/k!, in x = (t − m)/r).
            let mut jet = [0.0; FAST_DEGREE];
            self.kernel.phi_jet(m, &mut jet);
            let (below, above) = (self.head_integral(m), self.tail_integral(m));
            let mut b = [0.0; FAST_DEGREE + 1];
            b[0] = below / self.total;
            let mut rk = 1.0;
            for k in 1..n {
                rk *= r;
                b[k] = jet[k - 1] / k as f64 * rk / self.total;
            }
            // Below λ: B itself, else ln B. Above λ: the complement C = 1 − B (series
            // C(m) = above/S, −b_k), else ln C; small values keep their relative accuracy.
            let mut c = b.map(|x| -x);
            c[0] = above / self.total;
            let (series, poly, log) = if m < self.kernel.lambda {
                (b, FastMode::Poly, FastMode::LogHead)
            } else {
                (c, FastMode::PolyTail, FastMode::LogTail)
            };
            let mut modes = vec![(poly, series)];
            if series[0] > 0.0 {
                modes.push((log, log_series(&series)));
            }
            self.fast_mode[i] = FastMode::Exact;
            for (mode, coefficients) in modes {
                // p and its derivative polynomials: p^{(k)} has coefficients (j+k)!/j! c_{j+k}.
                let mut polys = [[0.0; FAST_DEGREE + 1]; FAST_ORDER + 1];
                polys[0] = coefficients;
                for k in 1..=FAST_ORDER {
                    for j in 0..=FAST_DEGREE - k {
                        polys[k][j] = (j + 1) as f64 * polys[k - 1][j + 1];
                    }
                }
                self.fast[i] = polys;
                self.fast_mode[i] = mode;
                if coefficients.iter().all(|x| x.is_finite()) && self.fast_cell_agrees(i, m, r, &scale) {
                    break;
                }
                self.fast_mode[i] = FastMode::Exact;
            }
        }
    }

    /// Whether cell i's fast path matches the exact one at 17 points of the cell: B to
    /// [`FAST_VALUE_TOLERANCE`], B^{(k)} to [`FAST_DERIVATIVE_RELATIVE`] relative plus
    /// [`FAST_DERIVATIVE_OF_SCALE`] of its size over [0, 1].
    fn fast_cell_agrees(&self, i: usize, m: f64, r: f64, scale: &[f64; FAST_ORDER + 1]) -> bool {
        (0..17).all(|j| {
            let t = m + r * (j as f64 / 8.0 - 1.0);
            let (mut exact, mut approx) = ([0.0; FAST_ORDER + 1], [0.0; FAST_ORDER + 1]);
            self.eval_exact(t, &mut exact);
            self.eval_fast(i, t, &mut approx);
            (0..=FAST_ORDER).all(|k| {
                let tol = if k == 0 {
                    FAST_VALUE_TOLERANCE
                } else {
                    FAST_DERIVATIVE_RELATIVE * exact[k].abs() + FAST_DERIVATIVE_OF_SCALE * scale[k]
                };
                (exact[k] - approx[k]).abs() <= tol
            })
        })
    }

    /// The fast path on cell i (out.len() ≤ FAST_ORDER + 1): the cell's polynomial p and
    /// its stored derivative polynomials by Estrin's scheme (independent, short dependency
    /// chains), then B = p, 1 − p, e^p or 1 − e^p by the cell's mode.
    #[inline(always)]
    fn eval_fast(&self, i: usize, t: f64, out: &mut [f64]) {
        let r = 0.5 / FAST_CELLS as f64;
        // 1/r = 2·FAST_CELLS is a power of two: the product is the quotient, exactly.
        let x = (t - (2 * i + 1) as f64 * r) * (1.0 / r);
        let c = &self.fast[i];
        let x2 = x * x;
        let x4 = x2 * x2;
        let x8 = x4 * x4;
        let mut p = [0.0; FAST_ORDER + 1];
        for (k, pk) in p.iter_mut().enumerate().take(out.len()) {
            *pk = estrin(&c[k], x, x2, x4, x8);
        }
        let inv = 1.0 / r;
        let (l1, l2, l3) = (p[1] * inv, p[2] * inv * inv, p[3] * inv * inv * inv);
        let d = match self.fast_mode[i] {
            FastMode::Poly => [p[0], l1, l2, l3],
            FastMode::PolyTail => [1.0 - p[0], -l1, -l2, -l3],
            mode => {
                // e^L and its derivatives: E' = E L', E'' = E (L'' + L'²), E''' = E (L''' + 3 L' L'' + L'³).
                let e = p[0].exp();
                let d = [e, e * l1, e * (l2 + l1 * l1), e * (l3 + 3.0 * l1 * l2 + l1 * l1 * l1)];
                if mode == FastMode::LogHead { d } else { [1.0 - d[0], -d[1], -d[2], -d[3]] }
            }
        };
        for (o, v) in out.iter_mut().zip(d) {
            *o = v;
        }
    }

    /// The table cell i ∋ t and its ends [a, b].
    fn cell(t: f64) -> (usize, f64, f64) {
        let h = 1.0 / CELLS as f64;
        let i = ((t * CELLS as f64) as usize).min(CELLS - 1);
        (i, i as f64 * h, (i + 1) as f64 * h)
    }

    /// ∫₀ᵗ φ: the table value at the nearer end of t's cell plus or minus the rest.
    fn head_integral(&self, t: f64) -> f64 {
        let (i, a, b) = Self::cell(t);
        if t - a <= b - t { self.head[i] + self.partial(a, t) } else { self.head[i + 1] - self.partial(t, b) }
    }

    /// ∫ₜ¹ φ, like [`Self::head_integral`] from the other end of the table.
    fn tail_integral(&self, t: f64) -> f64 {
        let (i, a, b) = Self::cell(t);
        if b - t <= t - a { self.tail[i + 1] + self.partial(t, b) } else { self.tail[i] - self.partial(a, t) }
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
        self.rule8.integrate(a, b, |s| self.kernel.phi(s))
    }

    /// B, B′, … at t ∈ [0, 1] (see [`crate::basis::BFunction::eval`]): the fast cell
    /// polynomials where they apply, else quadrature and jets.
    pub(crate) fn eval(&self, t: f64, out: &mut [f64]) {
        if out.len() <= FAST_ORDER + 1 && !out.is_empty() && t > 0.0 && t < 1.0 {
            let i = ((t * FAST_CELLS as f64) as usize).min(FAST_CELLS - 1);
            if self.fast_mode[i] != FastMode::Exact {
                return self.eval_fast(i, t, out);
            }
        }
        self.eval_exact(t, out)
    }

    /// [`Self::eval`] with the number of outputs K known at compile time (the batch paths),
    /// so that only the K polynomials asked for are evaluated and every loop unrolls.
    #[inline]
    pub(crate) fn eval_array<const K: usize>(&self, t: f64, out: &mut [f64; K]) {
        if K <= FAST_ORDER + 1 && K > 0 && t > 0.0 && t < 1.0 {
            let i = ((t * FAST_CELLS as f64) as usize).min(FAST_CELLS - 1);
            if self.fast_mode[i] != FastMode::Exact {
                return self.eval_fast(i, t, out);
            }
        }
        self.eval_exact(t, out)
    }

    /// Quadrature for B, Taylor jets of φ for the derivatives.
    fn eval_exact(&self, t: f64, out: &mut [f64]) {
        if out.is_empty() {
            return;
        }
        // Below λ integrate from 0, above from 1 (small values keep their relative accuracy).
        out[0] = if t <= self.kernel.lambda {
            self.head_integral(t) / self.total
        } else {
            1.0 - self.tail_integral(t) / self.total
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
