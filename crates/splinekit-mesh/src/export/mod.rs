//! Writing meshes and polylines to files other programs read — OBJ, STL (binary and
//! ASCII), PLY and glTF 2.0 (.gltf and .glb) — and reading the first three back.
//!
//! Every writer first checks that each number fits the format ([`representable`]) and
//! refuses with an [`ExportError`] naming the first one that does not, so no file ever
//! holds NaN or infinity; write errors of the output are returned, never ignored.

pub mod base64;
pub mod by_extension;
pub mod format;
pub mod gltf;
pub mod obj;
pub mod ply;
pub mod representable;
pub mod stl;

pub use by_extension::{EXPORT_COLOR, mesh_bytes, polyline_bytes, polyline_svg};
pub use format::{Format, Subject};
pub use gltf::{GltfGeometry, GltfObject, GltfScene};
pub use representable::ExportError;
