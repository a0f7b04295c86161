//! Triangular B-functions: three weights β_u, β_v, β_w on the triangle, made from a 1-D
//! B-function B ([`BFunction`]: ERBS, Beta-function B-splines, polynomial, …), that blend
//! three local triangles into a GERBS triangle.
//!
//! With b_i = B(λ_i) for the barycentric coordinates λ = (u, v, w) there are two forms:
//!
//! | form | β_i | needs |
//! | --- | --- | --- |
//! | [`TriangularForm::Rational`] | b_i / (b_u + b_v + b_w) | any B-function |
//! | [`TriangularForm::NonRational`] | b_i + (1 − b_u − b_v − b_w)/3 | B symmetric, B(t) + B(1 − t) = 1 |
//!
//! The rational form is the "rational version of the 1-D basis" of Dechevsky, Lakså and
//! Bang's triangular GERBS (GMlib's `ERBS_RATIONAL`, `BFBS_RATIONAL`): a Shepard-type
//! normalisation, and *rational* here means exactly that division by Σ b_j — it is rational
//! in the values of B even when B is a polynomial. The non-rational form is a sum with no
//! division: the defect 1 − Σ b_j is shared equally. Both have, for a B-function flat to
//! order k at its ends ([`BFunction::flatness`]; ERBS to every order):
//!
//! 1. **partition of unity**, β_u + β_v + β_w = 1;
//! 2. **corner interpolation**, β_i = 1 at corner i and 0 at the other two;
//! 3. **flat corners**: every partial derivative of order 1 … k of every β_j vanishes at
//!    every corner. Near corner i, b_j = O(r^{k+1}) for j ≠ i and 1 − b_i = O(r^{k+1}) (B
//!    is flat at 0 and 1), and so are the sums and quotients made of them;
//! 4. **edges**: on the edge opposite corner i, β_i = 0 (b_i = B(0) = 0, and for the
//!    non-rational form 1 − Σ b_j = 1 − B(t) − B(1 − t) = 0 there), and for symmetric B the
//!    other two are B and 1 − B along the edge: the triangle blends like the 1-D blending
//!    spline on its edges, which two triangles sharing an edge then agree on;
//! 5. **non-negativity**: the rational form always; the non-rational form when B is convex
//!    on [0, ½] (every S-shaped symmetric B-function of the kernel): then Σ b_j ≤ 1, since
//!    B(t) ≤ t on [0, ½] when all λ_i ≤ ½, and B(λ_v) + B(λ_w) ≤ B(λ_v + λ_w) = 1 − B(λ_u)
//!    (superadditivity of convex B with B(0) = 0) when λ_u > ½.
//!
//! Six variants as the issue names them are the three kinds of B (ERBS, Beta-function
//! B-spline, polynomial) in the two forms. For the cubic B(t) = 3t² − 2t³ the non-rational
//! form is the cubic Bernstein–Bézier polynomial β_u = u³ + 3u²(v + w) + 2uvw, whose
//! coefficients are 1 where i is the largest index and ⅓ at b_111 (GMlib's polynomial
//! barycentric basis of order 1, u²(3 − 2u + 6vw), differs from it only in the interior
//! term); for ERBS it is flat to every order and still needs no division.
//!
//! Derivatives: ∂^{p,q} b_u = B^{(p)}(u) for q = 0 (else 0), ∂^{p,q} b_v = B^{(q)}(v) for
//! p = 0, ∂^{p,q} b_w = (−1)^{p+q} B^{(p+q)}(w); the rational form then follows by the
//! quotient rule in two variables, β^{(k,l)} = (b^{(k,l)} − Σ_{(p,q)≠0} C(k,p) C(l,q)
//! S^{(p,q)} β^{(k−p,l−q)})/S with S = Σ b_j, to any order.

use smallvec::{SmallVec, smallvec};

use crate::basis::{BFunction, binomial};
use crate::error::{Error, Result};
use crate::triangle::traits::{clamp_to_triangle, clamp_uv};

/// How the three weights are made from the values b_i = B(λ_i) (see the
/// [module documentation](self)).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TriangularForm {
    /// β_i = b_i / Σ_j b_j.
    Rational,
    /// β_i = b_i + (1 − Σ_j b_j)/3 (symmetric B only).
    NonRational,
}

/// A triangular B-function: the weights (β_u, β_v, β_w) of a GERBS triangle.
#[derive(Debug, Clone, PartialEq)]
pub struct TriangularBFunction {
    bfunction: BFunction,
    form: TriangularForm,
}

/// B(t) + B(1 − t) may differ from 1 by this much in a symmetric B-function (the ERBS
/// table's values are within about an ulp).
const SYMMETRY_TOLERANCE: f64 = 1e-13;

impl TriangularBFunction {
    /// The triangular B-function of `bfunction` in `form`.
    ///
    /// # Errors
    ///
    /// The non-rational form of a B-function that is not symmetric (B(t) + B(1 − t) ≠ 1:
    /// ERBS with λ ≠ ½ or γ ≠ 1, Beta-function B-splines with a ≠ b), naming `bfunction`
    /// and the values; the rational form of a B-function with B(⅓) = 0 (the sum would
    /// vanish at the centroid).
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::basis::BFunction;
    /// use splinekit::triangle::{TriangularBFunction, TriangularForm};
    /// let b = TriangularBFunction::new(BFunction::erbs_default(), TriangularForm::NonRational).unwrap();
    /// let [bu, bv, bw] = b.values(0.2, 0.3, 0.5);
    /// assert!((bu + bv + bw - 1.0).abs() < 1e-15 && bu >= 0.0 && bv >= 0.0 && bw >= 0.0);
    /// assert_eq!(b.values(1.0, 0.0, 0.0), [1.0, 0.0, 0.0]);
    /// // An asymmetric Beta-function B-spline has only the rational form.
    /// assert!(TriangularBFunction::new(BFunction::beta(1, 3).unwrap(), TriangularForm::NonRational).is_err());
    /// assert!(TriangularBFunction::new(BFunction::beta(1, 3).unwrap(), TriangularForm::Rational).is_ok());
    /// ```
    pub fn new(bfunction: BFunction, form: TriangularForm) -> Result<Self> {
        match form {
            TriangularForm::NonRational => {
                for t in [0.05, 0.1, 0.2, 0.3, 1.0 / 3.0, 0.4, 0.45] {
                    let sum = bfunction.value(t) + bfunction.value(1.0 - t);
                    if (sum - 1.0).abs() > SYMMETRY_TOLERANCE {
                        return Err(Error::invalid(
                            "bfunction",
                            format!(
                                "the non-rational triangular form needs a symmetric B-function, B(t) + B(1 − t) = 1, but B({t}) + B({}) = {sum}",
                                1.0 - t
                            ),
                        ));
                    }
                }
            }
            TriangularForm::Rational => {
                let third = bfunction.value(1.0 / 3.0);
                if third.is_nan() || third <= 0.0 {
                    return Err(Error::invalid(
                        "bfunction",
                        format!("B(1/3) = {third}: the rational triangular form would divide by zero at the centroid"),
                    ));
                }
            }
        }
        Ok(TriangularBFunction { bfunction, form })
    }

    /// [`Self::new`] in the rational form.
    pub fn rational(bfunction: BFunction) -> Result<Self> {
        Self::new(bfunction, TriangularForm::Rational)
    }

    /// [`Self::new`] in the non-rational form.
    pub fn non_rational(bfunction: BFunction) -> Result<Self> {
        Self::new(bfunction, TriangularForm::NonRational)
    }

    /// The 1-D B-function.
    pub fn bfunction(&self) -> &BFunction {
        &self.bfunction
    }

    /// The form.
    pub fn form(&self) -> TriangularForm {
        self.form
    }

    /// The order k to which every partial derivative of the weights vanishes at the corners
    /// (the B-function's [`BFunction::flatness`]; `None`: every order).
    pub fn flatness(&self) -> Option<usize> {
        self.bfunction.flatness()
    }

    /// (β_u, β_v, β_w) at (u, v, w), clamped to the triangle as
    /// [`clamp_to_triangle`] says.
    pub fn values(&self, u: f64, v: f64, w: f64) -> [f64; 3] {
        let (u, v) = clamp_to_triangle(u, v, w);
        let mut out = [[0.0; 3]];
        self.eval_partials(u, v, 0, 0, &mut out);
        out[0]
    }

    /// Writes the partials ∂^{p+q}β_i/∂u^p∂v^q (w = 1 − u − v) for p ≤ `du`, q ≤ `dv` into
    /// `out[p·(dv+1) + q][i]`, i = 0, 1, 2 for β_u, β_v, β_w (see the
    /// [module documentation](self) for the formulas).
    pub fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [[f64; 3]]) {
        let (u, v) = clamp_uv(u, v);
        let w = 1.0 - u - v;
        let order = du + dv;
        let mut bu: SmallVec<[f64; 8]> = smallvec![0.0; order + 1];
        let mut bv: SmallVec<[f64; 8]> = smallvec![0.0; order + 1];
        let mut bw: SmallVec<[f64; 8]> = smallvec![0.0; order + 1];
        self.bfunction.eval(u, &mut bu);
        self.bfunction.eval(v, &mut bv);
        self.bfunction.eval(w, &mut bw);
        let cols = dv + 1;
        let n = (du + 1) * cols;
        // b[(p, q)][i] and the sum S^{(p,q)}.
        let mut b: SmallVec<[[f64; 3]; 16]> = smallvec![[0.0; 3]; n];
        let mut s: SmallVec<[f64; 16]> = smallvec![0.0; n];
        for p in 0..=du {
            for q in 0..=dv {
                let sign = if (p + q) % 2 == 0 { 1.0 } else { -1.0 };
                let x = [if q == 0 { bu[p] } else { 0.0 }, if p == 0 { bv[q] } else { 0.0 }, sign * bw[p + q]];
                b[p * cols + q] = x;
                s[p * cols + q] = x[0] + x[1] + x[2];
            }
        }
        match self.form {
            TriangularForm::NonRational => {
                for (k, (o, x)) in out.iter_mut().zip(&b).enumerate().take(n) {
                    let defect = (if k == 0 { 1.0 } else { 0.0 } - s[k]) / 3.0;
                    *o = [x[0] + defect, x[1] + defect, x[2] + defect];
                }
            }
            TriangularForm::Rational => {
                let inv = 1.0 / s[0];
                for k in 0..=du {
                    for l in 0..=dv {
                        let mut val = b[k * cols + l];
                        for p in 0..=k {
                            for q in 0..=l {
                                if p == 0 && q == 0 {
                                    continue;
                                }
                                let c = binomial(k, p) * binomial(l, q) * s[p * cols + q];
                                let prev = out[(k - p) * cols + (l - q)];
                                for i in 0..3 {
                                    val[i] -= c * prev[i];
                                }
                            }
                        }
                        out[k * cols + l] = val.map(|x| x * inv);
                    }
                }
            }
        }
    }
}
