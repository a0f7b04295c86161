//! Derivatives of rational curves from their homogeneous form.
//!
//! With A(t) = Σ w_i P_i b_i(t) and w(t) = Σ w_i b_i(t), the rational curve C = A / w has
//! (Leibniz applied to A = w C, *The NURBS Book* eq. 4.8)
//!
//! C^{(k)} = ( A^{(k)} − Σ_{i=1}^{k} C(k, i) w^{(i)} C^{(k−i)} ) / w.

use crate::Point;
use crate::basis::binomial;

/// Turns `a[k] = A^{(k)}` into `C^{(k)}` in place, given `w[k] = w^{(k)}`.
#[inline]
pub fn rational_derivatives<const D: usize>(a: &mut [Point<D>], w: &[f64]) {
    let inv = 1.0 / w[0];
    for k in 0..a.len() {
        let mut v = a[k];
        for i in 1..=k {
            v -= a[k - i] * (binomial(k, i) * w[i]);
        }
        a[k] = v * inv;
    }
}
