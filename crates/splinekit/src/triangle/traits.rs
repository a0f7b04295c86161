//! The [`Triangle`] trait: what every triangular parametric surface T: Δ → ℝᴰ over the
//! barycentric triangle Δ = {(u, v, w) : u, v, w ≥ 0, u + v + w = 1} can do (GMlib's
//! `PTriangle`).
//!
//! Two of the three coordinates are independent. The kernel takes (u, v), with
//! w = 1 − u − v, as the parameters of the partial derivatives
//!
//! ∂^{i+j}T/∂uⁱ∂vʲ,
//!
//! i.e. derivatives along the parameter-plane directions e_u − e_w = (1, 0, −1) and
//! e_v − e_w = (0, 1, −1). Every other derivative follows from them by the chain rule:
//!
//! * the **directional derivative** along d = (d_u, d_v, d_w), d_u + d_v + d_w = 0 (a
//!   tangent vector of Δ), of order r: D_d^r T = Σ_i C(r, i) d_uⁱ d_v^{r−i} ∂^{r}T/∂uⁱ∂v^{r−i}
//!   (Farin, *Curves and Surfaces for CAGD*, §17.3);
//! * the **barycentric derivatives** D_u, D_v, D_w: the partial derivatives with respect to
//!   u, v and w, each taken as an independent variable, of T extended off the plane
//!   u + v + w = 1 as T(u/s, v/s, w/s), s = u + v + w (homogeneous of degree 0, the one
//!   extension every triangle has). They are D_u = (1 − u) T_u − v T_v,
//!   D_v = −u T_u + (1 − v) T_v, D_w = −u T_u − v T_v: the derivative along e_u − λ, from the
//!   point λ straight towards corner u, and so on; D_u − D_w = T_u, D_v − D_w = T_v and
//!   u D_u + v D_v + w D_w = 0. GMlib's `PBezierTriangle` differentiates the Bernstein form
//!   as a homogeneous polynomial of degree n instead; its D_u is this one plus n T (a
//!   point, not a vector: it moves with a translation of the net), so the kernel keeps
//!   the extension that gives tangent vectors for every kind.

use smallvec::{SmallVec, smallvec};

use crate::Point;
use crate::basis::binomial;
use crate::surface::{Curvatures, FundamentalForms, unit_normal};

/// (u, v) of the point of Δ nearest in the barycentric sense to (u, v, w): negative
/// coordinates become 0, then the three are divided by their sum (NaN counts as 0; all
/// zero gives the centroid). This is how every triangle clamps its parameters.
///
/// # Examples
///
/// ```
/// use splinekit::triangle::clamp_to_triangle;
/// assert_eq!(clamp_to_triangle(2.0, 1.0, 1.0), (0.5, 0.25));
/// assert_eq!(clamp_to_triangle(-1.0, 0.5, 0.5), (0.0, 0.5));
/// ```
#[inline]
pub fn clamp_to_triangle(u: f64, v: f64, w: f64) -> (f64, f64) {
    let (u, v, w) = (u.max(0.0), v.max(0.0), w.max(0.0));
    let s = u + v + w;
    if s == 1.0 {
        (u, v)
    } else if s > 0.0 && s.is_finite() {
        (u / s, v / s)
    } else {
        (1.0 / 3.0, 1.0 / 3.0)
    }
}

/// (u, v) clamped to the triangle u, v ≥ 0, u + v ≤ 1 as [`clamp_to_triangle`] does with
/// w = 1 − u − v, and unchanged (bit for bit) inside it.
#[inline]
pub(crate) fn clamp_uv(u: f64, v: f64) -> (f64, f64) {
    if u >= 0.0 && v >= 0.0 && u + v <= 1.0 { (u, v) } else { clamp_to_triangle(u, v, 1.0 - u - v) }
}

/// The control net of a Bézier triangle, as [`Triangle::bezier_net`] gives it: the points
/// in the storage order of [`net_index`](super::net_index), and the weights of a rational one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BezierNet<'a, const D: usize> {
    /// The (n+1)(n+2)/2 control points.
    pub points: &'a [Point<D>],
    /// One positive weight per point (rational triangles), or `None`.
    pub weights: Option<&'a [f64]>,
}

/// A triangular parametric surface T(u, v, w), u + v + w = 1, u, v, w ≥ 0.
///
/// Implementors provide [`Triangle::eval_partials`]; everything else is derived. Corner u
/// is (1, 0, 0), v is (0, 1, 0), w is (0, 0, 1). Parameters outside the triangle are
/// clamped by [`clamp_to_triangle`].
///
/// # Examples
///
/// ```
/// use splinekit::Point;
/// use splinekit::triangle::{BezierTriangle, Triangle};
/// // The flat triangle with corners x, y and the origin: T = u x + v y, normal +z.
/// let t = BezierTriangle::new(vec![Point::<3>::x(), Point::<3>::y(), Point::<3>::zeros()]).unwrap();
/// assert_eq!(t.point(0.2, 0.3, 0.5), Point::<3>::new(0.2, 0.3, 0.0));
/// assert_eq!(t.normal(0.2, 0.3, 0.5), Some(Point::<3>::z()));
/// // D_w is the derivative from the point towards corner w (the origin): −T.
/// let [_, _, dw] = t.barycentric_derivatives(0.2, 0.3, 0.5);
/// assert!((dw + t.point(0.2, 0.3, 0.5)).norm() < 1e-15);
/// ```
pub trait Triangle<const D: usize>: Send + Sync {
    /// Writes ∂^{i+j}T/∂uⁱ∂vʲ at (u, v, 1 − u − v) for i ≤ `du`, j ≤ `dv` into
    /// `out[i·(dv+1) + j]` (`out.len()` ≥ (du+1)(dv+1); the layout of
    /// [`Surface::eval_partials`](crate::surface::Surface::eval_partials)). (u, v) outside
    /// the triangle is clamped.
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]);

    /// The point T(u, v, w); (u, v, w) is clamped to the triangle and divided by its sum.
    fn point(&self, u: f64, v: f64, w: f64) -> Point<D> {
        let (u, v) = clamp_to_triangle(u, v, w);
        let mut out = [Point::<D>::zeros()];
        self.eval_partials(u, v, 0, 0, &mut out);
        out[0]
    }

    /// The partial derivative ∂^{i+j}T/∂uⁱ∂vʲ (w = 1 − u − v) at (u, v, w).
    fn partial(&self, u: f64, v: f64, w: f64, i: usize, j: usize) -> Point<D> {
        let (u, v) = clamp_to_triangle(u, v, w);
        let mut out: SmallVec<[Point<D>; 16]> = smallvec![Point::<D>::zeros(); (i + 1) * (j + 1)];
        self.eval_partials(u, v, i, j, &mut out);
        out[i * (j + 1) + j]
    }

    /// Writes the directional derivatives d^r/dt^r T(λ + t d) at λ = (u, v, w) for
    /// r < `out.len()` into `out[r]`: D_d^r T = Σ_i C(r, i) d_uⁱ d_v^{r−i} ∂^r T/∂uⁱ∂v^{r−i}.
    /// `direction` should sum to zero (a direction in the plane of the triangle); its mean
    /// is subtracted from it first, so (1, 0, 0) means (⅔, −⅓, −⅓).
    fn directional_derivatives(&self, u: f64, v: f64, w: f64, direction: [f64; 3], out: &mut [Point<D>]) {
        let Some(order) = out.len().checked_sub(1) else { return };
        let (u, v) = clamp_to_triangle(u, v, w);
        let mean = (direction[0] + direction[1] + direction[2]) / 3.0;
        let (a, b) = (direction[0] - mean, direction[1] - mean);
        let mut p: SmallVec<[Point<D>; 16]> = smallvec![Point::<D>::zeros(); (order + 1) * (order + 1)];
        self.eval_partials(u, v, order, order, &mut p);
        for (r, o) in out.iter_mut().enumerate() {
            let mut acc = Point::<D>::zeros();
            for i in 0..=r {
                acc += p[i * (order + 1) + (r - i)] * (binomial(r, i) * a.powi(i as i32) * b.powi((r - i) as i32));
            }
            *o = acc;
        }
    }

    /// The barycentric derivatives [D_u, D_v, D_w] at (u, v, w) (see the
    /// [module documentation](self)): D_u = (1 − u) T_u − v T_v, D_v = −u T_u + (1 − v) T_v,
    /// D_w = −u T_u − v T_v.
    fn barycentric_derivatives(&self, u: f64, v: f64, w: f64) -> [Point<D>; 3] {
        let (u, v) = clamp_to_triangle(u, v, w);
        let mut o = [Point::<D>::zeros(); 4];
        self.eval_partials(u, v, 1, 1, &mut o);
        let (tu, tv) = (o[2], o[1]);
        [tu * (1.0 - u) - tv * v, tv * (1.0 - v) - tu * u, -(tu * u + tv * v)]
    }

    /// The unit normal (T_u × T_v)/|T_u × T_v| of a triangle in ℝ³ (corners u, v, w
    /// counter-clockwise seen from the side it points to); `None` in other dimensions or
    /// where the triangle is not regular.
    fn normal(&self, u: f64, v: f64, w: f64) -> Option<Point<D>> {
        let (u, v) = clamp_to_triangle(u, v, w);
        let mut o = [Point::<D>::zeros(); 4];
        self.eval_partials(u, v, 1, 1, &mut o);
        unit_normal(&o[2], &o[1])
    }

    /// The fundamental forms in the parameters (u, v) (ℝ³, regular points only).
    fn fundamental_forms(&self, u: f64, v: f64, w: f64) -> Option<FundamentalForms> {
        let (u, v) = clamp_to_triangle(u, v, w);
        let mut o = [Point::<D>::zeros(); 9];
        self.eval_partials(u, v, 2, 2, &mut o);
        // o[i*3 + j]: (1,0) = T_u, (0,1) = T_v, (2,0) = T_uu, (1,1) = T_uv, (0,2) = T_vv.
        FundamentalForms::from_partials(&o[3], &o[1], &o[6], &o[4], &o[2])
    }

    /// The Bézier net where the triangle is a (rational) Bézier triangle, which exporters
    /// write exactly; `None` (the default) for other kinds.
    fn bezier_net(&self) -> Option<BezierNet<'_, D>> {
        None
    }

    /// Gaussian, mean and principal curvatures (ℝ³, regular points only); the mean
    /// curvature has the sign of [`Triangle::normal`]. Both are independent of the
    /// parametrisation, so they are those of the surface.
    fn curvatures(&self, u: f64, v: f64, w: f64) -> Option<Curvatures> {
        Some(Curvatures::of(&self.fundamental_forms(u, v, w)?))
    }
}

// Every method behind `&T`, `Box<T>` and `Arc<T>`.
crate::curve::traits::forward_through_pointers!(Triangle {
    #[inline] fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]);
    #[inline] fn point(&self, u: f64, v: f64, w: f64) -> Point<D>;
    fn partial(&self, u: f64, v: f64, w: f64, i: usize, j: usize) -> Point<D>;
    fn directional_derivatives(&self, u: f64, v: f64, w: f64, direction: [f64; 3], out: &mut [Point<D>]);
    fn barycentric_derivatives(&self, u: f64, v: f64, w: f64) -> [Point<D>; 3];
    fn normal(&self, u: f64, v: f64, w: f64) -> Option<Point<D>>;
    fn fundamental_forms(&self, u: f64, v: f64, w: f64) -> Option<FundamentalForms>;
    fn curvatures(&self, u: f64, v: f64, w: f64) -> Option<Curvatures>;
    fn bezier_net(&self) -> Option<BezierNet<'_, D>>;
});
