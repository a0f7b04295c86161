//! Triangulations of points in the plane as modelling objects: the (constrained) Delaunay
//! triangulation with insertion, constraint edges and vertex removal, its dual, the
//! Voronoi diagram, and height fields interpolating over it (piecewise linear, or C¹ by the
//! Clough–Tocher split). Built on spade (exact, robust orientation and in-circle predicates
//! after Shewchuk), so every triangle's circumcircle is empty of the other vertices
//! exactly, not to a tolerance.

pub mod delaunay;
pub mod interpolant;
pub mod voronoi;

pub use delaunay::Delaunay;
pub use interpolant::{HeightInterpolant, HeightPieces, estimate_gradients, gradient_of_normal, height_pieces};
pub use voronoi::VoronoiCell;
