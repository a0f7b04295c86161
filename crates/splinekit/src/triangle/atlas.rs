//! A family of triangles seen as one [`Surface`]: an atlas of unit charts laid side by side
//! along u, the way tensor-only front ends (evaluation on a (u, v) domain, meshing, STEP,
//! rendering) take triangular shapes.
//!
//! Chart c covers u ∈ [c, c + 1], v ∈ [0, 1]. At (c + s, t) the atlas is triangle c at the
//! barycentric point of the collapse [`degenerate_patch_parameters`]`(s, t)` =
//! (s(1 − t), s t, 1 − s): the edge s = 0 collapses to corner w, s = 1 is the edge from
//! corner u (t = 0) to corner v (t = 1). A Bézier triangle's chart is therefore exactly its
//! degenerate tensor patch ([`BezierTriangle::to_tensor_patch`]), which is what STEP writes.
//!
//! Partials with respect to (s, t) follow from the triangle's (u, v)-partials by the chain
//! rule through the bilinear map u = s − s t, v = s t, to every order (in jets: u − u₀ =
//! (1 − t₀)σ − s₀τ − στ, v − v₀ = t₀σ + s₀τ + στ). The normal is the triangle's own
//! (S_s × S_t = s T_u × T_v, so the orientation agrees), which stays defined at the
//! collapsed corner. Where a triangle has no partials (a blending triangulation's corner of
//! valence ≠ 6), the chart takes those 10⁻⁹ of the way towards the triangle's centroid, so
//! that tools which sample partials on the square (fitting, projection) get finite numbers.
//!
//! Meshers do not sample the square: [`Surface::triangle_atlas`] hands them the triangles,
//! which they mesh on barycentric lattices (no slivers at the collapsed corner), and where
//! the atlas knows which corners are shared ([`TriangleAtlas::corner_ids`]) they weld
//! them into one watertight mesh.

use std::sync::Arc;

use smallvec::{SmallVec, smallvec};

use crate::error::{Error, Result};
use crate::query::Aabb;
use crate::surface::Surface;
use crate::triangle::bezier_triangle::BezierTriangle;
use crate::triangle::degenerate_patch::degenerate_patch_parameters;
use crate::triangle::jet::{Jet, compose_point};
use crate::triangle::rational_bezier_triangle::RationalBezierTriangle;
use crate::triangle::traits::Triangle;
use crate::{Interval, Point};

/// One chart's triangle, with its Bézier form where it has one (exporters write those
/// exactly).
#[derive(Clone)]
pub enum AtlasTriangle<const D: usize> {
    /// A polynomial Bézier triangle.
    Bezier(BezierTriangle<D>),
    /// A rational Bézier triangle.
    Rational(RationalBezierTriangle<D>),
    /// Any other triangle.
    Other(Arc<dyn Triangle<D>>),
}

impl<const D: usize> AtlasTriangle<D> {
    /// The triangle.
    pub fn triangle(&self) -> &dyn Triangle<D> {
        match self {
            AtlasTriangle::Bezier(t) => t,
            AtlasTriangle::Rational(t) => t,
            AtlasTriangle::Other(t) => t.as_ref(),
        }
    }
}

impl<const D: usize> std::fmt::Debug for AtlasTriangle<D> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            AtlasTriangle::Bezier(t) => write!(f, "Bezier(degree {})", t.degree()),
            AtlasTriangle::Rational(t) => write!(f, "Rational(degree {})", t.degree()),
            AtlasTriangle::Other(_) => write!(f, "Other"),
        }
    }
}

/// Triangles as one surface over their atlas of unit charts (see the module documentation).
#[derive(Debug, Clone)]
pub struct TriangleAtlas<const D: usize> {
    charts: Vec<AtlasTriangle<D>>,
    corner_ids: Option<Vec<[u32; 3]>>,
    bounds: Option<Aabb<D>>,
}

impl<const D: usize> TriangleAtlas<D> {
    /// The atlas of `charts` (at least one), none of them sharing corners.
    pub fn new(charts: Vec<AtlasTriangle<D>>) -> Result<Self> {
        if charts.is_empty() {
            return Err(Error::invalid("triangles", "an atlas needs at least one triangle"));
        }
        Ok(TriangleAtlas { charts, corner_ids: None, bounds: None })
    }

    /// The atlas of `charts` whose corners u, v, w are the vertices `corner_ids[c]` of a
    /// triangulation: two charts with corners a and b in common share the edge a–b, and
    /// meet along it (the point at fraction f from a on one is the point at fraction f from a
    /// on the other). Meshes weld such edges.
    pub fn with_corner_ids(charts: Vec<AtlasTriangle<D>>, corner_ids: Vec<[u32; 3]>) -> Result<Self> {
        if corner_ids.len() != charts.len() {
            return Err(Error::invalid(
                "triangles",
                format!("{} corner triples for {} triangles", corner_ids.len(), charts.len()),
            ));
        }
        let mut atlas = Self::new(charts)?;
        atlas.corner_ids = Some(corner_ids);
        Ok(atlas)
    }

    /// A single triangle's atlas.
    pub fn single(triangle: AtlasTriangle<D>) -> Self {
        TriangleAtlas { charts: vec![triangle], corner_ids: None, bounds: None }
    }

    /// The atlas with a box known to hold every triangle (what
    /// [`Surface::enclosing_box`] then gives).
    pub fn with_enclosing_box(mut self, bounds: Aabb<D>) -> Self {
        self.bounds = Some(bounds);
        self
    }

    /// The charts' triangles.
    pub fn charts(&self) -> &[AtlasTriangle<D>] {
        &self.charts
    }

    /// The triangulation's vertex numbers at the corners u, v, w of each chart, if shared.
    pub fn corner_ids(&self) -> Option<&[[u32; 3]]> {
        self.corner_ids.as_deref()
    }

    /// The chart and its (s, t) ∈ [0, 1]² of the atlas parameter (u, v), clamped to the domain.
    pub fn locate(&self, u: f64, v: f64) -> (usize, f64, f64) {
        let n = self.charts.len();
        let u = if u.is_nan() { 0.0 } else { u.clamp(0.0, n as f64) };
        let c = (u.floor() as usize).min(n - 1);
        let t = if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
        (c, (u - c as f64).clamp(0.0, 1.0), t)
    }

    /// The atlas parameter (c + s, t) of the barycentric point (u, v, 1 − u − v) of chart c:
    /// s = u + v, t = v / (u + v) (t = 0 at corner w, where every t gives the point).
    pub fn atlas_parameter(chart: usize, u: f64, v: f64) -> (f64, f64) {
        let s = u + v;
        let t = if s > 0.0 { v / s } else { 0.0 };
        (chart as f64 + s, t)
    }
}

impl<const D: usize> Surface<D> for TriangleAtlas<D> {
    fn domain_u(&self) -> Interval {
        Interval::new(0.0, self.charts.len() as f64)
    }
    fn domain_v(&self) -> Interval {
        Interval::new(0.0, 1.0)
    }

    fn eval_partials(&self, u: f64, v: f64, du: usize, dv: usize, out: &mut [Point<D>]) {
        let (c, s, t) = self.locate(u, v);
        let tri = self.charts[c].triangle();
        let [a, b, _] = degenerate_patch_parameters(s, t);
        if du == 0 && dv == 0 {
            tri.eval_partials(a, b, 0, 0, out);
            return;
        }
        let n = du + dv;
        let w = n + 1;
        let mut partials: SmallVec<[Point<D>; 25]> = smallvec![Point::<D>::zeros(); w * w];
        tri.eval_partials(a, b, n, n, &mut partials);
        if partials.iter().any(|p| !p.iter().all(|x| x.is_finite())) {
            // A singular corner (a blending triangulation's vertex of valence ≠ 6, where the
            // partials in (u, v) do not exist): those 10⁻⁹ towards the centroid, the point kept.
            let value = partials[0];
            let nudge = |x: f64| x + (1.0 / 3.0 - x) * 1e-9;
            tri.eval_partials(nudge(a), nudge(b), n, n, &mut partials);
            if value.iter().all(|x| x.is_finite()) {
                partials[0] = value;
            }
        }
        // u = s − s t and v = s t about (s, t): the jets of the bilinear map.
        let mut x = Jet::affine(du, dv, a, 1.0 - t, -s);
        let mut y = Jet::affine(du, dv, b, t, s);
        if du >= 1 && dv >= 1 {
            let cross = Jet::affine(du, dv, 0.0, 1.0, 0.0).mul(&Jet::affine(du, dv, 0.0, 0.0, 1.0));
            x = x.sub(&cross);
            y = y.add(&cross);
        }
        compose_point(&x, &y, &partials, out);
    }

    fn breakpoints_u(&self) -> Vec<f64> {
        (0..=self.charts.len()).map(|c| c as f64).collect()
    }

    /// The triangle's own normal (defined at the collapsed corner too).
    fn normal(&self, u: f64, v: f64) -> Option<Point<D>> {
        let (c, s, t) = self.locate(u, v);
        let [a, b, w] = degenerate_patch_parameters(s, t);
        self.charts[c].triangle().normal(a, b, w)
    }

    /// The box given to [`TriangleAtlas::with_enclosing_box`], else the box of the control
    /// points where every chart is a Bézier triangle (convex hull property; rational ones
    /// with positive weights), else `None`.
    fn enclosing_box(&self) -> Option<Aabb<D>> {
        if let Some(b) = &self.bounds {
            return Some(*b);
        }
        let mut points: Vec<Point<D>> = Vec::new();
        for chart in &self.charts {
            match chart {
                AtlasTriangle::Bezier(t) => points.extend_from_slice(t.control_points()),
                AtlasTriangle::Rational(t) => points.extend_from_slice(t.control_points()),
                AtlasTriangle::Other(_) => return None,
            }
        }
        Some(Aabb::around(&points, 0.0))
    }

    fn triangle_atlas(&self) -> Option<&TriangleAtlas<D>> {
        Some(self)
    }
}
