//! The map of the unit square onto the triangle that the exact tensor-product forms of
//! Bézier triangles use ([`BezierTriangle::to_tensor_patch`](super::BezierTriangle::to_tensor_patch),
//! [`RationalBezierTriangle::to_tensor_patch`](super::RationalBezierTriangle::to_tensor_patch)).
//!
//! (s, t) ↦ (u, v, w) = (s(1 − t), s t, 1 − s) is bilinear, so a triangle of degree n
//! becomes a tensor-product patch of degree (n, n):
//! T = Σ_m B^n_m(s) Σ_{j≤m} B^m_j(t) b_{m−j, j, n−m}, each inner curve of degree m raised
//! to degree n. The edge s = 0 collapses to corner w (the patch is degenerate there: its
//! t-derivative vanishes); s = 1 is the edge from corner u (t = 0) to corner v (t = 1),
//! t = 0 the edge from w to u and t = 1 the edge from w to v. This is the collapse STEP
//! and tensor-only tools take a triangle in.

/// The barycentric point (u, v, w) = (s(1 − t), s t, 1 − s) of the square's (s, t).
///
/// # Examples
///
/// ```
/// use splinekit::triangle::degenerate_patch_parameters;
/// assert_eq!(degenerate_patch_parameters(0.0, 0.7), [0.0, 0.0, 1.0]);
/// assert_eq!(degenerate_patch_parameters(1.0, 0.25), [0.75, 0.25, 0.0]);
/// ```
#[inline]
pub fn degenerate_patch_parameters(s: f64, t: f64) -> [f64; 3] {
    [s * (1.0 - t), s * t, 1.0 - s]
}
