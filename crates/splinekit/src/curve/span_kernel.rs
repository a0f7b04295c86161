//! Evaluation of a spline Σ N_{i,p}(t) c_i and its derivatives on one knot span.
//!
//! The triangular Cox–de Boor scheme (NURBS Book A2.2) computes the non-zero basis
//! functions of degree 0, 1, …, p at t; row p − k is the basis of degree p − k. The k-th
//! derivative is then a spline of degree p − k on the same knots (NURBS Book eq. 3.8):
//!
//! c^{(k)}(t) = Σ_{i=s−p+k}^{s} N_{i,p−k}(t) Q^k_i,
//! Q^k_i = (p − k + 1)(Q^{k−1}_i − Q^{k−1}_{i−1}) / (t_{i+p−k+1} − t_i), Q^0_i = c_i,
//!
//! where s is the span. For i in that range t_i ≤ t_s < t_{s+1} ≤ t_{i+p−k+1}, so no
//! denominator vanishes. Cost O(p²) for the position and all derivatives together.
//!
//! Every denominator is a knot difference t_i − t_{i−j} (1 ≤ j ≤ p) independent of t — in
//! A2.2, right[r+1] + left[j−r] = t_{s+r+1} − t_{s+r+1−j} — so their reciprocals are
//! tabulated once per curve ([`ReciprocalKnotDifferences`]) and evaluation divides by
//! nothing.
//! The kernel is monomorphised on the order W = p + 1 ≤ 8 (arrays on the stack, loops the
//! compiler unrolls); higher degrees use the same algorithm with heap scratch.

use crate::Coefficient;

/// Table of 1/(t_i − t_{i−j}) for j = 1 … p (0 where the difference is 0), stored row by
/// row: entry `i·p + j − 1`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ReciprocalKnotDifferences {
    degree: usize,
    values: Vec<f64>,
}

impl ReciprocalKnotDifferences {
    /// Tabulates the reciprocals for `knots` and `degree`.
    pub fn new(knots: &[f64], degree: usize) -> Self {
        let p = degree;
        let mut values = vec![0.0; knots.len() * p];
        for i in 0..knots.len() {
            for j in 1..=p.min(i) {
                let d = knots[i] - knots[i - j];
                values[i * p + j - 1] = if d > 0.0 { 1.0 / d } else { 0.0 };
            }
        }
        ReciprocalKnotDifferences { degree, values }
    }
    /// 1/(t_i − t_{i−j}) for 1 ≤ j ≤ p (0 where the knots coincide).
    #[inline(always)]
    pub(crate) fn get(&self, i: usize, j: usize) -> f64 {
        self.values[i * self.degree + j - 1]
    }
}

/// Writes c^{(k)}(t) for k = 0 … out.len() − 1 (zero above the degree) on span `span`.
#[inline]
pub fn eval_on_span<T: Coefficient>(
    knots: &[f64],
    inv: &ReciprocalKnotDifferences,
    coefficients: &[T],
    degree: usize,
    span: usize,
    t: f64,
    out: &mut [T],
) {
    eval_local(knots, inv, &coefficients[span - degree..=span], degree, span, t, out)
}

/// As [`eval_on_span`], given only the p + 1 coefficients c_{s−p} … c_s active on the span
/// (tensor-product surfaces gather them per row).
#[inline]
pub fn eval_local<T: Coefficient>(
    knots: &[f64],
    inv: &ReciprocalKnotDifferences,
    local: &[T],
    degree: usize,
    span: usize,
    t: f64,
    out: &mut [T],
) {
    let coefficients = local;
    match degree {
        0 => {
            out[0] = coefficients[0];
            for o in out.iter_mut().skip(1) {
                *o = T::zero();
            }
        }
        1 => eval_fixed::<2, T>(knots, inv, local, span, t, out),
        2 => eval_fixed::<3, T>(knots, inv, local, span, t, out),
        3 => eval_fixed::<4, T>(knots, inv, local, span, t, out),
        4 => eval_fixed::<5, T>(knots, inv, local, span, t, out),
        5 => eval_fixed::<6, T>(knots, inv, local, span, t, out),
        6 => eval_fixed::<7, T>(knots, inv, local, span, t, out),
        7 => eval_fixed::<8, T>(knots, inv, local, span, t, out),
        _ => eval_dynamic(knots, inv, local, degree, span, t, out),
    }
}

#[inline(always)]
fn eval_fixed<const W: usize, T: Coefficient>(
    knots: &[f64],
    inv: &ReciprocalKnotDifferences,
    local: &[T],
    span: usize,
    t: f64,
    out: &mut [T],
) {
    let p = W - 1;
    // Local knots t_{s−p+1} … t_{s+p}: kn[j] = t_{s−p+1+j}, j < 2p.
    let kn = &knots[span + 1 - p..span + p + 1];
    let cs = &local[..W];
    let mut left = [0.0f64; W];
    let mut right = [0.0f64; W];
    // rows[j][r] = N_{s−j+r, j}(t).
    let mut rows = [[0.0f64; W]; W];
    rows[0][0] = 1.0;
    for j in 1..W {
        left[j] = t - kn[p - j];
        right[j] = kn[p + j - 1] - t;
        let mut saved = 0.0;
        for r in 0..j {
            let temp = rows[j - 1][r] * inv.get(span + r + 1, j);
            rows[j][r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        rows[j][j] = saved;
    }
    let mut acc = T::zero();
    for r in 0..W {
        acc += cs[r] * rows[p][r];
    }
    out[0] = acc;
    if out.len() == 1 {
        return;
    }
    let mut q: [T; W] = [T::zero(); W];
    q.copy_from_slice(cs);
    for k in 1..out.len() {
        if k > p {
            out[k] = T::zero();
            continue;
        }
        // Q^k_r for r = p … k (descending so q[r − 1] is still Q^{k−1}).
        let factor = (p - k + 1) as f64;
        for r in (k..W).rev() {
            // 1/(t_{i+p−k+1} − t_i) with i = s − p + r.
            q[r] = (q[r] - q[r - 1]) * (factor * inv.get(span + r + 1 - k, p - k + 1));
        }
        let row = &rows[p - k];
        let mut acc = T::zero();
        for r in k..W {
            acc += q[r] * row[r - k];
        }
        out[k] = acc;
    }
}

fn eval_dynamic<T: Coefficient>(
    knots: &[f64],
    inv: &ReciprocalKnotDifferences,
    local: &[T],
    p: usize,
    span: usize,
    t: f64,
    out: &mut [T],
) {
    let w = p + 1;
    let kn = &knots[span + 1 - p..span + p + 1];
    let cs = &local[..w];
    let mut left = vec![0.0; w];
    let mut right = vec![0.0; w];
    let mut rows = vec![0.0; w * w];
    rows[0] = 1.0;
    for j in 1..w {
        left[j] = t - kn[p - j];
        right[j] = kn[p + j - 1] - t;
        let mut saved = 0.0;
        for r in 0..j {
            let temp = rows[(j - 1) * w + r] * inv.get(span + r + 1, j);
            rows[j * w + r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        rows[j * w + j] = saved;
    }
    let mut acc = T::zero();
    for r in 0..w {
        acc += cs[r] * rows[p * w + r];
    }
    out[0] = acc;
    let mut q: Vec<T> = cs.to_vec();
    for k in 1..out.len() {
        if k > p {
            out[k] = T::zero();
            continue;
        }
        let factor = (p - k + 1) as f64;
        for r in (k..w).rev() {
            q[r] = (q[r] - q[r - 1]) * (factor * inv.get(span + r + 1 - k, p - k + 1));
        }
        let mut acc = T::zero();
        for r in k..w {
            acc += q[r] * rows[(p - k) * w + r - k];
        }
        out[k] = acc;
    }
}
