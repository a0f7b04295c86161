//! # splinekit-mesh
//!
//! Turning splinekit shapes into things other programs read: polylines for curves
//! (regular or adaptive to a chord-height tolerance), triangle meshes for surfaces
//! (regular grids and adaptive quad-trees with welded seams), and the exports OBJ, STL,
//! PLY, glTF 2.0 and SVG.

#![warn(missing_docs)]

pub mod adaptive_mesh;
pub mod boundary_gluing;
pub mod brep_mesh;
pub mod doo_sabin_limit;
pub mod export;
pub mod limit_mesh;
pub mod measure;
mod mesh_cleanup;
pub mod mesh_options;
pub mod polyline;
pub mod subdivision_mesh;
pub mod subdivision_surface;
pub mod surface_mesh;
pub mod svg;
pub mod triangle_atlas_mesh;
pub mod triangle_mesh;
pub mod trimmed_mesh;

pub use polyline::Polyline;
pub use surface_mesh::{AdaptiveTolerance, MeshOptions};
pub use svg::{Projection, SvgFigure};
pub use triangle_mesh::TriangleMesh;
