//! Sub-triangles of a surface: T(u, v, w) = S(u a + v b + w c) for three points a, b, c
//! of the surface's (u, v) domain (GMlib's `PSubTriangle`).
//!
//! With w = 1 − u − v the parameter point is p(u, v) = c + u e₁ + v e₂, e₁ = a − c,
//! e₂ = b − c, an affine map, so the chain rule is exact and finite:
//!
//! ∂^{i+j}T/∂uⁱ∂vʲ = (e₁·∇)ⁱ (e₂·∇)ʲ S
//!   = Σ_{p≤i} Σ_{q≤j} C(i,p) C(j,q) e₁ₓᵖ e₁ᵧ^{i−p} e₂ₓ^q e₂ᵧ^{j−q} ∂^{i+j}S/∂x^{p+q}∂y^{i+j−p−q}.

use smallvec::{SmallVec, smallvec};

use crate::Point;
use crate::basis::binomial;
use crate::error::{Error, Result, check_points_finite};
use crate::surface::Surface;
use crate::triangle::traits::{Triangle, clamp_uv};

/// The triangle (u, v, w) ↦ S(u a + v b + w c) on a surface S.
#[derive(Debug, Clone, PartialEq)]
pub struct SubTriangle<S> {
    surface: S,
    corners: [Point<2>; 3],
}

/// Corners may stray this far (relative to the domain's length) outside an open domain.
const DOMAIN_SLACK: f64 = 1e-12;

impl<S> SubTriangle<S> {
    /// The sub-triangle of `surface` with corners a, b, c (the images of corners u, v, w)
    /// in its (u, v) domain. The corners must be finite, not collinear, and inside the
    /// domain in each open direction (closed directions wrap).
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::surface::Surface;
    /// use splinekit::surface::model::Sphere;
    /// use splinekit::triangle::{SubTriangle, Triangle};
    /// let sphere = Sphere::new(2.0).unwrap();
    /// let (a, b, c) = (Point::<2>::new(0.1, 0.2), Point::<2>::new(1.0, 0.3), Point::<2>::new(0.5, 1.0));
    /// let t = SubTriangle::new(sphere.clone(), [a, b, c]).unwrap();
    /// // T(u, v, w) = S(u a + v b + w c), the parameter computed as c + u (a − c) + v (b − c).
    /// let q = t.surface_parameter(0.2, 0.3);
    /// assert!((q - (a * 0.2 + b * 0.3 + c * 0.5)).norm() < 1e-15);
    /// assert_eq!(t.point(0.2, 0.3, 0.5), sphere.point(q.x, q.y));
    /// // The sphere's curvatures survive the reparametrisation: K = 1/4.
    /// assert!((t.curvatures(0.2, 0.3, 0.5).unwrap().gaussian - 0.25).abs() < 1e-12);
    /// assert!(SubTriangle::new(sphere, [a, a, c]).is_err());
    /// ```
    pub fn new<const D: usize>(surface: S, corners: [Point<2>; 3]) -> Result<Self>
    where
        S: Surface<D>,
    {
        check_points_finite("corners", &corners)?;
        let [a, b, c] = corners;
        let (e1, e2) = (a - c, b - c);
        let area = e1.x * e2.y - e1.y * e2.x;
        if area.abs() <= 1e-14 * e1.norm() * e2.norm() || area.is_nan() {
            return Err(Error::invalid(
                "corners",
                format!("the three points are collinear (twice the signed area is {area}): {a:?}, {b:?}, {c:?}"),
            ));
        }
        let domains =
            [(surface.domain_u(), surface.is_closed_u(), "u"), (surface.domain_v(), surface.is_closed_v(), "v")];
        for (i, p) in corners.iter().enumerate() {
            for (axis, (domain, closed, name)) in domains.iter().enumerate() {
                let slack = DOMAIN_SLACK * domain.length().max(1.0);
                let x = p[axis];
                if !closed && (x < domain.start - slack || x > domain.end + slack) {
                    return Err(Error::invalid(
                        format!("corners[{i}]"),
                        format!(
                            "{name} = {x} is outside the surface's {name}-domain [{}, {}]",
                            domain.start, domain.end
                        ),
                    ));
                }
            }
        }
        Ok(SubTriangle { surface, corners })
    }

    /// The surface.
    pub fn surface(&self) -> &S {
        &self.surface
    }

    /// The corners a, b, c in the surface's (u, v) domain.
    pub fn corners(&self) -> &[Point<2>; 3] {
        &self.corners
    }

    /// The surface parameter of (u, v, 1 − u − v): c + u (a − c) + v (b − c).
    pub fn surface_parameter(&self, u: f64, v: f64) -> Point<2> {
        let [a, b, c] = self.corners;
        c + (a - c) * u + (b - c) * v
    }
}

impl<const D: usize, S: Surface<D>> Triangle<D> for SubTriangle<S> {
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        let (u, v) = clamp_uv(u, v);
        let p = self.surface_parameter(u, v);
        if du == 0 && dv == 0 {
            out[0] = self.surface.point(p.x, p.y);
            return;
        }
        let [a, b, c] = self.corners;
        let (e1, e2) = (a - c, b - c);
        let n = du + dv;
        let w = n + 1;
        let mut s: SmallVec<[Point<D>; 25]> = smallvec![Point::<D>::zeros(); w * w];
        self.surface.eval_partials(p.x, p.y, n, n, &mut s);
        for i in 0..=du {
            for j in 0..=dv {
                let mut acc = Point::<D>::zeros();
                for pp in 0..=i {
                    for q in 0..=j {
                        let coef = binomial(i, pp)
                            * binomial(j, q)
                            * e1.x.powi(pp as i32)
                            * e1.y.powi((i - pp) as i32)
                            * e2.x.powi(q as i32)
                            * e2.y.powi((j - q) as i32);
                        if coef != 0.0 {
                            acc += s[(pp + q) * w + (i - pp + j - q)] * coef;
                        }
                    }
                }
                out[i * (dv + 1) + j] = acc;
            }
        }
    }
}
