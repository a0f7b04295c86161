//! The triangular control net of a Bézier triangle and the algorithms that work on it,
//! written once over any [`Coefficient`] (points for polynomial triangles, homogeneous
//! points for rational ones).
//!
//! A net of degree n holds the (n+1)(n+2)/2 coefficients b_ijk, i + j + k = n, of
//!
//! T(u, v, w) = Σ_{i+j+k=n} B^n_ijk(u, v, w) b_ijk,  B^n_ijk = n!/(i! j! k!) uⁱ vʲ wᵏ,
//!
//! (Farin, *Curves and Surfaces for CAGD*, 5th ed., ch. 17; Lai & Schumaker, *Spline
//! Functions on Triangulations*, ch. 2). **Storage order**: by rows of falling i (the power
//! of u), and inside a row by falling j, so b_n00 comes first and b_00n last:
//! b_n00, b_(n−1)10, b_(n−1)01, b_(n−2)20, b_(n−2)11, b_(n−2)02, …; the position of b_ijk is
//! [`net_index`]`(j, k)` = (j+k)(j+k+1)/2 + k (GMlib's order).
//!
//! Every algorithm is one *step* of de Casteljau's algorithm with some argument
//! a = (a₁, a₂, a₃), taking a net of degree m to one of degree m − 1,
//!
//! b'_I = a₁ b_{I+e₁} + a₂ b_{I+e₂} + a₃ b_{I+e₃},  |I| = m − 1,
//!
//! and the blossom b[a¹, …, aⁿ] is n such steps (in any order: the blossom is symmetric).
//! With a = (u, v, w) the steps are de Casteljau's evaluation; with a direction d
//! (d₁ + d₂ + d₃ = 0) one step is the difference Δ_d of Farin's directional derivative
//! D_d T = n Σ B^{n−1}_I Δ_d b_I.

use smallvec::{SmallVec, smallvec};

use crate::Coefficient;
use crate::basis::binomial;
use crate::error::{Error, Result};

/// The highest degree a Bézier triangle may have (496 control points); beyond it the
/// multinomial weights lose exactness long before anyone needs such a net.
pub const MAX_DEGREE: usize = 30;

/// The number of control points of a net of degree n, (n+1)(n+2)/2.
#[inline]
pub const fn net_len(degree: usize) -> usize {
    (degree + 1) * (degree + 2) / 2
}

/// The position of b_ijk in a net's storage, (j+k)(j+k+1)/2 + k (i = n − j − k is
/// implied; see the [module documentation](self) for the order).
///
/// # Examples
///
/// ```
/// use splinekit::triangle::net_index;
/// // Degree 2: b_200, b_110, b_101, b_020, b_011, b_002.
/// assert_eq!([net_index(0, 0), net_index(1, 0), net_index(0, 1), net_index(2, 0), net_index(1, 1), net_index(0, 2)], [0, 1, 2, 3, 4, 5]);
/// ```
#[inline]
pub const fn net_index(j: usize, k: usize) -> usize {
    (j + k) * (j + k + 1) / 2 + k
}

/// The multi-indices (i, j, k) of a net of degree n in storage order.
pub fn multi_indices(degree: usize) -> impl Iterator<Item = (usize, usize, usize)> {
    (0..=degree).flat_map(move |r| (0..=r).map(move |k| (degree - r, r - k, k)))
}

/// The degree n of a net of `len` points ((n+1)(n+2)/2 = len), or an error naming `field`.
pub fn degree_of_len(len: usize, field: &str) -> Result<usize> {
    let mut n = 0;
    while net_len(n) < len && n <= MAX_DEGREE {
        n += 1;
    }
    if net_len(n) != len {
        return Err(Error::count(
            field,
            "a triangular number of points, (n+1)(n+2)/2 for degree n: 1, 3, 6, 10, 15, …",
            len,
        ));
    }
    if n > MAX_DEGREE {
        return Err(Error::invalid(field, format!("degree {n} exceeds the largest supported, {MAX_DEGREE}")));
    }
    Ok(n)
}

/// n!/(n − r)!, the factor of an r-th derivative of a degree-n triangle.
#[inline]
pub(crate) fn falling(n: usize, r: usize) -> f64 {
    ((n - r + 1)..=n).map(|x| x as f64).product()
}

/// Buffers big enough for degree 7 nets stay on the stack.
type NetBuf<T> = SmallVec<[T; 36]>;

/// The argument of a step in the direction of increasing u (w = 1 − u − v falls).
pub(crate) const DIR_U: [f64; 3] = [1.0, 0.0, -1.0];
/// The argument of a step in the direction of increasing v.
pub(crate) const DIR_V: [f64; 3] = [0.0, 1.0, -1.0];

/// One de Casteljau step with argument `a` on the first [`net_len`]`(m)` entries of `net`
/// (degree m), in place: afterwards the first `net_len(m − 1)` entries hold the net of
/// degree m − 1. Row r of the new net reads rows r and r + 1 of the old one, which are
/// still unchanged when it is written (rows are done in increasing order).
#[inline]
pub(crate) fn step<T: Coefficient>(net: &mut [T], m: usize, a: [f64; 3]) {
    for r in 0..m {
        let row = r * (r + 1) / 2;
        let next = (r + 1) * (r + 2) / 2;
        for k in 0..=r {
            net[row + k] = net[row + k] * a[0] + net[next + k] * a[1] + net[next + k + 1] * a[2];
        }
    }
}

/// Σ_{i+j+k=m} m!/(i! j! k!) uⁱ vʲ wᵏ b_ijk, the Bernstein form of a net of degree m,
/// summed row by row: Σ_r C(m, r) u^{m−r} Σ_k C(r, k) v^{r−k} wᵏ b.
pub(crate) fn bernstein_sum<T: Coefficient>(net: &[T], m: usize, u: f64, v: f64, w: f64) -> T {
    let mut pu: SmallVec<[f64; 32]> = smallvec![1.0; m + 1];
    let mut pv: SmallVec<[f64; 32]> = smallvec![1.0; m + 1];
    let mut pw: SmallVec<[f64; 32]> = smallvec![1.0; m + 1];
    for e in 1..=m {
        pu[e] = pu[e - 1] * u;
        pv[e] = pv[e - 1] * v;
        pw[e] = pw[e - 1] * w;
    }
    let mut total = T::zero();
    for r in 0..=m {
        let row = r * (r + 1) / 2;
        let mut inner = T::zero();
        let mut c = 1.0;
        for k in 0..=r {
            inner += net[row + k] * (c * pv[r - k] * pw[k]);
            c = c * (r - k) as f64 / (k + 1) as f64;
        }
        total += inner * (binomial(m, r) * pu[m - r]);
    }
    total
}

/// De Casteljau's algorithm for degree N (LEN = (N+1)(N+2)/2 points) on an array: every
/// loop has a constant trip count, so the net stays in registers and the steps unroll.
#[inline(always)]
fn de_casteljau_fixed<T: Coefficient, const N: usize, const LEN: usize>(points: &[T], lam: [f64; 3]) -> T {
    let mut b: [T; LEN] = std::array::from_fn(|i| points[i]);
    for m in (1..=N).rev() {
        step(&mut b, m, lam);
    }
    b[0]
}

/// A triangular net of degree n (see the module documentation).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct TriangularNet<T> {
    degree: usize,
    points: Vec<T>,
}

impl<T: Coefficient> TriangularNet<T> {
    /// A net of the degree its length gives.
    pub(crate) fn new(points: Vec<T>, field: &str) -> Result<Self> {
        let degree = degree_of_len(points.len(), field)?;
        Ok(TriangularNet { degree, points })
    }

    pub(crate) fn degree(&self) -> usize {
        self.degree
    }

    pub(crate) fn points(&self) -> &[T] {
        &self.points
    }

    fn buffer(&self) -> NetBuf<T> {
        self.points.iter().copied().collect()
    }

    /// T(u, v, w) by de Casteljau's algorithm: n steps with argument (u, v, w); degrees
    /// 1 … 4 on a fixed-size array ([`de_casteljau_fixed`]), higher ones on a buffer
    /// ([`Self::de_casteljau_generic`]).
    #[inline]
    pub(crate) fn de_casteljau(&self, u: f64, v: f64, w: f64) -> T {
        let lam = [u, v, w];
        match self.degree {
            0 => self.points[0],
            1 => de_casteljau_fixed::<T, 1, 3>(&self.points, lam),
            2 => de_casteljau_fixed::<T, 2, 6>(&self.points, lam),
            3 => de_casteljau_fixed::<T, 3, 10>(&self.points, lam),
            4 => de_casteljau_fixed::<T, 4, 15>(&self.points, lam),
            _ => self.de_casteljau_generic(u, v, w),
        }
    }

    /// De Casteljau's algorithm on a buffer, for every degree (the path the fixed-size one
    /// is tested against).
    pub(crate) fn de_casteljau_generic(&self, u: f64, v: f64, w: f64) -> T {
        let mut b = self.buffer();
        for m in (1..=self.degree).rev() {
            step(&mut b, m, [u, v, w]);
        }
        b[0]
    }

    /// T(u, v, w) by the Bernstein form.
    pub(crate) fn bernstein(&self, u: f64, v: f64, w: f64) -> T {
        bernstein_sum(&self.points, self.degree, u, v, w)
    }

    /// ∂^{p+q}T/∂u^p∂v^q at (u, v, 1 − u − v) for p ≤ du, q ≤ dv into `out[p·(dv+1) + q]`,
    /// by de Casteljau: n!/(n−p−q)! b[λ^{n−p−q}, e_u^p, e_v^q] with λ = (u, v, w),
    /// e_u = (1, 0, −1), e_v = (0, 1, −1). The n − R steps with λ common to every order
    /// (R the highest total order asked, at most n) are done once.
    pub(crate) fn partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [T]) {
        let n = self.degree;
        let lam = [u, v, 1.0 - u - v];
        let top = (du + dv).min(n);
        let mut base = self.buffer();
        for m in (top + 1..=n).rev() {
            step(&mut base, m, lam);
        }
        let len = net_len(top);
        let mut tmp: NetBuf<T> = smallvec![T::zero(); len];
        for p in 0..=du {
            for q in 0..=dv {
                let r = p + q;
                out[p * (dv + 1) + q] = if r > n {
                    T::zero()
                } else {
                    tmp.copy_from_slice(&base[..len]);
                    let mut m = top;
                    for a in std::iter::repeat_n(DIR_U, p).chain(std::iter::repeat_n(DIR_V, q)) {
                        step(&mut tmp, m, a);
                        m -= 1;
                    }
                    while m > 0 {
                        step(&mut tmp, m, lam);
                        m -= 1;
                    }
                    tmp[0] * falling(n, r)
                };
            }
        }
    }

    /// The partials of [`Self::partials`] by the Bernstein form: the difference net
    /// Δ_u^p Δ_v^q b (degree n − p − q) summed against the Bernstein polynomials,
    /// times n!/(n−p−q)!.
    pub(crate) fn partials_bernstein(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [T]) {
        let n = self.degree;
        let w = 1.0 - u - v;
        let mut tmp = self.buffer();
        for p in 0..=du {
            for q in 0..=dv {
                let r = p + q;
                out[p * (dv + 1) + q] = if r > n {
                    T::zero()
                } else {
                    tmp.copy_from_slice(&self.points);
                    let mut m = n;
                    for a in std::iter::repeat_n(DIR_U, p).chain(std::iter::repeat_n(DIR_V, q)) {
                        step(&mut tmp, m, a);
                        m -= 1;
                    }
                    bernstein_sum(&tmp, m, u, v, w) * falling(n, r)
                };
            }
        }
    }

    /// The derivatives d^r/dt^r T(λ + t d) for r < `out.len()`, d₁ + d₂ + d₃ = 0:
    /// n!/(n−r)! b[λ^{n−r}, d^r] (Farin, eq. 17.13).
    pub(crate) fn directional(&self, lam: [f64; 3], d: [f64; 3], out: &mut [T]) {
        let n = self.degree;
        let top = (out.len() - 1).min(n);
        let mut base = self.buffer();
        for m in (top + 1..=n).rev() {
            step(&mut base, m, lam);
        }
        let len = net_len(top);
        let mut tmp: NetBuf<T> = smallvec![T::zero(); len];
        for (r, o) in out.iter_mut().enumerate() {
            *o = if r > n {
                T::zero()
            } else {
                tmp.copy_from_slice(&base[..len]);
                let mut m = top;
                for _ in 0..r {
                    step(&mut tmp, m, d);
                    m -= 1;
                }
                while m > 0 {
                    step(&mut tmp, m, lam);
                    m -= 1;
                }
                tmp[0] * falling(n, r)
            };
        }
    }

    /// The blossom b[a¹, …, aⁿ] (`args.len()` = n).
    pub(crate) fn blossom(&self, args: &[[f64; 3]]) -> T {
        let mut b = self.buffer();
        for (s, a) in args.iter().enumerate() {
            step(&mut b, self.degree - s, *a);
        }
        b[0]
    }

    /// The net of T restricted to the triangle with corners A, B, C (barycentric points of
    /// this triangle): T'(u, v, w) = T(uA + vB + wC), whose control points are the blossom
    /// values b'_ijk = b[Aⁱ, Bʲ, Cᵏ] (Farin, §17.4; Lai & Schumaker, Thm 2.39).
    pub(crate) fn restricted(&self, corners: &[[f64; 3]; 3]) -> Self {
        let n = self.degree;
        let mut args: SmallVec<[[f64; 3]; 32]> = smallvec![[0.0; 3]; n];
        let points = multi_indices(n)
            .map(|(i, j, _)| {
                for (s, a) in args.iter_mut().enumerate() {
                    *a = if s < i {
                        corners[0]
                    } else if s < i + j {
                        corners[1]
                    } else {
                        corners[2]
                    };
                }
                self.blossom(&args)
            })
            .collect();
        TriangularNet { degree: n, points }
    }

    /// The same triangle as a net of degree n + 1 (Farin, eq. 17.19):
    /// b'_I = (i b_{I−e₁} + j b_{I−e₂} + k b_{I−e₃})/(n + 1), |I| = n + 1.
    pub(crate) fn elevated(&self) -> Self {
        let n = self.degree;
        let scale = 1.0 / (n + 1) as f64;
        let points = multi_indices(n + 1)
            .map(|(i, j, k)| {
                let mut acc = T::zero();
                if i > 0 {
                    acc += self.points[net_index(j, k)] * (i as f64);
                }
                if j > 0 {
                    acc += self.points[net_index(j - 1, k)] * (j as f64);
                }
                if k > 0 {
                    acc += self.points[net_index(j, k - 1)] * (k as f64);
                }
                acc * scale
            })
            .collect();
        TriangularNet { degree: n + 1, points }
    }

    /// The net of the degenerate tensor-product patch of degree (n, n) that is this
    /// triangle under (s, t) ↦ (u, v, w) = (s(1 − t), s t, 1 − s): row m (along s) is the
    /// degree-m Bézier curve b_{m−l, l, n−m}, l = 0 … m, raised to degree n,
    /// c_l = Σ_r C(m, r) C(n−m, l−r)/C(n, l) b_r. Row 0 is corner w repeated.
    pub(crate) fn tensor_rows(&self) -> Vec<Vec<T>> {
        let n = self.degree;
        (0..=n)
            .map(|m| {
                (0..=n)
                    .map(|l| {
                        let mut acc = T::zero();
                        for r in l.saturating_sub(n - m)..=m.min(l) {
                            let c = binomial(m, r) * binomial(n - m, l - r) / binomial(n, l);
                            acc += self.points[net_index(r, n - m)] * c;
                        }
                        acc
                    })
                    .collect()
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn storage_order_and_index_agree() {
        for n in 0..8 {
            for (pos, (i, j, k)) in multi_indices(n).enumerate() {
                assert_eq!(i + j + k, n);
                assert_eq!(net_index(j, k), pos, "degree {n}, ({i}, {j}, {k})");
            }
            assert_eq!(multi_indices(n).count(), net_len(n));
            assert_eq!(degree_of_len(net_len(n), "p").unwrap(), n);
        }
        assert!(degree_of_len(7, "control_points").is_err());
        assert!(degree_of_len(0, "control_points").is_err());
    }

    #[test]
    fn the_fixed_size_de_casteljau_is_the_generic_one() {
        // Degrees 0 … 9: the unrolled sizes (1 … 4) and past them, bit for bit (the same
        // steps in the same order), on points and on homogeneous coefficients.
        let mut seed = 1u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        for n in 0..10 {
            let pts: Vec<crate::Point<3>> =
                (0..net_len(n)).map(|_| crate::Point::<3>::new(next(), next(), next())).collect();
            let hom: Vec<crate::ops::homogeneous::Homogeneous<3>> =
                pts.iter().map(|p| crate::ops::homogeneous::Homogeneous::lift(p, 1.5 + next())).collect();
            let (a, b) = (TriangularNet::new(pts, "p").unwrap(), TriangularNet::new(hom, "p").unwrap());
            for _ in 0..20 {
                let (u, v) = (next() + 0.5, next() + 0.5);
                let w = 1.0 - u - v;
                assert_eq!(a.de_casteljau(u, v, w), a.de_casteljau_generic(u, v, w), "degree {n}");
                assert_eq!(b.de_casteljau(u, v, w), b.de_casteljau_generic(u, v, w), "rational degree {n}");
            }
        }
    }

    #[test]
    fn a_linear_net_is_the_barycentric_combination() {
        let net = TriangularNet::new(vec![1.0, 10.0, 100.0], "p").unwrap();
        assert_eq!(net.de_casteljau(0.2, 0.3, 0.5), 0.2 + 3.0 + 50.0);
        assert_eq!(net.bernstein(0.2, 0.3, 0.5), 0.2 + 3.0 + 50.0);
        let mut d = [0.0; 4];
        net.partials(0.2, 0.3, 1, 1, &mut d);
        // ∂u = b_100 − b_001, ∂v = b_010 − b_001, no second derivatives.
        assert_eq!(d, [53.2, 10.0 - 100.0, 1.0 - 100.0, 0.0]);
    }
}
