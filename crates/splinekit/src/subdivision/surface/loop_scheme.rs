//! One Loop step (Loop 1987) on a triangle mesh, with creases.
//!
//! - edge point: smooth 3/8 (v₀ + v₁) + 1/8 (o₀ + o₁) with o the vertices opposite the
//!   edge, crease (v₀ + v₁)/2;
//! - vertex point, smooth: (1 − nβ)v + β Σeᵢ with β = (5/8 − (3/8 + cos(2π/n)/4)²)/n;
//!   crease and corner rules from [`super::creases`].
//!
//! Vertices of the result: vertex points in the input's order, then edge points. Triangle
//! (a, b, c) becomes (a, e_ab, e_ca), (e_ab, b, e_bc), (e_ca, e_bc, c), (e_bc, e_ca, e_ab).

use super::cage::Cage;
use super::catmull_clark::child_creases;
use super::creases::{edge_point, vertex_points};
use super::topology::Topology;
use crate::{Error, Point, Result};

/// Loop's β for valence n.
pub fn loop_beta(n: usize) -> f64 {
    let n = n as f64;
    let c = 0.375 + 0.25 * (std::f64::consts::TAU / n).cos();
    (0.625 - c * c) / n
}

/// One Loop step; faces that are not triangles are refused (use [`Cage::triangulated`]).
pub fn loop_step(cage: &Cage, topo: &Topology) -> Result<Cage> {
    if let Some(f) = (0..cage.face_count()).find(|&f| cage.face(f).len() != 3) {
        return Err(Error::invalid(
            format!("faces[{f}]"),
            format!(
                "Loop subdivision takes triangles, this face has {} vertices (ask for triangulation)",
                cage.face(f).len()
            ),
        ));
    }
    let vs = &cage.vertices;
    let nv = vs.len();
    let mut out = Vec::with_capacity(nv + topo.edges.len());
    vertex_points(topo, vs, cage.boundary, &mut out, |v, edges| {
        let beta = loop_beta(edges.len());
        let e = edges.iter().fold(Point::<3>::zeros(), |a, &(_, w)| a + vs[w as usize]);
        vs[v as usize] * (1.0 - edges.len() as f64 * beta) + e * beta
    });
    for e in 0..topo.edges.len() as u32 {
        let [a, b] = topo.edges[e as usize];
        let (pa, pb) = (vs[a as usize], vs[b as usize]);
        let h = topo.edge_he[e as usize];
        let smooth = || {
            let t = topo.twin[h as usize];
            let o0 = vs[topo.dest(topo.next(h)) as usize];
            let o1 = vs[topo.dest(topo.next(t)) as usize];
            (pa + pb) * 0.375 + (o0 + o1) * 0.125
        };
        out.push(edge_point(topo.edge_sharpness(e), (pa + pb) * 0.5, smooth));
    }
    let ep0 = nv as u32;
    let mut face_vertices = Vec::with_capacity(cage.face_vertices.len() * 4);
    for f in 0..cage.face_count() as u32 {
        let h = topo.face_start(f);
        let (a, b, c) = (topo.origin(h), topo.origin(h + 1), topo.origin(h + 2));
        let (ab, bc, ca) =
            (ep0 + topo.he_edge[h as usize], ep0 + topo.he_edge[h as usize + 1], ep0 + topo.he_edge[h as usize + 2]);
        face_vertices.extend_from_slice(&[a, ab, ca, ab, b, bc, ca, bc, c, bc, ca, ab]);
    }
    let face_offsets = (0..=face_vertices.len() as u32 / 3).map(|k| 3 * k).collect();
    Ok(Cage { vertices: out, face_offsets, face_vertices, creases: child_creases(topo, ep0), boundary: cage.boundary })
}
