//! The [`Surface`] trait: what every parametric surface S: \[a, b\]×\[c, d\] → ℝᴰ can do.

use smallvec::{SmallVec, smallvec};

use crate::Point;
use crate::curve::Interval;
pub use crate::surface::differential::{Curvatures, FundamentalForms, unit_normal};

/// Trimming loops in the parameter plane, as closed polygons (the last point joins the first).
#[derive(Debug, Clone, PartialEq)]
pub struct TrimLoops<'a> {
    /// The outer loop (`None`: the boundary of the domain).
    pub outer: Option<&'a [Point<2>]>,
    /// Holes.
    pub holes: Vec<&'a [Point<2>]>,
}

/// A parametric surface S(u, v) over [u₀, u₁] × [v₀, v₁].
///
/// Implementors provide the domains and [`Surface::eval_partials`] (and closedness where a
/// direction is periodic); everything else is derived. Parameters outside the domain are clamped in open directions and
/// wrapped in closed ones.
///
/// # Examples
///
/// ```
/// use splinekit::surface::Surface;
/// use splinekit::surface::model::Sphere;
/// // The sphere of radius 2: unit normals point outwards, K = 1/4 and H = ∓1/2 everywhere.
/// let s = Sphere::new(2.0).unwrap();
/// let (u, v) = (0.7, 0.3);
/// let n = s.normal(u, v).unwrap();
/// assert!((n - s.point(u, v) / 2.0).norm() < 1e-15);
/// let k = s.curvatures(u, v).unwrap();
/// assert!((k.gaussian - 0.25).abs() < 1e-14 && (k.mean.abs() - 0.5).abs() < 1e-14);
/// ```
pub trait Surface<const D: usize>: Send + Sync {
    /// The u-domain.
    fn domain_u(&self) -> Interval;
    /// The v-domain.
    fn domain_v(&self) -> Interval;
    /// Whether S(u₀, v) = S(u₁, v), continuing smoothly (open by default).
    fn is_closed_u(&self) -> bool {
        false
    }
    /// Whether S(u, v₀) = S(u, v₁), continuing smoothly (open by default).
    fn is_closed_v(&self) -> bool {
        false
    }

    /// Writes ∂^{i+j}S/∂uⁱ∂vʲ for i ≤ `du`, j ≤ `dv` into `out[i·(dv+1) + j]`
    /// (`out.len()` ≥ (du+1)(dv+1)).
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]);

    /// Evaluates a grid: `out[((a·vs.len() + b)·(du+1) + i)·(dv+1) + j]` is the (i, j)
    /// partial at (`us[a]`, `vs[b]`). Tensor-product surfaces override this to compute each
    /// basis once per row and column.
    fn eval_grid(&self, us: &[f64], vs: &[f64], du: usize, dv: usize, out: &mut [Point<D>]) {
        let w = (du + 1) * (dv + 1);
        for (a, &u) in us.iter().enumerate() {
            for (b, &v) in vs.iter().enumerate() {
                let k = a * vs.len() + b;
                self.eval_partials(u, v, du, dv, &mut out[k * w..(k + 1) * w]);
            }
        }
    }

    /// Points and unit normals on a grid (`points[a·vs.len() + b]` at (`us[a]`, `vs[b]`));
    /// normals are zero where the surface is not regular (and outside ℝ³). Tensor-product
    /// surfaces compute only S, S_u and S_v here, which is what shading needs.
    fn eval_grid_with_normals(&self, us: &[f64], vs: &[f64], points: &mut [Point<D>], normals: &mut [Point<D>]) {
        let mut values = vec![Point::<D>::zeros(); us.len() * vs.len() * 4];
        self.eval_grid(us, vs, 1, 1, &mut values);
        for ((p, n), v) in points.iter_mut().zip(normals.iter_mut()).zip(values.chunks_exact(4)) {
            *p = v[0];
            *n = unit_normal(&v[2], &v[1]).unwrap_or_else(Point::<D>::zeros);
        }
    }

    /// The u-parameters where the surface may lose smoothness (knot lines, patch joins),
    /// both ends of the domain included, in increasing order. Queries cut their patches
    /// there.
    fn breakpoints_u(&self) -> Vec<f64> {
        let d = self.domain_u();
        vec![d.start, d.end]
    }

    /// The v-parameters where the surface may lose smoothness; see
    /// [`Surface::breakpoints_u`].
    fn breakpoints_v(&self) -> Vec<f64> {
        let d = self.domain_v();
        vec![d.start, d.end]
    }

    /// For trimmed surfaces, whether (u, v) lies in the trimmed region; `None` for
    /// untrimmed surfaces (every parameter of the domain belongs to them).
    fn trim_contains(&self, _u: f64, _v: f64) -> Option<bool> {
        None
    }

    /// For trimmed surfaces, the trimming loops as closed polygons in (u, v) (the outer
    /// loop, `None` for the whole domain, and the holes); `None` for untrimmed surfaces.
    fn trim_loops(&self) -> Option<TrimLoops<'_>> {
        None
    }

    /// For the limit surface of a subdivision surface, the subdivision surface, which
    /// meshes are made of (its cage subdivided and placed on the limit) rather than of a
    /// parameter grid; `None` for other surfaces.
    fn subdivision(&self) -> Option<&crate::subdivision::surface::SubdivisionSurface> {
        None
    }

    /// For a boundary representation (faces sharing edges), the B-rep, which meshes are
    /// made of face by face with each edge sampled once (watertight) rather than of a
    /// parameter grid; `None` for other surfaces.
    fn brep(&self) -> Option<&crate::brep::Brep> {
        None
    }

    /// For triangles seen as a surface (an atlas of unit charts, one per triangle), the
    /// atlas, which meshes are made of (each triangle on a barycentric lattice) rather than
    /// of a parameter grid; `None` for other surfaces.
    fn triangle_atlas(&self) -> Option<&crate::triangle::TriangleAtlas<D>> {
        None
    }

    /// A box that certainly holds the surface, where the kind has one for the asking: the
    /// box of the control net for B-spline, Bézier and NURBS surfaces (positive weights;
    /// convex hull property; not tight in general), the cage's box for subdivision limits.
    /// `None` (the default) for other kinds.
    /// [`SurfaceExtent::extent`](crate::query::extent::SurfaceExtent::extent) takes it
    /// before sampling.
    fn enclosing_box(&self) -> Option<crate::query::Aabb<D>> {
        None
    }

    /// The point S(u, v).
    fn point(&self, u: f64, v: f64) -> Point<D> {
        let mut out = [Point::<D>::zeros()];
        self.eval_partials(u, v, 0, 0, &mut out);
        out[0]
    }

    /// The partial derivative ∂^{i+j}S/∂uⁱ∂vʲ.
    fn partial(&self, u: f64, v: f64, i: usize, j: usize) -> Point<D> {
        let mut out: SmallVec<[Point<D>; 9]> = smallvec![Point::<D>::zeros(); (i + 1) * (j + 1)];
        self.eval_partials(u, v, i, j, &mut out);
        out[i * (j + 1) + j]
    }

    /// The unit normal (S_u × S_v)/|S_u × S_v| of a surface in ℝ³; `None` in other
    /// dimensions or where the surface is not regular.
    fn normal(&self, u: f64, v: f64) -> Option<Point<D>> {
        let mut out = [Point::<D>::zeros(); 4];
        self.eval_partials(u, v, 1, 1, &mut out);
        unit_normal(&out[2], &out[1])
    }

    /// The fundamental forms (ℝ³, regular points only).
    fn fundamental_forms(&self, u: f64, v: f64) -> Option<FundamentalForms> {
        let mut o = [Point::<D>::zeros(); 9];
        self.eval_partials(u, v, 2, 2, &mut o);
        // o[i*3 + j]: (0,1) = S_v, (1,0) = S_u, (2,0) = S_uu, (1,1) = S_uv, (0,2) = S_vv.
        FundamentalForms::from_partials(&o[3], &o[1], &o[6], &o[4], &o[2])
    }

    /// Gaussian, mean and principal curvatures (ℝ³, regular points only).
    fn curvatures(&self, u: f64, v: f64) -> Option<Curvatures> {
        Some(Curvatures::of(&self.fundamental_forms(u, v)?))
    }
}

/// The unit normal at (u, v) from the partials `su`, `sv` there, or where S_u × S_v
/// vanishes (poles, apexes) its limit from just inside the domain: the normal at
/// (u, v) moved by 10⁻⁷ of the domain along v, then u, then the diagonals; `None` if the
/// surface is degenerate all around the point (or outside ℝ³).
pub fn normal_or_limit<const D: usize, S: Surface<D> + ?Sized>(
    s: &S,
    u: f64,
    v: f64,
    su: &Point<D>,
    sv: &Point<D>,
) -> Option<Point<D>> {
    if let Some(n) = unit_normal(su, sv) {
        return Some(n);
    }
    // Surfaces that know their normal where the partials vanish (a subdivision limit's
    // extraordinary vertices) say so here.
    if let Some(n) = s.normal(u, v) {
        return Some(n);
    }
    let (du, dv) = (s.domain_u(), s.domain_v());
    let (hu, hv) = (1e-7 * du.length(), 1e-7 * dv.length());
    let inside = |x: f64, d: &Interval| x >= d.start && x <= d.end;
    for (a, b) in [(0.0, hv), (0.0, -hv), (hu, 0.0), (-hu, 0.0), (hu, hv), (-hu, -hv), (hu, -hv), (-hu, hv)] {
        let (x, y) = (u + a, v + b);
        if inside(x, &du) && inside(y, &dv) {
            let mut o = [Point::<D>::zeros(); 4];
            s.eval_partials(x, y, 1, 1, &mut o);
            if let Some(n) = unit_normal(&o[2], &o[1]) {
                return Some(n);
            }
        }
    }
    None
}

// Every method, the provided ones too (a tensor-product grid path, a trimmed surface's
// loops), behind `&S`, `Box<S>` and `Arc<S>`.
crate::curve::traits::forward_through_pointers!(Surface {
    #[inline] fn domain_u(&self) -> Interval;
    #[inline] fn domain_v(&self) -> Interval;
    #[inline] fn is_closed_u(&self) -> bool;
    #[inline] fn is_closed_v(&self) -> bool;
    #[inline] fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]);
    fn eval_grid(&self, us: &[f64], vs: &[f64], du: usize, dv: usize, out: &mut [Point<D>]);
    fn eval_grid_with_normals(&self, us: &[f64], vs: &[f64], points: &mut [Point<D>], normals: &mut [Point<D>]);
    fn trim_contains(&self, u: f64, v: f64) -> Option<bool>;
    fn trim_loops(&self) -> Option<TrimLoops<'_>>;
    fn subdivision(&self) -> Option<&crate::subdivision::surface::SubdivisionSurface>;
    fn brep(&self) -> Option<&crate::brep::Brep>;
    fn triangle_atlas(&self) -> Option<&crate::triangle::TriangleAtlas<D>>;
    fn breakpoints_u(&self) -> Vec<f64>;
    fn breakpoints_v(&self) -> Vec<f64>;
    fn enclosing_box(&self) -> Option<crate::query::Aabb<D>>;
    #[inline] fn point(&self, u: f64, v: f64) -> Point<D>;
    fn partial(&self, u: f64, v: f64, i: usize, j: usize) -> Point<D>;
    fn normal(&self, u: f64, v: f64) -> Option<Point<D>>;
    fn fundamental_forms(&self, u: f64, v: f64) -> Option<FundamentalForms>;
    fn curvatures(&self, u: f64, v: f64) -> Option<Curvatures>;
});
