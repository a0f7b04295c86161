//! Triangulations of points in the plane as modelling objects: the (constrained) Delaunay
//! triangulation with insertion, constraint edges and vertex removal, and its dual, the
//! Voronoi diagram. Built on spade (exact, robust orientation and in-circle predicates
//! after Shewchuk), so every triangle's circumcircle is empty of the other vertices
//! exactly, not to a tolerance.

pub mod delaunay;
pub mod voronoi;

pub use delaunay::Delaunay;
pub use voronoi::VoronoiCell;
