//! Bézier triangles T(u, v, w) = Σ_{i+j+k=n} B^n_ijk(u, v, w) P_ijk of any degree n in any
//! dimension, B^n_ijk = n!/(i! j! k!) uⁱ vʲ wᵏ (Farin, *Curves and Surfaces for CAGD*,
//! ch. 17; Lai & Schumaker, *Spline Functions on Triangulations*, ch. 2).
//!
//! Control points are stored in the order of [`net_index`]: b_n00, then
//! rows of falling i, each row by falling j.

use crate::Point;
use crate::error::{Error, Result, check_points_finite};
use crate::surface::BezierSurface;
use crate::triangle::net::{TriangularNet, multi_indices, net_index};
use crate::triangle::traits::{Triangle, clamp_to_triangle, clamp_uv};

/// A polynomial Bézier triangle of degree n ≤ [`MAX_DEGREE`](super::MAX_DEGREE).
///
/// Evaluation (the [`Triangle`] methods) is de Casteljau's algorithm; the Bernstein form
/// is there too ([`BezierTriangle::point_bernstein`],
/// [`BezierTriangle::eval_partials_bernstein`]).
#[derive(Debug, Clone, PartialEq)]
pub struct BezierTriangle<const D: usize> {
    net: TriangularNet<Point<D>>,
}

/// Checks a barycentric point given as a field: finite, its sum not zero; returns it
/// divided by its sum.
pub(crate) fn barycentric_argument(field: &str, p: [f64; 3]) -> Result<[f64; 3]> {
    let s = p[0] + p[1] + p[2];
    if !(p.iter().all(|x| x.is_finite()) && s.is_finite() && s != 0.0) {
        return Err(Error::invalid(field, format!("must be finite with a non-zero sum, got {p:?}")));
    }
    Ok([p[0] / s, p[1] / s, p[2] / s])
}

/// The four children of the midpoint split: corner u's, corner v's, corner w's and the
/// middle one (each with the parent's orientation).
pub(crate) const MIDPOINT_CHILDREN: [[[f64; 3]; 3]; 4] = [
    [[1.0, 0.0, 0.0], [0.5, 0.5, 0.0], [0.5, 0.0, 0.5]],
    [[0.5, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.5, 0.5]],
    [[0.5, 0.0, 0.5], [0.0, 0.5, 0.5], [0.0, 0.0, 1.0]],
    [[0.0, 0.5, 0.5], [0.5, 0.0, 0.5], [0.5, 0.5, 0.0]],
];

/// The corners of the three children of a split at the interior point p: (p, v, w),
/// (u, p, w) and (u, v, p).
pub(crate) fn split_corners(field: &str, p: [f64; 3]) -> Result<[[[f64; 3]; 3]; 3]> {
    let p = barycentric_argument(field, p)?;
    if p.iter().any(|x| *x <= 0.0) {
        return Err(Error::invalid(
            field,
            format!("must lie inside the triangle (every barycentric coordinate > 0), got {p:?}"),
        ));
    }
    let (eu, ev, ew) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    Ok([[p, ev, ew], [eu, p, ew], [eu, ev, p]])
}

impl<const D: usize> BezierTriangle<D> {
    /// A Bézier triangle from its (n+1)(n+2)/2 control points in storage order (the degree
    /// follows from their number).
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::triangle::{BezierTriangle, Triangle};
    /// // A quadratic lifted at b_110: at the centroid T = Σ B_ijk P_ijk with B_110 = 2/9.
    /// let p = |x: f64, y: f64, z: f64| Point::<3>::new(x, y, z);
    /// let t = BezierTriangle::new(vec![
    ///     p(2.0, 0.0, 0.0), p(1.0, 1.0, 9.0), p(1.0, 0.0, 0.0),
    ///     p(0.0, 2.0, 0.0), p(0.0, 1.0, 0.0), p(0.0, 0.0, 0.0),
    /// ]).unwrap();
    /// assert_eq!(t.degree(), 2);
    /// let c = t.point(1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0);
    /// assert!((c - p(2.0 / 3.0, 2.0 / 3.0, 2.0)).norm() < 1e-15);
    /// assert!(BezierTriangle::<3>::new(vec![p(0.0, 0.0, 0.0); 4]).is_err());
    /// ```
    pub fn new(control_points: Vec<Point<D>>) -> Result<Self> {
        check_points_finite("control_points", &control_points)?;
        Ok(BezierTriangle { net: TriangularNet::new(control_points, "control_points")? })
    }

    /// The Bézier triangle of degree n with P_ijk = f(i, j, k).
    pub fn from_fn(degree: usize, f: impl FnMut((usize, usize, usize)) -> Point<D>) -> Result<Self> {
        if degree > super::MAX_DEGREE {
            return Err(Error::invalid("degree", format!("must be at most {}, got {degree}", super::MAX_DEGREE)));
        }
        Self::new(multi_indices(degree).map(f).collect())
    }

    pub(crate) fn from_net(net: TriangularNet<Point<D>>) -> Self {
        BezierTriangle { net }
    }

    /// The degree n.
    pub fn degree(&self) -> usize {
        self.net.degree()
    }

    /// The control points in storage order.
    pub fn control_points(&self) -> &[Point<D>] {
        self.net.points()
    }

    /// P_ijk, or `None` unless i + j + k = n.
    pub fn control_point(&self, i: usize, j: usize, k: usize) -> Option<&Point<D>> {
        (i + j + k == self.degree()).then(|| &self.net.points()[net_index(j, k)])
    }

    /// T(u, v, w) by de Casteljau's algorithm,
    /// b^r_I = u b^{r−1}_{I+e₁} + v b^{r−1}_{I+e₂} + w b^{r−1}_{I+e₃} for r = 1 … n
    /// (Farin, eq. 17.6); (u, v, w) is clamped as [`clamp_to_triangle`] says.
    pub fn point_de_casteljau(&self, u: f64, v: f64, w: f64) -> Point<D> {
        let (u, v) = clamp_to_triangle(u, v, w);
        self.net.de_casteljau(u, v, 1.0 - u - v)
    }

    /// T(u, v, w) by the Bernstein form Σ n!/(i! j! k!) uⁱ vʲ wᵏ P_ijk (clamped likewise).
    pub fn point_bernstein(&self, u: f64, v: f64, w: f64) -> Point<D> {
        let (u, v) = clamp_to_triangle(u, v, w);
        self.net.bernstein(u, v, 1.0 - u - v)
    }

    /// The partials of [`Triangle::eval_partials`] by the Bernstein form:
    /// ∂^{p+q}T/∂u^p∂v^q = n!/(n−p−q)! Σ_{|I|=n−p−q} B_I (Δ_u^p Δ_v^q P)_I with the forward
    /// differences Δ_u P_I = P_{I+e₁} − P_{I+e₃}, Δ_v P_I = P_{I+e₂} − P_{I+e₃}
    /// (Farin, eq. 17.12).
    pub fn eval_partials_bernstein(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        let (u, v) = clamp_uv(u, v);
        self.net.partials_bernstein(u, v, du, dv, out);
    }

    /// The same triangle as one of degree n + 1 (exact; Farin, eq. 17.19):
    /// P'_I = (i P_{I−e₁} + j P_{I−e₂} + k P_{I−e₃})/(n + 1).
    ///
    /// # Errors
    ///
    /// When the degree would exceed [`MAX_DEGREE`](super::MAX_DEGREE).
    pub fn elevate(&self) -> Result<Self> {
        if self.degree() >= super::MAX_DEGREE {
            return Err(Error::invalid(
                "degree",
                format!("cannot elevate degree {} beyond {}", self.degree(), super::MAX_DEGREE),
            ));
        }
        Ok(BezierTriangle { net: self.net.elevated() })
    }

    /// The triangle over the sub-triangle with corners a, b, c (barycentric points of this
    /// one, each divided by its sum): T'(u, v, w) = T(u a + v b + w c), exactly, by
    /// blossoming: P'_ijk = b[aⁱ, bʲ, cᵏ]. Corners outside the triangle extrapolate.
    pub fn restrict(&self, a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> Result<Self> {
        let corners = [barycentric_argument("a", a)?, barycentric_argument("b", b)?, barycentric_argument("c", c)?];
        Ok(BezierTriangle { net: self.net.restricted(&corners) })
    }

    /// Splits at the interior point p into the three triangles (p, v, w), (u, p, w),
    /// (u, v, p) (de Casteljau subdivision; Farin, §17.4): child k at (u', v', w') is
    /// T(u' q₁ + v' q₂ + w' q₃) for its corners q.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::triangle::{BezierTriangle, Triangle};
    /// let t = BezierTriangle::from_fn(3, |(i, j, k)| Point::<2>::new((i * j) as f64, (j + 2 * k) as f64)).unwrap();
    /// let p = [0.2, 0.5, 0.3];
    /// let [a, _, _] = t.split_at(p).unwrap();
    /// // Child (p, v, w) at (½, ¼, ¼) is T(½ p + ¼ e_v + ¼ e_w).
    /// let q = t.point(0.1, 0.25 + 0.25, 0.15 + 0.25);
    /// assert!((a.point(0.5, 0.25, 0.25) - q).norm() < 1e-14);
    /// ```
    pub fn split_at(&self, p: [f64; 3]) -> Result<[Self; 3]> {
        let corners = split_corners("point", p)?;
        Ok(corners.map(|c| BezierTriangle { net: self.net.restricted(&c) }))
    }

    /// Splits at the edge midpoints into four: the triangles at corners u, v, w and the
    /// middle one with corners (m_vw, m_uw, m_uv), all oriented like this one.
    pub fn split_midpoints(&self) -> [Self; 4] {
        MIDPOINT_CHILDREN.map(|c| BezierTriangle { net: self.net.restricted(&c) })
    }

    /// The exact degenerate tensor-product Bézier patch of degree (n, n) with
    /// S(s, t) = T(s(1 − t), s t, 1 − s) (see
    /// [`degenerate_patch_parameters`](super::degenerate_patch_parameters)): its edge
    /// s = 0 collapses to corner w, its edge s = 1 is the edge from u to v.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::surface::Surface;
    /// use splinekit::triangle::{BezierTriangle, Triangle, degenerate_patch_parameters};
    /// let t = BezierTriangle::from_fn(2, |(i, j, k)| Point::<3>::new(i as f64, (j * j) as f64, k as f64)).unwrap();
    /// let patch = t.to_tensor_patch();
    /// assert_eq!(patch.degrees(), (2, 2));
    /// let [u, v, w] = degenerate_patch_parameters(0.3, 0.8);
    /// assert!((patch.point(0.3, 0.8) - t.point(u, v, w)).norm() < 1e-15);
    /// ```
    pub fn to_tensor_patch(&self) -> BezierSurface<D> {
        BezierSurface::new(self.net.tensor_rows()).expect("a finite net of (n+1)² points is a valid Bézier surface")
    }

    /// The triangle with `f` applied to every control point (an affine map gives the
    /// mapped triangle: Bézier triangles are affine invariant).
    pub fn map_points(&self, f: impl Fn(&Point<D>) -> Point<D>) -> Result<Self> {
        Self::new(self.net.points().iter().map(f).collect())
    }
}

impl<const D: usize> Triangle<D> for BezierTriangle<D> {
    fn bezier_net(&self) -> Option<crate::triangle::traits::BezierNet<'_, D>> {
        Some(crate::triangle::traits::BezierNet { points: self.net.points(), weights: None })
    }

    /// De Casteljau with the λ-steps shared by every order (see the module documentation
    /// of [`super::net`]).
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        let (u, v) = clamp_uv(u, v);
        if du == 0 && dv == 0 {
            out[0] = self.net.de_casteljau(u, v, 1.0 - u - v);
        } else {
            self.net.partials(u, v, du, dv, out);
        }
    }

    /// By blossoming, n!/(n−r)! b[λ^{n−r}, d^r] (Farin, eq. 17.13), with d's mean removed.
    fn directional_derivatives(&self, u: f64, v: f64, w: f64, direction: [f64; 3], out: &mut [Point<D>]) {
        if out.is_empty() {
            return;
        }
        let (u, v) = clamp_to_triangle(u, v, w);
        let mean = (direction[0] + direction[1] + direction[2]) / 3.0;
        let d = direction.map(|x| x - mean);
        self.net.directional([u, v, 1.0 - u - v], d, out);
    }
}
