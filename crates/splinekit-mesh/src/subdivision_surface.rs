//! Subdivision surfaces on polygon meshes: Catmull–Clark (limit: the uniform bicubic
//! B-spline surface on regular quad regions) and Doo–Sabin (limit: the uniform biquadratic
//! one). Both work on any polygons, closed or with boundaries.
//!
//! Catmull–Clark, one step:
//! - face point f = the centroid of the face;
//! - edge point e = (v₀ + v₁ + f₀ + f₁)/4 for an interior edge, (v₀ + v₁)/2 on the boundary;
//! - vertex point v′ = (Q + 2R + (n − 3)v)/n for an interior vertex of valence n (Q the mean
//!   of its face points, R the mean of its edge midpoints), (m₀ + 6v + m₁)/8 for a boundary
//!   vertex with boundary neighbours m₀, m₁;
//! - every n-gon becomes n quads (v′, e, f, e).
//!
//! Doo–Sabin, one step: corner i of an n-gon with vertices v_j gets the point
//! p_i = Σ_j α_ij v_j with α_ii = (n + 5)/(4n), α_ij = (3 + 2 cos(2π(i − j)/n))/(4n)
//! (for quads 9/16, 3/16, 3/16, 1/16: the tensor product of Chaikin's ¾, ¼); new faces: one
//! per face (its corner points), one per interior edge (4 points), one per interior vertex
//! (the corner points around it).
//! Boundary edges and vertices make no faces, so the surface pulls away from open borders.
//!
//! Output order: a function of the input alone (hash maps serve lookups only; their order,
//! seeded anew for every map, never reaches the output). Catmull–Clark: the moved vertices
//! in input order, then the face points in face order, then the edge points in sorted
//! (min, max) vertex-pair order; each face's quads in face order, from its first corner; a
//! vertex's sum R over its edges in sorted edge order. Doo–Sabin: the face faces in face
//! order; then the edge faces in the order faces and their edges first meet each interior
//! edge (edge a→b of the lower-numbered face f, b→a of face g: f's corners at b and a, then
//! g's at a and b); then the vertex faces in vertex order, each starting at the vertex's
//! corner in its lowest-numbered face.

use foldhash::{HashMap, HashMapExt};

use crate::export::representable::{ExportError, Precision, check_vectors, one_line};

use splinekit::{Error, Result};

/// A mesh of polygons (each face's vertices counter-clockwise around its outer side).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PolygonMesh {
    /// Vertex positions.
    pub vertices: Vec<[f64; 3]>,
    /// Faces as vertex indices (at least 3 each).
    pub faces: Vec<Vec<u32>>,
}

type Edge = (u32, u32);

fn edge(a: u32, b: u32) -> Edge {
    (a.min(b), a.max(b))
}
fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn scale(a: [f64; 3], s: f64) -> [f64; 3] {
    [a[0] * s, a[1] * s, a[2] * s]
}

impl PolygonMesh {
    /// Checks the mesh as the kernel checks a subdivision cage (one home for the rules,
    /// [`Topology::new`](splinekit::subdivision::surface::Topology::new)): finite vertices,
    /// faces of 3 or more existing vertices, every edge in at most two faces used in opposite
    /// directions (a consistently oriented manifold), the faces at a vertex one fan.
    pub fn validate(&self) -> Result<()> {
        let vertices = self.vertices.iter().map(|p| splinekit::Point::<3>::from(*p)).collect();
        let cage = splinekit::subdivision::surface::Cage::new(vertices, &self.faces);
        splinekit::subdivision::surface::Topology::new(&cage).map(|_| ())
    }

    fn face_points(&self) -> Vec<[f64; 3]> {
        self.faces
            .iter()
            .map(|f| {
                scale(f.iter().fold([0.0; 3], |acc, &i| add(acc, self.vertices[i as usize])), 1.0 / f.len() as f64)
            })
            .collect()
    }

    /// Faces of each edge (one for a boundary edge, two inside).
    fn edge_faces(&self) -> HashMap<Edge, Vec<usize>> {
        let mut m: HashMap<Edge, Vec<usize>> = HashMap::new();
        for (f, face) in self.faces.iter().enumerate() {
            for k in 0..face.len() {
                m.entry(edge(face[k], face[(k + 1) % face.len()])).or_default().push(f);
            }
        }
        m
    }

    /// Edges with one face.
    pub fn boundary_edge_count(&self) -> usize {
        self.edge_faces().values().filter(|f| f.len() == 1).count()
    }

    /// One Catmull–Clark step.
    pub fn catmull_clark(&self) -> Result<PolygonMesh> {
        self.validate()?;
        let fp = self.face_points();
        let ef = self.edge_faces();
        let nv = self.vertices.len();
        // Edge points, indexed after the vertices and face points.
        let mut edges: Vec<Edge> = ef.keys().copied().collect();
        edges.sort_unstable();
        let edge_index: HashMap<Edge, u32> =
            edges.iter().enumerate().map(|(k, e)| (*e, (nv + fp.len() + k) as u32)).collect();
        let mut out = PolygonMesh { vertices: Vec::with_capacity(nv + fp.len() + edges.len()), faces: Vec::new() };
        // Per vertex: adjacent faces, edges, boundary neighbours.
        let mut faces_of = vec![Vec::new(); nv];
        for (f, face) in self.faces.iter().enumerate() {
            for &i in face {
                faces_of[i as usize].push(f);
            }
        }
        let mut edges_of = vec![Vec::new(); nv];
        let mut boundary_of = vec![Vec::new(); nv];
        for &(a, b) in &edges {
            let fs = &ef[&(a, b)];
            edges_of[a as usize].push(b);
            edges_of[b as usize].push(a);
            if fs.len() == 1 {
                boundary_of[a as usize].push(b);
                boundary_of[b as usize].push(a);
            }
        }
        for v in 0..nv {
            let p = self.vertices[v];
            let moved = if !boundary_of[v].is_empty() {
                if boundary_of[v].len() == 2 {
                    let (m0, m1) =
                        (self.vertices[boundary_of[v][0] as usize], self.vertices[boundary_of[v][1] as usize]);
                    scale(add(add(m0, m1), scale(p, 6.0)), 1.0 / 8.0)
                } else {
                    p // a corner where several borders meet stays put
                }
            } else if faces_of[v].is_empty() {
                p
            } else {
                let n = edges_of[v].len() as f64;
                let q =
                    scale(faces_of[v].iter().fold([0.0; 3], |acc, &f| add(acc, fp[f])), 1.0 / faces_of[v].len() as f64);
                let r = scale(
                    edges_of[v]
                        .iter()
                        .fold([0.0; 3], |acc, &w| add(acc, scale(add(p, self.vertices[w as usize]), 0.5))),
                    1.0 / n,
                );
                scale(add(add(q, scale(r, 2.0)), scale(p, n - 3.0)), 1.0 / n)
            };
            out.vertices.push(moved);
        }
        out.vertices.extend_from_slice(&fp);
        for e in &edges {
            let (a, b) = (self.vertices[e.0 as usize], self.vertices[e.1 as usize]);
            let fs = &ef[e];
            out.vertices.push(if fs.len() == 2 {
                scale(add(add(a, b), add(fp[fs[0]], fp[fs[1]])), 0.25)
            } else {
                scale(add(a, b), 0.5)
            });
        }
        for (f, face) in self.faces.iter().enumerate() {
            let n = face.len();
            let centre = (nv + f) as u32;
            for k in 0..n {
                let (prev, v, next) = (face[(k + n - 1) % n], face[k], face[(k + 1) % n]);
                out.faces.push(vec![v, edge_index[&edge(v, next)], centre, edge_index[&edge(prev, v)]]);
            }
        }
        Ok(out)
    }

    /// One Doo–Sabin step.
    pub fn doo_sabin(&self) -> Result<PolygonMesh> {
        self.validate()?;
        let ef = self.edge_faces();
        let mut out = PolygonMesh::default();
        // corner[(f, v)] = (index of the new point for vertex v of face f, v's place in f).
        let mut corner: HashMap<(usize, u32), (u32, usize)> = HashMap::new();
        for (f, face) in self.faces.iter().enumerate() {
            let points: Vec<[f64; 3]> = face.iter().map(|&v| self.vertices[v as usize]).collect();
            let first = out.vertices.len() as u32;
            out.vertices.extend(doo_sabin_corners(&points));
            for (k, &v) in face.iter().enumerate() {
                corner.insert((f, v), (first + k as u32, k));
            }
            out.faces.push((first..first + face.len() as u32).collect());
        }
        // The directed edges a→b of each face f, in face order, and each vertex's outgoing
        // edges (b, f) in the same order.
        let face_edges = || {
            self.faces
                .iter()
                .enumerate()
                .flat_map(|(f, face)| (0..face.len()).map(move |k| (face[k], face[(k + 1) % face.len()], f)))
        };
        let directed: HashMap<Edge, usize> = face_edges().map(|(a, b, f)| ((a, b), f)).collect();
        let mut outgoing: Vec<Vec<(u32, usize)>> = vec![Vec::new(); self.vertices.len()];
        for (a, b, f) in face_edges() {
            outgoing[a as usize].push((b, f));
        }
        // Edge faces: for an interior edge a→b in face f (and b→a in face g), where the
        // faces in order first meet it.
        let mut done = foldhash::HashSet::default();
        for (a, b, f) in face_edges() {
            if let Some(&g) = directed.get(&(b, a))
                && done.insert(edge(a, b))
            {
                out.faces.push(vec![corner[&(f, b)].0, corner[&(f, a)].0, corner[&(g, a)].0, corner[&(g, b)].0]);
            }
        }
        // Vertex faces: around each interior vertex (none of its edges on the boundary), in
        // vertex order, in the order of its faces from its first.
        let mut on_boundary = vec![false; self.vertices.len()];
        for (e, fs) in &ef {
            if fs.len() == 1 {
                on_boundary[e.0 as usize] = true;
                on_boundary[e.1 as usize] = true;
            }
        }
        for (v, list) in outgoing.iter().enumerate() {
            let v = v as u32;
            if list.len() < 3 || on_boundary[v as usize] {
                continue;
            }
            // Walk the faces around v: from face f (edge v→b) the next face owns edge b'→v ... use
            // the face whose edge v→w follows f's edge u→v.
            let mut ring = Vec::with_capacity(list.len());
            let (mut w, mut f) = list[0];
            for _ in 0..list.len() {
                ring.push(corner[&(f, v)].0);
                // The face on the other side of edge v→w is the one containing w→v; its
                // outgoing edge from v is the next around v.
                let g = directed[&(w, v)];
                let face = &self.faces[g];
                let k = corner[&(g, v)].1;
                w = face[(k + 1) % face.len()];
                f = g;
                if f == list[0].1 {
                    break;
                }
            }
            // The walk turns clockwise around v (seen from outside); the new face runs
            // counter-clockwise, from the same first corner.
            ring[1..].reverse();
            out.faces.push(ring);
        }
        Ok(out)
    }

    /// `steps` steps of a scheme.
    pub fn subdivide(&self, scheme: SurfaceScheme, steps: usize) -> Result<PolygonMesh> {
        let mut m = self.clone();
        for _ in 0..steps {
            if m.faces.iter().map(|f| f.len()).sum::<usize>() * 4 > 20_000_000 {
                return Err(Error::invalid("steps", format!("{steps} steps make more than 5·10⁶ faces")));
            }
            m = match scheme {
                SurfaceScheme::CatmullClark => m.catmull_clark()?,
                SurfaceScheme::DooSabin => m.doo_sabin()?,
            };
        }
        Ok(m)
    }

    /// A triangle mesh of the polygons (fans), with area-weighted vertex normals.
    pub fn triangulate(&self) -> crate::TriangleMesh {
        let mut m = crate::TriangleMesh { positions: self.vertices.clone(), ..Default::default() };
        for f in &self.faces {
            for k in 1..f.len() - 1 {
                m.triangles.push([f[0], f[k], f[k + 1]]);
            }
        }
        m.repair_normals();
        m
    }
}

/// The Doo–Sabin points of one n-gon's corners, p_i = Σ_j α_ij v_j, in O(n): with
/// θ_j = 2πj/n, cos(θ_i − θ_j) = cos θ_i cos θ_j + sin θ_i sin θ_j turns the weights into
/// p_i = v_i/4 + 3/(4n) Σ_j v_j + 1/(2n) (cos θ_i Σ_j cos θ_j v_j + sin θ_i Σ_j sin θ_j v_j).
pub(crate) fn doo_sabin_corners(v: &[[f64; 3]]) -> Vec<[f64; 3]> {
    let n = v.len() as f64;
    let angle = |j: usize| std::f64::consts::TAU * j as f64 / n;
    let (mut sum, mut cos, mut sin) = ([0.0; 3], [0.0; 3], [0.0; 3]);
    for (j, &p) in v.iter().enumerate() {
        let (s, c) = angle(j).sin_cos();
        sum = add(sum, p);
        cos = add(cos, scale(p, c));
        sin = add(sin, scale(p, s));
    }
    let mean = scale(sum, 3.0 / (4.0 * n));
    v.iter()
        .enumerate()
        .map(|(i, &p)| {
            let (s, c) = angle(i).sin_cos();
            let turn = scale(add(scale(cos, c), scale(sin, s)), 1.0 / (2.0 * n));
            add(add(scale(p, 0.25), mean), turn)
        })
        .collect()
}

/// A subdivision-surface scheme.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SurfaceScheme {
    /// Catmull–Clark (quads; bicubic B-spline limit on regular regions).
    CatmullClark,
    /// Doo–Sabin (biquadratic B-spline limit on regular regions).
    DooSabin,
}

/// Reads the vertices and polygon faces of an OBJ file (`v` and `f`, 1-based or negative
/// indices, `v/vt/vn` corners; the kernel's [`read_obj_cage`](splinekit::subdivision::surface::read_obj_cage)).
pub fn read_obj_polygons(text: &str) -> std::result::Result<PolygonMesh, String> {
    let cage = splinekit::subdivision::surface::read_obj_cage(text)?;
    Ok(PolygonMesh { vertices: cage.vertices, faces: cage.faces })
}

/// Writes the mesh as OBJ text (polygon faces) to `out` (give it a buffered writer);
/// refuses non-finite coordinates before writing anything.
pub fn write_obj_polygons(
    mesh: &PolygonMesh,
    name: &str,
    mut out: impl std::io::Write,
) -> std::result::Result<(), ExportError> {
    check_vectors(&mesh.vertices, Precision::Double, "OBJ", "vertices")?;
    writeln!(out, "# splinekit subdivision surface\no {}", one_line(name))?;
    for v in &mesh.vertices {
        writeln!(out, "v {} {} {}", v[0], v[1], v[2])?;
    }
    for f in &mesh.faces {
        out.write_all(b"f")?;
        for &i in f {
            write!(out, " {}", i + 1)?;
        }
        out.write_all(b"\n")?;
    }
    out.flush()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The O(n) corner points equal the mask Σ_j α_ij v_j summed term by term.
    #[test]
    fn doo_sabin_corners_match_the_mask() {
        for n in 3..12 {
            let v: Vec<[f64; 3]> =
                (0..n).map(|j| [(j as f64 * 1.7).sin() * 3.0, (j * j) as f64 * 0.1, 1.0 / (j as f64 + 1.0)]).collect();
            let fast = doo_sabin_corners(&v);
            for i in 0..n {
                let mut p = [0.0; 3];
                for j in 0..n {
                    let w = if i == j {
                        (n as f64 + 5.0) / (4.0 * n as f64)
                    } else {
                        (3.0 + 2.0 * (std::f64::consts::TAU * (i as f64 - j as f64) / n as f64).cos())
                            / (4.0 * n as f64)
                    };
                    p = add(p, scale(v[j], w));
                }
                for c in 0..3 {
                    assert!((fast[i][c] - p[c]).abs() < 1e-13, "n = {n}, corner {i}: {:?} vs {p:?}", fast[i]);
                }
            }
        }
    }
}
