//! Products of polynomials in Bernstein form, exactly in the Bernstein basis (degrees ≤ 15).
//!
//! For f = Σᵢ aᵢ B_{i,m} and g = Σⱼ bⱼ B_{j,n} on [0, 1],
//! f·g = Σ_k c_k B_{k,m+n} with c_k = Σ_{i+j=k} C(m,i) C(n,j) / C(m+n,k) · aᵢ bⱼ.
//! The queries use it for (H − q)·H′ (curves, degree 3 × 2) and (H − q)·∂H (surfaces,
//! tensor products), whose coefficients bound the sign of a gradient on a piece
//! (the convex-hull property: a Bernstein polynomial lies between its extreme
//! coefficients).

/// Coefficients of the product of two Bernstein polynomials of degrees `a.len() − 1` and
/// `b.len() − 1`, with `mul(aᵢ, bⱼ)` the scalar product of two coefficients; writes
/// `a.len() + b.len() − 1` values into `out`.
pub fn product<A, B>(a: &[A], b: &[B], mul: impl Fn(&A, &B) -> f64, out: &mut [f64]) {
    let (m, n) = (a.len() - 1, b.len() - 1);
    for c in out.iter_mut().take(m + n + 1) {
        *c = 0.0;
    }
    let (bm, bn, bmn) = (binomials(m), binomials(n), binomials(m + n));
    for (i, ai) in a.iter().enumerate() {
        for (j, bj) in b.iter().enumerate() {
            out[i + j] += bm[i] * bn[j] * mul(ai, bj);
        }
    }
    for (k, c) in out.iter_mut().take(m + n + 1).enumerate() {
        *c /= bmn[k];
    }
}

/// The tensor-product version: `a` is an (m₁+1)×(m₂+1) net in row-major order
/// (`a[i·(m₂+1) + j]`), `b` an (n₁+1)×(n₂+1) net; `out` receives the
/// (m₁+n₁+1)×(m₂+n₂+1) net of the product.
pub fn product_2d<A, B>(
    a: &[A],
    (m1, m2): (usize, usize),
    b: &[B],
    (n1, n2): (usize, usize),
    mul: impl Fn(&A, &B) -> f64,
    out: &mut [f64],
) {
    let w = m2 + n2 + 1;
    for c in out.iter_mut().take((m1 + n1 + 1) * w) {
        *c = 0.0;
    }
    let (bm1, bm2, bn1, bn2) = (binomials(m1), binomials(m2), binomials(n1), binomials(n2));
    for i1 in 0..=m1 {
        for i2 in 0..=m2 {
            let ai = &a[i1 * (m2 + 1) + i2];
            let wa = bm1[i1] * bm2[i2];
            for j1 in 0..=n1 {
                for j2 in 0..=n2 {
                    out[(i1 + j1) * w + i2 + j2] += wa * bn1[j1] * bn2[j2] * mul(ai, &b[j1 * (n2 + 1) + j2]);
                }
            }
        }
    }
    let (b1, b2) = (binomials(m1 + n1), binomials(m2 + n2));
    for k1 in 0..=m1 + n1 {
        for k2 in 0..w {
            out[k1 * w + k2] /= b1[k1] * b2[k2];
        }
    }
}

/// Pascal's triangle, C(n, k) for n, k < 16 (exact in f64).
const BINOMIALS: [[f64; 16]; 16] = crate::basis::bernstein::binomial_table::<16>();

/// The row C(n, 0 …) of binomial coefficients, n ≤ 15.
#[inline]
fn binomials(n: usize) -> &'static [f64; 16] {
    &BINOMIALS[n]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::basis::bernstein_all;

    fn eval(c: &[f64], s: f64) -> f64 {
        let mut b = vec![0.0; c.len()];
        bernstein_all(c.len() - 1, s, &mut b);
        c.iter().zip(&b).map(|(x, y)| x * y).sum()
    }

    #[test]
    fn product_matches_pointwise_multiplication() {
        let (a, b) = ([1.0, -2.0, 0.5, 3.0], [0.25, 4.0, -1.0]);
        let mut c = [0.0; 6];
        product(&a, &b, |x, y| x * y, &mut c);
        for k in 0..=10 {
            let s = k as f64 / 10.0;
            assert!((eval(&c, s) - eval(&a, s) * eval(&b, s)).abs() < 1e-14);
        }
    }

    #[test]
    fn tensor_product_matches_pointwise_multiplication() {
        let a: Vec<f64> = (0..12).map(|k| (k as f64 * 0.7).sin()).collect(); // 3×4: degrees (2, 3)
        let b: Vec<f64> = (0..6).map(|k| (k as f64 * 1.3).cos()).collect(); // 2×3: degrees (1, 2)
        let mut c = vec![0.0; 4 * 6];
        product_2d(&a, (2, 3), &b, (1, 2), |x, y| x * y, &mut c);
        let eval2 = |net: &[f64], (d1, d2): (usize, usize), u: f64, v: f64| {
            let rows: Vec<f64> = (0..=d1).map(|i| eval(&net[i * (d2 + 1)..(i + 1) * (d2 + 1)], v)).collect();
            eval(&rows, u)
        };
        for (u, v) in [(0.0, 0.0), (0.3, 0.9), (1.0, 0.5), (0.71, 0.13)] {
            let want = eval2(&a, (2, 3), u, v) * eval2(&b, (1, 2), u, v);
            assert!((eval2(&c, (3, 5), u, v) - want).abs() < 1e-13);
        }
    }
}
