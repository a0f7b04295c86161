//! What every surface mesher shares: the options ([`MeshOptions`], [`AdaptiveTolerance`]),
//! the vertex limit, the lattice parameters of a regular grid and points as three
//! coordinates. A leaf: the regular, adaptive and trimmed meshers and the boundary gluing
//! use it, and it uses none of them.

use splinekit::Point;
use splinekit::curve::Interval;

/// Most vertices a surface mesh may have.
pub const MAX_VERTICES: usize = 20_000_000;

/// The first three coordinates of a point (missing ones 0).
pub fn to3<const D: usize>(p: &Point<D>) -> [f64; 3] {
    let mut q = [0.0; 3];
    for (k, v) in q.iter_mut().enumerate().take(D.min(3)) {
        *v = p[k];
    }
    q
}

/// Options for surface meshes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshOptions {
    /// Store normalised (u, v) per vertex (duplicating seam vertices of closed surfaces).
    pub uv: bool,
}

impl Default for MeshOptions {
    fn default() -> Self {
        MeshOptions { uv: true }
    }
}

/// The parameter of lattice point `k` of `n` cells over `d` (the ends exactly).
pub(crate) fn lattice_param(d: Interval, k: i64, n: i64) -> f64 {
    if k == n { d.end } else { d.lerp(k as f64 / n as f64) }
}

/// Tolerances of the adaptive mesh.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdaptiveTolerance {
    /// Largest distance of the surface from a cell's flat approximation (at the cell centre
    /// and edge midpoints).
    pub chord_height: f64,
    /// Largest angle in radians between the normals at a cell's corners and centre.
    pub normal_angle: f64,
    /// Deepest quad-tree level below the initial grid.
    pub max_depth: u32,
}
