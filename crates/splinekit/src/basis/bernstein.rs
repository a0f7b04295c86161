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

/// Pascal's triangle as a table, `t[n][k]` = C(n, k) for n, k < N (zero for k > n), built
/// at compile time row by row from C(n, k) = C(n − 1, k − 1) + C(n − 1, k); exact in f64
/// for N ≤ 57. The fixed-width kernels read their binomial weights from such a table.
pub(crate) const fn binomial_table<const N: usize>() -> [[f64; N]; N] {
    let mut t = [[0.0; N]; N];
    let mut n = 0;
    while n < N {
        t[n][0] = 1.0;
        let mut k = 1;
        while k <= n {
            t[n][k] = t[n - 1][k - 1] + t[n - 1][k];
            k += 1;
        }
        n += 1;
    }
    t
}

/// The single Bernstein polynomial B_{i,n}(t).
pub fn bernstein(i: usize, degree: usize, t: f64) -> f64 {
    if i > degree {
        return 0.0;
    }
    binomial(degree, i) * t.powi(i as i32) * (1.0 - t).powi((degree - i) as i32)
}

/// The Bernstein polynomials of degree n and their derivatives up to `order` at t:
/// `out[r·(n+1) + i]` = d^r/dt^r B_{i,n}(t), from
/// D^r B_{i,n} = n!/(n−r)! Σ_k (−1)^{r−k} C(r,k) B_{i−k,n−r} (zero for r > n).
/// `out.len()` must be (order + 1)(n + 1).
pub fn bernstein_derivatives(degree: usize, t: f64, order: usize, out: &mut [f64]) {
    let n = degree;
    let w = n + 1;
    out[..(order + 1) * w].iter_mut().for_each(|x| *x = 0.0);
    for r in 0..=order.min(n) {
        let row = &mut out[r * w..(r + 1) * w];
        bernstein_all(n - r, t, &mut row[..n - r + 1]);
        // Apply the difference b_i ← b_{i−1} − b_i r times, the row growing by one each time.
        for len in (n - r + 1)..=n {
            row[len] = row[len - 1];
            for i in (1..len).rev() {
                row[i] = row[i - 1] - row[i];
            }
            row[0] = -row[0];
        }
        let factor: f64 = ((n - r + 1)..=n).map(|x| x as f64).product();
        row.iter_mut().for_each(|x| *x *= factor);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bernstein_derivatives_match_the_power_form() {
        // B_{1,3} = 3t(1−t)², B' = 3(1−t)² − 6t(1−t), B'' = −12(1−t) + 6t, B''' = 18.
        let t = 0.3;
        let mut out = vec![0.0; 5 * 4];
        bernstein_derivatives(3, t, 4, &mut out);
        let want = [
            3.0 * t * (1.0 - t) * (1.0 - t),
            3.0 * (1.0 - t).powi(2) - 6.0 * t * (1.0 - t),
            -12.0 * (1.0 - t) + 6.0 * t,
            18.0,
            0.0,
        ];
        for r in 0..5 {
            assert!((out[r * 4 + 1] - want[r]).abs() < 1e-14, "order {r}: {} vs {}", out[r * 4 + 1], want[r]);
            let sum: f64 = out[r * 4..r * 4 + 4].iter().sum();
            assert!((sum - if r == 0 { 1.0 } else { 0.0 }).abs() < 1e-13, "partition of unity, order {r}");
        }
    }
    #[test]
    fn binomial_table_is_pascals_triangle() {
        // Against the product formula of `binomial`, row 15 included (C(15, 7) = 6435),
        // and zero right of the diagonal.
        let t = binomial_table::<16>();
        for n in 0..16 {
            for k in 0..16 {
                assert_eq!(t[n][k], binomial(n, k), "C({n}, {k})");
            }
        }
        assert_eq!((t[15][7], t[3][4]), (6435.0, 0.0));
    }
}
