//! GERBS triangles (GMlib's `PERBSTriangle`): three local triangles ℓ_u, ℓ_v, ℓ_w, each in
//! its own affine frame, blended by a [`TriangularBFunction`]:
//!
//! T(λ) = β_u(λ) F_u(ℓ_u(λ)) + β_v(λ) F_v(ℓ_v(λ)) + β_w(λ) F_w(ℓ_w(λ)),
//!
//! every local evaluated at the same barycentric λ = (u, v, w) (GMlib feeds local i its
//! coordinates rotated so that its own corner comes first; here a local that wants that
//! is built with its corners in that order). F_i is local i's frame acting about its
//! origin o_i = ℓ_i(corner i): F_i(x) = o_i + A_i (x − o_i) + b_i on positions, A_i on
//! derivatives, so turning or scaling a local pivots about the point it interpolates.
//!
//! Partials follow by the Leibniz rule in two variables,
//! ∂^{k,l}T = Σ_i Σ_{p≤k} Σ_{q≤l} C(k,p) C(l,q) ∂^{p,q}β_i ∂^{k−p,l−q}(F_i ∘ ℓ_i).
//!
//! **Corners.** At corner i, β_i = 1 and every partial of every β_j of order 1 … k vanishes
//! (k the B-function's flatness; every order for ERBS), so T has F_i ∘ ℓ_i's value and all
//! its partials of total order ≤ k there. **Affine invariance**: Σ β_i = 1, so an affine
//! map G applied to the three locals maps T by G.

use std::sync::Arc;

use smallvec::{SmallVec, smallvec};

use crate::Point;
use crate::basis::binomial;
use crate::error::{Error, Result};
use crate::frame::Affine;
use crate::triangle::bezier_triangle::BezierTriangle;
use crate::triangle::net::{TriangularNet, falling, multi_indices};
use crate::triangle::traits::{Triangle, clamp_uv};
use crate::triangle::triangular_bfunction::TriangularBFunction;

/// The corners u, v, w in barycentric coordinates.
const CORNERS: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

#[derive(Clone)]
struct LocalTriangle<const D: usize> {
    shape: Arc<dyn Triangle<D>>,
    origin: Point<D>,
    frame: Affine<D>,
}

/// A GERBS triangle: three framed local triangles blended by a triangular B-function.
#[derive(Clone)]
pub struct GerbsTriangle<const D: usize> {
    locals: [LocalTriangle<D>; 3],
    basis: TriangularBFunction,
}

/// Checks a local's index.
fn check_index(i: usize) -> Result<()> {
    if i < 3 { Ok(()) } else { Err(Error::invalid("local", format!("must be 0, 1 or 2 (corner u, v, w), got {i}"))) }
}

impl<const D: usize> GerbsTriangle<D> {
    /// The GERBS triangle of the locals at corners u, v, w, blended by `basis`, every frame
    /// the identity. Each local's origin is its value at its own corner.
    ///
    /// # Examples
    ///
    /// ```
    /// use std::sync::Arc;
    /// use splinekit::Point;
    /// use splinekit::basis::BFunction;
    /// use splinekit::frame::Affine;
    /// use splinekit::triangle::{BezierTriangle, GerbsTriangle, Triangle, TriangularBFunction};
    /// let flat = |z: f64| -> Arc<dyn Triangle<3>> {
    ///     Arc::new(BezierTriangle::new(vec![Point::<3>::new(1.0, 0.0, z), Point::<3>::new(0.0, 1.0, z), Point::<3>::new(0.0, 0.0, z)]).unwrap())
    /// };
    /// let basis = TriangularBFunction::rational(BFunction::erbs_default()).unwrap();
    /// let mut t = GerbsTriangle::new([flat(0.0), flat(1.0), flat(2.0)], basis).unwrap();
    /// // Each corner has its own local's value; lifting local u lifts corner u only.
    /// assert_eq!(t.point(0.0, 1.0, 0.0), Point::<3>::new(0.0, 1.0, 1.0));
    /// t.set_frame(0, Affine::translation(Point::<3>::new(0.0, 0.0, 5.0))).unwrap();
    /// assert_eq!(t.point(1.0, 0.0, 0.0), Point::<3>::new(1.0, 0.0, 5.0));
    /// assert_eq!(t.point(0.0, 0.0, 1.0), Point::<3>::new(0.0, 0.0, 2.0));
    /// ```
    pub fn new(locals: [Arc<dyn Triangle<D>>; 3], basis: TriangularBFunction) -> Result<Self> {
        let mut built: SmallVec<[LocalTriangle<D>; 3]> = SmallVec::new();
        for (i, shape) in locals.into_iter().enumerate() {
            let c = CORNERS[i];
            let origin = shape.point(c[0], c[1], c[2]);
            if !origin.iter().all(|x| x.is_finite()) {
                return Err(Error::invalid(
                    format!("locals[{i}]"),
                    format!("its value at its corner is not finite: {origin:?}"),
                ));
            }
            built.push(LocalTriangle { shape, origin, frame: Affine::identity() });
        }
        let locals = built.into_inner().unwrap_or_else(|_| unreachable!("three locals"));
        Ok(GerbsTriangle { locals, basis })
    }

    /// The GERBS triangle whose local at each corner is the Bézier triangle of `degree`
    /// matching `model`'s partials of total order ≤ `degree` there ([`hermite_local`]).
    /// With an ERBS basis T then has the model's value and those partials at all three
    /// corners (with a B-function flat to order k, those up to order min(k, degree)).
    pub fn hermite(model: &dyn Triangle<D>, degree: usize, basis: TriangularBFunction) -> Result<Self> {
        let locals: [Arc<dyn Triangle<D>>; 3] = [
            Arc::new(hermite_local(model, 0, degree)?),
            Arc::new(hermite_local(model, 1, degree)?),
            Arc::new(hermite_local(model, 2, degree)?),
        ];
        Self::new(locals, basis)
    }

    /// The triangular B-function.
    pub fn basis(&self) -> &TriangularBFunction {
        &self.basis
    }

    /// Local i (0, 1, 2 at corners u, v, w) as given, without its frame.
    pub fn local(&self, i: usize) -> Option<&Arc<dyn Triangle<D>>> {
        self.locals.get(i).map(|l| &l.shape)
    }

    /// Local i's origin, its value at its corner (the point its frame acts about).
    pub fn origin(&self, i: usize) -> Option<Point<D>> {
        self.locals.get(i).map(|l| l.origin)
    }

    /// Local i's frame.
    pub fn frame(&self, i: usize) -> Option<&Affine<D>> {
        self.locals.get(i).map(|l| &l.frame)
    }

    /// Sets local i's frame (acting about its origin).
    pub fn set_frame(&mut self, i: usize, frame: Affine<D>) -> Result<()> {
        check_index(i)?;
        self.locals[i].frame = frame;
        Ok(())
    }

    /// Local i with its frame applied: its partials (layout of
    /// [`Triangle::eval_partials`]) at (u, v).
    pub fn local_partials(&self, i: usize, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) -> Result<()> {
        check_index(i)?;
        let l = &self.locals[i];
        let n = (du + 1) * (dv + 1);
        l.shape.eval_partials(u, v, du, dv, &mut out[..n]);
        l.frame.apply_derivatives_about(&l.origin, &mut out[..n]);
        Ok(())
    }
}

impl<const D: usize> Triangle<D> for GerbsTriangle<D> {
    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        let (u, v) = clamp_uv(u, v);
        let cols = dv + 1;
        let n = (du + 1) * cols;
        let mut beta: SmallVec<[[f64; 3]; 16]> = smallvec![[0.0; 3]; n];
        self.basis.eval_partials(u, v, du, dv, &mut beta);
        let mut local: SmallVec<[Point<D>; 16]> = smallvec![Point::<D>::zeros(); n];
        out[..n].iter_mut().for_each(|o| *o = Point::<D>::zeros());
        for (i, l) in self.locals.iter().enumerate() {
            l.shape.eval_partials(u, v, du, dv, &mut local);
            l.frame.apply_derivatives_about(&l.origin, &mut local);
            for k in 0..=du {
                for m in 0..=dv {
                    let mut acc = Point::<D>::zeros();
                    for p in 0..=k {
                        for q in 0..=m {
                            let b = beta[p * cols + q][i];
                            if b != 0.0 {
                                acc += local[(k - p) * cols + (m - q)] * (binomial(k, p) * binomial(m, q) * b);
                            }
                        }
                    }
                    out[k * cols + m] += acc;
                }
            }
        }
    }
}

/// The Bézier triangle of `degree` whose partials of total order ≤ `degree` at corner
/// `corner` (0, 1, 2: u, v, w) are `model`'s: the Taylor polynomial there in Bernstein
/// form. With c the corner and o₁, o₂ the other two in cyclic order, and
/// D_{a,b} = D_{o₁−c}^a D_{o₂−c}^b model(c) (directional derivatives along the edges),
/// P = Σ_{a≤a'} Σ_{b≤b'} C(a', a) C(b', b) (d − a − b)!/d! D_{a,b} for the point with
/// indices a' at o₁, b' at o₂ and d − a' − b' at c (Newton's forward formula
/// (1 + Δ₁)^{a'} (1 + Δ₂)^{b'} b_c with D_{a,b} = d!/(d−a−b)! Δ₁^a Δ₂^b b_c).
///
/// # Examples
///
/// ```
/// use splinekit::Point;
/// use splinekit::surface::model::Sphere;
/// use splinekit::triangle::{SubTriangle, Triangle, hermite_local};
/// let s = SubTriangle::new(Sphere::new(1.0).unwrap(), [Point::<2>::new(0.2, 0.1), Point::<2>::new(0.9, 0.2), Point::<2>::new(0.4, 0.8)]).unwrap();
/// let local = hermite_local(&s, 1, 3).unwrap();
/// // At corner v the local has the model's point and partials up to order 3.
/// for (i, j) in [(0, 0), (1, 0), (0, 1), (2, 1), (0, 3)] {
///     assert!((local.partial(0.0, 1.0, 0.0, i, j) - s.partial(0.0, 1.0, 0.0, i, j)).norm() < 1e-12);
/// }
/// ```
pub fn hermite_local<const D: usize, T: Triangle<D> + ?Sized>(
    model: &T,
    corner: usize,
    degree: usize,
) -> Result<BezierTriangle<D>> {
    check_index(corner).map_err(|_| Error::invalid("corner", format!("must be 0, 1 or 2, got {corner}")))?;
    if degree == 0 || degree > super::MAX_DEGREE {
        return Err(Error::invalid("degree", format!("must be between 1 and {}, got {degree}", super::MAX_DEGREE)));
    }
    let d = degree;
    let (o1, o2) = ((corner + 1) % 3, (corner + 2) % 3);
    let c = CORNERS[corner];
    // Edge directions in the (u, v) chart: the first two barycentric components.
    let dir = |o: usize| [CORNERS[o][0] - c[0], CORNERS[o][1] - c[1]];
    let (d1, d2) = (dir(o1), dir(o2));
    let w = d + 1;
    let mut partials = vec![Point::<D>::zeros(); w * w];
    model.eval_partials(c[0], c[1], d, d, &mut partials);
    // D_{a,b} for a + b ≤ d by the chain rule of the two directions.
    let mut mixed = vec![Point::<D>::zeros(); w * w];
    for a in 0..=d {
        for b in 0..=d - a {
            let mut acc = Point::<D>::zeros();
            for p1 in 0..=a {
                for p2 in 0..=b {
                    let coef = binomial(a, p1)
                        * binomial(b, p2)
                        * d1[0].powi(p1 as i32)
                        * d1[1].powi((a - p1) as i32)
                        * d2[0].powi(p2 as i32)
                        * d2[1].powi((b - p2) as i32);
                    if coef != 0.0 {
                        acc += partials[(p1 + p2) * w + (a - p1 + b - p2)] * coef;
                    }
                }
            }
            mixed[a * w + b] = acc;
        }
    }
    let points = multi_indices(d)
        .map(|idx| {
            let idx = [idx.0, idx.1, idx.2];
            let (a_top, b_top) = (idx[o1], idx[o2]);
            let mut acc = Point::<D>::zeros();
            for a in 0..=a_top {
                for b in 0..=b_top {
                    acc += mixed[a * w + b] * (binomial(a_top, a) * binomial(b_top, b) / falling(d, a + b));
                }
            }
            acc
        })
        .collect();
    Ok(BezierTriangle::from_net(TriangularNet::new(points, "control_points")?))
}
