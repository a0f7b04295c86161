//! Surfaces whose coordinates are sums of separable terms a·f(u)·g(v):
//! ∂^{i+j}/∂uⁱ∂vʲ (a f(u) g(v)) = a f⁽ⁱ⁾(u) g⁽ʲ⁾(v), exact to any order.

use crate::Point;
use crate::basis::binomial;
use crate::curve::Interval;
use crate::curve::model::trig::SinCosCache;
use crate::curve::model::{Term, TrigSeries};
use smallvec::SmallVec;

/// A function of one variable with derivatives of every order.
#[derive(Debug, Clone, PartialEq)]
pub enum Factor {
    /// A trigonometric series plus constant and linear part.
    Series(TrigSeries),
    /// The polynomial Σ c_k tᵏ.
    Polynomial(Vec<f64>),
    /// ln(1 − a t) (for t < 1/a).
    LogOneMinus(f64),
    /// The product of two factors (Leibniz rule).
    Product(Box<Factor>, Box<Factor>),
    /// ln tan(t/2) (for 0 < t < π), whose derivative is csc t = 1/sin t; the higher ones
    /// are csc's, from Taylor-mode division of 1 by the jet of sin t.
    LogTanHalf,
}

impl Factor {
    /// The constant c.
    pub fn constant(c: f64) -> Self {
        Factor::Polynomial(vec![c])
    }
    /// a cos(ω t).
    pub fn cos(a: f64, w: f64) -> Self {
        Factor::Series(TrigSeries::of(&[Term::cos(a, w)]))
    }
    /// a sin(ω t).
    pub fn sin(a: f64, w: f64) -> Self {
        Factor::Series(TrigSeries::of(&[Term::sin(a, w)]))
    }
    /// The product self · other.
    pub fn times(self, other: Factor) -> Self {
        Factor::Product(Box::new(self), Box::new(other))
    }
    /// c + Σ terms.
    pub fn trig(constant: f64, terms: &[Term]) -> Self {
        Factor::Series(TrigSeries { constant, linear: 0.0, terms: SmallVec::from_slice(terms) })
    }

    /// The k-th derivative at t.
    pub fn derivative(&self, t: f64, k: usize) -> f64 {
        match self {
            Factor::Series(s) => s.derivative(t, k),
            Factor::Polynomial(c) => {
                let mut v = 0.0;
                for (n, &cn) in c.iter().enumerate().skip(k) {
                    let falling: f64 = (0..k).map(|i| (n - i) as f64).product();
                    v += cn * falling * t.powi((n - k) as i32);
                }
                v
            }
            Factor::LogOneMinus(a) => {
                let x = 1.0 - a * t;
                if k == 0 {
                    x.ln()
                } else {
                    // d^k/dt^k ln(1 − a t) = −(k − 1)! aᵏ / (1 − a t)ᵏ.
                    let fact: f64 = (1..k).map(|i| i as f64).product();
                    -fact * (a / x).powi(k as i32)
                }
            }
            Factor::Product(f, g) => {
                (0..=k).map(|j| binomial(k, j) * f.derivative(t, j) * g.derivative(t, k - j)).sum()
            }
            Factor::LogTanHalf => {
                let mut all = SmallVec::<[f64; 8]>::from_elem(0.0, k + 1);
                log_tan_half(t, &mut all);
                all[k]
            }
        }
    }

    /// The derivatives of orders 0, 1, …, `out.len()` − 1 at t into `out`: the values of
    /// [`Factor::derivative`], with one sine and cosine per series term for all orders.
    pub fn derivatives(&self, t: f64, out: &mut [f64]) {
        self.derivatives_cached(t, out, &mut SinCosCache::default());
    }

    /// [`Factor::derivatives`] sharing the sines and cosines of `cache`.
    pub fn derivatives_cached(&self, t: f64, out: &mut [f64], cache: &mut SinCosCache) {
        match self {
            Factor::Series(s) => s.derivatives_cached(t, out, cache),
            Factor::Polynomial(c) if c.len() == 1 => {
                for (k, o) in out.iter_mut().enumerate() {
                    *o = if k == 0 { c[0] } else { 0.0 };
                }
            }
            Factor::Product(f, g) => {
                let n = out.len();
                let (mut a, mut b) = (SmallVec::<[f64; 8]>::from_elem(0.0, n), SmallVec::<[f64; 8]>::from_elem(0.0, n));
                f.derivatives_cached(t, &mut a, cache);
                g.derivatives_cached(t, &mut b, cache);
                for (k, o) in out.iter_mut().enumerate() {
                    *o = (0..=k).map(|j| binomial(k, j) * a[j] * b[k - j]).sum();
                }
            }
            Factor::LogTanHalf => log_tan_half(t, out),
            _ => {
                for (k, o) in out.iter_mut().enumerate() {
                    *o = self.derivative(t, k);
                }
            }
        }
    }
}

/// The derivatives of ln tan(t/2) of orders 0 … out.len() − 1: the value, then those of
/// csc t = 1/sin t of orders 0 … out.len() − 2, from the jet of sin t (Taylor mode,
/// [`crate::taylor::div`]).
fn log_tan_half(t: f64, out: &mut [f64]) {
    let n = out.len();
    if n == 0 {
        return;
    }
    out[0] = (t / 2.0).tan().ln();
    let m = n - 1;
    let (s, c) = t.sin_cos();
    let (mut sin_jet, mut one) = (SmallVec::<[f64; 8]>::from_elem(0.0, m), SmallVec::<[f64; 8]>::from_elem(0.0, m));
    let mut fact = 1.0;
    for (k, g) in sin_jet.iter_mut().enumerate() {
        if k > 0 {
            fact *= k as f64;
        }
        *g = [s, c, -s, -c][k % 4] / fact;
    }
    if let Some(o) = one.first_mut() {
        *o = 1.0;
    }
    let mut csc = SmallVec::<[f64; 8]>::from_elem(0.0, m);
    crate::taylor::div(&one, &sin_jet, &mut csc);
    let mut fact = 1.0;
    for (k, o) in out[1..].iter_mut().enumerate() {
        if k > 0 {
            fact *= k as f64;
        }
        *o = csc[k] * fact;
    }
}

/// The parameter evaluated: wrapped into the domain when closed, clamped to it otherwise.
pub(crate) fn in_domain(domain: Interval, closed: bool, t: f64) -> f64 {
    if closed { domain.wrap_periodic(t, crate::basis::Side::Right) } else { domain.clamp(t) }
}

/// One separable term a·f(u)·g(v).
#[derive(Debug, Clone, PartialEq)]
pub struct SeparableTerm {
    /// The coefficient a.
    pub coefficient: f64,
    /// f(u).
    pub u: Factor,
    /// g(v).
    pub v: Factor,
}

/// a·f(u)·g(v).
pub fn term(coefficient: f64, u: Factor, v: Factor) -> SeparableTerm {
    SeparableTerm { coefficient, u, v }
}

/// A 3-D surface with separable coordinates over a domain.
#[derive(Debug, Clone, PartialEq)]
pub struct SeparableSurface {
    /// Terms of x, y and z.
    pub coordinates: [Vec<SeparableTerm>; 3],
    /// u-domain.
    pub domain_u: Interval,
    /// v-domain.
    pub domain_v: Interval,
    /// Closed (periodic) in u.
    pub closed_u: bool,
    /// Closed (periodic) in v.
    pub closed_v: bool,
}

impl SeparableSurface {
    /// Writes the partials (layout of [`crate::surface::Surface::eval_partials`]).
    pub fn eval_into(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<3>]) {
        let (u, v) = (in_domain(self.domain_u, self.closed_u, u), in_domain(self.domain_v, self.closed_v, v));
        let count = (du + 1) * (dv + 1);
        for o in out[..count].iter_mut() {
            *o = Point::<3>::zeros();
        }
        let (mut fu, mut gv) =
            (SmallVec::<[f64; 8]>::from_elem(0.0, du + 1), SmallVec::<[f64; 8]>::from_elem(0.0, dv + 1));
        let mut cache = SinCosCache::default();
        for (c, terms) in self.coordinates.iter().enumerate() {
            for t in terms {
                t.u.derivatives_cached(u, &mut fu, &mut cache);
                t.v.derivatives_cached(v, &mut gv, &mut cache);
                for i in 0..=du {
                    for j in 0..=dv {
                        out[i * (dv + 1) + j][c] += t.coefficient * fu[i] * gv[j];
                    }
                }
            }
        }
    }
}

/// Implements `Surface<3>` for a model-surface struct with a `surface: SeparableSurface`
/// (or a [`super::rational::RationalSurface`], which has the same fields and `eval_into`).
macro_rules! separable_model_surface {
    ($ty:ty) => {
        impl $crate::surface::Surface<3> for $ty {
            fn domain_u(&self) -> $crate::curve::Interval {
                self.surface.domain_u
            }
            fn domain_v(&self) -> $crate::curve::Interval {
                self.surface.domain_v
            }
            fn is_closed_u(&self) -> bool {
                self.surface.closed_u
            }
            fn is_closed_v(&self) -> bool {
                self.surface.closed_v
            }
            fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [$crate::Point<3>]) {
                self.surface.eval_into(u, v, du, dv, out)
            }
        }
    };
}
pub(crate) use separable_model_surface;

/// Checks a parameter is finite and positive.
pub(crate) fn positive(field: &str, v: f64) -> crate::Result<f64> {
    if v > 0.0 && v.is_finite() {
        Ok(v)
    } else {
        Err(crate::Error::invalid(field, format!("must be positive and finite, got {v}")))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn all_orders_at_once_match_one_order_at_a_time() {
        let series = Factor::Series(TrigSeries {
            constant: 0.5,
            linear: -1.25,
            terms: SmallVec::from_slice(&[
                Term::cos(2.0, 3.0),
                Term { amplitude: -0.7, frequency: 0.5, phase: 0.3, sine: true },
            ]),
        });
        let factors = [
            series.clone(),
            Factor::Polynomial(vec![1.0, -2.0, 0.5, 3.0]),
            Factor::LogOneMinus(0.4),
            series.times(Factor::Polynomial(vec![0.0, 2.0, 1.0])),
            Factor::LogTanHalf,
        ];
        for f in &factors {
            for t in [-0.9, 0.0, 0.37, 1.7].map(|t| if *f == Factor::LogTanHalf { t + 1.0 } else { t }) {
                let mut all = [0.0; 6];
                f.derivatives(t, &mut all);
                for (k, v) in all.iter().enumerate() {
                    let one = f.derivative(t, k);
                    assert!((v - one).abs() <= 1e-12 * one.abs().max(1.0), "{f:?} order {k} at {t}: {v} vs {one}");
                }
            }
        }
    }

    #[test]
    fn log_tan_half_has_the_derivatives_of_csc() {
        // d/dt ln tan(t/2) = csc t, d²/dt² = −csc t cot t, d³/dt³ = csc t (cot² t + csc² t).
        for t in [0.2f64, 1.0, 2.5] {
            let (csc, cot) = (1.0 / t.sin(), 1.0 / t.tan());
            let mut d = [0.0; 4];
            Factor::LogTanHalf.derivatives(t, &mut d);
            let exact = [(t / 2.0).tan().ln(), csc, -csc * cot, csc * (cot * cot + csc * csc)];
            for (k, (a, b)) in d.iter().zip(exact).enumerate() {
                assert!((a - b).abs() <= 1e-13 * b.abs().max(1.0), "order {k} at {t}: {a} vs {b}");
            }
        }
    }
}
