//! Bernstein polynomials B_{i,n}(t) = C(n,i) tⁱ (1−t)^{n−i} on [0, 1].

/// All n + 1 Bernstein polynomials of degree n at t, by the stable triangular recurrence
/// B_{i,k} = (1−t) B_{i,k−1} + t B_{i−1,k−1} (NURBS Book A1.3). `out.len()` must be n + 1.
pub fn bernstein_all(degree: usize, t: f64, out: &mut [f64]) {
    out[0] = 1.0;
    let u1 = 1.0 - t;
    for j in 1..=degree {
        let mut saved = 0.0;
        for k in 0..j {
            let temp = out[k];
            out[k] = saved + u1 * temp;
            saved = t * temp;
        }
        out[j] = saved;
    }
}

/// Binomial coefficient C(n, k) as f64 (exact while it fits in 53 bits).
pub fn binomial(n: usize, k: usize) -> f64 {
    if k > n {
        return 0.0;
    }
    let k = k.min(n - k);
    let mut c = 1.0;
    for i in 0..k {
        c = c * (n - i) as f64 / (i + 1) as f64;
    }
    c.round()
}

/// The single Bernstein polynomial B_{i,n}(t).
pub fn bernstein(i: usize, degree: usize, t: f64) -> f64 {
    if i > degree {
        return 0.0;
    }
    binomial(degree, i) * t.powi(i as i32) * (1.0 - t).powi((degree - i) as i32)
}
