//! Half-edge adjacency of a [`Cage`], built in linear time and memory.
//!
//! Half-edge h is corner k of face f (h = `face_offsets[f] + k`): it runs from the face's
//! k-th vertex to its (k + 1)-th. `twin` pairs the two half-edges of an interior edge
//! (found through one hash map of directed edges); each vertex keeps its outgoing
//! half-edges in counter-clockwise order around it (next = twin(prev(h))), starting, at a
//! boundary vertex, at the outgoing boundary half-edge.

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

use super::cage::{Cage, INFINITE_SHARPNESS};
use crate::{Error, Result};

/// A multiplicative hash for vertex-index pairs (the Fx hash of rustc): the default
/// SipHash costs more than the rest of a subdivision step.
#[derive(Default, Clone, Copy)]
pub struct PairHasher(u64);

impl Hasher for PairHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(b as u64);
        }
    }
    fn write_u32(&mut self, x: u32) {
        self.write_u64(x as u64);
    }
    fn write_u64(&mut self, x: u64) {
        self.0 = (self.0.rotate_left(5) ^ x).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
}

/// A hash map keyed by directed edges (or any vertex-index pairs).
pub type PairMap<V> = HashMap<(u32, u32), V, BuildHasherDefault<PairHasher>>;

/// No half-edge (the twin of a boundary half-edge).
pub const NONE: u32 = u32::MAX;

/// Adjacency of a cage.
#[derive(Debug, Clone)]
pub struct Topology {
    /// Face of each half-edge.
    pub he_face: Vec<u32>,
    /// Opposite half-edge, or [`NONE`] on the boundary.
    pub twin: Vec<u32>,
    /// Edge of each half-edge.
    pub he_edge: Vec<u32>,
    /// Edges as (vertex, vertex) in the direction of their first half-edge.
    pub edges: Vec<[u32; 2]>,
    /// First half-edge of each edge.
    pub edge_he: Vec<u32>,
    /// Sharpness of each edge (+∞ for infinitely sharp; boundary edges are 0 here and
    /// sharp by [`Topology::is_boundary_edge`]).
    pub sharpness: Vec<f64>,
    /// Outgoing half-edges of vertex v, counter-clockwise: `vertex_out[vertex_offsets[v]..vertex_offsets[v + 1]]`.
    pub vertex_offsets: Vec<u32>,
    /// See `vertex_offsets`.
    pub vertex_out: Vec<u32>,
    /// Whether each vertex is on the boundary.
    pub vertex_boundary: Vec<bool>,
    face_offsets: Vec<u32>,
    face_vertices: Vec<u32>,
}

impl Topology {
    /// Builds the adjacency, refusing edges with more than two faces or inconsistent
    /// orientation, vertices whose faces form more than one fan and creases that are not
    /// edges of the cage.
    pub fn new(cage: &Cage) -> Result<Topology> {
        cage.validate()?;
        let nh = cage.face_vertices.len();
        let nv = cage.vertices.len();
        let mut he_face = vec![0u32; nh];
        for f in 0..cage.face_count() {
            for h in cage.face_offsets[f]..cage.face_offsets[f + 1] {
                he_face[h as usize] = f as u32;
            }
        }
        let mut topo = Topology {
            he_face,
            twin: vec![NONE; nh],
            he_edge: vec![0; nh],
            edges: Vec::new(),
            edge_he: Vec::new(),
            sharpness: Vec::new(),
            vertex_offsets: Vec::new(),
            vertex_out: Vec::new(),
            vertex_boundary: vec![false; nv],
            face_offsets: cage.face_offsets.clone(),
            face_vertices: cage.face_vertices.clone(),
        };
        let mut directed: PairMap<u32> = PairMap::with_capacity_and_hasher(nh, Default::default());
        for h in 0..nh as u32 {
            let (a, b) = (topo.origin(h), topo.dest(h));
            if a == b {
                return Err(Error::invalid(
                    format!("faces[{}]", topo.he_face[h as usize]),
                    format!("vertex {a} repeats along an edge"),
                ));
            }
            if let Some(g) = directed.insert((a, b), h) {
                return Err(Error::invalid(
                    format!("faces[{}]", topo.he_face[h as usize]),
                    format!(
                        "the edge {a}→{b} is also in faces[{}]: faces must be oriented consistently, two per edge at most",
                        topo.he_face[g as usize]
                    ),
                ));
            }
        }
        for h in 0..nh as u32 {
            let (a, b) = (topo.origin(h), topo.dest(h));
            match directed.get(&(b, a)) {
                Some(&t) => {
                    topo.twin[h as usize] = t;
                    if t > h {
                        topo.he_edge[h as usize] = topo.edges.len() as u32;
                        topo.he_edge[t as usize] = topo.edges.len() as u32;
                        topo.edges.push([a, b]);
                        topo.edge_he.push(h);
                    }
                }
                None => {
                    topo.he_edge[h as usize] = topo.edges.len() as u32;
                    topo.edges.push([a, b]);
                    topo.edge_he.push(h);
                    topo.vertex_boundary[a as usize] = true;
                    topo.vertex_boundary[b as usize] = true;
                }
            }
        }
        topo.sharpness = vec![0.0; topo.edges.len()];
        for (k, c) in cage.creases.iter().enumerate() {
            let h = directed.get(&(c.a, c.b)).or_else(|| directed.get(&(c.b, c.a))).ok_or_else(|| {
                Error::invalid(format!("creases[{k}]"), format!("{}–{} is not an edge of the cage", c.a, c.b))
            })?;
            topo.sharpness[topo.he_edge[*h as usize] as usize] =
                if c.sharpness >= INFINITE_SHARPNESS { f64::INFINITY } else { c.sharpness };
        }
        // Vertex fans.
        let mut count = vec![0u32; nv + 1];
        let mut start = vec![NONE; nv];
        for h in 0..nh as u32 {
            let v = topo.origin(h) as usize;
            count[v + 1] += 1;
            if start[v] == NONE || topo.twin[h as usize] == NONE {
                start[v] = h;
            }
        }
        for v in 0..nv {
            count[v + 1] += count[v];
        }
        topo.vertex_offsets = count;
        topo.vertex_out = vec![NONE; nh];
        for v in 0..nv {
            let (lo, hi) = (topo.vertex_offsets[v] as usize, topo.vertex_offsets[v + 1] as usize);
            if lo == hi {
                continue;
            }
            let mut h = start[v];
            let mut k = lo;
            loop {
                topo.vertex_out[k] = h;
                k += 1;
                let t = topo.twin[topo.prev(h) as usize];
                if t == NONE || t == start[v] || k == hi {
                    if k != hi || (t != NONE && t != start[v]) {
                        return Err(Error::invalid(
                            format!("vertices[{v}]"),
                            "its faces form more than one fan (a non-manifold vertex)",
                        ));
                    }
                    break;
                }
                h = t;
            }
        }
        Ok(topo)
    }

    /// Face of half-edge h's corner: first half-edge index of face f.
    pub fn face_start(&self, f: u32) -> u32 {
        self.face_offsets[f as usize]
    }
    /// Number of vertices of face f.
    pub fn face_len(&self, f: u32) -> u32 {
        self.face_offsets[f as usize + 1] - self.face_offsets[f as usize]
    }
    /// Number of faces.
    pub fn face_count(&self) -> usize {
        self.face_offsets.len() - 1
    }
    /// Next half-edge in its face.
    pub fn next(&self, h: u32) -> u32 {
        let f = self.he_face[h as usize] as usize;
        if h + 1 == self.face_offsets[f + 1] { self.face_offsets[f] } else { h + 1 }
    }
    /// Previous half-edge in its face.
    pub fn prev(&self, h: u32) -> u32 {
        let f = self.he_face[h as usize] as usize;
        if h == self.face_offsets[f] { self.face_offsets[f + 1] - 1 } else { h - 1 }
    }
    /// Start vertex of h.
    pub fn origin(&self, h: u32) -> u32 {
        self.face_vertices[h as usize]
    }
    /// End vertex of h.
    pub fn dest(&self, h: u32) -> u32 {
        self.face_vertices[self.next(h) as usize]
    }
    /// Outgoing half-edges of v, counter-clockwise.
    pub fn outgoing(&self, v: u32) -> &[u32] {
        &self.vertex_out[self.vertex_offsets[v as usize] as usize..self.vertex_offsets[v as usize + 1] as usize]
    }
    /// Whether edge e has one face.
    pub fn is_boundary_edge(&self, e: u32) -> bool {
        self.twin[self.edge_he[e as usize] as usize] == NONE
    }
    /// Effective sharpness of edge e: +∞ on the boundary.
    pub fn edge_sharpness(&self, e: u32) -> f64 {
        if self.is_boundary_edge(e) { f64::INFINITY } else { self.sharpness[e as usize] }
    }

    /// The edges at vertex v counter-clockwise: (edge, neighbour vertex) for each outgoing
    /// half-edge, then, at a boundary vertex, the incoming boundary edge. Face i of v's fan
    /// lies between edges i and i + 1.
    pub fn vertex_edges(&self, v: u32) -> Vec<(u32, u32)> {
        let out = self.outgoing(v);
        let mut r: Vec<(u32, u32)> = out.iter().map(|&h| (self.he_edge[h as usize], self.dest(h))).collect();
        if self.vertex_boundary[v as usize]
            && let Some(&last) = out.last()
        {
            let p = self.prev(last);
            r.push((self.he_edge[p as usize], self.origin(p)));
        }
        r
    }
}
