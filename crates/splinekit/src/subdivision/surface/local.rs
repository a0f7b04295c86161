//! Local neighbourhoods: a few faces of a cage cut out as a cage of their own, so that
//! limit evaluation subdivides only what the point depends on.
//!
//! One subdivision step of the 1-ring of a face F (every face sharing a vertex with F)
//! gives the right points on the 1-ring of each child of F: they are vertex points of F's
//! vertices (whose whole fans are in the 1-ring), edge points of edges at F's vertices
//! (both faces in the 1-ring) and face points of 1-ring faces. The vertices on the rim of
//! the neighbourhood get wrong points, which nothing uses. Likewise one step of a vertex's
//! star (its faces) gives the right star of the vertex's child.

use std::collections::HashMap;

use super::cage::{Cage, Crease};
use super::topology::Topology;

/// The cage of `faces` (face `faces[k]` becomes face k; vertices renumbered in order of
/// first use, so the first face's first vertex is vertex 0), with the creases between
/// kept vertices, and the map from old vertex indices to new.
pub fn sub_cage(cage: &Cage, topo: &Topology, faces: &[u32]) -> (Cage, HashMap<u32, u32>) {
    let mut map: HashMap<u32, u32> = HashMap::with_capacity(faces.len() * 4);
    let mut vertices = Vec::new();
    let mut face_offsets = vec![0u32];
    let mut face_vertices = Vec::new();
    for &f in faces {
        for &v in cage.face(f as usize) {
            let id = *map.entry(v).or_insert_with(|| {
                vertices.push(cage.vertices[v as usize]);
                vertices.len() as u32 - 1
            });
            face_vertices.push(id);
        }
        face_offsets.push(face_vertices.len() as u32);
    }
    let mut creases = Vec::new();
    for &f in faces {
        let start = topo.face_start(f);
        for k in 0..topo.face_len(f) {
            let h = start + k;
            let e = topo.he_edge[h as usize];
            let s = topo.sharpness[e as usize];
            // Each interior sharp edge once: from its first half-edge, or from the one we have.
            if s > 0.0
                && (topo.edge_he[e as usize] == h || !faces.contains(&topo.he_face[topo.edge_he[e as usize] as usize]))
            {
                let (a, b) = (topo.origin(h), topo.dest(h));
                if let (Some(&a), Some(&b)) = (map.get(&a), map.get(&b)) {
                    creases.push(Crease { a, b, sharpness: s });
                }
            }
        }
    }
    (Cage { vertices, face_offsets, face_vertices, creases, boundary: cage.boundary }, map)
}

/// Face f first, then the other faces sharing a vertex with it.
pub fn one_ring_faces(topo: &Topology, f: u32) -> Vec<u32> {
    let mut faces = vec![f];
    let start = topo.face_start(f);
    for k in 0..topo.face_len(f) {
        let v = topo.origin(start + k);
        for &h in topo.outgoing(v) {
            let g = topo.he_face[h as usize];
            if !faces.contains(&g) {
                faces.push(g);
            }
        }
    }
    faces
}

/// The faces of vertex v (its star), counter-clockwise.
pub fn star_faces(topo: &Topology, v: u32) -> Vec<u32> {
    topo.outgoing(v).iter().map(|&h| topo.he_face[h as usize]).collect()
}
