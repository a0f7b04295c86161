//! # splinekit-render
//!
//! Offscreen rendering with wgpu: shaded triangle meshes (two directional lights, smooth
//! normals, per-vertex colours for colour maps), curves as lines of a given screen width,
//! points as discs, 4× MSAA, a camera fitted to the scene's bounds or given. Images are
//! written as PNG, animations as GIF. Headless it runs on wgpu's GL backend (Mesa's
//! llvmpipe on a machine without a GPU); on real GPUs on Vulkan or GL. The renderer is the
//! default feature `gpu`; without it the crate composes scenes, exports them as glTF and
//! carries the web viewer (`web_viewer`: the pinned three.js bundle).

#![warn(missing_docs)]

#[cfg(feature = "gpu")]
pub mod backends;
pub mod camera;
pub mod compose;
pub mod fields;
#[cfg(feature = "gpu")]
pub mod geometry;
pub mod gltf_export;
pub mod image;
#[cfg(feature = "gpu")]
pub mod renderer;
pub mod scene;
pub mod scene_file;
pub mod web_viewer;

#[cfg(feature = "gpu")]
pub use backends::prepare_headless_environment;
pub use camera::Camera;
pub use compose::{SurfaceFor, compose, compose_with, recompose_object};
#[cfg(feature = "gpu")]
pub use geometry::{Geometry, GeometryData};
pub use gltf_export::scene_to_gltf;
pub use image::{Image, write_gif};
#[cfg(feature = "gpu")]
pub use renderer::{RenderError, RenderTarget, Renderer};
pub use scene::{LineItem, MeshItem, ObjectItems, PointItem, RenderScene};
pub use scene_file::scene_file;
