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
