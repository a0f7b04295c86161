//! The triangle family: triangular parametric surfaces over barycentric coordinates
//! (u, v, w), u + v + w = 1 (GMlib's `PTriangle` and its kinds).
//!
//! * [`Triangle`]: the capability trait: position, partials in (u, v), directional and
//!   barycentric derivatives, normal, curvatures;
//! * [`BezierTriangle`], [`RationalBezierTriangle`]: Bézier triangles of any degree,
//!   polynomial and rational (weights beside the points), in any dimension: de Casteljau
//!   and the Bernstein form, derivatives of every order, degree elevation, subdivision
//!   into three and into four, the exact degenerate tensor-product patch;
//! * [`SubTriangle`]: the triangle S(u a + v b + w c) of any [`Surface`](crate::surface::Surface);
//! * [`TriangularBFunction`]: three blending weights made from a 1-D
//!   [`BFunction`](crate::basis::BFunction), rational or not;
//! * [`GerbsTriangle`]: three framed local triangles blended by them;
//! * [`TriangulationBlend`]: a blending-spline surface over a whole triangulated surface,
//!   one framed local per vertex, smooth across the edges;
//! * [`TriangleAtlas`]: any of these seen as one [`Surface`](crate::surface::Surface) over
//!   unit charts, for the tensor-product front ends.
//!
//! # Why a trait of its own, not `Surface<3>`
//!
//! A triangle is a surface, and it can be written over the unit square by the collapse
//! (s, t) ↦ (s(1 − t), s t, 1 − s) ([`degenerate_patch_parameters`]). The kernel still
//! gives triangles their own trait, for three reasons:
//!
//! 1. **The domain.** [`Surface`](crate::surface::Surface) promises a rectangle: queries,
//!    tessellators, grid evaluation, iso-curves and breakpoints sample and clamp to
//!    [u₀, u₁] × [v₀, v₁]. Half of the unit square is not in a triangle, and any mapping
//!    that fills the square distorts the triangle's parametrisation.
//! 2. **The singular corner.** Under the collapse, ∂S/∂t vanishes along s = 0: normals,
//!    curvatures and Newton steps there must take limits, and the map's Jacobian makes
//!    derivatives of the square patch mix all orders of the triangle's. The triangle's own
//!    partials are regular everywhere a regular triangle is.
//! 3. **Symmetry.** Barycentric coordinates treat the three corners alike (subdivision,
//!    blending by three weights, triangulations); the square's two directions do not.
//!
//! Where a tensor-product surface is needed (STEP, tensor-only tools), a Bézier triangle
//! converts exactly: [`BezierTriangle::to_tensor_patch`] gives a
//! [`BezierSurface`](crate::surface::BezierSurface) of degree (n, n) and
//! [`RationalBezierTriangle::to_tensor_patch`] a rational one, both with that collapse.
//! Partials share [`Surface::eval_partials`](crate::surface::Surface::eval_partials)'s
//! layout, and normals and curvatures come from the same
//! [`FundamentalForms`](crate::surface::FundamentalForms), so the two families agree
//! wherever both apply.

pub mod atlas;
mod atlas_surface;
pub mod bezier_triangle;
pub mod degenerate_patch;
pub mod gerbs_triangle;
pub mod jet;
pub mod net;
pub mod rational_bezier_triangle;
pub mod sub_triangle;
pub mod traits;
pub mod triangular_bfunction;
pub mod triangulation_blend;

pub use atlas::TriangleAtlas;
pub use bezier_triangle::BezierTriangle;
pub use degenerate_patch::degenerate_patch_parameters;
pub use gerbs_triangle::{GerbsTriangle, hermite_local};
pub use net::{MAX_DEGREE, multi_indices, net_index, net_len};
pub use rational_bezier_triangle::RationalBezierTriangle;
pub use sub_triangle::SubTriangle;
pub use traits::{BezierNet, Triangle, clamp_to_triangle};
pub use triangular_bfunction::{TriangularBFunction, TriangularForm};
pub use triangulation_blend::{BlendTriangle, TriangulatedSurface, TriangulationBlend};
