//! Truncated Taylor series arithmetic ("jets") for derivatives of any order of composed
//! elementary functions. A jet holds normalised coefficients g_k = g^{(k)}(t)/k!.

/// e = exp(g) on jets: e_0 = exp(g_0), e_k = (1/k) Σ_{j=1}^{k} j g_j e_{k−j}.
pub fn exp(g: &[f64], e: &mut [f64]) {
    let n = g.len().min(e.len());
    if n == 0 {
        return;
    }
    e[0] = g[0].exp();
    for k in 1..n {
        let mut acc = 0.0;
        for j in 1..=k {
            acc += j as f64 * g[j] * e[k - j];
        }
        e[k] = acc / k as f64;
    }
}

/// Cauchy product c = a · b on jets.
pub fn mul(a: &[f64], b: &[f64], c: &mut [f64]) {
    for k in 0..c.len() {
        c[k] = (0..=k).map(|j| a[j] * b[k - j]).sum();
    }
}

/// p = xᵃ on jets (x₀ > 0): p₀ = x₀ᵃ, p_k = (1/(k x₀)) Σ_{j=1}^{k} ((a + 1) j − k) x_j p_{k−j}.
pub fn powf(x: &[f64], a: f64, p: &mut [f64]) {
    let n = x.len().min(p.len());
    if n == 0 {
        return;
    }
    p[0] = x[0].powf(a);
    for k in 1..n {
        let mut acc = 0.0;
        for j in 1..=k {
            acc += ((a + 1.0) * j as f64 - k as f64) * x[j] * p[k - j];
        }
        p[k] = acc / (k as f64 * x[0]);
    }
}
