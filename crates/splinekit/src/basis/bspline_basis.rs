//! The B-spline basis: the p + 1 non-zero functions N_{i−p..i,p}(t) on a span and their
//! derivatives (Cox–de Boor recursion in the triangular form of Piegl & Tiller,
//! *The NURBS Book*, algorithms A2.2 and A2.3).
//!
//! N_{i,0}(t) = 1 on [t_i, t_{i+1}), and
//! N_{i,p}(t) = (t − t_i)/(t_{i+p} − t_i) N_{i,p−1}(t) + (t_{i+p+1} − t)/(t_{i+p+1} − t_{i+1}) N_{i+1,p−1}(t).
//!
//! Scratch space lives on the stack for degree < 8; higher degrees spill to the heap.

use smallvec::{SmallVec, smallvec};

/// Inline capacity of per-call scratch buffers.
pub(crate) const INLINE: usize = 8;

/// Writes N_{span−p+r, p}(t), r = 0 … p, into `out[..=p]`. Requires t_span < t_{span+1}.
#[inline]
pub fn basis_functions(knots: &[f64], degree: usize, span: usize, t: f64, out: &mut [f64]) {
    let p = degree;
    let mut left: SmallVec<[f64; INLINE]> = smallvec![0.0; p + 1];
    let mut right: SmallVec<[f64; INLINE]> = smallvec![0.0; p + 1];
    out[0] = 1.0;
    for j in 1..=p {
        left[j] = t - knots[span + 1 - j];
        right[j] = knots[span + j] - t;
        let mut saved = 0.0;
        for r in 0..j {
            let temp = out[r] / (right[r + 1] + left[j - r]);
            out[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        out[j] = saved;
    }
}

/// Basis values and derivatives: `ders[k*(p+1) + r]` = d^k/dt^k N_{span−p+r,p}(t) for
/// k = 0 … `order` (orders above p are zero). `ders.len()` must be ≥ (order+1)(p+1).
pub fn basis_derivatives(knots: &[f64], degree: usize, span: usize, t: f64, order: usize, ders: &mut [f64]) {
    let p = degree;
    let w = p + 1;
    let n = order.min(p);
    // ndu[j][r] stored row-major (p+1)x(p+1): upper triangle basis, lower knot differences.
    let mut ndu: SmallVec<[f64; INLINE * INLINE]> = smallvec![0.0; w * w];
    let mut left: SmallVec<[f64; INLINE]> = smallvec![0.0; w];
    let mut right: SmallVec<[f64; INLINE]> = smallvec![0.0; w];
    ndu[0] = 1.0;
    for j in 1..=p {
        left[j] = t - knots[span + 1 - j];
        right[j] = knots[span + j] - t;
        let mut saved = 0.0;
        for r in 0..j {
            ndu[j * w + r] = right[r + 1] + left[j - r];
            let temp = ndu[r * w + j - 1] / ndu[j * w + r];
            ndu[r * w + j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j * w + j] = saved;
    }
    for j in 0..=p {
        ders[j] = ndu[j * w + p];
    }
    for v in ders[w..(order + 1) * w].iter_mut() {
        *v = 0.0;
    }
    if n == 0 {
        return;
    }
    let mut a: SmallVec<[f64; 2 * INLINE]> = smallvec![0.0; 2 * w];
    for r in 0..=p {
        let (mut s1, mut s2) = (0usize, 1usize);
        a[0] = 1.0;
        for k in 1..=n {
            let mut d = 0.0;
            let rk = r as isize - k as isize;
            let pk = p - k;
            if r >= k {
                let rk = rk as usize;
                a[s2 * w] = a[s1 * w] / ndu[(pk + 1) * w + rk];
                d = a[s2 * w] * ndu[rk * w + pk];
            }
            let j1: usize = if rk >= -1 { 1 } else { (-rk) as usize };
            let j2: usize = if r as isize - 1 <= pk as isize { k - 1 } else { p - r };
            for j in j1..=j2 {
                let idx = (rk + j as isize) as usize;
                a[s2 * w + j] = (a[s1 * w + j] - a[s1 * w + j - 1]) / ndu[(pk + 1) * w + idx];
                d += a[s2 * w + j] * ndu[idx * w + pk];
            }
            if r <= pk {
                a[s2 * w + k] = -a[s1 * w + k - 1] / ndu[(pk + 1) * w + r];
                d += a[s2 * w + k] * ndu[r * w + pk];
            }
            ders[k * w + r] = d;
            std::mem::swap(&mut s1, &mut s2);
        }
    }
    let mut factor = p as f64;
    for k in 1..=n {
        for j in 0..=p {
            ders[k * w + j] *= factor;
        }
        factor *= (p - k) as f64;
    }
}

/// Value of the single basis function N_{i,p}(t) (A2.4), for plots and tests.
/// Uses the right limit, except at the last knot where the last function takes the value 1.
pub fn basis_function(knots: &[f64], degree: usize, i: usize, t: f64) -> f64 {
    let p = degree;
    let m = knots.len() - 1;
    if (i == 0 && t == knots[0]) || (i == m - p - 1 && t == knots[m]) {
        return 1.0;
    }
    if t < knots[i] || t >= knots[i + p + 1] {
        return 0.0;
    }
    let mut n: SmallVec<[f64; INLINE]> = smallvec![0.0; p + 1];
    for (j, v) in n.iter_mut().enumerate() {
        *v = if t >= knots[i + j] && t < knots[i + j + 1] { 1.0 } else { 0.0 };
    }
    for k in 1..=p {
        let mut saved = if n[0] == 0.0 { 0.0 } else { (t - knots[i]) * n[0] / (knots[i + k] - knots[i]) };
        for j in 0..(p - k + 1) {
            let ul = knots[i + j + 1];
            let ur = knots[i + j + k + 1];
            if n[j + 1] == 0.0 {
                n[j] = saved;
                saved = 0.0;
            } else {
                let temp = n[j + 1] / (ur - ul);
                n[j] = saved + (ur - t) * temp;
                saved = (t - ul) * temp;
            }
        }
    }
    n[0]
}
