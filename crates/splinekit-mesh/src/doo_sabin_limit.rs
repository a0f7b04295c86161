//! The Doo–Sabin limit of a closed polygon mesh's vertices: for each vertex its limit
//! point and limit normal, in the mesh's vertex order.
//!
//! One Doo–Sabin step maps each n-gon F to its F-face, p_i = Σ_j α_ij v_j
//! ([`super::subdivision_surface`]), a circulant map of F's own vertices: in the Fourier
//! modes v_j = ω^{jl} of the face it has eigenvalue 1 (l = 0), ½ (l = ±1, any n) and ¼ (the
//! rest). So the F-faces descended from a face converge to the face's centroid, which
//! every step keeps, and their shape tends to the mode l = 1 scaled by ½ a step. A
//! vertex v of valence m gets, in one step, its vertex face: the m corner points of v, one
//! in each face around it, counter-clockwise. Its limit is that face's centre:
//!
//! - position: the centroid (1/m) Σ_k q_k of the corner points q_k (on a regular grid the
//!   tensor mask (1, 6, 1) ⊗ (1, 6, 1)/64, the biquadratic B-spline at the centre of the
//!   patch whose middle control point is v);
//! - normal: a × b normalised, a = Σ_k cos(2πk/m) q_k, b = Σ_k sin(2πk/m) q_k, the mode
//!   l = 1 that the descended faces flatten to (the tangent plane of the limit there).
//!
//! A border vertex has no vertex face (Doo–Sabin makes none on open borders, see
//! [`super::subdivision_surface`]), so no limit point: it is refused, naming the vertex.

use splinekit::subdivision::surface::{Cage, Topology};
use splinekit::{Error, Point, Result};

use crate::limit_mesh::LimitMesh;
use crate::subdivision_surface::{PolygonMesh, doo_sabin_corners};

/// The limit mesh of `mesh` under Doo–Sabin: every vertex at its limit point with its
/// limit normal, the faces as they are (each corner with its vertex's normal).
pub fn doo_sabin_limit_mesh(mesh: &PolygonMesh) -> Result<LimitMesh> {
    let cage = Cage::new(mesh.vertices.iter().map(|&p| Point::<3>::from(p)).collect(), &mesh.faces);
    let topo = Topology::new(&cage)?;
    // The corner points of every face, in the cage's corner (half-edge) order.
    let mut corners = Vec::with_capacity(cage.face_vertices.len());
    for f in 0..cage.face_count() {
        let points: Vec<[f64; 3]> = cage.face(f).iter().map(|&v| mesh.vertices[v as usize]).collect();
        corners.extend(doo_sabin_corners(&points).into_iter().map(Point::<3>::from));
    }
    let mut positions = Vec::with_capacity(mesh.vertices.len());
    let mut normals = Vec::with_capacity(mesh.vertices.len());
    for v in 0..mesh.vertices.len() as u32 {
        let out = topo.outgoing(v);
        if out.is_empty() {
            return Err(Error::invalid(format!("vertices[{v}]"), "the vertex is in no face, it has no limit"));
        }
        if topo.vertex_boundary[v as usize] {
            return Err(Error::invalid(
                format!("vertices[{v}]"),
                "the vertex is on an open border, where Doo–Sabin makes no vertex face and the limit has no point for it; \
                 the Doo–Sabin limit needs a closed mesh",
            ));
        }
        // Half-edge h is corner h of its face: the corner point of v in that face.
        let ring: Vec<Point<3>> = out.iter().map(|&h| corners[h as usize]).collect();
        let m = ring.len() as f64;
        let (mut centre, mut a, mut b) = (Point::<3>::zeros(), Point::<3>::zeros(), Point::<3>::zeros());
        for (k, q) in ring.iter().enumerate() {
            let (s, c) = (std::f64::consts::TAU * k as f64 / m).sin_cos();
            centre += q;
            a += q * c;
            b += q * s;
        }
        let n = a.cross(&b);
        let len = n.norm();
        positions.push((centre / m).into());
        normals.push(if len > 0.0 { (n / len).into() } else { [0.0; 3] });
    }
    let faces = mesh.faces.iter().map(|f| f.iter().map(|&v| (v, v)).collect()).collect();
    Ok(LimitMesh { positions, normals, faces })
}
