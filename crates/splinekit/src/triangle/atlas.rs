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
//! Meshers do not sample the square:
//! [`Surface::triangle_atlas`](crate::surface::Surface::triangle_atlas) hands them the triangles,
//! which they mesh on barycentric lattices (no slivers at the collapsed corner), and where
//! the atlas knows which corners are shared ([`TriangleAtlas::corner_ids`]) they weld
//! them into one watertight mesh.

use std::sync::Arc;

use crate::error::{Error, Result};
use crate::query::Aabb;
use crate::triangle::traits::Triangle;

/// Triangles as one surface over their atlas of unit charts (see the module documentation).
#[derive(Clone)]
pub struct TriangleAtlas<const D: usize> {
    charts: Vec<Arc<dyn Triangle<D>>>,
    corner_ids: Option<Vec<[u32; 3]>>,
    bounds: Option<Aabb<D>>,
}

impl<const D: usize> TriangleAtlas<D> {
    /// The atlas of `charts` (at least one), none of them sharing corners.
    pub fn new(charts: Vec<Arc<dyn Triangle<D>>>) -> Result<Self> {
        if charts.is_empty() {
            return Err(Error::invalid("triangles", "an atlas needs at least one triangle"));
        }
        Ok(TriangleAtlas { charts, corner_ids: None, bounds: None })
    }

    /// The atlas of `charts` whose corners u, v, w are the vertices `corner_ids[c]` of a
    /// triangulation: two charts with corners a and b in common share the edge a–b, and
    /// meet along it (the point at fraction f from a on one is the point at fraction f from a
    /// on the other). Meshes weld such edges.
    pub fn with_corner_ids(charts: Vec<Arc<dyn Triangle<D>>>, corner_ids: Vec<[u32; 3]>) -> Result<Self> {
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
    pub fn single(triangle: Arc<dyn Triangle<D>>) -> Self {
        TriangleAtlas { charts: vec![triangle], corner_ids: None, bounds: None }
    }

    /// The atlas with a box known to hold every triangle (what
    /// [`Surface::enclosing_box`](crate::surface::Surface::enclosing_box) then gives).
    pub fn with_enclosing_box(mut self, bounds: Aabb<D>) -> Self {
        self.bounds = Some(bounds);
        self
    }

    /// The charts' triangles.
    pub fn charts(&self) -> &[Arc<dyn Triangle<D>>] {
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

    /// The box given to [`TriangleAtlas::with_enclosing_box`], if any.
    pub fn given_box(&self) -> Option<Aabb<D>> {
        self.bounds
    }
}

impl<const D: usize> std::fmt::Debug for TriangleAtlas<D> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("TriangleAtlas")
            .field("charts", &self.charts.len())
            .field("shared", &self.corner_ids.is_some())
            .finish()
    }
}
