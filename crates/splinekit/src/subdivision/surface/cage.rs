//! The control cage of a subdivision surface: vertices, polygon faces (flat, with offsets),
//! per-edge crease sharpness and the boundary rule.

use crate::{Error, Point, Result};

/// How boundary vertices are treated (OpenSubdiv's `VtxBoundaryInterpolation`).
///
/// Boundary edges are always infinitely sharp (crease rule: the edge point is the
/// midpoint). With [`BoundaryRule::EdgeOnly`] a boundary vertex with one face (a corner of
/// a single face) takes the crease rule (e₀ + 6v + e₁)/8 like every other boundary vertex;
/// with [`BoundaryRule::EdgeAndCorner`] it is a corner and stays put, so the limit
/// surface interpolates it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum BoundaryRule {
    /// Boundary edges sharp, every boundary vertex a crease vertex (the default).
    #[default]
    EdgeOnly,
    /// Boundary edges sharp, boundary vertices of a single face corners.
    EdgeAndCorner,
}

/// Sharpness at or above this value is infinite (as in OpenSubdiv, `SHARPNESS_INFINITE`).
pub const INFINITE_SHARPNESS: f64 = 10.0;

/// One creased edge: its two vertices and its sharpness s ≥ 0 (s ≥ 10 or +∞: infinitely
/// sharp; 0 < s < 10: semi-sharp, ⌈s⌉ steps of the crease rule with the last blended by
/// the fractional part, then smooth).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Crease {
    /// First vertex.
    pub a: u32,
    /// Second vertex.
    pub b: u32,
    /// Sharpness.
    pub sharpness: f64,
}

/// A polygon cage. Faces are counter-clockwise seen from outside; each edge has at most
/// two faces, used in opposite directions, and the faces at a vertex form one fan.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Cage {
    /// Vertex positions.
    pub vertices: Vec<Point<3>>,
    /// Face `f` is `face_vertices[face_offsets[f]..face_offsets[f + 1]]`.
    pub face_offsets: Vec<u32>,
    /// Vertex indices of all faces, one after the other.
    pub face_vertices: Vec<u32>,
    /// Creased edges (edges not listed are smooth, sharpness 0).
    pub creases: Vec<Crease>,
    /// The boundary rule.
    pub boundary: BoundaryRule,
}

impl Cage {
    /// A cage from vertices and faces (lists of vertex indices), no creases.
    pub fn new(vertices: Vec<Point<3>>, faces: &[Vec<u32>]) -> Self {
        let mut face_offsets = Vec::with_capacity(faces.len() + 1);
        face_offsets.push(0);
        let mut face_vertices = Vec::with_capacity(faces.iter().map(Vec::len).sum());
        for f in faces {
            face_vertices.extend_from_slice(f);
            face_offsets.push(face_vertices.len() as u32);
        }
        Cage { vertices, face_offsets, face_vertices, creases: Vec::new(), boundary: BoundaryRule::EdgeOnly }
    }

    /// The cube [−1, 1]³: vertex k at (±1, ±1, ±1) with the signs of bits 0, 1, 2 of k, six
    /// quads counter-clockwise seen from outside (Catmull–Clark puts its corners' limit at
    /// (±½, ±½, ±½)). The example cage of documents, tests and timings.
    pub fn cube() -> Self {
        let sign = |k: u32, bit: u32| if k & bit == 0 { -1.0 } else { 1.0 };
        let vertices = (0..8).map(|k| Point::<3>::new(sign(k, 1), sign(k, 2), sign(k, 4))).collect();
        let faces =
            [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]].map(|f| f.to_vec());
        Cage::new(vertices, &faces)
    }

    /// The same cage with creases.
    pub fn with_creases(mut self, creases: Vec<Crease>) -> Self {
        self.creases = creases;
        self
    }

    /// The same cage with a boundary rule.
    pub fn with_boundary(mut self, boundary: BoundaryRule) -> Self {
        self.boundary = boundary;
        self
    }

    /// Number of faces.
    pub fn face_count(&self) -> usize {
        self.face_offsets.len().saturating_sub(1)
    }

    /// The vertex indices of face `f`.
    pub fn face(&self, f: usize) -> &[u32] {
        &self.face_vertices[self.face_offsets[f] as usize..self.face_offsets[f + 1] as usize]
    }

    /// Whether every face is a triangle.
    pub fn is_triangle_mesh(&self) -> bool {
        (0..self.face_count()).all(|f| self.face(f).len() == 3)
    }

    /// Whether every face is a quad.
    pub fn is_quad_mesh(&self) -> bool {
        (0..self.face_count()).all(|f| self.face(f).len() == 4)
    }

    /// The cage with every n-gon split into a fan of n − 2 triangles from its first vertex
    /// (creases kept: fan diagonals are new, smooth edges).
    pub fn triangulated(&self) -> Cage {
        let faces: Vec<Vec<u32>> = (0..self.face_count())
            .flat_map(|f| {
                let p = self.face(f);
                (1..p.len() - 1).map(move |k| vec![p[0], p[k], p[k + 1]])
            })
            .collect();
        Cage { creases: self.creases.clone(), boundary: self.boundary, ..Cage::new(self.vertices.clone(), &faces) }
    }

    /// Checks that coordinates are finite, faces have 3 or more existing vertices and
    /// sharpness values are finite-or-+∞ and ≥ 0 (the topology is checked by
    /// [`super::Topology::new`]).
    pub fn validate(&self) -> Result<()> {
        if let Some(i) = self.vertices.iter().position(|p| !p.iter().all(|x| x.is_finite())) {
            return Err(Error::invalid(format!("vertices[{i}]"), "coordinates must be finite"));
        }
        if self.face_count() == 0 {
            return Err(Error::invalid("faces", "the cage has no faces"));
        }
        let n = self.vertices.len() as u32;
        for f in 0..self.face_count() {
            let face = self.face(f);
            if face.len() < 3 {
                return Err(Error::invalid(
                    format!("faces[{f}]"),
                    format!("a face needs 3 or more vertices, got {}", face.len()),
                ));
            }
            if let Some(&i) = face.iter().find(|&&i| i >= n) {
                return Err(Error::invalid(
                    format!("faces[{f}]"),
                    format!("vertex {i} does not exist (there are {n})"),
                ));
            }
        }
        for (k, c) in self.creases.iter().enumerate() {
            if c.sharpness.is_nan() || c.sharpness < 0.0 {
                return Err(Error::invalid(
                    format!("creases[{k}].sharpness"),
                    format!("sharpness must be ≥ 0 (or inf), got {}", c.sharpness),
                ));
            }
        }
        Ok(())
    }
}
