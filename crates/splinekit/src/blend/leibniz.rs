//! The derivatives of a blend of two local pieces by the Leibniz rule — the one formula
//! behind two-curve blends, blending-spline curves and, once per direction, blending-spline
//! surfaces.
//!
//! With w = (t − c)/Δ, the blend f = a + B(w)(b − a) has
//!
//! f^{(r)} = a^{(r)} + Σ_{j=0}^{r} C(r, j) B^{(j)}(w) h^j (b − a)^{(r−j)},  h = 1/Δ,
//!
//! for every order r: B^{(j)} is the B-function's j-th derivative in w, and h^j the chain
//! rule of the affine map t ↦ w.

use crate::Coefficient;

/// Writes f^{(r)} for r = 0 … `out.len() − 1` into `out`, from the derivatives `a[r]`,
/// `b[r]` of the two pieces and `bf[j]` = B^{(j)}(w) (see the module documentation).
/// `a`, `b` and `bf` need at least `out.len()` entries.
///
/// # Examples
///
/// ```
/// use splinekit::blend::leibniz::blend_derivatives;
/// // a = 0, b = t (so b′ = 1), B(w) = w with Δ = 2: f = t·t/2, f′ = t, f″ = 1; at t = 3:
/// let (a, b) = ([0.0, 0.0, 0.0], [3.0, 1.0, 0.0]);
/// let bf = [1.5, 1.0, 0.0];
/// let mut f = [0.0; 3];
/// blend_derivatives(&a, &b, &bf, 0.5, &mut f);
/// assert_eq!(f, [4.5, 3.0, 1.0]);
/// ```
#[inline]
pub fn blend_derivatives<T: Coefficient>(a: &[T], b: &[T], bf: &[f64], h: f64, out: &mut [T]) {
    let n = out.len();
    blend_derivatives_strided(a, b, bf, h, out, 1, n);
}

/// [`blend_derivatives`] on every `stride`-th entry: f^{(r)} goes to `out[r·stride]` from
/// `a[r·stride]` and `b[r·stride]`, for r < `count` (the u-direction of a surface's
/// partials, laid out with the v-orders innermost).
#[inline(always)]
pub(crate) fn blend_derivatives_strided<T: Coefficient>(
    a: &[T],
    b: &[T],
    bf: &[f64],
    h: f64,
    out: &mut [T],
    stride: usize,
    count: usize,
) {
    for r in 0..count {
        let mut v = a[r * stride];
        let (mut scale, mut choose) = (1.0, 1.0);
        for j in 0..=r {
            let k = (r - j) * stride;
            v += (b[k] - a[k]) * (choose * bf[j] * scale);
            scale *= h;
            // C(r, j+1) = C(r, j)(r − j)/(j + 1), exact for the small orders used here.
            choose = choose * (r - j) as f64 / (j + 1) as f64;
        }
        out[r * stride] = v;
    }
}
