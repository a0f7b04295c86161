//! Truncated bivariate Taylor polynomials ("jets"), the arithmetic behind the chain rule of
//! every order where a triangle is composed with a map of its parameters
//! ([`TriangleAtlas`](super::TriangleAtlas)'s collapse of the square,
//! [`TriangulationBlend`](super::TriangulationBlend)'s charts and weights).
//!
//! A jet of f at (u₀, v₀) holds the coefficients c_pq = ∂^{p+q}f/∂u^p∂v^q / (p! q!) for
//! p ≤ P, q ≤ Q: f(u₀ + σ, v₀ + τ) = Σ c_pq σ^p τ^q + (terms with p > P or q > Q). The
//! rectangle is closed under products (c_pq of a product reads only indices ≤ (p, q)), so
//! sums, products and compositions with a function of one variable
//! (g ∘ f)(u₀ + σ, v₀ + τ) = Σ_m g^{(m)}(f₀)/m! (f − f₀)^m, m ≤ P + Q, are exact on it.

use smallvec::{SmallVec, smallvec};

use crate::Point;

/// A jet truncated to the rectangle p ≤ P, q ≤ Q (see the module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct Jet {
    p: usize,
    q: usize,
    c: SmallVec<[f64; 16]>,
}

/// p!.
fn factorial(p: usize) -> f64 {
    (1..=p).map(|x| x as f64).product()
}

impl Jet {
    /// The constant `value` (all derivatives zero), truncated to (P, Q).
    pub fn constant(p: usize, q: usize, value: f64) -> Self {
        let mut c = smallvec![0.0; (p + 1) * (q + 1)];
        c[0] = value;
        Jet { p, q, c }
    }

    /// The jet with value `value` and every derivative NaN (a function not differentiable
    /// there).
    pub fn nan_derivatives(p: usize, q: usize, value: f64) -> Self {
        let mut c = smallvec![f64::NAN; (p + 1) * (q + 1)];
        c[0] = value;
        Jet { p, q, c }
    }

    /// The affine function value + a σ + b τ.
    pub fn affine(p: usize, q: usize, value: f64, a: f64, b: f64) -> Self {
        let mut j = Self::constant(p, q, value);
        if p >= 1 {
            j.c[q + 1] = a;
        }
        if q >= 1 {
            j.c[1] = b;
        }
        j
    }

    /// The jet of the partials `partials[i·(Q+1) + j]` = ∂^{i+j}f/∂uⁱ∂vʲ.
    pub fn from_partials(p: usize, q: usize, partials: &[f64]) -> Self {
        let mut c: SmallVec<[f64; 16]> = smallvec![0.0; (p + 1) * (q + 1)];
        for i in 0..=p {
            for j in 0..=q {
                c[i * (q + 1) + j] = partials[i * (q + 1) + j] / (factorial(i) * factorial(j));
            }
        }
        Jet { p, q, c }
    }

    /// The truncation orders (P, Q).
    pub fn orders(&self) -> (usize, usize) {
        (self.p, self.q)
    }

    /// The value f(u₀, v₀).
    pub fn value(&self) -> f64 {
        self.c[0]
    }

    /// The coefficient c_ij.
    pub fn coefficient(&self, i: usize, j: usize) -> f64 {
        self.c[i * (self.q + 1) + j]
    }

    /// ∂^{i+j}f/∂uⁱ∂vʲ = i! j! c_ij.
    pub fn partial(&self, i: usize, j: usize) -> f64 {
        self.coefficient(i, j) * factorial(i) * factorial(j)
    }

    /// The sum.
    pub fn add(&self, other: &Jet) -> Jet {
        let mut r = self.clone();
        r.c.iter_mut().zip(&other.c).for_each(|(a, b)| *a += b);
        r
    }

    /// The difference.
    pub fn sub(&self, other: &Jet) -> Jet {
        let mut r = self.clone();
        r.c.iter_mut().zip(&other.c).for_each(|(a, b)| *a -= b);
        r
    }

    /// s · f.
    pub fn scale(&self, s: f64) -> Jet {
        let mut r = self.clone();
        r.c.iter_mut().for_each(|a| *a *= s);
        r
    }

    /// f + s.
    pub fn shift(&self, s: f64) -> Jet {
        let mut r = self.clone();
        r.c[0] += s;
        r
    }

    /// The product, truncated.
    pub fn mul(&self, other: &Jet) -> Jet {
        let cols = self.q + 1;
        let mut c: SmallVec<[f64; 16]> = smallvec![0.0; self.c.len()];
        for i in 0..=self.p {
            for j in 0..=self.q {
                let a = self.c[i * cols + j];
                if a == 0.0 {
                    continue;
                }
                for k in 0..=self.p - i {
                    for l in 0..=self.q - j {
                        c[(i + k) * cols + j + l] += a * other.c[k * cols + l];
                    }
                }
            }
        }
        Jet { p: self.p, q: self.q, c }
    }

    /// g ∘ f, given g^{(m)}(f(u₀, v₀)) for m = 0 … P + Q in `derivatives` (missing ones are
    /// taken as zero).
    pub fn compose(&self, derivatives: &[f64]) -> Jet {
        let n = self.p + self.q;
        let h = self.shift(-self.c[0]);
        let mut out = Jet::constant(self.p, self.q, derivatives.first().copied().unwrap_or(0.0));
        let mut power = Jet::constant(self.p, self.q, 1.0);
        let mut fact = 1.0;
        for m in 1..=n {
            power = power.mul(&h);
            fact *= m as f64;
            let g = derivatives.get(m).copied().unwrap_or(0.0);
            if g != 0.0 {
                out = out.add(&power.scale(g / fact));
            }
        }
        out
    }

    /// 1/f (f(u₀, v₀) ≠ 0).
    pub fn recip(&self) -> Jet {
        let x = self.c[0];
        let n = self.p + self.q;
        let mut d: SmallVec<[f64; 8]> = smallvec![0.0; n + 1];
        // (1/x)^{(m)} = (−1)^m m! / x^{m+1}.
        let mut v = 1.0 / x;
        for (m, dm) in d.iter_mut().enumerate() {
            *dm = v;
            v *= -((m + 1) as f64) / x;
        }
        self.compose(&d)
    }

    /// √f (f(u₀, v₀) > 0).
    pub fn sqrt(&self) -> Jet {
        let x = self.c[0];
        let n = self.p + self.q;
        let mut d: SmallVec<[f64; 8]> = smallvec![0.0; n + 1];
        // (x^{1/2})^{(m)} = (1/2)(1/2 − 1)…(1/2 − m + 1) x^{1/2 − m}.
        let mut coef = 1.0;
        for (m, dm) in d.iter_mut().enumerate() {
            *dm = coef * x.powf(0.5 - m as f64);
            coef *= 0.5 - m as f64;
        }
        self.compose(&d)
    }
}

/// A complex-valued jet x + i y (for conformal power maps).
#[derive(Debug, Clone, PartialEq)]
pub struct ComplexJet {
    /// The real part.
    pub re: Jet,
    /// The imaginary part.
    pub im: Jet,
}

impl ComplexJet {
    /// The product.
    pub fn mul(&self, o: &ComplexJet) -> ComplexJet {
        ComplexJet { re: self.re.mul(&o.re).sub(&self.im.mul(&o.im)), im: self.re.mul(&o.im).add(&self.im.mul(&o.re)) }
    }

    /// z^α on the principal branch about z₀ = z(u₀, v₀) ≠ 0:
    /// Σ_m C(α, m) z₀^{α−m} (z − z₀)^m.
    pub fn powf(&self, alpha: f64) -> ComplexJet {
        let (x, y) = (self.re.value(), self.im.value());
        let (p, q) = self.re.orders();
        let n = p + q;
        let h = ComplexJet { re: self.re.shift(-x), im: self.im.shift(-y) };
        let (r, theta) = (x.hypot(y), y.atan2(x));
        let base = |e: f64| {
            let m = r.powf(e);
            (m * (e * theta).cos(), m * (e * theta).sin())
        };
        let (b0, b1) = base(alpha);
        let mut out = ComplexJet { re: Jet::constant(p, q, b0), im: Jet::constant(p, q, b1) };
        let mut power = ComplexJet { re: Jet::constant(p, q, 1.0), im: Jet::constant(p, q, 0.0) };
        let mut binom = 1.0;
        for m in 1..=n {
            power = power.mul(&h);
            binom *= (alpha - (m - 1) as f64) / m as f64;
            let (cr, ci) = base(alpha - m as f64);
            let (cr, ci) = (binom * cr, binom * ci);
            out.re = out.re.add(&power.re.scale(cr).sub(&power.im.scale(ci)));
            out.im = out.im.add(&power.re.scale(ci).add(&power.im.scale(cr)));
        }
        out
    }
}

/// Writes the partials of F(X(u, v), Y(u, v)) for i ≤ P, j ≤ Q into `out[i·(Q+1) + j]`,
/// given the jets of X and Y and F's partials ∂^{a+b}F/∂X^a∂Y^b at (X₀, Y₀) for
/// a + b ≤ P + Q in `f[a·(P+Q+1) + b]`: F(X₀ + x, Y₀ + y) = Σ ∂^{ab}F/(a! b!) x^a y^b with
/// x = X − X₀, y = Y − Y₀ (whose jets start at order 1).
pub fn compose_point<const D: usize>(x: &Jet, y: &Jet, f: &[Point<D>], out: &mut [Point<D>]) {
    let (p, q) = x.orders();
    let n = p + q;
    let w = n + 1;
    let hx = x.shift(-x.value());
    let hy = y.shift(-y.value());
    let cols = q + 1;
    out[..(p + 1) * cols].iter_mut().for_each(|o| *o = Point::<D>::zeros());
    let mut px = Jet::constant(p, q, 1.0);
    for a in 0..=n {
        if a > 0 {
            px = px.mul(&hx);
        }
        let mut pxy = px.clone();
        for b in 0..=n - a {
            if b > 0 {
                pxy = pxy.mul(&hy);
            }
            let scale = 1.0 / (factorial(a) * factorial(b));
            let v = f[a * w + b] * scale;
            for i in 0..=p {
                for j in 0..=q {
                    let c = pxy.coefficient(i, j);
                    if c != 0.0 {
                        out[i * cols + j] += v * (c * factorial(i) * factorial(j));
                    }
                }
            }
        }
    }
}

/// The jet of Σ_k coefficients; convenience for weights given as jets.
pub fn sum(jets: &[Jet]) -> Option<Jet> {
    let mut it = jets.iter();
    let first = it.next()?.clone();
    Some(it.fold(first, |acc, j| acc.add(j)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sqrt_and_recip_match_closed_forms() {
        // f = 2 + σ + 3τ at order (2, 2): √f and 1/f against their Taylor coefficients.
        let f = Jet::affine(2, 2, 2.0, 1.0, 3.0);
        let s = f.sqrt();
        // ∂²√f/∂u∂v = −(1/4) f^{−3/2} · 1 · 3.
        assert!((s.partial(1, 1) + 0.75 * 2f64.powf(-1.5)).abs() < 1e-15);
        let r = f.recip();
        // ∂²(1/f)/∂v² = 2 · 9 / f³.
        assert!((r.partial(0, 2) - 18.0 / 8.0).abs() < 1e-14);
        // f · (1/f) = 1.
        let one = f.mul(&r);
        assert!((one.value() - 1.0).abs() < 1e-15 && one.c[1..].iter().all(|c| c.abs() < 1e-15));
    }

    #[test]
    fn complex_power_matches_differences() {
        // z = (1 + σ) + i (0.5 + 2τ); ζ = z^1.2; ∂ζ/∂u = 1.2 z^0.2.
        let z = ComplexJet { re: Jet::affine(1, 1, 1.0, 1.0, 0.0), im: Jet::affine(1, 1, 0.5, 0.0, 2.0) };
        let w = z.powf(1.2);
        let (r, t) = (1.25f64.sqrt(), 0.5f64.atan2(1.0));
        let d = (1.2 * r.powf(0.2) * (0.2 * t).cos(), 1.2 * r.powf(0.2) * (0.2 * t).sin());
        assert!((w.re.partial(1, 0) - d.0).abs() < 1e-14 && (w.im.partial(1, 0) - d.1).abs() < 1e-14);
    }
}
