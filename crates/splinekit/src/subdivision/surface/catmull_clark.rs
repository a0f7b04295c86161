//! One Catmull–Clark step (any polygons; every n-gon becomes n quads), with creases.
//!
//! - face point f = the centroid of the face;
//! - edge point: smooth (v₀ + v₁ + f₀ + f₁)/4, crease (v₀ + v₁)/2 (see [`super::creases`]);
//! - vertex point, smooth: ((n − 2)v + Σeᵢ/n + Σfᵢ/n)/n for n edges eᵢ and faces fᵢ
//!   (Catmull and Clark 1978 as written in OpenSubdiv); crease and corner rules from
//!   [`super::creases`].
//!
//! Vertices of the result: the vertex points in the input's order (vertex i stays vertex
//! i), then the face points, then the edge points. Face f's k-th corner becomes the quad
//! (vₖ, e(vₖvₖ₊₁), f, e(vₖ₋₁vₖ)), faces in the input's order. Linear time and memory.

use super::cage::{Cage, Crease};
use super::creases::{child_sharpness, edge_point, vertex_points};
use super::topology::Topology;
use crate::Point;

/// Which new points a step makes (Catmull–Clark proper or its bilinear sibling).
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum QuadRule {
    CatmullClark,
    Bilinear,
}

/// One Catmull–Clark step of `cage` (with its topology).
pub fn catmull_clark_step(cage: &Cage, topo: &Topology) -> Cage {
    quad_split(cage, topo, QuadRule::CatmullClark)
}

pub(crate) fn quad_split(cage: &Cage, topo: &Topology, rule: QuadRule) -> Cage {
    let nv = cage.vertices.len();
    let nf = cage.face_count();
    let ne = topo.edges.len();
    let vs = &cage.vertices;
    let mut out = Vec::with_capacity(nv + nf + ne);
    let face_points: Vec<Point<3>> = (0..nf)
        .map(|f| {
            let face = cage.face(f);
            face.iter().fold(Point::<3>::zeros(), |a, &i| a + vs[i as usize]) / face.len() as f64
        })
        .collect();
    if rule == QuadRule::Bilinear {
        // Every vertex stays.
        out.extend_from_slice(vs);
    } else {
        vertex_points(topo, vs, cage.boundary, &mut out, |v, edges| {
            let n = edges.len() as f64;
            let e = edges.iter().fold(Point::<3>::zeros(), |a, &(_, w)| a + vs[w as usize]);
            let f = topo
                .outgoing(v)
                .iter()
                .fold(Point::<3>::zeros(), |a, &h| a + face_points[topo.he_face[h as usize] as usize]);
            (vs[v as usize] * (n - 2.0) + e / n + f / n) / n
        });
    }
    out.extend_from_slice(&face_points);
    for e in 0..ne as u32 {
        let [a, b] = topo.edges[e as usize];
        let mid = (vs[a as usize] + vs[b as usize]) * 0.5;
        if rule == QuadRule::Bilinear {
            out.push(mid);
            continue;
        }
        let h = topo.edge_he[e as usize];
        let smooth = || {
            let t = topo.twin[h as usize];
            (vs[a as usize]
                + vs[b as usize]
                + face_points[topo.he_face[h as usize] as usize]
                + face_points[topo.he_face[t as usize] as usize])
                * 0.25
        };
        out.push(edge_point(topo.edge_sharpness(e), mid, smooth));
    }
    let (fp0, ep0) = (nv as u32, (nv + nf) as u32);
    let mut face_offsets = Vec::with_capacity(cage.face_vertices.len() + 1);
    let mut face_vertices = Vec::with_capacity(cage.face_vertices.len() * 4);
    face_offsets.push(0u32);
    for f in 0..nf as u32 {
        let start = topo.face_start(f);
        let n = topo.face_len(f);
        for k in 0..n {
            let h = start + k;
            let hp = start + (k + n - 1) % n;
            face_vertices.extend_from_slice(&[
                topo.origin(h),
                ep0 + topo.he_edge[h as usize],
                fp0 + f,
                ep0 + topo.he_edge[hp as usize],
            ]);
            face_offsets.push(face_vertices.len() as u32);
        }
    }
    let creases = child_creases(topo, ep0);
    Cage { vertices: out, face_offsets, face_vertices, creases, boundary: cage.boundary }
}

/// The child creases when edge e's point is vertex `ep0 + e`: each sharp interior edge
/// a–b gives a–e and e–b with the decayed sharpness.
pub(crate) fn child_creases(topo: &Topology, ep0: u32) -> Vec<Crease> {
    let mut creases = Vec::new();
    for (e, &s) in topo.sharpness.iter().enumerate() {
        let c = child_sharpness(s);
        if c > 0.0 && !topo.is_boundary_edge(e as u32) {
            let [a, b] = topo.edges[e];
            let m = ep0 + e as u32;
            creases.push(Crease { a, b: m, sharpness: c });
            creases.push(Crease { a: m, b, sharpness: c });
        }
    }
    creases
}
