//! Writing meshes and polylines to files other programs read — OBJ, STL (binary and
//! ASCII), PLY and glTF 2.0 (.gltf and .glb) — and reading the first three back.

pub mod gltf;
pub mod obj;
pub mod ply;
pub mod stl;

pub use gltf::{GltfGeometry, GltfObject, GltfScene};
