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

/// q = a / b on jets (b₀ ≠ 0): q_k = (a_k − Σ_{j=1}^{k} b_j q_{k−j}) / b₀.
pub fn div(a: &[f64], b: &[f64], q: &mut [f64]) {
    for k in 0..q.len() {
        let mut acc = a[k];
        for j in 1..=k {
            acc -= b[j] * q[k - j];
        }
        q[k] = acc / b[0];
    }
}

/// s = sin(g), c = cos(g) on jets: s₀ = sin g₀, c₀ = cos g₀ and, from s′ = c g′ and
/// c′ = −s g′, s_k = (1/k) Σ_{j=1}^{k} j g_j c_{k−j}, c_k = −(1/k) Σ_{j=1}^{k} j g_j s_{k−j}.
pub fn sin_cos(g: &[f64], s: &mut [f64], c: &mut [f64]) {
    let n = g.len().min(s.len()).min(c.len());
    if n == 0 {
        return;
    }
    (s[0], c[0]) = g[0].sin_cos();
    for k in 1..n {
        let (mut sk, mut ck) = (0.0, 0.0);
        for j in 1..=k {
            sk += j as f64 * g[j] * c[k - j];
            ck -= j as f64 * g[j] * s[k - j];
        }
        s[k] = sk / k as f64;
        c[k] = ck / k as f64;
    }
}

/// q = a / b on jets in two variables (b₀₀ ≠ 0), each a row-major (m + 1) × (n + 1) array
/// of the coefficients g_ij = ∂ⁱ_u∂ʲ_v g / (i! j!), `cols` = n + 1:
/// q_ij = (a_ij − Σ_{(k,l) ≤ (i,j), (k,l) ≠ (0,0)} b_kl q_{i−k, j−l}) / b₀₀, the
/// coefficients of q b = a solved in the order of i then j.
pub fn div2(a: &[f64], b: &[f64], cols: usize, q: &mut [f64]) {
    let rows = q.len() / cols;
    for i in 0..rows {
        for j in 0..cols {
            let mut acc = a[i * cols + j];
            for k in 0..=i {
                for l in 0..=j {
                    if k + l > 0 {
                        acc -= b[k * cols + l] * q[(i - k) * cols + (j - l)];
                    }
                }
            }
            q[i * cols + j] = acc / b[0];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Jets of f at t by Taylor coefficients f^{(k)}(t)/k! from `derivative(k)`.
    fn jet(n: usize, derivative: impl Fn(usize) -> f64) -> Vec<f64> {
        let mut fact = 1.0;
        (0..n)
            .map(|k| {
                if k > 0 {
                    fact *= k as f64;
                }
                derivative(k) / fact
            })
            .collect()
    }

    #[test]
    fn quotients_and_sines_of_jets_match_closed_forms() {
        let t = 0.7f64;
        // 1 / (1 + t) has k-th derivative (−1)^k k! / (1 + t)^{k+1}: coefficient (−1)^k / (1 + t)^{k+1}.
        let one = jet(8, |k| if k == 0 { 1.0 } else { 0.0 });
        let x = jet(8, |k| match k {
            0 => 1.0 + t,
            1 => 1.0,
            _ => 0.0,
        });
        let mut q = vec![0.0; 8];
        div(&one, &x, &mut q);
        for (k, qk) in q.iter().enumerate() {
            let exact = (-1f64).powi(k as i32) / (1.0 + t).powi(k as i32 + 1);
            assert!((qk - exact).abs() < 1e-14, "1/(1+t) order {k}");
        }
        // sin(2t) and cos(2t): coefficients 2^k sin(2t + kπ/2)/k!.
        let g = jet(8, |k| match k {
            0 => 2.0 * t,
            1 => 2.0,
            _ => 0.0,
        });
        let (mut s, mut c) = (vec![0.0; 8], vec![0.0; 8]);
        sin_cos(&g, &mut s, &mut c);
        let (es, ec) = (
            jet(8, |k| 2f64.powi(k as i32) * (2.0 * t + k as f64 * std::f64::consts::FRAC_PI_2).sin()),
            jet(8, |k| 2f64.powi(k as i32) * (2.0 * t + k as f64 * std::f64::consts::FRAC_PI_2).cos()),
        );
        for k in 0..8 {
            assert!((s[k] - es[k]).abs() < 1e-13 && (c[k] - ec[k]).abs() < 1e-13, "sin, cos order {k}");
        }
    }

    #[test]
    fn two_variable_quotient_matches_the_product_it_inverts() {
        // b = 2 + u + 3v + uv², a = b · (1 − u + v²): dividing a by b gives 1 − u + v² back.
        let cols = 4;
        let mut b = vec![0.0; 16];
        let mut want = vec![0.0; 16];
        (b[0], b[cols], b[1], b[cols + 2]) = (2.0, 1.0, 3.0, 1.0);
        (want[0], want[cols], want[2]) = (1.0, -1.0, 1.0);
        let mut a = vec![0.0; 16];
        for i in 0..4 {
            for j in 0..4 {
                for k in 0..=i {
                    for l in 0..=j {
                        a[i * cols + j] += b[k * cols + l] * want[(i - k) * cols + (j - l)];
                    }
                }
            }
        }
        let mut q = vec![0.0; 16];
        div2(&a, &b, cols, &mut q);
        for (k, (x, y)) in q.iter().zip(&want).enumerate() {
            assert!((x - y).abs() < 1e-14, "coefficient {k}: {x} vs {y}");
        }
    }
}
