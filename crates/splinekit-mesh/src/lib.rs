//! # splinekit-mesh
//!
//! Turning splinekit shapes into things other programs read: polylines for curves
//! (regular or adaptive to a chord-height tolerance) and SVG drawings. Triangle meshes for
//! surfaces and the OBJ/STL/PLY/glTF exports join here as surfaces arrive.

#![warn(missing_docs)]

pub mod polyline;
pub mod svg;

pub use polyline::Polyline;
pub use svg::{Projection, SvgFigure};
