//! Rational Bézier triangles
//! T(u, v, w) = Σ B^n_ijk ω_ijk P_ijk / Σ B^n_ijk ω_ijk with positive weights ω beside the
//! points (Farin, *Curves and Surfaces for CAGD*, §17.9).
//!
//! The numerator A = Σ B ω P and the denominator ω = Σ B ω are one polynomial triangle over
//! homogeneous points (ω P, ω), so every algorithm of the polynomial case (de Casteljau,
//! the Bernstein form, blossoms, elevation, subdivision, the tensor conversion) runs on
//! them unchanged. Partials follow from the quotient rule in two variables (as for NURBS
//! surfaces, the NURBS Book eq. 4.20):
//! T^{(k,l)} = (A^{(k,l)} − Σ_{(i,j)≠(0,0)} C(k,i) C(l,j) ω^{(i,j)} T^{(k−i,l−j)}) / ω.

use smallvec::{SmallVec, smallvec};

use crate::Point;
use crate::curve::nurbs::check_weights;
use crate::error::{Error, Result, check_points_finite};
use crate::ops::homogeneous::Homogeneous;
use crate::surface::NurbsSurface;
use crate::surface::nurbs_surface::rational_partials;
use crate::triangle::bezier_triangle::{MIDPOINT_CHILDREN, barycentric_argument, split_corners};
use crate::triangle::net::{TriangularNet, degree_of_len, net_index};
use crate::triangle::traits::{Triangle, clamp_to_triangle, clamp_uv};

/// A rational Bézier triangle of degree n with positive weights.
#[derive(Debug, Clone, PartialEq)]
pub struct RationalBezierTriangle<const D: usize> {
    points: Vec<Point<D>>,
    weights: Vec<f64>,
    net: TriangularNet<Homogeneous<D>>,
}

impl<const D: usize> RationalBezierTriangle<D> {
    /// A rational Bézier triangle from its control points (storage order of
    /// [`net_index`]) and one weight > 0 per point.
    ///
    /// # Examples
    ///
    /// ```
    /// use splinekit::Point;
    /// use splinekit::triangle::{RationalBezierTriangle, Triangle};
    /// // The octant of the unit sphere (Farin, Piper & Worsey 1987): every point at distance 1.
    /// let t = RationalBezierTriangle::sphere_octant();
    /// assert!((t.point(0.2, 0.3, 0.5).norm() - 1.0).abs() < 1e-15);
    /// // Weights must be positive, one per point.
    /// let p = vec![Point::<3>::x(), Point::<3>::y(), Point::<3>::z()];
    /// assert!(RationalBezierTriangle::new(p.clone(), vec![1.0, 0.0, 1.0]).is_err());
    /// assert!(RationalBezierTriangle::new(p, vec![1.0, 1.0]).is_err());
    /// ```
    pub fn new(control_points: Vec<Point<D>>, weights: Vec<f64>) -> Result<Self> {
        check_points_finite("control_points", &control_points)?;
        degree_of_len(control_points.len(), "control_points")?;
        check_weights(&weights, control_points.len())?;
        let lifted = control_points.iter().zip(&weights).map(|(p, w)| Homogeneous::lift(p, *w)).collect();
        let net = TriangularNet::new(lifted, "control_points")?;
        Ok(RationalBezierTriangle { points: control_points, weights, net })
    }

    fn from_net(net: TriangularNet<Homogeneous<D>>) -> Self {
        let points = net.points().iter().map(Homogeneous::project).collect();
        let weights = net.points().iter().map(|h| h.weight).collect();
        RationalBezierTriangle { points, weights, net }
    }

    /// The degree n.
    pub fn degree(&self) -> usize {
        self.net.degree()
    }

    /// The control points in storage order.
    pub fn control_points(&self) -> &[Point<D>] {
        &self.points
    }

    /// The weights, one per control point.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// (P_ijk, ω_ijk), or `None` unless i + j + k = n.
    pub fn control_point(&self, i: usize, j: usize, k: usize) -> Option<(&Point<D>, f64)> {
        (i + j + k == self.degree()).then(|| (&self.points[net_index(j, k)], self.weights[net_index(j, k)]))
    }

    /// T(u, v, w) by de Casteljau's algorithm on the homogeneous net, then A/ω.
    pub fn point_de_casteljau(&self, u: f64, v: f64, w: f64) -> Point<D> {
        let (u, v) = clamp_to_triangle(u, v, w);
        self.net.de_casteljau(u, v, 1.0 - u - v).project()
    }

    /// T(u, v, w) by the Bernstein form of numerator and denominator.
    pub fn point_bernstein(&self, u: f64, v: f64, w: f64) -> Point<D> {
        let (u, v) = clamp_to_triangle(u, v, w);
        self.net.bernstein(u, v, 1.0 - u - v).project()
    }

    /// The partials of [`Triangle::eval_partials`] from the Bernstein form of the
    /// homogeneous partials (see
    /// [`BezierTriangle::eval_partials_bernstein`](super::BezierTriangle::eval_partials_bernstein)),
    /// then the quotient rule.
    pub fn eval_partials_bernstein(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        let (u, v) = clamp_uv(u, v);
        let mut h: SmallVec<[Homogeneous<D>; 16]> =
            smallvec![Homogeneous::lift(&Point::<D>::zeros(), 0.0); (du + 1) * (dv + 1)];
        self.net.partials_bernstein(u, v, du, dv, &mut h);
        rational_partials(&h, du, dv, out);
    }

    /// The same triangle at degree n + 1 (the homogeneous net elevated; exact).
    pub fn elevate(&self) -> Result<Self> {
        if self.degree() >= super::MAX_DEGREE {
            return Err(Error::invalid(
                "degree",
                format!("cannot elevate degree {} beyond {}", self.degree(), super::MAX_DEGREE),
            ));
        }
        Ok(Self::from_net(self.net.elevated()))
    }

    /// T'(u, v, w) = T(u a + v b + w c) exactly (the homogeneous net blossomed).
    pub fn restrict(&self, a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> Result<Self> {
        let corners = [barycentric_argument("a", a)?, barycentric_argument("b", b)?, barycentric_argument("c", c)?];
        let net = self.net.restricted(&corners);
        if let Some((i, h)) = net.points().iter().enumerate().find(|(_, h)| h.weight.is_nan() || h.weight <= 0.0) {
            return Err(Error::invalid(
                "corners",
                format!("the restricted triangle's weight {i} is {} (corners outside the triangle)", h.weight),
            ));
        }
        Ok(Self::from_net(net))
    }

    /// Splits at the interior point p into (p, v, w), (u, p, w), (u, v, p), as
    /// [`BezierTriangle::split_at`](super::BezierTriangle::split_at) does.
    pub fn split_at(&self, p: [f64; 3]) -> Result<[Self; 3]> {
        let corners = split_corners("point", p)?;
        Ok(corners.map(|c| Self::from_net(self.net.restricted(&c))))
    }

    /// Splits at the edge midpoints into four, as
    /// [`BezierTriangle::split_midpoints`](super::BezierTriangle::split_midpoints) does.
    pub fn split_midpoints(&self) -> [Self; 4] {
        MIDPOINT_CHILDREN.map(|c| Self::from_net(self.net.restricted(&c)))
    }

    /// The exact degenerate rational tensor-product Bézier patch of degree (n, n),
    /// S(s, t) = T(s(1 − t), s t, 1 − s), as a NURBS surface with one span each way.
    pub fn to_tensor_patch(&self) -> NurbsSurface<D> {
        let rows = self.net.tensor_rows();
        let points = rows.iter().map(|r| r.iter().map(Homogeneous::project).collect()).collect();
        let weights = rows.iter().map(|r| r.iter().map(|h| h.weight).collect()).collect();
        NurbsSurface::rational_bezier(points, weights).expect("convex combinations of positive weights are positive")
    }

    /// The control points mapped by `f`, weights kept (an affine map gives the mapped
    /// triangle).
    pub fn map_points(&self, f: impl Fn(&Point<D>) -> Point<D>) -> Result<Self> {
        Self::new(self.points.iter().map(f).collect(), self.weights.clone())
    }
}

impl RationalBezierTriangle<3> {
    /// The octant x, y, z ≥ 0 of the unit sphere as a non-degenerate quartic rational
    /// Bézier triangle, corners u, v, w at x, y, z (G. Farin, B. Piper, A. Worsey, "The
    /// octant of a sphere as a non-degenerate triangular Bézier patch", CAGD 4 (1987)
    /// 329–332; Farin, *Curves and Surfaces for CAGD*, §17.9). With
    /// a₀ = (√3 − 1)/√3, a₁ = (√3 + 1)/(2√3), a₂ = 1 − (5 − √2)(7 − √3)/46:
    ///
    /// | points | P | ω |
    /// | --- | --- | --- |
    /// | corners P_400, … | (1, 0, 0), … | 4√3(√3 − 1) |
    /// | next to a corner P_310, … | (1, a₀, 0), … | 3√2 |
    /// | edge middles P_220, … | (a₁, a₁, 0), … | 4 |
    /// | interior P_211, … | (1, a₂, a₂), … | √2(3 + 2√2 − √3)/√3 |
    ///
    /// (the others by permuting coordinates with the indices). Every point lies on the
    /// sphere to rounding.
    pub fn sphere_octant() -> Self {
        let (s2, s3) = (2f64.sqrt(), 3f64.sqrt());
        let a0 = (s3 - 1.0) / s3;
        let a1 = (s3 + 1.0) / (2.0 * s3);
        let a2 = 1.0 - (5.0 - s2) * (7.0 - s3) / 46.0;
        let (corner, near, middle, inner) = (4.0 * s3 * (s3 - 1.0), 3.0 * s2, 4.0, s2 * (3.0 + 2.0 * s2 - s3) / s3);
        // The coordinate of P_ijk along the axis of index e, from the multi-index pattern.
        let coordinate = |own: usize, others: (usize, usize)| -> f64 {
            match (own, others) {
                (0, _) => 0.0,
                (1, (3, 0) | (0, 3)) => a0,
                (1, _) => a2,
                (2, (1, 1)) => 1.0,
                (2, _) => a1,
                _ => 1.0,
            }
        };
        let mut points = Vec::with_capacity(15);
        let mut weights = Vec::with_capacity(15);
        for (i, j, k) in crate::triangle::net::multi_indices(4) {
            points.push(Point::<3>::new(coordinate(i, (j, k)), coordinate(j, (i, k)), coordinate(k, (i, j))));
            let zeros = [i, j, k].iter().filter(|x| **x == 0).count();
            let max = i.max(j).max(k);
            weights.push(match (zeros, max) {
                (2, _) => corner,
                (1, 3) => near,
                (1, _) => middle,
                _ => inner,
            });
        }
        RationalBezierTriangle::new(points, weights).expect("the octant's net is valid")
    }
}

impl<const D: usize> Triangle<D> for RationalBezierTriangle<D> {
    fn bezier_net(&self) -> Option<crate::triangle::traits::BezierNet<'_, D>> {
        Some(crate::triangle::traits::BezierNet { points: &self.points, weights: Some(&self.weights) })
    }

    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        let (u, v) = clamp_uv(u, v);
        if du == 0 && dv == 0 {
            out[0] = self.net.de_casteljau(u, v, 1.0 - u - v).project();
            return;
        }
        let mut h: SmallVec<[Homogeneous<D>; 16]> =
            smallvec![Homogeneous::lift(&Point::<D>::zeros(), 0.0); (du + 1) * (dv + 1)];
        self.net.partials(u, v, du, dv, &mut h);
        rational_partials(&h, du, dv, out);
    }
}
